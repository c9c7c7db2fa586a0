// Complete separation of two simple polygons along d (issue 5 item 1, DHS §6): the linear-time
// envelope walk (src/nonconvex2/envelope.cpp) against an independent oracle, the previous
// divide-and-conquer construction (envelope_dc.hpp, O(n log n), no longer in the library):
// envelopes must agree piece for piece (same edges, same breakpoint levels, compared exactly) and
// PairDepth2::separation must equal the oracle's separation bit for bit (depth, normal,
// translation, witnesses, features). Inputs: random star polygons (real and integer), spirals,
// combs, mazes (thickened random spanning trees: deep pockets, axis-parallel, collinear runs),
// random simple polygons grown by notches (many reflex vertices), polygons with holes, the
// nesting pieces, 10^6 offsets, staircases, spikes, several rightmost vertices; directions random,
// axis-aligned, along and across edges, and along vertex differences (equal levels). Pinned seeds.
// A timing table (walk vs divide and conquer) for n = 10 … 10^4 is printed.
#include <pendepth/depth2_polygon_polygon.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>

#include "envelope_dc.hpp"
#include "geometry/exact.hpp"
#include "nonconvex2/envelope.hpp"
#include "polygon2/shapes.hpp"
#include "test_scale.hpp"

namespace {

namespace oracle = nonconvex2_test::oracle;
using pendepth::Depth2;
using pendepth::Polygon;
using pendepth::Vec2;
using pendepth::exact::exact_sign;

// ---- Inputs ----

struct Counts {
  std::size_t envelopes = 0, pieces = 0, separations = 0, positive = 0, shapes = 0;
};
Counts& counts() {
  static Counts c;
  return c;
}

// Exact sign of level(a) − level(b) across d for two vertices of S.
int cmp_level(const Polygon& S, std::uint32_t a, std::uint32_t b, const Vec2& d) {
  const Vec2 &p = S.vertices()[a], &q = S.vertices()[b];
  return exact_sign([&](auto L) { return L(d.x()) * (L(p.y()) - L(q.y())) - L(d.y()) * (L(p.x()) - L(q.x())); });
}

// The walk's envelope equals the divide-and-conquer oracle's: same edges, same breakpoint levels.
void check_envelope(const Polygon& S, const Vec2& d, const std::string& what) {
  const auto got = pendepth::nonconvex2::right_envelope(S, d);
  const auto want = oracle::Envelope(S, d).build();
  ++counts().envelopes;
  counts().pieces += want.size();
  ASSERT_EQ(got.size(), want.size()) << what << " d=" << d.transpose();
  for (std::size_t k = 0; k < got.size(); ++k) {
    ASSERT_EQ(got[k].edge, want[k].edge) << what << " piece " << k << " d=" << d.transpose();
    ASSERT_EQ(cmp_level(S, got[k].lo, want[k].lo, d), 0) << what << " piece " << k << " d=" << d.transpose();
    ASSERT_EQ(cmp_level(S, got[k].hi, want[k].hi, d), 0) << what << " piece " << k << " d=" << d.transpose();
  }
}

// Directions for shape S: random, axis-aligned, along and across edges, along vertex differences.
std::vector<Vec2> directions(const Polygon& S, std::mt19937_64& rng, int random_count) {
  std::vector<Vec2> ds{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-3, 7}};
  std::uniform_real_distribution<double> ua(0, 2 * polygon2_test::kPi);
  const auto V = S.vertices();
  const std::size_t n = S.ring(0).size();
  for (int k = 0; k < random_count; ++k) {
    const double a = ua(rng);
    ds.emplace_back(std::cos(a), std::sin(a));
    const std::size_t g = rng() % n, h = rng() % n;
    const Vec2 e = V[S.next(g)] - V[g];
    ds.push_back(k % 2 ? e : Vec2(-e));          // parallel to an edge: a level-constant edge
    ds.emplace_back(-e.y(), e.x());              // across an edge: a u-constant edge
    if (h != g) ds.push_back(V[h] - V[g]);       // two vertices on one level
  }
  return ds;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const Vec2& a, const Vec2& b) { return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()); }

