// Certified (1+δ)-approximate σ of two huge point sets (include/pendepth/approximate.hpp; survey
// §3.4–§4, Agarwal–Har-Peled–Varadarajan's ε-kernels; DHS §5 via minimum_depth on small hulls).
//
// Contract: lower ≤ σ ≤ upper = depth, upper ≤ (1+δ)·lower when converged. Proof sketch
// (docs/algorithms.md "Approximate σ"): kernels K ⊆ X give an inner Minkowski sum, hence
// σ(K) ≤ σ (lower); any direction u gives σ ≤ h_M(u)/|u| evaluated exactly on the full sets
// (upper). Refinement adds the full sets' extreme points where the kernels' sum is low.
//
// Steps: (1) validation, an exact affine basis per set (orient3d), the column-grid ε-kernel W of
// each set (O(n)); (2) rounds: exact σ of the kernels' hulls (minimum_depth), a batch of B
// directions (σ's normal and the kernels' facet normals with the lowest Minkowski support), their
// extreme points over W added to the kernels; (3) when W cannot improve the bound, the best
// direction is certified on the full sets (exact argmax: floating filter, exact tournament on the
// candidates; value by exact::accurate_value, rounded up); a failed certification adds the full
// sets' extreme points of the batch to W and the kernels. Separated kernels: a facet normal of the
// kernels' explicit Minkowski difference is tried as a separating direction, exactly.
// Pairs outside the magnitude band [2^-60, 2^60) run on copies scaled by a power of two.
// Complexity: O(n + m) + rounds·O((|W_P| + |W_Q|)·B + k log k) + scans·O(n + m).
#include <pendepth/approximate.hpp>
#include <pendepth/depth3.hpp>
#include <pendepth/polytope.hpp>

#include "geometry/exact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_set>
#include <vector>

