// The soak (issue "robustness campaign", docs/robustness.md): random queries over every kind of
// shape pair, each answer checked against a second method or a property, on every core:
//   2D: the two engines of a pair agree (convex: merge vs depth field; polygon × polygon: per
//       query vs no-fit polygon; polygon × convex: the union boundary vs pairs of triangles);
//       swapping P and Q with t → −t (d → −d) gives the same depths; σ ≤ σ_d ≤ complete
//       separation; the overlap test agrees with every depth; moving Q by the answer separates
//       and a move shorter by 1e-9 does not; batch = single, bit for bit.
//   3D: σ equals an O(n·m) reference (every candidate facet normal of M: faces of P, faces of
//       Q, edge × edge); swapping agrees; σ ≤ σ_d; batch = single.
// Every result field must be finite (no NaN, no infinity at these sizes).
//
// CI runs a short soak (PENDEPTH_SOAK_PLACEMENTS unset: 3,000 placements, about 50,000 engine
// calls); scripts/soak.sh runs millions.
#include <pendepth/depth2_polygon_polygon.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "convex3/shapes3.hpp"
#include "polygon2/shapes.hpp"

namespace {

using namespace pendepth;
using Rng = std::mt19937_64;

constexpr double kRel = 1e-9;  // agreement of two exact methods (each within a few ulps)

struct Tally {
  std::atomic<long long> placements{0}, calls{0}, failures{0};
  std::mutex mu;
  std::vector<std::string> first;
  void fail(const std::string& what) {
    ++failures;
    std::lock_guard<std::mutex> lock(mu);
    if (first.size() < 20) first.push_back(what);
  }
};

long long env_count(const char* name, long long fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoll(v) : fallback;
}

bool finite(const Depth2& r) {
  return std::isfinite(r.depth) && r.translation.allFinite() && r.normal.allFinite() && r.witness_p.allFinite() &&
         r.witness_q.allFinite();
}
bool finite(const Depth3& r) {
  return std::isfinite(r.depth) && std::isfinite(r.lower_bound) && std::isfinite(r.upper_bound) &&
         r.translation.allFinite() && r.normal.allFinite() && r.witness_p.allFinite() && r.witness_q.allFinite();
}

bool close(double a, double b, double size) { return std::abs(a - b) <= kRel * (size + std::abs(a) + std::abs(b)); }

bool same_bits(const Depth2& a, const Depth2& b) {
  return std::memcmp(&a.depth, &b.depth, sizeof(double)) == 0 && a.translation == b.translation &&
         a.normal == b.normal && a.witness_p == b.witness_p && a.witness_q == b.witness_q &&
         a.feature_p == b.feature_p && a.feature_q == b.feature_q && a.overlapping == b.overlapping;
}
bool same_bits(const Depth3& a, const Depth3& b) {
  return std::memcmp(&a.depth, &b.depth, sizeof(double)) == 0 && a.translation == b.translation &&
         a.normal == b.normal && a.witness_p == b.witness_p && a.witness_q == b.witness_q &&
         a.feature_p == b.feature_p && a.feature_q == b.feature_q && a.overlapping == b.overlapping &&
         a.lower_bound == b.lower_bound && a.upper_bound == b.upper_bound;
}

std::string where(const char* kind, int pair, const Vec2& t, const Vec2& d) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s pair %d t=(%.17g, %.17g) d=(%.17g, %.17g)", kind, pair, t.x(), t.y(), d.x(), d.y());
  return buf;
}

// ---- 2D shapes ----

std::vector<Vec2> ring_of(const ConvexPolygon& c) { return {c.vertices().begin(), c.vertices().end()}; }

Shape2 random_shape(Rng& rng, bool convex, bool grid) {
  return convex ? Shape2(polygon2_test::random_convex(rng, 3 + int(rng() % 30), 20 + double(rng() % 60), grid))
                : Shape2(polygon2_test::random_polygon(rng, 6 + int(rng() % 14), int(rng() % 3), grid));
}

