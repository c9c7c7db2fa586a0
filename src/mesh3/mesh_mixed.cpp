// Pair3 on a non-convex mesh against a point, segment, flat polygon, rounded shape or curved
// primitive, in either role (issue 16 items 4–5 on the meshes of issue 17; survey §3.5–§4:
// convex decomposition, per-piece convex queries). Contract in mesh_mixed.hpp.
//
// Pieces K_i of the mesh, S the other shape, M_i the sum of piece pair i (a convex Pair3), O =
// ∪ int M_i the open overlap set (the pieces cover the mesh with disjoint interiors). Q moves;
// for v a translation of Q, "piece i at v" is piece pair i with Q's pose translated by v.
//
//   pruning   a bounding ball of each piece (center, radius in the mesh's frame) and one of S
//             (its support function's rho about its origin): piece i can touch at v only when
//             |o_i − v| <= r_i + r_S, o_i the offset of the balls' centres at v = 0 (with a
//             relative margin of 2^-30 far above the rounding of o_i).
//   overlap   some piece pair overlaps (its exact test), candidates by the balls.
//   distance  apart / touching: min over pieces of the pair's signed distance, pieces in increasing
//             ball distance, stopping when the ball distance exceeds the best upper bound
//             (bracket = [min of lower bounds, min of upper bounds]); overlapping: −σ's bounds.
//   cast      overlapping → 0; else the least cast over the pieces whose ball the ray meets, in
//             increasing ball entry, stopping when the entry exceeds the best (a bracket as above).
//   σ_d       the walk over the union: cur = 0; while some piece overlaps at cur·d̂ (its exact
//             test: the point is in O), cur += that piece's σ_d from there (the largest of the
//             covering pieces'). It stops at a translation where no piece overlaps (exact test):
//             moving Q by the answer's translation certainly separates; touching is not
//             overlapping (exact fits and slots end the walk). Every point before is in O. The
//             decisions are exact at the double points the walk visits (the translations as
//             rounded); an exit point that is not a double but lies exactly on another sum's
//             boundary is decided at its rounding (the mesh–mesh walk, mesh_line.cpp, compares
//             such ends exactly; here a step's exit comes from the pair engines as a double).
//             With brackets (rounded, curved shapes) a step's exit is in [cur + lo, cur + hi],
//             the walk moves to cur + hi; the gap [cur + lo, cur + hi] is shown covered when the
//             next piece overlaps at cur + lo too (convex: then at every point between), else the
//             answer's lower_bound is the least such unshown gap start. upper_bound = depth.
//   σ         lower = max over overlapping pieces of their σ's lower bound (O ⊇ int M_i),
//             upper = the least σ_d over directions (least_directional, as mesh_pair.cpp).
//   separation the largest exit of the ray from an int M_i the ray crosses: the exit by a cast
//             from beyond the piece's ball back along −d (exit = S − entry, S the ball's far end),
//             kept when the ray meets int M_i (0 inside, or the midpoint of the forward cast's
//             entry and that exit inside: a chord of a convex set lies in its boundary or has its
//             midpoint interior; a grazing ray is not overlap). One rounding of S − entry.
// Cost: O(n) ball tests per step + the pair queries of the candidates (flat shapes: O(C·c) each,
// src/convex3/flat3.cpp; rounded: a few exact GJKs; curved: the certified engine).
#include "mesh3/mesh_mixed.hpp"

#include "front/mesh_shapes.hpp"
#include "front/scale.hpp"
#include "mesh3/mesh_pair.hpp"
#include "primitives/support3.hpp"

#include <pendepth/mesh3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pendepth::mesh3 {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The balls' centre offsets at v = 0 (P's ball centre − Q's), world frame, and the margin.
struct Offsets {
  std::vector<Vec3> o;
  std::vector<double> reach;  // r_i + r_S + margin
};

Offsets offsets(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  Offsets x;
  const Pose3& pm = m.mesh_is_p ? pose_p : pose_q;
  const Pose3& po = m.mesh_is_p ? pose_q : pose_p;
  const Eigen::Matrix3d R = pm.matrix();
  const double s = m.mesh_is_p ? 1 : -1;
  const MixedPair::Pieces& b = m.built();
  x.o.reserve(b.center.size()), x.reach.reserve(b.center.size());
  for (std::size_t i = 0; i < b.center.size(); ++i) {
    const Vec3 c = R * b.center[i] + pm.translation;
    const Vec3 o = s * (c - po.translation);
    const double e = 0x1p-30 * (c.norm() + po.translation.norm() + b.center[i].norm() + b.radius[i] + m.radius_other) +
                     0x1p-1000;
    x.o.push_back(o);
    x.reach.push_back(b.radius[i] + m.radius_other + e);
  }
  return x;
}

