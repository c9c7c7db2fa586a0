// Benchmark: 3D convex intersection depth (DHS §5-§6) — pendepth's public queries against the
// usual GJK/EPA/MPR peers and a linear scan, on the same inputs in the same run (docs/design.md §6).
//
// Notation: P fixed at the identity, Q placed by (rotation, translation); M = P ⊕ (−Q').
// Benchmark names are <query>/<implementation>/<n>:
//   sigma/pendepth        minimum_depth: exact σ (certified expansion)
//   sigma/ccd_epa         libccd ccdGJKPenetration (GJK + EPA), default tolerances (1e-4)
//   sigma/ccd_epa_tight   the same with epa_tolerance 1e-10 (max 1000 iterations)
//   sigma/ccd_mpr         libccd ccdMPRPenetration (MPR: a penetration along the centre line,
//                         not the minimum), default tolerance
//   sigma/fcl_sd          FCL 0.7 fcl::distance with enable_signed_distance (GST_LIBCCD: FCL's
//                         libccd GJK + EPA), default distance_tolerance 1e-6
//   sigma/fcl_epa         FCL 0.7 fcl::collide, enable_contact, GST_INDEP (FCL's own GJK + EPA),
//                         default gjk_tolerance 1e-6; its contact carries the depth negated, so
//                         the magnitude is compared
//   sigma/bullet          Bullet 3.24 float64 btGjkEpaSolver2::Penetration, btConvexHullShape
//                         with margin 0; Q's rotation matrix made before timing
//   sigma/bullet_q        the same, Q's pose made per query from the quaternion pendepth gets
//                         (Bullet's setRotation), as pendepth converts its Pose3 per query
//   sigma_hulls/<impl>/all  the σ peers above on the shared real hulls: the pairs and placements
//                         of hulls/<q>/all below (960 queries, each checked against the O(n·m)
//                         reference)
//   sigma_d/pendepth      directional_depth (the public query: expansion or DK by size)
//   sigma_d/dk, /expand   its two exact methods: Compute-Depth-3D on the DK hierarchies
//                         (convex3::directional_depth_dk), the certified expansion
//                         (convex3::directional_depth_expand)
//   sigma_d/facet_scan    ray exit over every facet plane of M, prebuilt for Q's rotation:
//                         the O(|facets of M|) = O(n + m) linear reference
// σ against σ_d's two exact methods on the same placements and directions (pendepth only):
//   small/<q>/<n>         P and Q hulls of n ellipsoid points each (|P| + |Q| ≈ 2n), random
//                         rotations and translations kept when overlapping, random directions
//   small16/<q>/<n>       the same with |Q| = 16 points (a large P against a small Q)
//   hulls/<q>/all         the 60 shared real hulls (../shared/data/hulls, 4–~60 vertices), pairs
//                         (i, i + 7), Q rotated and placed around P's centroid, overlapping
//   with <q> = sigma (minimum_depth), sigma_d_dk (Compute-Depth-3D, convex3::directional_depth_dk),
//   sigma_d_expand (the certified expansion's Phase D, convex3::directional_depth_expand); every
//   query is checked before timing: both σ_d methods agree within 8 ulps and on overlap, σ ≤ σ_d.
//   They chose pendepth::directional_depth's rule (no size crossover: a work budget, see
//   convex3::directional_work_budget) and report the work against that budget.
// libccd's support functions are written here as plain scans over the vertex arrays (as
// Bullet's btConvexHullShape does); FCL's Convex walks its vertex adjacency for > 32 vertices.
// Inputs (fixed seed per size, generated outside the timed loops): P and Q are the hulls
// (ConvexPolytope::hull) of n points on random ellipsoids; σ uses kQueries random rotations of Q
// with random translations, kept when pendepth reports an overlap. The exact value of each query
// is pendepth's certified σ (lower_bound == upper_bound), checked against the O(n·m) facet
// enumeration (src/convex3/minkowski_facets) when n <= kVerifyMax; a disagreement beyond 8 ulps
// fails the benchmark. Before timing, each peer runs every query once: the counters err_max /
// err_median (|depth − exact|) and failures (exception, NaN/inf, "no contact", or relative
// error > kFailRel) come from that pass. bench/run_convex3.sh prints the tables of
// docs/benchmarks.md from this program's JSON output.
#include <benchmark/benchmark.h>
#include <pendepth/depth3.hpp>
#include <pendepth/io.hpp>
#include <pendepth/polytope.hpp>

#include "convex3/distance_compare.hpp"
#include "convex3/minimum_expand.hpp"
#include "convex3/minkowski_facets.hpp"
#include "hulls3.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#if PENDEPTH_BENCH_CCD
#include <ccd/ccd.h>
#endif
#if PENDEPTH_BENCH_FCL
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#endif
#if PENDEPTH_BENCH_BULLET
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkConvexCast.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#endif

namespace {

using pendepth::ConvexPolytope;
using pendepth::Depth3;
using pendepth::Pose3;
using pendepth::Vec3;
using Mat3 = Eigen::Matrix3d;
using Clock = std::chrono::steady_clock;

constexpr std::size_t kQueries = 64;       // σ queries per size
constexpr std::size_t kDirQueries = 256;   // σ_d queries per size
constexpr std::size_t kVerifyMax = 512;    // O(n·m) exact check of every σ query up to here
constexpr std::size_t kDirVerifyMax = 4096;  // O(n·m) exact check of σ_d queries up to here,
constexpr std::size_t kDirVerifyCount = 32;  // the first this many
constexpr double kFailRel = 1e-6;          // relative error that counts as a failure
constexpr std::size_t kDirQ = 64;          // |Q| in the σ_d series

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// n points on an ellipsoid with semi-axes in [0.8, 1.25], centred at the origin.
std::vector<Vec3> ellipsoid_points(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.8, 1.25);
  std::normal_distribution<double> g;
  const Vec3 axes(U(rng), U(rng), U(rng));
  std::vector<Vec3> p;
  p.reserve(n);
  while (p.size() < n) {
    Vec3 v(g(rng), g(rng), g(rng));
    if (v.norm() > 1e-3) p.push_back(v.normalized().cwiseProduct(axes));
  }
  return p;
}

using pendepth::bench::centroid;
using pendepth::bench::radius;
using pendepth::bench::random_in_ball;
using pendepth::bench::random_rotation;
using pendepth::bench::shared_hulls;

// The O(n·m) exact reference for σ (as tests/convex3): min over every implicit facet of M.
struct Ref {
  bool overlapping = true;
  double sigma = std::numeric_limits<double>::infinity();
};
Ref sigma_reference(const ConvexPolytope& P, const ConvexPolytope& Q, const Mat3& R, const Vec3& t) {
  pendepth::convex3::RelativePose rel;
  rel.R = R, rel.tq = t;  // P at the identity: exactly what depth3.cpp forms
  Ref r;
  for (const auto& k : pendepth::convex3::minkowski_facets(P, Q, rel, std::nullopt)) {
    if (k.sign <= 0) return Ref{false, 0};
    r.sigma = std::min(r.sigma, k.distance);
  }
  return r;
}

struct Query {
  int pair = 0;  // index into SigmaCase::P / Q
  Pose3 pose;    // of Q (P at the identity)
  Mat3 R;      // pose.matrix(): the same doubles for every implementation
  double exact = 0;
};

struct SigmaCase {
  std::size_t n = 0;                 // 0: the shared real hulls
  std::vector<ConvexPolytope> P, Q;  // pairs (one for n > 0)
  std::vector<Query> queries;
  double hull_ms = 0;        // both hulls
  std::size_t verified = 0;  // queries checked against the O(n·m) reference
  double ref_max_ulps = 0;
  std::string error;
};

