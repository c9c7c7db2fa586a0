// 3D depth queries on two convex polytopes with poses: the public entry points.
//   σ   : minimum_expand.cpp — exact certified expansion on the implicit M = P ⊕ (−Q').
//   σ_d : minimum_expand.cpp's Phase D — the same certified expansion cast along the ray, within
//         a work budget O(log n · log m); beyond it directional3.cpp — Compute-Depth-3D
//         (DHS §5.2) on the inner DK hierarchies, O(log n · log m) constant-size steps. Both exact.
// The O(n·m) enumeration of M's implicit facet normals (minkowski_facets.cpp) is kept here as
// convex3::directional_depth_facets and friends: the exact reference for tests and benchmarks.
#include <pendepth/depth3.hpp>

#include "convex3/minimum_expand.hpp"
#include "convex3/minkowski_facets.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pendepth {

using convex3::FacetCandidate;
using convex3::FacetSource;
using convex3::RelativePose;

namespace {

// No rotation: x = y = z = +0 (as in most poses of a fixed P) and w finite, nonzero. The matrix
// is then I exactly — the general path of Pose3::matrix gives I (w normalises to ±1 exactly,
// every other product is +0) through a square root and four divisions.
[[gnu::always_inline]] inline bool unrotated(const Pose3& pose) {
  const Eigen::Vector4d c = pose.rotation.coeffs();
  auto plus_zero = [](double x) { return x == 0 && !std::signbit(x); };
  return plus_zero(c[0]) && plus_zero(c[1]) && plus_zero(c[2]) && std::isfinite(c[3]) && c[3] != 0;
}

// The rotation of q = (x, y, z, w) (Eigen's coefficient order), |q|² neither over- nor
// underflowing: with s = 2/|q|², R = I + s·[−(y²+z²), xy − wz, xz + wy; xy + wz, −(x²+z²), yz − wx;
// xz − wy, yz + wx, −(x²+y²)] — Eigen's toRotationMatrix of q/|q| with 2/|q|² in place of the
// normalisation, the same terms in the same order (Bullet's setRotation too). 13 products, one
// division, 15 sums.
Eigen::Matrix3d rotation_of_scaled(const Eigen::Vector4d& q) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double s = 2 / ((x * x + y * y) + (z * z + w * w));
  const double xs = x * s, ys = y * s, zs = z * s;
  const double wx = w * xs, wy = w * ys, wz = w * zs;
  const double xx = x * xs, xy = x * ys, xz = x * zs;
  const double yy = y * ys, yz = y * zs, zz = z * zs;
  Eigen::Matrix3d R;
  R << 1 - (yy + zz), xy - wz, xz + wy,  //
      xy + wz, 1 - (xx + zz), yz - wx,   //
      xz - wy, yz + wx, 1 - (xx + yy);
  return R;
}

}  // namespace

// The quaternion is first scaled by a power of two so that its largest |coefficient| lies in
// [1, 2): exact (the same rotation and, when nothing over- or underflows, the same matrix bit
// for bit: every entry below is a product of two coefficients and s = 2/|q|², invariant under
// q ↦ 2^k·q), and its squared norm can then neither overflow nor underflow at any magnitude
// (2^±1000 quaternions are valid rotations).
//
// The matrix of q = (w, x, y, z) is I + (2/|q|²)·[the quadratic terms], computed with one
// division s = 2/|q|² and no square root (as Bullet's btMatrix3x3::setRotation), not by
// normalising q first (a square root and four divisions; ~29 → ~22 ns of a portable 8-point
// signed distance, no measurable change of a query's time: docs/benchmarks.md σ section, Run
// 12). Measured accuracy against the exact rotation of the double quaternion
// (tests/convex3/test_rotation_accuracy.cpp, an oracle in 50-digit arithmetic; 10⁶ random
// quaternions and 10⁶ in each of four adversarial families — magnitudes 2^±1000 and subnormal,
// near-180° turns, one dominant coefficient, mixed magnitudes; ε = 2^−52, one ulp of 1): max
// |entry error| 4.36 ε here against 5.72 ε by normalising first, max |RᵀR − I| 8.72 ε against
// 11.47 ε (a priori ≤ 7.5 ε per entry; docs/benchmarks.md, σ section, Run 12). Inputs whose
// scaled |q|² rounds to a power of four (unit quaternions whose squared norm rounds to 1 among
// them: √ and the divisions exact) give the same bits as the normalisation did.
Eigen::Matrix3d Pose3::matrix() const {
  const Eigen::Vector4d c = rotation.coeffs();
  const double big = c.cwiseAbs().maxCoeff();
  if (!c.allFinite() || big == 0) throw InvalidInput("pose: rotation quaternion is zero or non-finite");
  if (unrotated(*this)) return Eigen::Matrix3d::Identity();
  // ldexp(x, −e) is one correctly rounded product x·2^−e whenever 2^−e is a normal double (the
  // exponent of a normal `big` read from its bits): the same bits without two libm calls per
  // coefficient; ilogb / ldexp for a subnormal `big`.
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(big);
  const int biased = static_cast<int>(bits >> 52 & 0x7ff);
  Eigen::Vector4d q;
  if (biased > 1 && biased < 2046) {  // e = biased − 1023 ∈ [−1021, 1022]: 2^−e normal
    const double s = std::bit_cast<double>(static_cast<std::uint64_t>(2046 - biased) << 52);  // 2^(1023 − biased)
    // One vector product (the same four roundings): coefficientwise stores read back by the
    // loads below stalled store forwarding.
    q = c * s;
  } else {
    const int e = std::ilogb(big);
    for (int k = 0; k < 4; ++k) q[k] = std::ldexp(c[k], -e);
  }
  return rotation_of_scaled(q);
}

