// Pair3 on a non-convex mesh P against a point q, in either role (issue 16 item 4: "a point Q
// gives the signed distance field of P"; contract in mesh_mixed.hpp).
//
// O = int P − q (overlap ⇔ the placed point is interior to the mesh). Everything is decided on
// the mesh's own triangles (closed, outward; the convex decomposition is not used, so overlap, σ,
// σ_d and the distance agree to the last bit of the exact placed point):
//   overlap   x ∈ int P ⇔ x on no triangle (exact: in its plane and inside its three edges) and
//             an odd number of proper crossings of a ray from x (exact signs; a ray through an
//             edge or a vertex, or in a triangle's plane, is detected exactly and replaced by the
//             next direction of the moment curve (1, s, s²): parity_inside).
//   σ, sd     dist(x, ∂P) = the least distance to a triangle (each flat_flat_distance: exact
//             decisions, a few ulps), triangles in increasing box distance, stopping when the box
//             distance exceeds the best: σ = that distance inside, sd = ± it (0 on the surface).
//             Exact (lower == upper).
//   σ_d, cast the first parameter λ >= 0 where the ray x + λ·d' meets a closed triangle (d' the
//             direction in the mesh's frame; the point leaves int P, resp. first touches P, there;
//             a cast from a point on the surface is 0, the nearest triangle's distance being 0):
//             the line meets the closed triangle ⇔ the three Plücker signs d'·((a − x) × (b − x))
//             over its edges do not disagree (exact signs), λ = n·(a − x)/(n·d') with its exact
//             sign; a triangle whose plane holds the line is skipped (the line then reaches it
//             through an edge shared with a triangle it crosses, at the same λ). x is the exact
//             placed point R·p + tq − tp (R, tq, tp the relative pose in doubles, as the mesh
//             engines); λ accurate to ~1 ulp; the least of accurate values is accurate.
//   separation the last exit: the hits in increasing λ; between two consecutive distinct hits
//             the point is inside or outside throughout, decided by the exact overlap test at the
//             midpoint; the answer is the last hit preceded by an inside stretch (0 when none).
// Ties: σ / sd take the least triangle index among equal distances, rays the least (λ, index).
// Searches go through the box tree over the triangles (tri_tree.hpp, built once per pair): the
// nearest triangle best-first by box distance, the ray's triangles by a conservative ray–box
// test; the tree only prunes, so the answers equal the linear scan's (MixedPair::linear, the
// tests' reference) bit for bit.
// Cost: O(log T + k) nodes and k exact tests per query typically (T triangles, k the triangles
// near x or along the ray), O(T) worst case (a ray grazing many boxes); build O(T log T).
#include "mesh3/mesh_mixed.hpp"

#include "geometry/exact.hpp"
#include "mesh3/lifted3.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>

