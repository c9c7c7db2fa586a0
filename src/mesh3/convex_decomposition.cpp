// Exact convex decomposition of a validated closed mesh (include/pendepth/mesh3.hpp;
// docs/algorithms.md "Convex decomposition"; issue 17 item 2).
//
// CGAL's Nef_polyhedron_3 with the exact kernel (Epeck: lazy GMP rationals), then
// convex_decomposition_3 (Hachenberger, "Exact Minkowski sums of polyhedra and exact and
// efficient decomposition of polyhedra into convex pieces", Algorithmica 2009): the solid is cut
// by planes through its reflex edges until no reflex edge is left; O(r²) pieces for r reflex
// edges at worst. The cuts create new vertices where a cut plane crosses an edge of the mesh or of
// another cut: their coordinates are rationals, in general not doubles. Each piece is returned as
// the hull of its vertices rounded to the nearest double (ties to the lower), and the pieces with
// a rounded vertex are counted (ConvexDecomposition3::rounded_pieces), and a sliver piece that
// rounding makes flat is dropped (dropped_slivers; seen on CGAL's dragknob.off): when both are 0
// the pieces are exact — their volumes sum exactly to the mesh's and they tile it. A decomposition that uses
// only the mesh's own vertices does not exist in general (Schönhardt's polyhedron needs Steiner
// points), so the rounding is stated rather than avoided.
//
// Split first (docs/benchmarks.md "Closed meshes: splitting before the Nef decomposition"): almost all of
// convex_decomposition_3's time is ray shooting in the Nef point locator while it raises the walls
// of reflex edges (perf: ~70% under SNC_point_locator::shoot, mostly exact evaluation of rays
// against the walls already raised), and that cost grows faster than the number of reflex edges.
// So a mesh with more than DecompositionSplit::max_reflex_per_cell reflex edges is first split by
// axis-parallel planes through the median of its reflex edges' midpoints, recursively (a kd-tree
// over the reflex edges' coordinates alone, at most max_depth levels); each leaf box is then
// intersected, exactly, with the whole solid (one Nef intersection per cell, never of a cell with
// a further box, so cell vertices stay first-degree rationals at any depth) and each cell is
// decomposed on its own. The leaf boxes tile the box around the mesh, so the cells tile the solid: the union of their
// pieces is the solid and their interiors are disjoint; each piece is convex. A cut plane passes
// through no mesh vertex (it lies strictly between two consecutive vertex coordinates on its
// axis), so every cell is a regular solid. The cuts add pieces where they cross a convex region (175 → 368
// on sphere966; a few percent on most meshes); bounded walls sometimes make fewer (oblong). Smaller
// cells do not pay: convex_decomposition_3's CPU time is about linear in the reflex edges at ≤ 128
// per cell, and the cut faces add pieces (docs/benchmarks.md "… leaf boxes"). Should a Nef
// operation on a cell throw, the whole mesh is decomposed again in one run (the reference path, max_depth = 0).
//
// The CGAL Nef headers are heavy to compile: they stay in this one file.
#include <pendepth/mesh3.hpp>

#include "mesh3/convex_decomposition_nef.hpp"
#include "mesh3/mesh_impl.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/convex_decomposition_3.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace pendepth {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Nef = CGAL::Nef_polyhedron_3<K>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Poly = CGAL::Polyhedron_3<K>;

// The double nearest to the exact value x (ties to the lower); `exact` tells whether x is one.
double nearest(const K::FT& x, bool& exact) {
  const auto& e = CGAL::exact(x);
  const std::pair<double, double> iv = CGAL::to_interval(e);
  if (iv.first == iv.second) {
    exact = true;
    return iv.first;
  }
  exact = false;
  using ET = std::decay_t<decltype(e)>;
  return e - ET(iv.first) <= ET(iv.second) - e ? iv.first : iv.second;
}

// Exactly: do the points span less than 3 dimensions?
bool flat(const std::vector<Vec3>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) {
      if (predicates::collinear3(v[0], v[i], v[j])) continue;
      for (std::size_t k = j + 1; k < v.size(); ++k)
        if (predicates::orient3d(v[0], v[i], v[j], v[k]) != 0) return false;
      return true;  // v[0], v[i], v[j] span a plane holding every point
    }
  return true;
}

K::Point_3 point(const Vec3& p) { return K::Point_3(p.x(), p.y(), p.z()); }

