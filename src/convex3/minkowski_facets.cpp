// Implicit facets of M = P ⊕ (−Q') (DHS §2 Lemma 2.1 in 3D; survey §3.1, §3.4).
//
// Every facet of M is F_P(u) ⊕ F_{−Q'}(u) for its outward normal u, and is of one of three
// kinds: a face of P plus a vertex (or parallel face/edge) of Q', a vertex of P plus a face of
// Q', or two non-parallel edges e_P, e_Q' (u ∥ e_P × e_Q', both edges extreme for u).
// For any direction u, h_M(u)/|u| bounds dist(0, ∂M) from above, and the facet normals attain
// it (likewise (h_M(u))/(u·d̂) bounds the ray exit along d for u·d > 0). So enumerating a
// superset of the facet normals and evaluating each exactly gives σ and σ_d exactly.
//   * face normals: u = (b − a) × (c − a) exactly; the other shape's support vertex comes from
//     the DK walk on the rounded direction, then an exact hill climb (a local maximum of a
//     linear function on a convex polytope is global) makes it a true maximiser for the exact u;
//   * edge pairs: u = e_P × e_Q'; the pair is kept iff for one sign s both P's edge is extreme
//     for s·u and Q''s edge for −s·u (exact signs at the four adjacent apexes). All O(n·m)
//     pairs are tested: the Gauss-map overlay walk that would make this O(n + m + k) is not
//     implemented (DEPARTURE: DHS computes σ from the explicit M in O(n²); this is the same
//     bound with O(n + m) memory).
// Values: h_M(u) = u·(p − q') is a polynomial in the inputs (degree ≤ 6 with a rotation),
// evaluated by exact::accurate_value (few ulps), signs by exact::exact_sign.
#include "convex3/minkowski_facets.hpp"

#include "geometry/exact.hpp"

#include <array>
#include <cmath>

