// Generalized penetration depth PD_g in 3D for convex polytopes (survey §4; motion.hpp).
//
// Contract: PD_g under DISP (the largest displacement of Q's points) equals the translational σ
// for two convex shapes (Zhang et al.; proof in include/pendepth/motion.hpp): a separating end
// pose leaves a plane between the shapes, and the point of Q deepest against its normal travels
// at least the support overlap along that normal, which is ≥ σ. So the answer is σ's motion —
// identity rotation, σ's translation — with σ's certified bounds. Cost: one σ query (Pair3).
// Meshes (non-convex 3D shapes) do not exist in pendepth yet: no upper bounds for them here.
#include <pendepth/motion.hpp>
#include <pendepth/pendepth.hpp>

namespace pendepth {

GeneralizedDepth3 generalized_depth(const Shape3& P, const Pose3& pose_p, const Shape3& Q,
                                    const Pose3& pose_q) {
  const Depth3 s = Pair3(P, Q).minimum(pose_p, pose_q);  // checks the poses, scales the pair
  GeneralizedDepth3 r;
  r.overlapping = s.overlapping;
  r.depth = r.sigma = s.depth;
  r.lower_bound = s.overlapping ? s.lower_bound : 0;
  r.upper_bound = s.overlapping ? s.upper_bound : 0;
  r.translation = s.translation;
  return r;
}

}  // namespace pendepth
