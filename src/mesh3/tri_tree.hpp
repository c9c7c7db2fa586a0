// Private: a 3D axis-aligned box hierarchy over a mesh's triangles (the point path of Pair3 on a
// non-convex mesh, mesh_point.cpp: nearest-triangle and ray-hit searches). The project's
// geometry::BoxTree is 2D; this is the same idea in 3D: median split on the longer axis of the
// node's box by box centre, leaves of up to kLeaf triangles.
//
// Boxes only prune: every answer the callers report is an exact predicate (or an exact-decision
// distance) on the triangles themselves, so the tree must never drop a triangle the linear scan
// would keep. Node boxes contain their triangles' boxes exactly (min / max of doubles), so a
// node's rounded box distance is <= each of its triangles' (rounding is monotone), and ray_box is
// conservative (box grown by the caller's margin, slab bounds widened).
// Build O(T log T), space O(T); a query visits O(log T + k) nodes typically.
#pragma once

#include <pendepth/geometry.hpp>

#include "geometry/box_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace pendepth::mesh3 {

struct TriTree {
  static constexpr std::uint32_t kLeaf = 4;
  struct Node {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
    std::int32_t left = -1, right = -1;  // leaf when left < 0
    std::uint32_t b = 0, e = 0;          // leaf: items[b, e)
  };
  std::vector<Node> nodes;  // nodes[0] the root
  std::vector<std::uint32_t> items;

  void build(const std::vector<std::array<Vec3, 2>>& box) {
    nodes.clear();
    items.resize(box.size());
    for (std::size_t k = 0; k < box.size(); ++k) items[k] = static_cast<std::uint32_t>(k);
    if (box.empty()) return;
    nodes.reserve(2 * box.size() / kLeaf + 2);
    split(box, 0, static_cast<std::uint32_t>(box.size()));
  }

  /// The conservative ray–box test of the ray x + λ d, λ >= 0 (x within `e` of the exact origin),
  /// against [lo − e, hi + e]: false only if the exact ray provably misses the box.
  static bool ray_box(const Vec3& x, const Vec3& d, const Vec3& lo, const Vec3& hi, double e) {
    double lmin = -std::numeric_limits<double>::infinity(), lmax = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const double l = geometry::widen_down(lo[k] - e), h = geometry::widen_up(hi[k] + e);
      if (d[k] == 0) {
        if (x[k] < l || x[k] > h) return false;
        continue;
      }
      double a = (l - x[k]) / d[k], b = (h - x[k]) / d[k];
      if (a > b) std::swap(a, b);
      if (std::isfinite(a)) a = geometry::widen_down(a);
      if (std::isfinite(b)) b = geometry::widen_up(b);
      lmin = std::max(lmin, a), lmax = std::min(lmax, b);
    }
    return lmin <= lmax && lmax >= 0;
  }

  /// Visits every triangle whose box the ray meets (conservatively, see ray_box).
  template <class F>
  void along_ray(const Vec3& x, const Vec3& d, double e, F&& f) const {
    visit([&](const Node& n) { return ray_box(x, d, n.lo, n.hi, e); }, f);
  }
  /// Visits every triangle whose box holds x up to `e` (componentwise).
  template <class F>
  void near_point(const Vec3& x, double e, F&& f) const {
    visit(
        [&](const Node& n) {
          for (int k = 0; k < 3; ++k)
            if (x[k] < geometry::widen_down(n.lo[k] - e) || x[k] > geometry::widen_up(n.hi[k] + e)) return false;
          return true;
        },
        f);
  }

 private:
  template <class Keep, class F>
  void visit(Keep&& keep, F& f) const {
    if (nodes.empty()) return;
    std::vector<std::uint32_t> st{0};
    while (!st.empty()) {
      const Node& n = nodes[st.back()];
      st.pop_back();
      if (!keep(n)) continue;
      if (n.left < 0) {
        for (std::uint32_t i = n.b; i < n.e; ++i) f(items[i]);
      } else {
        st.push_back(static_cast<std::uint32_t>(n.right));
        st.push_back(static_cast<std::uint32_t>(n.left));
      }
    }
  }
  std::int32_t split(const std::vector<std::array<Vec3, 2>>& box, std::uint32_t b, std::uint32_t e) {
    const auto id = static_cast<std::int32_t>(nodes.size());
    nodes.emplace_back();
    Vec3 lo = box[items[b]][0], hi = box[items[b]][1];
    for (std::uint32_t k = b + 1; k < e; ++k) lo = lo.cwiseMin(box[items[k]][0]), hi = hi.cwiseMax(box[items[k]][1]);
    nodes[id].lo = lo, nodes[id].hi = hi;
    if (e - b <= kLeaf) {
      nodes[id].b = b, nodes[id].e = e;
      return id;
    }
    int axis = 0;
    const Vec3 ext = hi - lo;
    if (ext[1] > ext[axis]) axis = 1;
    if (ext[2] > ext[axis]) axis = 2;
    const std::uint32_t mid = (b + e) / 2;
    std::nth_element(items.begin() + b, items.begin() + mid, items.begin() + e, [&](std::uint32_t u, std::uint32_t v) {
      const double cu = box[u][0][axis] + box[u][1][axis], cv = box[v][0][axis] + box[v][1][axis];
      return cu < cv || (cu == cv && u < v);
    });
    const std::int32_t l = split(box, b, mid);
    const std::int32_t r = split(box, mid, e);
    nodes[id].left = l, nodes[id].right = r;
    return id;
  }
};

}  // namespace pendepth::mesh3
