// pendepth — reading shapes and writing results (docs/design.md §3).
//
// Readers report bad input as InvalidInput with a message "SOURCE:LINE: problem" (SOURCE is the
// file name or the name given for a string), or "SOURCE: problem (byte offset K)" for binary
// files, so a command-line tool can print it as one line.
// Writers print doubles with the shortest representation that reads back to the same double.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/depth3.hpp>
#include <pendepth/geometry.hpp>
#include <pendepth/polygon.hpp>
#include <pendepth/polytope.hpp>

#include <array>
#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth::io {

/// An output that could not be written (a file that cannot be created, a full disk, a closed
/// pipe): not bad input, so a distinct type (the command-line tool exits with status 3).
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A polygon as written in a file: rings (outer first, then holes) in the order and orientation
/// given, the repeated closing vertex of each ring dropped. line[r][i] is the 1-based source line
/// of vertex i of ring r, for error messages.
struct WktPolygon {
  std::vector<std::vector<Vec2>> rings;
  std::vector<std::vector<std::size_t>> lines;
  std::size_t first_line = 1;  ///< line of the POLYGON keyword
};

/// Parses text holding exactly one `POLYGON ((x y, ...), (hole ...))`: keyword case-insensitive,
/// whitespace and newlines anywhere, 2D coordinates only. Throws InvalidInput "SOURCE:LINE: ..."
/// for: an unknown geometry type, POLYGON EMPTY, Z/M coordinates, a missing parenthesis or
/// comma, a non-numeric token, a non-finite or out-of-range number, a ring with fewer than 3
/// points (after dropping a repeated closing vertex), trailing text. O(length of text).
WktPolygon parse_wkt_polygon(std::string_view text, std::string_view source = "<wkt>");

/// Reads a file and parses it with parse_wkt_polygon (SOURCE = the path as given). Throws
/// InvalidInput "PATH: cannot read file (reason)" if the file cannot be opened.
WktPolygon read_wkt_polygon(const std::filesystem::path& path);

/// Reads a WKT file holding one convex polygon without holes and validates it as a ConvexPolygon
/// named `name`. A validation error is rethrown as "PATH:LINE: <ConvexPolygon message>", LINE
/// being the line of the vertex the message names (else the line of the outer ring's first
/// vertex). Holes: "PATH: convex polygons cannot have holes (...)". O(n log n).
ConvexPolygon read_convex_polygon(const std::filesystem::path& path, std::string_view name);

/// Reads a WKT file holding a simple polygon, possibly with holes, and validates it as a Polygon
/// named `name`. A validation error is rethrown as "PATH:LINE: <Polygon message>", LINE being the
/// line of the first vertex or edge the message names in the ring it names (else the ring's first
/// vertex, else the POLYGON keyword). O(n log n) plus Polygon's validation.
Polygon read_polygon(const std::filesystem::path& path, std::string_view name);

/// A 2D shape file for the command-line tool: `convex` when the file holds one ring that
/// ConvexPolygon accepts, otherwise `polygon` (non-convex or with holes). Errors: a ring that is
/// neither convex nor a valid simple polygon reports the Polygon validation (as read_polygon);
/// other convex-validation errors (non-finite, zero area, fewer than 3 points) are reported as
/// read_convex_polygon does. The file is read once.
struct Shape2 {
  std::optional<ConvexPolygon> convex;
  std::optional<Polygon> polygon;
};
Shape2 read_shape2(const std::filesystem::path& path, std::string_view name);
/// As read_shape2, for a parsed polygon; error messages start "SOURCE:LINE: ".
Shape2 shape2_from_wkt(const WktPolygon& w, std::string_view source, std::string_view name);

/// The whole content of a file, read to its end: FIFOs, pipes and character devices work like
/// regular files (no size is asked, no seek). Throws InvalidInput "PATH: cannot read file
/// (reason)".
std::string read_text_file(const std::filesystem::path& path);
/// The rest of a stream (e.g. std::cin), read to its end; `size_hint` bytes are reserved first.
/// Throws InvalidInput "SOURCE: cannot read file (read error)" if the stream fails before its end.
std::string read_stream(std::istream& in, std::string_view source, std::size_t size_hint = 0);

