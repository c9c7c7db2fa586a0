// The per-pair no-fit polygon, classification of the candidates (issue 5 item 4; nfp_build.cpp
// step 2): which parts of each reduced-convolution candidate lie on ∂O.
//
// Every point of a candidate c is in cl(O) (a touching placement), so it is in O or on ∂O. Where
// ∂O ∩ c begins or ends inside c, or is an isolated point of c, the placement has a contact that
// does not slide along c's line, and every touching contact lies on a candidate (nfp_build.cpp),
// so another candidate d meets c there: crossing or touching c's line, or collinear with an end
// there. Hence c, split at every point where another candidate meets it, consists of open parts
// that lie wholly in O or wholly on ∂O, and one exact point per part decides it.
//  0. Large shapes whose candidates are crowded (at least half of a sample have 16 or more
//     box-overlapping neighbours: a dense star against a small Q, where box-overlapping pairs grow
//     as n², issue 19 item 4): trim_deep walks each crowded candidate from each end inward, one
//     convex pair sum of pieces at a time (a sum surely holding the probe point, found nearest
//     first in the pieces' box trees, clipped to the farthest parameter whose point it also surely
//     holds: floating filters with static error bounds, never a wrong "in O"), and drops the
//     certified prefix and suffix from the candidate's box; a candidate certified whole gives no
//     piece and meets nothing. Split points not in O lie on both candidates' remaining parts, so
//     step 1 still finds them; the ones in O it may miss change no part's class (the parts next to
//     a point of the open set O are in O), hence no piece.
//  1. Split points: for each pair of candidates with overlapping boxes, non-parallel: the
//     crossing of their lines when it lies on both closed segments (4 exact comparisons);
//     collinear: the ends of each strictly inside the other (the end as the crossing with a line of
//     an input edge at that sum vertex, not parallel to c, so every parameter stays symbolic).
//  2. Per candidate, the split parameters sorted exactly (compare_params) and merged when equal.
//  3. Each open part: a double μ midway between its ends' approximations, certified strictly
//     inside (by the ends' error bounds, else two exact comparisons), and the point c(μ) tested
//     against the open sums whose boxes contain it (exact signs of degree 3): for small shapes the
//     sums of convex parts A ⊕ (−B) (convex_parts.hpp: Hertel–Mehlhorn on the triangulations; O
//     is also the union of the open sums of the parts, as both are {t : int P ∩ int(Q + t) ≠ ∅}),
//     fewer sums than triangle pairs, and far fewer with the point on their boundary (counts:
//     docs/benchmarks.md); for large shapes (more than 256 part pairs) the sums of pieces — the
//     parts without their straight vertices, split by diagonals when they have more than 12
//     corners — by a dual descent of the pieces' box trees (make_pieces: a triangulation fans long
//     straight runs from far vertices, and those thin triangles' boxes made the triangle pairs'
//     descent meet O(n) sums per point on combs); the descent also prunes a node pair by the
//     nodes' extents along the two diagonals (an 8-DOP with the boxes, PieceDop: a separating
//     diagonal with a margin above the roundings), as a star's thin radial pieces at diagonal
//     angles have boxes as long as the spike holding O(n) points of ∂O each. No test
//     is needed for a part next to a crossing where c enters the left of a strict candidate d
//     inside both: d is an edge of an open pair sum lying on d's left (nfp_build.cpp step 1), so
//     c's points just past the crossing, hence the whole part, are in O. Each split point not
//     closing a boundary part is tested itself (an exact fit: an isolated point of ∂O).
//     Split points that are sum vertices (the ends of c, a crossing at an end of the other
//     candidate, a collinear neighbour's end) carry the vertex as a key: equal keys are equal
//     points without arithmetic, and each vertex's membership in O is known once per pair. O is
//     open and ∂O closed, so a part next to a vertex known in O is in O (no test), and the ends of
//     a part found on ∂O are on ∂O (recorded for the other candidates through them).
//  4. Maximal runs of boundary parts and points are the pieces: the same closed maximal uncovered
//     intervals as the reference cutting nfp_cut.cpp, which is used instead for a candidate whose
//     parts cannot be sampled (a part too short for a double between its ends). A collinear
//     neighbour's end whose four input edges are all parallel to c (straight vertices of both
//     shapes: rectilinear pieces) is split by a line through that sum vertex across c
//     (cross_line_through).
// Filters that keep the exact arithmetic rare (each sound on its own; the exact test follows when
// one cannot decide): neighbours along the convolution sharing an end vertex meet only there;
// segment pairs apart by a floating margin; splits ordered by certified approximations; at a
// point, a sum with c's own line as an edge (by vertex ids, strictly convex vertices only) is
// skipped; a floating separating-axis test on the sum's half-planes (one per edge of the two parts,
// cached per part pair when there are ≤ 256 pairs, which are then scanned flat, and per piece pair
// met on large shapes); the sum that last surely held a point tried first; an edge parallel
// to c is decided by degree-2 signs (the point's parameter drops out). A flat point test runs the
// floating filters over all its sums first and stops at one that surely holds the point; the
// exact signs (parallel edges, then degree 3) only follow for the undecided sums when none does —
// most of those have the point on their boundary, as candidates are edges of sums. The pieces'
// rounded ends come from the split values when their error bounds certify 8 ulps.
// Two convex shapes: every candidate at a strictly convex vertex is a whole edge of the convex
// sum and is kept whole without a test, and so is one at a straight vertex whose shape lies on
// the candidate's outer side (two exact comparisons of input coordinates); the other straight
// candidates lie wholly in O, ends included (nfp_classify below), and give no piece.
// Cost: candidate pairs by boxes (all pairs for K ≤ 64, else a sort of the boxes on x and a sweep,
// or a box hierarchy when the sweep's x-overlap tests pass 32 per candidate; after step 0 only the
// boxes of the uncertified parts; met in canonical order, i then j, whichever search found them),
// O(1) exact tests per meeting pair; step 0 at most 8 probes per
// end of a crowded candidate, each a descent reaching at most 128 piece pairs; per part or point
// the pair sums whose boxes hold the point, O(1) tests each. For
// X box-overlapping pairs: O(K log K + X + (K + X)·v), v sums per point (worst O(nm)); a
// candidate met by more than kMaxSplits others is cut by the reference instead.
// Redundant candidates (nfp_build.cpp step 1) split the others where they end on a collinear
// candidate (crossings of a redundant candidate are crossings of the kept ones on its line) and
// are not classified. Exact ties of integer-like data (parallel and collinear candidates, a
// crossing exactly at a candidate's end) are decided by exact differences and products first.
// Measured costs: docs/benchmarks.md.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "geometry/exact.hpp"
#include "nonconvex2/convex_parts.hpp"
#include "nonconvex2/shape_side.hpp"
#include "nonconvex2/strip_pieces.hpp"
#include "nonconvex2/nfp_impl.hpp"

