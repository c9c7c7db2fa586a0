// Generalized penetration depth PD_g in 2D (survey §4; include/pendepth/motion.hpp).
//
// Contract: P fixed, Q at t; a motion rotates Q by θ about its reference point and translates it
// by v; its cost is DISP(θ, v) = max_{q ∈ Q} |R_θ q + v − q|, attained at a vertex of Q's convex
// hull (a convex function of q). Returns certified bounds lower ≤ PD_g ≤ upper and the motion that
// realises `upper` (verified separating by the exact overlap test on Q.rotated(θ)).
//
// Method.
//   Both convex: PD_g = σ (theorem, motion.hpp); no probing.
//   Parts bound: max over pairs of convex parts (P_i, Q_j) overlapping at t of σ(P_i, Q_j). Any
//     motion separating P and Q separates P_i from the moved Q_j ⊆ moved Q, and the displacement of
//     Q's points bounds that of Q_j's, which is ≥ σ(P_i, Q_j) by the theorem for convex pairs.
//     σ of two convex polygons is within a few ulps (minimum_depth); it is lowered by 16 ulps.
//   Probes (upper bounds): for an angle θ, Q.rotated(θ) (the coordinates a user of the rotation
//     gets), a Pair2 (options.prepare), and for three rotation centres c (Q's reference point, the
//     centre of its hull's box, the mean of its hull vertices) the exact σ translation u of the
//     rotated Q placed at t + c − R_θ c, i.e. v = c − R_θ c + u. Angles: 0, the quarter turns and
//     the edge alignments near Q (an edge of Q turned parallel to an edge of P: where slots and
//     exact fits are), smallest turn first, only where |sin(θ/2)|·D < best (D hull diameter).
//   Branch and bound over angle intervals I = [a, b] (radians, m the middle, h ≥ the half-width):
//     rotate about ζ, the centre of the smallest enclosing circle of Q's hull (R_c ≥ max |q − ζ|).
//     Lower bound of every separating motion with angle θ ∈ I:
//       - rotation: the motion has a fixed point z and moves the hull vertex farthest from it by
//         2|sin(θ/2)|·|q − z| ≥ 2|sin(θ/2)|·R_mec (a lower bound of the enclosing radius);
//       - eroded parts: E_j = R_m(Q_j − ζ) ⊖ disk(ρ), ρ ≥ 2 sin(h/2)·R_c + the rounding of the
//         rotated vertices (32u·R_c), computed by clipping the hull of the rotated vertices by its
//         edges moved in, every vertex then certified ≥ ρ inside every edge line by a floating value
//         with a proven error bound (exact::Fl; else clip deeper, or drop the part). A point y of E_j
//         turned by θ − m moves ≤ 2 sin(h/2)|y| ≤ ρ, so E_j ⊆ R_θ(Q_j − ζ): the position u of ζ of a
//         separating motion is outside U = ∪ int(P_i ⊕ (−E_j));
//       - cost: DISP ≥ max_k (|u − z_k| − r_k), z_k = q_k + t − R_m(q_k − ζ), r_k ≥ 2 sin(h/2)|q_k − ζ|
//         plus the rounding of z_k; its minimum over the free set ℝ² \ U by motion::FreeSpace
//         (free_space2.hpp: the sums' edges cut by the other open sums, exact signs, covered
//         intervals shrunk; golden section per kept piece with a Lipschitz bound, rounded down).
//         That minimum is over the boundary unless the unconstrained minimiser is free: the
//         sublevel set {f < bound} is convex and misses the boundary, so it lies in U when one of
//         its points does — the pure rotation about ζ (u = ζ + t), tested exactly. Otherwise the
//         interval keeps only the rotation bound.
//     Upper bound at the middle angle of every interval left open: the same free-space minimum of
//     the unweighted cost on Q.rotated(m)'s parts (h = 0), and the pure rotation about ζ; each
//     candidate checked by the exact overlap test at the placement t + v the caller gets (nudged
//     along the edge's outward normal by ulps if rounding put it inside) and costed by
//     displacement_upper.
//     Search: intervals of at most π/8 cut at 0 and at the quarter turns, best-first by lower
//     bound, bisected; an interval closes when its bound is within the tolerance of the best upper
//     bound. Stops when every open interval's bound is within the tolerance (converged) or after
//     max_intervals evaluations. Where the best cost is flat in θ (Q pinned by one vertex: turning
//     about it changes nothing) the bound's O(h·R_c) slack needs tiny intervals all along the
//     plateau and the budget may run out first (the gap is then reported).
//   Exact fits at non-quarter angles are lost to the rounding of Q.rotated's coordinates (the
//   rotated copy is a hair larger than the hole): the lower bound sees them, the upper bound
//   cannot reach them, so such pairs do not converge.
// Cost: probes O(k·(n log n + m log m) + k·c·q) (c = 3 centres, q a σ query of Pair2); per interval
// O(Σ n_i m_j) exact turn signs to build the sums, then per visited edge O(S·ℓ) line tests; on
// nesting pieces 50–80 intervals per query (docs/benchmarks.md).
// Numeric domain: the pair is scaled by the front door's power of two (src/front/scale.hpp) before
// the search and every length scaled back.
#include <pendepth/motion.hpp>
#include <pendepth/pendepth.hpp>

