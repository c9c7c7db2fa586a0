// Medial axis of the convex polygon M = P ⊕ (−Q) by the shrinking wavefront (DHS §3,
// Theorem 3.2; docs/algorithms.md §R3.1). N = |M|.
//
// The wavefront is M shrunk by time r: every edge line moves inward at unit speed, every vertex
// slides along the bisector of its two lines. A convex polygon has only edge events: edge i
// vanishes when the bisectors of its two end vertices meet, at the centre of the disk tangent to
// the lines prev(i), i, next(i). Events sit in a min-heap keyed by that radius (a radix heap,
// since radii are popped in non-decreasing order, behind a small batch of the next events that
// are prefetched: radius order is random in memory); an edge whose neighbours change gets a new
// stamp and a fresh entry, stale entries are skipped when popped (lazy deletion). Memory O(N).
//
// Departure from the recipe (docs/algorithms.md §R3.1): it solves the 3×3 system n_t·x + r = c_t by
// Cramer's rule, whose determinant cross(n_i − n_a, n_b − n_a) is O(Δ²) for consecutive normals Δ
// apart and is built from the cancelling differences n_i − n_a. Here each wavefront vertex carries
// its bisector line u·x = h with u computed without cancellation (rot90(n_a + n_b)/|n_a + n_b| when
// the lines are within 90°), anchored at the exact-ish vertex of M or at the node it came from; an
// event is the intersection of two such lines, determinant O(Δ). The position error of a node along
// its spokes is then O(ε·|M|/Δ) and across them O(ε·|M|), which is what routing needs.
#include "convex2/medial_axis.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace pendepth::convex2 {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Wavefront state of a live edge k of M, packed in one cache line (events are processed in
// radius order, which is random in memory): its line and the wavefront vertex (k, next) —
// bisector u·x = h and the medial node it started from. Event versions live in a separate dense
// array so that skipping the many stale queue entries stays in cache.
struct alignas(64) Wave {
  Vec2 n;                 // unit outward normal of line k
  Vec2 u;                 // bisector of vertex (k, next): u·x = h
  double c;               // offset of line k
  double h;
  std::uint32_t prev, next;
  std::int32_t org;       // medial node where vertex (k, next) started (kLeaf: a vertex of M)
};
constexpr std::uint32_t kDead = 0xffffffffu;

// Signs of cross(n_a, n_b) and n_a·n_b for edges a, b of M: the rounded unit normals decide when
// the value clears their error (each normal is within 5ε of the true one, so cross and dot are
// within 12ε + rounding), the exact edge vectors of M otherwise.
constexpr double kNormalFilter = 32 * 0x1p-53;
struct TurnSigns {
  const MinkowskiSum& M;
  const std::vector<Wave>& w;
  int cross_sign(std::uint32_t a, std::uint32_t b) const {
    const double v = cross(w[a].n, w[b].n);
    if (std::abs(v) > kNormalFilter) return v > 0 ? 1 : -1;
    Vec2 a0, a1, b0, b1;
    M.edge_points(a, a0, a1);
    M.edge_points(b, b0, b1);
    return predicates::cross_edges(a0, a1, b0, b1);
  }
  int dot_sign(std::uint32_t a, std::uint32_t b) const {
    const double v = w[a].n.dot(w[b].n);
    if (std::abs(v) > kNormalFilter) return v > 0 ? 1 : -1;
    Vec2 a0, a1, b0, b1;
    M.edge_points(a, a0, a1);
    M.edge_points(b, b0, b1);
    return predicates::dot_edges(a0, a1, b0, b1);
  }
  // Does the counter-clockwise turn from n_a to n_b (a != b) span 180° or more?
  bool wide(std::uint32_t a, std::uint32_t b) const {
    const int c = cross_sign(a, b);
    return c < 0 || (c == 0 && dot_sign(a, b) < 0);
  }
};

// Unit normal of the bisector {x : dist to line a = dist to line b} = {(n_b − n_a)·x = c_b − c_a},
// oriented along n_b − n_a. When the counter-clockwise turn from n_a to n_b is at most 90°,
// rot90(n_a + n_b) has the same direction and no cancellation (and stays right when the rounded
// normals coincide or are out of order).
Vec2 bisector_normal(const Vec2& na, const Vec2& nb, bool within_90) {
  if (within_90) {
    const Vec2 s = na + nb;
    return Vec2(-s.y(), s.x()) / s.norm();
  }
  const Vec2 d = nb - na;
  return d / d.norm();
}

// Intersection of u1·x = h1 and u2·x = h2; false unless cross(u1, u2) > 0 and the result is finite.
bool intersect(const Vec2& u1, double h1, const Vec2& u2, double h2, Vec2& x) {
  const double det = cross(u1, u2);
  x = Vec2((h1 * u2.y() - h2 * u1.y()) / det, (u1.x() * h2 - u2.x() * h1) / det);
  return det > 0 && std::isfinite(x.x()) && std::isfinite(x.y());
}