/// The shape file formats: 2D WKT, 3D OBJ, OFF, STL and PLY.
enum class ShapeFormat { Wkt, Obj, Off, Stl, Ply };
/// The format of a path by its extension (.wkt, .obj, .off, .stl, .ply, any case), else nullopt.
std::optional<ShapeFormat> shape_format_of(const std::filesystem::path& path);
/// The format of a file's content, for standard input and paths without an extension: PLY by its
/// first line `ply` (the format's magic); binary STL by its size (84 + 50·count bytes); otherwise
/// the first word past blank and '#' lines —
/// a WKT geometry type (POLYGON, ...), `solid` (ASCII STL), an OFF keyword or a bare count (OFF),
/// an OBJ statement (v, f, o, g, mtllib, ...). Nullopt when none fits. O(size) at worst.
std::optional<ShapeFormat> guess_shape_format(std::string_view bytes);

/// One line of a batch query file: placement t, direction d (all zero: ask for σ), source line.
struct Query2 {
  Vec2 t{0, 0};
  Vec2 d{0, 0};
  std::size_t line = 0;
};

/// Parses batch queries, one `x,y,dx,dy` per line (spaces and tabs around fields allowed). Blank
/// lines and lines starting with '#' are skipped, and so is a header: a first data line that is
/// exactly `x,y,dx,dy` (spaces and tabs around the names allowed). Any other line must be numbers:
/// throws InvalidInput "SOURCE:LINE: problem" for a wrong field count ("expected 4 numbers, got
/// 3"), an empty, non-numeric or non-finite field (offending text quoted with non-printable bytes
/// as \xNN). O(length of text).
std::vector<Query2> parse_queries_csv(std::string_view text, std::string_view source = "<csv>");
std::vector<Query2> read_queries_csv(const std::filesystem::path& path);

/// A 3D batch query: placement t, direction d (all zero: ask for σ), source line.
struct Query3 {
  Vec3 t{0, 0, 0};
  Vec3 d{0, 0, 0};
  std::size_t line = 0;
};

/// As parse_queries_csv, with lines `x,y,z,dx,dy,dz` (6 numbers; header `x,y,z,dx,dy,dz`).
std::vector<Query3> parse_queries3_csv(std::string_view text, std::string_view source = "<csv>");
std::vector<Query3> read_queries3_csv(const std::filesystem::path& path);

/// One line of a 2D trajectory file: Q rotated by `degrees` about its origin, then placed at t.
struct PoseLine2 {
  Vec2 t{0, 0};
  double degrees = 0;
  std::size_t line = 0;
};
/// One line of a 3D trajectory file: Q rotated by q (normalised by the library), then moved by t.
struct PoseLine3 {
  Vec3 t{0, 0, 0};
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  std::size_t line = 0;
};
/// Trajectory files (`pendepth trajectory`, src/io/poses_csv.cpp), as parse_queries_csv: lines
/// `x,y,angle_deg` (2D) or `x,y,z,qw,qx,qy,qz` (3D), header exactly those names, blank and '#'
/// lines skipped; InvalidInput "SOURCE:LINE: problem" (wrong count, empty, non-numeric or
/// non-finite field, a zero quaternion).
std::vector<PoseLine2> parse_poses2_csv(std::string_view text, std::string_view source = "<csv>");
std::vector<PoseLine2> read_poses2_csv(const std::filesystem::path& path);
std::vector<PoseLine3> parse_poses3_csv(std::string_view text, std::string_view source = "<csv>");
std::vector<PoseLine3> read_poses3_csv(const std::filesystem::path& path);

// ---- 3D point sets (docs/design.md §3: convex algorithms take the hull of the vertices) ----
// The parsers return the vertices in file order (empty if the file holds none); faces, normals,
// colours and texture coordinates are checked but not kept. Numbers go through std::from_chars:
// 10⁶ vertices parse in well under a second. Every coordinate is checked finite. Offending text
// is quoted in messages with non-printable bytes as \xNN.