namespace pendepth::mesh3 {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using lifted::A3;
using lifted::cross;
using lifted::dot;
using lifted::lv;
using lifted::sub;

// The point in the mesh's frame, exactly x = R p + tq − tp, and the ray's direction there.
struct Frame : MeshFrame {
  Vec3 p;
  Vec3 x;  // rounded
  template <class L>
  auto placed(L lift) const {
    const auto q = lv(lift, p);
    A3<decltype(lift(0.0))> r;
    for (int i = 0; i < 3; ++i)
      r[i] = lift(R(i, 0)) * q[0] + lift(R(i, 1)) * q[1] + lift(R(i, 2)) * q[2] + lift(tq[i]) - lift(tp[i]);
    return r;
  }
};

// Q's pose moved by v.
Pose3 moved(const Pose3& pose_q, const Vec3& v) {
  Pose3 q = pose_q;
  q.translation += v;
  return q;
}

Frame frame(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3* d) {
  Frame f{mesh_frame(m, pose_p, pose_q, d), m.pt.v[0], {}};
  f.x = f.R * f.p + (f.tq - f.tp);
  return f;
}

double box_distance(const std::array<Vec3, 2>& b, const Vec3& x) {
  Vec3 g = Vec3::Zero();
  for (int k = 0; k < 3; ++k) g[k] = x[k] < b[0][k] ? b[0][k] - x[k] : x[k] > b[1][k] ? x[k] - b[1][k] : 0.0;
  return g.norm();
}

double margin(const Frame& f, const MixedPair& m) {
  return 0x1p-30 * (f.x.norm() + f.tq.norm() + f.tp.norm() + f.p.norm() + m.radius_other) + 0x1p-1000;
}

// The exact distance of triangle i and the point (mesh pair roles: triangle as A).
Distance3 tri_distance(const MixedPair& m, std::size_t i, const Pose3& pose_p, const Pose3& pose_q) {
  const Pose3& pm = m.mesh_is_p ? pose_p : pose_q;
  const Pose3& po = m.mesh_is_p ? pose_q : pose_p;
  return convex3::flat_flat_distance(m.tri_flat[i], pm, m.pt, po);
}

struct Hit {
  double lambda;  // in units of f.d
  std::size_t t;
  bool operator<(const Hit& o) const { return lambda < o.lambda || (lambda == o.lambda && t < o.t); }
};

// Visits the triangles a ray from the placed point may meet: all of them (linear reference) or
// those whose box the tree's conservative ray–box test keeps.
template <class F>
void ray_candidates(const MixedPair& m, const Frame& f, const Vec3& d, F&& visit) {
  if (m.linear) {
    for (std::size_t t = 0; t < m.tri.size(); ++t) visit(t);
  } else {
    m.tree.along_ray(f.x, d, margin(f, m), [&](std::uint32_t t) { visit(t); });
  }
}

// Every λ >= 0 where the ray meets a closed triangle, sorted by (λ, triangle).
std::vector<Hit> hits(const MixedPair& m, const Frame& f) {
  std::vector<Hit> out;
  ray_candidates(m, f, f.d, [&](std::size_t t) {
    const auto& T = m.tri[t];
    const int den = exact::exact_sign([&](auto L) {
      return dot(cross(sub(lv(L, T[1]), lv(L, T[0])), sub(lv(L, T[2]), lv(L, T[0]))), lv(L, f.d));
    });
    if (den == 0) return;  // the line is parallel to the plane (or in it: file comment)
    bool pos = false, neg = false;
    for (int e = 0; e < 3 && !(pos && neg); ++e) {
      const int s = exact::exact_sign([&](auto L) {
        const auto x = f.placed(L);
        return dot(lv(L, f.d), cross(sub(lv(L, T[e]), x), sub(lv(L, T[(e + 1) % 3]), x)));
      });
      pos = pos || s > 0, neg = neg || s < 0;
    }
    if (pos && neg) return;
    auto num = [&](auto L) {
      return dot(cross(sub(lv(L, T[1]), lv(L, T[0])), sub(lv(L, T[2]), lv(L, T[0]))), sub(lv(L, T[0]), f.placed(L)));
    };
    const int sn = exact::exact_sign(num);
    if (sn * den < 0) return;  // behind the start
    const double lambda = sn == 0 ? 0.0 : exact::accurate_ratio(num, [&](auto L) {
      return dot(cross(sub(lv(L, T[1]), lv(L, T[0])), sub(lv(L, T[2]), lv(L, T[0]))), lv(L, f.d));
    });
    out.push_back({lambda, t});
  });
  std::sort(out.begin(), out.end());
  return out;
}

// Is the exact placed point on the closed triangle T (of nonzero area)? In T's plane, and on the
// inner side (or on) each edge within that plane: n·((b − a) × (x − a)) >= 0, n = (T1 − T0) × (T2 − T0).
bool on_triangle(const std::array<Vec3, 3>& T, const Frame& f) {
  auto n = [&](auto L) { return cross(sub(lv(L, T[1]), lv(L, T[0])), sub(lv(L, T[2]), lv(L, T[0]))); };
  if (exact::exact_sign([&](auto L) { return dot(n(L), sub(f.placed(L), lv(L, T[0]))); }) != 0) return false;
  for (int e = 0; e < 3; ++e)
    if (exact::exact_sign([&](auto L) {
          const auto a = lv(L, T[e]);
          return dot(n(L), cross(sub(lv(L, T[(e + 1) % 3]), a), sub(f.placed(L), a)));
        }) < 0)
      return false;
  return true;
}

// The exact placed point on the surface: on some closed triangle of nonzero area (a zero-area
// triangle of a closed mesh lies on its neighbours' edges).
bool on_surface(const MixedPair& m, const Frame& f) {
  bool on = false;
  auto test = [&](std::size_t t) { on = on || (!m.tri_zero[t] && on_triangle(m.tri[t], f)); };
  if (m.linear) {
    for (std::size_t t = 0; t < m.tri.size() && !on; ++t) test(t);
  } else {
    m.tree.near_point(f.x, margin(f, m), [&](std::uint32_t t) { test(t); });
  }
  return on;
}

// Ray parity, for a point on no triangle. The ray x + λ·d, λ > 0, d = (q², p·q, p²) (a point of
// the moment curve (1, s, s²), s = p/q: any three are linearly independent, all components exact
// doubles). Per triangle of nonzero area, exact signs: a proper crossing (λ > 0, the three
// Plücker signs d·((a − x) × (b − x)) nonzero and equal) flips the parity; the ray through an edge
// or vertex (a zero Plücker sign among non-disagreeing ones, λ > 0), or lying in a triangle's
// plane, makes d degenerate: the next s is tried. The degenerate directions lie on the planes
// through x and an edge or a triangle's plane (x on no triangle), each holding at most two
// moment-curve directions: at most 2·(E + T) + 1 tries, in practice the first. The tries are the
// reduced fractions s = p/q, 4096 ≤ q ≤ 8192, p < 2^26 (so q², p·q, p² are exact): distinct
// fractions are distinct directions, ~9·10⁷ of them: more than 2·(E + T) + 1 below ~1.8·10⁷
// triangles (a mesh beyond that could, in theory, reach the logic_error below).
bool parity_inside(const MixedPair& m, const Frame& f) {
  return moment_ray_parity("mesh point", [&](const Vec3& d) -> std::optional<bool> {
    bool inside = false, degenerate = false;
    ray_candidates(m, f, d, [&](std::size_t t) {
      if (degenerate || m.tri_zero[t]) return;
      const auto& T = m.tri[t];
      auto n = [&](auto L) { return cross(sub(lv(L, T[1]), lv(L, T[0])), sub(lv(L, T[2]), lv(L, T[0]))); };
      const int den = exact::exact_sign([&](auto L) { return dot(n(L), lv(L, d)); });
      const int sn = exact::exact_sign([&](auto L) { return dot(n(L), sub(lv(L, T[0]), f.placed(L))); });
      if (den == 0) {
        degenerate = sn == 0;  // the ray in the triangle's plane
        return;
      }
      if (sn * den <= 0) return;  // the plane is behind the start, or holds x (x on no triangle)
      int pos = 0, neg = 0;
      for (int e = 0; e < 3; ++e) {
        const int s = exact::exact_sign([&](auto L) {
          const auto x = f.placed(L);
          return dot(lv(L, d), cross(sub(lv(L, T[e]), x), sub(lv(L, T[(e + 1) % 3]), x)));
        });
        pos += s > 0, neg += s < 0;
      }
      if (pos > 0 && neg > 0) return;  // misses
      if (pos + neg < 3) {
        degenerate = true;  // through an edge or a vertex
        return;
      }
      inside = !inside;
    });
    return degenerate ? std::nullopt : std::optional<bool>(inside);
  });
}

// The outward unit normal of triangle t in the world frame.
Vec3 tri_normal(const Frame& f, const MixedPair& m, std::size_t t) {
  const auto& T = m.tri[t];
  return (f.Rm * (T[1] - T[0]).cross(T[2] - T[0])).normalized();
}

// Features: the point's vertex 0; on the mesh's side none (the triangle t is no piece's feature:
// piece_p / piece_q stay −1, and formatters index pieces or the hull).
template <class R>
void set_features(const MixedPair& m, R& r, std::size_t) {
  const Feature3 pt{FeatureKind3::Vertex, 0};
  (m.mesh_is_p ? r.feature_q : r.feature_p) = pt;
  (m.mesh_is_p ? r.feature_p : r.feature_q) = Feature3{};
}

// The nearest triangle: its exact distance (best) and its index `at`, the least index among equal
// distances. Only triangles whose lower bound (box distance less a margin) is <= best are
// evaluated, the others cannot be nearer: linearly (by increasing bound) or best-first over the
// tree (a node's bound is <= its triangles'); both evaluate every triangle with bound <= the
// answer, so they agree bit for bit.
Distance3 nearest(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, std::size_t& at) {
  const Frame f = frame(m, pose_p, pose_q, nullptr);
  const double e = margin(f, m);
  auto bound = [&](const std::array<Vec3, 2>& b) { return box_distance(b, f.x) * (1 - 0x1p-40) - e; };
  Distance3 best;
  bool have = false;
  auto eval = [&](std::size_t t) {
    const Distance3 r = tri_distance(m, t, pose_p, pose_q);
    if (!have || r.distance < best.distance || (r.distance == best.distance && t < at)) best = r, at = t, have = true;
  };
  if (m.linear) {
    std::vector<std::pair<double, std::size_t>> c;
    c.reserve(m.tri.size());
    for (std::size_t t = 0; t < m.tri.size(); ++t) c.push_back({bound(m.tri_box[t]), t});
    std::sort(c.begin(), c.end());
    for (const auto& [lb, t] : c) {
      if (have && lb > best.distance) break;
      eval(t);
    }
    return best;
  }
  using Entry = std::pair<double, std::uint32_t>;  // (bound, node)
  std::vector<Entry> heap;
  auto push = [&](std::uint32_t n) {
    const auto& N = m.tree.nodes[n];
    heap.push_back({bound({N.lo, N.hi}), n});
    std::push_heap(heap.begin(), heap.end(), std::greater<>());
  };
  if (!m.tree.nodes.empty()) push(0);
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), std::greater<>());
    const auto [lb, n] = heap.back();
    heap.pop_back();
    if (have && lb > best.distance) break;
    const auto& N = m.tree.nodes[n];
    if (N.left >= 0) {
      push(static_cast<std::uint32_t>(N.left)), push(static_cast<std::uint32_t>(N.right));
      continue;
    }
    for (std::uint32_t i = N.b; i < N.e; ++i) {
      const std::uint32_t t = m.tree.items[i];
      if (!have || bound(m.tri_box[t]) <= best.distance) eval(t);
    }
  }
  return best;
}

}  // namespace