// Order-preserving map of finite doubles to unsigned integers.
std::uint64_t order_key(double r) {
  const auto b = std::bit_cast<std::uint64_t>(r);
  return (b >> 63) ? ~b : b | (std::uint64_t(1) << 63);
}

struct Event {
  std::uint64_t key;  // order_key(radius)
  std::uint32_t edge, stamp;
  bool operator>(const Event& o) const { return key > o.key; }
};

// Monotone min-priority queue (radix heap: buckets by the highest bit in which a key differs
// from the last key extracted). Sequential bucket scans instead of a binary heap's random
// sift-downs: the queue holds ~N entries and N reaches millions. Requires every pushed key to be
// >= last(); extraction is in non-decreasing key order.
class RadixHeap {
 public:
  bool empty() const { return count_ == 0; }
  std::uint64_t last() const { return last_; }
  void push(const Event& e) {
    buckets_[bucket(e.key)].push_back(e);
    ++count_;
  }
  Event pop() {  // requires !empty()
    if (buckets_[0].empty()) {
      std::size_t i = 1;
      while (buckets_[i].empty()) ++i;
      std::vector<Event>& from = buckets_[i];
      std::uint64_t least = from[0].key;
      for (const Event& e : from) least = std::min(least, e.key);
      last_ = least;
      for (const Event& e : from) buckets_[bucket(e.key)].push_back(e);  // all land below i
      from.clear();
    }
    const Event e = buckets_[0].back();
    buckets_[0].pop_back();
    --count_;
    return e;
  }
  void reserve(std::size_t n) { buckets_[64].reserve(n); }

 private:
  std::size_t bucket(std::uint64_t k) const { return std::size_t(std::bit_width(k ^ last_)); }
  std::array<std::vector<Event>, 65> buckets_;
  std::uint64_t last_ = 0;
  std::size_t count_ = 0;
};

// The event queue: a radix heap behind a small binary heap holding the next events. Events enter
// the front batch kBatch at a time (or directly, when they precede everything left in the radix
// heap), and `soon(edge)` is called for each as it enters, well before it is popped: the
// wavefront processes events in radius order, which is random in memory, so this is where the
// prefetches go. Radii are non-decreasing in exact arithmetic; a new event that precedes the
// current one only by rounding is clamped to it.
class EventQueue {
 public:
  static constexpr std::size_t kBatch = 16;
  void reserve(std::size_t n) { heap_.reserve(n); }
  template <class Soon>
  void push(double r, std::uint32_t edge, std::uint32_t stamp, Soon&& soon) {
    const Event e{std::max(order_key(r), popped_), edge, stamp};
    if (e.key >= heap_.last()) {
      heap_.push(e);
      return;
    }
    front_.push_back(e);
    std::push_heap(front_.begin(), front_.end(), std::greater<Event>());
    soon(edge);
  }
  template <class Soon>
  Event pop(Soon&& soon) {  // requires a non-empty queue
    // Every front event is <= heap_.last() <= every event left in the radix heap.
    if (front_.empty())
      for (std::size_t k = 0; k < kBatch && !heap_.empty(); ++k) {
        front_.push_back(heap_.pop());  // ascending: already a valid min-heap order
        soon(front_.back().edge);
      }
    std::pop_heap(front_.begin(), front_.end(), std::greater<Event>());
    const Event e = front_.back();
    front_.pop_back();
    popped_ = e.key;
    return e;
  }
  // The event most likely popped next (null if the front batch is empty).
  const Event* peek() const { return front_.empty() ? nullptr : &front_.front(); }

 private:
  RadixHeap heap_;
  std::vector<Event> front_;
  std::uint64_t popped_ = 0;
};

}  // namespace