/// Wavefront OBJ: `v x y z [w]` lines (also `v x y z r g b`, a common colour extension); w is
/// the rational weight of curves and surfaces and does not move the point. `#` starts a comment
/// anywhere. Checked: `vt u [v [w]]` and `vn i j k` are numbers; the references of faces `f`
/// (v, v/vt, v//vn, v/vt/vn, at least 3), lines `l` (v, v/vt, at least 2) and points `p` are
/// non-zero integers naming an existing vertex, texture vertex, normal (negative: relative to
/// those read so far; positive: checked against the file's totals). Other statements of the
/// OBJ specification (g, o, s, usemtl, mtllib, curves, ...) are accepted without being read; any
/// other first word is an error, and so is a line continuation (a trailing backslash). Throws "SOURCE:LINE:
/// malformed vertex line: ..." for a wrong number count or a non-numeric field, "SOURCE:LINE: ...
/// not a finite number" for inf, nan or an out-of-range value, "SOURCE:LINE: malformed face..."
/// or "reference to vertex K, but the file has N vertices". O(length of text).
std::vector<Vec3> parse_obj_points(std::string_view text, std::string_view source = "<obj>");

/// Geomview OFF: optional header keyword [ST][C][N]OFF or nOFF (then the dimension, which must
/// be 3; 4OFF, 4D and binary OFF are rejected), then `vertices faces [edges]`, then one vertex
/// per line: x y z followed by the normal, colour or texture fields the keyword announces
/// (plain OFF: exactly 3 numbers), then exactly `faces` face lines `k i_1 ... i_k [colour]` (k >= 3,
/// 0-based indices below the vertex count, colour 0, 1, 3 or 4 numbers), then nothing but blank
/// and `#` comment lines (the edge count is not checked). Throws "SOURCE:LINE: problem" for a bad
/// keyword, bad counts, a malformed or non-finite vertex, a malformed face or index out of range,
/// a file ending before the declared counts, or content after the last face (the messages name
/// the header's counts). O(length of text).
std::vector<Vec3> parse_off_points(std::string_view text, std::string_view source = "<off>");

/// STL, ASCII or binary. Binary is recognised by its size, 84 + 50·triangles bytes (the count
/// is the little-endian uint32 at byte 80), whatever the header says — binary files often begin
/// with "solid" too; otherwise a file beginning with "solid" (any case) and holding no NUL byte
/// is ASCII: `solid [name]`, facets `facet normal nx ny nz` / `outer loop` / three `vertex x y z`
/// / `endloop` / `endfacet`, `endsolid [name]` (keywords any case, one statement per line, several
/// solids allowed). Returns the distinct vertices in order of first appearance (every STL vertex
/// is repeated by each of its triangles); -0 and 0 are the same vertex. Errors: ASCII
/// "SOURCE:LINE: problem" (unexpected keyword, malformed statement, a loop of other than 3
/// vertices, malformed or non-finite vertex, a file ending inside a solid); binary "SOURCE:
/// problem (byte offset K)" (size not 84 + 50·count, non-finite coordinate). O(size) expected.
std::vector<Vec3> parse_stl_points(std::string_view bytes, std::string_view source = "<stl>");

/// The vertices of a 3D shape file's content with the parser of `format` (Obj, Off, Stl or Ply:
/// parse_ply's vertices; Wkt throws InvalidInput).
std::vector<Vec3> parse_mesh_points(std::string_view bytes, ShapeFormat format, std::string_view source);

/// Reads a .obj, .off, .stl or .ply file (extension case-insensitive) with the parser above.
/// Throws "PATH: cannot read file (reason)" or "PATH: unknown 3D shape format '.ext' (expected
/// .obj, .off, .stl or .ply)".
std::vector<Vec3> read_mesh_points(const std::filesystem::path& path);

/// A 3D mesh file as read: every vertex and every face (a polygon of vertex indices), with where
/// each face is in the file for messages. Faces are not validated here (src/mesh3/validate.cpp).
struct MeshFile {
  std::string source;                     ///< the file name used in messages
  std::vector<Vec3> points;               ///< the vertices, in file order (STL: distinct, merged)
  std::vector<std::size_t> indices;       ///< face f's vertices: indices[face_start[f], face_start[f+1])
  std::vector<std::size_t> face_start;    ///< faces() + 1 entries
  std::vector<std::size_t> face_location; ///< face f's line (text) or byte offset (binary formats)
  bool byte_offsets = false;              ///< face_location holds byte offsets
  int index_base = 0;                     ///< the file's own vertex numbering: 1 for OBJ, else 0

