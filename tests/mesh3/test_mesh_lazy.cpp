// Pair3 with a non-convex mesh builds its convex pieces on first use (src/mesh3/lazy.hpp), not at
// construction. Tests:
//   - lazy == eager bit for bit: every query kind (overlap, σ, σ_d, separation, signed distance,
//     cast, the batches) on mesh × mesh, mesh × polytope, mesh × sphere / ellipsoid / segment /
//     point, both roles, random poses (fixed seed), against the same pair built with the pieces
//     at construction (mesh3::eager_pieces, the path before), each from freshly validated meshes
//     (so the lazy pair also builds its own Mesh3::decomposition()); the lazy pair is queried in
//     another order (the queries that need no pieces first).
//   - laziness is real: a torus whose decomposition has a piece too thin for the rounded-shape
//     engine pairs with a segment — overlap and σ_d answer (on the triangles), distance refuses
//     naming the thin piece and the mesh's source, every time.
//   - thread safety: two threads querying a fresh pair at once (both racing to build the pieces
//     and the mesh's decomposition) answer bit for bit as the eager pair, over several rounds.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/lazy.hpp"
#include "mesh_gen.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <functional>
#include <random>
#include <thread>

namespace {

using namespace pendepth;
using namespace mesh3_test;

using Bits = std::vector<std::uint64_t>;

void put(Bits& b, double x) { b.push_back(std::bit_cast<std::uint64_t>(x)); }
void put(Bits& b, const Vec3& v) {
  for (int k = 0; k < 3; ++k) put(b, v[k]);
}
void put(Bits& b, const Feature3& f) { b.push_back(static_cast<std::uint64_t>(f.kind)), b.push_back(static_cast<std::uint64_t>(f.index)); }
void put_ints(Bits& b, std::initializer_list<long long> xs) {
  for (long long x : xs) b.push_back(static_cast<std::uint64_t>(x));
}

Bits bits(const Depth3& r) {
  Bits b;
  for (double x : {r.depth, r.lower_bound, r.upper_bound}) put(b, x);
  for (const Vec3* v : {&r.translation, &r.normal, &r.facet_normal, &r.witness_p, &r.witness_q}) put(b, *v);
  put(b, r.feature_p), put(b, r.feature_q);
  put_ints(b, {static_cast<long long>(r.candidates), r.overlapping, r.piece_p, r.piece_q, static_cast<long long>(r.kind)});
  return b;
}
Bits bits(const Distance3& r) {
  Bits b;
  for (double x : {r.distance, r.lower_bound, r.upper_bound}) put(b, x);
  for (const Vec3* v : {&r.translation, &r.normal, &r.witness_p, &r.witness_q}) put(b, *v);
  put(b, r.feature_p), put(b, r.feature_q);
  put_ints(b, {r.overlapping, r.piece_p, r.piece_q});
  return b;
}
Bits bits(const Cast3& r) {
  Bits b;
  for (double x : {r.distance, r.lower_bound, r.upper_bound}) put(b, x);
  for (const Vec3* v : {&r.translation, &r.normal, &r.witness_p, &r.witness_q}) put(b, *v);
  put(b, r.feature_p), put(b, r.feature_q);
  put_ints(b, {r.hit, r.overlapping, r.piece_p, r.piece_q});
  return b;
}

// A shape made fresh (its mesh validated again, so no decomposition is shared between pairs).
using Make = std::function<Shape3()>;
Make mesh(const Gen& g, const std::string& name) {
  return [g, name] { return Shape3::from_mesh(Mesh3::validate(to_file(g, name), name)); };
}
Make fixed(const Shape3& s) {
  return [s] { return s; };
}

Pair3 make_pair(const Make& p, const Make& q, bool eager) {
  mesh3::eager_pieces = eager;
  Pair3 pair(p(), q());
  mesh3::eager_pieces = false;
  return pair;
}

struct Query {
  Pose3 pp, pq;
  Vec3 d;
};

std::vector<Query> queries(std::mt19937_64& rng, double spread, int n) {
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<Query> out;
  for (int k = 0; k < n; ++k) {
    Query q;
    q.pp = Pose3(Eigen::Quaterniond(1 + U(rng), U(rng) * 0.3, U(rng) * 0.3, U(rng) * 0.3), Vec3(U(rng), U(rng), U(rng)) * 0.25);
    q.pq = Pose3(Eigen::Quaterniond(1 + U(rng), U(rng), U(rng), U(rng)), Vec3(U(rng), U(rng), U(rng)) * spread);
    q.d = Vec3(U(rng), U(rng), U(rng));
    if (q.d.isZero(0)) q.d = Vec3(1, 0, 0);
    out.push_back(q);
  }
  return out;
}

// Every query kind's answers, in order `pieces_last`: the queries that need no pieces (overlap,
// σ_d, separation) first, else σ first.
Bits answers(const Pair3& pair, const std::vector<Query>& qs, bool pieces_last) {
  Bits all;
  auto add = [&](const Bits& b) { all.insert(all.end(), b.begin(), b.end()); };
  auto cheap = [&] {
    for (const Query& q : qs) {
      add({pair.overlapping(q.pp, q.pq)});
      add(bits(pair.along(q.pp, q.pq, q.d)));
      add(bits(pair.separation(q.pp, q.pq, q.d)));
    }
  };
  auto costly = [&] {
    for (const Query& q : qs) {
      add(bits(pair.minimum(q.pp, q.pq)));
      add(bits(pair.signed_distance(q.pp, q.pq)));
      add(bits(pair.cast(q.pp, q.pq, q.d)));
    }
    std::vector<Pose3> poses;
    for (const Query& q : qs) poses.push_back(q.pq);
    std::vector<Depth3> mins(poses.size()), alongs(poses.size());
    std::vector<Distance3> dists(poses.size());
    const std::vector<Vec3> d{qs[0].d};
    pair.minimum(qs[0].pp, poses, mins, 2);
    pair.along(qs[0].pp, poses, d, alongs, 2);
    pair.signed_distance(qs[0].pp, poses, dists, 2);
    for (std::size_t i = 0; i < poses.size(); ++i) add(bits(mins[i])), add(bits(alongs[i])), add(bits(dists[i]));
  };
  if (pieces_last) cheap(), costly();
  else costly(), cheap();
  return all;
}

// The answers of `eager` in the order of `answers(…, pieces_last)`.
void expect_lazy_equals_eager(const Make& p, const Make& q, double spread, int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::vector<Query> qs = queries(rng, spread, n);
  for (const bool pieces_last : {true, false}) {
    const Pair3 eager = make_pair(p, q, true), lazy = make_pair(p, q, false);
    EXPECT_EQ(answers(lazy, qs, pieces_last), answers(eager, qs, pieces_last))
        << eager.P().name() << " × " << eager.Q().name() << " pieces_last " << pieces_last;
  }
}

const Gen kComb = polycube(comb(3));
const Gen kL = polycube(l_block());
const Gen kTorus = torus(8, 4);

TEST(MeshLazy, MeshMeshEqualsEager) {
  expect_lazy_equals_eager(mesh(kComb, "comb"), mesh(kL, "L"), 2.5, 5, 1);
  expect_lazy_equals_eager(mesh(kTorus, "torus"), mesh(kComb, "comb"), 3, 2, 2);
}

TEST(MeshLazy, MeshPolytopeEqualsEager) {
  const Shape3 box = Shape3::box(0.4, 0.3, 0.6, "box");
  expect_lazy_equals_eager(mesh(kComb, "comb"), fixed(box), 2.5, 6, 3);
  expect_lazy_equals_eager(fixed(box), mesh(kTorus, "torus"), 3, 6, 4);
}

TEST(MeshLazy, MeshMixedEqualsEager) {
  for (const Shape3& s : {Shape3::sphere(0.5, "sphere"), Shape3::segment(Vec3(-1.5, 0.2, 0.5), Vec3(2.5, 0.7, 0.5), "seg"),
                          Shape3::point(Vec3(0.5, 0.5, 0.5), "pt")}) {
    expect_lazy_equals_eager(mesh(kComb, "comb"), fixed(s), 2.5, 5, 5);
    expect_lazy_equals_eager(fixed(s), mesh(kL, "L"), 2, 5, 6);
  }
  expect_lazy_equals_eager(mesh(kTorus, "torus"), fixed(Shape3::ellipsoid(0.8, 0.5, 0.3, "ell")), 3, 2, 7);
}

TEST(MeshLazy, SegmentAnswersWithoutPieces) {
  // torus(10, 6): its rounded decomposition has a piece too thin for the rounded or flat engine
  // (test_mesh_mixed.cpp), which the pieces' build refuses. Overlap and σ_d of a segment are on
  // the triangles: they answer; the queries that need the pieces refuse, naming the mesh's source.
  const Shape3 tor = mesh(torus(10, 6), "torus")();
  const Pair3 pair(tor, Shape3::segment(Vec3(-5, 0, 0), Vec3(5, 0, 0), "seg"));
  EXPECT_TRUE(pair.overlapping(Pose3(), Pose3()));
  const Depth3 s = pair.along(Pose3(), Pose3(), Vec3(0, 0, 1));
  EXPECT_TRUE(s.overlapping);
  EXPECT_GT(s.depth, 0);
  EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(s.translation)));  // moving by σ_d separates
  for (int k = 0; k < 2; ++k) {  // the failed build is not kept: the same refusal every time
    try {
      (void)pair.signed_distance(Pose3(), Pose3());
      FAIL() << "accepted";
    } catch (const InvalidInput& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("too thin"), std::string::npos) << m;
      EXPECT_EQ(m.rfind("torus: ", 0), 0u) << m;  // the mesh's source first
    }
  }
  EXPECT_THROW((void)pair.cast(Pose3(), Pose3(Vec3(0, 0, 9)), Vec3(0, 0, -1)), InvalidInput);
}

