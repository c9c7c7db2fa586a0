// 3D quickstart: two convex polytopes given as point sets (hulled exactly once), Q posed with a
// rotation and a translation; the minimum depth σ with its certified bounds, and σ_d.
#include <pendepth/depth3.hpp>

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

  const auto P = pendepth::ConvexPolytope::hull(cube);        // fixed
  const auto Q = pendepth::ConvexPolytope::hull(octahedron);  // moving
  const pendepth::Pose3 pose_p;                                 // identity
  const pendepth::Pose3 pose_q(Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3::UnitZ())), Vec3(1.5, 0.2, 0));

  const pendepth::Depth3 s = pendepth::minimum_depth(P, pose_p, Q, pose_q);
  std::printf("sigma   = %.17g in [%.17g, %.17g], move Q by (%.6g, %.6g, %.6g)\n", s.depth, s.lower_bound,
              s.upper_bound, s.translation.x(), s.translation.y(), s.translation.z());
  const pendepth::Depth3 a = pendepth::directional_depth(P, pose_p, Q, pose_q, Vec3(0, 0, 1));
  std::printf("sigma_d = %.17g along +z\n", a.depth);
  return (s.overlapping && s.lower_bound == s.upper_bound && a.depth >= s.depth) ? 0 : 1;
}