namespace pendepth {
namespace {

using exact::accurate_value;
using exact::exact_sign;

constexpr double kU = 0x1p-53;
constexpr double kComfortHi = 0x1p60, kComfortLo = 0x1p-60;  // no rescaling inside this band
constexpr int kGridCoarse = 64;           // columns per axis of W (at most 6·G² points): δ ≥ 1e-2
constexpr int kGridFine = 128;            // δ < 1e-2 (W's error must stay well below δ·σ)
constexpr std::size_t kBatch = 32;        // directions per round at least (and per repair scan)
constexpr std::size_t kBatchMax = 512;    // at most: every kernel facet below the target, lowest first
constexpr std::size_t kMaxRounds = 400;
constexpr std::size_t kMaxFullScans = 64;
constexpr std::size_t kMaxDifferences = 1 << 18;  // explicit Minkowski difference (separated kernels)

struct Rel {  // as RelativePose in src/convex3/depth3.cpp: q' = R q + (tq − tp), doubles
  Eigen::Matrix3d Rp, R;
  Vec3 tq, tp, t;  // t = fl(tq − tp), for floating estimates only
};

struct Cloud {
  std::span<const Vec3> X;
  std::string name;
  Vec3 maxabs{0, 0, 0};       // per axis max |x_k| (bounds of the floating filters)
  std::vector<int> W, K;      // working set and kernel (indices into X)
  std::unordered_set<int> inW, inK;
  bool add_W(int i) { return inW.insert(i).second ? (W.push_back(i), true) : false; }
  bool add_K(int i) {
    add_W(i);
    return inK.insert(i).second ? (K.push_back(i), true) : false;
  }
};

void validate(Cloud& c) {
  if (c.X.empty()) throw InvalidInput(c.name + ": no points");
  for (std::size_t i = 0; i < c.X.size(); ++i) {
    const Vec3& x = c.X[i];
    if (!x.allFinite()) throw InvalidInput(c.name + ": point " + std::to_string(i) + " is not finite");
    for (int k = 0; k < 3; ++k) c.maxabs[k] = std::max(c.maxabs[k], std::abs(x[k]));
  }
}

// Four affinely independent points (exact predicates), or InvalidInput.
std::array<int, 4> affine_basis(const Cloud& c) {
  const auto& X = c.X;
  const int n = static_cast<int>(X.size());
  int b = -1, cc = -1, d = -1;
  for (int i = 1; i < n && b < 0; ++i)
    if (X[i] != X[0]) b = i;
  for (int i = 1; b >= 0 && i < n && cc < 0; ++i)
    if (!predicates::collinear3(X[0], X[b], X[i])) cc = i;
  for (int i = 1; cc >= 0 && i < n && d < 0; ++i)
    if (predicates::orient3d(X[0], X[b], X[cc], X[i]) != 0) d = i;
  if (d < 0) throw InvalidInput(c.name + ": flat input (fewer than 4 affinely independent points)");
  return {0, b, cc, d};
}

// The column-grid ε-kernel (AHV's simple kernel): per axis a, a G×G grid over the other two
// coordinates' bounding box; the top and bottom point (in coordinate a) of each column.
void column_kernel(Cloud& c, int G) {
  const auto& X = c.X;
  Vec3 lo = X[0], hi = X[0];
  for (const Vec3& x : X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const int GG = G * G;
  Vec3 scale;
  for (int k = 0; k < 3; ++k) {
    scale[k] = G / (hi[k] - lo[k]);  // an extent of 0 or a tiny one: every point in column 0
    if (!std::isfinite(scale[k])) scale[k] = 0;
  }
  auto cell = [&](double v, int k) { return std::clamp(static_cast<int>((v - lo[k]) * scale[k]), 0, G - 1); };
  // The columns' current extreme values are kept next to their indices (no random reads of X).
  std::vector<int> top(3 * GG, -1), bot(3 * GG, -1);
  std::vector<double> topv(3 * GG, -std::numeric_limits<double>::infinity()),
      botv(3 * GG, std::numeric_limits<double>::infinity());
  for (int i = 0; i < static_cast<int>(X.size()); ++i) {
    const Vec3& x = X[i];
    const int cx = cell(x[0], 0), cy = cell(x[1], 1), cz = cell(x[2], 2);
    const int col[3] = {cy * G + cz, GG + cz * G + cx, 2 * GG + cx * G + cy};
    for (int a = 0; a < 3; ++a) {
      const int k = col[a];
      if (x[a] > topv[k]) topv[k] = x[a], top[k] = i;
      if (x[a] < botv[k]) botv[k] = x[a], bot[k] = i;
    }
  }
  for (int k = 0; k < 3 * GG; ++k)
    if (top[k] >= 0) c.add_W(top[k]), c.add_W(bot[k]);
}

// Floating argmax of dirs[j]·x over the index set S (nullptr: all of X). Directions in separate
// coordinate arrays and a branch-free update, so the inner loop vectorises.
void scan_max(const Cloud& c, const std::vector<int>* S, const std::vector<Vec3>& dirs, std::vector<int>& arg) {
  const std::size_t B = dirs.size();
  std::vector<double> dx(B), dy(B), dz(B), best(B, -std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> at(B, -1);
  for (std::size_t j = 0; j < B; ++j) dx[j] = dirs[j].x(), dy[j] = dirs[j].y(), dz[j] = dirs[j].z();
  auto visit = [&](std::int64_t i) {
    const double x = c.X[i].x(), y = c.X[i].y(), z = c.X[i].z();
    double* __restrict bp = best.data();
    std::int64_t* __restrict ap = at.data();
    const double *__restrict px = dx.data(), *__restrict py = dy.data(), *__restrict pz = dz.data();
    for (std::size_t j = 0; j < B; ++j) {
      const double f = px[j] * x + py[j] * y + pz[j] * z;
      const bool better = f > bp[j];
      bp[j] = better ? f : bp[j];
      ap[j] = better ? i : ap[j];
    }
  };
  if (S)
    for (int i : *S) visit(i);
  else
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(c.X.size()); ++i) visit(i);
  arg.assign(B, -1);
  for (std::size_t j = 0; j < B; ++j) arg[j] = static_cast<int>(at[j]);
}

// The exact maximiser over S (nullptr: X) of φ(x), where w·x approximates φ(x) within `err` and
// better(a, b) is the exact sign of φ(a) − φ(b): floating pass, candidates within 2·err of the
// floating maximum, exact tournament among them.
template <class Better>
int exact_argmax(const Cloud& c, const std::vector<int>* S, const Vec3& w, double err, Better&& better) {
  const int n = S ? static_cast<int>(S->size()) : static_cast<int>(c.X.size());
  auto id = [&](int k) { return S ? (*S)[k] : k; };
  double fmax = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) fmax = std::max(fmax, w.dot(c.X[id(k)]));
  const double cut = fmax - 2 * err;
  int best = -1;
  for (int k = 0; k < n; ++k) {
    const int i = id(k);
    if (w.dot(c.X[i]) < cut) continue;
    if (best < 0 || better(i, best) > 0) best = i;
  }
  return best;
}

// Exact support points of P (max u·p) and Q (min u·(R q)) for u in P's frame, and the certified
// upper bound h_M(u)/|u| (0 when h_M(u) ≤ 0 exactly).
struct Certified {
  int p = -1, q = -1;
  double upper = std::numeric_limits<double>::infinity();
  bool separates = false;  // h_M(u) ≤ 0 exactly
};

Certified certify(const Cloud& P, const std::vector<int>* SP, const Cloud& Q, const std::vector<int>* SQ,
                  const Rel& rel, const Vec3& u) {
  const auto& R = rel.R;
  const double ep = 3.02 * kU * (std::abs(u.x()) * P.maxabs.x() + std::abs(u.y()) * P.maxabs.y() +
                                 std::abs(u.z()) * P.maxabs.z()) + 0x1p-1000;
  const Vec3 w = -(R.transpose() * u);
  double eq = 0x1p-1000;
  for (int l = 0; l < 3; ++l) {
    double ew = 0;
    for (int k = 0; k < 3; ++k) ew += std::abs(R(k, l)) * std::abs(u[k]);
    eq += (3.02 * kU * ew) * Q.maxabs[l] * 1.01 + 3.02 * kU * std::abs(w[l]) * Q.maxabs[l];
  }
  Certified r;
  r.p = exact_argmax(P, SP, u, ep, [&](int a, int b) { return predicates::dot3_sign(u, P.X[a], P.X[b]); });
  r.q = exact_argmax(Q, SQ, w, eq, [&](int a, int b) {
    const Vec3 &qa = Q.X[a], &qb = Q.X[b];
    return exact_sign([&](auto L) {  // −u·R(qa − qb)
      auto s = L(0.0);
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) s = s - L(u[k]) * L(R(k, l)) * (L(qa[l]) - L(qb[l]));
      return s;
    });
  });
  const Vec3 &p = P.X[r.p], &q = Q.X[r.q];
  auto h = [&](auto L) {  // u·p − u·(R q + tq − tp)
    auto s = L(0.0);
    for (int k = 0; k < 3; ++k) {
      auto rq = L(R(k, 0)) * L(q[0]) + L(R(k, 1)) * L(q[1]) + L(R(k, 2)) * L(q[2]);
      s = s + L(u[k]) * (L(p[k]) - rq - L(rel.tq[k]) + L(rel.tp[k]));
    }
    return s;
  };
  if (exact_sign(h) <= 0) {
    r.separates = true;
    r.upper = 0;
    return r;
  }
  const double v = accurate_value(h) * (1 + 0x1p-50);  // ≥ h_M(u): accurate to ~1 ulp
  const double norm_lo = std::sqrt(u.squaredNorm()) * (1 - 0x1p-50);
  r.upper = v / norm_lo * (1 + 0x1p-50);
  return r;
}

ConvexPolytope kernel_hull(Cloud& c) {
  std::vector<Vec3> pts;
  pts.reserve(c.K.size());
  for (int i : c.K) pts.push_back(c.X[i]);
  ConvexPolytope H = ConvexPolytope::hull(pts, c.name);  // K holds an affine basis: never flat
  std::vector<int> keep;
  keep.reserve(H.size());
  for (std::size_t v = 0; v < H.size(); ++v) keep.push_back(c.K[H.input_index(v)]);
  c.K = std::move(keep);  // the hull's vertices (interior points never matter again)
  return H;
}

double est_h(const Rel& rel, const Vec3& u, const Vec3& p, const Vec3& q) {  // floating h_M(u)/|u|
  return (u.dot(p) - u.dot(rel.R * q + rel.t)) / u.norm();
}

}  // namespace

