// pendepth — lower-dimensional shapes against a solid convex polytope in 3D (issue 16 item 4;
// docs/design.md "Lower-dimensional shapes"; survey §3: M's facet normals, support functions).
//
// Contract (flat3.hpp): S a solid ConvexPolytope (the role of P), L a point, segment or flat
// convex polygon with k vertices (the role of Q), both posed; M = S ⊕ (−L') with L' the placed L
// (in S's frame, l' = R·l + tq − tp). M is full-dimensional because S is, so overlap ⇔ 0 ∈ int M
// is the same definition as for two solids.
//
// Method: explicit enumeration of a SUPERSET of M's facet normals — S's face normals, ±L's
// normal (a polygon), and ±e_S × R·e_L for every true edge of S and edge of L — each a vector
// known exactly as a polynomial in the input doubles. Every u of the set has the valid
// supporting half-space u·x <= h_M(u), and M is the intersection of those half-spaces, so:
//   * 0 ∈ int M  ⇔  h_M(u) > 0 for every u (exact signs);
//   * σ   = min_u h_M(u)/|u|          (the distance to the boundary of an interior point);
//   * σ_d = min_{u·d>0} h_M(u)/(u·d̂)  (the exit of the ray from the half-space intersection);
//   * the cast's entry = max_{u·d<0} h_M(u)/(u·d̂), a hit iff entry <= exit (ratios compared
//     by exact signs);
//   * apart: dist(0, M) = max_u −h_M(u)/|u| over any family containing the direction of the
//     closest pair; the family adds, besides the facet normals (face–vertex, edge–edge pairs),
//     the exact directions of the vertex–vertex, vertex–edge and edge–vertex closest pairs.
// h_M(u) = max_i u·s_i − min_j u·l'_j with both extremes found exactly. S: every candidate
// names a vertex or edge of S (a face's corner; the edge; the vertex of a closest pair) and is
// kept only if that vertex passes the exact local-maximum test over S's adjacency (a local
// maximum of a linear function on a convex polytope is global; the edge's other end is a known
// tie) — a relevant u (a facet of M, a closest pair's direction) always passes, so the set stays
// a superset; ±L's normal climbs from S's support query. L: an exact scan of its k vertices.
// Ties known from the construction are never evaluated (exact zeros cost the slow tiers).
// Values: floating enclosures (the Fl tier's rigorous error bounds) select the candidates that
// can be optimal; only those get h_M(u) and the components of u accurate to ~1 ulp
// (exact::accurate_value) and |u| by a stable norm, so every length is within a few ulps (the
// minimum or maximum of values each a few ulps off is a few ulps off the exact one). Witnesses and
// contact points: the closest points of S and L' (after the move) in doubles, up to rounding.
// Complexity per query: O(C·c) for C = f_S + 2·e_S·e_L (+2) candidates (σ, σ_d, cast) and
// C + n·k + n·e_L + e_S·k (distance), c the vertex degree (a climb for L's normal), plus
// O(f_S·k + n·k + e_S·k) for the witnesses. Meant for points, segments and small polygons (k
// small); nothing is built per pair. Measured: docs/benchmarks.md (bench_primitives3).
// Two lower-dimensional shapes (flat_flat_distance, the cores of rounded shapes): the same family
// with S flat (±its normal, its edges); when the dimensions sum to 3 or more M may be solid, and
// 0 ∈ int M ⇔ every facet candidate has h > 0, then −σ as above. A polygon's exact parallel
// classes of edges and chords (FlatShape3::edge_dir / chord_dir, built once by flat_shape) mark
// more known ties: a candidate orthogonal to its own edge is orthogonal to every chord parallel
// to that edge (squares, rectangles, hexagons).
#include "convex3/flat3.hpp"

#include "convex3/polytope_data.hpp"
#include "geometry/exact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pendepth::convex3 {

// ---- the normal form of a lower-dimensional point set ----------------------------------------

namespace {
void parallel_classes(FlatShape3& f);  // FlatShape3::edge_dir, chord_dir (below)
}  // namespace

FlatShape3 flat_shape(std::span<const Vec3> pts, std::string_view name) {
  FlatShape3 f;
  f.name = std::string(name);
  if (pts.empty()) throw InvalidInput(f.name + ": no points");
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!pts[i].allFinite()) throw InvalidInput(f.name + ": point " + std::to_string(i) + " is not finite");
  std::size_t b = pts.size(), c = pts.size();
  for (std::size_t i = 1; i < pts.size() && b == pts.size(); ++i)
    if (pts[i] != pts[0]) b = i;
  if (b == pts.size()) {  // one point (possibly repeated)
    f.v = {pts[0]}, f.input = {0}, f.dim = 0;
    return f;
  }
  for (std::size_t i = 1; i < pts.size() && c == pts.size(); ++i)
    if (!predicates::collinear3(pts[0], pts[b], pts[i])) c = i;
  if (c == pts.size()) {  // a segment: the extremes along the line, exactly
    const Vec3 e = pts[b] - pts[0];  // any direction not orthogonal to the line orders it: use
    // exact comparisons of the points themselves along the line via the dominant axis (the line
    // is not orthogonal to its dominant axis, and projection onto it is injective on the line)
    int ax = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(e[k]) > std::abs(e[ax])) ax = k;
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 1; i < pts.size(); ++i) {
      if (pts[i][ax] < pts[lo][ax]) lo = i;
      if (pts[i][ax] > pts[hi][ax]) hi = i;
    }
    f.v = {pts[lo], pts[hi]}, f.input = {lo, hi}, f.dim = 1;
    return f;
  }
  for (std::size_t i = 1; i < pts.size(); ++i)
    if (predicates::orient3d(pts[0], pts[b], pts[c], pts[i]) != 0)
      throw InvalidInput(f.name + ": the points are not flat (they span a solid: use Shape3::hull)");
  // A polygon: the 2D hull of the projection that drops the axis of the normal's largest
  // component (injective on the plane; orientations exact: a projection only drops a coordinate).
  const Vec3 n = (pts[b] - pts[0]).cross(pts[c] - pts[0]);
  int ax = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[ax])) ax = k;
  // The rounded normal's dominant axis may be wrong only when two components are nearly equal;
  // then either projection is injective unless the exact component is zero: check exactly.
  const int ax1 = (ax + 1) % 3, ax2 = (ax + 2) % 3;
  auto proj = [&](const Vec3& p) { return Vec2(p[ax1], p[ax2]); };
  if (predicates::orient2d(proj(pts[0]), proj(pts[b]), proj(pts[c])) == 0) {
    for (int k = 0; k < 3; ++k) {
      auto pk = [&](const Vec3& p) { return Vec2(p[(k + 1) % 3], p[(k + 2) % 3]); };
      if (predicates::orient2d(pk(pts[0]), pk(pts[b]), pk(pts[c])) != 0) {
        ax = k;
        break;
      }
    }
  }
  auto P2 = [&](std::size_t i) { return Vec2(pts[i][(ax + 1) % 3], pts[i][(ax + 2) % 3]); };
  std::vector<std::size_t> idx(pts.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](std::size_t x, std::size_t y) {
    const Vec2 a = P2(x), c2 = P2(y);
    return a.x() < c2.x() || (a.x() == c2.x() && (a.y() < c2.y() || (a.y() == c2.y() && x < y)));
  });
  idx.erase(std::unique(idx.begin(), idx.end(), [&](std::size_t x, std::size_t y) { return P2(x) == P2(y); }),
            idx.end());
  std::vector<std::size_t> h(2 * idx.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < idx.size(); ++i) {  // Andrew's monotone chain, strict turns only
    while (k >= 2 && predicates::orient2d(P2(h[k - 2]), P2(h[k - 1]), P2(idx[i])) <= 0) --k;
    h[k++] = idx[i];
  }
  for (std::size_t i = idx.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && predicates::orient2d(P2(h[k - 2]), P2(h[k - 1]), P2(idx[i])) <= 0) --k;
    h[k++] = idx[i];
  }
  h.resize(k - 1);
  for (std::size_t i : h) f.v.push_back(pts[i]), f.input.push_back(i);
  f.dim = 2;
  parallel_classes(f);
  return f;
}

namespace {

template <class N>
using V = std::array<N, 3>;
template <class N>
V<N> sub(const V<N>& a, const V<N>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
template <class N>
N dot(const V<N>& a, const V<N>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class N>
V<N> cross(const V<N>& a, const V<N>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class N>
V<N> scl(const N& s, const V<N>& a) { return {s * a[0], s * a[1], s * a[2]}; }

// Exact: is v[b] − v[a] parallel to v[d] − v[c] (the input doubles; the differences never rounded)?
bool parallel(const std::vector<Vec3>& v, int a, int b, int c, int d) {
  for (int k = 0; k < 3; ++k)
    if (exact::exact_sign([&](auto f) {
          const V<decltype(f(0.0))> x{f(v[b].x()) - f(v[a].x()), f(v[b].y()) - f(v[a].y()), f(v[b].z()) - f(v[a].z())};
          const V<decltype(f(0.0))> y{f(v[d].x()) - f(v[c].x()), f(v[d].y()) - f(v[c].y()), f(v[d].z()) - f(v[c].z())};
          return cross(x, y)[k];
        }) != 0)
      return false;
  return true;
}

void parallel_classes(FlatShape3& f) {
  const int k = static_cast<int>(f.v.size());
  if (f.dim != 2 || k > 64) return;
  f.edge_dir.assign(k, -1);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i <= j && f.edge_dir[j] < 0; ++i)
      if (i == j || parallel(f.v, i, (i + 1) % k, j, (j + 1) % k)) f.edge_dir[j] = i;
  f.chord_dir.assign(static_cast<std::size_t>(k * k), -1);
  for (int a = 0; a < k; ++a)
    for (int b = a + 1; b < k; ++b)
      for (int j = 0; j < k; ++j)
        if (f.edge_dir[j] == j && parallel(f.v, a, b, j, (j + 1) % k)) {
          f.chord_dir[a * k + b] = f.chord_dir[b * k + a] = j;
          break;
        }
}
template <class N>
V<N> neg(const V<N>& a) { return {-a[0], -a[1], -a[2]}; }

// Closest points in doubles (Ericson, Real-Time Collision Detection §5.1.5, §5.1.9): only for
// the witnesses and contact points, whose contract is "up to rounding"; every decision and
// every length of the answers is exact / accurate elsewhere.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double den = 1 / (va + vb + vc);
  const double v = vb * den, w = vc * den;
  if (!std::isfinite(v) || !std::isfinite(w)) return a;  // a degenerate triangle (not used so)
  return a + ab * v + ac * w;
}
Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const double n = e.squaredNorm();
  const double t = n > 0 ? std::clamp((p - a).dot(e) / n, 0.0, 1.0) : 0.0;
  return a + t * e;
}
// The closest points of segments [p1, q1] and [p2, q2].
std::pair<Vec3, Vec3> closest_segments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) return {p1, p2};
  if (a <= 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), den = a * e - b * b;
      s = den > 0 ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
      else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  return {p1 + s * d1, p2 + t * d2};
}

// Candidate directions of M (see the header comment); `sg` = ±1 for the two-sided kinds.
enum class Kind { FaceS, FaceL, EdgeEdge, VertexVertex, VertexEdge, EdgeVertex };
struct Cand {
  Kind kind;
  int s = -1;  // S triangle (FaceS), S vertex, or S half-edge (a true edge)
  int l = -1;  // L vertex or L edge
  int sg = 1;
};

struct Eval {
  int i = -1, j = -1;  // exact support of S along u, exact minimiser of u·l' over L
  int hsign = 0;       // exact sign of h_M(u)
  bool valid = false;  // u ≠ 0 and the candidate relevant (see Ctx::eval)
  // Floating values with rigorous error bounds (the Fl tier): h ∈ hv ± he, u ∈ uv ± (componentwise,
  // norm ue); enough to discard most candidates without the accurate (double-double) values.
  double hv = 0, he = 0, ue = 0;
  Vec3 uv{0, 0, 0};
  // Filled by Ctx::refine: h_M(u) ~1 ulp, |u| ~1 ulp, u each component ~1 ulp.
  bool refined = false;
  double h = 0, norm = 0;
  Vec3 u{0, 0, 0};
};

constexpr double kInflate = 0x1p-50;  // covers the rounding of the few operations on the bounds
// Encloses |h_M(u)|/|u| from the floating bounds.
void ratio_bounds(const Eval& e, double& lo, double& hi) {
  const double n = e.uv.norm(), a = std::abs(e.hv);
  const double nlo = (n - e.ue) * (1 - kInflate), nhi = (n + e.ue) * (1 + kInflate);
  const double alo = std::max(0.0, a - e.he) * (1 - kInflate), ahi = (a + e.he) * (1 + kInflate);
  lo = nhi > 0 ? alo / nhi * (1 - kInflate) : 0;
  hi = nlo > 0 ? ahi / nlo * (1 + kInflate) : std::numeric_limits<double>::infinity();
}

// S is a solid polytope (SD, aS set) or, for the distance of two lower-dimensional shapes whose
// dimensions sum to at most 2, a lower-dimensional shape too (fs set): its faces are then ±its
// normal (triangle (0, 1, 2)), its edges j = (j, j + 1), its support an exact scan.
struct Ctx {
  const ConvexPolytope* S;
  const PolytopeData* SD;
  const VertexAdjacency* aS;
  const FlatShape3* fs;
  const FlatShape3& L;
  RelativePose rel;

  const Vec3& sv(int i) const { return fs ? fs->v[i] : SD->v[i]; }
  int s_count() const { return static_cast<int>(fs ? fs->v.size() : SD->v.size()); }

  template <class F>
  auto lift(F f, const Vec3& a) const {
    using N = decltype(f(0.0));
    return V<N>{f(a.x()), f(a.y()), f(a.z())};
  }
  template <class F>
  auto s(F f, int i) const { return lift(f, sv(i)); }
  // R·(b − a) for L vertices a, b (a < 0: R·l_b)
  template <class F>
  auto rvec(F f, int a, int b) const {
    using N = decltype(f(0.0));
    V<N> out;
    for (int c = 0; c < 3; ++c) {
      N acc = f(0.0);
      for (int k = 0; k < 3; ++k) acc = acc + f(rel.R(c, k)) * (a < 0 ? f(L.v[b][k]) : f(L.v[b][k]) - f(L.v[a][k]));
      out[c] = acc;
    }
    return out;
  }
  template <class F>
  auto lp(F f, int j) const {  // the placed L vertex j
    auto r = rvec(f, -1, j);
    for (int c = 0; c < 3; ++c) r[c] = r[c] + (f(rel.tq[c]) - f(rel.tp[c]));
    return r;
  }
  int ledge_end(int j) const { return (j + 1) % static_cast<int>(L.v.size()); }
  template <class F>
  auto ledge(F f, int j) const { return rvec(f, j, ledge_end(j)); }
  int s_origin(int h) const { return fs ? h : SD->levels[0].origin(h); }
  int s_target(int h) const { return fs ? (h + 1) % static_cast<int>(fs->v.size()) : SD->levels[0].target(h); }
  template <class F>
  auto sedge(F f, int h) const { return sub(s(f, s_target(h)), s(f, s_origin(h))); }

  template <class F>
  auto dir(const Cand& c, F f) const {
    using N = decltype(f(0.0));
    V<N> u;
    switch (c.kind) {
      case Kind::FaceS: {
        const std::array<int, 3> t = fs ? std::array<int, 3>{0, 1, 2} : SD->tris[c.s];
        u = cross(sub(s(f, t[1]), s(f, t[0])), sub(s(f, t[2]), s(f, t[0])));
        break;
      }
      case Kind::FaceL: u = cross(rvec(f, 0, 1), rvec(f, 0, 2)); break;
      case Kind::EdgeEdge: u = cross(sedge(f, c.s), ledge(f, c.l)); break;
      case Kind::VertexVertex: u = sub(lp(f, c.l), s(f, c.s)); break;
      case Kind::VertexEdge: {
        const auto w = sub(lp(f, c.l), s(f, c.s));
        const auto e = ledge(f, c.l);
        u = sub(scl(dot(e, e), w), scl(dot(w, e), e));
        break;
      }
      case Kind::EdgeVertex: {
        const auto w = sub(lp(f, c.l), s(f, s_origin(c.s)));
        const auto e = sedge(f, c.s);
        u = sub(scl(dot(e, e), w), scl(dot(w, e), e));
        break;
      }
    }
    return c.sg < 0 ? neg(u) : u;
  }

  bool zero(const Cand& c) const {
    for (int k = 0; k < 3; ++k)
      if (exact::exact_sign([&](auto f) { return dir(c, f)[k]; }) != 0) return false;
    return true;
  }

  // h_M(u) with exact extremes; nullopt-like (norm 0) for u = 0.
  Eval eval(const Cand& c) const {
    Eval r;
    const auto ua = dir(c, exact::LiftFl{});
    const Vec3 u(ua[0].v, ua[1].v, ua[2].v);
    const bool surely_nonzero = [&] {
      for (int k = 0; k < 3; ++k)
        if (exact::certified_sign(ua[k]) != 2 && ua[k].v != 0) return true;
      return false;
    }();
    if (!surely_nonzero && zero(c)) return r;
    // Ties known from the construction are skipped (exact zeros cost the slow exact tiers): S's
    // face along its own normal (any of its vertices is a maximiser), the two ends of the edge
    // of S or of L that u is orthogonal to, every vertex of L along L's normal.
    const bool s_edge = c.kind == Kind::EdgeEdge || c.kind == Kind::EdgeVertex;
    const bool l_edge = c.kind == Kind::EdgeEdge || c.kind == Kind::VertexEdge;
    // A flat shape's chords parallel to the candidate's own edge tie too (FlatShape3::chord_dir).
    auto chord_tie = [](const FlatShape3* F, int e, int a, int b) {
      const int k = static_cast<int>(F->v.size());
      return !F->chord_dir.empty() && F->chord_dir[a * k + b] >= 0 && F->chord_dir[a * k + b] == F->edge_dir[e];
    };
    auto s_tie = [&](int a, int b) {
      return s_edge && ((a == s_origin(c.s) && b == s_target(c.s)) || (b == s_origin(c.s) && a == s_target(c.s)) ||
                        (fs && chord_tie(fs, c.s, a, b)));
    };
    auto l_tie = [&](int a, int b) {
      return c.kind == Kind::FaceL ||
             (l_edge && ((a == c.l && b == ledge_end(c.l)) || (b == c.l && a == ledge_end(c.l)) || chord_tie(&L, c.l, a, b)));
    };
    int i = 0;
    if (c.kind == Kind::FaceS) {
      i = fs ? 0 : SD->tris[c.s][0];
    } else if (!fs && c.kind != Kind::FaceL) {
      // u is relevant only where S's support along u holds the candidate's own vertex or edge (a
      // facet of M, or the direction of a closest pair): check that vertex is a local — hence
      // global — maximum, else drop the candidate (the superset of facet normals stays one).
      i = c.kind == Kind::EdgeEdge || c.kind == Kind::EdgeVertex ? s_origin(c.s) : c.s;
      for (int e = aS->start[i]; e < aS->start[i + 1]; ++e) {
        const int nb = aS->nbr[e];
        if (!s_tie(nb, i) && exact::exact_sign([&](auto f) { return dot(dir(c, f), sub(s(f, nb), s(f, i))); }) > 0)
          return r;  // not relevant: valid stays false
      }
    } else if (fs) {
      for (int x = 1; x < s_count(); ++x)
        if (!s_tie(x, i) && exact::exact_sign([&](auto f) { return dot(dir(c, f), sub(s(f, x), s(f, i))); }) > 0) i = x;
    } else {
      i = (u.allFinite() && u != Vec3::Zero()) ? S->support(u) : 0;
      for (bool moved = true; moved;) {  // exact climb: a local maximum is the global one
        moved = false;
        for (int e = aS->start[i]; e < aS->start[i + 1]; ++e) {
          const int nb = aS->nbr[e];
          if (!s_tie(nb, i) && exact::exact_sign([&](auto f) { return dot(dir(c, f), sub(s(f, nb), s(f, i))); }) > 0) {
            i = nb, moved = true;
            break;
          }
        }
      }
    }
    int j = 0;
    for (int x = 1; x < static_cast<int>(L.v.size()); ++x)
      if (!l_tie(x, j) && exact::exact_sign([&](auto f) { return dot(dir(c, f), rvec(f, j, x)); }) < 0) j = x;
    r.i = i, r.j = j;
    auto hf = [&](auto f) { return dot(dir(c, f), sub(s(f, i), lp(f, j))); };
    r.hsign = exact::exact_sign(hf);
    const exact::Fl hfl = hf(exact::LiftFl{});
    r.hv = hfl.v, r.he = exact::safe_bound(hfl.e);
    Vec3 ue;
    for (int k = 0; k < 3; ++k) r.uv[k] = ua[k].v, ue[k] = exact::safe_bound(ua[k].e);
    r.ue = ue.norm() * (1 + kInflate);
    r.valid = std::isfinite(r.hv) && r.uv.allFinite() && std::isfinite(r.ue);
    if (!r.valid) refine(c, r), r.valid = true;  // over- or underflow of the floating tier: accurate
    return r;
  }

  // The accurate values of a candidate (each component of u accurately: no squares, so no over-
  // or underflow of |u|²).
  void refine(const Cand& c, Eval& r) const {
    if (r.refined) return;
    const int i = r.i, j = r.j;
    auto hf = [&](auto f) { return dot(dir(c, f), sub(s(f, i), lp(f, j))); };
    r.h = r.hsign == 0 ? 0.0 : exact::accurate_value(hf);
    Vec3 uc;
    for (int k = 0; k < 3; ++k) uc[k] = exact::accurate_value([&](auto f) { return dir(c, f)[k]; });
    r.norm = uc.stableNorm();
    r.u = uc;
    r.refined = true;
    // Keep the bounds consistent for callers that read them after refining.
    r.hv = r.h, r.he = std::abs(r.h) * 0x1p-50, r.uv = uc, r.ue = r.norm * 0x1p-50;
  }

  static Vec3 unit(const Eval& e) { return e.u / e.norm; }  // precondition: refined
  Vec3 svert(int i) const { return sv(i); }
  std::vector<int> s_edges() const {
    if (!fs) return SD->edges;
    std::vector<int> e(fs->dim == 0 ? 0 : fs->dim == 1 ? 1 : fs->v.size());
    for (std::size_t j = 0; j < e.size(); ++j) e[j] = static_cast<int>(j);
    return e;
  }
  Vec3 lvert(int j) const { return rel.place(L.v[j]); }

  // The facet candidates (σ, σ_d, overlap, cast): S's faces, L's normal, edge × edge.
  std::vector<Cand> facets() const {
    std::vector<Cand> out;
    if (fs && fs->dim == 2) out.push_back({Kind::FaceS, 0, -1, 1}), out.push_back({Kind::FaceS, 0, -1, -1});
    std::vector<char> seen(fs ? 0 : S->face_count(), 0);
    for (std::size_t t = 0; !fs && t < SD->tris.size(); ++t) {
      const int fc = S->face_of_triangle(t);
      if (!seen[fc]) seen[fc] = 1, out.push_back({Kind::FaceS, static_cast<int>(t), -1, 1});
    }
    if (L.dim == 2) out.push_back({Kind::FaceL, -1, 0, 1}), out.push_back({Kind::FaceL, -1, 0, -1});
    const int le = L.dim == 0 ? 0 : L.dim == 1 ? 1 : static_cast<int>(L.v.size());
    for (int h : s_edges())
      for (int j = 0; j < le; ++j) out.push_back({Kind::EdgeEdge, h, j, 1}), out.push_back({Kind::EdgeEdge, h, j, -1});
    return out;
  }
  // The extra directions of the closest pairs (distance).
  std::vector<Cand> closest_pairs() const {
    std::vector<Cand> out;
    const int n = s_count(), k = static_cast<int>(L.v.size());
    const int le = L.dim == 0 ? 0 : L.dim == 1 ? 1 : k;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < k; ++j) out.push_back({Kind::VertexVertex, i, j, 1});
      for (int j = 0; j < le; ++j) out.push_back({Kind::VertexEdge, i, j, 1});
    }
    for (int h : s_edges())
      for (int j = 0; j < k; ++j) out.push_back({Kind::EdgeVertex, h, j, 1});
    return out;
  }

  Feature3 feature_s(const Cand& c, const Eval& e) const {
    switch (c.kind) {
      case Kind::FaceS: return {FeatureKind3::Face, c.s};
      case Kind::EdgeEdge:
      case Kind::EdgeVertex: return {FeatureKind3::Edge, c.s};
      default: return {FeatureKind3::Vertex, e.i};
    }
  }
  Feature3 feature_l(const Cand& c, const Eval& e) const {
    switch (c.kind) {
      case Kind::FaceL: return {FeatureKind3::Face, 0};
      case Kind::EdgeEdge:
      case Kind::VertexEdge: return {FeatureKind3::Edge, c.l};
      default: return {FeatureKind3::Vertex, e.j};
    }
  }
  // The closest points (S's frame, doubles) of S and L' + v: the witnesses and contact points.
  // S's triangles (or fan) against L's vertices, S's vertices against L's triangles (fan),
  // segment or point, S's edges against L's edges. O(f·k + n·k + e·k).
  std::pair<Vec3, Vec3> closest(const Vec3& v) const {
    const int k = static_cast<int>(L.v.size()), n = s_count();
    std::vector<Vec3> l(k);
    for (int j = 0; j < k; ++j) l[j] = lvert(j) + v;
    double best = std::numeric_limits<double>::infinity();
    std::pair<Vec3, Vec3> out{svert(0), l[0]};
    auto take = [&](const Vec3& a, const Vec3& b) {
      const double d = (a - b).squaredNorm();
      if (d < best) best = d, out = {a, b};
    };
    auto point_vs = [&](const Vec3& p, const std::vector<Vec3>& poly, bool p_on_s) {  // p against a flat shape
      Vec3 c = poly[0];
      if (poly.size() == 2) c = closest_on_segment(p, poly[0], poly[1]);
      double bd = (c - p).squaredNorm();
      for (std::size_t t = 1; t + 1 < poly.size() && poly.size() >= 3; ++t) {
        const Vec3 x = closest_on_triangle(p, poly[0], poly[t], poly[t + 1]);
        if ((x - p).squaredNorm() < bd || t == 1) bd = (x - p).squaredNorm(), c = x;
      }
      p_on_s ? take(p, c) : take(c, p);
    };
    if (fs) {
      std::vector<Vec3> sv(fs->v.begin(), fs->v.end());
      for (const Vec3& q : l) point_vs(q, sv, false);
    } else {
      for (const auto& t : SD->tris)
        for (const Vec3& q : l) take(closest_on_triangle(q, SD->v[t[0]], SD->v[t[1]], SD->v[t[2]]), q);
    }
    for (int i = 0; i < n; ++i) point_vs(svert(i), l, true);
    const int le = L.dim == 0 ? 0 : L.dim == 1 ? 1 : k;
    for (int h : s_edges())
      for (int j = 0; j < le; ++j) {
        const auto [a, b] = closest_segments(svert(s_origin(h)), svert(s_target(h)), l[j], l[(j + 1) % k]);
        take(a, b);
      }
    return out;
  }
  Vec3 contact(const Cand&, const Eval&, const Vec3& v) const {
    const auto [a, b] = closest(v);
    return 0.5 * (a + b);
  }
};

RelativePose relative(const Pose3& ps, const Pose3& pl) {
  const Eigen::Matrix3d Rp = ps.matrix(), Rq = pl.matrix();
  RelativePose r;
  r.R = Rp.transpose() * Rq;
  r.tq = Rp.transpose() * pl.translation;
  r.tp = Rp.transpose() * ps.translation;
  return r;
}

Ctx make_ctx(const ConvexPolytope& S, const FlatShape3& L, const Pose3& ps, const Pose3& pl) {
  const PolytopeData& d = data_of(S);
  return Ctx{&S, &d, &vertex_adjacency(d), nullptr, L, relative(ps, pl)};
}

