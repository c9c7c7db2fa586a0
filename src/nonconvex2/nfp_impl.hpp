// Private: the stored no-fit polygon (nfp2.hpp): the uncovered closed pieces of the reduced-
// convolution candidates (exact, symbolic), a box hierarchy over them, and the exported rings.
#pragma once

#include <pendepth/nfp2.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "nonconvex2/edge_cut.hpp"
#include "nonconvex2/pair_sums.hpp"

namespace pendepth {

namespace nonconvex2 {

/// One uncovered closed piece [lo, hi] (μ on E, lo ≤ hi exactly) of a candidate E, an edge of a
/// pair sum whose line is `edge`; O lies on its left. A zero-length piece is a single point.
struct NfpPiece {
  Ray E;
  Line edge;
  Param lo, hi;
  Vec2 a, b;      // the ends, each coordinate to a few ulps
  Vec2 blo, bhi;  // conservative box of the exact piece
};

/// A reduced-convolution candidate (nfp_build.cpp step 1): the symbolic edge ray E from sum
/// vertex (p0, q0) to (p1, q1) (μ ∈ [0, 1]), its line, its ends A = E(0), B = E(1) each rounded
/// once, and a conservative box.
struct NfpCandidate {
  Ray E;
  Line line;
  Vec2 A, B, lo, hi;
  bool strict = false;  // the candidate's vertex is strictly convex (not a straight vertex)
  // Its points all lie on other, non-redundant candidates collinear with it (the second path of a
  // pair of parallel edges, nfp_candidates): it only splits others, is never classified itself and
  // gives no piece.
  bool redundant = false;
};

/// The candidates of P ⊕ (−Q) (nfp_build.cpp): O(nm) exact orientation tests; the redundant ones
/// marked.
std::vector<NfpCandidate> nfp_candidates(const Polygon& P, const Polygon& Q);

/// Appends the uncovered closed pieces of candidate c, in increasing μ, found by cutting c with
/// every open pair sum that can meet it (nfp_cut.cpp). The reference method: the builder uses
/// nfp_classify, which falls back to this per candidate.
void nfp_cut(const PairDepth2::Impl& S, const NfpCandidate& c, std::vector<NfpPiece>& out);

/// Appends the uncovered closed pieces of every candidate, candidate by candidate in order, the
/// same pieces as nfp_cut, found by splitting each candidate where other candidates meet it and
/// testing one point per part (nfp_classify.cpp).
void nfp_classify(const PairDepth2::Impl& S, const std::vector<NfpCandidate>& cands, std::vector<NfpPiece>& out);

/// nfp_classify's step 0 on large shapes (trim_deep: the parts of candidates certified in O are
/// left out of the pairing, candidates certified whole give no piece), per thread, for the tests:
/// nfp_trim_mode() = kTrimOff classifies without it (the reference they compare with), kTrimAuto
/// (the default) where candidates are crowded, kTrimAll on every candidate of a large pair (the
/// tests, to exercise it on every input); nfp_trim_stats() accumulates candidates certified whole
/// (dead), trimmed, and pairs met.
struct NfpTrimStats {
  std::size_t dead = 0, trimmed = 0, meets = 0;
  std::size_t dop_pruned = 0;  // node pairs of the pieces' descent pruned by their k-DOPs, not by their boxes
  std::size_t swept = 0, tree_joins = 0;  // pairs (K > 64) whose step 1 found its pairs by the sweep / the box tree
};
constexpr int kTrimOff = 0, kTrimAuto = 1, kTrimAll = 2;
int& nfp_trim_mode();
NfpTrimStats& nfp_trim_stats();

/// nfp_classify's k-DOP pruning of the pieces' dual descent on large shapes (nfp_classify.cpp,
/// PieceDop), per thread, for the tests: kDopOn (the default), kDopOff (boxes only, the method
/// before it: the reference they compare with), kDopPlanted (a wrong margin the tests must catch).
constexpr int kDopOff = 0, kDopOn = 1, kDopPlanted = 2;
int& nfp_dop_mode();

/// How nfp_classify's step 1 finds the box-overlapping candidate pairs when K > 64, per thread,
/// for the tests: kPairsAuto (the default) by a sort-and-sweep on x within a budget of tests, else
/// by the box tree; kPairsTree always by the box tree (the method before the sweep: the reference
/// they compare with). Either way the pairs meet in canonical order, so the output is the same.
constexpr int kPairsAuto = 0, kPairsTree = 1;
int& nfp_pairs_mode();

/// One ring and no right turn (straight vertices allowed): a convex polygon (exact turns).
bool convex_shape(const Polygon& S);

/// The piece [lo, hi] of candidate c with its rounded ends and box.
NfpPiece make_piece(const NfpCandidate& c, const Param& lo, const Param& hi);
/// The same with its ends a, b given (each coordinate to a few ulps of the exact end).
NfpPiece make_piece(const NfpCandidate& c, const Param& lo, const Param& hi, const Vec2& a, const Vec2& b);

}  // namespace nonconvex2

namespace nonconvex2 {

/// The floating fast path of the queries (nfp_fast.cpp): a flat structure-of-arrays copy of ∂O in
/// doubles whose decisions are certified by static error bounds, or reported undecided so the
/// caller runs the exact path. Ring edges: the export's rings (each vertex the exact vertex rounded
/// to nearest); piece ends: NfpPiece::a, b (each coordinate within a few ulps of the exact end).
struct NfpFlat {
  std::vector<double> rx0, ry0, rx1, ry1;  // ring edges of cl(O), O on their left
  // Above kSlabMin ring edges: horizontal slabs of equal height over the rings' y range, slab s
  // holding (copies of) every edge whose y range meets it, edges of slab s at [slab[s], slab[s+1]).
  std::vector<std::uint32_t> slab;
  double ylo = 0, yhi = 0, yscale = 0;
  bool overlap_usable = false;  // the overlap filter applies (magnitudes in range), any size
  std::vector<double> px0, py0, px1, py1;  // pieces (same indices as Impl::pieces)
  std::vector<double> pex, pey;            // b − a per piece (rounded)
  std::vector<double> pinv;                // 1 / |b − a|² per piece (0 for a point)
  std::vector<std::array<Vec2, 2>> slits;   // copies of the export's, next to the edges
  std::vector<Vec2> points;
  std::vector<std::array<std::int32_t, 2>> wedge;  // Impl::wedge (reflex vertices at the pieces' ends)
  double rmax = 0;                         // largest |coordinate| stored here
  bool usable = false;                     // sizes and magnitudes inside the filters' range
  // Per piece: its edge ray's origin o = o1 + o2 and direction (a1 + a2) − (b1 + b2) as exact
  // double-doubles (hi, lo), |dir|² as a double-double to 2⁻⁹⁹ relative; ok false when dir is not
  // exactly two doubles or magnitudes are out of the fast value's range (nfp_value.cpp).
  struct PieceDD {
    double ox, oxl, oy, oyl, dx, dxl, dy, dyl, dd, ddl;
    // 1/|D|² as a double-double (ddinv + ddinvl) within 2⁻⁹⁶ relative (nfp_value.cpp's header).
    double ddinv = 0, ddinvl = 0;
    // o × D = ox·Dy − oy·Dx as a double-double (k + kl) within ke (σ's projection: c = t × D − o × D).
    double k = 0, kl = 0, ke = 0;
    bool ok = false;
    // The sum vertex o + D (μ = 1) exactly as a double-double, when v1_ok (σ's vertex_values).
    double v1x = 0, v1xl = 0, v1y = 0, v1yl = 0;
    bool v1_ok = false;
    // The edge line's point c1 + c2 and direction e1 − e0, exact double-doubles (σ_d's crossing).
    double cx, cxl, cy, cyl, ex, exl, ey, eyl;
    bool line_ok = false;
  };
  std::vector<PieceDD> pdd;
  // Per piece, its lo and hi ends when they are cut points (the crossing of the edge with another
  // candidate's line: O's reflex vertices; sum vertices are exact in pdd): each coordinate a
  // double-double (x + xl) within ex of the exact end, ex = 0 when exact (end_dd, nfp_value.cpp);
  // ok false for sum vertices and where the double-double tier could not bound an end.
  struct EndDD {
    double x = 0, xl = 0, ex = 0, y = 0, yl = 0, ey = 0;
    bool ok = false;
  };
  std::vector<std::array<EndDD, 2>> pend;
  // Per piece, when usable: an id of its edge's supporting line (build_lines, nfp_lines.cpp); one
  // id only for one exact geometric line (collinear pieces the grouping's filter missed keep
  // distinct ids). σ's winner search takes two projections on pieces of one id as a tie by this
  // lookup (nfp_query.cpp MinBest) instead of same_point's exact zero tests.
  std::vector<std::uint32_t> pline;
  bool one_line(std::uint32_t i, std::uint32_t j) const { return pline[i] == pline[j]; }

