// The implicit union boundary ∂O of the convolved triangles (DHS §4.1 Step 3); representation and
// contract in union_boundary.hpp.
//
// Construction (departure from DHS, stated as the issue allows):
//   1. Candidates (Build::find_candidates): the reduced convolution of ∂P with B — one segment per
//      P edge, one implicit arc per convex vertex of P (≤ 2N candidates, O(N log m) binary
//      searches). Every contact placement with disjoint interiors lies on it (a vertex of Q against
//      an edge of P only with Q's vertex extreme for that edge's outward normal; a vertex of P
//      against an edge of Q only at a convex vertex with Q's edge normal in P's normal cone there).
//   2. Each candidate loses its points in O (Build::subtract_overlap). At a candidate point x,
//      Q + x touches ∂P with points outside P next to the contact, except possibly at the
//      candidate's natural ends (Q's vertex at a P vertex). So x ∈ O ⇔ int(Q + x) meets the
//      relative interior of some P edge f ⇔ x ∈ int(f ⊕ B) (the edge "sausage", an implicit
//      (m+2)-gon, ConvolvedTriangles::segment_*), or, at the ends, x ∈ int R_T for a triangle T
//      around the P vertex (its fan; R_T is cut with the end's element only when it contains the
//      end, an exact O(1) angle test at B's vertex there). Sausages have small boxes (|f| + |B|;
//      the R_i of long diagonals do not), found in a bounding-volume hierarchy (BVH,
//      src/geometry/box_tree.hpp); a segment meets an open convex (m+2)-gon in one open interval
//      (O(log m)). A candidate's own sausages (its edge; an arc's two edges) are skipped: it lies
//      on their boundaries. Arcs are split recursively into B-edge ranges (boxes in O(1) from B's
//      four extreme vertices); a range whose padded box has its four corners inside one sausage (at
//      most three tried, nearest edges first) is covered at once, a single B edge is cut by the
//      sausages meeting it until one covers it. Same-orientation coinciding copies (collinear,
//      overlapping, O on the same side) are removed from the candidate with the larger id
//      (candidate BVH). Sorting the open intervals and sweeping leaves the closed remnants. Ties
//      that are structural (two cuts on the same line, a convolution vertex on a line through it,
//      B-edge angle ranks, a B vertex shared by both sides of a side test) are decided without
//      arithmetic; all other decisions are filtered exact predicates, and the O(log m) binary
//      searches on the R_i and sausages run on the floating-point values with the answer confirmed
//      by two exact predicates (ConvolvedTriangles), so most of their steps cost no exact
//      evaluation.
//   3. Zero-length remnants lying on another piece are dropped (drop_covered_points).
//   4. Pieces are linked into rings by exact equality of their symbolic ends (candidates found by
//      sorting rounded coordinates), the clockwise-first rule at vertices with several
//      continuations (link_rings); each ring's orientation by its signed area (orient_rings).
//   5. The BVH over the piece boxes for the queries (index_pieces).
//   The paper's divide and conquer (O(N log²(N+m) + m)) is replaced by this local subtraction,
//   far simpler to make exact. Worst case: a candidate can meet Θ(N) sausages (Q much larger than
//   P's edges) and an arc Θ(m) B edges near one sausage, so the build is O(N²·m log m) in the worst
//   case. Output-sensitive first pass (Build::subtract_overlap, issue 19 item 4): a candidate with
//   more than 64 sausage boxes in reach is first tried against only the 32 sausages nearest to
//   its contact (best-first in a hierarchy over the edge midpoints, O(k log N)); if they
//   cover it entirely it has no piece (a subset of the covers proves it), else it is redone by the
//   full gathering above (the same pieces bit for bit: tests/polygon2/test_union_nearest.cpp).
//   The full gathering then costs O(reach) only for candidates that keep a piece of ∂O, so the
//   build is near-linear where ∂O is small against the sausages in reach (a star under a large Q:
//   10⁵ vertices in 2 s instead of 20 s). Chain hierarchy (Cover::gather_chain): for the segment
//   candidates that keep a piece while Q spans hundreds of edges (a finely sampled spiral: ~660
//   sausages in box reach, ~3 that can meet the candidate), the full gathering walks a binary tree
//   over P's edges in index order (rings are contiguous runs, so a node is mostly a chain of
//   ∂P) whose nodes keep a 16-direction k-DOP of their end points; a node is skipped when one of
//   those directions separates its sausages (k-DOP ⊕ B) from the candidate segment, an edge f
//   when the candidate lies beyond f's own candidate line or f lies on P's side of the
//   candidate's edge — all with a margin above the rounding error, so a skipped sausage cannot
//   meet the segment and would add no interval. The rest keep their order (a total order by
//   (distance, index)), so the intervals and pieces are the same bit for bit; a segment candidate
//   with at most 64 survivors skips the first pass. O(log N + k) per candidate for k survivors
//   plus the nodes that are near the candidate without being separated: the spiral of 10⁵
//   vertices builds in 0.47 s instead of 6.7 s (with the triangulation's insertion order,
//   triangulation.cpp). Arcs keep the unpruned gathering (few on smooth shapes).
//   Measured build times and the comparison with CGAL's reduced convolution: docs/benchmarks.md.
//   Space stays O(N + m): the transient interval lists are per candidate, the result is O(N)
//   pieces (Facts 4.1-4.2) plus three BVHs (pieces, sausages, edges: O(N)); B is shared with the
//   convolved triangles; the chain hierarchy (about N/3 nodes of 22 words) lives during the build only.
//
// Queries: ray shooting and nearest point are branch-and-bound on the BVH over the piece boxes
// (DHS §4.3 uses ears + partition trees, §4.2 / Lemma 4.3 the visibility polygon); within an arc,
// a line is located by binary search on B (O(log m)), the nearest point by branch-and-bound on
// B-edge ranges. t ∈ O: a sausage containing t (BVH), else the parity of the horizontal ray from
// an interior point of Q + t through P's edges (edge BVH). The last exit (complete separation):
// the largest exit from an open sausage (the last overlapping placements have Q + x ⊄ P).
// All decisions exact; boxes and floating bounds only prune.
#include "polygon2/union_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "geometry/box_tree.hpp"
#include "geometry/exact.hpp"

