// The exact CGAL oracle for distance and cast (oracle_distance.hpp).
#include "oracle_distance.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_2.h>

#include <cmath>
#include <limits>
#include <optional>
#include <boost/variant.hpp>
#include <vector>

namespace nonconvex2_test {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using Point = K::Point_2;
using Vector = K::Vector_2;
using Segment = K::Segment_2;
using Ray = K::Ray_2;

std::vector<Segment> segments(const pendepth::Polygon& S, FT tx, FT ty) {
  std::vector<Segment> out;
  const auto v = S.vertices();
  for (std::size_t k = 0; k < v.size(); ++k) {
    const auto &a = v[k], &b = v[S.next(k)];
    out.emplace_back(Point(FT(a.x()) + tx, FT(a.y()) + ty), Point(FT(b.x()) + tx, FT(b.y()) + ty));
  }
  return out;
}

// The first parameter λ >= 0 (units of the ray's direction vector) at which the ray meets s.
std::optional<FT> first_hit(const Ray& r, const Segment& s) {
  const auto x = CGAL::intersection(r, s);
  if (!x) return std::nullopt;
  const Vector dir = r.to_vector();
  const FT dd = dir * dir;
  auto param = [&](const Point& p) { return ((p - r.source()) * dir) / dd; };
  if (const Point* p = boost::get<Point>(&*x)) return param(*p);
  const Segment* seg = boost::get<Segment>(&*x);
  // A collinear overlap: its nearest end, or the ray's source when it lies on the segment.
  const FT a = param(seg->source()), b = param(seg->target());
  const FT m = a < b ? a : b;
  return m < 0 ? FT(0) : m;
}

}  // namespace

ExactDistance exact_boundary_distance(const pendepth::Polygon& P, const pendepth::Polygon& Q, const pendepth::Vec2& t) {
  const auto sp = segments(P, 0, 0), sq = segments(Q, FT(t.x()), FT(t.y()));
  std::optional<FT> best;
  for (const Segment& a : sp)
    for (const Segment& b : sq) {
      const FT d = CGAL::squared_distance(a, b);
      if (!best || d < *best) best = d;
    }
  ExactDistance r;
  r.touching = *best == 0;
  r.distance = std::sqrt(CGAL::to_double(best->exact()));
  return r;
}

ExactCast exact_cast(const pendepth::Polygon& P, const pendepth::Polygon& Q, const pendepth::Vec2& t,
                     const pendepth::Vec2& d) {
  const FT tx(t.x()), ty(t.y());
  const Vector dir(FT(d.x()), FT(d.y()));
  const auto sp = segments(P, 0, 0), sq = segments(Q, tx, ty);
  std::optional<FT> best;
  auto consider = [&](const std::optional<FT>& s) {
    if (s && (!best || *s < *best)) best = s;
  };
  for (const pendepth::Vec2& q : Q.vertices()) {
    const Ray r(Point(FT(q.x()) + tx, FT(q.y()) + ty), dir);
    for (const Segment& e : sp) consider(first_hit(r, e));
  }
  for (const pendepth::Vec2& p : P.vertices()) {
    const Ray r(Point(FT(p.x()), FT(p.y())), -dir);
    for (const Segment& e : sq) consider(first_hit(r, e));
  }
  ExactCast out;
  if (!best) {
    out.distance = std::numeric_limits<double>::infinity();
    return out;
  }
  out.hit = true;
  out.distance = CGAL::to_double(best->exact()) * std::hypot(d.x(), d.y());
  return out;
}

}  // namespace nonconvex2_test