namespace pendepth::convex3 {

namespace {

using exact::accurate_value;
using exact::exact_sign;

struct Ctx {
  const PolytopeData& P;
  const PolytopeData& Q;
  const RelativePose& pose;
  // q' = R q + tq − tp, lifted.
  template <class L>
  auto qp(L lift, const Vec3& q, int i) const {
    return lift(pose.R(i, 0)) * lift(q.x()) + lift(pose.R(i, 1)) * lift(q.y()) + lift(pose.R(i, 2)) * lift(q.z()) +
           lift(pose.tq[i]) - lift(pose.tp[i]);
  }
  // R (b − a), lifted.
  template <class L>
  auto rdiff(L lift, const Vec3& b, const Vec3& a, int i) const {
    return lift(pose.R(i, 0)) * (lift(b.x()) - lift(a.x())) + lift(pose.R(i, 1)) * (lift(b.y()) - lift(a.y())) +
           lift(pose.R(i, 2)) * (lift(b.z()) - lift(a.z()));
  }
};

template <class A, class B>
auto cross3(const A& a, const B& b) {
  using T = decltype(a[1] * b[2]);
  return std::array<T, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Steepest-free exact climb: move to any neighbour with a strictly larger f until none.
// better(w, v) = exact sign of f(w) − f(v).
template <class Better>
int climb(const PolytopeData& D, int v, Better better) {
  const DKLevel& L = D.levels[0];
  for (bool moved = true; moved;) {
    moved = false;
    int h0 = D.vertex_he[v], h = h0;
    do {
      int w = L.target(h);
      if (better(w, v) > 0) {
        v = w;
        moved = true;
        break;
      }
      h = L.ccw(h);
    } while (h != h0);
  }
  return v;
}

// Evaluates the candidate whose normal is U(lift) (an array of 3 lifted values).
template <class UF>
void evaluate(const Ctx& c, UF U, const std::optional<Vec3>& d, FacetCandidate& out) {
  const Vec3& p = c.P.v[out.p_vertex];
  const Vec3& q = c.Q.v[out.q_vertex];
  auto num = [&](auto L) {
    auto u = U(L);
    return u[0] * (L(p.x()) - c.qp(L, q, 0)) + u[1] * (L(p.y()) - c.qp(L, q, 1)) + u[2] * (L(p.z()) - c.qp(L, q, 2));
  };
  auto norm2 = [&](auto L) {
    auto u = U(L);
    return u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  };
  out.sign = exact_sign(num);
  double n2 = accurate_value(norm2);
  double h = accurate_value(num);
  out.distance = h / std::sqrt(n2);
  auto ud = U(exact::LiftFl{});
  out.unit = Vec3(ud[0].v, ud[1].v, ud[2].v).normalized();
  if (d) {
    const Vec3 dv = *d;
    auto den = [&](auto L) {
      auto u = U(L);
      return u[0] * L(dv.x()) + u[1] * L(dv.y()) + u[2] * L(dv.z());
    };
    out.dir_sign = exact_sign(den);
    if (out.dir_sign > 0) out.exit = exact::accurate_ratio(num, den) * dv.norm();
  }
}

}  // namespace

std::vector<FacetCandidate> minkowski_facets(const ConvexPolytope& Pp, const ConvexPolytope& Qp,
                                             const RelativePose& pose, const std::optional<Vec3>& d) {
  const PolytopeData& P = convex3::data_of(Pp);
  const PolytopeData& Q = convex3::data_of(Qp);
  Ctx c{P, Q, pose};
  std::vector<FacetCandidate> out;
  out.reserve(P.tris.size() + Q.tris.size());

  // Faces of P: u = (b − a) × (c − a); Q''s support minimises u·q'.
  for (int f = 0; f < static_cast<int>(P.tris.size()); ++f) {
    const Vec3 &a = P.v[P.tris[f][0]], &b = P.v[P.tris[f][1]], &cc = P.v[P.tris[f][2]];
    auto U = [&](auto L) {
      std::array<decltype(L(0.0)), 3> e1{L(b.x()) - L(a.x()), L(b.y()) - L(a.y()), L(b.z()) - L(a.z())};
      std::array<decltype(L(0.0)), 3> e2{L(cc.x()) - L(a.x()), L(cc.y()) - L(a.y()), L(cc.z()) - L(a.z())};
      return cross3(e1, e2);
    };
    FacetCandidate k;
    k.source = FacetSource::FaceP;
    k.p_feature = f;
    k.p_vertex = P.tris[f][0];
    Vec3 u = (b - a).cross(cc - a);
    int q0 = Qp.support(-(pose.R.transpose() * u));
    k.q_vertex = climb(Q, q0, [&](int w, int v) {  // sign of u·(q'_v − q'_w): w better if lower
      return exact_sign([&](auto L) {
        auto uu = U(L);
        return uu[0] * c.rdiff(L, Q.v[v], Q.v[w], 0) + uu[1] * c.rdiff(L, Q.v[v], Q.v[w], 1) +
               uu[2] * c.rdiff(L, Q.v[v], Q.v[w], 2);
      });
    });
    k.q_feature = k.q_vertex;
    evaluate(c, U, d, k);
    out.push_back(k);
  }

  // Faces of Q': outward normal n' = R(b − a) × R(c − a); M's facet normal is u = −n'.
  for (int f = 0; f < static_cast<int>(Q.tris.size()); ++f) {
    const Vec3 &a = Q.v[Q.tris[f][0]], &b = Q.v[Q.tris[f][1]], &cc = Q.v[Q.tris[f][2]];
    auto U = [&](auto L) {
      std::array<decltype(c.rdiff(L, b, a, 0)), 3> e1{c.rdiff(L, b, a, 0), c.rdiff(L, b, a, 1), c.rdiff(L, b, a, 2)};
      std::array<decltype(c.rdiff(L, b, a, 0)), 3> e2{c.rdiff(L, cc, a, 0), c.rdiff(L, cc, a, 1),
                                                      c.rdiff(L, cc, a, 2)};
      return cross3(e2, e1);  // −(e1 × e2)
    };
    FacetCandidate k;
    k.source = FacetSource::FaceQ;
    k.q_feature = f;
    k.q_vertex = Q.tris[f][0];
    Vec3 u = (pose.R * (cc - a)).cross(pose.R * (b - a));
    int p0 = Pp.support(u);
    k.p_vertex = climb(P, p0, [&](int w, int v) {
      return exact_sign([&](auto L) {
        auto uu = U(L);
        return uu[0] * (L(P.v[w].x()) - L(P.v[v].x())) + uu[1] * (L(P.v[w].y()) - L(P.v[v].y())) +
               uu[2] * (L(P.v[w].z()) - L(P.v[v].z()));
      });
    });
    k.p_feature = k.p_vertex;
    evaluate(c, U, d, k);
    out.push_back(k);
  }

  // Edge pairs.
  const DKLevel& LP = P.levels[0];
  const DKLevel& LQ = Q.levels[0];
  for (int hp : P.edges) {
    const Vec3 &pa = P.v[LP.origin(hp)], &pb = P.v[LP.target(hp)];
    const Vec3 &pc = P.v[LP.target(LP.next(hp))], &pe = P.v[LP.target(LP.next(LP.twin[hp]))];
    for (int hq : Q.edges) {
      const Vec3 &qa = Q.v[LQ.origin(hq)], &qb = Q.v[LQ.target(hq)];
      const Vec3 &qc = Q.v[LQ.target(LQ.next(hq))], &qe = Q.v[LQ.target(LQ.next(LQ.twin[hq]))];
      auto U = [&](auto L) {
        std::array<decltype(L(0.0)), 3> ep{L(pb.x()) - L(pa.x()), L(pb.y()) - L(pa.y()), L(pb.z()) - L(pa.z())};
        std::array<decltype(c.rdiff(L, qb, qa, 0)), 3> eq{c.rdiff(L, qb, qa, 0), c.rdiff(L, qb, qa, 1),
                                                          c.rdiff(L, qb, qa, 2)};
        return cross3(ep, eq);
      };
      auto side_p = [&](const Vec3& x) {
        return exact_sign([&](auto L) {
          auto u = U(L);
          return u[0] * (L(x.x()) - L(pa.x())) + u[1] * (L(x.y()) - L(pa.y())) + u[2] * (L(x.z()) - L(pa.z()));
        });
      };
      auto side_q = [&](const Vec3& x) {
        return exact_sign([&](auto L) {
          auto u = U(L);
          return u[0] * c.rdiff(L, x, qa, 0) + u[1] * c.rdiff(L, x, qa, 1) + u[2] * c.rdiff(L, x, qa, 2);
        });
      };
      int s1 = side_p(pc), s2 = side_p(pe);
      if (s1 * s2 < 0 || (s1 == 0 && s2 == 0)) continue;  // not extreme / parallel edges
      int s = (s1 != 0 ? -s1 : -s2);  // P's edge is extreme for s·u
      // Q''s edge must be extreme for −s·u: s·u·(x − qa') >= 0 at both apexes.
      if (s * side_q(qc) < 0 || s * side_q(qe) < 0) continue;
      FacetCandidate k;
      k.source = FacetSource::EdgeEdge;
      k.p_feature = hp;
      k.q_feature = hq;
      k.p_vertex = LP.origin(hp);
      k.q_vertex = LQ.origin(hq);
      if (s > 0) evaluate(c, U, d, k);
      else
        evaluate(c, [&](auto L) {
          auto u = U(L);
          return decltype(u){-u[0], -u[1], -u[2]};
        }, d, k);
      out.push_back(k);
    }
  }
  return out;
}

}  // namespace pendepth::convex3
