// The minimum of a weighted farthest-point cost over the free placements of a moving union of
// convex parts: contract, method and cost in free_space2.hpp.
#include "motion/free_space2.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/exact.hpp"

namespace pendepth::motion {

namespace {

constexpr double kU = 0x1p-53;
constexpr double kPad = 0x1p-40;  // relative padding of boxes (covers their rounding)

// Exact sign of cross(d1 − d0, p − q) for input doubles.
int turn_sign(const Vec2& d0, const Vec2& d1, const Vec2& p, const Vec2& q) {
  return exact::exact_sign([&](auto L) {
    return (L(d1.x()) - L(d0.x())) * (L(p.y()) - L(q.y())) - (L(d1.y()) - L(d0.y())) * (L(p.x()) - L(q.x()));
  });
}

Vec2 pad_down(const Vec2& v) { return v - kPad * v.cwiseAbs() - Vec2::Constant(1e-300); }
Vec2 pad_up(const Vec2& v) { return v + kPad * v.cwiseAbs() + Vec2::Constant(1e-300); }

double up(double x) { return x + (std::abs(x) * 4 * kU + 1e-300); }
double down(double x) { return x - (std::abs(x) * 4 * kU + 1e-300); }

double dist_point_segment(const Vec2& p, const Vec2& a, const Vec2& d) {
  const double dd = d.squaredNorm();
  double l = dd > 0 ? (p - a).dot(d) / dd : 0;
  l = std::clamp(l, 0.0, 1.0);
  return (a + l * d - p).norm();
}

}  // namespace

FreeSpace::FreeSpace(const std::vector<ConvexPolygon>& fixed, const std::vector<std::vector<Vec2>>& moving) {
  std::vector<std::vector<Vec2>> neg(moving.size());
  for (std::size_t j = 0; j < moving.size(); ++j)
    for (const Vec2& e : moving[j]) neg[j].push_back(-e), scale_ = std::max(scale_, e.cwiseAbs().maxCoeff());
  for (const ConvexPolygon& A : fixed)
    for (const Vec2& a : A.vertices()) scale_ = std::max(scale_, a.cwiseAbs().maxCoeff());
  for (const ConvexPolygon& Apoly : fixed) {
    const auto A = Apoly.vertices();
    Vec2 alo = A[0], ahi = A[0];
    for (const Vec2& a : A) alo = alo.cwiseMin(a), ahi = ahi.cwiseMax(a);
    for (const auto& B : neg) {
      Vec2 blo = B[0], bhi = B[0];
      for (const Vec2& b : B) blo = blo.cwiseMin(b), bhi = bhi.cwiseMax(b);
      Sum s;
      s.first = segs_.size();
      s.lo = pad_down(alo + blo), s.hi = pad_up(ahi + bhi);
      // An edge x0 → x1 of one part at the other part's vertices extreme against its outward normal
      // (smallest cross(x1 − x0, y)); ties all kept so that collinear edges cover the sum's edge.
      auto add = [&](std::span<const Vec2> X, std::span<const Vec2> Y) {
        for (std::size_t i = 0; i < X.size(); ++i) {
          const Vec2 &x0 = X[i], &x1 = X[i + 1 == X.size() ? 0 : i + 1];
          std::size_t best = 0;
          for (std::size_t k = 1; k < Y.size(); ++k)
            if (turn_sign(x0, x1, Y[k], Y[best]) < 0) best = k;
          for (std::size_t k = 0; k < Y.size(); ++k) {
            if (k != best && turn_sign(x0, x1, Y[k], Y[best]) != 0) continue;
            Seg g{x0, x1, Y[k], {}, {}};
            g.lo = pad_down(x0.cwiseMin(x1) + Y[k]), g.hi = pad_up(x0.cwiseMax(x1) + Y[k]);
            segs_.push_back(g);
          }
        }
      };
      add(A, B);
      add(B, A);
      s.count = segs_.size() - s.first;
      sums_.push_back(s);
    }
  }
}

bool FreeSpace::inside(const Vec2& u) const {
  for (const Sum& k : sums_) {
    if ((u.array() <= k.lo.array()).any() || (u.array() >= k.hi.array()).any()) continue;
    bool in = true;
    for (std::size_t i = k.first; i < k.first + k.count && in; ++i) {
      const Seg& s = segs_[i];
      in = exact::exact_sign([&](auto L) {
             return (L(s.x1.x()) - L(s.x0.x())) * (L(u.y()) - L(s.x0.y()) - L(s.y.y())) -
                    (L(s.x1.y()) - L(s.x0.y())) * (L(u.x()) - L(s.x0.x()) - L(s.y.x()));
           }) > 0;
    }
    if (in) return true;
  }
  return false;
}

bool FreeSpace::covered(const Seg& s, const Sum& k, double& lo, double& hi) const {
  lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  for (std::size_t i = k.first; i < k.first + k.count; ++i) {
    const Seg& l = segs_[i];
    // α + λ·β > 0 on the open side: α = cross(D, x0 + y − o), β = cross(D, x1 − x0), D the line's.
    auto alpha = [&](auto L) {
      return (L(l.x1.x()) - L(l.x0.x())) * (L(s.x0.y()) + L(s.y.y()) - L(l.x0.y()) - L(l.y.y())) -
             (L(l.x1.y()) - L(l.x0.y())) * (L(s.x0.x()) + L(s.y.x()) - L(l.x0.x()) - L(l.y.x()));
    };
    auto beta = [&](auto L) {
      return (L(l.x1.x()) - L(l.x0.x())) * (L(s.x1.y()) - L(s.x0.y())) -
             (L(l.x1.y()) - L(l.x0.y())) * (L(s.x1.x()) - L(s.x0.x()));
    };
    // The same edge of a part (in either direction) in two sums: parallel symbolically.
    if ((s.x0 == l.x0 && s.x1 == l.x1) || (s.x0 == l.x1 && s.x1 == l.x0)) {
      if (exact::exact_sign(alpha) <= 0) return false;
      continue;
    }
    const exact::Fl a = alpha(exact::LiftFl{}), b = beta(exact::LiftFl{});
    const double ae = exact::safe_bound(a.e), be = exact::safe_bound(b.e);
    if (!std::isfinite(a.v) || !std::isfinite(ae) || !std::isfinite(b.v) || !std::isfinite(be)) return false;
    const int sb = std::abs(b.v) > be ? (b.v > 0 ? 1 : -1) : exact::exact_sign(beta);
    if (sb == 0) {  // parallel: the whole line is on the open side or none of it
      if (exact::exact_sign(alpha) <= 0) return false;
      continue;
    }
    // |β| ∈ [mlo, mhi] (mlo may be ≤ 0 when only the exact sign is known: then only a threshold of
    // the right sign is bounded, which is the case of a far, nearly parallel line).
    const double mhi = std::abs(b.v) + be, mlo = std::abs(b.v) - be;
    if (sb > 0) {  // λ > −α/β: an upper estimate of −α/β
      const double nhi = -a.v + ae;
      if (nhi <= 0) lo = std::max(lo, up(nhi / mhi));
      else if (mlo > 0) lo = std::max(lo, up(nhi / mlo));
      else return false;
    } else {  // λ < α/|β|: a lower estimate
      const double alo = a.v - ae;
      if (alo >= 0) hi = std::min(hi, down(alo / mhi));
      else if (mlo > 0) hi = std::min(hi, down(alo / mlo));
      else return false;
    }
    if (!(lo < hi) || lo >= 1 || hi <= 0) return false;
  }
  return lo < hi && lo < 1 && hi > 0;
}

FreeMinimum FreeSpace::minimum(const FarthestCost& f, double cap) const {
  FreeMinimum out;
  out.lower = cap;
  const std::size_t K = f.z.size();
  if (K == 0 || sums_.empty() || !(cap > 0)) return out;
  // The region where f < cap: within cap + r_k of every z_k.
  Vec2 rlo(-1e308, -1e308), rhi(1e308, 1e308);
  double zs = 0, rmax = 0;
  for (std::size_t k = 0; k < K; ++k) {
    const double w = up(cap + f.r[k]);
    rlo = rlo.cwiseMax(f.z[k] - Vec2::Constant(w)), rhi = rhi.cwiseMin(f.z[k] + Vec2::Constant(w));
    zs = std::max(zs, f.z[k].cwiseAbs().maxCoeff()), rmax = std::max(rmax, f.r[k]);
  }
  if ((rlo.array() > rhi.array()).any()) return out;
  rlo = pad_down(rlo), rhi = pad_up(rhi);
  // ε bounds the error of one evaluation of f at a computed point of an edge (the edge's points
  // rounded, the distances' roundings), with room: every lower bound below subtracts 16ε.
  const double eps = 64 * kU * (4 * scale_ + zs + rmax + (std::isfinite(cap) ? cap : 0.0)) + 1e-300;
  auto cost = [&](const Vec2& x) {
    double v = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < K; ++k) v = std::max(v, (x - f.z[k]).norm() - f.r[k]);
    return v;
  };
  auto quick = [&](const Vec2& a, const Vec2& d) {
    double v = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < K; ++k) v = std::max(v, dist_point_segment(f.z[k], a, d) - f.r[k]);
    return v - 16 * eps;
  };
  auto meets = [](const Vec2& alo, const Vec2& ahi, const Vec2& blo, const Vec2& bhi) {
    return !((ahi.array() < blo.array()).any() || (bhi.array() < alo.array()).any());
  };
  std::vector<std::size_t> near;  // sums meeting the region
  for (std::size_t k = 0; k < sums_.size(); ++k)
    if (meets(sums_[k].lo, sums_[k].hi, rlo, rhi)) near.push_back(k);
  std::vector<std::pair<double, std::size_t>> order;  // (quick bound, edge), edges of nearby sums
  std::vector<std::size_t> owner(segs_.size());
  for (std::size_t k : near)
    for (std::size_t i = sums_[k].first; i < sums_[k].first + sums_[k].count; ++i) {
      owner[i] = k;
      const Seg& s = segs_[i];
      if (!meets(s.lo, s.hi, rlo, rhi)) continue;
      const double q = quick(s.x0 + s.y, s.x1 - s.x0);
      if (q < cap) order.emplace_back(q, i);
    }
  std::sort(order.begin(), order.end());
  double F = cap;
  std::vector<std::pair<double, double>> cov;
  for (const auto& [q, i] : order) {
    if (q >= F) break;
    const Seg& s = segs_[i];
    cov.clear();
    // One open sum holds the whole edge (the usual case deep inside U): the sums whose box holds
    // the edge's are tried first, and the edge is dropped at the first that holds it.
    bool whole = false;
    for (int pass = 0; pass < 2 && !whole; ++pass)
      for (std::size_t k : near) {
        if (k == owner[i] || !meets(s.lo, s.hi, sums_[k].lo, sums_[k].hi)) continue;
        const bool holds_box =
            (sums_[k].lo.array() <= s.lo.array()).all() && (s.hi.array() <= sums_[k].hi.array()).all();
        if (holds_box != (pass == 0)) continue;
        double lo, hi;
        if (!covered(s, sums_[k], lo, hi)) continue;
        if (lo < 0 && hi > 1) {
          whole = true;
          break;
        }
        cov.emplace_back(lo, hi);
      }
    if (whole) continue;
    std::sort(cov.begin(), cov.end());
    const Vec2 a = s.x0 + s.y, d = s.x1 - s.x0;
    const double L = d.norm() * (1 + 8 * kU);  // Lipschitz constant of f(a + λd) in λ
    auto piece = [&](double la, double lb) {
      if (quick(a + la * d, (lb - la) * d) >= F) return;
      // Golden section on the convex f(a + λd); bracket [x, y], interior points p < r.
      constexpr double g = 0.6180339887498949;
      double x = la, y = lb, best = std::min(cost(a + la * d), cost(a + lb * d));
      double bestl = cost(a + la * d) <= cost(a + lb * d) ? la : lb;
      double p = y - g * (y - x), r = x + g * (y - x), fp = cost(a + p * d), fr = cost(a + r * d);
      for (int it = 0; it < 90 && (y - x) * L > 1e-13 * (scale_ + zs); ++it) {
        if (fp <= fr) {
          y = r, r = p, fr = fp, p = y - g * (y - x), fp = cost(a + p * d);
        } else {
          x = p, p = r, fp = fr, r = x + g * (y - x), fr = cost(a + r * d);
        }
      }
      const double interior = std::min(fp, fr);
      const double il = fp <= fr ? p : r;
      if (interior < best) best = interior, bestl = il;
      // min over [la, lb] ≥ (value at a point of the final bracket) − L·width, less the slack of
      // comparisons decided on rounded values (≤ 8ε) and of the evaluation itself.
      const double lb_piece = down(interior - L * (y - x) - 16 * eps);
      if (lb_piece < F) {
        F = lb_piece;
        out.found = true;
        out.argmin = a + bestl * d;
        out.value = best;
        out.outward = Vec2(d.y(), -d.x()) / d.norm();
      }
    };
    double cur = 0;
    for (const auto& [lo, hi] : cov) {
      if (lo >= cur) piece(cur, std::min(lo, 1.0));
      cur = std::max(cur, hi);
      if (cur > 1) break;
    }
    if (cur <= 1) piece(cur, 1.0);
  }
  out.lower = F;
  return out;
}

}  // namespace pendepth::motion
