// End-to-end tests of 3D mesh files in `pendepth` (docs/design.md §3, issue 17 item 1): a file
// without faces is a point set (its hull); a closed convex mesh answers exactly as its hull; a
// non-convex closed mesh is answered on its convex pieces; a broken mesh is refused naming its
// face and edge; `--hull` takes the hull of any file's vertices on every 3D command; .ply by extension and by content (standard input).
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "cli/cli_fixture.hpp"
#include "mesh3/mesh_gen.hpp"

using pendepth::ConvexPolytope;
using pendepth::Depth3;
using pendepth::InvalidInput;
using pendepth::Pair3;
using pendepth::Pose3;
using pendepth::Shape3;
using pendepth::Vec3;
using cli_test::quote;
using cli_test::Result;
using mesh3_test::Gen;
namespace io = pendepth::io;

namespace {

Gen points_only(const Gen& g) { return Gen{g.points, {}}; }

Gen moved(Gen g, const Vec3& by) {
  for (Vec3& p : g.points) p += by;
  return g;
}

// A random convex polytope as a closed mesh: its hull's vertices and (outward) triangles.
Gen random_convex(std::mt19937_64& rng, int n) {
  std::normal_distribution<double> N;
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) pts.emplace_back(N(rng), N(rng), N(rng));
  const ConvexPolytope h = ConvexPolytope::hull(pts, "r");
  Gen g;
  g.points.assign(h.vertices().begin(), h.vertices().end());
  for (const auto& t : h.triangles()) g.faces.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  return g;
}

