// The command-line tool against a hostile environment (issue 20, part 2): failed writes (a full
// device, a closed pipe, an --svg file that cannot be written) exit 3 with one line on stderr;
// named pipes, `-` (standard input) and extensionless paths work as inputs; the strict readers'
// errors reach the user as one line with exit status 2.
#include "cli/cli_fixture.hpp"

#include <sys/stat.h>

#include <algorithm>

using namespace cli_test;

namespace {

class CliRobust : public CliFixture {
 protected:
  std::string square() { return write("P.wkt", "POLYGON ((0 0, 4 0, 4 3, 0 3, 0 0))\n"); }
  std::string cube_off() { return write("cube.off", "OFF\n8 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n1 1 0\n1 0 1\n0 1 1\n"); }

  // Runs `sh -c script` (PENDEPTH stands for the binary); returns the status of the last command
  // and what it wrote on stdout / stderr (to files in the scratch directory).
  Result shell(std::string script) {
    for (std::size_t at; (at = script.find("PENDEPTH")) != std::string::npos;) script.replace(at, 8, quote(PENDEPTH_CLI));
    const fs::path out = dir_ / "sh_out.txt", err = dir_ / "sh_err.txt";
    const std::string cmd = "cd " + quote(dir_.string()) + " && { " + script + " ; } > " + quote(out.string()) + " 2> " +
                            quote(err.string());
    const int rc = std::system(cmd.c_str());
    Result r;
    r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }
};

}  // namespace

// ---- failed writes: exit status 3 and a message, never a silent exit 0 ----

TEST_F(CliRobust, WritingToAFullDeviceFails) {
  ASSERT_TRUE(fs::exists("/dev/full")) << "the test needs /dev/full (every Linux has it)";
  const std::string P = square();
  // The input: `pendepth ... > /dev/full` exited 0, the answer lost.
  for (const std::string& args : {"depth " + quote(P) + " " + quote(P) + " --offset 1,1",
                                  "depth " + quote(P) + " " + quote(P) + " --json", "nfp " + quote(P) + " " + quote(P)}) {
    const Result r = shell("PENDEPTH " + args + " > /dev/full");
    EXPECT_EQ(r.status, 3) << args;
    EXPECT_EQ(r.err, "pendepth: standard output: cannot write (No space left on device)\n") << args;
  }
  const std::string q = write("q.csv", "x,y,dx,dy\n1,1,0,0\n1,1,1,0\n");
  const Result b = shell("PENDEPTH batch " + quote(P) + " " + quote(P) + " --queries " + quote(q) + " > /dev/full");
  EXPECT_EQ(b.status, 3);
  EXPECT_EQ(b.err, "pendepth: standard output: cannot write (No space left on device)\n");
  // --svg to a full device, and to a path that cannot be created.
  const Result s = run("depth " + quote(P) + " " + quote(P) + " --svg /dev/full");
  EXPECT_EQ(s.status, 3);
  EXPECT_EQ(s.err, "pendepth: /dev/full: cannot write file (No space left on device)\n");
  const std::string nodir = (dir_ / "no" / "such" / "dir.svg").string();
  const Result n = run("depth " + quote(P) + " " + quote(P) + " --svg " + quote(nodir));
  EXPECT_EQ(n.status, 3);
  EXPECT_EQ(n.err, "pendepth: " + nodir + ": cannot write file (No such file or directory)\n");
}

TEST_F(CliRobust, AClosedPipeFails) {
  const std::string P = square();
  std::string csv = "x,y,dx,dy\n";
  for (int i = 0; i < 20000; ++i) csv += std::to_string(i % 7) + ".5," + std::to_string(i % 5) + ",0,0\n";
  const std::string q = write("q.csv", csv);
  // Far more output than a pipe holds, and a reader that reads nothing: the write meets EPIPE.
  const Result r = shell("{ PENDEPTH batch " + quote(P) + " " + quote(P) + " --queries " + quote(q) +
                         "; echo $? > status.txt; } | true");
  EXPECT_EQ(slurp(dir_ / "status.txt"), "3\n");
  EXPECT_EQ(r.err, "pendepth: standard output: cannot write (Broken pipe)\n");
}

// ---- inputs that are not regular files ----

