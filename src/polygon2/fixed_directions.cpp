// σ_d for a fixed set of directions (DHS §6): per direction d, a decomposition of the overlap set
// O into slabs parallel to d with persistent point location (Sarnak–Tarjan), so each query is two
// binary searches, in O(n) space per direction.
//
// Contract: PolygonDirectionSet::along(t, k) == PolygonDepth2::along(t, direction(k)), bit for bit
// (same piece of ∂O, same exact hit, same result builder). The set refers to the PolygonDepth2's
// structure, which must outlive it (moving the PolygonDepth2 is fine: its state is on the heap).
//
// Construction for one direction d (u(x) = cross(d, x), the coordinate across d):
//   1. Split every piece of the union boundary ∂O (union_boundary.hpp) into u-MONOTONE sub-pieces:
//      a segment is one (or none, if parallel to d); an arc — a convex chain of B edges — changes
//      the sign of cross(d, e) at most twice, so it is cut at those B vertices into ≤ 3 runs
//      (elements parallel to d, of zero u-extent, are dropped). Each sub-piece knows whether the
//      ray along +d LEAVES O through it (u increasing along the piece: O is on its left) or enters.
//   2. The u-values of all sub-piece ends (symbolic points: convolution vertices p + b, crossings of
//      two element lines) are sorted with exact comparisons and merged into K distinct keys. The
//      open slabs between consecutive keys are crossed by sub-pieces that span them entirely, and
//      these never cross inside a slab (pieces of ∂O meet only at their ends, which are keys), so
//      along d they are totally ordered: that order is computed on one reference line t_s + λ·d
//      inside each slab (a double point whose u is certified strictly inside the slab), with the
//      exact cut comparison of convolved_triangles.hpp; coincident slit copies (opposite
//      orientation) put the leaving copy first.
//   3. A sweep over the slabs keeps that order in a partially persistent sorted sequence
//      (fixed_directions_persistent.hpp: a treap made persistent by node copying): at key k the
//      sub-pieces ending there are erased and those starting there inserted by binary search on
//      slab k's reference line; the result is committed as version k. Inserting by comparisons on
//      a later slab than the one where the others were ordered is sound because the order of two
//      sub-pieces is the same in every slab both span: a strict order cannot flip (no crossings),
//      and a slit tie resolves consistently — where the two copies separate, the leaving one is
//      behind, else O would lie on both sides of both. (Same-orientation coincident copies cannot
//      bound a union.)
// Query (t, d): binary search of u(t) among the keys (exact), then a descent of the slab's version
// for the first sub-piece not behind t and the one after it (exact side test: the element of the
// sub-piece covering u(t), a binary search over its B edges for arcs, then the sign of λ on that
// element's line). t ∈ O iff that sub-piece exists, t is not on it, and the ray leaves O through
// it; then σ_d is the first hit of the ray with that piece (UnionBoundary::first_hit), turned into
// a result by the same builder as PolygonDepth2::along.
//
// Departures from the paper and why:
//   - The paper's decomposition with point location is realized as the slab method made
//     persistent (option (b) of issue 4) rather than a trapezoidal map with a randomized
//     point-location DAG: the slab order and its exact comparisons on certified reference lines
//     are what the old slab code already had and the tests already pin; a trapezoidal map would
//     need exact comparisons of two curved sub-pieces at a shared end (a limit, not a point
//     test), new symbolic code for no gain in the bounds. Same bounds: O(n) space, O(log n) query.
//   - A query whose u(t) equals a key exactly (the ray runs along a slab boundary line through an
//     end of a piece), or lands in a slab too thin to hold a double reference point, is answered
//     by PolygonDepth2::along itself (exact; measure-zero placements). So is a query whose first
//     boundary point is a tie between two coincident pieces (a slit of ∂O, where Q fits a pocket
//     exactly): along() breaks that tie by its own search order, and deferring to it keeps the
//     witnesses and features identical. polygon2::fixed_direction_fallbacks() counts these
//     deferrals process-wide (a test and benchmark hook). Sub-pieces starting in a thin slab are
//     inserted at the next certified one.
// Complexity per direction, E = O(n) sub-pieces: build O(E log E) exact comparisons for the keys
// plus expected O(E log E) cut comparisons (each O(log m) for arcs) for the sweep; space O(E):
// the sub-pieces, the keys, one root and one flag per slab, and expected O(E) persistent nodes
// (per sub-piece: a 20-byte record, two 4-byte key ends, a 4-byte root and a bit for each slab it
// starts, and a few 20-byte persistent nodes; bytes per piece of ∂O in docs/benchmarks.md — the
// per-slab lists this replaced took Θ(n²) on combs seen across their teeth); query expected
// O(log n · log m) exact predicates (O(log n) when the pieces met are segments).
#include <pendepth/depth2_polygon_convex.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <string>

