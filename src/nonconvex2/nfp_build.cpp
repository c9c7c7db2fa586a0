// The per-pair no-fit polygon, construction (issue 5 item 4; survey §2 reduced convolution, DHS §6):
// the boundary of O = ∪ int S_ij (depth2_polygon_polygon.hpp) as exact uncovered pieces.
//
// 1. Candidates (reduced convolution): an edge e = p0 → p1 of P (any ring, P's interior on its
//    left) with a vertex q of Q such that q is convex in Q (interior angle ≤ π) and both Q edges
//    at q lie on the closed outer side of e; then Q + x with q + x on e touches e from outside
//    only at q, and the segment e − q is an edge of the convex sum T ⊕ (−U) for the triangle T of
//    P at e and any triangle U of Q at q (q is extreme in U against e's outward normal). And
//    symmetrically an edge of Q (as the edge −q0 → −q1 of −Q) with a convex vertex p of P whose
//    two edges lie on the outer side of it. Every point of ∂O is a touching placement whose
//    contact is such an edge–vertex pair (a reflex vertex or a vertex whose edges reach across e
//    would overlap), and triangulation diagonals never carry ∂O (their translates lie in O except
//    at their ends), so ∂O ⊆ ∪ candidates. Each candidate is kept symbolic: a Ray from the sum
//    vertex (p0, q) to (p1, q) (resp. (p, q0) to (p, q1)) with sym = true, so the exact algebra
//    of pair_sums.hpp and its symbolic ties apply. O lies on every candidate's left.
//    An edge of P antiparallel to an edge of Q gives up to four collinear candidates forming two
//    paths between the same two sum vertices, each covering the segment between them; when one
//    path is complete the other path's candidates are marked redundant: they still split the
//    other candidates in step 2 but are not classified (a sizeable share of the candidates on
//    real pieces, docs/benchmarks.md; the pieces cover the same points of ∂O, fewer duplicated).
// 2. Each candidate is classified (nfp_classify.cpp): split where other candidates meet it, one
//    exact point test per part against the open sums; maximal runs of uncovered parts are kept.
//    A point of a candidate lies on ∂S for a non-degenerate S of the family, so if no open sum
//    covers it, it is in cl(O) \ O = ∂O; with step 1 the pieces are exactly ∂O (with duplicates
//    where candidates coincide; zero-length pieces at isolated points). These are the same pieces
//    as the reference cutting (nfp_cut.cpp: every open sum meeting the candidate cut from it
//    exactly), which remains the fallback for candidates the classification does not settle.
// 3. nfp_rings.cpp links the pieces into rings, slits and points; a box hierarchy over the piece
//    boxes serves the queries (nfp_query.cpp).
// Cost: candidates O(nm) cross signs of edge vectors, each once (the turn tests are those signs,
// possibly negated; exact by rounding monotonicity and FMA product errors when the edge vectors
// are exact differences, else a static filter, then the exact predicate; K kept, K ≤ nm,
// typically O(n + m) on real pieces); classification O(K log K + X) for X box-overlapping candidate
// pairs plus one point test (O(1) sums on real pieces, worst O(nm)) per part and per split point;
// worst case O(n²m²) exact tests (a candidate met by > 256 others is cut by the reference, O(nm)).
// The cost per pair by step (classification, export, candidates, triangulations, hierarchies) is
// in docs/benchmarks.md.
// Departure from the usual reduced-convolution builders (CGAL, Clipper):
// no arrangement of the candidates is built and no winding numbers are computed; membership in O
// is decided directly by the open convex pair sums, which also yields the slits and isolated
// points of degenerate fits (that the winding number of the convolution cannot tell apart).
#include <cmath>

#include "geometry/exact.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "nonconvex2/shape_side.hpp"

