// The per-pair no-fit polygon, construction (issue 5 item 4; survey §2 reduced convolution, DHS §6):
// the boundary of O = ∪ int S_ij (depth2_nonconvex.hpp) as exact uncovered pieces.
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
// 2. Each candidate is classified (nfp_classify.cpp): split where other candidates meet it, one
//    exact point test per part against the open sums; maximal runs of uncovered parts are kept.
//    A point of a candidate lies on ∂S for a non-degenerate S of the family, so if no open sum
//    covers it, it is in cl(O) \ O = ∂O; with step 1 the pieces are exactly ∂O (with duplicates
//    where candidates coincide; zero-length pieces at isolated points). These are the same pieces
//    as the reference cutting (nfp_cut.cpp: every open sum meeting the candidate cut from it
//    exactly), which remains the fallback for candidates the classification does not settle.
// 3. nfp_rings.cpp links the pieces into rings, slits and points; a box hierarchy over the piece
//    boxes serves the queries (nfp_query.cpp).
// Cost: candidates O(nm) turn tests (static floating filter, exact fallback; K kept, K ≤ nm,
// typically O(n + m) on real pieces); classification O(K log K + X) for X box-overlapping candidate
// pairs plus one point test (O(1) sums on real pieces, worst O(nm)) per part and per split point;
// worst case O(n²m²) exact tests (a candidate met by > 256 others is cut by the reference, O(nm)).
// Measured (callgrind, Release, per pair over every ordered pair of the nesting instances):
// albano 202 k instructions (classification 103 k, export 55 k, candidates 19 k, triangulations
// and hierarchies 14 k), shirts 238 k, trousers 91 k — the reference cutting with the rational
// export took 1.16 M on albano (docs/algorithms.md).
// Departure from the usual reduced-convolution builders (CGAL, Clipper):
// no arrangement of the candidates is built and no winding numbers are computed; membership in O
// is decided directly by the open convex pair sums, which also yields the slits and isolated
// points of degenerate fits (that the winding number of the convolution cannot tell apart).
#include <cmath>

#include "geometry/exact.hpp"
#include "nonconvex2/nfp_impl.hpp"

