// The per-pair no-fit polygon, floating fast path of the queries (issue 19 item 1): a flat
// structure-of-arrays copy of ∂O in doubles, scanned linearly, whose every decision is certified
// by a static error bound or reported undecided (the caller then decides exactly). Nothing here
// produces an answer value: it only decides membership when that is certain and narrows σ's and
// σ_d's exact search to the pieces that can win (nfp_query.cpp evaluates those exactly, as before;
// the winner's value from double-doubles: nfp_value.cpp).
//
// Data: ring edges of cl(O) from the export (nfp_rings.cpp: every vertex is the exact vertex
// rounded to nearest), slits and isolated points likewise, and the pieces' ends NfpPiece::a, b
// (each coordinate within a few ulps of the exact end). M = max(|t|∞, rmax) bounds every
// coordinate involved; ε = 2⁻⁵³.
//
// overlapping(t) — t ∈ O iff t lies inside the rings by parity (O on the left of every ring: the
//   winding number of t is 1 in O and 0 outside cl(O)) and on no ring edge, slit or isolated point
//   (cl(O) \ O = ∂O). Crossing number with the rightward horizontal ray, half-open rule:
//   * y of a vertex against t.y: rounding to nearest is monotone, so v.y > t.y ⇒ v*.y > t.y and
//     v.y < t.y ⇒ v*.y < t.y for the exact v*; v.y = t.y is undecided;
//   * side of t for a straddling edge: the determinant in double differs from the exact one (exact
//     ends, ≤ ε·M away per coordinate) by ≤ 12·ε·M² (endpoint moves) + 24·ε·M² (rounding,
//     Shewchuk's ccwerrboundA on terms ≤ 8M²) < 2⁻⁴⁷·M²; the filter uses 2⁻⁴⁴·M²;
//   * slits: t outside a slit's box (strict, monotone as above), or off its line by the bound;
//     points: t differs from the rounded point in a coordinate (then from the exact one).
// nearest_candidates(t) — the distance from t to a rounded piece differs from the distance to the
//   exact piece by the ends' displacement (≤ 2⁻⁵⁰·M·√2) and from its double evaluation (the
//   projection parameter by a stored 1/|b − a|², clamped to [0, 1]: any clamped parameter gives a
//   point of the segment, whose distance is off by a few ulps of M) by a few ulps of M:
//   |d̂ − d*| < e = 2⁻⁴⁰·M. A piece can be nearest only if d̂ − e ≤ min d̂ + e, hence only if
//   d̂² ≤ min d̂² + 2⁻³⁵·M² (the threshold taken, no square root). For each candidate,
//   dot(t − a, b − a) and |b − a|² − dot against ±2⁻⁴⁰·M² (error ≪ that: the ends' displacement
//   and rounding on terms ≤ 8M², checked against rationals in tests/nonconvex2/test_nfp_fast.cpp)
//   flag t's projection as strictly inside the exact piece, before its lo end or beyond its hi end.
// first_hit_candidates(t, d) — for X on a piece, cross(d, X − t) and dot(d, X − t) are linear in
//   X, so over the exact piece they lie between their values at the exact ends, each within
//   e_d = 2⁻⁴⁰·M·(|dx| + |dy|) of the double values at the rounded ends. A piece both of whose ends
//   are beyond e_d on one side of the line misses it; a hit at λ has dot = λ·|d|² within
//   [min − e_d, max + e_d] of the end values; a piece with ends certified on opposite sides and
//   min − e_d > 0 is hit at some λ ≤ (max + e_d)/|d|²: U is the least such bound, and only pieces
//   with min − e_d ≤ U (and max + e_d > 0) can be hit first. A piece with ends certified on
//   opposite sides but min − e_d ≤ 0 spans t's perpendicular (a third of the candidates on the
//   bench's nesting pieces, half of them crossing behind t, each decided exactly before): it meets
//   the line at λ = cross(b − a, t − a)/cross(d, b − a), where cross(d, b − a) = cb − ca (ca, cb:
//   cross(d, a − t), cross(d, b − t), certified of opposite signs) has a known sign; with cross(b − a, t − a)
//   certified by nearest_candidates' bound (side_of_piece, 2⁻⁴⁰·M²) it is hit ahead (then as a
//   piece with min − e_d > 0: λ ≤ (max + e_d)/|d|²) or behind t (dropped); else it stays an
//   uncertified candidate.
// inside_by_candidates (nfp_impl.hpp) — the overlap test skipped: let δ be the least distance from
//   t to a piece (σ) or λ* the ray's first hit (σ_d). The pieces cover ∂O (every boundary point of
//   the union of open pair sums is uncovered on some sum's edge), so the open disk of radius δ
//   about t (σ_d: the segment [t, t + λ*·d)) meets no point of ∂O and lies wholly in O or wholly
//   outside it. A sole candidate holds every piece at distance δ (hit at λ*), so the nearest (first)
//   point X is in the relative interior of that piece alone (kInside) and no other piece passes
//   through X; points just left of X are inside the piece's open pair sum (O lies on a piece's
//   left), so when t is strictly left of the piece's line (kFromO: cross(b − a, t − a) > B, the
//   same bound as the dot products; σ_d: a right and b left of the ray, beyond e_d, so the ray
//   meets X coming from the left), the points of the disk (segment) next to X are in O, hence t.
//   Otherwise the caller runs the overlap test (t outside O, or two pieces near: no shortcut).
// inside_by_nearest (σ) — also the shared-vertex wedge: V a reflex vertex of O (Impl::wedge, exact
//   at the export: the pieces of positive length ending at V all arrive along one direction u,
//   those starting there all leave along w, cross(u, w) < 0), and every candidate one of them
//   with t's projection certainly beyond its hi end (an arriving one, kBeyondHi) or before its lo
//   end (a leaving one, kBeforeLo), or a zero-length piece at V. Then every candidate's nearest
//   point is V, so δ = |v|, v = t − V (the nearest piece is a candidate), and t ≠ V (the flags are
//   strict); every piece through V is at distance ≤ |v| = δ, hence a candidate, hence one of
//   those (at least one arriving and one leaving: V is a wedge vertex): near V, ∂O is two
//   segments leaving V along −u and w, which cut a small disk about V into two open sectors, each
//   wholly in O or wholly outside cl(O). The points just left of a leaving piece next to V are in
//   O (as above), so the sector swept counterclockwise from w to −u lies in O; the other, the cone
//   C = {α·(−u) + β·w : α, β ≥ 0} (convex: the right turn puts −u and w less than π apart), lies
//   outside. The flags give dot(v, u) > 0 > dot(v, w), so every c ≠ 0 in C has
//   dot(v, c) = −α·dot(v, u) + β·dot(v, w) < 0: v ∉ C, and V + s·v lies in O's sector for small
//   s > 0; those points are in the open disk of radius δ about t, which meets no point of ∂O, so
//   the disk and t lie in O. (At a convex vertex of O, cross(u, w) > 0, the same flags hold with t
//   outside: no wedge there. Pinch vertices, slits, and pieces through V inside their extent give
//   no wedge or a candidate without a wedge end.)
// Range: used only when rmax ∈ [2⁻³⁰⁰, 2³⁰⁰] (no overflow or underflow of M², far below the
// front door's own band, src/front/scale.hpp); σ and σ_d for at most kFlatMax pieces (beyond, the
// hierarchy's O(log N) traversal wins over a linear scan); queries with |t| beyond 2³⁰⁰ are
// undecided. Cost: one pass over the ring edges (overlap) — above kSlabMin edges only over those
// of t's horizontal slab (about 4 edges per slab, at most 8 copies per edge; when tall edges leave
// a slab with more than a sixteenth of the edges, all edges up to 256, else the exact pair-sum test)
// — and two passes over the pieces (σ: the first branch-free, two pieces per SSE2 step, four per
// AVX step where isa::use_v3() (the same operations per lane: the same doubles), the second over
// the stored distances; σ_d: the first, its line test two or four pieces wide likewise, lists the
// pieces meeting the ray's line ahead of t (the dot products only in steps where some lane meets
// the line), the second visits that list — a branch-free version of the whole pass was 17 %
// slower at 117 pieces and no faster on nesting pieces). σ and σ_d skip the overlap pass when
// inside_by_candidates (σ: inside_by_nearest) proves t ∈ O (about half of σ's overlapping
// placements in the tests, degenerate ones included).
#include <algorithm>
#include <cmath>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "geometry/isa.hpp"
#include "nonconvex2/nfp_impl.hpp"
#if PENDEPTH_V3_CLONES
#include <immintrin.h>
#endif

