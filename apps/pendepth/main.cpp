// pendepth — command-line tool (DESIGN.md §3).
//
//   pendepth depth P Q [--offset X,Y[,Z]] [--direction X,Y[,Z]] [--separate] [--json] [--svg FILE]
//                      [--rotate-q QW,QX,QY,QZ] [--rotate-p QW,QX,QY,QZ]
//   pendepth batch P Q --queries FILE [--json] [--rotate-q ...] [--rotate-p ...]
//   pendepth nfp P Q [--json]
//
// Exit status: 0 success, 2 bad input (one line on stderr naming file, line and problem),
// 1 internal error. Shapes: .wkt (2D polygons); .obj, .off, .stl (3D: the convex hull of the
// vertices). P and Q must have the same dimension. Rotations are 3D only.
//
// 2D algorithm choice: both convex → the convex queries (DHS §3); one polygon non-convex or with
// holes and the other convex → PolygonDepth2 (DHS §4, §6), built once per run. PolygonDepth2 fixes
// the polygon, so when Q is the non-convex one the roles are swapped: Q + t overlaps P exactly when
// P − t overlaps Q, moving Q by v is moving P by −v, so depth(P, Q, t, d) is depth(Q, P, −t, −d)
// with translation and normal negated, witnesses mapped back into P's frame and features swapped.
// Two non-convex polygons (issue 5): `depth` asks PairDepth2 (per-query dual-tree descent, no
// preprocessing beyond the triangulations); `batch` builds the no-fit polygon NoFitPolygon2 once
// and answers every query on it; `--svg` draws the no-fit polygon (cl O, slits, points).
// `nfp` prints the no-fit polygon of any two polygons as WKT (see its --help for the semantics).
#include <pendepth/depth2.hpp>
#include <pendepth/depth2_nonconvex.hpp>
#include <pendepth/depth2_polygon.hpp>
#include <pendepth/depth3.hpp>
#include <pendepth/io.hpp>
#include <pendepth/nfp2.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace {

using pendepth::ConvexPolygon;
using pendepth::ConvexPolytope;
using pendepth::Depth2;
using pendepth::Depth3;
using pendepth::InvalidInput;
using pendepth::NoFitPolygon2;
using pendepth::Polygon;
using pendepth::Pose3;
using pendepth::Vec2;
using pendepth::Vec3;
namespace io = pendepth::io;

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// The dimension of a shape file, by its extension: 2 (.wkt) or 3 (.obj, .off, .stl).
int shape_dimension(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".wkt") return 2;
  if (ext == ".obj" || ext == ".off" || ext == ".stl") return 3;
  throw InvalidInput(path + ": unknown shape format '" + ext + "' (expected .wkt, .obj, .off or .stl)");
}

// The common dimension of P and Q; mixing a 2D and a 3D shape is bad input.
int pair_dimension(const std::string& p, const std::string& q) {
  const int dp = shape_dimension(p), dq = shape_dimension(q);
  if (dp != dq)
    throw InvalidInput(q + ": Q is a " + std::to_string(dq) + "D shape but P (" + p + ") is " + std::to_string(dp) +
                       "D; both must be 2D (.wkt) or both 3D (.obj, .off, .stl)");
  return dp;
}


