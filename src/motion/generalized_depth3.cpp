// Generalized penetration depth PD_g in 3D (survey §4; include/pendepth/motion.hpp).
//
// Contract: P at pose_p, Q at pose_q; a motion rotates Q by R_w (world frame) about its placed
// reference point and translates it by v; its cost is DISP = max_{q ∈ Q} |x'(q) − x(q)|, x and x'
// Q's points before and after, attained at a vertex of Q's hull (a convex function of q).
//
// Convex pairs: PD_g = σ (theorem, motion.hpp): identity rotation, σ's translation and certified
//   bounds. Cost: one σ query (Pair3).
// Mesh pairs (either shape non-convex; Pair3 answers on convex pieces, src/mesh3/mesh_pair.cpp):
//   Lower bound: the mesh σ lower bound, max σ(P_i, Q_j) over overlapping piece pairs. A motion
//     separating P and Q separates P_i from the moved Q_j; the displacement of Q's points bounds
//     that of Q_j's, which is ≥ σ(P_i, Q_j) by the theorem for convex pairs.
//   Upper bound: local optimisation from the translational answer. Start: identity rotation,
//     the mesh σ upper bound's translation (DISP = its length). Then a pattern search over the
//     rotation vector ω (world axes x, y, z, ± step; a success keeps the step, a round without
//     one halves it), starting at the angle that turns Q's farthest hull vertex by the current
//     best cost. A probe at ω: Q's pose rotated by R_w = exp(ω) about its reference point and
//     about its hull box centre c (shift R_q c − R_w R_q c of the reference point). Candidates:
//     the turn alone (when it separates), the turn plus the best motion's translation so far, and
//     (about the reference point) the exact σ_d of the turned pose along that translation's
//     direction (the start's σ direction turned with Q at first). Not the full mesh σ upper bound
//     per probe: on polycubes it costs ~80 ms (the exact σ of every overlapping piece pair plus up
//     to 10 σ_d) against ~15 ms for one σ_d and 0.08 ms for an overlap test (measured,
//     docs/benchmarks.md). Each candidate is placed at T = pose_q.translation + v (nudged
//     outwards along its σ part by a few ulps while rounding leaves it inside), verified by the
//     exact overlap test at that pose, and costed by disp_upper (the pose matrices as the engines
//     use them, rounded up past every rounding). Rotations that cannot beat the best are skipped
//     without a query: for any v, two hull vertices x_k, x_0 (placed, about the reference point)
//     part by |(R_w − I)(x_k − x_0)| ≤ 2·DISP.
//   The bounds generally do not meet (converged: upper − lower ≤ tolerance·upper): σ is not
//   continuous in the rotation for non-convex pairs (a peg turned in its slot), so no Lipschitz
//   argument bounds PD_g below between probes; the piece bound is what is proven
//   (docs/algorithms.md).
// Cost: k probes × (one σ_d + up to 6 overlap tests) after the start's mesh σ;
//   capped by options.max_probes (64).
// Numeric domain: every query goes through Pair3 (its power-of-two scaling, src/front/scale.hpp);
//   DISP is evaluated on operands scaled by a power of two (exact) so that it neither overflows
//   nor underflows.
#include "mesh3/mesh_pair.hpp"

#include <pendepth/motion.hpp>
#include <pendepth/pendepth.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace pendepth {