MedialAxis medial_axis(const MinkowskiSum& M) {
  const std::size_t N = M.size();
  MedialAxis out;

  // Lines of M relative to the centre of its bounding box.
  Vec2 lo = M.vertex(0), hi = lo;
  for (std::size_t k = 1; k < N; ++k) {
    const Vec2 v = M.vertex(k);
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  out.origin = 0.5 * lo + 0.5 * hi;
  out.normal.resize(N);
  out.offset.resize(N);
  for (std::size_t k = 0; k < N; ++k) {
    out.normal[k] = M.outward_normal(k);
    out.offset[k] = out.normal[k].dot(M.vertex(k) - out.origin);
  }
  const auto& n = out.normal;

  // Wavefront: cyclic list of live edges.
  std::vector<Wave> w(N);
  std::vector<std::uint32_t> stamp(N, 0);  // version of k's event; kDead once k has collapsed
  const TurnSigns turn{M, w};
  for (std::size_t k = 0; k < N; ++k) {
    w[k].n = n[k];
    w[k].c = out.offset[k];
  }
  for (std::size_t k = 0; k < N; ++k) {
    const std::size_t k1 = (k + 1) % N;
    Wave& wk = w[k];
    wk.prev = std::uint32_t((k + N - 1) % N);
    wk.next = std::uint32_t(k1);
    wk.org = MedialAxis::kLeaf;
    // Consecutive edges of M turn by less than 180°.
    wk.u = bisector_normal(n[k], n[k1], turn.dot_sign(std::uint32_t(k), std::uint32_t(k1)) >= 0);
    wk.h = wk.u.dot(M.vertex(k1) - out.origin);
  }

  const std::size_t internal = N - 2;
  out.centre.reserve(internal);
  out.line.reserve(internal);
  out.adj.reserve(internal);
  out.wide.reserve(internal);
  auto add_node = [&](const Vec2& x, std::array<std::uint32_t, 3> lines,
                      std::array<std::int32_t, 3> adj) {
    const auto id = std::int32_t(out.centre.size());
    // The node consumes wavefront vertices whose origins are earlier event nodes; their pending
    // third branch (slot 2) leads here.
    for (int k = 0; k < 3; ++k)
      if (adj[k] >= 0) out.adj[adj[k]][2] = id;
    out.centre.push_back(x);
    out.line.push_back(lines);
    out.adj.push_back(adj);
    std::uint8_t wide = 3;
    for (std::uint8_t k = 0; k < 3 && wide == 3; ++k)
      if (turn.wide(lines[k], lines[(k + 1) % 3])) wide = k;
    out.wide.push_back(wide);
    return id;
  };

  // Event of edge i: centre where the bisectors of its end vertices meet, radius to line i.
  auto event = [&](std::uint32_t i, double& r, Vec2& x) {
    const Wave& wi = w[i];
    const Wave& wa = w[wi.prev];
    if (!intersect(wa.u, wa.h, wi.u, wi.h, x)) return false;
    r = wi.c - wi.n.dot(x);
    return std::isfinite(r);
  };

  auto soon = [&](std::uint32_t e) {
    __builtin_prefetch(&stamp[e]);
    __builtin_prefetch(&w[e]);
  };
  EventQueue queue;
  if (N > 3) queue.reserve(N);
  for (std::uint32_t i = 0; i < N && N > 3; ++i) {
    double r;
    Vec2 x;
    if (!event(i, r, x)) {
      out.ok = false;
      return out;
    }
    queue.push(r, i, 0, soon);
  }

  std::size_t live = N;
  std::uint32_t last = 0;
  while (live > 3) {
    const Event ev = queue.pop(soon);
    const std::uint32_t i = ev.edge;
    if (ev.stamp != stamp[i]) continue;  // stale, or edge already gone (kDead)
    if (const Event* up = queue.peek()) {  // the next event's neighbours, while this one runs
      const Wave& wn = w[up->edge];
      __builtin_prefetch(&w[wn.prev]);
      __builtin_prefetch(&w[wn.next]);
    }
    const Wave& wi = w[i];
    const std::uint32_t a = wi.prev, b = wi.next;
    Wave &wa = w[a], &wb = w[b];
    __builtin_prefetch(&w[wa.prev]);  // a's next event reads it
    // A current entry was computed from these same bisectors: recomputing gives the same centre.
    double radius;
    Vec2 x;
    event(i, radius, x);
    const std::int32_t id = add_node(x, {a, i, b}, {wa.org, wi.org, MedialAxis::kLeaf});
    // Edge i leaves the wavefront; the new vertex (a, b) starts at node id.
    stamp[i] = kDead;
    wa.next = b;
    wb.prev = a;
    --live;
    wa.u = bisector_normal(wa.n, wb.n, turn.dot_sign(a, b) >= 0 && !turn.wide(a, b));
    wa.h = wa.u.dot(x);
    wa.org = id;
    last = a;
    if (live == 3) break;
    for (std::uint32_t e : {a, b}) {
      double r;
      Vec2 ex;
      if (!event(e, r, ex)) {
        out.ok = false;
        return out;
      }
      queue.push(r, e, ++stamp[e], soon);
    }
  }

  // Final three lines a, b, c: their three bisectors concur; intersect the best-conditioned pair.
  const std::uint32_t a = last, b = w[a].next, cc = w[b].next;
  const Wave* v[3] = {&w[a], &w[b], &w[cc]};
  int best = 0;
  double best_det = -1;
  for (int k = 0; k < 3; ++k) {
    const double det = cross(v[k]->u, v[(k + 1) % 3]->u);
    if (det > best_det) best_det = det, best = k;
  }
  Vec2 x;
  const Wave &p = *v[best], &q = *v[(best + 1) % 3];
  if (!intersect(p.u, p.h, q.u, q.h, x)) {
    out.ok = false;
    return out;
  }
  out.root = add_node(x, {a, b, cc}, {w[a].org, w[b].org, w[cc].org});
  return out;
}

}  // namespace pendepth::convex2
