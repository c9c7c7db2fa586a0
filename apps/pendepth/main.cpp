// pendepth — command-line tool (docs/design.md §3): argument parsing plus front-door calls
// (include/pendepth/pendepth.hpp).
//
//   pendepth depth P Q [--offset X,Y[,Z]] [--direction X,Y[,Z]] [--separate] [--json] [--svg FILE]
//                      [--html FILE] [--rotate-q QW,QX,QY,QZ | DEG (2D)] [--rotate-p QW,QX,QY,QZ]
//                      [--generalized] [--approximate DELTA] [--hull]
//   pendepth batch P Q --queries FILE [--json] [--threads N] [--progress] [--rotate-q ...|DEG] [--rotate-p ...]
//   (--hull: 3D, on depth, batch, distance, cast, trajectory)
//   pendepth nfp P Q [--json]
//   pendepth distance P Q [--offset X,Y[,Z]] [--rotate-q ...] [--rotate-p ...] [--json]
//   pendepth cast P Q [--offset X,Y[,Z]] --direction X,Y[,Z] [--rotate-q ...] [--rotate-p ...] [--json]
//   pendepth batch P Q --queries FILE --signed ...   (signed distances: distance,tx,ty[,tz])
//   pendepth trajectory P Q --poses FILE [--json] [--cold]
//   pendepth nfp-all INSTANCE.json [--rotations A,B,...] [--threads N] [--progress] [--json]
//
// Exit status: 0 success, 2 bad input (one line on stderr naming file, line and problem),
// 3 an output that cannot be written (standard output or --svg FILE: full disk, closed pipe,
// a path that cannot be created), 1 internal error. Shapes: .wkt (2D polygons); .obj, .off, .stl,
// .ply (3D, as Shape3::from_file: a file without faces is a point set, its hull; with faces a
// closed mesh, convex → the convex path, else a mesh shape, answered on its convex pieces; --hull
// forces the hull); `-` (standard input) or a path without an extension (a FIFO, /dev/stdin, a
// process substitution) is recognised by its content. P and Q must have the same dimension. Rotations: 3D quaternions for P and Q; 2D an angle in degrees for Q only.
//
// Engines: Pair2 / Pair3 pick them. `depth` asks one question, so it prepares only what the query
// needs (Prepare::Queries: two non-convex polygons are answered per query, nothing built);
// `batch` prepares everything once (Prepare::Full: the depth field, the no-fit polygon) and
// answers the queries in parallel batches; `--svg` draws the no-fit polygon of non-convex pairs.
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>
#include <pendepth/nesting.hpp>
#include <pendepth/pendepth.hpp>
#include <pendepth/shape_spec.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <vector>
#include <span>
#include <string>

#include <unistd.h>

namespace {

using pendepth::Depth2;
using pendepth::Depth3;
using pendepth::InvalidInput;
using pendepth::Pair2;
using pendepth::Pair3;
using pendepth::Pose3;
using pendepth::Shape2;
using pendepth::Shape3;
using pendepth::Vec2;
using pendepth::Vec3;
namespace io = pendepth::io;

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

constexpr const char* kStdin = "<stdin>";  // the source name of `-` in messages

// The dimension of a shape file by its extension: 2 (.wkt) or 3 (.obj, .off, .stl, .ply); 0 for `-`
// and paths without an extension (known once the content is read).
int shape_dimension(const std::string& path) {
  if (const auto spec = io::parse_shape_spec(path)) return spec->dimension;  // sphere:R, point:X,Y, ...
  if (path == "-" || std::filesystem::path(path).extension().empty()) return 0;
  if (const auto f = io::shape_format_of(path)) return *f == io::ShapeFormat::Wkt ? 2 : 3;
  throw InvalidInput(path + ": unknown shape format '" + lower_extension(path) +
                     "' (expected .wkt, .obj, .off, .stl or .ply)");
}

void check_same_dimension(const std::string& p, int dp, const std::string& q, int dq) {
  if (dp != 0 && dq != 0 && dp != dq)
    throw InvalidInput(q + ": Q is a " + std::to_string(dq) + "D shape but P (" + p + ") is " + std::to_string(dp) +
                       "D; both must be 2D (.wkt) or both 3D (.obj, .off, .stl, .ply)");
}

// Standard input may be read once: at most one of the file arguments is `-`.
void check_one_stdin(std::initializer_list<const std::string*> args) {
  int n = 0;
  for (const std::string* a : args) n += *a == "-";
  if (n > 1) throw InvalidInput("only one file argument can be '-' (standard input is read once)");
}

// A shape argument read once: a path, or `-` for standard input. The format comes from the
// extension, else (standard input, a FIFO or process substitution without one) from the content.
struct ShapeText {
  std::string source;  // the path as given, or <stdin>
  io::ShapeFormat format = io::ShapeFormat::Wkt;
  std::string text;
  std::optional<io::ShapeSpec> spec;  // a primitive spec instead of a file (text empty)
  int dimension() const { return spec ? spec->dimension : format != io::ShapeFormat::Wkt ? 3 : 2; }
};

ShapeText load_shape(const std::string& arg) {
  ShapeText s;
  s.source = arg == "-" ? kStdin : arg;
  if ((s.spec = io::parse_shape_spec(arg))) {
    s.format = io::ShapeFormat::Obj;
    return s;
  }
  if (arg != "-" && shape_dimension(arg) != 0) {
    s.format = *io::shape_format_of(arg);
    s.text = io::read_text_file(arg);
    return s;
  }
  s.text = arg == "-" ? io::read_stream(std::cin, kStdin) : io::read_text_file(arg);
  const auto f = io::guess_shape_format(s.text);
  if (!f)
    throw InvalidInput(s.source + ": cannot tell the shape format from the content (expected a WKT POLYGON, OBJ, "
                                  "OFF, STL or PLY; name the file .wkt, .obj, .off, .stl or .ply)");
  s.format = *f;
  return s;
}

// P and Q, read once each, of the same dimension (checked by extension before anything is read).
std::pair<ShapeText, ShapeText> load_pair(const std::string& p, const std::string& q) {
  check_same_dimension(p, shape_dimension(p), q, shape_dimension(q));
  ShapeText P = load_shape(p), Q = load_shape(q);
  check_same_dimension(P.source, P.dimension(), Q.source, Q.dimension());
  return {std::move(P), std::move(Q)};
}

Shape2 make_shape2(const ShapeText& s, std::string_view name) {
  if (s.spec) return io::shape2_from_spec(*s.spec, name);  // point:X,Y, segment:X1,Y1,X2,Y2
  io::Shape2 r = io::shape2_from_wkt(io::parse_wkt_polygon(s.text, s.source), s.source, name);
  return r.convex ? Shape2(std::move(*r.convex)) : Shape2(std::move(*r.polygon));
}

// A 3D shape as Shape3::from_file reads it (docs/design.md §3): a file without faces is a point
// set (its hull, or Shape3::flat when its points are coplanar, as a file with faces whose points
// are); a file with faces a validated closed mesh (convex → the convex path, else a mesh
// shape, answered on its convex decomposition; --html refuses it). `hull` (--hull):
// the hull of the vertices, faces ignored and not validated.
Shape3 make_shape3(const ShapeText& s, std::string_view name, bool hull) {
  if (s.spec) return io::shape3_from_spec(*s.spec, name, hull);
  if (hull) return io::shape3_from_points(io::parse_mesh_points(s.text, s.format, s.source), s.source, name);
  const io::MeshFile file = io::parse_mesh(s.text, io::mesh_format(s.format, s.source), s.source);
  if (file.faces() == 0 || io::affine_dimension(file.points) < 3)  // a point set, or flat: Shape3::flat
    return io::shape3_from_points(file.points, file.source, name);
  return Shape3::from_mesh(pendepth::Mesh3::validate(file, name));
}

// The pair of 3D shapes; an error about a mesh shape (its pieces' scale) is prefixed with its file's name.
Pair3 make_pair3(const ShapeText& p, const ShapeText& q, bool hull, pendepth::Prepare prepare = pendepth::Prepare::Auto) {
  Shape3 P = make_shape3(p, "P", hull), Q = make_shape3(q, "Q", hull);
  const ShapeText* mesh = !P.is_convex() ? &p : !Q.is_convex() ? &q : nullptr;
  try {
    return Pair3(std::move(P), std::move(Q), prepare);
  } catch (const InvalidInput& e) {
    if (!mesh) throw;
    throw InvalidInput(mesh->source + ": " + e.what());
  }
}

// The polytope a 3D result's features index. A mesh pair's answer: the piece named by piece_p /
// piece_q (Mesh3::decomposition().pieces; a convex shape is piece 0). Shapes without a polytope
// (points, segments, flat polygons and the primitives built on them: spheres, capsules;
// Shape3::flat_shape) are formatted against a stand-in polytope with their features printed as
// "none" (the formatters index a polytope's vertices), and the summary names them instead of
// counting hull vertices. Else the shape's polytope.
const pendepth::ConvexPolytope& shown(const Shape3& s, int piece = -1) {
  static const pendepth::ConvexPolytope stand_in = pendepth::ConvexPolytope::hull(
      std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, "primitive");
  if (s.flat_shape() || s.curved()) return stand_in;  // (curved primitives: no polytope either)
  return piece < 0 || s.is_convex() ? s.polytope() : s.mesh()->decomposition().pieces[static_cast<std::size_t>(piece)];
}
template <class R>
R shown(R r, const Pair3& pair) {
  if (pair.P().flat_shape() || pair.P().curved()) r.feature_p = {};
  if (pair.Q().flat_shape() || pair.Q().curved()) r.feature_q = {};
  return r;
}
std::string shown_summary(std::string s, const Pair3& pair) {
  for (const auto& [tag, shape] : {std::pair{"P ", &pair.P()}, std::pair{"Q ", &pair.Q()}}) {
    if (!shape->flat_shape() && !shape->curved()) continue;
    const int dim = shape->dimension();
    const std::string what = dim == 0   ? "a point"
                             : dim == 1 ? "a segment"
                             : dim == 2 ? "a flat polygon of " + std::to_string(shape->flat_vertices().size()) + " vertices"
                                        : "a primitive";
    const std::string from = std::string(tag) + "4 hull vertices", to = std::string(tag) + shape->name() + " (" + what + ")";
    if (const auto k = s.find(from, s.find("shapes:")); k != std::string::npos) s.replace(k, from.size(), to);
  }
  return s;
}

// --hull is about 3D files' faces: a 2D pair rejects it.
void reject_hull2(bool hull) {
  if (hull) throw InvalidInput("--hull: applies to 3D mesh files only (.obj, .off, .stl, .ply)");
}

constexpr const char* kHullHelp =
    "3D: take the convex hull of each file's vertices, faces ignored and not checked (without it a file "
    "with faces must be a closed mesh; a non-convex one is answered on its exact convex decomposition, built when "
    "a query needs it — minutes for thousands of reflex edges; points, and a segment's σ_d, never need it)";


// N comma-separated numbers from an option value (`names` as in "X,Y"); the option name goes
// into the error message.
template <int N>
Eigen::Matrix<double, N, 1> parse_numbers(const std::string& text, const char* option, const char* names) {
  static constexpr const char* kCount[] = {"", "one", "two", "three", "four"};
  const std::string expected = std::string(option) + ": expected " + names + " (" + kCount[N] + (N == 1 ? " number" : " numbers") + "), got '" + text + "'";
  Eigen::Matrix<double, N, 1> v;
  int count = 0;
  std::string_view rest = text;
  for (;;) {
    const std::size_t comma = rest.find(',');
    std::string_view f = rest.substr(0, comma);
    while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
    while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
    if (!f.empty() && f.front() == '+') f.remove_prefix(1);
    double x = 0;
    auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), x);
    if (f.empty() || ec == std::errc::invalid_argument || ptr != f.data() + f.size()) throw InvalidInput(expected);
    if (ec == std::errc::result_out_of_range || !std::isfinite(x))
      throw InvalidInput(std::string(option) + ": non-finite number in '" + text + "'");
    if (count < N) v[count] = x;
    ++count;
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  if (count != N) throw InvalidInput(expected);
  return v;
}

