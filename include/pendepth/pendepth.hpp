// pendepth — the front door: one header, two shape classes, two pair classes.
//
//   #include <pendepth/pendepth.hpp>
//   using namespace pendepth;
//   Shape2 P = Shape2::from_wkt(text);                 // any 2D shape: convex, simple, with holes
//   Shape2 Q(std::vector<Vec2>{...});                   // outer ring; holes as 2nd argument
//   Pair2 pair(P, Q);                                   // picks the engine, preprocesses once
//   Depth2 s = pair.minimum(t);  pair.along(t, d);  pair.separation(t, d);  pair.overlapping(t);
//   pair.minimum(ts, out);                              // batch: parallel, bit-identical to singles
//   DepthValue2 v = pair.depth_value(t);                // lean σ (depth, translation; same bits)
//   Shape3 A = Shape3::hull(points), B = Shape3::from_file("part.obj");
//   Pair3 pair3(A, B);  pair3.minimum(pose_p, pose_q);  pair3.along(pose_p, pose_q, d);
//
// Conventions (docs/design.md §1): P is fixed, Q moves; Q is placed at t (2D) or posed (3D);
// M = P ⊕ (−Q); touching is not overlapping (depth 0); `translation` is the move to apply to Q;
// witnesses are world coordinates. For non-convex shapes overlap means t ∈ O, the open overlap
// set (exact fits and slits are touching placements, depth 0).
//
// Which engine a pair uses (Pair2::engine(), docs/design.md §2):
//   convex × convex        the O(log) queries of DHS §3 (σ by the depth field or the
//                          O(n + m) merge, see Prepare);
//   polygon × convex       PolygonDepth2 (DHS §4, §6), either way round: when Q is the polygon
//                          the roles are swapped internally and the answer mapped back;
//   polygon × polygon      PairDepth2 (per query, nothing built) or the no-fit polygon
//                          NoFitPolygon2 (built once, fast queries), see Prepare.
// Errors: invalid shapes and queries throw InvalidInput (a std::invalid_argument) naming the
// shape or the query; valid queries never throw and never return NaN.
// Magnitudes (docs/robustness.md): any finite size. Pairs of huge or tiny shapes are answered on
// copies scaled by a power of two (the same bits as at unit size; an explicit infinity only where
// the true value overflows); a pair spanning more than 2^600 (2D) / 2^280 (3D) from its largest
// coordinate to its smallest edge, or a placement with no exact value at the pair's scale, is
// InvalidInput naming the values and the limit.
#pragma once

