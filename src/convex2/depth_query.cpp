// DepthQuery2: validate once, preprocess once, query many (docs/design.md §2).
#include <pendepth/depth2.hpp>

namespace pendepth {

DepthQuery2::DepthQuery2(ConvexPolygon P, ConvexPolygon Q)
    : P_(std::move(P)), Q_(std::move(Q)), field_(P_, Q_) {}

}  // namespace pendepth