namespace pendepth::polygon2 {

using exact::exact_sign;

namespace {

const Vec2 kZero(0, 0);

// compare_angle with the tie of an edge with itself decided by construction (an exact zero costs
// the rational fallback; arcs of different vertices share their B edges).
int compare_angle(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  if (a0 == b0 && a1 == b1) return 0;
  return predicates::compare_angle(a0, a1, b0, b1);
}


// A parameter μ on an element's line S + μ·D (S = pt + pb, D = e1 − e0), as num/den.
struct Mu {
  enum K : std::uint8_t { C0, C1, Line, Pt, Ray, Foot } k = C0;
  Cut o;          // Line: crossing with o's line
  Vec2 p, b;      // Pt: the point p + b (on the line); Ray: t = p, d = b; Foot: t = p
  std::uint32_t pi = 0, bi = 0;
};

template <class LF>
auto mu_num(const Cut& E, const Mu& s, LF L) -> decltype(L(0.0)) {
  switch (s.k) {
    case Mu::C0:
      return L(0.0);
    case Mu::C1:
      return L(1.0);
    default:
      break;
  }
  auto Sx = L(E.pt.x()) + L(E.pb.x()), Sy = L(E.pt.y()) + L(E.pb.y());
  auto Dx = L(E.e1.x()) - L(E.e0.x()), Dy = L(E.e1.y()) - L(E.e0.y());
  switch (s.k) {
    case Mu::Line: {
      const Cut& O = s.o;
      auto Ox = L(O.pt.x()) + L(O.pb.x()) - Sx, Oy = L(O.pt.y()) + L(O.pb.y()) - Sy;
      return Ox * (L(O.e1.y()) - L(O.e0.y())) - Oy * (L(O.e1.x()) - L(O.e0.x()));
    }
    case Mu::Pt:
      return (L(s.p.x()) + L(s.b.x()) - Sx) * Dx + (L(s.p.y()) + L(s.b.y()) - Sy) * Dy;
    case Mu::Ray:
      return (L(s.p.x()) - Sx) * L(s.b.y()) - (L(s.p.y()) - Sy) * L(s.b.x());
    default:  // Foot
      return (L(s.p.x()) - Sx) * Dx + (L(s.p.y()) - Sy) * Dy;
  }
}

template <class LF>
auto mu_den(const Cut& E, const Mu& s, LF L) -> decltype(L(0.0)) {
  if (s.k == Mu::C0 || s.k == Mu::C1) return L(1.0);
  auto Dx = L(E.e1.x()) - L(E.e0.x()), Dy = L(E.e1.y()) - L(E.e0.y());
  switch (s.k) {
    case Mu::Line:
      return Dx * (L(s.o.e1.y()) - L(s.o.e0.y())) - Dy * (L(s.o.e1.x()) - L(s.o.e0.x()));
    case Mu::Ray:
      return Dx * L(s.b.y()) - Dy * L(s.b.x());
    default:  // Pt, Foot
      return Dx * Dx + Dy * Dy;
  }
}

int mu_den_sign(const Cut& E, const Mu& a) {
  if (a.k == Mu::C0 || a.k == Mu::C1) return 1;
  return exact_sign([&](auto L) { return mu_den(E, a, L); });
}

// Does the line of O contain the convolution vertex p + b by construction (one of its two
// natural points)? Exact and free; used to skip the rational fallback on the frequent ties.
bool on_line_struct(const Cut& O, const Vec2& p, const Vec2& b) {
  if (O.b_edge) return O.pt == p && (O.e0 == b || O.e1 == b) && O.pb == O.e0;
  return O.pb == b && (O.e0 == p || O.e1 == p) && O.pt == O.e0;
}
// 0 / 1 when the parameter is E's natural start / end by construction, -1 when unknown.
int struct_end(const Cut& E, const Mu& a) {
  if (a.k == Mu::C0) return 0;
  if (a.k == Mu::C1) return 1;
  const Vec2 &sp = E.pt, &sb = E.pb;
  const Vec2& ep = E.b_edge ? E.pt : E.e1;
  const Vec2& eb = E.b_edge ? E.e1 : E.pb;
  if (a.k == Mu::Line) {
    if (on_line_struct(a.o, sp, sb)) return 0;
    if (on_line_struct(a.o, ep, eb)) return 1;
  } else if (a.k == Mu::Pt) {
    if (a.p == sp && a.b == sb) return 0;
    if (a.p == ep && a.b == eb) return 1;
  }
  return -1;
}
bool same_cut_line(const Cut& a, const Cut& b) { return a.pt == b.pt && a.pb == b.pb && a.e0 == b.e0 && a.e1 == b.e1; }

// Exact comparison of two parameters on E's line (both dens non-zero).
int cmp_mu(const Cut& E, const Mu& a, const Mu& b) {
  if ((a.k == Mu::C0 || a.k == Mu::C1) && (b.k == Mu::C0 || b.k == Mu::C1)) return int(a.k) - int(b.k);
  if (a.k == Mu::Line && b.k == Mu::Line && same_cut_line(a.o, b.o)) return 0;
  {  // both at a natural end of E by construction
    const int sa = struct_end(E, a), sb = struct_end(E, b);
    if (sa >= 0 && sb >= 0) return sa - sb;
  }
  const int da = mu_den_sign(E, a), db = mu_den_sign(E, b);
  const int s = exact_sign([&](auto L) { return mu_num(E, a, L) * mu_den(E, b, L) - mu_num(E, b, L) * mu_den(E, a, L); });
  return s * da * db;
}

Mu c0() { return Mu{}; }
Mu c1() {
  Mu m;
  m.k = Mu::C1;
  return m;
}
Mu line_mu(const Cut& o) {
  Mu m;
  m.k = Mu::Line;
  m.o = o;
  return m;
}

Mu mu_of(const EndPoint& e) {
  Mu m;
  switch (e.kind) {
    case EndPoint::Kind::Mu0:
      m.k = Mu::C0;
      break;
    case EndPoint::Kind::Mu1:
      m.k = Mu::C1;
      break;
    case EndPoint::Kind::Crossing:
      m.k = Mu::Line;
      m.o = e.other;
      break;
    case EndPoint::Kind::Point:
      m.k = Mu::Pt;
      m.p = e.p;
      m.b = e.b;
      m.pi = e.p_index;
      m.bi = e.b_index;
      break;
  }
  return m;
}

EndPoint end_of(const Mu& m) {
  EndPoint e;
  switch (m.k) {
    case Mu::C0:
      e.kind = EndPoint::Kind::Mu0;
      break;
    case Mu::C1:
      e.kind = EndPoint::Kind::Mu1;
      break;
    case Mu::Line:
      e.kind = EndPoint::Kind::Crossing;
      e.other = m.o;
      break;
    default:
      e.kind = EndPoint::Kind::Point;
      e.p = m.p;
      e.b = m.b;
      e.p_index = m.pi;
      e.b_index = m.bi;
      break;
  }
  return e;
}

// Homogeneous coordinates (X, Y, W) of the point at parameter m on E (W != 0).
template <class LF>
std::array<decltype(LF{}(0.0)), 3> point_h(const Cut& E, const Mu& m, LF L) {
  auto Sx = L(E.pt.x()) + L(E.pb.x()), Sy = L(E.pt.y()) + L(E.pb.y());
  switch (m.k) {
    case Mu::C0:
      return {Sx, Sy, L(1.0)};
    case Mu::C1:
      return {Sx + L(E.e1.x()) - L(E.e0.x()), Sy + L(E.e1.y()) - L(E.e0.y()), L(1.0)};
    case Mu::Pt:
      return {L(m.p.x()) + L(m.b.x()), L(m.p.y()) + L(m.b.y()), L(1.0)};
    default: {
      auto n = mu_num(E, m, L), d = mu_den(E, m, L);
      return {Sx * d + n * (L(E.e1.x()) - L(E.e0.x())), Sy * d + n * (L(E.e1.y()) - L(E.e0.y())), d};
    }
  }
}

// The convolution vertex p + b that parameter m on E is by construction (C0/C1/Pt, or a crossing
// that struct_end places at a natural end); false when not known structurally.
bool struct_vertex(const Cut& E, const Mu& m, Vec2& p, Vec2& b) {
  if (m.k == Mu::Pt) {
    p = m.p;
    b = m.b;
    return true;
  }
  const int e = struct_end(E, m);
  if (e < 0) return false;
  p = e == 0 ? E.pt : (E.b_edge ? E.pt : E.e1);
  b = e == 0 ? E.pb : (E.b_edge ? E.e1 : E.pb);
  return true;
}

bool same_point(const Cut& E1, const Mu& m1, const Cut& E2, const Mu& m2) {
  {  // the same vertex by construction: equal without the (rational) fallback that ties need
    Vec2 p1, b1, p2, b2;
    if (struct_vertex(E1, m1, p1, b1) && struct_vertex(E2, m2, p2, b2) && p1 == p2 && b1 == b2) return true;
  }
  // The crossing of the same two (non-parallel) lines, named from either side.
  if (m1.k == Mu::Line && m2.k == Mu::Line &&
      ((same_cut_line(E1, m2.o) && same_cut_line(m1.o, E2)) || (same_cut_line(E1, E2) && same_cut_line(m1.o, m2.o))))
    return true;
  // A coordinate certified different by the cheap tier decides first: on axis-parallel input one
  // coordinate often ties exactly, and deciding it would need the rational fallback.
  {
    const auto a = point_h(E1, m1, exact::LiftFl{});
    const auto b = point_h(E2, m2, exact::LiftFl{});
    for (int c = 0; c < 2; ++c)
      if (exact::certified_sign(a[c] * b[2] - b[c] * a[2]) != 2) return false;
  }
  for (int c = 0; c < 2; ++c) {
    const int s = exact_sign([&](auto L) {
      auto a = point_h(E1, m1, L);
      auto b = point_h(E2, m2, L);
      return a[c] * b[2] - b[c] * a[2];
    });
    if (s != 0) return false;
  }
  return true;
}

// The point rounded: per coordinate exactly what exact::accurate_value (natural points) or
// exact::accurate_ratio (crossings) return, with the homogeneous coordinates evaluated once per
// tier instead of once per coordinate and tier.
Vec2 approx_point(const Cut& E, const Mu& m) {
  const auto fl = point_h(E, m, exact::LiftFl{});
  std::array<exact::DD, 3> dd;
  bool have_dd = false;
  auto value = [&](int c, double& out) {  // exact::detail::floating_value on coordinate c
    const exact::Fl& r = fl[c];
    if (std::isfinite(r.v) && exact::safe_bound(r.e) <= std::abs(r.v) * 0x1p-53) {
      out = r.v;
      return true;
    }
    if (!have_dd) {
      dd = point_h(E, m, exact::LiftDD{});
      have_dd = true;
    }
    const exact::DD& d = dd[c];
    if (exact::dd_finite(d) && exact::safe_bound(d.e) <= std::abs(d.hi) * 0x1p-54) {
      out = d.hi;
      return true;
    }
    return false;
  };
  Vec2 r;
  if (m.k == Mu::C0 || m.k == Mu::C1 || m.k == Mu::Pt) {
    for (int c = 0; c < 2; ++c) {
      double v;
      r[c] = value(c, v) ? v : point_h(E, m, exact::LiftQ{})[c].v.get_d();
    }
    return r;
  }
  for (int c = 0; c < 2; ++c) {
    double a, b;
    if (value(c, a) && value(2, b) && b != 0) {
      const double q = a / b;
      if (std::isfinite(q) && (q != 0 || a == 0)) {
        r[c] = q;
        continue;
      }
    }
    const auto h = point_h(E, m, exact::LiftQ{});
    r[c] = mpq_class(h[c].v / h[2].v).get_d();
  }
  return r;
}

// λ of a hit on the line t + λ·d, as num/den.
template <class LF>
auto lam_num(const Hit& h, const Vec2& t, const Vec2& d, LF L) -> decltype(L(0.0)) {
  if (h.is_point)
    return (L(h.p.x()) + L(h.b.x()) - L(t.x())) * L(d.x()) + (L(h.p.y()) + L(h.b.y()) - L(t.y())) * L(d.y());
  const Cut& c = h.cut;
  return (L(c.pt.x()) + L(c.pb.x()) - L(t.x())) * (L(c.e1.y()) - L(c.e0.y())) -
         (L(c.pt.y()) + L(c.pb.y()) - L(t.y())) * (L(c.e1.x()) - L(c.e0.x()));
}
template <class LF>
auto lam_den(const Hit& h, const Vec2& d, LF L) -> decltype(L(0.0)) {
  if (h.is_point) return L(d.x()) * L(d.x()) + L(d.y()) * L(d.y());
  const Cut& c = h.cut;
  return L(d.x()) * (L(c.e1.y()) - L(c.e0.y())) - L(d.y()) * (L(c.e1.x()) - L(c.e0.x()));
}

// Squared distance of a Near to t, as num/den (den > 0).
template <class LF>
std::array<decltype(LF{}(0.0)), 2> near_d2(const Near& n, const Vec2& t, LF L) {
  const Cut& E = n.cut;
  auto Sx = L(E.pt.x()) + L(E.pb.x()) - L(t.x()), Sy = L(E.pt.y()) + L(E.pb.y()) - L(t.y());
  auto Dx = L(E.e1.x()) - L(E.e0.x()), Dy = L(E.e1.y()) - L(E.e0.y());
  switch (n.kind) {
    case Near::Kind::Foot: {
      auto c = Dx * Sy - Dy * Sx;
      return {c * c, Dx * Dx + Dy * Dy};
    }
    case Near::Kind::Point: {
      auto x = L(n.p.x()) + L(n.b.x()) - L(t.x()), y = L(n.p.y()) + L(n.b.y()) - L(t.y());
      return {x * x + y * y, L(1.0)};
    }
    default: {
      Mu m = line_mu(n.other);
      auto num = mu_num(E, m, L), den = mu_den(E, m, L);
      auto x = Sx * den + num * Dx, y = Sy * den + num * Dy;
      return {x * x + y * y, den * den};
    }
  }
}

// ---- boxes (xmin, ymin, xmax, ymax) and the hierarchies over them (src/geometry/box_tree.hpp) ----
using Box = std::array<double, 4>;
using geometry::BoxTree;

Vec2 box_lo(const Box& b) { return Vec2(b[0], b[1]); }
Vec2 box_hi(const Box& b) { return Vec2(b[2], b[3]); }

// The hierarchy over `boxes`: median splits, up to 4 items per leaf.
void build_tree(BoxTree& T, const std::vector<Box>& boxes) {
  T.build_buckets<4>(boxes.size(), [&](std::size_t k) { return box_lo(boxes[k]); }, [&](std::size_t k) { return box_hi(boxes[k]); });
}

bool boxes_meet(const Box& a, const Box& b) { return !(a[0] > b[2] || a[2] < b[0] || a[1] > b[3] || a[3] < b[1]); }

Box pad(Box r) {
  for (int c = 0; c < 4; ++c) {
    const double p = std::abs(r[c]) * 0x1p-50 + 0x1p-1000;
    r[c] += c < 2 ? -p : p;
  }
  return r;
}

// Parameter range [enter, exit] of the ray t + λ·d inside node n (conservative, widened), or false.
bool ray_node(const BoxTree::Node& n, const Vec2& t, const Vec2& d, double& enter, double& exit) {
  return geometry::ray_box<geometry::RaySlack::Interval>(t, d, n.lo, n.hi, enter, exit);
}

double box_dist2(const Vec2& lo, const Vec2& hi, const Vec2& t) {
  const double dx = std::max({lo.x() - t.x(), 0.0, t.x() - hi.x()}), dy = std::max({lo.y() - t.y(), 0.0, t.y() - hi.y()});
  return (dx * dx + dy * dy) * (1 - 0x1p-40);
}
double box_dist2(const Box& b, const Vec2& t) { return box_dist2(box_lo(b), box_hi(b), t); }

// Clockwise order of directions w (as edge pairs) starting from the reference r, exact.
int cw_class(const Vec2& r0, const Vec2& r1, const Vec2& w0, const Vec2& w1) {
  const int c = predicates::cross_edges(r0, r1, w0, w1);
  if (c == 0) return predicates::dot_edges(r0, r1, w0, w1) > 0 ? 0 : 2;
  return c < 0 ? 1 : 3;
}
bool cw_less(const Vec2& r0, const Vec2& r1, const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  const int ca = cw_class(r0, r1, a0, a1), cb = cw_class(r0, r1, b0, b1);
  if (ca != cb) return ca < cb;
  if (ca == 0 || ca == 2) return false;
  return predicates::cross_edges(a0, a1, b0, b1) < 0;
}

}  // namespace

namespace {
std::array<mpq_class, 2> exact_point(const Cut& E, const Mu& mu) {
  auto h = point_h(E, mu, exact::LiftQ{});
  return {mpq_class(h[0].v / h[2].v), mpq_class(h[1].v / h[2].v)};
}
}  // namespace

// ---- free functions on hits / nears ----

int hit_sign(const Hit& h, const Vec2& t, const Vec2& d) {
  return exact_sign([&](auto L) { return lam_num(h, t, d, L); }) * exact_sign([&](auto L) { return lam_den(h, d, L); });
}

int compare_hits(const Hit& a, const Hit& b, const Vec2& t, const Vec2& d) {
  const int sa = exact_sign([&](auto L) { return lam_den(a, d, L); });
  const int sb = exact_sign([&](auto L) { return lam_den(b, d, L); });
  const int s = exact_sign([&](auto L) { return lam_num(a, t, d, L) * lam_den(b, d, L) - lam_num(b, t, d, L) * lam_den(a, d, L); });
  return s * sa * sb;
}

double hit_value(const Hit& h, const Vec2& t, const Vec2& d) {
  if (!h.is_point) return cut_value(h.cut, t, d);
  return exact::accurate_ratio([&](auto L) { return lam_num(h, t, d, L); }, [&](auto L) { return lam_den(h, d, L); });
}

int compare_near(const Near& a, const Near& b, const Vec2& t) {
  return exact_sign([&](auto L) {
    auto x = near_d2(a, t, L);
    auto y = near_d2(b, t, L);
    return x[0] * y[1] - y[0] * x[1];
  });
}

double near_distance(const Near& n, const Vec2& t) {
  return std::sqrt(exact::accurate_ratio([&](auto L) { return near_d2(n, t, L)[0]; }, [&](auto L) { return near_d2(n, t, L)[1]; }));
}

Vec2 near_point(const Near& n) {
  // Foot: t is not stored here; callers use near_point_at(n, t) semantics through UnionBoundary.
  Mu m;
  switch (n.kind) {
    case Near::Kind::Point:
      m.k = Mu::Pt;
      m.p = n.p;
      m.b = n.b;
      break;
    case Near::Kind::Crossing:
      m = line_mu(n.other);
      break;
    default:
      m.k = Mu::Foot;
      m.p = n.p;  // the foot's placement t is kept in p (set by nearest_on_piece)
      break;
  }
  return approx_point(n.cut, m);
}

// ---- the structure ----

struct UnionBoundary::Index {
  BoxTree pieces, sausages, edges;  // pieces of ∂O; the edge sausages f_g ⊕ B; P's edges
  std::vector<Box> piece_box;
  std::array<std::uint32_t, 4> ext{};  // B vertices with min x, min y, max x, max y
};

namespace {

struct Candidate {
  bool arc = false;
  std::uint32_t p = 0, b0 = 0, count = 1;  // arc: B edges b0 .. b0 + count − 1
};

struct Pos {
  std::uint32_t j = 0;
  Mu mu;
};

struct Interval {
  Pos s, e;
  bool s_incl = false, e_incl = false;
};

}  // namespace

UnionBoundary::~UnionBoundary() = default;
UnionBoundary::UnionBoundary(UnionBoundary&&) noexcept = default;
UnionBoundary& UnionBoundary::operator=(UnionBoundary&&) noexcept = default;

std::size_t UnionBoundary::element_count(std::size_t k) const {
  const Piece& pc = pieces_[k];
  if (pc.kind == Piece::Kind::Segment) return 1;
  const std::size_t m = R_->B().size();
  return (pc.b1 + m - pc.b0) % m + 1;
}

Cut UnionBoundary::element(std::size_t k, std::size_t j) const {
  const Piece& pc = pieces_[k];
  const auto& B = R_->B();
  const std::size_t m = B.size();
  const auto V = P_->vertices();
  Cut c;
  if (pc.kind == Piece::Kind::Segment) {
    c.pt = V[pc.p];
    c.pb = B[pc.b0];
    c.e0 = V[pc.p];
    c.p_from = pc.p;
    c.p_to = static_cast<std::uint32_t>(P_->next(pc.p));
    c.e1 = V[c.p_to];
    c.b = pc.b0;
    c.b_edge = false;
  } else {
    const std::size_t bk = (pc.b0 + j) % m;
    c.pt = V[pc.p];
    c.pb = B[bk];
    c.e0 = B[bk];
    c.e1 = B[(bk + 1) % m];
    c.p_from = c.p_to = pc.p;
    c.b = static_cast<std::uint32_t>(bk);
    c.b_edge = true;
  }
  return c;
}

Vec2 UnionBoundary::start_point(std::size_t k) const { return approx_point(element(k, 0), mu_of(pieces_[k].start)); }
Vec2 UnionBoundary::end_point(std::size_t k) const {
  return approx_point(element(k, element_count(k) - 1), mu_of(pieces_[k].end));
}
std::array<mpq_class, 2> UnionBoundary::exact_start(std::size_t k) const { return exact_point(element(k, 0), mu_of(pieces_[k].start)); }
std::array<mpq_class, 2> UnionBoundary::exact_end(std::size_t k) const {
  return exact_point(element(k, element_count(k) - 1), mu_of(pieces_[k].end));
}
std::array<double, 4> UnionBoundary::box(std::size_t k) const { return index_->piece_box[k]; }

// ---- construction (DHS §4.1 Step 3; the steps are described in the file header) ----

namespace {

// A closed remnant of candidate `cand` from position a to position b (a piece before linking).
struct Raw {
  std::uint32_t cand;
  Pos a, b;
};

// Padded box of the B vertices k0 .. k0 + len (cyclic, len + 1 vertices) translated by v, from
// the two end vertices and those of B's extreme vertices `ext` in the range. O(1).
Box range_box(const std::vector<Vec2>& B, const std::array<std::uint32_t, 4>& ext, const Vec2& v, std::size_t k0,
              std::size_t len) {
  const std::size_t m = B.size();
  Box r{INFINITY, INFINITY, -INFINITY, -INFINITY};
  auto add = [&](std::size_t k) {
    const Vec2& b = B[k % m];
    r[0] = std::min(r[0], b.x());
    r[1] = std::min(r[1], b.y());
    r[2] = std::max(r[2], b.x());
    r[3] = std::max(r[3], b.y());
  };
  add(k0);
  add(k0 + len);
  for (std::uint32_t e : ext)
    if ((e + m - k0 % m) % m <= len) add(e);
  r[0] += v.x();
  r[1] += v.y();
  r[2] += v.x();
  r[3] += v.y();
  return pad(r);
}

// Padded box of the segment a → b translated by t.
Box segment_box(const Vec2& a, const Vec2& b, const Vec2& t) {
  return pad(Box{std::min(a.x(), b.x()) + t.x(), std::min(a.y(), b.y()) + t.y(), std::max(a.x(), b.x()) + t.x(),
                 std::max(a.y(), b.y()) + t.y()});
}

// Half-width of the window in which rounded copies of one exact point p lie (a few ulps).
double point_tol(const Vec2& p) { return (std::abs(p.x()) + std::abs(p.y())) * 0x1p-44 + 0x1p-1000; }

// Steps 1-2 of the construction: the candidates (the reduced convolution of ∂P with B) and the
// closed remnants each keeps outside O. Scratch buffers are reused from candidate to candidate.
struct Build {
  const Polygon& P;
  const ConvolvedTriangles& R;
  UnionBoundary::Index& X;
  std::span<const Vec2> V;
  const std::vector<Vec2>& B;
  std::size_t N, m;
  std::vector<std::uint32_t> prev;  // prev[next(g)] = g
  std::vector<Candidate> cand;      // segments 0..N-1 by P edge, then arcs by P vertex
  std::vector<Box> sbox, cb;        // boxes of the edge sausages; of the candidates
  BoxTree cbvh;                     // over cb
  std::vector<Vec2> key;            // key[g] = V[g] + V[next(g)]: twice edge g's midpoint
  BoxTree keys;                     // over the points key[g] (the nearest-first search)
  std::vector<Raw> raw;             // the remnants, candidate by candidate
  std::vector<Interval> ivs;        // scratch: the current candidate's covered intervals
  std::vector<std::uint32_t> near;  // scratch: sausages / candidates near the current candidate
  std::vector<std::pair<std::uint32_t, std::uint32_t>> st;  // scratch: B-edge ranges [lo, hi)
  bool nearest_first = true;        // the output-sensitive first pass of subtract_overlap
  std::size_t covered_early = 0;    // candidates it found entirely inside O
  std::size_t chain_pruned = 0;     // chain nodes and edges the separation tests skipped

