// Pair3 on meshes: pieces and boxes, the exact overlap test, signed distance and σ with
// certified bounds (issue 17 items 3–5; survey §3.5–§4: convex decomposition with per-pair convex
// depths as bounds, Kim et al.; DHS §6). Contract in mesh_pair.hpp; σ_d in mesh_line.cpp.
//
//   overlap   int P ∩ int Q' ≠ ∅ ⇔ some 0 ∈ int M_ij (pieces have disjoint interiors and cover
//             the solids): the pairs whose box sum holds 0, each by the exact convex test.
//             O(n·m) box tests + the candidates' convex tests.
//   distance  apart / touching: min over pairs of the convex signed distances (each within a few
//             ulps of its exact value, so their min is too; not always correctly rounded: two
//             decompositions of one mesh can differ by an ulp), pairs in increasing box
//             distance, stopping when the box distance exceeds the best; overlapping: −σ's bounds.
//   σ         O ⊇ int M_ij for every pair, so σ = dist(0, ∂O) >= σ_ij = dist(0, ∂M_ij) on every
//             overlapping pair: lower = max σ_ij. Moving by σ_d along any d separates, so every
//             exact σ_d is an upper bound: upper = least σ_d over the normals of the deepest
//             pairs (the deepest first; its σ_d equals the lower bound when that pair's nearest
//             facet is not covered by another pair) and the six axis directions, then up to three
//             times along the normal of the facet where the best move ends while that improves;
//             stop as soon as upper meets lower. Bounds within 16 ulps are reported equal (exact
//             to a few ulps).
//             Cost: k σ_d queries (mesh_line.cpp) after the n·m pair tests.
//             When the bounds do not meet and the exact σ ends within its work limit
//             (kExactSigmaMaxWork, a deterministic count): the exact σ from mesh_sigma_exact.cpp, a
//             1-ulp bracket (off: a SigmaBoundsOnly guard on the thread).
#include "mesh3/mesh_pair.hpp"

#include "mesh3/mesh_sigma_exact.hpp"

#include <pendepth/mesh3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pendepth::mesh3 {
namespace {

Box3 box_of(const ConvexPolytope& X) {
  Box3 b{X[0], X[0]};
  for (const Vec3& v : X.vertices()) b.lo = b.lo.cwiseMin(v), b.hi = b.hi.cwiseMax(v);
  return b;
}

// Widened by a relative margin far above the rounding of the placed boxes.
Box3 widen(Box3 b) {
  const double m = std::max(b.lo.cwiseAbs().maxCoeff(), b.hi.cwiseAbs().maxCoeff());
  const double e = 0x1p-40 * m + 0x1p-1000;
  b.lo.array() -= e, b.hi.array() += e;
  return b;
}

double box_distance(const Box3& b) {  // distance from 0 to the box, rounded
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < 3; ++k) c[k] = b.lo[k] > 0 ? b.lo[k] : b.hi[k] < 0 ? -b.hi[k] : 0.0;
  return c.norm();
}

bool holds_zero(const Box3& b) { return (b.lo.array() <= 0).all() && (b.hi.array() >= 0).all(); }

}  // namespace

MeshPair MeshPair::make(std::vector<ConvexPolytope> P, std::vector<ConvexPolytope> Q, bool exact) {
  MeshPair m;
  m.P = std::move(P), m.Q = std::move(Q), m.exact = exact;
  for (const auto& x : m.P) m.boxP.push_back(box_of(x));
  for (const auto& x : m.Q) m.boxQ.push_back(box_of(x));
  return m;
}

std::vector<ConvexPolytope> pieces_of(const Shape3& s, bool& exact) {
  if (s.is_convex() || !s.mesh()) return {s.polytope()};
  const ConvexDecomposition3& d = s.mesh()->decomposition();
  exact = exact && d.rounded_pieces == 0 && d.dropped_slivers == 0;
  return d.pieces;
}

