// Pair3's mesh pairs (either shape non-convex): the pieces of both decompositions in engine
// coordinates (src/front/scale.hpp, the same numeric domain as the convex pairs), built once per
// pair on its first query (mesh3/lazy.hpp). The queries are in src/mesh3/mesh_pair.cpp and
// mesh_line.cpp.
#include "front/mesh_shapes.hpp"
#include "front/scale.hpp"
#include "mesh3/mesh_pair.hpp"

#include <pendepth/mesh3.hpp>

namespace pendepth::front {
namespace {

mesh3::LazyMeshPair::Built build(const Shape3& P, const Shape3& Q) {
  bool exact = true;
  std::vector<ConvexPolytope> pp = mesh3::pieces_of(P, exact), qq = mesh3::pieces_of(Q, exact);
  Extent x;
  for (const auto* list : {&pp, &qq})
    for (const ConvexPolytope& c : *list) {
      for (const Vec3& v : c.vertices()) x.add_point(v.cwiseAbs().maxCoeff());
      for (const auto& t : c.triangles())
        for (int k = 0; k < 3; ++k) x.add_edge(c[t[k]], c[t[(k + 1) % 3]]);
    }
  const Scale scale = Scale::for_pair(x, kBand3);
  if (!scale.identity()) {
    auto to_engine = [&](std::vector<ConvexPolytope>& list, const Shape3& s, const char* which) {
      for (std::size_t i = 0; i < list.size(); ++i) {
        const auto v = list[i].vertices();
        for (std::size_t k = 0; k < v.size(); ++k)
          scale.vec_to_engine(v[k], [&] {
            return std::string(which) + " (" + s.name() + ") piece " + std::to_string(i) + " vertex " + std::to_string(k) + ":";
          });
        list[i] = list[i].scaled(-scale.e);
      }
    };
    to_engine(pp, P, "P");
    to_engine(qq, Q, "Q");
  }
  return {std::make_shared<const mesh3::MeshPair>(mesh3::MeshPair::make(std::move(pp), std::move(qq), exact)), scale.e};
}

}  // namespace

void rethrow_with_mesh_source(const Shape3& P, const Shape3& Q, const InvalidInput& e) {
  const Shape3& s = !P.is_convex() ? P : Q;
  if (!s.mesh() || s.mesh()->source().empty()) throw e;
  throw InvalidInput(s.mesh()->source() + ": " + e.what());
}

std::shared_ptr<const mesh3::LazyMeshPair> mesh_pair(const Shape3& P, const Shape3& Q) {
  return std::make_shared<const mesh3::LazyMeshPair>([P, Q]() -> mesh3::LazyMeshPair::Built {
    try {
      return build(P, Q);
    } catch (const InvalidInput& e) {
      rethrow_with_mesh_source(P, Q, e);
    }
  });
}

}  // namespace pendepth::front