// s scaled by 2^k (exactly), to soak the numeric domain too.
Shape2 scaled(const Shape2& s, int k) {
  if (k == 0) return s;
  auto rings = s.rings();
  for (auto& ring : rings)
    for (Vec2& v : ring) v = Vec2(std::ldexp(v.x(), k), std::ldexp(v.y(), k));
  return Shape2(rings[0], std::vector<std::vector<Vec2>>(rings.begin() + 1, rings.end()));
}

// One pair in four at a random power-of-two scale (2D: 2^-600 … 2^600; 3D: 2^-250 … 2^250).
int random_exponent(Rng& rng, int range) {
  return rng() % 4 == 0 ? static_cast<int>(rng() % (2 * range + 1)) - range : 0;
}

// A placement near or inside the overlap region: on a 1/4 grid when `grid` (exact fits,
// touching contacts), else uniform.
Vec2 random_placement(Rng& rng, double reach, bool grid) {
  std::uniform_real_distribution<double> u(-1, 1);
  Vec2 t(u(rng), u(rng));
  if (grid) t = Vec2(std::round(64 * t.x()) / 64, std::round(64 * t.y()) / 64);
  return t * reach;  // reach is a power of two: grid placements stay on the (scaled) grid
}

Vec2 random_direction(Rng& rng) {
  static const Vec2 axes[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 2}};
  if (rng() % 3 == 0) return axes[rng() % 6];
  std::normal_distribution<double> g;
  Vec2 d(g(rng), g(rng));
  return d.isZero() ? Vec2(1, 0) : d;
}

// Is some placement within r of x separating? The end of an answer's move lies on ∂O, the
// boundary of the open overlap set, but for non-convex shapes continuing the move can re-enter O
// (the nearest boundary point may be the tip of a thin wedge of separating placements), so the
// check looks around x. An exact fit (an isolated separating point or slit) has no separating
// neighbours: it counts when the no-fit polygon lists it.
bool separated_near(const Pair2& pair, const Vec2& x, double r) {
  if (!pair.overlapping(x)) return true;
  for (int k = 0; k < 16; ++k) {
    const double a = k * polygon2_test::kPi / 8;
    if (!pair.overlapping(x + r * Vec2(std::cos(a), std::sin(a)))) return true;
  }
  const auto& nfp = pair.no_fit_polygon();
  for (const Vec2& p : nfp.points)
    if ((p - x).norm() <= r) return true;
  for (const auto& sl : nfp.slits) {
    const Vec2 e = sl[1] - sl[0];
    const double u = std::clamp((x - sl[0]).dot(e) / e.squaredNorm(), 0.0, 1.0);
    if ((sl[0] + u * e - x).norm() <= r) return true;
  }
  return false;
}