bool point_zero_area(const std::array<Vec3, 3>& T) {
  for (int k = 0; k < 3; ++k)
    if (exact::exact_sign([&](auto L) { return cross(sub(lv(L, T[1]), lv(L, T[0])), sub(lv(L, T[2]), lv(L, T[0])))[k]; }) != 0)
      return false;
  return true;
}

bool point_overlapping(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  const Frame f = frame(m, pose_p, pose_q, nullptr);
  return !on_surface(m, f) && parity_inside(m, f);
}

namespace {
// σ for an overlapping placement.
Depth3 minimum_inside(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  Depth3 r;
  std::size_t t = 0;
  const Distance3 n = nearest(m, pose_p, pose_q, t);
  r.overlapping = true;
  r.depth = r.lower_bound = r.upper_bound = n.distance;
  // The distance engine's translation brings its B (the point) onto the triangle; when the mesh
  // is Q, the mesh moves instead: the opposite vector.
  r.translation = m.mesh_is_p ? n.translation : Vec3(-n.translation);
  r.normal = r.depth > 0 ? Vec3(r.translation / r.depth) : Vec3::Zero();
  r.facet_normal = r.normal;
  r.witness_p = r.witness_q = m.mesh_is_p ? n.witness_p : n.witness_q;
  r.candidates = m.tri.size();
  set_features(m, r, t);
  return r;
}
}  // namespace

