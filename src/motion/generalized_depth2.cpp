// Generalized penetration depth PD_g in 2D (survey §4; include/pendepth/motion.hpp).
//
// Contract: P fixed, Q at t; a motion rotates Q by θ about its reference point and translates it
// by v; its cost is DISP(θ, v) = max_{q ∈ Q} |R_θ q + v − q|, attained at a vertex of Q's convex
// hull (a convex function of q). Returns certified bounds lower ≤ PD_g ≤ upper and the motion that
// realises `upper` (verified separating by the exact overlap test on Q.rotated(θ)).
//
// Method.
//   Both convex: PD_g = σ (theorem, motion.hpp); no probing.
//   Lower bound: max over pairs of convex parts (P_i, Q_j) overlapping at t of σ(P_i, Q_j). Any
//     motion separating P and Q separates P_i from the moved Q_j ⊆ moved Q, and the displacement of
//     Q's points bounds that of Q_j's, which is ≥ σ(P_i, Q_j) by the theorem for convex pairs.
//     σ of two convex polygons is within a few ulps (minimum_depth); it is lowered by 16 ulps.
//   Upper bound: probed angles θ. For each, Q.rotated(θ) (the coordinates a user of the rotation
//     gets), a Pair2 (options.prepare; Auto builds the no-fit polygon of a
//     small non-convex pair: on combs its build costs ~12 σ queries of PairDepth2), and for three rotation centres c (Q's reference point,
//     the centre of its hull's box, the mean of its hull vertices): the exact σ translation u of
//     the rotated Q placed at t + c − R_θ c, i.e. v = c − R_θ c + u. The placement t + v is checked
//     with the exact overlap test (nudged outwards by a few ulps if rounding put it inside) and its
//     cost taken by displacement_upper (rounded up past every rounding of the evaluation).
//     Angles: only where a motion can beat the best so far — every motion with angle θ moves two
//     hull vertices q, q' apart by |R_θ − I||q − q'| = 2|sin(θ/2)||q − q'|, so DISP ≥ |sin(θ/2)|·D
//     with D the hull's diameter. In that window of the range: the alignment angles (an edge of Q
//     turned parallel to an edge of P near it, smallest turns first, a quarter of the probes), the
//     exact quarter turns, a uniform grid, then a refinement that bisects the gaps next to the
//     best angle.
//   Why no lower bound between probed angles: σ is not continuous in θ for non-convex pairs (a
//   peg aligned in a tight slot has σ = 0; turned by any ε it overlaps both walls and must be
//   pulled out), and neither is the best cost at a fixed angle, so no Lipschitz argument on
//   probes bounds PD_g below; the parts bound is what is proven.
// Cost: O(k·(n log n + m log m) + k·c·q) for k probes, c = 3 centres, q the cost of a σ query of
// PairDepth2 (docs/benchmarks.md); capped by options.max_probes.
// Numeric domain: the pair is scaled by the front door's power of two (src/front/scale.hpp) before
// the search and every length scaled back.
#include <pendepth/motion.hpp>
#include <pendepth/pendepth.hpp>

#include "front/checks.hpp"
#include "front/scale.hpp"
#include "nonconvex2/convex_parts.hpp"
#include "polygon2/triangulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