// N comma-separated numbers from an option value (`names` as in "X,Y"); the option name goes
// into the error message.
template <int N>
Eigen::Matrix<double, N, 1> parse_numbers(const std::string& text, const char* option, const char* names) {
  static constexpr const char* kCount[] = {"", "one", "two", "three", "four"};
  const std::string expected = std::string(option) + ": expected " + names + " (" + kCount[N] + " numbers), got '" + text + "'";
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

// v scaled by a power of two so its largest |component| lies in [1, 2): exact (up to components
// 2^-1000 times smaller than the largest), so the library's norms can neither underflow nor
// overflow. v must not be zero.
template <class V>
V rescale(const V& v) {
  const int e = std::ilogb(v.cwiseAbs().maxCoeff());
  V r;
  for (int k = 0; k < v.size(); ++k) r[k] = std::ldexp(v[k], -e);
  return r;
}

// --rotate-p / --rotate-q: a quaternion w,x,y,z, normalised by the library (after an exact
// power-of-two rescaling); zero is bad input. Empty text: the identity.
Eigen::Quaterniond parse_rotation(const std::string& text, const char* option) {
  if (text.empty()) return Eigen::Quaterniond::Identity();
  const Eigen::Vector4d q = parse_numbers<4>(text, option, "QW,QX,QY,QZ");
  if (q.isZero(0)) throw InvalidInput(std::string(option) + ": the quaternion is zero (it must be a rotation)");
  const Eigen::Vector4d r = rescale(q);
  return Eigen::Quaterniond(r[0], r[1], r[2], r[3]);
}

void write_stdout(const std::string& s) { std::fwrite(s.data(), 1, s.size(), stdout); }

// A 2D pair with at least one non-convex polygon (DHS §4): PolygonDepth2 on (polygon, convex),
// with the roles swapped back when P is the convex one (see the file comment).
class PolygonPair {
 public:
  // Takes the shapes of P and Q, exactly one of them convex.
  PolygonPair(io::Shape2 P, io::Shape2 Q) : P_(std::move(P)), Q_(std::move(Q)), swapped_(P_.convex.has_value()) {
    pd_.emplace(swapped_ ? *Q_.polygon : *P_.polygon, swapped_ ? *P_.convex : *Q_.convex);
  }

  Depth2 minimum(const Vec2& t) const { return back(swapped_ ? pd_->minimum(-t) : pd_->minimum(t), t); }
  Depth2 along(const Vec2& t, const Vec2& d) const {
    return back(swapped_ ? pd_->along(-t, -d) : pd_->along(t, d), t);
  }
  Depth2 separation(const Vec2& t, const Vec2& d) const {
    return back(swapped_ ? pd_->separation(-t, -d) : pd_->separation(t, d), t);
  }

  void append_json(std::string& out, const Depth2& r) const {
    if (swapped_) io::append_json(out, r, *P_.convex, *Q_.polygon);
    else io::append_json(out, r, *P_.polygon, *Q_.convex);
  }
  std::string summary(const Depth2& r) const {
    return swapped_ ? io::summary(r, *P_.convex, *Q_.polygon) : io::summary(r, *P_.polygon, *Q_.convex);
  }

  // The picture: P and Q in their own frames; the configuration panel shows ∂O, the boundary of
  // the set of placements t of Q where the interiors overlap, arcs expanded (for a swapped pair
  // PolygonDepth2's own set is −O, so its rings are negated).
  void write_svg(const std::string& path, const Vec2& t, const Depth2& r, const std::optional<Vec2>& d) const {
    io::SvgScene scene;
    scene.P = rings(P_);
    scene.Q = rings(Q_);
    scene.config = pd_->boundary_rings();
    if (swapped_)
      for (auto& ring : scene.config)
        for (Vec2& x : ring) x = Vec2(0, 0) - x;
    scene.config_label = "O: placements t where Q + t overlaps P (outline ∂O)";
    scene.config_target = "t + v on ∂O";
    io::write_svg(path, scene, t, r, io::SvgOptions{d, true});
  }

 private:
  static std::vector<std::vector<Vec2>> rings(const io::Shape2& s) {
    std::vector<std::vector<Vec2>> out;
    if (s.convex) {
      out.emplace_back(s.convex->vertices().begin(), s.convex->vertices().end());
    } else {
      for (std::size_t k = 0; k < s.polygon->ring_count(); ++k)
        out.emplace_back(s.polygon->ring(k).begin(), s.polygon->ring(k).end());
    }
    return out;
  }

  // Maps an answer of the swapped problem (Q fixed at 0, P placed at −t, moved by v') back:
  // v = −v', and a point x of the swapped frame after the move is x + t + v in P's frame.
  Depth2 back(Depth2 r, const Vec2& t) const {
    if (!swapped_) return r;
    const Vec2 zero(0, 0);
    r.translation = zero - r.translation;  // 0 − x, never −0
    r.normal = zero - r.normal;
    std::swap(r.feature_p, r.feature_q);
    if (r.overlapping || r.depth > 0) {
      const Vec2 shift = t + r.translation;
      const Vec2 wp = r.witness_q + shift, wq = r.witness_p + shift;
      r.witness_p = wp;
      r.witness_q = wq;
    }
    return r;
  }

  io::Shape2 P_, Q_;
  bool swapped_;
  std::optional<pendepth::PolygonDepth2> pd_;
};

struct DepthArgs {
  std::string p, q, offset, direction, svg, rotate_p, rotate_q;
  bool separate = false, json = false;
};

void reject_rotations(const std::string& rotate_p, const std::string& rotate_q) {
  if (!rotate_q.empty()) throw InvalidInput("--rotate-q: rotations apply to 3D shapes only");
  if (!rotate_p.empty()) throw InvalidInput("--rotate-p: rotations apply to 3D shapes only");
}

int run_depth3(const DepthArgs& a) {
  if (!a.svg.empty()) throw InvalidInput("--svg draws 2D shapes only");
  const Eigen::Quaterniond rq = parse_rotation(a.rotate_q, "--rotate-q");
  const Eigen::Quaterniond rp = parse_rotation(a.rotate_p, "--rotate-p");
  const Vec3 t = a.offset.empty() ? Vec3(0, 0, 0) : parse_vec3(a.offset, "--offset");
  std::optional<Vec3> d;
  if (!a.direction.empty()) {
    d = parse_vec3(a.direction, "--direction");
    if (d->isZero(0)) throw InvalidInput("--direction: the direction is zero");
  }
  const ConvexPolytope P = io::read_convex_polytope(a.p, "P");
  const ConvexPolytope Q = io::read_convex_polytope(a.q, "Q");
  const Pose3 pose_p(rp, Vec3::Zero()), pose_q(rq, t);
  Depth3 r;
  if (d) {
    // Complete separation equals σ_d for convex shapes: once the ray leaves the convex M it
    // never re-enters.
    r = pendepth::directional_depth(P, pose_p, Q, pose_q, rescale(*d));
    if (a.separate) r.kind = pendepth::DepthKind::Separation;
  } else {
    r = pendepth::minimum_depth(P, pose_p, Q, pose_q);
  }
  std::string out;
  if (a.json) {
    io::append_json(out, r, P, Q);
    out += '\n';
  } else {
    out = io::summary(r, P, Q);
  }
  write_stdout(out);
  return 0;
}

int run_depth_polygon(const DepthArgs& a, io::Shape2 P, io::Shape2 Q, const Vec2& t, const std::optional<Vec2>& d) {
  const PolygonPair pair(std::move(P), std::move(Q));
  Depth2 r;
  if (d) {
    const Vec2 u = rescale(*d);
    r = a.separate ? pair.separation(t, u) : pair.along(t, u);
  } else {
    r = pair.minimum(t);
  }
  if (!a.svg.empty()) pair.write_svg(a.svg, t, r, d);
  std::string out;
  if (a.json) {
    pair.append_json(out, r);
    out += '\n';
  } else {
    out = pair.summary(r);
  }
  write_stdout(out);
  return 0;
}

// The no-fit polygon's parts as a WKT geometry: polygons with holes, slits as 2-point lines, points.
io::Geometry2 nfp_geometry(const NoFitPolygon2& nfp) {
  io::Geometry2 g;
  g.polygons = nfp.polygons();
  for (const auto& s : nfp.slits()) g.lines.push_back({s[0], s[1]});
  g.points = nfp.points();
  return g;
}

std::vector<std::vector<Vec2>> polygon_rings(const Polygon& P) {
  std::vector<std::vector<Vec2>> out;
  for (std::size_t k = 0; k < P.ring_count(); ++k) out.emplace_back(P.ring(k).begin(), P.ring(k).end());
  return out;
}

// Two non-convex polygons (or with holes), one placement: PairDepth2, which needs no preprocessing
// beyond the triangulations; the no-fit polygon is built only for the picture.
int run_depth_pair(const DepthArgs& a, const Polygon& P, const Polygon& Q, const Vec2& t,
                   const std::optional<Vec2>& d) {
  const pendepth::PairDepth2 pd(P, Q);
  Depth2 r;
  if (d) {
    const Vec2 u = rescale(*d);
    r = a.separate ? pd.separation(t, u) : pd.along(t, u);
  } else {
    r = pd.minimum(t);
  }
  if (!a.svg.empty()) {
    const NoFitPolygon2 nfp(P, Q);
    io::SvgScene scene;
    scene.P = polygon_rings(P);
    scene.Q = polygon_rings(Q);
    for (const auto& poly : nfp.polygons()) scene.config.insert(scene.config.end(), poly.begin(), poly.end());
    scene.config_segments = nfp.slits();
    scene.config_points = nfp.points();
    scene.config_label = "no-fit polygon: cl O, slits, exact fits";
    scene.config_target = "t + v on ∂O";
    io::write_svg(a.svg, scene, t, r, io::SvgOptions{d, true});
  }
  std::string out;
  if (a.json) {
    io::append_json(out, r, P, Q);
    out += '\n';
  } else {
    out = io::summary(r, P, Q);
  }
  write_stdout(out);
  return 0;
}

int run_depth(const DepthArgs& a) {
  if (pair_dimension(a.p, a.q) == 3) return run_depth3(a);
  reject_rotations(a.rotate_p, a.rotate_q);
  io::Shape2 SP = io::read_shape2(a.p, "P");
  io::Shape2 SQ = io::read_shape2(a.q, "Q");
  const Vec2 t = a.offset.empty() ? Vec2(0, 0) : parse_vec(a.offset, "--offset");
  std::optional<Vec2> d;
  if (!a.direction.empty()) {
    d = parse_vec(a.direction, "--direction");
    if (d->x() == 0 && d->y() == 0) throw InvalidInput("--direction: the direction is zero");
  }
  if (SP.polygon && SQ.polygon) return run_depth_pair(a, *SP.polygon, *SQ.polygon, t, d);
  if (!SP.convex || !SQ.convex) return run_depth_polygon(a, std::move(SP), std::move(SQ), t, d);
  const ConvexPolygon& P = *SP.convex;
  const ConvexPolygon& Q = *SQ.convex;
  Depth2 r;
  if (d) {
    const Vec2 u = rescale(*d);
    r = a.separate ? pendepth::separation_depth(P, Q, t, u) : pendepth::directional_depth(P, Q, t, u);
  } else {
    r = pendepth::minimum_depth(P, Q, t);
  }
  if (!a.svg.empty()) io::write_svg(a.svg, P, Q, t, r, io::SvgOptions{d, true});
  std::string out;
  if (a.json) {
    io::append_json(out, r, P, Q);
    out += '\n';
  } else {
    out = io::summary(r, P, Q);
  }
  write_stdout(out);
  return 0;
}

struct BatchArgs {
  std::string p, q, queries, rotate_p, rotate_q;
  bool json = false;
};

// The loop every batch shares: one answer per query line (the library's InvalidInput gets the
// query's file and line), CSV rows under `header` or JSON Lines, written in blocks of 1 MiB.
template <class Query, class Answer, class Json>
int write_batch(const BatchArgs& a, const std::vector<Query>& queries, const char* header, Answer&& answer,
                Json&& json) {
  constexpr std::size_t kFlushBytes = 1 << 20;
  std::string out;
  out.reserve(kFlushBytes + 4096);
  if (!a.json) out += header;
  for (const Query& q : queries) {
    decltype(answer(q)) r;
    try {
      r = answer(q);
    } catch (const InvalidInput& e) {
      throw InvalidInput(a.queries + ":" + std::to_string(q.line) + ": " + e.what());
    }
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

int run_batch3(const BatchArgs& a) {
  const Eigen::Quaterniond rq = parse_rotation(a.rotate_q, "--rotate-q");
  const Eigen::Quaterniond rp = parse_rotation(a.rotate_p, "--rotate-p");
  // Hulls and their hierarchies are built here, once for the whole batch.
  const ConvexPolytope P = io::read_convex_polytope(a.p, "P");
  const ConvexPolytope Q = io::read_convex_polytope(a.q, "Q");
  const std::vector<io::Query3> queries = io::read_queries3_csv(a.queries);
  const Pose3 pose_p(rp, Vec3::Zero());

  return write_batch(
      a, queries, "depth,tx,ty,tz\n",
      [&](const io::Query3& q) -> Depth3 {
        const Pose3 pose_q(rq, q.t);
        return q.d.isZero(0) ? pendepth::minimum_depth(P, pose_p, Q, pose_q)
                             : pendepth::directional_depth(P, pose_p, Q, pose_q, rescale(q.d));
      },
      [&](std::string& out, const Depth3& r) { io::append_json(out, r, P, Q); });
}

// A batch with a non-convex polygon: PolygonDepth2 is built once, before the first query.
int run_batch_polygon(const BatchArgs& a, io::Shape2 P, io::Shape2 Q, const std::vector<io::Query2>& queries) {
  const PolygonPair pair(std::move(P), std::move(Q));
  return write_batch(
      a, queries, "depth,tx,ty\n",
      [&](const io::Query2& q) -> Depth2 {
        return (q.d.x() == 0 && q.d.y() == 0) ? pair.minimum(q.t) : pair.along(q.t, rescale(q.d));
      },
      [&](std::string& out, const Depth2& r) { pair.append_json(out, r); });
}

// A batch with two non-convex polygons: the no-fit polygon is built once, before the first query,
// and every query is answered on it (σ for a zero direction, σ_d otherwise).
int run_batch_pair(const BatchArgs& a, const Polygon& P, const Polygon& Q, const std::vector<io::Query2>& queries) {
  const NoFitPolygon2 nfp(P, Q);
  return write_batch(
      a, queries, "depth,tx,ty\n",
      [&](const io::Query2& q) -> Depth2 {
        return (q.d.x() == 0 && q.d.y() == 0) ? nfp.minimum(q.t) : nfp.along(q.t, rescale(q.d));
      },
      [&](std::string& out, const Depth2& r) { io::append_json(out, r, P, Q); });
}

int run_batch(const BatchArgs& a) {
  if (pair_dimension(a.p, a.q) == 3) return run_batch3(a);
  reject_rotations(a.rotate_p, a.rotate_q);
  io::Shape2 SP = io::read_shape2(a.p, "P");
  io::Shape2 SQ = io::read_shape2(a.q, "Q");
  const std::vector<io::Query2> queries = io::read_queries_csv(a.queries);
  if (SP.polygon && SQ.polygon) return run_batch_pair(a, *SP.polygon, *SQ.polygon, queries);
  if (!SP.convex || !SQ.convex) return run_batch_polygon(a, std::move(SP), std::move(SQ), queries);
  ConvexPolygon P = std::move(*SP.convex);
  ConvexPolygon Q = std::move(*SQ.convex);

  // σ goes through the preprocessed field, built once and only if some query asks for it.
  const bool any_minimum = std::any_of(queries.begin(), queries.end(),
                                       [](const io::Query2& q) { return q.d.x() == 0 && q.d.y() == 0; });
  std::optional<pendepth::DepthQuery2> field;
  if (any_minimum) field.emplace(std::move(P), std::move(Q));
  const ConvexPolygon& PP = field ? field->P() : P;
  const ConvexPolygon& QQ = field ? field->Q() : Q;

  return write_batch(
      a, queries, "depth,tx,ty\n",
      [&](const io::Query2& q) -> Depth2 {
        return (q.d.x() == 0 && q.d.y() == 0) ? field->minimum(q.t)
                                              : pendepth::directional_depth(PP, QQ, q.t, rescale(q.d));
      },
      [&](std::string& out, const Depth2& r) { io::append_json(out, r, PP, QQ); });
}

struct NfpArgs {
  std::string p, q;
  bool json = false;
};

// The no-fit polygon of any two polygons (convex ones too: read as polygons), as WKT or JSON.
int run_nfp(const NfpArgs& a) {
  if (shape_dimension(a.p) != 2 || shape_dimension(a.q) != 2)
    throw InvalidInput((shape_dimension(a.p) != 2 ? a.p : a.q) + ": nfp takes 2D shapes (.wkt) only");
  const Polygon P = io::read_polygon(a.p, "P");
  const Polygon Q = io::read_polygon(a.q, "Q");
  const NoFitPolygon2 nfp(P, Q);
  const io::Geometry2 g = nfp_geometry(nfp);
  std::string out;
  if (a.json) io::append_json(out, g);
  else out = io::to_wkt(g);
  out += '\n';
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
               ".obj, .off, .stl meshes (3D: the convex hull of the vertices)."};
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 2 bad input (one line on stderr: FILE:LINE: problem).");

  DepthArgs da;
  CLI::App* depth = app.add_subcommand(
      "depth", "Depth of one placement: the minimum σ, or σ_d along --direction, or the complete separation.");
  depth->add_option("P", da.p, "fixed shape file (.wkt, or 3D .obj/.off/.stl)")->required()->type_name("FILE");
  depth->add_option("Q", da.q, "moving shape file (same dimension as P)")->required()->type_name("FILE");
  depth->add_option("--offset", da.offset, "placement t of Q (default 0); negative: --offset=-1,2")
      ->type_name("X,Y[,Z]");
  CLI::Option* dir =
      depth->add_option("--direction", da.direction, "compute σ_d along d instead of σ")->type_name("X,Y[,Z]");
  depth->add_flag("--separate", da.separate, "complete separation along --direction (convex pairs: equals σ_d)")
      ->needs(dir);
  depth->add_flag("--json", da.json, "print one JSON object instead of a summary");
  depth->add_option("--svg", da.svg, "also draw the query into this SVG file (2D)")->type_name("FILE");
  depth->add_option("--rotate-q", da.rotate_q, "3D: rotation of Q about its origin, before the offset (quaternion, normalised)")
      ->type_name("QW,QX,QY,QZ");
  depth->add_option("--rotate-p", da.rotate_p, "3D: rotation of P about its origin (quaternion, normalised)")
      ->type_name("QW,QX,QY,QZ");

  BatchArgs ba;
  CLI::App* batch = app.add_subcommand(
      "batch", "Many placements: CSV lines x,y,dx,dy or x,y,z,dx,dy,dz (zero direction asks for σ). "
               "Prints CSV depth,tx,ty[,tz]. Shapes are preprocessed once (two non-convex polygons: "
               "their no-fit polygon, see nfp).");
  batch->add_option("P", ba.p, "fixed shape file (.wkt, or 3D .obj/.off/.stl)")->required()->type_name("FILE");
  batch->add_option("Q", ba.q, "moving shape file (same dimension as P)")->required()->type_name("FILE");
  batch->add_option("--queries", ba.queries, "CSV file of queries x,y[,z],dx,dy[,dz]")->required()->type_name("FILE");
  batch->add_flag("--json", ba.json, "print JSON Lines (one object per query) instead of CSV");
  batch->add_option("--rotate-q", ba.rotate_q, "3D: rotation of Q for every query (quaternion, normalised)")
      ->type_name("QW,QX,QY,QZ");
  batch->add_option("--rotate-p", ba.rotate_p, "3D: rotation of P (quaternion, normalised)")->type_name("QW,QX,QY,QZ");

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

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "pendepth: %s (see pendepth --help)\n", one_line(e.what()).c_str());
    return 2;
  }

  try {
    if (depth->parsed()) return run_depth(da);
    if (nfp->parsed()) return run_nfp(na);
    return run_batch(ba);
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "%s\n", one_line(e.what()).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pendepth: internal error: %s\n", one_line(e.what()).c_str());
    return 1;
  }
}