Depth3 point_minimum(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  return point_overlapping(m, pose_p, pose_q) ? minimum_inside(m, pose_p, pose_q) : Depth3{};
}

Distance3 point_distance(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  if (point_overlapping(m, pose_p, pose_q)) {
    const Depth3 s = minimum_inside(m, pose_p, pose_q);
    Distance3 o;
    o.overlapping = true;
    o.distance = o.lower_bound = o.upper_bound = -s.depth;
    o.translation = s.translation, o.normal = s.normal;
    o.witness_p = s.witness_p, o.witness_q = s.witness_q;
    o.feature_p = s.feature_p, o.feature_q = s.feature_q;
    return o;
  }
  std::size_t t = 0;
  Distance3 r = nearest(m, pose_p, pose_q, t);
  if (!m.mesh_is_p) {  // seen from the other side (pair3.cpp's flat_distance)
    r.normal = -r.normal, r.translation = -r.translation;
    std::swap(r.witness_p, r.witness_q);
  }
  r.lower_bound = r.upper_bound = r.distance;
  set_features(m, r, t);
  return r;
}

Depth3 point_along(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation) {
  Depth3 r;
  r.kind = separation ? DepthKind::Separation : DepthKind::Directional;
  r.overlapping = point_overlapping(m, pose_p, pose_q);
  if (!r.overlapping && !separation) return r;
  const Frame f = frame(m, pose_p, pose_q, &d);
  const std::vector<Hit> h = hits(m, f);
  r.candidates = m.tri.size();
  const Hit* pick = nullptr;
  if (!separation) {
    if (!h.empty()) pick = &h[0];  // inside: the first hit is at λ > 0
  } else {
    const double dn = f.d.norm();
    bool inside = r.overlapping;  // the state before the current hit
    double prev = 0;
    for (std::size_t k = 0; k < h.size(); ++k) {
      if (k > 0 && h[k].lambda == prev) continue;
      if (k > 0 || h[k].lambda > 0) {
        if (k > 0) {  // the stretch (prev, λ_k): inside or out throughout
          const double mid = 0.5 * (prev + h[k].lambda) * dn;
          inside = point_overlapping(m, pose_p, moved(pose_q, mid * d.normalized()));
        }
        if (inside) pick = &h[k];
      }
      prev = h[k].lambda;
    }
  }
  if (!pick) return r;
  const double s = pick->lambda * f.d.norm();
  const Vec3 u = d.normalized();
  r.depth = r.lower_bound = r.upper_bound = s;
  r.translation = s * u;
  r.normal = u;
  r.facet_normal = m.mesh_is_p ? tri_normal(f, m, pick->t) : Vec3(-tri_normal(f, m, pick->t));
  r.witness_p = r.witness_q = f.Rm * (f.x + pick->lambda * f.d) + f.tm;
  set_features(m, r, pick->t);
  return r;
}

