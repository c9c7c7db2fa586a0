// Private: the convolved triangles R_i = T_i ⊕ (−Q) of a triangulated polygon, kept implicit
// (DHS §4.1 Step 2, "Implicit Representation of the Convolved Triangles").
//
// B = −Q in normal form (b_0 lowest-leftmost, CCW, edge angles strictly increasing in [0, 2π)).
// Each triangle T (normal form v_0 lowest-leftmost, CCW) stores c_j = number of B edges whose
// angle is strictly smaller than that of its edge τ_j = v_{j+1} − v_j (three binary searches,
// O(log m)). The boundary of R = T ⊕ B is the merge of the three τ_j and the m edges of B in angle
// order (ties: τ first): τ_j sits at position j + c_j, and vertex k (k < m + 3) is
// v_α + b_{k−α}, α = #{j : j + c_j < k}. So any vertex or edge of R is available in O(1), and every
// point/line question on R is a binary search with exact predicates on the input doubles.
#pragma once

#include <pendepth/polygon.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "polygon2/triangulation.hpp"

namespace pendepth::polygon2 {

/// The line of one edge of some R_i, exactly: it passes through pt + pb (pt a vertex of P, pb a
/// vertex of B) with direction e1 − e0 (a triangle edge, or an edge of B). The ray t + λ·d meets it
/// at λ = cross(pt + pb − t, e1 − e0) / cross(d, e1 − e0).
struct Cut {
  Vec2 pt, pb, e0, e1;
  std::uint32_t tri = 0;   ///< triangle index
  std::uint32_t p_from = 0, p_to = 0;  ///< global P vertices: the triangle edge (P side) or p_from = p_to = the fixed vertex (B side)
  std::uint32_t b = 0;     ///< B vertex index of pb; for a B edge, the edge b → b+1
  bool b_edge = false;     ///< true: edge of −Q translated by a P vertex; false: triangle edge translated by a B vertex
};

/// Exact sign of λ(c) for the ray t + λ·d (d ≠ 0; c's line not parallel to d).
int cut_sign(const Cut& c, const Vec2& t, const Vec2& d);
/// Exact comparison of λ(a) and λ(b): -1, 0, +1.
int compare_cuts(const Cut& a, const Cut& b, const Vec2& t, const Vec2& d);
/// λ(c) to a few ulps.
double cut_value(const Cut& c, const Vec2& t, const Vec2& d);

/// The part of a line's direction d = d1 − d0 that does not depend on the triangle: the numbers of
/// B edges whose angle is <= / < angle(d) and <= / < angle(−d). One binary search each (O(1) for a
/// B edge); computed once per line and reused for every R_i and sausage it is cut with.
struct LineDir {
  Vec2 d0{0, 0}, d1{0, 0};
  std::array<std::uint32_t, 4> b{};  ///< B edges: <= d, < d, <= −d, < −d
};

class ConvolvedTriangles {
 public:
  /// Triangulates P (or takes `tris`, a triangulation of P: triangulate(P)'s triangles in its
  /// order, each possibly rotated — the per-shape one, src/front/shape2_data.hpp) and builds the
  /// implicit R_i. O(N log N + N log m); O(N log m) given the triangles.
  ConvolvedTriangles(const Polygon& P, const ConvexPolygon& Q, const std::vector<TriangleIds>* tris = nullptr);

  std::size_t size() const { return tri_.size(); }
  /// Vertices of B = −Q: b_j = −Q[(Q.top() + j) mod m].
  const std::vector<Vec2>& B() const { return b_; }
  std::size_t q_index(std::size_t j) const { return (q_top_ + j) % b_.size(); }
  /// Triangle i in normal form: global P vertex ids, v_0 lowest-leftmost, CCW.
  const TriangleIds& triangle(std::size_t i) const { return tri_[i].id; }
  /// Number of vertices (= edges) of R_i: m + 3.
  std::size_t vertex_count() const { return b_.size() + 3; }
  /// Vertex k of R_i as (triangle vertex slot 0..2, B index): its point is v_slot + b_index.
  void vertex(std::size_t i, std::size_t k, int& slot, std::size_t& bj) const;
  /// The line of edge k of R_i (from vertex k to k+1).
  Cut edge(std::size_t i, std::size_t k) const;

