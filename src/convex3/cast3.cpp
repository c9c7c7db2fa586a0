// Exact shape cast (time of impact) of two posed convex polytopes along d: the smallest s >= 0
// with Q' + s·d̂ touching P, i.e. the entry of the ray {s·d̂ : s >= 0} into M = P ⊕ (−Q').
//
// Fast path (signed_distance3.cpp, shape_cast_certified): a GJK ray cast in doubles (van den
// Bergen 2004) proposes the entry triangle of pairs or a miss; exact certificates accept it (the
// line crosses the triangle, whose plane supports M with n·d < 0, entry at s >= 0; a miss by two
// planes covering the ray or by exact GJK on the projection along d). It answers all 960 of the
// benchmark's queries (tests/convex3/test_cast_fast.cpp: ≥ 98 % of such placements). Otherwise:
// the entry of the line ℓ = {s·d} into M is the exit of the reversed line {s·(−d)}:
// s_in = −T(−d), and the exit along +d is s_out = T(+d), both by the descent of
// Compute-Depth-3D on the inner DK hierarchies (DHS §5.2; directional3.cpp, line_exit_dk),
// which returns the exit facet u of M (a supporting plane, exact support pair) with T =
// h_M(u)/(u·d) and the exact sign of h_M(u) — so every decision below is an exact sign:
//   * ℓ misses int M                         → no hit (+infinity);
//   * h_M(u_in) < 0 (the entry lies ahead)   → hit at s_in = −h_M(u_in)/(u_in·(−d̂)) > 0, the
//     contact on the entry facet u_in (normal = u_in/|u_in|, pointing from P towards Q);
//   * else s_in <= 0: h_M(u_out) < 0 means the whole chord lies behind 0 (no hit); otherwise
//     0 ∈ M: distance 0 (overlapping iff both h > 0, i.e. 0 ∈ int M; touching otherwise, with
//     the facet through 0 as normal and contact).
// Grazes: the descent decides on ℓ perturbed by Simulation of Simplicity. When a perturbed line
// misses int M (in or out), ℓ misses int M too (int M is open: a line crossing it keeps crossing
// it under small perturbations), so the ray misses M or only grazes it (meets ∂M, never int M:
// a face or edge of Q sliding along one of P, a vertex touching); cast_graze (directional3.cpp)
// then decides exactly whether it meets M and where first. When both perturbed lines hit, their
// chords tend to sub-chords of ℓ ∩ M whose ends are either ends of ℓ ∩ M (an exit facet crossed
// transversally) or 0 (a facet parallel to d, crossed at the perturbation's origin, h = 0), so
// the decisions above are those of the closed M. Cost: fast path O(k·c) (GJK iterations ×
// climbs, ≤ 64 iterations); fallback O(log n · log m) per descent, two descents at most; a
// graze adds cast_graze's O(k·c + f·(f + g)) (support faces of f and g vertices).
#include <pendepth/depth3.hpp>

#include "convex3/minimum_expand.hpp"

#include <cmath>
#include <limits>

namespace pendepth {

namespace {
Cast3 cast_exact(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q, const Pose3& pose_q,
                 const Vec3& d) {
  if (!d.allFinite() || d == Vec3::Zero()) throw InvalidInput("direction: zero or non-finite");
  if (!pose_p.translation.allFinite()) throw InvalidInput("pose of P: non-finite translation");
  if (!pose_q.translation.allFinite()) throw InvalidInput("pose of Q: non-finite translation");
  const Eigen::Matrix3d Rp = pose_p.matrix(), Rq = pose_q.matrix();
  convex3::RelativePose rel;
  rel.R = Rp.transpose() * Rq;
  rel.tq = Rp.transpose() * pose_q.translation;
  rel.tp = Rp.transpose() * pose_p.translation;
  const Vec3 dl = Rp.transpose() * d;
  if (dl == Vec3::Zero()) throw InvalidInput("direction: underflows to zero in P's frame");

  if (auto fast = convex3::shape_cast_certified(P, Q, rel, dl, Rp, pose_p.translation)) return *fast;
  Cast3 r;
  r.distance = std::numeric_limits<double>::infinity();
  const convex3::LineExit in = convex3::line_exit_dk(P, Q, rel, -dl);
  auto fill = [&](const convex3::LineExit& e, double s) {
    r.hit = true;
    r.distance = s;
    const Vec3 dir = dl.normalized();
    r.translation = Rp * (s * dir);
    r.normal = Rp * e.unit;
    r.witness_p = r.witness_q = Rp * e.contact + pose_p.translation;
    r.feature_p = e.feature_p;
    r.feature_q = e.feature_q;
  };
  // A perturbed line that misses int M: the line does not meet int M (an open set), so the ray
  // misses M or only grazes it — decided exactly by cast_graze.
  if (!in.hit) return convex3::cast_graze(P, Q, rel, dl, Rp, pose_p.translation);
  if (in.h_sign < 0) {
    fill(in, -in.exit);  // in.exit = h_M(u)·|d|/(u·(−d)) < 0
    return r;
  }
  // The forward descent perturbs the same line as the reversed one (orient −1), so that both
  // exits with h > 0 mean 0 ∈ int M (two differently perturbed lines could lie on either side
  // of a face plane through 0 and report a touching contact as an overlap).
  const convex3::LineExit out = convex3::line_exit_dk(P, Q, rel, dl, -1);
  if (!out.hit) return convex3::cast_graze(P, Q, rel, dl, Rp, pose_p.translation);
  if (out.h_sign < 0) return r;  // the chord lies behind the start
  if (in.h_sign > 0 && out.h_sign > 0) {     // 0 ∈ int M
    r.hit = r.overlapping = true;
    r.distance = 0;
    return r;
  }
  // Touching at s = 0: the facet through 0 (the entry one if 0 lies on it).
  fill(in.h_sign == 0 ? in : out, 0.0);
  return r;
}

}  // namespace

// The exact engine: the bracket is the answer itself (+infinity on a miss).
Cast3 shape_cast(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q, const Pose3& pose_q,
                 const Vec3& d) {
  Cast3 r = cast_exact(P, pose_p, Q, pose_q, d);
  r.lower_bound = r.upper_bound = r.distance;
  return r;
}

}  // namespace pendepth
