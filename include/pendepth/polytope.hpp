// pendepth — validated convex polytopes in 3D and their Dobkin–Kirkpatrick hierarchy.
//
// ConvexPolytope is the 3D normal form every O(log n) search relies on (notes §4.2):
//   * the vertex set is STRICTLY convex: every vertex is a proper extreme point (points inside,
//     on facets or on edges of the hull are dropped, decided by exact orient3d), so no three
//     vertices are collinear and no triangle is degenerate;
//   * the boundary is triangulated (coplanar triangles allowed: a flat facet with k vertices
//     becomes k - 2 triangles), every triangle counter-clockwise seen from outside;
//   * half-edges: half-edge h = 3f + k runs from triangles()[f][k] to triangles()[f][(k+1)%3];
//     twin(h) is the opposite half-edge (the boundary is a closed 2-manifold).
// The inner DK hierarchy (DHS §5.1, Fact 5.1) is built once by hull(); support() walks it.
#pragma once

#include <pendepth/geometry.hpp>

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth {

namespace predicates {

/// Exact sign of det[b - a, c - a, d - a] = ((b - a) x (c - a)) . (d - a): +1 if d lies on the
/// side of the plane (a, b, c) that (b - a) x (c - a) points to (outside of a CCW-from-outside
/// triangle), -1 on the other side, 0 coplanar. Filtered double, exact fallback.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Exactly true iff a, b, c lie on one line (including coincident points).
bool collinear3(const Vec3& a, const Vec3& b, const Vec3& c);

/// Exact sign of u . (a - b).
int dot3_sign(const Vec3& u, const Vec3& a, const Vec3& b);

}  // namespace predicates

namespace convex3 {
struct PolytopeData;
}

class ConvexPolytope {
 public:
  /// Convex hull of a point set in the normal form above, plus its inner DK hierarchy.
  /// Exact incremental hull (exact orient3d), then non-extreme points are removed.
  /// Throws InvalidInput naming `name` for: non-finite coordinates (with the point index),
  /// fewer than 4 affinely independent points (empty, coincident, collinear or coplanar input).
  /// O(n log n) expected (randomised insertion order from a pinned seed: deterministic).
  static ConvexPolytope hull(std::span<const Vec3> points, std::string_view name = "points");

  std::size_t size() const;
  const Vec3& operator[](std::size_t i) const;
  std::span<const Vec3> vertices() const;
  /// Triangles, CCW seen from outside (outward normal (b - a) x (c - a)).
  std::span<const std::array<int, 3>> triangles() const;
  /// Half-edge twin (see the header comment for the numbering).
  int twin(int h) const;
  /// Index in the input point list of vertex i.
  std::size_t input_index(std::size_t i) const;
  const std::string& name() const;

  /// Support vertex in direction u (a vertex maximising u . v), by the walk down the inner DK
  /// hierarchy (O'Rourke CGC §7.10 / Edelsbrunner–Maurer; notes §4.3). O(log n).
  /// Ties are broken deterministically by a symbolic perturbation: among maximisers of u . v
  /// the one maximising coordinate k, then coordinate j, where k, j are the axes of the
  /// smallest and middle |u_i| (k < j on equal magnitudes). Exact: the returned vertex is a
  /// true maximiser of u . v for the double vector u. Precondition: u finite and non-zero.
  int support(const Vec3& u) const;
  /// Same answer (same tie-break) by scanning all vertices. O(n). For tests and tiny shapes.
  int support_brute(const Vec3& u) const;

  /// Number of hierarchy levels (1 = the polytope itself is the top level) and vertex counts.
  std::size_t hierarchy_levels() const;
  std::vector<std::size_t> level_sizes() const;
  /// Triangles of hierarchy level i (0 = the polytope). For tests.
  std::vector<std::array<int, 3>> level_triangles(std::size_t i) const;

  const convex3::PolytopeData& data() const { return *d_; }

 private:
  std::shared_ptr<const convex3::PolytopeData> d_;
};

/// Reads the vertices ("v x y z" lines) of a Wavefront OBJ file; other lines are ignored.
/// Throws InvalidInput naming the file (and line) if it cannot be opened, a "v" line is
/// malformed, or it holds no vertex.
std::vector<Vec3> read_obj_vertices(const std::string& path);

}  // namespace pendepth