// The hull set of the `sigma_hulls/` and `distance/` rows: the shared game hulls, or with
// PENDEPTH_BENCH_GEN_HULLS=N sixty generated hulls of N points on random ellipsoids (inputs beyond
// ../shared/data; the same placements, pairs and peers).
std::vector<ConvexPolytope> real_or_generated_hulls() {
  const char* g = std::getenv("PENDEPTH_BENCH_GEN_HULLS");
  if (!g) return shared_hulls();
  const std::size_t n = std::strtoull(g, nullptr, 10);
  std::mt19937_64 rng(0x9e4d157 + n);
  std::vector<ConvexPolytope> H;
  for (int k = 0; k < 60 && n >= 4; ++k) H.push_back(ConvexPolytope::hull(ellipsoid_points(n, rng), "G"));
  return H;
}

SigmaCase build_sigma_case(std::size_t n) {
  std::mt19937_64 rng(0x5eed3000 + n);
  auto pp = ellipsoid_points(n, rng), qp = ellipsoid_points(n, rng);
  auto t0 = Clock::now();
  SigmaCase c;
  c.n = n;
  c.P.push_back(ConvexPolytope::hull(pp, "P")), c.Q.push_back(ConvexPolytope::hull(qp, "Q"));
  c.hull_ms = ms_since(t0);
  std::size_t attempts = 0;
  while (c.queries.size() < kQueries && attempts++ < 100 * kQueries) {
    Query q;
    q.pose = Pose3(random_rotation(rng), random_in_ball(rng, 1.0));
    q.R = q.pose.matrix();
    Depth3 d = pendepth::minimum_depth(c.P[0], Pose3(), c.Q[0], q.pose);
    if (!d.overlapping) continue;
    if (d.lower_bound != d.upper_bound) c.error = "pendepth result not certified";
    q.exact = d.depth;
    if (n <= kVerifyMax) {
      Ref ref = sigma_reference(c.P[0], c.Q[0], q.R, q.pose.translation);
      double ulps = ref.overlapping ? std::abs(ref.sigma - d.depth) / (ref.sigma * 0x1p-52) : 1e300;
      c.ref_max_ulps = std::max(c.ref_max_ulps, ulps);
      if (ulps > 8) c.error = "pendepth σ disagrees with the O(n·m) reference";
      ++c.verified;
    }
    c.queries.push_back(q);
  }
  if (c.queries.size() < kQueries) c.error = "too few overlapping placements";
  return c;
}

SigmaCase build_hulls_sigma_case();  // below: the shared real hulls (n = 0)

const SigmaCase& sigma_case(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<SigmaCase>> cache;
  auto& p = cache[n];
  if (!p) p = std::make_unique<SigmaCase>(n == 0 ? build_hulls_sigma_case() : build_sigma_case(n));
  return *p;
}

// A depth query of one implementation: NaN for "no contact", throws on failure.
using DepthFn = std::function<double(std::size_t)>;
using Factory = std::function<DepthFn(const SigmaCase&)>;

// ---- peers ----

#if PENDEPTH_BENCH_CCD
// libccd object: vertices in their own frame, placed by (R, t); support = scan over the array.
struct CcdHull {
  const std::vector<Vec3>* v;
  Mat3 R = Mat3::Identity();
  Vec3 t = Vec3::Zero();
};
void ccd_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto& h = *static_cast<const CcdHull*>(obj);
  const Vec3 d = h.R.transpose() * Vec3(dir->v[0], dir->v[1], dir->v[2]);
  const std::vector<Vec3>& v = *h.v;
  std::size_t best = 0;
  double bv = d.dot(v[0]);
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double x = d.dot(v[i]);
    if (x > bv) bv = x, best = i;
  }
  const Vec3 w = h.R * v[best] + h.t;
  out->v[0] = w.x(), out->v[1] = w.y(), out->v[2] = w.z();
}
void ccd_center(const void* obj, ccd_vec3_t* out) {
  const auto& h = *static_cast<const CcdHull*>(obj);
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : *h.v) c += p;
  c = h.R * (c / double(h.v->size())) + h.t;
  out->v[0] = c.x(), out->v[1] = c.y(), out->v[2] = c.z();
}

Factory ccd_factory(bool mpr, bool tight) {
  return [mpr, tight](const SigmaCase& c) -> DepthFn {
    using Verts = std::vector<std::vector<Vec3>>;
    auto pv = std::make_shared<Verts>(), qv = std::make_shared<Verts>();
    for (std::size_t k = 0; k < c.P.size(); ++k) {
      pv->emplace_back(c.P[k].vertices().begin(), c.P[k].vertices().end());
      qv->emplace_back(c.Q[k].vertices().begin(), c.Q[k].vertices().end());
    }
    return [pv, qv, mpr, tight, &c](std::size_t i) {
      const Query& q = c.queries[i];
      CcdHull a{&(*pv)[q.pair]}, b{&(*qv)[q.pair], q.R, q.pose.translation};
      ccd_t ccd;
      CCD_INIT(&ccd);
      ccd.support1 = ccd.support2 = ccd_support;
      ccd.center1 = ccd.center2 = ccd_center;
      if (tight) ccd.epa_tolerance = 1e-10, ccd.max_iterations = 1000;
      ccd_real_t depth = 0;
      ccd_vec3_t dir, pos;
      int r = mpr ? ccdMPRPenetration(&a, &b, &ccd, &depth, &dir, &pos)
                  : ccdGJKPenetration(&a, &b, &ccd, &depth, &dir, &pos);
      if (r == -2) throw std::runtime_error("libccd: out of memory");
      return r == 0 ? double(depth) : std::numeric_limits<double>::quiet_NaN();
    };
  };
}
#endif

#if PENDEPTH_BENCH_FCL
std::shared_ptr<fcl::Convexd> fcl_convex(const ConvexPolytope& S) {
  auto v = std::make_shared<std::vector<fcl::Vector3d>>(S.vertices().begin(), S.vertices().end());
  auto f = std::make_shared<std::vector<int>>();
  for (const auto& t : S.triangles()) f->insert(f->end(), {3, t[0], t[1], t[2]});
  return std::make_shared<fcl::Convexd>(v, int(S.triangles().size()), f);
}

Factory fcl_factory(bool signed_distance) {
  return [signed_distance](const SigmaCase& c) -> DepthFn {
    auto shapes = std::make_shared<std::vector<std::pair<std::shared_ptr<fcl::Convexd>, std::shared_ptr<fcl::Convexd>>>>();
    for (std::size_t k = 0; k < c.P.size(); ++k) shapes->emplace_back(fcl_convex(c.P[k]), fcl_convex(c.Q[k]));
    return [shapes, signed_distance, &c](std::size_t i) {
      const Query& q = c.queries[i];
      const auto& [a, b] = (*shapes)[q.pair];
      fcl::Transform3d ta = fcl::Transform3d::Identity(), tb = fcl::Transform3d::Identity();
      tb.linear() = q.R;
      tb.translation() = q.pose.translation;
      if (signed_distance) {
        fcl::DistanceRequestd req(false, true, 0, 0, 1e-6, fcl::GST_LIBCCD);
        fcl::DistanceResultd res;
        fcl::distance(a.get(), ta, b.get(), tb, req, res);
        return res.min_distance < 0 ? -res.min_distance : std::numeric_limits<double>::quiet_NaN();
      }
      fcl::CollisionRequestd req(1, true, 1, false, true, fcl::GST_INDEP, 1e-6);
      fcl::CollisionResultd res;
      fcl::collide(a.get(), ta, b.get(), tb, req, res);
      if (!res.isCollision() || res.numContacts() == 0) return std::numeric_limits<double>::quiet_NaN();
      // FCL 0.7's GJKSolver_indep stores −(EPA depth) in the contact: the magnitude is the depth.
      return std::abs(res.getContact(0).penetration_depth);
    };
  };
}
#endif

