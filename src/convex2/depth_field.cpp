// PLACEHOLDER while the medial-axis field is written (replaced in this change): linear scan.
#include <pendepth/depth2.hpp>

#include "convex2/minkowski_sum.hpp"

namespace pendepth {

struct DepthField::Impl {
  convex2::MinkowskiSum M;
};

DepthField::DepthField(const ConvexPolygon& P, const ConvexPolygon& Q)
    : impl_(std::make_unique<Impl>(Impl{convex2::MinkowskiSum(P, Q)})) {}
DepthField::~DepthField() = default;
DepthField::DepthField(DepthField&&) noexcept = default;
DepthField& DepthField::operator=(DepthField&&) noexcept = default;

Depth2 DepthField::minimum(const Vec2& t) const {
  convex2::require_finite(t, "placement t");
  const convex2::Nearest best = convex2::nearest_edge(impl_->M, t);
  if (!(best.distance > 0)) return Depth2{};
  return impl_->M.result_for_edge(best.edge, t, best.distance);
}
std::size_t DepthField::edge_count() const { return impl_->M.size(); }
std::size_t DepthField::node_count() const { return 0; }
std::size_t DepthField::max_search_depth() const { return impl_->M.size(); }

}  // namespace pendepth