  std::size_t faces() const { return face_start.empty() ? 0 : face_start.size() - 1; }
  /// "SOURCE:LINE: face F" (text) or "SOURCE: face F (byte offset K)" (binary); F 0-based.
  std::string face_where(std::size_t f) const;
  /// Vertex i as the file numbers it (i + index_base).
  std::string vertex_name(std::size_t i) const { return std::to_string(i + index_base); }
  /// Reader use: a new face starts at `location`.
  void begin_face(std::size_t location) {
    face_start.push_back(indices.size());
    face_location.push_back(location);
  }
};

/// The 3D mesh formats parse_mesh reads.
enum class MeshFormat { Obj, Off, Stl, Ply };
/// The mesh format of a 3D shape format (Wkt throws InvalidInput "SOURCE: a 2D shape (WKT) where
/// a 3D shape is expected").
MeshFormat mesh_format(ShapeFormat format, std::string_view source);

/// PLY (ASCII, binary_little_endian or binary_big_endian 1.0): the `vertex` element's x, y, z
/// (float or double; other properties of any type are skipped) and the `face` element's
/// `vertex_indices` (or `vertex_index`) list (any integer types); other elements are skipped.
/// ASCII: one element per line. Errors "SOURCE:LINE: problem" (header, ASCII body) or "SOURCE:
/// problem (byte offset K)" (binary body): a bad header, a missing x/y/z, a malformed or
/// non-finite number, an index out of range, a file ending early, or bytes/lines after the last
/// element. O(size).
MeshFile parse_ply(std::string_view bytes, std::string_view source = "<ply>");

/// Vertices and faces of a mesh file's content with the reader of `format`, with exactly the
/// errors of parse_obj_points, parse_off_points, parse_stl_points (OBJ `l` and `p` elements are
/// checked and ignored; STL vertices with equal coordinates are merged, -0 == 0) or parse_ply.
MeshFile parse_mesh(std::string_view bytes, MeshFormat format, std::string_view source);

/// Reads a .obj, .off, .stl or .ply file (extension case-insensitive) with parse_mesh. Throws
/// "PATH: cannot read file (reason)" or "PATH: unknown 3D shape format '.ext' (expected .obj,
/// .off, .stl or .ply)".
MeshFile read_mesh(const std::filesystem::path& path);

/// The convex hull of points read from SOURCE, as read_convex_polytope reports it: "SOURCE: NAME:
/// only K points (...)" for fewer than 4, "SOURCE: NAME: <hull message>" for flat sets.
ConvexPolytope convex_polytope_from_points(std::span<const Vec3> points, std::string_view source,
                                           std::string_view name);

/// The convex hull of a mesh file's vertices as a ConvexPolytope named `name` (hierarchy
/// included). Besides the reader's errors, throws "PATH: NAME: only K points (...)" for fewer
/// than 4 points and "PATH: NAME: <hull message>" for degenerate (flat) point sets. Feature
/// indices of results refer to the vertices as returned by read_mesh_points, 0-based.
/// O(size + n log n).
ConvexPolytope read_convex_polytope(const std::filesystem::path& path, std::string_view name);

/// `POLYGON ((x0 y0, ..., x0 y0))`: the vertices in their stored order, ring closed explicitly,
/// shortest round-trip doubles. Reading the text back gives the same doubles.
std::string to_wkt(std::span<const Vec2> ring);
std::string to_wkt(const ConvexPolygon& polygon);

/// A 2D geometry of several parts, e.g. a no-fit polygon (`pendepth nfp`): polygons with holes
/// (polygons[k][0] the outer ring, polygons[k][1..] its holes, closing vertex not repeated),
/// polylines (a slit is a polyline of 2 points) and isolated points.
struct Geometry2 {
  std::vector<std::vector<std::vector<Vec2>>> polygons;
  std::vector<std::vector<Vec2>> lines;
  std::vector<Vec2> points;
};

/// `MULTIPOLYGON (((x y, ...), (hole ...)), ...)` when g has no lines and no points (every ring
/// closed explicitly; `MULTIPOLYGON EMPTY` without polygons), else `GEOMETRYCOLLECTION
/// (MULTIPOLYGON (...), MULTILINESTRING ((x y, x y), ...), MULTIPOINT ((x y), ...))` with only the
/// non-empty parts. Shortest round-trip doubles: parse_wkt_geometry gives g back exactly. Throws
/// InvalidInput for a non-finite coordinate, a ring of fewer than 3 or a line of fewer than 2
/// points. O(size of g).
std::string to_wkt(const Geometry2& g);