#if PENDEPTH_BENCH_BULLET
std::shared_ptr<btConvexHullShape> bullet_hull(const ConvexPolytope& S) {
  auto h = std::make_shared<btConvexHullShape>();
  for (const Vec3& p : S.vertices()) h->addPoint(btVector3(p.x(), p.y(), p.z()), false);
  h->recalcLocalAabb();
  h->setMargin(0);  // otherwise Bullet pads the hull by 0.04
  return h;
}

// Q's pose for Bullet: from the query's rotation matrix (converted once, outside the timed loop),
// or (`from_quaternion`, the rows …_q) from the same quaternion pendepth receives, converted per
// query by Bullet's btMatrix3x3::setRotation — what pendepth pays for its Pose3 (40–50 ns).
btTransform bullet_pose(const Mat3& R, const Pose3& pose, bool from_quaternion) {
  const Vec3& t = pose.translation;
  const btVector3 origin(t.x(), t.y(), t.z());
  if (from_quaternion) {
    const Eigen::Quaterniond& r = pose.rotation;
    return btTransform(btQuaternion(r.x(), r.y(), r.z(), r.w()), origin);
  }
  return btTransform(btMatrix3x3(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)), origin);
}

Factory bullet_factory(bool from_quaternion) {
  return [from_quaternion](const SigmaCase& c) -> DepthFn {
    auto shapes = std::make_shared<std::vector<std::pair<std::shared_ptr<btConvexHullShape>, std::shared_ptr<btConvexHullShape>>>>();
    for (std::size_t k = 0; k < c.P.size(); ++k) shapes->emplace_back(bullet_hull(c.P[k]), bullet_hull(c.Q[k]));
    return [shapes, from_quaternion, &c](std::size_t i) {
      const Query& q = c.queries[i];
      const auto& [a, b] = (*shapes)[q.pair];
      const Vec3& t = q.pose.translation;
      btTransform ta;
      ta.setIdentity();
      const btTransform tb = bullet_pose(q.R, q.pose, from_quaternion);
      btVector3 guess = t.squaredNorm() > 0 ? btVector3(t.x(), t.y(), t.z()) : btVector3(1, 0, 0);
      btGjkEpaSolver2::sResults res;
      // The normal comes back in A's frame (here the world frame): only the distance is used.
      if (!btGjkEpaSolver2::Penetration(a.get(), ta, b.get(), tb, guess, res))
        return std::numeric_limits<double>::quiet_NaN();
      return double(-res.distance);
    };
  };
}
#endif

Factory pendepth_factory() {
  return [](const SigmaCase& c) -> DepthFn {
    return [&c](std::size_t i) {
      const Query& q = c.queries[i];
      return pendepth::minimum_depth(c.P[q.pair], Pose3(), c.Q[q.pair], q.pose).depth;
    };
  };
}

void bm_sigma(benchmark::State& state, Factory make, std::size_t n) {
  const SigmaCase& c = sigma_case(n);
  if (!c.error.empty()) {
    state.SkipWithError(c.error.c_str());
    return;
  }
  DepthFn f = make(c);
  // Accuracy pass: every query once.
  std::vector<double> errs;
  int failures = 0, exceptions = 0, no_contact = 0;
  for (std::size_t i = 0; i < c.queries.size(); ++i) {
    const double exact = c.queries[i].exact;
    double d;
    try {
      d = f(i);
    } catch (const std::exception&) {
      ++failures, ++exceptions;
      continue;
    }
    if (!std::isfinite(d)) {
      ++failures, ++no_contact;
      continue;
    }
    const double e = std::abs(d - exact);
    errs.push_back(e);
    failures += e > kFailRel * exact;
  }
  std::sort(errs.begin(), errs.end());
  std::size_t i = 0;
  for (auto _ : state) {
    try {
      benchmark::DoNotOptimize(f(i));
    } catch (const std::exception&) {
    }
    i = i + 1 == c.queries.size() ? 0 : i + 1;
  }
  state.counters["queries"] = double(c.queries.size());
  state.counters["failures"] = failures;
  state.counters["exceptions"] = exceptions;
  state.counters["no_contact"] = no_contact;
  state.counters["err_max"] = errs.empty() ? -1 : errs.back();
  state.counters["err_median"] = errs.empty() ? -1 : errs[errs.size() / 2];
  state.counters["verified"] = double(c.verified);
  state.counters["ref_max_ulps"] = c.ref_max_ulps;
  state.counters["hull_ms"] = c.hull_ms;
  double mean = 0;
  for (const Query& q : c.queries) mean += q.exact;
  state.counters["depth_mean"] = mean / double(c.queries.size());
}

// ---- σ_d: pendepth vs the linear scan over M's facets ----

struct DirCase {
  std::size_t n = 0;
  ConvexPolytope P, Q;
  Eigen::Quaterniond rot;
  Mat3 R;
  std::vector<Vec3> t, d;  // placements of Q (with rotation rot), unit directions
  // M's facets for rotation R and translation 0, as planes unit·x <= off (a superset is fine).
  std::vector<double> ux, uy, uz, off;
  double hull_ms = 0, facets_ms = 0;
  std::size_t verified = 0;
  double max_diff_scan = 0, max_ulps_exact = 0;
  std::string error;

  double scan(std::size_t i) const {
    const Vec3& tt = t[i];
    const Vec3& dd = d[i];
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < off.size(); ++k) {
      const double ud = ux[k] * dd.x() + uy[k] * dd.y() + uz[k] * dd.z();
      if (ud > 0) {
        const double s = (off[k] - (ux[k] * tt.x() + uy[k] * tt.y() + uz[k] * tt.z())) / ud;
        best = std::min(best, s);
      }
    }
    return best;
  }
};

namespace pc3 = pendepth::convex3;
}  // namespace

namespace pendepth::convex3 {
// Test reference of depth3.cpp: σ_d as the exit over ALL implicit facets of M, O(n·m) exact.
Depth3 directional_depth_facets(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                                const Pose3& pose_q, const Vec3& d);
}  // namespace pendepth::convex3