Vec2 parse_vec(const std::string& text, const char* option) { return parse_numbers<2>(text, option, "X,Y"); }
Vec3 parse_vec3(const std::string& text, const char* option) { return parse_numbers<3>(text, option, "X,Y,Z"); }

// --rotate-p / --rotate-q: a quaternion w,x,y,z, normalised by the library; zero is bad input. Empty text: the identity.
Eigen::Quaterniond parse_rotation(const std::string& text, const char* option) {
  if (text.empty()) return Eigen::Quaterniond::Identity();
  const Eigen::Vector4d q = parse_numbers<4>(text, option, "QW,QX,QY,QZ");
  if (q.isZero(0)) throw InvalidInput(std::string(option) + ": the quaternion is zero (it must be a rotation)");
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

// Standard output, checked: a full disk or a closed pipe (SIGPIPE is ignored) is a WriteError,
// never a silent exit 0 with the answers lost.
void write_stdout(const std::string& s) {
  errno = 0;
  if (!s.empty() && std::fwrite(s.data(), 1, s.size(), stdout) != s.size())
    throw io::WriteError(std::string("standard output: cannot write (") + (errno ? std::strerror(errno) : "write error") + ")");
}

void flush_stdout() {
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout))
    throw io::WriteError(std::string("standard output: cannot write (") + (errno ? std::strerror(errno) : "write error") + ")");
}

// ---- output of 2D results: the io writers take the shapes' own classes ----

// A point or a segment (Shape2::point, segment) has neither a ConvexPolygon nor a Polygon.
io::Features2 features_of(const Shape2& s) {
  if (s.dimension() < 2) return io::Features2{nullptr, nullptr, s.size()};
  return s.is_convex() ? io::Features2{&s.convex(), nullptr} : io::Features2{nullptr, &s.polygon()};
}

void append_json(std::string& out, const Depth2& r, const Shape2& P, const Shape2& Q) {
  if (P.dimension() < 2 || Q.dimension() < 2) return io::append_json(out, r, features_of(P), features_of(Q));
  if (P.is_convex() && Q.is_convex()) io::append_json(out, r, P.convex(), Q.convex());
  else if (Q.is_convex()) io::append_json(out, r, P.polygon(), Q.convex());
  else if (P.is_convex()) io::append_json(out, r, P.convex(), Q.polygon());
  else io::append_json(out, r, P.polygon(), Q.polygon());
}

std::string summary(const Depth2& r, const Shape2& P, const Shape2& Q) {
  if (P.dimension() < 2 || Q.dimension() < 2) return io::summary(r, features_of(P), features_of(Q));
  if (P.is_convex() && Q.is_convex()) return io::summary(r, P.convex(), Q.convex());
  if (Q.is_convex()) return io::summary(r, P.polygon(), Q.convex());
  if (P.is_convex()) return io::summary(r, P.convex(), Q.polygon());
  return io::summary(r, P.polygon(), Q.polygon());
}