namespace pendepth::nonconvex2 {

namespace {

const Param kZero{Param::Zero, {}, 0}, kOne{Param::One, {}, 0};
constexpr std::uint32_t kMaxSplits = 256;
const Vec2 kO(0, 0);

// A split parameter on a candidate, its value v and a bound on |v − μ|.
// `key`: when the split point is known to be a sum vertex (P vertex p, Q vertex q), (p << 32) | q,
// else kNoKey. Equal keys are the same point (symbolic tie, no arithmetic), and the vertex's
// coverage is looked up once per pair.
constexpr std::uint64_t kNoKey = ~std::uint64_t(0);
std::uint64_t vertex_key(std::uint32_t p, std::uint32_t q) { return (std::uint64_t(p) << 32) | q; }

// `in_o`: kBefore / kAfter when the part of the candidate just before / after the split point is
// known to lie in O (a transversal crossing into the open side of another candidate's sum).
constexpr std::uint8_t kBefore = 1, kAfter = 2;
struct Split {
  Param p;
  double v, err;
  std::uint64_t key = kNoKey;
  std::uint8_t in_o = 0;
};

Split split(const Param& p, const Ray& E) {
  if (p.kind != Param::Cut) return {p, p.kind == Param::Zero ? 0.0 : p.kind == Param::One ? 1.0 : p.value, 0};
  // One floating pass with forward error bounds: |n/d − ñ/d̃| ≤ (bn + |v|·bd) / (|d̃| − bd).
  const exact::LiftFl F;
  const exact::Fl n = line_num(p.line, E, F), d = line_den(p.line, E, F);
  const double bn = exact::safe_bound(n.e), bd = exact::safe_bound(d.e);
  if (std::abs(d.v) > 2 * bd && std::isfinite(n.v)) {
    const double v = n.v / d.v;
    return {p, v, exact::safe_bound((bn + std::abs(v) * bd) / (std::abs(d.v) - bd) + std::abs(v) * 0x1p-52)};
  }
  const double v = line_value(p.line, E);  // to a few ulps
  return {p, v, std::abs(v) * 0x1p-48};
}

bool boxes_meet(const NfpCandidate& a, const NfpCandidate& b) {
  return !(a.lo.x() > b.hi.x() || b.lo.x() > a.hi.x() || a.lo.y() > b.hi.y() || b.lo.y() > a.hi.y());
}

// Exact sign of cross(dir a, dir b); candidates' directions are a1 − b1 (a2 = b2 = 0), input
// differences, so the static-filter predicate applies.
// A floating filter first (each direction a difference rounded once; 2⁻⁵⁰ of the products covers
// those and the roundings of the cross product, 2⁻¹⁰⁰⁰ underflow); then, for directions that are
// exact differences (integer-like data, where exactly parallel candidates are common), the sign
// of exact products (exact::sign_ab_minus_cd); else the exact predicate.
int parallel_sign(const Ray& a, const Ray& b) {
  const Vec2 da = a.a1 - a.b1, db = b.a1 - b.b1;
  const double p = da.x() * db.y(), q = da.y() * db.x(), cr = p - q;
  if (std::abs(cr) > (std::abs(p) + std::abs(q)) * 0x1p-50 + 0x1p-1000) return cr > 0 ? 1 : -1;
  const exact::LiftFlX X;
  const int s = exact::sign_ab_minus_cd(X(a.a1.x()) - X(a.b1.x()), X(b.a1.y()) - X(b.b1.y()), X(a.a1.y()) - X(a.b1.y()), X(b.a1.x()) - X(b.b1.x()));
  return s != 2 ? s : predicates::cross_edges(a.b1, a.a1, b.b1, b.a1);
}

// Exact: b's origin on a's line. Asked of parallel candidates, which are mostly collinear (an
// exact zero), so exact differences and products are tried before the general tiers.
bool origin_on_line(const Ray& a, const Ray& b) {
  auto cross = [&](auto L) {
    auto x = L(b.o1.x()) + L(b.o2.x()) - L(a.o1.x()) - L(a.o2.x());
    auto y = L(b.o1.y()) + L(b.o2.y()) - L(a.o1.y()) - L(a.o2.y());
    return std::array{ray_dx(a, L), y, ray_dy(a, L), x};
  };
  const auto t = cross(exact::LiftFlX{});
  const int s = exact::sign_ab_minus_cd(t[0], t[1], t[2], t[3]);
  if (s != 2) return s == 0;
  return exact::exact_sign([&](auto L) {
           const auto u = cross(L);
           return u[0] * u[1] - u[2] * u[3];
         }) == 0;
}

// Large shapes: a box-tree node's extents along the two diagonals (with the node's box, an
// 8-DOP), from the projections x ± y of its pieces' corners, each rounded once. A spike's thin
// radial piece at a diagonal angle has a box as long as the spike in both axes but a narrow extent
// across it along one diagonal, so the descent of covered_by_pieces / probe meets far fewer pair
// sums (issue 19 item 4, stars). Pruning only, certified (dop_misses). (A 16-DOP, with (2, ±1) and
// (1, ±2) too, measured no faster on the stars: the pruned descent is no longer the cost.)
constexpr int kDopDirs = 2;
constexpr std::array<std::array<double, 2>, kDopDirs> kDopDir{{{1, 1}, {1, -1}}};
struct PieceDop {
  std::array<double, kDopDirs> lo, hi;
};

// A candidate's box and index, as step 1's sweep reads them (contiguous, sorted on lo.x).
struct SweepBox {
  double lx, hx, ly, hy;
  std::uint32_t k;
};

struct PartPair {
  Vec2 lo, hi;
  std::uint32_t a, b;
  std::uint32_t off;  // its half-planes: edges of part a (against part b's vertices), then of b
  bool ready = false;
  double smax = 0;  // bounds every coordinate of both parts
};

// The classifier's scratch, reused by the thread's next pair (no allocation per pair on small
// pieces); released after a large pair (trim).
struct Buffers {
  std::vector<std::uint32_t> prevP, prevQ;
  PairDepth2::Impl::DescentStack stack;
  // Large shapes: the undecided piece pairs of a point test.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> undecided_pairs;
  std::vector<PartPair> flat;
  // Large shapes: the piece pairs met so far and their slots (Classifier::piece_pair).
  std::vector<PartPair> piece_pairs;
  std::vector<std::uint32_t> piece_slot;
  std::vector<double> hdx, hdy, hc, he;
  std::vector<signed char> vertex_table;
  std::unordered_map<std::uint64_t, signed char> vertex_map;
  std::vector<std::uint32_t> undecided, first, at;
  std::vector<std::pair<std::uint32_t, Split>> found;  // (candidate, split parameter)
  // Step 1: the candidates' boxes sorted on lo.x (sweep_pairs), the box-overlapping pairs i < j,
  // the same in canonical order, and per candidate its number of box-overlapping others.
  std::vector<SweepBox> sweep;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs, pairs_sorted;
  std::vector<std::uint32_t> degree;
  std::vector<char> reference, part, vert;
  std::vector<Split*> grouped, sp;
  // trim_deep: per candidate the box of its part not certified in O, and whether none is left.
  std::vector<Vec2> act_lo, act_hi;
  std::vector<char> dead;
  BoxTree cand_tree;
  // Large shapes: the pieces' box-tree nodes' extents along the diagonal directions (PieceDop).
  std::vector<PieceDop> dop_p, dop_b;
  void trim() {
    const std::size_t big = std::size_t(1) << 14;
    if (vertex_table.capacity() > big || found.capacity() > big || pairs.capacity() > big || sweep.capacity() > big || act_lo.capacity() > big || hdx.capacity() > big || !vertex_map.empty() ||
        cand_tree.nodes.capacity() > big || dop_p.capacity() > big || piece_slot.capacity() > big || piece_pairs.capacity() > big)
      *this = Buffers();
  }
};

Buffers& thread_buffers() {
  thread_local Buffers b;
  return b;
}

// Floating filter: the ends of y strictly on one side of x's line, by a margin above the
// roundings (A, B within 2⁻⁵³ relative of the exact ends; the direction exact differences
// rounded once), so the closed segments cannot meet.
inline bool apart(const NfpCandidate& x, const NfpCandidate& y) {
  const Vec2 dir = x.E.a1 - x.E.b1, u = y.A - x.A, w = y.B - x.A;
  const double S = std::max({x.A.cwiseAbs().maxCoeff(), y.A.cwiseAbs().maxCoeff(), y.B.cwiseAbs().maxCoeff()});
  const double err = (std::abs(dir.x()) + std::abs(dir.y())) * S * 0x1p-48;
  const double su = dir.x() * u.y() - dir.y() * u.x(), sw = dir.x() * w.y() - dir.y() * w.x();
  return (su > err && sw > err) || (su < -err && sw < -err);
}

// Candidates sharing an end vertex (neighbours along the convolution, most meeting pairs on
// real pieces): non-parallel lines meet only there, an end of both, which splits nothing.
inline bool shared_end(const Ray& a, const Ray& b) {
  return (a.p0 == b.p0 && a.q0 == b.q0) || (a.p0 == b.p1 && a.q0 == b.q1) || (a.p1 == b.p0 && a.q1 == b.q0) ||
         (a.p1 == b.p1 && a.q1 == b.q1);
}

// Where the crossing sx (at parameter p, the cut by another candidate's line) lies on the closed
// segment of E: -1 off it, 0 / 1 at that end, 2 strictly inside; certified by the error bounds
// when clear, else exactly (symbolic ends included).
inline int crossing_where(const Split& sx, const Param& p, const Ray& E) {
  if (sx.v - sx.err > 0 && sx.v + sx.err < 1) return 2;
  if (sx.v + sx.err < 0 || sx.v - sx.err > 1) return -1;
  // μ = num / den against 0 and 1 (symbolic when the line passes through an end vertex):
  // the signs of num and num − den, times den's.
  if (const int k = known_lambda(p.line, E); k >= 0) return k;
  // Exact differences and products first (integer-like data: the crossing is often
  // exactly at an end), with num = x·ey − y·ex, den = dx·ey − dy·ex and
  // num − den = (x − dx)·ey − (y − dy)·ex; else the general tiers.
  const exact::LiftFlX X;
  const Line& l = p.line;
  const exact::FlX ex = X(l.e1.x()) - X(l.e0.x()), ey = X(l.e1.y()) - X(l.e0.y()), dx = ray_dx(E, X), dy = ray_dy(E, X);
  const exact::FlX x = X(l.c1.x()) + X(l.c2.x()) - X(E.o1.x()) - X(E.o2.x()), y = X(l.c1.y()) + X(l.c2.y()) - X(E.o1.y()) - X(E.o2.y());
  int den = exact::sign_ab_minus_cd(dx, ey, dy, ex);
  if (den == 2) den = exact::exact_sign([&](auto L) { return line_den(l, E, L); });
  int s0 = exact::sign_ab_minus_cd(x, ey, y, ex);
  if (s0 == 2) s0 = exact::exact_sign([&](auto L) { return line_num(l, E, L); });
  s0 *= den;
  if (s0 <= 0) return s0 == 0 ? 0 : -1;
  int s1 = exact::sign_ab_minus_cd(x - dx, ey, y - dy, ex);
  if (s1 == 2) s1 = exact::exact_sign([&](auto L) { return line_num(l, E, L) - line_den(l, E, L); });
  s1 *= den;
  return s1 < 0 ? 2 : s1 == 0 ? 1 : -1;
}

struct Classifier {
  const PairDepth2::Impl& S;
  const std::vector<NfpCandidate>& cands;
  Buffers& buf = thread_buffers();
  std::vector<std::uint32_t>&prevP = buf.prevP, &prevQ = buf.prevQ;  // filled on first use
  PairDepth2::Impl::DescentStack& stack = buf.stack;

  // Convex parts of P and of −Q (convex_parts.hpp; per shape and role, shared by every pair built
  // from the same sides: shape_side.hpp) and all their pairs with the sums' boxes, when
  // there are few (≤ 256): a point is then tested against the sums of parts (the same union O as
  // the sums of triangles), scanned flat; each pair's half-planes are computed on first use.
  const ConvexParts &pp = S.sp->parts(), &pb = S.sb->parts();
  std::vector<PartPair>& flat = buf.flat;
  std::vector<double>&hdx = buf.hdx, &hdy = buf.hdy, &hc = buf.hc, &he = buf.he;
  // The part holding each boundary edge g → next(g) of P (of −Q: −h → −next(h)); a boundary edge
  // lies in exactly one triangle, hence one part.
  // Large shapes (more than 256 part pairs): the pieces of P and −Q (make_pieces), the piece
  // holding each boundary edge instead, their box trees and coordinate bounds. All per shape and
  // role, shared (ShapeSide::edge_parts, ShapeSide::pieces).
  bool large = pp.size() * pb.size() > 256;
  const ShapeSide::Pieces &pieces_p = large ? S.sp->pieces() : no_pieces(), &pieces_b = large ? S.sb->pieces() : no_pieces();
  const std::vector<std::uint32_t>&edge_part_p = large ? pieces_p.edge_piece : S.sp->edge_parts(),
                                   &edge_part_q = large ? pieces_b.edge_piece : S.sb->edge_parts();
  const ConvexParts &rp = pieces_p.r, &rb = pieces_b.r;
  const BoxTree &tree_p = pieces_p.tree, &tree_b = pieces_b.tree;
  const std::vector<double>&smax_p = pieces_p.smax, &smax_b = pieces_b.smax;
  static const ShapeSide::Pieces& no_pieces() {
    static const ShapeSide::Pieces none;
    return none;
  }
  // Large shapes: per node of tree_p / tree_b its extents along kDopDir (PieceDop); dop_scale:
  // the largest |coordinate| of P's pieces plus that of −Q's.
  const int dop_mode = nfp_dop_mode();
  const bool dop_on = large && dop_mode != kDopOff;
  std::vector<PieceDop>&dop_p = buf.dop_p, &dop_b = buf.dop_b;
  double dop_scale = 0;
  std::size_t dop_pruned = 0;  // added to nfp_trim_stats() by run()
  // The nodes' extents bottom-up (an explicit post-order; one-item leaves: `tri` is the piece).
  static void node_dops(const BoxTree& T, const ConvexParts& X, std::vector<PieceDop>& D) {
    D.resize(T.nodes.size());
    if (T.nodes.empty()) return;
    std::vector<std::int32_t> order, st{0};
    order.reserve(T.nodes.size());
    while (!st.empty()) {
      const std::int32_t n = st.back();
      st.pop_back();
      order.push_back(n);
      if (T.nodes[n].left >= 0) st.push_back(T.nodes[n].left), st.push_back(T.nodes[n].right);
    }
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
      const auto& N = T.nodes[*it];
      PieceDop& d = D[*it];
      if (N.left >= 0) {
        const PieceDop &l = D[N.left], &r = D[N.right];
        for (int j = 0; j < kDopDirs; ++j) d.lo[j] = std::min(l.lo[j], r.lo[j]), d.hi[j] = std::max(l.hi[j], r.hi[j]);
        continue;
      }
      d.lo.fill(INFINITY), d.hi.fill(-INFINITY);
      for (std::uint32_t i = X.start[N.tri]; i < X.start[N.tri + 1]; ++i)
        for (int j = 0; j < kDopDirs; ++j) {
          const double v = kDopDir[j][0] * X.v[i].x() + kDopDir[j][1] * X.v[i].y();
          d.lo[j] = std::min(d.lo[j], v), d.hi[j] = std::max(d.hi[j], v);
        }
    }
  }
  // Certified: the exact point M (|M − m| ≤ tol per coordinate, mmax = max |m|) lies outside the
  // closed sum of every pair of pieces under nodes A (of P) and B (of −Q), by a separating
  // direction u = (a, b) of kDopDir: u·M > h_A(u) + h_B(u) (or below the minima) by more than
  // the roundings. Bounds (w = |a| + |b| = 2, u₅₃ = 2⁻⁵³, G = dop_scale ≥ max coordinate of A's
  // corners + max of B's): each stored projection is within u₅₃·w·G of the exact one (a·x exact,
  // one rounded sum), their sum adds u₅₃·w·G·(1 + u₅₃); u·m (one rounded sum) is within u₅₃·w·mmax
  // of the exact u·m, and |u·M − u·m| ≤ w·tol; the subtraction of the margin rounds once more.
  // Margin w·(tol + (G + mmax)·2⁻⁴⁹): four times the sum of those. Never drops a sum that holds
  // M, as a box test never does; kDopPlanted (tests only) shrinks each extent by 1/64 of its width
  // instead, a wrong pruning the tests must catch.
  bool dop_misses(const PieceDop& A, const PieceDop& B, const Vec2& m, double mmax, double tol) const {
    const double g = (dop_scale + mmax) * 0x1p-49;
    for (int j = 0; j < kDopDirs; ++j) {
      const double a = kDopDir[j][0], b = kDopDir[j][1], w = std::abs(a) + std::abs(b);
      const double s = a * m.x() + b * m.y(), lo = A.lo[j] + B.lo[j], hi = A.hi[j] + B.hi[j];
      const double margin = dop_mode == kDopPlanted ? -(hi - lo) / 64 : w * (tol + g);
      if (s - margin > hi || s + margin < lo) return true;
    }
    return false;
  }
  // The coverage of sum vertices (vertex_state): a table over all (P, Q) vertex pairs when small.
  std::size_t qn = S.Q.size();
  bool small_table = std::uint64_t(S.P.size()) * S.Q.size() <= (std::uint64_t(1) << 20);