Placed place(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  Placed pl;
  pl.Rp = pose_p.matrix();
  pl.tp_world = pose_p.translation;
  pl.R = pl.Rp.transpose() * pose_q.matrix();
  pl.tq = pl.Rp.transpose() * pose_q.translation;
  pl.tp = pl.Rp.transpose() * pose_p.translation;
  const Vec3 t = pl.tq - pl.tp;
  pl.boxQ.reserve(m.Q.size());
  for (const Box3& b : m.boxQ) {
    Box3 r{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
    for (int c = 0; c < 8; ++c) {
      const Vec3 v = pl.R * Vec3(c & 1 ? b.hi.x() : b.lo.x(), c & 2 ? b.hi.y() : b.lo.y(), c & 4 ? b.hi.z() : b.lo.z()) + t;
      r.lo = r.lo.cwiseMin(v), r.hi = r.hi.cwiseMax(v);
    }
    pl.boxQ.push_back(widen(r));
  }
  return pl;
}

Box3 sum_box(const MeshPair& m, const Placed& pl, std::size_t i, std::size_t j) {
  return widen(Box3{m.boxP[i].lo - pl.boxQ[j].hi, m.boxP[i].hi - pl.boxQ[j].lo});
}

bool overlapping(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  const Placed pl = place(m, pose_p, pose_q);
  for (std::size_t i = 0; i < m.P.size(); ++i)
    for (std::size_t j = 0; j < m.Q.size(); ++j)
      if (holds_zero(sum_box(m, pl, i, j)) && minimum_depth(m.P[i], pose_p, m.Q[j], pose_q).overlapping) return true;
  return false;
}

Depth3 minimum(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  const Placed pl = place(m, pose_p, pose_q);
  std::vector<DeepPair> deep;
  std::size_t work = 0;
  for (std::size_t i = 0; i < m.P.size(); ++i)
    for (std::size_t j = 0; j < m.Q.size(); ++j) {
      if (!holds_zero(sum_box(m, pl, i, j))) continue;
      const Depth3 r = minimum_depth(m.P[i], pose_p, m.Q[j], pose_q);
      work += r.candidates;
      if (r.overlapping) deep.push_back({r.depth, r.normal});
    }
  Depth3 r = least_from_deep(std::move(deep), work, [&](const Vec3& d) { return along(m, pose_p, pose_q, d, false); });
  if (SigmaKeepBounds* keep = SigmaKeepBounds::active) keep->bounds = r;
  // Bounds apart: the exact σ (mesh_sigma_exact.cpp) when it ends within its work limit.
  if (SigmaBoundsOnly::depth == 0 && r.overlapping && r.lower_bound < r.upper_bound)
    if (std::optional<Depth3> x = exact_minimum(m, pose_p, pose_q, r.upper_bound)) {
      x->candidates += r.candidates;
      return *x;
    }
  return r;
}

Distance3 overlap_distance3(const Depth3& s) {
  Distance3 o;
  o.overlapping = true;
  o.distance = o.lower_bound = -s.upper_bound;
  o.upper_bound = -s.lower_bound;
  o.translation = s.translation;
  o.normal = s.normal;
  o.witness_p = s.witness_p, o.witness_q = s.witness_q;
  o.feature_p = s.feature_p, o.feature_q = s.feature_q;
  o.piece_p = s.piece_p, o.piece_q = s.piece_q;
  return o;
}

Depth3 least_from_deep(std::vector<DeepPair> deep, std::size_t work,
                       const std::function<Depth3(const Vec3&)>& along_d) {
  if (deep.empty()) {
    Depth3 none;
    none.candidates = work;
    return none;
  }
  std::sort(deep.begin(), deep.end(), [](const DeepPair& a, const DeepPair& b) { return a.s > b.s; });
  std::vector<Vec3> normals;
  for (std::size_t k = 0; k < std::min<std::size_t>(deep.size(), 4); ++k) normals.push_back(deep[k].normal);
  return least_directional(deep[0].s, normals, work, along_d);
}

Depth3 least_directional(double lower, const std::vector<Vec3>& normals, std::size_t work,
                         const std::function<Depth3(const Vec3&)>& along_d) {
  Depth3 best;
  std::vector<Vec3> dirs = normals;
  for (int a = 0; a < 3; ++a) dirs.push_back(Vec3::Unit(a)), dirs.push_back(-Vec3::Unit(a));
  bool have = false;
  auto meets = [&](double upper) { return upper - lower <= 16 * std::numeric_limits<double>::epsilon() * upper; };
  std::vector<Vec3> tried;  // unit directions already asked (deep normals are often axes)
  for (const Vec3& d : dirs) {
    if (!(d.allFinite() && d != Vec3::Zero())) continue;
    const Vec3 u = d.normalized();
    if (std::find(tried.begin(), tried.end(), u) != tried.end()) continue;
    tried.push_back(u);
    const Depth3 r = along_d(d);
    work += r.candidates;
    if (!have || r.depth < best.depth) best = r, have = true;
    if (meets(best.depth)) break;
  }
  // Refinement: along the normal of the facet where the best move ends (the foot of 0 on that
  // facet's plane is nearer than the exit point), while it improves, at most 3 times.
  for (int k = 0; k < 3 && !meets(best.depth); ++k) {
    const Vec3 d = best.facet_normal;
    if (!(d.allFinite() && d != Vec3::Zero()) || d == best.normal) break;
    const Depth3 r = along_d(d);
    work += r.candidates;
    if (!(r.depth < best.depth)) break;
    best = r;
  }
  best.kind = DepthKind::Minimum;
  best.overlapping = true;
  best.candidates = work;
  best.upper_bound = std::max(best.upper_bound, best.depth);
  best.lower_bound = meets(best.depth) ? best.depth : std::min(lower, best.depth);
  return best;
}

Distance3 signed_distance(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  const Placed pl = place(m, pose_p, pose_q);
  struct Cand {
    double lb;
    std::size_t i, j;
  };
  std::vector<Cand> c;
  c.reserve(m.P.size() * m.Q.size());
  for (std::size_t i = 0; i < m.P.size(); ++i)
    for (std::size_t j = 0; j < m.Q.size(); ++j)
      c.push_back({box_distance(sum_box(m, pl, i, j)) * (1 - 0x1p-40), i, j});
  std::sort(c.begin(), c.end(), [](const Cand& a, const Cand& b) { return a.lb < b.lb; });
  Distance3 best;
  bool have = false;
  for (const Cand& k : c) {
    if (have && k.lb > best.distance) break;
    Distance3 r = pendepth::signed_distance(m.P[k.i], pose_p, m.Q[k.j], pose_q);
    if (r.overlapping) {  // −σ of the meshes, from σ's bounds
      return overlap_distance3(minimum(m, pose_p, pose_q));
    }
    if (!have || r.distance < best.distance) {
      best = r, have = true;
      best.piece_p = static_cast<int>(k.i), best.piece_q = static_cast<int>(k.j);
    }
  }
  return best;
}

}  // namespace pendepth::mesh3