namespace {

constexpr double kU = 0x1p-53;  // unit roundoff
constexpr double kInf = std::numeric_limits<double>::infinity();

// A quaternion scaled by a power of two (exact) then normalised: finite for any magnitude.
Eigen::Quaterniond unit(const Eigen::Quaterniond& q) {
  const int e = std::ilogb(q.coeffs().cwiseAbs().maxCoeff());
  Eigen::Quaterniond s;
  for (int k = 0; k < 4; ++k) s.coeffs()[k] = std::ldexp(q.coeffs()[k], -e);
  return s.normalized();
}

// Certified upper bound of max_k |A q_k + T − (B q_k + t)| (the displacement of Q's hull vertices
// q_k from the pose (B, t) to (A, T)). Operands scaled by 2^-s (exact) so that the largest is
// about 1; per coordinate the computed c = ((A q)_i − (B q)_i) + (T_i − t_i), a sum of 8 rounded
// terms, errs by at most 9u·M (M the sum of the terms' magnitudes) plus 2^-1060 for underflowed
// products; the norm of the widened coordinates by at most 4u relative; raised by 8u, scaled back.
double disp_upper(const std::vector<Vec3>& q, const Eigen::Matrix3d& A, const Vec3& T, const Eigen::Matrix3d& B,
                  const Vec3& t) {
  double big = std::max(T.cwiseAbs().maxCoeff(), t.cwiseAbs().maxCoeff());
  for (const Vec3& x : q) big = std::max(big, x.cwiseAbs().maxCoeff());
  if (big == 0) return 0;
  const int s = std::ilogb(big) + 1;
  const Vec3 Ts(std::ldexp(T.x(), -s), std::ldexp(T.y(), -s), std::ldexp(T.z(), -s));
  const Vec3 ts(std::ldexp(t.x(), -s), std::ldexp(t.y(), -s), std::ldexp(t.z(), -s));
  const Vec3 dt = Ts - ts, mt = Ts.cwiseAbs() + ts.cwiseAbs();
  const Eigen::Matrix3d Aa = A.cwiseAbs(), Ba = B.cwiseAbs();
  double worst = 0;
  for (const Vec3& x : q) {
    const Vec3 xs(std::ldexp(x.x(), -s), std::ldexp(x.y(), -s), std::ldexp(x.z(), -s));
    const Vec3 c = (A * xs - B * xs) + dt;
    const Vec3 m = Aa * xs.cwiseAbs() + Ba * xs.cwiseAbs() + mt;
    const Vec3 w = c.cwiseAbs() + 9 * kU * m + Vec3::Constant(0x1p-1060);
    worst = std::max(worst, w.norm() * (1 + 8 * kU));
  }
  return std::ldexp(worst, s);
}

struct Search {
  const Pair3& pair;
  Pose3 pose_p, pose_q;
  Eigen::Quaterniond q0;          // pose_q's rotation, normalised
  Eigen::Matrix3d B;              // pose_q.matrix()
  std::vector<Vec3> hull;         // Q's hull vertices, own frame
  std::vector<Vec3> placed;       // B·hull (about the reference point)
  std::vector<Vec3> centres;      // own-frame rotation centres: the reference point, the hull box centre
  GeneralizedDepth3 r;
  double best = kInf;
  Vec3 best_u{0, 0, 0};           // the best motion's translation after its rotation about its centre
  Vec3 start_dir{0, 0, 0};        // the start's σ translation

  // The motion (rotation w, translation v) if it separates (exact test at the pose the caller
  // gets): its certified cost, kept when it beats the best; else infinity.
  double accept(const Eigen::Quaterniond& w, bool identity, const Vec3& shift, const Vec3& u) {
    const Eigen::Quaterniond qf = identity ? pose_q.rotation : Eigen::Quaterniond(w * q0);
    for (double eps : {0.0, 0x1p-50, 0x1p-44, 0x1p-36, 0x1p-26}) {
      const Vec3 v = shift + u * (1 + eps);
      const Pose3 moved(qf, pose_q.translation + v);
      try {
        if (pair.overlapping(pose_p, moved)) {
          if (u == Vec3::Zero()) return kInf;  // nothing to nudge
          continue;
        }
      } catch (const InvalidInput&) {  // a pose outside the pair's numeric domain: no motion here
        return kInf;
      }
      const double cost = disp_upper(hull, moved.matrix(), moved.translation, B, pose_q.translation);
      if (cost < best) {
        best = cost;
        r.rotation = identity ? Eigen::Quaterniond::Identity() : w;
        r.translation = v;
        r.pose = moved;
        best_u = u;
      }
      return cost;
    }
    return kInf;
  }

  // A probe at rotation vector ω (world frame): every centre's candidates.
  double probe(const Vec3& omega) {
    ++r.probes;
    const double angle = omega.norm();
    const Eigen::Quaterniond w = angle == 0 ? Eigen::Quaterniond::Identity()
                                            : Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle));
    const Eigen::Quaterniond qf(w * q0);
    const Eigen::Matrix3d Rw = w.toRotationMatrix();
    double here = kInf;
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const Vec3 bc = B * centres[k];
      const Vec3 shift = bc - Rw * bc;  // keeps the centre in place
      const Pose3 turned(qf, pose_q.translation + shift);
      try {
        if (!pair.overlapping(pose_p, turned)) {  // the turn alone separates
          here = std::min(here, accept(w, false, shift, Vec3::Zero()));
          continue;
        }
        if (best_u != Vec3::Zero()) here = std::min(here, accept(w, false, shift, best_u));
        if (k == 0) {  // σ_d along the best direction so far (or the start's, turned with Q)
          const Vec3 d = best_u != Vec3::Zero() ? best_u : Rw * start_dir;
          if (d != Vec3::Zero()) here = std::min(here, accept(w, false, shift, pair.along(pose_p, turned, d).translation));
        }
      } catch (const InvalidInput&) {  // a pose outside the pair's numeric domain
        continue;
      }
    }
    return here;
  }

  // Whether a rotation can beat the best: max_k |(R_w − I)(x_k − x_0)| / 2 ≤ DISP for every v
  // (a heuristic filter with a margin of a millionth; not used for any bound).
  bool useful(const Vec3& omega) const {
    const double angle = omega.norm();
    if (angle == 0) return false;
    const Eigen::Matrix3d M = Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix() - Eigen::Matrix3d::Identity();
    double spread = 0;
    for (const Vec3& x : placed) spread = std::max(spread, (M * (x - placed[0])).norm());
    return spread / 2 * (1 - 1e-6) < best;
  }
};

}  // namespace

