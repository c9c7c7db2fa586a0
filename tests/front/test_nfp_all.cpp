// Front door, whole instances (pendepth.hpp no_fit_polygons, nesting.hpp): every entry equals
// no_fit_polygon of the rotated pair bit for bit, at 1 and 2 threads and with a progress callback;
// the order i, a, j, b; quarter turns give the exactly rotated no-fit polygon; errors.
#include <pendepth/nesting.hpp>
#include <pendepth/nfp2.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "front/common.hpp"

namespace {

using namespace pendepth;
using front_test::error_of;
using front_test::same_bits;

bool same_vec(const Vec2& a, const Vec2& b) { return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()); }

// Bit-for-bit equality of two no-fit polygons (rings, slits, points, in order).
::testing::AssertionResult same_parts(const NoFitPolygonParts& a, const NoFitPolygonParts& b) {
  auto fail = [](const char* what) { return ::testing::AssertionFailure() << "differ in " << what; };
  if (a.polygons.size() != b.polygons.size()) return fail("polygon count");
  for (std::size_t k = 0; k < a.polygons.size(); ++k) {
    if (a.polygons[k].size() != b.polygons[k].size()) return fail("ring count");
    for (std::size_t r = 0; r < a.polygons[k].size(); ++r) {
      if (a.polygons[k][r].size() != b.polygons[k][r].size()) return fail("ring size");
      for (std::size_t i = 0; i < a.polygons[k][r].size(); ++i)
        if (!same_vec(a.polygons[k][r][i], b.polygons[k][r][i])) return fail("a vertex");
    }
  }
  if (a.slits.size() != b.slits.size() || a.points.size() != b.points.size()) return fail("slit or point count");
  for (std::size_t k = 0; k < a.slits.size(); ++k)
    if (!same_vec(a.slits[k][0], b.slits[k][0]) || !same_vec(a.slits[k][1], b.slits[k][1])) return fail("a slit");
  for (std::size_t k = 0; k < a.points.size(); ++k)
    if (!same_vec(a.points[k], b.points[k])) return fail("a point");
  return ::testing::AssertionSuccess();
}

std::vector<Shape2> shapes_of(const NestingInstance& inst) {
  std::vector<Shape2> s;
  for (const auto& it : inst.items) s.push_back(it.shape);
  return s;
}

std::string instance(const std::string& name) { return std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + name + ".json"; }

// Every entry against the single call on the rotated pair, in the documented order.
void expect_entries(const std::vector<Shape2>& shapes, const std::vector<std::vector<double>>& rotations,
                    const std::vector<NoFitPolygonEntry>& got) {
  auto angles = [&](std::size_t i) { return rotations.size() == 1 ? rotations[0] : rotations[i]; };
  std::size_t k = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (const double a : angles(i))
      for (std::size_t j = 0; j < shapes.size(); ++j)
        for (const double b : angles(j)) {
          ASSERT_LT(k, got.size());
          const NoFitPolygonEntry& e = got[k++];
          ASSERT_EQ(e.i, i);
          ASSERT_EQ(e.j, j);
          ASSERT_TRUE(same_bits(e.rotation_i, a) && same_bits(e.rotation_j, b));
          EXPECT_TRUE(same_parts(e.nfp, no_fit_polygon(shapes[i].rotated(a), shapes[j].rotated(b))))
              << "pair " << i << "@" << a << ", " << j << "@" << b;
        }
  EXPECT_EQ(k, got.size());
}

TEST(NoFitPolygons, EveryPairEqualsTheSingleCallAtAnyThreadCount) {
  const NestingInstance inst = read_nesting_instance(instance("shirts"));
  const std::vector<Shape2> shapes = shapes_of(inst);
  ASSERT_EQ(shapes.size(), 8u);
  // Quarter turns (exact) and 45° (rounded once), shared by every shape.
  const std::vector<std::vector<double>> rot{{0, 90, 45, 180}};
  const auto one = no_fit_polygons(shapes, rot, 1);
  expect_entries(shapes, rot, one);
  std::size_t calls = 0, last = 0, total = 0;
  const auto two = no_fit_polygons(shapes, rot, 2, [&](std::size_t done, std::size_t all) {
    EXPECT_GE(done, last);
    last = done, total = all, ++calls;
  });
  EXPECT_EQ(total, one.size());
  EXPECT_EQ(last, total);
  EXPECT_GT(calls, 2u);
  ASSERT_EQ(two.size(), one.size());
  for (std::size_t k = 0; k < one.size(); ++k) EXPECT_TRUE(same_parts(one[k].nfp, two[k].nfp)) << k;
}

