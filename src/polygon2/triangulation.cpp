// Triangulation of a polygon with holes (DHS §4.1 Step 1). Two algorithms, same contract
// (triangulation.hpp): exact ear clipping for small hole-free polygons (the nesting pieces the
// no-fit-polygon build triangulates per pair: 4-30 vertices, many of them straight), CGAL's
// constrained Delaunay triangulation (CDT) for everything else. DHS only needs "a triangulation";
// any algorithm giving N - 2 proper triangles without Steiner points fits.
//
// Ear clipping (Meisters' two-ears theorem). The remaining ring is always a simple CCW polygon.
// Vertex v with neighbours u, w is an ear iff orient2d(u, v, w) > 0 (never a zero-area triangle,
// so a straight vertex is never a tip; it stays in the ring and ends up as a corner) and no other
// vertex of the ring lies in the CLOSED triangle uvw (a vertex on u-w would be a T-junction).
// Then no edge meets the open triangle or the open diagonal, so u-w is a proper diagonal and the
// rest stays simple; every simple polygon with N > 3 has such an ear (a leaf of any triangulation
// by proper diagonals), so the search cannot fail on a valid Polygon — the CDT fallback is a net.
// Only non-convex vertices (orient2d(prev, x, next) <= 0) need testing: if any vertex lies in
// the closed triangle, the first one met by a line sweeping from v parallel to u-w has both
// neighbours on the far side of (or on) the sweep line, while the open segment from v to it lies
// in P's interior, so its interior angle is >= 180°. Clipping shrinks the angles at u and w, so
// the non-convex set only shrinks, and only u and w can change ear status: another ear keeps
// its triangle and loses candidates; another non-ear's triangle held a vertex other than the
// (convex) clipped v, by the sweep argument, and that vertex stays. So ear flags are cached.
// Every decision is an exact orientation (predicates::orient2d's static filter inlined, then the
// exact predicate where it cannot decide) or an exact comparison of input
// coordinates (bounding-box rejection). Among the ears the one with the shortest diagonal is
// clipped (a float key that only orders valid choices): fatter triangles than the first ear
// found make the no-fit-polygon build that uses them slightly cheaper (docs/benchmarks.md).
// Cost: N + 2(N - 3) ear tests of O(r) orient2d each for r non-convex vertices, plus an O(N)
// scan per clip: O(N^2) worst case. kEarMax = 32: there ear clipping still clearly beats the CDT
// even on its worst inputs (combs: long collinear runs in wide ears), and the margin shrinks as N
// grows (comparison in docs/benchmarks.md).
//
// CDT: Epick's predicates are exact; the only constructions a CDT needs are intersections of
// crossing constraints, which cannot occur because Polygon's validation guarantees the rings are
// simple and pairwise disjoint (the intersection tag below makes CGAL throw instead of
// constructing, should that invariant ever break). A face is inside P iff crossing constraint
// edges from the infinite face reaches it an odd number of times (nesting depth; CGAL's "mark
// domains" idea). O(N log N).
#include "polygon2/triangulation.hpp"

#include "geometry/exact.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>
#include <utility>

namespace pendepth::polygon2 {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
struct FaceInfo {
  int depth = -1;
};
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;

static_assert(kEarMax <= 255, "ring links are stored in bytes");

// predicates::orient2d with its static filter inlined (on these tiny polygons the call and the
// generic filter cost more than the arithmetic); what the filter cannot decide goes to the exact
// predicate, so every sign is the exact one.
inline int orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double p1 = (b.x() - a.x()) * (c.y() - a.y()), p2 = (b.y() - a.y()) * (c.x() - a.x());
  const double d = p1 - p2, bound = exact::kCrossBound * (std::abs(p1) + std::abs(p2)) + exact::kTiny;
  if (d > bound) return 1;
  if (d < -bound) return -1;
  return predicates::orient2d(a, b, c);
}

