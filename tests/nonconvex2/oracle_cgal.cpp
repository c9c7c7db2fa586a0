// The exact CGAL oracle (see oracle.hpp). The only file of these tests that includes CGAL.
#include "oracle.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/minkowski_sum_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <cmath>
#include <list>

#include "polygon2/triangulation.hpp"

namespace nonconvex2_test {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using Point = K::Point_2;
using Vector = K::Vector_2;
using Polygon2 = CGAL::Polygon_2<K>;
using PolygonWH = CGAL::Polygon_with_holes_2<K>;

namespace {

Point lift(const pendepth::Vec2& p) { return Point(p.x(), p.y()); }

// Convex pieces (as point lists) covering the shape with disjoint interiors.
std::vector<std::vector<Point>> convex_pieces(const pendepth::Polygon& S) {
  std::vector<std::vector<Point>> out;
  if (S.hole_count() == 0) {
    using Traits = CGAL::Partition_traits_2<K>;
    std::vector<Traits::Point_2> ring;
    for (const auto& p : S.ring(0)) ring.push_back(lift(p));
    std::list<Traits::Polygon_2> parts;
    CGAL::approx_convex_partition_2(ring.begin(), ring.end(), std::back_inserter(parts));
    for (const auto& part : parts) out.emplace_back(part.vertices_begin(), part.vertices_end());
  } else {
    for (const auto& t : pendepth::polygon2::triangulate(S)) {
      std::vector<Point> tri;
      for (auto g : t) tri.push_back(lift(S.vertices()[g]));
      out.push_back(tri);
    }
  }
  return out;
}

struct Interval {
  FT a, b;  // open interval (a, b) of λ inside the piece
};

// The open interval of λ where o + λ·v lies in int R (false if the line misses int R).
bool line_interval(const Polygon2& R, const CGAL::Bbox_2& box, const Point& o, const Vector& v, Interval& out) {
  const K::Line_2 line(o, v);
  // Exact, filtered predicate: a line missing the piece's (conservative) box misses the piece.
  if (!CGAL::do_intersect(line, K::Iso_rectangle_2(box))) return false;
  const FT vv = v * v;
  std::vector<FT> ls;
  for (auto e = R.edges_begin(); e != R.edges_end(); ++e) {
    auto x = CGAL::intersection(*e, line);
    if (!x) continue;
    if (const Point* p = boost::get<Point>(&*x)) {
      ls.push_back(((*p - o) * v) / vv);
    } else if (const K::Segment_2* q = boost::get<K::Segment_2>(&*x)) {
      ls.push_back(((q->source() - o) * v) / vv);
      ls.push_back(((q->target() - o) * v) / vv);
    }
  }
  if (ls.size() < 2) return false;
  auto [lo, hi] = std::minmax_element(ls.begin(), ls.end());
  if (*lo == *hi) return false;
  if (R.bounded_side(o + v * ((*lo + *hi) / 2)) != CGAL::ON_BOUNDED_SIDE) return false;
  out = {*lo, *hi};
  return true;
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

double as_length(const FT& lambda, const pendepth::Vec2& d) { return CGAL::to_double(CGAL::exact(lambda)) * std::hypot(d.x(), d.y()); }

}  // namespace

struct PairOracle::Impl {
  std::vector<Polygon2> parts;
  std::vector<CGAL::Bbox_2> boxes;
  bool has_M = false;
  PolygonWH M;

