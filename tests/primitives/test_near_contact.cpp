// Near-contact signed distances of curved primitives (src/primitives/support3.cpp, issue 16
// item 5): Q moved off an overlap by σ's translation × (1 + 1e-9), so the pair is apart by
// sd ≈ 1e-9·σ and its nearest points often lie on a ridge of M (a box edge, a cone's slant line
// or a cylinder's side line against a rim). GJK's triangles there are slivers and needles; with
// Johnson's normal equations it cycled and left brackets up to ~2e-11 wide (touching reported
// on some). The contract: certified apart, relative gap 1e-12 or the rounding floor.
// Oracles, independent of the engine: NESTED TESSELLATIONS (the polytope engines on inscribed and
// circumscribed polytopes bracket sd; test_curved.cpp's construction) and a HIGH-PRECISION GJK
// (100 digits, the closed-form supports evaluated in that precision on the engine's exact relative
// pose — P at the identity, so R and t are Q's own doubles): any y in the hull of support points is
// a point of M (|y| >= sd) and any direction w gives sd >= −h_M(w)/|w|; at 100 digits Johnson's
// solve has no conditioning trouble, and the bracket closes to < 1e-30.
#include <gtest/gtest.h>

#include <pendepth/pendepth.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "primitives/tessellation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace pendepth {
namespace {

using curved_test::random_pose;

using Big = boost::multiprecision::cpp_bin_float_100;
using BVec = std::array<Big, 3>;

BVec sub(const BVec& a, const BVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Big dot(const BVec& a, const BVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
BVec scaled(const BVec& a, const Big& s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// A shape with its closed-form support point in 100 digits (centred at the origin).
enum class Kind { Cylinder, Cone, Ellipsoid, Box, Sphere, Capsule };
struct Solid {
  Kind kind;
  double a, b, c;
  Shape3 shape() const {
    switch (kind) {
      case Kind::Cylinder: return Shape3::cylinder(a, b);
      case Kind::Cone: return Shape3::cone(a, b);
      case Kind::Ellipsoid: return Shape3::ellipsoid(a, b, c);
      case Kind::Box: return Shape3::box(a, b, c);
      case Kind::Sphere: return Shape3::sphere(a);
      case Kind::Capsule: return Shape3::capsule(a, b);
    }
    return Shape3::sphere(a);
  }
  BVec support(const BVec& v) const {
    using boost::multiprecision::sqrt;
    const Big r = sqrt(v[0] * v[0] + v[1] * v[1]);
    const Big A = a, B = b, C = c;
    auto rim = [&](const Big& z) { return r > 0 ? BVec{A * v[0] / r, A * v[1] / r, z} : BVec{A, 0, z}; };
    auto sgn = [](const Big& x, const Big& h) { return x >= 0 ? h : Big(-h); };
    switch (kind) {
      case Kind::Cylinder: return rim(sgn(v[2], B));
      case Kind::Cone: return B * v[2] >= A * r - B * v[2] ? BVec{0, 0, B} : rim(-B);
      case Kind::Ellipsoid: {
        const Big n = sqrt(A * A * v[0] * v[0] + B * B * v[1] * v[1] + C * C * v[2] * v[2]);
        return {A * A * v[0] / n, B * B * v[1] / n, C * C * v[2] / n};
      }
      case Kind::Box: return {sgn(v[0], A), sgn(v[1], B), sgn(v[2], C)};
      case Kind::Sphere: return scaled(v, A / sqrt(dot(v, v)));
      case Kind::Capsule: {
        BVec s = scaled(v, A / sqrt(dot(v, v)));
        s[2] += sgn(v[2], B);
        return s;
      }
    }
    return v;
  }
};

// The nearest point of conv(pts) to the origin (Johnson's sub-simplices by enumeration, solved in
// 100 digits); pts keeps the face that holds it. Returns false when a tetrahedron holds the origin.
bool nearest_big(std::vector<BVec>& pts, BVec& y) {
  const int n = static_cast<int>(pts.size());
  Big best = -1;
  int best_mask = 0;
  for (int mask = 1; mask < 1 << n; ++mask) {
    std::vector<int> idx;
    for (int i = 0; i < n; ++i)
      if (mask >> i & 1) idx.push_back(i);
    const int k = static_cast<int>(idx.size()) - 1;
    // Solve G μ = −Eᵀa (E the edges from a), Gaussian elimination with partial pivoting.
    std::vector<std::vector<Big>> G(k, std::vector<Big>(k + 1));
    const BVec& a = pts[idx[0]];
    for (int i = 0; i < k; ++i) {
      const BVec ei = sub(pts[idx[i + 1]], a);
      for (int j = 0; j < k; ++j) G[i][j] = dot(ei, sub(pts[idx[j + 1]], a));
      G[i][k] = -dot(ei, a);
    }
    bool ok = true;
    for (int col = 0; col < k && ok; ++col) {
      int piv = col;
      for (int i = col + 1; i < k; ++i)
        if (abs(G[i][col]) > abs(G[piv][col])) piv = i;
      if (G[piv][col] == 0) ok = false;
      else {
        std::swap(G[piv], G[col]);
        for (int i = 0; i < k; ++i)
          if (i != col) {
            const Big f = G[i][col] / G[col][col];
            for (int j = col; j <= k; ++j) G[i][j] -= f * G[col][j];
          }
      }
    }
    if (!ok) continue;
    Big w0 = 1;
    BVec z = a;
    bool positive = true;
    for (int i = 0; i < k; ++i) {
      const Big mu = G[i][k] / G[i][i];
      positive = positive && mu > 0;
      w0 -= mu;
      const BVec e = sub(pts[idx[i + 1]], a);
      for (int d = 0; d < 3; ++d) z[d] += mu * e[d];
    }
    if (!positive || !(w0 > 0)) continue;
    if (k == 3) return false;  // the origin inside the tetrahedron
    const Big d2 = dot(z, z);
    if (best < 0 || d2 < best) best = d2, best_mask = mask, y = z;
  }
  std::vector<BVec> kept;
  for (int i = 0; i < n; ++i)
    if (best_mask >> i & 1) kept.push_back(pts[i]);
  pts = kept;
  return true;
}

// The signed distance of P (at the identity) and Q at (R, t) when apart: [lower, upper] in 100
// digits by GJK on M = P − (R·Q + t). Overlapping (or the budget spent): lower = −∞.
std::array<Big, 2> oracle_distance(const Solid& P, const Solid& Q, const Eigen::Matrix3d& R, const Vec3& t) {
  auto support_m = [&](const BVec& u) {
    BVec rtu;  // −Rᵀu
    for (int i = 0; i < 3; ++i) rtu[i] = -(Big(R(0, i)) * u[0] + Big(R(1, i)) * u[1] + Big(R(2, i)) * u[2]);
    const BVec sq = Q.support(rtu), sp = P.support(u);
    BVec x;
    for (int i = 0; i < 3; ++i) x[i] = sp[i] - (Big(R(i, 0)) * sq[0] + Big(R(i, 1)) * sq[1] + Big(R(i, 2)) * sq[2] + t[i]);
    return x;
  };
  std::vector<BVec> pts{support_m(BVec{Big(-t[0]), Big(-t[1]), Big(-t[2])})};
  Big lower = -1, upper = boost::multiprecision::sqrt(dot(pts[0], pts[0]));
  for (int it = 0; it < 400 && upper - lower > Big("1e-40"); ++it) {
    BVec y;
    if (!nearest_big(pts, y)) return {Big(-1e300), Big(0)};
    const Big ny = boost::multiprecision::sqrt(dot(y, y));
    if (ny < upper) upper = ny;
    const BVec w = scaled(y, Big(-1) / ny);  // unit, towards the origin
    const BVec v = support_m(w);
    const Big lo = -dot(v, w);
    if (lo > lower) lower = lo;
    bool fresh = true;
    for (const BVec& p : pts) fresh = fresh && p != v;
    if (!fresh || pts.size() == 4) break;
    pts.push_back(v);
  }
  return {lower, upper};
}

// The rounding floor of the contract (docs/robustness.md "Curved primitives"): 96u × the pair's
// size (the circumradii and the offset). The a-priori error δ of one support is 16u·ρ_P + 24u·ρ_Q
// + 4u·|t| and each end of the bracket carries one, plus the rounding of y and ⟨x, w⟩ (measured
// here: each end 16–36u·size from the 100-digit value, the gap at most 65u·size).
double rho(const Solid& s) {
  switch (s.kind) {
    case Kind::Ellipsoid: return std::max({s.a, s.b, s.c});
    case Kind::Box: return std::sqrt(s.a * s.a + s.b * s.b + s.c * s.c);
    case Kind::Sphere: return s.a;
    case Kind::Capsule: return s.a + s.b;
    default: return std::hypot(s.a, s.b);
  }
}
double rounding_floor(const Solid& P, const Solid& Q, const Vec3& t) { return 96 * 0x1p-53 * (rho(P) + rho(Q) + t.norm()); }

const Solid kCyl{Kind::Cylinder, 0.1, 0.2, 0}, kCone{Kind::Cone, 0.12, 0.15, 0}, kEll{Kind::Ellipsoid, 0.1, 0.2, 0.15};
const Solid kOthers[] = {{Kind::Box, 0.1, 0.08, 0.12}, {Kind::Sphere, 0.1, 0, 0}, {Kind::Capsule, 0.05, 0.1, 0}, kCyl, kCone, kEll};

TEST(NearContact, RidgePairsAgainstHighPrecisionOracle) {
  // P at the identity, Q at a random pose; overlapping poses give the near-contact pose.
  std::mt19937_64 rng(20261128);
  int checked = 0, worst_case = -1;
  double worst = 0;
  Big worst_oracle_gap = 0;
  for (const Solid& P : {kCyl, kCone, kEll})
    for (const Solid& Q : kOthers) {
      const Pair3 pair(P.shape(), Q.shape());
      for (int it = 0; it < 40; ++it) {
        const Pose3 pq = random_pose(rng, 0.25);
        const Depth3 m = pair.minimum(Pose3(), pq);
        if (!m.overlapping) continue;
        Pose3 moved = pq;
        moved.translation += m.translation * (1 + 1e-9);
        const Distance3 s = pair.signed_distance(Pose3(), moved);
        const auto [lo, hi] = oracle_distance(P, Q, moved.matrix(), moved.translation);
        ASSERT_GT(lo, 0) << checked;  // the oracle certifies apart
        EXPECT_LT(hi - lo, Big("1e-30")) << checked;
        worst_oracle_gap = std::max(worst_oracle_gap, Big(hi - lo));
        // The brackets meet (the true value lies in both), the engine's is certified apart and
        // within the contract.
        EXPECT_LE(Big(s.lower_bound), hi) << checked;
        EXPECT_GE(Big(s.upper_bound), lo) << checked;
        EXPECT_GT(s.lower_bound, 0) << checked << " " << P.shape().name() << " vs " << Q.shape().name();
        const double gap = s.upper_bound - s.lower_bound;
        const double floor = rounding_floor(P, Q, moved.translation);
        EXPECT_LE(gap, 1e-12 * s.distance + floor) << checked << " " << P.shape().name() << " vs " << Q.shape().name();
        if (gap / floor > worst) worst = gap / floor, worst_case = checked;
        ++checked;
      }
    }
  std::printf("near contact vs 100-digit GJK: %d poses, worst engine gap %.3g × the floor (pose %d), worst oracle gap %.3g\n", checked,
              worst, worst_case, static_cast<double>(worst_oracle_gap));
  EXPECT_GT(checked, 250);
}

// The nested tessellations' description of a curved Solid.
curved_test::Curved as_curved(const Solid& s) {
  using curved_test::K;
  return {s.kind == Kind::Cylinder ? K::Cyl : s.kind == Kind::Cone ? K::Cone : K::Ell, s.a, s.b, s.c};
}

TEST(NearContact, RandomPosesOfEveryPairAreCertifiedApartWithinTheFloor) {
  // Both shapes at random poses (the engine's relative pose rounded), every pair of the 100-digit
  // test plus a hull and a rounded hull; σ's move lengthened by 1e-9 and σ_d's likewise. The
  // nested tessellations bracket sd (sd(O) <= sd <= sd(I)); the bracket is certified apart and
  // within the contract. (Before GJK's triangle solve: 5 of 1952 such poses reported touching,
  // brackets up to 2.6e-11 wide.)
  const std::vector<Vec3> pts{Vec3(0.1, 0, 0), Vec3(-0.05, 0.09, 0.02), Vec3(-0.05, -0.08, 0.03), Vec3(0, 0.01, 0.15),
                              Vec3(0.01, 0, -0.12)};
  const Shape3 hull = Shape3::hull(pts);
  std::mt19937_64 rng(1952);
  int checked = 0, checked_d = 0;
  double worst = 0;
  for (const Solid& P : {kCyl, kCone, kEll}) {
    const Shape3 in = curved_test::tessellation(as_curved(P), 32, false), out = curved_test::tessellation(as_curved(P), 32, true);
    curved_test::verify_nesting(as_curved(P), in, out);
    std::vector<std::pair<Shape3, double>> others;  // the shape and its size (circumradius)
    for (const Solid& Q : kOthers) others.push_back({Q.shape(), rho(Q)});
    others.push_back({hull, 0.151});
    others.push_back({Shape3::rounded(hull, 0.02), 0.171});
    for (const auto& [Q, rq] : others) {
      const Pair3 pair(P.shape(), Q), inner(in, Q), outer(out, Q);
      for (int it = 0; it < 24; ++it) {
        const Pose3 pp = random_pose(rng, 0.05), pq = random_pose(rng, 0.25);
        const Depth3 m = pair.minimum(pp, pq);
        if (!m.overlapping) continue;
        std::normal_distribution<double> g;
        const Depth3 a = pair.along(pp, pq, Vec3(g(rng), g(rng), g(rng)));
        for (int k = 0; k < 2; ++k) {
          Pose3 moved = pq;
          moved.translation += (k == 0 ? m.translation : a.translation) * (1 + 1e-9);
          const Distance3 s = pair.signed_distance(pp, moved);
          const Distance3 si = inner.signed_distance(pp, moved), so = outer.signed_distance(pp, moved);
          EXPECT_LE(s.lower_bound, si.distance + 1e-15) << checked;
          EXPECT_GE(s.upper_bound, so.distance - 1e-15) << checked;
          EXPECT_GT(s.lower_bound, 0) << checked << " " << P.shape().name() << " vs " << Q.name();
          const double floor = 96 * 0x1p-53 * (rho(P) + rq + (moved.translation - pp.translation).norm());
          EXPECT_LE(s.upper_bound - s.lower_bound, 1e-12 * s.distance + floor) << checked << " " << P.shape().name() << " vs " << Q.name();
          worst = std::max(worst, (s.upper_bound - s.lower_bound) / floor);
          ++(k == 0 ? checked : checked_d);
        }
      }
    }
  }
  std::printf("near contact, random poses: %d after σ's move, %d after σ_d's; worst gap %.3g × the floor\n", checked, checked_d, worst);
  EXPECT_GT(checked, 150);
}

}  // namespace
}  // namespace pendepth
