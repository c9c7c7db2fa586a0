// Shapes valid by construction from the fuzzer's bytes, and the queries run on every pair with
// their invariants (docs/robustness.md "Fuzzing"):
//   - convex polygons: the exact convex hull of small integer points (int64 cross products);
//   - star-shaped polygons: vertices at increasing angles around the origin (non-convex);
//   - grid polygons: orthogonal "histograms" of integer columns, optionally with a rectangular
//     hole (collinear vertices, touching and sliding contacts, exact fits);
//   - 3D: the hull of small integer points;
// each mapped by an exact power-of-two scale and an integer offset. Coordinates stay within
// |x| <= kCoordLimit = 1e6: huge magnitudes are the numeric-domain work of issue 20 (part 1),
// which will widen this limit once the engines take any finite input.
#pragma once

#include <pendepth/pendepth.hpp>

#include "fuzz_common.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>
#include <vector>

namespace fuzz {

using pendepth::Depth2;
using pendepth::Depth3;
using pendepth::Pair2;
using pendepth::Pair3;
using pendepth::Pose3;
using pendepth::Shape2;
using pendepth::Shape3;
using pendepth::Vec2;
using pendepth::Vec3;
using Rings = std::vector<std::vector<Vec2>>;

// Byte reads are sequenced explicitly (one per statement, or in a braced list): the order in
// which function arguments are evaluated differs between GCC and clang, and the corpus replay
// (tests/fuzz_corpus, GCC) must read an input as the fuzzer (clang) did.

/// Integers in [lo, hi] as a vector, read in order.
inline Vec2 ints2(Bytes& b, int lo, int hi) {
  const double x = b.range(lo, hi);
  const double y = b.range(lo, hi);
  return Vec2(x, y);
}
inline Vec3 ints3(Bytes& b, int lo, int hi) {
  const double x = b.range(lo, hi);
  const double y = b.range(lo, hi);
  const double z = b.range(lo, hi);
  return Vec3(x, y, z);
}

/// Largest coordinate magnitude of the query targets (see the header comment: part 1 of issue 20
/// widens it).
constexpr double kCoordLimit = 1e6;

/// An exact map x -> x·2^e + offset (e in [-12, 4], offset an integer): integer inputs stay
/// exactly representable, so exact degeneracies survive it.
struct Frame {
  int e = 0;
  Vec2 offset{0, 0};
  Vec2 operator()(double x, double y) const { return Vec2(std::ldexp(x, e), std::ldexp(y, e)) + offset; }
  static Frame from(Bytes& b) {
    Frame f;
    f.e = b.range(-12, 4);
    if (b.u8() & 1) f.offset = ints2(b, -30000, 30000) * 8.0;
    return f;
  }
};

inline std::int64_t cross(const std::array<std::int64_t, 2>& o, const std::array<std::int64_t, 2>& a,
                          const std::array<std::int64_t, 2>& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/// The exact convex hull (counter-clockwise, no collinear vertices) of integer points; empty if
/// they are collinear.
inline std::vector<std::array<std::int64_t, 2>> hull(std::vector<std::array<std::int64_t, 2>> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return {};
  std::vector<std::array<std::int64_t, 2>> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h.size() >= 3 ? h : std::vector<std::array<std::int64_t, 2>>{};
}

/// A convex polygon: the hull of 3..24 points of 8- or 16-bit integers.
inline Rings convex_rings(Bytes& b) {
  const int n = b.range(3, 24);
  const bool wide = b.u8() & 1;
  std::vector<std::array<std::int64_t, 2>> pts;
  for (int i = 0; i < n; ++i) {
    const double x = wide ? b.i16() : static_cast<std::int8_t>(b.u8());
    const double y = wide ? b.i16() : static_cast<std::int8_t>(b.u8());
    pts.push_back({static_cast<std::int64_t>(x), static_cast<std::int64_t>(y)});
  }
  const auto h = hull(pts);
  if (h.empty()) return {};
  const Frame f = Frame::from(b);
  std::vector<Vec2> ring;
  for (const auto& p : h) ring.push_back(f(double(p[0]), double(p[1])));
  return {ring};
}

/// A star-shaped polygon: k vertices at strictly increasing angles, radii 1..256.
inline Rings star_rings(Bytes& b) {
  const int k = b.range(3, 20);
  std::vector<Vec2> ring;
  const Frame f = Frame::from(b);
  for (int i = 0; i < k; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.05 + 0.9 * b.u8() / 255.0) / k;
    const double r = 1 + b.u8();
    ring.push_back(f(r * std::cos(a), r * std::sin(a)));
  }
  return {ring};
}

/// An orthogonal polygon over 1..8 integer columns of widths 1..3 and heights 1..6, turned by a
/// multiple of 90° and maybe mirrored, with a rectangular hole below the lowest column when
/// there is room.
inline Rings grid_rings(Bytes& b) {
  const int k = b.range(1, 8);
  std::vector<int> x{0}, h;
  for (int i = 0; i < k; ++i) {
    x.push_back(x.back() + b.range(1, 3));
    h.push_back(b.range(1, 6));
  }
  std::vector<std::array<double, 2>> outer{{0, 0}, {double(x.back()), 0}};
  for (int i = k - 1; i >= 0; --i) {
    outer.push_back({double(x[i + 1]), double(h[i])});
    outer.push_back({double(x[i]), double(h[i])});
  }
  std::vector<std::vector<std::array<double, 2>>> rings{outer};
  const int low = *std::min_element(h.begin(), h.end());
  if (low >= 3 && x.back() >= 3 && (b.u8() & 1)) {
    const int a = b.range(1, x.back() - 2), c = b.range(a + 1, x.back() - 1);
    rings.push_back({{double(a), 1}, {double(c), 1}, {double(c), double(low - 1)}, {double(a), double(low - 1)}});
  }
  const int turn = b.u8() % 8;
  const Frame f = Frame::from(b);
  Rings out;
  for (const auto& r : rings) {
    std::vector<Vec2> ring;
    for (auto [px, py] : r) {
      for (int t = 0; t < turn % 4; ++t) std::tie(px, py) = std::make_tuple(-py, px);
      if (turn >= 4) px = -px;
      ring.push_back(f(px, py));
    }
    out.push_back(ring);
  }
  return out;
}

/// A shape of the kind `kind` (0 convex, 1 star, 2 grid); nullopt if the bytes give a degenerate
/// point set or the validation rejects the shape (allowed: InvalidInput is checked one-line).
inline std::optional<Shape2> shape2(Bytes& b, int kind, const char* name) {
  Rings rings = kind == 0 ? convex_rings(b) : kind == 1 ? star_rings(b) : grid_rings(b);
  if (rings.empty()) return std::nullopt;
  std::optional<Shape2> s;
  allowed([&] {
    std::vector<Vec2> outer = rings[0];
    rings.erase(rings.begin());
    s.emplace(std::move(outer), std::move(rings), name);
  });
  return s;
}

inline double scale_of(const Shape2& s) {
  double m = 0;
  for (const auto& r : s.rings())
    for (const Vec2& p : r) m = std::max({m, std::fabs(p.x()), std::fabs(p.y())});
  return m;
}

/// A placement near a contact: a vertex of P minus a vertex of Q, plus a small offset (often
/// zero: vertex on vertex; the shapes' own scale: a step along an edge).
inline Vec2 placement(Bytes& b, const Shape2& P, const Shape2& Q) {
  const auto rp = P.rings(), rq = Q.rings();
  const auto& a = rp[b.u8() % rp.size()];
  const auto& c = rq[b.u8() % rq.size()];
  const Vec2 from = a[b.u8() % a.size()];
  const Vec2 t = from - c[b.u8() % c.size()];
  const double step = std::ldexp(1.0, b.range(-6, 3));
  return t + ints2(b, -3, 3) * step;
}

inline Vec2 direction(Bytes& b) {
  for (;;) {
    const Vec2 d = ints2(b, -8, 8);
    if (d != Vec2(0, 0)) return d;
    if (b.left() == 0) return Vec2(1, 0);
  }
}

/// Every 2D query on the pair, at a few placements, with its invariants (see the header comment).
/// `full`: also build the per-pair structures (the depth field, the no-fit polygon).
inline void exercise2(Bytes& b, const Shape2& P, const Shape2& Q) {
  const std::size_t nm = P.size() * Q.size();
  const bool full = nm <= 600;
  const Pair2 quick(P, Q, pendepth::Prepare::Queries);
  std::optional<Pair2> built;
  if (full) built.emplace(P, Q, pendepth::Prepare::Full);
  const double S = std::max(scale_of(P), scale_of(Q));
  for (int q = 0; q < 4 && b.left() > 0; ++q) {
    const Vec2 t = placement(b, P, Q), d = direction(b);
    const double tol = 1e-9 * (S + t.norm()) + 1e-300;
    const Depth2 r = quick.minimum(t);
    check_depth(r);
    check(r.overlapping == quick.overlapping(t), "minimum().overlapping != overlapping()");
    if (r.overlapping) check(r.depth > 0, "overlapping but depth 0");
    const Depth2 ra = quick.along(t, d);
    check_depth(ra);
    check(ra.overlapping == r.overlapping, "along().overlapping != minimum().overlapping");
    check(ra.depth >= r.depth - tol, "sigma > sigma_d", r.depth, ra.depth);
    const Depth2 rs = quick.separation(t, d);
    check_depth(rs, true);
    check(rs.depth >= ra.depth - tol, "separation < sigma_d", ra.depth, rs.depth);
    // Moving Q by the answer leaves (at most rounding) no overlap.
    check(quick.minimum(t + r.translation).depth <= tol, "overlap after the minimum move", r.depth);
    check(quick.minimum(t + ra.translation).depth <= tol, "overlap after the directional move", ra.depth);
    if (built) {
      const Depth2 f = built->minimum(t), fa = built->along(t, d);
      check_depth(f);
      check_depth(fa);
      check(f.overlapping == r.overlapping && fa.overlapping == r.overlapping, "engines disagree on overlap");
      check(std::fabs(f.depth - r.depth) <= tol, "engines disagree on sigma", r.depth, f.depth);
      check(std::fabs(fa.depth - ra.depth) <= tol, "engines disagree on sigma_d", ra.depth, fa.depth);
      // A batch gives the single call's bits.
      const Vec2 ts[2] = {t, t + d};
      Depth2 out[2];
      built->minimum(ts, out, 1);
      check(out[0].depth == f.depth && out[0].translation == f.translation, "batch != single");
    }
  }
  if (full) {
    const pendepth::NoFitPolygonParts nfp = pendepth::no_fit_polygon(P, Q);
    for (const auto& poly : nfp.polygons)
      for (const auto& ring : poly) {
        check(ring.size() >= 3, "no-fit polygon ring of fewer than 3 vertices");
        for (const Vec2& p : ring) check(p.allFinite(), "no-fit polygon vertex not finite");
      }
    for (const auto& s : nfp.slits) check(s[0].allFinite() && s[1].allFinite(), "slit not finite");
    for (const Vec2& p : nfp.points) check(p.allFinite(), "fit point not finite");
  }
}

/// 3D: the hull of 4..40 small integer points, scaled by a power of two and offset.
inline std::optional<Shape3> shape3(Bytes& b, const char* name) {
  const int n = b.range(4, 40);
  const int e = b.range(-12, 4);
  const Vec3 offset = (b.u8() & 1) ? Vec3(ints3(b, -30000, 30000) * 8.0) : Vec3(0, 0, 0);
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) {
    const auto c = [&] { return std::ldexp(double(static_cast<std::int8_t>(b.u8())), e); };
    const double x = c();
    const double y = c();
    const double z = c();
    pts.push_back(Vec3(x, y, z) + offset);
  }
  std::optional<Shape3> s;
  allowed([&] { s.emplace(Shape3::hull(pts, name)); });  // flat point sets are rejected
  return s;
}