// Issue 19 item 2: a Shape2 triangulates itself (and makes its convex parts) once per role, and
// every pair built from it reuses that. The answers must not depend on which pair filled the
// cache: pairs built in reverse order, in parallel, and through Pair2's no-fit-polygon engine all
// equal the engine-level NoFitPolygon2 on the bare polygons (its own fresh triangulations, full
// build with the query structures), bit for bit, exports and queries.
TEST(NoFitPolygons, SharedPerShapeWorkGivesTheFreshBuildInAnyOrder) {
  std::vector<Shape2> shapes = shapes_of(read_nesting_instance(instance("albano")));
  if (shapes.size() > 6) shapes.erase(shapes.begin() + 6, shapes.end());
  shapes.push_back(shapes[0].rotated(45));  // a rounded rotation too
  const std::size_t n = shapes.size();
  std::vector<NoFitPolygonParts> fresh(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const NoFitPolygon2 f(shapes[i].polygon(), shapes[j].polygon());
      fresh[i * n + j] = NoFitPolygonParts{f.polygons(), f.slits(), f.points()};
    }
  // Reverse order first (each shape's Q side is made before its P side), on new shape objects.
  std::vector<Shape2> copies;
  for (const Shape2& s : shapes) copies.push_back(s.rotated(0));  // a new Shape2, same rings
  for (std::size_t k = n * n; k-- > 0;)
    EXPECT_TRUE(same_parts(no_fit_polygon(copies[k / n], copies[k % n]), fresh[k])) << "pair " << k / n << ", " << k % n;
  // In parallel on the same (now filled) shapes, and on other new copies filled by the threads.
  const std::vector<std::vector<double>> zero{{0}};
  for (const auto& got : {no_fit_polygons(copies, zero, 2), no_fit_polygons(shapes, zero, 2)}) {
    ASSERT_EQ(got.size(), n * n);
    for (std::size_t k = 0; k < n * n; ++k) EXPECT_TRUE(same_parts(got[k].nfp, fresh[k])) << "entry " << k;
  }
  // Pair2's engine on the shared sides: the same export and the same query answers.
  const std::array<Vec2, 4> ts{Vec2(0, 0), Vec2(1.5, -2.25), Vec2(-7, 3), Vec2(12.5, 0.75)};
  std::size_t engine_pairs = 0;
  for (std::size_t i = 0; i < n; i += 2)
    for (std::size_t j = 0; j < n; j += 3) {
      const Pair2 pair(copies[i], copies[j], Prepare::Full);
      if (pair.engine() != Engine2::NoFitPolygon) continue;  // a convex piece: not this engine
      ++engine_pairs;
      EXPECT_TRUE(same_parts(pair.no_fit_polygon(), fresh[i * n + j]));
      const NoFitPolygon2 f(shapes[i].polygon(), shapes[j].polygon());
      for (const Vec2& t : ts) {
        EXPECT_EQ(pair.overlapping(t), f.overlapping(t));
        const Depth2 a = pair.minimum(t), b = f.minimum(t);
        EXPECT_TRUE(same_bits(a.depth, b.depth) && same_vec(a.translation, b.translation)) << i << ", " << j;
      }
    }
  EXPECT_GT(engine_pairs, 3u);
}