TEST_F(CliRobust, ANamedPipeIsAShapeFile) {
  const std::string P = square();
  const fs::path fifo = dir_ / "fifo.wkt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The input: a FIFO was rejected as empty.
  const Result r = shell("cat " + quote(P) + " > fifo.wkt & PENDEPTH depth fifo.wkt " + quote(P) + " --offset 1,1 --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, run("depth " + quote(P) + " " + quote(P) + " --offset 1,1 --json").out);
  EXPECT_NE(r.out.find("\"depth\":2,"), std::string::npos) << r.out;
  // A 3D FIFO and a FIFO of queries.
  const std::string C = cube_off();
  const fs::path fifo3 = dir_ / "fifo.off", fifoq = dir_ / "fifo.csv";
  ASSERT_EQ(::mkfifo(fifo3.c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo(fifoq.c_str(), 0600), 0);
  const Result r3 = shell("cat " + quote(C) + " > fifo.off & printf '0.5,0,0,0,0,0\\n' > fifo.csv & PENDEPTH batch fifo.off " +
                          quote(C) + " --queries fifo.csv");
  EXPECT_EQ(r3.status, 0) << r3.err;
  EXPECT_EQ(r3.out, "depth,tx,ty,tz\n0.5,0.5,0,0\n");
}

TEST_F(CliRobust, DashReadsStandardInput) {
  const std::string P = square();
  const std::string want = run("depth " + quote(P) + " " + quote(P) + " --offset 1,1 --json").out;
  ASSERT_NE(want, "");
  Result r = shell("PENDEPTH depth - " + quote(P) + " --offset 1,1 --json < " + quote(P));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, want);
  r = shell("cat " + quote(P) + " | PENDEPTH depth " + quote(P) + " - --offset 1,1 --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, want);
  // Extensionless paths (a process substitution is /dev/fd/N) are recognised by their content too.
  const std::string noext = write("shape", "POLYGON ((0 0, 4 0, 4 3, 0 3, 0 0))\n");
  EXPECT_EQ(run("depth " + quote(noext) + " " + quote(P) + " --offset 1,1 --json").out, want);
  // Queries from standard input; 3D shapes from standard input (OFF, OBJ, STL by their content).
  r = shell("printf 'x,y,dx,dy\\n1,1,0,0\\n' | PENDEPTH batch " + quote(P) + " " + quote(P) + " --queries -");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "depth,tx,ty\n2,0,2\n");
  const std::string C = cube_off();
  const std::string want3 = run("depth " + quote(C) + " " + quote(C) + " --offset 0.5,0,0").out;
  r = shell("PENDEPTH depth - " + quote(C) + " --offset 0.5,0,0 < " + quote(C));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, want3);
  const std::string obj = write("cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nv 1 1 0\nv 1 0 1\nv 0 1 1\n");
  r = shell("PENDEPTH depth " + quote(C) + " - --offset 0.5,0,0 < " + quote(obj));
  EXPECT_EQ(r.out, want3) << r.err;
  // Errors name <stdin>; only one argument may be `-`; the format must be recognisable.
  r = shell("printf 'POLYGON ((0 0, 1 0, 1 x))' | PENDEPTH depth - " + quote(P));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<stdin>:1: expected a number for y, got 'x'\n");
  r = shell("PENDEPTH depth - - < " + quote(P));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "only one file argument can be '-' (standard input is read once)\n");
  r = shell("PENDEPTH batch - " + quote(P) + " --queries - < " + quote(P));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "only one file argument can be '-' (standard input is read once)\n");
  r = shell("printf 'hello' | PENDEPTH depth - " + quote(P));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "<stdin>: cannot tell the shape format from the content (expected a WKT POLYGON, OBJ, OFF, STL or PLY; "
            "name the file .wkt, .obj, .off, .stl or .ply)\n");
  r = shell("PENDEPTH depth - " + quote(P) + " < " + quote(C));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, P + ": Q is a 2D shape but P (<stdin>) is 3D; both must be 2D (.wkt) or both 3D (.obj, .off, .stl, .ply)\n");
  r = shell("PENDEPTH nfp - " + quote(P) + " < " + quote(C));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<stdin>: nfp takes 2D shapes (.wkt) only\n");
}

// ---- the strict readers through the tool ----

TEST_F(CliRobust, StrictReadersReportOneLine) {
  const std::string P = square();
  // OFF: 5 vertices declared, 8 given (was accepted with the first 5).
  const std::string off = write("five.off", "OFF\n5 6 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n1 1 0\n1 0 1\n0 1 1\n");
  expect_error("depth " + quote(off) + " " + quote(cube_off()),
               off + ":8: malformed face 0: 1 vertex (at least 3) (the header at line 2 declares 5 vertices and 6 faces)");
  // Query files whose only line is not numbers (each was taken as a header: exit 0, no rows).
  for (const std::string& line : {"1;1;0;0", "\"1\",\"1\",\"0\",\"0\"", "0x1,1,0,0", "X,Y,DX,DY", "\x01\x02\x03"}) {
    const std::string q = write("q.csv", line + std::string("\n"));
    const Result r = run("batch " + quote(P) + " " + quote(P) + " --queries " + quote(q));
    EXPECT_EQ(r.status, 2) << line;
    EXPECT_EQ(r.out, "") << line;
    EXPECT_EQ(r.err.rfind(q + ":1: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // A NUL byte in a number: the whole message, the NUL shown as \x00.
  const std::string nul = write("nul.wkt", std::string("POLYGON ((0 0, 1\0""2 0, 1 1))", 27));
  expect_error("depth " + quote(nul) + " " + quote(P), nul + ":1: expected a number for x, got '1\\x002'");
}
