// TEMPORARY (branch api16 only, never merged as is): placeholders so that the 2D and 3D halves of
// issue 16 (signed distance, cast) can be built in parallel. Each helper deletes the stubs it
// implements; this file must not exist on main.
#include <pendepth/pendepth.hpp>

#include <stdexcept>

namespace pendepth {
Distance3 Pair3::signed_distance(const Pose3&, const Pose3&) const { throw std::logic_error("Pair3::signed_distance: not yet"); }
Cast3 Pair3::cast(const Pose3&, const Pose3&, const Vec3&) const { throw std::logic_error("Pair3::cast: not yet"); }
void Pair3::signed_distance(std::span<const Pose3>, std::span<Distance3>, unsigned) const { throw std::logic_error("not yet"); }
void Pair3::signed_distance(const Pose3&, std::span<const Pose3>, std::span<Distance3>, unsigned) const { throw std::logic_error("not yet"); }
}  // namespace pendepth
