// Private: the implicit boundary ∂O of the overlap set O = ∪ int R_i, R_i = T_i ⊕ B, B = −Q
// (DHS §4.1 Step 3, Facts 4.1-4.2), and the exact primitives the queries (and the fixed direction
// sets of §6) are built on.
//
// Contract
//   O = int P ⊕ int B (open); ∂O = closure(O) \ O. Every point of ∂O lies on the reduced
//   convolution of ∂P with B (a contact placement of Q against P with disjoint interiors): either
//     - a SEGMENT: a P edge g → next(g) translated by b_k, the vertex of B extreme in the edge's
//       outward normal (ties: the tail of B's parallel edge, as in R_i's edge order), or
//     - an ARC: a P vertex v translated by the chain of B edges whose angles lie in
//       [angle(e_in), angle(e_out)) (e_in, e_out the P edges at v; non-empty only at convex
//       vertices of P's interior angle < π).
//   ∂O = those candidates minus (a) their points inside some int R_j, (b) for coinciding pieces
//   of the same orientation (two translates lying on one line, O on the same side) the copy with
//   the larger candidate id. What remains is a list of PIECES, each a closed sub-piece of one
//   candidate: a sub-segment, or a sub-arc (a contiguous B-edge range, first and last edge cut).
//   Every piece is oriented with O on its left (P's rings are CCW outer / CW holes, so candidates
//   are oriented that way already).
//
// Degenerate parts of ∂O (documented choice): where Q fits a pocket exactly, ∂O has SLITS —
// points of ∂O with O on both sides. They are two pieces of opposite orientation on the same line
// (both kept: the left side of each is in O). Where Q fits a hole exactly, ∂O has an isolated
// point: a zero-length piece (start == end) forming a ring on its own. A zero-length remnant that
// coincides with an endpoint of a non-degenerate piece is dropped (it adds no point).
//
// Rings: pieces are linked end → start into closed rings (exact equality of symbolic endpoints).
// At a union vertex with several outgoing pieces (O pinched, slit ends) the outgoing piece whose
// initial direction is first clockwise from the reversed incoming direction is taken, so each
// ring bounds one face of O locally. Outer rings are counter-clockwise (positive signed area);
// holes of O clockwise; a slit-only or single-point ring has area 0 (`Ring::area_sign` = 0).
//
// Symbolic points: a piece end lies on a straight ELEMENT (the segment, or one B edge of an arc),
// whose line is a `Cut` (point pt + pb, direction e1 − e0). It is either the element's natural end
// (μ = 0: pt + pb, μ = 1: pt + pb + e1 − e0 — a vertex p + b of the convolution) or the
// intersection of the element's line with another Cut's line. Nothing is rounded: every decision
// is an exact predicate on the input doubles (exact::exact_sign; GMP fallback automatic); values
// (λ, distances, coordinates) are evaluated to a few ulps.
//
// Space: pieces and rings are O(n) (Facts 4.1-4.2: ∂O has O(n) vertices for a triangulated P of
// n vertices against convex Q), each O(1) words; B is shared (O(m)); the bounding-volume
// hierarchies over the pieces and over the R_i are O(n). Arcs are never expanded.
#pragma once

#include <pendepth/polygon.hpp>

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "polygon2/convolved_triangles.hpp"

