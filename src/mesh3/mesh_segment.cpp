// Pair3 on a non-convex mesh P against a segment S = [a, b], in either role (issue 16 item 4 on
// the meshes of issue 17; contract in mesh_mixed.hpp). O = {v : (S + v) ∩ int P ≠ ∅}, open.
//
// The union of the convex pieces' sums is not O for a segment: S lying in a face shared by two
// pieces is inside int P but in no open piece sum. So overlap and σ_d are decided on the mesh's
// own triangles, with exact rationals (CGAL Epeck: lazy GMP rationals with interval filters).
// A, B are the exact placed end points in the mesh's frame, A = R a + tq − tp (R, tq, tp the
// relative pose in doubles, as the point path mesh_point.cpp); everything below is exact on them.
//
//   inside(X)  X ∈ int P for a rational point X: on no closed triangle (exact has_on) and an odd
//              number of proper crossings of a ray X + μ·d, μ > 0 (d on the moment curve
//              (q², pq, p²) as mesh_point.cpp's parity; a ray through an edge or vertex, or in a
//              triangle's plane, is detected by exact orientations and the next direction tried).
//   overlap    the parameters λ ∈ [0, 1] where [A, B] meets a closed triangle (CGAL's exact
//              segment–triangle intersection: a point, or the two ends of a coplanar overlap) are
//              the ends of the components of {λ : A + λ(B − A) ∈ ∂P} (each triangle contributes a
//              closed interval); between two consecutive distinct ones (with 0 and 1) the point
//              misses ∂P, so it is in int P throughout or nowhere: overlap ⇔ some such midpoint
//              is inside. (The λ themselves lie on ∂P and are never interior.)
//   σ_d        ∂O ⊆ (∂P − A) ∪ (∂P − B) ∪ ⋃_edges e (e ⊕ [−B, −A]): translated triangles and
//              parallelograms (split into two triangles; an edge parallel to S gives a segment,
//              covered by the parallelograms of the other edges at its end vertices). The ray
//              v = μ·d' (d' the direction in the mesh's frame, negated when the mesh moves)
//              meets them at exact μ (a point, or both ends of a coplanar overlap); between
//              consecutive candidates the ray does not cross ∂O, so membership is constant. From
//              v = 0 ∈ O (open) the exit is the first candidate μ > 0 with S + μ d' not
//              overlapping (exact test above); each candidate found in O carries the next open
//              stretch into O. separation: the end of the last stretch whose midpoint is in O.
//              The answer is RN(μ) · |d'| (as the point path; exact when d' is a unit axis and
//              μ a double, else within ~1 ulp: the rounded exit may lie just inside O).
// The box tree over the triangles (tri_tree.hpp) prunes: segment tests visit the triangles whose
// box meets the segment's box, the ray the triangles whose box, grown by the segment box's half
// extent, the ray from its centre meets (a superset of the polygons the exact ray can meet).
// The triangles' exact points are built once per pair (SegmentTriangles, shared by the queries).
// Cost: per overlap test O(log T + k) exact segment–triangle tests and one parity ray; σ_d: the
// candidates along the ray (k' polygons) plus one overlap test per candidate up to the exit.
#include "geometry/rounded.hpp"
#include "mesh3/mesh_exact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace pendepth::mesh3 {
namespace exact3 {

P3 place(const Eigen::Matrix3d& R, const Vec3& p, const Vec3& tq, const Vec3& tp) {
  FT c[3];
  for (int i = 0; i < 3; ++i) c[i] = FT(R(i, 0)) * p[0] + FT(R(i, 1)) * p[1] + FT(R(i, 2)) * p[2] + FT(tq[i]) - FT(tp[i]);
  return P3(c[0], c[1], c[2]);
}

double dbl(const FT& x) { return exact::round_nearest(x.exact()); }

}  // namespace exact3

namespace {

using namespace exact3;

// The segment in the mesh's frame.
struct Frame : MeshFrame {
  P3 A, B;  // the exact placed end points
};

Frame frame(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3* d) {
  Frame f{mesh_frame(m, pose_p, pose_q, d), {}, {}};
  f.A = place(f.R, m.seg[0], f.tq, f.tp), f.B = place(f.R, m.seg[1], f.tq, f.tp);
  return f;
}

P3 pt(const Vec3& v) { return P3(v[0], v[1], v[2]); }

bool on_surface(const MixedPair& m, const P3& X) {
  bool on = false;
  near_box(m, approx(X), 0, [&](std::size_t t) { on = on || (!m.tri_zero[t] && tri(m, t).has_on(X)); });
  return on;
}

// Ray parity for a rational point on no triangle (mesh_point.cpp's parity_inside, on exact
// orientations): per triangle of nonzero area, the ray X + μ d crosses its plane at μ > 0 iff
// orient(T0, T1, T2, X) and orient(T0, T1, T2, T0 + d) are nonzero with opposite signs; then
// the three orientations (X, X + d, T_e, T_e+1) decide: all nonzero and equal, a proper crossing;
// of both signs, a miss; else (through an edge or vertex) degenerate. In the plane: degenerate.
bool parity_inside(const MixedPair& m, const P3& X) {
  const Vec3 xa = approx(X);
  return moment_ray_parity("mesh segment", [&](const Vec3& d) -> std::optional<bool> {
    const V3 dv(d[0], d[1], d[2]);
    const P3 Y = X + dv;
    bool inside = false, degenerate = false;
    along_ray(m, xa, 0, d, [&](std::size_t t) {
      if (degenerate || m.tri_zero[t]) return;
      const P3 &T0 = tp3(m, t)[0], &T1 = tp3(m, t)[1], &T2 = tp3(m, t)[2];
      const int den = CGAL::orientation(T0, T1, T2, T0 + dv);
      const int sx = CGAL::orientation(T0, T1, T2, X);
      if (den == 0) {
        degenerate = sx == 0;  // the ray in the triangle's plane
        return;
      }
      if (sx == 0 || sx == den) return;  // the plane holds X (X on no triangle) or is behind
      const P3* T[3] = {&T0, &T1, &T2};
      int pos = 0, neg = 0;
      for (int e = 0; e < 3; ++e) {
        const int s = CGAL::orientation(X, Y, *T[e], *T[(e + 1) % 3]);
        pos += s > 0, neg += s < 0;
      }
      if (pos > 0 && neg > 0) return;
      if (pos + neg < 3) {
        degenerate = true;
        return;
      }
      inside = !inside;
    });
    return degenerate ? std::nullopt : std::optional<bool>(inside);
  });
}

}  // namespace