// The picture: P and Q in their own frames; the configuration panel shows M for two convex shapes,
// else the no-fit polygon (cl O, slits, exact fits).
void write_svg(const std::string& path, const Pair2& pair, const Vec2& t, const Depth2& r, const std::optional<Vec2>& d) {
  const Shape2 &P = pair.P(), &Q = pair.Q();
  if (P.is_convex() && Q.is_convex()) {
    io::write_svg(path, P.convex(), Q.convex(), t, r, io::SvgOptions{d, true});
    return;
  }
  io::SvgScene scene;
  scene.P = P.rings();
  scene.Q = Q.rings();
  if (pair.engine() != pendepth::Engine2::Flat || P.is_convex() || Q.is_convex() || P.dimension() + Q.dimension() == 2) {
    const pendepth::NoFitPolygonParts& nfp = pair.no_fit_polygon();  // a segment and a non-convex shape: none
    for (const auto& poly : nfp.polygons) scene.config.insert(scene.config.end(), poly.begin(), poly.end());
    scene.config_segments = nfp.slits;
    scene.config_points = nfp.points;
  }
  scene.config_label = "no-fit polygon: cl O, slits, exact fits";
  scene.config_target = "t + v on ∂O";
  io::write_svg(path, scene, t, r, io::SvgOptions{d, true});
}

struct DepthArgs {
  std::string p, q, offset, direction, svg, html, rotate_p, rotate_q, approximate;
  bool separate = false, json = false, generalized = false, hull = false;
};

// ---- 2D rotations of Q (issue 19 item 3) and the generalized depth PD_g (issue 18) ----

void reject_rotations(const std::string& rotate_p, const std::string& rotate_q) {
  if (!rotate_q.empty()) throw InvalidInput("--rotate-q: rotations apply to 3D shapes only");
  if (!rotate_p.empty()) throw InvalidInput("--rotate-p: 2D rotates Q only (--rotate-q DEG)");
}

// Q turned by --rotate-q DEG (Shape2::rotated: exact for multiples of 90°, else rounded).
Shape2 rotate_q2(const Shape2& Q, const std::string& degrees) {
  if (degrees.empty()) return Q;
  return Q.rotated(parse_numbers<1>(degrees, "--rotate-q", "DEG")[0]);
}

// The note a rounded rotation owes the reader (human output), and its JSON field.
std::string rotation_note(const std::string& degrees) {
  if (degrees.empty() || Shape2::rotation_is_exact(parse_numbers<1>(degrees, "--rotate-q", "DEG")[0])) return "";
  return "note: Q's coordinates were rotated by " + degrees + " degrees and rounded to doubles (not a multiple of 90)\n";
}
void add_rotation_field(std::string& json_object, const std::string& degrees) {
  if (degrees.empty()) return;
  while (!json_object.empty() && json_object.back() != '}') json_object.pop_back();
  json_object.pop_back();
  json_object += std::string(",\"rotation_exact\":") +
                 (Shape2::rotation_is_exact(parse_numbers<1>(degrees, "--rotate-q", "DEG")[0]) ? "true" : "false") + "}";
}

