// PairDepth2: construction (triangulate both shapes, normal-form triangles of P and of −Q, box
// hierarchies), the exact overlap test, and the contact-result builder shared by the queries.
// Construction O(n log n + m log m); overlapping(t) visits the pairs whose sum box holds t (worst
// case O(nm), a handful on real pieces).
#include <bit>
#include <cmath>
#include <cstdint>

#include "geometry/exact.hpp"
#include "geometry/isa.hpp"
#include "nonconvex2/boundary_distance.hpp"
#include "nonconvex2/pair_sums.hpp"
#include "nonconvex2/query.hpp"
#include "nonconvex2/shape_side.hpp"
#include "polygon2/triangulation.hpp"

namespace pendepth {

namespace {

void require_finite(const Vec2& v, const char* what) {
  if (!std::isfinite(v.x()) || !std::isfinite(v.y())) throw InvalidInput(std::string(what) + " has a non-finite coordinate");
}

// Triangles of `shape` in normal form into `out`; `negate` stores −shape (for Q), keeping Q's
// vertex ids.
void normal_triangles(const Polygon& shape, bool negate, std::vector<nonconvex2::Tri>& out) {
  const auto V = shape.vertices();
  // The triangulation's id triples, kept by the thread (once per shape and role, shape_side.hpp;
  // engine-level pairs without a cache run it twice per pair).
  thread_local std::vector<polygon2::TriangleIds> tris;
  polygon2::triangulate(shape, tris);
  out.resize(tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const auto& ids = tris[t];
    std::array<Vec2, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = negate ? Vec2(-V[ids[k]]) : V[ids[k]];  // −x is exact; −U stays CCW
    int low = 0;
    for (int k = 1; k < 3; ++k)
      if (v[k].y() < v[low].y() || (v[k].y() == v[low].y() && v[k].x() < v[low].x())) low = k;
    nonconvex2::Tri& T = out[t];
    for (int k = 0, i = low; k < 3; ++k, i = i == 2 ? 0 : i + 1) {
      T.v[k] = v[i];
      T.id[k] = ids[i];
    }
    T.lo = T.v[0].cwiseMin(T.v[1]).cwiseMin(T.v[2]);
    T.hi = T.v[0].cwiseMax(T.v[1]).cwiseMax(T.v[2]);
  }
  if (tris.capacity() > (std::size_t(1) << 12)) tris = {};  // large shapes do not pin their memory
}

}  // namespace

namespace nonconvex2 {

ShapeSide::ShapeSide(const Polygon& s, bool negate) : shape(s), negated(negate) {
  normal_triangles(shape, negate, tris);
  tree.build(tris);
}

const ConvexParts& ShapeSide::parts() const {
  std::call_once(parts_once_, [&] { convex_parts(tris, shape.hole_count() == 0, parts_); });
  return parts_;
}

std::shared_ptr<const ShapeSide> make_side(const Polygon& shape, bool negate) { return std::make_shared<const ShapeSide>(shape, negate); }

const std::vector<polygon2::TriangleIds>& ShapeCache::triangles(const Polygon& shape) const {
  std::call_once(tri_once_, [&] {
    const auto s = side(shape, false);
    tri_.reserve(s->tris.size());
    for (const Tri& T : s->tris) tri_.push_back(T.id);
  });
  return tri_;
}

std::shared_ptr<const BoxTree> ShapeCache::edge_tree(const Polygon& shape) const {
  std::call_once(edge_once_, [&] { edge_ = BoundaryPair2::edge_tree(shape); });
  return edge_;
}

}  // namespace nonconvex2

PairDepth2::Impl::Impl(const Polygon& p, const Polygon& q) : Impl(nonconvex2::make_side(p, false), nonconvex2::make_side(q, true)) {}

PairDepth2::Impl::Impl(std::shared_ptr<const nonconvex2::ShapeSide> p, std::shared_ptr<const nonconvex2::ShapeSide> q)
    : sp(std::move(p)), sb(std::move(q)), P(sp->shape), Q(sb->shape), tp(sp->tris), tb(sb->tris), hp(sp->tree), hb(sb->tree) {}

PairDepth2::PairDepth2(const Polygon& P, const Polygon& Q) : impl_(std::make_unique<Impl>(P, Q)) {}
PairDepth2::PairDepth2(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PairDepth2 pair_from_impl(std::unique_ptr<PairDepth2::Impl> impl) { return PairDepth2(std::move(impl)); }
PairDepth2::~PairDepth2() = default;
PairDepth2::PairDepth2(PairDepth2&&) noexcept = default;
PairDepth2& PairDepth2::operator=(PairDepth2&&) noexcept = default;

std::size_t PairDepth2::triangle_count_p() const { return impl_->tp.size(); }
std::size_t PairDepth2::triangle_count_q() const { return impl_->tb.size(); }

bool PairDepth2::overlapping(const Vec2& t, PairQueryStats* stats) const {
  require_finite(t, "placement t");
  return impl_->descend(
      [&](const Vec2& lo, const Vec2& hi) { return lo.x() <= t.x() && t.x() <= hi.x() && lo.y() <= t.y() && t.y() <= hi.y(); },
      [&](std::uint32_t i, std::uint32_t j) { return nonconvex2::sum_contains(nonconvex2::make_sum(impl_->tp[i], impl_->tb[j]), t); },
      stats);
}

Depth2 PairDepth2::Impl::contact(const nonconvex2::Line& E, const Vec2& t, const Vec2& translation, int end) const {
  Depth2 r = contact_features(E, t, translation, end);
  r.depth = std::hypot(translation.x(), translation.y());
  if (r.depth > 0) r.normal = translation / r.depth;
  return r;
}

Depth2 PairDepth2::Impl::contact_features(const nonconvex2::Line& E, const Vec2& t, const Vec2& translation, int end) const {
  Depth2 r;
  r.translation = translation;
  if (!E.q_edge) {
    // Vertex q0 of Q against the triangle edge p0 → p1 of P: an edge of P, or (a diagonal) the
    // contact is at one of its ends — an interior point of a diagonal is interior to P.
    const bool boundary = P.next(E.p0) == E.p1;
    r.feature_p = boundary ? Feature{FeatureKind::Edge, int(E.p0)} : Feature{FeatureKind::Vertex, int(end == 1 ? E.p1 : E.p0)};
    r.feature_q = {FeatureKind::Vertex, int(E.q0)};
    r.witness_q = r.witness_p = Q.vertices()[E.q0] + t + translation;
    if (!boundary) r.witness_p = P.vertices()[r.feature_p.index];
  } else {
    // Vertex p0 of P against Q's triangle edge q0 → q1 (same reasoning for diagonals of Q).
    const bool boundary = Q.next(E.q0) == E.q1;
    r.feature_q = boundary ? Feature{FeatureKind::Edge, int(E.q0)} : Feature{FeatureKind::Vertex, int(end == 1 ? E.q1 : E.q0)};
    r.feature_p = {FeatureKind::Vertex, int(E.p0)};
    r.witness_p = r.witness_q = P.vertices()[E.p0];
  }
  return r;
}

namespace nonconvex2 {

Vec2 check_and_scale(const Vec2& t, const Vec2& d) {
  require_finite(t, "placement t");
  require_finite(d, "direction d");
  if (d.x() == 0 && d.y() == 0) throw InvalidInput("direction d is the zero vector");
  // d·2⁻ᵉ with e the exponent of the larger component (so that one lies in [1, 2)). For a normal
  // component with 2⁻ᵉ normal (biased exponent 1 … 2045) the product by the double 2⁻ᵉ, a single
  // correctly rounded operation, is ldexp's result (exact, or the same rounding of a subnormal
  // smaller component) without ilogb's and two ldexp's calls (a few % of a σ_d query).
  const double m = std::max(std::abs(d.x()), std::abs(d.y()));
  const std::uint64_t biased = std::bit_cast<std::uint64_t>(m) >> 52;
  if (biased >= 1 && biased <= 2045) {
    const double s = std::bit_cast<double>((2046 - biased) << 52);
    return Vec2(d.x() * s, d.y() * s);
  }
  const int e = std::ilogb(m);
  return Vec2(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
}

void check_point(const Vec2& t) { require_finite(t, "placement t"); }

namespace {

template <class L>
auto norm_squared(const Vec2& d, L lift) {
  return lift(d.x()) * lift(d.x()) + lift(d.y()) * lift(d.y());
}

// accurate_value(norm_squared) starts with the Fl tier, which never certifies this sum of two
// squares (its bound is at least u·|v| plus 2⁻¹⁰⁰⁰ from each product, above the u·|v| it requires),
// then takes the DD tier's hi when its bound allows: that tier directly, the same operations and
// test (the same double); false where the full chain must decide.
bool norm_dd(const Vec2& d, double& norm) {
  const exact::DD s = norm_squared(d, exact::LiftDD{});
  if (!(exact::dd_finite(s) && exact::safe_bound(s.e) <= std::abs(s.hi) * 0x1p-54)) return false;
  norm = std::sqrt(s.hi);
  return true;
}

#if PENDEPTH_V3_CLONES
// The same compiled for x86-64-v3 (geometry/isa.hpp): the products' residuals (std::fma, exact
// either way) by the instruction instead of libm's call, which was most of this function's ~8 %
// of a lean σ_d query on nesting pieces; the same double.
PENDEPTH_V3_CLONE bool norm_dd_v3(const Vec2& d, double& norm) { return norm_dd(d, norm); }
#endif

}  // namespace

double norm_accurate(const Vec2& d) {
  double norm;
#if PENDEPTH_V3_CLONES
  if (isa::use_v3() ? norm_dd_v3(d, norm) : norm_dd(d, norm)) return norm;
#else
  if (norm_dd(d, norm)) return norm;
#endif
  return std::sqrt(exact::accurate_value([&](auto L) { return norm_squared(d, L); }));
}

int end_on_ray(const Line& E, const Vec2& t, const Vec2& d) {
  for (int end = 0; end < 2; ++end) {
    const int s = exact::exact_sign([&](auto L) {
      auto x = L(E.c1.x()) + L(E.c2.x()) - L(t.x()), y = L(E.c1.y()) + L(E.c2.y()) - L(t.y());
      if (end == 1) {
        x = x + L(E.e1.x()) - L(E.e0.x());
        y = y + L(E.e1.y()) - L(E.e0.y());
      }
      return L(d.x()) * y - L(d.y()) * x;
    });
    if (s == 0) return end;
  }
  return -1;
}

}  // namespace nonconvex2
}  // namespace pendepth
