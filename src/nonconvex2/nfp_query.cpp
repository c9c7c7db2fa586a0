// The per-pair no-fit polygon, queries (issue 5 item 4; fast path issue 19 item 1): σ_d and σ on
// the stored pieces of ∂O (nfp_build.cpp), the overlap test on the rings and the pair sums.
//
// overlapping(t): the certified floating parity test on the rings, slits and points
//   (nfp_fast.cpp); where it cannot decide (t on or ulps from ∂O, level with a ring vertex), the
//   exact pair-sum test of PairDepth2 (dual descent to the sums whose box holds t), which is
//   symbolic exactly where parity is ambiguous (slits, isolated points, rays through vertices).
// along(t, d), t ∈ O: the component of the line inside O containing t ends at the first point of
//   ∂O hit by the ray (pieces are closed subsets of ℝ² \ O and every exit point lies on one), so
//   σ_d = min over pieces of the first λ > 0 where the ray meets the closed piece. Up to 256
//   pieces, the floating scan names the pieces that can be hit first (nfp_fast.cpp) and only those
//   are tested exactly; beyond, best-first traversal of the piece hierarchy by conservative box
//   entry λ. Hits are compared exactly (the crossing with the piece's line, or its nearer end
//   when the ray runs along it); equal hits go to the lowest piece index.
// minimum(t), t ∈ O: σ = min over pieces of the exact distance from t to the closed piece; the
//   floating scan's candidates (up to 256 pieces) or branch and bound on the hierarchy with
//   conservative box distances; exact comparisons of squared distances (edge_cut.hpp, the same
//   candidates as PairDepth2::minimum); equally near pieces go to the lowest index. On the fast
//   path two projections on pieces of one exact line are a tie by NfpFlat's line table
//   (nfp_lines.cpp) instead of same_point's exact collinearity test.
// On the fast path the candidates come first: a sole candidate whose interior holds t's nearest
// point (the ray's first) with O's side towards t proves t ∈ O (NfpFlat::inside_by_candidates),
// and so for σ do candidates all meeting at a reflex vertex of O that is t's nearest point
// (NfpFlat::inside_by_nearest; proofs in nfp_fast.cpp): the overlap test is skipped; otherwise it
// runs as above.
// Both ways every piece that can win is compared exactly, so the fast and the exact path (the
// `exact_path` flag, kept for the tests) pick the same piece. The winner's values are RN of the
// exact reals (geometry/rounded.hpp): σ² and the translation at a projection, λ at a crossing from
// the piece's double-doubles (nfp_value.cpp), σ at a sum vertex or at a cut end (a reflex vertex
// of O) from the per-piece tables built with the no-fit polygon, other kinds from the generic double-double tier,
// each only when certified inside one rounding cell, else rationals — the exact path uses the
// rationals alone, so the two agree bit for bit exactly when the certificates are right. Results go through
// PairDepth2::Impl::contact, so kinds, features and witnesses follow depth2_polygon_polygon.hpp.
// Cost per query: O(N) flops and O(1) exact evaluations on real pieces, O(log N + k) node visits
// for N > 256 pieces and k boxes near the answer (worst case O(N)), plus the overlap test.
#include <cmath>
#include <limits>
#include <queue>

#include "geometry/exact.hpp"
#include "geometry/rounded.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "nonconvex2/query.hpp"