namespace pendepth::nonconvex2 {

namespace {

// Largest piece count scanned linearly for σ and σ_d: at 776 pieces (100 × 100 stars) the
// hierarchy was faster (σ 2.5 against 3.1 µs, σ_d 0.8 against 1.4 µs), at 117 the scan.
constexpr std::size_t kFlatMax = 256;
constexpr double kLow = 0x1p-300, kHigh = 0x1p300;
// Ring edges scanned whole up to this count; beyond, only those of t's horizontal slab.
constexpr std::size_t kSlabMin = 16;

double bound_m(const Vec2& t, double rmax) { return std::max({std::abs(t.x()), std::abs(t.y()), rmax}); }

}  // namespace

void NfpFlat::build(const NoFitPolygon2::Impl& N) {
  double r = 0;
  auto see = [&](const Vec2& v) { r = std::max({r, std::abs(v.x()), std::abs(v.y())}); };
  // Each array allocated once at its final size (growth by push_back was a visible share of the
  // build on small pairs).
  std::size_t ring_edges = 0;
  for (const auto& poly : N.polys)
    for (const auto& ring : poly) ring_edges += ring.size();
  for (auto* v : {&rx0, &ry0, &rx1, &ry1}) v->reserve(ring_edges);
  for (auto* v : {&px0, &py0, &px1, &py1, &pinv}) v->reserve(N.pieces.size());
  for (const auto& poly : N.polys)
    for (const auto& ring : poly)
      for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        rx0.push_back(ring[j].x()), ry0.push_back(ring[j].y());
        rx1.push_back(ring[i].x()), ry1.push_back(ring[i].y());
        see(ring[i]);
      }
  slits = N.slits;
  points = N.points;
  wedge = N.wedge;
  for (const auto& s : slits) see(s[0]), see(s[1]);
  for (const Vec2& p : points) see(p);
  for (const NfpPiece& pc : N.pieces) {
    px0.push_back(pc.a.x()), py0.push_back(pc.a.y());
    px1.push_back(pc.b.x()), py1.push_back(pc.b.y());
    const double ex = pc.b.x() - pc.a.x(), ey = pc.b.y() - pc.a.y(), l2 = ex * ex + ey * ey;
    pex.push_back(ex), pey.push_back(ey);
    pinv.push_back(l2 > 0 ? 1 / l2 : 0.0);
    see(pc.a), see(pc.b);
  }
  build_values(N, pdd, pend);
  rmax = r;
  usable = !N.pieces.empty() && N.pieces.size() <= kFlatMax && r >= kLow && r <= kHigh;
  if (usable) build_lines(N, pdd, pline);
  overlap_usable = !N.pieces.empty() && !rx0.empty() && r >= kLow && r <= kHigh;
  if (rx0.size() <= kSlabMin) return;
  // Slabs: about 4 edges per slab; an edge goes to every slab from slab_of(its lowest y) to
  // slab_of(its highest y). slab_of is monotone (a subtraction and a product by positive
  // constants, then floor), so an edge whose y range holds t.y is in slab_of(t.y).
  // Tall edges (a comb's teeth) span many slabs: the copies are capped at 8 per edge (fewer,
  // taller slabs), and when a slab still holds more than max(64, a sixteenth of the) edges
  // the slabs do not pay: up to kFlatMax edges all are scanned, beyond the exact pair-sum test
  // stays in charge (overlap_usable false).
  const std::size_t E = rx0.size();
  ylo = *std::min_element(ry0.begin(), ry0.end()), yhi = *std::max_element(ry0.begin(), ry0.end());
  std::size_t count = std::max<std::size_t>(1, E / 4);
  std::vector<std::uint32_t> first;
  auto range = [&](std::size_t k, std::size_t& a, std::size_t& b) {
    a = slab_of(std::min(ry0[k], ry1[k]), count), b = slab_of(std::max(ry0[k], ry1[k]), count);
  };
  for (;; count = std::max<std::size_t>(1, count / 2)) {
    yscale = yhi > ylo ? double(count) / (yhi - ylo) : 0;
    first.assign(count + 1, 0);
    std::size_t total = 0;
    for (std::size_t k = 0; k < E; ++k) {
      std::size_t a, b;
      range(k, a, b);
      for (std::size_t s = a; s <= b; ++s) ++first[s + 1];
      total += b - a + 1;
    }
    if (total <= 8 * E || count == 1) break;
  }
  std::size_t widest = 0;
  for (std::size_t s = 0; s < count; ++s) widest = std::max<std::size_t>(widest, first[s + 1]);
  if (widest > std::max<std::size_t>(64, E / 16)) {
    overlap_usable = E <= kFlatMax;  // a linear scan still pays for a few edges
    return;
  }
  for (std::size_t s = 0; s < count; ++s) first[s + 1] += first[s];
  std::vector<double> x0(first[count]), y0(first[count]), x1(first[count]), y1(first[count]);
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for (std::size_t k = 0; k < E; ++k) {
    std::size_t a, b;
    range(k, a, b);
    for (std::size_t s = a; s <= b; ++s) {
      const std::uint32_t i = fill[s]++;
      x0[i] = rx0[k], y0[i] = ry0[k], x1[i] = rx1[k], y1[i] = ry1[k];
    }
  }
  rx0.swap(x0), ry0.swap(y0), rx1.swap(x1), ry1.swap(y1);
  slab.swap(first);
}

