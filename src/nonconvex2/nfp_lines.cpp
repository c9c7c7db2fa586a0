// The per-pair no-fit polygon, σ's tie table (issue 19 item 1): the pieces grouped by the exact
// supporting line of their edges, built once with the fast path (NfpFlat::pline).
//
// Why: on nesting pieces two σ candidates often lie on one geometric line (pieces of two
// candidates from parallel edges of P and Q, overlapping along it) with t's projection inside
// both: the same point, an exact tie. same_point recognises it by collinear (edge_cut.hpp), whose
// two degree-2 signs are exact zeros no floating filter can certify, so each such comparison ran
// exact expansions per query (every one of the ~10⁵ candidate comparisons in the bench's albano
// and shirts σ queries; docs/benchmarks.md, "Thirteenth step"). With the table, two projections on
// pieces of one id are the same point by a lookup (nfp_query.cpp MinBest::consider).
//
// Contract: out[k] = out[j] only if pieces k and j have one exact supporting line (collinear, the
// exact test); collinear pieces may keep distinct ids where the filter below misses them (the
// query then compares exactly, as without the table: never a wrong answer, only the old cost).
// Method: each edge line's direction e = e1 − e0 (doubles) is folded to ex > 0 or (ex = 0, ey > 0)
// (one orientation per line), keyed by the pseudo-angle a = ey/(ex + |ey|) (monotone in the angle
// on that half-plane) and the offset h = (ex·cy − ey·cx)/(ex + |ey|) (c = c1 + c2, a point of the
// line). Exactly parallel directions are positive multiples after folding, so their keys differ by
// a few ulps (a: ~2⁻⁵⁰; h: ~2⁻⁴⁸·M, M the largest |c|) — far inside the windows taken, 2⁻³⁰ and
// 2⁻³⁰·M. Pieces sorted by a; each pair within both windows and not yet in one group is tested
// exactly and merged (union–find: one geometric line is an equivalence class, so merging is
// exact). The exact test: where the directions and the points' difference are exact doubles
// (integer-like data), the two degree-2 signs by exact::sign_ab_minus_cd (equal products compared
// by their FMA residuals); else edge_cut.hpp's collinear (symbolic same_line, then exact signs,
// whose exact zeros need expansions).
// Cost: O(N log N) for N ≤ 256 pieces (the fast path's bound), plus O(N·w) key comparisons for w
// lines within the angle window (parallel edges: axis-parallel ones on nesting pieces) and one
// exact test per merge or near miss.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "geometry/exact.hpp"
#include "nonconvex2/nfp_impl.hpp"

namespace pendepth::nonconvex2 {

namespace {

// collinear(l, m) (edge_cut.hpp) decided on doubles where the lines' directions e1 − e0 and the
// difference of their points c1 + c2 are exact doubles (integer-like data): the two degree-2 signs
// by exact::sign_ab_minus_cd (equal products compared by their FMA residuals). Else (or a residual
// out of range) collinear itself.
bool collinear_exact_doubles(const Line& l, const Line& m) {
  using exact::FlX;
  auto d = [](const Vec2& a, const Vec2& b, int i) { return FlX{a[i]} - FlX{b[i]}; };
  const FlX lx = d(l.e1, l.e0, 0), ly = d(l.e1, l.e0, 1), mx = d(m.e1, m.e0, 0), my = d(m.e1, m.e0, 1);
  const FlX wx = FlX{m.c1.x()} + FlX{m.c2.x()} - FlX{l.c1.x()} - FlX{l.c2.x()};
  const FlX wy = FlX{m.c1.y()} + FlX{m.c2.y()} - FlX{l.c1.y()} - FlX{l.c2.y()};
  const int par = exact::sign_ab_minus_cd(lx, my, ly, mx);
  if (par == 0) {
    if (const int on = exact::sign_ab_minus_cd(lx, wy, ly, wx); on != 2) return on == 0;
  } else if (par != 2) {
    return false;
  }
  return collinear(l, m);
}

}  // namespace

void build_lines(const NoFitPolygon2::Impl& N, const std::vector<NfpFlat::PieceDD>& pdd, std::vector<std::uint32_t>& out) {
  const std::size_t n = N.pieces.size();
  // Scratch reused per thread (no allocation per build but the output).
  thread_local std::vector<double> a, h;
  thread_local std::vector<std::uint32_t> order;  // the pieces with a key (a degenerate direction keeps its own id)
  a.resize(n), h.resize(n), order.clear();
  double M = 0;
  for (std::size_t k = 0; k < n; ++k) {
    // The rounded e1 − e0 and c1 + c2 from the compact per-piece table (the pieces' records are
    // large: one more pass over them costs more than the keys).
    const NfpFlat::PieceDD& v = pdd[k];
    double ex = v.ex, ey = v.ey;
    const double cx = v.cx, cy = v.cy;
    if (ex < 0 || (ex == 0 && ey < 0)) ex = -ex, ey = -ey;
    M = std::max({M, std::abs(cx), std::abs(cy)});
    const double norm = ex + std::abs(ey);
    if (!(norm > 0 && std::isfinite(norm))) continue;
    a[k] = ey / norm, h[k] = (ex * cy - ey * cx) / norm;
    if (std::isfinite(h[k])) order.push_back(std::uint32_t(k));
  }
  std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) { return a[i] < a[j] || (a[i] == a[j] && i < j); });
  out.resize(n);
  std::iota(out.begin(), out.end(), 0u);
  auto find = [&](std::uint32_t k) {
    while (out[k] != k) k = out[k] = out[out[k]];
    return k;
  };
  const double wa = 0x1p-30, wh = 0x1p-30 * M;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::uint32_t p = order[i];
    for (std::size_t j = i + 1; j < order.size() && a[order[j]] - a[p] <= wa; ++j) {
      const std::uint32_t q = order[j];
      if (!(std::abs(h[q] - h[p]) <= wh)) continue;
      const std::uint32_t rp = find(p), rq = find(q);
      if (rp != rq && collinear_exact_doubles(N.pieces[p].edge, N.pieces[q].edge)) out[std::max(rp, rq)] = std::min(rp, rq);
    }
  }
  for (std::size_t k = 0; k < n; ++k) out[k] = find(std::uint32_t(k));
}

}  // namespace pendepth::nonconvex2