namespace {

DirCase build_dir_case(std::size_t n) {
  std::mt19937_64 rng(0xd1ec3000 + n);
  auto pp = ellipsoid_points(n, rng), qp = ellipsoid_points(kDirQ, rng);
  DirCase c;
  c.n = n;
  auto t0 = Clock::now();
  c.P = ConvexPolytope::hull(pp, "P");
  c.hull_ms = ms_since(t0);
  c.Q = ConvexPolytope::hull(qp, "Q");
  c.rot = random_rotation(rng);
  c.R = Pose3(c.rot, Vec3::Zero()).matrix();
  t0 = Clock::now();
  pc3::RelativePose rel;
  rel.R = c.R;
  for (const auto& k : pc3::minkowski_facets(c.P, c.Q, rel, std::nullopt)) {
    if (k.sign <= 0) {
      c.error = "M does not contain the origin at translation 0";
      return c;
    }
    c.ux.push_back(k.unit.x()), c.uy.push_back(k.unit.y()), c.uz.push_back(k.unit.z());
    c.off.push_back(k.distance);
  }
  c.facets_ms = ms_since(t0);
  std::size_t attempts = 0;
  while (c.t.size() < kDirQueries && attempts++ < 100 * kDirQueries) {
    Vec3 t = random_in_ball(rng, 1.0);
    Vec3 d = random_in_ball(rng, 1.0);
    if (d.norm() < 1e-3) continue;
    d.normalize();
    Pose3 pq(c.rot, t);
    Depth3 r = pendepth::directional_depth(c.P, Pose3(), c.Q, pq, d);
    if (!r.overlapping) continue;
    c.t.push_back(t), c.d.push_back(d);
    const std::size_t i = c.t.size() - 1;
    c.max_diff_scan = std::max(c.max_diff_scan, std::abs(c.scan(i) - r.depth));
    if (n <= kDirVerifyMax && c.verified < kDirVerifyCount) {
      Depth3 ref = pc3::directional_depth_facets(c.P, Pose3(), c.Q, pq, d);
      const double ulps = std::abs(ref.depth - r.depth) / (ref.depth * 0x1p-52);
      c.max_ulps_exact = std::max(c.max_ulps_exact, ulps);
      if (!ref.overlapping || ulps > 8) c.error = "pendepth σ_d disagrees with the O(n·m) reference";
      ++c.verified;
    }
  }
  if (c.t.size() < kDirQueries) c.error = "too few overlapping placements";
  if (c.max_diff_scan > 1e-9) c.error = "facet scan disagrees with pendepth σ_d";
  return c;
}

const DirCase& dir_case(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<DirCase>> cache;
  auto& p = cache[n];
  if (!p) p = std::make_unique<DirCase>(build_dir_case(n));
  return *p;
}

enum class DirImpl { Public, Scan, DK, Expand };

void bm_dir(benchmark::State& state, DirImpl impl, std::size_t n) {
  const DirCase& c = dir_case(n);
  if (!c.error.empty()) {
    state.SkipWithError(c.error.c_str());
    return;
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const Pose3 pq(c.rot, c.t[i]);
    switch (impl) {
      case DirImpl::Public:
        benchmark::DoNotOptimize(pendepth::directional_depth(c.P, Pose3(), c.Q, pq, c.d[i]).depth);
        break;
      case DirImpl::Scan: benchmark::DoNotOptimize(c.scan(i)); break;
      case DirImpl::DK: benchmark::DoNotOptimize(pc3::directional_depth_dk(c.P, Pose3(), c.Q, pq, c.d[i]).depth); break;
      case DirImpl::Expand:
        benchmark::DoNotOptimize(pc3::directional_depth_expand(c.P, Pose3(), c.Q, pq, c.d[i]).depth);
        break;
    }
    i = i + 1 == c.t.size() ? 0 : i + 1;
  }
  if (impl == DirImpl::Expand || impl == DirImpl::DK) {  // agreement with the public query
    double worst = 0;
    for (std::size_t k = 0; k < c.t.size(); ++k) {
      const Pose3 pq(c.rot, c.t[k]);
      const double a = pendepth::directional_depth(c.P, Pose3(), c.Q, pq, c.d[k]).depth;
      const double b = impl == DirImpl::DK ? pc3::directional_depth_dk(c.P, Pose3(), c.Q, pq, c.d[k]).depth
                                           : pc3::directional_depth_expand(c.P, Pose3(), c.Q, pq, c.d[k]).depth;
      worst = std::max(worst, std::abs(a - b) / (a * 0x1p-52));
    }
    state.counters["max_ulps_vs_public"] = worst;
    if (worst > 8) state.SkipWithError("σ_d methods disagree");
  }
  state.counters["P_vertices"] = double(c.P.size());
  state.counters["Q_vertices"] = double(c.Q.size());
  state.counters["M_facets"] = double(c.off.size());
  state.counters["hull_ms"] = c.hull_ms;
  state.counters["facets_ms"] = c.facets_ms;
  state.counters["verified"] = double(c.verified);
  state.counters["max_ulps_exact"] = c.max_ulps_exact;
  state.counters["max_diff_scan"] = c.max_diff_scan;
}

// ---- σ, σ_d (DK) and σ_d (expansion) on the same queries ----

struct CrossQuery {
  int pair = 0;  // index into CrossCase::P / Q
  Pose3 pose;    // of Q (P at the identity)
  Vec3 d;
};

struct CrossCase {
  std::vector<ConvexPolytope> P, Q;
  std::vector<CrossQuery> queries;
  double max_ulps = 0;  // between the two σ_d methods
  double supports_sigma = 0, supports_expand = 0;  // per query
  double work_mean = 0, work_max = 0, budget_share_max = 0;  // the expansion's work (σ_d)
  std::string error;
};

// Keeps q if the shapes overlap there; checks the two σ_d methods against each other and σ ≤ σ_d.
void add_cross_query(CrossCase& c, const CrossQuery& q) {
  const ConvexPolytope &P = c.P[q.pair], &Q = c.Q[q.pair];
  Depth3 s = pendepth::minimum_depth(P, Pose3(), Q, q.pose);
  if (!s.overlapping) return;
  Depth3 a = pc3::directional_depth_expand(P, Pose3(), Q, q.pose, q.d);
  std::size_t work = 0;
  pc3::RelativePose rel;
  rel.R = q.pose.matrix(), rel.tq = q.pose.translation;
  (void)pc3::directional_depth_expand(P, Q, rel, q.d, Mat3::Identity(), Vec3::Zero(), SIZE_MAX, &work);
  const double share = double(work) / double(pc3::directional_work_budget(P.size(), Q.size()));
  c.work_mean += double(work), c.work_max = std::max(c.work_max, double(work));
  c.budget_share_max = std::max(c.budget_share_max, share);
  Depth3 b = pc3::directional_depth_dk(P, Pose3(), Q, q.pose, q.d);
  const double ulps = std::abs(a.depth - b.depth) / (std::max(a.depth, b.depth) * 0x1p-52);
  c.max_ulps = std::max(c.max_ulps, ulps);
  if (!a.overlapping || !b.overlapping || ulps > 8) c.error = "σ_d: expansion and DK disagree";
  if (s.depth > a.depth * (1 + 0x1p-50)) c.error = "σ > σ_d";
  c.supports_sigma += double(s.candidates);
  c.supports_expand += double(a.candidates);
  c.queries.push_back(q);
}

void finish_cross_case(CrossCase& c, std::size_t want) {
  if (c.queries.size() < want) c.error = "too few overlapping placements";
  c.supports_sigma /= double(std::max<std::size_t>(c.queries.size(), 1));
  c.supports_expand /= double(std::max<std::size_t>(c.queries.size(), 1));
  c.work_mean /= double(std::max<std::size_t>(c.queries.size(), 1));
}

// n ellipsoid points for P, m for Q (m = 0: m = n).
const CrossCase& small_case(std::size_t n, std::size_t m) {
  static std::map<std::pair<std::size_t, std::size_t>, std::unique_ptr<CrossCase>> cache;
  auto& p = cache[{n, m}];
  if (p) return *p;
  p = std::make_unique<CrossCase>();
  CrossCase& c = *p;
  std::mt19937_64 rng(0x5a11c3 + 7919 * n + m);
  constexpr int kShapes = 8;
  for (int k = 0; k < kShapes; ++k) {
    c.P.push_back(ConvexPolytope::hull(ellipsoid_points(n, rng), "P"));
    c.Q.push_back(ConvexPolytope::hull(ellipsoid_points(m ? m : n, rng), "Q"));
  }
  std::size_t attempts = 0;
  while (c.queries.size() < kDirQueries && attempts++ < 100 * kDirQueries) {
    CrossQuery q;
    q.pair = int(attempts % kShapes);
    q.pose = Pose3(random_rotation(rng), random_in_ball(rng, 1.0));
    q.d = random_in_ball(rng, 1.0);
    if (q.d.norm() < 1e-3) continue;
    add_cross_query(c, q);
  }
  finish_cross_case(c, kDirQueries);
  return c;
}

const CrossCase& hulls_case() {
  static std::unique_ptr<CrossCase> p;
  if (p) return *p;
  p = std::make_unique<CrossCase>();
  CrossCase& c = *p;
  const std::vector<ConvexPolytope> H = real_or_generated_hulls();
  if (H.size() < 8) {
    c.error = "shared hulls not found";
    return c;
  }
  std::mt19937_64 rng(0x6a11);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  for (std::size_t i = 0; i < H.size(); ++i) c.P.push_back(H[i]), c.Q.push_back(H[(i + 7) % H.size()]);
  const std::size_t want = 16 * H.size();
  std::size_t attempts = 0;
  while (c.queries.size() < want && attempts++ < 100 * want) {
    CrossQuery q;
    q.pair = int(attempts % H.size());
    const ConvexPolytope &P = c.P[q.pair], &Q = c.Q[q.pair];
    const Vec3 cp = centroid(P);
    const double r = radius(P);
    auto rot = random_rotation(rng);
    q.pose = Pose3(rot, cp - rot.toRotationMatrix() * centroid(Q) + r * Vec3(U(rng), U(rng), U(rng)));
    q.d = random_in_ball(rng, 1.0);
    if (q.d.norm() < 1e-3) continue;
    add_cross_query(c, q);
  }
  finish_cross_case(c, want);
  return c;
}

// Hard inputs for the expansion (same queries for the three methods): massive coplanarity and
// hub vertices of high degree (long climbs), slivers, a fine sphere; Q a small integer sphere or
// a random hull.
std::vector<Vec3> integer_sphere_points(int N) {
  std::vector<Vec3> p;
  const int R = static_cast<int>(std::sqrt(double(N))) + 1;
  for (int x = -R; x <= R; ++x)
    for (int y = -R; y <= R; ++y)
      for (int z = -R; z <= R; ++z)
        if (x * x + y * y + z * z == N) p.emplace_back(x, y, z);
  return p;
}
std::vector<Vec3> circle_solid(int k, double z0, double z1, bool apexes) {  // prism or bipyramid
  std::vector<Vec3> p;
  for (int i = 0; i < k; ++i) {
    const double t = 2 * M_PI * i / k;
    if (apexes) {
      p.emplace_back(std::cos(t), std::sin(t), 0);
    } else {
      p.emplace_back(std::cos(t), std::sin(t), z0);
      p.emplace_back(std::cos(t), std::sin(t), z1);
    }
  }
  if (apexes) p.emplace_back(0, 0, z1), p.emplace_back(0, 0, z0);
  return p;
}
const char* const kHardNames[] = {"intsphere1105", "bipyramid2000", "prism2000", "sliver1000", "sphere20000"};

const CrossCase& hard_case(std::size_t which) {
  static std::map<std::size_t, std::unique_ptr<CrossCase>> cache;
  auto& p = cache[which];
  if (p) return *p;
  p = std::make_unique<CrossCase>();
  CrossCase& c = *p;
  std::mt19937_64 rng(0x4a2d + which);
  std::vector<Vec3> pts;
  double scale = 1;
  switch (which) {
    case 0: pts = integer_sphere_points(1105), scale = 33; break;
    case 1: pts = circle_solid(2000, -0.5, 1.5, true); break;
    case 2: pts = circle_solid(2000, -0.3, 0.3, false); break;
    case 3: {
      pts = ellipsoid_points(1000, rng);
      for (auto& x : pts) x.z() *= 1e-6;
      break;
    }
    default: pts = ellipsoid_points(20000, rng); break;
  }
  c.P.push_back(ConvexPolytope::hull(pts, kHardNames[which]));
  auto q = which == 0 ? integer_sphere_points(11) : ellipsoid_points(24, rng);
  for (auto& x : q) x *= which == 0 ? 3.0 : 0.4;
  c.Q.push_back(ConvexPolytope::hull(q, "Q"));
  std::size_t attempts = 0;
  std::uniform_int_distribution<int> I(-30, 30);
  while (c.queries.size() < kQueries && attempts++ < 1000 * kQueries) {
    CrossQuery cq;
    cq.pose = which == 0 ? Pose3(Vec3(I(rng), I(rng), I(rng)))  // integer: exact coincidences
                         : Pose3(random_rotation(rng), scale * random_in_ball(rng, 1.0));
    cq.d = random_in_ball(rng, 1.0);
    if (cq.d.norm() < 1e-3) continue;
    if (which == 0 && attempts % 2) cq.d = Vec3(I(rng) % 2, I(rng) % 2, 1);  // axis-like directions
    add_cross_query(c, cq);
  }
  finish_cross_case(c, kQueries);
  return c;
}

// σ against the peers on the shared real hulls (sigma_hulls/<impl>): hulls_case()'s pairs and
// placements; each exact σ is also checked against the O(n·m) facet reference (≤ 8 ulps).
SigmaCase build_hulls_sigma_case() {
  const CrossCase& h = hulls_case();
  SigmaCase c;
  c.error = h.error;
  c.P = h.P, c.Q = h.Q;
  for (const CrossQuery& x : h.queries) {
    Query q;
    q.pair = x.pair, q.pose = x.pose, q.R = x.pose.matrix();
    const Depth3 d = pendepth::minimum_depth(c.P[q.pair], Pose3(), c.Q[q.pair], q.pose);
    if (d.lower_bound != d.upper_bound) c.error = "pendepth result not certified";
    q.exact = d.depth;
    const Ref ref = sigma_reference(c.P[q.pair], c.Q[q.pair], q.R, q.pose.translation);
    const double ulps = ref.overlapping ? std::abs(ref.sigma - d.depth) / (ref.sigma * 0x1p-52) : 1e300;
    c.ref_max_ulps = std::max(c.ref_max_ulps, ulps);
    if (ulps > 8) c.error = "pendepth σ disagrees with the O(n·m) reference";
    ++c.verified;
    c.queries.push_back(q);
  }
  return c;
}

enum class CrossQ { Sigma, SigmaDK, SigmaExpand };

void bm_cross(benchmark::State& state, CrossQ which, const CrossCase* (*get)(std::size_t, std::size_t),
              std::size_t n, std::size_t m) {
  const CrossCase& c = *get(n, m);
  if (!c.error.empty()) {
    state.SkipWithError(c.error.c_str());
    return;
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const CrossQuery& q = c.queries[i];
    const ConvexPolytope &P = c.P[q.pair], &Q = c.Q[q.pair];
    double v = 0;
    switch (which) {
      case CrossQ::Sigma: v = pendepth::minimum_depth(P, Pose3(), Q, q.pose).depth; break;
      case CrossQ::SigmaDK: v = pc3::directional_depth_dk(P, Pose3(), Q, q.pose, q.d).depth; break;
      case CrossQ::SigmaExpand: v = pc3::directional_depth_expand(P, Pose3(), Q, q.pose, q.d).depth; break;
    }
    benchmark::DoNotOptimize(v);
    i = i + 1 == c.queries.size() ? 0 : i + 1;
  }
  double vp = 0, vq = 0;
  for (std::size_t k = 0; k < c.P.size(); ++k) vp += double(c.P[k].size()), vq += double(c.Q[k].size());
  state.counters["P_vertices"] = vp / double(c.P.size());
  state.counters["Q_vertices"] = vq / double(c.Q.size());
  state.counters["queries"] = double(c.queries.size());
  state.counters["max_ulps_dk_vs_expand"] = c.max_ulps;
  state.counters["supports_sigma"] = c.supports_sigma;
  state.counters["supports_expand"] = c.supports_expand;
  state.counters["work_mean"] = c.work_mean;
  state.counters["work_max"] = c.work_max;
  state.counters["budget_share_max"] = c.budget_share_max;
}

const CrossCase* small_getter(std::size_t n, std::size_t m) { return &small_case(n, m); }
const CrossCase* hulls_getter(std::size_t, std::size_t) { return &hulls_case(); }
const CrossCase* hard_getter(std::size_t which, std::size_t) { return &hard_case(which); }

void register_cross() {
  const std::pair<CrossQ, const char*> qs[] = {
      {CrossQ::Sigma, "sigma"}, {CrossQ::SigmaDK, "sigma_d_dk"}, {CrossQ::SigmaExpand, "sigma_d_expand"}};
  for (const auto& [w, name] : qs)
    benchmark::RegisterBenchmark((std::string("hulls/") + name + "/all").c_str(), bm_cross, w, hulls_getter, 0, 0)
        ->Unit(benchmark::kMicrosecond);
  for (std::size_t n : {4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048})
    for (const auto& [w, name] : qs)
      benchmark::RegisterBenchmark((std::string("small/") + name + "/" + std::to_string(n)).c_str(), bm_cross, w,
                                   small_getter, n, 0)
          ->Unit(benchmark::kMicrosecond);
  for (std::size_t k = 0; k < std::size(kHardNames); ++k)
    for (const auto& [w, name] : qs)
      benchmark::RegisterBenchmark((std::string("hard/") + name + "/" + kHardNames[k]).c_str(), bm_cross, w,
                                   hard_getter, k, 0)
          ->Unit(benchmark::kMicrosecond);
  for (std::size_t n : {64, 128, 256, 512, 1024, 4096})
    for (const auto& [w, name] : qs)
      benchmark::RegisterBenchmark((std::string("small16/") + name + "/" + std::to_string(n)).c_str(), bm_cross, w,
                                   small_getter, n, 16)
          ->Unit(benchmark::kMicrosecond);
}

}  // namespace