std::size_t NfpFlat::slab_of(double y, std::size_t count) const {
  const double s = std::floor((y - ylo) * yscale);
  return s <= 0 ? 0 : s >= double(count - 1) ? count - 1 : std::size_t(s);
}

int NfpFlat::overlapping(const Vec2& t) const {
  const double tx = t.x(), ty = t.y(), M = bound_m(t, rmax);
  if (!(M <= kHigh)) return -1;
  const double B = 0x1p-44 * M * M;
  // Branch-free over the edges (of t's slab): `close` collects the undecided cases.
  bool close = false, in = false;
  std::size_t k0 = 0, n = rx0.size();
  if (!slab.empty()) {
    if (ty < ylo || ty > yhi) return 0;  // below or above every ring vertex (monotone rounding)
    const std::size_t s = slab_of(ty, slab.size() - 1);
    k0 = slab[s], n = slab[s + 1];
  }
  const double *x0 = rx0.data(), *y0 = ry0.data(), *x1 = rx1.data(), *y1 = ry1.data();
  for (std::size_t k = k0; k < n; ++k) {
    const bool above0 = y0[k] > ty, above1 = y1[k] > ty;
    close |= (y0[k] == ty) | (y1[k] == ty);
    if (above0 == above1) continue;
    const double det = (x1[k] - x0[k]) * (ty - y0[k]) - (y1[k] - y0[k]) * (tx - x0[k]);
    close |= std::abs(det) <= B;
    in ^= (det > 0) == above1;
  }
  if (close) return -1;
  if (!in) return 0;
  for (const Vec2& p : points)
    if (p.x() == tx && p.y() == ty) return -1;
  for (const auto& s : slits) {
    const Vec2 &a = s[0], &b = s[1];
    if (tx < std::min(a.x(), b.x()) || tx > std::max(a.x(), b.x()) || ty < std::min(a.y(), b.y()) || ty > std::max(a.y(), b.y()))
      continue;
    const double det = (b.x() - a.x()) * (ty - a.y()) - (b.y() - a.y()) * (tx - a.x());
    if (std::abs(det) <= B) return -1;
  }
  return 1;
}