#include "geometry/exact.hpp"
#include "polygon2/fixed_directions_persistent.hpp"
#include "polygon2/query_impl.hpp"
#include "polygon2/union_boundary.hpp"

namespace pendepth {

namespace polygon2 {
namespace {
std::atomic<std::size_t> g_fallbacks{0};
}  // namespace
/// Queries answered by PolygonDepth2::along instead of the slabs, since the start of the process.
std::size_t fixed_direction_fallbacks() { return g_fallbacks.load(std::memory_order_relaxed); }
}  // namespace polygon2

using polygon2::Cut;
using polygon2::EndPoint;
using polygon2::Piece;
using polygon2::UnionBoundary;

namespace {

Cut zero_cut() {
  Cut c;
  c.pt = c.pb = c.e0 = c.e1 = Vec2(0, 0);
  return c;
}

// A symbolic point: a0 + a1 (Plain), the natural end pt + pb + e1 − e0 of `line` (Mu1), or the
// crossing of `line` and `other` (Crossing). Its u-value is f/D with D = 1 unless Crossing.
struct SymPoint {
  enum class Kind : std::uint8_t { Plain, Mu1, Crossing };
  Kind kind = Kind::Plain;
  Vec2 a0{0, 0}, a1{0, 0};
  Cut line = zero_cut(), other = zero_cut();
};

// u·D for X (u(x) = cross(d, x)).
template <class Lift>
auto u_num(const SymPoint& X, const Vec2& d, Lift L) {
  const auto dx = L(d.x()), dy = L(d.y());
  switch (X.kind) {
    case SymPoint::Kind::Plain:
      return dx * (L(X.a0.y()) + L(X.a1.y())) - dy * (L(X.a0.x()) + L(X.a1.x()));
    case SymPoint::Kind::Mu1: {
      const Cut& c = X.line;
      return dx * (L(c.pt.y()) + L(c.pb.y()) + L(c.e1.y()) - L(c.e0.y())) -
             dy * (L(c.pt.x()) + L(c.pb.x()) + L(c.e1.x()) - L(c.e0.x()));
    }
    case SymPoint::Kind::Crossing:
    default: {
      const Cut &c = X.line, &o = X.other;
      const auto ax = L(c.pt.x()) + L(c.pb.x()), ay = L(c.pt.y()) + L(c.pb.y());
      const auto ex = L(c.e1.x()) - L(c.e0.x()), ey = L(c.e1.y()) - L(c.e0.y());
      const auto fx = L(o.e1.x()) - L(o.e0.x()), fy = L(o.e1.y()) - L(o.e0.y());
      const auto wx = L(o.pt.x()) + L(o.pb.x()) - ax, wy = L(o.pt.y()) + L(o.pb.y()) - ay;
      const auto N = wx * fy - wy * fx;  // μ = N / D on c's line
      const auto D = ex * fy - ey * fx;
      return (dx * ay - dy * ax) * D + N * (dx * ey - dy * ex);
    }
  }
}

template <class Lift>
auto u_den(const SymPoint& X, Lift L) {
  if (X.kind != SymPoint::Kind::Crossing) return L(1.0);
  const Cut &c = X.line, &o = X.other;
  return (L(c.e1.x()) - L(c.e0.x())) * (L(o.e1.y()) - L(o.e0.y())) -
         (L(c.e1.y()) - L(c.e0.y())) * (L(o.e1.x()) - L(o.e0.x()));
}

int den_sign(const SymPoint& X) {
  if (X.kind != SymPoint::Kind::Crossing) return 1;
  return exact::exact_sign([&](auto L) { return u_den(X, L); });
}

// Exact sign of u(X) − u(Y).
int compare_u(const SymPoint& X, const SymPoint& Y, const Vec2& d) {
  const int s = exact::exact_sign([&](auto L) { return u_num(X, d, L) * u_den(Y, L) - u_num(Y, d, L) * u_den(X, L); });
  return s * den_sign(X) * den_sign(Y);
}

// Exact sign of u(t) − u(X).
int compare_u(const Vec2& t, const SymPoint& X, const Vec2& d) {
  const int s = exact::exact_sign(
      [&](auto L) { return (L(d.x()) * L(t.y()) - L(d.y()) * L(t.x())) * u_den(X, L) - u_num(X, d, L); });
  return s * den_sign(X);
}

// Exact sign of u(t) − u(pt + pb) for the natural start of element c.
int compare_u_start(const Vec2& t, const Cut& c, const Vec2& d) {
  return exact::exact_sign([&](auto L) {
    return L(d.x()) * (L(t.y()) - L(c.pt.y()) - L(c.pb.y())) - L(d.y()) * (L(t.x()) - L(c.pt.x()) - L(c.pb.x()));
  });
}

// Exact sign of cross(d, e1 − e0): the u-direction of element c.
int u_direction(const Cut& c, const Vec2& d) {
  return exact::exact_sign([&](auto L) {
    return L(d.x()) * (L(c.e1.y()) - L(c.e0.y())) - L(d.y()) * (L(c.e1.x()) - L(c.e0.x()));
  });
}

// u(X) to a few ulps (for choosing reference points only; never for a decision).
double u_value(const SymPoint& X, const Vec2& d) {
  return exact::accurate_ratio([&](auto L) { return u_num(X, d, L); }, [&](auto L) { return u_den(X, L); });
}

SymPoint natural_start(const Cut& c) {
  SymPoint s;
  s.a0 = c.pt;
  s.a1 = c.pb;
  return s;
}

SymPoint natural_end(const Cut& c) {
  SymPoint s;
  s.kind = SymPoint::Kind::Mu1;
  s.line = c;
  return s;
}

SymPoint end_point(const EndPoint& e, const Cut& element) {
  switch (e.kind) {
    case EndPoint::Kind::Mu0: return natural_start(element);
    case EndPoint::Kind::Mu1: return natural_end(element);
    case EndPoint::Kind::Crossing: {
      SymPoint s;
      s.kind = SymPoint::Kind::Crossing;
      s.line = element;
      s.other = e.other;
      return s;
    }
    case EndPoint::Kind::Point:
    default: {
      SymPoint s;
      s.a0 = e.p;
      s.a1 = e.b;
      return s;
    }
  }
}

}  // namespace

struct PolygonDirectionSet::Impl {
  // A u-monotone run of elements [j0, j1] of one piece of ∂O.
  struct Sub {
    std::uint32_t piece : 31 = 0;
    std::uint32_t leaves : 1 = 0;  // u increases along the piece: the ray along +d leaves O here
    std::uint32_t j0 = 0, j1 = 0;
    std::uint32_t lo = 0, hi = 0;  // key ranks of its u-range ends (lo < hi)
  };
  // One end of a sub-piece, for the key list: the low (u-min) or high end.
  struct KeyRef {
    std::uint32_t sub : 31 = 0;
    std::uint32_t high : 1 = 0;
  };
  struct Direction {
    Vec2 given{0, 0}, d{0, 0};  // as given, and scaled by a power of two (as along() does)
    std::vector<Sub> subs;
    std::vector<KeyRef> keys;          // distinct u-values, increasing
    polygon2::PersistentOrder order;   // version s = the sub-pieces spanning slab s, along d
    std::vector<bool> thin;            // slab without a certified reference line
    Direction() : order(0) {}
  };

