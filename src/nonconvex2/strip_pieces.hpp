// Private: convex pieces with Steiner points for the fans of a long edge (issue 19 item 4: a comb
// rotated by 45°, coordinates rounded). Used by the no-fit polygon classification's large path
// (nfp_classify.cpp make_pieces, through ShapeSide::pieces) before its own splitting.
//
// Why: without Steiner points, every convex piece holding a point inside a polygon edge AB holds
// both A and B. When the vertices facing AB are not exactly collinear (a rotated, rounded comb
// base), the Hertel–Mehlhorn parts fan O(n) long thin wedges to A and B, a point of the base meets
// O(n) of them (no box or k-DOP separates a thin wedge from the points beside it), and the
// classification's point tests turn quadratic. Here such a fan region is re-covered by one fat
// convex piece holding AB and one small piece per edge of the region's other boundary.
//
// Construction, for a boundary edge A → B whose end vertices lie on many parts (≥ kFanDegree
// together): R = the union of the parts at A or at B (except the parts holding P's other edges at
// A and at B, which keep end teeth out; the part holding AB always in), a simple region whose
// boundary is A → B and then a chain v_0 = B, v_1, …, v_K = A (diagonals cancelled). T0 is the
// trapezoid A, B, c_B, c_A (c_A = A + H·(u + n), c_B = B + H·(n − u); u along AB, n its left
// normal, H half the chain's least height over AB), and s_j (0 < j < K) points on T0's midline
// (height H/2) with decreasing abscissa, each on the inner side of both chain edges at v_j; s_0 = B,
// s_K = A. The pieces: T0 and Q_j = conv(v_j, v_{j+1}, s_{j+1}, s_j) (a triangle at either end).
// Every condition below is checked exactly (orient2d on doubles); when one fails the region keeps
// its parts, so the construction is only a heuristic in where it applies, never in what it gives.
// Checks: T0 strictly convex CCW; c_A, c_B inside R's angles at A, B; no chain edge meets T0's
// three sides other than AB (closed segments; collinear overlaps count as meeting); every s_j
// strictly inside T0; every Q_j strictly convex CCW.
// Proof that the pieces cover exactly R: ∂R = [A→B] + chain. Σ_j ∂Q_j = chain + (s_K → … → s_0)
// (the sides v_j → s_j cancel between neighbours) = ∂R − D, D = [A→B] + (s_0 → … → s_K) a closed
// curve inside the convex T0. Winding numbers: for x ∉ T0 not on a curve, Σ_j w(Q_j, x) =
// w(∂R, x) − w(D, x) = w(∂R, x), 1 inside R and 0 outside; each w(Q_j, x) ∈ {0, 1} (convex, CCW),
// so x ∈ int R \ T0 lies in some Q_j and no Q_j reaches outside R. T0 ⊂ R: the chain does not
// meet T0's other sides and starts at B outside T0's angle, so int T0 misses ∂R, and it holds
// points of R near B. So O (the union of the open sums of any decomposition into non-degenerate
// convex pieces covering P, overlaps allowed) and every exact decision are unchanged.
// Steiner vertices carry id kSteiner (never a vertex id: no symbolic test treats them as one).
// Cost: O(parts' size · log) for the edge pairing, O(|R|) per region tried.
#pragma once

#include <cstdint>

#include "nonconvex2/convex_parts.hpp"

namespace pendepth::nonconvex2 {

constexpr std::uint32_t kSteiner = ~std::uint32_t(0);

/// Tests: kStripOn (default), kStripOff (the parts as they are: the method before), kStripPlanted
/// (a wrong cover: two pieces Q_j left out, which the tests must catch). Per thread; read when a
/// ShapeSide makes its pieces.
constexpr int kStripOff = 0, kStripOn = 1, kStripPlanted = 2;
int& nfp_strip_mode();
/// Counters for the tests (per thread): regions replaced, and tried but kept (a check failed).
struct StripStats {
  std::size_t replaced = 0, kept = 0;
};
StripStats& nfp_strip_stats();

/// `out` = X with each fan region re-covered as above; false (out untouched) when none is.
bool strip_fans(const ConvexParts& X, ConvexParts& out);

}  // namespace pendepth::nonconvex2
