// Independent exact oracle for polygon2, built with CGAL's exact kernel (Epeck) from explicit
// convolved triangles R_i = T_i ⊕ (−Q), each the exact convex hull of its 3m vertex differences.
//
// Overlap set O = {t : interiors of P and Q + t overlap} = ∪ int R_i (exact for convex T_i, Q).
// Note O ⊆ int M but O ≠ int M in general: where Q fits a pocket exactly, M = ∪ R_i has a slit of
// touching placements inside its topological interior. Touching is not overlapping (docs/design.md
// §1.2), which makes O the set that matters, so the ray queries use O; the regularised union
// (Polygon_set_2 join, docs/design.md §4) is kept to check O ⊆ int M and to count slit placements.
// A ray query intersects the line t + λ·d with every explicit R_i exactly (λ of the crossings with
// its edges, interior crossing confirmed by an exact midpoint test), then classifies the sorted
// breakpoints.
#pragma once

#include <pendepth/geometry.hpp>

#include <gmpxx.h>

#include <array>
#include <memory>
#include <vector>

namespace polygon2_test {

class UnionOracle {
 public:
  UnionOracle(const std::vector<std::array<pendepth::Vec2, 3>>& triangles, const std::vector<pendepth::Vec2>& Q);
  ~UnionOracle();
  /// Exact: t ∈ O (some int R_i contains t).
  bool inside(const pendepth::Vec2& t) const;
  /// Exact: t in the interior of the regularised union of the R_i (Polygon_set_2).
  bool inside_union(const pendepth::Vec2& t) const;
  /// σ_d(t): end of the component of {λ : t + λ·d ∈ O} containing 0, as a length, rounded once.
  double along(const pendepth::Vec2& t, const pendepth::Vec2& d) const;
  /// sup{λ >= 0 : t + λ d̂ ∈ O}, 0 if none, as a length, rounded once.
  double separation(const pendepth::Vec2& t, const pendepth::Vec2& d) const;
  /// Vertices of the regularised union's boundary (rounded to double).
  std::vector<pendepth::Vec2> boundary_vertices() const;

  // ---- the union boundary, exactly (for tests of the implicit ∂O) ----
  struct ExactPoint {
    mpq_class x, y;
  };
  /// Area of the regularised union (exact, rounded once).
  double union_area() const;
  /// Outer boundaries and holes of the regularised union (Polygon_set_2's polygons with holes).
  std::size_t outer_count() const;
  std::size_t hole_count() const;
  /// Exact: p lies on the regularised union's boundary.
  bool on_union_boundary(const ExactPoint& p) const;
  /// Exact: p ∈ O (some int R_i) / p in the interior of the regularised union.
  bool inside(const ExactPoint& p) const;
  bool inside_union(const ExactPoint& p) const;
  /// Number of vertices of the regularised union's boundary lying on none of the closed segments.
  std::size_t vertices_off(const std::vector<std::array<ExactPoint, 2>>& segments) const;
  /// dist(t, boundary of the regularised union), exact then rounded once.
  double boundary_distance(const pendepth::Vec2& t) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace polygon2_test
