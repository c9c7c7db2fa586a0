// Private: shapes made from meshes (src/front/shape3_mesh.cpp) and Pair3's mesh pairs
// (src/front/pair3_mesh.cpp).
#pragma once

#include <pendepth/pendepth.hpp>

#include <memory>

namespace pendepth::mesh3 {
struct MeshPair;
}

namespace pendepth::front {

/// The pieces of P and Q (either non-convex) in engine coordinates, and the pair's scale
/// exponent (src/front/scale.hpp: the extent of every piece's vertices and edges; throws
/// InvalidInput as for convex pairs when the sizes leave the band or a vertex has no exact
/// engine value).
std::shared_ptr<const mesh3::MeshPair> mesh_pair(const Shape3& P, const Shape3& Q, int& scale_exp);

}  // namespace pendepth::front
