// Private: the convex pair sums S_ij = T_i ⊕ (−U_j) of two triangulated polygons, kept implicit
// (DHS §4.1 Step 2 generalised to two decompositions), the exact line algebra shared by the
// queries, and the box hierarchies over both triangulations (src/geometry/box_tree.hpp).
//
// Every point of a sum is symbolic: a vertex of P plus a vertex of B = −Q (exact negation), never
// rounded before a decision. A line is "through c1 + c2 with direction e1 − e0"; a ray is
// "origin o1 + o2, direction (a1 + a2) − (b1 + b2)" so that the query ray t + λ·d and an edge of a
// sum (from one sum vertex to the next) share one set of exact formulas. Each formula is a
// polynomial of degree ≤ 2 in the input doubles, evaluated with exact::exact_sign.
// The idea of the Cut/line parameter formulas is the one of src/polygon2/convolved_triangles
// (copied, not shared, so the two modules evolve independently).
#pragma once

#include <pendepth/depth2_polygon_polygon.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/box_tree.hpp"

namespace pendepth::nonconvex2 {

/// A line through c1 + c2 with direction e1 − e0, and where it comes from: either a triangle
/// edge p0 → p1 of P translated by the vertex −q0 of −Q (q_edge false, q0 = q1), or the edge
/// −q0 → −q1 of −U (Q's triangle edge q0 → q1) translated by the P vertex p0 (q_edge true,
/// p0 = p1). Interior of the sum on its left.
struct Line {
  Vec2 c1{0, 0}, c2{0, 0}, e0{0, 0}, e1{0, 0};
  std::uint32_t p0 = 0, p1 = 0, q0 = 0, q1 = 0;
  bool q_edge = false;
};

/// Ray (or parametrised line) o + λ·dir with o = o1 + o2 and dir = (a1 + a2) − (b1 + b2).
/// When `sym`, the ray is an edge of a sum: o is the sum vertex (p0, q0) (P vertex + −Q vertex)
/// and o + dir the vertex (p1, q1); lines through those vertices then have λ = 0 resp. 1 known
/// symbolically (shared vertices of neighbouring sums are everywhere; the numeric ties would
/// need rational arithmetic).
struct Ray {
  Vec2 o1{0, 0}, o2{0, 0}, a1{0, 0}, a2{0, 0}, b1{0, 0}, b2{0, 0};
  bool sym = false;
  std::uint32_t p0 = 0, q0 = 0, p1 = 0, q1 = 0;
  static Ray query(const Vec2& t, const Vec2& d) {
    Ray r;
    r.o1 = t;
    r.a1 = d;
    return r;
  }
};

/// A sum vertex: P vertex p + B vertex b (b = −Q vertex q).
struct SumVertex {
  Vec2 p, b;
  std::uint32_t pid = 0, qid = 0;
};

/// One convex pair sum: 6 edges in CCW order (consecutive collinear edges possible when a
/// triangle edge of P and one of −U are parallel), edge k from vertex k to vertex k + 1.
struct Sum {
  std::array<SumVertex, 6> v;
  std::array<Line, 6> e;
};

/// λ at which ray r meets line c: cross(c − o, e) / cross(dir, e). The generic helpers return the
/// numerator and denominator as polynomials of the lift L.
template <class L>
auto line_num(const Line& c, const Ray& r, L lift) {
  auto x = lift(c.c1.x()) + lift(c.c2.x()) - lift(r.o1.x()) - lift(r.o2.x());
  auto y = lift(c.c1.y()) + lift(c.c2.y()) - lift(r.o1.y()) - lift(r.o2.y());
  return x * (lift(c.e1.y()) - lift(c.e0.y())) - y * (lift(c.e1.x()) - lift(c.e0.x()));
}
template <class L>
auto ray_dx(const Ray& r, L lift) {
  return lift(r.a1.x()) + lift(r.a2.x()) - lift(r.b1.x()) - lift(r.b2.x());
}
template <class L>
auto ray_dy(const Ray& r, L lift) {
  return lift(r.a1.y()) + lift(r.a2.y()) - lift(r.b1.y()) - lift(r.b2.y());
}
template <class L>
auto line_den(const Line& c, const Ray& r, L lift) {
  return ray_dx(r, lift) * (lift(c.e1.y()) - lift(c.e0.y())) - ray_dy(r, lift) * (lift(c.e1.x()) - lift(c.e0.x()));
}

/// λ(c) when known symbolically (0 or 1: c passes through the ray's start or end vertex), else -1.
/// Only meaningful for c not parallel to r.
int known_lambda(const Line& c, const Ray& r);
/// Exact sign of λ(c) on ray r (c not parallel to r).
int line_sign(const Line& c, const Ray& r);
/// Exact comparison of λ(a) and λ(b) on ray r: -1, 0, +1.
int compare_lines(const Line& a, const Line& b, const Ray& r);
/// λ(c) to a few ulps.
double line_value(const Line& c, const Ray& r);

/// The open interval of λ where ray r's line lies in int S: false when it misses int S (also when
/// it only touches S's boundary). Entry and exit are edges of S. ≤ 6 + 10 exact predicates.
/// `along`: when the ray runs along the line of `*along` (an edge of some sum), edges of S on the
/// same symbolic line are recognised without arithmetic.
bool sum_interval(const Sum& S, const Ray& r, Line& entry, Line& exit, const Line* along = nullptr);
/// Symbolic identity of two edge lines (same edge of P or −U, translated by the same vertex).
bool same_line(const Line& a, const Line& b);
/// Exact: t ∈ int S.
bool sum_contains(const Sum& S, const Vec2& t);

/// A triangle in normal form (v_0 lowest-leftmost, CCW) with its global vertex ids.
struct Tri {
  std::array<Vec2, 3> v;
  std::array<std::uint32_t, 3> id;
  Vec2 lo, hi;  // bounding box (exact: coordinates are input doubles)
};

/// The box hierarchy over triangles and pieces, and the ray–box test: src/geometry/box_tree.hpp
/// (shared with polygon2); the names stay valid here.
using BoxTree = geometry::BoxTree;
using geometry::ray_box;

/// T ⊕ B for a P triangle and a −Q triangle (both normal form): exact angle merge, 5 comparisons.
Sum make_sum(const Tri& T, const Tri& B);

/// Conservative box of A ⊕ (−B's original) = [A.lo + B.lo, A.hi + B.hi] for B stored as −Q,
/// inflated outwards by a few ulps so the rounding of the sums never shrinks it.
void sum_box(const Vec2& alo, const Vec2& ahi, const Vec2& blo, const Vec2& bhi, Vec2& lo, Vec2& hi);

struct ShapeSide;  // shape_side.hpp: one shape's triangles, hierarchy and convex parts in one role

}  // namespace pendepth::nonconvex2

