// The exact mesh σ's equality of planes and its classes of equal planes
// (src/mesh3/plane_classes.hpp: detail::same_plane, detail::plane_classes, the skip of repeated
// lines in mesh_sigma_exact.cpp) on constructed planes, against a brute-force oracle in GMP
// rationals (mpq_class over the same input doubles: the same plane iff n_a × n_b = 0 and
// c_a (n_a·n_b) = c_b |n_a|²; the class of p = the first plane in the order equal to p).
// The inputs are the classes' hard cases: equal planes written differently (scaled normals,
// opposite orientations, different defining points), distinct planes at exactly equal distance
// from 0 (the faces of a cube and of an octahedron, integer normals of equal length), planes one
// ulp apart in the offset or in a normal component, planes within 1 % of each other, magnitudes
// 2^±300, and random lattice planes (many coincidences). On the meshes the tests pose, lines of
// distinct planes at equal distance never carry the answer, so a too-coarse class escaped them.
// Planted by hand (not committed), each made these tests fail: planes merged by equal distance
// alone (`ps.dist(reps[k]) == ps.dist(p)` for the same_plane test), and merged within 1 % of
// their distance (the same with |Δdist| <= 1 % of dist), and same_plane's exact offset test
// dropped (parallel planes equal).
#include "mesh3/plane_classes.hpp"
#include "rational.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

using mesh3_test::rational;
using pendepth::mesh3::PlaneNumber;
using I = CGAL::Interval_nt<true>;

template <class T>
struct V {
  T x, y, z;
};
using D3 = std::array<double, 3>;

template <class T>
V<T> lift(const D3& a) {
  return {T(a[0]), T(a[1]), T(a[2])};
}
template <class T>
V<T> sub(const V<T>& a, const V<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
V<T> cross(const V<T>& a, const V<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
T dot(const V<T>& a, const V<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// A plane given either directly (n·x <= c, the doubles) or through three points
// (n = (b − a) × (c − a), c = n·a): the same polynomials in each number type.
struct Def {
  bool by_points = false;
  D3 n{}, a{}, b{}, c{};
  double off = 0;
};
template <class T>
std::pair<V<T>, T> poly(const Def& d) {
  if (!d.by_points) return {lift<T>(d.n), T(d.off)};
  const V<T> a = lift<T>(d.a);
  const V<T> n = cross(sub(lift<T>(d.b), a), sub(lift<T>(d.c), a));
  return {n, dot(n, a)};
}

struct Exact {
  V<PlaneNumber> n;
  PlaneNumber c;
};
struct Planes {
  std::vector<Def> defs;
  std::vector<V<I>> nis;
  std::vector<I> cis;
  std::vector<Exact> ex;
  std::vector<double> ds;
  void add(const Def& d) {
    defs.push_back(d);
    auto [ni, ci] = poly<I>(d);
    auto [n, c] = poly<PlaneNumber>(d);
    nis.push_back(ni), cis.push_back(ci), ex.push_back({n, c});
    // |c|/|n| to a few ulps, scaled by a power of two first (|n|² may leave the doubles at 2^±300).
    int e = 0;
    std::frexp(std::max({std::abs(to_double(n.x)), std::abs(to_double(n.y)), std::abs(to_double(n.z))}), &e);
    auto sc = [&](const PlaneNumber& v) { return std::ldexp(to_double(v), -e); };
    const double nx = sc(n.x), ny = sc(n.y), nz = sc(n.z);
    ds.push_back(std::abs(sc(c)) / std::sqrt(nx * nx + ny * ny + nz * nz));
  }
  double dist(std::size_t p) const { return ds[p]; }
  const V<I>& ni(std::size_t p) const { return nis[p]; }
  const I& ci(std::size_t p) const { return cis[p]; }
  const Exact& exact(std::size_t p) const { return ex[p]; }
};

// The oracle: the same plane (either side, or the same half-space), in mpq_class.
bool oracle_same(const Def& a, const Def& b, bool same_side) {
  auto [na, ca] = poly<mpq_class>(a);
  auto [nb, cb] = poly<mpq_class>(b);
  const V<mpq_class> x = cross(na, nb);
  if (x.x != 0 || x.y != 0 || x.z != 0) return false;
  const mpq_class ab = dot(na, nb);
  if (same_side && !(ab > 0)) return false;
  return ca * ab == cb * dot(na, na);
}

// Every pair (both tiers, both sides) and the classes against the oracle. The inputs' hardness,
// counted over pairs: equal planes (a class of several) and distinct planes whose distances the
// margin cannot tell apart (only the exact test separates them).
struct Hardness {
  int equal = 0, tied = 0;
};
Hardness check(const Planes& ps) {
  Hardness h;
  const std::size_t n = ps.defs.size();
  for (std::size_t p = 0; p < n; ++p) {
    auto [np, cp] = poly<mpq_class>(ps.defs[p]);
    EXPECT_FALSE(np.x == 0 && np.y == 0 && np.z == 0) << "plane " << p << ": zero normal";
  }
  std::vector<std::vector<char>> same(n, std::vector<char>(n));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      same[a][b] = oracle_same(ps.defs[a], ps.defs[b], false);
      if (a < b) (same[a][b] ? h.equal : h.tied) += !pendepth::mesh3::detail::distances_differ(ps.dist(a), ps.dist(b));
      const bool side = oracle_same(ps.defs[a], ps.defs[b], true);
      for (bool filtered : {false, true}) {
        EXPECT_EQ(pendepth::mesh3::detail::same_plane(ps, a, b, false, filtered), bool(same[a][b]))
            << a << " " << b << " filtered " << filtered;
        EXPECT_EQ(pendepth::mesh3::detail::same_plane(ps, a, b, true, filtered), side)
            << a << " " << b << " same side, filtered " << filtered;
      }
    }
  std::vector<std::size_t> order(n);
  for (std::size_t p = 0; p < n; ++p) order[p] = p;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ps.dist(a) < ps.dist(b); });
  std::vector<std::size_t> cls;
  pendepth::mesh3::detail::plane_classes(ps, order, cls);
  EXPECT_EQ(cls.size(), n);
  if (cls.size() != n) return h;
  for (std::size_t p : order) {
    std::size_t want = p;
    for (std::size_t q : order)
      if (same[q][p]) {
        want = q;
        break;
      }
    EXPECT_EQ(cls[p], want) << "plane " << p << " (dist " << ps.dist(p) << ")";
  }
  return h;
}
void check_hard(const Planes& ps) {
  const Hardness h = check(ps);
  EXPECT_GT(h.equal, 0);
  EXPECT_GT(h.tied, 0);
}

