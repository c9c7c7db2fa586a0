// Exact oracle for 2D convex depth (see exact_oracle.hpp). The only file of the tests that sees
// CGAL: Epeck (lazy exact rationals) for hulls, M, point location, distances and ray exits.
#include "oracle/exact_oracle.hpp"

// The oracle runs on one thread. Without this, CGAL's lazy numbers guard each exact evaluation
// with std::call_once, which here costs a futex system call per evaluated node.
#define CGAL_HAS_NO_THREADS 1

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/minkowski_sum_2.h>
#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace oracle {
namespace {

using K = CGAL::Epeck;
using FT = K::FT;
using Point = K::Point_2;
using Vector = K::Vector_2;
using Segment = K::Segment_2;
using Ray = K::Ray_2;

// The exact number type behind Epeck is mpq_class (CGAL_USE_GMPXX) or CGAL::Gmpq.
template <class Q>
mpq_class to_mpq(const Q& q) {
  if constexpr (std::is_same_v<Q, mpq_class>) return q;
  else return mpq_class(q.mpq());
}
mpq_class exact_value(const FT& x) { return to_mpq(CGAL::exact(x)); }

// q rounded to the nearest double (MPFR rounds correctly to 53 bits).
double round_to_double(const mpq_class& q) {
  mpfr_t x;
  mpfr_init2(x, 53);
  mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
  double r = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return r;
}

// sqrt(q) for q >= 0, to the nearest double: 256-bit sqrt then one rounding to 53 bits
// (error at most 0.5 ulp + 2^-200 relative).
double sqrt_to_double(const mpq_class& q) {
  if (sgn(q) < 0) throw std::logic_error("oracle: sqrt of a negative rational");
  mpfr_t x;
  mpfr_init2(x, 256);
  mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(x, x, MPFR_RNDN);
  double r = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return r;
}

bool is_double(const FT& x, double& rounded) {
  mpq_class q = exact_value(x);
  rounded = round_to_double(q);
  return std::isfinite(rounded) && mpq_class(rounded) == q;
}

// Cheap sufficient test: a point interval [v, v] from the lazy number's interval arithmetic
// contains the exact value, so the value is v. (Misses a few doubles whose interval widened.)
bool is_double_fast(const FT& x, double& value) {
  const auto& a = x.approx();
  value = a.inf();
  return a.inf() == a.sup() && std::isfinite(value);
}

double nearest_double(const FT& x) {
  double v;
  return is_double_fast(x, v) ? v : round_to_double(exact_value(x));
}

Point to_point(const Vec2& v) { return Point(v.x(), v.y()); }

// Exact convex hull of a point set (CCW, extreme points only).
std::vector<Point> exact_hull(std::span<const Vec2> pts) {
  std::vector<Point> in;
  in.reserve(pts.size());
  for (const Vec2& v : pts) {
    if (!std::isfinite(v.x()) || !std::isfinite(v.y())) throw std::invalid_argument("oracle: non-finite point");
    in.push_back(to_point(v));
  }
  std::vector<Point> out;
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out));
  if (out.size() < 3) throw std::invalid_argument("oracle: point set spans no area");
  return out;
}

// Normal form: CCW, no repeated or collinear vertices, vertex 0 the lowest then leftmost.
std::vector<Point> normalise(std::vector<Point> poly) {
  if (CGAL::orientation_2(poly.begin(), poly.end(), K()) == CGAL::CLOCKWISE) std::reverse(poly.begin(), poly.end());
  bool changed = true;
  while (changed && poly.size() >= 3) {
    changed = false;
    std::vector<Point> kept;
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point &a = poly[(i + n - 1) % n], &b = poly[i], &c = poly[(i + 1) % n];
      if (b == a || CGAL::orientation(a, b, c) == CGAL::COLLINEAR) changed = true;
      else kept.push_back(b);
    }
    poly.swap(kept);
  }
  if (poly.size() < 3) throw std::logic_error("oracle: degenerate M");
  auto lowest = std::min_element(poly.begin(), poly.end(),
                                 [](const Point& a, const Point& b) { return CGAL::compare_yx(a, b) == CGAL::SMALLER; });
  std::rotate(poly.begin(), lowest, poly.end());
  return poly;
}

// Half of the angle circle: 0 for angles in [0, pi), 1 for [pi, 2pi).
int half(const Vector& v) {
  int sy = CGAL::sign(v.y());
  return (sy < 0 || (sy == 0 && CGAL::sign(v.x()) < 0)) ? 1 : 0;
}
// Polar angle order in [0, 2pi): -1, 0, +1.
int compare_angle(const Vector& a, const Vector& b) {
  int ha = half(a), hb = half(b);
  if (ha != hb) return ha < hb ? -1 : 1;
  int o = CGAL::orientation(a, b);
  return o > 0 ? -1 : (o < 0 ? 1 : 0);
}