namespace pendepth {

namespace {

constexpr double kU = 0x1p-53;  // unit roundoff

// The map of Shape2::rotated(degrees), with the same arithmetic (so the same bits): quarter turns
// exactly, any other angle with the rounded cos and sin of the reduced angle.
struct Turn {
  int quarter = -1;
  double c = 1, s = 0;
  explicit Turn(double degrees) {
    double r = std::fmod(degrees, 360.0);
    if (r < 0) r += 360.0;
    if (r == 360.0) r = 0.0;
    if (Shape2::rotation_is_exact(r)) {
      quarter = static_cast<int>(r / 90.0);
    } else {
      const double rad = r * (std::numbers::pi / 180.0);
      c = std::cos(rad), s = std::sin(rad);
    }
  }
  Vec2 operator()(const Vec2& p) const {
    switch (quarter) {
      case 0: return p;
      case 1: return Vec2(-p.y(), p.x());
      case 2: return Vec2(-p.x(), -p.y());
      case 3: return Vec2(p.y(), -p.x());
      default: return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y());
    }
  }
};

// Convex parts of a shape: itself when convex, else the Hertel–Mehlhorn parts of its triangulation
// (nonconvex2/convex_parts.hpp; the triangles themselves for a shape with holes).
std::vector<ConvexPolygon> convex_parts_of(const Shape2& S) {
  if (S.is_convex()) return {S.convex()};
  const Polygon& poly = S.polygon();
  const auto V = poly.vertices();
  std::vector<polygon2::TriangleIds> ids;
  polygon2::triangulate(poly, ids);
  std::vector<nonconvex2::Tri> tris(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k) {
    int low = 0;
    for (int i = 1; i < 3; ++i) {
      const Vec2 &a = V[ids[k][i]], &b = V[ids[k][low]];
      if (a.y() < b.y() || (a.y() == b.y() && a.x() < b.x())) low = i;
    }
    nonconvex2::Tri& T = tris[k];
    for (int j = 0, i = low; j < 3; ++j, i = i == 2 ? 0 : i + 1) T.v[j] = V[ids[k][i]], T.id[j] = ids[k][i];
    T.lo = T.v[0].cwiseMin(T.v[1]).cwiseMin(T.v[2]);
    T.hi = T.v[0].cwiseMax(T.v[1]).cwiseMax(T.v[2]);
  }
  nonconvex2::ConvexParts cp;
  nonconvex2::convex_parts(tris, poly.hole_count() == 0, cp);
  std::vector<ConvexPolygon> out;
  out.reserve(cp.size());
  for (std::size_t k = 0; k < cp.size(); ++k)
    out.emplace_back(std::span<const Vec2>(cp.v.data() + cp.start[k], cp.start[k + 1] - cp.start[k]), S.name());
  return out;
}

// `s` scaled by 2^-e (exact; as the front door's engine copies).
Shape2 scaled_shape(const Shape2& s, const front::Scale& scale, const char* which) {
  if (scale.identity()) return s;
  auto rings = s.rings();
  for (auto& ring : rings)
    for (Vec2& p : ring) p = scale.vec_to_engine(p, std::string(which) + " (" + s.name() + ")");
  std::vector<Vec2> outer = std::move(rings.front());
  rings.erase(rings.begin());
  return Shape2(std::move(outer), std::move(rings), s.name());
}

struct Search {
  const Shape2 &P, &Q;
  Vec2 t;
  Prepare prepare;
  std::vector<Vec2> hull;     // Q's hull vertices (own frame)
  std::vector<Vec2> centres;  // rotation centres tried at every angle
  double diameter = 0;        // of the hull (a lower estimate is enough: see the window)

  double best = std::numeric_limits<double>::infinity();
  GeneralizedDepth2 r;
  std::map<double, double> probed;  // angle -> best cost found there (inf: none)