  // The chain hierarchy (segment candidates' full gathering, output-sensitive): a binary tree over
  // P's edges in index order (each ring a contiguous run), leaves of up to 8 edges; a node keeps the
  // union of its edges' sausage boxes and a k-DOP of its edges' end points — the minimum of u_k·v
  // over them for kDirs unit-ish directions u_k spread over the circle. A node whose k-DOP, grown
  // by B, lies beyond the candidate segment in some u_k (with a margin above the rounding error)
  // holds no sausage meeting the segment.
  static constexpr int kDirs = 16;
  struct ChainNode {
    std::uint32_t lo = 0, hi = 0;            // edges lo .. hi − 1
    std::int32_t left = -1, right = -1;      // children; leaf when left < 0
    Box box{};                               // union of sbox over the edges
    std::array<double, kDirs> dop{};         // min over the edges' end points of u_k·v
  };
  std::vector<ChainNode> chain;
  std::array<Vec2, kDirs> dirs;
  std::array<double, kDirs> bmin{};  // min over B of u_k·b
  double sep_margin = 0;             // bound on the rounding error of the separation tests
  std::vector<std::uint32_t> stack;  // scratch: chain nodes to visit
  std::int32_t build_chain(std::uint32_t lo, std::uint32_t hi);

  // B's extreme vertices (into X.ext) and P's predecessor links. O(N + m).
  Build(const Polygon& P_in, const ConvolvedTriangles& R_in, UnionBoundary::Index& X_in);
  // First B edge whose angle is >= angle(x1 − x0) (m if none). O(log m).
  std::uint32_t lower(const Vec2& x0, const Vec2& x1) const;
  // Element j of candidate c as a Cut (a segment has the one element j = 0).
  Cut elem(const Candidate& c, std::size_t j) const;
  Box cand_box(const Candidate& c) const;

  // Step 1: one segment per P edge, one arc per convex vertex with a non-empty B-edge range.
  // O(N log m).
  void find_candidates();
  // The hierarchies over the edge sausages (X.sausages), P's edges (X.edges) and the candidates
  // (cbvh), with the boxes sbox, cb. O(N log N).
  void build_hierarchies();
  // Step 2 for candidate ci: appends to `raw` its closed remnants outside O (its points in no
  // int R_T of its ends' fans, in no sausage other than its own, and not on a same-orientation
  // copy in a candidate of smaller id), in order along the candidate.
  void subtract_overlap(std::uint32_t ci);
  // The pieces of the remnants (ring links not yet set).
  std::vector<Piece> pieces() const;
};

// The covered parts of one candidate: open (or, at the candidate's ends, closed) intervals of
// positions (element j, μ) lying in O, collected in `ivs`, and the sweep leaving the rest.
struct Cover {
  Build& S;
  const std::uint32_t ci;
  const Candidate& C;
  const std::uint32_t Lc;  // number of elements
  LineDir seg_dir;         // a segment's direction data, computed at most once (O(log m))
  bool have_seg_dir = false;

