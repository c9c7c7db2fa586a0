// Lower-dimensional shapes and primitives in Pair3 (issue 16 items 4, 5), peers in one run: the
// signed distance and σ of a solid hull against a point, a segment, a triangle, a sphere, a
// capsule and another hull of the same size (the existing solid–solid engine), random poses
// (half overlapping). Counters: µs per query. BM_RoundedFlatCores: rounded shapes on two
// lower-dimensional cores. BM_CurvedBullet: Bullet float64 (optional peer, as in bench_convex3) on
// the curved pairs' shapes and poses, checked against pendepth's certified brackets.
#include <pendepth/pendepth.hpp>

#include "primitives/ball3.hpp"
#include "primitives/coaxial3.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#if PENDEPTH_BENCH_BULLET
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btConvexInternalShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btMultiSphereShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#endif

using namespace pendepth;

namespace {

std::vector<Vec3> sphere_points(std::mt19937_64& rng, int n) {
  std::normal_distribution<double> g;
  std::vector<Vec3> p;
  while (static_cast<int>(p.size()) < n) p.push_back(Vec3(g(rng), g(rng), g(rng)).normalized());
  return p;
}

Shape3 other(int kind, std::mt19937_64& rng, int n) {
  switch (kind) {
    case 0: return Shape3::point(Vec3(0, 0, 0));
    case 1: return Shape3::segment(Vec3(0, 0, -0.5), Vec3(0, 0, 0.5));
    case 2: return Shape3::flat(std::vector<Vec3>{Vec3(-0.5, -0.3, 0), Vec3(0.5, -0.3, 0), Vec3(0, 0.6, 0)});
    case 3: return Shape3::sphere(0.5);
    case 4: return Shape3::capsule(0.3, 0.5);
    default: return Shape3::hull(sphere_points(rng, n));
  }
}
const char* kNames[] = {"point", "segment", "triangle", "sphere", "capsule", "hull"};

void run(benchmark::State& state, bool distance) {
  const int kind = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  std::mt19937_64 rng(42);
  const Pair3 pair(Shape3::hull(sphere_points(rng, n)), other(kind, rng, n));
  std::uniform_real_distribution<double> U(-1.6, 1.6);
  std::normal_distribution<double> g;
  std::vector<Pose3> poses;
  for (int i = 0; i < 256; ++i)
    poses.emplace_back(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(U(rng), U(rng), U(rng)));
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const Pose3& q = poses[i++ % poses.size()];
    sink += distance ? pair.signed_distance(Pose3(), q).distance : pair.minimum(Pose3(), q).depth;
  }
  benchmark::DoNotOptimize(sink);
  state.SetLabel(std::string(kNames[kind]) + " vs hull " + std::to_string(n));
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_SignedDistance(benchmark::State& s) { run(s, true); }
void BM_Minimum(benchmark::State& s) { run(s, false); }

// Curved primitives (src/primitives/support3.cpp, certified brackets): pairs of ~unit size, random
// poses (about half overlapping); counters: µs per query and the mean certified gap achieved
// (upper − lower, relative to |value| + 1e-3).
struct CurvedCase {
  std::vector<Vec3> hull;  // the 16-point hull of kinds 0–2 (Q), empty otherwise
  std::vector<Pose3> poses;
};
CurvedCase curved_case(int kind) {
  std::mt19937_64 rng(42);
  CurvedCase c;
  if (kind <= 2) c.hull = sphere_points(rng, 16);
  std::uniform_real_distribution<double> U(-1.2, 1.2);
  std::normal_distribution<double> g;
  for (int i = 0; i < 256; ++i)
    c.poses.emplace_back(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(U(rng), U(rng), U(rng)));
  return c;
}
Shape3 curved_pair_shape(int kind, bool p, const CurvedCase& c) {
  switch (kind) {
    case 0: return p ? Shape3::cylinder(0.5, 0.7) : Shape3::hull(c.hull);
    case 1: return p ? Shape3::cone(0.6, 0.7) : Shape3::hull(c.hull);
    case 2: return p ? Shape3::ellipsoid(0.5, 0.8, 0.6) : Shape3::hull(c.hull);
    case 3: return p ? Shape3::cylinder(0.5, 0.7) : Shape3::ellipsoid(0.5, 0.8, 0.6);
    case 4: return p ? Shape3::cone(0.6, 0.7) : Shape3::box(0.5, 0.4, 0.3);
    default: return p ? Shape3::ellipsoid(0.5, 0.8, 0.6) : Shape3::sphere(0.5);
  }
}
const char* kCurvedNames[] = {"cylinder vs hull 16", "cone vs hull 16", "ellipsoid vs hull 16",
                              "cylinder vs ellipsoid", "cone vs box", "ellipsoid vs sphere"};

void run_curved(benchmark::State& state, bool distance) {
  const int kind = static_cast<int>(state.range(0));
  const CurvedCase c = curved_case(kind);
  const Pair3 pair(curved_pair_shape(kind, true, c), curved_pair_shape(kind, false, c));
  const std::vector<Pose3>& poses = c.poses;
  std::size_t i = 0;
  double sink = 0, gap = 0;
  for (auto _ : state) {
    const Pose3& q = poses[i++ % poses.size()];
    if (distance) {
      const Distance3 r = pair.signed_distance(Pose3(), q);
      sink += r.distance, gap += (r.upper_bound - r.lower_bound) / (std::abs(r.distance) + 1e-3);
    } else {
      const Depth3 r = pair.minimum(Pose3(), q);
      sink += r.depth, gap += (r.upper_bound - r.lower_bound) / (r.depth + 1e-3);
    }
  }
  benchmark::DoNotOptimize(sink);
  state.SetLabel(kCurvedNames[kind]);
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["mean_rel_gap"] = gap / static_cast<double>(state.iterations());
}
// Coaxial and near-coaxial pairs (src/primitives/coaxial3.cpp): Q tilted by ε about a horizontal
// axis (ε = 0: exactly coaxial, the closed form; ε > 0: EPA), 16 placements near the centre.
// Args: pair (0: cylinder(1, 1) in rounded cylinder(1, 1) ⊕ 0.5, σ on a continuum at t = 0;
// 1: cylinder(0.5, 0.7) vs capsule(0.2, 0.3)), −log10 ε (0: ε = 0), mode (0: σ; 1: σ with the
// pre-step off, EPA; 2: σ_d along random directions, EPA). Counters: µs per query, the worst and
// the mean relative gap.
void BM_CurvedCoaxial(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const double eps = k == 0 ? 0.0 : std::pow(10.0, -k);
  const Pair3 pair = kind == 0 ? Pair3(Shape3::cylinder(1, 1), Shape3::rounded(Shape3::cylinder(1, 1), 0.5))
                               : Pair3(Shape3::cylinder(0.5, 0.7), Shape3::capsule(0.2, 0.3));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-0.2, 0.2), A(0, 6.283185307179586);
  std::vector<Pose3> poses;
  for (int i = 0; i < 16; ++i) {
    const double phi = A(rng);
    const Vec3 t = i == 0 ? Vec3::Zero() : Vec3(U(rng), U(rng), U(rng));
    poses.push_back(eps == 0 ? Pose3(t)
                             : Pose3(Eigen::Quaterniond(Eigen::AngleAxisd(eps, Vec3(std::cos(phi), std::sin(phi), 0))), t));
  }
  std::vector<Vec3> dirs;
  std::normal_distribution<double> g;
  for (int i = 0; i < 16; ++i) dirs.emplace_back(g(rng), g(rng), g(rng));
  const int mode = static_cast<int>(state.range(2));
  primitives::coaxial_enabled = mode != 1;
  std::size_t i = 0;
  double sink = 0, gap = 0, worst = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % poses.size();
    const Depth3 r = mode == 2 ? pair.along(Pose3(), poses[k], dirs[k]) : pair.minimum(Pose3(), poses[k]);
    const double g = (r.upper_bound - r.lower_bound) / r.depth;
    sink += r.depth, gap += g, worst = std::max(worst, g);
  }
  primitives::coaxial_enabled = true;
  benchmark::DoNotOptimize(sink);
  state.SetLabel(std::string(kind == 0 ? "cyl in rounded cyl" : "cyl vs capsule") +
                 (mode == 1 ? " EPA" : mode == 2 ? " sigma_d" : ""));
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["mean_rel_gap"] = gap / static_cast<double>(state.iterations());
  state.counters["worst_rel_gap"] = worst;
}

