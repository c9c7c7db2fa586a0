// σ(t) = dist(t, ∂O) for t ∈ O: the shortest translation of Q separating it from P (DHS §4.2,
// Lemma 4.3 computes it from the visibility polygon of t within the disk of radius σ_d).
//
// Departure from DHS: branch-and-bound over the bounding-volume hierarchy of the union-boundary
// pieces (nearest boxes first, pruned by the best distance so far; inside an arc by B-edge
// ranges whose boxes come in O(1) from B's extreme vertices). Each candidate is the foot of t on
// an element, an explicit convolution vertex p + b, or a union vertex (two lines crossing); the
// choice among them is exact (squared distances compared as rational functions of the input
// doubles), the distance is evaluated to a few ulps. Worst case O(n·m) element visits; on the
// shapes measured the hierarchy touches O(log n) pieces.
// Result: the nearest point x; translation x − t; normal = the outward normal of ∂O there (the
// normal of the element pointing away from t for a foot — right-hand, except on a slit where t
// may lie on either side — and (x − t)/|x − t| at a vertex); features: a vertex
// of Q against an edge of P (foot on a segment), a vertex of P against an edge of Q (foot on an
// arc), two vertices (convolution vertex), or at a union vertex the features of the first line.
#include <cmath>

#include "geometry/exact.hpp"
#include "polygon2/query_impl.hpp"

namespace pendepth {

Depth2 PolygonDepth2::minimum(const Vec2& t) const {
  if (!std::isfinite(t.x()) || !std::isfinite(t.y())) throw InvalidInput("placement t has a non-finite coordinate");
  const Impl& S = *impl_;
  Depth2 r;
  r.kind = DepthKind::Minimum;
  polygon2::Near n;
  if (!S.U.in_overlap(t) || !S.U.nearest(t, n)) return r;
  r.overlapping = true;
  r.depth = polygon2::near_distance(n, t);
  const polygon2::Cut& E = n.cut;
  Vec2 dir;
  if (n.kind == polygon2::Near::Kind::Foot) {
    // Outward normal: O lies left of the element, so it is the right-hand normal of e1 − e0.
    const double dx = exact::accurate_value([&](auto L) { return L(E.e1.x()) - L(E.e0.x()); });
    const double dy = exact::accurate_value([&](auto L) { return L(E.e1.y()) - L(E.e0.y()); });
    // On a slit O lies on both sides: point from t towards the element.
    const int side = exact::exact_sign([&](auto L) {
      return (L(E.e1.x()) - L(E.e0.x())) * (L(t.y()) - L(E.pt.y()) - L(E.pb.y())) -
             (L(E.e1.y()) - L(E.e0.y())) * (L(t.x()) - L(E.pt.x()) - L(E.pb.x()));
    });
    dir = side >= 0 ? Vec2(dy, -dx) : Vec2(-dy, dx);
  } else {
    const Vec2 x = polygon2::near_point(n);
    // x − t accurately: the rounded point minus t loses at most one more rounding per coordinate.
    dir = x - t;
    if (dir.x() == 0 && dir.y() == 0) dir = Vec2(1, 0);
  }
  r.normal = dir / dir.norm();
  r.translation = r.depth * r.normal;
  const Vec2 x = t + r.translation;
  const auto& V = S.P.vertices();
  auto q_vertex_on_p = [&](std::size_t q, std::uint32_t p_from, std::uint32_t p_to) {
    r.feature_q = {FeatureKind::Vertex, int(q)};
    r.feature_p = S.P.next(p_from) == p_to ? Feature{FeatureKind::Edge, int(p_from)} : Feature{FeatureKind::Vertex, int(p_from)};
    r.witness_q = r.witness_p = S.Q[q] + x;
  };
  switch (n.kind) {
    case polygon2::Near::Kind::Point:
      r.feature_p = {FeatureKind::Vertex, int(n.p_index)};
      r.feature_q = {FeatureKind::Vertex, int(S.R.q_index(n.b_index))};
      r.witness_p = r.witness_q = V[n.p_index];
      break;
    default:
      if (E.b_edge) {  // a vertex of P against an edge of Q
        r.feature_p = {FeatureKind::Vertex, int(E.p_from)};
        r.feature_q = {FeatureKind::Edge, int(S.R.q_index(E.b))};
        r.witness_p = r.witness_q = V[E.p_from];
      } else {
        q_vertex_on_p(S.R.q_index(E.b), E.p_from, E.p_to);
      }
      break;
  }
  // A zero component can come out as −0 (0 times a negative factor); report it as +0.
  for (int c = 0; c < 2; ++c) {
    if (r.normal[c] == 0) r.normal[c] = 0.0;
    if (r.translation[c] == 0) r.translation[c] = 0.0;
  }
  return r;
}

}  // namespace pendepth
