// Private: a value built on first use, once, thread-safe (std::call_once) — the convex pieces of
// a Pair3 with a non-convex mesh (front/pair3_mesh.cpp, mesh_mixed.cpp). A Pair3 does not
// decompose its mesh at construction: only the queries that need the pieces build them (a mesh
// against a point or a segment answers overlap and σ_d on the mesh's own triangles and never
// does). A build that throws (InvalidInput: a piece outside the numeric domain, a piece too thin
// for the rounded or flat engine) leaves the value unbuilt: every later query throws the same.
// Mesh3::decomposition() is itself built once per mesh (validate.cpp), so pairs sharing a mesh
// share its decomposition.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <utility>

namespace pendepth::mesh3 {

/// Private (tests): while true, Pair3 builds the pieces at construction (the eager path before
/// they were lazy; tests compare the two bit for bit). Set only while no Pair3 is constructed.
inline bool eager_pieces = false;

template <class T>
class Lazy {
 public:
  explicit Lazy(std::function<T()> make) : make_(std::move(make)) {}
  const T& get() const {
    std::call_once(once_, [this] { value_.emplace(make_()); });
    return *value_;
  }

 private:
  std::function<T()> make_;
  mutable std::once_flag once_;
  mutable std::optional<T> value_;
};

}  // namespace pendepth::mesh3