#include "front/checks.hpp"
#include "geometry/exact.hpp"
#include "motion/free_space2.hpp"
#include "front/scale.hpp"
#include "front/shape2_data.hpp"
#include "nonconvex2/convex_parts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <queue>
#include <set>
#include <span>

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
// (nonconvex2/convex_parts.hpp; the triangles themselves for a shape with holes), made once per
// shape and shared with its other pairs and calls (the shape's role-P side, front/shape2_data.hpp).
std::vector<ConvexPolygon> convex_parts_of(const Shape2& S) {
  if (S.is_convex()) return {S.convex()};
  const nonconvex2::ConvexParts& cp = front::shape_side(S, false)->parts();
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
  std::set<double> exact_probed;     // angles whose exact best motion was tried (Bnb::upper)

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
      // The placement the caller gets is t + fl(t + move·(1 + ε) − t); nudge outwards while
      // rounding leaves it inside O.
      for (double eps : {0.0, 0x1p-50, 0x1p-44, 0x1p-36}) {
        const Vec2 v = (t + move * (1 + eps)) - t;  // rounded: displacement_upper accounts for it
        if (pair.overlapping(t + v)) continue;  // the placement the caller gets
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


// ---- branch and bound over angle intervals (the certified lower bound between angles) ----------

double round_up(double x) { return x + (std::abs(x) * 4 * kU + 1e-300); }
double round_down(double x) { return x - (std::abs(x) * 4 * kU + 1e-300); }

// The smallest enclosing circle of Q's hull vertices (Welzl, move-to-front order, floating): its
// centre ζ is the rotation centre of the bounds (it minimises R_c = max |q − ζ|); `rc` ≥ R_c
// (rounded up), `rmec_low` ≤ the true smallest radius (the smallest circle of the 2 or 3 support
// points found, rounded down: a subset's circle is never larger).
struct Enclosing {
  Vec2 centre{0, 0};
  double rc = 0, rmec_low = 0;
};
Enclosing enclosing(const std::vector<Vec2>& h) {
  struct C {
    Vec2 c{0, 0};
    double r = -1;
    std::vector<Vec2> s;
  };
  auto two = [](const Vec2& a, const Vec2& b) { return C{0.5 * (a + b), 0.5 * (a - b).norm(), {a, b}}; };
  auto three = [&](const Vec2& a, const Vec2& b, const Vec2& c) {
    const Vec2 ab = b - a, ac = c - a;
    const double d = 2 * (ab.x() * ac.y() - ab.y() * ac.x());
    if (d == 0) {
      C best = two(a, b);
      for (const C& x : {two(a, c), two(b, c)})
        if (x.r > best.r) best = x;
      return best;
    }
    const Vec2 o(ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm(),
                 ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm());
    const Vec2 cen = a + o / d;
    return C{cen, std::max({(a - cen).norm(), (b - cen).norm(), (c - cen).norm()}), {a, b, c}};
  };
  auto in = [](const C& c, const Vec2& p) { return (p - c.c).norm() <= c.r * (1 + 1e-12); };
  C c;
  c.c = h[0], c.r = 0, c.s = {h[0]};
  for (std::size_t i = 1; i < h.size(); ++i) {
    if (in(c, h[i])) continue;
    c = C{h[i], 0, {h[i]}};
    for (std::size_t j = 0; j < i; ++j) {
      if (in(c, h[j])) continue;
      c = two(h[i], h[j]);
      for (std::size_t k = 0; k < j; ++k)
        if (!in(c, h[k])) c = three(h[i], h[j], h[k]);
    }
  }
  Enclosing e;
  e.centre = c.c;
  for (const Vec2& q : h) e.rc = std::max(e.rc, (q - c.c).norm());
  e.rc = round_up(e.rc * (1 + 4 * kU));
  // The smallest circle of the support points: the longest side's half when the triangle is not
  // acute, else the circumradius abc / (4·area).
  double low = 0;
  const auto& s = c.s;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) low = std::max(low, 0.5 * (s[i] - s[j]).norm());
  if (s.size() == 3) {
    const double a = (s[1] - s[2]).norm(), b = (s[0] - s[2]).norm(), cc = (s[0] - s[1]).norm();
    const double m = std::max({a, b, cc}), sq = a * a + b * b + cc * cc;
    const double area2 = std::abs((s[1] - s[0]).x() * (s[2] - s[0]).y() - (s[1] - s[0]).y() * (s[2] - s[0]).x());
    if (2 * m * m < sq && area2 > 0) low = std::max(low, a * b * cc / (2 * area2));
  }
  e.rmec_low = low * (1 - 1e-9);
  return e;
}

// The convex polygon H eroded by the disk of radius rho, rounded inwards: the clip by the edges'
// half-planes moved in by a slightly larger radius, each resulting vertex then certified at
// distance ≥ rho inside every edge line of H (floating value with a proven error bound,
// exact::Fl). Empty when nothing certified remains (the part is dropped: a smaller union only
// lowers the bound).
std::optional<std::vector<Vec2>> erode(std::span<const Vec2> H, double rho) {
  const std::size_t n = H.size();
  double big = 0;
  for (const Vec2& v : H) big = std::max(big, v.cwiseAbs().maxCoeff());
  for (int attempt = 0; attempt < 3; ++attempt) {
    const double rr = rho * (1 + std::ldexp(1.0, -40 + 8 * attempt)) + std::ldexp(64 * kU * big, 8 * attempt) + 1e-300;
    std::vector<Vec2> poly(H.begin(), H.end()), next;
    for (std::size_t i = 0; i < n && poly.size() >= 3; ++i) {
      const Vec2 &v0 = H[i], &v1 = H[i + 1 == n ? 0 : i + 1];
      const Vec2 e = v1 - v0;
      const double off = rr * e.norm();
      auto val = [&](const Vec2& p) { return e.x() * (p.y() - v0.y()) - e.y() * (p.x() - v0.x()) - off; };
      next.clear();
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const Vec2 &p = poly[k], &q = poly[k + 1 == poly.size() ? 0 : k + 1];
        const double fp = val(p), fq = val(q);
        if (fp >= 0) next.push_back(p);
        if ((fp >= 0) != (fq >= 0)) next.push_back(p + (q - p) * (fp / (fp - fq)));
      }
      poly.swap(next);
    }
    if (poly.size() < 3) return std::nullopt;
    bool ok = true;
    for (const Vec2& w : poly)
      for (std::size_t i = 0; i < n && ok; ++i) {
        const Vec2 &v0 = H[i], &v1 = H[i + 1 == n ? 0 : i + 1];
        using exact::Fl;
        const Fl ex = Fl{v1.x(), 0} - Fl{v0.x(), 0}, ey = Fl{v1.y(), 0} - Fl{v0.y(), 0};
        const Fl c = ex * (Fl{w.y(), 0} - Fl{v0.y(), 0}) - ey * (Fl{w.x(), 0} - Fl{v0.x(), 0});
        const double len =
            std::hypot(std::abs(ex.v) + exact::safe_bound(ex.e), std::abs(ey.v) + exact::safe_bound(ey.e)) * (1 + 4 * kU);
        ok = c.v - exact::safe_bound(c.e) >= round_up(rho * len);
      }
    if (!ok) continue;
    try {
      const ConvexPolygon E = ConvexPolygon::hull(poly, "eroded part");
      return std::vector<Vec2>(E.vertices().begin(), E.vertices().end());
    } catch (const InvalidInput&) {
      return std::nullopt;
    }
  }
  return std::nullopt;
}

