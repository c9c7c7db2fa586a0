// Signed-distance identity dump (scripts/sigma_identity.py BUILD/bin/distance_identity --check
// scripts/distance_identity.sha256): every field of pendepth::signed_distance (convex polytopes,
// 3D), in hex floats, over fixed sets of placements, so that two builds can be compared bit for
// bit (a change of the engine that must not change any answer keeps the hash of each set).
//
// Sets (fixed seeds; apart, touching and overlapping placements all dumped):
//  * bench: the placements of bench_convex3's `distance/…/hulls` (namespace sdist: the 60 real
//    game hulls, pairs (i, i + 7), same generator and seed), every attempt dumped — its 960
//    apart placements and the overlapping ones it skips;
//  * hulls-S: the real hulls, pairs (i, i + 7) and (i, i + 13), Q at P's centroid +
//    (r_P + r_Q)·U(0.3, 1.6) in a random direction, P posed too (random rotation half of the
//    time); one placement in five with Q rotated by a quarter turn only (axis-aligned faces of
//    both shapes parallel: coplanar support polygons); seeds S = 1, 2, 3000 placements each;
//  * boxes: integer boxes against integer boxes, quarter turns and generic rotations, integer and
//    half-integer offsets: touching, parallel faces and edges, edge–edge closest pairs;
//  * prisms: integer prisms and bipyramids against each other and boxes, quarter turns and
//    random rotations, offsets up to 40.
//   distance_identity [SET]   (no argument: every set, one "# set NAME" line before each)
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
using pendepth::Distance3;
using pendepth::Pose3;
using pendepth::Vec3;
using namespace pendepth::bench;  // hulls3.hpp: the shared hulls, draws and solids

namespace {

Distance3 dump(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq) {
  const Distance3 d = pendepth::signed_distance(P, pp, Q, pq);
  std::printf("%d %a %a %a", int(d.overlapping), d.distance, d.lower_bound, d.upper_bound);
  for (const Vec3* v : {&d.translation, &d.normal, &d.witness_p, &d.witness_q})
    std::printf(" %a %a %a", (*v)[0], (*v)[1], (*v)[2]);
  std::printf(" %d %d %d %d %d %d\n", int(d.feature_p.kind), d.feature_p.index, int(d.feature_q.kind),
              d.feature_q.index, d.piece_p, d.piece_q);
  return d;
}

// bench_convex3's sdist::dist_case, the cast draws included (they move the generator).
void bench() {
  static const std::vector<ConvexPolytope> H = shared_hulls();
  std::mt19937_64 rng(0xd157);
  std::uniform_real_distribution<double> U(0.6, 1.6);
  const std::size_t want = 16 * H.size();
  std::size_t attempts = 0, apart = 0;
  while (apart < want && attempts++ < 100 * want) {
    const int pair = int(attempts % H.size());
    const ConvexPolytope &P = H[pair], &Q = H[(pair + 7) % H.size()];
    const auto rot = random_rotation(rng);
    Vec3 dir = random_in_ball(rng, 1.0);
    if (dir.norm() < 1e-3) continue;
    const Pose3 pose(rot, centroid(P) - rot.toRotationMatrix() * centroid(Q) +
                              (radius(P) + radius(Q)) * U(rng) * dir.normalized());
    const Distance3 d = dump(P, Pose3(), Q, pose);
    if (!(d.distance > 0)) continue;
    const Vec3 cd = (centroid(P) - pose.translation).normalized() + 0.5 * random_in_ball(rng, 1.0);
    if (cd.norm() < 1e-3) continue;
    ++apart;
  }
}

Eigen::Quaterniond quarter_turn(std::mt19937_64& rng) {
  const double h = std::sqrt(0.5);
  const Eigen::Quaterniond q[] = {{1, 0, 0, 0}, {h, h, 0, 0}, {h, 0, h, 0}, {h, 0, 0, h}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  return q[std::uniform_int_distribution<int>(0, 5)(rng)];
}

void hulls(unsigned seed) {
  static const std::vector<ConvexPolytope> H = shared_hulls();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.3, 1.6);
  for (int k = 0; k < 3000; ++k) {
    const ConvexPolytope &P = H[k % H.size()], &Q = H[(k + (k % 2 ? 13 : 7)) % H.size()];
    const bool axis = k % 5 == 0;
    const Eigen::Quaterniond rq = axis ? quarter_turn(rng) : random_rotation(rng);
    const Eigen::Quaterniond rp = k % 2 && !axis ? random_rotation(rng) : Eigen::Quaterniond::Identity();
    const Vec3 tp = k % 2 ? random_in_ball(rng, 2.0) : Vec3::Zero();
    const Vec3 dir = random_in_ball(rng, 1.0);
    if (dir.norm() < 1e-3) continue;
    const Vec3 cp = rp.toRotationMatrix() * centroid(P) + tp;
    const Pose3 pq(rq, cp - rq.toRotationMatrix() * centroid(Q) + (radius(P) + radius(Q)) * U(rng) * dir.normalized());
    dump(P, Pose3(rp, tp), Q, pq);
  }
}

std::vector<Eigen::Quaterniond> rotations(std::mt19937_64& rng) {
  std::vector<Eigen::Quaterniond> r;
  const double h = std::sqrt(0.5);
  r.emplace_back(1, 0, 0, 0);
  r.emplace_back(h, h, 0, 0);
  r.emplace_back(h, 0, 0, h);
  r.emplace_back(0.5, 0.5, 0.5, 0.5);
  for (int k = 0; k < 2; ++k) r.push_back(random_rotation(rng));
  return r;
}

void boxes() {
  std::mt19937_64 rng(7);
  const std::vector<ConvexPolytope> S = {box(1, 1, 1), box(2, 1, 1), box(3, 2, 1), box(1, 1, 0.5)};
  const auto R = rotations(rng);
  for (std::size_t a = 0; a < S.size(); ++a)
    for (std::size_t b = 0; b < S.size(); ++b)
      for (const auto& q : R)
        for (int x = -6; x <= 6; x += 2)
          for (int y = -2; y <= 4; y += 3)
            for (int z : {-3, 0, 2, 5})
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
          const Vec3 t = k < 12 ? Vec3(20.0 * Vec3(k % 3 - 1, (k / 3) % 2, k / 6)) : Vec3(40.0 * Vec3(U(rng), U(rng), U(rng)));
          dump(S[a], Pose3(), S[b], Pose3(q, t));
        }
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::pair<std::string, std::function<void()>>> sets = {
      {"bench", bench}, {"hulls-1", [] { hulls(1); }}, {"hulls-2", [] { hulls(2); }},
      {"boxes", boxes}, {"prisms", prisms}};
  for (const auto& [name, run] : sets)
    if (argc < 2 || name == argv[1]) {
      std::printf("# set %s\n", name.c_str());
      run();
    }
  return 0;
}