namespace {

// The pieces that may meet σ_d's ray line ahead of t (first_hit_candidates' line test), in
// increasing index order, with ca, cb = cross(d, a − t), cross(d, b − t) and pa, pb = dot(d, a − t),
// dot(d, b − t). Filled by the line tests a lane mask at a time, then visited by one scalar loop
// whose running bound and constants stay in registers (a visit inside the SIMD loop read them
// through the closure's references after every store).
struct LineMeets {
  std::uint32_t idx[kFlatMax];
  double v[4][kFlatMax];  // ca, cb, pa, pb
  std::size_t n = 0;
  // Lanes `lanes` (bit i: piece k + i) of a step whose values are c[j][i] (c: ca, cb, pa, pb).
  template <std::size_t W>
  void add(std::size_t k, int lanes, const double (&c)[4][W]) {
    for (; lanes != 0; lanes &= lanes - 1) {
      const int i = __builtin_ctz(unsigned(lanes));
      idx[n] = std::uint32_t(k + i);
      for (int j = 0; j < 4; ++j) v[j][n] = c[j][i];
      ++n;
    }
  }
};

#if PENDEPTH_V3_CLONES
// nearest_candidates' pass 1, four pieces per AVX step (x86-64-v3 processors, isa::use_v3()): the
// same operations per lane as the two-wide and scalar loops (no fused multiply-add: each product
// and sum rounds as there), so the same q[k] and the same least value; returns the index reached.
[[gnu::target("arch=x86-64-v3")]] std::size_t distances_v3(const double* x0, const double* y0, const double* ex, const double* ey,
                                                           const double* il, std::size_t n, double tx, double ty, double* q,
                                                           double& best) {
  const __m256d Tx = _mm256_set1_pd(tx), Ty = _mm256_set1_pd(ty), zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1);
  __m256d lo4 = _mm256_set1_pd(INFINITY);
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const __m256d Ex = _mm256_loadu_pd(ex + k), Ey = _mm256_loadu_pd(ey + k);
    const __m256d wx = _mm256_sub_pd(Tx, _mm256_loadu_pd(x0 + k)), wy = _mm256_sub_pd(Ty, _mm256_loadu_pd(y0 + k));
    __m256d s = _mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(wx, Ex), _mm256_mul_pd(wy, Ey)), _mm256_loadu_pd(il + k));
    s = _mm256_min_pd(_mm256_max_pd(s, zero), one);
    const __m256d dx = _mm256_sub_pd(wx, _mm256_mul_pd(s, Ex)), dy = _mm256_sub_pd(wy, _mm256_mul_pd(s, Ey));
    const __m256d d2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    _mm256_storeu_pd(q + k, d2);
    lo4 = _mm256_min_pd(lo4, d2);
  }
  double l[4];
  _mm256_storeu_pd(l, lo4);
  best = std::min({best, l[0], l[1], l[2], l[3]});
  return k;
}