namespace pendepth::polygon2 {

/// One end of a piece: a point on the piece's first (start) or last (end) element, given by its
/// parameter μ on the element's line pt + pb + μ·(e1 − e0).
struct EndPoint {
  enum class Kind : std::uint8_t {
    Mu0,       ///< μ = 0: the element's natural start, the convolution vertex pt + pb
    Mu1,       ///< μ = 1: the element's natural end, pt + pb + e1 − e0
    Crossing,  ///< the element's line ∩ other's line (never parallel)
    Point      ///< the convolution vertex p + b, lying on the element's line (where two
               ///< same-orientation pieces overlap, the end of the kept copy)
  };
  Kind kind = Kind::Mu0;
  Cut other;                        ///< Crossing
  Vec2 p{0, 0}, b{0, 0};            ///< Point
  std::uint32_t p_index = 0, b_index = 0;  ///< Point: P and B indices of p, b
};

struct Piece {
  enum class Kind : std::uint8_t { Segment, Arc };
  Kind kind = Kind::Segment;
  std::uint32_t p = 0;   ///< Segment: P edge p → P.next(p); Arc: the P vertex p
  std::uint32_t b0 = 0;  ///< Segment: the B vertex translating the edge; Arc: first B edge (b0 → b0+1)
  std::uint32_t b1 = 0;  ///< Segment: = b0; Arc: last B edge (cyclic range b0..b1, fewer than m edges)
  std::uint32_t candidate = 0;  ///< candidate id (segments 0..N-1 by P edge, arcs N + P vertex)
  EndPoint start, end;   ///< on element 0 / on the last element
  std::uint32_t ring = 0;           ///< ring index
  std::uint32_t next = 0, prev = 0; ///< neighbours in the ring (end of this = start of next)
};

/// A closed boundary cycle of O: pieces first, next(first), ... (count of them).
struct Ring {
  std::uint32_t first = 0, count = 0;
  int area_sign = 0;  ///< +1 outer (CCW), -1 hole of O (CW), 0 degenerate (slit or point only)
};

/// A point where a line meets a piece: either the crossing of the line with element `cut`'s line,
/// or (when the line runs along an element, or passes through its natural end) the explicit
/// convolution vertex p + b.
struct Hit {
  bool is_point = false;
  Cut cut;        ///< the element crossed (is_point: the element containing the point)
  Vec2 p{0, 0}, b{0, 0};  ///< is_point: the point p + b (p a vertex of P, b a vertex of B)
  std::uint32_t piece = 0;
  std::uint32_t b_index = 0;  ///< is_point: B index of b
  std::uint32_t p_index = 0;  ///< is_point: P index of p
};

/// Exact sign of λ(h) on the line t + λ·d.
int hit_sign(const Hit& h, const Vec2& t, const Vec2& d);
/// Exact comparison of λ(a), λ(b) on the line t + λ·d: -1, 0, +1.
int compare_hits(const Hit& a, const Hit& b, const Vec2& t, const Vec2& d);
/// λ(h) to a few ulps.
double hit_value(const Hit& h, const Vec2& t, const Vec2& d);

/// The nearest point of a piece to a placement t: the foot of t on an element, an explicit
/// convolution vertex p + b, or the crossing of two lines (a union vertex). Compared exactly.
struct Near {
  enum class Kind : std::uint8_t { Foot, Point, Crossing } kind = Kind::Foot;
  Cut cut;    ///< Foot: the element; Point: the element containing the point; Crossing: first line
  Cut other;  ///< Crossing: the second line
  Vec2 p{0, 0}, b{0, 0};                   ///< Point: p + b; Foot: p = the placement t
  std::uint32_t p_index = 0, b_index = 0;  ///< Point: indices into P and B
  std::uint32_t piece = 0;
};
/// Exact comparison of |x(a) − t|² and |x(b) − t|².
int compare_near(const Near& a, const Near& b, const Vec2& t);
/// |x(n) − t| to a few ulps, and x(n) rounded.
double near_distance(const Near& n, const Vec2& t);
Vec2 near_point(const Near& n);

class UnionBoundary {
 public:
  /// Builds ∂O for the convolved triangles of P (see the file header). Throws nothing beyond
  /// allocation failures (inputs are validated by Polygon / ConvexPolygon). Keeps pointers to P
  /// and R: both must outlive the structure and stay in place (PolygonDepth2::Impl holds all three).
  /// `nearest_first` = false disables the output-sensitive parts of step 2 — the first pass and
  /// the chain hierarchy's pruning (every candidate gathers every sausage in reach, the method
  /// before them, O(N²) on a star or a finely sampled spiral): the same pieces bit for bit,
  /// slower; kept as the reference of tests/polygon2/test_union_nearest.cpp.
  UnionBoundary(const Polygon& P, const ConvolvedTriangles& R, bool nearest_first = true);
  ~UnionBoundary();
  UnionBoundary(UnionBoundary&&) noexcept;
  UnionBoundary& operator=(UnionBoundary&&) noexcept;

  const std::vector<Piece>& pieces() const { return pieces_; }
  const std::vector<Ring>& rings() const { return rings_; }
  /// Number of straight elements of piece k (1 for a segment, the B-edge count for an arc).
  std::size_t element_count(std::size_t k) const;
  /// Element j (0-based) of piece k as a Cut; its portion on the piece is [start, end] for
  /// j = 0 / last, the whole element (μ ∈ [0, 1]) otherwise.
  Cut element(std::size_t k, std::size_t j) const;
  /// Start / end point of piece k, rounded (a few ulps).
  Vec2 start_point(std::size_t k) const;
  Vec2 end_point(std::size_t k) const;
  /// Start / end point of piece k exactly (rational coordinates; for tests and export).
  std::array<mpq_class, 2> exact_start(std::size_t k) const;
  std::array<mpq_class, 2> exact_end(std::size_t k) const;
  /// Conservative axis-aligned box of piece k (padded so that exact points never fall outside).
  std::array<double, 4> box(std::size_t k) const;  ///< xmin, ymin, xmax, ymax