  const PolygonDepth2::Impl* pd = nullptr;  // stable when the PolygonDepth2 is moved
  const UnionBoundary* ub = nullptr;
  std::vector<Direction> dirs;

  SymPoint sub_end(const Sub& s, bool high) const {
    // The traversal start of the sub is its low end when it leaves O (u increasing).
    const bool at_start = high != s.leaves;
    const Piece& pc = ub->pieces()[s.piece];
    const std::size_t last = ub->element_count(s.piece) - 1;
    if (at_start) {
      const Cut el = ub->element(s.piece, s.j0);
      return s.j0 == 0 ? end_point(pc.start, el) : natural_start(el);
    }
    const Cut el = ub->element(s.piece, s.j1);
    return s.j1 == last ? end_point(pc.end, el) : natural_end(el);
  }
  SymPoint key_point(const Direction& D, std::size_t k) const {
    const KeyRef& r = D.keys[k];
    return sub_end(D.subs[r.sub], r.high);
  }

  // The element of sub s whose u-range contains u(t) (u(t) strictly inside the sub's u-range).
  Cut covering_element(const Direction& D, const Sub& s, const Vec2& t) const {
    std::uint32_t lo = s.j0, hi = s.j1;  // answer in [lo, hi]
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo + 1) / 2;
      const int c = compare_u_start(t, ub->element(s.piece, mid), D.d);
      // Elements run in increasing u when the sub leaves O, else decreasing.
      const bool past = s.leaves ? c > 0 : c < 0;
      if (past) lo = mid;
      else hi = mid - 1;
    }
    return ub->element(s.piece, lo);
  }

  // Sign of λ where t + λ·d meets sub s (u(t) inside the sub's open u-range).
  int side(const Direction& D, const Sub& s, const Vec2& t) const {
    return polygon2::cut_sign(covering_element(D, s, t), t, D.d);
  }

  // PolygonDepth2::along's own steps (src/polygon2/ray_shooting.cpp), for the deferred queries.
  Depth2 deferred(const Vec2& t, const Vec2& d) const {
    polygon2::g_fallbacks.fetch_add(1, std::memory_order_relaxed);
    Depth2 r;
    r.kind = DepthKind::Directional;
    polygon2::Hit h;
    if (!ub->in_overlap(t) || !ub->ray_first(t, d, h)) return r;
    r = polygon2::result_at_hit(*pd, h, t, d);
    r.kind = DepthKind::Directional;
    r.overlapping = true;
    return r;
  }

  void build(Direction& D);
};