Def direct(D3 n, double off) { return Def{false, n, {}, {}, {}, off}; }
Def scaled(const Def& d, double s) { return direct({d.n[0] * s, d.n[1] * s, d.n[2] * s}, d.off * s); }

// Three points on the plane n·x = off (n integer, off a multiple of the chosen axis's
// coefficient): lattice points stepped along two directions in the plane.
Def through_points(D3 n, double off, double s, int shift) {
  int ax = 0;  // an axis with n[ax] != 0
  while (n[ax] == 0) ++ax;
  const int u = (ax + 1) % 3, w = (ax + 2) % 3;
  auto point = [&](double pu, double pw) {
    D3 p{};
    p[u] = pu, p[w] = pw;
    p[ax] = (off - n[u] * pu - n[w] * pw) / n[ax];  // exact for the inputs used (multiples)
    for (double& x : p) x *= s;
    return p;
  };
  const double k = n[ax];
  return Def{true, {}, point(shift * k, 0), point((shift + 1) * k, 2 * k), point(shift * k, 3 * k), 0};
}

// The planes of a cube [-r, r]³ and of the octahedron |x|+|y|+|z| <= r: distinct planes at
// exactly equal distance, each also written scaled, opposite and through points.
TEST(PlaneClasses, CubeAndOctahedronFacesAtEqualDistance) {
  for (double scale : {1.0, 0x1p-300, 0x1p300}) {
    Planes ps;
    for (int s : {1, -1})
      for (int a = 0; a < 3; ++a) {
        D3 n{};
        n[a] = s;
        const Def d = direct(n, 2 * scale);
        ps.add(d), ps.add(scaled(d, 3)), ps.add(scaled(d, -0.5));
      }
    for (int m = 0; m < 8; ++m) {
      const D3 n{m & 1 ? -1.0 : 1.0, m & 2 ? -1.0 : 1.0, m & 4 ? -1.0 : 1.0};
      const Def d = direct(n, 4 * scale);
      ps.add(d), ps.add(scaled(d, 0x1p-7)), ps.add(through_points(n, 4, scale, m));
    }
    check_hard(ps);
  }
}