// ---- DHS Lemmas 5.2 / 5.3: first_hit / first_contact (outer hierarchy) vs a linear scan ----
namespace lines {

struct LineCase {
  pendepth::ConvexPolytope P;
  std::vector<pendepth::Vec3> o, d, m;
  double outer_ms = 0;
};

const LineCase& line_case(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<LineCase>> cache;
  auto& c = cache[n];
  if (c) return *c;
  std::mt19937_64 rng(4000 + n);
  std::normal_distribution<double> g;
  std::vector<pendepth::Vec3> pts;
  while (pts.size() < n) pts.push_back(pendepth::Vec3(g(rng), g(rng), g(rng)).normalized());
  c = std::make_unique<LineCase>(LineCase{pendepth::ConvexPolytope::hull(pts, "sphere"), {}, {}, {}, 0});
  auto t0 = std::chrono::steady_clock::now();
  c->P.face_count();  // builds the outer hierarchy
  c->outer_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  for (int i = 0; i < 256; ++i) {
    pendepth::Vec3 d(g(rng), g(rng), g(rng));
    c->o.push_back(pendepth::Vec3(0.4 * g(rng), 0.4 * g(rng), 0.4 * g(rng)));
    c->d.push_back(d);
    c->m.push_back(d.cross(pendepth::Vec3(g(rng), g(rng), g(rng))));
  }
  return *c;
}

// Linear reference for Lemma 5.2: entry = max over entering triangles of the plane crossing.
double scan_hit(const pendepth::ConvexPolytope& P, const pendepth::Vec3& o, const pendepth::Vec3& d) {
  double lo = -INFINITY, hi = INFINITY;
  for (const auto& t : P.triangles()) {
    const pendepth::Vec3 n = (P[t[1]] - P[t[0]]).cross(P[t[2]] - P[t[0]]);
    const double A = n.dot(d), B = n.dot(P[t[0]] - o);
    if (A < 0) lo = std::max(lo, B / A);
    else if (A > 0) hi = std::min(hi, B / A);
    else if (B < 0) return NAN;
  }
  return lo <= hi ? lo : NAN;
}

// Linear reference for Lemma 5.3: minimum shift over the crossings of the swept plane with edges.
double scan_contact(const pendepth::ConvexPolytope& P, const pendepth::Vec3& p, const pendepth::Vec3& l,
                    const pendepth::Vec3& m) {
  const pendepth::Vec3 nu = l.cross(m), w = m * l.squaredNorm() - l * l.dot(m);
  double best = INFINITY;
  for (const auto& t : P.triangles())
    for (int k = 0; k < 3; ++k) {
      const pendepth::Vec3 &a = P[t[k]], &b = P[t[(k + 1) % 3]];
      const double sa = nu.dot(a - p), sb = nu.dot(b - p);
      if ((sa > 0) == (sb > 0) && sa != 0 && sb != 0) continue;
      const pendepth::Vec3 x = sa == sb ? a : a + (sa / (sa - sb)) * (b - a);
      best = std::min(best, w.dot(x - p) / w.dot(m));
    }
  return best;
}

void bm_line(benchmark::State& state, bool contact, bool scan, std::size_t n) {
  const LineCase& c = line_case(n);
  std::size_t i = 0, nodes = 0, count = 0;
  double max_rel = 0;
  for (auto _ : state) {
    double v;
    if (contact) {
      if (scan) v = scan_contact(c.P, c.o[i], c.d[i], c.m[i]);
      else {
        auto r = c.P.first_contact(c.o[i], c.d[i], c.m[i]);
        v = r.shift, nodes += r.nodes_visited;
      }
    } else {
      if (scan) v = scan_hit(c.P, c.o[i], c.d[i]);
      else {
        auto r = c.P.first_hit(c.o[i], c.d[i]);
        v = r.t_enter, nodes += r.nodes_visited;
      }
    }
    benchmark::DoNotOptimize(v);
    ++count;
    i = (i + 1) % c.o.size();
  }
  if (!scan)  // agreement with the linear scan (outside the timed loop; 32 queries from 2^18 on)
    for (std::size_t k = 0; k < (n >= 262144 ? std::size_t(32) : c.o.size()); ++k) {
      double a = contact ? c.P.first_contact(c.o[k], c.d[k], c.m[k]).shift : c.P.first_hit(c.o[k], c.d[k]).t_enter;
      double b = contact ? scan_contact(c.P, c.o[k], c.d[k], c.m[k]) : scan_hit(c.P, c.o[k], c.d[k]);
      max_rel = std::max(max_rel, std::abs(a - b) / std::max(1.0, std::abs(b)));
    }
  state.counters["P_vertices"] = double(c.P.size());
  state.counters["outer_levels"] = double(c.P.outer_hierarchy_levels());
  state.counters["outer_build_ms"] = c.outer_ms;
  if (!scan) state.counters["nodes_per_query"] = double(nodes) / double(std::max<std::size_t>(count, 1));
  if (!scan) state.counters["max_rel_diff_scan"] = max_rel;
}

void register_benchmarks() {
  for (std::size_t n : {64, 512, 4096, 32768, 262144, 1000000})
    for (bool contact : {false, true})
      for (bool scan : {false, true})
        benchmark::RegisterBenchmark((std::string(contact ? "first_contact/" : "first_hit/") +
                                      (scan ? "scan/" : "pendepth/") + std::to_string(n))
                                         .c_str(),
                                     bm_line, contact, scan, n)
            ->Unit(benchmark::kMicrosecond);
}

}  // namespace lines