std::string num(double x) {
  if (!std::isfinite(x)) return x > 0 ? "1e999" : "-1e999";  // an overflowed length (docs/robustness.md)
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

int run_generalized2(const DepthArgs& a, const Shape2& P, const Shape2& Q, const Vec2& t) {
  const pendepth::GeneralizedDepth2 r = pendepth::generalized_depth(P, Q, t);
  std::string out;
  if (a.json) {
    out = "{\"kind\":\"generalized\",\"metric\":\"max_displacement\",\"overlapping\":" +
          std::string(r.overlapping ? "true" : "false") + ",\"depth\":" + num(r.depth) + ",\"lower_bound\":" +
          num(r.lower_bound) + ",\"upper_bound\":" + num(r.upper_bound) + ",\"angle\":" + num(r.angle) +
          ",\"translation\":[" + num(r.translation.x()) + "," + num(r.translation.y()) + "],\"sigma\":" + num(r.sigma) +
          ",\"sigma_at_angle\":" + num(r.sigma_at_angle) + ",\"converged\":" + (r.converged ? "true" : "false") +
          ",\"probes\":" + std::to_string(r.probes) + ",\"intervals\":" + std::to_string(r.intervals) + ",\"angle_exact\":" + (r.rotation_exact ? "true" : "false") + "}";
    add_rotation_field(out, a.rotate_q);
    out += '\n';
  } else {
    out = rotation_note(a.rotate_q) + "generalized depth PD_g (largest displacement of Q's points): " + num(r.depth) +
          "\n  certified bounds: [" + num(r.lower_bound) + ", " + num(r.upper_bound) + "]" +
          (r.converged ? "" : " (not converged: the gap is above the tolerance)") + "\n  motion: rotate Q by " +
          num(r.angle) + " degrees about its reference point" + (r.rotation_exact ? "" : " (coordinates rounded)") +
          ", then translate by (" + num(r.translation.x()) + ", " + num(r.translation.y()) + ")\n  translational depth: " +
          num(r.sigma) + " (at that angle: " + num(r.sigma_at_angle) + "); angles probed: " + std::to_string(r.probes) +
          ", angle intervals bounded: " + std::to_string(r.intervals) + "\n";
  }
  write_stdout(out);
  return 0;
}

int run_generalized3(const DepthArgs& a, const Shape3& P, const Pose3& pose_p, const Shape3& Q, const Pose3& pose_q) {
  const pendepth::GeneralizedDepth3 r = pendepth::generalized_depth(P, pose_p, Q, pose_q);
  const auto& w = r.rotation;
  std::string out;
  if (a.json) {
    out = "{\"kind\":\"generalized\",\"metric\":\"max_displacement\",\"overlapping\":" +
          std::string(r.overlapping ? "true" : "false") + ",\"depth\":" + num(r.depth) + ",\"lower_bound\":" +
          num(r.lower_bound) + ",\"upper_bound\":" + num(r.upper_bound) + ",\"rotation\":[" + num(w.w()) + "," +
          num(w.x()) + "," + num(w.y()) + "," + num(w.z()) + "],\"translation\":[" + num(r.translation.x()) + "," +
          num(r.translation.y()) + "," + num(r.translation.z()) + "],\"sigma\":" + num(r.sigma) +
          ",\"converged\":" + (r.converged ? "true" : "false") + ",\"probes\":" + std::to_string(r.probes) + "}\n";
  } else {
    const bool convex = P.is_convex() && Q.is_convex();
    out = "generalized depth PD_g (largest displacement of Q's points): " + num(r.depth) +
          (convex ? " = σ (convex polytopes)" : " (meshes: the best motion found; translational σ " + num(r.sigma) + ")") +
          "\n  certified bounds: [" + num(r.lower_bound) + ", " + num(r.upper_bound) + "]" +
          (r.converged ? "" : " (not converged: the gap is reported)") + "\n  motion: rotation (w,x,y,z) (" +
          num(w.w()) + ", " + num(w.x()) + ", " + num(w.y()) + ", " + num(w.z()) + "), then translate by (" +
          num(r.translation.x()) + ", " + num(r.translation.y()) + ", " + num(r.translation.z()) + ")\n";
  }
  write_stdout(out);
  return 0;
}

void check_generalized(const DepthArgs& a) {
  if (!a.generalized) return;
  if (!a.direction.empty()) throw InvalidInput("--generalized: asks for the minimum depth under rigid motion; drop --direction");
  if (!a.svg.empty() || !a.html.empty()) throw InvalidInput("--generalized: --svg and --html are not drawn for it");
}

// --approximate DELTA: certified (1+δ)-approximate σ of the point sets' hulls, no hull built
// (include/pendepth/approximate.hpp).
int run_approximate3(const DepthArgs& a, const ShapeText& p, const ShapeText& q, const Pose3& pose_p,
                     const Pose3& pose_q) {
  if (!a.direction.empty() || !a.html.empty() || a.generalized)
    throw InvalidInput("--approximate: answers σ only (no --direction, --html, --generalized)");
  if (p.spec || q.spec)
    throw InvalidInput("--approximate: reads point files; '" + (p.spec ? p.source : q.source) + "' is a primitive spec");
  double delta = 0;
  const char* end = a.approximate.data() + a.approximate.size();
  if (auto [ptr, ec] = std::from_chars(a.approximate.data(), end, delta); ec != std::errc() || ptr != end)
    throw InvalidInput("--approximate: '" + a.approximate + "' is not a number");
  const auto P = io::parse_mesh_points(p.text, p.format, p.source), Q = io::parse_mesh_points(q.text, q.format, q.source);
  const pendepth::ApproxDepth3 r = pendepth::approximate_minimum_depth(P, pose_p, Q, pose_q, delta);
  std::string out;
  auto vec = [&](const Vec3& v) {
    out += '[';
    for (int k = 0; k < 3; ++k) io::append_double(out, v[k]), out += k < 2 ? "," : "]";
  };
  auto num = [&](const char* key, double v, bool last = false) {
    out += a.json ? std::string("\"") + key + "\":" : std::string(key) + " ";
    io::append_double(out, v);
    out += a.json ? (last ? "" : ",") : "\n";
  };
  if (a.json) out += '{';
  num("depth", r.depth), num("lower_bound", r.lower_bound), num("upper_bound", r.upper_bound);
  out += a.json ? "\"normal\":" : "normal ", vec(r.normal), out += a.json ? "," : "\n";
  out += a.json ? "\"translation\":" : "translation ", vec(r.translation), out += a.json ? "," : "\n";
  out += a.json ? "\"converged\":" : "converged ", out += r.converged ? "true" : "false", out += a.json ? "," : "\n";
  out += a.json ? "\"overlapping\":" : "overlapping ", out += r.overlapping ? "true" : "false", out += a.json ? "," : "\n";
  num("kernel_p", double(r.kernel_p)), num("kernel_q", double(r.kernel_q), true);
  out += a.json ? "}\n" : "";
  write_stdout(out);
  return 0;
}

int run_depth3(const DepthArgs& a, const ShapeText& p, const ShapeText& q) {
  if (!a.svg.empty()) throw InvalidInput("--svg draws 2D shapes only");
  const Eigen::Quaterniond rq = parse_rotation(a.rotate_q, "--rotate-q");
  const Eigen::Quaterniond rp = parse_rotation(a.rotate_p, "--rotate-p");
  const Vec3 t = a.offset.empty() ? Vec3(0, 0, 0) : parse_vec3(a.offset, "--offset");
  std::optional<Vec3> d;
  if (!a.direction.empty()) {
    d = parse_vec3(a.direction, "--direction");
    if (d->isZero(0)) throw InvalidInput("--direction: the direction is zero");
  }
  if (!a.approximate.empty()) return run_approximate3(a, p, q, Pose3(rp, Vec3::Zero()), Pose3(rq, t));
  const Pair3 pair = make_pair3(p, q, a.hull);
  const Pose3 pose_p(rp, Vec3::Zero()), pose_q(rq, t);
  if (!a.html.empty() && (!pair.P().is_convex() || !pair.Q().is_convex()))
    throw InvalidInput("--html: convex shapes only (a non-convex mesh: add --hull)");
  if (a.generalized) return run_generalized3(a, pair.P(), pose_p, pair.Q(), pose_q);
  const Depth3 r = !d ? pair.minimum(pose_p, pose_q)
                      : a.separate ? pair.separation(pose_p, pose_q, *d) : pair.along(pose_p, pose_q, *d);
  if (!a.html.empty())
    io::write_html(a.html, io::depth_scene3(pair.P().polytope(), pose_p, pair.Q().polytope(), pose_q, r,
                                            io::Html3Options{d, a.p, a.q}));
  std::string out;
  if (a.json) {
    io::append_json(out, shown(r, pair), shown(pair.P(), r.piece_p), shown(pair.Q(), r.piece_q));
    out += '\n';
  } else {
    out = shown_summary(io::summary(shown(r, pair), shown(pair.P(), r.piece_p), shown(pair.Q(), r.piece_q)), pair);
  }
  write_stdout(out);
  return 0;
}

int run_depth(const DepthArgs& a) {
  check_one_stdin({&a.p, &a.q});
  const auto [p, q] = load_pair(a.p, a.q);
  check_generalized(a);
  if (p.dimension() == 3) return run_depth3(a, p, q);
  reject_rotations(a.rotate_p, "");
  reject_hull2(a.hull);
  if (!a.approximate.empty()) throw InvalidInput("--approximate: 3D point sets only");
  if (!a.html.empty()) throw InvalidInput("--html draws 3D shapes only (use --svg for 2D)");
  const Shape2 P = make_shape2(p, "P");
  const Shape2 Q = rotate_q2(make_shape2(q, "Q"), a.rotate_q);
  const Vec2 t = a.offset.empty() ? Vec2(0, 0) : parse_vec(a.offset, "--offset");
  if (a.generalized) return run_generalized2(a, P, Q, t);
  std::optional<Vec2> d;
  if (!a.direction.empty()) {
    d = parse_vec(a.direction, "--direction");
    if (d->x() == 0 && d->y() == 0) throw InvalidInput("--direction: the direction is zero");
  }
  const Pair2 pair(P, Q, pendepth::Prepare::Queries);
  const Depth2 r = !d ? pair.minimum(t) : a.separate ? pair.separation(t, *d) : pair.along(t, *d);
  if (!a.svg.empty()) write_svg(a.svg, pair, t, r, d);
  std::string out;
  if (a.json) {
    append_json(out, r, P, Q);
    add_rotation_field(out, a.rotate_q);
    out += '\n';
  } else {
    out = rotation_note(a.rotate_q) + summary(r, P, Q);
  }
  write_stdout(out);
  return 0;
}

struct BatchArgs {
  std::string p, q, queries, rotate_p, rotate_q;
  unsigned threads = 0;
  bool json = false, progress = false, signed_distance = false, hull = false;
};

bool show_progress(const BatchArgs& a) { return a.progress || isatty(fileno(stderr)); }

// A progress line on stderr ("pendepth batch: K / N queries"; nfp-all: "pendepth nfp-all: K / N
// pairs"), redrawn as chunks finish; off unless asked for (--progress) or stderr is a terminal.
class Progress {
 public:
  Progress(std::size_t total, bool on, const char* what = "batch", const char* unit = "queries")
      : total_(total), on_(on && total > 0), what_(what), unit_(unit) {
    draw();
  }
  void set(std::size_t done) {
    done_ = done;
    draw();
  }
  void add(std::size_t n) {
    done_ += n;
    draw();
  }
  ~Progress() {
    if (on_) std::fputc('\n', stderr);
  }

 private:
  void draw() const {
    if (on_) std::fprintf(stderr, "\rpendepth %s: %zu / %zu %s", what_, done_, total_, unit_);
  }
  std::size_t total_, done_ = 0;
  bool on_;
  const char *what_, *unit_;
};

// Answers every query in two parallel batches, σ (zero direction) and σ_d, each in file order and
// in chunks of kChunk queries (for the progress line; every answer depends on its query only, so
// chunking changes no bit). `minimum(ts, out)` and `along(ts, ds, out)` are the pair's batch calls
// on spans. Returns the answers in query order.
template <class Result, class Query, class Minimum, class Along>
std::vector<Result> answer_all(const std::vector<Query>& queries, bool progress, Minimum&& minimum, Along&& along) {
  using V = decltype(Query::t);
  constexpr std::size_t kChunk = 1 << 14;
  std::vector<V> tm, ta, da;
  std::vector<std::size_t> im, ia;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    if (queries[i].d.isZero(0)) {
      tm.push_back(queries[i].t);
      im.push_back(i);
    } else {
      ta.push_back(queries[i].t);
      da.push_back(queries[i].d);
      ia.push_back(i);
    }
  }
  std::vector<Result> rm(tm.size()), ra(ta.size()), out(queries.size());
  Progress bar(queries.size(), progress);
  for (std::size_t b = 0; b < tm.size(); b += kChunk) {
    const std::size_t n = std::min(kChunk, tm.size() - b);
    minimum(std::span<const V>(tm).subspan(b, n), std::span<Result>(rm).subspan(b, n));
    bar.add(n);
  }
  for (std::size_t b = 0; b < ta.size(); b += kChunk) {
    const std::size_t n = std::min(kChunk, ta.size() - b);
    along(std::span<const V>(ta).subspan(b, n), std::span<const V>(da).subspan(b, n), std::span<Result>(ra).subspan(b, n));
    bar.add(n);
  }
  for (std::size_t k = 0; k < im.size(); ++k) out[im[k]] = rm[k];
  for (std::size_t k = 0; k < ia.size(); ++k) out[ia[k]] = ra[k];
  return out;
}

