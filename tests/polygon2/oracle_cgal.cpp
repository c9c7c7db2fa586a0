// The exact CGAL oracle (see oracle.hpp). The only file of the tests that includes CGAL.
#include "oracle.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>

namespace polygon2_test {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using Point = K::Point_2;
using Polygon2 = CGAL::Polygon_2<K>;
using PolygonWH = CGAL::Polygon_with_holes_2<K>;
using PolygonSet = CGAL::Polygon_set_2<K>;

struct UnionOracle::Impl {
  std::vector<Polygon2> parts;  // the R_i, exact, CCW
  PolygonSet set;               // their regularised union
  std::vector<K::Segment_2> boundary;
};

UnionOracle::UnionOracle(const std::vector<std::array<pendepth::Vec2, 3>>& triangles, const std::vector<pendepth::Vec2>& Q)
    : impl_(std::make_unique<Impl>()) {
  for (const auto& T : triangles) {
    std::vector<Point> pts, hull;
    for (const auto& a : T)
      for (const auto& q : Q) pts.emplace_back(FT(a.x()) - FT(q.x()), FT(a.y()) - FT(q.y()));
    CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(hull));
    impl_->parts.emplace_back(hull.begin(), hull.end());
  }
  impl_->set.join(impl_->parts.begin(), impl_->parts.end());
  std::vector<PolygonWH> pwh;
  impl_->set.polygons_with_holes(std::back_inserter(pwh));
  for (const auto& p : pwh) {
    for (auto e = p.outer_boundary().edges_begin(); e != p.outer_boundary().edges_end(); ++e) impl_->boundary.push_back(*e);
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h)
      for (auto e = h->edges_begin(); e != h->edges_end(); ++e) impl_->boundary.push_back(*e);
  }
}

UnionOracle::~UnionOracle() = default;

