// Triangulation of a polygon with holes (DHS §4.1 Step 1): CGAL's constrained Delaunay
// triangulation with the Epick kernel. Epick's predicates are exact; the only constructions a
// CDT needs are intersections of crossing constraints, which cannot occur because Polygon's
// validation guarantees the rings are simple and pairwise disjoint (the intersection tag below
// makes CGAL throw instead of constructing, should that invariant ever break).
// A face is inside P iff crossing constraint edges from the infinite face reaches it an odd
// number of times (nesting depth; CGAL's "mark domains" idea). O(N log N).
#include "polygon2/triangulation.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
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

}  // namespace

std::vector<TriangleIds> triangulate(const Polygon& P) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> vh(P.size());
  for (std::size_t g = 0; g < P.size(); ++g) {
    const Vec2& p = P.vertices()[g];
    vh[g] = cdt.insert(K::Point_2(p.x(), p.y()));
    vh[g]->info() = static_cast<std::uint32_t>(g);
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

}  // namespace pendepth::polygon2
