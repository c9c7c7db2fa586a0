// σ_d and complete separation along d for meshes (Pair3 on non-convex shapes; issue 17 item 3;
// DHS §6, survey §3.5–§4 convex decomposition). Contract in mesh_pair.hpp.
//
// The line ℓ = {s·d} (P's frame; 0 is the current placement) meets each open int M_ij in an
// open interval (a_ij, b_ij) or not at all. O = ∪ int M_ij, so
//   σ_d        = the least s >= 0 covered by no interval: start at s = 0; while some interval
//                holds s strictly (a < s < b), jump to its exit b. Touching is not overlapping:
//                an endpoint shared by (a, b) and (b, c) is not covered (exact fits, slots);
//   separation = the largest exit b > 0 (0 when none): beyond it Q slides on freely.
// Each interval comes from two descents of Compute-Depth-3D on the pair's DK hierarchies
// (convex3::line_exit_dk on +d and −d, the same Simulation-of-Simplicity-perturbed line, as the
// convex shape cast does): the entry and exit facets u of M_ij, with the exact sign of h_M(u).
// A perturbed line misses int M_ij ⇒ ℓ misses it (int M_ij is open). A perturbed line may cross
// int M_ij while ℓ only grazes it (ℓ inside a supporting plane: a face of Q sliding along a face
// of P — every slot); so an interval is used only after the exact test that ℓ meets int M_ij:
// no plane parallel to d separates P_i and Q'_j (2D separating axes of the projections along d:
// the planes spanned by d and an edge of either piece; weak separation = touching = miss); it runs
// before the descents (cheaper, and it rejects most pairs the boxes let through). Then
// the exits are exact: an endpoint is λ = u·(p − q')/(u·d) (point λ·d) for the facet's defining
// features (P face, Q face, or the cross product of an edge of each), compared between pairs by
// the rounded values when they differ by more than 2^-40 relative, else by the exact sign of the
// cross-multiplied polynomials (src/geometry/exact.hpp tiers, rationals last).
// Small pairs (n_i·m_j <= kFacetPathMax vertices) skip the descents: the interval is (max entry,
// min exit) over the implicit facet normals of M_ij (convex3::minkowski_facets, each a supporting
// plane with its exact support pair; the facets attain M, and once ℓ is known to meet int M_ij a
// facet parallel to ℓ holds it strictly inside), compared exactly as below — the same exact
// endpoints; only the winning pair's exit facet, contact and features come from one descent.
// Boxes prune: only pairs whose box sum box(P_i) ⊕ −box(Q'_j) meets the ray s >= 0 are examined.
// Cost: O(n·m) box tests, O(n_i·m_j) facet candidates or two O(log n_i · log m_j) descents per candidate pair, O(e·(n_i + m_j))
// for a graze test (e edges), O(k²) exact comparisons for k intervals at worst.
#include "mesh3/mesh_pair.hpp"

#include "convex3/minimum_expand.hpp"
#include "convex3/minkowski_facets.hpp"
#include "convex3/polytope_data.hpp"
#include "geometry/exact.hpp"
#include "mesh3/lifted3.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace pendepth::mesh3 {
namespace {

using lifted::A3;
using lifted::cross;
using lifted::dot;
using lifted::lv;
using lifted::sub;
// R·v with R's doubles lifted.
template <class L, class T>
A3<T> rot(L lift, const Eigen::Matrix3d& R, const A3<T>& v) {
  A3<T> r;
  for (int i = 0; i < 3; ++i) r[i] = lift(R(i, 0)) * v[0] + lift(R(i, 1)) * v[1] + lift(R(i, 2)) * v[2];
  return r;
}

struct Frame {
  const Eigen::Matrix3d& R;
  const Vec3 &tq, &tp, &d;
  // q' = R q + tq − tp, exactly (lifted).
  template <class L>
  auto placed(L lift, const Vec3& q) const {
    auto r = rot(lift, R, lv(lift, q));
    const auto a = lv(lift, tq), b = lv(lift, tp);
    for (int k = 0; k < 3; ++k) r[k] = r[k] + a[k] - b[k];
    return r;
  }
};

// The plane of a facet of M_ij from its defining features: normal u, a point p − q' on it.
struct FacetDef {
  int kind = 0;    // 0: P face normal, 1: Q face normal, 2: P edge × Q edge
  Vec3 a[3], b[3];  // P points, Q points (Q's own frame)
  int den_sign = 1;  // exact sign of u·d