  Classifier(const PairDepth2::Impl& s, const std::vector<NfpCandidate>& c) : S(s), cands(c) {
    prevP.clear(), prevQ.clear(), flat.clear(), vertex_map.clear();
    if (small_table) vertex_table.assign(S.P.size() * qn, -1);
    if (large) {  // large shapes: the pieces and their dual descent, with the nodes' k-DOPs
      hdx.clear(), hdy.clear(), hc.clear(), he.clear(), buf.piece_pairs.clear();
      if (piece_cache) buf.piece_slot.assign(rp.size() * rb.size(), 0);
      if (dop_on) {
        node_dops(tree_p, rp, buf.dop_p), node_dops(tree_b, rb, buf.dop_b);
        for (const double x : smax_p) dop_scale = std::max(dop_scale, x);
        double sb = 0;
        for (const double x : smax_b) sb = std::max(sb, x);
        dop_scale += sb;
      }
      return;
    }
    flat.reserve(pp.size() * pb.size());
    std::uint32_t off = 0;
    for (std::uint32_t a = 0; a < pp.size(); ++a)
      for (std::uint32_t b = 0; b < pb.size(); ++b) {
        PartPair f{{}, {}, a, b, off};
        sum_box(pp.lo[a], pp.hi[a], pb.lo[b], pb.hi[b], f.lo, f.hi);
        flat.push_back(f);
        off += (pp.start[a + 1] - pp.start[a]) + (pb.start[b + 1] - pb.start[b]);
      }
    hdx.resize(off), hdy.resize(off), hc.resize(off), he.resize(off);
  }

  // Large shapes: the pieces of one shape (P's, or −Q's) from its convex parts X. A part's
  // straight vertices are dropped (the same convex set; its sums with any piece are the same
  // sets, and the filters and exact tests below run over its corners only), and a part with more
  // than kMaxCorners corners is split by diagonals between its corners, halving, into convex
  // pieces of at most that many (strictly convex, non-degenerate: corners in convex position).
  // Why: a triangulation must fan a long straight run of vertices (the comb's base between its
  // teeth) from a few far vertices, so thin triangles spanning the shape have boxes holding
  // O(n) placements each and a point test met O(n) triangle pairs (quadratic builds, issue 19
  // item 4); the part holding the fan is one piece of 4 corners. O is the union of the open sums
  // of any decomposition into non-degenerate convex pieces ({t : int P ∩ int(Q + t) ≠ ∅}), and
  // every decision is exact, so the answers are the same as with triangles.
  // edge_piece[g]: the piece holding boundary edge g → next(g) (on one of its corner edges);
  // smax[k] bounds piece k's coordinates. O(parts' size) plus O(log) per split. ShapeSide::pieces
  // first re-covers the fans of a long edge with Steiner pieces (strip_pieces.hpp: a rotated comb);
  // their Steiner vertices carry id kSteiner and hold no boundary edge.
  static constexpr std::size_t kMaxCorners = 12;
  static void make_pieces(const ConvexParts& X, const Polygon& shape, ConvexParts& out, std::vector<std::uint32_t>& edge_piece,
                          std::vector<double>& smax) {
    out.v.clear(), out.id.clear(), out.start.clear(), out.lo.clear(), out.hi.clear(), smax.clear();
    edge_piece.assign(shape.size(), ~std::uint32_t(0));
    std::vector<std::uint32_t> corner, at, corner_piece;  // corner positions; per position its corner edge
    std::vector<std::vector<std::uint32_t>> todo;
    for (std::uint32_t k = 0; k < X.size(); ++k) {
      const std::uint32_t s = X.start[k], n = X.start[k + 1] - s;
      corner.clear();
      for (std::uint32_t i = 0; i < n; ++i)
        if (predicates::orient2d(X.v[s + (i + n - 1) % n], X.v[s + i], X.v[s + (i + 1) % n]) != 0) corner.push_back(i);
      const auto kc = static_cast<std::uint32_t>(corner.size());
      // at[i]: the corner edge (index of its first corner) holding the part's edge i → i + 1.
      at.assign(n, kc - 1);
      for (std::uint32_t c = 0; c < kc; ++c)
        for (std::uint32_t i = corner[c]; i < (c + 1 < kc ? corner[c + 1] : n); ++i) at[i] = c;
      corner_piece.assign(kc, 0);
      std::vector<std::uint32_t> all(kc);
      for (std::uint32_t c = 0; c < kc; ++c) all[c] = c;
      todo.assign(1, std::move(all));
      while (!todo.empty()) {
        std::vector<std::uint32_t> L = std::move(todo.back());
        todo.pop_back();
        if (L.size() > kMaxCorners) {
          const std::size_t h = L.size() / 2;
          std::vector<std::uint32_t> R(L.begin() + h, L.end());
          R.push_back(L[0]);
          L.resize(h + 1);
          todo.push_back(std::move(L));
          todo.push_back(std::move(R));
          continue;
        }
        const auto piece = static_cast<std::uint32_t>(out.lo.size());
        out.start.push_back(static_cast<std::uint32_t>(out.v.size()));
        Vec2 lo = X.v[s + corner[L[0]]], hi = lo;
        double m = 0;
        for (std::size_t t = 0; t < L.size(); ++t) {
          const Vec2& x = X.v[s + corner[L[t]]];
          out.v.push_back(x);
          out.id.push_back(X.id[s + corner[L[t]]]);
          lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
          m = std::max(m, x.cwiseAbs().maxCoeff());
          if (L[(t + 1) % L.size()] == (L[t] + 1) % kc) corner_piece[L[t]] = piece;  // a corner edge of the part
        }
        out.lo.push_back(lo), out.hi.push_back(hi), smax.push_back(m);
      }
      for (std::uint32_t i = 0; i < n; ++i)
        if (X.id[s + i] != kSteiner && shape.next(X.id[s + i]) == X.id[s + (i + 1) % n]) edge_piece[X.id[s + i]] = corner_piece[at[i]];
    }
    out.start.push_back(static_cast<std::uint32_t>(out.v.size()));
  }

  // m = c(p) in the open sum of pieces a (of P) and b (of −Q): in_part_sum's tests, the
  // half-planes computed on the fly (the same floating values as prepare()'s).
  int in_piece_sum(std::uint32_t a, std::uint32_t b, const NfpCandidate& c, const Param& p, const Vec2& m, double tol, bool exact,
                   int den) const {
    const double S = std::max({smax_p[a], smax_b[b], m.cwiseAbs().maxCoeff()});
    const double slack = 2 * (tol + 16 * S * 0x1p-53);
    bool sure = true;
    const bool inside = each_sum_edge(a, b, [&](const Vec2& x0, const Vec2& x1, const Vec2& d, double hc, const ConvexParts& Y,
                                                std::uint32_t ky) {
      const double val = d.x() * m.y() - d.y() * m.x() - hc, err = (std::abs(d.x()) + std::abs(d.y())) * slack;
      if (val < -err) return false;
      if (val > err) return true;
      if (!exact) {
        sure = false;
        return true;
      }
      return edge_holds(x0, x1, Y, ky, c, p, m, slack, den);
    });
    if (!inside) return -1;
    return sure ? 1 : 0;
  }
  // Each edge x0 → x1 of piece a of P (side 0), then of piece b of −Q (side 1), as a supporting
  // line of the pieces' sum: d = x1 − x0 and the offset hc = cross(d, x0) + min over the other
  // piece's vertices y of cross(d, y) (in exact arithmetic m is strictly inside the sum iff
  // cross(d, m) − hc > 0 for every edge), in floating point; f(x0, x1, d, hc, other piece's parts,
  // its index) returns false to stop. Returns false when f stopped.
  template <class F>
  bool each_sum_edge(std::uint32_t a, std::uint32_t b, F&& f) const {
    for (int side = 0; side < 2; ++side) {
      const ConvexParts& X = side == 0 ? rp : rb;
      const ConvexParts& Y = side == 0 ? rb : rp;
      const std::uint32_t kx = side == 0 ? a : b, ky = side == 0 ? b : a;
      const std::uint32_t x0i = X.start[kx], xn = X.start[kx + 1] - x0i;
      for (std::uint32_t i = 0; i < xn; ++i) {
        const Vec2& x0 = X.v[x0i + i];
        const Vec2& x1 = X.v[x0i + (i + 1) % xn];
        const Vec2 d = x1 - x0;
        double lo = INFINITY;
        for (std::uint32_t j = Y.start[ky]; j < Y.start[ky + 1]; ++j) lo = std::min(lo, d.x() * Y.v[j].y() - d.y() * Y.v[j].x());
        if (!f(x0, x1, d, d.x() * x0.y() - d.y() * x0.x() + lo, Y, ky)) return false;
      }
    }
    return true;
  }
  // Symbolic: c's line is an edge line of the pieces' sum (own_edge_part; c strict, so its
  // convex vertex is a corner of every piece holding it).
  bool own_edge_piece(std::uint32_t a, std::uint32_t b, const Ray& E) const {
    auto has_vertex = [](const ConvexParts& X, std::uint32_t k, std::uint32_t v) {
      for (std::uint32_t i = X.start[k]; i < X.start[k + 1]; ++i)
        if (X.id[i] == v) return true;
      return false;
    };
    if (E.q0 == E.q1) return a == edge_part_p[E.p0] && has_vertex(rb, b, E.q0);
    return b == edge_part_q[E.q0] && has_vertex(rp, a, E.p0);
  }
  // Large shapes: the dual descent of the pieces' box trees over the piece pairs whose sum box
  // meets [mlo, mhi]; `Nearer`: the child pair whose sum box's centre is nearer m first (trim_deep's
  // probes: deep points of dense shapes, e.g. a star's spikes, are then surely held by the first
  // sums reached rather than after O(n) far ones). leaf(a, b) returns true to stop.
  // Node pairs are also pruned by their k-DOPs (dop_misses; m within tol of the exact point).
  template <bool Nearer, class Leaf>
  void descend_pieces(const Vec2& m, double tol, const Vec2& mlo, const Vec2& mhi, Leaf&& leaf) {
    const double mmax = m.cwiseAbs().maxCoeff();
    stack.assign(1, {0, 0});
    while (!stack.empty()) {
      const auto [a, b] = stack.back();
      stack.pop_back();
      const auto &A = tree_p.nodes[a], &B = tree_b.nodes[b];
      // sum_box's test (pair_sums.cpp), inlined: the descent's innermost step.
      using geometry::widen_down, geometry::widen_up;
      if (widen_down(A.lo.x() + B.lo.x()) > mhi.x() || widen_up(A.hi.x() + B.hi.x()) < mlo.x() || widen_down(A.lo.y() + B.lo.y()) > mhi.y() ||
          widen_up(A.hi.y() + B.hi.y()) < mlo.y())
        continue;
      if (dop_on && dop_misses(dop_p[a], dop_b[b], m, mmax, tol)) {
        ++dop_pruned;
        continue;
      }
      const bool la = A.left < 0, lb = B.left < 0;
      if (la && lb) {
        if (leaf(A.tri, B.tri)) return;
        continue;
      }
      auto push = [&](std::int32_t a0, std::int32_t b0, std::int32_t a1, std::int32_t b1) {
        auto dist = [&](std::int32_t x, std::int32_t y) {
          const auto &X = tree_p.nodes[x], &Y = tree_b.nodes[y];
          return (0.5 * (X.lo + X.hi + Y.lo + Y.hi) - m).squaredNorm();
        };
        if (Nearer && dist(a0, b0) < dist(a1, b1)) std::swap(a0, a1), std::swap(b0, b1);
        stack.push_back({a0, b0});
        stack.push_back({a1, b1});
      };
      if (lb || (!la && (A.hi - A.lo).sum() >= (B.hi - B.lo).sum())) push(A.left, b, A.right, b);
      else push(a, B.left, a, B.right);
    }
  }