// Integer normals of equal length (|(1,2,2)| = |(0,0,3)| = 3): distinct planes at distance 1,
// and the same planes written with other points.
TEST(PlaneClasses, EqualLengthNormals) {
  Planes ps;
  const std::vector<D3> ns{{1, 2, 2}, {2, 1, 2}, {2, 2, 1}, {-1, 2, 2}, {2, -2, 1}, {0, 0, 3}, {3, 0, 0}, {0, -3, 0}};
  for (const D3& n : ns) {
    ps.add(direct(n, 3)), ps.add(direct(n, -3)), ps.add(through_points(n, 6, 0.5, 1));
    ps.add(through_points(n, -6, 0.5, -2));
  }
  check_hard(ps);
}

// Neighbours: one ulp in the offset or in a normal component, within 1 % (same distance to 1 %,
// different planes), and the plane through 0 (distance 0) in several directions.
TEST(PlaneClasses, NearlyEqualPlanes) {
  for (double scale : {1.0, 0x1p-300, 0x1p300}) {
    Planes ps;
    const D3 n{0.75 * scale, -1.25 * scale, 0.5 * scale};
    const double off = 1.0;
    ps.add(direct(n, off));
    ps.add(direct(n, std::nextafter(off, 2.0)));
    ps.add(direct(n, std::nextafter(off, 0.0)));
    for (int a = 0; a < 3; ++a) {
      D3 m = n;
      m[a] = std::nextafter(m[a], INFINITY);
      ps.add(direct(m, off));
      m[a] = n[a] * 1.005;
      ps.add(direct(m, off * 1.005));  // not a multiple: only this component scaled
    }
    ps.add(direct({n[0] * 1.01, n[1] * 1.01, n[2] * 1.01}, off * 1.01 * 1.01));  // parallel, 1 % away
    ps.add(direct({100, 0, 0}, 100)), ps.add(direct({100, 1, 0}, 100)), ps.add(direct({100, 0, 1}, 100));
    ps.add(direct({1, 0, 0}, 0)), ps.add(direct({0, 1, 0}, 0)), ps.add(direct({-2, 0, 0}, 0));
    ps.add(direct({0, 0, 1}, 0x1p-1074)), ps.add(direct({0, 0, 1}, -0x1p-1074));
    check_hard(ps);
  }
}

// Random lattice planes: small integer normals and offsets, each written several ways
// (scaled by ±2^k or ±3, through points), shuffled; many equal planes and many equal distances.
TEST(PlaneClasses, RandomLatticePlanes) {
  std::mt19937_64 rng(20261127);
  std::uniform_int_distribution<int> coef(-2, 2), pick(0, 5);
  for (int round = 0; round < 40; ++round) {
    std::vector<Def> defs;
    for (int k = 0; k < 12; ++k) {
      D3 n{};
      while (n[0] == 0 && n[1] == 0 && n[2] == 0) n = {double(coef(rng)), double(coef(rng)), double(coef(rng))};
      const double off = coef(rng);
      const Def d = direct(n, off);
      defs.push_back(d);
      const double factors[] = {2.0, -4.0, 3.0, -1.0, 0x1p-20, 0x1p40};
      defs.push_back(scaled(d, factors[pick(rng)]));
      int ax = 0;
      while (n[ax] == 0) ++ax;
      defs.push_back(through_points(n, off * n[ax], 1.0, coef(rng)));  // off·n[ax]: points exact
    }
    std::shuffle(defs.begin(), defs.end(), rng);
    Planes ps;
    for (const Def& d : defs) ps.add(d);
    check_hard(ps);
    if (HasFailure()) return;
  }
}

}  // namespace