  template <class L>
  auto normal(const Frame& f, L lift) const {
    if (kind == 0) return cross(sub(lv(lift, a[1]), lv(lift, a[0])), sub(lv(lift, a[2]), lv(lift, a[0])));
    // The plane through the three placed points (R is rounded, so R(e1 × e2) may tilt it).
    if (kind == 1) return cross(rot(lift, f.R, sub(lv(lift, b[1]), lv(lift, b[0]))), rot(lift, f.R, sub(lv(lift, b[2]), lv(lift, b[0]))));
    return cross(sub(lv(lift, a[1]), lv(lift, a[0])), rot(lift, f.R, sub(lv(lift, b[1]), lv(lift, b[0]))));
  }
  template <class L>
  auto num(const Frame& f, L lift) const {
    return dot(normal(f, lift), sub(lv(lift, a[0]), f.placed(lift, b[0])));
  }
  template <class L>
  auto den(const Frame& f, L lift) const {
    return dot(normal(f, lift), lv(lift, f.d));
  }
};

// Points of a feature of a piece (vertex: 1, edge: 2, face: 3).
int feature_points(const ConvexPolytope& X, const Feature3& ft, Vec3* out) {
  const auto tris = X.triangles();
  switch (ft.kind) {
    case FeatureKind3::Vertex: out[0] = X[ft.index]; return 1;
    case FeatureKind3::Edge: {
      const auto& t = tris[ft.index / 3];
      out[0] = X[t[ft.index % 3]], out[1] = X[t[(ft.index % 3 + 1) % 3]];
      return 2;
    }
    case FeatureKind3::Face: {
      const auto& t = tris[ft.index];
      for (int k = 0; k < 3; ++k) out[k] = X[t[k]];
      return 3;
    }
    default: return 0;
  }
}

// An endpoint of an interval: its rounded value (length units: λ·|d|), the exact sign of λ, and
// the facet defining it exactly.
struct End {
  double v = 0;
  int sign = 0;
  FacetDef f;
};

struct Interval {
  End a, b;
  std::size_t i = 0, j = 0;
  convex3::LineExit out;
  bool has_out = false;   // `out` computed (the facet path leaves it to the winner)
  bool overlap0 = false;  // 0 ∈ int M_ij (exact: both exits have h > 0)
  int genuine = -1;       // ℓ meets int M_ij: -1 unknown, 0 no, 1 yes
};

FacetDef facet_of(const ConvexPolytope& Pi, const ConvexPolytope& Qj, const convex3::LineExit& e, const Frame& f) {
  FacetDef r;
  const int np = feature_points(Pi, e.feature_p, r.a), nq = feature_points(Qj, e.feature_q, r.b);
  if (np == 3) r.kind = 0;
  else if (nq == 3) r.kind = 1;
  else if (np == 2 && nq == 2) r.kind = 2;
  else throw std::logic_error("mesh σ_d: an exit facet without a face or two edges");
  r.den_sign = exact::exact_sign([&](auto L) { return r.den(f, L); });
  return r;
}

// sign(x − y), exactly.
int compare(const End& x, const End& y, const Frame& f) {
  if (x.sign != y.sign) return x.sign < y.sign ? -1 : 1;
  if (x.sign == 0) return 0;
  const double m = std::max(std::abs(x.v), std::abs(y.v));
  if (x.v - y.v > 0x1p-40 * m) return 1;
  if (y.v - x.v > 0x1p-40 * m) return -1;
  // λx − λy = (nx·dy − ny·dx)/(dx·dy)
  const int s = exact::exact_sign([&](auto L) { return x.f.num(f, L) * y.f.den(f, L) - y.f.num(f, L) * x.f.den(f, L); });
  return s * x.f.den_sign * y.f.den_sign;
}

// The interval of ℓ in int M_ij from the implicit facets of M_ij (small pieces), for a line
// known to meet int M_ij (meets_interior): every candidate facet normal u is a supporting plane,
// the facets attain M, and a facet with u·d = 0 holds ℓ strictly inside its open half-space; so
// the interval is (max entry, min exit) over u·d < 0 and u·d > 0, compared exactly (compare).
// The same exact endpoints as the descents' (any facet attaining the extreme gives the same λ).
// False when the exit is at s <= 0.
bool facet_interval(const ConvexPolytope& Pi, const ConvexPolytope& Qj, const convex3::RelativePose& rel,
                    const Frame& f, Interval& x) {
  const convex3::PolytopeData& P = convex3::data_of(Pi);
  const convex3::PolytopeData& Q = convex3::data_of(Qj);
  const convex3::DKLevel &LP = P.levels[0], &LQ = Q.levels[0];
  const double dn = f.d.norm();
  bool have_a = false, have_b = false;
  for (const convex3::FacetCandidate& k : convex3::minkowski_facets(Pi, Qj, rel, f.d)) {
    if (k.dir_sign == 0) continue;
    End e;
    switch (k.source) {
      case convex3::FacetSource::FaceP:
        e.f.kind = 0;
        for (int t = 0; t < 3; ++t) e.f.a[t] = P.v[P.tris[k.p_feature][t]];
        e.f.b[0] = Q.v[k.q_vertex];
        break;
      case convex3::FacetSource::FaceQ:
        e.f.kind = 1;
        for (int t = 0; t < 3; ++t) e.f.b[t] = Q.v[Q.tris[k.q_feature][t]];
        e.f.a[0] = P.v[k.p_vertex];
        break;
      case convex3::FacetSource::EdgeEdge:
        e.f.kind = 2;
        e.f.a[0] = P.v[LP.origin(k.p_feature)], e.f.a[1] = P.v[LP.target(k.p_feature)];
        e.f.b[0] = Q.v[LQ.origin(k.q_feature)], e.f.b[1] = Q.v[LQ.target(k.q_feature)];
        break;
    }
    e.f.den_sign = exact::exact_sign([&](auto L) { return e.f.den(f, L); });
    if (e.f.den_sign == 0) throw std::logic_error("mesh σ_d: a facet's exact u·d disagrees with its definition");
    e.sign = k.sign * k.dir_sign;  // sign of λ = h_M(u)/(u·d)
    if (k.dir_sign > 0) {
      e.v = e.sign == 0 ? 0.0 : k.exit;
      if (!have_b || compare(e, x.b, f) < 0) x.b = e, have_b = true;
    } else {
      e.v = e.sign == 0 ? 0.0 : exact::accurate_ratio([&](auto L) { return e.f.num(f, L); }, [&](auto L) { return e.f.den(f, L); }) * dn;
      if (!have_a || compare(e, x.a, f) > 0) x.a = e, have_a = true;
    }
  }
  if (!have_a || !have_b) throw std::logic_error("mesh σ_d: a bounded sum without entry or exit facets");
  return x.b.sign > 0;
}

// Exactly: does the line {s·d} meet int(P_i ⊕ −Q'_j), i.e. does no plane parallel to d separate
// P_i and Q'_j (weakly)? Separating planes of the projections along d may be taken through an
// edge of either piece (2D separating axis theorem): normal u = e × d.
bool meets_interior(const ConvexPolytope& Pi, const ConvexPolytope& Qj, const Frame& f) {
  const auto vp = Pi.vertices();
  std::vector<Vec3> vq(Qj.size());
  double mx = 0;
  for (std::size_t k = 0; k < Qj.size(); ++k) vq[k] = f.R * Qj[k] + (f.tq - f.tp), mx = std::max(mx, vq[k].norm());
  for (const Vec3& p : vp) mx = std::max(mx, p.norm());
  std::vector<double> gp(vp.size()), gq(vq.size());
  auto separates = [&](auto edge_lift, const Vec3& e_approx) {
    bool zero = true;  // e × d exactly zero: not a direction
    for (int k = 0; k < 3 && zero; ++k)
      zero = exact::exact_sign([&](auto L) { return cross(edge_lift(L), lv(L, f.d))[k]; }) == 0;
    if (zero) return false;
    const Vec3 u = e_approx.cross(f.d);
    const double tol = 0x1p-36 * (e_approx.norm() * f.d.norm() * mx) + 0x1p-1000;
    for (std::size_t k = 0; k < vp.size(); ++k) gp[k] = u.dot(vp[k]);
    for (std::size_t k = 0; k < vq.size(); ++k) gq[k] = u.dot(vq[k]);
    for (int side : {1, -1}) {  // side 1: u·p <= u·q' for all p, q
      double hp = -INFINITY, lq = INFINITY;
      for (double g : gp) hp = std::max(hp, side * g);
      for (double g : gq) lq = std::min(lq, side * g);
      if (hp - lq > 2 * tol) continue;  // clearly not separating on this side
      bool ok = true;
      for (std::size_t x = 0; x < vp.size() && ok; ++x) {
        if (side * gp[x] < hp - tol) continue;
        for (std::size_t y = 0; y < vq.size() && ok; ++y) {
          if (side * gq[y] > lq + tol) continue;
          const int s = exact::exact_sign([&](auto L) {
            return dot(cross(edge_lift(L), lv(L, f.d)), sub(lv(L, vp[x]), f.placed(L, Qj[y])));
          });
          if (side * s > 0) ok = false;
        }
      }
      if (ok) return true;
    }
    return false;
  };
  const auto tp = Pi.triangles();
  for (const auto& t : tp)
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = Pi[t[k]], &b = Pi[t[(k + 1) % 3]];
      if (t[k] > t[(k + 1) % 3]) continue;
      if (separates([&](auto L) { return sub(lv(L, b), lv(L, a)); }, b - a)) return false;
    }
  for (const auto& t : Qj.triangles())
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = Qj[t[k]], &b = Qj[t[(k + 1) % 3]];
      if (t[k] > t[(k + 1) % 3]) continue;
      if (separates([&](auto L) { return rot(L, f.R, sub(lv(L, b), lv(L, a))); }, f.R * (b - a))) return false;
    }
  return true;
}