namespace {

ApproxDepth3 approximate_in_band(std::span<const Vec3> P_points, const Pose3& pose_p, std::span<const Vec3> Q_points,
                                 const Pose3& pose_q, double delta) {
  Rel rel;
  rel.Rp = pose_p.matrix();
  rel.R = rel.Rp.transpose() * pose_q.matrix();
  rel.tq = rel.Rp.transpose() * pose_q.translation;
  rel.tp = rel.Rp.transpose() * pose_p.translation;
  rel.t = rel.tq - rel.tp;

  Cloud P, Q;
  P.X = P_points, P.name = "P", Q.X = Q_points, Q.name = "Q";
  validate(P), validate(Q);
  for (Cloud* c : {&P, &Q}) {
    for (int i : affine_basis(*c)) c->add_K(i);
    const int G = delta < 1e-2 ? kGridFine : kGridCoarse;
    if (c->X.size() <= 6u * G * G) {
      for (int i = 0; i < static_cast<int>(c->X.size()); ++i) c->add_W(i);
    } else {
      column_kernel(*c, G);
    }
    // Initial kernel: W's extreme points in the 26 directions of the cube's faces, edges, corners.
    std::vector<Vec3> dirs;
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z)
          if (x || y || z) dirs.emplace_back(x, y, z);
    std::vector<int> arg;
    scan_max(*c, &c->W, dirs, arg);
    for (int i : arg) c->add_K(i);
  }
  const bool w_is_all = P.W.size() == P.X.size() && Q.W.size() == Q.X.size();