void PolygonDirectionSet::Impl::build(Direction& D) {
  const Vec2& d = D.d;
  // 1. u-monotone sub-pieces.
  for (std::uint32_t k = 0; k < ub->pieces().size(); ++k) {
    const std::size_t count = ub->element_count(k);
    std::uint32_t j = 0;
    while (j < count) {
      const int s = u_direction(ub->element(k, j), d);
      if (s == 0) {
        ++j;
        continue;
      }
      std::uint32_t e = j;
      while (e + 1 < count && u_direction(ub->element(k, e + 1), d) == s) ++e;
      Sub sub;
      sub.piece = k;
      sub.j0 = j;
      sub.j1 = e;
      sub.leaves = s > 0;
      // A run may still have zero u-extent when its end is cut at its start (zero-length piece).
      if (compare_u(sub_end(sub, false), sub_end(sub, true), d) < 0) D.subs.push_back(sub);
      j = e + 1;
    }
  }
  // 2. Keys: all sub ends sorted by u, merged when equal.
  std::vector<KeyRef> ends;
  ends.reserve(2 * D.subs.size());
  for (std::uint32_t i = 0; i < D.subs.size(); ++i) {
    ends.push_back({i, false});
    ends.push_back({i, true});
  }
  auto point = [&](const KeyRef& r) { return sub_end(D.subs[r.sub], r.high); };
  std::sort(ends.begin(), ends.end(), [&](const KeyRef& a, const KeyRef& b) { return compare_u(point(a), point(b), d) < 0; });
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (D.keys.empty() || compare_u(point(D.keys.back()), point(ends[i]), d) != 0) D.keys.push_back(ends[i]);
    Sub& s = D.subs[ends[i].sub];
    (ends[i].high ? s.hi : s.lo) = std::uint32_t(D.keys.size() - 1);
  }
  // 3. Sweep the slabs: the sub-pieces spanning slab k, ordered along d on a reference line,
  // form version k of a persistent sorted sequence. Sub-pieces do not cross inside slabs, so
  // version k is version k − 1 minus the sub-pieces ending at key k plus those starting there,
  // inserted by binary search on slab k's reference line.
  const std::size_t slabs = D.keys.empty() ? 0 : D.keys.size() - 1;
  std::vector<std::uint32_t> start_begin(slabs + 2, 0), end_begin(slabs + 2, 0);  // CSR by key
  for (const Sub& s : D.subs) ++start_begin[s.lo + 1], ++end_begin[s.hi + 1];
  for (std::size_t k = 0; k <= slabs; ++k) start_begin[k + 1] += start_begin[k], end_begin[k + 1] += end_begin[k];
  std::vector<std::uint32_t> starting(D.subs.size()), ending(D.subs.size());
  {
    std::vector<std::uint32_t> fs(start_begin.begin(), start_begin.end() - 1), fe(end_begin.begin(), end_begin.end() - 1);
    for (std::uint32_t i = 0; i < D.subs.size(); ++i) starting[fs[D.subs[i].lo]++] = i, ending[fe[D.subs[i].hi]++] = i;
  }
  D.order = polygon2::PersistentOrder(D.subs.size());
  D.thin.assign(slabs, false);
  std::vector<Cut> cache(D.subs.size());  // covering element on the current reference line
  std::vector<std::uint32_t> stamp(D.subs.size(), std::uint32_t(-1));
  std::vector<std::uint32_t> pending;  // started in thin slabs, not inserted yet
  const double dd = d.x() * d.x() + d.y() * d.y();
  const Vec2 across(-d.y(), d.x());  // u(s·across) = s·|d|²
  for (std::size_t k = 0; k < slabs; ++k) {
    D.order.begin(std::uint32_t(k));
    for (std::uint32_t e = end_begin[k]; e < end_begin[k + 1]; ++e)
      if (D.order.contains(ending[e])) D.order.erase(ending[e]);
    const SymPoint a = key_point(D, k), b = key_point(D, k + 1);
    const double ua = u_value(a, d), ub_ = u_value(b, d);
    // A double point strictly inside the slab, certified exactly; a few candidates.
    Vec2 ref;
    bool ok = false;
    for (double w : {0.5, 0.25, 0.75, 0.125, 0.875}) {
      ref = ((ua + w * (ub_ - ua)) / dd) * across;
      if (compare_u(ref, a, d) > 0 && compare_u(ref, b, d) < 0) {
        ok = true;
        break;
      }
    }
    if (!ok) {
      D.thin[k] = true;  // queries here defer; its new sub-pieces wait for the next certified slab
      pending.insert(pending.end(), starting.begin() + start_begin[k], starting.begin() + start_begin[k + 1]);
      continue;
    }
    // Strict total order on this slab's sub-pieces: along d on the reference line; coincident
    // copies (a slit) leaving first, then by index.
    auto cut = [&](std::uint32_t i) -> const Cut& {
      if (stamp[i] != k) {
        cache[i] = covering_element(D, D.subs[i], ref);
        stamp[i] = std::uint32_t(k);
      }
      return cache[i];
    };
    auto less = [&](std::uint32_t x, std::uint32_t y) {
      const int c = polygon2::compare_cuts(cut(x), cut(y), ref, d);
      if (c != 0) return c < 0;
      if (D.subs[x].leaves != D.subs[y].leaves) return D.subs[x].leaves != 0;
      return x < y;
    };
    for (std::uint32_t i : pending)
      if (D.subs[i].hi > k) D.order.insert(i, less);
    pending.clear();
    for (std::uint32_t e = start_begin[k]; e < start_begin[k + 1]; ++e) D.order.insert(starting[e], less);
    D.order.commit();
  }
  D.order.finish();
  D.subs.shrink_to_fit();
  D.keys.shrink_to_fit();
}

