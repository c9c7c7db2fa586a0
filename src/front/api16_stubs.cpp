// TEMPORARY (branch api16 only, never merged as is): placeholders so that the 2D and 3D halves of
// issue 16 (signed distance, cast) can be built in parallel. Each helper deletes the stubs it
// implements; this file must not exist on main.
#include <pendepth/pendepth.hpp>

#include <stdexcept>

namespace pendepth {
Distance2 Pair2::signed_distance(const Vec2&) const { throw std::logic_error("Pair2::signed_distance: not yet"); }
Cast2 Pair2::cast(const Vec2&, const Vec2&) const { throw std::logic_error("Pair2::cast: not yet"); }
void Pair2::signed_distance(std::span<const Vec2>, std::span<Distance2>, unsigned) const { throw std::logic_error("not yet"); }
}  // namespace pendepth