// Every check of one 2D pair over `count` placements.
// P and Q are given at unit size and soaked at size 2^k through the front door; the engine used
// directly as a second method (pairs of triangles) answers at unit size, inside its exact band.
void soak_pair2(Rng& rng, const Shape2& P1, const Shape2& Q1, int k, const char* kind, int id, int count,
                Tally& tally) {
  const Shape2 P = scaled(P1, k), Q = scaled(Q1, k);
  const Pair2 a(P, Q, Prepare::Queries), b(P, Q, Prepare::Full), swapped(Q, P, Prepare::Queries);
  std::optional<PairDepth2> triangles;  // the second method for polygon × convex
  if (a.engine() == Engine2::PolygonConvex || a.engine() == Engine2::PolygonConvexSwapped)
    triangles.emplace(P1.polygon(), Q1.polygon());
  double reach = 0, size = 0;
  for (const Shape2* s : {&P, &Q})
    for (const auto& ring : s->rings())
      for (const Vec2& v : ring) reach = std::max(reach, v.cwiseAbs().maxCoeff());
  size = reach;
  reach = std::ldexp(1.0, std::ilogb(reach) + 2);  // a power of two above 2·size
  const bool grid = rng() % 2;
  std::vector<Vec2> ts;
  std::vector<Depth2> singles;
  long long calls = 0;
  for (int i = 0; i < count; ++i) {
    const Vec2 t = random_placement(rng, reach, grid), d = random_direction(rng);
    ts.push_back(t);
    const std::string at = where(kind, id, t, d);
    const bool o = a.overlapping(t);
    const Depth2 m = a.minimum(t), s = a.along(t, d), c = a.separation(t, d);
    const Depth2 m2 = b.minimum(t), s2 = b.along(t, d);
    const Depth2 ms = swapped.minimum(-t), ss = swapped.along(-t, -d);
    calls += 8;
    singles.push_back(m);
    for (const Depth2* r : {&m, &s, &c, &m2, &s2, &ms, &ss})
      if (!finite(*r)) tally.fail(at + ": a non-finite field");
    if (o != m.overlapping || o != (m.depth > 0) || o != s.overlapping || o != (s.depth > 0) ||
        o != b.overlapping(t) || o != swapped.overlapping(-t))
      tally.fail(at + ": the overlap test disagrees with a depth or an engine");
    if (!close(m.depth, m2.depth, size) || !close(s.depth, s2.depth, size))
      tally.fail(at + ": Queries and Full engines disagree: " + std::to_string(m.depth) + " vs " +
                 std::to_string(m2.depth) + ", " + std::to_string(s.depth) + " vs " + std::to_string(s2.depth));
    if (!close(m.depth, ms.depth, size) || !close(s.depth, ss.depth, size))
      tally.fail(at + ": swapping P and Q changes the depth");
    if (m.depth > s.depth * (1 + kRel) + kRel * size) tally.fail(at + ": σ > σ_d");
    if (s.depth > c.depth * (1 + kRel) + kRel * size) tally.fail(at + ": σ_d > complete separation");
    if (triangles) {
      const Vec2 t1(std::ldexp(t.x(), -k), std::ldexp(t.y(), -k));
      const Depth2 mt = triangles->minimum(t1), st = triangles->along(t1, d);
      calls += 2;
      if (!close(m.depth, std::ldexp(mt.depth, k), size) || !close(s.depth, std::ldexp(st.depth, k), size))
        tally.fail(at + ": union boundary and pairs of triangles disagree");
    }
    // The answers' moves: a little further separates, a little shorter does not.
    if (m.depth > 1e-6 * size) {
      calls += 4;
      if (!separated_near(a, t + m.translation, kRel * size))
        tally.fail(at + ": σ's move does not reach a separating placement");
      if (!a.overlapping(t + m.translation * (1 - kRel)))
        tally.fail(at + ": σ's move shortened by 1e-9 separates");
      const Vec2 u = d / d.norm();
      if (!separated_near(a, t + u * s.depth, kRel * size))
        tally.fail(at + ": σ_d's move does not reach a separating placement");
      if (!a.overlapping(t + u * (s.depth * (1 - kRel))))
        tally.fail(at + ": σ_d's move shortened by 1e-9 separates");
    }
  }
  std::vector<Depth2> batch(ts.size());
  a.minimum(ts, batch, 2);
  calls += static_cast<long long>(ts.size());
  for (std::size_t i = 0; i < ts.size(); ++i)
    if (!same_bits(batch[i], singles[i])) tally.fail(where(kind, id, ts[i], {0, 0}) + ": batch != single");
  tally.calls += calls;
  tally.placements += count;
}

// ---- 3D ----

double support(const std::vector<Vec3>& v, const Vec3& u) {
  double h = -std::numeric_limits<double>::infinity();
  for (const Vec3& x : v) h = std::max(h, x.dot(u));
  return h;
}

