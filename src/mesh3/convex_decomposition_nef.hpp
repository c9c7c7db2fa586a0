// Internal: the exact (unrounded) convex decomposition of a mesh, split into cells first
// (src/mesh3/convex_decomposition.cpp), for the library's rounding step and for tests that check
// the exact pieces against the mesh with Nef boolean operations (tests/mesh3/test_mesh_decompose_split.cpp).
#pragma once

#include <pendepth/mesh3.hpp>

#include <cstddef>

namespace pendepth::detail {

/// How the mesh is split before CGAL's convex_decomposition_3 runs on each cell.
struct DecompositionSplit {
  /// A cell with more reflex edges than this (edges meeting it, counted on the mesh) is cut in two.
  std::size_t max_reflex_per_cell = 128;
  /// At most this many levels of cuts (2^max_depth cells).
  int max_depth = 4;
};

/// What an exact check of a split decomposition found (every comparison exact, Epeck/Nef).
struct DecompositionCheck {
  std::size_t pieces = 0;
  std::size_t cells = 0;
  bool union_is_mesh = false;     ///< Nef union of the pieces == the mesh's Nef polyhedron
  bool volumes_sum = false;       ///< Σ exact piece volumes == the exact mesh volume (so interiors are disjoint)
  bool each_convex = false;       ///< every vertex of a piece on or below each of its facets' planes
};

/// The decomposition under `split`, rounded as ConvexDecomposition3 says.
ConvexDecomposition3 convex_decomposition(const Mesh3& mesh, const DecompositionSplit& split);

/// Decomposes under `split` and checks the exact pieces against the mesh. Nef unions: for small meshes.
DecompositionCheck check_decomposition(const Mesh3& mesh, const DecompositionSplit& split);

}  // namespace pendepth::detail