  void build(const NoFitPolygon2::Impl& nfp);
  std::size_t slab_of(double y, std::size_t count) const;
  /// t ∈ O: 1 or 0 when certified, -1 when a decision is too close to call (t on or ulps from a
  /// ring edge, a slit, an isolated point, or level with a ring vertex).
  int overlapping(const Vec2& t) const;
  /// Flag on a candidate index (indices stay below it): certified interior case (below).
  static constexpr std::uint32_t kInside = 1u << 31;
  /// Flags of nearest_candidates: t's projection on the piece's line falls certainly strictly
  /// before its lo end (kBeforeLo) or beyond its hi end (kBeyondHi), so its nearest point is that end.
  static constexpr std::uint32_t kBeforeLo = 1u << 30, kBeyondHi = 1u << 29;
  /// t certainly strictly on O's side (the left) of the piece's line (nearest_candidates, with
  /// kInside), or the ray certainly crossing the piece from O's side (first_hit_candidates).
  static constexpr std::uint32_t kFromO = 1u << 28;
  static constexpr std::uint32_t kFlags = kInside | kBeforeLo | kBeyondHi | kFromO;
  /// t ∈ O certified by σ's or σ_d's candidates alone, without the overlap test: one candidate,
  /// t's nearest point on ∂O (or the ray's first) strictly inside it, O's side towards t (proof in
  /// nfp_fast.cpp). False says nothing (the caller runs the overlap test).
  static bool inside_by_candidates(const std::vector<std::uint32_t>& cand) {
    return cand.size() == 1 && (cand[0] & (kInside | kFromO)) == (kInside | kFromO);
  }
  /// Candidates all meeting at one reflex vertex V of O (`wedge`): t's projection certainly
  /// beyond the hi end of each arriving at V, before the lo end of each leaving it, or a
  /// zero-length piece at V. Then V is every candidate's nearest point (all tie: σ's winner is the
  /// first, the lowest index) and t ∈ O (proof in nfp_fast.cpp). False says nothing.
  bool at_wedge(const std::vector<std::uint32_t>& cand) const {
    if (cand.size() < 2 || wedge.empty()) return false;
    std::int32_t V = -1;
    for (std::uint32_t c : cand) {
      const auto& w = wedge[c & ~kFlags];
      // Unflagged: only a zero-length piece (both ends one vertex) has its nearest point known.
      const std::int32_t at = (c & kBeyondHi) ? w[1] : (c & kBeforeLo) ? w[0] : (c & kFlags) == 0 && w[0] == w[1] ? w[0] : -1;
      if (at < 0 || (V >= 0 && at != V)) return false;
      V = at;
    }
    return true;
  }
  /// σ's proof of t ∈ O: inside_by_candidates or at_wedge.
  bool inside_by_nearest(const std::vector<std::uint32_t>& cand) const { return inside_by_candidates(cand) || at_wedge(cand); }
  /// Appends to `out`, in increasing order, the indices of every piece whose exact distance to t
  /// can be the minimum (a superset of the exact nearest pieces; usually one), flagged kInside when
  /// t's projection on the piece's line falls certainly strictly inside the piece, kBeforeLo or
  /// kBeyondHi when certainly outside it.
  void nearest_candidates(const Vec2& t, std::vector<std::uint32_t>& out) const;
  /// Appends, in increasing order, every piece the ray t + λ·d (λ > 0) can hit first (a superset
  /// of the exact first pieces), flagged kInside when the ray certainly crosses the piece's
  /// interior at some λ > 0 (the piece's ends strictly on either side of the ray's line).
  void first_hit_candidates(const Vec2& t, const Vec2& d, std::vector<std::uint32_t>& out) const;
  /// cross(b − a, t − a) of piece k in doubles (from the rounded b − a): within 2⁻⁴⁰·M² of the
  /// exact piece's (M = max(|t|∞, rmax); nfp_fast.cpp's header), so beyond that bound t is
  /// certainly strictly left (> 0) or right (< 0) of the piece's line.
  double side_of_piece(std::size_t k, double tx, double ty) const { return pex[k] * (ty - py0[k]) - pey[k] * (tx - px0[k]); }
  /// σ² and the translation from t to its projection on piece k's edge line, each RN(exact)
  /// (geometry/rounded.hpp), from the piece's double-doubles with a static error bound
  /// (nfp_value.cpp); false (nothing certified) when a value is too close to a rounding midpoint
  /// or out of range: the caller then takes the generic rounded evaluation.
  /// `diag` (tests): the double-double values σ², X − t (x, y) and their error bounds, before the
  /// rounding check (set when the bounds were computed, i.e. when the range checks passed).
  struct ProjectionDiag {
    double hi[3], lo[3], bound[3];
    bool set = false;
    double scale[2] = {1, 0};  // crossing_value: num and den are N and D divided by scale[0] + scale[1]
  };
  bool projection_values(std::uint32_t k, const Vec2& t, double& sigma2, Vec2& translation, ProjectionDiag* diag = nullptr) const;
  /// σ² and the translation from t to the end μ = `end` (0 or 1) of piece k's edge ray (a vertex
  /// of a pair sum: o, or o + D), each RN(exact), from the piece's double-doubles with a static
  /// error bound (nfp_value.cpp); false when not certified. `diag` as for projection_values.
  bool vertex_values(std::uint32_t k, int end, const Vec2& t, double& sigma2, Vec2& translation, ProjectionDiag* diag = nullptr) const;
  /// The same at piece k's lo (end 0) or hi (end 1) end when it is a cut point, from pend (built
  /// once with the no-fit polygon); false when not certified or not a tabled end.
  bool end_values(std::uint32_t k, int end, const Vec2& t, double& sigma2, Vec2& translation, ProjectionDiag* diag = nullptr) const;
  /// RN(λ) of the crossing of the ray t + λ·d with piece k's edge line (line_num / line_den),
  /// from the piece's double-doubles with a static error bound; false when not certified. `diag`
  /// (tests): q, the residual r̃ and the denominator (hi, lo) in hi / lo, E and the denominator's
  /// bound in bound[1], bound[2], the scale of N and D in scale (an axis-parallel edge's ±E).
  bool crossing_value(std::uint32_t k, const Vec2& t, const Vec2& d, double& lambda, ProjectionDiag* diag = nullptr) const;
};

}  // namespace nonconvex2

namespace nonconvex2 {
/// NfpFlat::pdd and pend for every piece (nfp_value.cpp); one piece's from its edge ray.
void build_values(const NoFitPolygon2::Impl& nfp, std::vector<NfpFlat::PieceDD>& out, std::vector<std::array<NfpFlat::EndDD, 2>>& ends);
NfpFlat::PieceDD piece_dd(const Ray& E, const Line* edge = nullptr);
/// NfpFlat::pline for every piece (nfp_lines.cpp): pieces on one exact line share an id; pdd the
/// pieces' PieceDD (build_values: the keys' rounded edge lines).
void build_lines(const NoFitPolygon2::Impl& nfp, const std::vector<NfpFlat::PieceDD>& pdd, std::vector<std::uint32_t>& out);
/// NfpFlat::pend's entry for the point at parameter p of E, v = piece_dd(E) (ok false for μ = 0, 1,
/// a projection, or when v is not ok).
NfpFlat::EndDD end_dd(const Ray& E, const Param& p, const NfpFlat::PieceDD& v);
/// Whether NfpFlat's values use the FMA instruction (default: when the processor has it); the same
/// doubles either way. Tests set it to run both builds.
bool& nfp_values_fma();
}  // namespace nonconvex2

struct NoFitPolygon2::Impl {
  PairDepth2::Impl S;  // triangulations, box hierarchies, the exact overlap test and contact()
  std::vector<nonconvex2::NfpPiece> pieces;
  nonconvex2::BoxTree tree;  // over the piece boxes (leaf `tri` = piece index)
  std::vector<std::vector<std::vector<Vec2>>> polys;
  std::vector<std::array<Vec2, 2>> slits;
  std::vector<Vec2> points;
  // Per piece: the vertex id of a reflex vertex of O at its lo end and at its hi end (both for a
  // zero-length piece there), else -1 (nfp_export, nfp_rings.cpp link_wedges: the pieces at such a
  // vertex arrive along one direction and leave along another, turning strictly right); empty when
  // no piece has one (the convex export). σ's fast path proves t ∈ O by such a wedge
  // (NfpFlat::inside_by_nearest, nfp_fast.cpp).
  std::vector<std::array<std::int32_t, 2>> wedge;
  NfpSize sz;
  nonconvex2::NfpFlat flat;  // the fast path (built last, from pieces and rings)
  Impl(const Polygon& P, const Polygon& Q);
  /// From shared per-shape sides (shape_side.hpp: p made with negate false, q with true); the
  /// same bits as Impl(p->shape, q->shape). `queries` false: only the export (polys, slits,
  /// points) is made, not the query structures (tree, flat): for callers that only read the rings.
  Impl(std::shared_ptr<const nonconvex2::ShapeSide> p, std::shared_ptr<const nonconvex2::ShapeSide> q, bool queries = true);

