// Shared fixture for the end-to-end CLI tests: a scratch directory per test, and a runner that
// executes the built `pendepth` binary (PENDEPTH_CLI) capturing exit status, stdout and stderr.
#pragma once

#include <pendepth/io.hpp>
#include <pendepth/polygon.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cli_test {

namespace fs = std::filesystem;

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Polygon rings (outer first), as the 2D polygon tests write them to .wkt files.
using Rings = std::vector<std::vector<pendepth::Vec2>>;

/// A POLYGON in WKT with the shortest round-trip doubles (closing vertex repeated).
inline std::string wkt_of(const Rings& rings) {
  std::string s = "POLYGON (";
  for (std::size_t k = 0; k < rings.size(); ++k) {
    s += k ? ",\n(" : "(";
    for (std::size_t i = 0; i <= rings[k].size(); ++i) {
      const pendepth::Vec2& p = rings[k][i % rings[k].size()];
      if (i) s += ", ";
      pendepth::io::append_double(s, p.x());
      s += ' ';
      pendepth::io::append_double(s, p.y());
    }
    s += ')';
  }
  return s + ")\n";
}

inline Rings rings_of(const pendepth::Polygon& P) {
  Rings r;
  for (std::size_t k = 0; k < P.ring_count(); ++k) r.emplace_back(P.ring(k).begin(), P.ring(k).end());
  return r;
}

struct Result {
  int status = -1;
  std::string out, err;
};

class CliFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("pendepth-test-" + std::string(info->test_suite_name()) + "-" +
                                        std::to_string(::getpid()) + "-" + info->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  Result run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd = quote(PENDEPTH_CLI) + " " + args + " > " + quote(out) + " 2> " + quote(err);
    const int rc = std::system(cmd.c_str());
    Result r;
    r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }
  // Exit status 2 and exactly the line `message` on stderr, nothing on stdout.
  void expect_error(const std::string& args, const std::string& message) {
    const Result r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.err, message + "\n") << args;
    EXPECT_EQ(r.out, "") << args;
  }

  fs::path dir_;
};

}  // namespace cli_test