// Exact sign of u·d for the candidate (d in S's frame).
int dir_sign(const Ctx& x, const Cand& c, const Vec3& d) {
  return exact::exact_sign([&](auto f) { return dot(x.dir(c, f), x.lift(f, d)); });
}
// h_M(u)·|d|/(u·d) within a few ulps (u·d ≠ 0).
double ratio(const Ctx& x, const Cand& c, const Eval& e, const Vec3& d) {
  const double r = exact::accurate_ratio([&](auto f) { return dot(x.dir(c, f), sub(x.s(f, e.i), x.lp(f, e.j))); },
                                         [&](auto f) { return dot(x.dir(c, f), x.lift(f, d)); });
  return r * d.norm();
}
// Exact sign of h1/(u1·d) − h2/(u2·d) when u1·d and u2·d have the same sign (their product is
// positive): sign(h1·(u2·d) − h2·(u1·d)).
int compare_ratio(const Ctx& x, const Cand& c1, const Eval& e1, const Cand& c2, const Eval& e2, const Vec3& d) {
  return exact::exact_sign([&](auto f) {
    const auto dd = x.lift(f, d);
    const auto h1 = dot(x.dir(c1, f), sub(x.s(f, e1.i), x.lp(f, e1.j)));
    const auto h2 = dot(x.dir(c2, f), sub(x.s(f, e2.i), x.lp(f, e2.j)));
    return h1 * dot(x.dir(c2, f), dd) - h2 * dot(x.dir(c1, f), dd);
  });
}

struct Scan {
  std::vector<Cand> cands;
  std::vector<Eval> evals;
  bool overlapping = true;  // every h > 0
  bool touching = false;    // every h >= 0, some h = 0
  int zero_at = -1;
};
// The candidate among those with ok(k) minimising (sense > 0) or maximising (sense < 0) the
// accurate |h_M(u)|/|u|: the floating bounds select the few whose enclosures reach the best
// bound, only those are refined. Returns −1 when none; `value` the accurate optimum.
template <class Ok>
int select(const Ctx& x, const std::vector<Cand>& cands, std::vector<Eval>& evals, int sense, Ok ok, double& value) {
  double threshold = sense > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 2>> b(cands.size());
  for (std::size_t k = 0; k < cands.size(); ++k) {
    if (!evals[k].valid || !ok(k)) continue;
    ratio_bounds(evals[k], b[k][0], b[k][1]);
    threshold = sense > 0 ? std::min(threshold, b[k][1]) : std::max(threshold, b[k][0]);
  }
  int best = -1;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    if (!evals[k].valid || !ok(k) || (sense > 0 ? b[k][0] > threshold : b[k][1] < threshold)) continue;
    x.refine(cands[k], evals[k]);
    const double v = std::abs(evals[k].h) / evals[k].norm;
    if (best < 0 || (sense > 0 ? v < value : v > value)) value = v, best = static_cast<int>(k);
  }
  return best;
}

Scan scan(const Ctx& x) {
  Scan s;
  s.cands = x.facets();
  s.evals.reserve(s.cands.size());
  bool nonneg = true;
  for (std::size_t k = 0; k < s.cands.size(); ++k) {
    s.evals.push_back(x.eval(s.cands[k]));
    const Eval& e = s.evals.back();
    if (!e.valid) continue;
    if (e.hsign <= 0) s.overlapping = false;
    if (e.hsign < 0) nonneg = false;
    if (e.hsign == 0 && s.zero_at < 0) s.zero_at = static_cast<int>(k);
  }
  s.touching = nonneg && !s.overlapping;
  return s;
}

Depth3 world(Depth3 r, const Pose3& ps, const Vec3& v, const Vec3& normal, const Vec3& facet, const Vec3& w) {
  const Eigen::Matrix3d Rp = ps.matrix();
  r.translation = Rp * v + Vec3::Zero();  // + 0: no −0 components from the rotation
  r.normal = Rp * normal + Vec3::Zero();
  r.facet_normal = Rp * facet + Vec3::Zero();
  r.witness_p = r.witness_q = Rp * w + ps.translation;
  return r;
}

// Apart (or touching when no h < 0): the largest −h_M(u)/|u| over `cands`, which hold the facet
// normals and the closest-pair directions; the witnesses from the best candidate's features.
Distance3 apart(const Ctx& x, const std::vector<Cand>& cands, std::vector<Eval>& evals, const Pose3& ps) {
  Distance3 r;
  const Eigen::Matrix3d Rp = ps.matrix();
  double bv = 0;
  const int best = select(x, cands, evals, -1, [&](std::size_t k) { return evals[k].hsign < 0; }, bv);
  if (best < 0) return r;
  const Cand& c = cands[best];
  const Eval& e = evals[best];
  const Vec3 u = x.unit(e);  // from S towards L
  // The closest pair on S and L' (doubles); witness_q − witness_p = distance·normal up to rounding.
  const auto [wp, wq0] = x.closest(Vec3::Zero());
  const Vec3 wq = wp + bv * u;
  (void)wq0;
  r.distance = r.lower_bound = r.upper_bound = bv;
  r.normal = Rp * u + Vec3::Zero();
  r.translation = -bv * r.normal + Vec3::Zero();
  r.witness_p = Rp * wp + ps.translation;
  r.witness_q = Rp * wq + ps.translation;
  r.feature_p = x.feature_s(c, e), r.feature_q = x.feature_l(c, e);
  return r;
}

}  // namespace

namespace {
// σ of the context's M from its scan of the facet candidates (0 when not overlapping).
Depth3 minimum_of(const Ctx& x, Scan& sc, const Pose3& ps) {
  Depth3 r;
  r.kind = DepthKind::Minimum;
  r.candidates = sc.cands.size();
  if (!sc.overlapping) return r;
  double bv = 0;
  const int best = select(x, sc.cands, sc.evals, 1, [](std::size_t) { return true; }, bv);
  const Cand& c = sc.cands[best];
  const Eval& e = sc.evals[best];
  const Vec3 u = x.unit(e), v = bv * u;
  r.overlapping = true;
  r.depth = r.lower_bound = r.upper_bound = bv;
  r.feature_p = x.feature_s(c, e), r.feature_q = x.feature_l(c, e);
  return world(r, ps, v, u, u, x.contact(c, e, v));
}

// The signed distance of an overlapping pair from σ: the move of Q by σ's translation; witness_q
// on the unmoved Q.
Distance3 overlap_distance(const Depth3& m) {
  Distance3 r;
  r.distance = r.lower_bound = r.upper_bound = -m.depth;
  r.overlapping = true;
  r.normal = m.normal;
  r.translation = m.translation;
  r.witness_p = m.witness_p, r.witness_q = m.witness_q - m.translation;
  r.feature_p = m.feature_p, r.feature_q = m.feature_q;
  return r;
}
}  // namespace