// ---- signed distance of disjoint real hulls (issue 16) ----
//   distance/pendepth       pendepth::signed_distance: exact (exact GJK + certificate)
//   distance/bullet_gjk     Bullet float64 btGjkPairDetector + btVoronoiSimplexSolver (the path
//                           of Bullet's collision world), btConvexHullShape with margin 0
//   distance/bullet_gjk_q   the same, Q's pose from the quaternion per query (as sigma/bullet_q)
//   distance/bullet_gjk2    Bullet float64 btGjkEpaSolver2::Distance (margin 0)
//   distance/fcl_ccd        FCL 0.7 fcl::distance, GST_LIBCCD (libccd's GJK), tolerance 1e-6
//   distance/fcl_indep      FCL 0.7 fcl::distance, GST_INDEP (FCL's own GJK), tolerance 1e-6
// Inputs: the 60 shared hulls, pairs (i, i + 7), Q rotated at random and placed at P's centroid
// + (r_P + r_Q)·U(0.6, 1.6) in a random direction, kept when pendepth says apart (16 per pair).
// The exact value is pendepth's (tests/oracle3/test_distance3.cpp checks it against CGAL);
// err_max / err_median = |d − exact| over one pass before timing; failures: NaN/inf, exception
// or relative error > kFailRel. (libccd 2.1 has no distance query: only through FCL.)
namespace sdist {

struct DistQuery {
  int pair = 0;
  Pose3 pose;
  Mat3 R;
  double exact = 0;
  Vec3 d;                  // cast direction: towards P's centroid, perturbed (about half hit)
  double cast_exact = 0;   // pendepth's exact time of impact (+inf: miss)
  double cast_length = 0;  // length of the sweep given to the peers (beyond every hit)
};
struct DistCase {
  std::vector<ConvexPolytope> P, Q;
  std::vector<DistQuery> queries;
  std::string error;
};

const DistCase& dist_case() {
  static std::unique_ptr<DistCase> p;
  if (p) return *p;
  p = std::make_unique<DistCase>();
  DistCase& c = *p;
  const std::vector<ConvexPolytope> H = real_or_generated_hulls();
  if (H.size() < 8) {
    c.error = "shared hulls not found";
    return c;
  }
  for (std::size_t i = 0; i < H.size(); ++i) c.P.push_back(H[i]), c.Q.push_back(H[(i + 7) % H.size()]);
  std::mt19937_64 rng(0xd157);
  std::uniform_real_distribution<double> U(0.6, 1.6);
  const std::size_t want = 16 * H.size();
  std::size_t attempts = 0;
  while (c.queries.size() < want && attempts++ < 100 * want) {
    DistQuery q;
    q.pair = int(attempts % H.size());
    const ConvexPolytope &P = c.P[q.pair], &Q = c.Q[q.pair];
    const auto rot = random_rotation(rng);
    Vec3 dir = random_in_ball(rng, 1.0);
    if (dir.norm() < 1e-3) continue;
    q.pose = Pose3(rot, centroid(P) - rot.toRotationMatrix() * centroid(Q) +
                            (radius(P) + radius(Q)) * U(rng) * dir.normalized());
    q.R = q.pose.matrix();
    const pendepth::Distance3 d = pendepth::signed_distance(P, Pose3(), Q, q.pose);
    if (!(d.distance > 0)) continue;
    q.exact = d.distance;
    q.d = (centroid(P) - q.pose.translation).normalized() + 0.5 * random_in_ball(rng, 1.0);
    if (q.d.norm() < 1e-3) continue;
    q.cast_exact = pendepth::shape_cast(P, Pose3(), Q, q.pose, q.d).distance;
    q.cast_length = 4 * (radius(P) + radius(Q)) + (q.pose.translation - centroid(P)).norm();
    c.queries.push_back(q);
  }
  if (c.queries.size() < want) c.error = "too few disjoint placements";
  return c;
}

using DistFn = std::function<double(std::size_t)>;
using DistFactory = std::function<DistFn(const DistCase&)>;

DistFactory pendepth_distance() {
  return [](const DistCase& c) -> DistFn {
    return [&c](std::size_t i) {
      const DistQuery& q = c.queries[i];
      return pendepth::signed_distance(c.P[q.pair], Pose3(), c.Q[q.pair], q.pose).distance;
    };
  };
}

// The exact GJK loop alone (the signed distance before its certified floating fast path; the
// same answers bit for bit: tests/convex3/test_distance_fast.cpp).
DistFactory pendepth_distance_exact() {
  return [](const DistCase& c) -> DistFn {
    return [&c](std::size_t i) {
      const DistQuery& q = c.queries[i];
      return pendepth::convex3::signed_distance_path(c.P[q.pair], Pose3(), c.Q[q.pair], q.pose,
                                                     pendepth::convex3::SignedDistancePath{false, 1.0})
          .distance;
    };
  };
}

#if PENDEPTH_BENCH_BULLET
btTransform bt_transform(const Mat3& R, const Vec3& t) { return bullet_pose(R, Pose3(t), false); }
DistFactory bullet_distance(bool pair_detector, bool from_quaternion = false) {
  return [pair_detector, from_quaternion](const DistCase& c) -> DistFn {
    auto hulls = std::make_shared<std::vector<std::pair<std::shared_ptr<btConvexHullShape>, std::shared_ptr<btConvexHullShape>>>>();
    for (std::size_t k = 0; k < c.P.size(); ++k) hulls->emplace_back(bullet_hull(c.P[k]), bullet_hull(c.Q[k]));
    return [hulls, pair_detector, from_quaternion, &c](std::size_t i) {
      const DistQuery& q = c.queries[i];
      const auto& [a, b] = (*hulls)[q.pair];
      btTransform ta;
      ta.setIdentity();
      const btTransform tb = bullet_pose(q.R, q.pose, from_quaternion);
      if (pair_detector) {
        btVoronoiSimplexSolver simplex;
        btGjkEpaPenetrationDepthSolver epa;  // only consulted on penetration (never here)
        btGjkPairDetector gjk(a.get(), b.get(), &simplex, &epa);
        btGjkPairDetector::ClosestPointInput in;
        in.m_transformA = ta;
        in.m_transformB = tb;
        btPointCollector out;
        gjk.getClosestPoints(in, out, nullptr);
        return out.m_hasResult ? double(out.m_distance) : std::numeric_limits<double>::quiet_NaN();
      }
      btGjkEpaSolver2::sResults res;
      const Vec3& t = q.pose.translation;
      if (!btGjkEpaSolver2::Distance(a.get(), ta, b.get(), tb, btVector3(t.x(), t.y(), t.z()), res))
        return std::numeric_limits<double>::quiet_NaN();
      return double(res.distance);
    };
  };
}
#endif

#if PENDEPTH_BENCH_FCL
DistFactory fcl_distance(fcl::GJKSolverType solver) {
  return [solver](const DistCase& c) -> DistFn {
    auto hulls = std::make_shared<std::vector<std::pair<std::shared_ptr<fcl::Convexd>, std::shared_ptr<fcl::Convexd>>>>();
    for (std::size_t k = 0; k < c.P.size(); ++k) hulls->emplace_back(fcl_convex(c.P[k]), fcl_convex(c.Q[k]));
    return [hulls, solver, &c](std::size_t i) {
      const DistQuery& q = c.queries[i];
      const auto& [a, b] = (*hulls)[q.pair];
      fcl::Transform3d ta = fcl::Transform3d::Identity(), tb = fcl::Transform3d::Identity();
      tb.linear() = q.R;
      tb.translation() = q.pose.translation;
      fcl::DistanceRequestd req(false, false, 0, 0, 1e-6, solver);
      fcl::DistanceResultd res;
      fcl::distance(a.get(), ta, b.get(), tb, req, res);
      return double(res.min_distance);
    };
  };
}
#endif

void bm_distance(benchmark::State& state, DistFactory make) {
  const DistCase& c = dist_case();
  if (!c.error.empty()) {
    state.SkipWithError(c.error.c_str());
    return;
  }
  DistFn f = make(c);
  std::vector<double> errs;
  double rel_max = 0;
  int failures = 0;
  for (std::size_t i = 0; i < c.queries.size(); ++i) {
    double d;
    try {
      d = f(i);
    } catch (const std::exception&) {
      ++failures;
      continue;
    }
    if (!std::isfinite(d)) {
      ++failures;
      continue;
    }
    const double e = std::abs(d - c.queries[i].exact);
    errs.push_back(e);
    rel_max = std::max(rel_max, e / c.queries[i].exact);
    failures += e > kFailRel * c.queries[i].exact;
  }
  std::sort(errs.begin(), errs.end());
  std::size_t i = 0;
  for (auto _ : state) {
    try {
      benchmark::DoNotOptimize(f(i));
    } catch (const std::exception&) {
    }
    i = i + 1 == c.queries.size() ? 0 : i + 1;
  }
  state.counters["queries"] = double(c.queries.size());
  state.counters["failures"] = failures;
  state.counters["err_max"] = errs.empty() ? -1 : errs.back();
  state.counters["err_median"] = errs.empty() ? -1 : errs[errs.size() / 2];
  state.counters["rel_err_max"] = rel_max;
}

// ---- shape cast on the same placements (pendepth exact vs Bullet's GJK convex cast) ----
//   cast/pendepth/hulls   pendepth::shape_cast (exact; two DK line descents)
//   cast/bullet_gjk/hulls Bullet float64 btGjkConvexCast (GJK ray cast, van den Bergen) sweeping
//                         Q over cast_length along d̂, margin 0; time of impact = fraction·length
// err_max over the queries both call a hit; failures = hit/miss disagreements (Bullet's
// default tolerances) or relative error > kFailRel.
using CastFn = std::function<double(std::size_t)>;  // +inf for a miss
using CastFactory = std::function<CastFn(const DistCase&)>;

CastFactory pendepth_cast() {
  return [](const DistCase& c) -> CastFn {
    return [&c](std::size_t i) {
      const DistQuery& q = c.queries[i];
      return pendepth::shape_cast(c.P[q.pair], Pose3(), c.Q[q.pair], q.pose, q.d).distance;
    };
  };
}

#if PENDEPTH_BENCH_BULLET
CastFactory bullet_cast() {
  return [](const DistCase& c) -> CastFn {
    auto hulls = std::make_shared<std::vector<std::pair<std::shared_ptr<btConvexHullShape>, std::shared_ptr<btConvexHullShape>>>>();
    for (std::size_t k = 0; k < c.P.size(); ++k) hulls->emplace_back(bullet_hull(c.P[k]), bullet_hull(c.Q[k]));
    return [hulls, &c](std::size_t i) {
      const DistQuery& q = c.queries[i];
      const auto& [a, b] = (*hulls)[q.pair];
      btVoronoiSimplexSolver simplex;
      btGjkConvexCast cast(b.get(), a.get(), &simplex);  // Q moves, P stays
      btTransform ta;
      ta.setIdentity();
      const btTransform from = bt_transform(q.R, q.pose.translation);
      const btTransform to = bt_transform(q.R, q.pose.translation + q.cast_length * q.d.normalized());
      btConvexCast::CastResult res;
      if (!cast.calcTimeOfImpact(from, to, ta, ta, res)) return std::numeric_limits<double>::infinity();
      return double(res.m_fraction) * q.cast_length;
    };
  };
}
#endif

void bm_cast(benchmark::State& state, CastFactory make) {
  const DistCase& c = dist_case();
  if (!c.error.empty()) {
    state.SkipWithError(c.error.c_str());
    return;
  }
  CastFn f = make(c);
  double err_max = 0;
  int failures = 0, hits = 0;
  for (std::size_t i = 0; i < c.queries.size(); ++i) {
    const double x = f(i), e = c.queries[i].cast_exact;
    hits += std::isfinite(e);
    if (std::isfinite(x) != std::isfinite(e)) {
      ++failures;
      continue;
    }
    if (!std::isfinite(e)) continue;
    err_max = std::max(err_max, std::abs(x - e));
    failures += std::abs(x - e) > kFailRel * std::max(e, 1e-300);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(i));
    i = i + 1 == c.queries.size() ? 0 : i + 1;
  }
  state.counters["queries"] = double(c.queries.size());
  state.counters["hits"] = hits;
  state.counters["failures"] = failures;
  state.counters["err_max"] = err_max;
}