namespace convex3 {

namespace {

// Whether every off-diagonal zero of the identity matrix M is +0 (a −0 would make +0·x above
// a −0·x).
bool is_plus_zero_identity(const Eigen::Matrix3d& M) {
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      if (i != k && std::signbit(M(k, i))) return false;
  return true;
}

// Iᵀ·x rounded as the product: x_i if x_i ≠ 0, else −0 iff x_i and both other terms are −0.
// Returned whole and assigned per column on purpose: the readers of r.R load its columns as
// 16 + 8 bytes, so coefficientwise stores into r.R stall their store forwarding (measured:
// docs/benchmarks.md, σ section, Run 10).
Vec3 identity_times(const Vec3& x) {
  Vec3 r;
  for (int i = 0; i < 3; ++i)
    r[i] = x[i] != 0 ? x[i]
                     : std::signbit(x[0]) && std::signbit(x[1]) && std::signbit(x[2]) ? -0.0 : 0.0;
  return r;
}

}  // namespace

RelativePose relative_pose(const Pose3& pp, const Pose3& pq, Eigen::Matrix3d* Rp_out) {
  if (!pp.translation.allFinite()) throw InvalidInput("pose of P: non-finite translation");
  if (!pq.translation.allFinite()) throw InvalidInput("pose of Q: non-finite translation");
  // P unrotated (x = y = z = +0, most poses of a fixed P) is known from the quaternion: its
  // matrix is I with +0 off the diagonal, with neither the conversion nor the comparison below.
  const bool unrot = unrotated(pp);
  const Eigen::Matrix3d Rp = unrot ? Eigen::Matrix3d::Identity() : pp.matrix(), Rq = pq.matrix();
  if (Rp_out) *Rp_out = Rp;
  RelativePose r;
  if (unrot || (Rp == Eigen::Matrix3d::Identity() && is_plus_zero_identity(Rp))) {
    // Rp = I exactly (P unrotated: most poses of a fixed P): each coefficient of Iᵀ·x is the
    // sum of x_i·1 = x_i and two terms +0·x_k = ±0 (the sign of x_k; everything finite), so in
    // any order of summation it is x_i when x_i ≠ 0 and else a zero, −0 only when all three
    // terms are: the products' bits without the 45 products.
    for (int j = 0; j < 3; ++j) r.R.col(j) = identity_times(Rq.col(j));
    r.tq = identity_times(pq.translation);
    r.tp = identity_times(pp.translation);
    return r;
  }
  r.R = Rp.transpose() * Rq;
  r.tq = Rp.transpose() * pq.translation;
  r.tp = Rp.transpose() * pp.translation;
  return r;
}

}  // namespace convex3

namespace {

using convex3::relative_pose;

Feature3 feature_of(FacetSource s, bool of_p, int index) {
  if (s == FacetSource::EdgeEdge) return {FeatureKind3::Edge, index};
  bool face = (s == FacetSource::FaceP) == of_p;
  return {face ? FeatureKind3::Face : FeatureKind3::Vertex, index};
}

// Fills the result for the move v (P's frame) ending on candidate k's facet.
Depth3 finish(const ConvexPolytope& P, const ConvexPolytope& Q, const Pose3& pose_p, const RelativePose& rel,
              const FacetCandidate& k, double depth, const Vec3& dir, DepthKind kind, std::size_t ncand) {
  Depth3 r;
  r.kind = kind;
  r.overlapping = true;
  r.candidates = ncand;
  r.depth = r.lower_bound = r.upper_bound = depth;
  Vec3 v = depth * dir;
  // Contact point (P's frame): on P's feature, touching the moved Q's feature.
  Vec3 w;
  if (k.source == FacetSource::FaceP) {
    w = rel.place(Q[k.q_vertex]) + v;  // Q's vertex lands on P's face plane
  } else if (k.source == FacetSource::FaceQ) {
    w = P[k.p_vertex];
  } else {  // closest point of the two edge lines after the move (they intersect)
    const auto& LP = convex3::data_of(P).levels[0];
    const auto& LQ = convex3::data_of(Q).levels[0];
    Vec3 a = P[LP.origin(k.p_feature)], e = P[LP.target(k.p_feature)] - a;
    Vec3 b = rel.place(Q[LQ.origin(k.q_feature)]) + v, f = rel.R * (Q[LQ.target(k.q_feature)] - Q[LQ.origin(k.q_feature)]);
    Vec3 n = e.cross(f);
    double s = (b - a).cross(f).dot(n) / n.squaredNorm();
    w = a + std::clamp(s, 0.0, 1.0) * e;
  }
  Eigen::Matrix3d Rp = pose_p.matrix();
  r.translation = Rp * v;
  r.normal = Rp * dir;
  r.facet_normal = Rp * k.unit;
  r.witness_p = r.witness_q = Rp * w + pose_p.translation;
  r.feature_p = feature_of(k.source, true, k.p_feature);
  r.feature_q = feature_of(k.source, false, k.q_feature);
  return r;
}

}  // namespace