  ApproxDepth3 out;
  double lower = 0, upper = std::numeric_limits<double>::infinity();
  Vec3 best_u = Vec3::Zero();  // P's frame, the direction of `upper`
  std::set<std::tuple<int, int, int, int>> scanned;  // facets whose normals were already scanned on W
  std::map<std::tuple<int, int, int, int>, double> hcache;  // facets' floating Minkowski supports
  std::size_t full_scans = 0;
  double best_estimate = std::numeric_limits<double>::infinity();  // lowest floating h over W
  bool done = false;

  auto full_certify = [&](const Vec3& u) {
    ++full_scans;
    Certified c = certify(P, nullptr, Q, nullptr, rel, u);
    if (c.upper < upper) upper = c.upper, best_u = u;
    return c;
  };
  // Repairs W where it is too coarse: the full sets' extreme points for `dirs` (P's frame).
  auto repair = [&](const std::vector<Vec3>& dirs) {
    ++full_scans;
    std::vector<Vec3> dq;
    for (const Vec3& u : dirs) dq.push_back(-(rel.R.transpose() * u));
    std::vector<int> ap, aq;
    scan_max(P, nullptr, dirs, ap), scan_max(Q, nullptr, dq, aq);
    bool grew = false;
    for (int i : ap) grew |= P.add_K(i);
    for (int i : aq) grew |= Q.add_K(i);
    return grew;
  };

