// Private: storage of a ConvexPolytope and its inner Dobkin–Kirkpatrick hierarchy (flat arrays).
//
// Every level is a closed triangulated surface over a subset of the polytope's vertices (global
// vertex ids). Half-edge h = 3f + k runs from fv[h] to fv[3f + (k+1)%3]; rotations around the
// origin of h (seen from outside): ccw(h) = twin(prev(h)), cw(h) = next(twin(h)).
#pragma once

#include <pendepth/polytope.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

namespace pendepth::convex3 {

struct OuterHierarchy;  // outer_hierarchy.hpp

struct DKLevel {
  std::vector<int> fv;    ///< 3 per triangle, global vertex ids, CCW from outside
  std::vector<int> twin;  ///< opposite half-edge at this level
  /// Link to the finer level (index - 1), empty on level 0. For h = (a -> b): the finer level's
  /// half-edge (a -> b) if that edge exists there, else (a -> v) where v is the removed vertex
  /// whose hole retriangulation created the diagonal (a, b) (its "umbrella" parent, DHS §5.1).
  std::vector<int> down;
  std::vector<int> verts;  ///< vertex ids present at this level

  static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }
  int origin(int h) const { return fv[h]; }
  int target(int h) const { return fv[next(h)]; }
  int ccw(int h) const { return twin[prev(h)]; }
  int cw(int h) const { return next(twin[h]); }
};

/// Vertex adjacency of level 0 in flat arrays (CSR) plus coordinate ranges, for support queries
/// by hill climbing (minimum_expand.cpp). Built once per shape on first use (vertex_adjacency.cpp).
struct VertexAdjacency {
  std::vector<int> start;  ///< n + 1 offsets: vertex v's entries are [start[v], start[v+1])
  std::vector<int> nbr;    ///< neighbour vertex (every level-0 edge, flat-facet diagonals too), CCW
  std::vector<int> he;     ///< level-0 half-edge v -> nbr[k]
  std::vector<double> dx, dy, dz;  ///< nbr[k] − v, rounded (contiguous, for the climbs)
  Vec3 extent{0, 0, 0};    ///< max − min of each coordinate over the vertices
  Vec3 centroid{0, 0, 0};  ///< mean of the vertices (rounded; an interior point up to rounding)
  /// Cube map of seeds: direction u falls in cell (face of the largest |u_i|, then a k × k grid
  /// of the other two coordinates divided by |u_i|); cube[cell] is a vertex maximising the
  /// rounded u·v at the cell's centre direction (approximate: a starting point for exact climbs).
  int cube_k = 1;
  std::vector<int> cube;
  /// Flat faces of level 0 (a face of the polytope with its diagonals): face_of[t] = the face of
  /// triangle t; face_tris[face_start[f] .. face_start[f+1]) = its triangles (breadth first
  /// across diagonals from its least triangle); face_canon[f] = {least triangle id, the
  /// lexicographically least vertex a (by coordinates), a's successor and predecessor on the
  /// face's boundary, counter-clockwise from outside}. σ's canonical answer reads these instead
  /// of flooding the face on every query (minimum_expand.cpp).
  std::vector<int> face_of, face_start, face_tris;
  std::vector<std::array<int, 4>> face_canon;
};

struct PolytopeData {
  std::string name;
  std::vector<Vec3> v;
  std::vector<std::size_t> input_index;
  std::vector<std::array<int, 3>> tris;
  std::vector<DKLevel> levels;  ///< levels[0] = the polytope itself
  std::vector<int> vertex_he;   ///< one outgoing level-0 half-edge per vertex
  /// One half-edge per true edge (h < twin(h), its two triangles not coplanar): edges of the
  /// polytope proper, not diagonals of flat facets.
  std::vector<int> edges;
  std::array<int, 4> protected_tet{};
  /// Lazily built VertexAdjacency (thread-safe); a copy starts empty and rebuilds on use.
  /// `ready` (set with release order once `value` is built) lets every later call skip
  /// std::call_once, which costs a thread-local setup and a pthread_once call per query.
  struct AdjacencyCache {
    std::once_flag once;
    std::atomic<bool> ready{false};
    VertexAdjacency value;
    AdjacencyCache() = default;
    AdjacencyCache(const AdjacencyCache&) {}
    AdjacencyCache& operator=(const AdjacencyCache&) { return *this; }
  };
  mutable AdjacencyCache adjacency_cache;
  /// Lazily built outer DK hierarchies (outer_hierarchy.cpp): entry i is the outer hierarchy of
  /// inner level i (DHS §5.1's twin representation), built on its first use under the mutex; a
  /// copy starts empty and rebuilds on use.
  struct OuterCache {
    std::mutex mu;
    std::vector<std::shared_ptr<const OuterHierarchy>> value;
    OuterCache() = default;
    OuterCache(const OuterCache&) {}
    OuterCache& operator=(const OuterCache&) { return *this; }
  };
  mutable OuterCache outer_cache;
};

/// The outer hierarchy of inner level `level` of d (0: the polytope), built on the first call
/// (O(n_i log n_i)), then O(1). Precondition: level < d.levels.size().
const OuterHierarchy& outer_hierarchy(const PolytopeData& d, std::size_t level = 0);

/// The CSR adjacency of d's level 0 and its seed cube map, built on the first call (O(n)), then
/// O(1).
const VertexAdjacency& vertex_adjacency(const PolytopeData& d);

/// The reference support query (tests): same answer and tie-break as ConvexPolytope::support by
/// scanning all vertices, O(n).
int support_brute(const ConvexPolytope& P, const Vec3& u);

/// A vertex near the maximiser of u·v (from the cube map; any vertex for a zero or non-finite
/// u). O(1).
inline int seed_vertex(const VertexAdjacency& a, const Vec3& u) {
  const double x = std::abs(u[0]), y = std::abs(u[1]), z = std::abs(u[2]);
  const int ax = x >= y ? (x >= z ? 0 : 2) : (y >= z ? 1 : 2);
  const double m = ax == 0 ? x : ax == 1 ? y : z;
  if (!(m > 0 && m <= 1.7e308)) return a.cube[0];
  const int k = a.cube_k;
  const double s = 0.5 * k / m;  // u_i + m lies in [0, 2m]
  const int i = std::min(static_cast<int>((u[(ax + 1) % 3] + m) * s), k - 1);
  const int j = std::min(static_cast<int>((u[(ax + 2) % 3] + m) * s), k - 1);
  return a.cube[((2 * ax + (u[ax] < 0)) * k + i) * k + j];
}

/// Exact incremental hull of pts restricted to `ids`, seeded by 4 affinely independent ids.
/// Returns triangles (CCW from outside) over point ids. Points strictly inside or on the
/// boundary of the current hull are never inserted; the result may still keep vertices that
/// a later point made non-extreme (the caller filters). Expected O(k log k).
std::vector<std::array<int, 3>> incremental_hull(const std::vector<Vec3>& pts, std::vector<int> ids,
                                                 std::array<int, 4> seed);

/// Builds the twin array of a closed triangle mesh given as fv (3 per triangle). O(F log F).
/// Returns false if some half-edge has no unique twin (not a closed 2-manifold).
bool build_twins(const std::vector<int>& fv, std::vector<int>& twin);

/// Builds levels 1.. of the inner hierarchy from d.levels[0] (DHS §5.1, docs/algorithms.md §R4.2).
void build_dk_hierarchy(PolytopeData& d);

}  // namespace pendepth::convex3