// One answer per query line as CSV rows under `header`, or JSON Lines, written in blocks of 1 MiB.
template <class Result, class Json>
int write_batch(const BatchArgs& a, const std::vector<Result>& results, const char* header, Json&& json) {
  constexpr std::size_t kFlushBytes = 1 << 20;
  std::string out;
  out.reserve(kFlushBytes + 4096);
  if (!a.json) out += header;
  for (const Result& r : results) {
    if (a.json) {
      json(out, r);
      out += '\n';
    } else {
      io::append_csv_row(out, r);
    }
    if (out.size() >= kFlushBytes) {
      write_stdout(out);
      out.clear();
    }
  }
  write_stdout(out);
  return 0;
}

// ---- signed distance and shape cast (issue 16 item 7) ----

struct DistanceArgs {
  std::string p, q, offset, direction, rotate_p, rotate_q;
  bool json = false, hull = false;
};

// `distance` (cast false) and `cast` (cast true), 2D or 3D by the shapes.
int run_distance(const DistanceArgs& a, bool cast) {
  check_one_stdin({&a.p, &a.q});
  const auto [p, q] = load_pair(a.p, a.q);
  std::string out;
  if (p.dimension() == 3) {
    const Eigen::Quaterniond rq = parse_rotation(a.rotate_q, "--rotate-q");
    const Eigen::Quaterniond rp = parse_rotation(a.rotate_p, "--rotate-p");
    const Vec3 t = a.offset.empty() ? Vec3(0, 0, 0) : parse_vec3(a.offset, "--offset");
    const Vec3 d = cast ? parse_vec3(a.direction, "--direction") : Vec3(0, 0, 0);
    if (cast && d.isZero(0)) throw InvalidInput("--direction: the direction is zero");
    const Pair3 pair = make_pair3(p, q, a.hull);
    const Pose3 pose_p(rp, Vec3::Zero()), pose_q(rq, t);
    if (cast) {  // a mesh pair's features index the pieces piece_p / piece_q
      const pendepth::Cast3 r = shown(pair.cast(pose_p, pose_q, d), pair);
      const auto &FP = shown(pair.P(), r.piece_p), &FQ = shown(pair.Q(), r.piece_q);
      a.json ? io::append_json(out, r, FP, FQ) : void(out = io::summary(r, FP, FQ));
    } else {
      const pendepth::Distance3 r = shown(pair.signed_distance(pose_p, pose_q), pair);
      const auto &FP = shown(pair.P(), r.piece_p), &FQ = shown(pair.Q(), r.piece_q);
      a.json ? io::append_json(out, r, FP, FQ) : void(out = io::summary(r, FP, FQ));
    }
  } else {
    reject_rotations(a.rotate_p, a.rotate_q);
    reject_hull2(a.hull);
    const Shape2 P = make_shape2(p, "P"), Q = make_shape2(q, "Q");
    const Vec2 t = a.offset.empty() ? Vec2(0, 0) : parse_vec(a.offset, "--offset");
    const Vec2 d = cast ? parse_vec(a.direction, "--direction") : Vec2(0, 0);
    if (cast && d.x() == 0 && d.y() == 0) throw InvalidInput("--direction: the direction is zero");
    const Pair2 pair(P, Q, pendepth::Prepare::Queries);
    if (cast) {
      const pendepth::Cast2 r = pair.cast(t, d);
      a.json ? io::append_json(out, r, features_of(P), features_of(Q)) : void(out = io::summary(r, features_of(P), features_of(Q)));
    } else {
      const pendepth::Distance2 r = pair.signed_distance(t);
      a.json ? io::append_json(out, r, features_of(P), features_of(Q)) : void(out = io::summary(r, features_of(P), features_of(Q)));
    }
  }
  if (a.json) out += '\n';
  write_stdout(out);
  return 0;
}

// `batch --signed`: placements only (every direction must be zero), answered in chunks.
template <class Query>
void require_placements(const BatchArgs& a, const std::vector<Query>& queries) {
  for (const Query& q : queries)
    if (!q.d.isZero(0))
      throw InvalidInput((a.queries == "-" ? std::string(kStdin) : a.queries) + ":" + std::to_string(q.line) +
                         ": --signed takes placements only: the direction columns must be 0");
}

template <class Result, class V, class Query, class Run>
std::vector<Result> signed_all(const BatchArgs& a, const std::vector<Query>& queries, Run&& run) {
  require_placements(a, queries);
  constexpr std::size_t kChunk = 1 << 14;
  std::vector<V> ts;
  for (const Query& q : queries) ts.push_back(q.t);
  std::vector<Result> out(ts.size());
  Progress bar(ts.size(), show_progress(a));
  for (std::size_t b = 0; b < ts.size(); b += kChunk) {
    const std::size_t n = std::min(kChunk, ts.size() - b);
    run(std::span<const V>(ts).subspan(b, n), std::span<Result>(out).subspan(b, n));
    bar.add(n);
  }
  return out;
}

int run_signed_batch(const BatchArgs& a, const Pair2& pair, const std::vector<io::Query2>& queries) {
  const auto results = signed_all<pendepth::Distance2, Vec2>(
      a, queries, [&](std::span<const Vec2> ts, std::span<pendepth::Distance2> out) { pair.signed_distance(ts, out, a.threads); });
  return write_batch(a, results, "distance,tx,ty\n", [&](std::string& out, const pendepth::Distance2& r) {
    io::append_json(out, r, features_of(pair.P()), features_of(pair.Q()));
  });
}

int run_signed_batch3(const BatchArgs& a, const Pair3& pair, const Pose3& pose_p, const Eigen::Quaterniond& rq,
                      const std::vector<io::Query3>& queries) {
  const auto results = signed_all<pendepth::Distance3, Vec3>(
      a, queries, [&](std::span<const Vec3> ts, std::span<pendepth::Distance3> out) {
        std::vector<Pose3> poses;
        for (const Vec3& t : ts) poses.emplace_back(rq, t);
        pair.signed_distance(pose_p, poses, out, a.threads);
      });
  return write_batch(a, results, "distance,tx,ty,tz\n", [&](std::string& out, const pendepth::Distance3& r) {
    io::append_json(out, shown(r, pair), shown(pair.P(), r.piece_p), shown(pair.Q(), r.piece_q));
  });
}