PolygonDirectionSet::PolygonDirectionSet(const PolygonDepth2& pd, std::vector<Vec2> directions)
    : impl_(std::make_unique<Impl>()) {
  impl_->pd = &polygon_depth_impl(pd);
  impl_->ub = &polygon_depth_impl(pd).U;
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const Vec2& d = directions[k];
    if (!std::isfinite(d.x()) || !std::isfinite(d.y()))
      throw InvalidInput("direction " + std::to_string(k) + " has a non-finite coordinate");
    if (d.x() == 0 && d.y() == 0) throw InvalidInput("direction " + std::to_string(k) + " is the zero vector");
  }
  impl_->dirs.resize(directions.size());
  for (std::size_t k = 0; k < directions.size(); ++k) {
    Impl::Direction& D = impl_->dirs[k];
    D.given = directions[k];
    D.d = polygon2::check_and_scale(Vec2(0, 0), directions[k]);
    impl_->build(D);
  }
}

PolygonDirectionSet::~PolygonDirectionSet() = default;
PolygonDirectionSet::PolygonDirectionSet(PolygonDirectionSet&&) noexcept = default;
PolygonDirectionSet& PolygonDirectionSet::operator=(PolygonDirectionSet&&) noexcept = default;

std::size_t PolygonDirectionSet::size() const { return impl_->dirs.size(); }
const Vec2& PolygonDirectionSet::direction(std::size_t k) const { return impl_->dirs.at(k).given; }