namespace pendepth {

namespace nonconvex2 {

namespace {

double lower(double x) { return x - std::abs(x) * 0x1p-44 - 0x1p-1000; }
double upper(double x) { return x + std::abs(x) * 0x1p-44 + 0x1p-1000; }

// One edge g → next(g) of a shape: its vector d = next − g rounded once, and whether that rounding
// was exact (Knuth's TwoSum error of both coordinates is zero; overflow counts as inexact).
struct EdgeVec {
  double x = 0, y = 0;
  bool exact = false;
  std::uint32_t prev = 0;  // the vertex before g in its ring
};

bool exact_difference(double a, double b, double& d) {
  d = a - b;
  const double bb = d - a;
  return std::isfinite(d) && (a - (d - bb)) + (-b - bb) == 0;
}

void edge_vectors(const Polygon& S, EdgeVec* E) {
  const auto V = S.vertices();
  for (std::size_t g = 0; g < S.size(); ++g) {
    const std::size_t g1 = S.next(g);
    double dx, dy;
    const bool ex = exact_difference(V[g1].x(), V[g].x(), dx), ey = exact_difference(V[g1].y(), V[g].y(), dy);
    E[g].x = dx, E[g].y = dy, E[g].exact = ex && ey;
    E[g1].prev = static_cast<std::uint32_t>(g);
  }
}

// Exact sign of cross(u, v) for the edges u = a0 → a1 and v = b0 → b1 with vectors U, V.
// When both vectors are exact the cross is U.x·V.y − U.y·V.x of exact doubles, decided by
// exact::sign_ab_minus_cd (rounding monotonicity, then the products' FMA errors on equal
// roundings: parallel edges of integer shapes, the common case the static filter cannot settle).
// Otherwise the usual static filter. Then the exact fallback `exact_fallback()`
// (predicates::cross_edges, the same polynomial; its vertices are looked up only then).
template <class Fallback>
inline int cross_sign(const EdgeVec& U, const EdgeVec& V, Fallback&& exact_fallback) {
  if (U.exact && V.exact) {
    const int s = exact::sign_ab_minus_cd(U.x, V.y, U.y, V.x);
    if (s != 2) return s;
  } else {
    const double p1 = U.x * V.y, p2 = U.y * V.x;
    // The filter of predicates::cross_edges on the same rounded products.
    const double d = p1 - p2, bound = exact::kCrossBound * (std::abs(p1) + std::abs(p2)) + exact::kTiny;
    if (d > bound) return 1;
    if (d < -bound) return -1;
  }
  return exact_fallback();
}

struct Scratch {
  std::vector<EdgeVec> edges;
  std::vector<signed char> buf;
  std::vector<std::uint32_t> fits;
  std::vector<char> keep;
  // Large pairs do not pin their memory: shrink after them.
  void trim() {
    if (buf.size() > (std::size_t(1) << 16)) {
      edges = {};
      buf = {};
      fits = {};
      keep = {};
    }
  }
};

// The conservative box and rounded ends of a candidate whose E and line are set. The ends are
// each a sum of two input doubles rounded once.
void finish(NfpCandidate& c) {
  const Line& line = c.line;
  c.A = line.c1 + line.c2;
  c.B = line.q_edge ? Vec2(line.c1 + line.e1) : Vec2(line.e1 + line.c2);
  c.lo = Vec2(lower(std::min(c.A.x(), c.B.x())), lower(std::min(c.A.y(), c.B.y())));
  c.hi = Vec2(upper(std::max(c.A.x(), c.B.x())), upper(std::max(c.A.y(), c.B.y())));
}

}  // namespace

std::vector<NfpCandidate> nfp_candidates(const Polygon& P, const Polygon& Q) {
  const auto VP = P.vertices(), VQ = Q.vertices();
  const std::size_t n = P.size(), m = Q.size();
  // Scratch reused by the thread's next call (the builder runs once per pair, and fresh
  // allocations were a visible part of the set-up): edge vectors, turns and signs, the
  // qualifying pairs.
  thread_local Scratch scratch;
  std::vector<EdgeVec>& edges = scratch.edges;
  edges.resize(n + m);
  const EdgeVec* const EP = edges.data();
  const EdgeVec* const EQ = EP + n;
  edge_vectors(P, edges.data());
  edge_vectors(Q, edges.data() + n);
  // Every test below is the sign of cross(P edge g, Q edge h) for some g, h (the edges at a
  // vertex reversed where needed: an exact negation), so the n·m signs are computed once into a
  // table (up to 4 M entries; larger pairs evaluate each sign when needed, O(n + m) memory).
  // Then the turn at a vertex (> 0 strictly convex, 0 straight, < 0 reflex) and, per pair, the
  // two "edges on the outer side" tests read the table. One buffer: n + m turns, then the table.
  auto edge_sign = [&](std::size_t g, std::size_t h) {
    return cross_sign(EP[g], EQ[h], [&] { return predicates::cross_edges(VP[g], VP[P.next(g)], VQ[h], VQ[Q.next(h)]); });
  };
  const bool table = n * m <= (std::size_t(1) << 22);
  std::vector<signed char>& buf = scratch.buf;
  buf.resize(n + m + (table ? n * m : 0));
  signed char* const turnP = buf.data();
  signed char* const turnQ = turnP + n;
  signed char* const cross_table = turnQ + m;
  for (std::size_t g = 0; g < n && table; ++g)
    for (std::size_t h = 0; h < m; ++h) cross_table[g * m + h] = static_cast<signed char>(edge_sign(g, h));
  for (std::size_t g = 0; g < n; ++g) {
    const std::uint32_t a = EP[g].prev;
    turnP[g] = static_cast<signed char>(cross_sign(EP[a], EP[g], [&] { return predicates::cross_edges(VP[a], VP[g], VP[g], VP[P.next(g)]); }));
  }
  for (std::size_t h = 0; h < m; ++h) {
    const std::uint32_t a = EQ[h].prev;
    turnQ[h] = static_cast<signed char>(cross_sign(EQ[a], EQ[h], [&] { return predicates::cross_edges(VQ[a], VQ[h], VQ[h], VQ[Q.next(h)]); }));
  }
  // Vertex q of Q qualifies for P's edge g iff q is not reflex and Q's edges at q lie on the
  // closed right (outer) side of g: cross(g, q_prev − q) = −sign[g][prev q] ≤ 0 and
  // cross(g, q_next − q) = sign[g][q] ≤ 0. Vertex p of P qualifies for Q's edge h iff p is not
  // reflex and cross(h, p_prev − p) = sign[prev p][h] ≤ 0 and cross(h, p_next − p) =
  // −sign[p][h] ≤ 0. The qualifying pairs are listed first (same order as the output) so the
  // candidates, large records, are written once into storage allocated once.
  std::vector<std::uint32_t>& fits = scratch.fits;  // (edge, vertex) pairs, P edges first
  fits.clear();
  auto list = [&](auto&& sign) {
    for (std::uint32_t g = 0; g < n; ++g)
      for (std::uint32_t q = 0; q < m; ++q)
        if (turnQ[q] >= 0 && sign(g, EQ[q].prev) >= 0 && sign(g, q) <= 0) fits.insert(fits.end(), {g, q});
    const std::size_t kp = fits.size() / 2;
    for (std::uint32_t h = 0; h < m; ++h)
      for (std::uint32_t p = 0; p < n; ++p)
        if (turnP[p] >= 0 && sign(EP[p].prev, h) <= 0 && sign(p, h) >= 0) fits.insert(fits.end(), {h, p});
    return kp;
  };
  const std::size_t kp = table ? list([&](std::size_t g, std::size_t h) { return int(cross_table[g * m + h]); }) : list(edge_sign);
  std::vector<NfpCandidate> cand(fits.size() / 2);
  for (std::size_t k = 0; k < cand.size(); ++k) {
    NfpCandidate& c = cand[k];
    Ray& E = c.E;
    Line& L = c.line;
    E.sym = true;
    if (k < kp) {  // P's edge g → g1 with Q's vertex q: from sum vertex (g, q) to (g1, q)
      const std::uint32_t g = fits[2 * k], q = fits[2 * k + 1], g1 = static_cast<std::uint32_t>(P.next(g));
      E.o1 = VP[g];
      E.o2 = -VQ[q];
      E.a1 = VP[g1];
      E.b1 = VP[g];
      E.p0 = g, E.q0 = q, E.p1 = g1, E.q1 = q;
      L.c1 = VP[g], L.c2 = -VQ[q], L.e0 = VP[g], L.e1 = VP[g1];
      L.p0 = g, L.p1 = g1, L.q0 = L.q1 = q, L.q_edge = false;
      c.strict = turnQ[q] > 0;
    } else {  // −Q's edge −h → −h1 with P's vertex p: from (p, h) to (p, h1)
      const std::uint32_t h = fits[2 * k], p = fits[2 * k + 1], h1 = static_cast<std::uint32_t>(Q.next(h));
      E.o1 = VP[p];
      E.o2 = -VQ[h];
      E.a1 = -VQ[h1];
      E.b1 = -VQ[h];
      E.p0 = p, E.q0 = h, E.p1 = p, E.q1 = h1;
      L.c1 = VP[p], L.c2 = -VQ[h], L.e0 = -VQ[h], L.e1 = -VQ[h1];
      L.p0 = L.p1 = p, L.q0 = h, L.q1 = h1, L.q_edge = true;
      c.strict = turnP[p] > 0;
    }
    finish(c);
  }
  // Redundant candidates. An edge g = p0 → p1 of P antiparallel to an edge h = q0 → q1 of Q
  // (cross sign 0 exactly, opposite directions) gives −h the direction of g and up to four
  // candidates on one line, each from sum vertex to sum vertex: g − q0 = (p0,q0)→(p1,q0),
  // p1 − h = (p1,q0)→(p1,q1), p0 − h = (p0,q0)→(p0,q1), g − q1 = (p0,q1)→(p1,q1). Each of the two
  // paths from (p0,q0) to (p1,q1), through (p1,q0) or through (p0,q1), covers the whole segment
  // between them, so when both candidates of one path are kept the other path's add no point of
  // ∂O: they are marked redundant. They still split the other candidates (nfp_classify), so every
  // kept candidate is split and classified as before, and the pieces cover the same points. A
  // candidate kept for one group's path is never marked by another group (a straight vertex puts a
  // candidate in two groups), so each redundant candidate stays covered by kept ones.
  std::vector<char>& keep = scratch.keep;
  keep.assign(cand.size(), 0);
  auto sign_of = [&](std::size_t g, std::size_t h) { return table ? int(cross_table[g * m + h]) : edge_sign(g, h); };
  // The candidate index of the (edge, vertex) pair in fits[from, to) (sorted), or npos.
  constexpr std::size_t npos = ~std::size_t(0);
  auto find = [&](std::size_t from, std::size_t to, std::uint32_t e, std::uint32_t v) {
    std::size_t lo = from, hi = to;
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (fits[2 * mid] < e || (fits[2 * mid] == e && fits[2 * mid + 1] < v)) lo = mid + 1;
      else hi = mid;
    }
    return lo < to && fits[2 * lo] == e && fits[2 * lo + 1] == v ? lo : npos;
  };
  // Keeps path (x, y) when both are present and not redundant, and marks (u, w) redundant.
  auto settle = [&](std::size_t x, std::size_t y, std::size_t u, std::size_t w) {
    if (x == npos || y == npos || cand[x].redundant || cand[y].redundant) return false;
    keep[x] = keep[y] = 1;
    for (const std::size_t z : {u, w})
      if (z != npos && !keep[z]) cand[z].redundant = true;
    return true;
  };
  for (std::size_t a = 0; a < kp; ++a) {
    const std::uint32_t g = fits[2 * a], h = fits[2 * a + 1];  // candidate g − q0 with q0 = h's start
    if (sign_of(g, h) != 0) continue;
    const std::uint32_t g1 = static_cast<std::uint32_t>(P.next(g)), h1 = static_cast<std::uint32_t>(Q.next(h));
    // Parallel and both non-degenerate: opposite directions iff a non-zero coordinate of the edge
    // vectors differs in sign (exact double comparisons).
    const bool by_x = VP[g1].x() != VP[g].x();
    const bool opposite = by_x ? (VP[g1].x() > VP[g].x()) != (VQ[h1].x() > VQ[h].x()) : (VP[g1].y() > VP[g].y()) != (VQ[h1].y() > VQ[h].y());
    if (!opposite) continue;
    const std::size_t b = find(0, kp, g, h1), c = find(kp, cand.size(), h, g), d = find(kp, cand.size(), h, g1);
    if (!settle(a, d, b, c)) settle(c, b, a, d);
  }
  scratch.trim();
  return cand;
}

}  // namespace nonconvex2