  Cover(Build& s, std::uint32_t c) : S(s), ci(c), C(s.cand[c]), Lc(C.arc ? C.count : 1) {}
  // An interval ending at μ = 1 of a non-last element ends at μ = 0 of the next one instead.
  void normalize_end(Interval& I) const;
  // Open interval (in, out) of element j's line inside some int R: clip to the element.
  void add_cover(std::uint32_t j, const Cut& E, const Cut& in, const Cut& out);
  // Open overlap of element j with the collinear, same-direction segment [x0, x1] (points p + b).
  void add_coincident(std::uint32_t j, const Cut& E, const Mu& x0, const Mu& x1);
  Mu pt_mu(std::uint32_t pi, std::uint32_t bi) const;
  int cmp_pos(const Pos& a, const Pos& b) const;
  // Sweep: the closed remnants of `list` (appended to S.raw when `emit`); whether any exists.
  bool sweep(std::vector<Interval>& list, bool emit) const;
  // S.near := the sausages whose boxes meet the candidate's, except its own, likely covers first
  // (sorted by (distance, index): a canonical order). With `prune` (segment candidates only): minus
  // sausages proven not to meet the candidate segment (their interiors could add no interval; the
  // order of the rest is unchanged, so the same intervals in the same order: the same pieces),
  // found in the chain hierarchy, O(log N + k) for the k sausages not pruned.
  // False (S.near incomplete, unordered) once more than `cap` sausages are found.
  bool gather_sausages(bool prune = false, std::size_t cap = SIZE_MAX);
  // The sausages of the chain hierarchy surviving the separation tests (into S.near, unordered);
  // false once more than `cap` are found.
  bool gather_chain(std::size_t cap);
  // S.near := up to `count` sausages whose boxes meet the candidate's, except its own, nearest to
  // its contact first (by the distance gather_sausages orders by), found best-first in the
  // hierarchy over the edge midpoints (S.keys) without visiting the others. O(count log N).
  void gather_nearest(std::size_t count);
  // The candidate's natural ends inside int R_T of a fan triangle T at its P vertices.
  void cover_ends_by_fans();
  // Element ranges inside sausages: a range whose box lies in one is covered at once; a single
  // element is cut by the sausages meeting it until it is covered.
  void cover_by_sausages();
  // Same-orientation coinciding copies in candidates with a smaller id.
  void cover_coincident();
};

Build::Build(const Polygon& P_in, const ConvolvedTriangles& R_in, UnionBoundary::Index& X_in)
    : P(P_in), R(R_in), X(X_in), V(P_in.vertices()), B(R_in.B()), N(V.size()), m(B.size()) {
  for (std::uint32_t k = 0; k < m; ++k) {
    if (B[k].x() < B[X.ext[0]].x()) X.ext[0] = k;
    if (B[k].y() < B[X.ext[1]].y()) X.ext[1] = k;
    if (B[k].x() > B[X.ext[2]].x()) X.ext[2] = k;
    if (B[k].y() > B[X.ext[3]].y()) X.ext[3] = k;
  }
  prev.resize(N);
  for (std::size_t g = 0; g < N; ++g) prev[P.next(g)] = static_cast<std::uint32_t>(g);
}

std::uint32_t Build::lower(const Vec2& x0, const Vec2& x1) const {
  std::size_t lo = 0, hi = m;
  while (lo < hi) {
    std::size_t mid = (lo + hi) / 2;
    if (compare_angle(B[mid], B[(mid + 1) % m], x0, x1) >= 0) hi = mid;
    else lo = mid + 1;
  }
  return static_cast<std::uint32_t>(lo);
}

Cut Build::elem(const Candidate& c, std::size_t j) const {
  Cut e;
  if (!c.arc) {
    e.pt = V[c.p];
    e.pb = B[c.b0];
    e.e0 = V[c.p];
    e.p_from = c.p;
    e.p_to = static_cast<std::uint32_t>(P.next(c.p));
    e.e1 = V[e.p_to];
    e.b = c.b0;
  } else {
    const std::size_t bk = (c.b0 + j) % m;
    e.pt = V[c.p];
    e.pb = B[bk];
    e.e0 = B[bk];
    e.e1 = B[(bk + 1) % m];
    e.p_from = e.p_to = c.p;
    e.b = static_cast<std::uint32_t>(bk);
    e.b_edge = true;
  }
  return e;
}

Box Build::cand_box(const Candidate& c) const {
  if (c.arc) return range_box(B, X.ext, V[c.p], c.b0, c.count);
  return segment_box(V[c.p], V[P.next(c.p)], B[c.b0]);
}

void Build::find_candidates() {
  cand.reserve(2 * N);
  for (std::uint32_t g = 0; g < N; ++g) {
    Candidate c;
    c.p = g;
    c.b0 = lower(V[g], V[P.next(g)]) % m;
    cand.push_back(c);
  }
  for (std::uint32_t g = 0; g < N; ++g) {
    const std::size_t a = prev[g], n = P.next(g);
    if (predicates::orient2d(V[a], V[g], V[n]) <= 0) continue;  // reflex or straight: no arc
    const std::uint32_t lo = lower(V[a], V[g]) % m, hi = lower(V[g], V[n]) % m;
    const std::uint32_t cnt = static_cast<std::uint32_t>((hi + m - lo) % m);
    if (cnt == 0) continue;
    Candidate c;
    c.arc = true;
    c.p = g;
    c.b0 = lo;
    c.count = cnt;
    cand.push_back(c);
  }
}

void Build::build_hierarchies() {
  sbox.resize(R.segment_count());
  for (std::size_t g = 0; g < sbox.size(); ++g) sbox[g] = R.segment_box(g);
  {
    std::vector<Box> sb = sbox;
    build_tree(X.sausages, sb);
    for (std::size_t g = 0; g < sb.size(); ++g) {
      const Vec2 &a = V[g], &b = V[P.next(g)];
      sb[g] = Box{std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.x(), b.x()), std::max(a.y(), b.y())};
    }
    build_tree(X.edges, sb);
  }
  cb.resize(cand.size());
  for (std::size_t c = 0; c < cand.size(); ++c) cb[c] = cand_box(cand[c]);
  build_tree(cbvh, cb);
  key.resize(sbox.size());
  for (std::size_t g = 0; g < key.size(); ++g) key[g] = V[g] + V[P.next(g)];
  // The chain hierarchy: directions, B's support, the error margin, the nodes.
  double mag = 0;
  for (const Vec2& v : V) mag = std::max({mag, std::abs(v.x()), std::abs(v.y())});
  double bmag = 0;
  for (const Vec2& b : B) bmag = std::max({bmag, std::abs(b.x()), std::abs(b.y())});
  // Each compared value is a sum of at most four products u·w, |u|∞ ≤ 1, |w|∞ ≤ 2(mag + bmag),
  // rounded a few times: 2^-44 of that bounds the error of a difference of two such values.
  sep_margin = (mag + bmag) * 0x1p-44 + 0x1p-1000;
  for (int k = 0; k < kDirs; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / kDirs;
    dirs[k] = Vec2(std::cos(a), std::sin(a));
    bmin[k] = std::numeric_limits<double>::infinity();
    for (const Vec2& b : B) bmin[k] = std::min(bmin[k], dirs[k].dot(b));
  }
  chain.clear();
  chain.reserve(N / 4 + 2);
  if (N > 0) build_chain(0, static_cast<std::uint32_t>(N));
  keys.build_buckets<4>(key.size(), [&](std::size_t k) -> const Vec2& { return key[k]; },
                        [&](std::size_t k) -> const Vec2& { return key[k]; });
}

std::int32_t Build::build_chain(std::uint32_t lo, std::uint32_t hi) {
  const std::int32_t id = static_cast<std::int32_t>(chain.size());
  chain.emplace_back();
  chain[id].lo = lo;
  chain[id].hi = hi;
  if (hi - lo > 8) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    const std::int32_t l = build_chain(lo, mid), r = build_chain(mid, hi);
    ChainNode& n = chain[id];
    n.left = l;
    n.right = r;
    const ChainNode &a = chain[l], &b = chain[r];
    n.box = Box{std::min(a.box[0], b.box[0]), std::min(a.box[1], b.box[1]), std::max(a.box[2], b.box[2]),
                std::max(a.box[3], b.box[3])};
    for (int k = 0; k < kDirs; ++k) n.dop[k] = std::min(a.dop[k], b.dop[k]);
    return id;
  }
  ChainNode& n = chain[id];
  n.box = sbox[lo];
  n.dop.fill(std::numeric_limits<double>::infinity());
  for (std::uint32_t g = lo; g < hi; ++g) {
    const Box& b = sbox[g];
    n.box = Box{std::min(n.box[0], b[0]), std::min(n.box[1], b[1]), std::max(n.box[2], b[2]), std::max(n.box[3], b[3])};
    for (const Vec2* v : {&V[g], &V[P.next(g)]})
      for (int k = 0; k < kDirs; ++k) n.dop[k] = std::min(n.dop[k], dirs[k].dot(*v));
  }
  return id;
}

void Build::subtract_overlap(std::uint32_t ci) {
  // Output-sensitive first pass: most candidates lie entirely in O (a star's spikes under a large
  // Q), and the few sausages nearest to the candidate's contact cover it. Covers only ever add
  // points of O, so "no remnant" with a subset of the sausages is the answer of the full set; a
  // candidate that keeps a remnant is redone below exactly as before (same sausages, same order:
  // the same pieces, bit for bit). Without it, gathering every sausage whose box meets the
  // candidate's costs Θ(N) per candidate on a star (Θ(N²) in all).
  // Few sausages in reach (at most 64 boxes meet the candidate's): the full pass at once.
  // Segment candidates count only the sausages the chain hierarchy does not prune (gather_chain:
  // the spiral's candidates keep pieces while hundreds of sausages are in box reach, of which ~3
  // survive); when at most 64 survive they are the full pass's list as they stand. The reference
  // method (nearest_first = false) gathers every sausage in box reach.
  const bool prune = nearest_first && !cand[ci].arc;
  bool gathered = false;
  std::size_t reach = 0;
  if (prune) gathered = Cover(*this, ci).gather_sausages(true, 64);
  else if (nearest_first)
    X.sausages.overlap_until(box_lo(cb[ci]), box_hi(cb[ci]), [&](std::uint32_t g) { return boxes_meet(sbox[g], cb[ci]) && ++reach > 64; });
  if ((prune && !gathered) || reach > 64) {
    ivs.clear();
    Cover first(*this, ci);
    first.gather_nearest(32);
    first.cover_ends_by_fans();
    first.cover_by_sausages();
    if (!first.sweep(ivs, false)) {
      ++covered_early;
      return;
    }
  }
  ivs.clear();
  Cover cover(*this, ci);
  if (!gathered) cover.gather_sausages(prune);
  cover.cover_ends_by_fans();
  cover.cover_by_sausages();
  {
    std::vector<Interval> copy = ivs;
    if (!cover.sweep(copy, false)) return;  // nothing left: skip the coincidence search
  }
  cover.cover_coincident();
  cover.sweep(ivs, true);
}

std::vector<Piece> Build::pieces() const {
  std::vector<Piece> all;
  all.reserve(raw.size());
  for (const Raw& r : raw) {
    const Candidate& C = cand[r.cand];
    Piece pc;
    pc.kind = C.arc ? Piece::Kind::Arc : Piece::Kind::Segment;
    pc.p = C.p;
    pc.b0 = C.arc ? static_cast<std::uint32_t>((C.b0 + r.a.j) % m) : C.b0;
    pc.b1 = C.arc ? static_cast<std::uint32_t>((C.b0 + r.b.j) % m) : C.b0;
    pc.candidate = r.cand;
    pc.start = end_of(r.a.mu);
    pc.end = end_of(r.b.mu);
    all.push_back(pc);
  }
  return all;
}

void Cover::normalize_end(Interval& I) const {
  if (I.e.mu.k == Mu::C1 && I.e.j + 1 < Lc) {
    I.e.j += 1;
    I.e.mu = c0();
  }
}

void Cover::add_cover(std::uint32_t j, const Cut& E, const Cut& in, const Cut& out) {
  const Mu mi = line_mu(in), mo = line_mu(out);
  if (cmp_mu(E, mo, c0()) <= 0 || cmp_mu(E, mi, c1()) >= 0) return;
  Interval I;
  I.s.j = I.e.j = j;
  if (cmp_mu(E, mi, c0()) < 0) {
    I.s.mu = c0();
    I.s_incl = true;
  } else {
    I.s.mu = mi;
  }
  if (cmp_mu(E, mo, c1()) > 0) {
    I.e.mu = c1();
    I.e_incl = true;
  } else {
    I.e.mu = mo;
  }
  normalize_end(I);
  S.ivs.push_back(std::move(I));
}

void Cover::add_coincident(std::uint32_t j, const Cut& E, const Mu& x0, const Mu& x1) {
  Mu lo = cmp_mu(E, x0, c0()) > 0 ? x0 : c0();
  Mu hi = cmp_mu(E, x1, c1()) < 0 ? x1 : c1();
  if (cmp_mu(E, lo, hi) >= 0) return;
  Interval I;
  I.s.j = I.e.j = j;
  I.s.mu = lo;
  I.e.mu = hi;
  normalize_end(I);
  S.ivs.push_back(std::move(I));
}

Mu Cover::pt_mu(std::uint32_t pi, std::uint32_t bi) const {
  Mu r;
  r.k = Mu::Pt;
  r.p = S.V[pi];
  r.b = S.B[bi % S.m];
  r.pi = pi;
  r.bi = static_cast<std::uint32_t>(bi % S.m);
  return r;
}

int Cover::cmp_pos(const Pos& a, const Pos& b) const {
  if (a.j != b.j) return a.j < b.j ? -1 : 1;
  return cmp_mu(S.elem(C, a.j), a.mu, b.mu);
}