namespace pendepth {

using exact::exact_sign;
using nonconvex2::Cand;
using nonconvex2::Line;
using nonconvex2::NfpFlat;
using nonconvex2::NfpPiece;
using nonconvex2::Param;
using nonconvex2::Ray;

namespace {

// The ray's first point on a piece: the crossing with the piece's line, or (ray along the line)
// the end `at` of the piece.
struct Hit {
  const NfpPiece* piece = nullptr;
  bool end = false;
  Param at;
};

// λ of the hit on the query ray (t + λ·d) as num / den.
template <class L>
auto hit_nd(const Hit& h, const Ray& ray, const Vec2& t, L lift) {
  using T = decltype(lift(0.0));
  if (!h.end) return std::pair<T, T>{nonconvex2::line_num(h.piece->edge, ray, lift), nonconvex2::line_den(h.piece->edge, ray, lift)};
  const Ray& E = h.piece->E;
  auto [n, dd] = nonconvex2::param_nd(h.at, E, t, lift);
  auto dx = lift(ray.a1.x()), dy = lift(ray.a1.y());
  auto ox = lift(E.o1.x()) + lift(E.o2.x()) - lift(t.x()), oy = lift(E.o1.y()) + lift(E.o2.y()) - lift(t.y());
  auto ddot = nonconvex2::ray_dx(E, lift) * dx + nonconvex2::ray_dy(E, lift) * dy;
  return std::pair<T, T>{(ox * dx + oy * dy) * dd + n * ddot, dd * (dx * dx + dy * dy)};
}

int compare_hits(const Hit& a, const Hit& b, const Ray& ray, const Vec2& t) {
  if (!a.end && !b.end) return nonconvex2::compare_lines(a.piece->edge, b.piece->edge, ray);
  const int sa = exact_sign([&](auto L) { return hit_nd(a, ray, t, L).second; });
  const int sb = exact_sign([&](auto L) { return hit_nd(b, ray, t, L).second; });
  return sa * sb * exact_sign([&](auto L) {
           auto [na, da] = hit_nd(a, ray, t, L);
           auto [nb, db] = hit_nd(b, ray, t, L);
           return na * db - nb * da;
         });
}

// Side of the point at parameter p of E relative to the query line: sign of cross(d, X − t).
int side_of(const Param& p, const Ray& E, const Vec2& t, const Vec2& d) {
  const int s = exact_sign([&](auto L) {
    auto [n, dd] = nonconvex2::param_nd(p, E, t, L);
    auto x = (L(E.o1.x()) + L(E.o2.x()) - L(t.x())) * dd + n * nonconvex2::ray_dx(E, L);
    auto y = (L(E.o1.y()) + L(E.o2.y()) - L(t.y())) * dd + n * nonconvex2::ray_dy(E, L);
    return L(d.x()) * y - L(d.y()) * x;
  });
  return s * exact_sign([&](auto L) { return nonconvex2::param_nd(p, E, t, L).second; });
}

// The ray's first point on the closed piece at λ > 0 (t ∈ O is on no piece), if any.
bool first_hit(const NfpPiece& pc, const Ray& ray, const Vec2& t, const Vec2& d, Hit& out) {
  const int den = exact_sign([&](auto L) { return nonconvex2::line_den(pc.edge, ray, L); });
  if (den != 0) {
    if (nonconvex2::line_sign(pc.edge, ray) <= 0) return false;
    if (side_of(pc.lo, pc.E, t, d) * side_of(pc.hi, pc.E, t, d) > 0) return false;
    out = Hit{&pc, false, {}};
    return true;
  }
  if (exact_sign([&](auto L) { return nonconvex2::line_num(pc.edge, ray, L); }) != 0) return false;  // parallel, apart
  // Along the piece's line: the nearer end with λ > 0 (both ends lie on one side of t).
  Hit h0{&pc, true, pc.lo}, h1{&pc, true, pc.hi};
  const Hit& nearer = compare_hits(h0, h1, ray, t) <= 0 ? h0 : h1;
  const int s = exact_sign([&](auto L) {
    auto [n, dd] = hit_nd(nearer, ray, t, L);
    return n * dd;
  });
  if (s <= 0) return false;
  out = nearer;
  return true;
}

double box_distance(const Vec2& t, const Vec2& lo, const Vec2& hi) {
  const double dx = std::max({lo.x() - t.x(), 0.0, t.x() - hi.x()}), dy = std::max({lo.y() - t.y(), 0.0, t.y() - hi.y()});
  return std::hypot(dx, dy) * (1 - 0x1p-40);
}

}  // namespace

bool NoFitPolygon2::Impl::overlapping_exact(const Vec2& t) const {
  return S.descend(
      [&](const Vec2& lo, const Vec2& hi) { return lo.x() <= t.x() && t.x() <= hi.x() && lo.y() <= t.y() && t.y() <= hi.y(); },
      [&](std::uint32_t i, std::uint32_t j) { return nonconvex2::sum_contains(nonconvex2::make_sum(S.tp[i], S.tb[j]), t); },
      nullptr);
}

bool NoFitPolygon2::Impl::overlapping(const Vec2& t) const {
  if (flat.overlap_usable) {
    const int f = flat.overlapping(t);
    if (f >= 0) return f == 1;
  }
  return overlapping_exact(t);
}

namespace {

// Scratch for the fast path's candidate lists (no allocation per query).
std::vector<std::uint32_t>& scratch() {
  thread_local std::vector<std::uint32_t> v;
  v.clear();
  return v;
}

// σ_d's running best: the exact first hit, ties to the lowest piece index.
struct AlongBest {
  Hit hit;
  std::uint32_t index = 0;
  bool found = false;
  // `crosses`: certified by the fast path (NfpFlat::kInside), so first_hit's answer is known.
  void consider(const NoFitPolygon2::Impl& N, std::uint32_t k, const Ray& ray, const Vec2& t, const Vec2& d, bool crosses = false) {
    Hit h;
    if (crosses) h = Hit{&N.pieces[k], false, {}};
    else if (!first_hit(N.pieces[k], ray, t, d, h)) return;
    if (found) {
      // Two crossings of one geometric line are the same point (λ equal).
      const int c = !h.end && !hit.end && collinear(h.piece->edge, hit.piece->edge) ? 0 : compare_hits(h, hit, ray, t);
      if (c > 0 || (c == 0 && k > index)) return;
    }
    hit = h;
    index = k;
    found = true;
    crossing = crosses;
  }
  // The best hit certified as the crossing of the piece's interior (so at no end of its edge).
  bool crossing = false;
  // RN(λ) of the best hit (a function of the hit alone, evaluated once; `exact`: rationals only).
  double value(const Ray& ray, const Vec2& t, bool exact) const {
    return exact::rounded_ratio_of([&](auto L) { return hit_nd(hit, ray, t, L); }, exact);
  }
};

// σ's running best: the exact nearest point, ties to the lowest piece index. Kept as the piece
// index and which point of it (no Cand copies in the loop); the winner's Cand is made once.
struct MinBest {
  std::uint32_t index = 0;
  std::uint8_t at = 0;  // 0: t's projection on the piece's line; 1: its lo end; 2: its hi end
  bool found = false;
  bool inside = false;  // the projection, strictly inside its piece (so at no end of its edge)
  static Cand cand_of(const NoFitPolygon2::Impl& N, std::uint32_t k, std::uint8_t at) {
    const NfpPiece& pc = N.pieces[k];
    return Cand{pc.E, at == 0 ? Param{Param::Proj, {}} : at == 1 ? pc.lo : pc.hi, pc.edge};
  }
  Cand cand(const NoFitPolygon2::Impl& N) const { return cand_of(N, index, at); }
  // `flags`: t's projection certified strictly inside the piece (NfpFlat::kInside), before its lo
  // end (kBeforeLo) or beyond its hi end (kBeyondHi) by the fast path; else decided exactly.
  // `lines` (the fast path): NfpFlat::pline, two projections on one line being one point.
  void consider(const NoFitPolygon2::Impl& N, std::uint32_t k, const Vec2& t, std::uint32_t flags = 0, const NfpFlat* lines = nullptr) {
    const NfpPiece& pc = N.pieces[k];
    std::uint8_t a = 0;
    const bool proj_inside = (flags & NfpFlat::kInside) != 0;
    if (proj_inside) {
    } else if (flags & NfpFlat::kBeforeLo) a = 1;
    else if (flags & NfpFlat::kBeyondHi) a = 2;
    else {
      const Param proj{Param::Proj, {}};
      if (nonconvex2::compare_params(proj, pc.lo, pc.E, t) <= 0) a = 1;
      else if (nonconvex2::compare_params(proj, pc.hi, pc.E, t) >= 0) a = 2;
    }
    if (found) {
      // Projections on one line (the tabled line ids; every tie of this loop on the bench's pieces)
      // are one point, so are the same point as the running best's: the later index loses.
      if (lines && a == 0 && at == 0 && lines->one_line(k, index)) {
        if (k > index) return;
      } else {
        // A shared vertex of two pieces is recognised symbolically.
        const Cand c = cand_of(N, k, a), b = cand(N);
        const int s = nonconvex2::same_point(c, b) ? 0 : exact_sign([&](auto L) {
          auto [n1, d1] = nonconvex2::sq_dist(c, t, L);
          auto [n2, d2] = nonconvex2::sq_dist(b, t, L);
          return n1 * d2 - n2 * d1;
        });
        if (s > 0 || (s == 0 && k > index)) return;
      }
    }
    index = k;
    at = a;
    found = true;
    inside = proj_inside;
  }
  // σ = √RN(σ²) of the best candidate (a function of the candidate alone, evaluated once;
  // `exact`: rationals only).
  double value(const NoFitPolygon2::Impl& N, const Vec2& t, bool exact) const {
    const Cand c = cand(N);
    return std::sqrt(exact::rounded_ratio_of([&](auto L) { return nonconvex2::sq_dist(c, t, L); }, exact));
  }
};

// The vector from t to the candidate point, each coordinate RN(exact) (geometry/rounded.hpp):
// the same double on the fast and the exact path. The projection on an axis-parallel edge has one
// coordinate exactly 0 (decided exactly: a zero numerator always needs the rationals).
Vec2 rounded_translation(const Cand& c, const Vec2& t, bool exact) {
  const Ray& E = c.E;
  auto coord = [&](int axis) {
    return exact::rounded_ratio_of([&](auto L) { return nonconvex2::point_nd(c.at, E, t, axis, L); }, exact);
  };
  if (c.at.kind == Param::Proj) {
    if (exact_sign([&](auto L) { return nonconvex2::ray_dx(E, L); }) == 0) return Vec2(coord(0), 0);
    if (exact_sign([&](auto L) { return nonconvex2::ray_dy(E, L); }) == 0) return Vec2(0, coord(1));
  }
  return Vec2(coord(0), coord(1));
}

struct Job {
  double key;
  std::int32_t node;
  bool operator>(const Job& o) const { return key > o.key; }
};

}  // namespace

namespace {

// t ∈ O for σ's and σ_d's winner searches: `proved` when the fast path's candidates named first
// prove it (NfpFlat::inside_by_candidates, inside_by_nearest), else by the overlap test (exact
// alone on the exact path).
bool winner_overlaps(const NoFitPolygon2::Impl& N, const Vec2& t, bool exact_path, bool proved) {
  if (N.pieces.empty()) return false;
  if (proved) return true;
  return exact_path ? N.overlapping_exact(t) : N.overlapping(t);
}

// σ_d's winner and RN(λ) (λ on the scaled d), shared by along and along_value; false when t ∉ O.
bool along_winner(const NoFitPolygon2::Impl& N, const Vec2& t, const Vec2& d, bool exact_path, AlongBest& best, double& value) {
  const NfpFlat& flat = N.flat;
  const bool fast = flat.usable && !exact_path;
  // The fast path names its candidates first: a sole one crossed from O's side proves t ∈ O
  // (NfpFlat::inside_by_candidates), else the overlap test decides.
  std::vector<std::uint32_t>& cand = scratch();
  if (fast) flat.first_hit_candidates(t, d, cand);
  if (!winner_overlaps(N, t, exact_path, fast && NfpFlat::inside_by_candidates(cand))) return false;
  const Ray ray = Ray::query(t, d);
  value = std::numeric_limits<double>::infinity();
  if (fast) {
    for (std::uint32_t k : cand) best.consider(N, k & ~NfpFlat::kFlags, ray, t, d, (k & NfpFlat::kInside) != 0);
  } else {
    // Best-first traversal of the piece hierarchy by conservative box entry λ.
    std::priority_queue<Job, std::vector<Job>, std::greater<Job>> jobs;
    auto push = [&](std::int32_t node) {
      double l0, l1;
      if (!nonconvex2::ray_box(t, d, N.tree.nodes[node].lo, N.tree.nodes[node].hi, l0, l1) || l1 < 0) return;
      jobs.push({l0, node});
    };
    push(0);
    while (!jobs.empty()) {
      const Job J = jobs.top();
      jobs.pop();
      if (best.found && J.key > value + std::abs(value) * 0x1p-40) break;
      const auto& node = N.tree.nodes[J.node];
      if (node.left >= 0) {
        push(node.left);
        push(node.right);
        continue;
      }
      const std::uint32_t before = best.index;
      const bool had = best.found;
      best.consider(N, node.tri, ray, t, d);
      if (best.found && (!had || best.index != before)) value = best.value(ray, t, exact_path);
    }
  }
  if (!best.found) return false;  // unreachable for t ∈ O (O is bounded)
  // RN(λ): a crossing from the piece's double-doubles (nfp_value.cpp) when certified, else the
  // generic rounded evaluation.
  if (!exact_path && !(!best.hit.end && flat.crossing_value(best.index, t, d, value)) && flat.usable) value = best.value(ray, t, false);
  return true;
}

// σ's winner, σ and its translation, shared by minimum and minimum_value; false when t ∉ O.
bool min_winner(const NoFitPolygon2::Impl& N, const Vec2& t, bool exact_path, MinBest& best, double& value, Vec2& translation) {
  const NfpFlat& flat = N.flat;
  const bool fast = flat.usable && !exact_path;
  // As along_winner: a sole nearest candidate with t on O's side, or candidates all meeting at
  // a reflex vertex of O that is t's nearest point (at_wedge), proves t ∈ O.
  std::vector<std::uint32_t>& cand = scratch();
  if (fast) flat.nearest_candidates(t, cand);
  const bool wedge = fast && flat.at_wedge(cand);
  if (!winner_overlaps(N, t, exact_path, wedge || (fast && NfpFlat::inside_by_candidates(cand)))) return false;
  value = std::numeric_limits<double>::infinity();
  if (fast) {
    // At a wedge every candidate's nearest point is the same exact vertex: all tie and the first
    // (lowest index) wins, as the loop's exact comparisons would decide.
    const std::size_t n = wedge ? 1 : cand.size();
    for (std::size_t i = 0; i < n; ++i) best.consider(N, cand[i] & ~NfpFlat::kFlags, t, cand[i] & NfpFlat::kFlags, &flat);
  } else {
    // Branch and bound on the hierarchy with conservative box distances; every piece as near as
    // the best is visited (its box key is below its distance), so ties resolve by index.
    std::priority_queue<Job, std::vector<Job>, std::greater<Job>> jobs;
    jobs.push({0, 0});
    while (!jobs.empty()) {
      const Job J = jobs.top();
      jobs.pop();
      if (best.found && J.key > value * (1 + 0x1p-40)) break;
      const auto& node = N.tree.nodes[J.node];
      if (node.left >= 0) {
        for (std::int32_t c : {node.left, node.right}) jobs.push({box_distance(t, N.tree.nodes[c].lo, N.tree.nodes[c].hi), c});
        continue;
      }
      const std::uint32_t before = best.index;
      const bool had = best.found;
      best.consider(N, node.tri, t);
      if (best.found && (!had || best.index != before)) value = best.value(N, t, exact_path);
    }
  }
  if (!best.found) return false;  // unreachable for t ∈ O
  // σ = √RN(σ²) and the translation RN per coordinate: at a projection from the piece's
  // double-doubles (nfp_value.cpp) when certified, else the generic rounded evaluation.
  double s2;
  // The winner at a sum vertex (its piece's end is the symbolic μ = 0 or 1): which one, else -1.
  const Param::Kind kind = best.at == 0 ? Param::Proj : best.at == 1 ? N.pieces[best.index].lo.kind : N.pieces[best.index].hi.kind;
  const int vertex = kind == Param::Zero ? 0 : kind == Param::One ? 1 : -1;
  if (!exact_path && best.at == 0 && flat.projection_values(best.index, t, s2, translation)) {
    value = std::sqrt(s2);
  } else if (!exact_path && vertex >= 0 && flat.vertex_values(best.index, vertex, t, s2, translation)) {
    value = std::sqrt(s2);  // at a sum vertex (nfp_value.cpp)
  } else if (!exact_path && best.at != 0 && vertex < 0 && flat.end_values(best.index, best.at - 1, t, s2, translation)) {
    value = std::sqrt(s2);  // at a cut end, from the piece's table built with the no-fit polygon
  } else {
    if (!exact_path && flat.usable) value = best.value(N, t, false);
    translation = rounded_translation(best.cand(N), t, exact_path);
  }
  return true;
}

}  // namespace

Depth2 NoFitPolygon2::Impl::along(const Vec2& t, const Vec2& d, bool exact_path) const {
  Depth2 r;
  r.kind = DepthKind::Directional;
  AlongBest best;
  double value;
  if (!along_winner(*this, t, d, exact_path, best, value)) return r;
  const double dn = nonconvex2::norm_accurate(d);
  const double depth = std::max(0.0, value * dn);
  const Line& E = best.hit.piece->edge;
  // A certified crossing of the piece's interior is at no end of the edge (the piece lies in it).
  r = S.contact_features(E, t, depth * (d / dn), best.crossing ? -1 : nonconvex2::end_on_ray(E, t, d));
  r.depth = depth;
  r.normal = d / dn;
  r.kind = DepthKind::Directional;
  r.overlapping = true;
  return r;
}

DepthValue2 NoFitPolygon2::Impl::along_value(const Vec2& t, const Vec2& d, bool exact_path) const {
  AlongBest best;
  double value;
  if (!along_winner(*this, t, d, exact_path, best, value)) return {};
  const double dn = nonconvex2::norm_accurate(d);
  const double depth = std::max(0.0, value * dn);
  return {depth, depth * (d / dn), true};
}

Depth2 NoFitPolygon2::Impl::minimum(const Vec2& t, bool exact_path) const {
  Depth2 r;
  r.kind = DepthKind::Minimum;
  MinBest best;
  double value;
  Vec2 translation;
  if (!min_winner(*this, t, exact_path, best, value, translation)) return r;
  // A projection strictly inside its piece is at no end of the edge (the piece lies in it).
  r = S.contact(pieces[best.index].edge, t, translation, best.inside ? -1 : nonconvex2::cand_end(best.cand(*this), t));
  r.depth = value;
  r.kind = DepthKind::Minimum;
  r.overlapping = true;
  return r;
}

DepthValue2 NoFitPolygon2::Impl::minimum_value(const Vec2& t, bool exact_path) const {
  MinBest best;
  double value;
  Vec2 translation;
  if (!min_winner(*this, t, exact_path, best, value, translation)) return {};
  return {value, translation, true};
}

bool NoFitPolygon2::overlapping(const Vec2& t) const {
  nonconvex2::check_point(t);
  return impl_->overlapping(t);
}

Depth2 NoFitPolygon2::along(const Vec2& t, const Vec2& d_in) const {
  const Vec2 d = nonconvex2::check_and_scale(t, d_in);
  return impl_->along(t, d);
}

Depth2 NoFitPolygon2::minimum(const Vec2& t) const {
  nonconvex2::check_point(t);
  return impl_->minimum(t);
}

DepthValue2 NoFitPolygon2::directional_depth_value(const Vec2& t, const Vec2& d_in) const {
  const Vec2 d = nonconvex2::check_and_scale(t, d_in);
  return impl_->along_value(t, d);
}

DepthValue2 NoFitPolygon2::depth_value(const Vec2& t) const {
  nonconvex2::check_point(t);
  return impl_->minimum_value(t);
}

}  // namespace pendepth
