// The point path of Pair3 on a non-convex mesh (src/mesh3/mesh_point.cpp): decisions on the
// surface's ½-ulp slivers, and its box tree against the linear scan.
//
// Oracles and properties.
//  - Rotated meshes (vertices rotated and rounded to doubles, pose the identity, so the placed
//    point is the double itself): points ±1 ulp per coordinate (all 27 offsets) from vertices,
//    edge midpoints and face centroids: the side against CGAL's Side_of_triangle_mesh (Epick:
//    exact predicates) on the mesh's own triangles; overlapping ⇔ σ > 0 ⇔ signed distance < 0,
//    on the boundary ⇔ distance 0 (then not overlapping, σ = σ_d = 0, cast 0), σ = −distance,
//    σ_d > 0 ⇔ overlapping, both roles agree.
//  - Rotated poses (the placed point R·p + t − t' is not a double): the same consistency.
//  - The tree path equals the linear scan (MixedPair::linear, the reference) bit for bit on every
//    query, random points and near-surface points, random rotations, both roles.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_mixed.hpp"
#include "mesh_gen.hpp"
#include "oracle_cgal.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <random>
#include <sstream>

namespace {

using namespace pendepth;
using namespace mesh3_test;

// All faces fanned into triangles (so that rounded rotated quads stay valid) and the vertices
// rotated by q and rounded.
Gen rotated(const Gen& g, const Eigen::Quaterniond& q) {
  Gen r;
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  for (const Vec3& p : g.points) r.points.push_back(R * p);
  for (const auto& t : fan(g)) r.faces.push_back({t[0], t[1], t[2]});
  return r;
}

std::string show(const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << v.x() << "," << v.y() << "," << v.z();
  return s.str();
}

// Feature points of a mesh: vertices, edge midpoints, face centroids (rounded), `n` of each kind.
std::vector<Vec3> features(const Mesh3& m, std::mt19937_64& rng, int n) {
  const auto pts = m.points();
  const auto tris = m.triangles();
  std::uniform_int_distribution<std::size_t> V(0, pts.size() - 1), T(0, tris.size() - 1);
  std::uniform_int_distribution<int> E(0, 2);
  std::vector<Vec3> out;
  for (int k = 0; k < n; ++k) {
    out.push_back(pts[V(rng)]);
    const auto& t = tris[T(rng)];
    const int e = E(rng);
    out.push_back(0.5 * (pts[t[e]] + pts[t[(e + 1) % 3]]));
    const auto& u = tris[T(rng)];
    out.push_back((pts[u[0]] + pts[u[1]] + pts[u[2]]) / 3);
  }
  return out;
}

// x moved by o[k] ∈ {−1, 0, 1} ulps per coordinate.
Vec3 ulps(const Vec3& x, int code) {
  Vec3 y = x;
  for (int k = 0; k < 3; ++k, code /= 3) {
    const int o = code % 3 - 1;
    if (o) y[k] = std::nextafter(y[k], o * std::numeric_limits<double>::infinity());
  }
  return y;
}

// The consistency of the five queries at one placement; returns the side (1 in, 0 on, −1 out).
int consistent(const Pair3& pair, const Pair3& swapped, const Pose3& pm, const Pose3& pt, const Vec3& d, const std::string& what) {
  const bool ov = pair.overlapping(pm, pt);
  const Distance3 sd = pair.signed_distance(pm, pt);
  const Depth3 s = pair.minimum(pm, pt);
  const Depth3 a = pair.along(pm, pt, d);
  const Cast3 c = pair.cast(pm, pt, d);
  EXPECT_EQ(ov, s.depth > 0) << what;
  EXPECT_EQ(ov, sd.distance < 0) << what;
  EXPECT_EQ(ov, a.depth > 0) << what;
  EXPECT_EQ(s.depth, ov ? -sd.distance : 0.0) << what;
  if (ov || sd.distance == 0) {
    EXPECT_TRUE(c.hit) << what;
    EXPECT_EQ(c.distance, 0) << what;
  } else {
    EXPECT_GT(c.distance, 0) << what;
  }
  // The other role: P the point, Q the mesh.
  EXPECT_EQ(swapped.overlapping(pt, pm), ov) << what;
  EXPECT_EQ(swapped.signed_distance(pt, pm).distance, sd.distance) << what;
  return ov ? 1 : sd.distance == 0 ? 0 : -1;
}

std::vector<Gen> meshes(std::mt19937_64& rng) {
  return {polycube(l_block()), polycube(comb(3)), torus(12, 6), bumpy_sphere(rng, 8, 10, 0.3)};
}

TEST(MeshPoint, UlpNeighboursOfRotatedMeshesAgainstCgal) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> U(-1, 1);
  int sides[3] = {0, 0, 0};
  for (const Gen& g0 : meshes(rng)) {
    const Gen g = rotated(g0, Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)));
    const Mesh3 mesh = Mesh3::validate(to_file(g, "m"), "m");
    const auto pv = mesh.points();
    const auto tv = mesh.triangles();
    const CgalInside cgal(std::vector<Vec3>(pv.begin(), pv.end()),
                          std::vector<std::array<std::size_t, 3>>(tv.begin(), tv.end()));
    const Shape3 ms = Shape3::from_mesh(mesh);
    // The point at the origin translated by x: placed exactly at x.
    const Pair3 pair(ms, Shape3::point(Vec3::Zero())), swapped(Shape3::point(Vec3::Zero()), ms);
    for (const Vec3& f : features(mesh, rng, 6))
      for (int code = 0; code < 27; ++code) {
        const Vec3 x = ulps(f, code);
        const Vec3 d(U(rng), U(rng), U(rng));
        const std::string what = "x " + show(x);
        const int side = consistent(pair, swapped, Pose3(), Pose3(x), d, what);
        EXPECT_EQ(side, cgal.side(x)) << what;
        ++sides[side + 1];
      }
  }
  // Every kind occurs (the test can fail on each).
  EXPECT_GT(sides[0], 50);
  EXPECT_GT(sides[1], 10);
  EXPECT_GT(sides[2], 50);
}