  /// Exact: is t in the interior of R_i? O(log m).
  bool contains_interior(std::size_t i, const Vec2& t) const;
  /// The open interval of λ where t + λ·d lies in int R_i: entry and exit cuts. Returns false
  /// when the line misses int R_i (including lines touching R_i only along its boundary). O(log m).
  bool line_interval(std::size_t i, const Vec2& t, const Vec2& d, Cut& entry, Cut& exit) const;
  /// The same for the line of a cut, pt + pb + μ·(e1 − e0): μ of entry/exit is the cut's λ
  /// with the line as the ray (used by the union boundary, DHS §4.1 Step 3). O(log m).
  bool line_interval(std::size_t i, const Cut& line, Cut& entry, Cut& exit) const;
  /// The direction data of the line of a cut (see LineDir).
  LineDir line_dir(const Cut& line) const;
  /// line_interval / segment_line_interval with the direction data precomputed (the same answers).
  bool line_interval(std::size_t i, const Cut& line, const LineDir& dir, Cut& entry, Cut& exit) const;
  bool segment_line_interval(std::size_t g, const Cut& line, const LineDir& dir, Cut& entry, Cut& exit) const;
  /// Conservative bounding box of R_i (xmin, ymin, xmax, ymax), padded for rounding.
  std::array<double, 4> box(std::size_t i) const;
  /// Heap bytes (triangles, edge sausages, fans and B).
  std::size_t bytes() const {
    return (tri_.capacity() + seg_.capacity()) * sizeof(Tri) + b_.capacity() * sizeof(Vec2) +
           (fan_.capacity() + fan_start_.capacity() + opp_lt_.capacity() + opp_le_.capacity()) * sizeof(std::uint32_t);
  }

  // The edge sausages S_g = f_g ⊕ B for the P edges f_g = (g, P.next(g)), implicit like the R_i
  // (a 2-gon instead of a triangle: m + 2 edges). For a placement x where Q + x is not inside P,
  // x ∈ O ⇔ x ∈ int S_g for some g (int(Q + x) then meets ∂P, hence some edge's relative interior).
  // Their boxes are small (|f_g| + |B|), unlike the R_i of long triangulation diagonals.
  std::size_t segment_count() const { return seg_.size(); }
  bool segment_contains_interior(std::size_t g, const Vec2& t) const;
  /// As line_interval; the returned cuts carry tri = g.
  bool segment_line_interval(std::size_t g, const Vec2& t, const Vec2& d, Cut& entry, Cut& exit) const;
  bool segment_line_interval(std::size_t g, const Cut& line, Cut& entry, Cut& exit) const;
  std::array<double, 4> segment_box(std::size_t g) const;
  /// Triangles incident to P vertex v.
  std::span<const std::uint32_t> triangles_at(std::size_t v) const {
    return std::span<const std::uint32_t>(fan_).subspan(fan_start_[v], fan_start_[v + 1] - fan_start_[v]);
  }

 private:
  struct Tri {
    TriangleIds id;
    std::array<Vec2, 3> v;
    std::array<std::uint32_t, 3> c;
    int n = 3;  ///< 3: triangle; 2: edge sausage (id[2], v[2], c[2] unused)
  };
  // Inline: the innermost step of every binary search on an R_i.
  void vertex_of(const Tri& T, std::size_t k, int& slot, std::size_t& bj) const {
    const std::size_t m = b_.size();
    if (k >= m + T.n) k %= m + T.n;
    int a = 0;
    while (a < T.n && a + T.c[a] < k) ++a;
    slot = a == T.n ? 0 : a;
    bj = k - a;  // < m + T.n - a <= 2m: one conditional subtraction replaces the division
    if (bj >= m) bj -= m;
  }
  Cut edge_of(const Tri& T, std::size_t idx, std::size_t k) const;
  bool contains_of(const Tri& T, const Vec2& t) const;
  std::array<double, 4> box_of(const Tri& T) const;
  LineDir dir_of(const Vec2& s2, const Vec2& d0, const Vec2& d1, int bedge) const;
  bool line_interval_impl(const Tri& T, std::size_t i, const Vec2& s1, const Vec2& s2, const LineDir& dir, Cut& entry,
                          Cut& exit) const;
  std::vector<Tri> tri_, seg_;
  std::vector<std::uint32_t> fan_, fan_start_;
  std::vector<std::uint32_t> opp_lt_, opp_le_;  ///< per B edge k: B edges with angle < / <= angle(−edge k)
  std::vector<Vec2> b_;
  std::size_t q_top_ = 0;
  std::array<double, 4> bbox_b_{};
};

}  // namespace pendepth::polygon2