/// Parses one POLYGON, MULTIPOLYGON, LINESTRING, MULTILINESTRING, POINT, MULTIPOINT (points with
/// or without their own parentheses) or a GEOMETRYCOLLECTION of these (not nested), EMPTY allowed
/// for each; the parts are appended to the fields of Geometry2 in text order. Keywords
/// case-insensitive, 2D only; a ring's repeated closing vertex is dropped. Throws InvalidInput
/// "SOURCE:LINE: problem" (unknown type, Z/M, missing parenthesis or comma, bad number, a ring of
/// fewer than 3 or a line of fewer than 2 points, trailing text). O(length of text).
Geometry2 parse_wkt_geometry(std::string_view text, std::string_view source = "<wkt>");

/// Appends one JSON object (no newline): {"polygons":[[[[x,y],...],...],...],"lines":[[[x,y],
/// ...],...],"points":[[x,y],...]}, shortest round-trip doubles.
void append_json(std::string& out, const Geometry2& g);

/// Appends the shortest decimal text that reads back as exactly x (std::to_chars); ±infinity as
/// ±1e999 (valid JSON that parsers read as infinity). x not NaN.
void append_double(std::string& out, double x);

/// Appends one JSON object (no newline) for a 2D result: depth, translation [x,y], normal,
/// witness_p, witness_q, kind ("minimum" | "directional" | "separation"), overlapping,
/// feature_p / feature_q {"kind": "vertex" | "edge" | "none", "index": i}. Feature indices are
/// input indices into the rings as given (ConvexPolygon::input_index); an edge reports its start
/// vertex in counter-clockwise order and "end" its end vertex. No allocation once `out` has
/// capacity.
void append_json(std::string& out, const Depth2& r, const ConvexPolygon& P, const ConvexPolygon& Q);

/// The same object for a polygon with holes against a convex polygon (either role). A polygon's
/// features carry the ring: {"kind":"vertex","ring":k,"index":i} or {"kind":"edge","ring":k,
/// "index":i,"end":j}, indices into ring k as given (0 = outer, k = hole k; Polygon::input_index),
/// the edge running with P's interior on its left; a convex shape's features are as above.
void append_json(std::string& out, const Depth2& r, const Polygon& P, const ConvexPolygon& Q);
void append_json(std::string& out, const Depth2& r, const ConvexPolygon& P, const Polygon& Q);
/// Two polygons with holes (PairDepth2, NoFitPolygon2): both shapes' features carry the ring.
void append_json(std::string& out, const Depth2& r, const Polygon& P, const Polygon& Q);

/// Appends one CSV row "depth,tx,ty\n".
void append_csv_row(std::string& out, const Depth2& r);

/// A multi-line human-readable summary of a 2D result (ends with a newline).
std::string summary(const Depth2& r, const ConvexPolygon& P, const ConvexPolygon& Q);
std::string summary(const Depth2& r, const Polygon& P, const ConvexPolygon& Q);
std::string summary(const Depth2& r, const ConvexPolygon& P, const Polygon& Q);
std::string summary(const Depth2& r, const Polygon& P, const Polygon& Q);

/// Appends one JSON object (no newline) for a 3D result: depth, translation [x,y,z], normal,
/// witness_p, witness_q, kind, overlapping, feature_p / feature_q, lower_bound, upper_bound.
/// Features use input vertex indices (ConvexPolytope::input_index): {"kind":"vertex","index":i},
/// {"kind":"edge","index":i,"end":j}, {"kind":"face","index":f,"vertices":[i,j,k]} (f the
/// triangle of P's or Q's triangulation, vertices counter-clockwise seen from outside) or
/// {"kind":"none","index":null}. No allocation once `out` has capacity.
void append_json(std::string& out, const Depth3& r, const ConvexPolytope& P, const ConvexPolytope& Q);

/// Appends one CSV row "depth,tx,ty,tz\n".
void append_csv_row(std::string& out, const Depth3& r);

/// A multi-line human-readable summary of a 3D result (ends with a newline).
std::string summary(const Depth3& r, const ConvexPolytope& P, const ConvexPolytope& Q);

