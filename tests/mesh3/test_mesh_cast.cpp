// Shape casts on meshes (src/mesh3/mesh_cast.cpp): the first contact of Q moving along d with P.
//
// Oracle: polycubes, as in test_mesh_pair.cpp. Q + t + λ·d touches or overlaps P iff t + λ·d lies
// in some closed box [p − q − 1, p − q + 1]³ over the voxel pairs (p, q), so the cast is the least
// entry λ >= 0 of the ray into those closed boxes, in GMP rationals from the voxels alone
// (independent of the decomposition and of the convex engines). Closed forms (a cube falling onto
// a comb's teeth, or exactly fitting between them: first contact with both teeth's faces; a peg
// entering a hole) check the
// oracle and the pair together; random polycubes, random translations (half on the half-integer
// grid: exact fits, rays sliding along faces) and directions check Pair3 against it. Properties
// with rotations: moving Q by the cast's translation leaves the pair touching (|signed distance|
// tiny), halfway apart; the cast from the far side along −d equals the complete separation along
// d (the last exit: σ_d for convex shapes) for generic rays.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh_gen.hpp"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <limits>
#include <optional>
#include <random>

namespace {

using namespace pendepth;
using namespace mesh3_test;

constexpr double kInf = std::numeric_limits<double>::infinity();

Shape3 mesh_shape(const std::set<Voxel>& v, const std::string& name) {
  return Shape3::from_mesh(Mesh3::validate(to_file(polycube(v), name), name));
}

// The least entry λ >= 0 of t + λ·d into the closed boxes (file comment); nullopt: a miss.
std::optional<mpq_class> oracle_cast(const std::set<Voxel>& P, const std::set<Voxel>& Q, const Vec3& t, const Vec3& d) {
  std::optional<mpq_class> best;
  for (const Voxel& p : P)
    for (const Voxel& q : Q) {
      mpq_class a = 0, b = 0;
      bool first = true, empty = false;
      for (int k = 0; k < 3 && !empty; ++k) {
        const mpq_class lo(p[k] - q[k] - 1), hi(p[k] - q[k] + 1), tk(t[k]);
        if (d[k] == 0) {
          empty = tk < lo || tk > hi;
          continue;
        }
        const mpq_class dk(d[k]);
        mpq_class x0 = (lo - tk) / dk, x1 = (hi - tk) / dk;
        if (d[k] < 0) std::swap(x0, x1);
        if (first || x0 > a) a = x0;
        if (first || x1 < b) b = x1;
        first = false;
      }
      if (empty || (!first && (a > b || b < 0))) continue;
      const mpq_class entry = first || a < 0 ? mpq_class(0) : a;
      if (!best || entry < *best) best = entry;
    }
  return best;
}

bool oracle_overlapping(const std::set<Voxel>& P, const std::set<Voxel>& Q, const Vec3& t) {
  for (const Voxel& p : P)
    for (const Voxel& q : Q) {
      bool in = true;
      for (int k = 0; k < 3; ++k) in = in && mpq_class(p[k] - q[k] - 1) < t[k] && mpq_class(t[k]) < p[k] - q[k] + 1;
      if (in) return true;
    }
  return false;
}

std::string show(const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << v.x() << "," << v.y() << "," << v.z();
  return s.str();
}

// Checks one cast against the oracle; returns whether it hit.
bool check(const Pair3& pair, const std::set<Voxel>& P, const std::set<Voxel>& Q, const Vec3& t, const Vec3& d,
           const std::string& what) {
  const Cast3 c = pair.cast(Pose3(), Pose3(t), d);
  const std::optional<mpq_class> o = oracle_cast(P, Q, t, d);
  EXPECT_EQ(c.hit, o.has_value()) << what;
  EXPECT_EQ(c.overlapping, oracle_overlapping(P, Q, t)) << what;
  EXPECT_EQ(c.lower_bound, c.distance) << what;  // exact
  EXPECT_EQ(c.upper_bound, c.distance) << what;
  if (!o) {
    EXPECT_EQ(c.distance, kInf) << what;
    return false;
  }
  const double want = o->get_d() * d.norm();
  if (want == 0) EXPECT_EQ(c.distance, 0) << what;
  else EXPECT_NEAR(c.distance, want, 1e-14 * want) << what;
  if (!c.overlapping) {
    EXPECT_GE(c.piece_p, 0) << what;
    EXPECT_GE(c.piece_q, 0) << what;
    EXPECT_LE((c.translation - c.distance * d.normalized()).norm(), 1e-15 * (1 + c.distance)) << what;
  } else {
    EXPECT_EQ(c.distance, 0) << what;
    EXPECT_EQ(c.translation, Vec3::Zero()) << what;
  }
  return true;
}

TEST(MeshCast, ClosedForms) {
  const auto P = comb(3);  // base y∈[0,1], x∈[0,5]; teeth x∈[0,1],[2,3],[4,5], y∈[1,3]
  const auto Q = std::set<Voxel>{{0, 0, 0}};
  const Pair3 pair(mesh_shape(P, "comb"), mesh_shape(Q, "cube"));
  struct Case {
    Vec3 t, d;
    double cast;
  } cases[] = {
      {{0.5, 5, 0}, {0, -1, 0}, 2},       // onto the teeth's tops
      {{1, 5, 0}, {0, -2, 0}, 2},         // fits the gap exactly: its faces touch both teeth's at once
      {{1.25, 5, 0}, {0, -1, 0}, 2},      // does not fit: the teeth again
      {{-3, 1.5, 0}, {1, 0, 0}, 2},       // from the side into tooth 0
      {{1, 1.5, 0}, {1, 0, 0}, 0},        // in the gap: touching at the start
      {{1, 1.5, 3}, {0, 0, -1}, 2},       // down into the gap's layer: touches both teeth's faces
      {{7, 2, 0}, {-1, 0, 0}, 2},         // from the right into tooth 2
      {{7, 5, 0}, {1, 0, 0}, kInf},       // away: a miss
  };
  for (const Case& c : cases) {
    const std::string what = "t " + show(c.t) + " d " + show(c.d);
    const std::optional<mpq_class> o = oracle_cast(P, Q, c.t, c.d);
    EXPECT_EQ(o ? o->get_d() * c.d.norm() : kInf, c.cast) << what << " (oracle)";
    const Cast3 r = pair.cast(Pose3(), Pose3(c.t), c.d);
    EXPECT_EQ(r.distance, c.cast) << what;
    EXPECT_EQ(r.hit, c.cast < kInf) << what;
    check(pair, P, Q, c.t, c.d, what);
  }
  // A peg entering a hole that fits it exactly: the first contact is with the hole's rim.
  std::set<Voxel> ring;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      if (x != 1 || y != 1) ring.insert({x, y, 0});
  const auto peg = std::set<Voxel>{{0, 0, 0}, {0, 0, 1}};
  const Pair3 pg(mesh_shape(ring, "ring"), mesh_shape(peg, "peg"));
  EXPECT_EQ(pg.cast(Pose3(), Pose3(Vec3(1, 1, -3)), Vec3(0, 0, 1)).distance, 1);
  EXPECT_EQ(pg.cast(Pose3(), Pose3(Vec3(1, 1.25, -3)), Vec3(0, 0, 1)).distance, 1);
  EXPECT_EQ(pg.cast(Pose3(), Pose3(Vec3(5, 1, -3)), Vec3(0, 0, 1)).hit, false);
  check(pg, ring, peg, Vec3(1, 1, -3), Vec3(0, 0, 1), "peg");
}

TEST(MeshCast, RandomPolycubesAgainstVoxelOracle) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> U(-1, 1);
  int shapes = 0, hits = 0, positive = 0, overlapping = 0, misses = 0;
  for (int attempt = 0; shapes < 3 && attempt < 50; ++attempt) {
    const auto P = random_polycube(rng, 7), Q = random_polycube(rng, 4);
    std::optional<Pair3> pair;
    try {
      pair.emplace(mesh_shape(P, "P"), mesh_shape(Q, "Q"));
    } catch (const InvalidInput&) {
      continue;  // a non-manifold union: not a valid mesh
    }
    ++shapes;
    for (int k = 0; k < 150; ++k) {
      Vec3 t(4 * U(rng), 4 * U(rng), 4 * U(rng));
      if (k % 2) t = (2 * t).array().round() / 2;  // the half-integer grid: fits, faces sliding on faces
      Vec3 d(U(rng), U(rng), U(rng));
      if (k % 3 == 0) d = Vec3::Unit(k % 9 / 3) * (k % 4 ? 1.0 : -2.0);
      if (k % 3 == 1) d = d.array().round();
      if (d == Vec3::Zero()) d = Vec3(0, 0, 1);
      const std::string what = "shape " + std::to_string(shapes) + " t " + show(t) + " d " + show(d);
      const bool hit = check(*pair, P, Q, t, d, what);
      hits += hit, misses += !hit;
      const Cast3 c = pair->cast(Pose3(), Pose3(t), d);
      positive += c.distance > 0 && hit;
      overlapping += c.overlapping;
    }
  }
  EXPECT_EQ(shapes, 3);
  EXPECT_GT(positive, 40);
  EXPECT_GT(overlapping, 20);
  EXPECT_GT(misses, 20);
}