// Minkowski sum of two normal-form convex polygons by merging edges in angle order (both start
// at their lowest-leftmost vertex, so both edge sequences run over [0, 2pi) once). Each vertex is
// A[i] + B[j] constructed directly (no running sum: keeps the lazy DAG shallow).
std::vector<Point> merge_sum(const std::vector<Point>& A, const std::vector<Point>& B) {
  const std::size_t n = A.size(), m = B.size();
  std::vector<Point> out;
  out.reserve(n + m);
  std::size_t i = 0, j = 0;
  while (i < n || j < m) {
    out.push_back(A[i % n] + (B[j % m] - CGAL::ORIGIN));
    if (i == n) ++j;
    else if (j == m) ++i;
    else {
      int c = compare_angle(A[(i + 1) % n] - A[i], B[(j + 1) % m] - B[j]);
      if (c <= 0) ++i;
      if (c >= 0) ++j;
    }
  }
  return normalise(std::move(out));
}

std::vector<Point> negate(const std::vector<Point>& poly) {
  std::vector<Point> out;
  out.reserve(poly.size());
  for (const Point& p : poly) out.push_back(CGAL::ORIGIN - (p - CGAL::ORIGIN));
  return normalise(std::move(out));  // a half-turn keeps the orientation
}

}  // namespace

struct ExactDifference::Impl {
  std::vector<Point> p, q, m;  // hull(P), hull(Q), M — each in normal form
  std::vector<Segment> edges;  // edge k: m[k] -> m[k+1]
  Vec2 lo, hi;
};

ExactDifference::ExactDifference(std::span<const Vec2> p_points, std::span<const Vec2> q_points, Construction how)
    : impl_(std::make_unique<Impl>()) {
  Impl& I = *impl_;
  I.p = normalise(exact_hull(p_points));
  I.q = normalise(exact_hull(q_points));
  const std::vector<Point> nq = negate(I.q);
  if (how == Construction::Auto) how = I.p.size() * I.q.size() <= 4096 ? Construction::PairwiseHull : Construction::Merge;
  switch (how) {
    case Construction::PairwiseHull: {
      std::vector<Point> diffs;
      diffs.reserve(I.p.size() * nq.size());
      for (const Point& a : I.p)
        for (const Point& b : nq) diffs.push_back(a + (b - CGAL::ORIGIN));
      std::vector<Point> h;
      CGAL::convex_hull_2(diffs.begin(), diffs.end(), std::back_inserter(h));
      I.m = normalise(std::move(h));
      break;
    }
    case Construction::Merge:
      I.m = merge_sum(I.p, nq);
      break;
    case Construction::CgalMinkowskiSum: {
      CGAL::Polygon_2<K> A(I.p.begin(), I.p.end()), B(nq.begin(), nq.end());
      auto sum = CGAL::minkowski_sum_2(A, B);
      if (sum.number_of_holes() != 0) throw std::logic_error("oracle: Minkowski sum of convex polygons has a hole");
      const auto& outer = sum.outer_boundary();
      I.m = normalise(std::vector<Point>(outer.vertices_begin(), outer.vertices_end()));
      break;
    }
    case Construction::Auto:
      break;
  }
  if (!CGAL::is_convex_2(I.m.begin(), I.m.end(), K()) || !CGAL::is_simple_2(I.m.begin(), I.m.end(), K()))
    throw std::logic_error("oracle: M is not a simple convex polygon");
  const std::size_t N = I.m.size();
  I.edges.reserve(N);
  for (std::size_t k = 0; k < N; ++k) I.edges.emplace_back(I.m[k], I.m[(k + 1) % N]);
  const double inf = std::numeric_limits<double>::infinity();
  I.lo = Vec2(inf, inf);
  I.hi = Vec2(-inf, -inf);
  for (std::size_t k = 0; k < N; ++k) {  // approximate: only used to draw placements
    const Vec2 v(CGAL::to_double(I.m[k].x()), CGAL::to_double(I.m[k].y()));
    I.lo = I.lo.cwiseMin(v);
    I.hi = I.hi.cwiseMax(v);
  }
}

ExactDifference::~ExactDifference() = default;
ExactDifference::ExactDifference(ExactDifference&&) noexcept = default;
ExactDifference& ExactDifference::operator=(ExactDifference&&) noexcept = default;

std::size_t ExactDifference::size() const { return impl_->m.size(); }

Vec2 ExactDifference::vertex(std::size_t k) const {
  const Point& p = impl_->m[k];
  return Vec2(nearest_double(p.x()), nearest_double(p.y()));
}

bool ExactDifference::vertex_is_double(std::size_t k) const {
  double x, y;
  return is_double(impl_->m[k].x(), x) && is_double(impl_->m[k].y(), y);
}

std::vector<Vec2> ExactDifference::boundary_doubles() const {
  std::vector<Vec2> out;
  const std::size_t N = size();
  auto add = [&](const Point& p) {
    double x, y;
    if (is_double_fast(p.x(), x) && is_double_fast(p.y(), y)) out.emplace_back(x, y);
  };
  for (std::size_t k = 0; k < N; ++k) {
    const Point &a = impl_->m[k], &b = impl_->m[(k + 1) % N];
    add(a);
    add(CGAL::midpoint(a, b));
    add(a + (b - a) / FT(4));
    add(a + (b - a) * FT(3) / FT(4));
  }
  return out;
}