  /// Every point where the LINE t + λ·d (d ≠ 0) meets piece k, λ of any sign, appended to out
  /// (at most 2 for a piece running across; where the line contains a straight element, the two
  /// ends of that element's portion). O(log m).
  void line_hits(std::size_t k, const Vec2& t, const Vec2& d, std::vector<Hit>& out) const;
  /// The first λ > 0 on the ray t + λ·d meeting piece k (false if none). O(log m).
  bool first_hit(std::size_t k, const Vec2& t, const Vec2& d, Hit& h) const;
  /// The first point of ∂O on the ray t + λ·d, λ > 0, with the bounding-volume hierarchy
  /// (false if the ray misses ∂O). O(log n · log m) typical. With `tie`: set to whether another
  /// piece meets the ray at the same point as h (a union vertex, a slit); h is the same either way.
  bool ray_first(const Vec2& t, const Vec2& d, Hit& h, bool* tie = nullptr) const;
  /// The same by visiting every piece, O(n log m) (DHS §4.2).
  bool ray_first_scan(const Vec2& t, const Vec2& d, Hit& h) const;
  /// The nearest point of piece k to t (exact choice among candidates).
  Near nearest_on_piece(std::size_t k, const Vec2& t) const;
  /// The nearest point of ∂O to t, branch-and-bound on the hierarchy (false if ∂O is empty).
  bool nearest(const Vec2& t, Near& n) const;

  /// Exact: t ∈ O (some int R_i contains t), with the hierarchy over the R_i. O(log n + k log m).
  bool in_overlap(const Vec2& t) const;
  /// Exact: t ∈ ∂O (t lies on some piece), with the hierarchy over the piece boxes containing t.
  bool on_boundary(const Vec2& t) const;
  /// The last exit sup{λ ≥ 0 : t + λ·d ∈ O} as the exit cut of some R_i (false when the ray
  /// never meets O after 0), branch-and-bound over the R_i (§6).
  bool last_exit(const Vec2& t, const Vec2& d, Cut& exit) const;

  /// Heap bytes of the structure: pieces, rings, hierarchies.
  std::size_t bytes() const;
  std::size_t segment_count() const;
  std::size_t arc_count() const;
  /// Distinct explicit vertices (piece ends; a ring's shared ends counted once).
  std::size_t vertex_count() const;
  /// Candidates the nearest-first pass found entirely inside O (construction statistics).
  std::size_t covered_early() const { return covered_early_; }
  /// Chain-hierarchy nodes and P edges whose sausages the separation tests proved to miss a
  /// segment candidate (construction statistics; 0 with nearest_first = false).
  std::size_t chain_pruned() const { return chain_pruned_; }

  struct Index;  ///< bounding-volume hierarchies (private)

 private:
  // Construction steps 3-5 (union_boundary.cpp; steps 1-2 produce pieces_ from the candidates).
  /// Conservative box of piece k (box(k) once the index exists).
  std::array<double, 4> piece_box_of(std::size_t k) const;
  /// Step 3: sp, ep := the rounded start / end of every piece, zero := whether it has zero length;
  /// then drops each zero-length piece whose point lies on another piece (exact), keeping the
  /// three lists aligned with pieces_.
  void drop_covered_points(std::vector<Vec2>& sp, std::vector<Vec2>& ep, std::vector<char>& zero);
  /// Step 4: links every piece's end to a piece starting there (exact symbolic equality; the
  /// clockwise-first continuation where there are several), reorders pieces_ ring by ring (sp, ep
  /// follow) and sets rings_ with the next / prev links.
  void link_rings(std::vector<Vec2>& sp, std::vector<Vec2>& ep, const std::vector<char>& zero);
  /// Every ring's area sign: floating with an error bound, exact (rationals) when undecided.
  void orient_rings(const std::vector<Vec2>& sp, const std::vector<Vec2>& ep);
  /// Step 5: the piece boxes and the hierarchy over them.
  void index_pieces();

  const Polygon* P_ = nullptr;
  const ConvolvedTriangles* R_ = nullptr;
  std::vector<Piece> pieces_;
  std::vector<Ring> rings_;
  std::unique_ptr<Index> index_;
  std::size_t covered_early_ = 0;
  std::size_t chain_pruned_ = 0;
};

}  // namespace pendepth::polygon2