Depth3 flat_minimum(const ConvexPolytope& S, const Pose3& ps, const FlatShape3& L, const Pose3& pl) {
  const Ctx x = make_ctx(S, L, ps, pl);
  Scan sc = scan(x);
  return minimum_of(x, sc, ps);
}

Depth3 flat_directional(const ConvexPolytope& S, const Pose3& ps, const FlatShape3& L, const Pose3& pl,
                        const Vec3& d_world) {
  const Ctx x = make_ctx(S, L, ps, pl);
  const Vec3 d = ps.matrix().transpose() * d_world;
  if (!d.allFinite() || d == Vec3::Zero()) throw InvalidInput("direction: zero or non-finite in P's frame");
  Scan sc = scan(x);
  Depth3 r;
  r.kind = DepthKind::Directional;
  r.candidates = sc.cands.size();
  if (!sc.overlapping) return r;
  // h/(u·d) over the candidates facing d: floating enclosures first, accurate ratios for the few
  // that can be the least (h > 0 on every candidate here).
  const std::size_t C = sc.cands.size();
  std::vector<double> lo(C, 0), hi(C, 0);
  std::vector<char> facing(C, 0);
  double threshold = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < C; ++k) {
    if (!sc.evals[k].valid || dir_sign(x, sc.cands[k], d) <= 0) continue;
    facing[k] = 1;
    const exact::Fl a = dot(x.dir(sc.cands[k], exact::LiftFl{}), x.lift(exact::LiftFl{}, d));
    const Eval& e = sc.evals[k];
    const double ae = exact::safe_bound(a.e), alo = (a.v - ae) * (1 - kInflate), ahi = (a.v + ae) * (1 + kInflate);
    const double hlo = std::max(0.0, e.hv - e.he) * (1 - kInflate), hhi = (e.hv + e.he) * (1 + kInflate);
    lo[k] = ahi > 0 ? hlo / ahi * (1 - kInflate) : 0;
    hi[k] = alo > 0 && std::isfinite(ahi) ? hhi / alo * (1 + kInflate) : std::numeric_limits<double>::infinity();
    threshold = std::min(threshold, hi[k]);
  }
  int best = -1;
  double bv = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < C; ++k) {
    if (!facing[k] || lo[k] > threshold) continue;
    const double v = ratio(x, sc.cands[k], sc.evals[k], d);
    if (v < bv) bv = v, best = static_cast<int>(k);
  }
  const Cand& c = sc.cands[best];  // M bounded and 0 ∈ int M: some facet faces d
  Eval& e = sc.evals[best];
  x.refine(c, e);
  const Vec3 dh = d.normalized(), v = bv * dh;
  r.overlapping = true;
  r.depth = r.lower_bound = r.upper_bound = bv;
  r.feature_p = x.feature_s(c, e), r.feature_q = x.feature_l(c, e);
  return world(r, ps, v, dh, x.unit(e), x.contact(c, e, v));
}

Distance3 flat_signed_distance(const ConvexPolytope& S, const Pose3& ps, const FlatShape3& L, const Pose3& pl) {
  const Ctx x = make_ctx(S, L, ps, pl);
  const Eigen::Matrix3d Rp = ps.matrix();
  Distance3 r;
  Scan sc = scan(x);
  if (sc.overlapping) return overlap_distance(minimum_of(x, sc, ps));
  if (sc.touching) {
    const Cand& c = sc.cands[sc.zero_at];
    const Eval& e = sc.evals[sc.zero_at];
    r.witness_p = r.witness_q = Rp * x.contact(c, e, Vec3::Zero()) + ps.translation;
    r.feature_p = x.feature_s(c, e), r.feature_q = x.feature_l(c, e);
    return r;
  }
  std::vector<Cand> cands = sc.cands;
  std::vector<Eval> evals = sc.evals;
  for (const Cand& c : x.closest_pairs()) cands.push_back(c), evals.push_back(x.eval(c));
  return apart(x, cands, evals, ps);
}

