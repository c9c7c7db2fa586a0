// End-to-end tests of `pendepth depth … --html FILE` (issue 21): the page is written for every 3D
// query kind next to the usual output, and bad uses are one-line errors with exit status 2. The
// pages in a real browser: tests/html3/check_pages.py (ctest label browser).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using cli_test::quote;
using cli_test::slurp;

class CliHtml3 : public cli_test::CliFixture {
 protected:
  std::string cube() {
    return write("cube.off", "OFF\n8 0 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n");
  }
};

TEST_F(CliHtml3, WritesAPageForEveryQueryKind) {
  const std::string c = quote(cube());
  for (const std::string extra : {"", " --direction 1,0,0", " --direction 1,0,0 --separate", " --json"}) {
    const std::string page = (dir_ / "page.html").string();
    const cli_test::Result r = run("depth " + c + " " + c + " --offset 0.75,0.5,0.5 --html " + quote(page) + extra);
    ASSERT_EQ(r.status, 0) << extra << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("0.25"), std::string::npos) << extra;  // the usual output is still printed
    const std::string html = slurp(page);
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u) << extra;
    EXPECT_NE(html.find("\"id\":\"Q_moved\""), std::string::npos) << extra;
    fs::remove(page);
  }
}

TEST_F(CliHtml3, TwoDimensionalShapesAreRejected) {
  const std::string sq = quote(write("sq.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 1))"));
  expect_error("depth " + sq + " " + sq + " --html " + quote((dir_ / "x.html").string()),
               "--html draws 3D shapes only (use --svg for 2D)");
  EXPECT_FALSE(fs::exists(dir_ / "x.html"));
}

// A page that cannot be written is a failed write (exit 3, as --svg and standard output), not
// bad input; so is a full device.
TEST_F(CliHtml3, UnwritableFileIsAWriteError) {
  const std::string c = quote(cube());
  const std::string page = (dir_ / "no" / "such" / "dir.html").string();
  const cli_test::Result r = run("depth " + c + " " + c + " --html " + quote(page));
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.err.rfind("pendepth: " + page + ": cannot write file (", 0), 0u) << r.err;
  const cli_test::Result full = run("depth " + c + " " + c + " --html /dev/full");
  EXPECT_EQ(full.status, 3) << full.err;
}

}  // namespace