namespace pendepth {

namespace nonconvex2 {

namespace {

double lower(double x) { return x - std::abs(x) * 0x1p-44 - 0x1p-1000; }
double upper(double x) { return x + std::abs(x) * 0x1p-44 + 0x1p-1000; }

// Exact sign of cross(b − a, d − c) for input doubles (a static floating filter first).
int cross_sign(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) { return predicates::cross_edges(a, b, c, d); }

// prev[g]: the vertex before g in its ring.
std::vector<std::uint32_t> previous(const Polygon& S) {
  std::vector<std::uint32_t> prev(S.size());
  for (std::size_t g = 0; g < S.size(); ++g) prev[S.next(g)] = static_cast<std::uint32_t>(g);
  return prev;
}

NfpCandidate candidate(const Ray& E, const Line& line) {
  NfpCandidate c{E, line, {}, {}, {}, {}};
  // The ends, each a sum of two input doubles rounded once.
  c.A = line.c1 + line.c2;
  c.B = line.q_edge ? Vec2(line.c1 + line.e1) : Vec2(line.e1 + line.c2);
  c.lo = Vec2(lower(std::min(c.A.x(), c.B.x())), lower(std::min(c.A.y(), c.B.y())));
  c.hi = Vec2(upper(std::max(c.A.x(), c.B.x())), upper(std::max(c.A.y(), c.B.y())));
  return c;
}

}  // namespace

std::vector<NfpCandidate> nfp_candidates(const Polygon& P, const Polygon& Q) {
  const auto VP = P.vertices(), VQ = Q.vertices();
  const auto prevP = previous(P), prevQ = previous(Q);
  // Turn at each vertex: > 0 strictly convex, 0 straight, < 0 reflex.
  std::vector<signed char> convexP(P.size()), convexQ(Q.size());
  for (std::size_t g = 0; g < P.size(); ++g) convexP[g] = static_cast<signed char>(cross_sign(VP[prevP[g]], VP[g], VP[g], VP[P.next(g)]));
  for (std::size_t g = 0; g < Q.size(); ++g) convexQ[g] = static_cast<signed char>(cross_sign(VQ[prevQ[g]], VQ[g], VQ[g], VQ[Q.next(g)]));
  std::vector<NfpCandidate> cand;
  for (std::uint32_t g = 0; g < P.size(); ++g) {
    const auto g1 = static_cast<std::uint32_t>(P.next(g));
    for (std::uint32_t q = 0; q < Q.size(); ++q) {
      if (convexQ[q] < 0) continue;
      // Q's edges at q on the closed right (outer) side of e: cross(e, w) ≤ 0.
      if (cross_sign(VP[g], VP[g1], VQ[q], VQ[prevQ[q]]) > 0 || cross_sign(VP[g], VP[g1], VQ[q], VQ[Q.next(q)]) > 0) continue;
      Ray E;
      E.o1 = VP[g];
      E.o2 = -VQ[q];
      E.a1 = VP[g1];
      E.b1 = VP[g];
      E.sym = true;
      E.p0 = g, E.q0 = q, E.p1 = g1, E.q1 = q;
      Line c;
      c.c1 = VP[g], c.c2 = -VQ[q], c.e0 = VP[g], c.e1 = VP[g1];
      c.p0 = g, c.p1 = g1, c.q0 = c.q1 = q, c.q_edge = false;
      cand.push_back(candidate(E, c));
      cand.back().strict = convexQ[q] > 0;
    }
  }
  for (std::uint32_t h = 0; h < Q.size(); ++h) {
    const auto h1 = static_cast<std::uint32_t>(Q.next(h));
    for (std::uint32_t p = 0; p < P.size(); ++p) {
      if (convexP[p] < 0) continue;
      // P's edges at p on the closed outer side of Q's edge h: cross(q1 − q0, w) ≤ 0.
      if (cross_sign(VQ[h], VQ[h1], VP[p], VP[prevP[p]]) > 0 || cross_sign(VQ[h], VQ[h1], VP[p], VP[P.next(p)]) > 0) continue;
      Ray E;
      E.o1 = VP[p];
      E.o2 = -VQ[h];
      E.a1 = -VQ[h1];
      E.b1 = -VQ[h];
      E.sym = true;
      E.p0 = p, E.q0 = h, E.p1 = p, E.q1 = h1;
      Line c;
      c.c1 = VP[p], c.c2 = -VQ[h], c.e0 = -VQ[h], c.e1 = -VQ[h1];
      c.p0 = c.p1 = p, c.q0 = h, c.q1 = h1, c.q_edge = true;
      cand.push_back(candidate(E, c));
      cand.back().strict = convexP[p] > 0;
    }
  }
  return cand;
}

}  // namespace nonconvex2

NoFitPolygon2::Impl::Impl(const Polygon& P, const Polygon& Q) : S(P, Q) {
  // Step 1: candidates.
  const std::vector<nonconvex2::NfpCandidate> cand = nonconvex2::nfp_candidates(P, Q);
  sz.candidates = cand.size();
  // Step 2: their uncovered closed pieces.
  nonconvex2::nfp_classify(S, cand, pieces);
  sz.pieces = pieces.size();
  // Step 3: the query index over the piece boxes (BoxTree only reads a leaf's box).
  std::vector<nonconvex2::Tri> boxes(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    boxes[k].lo = pieces[k].blo;
    boxes[k].hi = pieces[k].bhi;
  }
  tree.build(boxes);
  nfp_export(*this);
}

NoFitPolygon2::NoFitPolygon2(const Polygon& P, const Polygon& Q) : impl_(std::make_unique<Impl>(P, Q)) {}
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
  s.bytes = b;
  return s;
}

}  // namespace pendepth