/// Signed distance and shape cast (Distance2/3, Cast2/3; docs/design.md §3 `distance`, `cast`):
/// one JSON object (no newline) {"distance", "translation", "normal", "witness_p", "witness_q",
/// "overlapping", "feature_p", "feature_q"} (a cast adds "hit" after "distance"; 3D distance adds
/// "lower_bound", "upper_bound"; a missed cast's distance is 1e999), a CSV row
/// "distance,tx,ty[,tz]\n", or a summary. Features are formatted as for Depth2/Depth3 against the
/// shape whose numbering they use: Features2 holds a convex shape's ConvexPolygon or another
/// shape's Polygon (exactly one of the two), or for a point or segment (Shape2::point, segment)
/// neither and `flat` = its vertex count: {"kind":"vertex","index":j}, {"kind":"edge","index":0,"end":1}.
struct Features2 {
  const ConvexPolygon* convex = nullptr;
  const Polygon* polygon = nullptr;
  std::size_t flat = 0;
};
/// A 2D depth result (as the overloads above) with either shape given as Features2 (points and
/// segments included).
void append_json(std::string& out, const Depth2& r, Features2 P, Features2 Q);
std::string summary(const Depth2& r, Features2 P, Features2 Q);
void append_json(std::string& out, const Distance2& r, Features2 P, Features2 Q);
void append_json(std::string& out, const Cast2& r, Features2 P, Features2 Q);
void append_csv_row(std::string& out, const Distance2& r);
std::string summary(const Distance2& r, Features2 P, Features2 Q);
std::string summary(const Cast2& r, Features2 P, Features2 Q);
void append_json(std::string& out, const Distance3& r, const ConvexPolytope& P, const ConvexPolytope& Q);
void append_json(std::string& out, const Cast3& r, const ConvexPolytope& P, const ConvexPolytope& Q);
void append_csv_row(std::string& out, const Distance3& r);
std::string summary(const Distance3& r, const ConvexPolytope& P, const ConvexPolytope& Q);
std::string summary(const Cast3& r, const ConvexPolytope& P, const ConvexPolytope& Q);

/// What write_svg draws besides P and Q.
struct SvgOptions {
  std::optional<Vec2> direction;  ///< σ_d / separation direction, drawn as an arrow
  bool draw_M = true;             ///< add a configuration-space panel: M = P ⊕ (−Q), t, t → t + v
};

/// Writes an SVG picture of a 2D query: P (filled light blue), Q + t (light red, translucent),
/// Q + t + r.translation (dashed outline), the move, the witness point, the direction, and,
/// with draw_M, a second panel at the same scale with M, the point t and the arrow t → t + v.
/// Y axis points up; the view fits the content; outlines are decimated to half a pixel so
/// 10⁶-vertex shapes give small files. Throws WriteError "PATH: cannot write file (reason)" if
/// the file cannot be created or written (checked after flushing and closing). O(n + m).
void write_svg(const std::filesystem::path& path, const ConvexPolygon& P, const ConvexPolygon& Q,
               const Vec2& t, const Depth2& r, const SvgOptions& options = {});

/// What the general write_svg draws: P and Q as rings in their own frames (outer ring first,
/// then holes; several rings are filled with the even-odd rule), and the configuration-space
/// rings (e.g. the boundary of the overlap set O of a polygon with holes, or M) in the frame of
/// the placements t, labelled `config_label`; `config_target` labels the end t + v of the move.
struct SvgScene {
  std::vector<std::vector<Vec2>> P, Q, config;
  /// Lower-dimensional parts of the configuration set, drawn as lines and dots in its panel
  /// (e.g. the slits and isolated points of a no-fit polygon).
  std::vector<std::array<Vec2, 2>> config_segments;
  std::vector<Vec2> config_points;
  std::string config_label = "M = P ⊕ (−Q)";
  std::string config_target = "t + v on ∂M";
};

/// As above for any scene: the configuration panel is drawn when options.draw_M is set and
/// scene.config is not empty. Throws InvalidInput if P or Q has no ring of 3 points, WriteError if
/// the file cannot be written. O(total size of the rings).
void write_svg(const std::filesystem::path& path, const SvgScene& scene, const Vec2& t, const Depth2& r,
               const SvgOptions& options = {});