/// Every 3D query on the pair, at a few poses, with its invariants.
inline void exercise3(Bytes& b, const Shape3& P, const Shape3& Q) {
  const Pair3 pair(P, Q);
  double S = 0;
  for (const Shape3* s : {&P, &Q})
    for (const Vec3& v : s->polytope().vertices()) S = std::max(S, v.cwiseAbs().maxCoeff());
  for (int q = 0; q < 3 && b.left() > 0; ++q) {
    Eigen::Quaterniond rot = Eigen::Quaterniond::Identity();
    if (b.u8() & 1) {
      Eigen::Vector4d c;
      for (int k = 0; k < 4; ++k) c[k] = b.range(-4, 4);
      if (!c.isZero(0)) rot = Eigen::Quaterniond(c[0], c[1], c[2], c[3]);
    }
    const auto& vp = P.polytope().vertices();
    const auto& vq = Q.polytope().vertices();
    const Pose3 pose_q0(rot, Vec3::Zero());
    const Vec3 from = vp[b.u8() % vp.size()];
    const Vec3 to = pose_q0.apply(vq[b.u8() % vq.size()]);
    const Vec3 step = ints3(b, -2, 2);
    const Vec3 t = from - to + step * std::ldexp(1.0, b.range(-6, 3));
    const Pose3 pose_p, pose_q(rot, t);
    Vec3 d = ints3(b, -4, 4);
    if (d.isZero(0)) d = Vec3(0, 0, 1);
    const double tol = 1e-9 * (S + t.norm()) + 1e-300;
    const Depth3 r = pair.minimum(pose_p, pose_q);
    check_depth(r);
    check(r.lower_bound <= r.depth + tol && r.depth <= r.upper_bound + tol, "depth outside its bounds", r.lower_bound,
          r.upper_bound);
    check(r.overlapping == pair.overlapping(pose_p, pose_q), "minimum().overlapping != overlapping()");
    if (r.overlapping) check(r.depth > 0, "overlapping but depth 0");
    const Depth3 ra = pair.along(pose_p, pose_q, d);
    check_depth(ra);
    check(ra.overlapping == r.overlapping, "along().overlapping != minimum().overlapping");
    check(ra.depth >= r.depth - tol, "sigma > sigma_d", r.depth, ra.depth);
    check(pair.minimum(pose_p, Pose3(rot, t + r.translation)).depth <= tol, "overlap after the minimum move", r.depth);
    check(pair.minimum(pose_p, Pose3(rot, t + ra.translation)).depth <= tol, "overlap after the directional move",
          ra.depth);
  }
}

}  // namespace fuzz