// Q's pose moved by v.
Pose3 moved(const Pose3& pose_q, const Vec3& v) {
  Pose3 q = pose_q;
  q.translation += v;
  return q;
}

// Piece i may touch at translation v (not finite: cannot tell, so yes).
bool near(const Offsets& x, std::size_t i, const Vec3& v) {
  const double g = (x.o[i] - v).norm();
  return !(g > x.reach[i]);
}

// The ray parameters s (unit u) where piece i's ball is within reach: [lo, hi]; false on a miss.
bool ray_ball(const Offsets& x, std::size_t i, const Vec3& u, double& lo, double& hi) {
  const double s0 = x.o[i].dot(u);
  const double g2 = (x.o[i] - s0 * u).squaredNorm();
  const double R = x.reach[i] * (1 + 0x1p-30);
  if (!std::isfinite(s0) || !std::isfinite(g2) || !std::isfinite(R)) {
    lo = -kInf, hi = kInf;
    return true;
  }
  if (g2 > R * R) return false;
  const double h = std::sqrt(R * R - g2) * (1 + 0x1p-30);
  const double e = 0x1p-30 * (std::abs(s0) + h);
  lo = s0 - h - e, hi = s0 + h + e;
  return hi >= 0;
}

// The point path's numeric domain: a pose in engine coordinates, a distance or cast answer back.
Pose3 ep(const MixedPair& m, const Pose3& pose, const char* which) {
  const front::Scale s{m.scale_exp};
  if (s.identity()) return pose;
  return Pose3(pose.rotation, s.vec_to_engine(pose.translation, std::string("pose of ") + which + " translation:"));
}
template <class R>
R back(const MixedPair& m, R r) {
  const front::Scale s{m.scale_exp};
  if (s.identity()) return r;
  r.distance = s.length(r.distance), r.lower_bound = s.length(r.lower_bound), r.upper_bound = s.length(r.upper_bound);
  r.translation = s.vec(r.translation), r.witness_p = s.vec(r.witness_p), r.witness_q = s.vec(r.witness_q);
  return r;
}

template <class R>
R& name_piece(const MixedPair& m, R& r, std::size_t i) {
  if (m.mesh_is_p) r.piece_p = static_cast<int>(i), r.piece_q = 0;
  else r.piece_p = 0, r.piece_q = static_cast<int>(i);
  return r;
}

// The piece pairs of `mesh`'s convex pieces with `other` and their bounding balls (MixedPair::make).
MixedPair::Pieces piece_pairs(const Shape3& mesh, const Shape3& other, bool mesh_is_p) {
  MixedPair::Pieces m;
  const front::Scale scale;
  bool exact = true;
  const std::vector<ConvexPolytope> pieces = pieces_of(mesh, exact);
  for (const ConvexPolytope& k : pieces) {
    std::vector<Vec3> kv(k.vertices().begin(), k.vertices().end());
    for (Vec3& v : kv) v = scale.vec_to_engine(v, mesh.name() + " piece vertex:");
    Vec3 lo = kv[0], hi = kv[0];
    for (const Vec3& v : kv) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const Vec3 c = 0.5 * (lo + hi);
    double r = 0;
    for (const Vec3& v : kv) r = std::max(r, (v - c).norm());
    m.center.push_back(c);
    m.radius.push_back(r * (1 + 0x1p-40) + 0x1p-1000);
    if (!other.curved()) {  // the flat and rounded engines need the piece's outer hierarchy
      try {
        (void)k.face_count();
      } catch (const InvalidInput& e) {
        throw InvalidInput("pair: " + mesh.name() + " against " + other.name() + ": a piece of the mesh's decomposition is " +
                           "too thin for the rounded or flat engine (" + e.what() + "); use the mesh's hull (--hull)");
      }
    }
    const Shape3 piece(k);
    m.pieces.push_back(mesh_is_p ? Pair3(piece, other) : Pair3(other, piece));
  }
  return m;
}

}  // namespace

