// Pair3 on meshes: the shape cast (time of impact) along d (issue 16 item 3 on the shapes of
// issue 17; contract in mesh_pair.hpp).
//
// Q + s·d̂ touches or overlaps P iff s·d̂ lies in the closed union ∪ M_ij (pieces cover the solids:
// a point of P ∩ (Q' + x) lies in some P_i ∩ (Q'_j + x)), so the first contact is the least
// entry of the ray into the closed M_ij: the least exact convex cast (shape_cast) over the piece
// pairs. A minimum of values each a few ulps from the exact entry is a few ulps from the exact
// minimum; the hit/miss decisions are each exact. Overlapping at s = 0 (0 ∈ some int M_ij) is the
// exact overlap test of overlapping(): then distance 0, vectors 0, features None, as for convex
// shapes. Pruning: the ray's entry into each widened box sum box(P_i) ⊕ −box(Q'_j) (a lower bound
// of the entry into M_ij, computed with a margin far above its rounding; +∞ when the ray
// certainly misses the box); pairs in increasing box entry, stopping when the box entry exceeds
// the best cast so far. Cost: O(n·m log(n·m)) box work + the convex casts of the surviving pairs
// (each O(log n_i · log m_j), src/convex3/cast3.cpp).
#include "mesh3/mesh_pair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pendepth::mesh3 {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A lower bound of the entry parameter s >= 0 of the ray s·u (u unit, P's frame) into the box,
// +∞ when the ray misses it by more than the rounding of this computation. The box is already
// widened by 2^-40 of its magnitude (sum_box), far above the relative 2^-50 slack used here.
double box_entry(const Box3& b, const Vec3& u) {
  double lo = 0, hi = kInf;
  for (int k = 0; k < 3; ++k) {
    if (u[k] == 0) {
      if (b.lo[k] > 0 || b.hi[k] < 0) return kInf;
      continue;
    }
    double a = b.lo[k] / u[k], c = b.hi[k] / u[k];
    if (a > c) std::swap(a, c);
    lo = std::max(lo, a), hi = std::min(hi, c);
  }
  if (lo > hi * (1 + 0x1p-50) + 0x1p-1000) return kInf;
  return lo * (1 - 0x1p-50);
}

}  // namespace

Cast3 cast(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) {
  Cast3 best;
  best.distance = best.lower_bound = best.upper_bound = kInf;
  if (overlapping(m, pose_p, pose_q)) {
    best.distance = best.lower_bound = best.upper_bound = 0;
    best.hit = best.overlapping = true;
    return best;
  }
  const Placed pl = place(m, pose_p, pose_q);
  const Vec3 u = (pl.Rp.transpose() * d).normalized();
  struct Cand {
    double entry;
    std::size_t i, j;
  };
  std::vector<Cand> c;
  for (std::size_t i = 0; i < m.P.size(); ++i)
    for (std::size_t j = 0; j < m.Q.size(); ++j)
      if (const double e = box_entry(sum_box(m, pl, i, j), u); e < kInf) c.push_back({e, i, j});
  std::sort(c.begin(), c.end(), [](const Cand& a, const Cand& b) { return a.entry < b.entry; });
  for (const Cand& k : c) {
    if (best.hit && k.entry > best.distance) break;
    Cast3 r = shape_cast(m.P[k.i], pose_p, m.Q[k.j], pose_q, d);
    if (!r.hit || (best.hit && !(r.distance < best.distance))) continue;
    best = r;
    best.piece_p = static_cast<int>(k.i), best.piece_q = static_cast<int>(k.j);
  }
  return best;
}

}  // namespace pendepth::mesh3