bool Cover::sweep(std::vector<Interval>& list, bool emit) const {
  std::sort(list.begin(), list.end(), [&](const Interval& a, const Interval& b) {
    const int c = cmp_pos(a.s, b.s);
    if (c != 0) return c < 0;
    return a.s_incl && !b.s_incl;
  });
  bool any = false;
  Pos cur;
  cur.j = 0;
  cur.mu = c0();
  bool cur_cov = false;
  Pos end;
  end.j = Lc - 1;
  end.mu = c1();
  for (const Interval& I : list) {
    const int c = cmp_pos(I.s, cur);
    if (c > 0 || (c == 0 && !I.s_incl && !cur_cov)) {
      any = true;
      if (!emit) return true;
      S.raw.push_back({ci, cur, I.s});
      cur = I.e;
      cur_cov = I.e_incl;
    } else {
      const int e = cmp_pos(I.e, cur);
      if (e > 0 || (e == 0 && I.e_incl)) {
        cur = I.e;
        cur_cov = cur_cov && e == 0 ? true : I.e_incl;
      }
    }
  }
  const int c = cmp_pos(end, cur);
  if (c > 0 || (c == 0 && !cur_cov)) {
    any = true;
    if (emit) S.raw.push_back({ci, cur, end});
  }
  return any;
}

bool Cover::gather_sausages(bool prune, std::size_t cap) {
  // Points of O: inside an edge sausage int(f_g ⊕ B) (Q + x meets the relative interior of f_g),
  // or inside int R_T for a triangle T around the candidate's P vertices (Q + x touching P at a
  // vertex from inside — the only contact placements with Q + x ⊂ P). Both sets lie in O.
  // `near`: the sausages whose boxes meet the candidate's.
  const auto& V = S.V;
  auto& near = S.near;
  near.clear();
  if (prune && !C.arc) {
    if (!gather_chain(cap)) return false;
  } else {
    S.X.sausages.overlap(box_lo(S.cb[ci]), box_hi(S.cb[ci]), [&](std::uint32_t g) {
      if (boxes_meet(S.sbox[g], S.cb[ci])) near.push_back(g);
    });
  }
  // Likely covers first: edges near the candidate's contact with P (its P edge or vertex), which
  // cross Q + x there when ∂P bends towards Q; the order only affects speed.
  const Vec2 f = C.arc ? Vec2(2 * V[C.p]) : Vec2(V[C.p] + V[S.P.next(C.p)]);
  const double cx = f.x(), cy = f.y();
  std::vector<std::pair<double, std::uint32_t>> order;
  order.reserve(near.size());
  for (std::uint32_t g : near) {
    // The candidate lies on the boundary of its own sausages (a segment: its edge's; an arc: the
    // two edges at its vertex, whose outward normals bound the arc's normals), never in their
    // interiors: skipping them changes no cover and keeps the range test from wasting its tries
    // on them.
    if (g == C.p || (C.arc && g == S.prev[C.p])) continue;
    const Vec2 e = V[g] + V[S.P.next(g)];
    order.push_back({std::abs(e.x() - cx) + std::abs(e.y() - cy), g});
  }
  // A total order (distance, then index), so that the pruned list is the full one minus the pruned
  // sausages in the same order.
  std::sort(order.begin(), order.end());
  near.clear();
  for (const auto& o : order) near.push_back(o.second);
  return true;
}

bool Cover::gather_chain(std::size_t cap) {
  // Sausage S_f = f ⊕ B meets the segment E = [x0, x1] (a P edge g translated by b = B[C.b0]) only
  // if no line separates them. Tried, each with the margin S.sep_margin (so a rounding error never
  // prunes a sausage that meets E):
  //   - per node, the k-DOP directions u_k: max(u_k·x0, u_k·x1) < min_node u_k·v + min_B u_k·b;
  //   - per edge f, the line of candidate f (S_f's supporting line, f's outward normal: S_f lies on
  //     its inner side): both x0 and x1 strictly beyond it;
  //   - per edge f, the line of g: both end points of f strictly on P's side of g's line, so S_f
  //     lies on the inner side of E's line (b is extreme in g's outward normal).
  // E ∩ int S_f = ∅ then, so S_f adds no interval to E (add_cover clips to E).
  const auto& V = S.V;
  const auto& B = S.B;
  auto& near = S.near;
  const Box& cbox = S.cb[ci];
  const std::uint32_t gn = static_cast<std::uint32_t>(S.P.next(C.p));
  const Vec2 x0 = V[C.p] + B[C.b0], x1 = V[gn] + B[C.b0];
  const Vec2 dg = V[gn] - V[C.p];
  const double eps = S.sep_margin;
  std::array<double, Build::kDirs> cmax;
  for (int k = 0; k < Build::kDirs; ++k) cmax[k] = std::max(S.dirs[k].dot(x0), S.dirs[k].dot(x1)) - S.bmin[k] + eps;
  auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
  // Scale of the cross products below: |d|₁ times the coordinates' bound (sep_margin / 2^-44).
  const double gscale = std::abs(dg.x()) + std::abs(dg.y());
  auto& stack = S.stack;
  stack.clear();
  stack.push_back(0);
  while (!stack.empty()) {
    const Build::ChainNode& n = S.chain[stack.back()];
    stack.pop_back();
    if (!boxes_meet(n.box, cbox)) continue;
    bool separated = false;
    for (int k = 0; k < Build::kDirs && !separated; ++k) separated = cmax[k] < n.dop[k];
    if (separated) {
      ++S.chain_pruned;
      continue;
    }
    if (n.left >= 0) {
      stack.push_back(static_cast<std::uint32_t>(n.right));
      stack.push_back(static_cast<std::uint32_t>(n.left));
      continue;
    }
    for (std::uint32_t f = n.lo; f < n.hi; ++f) {
      if (f == C.p || !boxes_meet(S.sbox[f], cbox)) continue;
      const std::uint32_t fn = static_cast<std::uint32_t>(S.P.next(f));
      const Vec2 df = V[fn] - V[f];
      const double fscale = (std::abs(df.x()) + std::abs(df.y())) * 4;
      // x0, x1 beyond candidate f's line (on the right of V[f] + B[b_f] → along df)
      const Vec2 sf = V[f] + B[S.cand[f].b0];
      const double lim_f = -eps * fscale;
      const double lim_g = eps * gscale * 4;
      if ((cross(df, x0 - sf) < lim_f && cross(df, x1 - sf) < lim_f) ||
          // f's end points on the left of g's line
          (cross(dg, V[f] - V[C.p]) > lim_g && cross(dg, V[fn] - V[C.p]) > lim_g)) {
        ++S.chain_pruned;
        continue;
      }
      near.push_back(f);
      if (near.size() > cap) return false;
    }
  }
  return true;
}

void Cover::gather_nearest(std::size_t count) {
  // Best-first search in S.keys (the points key[g] = V[g] + V[next(g)]) by their L1 distance to f,
  // gather_sausages' order; a node's distance bounds its keys' from below. Sausages whose boxes
  // miss the candidate's are skipped; the search stops after visiting 8·count keys.
  const auto& V = S.V;
  auto& near = S.near;
  near.clear();
  const auto& T = S.keys;
  if (T.nodes.empty()) return;
  const Vec2 f = C.arc ? Vec2(2 * V[C.p]) : Vec2(V[C.p] + V[S.P.next(C.p)]);
  const double cx = f.x(), cy = f.y();
  const Box& cbox = S.cb[ci];
  struct Entry {
    double d;
    bool item;
    std::uint32_t id;
    bool operator>(const Entry& o) const {
      if (d != o.d) return d > o.d;
      if (item != o.item) return item;
      return id > o.id;
    }
  };
  std::vector<Entry> heap;
  heap.reserve(64);
  auto push = [&](Entry e) {
    heap.push_back(e);
    std::push_heap(heap.begin(), heap.end(), std::greater<>());
  };
  auto node_dist = [&](const BoxTree::Node& n) {
    const double dx = std::max({0.0, n.lo.x() - cx, cx - n.hi.x()}), dy = std::max({0.0, n.lo.y() - cy, cy - n.hi.y()});
    return dx + dy;
  };
  push({node_dist(T.nodes[0]), false, 0});
  std::size_t visited = 0;
  while (!heap.empty() && near.size() < count) {
    if (visited > 8 * count) return;
    std::pop_heap(heap.begin(), heap.end(), std::greater<>());
    const Entry e = heap.back();
    heap.pop_back();
    if (e.item) {
      near.push_back(e.id);
      continue;
    }
    const BoxTree::Node& n = T.nodes[e.id];
    if (n.left >= 0) {
      push({node_dist(T.nodes[static_cast<std::size_t>(n.left)]), false, static_cast<std::uint32_t>(n.left)});
      push({node_dist(T.nodes[static_cast<std::size_t>(n.right)]), false, static_cast<std::uint32_t>(n.right)});
      continue;
    }
    T.leaf_until(n, [&](std::uint32_t g) {
      ++visited;
      // gather_sausages' filters: the sausage's box meets the candidate's; not its own.
      if (!boxes_meet(S.sbox[g], cbox) || g == C.p || (C.arc && g == S.prev[C.p])) return false;
      const Vec2& k = S.key[g];
      push({std::abs(k.x() - cx) + std::abs(k.y() - cy), true, g});
      return false;
    });
  }
}

void Cover::cover_ends_by_fans() {
  // Fan triangles: only the candidate's natural ends can lie in them (elsewhere Q + x has points
  // outside P near the contact, and x ∈ O is decided by the sausages). So R_T matters only when
  // it contains the end x = v + b_e (v the P vertex, b_e the B vertex there): exactly when the
  // triangle b_e + (v − T) meets int B, i.e. (both convex, b_e on ∂B) when its closed angle at
  // b_e, from v − u1 to v − u2, meets B's open angle at b_e, from b_{e+1} − b_e to b_{e−1} − b_e.
  // Exact and O(1); only then is the O(log m) interval computed.
  const auto& V = S.V;
  const auto& B = S.B;
  const std::size_t m = S.m;
  Cut in, out;
  auto end_in_fan = [&](std::uint32_t T, std::uint32_t v, std::uint32_t e) {
    const TriangleIds& t = S.R.triangle(T);
    const int sl = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
    const Vec2 &pv = V[v], &u1 = V[t[(sl + 1) % 3]], &u2 = V[t[(sl + 2) % 3]];
    const Vec2 &be = B[e], &bn = B[(e + 1) % m], &bp = B[(e + m - 1) % m];
    // v − u1 strictly inside B's angle
    if (predicates::cross_edges(be, bn, u1, pv) > 0 && predicates::cross_edges(u1, pv, be, bp) > 0) return true;
    // else they meet iff b_{e+1} − b_e lies in [v − u1, v − u2)
    const int c = predicates::cross_edges(u1, pv, be, bn);
    return (c > 0 || (c == 0 && predicates::dot_edges(u1, pv, be, bn) > 0)) && predicates::cross_edges(be, bn, u2, pv) > 0;
  };
  for (int side = 0; side < 2; ++side) {
    const std::uint32_t j = side == 0 ? 0 : Lc - 1;
    const std::uint32_t v = side == 0 || C.arc ? C.p : static_cast<std::uint32_t>(S.P.next(C.p));
    const std::uint32_t e = side == 0 || !C.arc ? C.b0 : static_cast<std::uint32_t>((C.b0 + Lc) % m);
    const Cut E = S.elem(C, j);
    bool have_dir = false;
    LineDir D;
    for (std::uint32_t T : S.R.triangles_at(v)) {
      if (!end_in_fan(T, v, e)) continue;
      if (!have_dir) {
        D = S.R.line_dir(E);
        have_dir = true;
        if (!C.arc) {
          seg_dir = D;
          have_seg_dir = true;
        }
      }
      if (S.R.line_interval(T, E, D, in, out)) add_cover(j, E, in, out);
    }
  }
}

