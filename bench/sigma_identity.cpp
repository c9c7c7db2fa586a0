// σ identity dump (scripts/sigma_identity.py): every field of pendepth::minimum_depth, in hex
// floats, over fixed sets of placements, so that two builds can be compared bit for bit (a change
// of the engine that must not change any answer: the hash of each set stays the same).
//
// Sets (fixed seeds; overlapping and not overlapping placements both dumped):
//  * hulls-S: the 60 real game hulls of ../shared/data/hulls, pairs (i, i + 7), Q rotated at
//    random about P's centroid and offset by up to 0.3 × P's radius per coordinate (as
//    bench_convex3's hulls_case), seeds S = 1, 2, 3, 3000 placements each;
//  * boxes: integer boxes against integer boxes, identity or quarter-turn rotations, integer
//    offsets: coplanar faces, parallel edges, touching and exact fits, several facets of M at σ;
//  * prisms: regular-ish integer prisms and bipyramids against boxes and each other, rotations
//    about the axes by quarter turns and random rotations, small and integer offsets;
//  * slivers: hulls flattened to 1e-9 against real hulls.
//   sigma_identity [SET]   (no argument: every set, one "# set NAME" line before each)
#include <pendepth/depth3.hpp>
#include <pendepth/io.hpp>
#include <pendepth/polytope.hpp>

#include "hulls3.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

using pendepth::ConvexPolytope;
using pendepth::Depth3;
using pendepth::Pose3;
using pendepth::Vec3;
using namespace pendepth::bench;  // hulls3.hpp: the shared hulls, draws and solids

namespace {

void dump(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq) {
  const Depth3 d = pendepth::minimum_depth(P, pp, Q, pq);
  std::printf("%d %d %a %a %a", int(d.overlapping), int(d.kind), d.depth, d.lower_bound, d.upper_bound);
  for (const Vec3* v : {&d.translation, &d.normal, &d.facet_normal, &d.witness_p, &d.witness_q})
    std::printf(" %a %a %a", (*v)[0], (*v)[1], (*v)[2]);
  std::printf(" %d %d %d %d %d %d %zu\n", int(d.feature_p.kind), d.feature_p.index, int(d.feature_q.kind),
              d.feature_q.index, d.piece_p, d.piece_q, std::size_t(d.candidates));
}

void hulls(unsigned seed) {
  static const std::vector<ConvexPolytope> H = shared_hulls();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  for (int k = 0; k < 3000; ++k) {
    const ConvexPolytope &P = H[k % H.size()], &Q = H[(k + 7) % H.size()];
    const Vec3 cp = centroid(P);
    double r = 0;
    for (const Vec3& v : P.vertices()) r = std::max(r, (v - cp).norm());
    const auto rot = random_rotation(rng);
    dump(P, Pose3(), Q, Pose3(rot, cp - rot.toRotationMatrix() * centroid(Q) + r * Vec3(U(rng), U(rng), U(rng))));
  }
}

// Quarter turns about the axes (exact rotation matrices) and a few generic rotations.
std::vector<Eigen::Quaterniond> rotations(std::mt19937_64& rng) {
  std::vector<Eigen::Quaterniond> r;
  const double h = std::sqrt(0.5);
  r.emplace_back(1, 0, 0, 0);
  r.emplace_back(h, h, 0, 0);
  r.emplace_back(h, 0, h, 0);
  r.emplace_back(h, 0, 0, h);
  r.emplace_back(0, 1, 0, 0);
  r.emplace_back(0.5, 0.5, 0.5, 0.5);
  for (int k = 0; k < 3; ++k) r.push_back(random_rotation(rng));
  return r;
}

void boxes() {
  std::mt19937_64 rng(7);
  const std::vector<ConvexPolytope> S = {box(1, 1, 1), box(2, 1, 1), box(3, 2, 1), box(1, 1, 0.5), box(2, 2, 2)};
  const auto R = rotations(rng);
  for (std::size_t a = 0; a < S.size(); ++a)
    for (std::size_t b = 0; b < S.size(); ++b)
      for (const auto& q : R)
        for (int x = -3; x <= 3; ++x)
          for (int y = -2; y <= 2; ++y)
            for (int z : {-2, 0, 1})
              dump(S[a], Pose3(), S[b], Pose3(q, Vec3(x, 0.5 * y, 0.5 * z)));
}

void prisms() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  const std::vector<ConvexPolytope> S = {prism(6, 10, 3), prism(8, 20, 5), bipyramid(12, 20, 7), box(5, 5, 5),
                                         bipyramid(5, 10, 10)};
  const auto R = rotations(rng);
  for (std::size_t a = 0; a < S.size(); ++a)
    for (std::size_t b = 0; b < S.size(); ++b)
      for (const auto& q : R)
        for (int k = 0; k < 24; ++k) {
          const Vec3 t = k < 12 ? Vec3(4.0 * Vec3(k % 3 - 1, (k / 3) % 2, k / 6)) : Vec3(6.0 * Vec3(U(rng), U(rng), U(rng)));
          dump(S[a], Pose3(), S[b], Pose3(q, t));
        }
}

void slivers() {
  static const std::vector<ConvexPolytope> H = shared_hulls();
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<ConvexPolytope> F;
  for (int k = 0; k < 10; ++k) {
    std::vector<Vec3> v;
    for (int i = 0; i < 40; ++i) v.emplace_back(U(rng), U(rng), 1e-9 * U(rng));
    F.push_back(ConvexPolytope::hull(v));
  }
  for (int k = 0; k < 600; ++k) {
    const ConvexPolytope &P = H[k % H.size()], &Q = F[k % F.size()];
    const Vec3 cp = centroid(P);
    dump(P, Pose3(), Q, Pose3(random_rotation(rng), cp + 0.2 * Vec3(U(rng), U(rng), U(rng))));
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::pair<std::string, std::function<void()>>> sets = {
      {"hulls-1", [] { hulls(1); }}, {"hulls-2", [] { hulls(2); }}, {"hulls-3", [] { hulls(3); }},
      {"boxes", boxes},             {"prisms", prisms},           {"slivers", slivers}};
  for (const auto& [name, run] : sets)
    if (argc < 2 || name == argv[1]) {
      std::printf("# set %s\n", name.c_str());
      run();
    }
  return 0;
}
