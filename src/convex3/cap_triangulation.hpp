// Private: retriangulation of the hole left by removing a vertex of degree ≤ kMaxRemovedDegree
// from a convex polytope level (DHS §5.1, the Dobkin–Kirkpatrick construction), shared by the
// inner hierarchy (primal points) and the outer hierarchy (polar dual, orientation of planes).
//
// The link of the removed vertex is a cycle of k vertices (indices 0..k-1). A cap is a
// triangulation of that cycle whose triangles are faces of the convex hull of the link: triangle
// (i, m, j) is valid when no other link vertex lies strictly outside its plane, which the caller's
// exact predicate `outside(i, m, j, t)` decides. Dynamic programming over sub-polygons i..j picks
// any valid apex (coplanar link vertices admit several caps; any one is a correct face set).
// O(k⁴) predicate calls, k ≤ 8.
#pragma once

#include <array>
#include <utility>
#include <vector>

namespace pendepth::convex3 {

inline constexpr int kMaxRemovedDegree = 8;

/// Appends the cap's triangles (i, m, j) over link indices to `out`; false if no valid cap exists.
template <class Outside>
bool cap_triangulation(int k, Outside&& outside, std::vector<std::array<int, 3>>& out) {
  auto valid = [&](int i, int m, int j) {
    for (int t = 0; t < k; ++t)
      if (t != i && t != m && t != j && outside(i, m, j, t)) return false;
    return true;
  };
  // choice[i][j]: apex m of the triangle closing sub-polygon i..j, -1 impossible, -2 empty.
  int choice[kMaxRemovedDegree][kMaxRemovedDegree];
  for (int len = 1; len < k; ++len)
    for (int i = 0; i + len < k; ++i) {
      const int j = i + len;
      choice[i][j] = -1;
      if (len == 1) {
        choice[i][j] = -2;
        continue;
      }
      for (int m = i + 1; m < j && choice[i][j] == -1; ++m)
        if (choice[i][m] != -1 && choice[m][j] != -1 && valid(i, m, j)) choice[i][j] = m;
    }
  if (choice[0][k - 1] == -1) return false;
  std::vector<std::pair<int, int>> todo{{0, k - 1}};
  while (!todo.empty()) {
    auto [i, j] = todo.back();
    todo.pop_back();
    const int m = choice[i][j];
    if (m < 0) continue;
    out.push_back({i, m, j});
    todo.push_back({i, m});
    todo.push_back({m, j});
  }
  return true;
}

}  // namespace pendepth::convex3
