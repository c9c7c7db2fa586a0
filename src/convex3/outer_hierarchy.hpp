// Private: the outer Dobkin–Kirkpatrick hierarchy of a ConvexPolytope (DHS §5.1, Fact 5.1) and
// the exact plane arithmetic shared by its construction and the line queries (line_queries.cpp).
//
// Planes. Every plane is n·(x − c) = h with c the hierarchy's centre (an interior point of P, a
// double) and (n, h) polynomials in input doubles: a face plane comes from three vertices of one
// of its triangles, a query plane from the query's doubles. A point is the meet of three planes,
// x − c = N / D by Cramer's rule, so every decision below is the exact sign of a polynomial
// (exact::exact_sign on generic lambdas); nothing is rounded before a decision.
//
// Outer hierarchy = inner hierarchy of the polar dual about c. A true face f of P (all coplanar
// triangles together) has dual point D_f = n_f / h_f (h_f > 0 because c is interior); the dual
// polytope conv{D_f} has one vertex per face and one (triangulated) facet per vertex of P.
// Removing an independent set of dual vertices of degree <= 8 = dropping an independent set of
// face planes; level i+1 of the outer hierarchy is the intersection of the half-spaces of the
// faces still present. Its vertices are the dual triangles, i.e. triples of plane ids (a vertex
// of P where k > 3 faces meet is k - 2 triples naming the same point).
#pragma once

#include "convex3/polytope_data.hpp"
#include "geometry/exact.hpp"

#include <array>
#include <vector>

namespace pendepth::convex3 {

/// A plane given symbolically. kind 0: through points a, b, p2, normal (b − a) × (p2 − a).
/// kind 1: through point a with normal b × p2 (b, p2 vectors). Evaluated relative to a centre.
struct PlaneDef {
  int kind = 0;
  Vec3 a{0, 0, 0}, b{0, 0, 0}, p2{0, 0, 0};
};

template <class T>
struct PlaneVal {
  T n[3];
  T h;  ///< the plane is n·(x − centre) = h
};

template <class L>
auto eval_plane(const PlaneDef& p, const Vec3& ctr, L lift) {
  using T = decltype(lift(0.0));
  T u[3], v[3];
  for (int i = 0; i < 3; ++i) {
    if (p.kind == 0) {
      u[i] = lift(p.b[i]) - lift(p.a[i]);
      v[i] = lift(p.p2[i]) - lift(p.a[i]);
    } else {
      u[i] = lift(p.b[i]);
      v[i] = lift(p.p2[i]);
    }
  }
  PlaneVal<T> r;
  r.n[0] = u[1] * v[2] - u[2] * v[1];
  r.n[1] = u[2] * v[0] - u[0] * v[2];
  r.n[2] = u[0] * v[1] - u[1] * v[0];
  r.h = r.n[0] * (lift(p.a[0]) - lift(ctr[0])) + r.n[1] * (lift(p.a[1]) - lift(ctr[1])) +
        r.n[2] * (lift(p.a[2]) - lift(ctr[2]));
  return r;
}

template <class T>
struct MeetVal {
  T N[3];
  T D;  ///< the meet point is centre + N / D (D = det of the three normals)
};

/// Cramer's rule for the meet of three planes (relative to the centre).
template <class T>
MeetVal<T> meet(const PlaneVal<T>& p, const PlaneVal<T>& q, const PlaneVal<T>& r) {
  auto cross = [](const T* a, const T* b, T* out) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
  };
  T qr[3], rp[3], pq[3];
  cross(q.n, r.n, qr);
  cross(r.n, p.n, rp);
  cross(p.n, q.n, pq);
  MeetVal<T> m;
  m.D = p.n[0] * qr[0] + p.n[1] * qr[1] + p.n[2] * qr[2];
  for (int i = 0; i < 3; ++i) m.N[i] = p.h * qr[i] + q.h * rp[i] + r.h * pq[i];
  return m;
}

/// n_g·(x − c) − h_g scaled by D (sign must be multiplied by sign(D)).
template <class T>
T side_num(const PlaneVal<T>& g, const MeetVal<T>& x) {
  return g.n[0] * x.N[0] + g.n[1] * x.N[1] + g.n[2] * x.N[2] - g.h * x.D;
}

struct OuterLevel {
  DKLevel dual;              ///< triangulated dual surface; vertex ids = face ids of P
  std::vector<int> creator;  ///< per dual triangle: the face whose removal created it, or -1
};

struct OuterHierarchy {
  Vec3 center{0, 0, 0};  ///< strictly interior point of P (exactly verified)
  /// Face (true facet) of each triangle of the polytope (the triangles of its inner level, in
  /// order), and one reference triangle (vertex ids) per face.
  std::vector<int> face_of_tri;
  std::vector<std::array<int, 3>> face_ref;
  std::vector<OuterLevel> levels;  ///< levels[0]: all faces (the polytope itself)
  /// Face g is present in levels 0..last_level[g]; if that is not the top level, g was removed
  /// there and last_he[g] is an outgoing dual half-edge of g at that level (its <= 8 neighbours).
  std::vector<int> last_level, last_he;
  /// Per dual triangle of level 0: the vertex of P it stands for.
  std::vector<int> base_vertex;
  std::vector<int> protected_faces;  ///< their normals positively span R^3: every level is bounded
  /// Plane values of each face in filtered double (value + error bound), for fast filters.
  std::vector<PlaneVal<exact::Fl>> fl;

  PlaneDef face_plane(const std::vector<Vec3>& v, int f) const {
    const auto& t = face_ref[f];
    return {0, v[t[0]], v[t[1]], v[t[2]]};
  }
  std::size_t top() const { return levels.size() - 1; }
};

/// Builds the outer hierarchy of inner level `level` of d (d's inner hierarchy must exist).
/// O(n log n) time (twin arrays sorted per level), O(n) memory.
std::shared_ptr<const OuterHierarchy> build_outer_hierarchy(const PolytopeData& d, std::size_t level);

}  // namespace pendepth::convex3
