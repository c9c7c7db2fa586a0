// Private: the axis-aligned box hierarchy and the conservative ray–box test shared by polygon2
// (the union boundary's pieces, edge sausages and P edges) and nonconvex2 (the triangulations of
// both shapes, the no-fit polygon's pieces).
//
// Boxes are closed, [lo, hi] per axis, and only ever prune: every decision the callers report is
// an exact predicate on their items, so a box must contain its item (callers pad) and the ray–box
// interval must contain the exact one (ray_box widens).
#pragma once

#include <pendepth/geometry.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace pendepth::geometry {

/// x lowered resp. raised by 2^-50 relative plus 2^-1000: covers two roundings of 2^-53 each
/// (a difference, then a quotient or sum) and underflow.
inline double widen_down(double x) { return x - std::abs(x) * 0x1p-50 - 0x1p-1000; }
inline double widen_up(double x) { return x + std::abs(x) * 0x1p-50 + 0x1p-1000; }

/// How ray_box widens the rounded slab interval so that it contains the exact one.
enum class RaySlack : std::uint8_t {
  Bounds,    ///< each slab bound by widen_down / widen_up before they are combined (tightest)
  Interval,  ///< the combined interval by (|lmin| + |lmax|)·2^-40 + 2^-1000 on both sides. The
             ///< union boundary's queries order sibling boxes by these values and break exact
             ///< ties between hits by visit order: their answers depend on this margin.
};

namespace detail {
template <RaySlack Slack>
inline bool ray_box(const Vec2& t, const Vec2& d, const Vec2& lo, const Vec2& hi, double& lmin, double& lmax) {
  lmin = -std::numeric_limits<double>::infinity();
  lmax = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0) {
      if (t[k] < lo[k] || t[k] > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - t[k]) / d[k], b = (hi[k] - t[k]) / d[k];
    if (a > b) std::swap(a, b);
    if constexpr (Slack == RaySlack::Bounds) {
      a = widen_down(a);
      b = widen_up(b);
    }
    lmin = std::max(lmin, a);
    lmax = std::min(lmax, b);
  }
  if constexpr (Slack == RaySlack::Interval) {
    const double s = (std::abs(lmin) + std::abs(lmax)) * 0x1p-40 + 0x1p-1000;
    if (std::isfinite(lmin)) lmin -= s;
    if (std::isfinite(lmax)) lmax += s;
  }
  return lmin <= lmax;
}
}  // namespace detail

/// Conservative ray–box test on the line t + λ·d against the box [lo, hi]: false only if the line
/// provably misses the box; otherwise [lmin, lmax] ⊇ the λ range inside the box. O(1).
template <RaySlack Slack = RaySlack::Bounds>
inline bool ray_box(const Vec2& t, const Vec2& d, const Vec2& lo, const Vec2& hi, double& lmin, double& lmax) {
  return detail::ray_box<Slack>(t, d, lo, hi, lmin, lmax);
}
/// The per-bound test is out of line (box_tree.cpp): its callers' descent loops stay small.
template <>
bool ray_box<RaySlack::Bounds>(const Vec2& t, const Vec2& d, const Vec2& lo, const Vec2& hi, double& lmin, double& lmax);

/// Binary box hierarchy over items given by their boxes (median split on the longer axis of the
/// node's box, by box centre). Two leaf layouts:
///   - one item per leaf (build, build_boxes, build_in_order): the leaf's item is `tri`,
///     `items` is empty, 2s − 1 nodes for s items;
///   - buckets (build_buckets): a leaf holds up to LeafMax items, items[tri, tri + count).
/// nodes[0] is the root; a node is a leaf when left < 0. Space O(s).
struct BoxTree {
  struct Node {
    Vec2 lo{0, 0}, hi{0, 0};
    std::int32_t left = -1, right = -1;  // children; leaf when left < 0
    std::uint32_t tri = 0;               // leaf: its item (one-item leaves) or first slot in `items`
    std::uint32_t count = 1;             // leaf: number of items (bucket leaves; 1 otherwise)
  };
  std::vector<Node> nodes;            // nodes[0] is the root
  std::vector<std::uint32_t> items;   // bucket trees: the items, leaf by leaf

