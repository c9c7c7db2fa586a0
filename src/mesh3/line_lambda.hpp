// Private: the interval of a line's parameter λ in a convex set given by its constraints, the
// core of the exact mesh σ's line_interval (mesh_sigma_exact.cpp; issue 17 item 4), kept apart
// from the planes' geometry so that tests/mesh3/test_line_lambda.cpp can drive its filter with
// constructed constraints (exact and near ties, a = 0, a of uncertain sign) against GMP rationals.
#pragma once

#include "mesh3/plane_number.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace pendepth::mesh3::detail {

struct PlaneLambda {
  std::size_t p;
  CGAL::Interval_nt<true> l;
};

// The set {λ : a_p·λ <= b_p for every p} (strict = false) or {λ : a_p·λ < b_p} (strict = true),
// p in [first, first + count): lo = max b/a over a < 0, hi = min b/a over a > 0 (nullopt: that
// side unbounded). False when the set is empty (an a = 0 constraint with b < 0, resp. b <= 0;
// lo > hi, resp. lo >= hi); lo and hi are then unspecified.
// Cs gives for each p: on_line(p) (the constraint's plane holds the line, a = b = 0 exactly by
// construction: no constraint when closed, the empty set when open); a_i(p), b_i(p): intervals
// holding a and b exactly (a proven forward error bound); a_e(p), b_e(p): the exact values;
// optionally lambda_e(p): the exact b_e(p) / a_e(p) for a_e(p) != 0 (a cache may answer it).
// filtered = false: every constraint evaluated exactly (the reference tier). filtered = true: λ
// enclosed as b_i / a_i when a_i certainly excludes 0, else exactly (a's sign, and λ when a != 0);
// then only the constraints whose enclosure meets the certain bound of the extremum (lo_bound =
// max of the lower ends <= max λ⁻, hi_bound = min of the upper ends >= min λ⁺) are evaluated
// exactly — an enclosure touching the bound included (`>=`, `<=`: a tie may be the extremum) —
// the same ends and the same emptiness as the reference. O(count) interval operations; usually
// 1–3 exact λ (near ties and exact ties more).
template <class Cs>
bool lambda_interval(const Cs& cs, std::size_t first, std::size_t count, bool strict, bool filtered,
                     std::optional<PlaneNumber>& lo, std::optional<PlaneNumber>& hi) {
  using I = CGAL::Interval_nt<true>;
  lo.reset(), hi.reset();
  auto lambda_of = [&](std::size_t p) {  // λ = b/a, a != 0
    if constexpr (requires { cs.lambda_e(p); }) return cs.lambda_e(p);
    else return PlaneNumber(cs.b_e(p) / cs.a_e(p));
  };
  auto exact_lambda = [&](std::size_t p, PlaneNumber& l) {  // sign(a); λ = b/a when a != 0
    const PlaneNumber a = cs.a_e(p);
    const CGAL::Sign sa = sign(a);
    if (sa != CGAL::ZERO) l = filtered ? lambda_of(p) : PlaneNumber(cs.b_e(p) / a);  // the reference as before
    return sa;
  };
  // Constraint p decided exactly: `lambda` (sa, l set), `skip` (a = 0, the whole line on the
  // right side of p) or `empty` (a = 0, the whole line on the wrong side: the set is empty).
  enum class Exact { lambda, skip, empty };
  auto exact_constraint = [&](std::size_t p, CGAL::Sign& sa, PlaneNumber& l) {
    sa = exact_lambda(p, l);
    if (sa != CGAL::ZERO) return Exact::lambda;
    const PlaneNumber b = cs.b_e(p);
    return (strict ? !is_positive(b) : is_negative(b)) ? Exact::empty : Exact::skip;
  };
  auto take = [&](CGAL::Sign sa, const PlaneNumber& l) {
    if (sa == CGAL::POSITIVE) {
      if (!hi || l < *hi) hi = l;
    } else {
      if (!lo || l > *lo) lo = l;
    }
  };
  auto empty = [&] { return lo && hi && (strict ? !(*lo < *hi) : *lo > *hi); };
  if (!filtered) {
    for (std::size_t p = first; p < first + count; ++p) {
      if (cs.on_line(p)) {
        if (strict) return false;
        continue;
      }
      PlaneNumber l;
      CGAL::Sign sa;
      const Exact e = exact_constraint(p, sa, l);
      if (e != Exact::lambda) {
        if (e == Exact::empty) return false;
        continue;
      }
      take(sa, l);
      if (empty()) return false;
    }
    return true;
  }
  // Enclosures of λ for the constraints of certain sign of a; exact at once for the others.
  static thread_local std::vector<PlaneLambda> neg, pos;
  neg.clear(), pos.clear();
  double lo_bound = -INFINITY, hi_bound = INFINITY;  // certain: max λ⁻ >= lo_bound, min λ⁺ <= hi_bound
  for (std::size_t p = first; p < first + count; ++p) {
    if (cs.on_line(p)) {
      if (strict) return false;
      continue;
    }
    const I a = cs.a_i(p);
    if (a.inf() > 0 || a.sup() < 0) {
      const I l = cs.b_i(p) / a;
      if (a.inf() > 0) pos.push_back({p, l}), hi_bound = std::min(hi_bound, l.sup());
      else neg.push_back({p, l}), lo_bound = std::max(lo_bound, l.inf());
      continue;
    }
    PlaneNumber l;
    CGAL::Sign sa;
    if (const Exact e = exact_constraint(p, sa, l); e != Exact::lambda) {
      if (e == Exact::empty) return false;
      continue;
    }
    const auto [li, ls] = to_interval(l);
    if (sa == CGAL::POSITIVE) pos.push_back({p, I(li, ls)}), hi_bound = std::min(hi_bound, ls);
    else neg.push_back({p, I(li, ls)}), lo_bound = std::max(lo_bound, li);
  }
  // The exact extremum over the constraints that may attain it (a's sign is known: certain in
  // intervals, or exact above).
  for (const PlaneLambda& q : neg)
    if (q.l.sup() >= lo_bound) take(CGAL::NEGATIVE, lambda_of(q.p));
  for (const PlaneLambda& q : pos)
    if (q.l.inf() <= hi_bound) take(CGAL::POSITIVE, lambda_of(q.p));
  return !empty();
}

}  // namespace pendepth::mesh3::detail
