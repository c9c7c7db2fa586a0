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
#include <stdexcept>
#include <string>
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

/// A crossing of the ray μ·d' with a polygon of the ∂O superset: its exact parameter and the
/// polygon's normal (mesh frame).
struct Cand {
  FT mu;
  Vec3 normal;
};

/// Adds to `out` the crossings of the ray from + μ·dv (μ >= 0; dd = |dv|²) with the closed triangle
/// p, q, r (none when it is degenerate): μ = (X − from)·dv / dd, exact, for the intersection point X
/// (both ends of a coplanar overlap), each with the triangle's normal from the rounded points.
inline void ray_crossings(const P3& from, const V3& dv, const FT& dd, const P3& p, const P3& q, const P3& r,
                          std::vector<Cand>& out) {
  if (CGAL::collinear(p, q, r)) return;
  const K::Triangle_3 T(p, q, r);
  const K::Ray_3 ray(from, dv);
  if (!CGAL::do_intersect(ray, T)) return;
  const Vec3 n = (approx(q) - approx(p)).cross(approx(r) - approx(p));
  points_of(CGAL::intersection(ray, T), [&](const P3& X) { out.push_back({((X - from) * dv) / dd, n}); });
}

/// Over the sorted candidates `c`: σ_d's exit = the first candidate where the moved shape is not in
/// O (`in_o(μ)`; each candidate found in O carries the open stretch after it into O, equal
/// candidates tested once), or a separation's = the end of the last stretch whose midpoint is in O
/// (null: never in O). `what` names the engine in the logic error (O is bounded: σ_d always exits).
template <class InO>
const Cand* exit_candidate(const std::vector<Cand>& c, bool separation, InO&& in_o, const char* what) {
  if (!separation) {
    FT last(0);
    for (const Cand& k : c) {
      if (!(k.mu > last)) continue;
      if (!in_o(k.mu)) return &k;
      last = k.mu;
    }
    throw std::logic_error(std::string(what) + " σ_d: the ray does not leave O (O is bounded)");
  }
  const Cand* pick = nullptr;
  FT prev(0);
  for (const Cand& k : c) {
    if (!(k.mu > prev)) continue;
    if (in_o((prev + k.mu) / 2)) pick = &k;
    prev = k.mu;
  }
  return pick;
}

/// Fills `r` with the move to candidate `k` along the world direction `d` (`d_mesh` the ray's
/// direction in the mesh's frame Rm, tm): RN(μ)·|d_mesh|, the polygon's normal facing d, and the
/// witness at the shape's first point `first` (mesh frame) moved there.
inline void exit_answer(Depth3& r, const Cand& k, const Vec3& d, const Vec3& d_mesh, const Eigen::Matrix3d& Rm,
                        const Vec3& tm, const Vec3& first) {
  const Vec3 u = d.normalized();
  const double s = dbl(k.mu) * d_mesh.norm();
  r.depth = r.lower_bound = r.upper_bound = s;
  r.translation = s * u;
  r.normal = u;
  Vec3 n = (Rm * k.normal).normalized();
  if (n.dot(u) < 0) n = -n;
  r.facet_normal = n.allFinite() ? n : u;
  r.witness_p = r.witness_q = Rm * (first + dbl(k.mu) * d_mesh) + tm;
}

}  // namespace exact3
}  // namespace pendepth::mesh3