// Ball pairs (src/primitives/ball3.cpp): a sphere against a solid of revolution, σ on a ring of
// nearest points when the centre is on the axis. Args: pair (0: sphere(0.2) on the axis of
// cone(1, 1) at (0, 0, −0.3), the one placement; 1: sphere(0.2) vs cone(1, 1), 16 overlapping
// placements U(−0.6, 0.6)³, Q randomly rotated; 2: rounded point (0.05, 0, 0) ⊕ 0.2 vs
// cylinder(0.6, 0.8), likewise; 3: sphere(0.2) vs the spheroid ellipsoid(1, 1, 1.5), likewise (no
// closed form: EPA in both modes); 4: sphere(0.2) on the spheroid's axis at (0, 0, 0.3), a ring of
// nearest points, EPA in both modes), mode (0: σ; 1: σ with the ball pre-step off — EPA, BASE's
// path; 2: signed distance; 3: signed distance, pre-step off). Counters: µs per query, the worst
// and the mean relative gap (upper − lower)/|value|.
void BM_CurvedBall(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0)), mode = static_cast<int>(state.range(1));
  const Shape3 ball = kind == 2 ? Shape3::rounded(Shape3::point(Vec3(0.05, 0, 0)), 0.2) : Shape3::sphere(0.2);
  const Shape3 body = kind <= 1 ? Shape3::cone(1, 1) : kind == 2 ? Shape3::cylinder(0.6, 0.8) : Shape3::ellipsoid(1, 1, 1.5);
  const Pair3 pair(body, ball);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-0.6, 0.6);
  std::normal_distribution<double> g;
  std::vector<Pose3> poses;
  if (kind == 0) poses.emplace_back(Vec3(0, 0, -0.3));
  if (kind == 4) poses.emplace_back(Vec3(0, 0, 0.3));
  while (poses.size() < 16 && kind > 0 && kind < 4) {
    const Pose3 q(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(U(rng), U(rng), U(rng)));
    if (pair.overlapping(Pose3(), q)) poses.push_back(q);
  }
  primitives::ball_enabled = mode == 0 || mode == 2;
  std::size_t i = 0;
  double sink = 0, gap = 0, worst = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % poses.size();
    double lo, hi, v;
    if (mode >= 2) {
      const Distance3 r = pair.signed_distance(Pose3(), poses[k]);
      lo = r.lower_bound, hi = r.upper_bound, v = r.distance;
    } else {
      const Depth3 r = pair.minimum(Pose3(), poses[k]);
      lo = r.lower_bound, hi = r.upper_bound, v = r.depth;
    }
    const double e = (hi - lo) / std::abs(v);
    sink += v, gap += e, worst = std::max(worst, e);
  }
  primitives::ball_enabled = true;
  benchmark::DoNotOptimize(sink);
  static const char* names[] = {"sphere on cone axis", "sphere vs cone", "rounded point vs cylinder", "sphere vs spheroid",
                                "sphere on spheroid axis"};
  state.SetLabel(std::string(names[kind]) + (mode >= 2 ? " sd" : " sigma") + (mode % 2 ? " EPA" : ""));
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["mean_rel_gap"] = gap / static_cast<double>(state.iterations());
  state.counters["worst_rel_gap"] = worst;
}