  // Large shapes: m (within [mlo, mhi]) in O; the floating filters first over every piece pair
  // whose sum box holds m (stopping at one that surely holds it), then the exact test of the
  // undecided pairs.
  template <class DenSign>
  bool covered_by_pieces(const NfpCandidate& c, const Param& p, const Vec2& m, double tol, const Vec2& mlo, const Vec2& mhi,
                         DenSign&& den_sign) {
    auto& undecided = buf.undecided_pairs;
    undecided.clear();
    bool sure = false;
    auto filter = [&](std::uint32_t a, std::uint32_t b) {
      if (c.strict && own_edge_piece(a, b, c.E)) return false;
      const int r = piece_sum(a, b, c, p, m, tol, false, 0);
      if (r == 0) undecided.push_back({a, b});
      if (r > 0) hint_a = a, hint_b = b;
      return sure = r > 0;
    };
    // The hint first (the descent then skips it: each pair sum is filtered once).
    const std::uint32_t ha = hint_a, hb = hint_b;
    if (ha != kNoHint && filter(ha, hb)) return true;
    descend_pieces<false>(m, tol, mlo, mhi, [&](std::uint32_t a, std::uint32_t b) { return !(a == ha && b == hb) && filter(a, b); });
    if (sure) return true;
    for (const auto& [a, b] : undecided)
      if (piece_sum(a, b, c, p, m, tol, true, den_sign()) > 0) return true;
    return false;
  }

  // ---- Step 0 (large shapes, trim_deep): the parts of the candidates certified in O ----
  // Dense shapes (a star's spikes against a small Q) have candidates met by O(n) others, nearly
  // all of it deep in O: box-overlapping pairs and split points grow as n². Walking from each end
  // of a candidate inward, one convex pair sum at a time, certifies a prefix [0, a] and a suffix
  // [b, 1] in O (floating filters with static error bounds only, never a wrong "in O"); step 1
  // then pairs only the boxes of the rest [a, b], and a candidate certified whole gives no piece.
  bool trimmed = false, have_tree = false;  // have_tree: buf.cand_tree holds the candidates' boxes
  // swept: buf.pairs holds every box-overlapping pair of the candidates' (untrimmed) boxes
  // (sweep_pairs, tried once: sweep_tried).
  bool sweep_tried = false, swept = false;
  static constexpr std::size_t kSweepTests = 32;  // the sweep's budget: x-overlap tests per candidate
  static constexpr double kSweepSkip = 1.5;  // the sweep skipped past kSweepSkip times its budget, estimated
  static constexpr int kTrimRounds = 8;      // sums chained per end
  static constexpr int kProbeLeaves = 128;   // piece pairs visited per probe
  static constexpr int kProbeSure = 4;       // sums surely holding the probe point tried per probe
  static constexpr std::size_t kCrowded = 16;  // box-overlapping candidates that make one worth trimming

  // c(μ) for a double μ, to within tol (covered_point's bound for an exact parameter).
  static Vec2 value_point(const NfpCandidate& c, double mu, double& tol) {
    tol = (c.A.cwiseAbs().maxCoeff() + c.B.cwiseAbs().maxCoeff()) * 0x1p-40 + 0x1p-1000;
    return c.A + mu * (c.B - c.A);
  }
  // c(cur) surely in the open sum of pieces a, b: the farthest μ' from cur toward `to` (inclusive)
  // found with c(μ') surely in that sum too, so every point of c between them is (a convex set);
  // cur when none. The half-planes' floating values, linear in μ, give the candidate μ'; the
  // point filter in_piece_sum certifies it (halving the step up to three times).
  double sum_reach(std::uint32_t a, std::uint32_t b, const NfpCandidate& c, double cur, double to) const {
    double tol;
    const Vec2 m = value_point(c, cur, tol), D = c.B - c.A;
    const double dir = to > cur ? 1 : -1, span = std::abs(to - cur);
    const double S = std::max({smax_p[a], smax_b[b], c.A.cwiseAbs().maxCoeff(), c.B.cwiseAbs().maxCoeff()});
    const double slack = 2 * (tol + 16 * S * 0x1p-53);
    double lim = span;
    each_sum_edge(a, b, [&](const Vec2&, const Vec2&, const Vec2& d, double hc, const ConvexParts&, std::uint32_t) {
      const double val = d.x() * m.y() - d.y() * m.x() - hc;
      const double rate = dir * (d.x() * D.y() - d.y() * D.x()), err = (std::abs(d.x()) + std::abs(d.y())) * slack;
      if (rate < 0) lim = std::min(lim, (val - 4 * err) / -rate);
      return true;
    });
    if (!(lim > 0)) return cur;
    for (int tries = 0; tries < 4; ++tries, lim *= 0.5) {
      const double t = tries == 0 && lim >= span ? to : cur + dir * std::min(lim, span) * 0.99;
      if (t == cur || !(std::abs(t - cur) <= span)) return cur;
      double tt;
      const Vec2 mt = value_point(c, t, tt);
      if (in_piece_sum(a, b, c, Param{Param::Value, {}, t}, mt, tt, false, 0) > 0) return t;
    }
    return cur;
  }
  // The farthest μ' toward `to` with c between cur and μ' certified in O through one of the pair
  // sums surely holding c(cur) (nearer first, a few); cur when none.
  double probe(const NfpCandidate& c, double cur, double to) {
    double tol;
    const Vec2 m = value_point(c, cur, tol);
    const Vec2 mlo = m.array() - tol, mhi = m.array() + tol;
    double best = cur;
    int leaves = 0, sure = 0;
    const Param p{Param::Value, {}, cur};
    descend_pieces<true>(m, tol, mlo, mhi, [&](std::uint32_t a, std::uint32_t b) {
      ++leaves;
      if (in_piece_sum(a, b, c, p, m, tol, false, 0) > 0) {
        ++sure;
        const double r = sum_reach(a, b, c, cur, to);
        if (std::abs(r - cur) > std::abs(best - cur)) best = r;
      }
      return best == to || sure >= kProbeSure || leaves >= kProbeLeaves;
    });
    return best;
  }
  // buf.dead, buf.act_lo / act_hi for every candidate (see above).
  void trim_deep() {
    const std::size_t K = cands.size();
    buf.act_lo.resize(K), buf.act_hi.resize(K);
    buf.dead.assign(K, 0);
    // Crowded candidates only: those whose box meets at least kCrowded others'. Elsewhere the
    // pairing is cheap and the probes would cost more than they save (combs, spirals). The counts
    // come from step 1's pairs when the sweep finds them all within its budget (no tree), else
    // from a counting pass over a box tree of all candidates, stopped there (the tree refitted to
    // the trimmed boxes by find_splits).
    BoxTree& tree = buf.cand_tree;
    if (sweep_pairs()) {
      auto& degree = buf.degree;
      degree.assign(K, 0);
      for (const auto& [i, j] : buf.pairs) ++degree[i], ++degree[j];
    } else {
      build_candidate_tree(tree);
      have_tree = true;
    }
    std::vector<std::int32_t> st;
    auto crowded = [&](std::size_t k) {
      if (swept) return buf.degree[k] >= kCrowded;
      const Vec2 &lo = cands[k].lo, &hi = cands[k].hi;
      std::size_t count = 0;
      st.assign(1, 0);
      while (!st.empty() && count < kCrowded) {
        const auto& N = tree.nodes[st.back()];
        st.pop_back();
        if (N.lo.x() > hi.x() || lo.x() > N.hi.x() || N.lo.y() > hi.y() || lo.y() > N.hi.y()) continue;
        if (N.left >= 0) st.push_back(N.left), st.push_back(N.right);
        else count += N.tri != k;
      }
      return count >= kCrowded;
    };
    // A sample first (every 32nd candidate): less than half crowded (combs: the teeth's candidates
    // meet their neighbours', most of them on ∂O), and the pairing is left as it is.
    std::size_t sampled = 0, crowded_sampled = 0;
    for (std::size_t k = 0; k < K; k += 32) ++sampled, crowded_sampled += crowded(k);
    const bool all = nfp_trim_mode() == kTrimAll;
    if (!all && 2 * crowded_sampled < sampled) {
      trimmed = false;
      return;
    }
    for (std::size_t k = 0; k < K; ++k) {
      const NfpCandidate& c = cands[k];
      buf.act_lo[k] = c.lo, buf.act_hi[k] = c.hi;
      if (!all && !crowded(k)) continue;
      auto walk = [&](double from, double to, bool& moved) {
        double cur = from;
        for (int r = 0; r < kTrimRounds && cur != to; ++r) {
          const double next = probe(c, cur, to);
          if (next == cur) break;
          cur = next, moved = true;
        }
        return cur;
      };
      bool ca = false, cb = false;
      const double a = walk(0.0, 1.0, ca);  // [0, a] in O when ca
      if (ca && a == 1) {
        buf.dead[k] = 1, ++nfp_trim_stats().dead;
        continue;
      }
      const double b = walk(1.0, ca ? a : 0.0, cb);  // [b, 1] in O when cb
      if (cb && b == (ca ? a : 0.0)) {
        buf.dead[k] = 1, ++nfp_trim_stats().dead;
        continue;
      }
      if (!ca && !cb) continue;
      ++nfp_trim_stats().trimmed;
      double ta, tb;
      const Vec2 ma = value_point(c, ca ? a : 0.0, ta), mb = value_point(c, cb ? b : 1.0, tb);
      const double t = std::max(ta, tb);
      auto lower = [&](double x) { return x - std::abs(x) * 0x1p-44 - t; };
      auto upper = [&](double x) { return x + std::abs(x) * 0x1p-44 + t; };
      buf.act_lo[k] = Vec2(std::max(c.lo.x(), lower(std::min(ma.x(), mb.x()))), std::max(c.lo.y(), lower(std::min(ma.y(), mb.y()))));
      buf.act_hi[k] = Vec2(std::min(c.hi.x(), upper(std::max(ma.x(), mb.x()))), std::min(c.hi.y(), upper(std::max(ma.y(), mb.y()))));
    }
  }