  std::vector<Interval> intervals(const pendepth::Vec2& t, const pendepth::Vec2& d) const {
    std::vector<Interval> out;
    Interval iv;
    for (std::size_t k = 0; k < parts.size(); ++k)
      if (line_interval(parts[k], boxes[k], lift(t), Vector(d.x(), d.y()), iv)) out.push_back(iv);
    return out;
  }
};

PairOracle::PairOracle(const pendepth::Polygon& P, const pendepth::Polygon& Q) : impl_(std::make_unique<Impl>()) {
  const auto A = convex_pieces(P), B = convex_pieces(Q);
  for (const auto& a : A)
    for (const auto& b : B) {
      std::vector<Point> pts, hull;
      for (const auto& x : a)
        for (const auto& y : b) pts.push_back(Point(x.x() - y.x(), x.y() - y.y()));
      CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(hull));
      impl_->parts.emplace_back(hull.begin(), hull.end());
      impl_->boxes.push_back(impl_->parts.back().bbox());
    }
  if (P.hole_count() == 0 && Q.hole_count() == 0) {
    Polygon2 p, q;
    for (const auto& v : P.ring(0)) p.push_back(lift(v));
    for (const auto& v : Q.ring(0)) q.push_back(Point(-v.x(), -v.y()));  // −Q is still CCW
    impl_->M = CGAL::minkowski_sum_2(p, q);
    impl_->has_M = true;
  }
}

PairOracle::~PairOracle() = default;

std::size_t PairOracle::piece_count() const { return impl_->parts.size(); }
bool PairOracle::has_M() const { return impl_->has_M; }

bool PairOracle::inside(const pendepth::Vec2& t) const {
  const Point p = lift(t);
  return std::any_of(impl_->parts.begin(), impl_->parts.end(), [&](const Polygon2& R) { return R.bounded_side(p) == CGAL::ON_BOUNDED_SIDE; });
}

double PairOracle::along(const pendepth::Vec2& t, const pendepth::Vec2& d) const {
  const auto iv = impl_->intervals(t, d);
  if (!in_some(iv, FT(0))) return 0;
  for (const FT& l : breakpoints(iv))  // membership is constant between breakpoints
    if (l > 0 && !in_some(iv, l)) return as_length(l, d);
  return 0;
}

double PairOracle::separation(const pendepth::Vec2& t, const pendepth::Vec2& d) const {
  const auto iv = impl_->intervals(t, d);
  const auto b = breakpoints(iv);
  for (std::size_t k = b.size(); k-- > 1;) {
    if (b[k] <= 0) break;
    if (in_some(iv, (b[k - 1] + b[k]) / 2)) return as_length(b[k], d);
  }
  return 0;
}

double PairOracle::minimum(const pendepth::Vec2& t) const {
  if (!inside(t)) return 0;
  const Point pt = lift(t);
  // Bound: the exit along +x is a point of the complement.
  const auto iv = impl_->intervals(t, {1, 0});
  FT U = 0;
  for (const FT& l : breakpoints(iv))
    if (l > 0 && !in_some(iv, l)) {
      U = l;
      break;
    }
  const double R = CGAL::to_double(U) * (1 + 1e-9) + 1e-300;
  std::vector<std::size_t> near;
  for (std::size_t k = 0; k < impl_->parts.size(); ++k) {
    const auto& b = impl_->boxes[k];
    const double dx = std::max({b.xmin() - t.x(), 0.0, t.x() - b.xmax()}), dy = std::max({b.ymin() - t.y(), 0.0, t.y() - b.ymax()});
    if (std::hypot(dx, dy) <= R * (1 + 1e-9)) near.push_back(k);
  }
  FT best = U * U;
  for (std::size_t k : near) {
    const Polygon2& Rk = impl_->parts[k];
    for (auto e = Rk.edges_begin(); e != Rk.edges_end(); ++e) {
      const Point A = e->source();
      const Vector v = e->target() - A;
      const FT vv = v * v;
      std::vector<Interval> cover;
      Interval c;
      const CGAL::Bbox_2 eb = e->bbox();
      for (std::size_t j : near)
        if (j != k && CGAL::do_overlap(eb, impl_->boxes[j]) && line_interval(impl_->parts[j], impl_->boxes[j], A, v, c) &&
            c.b > 0 && c.a < 1)
          cover.push_back(c);
      std::sort(cover.begin(), cover.end(), [](const Interval& x, const Interval& y) { return x.a < y.a; });
      const FT proj = ((pt - A) * v) / vv;
      auto piece = [&](const FT& lo, const FT& hi) {
        const FT mu = proj < lo ? lo : (proj > hi ? hi : proj);
        const FT d2 = CGAL::squared_distance(A + v * mu, pt);
        if (d2 < best) best = d2;
      };
      FT s = 0;
      bool done = false;
      for (const auto& cv : cover) {
        if (cv.a >= s) {
          piece(s, cv.a);
          s = cv.b;
        } else if (cv.b > s) {
          s = cv.b;
        }
        if (s > 1) {
          done = true;
          break;
        }
      }
      if (!done) piece(s, FT(1));
    }
  }
  return std::sqrt(CGAL::to_double(CGAL::exact(best)));
}

namespace {
// cl(O) as exact polygons with holes.
std::vector<PolygonWH> closure(bool has_M, const PolygonWH& M, const std::vector<Polygon2>& parts) {
  if (has_M) return {M};
  CGAL::Polygon_set_2<K> set;
  set.join(parts.begin(), parts.end());
  std::vector<PolygonWH> out;
  set.polygons_with_holes(std::back_inserter(out));
  return out;
}
}  // namespace

double PairOracle::closure_area() const {
  FT a = 0;
  for (const auto& pwh : closure(impl_->has_M, impl_->M, impl_->parts)) {
    a += pwh.outer_boundary().area();
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) a += h->area();  // holes are CW: negative
  }
  return CGAL::to_double(a.exact());
}

std::vector<pendepth::Vec2> PairOracle::closure_vertices() const {
  std::vector<pendepth::Vec2> out;
  auto add = [&](const Polygon2& r) {
    for (auto v = r.vertices_begin(); v != r.vertices_end(); ++v)
      out.push_back({CGAL::to_double(v->x().exact()), CGAL::to_double(v->y().exact())});
  };
  for (const auto& pwh : closure(impl_->has_M, impl_->M, impl_->parts)) {
    add(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) add(*h);
  }
  return out;
}

int PairOracle::side_of_M(const pendepth::Vec2& t) const {
  const Point p = lift(t);
  const auto outer = impl_->M.outer_boundary().bounded_side(p);
  if (outer == CGAL::ON_UNBOUNDED_SIDE) return -1;
  if (outer == CGAL::ON_BOUNDARY) return 0;
  for (auto h = impl_->M.holes_begin(); h != impl_->M.holes_end(); ++h) {
    const auto s = h->bounded_side(p);
    if (s == CGAL::ON_BOUNDARY) return 0;
    if (s == CGAL::ON_BOUNDED_SIDE) return -1;
  }
  return 1;
}

}  // namespace nonconvex2_test