  std::size_t round = 0;
  for (; round < kMaxRounds && !done && full_scans < kMaxFullScans; ++round) {
    ConvexPolytope HP = kernel_hull(P), HQ = kernel_hull(Q);
    const Depth3 s = minimum_depth(HP, pose_p, HQ, pose_q);

    if (!s.overlapping) {
      // Separated (or touching) kernels: a facet of their explicit Minkowski difference whose
      // plane has 0 outside (or on it) is a candidate separating direction of the full sets.
      lower = 0;
      if (HP.size() * HQ.size() > kMaxDifferences) break;
      std::vector<Vec3> diff;
      for (const Vec3& p : HP.vertices())
        for (const Vec3& q : HQ.vertices()) diff.push_back(p - (rel.R * q + rel.t));
      Vec3 u = Vec3::Zero();
      try {
        ConvexPolytope D = ConvexPolytope::hull(diff, "kernels' Minkowski difference");
        double most = std::numeric_limits<double>::infinity();
        for (const auto& t : D.triangles()) {
          Vec3 n = (D[t[1]] - D[t[0]]).cross(D[t[2]] - D[t[0]]);
          const double len = n.norm();
          if (!(len > 0)) continue;
          const double off = n.dot(D[t[0]]) / len;
          if (off < most) most = off, u = n;
        }
      } catch (const InvalidInput&) {  // rounded differences flat: no candidate
      }
      if (u == Vec3::Zero()) break;
      const Certified cw = certify(P, &P.W, Q, &Q.W, rel, u);
      if (!cw.separates) {
        if (!(P.add_K(cw.p) | Q.add_K(cw.q))) {  // the kernels themselves are not separated by u
          full_certify(u);
          break;
        }
        continue;
      }
      const Certified cx = w_is_all ? cw : full_certify(u);
      if (w_is_all) ++full_scans, upper = 0, best_u = u;
      if (cx.separates) {
        done = true;
        break;
      }
      P.add_K(cx.p), Q.add_K(cx.q);
      continue;
    }

    lower = s.lower_bound * (1 - 0x1p-48);  // σ of the kernels, a few ulps from exact: rounded down
    const Vec3 u0 = rel.Rp.transpose() * s.normal;
    // Candidate directions: σ's normal, then the kernels' facet normals by their (floating)
    // Minkowski support, lowest first, skipping facets already scanned.
    struct Cand {
      double h;
      Vec3 u;
      std::tuple<int, int, int, int> key;
    };
    // A facet's Minkowski support only grows as the other kernel grows, so a cached value below
    // which the facet is not needed stays valid: only new or low facets are re-evaluated.
    std::vector<Cand> cands;
    const double target_old = best_estimate / (1 + delta);
    auto consider = [&](const std::tuple<int, int, int, int>& key, const Vec3& u, auto&& eval) {
      if (scanned.count(key)) return;
      auto it = hcache.find(key);
      if (it != hcache.end() && !(it->second < target_old)) {
        cands.push_back({it->second, u, key});
        return;
      }
      const double h = eval();
      hcache[key] = h;
      cands.push_back({h, u, key});
    };
    for (const auto& t : HP.triangles()) {
      Vec3 n = (HP[t[1]] - HP[t[0]]).cross(HP[t[2]] - HP[t[0]]);
      if (!(n.squaredNorm() > 0)) continue;
      std::array<int, 3> k{P.K[t[0]], P.K[t[1]], P.K[t[2]]};
      std::sort(k.begin(), k.end());
      consider({0, k[0], k[1], k[2]}, n, [&] {
        return est_h(rel, n, HP[t[0]], HQ[HQ.support(-(rel.R.transpose() * n))]);
      });
    }
    for (const auto& t : HQ.triangles()) {
      Vec3 m = (HQ[t[1]] - HQ[t[0]]).cross(HQ[t[2]] - HQ[t[0]]);
      if (!(m.squaredNorm() > 0)) continue;
      const Vec3 u = -(rel.R * m);
      std::array<int, 3> k{Q.K[t[0]], Q.K[t[1]], Q.K[t[2]]};
      std::sort(k.begin(), k.end());
      consider({1, k[0], k[1], k[2]}, u, [&] { return est_h(rel, u, HP[HP.support(u)], HQ[t[0]]); });
    }
    std::sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& b) { return a.h < b.h; });
    // Every facet below the target lower bound needs refining: take them all (up to kBatchMax).
    const double target = best_estimate / (1 + delta);
    std::vector<Vec3> dirs{u0};
    for (const Cand& c : cands) {
      if (dirs.size() >= kBatchMax || (dirs.size() >= kBatch && !(c.h < target))) break;
      scanned.insert(c.key);
      dirs.push_back(c.u);
    }
    // Extreme points over W.
    std::vector<Vec3> dq;
    for (const Vec3& u : dirs) dq.push_back(-(rel.R.transpose() * u));
    std::vector<int> ap, aq;
    scan_max(P, &P.W, dirs, ap), scan_max(Q, &Q.W, dq, aq);
    bool grew = false;
    std::size_t best = 0;
    double best_h = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < dirs.size(); ++j) {
      grew |= P.add_K(ap[j]);
      grew |= Q.add_K(aq[j]);
      const double h = est_h(rel, dirs[j], P.X[ap[j]], Q.X[aq[j]]);
      if (h < best_h) best_h = h, best = j;
    }
    best_estimate = std::min(best_estimate, best_h);
    // Certify on the full sets when W's bound is good enough or W cannot improve any further.
    if (best_h <= (1 + delta) * lower || !grew) {
      const Certified c = full_certify(dirs[best]);
      if (upper <= (1 + delta) * lower) {
        done = true;
        break;
      }
      if (w_is_all) {
        if (!grew) break;  // nothing left to add: stuck at the rounding level
        continue;
      }
      const bool added = (P.add_K(c.p) | Q.add_K(c.q));
      dirs.resize(std::min(dirs.size(), kBatch));
      if (!repair(dirs) && !added && !grew) break;
    }
  }
  if (!done && !(upper < std::numeric_limits<double>::infinity()) && full_scans < kMaxFullScans + 8) {
    // Always return a certified upper bound: the kernels' last σ direction, or an axis.
    ConvexPolytope HP = kernel_hull(P), HQ = kernel_hull(Q);
    const Depth3 s = minimum_depth(HP, pose_p, HQ, pose_q);
    full_certify(s.overlapping ? Vec3(rel.Rp.transpose() * s.normal) : Vec3(1, 0, 0));
  }

  out.lower_bound = lower;
  out.upper_bound = out.depth = upper;
  out.converged = done;
  out.overlapping = upper > 0;
  if (best_u != Vec3::Zero()) {
    out.normal = rel.Rp * best_u.normalized();
    out.translation = out.depth * out.normal;
  }
  out.kernel_p = P.K.size(), out.kernel_q = Q.K.size();
  out.working_p = P.W.size(), out.working_q = Q.W.size();
  out.rounds = round;
  out.full_scans = full_scans;
  return out;
}

}  // namespace