// What the library says about a file with faces that is not a closed mesh.
std::string validation_error(const std::string& path, const std::string& name) {
  try {
    pendepth::Mesh3::validate(io::read_mesh(path), name);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}

class CliMesh : public cli_test::CliFixture {
 protected:
  // Query files for batch / trajectory, the same for every pair.
  void SetUp() override {
    CliFixture::SetUp();
    queries_ = write("q.csv", "0.2,0.1,-0.3,0,0,0\n0.4,-0.2,0.1,1,0.5,-0.25\n3,3,3,0,0,0\n-0.1,0.3,0.2,0,0,1\n");
    placements_ = write("t.csv", "0.2,0.1,-0.3,0,0,0\n3,3,3,0,0,0\n0.5,0.5,0.5,0,0,0\n");
    poses_ = write("poses.csv", "0.2,0.1,-0.3,1,0,0,0\n0.3,0.1,-0.2,0.9,0.1,0.2,0.3\n0.4,0,0,1,0.2,0,0\n");
  }
  // Every 3D command and mode, as arguments after "CMD P Q" (CMD first).
  std::vector<std::pair<std::string, std::string>> commands() const {
    return {{"depth", "--offset 0.3,-0.2,0.1 --json"},
            {"depth", "--offset 0.3,-0.2,0.1 --direction 1,0.5,-0.25 --json"},
            {"depth", "--offset 0.3,-0.2,0.1 --direction 1,0.5,-0.25 --separate"},
            {"depth", "--offset 0.3,-0.2,0.1 --rotate-q 0.9,0.1,0.2,0.3 --rotate-p 1,0,0.1,0"},
            {"depth", "--offset 0.3,-0.2,0.1 --generalized --json"},
            {"batch", "--queries " + quote(queries_) + " --json --threads 2"},
            {"batch", "--queries " + quote(placements_) + " --signed"},
            {"distance", "--offset 0.3,-0.2,0.1 --json"},
            {"distance", "--offset 5,1,0.5"},
            {"cast", "--offset 5,1,0.5 --direction -1,0,0 --json"},
            {"trajectory", "--poses " + quote(poses_) + " --json"}};
  }
  Result run3(const std::string& cmd, const std::string& p, const std::string& q, const std::string& args) {
    return run(cmd + " " + quote(p) + " " + quote(q) + " " + args);
  }
  std::string queries_, placements_, poses_;
};

// A closed convex mesh takes the convex path: every command prints exactly what it prints for the
// point set of the same vertices, and what --hull prints; in OBJ, OFF and PLY (ASCII and binary).
TEST_F(CliMesh, ConvexMeshesAnswerAsTheirHulls) {
  std::mt19937_64 rng(17);
  for (int round = 0; round < 2; ++round) {
    const Gen P = random_convex(rng, 40), Q = moved(random_convex(rng, 30), Vec3(0.25, 0, 0));
    ASSERT_GE(P.faces.size(), 12u);
    const std::string P_pts = write("P_pts.obj", mesh3_test::write_obj(points_only(P)));
    const std::string Q_pts = write("Q_pts.obj", mesh3_test::write_obj(points_only(Q)));
    const std::string P_mesh = write("P.obj", mesh3_test::write_obj(P));
    const std::vector<std::string> Q_meshes = {
        write("Q.obj", mesh3_test::write_obj(Q)), write("Q.off", mesh3_test::write_off(Q)),
        write("Q.ply", mesh3_test::write_ply(Q, "ascii")), write("Qle.PLY", mesh3_test::write_ply(Q, "binary_little_endian")),
        write("Qbe.ply", mesh3_test::write_ply(Q, "binary_big_endian"))};
    for (const auto& [cmd, args] : commands()) {
      const Result want = run3(cmd, P_pts, Q_pts, args);
      ASSERT_EQ(want.status, 0) << cmd << " " << args << ": " << want.err;
      ASSERT_FALSE(want.out.empty());
      for (const std::string& q : Q_meshes) {
        for (const std::string& hull : {"", " --hull"}) {
          const Result r = run3(cmd, P_mesh, q, args + hull);
          EXPECT_EQ(r.status, 0) << cmd << " " << args << hull << " " << q << ": " << r.err;
          EXPECT_EQ(r.out, want.out) << cmd << " " << args << hull << " " << q;
        }
      }
    }
    // The answers are the library's on the hulls (σ, bit for bit).
    const Result r = run3("depth", P_mesh, Q_meshes[3], "--offset 0.3,-0.2,0.1 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const Depth3 s = Pair3(Shape3::hull(P.points), Shape3::hull(Q.points)).minimum(Pose3(), Pose3(Vec3(0.3, -0.2, 0.1)));
    EXPECT_EQ(nlohmann::json::parse(r.out)["depth"].get<double>(), s.depth);
  }
}

// A non-convex closed mesh: answered on its convex pieces by depth, batch, distance, cast and
// trajectory and depth --generalized (the library's answers, bit for bit); --html refuses it
// (exit 2); --hull answers its hull's σ; --approximate reads the vertices anyway.
TEST_F(CliMesh, NonConvexMeshAnswersOnPieces) {
  const Gen L = mesh3_test::polycube(mesh3_test::l_block());  // an L of 5 unit voxels
  const Gen C = moved(mesh3_test::cube(), Vec3(-0.2, -0.3, 0.1));
  const std::string l = write("L.obj", mesh3_test::write_obj(L)), l_pts = write("L_pts.obj", mesh3_test::write_obj(points_only(L)));
  const std::string c = write("C.ply", mesh3_test::write_ply(C, "ascii"));
  ASSERT_FALSE(Shape3::from_file(l).is_convex());
  for (const auto& [cmd, args] : commands()) {
    for (const bool swap : {false, true}) {
      const Result r = swap ? run3(cmd, c, l, args) : run3(cmd, l, c, args);
      EXPECT_EQ(r.status, 0) << cmd << " " << args << ": " << r.err;
      EXPECT_FALSE(r.out.empty()) << cmd << " " << args;
    }
    const Result want = run3(cmd, l_pts, c, args);
    ASSERT_EQ(want.status, 0) << cmd << " " << args << ": " << want.err;
    const Result r = run3(cmd, l, c, args + " --hull");
    EXPECT_EQ(r.status, 0) << cmd << " " << args << ": " << r.err;
    EXPECT_EQ(r.out, want.out) << cmd << " " << args;
  }
  // The mesh answers are the library's on the mesh pair: σ (bounds), σ_d, distance, with pieces.
  const Pair3 mesh_pair(Shape3::from_file(l, "P"), Shape3::from_file(c, "Q"));
  const Pose3 at(Vec3(0.9, 0.9, 0.2));
  const Depth3 m = mesh_pair.minimum(Pose3(), at);
  const auto js = nlohmann::json::parse(run3("depth", l, c, "--offset 0.9,0.9,0.2 --json").out);
  EXPECT_EQ(js["depth"].get<double>(), m.depth);
  EXPECT_EQ(js["lower_bound"].get<double>(), m.lower_bound);
  EXPECT_EQ(js["piece_p"].get<int>(), m.piece_p);
  // cast: the library's mesh cast, with its bracket and pieces.
  const pendepth::Cast3 k = mesh_pair.cast(Pose3(), Pose3(Vec3(5, 1, 0.5)), Vec3(-1, 0, 0));
  ASSERT_TRUE(k.hit);
  const auto jk = nlohmann::json::parse(run3("cast", l, c, "--offset 5,1,0.5 --direction -1,0,0 --json").out);
  EXPECT_EQ(jk["distance"].get<double>(), k.distance);
  EXPECT_EQ(jk["lower_bound"].get<double>(), k.lower_bound);
  EXPECT_EQ(jk["upper_bound"].get<double>(), k.upper_bound);
  EXPECT_EQ(jk["piece_p"].get<int>(), k.piece_p);
  EXPECT_EQ(jk["piece_q"].get<int>(), k.piece_q);
  const Depth3 d = mesh_pair.along(Pose3(), at, Vec3(1, 0.5, -0.25));
  EXPECT_EQ(nlohmann::json::parse(run3("depth", l, c, "--offset 0.9,0.9,0.2 --direction 1,0.5,-0.25 --json").out)["depth"].get<double>(),
            d.depth);
  // --generalized: PD_g of the mesh pair (issue 18 item 2), every field the library's.
  const pendepth::GeneralizedDepth3 g = pendepth::generalized_depth(mesh_pair.P(), Pose3(), mesh_pair.Q(), at);
  const auto jg = nlohmann::json::parse(run3("depth", l, c, "--offset 0.9,0.9,0.2 --generalized --json").out);
  EXPECT_EQ(jg["kind"], "generalized");
  EXPECT_EQ(jg["depth"].get<double>(), g.depth);
  EXPECT_EQ(jg["lower_bound"].get<double>(), g.lower_bound);
  EXPECT_EQ(jg["upper_bound"].get<double>(), g.upper_bound);
  EXPECT_EQ(jg["sigma"].get<double>(), m.depth);
  EXPECT_EQ(jg["converged"].get<bool>(), g.converged);
  EXPECT_EQ(jg["probes"].get<std::size_t>(), g.probes);
  const double w[4] = {g.rotation.w(), g.rotation.x(), g.rotation.y(), g.rotation.z()};
  for (int k = 0; k < 4; ++k) EXPECT_EQ(jg["rotation"][k].get<double>(), w[k]);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(jg["translation"][k].get<double>(), g.translation[k]);
  EXPECT_FALSE(mesh_pair.overlapping(Pose3(), g.pose));
  EXPECT_LE(g.lower_bound, g.upper_bound);
  EXPECT_LE(g.upper_bound, m.upper_bound * (1 + 1e-12));  // rotation only helps (the cost is rounded up)
  const Result h = run3("depth", l, c, "--offset 0.9,0.9,0.2 --generalized");
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_NE(h.out.find("meshes: the best motion found"), std::string::npos) << h.out;
  EXPECT_EQ(run3("depth", l, c, "--offset 0.9,0.9,0.2 --html x.html").status, 2);
  const pendepth::Distance3 sd = mesh_pair.signed_distance(Pose3(), Pose3(Vec3(5, 1, 0.5)));
  EXPECT_EQ(nlohmann::json::parse(run3("distance", l, c, "--offset 5,1,0.5 --json").out)["distance"].get<double>(), sd.distance);
  EXPECT_GT(sd.distance, 0);
  // --hull's σ is the hull's σ (the library's, bit for bit), here with the cube in the L's notch.
  const Result r = run3("depth", l, c, "--hull --offset 0.9,0.9,0.2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Depth3 s = Pair3(Shape3::from_file(l, "P", true), Shape3::from_file(c, "Q", true))
                       .minimum(Pose3(), Pose3(Vec3(0.9, 0.9, 0.2)));
  ASSERT_TRUE(s.overlapping);
  EXPECT_EQ(nlohmann::json::parse(r.out)["depth"].get<double>(), s.depth);
  // --approximate works on raw vertices, faces or not (no validation, no --hull needed).
  const Result a = run3("depth", l, c, "--approximate 0.01 --json");
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.out, run3("depth", l_pts, c, "--approximate 0.01 --json").out);
  EXPECT_EQ(run3("depth", l, c, "--approximate 0.01 --json --hull").out, a.out);
}

// Files with faces that are not a closed, consistently oriented mesh: exit 2 with the library's
// message naming the face and edge; --hull takes their vertices' hull instead.
TEST_F(CliMesh, BrokenMeshesAreRefusedNamingTheFace) {
  Gen open = mesh3_test::cube();
  open.faces.pop_back();  // a missing face: its four edges are open
  Gen flipped = mesh3_test::cube();
  std::reverse(flipped.faces[2].begin(), flipped.faces[2].end());
  const std::string cube_pts = write("cube_pts.obj", mesh3_test::write_obj(points_only(mesh3_test::cube())));
  const std::string P = write("P.obj", mesh3_test::write_obj(moved(mesh3_test::cube(), Vec3(0.5, 0.25, 0))));
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"open.obj", mesh3_test::write_obj(open)},
           {"open.ply", mesh3_test::write_ply(open, "binary_little_endian")},
           {"flipped.off", mesh3_test::write_off(flipped)}}) {
    const std::string q = write(name, text);
    const std::string message = validation_error(q, "Q");
    EXPECT_NE(message.find(q + (name.ends_with(".ply") ? ": face " : ":")), std::string::npos) << message;
    EXPECT_NE(message.find(name.starts_with("open") ? "not closed: edge" : "inconsistent orientation"), std::string::npos)
        << message;
    for (const auto& [cmd, args] : commands()) {
      expect_error(cmd + " " + quote(P) + " " + quote(q) + " " + args, message);
      const Result r = run3(cmd, P, q, args + " --hull");
      EXPECT_EQ(r.status, 0) << cmd << " " << args << ": " << r.err;
      EXPECT_EQ(r.out, run3(cmd, P, cube_pts, args).out) << cmd << " " << args;
    }
  }
  // A lone face: its points are coplanar, so it is a flat polygon (Shape3::flat), not an open
  // mesh — the same answer with or without --hull.
  const std::string flat = write("flat.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3 2\n");
  const Result f = run("depth " + quote(P) + " " + quote(flat));
  EXPECT_EQ(f.status, 0) << f.err;
  EXPECT_NE(f.out.find("(a flat polygon of 4 vertices)"), std::string::npos) << f.out;
  EXPECT_EQ(run("depth " + quote(P) + " " + quote(flat) + " --hull").out, f.out);
}

