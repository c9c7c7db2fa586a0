// End to end: `pendepth nfp-all INSTANCE.json` — the CSV rows i,rotation_i,j,rotation_j,"WKT"
// equal the library's no-fit polygon of the rotated pair (and `pendepth nfp` at rotation 0), the
// same bytes at 1 and 2 threads, JSON Lines, the progress line, the ESICUP instances of
// ../shared/data, and the error contract (exit 2 with one line naming file, item and problem;
// exit 3 for a failed write).
#include <pendepth/io.hpp>
#include <pendepth/nesting.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_fixture.hpp"

namespace {

using cli_test::CliFixture;
using nlohmann::json;
using namespace pendepth;

// Two items: an L (closing vertex repeated, orientations 0 and 90) and a plate with a square hole
// (type "polygon", no allowed_orientations: 0 only).
const char* kInstance = R"({
  "name": "small",
  "items": [
    {"id": 0, "demand": 2, "allowed_orientations": [0.0, 90.0],
     "shape": {"type": "simple_polygon", "data": [[0, 0], [3, 0], [3, 1], [1, 1], [1, 2], [0, 2], [0, 0]]}},
    {"id": "plate", "demand": 1,
     "shape": {"type": "polygon", "data": {"outer": [[0, 0], [6, 0], [6, 6], [0, 6]],
                                            "inner": [[[2, 2], [2, 4], [4, 4], [4, 2]]]}}}
  ],
  "strip_height": 10
})";

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::string wkt_of(const NoFitPolygonParts& n) {
  io::Geometry2 g;
  g.polygons = n.polygons;
  for (const auto& s : n.slits) g.lines.push_back({s[0], s[1]});
  g.points = n.points;
  return io::to_wkt(g);
}

std::string instance(const std::string& name) { return std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + name + ".json"; }

class NfpAll : public CliFixture {};

TEST_F(NfpAll, RowsAreTheRotatedPairsNoFitPolygons) {
  const std::string path = write("small.json", kInstance);
  const auto r = run("nfp-all " + cli_test::quote(path) + " --threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");  // no progress line unless asked (stderr is not a terminal here)
  const auto rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), 1u + 3 * 3);  // copies: L@0, L@90, plate@0
  EXPECT_EQ(rows[0], "i,rotation_i,j,rotation_j,nfp");
  const NestingInstance inst = parse_nesting_instance(kInstance, "small");
  const std::vector<std::pair<std::size_t, double>> copies{{0, 0.0}, {0, 90.0}, {1, 0.0}};
  std::size_t k = 1;
  for (const auto& [i, a] : copies)
    for (const auto& [j, b] : copies) {
      const std::string wkt = wkt_of(no_fit_polygon(inst.items[i].shape.rotated(a), inst.items[j].shape.rotated(b)));
      std::ostringstream want;
      want << i << ',' << a << ',' << j << ',' << b << ",\"" << wkt << '"';
      EXPECT_EQ(rows[k++], want.str());
    }
  // Rotation 0: the same WKT as `pendepth nfp` on the shapes as files.
  const std::string L = write("L.wkt", "POLYGON ((0 0, 3 0, 3 1, 1 1, 1 2, 0 2, 0 0))\n");
  const std::string plate = write("plate.wkt", "POLYGON ((0 0, 6 0, 6 6, 0 6, 0 0), (2 2, 2 4, 4 4, 4 2, 2 2))\n");
  EXPECT_EQ("0,0,1,0,\"" + lines_of(run("nfp " + cli_test::quote(L) + " " + cli_test::quote(plate)).out)[0] + "\"", rows[3]);
  EXPECT_EQ("1,0,0,0,\"" + lines_of(run("nfp " + cli_test::quote(plate) + " " + cli_test::quote(L)).out)[0] + "\"", rows[7]);
  // Two threads: the same bytes.
  EXPECT_EQ(run("nfp-all " + cli_test::quote(path) + " --threads 2").out, r.out);
}

TEST_F(NfpAll, RotationsOptionJsonAndProgress) {
  const std::string path = write("small.json", kInstance);
  const auto r = run("nfp-all " + cli_test::quote(path) + " --rotations 0,180 --json --progress");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("pendepth nfp-all: 16 / 16 pairs"), std::string::npos) << r.err;
  const auto rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), 16u);  // every item at 0 and 180
  const NestingInstance inst = parse_nesting_instance(kInstance, "small");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const json o = json::parse(rows[k]);
    const std::size_t i = o["i"], j = o["j"];
    const double a = o["rotation_i"], b = o["rotation_j"];
    EXPECT_EQ(i, k / 8);
    EXPECT_EQ(a, (k / 4) % 2 ? 180.0 : 0.0);
    EXPECT_EQ(j, (k / 2) % 2);
    EXPECT_EQ(b, k % 2 ? 180.0 : 0.0);
    std::string want;
    io::Geometry2 g;
    const NoFitPolygonParts n = no_fit_polygon(inst.items[i].shape.rotated(a), inst.items[j].shape.rotated(b));
    g.polygons = n.polygons;
    for (const auto& s : n.slits) g.lines.push_back({s[0], s[1]});
    g.points = n.points;
    io::append_json(want, g);
    EXPECT_EQ(o["nfp"], json::parse(want)) << rows[k];
  }
}