namespace {
// Largest piece count whose query tree is built in order (BoxTree::build_in_order) rather than by
// median splits: for small no-fit polygons the in-order tree is several times cheaper to build
// and costs σ and σ_d only a few per cent, a trade-off that pays within a handful of queries; for
// large ones its queries get noticeably slower, hence the bound (docs/benchmarks.md).
constexpr std::size_t kInOrderTreeMax = 64;
}  // namespace

NoFitPolygon2::Impl::Impl(const Polygon& P, const Polygon& Q) : Impl(nonconvex2::make_side(P, false), nonconvex2::make_side(Q, true)) {}

NoFitPolygon2::Impl::Impl(std::shared_ptr<const nonconvex2::ShapeSide> p, std::shared_ptr<const nonconvex2::ShapeSide> q, bool queries)
    : S(std::move(p), std::move(q)) {
  // Step 1: candidates.
  const std::vector<nonconvex2::NfpCandidate> cand = nonconvex2::nfp_candidates(S.P, S.Q);
  sz.candidates = cand.size();
  // Step 2: their uncovered closed pieces. Usually about one per candidate (a candidate is cut
  // into few pieces, many are covered whole): reserving that many saves the growth of a vector
  // of large records.
  pieces.reserve(cand.size());
  nonconvex2::nfp_classify(S, cand, pieces);
  // Large pairs cover most candidates whole (large star pairs have many times more candidates than
  // pieces): the stored no-fit polygon does not keep that slack.
  if (pieces.capacity() > 2 * pieces.size() + 64) pieces.shrink_to_fit();
  sz.pieces = pieces.size();
  // Step 3: the query index over the piece boxes, read in place. Pieces come candidate by
  // candidate in convolution order (P's edges, then Q's, each in ring order), so runs of
  // consecutive pieces are mostly spatially close: for few pieces the linear in-order pairing
  // makes a tree nearly as good for the queries as the sorting median split, built far cheaper.
  if (!queries) {
    nfp_export(*this);
    return;
  }
  const auto lo = [&](std::size_t k) -> const Vec2& { return pieces[k].blo; };
  const auto hi = [&](std::size_t k) -> const Vec2& { return pieces[k].bhi; };
  if (pieces.size() <= kInOrderTreeMax) tree.build_in_order(pieces.size(), lo, hi);
  else tree.build_boxes(pieces.size(), lo, hi);
  nfp_export(*this);
  flat.build(*this);
}