// Rotations: the move touches, half of it does not; from the far side the cast meets the last
// exit (complete separation) of the reversed ray.
TEST(MeshCast, RotatedMovesTouchAndFarSideIsSeparation) {
  const Pair3 pair(mesh_shape(cup(2), "cup"), mesh_shape(l_block(), "L"));
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(-1, 1);
  int touched = 0, far = 0;
  for (int k = 0; k < 80; ++k) {
    const Eigen::Quaterniond rq(U(rng), U(rng), U(rng), U(rng)), rp(U(rng), U(rng), U(rng), U(rng));
    const Pose3 pp(rp, Vec3(U(rng), U(rng), U(rng))), pq(rq, Vec3(1.5 + 4 * U(rng), 1.5 + 4 * U(rng), 1 + 4 * U(rng)));
    const Vec3 d = k % 2 ? Vec3(U(rng), U(rng), U(rng)) : Vec3(pp.translation - pq.translation + 0.5 * Vec3(U(rng), U(rng), U(rng)));
    const Cast3 c = pair.cast(pp, pq, d);
    EXPECT_EQ(c.overlapping, pair.overlapping(pp, pq)) << k;
    if (c.hit && c.distance > 0) {
      ++touched;
      const double sd = pair.signed_distance(pp, Pose3(rq, pq.translation + c.translation)).distance;
      EXPECT_LE(std::abs(sd), 1e-12 * (10 + c.distance)) << k;
      EXPECT_GT(pair.signed_distance(pp, Pose3(rq, pq.translation + 0.5 * c.translation)).distance, 0) << k;
      EXPECT_FALSE(pair.overlapping(pp, Pose3(rq, pq.translation + c.translation * (1 - 1e-9)))) << k;
    }
    const double sep = pair.separation(pp, pq, d).depth;
    if (sep > 0) {
      ++far;
      const double L = sep + 5;
      const Cast3 back = pair.cast(pp, Pose3(rq, pq.translation + L * d.normalized()), -d);
      ASSERT_TRUE(back.hit) << k;
      EXPECT_NEAR(back.distance, L - sep, 1e-12 * L) << k;
    }
  }
  EXPECT_GT(touched, 15);
  EXPECT_GT(far, 15);
}

