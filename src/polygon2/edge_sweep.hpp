// Polygon validation, step 2: do any two edges of the rings meet where they must not?
// (docs/design.md §1.3; used by Polygon's constructor, src/polygon2/polygon.cpp.)
//
// Contract: `rings` have passed the per-ring checks of step 1 (finite coordinates, no closing
// vertex, no repeated vertex within a ring, at least 3 vertices). Within a ring, non-adjacent
// edges must not meet and adjacent edges must not fold back (collinear, opposite directions);
// edges of different rings must not meet at all. The first violation found throws
// InvalidInput("<name>: ring k: self-intersecting (edges i and j intersect)") or
// InvalidInput("<name>: ring a (...) and ring b (...) touch or cross (edge i of ring a, edge j of
// ring b)"), each pair confirmed by edge_pair_violation below.
//
// Complexity: O(N log N), N = total number of edges (a box sweep with a budget of O(N) pairs,
// then, if needed, the Shamos–Hoey sweep; see edge_sweep.cpp).
// Every decision is an exact predicate (predicates::orient2d, dot_edges) on the input doubles.
#pragma once

#include <pendepth/polygon.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pendepth::polygon2 {

// "ring 0 (outer)" / "ring k (hole k)".
std::string validation_ring_name(std::size_t k);

// The pairwise rule for edge i of ring a and edge j of ring b ((a, i) != (b, j)): the message (without
// the "<name>: " prefix) if the two edges violate it, nullopt if they may coexist. O(1).
std::optional<std::string> edge_pair_violation(const std::vector<std::vector<Vec2>>& rings, std::size_t a,
                                               std::size_t i, std::size_t b, std::size_t j);

// Throws InvalidInput naming the first violating edge pair found; returns if there is none.
// The Shamos–Hoey sweep, O(N log N).
void check_edges_sweep(const std::vector<std::vector<Vec2>>& rings, const std::string& name);

// The box sweep: edges sorted by x-extent, every pair with overlapping bounding boxes checked,
// O(N log N + K) (K = such pairs: Θ(N²) on stars with long spikes, O(N) on combs and spirals,
// where it is 4–7× faster than the Shamos–Hoey sweep). Gives up after examining `budget` pairs
// of overlapping x-extents: returns false then (no violation found so far), true when decided.
bool check_edges_boxes(const std::vector<std::vector<Vec2>>& rings, const std::string& name, std::size_t budget);

// Step 2 as Polygon runs it: the box sweep with a budget of `budget_per_edge`·N pairs, then, if
// it gave up, the Shamos–Hoey sweep. O(N log N) worst case.
inline constexpr std::size_t kBoxBudgetPerEdge = 32;
void check_edges(const std::vector<std::vector<Vec2>>& rings, const std::string& name,
                 std::size_t budget_per_edge = kBoxBudgetPerEdge);

}  // namespace pendepth::polygon2