void register_benchmarks() {
  std::vector<std::pair<std::string, DistFactory>> impls{{"pendepth", pendepth_distance()},
                                                         {"pendepth_exact", pendepth_distance_exact()}};
#if PENDEPTH_BENCH_BULLET
  impls.emplace_back("bullet_gjk", bullet_distance(true));
  impls.emplace_back("bullet_gjk_q", bullet_distance(true, true));
  impls.emplace_back("bullet_gjk2", bullet_distance(false));
#endif
#if PENDEPTH_BENCH_FCL
  impls.emplace_back("fcl_ccd", fcl_distance(fcl::GST_LIBCCD));
  impls.emplace_back("fcl_indep", fcl_distance(fcl::GST_INDEP));
#endif
  for (const auto& [name, make] : impls)
    benchmark::RegisterBenchmark(("distance/" + name + "/hulls").c_str(), bm_distance, make)
        ->Unit(benchmark::kMicrosecond);
  std::vector<std::pair<std::string, CastFactory>> casts{{"pendepth", pendepth_cast()}};
#if PENDEPTH_BENCH_BULLET
  casts.emplace_back("bullet_gjk", bullet_cast());
#endif
  for (const auto& [name, make] : casts)
    benchmark::RegisterBenchmark(("cast/" + name + "/hulls").c_str(), bm_cast, make)->Unit(benchmark::kMicrosecond);
}

}  // namespace sdist

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  std::vector<std::pair<std::string, Factory>> impls{{"pendepth", pendepth_factory()}};
#if PENDEPTH_BENCH_CCD
  impls.emplace_back("ccd_epa", ccd_factory(false, false));
  impls.emplace_back("ccd_epa_tight", ccd_factory(false, true));
  impls.emplace_back("ccd_mpr", ccd_factory(true, false));