MixedPair MixedPair::make(const Shape3& P, const Shape3& Q) {
  MixedPair m;
  m.mesh_is_p = !P.is_convex();
  const Shape3& mesh = m.mesh_is_p ? P : Q;
  const Shape3& other = m.mesh_is_p ? Q : P;
  if (other.dimension() <= 2) {  // the mesh's triangles (mesh_point / mesh_segment / mesh_flat.cpp)
    const convex3::FlatShape3 fs = *other.flat_shape();
    const Mesh3& mm = *mesh.mesh();
    const auto pts = mm.points();
    front::Extent x;
    for (const Vec3& v : fs.v) x.add_point(v.cwiseAbs().maxCoeff());
    for (std::size_t j = 0; fs.v.size() > 1 && j < fs.v.size(); ++j) x.add_edge(fs.v[j], fs.v[(j + 1) % fs.v.size()]);
    for (const auto& t : mm.triangles())
      for (int e = 0; e < 3; ++e) x.add_point(pts[t[e]].cwiseAbs().maxCoeff()), x.add_edge(pts[t[e]], pts[t[(e + 1) % 3]]);
    const front::Scale ts = front::Scale::for_pair(x, front::kBand3);
    m.scale_exp = ts.e;
    auto in = [&](const Vec3& v, const std::string& what) { return ts.vec_to_engine(v, what); };
    for (const auto& t : mm.triangles()) {
      const std::array<Vec3, 3> T{in(pts[t[0]], mesh.name() + " vertex:"), in(pts[t[1]], mesh.name() + " vertex:"),
                                  in(pts[t[2]], mesh.name() + " vertex:")};
      m.tri.push_back(T);
      m.tri_flat.push_back(convex3::flat_shape(T, "triangle"));
      m.tri_box.push_back({T[0].cwiseMin(T[1]).cwiseMin(T[2]), T[0].cwiseMax(T[1]).cwiseMax(T[2])});
      m.tri_zero.push_back(point_zero_area(T));
    }
    m.tree.build(m.tri_box);
    m.radius_other = primitives::support_of(other).rho;
    if (other.dimension() == 0) {
      m.point = true;
      m.pt = fs;
      m.pt.v[0] = in(m.pt.v[0], other.name() + " point:");
      return m;  // the point path needs no pieces (mesh_point.cpp)
    }
    // a segment or flat polygon: its points on the triangles' scale; the pieces below (identity
    // scale, each pair scales itself) answer distance, cast and σ's lower bound
    m.seg_tri = segment_triangles(m);
    if (other.dimension() == 1) {
      m.segment = true;
      m.seg = {in(fs.v[0], other.name() + " end point:"), in(fs.v[1], other.name() + " end point:")};
    } else {
      m.flat = true;
      for (const Vec3& v : fs.v) m.flat_v.push_back(in(v, other.name() + " vertex:"));
    }
  }
  m.radius_other = primitives::support_of(other).rho;
  // The piece pairs (identity scale: each pair scales itself), built on first use (lazy.hpp).
  m.lazy = std::make_shared<const Lazy<MixedPair::Pieces>>([P, Q, mesh_is_p = m.mesh_is_p]() {
    try {
      return piece_pairs(mesh_is_p ? P : Q, mesh_is_p ? Q : P, mesh_is_p);
    } catch (const InvalidInput& e) {
      front::rethrow_with_mesh_source(P, Q, e);
    }
  });
  if (eager_pieces) m.built();  // tests: the eager path
  return m;
}

MeshFrame mesh_frame(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3* d) {
  const Pose3& pm = m.mesh_is_p ? pose_p : pose_q;
  const Pose3& po = m.mesh_is_p ? pose_q : pose_p;
  MeshFrame f;
  f.Rm = pm.matrix();
  f.tm = pm.translation;
  f.R = f.Rm.transpose() * po.matrix();
  f.tq = f.Rm.transpose() * po.translation;
  f.tp = f.Rm.transpose() * pm.translation;
  if (d) {
    f.d = f.Rm.transpose() * *d;
    if (!m.mesh_is_p) f.d = -f.d;  // the mesh moves along d: S, relatively, along −d
    if (f.d == Vec3::Zero()) throw InvalidInput("direction: underflows to zero in the mesh's frame");
  }
  return f;
}