namespace {
Point lift(const pendepth::Vec2& p) { return Point(p.x(), p.y()); }

struct Interval {
  FT a, b;  // open interval (a, b) of λ in int R_i
};

// The open intervals of λ where t + λ·d lies in int R_i, for every i meeting the line's interior.
std::vector<Interval> intervals(const std::vector<Polygon2>& parts, const pendepth::Vec2& t, const pendepth::Vec2& d) {
  const Point pt = lift(t);
  const K::Vector_2 v(d.x(), d.y());
  const K::Line_2 line(pt, v);
  const FT vv = v * v;
  std::vector<Interval> out;
  for (const auto& R : parts) {
    std::vector<FT> ls;
    for (auto e = R.edges_begin(); e != R.edges_end(); ++e) {
      auto x = CGAL::intersection(*e, line);
      if (!x) continue;
      if (const Point* p = boost::get<Point>(&*x)) {
        ls.push_back(((*p - pt) * v) / vv);
      } else if (const K::Segment_2* q = boost::get<K::Segment_2>(&*x)) {
        ls.push_back(((q->source() - pt) * v) / vv);
        ls.push_back(((q->target() - pt) * v) / vv);
      }
    }
    if (ls.size() < 2) continue;
    auto [lo, hi] = std::minmax_element(ls.begin(), ls.end());
    if (*lo == *hi) continue;
    const Point mid = pt + v * ((*lo + *hi) / 2);
    if (R.bounded_side(mid) == CGAL::ON_BOUNDED_SIDE) out.push_back({*lo, *hi});
  }
  return out;
}

bool in_some(const std::vector<Interval>& iv, const FT& l) {
  return std::any_of(iv.begin(), iv.end(), [&](const Interval& i) { return i.a < l && l < i.b; });
}

std::vector<FT> breakpoints(const std::vector<Interval>& iv) {
  std::vector<FT> out{FT(0)};
  for (const auto& i : iv) {
    out.push_back(i.a);
    out.push_back(i.b);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double as_length(const FT& lambda, const pendepth::Vec2& d) {
  return CGAL::to_double(CGAL::exact(lambda)) * std::hypot(d.x(), d.y());
}
}  // namespace

bool UnionOracle::inside(const pendepth::Vec2& t) const {
  const Point p = lift(t);
  return std::any_of(impl_->parts.begin(), impl_->parts.end(),
                     [&](const Polygon2& R) { return R.bounded_side(p) == CGAL::ON_BOUNDED_SIDE; });
}

bool UnionOracle::inside_union(const pendepth::Vec2& t) const {
  return impl_->set.oriented_side(lift(t)) == CGAL::ON_POSITIVE_SIDE;
}

double UnionOracle::along(const pendepth::Vec2& t, const pendepth::Vec2& d) const {
  const auto iv = intervals(impl_->parts, t, d);
  if (!in_some(iv, FT(0))) return 0;
  for (const FT& l : breakpoints(iv))  // membership is constant between breakpoints
    if (l > 0 && !in_some(iv, l)) return as_length(l, d);
  return 0;  // unreachable: the last breakpoint is outside every open interval
}

double UnionOracle::separation(const pendepth::Vec2& t, const pendepth::Vec2& d) const {
  const auto iv = intervals(impl_->parts, t, d);
  const auto b = breakpoints(iv);
  for (std::size_t k = b.size(); k-- > 1;) {
    if (b[k] <= 0) break;
    if (in_some(iv, (b[k - 1] + b[k]) / 2)) return as_length(b[k], d);
  }
  return 0;
}

namespace {
// An exact rational as FT, type-agnostic: integers split into 48-bit chunks (each exact in double).
FT ft_of_mpz(mpz_class z) {
  const bool neg = z < 0;
  if (neg) z = -z;
  FT r = 0, scale = 1;
  const FT base = FT(281474976710656.0);  // 2^48
  while (z != 0) {
    mpz_class low = z % mpz_class(281474976710656.0);
    r += FT(low.get_d()) * scale;
    scale *= base;
    z /= mpz_class(281474976710656.0);
  }
  return neg ? -r : r;
}
Point exact_point(const UnionOracle::ExactPoint& p) {
  return Point(ft_of_mpz(p.x.get_num()) / ft_of_mpz(p.x.get_den()), ft_of_mpz(p.y.get_num()) / ft_of_mpz(p.y.get_den()));
}
}  // namespace

double UnionOracle::union_area() const {
  std::vector<PolygonWH> pwh;
  impl_->set.polygons_with_holes(std::back_inserter(pwh));
  FT a = 0;
  for (const auto& p : pwh) {
    a += p.outer_boundary().area();
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += h->area();  // holes are clockwise
  }
  return CGAL::to_double(CGAL::exact(a));
}

std::size_t UnionOracle::outer_count() const { return impl_->set.number_of_polygons_with_holes(); }

std::size_t UnionOracle::hole_count() const {
  std::vector<PolygonWH> pwh;
  impl_->set.polygons_with_holes(std::back_inserter(pwh));
  std::size_t n = 0;
  for (const auto& p : pwh) n += p.number_of_holes();
  return n;
}

bool UnionOracle::on_union_boundary(const ExactPoint& p) const {
  const Point q = exact_point(p);
  return std::any_of(impl_->boundary.begin(), impl_->boundary.end(), [&](const K::Segment_2& s) { return s.has_on(q); });
}

bool UnionOracle::inside(const ExactPoint& p) const {
  const Point q = exact_point(p);
  return std::any_of(impl_->parts.begin(), impl_->parts.end(),
                     [&](const Polygon2& R) { return R.bounded_side(q) == CGAL::ON_BOUNDED_SIDE; });
}

bool UnionOracle::inside_union(const ExactPoint& p) const {
  return impl_->set.oriented_side(exact_point(p)) == CGAL::ON_POSITIVE_SIDE;
}

std::size_t UnionOracle::vertices_off(const std::vector<std::array<ExactPoint, 2>>& segments) const {
  std::vector<K::Segment_2> segs;
  for (const auto& s : segments) segs.emplace_back(exact_point(s[0]), exact_point(s[1]));
  std::size_t off = 0;
  for (const auto& b : impl_->boundary) {
    const Point& v = b.source();
    bool on = false;
    for (const auto& s : segs)
      if (s.is_degenerate() ? s.source() == v : s.has_on(v)) {
        on = true;
        break;
      }
    off += !on;
  }
  return off;
}

double UnionOracle::boundary_distance(const pendepth::Vec2& t) const {
  const Point q = lift(t);
  FT best = -1;
  for (const auto& s : impl_->boundary) {
    const FT d2 = CGAL::squared_distance(q, s);
    if (best < 0 || d2 < best) best = d2;
  }
  return std::sqrt(CGAL::to_double(CGAL::exact(best)));
}

std::vector<pendepth::Vec2> UnionOracle::boundary_vertices() const {
  std::vector<pendepth::Vec2> out;
  for (const auto& s : impl_->boundary) out.emplace_back(CGAL::to_double(s.source().x()), CGAL::to_double(s.source().y()));
  return out;
}

}  // namespace polygon2_test