// Angle intervals I = [a, b] (radians): a certified lower bound of DISP over every separating
// motion with angle in I, and the exact best motion at an angle as an upper-bound candidate.
struct Bnb {
  const Shape2 &P, &Q;
  Vec2 t;
  const std::vector<ConvexPolygon> &parts_p, &parts_q;
  Search& S;
  Enclosing enc;
  double parts_lower = 0;
  double min_deg = 0, max_deg = 0;
  std::size_t evaluations = 0;

  // min over θ ∈ [a, b] of 2|sin(θ/2)|·R_mec: every motion with angle θ has a fixed point z and
  // moves the hull vertex farthest from z by 2|sin(θ/2)|·|q − z| ≥ 2|sin(θ/2)|·R_mec.
  double rotation_bound(double a, double b) const {
    const double k = std::ceil(a / (2 * std::numbers::pi) - 1e-9);  // a multiple of 2π in [a, b]?
    if (k * 2 * std::numbers::pi <= b + 1e-9 * (1 + std::abs(b))) return 0;
    const double s = std::min(std::abs(std::sin(0.5 * a)), std::abs(std::sin(0.5 * b)));
    return std::max(0.0, round_down(round_down(2 * s) * enc.rmec_low) * (1 - 1e-12));
  }

  double lower(double a, double b) {
    ++evaluations;
    const double cap = S.best;
    double lb = std::max(rotation_bound(a, b), parts_lower);
    if (lb >= cap) return lb;
    const double m = 0.5 * (a + b);
    const double h = round_up(std::max(m - a, b - m));
    const double s2 = round_up(std::sin(0.5 * h));  // ≥ sin(h/2)
    const double cm = std::cos(m), sm = std::sin(m);
    // ρ ≥ 2 sin(h/2)·R_c plus the rounding of the rotated vertices (≤ 12u·|q − ζ|, taken as 32u·R_c).
    const double rho = round_up(round_up(2 * s2) * enc.rc) + 32 * kU * enc.rc + 1e-300;
    const Vec2 zeta = enc.centre;
    auto rot = [&](const Vec2& d) { return Vec2(cm * d.x() - sm * d.y(), sm * d.x() + cm * d.y()); };
    std::vector<std::vector<Vec2>> eroded;
    for (const ConvexPolygon& Qj : parts_q) {
      std::vector<Vec2> ys;
      for (const Vec2& q : Qj.vertices()) ys.push_back(rot(q - zeta));
      try {
        const ConvexPolygon H = ConvexPolygon::hull(ys, "rotated part");
        if (auto E = erode(H.vertices(), rho)) eroded.push_back(std::move(*E));
      } catch (const InvalidInput&) {
      }
    }
    if (eroded.empty()) return lb;
    const motion::FreeSpace fs(parts_p, eroded);
    // f(u) = max_k |u − z_k| − r_k with u the position of ζ: z_k = q_k + t − R_m(q_k − ζ) (no move
    // of q_k at angle m), r_k ≥ 2 sin(h/2)|q_k − ζ| plus the rounding of z_k.
    motion::FarthestCost fc;
    double zmax = 0;
    for (const Vec2& q : S.hull) {
      const Vec2 d = q - zeta;
      fc.z.push_back(q + t - rot(d));
      fc.r.push_back(round_up(round_up(2 * s2) * round_up(d.norm())) +
                     32 * kU * (q.cwiseAbs().sum() + t.cwiseAbs().sum() + 2 * enc.rc) + 1e-300);
      zmax = std::max(zmax, fc.z.back().cwiseAbs().maxCoeff());
    }
    const motion::FreeMinimum fm = fs.minimum(fc, cap);
    if (fm.lower <= lb) return lb;
    // min over the free set equals min over Γ ⊇ ∂C when the sublevel set {f < fm.lower} lies in
    // U: it is convex, misses Γ, so it lies in U if one of its points does (pure rotation about ζ).
    const Vec2 uc = zeta + t;
    double fu = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < fc.z.size(); ++k) fu = std::max(fu, (uc - fc.z[k]).norm() - fc.r[k]);
    fu = round_up(fu) + 64 * kU * (uc.cwiseAbs().maxCoeff() + zmax) + 1e-300;
    if (fu < fm.lower && fs.inside(uc)) lb = fm.lower;
    return lb;
  }

  // The exact best motion at `deg` (free-space minimum of the unweighted cost on Q.rotated's
  // coordinates), verified by the exact overlap test (nudged out by ulps if rounding put it
  // inside) and costed by displacement_upper.
  void upper(double deg) {
    deg = std::clamp(deg, min_deg, max_deg);
    if (!S.exact_probed.insert(deg).second) return;
    const Turn turn(deg);
    std::vector<std::vector<Vec2>> moving;
    for (const ConvexPolygon& Qj : parts_q) {
      std::vector<Vec2> ys;
      for (const Vec2& q : Qj.vertices()) ys.push_back(turn(q));
      try {
        const ConvexPolygon H = ConvexPolygon::hull(ys, "rotated part");
        moving.emplace_back(H.vertices().begin(), H.vertices().end());
      } catch (const InvalidInput&) {
      }
    }
    std::vector<Vec2> rq(S.hull.size());
    motion::FarthestCost fc;
    for (std::size_t i = 0; i < S.hull.size(); ++i) {
      rq[i] = turn(S.hull[i]);
      fc.z.push_back(t + S.hull[i] - rq[i]);
      fc.r.push_back(0);
    }
    auto value = [&](const Vec2& T) {
      double v = 0;
      for (const Vec2& z : fc.z) v = std::max(v, (T - z).norm());
      return v;
    };
    std::vector<std::pair<Vec2, Vec2>> cand;  // placement of Q's origin, outward nudge direction
    const Vec2 pure = t + enc.centre - turn(enc.centre);  // rotation about ζ only
    if (value(pure) < S.best) cand.emplace_back(pure, Vec2(0, 0));
    if (!moving.empty()) {
      const motion::FreeSpace fs(parts_p, moving);
      const motion::FreeMinimum fm = fs.minimum(fc, S.best);
      if (fm.found && fm.value < S.best) cand.emplace_back(fm.argmin, fm.outward);
    }
    if (cand.empty()) return;
    std::optional<Shape2> Qr;
    try {
      Qr.emplace(Q.rotated(deg));
    } catch (const InvalidInput&) {
      return;
    }
    const Pair2 pair(P, *Qr, Prepare::Queries);
    for (const auto& [T0, n] : cand) {
      const double scale = T0.cwiseAbs().maxCoeff() + enc.rc + enc.centre.cwiseAbs().maxCoeff();
      for (double eps : {0.0, 0x1p-50, 0x1p-46, 0x1p-42, 0x1p-36}) {
        const Vec2 v = (T0 + n * (eps * scale)) - t;
        if (pair.overlapping(t + v)) continue;  // the placement the caller gets
        const double cost = displacement_upper(S.hull.data(), rq.data(), S.hull.size(), v);
        if (cost < S.best) {
          S.best = cost;
          S.r.angle = deg;
          S.r.translation = v;
          S.r.rotation_exact = Shape2::rotation_is_exact(deg);
          S.r.sigma_at_angle = pair.minimum(t).depth;
        }
        break;
      }
    }
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

  Search S{P, Q, t, o.prepare, {}, {}, 0, std::numeric_limits<double>::infinity(), r, {}, {}};
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

  double global_lower = lower;  // the parts bound until the branch and bound certifies more
  auto closed = [&] { return S.best - global_lower <= o.tolerance * S.best; };
  const std::size_t cap = std::max<std::size_t>(o.max_probes, 1);
  auto try_angle = [&](double deg) {
    if (S.r.probes >= cap || S.probed.count(deg) || !S.useful(deg)) return;
    S.probe(deg);
  };
  Bnb B{P, Q, t, parts_p, parts_q, S, enclosing(S.hull), lower, o.min_degrees, o.max_degrees, 0};
  B.enc.rmec_low = std::max(B.enc.rmec_low, 0.5 * S.diameter * (1 - 1e-9));  // R_mec ≥ D/2
  // Angle 0 first (the range holds it): σ's own motion, often already optimal; then the exact best
  // motion there.
  try_angle(0.0);
  B.upper(0.0);
  if (!closed()) {
    // Quarter turns (exact coordinates: exact fits there are attainable), then the alignment
    // angles, smallest turn first (an edge of Q turned parallel to an edge of P near it: where
    // slots and exact fits are), each probed by σ about three centres and by its exact best motion.
    for (double q = std::ceil(o.min_degrees / 90) * 90; q <= o.max_degrees; q += 90)
      if (q != 0 && S.useful(q)) try_angle(q), B.upper(q);
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
      const std::size_t budget = std::max<std::size_t>(cap / 16, 1);
      for (std::size_t i = 0, used = 0; i < align.size() && used < budget && !closed(); ++i)
        if (!S.probed.count(align[i]) && S.useful(align[i])) try_angle(align[i]), B.upper(align[i]), ++used;
    }
  }
  // Branch and bound over angle intervals (radians), best-first by lower bound. The range is
  // widened by the rounding of its conversion; intervals start at most π/8 wide, split at 0 and at
  // the quarter turns.
  if (!closed() && std::isfinite(S.best)) {
    constexpr double kPi = std::numbers::pi, kDeg = std::numbers::pi / 180;
    struct Node {
      double lb, a, b;
      bool operator>(const Node& o) const { return lb > o.lb; }
    };
    std::priority_queue<Node, std::vector<Node>, std::greater<Node>> heap;
    double settled = std::numeric_limits<double>::infinity();  // min lower bound of closed intervals
    auto closes = [&](double lb) { return S.best - lb <= o.tolerance * S.best; };
    // An interval that stays open gets its middle angle's exact best motion (the upper bound
    // that closes it and its neighbours).
    auto visit = [&](double a, double b, double parent) {
      const double lb = std::max(parent, B.lower(a, b));
      if (!closes(lb)) B.upper(0.5 * (a + b) / kDeg);
      if (closes(lb)) settled = std::min(settled, lb);
      else heap.push({lb, a, b});
    };
    const double a0 = round_down(o.min_degrees * kDeg), b0 = round_up(o.max_degrees * kDeg);
    std::vector<double> cuts{a0, b0};
    for (double q = std::ceil(a0 / (kPi / 2)); q * (kPi / 2) < b0; ++q)
      if (q * (kPi / 2) > a0) cuts.push_back(q * (kPi / 2));
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const int pieces = std::max(1, int(std::ceil((cuts[i + 1] - cuts[i]) / (kPi / 8))));
      for (int k = 0; k < pieces; ++k) {
        const double a = k == 0 ? cuts[i] : cuts[i] + (cuts[i + 1] - cuts[i]) * k / pieces;
        const double b = k + 1 == pieces ? cuts[i + 1] : cuts[i] + (cuts[i + 1] - cuts[i]) * (k + 1) / pieces;
        visit(a, b, 0);
      }
    }
    while (!heap.empty()) {
      const Node n = heap.top();
      if (closes(std::min(n.lb, settled)) || B.evaluations >= o.max_intervals) break;
      heap.pop();
      const double m = 0.5 * (n.a + n.b);
      if (closes(n.lb) || !(n.a < m && m < n.b)) {  // closed since the upper bound dropped, or unsplittable
        settled = std::min(settled, n.lb);
        continue;
      }
      visit(n.a, m, n.lb);
      visit(m, n.b, n.lb);
    }
    const double open = heap.empty() ? std::numeric_limits<double>::infinity() : heap.top().lb;
    global_lower = std::max(lower, std::min(settled, open));
  }
  r = S.r;
  r.intervals = B.evaluations;
  r.upper_bound = r.depth = S.best;
  r.lower_bound = std::min(global_lower, S.best);
  r.converged = closed();
  return back(r);
}

}  // namespace pendepth