Distance3 flat_flat_distance(const FlatShape3& A, const Pose3& pa, const FlatShape3& B, const Pose3& pb,
                             Vec3* touch_normal) {
  const Ctx x{nullptr, nullptr, nullptr, &A, B, relative(pa, pb)};
  Scan sc;
  sc.cands = x.facets();
  for (const Cand& c : sc.cands) {
    sc.evals.push_back(x.eval(c));
    if (sc.evals.back().valid && sc.evals.back().hsign <= 0) sc.overlapping = false;
  }
  // Dimensions summing to 3 or more: M may be solid. Its facet normals are among the candidates
  // (±A's and ±B's normals, edge × edge), so 0 ∈ int M iff every one has h > 0 (a flat M has a
  // normal n with h(n) = −h(−n) among them), and then σ is the least h/|u| as for a solid S.
  if (A.dim + B.dim > 2 && sc.overlapping) return overlap_distance(minimum_of(x, sc, pa));
  std::vector<Cand>& cands = sc.cands;
  std::vector<Eval>& evals = sc.evals;
  for (const Cand& c : x.closest_pairs()) cands.push_back(c), evals.push_back(x.eval(c));
  Distance3 r = apart(x, cands, evals, pa);
  if (r.distance > 0) return r;
  // Touching (0 ∈ ∂M, or M has no interior): a candidate plane through 0 (h = 0, every h >= 0)
  // supports M and gives the contact; without one (points on points or on collinear segments)
  // a vertex of one shape in the other, and any normal ⊥ to the cores' span.
  const Eigen::Matrix3d Ra = pa.matrix();
  Vec3 c = Vec3::Zero(), n = Vec3::Zero();
  bool found = false;
  for (std::size_t k = 0; k < cands.size() && !found; ++k)
    if (evals[k].valid && evals[k].hsign == 0) {
      x.refine(cands[k], evals[k]);
      c = x.contact(cands[k], evals[k], Vec3::Zero()), n = Ctx::unit(evals[k]), found = true;
      r.feature_p = x.feature_s(cands[k], evals[k]), r.feature_q = x.feature_l(cands[k], evals[k]);
    }
  if (!found) {
    c = x.contact(Cand{}, Eval{}, Vec3::Zero());
    std::vector<Vec3> a(A.v.size()), b(B.v.size());
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = x.svert(static_cast<int>(i));
    for (std::size_t j = 0; j < b.size(); ++j) b[j] = x.lvert(static_cast<int>(j));
    const Vec3 e = a.size() > 1 ? Vec3(a[1] - a[0]) : b.size() > 1 ? Vec3(b[1] - b[0]) : Vec3(1, 0, 0);
    int ax = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(e[k]) < std::abs(e[ax])) ax = k;
    n = e.cross(Vec3::Unit(ax)).normalized();
  }
  r.witness_p = r.witness_q = Ra * c + pa.translation;
  if (touch_normal) *touch_normal = Ra * n;
  return r;
}

Cast3 miss() {
  Cast3 r;
  r.distance = std::numeric_limits<double>::infinity();
  return r;
}

namespace {
Cast3 flat_cast_exact(const ConvexPolytope& S, const Pose3& ps, const FlatShape3& L, const Pose3& pl,
                      const Vec3& d_world) {
  const Ctx x = make_ctx(S, L, ps, pl);
  const Eigen::Matrix3d Rp = ps.matrix();
  const Vec3 d = Rp.transpose() * d_world;
  if (!d.allFinite() || d == Vec3::Zero()) throw InvalidInput("direction: zero or non-finite in P's frame");
  Scan sc = scan(x);
  Cast3 r;
  if (sc.overlapping) {
    r.hit = r.overlapping = true;
    return r;
  }
  // The ray s·d̂ (s >= 0) against the half-spaces u·x <= h: entry = max over u·d < 0 (and 0),
  // exit = min over u·d > 0; u·d = 0 needs h >= 0. Ties broken by the candidate order.
  int in = -1, out = -1;
  std::vector<int> ds(sc.cands.size(), 0);
  for (std::size_t k = 0; k < sc.cands.size(); ++k) {
    const Cand& c = sc.cands[k];
    const Eval& e = sc.evals[k];
    if (!e.valid) continue;
    const int s = ds[k] = dir_sign(x, c, d);
    if (s == 0) {
      if (e.hsign < 0) return miss();
    } else if (s < 0) {  // entry bound h/(u·d): positive iff h < 0
      if (e.hsign < 0 && (in < 0 || compare_ratio(x, c, e, sc.cands[in], sc.evals[in], d) > 0))
        in = static_cast<int>(k);
    } else {
      if (e.hsign < 0) return miss();  // exit < 0
      if (out < 0 || compare_ratio(x, c, e, sc.cands[out], sc.evals[out], d) < 0) out = static_cast<int>(k);
    }
  }
  // entry = max(0, bound of `in`); exit = bound of `out` (>= 0). Hit iff entry <= exit.
  if (in >= 0 && out >= 0) {
    const int diff = exact::exact_sign([&](auto f) {
      const auto dd = x.lift(f, d);
      const Cand &c1 = sc.cands[in], &c2 = sc.cands[out];
      const Eval &e1 = sc.evals[in], &e2 = sc.evals[out];
      const auto h1 = dot(x.dir(c1, f), sub(x.s(f, e1.i), x.lp(f, e1.j)));
      const auto h2 = dot(x.dir(c2, f), sub(x.s(f, e2.i), x.lp(f, e2.j)));
      return h1 * dot(x.dir(c2, f), dd) - h2 * dot(x.dir(c1, f), dd);
    });
    // h1/a1 − h2/a2 = (h1·a2 − h2·a1)/(a1·a2) with a1 < 0 < a2: sign = −diff.
    if (-diff > 0) return miss();
  }
  r.hit = true;
  const Vec3 dh = d.normalized();
  if (in < 0) {  // touching at s = 0 (0 ∈ ∂M): the facet through 0
    const Cand& c = sc.cands[sc.zero_at];
    Eval& e = sc.evals[sc.zero_at];
    x.refine(c, e);
    r.normal = Rp * x.unit(e);
    r.witness_p = r.witness_q = Rp * x.contact(c, e, Vec3::Zero()) + ps.translation;
    r.feature_p = x.feature_s(c, e), r.feature_q = x.feature_l(c, e);
    return r;
  }
  const Cand& c = sc.cands[in];
  Eval& e = sc.evals[in];
  x.refine(c, e);
  const double s = ratio(x, c, e, d);
  const Vec3 v = s * dh;
  r.distance = s;
  r.translation = Rp * v;
  r.normal = Rp * x.unit(e);
  r.witness_p = r.witness_q = Rp * x.contact(c, e, v) + ps.translation;
  r.feature_p = x.feature_s(c, e), r.feature_q = x.feature_l(c, e);
  return r;
}

}  // namespace

Cast3 flat_cast(const ConvexPolytope& S, const Pose3& ps, const FlatShape3& L, const Pose3& pl, const Vec3& d) {
  Cast3 r = flat_cast_exact(S, ps, L, pl, d);
  r.lower_bound = r.upper_bound = r.distance;  // exact: the bracket is the answer
  return r;
}

}  // namespace pendepth::convex3
