// Replays the fuzzers' seed corpus (tests/fuzz/corpus/<target>/, crash inputs included once
// found) through the targets' own code in the ordinary test suite: every input must pass the
// target's invariants (a violation aborts the test). The libFuzzer runs themselves are
// scripts/fuzz.sh (docs/robustness.md, "Fuzzing").
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#define PENDEPTH_DECLARE(name) int name(const std::uint8_t* data, std::size_t size);
PENDEPTH_DECLARE(fuzz_wkt)
PENDEPTH_DECLARE(fuzz_obj)
PENDEPTH_DECLARE(fuzz_off)
PENDEPTH_DECLARE(fuzz_stl_ascii)
PENDEPTH_DECLARE(fuzz_stl_binary)
PENDEPTH_DECLARE(fuzz_queries_csv)
PENDEPTH_DECLARE(fuzz_query2_convex)
PENDEPTH_DECLARE(fuzz_query2_polygon)
PENDEPTH_DECLARE(fuzz_query3)
PENDEPTH_DECLARE(fuzz_shapes_raw)
#undef PENDEPTH_DECLARE

namespace {

namespace fs = std::filesystem;
using Target = int (*)(const std::uint8_t*, std::size_t);

struct Case {
  const char* name;
  Target run;
};

const Case kTargets[] = {
    {"fuzz_wkt", fuzz_wkt},
    {"fuzz_obj", fuzz_obj},
    {"fuzz_off", fuzz_off},
    {"fuzz_stl_ascii", fuzz_stl_ascii},
    {"fuzz_stl_binary", fuzz_stl_binary},
    {"fuzz_queries_csv", fuzz_queries_csv},
    {"fuzz_query2_convex", fuzz_query2_convex},
    {"fuzz_query2_polygon", fuzz_query2_polygon},
    {"fuzz_query3", fuzz_query3},
    {"fuzz_shapes_raw", fuzz_shapes_raw},
};

class FuzzCorpus : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(FuzzCorpus, EverySeedPassesTheInvariants) {
  const fs::path dir = fs::path(PENDEPTH_FUZZ_CORPUS) / GetParam().name;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 3u) << dir;  // the loader fails loudly on a missing corpus
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    std::ifstream in(f, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(GetParam().run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzCorpus, ::testing::ValuesIn(kTargets),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });
