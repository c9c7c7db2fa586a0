// pendepth — Shape3 and Pair3: the front door over the 3D convex engines
// (include/pendepth/pendepth.hpp; DHS §5–§6).
//
// σ is the certified expansion (minimum_depth), σ_d Compute-Depth-3D (directional_depth); both
// need only the per-shape structures Shape3 builds once (hull, DK hierarchy; the adjacency and
// the outer hierarchy are built on first use inside ConvexPolytope, thread-safe), so Prepare
// changes nothing in 3D today.
#include <pendepth/io.hpp>
#include <pendepth/pendepth.hpp>

#include "front/batch.hpp"
#include "front/checks.hpp"

namespace pendepth {

Shape3::Shape3(ConvexPolytope polytope) : p_(std::make_shared<const ConvexPolytope>(std::move(polytope))) {}

Shape3 Shape3::hull(std::span<const Vec3> points, std::string_view name) {
  return Shape3(ConvexPolytope::hull(points, name));
}

Shape3 Shape3::from_file(const std::filesystem::path& path, std::string_view name) {
  return Shape3(io::read_convex_polytope(path, name));
}

const ConvexPolytope& Shape3::polytope() const { return *p_; }
std::size_t Shape3::size() const { return p_->size(); }
const std::string& Shape3::name() const { return p_->name(); }

namespace {

// A pose's translation must be finite and its quaternion non-zero and finite (Pose3::matrix
// checks the quaternion; the engines call it).
void check_pose(const Pose3& pose, const std::string& what) {
  front::check_placement(pose.translation, what + " translation");
  if (!front::finite(pose.rotation.coeffs()))
    throw InvalidInput(what + " rotation " + front::text(pose.rotation.coeffs()) + " is not finite");
  if (pose.rotation.coeffs().isZero(0)) throw InvalidInput(what + " rotation is the zero quaternion");
}

void check_poses(std::span<const Pose3> poses, std::size_t out_size) {
  if (out_size != poses.size())
    throw InvalidInput("batch: " + std::to_string(poses.size()) + " poses but room for " + std::to_string(out_size) +
                       " results");
  for (std::size_t i = 0; i < poses.size(); ++i) check_pose(poses[i], "batch: pose " + std::to_string(i));
}

void check_directions(std::span<const Vec3> ds, std::size_t n) {
  if (ds.size() != 1 && ds.size() != n)
    throw InvalidInput("batch: " + std::to_string(ds.size()) + " directions for " + std::to_string(n) +
                       " poses (give one direction, or one per pose)");
  for (std::size_t i = 0; i < ds.size(); ++i) front::check_direction(ds[i], "batch: direction " + std::to_string(i));
}

}  // namespace

Pair3::Pair3(Shape3 P, Shape3 Q, Prepare) : P_(std::move(P)), Q_(std::move(Q)) {}

bool Pair3::overlapping(const Pose3& pose_p, const Pose3& pose_q) const {
  return minimum(pose_p, pose_q).overlapping;
}

Depth3 Pair3::minimum(const Pose3& pose_p, const Pose3& pose_q) const {
  check_pose(pose_p, "pose of P");
  check_pose(pose_q, "pose of Q");
  return minimum_depth(P_.polytope(), pose_p, Q_.polytope(), pose_q);
}

Depth3 Pair3::along(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const {
  check_pose(pose_p, "pose of P");
  check_pose(pose_q, "pose of Q");
  front::check_direction(d);
  return directional_depth(P_.polytope(), pose_p, Q_.polytope(), pose_q, d);
}

Depth3 Pair3::separation(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const {
  Depth3 r = along(pose_p, pose_q, d);
  r.kind = DepthKind::Separation;
  return r;
}

void Pair3::overlapping(std::span<const Pose3> poses_q, std::span<bool> out, unsigned threads) const {
  check_poses(poses_q, out.size());
  const Pose3 pose_p;
  front::parallel_for(poses_q.size(), threads, [&](std::size_t i) {
    out[i] = minimum_depth(P_.polytope(), pose_p, Q_.polytope(), poses_q[i]).overlapping;
  });
}

void Pair3::minimum(std::span<const Pose3> poses_q, std::span<Depth3> out, unsigned threads) const {
  minimum(Pose3(), poses_q, out, threads);
}

void Pair3::along(std::span<const Pose3> poses_q, std::span<const Vec3> ds, std::span<Depth3> out,
                  unsigned threads) const {
  along(Pose3(), poses_q, ds, out, threads);
}

void Pair3::minimum(const Pose3& pose_p, std::span<const Pose3> poses_q, std::span<Depth3> out,
                    unsigned threads) const {
  check_pose(pose_p, "pose of P");
  check_poses(poses_q, out.size());
  front::parallel_for(poses_q.size(), threads, [&](std::size_t i) {
    out[i] = minimum_depth(P_.polytope(), pose_p, Q_.polytope(), poses_q[i]);
  });
}

void Pair3::along(const Pose3& pose_p, std::span<const Pose3> poses_q, std::span<const Vec3> ds,
                  std::span<Depth3> out, unsigned threads) const {
  check_pose(pose_p, "pose of P");
  check_poses(poses_q, out.size());
  if (poses_q.empty()) return;
  check_directions(ds, poses_q.size());
  const bool one = ds.size() == 1;
  front::parallel_for(poses_q.size(), threads, [&](std::size_t i) {
    out[i] = directional_depth(P_.polytope(), pose_p, Q_.polytope(), poses_q[i], ds[one ? 0 : i]);
  });
}

}  // namespace pendepth