// The mesh as a CGAL surface mesh (exact: doubles convert exactly).
Mesh surface_mesh(const Mesh3& mesh) {
  Mesh sm;
  const auto pts = mesh.points();
  std::map<std::size_t, Mesh::Vertex_index> vid;
  for (const auto& t : mesh.triangles())
    for (std::size_t v : t)
      if (!vid.count(v)) vid.emplace(v, sm.add_vertex(point(pts[v])));
  for (const auto& t : mesh.triangles()) sm.add_face(vid.at(t[0]), vid.at(t[1]), vid.at(t[2]));
  return sm;
}

struct ReflexEdge {
  Vec3 a, b;
};

// The reflex edges as segments: the neighbour's vertex opposite the edge strictly outside the
// (outward) triangle's plane, exact orient3d as in Mesh3::validate. Only where to cut depends on them.
std::vector<ReflexEdge> reflex_edges(const Mesh3& mesh) {
  const auto p = mesh.points();
  const auto tris = mesh.triangles();
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> opposite;  // directed edge → third vertex
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) opposite[{t[k], t[(k + 1) % 3]}] = t[(k + 2) % 3];
  std::vector<ReflexEdge> out;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) {
      const std::size_t u = t[k], v = t[(k + 1) % 3];
      if (u > v) continue;
      if (predicates::orient3d(p[t[0]], p[t[1]], p[t[2]], p[opposite.at({v, u})]) > 0) out.push_back({p[u], p[v]});
    }
  return out;
}

// An axis-parallel box (closed), a cell of the split: the solid's part inside it.
struct Box {
  double lo[3], hi[3];
};

// Axis-parallel cuts through no mesh vertex, and the boxes around the mesh they bound.
class Cutter {
 public:
  explicit Cutter(const Mesh3& mesh) {
    for (int i = 0; i < 3; ++i) {
      std::vector<double>& c = coords_[i];
      for (const auto& t : mesh.triangles())
        for (std::size_t v : t) c.push_back(mesh.points()[v][i]);
      std::sort(c.begin(), c.end());
      c.erase(std::unique(c.begin(), c.end()), c.end());
      // Beyond the mesh by at least e: strictly, unless that overflows near ±DBL_MAX, where the
      // box ends at the largest finite double (at worst on the mesh's extreme face, which the
      // regularised intersection keeps), never at an infinity no kernel point can hold.
      const double e = std::max({1.0, std::abs(c.front()), std::abs(c.back())});
      around_.lo[i] = std::max(c.front() - e, std::numeric_limits<double>::lowest());
      around_.hi[i] = std::min(c.back() + e, std::numeric_limits<double>::max());
    }
  }

  struct Cut {
    int axis;
    double at;
  };

  // The box around the whole mesh (the root cell).
  const Box& around() const { return around_; }

  // The plane through the median of the edges' midpoints on the axis where they spread most,
  // moved to a double strictly between two consecutive vertex coordinates; none if there is no such double.
  std::optional<Cut> choose(const std::vector<ReflexEdge>& edges) const {
    int axis = 0;
    double spread[3];
    for (int i = 0; i < 3; ++i) {
      const auto [lo, hi] = std::minmax_element(edges.begin(), edges.end(), [&](const ReflexEdge& x, const ReflexEdge& y) {
        return mid(x, i) < mid(y, i);
      });
      spread[i] = mid(*hi, i) - mid(*lo, i);
      if (spread[i] > spread[axis]) axis = i;
    }
    std::vector<double> m;
    for (const auto& e : edges) m.push_back(mid(e, axis));
    std::nth_element(m.begin(), m.begin() + m.size() / 2, m.end());
    const std::vector<double>& c = coords_[axis];
    const auto above = std::upper_bound(c.begin(), c.end(), m[m.size() / 2]);
    if (above == c.begin() || above == c.end()) return std::nullopt;
    const double a = *(above - 1), b = *above, at = a + (b - a) / 2;
    if (!(a < at && at < b)) return std::nullopt;
    return Cut{axis, at};
  }

  // The part of `box` below (`upper` false) or above the cut.
  static Box side(Box box, const Cut& cut, bool upper) {
    (upper ? box.lo : box.hi)[cut.axis] = cut.at;
    return box;
  }