  // The convex sets whose pair sums the point tests use, of P (side 0) and of −Q (side 1): the
  // parts for few part pairs (flat), else the pieces (piece_pair).
  const ConvexParts& sums_of(int side) const { return side == 0 ? (large ? rp : pp) : (large ? rb : pb); }
  // Large shapes: piece pair (a, b) with its half-planes (prepare), made on first use and kept
  // for the pair's later point tests, as flat's part pairs are (box unused). The slot table
  // piece_slot[a·|pieces of −Q| + b] (1 + index in buf.piece_pairs, 0 none) exists when
  // piece_cache; without it in_piece_sum computes the half-planes per test, O(|a|·|b|).
  bool piece_cache = large && std::uint64_t(rp.size()) * rb.size() <= (std::uint64_t(1) << 18);
  PartPair& piece_pair(std::uint32_t a, std::uint32_t b) {
    std::uint32_t& slot = buf.piece_slot[std::size_t(a) * rb.size() + b];
    if (slot == 0) {
      PartPair f{{}, {}, a, b, static_cast<std::uint32_t>(hdx.size())};
      const std::size_t n = hdx.size() + (rp.start[a + 1] - rp.start[a]) + (rb.start[b + 1] - rb.start[b]);
      hdx.resize(n), hdy.resize(n), hc.resize(n), he.resize(n);
      prepare(f);
      buf.piece_pairs.push_back(f);
      slot = static_cast<std::uint32_t>(buf.piece_pairs.size());
    }
    return buf.piece_pairs[slot - 1];
  }
  // in_part_sum of piece pair (a, b): through its kept half-planes when piece_cache, else
  // in_piece_sum (the same floating values, the same answers).
  int piece_sum(std::uint32_t a, std::uint32_t b, const NfpCandidate& c, const Param& p, const Vec2& m, double tol, bool exact, int den) {
    return piece_cache ? in_part_sum(piece_pair(a, b), c, p, m, tol, exact, den) : in_piece_sum(a, b, c, p, m, tol, exact, den);
  }

  // Half-planes of A ⊕ B for convex A, B: for each edge d of one part from x0, m is inside iff
  // cross(d, m) > cross(d, x0) + min over the other part's vertices y of cross(d, y) (the sum's
  // edge parallel to d is d translated by the extreme y); A ⊕ B is their intersection.
  void prepare(PartPair& f) {
    f.smax = 0;
    for (int side = 0; side < 2; ++side) {
      const ConvexParts& X = sums_of(side);
      const std::uint32_t k = side == 0 ? f.a : f.b;
      for (std::uint32_t i = X.start[k]; i < X.start[k + 1]; ++i) f.smax = std::max(f.smax, X.v[i].cwiseAbs().maxCoeff());
    }
    std::uint32_t h = f.off;
    for (int side = 0; side < 2; ++side) {
      const ConvexParts &X = sums_of(side), &Y = sums_of(1 - side);
      const std::uint32_t kx = side == 0 ? f.a : f.b, ky = side == 0 ? f.b : f.a;
      const std::uint32_t x0i = X.start[kx], xn = X.start[kx + 1] - x0i;
      for (std::uint32_t i = 0; i < xn; ++i, ++h) {
        const Vec2& x0 = X.v[x0i + i];
        const Vec2 d = X.v[x0i + (i + 1) % xn] - x0;
        double lo = INFINITY;
        for (std::uint32_t j = Y.start[ky]; j < Y.start[ky + 1]; ++j) lo = std::min(lo, d.x() * Y.v[j].y() - d.y() * Y.v[j].x());
        hdx[h] = d.x(), hdy[h] = d.y(), hc[h] = d.x() * x0.y() - d.y() * x0.x() + lo;
        he[h] = std::abs(d.x()) + std::abs(d.y());
      }
    }
    f.ready = true;
  }

  // Exact: the edge x0 → x1 of one part holds the point m = c(p) strictly in its half-plane of
  // the sum, i.e. cross(d, m − x0 − y) > 0 for some vertex y of the other part Y (d = x1 − x0).
  // Floating per y first (the half-plane filter's bound); an edge parallel to c by degree-2 signs
  // (m's parameter drops out), any other by the degree-3 sign over the parameter's denominator.
  static bool edge_holds(const Vec2& x0, const Vec2& x1, const ConvexParts& Y, std::uint32_t ky, const NfpCandidate& c, const Param& p,
                         const Vec2& m, double slack, int den) {
    const Ray& E = c.E;
    const Vec2 d = x1 - x0, dirc = E.a1 - E.b1;
    const double err = (std::abs(d.x()) + std::abs(d.y())) * slack;
    const double base = d.x() * m.y() - d.y() * m.x() - (d.x() * x0.y() - d.y() * x0.x());
    const double cr = d.x() * dirc.y() - d.y() * dirc.x();
    bool parallel = std::abs(cr) <= (std::abs(d.x()) + std::abs(d.y())) * (std::abs(dirc.x()) + std::abs(dirc.y())) * 0x1p-50;
    if (parallel) {  // exact: exact differences and products first, else the predicate
      const exact::LiftFlX X;
      const int s = exact::sign_ab_minus_cd(X(x1.x()) - X(x0.x()), X(E.a1.y()) - X(E.b1.y()), X(x1.y()) - X(x0.y()), X(E.a1.x()) - X(E.b1.x()));
      parallel = (s != 2 ? s : predicates::cross_edges(x0, x1, E.b1, E.a1)) == 0;
    }
    for (std::uint32_t j = Y.start[ky]; j < Y.start[ky + 1]; ++j) {
      const Vec2& y = Y.v[j];
      const double val = base - (d.x() * y.y() - d.y() * y.x());
      if (val < -err) continue;
      if (val > err) return true;
      if (parallel) {
        if (exact::exact_sign_tie_likely([&](auto L) {
              auto u = L(E.o1.x()) + L(E.o2.x()) - L(x0.x()) - L(y.x()), v = L(E.o1.y()) + L(E.o2.y()) - L(x0.y()) - L(y.y());
              return (L(x1.x()) - L(x0.x())) * v - (L(x1.y()) - L(x0.y())) * u;
            }) > 0)
          return true;
        continue;
      }
      if (den * exact::exact_sign_tie_likely([&](auto L) {
            auto [n, dd] = param_nd(p, E, kO, L);
            auto x = (L(E.o1.x()) + L(E.o2.x()) - L(x0.x()) - L(y.x())) * dd + n * ray_dx(E, L);
            auto yy = (L(E.o1.y()) + L(E.o2.y()) - L(x0.y()) - L(y.y())) * dd + n * ray_dy(E, L);
            return (L(x1.x()) - L(x0.x())) * yy - (L(x1.y()) - L(x0.y())) * x;
          }) > 0)
        return true;
    }
    return false;
  }

  // m = c(p) (to within tol) in the open sum of part pair f: +1 / -1 certain by the floating
  // half-planes, 0 undecided; with `exact` the undecided half-planes are decided (edge_holds)
  // and the answer is exact (0 never returned).
  int in_part_sum(const PartPair& f, const NfpCandidate& c, const Param& p, const Vec2& m, double tol, bool exact, int den) const {
    const double S = std::max(f.smax, m.cwiseAbs().maxCoeff());
    const double slack = 2 * (tol + 16 * S * 0x1p-53);
    bool sure = true;
    std::uint32_t h = f.off;
    for (int side = 0; side < 2; ++side) {
      const ConvexParts& X = sums_of(side);
      const std::uint32_t kx = side == 0 ? f.a : f.b, ky = side == 0 ? f.b : f.a;
      const std::uint32_t x0i = X.start[kx], xn = X.start[kx + 1] - x0i;
      for (std::uint32_t i = 0; i < xn; ++i, ++h) {
        const double val = hdx[h] * m.y() - hdy[h] * m.x() - hc[h], err = he[h] * slack;
        if (val < -err) return -1;
        if (val > err) continue;
        if (!exact) {
          sure = false;
          continue;
        }
        const std::uint32_t i1 = x0i + (i + 1) % xn;
        if (!edge_holds(X.v[x0i + i], X.v[i1], sums_of(1 - side), ky, c, p, m, slack, den)) return -1;
      }
    }
    return sure ? 1 : 0;
  }
  // Symbolic: c's line is an edge line of A ⊕ B (own_edge below, for parts).
  bool own_edge_part(const PartPair& f, const Ray& E) const {
    auto has_vertex = [](const ConvexParts& X, std::uint32_t k, std::uint32_t a) {
      for (std::uint32_t i = X.start[k]; i < X.start[k + 1]; ++i)
        if (X.id[i] == a) return true;
      return false;
    };
    if (E.q0 == E.q1) return f.a == edge_part_p[E.p0] && has_vertex(pb, f.b, E.q0);  // P's edge p0 → p1 = next(p0)
    return f.b == edge_part_q[E.q0] && has_vertex(pp, f.a, E.p0);                    // −Q's edge −q0 → −q1, q1 = next(q0)
  }

  // A line through the sum vertex (p, q) not parallel to `avoid`: an input edge at p translated
  // by −q, or one at q (as an edge of −Q) translated by p. False when all four are parallel.
  bool line_through(std::uint32_t p, std::uint32_t q, const Ray& avoid, Line& out) {
    if (prevP.empty()) {
      prevP.resize(S.P.size());
      prevQ.resize(S.Q.size());
      for (std::size_t g = 0; g < S.P.size(); ++g) prevP[S.P.next(g)] = static_cast<std::uint32_t>(g);
      for (std::size_t g = 0; g < S.Q.size(); ++g) prevQ[S.Q.next(g)] = static_cast<std::uint32_t>(g);
    }
    const auto VP = S.P.vertices(), VQ = S.Q.vertices();
    const auto pn = static_cast<std::uint32_t>(S.P.next(p)), pp = prevP[p];
    const auto qn = static_cast<std::uint32_t>(S.Q.next(q)), qp = prevQ[q];
    // The four edges at the vertex: 0, 1 of P (at p), 2, 3 of −Q (at q). Any one not parallel to
    // `avoid` will do (the crossing is the same point): a floating test with a static bound picks
    // a surely non-parallel one; the exact test only when none is certain.
    const Vec2 e0[4] = {VP[p], VP[pp], -VQ[q], -VQ[qp]}, e1[4] = {VP[pn], VP[p], -VQ[qn], -VQ[q]};
    const Vec2 dir = avoid.a1 - avoid.b1;
    int pick = -1;
    for (int k = 0; k < 4 && pick < 0; ++k) {
      const Vec2 d = e1[k] - e0[k];
      const double cr = dir.x() * d.y() - dir.y() * d.x();
      // dir and d are differences rounded once (relative 2⁻⁵³ each): 2⁻⁵⁰ of the products covers
      // them and the three roundings of cr; 2⁻¹⁰⁰⁰ covers underflow.
      if (std::abs(cr) > (std::abs(dir.x() * d.y()) + std::abs(dir.y() * d.x())) * 0x1p-50 + 0x1p-1000) pick = k;
    }
    for (int k = 0; k < 4 && pick < 0; ++k)
      if (predicates::cross_edges(avoid.b1, avoid.a1, e0[k], e1[k]) != 0) pick = k;  // line_den(c, avoid) ≠ 0
    if (pick < 0) return false;
    Line& c = out;
    c.e0 = e0[pick], c.e1 = e1[pick];
    switch (pick) {
      case 0: c.c1 = VP[p], c.c2 = -VQ[q], c.p0 = p, c.p1 = pn, c.q0 = c.q1 = q, c.q_edge = false; break;
      case 1: c.c1 = VP[pp], c.c2 = -VQ[q], c.p0 = pp, c.p1 = p, c.q0 = c.q1 = q, c.q_edge = false; break;
      case 2: c.c1 = VP[p], c.c2 = -VQ[q], c.p0 = c.p1 = p, c.q0 = q, c.q1 = qn, c.q_edge = true; break;
      default: c.c1 = VP[p], c.c2 = -VQ[qp], c.p0 = c.p1 = p, c.q0 = qp, c.q1 = q, c.q_edge = true; break;
    }
    return true;
  }

