// pendepth — σ along a 2D trajectory (include/pendepth/pendepth.hpp `trajectory`; issue 18 item 3).
//
// Placement k: Q rotated by degrees_k about its origin (Shape2::rotated: exact at quarter turns,
// one rounding per coordinate otherwise), then moved by t_k. The per-pair work (Pair2: convex
// normal forms, triangulations, no-fit polygon) depends on the angle only, so one Pair2 serves
// every run of placements with the same angle (bitwise): nesting trajectories try few angles
// (a piece's allowed orientations). A Pair2's answer never depends on the calls before it, so
// the reused pair answers exactly as a new one would (the `warm` = false path builds a pair per
// placement, for comparison). Cost: one Pair2 per change of angle + one σ per placement.
#include <pendepth/pendepth.hpp>

#include <cmath>
#include <cstring>
#include <optional>
#include <string>

namespace pendepth {

std::vector<Depth2> trajectory(const Shape2& P, const Shape2& Q, std::span<const Placement2> poses, bool warm,
                               Prepare prepare) {
  auto where = [](std::size_t k) { return "trajectory: pose " + std::to_string(k) + ": "; };
  for (std::size_t k = 0; k < poses.size(); ++k) {
    if (!std::isfinite(poses[k].degrees)) throw InvalidInput(where(k) + "the angle is not finite");
    if (!std::isfinite(poses[k].t.x()) || !std::isfinite(poses[k].t.y()))
      throw InvalidInput(where(k) + "the placement is not finite");
  }
  std::vector<Depth2> out(poses.size());
  std::optional<Pair2> pair;
  double angle = 0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    try {
      const double a = poses[k].degrees;
      if (!warm || !pair || std::memcmp(&a, &angle, sizeof a) != 0) pair.emplace(P, Q.rotated(a), prepare), angle = a;
      out[k] = pair->minimum(poses[k].t);
    } catch (const InvalidInput& e) {
      throw InvalidInput(where(k) + e.what());
    }
  }
  return out;
}

}  // namespace pendepth
