// Trajectory files (`pendepth trajectory --poses FILE`, docs/design.md §3): one pose per line,
// 2D `x,y,angle_deg` (Q rotated by angle_deg about its origin, then placed at (x, y)) or 3D
// `x,y,z,qw,qx,qy,qz` (Q rotated by the quaternion, normalised, then translated).
//
// The conventions of the batch query files (src/io/csv_rows.hpp, shared with queries_csv.cpp):
// blank lines and '#' lines skipped, a header accepted only as the first data line and only when
// it is exactly the expected names, any other line exactly N finite numbers separated by ',';
// errors "SOURCE:LINE: problem". In 3D a zero quaternion is an error too (it is no rotation).
#include <pendepth/io.hpp>

#include "io/csv_rows.hpp"

namespace pendepth::io {
namespace {

constexpr detail::CsvLayout<3> kPoses2{{"x", "y", "angle_deg"}, 7, " (a 3D pose x,y,z,qw,qx,qy,qz; the shapes are 2D)"};
constexpr detail::CsvLayout<7> kPoses3{{"x", "y", "z", "qw", "qx", "qy", "qz"}, 3,
                                       " (a 2D pose x,y,angle_deg; the shapes are 3D)"};

}  // namespace

std::vector<PoseLine2> parse_poses2_csv(std::string_view text, std::string_view source) {
  std::vector<PoseLine2> out;
  detail::parse_csv_rows(text, source, kPoses2, [&](const double (&v)[3], std::size_t line, auto&&) {
    out.push_back({Vec2(v[0], v[1]), v[2], line});
  });
  return out;
}

std::vector<PoseLine3> parse_poses3_csv(std::string_view text, std::string_view source) {
  std::vector<PoseLine3> out;
  detail::parse_csv_rows(text, source, kPoses3, [&](const double (&v)[7], std::size_t line, auto&& fail) {
    if (v[3] == 0 && v[4] == 0 && v[5] == 0 && v[6] == 0) fail("the rotation quaternion is zero (it must be a rotation)");
    out.push_back({Vec3(v[0], v[1], v[2]), Eigen::Quaterniond(v[3], v[4], v[5], v[6]), line});
  });
  return out;
}

std::vector<PoseLine2> read_poses2_csv(const std::filesystem::path& path) {
  return parse_poses2_csv(read_text_file(path), path.string());
}

std::vector<PoseLine3> read_poses3_csv(const std::filesystem::path& path) {
  return parse_poses3_csv(read_text_file(path), path.string());
}

}  // namespace pendepth::io