  // When the four input edges at the sum vertex (p, q) are all parallel to `avoid` (straight
  // vertices of both shapes on a collinear run: common on rectilinear pieces), a line through the
  // vertex across `avoid`: direction the normal (−dy, dx) of avoid's direction (a1 − b1 rounded
  // once, negation exact), anchored at P's p and −Q's q; ids p0 = p1 = p, q0 = q1 = q (it passes
  // through that sum vertex, which known_lambda and the tests by ids may use; no input edge has
  // both pairs equal, so same_line never ties it symbolically). The crossing with avoid's line is
  // the vertex itself, as with an input edge's line; false (reference cut) when the direction is
  // exactly parallel after all (a zero direction).
  bool cross_line_through(std::uint32_t p, std::uint32_t q, const Ray& avoid, Line& out) const {
    const Vec2 dir = avoid.a1 - avoid.b1, e1(-dir.y(), dir.x()), e0(0, 0);
    if (predicates::cross_edges(avoid.b1, avoid.a1, e0, e1) == 0) return false;
    out.c1 = S.P.vertices()[p], out.c2 = -S.Q.vertices()[q], out.e0 = e0, out.e1 = e1;
    out.p0 = out.p1 = p, out.q0 = out.q1 = q, out.q_edge = false;
    return true;
  }

  // Exact: the point at parameter p (value v to a few ulps) of candidate c lies in O. Sum
  // vertices (the ends of most parts) are looked up once: each ends two or more candidates.
  // (A table over all (P, Q) vertex pairs when small, else a hash map.)
  std::vector<signed char>& vertex_table = buf.vertex_table;
  std::unordered_map<std::uint64_t, signed char>& vertex_map = buf.vertex_map;
  // The known coverage of sum vertex `key`: -1 unknown, 0 not in O, 1 in O.
  signed char& vertex_state(std::uint64_t key) {
    if (small_table) return vertex_table[(key >> 32) * qn + (key & 0xffffffffu)];
    return vertex_map.try_emplace(key, -1).first->second;
  }
  bool covered(const NfpCandidate& c, const Split& at) {
    const Param p = normalised(at.p, c.E);
    std::uint64_t key = at.key;
    if (p.kind == Param::Zero) key = vertex_key(c.E.p0, c.E.q0);
    else if (p.kind == Param::One) key = vertex_key(c.E.p1, c.E.q1);
    if (key == kNoKey) return covered_point(c, p, at);
    signed char& v = vertex_state(key);
    if (v < 0) v = covered_point(c, p, at);
    return v;
  }
  // Few part pairs: two passes, the floating filters over every part sum whose box holds the
  // point, stopping at one that certainly contains it; only then the exact test of the undecided
  // ones (most have the point on their boundary, as the point lies on candidates, and are not
  // needed when another sum contains it). Large shapes: the same two passes over the piece pairs
  // the dual descent of their box trees finds (covered_by_pieces).
  // The hint: the sum that last surely held a tested point (a part pair's index in flat, hint_b
  // unused; or the piece pair (hint_a, hint_b)), tried first. The points tested one after the
  // other are mostly the parts and split points of one candidate in order, close together, and
  // a sum that holds one often holds the next (gardeyn2: a third of the covered points found by
  // the hint, docs/benchmarks.md). Only the order of the filters changes: the answer is exact.
  static constexpr std::uint32_t kNoHint = ~std::uint32_t(0);
  std::uint32_t hint_a = kNoHint, hint_b = kNoHint;
  std::vector<std::uint32_t>& undecided = buf.undecided;
  bool covered_point(const NfpCandidate& c, const Param& p, const Split& at) {
    // The point to within tol: A and B within a few ulps of the exact ends, v within err of μ.
    const Vec2 m = c.A + at.v * (c.B - c.A);
    const double tol = (c.A.cwiseAbs().maxCoeff() + c.B.cwiseAbs().maxCoeff()) * 0x1p-40 + 2 * at.err * (c.B - c.A).cwiseAbs().maxCoeff() + 0x1p-1000;
    const Vec2 mlo = m.array() - tol, mhi = m.array() + tol;
    int den = 2;  // sign of the cut's denominator, computed on first use
    auto den_sign = [&] {
      if (den == 2) den = p.kind == Param::Cut ? exact::exact_sign([&](auto L) { return line_den(p.line, c.E, L); }) : 1;
      return den;
    };
    if (!flat.empty()) {
      undecided.clear();
      // The hint first (t = 0), then every part pair but the hint.
      const auto n = static_cast<std::uint32_t>(flat.size()), h = hint_a;
      for (std::uint32_t t = h < n ? 0 : 1; t <= n; ++t) {
        const std::uint32_t k = t == 0 ? h : t - 1;
        if (t > 0 && k == h) continue;
        PartPair& f = flat[k];
        if (f.lo.x() > mhi.x() || f.hi.x() < mlo.x() || f.lo.y() > mhi.y() || f.hi.y() < mlo.y()) continue;
        if (c.strict && own_edge_part(f, c.E)) continue;
        if (!f.ready) prepare(f);
        const int r = in_part_sum(f, c, p, m, tol, false, 0);
        if (r > 0) {
          hint_a = k;
          return true;
        }
        if (r == 0) undecided.push_back(k);
      }
      for (const std::uint32_t k : undecided)
        if (in_part_sum(flat[k], c, p, m, tol, true, den_sign()) > 0) return true;
      return false;
    }
    return covered_by_pieces(c, p, m, tol, mlo, mhi, den_sign);
  }

  // The point of c at split s from its value, when the bounds certify it to 8 ulps per coordinate
  // (false: the caller evaluates it accurately). The exact point is A* + μ(B* − A*) with A, B the
  // ends A*, B* rounded once and |v − μ| ≤ err; a = fma(v, B − A, A) is off by at most
  // u(|A| + |v|(|B − A| + |A| + |B|) + |a|)·1.02 + err(|B − A| + 2u(|A| + |B|)) (u = 2⁻⁵³). A
  // coordinate with A = B keeps A (the exact one lies between A* and B*, within an ulp of A).
  // A cut whose floating bound is too loose gets μ again from double-double numerator and
  // denominator (|μ − v| ≤ (bn + |v|·bd)/(|d| − bd) + u|v| for their bounds bn, bd).
  // A split known to be a sum vertex (an end of c, or a key) is that vertex rounded once (a
  // difference of two input doubles): correctly rounded, and exact where a coordinate is 0, which
  // no relative bound certifies.
  bool end_point(const NfpCandidate& c, const Split& s, Vec2& out) const {
    if (s.p.kind == Param::Zero || s.p.kind == Param::One) {
      out = s.p.kind == Param::Zero ? c.A : c.B;
      return true;
    }
    if (s.key != kNoKey) {
      out = S.P.vertices()[s.key >> 32] - S.Q.vertices()[s.key & 0xffffffffu];
      return true;
    }
    constexpr double u = 0x1p-53;
    auto at = [&](double v, double err) {
      for (int k = 0; k < 2; ++k) {
        const double A = c.A[k], B = c.B[k];
        if (A == B) {
          out[k] = A;
          continue;
        }
        const double D = B - A, a = std::fma(v, D, A), S = std::abs(A) + std::abs(B);
        const double bound = 1.02 * u * (std::abs(A) + std::abs(v) * (std::abs(D) + S) + std::abs(a)) + err * (std::abs(D) + 2 * u * S) + 0x1p-1000;
        if (!(bound <= 8 * u * std::abs(a))) return false;
        out[k] = a;
      }
      return true;
    };
    if (at(s.v, s.err)) return true;
    if (s.p.kind != Param::Cut) return false;
    const exact::LiftDD L;
    const exact::DD n = line_num(s.p.line, c.E, L), d = line_den(s.p.line, c.E, L);
    const double bn = std::abs(n.lo) + exact::safe_bound(n.e), bd = std::abs(d.lo) + exact::safe_bound(d.e);
    if (!exact::dd_finite(n) || !exact::dd_finite(d) || !(std::abs(d.hi) > 2 * bd)) return false;
    const double v = n.hi / d.hi;
    return at(v, exact::safe_bound((bn + std::abs(v) * bd) / (std::abs(d.hi) - bd) + u * std::abs(v)));
  }

  // Adds to `sp` the ends of candidate d lying strictly inside the collinear candidate c.
  // False when an end has no usable line (the caller then cuts c by the reference method).
  bool collinear_ends(const NfpCandidate& c, const NfpCandidate& d, std::uint32_t ci, std::vector<std::pair<std::uint32_t, Split>>& found) {
    // dir from the input doubles (one rounding): its error stays relative to |dir| even for a
    // short candidate, which B − A's would not.
    const Vec2 dir = c.E.a1 - c.E.b1;
    const double len2 = dir.squaredNorm();
    for (int k = 0; k < 2; ++k) {
      const std::uint32_t p = k == 0 ? d.E.p0 : d.E.p1, q = k == 0 ? d.E.q0 : d.E.q1;
      if ((p == c.E.p0 && q == c.E.q0) || (p == c.E.p1 && q == c.E.q1)) continue;  // a shared end
      // Floating filter on the position along c (the rounded ends are within 2⁻⁵³ relative of
      // the exact ones; the margin is far above every rounding): clearly outside [0, 1] skips.
      const Vec2& X = k == 0 ? d.A : d.B;
      const double S = std::max({c.A.cwiseAbs().maxCoeff(), c.B.cwiseAbs().maxCoeff(), X.cwiseAbs().maxCoeff()});
      const double u = (X - c.A).dot(dir), err = (std::abs(dir.x()) + std::abs(dir.y())) * S * 0x1p-44;
      if (u < -err || u > len2 + err) continue;
      // Near an end of c: strictly inside iff dot(X − A, dir) > 0 and dot(X − B, dir) < 0, exact
      // (degree 2; X, A, B sums of two input doubles, dir = a1 − b1 exactly).
      if (std::abs(u) <= err || std::abs(u - len2) <= err) {
        auto along = [&](int end) {
          auto terms = [&](auto L) {
            auto x = L(d.E.o1.x()) + L(d.E.o2.x()) - L(c.E.o1.x()) - L(c.E.o2.x());
            auto y = L(d.E.o1.y()) + L(d.E.o2.y()) - L(c.E.o1.y()) - L(c.E.o2.y());
            auto dx = L(c.E.a1.x()) - L(c.E.b1.x()), dy = L(c.E.a1.y()) - L(c.E.b1.y());
            if (k == 1) x = x + L(d.E.a1.x()) - L(d.E.b1.x()), y = y + L(d.E.a1.y()) - L(d.E.b1.y());
            if (end == 1) x = x - dx, y = y - dy;
            return std::array{x, dx, -y, dy};  // x·dx − (−y)·dy
          };
          // Exact differences and products first (an end exactly at c's end is common), else the
          // general tiers.
          const auto t = terms(exact::LiftFlX{});
          const int s = exact::sign_ab_minus_cd(t[0], t[1], t[2], t[3]);
          if (s != 2) return s;
          return exact::exact_sign([&](auto L) {
            const auto u = terms(L);
            return u[0] * u[1] - u[2] * u[3];
          });
        };
        if (along(0) <= 0 || along(1) >= 0) continue;
      }
      Line l;
      if (!line_through(p, q, c.E, l) && !cross_line_through(p, q, c.E, l)) return false;
      const Param pm{Param::Cut, l, 0};
      Split sp = split(pm, c.E);
      sp.key = vertex_key(p, q);
      found.push_back({ci, sp});
    }
    return true;
  }