// The parameters (length units, s·|d|) where the ray {s·d̂ : s >= 0} is in a (widened) box,
// widened again for rounding; false when it misses the box.
bool ray_box(const Box3& b, const Vec3& d, double dn, double& lo, double& hi) {
  lo = 0, hi = INFINITY;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (b.lo[k] > 0 || b.hi[k] < 0) return false;
      continue;
    }
    double t0 = b.lo[k] / d[k], t1 = b.hi[k] / d[k];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0), hi = std::min(hi, t1);
  }
  if (!(lo <= hi * (1 + 0x1p-30) + 0x1p-1000)) return false;
  lo = lo * dn * (1 - 0x1p-30) - 0x1p-1000, hi = hi * dn * (1 + 0x1p-30) + 0x1p-1000;
  return true;
}

}  // namespace

Depth3 along(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation) {
  const Placed pl = place(m, pose_p, pose_q);
  const Vec3 dl = pl.Rp.transpose() * d;
  if (dl == Vec3::Zero()) throw InvalidInput("direction: underflows to zero in P's frame");
  const Frame f{pl.R, pl.tq, pl.tp, dl};
  convex3::RelativePose rel;
  rel.R = pl.R, rel.tq = pl.tq, rel.tp = pl.tp;

  // Candidate pairs: those whose box sum the ray meets, with the box's parameter range [A, B]
  // (length units) ⊇ the pair's interval; each pair's descents run on first need.
  struct Cand {
    std::size_t i, j;
    double A, B;
    int state = -1;  // -1 not evaluated, 0 no interval at s > 0, 1 interval iv[index]
    std::size_t index = 0;
  };
  std::vector<Cand> cand;
  const double dn = dl.norm();
  for (std::size_t i = 0; i < m.P.size(); ++i)
    for (std::size_t j = 0; j < m.Q.size(); ++j) {
      double A, B;
      if (ray_box(sum_box(m, pl, i, j), dl, dn, A, B)) cand.push_back({i, j, A, B});
    }
  std::vector<Interval> iv;
  iv.reserve(cand.size());
  auto use_facets = [](const ConvexPolytope& Pi, const ConvexPolytope& Qj) {
    if (line_path != LinePath::Auto) return line_path == LinePath::Facets;
    return Pi.size() * Qj.size() <= kFacetPathMax;
  };
  std::size_t examined = 0;
  auto eval = [&](Cand& c) -> Interval* {
    if (c.state < 0) {
      c.state = 0;
      ++examined;
      // The exact test first: it is cheap against the descents and rejects most box candidates.
      if (!meets_interior(m.P[c.i], m.Q[c.j], f)) return nullptr;
      Interval x;
      x.i = c.i, x.j = c.j;
      if (use_facets(m.P[c.i], m.Q[c.j])) {
        if (!facet_interval(m.P[c.i], m.Q[c.j], rel, f, x)) return nullptr;  // exits at s <= 0
      } else {
        const convex3::LineExit in = convex3::line_exit_dk(m.P[c.i], m.Q[c.j], rel, -dl);
        if (!in.hit) return nullptr;
        const convex3::LineExit out = convex3::line_exit_dk(m.P[c.i], m.Q[c.j], rel, dl, -1);
        if (!out.hit || out.h_sign <= 0) return nullptr;  // misses int M_ij, or exits at s <= 0
        x.out = out, x.has_out = true;
        x.a = {-in.exit, -in.h_sign, facet_of(m.P[c.i], m.Q[c.j], in, f)};
        x.b = {out.exit, out.h_sign, facet_of(m.P[c.i], m.Q[c.j], out, f)};
        // A facet parallel to ℓ crossed by the perturbed line: ℓ lies in that supporting plane
        // (its h is 0, else the perturbed chord would be unbounded), so it misses int M_ij.
        if (x.a.f.den_sign == 0 || x.b.f.den_sign == 0) return nullptr;
      }
      x.overlap0 = x.a.sign < 0;  // and x.b.sign > 0: 0 ∈ int M_ij
      x.genuine = 1;               // ℓ meets int M_ij (tested above)
      c.state = 1, c.index = iv.size();
      iv.push_back(std::move(x));
    }
    return c.state == 1 ? &iv[c.index] : nullptr;
  };
  auto genuine = [&](Interval& x) {
    if (x.genuine < 0) x.genuine = meets_interior(m.P[x.i], m.Q[x.j], f) ? 1 : 0;
    return x.genuine == 1;
  };

  std::size_t last = SIZE_MAX;  // the interval whose exit is the answer
  bool overlapping = false;
  for (Cand& c : cand)  // the intervals holding 0: boxes with A <= 0 <= B
    if (c.A <= 0 && c.B >= 0)
      if (Interval* x = eval(c); x && x->overlap0) {
        overlapping = true;
        if (!separation && (last == SIZE_MAX || compare(x->b, iv[last].b, f) > 0)) last = c.index;
      }
  if (separation) {
    // The largest genuine exit: boxes in decreasing B until B is below the best exit.
    std::sort(cand.begin(), cand.end(), [](const Cand& a, const Cand& b) { return a.B > b.B; });
    for (Cand& c : cand) {
      if (last != SIZE_MAX && c.B < iv[last].b.v) break;
      Interval* x = eval(c);
      if (x && (last == SIZE_MAX || compare(x->b, iv[last].b, f) > 0) && genuine(*x)) last = c.index;
    }
  } else {
    // Walk: cur = 0, then the exit of the interval that last held cur strictly (a box holding
    // an interval around cur has A < cur < B).
    for (bool moved = last != SIZE_MAX; moved;) {
      moved = false;
      const double cur = iv[last].b.v;
      for (Cand& c : cand) {
        if (!(c.A < cur && cur < c.B)) continue;
        Interval* x = eval(c);
        if (!x || c.index == last) continue;
        const End& b = iv[last].b;
        if (compare(x->b, b, f) <= 0 || compare(x->a, b, f) >= 0 || !genuine(*x)) continue;
        last = c.index, moved = true;
        break;
      }
    }
  }

  Depth3 r;
  r.kind = separation ? DepthKind::Separation : DepthKind::Directional;
  r.candidates = examined;
  r.overlapping = overlapping;
  if (last == SIZE_MAX) return r;
  Interval* x = &iv[last];
  if (!x->has_out) {  // the facet path: the winner's exit facet, contact and features by the descent
    x->out = convex3::line_exit_dk(m.P[x->i], m.Q[x->j], rel, dl, -1);
    if (!x->out.hit || x->out.h_sign <= 0) throw std::logic_error("mesh σ_d: the descent misses the facet path's interval");
    x->has_out = true;
  }
  const double s = x->b.v;
  const Vec3 dir = dl.normalized();
  r.depth = r.lower_bound = r.upper_bound = s;
  r.translation = pl.Rp * (s * dir);
  r.normal = pl.Rp * dir;
  r.facet_normal = pl.Rp * x->out.unit;
  r.witness_p = r.witness_q = pl.Rp * x->out.contact + pl.tp_world;
  r.feature_p = x->out.feature_p;
  r.feature_q = x->out.feature_q;
  r.piece_p = static_cast<int>(x->i);
  r.piece_q = static_cast<int>(x->j);
  return r;
}

}  // namespace pendepth::mesh3