// σ by brute force, for P fixed and Q's vertices already posed (q'): the minimum over every
// candidate facet normal u of M = P ⊕ (−Q') (faces of P, faces of −Q', edge × edge) of h_M(u)
// for unit u. Double arithmetic: a reference to about 1e-12 of the size.
double reference_sigma(const Shape3& P, const Shape3& Q, const std::vector<Vec3>& qv) {
  const auto& Pp = P.polytope();
  const auto& Qp = Q.polytope();
  std::vector<Vec3> pv(Pp.vertices().begin(), Pp.vertices().end());
  std::vector<Vec3> fn, ep, eq;
  for (const auto& t : Pp.triangles()) {
    const Vec3 a = pv[t[0]], b = pv[t[1]], c = pv[t[2]];
    fn.push_back((b - a).cross(c - a));
    ep.push_back(b - a), ep.push_back(c - b), ep.push_back(a - c);
  }
  for (const auto& t : Qp.triangles()) {
    const Vec3 a = qv[t[0]], b = qv[t[1]], c = qv[t[2]];
    fn.push_back(-(b - a).cross(c - a));  // a facet of −Q'
    eq.push_back(b - a), eq.push_back(c - b), eq.push_back(a - c);
  }
  for (const Vec3& x : ep)
    for (const Vec3& y : eq) {
      const Vec3 n = x.cross(y);
      if (n.squaredNorm() > 0) fn.push_back(n), fn.push_back(-n);
    }
  double best = std::numeric_limits<double>::infinity();
  std::vector<Vec3> negq(qv.size());
  for (std::size_t i = 0; i < qv.size(); ++i) negq[i] = -qv[i];
  for (Vec3 u : fn) {
    const double n = u.norm();
    if (!(n > 0)) continue;
    u /= n;
    best = std::min(best, support(pv, u) + support(negq, u));  // h_M(u)
  }
  return std::max(best, 0.0);
}

Vec3 random_d3(Rng& rng) {
  std::normal_distribution<double> g;
  Vec3 d(g(rng), g(rng), g(rng));
  if (rng() % 4 == 0) d = Vec3(0, 0, 1);
  return d.isZero() ? Vec3(1, 0, 0) : d;
}

Shape3 random_hull(Rng& rng, int k) {
  std::vector<Vec3> v;
  switch (rng() % 4) {
    case 0: v = test3::random_ball(rng, 4 + int(rng() % 20), 1 + double(rng() % 3)); break;
    case 1: v = test3::random_sphere(rng, 6 + int(rng() % 30), 2); break;
    case 2: v = test3::grid(2 + int(rng() % 2)); break;  // cubes: coplanar faces, ties
    default: v = test3::integer_sphere(std::vector<int>{3, 9, 11, 27}[rng() % 4]); break;
  }
  for (Vec3& x : v) x = Vec3(std::ldexp(x.x(), k), std::ldexp(x.y(), k), std::ldexp(x.z(), k));
  return Shape3::hull(v);
}

