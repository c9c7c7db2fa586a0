// Independent exact reference for the 3D depth of two convex polytopes (tests only).
//
// Notation as in include/pendepth/depth3.hpp: P fixed, Q placed in P's frame as
// q' = R q + tq − tp, evaluated EXACTLY for the given double R, tq, tp (the semantics pendepth
// documents); M = hull{p − q'} over all input points; σ = dist(0, ∂M) when 0 ∈ int M (else 0);
// σ_d = s*·|d| for the exit parameter s* = max{s : s·d ∈ M}.
//
// Shares no code path with pendepth: CGAL's exact kernel (Epeck, GMP rationals) builds the hull of
// all n·m pairwise differences with CGAL::convex_hull_3 from the RAW point sets (no normal form,
// no hierarchy, no pendepth predicate). Every facet plane u·x = h (u = (b − a) × (c − a), rational)
// is then evaluated in mpq: 0 ∈ int M iff h > 0 on every facet; σ² = min h²/|u|² (rational);
// s* = min h/(u·d) over facets with u·d > 0 (rational), σ_d² = s*²·|d|². The reported depths are
// sqrt(rational) rounded to the nearest double by MPFR (256-bit sqrt, then one rounding): within
// 0.5 ulp (+2⁻²⁰⁰ relative) of the true value. Cost O(nm log nm) exact arithmetic per placement.
//
// CGAL stays inside oracle3_cgal.cpp; this header only exposes doubles.
#pragma once

#include <pendepth/geometry.hpp>

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace oracle3 {

using pendepth::Vec3;

/// Result of one exact query (rounded once to doubles).
struct Answer {
  bool overlapping = false;  ///< 0 ∈ int M (exact)
  bool on_boundary = false;  ///< 0 ∈ ∂M (exact): touching
  double depth = 0;          ///< correctly rounded σ or σ_d (0 when not overlapping)
  /// Outward unit normals (rounded) of every facet of M attaining the exact optimum.
  std::vector<Vec3> normals;
};

/// An exact convex polytope: hull of a point set given by doubles, optionally mapped exactly
/// by x ↦ R x + t1 − t2 first.
class ExactHull {
 public:
  explicit ExactHull(std::span<const Vec3> pts);
  ExactHull(std::span<const Vec3> pts, const Eigen::Matrix3d& R, const Vec3& t1, const Vec3& t2);
  ~ExactHull();
  ExactHull(ExactHull&&) noexcept;
  ExactHull& operator=(ExactHull&&) noexcept;

  std::size_t vertices() const;
  std::size_t facets() const;  ///< triangles of CGAL's triangulated boundary
  bool solid() const;          ///< full-dimensional (exact); the queries below assume it
  /// max over facets of (u·x − h)/|u| for the double point x, evaluated exactly then rounded:
  /// ≈ the signed distance to the boundary near ∂ (0 exactly on it, < 0 inside, > 0 outside).
  double gap(const Vec3& x) const;

  struct Impl;
  explicit ExactHull(std::unique_ptr<Impl> impl);
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

/// Shape-cast answer: hit ⇔ the ray meets M; distance = entry parameter·|d| (0 when 0 ∈ M),
/// correctly rounded; grazing ⇔ the ray meets M but not its interior.
struct CastAnswer {
  bool hit = false, grazing = false;
  double distance = std::numeric_limits<double>::infinity();
};

/// M = hull(P) ⊕ (−hull(Q')) with Q' = R Q + tq − tp exactly.
class ExactDifference {
 public:
  ExactDifference(std::span<const Vec3> p_points, std::span<const Vec3> q_points, const Eigen::Matrix3d& R,
                  const Vec3& tq, const Vec3& tp);
  /// The same for a Q of any dimension (a point, a segment, a flat polygon: `raw_q` true uses
  /// every q' and every p without first taking hulls, which need solids): P and Q may both be
  /// lower-dimensional when their differences span a solid.
  ExactDifference(std::span<const Vec3> p_points, std::span<const Vec3> q_points, const Eigen::Matrix3d& R,
                  const Vec3& tq, const Vec3& tp, bool raw_q);
  ~ExactDifference();

  const ExactHull& hull() const { return *m_; }
  /// σ at the current placement (0 ∈ M's frame).
  Answer sigma() const;
  /// σ_d for the double direction d (P's frame, non-zero).
  Answer sigma_d(const Vec3& d) const;
  /// Vertices of M that are exactly doubles, and midpoints of M's edges that are exactly doubles
  /// (every point returned lies exactly on ∂M).
  std::vector<Vec3> boundary_doubles() const;
  /// Signed distance of 0 to M, correctly rounded: dist(0, M) > 0 when 0 ∉ M (the exact minimum
  /// of CGAL::squared_distance over M's boundary triangles), 0 on ∂M, −σ when 0 ∈ int M.
  double signed_distance() const;
  /// The ray s·d (s >= 0, d in P's frame): entry into M (exact).
  CastAnswer cast(const Vec3& d) const;

 private:
  std::unique_ptr<ExactHull> m_;
};

}  // namespace oracle3
