// Exact reference for the 2D convex intersection depth (tests only; docs/design.md §5).
//
// Notation: P fixed, Q moving, placed at t; M = P ⊕ (−Q); σ_d(t) the exit parameter of the ray
// t + s·d̂ from int M, σ(t) = dist(t, ∂M) inside M, 0 elsewhere.
//
// Independent of pendepth's code paths: the oracle starts from the raw point sets (not pendepth's
// normal form), takes their exact convex hulls and builds M with CGAL's exact kernel (Epeck) as
// the hull of all pairwise differences (small n·m), by its own exact slope merge (large n·m), or by
// CGAL::minkowski_sum_2 (cross-check). Point location is CGAL::bounded_side_2; σ² is the exact
// minimum of the squared point–segment distances, σ_d² the exact squared distance from t to the
// exact ray–segment intersection point. Both are rational; the reported depth is sqrt(rational)
// rounded to the nearest double (MPFR, 256 bits: within 0.5 ulp + 2^-200 relative).
//
// CGAL stays inside exact_oracle.cpp; this header only exposes doubles.
#pragma once

#include <pendepth/geometry.hpp>

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace oracle {

using pendepth::Vec2;

enum class Location { Inside, Boundary, Outside };

/// How the exact M is built. Auto: pairwise-difference hull when n·m <= 4096, else the merge.
enum class Construction { Auto, PairwiseHull, Merge, CgalMinkowskiSum };

class ExactDifference {
 public:
  /// M = hull(p_points) ⊕ (−hull(q_points)), exactly. Points must be finite and each set must
  /// span a positive area (the tests only pass valid shapes).
  ExactDifference(std::span<const Vec2> p_points, std::span<const Vec2> q_points,
                  Construction how = Construction::Auto);
  ~ExactDifference();
  ExactDifference(ExactDifference&&) noexcept;
  ExactDifference& operator=(ExactDifference&&) noexcept;

  /// Number of vertices of M (strictly convex, CCW, vertex 0 lowest then leftmost).
  std::size_t size() const;
  /// Vertex k of M rounded to the nearest double, and whether that rounding is exact.
  Vec2 vertex(std::size_t k) const;
  bool vertex_is_double(std::size_t k) const;
  /// Points exactly on ∂M that are exactly representable: vertices, edge midpoints and quarter
  /// points that are doubles (found with a sufficient test on CGAL's interval approximation: every
  /// point returned is exact; a few representable ones may be missed).
  std::vector<Vec2> boundary_doubles() const;
  /// Vertices of hull(P) and hull(Q) (exact inputs, CCW).
  std::vector<Vec2> p_hull() const;
  std::vector<Vec2> q_hull() const;
  /// Approximate bounding box of M (only used to draw placements).
  Vec2 box_lo() const;
  Vec2 box_hi() const;

  /// Exact location of t with respect to M.
  Location locate(const Vec2& t) const;
  /// σ(t) rounded to nearest: dist(t, ∂M) for t ∈ int M, else exactly 0.
  double minimum_depth(const Vec2& t) const;
  /// σ_d(t) rounded to nearest: |p − t| for the exit point p of the ray t + s·d (s >= 0) from
  /// int M, else exactly 0. d must be finite and non-zero.
  double directional_depth(const Vec2& t, const Vec2& d) const;
  /// Exact complete separation along d (DHS §6) for convex M: end of the line's interval in
  /// int M when the ray reaches it, else 0 (correctly rounded).
  double separation_depth(const Vec2& t, const Vec2& d) const;

  /// Exactly the same vertex cycle (both normalised).
  bool same_polygon(const ExactDifference& other) const;
  /// Vertex list for failure messages (%.17g).
  std::string describe() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

/// |got − want| / (2^-52·|want|): the error in units of the double epsilon relative to the
/// reference. 0 if both are 0; +inf if exactly one of them is 0.
double relative_ulps(double got, double want);

/// Absolute slack for depths in the underflow range (|depth| below ~2^-970), where a relative
/// error bound cannot hold: the same 2^-1000 pendepth's exact.hpp allows for underflow.
inline constexpr double kUnderflowSlack = 0x1p-1000;

/// |got − want| <= tol·2^-52·|want| + kUnderflowSlack.
bool within(double got, double want, double tol);

}  // namespace oracle