NoFitPolygon2::NoFitPolygon2(const Polygon& P, const Polygon& Q) : impl_(std::make_unique<Impl>(P, Q)) {}
NoFitPolygon2::NoFitPolygon2(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
NoFitPolygon2 nfp_from_impl(std::unique_ptr<NoFitPolygon2::Impl> impl) { return NoFitPolygon2(std::move(impl)); }
NoFitPolygon2::~NoFitPolygon2() = default;
NoFitPolygon2::NoFitPolygon2(NoFitPolygon2&&) noexcept = default;
NoFitPolygon2& NoFitPolygon2::operator=(NoFitPolygon2&&) noexcept = default;

const std::vector<std::vector<std::vector<Vec2>>>& NoFitPolygon2::polygons() const { return impl_->polys; }
const std::vector<std::array<Vec2, 2>>& NoFitPolygon2::slits() const { return impl_->slits; }
const std::vector<Vec2>& NoFitPolygon2::points() const { return impl_->points; }

NfpSize NoFitPolygon2::size() const {
  NfpSize s = impl_->sz;
  s.rings = 0;
  for (const auto& poly : impl_->polys) s.rings += poly.size();
  s.slits = impl_->slits.size();
  s.points = impl_->points.size();
  std::size_t b = impl_->pieces.capacity() * sizeof(nonconvex2::NfpPiece) + impl_->tree.nodes.capacity() * sizeof(nonconvex2::BoxTree::Node);
  for (const auto& poly : impl_->polys) {
    b += poly.capacity() * sizeof(poly[0]);
    for (const auto& ring : poly) b += ring.capacity() * sizeof(Vec2);
  }
  b += impl_->slits.capacity() * sizeof(impl_->slits[0]) + impl_->points.capacity() * sizeof(Vec2);
  const nonconvex2::NfpFlat& f = impl_->flat;
  b += (f.rx0.capacity() + f.ry0.capacity() + f.rx1.capacity() + f.ry1.capacity() + f.px0.capacity() + f.py0.capacity() + f.pinv.capacity() +
        f.px1.capacity() + f.py1.capacity()) * sizeof(double) +
       f.slits.capacity() * sizeof(f.slits[0]) + f.points.capacity() * sizeof(Vec2);
  s.bytes = b;
  return s;
}

}  // namespace pendepth
