// DHS Lemmas 5.2 / 5.3 (line_queries.cpp) against exact brute force over all triangles / edges:
// first_hit = [max entering, min leaving] parameter over the triangle planes (exact fraction
// comparisons, the winner evaluated in GMP); first_contact = minimum over the vertices of P on
// the swept plane and the crossings of P's edges with it (GMP). Random hulls (4 … 5,000
// vertices), the shared hulls, integer spheres / prisms / bipyramids / cube (massive
// coplanarity), lines through vertices, along edges, in face planes, tangent and missing lines,
// coordinates offset by 10⁶; visited-node counts grow like log n.
#include <gtest/gtest.h>

#include <pendepth/polytope.hpp>

#include "geometry/exact.hpp"
#include "shapes3.hpp"
#include "test_scale.hpp"

#include <cmath>
#include <cstring>
#include <gmpxx.h>
#include <optional>
#include <span>

namespace pendepth {
namespace {

using pendepth_test::scaled;

mpq_class q(double x) { return mpq_class(x); }

std::int64_t ulps(double a, double b) {
  if (a == b) return 0;
  if (std::signbit(a) != std::signbit(b)) return std::abs(a) + std::abs(b) < 1e-300 ? 0 : INT64_MAX;
  std::int64_t ia, ib;
  std::memcpy(&ia, &a, 8), std::memcpy(&ib, &b, 8);
  return std::abs(ia - ib);
}

// The double nearest to x (mpq get_d truncates).
double nearest(const mpq_class& x) {
  double t = x.get_d();
  for (double u : {std::nextafter(t, -INFINITY), std::nextafter(t, INFINITY)})
    if (std::isfinite(u) && abs(x - mpq_class(u)) < abs(x - mpq_class(t))) t = u;
  return t;
}

// A polytope surface: the polytope itself or one of its inner hierarchy levels.
struct Surface {
  std::span<const Vec3> v;
  std::vector<std::array<int, 3>> tris;
  std::vector<int> verts;
  Surface(const ConvexPolytope& P, std::size_t level) : v(P.vertices()), tris(P.level_triangles(level)) {
    std::vector<char> used(v.size(), 0);
    for (const auto& t : tris)
      for (int x : t) used[x] = 1;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (used[i]) verts.push_back(static_cast<int>(i));
  }
};

// ---- brute force Lemma 5.2 -----------------------------------------------------------------
struct BruteHit {
  bool hit = false;
  mpq_class lo, hi;
};

// Constraint of triangle (a, b, c): n·(o + t d − a) <= 0, n = (b − a) × (c − a): t·A <= B with
// A = n·d, B = n·(a − o). Fractions compared exactly by sign(B1 A2 − B2 A1) (filtered exact).
BruteHit brute_hit(const Surface& P, const Vec3& o, const Vec3& d) {
  struct Frac {
    int tri = -1;
  };
  auto AB = [&](int t, auto L) {
    const auto& T = P.tris[t];
    const Vec3 &a = P.v[T[0]], &b = P.v[T[1]], &c = P.v[T[2]];
    using X = decltype(L(0.0));
    X u[3], v[3], n[3];
    for (int i = 0; i < 3; ++i) u[i] = L(b[i]) - L(a[i]), v[i] = L(c[i]) - L(a[i]);
    n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
    X A = n[0] * L(d[0]) + n[1] * L(d[1]) + n[2] * L(d[2]);
    X B = n[0] * (L(a[0]) - L(o[0])) + n[1] * (L(a[1]) - L(o[1])) + n[2] * (L(a[2]) - L(o[2]));
    return std::pair<X, X>{A, B};
  };
  auto Asign = [&](int t) { return exact::exact_sign([&](auto L) { return AB(t, L).first; }); };
  auto Bsign = [&](int t) { return exact::exact_sign([&](auto L) { return AB(t, L).second; }); };
  // sign(B1/A1 − B2/A2)
  auto cmp = [&](int t1, int t2) {
    int s = exact::exact_sign([&](auto L) {
      auto [A1, B1] = AB(t1, L);
      auto [A2, B2] = AB(t2, L);
      return B1 * A2 - B2 * A1;
    });
    return s * Asign(t1) * Asign(t2);
  };
  int lo = -1, hi = -1;
  BruteHit r;
  for (int t = 0; t < static_cast<int>(P.tris.size()); ++t) {
    int a = Asign(t);
    if (a == 0) {
      if (Bsign(t) < 0) return r;
    } else if (a < 0) {
      if (lo < 0 || cmp(t, lo) > 0) lo = t;
    } else {
      if (hi < 0 || cmp(t, hi) < 0) hi = t;
    }
  }
  if (lo < 0 || hi < 0 || cmp(lo, hi) > 0) return r;
  auto value = [&](int t) {
    auto [A, B] = AB(t, exact::LiftQ{});
    return mpq_class(B.v / A.v);
  };
  r.hit = true, r.lo = value(lo), r.hi = value(hi);
  return r;
}

// ---- brute force Lemma 5.3 -----------------------------------------------------------------
struct BruteContact {
  bool contact = false;
  mpq_class shift;
};

std::array<mpq_class, 3> qv(const Vec3& v) { return {q(v[0]), q(v[1]), q(v[2])}; }
mpq_class dotq(const std::array<mpq_class, 3>& a, const std::array<mpq_class, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
std::array<mpq_class, 3> crossq(const std::array<mpq_class, 3>& a, const std::array<mpq_class, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
std::array<mpq_class, 3> subq(const std::array<mpq_class, 3>& a, const std::array<mpq_class, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

BruteContact brute_contact(const Surface& P, const Vec3& p, const Vec3& l, const Vec3& m) {
  auto L = qv(l), M = qv(m), Pq = qv(p);
  auto nu = crossq(L, M);
  mpq_class ll = dotq(L, L), lm = dotq(L, M);
  std::array<mpq_class, 3> w{M[0] * ll - L[0] * lm, M[1] * ll - L[1] * lm, M[2] * ll - L[2] * lm};
  mpq_class wm = dotq(w, M);
  // side of each vertex w.r.t. the swept plane (filtered exact)
  std::vector<int> side(P.v.size());
  for (int v : P.verts)
    side[v] = exact::exact_sign([&](auto Lf) {
      auto lx = Lf(l[0]), ly = Lf(l[1]), lz = Lf(l[2]), mx = Lf(m[0]), my = Lf(m[1]), mz = Lf(m[2]);
      return (ly * mz - lz * my) * (Lf(P.v[v][0]) - Lf(p[0])) + (lz * mx - lx * mz) * (Lf(P.v[v][1]) - Lf(p[1])) +
             (lx * my - ly * mx) * (Lf(P.v[v][2]) - Lf(p[2]));
    });
  BruteContact r;
  auto offer = [&](const std::array<mpq_class, 3>& x) {
    mpq_class s = dotq(w, subq(x, Pq)) / wm;
    if (!r.contact || s < r.shift) r.shift = s;
    r.contact = true;
  };
  for (int v : P.verts)
    if (side[v] == 0) offer(qv(P.v[v]));
  for (std::size_t t = 0; t < P.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      int a = P.tris[t][k], b = P.tris[t][(k + 1) % 3];
      if (a > b || side[a] * side[b] >= 0) continue;  // every edge once; crossing strictly
      auto A = qv(P.v[a]), B = qv(P.v[b]);
      auto AB = subq(B, A);
      mpq_class lam = dotq(nu, subq(Pq, A)) / dotq(nu, AB);
      offer({A[0] + lam * AB[0], A[1] + lam * AB[1], A[2] + lam * AB[2]});
    }
  return r;
}

// ---- query generators ----------------------------------------------------------------------
struct Line {
  Vec3 o, d;
  Vec3 m{0, 0, 0};  ///< move direction for Lemma 5.3 (zero: a generated one)
};

std::vector<Line> lines_for(const ConvexPolytope& P, std::mt19937_64& rng, int count) {
  std::vector<Line> out;
  std::normal_distribution<double> g;
  std::uniform_int_distribution<int> small(-3, 3);
  const auto tris = P.triangles();
  Vec3 lo = P[0], hi = P[0];
  for (const Vec3& v : P.vertices()) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const Vec3 mid = (lo + hi) / 2;
  const double R = (hi - lo).norm();
  auto rnd = [&] { return Vec3(g(rng), g(rng), g(rng)); };
  auto vtx = [&] { return P[rng() % P.size()]; };
  for (int i = 0; static_cast<int>(out.size()) < count; ++i) {
    const auto& t = tris[rng() % tris.size()];
    const Vec3 &a = P[t[0]], &b = P[t[1]], &c = P[t[2]];
    Line L;
    switch (i % 9) {
      case 0: L = {mid + 0.3 * R * rnd(), rnd()}; break;                      // generic, mostly hits
      case 1: L = {mid + 2 * R * rnd(), rnd()}; break;                        // mostly misses
      case 2: L = {vtx(), rnd()}; break;                                      // through a vertex
      case 3: L = {a, b - a}; break;                                          // along an edge (tangent)
      case 4:  // in a face plane, sweeping that plane: the section is the whole face
        L = {a, (b - a) + double(small(rng)) * (c - a), (rng() % 2) ? c - a : a - b};
        break;
      case 5: L = {vtx(), vtx() - mid}; break;                                // vertex to vertex-ish
      case 6: L = {vtx(), Vec3(small(rng), small(rng), small(rng))}; break;  // integer directions
      case 7: L = {(a + b) / 2, (a - b).cross(c - a).cross(b - a) + rnd() * 1e-3}; break;
      default: L = {mid + 0.5 * R * rnd(), Vec3(small(rng), small(rng), small(rng))}; break;
    }
    if (L.d.allFinite() && L.d != Vec3::Zero()) out.push_back(L);
  }
  return out;
}

struct Stats {
  int queries = 0, hits = 0, contacts = 0, touching = 0, vertex_contacts = 0;
  std::int64_t max_ulps = 0;
};

void check_shape(const ConvexPolytope& P, const std::string& name, int count, std::mt19937_64& rng, Stats& st,
                 std::size_t level = 0) {
  SCOPED_TRACE(name + " level " + std::to_string(level));
  auto lines = lines_for(P, rng, count);
  const Surface S(P, level);
  int failures = 0;
  for (std::size_t i = 0; i < lines.size() && failures < 5; ++i) {
    const Line& L = lines[i];
    // Lemma 5.2
    LineHit h = P.first_hit(L.o, L.d, level);
    BruteHit b = brute_hit(S, L.o, L.d);
    ++st.queries;
    if (h.hit != b.hit) {
      ADD_FAILURE() << "hit mismatch, line " << i << " o=" << L.o.transpose() << " d=" << L.d.transpose()
                    << " got " << h.hit;
      ++failures;
      continue;
    }
    if (h.hit) {
      ++st.hits;
      if (b.lo == b.hi) {  // a tangent line touching one point: zero-length interval
        ++st.touching;
        EXPECT_EQ(h.t_enter, h.t_exit);
      }
      std::int64_t u = std::max(ulps(h.t_enter, nearest(b.lo)), ulps(h.t_exit, nearest(b.hi)));
      st.max_ulps = std::max(st.max_ulps, u);
      if (u > 2) {
        ADD_FAILURE() << "t mismatch, line " << i << ": [" << h.t_enter << ", " << h.t_exit << "] vs ["
                      << b.lo.get_d() << ", " << b.hi.get_d() << "]";
        ++failures;
      }
      EXPECT_GE(h.face_enter, 0);
      EXPECT_LE(h.t_enter, h.t_exit);
    }
    // Lemma 5.3: the same line translating along a direction not parallel to it.
    Vec3 m = L.m != Vec3::Zero() ? L.m
             : (i % 3 == 0)     ? L.d.cross(Vec3(1, 2, 3))
                                : Vec3(rng() % 7 - 3.0, rng() % 5 - 2.0, 1.0);
    if (m.cross(L.d) == Vec3::Zero() || m == Vec3::Zero()) continue;
    if (std::abs(m.normalized().dot(L.d.normalized())) > 1 - 1e-12) continue;
    LineContact c = P.first_contact(L.o, L.d, m, level);
    BruteContact bc = brute_contact(S, L.o, L.d, m);
    if (c.contact != bc.contact) {
      ADD_FAILURE() << "contact mismatch, line " << i << " got " << c.contact;
      ++failures;
      continue;
    }
    if (!c.contact) continue;
    ++st.contacts;
    std::int64_t u = ulps(c.shift, nearest(bc.shift));
    st.max_ulps = std::max(st.max_ulps, u);
    if (u > 2) {
      ADD_FAILURE() << "shift mismatch, line " << i << ": " << c.shift << " vs " << bc.shift.get_d();
      ++failures;
    }
    if (c.feature == LineContact::Feature::Vertex) {
      ++st.vertex_contacts;
      // the vertex is on the swept plane and realises the minimum exactly
      auto Lq = qv(L.d), Mq = qv(m);
      mpq_class ll = dotq(Lq, Lq), lm = dotq(Lq, Mq);
      std::array<mpq_class, 3> w{Mq[0] * ll - Lq[0] * lm, Mq[1] * ll - Lq[1] * lm, Mq[2] * ll - Lq[2] * lm};
      auto x = qv(P[c.vertex]);
      EXPECT_EQ(dotq(crossq(Lq, Mq), subq(x, qv(L.o))), 0);
      EXPECT_EQ(dotq(w, subq(x, qv(L.o))) / dotq(w, Mq), bc.shift);
    } else {
      ASSERT_EQ(c.feature, LineContact::Feature::Edge);
      EXPECT_LT(c.edge[0], c.edge[1]);
    }
  }
}

TEST(LineQueries, StandardClouds) {
  std::mt19937_64 rng(5251);
  Stats st;
  for (const auto& c : test3::standard_clouds()) {
    auto P = ConvexPolytope::hull(c.pts, c.name);
    check_shape(P, c.name, scaled(P.size() > 1000 ? 60 : 150), rng, st);
  }
  std::cout << "[ stats    ] standard clouds: " << st.queries << " lines, " << st.hits << " hits (" << st.touching
            << " touching one point), " << st.contacts << " contacts (" << st.vertex_contacts << " at a vertex), max "
            << st.max_ulps << " ulps\n";
  EXPECT_GT(st.touching, 50);
}

TEST(LineQueries, RandomHulls) {
  std::mt19937_64 rng(77);
  Stats st;
  for (int n : {4, 5, 6, 10, 30, 100, 300, 1000, 5000}) {
    for (int rep = 0; rep < (n < 100 ? 6 : 1); ++rep) {
      auto pts = (rep % 2) ? test3::random_ball(rng, n * 8) : test3::random_sphere(rng, n);
      auto P = ConvexPolytope::hull(pts, "random" + std::to_string(n));
      check_shape(P, "random" + std::to_string(n), scaled(n >= 1000 ? 40 : 80), rng, st);
    }
  }
  std::cout << "[ stats    ] random hulls: " << st.queries << " lines, " << st.hits << " hits, " << st.contacts
            << " contacts, max " << st.max_ulps << " ulps\n";
}

TEST(LineQueries, OffsetByMillion) {
  std::mt19937_64 rng(31337);
  Stats st;
  const Vec3 off(1e6, -1e6, 1e6);
  for (auto c : test3::standard_clouds()) {
    if (c.pts.size() > 600) continue;
    for (auto& p : c.pts) p += off;
    auto P = ConvexPolytope::hull(c.pts, c.name + "+1e6");
    check_shape(P, c.name + "+1e6", scaled(60), rng, st);
  }
  std::cout << "[ stats    ] offset 1e6: " << st.queries << " lines, max " << st.max_ulps << " ulps\n";
}

TEST(LineQueries, SharedHulls) {
  std::mt19937_64 rng(4242);
  Stats st;
  for (const auto& f : test3::shared_hull_files()) {
    auto P = ConvexPolytope::hull(read_obj_vertices(f), f);
    check_shape(P, f, scaled(40), rng, st);
  }
  EXPECT_GT(st.queries, 0);
  std::cout << "[ stats    ] shared hulls: " << st.queries << " lines, max " << st.max_ulps << " ulps\n";
}

// DHS §5.1: every inner level P_i has its own outer hierarchy; the queries on P_i are checked
// against brute force over P_i's triangles.
TEST(LineQueries, InnerLevels) {
  std::mt19937_64 rng(606);
  Stats st;
  auto clouds = test3::standard_clouds();
  clouds.push_back({"rsphere5000", test3::random_sphere(rng, 5000)});
  for (const auto& c : clouds) {
    auto P = ConvexPolytope::hull(c.pts, c.name);
    const std::size_t k = P.hierarchy_levels();
    for (std::size_t level : {std::size_t(1), k / 2, k - 1})
      if (level > 0 && level < k) check_shape(P, c.name, scaled(25), rng, st, level);
  }
  EXPECT_THROW(ConvexPolytope::hull(test3::grid(2), "cube").first_hit(Vec3(0, 0, 0), Vec3(1, 0, 0), 99), InvalidInput);
  std::cout << "[ stats    ] inner levels: " << st.queries << " lines, " << st.hits << " hits, " << st.contacts
            << " contacts, max " << st.max_ulps << " ulps\n";
}

// Analytic: the unit cube [0,1]³.
TEST(LineQueries, CubeAnalytic) {
  auto P = ConvexPolytope::hull(test3::grid(2), "cube");
  LineHit h = P.first_hit(Vec3(0.5, 0.25, -3), Vec3(0, 0, 2));
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.t_enter, 1.5);
  EXPECT_EQ(h.t_exit, 2.0);
  EXPECT_EQ(h.enter, Vec3(0.5, 0.25, 0));
  // Along an edge: touching along the whole edge.
  h = P.first_hit(Vec3(0, 0, -1), Vec3(0, 0, 1));
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.t_enter, 1.0);
  EXPECT_EQ(h.t_exit, 2.0);
  // Touching a vertex only: zero-length interval.
  h = P.first_hit(Vec3(1, 1, 1), Vec3(1, -1, 0));
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.t_enter, 0.0);
  EXPECT_EQ(h.t_exit, 0.0);
  // Missing by a hair.
  EXPECT_FALSE(P.first_hit(Vec3(1 + 0x1p-52, 0.5, 0), Vec3(0, 0, 1)).hit);
  // A line parallel to z at (x, y) = (2, 0.5) moving along −x: first touches the face x = 1.
  LineContact c = P.first_contact(Vec3(2, 0.5, 0), Vec3(0, 0, 1), Vec3(-1, 0, 0));
  ASSERT_TRUE(c.contact);
  EXPECT_EQ(c.shift, 1.0);
  EXPECT_EQ(c.point.x(), 1.0);
  EXPECT_EQ(c.point.y(), 0.5);
  // A diagonal line moving along +y first touches the edge x = 1, y = 0 … or the vertex (1,0,0).
  c = P.first_contact(Vec3(1, -5, 0), Vec3(-1, 0, 1), Vec3(0, 1, 0));
  ASSERT_TRUE(c.contact);
  EXPECT_EQ(c.shift, 5.0);
  // Sweeping a plane that misses the cube.
  EXPECT_FALSE(P.first_contact(Vec3(0, 0, 1.5), Vec3(1, 0, 0), Vec3(0, 1, 0)).contact);
}

TEST(LineQueries, InvalidInput) {
  auto P = ConvexPolytope::hull(test3::grid(2), "cube");
  const double nan = std::nan("");
  EXPECT_THROW(P.first_hit(Vec3(0, 0, 0), Vec3(0, 0, 0)), InvalidInput);
  EXPECT_THROW(P.first_hit(Vec3(nan, 0, 0), Vec3(1, 0, 0)), InvalidInput);
  EXPECT_THROW(P.first_hit(Vec3(0, 0, 0), Vec3(INFINITY, 0, 0)), InvalidInput);
  EXPECT_THROW(P.first_contact(Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(2, 4, 6)), InvalidInput);
  EXPECT_THROW(P.first_contact(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)), InvalidInput);
  EXPECT_THROW(P.first_contact(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, nan, 0)), InvalidInput);
  try {
    P.first_contact(Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(-2, -4, -6));
    ADD_FAILURE();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("parallel"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cube"), std::string::npos);
  }
}

// Visited nodes grow like log n: 16× and 8× more vertices add a bounded number of levels' work.
TEST(LineQueries, LogarithmicVisits) {
  std::mt19937_64 rng(9);
  std::vector<double> avg;
  std::vector<int> sizes{256, 4096, scaled(32768) < 32768 ? 16384 : 32768};
  for (int n : sizes) {
    auto P = ConvexPolytope::hull(test3::random_sphere(rng, n), "s");
    std::normal_distribution<double> g;
    double sum = 0;
    const int Q = 300;
    for (int i = 0; i < Q; ++i) {
      Vec3 o(0.3 * g(rng), 0.3 * g(rng), 0.3 * g(rng)), d(g(rng), g(rng), g(rng));
      sum += double(P.first_hit(o, d).nodes_visited);
      sum += double(P.first_contact(o, d, d.cross(Vec3(g(rng), g(rng), g(rng)))).nodes_visited);
    }
    avg.push_back(sum / (2 * Q));
    std::cout << "[ stats    ] n = " << n << ": " << P.outer_hierarchy_levels() << " outer levels, "
              << avg.back() << " nodes per query\n";
  }
  // log n grows by 1.5× and 1.25× between the sizes; linear work would grow 16× and 8×.
  EXPECT_LT(avg[1], 2.5 * avg[0]);
  EXPECT_LT(avg[2], 2.5 * avg[1]);
}

}  // namespace
}  // namespace pendepth