// σ by certified expansion on the implicit M (minimum_expand.cpp); the O(n·m) enumeration of
// minkowski_facets.cpp stays the reference in tests.
Depth3 minimum_depth(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q, const Pose3& pose_q) {
  Eigen::Matrix3d Rp;
  const RelativePose rel = relative_pose(pose_p, pose_q, &Rp);
  return convex3::minimum_depth_expand(P, Q, rel, Rp, pose_p.translation);
}

namespace convex3 {

// σ warm-started from a seed (minimum_expand.hpp): the same answer as minimum_depth.
Depth3 minimum_depth_seeded(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                            const Pose3& pose_q, ExpandSeed* seed) {
  Eigen::Matrix3d Rp;
  const RelativePose rel = relative_pose(pose_p, pose_q, &Rp);
  return minimum_depth_expand(P, Q, rel, Rp, pose_p.translation, seed);
}

namespace {

// The validated inputs of the expansion: relative pose, P's rotation, d in P's frame.
struct DirectionalInput {
  RelativePose rel;
  Eigen::Matrix3d Rp;
  Vec3 d;
};
DirectionalInput directional_input(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) {
  if (!d.allFinite() || d == Vec3::Zero()) throw InvalidInput("direction: zero or non-finite");
  DirectionalInput in;
  in.rel = relative_pose(pose_p, pose_q, &in.Rp);
  in.d = in.Rp.transpose() * d;
  if (in.d == Vec3::Zero()) throw InvalidInput("direction: underflows to zero in P's frame");
  return in;
}

}  // namespace

// σ_d by the directional phase of the certified expansion (minimum_expand.cpp), no budget.
Depth3 directional_depth_expand(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                                const Pose3& pose_q, const Vec3& d) {
  const DirectionalInput in = directional_input(pose_p, pose_q, d);
  return *directional_depth_expand(P, Q, in.rel, in.d, in.Rp, pose_p.translation);
}

// Reference for tests: the exit facet as the minimum over ALL implicit facet normals of M
// (minkowski_facets.cpp), O(n·m) exact predicates.
Depth3 directional_depth_facets(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                                const Pose3& pose_q, const Vec3& d) {
  if (!d.allFinite() || d == Vec3::Zero()) throw InvalidInput("direction: zero or non-finite");
  Eigen::Matrix3d Rp;
  const RelativePose rel = relative_pose(pose_p, pose_q, &Rp);
  Vec3 dl = Rp.transpose() * d;  // direction in P's frame
  auto cands = convex3::minkowski_facets(P, Q, rel, dl);
  Depth3 none;
  none.kind = DepthKind::Directional;
  none.candidates = cands.size();
  const FacetCandidate* best = nullptr;
  for (const auto& k : cands) {
    if (k.sign <= 0) return none;
    if (k.dir_sign > 0 && (!best || k.exit < best->exit)) best = &k;
  }
  // 0 ∈ int M and M bounded: some facet faces d.
  return finish(P, Q, pose_p, rel, *best, best->exit, dl.normalized(), DepthKind::Directional, cands.size());
}

}  // namespace convex3

Depth3 directional_depth(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q, const Pose3& pose_q,
                         const Vec3& d) {
  // The expansion within its work budget, Compute-Depth-3D beyond it (minimum_expand.hpp).
  const convex3::DirectionalInput in = convex3::directional_input(pose_p, pose_q, d);
  if (auto r = convex3::directional_depth_expand(P, Q, in.rel, in.d, in.Rp, pose_p.translation,
                                                 convex3::directional_work_budget(P.size(), Q.size())))
    return *r;
  return convex3::directional_depth_dk(P, pose_p, Q, pose_q, d);
}

}  // namespace pendepth