// The numeric domain (as src/front/scale.hpp, without a hull to measure edges): inputs whose
// largest magnitude lies outside [2^-60, 2^60) are answered on copies scaled by 2^-e (e its binary
// exponent), and lengths scaled back; a coordinate that scaling would round is InvalidInput.
ApproxDepth3 approximate_minimum_depth(std::span<const Vec3> P_points, const Pose3& pose_p,
                                       std::span<const Vec3> Q_points, const Pose3& pose_q, double delta) {
  if (!(delta >= 1e-9 && delta < 1))
    throw InvalidInput("approximate depth: delta must lie in [1e-9, 1), got " + std::to_string(delta));
  if (!pose_p.translation.allFinite()) throw InvalidInput("pose of P: non-finite translation");
  if (!pose_q.translation.allFinite()) throw InvalidInput("pose of Q: non-finite translation");
  if (P_points.size() > std::size_t(std::numeric_limits<int>::max()) || Q_points.size() > std::size_t(std::numeric_limits<int>::max()))
    throw InvalidInput("approximate depth: more than 2^31 - 1 points in one set");
  double largest = std::max(pose_p.translation.cwiseAbs().maxCoeff(), pose_q.translation.cwiseAbs().maxCoeff());
  for (auto [X, name] : {std::pair{P_points, "P"}, std::pair{Q_points, "Q"}})
    for (std::size_t i = 0; i < X.size(); ++i) {
      if (!X[i].allFinite()) throw InvalidInput(std::string(name) + ": point " + std::to_string(i) + " is not finite");
      largest = std::max(largest, X[i].cwiseAbs().maxCoeff());
    }
  if (largest == 0 || (largest >= kComfortLo && largest < kComfortHi))
    return approximate_in_band(P_points, pose_p, Q_points, pose_q, delta);
  const int e = std::ilogb(largest);
  auto down = [&](const Vec3& x, const char* what, std::size_t i) {
    Vec3 y;
    for (int k = 0; k < 3; ++k) {
      y[k] = std::ldexp(x[k], -e);
      if (std::ldexp(y[k], e) != x[k])
        throw InvalidInput(std::string("approximate depth: ") + what + (i == std::size_t(-1) ? "" : " " + std::to_string(i)) +
                           " has no exact value at the pair's scale 2^" + std::to_string(e) +
                           " (its sizes span too many orders of magnitude)");
    }
    return y;
  };
  std::vector<Vec3> Ps(P_points.size()), Qs(Q_points.size());
  for (std::size_t i = 0; i < Ps.size(); ++i) Ps[i] = down(P_points[i], "P point", i);
  for (std::size_t i = 0; i < Qs.size(); ++i) Qs[i] = down(Q_points[i], "Q point", i);
  const Pose3 pp(pose_p.rotation, down(pose_p.translation, "the translation of P", std::size_t(-1))),
      pq(pose_q.rotation, down(pose_q.translation, "the translation of Q", std::size_t(-1)));
  ApproxDepth3 r = approximate_in_band(Ps, pp, Qs, pq, delta);
  r.depth = std::ldexp(r.depth, e), r.lower_bound = std::ldexp(r.lower_bound, e), r.upper_bound = std::ldexp(r.upper_bound, e);
  for (int k = 0; k < 3; ++k) r.translation[k] = std::ldexp(r.translation[k], e);
  return r;
}

}  // namespace pendepth