int run_batch3(const BatchArgs& a, const ShapeText& p, const ShapeText& q) {
  const Eigen::Quaterniond rq = parse_rotation(a.rotate_q, "--rotate-q");
  const Eigen::Quaterniond rp = parse_rotation(a.rotate_p, "--rotate-p");
  const Pair3 pair = make_pair3(p, q, a.hull, pendepth::Prepare::Full);
  const std::vector<io::Query3> queries = a.queries == "-" ? io::parse_queries3_csv(io::read_stream(std::cin, kStdin), kStdin)
                                                           : io::read_queries3_csv(a.queries);
  const Pose3 pose_p(rp, Vec3::Zero());
  if (a.signed_distance) return run_signed_batch3(a, pair, pose_p, rq, queries);
  const auto poses = [&](std::span<const Vec3> ts) {
    std::vector<Pose3> p;
    p.reserve(ts.size());
    for (const Vec3& t : ts) p.emplace_back(rq, t);
    return p;
  };
  const std::vector<Depth3> results = answer_all<Depth3>(
      queries, show_progress(a),
      [&](std::span<const Vec3> ts, std::span<Depth3> out) { pair.minimum(pose_p, poses(ts), out, a.threads); },
      [&](std::span<const Vec3> ts, std::span<const Vec3> ds, std::span<Depth3> out) {
        pair.along(pose_p, poses(ts), ds, out, a.threads);
      });
  return write_batch(a, results, "depth,tx,ty,tz\n", [&](std::string& out, const Depth3& r) {
    io::append_json(out, shown(r, pair), shown(pair.P(), r.piece_p), shown(pair.Q(), r.piece_q));
  });
}

// 2D: every per-pair structure is built once, before the first query (the depth field of two
// convex polygons, the no-fit polygon of two non-convex ones).
int run_batch(const BatchArgs& a) {
  check_one_stdin({&a.p, &a.q, &a.queries});
  const auto [p, q] = load_pair(a.p, a.q);
  if (p.dimension() == 3) return run_batch3(a, p, q);
  reject_rotations(a.rotate_p, "");
  reject_hull2(a.hull);
  const Pair2 pair(make_shape2(p, "P"), rotate_q2(make_shape2(q, "Q"), a.rotate_q), pendepth::Prepare::Full);
  if (const std::string note = rotation_note(a.rotate_q); !note.empty()) std::fputs(("pendepth: " + note).c_str(), stderr);
  const std::vector<io::Query2> queries = a.queries == "-" ? io::parse_queries_csv(io::read_stream(std::cin, kStdin), kStdin)
                                                           : io::read_queries_csv(a.queries);
  if (a.signed_distance) return run_signed_batch(a, pair, queries);
  const std::vector<Depth2> results = answer_all<Depth2>(
      queries, show_progress(a),
      [&](std::span<const Vec2> ts, std::span<Depth2> out) { pair.minimum(ts, out, a.threads); },
      [&](std::span<const Vec2> ts, std::span<const Vec2> ds, std::span<Depth2> out) {
        pair.along(ts, ds, out, a.threads);
      });
  return write_batch(a, results, "depth,tx,ty\n",
                     [&](std::string& out, const Depth2& r) { append_json(out, r, pair.P(), pair.Q()); });
}

struct NfpArgs {
  std::string p, q;
  bool json = false;
};

// The no-fit polygon of any two polygons (convex ones too), as WKT or JSON.
int run_nfp(const NfpArgs& a) {
  check_one_stdin({&a.p, &a.q});
  for (const std::string* s : {&a.p, &a.q})
    if (const int d = shape_dimension(*s); d == 3) throw InvalidInput(*s + ": nfp takes 2D shapes (.wkt) only");
  const ShapeText p = load_shape(a.p), q = load_shape(a.q);
  for (const ShapeText* s : {&p, &q})
    if (s->dimension() != 2) throw InvalidInput(s->source + ": nfp takes 2D shapes (.wkt) only");
  const pendepth::NoFitPolygonParts nfp = pendepth::no_fit_polygon(make_shape2(p, "P"), make_shape2(q, "Q"));
  io::Geometry2 g;
  g.polygons = nfp.polygons;
  for (const auto& s : nfp.slits) g.lines.push_back({s[0], s[1]});
  g.points = nfp.points;
  std::string out;
  if (a.json) io::append_json(out, g);
  else out = io::to_wkt(g);
  out += '\n';
  write_stdout(out);
  return 0;
}

// ---- trajectory: σ at every pose of a path, warm-started from the previous pose ----------------
struct TrajectoryArgs {
  std::string p, q, poses;
  bool json = false, cold = false, hull = false;
};

// Answers pose k with `answer(k)`; a bad pose (outside the numeric domain) is named by its line.
template <class Result, class PoseLine, class Answer>
std::vector<Result> answer_poses(const std::string& source, const std::vector<PoseLine>& poses, Answer&& answer) {
  std::vector<Result> out(poses.size());
  for (std::size_t k = 0; k < poses.size(); ++k) try {
      out[k] = answer(k);
    } catch (const InvalidInput& e) {
      throw InvalidInput(source + ":" + std::to_string(poses[k].line) + ": " + e.what());
    }
  return out;
}

// 2D: Q rotated per pose (Shape2::rotated), one Pair2 per run of equal angles (bitwise), as
// pendepth::trajectory; --cold builds a pair per pose. 3D: Pair3 with a WarmStart3 (--cold: none).
// The answers are the same either way, bit for bit.
int run_trajectory(const TrajectoryArgs& a) {
  check_one_stdin({&a.p, &a.q, &a.poses});
  const auto [p, q] = load_pair(a.p, a.q);
  const std::string source = a.poses == "-" ? kStdin : a.poses;
  auto text = [&] { return a.poses == "-" ? io::read_stream(std::cin, kStdin) : io::read_text_file(a.poses); };
  BatchArgs out;
  out.json = a.json;
  if (p.dimension() == 3) {
    const auto poses = io::parse_poses3_csv(text(), source);
    const Pair3 pair = make_pair3(p, q, a.hull);
    pendepth::WarmStart3 warm;
    const auto results = answer_poses<Depth3>(source, poses, [&](std::size_t k) {
      const Pose3 pose(poses[k].q, poses[k].t);
      return a.cold ? pair.minimum(Pose3(), pose) : pair.minimum(Pose3(), pose, warm);
    });
    return write_batch(out, results, "depth,tx,ty,tz\n", [&](std::string& o, const Depth3& r) {
      io::append_json(o, shown(r, pair), shown(pair.P(), r.piece_p), shown(pair.Q(), r.piece_q));
    });
  }
  reject_hull2(a.hull);
  const auto poses = io::parse_poses2_csv(text(), source);
  const Shape2 P = make_shape2(p, "P"), Q = make_shape2(q, "Q");
  std::optional<Pair2> pair;
  double angle = 0;
  std::vector<Shape2> rotated;  // Q at each pose's angle, for the JSON features
  const auto results = answer_poses<Depth2>(source, poses, [&](std::size_t k) {
    const double deg = poses[k].degrees;
    if (a.cold || !pair || std::memcmp(&deg, &angle, sizeof deg) != 0) pair.emplace(P, Q.rotated(deg)), angle = deg;
    if (a.json) rotated.push_back(pair->Q());
    return pair->minimum(poses[k].t);
  });
  std::size_t k = 0;
  return write_batch(out, results, "depth,tx,ty\n",
                     [&](std::string& o, const Depth2& r) { append_json(o, r, P, rotated[k++]); });
}