std::size_t PolygonDirectionSet::bytes() const {
  std::size_t b = sizeof(Impl) + impl_->dirs.capacity() * sizeof(Impl::Direction);
  for (const auto& D : impl_->dirs)
    b += D.subs.capacity() * sizeof(Impl::Sub) + D.keys.capacity() * sizeof(Impl::KeyRef) + D.order.bytes() +
         D.thin.capacity() / 8;
  return b;
}

Depth2 PolygonDirectionSet::along(const Vec2& t, std::size_t k) const {
  if (k >= impl_->dirs.size())
    throw InvalidInput("direction index " + std::to_string(k) + " out of range (" + std::to_string(impl_->dirs.size()) +
                       " directions)");
  const Impl::Direction& D = impl_->dirs[k];
  polygon2::check_and_scale(t, D.d);  // validates t
  Depth2 outside;
  outside.kind = DepthKind::Directional;
  // Slab of u(t): the first key with u(key) >= u(t).
  std::size_t lo = 0, hi = D.keys.size();
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (compare_u(t, impl_->key_point(D, mid), D.d) > 0) lo = mid + 1;
    else hi = mid;
  }
  if (lo == 0 || lo == D.keys.size()) return outside;  // beyond ∂O across d: t ∉ O
  if (compare_u(t, impl_->key_point(D, lo), D.d) == 0 || D.thin[lo - 1]) {
    return impl_->deferred(t, D.d);
  }
  // First sub-piece not behind t, and the next one.
  const auto [first, next] = D.order.first_not_behind(
      std::uint32_t(lo - 1), [&](std::uint32_t i) { return impl_->side(D, D.subs[i], t) < 0; });
  if (first == polygon2::PersistentOrder::kNil) return outside;
  const Impl::Sub& s = D.subs[first];
  if (!s.leaves || impl_->side(D, s, t) == 0) return outside;  // t ∉ O, or t on ∂O
  // A coincident copy next in the order (a slit of ∂O, or pieces touching at this point): the
  // first boundary point is a tie between pieces, which along() breaks by its own search order;
  // defer to it so witnesses and features are the same.
  polygon2::Hit h;
  if ((next != polygon2::PersistentOrder::kNil &&
       polygon2::compare_cuts(impl_->covering_element(D, s, t), impl_->covering_element(D, D.subs[next], t), t, D.d) ==
           0) ||
      !impl_->ub->first_hit(s.piece, t, D.d, h)) {
    return impl_->deferred(t, D.d);
  }
  Depth2 r = polygon2::result_at_hit(*impl_->pd, h, t, D.d);
  r.kind = DepthKind::Directional;
  r.overlapping = true;
  return r;
}

}  // namespace pendepth