  // The probe at `deg`: every centre's candidate, verified; returns the best cost there.
  double probe(double deg) {
    ++r.probes;
    const Turn turn(deg);
    std::optional<Shape2> Qr;
    try {
      Qr.emplace(Q.rotated(deg));
    } catch (const InvalidInput&) {  // rounding made the rotated rings invalid: no motion here
      return std::numeric_limits<double>::infinity();
    }
    const Pair2 pair(P, *Qr, prepare);
    std::vector<Vec2> rq(hull.size());
    for (std::size_t i = 0; i < hull.size(); ++i) rq[i] = turn(hull[i]);
    double here = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const Vec2 shift = centres[k] - turn(centres[k]);
      const Depth2 d = pair.minimum(t + shift);
      const Vec2 move = shift + d.translation;
      // The placement actually tested is fl(t + move·(1 + ε)); nudge outwards while rounding
      // leaves it inside O.
      for (double eps : {0.0, 0x1p-50, 0x1p-44, 0x1p-36}) {
        const Vec2 T = t + move * (1 + eps);
        if (pair.overlapping(T)) continue;
        const Vec2 v = T - t;  // rounded once: displacement_upper accounts for it
        const double cost = displacement_upper(hull.data(), rq.data(), hull.size(), v);
        here = std::min(here, cost);
        if (cost < best) {
          best = cost;
          r.angle = deg;
          r.translation = v;
          r.rotation_exact = Shape2::rotation_is_exact(deg);
          r.sigma_at_angle = k == 0 ? d.depth : pair.minimum(t).depth;
        }
        break;
      }
    }
    probed[deg] = here;
    return here;
  }

  // Whether an angle can still beat the best: DISP ≥ |sin(θ/2)|·D (see the file comment),
  // evaluated with a margin of a millionth so the test never drops a useful angle by rounding.
  bool useful(double deg) const {
    const double s = std::abs(std::sin(deg * (std::numbers::pi / 360.0)));
    return s * diameter * (1 - 1e-6) < best;
  }
};

}  // namespace

double displacement_upper(const Vec2* q, const Vec2* rq, std::size_t n, const Vec2& v) {
  // Per coordinate: fl(fl(rq − q) + v) differs from rq − q + v by at most 2.01·u·(|rq| + |q| + |v|);
  // the Euclidean error is at most the sum of the two coordinates' errors; hypot errs by < 1 ulp;
  // v itself is a rounded difference (half an ulp per coordinate, < u·(|v.x| + |v.y|)). The sum is
  // then raised by 4u for its own roundings.
  double worst = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = (rq[i].x() - q[i].x()) + v.x(), dy = (rq[i].y() - q[i].y()) + v.y();
    const double m = std::hypot(dx, dy);
    const double err = 2.01 * kU *
                           (std::abs(rq[i].x()) + std::abs(q[i].x()) + std::abs(rq[i].y()) + std::abs(q[i].y()) +
                            std::abs(v.x()) + std::abs(v.y())) +
                       kU * (std::abs(v.x()) + std::abs(v.y())) + 2 * kU * m;
    worst = std::max(worst, (m + err) * (1 + 4 * kU));
  }
  return worst;
}