struct NfpAllArgs {
  std::string instance, rotations;
  unsigned threads = 0;
  bool json = false, progress = false;
};

// --rotations A,B,...: degrees, finite, at least one.
std::vector<double> parse_rotation_list(const std::string& text) {
  std::vector<double> out;
  std::size_t at = 0;
  while (true) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string field = text.substr(at, comma - at);
    double v = 0;
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
    if (field.empty() || ec != std::errc() || end != field.data() + field.size() || !std::isfinite(v))
      throw InvalidInput("--rotations: \"" + field + "\" is not a finite angle in degrees (expected A,B,... e.g. 0,90,180,270)");
    out.push_back(v);
    if (comma == text.size()) break;
    at = comma + 1;
  }
  return out;
}

// The no-fit polygon of every ordered pair of items of a nesting instance (i == j included), at
// every rotation of each (--rotations for all items, else each item's allowed_orientations): CSV
// rows i,rotation_i,j,rotation_j,"WKT" (i, j the items' indices in "items", P = item i fixed, Q
// = item j moving; the WKT as `nfp` prints it, quoted), or JSON Lines
// {"i":…,"rotation_i":…,"j":…,"rotation_j":…,"nfp":{…as nfp --json…}}.
int run_nfp_all(const NfpAllArgs& a) {
  const pendepth::NestingInstance inst = a.instance == "-" ? pendepth::parse_nesting_instance(io::read_stream(std::cin, kStdin), kStdin)
                                                           : pendepth::read_nesting_instance(a.instance);
  std::vector<Shape2> shapes;
  std::vector<std::vector<double>> rotations;
  for (const auto& item : inst.items) {
    shapes.push_back(item.shape);
    rotations.push_back(item.allowed_orientations);
  }
  if (!a.rotations.empty()) rotations.assign(1, parse_rotation_list(a.rotations));
  std::optional<Progress> bar;
  const auto entries = pendepth::no_fit_polygons(shapes, rotations, a.threads, [&](std::size_t done, std::size_t total) {
    if (!bar) bar.emplace(total, a.progress || isatty(fileno(stderr)), "nfp-all", "pairs");
    bar->set(done);
  });
  bar.reset();
  constexpr std::size_t kFlushBytes = 1 << 20;
  std::string out;
  if (!a.json) out += "i,rotation_i,j,rotation_j,nfp\n";
  for (const auto& e : entries) {
    io::Geometry2 g;
    g.polygons = e.nfp.polygons;
    for (const auto& s : e.nfp.slits) g.lines.push_back({s[0], s[1]});
    g.points = e.nfp.points;
    if (a.json) {
      out += "{\"i\":" + std::to_string(e.i) + ",\"rotation_i\":";
      io::append_double(out, e.rotation_i);
      out += ",\"j\":" + std::to_string(e.j) + ",\"rotation_j\":";
      io::append_double(out, e.rotation_j);
      out += ",\"nfp\":";
      io::append_json(out, g);
      out += "}\n";
    } else {
      out += std::to_string(e.i) + ',';
      io::append_double(out, e.rotation_i);
      out += ',' + std::to_string(e.j) + ',';
      io::append_double(out, e.rotation_j);
      out += ",\"" + io::to_wkt(g) + "\"\n";
    }
    if (out.size() >= kFlushBytes) {
      write_stdout(out);
      out.clear();
    }
  }
  write_stdout(out);
  return 0;
}

