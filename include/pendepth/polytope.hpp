// pendepth — validated convex polytopes in 3D and their Dobkin–Kirkpatrick hierarchy.
//
// ConvexPolytope is the 3D normal form every O(log n) search relies on (docs/algorithms.md §R4.2):
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

class ConvexPolytope;
namespace convex3 {
struct PolytopeData;
/// The polytope's internal structures (src/convex3/polytope_data.hpp): for the engines and tests.
const PolytopeData& data_of(const ConvexPolytope& P);
}  // namespace convex3

/// First intersection of a directed line with a ConvexPolytope (DHS Lemma 5.2).
struct LineHit {
  bool hit = false;  ///< the line meets the closed polytope (touching counts)
  /// The line meets the polytope in origin + t·dir for t in [t_enter, t_exit] (a tangent line
  /// touching a vertex or an edge: t_enter == t_exit). Few-ulp accurate (exact decisions).
  double t_enter = 0, t_exit = 0;
  Vec3 enter{0, 0, 0}, exit{0, 0, 0};  ///< the two points (accurate coordinates)
  /// True faces (see face_of_triangle) whose planes give t_enter and t_exit: the line crosses
  /// face_enter's plane inwards (n·dir < 0) and face_exit's outwards (n·dir > 0).
  int face_enter = -1, face_exit = -1;
  std::size_t nodes_visited = 0;  ///< hierarchy nodes examined (diagnostic: grows like log n)
};

/// First contact of a translating line with a ConvexPolytope (DHS Lemma 5.3).
struct LineContact {
  enum class Feature { None, Vertex, Edge };
  bool contact = false;  ///< false: the translating line never touches the polytope
  /// The line {point + shift·move_dir + τ·line_dir : τ real} is the first that touches.
  double shift = 0;
  Vec3 point{0, 0, 0};  ///< a contact point (exactly the vertex for a vertex contact)
  /// The feature of the polytope the contact point lies on: a vertex, or the relative interior of
  /// a true edge (vertex ids, edge[0] < edge[1]). When the first contact is a whole segment (an
  /// edge or face parallel to line_dir), the point is its end with the smallest
  /// (move_dir ⊥ line_dir)-then-line_dir key, i.e. a deterministic vertex of that segment.
  Feature feature = Feature::None;
  int vertex = -1;
  std::array<int, 2> edge{-1, -1};
  std::size_t nodes_visited = 0;  ///< hierarchy nodes examined (diagnostic)
};

class ConvexPolytope {
 public:
  /// Convex hull of a point set in the normal form above, plus its inner DK hierarchy.
  /// Exact incremental hull (exact orient3d), then non-extreme points are removed.
  /// Throws InvalidInput naming `name` for: non-finite coordinates (with the point index),
  /// fewer than 4 affinely independent points (empty, coincident, collinear or coplanar input).
  /// O(n log n) expected (randomised insertion order from a pinned seed: deterministic).
  static ConvexPolytope hull(std::span<const Vec3> points, std::string_view name = "points");

  /// The same polytope with every coordinate multiplied by 2^exponent: the same numbering of
  /// vertices, triangles, half-edges and hierarchy levels (scaling by a power of two keeps every
  /// orientation). Throws InvalidInput when a coordinate would overflow or lose bits. O(n).
  ConvexPolytope scaled(int exponent) const;

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
  /// hierarchy (O'Rourke CGC §7.10 / Edelsbrunner–Maurer; docs/algorithms.md §R4.3). O(log n).
  /// Ties are broken deterministically by a symbolic perturbation: among maximisers of u . v
  /// the one maximising coordinate k, then coordinate j, where k, j are the axes of the
  /// smallest and middle |u_i| (k < j on equal magnitudes). Exact: the returned vertex is a
  /// true maximiser of u . v for the double vector u. Precondition: u finite and non-zero.
  int support(const Vec3& u) const;

  /// Number of hierarchy levels (1 = the polytope itself is the top level) and vertex counts.
  std::size_t hierarchy_levels() const;
  std::vector<std::size_t> level_sizes() const;
  /// Triangles of hierarchy level i (0 = the polytope): the levels first_hit and first_contact take.
  std::vector<std::array<int, 3>> level_triangles(std::size_t i) const;

  /// Number of true faces (maximal coplanar sets of triangles) and the face of triangle t.
  std::size_t face_count() const;
  int face_of_triangle(std::size_t t) const;
  /// Number of levels of the outer DK hierarchy (DHS §5.1: P = P_1 ⊂ … ⊂ P_k, each level the
  /// intersection of a subset of the face half-spaces; built on first use, O(n log n)).
  std::size_t outer_hierarchy_levels() const;

  /// DHS Lemma 5.2: the intersection of the line origin + t·dir (t real) with the polytope, or
  /// with inner hierarchy level `level` (0 = the polytope; its triangles: level_triangles), by a
  /// descent of that level's outer hierarchy with O(1) work per level: O(log n). Exact
  /// decisions (filtered, with exact fallback); a line that only touches the boundary is a hit
  /// with t_enter == t_exit (or the touched segment if it lies in a face plane). face_enter /
  /// face_exit are faces of that level (face_of_triangle numbers level 0's).
  /// Throws InvalidInput for a non-finite origin, a zero or non-finite dir, or a bad level.
  LineHit first_hit(const Vec3& origin, const Vec3& dir, std::size_t level = 0) const;

  /// DHS Lemma 5.3: the line through `point` with direction line_dir translates along move_dir
  /// from infinity (shift from −∞ upwards); returns the first shift at which it touches the
  /// polytope and where. O(log n) by the outer-hierarchy descent on the plane the line sweeps.
  /// `level` selects an inner hierarchy level as for first_hit.
  /// Throws InvalidInput for non-finite input, zero vectors, line_dir parallel to move_dir, or a
  /// bad level. (DHS Lemma 5.4, a plane with normal u moving so that u·x decreases, first
  /// touches support(u): that is the existing support() walk on the inner hierarchy.)
  LineContact first_contact(const Vec3& point, const Vec3& line_dir, const Vec3& move_dir,
                            std::size_t level = 0) const;

  friend const convex3::PolytopeData& convex3::data_of(const ConvexPolytope& P);

 private:
  std::shared_ptr<const convex3::PolytopeData> d_;
};

}  // namespace pendepth