// first_hit_candidates' line test, four pieces per AVX step (as distances_v3: the same operations
// per lane as the narrower loops): appends each piece that may meet the ray's line ahead of t to
// `meet`, in increasing order; returns the index reached.
[[gnu::target("arch=x86-64-v3")]] std::size_t line_test_v3(const double* x0, const double* y0, const double* x1, const double* y1,
                                                            std::size_t n, double tx, double ty, double dx, double dy, double e,
                                                            LineMeets& meet) {
  const __m256d Tx = _mm256_set1_pd(tx), Ty = _mm256_set1_pd(ty), Dx = _mm256_set1_pd(dx), Dy = _mm256_set1_pd(dy);
  const __m256d E = _mm256_set1_pd(e), mE = _mm256_set1_pd(-e);
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const __m256d ax = _mm256_sub_pd(_mm256_loadu_pd(x0 + k), Tx), ay = _mm256_sub_pd(_mm256_loadu_pd(y0 + k), Ty);
    const __m256d bx = _mm256_sub_pd(_mm256_loadu_pd(x1 + k), Tx), by = _mm256_sub_pd(_mm256_loadu_pd(y1 + k), Ty);
    const __m256d ca = _mm256_sub_pd(_mm256_mul_pd(Dx, ay), _mm256_mul_pd(Dy, ax));
    const __m256d cb = _mm256_sub_pd(_mm256_mul_pd(Dx, by), _mm256_mul_pd(Dy, bx));
    const __m256d miss = _mm256_or_pd(_mm256_and_pd(_mm256_cmp_pd(ca, E, _CMP_GT_OQ), _mm256_cmp_pd(cb, E, _CMP_GT_OQ)),
                                      _mm256_and_pd(_mm256_cmp_pd(ca, mE, _CMP_LT_OQ), _mm256_cmp_pd(cb, mE, _CMP_LT_OQ)));
    int lanes = ~_mm256_movemask_pd(miss) & 15;
    if (lanes == 0) continue;
    // Pieces meeting the line: behind t (both dot products certainly ≤ 0) dropped here.
    const __m256d pa = _mm256_add_pd(_mm256_mul_pd(Dx, ax), _mm256_mul_pd(Dy, ay));
    const __m256d pb = _mm256_add_pd(_mm256_mul_pd(Dx, bx), _mm256_mul_pd(Dy, by));
    lanes &= _mm256_movemask_pd(_mm256_cmp_pd(_mm256_add_pd(_mm256_max_pd(pa, pb), E), _mm256_setzero_pd(), _CMP_GT_OQ));
    if (lanes == 0) continue;
    double c[4][4];
    _mm256_storeu_pd(c[0], ca), _mm256_storeu_pd(c[1], cb), _mm256_storeu_pd(c[2], pa), _mm256_storeu_pd(c[3], pb);
    meet.add(k, lanes, c);
  }
  return k;
}
#endif

}  // namespace

