// pendepth — rounded shapes in 3D: spheres, capsules and any convex core ⊕ a ball (issue 16 item
// 5; docs/design.md "Primitives"; survey §3 on rounded shapes: GJK engines treat the margin of
// a sphere-swept core exactly this way).
//
// Contract (rounded3.hpp): P = C_P ⊕ B(r_P), Q = C_Q ⊕ B(r_Q), r = r_P + r_Q > 0. Then
// M = P ⊕ (−Q) = M_C ⊕ B(r) with M_C = C_P ⊕ (−C_Q), and the signed distance function of M is
// that of M_C minus r (for a convex set the offset by r moves every boundary point along its
// normal by r, inside and out):
//   sd = sd_C − r,  overlap ⇔ sd < 0,  σ = max(0, −sd),  normal and features those of the cores,
//   witness_p = w_P + r_P·n (P's surface point), witness_q = witness_p + sd·n.
// sd_C is exact to a few ulps (the core engines), so sd is one rounding further: |error| <=
// few ulps of sd_C + half an ulp of sd, and the overlap decision is exact up to that rounding
// (a pair within a few ulps of contact may be called touching or overlapping either way).
// σ_d and the cast need the ray's exit from / entry into M_C ⊕ B(r): the roots of the convex
// function φ(s) = sd_C(s·d̂) − r, whose derivative is n(s)·d̂ (n the core answer's normal, the
// gradient of the signed distance). Newton's method from the right of the exit root (from the left
// of the entry root) converges monotonically on a convex function: every step ends on the root's
// far side or on it, in one step where the active feature of M_C is a facet (a flat piece of the
// offset), quadratically where it is an edge or a vertex (a cylinder or a sphere piece of the
// offset). It stops when φ <= 0 is reached or a step makes no progress in floating point; the
// answer is then within a few ulps of the root when the ray crosses ∂M transversally (a ray that
// only grazes M converges linearly; the iteration is capped at 200 steps and the graze decided
// by φ at the last iterate, to within rounding). Cost: one core distance per Newton step (1–6).
#include "primitives/rounded3.hpp"

#include <cmath>
#include <limits>

namespace pendepth::primitives {

namespace {
constexpr int kMaxNewton = 200;
}

Distance3 rounded_distance(const CoreDistance& core, double rp, double rq) {
  Vec3 touch = Vec3::Zero();
  const Distance3 c = core(Vec3::Zero(), &touch);
  const double r = rp + rq;
  // (+ 0: a −0 component, from rotating an axis vector, prints as 0)
  const Vec3 n = ((c.distance == 0 && !c.overlapping) ? touch : c.normal) + Vec3::Zero();
  Distance3 out;
  out.distance = out.lower_bound = out.upper_bound = c.distance - r;
  out.overlapping = out.distance < 0;
  out.feature_p = c.feature_p, out.feature_q = c.feature_q;
  out.witness_p = c.witness_p + rp * n;
  if (out.distance == 0) {  // touching: the contact point; normal and translation 0 by convention
    out.witness_q = out.witness_p;
    return out;
  }
  out.normal = n;
  out.translation = -out.distance * n + Vec3::Zero();
  out.witness_q = out.witness_p + out.distance * n;
  return out;
}

Depth3 rounded_minimum(const CoreDistance& core, double rp, double rq) {
  const Distance3 s = rounded_distance(core, rp, rq);
  Depth3 r;
  r.kind = DepthKind::Minimum;
  if (!s.overlapping) return r;
  r.overlapping = true;
  r.depth = r.lower_bound = r.upper_bound = -s.distance;
  r.translation = s.translation;
  r.normal = r.facet_normal = s.normal;
  r.witness_p = r.witness_q = s.witness_p;
  r.feature_p = s.feature_p, r.feature_q = s.feature_q;
  return r;
}

Depth3 rounded_along(const CoreDistance& core, double rp, double rq, const Vec3& d) {
  const double r = rp + rq;
  Depth3 out;
  out.kind = DepthKind::Directional;
  if (!(core(Vec3::Zero(), nullptr).distance < r)) return out;
  const Vec3 dh = d.normalized();
  // A point beyond the exit: φ(s) > 0 (doubling from r; φ(s) >= s − |M_C's farthest point| − r).
  double s = r;
  Distance3 c = core(s * dh, nullptr);
  for (int k = 0; k < 2100 && !(c.distance > r); ++k) s *= 2, c = core(s * dh, nullptr);
  for (int k = 0; k < kMaxNewton; ++k) {
    const double slope = c.normal.dot(dh);
    if (!(slope > 0)) break;  // convex φ, root on the left: the slope is positive (guard only)
    const double next = s - (c.distance - r) / slope;
    if (!(next < s)) break;
    const Distance3 cn = core(next * dh, nullptr);
    s = next, c = cn;
    if (!(c.distance > r)) break;
  }
  out.overlapping = true;
  out.depth = out.lower_bound = out.upper_bound = s;
  out.normal = dh;
  out.translation = s * dh + Vec3::Zero();
  out.facet_normal = c.normal;
  // The contact after the move: P's surface point over the core witness.
  out.witness_p = out.witness_q = c.witness_p + rp * c.normal;
  out.feature_p = c.feature_p, out.feature_q = c.feature_q;
  out.candidates = 0;
  return out;
}

Cast3 rounded_cast(const CoreDistance& core, double rp, double rq, const Vec3& d) {
  const double r = rp + rq;
  Cast3 out;
  Vec3 touch = Vec3::Zero();
  Distance3 c = core(Vec3::Zero(), &touch);
  if (!(c.distance > r)) {  // overlapping or touching at s = 0
    out.hit = true;
    out.overlapping = c.distance < r;
    if (!out.overlapping) {
      const Vec3 n = (c.distance == 0 && !c.overlapping) ? touch : c.normal;
      out.normal = n;
      out.witness_p = out.witness_q = c.witness_p + rp * n;
      out.feature_p = c.feature_p, out.feature_q = c.feature_q;
    }
    return out;
  }
  const Vec3 dh = d.normalized();
  double s = 0;
  for (int k = 0; k < kMaxNewton; ++k) {
    const double slope = c.normal.dot(dh);
    if (!(slope < 0)) break;  // φ > 0 and not decreasing: never reached (convex φ)
    const double next = s - (c.distance - r) / slope;
    if (!(next > s)) break;
    const Distance3 cn = core(next * dh, nullptr);
    s = next, c = cn;
    if (!(c.distance > r)) break;
  }
  // Reached (φ <= 0, or within rounding of the root: no progress and φ a few ulps above 0).
  const double slack = 8 * std::numeric_limits<double>::epsilon() * (r + std::abs(c.distance) + s);
  if (!(c.distance - r <= slack)) {
    out.distance = std::numeric_limits<double>::infinity();
    return out;
  }
  out.hit = true;
  out.distance = s;
  out.translation = s * dh + Vec3::Zero();
  out.normal = c.normal;
  out.witness_p = out.witness_q = c.witness_p + rp * c.normal;
  out.feature_p = c.feature_p, out.feature_q = c.feature_q;
  return out;
}

}  // namespace pendepth::primitives