TEST_F(NfpAll, EsicupInstances) {
  // shirts at four orientations (8 items: 32 copies), baldacci4 (no allowed_orientations: 0),
  // albano at its own orientations (0, 180); one row per ordered pair of copies, same bytes at 1
  // and 2 threads.
  struct Case {
    const char* name;
    const char* rotations;
    std::size_t copies;
  };
  for (const Case& c : {Case{"shirts", "--rotations 0,90,180,270", 32}, Case{"baldacci4", "", 14}, Case{"albano", "", 16}}) {
    const std::string args = "nfp-all " + cli_test::quote(instance(c.name)) + " " + c.rotations;
    const auto two = run(args + " --threads 2");
    ASSERT_EQ(two.status, 0) << c.name << ": " << two.err;
    EXPECT_EQ(lines_of(two.out).size(), 1 + c.copies * c.copies) << c.name;
    EXPECT_EQ(run(args + " --threads 1").out, two.out) << c.name;
  }
}

TEST_F(NfpAll, BadInputExitsTwoNamingFileItemAndProblem) {
  auto item = [](const std::string& fields) { return R"({"items": [{"id": 0, "demand": 1, "shape": {"type": "simple_polygon", "data": [[0,0],[1,0],[0,1]]}}, )" + fields + "]}"; };
  const std::string bowtie = write("bowtie.json", item(R"({"id": 7, "demand": 1, "shape": {"type": "simple_polygon", "data": [[0,0],[1,1],[1,0],[0,1]]}})"));
  expect_error("nfp-all " + cli_test::quote(bowtie),
               bowtie + ": item 1 (id 7): shape: ring 0 (outer): self-intersecting (edges 0 and 2 intersect)");
  const std::string multi = write("multi.json", item(R"({"id": 1, "demand": 1, "shape": {"type": "multi_polygon", "data": []}})"));
  expect_error("nfp-all " + cli_test::quote(multi), multi + ": item 1 (id 1): shape type \"multi_polygon\" is not supported (one item must be one polygon)");
  const std::string point = write("point.json", item(R"({"id": 1, "demand": 1, "shape": {"type": "simple_polygon", "data": [[0,0],[1],[0,1]]}})"));
  expect_error("nfp-all " + cli_test::quote(point), point + ": item 1 (id 1): shape data point 1: expected [x, y]");
  const std::string demand = write("demand.json", item(R"({"id": 1, "demand": -2, "shape": {}})"));
  expect_error("nfp-all " + cli_test::quote(demand), demand + ": item 1 (id 1): \"demand\": expected a non-negative integer");
  const std::string angle = write("angle.json", item(R"({"id": 1, "demand": 1, "allowed_orientations": [0, "x"], "shape": {}})"));
  expect_error("nfp-all " + cli_test::quote(angle), angle + ": item 1 (id 1): allowed_orientations[1]: expected a number, got string");
  const std::string noshape = write("noshape.json", item(R"({"id": 1, "demand": 1})"));
  expect_error("nfp-all " + cli_test::quote(noshape), noshape + ": item 1 (id 1): item: missing \"shape\"");
  const std::string empty = write("empty.json", R"({"name": "x", "items": []})");
  expect_error("nfp-all " + cli_test::quote(empty), empty + ": \"items\" is empty");
  const std::string broken = write("broken.json", R"({"items": [{"id": 0,)");
  expect_error("nfp-all " + cli_test::quote(broken), broken + ": invalid JSON (byte 21)");
  const std::string ok = write("ok.json", kInstance);
  expect_error("nfp-all " + cli_test::quote(ok) + " --rotations 0,,90",
               "--rotations: \"\" is not a finite angle in degrees (expected A,B,... e.g. 0,90,180,270)");
  expect_error("nfp-all " + cli_test::quote(ok) + " --rotations nan",
               "--rotations: \"nan\" is not a finite angle in degrees (expected A,B,... e.g. 0,90,180,270)");
  expect_error("nfp-all " + cli_test::quote((dir_ / "missing.json").string()),
               (dir_ / "missing.json").string() + ": cannot read file (No such file or directory)");
}

TEST_F(NfpAll, FailedWriteExitsThree) {
  const std::string ok = write("ok.json", kInstance);
  ASSERT_TRUE(cli_test::fs::exists("/dev/full")) << "the test needs /dev/full (every Linux has it)";
  const auto err = dir_ / "err.txt";
  const int rc = std::system((cli_test::quote(PENDEPTH_CLI) + " nfp-all " + cli_test::quote(ok) + " > /dev/full 2> " + cli_test::quote(err.string())).c_str());
  EXPECT_EQ(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, 3);
  EXPECT_EQ(cli_test::slurp(err), "pendepth: standard output: cannot write (No space left on device)\n");
}

}  // namespace