TEST(MeshPoint, UlpNeighboursUnderRotatedPosesBothRoles) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> U(-1, 1);
  int in = 0, out = 0;
  for (const Gen& g : meshes(rng)) {
    const Mesh3 mesh = Mesh3::validate(to_file(g, "m"), "m");
    const Shape3 ms = Shape3::from_mesh(mesh);
    const Pair3 pair(ms, Shape3::point(Vec3::Zero())), swapped(Shape3::point(Vec3::Zero()), ms);
    for (const Vec3& f : features(mesh, rng, 4)) {
      const Pose3 pm(Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)), Vec3(U(rng), U(rng), U(rng)));
      const Vec3 w = pm.apply(f);  // the feature in the world, rounded
      for (int code = 0; code < 27; code += 2) {
        const Vec3 x = ulps(w, code);
        const int side = consistent(pair, swapped, pm, Pose3(x), Vec3(U(rng), U(rng), U(rng)), "x " + show(x));
        in += side > 0, out += side < 0;
      }
    }
  }
  EXPECT_GT(in, 30);
  EXPECT_GT(out, 30);
}

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same(const Vec3& a, const Vec3& b) { return same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.z(), b.z()); }
template <class R>
bool same_common(const R& a, const R& b) {
  return same(a.translation, b.translation) && same(a.normal, b.normal) && same(a.witness_p, b.witness_p) &&
         same(a.witness_q, b.witness_q) && a.feature_p == b.feature_p && a.feature_q == b.feature_q &&
         same(a.lower_bound, b.lower_bound) && same(a.upper_bound, b.upper_bound) && a.overlapping == b.overlapping;
}
bool same_depth(const Depth3& a, const Depth3& b) {
  return same_common(a, b) && same(a.depth, b.depth) && same(a.facet_normal, b.facet_normal);
}

TEST(MeshPoint, TreeEqualsLinearBitForBit) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(-1, 1), W(0, 1);
  int checked = 0, in = 0;
  for (const Gen& g : meshes(rng)) {
    const Mesh3 mesh = Mesh3::validate(to_file(g, "m"), "m");
    const Shape3 ms = Shape3::from_mesh(mesh);
    Vec3 lo = mesh.points()[0], hi = lo;
    for (const Vec3& v : mesh.points()) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const std::vector<Vec3> near = features(mesh, rng, 8);
    for (const bool mesh_is_p : {true, false}) {
      const Shape3 pt = Shape3::point(Vec3(0.125, -0.25, 0.5));
      const mesh3::MixedPair tree = mesh_is_p ? mesh3::MixedPair::make(ms, pt) : mesh3::MixedPair::make(pt, ms);
      mesh3::MixedPair lin = tree;
      lin.linear = true;
      ASSERT_FALSE(tree.linear);
      for (int k = 0; k < 80; ++k) {
        const Pose3 pm(Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)), Vec3(U(rng), U(rng), U(rng)));
        // The point's world position: uniform in the mesh's box grown by 1, or a feature ± 1 ulp.
        const Vec3 local = k % 2 ? Vec3(lo + (hi - lo).cwiseProduct(Vec3(W(rng), W(rng), W(rng))) + Vec3(U(rng), U(rng), U(rng)))
                                 : ulps(near[static_cast<std::size_t>(k / 2) % near.size()], k % 27);
        const Pose3 po(Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)), Vec3::Zero());
        const Pose3 po2(po.rotation, pm.apply(local) - po.matrix() * Vec3(0.125, -0.25, 0.5));
        const Pose3& pp = mesh_is_p ? pm : po2;
        const Pose3& pq = mesh_is_p ? po2 : pm;
        const Vec3 d(U(rng), U(rng), U(rng));
        const std::string what = "k " + std::to_string(k) + (mesh_is_p ? " mesh P" : " mesh Q");
        const bool ov = mesh3::point_overlapping(tree, pp, pq);
        EXPECT_EQ(ov, mesh3::point_overlapping(lin, pp, pq)) << what;
        const Distance3 a = mesh3::point_distance(tree, pp, pq), b = mesh3::point_distance(lin, pp, pq);
        EXPECT_TRUE(same_common(a, b) && same(a.distance, b.distance)) << what << " distance " << a.distance << " " << b.distance;
        EXPECT_TRUE(same_depth(mesh3::point_minimum(tree, pp, pq), mesh3::point_minimum(lin, pp, pq))) << what << " minimum";
        for (const bool sep : {false, true})
          EXPECT_TRUE(same_depth(mesh3::point_along(tree, pp, pq, d, sep), mesh3::point_along(lin, pp, pq, d, sep)))
              << what << (sep ? " separation" : " along");
        const Cast3 c = mesh3::point_cast(tree, pp, pq, d), e = mesh3::point_cast(lin, pp, pq, d);
        EXPECT_TRUE(same_common(c, e) && same(c.distance, e.distance) && c.hit == e.hit) << what << " cast";
        ++checked, in += ov;
      }
    }
  }
  EXPECT_EQ(checked, 4 * 2 * 80);
  EXPECT_GT(in, 40);
}

}  // namespace
