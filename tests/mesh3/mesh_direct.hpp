// Shared by the tests of the exact mesh σ (test_mesh_sigma_exact.cpp, test_mesh_sigma_tiers.cpp),
// which call the mesh engine below Pair3: a generated mesh as a shape, and the pair of piece lists
// the front door would build for it (no numeric-domain scaling: the tests' meshes are unit-sized).
#pragma once

#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_pair.hpp"
#include "mesh_gen.hpp"

#include <string>
#include <utility>

namespace mesh3_test {

/// The validated closed mesh of g as a Shape3 (convex pieces on demand).
inline pendepth::Shape3 mesh_shape(const Gen& g, const std::string& name) {
  return pendepth::Shape3::from_mesh(pendepth::Mesh3::validate(to_file(g, name), name));
}

/// The pieces of both shapes as the mesh engine takes them (exact unless a decomposition rounded).
inline pendepth::mesh3::MeshPair direct(const pendepth::Shape3& a, const pendepth::Shape3& b) {
  bool exact = true;
  auto P = pendepth::mesh3::pieces_of(a, exact);
  auto Q = pendepth::mesh3::pieces_of(b, exact);
  return pendepth::mesh3::MeshPair::make(std::move(P), std::move(Q), exact);
}

}  // namespace mesh3_test