 private:
  static double mid(const ReflexEdge& e, int i) { return e.a[i] / 2 + e.b[i] / 2; }
  std::vector<double> coords_[3];
  Box around_;
};

// The leaves of a kd-tree over the reflex edges: cut `box` while it meets more than
// split.max_reflex_per_cell of them and a cut separates them (neither side keeps them all), at
// most split.max_depth levels. Only the reflex edges' coordinates are looked at: no Nef operation.
void split_boxes(const Box& box, const std::vector<ReflexEdge>& edges, const Cutter& cutter,
                 const detail::DecompositionSplit& split, int depth, std::vector<Box>& out) {
  std::optional<Cutter::Cut> cut;
  std::vector<ReflexEdge> below, above;
  if (edges.size() > split.max_reflex_per_cell && depth < split.max_depth && (cut = cutter.choose(edges))) {
    for (const auto& e : edges) {
      if (std::min(e.a[cut->axis], e.b[cut->axis]) < cut->at) below.push_back(e);
      if (std::max(e.a[cut->axis], e.b[cut->axis]) > cut->at) above.push_back(e);
    }
    if (std::max(below.size(), above.size()) == edges.size()) cut.reset();  // no progress
  }
  if (!cut) {
    out.push_back(box);
    return;
  }
  split_boxes(Cutter::side(box, *cut, false), below, cutter, split, depth + 1, out);
  split_boxes(Cutter::side(box, *cut, true), above, cutter, split, depth + 1, out);
}

// The solid's part inside `box`: one exact Nef intersection of the whole solid with the box, never
// of a cell with a further box. So every vertex of a cell is a mesh vertex, a box corner, or a mesh
// edge / face meeting a box face / edge — a rational of the first degree in the input doubles at
// any depth of the kd-tree — and the cells depend on the solid alone, not on one another. O(n log n)
// per cell in Nef's overlay: ~3% of the time at the default split (anchor), 9–14% at 8–32 reflex
// edges per cell (docs/benchmarks.md "… leaf boxes").
Nef cell_of(const Nef& solid, const Box& b) {
  const auto P = [](double x, double y, double z) { return K::Point_3(x, y, z); };
  Mesh box;
  CGAL::make_hexahedron(P(b.lo[0], b.lo[1], b.lo[2]), P(b.hi[0], b.lo[1], b.lo[2]), P(b.hi[0], b.hi[1], b.lo[2]),
                        P(b.lo[0], b.hi[1], b.lo[2]), P(b.lo[0], b.hi[1], b.hi[2]), P(b.lo[0], b.lo[1], b.hi[2]),
                        P(b.hi[0], b.lo[1], b.hi[2]), P(b.hi[0], b.hi[1], b.hi[2]), box);
  return solid * Nef(box);
}

// The marked bounded volumes of a decomposed Nef polyhedron, as polyhedra (the first volume is the outer one).
void collect_pieces(Nef& decomposed, std::vector<Poly>& out) {
  for (auto ci = ++decomposed.volumes_begin(); ci != decomposed.volumes_end(); ++ci) {
    if (!ci->mark()) continue;
    out.emplace_back();
    decomposed.convert_inner_shell_to_polyhedron(ci->shells_begin(), out.back());
  }
}

// CGAL's convex decomposition of one cell, its pieces appended to `out`.
void decompose_into(Nef cell, std::vector<Poly>& out) {
  CGAL::convex_decomposition_3(cell);
  collect_pieces(cell, out);
}

// The exact pieces; the split path falls back to one run if a Nef operation throws.
std::vector<Poly> exact_pieces(const Mesh3& mesh, const detail::DecompositionSplit& split, std::size_t& cells) {
  const Mesh sm = surface_mesh(mesh);
  const Nef solid(sm);
  const Cutter cutter(mesh);
  std::vector<Box> boxes;
  split_boxes(cutter.around(), reflex_edges(mesh), cutter, split, 0, boxes);
  std::vector<Poly> out;
  cells = boxes.size();
  if (boxes.size() == 1) {
    decompose_into(solid, out);
    return out;
  }
  try {
    for (const Box& b : boxes) decompose_into(cell_of(solid, b), out);
  } catch (const std::exception&) {
    out.clear();
    cells = 1;
    decompose_into(solid, out);
  }
  return out;
}