void BM_CurvedSignedDistance(benchmark::State& s) { run_curved(s, true); }
void BM_CurvedMinimum(benchmark::State& s) { run_curved(s, false); }

#if PENDEPTH_BENCH_BULLET
// Bullet 3.24 float64 on the same shapes and poses (P at the identity, Q at the pose), every
// margin 0 so that Bullet's shape is ours exactly:
//   cylinder:R,H   btCylinderShapeZ(R,R,H); setMargin(0) moves the margin back into the implicit
//                  dimensions (by default 0.04 of the half extents is a rounding margin)
//   cone:R,H       btConeShapeZ(R, 2H): Bullet's cone is centred at mid-height, apex at +height/2,
//                  base at −height/2 — ours (base z = −H, apex z = +H) exactly; setMargin(0)
//   box, hull      btBoxShape / btConvexHullShape, setMargin(0) (else padded by 0.04)
//   sphere:R       btSphereShape(R): a point with margin R; btGjkEpaSolver2::Distance works on the
//                  margin-free cores, so its distance is corrected by the margins (as
//                  btGjkPairDetector does); Penetration uses the margins itself
//   ellipsoid      Bullet has none. btMultiSphereShape (one unit sphere, local scaling A,B,C,
//                  margin 0) returns S·v̂ — a point of the ellipsoid, not its support point
//                  S²v/|Sv| — so it is not the ellipsoid (variant 2 below measures what that
//                  costs); variant 1 is an exact support-mapped btConvexInternalShape
//                  (BulletEllipsoid), which Bullet's GJK/EPA call through the virtual support.
// Signed distance: btGjkEpaSolver2::Distance, on penetration btGjkEpaSolver2::Penetration (what
// btGjkEpaSolver2::SignedDistance does); σ: btGjkEpaSolver2::Penetration (0 when separated).
// Before timing, every pose is checked against pendepth's certified bracket [lower, upper]:
// err = distance outside the bracket (0 inside); a failure is err > 1e-6·max(|value|, 1e-3) or a
// Bullet failure status. Counters err_max (absolute), failures and overlapping (of the 256 poses).
class BulletEllipsoid : public btConvexInternalShape {
 public:
  explicit BulletEllipsoid(const btVector3& axes) : axes_(axes) {
    m_shapeType = CUSTOM_CONVEX_SHAPE_TYPE;
    setMargin(0);
  }
  btVector3 localGetSupportingVertexWithoutMargin(const btVector3& v) const override {
    const btVector3 s = axes_ * v;  // support of S·ball in direction v: S²v / |Sv|
    const btScalar n = s.length();
    return n > 0 ? axes_ * s / n : btVector3(axes_.x(), 0, 0);
  }
  void batchedUnitVectorGetSupportingVertexWithoutMargin(const btVector3* v, btVector3* out, int n) const override {
    for (int k = 0; k < n; ++k) out[k] = localGetSupportingVertexWithoutMargin(v[k]);
  }
  void calculateLocalInertia(btScalar, btVector3& inertia) const override { inertia.setZero(); }
  const char* getName() const override { return "BulletEllipsoid"; }

