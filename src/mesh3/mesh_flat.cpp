// Pair3 on a non-convex mesh P against a flat convex polygon F (a FlatShape3 of dimension 2), in
// either role (issue 16 item 4 on the meshes of issue 17; contract in mesh_mixed.hpp). O = {v :
// (F + v) ∩ int P ≠ ∅} = int P ⊕ (−F), open. As for the segment (mesh_segment.cpp, whose exact
// tools this file shares through mesh_exact.hpp), the union of the convex pieces' sums is not O:
// F lying in a face two pieces share is inside int P but in no open piece sum. So overlap and σ_d
// are decided on the mesh's own triangles with exact rationals (CGAL Epeck). F_0 … F_{k−1} are the
// exact placed vertices in the mesh's frame (R f + tq − tp, the relative pose in doubles).
//
//   overlap    F closed, int P open: F meets int P iff relint F does, iff some connected cell C
//              of relint F − ∂P lies in int P (membership is constant on a cell). In F's plane H,
//              ∂P ∩ H is a union of segments (triangles crossing H; CGAL's exact plane–triangle
//              intersection), isolated points, and triangles lying in H (their edges bound the
//              cells). Let φ(X) = (π X − π F_0)·(π F_1 − π F_0), π the projection of H along a
//              coordinate axis its normal is not orthogonal to (injective on H: the crossings
//              below are exact 2D segment intersections), and V the φ values of the arrangement's
//              vertices: F's vertices, the segments' (and H-triangles' edges') end points and the
//              points where two of these segments or a segment and an edge of F meet (exact
//              segment–segment intersections), those in F only. A cell C is open, so φ(C) is an open
//              interval whose ends are the max and min of φ on ∂C ⊂ F, attained at a vertex (on a
//              segment's relative interior away from vertices, φ either grows along it or is that
//              of its end points).
//              Hence C meets the chord {X ∈ F : φ(X) = c} for c the midpoint of some two
//              consecutive values of V within [φ_min, φ_max] of F: overlap ⇔ one of these chords
//              (exact segments of F) meets int P, decided by the segment's exact test.
//   σ_d        ∂O ⊆ ⋃ over feature pairs of P's boundary and −F of complementary dimension:
//              (∂P − F_i) (a triangle, F's vertex i on it), e ⊕ (−f) for each mesh edge e and edge f
//              of F (parallelograms, two triangles), and p − F for each mesh vertex p (F's plane
//              through p; a fan of triangles). (Any v with F + v touching a triangle T lies in
//              T ⊕ (−F), and the extreme points of {x ∈ F : x + v ∈ T} are vertices of F, vertices
//              of T − v, or an edge crossing.) The ray v = μ·d' meets these polygons at exact μ (a
//              point, or both ends of a coplanar overlap); between consecutive candidates
//              membership in O is constant; from v = 0 ∈ O the exit is the first candidate where
//              F + μ d' no longer overlaps (each candidate in O carries the next stretch into O:
//              O is open), separation the end of the last stretch whose midpoint is in O. The
//              answer is RN(μ)·|d'| as for the segment (exact when d' is a unit axis and μ a
//              double, else within ~1 ulp).
// Cost: per overlap test, with k_c the triangles near F's box, O(k_c²) exact segment
// intersections and up to O(k_c²) chords, each a segment test (mesh_segment.cpp) — fine for the
// few triangles near a polygon, quadratic when F spans many; σ_d: the candidates (O(k) polygons
// per triangle along the ray) plus one overlap test per candidate up to the exit.
#include "mesh3/mesh_exact.hpp"

#include <algorithm>
#include <stdexcept>