void NfpFlat::nearest_candidates(const Vec2& t, std::vector<std::uint32_t>& out) const {
  const double tx = t.x(), ty = t.y(), M = bound_m(t, rmax), B = 0x1p-40 * M * M;
  const std::size_t n = px0.size();  // ≤ kFlatMax (usable)
  const double *x0 = px0.data(), *y0 = py0.data(), *ex = pex.data(), *ey = pey.data(), *il = pinv.data();
  // Pass 1, branch-free (the clamps are selects): the squared distance to every rounded piece.
  double q[kFlatMax];
  double best = INFINITY;
  std::size_t k = 0;
#if PENDEPTH_V3_CLONES
  if (isa::use_v3()) k = distances_v3(x0, y0, ex, ey, il, n, tx, ty, q, best);
#endif
#ifdef __SSE2__
  // Two pieces per step (the same operations per lane as the scalar loop below).
  const __m128d Tx = _mm_set1_pd(tx), Ty = _mm_set1_pd(ty), zero = _mm_setzero_pd(), one = _mm_set1_pd(1);
  __m128d lo2 = _mm_set1_pd(best);
  for (; k + 2 <= n; k += 2) {
    const __m128d Ex = _mm_loadu_pd(ex + k), Ey = _mm_loadu_pd(ey + k);
    const __m128d wx = _mm_sub_pd(Tx, _mm_loadu_pd(x0 + k)), wy = _mm_sub_pd(Ty, _mm_loadu_pd(y0 + k));
    __m128d s = _mm_mul_pd(_mm_add_pd(_mm_mul_pd(wx, Ex), _mm_mul_pd(wy, Ey)), _mm_loadu_pd(il + k));
    s = _mm_min_pd(_mm_max_pd(s, zero), one);
    const __m128d dx = _mm_sub_pd(wx, _mm_mul_pd(s, Ex)), dy = _mm_sub_pd(wy, _mm_mul_pd(s, Ey));
    const __m128d d2 = _mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy));
    _mm_storeu_pd(q + k, d2);
    lo2 = _mm_min_pd(lo2, d2);
  }
  double l[2];
  _mm_storeu_pd(l, lo2);
  best = std::min(l[0], l[1]);
