// σ_d on the implicit union boundary ∂O (DHS §4.2 and the fast path of §4.3).
//
// For t ∈ O (O = ∪ int R_i open), σ_d(t) is the first λ > 0 with t + λ·d̂ ∈ ∂O: the points of the
// ray before it are in O, and ∂O ∩ O = ∅, so the first boundary point is exactly where the ray
// leaves O (touching a union vertex or an isolated boundary point ends it too).
//   along_scan(): visits every piece of ∂O, O(|∂O| log m) = O(n log m) (DHS §4.2).
//   along():      branch-and-bound ray shooting in a bounding-volume hierarchy over the piece
//                 boxes, nearest boxes first, pruned by the best hit so far; arcs are located by
//                 binary search on B (O(log m)). Departure from DHS §4.3 (ears + partition trees):
//                 the hierarchy is simpler and its measured query time grows sublinearly in n
//                 (docs/benchmarks.md); the worst case stays O(n log m). t ∈ O is decided from the
//                 first hit h itself, as the fixed directions do (§6): the segment (t, h) misses
//                 ∂O, so it lies in O or outside closure(O); at a point interior to one piece O
//                 is on the piece's left only, so t ∈ O iff the ray crosses the piece from left to
//                 right (cross(d, e) > 0, exact) and t ∉ ∂O (exact, piece boxes containing t). Where
//                 that local test is ambiguous — h at a vertex of its element or piece, or along
//                 an element, a second piece through h (union vertex, slit), a degenerate
//                 ring, t on ∂O — t ∈ O is decided by in_overlap (hierarchy over the R_i), as
//                 before. Either way the answer and the hit are the same.
#include "geometry/exact.hpp"
#include "polygon2/query_impl.hpp"

namespace pendepth {

namespace {
using polygon2::Cut;
using polygon2::EndPoint;

// Exact: the point of `e` (an end of a piece, lying on `el`'s line) is on the line t + λ·d.
bool on_ray_line(const EndPoint& e, const Cut& el, const Vec2& t, const Vec2& d) {
  auto X = [&](auto L, const Vec2& a, const Vec2& b) {  // cross(d, a + b − t)
    return L(d.x()) * (L(a.y()) + L(b.y()) - L(t.y())) - L(d.y()) * (L(a.x()) + L(b.x()) - L(t.x()));
  };
  auto Xe = [&](auto L) { return L(d.x()) * (L(el.e1.y()) - L(el.e0.y())) - L(d.y()) * (L(el.e1.x()) - L(el.e0.x())); };
  switch (e.kind) {
    case EndPoint::Kind::Mu0: return exact::exact_sign([&](auto L) { return X(L, el.pt, el.pb); }) == 0;
    case EndPoint::Kind::Mu1: return exact::exact_sign([&](auto L) { return X(L, el.pt, el.pb) + Xe(L); }) == 0;
    case EndPoint::Kind::Point: return exact::exact_sign([&](auto L) { return X(L, e.p, e.b); }) == 0;
    case EndPoint::Kind::Crossing:
    default: {
      // el's line A + μ·(e1 − e0) meets other's at μ = N / D (D ≠ 0): cross(d, X − t)·D = 0.
      const Cut& o = e.other;
      return exact::exact_sign([&](auto L) {
               const auto ex = L(el.e1.x()) - L(el.e0.x()), ey = L(el.e1.y()) - L(el.e0.y());
               const auto fx = L(o.e1.x()) - L(o.e0.x()), fy = L(o.e1.y()) - L(o.e0.y());
               const auto wx = L(o.pt.x()) + L(o.pb.x()) - L(el.pt.x()) - L(el.pb.x());
               const auto wy = L(o.pt.y()) + L(o.pb.y()) - L(el.pt.y()) - L(el.pb.y());
               return X(L, el.pt, el.pb) * (ex * fy - ey * fx) + (wx * fy - wy * fx) * Xe(L);
             }) == 0;
    }
  }
}

// Exact: the non-point hit h (a transversal crossing of h.cut) is a vertex of its element or an
// end of its piece — the places where the piece's orientation alone does not tell the side of O.
bool at_vertex(const polygon2::UnionBoundary& U, const polygon2::Hit& h, const Vec2& t, const Vec2& d) {
  EndPoint nat;
  nat.kind = EndPoint::Kind::Mu0;
  if (on_ray_line(nat, h.cut, t, d)) return true;
  nat.kind = EndPoint::Kind::Mu1;
  if (on_ray_line(nat, h.cut, t, d)) return true;
  const polygon2::Piece& pc = U.pieces()[h.piece];
  return on_ray_line(pc.start, U.element(h.piece, 0), t, d) ||
         on_ray_line(pc.end, U.element(h.piece, U.element_count(h.piece) - 1), t, d);
}

Depth2 along_with(const PolygonDepth2::Impl& S, const Vec2& t, const Vec2& d_in, bool scan) {
  const Vec2 d = polygon2::check_and_scale(t, d_in);
  Depth2 r;
  r.kind = DepthKind::Directional;
  polygon2::Hit h;
  if (scan) {
    if (!S.U.in_overlap(t) || !S.U.ray_first_scan(t, d, h)) return r;
  } else {
    bool tie = false;
    if (!S.U.ray_first(t, d, h, &tie)) return r;  // O is bounded: the ray of a t ∈ O meets ∂O
    const polygon2::Ring& ring = S.U.rings()[S.U.pieces()[h.piece].ring];
    int leaves = 0;  // 0: ambiguous
    if (!h.is_point && !tie && ring.count > 1 && ring.area_sign != 0 && !at_vertex(S.U, h, t, d))
      leaves = exact::exact_sign([&](auto L) {
        return L(d.x()) * (L(h.cut.e1.y()) - L(h.cut.e0.y())) - L(d.y()) * (L(h.cut.e1.x()) - L(h.cut.e0.x()));
      });
    if (leaves < 0) return r;  // enters O at h: (t, h) lies outside closure(O)
    if (leaves == 0 || S.U.on_boundary(t)) {
      if (!S.U.in_overlap(t)) return r;
    }
  }
  r = polygon2::result_at_hit(S, h, t, d);
  r.kind = DepthKind::Directional;
  r.overlapping = true;
  return r;
}
}  // namespace

Depth2 PolygonDepth2::along(const Vec2& t, const Vec2& d) const { return along_with(*impl_, t, d, false); }
Depth2 polygon2::along_scan(const PolygonDepth2& pd, const Vec2& t, const Vec2& d) {
  return along_with(polygon_depth_impl(pd), t, d, true);
}

}  // namespace pendepth
