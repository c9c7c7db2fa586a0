// Private: the minimum of a weighted farthest-point cost over the free placements of a moving
// union of convex parts (the bound of one angle interval of the PD_g branch and bound,
// generalized_depth2.cpp; docs/algorithms.md "Generalized depth").
//
// Notation: A_i fixed convex parts (P's), E_j moving convex parts given relative to the moving
// reference point u (placed part: E_j + u). The overlap set is U = ∪ int(A_i ⊕ (−E_j)) (open);
// the free set C = ℝ² \ U (closed). The cost is f(u) = max_k (|u − z_k| − r_k) (convex).
//
// minimum(f, cap) returns a certified lower bound of min(cap, min_{u ∈ Γ} f(u)) where Γ ⊇ ∂C is
// the union of the sums' edges with the parts strictly covered by some open sum removed:
//   - every sum A_i ⊕ (−E_j) is kept symbolic: its edges are an edge of one part translated by
//     the other part's extreme vertex (found by exact turn signs, ties all kept), so a point of an
//     edge is x0 + y + λ·(x1 − x0) with x0, x1, y input doubles;
//   - an edge is cut by the other sums' open half-planes: per line the exact signs of
//     α = cross(D, x0 + y − o) and β = cross(D, x1 − x0) decide parallel and coincident lines,
//     otherwise λ = −α/β is bounded by interval arithmetic (exact::Fl) and the covered interval
//     SHRUNK (rounded inwards), so the kept pieces are a superset of the true uncovered ones;
//   - per kept piece f(λ) is convex; a golden-section search with the Lipschitz constant |x1 − x0|
//     of f in λ and margins for every floating evaluation gives a lower bound of its minimum.
// Edges are visited in the order of a cheap bound (max_k distance(z_k, edge) − r_k) and skipped
// when that bound is at least the best found so far (or cap).
// Whether min over C equals min over Γ (the unconstrained minimiser may be free) is the caller's
// decision: inside(u) is the exact test u ∈ U.
// Cost: O(Σ_ij n_i m_j) exact turn signs to build; per visited edge O(S·ℓ) line tests (S sums
// whose box meets it, ℓ lines each) and O(K) per cost evaluation (K terms), ~60 evaluations.
#pragma once

#include <pendepth/polygon.hpp>

#include <cstddef>
#include <limits>
#include <vector>

namespace pendepth::motion {

/// f(u) = max_k (|u − z_k| − r_k), r_k ≥ 0.
struct FarthestCost {
  std::vector<Vec2> z;
  std::vector<double> r;
};

struct FreeMinimum {
  double lower = 0;  ///< certified: ≤ min(cap, min over Γ of f)
  bool found = false;  ///< a piece of Γ with value below cap was minimised
  Vec2 argmin{0, 0};   ///< the best point found on Γ (rounded), when found
  Vec2 outward{0, 0};  ///< unit normal of its edge towards the outside of its own sum
  double value = std::numeric_limits<double>::infinity();  ///< f(argmin) as evaluated
};

class FreeSpace {
 public:
  /// `fixed`: the A_i; `moving`: the E_j (CCW convex vertex lists, relative to u).
  FreeSpace(const std::vector<ConvexPolygon>& fixed, const std::vector<std::vector<Vec2>>& moving);
  /// Exact: u ∈ U.
  bool inside(const Vec2& u) const;
  FreeMinimum minimum(const FarthestCost& f, double cap) const;
  std::size_t sums() const { return sums_.size(); }

 private:
  struct Seg {
    Vec2 x0, x1, y;  // x0 + y + λ(x1 − x0), λ ∈ [0, 1]; the sum's interior on its left
    Vec2 lo, hi;     // box, padded outwards
  };
  struct Sum {
    std::size_t first = 0, count = 0;  // its edges in segs_
    Vec2 lo, hi;                       // box, padded outwards
  };
  std::vector<Seg> segs_;
  std::vector<Sum> sums_;
  double scale_ = 0;  // max |coordinate| of the parts
  // Appends to `out` the covered open λ-interval of edge `s` by the open sum `k` (shrunk), if any.
  bool covered(const Seg& s, const Sum& k, double& lo, double& hi) const;
};

}  // namespace pendepth::motion