void Cover::cover_by_sausages() {
  // Recursive element ranges. A range whose (padded) box has its four corners inside one int S_g
  // is covered at once (S_g convex); a single element is cut by every sausage whose box meets it,
  // until one covers it entirely.
  const auto& R = S.R;
  const auto& near = S.near;
  const auto& sbox = S.sbox;
  auto& ivs = S.ivs;
  auto& st = S.st;
  Cut in, out;
  auto rng_box = [&](std::uint32_t lo, std::uint32_t hi) {
    return C.arc ? range_box(S.B, S.X.ext, S.V[C.p], C.b0 + lo, hi - lo) : S.cb[ci];
  };
  st.clear();
  st.push_back({0, Lc});
  while (!st.empty()) {
    const auto [lo, hi] = st.back();
    st.pop_back();
    const Box rb = rng_box(lo, hi);
    // Every sausage of `near` meets the whole candidate's box (filtered when gathered).
    const bool root = lo == 0 && hi == Lc;
    bool whole = false, any = false;
    int tries = 0;
    for (const std::uint32_t g : near) {
      const Box& sb = sbox[g];
      if (!root && !boxes_meet(sb, rb)) continue;
      any = true;
      if (sb[0] > rb[0] || sb[1] > rb[1] || sb[2] < rb[2] || sb[3] < rb[3]) continue;
      whole = R.segment_contains_interior(g, Vec2(rb[0], rb[1])) && R.segment_contains_interior(g, Vec2(rb[2], rb[1])) &&
              R.segment_contains_interior(g, Vec2(rb[2], rb[3])) && R.segment_contains_interior(g, Vec2(rb[0], rb[3]));
      if (whole || ++tries >= 3) break;
    }
    if (!any) continue;
    if (whole) {
      Interval I;
      I.s.j = lo;
      I.s.mu = c0();
      I.s_incl = true;
      I.e.j = hi - 1;
      I.e.mu = c1();
      I.e_incl = true;
      normalize_end(I);
      ivs.push_back(std::move(I));
      continue;
    }
    if (hi - lo == 1) {
      // Stop once the element is covered: by one interval, or by a prefix (from its start) and a
      // suffix (to its end) that overlap.
      const Cut E = S.elem(C, lo);
      const LineDir D = have_seg_dir ? seg_dir : R.line_dir(E);
      bool has_pre = false, has_suf = false;
      Mu pre_end, suf_start;
      for (const std::uint32_t g : near) {
        if ((!root && !boxes_meet(sbox[g], rb)) || !R.segment_line_interval(g, E, D, in, out)) continue;
        const std::size_t before = ivs.size();
        add_cover(lo, E, in, out);
        if (ivs.size() == before) continue;
        const Interval& I = ivs.back();
        if (I.s_incl && I.e_incl) break;
        if (I.s_incl && (!has_pre || cmp_mu(E, I.e.mu, pre_end) > 0)) {
          pre_end = I.e.mu;
          has_pre = true;
        }
        if (I.e_incl && (!has_suf || cmp_mu(E, I.s.mu, suf_start) < 0)) {
          suf_start = I.s.mu;
          has_suf = true;
        }
        if (has_pre && has_suf && cmp_mu(E, suf_start, pre_end) < 0) break;
      }
      continue;
    }
    const std::uint32_t mid = (lo + hi) / 2;
    st.push_back({lo, mid});
    st.push_back({mid, hi});
  }
}

void Cover::cover_coincident() {
  const auto& V = S.V;
  const std::size_t m = S.m;
  auto& near = S.near;
  near.clear();
  S.cbvh.overlap(box_lo(S.cb[ci]), box_hi(S.cb[ci]), [&](std::uint32_t o) {
    if (o < ci) near.push_back(o);
  });
  auto in_range = [&](const Candidate& c, std::size_t k) { return (k + m - c.b0) % m < c.count; };
  for (std::uint32_t oi : near) {
    const Candidate& O = S.cand[oi];
    auto try_pair = [&](std::uint32_t j, const Cut& E, const Cut& F, const Mu& f0, const Mu& f1) {
      if (compare_angle(E.e0, E.e1, F.e0, F.e1) != 0) return;
      // Same B vertex (parallel edges share their extreme vertex): it cancels exactly, and the
      // plain cross product certifies the frequent exact zero (collinear edges) cheaply.
      const int side = E.pb == F.pb ? predicates::cross_edges(E.e0, E.e1, E.pt, F.pt) : exact_sign([&](auto L) {
        auto Dx = L(E.e1.x()) - L(E.e0.x()), Dy = L(E.e1.y()) - L(E.e0.y());
        return Dx * (L(F.pt.y()) + L(F.pb.y()) - L(E.pt.y()) - L(E.pb.y())) -
               Dy * (L(F.pt.x()) + L(F.pb.x()) - L(E.pt.x()) - L(E.pb.x()));
      });
      if (side == 0) add_coincident(j, E, f0, f1);
    };
    if (!C.arc && !O.arc) {
      const Cut E = S.elem(C, 0), F = S.elem(O, 0);
      try_pair(0, E, F, pt_mu(O.p, O.b0), pt_mu(F.p_to, O.b0));
    } else if (!C.arc && O.arc) {
      const Cut E = S.elem(C, 0);
      const std::uint32_t k = S.lower(E.e0, E.e1) % m;
      if (in_range(O, k)) {
        const Cut F = S.elem(O, (k + m - O.b0) % m);
        try_pair(0, E, F, pt_mu(O.p, k), pt_mu(O.p, k + 1));
      }
    } else if (C.arc && !O.arc) {
      const Cut F = S.elem(O, 0);
      const std::uint32_t k = S.lower(F.e0, F.e1) % m;
      if (in_range(C, k)) {
        const std::uint32_t j = static_cast<std::uint32_t>((k + m - C.b0) % m);
        try_pair(j, S.elem(C, j), F, pt_mu(O.p, O.b0), pt_mu(F.p_to, O.b0));
      }
    } else if (V[C.p] != V[O.p]) {
      for (int s = 0; s < 2; ++s) {
        const std::uint32_t k = s ? S.lower(V[O.p], V[C.p]) % m : S.lower(V[C.p], V[O.p]) % m;
        if (!in_range(C, k) || !in_range(O, k)) continue;
        const std::uint32_t j = static_cast<std::uint32_t>((k + m - C.b0) % m);
        try_pair(j, S.elem(C, j), S.elem(O, (k + m - O.b0) % m), pt_mu(O.p, k), pt_mu(O.p, k + 1));
      }
    }
  }
}

}  // namespace

UnionBoundary::UnionBoundary(const Polygon& P, const ConvolvedTriangles& R, bool nearest_first)
    : P_(&P), R_(&R), index_(std::make_unique<Index>()) {
  Build S(P, R, *index_);
  S.nearest_first = nearest_first;
  // 1. Candidates: the reduced convolution of ∂P with B, with the boxes and hierarchies used below.
  S.find_candidates();
  S.build_hierarchies();
  // 2. Covering: each candidate minus its points in O leaves closed remnants, the pieces.
  for (std::uint32_t ci = 0; ci < S.cand.size(); ++ci) S.subtract_overlap(ci);
  covered_early_ = S.covered_early;
  chain_pruned_ = S.chain_pruned;
  pieces_ = S.pieces();
  // 3. Zero-length remnants lying on another piece are dropped.
  std::vector<Vec2> sp, ep;  // rounded start / end of each piece
  std::vector<char> zero;    // whether the piece has zero length
  drop_covered_points(sp, ep, zero);
  // 4. Linking into rings, and their orientation.
  link_rings(sp, ep, zero);
  orient_rings(sp, ep);
  // 5. Index: the hierarchy over the pieces for the queries.
  index_pieces();
  pieces_.shrink_to_fit();
  rings_.shrink_to_fit();
}

std::array<double, 4> UnionBoundary::piece_box_of(std::size_t k) const {
  const Piece& pc = pieces_[k];
  const auto V = P_->vertices();
  const auto& B = R_->B();
  if (pc.kind == Piece::Kind::Arc) return range_box(B, index_->ext, V[pc.p], pc.b0, element_count(k));
  return segment_box(V[pc.p], V[P_->next(pc.p)], B[pc.b0]);
}

void UnionBoundary::drop_covered_points(std::vector<Vec2>& sp, std::vector<Vec2>& ep, std::vector<char>& zero) {
  const std::size_t K = pieces_.size();
  sp.resize(K);
  ep.resize(K);
  zero.assign(K, 0);
  for (std::size_t k = 0; k < K; ++k) {
    sp[k] = start_point(k);
    ep[k] = end_point(k);
    zero[k] = element_count(k) <= 2 &&
              same_point(element(k, 0), mu_of(pieces_[k].start), element(k, element_count(k) - 1), mu_of(pieces_[k].end));
  }
  // A zero-length remnant is dropped when its point lies on another piece (exact, rationals; such
  // remnants are rare: a candidate touching ∂O at one point).
  std::vector<char> drop(K, 0);
  {
    std::vector<Box> boxes(K);
    for (std::size_t k = 0; k < K; ++k) boxes[k] = piece_box_of(k);
    BoxTree tmp;
    build_tree(tmp, boxes);
    for (std::size_t k = 0; k < K; ++k) {
      if (!zero[k]) continue;
      const auto x = exact_point(element(k, 0), mu_of(pieces_[k].start));
      const double w = point_tol(sp[k]) * 16;
      bool on = false;
      tmp.overlap(Vec2(sp[k].x() - w, sp[k].y() - w), Vec2(sp[k].x() + w, sp[k].y() + w), [&](std::uint32_t o) {
        if (on || o == k || (zero[o] && o > k)) return;
        const std::size_t Le = element_count(o);
        for (std::size_t j = 0; j < Le && !on; ++j) {
          const Cut E = element(o, j);
          const Vec2 a0 = E.pt + E.pb, a1 = a0 + (E.e1 - E.e0);
          const double ww = w + point_tol(a0) + point_tol(a1);
          if (sp[k].x() < std::min(a0.x(), a1.x()) - ww || sp[k].x() > std::max(a0.x(), a1.x()) + ww ||
              sp[k].y() < std::min(a0.y(), a1.y()) - ww || sp[k].y() > std::max(a0.y(), a1.y()) + ww)
            continue;
          const auto A = j == 0 ? exact_point(E, mu_of(pieces_[o].start)) : exact_point(E, c0());
          const auto Bq = j + 1 == Le ? exact_point(E, mu_of(pieces_[o].end)) : exact_point(E, c1());
          const mpq_class ux = Bq[0] - A[0], uy = Bq[1] - A[1], vx = x[0] - A[0], vy = x[1] - A[1];
          if (ux == 0 && uy == 0) {
            on = vx == 0 && vy == 0;
          } else {
            on = ux * vy - uy * vx == 0 && ux * vx + uy * vy >= 0 && (x[0] - Bq[0]) * ux + (x[1] - Bq[1]) * uy <= 0;
          }
        }
      });
      drop[k] = on;
    }
  }
  std::vector<Piece> kept;
  std::vector<Vec2> ks, ke;
  std::vector<char> kz;
  for (std::size_t k = 0; k < K; ++k)
    if (!drop[k]) {
      kept.push_back(pieces_[k]);
      ks.push_back(sp[k]);
      ke.push_back(ep[k]);
      kz.push_back(zero[k]);
    }
  pieces_ = std::move(kept);
  sp = std::move(ks);
  ep = std::move(ke);
  zero = std::move(kz);
}