namespace exact3 {

bool inside(const MixedPair& m, const P3& X) { return !on_surface(m, X) && parity_inside(m, X); }

// Does [A, B] meet int P? (file comment)
bool seg_overlap(const MixedPair& m, const P3& A, const P3& B) {
  if (A == B) return inside(m, A);
  const V3 AB = B - A;
  const FT L = AB.squared_length();
  const K::Segment_3 S(A, B);
  std::vector<FT> lam{FT(0), FT(1)};
  const Vec3 a = approx(A), b = approx(B);
  near_box(m, 0.5 * (a + b), 0.5 * (a - b).cwiseAbs().maxCoeff(), [&](std::size_t t) {
    if (m.tri_zero[t]) return;
    const K::Triangle_3 T = tri(m, t);
    if (!CGAL::do_intersect(S, T)) return;
    points_of(CGAL::intersection(S, T), [&](const P3& X) { lam.push_back(((X - A) * AB) / L); });
  });
  std::sort(lam.begin(), lam.end());
  lam.erase(std::unique(lam.begin(), lam.end()), lam.end());
  for (std::size_t k = 0; k + 1 < lam.size(); ++k)
    if (inside(m, A + ((lam[k] + lam[k + 1]) / 2) * AB)) return true;
  return false;
}

}  // namespace exact3

namespace {

// Every μ >= 0 where the ray μ·d' meets a polygon of the ∂O superset (file comment), sorted.
std::vector<Cand> candidates(const MixedPair& m, const Frame& f) {
  const V3 dv(f.d[0], f.d[1], f.d[2]);
  const FT dd = dv.squared_length();
  const P3 O = CGAL::ORIGIN;
  const V3 AB = f.B - f.A;
  std::vector<Cand> out;
  auto shoot = [&](const P3& from, const P3& p, const P3& q, const P3& r) { ray_crossings(from, dv, dd, p, q, r, out); };
  const Vec3 a = approx(f.A), b = approx(f.B);
  along_ray(m, 0.5 * (a + b), 0.5 * (a - b).cwiseAbs().maxCoeff(), f.d, [&](std::size_t t) {
    if (m.tri_zero[t]) return;
    const auto& T = tp3(m, t);
    shoot(f.A, T[0], T[1], T[2]);  // v ∈ T − A: the end A on the triangle
    shoot(f.B, T[0], T[1], T[2]);
    for (int e = 0; e < 3; ++e) {  // v ∈ e ⊕ [−B, −A]: the segment through the edge
      const V3 p = T[e] - CGAL::ORIGIN, q = T[(e + 1) % 3] - CGAL::ORIGIN;
      const P3 pA = O + (p - (f.A - O)), qA = O + (q - (f.A - O)), qB = O + (q - (f.B - O)), pB = O + (p - (f.B - O));
      shoot(O, pA, qA, qB);
      shoot(O, pA, qB, pB);
    }
  });
  std::sort(out.begin(), out.end(), [](const Cand& x, const Cand& y) { return x.mu < y.mu; });
  return out;
}

}  // namespace

std::shared_ptr<const SegmentTriangles> segment_triangles(const MixedPair& m) {
  auto s = std::make_shared<SegmentTriangles>();
  s->T.reserve(m.tri.size());
  for (const auto& t : m.tri) s->T.push_back({pt(t[0]), pt(t[1]), pt(t[2])});
  return s;
}

bool segment_overlapping(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q) {
  const Frame f = frame(m, pose_p, pose_q, nullptr);
  return seg_overlap(m, f.A, f.B);
}

Depth3 segment_along(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation) {
  Depth3 r;
  r.kind = separation ? DepthKind::Separation : DepthKind::Directional;
  const Frame f = frame(m, pose_p, pose_q, &d);
  r.overlapping = seg_overlap(m, f.A, f.B);
  if (!r.overlapping && !separation) return r;
  const V3 dv(f.d[0], f.d[1], f.d[2]);
  const std::vector<Cand> c = candidates(m, f);
  r.candidates = c.size();
  auto in_o = [&](const FT& mu) { return seg_overlap(m, f.A + mu * dv, f.B + mu * dv); };
  const Cand* pick = exit_candidate(c, separation, in_o, "mesh segment");
  if (!pick) return r;
  // The witness: the segment's first end point at the exit.
  exit_answer(r, *pick, d, f.d, f.Rm, f.tm, approx(f.A));
  return r;
}

}  // namespace pendepth::mesh3