#endif
#if PENDEPTH_BENCH_FCL
  impls.emplace_back("fcl_sd", fcl_factory(true));
  impls.emplace_back("fcl_epa", fcl_factory(false));
#endif
#if PENDEPTH_BENCH_BULLET
  impls.emplace_back("bullet", bullet_factory(false));
  impls.emplace_back("bullet_q", bullet_factory(true));
#endif
  for (const auto& [name, make] : impls)  // the shared real hulls (n = 0)
    benchmark::RegisterBenchmark(("sigma_hulls/" + name + "/all").c_str(), bm_sigma, make, 0)
        ->Unit(benchmark::kMicrosecond);
  for (std::size_t n : {8, 64, 512, 4096, 32768})
    for (const auto& [name, make] : impls)
      benchmark::RegisterBenchmark(("sigma/" + name + "/" + std::to_string(n)).c_str(), bm_sigma, make, n)
          ->Unit(benchmark::kMicrosecond);
  const std::pair<DirImpl, const char*> dir_impls[] = {
      {DirImpl::Public, "pendepth"}, {DirImpl::Scan, "facet_scan"}, {DirImpl::DK, "dk"}, {DirImpl::Expand, "expand"}};
  for (std::size_t n : {64, 512, 4096, 32768, 262144, 1000000})
    for (const auto& [impl, name] : dir_impls)
      benchmark::RegisterBenchmark((std::string("sigma_d/") + name + "/" + std::to_string(n)).c_str(), bm_dir, impl,
                                   n)
          ->Unit(benchmark::kMicrosecond);
  register_cross();
  lines::register_benchmarks();
  sdist::register_benchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