void UnionBoundary::link_rings(std::vector<Vec2>& sp, std::vector<Vec2>& ep, const std::vector<char>& zero) {
  const std::size_t KP = pieces_.size();
  // Candidates for equal points: sorted by rounded x; equal exact points round within a few ulps.
  std::vector<std::uint32_t> by_x(KP);
  std::iota(by_x.begin(), by_x.end(), 0u);
  std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t a, std::uint32_t b) { return sp[a].x() < sp[b].x(); });
  auto starts_at = [&](const Vec2& q, const Cut& E, const Mu& mq, auto&& f) {
    const double w = point_tol(q);
    auto it = std::lower_bound(by_x.begin(), by_x.end(), q.x() - w, [&](std::uint32_t a, double x) { return sp[a].x() < x; });
    for (; it != by_x.end() && sp[*it].x() <= q.x() + w; ++it) {
      const std::uint32_t k = *it;
      if (std::abs(sp[k].y() - q.y()) > w) continue;
      if (same_point(element(k, 0), mu_of(pieces_[k].start), E, mq)) f(k);
    }
  };
  // End → start links, clockwise-first from the reversed incoming direction.
  const std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> nxt(KP, kNone);
  std::vector<char> taken(KP, 0);
  std::vector<std::vector<std::uint32_t>> options(KP);
  for (std::size_t k = 0; k < KP; ++k) {
    if (zero[k]) continue;
    const Cut E = element(k, element_count(k) - 1);
    starts_at(ep[k], E, mu_of(pieces_[k].end), [&](std::uint32_t o) {
      if (!zero[o]) options[k].push_back(o);
    });
    if (options[k].size() > 1) {
      // reference r = −(incoming direction)
      std::sort(options[k].begin(), options[k].end(), [&](std::uint32_t a, std::uint32_t b) {
        const Cut A = element(a, 0), Bc = element(b, 0);
        if (cw_less(E.e1, E.e0, A.e0, A.e1, Bc.e0, Bc.e1)) return true;
        if (cw_less(E.e1, E.e0, Bc.e0, Bc.e1, A.e0, A.e1)) return false;
        const bool sa = pieces_[a].kind == Piece::Kind::Segment, sb = pieces_[b].kind == Piece::Kind::Segment;
        if (sa != sb) return sa;
        return a < b;
      });
    }
  }
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t k = 0; k < KP; ++k) {
      if (nxt[k] != kNone || (pass == 0 && options[k].size() != 1)) continue;
      for (std::uint32_t o : options[k])
        if (!taken[o]) {
          nxt[k] = o;
          taken[o] = 1;
          break;
        }
    }
  // Follow the links; reorder pieces ring by ring.
  std::vector<char> seen(KP, 0);
  std::vector<Piece> ordered;
  ordered.reserve(KP);
  std::vector<Vec2> osp, oep;  // sp, ep in the new order
  osp.reserve(KP);
  oep.reserve(KP);
  for (std::size_t s0 = 0; s0 < KP; ++s0) {
    if (seen[s0]) continue;
    // Start an open chain at a piece nobody links to, if this one is on an open chain.
    std::size_t s = s0;
    Ring ring;
    ring.first = static_cast<std::uint32_t>(ordered.size());
    for (std::size_t k = s; k != kNone && !seen[k]; k = nxt[k]) {
      seen[k] = 1;
      Piece pc = pieces_[k];
      pc.ring = static_cast<std::uint32_t>(rings_.size());
      ordered.push_back(pc);
      osp.push_back(sp[k]);
      oep.push_back(ep[k]);
      ++ring.count;
    }
    for (std::uint32_t q = 0; q < ring.count; ++q) {
      ordered[ring.first + q].next = ring.first + (q + 1) % ring.count;
      ordered[ring.first + q].prev = ring.first + (q + ring.count - 1) % ring.count;
    }
    rings_.push_back(ring);
  }
  pieces_ = std::move(ordered);
  sp = std::move(osp);
  ep = std::move(oep);
}

void UnionBoundary::orient_rings(const std::vector<Vec2>& sp, const std::vector<Vec2>& ep) {
  for (Ring& rg : rings_) {
    double sum = 0, mag = 0;
    std::size_t terms = 0;
    auto acc = [&](const Vec2& a, const Vec2& b) {
      sum += a.x() * b.y() - a.y() * b.x();
      mag += std::abs(a.x() * b.y()) + std::abs(a.y() * b.x());
      ++terms;
    };
    for (std::uint32_t q = 0; q < rg.count; ++q) {
      const std::size_t k = rg.first + q;
      const std::size_t Le = element_count(k);
      Vec2 prevp = sp[k];  // = start_point(k)
      for (std::size_t j = 1; j < Le; ++j) {
        const Cut E = element(k, j);
        const Vec2 v = E.pt + E.pb;
        acc(prevp, v);
        prevp = v;
      }
      acc(prevp, ep[k]);  // = end_point(k)
    }
    if (std::abs(sum) > (64.0 + 4.0 * terms) * 0x1p-52 * mag + 0x1p-900) {
      rg.area_sign = sum > 0 ? 1 : -1;
      continue;
    }
    mpq_class exact_sum = 0;
    auto qpt = [&](const Cut& E, const Mu& mu) {
      auto h = point_h(E, mu, exact::LiftQ{});
      return std::array<mpq_class, 2>{mpq_class(h[0].v / h[2].v), mpq_class(h[1].v / h[2].v)};
    };
    for (std::uint32_t q = 0; q < rg.count; ++q) {
      const std::size_t k = rg.first + q;
      const std::size_t Le = element_count(k);
      auto a = qpt(element(k, 0), mu_of(pieces_[k].start));
      for (std::size_t j = 1; j <= Le; ++j) {
        auto b = j < Le ? qpt(element(k, j), c0()) : qpt(element(k, Le - 1), mu_of(pieces_[k].end));
        exact_sum += a[0] * b[1] - a[1] * b[0];
        a = b;
      }
    }
    rg.area_sign = sgn(exact_sum);
  }
}

void UnionBoundary::index_pieces() {
  Index& X = *index_;
  X.piece_box.resize(pieces_.size());
  for (std::size_t k = 0; k < pieces_.size(); ++k) X.piece_box[k] = piece_box_of(k);
  build_tree(X.pieces, X.piece_box);
}

// ---- line / ray against a piece ----

namespace {

// The hits of the line t + λ·d with the portion [ms, me] of element E (appended).
void element_hits(const Cut& E, const Mu& ms, const Mu& me, const Vec2& t, const Vec2& d, std::uint32_t piece,
                  std::size_t m, std::vector<Hit>& out) {
  Mu ray;
  ray.k = Mu::Ray;
  ray.p = t;
  ray.b = d;
  if (mu_den_sign(E, ray) != 0) {
    if (cmp_mu(E, ray, ms) >= 0 && cmp_mu(E, ray, me) <= 0) {
      Hit h;
      h.cut = E;
      h.piece = piece;
      out.push_back(h);
    }
    return;
  }
  if (exact_sign([&](auto L) { return mu_num(E, ray, L); }) != 0) return;  // parallel, off the line
  for (const Mu* mu : {&ms, &me}) {
    Hit h;
    h.piece = piece;
    h.cut = E;
    switch (mu->k) {
      case Mu::Line:
        h.cut = mu->o;
        break;
      case Mu::C0:
        h.is_point = true;
        h.p = E.pt;
        h.b = E.pb;
        h.p_index = E.p_from;
        h.b_index = E.b;
        break;
      case Mu::C1:
        h.is_point = true;
        if (E.b_edge) {
          h.p = E.pt;
          h.b = E.e1;
          h.p_index = E.p_from;
          h.b_index = static_cast<std::uint32_t>((E.b + 1) % m);
        } else {
          h.p = E.e1;
          h.b = E.pb;
          h.p_index = E.p_to;
          h.b_index = E.b;
        }
        break;
      default:
        h.is_point = true;
        h.p = mu->p;
        h.b = mu->b;
        h.p_index = mu->pi;
        h.b_index = mu->bi;
        break;
    }
    out.push_back(h);
  }
}

}  // namespace

void UnionBoundary::line_hits(std::size_t k, const Vec2& t, const Vec2& d, std::vector<Hit>& out) const {
  const Piece& pc = pieces_[k];
  const std::size_t Le = element_count(k), m = R_->B().size();
  auto portion = [&](std::size_t j, Mu& ms, Mu& me) {
    ms = j == 0 ? mu_of(pc.start) : c0();
    me = j + 1 == Le ? mu_of(pc.end) : c1();
  };
  const std::size_t first = out.size();
  auto test = [&](std::size_t j) {
    Mu ms, me;
    portion(j, ms, me);
    element_hits(element(k, j), ms, me, t, d, static_cast<std::uint32_t>(k), m, out);
  };
  if (Le == 1) {
    test(0);
  } else {
    // Classes of the arc's edges by cross(d, edge): 0 front (+), 1 anti-parallel, 2 back (−),
    // 3 parallel; along the arc (angles increasing, turn < π) the class advances cyclically, so
    // rank(j) = (class(j) − class(0)) mod 4 is non-decreasing. X(vertex) = cross(d, v + b − t)
    // is strictly monotone within the front and back runs.
    auto cls = [&](std::size_t j) {
      const Cut E = element(k, j);
      const int c = predicates::cross_edges(kZero, d, E.e0, E.e1);
      if (c > 0) return 0;
      if (c < 0) return 2;
      return predicates::dot_edges(kZero, d, E.e0, E.e1) < 0 ? 1 : 3;
    };
    const int c0v = cls(0);
    auto rank = [&](std::size_t j) { return (cls(j) - c0v + 4) % 4; };
    auto Xs = [&](std::size_t w) {  // vertex w of the arc (w = 0 .. Le), natural positions
      const Cut E = element(k, std::min(w, Le - 1));
      const Vec2& b = w < Le ? E.e0 : E.e1;
      return exact_sign([&](auto L) {
        return L(d.x()) * (L(E.pt.y()) + L(b.y()) - L(t.y())) - L(d.y()) * (L(E.pt.x()) + L(b.x()) - L(t.x()));
      });
    };
    std::vector<std::size_t> cand;
    std::size_t j = 0;
    while (j < Le) {
      const int r = rank(j);
      std::size_t lo = j, hi = Le;  // last element with rank r: binary search
      while (hi - lo > 1) {
        std::size_t mid = (lo + hi) / 2;
        if (rank(mid) <= r) lo = mid;
        else hi = mid;
      }
      const int c = (r + c0v) % 4;
      if (c == 1 || c == 3) {
        for (std::size_t q = j; q <= lo; ++q) cand.push_back(q);
      } else {
        // vertices j .. lo + 1, X strictly increasing (front) or decreasing (back): first vertex
        // with X on the far side or on the line.
        const int want = c == 0 ? 1 : -1;
        std::size_t a = j, b = lo + 2;  // search in [j, lo + 1]
        while (a < b) {
          std::size_t mid = (a + b) / 2;
          if (Xs(mid) * want >= 0) b = mid;
          else a = mid + 1;
        }
        for (std::size_t q : {a, a + 1})
          if (q >= 1 && q - 1 >= j && q - 1 <= lo) cand.push_back(q - 1);
        if (a <= lo) cand.push_back(a);
      }
      j = lo + 1;
    }
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    for (std::size_t q : cand) test(q);
  }
  // Remove repeated points (a vertex shared by two tested elements).
  for (std::size_t a = first; a < out.size(); ++a)
    for (std::size_t b = out.size(); b-- > a + 1;)
      if (compare_hits(out[a], out[b], t, d) == 0) out.erase(out.begin() + b);
}

bool UnionBoundary::first_hit(std::size_t k, const Vec2& t, const Vec2& d, Hit& h) const {
  std::vector<Hit> hs;
  line_hits(k, t, d, hs);
  bool found = false;
  for (const Hit& x : hs)
    if (hit_sign(x, t, d) > 0 && (!found || compare_hits(x, h, t, d) < 0)) {
      h = x;
      found = true;
    }
  return found;
}

bool UnionBoundary::ray_first_scan(const Vec2& t, const Vec2& d, Hit& h) const {
  bool found = false;
  Hit x;
  for (std::size_t k = 0; k < pieces_.size(); ++k)
    if (first_hit(k, t, d, x) && (!found || compare_hits(x, h, t, d) < 0)) {
      h = x;
      found = true;
    }
  return found;
}