Cast3 point_cast(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) {
  Cast3 r;
  r.distance = r.lower_bound = r.upper_bound = kInf;
  if (point_overlapping(m, pose_p, pose_q)) {
    r.distance = r.lower_bound = r.upper_bound = 0;
    r.hit = r.overlapping = true;
    return r;
  }
  const Frame f = frame(m, pose_p, pose_q, &d);
  std::size_t at = 0;
  const Distance3 n = nearest(m, pose_p, pose_q, at);
  if (n.distance == 0) {  // touching: on the surface (also when the ray then slides along it)
    r.distance = r.lower_bound = r.upper_bound = 0;
    r.hit = true;
    r.normal = m.mesh_is_p ? tri_normal(f, m, at) : Vec3(-tri_normal(f, m, at));
    r.witness_p = r.witness_q = m.mesh_is_p ? n.witness_q : n.witness_p;
    set_features(m, r, at);
    return r;
  }
  const std::vector<Hit> h = hits(m, f);
  if (h.empty()) return r;
  const Hit& k = h.front();  // the least (λ, triangle)
  const double s = k.lambda * f.d.norm();
  r.hit = true;
  r.distance = r.lower_bound = r.upper_bound = s;
  r.translation = s * d.normalized();
  r.normal = m.mesh_is_p ? tri_normal(f, m, k.t) : Vec3(-tri_normal(f, m, k.t));
  r.witness_p = r.witness_q = f.Rm * (f.x + k.lambda * f.d) + f.tm;
  set_features(m, r, k.t);
  return r;
}

}  // namespace pendepth::mesh3
