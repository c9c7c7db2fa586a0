// Exact 3D convex hull by randomised incremental insertion with outside sets (Clarkson–Shor
// insertion order, quickhull-style conflict bookkeeping). Every decision is the exact sign of
// orient3d, so coplanar and cospherical inputs (integer spheres, grids) are handled exactly.
//
// Invariant: every uninserted point that lies strictly outside the current hull H is stored in
// the outside set of exactly one face it sees. Inserting p: the faces p sees form a connected
// disk; they are replaced by the cone from p over the horizon. A point q of a removed face's
// outside set that sees no cone face lies in conv(H ∪ p): every point of the cone behind H lies
// below all faces visible from p, so q above a visible face and below the cone is inside.
// Expected O(n log n) for random order; the order comes from a pinned seed (deterministic).
#include "convex3/polytope_data.hpp"

#include <algorithm>
#include <random>

namespace pendepth::convex3 {

namespace {

struct Face {
  std::array<int, 3> v;
  std::array<int, 3> nb;  // nb[k]: face across edge (v[k], v[k+1])
  int head = -1;          // first point of the outside set
  int stamp = 0;
  bool alive = true;
};

}  // namespace

std::vector<std::array<int, 3>> incremental_hull(const std::vector<Vec3>& pts, std::vector<int> ids,
                                                 std::array<int, 4> seed) {
  using predicates::orient3d;
  const int N = static_cast<int>(pts.size());
  std::vector<Face> F;
  std::vector<int> next_pt(N, -1), face_of(N, -1), cone_start(N, -1);
  auto above = [&](int f, int p) {
    const auto& v = F[f].v;
    return orient3d(pts[v[0]], pts[v[1]], pts[v[2]], pts[p]) > 0;
  };

  auto [i0, i1, i2, i3] = seed;
  if (orient3d(pts[i0], pts[i1], pts[i2], pts[i3]) > 0) std::swap(i1, i2);
  const std::array<std::array<int, 3>, 4> tet{{{i0, i1, i2}, {i0, i3, i1}, {i1, i3, i2}, {i2, i3, i0}}};
  for (const auto& t : tet) F.push_back(Face{t, {-1, -1, -1}});
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k) {
      int a = F[f].v[k], b = F[f].v[(k + 1) % 3];
      for (int g = 0; g < 4; ++g)
        for (int l = 0; l < 3; ++l)
          if (F[g].v[l] == b && F[g].v[(l + 1) % 3] == a) F[f].nb[k] = g;
    }

  std::mt19937 rng(0x5eed3d);
  std::shuffle(ids.begin(), ids.end(), rng);
  auto assign = [&](int p, int first_face, int end_face) {
    for (int f = first_face; f < end_face; ++f)
      if (F[f].alive && above(f, p)) {
        face_of[p] = f;
        next_pt[p] = F[f].head;
        F[f].head = p;
        return;
      }
    face_of[p] = -1;
  };
  for (int p : ids)
    if (p != i0 && p != i1 && p != i2 && p != i3) assign(p, 0, 4);

  int stamp = 0;
  std::vector<int> visible, stack;
  for (int p : ids) {
    if (face_of[p] < 0) continue;
    ++stamp;
    visible.clear();
    stack.assign(1, face_of[p]);
    F[face_of[p]].stamp = stamp;
    while (!stack.empty()) {
      int f = stack.back();
      stack.pop_back();
      visible.push_back(f);
      for (int g : F[f].nb)
        if (F[g].stamp != stamp && above(g, p)) {
          F[g].stamp = stamp;
          stack.push_back(g);
        }
    }
    // Cone over the horizon: new face (a, b, p) for every horizon edge a -> b of a visible face.
    const int first_new = static_cast<int>(F.size());
    for (int f : visible)
      for (int k = 0; k < 3; ++k) {
        int g = F[f].nb[k];
        if (F[g].stamp == stamp) continue;
        int a = F[f].v[k], b = F[f].v[(k + 1) % 3];
        int nf = static_cast<int>(F.size());
        F.push_back(Face{{a, b, p}, {g, -1, -1}});
        for (int l = 0; l < 3; ++l)
          if (F[g].nb[l] == f) F[g].nb[l] = nf;
        cone_start[a] = nf;
      }
    const int end_new = static_cast<int>(F.size());
    for (int nf = first_new; nf < end_new; ++nf) {
      int b = F[nf].v[1];
      int succ = cone_start[b];  // the cone face whose horizon edge starts at b
      F[nf].nb[1] = succ;
      F[succ].nb[2] = nf;
    }
    for (int f : visible) {
      F[f].alive = false;
      for (int q = F[f].head; q >= 0;) {
        int nq = next_pt[q];
        if (q != p) assign(q, first_new, end_new);
        q = nq;
      }
      F[f].head = -1;
    }
    face_of[p] = -1;
  }

  std::vector<std::array<int, 3>> out;
  for (const auto& f : F)
    if (f.alive) out.push_back(f.v);
  return out;
}

bool build_twins(const std::vector<int>& fv, std::vector<int>& twin) {
  const int H = static_cast<int>(fv.size());
  std::vector<std::pair<std::uint64_t, int>> key(H);
  auto code = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
  for (int h = 0; h < H; ++h) key[h] = {code(fv[h], fv[DKLevel::next(h)]), h};
  std::sort(key.begin(), key.end());
  twin.assign(H, -1);
  for (int h = 0; h < H; ++h) {
    std::uint64_t want = code(fv[DKLevel::next(h)], fv[h]);
    auto it = std::lower_bound(key.begin(), key.end(), std::make_pair(want, -1));
    if (it == key.end() || it->first != want) return false;
    if (it + 1 != key.end() && (it + 1)->first == want) return false;
    twin[h] = it->second;
  }
  return true;
}

}  // namespace pendepth::convex3