 private:
  btVector3 axes_;
};

std::shared_ptr<btConvexShape> bullet_shape(int kind, bool p, const CurvedCase& c, bool multisphere) {
  std::shared_ptr<btConvexShape> s;
  auto ellipsoid = [&](double a, double b, double cc) -> std::shared_ptr<btConvexShape> {
    if (!multisphere) return std::make_shared<BulletEllipsoid>(btVector3(a, b, cc));
    const btVector3 centre(0, 0, 0);
    const btScalar radius = 1;
    auto m = std::make_shared<btMultiSphereShape>(&centre, &radius, 1);
    m->setLocalScaling(btVector3(a, b, cc));
    return m;
  };
  auto hull = [&] {
    auto h = std::make_shared<btConvexHullShape>();
    for (const Vec3& x : c.hull) h->addPoint(btVector3(x.x(), x.y(), x.z()), false);
    h->recalcLocalAabb();
    return h;
  };
  switch (kind) {
    case 0: s = p ? std::shared_ptr<btConvexShape>(std::make_shared<btCylinderShapeZ>(btVector3(0.5, 0.5, 0.7))) : hull(); break;
    case 1: s = p ? std::shared_ptr<btConvexShape>(std::make_shared<btConeShapeZ>(0.6, 1.4)) : hull(); break;
    case 2: s = p ? ellipsoid(0.5, 0.8, 0.6) : hull(); break;
    case 3: s = p ? std::shared_ptr<btConvexShape>(std::make_shared<btCylinderShapeZ>(btVector3(0.5, 0.5, 0.7))) : ellipsoid(0.5, 0.8, 0.6); break;
    case 4: s = p ? std::shared_ptr<btConvexShape>(std::make_shared<btConeShapeZ>(0.6, 1.4)) : std::make_shared<btBoxShape>(btVector3(0.5, 0.4, 0.3)); break;
    default: s = p ? ellipsoid(0.5, 0.8, 0.6) : std::make_shared<btSphereShape>(0.5); break;
  }
  if (s->getShapeType() != SPHERE_SHAPE_PROXYTYPE) s->setMargin(0);
  return s;
}