// Ear clipping of the hole-free P (size <= kEarMax) into `out`; false if no ear is left.
bool ear_clip(const Polygon& P, std::vector<TriangleIds>& out) {
  const auto V = P.vertices();
  const unsigned n = static_cast<unsigned>(P.size());
  std::array<std::uint8_t, kEarMax> prv, nxt, reflex;  // reflex: the non-convex vertices of the ring
  std::array<bool, kEarMax> convex;
  unsigned nr = 0;
  for (unsigned i = 0; i < n; ++i) {
    prv[i] = static_cast<std::uint8_t>(i == 0 ? n - 1 : i - 1);
    nxt[i] = static_cast<std::uint8_t>(i + 1 == n ? 0 : i + 1);
  }
  for (unsigned i = 0; i < n; ++i) {
    convex[i] = orient(V[prv[i]], V[i], V[nxt[i]]) > 0;
    if (!convex[i]) reflex[nr++] = static_cast<std::uint8_t>(i);
  }
  auto is_ear = [&](unsigned v) {
    if (!convex[v]) return false;
    const Vec2 &u = V[prv[v]], &a = V[v], &w = V[nxt[v]];
    const Vec2 lo = u.cwiseMin(a).cwiseMin(w), hi = u.cwiseMax(a).cwiseMax(w);  // exact: no rounding
    for (unsigned k = 0; k < nr; ++k) {
      const unsigned x = reflex[k];
      const Vec2& p = V[x];
      if (p.x() < lo.x() || p.x() > hi.x() || p.y() < lo.y() || p.y() > hi.y() || x == prv[v] || x == nxt[v]) continue;
      if (orient(u, a, p) >= 0 && orient(a, w, p) >= 0 && orient(w, u, p) >= 0) return false;
    }
    return true;
  };
  // After a clip the angle at i only shrank: a non-convex vertex may have become convex.
  auto refresh = [&](unsigned i) {
    if (convex[i] || orient(V[prv[i]], V[i], V[nxt[i]]) <= 0) return;
    convex[i] = true;
    for (unsigned k = 0; k < nr; ++k)
      if (reflex[k] == i) {
        reflex[k] = reflex[--nr];
        break;
      }
  };
  // Greedy: clip the ear with the shortest diagonal (fatter triangles than the first ear found:
  // fewer overlapping boxes downstream). The float key only orders valid ears.
  std::array<bool, kEarMax> ear;
  std::array<double, kEarMax> key;
  auto update = [&](unsigned v) {
    ear[v] = is_ear(v);
    if (ear[v]) key[v] = (V[nxt[v]] - V[prv[v]]).squaredNorm();
  };
  for (unsigned i = 0; i < n; ++i) update(i);
  unsigned first = 0;
  for (unsigned left = n; left > 3; --left) {
    unsigned best = kEarMax;
    for (unsigned k = 0, v = first; k < left; ++k, v = nxt[v])
      if (ear[v] && (best == kEarMax || key[v] < key[best])) best = v;
    if (best == kEarMax) return false;
    const unsigned u = prv[best], w = nxt[best];
    out.push_back({u, best, w});
    nxt[u] = static_cast<std::uint8_t>(w);
    prv[w] = static_cast<std::uint8_t>(u);
    first = w;
    refresh(u);
    refresh(w);
    update(u);
    update(w);
  }
  const unsigned u = prv[first], w = nxt[first];
  if (orient(V[u], V[first], V[w]) <= 0) return false;
  out.push_back({u, first, w});
  return true;
}

std::vector<TriangleIds> cdt_triangulate(const Polygon& P) {
  Cdt cdt;
  // Vertices in CGAL's spatial order (a deterministic shuffle, then Hilbert-sorted rounds: the
  // biased randomized insertion order), each located from the previous one. In ring order the
  // Delaunay insertions of a finely sampled curve (a spiral's arms) flip Θ(N) edges each: the
  // spiral of 10⁵ vertices spent about half of its 7 s build here, a few percent in this order
  // (perf; docs/benchmarks.md). It costs combs (long collinear runs) some time instead.
  std::vector<K::Point_2> pts;
  pts.reserve(P.size());
  for (const Vec2& p : P.vertices()) pts.emplace_back(p.x(), p.y());
  std::vector<std::size_t> order(P.size());  // the property map's key type
  for (std::size_t g = 0; g < order.size(); ++g) order[g] = g;
  CGAL::spatial_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_2<K, CGAL::Pointer_property_map<K::Point_2>::type>(
                         CGAL::make_property_map(pts)));
  std::vector<Cdt::Vertex_handle> vh(P.size());
  Cdt::Face_handle hint;
  for (const std::size_t g : order) {
    vh[g] = cdt.insert(pts[g], hint);
    vh[g]->info() = static_cast<std::uint32_t>(g);
    hint = vh[g]->face();
  }
  for (std::size_t g = 0; g < P.size(); ++g) cdt.insert_constraint(vh[g], vh[P.next(g)]);

  // Breadth-first over faces; crossing a constrained edge increases the depth by one.
  std::deque<std::pair<Cdt::Face_handle, int>> frontier{{cdt.infinite_face(), 0}};
  while (!frontier.empty()) {
    auto [f0, depth] = frontier.front();
    frontier.pop_front();
    if (f0->info().depth != -1) continue;
    std::deque<Cdt::Face_handle> queue{f0};
    f0->info().depth = depth;
    while (!queue.empty()) {
      Cdt::Face_handle f = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle n = f->neighbor(i);
        if (n->info().depth != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          frontier.emplace_back(n, depth + 1);
        } else {
          n->info().depth = depth;
          queue.push_back(n);
        }
      }
    }
  }

  std::vector<TriangleIds> out;
  out.reserve(cdt.number_of_faces());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info().depth % 2 == 1)
      out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return out;
}

}  // namespace

void triangulate(const Polygon& P, std::vector<TriangleIds>& out, TriangulationPath* path) {
  TriangulationPath used = TriangulationPath::cdt;
  out.clear();
  if (P.hole_count() == 0 && P.size() <= kEarMax) {
    out.reserve(P.size() - 2);
    used = TriangulationPath::ear_clipping;
    if (!ear_clip(P, out)) used = TriangulationPath::cdt_fallback;
  }
  if (used != TriangulationPath::ear_clipping) out = cdt_triangulate(P);
  if (path) *path = used;
}

std::vector<TriangleIds> triangulate(const Polygon& P, TriangulationPath* path) {
  std::vector<TriangleIds> out;
  triangulate(P, out, path);
  return out;
}

}  // namespace pendepth::polygon2
