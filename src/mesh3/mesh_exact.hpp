// Private: the exact (CGAL Epeck) tools the segment and flat-polygon paths share on a non-convex
// mesh's own triangles (mesh_segment.cpp defines the functions; mesh_flat.cpp uses them too).
// Every decision here is exact on the rational placed points; the box tree only prunes.
#pragma once

#include "mesh3/mesh_mixed.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pendepth::mesh3 {

// The mesh's triangles as exact points, built once per pair (CGAL's lazy points from doubles:
// their exact values are computed on demand under a once-flag, safe to share between threads).
struct SegmentTriangles {
  std::vector<std::array<CGAL::Epeck::Point_3, 3>> T;
};

namespace exact3 {

using K = CGAL::Epeck;
using FT = K::FT;
using P3 = K::Point_3;
using V3 = K::Vector_3;

/// R p + tq − tp, exactly (the placed point in the mesh's frame).
P3 place(const Eigen::Matrix3d& R, const Vec3& p, const Vec3& tq, const Vec3& tp);
/// The double nearest to x (ties to even).
double dbl(const FT& x);
inline Vec3 approx(const P3& p) { return Vec3(dbl(p.x()), dbl(p.y()), dbl(p.z())); }
inline const std::array<P3, 3>& tp3(const MixedPair& m, std::size_t t) { return m.seg_tri->T[t]; }
inline K::Triangle_3 tri(const MixedPair& m, std::size_t t) { return {tp3(m, t)[0], tp3(m, t)[1], tp3(m, t)[2]}; }

// A margin far above the rounding of approx() (exact value to double: 1 ulp) for box tests.
inline double margin(const Vec3& c, double h) { return 0x1p-30 * (c.norm() + h) + 0x1p-1000; }

/// Visits the triangles whose box meets the box [c − h, c + h] (componentwise, grown by a margin).
template <class F>
void near_box(const MixedPair& m, const Vec3& c, double h, F&& visit) {
  if (m.linear) {
    for (std::size_t t = 0; t < m.tri.size(); ++t) visit(t);
  } else {
    m.tree.near_point(c, h + margin(c, h), [&](std::uint32_t t) { visit(t); });
  }
}
/// Visits the triangles whose box, grown by h (and a margin), the ray c + μ d (μ >= 0) meets.
template <class F>
void along_ray(const MixedPair& m, const Vec3& c, double h, const Vec3& d, F&& visit) {
  if (m.linear) {
    for (std::size_t t = 0; t < m.tri.size(); ++t) visit(t);
  } else {
    m.tree.along_ray(c, d, h + margin(c, h), [&](std::uint32_t t) { visit(t); });
  }
}

// CGAL 5's intersection results are boost::variant (std::variant from CGAL 6 on).
/// Adds the points of an exact intersection result (a point, or a segment's two ends).
template <class R, class F>
void points_of(const R& r, F&& add) {
  if (!r) return;
  if (const P3* p = boost::get<P3>(&*r)) add(*p);
  else if (const K::Segment_3* s = boost::get<K::Segment_3>(&*r)) add(s->source()), add(s->target());
}

/// X ∈ int P (on no triangle, odd exact ray parity).
bool inside(const MixedPair& m, const P3& X);
/// [A, B] ∩ int P ≠ ∅.
bool seg_overlap(const MixedPair& m, const P3& A, const P3& B);

}  // namespace exact3
}  // namespace pendepth::mesh3
