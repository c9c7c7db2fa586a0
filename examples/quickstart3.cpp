// 3D quickstart: two convex polytopes given as point sets (hulled exactly once), Q posed with a
// rotation and a translation; the minimum depth σ with its certified bounds, σ_d, and a batch.
#include <pendepth/pendepth.hpp>

#include <cstdio>
#include <vector>

int main() {
  using pendepth::Vec3;
  std::vector<Vec3> cube, octahedron;
  for (int i = 0; i < 8; ++i) cube.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      Vec3 v = Vec3::Zero();
      v[a] = s;
      octahedron.push_back(v);
    }
  octahedron.push_back(Vec3(0.1, 0.2, 0.3));  // interior points are dropped by the hull

  const pendepth::Pair3 pair(pendepth::Shape3::hull(cube, "cube"),              // fixed
                             pendepth::Shape3::hull(octahedron, "octahedron"));   // moving
  const pendepth::Pose3 pose_p;                                                   // identity
  const pendepth::Pose3 pose_q(Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3::UnitZ())), Vec3(1.5, 0.2, 0));

  const pendepth::Depth3 s = pair.minimum(pose_p, pose_q);
  std::printf("sigma   = %.17g in [%.17g, %.17g], move Q by (%.6g, %.6g, %.6g)\n", s.depth, s.lower_bound,
              s.upper_bound, s.translation.x(), s.translation.y(), s.translation.z());
  const pendepth::Depth3 a = pair.along(pose_p, pose_q, Vec3(0, 0, 1));
  std::printf("sigma_d = %.17g along +z\n", a.depth);

  // A batch of poses of Q (P at identity), on every core; the same bits as single calls.
  std::vector<pendepth::Pose3> poses;
  for (int k = 0; k < 200; ++k) poses.emplace_back(pose_q.rotation, Vec3(-2 + 0.02 * k, 0.2, 0));
  std::vector<pendepth::Depth3> out(poses.size());
  pair.minimum(poses, out);
  std::printf("batch   : depth %.6g at x = %.2f\n", out[100].depth, poses[100].translation.x());
  return (s.overlapping && s.lower_bound == s.upper_bound && a.depth >= s.depth &&
          out[175].depth == pair.minimum(pendepth::Pose3(), poses[175]).depth)
             ? 0
             : 1;
}