#include <pendepth/approximate.hpp>
#include <pendepth/depth2.hpp>
#include <pendepth/depth3.hpp>
#include <pendepth/geometry.hpp>
#include <pendepth/polygon.hpp>
#include <pendepth/polytope.hpp>

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth {

class Mesh3;  // include/pendepth/mesh3.hpp
namespace mesh3 {
struct MeshPair;  // src/mesh3/mesh_pair.hpp
struct LazyMeshPair;  // src/front/mesh_shapes.hpp: MeshPair built on first use
struct MixedPair;  // src/mesh3/mesh_mixed.hpp
}
namespace convex3 {
struct FlatShape3;  // src/convex3/flat3.hpp
}
namespace primitives {
struct Curved3;  // src/primitives/support3.hpp
}

/// How much a pair prepares before its queries.
///   Queries: only what every query needs (triangulations, hierarchies); σ of two convex
///            polygons by the O(n + m) merge, two non-convex polygons by PairDepth2.
///   Full:    every per-pair structure: the depth field of two convex polygons, the no-fit
///            polygon of two non-convex ones (worst case O(n²m²) to build).
///   Auto:    convex × convex: the depth field when n + m > Pair2::kFieldAutoSize (there its
///            O(log) query beats the merge by 2× or more), else the merge; polygon × polygon:
///            the no-fit polygon when n·m ≤ Pair2::kNfpAutoLimit (its build then costs less than
///            a few PairDepth2 queries), else PairDepth2. polygon × convex has one engine.
/// The choice is made at construction, so an answer never depends on which calls came before
/// (a structure may be built on first use, under std::call_once).
enum class Prepare { Auto, Queries, Full };

/// The engine a Pair2 answers with.
enum class Engine2 {
  Convex,         ///< both convex (DepthQuery2 / directional_depth / separation_depth)
  PolygonConvex,  ///< P a polygon, Q convex (PolygonDepth2)
  PolygonConvexSwapped,  ///< P convex, Q a polygon (PolygonDepth2 on the swapped pair)
  PairPerQuery,   ///< both non-convex or with holes, per query (PairDepth2)
  NoFitPolygon,   ///< both non-convex or with holes, on the built no-fit polygon (NoFitPolygon2)
  Flat,           ///< a point or segment against a solid shape, either way round (FlatDepth2)
};
const char* to_string(Engine2 e);

/// A validated 2D shape: a simple polygon, convex or not, possibly with holes. Cheap to copy
/// (the validated data is shared, immutable). A single ring that is convex (collinear and
/// repeated vertices allowed) is kept in the convex normal form and uses the convex engines.
///
/// Feature indices in results: for a convex shape they index convex() (the normal form), for
/// any other shape polygon()'s global vertex numbering; input_vertex() maps either back to the
/// ring and vertex as given.
class Shape2 {
 public:
  /// Validates the outer ring and the holes (either orientation; closing vertex optional).
  /// Throws InvalidInput naming `name`, the ring (0 = outer, k = hole k) and the vertex.
  explicit Shape2(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes = {},
                  std::string_view name = "shape");
  explicit Shape2(ConvexPolygon convex);
  explicit Shape2(Polygon polygon);

  /// One `POLYGON ((...), (...))` in WKT. Throws InvalidInput "NAME:LINE: problem".
  static Shape2 from_wkt(std::string_view text, std::string_view name = "shape");
  /// A .wkt file. Throws InvalidInput "PATH:LINE: problem" (named `name` in the message).
  static Shape2 from_file(const std::filesystem::path& path, std::string_view name = "shape");

  /// Lower-dimensional shapes (docs/design.md "Lower-dimensional shapes"; src/front/shape2.cpp):
  /// a point, a segment. Pair2 takes one of them against any solid Shape2, in either role
  /// (overlap ⇔ the placement is interior to M = P ⊕ (−Q); src/polygon2/flat_depth2.hpp); two
  /// lower-dimensional shapes are InvalidInput. Result features of such a shape index its
  /// vertices (vertex 0, 1) and its one edge 0. Neither is convex(): is_convex() is false and
  /// polygon() throws InvalidInput; rings() is the one "ring" of its vertices. Throws
  /// InvalidInput naming `name` for a non-finite point or a segment whose ends coincide.
  static Shape2 point(const Vec2& p, std::string_view name = "point");
  static Shape2 segment(const Vec2& a, const Vec2& b, std::string_view name = "segment");
  /// 2 for a solid; 0 for a point, 1 for a segment.
  int dimension() const;
  /// The vertices of a point or segment (empty for a solid).
  std::span<const Vec2> flat_vertices() const;

  /// A solid convex polygon (kept in the convex normal form).
  bool is_convex() const;
  std::size_t hole_count() const;
  /// The convex normal form. Precondition: is_convex() (else throws std::logic_error).
  const ConvexPolygon& convex() const;
  /// The shape as a polygon with holes (a convex shape: its normal form as one ring; built on
  /// first use, thread-safe).
  const Polygon& polygon() const;
  /// The rings in normal form: outer counter-clockwise first, then the holes clockwise.
  std::vector<std::vector<Vec2>> rings() const;
  /// Number of vertices (of the normal form).
  std::size_t size() const;
  const std::string& name() const;
  /// Ring (0 = outer, k = hole k) and index, as given on input, of the vertex a result feature
  /// names (see the class comment).
  std::array<std::size_t, 2> input_vertex(std::size_t vertex) const;

  /// Q rotated counter-clockwise by `degrees` about its own origin (its reference point), as a
  /// new shape named NAME@DEGREES. Exact for multiples of 90° (coordinates are swapped and
  /// negated); any other angle rotates each coordinate once with the rounded cos and sin of the
  /// angle (rotation_is_exact() tells which). Throws InvalidInput for a non-finite angle, or
  /// when rounding makes the rotated rings invalid (named as for any shape).
  Shape2 rotated(double degrees) const;
  /// Whether rotated(degrees) is exact: `degrees` is a multiple of 90.
  static bool rotation_is_exact(double degrees);

  struct Data;
  /// Internal (src/front/shape2_data.hpp): the shared data and its per-shape caches.
  friend const Data& shape_data(const Shape2& s);

 private:
  Shape2() = default;
  std::shared_ptr<const Data> d_;
};

/// The no-fit polygon of P and Q: the boundary of O = {t : int P ∩ int(Q + t) ≠ ∅} as polygons
/// with holes (polygons[k][0] an outer ring, counter-clockwise; polygons[k][1..] its holes,
/// clockwise), slits (Q slides exactly in a slot of P: touching, depth 0, O on both sides) and
/// isolated points (Q fits a pocket or hole exactly), vertices rounded to the nearest double.
struct NoFitPolygonParts {
  std::vector<std::vector<std::vector<Vec2>>> polygons;
  std::vector<std::array<Vec2, 2>> slits;
  std::vector<Vec2> points;
};

/// Builds the no-fit polygon of any two 2D shapes (reduced convolution, exact; see nfp2.hpp for
/// the cost). For many queries on the same pair, use Pair2.
NoFitPolygonParts no_fit_polygon(const Shape2& P, const Shape2& Q);

/// One no-fit polygon of no_fit_polygons: P = shapes[i] rotated by rotation_i (fixed), Q =
/// shapes[j] rotated by rotation_j (moving), both about their own origins.
struct NoFitPolygonEntry {
  std::size_t i = 0, j = 0;
  double rotation_i = 0, rotation_j = 0;  ///< degrees, counter-clockwise
  NoFitPolygonParts nfp;
};

/// The no-fit polygons of a whole nesting instance (src/front/nfp_all.cpp): for every ordered pair
/// (i, j), i == j included (two copies of one item), and every allowed rotation a of shapes[i] and
/// b of shapes[j], the entry equal to no_fit_polygon(shapes[i].rotated(a), shapes[j].rotated(b))
/// (rotation 0: the shape itself). Both shapes rotate, as nesting engines (jagua-rs, SVGnest)
/// place both pieces at their own allowed orientations; for quarter turns only the difference
/// b − a matters up to an exact rotation of the answer, but the rounded rotations of other angles
/// do not commute, so every combination is built. rotations[i] lists shape i's angles in degrees
/// (rotations.size() == shapes.size()), or rotations has one list shared by every shape.
/// Order: i, then a (in list order), then j, then b. Per-shape work is done once: the rotated
/// copies (validated once each, Shape2::rotated) are shared by every pair, and so is each copy's
/// triangulation, hierarchy and convex parts in either role (made once, by the first pair that
/// needs them; issue 19 item 2); each pair goes through
/// no_fit_polygon (the same scaling to the numeric domain). Pairs run in parallel (TBB; threads
/// as Pair2's batches: 0 every core, 1 the calling thread) and every entry is bit-identical
/// whatever the thread count. progress(done, total) is called in the calling thread after each
/// chunk of pairs (about 1/256 of them, at least 64) when given; an exception it throws stops the work and
/// propagates. Throws InvalidInput for an empty or non-finite rotation list, a wrong number of
/// lists, a rotation making a shape invalid, or a pair outside the numeric domain (naming the
/// shapes, first such pair in the order above). Cost: the sum of the pairs' builds (nfp2.hpp).
std::vector<NoFitPolygonEntry> no_fit_polygons(std::span<const Shape2> shapes, std::span<const std::vector<double>> rotations,
                                               unsigned threads = 0,
                                               const std::function<void(std::size_t done, std::size_t total)>& progress = {});

/// A pair of 2D shapes, P fixed and Q moving, with the per-pair work done once. Cheap to copy;
/// all queries are const and thread-safe.
class Pair2 {
 public:
  /// Auto: two convex shapes with n + m above this use the depth field for σ.
  static constexpr std::size_t kFieldAutoSize = 64;
  /// Auto: two non-convex shapes with n·m at most this use the no-fit polygon.
  static constexpr std::size_t kNfpAutoLimit = 16384;

  Pair2(Shape2 P, Shape2 Q, Prepare prepare = Prepare::Auto);

  /// Exact: do the interiors of P and Q + t overlap (t ∈ O)? Throws InvalidInput for a
  /// non-finite t.
  bool overlapping(const Vec2& t) const;
  /// σ: the shortest move of Q + t that separates the interiors (kind Minimum).
  Depth2 minimum(const Vec2& t) const;
  /// σ_d: the shortest move along d (kind Directional). d may have any non-zero finite length.
  Depth2 along(const Vec2& t, const Vec2& d) const;
  /// Lean σ / σ_d for nesting loops: depth, translation and overlapping of minimum(t) / along(t,
  /// d), bit for bit, without features, witnesses and normal (on the no-fit polygon engine these
  /// are not computed: NoFitPolygon2::depth_value; other engines take them from the full query).
  DepthValue2 depth_value(const Vec2& t) const;
  DepthValue2 directional_depth_value(const Vec2& t, const Vec2& d) const;
  /// Complete separation along d (DHS §6; kind Separation): the shortest move along d after
  /// which Q can slide on to infinity without overlap (positive also when t ∉ O but the ray
  /// meets O later; `overlapping` tells t ∈ O).
  Depth2 separation(const Vec2& t, const Vec2& d) const;
  /// Signed distance (Distance2): > 0 apart, 0 touching, −σ(t) overlapping.
  Distance2 signed_distance(const Vec2& t) const;
  /// Shape cast (Cast2): the smallest s >= 0 with Q + t + s·d̂ touching P (+inf when never).
  Cast2 cast(const Vec2& t, const Vec2& d) const;

  // Batches: out[i] is the single call's answer for ts[i] (ds[i], or ds[0] when ds has one
  // entry), bit for bit, whatever `threads` is. threads = 0 uses every core, 1 runs in the
  // calling thread. All inputs are checked before any query runs; a bad one throws
  // InvalidInput naming its index. out must have ts.size() entries.
  void overlapping(std::span<const Vec2> ts, std::span<bool> out, unsigned threads = 0) const;
  void minimum(std::span<const Vec2> ts, std::span<Depth2> out, unsigned threads = 0) const;
  void along(std::span<const Vec2> ts, std::span<const Vec2> ds, std::span<Depth2> out,
             unsigned threads = 0) const;
  void separation(std::span<const Vec2> ts, std::span<const Vec2> ds, std::span<Depth2> out,
                  unsigned threads = 0) const;
  void signed_distance(std::span<const Vec2> ts, std::span<Distance2> out, unsigned threads = 0) const;

  /// The no-fit polygon of the pair (see NoFitPolygonParts), built on first use unless the
  /// engine holds it (thread-safe). A point or a segment against a convex shape: M itself; a
  /// segment against a non-convex shape: not built (InvalidInput).
  using NoFitPolygon = NoFitPolygonParts;
  const NoFitPolygon& no_fit_polygon() const;

  const Shape2& P() const;
  const Shape2& Q() const;
  Engine2 engine() const;

  struct Impl;

 private:
  std::shared_ptr<const Impl> impl_;
};

/// A placement of Q on a 2D trajectory: rotated counter-clockwise by `degrees` about its origin
/// (Shape2::rotated), then moved by t.
struct Placement2 {
  Vec2 t{0, 0};
  double degrees = 0;
};

/// σ along a 2D trajectory: out[k] = Pair2(P, Q.rotated(poses[k].degrees), prepare).minimum(
/// poses[k].t), bit for bit. `warm`: one Pair2 per run of equal angles (the per-pair work is done
/// once per change of angle); false: a new pair per placement (for comparison). Every placement is
/// checked first; errors name the placement's index (src/front/trajectory2.cpp).
std::vector<Depth2> trajectory(const Shape2& P, const Shape2& Q, std::span<const Placement2> poses, bool warm = true,
                               Prepare prepare = Prepare::Auto);

/// A validated convex polytope (the convex hull of a point set), with its Dobkin–Kirkpatrick
/// hierarchy built once. Cheap to copy.
class Shape3 {
 public:
  explicit Shape3(ConvexPolytope polytope);
  /// Exact convex hull. Throws InvalidInput for non-finite points or flat input (fewer than 4
  /// affinely independent points).
  static Shape3 hull(std::span<const Vec3> points, std::string_view name = "points");
  /// .obj, .off, .stl (ASCII or binary) or .ply (io::read_mesh). A file without faces: the hull
  /// of its vertices. A file with faces: a closed mesh (Mesh3::validate's checks and errors);
  /// convex → the convex path (the hull of its vertices: the same solid); not convex → a mesh
  /// shape (is_convex() false); input_index() of a mesh's polytope counts the vertices some face
  /// uses, in file order. `hull` = true: the hull of the vertices, faces ignored. Throws
  /// InvalidInput "PATH:LINE: problem" / "PATH:LINE: face F: NAME: problem". Points of affine
  /// dimension < 3 (coplanar: faces or not, or with `hull`) give Shape3::flat (io::shape3_from_points).
  static Shape3 from_file(const std::filesystem::path& path, std::string_view name = "shape", bool hull = false);
  /// A validated mesh: convex → the convex path, else a mesh shape.
  static Shape3 from_mesh(const Mesh3& mesh);

  /// Lower-dimensional shapes (docs/design.md "Lower-dimensional shapes"; src/front/shape3_flat.cpp):
  /// a point, a segment, or the flat convex polygon spanned by coplanar points (`flat` takes any
  /// point set of dimension 0, 1 or 2 and keeps its extreme points). Pair3 takes one of them
  /// against a solid shape (overlap ⇔ the placement is interior to M = P ⊕ (−Q), M being
  /// full-dimensional); two lower-dimensional shapes are InvalidInput. Throws InvalidInput
  /// naming `name` for non-finite or empty input, or (flat) points spanning a solid.
  static Shape3 point(const Vec3& p, std::string_view name = "point");
  static Shape3 segment(const Vec3& a, const Vec3& b, std::string_view name = "segment");
  static Shape3 flat(std::span<const Vec3> points, std::string_view name = "points");
  /// 3 for a solid (a rounded shape included); 0, 1, 2 for a point, a segment, a flat polygon.
  int dimension() const;
  /// The vertices of a lower-dimensional shape (one point; the two ends; the polygon's extreme
  /// points in cyclic order): result features of such a shape index these (vertex j, edge j from
  /// vertex j to j + 1, face 0). Empty for a solid.
  std::span<const Vec3> flat_vertices() const;
  /// Primitives (docs/design.md "Primitives"; src/front/shape3_primitives.cpp), centred at the
  /// origin: box(X, Y, Z) the polytope of half extents X, Y, Z; sphere(R) a point ⊕ ball;
  /// capsule(R, H) the segment (0,0,−H)–(0,0,H) ⊕ ball; rounded(core, R) any convex shape (solid,
  /// point, segment, flat polygon) ⊕ ball of radius R, R >= 0. Throws InvalidInput naming `name`
  /// for a non-finite or non-positive size (R = 0 allowed for rounded: the core itself).
  static Shape3 box(double hx, double hy, double hz, std::string_view name = "box");
  static Shape3 sphere(double r, std::string_view name = "sphere");
  static Shape3 capsule(double r, double h, std::string_view name = "capsule");
  static Shape3 rounded(const Shape3& core, double r, std::string_view name = "rounded");
  /// Curved primitives (src/front/shape3_curved.cpp), centred at the origin: cylinder(R, H) of
  /// radius R about the z axis, z in [−H, H]; cone(R, H) with base radius R at z = −H and apex
  /// (0, 0, H); ellipsoid(A, B, C) of semi-axes A, B, C along x, y, z. Pair3 answers any pair
  /// involving one of them (also rounded(curved, r)) by the certified support-function engine
  /// (src/primitives/support3.cpp): lower_bound <= the true value <= upper_bound, relative gap
  /// about 1e-12 or the rounding floor (docs/robustness.md "Curved primitives"). Throws
  /// InvalidInput naming `name` for a non-finite or non-positive size.
  static Shape3 cylinder(double r, double h, std::string_view name = "cylinder");
  static Shape3 cone(double r, double h, std::string_view name = "cone");
  static Shape3 ellipsoid(double a, double b, double c, std::string_view name = "ellipsoid");
  /// Internal (the engines): a curved primitive's parameters (also under rounding), else null.
  const primitives::Curved3* curved() const { return curved_.get(); }
  static Shape3 from_curved(std::shared_ptr<const primitives::Curved3> c);
  /// The rounding radius (0 for a shape without rounding) and the core (the shape without it).
  double radius() const { return radius_; }
  Shape3 core() const;
  /// Internal (the engines): a lower-dimensional shape's normal form, null for a solid.
  explicit Shape3(convex3::FlatShape3 flat);
  const convex3::FlatShape3* flat_shape() const;

  /// The convex polytope; for a non-convex mesh shape, the hull of its vertices. A
  /// lower-dimensional shape has none: throws InvalidInput.
  const ConvexPolytope& polytope() const;
  std::size_t size() const;
  const std::string& name() const;
  /// False only for a non-convex mesh shape (Pair3 answers on its convex decomposition).
  bool is_convex() const;
  /// The mesh of a shape made from a mesh (from_file with faces, from_mesh), else null.
  const Mesh3* mesh() const;

 private:
  Shape3() = default;
  std::shared_ptr<const ConvexPolytope> p_;
  std::shared_ptr<const Mesh3> mesh_;
  std::shared_ptr<const convex3::FlatShape3> flat_;  // a lower-dimensional shape (p_ null)
  std::shared_ptr<const primitives::Curved3> curved_;  // a curved primitive (p_, flat_ null)
  double radius_ = 0;  // a rounded shape: this shape's core (p_ or flat_) ⊕ ball of radius_
  std::string rounded_name_;
};

/// Per-caller state of Pair3's warm start for coherent motion (survey §3.3): the facet of M the
/// previous answer ended on. Pair3 is const and shared between threads, so the state lives with
/// the caller: one WarmStart3 per trajectory (per thread). Small and copyable; a state used with
/// another pair is ignored (that query starts cold). It never changes an answer, only its cost.
class WarmStart3 {
 public:
  /// Forgets the previous answer: the next query starts cold.
  void reset() { valid_ = false; }
  bool valid() const { return valid_; }

 private:
  friend class Pair3;
  const void* p_ = nullptr;
  const void* q_ = nullptr;
  std::array<int, 32> pairs_{};  // (P vertex, Q vertex): the previous facet of M and its neighbours
  int count_ = 0;
  bool valid_ = false;
};

/// A pair of 3D shapes, P and Q each with a pose (only the relative pose matters; results
/// are in the world frame): polytopes (src/convex3/), a lower-dimensional shape against a solid
/// one (src/convex3/flat3.cpp: exact), rounded shapes — spheres, capsules, core ⊕ ball — through
/// their cores' signed distance (src/primitives/rounded3.cpp: sd one rounding from the exact core
/// value, overlap and touching exact; σ_d and casts certified brackets: lower_bound <= exit <=
/// upper_bound = depth, a cast's distance the upper end of its bracket [lower_bound, upper_bound],
/// its hit exact); curved primitives — cylinders, cones, ellipsoids — by the certified
/// support-function engine (src/primitives/support3.cpp: every answer a bracket,
/// docs/robustness.md "Curved primitives"). Queries are const and thread-safe.
///
/// Meshes (either shape non-convex; docs/design.md "Meshes", src/mesh3/mesh_pair.hpp): answered
/// on the pieces of Mesh3::decomposition() (a convex shape is one piece), built on the first query
/// that needs them, once per pair, thread-safe (construction never decomposes; an InvalidInput of
/// the pieces — numeric domain, too thin — comes from that query, prefixed with the mesh's source).
/// overlapping, along, separation and signed_distance when apart or touching are exact; minimum
/// gives certified bounds (lower = the deepest overlapping piece pair's σ, upper = the least σ_d
/// over a few directions, depth = upper with its translation; lower_bound == upper_bound when
/// they meet within 16 ulps); signed_distance when overlapping: distance = lower_bound = −upper,
/// upper_bound = −lower. Results name the pieces (piece_p, piece_q) whose vertices / half-edges
/// / triangles feature_p, feature_q index. When a decomposition has rounded pieces
/// (ConvexDecomposition3::rounded_pieces > 0) the answers are exact for the rounded pieces, which
/// may differ from the mesh by slivers of ½ ulp. `candidates` counts the piece pairs descended
/// (σ_d, separation) or sums the convex work (σ). cast is exact: the least convex cast over the
/// box-pruned piece pairs (src/mesh3/mesh_cast.cpp). The warm start is ignored on meshes.
/// A non-convex mesh against a point, rounded shape or curved primitive, either role
/// (src/mesh3/mesh_mixed.hpp, docs/design.md): a point is answered exactly on the mesh's triangles
/// (its signed distance field; features of the mesh none, pieces −1); the other shapes by one
/// convex pair per piece — σ_d by a walk over overlap tests (moving by the answer separates),
/// brackets as their convex pairs', σ as bounds. A segment: overlap and σ_d exact on the mesh's
/// triangles in rationals (src/mesh3/mesh_segment.cpp: the pieces' union misses a segment lying
/// in a face two pieces share), distance and cast by the pieces, σ as bounds. A flat convex polygon:
/// the same (src/mesh3/mesh_flat.cpp: overlap by exact chords through its cells, σ_d by ∂O's crossings).
/// Costs: docs/benchmarks.md.
class Pair3 {
 public:
  Pair3(Shape3 P, Shape3 Q, Prepare prepare = Prepare::Auto);

  /// Exact: do the interiors of the posed P and Q overlap?
  bool overlapping(const Pose3& pose_p, const Pose3& pose_q) const;
  /// σ, exact (lower_bound == upper_bound == depth); meshes: certified bounds (class comment).
  Depth3 minimum(const Pose3& pose_p, const Pose3& pose_q) const;
  /// σ_d along d (world frame), exact.
  Depth3 along(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const;
  /// Complete separation along d: for convex shapes the ray leaves M once, so this is σ_d with
  /// kind Separation; for meshes the last exit of the ray from O (0 when it never meets O).
  Depth3 separation(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const;
  /// Signed distance (Distance3): > 0 apart, 0 touching, −σ overlapping; exact.
  Distance3 signed_distance(const Pose3& pose_p, const Pose3& pose_q) const;
  /// Shape cast (Cast3) along d (world frame): the smallest s >= 0 with Q + s·d̂ touching P.
  Cast3 cast(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const;

  /// σ warm-started from the previous answer held in `warm` (updated): equal to
  /// minimum(pose_p, pose_q) bit for bit in every field but `candidates` (the support queries
  /// done), because σ's answer is a function of M's nearest facet alone (the least canonical
  /// features among the facets at distance σ; src/convex3/minimum_expand.cpp). About half the
  /// support queries after a small move; measured time about the same as cold on real hulls
  /// (docs/benchmarks.md); shapes over 128 vertices always start cold.
  Depth3 minimum(const Pose3& pose_p, const Pose3& pose_q, WarmStart3& warm) const;
  /// σ along a trajectory: out[i] = minimum(pose_p, poses_q[i]), each warm-started from the
  /// previous one (`warm` false: each cold, for comparison), in the calling thread. All poses are
  /// checked first (InvalidInput naming the index).
  std::vector<Depth3> trajectory(const Pose3& pose_p, std::span<const Pose3> poses_q, bool warm = true) const;

  // Batches (as Pair2's): P at identity, or at pose_p for every query.
  void overlapping(std::span<const Pose3> poses_q, std::span<bool> out, unsigned threads = 0) const;
  void minimum(std::span<const Pose3> poses_q, std::span<Depth3> out, unsigned threads = 0) const;
  void along(std::span<const Pose3> poses_q, std::span<const Vec3> ds, std::span<Depth3> out,
             unsigned threads = 0) const;
  void minimum(const Pose3& pose_p, std::span<const Pose3> poses_q, std::span<Depth3> out,
               unsigned threads = 0) const;
  void along(const Pose3& pose_p, std::span<const Pose3> poses_q, std::span<const Vec3> ds,
             std::span<Depth3> out, unsigned threads = 0) const;
  void signed_distance(std::span<const Pose3> poses_q, std::span<Distance3> out, unsigned threads = 0) const;
  void signed_distance(const Pose3& pose_p, std::span<const Pose3> poses_q, std::span<Distance3> out,
                       unsigned threads = 0) const;

  const Shape3& P() const { return P_; }
  const Shape3& Q() const { return Q_; }

 private:
  Shape3 P_, Q_;
  // The numeric domain (src/front/scale.hpp): the engines see P_, Q_ scaled by 2^-scale_exp_
  // (the same objects unless the pair lies outside the comfort band).
  int scale_exp_ = 0;
  Shape3 engine_P_, engine_Q_;
  std::shared_ptr<const mesh3::LazyMeshPair> mesh_;  // either shape non-convex: pieces on first use (pair3_mesh.cpp)
  std::shared_ptr<const mesh3::MixedPair> mixed_;  // a mesh against a point / rounded / curved shape
  Depth3 min_engine(const Pose3& pose_p, const Pose3& pose_q) const;
  Depth3 along_engine(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const;
  Distance3 distance_engine(const Pose3& pose_p, const Pose3& pose_q) const;
};

}  // namespace pendepth

// PD_g, the generalized depth under rigid motion (rotation and translation): motion.hpp.
#include <pendepth/motion.hpp>
