// Minimal Wavefront OBJ vertex reader ("v x y z [w]" lines); faces and everything else are
// ignored because convex algorithms take the hull of the vertices (DESIGN.md §3).
#include <pendepth/polytope.hpp>

#include <fstream>
#include <sstream>

namespace pendepth {

std::vector<Vec3> read_obj_vertices(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InvalidInput(path + ": cannot open file");
  std::vector<Vec3> pts;
  std::string line;
  for (std::size_t lineno = 1; std::getline(in, line); ++lineno) {
    std::istringstream ls(line);
    std::string tag;
    if (!(ls >> tag) || tag != "v") continue;
    double x, y, z;
    if (!(ls >> x >> y >> z))
      throw InvalidInput(path + ":" + std::to_string(lineno) + ": malformed vertex line '" + line + "'");
    pts.emplace_back(x, y, z);
  }
  if (pts.empty()) throw InvalidInput(path + ": no vertex ('v x y z') lines");
  return pts;
}

}  // namespace pendepth