GeneralizedDepth2 generalized_depth(const Shape2& P_in, const Shape2& Q_in, const Vec2& t_in,
                                    const GeneralizedOptions2& o) {
  front::check_placement(t_in);
  if (!std::isfinite(o.min_degrees) || !std::isfinite(o.max_degrees) || o.min_degrees > 0 || o.max_degrees < 0)
    throw InvalidInput("generalized depth: the angle range [" + std::to_string(o.min_degrees) + ", " +
                       std::to_string(o.max_degrees) + "] degrees must be finite and contain 0");
  if (!(o.tolerance >= 0)) throw InvalidInput("generalized depth: the tolerance must be >= 0");

  // The numeric domain: the same power-of-two scale as Pair2 (src/front/scale.hpp).
  front::Extent x;
  for (const Shape2* s : {&P_in, &Q_in})
    for (const auto& ring : s->rings())
      for (std::size_t i = 0; i < ring.size(); ++i) {
        x.add_point(std::max(std::abs(ring[i].x()), std::abs(ring[i].y())));
        x.add_edge(ring[i], ring[i + 1 == ring.size() ? 0 : i + 1]);
      }
  const front::Scale scale = front::Scale::for_pair(x, front::kBand2);
  const Shape2 P = scaled_shape(P_in, scale, "P"), Q = scaled_shape(Q_in, scale, "Q");
  const Vec2 t = scale.vec_to_engine(t_in, "placement");

  GeneralizedDepth2 r;
  const Depth2 s0 = Pair2(P, Q, o.prepare).minimum(t);
  r.overlapping = s0.overlapping;
  r.sigma = r.sigma_at_angle = s0.depth;
  auto back = [&](GeneralizedDepth2 a) {
    a.depth = scale.length(a.depth), a.lower_bound = scale.length(a.lower_bound);
    a.upper_bound = scale.length(a.upper_bound), a.sigma = scale.length(a.sigma);
    a.sigma_at_angle = scale.length(a.sigma_at_angle), a.translation = scale.vec(a.translation);
    return a;
  };
  if (!s0.overlapping) return back(r);
  if (P.is_convex() && Q.is_convex() && o.convex_theorem) {
    r.depth = r.lower_bound = r.upper_bound = s0.depth;
    r.translation = s0.translation;
    return back(r);
  }

  // Lower bound: pairs of convex parts.
  double lower = 0;
  const auto parts_p = convex_parts_of(P), parts_q = convex_parts_of(Q);
  // Only pairs whose boxes overlap can overlap (boxes of Q's parts placed at t, widened by a
  // relative 2^-40 so that the rounding of the placed box never drops a pair).
  auto box = [](const ConvexPolygon& C, const Vec2& at) {
    Vec2 lo = C[0] + at, hi = lo;
    for (const Vec2& v : C.vertices()) lo = lo.cwiseMin(v + at), hi = hi.cwiseMax(v + at);
    const Vec2 pad = 0x1p-40 * (lo.cwiseAbs().cwiseMax(hi.cwiseAbs()));
    return std::array<Vec2, 2>{lo - pad, hi + pad};
  };
  std::vector<std::array<Vec2, 2>> boxes_q;
  for (const auto& B : parts_q) boxes_q.push_back(box(B, t));
  for (const auto& A : parts_p) {
    const auto a = box(A, Vec2(0, 0));
    for (std::size_t j = 0; j < parts_q.size(); ++j) {
      const auto& b = boxes_q[j];
      if ((a[1].array() < b[0].array()).any() || (b[1].array() < a[0].array()).any()) continue;
      const Depth2 d = minimum_depth(A, parts_q[j], t);
      if (d.overlapping) lower = std::max(lower, d.depth);
    }
  }
  lower *= 1 - 16 * kU;

  Search S{P, Q, t, o.prepare, {}, {}, 0, std::numeric_limits<double>::infinity(), r, {}};
  const auto outer = Q.rings().front();
  const ConvexPolygon hull = ConvexPolygon::hull(outer, Q.name());
  S.hull.assign(hull.vertices().begin(), hull.vertices().end());
  Vec2 lo = S.hull[0], hi = S.hull[0], mean(0, 0);
  for (const Vec2& q : S.hull) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q), mean += q;
  mean /= double(S.hull.size());
  S.centres = {Vec2(0, 0), 0.5 * (lo + hi), mean};
  if (S.hull.size() <= 512) {
    for (const Vec2& a : S.hull)
      for (const Vec2& b : S.hull) S.diameter = std::max(S.diameter, (a - b).norm());
  } else {
    for (const Vec2& b : S.hull) S.diameter = std::max(S.diameter, (S.hull[0] - b).norm());  // ≤ diameter
  }

  auto closed = [&] { return S.best - lower <= o.tolerance * S.best; };
  const std::size_t cap = std::max<std::size_t>(o.max_probes, 1);
  auto try_angle = [&](double deg) {
    if (S.r.probes >= cap || S.probed.count(deg) || !S.useful(deg)) return;
    S.probe(deg);
  };
  // Angle 0 first (the range holds it): σ's own motion, often already optimal.
  try_angle(0.0);
  if (!closed()) {
    // The window where a motion can still beat the best: |sin(θ/2)|·D < best.
    const double half = S.best < S.diameter ? 2 * std::asin(S.best / S.diameter) * (180 / std::numbers::pi) : 180.0;
    std::vector<std::pair<double, double>> windows;
    for (double k = std::floor((o.min_degrees - half) / 360); k <= std::ceil((o.max_degrees + half) / 360); ++k) {
      const double a = std::max(o.min_degrees, 360 * k - half), b = std::min(o.max_degrees, 360 * k + half);
      if (a <= b) windows.emplace_back(a, b);
    }
    // Alignment angles first, smallest turn first (a quarter of the probes): the turns that make
    // an edge of Q parallel to an edge of P near it — where exact fits and slots are (an isolated
    // angle a grid misses: a square turned in a square hole fits at one angle only).
    {
      const auto pr = P.rings(), qr = Q.rings();
      Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
      for (const Vec2& q : S.hull) lo = lo.cwiseMin(q + t), hi = hi.cwiseMax(q + t);
      const Vec2 pad = Vec2::Constant(S.best);
      std::vector<double> dir_p, dir_q;
      for (const auto& ring : pr)
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Vec2 &a = ring[i], &b = ring[i + 1 == ring.size() ? 0 : i + 1];
          if ((a.cwiseMax(b).array() < (lo - pad).array()).any() || (a.cwiseMin(b).array() > (hi + pad).array()).any())
            continue;  // an edge of P away from where Q can go
          dir_p.push_back(std::atan2(b.y() - a.y(), b.x() - a.x()));
        }
      for (const auto& ring : qr)
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Vec2 &a = ring[i], &b = ring[i + 1 == ring.size() ? 0 : i + 1];
          dir_q.push_back(std::atan2(b.y() - a.y(), b.x() - a.x()));
        }
      std::vector<double> align;
      if (dir_p.size() * dir_q.size() <= (std::size_t(1) << 18))
        for (double a : dir_p)
          for (double b : dir_q)
            for (double flip : {0.0, 180.0}) {
              double d = std::remainder((a - b) * (180 / std::numbers::pi) + flip, 360.0);
              if (d >= o.min_degrees && d <= o.max_degrees && d != 0) align.push_back(d);
            }
      std::sort(align.begin(), align.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
      align.erase(std::unique(align.begin(), align.end()), align.end());
      const std::size_t budget = cap / 4;
      for (std::size_t i = 0, used = 0; i < align.size() && used < budget && !closed(); ++i)
        if (!S.probed.count(align[i]) && S.useful(align[i])) try_angle(align[i]), ++used;
    }
    const std::size_t grid = std::max<std::size_t>(2, std::min<std::size_t>(cap / 2, 128));
    for (const auto& [a, b] : windows) {
      if (a == b) continue;
      for (double q = std::ceil(a / 90) * 90; q <= b; q += 90) try_angle(q);
      for (std::size_t i = 0; i <= grid && !closed(); ++i) try_angle(a + (b - a) * double(i) / double(grid));
    }
    // Refinement: bisect the gaps on either side of the best angle until they are below 1e-9°.
    while (S.r.probes < cap && !closed() && std::isfinite(S.best)) {
      const double b = S.r.angle;
      auto it = S.probed.find(b);
      bool progressed = false;
      if (it != S.probed.begin()) {
        const double m = 0.5 * (std::prev(it)->first + b);
        if (b - std::prev(it)->first > 1e-9 && !S.probed.count(m)) S.probe(m), progressed = true;
      }
      it = S.probed.find(b);
      if (std::next(it) != S.probed.end() && S.r.probes < cap) {
        const double m = 0.5 * (b + std::next(it)->first);
        if (std::next(it)->first - b > 1e-9 && !S.probed.count(m)) S.probe(m), progressed = true;
      }
      if (!progressed) break;
    }
  }
  r = S.r;
  r.upper_bound = r.depth = S.best;
  r.lower_bound = std::min(lower, S.best);
  r.converged = closed();
  return back(r);
}

}  // namespace pendepth