  /// Over records with members `lo`, `hi` (one item per leaf). O(s log s).
  template <class Rec>
  void build(const std::vector<Rec>& recs) {
    build_boxes(recs.size(), [&](std::size_t k) -> const Vec2& { return recs[k].lo; },
                [&](std::size_t k) -> const Vec2& { return recs[k].hi; });
  }
  /// The same tree over `count` leaves whose boxes are lo_of(k), hi_of(k) (any record type, no
  /// copy into records). O(s log s); no allocation besides `nodes` up to 64 leaves.
  template <class Lo, class Hi>
  void build_boxes(std::size_t count, Lo&& lo_of, Hi&& hi_of) {
    build_split<1>(count, lo_of, hi_of);
  }
  /// The same split rule, but ranges of at most LeafMax items become one leaf (their order in
  /// `items` is the one the selections left). Fewer nodes, for queries whose items cost more than
  /// a box test. O(s log s).
  template <std::uint32_t LeafMax, class Lo, class Hi>
  void build_buckets(std::size_t count, Lo&& lo_of, Hi&& hi_of) {
    build_split<LeafMax>(count, lo_of, hi_of);
  }
  /// A tree over `count` leaves in their given order, no sorting: neighbours paired bottom-up,
  /// level by level (an odd last node moves up a level unpaired), so subtrees are runs of
  /// consecutive leaves. For leaves whose order is already spatially coherent (the no-fit
  /// polygon's pieces follow the convolution). O(s), ~2 box unions per leaf; no allocation
  /// besides `nodes` up to 256 leaves. Same invariants as build_boxes (2s − 1 nodes, root 0).
  template <class Lo, class Hi>
  void build_in_order(std::size_t count, Lo&& lo_of, Hi&& hi_of);

  /// Visits the items of leaf n in order until f(item) returns true; returns whether it did.
  template <class F>
  bool leaf_until(const Node& n, F&& f) const {
    if (items.empty()) return f(n.tri);
    for (std::uint32_t i = n.tri; i < n.tri + n.count; ++i)
      if (f(items[i])) return true;
    return false;
  }
  /// Visits the items whose leaf boxes meet [qlo, qhi] until f returns true; returns whether it
  /// did. Depth-first, left child first. O(log s + k) typical for k items reported.
  template <class F>
  bool overlap_until(const Vec2& qlo, const Vec2& qhi, F&& f) const {
    if (nodes.empty()) return false;
    return items.empty() ? overlap_impl<false>(qlo, qhi, f) : overlap_impl<true>(qlo, qhi, f);
  }
  /// Visits every item whose leaf box meets [qlo, qhi].
  template <class F>
  void overlap(const Vec2& qlo, const Vec2& qhi, F&& f) const {
    overlap_until(qlo, qhi, [&](std::uint32_t i) {
      f(i);
      return false;
    });
  }
  /// Heap bytes (capacities).
  std::size_t bytes() const { return nodes.capacity() * sizeof(Node) + items.capacity() * sizeof(std::uint32_t); }

 private:
  template <std::uint32_t LeafMax, class Lo, class Hi>
  void build_split(std::size_t count, Lo&& lo_of, Hi&& hi_of);
  template <bool Buckets, class F>
  bool overlap_impl(const Vec2& qlo, const Vec2& qhi, F& f) const {
    std::uint32_t st[128];
    int top = 0;
    st[top++] = 0;
    while (top > 0) {
      const Node& n = nodes[st[--top]];
      if (n.lo.x() > qhi.x() || n.hi.x() < qlo.x() || n.lo.y() > qhi.y() || n.hi.y() < qlo.y()) continue;
      if (n.left < 0) {
        if constexpr (Buckets) {
          for (std::uint32_t i = n.tri; i < n.tri + n.count; ++i)
            if (f(items[i])) return true;
        } else if (f(n.tri)) {
          return true;
        }
      } else {
        st[top++] = static_cast<std::uint32_t>(n.left);
        st[top++] = static_cast<std::uint32_t>(n.right);
      }
    }
    return false;
  }
};