namespace {
std::vector<Vec2> to_doubles(const std::vector<Point>& poly) {
  std::vector<Vec2> out;
  for (const Point& p : poly) out.emplace_back(nearest_double(p.x()), nearest_double(p.y()));
  return out;
}
}  // namespace

std::vector<Vec2> ExactDifference::p_hull() const { return to_doubles(impl_->p); }
std::vector<Vec2> ExactDifference::q_hull() const { return to_doubles(impl_->q); }
Vec2 ExactDifference::box_lo() const { return impl_->lo; }
Vec2 ExactDifference::box_hi() const { return impl_->hi; }

Location ExactDifference::locate(const Vec2& t) const {
  switch (CGAL::bounded_side_2(impl_->m.begin(), impl_->m.end(), to_point(t), K())) {
    case CGAL::ON_BOUNDED_SIDE: return Location::Inside;
    case CGAL::ON_BOUNDARY: return Location::Boundary;
    default: return Location::Outside;
  }
}

double ExactDifference::minimum_depth(const Vec2& t) const {
  if (locate(t) != Location::Inside) return 0.0;
  const Point tp = to_point(t);
  FT best = CGAL::squared_distance(tp, impl_->edges[0]);
  for (std::size_t k = 1; k < impl_->edges.size(); ++k) {
    FT d2 = CGAL::squared_distance(tp, impl_->edges[k]);
    if (d2 < best) best = d2;
  }
  return sqrt_to_double(exact_value(best));
}

double ExactDifference::directional_depth(const Vec2& t, const Vec2& d) const {
  if (!std::isfinite(d.x()) || !std::isfinite(d.y()) || (d.x() == 0 && d.y() == 0))
    throw std::invalid_argument("oracle: invalid direction");
  if (locate(t) != Location::Inside) return 0.0;
  const Point tp = to_point(t);
  const Ray ray(tp, Vector(d.x(), d.y()));
  // From an interior point the ray meets ∂M exactly once (possibly at a vertex, seen twice).
  bool hit = false;
  FT best(0);
  for (const Segment& e : impl_->edges) {
    if (!CGAL::do_intersect(ray, e)) continue;
    auto x = CGAL::intersection(ray, e);
    const Point* p = x ? boost::get<Point>(&*x) : nullptr;  // CGAL 5.5: boost::optional<boost::variant>
    if (p == nullptr) throw std::logic_error("oracle: ray from an interior point overlaps an edge");
    FT d2 = CGAL::squared_distance(tp, *p);
    if (!hit || d2 > best) best = d2;
    hit = true;
  }
  if (!hit) throw std::logic_error("oracle: ray from an interior point never leaves M");
  return sqrt_to_double(exact_value(best));
}

double ExactDifference::separation_depth(const Vec2& t, const Vec2& d) const {
  if (!std::isfinite(d.x()) || !std::isfinite(d.y()) || (d.x() == 0 && d.y() == 0))
    throw std::invalid_argument("oracle: invalid direction");
  // The line t + s·d meets convex M in [entry, exit]; complete separation is exit (scaled by |d|)
  // when the line crosses int M (entry < exit) and exit > 0, else 0.
  const Point tp = to_point(t);
  const Vector dv(d.x(), d.y());
  auto cross = [](const Vector& u, const Vector& v) { return u.x() * v.y() - u.y() * v.x(); };
  bool have_entry = false, have_exit = false;
  FT entry(0), exit(0);
  for (const Segment& seg : impl_->edges) {
    const Vector e = seg.target() - seg.source();
    const FT den = cross(dv, e);
    if (CGAL::is_zero(den)) {
      if (!CGAL::is_positive(cross(e, tp - seg.source()))) return 0.0;  // line outside or along an edge
      continue;
    }
    const FT s = cross(seg.source() - tp, e) / den;
    if (CGAL::is_positive(den)) {
      if (!have_exit || s < exit) exit = s;
      have_exit = true;
    } else {
      if (!have_entry || s > entry) entry = s;
      have_entry = true;
    }
  }
  if (!have_entry || !have_exit || !(entry < exit) || !CGAL::is_positive(exit)) return 0.0;
  return sqrt_to_double(exact_value(exit * exit * (dv * dv)));
}

bool ExactDifference::same_polygon(const ExactDifference& other) const {
  const auto &a = impl_->m, &b = other.impl_->m;
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k] != b[k]) return false;
  return true;
}

std::string ExactDifference::describe() const {
  std::string s = "M (" + std::to_string(size()) + " vertices):";
  char buf[96];
  for (std::size_t k = 0; k < size() && k < 64; ++k) {
    Vec2 v = vertex(k);
    std::snprintf(buf, sizeof buf, " (%.17g, %.17g)", v.x(), v.y());
    s += buf;
  }
  if (size() > 64) s += " ...";
  return s;
}

double relative_ulps(double got, double want) {
  if (want == 0) return got == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  return std::abs(got - want) / std::abs(want) * 0x1p52;  // divide first: no underflow
}

bool within(double got, double want, double tol) {
  return std::abs(got - want) <= tol * 0x1p-52 * std::abs(want) + kUnderflowSlack;
}

}  // namespace oracle
