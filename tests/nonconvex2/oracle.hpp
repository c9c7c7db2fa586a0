// Independent exact oracle for nonconvex2, built with CGAL's exact kernel (Epeck).
//
// Each shape is cut into convex pieces independently of the library: CGAL's Hertel–Mehlhorn
// approximate convex partition for a ring without holes, the polygon2 triangulation only when the
// shape has holes. The overlap set O = ∪ int(A_i ⊕ (−B_j)) does not depend on the decomposition,
// so the oracle's pieces (explicit exact convex hulls of the vertex differences) differ from the
// library's triangle pairs. Ray queries intersect the line with every piece exactly; σ is the exact
// nearest point of the closed complement of O: on the edges of the pieces near t, the parts covered
// by no other open piece. For hole-free pairs the reduced-convolution sum (CGAL::minkowski_sum_2)
// is also available, to check O ⊆ M.
#pragma once

#include <pendepth/polygon.hpp>

#include <memory>
#include <vector>

namespace nonconvex2_test {

class PairOracle {
 public:
  PairOracle(const pendepth::Polygon& P, const pendepth::Polygon& Q);
  ~PairOracle();
  std::size_t piece_count() const;
  /// Exact: t ∈ O.
  bool inside(const pendepth::Vec2& t) const;
  /// σ_d(t) as a length, from the exact λ rounded once (times |d|).
  double along(const pendepth::Vec2& t, const pendepth::Vec2& d) const;
  /// sup{λ >= 0 : t + λ d̂ ∈ O}, 0 if none.
  double separation(const pendepth::Vec2& t, const pendepth::Vec2& d) const;
  /// σ(t) = dist(t, complement of O) for t ∈ O, else 0: the exact squared distance, then sqrt.
  double minimum(const pendepth::Vec2& t) const;
  /// Hole-free pairs only: -1 / 0 / +1 for t outside / on the boundary / inside CGAL's
  /// minkowski_sum_2(P, −Q) (reduced convolution, exact).
  int side_of_M(const pendepth::Vec2& t) const;
  bool has_M() const;
  /// cl(O) = M exactly (minkowski_sum_2 for hole-free pairs, else the regularised union of the
  /// exact convex piece sums with Polygon_set_2): its area rounded once, and the vertices of its
  /// boundary rings, each coordinate converted from the exact value.
  double closure_area() const;
  std::vector<pendepth::Vec2> closure_vertices() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace nonconvex2_test