  // Queries on validated input (only when built with queries) (nfp_query.cpp). The plain ones take the certified floating fast
  // path and run the exact decisions only where it is undecided; the `_exact` ones (kept for the
  // tests, which compare the two bit for bit) skip it: the pair-sum overlap test and the best-first
  // traversal of the piece hierarchy. Among pieces exactly equally near (a shared vertex), both
  // report the lowest piece index.
  bool overlapping(const Vec2& t) const;
  bool overlapping_exact(const Vec2& t) const;
  Depth2 minimum(const Vec2& t, bool exact_path = false) const;
  Depth2 along(const Vec2& t, const Vec2& d, bool exact_path = false) const;  // d from check_and_scale
  // The lean queries: the same winner and values as minimum / along, no contact features.
  DepthValue2 minimum_value(const Vec2& t, bool exact_path = false) const;
  DepthValue2 along_value(const Vec2& t, const Vec2& d, bool exact_path = false) const;  // d scaled
};

/// Links the pieces into rings, slits and isolated points (nfp_rings.cpp).
void nfp_export(NoFitPolygon2::Impl& nfp);
/// The export when the pieces are whole candidates bounding a convex sum (two convex shapes):
/// the edges by angle, O(N log N) exact angle comparisons; the same output as the general export.
/// False (nothing written) when the pieces are not of that form.
bool nfp_export_convex(NoFitPolygon2::Impl& nfp);

}  // namespace pendepth