namespace pendepth::mesh3 {
namespace {

using namespace exact3;
using P2 = K::Point_2;

// The polygon in the mesh's frame.
struct Frame : MeshFrame {
  std::vector<P3> F;  // the exact placed vertices
};

Frame frame(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3* d) {
  Frame f{mesh_frame(m, pose_p, pose_q, d), {}};
  for (const Vec3& v : m.flat_v) f.F.push_back(place(f.R, v, f.tq, f.tp));
  return f;
}

// F's box: centre and half extent (the largest coordinate half width), from the rounded points.
void box_of(const std::vector<P3>& F, Vec3& c, double& h) {
  Vec3 lo = approx(F[0]), hi = lo;
  for (const P3& p : F) {
    const Vec3 a = approx(p);
    lo = lo.cwiseMin(a), hi = hi.cwiseMax(a);
  }
  c = 0.5 * (lo + hi), h = 0.5 * (hi - lo).maxCoeff();
}

// Does F (exact, convex, planar, k >= 3 vertices in order, F_0 ≠ F_1) meet int P?
bool flat_overlap(const MixedPair& m, const std::vector<P3>& F) {
  const std::size_t k = F.size();
  std::size_t j2 = 2;
  while (j2 + 1 < k && CGAL::collinear(F[0], F[1], F[j2])) ++j2;
  const K::Plane_3 H(F[0], F[1], F[j2]);
  // φ on H's projection along a coordinate axis the normal is not orthogonal to (injective on H;
  // the crossings are then exact 2D segment intersections, where the filters decide).
  const V3 N = CGAL::cross_product(F[1] - F[0], F[j2] - F[0]);
  const FT ax = CGAL::abs(N.x()), ay = CGAL::abs(N.y()), az = CGAL::abs(N.z());
  const int drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
  auto pr = [&](const P3& X) { return drop == 0 ? P2(X.y(), X.z()) : drop == 1 ? P2(X.z(), X.x()) : P2(X.x(), X.y()); };
  const P2 f0 = pr(F[0]);
  const K::Vector_2 e = pr(F[1]) - f0;
  auto phi = [&](const P2& X) { return (X - f0) * e; };
  std::vector<FT> fv(k);
  for (std::size_t i = 0; i < k; ++i) fv[i] = phi(pr(F[i]));
  const FT lo = *std::min_element(fv.begin(), fv.end()), hi = *std::max_element(fv.begin(), fv.end());
  std::vector<FT> V(fv);
  std::vector<P2> f2;
  for (const P3& p : F) f2.push_back(pr(p));
  const CGAL::Orientation turn = CGAL::orientation(f2[0], f2[1], pr(F[j2]));
  auto in_f = [&](const P2& X) {  // X in the closed (projected) polygon
    for (std::size_t i = 0; i < k; ++i)
      if (CGAL::orientation(f2[i], f2[(i + 1) % k], X) == -turn) return false;
    return true;
  };
  auto add = [&](const P2& X) {  // a vertex of the arrangement: only those in F bound a cell
    const FT x = phi(X);
    if (lo < x && x < hi && in_f(X)) V.push_back(x);
  };
  // ∂P ∩ H near F: segments (a crossing triangle, or an edge of a triangle lying in H), points.
  std::vector<K::Segment_2> cut;
  Vec3 c;
  double h;
  box_of(F, c, h);
  near_box(m, c, h, [&](std::size_t t) {
    if (m.tri_zero[t]) return;
    const K::Triangle_3 T = tri(m, t);
    if (!CGAL::do_intersect(H, T)) return;
    const auto r = CGAL::intersection(H, T);
    if (!r) return;
    if (const P3* p = boost::get<P3>(&*r)) add(pr(*p));
    else if (const K::Segment_3* s = boost::get<K::Segment_3>(&*r)) cut.emplace_back(pr(s->source()), pr(s->target()));
    else if (boost::get<K::Triangle_3>(&*r))
      for (int j = 0; j < 3; ++j) cut.emplace_back(pr(tp3(m, t)[j]), pr(tp3(m, t)[(j + 1) % 3]));
  });
  std::vector<K::Segment_2> edges;
  for (std::size_t i = 0; i < k; ++i) edges.emplace_back(f2[i], f2[(i + 1) % k]);
  for (const K::Segment_2& s : cut) add(s.source()), add(s.target());
  for (std::size_t a = 0; a < cut.size() && m.flat_drop_family != 4; ++a) {
    auto meet = [&](const K::Segment_2& s) {
      if (!CGAL::do_intersect(cut[a], s)) return;
      const auto r = CGAL::intersection(cut[a], s);
      if (!r) return;
      if (const P2* p = boost::get<P2>(&*r)) add(*p);
      else if (const K::Segment_2* g = boost::get<K::Segment_2>(&*r)) add(g->source()), add(g->target());
    };
    for (std::size_t b = a + 1; b < cut.size(); ++b) meet(cut[b]);
    for (const K::Segment_2& f : edges) meet(f);
  }
  std::sort(V.begin(), V.end());
  V.erase(std::unique(V.begin(), V.end()), V.end());
  // The chord of F at φ = x (lo < x < hi, x no vertex's φ): the two edges whose ends straddle x.
  for (std::size_t j = 0; j + 1 < V.size(); ++j) {
    const FT x = (V[j] + V[j + 1]) / 2;
    P3 end[2];
    int n = 0;
    for (std::size_t i = 0; i < k && n < 2; ++i) {
      const std::size_t i1 = (i + 1) % k;
      if ((fv[i] < x) == (fv[i1] < x)) continue;
      end[n++] = F[i] + ((x - fv[i]) / (fv[i1] - fv[i])) * (F[i1] - F[i]);
    }
    if (n != 2) throw std::logic_error("mesh flat: a chord of the convex polygon has no two ends");
    if (seg_overlap(m, end[0], end[1])) return true;
  }
  return false;
}

// Every μ >= 0 where the ray μ·d' meets a polygon of the ∂O superset (file comment), sorted.
std::vector<Cand> candidates(const MixedPair& m, const Frame& f) {
  const V3 dv(f.d[0], f.d[1], f.d[2]);
  const FT dd = dv.squared_length();
  const P3 O = CGAL::ORIGIN;
  const std::vector<P3>& F = f.F;
  const std::size_t k = F.size();
  std::vector<Cand> out;
  auto shoot = [&](const P3& from, const P3& p, const P3& q, const P3& r) { ray_crossings(from, dv, dd, p, q, r, out); };
  auto minus = [&](const P3& p, const P3& x) { return O + (p - x); };  // the point p − x
  Vec3 c;
  double h;
  box_of(F, c, h);
  along_ray(m, c, h, f.d, [&](std::size_t t) {
    if (m.tri_zero[t]) return;
    const auto& T = tp3(m, t);
    if (m.flat_drop_family != 1)
      for (const P3& x : F) shoot(x, T[0], T[1], T[2]);  // v ∈ T − F_i: F's vertex i on the triangle
    if (m.flat_drop_family != 2)
      for (int e = 0; e < 3; ++e)  // v ∈ e ⊕ (−f): an edge of F across a mesh edge
        for (std::size_t i = 0; i < k; ++i) {
          const P3 &p = T[e], &q = T[(e + 1) % 3], &a = F[i], &b = F[(i + 1) % k];
          shoot(O, minus(p, a), minus(q, a), minus(q, b));
          shoot(O, minus(p, a), minus(q, b), minus(p, b));
        }
    if (m.flat_drop_family != 3)
      for (int e = 0; e < 3; ++e)  // v ∈ p − F: the mesh vertex p in F
        for (std::size_t i = 1; i + 1 < k; ++i) shoot(O, minus(T[e], F[0]), minus(T[e], F[i]), minus(T[e], F[i + 1]));
  });
  std::sort(out.begin(), out.end(), [](const Cand& x, const Cand& y) { return x.mu < y.mu; });
  return out;
}

std::vector<P3> moved(const std::vector<P3>& F, const V3& v) {
  std::vector<P3> G;
  G.reserve(F.size());
  for (const P3& p : F) G.push_back(p + v);
  return G;
}

}  // namespace

bool flat_overlapping(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  return flat_overlap(m, frame(m, pose_p, pose_q, nullptr).F);
}

Depth3 flat_along(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation) {
  Depth3 r;
  r.kind = separation ? DepthKind::Separation : DepthKind::Directional;
  const Frame f = frame(m, pose_p, pose_q, &d);
  r.overlapping = flat_overlap(m, f.F);
  if (!r.overlapping && !separation) return r;
  const V3 dv(f.d[0], f.d[1], f.d[2]);
  const std::vector<Cand> c = candidates(m, f);
  r.candidates = c.size();
  auto in_o = [&](const FT& mu) { return flat_overlap(m, moved(f.F, mu * dv)); };
  const Cand* pick = exit_candidate(c, separation, in_o, "mesh flat");
  if (!pick) return r;
  // The witness: the polygon's first vertex at the exit.
  exit_answer(r, *pick, d, f.d, f.Rm, f.tm, approx(f.F[0]));
  return r;
}

}  // namespace pendepth::mesh3