void bbox(const Polygon& S, Vec2& lo, Vec2& hi) {
  lo = hi = S.vertices()[0];
  for (const Vec2& p : S.vertices()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
}

// PairDepth2::separation equals the oracle separation bit for bit (depth, normal, translation,
// witnesses, features) for `nt` placements × the directions of both shapes.
void check_pair(const Polygon& P, const Polygon& Q, std::mt19937_64& rng, int nt, int nd, const std::string& what) {
  const pendepth::PairDepth2 query(P, Q);
  Vec2 plo, phi, qlo, qhi;
  bbox(P, plo, phi);
  bbox(Q, qlo, qhi);
  std::uniform_real_distribution<double> ux(plo.x() - qhi.x(), phi.x() - qlo.x()), uy(plo.y() - qhi.y(), phi.y() - qlo.y());
  std::vector<Vec2> ds = directions(P, rng, nd);
  for (const Vec2& d : directions(Q, rng, nd)) ds.push_back(d);
  for (int k = 0; k < nt; ++k) {
    Vec2 t(ux(rng), uy(rng));
    if (k % 3 == 1) t = Vec2(std::round(t.x()), std::round(t.y()));
    if (k % 3 == 2) t = P.vertices()[rng() % P.size()] - Q.vertices()[rng() % Q.size()];
    const bool ov = query.overlapping(t);
    for (const Vec2& d : ds) {
      const Depth2 got = query.separation(t, d), want = oracle::oracle_separation(P, Q, t, d, ov);
      ++counts().separations;
      counts().positive += want.depth > 0;
      const std::string at = what + " t=(" + std::to_string(t.x()) + "," + std::to_string(t.y()) + ") d=(" +
                             std::to_string(d.x()) + "," + std::to_string(d.y()) + ")";
      ASSERT_TRUE(same_bits(got.depth, want.depth)) << at << " got " << got.depth << " want " << want.depth;
      ASSERT_EQ(got.kind, want.kind) << at;
      ASSERT_EQ(got.overlapping, want.overlapping) << at;
      ASSERT_TRUE(same_bits(got.normal, want.normal)) << at;
      ASSERT_TRUE(same_bits(got.translation, want.translation)) << at;
      ASSERT_TRUE(same_bits(got.witness_p, want.witness_p)) << at;
      ASSERT_TRUE(same_bits(got.witness_q, want.witness_q)) << at;
      ASSERT_EQ(got.feature_p.kind, want.feature_p.kind) << at;
      ASSERT_EQ(got.feature_p.index, want.feature_p.index) << at;
      ASSERT_EQ(got.feature_q.kind, want.feature_q.kind) << at;
      ASSERT_EQ(got.feature_q.index, want.feature_q.index) << at;
    }
  }
}

void check_shape(const Polygon& S, std::mt19937_64& rng, int nd, const std::string& what) {
  ++counts().shapes;
  for (const Vec2& d : directions(S, rng, nd)) {
    check_envelope(S, d, what);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

template <class Make>
Polygon retry(Make make) {
  for (;;) {
    try {
      return make();
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

Polygon star(std::mt19937_64& rng, int n, double rmin, double rmax, bool grid) {
  return retry([&] { return Polygon::simple(polygon2_test::star_ring(rng, n, Vec2(0, 0), rmin, rmax, grid), "star"); });
}

// A random simple polygon grown from a square by `notches` vertex insertions: a point near a random
// edge (either side) is inserted when the ring stays simple. Deep irregular pockets, many reflex
// vertices; on the integer grid, collinear runs and shared levels are frequent.
Polygon notched(std::mt19937_64& rng, int notches, bool grid) {
  const double W = 64;
  std::vector<Vec2> ring{{0, 0}, {W, 0}, {W, W}, {0, W}};
  std::normal_distribution<double> off(0, 1);
  for (int k = 0, tries = 0; k < notches && tries < 40 * notches; ++tries) {
    const std::size_t i = rng() % ring.size(), j = (i + 1) % ring.size();
    const Vec2 a = ring[i], b = ring[j], e = b - a;
    const double s = std::uniform_real_distribution<double>(0.2, 0.8)(rng);
    Vec2 c = a + s * e + Vec2(-e.y(), e.x()) * (0.6 * off(rng)) + e * (0.1 * off(rng));
    if (grid) c = Vec2(std::round(c.x()), std::round(c.y()));
    std::vector<Vec2> cand(ring);
    cand.insert(cand.begin() + static_cast<std::ptrdiff_t>(j), c);
    try {
      (void)Polygon::simple(cand, "notched");
      ring = std::move(cand);
      ++k;
    } catch (const pendepth::InvalidInput&) {
    }
  }
  return Polygon::simple(ring, "notched");
}

Polygon spiral(std::mt19937_64& rng, int steps) {
  std::uniform_real_distribution<double> u(0, 1);
  const double b = 1 + u(rng), w = (0.2 + 0.6 * u(rng)) * polygon2_test::kPi * b;
  std::vector<Vec2> r = polygon2_test::spiral_ring(w + 0.5 + 2 * u(rng), b, w, 1 + 3 * u(rng), steps);
  const double a = 2 * polygon2_test::kPi * u(rng);
  for (Vec2& p : r) p = Vec2(std::cos(a) * p.x() - std::sin(a) * p.y(), std::sin(a) * p.x() + std::cos(a) * p.y());
  return Polygon::simple(r, "spiral");
}

Polygon comb(std::mt19937_64& rng) {
  const int teeth = 2 + int(rng() % 8);
  return Polygon::simple(polygon2_test::comb_ring(teeth, 1 + double(rng() % 3), 1 + double(rng() % 3), 2 + double(rng() % 6), 1 + double(rng() % 2)), "comb");
}

// S translated by o (each coordinate rounded once); throws InvalidInput if that broke simplicity.
Polygon shifted(const Polygon& S, const Vec2& o) {
  std::vector<std::vector<Vec2>> rings;
  for (std::size_t k = 0; k < S.ring_count(); ++k) {
    rings.emplace_back();
    for (const Vec2& p : S.ring(k)) rings.back().push_back(p + o);
  }
  return Polygon(rings, "shifted");
}

// The boundary of a thickened random spanning tree of a k×k grid (randomized depth-first search:
// long corridors, spirals and deep pockets; all edges axis-parallel, collinear runs through straight
// nodes), optionally rotated by a random angle. Nodes 2 apart, corridors 1 wide.
Polygon maze(std::mt19937_64& rng, int k, bool rotate) {
  const Vec2 dir[4] = {{1, 0}, {0, -1}, {-1, 0}, {0, 1}};  // clockwise: E, S, W, N
  const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, -1, 0, 1};
  std::vector<unsigned char> adj(k * k, 0), seen(k * k, 0);
  std::vector<int> stack{0};
  seen[0] = 1;
  while (!stack.empty()) {
    const int v = stack.back(), x = v % k, y = v / k;
    int opts[4], m = 0;
    for (int e = 0; e < 4; ++e) {
      const int X = x + dx[e], Y = y + dy[e];
      if (X >= 0 && Y >= 0 && X < k && Y < k && !seen[Y * k + X]) opts[m++] = e;
    }
    if (m == 0) {
      stack.pop_back();
      continue;
    }
    const int e = opts[rng() % m], w = (y + dy[e]) * k + x + dx[e];
    adj[v] |= 1 << e;
    adj[w] |= 1 << ((e + 2) % 4);
    seen[w] = 1;
    stack.push_back(w);
  }
  // Walk around the tree: at each node, sweep clockwise from the arrival direction to the next
  // corridor, emitting one corner per quarter turn.
  std::vector<Vec2> ring;
  int v = 0, back = 0;
  while (!(adj[0] >> back & 1)) ++back;
  const int v_start = v, back_start = back;
  do {
    int out = (back + 1) % 4;
    while (!(adj[v] >> out & 1)) out = (out + 1) % 4;
    const Vec2 p(2.0 * (v % k), 2.0 * (v / k));
    int e = back;
    do {
      ring.push_back(p + 0.5 * (dir[e] + dir[(e + 1) % 4]));
      e = (e + 1) % 4;
    } while (e != out);
    v = (v / k + dy[out]) * k + v % k + dx[out];
    back = (out + 2) % 4;
  } while (!(v == v_start && back == back_start));
  if (rotate) {
    const double a = std::uniform_real_distribution<double>(0, 2 * polygon2_test::kPi)(rng);
    for (Vec2& p : ring) p = Vec2(std::cos(a) * p.x() - std::sin(a) * p.y(), std::sin(a) * p.x() + std::cos(a) * p.y());
  }
  return Polygon::simple(ring, "maze");
}

// One random shape of each family, by index.
Polygon family(std::mt19937_64& rng, int which, int size) {
  switch (which % 9) {
    case 0: return star(rng, size, 20, 100, false);
    case 1: return star(rng, std::min(size, 100), 20, 100, true);  // rounding a denser star rarely stays simple
    case 2: return retry([&] { return spiral(rng, size / 2 + 4); });
    case 3: return comb(rng);
    case 4: return notched(rng, std::min(size, 150), true);  // each notch revalidates the ring
    case 5: return notched(rng, std::min(size, 150), false);
    case 6: return polygon2_test::random_polygon(rng, std::min(size, 60), 1 + int(rng() % 3), rng() % 2);
    case 7: return maze(rng, 2 + int(std::sqrt(double(size))), false);
    default: return retry([&] { return maze(rng, 2 + int(std::sqrt(double(size))), true); });
  }
}

TEST(SeparationEnvelope, RandomShapesAllDirections) {
  std::mt19937_64 rng(20261121);
  for (int it = 0; it < pendepth_test::scaled(700); ++it) {
    const int size = 6 + int(rng() % (it % 10 == 0 ? 200 : 40));
    const Polygon S = family(rng, it, size);
    check_shape(S, rng, 6, "family " + std::to_string(it % 9) + " #" + std::to_string(it));
    if (HasFatalFailure()) return;
  }
}

TEST(SeparationEnvelope, OffsetByAMillion) {
  std::mt19937_64 rng(77);
  int done = 0;
  for (int it = 0; done < pendepth_test::scaled(150); ++it) {
    const Polygon S0 = family(rng, it, 6 + int(rng() % 30));
    const Vec2 o = it % 2 ? Vec2(1e6, -1e6) : Vec2(-1e6 + 0.375, 3e6);
    try {
      const Polygon S = shifted(S0, o);
      check_shape(S, rng, 6, "offset family " + std::to_string(it % 9));
      ++done;
    } catch (const pendepth::InvalidInput&) {  // rounding made the shifted ring non-simple
    }
    if (HasFatalFailure()) return;
  }
}

TEST(SeparationEnvelope, HolesAreIgnored) {
  std::mt19937_64 rng(31);
  for (int it = 0; it < pendepth_test::scaled(60); ++it) {
    const Polygon S = polygon2_test::random_polygon(rng, 8 + int(rng() % 30), 1 + int(rng() % 4), it % 2);
    const Polygon outer = Polygon::simple(std::vector<Vec2>(S.ring(0).begin(), S.ring(0).end()), "outer");
    for (const Vec2& d : directions(S, rng, 4)) {
      check_envelope(S, d, "holes");
      // The same pieces as for the outer ring alone (the outer ring keeps its global indices).
      const auto a = pendepth::nonconvex2::right_envelope(S, d), b = pendepth::nonconvex2::right_envelope(outer, d);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t k = 0; k < a.size(); ++k) ASSERT_EQ(a[k].edge, b[k].edge);
    }
    const Polygon grid(polygon2_test::holes_grid(2 + it % 4, 3, 1, Vec2(it, -it)), "holes grid");
    check_shape(grid, rng, 4, "holes grid");
  }
}

TEST(SeparationEnvelope, NestingPieces) {
  std::mt19937_64 rng(5);
  for (const char* f : {"albano.json", "shirts.json", "trousers.json"}) {
    for (const auto& ring : polygon2_test::nesting_pieces(f)) {
      const Polygon S = Polygon::simple(ring, f);
      check_shape(S, rng, pendepth_test::scaled(12), f);
      if (HasFatalFailure()) return;
    }
  }
}

TEST(SeparationEnvelope, Degenerate) {
  std::mt19937_64 rng(9);
  // A staircase (every edge parallel or perpendicular to the axes; many vertices share a level).
  std::vector<Vec2> stairs{{0, 0}};
  for (int k = 0; k < 12; ++k) {
    stairs.push_back({double(k + 1), double(k)});
    stairs.push_back({double(k + 1), double(k + 1)});
  }
  stairs.push_back({0, 12});
  check_shape(Polygon::simple(stairs, "stairs"), rng, 8, "stairs");
  // Collinear runs along the direction and across it, and a thin spike.
  check_shape(Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, "runs"), rng, 8, "runs");
  check_shape(Polygon::simple(std::vector<Vec2>{{0, 0}, {10, 5}, {0, 1}, {-5, 10}, {-1, 0}}, "spikes"), rng, 8, "spikes");
  // Two rightmost vertices (a vertical edge at the maximum, and separated tips).
  check_shape(Polygon::simple(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 2}, {4, 2}, {4, 3}, {0, 3}}, "E"), rng, 8, "E");
  check_shape(Polygon::simple(std::vector<Vec2>{{0, 0}, {4, 1}, {1, 1.5}, {4, 2}, {0, 3}}, "tips"), rng, 8, "tips");
  // Combs against combs in every axis direction (the fit pockets of test_pair_depth).
  for (int it = 0; it < 20; ++it) check_shape(comb(rng), rng, 4, "comb");
}

TEST(Separation, PairsAgreeBitForBit) {
  std::mt19937_64 rng(424242);
  for (int it = 0; it < pendepth_test::scaled(60); ++it) {
    const Polygon P = family(rng, it, 6 + int(rng() % 30));
    const Polygon Q = family(rng, it / 7 + 3, 5 + int(rng() % 15));
    check_pair(P, Q, rng, 6, 2, "pair " + std::to_string(it));
    if (HasFatalFailure()) return;
  }
  const auto pieces = polygon2_test::nesting_pieces("albano.json");
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = 0; j < pieces.size(); ++j) {
      if ((i + j) % (pendepth_test::kDivisor) != 0) continue;
      check_pair(Polygon::simple(pieces[i], "P"), Polygon::simple(pieces[j], "Q"), rng, 2, 1, "albano");
      if (HasFatalFailure()) return;
    }
}