GeneralizedDepth3 generalized_depth(const Shape3& P, const Pose3& pose_p, const Shape3& Q, const Pose3& pose_q,
                                    const GeneralizedOptions3& o) {
  const Pair3 pair(P, Q);
  // Meshes: PD_g's lower bound is the pairs' max σ_ij (σ's bounds' lower end: a rotation can beat
  // σ), not the exact σ that minimum() may return (mesh_sigma_exact.cpp): both from one query.
  mesh3::SigmaKeepBounds keep;
  const Depth3 s = pair.minimum(pose_p, pose_q);  // checks the poses, scales the pair
  const double pair_lower = keep.bounds ? keep.bounds->lower_bound : s.lower_bound;
  GeneralizedDepth3 r;
  r.overlapping = s.overlapping;
  r.depth = r.sigma = s.depth;
  r.pose = pose_q;
  if (!(o.tolerance >= 0)) throw InvalidInput("generalized depth: the tolerance must be >= 0");
  if (!s.overlapping) return r;
  if (P.is_convex() && Q.is_convex() && o.convex_theorem) {
    r.lower_bound = s.lower_bound;
    r.upper_bound = s.upper_bound;
    r.translation = s.translation;
    r.pose.translation = pose_q.translation + s.translation;
    r.converged = r.lower_bound == r.upper_bound;
    return r;
  }

  Search S{pair, pose_p, pose_q, unit(pose_q.rotation), pose_q.matrix(), {}, {}, {}, r};
  const auto hv = Q.polytope().vertices();
  S.hull.assign(hv.begin(), hv.end());
  Vec3 lo = S.hull[0], hi = S.hull[0];
  for (const Vec3& x : S.hull) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x), S.placed.push_back(S.B * x);
  S.centres.push_back(Vec3::Zero());
  const Vec3 mid = 0.5 * lo + 0.5 * hi;
  if (mid != Vec3::Zero()) S.centres.push_back(mid);

  S.start_dir = s.translation;
  // The translational answer: its motion verified (nudged out if rounding left it inside).
  S.accept(Eigen::Quaterniond::Identity(), true, Vec3::Zero(), s.translation);
  if (S.best == kInf) {  // not verified even nudged by 2^-26 (never seen): the σ_d answers on the axes
    for (int a = 0; a < 3 && S.best == kInf; ++a)
      for (double sg : {1.0, -1.0})
        S.accept(Eigen::Quaterniond::Identity(), true, Vec3::Zero(), pair.along(pose_p, pose_q, sg * Vec3::Unit(a)).translation);
  }

  // The search stops when the gap is within the tolerance (the bounds stay as they are).
  auto closed = [&](double upper) { return upper - pair_lower <= o.tolerance * upper; };

  // Pattern search on the rotation vector.
  double rmax = 0;
  for (const Vec3& x : S.placed) rmax = std::max(rmax, x.norm());
  if (rmax > 0 && std::isfinite(S.best) && o.max_probes > 0) {
    double step = S.best >= 2 * rmax ? std::numbers::pi / 2 : 2 * std::asin(S.best / (2 * rmax));
    Vec3 omega = Vec3::Zero();
    const double min_step = 1e-9;
    while (S.r.probes < o.max_probes && step > min_step && !closed(S.best)) {
      bool improved = false;
      for (int a = 0; a < 3 && S.r.probes < o.max_probes; ++a)
        for (double sg : {1.0, -1.0}) {
          if (S.r.probes >= o.max_probes) break;
          const Vec3 cand = omega + sg * step * Vec3::Unit(a);
          if (!S.useful(cand)) continue;
          const double before = S.best;
          S.probe(cand);
          if (S.best < before) omega = cand, improved = true;
        }
      if (!improved) step /= 2;
    }
  }

  r = S.r;
  if (!std::isfinite(S.best)) {  // no motion verified (never seen): σ's, an upper bound in exact arithmetic
    S.best = s.upper_bound;
    r.rotation = Eigen::Quaterniond::Identity();
    r.translation = s.translation;
    r.pose = Pose3(pose_q.rotation, pose_q.translation + s.translation);
  }
  r.overlapping = true;
  r.sigma = s.depth;
  r.depth = r.upper_bound = S.best;
  r.converged = closed(S.best);
  r.lower_bound = std::min(pair_lower, S.best);
  return r;
}

}  // namespace pendepth