TEST(MeshLazy, TwoThreadsOnAFreshPair) {
  std::mt19937_64 rng(8);
  const std::vector<Query> qs = queries(rng, 2.5, 3);
  const std::vector<std::pair<Make, Make>> pairs{
      {mesh(kComb, "comb"), mesh(kL, "L")},
      {mesh(kComb, "comb"), fixed(Shape3::sphere(0.5, "sphere"))},
      {fixed(Shape3::segment(Vec3(-1.5, 0.2, 0.5), Vec3(2.5, 0.7, 0.5), "seg")), mesh(kL, "L")}};
  for (const auto& [p, q] : pairs) {
    const Bits want = answers(make_pair(p, q, true), qs, false);
    for (int round = 0; round < 2; ++round) {
      const Pair3 lazy = make_pair(p, q, false);
      Bits a, b;
      std::thread t1([&] { a = answers(lazy, qs, false); });
      std::thread t2([&] { b = answers(lazy, qs, round % 2 == 0); });
      t1.join(), t2.join();
      EXPECT_EQ(a, want) << lazy.P().name() << " × " << lazy.Q().name();
      if (round % 2 == 0) {
        EXPECT_EQ(b, answers(make_pair(p, q, true), qs, true));
      } else {
        EXPECT_EQ(b, want);
      }
    }
  }
}

}  // namespace
