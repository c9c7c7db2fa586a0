// Private: shapes made from meshes (src/front/shape3_mesh.cpp) and Pair3's mesh pairs
// (src/front/pair3_mesh.cpp).
#pragma once

#include <pendepth/pendepth.hpp>

#include "mesh3/lazy.hpp"

#include <memory>

namespace pendepth::mesh3 {
struct MeshPair;

/// Pair3's mesh pair (either shape non-convex): the pieces of P and Q in engine coordinates and
/// the pair's scale exponent, built on the first query (mesh3/lazy.hpp), never at construction.
struct LazyMeshPair {
  struct Built {
    std::shared_ptr<const MeshPair> pair;
    int scale_exp = 0;
  };
  explicit LazyMeshPair(std::function<Built()> make) : built(std::move(make)) {}
  Lazy<Built> built;
  const MeshPair& pair() const { return *built.get().pair; }
  int scale_exp() const { return built.get().scale_exp; }
};
}  // namespace pendepth::mesh3

namespace pendepth::front {

/// The pieces of P and Q (either non-convex) in engine coordinates, and the pair's scale
/// exponent (src/front/scale.hpp: the extent of every piece's vertices and edges), built when
/// first asked for (thread-safe); that build throws InvalidInput, prefixed with the mesh's
/// source, as for convex pairs when the sizes leave the band or a vertex has no exact engine value.
std::shared_ptr<const mesh3::LazyMeshPair> mesh_pair(const Shape3& P, const Shape3& Q);

/// An InvalidInput from building a mesh pair's pieces, prefixed with the source of the first
/// non-convex shape's mesh (as the CLI named the file when the pieces were built at construction).
[[noreturn]] void rethrow_with_mesh_source(const Shape3& P, const Shape3& Q, const InvalidInput& e);

}  // namespace pendepth::front
