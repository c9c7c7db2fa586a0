// pendepth — closed triangle meshes (non-convex polyhedra): validation and exact convex
// decomposition (docs/design.md "Meshes", docs/algorithms.md "Mesh validation", "Convex
// decomposition"; issue 17).
//
//   io::MeshFile f = io::read_mesh("part.obj");
//   Mesh3 m = Mesh3::validate(f, "part");         // throws InvalidInput naming face / edge / vertex
//   m.convex();                                     // exact: every edge convex, one surface
//   const ConvexDecomposition3& d = m.decomposition();   // built once (CGAL Nef), thread-safe
#pragma once

#include <pendepth/io.hpp>
#include <pendepth/polytope.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth {

/// A convex decomposition of a closed mesh: convex pieces with pairwise disjoint interiors whose
/// union is the solid (exact before rounding, see rounded_pieces).
struct ConvexDecomposition3 {
  /// The pieces, each the hull of its vertices rounded to the nearest doubles.
  std::vector<ConvexPolytope> pieces;
  /// Pieces with at least one vertex that is not exactly a double (a cut vertex with rational
  /// coordinates) and was rounded to the nearest double (error ≤ ½ ulp per coordinate): their
  /// union may miss or add slivers of that size. 0 means the pieces are exact: their volumes sum
  /// exactly to the mesh's and they cover it exactly.
  std::size_t rounded_pieces = 0;
  /// Pieces left out because rounding made them flat: slivers thinner than the rounding error
  /// (a piece with exact vertices is never flat).
  std::size_t dropped_slivers = 0;
  /// Distinct piece vertices that are not vertices of the mesh (new vertices of the cuts).
  std::size_t cut_vertices = 0;
  /// Reflex edges of the mesh (edges whose dihedral angle exceeds π), the decomposition's input size.
  std::size_t reflex_edges = 0;
  /// Cells the mesh was cut into (exactly, by axis-parallel planes) before each was decomposed
  /// on its own; 1 when it was decomposed in one run (src/mesh3/convex_decomposition.cpp).
  std::size_t cells = 1;
};

/// A validated closed, oriented, 2-manifold, non-self-intersecting triangle mesh bounding one
/// solid (one closed surface). Triangles are oriented outwards (CCW seen from outside; a file
/// oriented inwards is flipped, as polygons accept either orientation). Cheap to copy; a
/// default-constructed Mesh3 is empty and may only be assigned to.
class Mesh3 {
 public:
  /// Triangulates the file's faces (a face of more than 3 vertices must be planar and strictly
  /// convex: it is split into a fan), then checks, exactly (exact orient3d / collinearity and
  /// triangle–triangle predicates), and throws InvalidInput "WHERE: NAME: problem", WHERE the
  /// face ("FILE:LINE: face F" or "FILE: face F (byte offset K)"), for: a repeated vertex in a
  /// face, a zero-area face, a non-planar or non-convex polygon face, an open edge (one face), a
  /// non-manifold edge (3 or more faces), two faces using an edge in the same direction
  /// (inconsistent orientation), a non-manifold vertex (several fans), two separate surfaces, two
  /// faces that intersect other than along their shared edge or vertex, zero volume; and "FILE:
  /// NAME: no faces" for a file without faces. Edges and vertices are named by the file's own
  /// vertex numbers (1-based in OBJ). Vertices no face uses are ignored.
  /// O(n log n + k) for n triangles and k pairs of triangles with overlapping boxes.
  static Mesh3 validate(const io::MeshFile& file, std::string_view name = "mesh");

  /// The file's vertices (all of them, in file order; triangles index into this).
  std::span<const Vec3> points() const;
  /// Triangles, outward (normal (b − a) × (c − a) points out of the solid).
  std::span<const std::array<std::size_t, 3>> triangles() const;
  /// The file face triangle t comes from.
  std::size_t face_of(std::size_t t) const;
  /// The points some triangle uses, in file order.
  std::vector<Vec3> used_points() const;
  /// Exactly: is the solid convex (every edge's dihedral angle ≤ π, one closed surface)?
  bool convex() const;
  /// Number of reflex edges (dihedral angle > π, exact); 0 iff convex().
  std::size_t reflex_edges() const;
  /// The file's faces were oriented inwards and have been reversed.
  bool flipped() const;
  /// Volume (rounded; its sign was decided exactly).
  double volume() const;
  const std::string& name() const;
  const std::string& source() const;

  /// The exact convex decomposition (src/mesh3/convex_decomposition.cpp), computed on first use
  /// (thread-safe) and kept.
  const ConvexDecomposition3& decomposition() const;

  struct Impl;

 private:
  std::shared_ptr<Impl> impl_;
};

/// Convex decomposition of a validated mesh by CGAL's Nef_polyhedron_3 convex_decomposition_3
/// (exact kernel; cuts through reflex edges), pieces rounded as ConvexDecomposition3 says. A mesh
/// with more than 128 reflex edges is first cut exactly into cells by axis-parallel planes (a
/// kd-tree over its reflex edges, ≤ 16 cells), each decomposed on its own: 1.3–2× faster on
/// most slow sample meshes (docs/benchmarks.md).
/// O(r²) pieces for r reflex edges at worst; costly (seconds for thousands of triangles).
ConvexDecomposition3 convex_decomposition(const Mesh3& mesh);

}  // namespace pendepth