/// A 3D scene for write_html, in world coordinates: meshes, points and arrows grouped in layers
/// that the page shows or hides, and the panel's numbers (label, text) and notes. depth_scene3
/// builds the scene of a depth query; other query kinds fill one their own way.
struct Scene3 {
  struct Layer {
    std::string id, label;
    std::string color;  ///< swatch in the layer list, "#rrggbb"
    bool visible = true;
  };
  /// Parts of a mesh drawn in the highlight colour: triangles (indices into `triangles`),
  /// edges and vertices (indices into `vertices`).
  struct Highlight {
    std::vector<int> triangles;
    std::vector<std::array<int, 2>> edges;
    std::vector<int> vertices;
  };
  struct Mesh {
    std::string layer, color = "#808080";
    double opacity = 1;  ///< < 1: translucent
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
    Highlight highlight;
    std::string highlight_color = "#f2b200";
  };
  struct Point {
    std::string layer, color, label;
    Vec3 at{0, 0, 0};
  };
  struct Arrow {
    std::string layer, color, label;
    Vec3 from{0, 0, 0}, to{0, 0, 0};
  };
  std::string title;
  std::vector<Layer> layers;
  std::vector<Mesh> meshes;
  std::vector<Point> points;
  std::vector<Arrow> arrows;
  std::vector<std::array<std::string, 2>> numbers;
  std::vector<std::string> notes;
};

/// What depth_scene3 adds besides the shapes and the answer.
struct Html3Options {
  std::optional<Vec3> direction;  ///< σ_d / separation direction, drawn as an arrow from Q's centre
  std::string p_label = "P", q_label = "Q";  ///< e.g. the file names
  bool draw_M = true;  ///< a layer (hidden at first) with M = P ⊕ (−Q), t, t → t + v and M's facet there
  std::size_t M_max_pairs = 1 << 16;  ///< M is the hull of the n·m vertex differences: skipped above this
};

/// The scene of a 3D depth query (world frame): P at pose_p, Q at pose_q, Q moved by
/// r.translation (ghosted), the move as an arrow from the moved Q's witness back where it came
/// from, the witness points, the features r.feature_p / r.feature_q highlighted (vertex, edge =
/// half-edge 3f + k, face = every triangle of the true face of triangle f), the numbers, and M in
/// placement coordinates (t = pose_q's translation relative to P's; t + v lies on ∂M) with the
/// facet of normal r.facet_normal highlighted. Not overlapping: no move, witnesses or features.
/// M is computed with ConvexPolytope::hull of the differences, O(nm log nm); skipped with a note
/// above options.M_max_pairs pairs or when a difference is not finite. Anything else that is not
/// finite (a pose or an answer beyond the double range) is left out with a note: the scene is
/// always one html_page accepts.
Scene3 depth_scene3(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q, const Pose3& pose_q,
                    const Depth3& r, const Html3Options& options = {});

/// The self-contained HTML page of a scene (three.js and the viewer inlined, no network needed):
/// orbit / pan / zoom, layer toggles, the numbers panel, automatic framing. Coordinates are
/// written normalised (centre subtracted, scaled by a power of two to a half-extent in
/// [0.5, 1]), so any finite input scale (1e-300 … 1e300) gives finite JSON and a visible view.
/// Throws InvalidInput for a non-finite coordinate, or if the library was built without the
/// viewer (PENDEPTH_HTML_VIEWER=OFF). O(size of the scene).
std::string html_page(const Scene3& scene);

/// Writes html_page(scene) to a file. Throws InvalidInput as html_page, or WriteError "PATH:
/// cannot write file (reason)".
void write_html(const std::filesystem::path& path, const Scene3& scene);

}  // namespace pendepth::io

namespace pendepth {

/// Reads the vertices ("v x y z" lines) of a Wavefront OBJ file with io::parse_obj_points; other
/// lines are ignored. Unlike io::read_mesh_points it takes only OBJ, whatever the extension, and
/// an empty file is an error. Throws InvalidInput naming the file (and line) if it cannot be
/// opened, a "v" line is malformed, or it holds no vertex. (In namespace pendepth, not
/// pendepth::io: tests and benchmarks call it as pendepth::read_obj_vertices.)
std::vector<Vec3> read_obj_vertices(const std::string& path);

}  // namespace pendepth