// PLY by content: on standard input (`-`) and through a path without an extension, ASCII and
// binary, P or Q, the same answers as the .ply file.
TEST_F(CliMesh, PlyOnStandardInput) {
  const Gen C = moved(mesh3_test::cube(), Vec3(0.3, 0.2, 0.1));
  const std::string P = write("P.obj", mesh3_test::write_obj(mesh3_test::polycube({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}})));
  for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    const std::string ply = write("c.ply", mesh3_test::write_ply(C, format)), bare = write("c_" + format, cli_test::slurp(ply));
    const Result want = run3("depth", P, ply, "--json");
    ASSERT_EQ(want.status, 0) << want.err;
    EXPECT_TRUE(nlohmann::json::parse(want.out)["overlapping"].get<bool>());
    for (const std::string& args : {"depth " + quote(P) + " - --json < " + quote(ply),
                                    "depth " + quote(P) + " " + quote(bare) + " --json"}) {
      const Result r = run(args);
      EXPECT_EQ(r.status, 0) << args << ": " << r.err;
      EXPECT_EQ(r.out, want.out) << args;
    }
    const Result swapped = run("depth - " + quote(P) + " --json < " + quote(ply));
    EXPECT_EQ(swapped.status, 0) << swapped.err;
    EXPECT_EQ(swapped.out, run3("depth", ply, P, "--json").out);
  }
  // A broken PLY on standard input is named <stdin>, with its face and byte offset.
  Gen open = mesh3_test::cube();
  open.faces.pop_back();
  const std::string bad = write("open.ply", mesh3_test::write_ply(open, "binary_big_endian"));
  const Result r = run("depth " + quote(P) + " - < " + quote(bad));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.err.starts_with("<stdin>: face ")) << r.err;
  EXPECT_NE(r.err.find("(byte offset "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not closed"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// --hull is listed by every 3D command's help and refused on 2D shapes.
TEST_F(CliMesh, HullFlagOnEveryCommand) {
  const std::string a = write("a.wkt", "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))"), b = write("b.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))");
  const std::string q2 = write("q2.csv", "0.5,0.5,0,0\n"), poses2 = write("p2.csv", "0.5,0.5,0\n");
  const std::string ab = quote(a) + " " + quote(b);
  const std::string message = "--hull: applies to 3D mesh files only (.obj, .off, .stl, .ply)";
  expect_error("depth " + ab + " --hull", message);
  expect_error("batch " + ab + " --queries " + quote(q2) + " --hull", message);
  expect_error("distance " + ab + " --hull", message);
  expect_error("cast " + ab + " --direction 1,0 --hull", message);
  expect_error("trajectory " + ab + " --poses " + quote(poses2) + " --hull", message);
  for (const char* cmd : {"depth", "batch", "distance", "cast", "trajectory"}) {
    const Result h = run(std::string(cmd) + " --help");
    EXPECT_EQ(h.status, 0) << cmd;
    EXPECT_NE(h.out.find("--hull"), std::string::npos) << cmd;
    EXPECT_NE(h.out.find(".ply"), std::string::npos) << cmd;
  }
}

// A non-convex mesh against a point, a segment, a flat polygon or a primitive (src/mesh3/mesh_mixed.cpp), either role: every
// command but --generalized answers (exit 0), the JSON is the library's Pair3 answer.
TEST_F(CliMesh, MeshAgainstPointAndPrimitives) {
  const std::string l = write("L.obj", mesh3_test::write_obj(mesh3_test::polycube(mesh3_test::l_block())));
  for (const std::string& q : {std::string("point:0.5,0.5,0.5"), std::string("sphere:0.3"), std::string("capsule:0.2,0.3")}) {
    for (const auto& [cmd, args] : commands()) {
      if (args.find("--generalized") != std::string::npos) continue;
      for (const bool swap : {false, true}) {
        const Result r = swap ? run3(cmd, q, l, args) : run3(cmd, l, q, args);
        EXPECT_EQ(r.status, 0) << q << " " << cmd << " " << args << ": " << r.err;
        EXPECT_FALSE(r.out.empty()) << q << " " << cmd << " " << args;
      }
    }
  }
  const Pair3 pair(Shape3::from_file(l, "P"), Shape3::point(Vec3(0.5, 0.5, 0.5)));
  const Pose3 at(Vec3(0.3, -0.2, 0.1));
  const auto js = nlohmann::json::parse(run3("depth", l, "point:0.5,0.5,0.5", "--offset 0.3,-0.2,0.1 --direction 1,0.5,-0.25 --json").out);
  EXPECT_EQ(js["depth"].get<double>(), pair.along(Pose3(), at, Vec3(1, 0.5, -0.25)).depth);
  EXPECT_GT(js["depth"].get<double>(), 0);
  const auto jd = nlohmann::json::parse(run3("distance", l, "point:0.5,0.5,0.5", "--offset 0.3,-0.2,0.1 --json").out);
  EXPECT_EQ(jd["distance"].get<double>(), pair.signed_distance(Pose3(), at).distance);
  // A segment (src/mesh3/mesh_segment.cpp): the JSON is the library's answer, both roles.
  const std::string sq = "segment:0.25,0.5,0.5,1.25,0.5,0.5";
  const Pair3 sp(Shape3::from_file(l, "P"), Shape3::segment(Vec3(0.25, 0.5, 0.5), Vec3(1.25, 0.5, 0.5)));
  const auto ss = nlohmann::json::parse(run3("depth", l, sq, "--offset 0.3,-0.2,0.1 --direction 1,0.5,-0.25 --json").out);
  EXPECT_EQ(ss["depth"].get<double>(), sp.along(Pose3(), at, Vec3(1, 0.5, -0.25)).depth);
  EXPECT_GT(ss["depth"].get<double>(), 0);
  const auto sd = nlohmann::json::parse(run3("distance", l, sq, "--offset 0,1.5,0 --json").out);
  EXPECT_EQ(sd["distance"].get<double>(), sp.signed_distance(Pose3(), Pose3(Vec3(0, 1.5, 0))).distance);
  for (const auto& [cmd, args] : commands()) {
    if (args.find("--generalized") != std::string::npos) continue;
    for (const bool swap : {false, true}) {
      const Result r = swap ? run3(cmd, sq, l, args) : run3(cmd, l, sq, args);
      EXPECT_EQ(r.status, 0) << sq << " " << cmd << " " << args << ": " << r.err;
    }
  }
  // A flat polygon file (a lone face; src/mesh3/mesh_flat.cpp) in the face x = 1 two pieces
  // share: the JSON is the library's answer, both roles.
  const std::string fq = write("square.off", "OFF\n4 1 0\n1 0.25 0.25\n1 0.75 0.25\n1 0.75 0.75\n1 0.25 0.75\n4 0 1 2 3\n");
  const std::vector<Vec3> sqv{Vec3(1, 0.25, 0.25), Vec3(1, 0.75, 0.25), Vec3(1, 0.75, 0.75), Vec3(1, 0.25, 0.75)};
  const Pair3 fp(Shape3::from_file(l, "P"), Shape3::flat(sqv));
  const auto fs = nlohmann::json::parse(run3("depth", l, fq, "--direction 0,0,1 --json").out);
  EXPECT_EQ(fs["depth"].get<double>(), 0.75);
  EXPECT_EQ(fs["depth"].get<double>(), fp.along(Pose3(), Pose3(), Vec3(0, 0, 1)).depth);
  const auto fd = nlohmann::json::parse(run3("distance", l, fq, "--offset 0,1.5,0 --json").out);
  EXPECT_EQ(fd["distance"].get<double>(), fp.signed_distance(Pose3(), Pose3(Vec3(0, 1.5, 0))).distance);
  for (const auto& [cmd, args] : commands()) {
    if (args.find("--generalized") != std::string::npos) continue;
    for (const bool swap : {false, true}) {
      const Result r = swap ? run3(cmd, fq, l, args) : run3(cmd, l, fq, args);
      EXPECT_EQ(r.status, 0) << fq << " " << cmd << " " << args << ": " << r.err;
    }
  }
}

}  // namespace