btTransform bullet_pose(const Pose3& q) {
  const Eigen::Matrix3d R = q.matrix();
  const Vec3& t = q.translation;
  return btTransform(btMatrix3x3(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)),
                     btVector3(t.x(), t.y(), t.z()));
}

// Bullet's answer (signed distance, or σ ≥ 0); NaN on a Bullet failure status.
double bullet_query(const btConvexShape* a, const btConvexShape* b, const btTransform& tb, bool distance) {
  btTransform ta;
  ta.setIdentity();
  btVector3 guess = tb.getOrigin();
  if (guess.length2() == 0) guess = btVector3(1, 0, 0);
  btGjkEpaSolver2::sResults res;
  if (distance && btGjkEpaSolver2::Distance(a, ta, b, tb, guess, res))
    return double(res.distance) - double(a->getMargin() + b->getMargin());
  if (distance && res.status != btGjkEpaSolver2::sResults::Penetrating) return std::numeric_limits<double>::quiet_NaN();
  // The normal comes back in A's frame (here the world frame): only the distance is used.
  if (btGjkEpaSolver2::Penetration(a, ta, b, tb, guess, res)) return distance ? double(res.distance) : double(-res.distance);
  if (!distance && res.status == btGjkEpaSolver2::sResults::Separated) return 0.0;
  return std::numeric_limits<double>::quiet_NaN();
}

// range(0): pair kind; range(1): 1 signed distance, 0 σ; range(2): 1 exact ellipsoid shape,
// 2 btMultiSphereShape ellipsoid.
void BM_CurvedBullet(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  const bool distance = state.range(1) != 0, multisphere = state.range(2) == 2;
  const CurvedCase c = curved_case(kind);
  const Pair3 pair(curved_pair_shape(kind, true, c), curved_pair_shape(kind, false, c));
  const auto a = bullet_shape(kind, true, c, multisphere), b = bullet_shape(kind, false, c, multisphere);
  std::vector<btTransform> tb;
  for (const Pose3& q : c.poses) tb.push_back(bullet_pose(q));
  double err_max = 0;
  int failures = 0, overlapping = 0;
  for (std::size_t k = 0; k < c.poses.size(); ++k) {
    double lo, hi;
    if (distance) {
      const Distance3 r = pair.signed_distance(Pose3(), c.poses[k]);
      lo = r.lower_bound, hi = r.upper_bound, overlapping += r.overlapping;
    } else {
      const Depth3 r = pair.minimum(Pose3(), c.poses[k]);
      lo = r.lower_bound, hi = r.upper_bound, overlapping += r.overlapping;
    }
    const double v = bullet_query(a.get(), b.get(), tb[k], distance);
    const double err = std::isnan(v) ? std::numeric_limits<double>::infinity() : std::max({lo - v, v - hi, 0.0});
    if (!std::isnan(v)) err_max = std::max(err_max, err);
    if (err > 1e-6 * std::max(std::abs(0.5 * (lo + hi)), 1e-3)) ++failures;
  }
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % tb.size();
    sink += bullet_query(a.get(), b.get(), tb[k], distance);
  }
  benchmark::DoNotOptimize(sink);
  state.SetLabel(std::string(kCurvedNames[kind]) + (distance ? " distance" : " sigma") +
                 (multisphere ? " (multisphere ellipsoid)" : ""));
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["err_max"] = err_max;
  state.counters["failures"] = failures;
  state.counters["overlapping"] = overlapping;
}
#endif

