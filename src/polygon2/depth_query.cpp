// PolygonDepth2: construction (DHS §4.1 Steps 1-2), the exact overlap test, and the result
// builder shared by the ray queries.
#include <cmath>

#include "geometry/exact.hpp"
#include "polygon2/query_impl.hpp"

namespace pendepth {

namespace {
void require_finite(const Vec2& v, const char* what) {
  if (!std::isfinite(v.x()) || !std::isfinite(v.y())) throw InvalidInput(std::string(what) + " has a non-finite coordinate");
}
}  // namespace

PolygonDepth2::PolygonDepth2(const Polygon& P, const ConvexPolygon& Q) : impl_(std::make_unique<Impl>(P, Q)) {}
PolygonDepth2::PolygonDepth2(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PolygonDepth2 polygon_depth_from_impl(std::unique_ptr<PolygonDepth2::Impl> impl) { return PolygonDepth2(std::move(impl)); }
const PolygonDepth2::Impl& polygon_depth_impl(const PolygonDepth2& pd) { return *pd.impl_; }
PolygonDepth2::~PolygonDepth2() = default;
PolygonDepth2::PolygonDepth2(PolygonDepth2&&) noexcept = default;
PolygonDepth2& PolygonDepth2::operator=(PolygonDepth2&&) noexcept = default;

std::size_t PolygonDepth2::triangle_count() const { return impl_->R.size(); }

bool PolygonDepth2::overlapping(const Vec2& t) const {
  require_finite(t, "placement t");
  return impl_->U.in_overlap(t);
}

PolygonDepth2::BoundaryStats PolygonDepth2::boundary_stats() const {
  const polygon2::UnionBoundary& U = impl_->U;
  BoundaryStats s;
  s.rings = U.rings().size();
  s.vertices = U.vertex_count();
  s.segments = U.segment_count();
  s.arcs = U.arc_count();
  s.bytes = U.bytes() + impl_->R.bytes();  // the queries also read the triangles and B
  return s;
}

std::vector<std::vector<Vec2>> PolygonDepth2::boundary_rings() const {
  const polygon2::UnionBoundary& U = impl_->U;
  std::vector<std::vector<Vec2>> out;
  for (const polygon2::Ring& rg : U.rings()) {
    std::vector<Vec2> ring;
    for (std::uint32_t q = 0; q < rg.count; ++q) {
      const std::size_t k = rg.first + q;
      ring.push_back(U.start_point(k));
      for (std::size_t j = 1; j < U.element_count(k); ++j) {
        const polygon2::Cut E = U.element(k, j);
        ring.push_back(E.pt + E.pb);
      }
    }
    out.push_back(std::move(ring));
  }
  return out;
}

namespace polygon2 {

Vec2 check_and_scale(const Vec2& t, const Vec2& d) {
  require_finite(t, "placement t");
  require_finite(d, "direction d");
  if (d.x() == 0 && d.y() == 0) throw InvalidInput("direction d is the zero vector");
  const int e = std::ilogb(std::max(std::abs(d.x()), std::abs(d.y())));
  return Vec2(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
}

Depth2 result_at_cut(const PolygonDepth2::Impl& S, const Cut& c, const Vec2& t, const Vec2& d) {
  Depth2 r;
  const double dn = std::sqrt(exact::accurate_value([&](auto L) { return L(d.x()) * L(d.x()) + L(d.y()) * L(d.y()); }));
  r.depth = std::max(0.0, cut_value(c, t, d) * dn);
  r.normal = d / dn;
  r.translation = r.depth * r.normal;
  const Vec2 x = t + r.translation;
  const std::size_t q = S.R.q_index(c.b);
  if (c.b_edge) {  // a vertex of P against the edge q of Q (−(B edge b))
    r.feature_p = {FeatureKind::Vertex, int(c.p_from)};
    r.feature_q = {FeatureKind::Edge, int(q)};
    r.witness_p = r.witness_q = c.pt;
  } else {  // vertex q of Q against a triangle edge
    r.feature_q = {FeatureKind::Vertex, int(q)};
    if (S.P.next(c.p_from) == c.p_to) {
      r.feature_p = {FeatureKind::Edge, int(c.p_from)};
    } else {
      // A diagonal: the contact lies on ∂M, so Q's vertex touches the diagonal at an endpoint;
      // the endpoint is the one whose translate by b lies on the ray's line (exact).
      const int on = exact::exact_sign([&](auto L) {
        return L(d.x()) * (L(c.e0.y()) + L(c.pb.y()) - L(t.y())) - L(d.y()) * (L(c.e0.x()) + L(c.pb.x()) - L(t.x()));
      });
      r.feature_p = {FeatureKind::Vertex, int(on == 0 ? c.p_from : c.p_to)};
    }
    r.witness_q = r.witness_p = S.Q[q] + x;
  }
  return r;
}

Depth2 result_at_hit(const PolygonDepth2::Impl& S, const Hit& h, const Vec2& t, const Vec2& d) {
  if (!h.is_point) return result_at_cut(S, h.cut, t, d);
  Depth2 r;
  const double dn = std::sqrt(exact::accurate_value([&](auto L) { return L(d.x()) * L(d.x()) + L(d.y()) * L(d.y()); }));
  r.depth = std::max(0.0, hit_value(h, t, d) * dn);
  r.normal = d / dn;
  r.translation = r.depth * r.normal;
  r.feature_p = {FeatureKind::Vertex, int(h.p_index)};
  r.feature_q = {FeatureKind::Vertex, int(S.R.q_index(h.b_index))};
  r.witness_p = r.witness_q = h.p;
  return r;
}

}  // namespace polygon2
}  // namespace pendepth