  // The pieces of every candidate that is not redundant, appended to out (nfp_classify).
  void run(std::vector<NfpPiece>& out) {
    trimmed = flat.empty() && cands.size() > 64 && nfp_trim_mode() != kTrimOff;
    if (trimmed) trim_deep();  // 0. the parts of candidates certified in O (large shapes)
    find_splits();  // 1. split points of every meeting pair of candidates
    group_splits(); //    grouped by candidate
    for (std::size_t k = 0; k < cands.size(); ++k) classify_candidate(k, out);  // 2.–4.
    nfp_trim_stats().dop_pruned += dop_pruned;
  }

 private:
  // Step 1 for one box-overlapping pair i < j: the split points each puts on the other, appended
  // to buf.found (with a vertex key or an in_o side when known); buf.reference[i] / [j] set for a
  // collinear candidate whose neighbour's end has no usable line.
  void meet(std::size_t i, std::size_t j) {
    auto& found = buf.found;
    const NfpCandidate &c = cands[i], &d = cands[j];
    if ((c.redundant && d.redundant) || apart(c, d) || apart(d, c)) return;
    const int turn = parallel_sign(c.E, d.E);  // sign of cross(dir c, dir d)
    const bool non_parallel = turn != 0;
    if (non_parallel && shared_end(c.E, d.E)) return;
    // A redundant candidate lies in the union of kept candidates on its line (nfp_candidates), so
    // where it crosses another candidate, a kept one crosses it too: only its collinear ends
    // split others (one of them is no kept candidate's end).
    if (non_parallel && (c.redundant || d.redundant)) return;
    if (non_parallel) {
      const Param pc{Param::Cut, d.line, 0}, pd{Param::Cut, c.line, 0};
      Split sc = split(pc, c.E), sd = split(pd, d.E);
      const int wc = crossing_where(sc, pc, c.E);
      if (wc < 0) return;
      const int wd = crossing_where(sd, pd, d.E);
      if (wd < 0) return;
      // A crossing at an end of c splits nothing there; at an end of d it is d's sum vertex.
      // Crossing inside both, the other candidate strict: that candidate is an edge of an open
      // pair sum lying on its left (nfp_build.cpp step 1), so the side of the crossing on its
      // left is in O (see the header).
      if (wc == 2 && !c.redundant) {
        if (wd < 2) sc.key = wd == 0 ? vertex_key(d.E.p0, d.E.q0) : vertex_key(d.E.p1, d.E.q1);
        else if (d.strict) sc.in_o = turn < 0 ? kAfter : kBefore;
        found.push_back({static_cast<std::uint32_t>(i), sc});
      }
      if (wd == 2 && !d.redundant) {
        if (wc < 2) sd.key = wc == 0 ? vertex_key(c.E.p0, c.E.q0) : vertex_key(c.E.p1, c.E.q1);
        else if (c.strict) sd.in_o = turn > 0 ? kAfter : kBefore;
        found.push_back({static_cast<std::uint32_t>(j), sd});
      }
    } else if (origin_on_line(c.E, d.E)) {
      if (!c.redundant && !collinear_ends(c, d, static_cast<std::uint32_t>(i), found)) buf.reference[i] = 1;
      if (!d.redundant && !collinear_ends(d, c, static_cast<std::uint32_t>(j), found)) buf.reference[j] = 1;
    }
  }

  // The box tree over the candidates' boxes, read in place (no copy into records).
  void build_candidate_tree(BoxTree& tree) const {
    tree.build_boxes(cands.size(), [&](std::size_t k) -> const Vec2& { return cands[k].lo; },
                     [&](std::size_t k) -> const Vec2& { return cands[k].hi; });
  }

  // Step 1: buf.pairs, the pairs i < j of candidates whose (untrimmed) boxes meet, each once, in
  // no particular order: the boxes sorted on lo.x, then each box against the following ones up to
  // its hi.x (a pair is found from its box of smaller lo.x). True when complete; false once the
  // x-overlap tests pass kSweepTests · K (dense shapes, where box-overlapping pairs grow as n²:
  // the box tree after step 0 instead). O(K log K + X_x) for X_x pairs overlapping in x; the same
  // pairs as the tree's descents, for less than the tree's build on nesting pieces.
  bool sweep_pairs() {
    if (sweep_tried) return swept;
    sweep_tried = true;
    if (nfp_pairs_mode() == kPairsTree) return false;
    const std::size_t K = cands.size(), budget = kSweepTests * K;
    if (sweep_over_budget()) return false;
    auto& box = buf.sweep;
    box.resize(K);
    for (std::size_t k = 0; k < K; ++k)
      box[k] = {cands[k].lo.x(), cands[k].hi.x(), cands[k].lo.y(), cands[k].hi.y(), static_cast<std::uint32_t>(k)};
    std::sort(box.begin(), box.end(), [](const SweepBox& x, const SweepBox& y) { return x.lx < y.lx; });
    auto& pairs = buf.pairs;
    pairs.clear();
    std::size_t tests = 0;
    for (std::size_t a = 0; a < K; ++a) {
      const SweepBox& x = box[a];
      for (std::size_t b = a + 1; b < K && box[b].lx <= x.hx; ++b) {
        if (++tests > budget) return false;
        const SweepBox& y = box[b];
        if (y.ly <= x.hy && x.ly <= y.hy) pairs.push_back(std::minmax(x.k, y.k));
      }
    }
    swept = true;
    return true;
  }

  // True when the sweep would clearly pass its budget, so that its sort and tests would only
  // delay the tree (dense stars): the boxes' x-extents W sum to more than kSweepSkip ·
  // kSweepTests times the candidates' x-range R. For boxes spread over R a sweep makes about
  // K · W / R x-overlap tests (each box meets the lo.x of about K · width / R others), kSweepSkip
  // times its budget. Only a speed decision: the tree finds the same pairs. O(K), no sort.
  bool sweep_over_budget() const {
    double lo = INFINITY, hi = -INFINITY, width = 0;
    for (const auto& c : cands) lo = std::min(lo, c.lo.x()), hi = std::max(hi, c.hi.x()), width += c.hi.x() - c.lo.x();
    return width > kSweepSkip * kSweepTests * (hi - lo);
  }

  // Step 1 after step 0 with the sweep's pairs: those of two live candidates whose boxes of the
  // parts not certified in O meet (the pairs the refitted tree would give).
  void keep_active_pairs() {
    auto& pairs = buf.pairs;
    std::size_t n = 0;
    for (const auto& pr : pairs) {
      const auto [i, j] = pr;
      if (buf.dead[i] || buf.dead[j]) continue;
      const Vec2 &li = buf.act_lo[i], &hi = buf.act_hi[i], &lj = buf.act_lo[j], &hj = buf.act_hi[j];
      if (!(lj.x() > hi.x() || li.x() > hj.x() || lj.y() > hi.y() || li.y() > hj.y())) pairs[n++] = pr;
    }
    pairs.resize(n);
  }

  // Step 1 by the box tree (the sweep over budget): buf.pairs by one descent per candidate.
  // Trimmed (trim_deep): its tree of the candidates' boxes refitted to the boxes of the parts
  // not certified in O (empty for candidates wholly in O). A split point not in O lies on both
  // candidates outside their certified parts, so its pair still meets; points in O may be
  // missed, which changes no part's class (the parts next to a point of the open set O are in
  // O) and no piece.
  void tree_pairs() {
    const std::size_t K = cands.size();
    BoxTree local;
    BoxTree& tree = trimmed || have_tree ? buf.cand_tree : local;
    if (trimmed) {
      for (std::size_t k = tree.nodes.size(); k-- > 0;) {
        auto& N = tree.nodes[k];
        if (N.left < 0) {
          N.lo = buf.dead[N.tri] ? Vec2(INFINITY, INFINITY) : buf.act_lo[N.tri];
          N.hi = buf.dead[N.tri] ? Vec2(-INFINITY, -INFINITY) : buf.act_hi[N.tri];
        } else {
          N.lo = tree.nodes[N.left].lo.cwiseMin(tree.nodes[N.right].lo);
          N.hi = tree.nodes[N.left].hi.cwiseMax(tree.nodes[N.right].hi);
        }
      }
    } else if (!have_tree) {
      build_candidate_tree(tree);
    }
    auto& pairs = buf.pairs;
    pairs.clear();
    std::vector<std::int32_t> st;
    for (std::size_t i = 0; i < K; ++i) {
      if (trimmed && buf.dead[i]) continue;
      const Vec2 &lo = trimmed ? buf.act_lo[i] : cands[i].lo, &hi = trimmed ? buf.act_hi[i] : cands[i].hi;
      st.assign(1, 0);
      while (!st.empty()) {
        const auto& N = tree.nodes[st.back()];
        st.pop_back();
        if (N.lo.x() > hi.x() || lo.x() > N.hi.x() || N.lo.y() > hi.y() || lo.y() > N.hi.y()) continue;
        if (N.left >= 0) {
          st.push_back(N.left);
          st.push_back(N.right);
        } else if (N.tri > i) {
          pairs.emplace_back(static_cast<std::uint32_t>(i), N.tri);
        }
      }
    }
  }

  // buf.pairs_sorted: buf.pairs in canonical order, by i then j (a counting sort on i, then each
  // i's few j's sorted). Each candidate then meets its partners in increasing order, whichever
  // search found the pairs, so its split points reach sort_splits in the same order and the same
  // one of two equal parameters represents the point (rounded ends). O(K + X log d), d the largest
  // number of partners.
  void order_pairs() {
    const std::size_t K = cands.size();
    const auto& in = buf.pairs;
    auto& out = buf.pairs_sorted;
    auto& end = buf.at;  // scratch (group_splits reassigns it)
    end.assign(K + 1, 0);
    for (const auto& pr : in) ++end[pr.first + 1];
    for (std::size_t k = 0; k < K; ++k) end[k + 1] += end[k];
    out.resize(in.size());
    for (const auto& pr : in) out[end[pr.first]++] = pr;  // end[i]: the end of i's run
    for (std::size_t i = 0, b = 0; i < K; b = end[i++])
      if (end[i] - b > 1) std::sort(out.begin() + b, out.begin() + end[i]);
  }

  // Step 1: buf.found, the split points of all candidates (meet over every pair with overlapping
  // boxes: all pairs for K ≤ 64, else the sweep's pairs or the box tree's, in canonical order),
  // and buf.reference.
  void find_splits() {
    const std::size_t K = cands.size();
    auto& found = buf.found;
    found.clear();
    found.reserve(4 * K);
    buf.reference.assign(K, 0);
    if (K <= 64) {
      for (std::size_t i = 0; i < K; ++i)
        for (std::size_t j = i + 1; j < K; ++j)
          if (boxes_meet(cands[i], cands[j])) meet(i, j);
      return;
    }
    if (sweep_pairs()) {
      if (trimmed) keep_active_pairs();
      ++nfp_trim_stats().swept;
    } else {
      tree_pairs();
      ++nfp_trim_stats().tree_joins;
    }
    order_pairs();
    for (const auto& [i, j] : buf.pairs_sorted) meet(i, j);
    nfp_trim_stats().meets += buf.pairs_sorted.size();
  }