// Rounded shapes on two lower-dimensional cores (src/convex3/flat3.cpp flat_flat_distance): cores
// summing to dimension 2 (capsule–capsule, sphere–rounded triangle: the existing path) against
// 3 and 4 (rounded triangle–capsule, two rounded squares), signed distance and cast, random poses
// (about half overlapping).
Shape3 rounded_kind(int k) {
  const std::vector<Vec3> tri{Vec3(-0.5, -0.3, 0), Vec3(0.5, -0.3, 0), Vec3(0, 0.6, 0)};
  const std::vector<Vec3> sq{Vec3(-0.5, -0.5, 0), Vec3(0.5, -0.5, 0), Vec3(0.5, 0.5, 0), Vec3(-0.5, 0.5, 0)};
  switch (k) {
    case 0: return Shape3::capsule(0.2, 0.5);
    case 1: return Shape3::sphere(0.3);
    case 2: return Shape3::rounded(Shape3::flat(tri), 0.1);
    default: return Shape3::rounded(Shape3::flat(sq), 0.1);
  }
}
void BM_RoundedFlatCores(benchmark::State& state) {
  const int a = static_cast<int>(state.range(0)), b = static_cast<int>(state.range(1));
  const bool cast = state.range(2) != 0;
  const Pair3 pair(rounded_kind(a), rounded_kind(b));
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> U(-0.8, 0.8);
  std::normal_distribution<double> g;
  std::vector<Pose3> poses;
  std::vector<Vec3> dirs;
  for (int i = 0; i < 256; ++i) {
    poses.emplace_back(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(U(rng), U(rng), U(rng)));
    dirs.push_back(-poses.back().translation + 0.3 * Vec3(g(rng), g(rng), g(rng)));
  }
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % poses.size();
    sink += cast ? pair.cast(Pose3(), poses[k], dirs[k]).lower_bound : pair.signed_distance(Pose3(), poses[k]).distance;
  }
  benchmark::DoNotOptimize(sink);
  const char* names[] = {"capsule", "sphere", "rounded triangle", "rounded square"};
  state.SetLabel(std::string(names[a]) + " vs " + names[b] + (cast ? " cast" : " distance"));
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(BM_CurvedBall)->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1, 2, 3}});
BENCHMARK(BM_CurvedSignedDistance)->DenseRange(0, 5);
BENCHMARK(BM_CurvedMinimum)->DenseRange(0, 5);
BENCHMARK(BM_CurvedCoaxial)->ArgsProduct({{0, 1}, {0, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}, {0}})->Args({0, 0, 1})->Args({1, 0, 1})
    ->Args({0, 0, 2})->Args({1, 0, 2});
#if PENDEPTH_BENCH_BULLET
BENCHMARK(BM_CurvedBullet)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {1, 0}, {1}})
    ->Args({2, 1, 2})->Args({2, 0, 2})->Args({3, 1, 2})->Args({3, 0, 2})->Args({5, 1, 2})->Args({5, 0, 2});
#endif
BENCHMARK(BM_SignedDistance)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {16, 64}});
BENCHMARK(BM_Minimum)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {16, 64}});
BENCHMARK(BM_RoundedFlatCores)->Args({0, 0, 0})->Args({1, 2, 0})->Args({2, 0, 0})->Args({3, 3, 0})
    ->Args({0, 0, 1})->Args({1, 2, 1})->Args({2, 0, 1})->Args({3, 3, 1});
BENCHMARK_MAIN();
