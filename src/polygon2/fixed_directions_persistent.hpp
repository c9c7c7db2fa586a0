// A partially persistent sorted sequence for a plane sweep (Sarnak–Tarjan's planar point
// location; Driscoll, Sarnak, Sleator, Tarjan's node copying), used by fixed_directions.cpp for
// the per-slab orders of DHS §6.
//
// Contract: elements are ids 0 .. N−1. Versions are numbered by the caller in increasing order
// (begin(v)); within a version the caller inserts (with a strict weak order `less` valid for the
// current version's elements) and erases elements, then calls commit(). Every committed version
// stays readable: first_not_behind(v, behind) returns the first element of version v's order for
// which behind(e) is false (behind must be true on a prefix of the order), and the element after
// it. Never reads `less` again after the insertion, so the caller may compare on a per-version
// reference line.
//
// How: the ephemeral structure is a treap (priorities a fixed hash of the id, so the build is
// reproducible; expected depth O(log N), expected O(1) rotations per update, each changing ≤ 3
// child pointers). Its pointer changes are made persistent by node copying: a persistent node
// holds its element, two child pointers and ONE spare modification slot (version, which child,
// new value); a child change at version v fills the slot, or, when it is taken, copies the node
// (with the current children) and changes the parent the same way — amortized O(1) new nodes per
// pointer change since the in-degree is 1 (DSST, Theorem 1). Colours/priorities and parent
// pointers stay ephemeral (only queries of old versions are needed).
//
// Complexity: N updates in expected O(N log N) time (plus the comparisons) and expected O(N)
// nodes of 20 bytes; a query reads one node per level: expected O(log N) calls of `behind`.
// The ephemeral arrays are released by finish().
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace pendepth::polygon2 {

class PersistentOrder {
 public:
  static constexpr std::uint32_t kNil = 0xffffffffu;

  explicit PersistentOrder(std::size_t elements)
      : left_(elements, kNil), right_(elements, kNil), parent_(elements, kNil), live_(elements, kNil),
        in_(elements, 0) {}

  void begin(std::uint32_t version) { version_ = version; }
  bool contains(std::uint32_t x) const { return in_[x] != 0; }

  template <class Less>
  void insert(std::uint32_t x, Less less) {
    left_[x] = right_[x] = kNil;
    if (root_ == kNil) {
      root_ = x;
      parent_[x] = kNil;
    } else {
      std::uint32_t y = root_;
      for (;;) {
        const int f = less(x, y) ? 0 : 1;
        const std::uint32_t c = child(y, f);
        if (c == kNil) {
          set_child(y, f, x);
          break;
        }
        y = c;
      }
      while (parent_[x] != kNil && above(x, parent_[x])) rotate_up(x);
    }
    in_[x] = 1;
    live_[x] = new_node(x);
    flush();
  }

  void erase(std::uint32_t x) {
    while (left_[x] != kNil && right_[x] != kNil) rotate_up(above(left_[x], right_[x]) ? left_[x] : right_[x]);
    const std::uint32_t c = left_[x] != kNil ? left_[x] : right_[x];
    const std::uint32_t p = parent_[x];
    if (p == kNil) {
      root_ = c;
      if (c != kNil) parent_[c] = kNil;
    } else {
      set_child(p, left_[p] == x ? 0 : 1, c);
    }
    in_[x] = 0;
    flush();
  }

  // Records the current order as version version_ (the last begin()).
  void commit() {
    if (roots_.size() <= version_) roots_.resize(version_ + 1, kNil);
    roots_[version_] = root_ == kNil ? kNil : live_[root_];
  }

  // Drops the ephemeral state; versions stay readable.
  void finish() {
    left_ = right_ = parent_ = live_ = {};
    in_ = {};
    dirty_ = {};
    nodes_.shrink_to_fit();
    roots_.shrink_to_fit();
  }

  // (first element of version v not behind, the element after it); kNil where absent.
  template <class Behind>
  std::pair<std::uint32_t, std::uint32_t> first_not_behind(std::uint32_t v, Behind behind) const {
    std::uint32_t n = v < roots_.size() ? roots_[v] : kNil, cand = kNil, before = kNil;
    while (n != kNil) {
      if (behind(nodes_[n].elem)) {
        n = read(n, 1, v);
      } else {
        before = cand;  // the deepest ancestor of the next candidate whose left subtree holds it
        cand = n;
        n = read(n, 0, v);
      }
    }
    if (cand == kNil) return {kNil, kNil};
    std::uint32_t r = read(cand, 1, v);
    if (r == kNil) return {nodes_[cand].elem, before == kNil ? kNil : nodes_[before].elem};
    for (std::uint32_t l = read(r, 0, v); l != kNil; l = read(r, 0, v)) r = l;
    return {nodes_[cand].elem, nodes_[r].elem};
  }

  // Whole order of version v (tests and checks; O(size)).
  std::vector<std::uint32_t> elements(std::uint32_t v) const {
    std::vector<std::uint32_t> out, stack;
    std::uint32_t n = v < roots_.size() ? roots_[v] : kNil;
    while (n != kNil || !stack.empty()) {
      for (; n != kNil; n = read(n, 0, v)) stack.push_back(n);
      n = stack.back();
      stack.pop_back();
      out.push_back(nodes_[n].elem);
      n = read(n, 1, v);
    }
    return out;
  }

  std::size_t node_count() const { return nodes_.size(); }
  std::size_t bytes() const {
    return nodes_.capacity() * sizeof(Node) + roots_.capacity() * sizeof(std::uint32_t) +
           (left_.capacity() + right_.capacity() + parent_.capacity() + live_.capacity()) * sizeof(std::uint32_t) +
           in_.capacity() + dirty_.capacity() * sizeof(dirty_[0]);
  }

 private:
  static constexpr std::uint32_t kNoMod = 0xffffffffu;
  struct Node {
    std::uint32_t elem, left, right;
    std::uint32_t mod;        // version·2 + child (0 left, 1 right), or kNoMod
    std::uint32_t mod_value;  // that child from that version on
  };

  // Child f of persistent node n as of version v.
  std::uint32_t read(std::uint32_t n, int f, std::uint32_t v) const {
    const Node& x = nodes_[n];
    if (x.mod != kNoMod && int(x.mod & 1) == f && (x.mod >> 1) <= v) return x.mod_value;
    return f ? x.right : x.left;
  }
  std::uint32_t latest(std::uint32_t n, int f) const { return read(n, f, 0xffffffffu); }

  static std::uint64_t hash(std::uint64_t z) {  // splitmix64: fixed treap priorities
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  static bool above(std::uint32_t a, std::uint32_t b) {  // a has the higher (distinct) priority
    const std::uint64_t ha = hash(a), hb = hash(b);
    return ha != hb ? ha > hb : a > b;
  }

  std::uint32_t child(std::uint32_t a, int f) const { return f ? right_[a] : left_[a]; }
  std::uint32_t live_of(std::uint32_t a) const { return a == kNil ? kNil : live_[a]; }

  void set_child(std::uint32_t a, int f, std::uint32_t b) {
    (f ? right_ : left_)[a] = b;
    if (b != kNil) parent_[b] = a;
    dirty_.push_back({a, std::uint8_t(f)});
  }

  void rotate_up(std::uint32_t x) {
    const std::uint32_t p = parent_[x], g = parent_[p];
    const int gf = g == kNil ? -1 : (left_[g] == p ? 0 : 1);
    if (left_[p] == x) {
      set_child(p, 0, right_[x]);
      set_child(x, 1, p);
    } else {
      set_child(p, 1, left_[x]);
      set_child(x, 0, p);
    }
    if (g == kNil) {
      root_ = x;
      parent_[x] = kNil;
    } else {
      set_child(g, gf, x);
    }
  }

  std::uint32_t new_node(std::uint32_t a) {
    nodes_.push_back({a, live_of(left_[a]), live_of(right_[a]), kNoMod, kNil});
    return std::uint32_t(nodes_.size() - 1);
  }

  // Makes the persistent child f of a (as of version_) match the ephemeral tree; node copying
  // climbs to the parent when a's spare slot is taken.
  void persist(std::uint32_t a, int f) {
    for (;;) {
      const std::uint32_t target = live_of(child(a, f));
      const std::uint32_t n = live_[a];
      if (latest(n, f) == target) return;
      Node& x = nodes_[n];
      if (x.mod == kNoMod || x.mod == 2 * version_ + std::uint32_t(f)) {
        x.mod = 2 * version_ + std::uint32_t(f);
        x.mod_value = target;
        return;
      }
      live_[a] = new_node(a);  // the copy has the current children
      const std::uint32_t p = parent_[a];
      if (p == kNil) return;  // the root: commit() reads live_[root_]
      f = left_[p] == a ? 0 : 1;
      a = p;
    }
  }

  void flush() {
    for (const auto& [a, f] : dirty_)
      if (in_[a]) persist(a, f);
    dirty_.clear();
  }

  std::vector<std::uint32_t> left_, right_, parent_, live_;  // ephemeral treap over element ids
  std::vector<std::uint8_t> in_;
  std::vector<std::pair<std::uint32_t, std::uint8_t>> dirty_;  // child pointers changed by the update
  std::uint32_t root_ = kNil, version_ = 0;
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> roots_;  // version ↦ persistent root
};

}  // namespace pendepth::polygon2