namespace pendepth {

struct PairDepth2::Impl {
  // The per-shape work (shape_side.hpp), shared with every other pair built from the same sides;
  // the names below are views into it.
  std::shared_ptr<const nonconvex2::ShapeSide> sp, sb;  // P as P; Q as −Q
  const Polygon &P, &Q;
  const std::vector<nonconvex2::Tri>&tp, &tb;  // P triangles; −Q triangles (vertex ids are Q's)
  const nonconvex2::BoxTree &hp, &hb;
  /// Fresh sides (nothing shared).
  Impl(const Polygon& p, const Polygon& q);
  /// Given sides: sp made with negate false, sb with negate true (shape_side.hpp).
  Impl(std::shared_ptr<const nonconvex2::ShapeSide> p, std::shared_ptr<const nonconvex2::ShapeSide> q);

  /// Visits the leaf pairs (i, j) whose sum box passes `accept(lo, hi)`; `leaf(i, j)` returns true
  /// to stop. Returns true if stopped. `stack`: a caller's scratch buffer (no allocation per call).
  using DescentStack = std::vector<std::pair<std::int32_t, std::int32_t>>;
  template <class Accept, class Leaf>
  bool descend(Accept&& accept, Leaf&& leaf, PairQueryStats* stats, DescentStack& stack) const;
  template <class Accept, class Leaf>
  bool descend(Accept&& accept, Leaf&& leaf, PairQueryStats* stats) const {
    DescentStack stack;
    return descend(accept, leaf, stats, stack);
  }

  /// Builds the result of moving Q from t by `translation` to the contact described by edge line E
  /// of a sum. `end` (decided exactly by the caller: 0 = E's start vertex, 1 = its end, -1 = neither)
  /// names the touching end when E comes from a triangulation diagonal, whose interior points are
  /// interior to the shape and so can never be the contact.
  Depth2 contact(const nonconvex2::Line& E, const Vec2& t, const Vec2& translation, int end) const;
  /// The same with depth and normal left for the caller (σ_d sets them from d: no hypot).
  Depth2 contact_features(const nonconvex2::Line& E, const Vec2& t, const Vec2& translation, int end) const;
};

/// Internal (src/front/pair2.cpp): wraps a built Impl (one made from shared per-shape sides).
PairDepth2 pair_from_impl(std::unique_ptr<PairDepth2::Impl> impl);

template <class Accept, class Leaf>
bool PairDepth2::Impl::descend(Accept&& accept, Leaf&& leaf, PairQueryStats* stats, DescentStack& stack) const {
  stack.assign(1, {0, 0});
  while (!stack.empty()) {
    auto [a, b] = stack.back();
    stack.pop_back();
    const auto &A = hp.nodes[a], &B = hb.nodes[b];
    Vec2 lo, hi;
    nonconvex2::sum_box(A.lo, A.hi, B.lo, B.hi, lo, hi);
    if (stats) ++stats->node_pairs;
    if (!accept(lo, hi)) continue;
    const bool la = A.left < 0, lb = B.left < 0;
    if (la && lb) {
      if (stats) ++stats->pairs;
      if (leaf(A.tri, B.tri)) return true;
      continue;
    }
    const bool split_a = lb || (!la && (A.hi - A.lo).sum() >= (B.hi - B.lo).sum());
    if (split_a) {
      stack.push_back({A.left, b});
      stack.push_back({A.right, b});
    } else {
      stack.push_back({a, B.left});
      stack.push_back({a, B.right});
    }
  }
  return false;
}

}  // namespace pendepth