bool overlapping(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  if (m.point) return point_overlapping(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q"));
  if (m.segment) return segment_overlapping(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q"));
  if (m.flat) return flat_overlapping(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q"));
  const Offsets x = offsets(m, pose_p, pose_q);
  for (std::size_t i = 0; i < m.built().pieces.size(); ++i)
    if (near(x, i, Vec3::Zero()) && m.built().pieces[i].overlapping(pose_p, pose_q)) return true;
  return false;
}

Depth3 along(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation) {
  if (m.point) return front::Scale{m.scale_exp}.answer(point_along(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q"), d, separation));
  if (m.segment)
    return front::Scale{m.scale_exp}.answer(segment_along(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q"), d, separation));
  if (m.flat) return front::Scale{m.scale_exp}.answer(flat_along(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q"), d, separation));
  const Vec3 u = d.normalized();
  const Offsets x = offsets(m, pose_p, pose_q);
  Depth3 r;
  r.kind = separation ? DepthKind::Separation : DepthKind::Directional;
  std::size_t work = 0;
  if (separation) {
    r.overlapping = overlapping(m, pose_p, pose_q);
    for (std::size_t i = 0; i < m.built().pieces.size(); ++i) {
      double lo, hi;
      if (!ray_ball(x, i, u, lo, hi) || !std::isfinite(hi)) continue;
      const Pair3& pc = m.built().pieces[i];
      ++work;
      const double S = std::max(hi, 0.0);
      const Cast3 back = pc.cast(pose_p, moved(pose_q, S * u), -d);
      if (!back.hit || back.overlapping) continue;  // the ray misses M_i (S is beyond the ball)
      const double exit = S - back.distance;
      if (!(exit > 0) || (r.depth > 0 && !(exit > r.depth))) continue;
      bool genuine = pc.overlapping(pose_p, pose_q);
      if (!genuine) {
        const Cast3 fwd = pc.cast(pose_p, pose_q, d);
        genuine = fwd.hit && pc.overlapping(pose_p, moved(pose_q, (0.5 * (fwd.distance + exit)) * u));
      }
      if (!genuine) continue;
      r.depth = r.lower_bound = r.upper_bound = exit;
      r.translation = exit * u, r.normal = u, r.facet_normal = -back.normal;
      r.witness_p = back.witness_p, r.witness_q = back.witness_q;
      r.feature_p = back.feature_p, r.feature_q = back.feature_q;
      name_piece(m, r, i);
    }
    r.candidates = work;
    return r;
  }
  // σ_d: the walk (file comment).
  double cur = 0, lower = kInf;
  double gap_lo = 0, gap_hi = 0;  // the previous step's unshown gap [gap_lo, gap_hi) (empty: equal)
  Depth3 last;
  std::size_t last_piece = 0;
  bool any = false;
  const std::size_t max_steps = 4 * m.built().pieces.size() + 64;
  for (std::size_t step = 0;; ++step) {
    if (step > max_steps) throw std::logic_error("mixed σ_d: the walk does not end");
    const Vec3 v = cur * u;
    const Pose3 q = moved(pose_q, v);
    std::size_t best_i = 0;
    Depth3 best;
    bool found = false;
    for (std::size_t i = 0; i < m.built().pieces.size(); ++i) {
      if (!near(x, i, v)) continue;
      const Depth3 s = m.built().pieces[i].along(pose_p, q, d);
      work += s.candidates + 1;
      if (!s.overlapping) continue;
      if (!found || s.depth > best.depth) best = s, best_i = i, found = true;
    }
    if (gap_lo < gap_hi) {  // was the previous step's gap covered by the piece now holding cur?
      if (!found || !m.built().pieces[best_i].overlapping(pose_p, moved(pose_q, gap_lo * u))) lower = std::min(lower, gap_lo);
      gap_lo = gap_hi = 0;
    }
    if (!found) break;
    any = true;
    double next = cur + best.depth;
    if (!(next > cur)) next = std::nextafter(cur, kInf);  // rounding left the point covered
    if (best.lower_bound < best.depth) gap_lo = cur + best.lower_bound, gap_hi = next;
    last = best, last_piece = best_i, cur = next;
  }
  r.candidates = work;
  if (!any) return r;
  r = last;
  r.kind = DepthKind::Directional;
  r.overlapping = true;
  r.candidates = work;
  r.depth = r.upper_bound = cur;
  r.lower_bound = std::min(lower, cur);
  r.translation = cur * u;
  r.normal = u;
  name_piece(m, r, last_piece);
  return r;
}

Depth3 minimum(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  if (m.point) return front::Scale{m.scale_exp}.answer(point_minimum(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q")));
  const Offsets x = offsets(m, pose_p, pose_q);
  std::vector<DeepPair> deep;
  std::size_t work = 0;
  for (std::size_t i = 0; i < m.built().pieces.size(); ++i) {
    if (!near(x, i, Vec3::Zero())) continue;
    const Depth3 r = m.built().pieces[i].minimum(pose_p, pose_q);
    work += r.candidates;
    if (r.overlapping) deep.push_back({r.lower_bound, r.normal});
  }
  if ((m.segment || m.flat) && deep.empty() && overlapping(m, pose_p, pose_q))  // in a face the pieces share: σ >= 0
    return least_directional(0, {}, work, [&](const Vec3& d) { return along(m, pose_p, pose_q, d, false); });
  return least_from_deep(std::move(deep), work, [&](const Vec3& d) { return along(m, pose_p, pose_q, d, false); });
}

Distance3 signed_distance(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  if (m.point) return back(m, point_distance(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q")));
  if ((m.segment || m.flat) && overlapping(m, pose_p, pose_q)) return overlap_distance3(minimum(m, pose_p, pose_q));
  const Offsets x = offsets(m, pose_p, pose_q);
  struct Cand {
    double lb;
    std::size_t i;
  };
  std::vector<Cand> c;
  for (std::size_t i = 0; i < m.built().pieces.size(); ++i) {
    const double g = x.o[i].norm() - x.reach[i];
    c.push_back({std::isfinite(g) ? g * (1 - 0x1p-30) : -kInf, i});
  }
  std::sort(c.begin(), c.end(), [](const Cand& a, const Cand& b) { return a.lb < b.lb; });
  Distance3 best;
  bool have = false;
  double lower = kInf;
  for (const Cand& k : c) {
    if (have && k.lb > best.upper_bound) break;
    Distance3 r = m.built().pieces[k.i].signed_distance(pose_p, pose_q);
    if (r.overlapping) {  // −σ, from σ's bounds
      return overlap_distance3(minimum(m, pose_p, pose_q));
    }
    lower = std::min(lower, r.lower_bound);
    if (!have || r.upper_bound < best.upper_bound || (r.upper_bound == best.upper_bound && r.distance < best.distance)) {
      best = r, have = true;
      name_piece(m, best, k.i);
    }
  }
  best.lower_bound = std::min(lower, best.lower_bound);
  return best;
}

Cast3 cast(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) {
  if (m.point) return back(m, point_cast(m, ep(m, pose_p, "P"), ep(m, pose_q, "Q"), d));
  Cast3 best;
  best.distance = best.lower_bound = best.upper_bound = kInf;
  if (overlapping(m, pose_p, pose_q)) {
    best.distance = best.lower_bound = best.upper_bound = 0;
    best.hit = best.overlapping = true;
    return best;
  }
  const Vec3 u = d.normalized();
  const Offsets x = offsets(m, pose_p, pose_q);
  struct Cand {
    double entry;
    std::size_t i;
  };
  std::vector<Cand> c;
  for (std::size_t i = 0; i < m.built().pieces.size(); ++i) {
    double lo, hi;
    if (ray_ball(x, i, u, lo, hi)) c.push_back({std::max(lo, 0.0), i});
  }
  std::sort(c.begin(), c.end(), [](const Cand& a, const Cand& b) { return a.entry < b.entry; });
  double lower = kInf;
  for (const Cand& k : c) {
    if (best.hit && k.entry > best.upper_bound) break;
    Cast3 r = m.built().pieces[k.i].cast(pose_p, pose_q, d);
    if (!r.hit) continue;
    lower = std::min(lower, r.lower_bound);
    if (best.hit && !(r.distance < best.distance)) continue;
    best = r;
    name_piece(m, best, k.i);
  }
  if (best.hit) best.lower_bound = std::min(lower, best.lower_bound);
  return best;
}

}  // namespace pendepth::mesh3