TEST(NoFitPolygons, PerShapeRotationListsFromTheInstance) {
  // Albano's allowed orientations (0, 180 per item), one list per shape, and uneven lists.
  const NestingInstance inst = read_nesting_instance(instance("albano"));
  const std::vector<Shape2> shapes = shapes_of(inst);
  std::vector<std::vector<double>> rot;
  for (const auto& it : inst.items) rot.push_back(it.allowed_orientations);
  EXPECT_EQ(rot[0], (std::vector<double>{0, 180}));
  expect_entries(shapes, rot, no_fit_polygons(shapes, rot, 2));
  const std::vector<Shape2> three(shapes.begin(), shapes.begin() + 3);
  const std::vector<std::vector<double>> uneven{{0}, {270, 30}, {90, 180, -90}};
  expect_entries(three, uneven, no_fit_polygons(three, uneven, 2));
}

// The vertices of a no-fit polygon as a sorted multiset (rings, slit ends and points).
std::vector<std::array<double, 2>> vertex_set(const NoFitPolygonParts& n, int quarter_turns = 0) {
  std::vector<std::array<double, 2>> out;
  auto add = [&](Vec2 p) {
    for (int k = 0; k < quarter_turns; ++k) p = Vec2(-p.y(), p.x());
    out.push_back({p.x(), p.y()});
  };
  for (const auto& poly : n.polygons)
    for (const auto& ring : poly)
      for (const Vec2& p : ring) add(p);
  for (const auto& s : n.slits) add(s[0]), add(s[1]);
  for (const Vec2& p : n.points) add(p);
  std::sort(out.begin(), out.end());
  return out;
}

TEST(NoFitPolygons, QuarterTurnsGiveTheExactlyRotatedNoFitPolygon) {
  // Turning P and Q by the same quarter turn turns their no-fit polygon exactly: the entry at
  // (a + 90, b + 90) has the vertices of the entry at (a, b) turned by (x, y) → (−y, x), bit for
  // bit (rounded rotations would not). Trousers: many collinear edges and exact contacts.
  const std::vector<Shape2> all = shapes_of(read_nesting_instance(instance("trousers")));
  const std::vector<Shape2> shapes(all.begin(), all.begin() + 6);
  const std::vector<std::vector<double>> rot{{0, 90, 180, 270}};
  const auto e = no_fit_polygons(shapes, rot, 2);
  const std::size_t R = 4, C = shapes.size() * R;
  ASSERT_EQ(e.size(), C * C);
  std::size_t checked = 0;
  for (std::size_t x = 0; x < C; ++x)
    for (std::size_t y = 0; y < C; ++y) {
      const std::size_t xa = x % R, ya = y % R;
      if (xa + 1 >= R || ya + 1 >= R) continue;
      const NoFitPolygonEntry &base = e[x * C + y], &turned = e[(x + 1) * C + y + 1];
      ASSERT_EQ(turned.rotation_i, base.rotation_i + 90);
      ASSERT_EQ(turned.rotation_j, base.rotation_j + 90);
      EXPECT_EQ(vertex_set(turned.nfp), vertex_set(base.nfp, 1)) << base.i << "@" << base.rotation_i << ", " << base.j << "@" << base.rotation_j;
      ++checked;
    }
  EXPECT_EQ(checked, shapes.size() * shapes.size() * 9);
}

TEST(NoFitPolygons, ErrorsAtTheBoundary) {
  const Shape2 L = Shape2::from_wkt("POLYGON ((0 0, 3 0, 3 1, 1 1, 1 2, 0 2))", "L");
  const std::vector<Shape2> two{L, L};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of([&] { no_fit_polygons(two, std::vector<std::vector<double>>{{0}, {0}, {0}}); }),
            "no_fit_polygons: 3 rotation lists for 2 shapes (give one list, or one per shape)");
  EXPECT_EQ(error_of([&] { no_fit_polygons(two, std::vector<std::vector<double>>{{0}, {}}); }),
            "no_fit_polygons: the rotation list of shape 1 (L) is empty");
  EXPECT_EQ(error_of([&] { no_fit_polygons(two, std::vector<std::vector<double>>{{0, nan}}); }),
            "no_fit_polygons: shape 0 (L): rotation is not finite");
  // Nothing to pair: no entries, no call of the work.
  EXPECT_TRUE(no_fit_polygons({}, std::vector<std::vector<double>>{{0}}).empty());
}

}  // namespace