std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pendepth: exact intersection (penetration) depth of two shapes.\n"
               "P is fixed, Q moves; Q is placed at the offset t. Shapes: .wkt POLYGON files "
               "(2D: simple polygons, convex or not, with holes); "
               ".obj, .off, .stl, .ply files (3D: vertices only → their convex hull; with faces → a closed mesh, "
               "non-convex meshes answered on their convex pieces (σ as certified bounds); --hull takes the hull of any file's "
               "vertices)."};
  app.require_subcommand(1);
  app.footer("A shape or query file '-' is standard input (one of them at most).\n"
             "Exit status: 0 success, 2 bad input (one line on stderr: FILE:LINE: problem), "
             "3 output not written (full disk, closed pipe), 1 internal error.");

  DepthArgs da;
  CLI::App* depth = app.add_subcommand(
      "depth", "Depth of one placement: the minimum σ, or σ_d along --direction, or the complete separation.");
  depth->add_option("P", da.p, "fixed shape file (.wkt, or 3D .obj/.off/.stl/.ply; - reads standard input)")->required()->type_name("FILE");
  depth->add_option("Q", da.q, "moving shape file (same dimension as P)")->required()->type_name("FILE");
  depth->add_option("--offset", da.offset, "placement t of Q (default 0); negative: --offset=-1,2")
      ->type_name("X,Y[,Z]");
  CLI::Option* dir =
      depth->add_option("--direction", da.direction, "compute σ_d along d instead of σ")->type_name("X,Y[,Z]");
  depth->add_flag("--separate", da.separate, "complete separation along --direction (convex pairs: equals σ_d)")
      ->needs(dir);
  depth->add_flag("--json", da.json, "print one JSON object instead of a summary");
  depth->add_option("--svg", da.svg, "also draw the query into this SVG file (2D)")->type_name("FILE");
  depth->add_option("--html", da.html, "also write a self-contained HTML page showing the 3D query (orbit, zoom)")
      ->type_name("FILE");
  depth->add_option("--rotate-q", da.rotate_q,
                    "rotation of Q about its origin, before the offset: 3D a quaternion (normalised); 2D an angle in "
                    "degrees, counter-clockwise (exact for multiples of 90, else Q's coordinates are rotated and rounded)")
      ->type_name("QW,QX,QY,QZ|DEG");
  depth->add_flag("--generalized", da.generalized,
                  "generalized depth PD_g: Q may also rotate (about its reference point); cost = the largest "
                  "displacement of Q's points; prints certified bounds, the rotation and the translation");
  depth->add_option("--approximate", da.approximate,
                    "3D: certified (1+DELTA)-approximate σ of huge point sets, no hull built (DELTA in [1e-9, 1); the "
                    "files' vertices are used, faces ignored)")
      ->type_name("DELTA");
  depth->add_option("--rotate-p", da.rotate_p, "3D: rotation of P about its origin (quaternion, normalised)")
      ->type_name("QW,QX,QY,QZ");
  depth->add_flag("--hull", da.hull, kHullHelp);

  BatchArgs ba;
  CLI::App* batch = app.add_subcommand(
      "batch", "Many placements: CSV lines x,y,dx,dy or x,y,z,dx,dy,dz (zero direction asks for σ). "
               "Prints CSV depth,tx,ty[,tz]. Shapes are preprocessed once (two non-convex polygons: "
               "their no-fit polygon, see nfp).");
  batch->add_option("P", ba.p, "fixed shape file (.wkt, or 3D .obj/.off/.stl/.ply; - reads standard input)")->required()->type_name("FILE");
  batch->add_option("Q", ba.q, "moving shape file (same dimension as P)")->required()->type_name("FILE");
  batch->add_option("--queries", ba.queries, "CSV file of queries x,y[,z],dx,dy[,dz] (- reads standard input)")->required()->type_name("FILE");
  batch->add_flag("--json", ba.json, "print JSON Lines (one object per query) instead of CSV");
  batch->add_option("--threads", ba.threads, "threads for the queries (default 0: every core; answers do not depend on it)")
      ->type_name("N");
  batch->add_flag("--progress", ba.progress, "print progress on stderr (default: only when stderr is a terminal)");
  batch->add_option("--rotate-q", ba.rotate_q,
                    "rotation of Q for every query: 3D a quaternion (normalised); 2D an angle in degrees (a note "
                    "on stderr when it is not a multiple of 90: Q's coordinates are rounded)")
      ->type_name("QW,QX,QY,QZ|DEG");
  batch->add_option("--rotate-p", ba.rotate_p, "3D: rotation of P (quaternion, normalised)")->type_name("QW,QX,QY,QZ");
  batch->add_flag("--hull", ba.hull, kHullHelp);
  batch->add_flag("--signed", ba.signed_distance,
                  "signed distances instead of depths: CSV distance,tx,ty[,tz] (translation to touching); "
                  "the queries' direction columns must be 0");

  // distance and cast (issue 16): one placement, 2D or 3D by the shapes.
  DistanceArgs dsa, csa;
  CLI::App* distance = app.add_subcommand(
      "distance", "Signed distance of one placement: > 0 apart (Euclidean distance), 0 touching, -σ overlapping; "
                  "the translation brings Q into touching contact.");
  CLI::App* cast = app.add_subcommand(
      "cast", "Shape cast (time of impact): the smallest s >= 0 with Q moved by s along --direction touching P "
              "(0 when touching or overlapping, 1e999 in JSON / inf when it never does).");
  for (auto [cmd, args] : {std::pair{distance, &dsa}, std::pair{cast, &csa}}) {
    cmd->add_option("P", args->p, "fixed shape file (.wkt, or 3D .obj/.off/.stl/.ply; - reads standard input)")->required()->type_name("FILE");
    cmd->add_option("Q", args->q, "moving shape file (same dimension as P)")->required()->type_name("FILE");
    cmd->add_option("--offset", args->offset, "placement t of Q (default 0); negative: --offset=-1,2")->type_name("X,Y[,Z]");
    cmd->add_flag("--json", args->json, "print one JSON object instead of a summary");
    cmd->add_option("--rotate-q", args->rotate_q, "3D: rotation of Q about its origin, before the offset (quaternion)")
        ->type_name("QW,QX,QY,QZ");
    cmd->add_option("--rotate-p", args->rotate_p, "3D: rotation of P about its origin (quaternion)")->type_name("QW,QX,QY,QZ");
    cmd->add_flag("--hull", args->hull, kHullHelp);
  }
  cast->add_option("--direction", csa.direction, "direction d of the motion (any non-zero length)")->required()->type_name("X,Y[,Z]");

  NfpArgs na;
  CLI::App* nfp = app.add_subcommand(
      "nfp",
      "The no-fit polygon of two 2D polygons (any: convex, non-convex, with holes), as WKT. It is the set of "
      "placements of Q's reference point (the origin of Q's coordinates) where Q touches P: the boundary of "
      "O = {t : the interiors of P and Q + t overlap}. Printed as MULTIPOLYGON (((outer), (hole), ...), ...): "
      "the closure of O as polygons with holes (outer rings counter-clockwise, holes clockwise, vertices "
      "rounded to the nearest double). When Q fits P exactly somewhere, GEOMETRYCOLLECTION (MULTIPOLYGON (...), "
      "MULTILINESTRING (...), MULTIPOINT (...)) with only the non-empty parts: a line is a slit, placements "
      "where Q slides exactly in a slot of P (touching, depth 0, overlap on both sides); a point is an exact "
      "fit of Q in a pocket or hole (depth 0, overlap all around).");
  nfp->add_option("P", na.p, "fixed polygon file (.wkt)")->required()->type_name("FILE");
  nfp->add_option("Q", na.q, "moving polygon file (.wkt)")->required()->type_name("FILE");
  nfp->add_flag("--json", na.json,
                "print one JSON object {\"polygons\": [[ring, ...], ...], \"lines\": [[p, q], ...], "
                "\"points\": [p, ...]} (rings without the closing vertex) instead of WKT");

  TrajectoryArgs ta;
  CLI::App* traj = app.add_subcommand(
      "trajectory",
      "σ at every pose of a path, each warm-started from the previous one (the answers equal cold ones bit for "
      "bit). Poses: CSV lines x,y,angle_deg (2D: Q rotated counter-clockwise by angle_deg about its origin, then "
      "placed at x,y) or x,y,z,qw,qx,qy,qz (3D: Q rotated by the quaternion, then translated). Prints CSV "
      "depth,tx,ty[,tz], one row per pose.");
  traj->add_option("P", ta.p, "fixed shape file (.wkt, or 3D .obj/.off/.stl/.ply; - reads standard input)")->required()->type_name("FILE");
  traj->add_option("Q", ta.q, "moving shape file (same dimension as P)")->required()->type_name("FILE");
  traj->add_option("--poses", ta.poses, "CSV file of poses (- reads standard input)")->required()->type_name("FILE");
  traj->add_flag("--json", ta.json, "print JSON Lines (one object per pose) instead of CSV");
  traj->add_flag("--cold", ta.cold, "answer every pose from scratch (for comparison; same output)");
  traj->add_flag("--hull", ta.hull, kHullHelp);
  NfpAllArgs nfa;
  CLI::App* nfp_all = app.add_subcommand(
      "nfp-all",
      "The no-fit polygons of a whole nesting instance (ESICUP / jagua-rs JSON: items[].shape simple_polygon or "
      "polygon with holes, items[].allowed_orientations): every ordered pair of items (i = j included: two copies) "
      "at every rotation of each (P = item i fixed, Q = item j moving, both rotated about their own origins; "
      "quarter turns exact, other angles rounded once). Prints CSV rows i,rotation_i,j,rotation_j,\"WKT\" under that "
      "header, i and j the items' indices in the file, WKT as nfp prints it; pairs in the order i, rotation_i, j, "
      "rotation_j. Built in parallel; the output does not depend on --threads.");
  nfp_all->add_option("INSTANCE", nfa.instance, "nesting instance (.json; - reads standard input)")->required()->type_name("FILE");
  nfp_all->add_option("--rotations", nfa.rotations,
                      "rotations in degrees for every item (default: each item's allowed_orientations, or 0)")
      ->type_name("A,B,...");
  nfp_all->add_option("--threads", nfa.threads, "threads (default 0: every core)")->type_name("N");
  nfp_all->add_flag("--progress", nfa.progress, "print progress on stderr (default: only when stderr is a terminal)");
  nfp_all->add_flag("--json", nfa.json,
                    "print JSON Lines {\"i\":…,\"rotation_i\":…,\"j\":…,\"rotation_j\":…,\"nfp\":{as nfp --json}} instead");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "pendepth: %s (see pendepth --help)\n", one_line(e.what()).c_str());
    return 2;
  }

  // A closed pipe is reported as a failed write (exit 3 with a message), not a silent death by
  // SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  try {
    const int status = depth->parsed()      ? run_depth(da)
                       : nfp->parsed()      ? run_nfp(na)
                       : nfp_all->parsed()  ? run_nfp_all(nfa)
                       : distance->parsed() ? run_distance(dsa, false)
                       : cast->parsed()     ? run_distance(csa, true)
                       : traj->parsed()     ? run_trajectory(ta)
                                            : run_batch(ba);
    flush_stdout();
    return status;
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "%s\n", one_line(e.what()).c_str());
    return 2;
  } catch (const io::WriteError& e) {
    std::fprintf(stderr, "pendepth: %s\n", one_line(e.what()).c_str());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pendepth: internal error: %s\n", one_line(e.what()).c_str());
    return 1;
  }
}