  // Step 1: the split parameters grouped by candidate (counting sort): candidate k's are
  // buf.grouped[buf.first[k], buf.first[k + 1]).
  void group_splits() {
    const std::size_t K = cands.size();
    auto& found = buf.found;
    auto& first = buf.first;
    first.assign(K + 1, 0);
    for (const auto& f : found) ++first[f.first + 1];
    for (std::size_t k = 0; k < K; ++k) first[k + 1] += first[k];
    auto& grouped = buf.grouped;
    grouped.resize(found.size());
    auto& at = buf.at;
    at.assign(first.begin(), first.end() - 1);
    for (auto& f : found) grouped[at[f.first]++] = &f.second;
  }

  // Steps 2–4 for candidate k: its pieces appended to out (none for a redundant candidate; the
  // reference cut nfp_cut when it has no usable split, too many, or a part too short to sample).
  void classify_candidate(std::size_t k, std::vector<NfpPiece>& out) {
    const NfpCandidate& c = cands[k];
    if (c.redundant) return;  // its points are on kept candidates (nfp_candidates)
    if (trimmed && buf.dead[k]) return;  // wholly in O (trim_deep): no piece
    if (buf.reference[k]) {
      nfp_cut(S, c, out);
      return;
    }
    // Many candidates meet c (dense convolutions): one cut by the sums costs less than a point
    // test per part, and keeps the worst case at the reference's O(nm) per candidate.
    if (buf.first[k + 1] - buf.first[k] > kMaxSplits) {
      nfp_cut(S, c, out);
      return;
    }
    Split end0{kZero, 0, 0, vertex_key(c.E.p0, c.E.q0)}, end1{kOne, 1, 0, vertex_key(c.E.p1, c.E.q1)};
    const bool whole = sort_splits(c, k, end0, end1);  // 2.
    if (!classify_parts(c, whole)) {                   // 3.
      nfp_cut(S, c, out);
      return;
    }
    emit_pieces(c, out);  // 4.
  }

  // Step 2: buf.sp, candidate k's split points and its ends end0, end1 in exact order, equal
  // points merged (what any of them knows about the parts next to it kept). True when nothing
  // meets c inside (one part, sampled at μ = 1/2).
  bool sort_splits(const NfpCandidate& c, std::size_t k, Split& end0, Split& end1) {
    auto& sp = buf.sp;  // pointers: a Split is large, and sorting moves them
    sp.assign(buf.grouped.begin() + buf.first[k], buf.grouped.begin() + buf.first[k + 1]);
    const bool whole = sp.empty();
    sp.push_back(&end0);
    sp.push_back(&end1);
    if (whole) return true;
    // Exact order; among equal parameters the ends 0 and 1 first (symbolic sum vertices), so
    // the kept representative is the cheapest one.
    // Values further apart than their error bounds are ordered without exact arithmetic.
    auto cmp = [&](const Split& x, const Split& y) {
      if (x.v + x.err < y.v - y.err) return -1;
      if (y.v + y.err < x.v - x.err) return 1;
      if (x.key != kNoKey && x.key == y.key) return 0;
      return compare_params(x.p, y.p, c.E, kO);
    };
    auto rank = [](const Split& x) { return x.p.kind == Param::Cut ? 1 : 0; };
    std::sort(sp.begin(), sp.end(), [&](const Split* x, const Split* y) {
      const int s = cmp(*x, *y);
      return s != 0 ? s < 0 : rank(*x) < rank(*y);
    });
    // Equal split points merged; what any of them knows about the parts next to it is kept.
    std::size_t n = 1;
    for (std::size_t i = 1; i < sp.size(); ++i) {
      if (cmp(*sp[n - 1], *sp[i]) == 0) sp[n - 1]->in_o |= sp[i]->in_o;
      else sp[n++] = sp[i];
    }
    sp.resize(n);
    return false;
  }

  // Step 3: buf.part[i], the open part between buf.sp[i] and buf.sp[i + 1] lies on ∂O (1) or in
  // O (0). False when a part cannot be sampled (no double certified strictly inside it).
  bool classify_parts(const NfpCandidate& c, bool whole) {
    const auto& sp = buf.sp;
    auto& part = buf.part;
    const std::size_t V = sp.size();
    part.assign(V - 1, 0);
    bool sampled = true;
    for (std::size_t i = 0; i + 1 < V && sampled; ++i) {
      // An end known to be in O (open): the part next to it is in O too, no test. A part on ∂O
      // (closed) has its ends on ∂O: remembered for the other candidates through them.
      if ((sp[i]->in_o & kAfter) || (sp[i + 1]->in_o & kBefore) || (sp[i]->key != kNoKey && vertex_state(sp[i]->key) == 1) ||
          (sp[i + 1]->key != kNoKey && vertex_state(sp[i + 1]->key) == 1)) {
        part[i] = 0;
        continue;
      }
      const Split mid = split(Param{Param::Value, {}, 0.5 * (sp[i]->v + sp[i + 1]->v)}, c.E);
      // μ strictly between the two ends: by their error bounds when clear, else exactly.
      const bool certified = whole || (sp[i]->v + sp[i]->err < mid.v && mid.v < sp[i + 1]->v - sp[i + 1]->err) ||
                             (compare_params(sp[i]->p, mid.p, c.E, kO) < 0 && compare_params(mid.p, sp[i + 1]->p, c.E, kO) < 0);
      if (!certified) sampled = false;
      else if ((part[i] = !covered(c, mid))) {
        if (sp[i]->key != kNoKey) vertex_state(sp[i]->key) = 0;
        if (sp[i + 1]->key != kNoKey) vertex_state(sp[i + 1]->key) = 0;
      }
    }
    return sampled;
  }

  // Step 4: c's pieces appended to out, the maximal runs of boundary parts and split points on ∂O
  // (each split point not next to a boundary part tested itself), with their rounded ends.
  void emit_pieces(const NfpCandidate& c, std::vector<NfpPiece>& out) {
    const auto& sp = buf.sp;
    const auto& part = buf.part;
    auto& vert = buf.vert;
    const std::size_t V = sp.size();
    vert.assign(V, 0);
    for (std::size_t i = 0; i < V; ++i) vert[i] = (i > 0 && part[i - 1]) || (i + 1 < V && part[i]) || !covered(c, *sp[i]);
    for (std::size_t i = 0; i < V;) {
      if (!vert[i]) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < V && part[j]) ++j;
      Vec2 a, b;
      if (end_point(c, *sp[i], a) && end_point(c, *sp[j], b)) out.push_back(make_piece(c, sp[i]->p, sp[j]->p, a, b));
      else out.push_back(make_piece(c, sp[i]->p, sp[j]->p));
      i = j + 1;
    }
  }
};

}  // namespace

int& nfp_pairs_mode() {
  thread_local int mode = kPairsAuto;
  return mode;
}

int& nfp_trim_mode() {
  thread_local int mode = kTrimAuto;
  return mode;
}
int& nfp_dop_mode() {
  thread_local int mode = kDopOn;
  return mode;
}
NfpTrimStats& nfp_trim_stats() {
  thread_local NfpTrimStats stats;
  return stats;
}

const std::vector<std::uint32_t>& ShapeSide::edge_parts() const {
  std::call_once(edge_once_, [&] {
    const ConvexParts& X = parts();
    edge_parts_.assign(shape.size(), ~std::uint32_t(0));
    for (std::uint32_t k = 0; k < X.size(); ++k) {
      const std::uint32_t s = X.start[k], n = X.start[k + 1] - s;
      for (std::uint32_t i = 0; i < n; ++i)
        if (shape.next(X.id[s + i]) == X.id[s + (i + 1) % n]) edge_parts_[X.id[s + i]] = k;
    }
  });
  return edge_parts_;
}

const ShapeSide::Pieces& ShapeSide::pieces() const {
  std::call_once(pieces_once_, [&] {
    Pieces& p = pieces_;
    // Fans of a long edge re-covered with Steiner pieces first (strip_pieces.hpp).
    ConvexParts stripped;
    const bool strip = strip_fans(parts(), stripped);
    Classifier::make_pieces(strip ? stripped : parts(), shape, p.r, p.edge_piece, p.smax);
    p.tree.build_boxes(p.r.size(), [&](std::size_t k) -> const Vec2& { return p.r.lo[k]; }, [&](std::size_t k) -> const Vec2& { return p.r.hi[k]; });
  });
  return pieces_;
}

bool convex_shape(const Polygon& S) {
  if (S.hole_count() != 0) return false;
  const auto V = S.vertices();
  for (std::size_t g = 0; g < S.size(); ++g) {
    const std::size_t h = S.next(g);
    if (predicates::cross_edges(V[g], V[h], V[h], V[S.next(h)]) < 0) return false;
  }
  return true;
}

void nfp_classify(const PairDepth2::Impl& S, const std::vector<NfpCandidate>& cands, std::vector<NfpPiece>& out) {
  // Two convex shapes: a candidate at a strictly convex vertex is a whole edge of the convex sum
  // P ⊕ (−Q) (the vertex's angle, hence the whole convex shape, lies on the closed outer side of
  // the edge: the vertex is extreme against its outer normal), so nothing covers it and its piece
  // is [0, 1], as the reference cutting finds. At a straight vertex the candidate rule checks only
  // the two collinear edges, not the side of the angle: the edges there are parallel to the
  // candidate's direction d (both cross signs are 0). Let u be the straight vertex's outgoing edge
  // in its own shape (interior on u's left). P's edge with Q's straight vertex q: P lies in the
  // closed left half-plane of d's line, and Q + x (x on the candidate) in its closed right one
  // when u runs against d. −Q's edge (d = −(q1 − q0)) with P's straight vertex p: Q + x lies in
  // the closed left half-plane of d's line through p, and P in its closed right one when u runs
  // along d. Then no placement on the candidate overlaps: the piece is [0, 1] again (what the
  // cutting finds: no open sum meets the candidate). The direction of u against d is read off one
  // non-zero coordinate of d (exactly parallel vectors: exact comparisons of input doubles).
  // Otherwise (u along d for P's edge: Q's straight vertex q has −Q's outward normal −n there,
  // n the edge's outward normal) the whole candidate, ends included, lies in O = int K,
  // K = P ⊕ (−Q): a point x − y (x ∈ P, y ∈ Q) is on ∂K only if one direction w supports P at x
  // and −Q at −y; at the straight vertex −q the only such w is −n (its normal cone is one ray),
  // and x on P's edge is extreme along +n, so P would lie on one line. The same for −Q's edge
  // with P's straight vertex. Such a candidate gives no piece (what the reference cut finds:
  // ConvexPairs, StraightRunsInBothShapes compare them).
  if (convex_shape(S.P) && convex_shape(S.Q)) {
    const auto VP = S.P.vertices(), VQ = S.Q.vertices();
    auto outer_straight = [&](const NfpCandidate& c) {
      const Ray& E = c.E;
      const bool q_edge = c.line.q_edge;  // −Q's edge with P's straight vertex p, else P's edge with Q's q
      const Vec2& u0 = q_edge ? VP[E.p0] : VQ[E.q0];
      const Vec2& u1 = q_edge ? VP[S.P.next(E.p0)] : VQ[S.Q.next(E.q0)];
      const bool same = E.a1.x() != E.b1.x() ? (E.a1.x() > E.b1.x()) == (u1.x() > u0.x()) : (E.a1.y() > E.b1.y()) == (u1.y() > u0.y());
      return q_edge ? same : !same;
    };
    for (const NfpCandidate& c : cands) {
      if (c.redundant) continue;
      if (c.strict || outer_straight(c)) out.push_back(make_piece(c, kZero, kOne));
      // else: an inner straight candidate lies in O, ends included: no piece.
    }
    return;
  }
  Classifier(S, cands).run(out);
  thread_buffers().trim();
}

}  // namespace pendepth::nonconvex2