// Six times the signed volume of a closed polyhedron, exactly.
K::FT six_volume(const Poly& P) {
  K::FT v = 0;
  for (auto f = P.facets_begin(); f != P.facets_end(); ++f) {
    auto h = f->facet_begin();
    const K::Point_3& a = h->vertex()->point();
    for (++h; std::next(h) != f->facet_begin(); ++h)
      v += CGAL::determinant(a - CGAL::ORIGIN, h->vertex()->point() - CGAL::ORIGIN,
                             std::next(h)->vertex()->point() - CGAL::ORIGIN);
  }
  return v;
}

// Exactly: no vertex of P strictly outside any facet's plane (outside: orientation POSITIVE for an
// outward facet, CGAL's convention; `sign` is the sign of the volume, -1 when the facets face inwards).
bool convex(const Poly& P, int sign) {
  for (auto f = P.facets_begin(); f != P.facets_end(); ++f) {
    std::vector<K::Point_3> fv;
    auto h = f->facet_begin();
    do fv.push_back(h->vertex()->point());
    while (++h != f->facet_begin());
    for (std::size_t j = 2; j < fv.size(); ++j) {
      if (CGAL::collinear(fv[0], fv[1], fv[j])) continue;
      for (auto v = P.vertices_begin(); v != P.vertices_end(); ++v)
        if (CGAL::orientation(fv[0], fv[1], fv[j], v->point()) * sign == CGAL::POSITIVE) return false;
      break;
    }
  }
  return true;
}

}  // namespace

namespace detail {

ConvexDecomposition3 convex_decomposition(const Mesh3& mesh, const DecompositionSplit& split) {
  std::set<std::array<double, 3>> mesh_vertices;
  for (const auto& t : mesh.triangles())
    for (std::size_t i : t) mesh_vertices.insert({mesh.points()[i].x(), mesh.points()[i].y(), mesh.points()[i].z()});
  std::set<std::array<double, 3>> cut;

  ConvexDecomposition3 out;
  out.reflex_edges = mesh.reflex_edges();
  for (const Poly& P : exact_pieces(mesh, split, out.cells)) {
    std::vector<Vec3> v;
    bool rounded = false;
    for (auto it = P.points_begin(); it != P.points_end(); ++it) {
      bool ex[3];
      const Vec3 q(nearest(it->x(), ex[0]), nearest(it->y(), ex[1]), nearest(it->z(), ex[2]));
      const bool exact = ex[0] && ex[1] && ex[2];
      rounded = rounded || !exact;
      if (!exact || !mesh_vertices.count({q.x(), q.y(), q.z()})) cut.insert({q.x(), q.y(), q.z()});
      v.push_back(q);
    }
    const std::string name = mesh.name() + " piece " + std::to_string(out.pieces.size());
    if (!flat(v)) {
      out.pieces.push_back(ConvexPolytope::hull(v, name));
    } else {  // a sliver thinner than the rounding: only a rounded piece can be flat
      ++out.dropped_slivers;
      continue;
    }
    if (rounded) ++out.rounded_pieces;
  }
  out.cut_vertices = cut.size();
  return out;
}

DecompositionCheck check_decomposition(const Mesh3& mesh, const DecompositionSplit& split) {
  DecompositionCheck c;
  const std::vector<Poly> pieces = exact_pieces(mesh, split, c.cells);
  c.pieces = pieces.size();
  const Nef solid(surface_mesh(mesh));
  Nef all;  // empty
  K::FT sum = 0;
  c.each_convex = true;
  for (const Poly& P : pieces) {
    Poly copy = P;
    all += Nef(copy);
    const K::FT v = six_volume(P);
    const int sign = CGAL::sign(v);
    sum += sign * v;
    c.each_convex = c.each_convex && sign != 0 && convex(P, sign);
  }
  c.union_is_mesh = all == solid;
  K::FT mesh_volume = 0;
  for (const auto& t : mesh.triangles())
    mesh_volume += CGAL::determinant(point(mesh.points()[t[0]]) - CGAL::ORIGIN, point(mesh.points()[t[1]]) - CGAL::ORIGIN,
                                     point(mesh.points()[t[2]]) - CGAL::ORIGIN);
  c.volumes_sum = sum == mesh_volume;
  return c;
}

}  // namespace detail

ConvexDecomposition3 convex_decomposition(const Mesh3& mesh) { return detail::convex_decomposition(mesh, {}); }

}  // namespace pendepth