template <std::uint32_t LeafMax, class Lo, class Hi>
void BoxTree::build_split(std::size_t count, Lo&& lo_of, Hi&& hi_of) {
  nodes.clear();
  items.clear();
  if (count == 0) return;
  // Per leaf its index and split keys (twice the box centre, computed once: the selections
  // compare them often), kept together so the selection moves one record and reads no other.
  // The selection permutes these exactly as it permutes a bare index array compared through a
  // key table (the same comparisons in the same order), so the tree does not depend on it.
  struct Item {
    double key[2];
    std::uint32_t idx;
  };
  // Up to 64 leaves (the triangulations and piece sets of real nesting pieces) on the stack.
  Item small[64];
  std::vector<Item> large(count > 64 ? count : 0);
  Item* const item = count > 64 ? large.data() : small;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec2 &lo = lo_of(k), &hi = hi_of(k);
    item[k] = {{lo.x() + hi.x(), lo.y() + hi.y()}, static_cast<std::uint32_t>(k)};
  }
  nodes.resize(2 * count - 1);  // the one-item tree; bucket trees trim below
  // Depth-first by explicit stack: (node, begin, end). Ranges halve, so the stack holds at most
  // one pending sibling per level: ≤ 64 + 1 entries for any count.
  struct Job {
    std::int32_t node;
    std::uint32_t b, e;
  };
  Job jobs[66];
  int top = 0;
  jobs[top++] = {0, 0, static_cast<std::uint32_t>(count)};
  std::int32_t used = 1;
  // A range that is a leaf: its box and its items.
  auto fill_leaf = [&](Node& N, std::uint32_t b, std::uint32_t e) {
    if constexpr (LeafMax == 1) {
      N.tri = item[b].idx;
    } else {
      N.tri = b;
      N.count = e - b;
    }
  };
  while (top > 0) {
    const Job J = jobs[--top];
    Node& N = nodes[J.node];
    Vec2 lo = lo_of(item[J.b].idx), hi = hi_of(item[J.b].idx);
    for (std::uint32_t k = J.b + 1; k < J.e; ++k) {
      lo = lo.cwiseMin(lo_of(item[k].idx));
      hi = hi.cwiseMax(hi_of(item[k].idx));
    }
    N.lo = lo;
    N.hi = hi;
    if (J.e - J.b <= LeafMax) {
      fill_leaf(N, J.b, J.e);
      continue;
    }
    const int axis = (hi.x() - lo.x()) >= (hi.y() - lo.y()) ? 0 : 1;
    const std::uint32_t mid = (J.b + J.e) / 2;
    auto less = [axis](const Item& a, const Item& b) { return a.key[axis] < b.key[axis]; };
    if (J.e - J.b <= 3) {
      // std::nth_element sorts ranges of ≤ 3 by insertion, a stable sort: the same order here.
      for (Item* i = item + J.b + 1; i < item + J.e; ++i) {
        const Item v = *i;
        Item* j = i;
        for (; j > item + J.b && less(v, j[-1]); --j) *j = j[-1];
        *j = v;
      }
    } else {
      std::nth_element(item + J.b, item + mid, item + J.e, less);
    }
    N.left = used;
    N.right = used + 1;
    // A one-leaf child is filled here rather than by a job of its own (node ids are assigned
    // at this point either way, so the tree is unchanged).
    const Job child[2] = {{used, J.b, mid}, {used + 1, mid, J.e}};
    for (const Job& C : child) {
      if (C.e - C.b > 1) {
        jobs[top++] = C;
        continue;
      }
      Node& leaf = nodes[C.node];
      leaf.lo = lo_of(item[C.b].idx);
      leaf.hi = hi_of(item[C.b].idx);
      fill_leaf(leaf, C.b, C.e);
    }
    used += 2;
  }
  if constexpr (LeafMax > 1) {
    nodes.resize(static_cast<std::size_t>(used));
    nodes.shrink_to_fit();
    items.resize(count);
    for (std::size_t k = 0; k < count; ++k) items[k] = item[k].idx;
  }
}

template <class Lo, class Hi>
void BoxTree::build_in_order(std::size_t count, Lo&& lo_of, Hi&& hi_of) {
  items.clear();
  nodes.resize(count == 0 ? 0 : 2 * count - 1);
  if (count == 0) return;
  // Slots are handed out from the back: the leaves take the last `count`, each new parent the
  // slot before the previous one; a tree of s leaves has s − 1 parents, so the last parent made,
  // the root, gets slot 0. `level` holds the node ids of the current level, left to right.
  std::int32_t small[256];
  std::vector<std::int32_t> large(count > 256 ? count : 0);
  std::int32_t* const level = count > 256 ? large.data() : small;
  auto slot = static_cast<std::int32_t>(2 * count - 2);
  for (std::size_t k = 0; k < count; ++k, --slot) {
    Node& L = nodes[slot];
    L.lo = lo_of(k);
    L.hi = hi_of(k);
    L.left = L.right = -1;
    L.tri = static_cast<std::uint32_t>(k);
    level[k] = slot;
  }
  for (std::size_t n = count; n > 1; n = (n + 1) / 2) {
    for (std::size_t i = 0; i + 1 < n; i += 2, --slot) {
      const std::int32_t a = level[i], b = level[i + 1];
      Node& N = nodes[slot];
      N.lo = nodes[a].lo.cwiseMin(nodes[b].lo);
      N.hi = nodes[a].hi.cwiseMax(nodes[b].hi);
      N.left = a;
      N.right = b;
      N.tri = 0;
      level[i / 2] = slot;  // i / 2 ≤ i: read before written
    }
    if (n % 2 == 1) level[n / 2] = level[n - 1];
  }
}

}  // namespace pendepth::geometry