#endif
  for (; k < n; ++k) {
    const double wx = tx - x0[k], wy = ty - y0[k];
    const double s = std::clamp((wx * ex[k] + wy * ey[k]) * il[k], 0.0, 1.0);
    const double dx = wx - s * ex[k], dy = wy - s * ey[k];
    q[k] = dx * dx + dy * dy;
    best = std::min(best, q[k]);
  }
  // A piece can be nearest only if q[k] ≤ (√best + 2e)²·(1 + 2⁻⁴⁰) (header); as √best ≤ 2√2·M,
  // that is below best + 2⁻³⁵·M² (4e·2√2·M + 8M²·2⁻⁴⁰ + 4e² < 20·2⁻⁴⁰·M², the rest of the margin
  // covering this sum's rounding): a superset of the same candidates, without the square root's
  // latency before the second pass.
  const double thr = best + 0x1p-35 * M * M;
  for (std::size_t k = 0; k < n; ++k)
    if (q[k] <= thr) {
      // dot(t − a, b − a) and dot(t − b, a − b) = |b − a|² − dot(t − a, b − a) against B: the
      // projection of t falls strictly inside the exact piece, strictly before its lo end or
      // strictly beyond its hi end (the same error reasoning as for the determinant; a point piece
      // gets no flag).
      const double wx = tx - x0[k], wy = ty - y0[k];
      // cross(b − a, t − a) against B likewise: t strictly on O's side (the piece's left).
      const double dot = wx * ex[k] + wy * ey[k], l2 = ex[k] * ex[k] + ey[k] * ey[k], cross = side_of_piece(k, tx, ty);
      const std::uint32_t flag = dot > B && l2 - dot > B ? kInside | (cross > B ? kFromO : 0u) : dot < -B ? kBeforeLo : l2 - dot < -B ? kBeyondHi : 0u;
      out.push_back(std::uint32_t(k) | flag);
    }
}

