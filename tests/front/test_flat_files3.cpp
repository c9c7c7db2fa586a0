// Flat files (Shape3::from_file, io::shape3_from_points): a file whose points span fewer than 3
// dimensions — without faces, with a lone face, or read with hull = true — is the lower-
// dimensional Shape3::flat of its points, answering like Shape3::flat itself; 3D point sets stay
// hulls; empty files keep the hull's error.
#include <gtest/gtest.h>

#include <pendepth/pendepth.hpp>
#include <pendepth/shape_spec.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace pendepth {
namespace {

namespace fs = std::filesystem;

class FlatFiles3 : public ::testing::Test {
 protected:
  fs::path dir_ = fs::temp_directory_path() / ("pendepth-flat-files-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir_); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
};

TEST_F(FlatFiles3, CoplanarCollinearAndSinglePointFilesAreFlatShapes) {
  struct Case {
    std::string name, text;
    int dim;
    std::vector<Vec3> pts;
  };
  const std::vector<Case> cases = {
      {"square.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0.5 0.5 0\n", 2,
       {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0.5, 0.5, 0)}},
      {"face.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3 2\n", 2,
       {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}},
      {"tilted.obj", "v 0 0 0\nv 1 0 1\nv 0 1 1\nv 1 1 2\n", 2,
       {Vec3(0, 0, 0), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(1, 1, 2)}},
      {"line.obj", "v 0 0 0\nv 1 2 3\nv 0.5 1 1.5\n", 1, {Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(0.5, 1, 1.5)}},
      {"point.obj", "v 0.25 0.5 0.75\nv 0.25 0.5 0.75\n", 0, {Vec3(0.25, 0.5, 0.75), Vec3(0.25, 0.5, 0.75)}},
  };
  const Shape3 solid = Shape3::box(0.6, 0.4, 0.3);
  for (const Case& c : cases) {
    const std::string path = write(c.name, c.text);
    for (bool hull : {false, true}) {
      const Shape3 s = Shape3::from_file(path, "Q", hull);
      EXPECT_EQ(s.dimension(), c.dim) << c.name;
      EXPECT_EQ(io::affine_dimension(c.pts), c.dim) << c.name;
      const Pair3 from_file(solid, s), direct(solid, Shape3::flat(c.pts, "Q"));
      for (const Vec3& t : {Vec3(0, 0, 0), Vec3(0.3, -0.2, 0.1), Vec3(2, 1, -1)}) {
        const Pose3 pq(t);
        EXPECT_EQ(from_file.signed_distance(Pose3(), pq).distance, direct.signed_distance(Pose3(), pq).distance) << c.name;
        EXPECT_EQ(from_file.minimum(Pose3(), pq).depth, direct.minimum(Pose3(), pq).depth) << c.name;
      }
    }
  }
  // 3D point sets stay hulls; an empty file keeps the hull's error; two flat shapes are refused.
  const std::string tet = write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
  EXPECT_EQ(Shape3::from_file(tet, "P").dimension(), 3);
  EXPECT_EQ(Shape3::from_file(tet, "P").polytope().size(), 4u);
  const std::string empty = write("empty.obj", "# nothing\n");
  EXPECT_THROW(Shape3::from_file(empty, "P"), InvalidInput);
  const std::string sq = (dir_ / "square.obj").string();
  EXPECT_THROW(Pair3(Shape3::from_file(sq, "P"), Shape3::from_file(sq, "Q")), InvalidInput);
}

}  // namespace
}  // namespace pendepth