bool UnionBoundary::ray_first(const Vec2& t, const Vec2& d, Hit& h, bool* tie) const {
  const BoxTree& T = index_->pieces;
  if (tie) *tie = false;
  if (T.nodes.empty()) return false;
  bool found = false;
  double best = INFINITY;
  Hit x;
  std::vector<std::uint32_t> st{0};
  while (!st.empty()) {
    const BoxTree::Node& n = T.nodes[st.back()];
    st.pop_back();
    double en, ex;
    if (!ray_node(n, t, d, en, ex) || ex < 0 || en > best) continue;
    if (n.left < 0) {
      for (std::uint32_t i = n.tri; i < n.tri + n.count; ++i) {
        const std::uint32_t k = T.items[i];
        if (!first_hit(k, t, d, x)) continue;
        const int c = found ? compare_hits(x, h, t, d) : -1;
        if (c < 0) {
          h = x;
          found = true;
          if (tie) *tie = false;
          const double v = hit_value(h, t, d);
          best = v + std::abs(v) * 0x1p-40 + 0x1p-1000;
        } else if (c == 0 && tie) {
          *tie = true;  // boxes through h are never pruned (best is widened), so every tie is seen
        }
      }
      continue;
    }
    double e1, x1, e2, x2;
    const bool h1 = ray_node(T.nodes[n.left], t, d, e1, x1), h2 = ray_node(T.nodes[n.right], t, d, e2, x2);
    if (h1 && h2) {
      if (e1 <= e2) {
        st.push_back(static_cast<std::uint32_t>(n.right));
        st.push_back(static_cast<std::uint32_t>(n.left));
      } else {
        st.push_back(static_cast<std::uint32_t>(n.left));
        st.push_back(static_cast<std::uint32_t>(n.right));
      }
    } else if (h1) {
      st.push_back(static_cast<std::uint32_t>(n.left));
    } else if (h2) {
      st.push_back(static_cast<std::uint32_t>(n.right));
    }
  }
  return found;
}

// ---- nearest point ----

Near UnionBoundary::nearest_on_piece(std::size_t k, const Vec2& t) const {
  const Piece& pc = pieces_[k];
  const std::size_t Le = element_count(k), m = R_->B().size();
  auto on_element = [&](std::size_t j) {
    const Cut E = element(k, j);
    const Mu ms = j == 0 ? mu_of(pc.start) : c0();
    const Mu me = j + 1 == Le ? mu_of(pc.end) : c1();
    Mu foot;
    foot.k = Mu::Foot;
    foot.p = t;
    const Mu* end = nullptr;
    if (cmp_mu(E, foot, ms) <= 0) end = &ms;
    else if (cmp_mu(E, foot, me) >= 0) end = &me;
    Near n;
    n.piece = static_cast<std::uint32_t>(k);
    n.cut = E;
    if (!end) {
      n.kind = Near::Kind::Foot;
      n.p = t;
      return n;
    }
    switch (end->k) {
      case Mu::Line:
        n.kind = Near::Kind::Crossing;
        n.other = end->o;
        break;
      case Mu::C0:
        n.kind = Near::Kind::Point;
        n.p = E.pt;
        n.b = E.pb;
        n.p_index = E.p_from;
        n.b_index = E.b;
        break;
      case Mu::C1:
        n.kind = Near::Kind::Point;
        if (E.b_edge) {
          n.p = E.pt;
          n.b = E.e1;
          n.p_index = E.p_from;
          n.b_index = static_cast<std::uint32_t>((E.b + 1) % m);
        } else {
          n.p = E.e1;
          n.b = E.pb;
          n.p_index = E.p_to;
          n.b_index = E.b;
        }
        break;
      default:
        n.kind = Near::Kind::Point;
        n.p = end->p;
        n.b = end->b;
        n.p_index = end->pi;
        n.b_index = end->bi;
        break;
    }
    return n;
  };
  if (Le == 1) return on_element(0);
  // Branch-and-bound over B-edge ranges (boxes in O(1)).
  const auto& B = R_->B();
  const Vec2& v = P_->vertices()[pc.p];
  auto range_box = [&](std::size_t lo, std::size_t hi) {  // elements [lo, hi): vertices lo .. hi
    Box r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    auto add = [&](std::size_t q) {
      const Vec2& b = B[q % m];
      r[0] = std::min(r[0], b.x());
      r[1] = std::min(r[1], b.y());
      r[2] = std::max(r[2], b.x());
      r[3] = std::max(r[3], b.y());
    };
    add(pc.b0 + lo);
    add(pc.b0 + hi);
    for (std::uint32_t e : index_->ext)
      if ((e + m - (pc.b0 + lo) % m) % m <= hi - lo) add(e);
    r[0] += v.x();
    r[1] += v.y();
    r[2] += v.x();
    r[3] += v.y();
    return pad(r);
  };
  Near best;
  bool found = false;
  double bd2 = INFINITY;
  std::vector<std::pair<std::size_t, std::size_t>> st{{0, Le}};
  while (!st.empty()) {
    auto [lo, hi] = st.back();
    st.pop_back();
    if (found && box_dist2(range_box(lo, hi), t) > bd2) continue;
    if (hi - lo == 1) {
      Near n = on_element(lo);
      if (!found || compare_near(n, best, t) < 0) {
        best = n;
        found = true;
        const double dd = near_distance(best, t);
        bd2 = dd * dd * (1 + 0x1p-40) + 0x1p-1000;
      }
      continue;
    }
    const std::size_t mid = (lo + hi) / 2;
    const double d1 = box_dist2(range_box(lo, mid), t), d2 = box_dist2(range_box(mid, hi), t);
    if (d1 <= d2) {
      st.push_back({mid, hi});
      st.push_back({lo, mid});
    } else {
      st.push_back({lo, mid});
      st.push_back({mid, hi});
    }
  }
  return best;
}

bool UnionBoundary::nearest(const Vec2& t, Near& best) const {
  const BoxTree& T = index_->pieces;
  if (T.nodes.empty()) return false;
  bool found = false;
  double bd2 = INFINITY;
  std::vector<std::uint32_t> st{0};
  while (!st.empty()) {
    const BoxTree::Node& n = T.nodes[st.back()];
    st.pop_back();
    if (box_dist2(n.lo, n.hi, t) > bd2) continue;
    if (n.left < 0) {
      for (std::uint32_t i = n.tri; i < n.tri + n.count; ++i) {
        const std::uint32_t k = T.items[i];
        if (found && box_dist2(index_->piece_box[k], t) > bd2) continue;
        Near x = nearest_on_piece(k, t);
        if (!found || compare_near(x, best, t) < 0) {
          best = x;
          found = true;
          const double dd = near_distance(best, t);
          bd2 = dd * dd * (1 + 0x1p-40) + 0x1p-1000;
        }
      }
      continue;
    }
    const double d1 = box_dist2(T.nodes[n.left].lo, T.nodes[n.left].hi, t), d2 = box_dist2(T.nodes[n.right].lo, T.nodes[n.right].hi, t);
    if (d1 <= d2) {
      st.push_back(static_cast<std::uint32_t>(n.right));
      st.push_back(static_cast<std::uint32_t>(n.left));
    } else {
      st.push_back(static_cast<std::uint32_t>(n.left));
      st.push_back(static_cast<std::uint32_t>(n.right));
    }
  }
  return found;
}

// ---- queries on the R_i ----

bool UnionBoundary::in_overlap(const Vec2& t) const {
  // Q + t meets the relative interior of some P edge: t ∈ int(f_g ⊕ B).
  if (index_->sausages.overlap_until(t, t,
                                     [&](std::uint32_t g) { return R_->segment_contains_interior(g, t); }))
    return true;
  // Otherwise int(Q + t) misses ∂P: it overlaps P iff it lies inside P. Test the interior point
  // c = t + (q0 + q1 + q2)/3 (Q strictly convex) by the crossing number of the ray c + s·(1, 0)
  // with P's edges (half-open rule on y, exact in 3c = 3t + q0 + q1 + q2).
  const auto& B = R_->B();
  const Vec2 q0 = -B[0], q1 = -B[1], q2 = -B[2];
  auto c3 = [&](int k, auto L) { return L(3.0) * L(t[k]) + L(q0[k]) + L(q1[k]) + L(q2[k]); };
  const Vec2 ca = t + (q0 + q1 + q2) / 3;
  const double w = (std::abs(ca.x()) + std::abs(ca.y()) + std::abs(q0.x()) + std::abs(q0.y()) + std::abs(q1.x()) +
                    std::abs(q1.y()) + std::abs(q2.x()) + std::abs(q2.y())) * 0x1p-40 + 0x1p-1000;
  const auto V = P_->vertices();
  std::size_t crossings = 0;
  index_->edges.overlap(Vec2(ca.x() - w, ca.y() - w), Vec2(INFINITY, ca.y() + w), [&](std::uint32_t g) {
    const Vec2 &a = V[g], &b = V[P_->next(g)];
    const bool above_a = exact_sign([&](auto L) { return L(3.0) * L(a.y()) - c3(1, L); }) > 0;
    const bool above_b = exact_sign([&](auto L) { return L(3.0) * L(b.y()) - c3(1, L); }) > 0;
    if (above_a == above_b) return;
    // c strictly left of the edge directed upwards: the crossing lies to the right of c.
    const int o = exact_sign([&](auto L) {
      return (L(b.x()) - L(a.x())) * (c3(1, L) - L(3.0) * L(a.y())) - (L(b.y()) - L(a.y())) * (c3(0, L) - L(3.0) * L(a.x()));
    });
    if ((above_b ? o : -o) > 0) ++crossings;
  });
  return crossings % 2 == 1;
}

bool UnionBoundary::on_boundary(const Vec2& t) const {
  Near zero;  // the point t itself: distance 0
  zero.kind = Near::Kind::Point;
  zero.cut.pt = zero.cut.pb = zero.cut.e0 = zero.cut.e1 = Vec2(0, 0);
  zero.p = t;
  return index_->pieces.overlap_until(t, t, [&](std::uint32_t k) {
    return compare_near(nearest_on_piece(k, t), zero, t) == 0;
  });
}

bool UnionBoundary::last_exit(const Vec2& t, const Vec2& d, Cut& best) const {
  const BoxTree& T = index_->sausages;
  if (T.nodes.empty()) return false;
  bool found = false;
  double bound = 0;  // exits at or before this λ cannot win (λ > 0 is required anyway)
  Cut en, ex;
  std::vector<std::uint32_t> st{0};
  while (!st.empty()) {
    const BoxTree::Node& n = T.nodes[st.back()];
    st.pop_back();
    double e0, x0;
    if (!ray_node(n, t, d, e0, x0) || x0 < bound) continue;
    if (n.left < 0) {
      for (std::uint32_t i = n.tri; i < n.tri + n.count; ++i) {
        const std::uint32_t r = T.items[i];
        if (!R_->segment_line_interval(r, t, d, en, ex) || cut_sign(ex, t, d) <= 0) continue;
        const int c = found ? compare_cuts(ex, best, t, d) : 1;
        if (c > 0 || (c == 0 && ex.tri < best.tri)) {  // ties: lowest edge
          best = ex;
          found = true;
          const double v = cut_value(best, t, d);
          bound = v - std::abs(v) * 0x1p-40 - 0x1p-1000;
        }
      }
      continue;
    }
    double e1, x1, e2, x2;
    const bool h1 = ray_node(T.nodes[n.left], t, d, e1, x1), h2 = ray_node(T.nodes[n.right], t, d, e2, x2);
    if (h1 && h2) {  // farther exit first
      if (x1 >= x2) {
        st.push_back(static_cast<std::uint32_t>(n.right));
        st.push_back(static_cast<std::uint32_t>(n.left));
      } else {
        st.push_back(static_cast<std::uint32_t>(n.left));
        st.push_back(static_cast<std::uint32_t>(n.right));
      }
    } else if (h1) {
      st.push_back(static_cast<std::uint32_t>(n.left));
    } else if (h2) {
      st.push_back(static_cast<std::uint32_t>(n.right));
    }
  }
  return found;
}

// ---- sizes ----

std::size_t UnionBoundary::bytes() const {
  return pieces_.capacity() * sizeof(Piece) + rings_.capacity() * sizeof(Ring) + index_->pieces.bytes() +
         index_->sausages.bytes() + index_->edges.bytes() + index_->piece_box.capacity() * sizeof(Box) + sizeof(Index);
}
std::size_t UnionBoundary::segment_count() const {
  return std::count_if(pieces_.begin(), pieces_.end(), [](const Piece& p) { return p.kind == Piece::Kind::Segment; });
}
std::size_t UnionBoundary::arc_count() const { return pieces_.size() - segment_count(); }
std::size_t UnionBoundary::vertex_count() const { return pieces_.size(); }

}  // namespace pendepth::polygon2
