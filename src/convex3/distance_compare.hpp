// Private: exact comparison of the distance of two posed convex point sets with a radius — the
// overlap decision of rounded shapes (src/primitives/rounded3.cpp; signed_distance3.cpp).
#pragma once

#include <pendepth/depth3.hpp>

#include "convex3/flat3.hpp"
#include "convex3/minkowski_facets.hpp"
#include "convex3/polytope_data.hpp"

#include <memory>

namespace pendepth::convex3 {

/// A convex point set for the exact GJK of signed_distance3.cpp: the vertices (own frame) and a
/// climbing adjacency on which a vertex with no strictly better neighbour is a global optimum
/// of every linear function (a polytope's level-0 adjacency; the cycle of a strictly convex
/// polygon; nothing to climb for a point or a segment's two ends, which are each other's
/// neighbours).
class CorePoints {
 public:
  explicit CorePoints(const ConvexPolytope& S);
  explicit CorePoints(const FlatShape3& F);
  const PolytopeData& data() const { return *data_; }
  const VertexAdjacency& adjacency() const { return *adj_; }

 private:
  std::shared_ptr<const PolytopeData> own_data_;
  std::shared_ptr<const VertexAdjacency> own_adj_;
  const PolytopeData* data_ = nullptr;
  const VertexAdjacency* adj_ = nullptr;
};

/// The exact sign of dist(P, Q + λ·d) − r, r = rp + rq (the sum never rounded), for P, Q posed (poses as given, the relative pose
/// computed as in signed_distance: exact for the doubles R, tq, tp it holds) and Q moved
/// further by λ·d (world frame, never rounded: the term Rpᵀ·d·λ is kept as a polynomial), r > 0:
/// −1 when the sets meet (distance 0) and r > 0. dist² is a ratio of polynomials in the inputs
/// (|a|², |e × a|²/|e|², (n·a)²/|n|² on the final GJK simplex) compared with r² exactly.
/// `slope` (if non-null, and the sets do not meet) receives the sign of the derivative of
/// λ ↦ dist(P, Q + λ·d) at λ (exact: −sign(w·d), w the closest point of P ⊕ (−Q) to 0).
/// Cost: one exact GJK (signed_distance3.cpp) plus a few filtered signs.
int distance_compare(const CorePoints& P, const Pose3& pp, const CorePoints& Q, const Pose3& pq, const Vec3& d,
                     double lambda, double rp, double rq, int* slope = nullptr);

/// The exact sign of dist(P, the line {Q + s·d : s real}) − r, r = rp + rq > 0 (−1 when they
/// meet): the GJK on the projection along d_P = Rpᵀ·d (rounded when P's pose rotates: exact for
/// that direction) compared with r·|d_P|².
int line_distance_compare(const CorePoints& P, const Pose3& pp, const CorePoints& Q, const Pose3& pq, const Vec3& d,
                          double rp, double rq);

/// Which path answers signed_distance_gjk (signed_distance3.cpp), for tests and benchmarks: the
/// floating GJK with its one certificate (`fast`, falling back to the exact loop when the
/// certificate fails) or the exact loop alone; `margin` scales the certificate's error bounds
/// (1: the proven bounds, as in the library; 0: plain floating signs — unsound, used only to
/// show that the tests detect a certificate without its margin); `quick_value`: the value and
/// normal from the double-double evaluation of the final simplex (exact zeros by FlX / FlZ) when
/// its bounds hold, else (false) always the general per-component evaluation — the same bits;
/// `a_priori_value`: that double-double first without its running error bounds,
/// checked against bounds proven from the inputs' magnitudes (false: running bounds only) — the
/// same bits.
struct SignedDistancePath {
  bool fast = true;
  double margin = 1.0;
  bool quick_value = true;
  bool a_priori_value = true;
};

/// signed_distance_gjk along `path`; `fast_used` (if non-null) tells whether the certified fast
/// path answered.
Distance3 signed_distance_gjk(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                              const Eigen::Matrix3d& Rp, const Vec3& tp, const SignedDistancePath& path,
                              bool* fast_used);
/// The same from the poses (as pendepth::signed_distance).
Distance3 signed_distance_path(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq,
                               const SignedDistancePath& path, bool* fast_used = nullptr);

}  // namespace pendepth::convex3