TEST(MeshCast, ScaleAndErrors) {
  const Pair3 pair(mesh_shape(comb(3), "comb"), mesh_shape({{0, 0, 0}}, "cube"));
  EXPECT_THROW(pair.cast(Pose3(), Pose3(), Vec3::Zero()), InvalidInput);
  EXPECT_THROW(pair.cast(Pose3(), Pose3(), Vec3(NAN, 0, 0)), InvalidInput);
  EXPECT_THROW(pair.cast(Pose3(), Pose3(Vec3(INFINITY, 0, 0)), Vec3(1, 0, 0)), InvalidInput);
  Gen big = polycube(comb(3)), bigq = polycube({{0, 0, 0}});
  for (auto* g : {&big, &bigq})
    for (Vec3& v : g->points) v *= 0x1p200;
  const Pair3 scaled(Shape3::from_mesh(Mesh3::validate(to_file(big, "big"), "big")),
                     Shape3::from_mesh(Mesh3::validate(to_file(bigq, "bigq"), "bigq")));
  for (const Vec3& t : {Vec3(0.5, 5, 0), Vec3(1, 5, 0.25), Vec3(-3, 1.5, 0)}) {
    const Vec3 d(0.25, -1, 0);
    const Cast3 a = scaled.cast(Pose3(), Pose3(t * 0x1p200), d), b = pair.cast(Pose3(), Pose3(t), d);
    EXPECT_EQ(a.distance, b.distance * 0x1p200);
    EXPECT_EQ(a.upper_bound, b.upper_bound * 0x1p200);
    EXPECT_EQ(a.piece_p, b.piece_p);
  }
}

}  // namespace