void soak_pair3(Rng& rng, const Shape3& P, const Shape3& Q, int id, int count, Tally& tally) {
  const Pair3 a(P, Q), swapped(Q, P);
  double size = 0;
  for (const Shape3* s : {&P, &Q})
    for (const Vec3& v : s->polytope().vertices()) size = std::max(size, v.cwiseAbs().maxCoeff());
  std::uniform_real_distribution<double> u(-1.5 * size, 1.5 * size);
  std::normal_distribution<double> g;
  std::vector<Pose3> poses;
  std::vector<Depth3> singles;
  long long calls = 0;
  for (int i = 0; i < count; ++i) {
    Pose3 pose(Vec3(u(rng), u(rng), u(rng)));
    if (rng() % 3 == 0) {  // on a grid of the shapes' scale: touching contacts, ties
      const double unit = std::ldexp(1.0, std::ilogb(size) - 3);
      pose.translation = (pose.translation / unit).array().round() * unit;
    }
    if (rng() % 2) pose.rotation = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng));
    if (pose.rotation.coeffs().isZero()) pose.rotation = Eigen::Quaterniond::Identity();
    const Vec3 d = random_d3(rng);
    poses.push_back(pose);
    char at[160];
    std::snprintf(at, sizeof at, "3D pair %d pose %d (t=%.17g,%.17g,%.17g)", id, i, pose.translation.x(),
                  pose.translation.y(), pose.translation.z());
    const Depth3 m = a.minimum(Pose3(), pose), s = a.along(Pose3(), pose, d);
    // Swapped: P posed by the inverse of Q's pose, Q at identity: the same relative placement.
    const Eigen::Matrix3d R = pose.matrix();
    const Depth3 ms = swapped.minimum(Pose3(), Pose3(Eigen::Quaterniond(R.transpose()), -(R.transpose() * pose.translation)));
    calls += 3;
    singles.push_back(m);
    for (const Depth3* r : {&m, &s, &ms})
      if (!finite(*r)) tally.fail(std::string(at) + ": a non-finite field");
    if (m.overlapping != (m.depth > 0) || m.overlapping != s.overlapping)
      tally.fail(std::string(at) + ": the overlap decision disagrees with a depth");
    if (m.depth > s.depth * (1 + kRel) + kRel * size) tally.fail(std::string(at) + ": σ > σ_d");
    std::vector<Vec3> qv;
    for (const Vec3& q : Q.polytope().vertices()) qv.push_back(R * q + pose.translation);
    const double ref = reference_sigma(P, Q, qv);
    if (!close(m.depth, ref, size)) tally.fail(std::string(at) + ": σ " + std::to_string(m.depth) + " vs the O(n·m) reference " + std::to_string(ref));
    if (!(std::abs(m.depth - ms.depth) <= 1e-7 * size))  // the swapped pose is rounded: a looser bound
      tally.fail(std::string(at) + ": swapping P and Q changes σ");
  }
  std::vector<Depth3> batch(poses.size());
  a.minimum(poses, batch, 2);
  calls += static_cast<long long>(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i)
    if (!same_bits(batch[i], singles[i])) tally.fail("3D pair " + std::to_string(id) + ": batch != single");
  tally.calls += calls;
  tally.placements += count;
}

// ---- the driver ----

TEST(Soak, EveryPairKindAgreesWithASecondMethod) {
  const long long target = env_count("PENDEPTH_SOAK_PLACEMENTS", 3000);
  const unsigned seed = static_cast<unsigned>(env_count("PENDEPTH_SOAK_SEED", 1));
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  std::atomic<long long> next_pair{0};
  constexpr int kPerPair = 60;
  auto worker = [&] {
    for (;;) {
      const long long id = next_pair++;
      if (id * kPerPair >= target) return;
      Rng rng(seed * 1000003ull + static_cast<unsigned long long>(id));
      const int kind = static_cast<int>(id % 6);
      try {
        switch (kind) {
          case 0: case 1: case 2: case 3: {
            static const char* names[] = {"convex×convex", "polygon×convex", "convex×polygon", "polygon×polygon"};
            const int k = random_exponent(rng, 600);
            const Shape2 P = random_shape(rng, kind == 0 || kind == 2, rng() % 2);
            const Shape2 Q = random_shape(rng, kind == 0 || kind == 1, rng() % 2);
            soak_pair2(rng, P, Q, k, names[kind], int(id), kPerPair, tally);
            break;
          }
          default: {
            const int k = random_exponent(rng, 250);
            const Shape3 P = random_hull(rng, k), Q = random_hull(rng, k);
            soak_pair3(rng, P, Q, int(id), kPerPair, tally);
            break;
          }
        }
      } catch (const std::exception& e) {
        tally.fail("pair " + std::to_string(id) + ": threw " + e.what());
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned k = 0; k < threads; ++k) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("soak: %lld placements, %lld engine calls, %lld failures, %.1f s on %u threads (seed %u)\n",
              tally.placements.load(), tally.calls.load(), tally.failures.load(), secs, threads, seed);
  for (const auto& f : tally.first) ADD_FAILURE() << f;
  EXPECT_EQ(tally.failures.load(), 0);
}

}  // namespace