// Time per call, in microseconds (repeats until `budget` seconds have passed; at least once).
template <class F>
double micros(F&& f, double budget = 0.01) {
  int reps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double el = 0;
  do {
    f();
    ++reps;
    el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  } while (el < budget);
  return 1e6 * el / reps;
}

// Time per envelope and per separation query, walk vs divide and conquer, n = 10 … 10^4 (10^3 in
// Debug; bench/bench_separation.cpp goes to 10^5), printed; the results must agree on these
// larger inputs too.
TEST(Separation, TimingLinear) {
  std::mt19937_64 rng(1);
  const Polygon Q = star(rng, 16, 5, 10, false);
  const int top = pendepth_test::kDivisor == 1 ? 10000 : 1000;
  std::cout << "[separation] n | shape | envelope walk | envelope D&C | separation walk | separation D&C (us)\n";
  for (int n = 10; n <= top; n *= 10) {
    for (int kind = 0; kind < 3; ++kind) {
      const Polygon P = kind == 0 ? star(rng, n, 50, 100, false)
                        : kind == 1 ? spiral(rng, n / 2)
                                    : maze(rng, std::max(2, int(std::sqrt(n / 4.0))), true);
      const pendepth::PairDepth2 query(P, Q);
      const Vec2 d(0.6, 0.8), t = P.vertices()[0] - Q.vertices()[0];
      const bool ov = query.overlapping(t);
      const Depth2 a = query.separation(t, d), b = oracle::oracle_separation(P, Q, t, d, ov);
      ASSERT_TRUE(same_bits(a.depth, b.depth));
      check_envelope(P, d, "timing");
      const double en = micros([&] { return pendepth::nonconvex2::right_envelope(P, d).size(); });
      const double eo = micros([&] { return oracle::Envelope(P, d).build().size(); });
      const double sn = micros([&] { return query.separation(t, d).depth; });
      const double so = micros([&] { return oracle::oracle_separation(P, Q, t, d, ov).depth; });
      std::cout << "[separation] " << P.size() << " | " << (kind == 0 ? "star" : kind == 1 ? "spiral" : "maze") << " | " << en
                << " | " << eo << " | " << sn << " | " << so << "\n";
    }
  }
}

// What this process compared (printed once at the end).
class SeparationSummary : public ::testing::Environment {
 public:
  void TearDown() override {
    const Counts& c = counts();
    if (c.envelopes == 0) return;
    std::cout << "[separation] shapes " << c.shapes << ", envelopes compared " << c.envelopes << " (" << c.pieces
              << " pieces), separations compared bit for bit " << c.separations << " (" << c.positive << " positive)\n";
  }
};
[[maybe_unused]] ::testing::Environment* const separation_summary_env = ::testing::AddGlobalTestEnvironment(new SeparationSummary);

}  // namespace