void NfpFlat::first_hit_candidates(const Vec2& t, const Vec2& d, std::vector<std::uint32_t>& out) const {
  const double tx = t.x(), ty = t.y(), dx = d.x(), dy = d.y();
  const double M = bound_m(t, rmax), e = 0x1p-40 * M * (std::abs(dx) + std::abs(dy)), B = 0x1p-40 * M * M;
  const std::size_t n = px0.size();
  const double *x0 = px0.data(), *y0 = py0.data(), *x1 = px1.data(), *y1 = py1.data();
  // The line test: pieces with both ends certainly on one side of the ray's line miss it.
  LineMeets meet;
  std::size_t k = 0;
#if PENDEPTH_V3_CLONES
  if (isa::use_v3()) k = line_test_v3(x0, y0, x1, y1, n, tx, ty, dx, dy, e, meet);
#endif
#ifdef __SSE2__
  // Two pieces per step (the same operations per lane as the scalar loop below); most pieces miss
  // the line, so the step usually ends at the mask.
  {
    const __m128d Tx = _mm_set1_pd(tx), Ty = _mm_set1_pd(ty), Dx = _mm_set1_pd(dx), Dy = _mm_set1_pd(dy);
    const __m128d E = _mm_set1_pd(e), mE = _mm_set1_pd(-e);
    for (; k + 2 <= n; k += 2) {
      const __m128d ax = _mm_sub_pd(_mm_loadu_pd(x0 + k), Tx), ay = _mm_sub_pd(_mm_loadu_pd(y0 + k), Ty);
      const __m128d bx = _mm_sub_pd(_mm_loadu_pd(x1 + k), Tx), by = _mm_sub_pd(_mm_loadu_pd(y1 + k), Ty);
      const __m128d ca = _mm_sub_pd(_mm_mul_pd(Dx, ay), _mm_mul_pd(Dy, ax)), cb = _mm_sub_pd(_mm_mul_pd(Dx, by), _mm_mul_pd(Dy, bx));
      const __m128d miss = _mm_or_pd(_mm_and_pd(_mm_cmpgt_pd(ca, E), _mm_cmpgt_pd(cb, E)), _mm_and_pd(_mm_cmplt_pd(ca, mE), _mm_cmplt_pd(cb, mE)));
      int lanes = ~_mm_movemask_pd(miss) & 3;
      if (lanes == 0) continue;
      const __m128d pa = _mm_add_pd(_mm_mul_pd(Dx, ax), _mm_mul_pd(Dy, ay)), pb = _mm_add_pd(_mm_mul_pd(Dx, bx), _mm_mul_pd(Dy, by));
      lanes &= _mm_movemask_pd(_mm_cmpgt_pd(_mm_add_pd(_mm_max_pd(pa, pb), E), _mm_setzero_pd()));
      if (lanes == 0) continue;
      double c[4][2];
      _mm_storeu_pd(c[0], ca), _mm_storeu_pd(c[1], cb), _mm_storeu_pd(c[2], pa), _mm_storeu_pd(c[3], pb);
      meet.add(k, lanes, c);
    }
  }
#endif
  for (; k < n; ++k) {
    const double ax = x0[k] - tx, ay = y0[k] - ty, bx = x1[k] - tx, by = y1[k] - ty;
    const double ca = dx * ay - dy * ax, cb = dx * by - dy * bx;
    if ((ca > e && cb > e) || (ca < -e && cb < -e)) continue;  // misses the line
    const double pa = dx * ax + dy * ay, pb = dx * bx + dy * by;
    if (!(std::max(pa, pb) + e > 0)) continue;  // behind t
    const double c[4][1] = {{ca}, {cb}, {pa}, {pb}};
    meet.add(k, 1, c);
  }
  // The visit of each piece that may meet the line ahead of t.
  double U = INFINITY;
  double los[kFlatMax];  // lower bounds of the kept pieces (n ≤ kFlatMax: usable)
  std::size_t kept = 0;
  const std::size_t first = out.size();
  for (std::size_t i = 0; i < meet.n; ++i) {
    const std::uint32_t k = meet.idx[i];
    const double ca = meet.v[0][i], cb = meet.v[1][i], pa = meet.v[2][i], pb = meet.v[3][i];
    const double lo = std::min(pa, pb) - e, hi = std::max(pa, pb) + e;  // hi > 0 (the line test)
    const bool opposite = (ca > e && cb < -e) || (ca < -e && cb > e);
    bool crosses = opposite && lo > 0;
    if (opposite && !crosses) {
      // The piece spans t's perpendicular: the crossing's λ has the sign of cross(b − a, t − a)
      // when a is right of the ray (of its opposite when left): ahead, behind, or undecided.
      const double s = ca < 0 ? side_of_piece(k, tx, ty) : -side_of_piece(k, tx, ty);
      if (s < -B) continue;  // crosses the line behind t
      crosses = s > B;
    }
    if (crosses) U = std::min(U, hi);
    if (lo > U) continue;
    // From O's side (the piece's left) to its right: a strictly right of the ray, b strictly left.
    out.push_back(k | (crosses ? kInside | (ca < -e ? kFromO : 0u) : 0u)), los[kept++] = lo;
    // The winner's crossing value (nfp_value.cpp) reads the piece's line from pdd (two cache
    // lines, rarely cached: each query is usually on another pair): fetched now, while the
    // candidates are settled and t ∈ O is proved.
    __builtin_prefetch(&pdd[k].cx), __builtin_prefetch(&pdd[k].line_ok);
  }
  // Keep those still within the final U (in increasing index order).
  std::size_t w = first;
  for (std::size_t i = first; i < out.size(); ++i)
    if (los[i - first] <= U) out[w++] = out[i];
  out.resize(w);
}

}  // namespace pendepth::nonconvex2
