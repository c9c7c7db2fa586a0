// pendepth — Shape3 and Pair3: the front door over the 3D convex engines
// (include/pendepth/pendepth.hpp; DHS §5–§6).
//
// σ is the certified expansion (minimum_depth), σ_d Compute-Depth-3D (directional_depth); both
// need only the per-shape structures Shape3 builds once (hull, DK hierarchy; the adjacency and
// the outer hierarchy are built on first use inside ConvexPolytope, thread-safe), so Prepare
// changes nothing in 3D today.
#include <pendepth/io.hpp>
#include <pendepth/pendepth.hpp>

#include "front/batch.hpp"
#include "front/checks.hpp"
#include "front/mesh_shapes.hpp"
#include "front/scale.hpp"
#include "convex3/flat3.hpp"
#include "convex3/minimum_expand.hpp"
#include "mesh3/mesh_mixed.hpp"
#include "mesh3/mesh_pair.hpp"
#include "convex3/distance_compare.hpp"
#include "primitives/rounded3.hpp"
#include "primitives/support3.hpp"

namespace pendepth {

Shape3::Shape3(ConvexPolytope polytope) : p_(std::make_shared<const ConvexPolytope>(std::move(polytope))) {}

Shape3 Shape3::hull(std::span<const Vec3> points, std::string_view name) {
  return Shape3(ConvexPolytope::hull(points, name));
}

// (Lower-dimensional shapes: src/front/shape3_flat.cpp defines polytope, size and name.)

namespace {

// A pose's translation must be finite and its quaternion non-zero and finite (Pose3::matrix
// checks the quaternion; the engines call it).
void check_pose(const Pose3& pose, const std::string& what) {
  front::check_placement(pose.translation, what + " translation");
  if (!front::finite(pose.rotation.coeffs()))
    throw InvalidInput(what + " rotation " + front::text(pose.rotation.coeffs()) + " is not finite");
  if (pose.rotation.coeffs().isZero(0)) throw InvalidInput(what + " rotation is the zero quaternion");
}

Pose3 engine_pose(const front::Scale& scale, const Pose3& pose, const std::string& what);

// Every pose checked (and, for a scaled pair, converted to engine coordinates) before any
// query of the batch runs.
void check_poses(std::span<const Pose3> poses, std::size_t out_size, int scale_exp) {
  if (out_size != poses.size())
    throw InvalidInput("batch: " + std::to_string(poses.size()) + " poses but room for " + std::to_string(out_size) +
                       " results");
  for (std::size_t i = 0; i < poses.size(); ++i) {
    check_pose(poses[i], "batch: pose " + std::to_string(i));
    engine_pose(front::Scale{scale_exp}, poses[i], "batch: pose " + std::to_string(i));
  }
}

void check_directions(std::span<const Vec3> ds, std::size_t n) {
  if (ds.size() != 1 && ds.size() != n)
    throw InvalidInput("batch: " + std::to_string(ds.size()) + " directions for " + std::to_string(n) +
                       " poses (give one direction, or one per pose)");
  for (std::size_t i = 0; i < ds.size(); ++i) front::check_direction(ds[i], "batch: direction " + std::to_string(i));
}

}  // namespace

namespace {

// The sizes of a polytope: its largest coordinate and its smallest edge.
void add_extent(front::Extent& x, const Shape3& s) {
  if (s.radius() > 0) x.add_point(s.radius()), x.add_edge(Vec3(0, 0, 0), Vec3(s.radius(), 0, 0));
  if (const auto* c = s.curved()) {  // curved primitives: the largest and the smallest parameter
    for (double v : {c->a, c->b, c->c})
      if (v > 0) x.add_point(v), x.add_edge(Vec3(0, 0, 0), Vec3(v, 0, 0));
    return;
  }
  if (const auto* f = s.flat_shape()) {
    for (std::size_t i = 0; i < f->v.size(); ++i) {
      x.add_point(f->v[i].cwiseAbs().maxCoeff());
      if (f->v.size() > 1) x.add_edge(f->v[i], f->v[(i + 1) % f->v.size()]);
    }
    return;
  }
  const ConvexPolytope& P = s.polytope();
  for (const Vec3& v : P.vertices()) x.add_point(v.cwiseAbs().maxCoeff());
  for (const auto& tri : P.triangles())
    for (int k = 0; k < 3; ++k) x.add_edge(P[tri[k]], P[tri[(k + 1) % 3]]);
}

front::Scale pair_scale(const Shape3& P, const Shape3& Q) {
  front::Extent x;
  add_extent(x, P);
  add_extent(x, Q);
  return front::Scale::for_pair(x, front::kBand3);
}

// `s` in engine coordinates: the polytope scaled by 2^-e (exact, checked here so that the error
// names the vertex and the range), with the same numbering, so features need no mapping.
Shape3 engine_shape(const Shape3& s, const front::Scale& scale, const char* which) {
  if (scale.identity()) return s;
  if (s.radius() > 0) {  // the scaled core, rounded by the scaled radius (exact)
    double r = 0;
    if (!scale.to_engine(s.radius(), r))
      throw InvalidInput(std::string(which) + " (" + s.name() + ") radius: " + scale.describe(s.radius()));
    return Shape3::rounded(engine_shape(s.core(), scale, which), r, s.name());
  }
  if (const auto* c = s.curved()) {  // the parameters scaled exactly
    primitives::Curved3 g = *c;
    for (double* v : {&g.a, &g.b, &g.c})
      if (*v != 0 && !scale.to_engine(*v, *v))
        throw InvalidInput(std::string(which) + " (" + s.name() + ") size: " + scale.describe(*v));
    return Shape3::from_curved(std::make_shared<const primitives::Curved3>(std::move(g)));
  }
  if (const auto* f = s.flat_shape()) {  // the same normal form, every vertex scaled exactly
    convex3::FlatShape3 g = *f;
    for (std::size_t i = 0; i < g.v.size(); ++i)
      g.v[i] = scale.vec_to_engine(g.v[i], std::string(which) + " (" + s.name() + ") vertex " + std::to_string(i) + ":");
    return Shape3(std::move(g));
  }
  const auto v = s.polytope().vertices();
  for (std::size_t i = 0; i < v.size(); ++i)
    scale.vec_to_engine(v[i], std::string(which) + " (" + s.name() + ") vertex " + std::to_string(i) + ":");
  return Shape3(s.polytope().scaled(-scale.e));
}

// A pose in engine coordinates (its translation scaled; the rotation is scale-free).
Pose3 engine_pose(const front::Scale& scale, const Pose3& pose, const std::string& what) {
  if (scale.identity()) return pose;
  return Pose3(pose.rotation, scale.vec_to_engine(pose.translation, what + " translation " +
                                                                        front::text(pose.translation) + ":"));
}

}  // namespace

namespace {
// The shape combinations Pair3 answers; any other is an InvalidInput naming both shapes.
Shape3 supported_pair(Shape3 P, const Shape3& Q) {
  if (P.dimension() < 3 && Q.dimension() < 3)
    throw InvalidInput("pair: both shapes are lower-dimensional (P " + P.name() + " of dimension " +
                       std::to_string(P.dimension()) + ", Q " + Q.name() + " of dimension " +
                       std::to_string(Q.dimension()) + "): M = P ⊕ (−Q) has no interior; one shape must be solid");
  return P;
}
// A non-convex mesh against a point, segment, flat polygon, rounded or curved shape (mesh_mixed.hpp).
bool mixed_pair(const Shape3& P, const Shape3& Q) {
  auto other = [](const Shape3& s) { return s.dimension() < 3 || s.radius() > 0 || s.curved(); };
  return (!P.is_convex() && other(Q)) || (!Q.is_convex() && other(P));
}
}  // namespace

namespace {
// The pair's scale exponent: a mesh pair's comes with its pieces (built here on first use).
int exp_of(const std::shared_ptr<const mesh3::LazyMeshPair>& mesh, int convex_exp) {
  return mesh ? mesh->scale_exp() : convex_exp;
}
}  // namespace

Pair3::Pair3(Shape3 P, Shape3 Q, Prepare)
    : P_(supported_pair(std::move(P), Q)),
      Q_(std::move(Q)),
      scale_exp_(P_.is_convex() && Q_.is_convex() ? pair_scale(P_, Q_).e : 0),
      engine_P_(P_),
      engine_Q_(Q_) {
  if (mixed_pair(P_, Q_)) {  // each piece pair a convex Pair3 with its own numeric domain
    mixed_ = std::make_shared<const mesh3::MixedPair>(mesh3::MixedPair::make(P_, Q_));
    return;
  }
  if (!P_.is_convex() || !Q_.is_convex()) {
    mesh_ = front::mesh_pair(P_, Q_);  // pieces in engine coordinates on first use (pair3_mesh.cpp)
    if (mesh3::eager_pieces) mesh_->pair();  // tests: the eager path
    return;
  }
  engine_P_ = engine_shape(P_, front::Scale{scale_exp_}, "P");
  engine_Q_ = engine_shape(Q_, front::Scale{scale_exp_}, "Q");
}

// ---- lower-dimensional shapes (src/convex3/flat3.cpp) -----------------------------------------
// The engine takes the solid shape as S (P's role). When P is the lower-dimensional one, the pair
// is answered swapped — P moving by −v instead of Q by v, along −d for σ_d and casts — and the
// answer mapped back: vectors negated, witnesses and features exchanged, a contact point found
// with P moved by v is, with Q moved by −v instead, that point − v.
namespace {

bool is_flat(const Shape3& s) { return s.dimension() < 3; }
bool is_rounded(const Shape3& P, const Shape3& Q) { return P.radius() + Q.radius() > 0; }

Depth3 unswap(Depth3 r) {
  const Vec3 v = r.translation;
  r.translation = -r.translation, r.normal = -r.normal, r.facet_normal = -r.facet_normal;
  r.witness_p = r.witness_q = r.witness_p - v;
  std::swap(r.feature_p, r.feature_q);
  return r;
}

Depth3 flat_depth(const Shape3& P, const Pose3& pp, const Shape3& Q, const Pose3& pq, const Vec3* d) {
  if (is_flat(Q))
    return d ? convex3::flat_directional(P.polytope(), pp, *Q.flat_shape(), pq, *d)
             : convex3::flat_minimum(P.polytope(), pp, *Q.flat_shape(), pq);
  return unswap(d ? convex3::flat_directional(Q.polytope(), pq, *P.flat_shape(), pp, -*d)
                  : convex3::flat_minimum(Q.polytope(), pq, *P.flat_shape(), pp));
}

Distance3 flat_distance(const Shape3& P, const Pose3& pp, const Shape3& Q, const Pose3& pq) {
  if (is_flat(Q)) return convex3::flat_signed_distance(P.polytope(), pp, *Q.flat_shape(), pq);
  Distance3 r = convex3::flat_signed_distance(Q.polytope(), pq, *P.flat_shape(), pp);
  // Apart / touching: the closest pair, seen from the other side. Overlapping: σ's move of P by v
  // is Q's move by −v; witness_q stays on the unmoved Q (= the engine's witness_p).
  r.normal = -r.normal, r.translation = -r.translation;
  std::swap(r.witness_p, r.witness_q);
  std::swap(r.feature_p, r.feature_q);
  return r;
}

Cast3 flat_cast(const Shape3& P, const Pose3& pp, const Shape3& Q, const Pose3& pq, const Vec3& d) {
  if (is_flat(Q)) return convex3::flat_cast(P.polytope(), pp, *Q.flat_shape(), pq, d);
  Cast3 r = convex3::flat_cast(Q.polytope(), pq, *P.flat_shape(), pp, -d);
  const Vec3 v = r.translation;
  r.translation = -r.translation, r.normal = -r.normal;
  r.witness_p = r.witness_q = r.witness_p - v;
  std::swap(r.feature_p, r.feature_q);
  return r;
}

// ---- rounded shapes (src/primitives/rounded3.cpp): the cores' signed distance ----------------
// With Q's pose translated by `offset`; when the cores touch, a supporting normal of M_core at 0
// from the cast's facet through the contact (or flat_flat_distance's).
primitives::CoreDistance core_distance(const Shape3& P0, const Pose3& pp, const Shape3& Q0, const Pose3& pq) {
  return [P = P0.core(), Q = Q0.core(), pp, pq](const Vec3& offset, Vec3* touch) {
    Pose3 q = pq;
    q.translation += offset;
    if (is_flat(P) && is_flat(Q)) return convex3::flat_flat_distance(*P.flat_shape(), pp, *Q.flat_shape(), q, touch);
    const bool flat = is_flat(P) || is_flat(Q);
    const Distance3 r = flat ? flat_distance(P, pp, Q, q) : signed_distance(P.polytope(), pp, Q.polytope(), q);
    if (touch && r.distance == 0 && !r.overlapping)
      *touch = (flat ? flat_cast(P, pp, Q, q, Vec3(1, 0, 0)) : shape_cast(P.polytope(), pp, Q.polytope(), q, Vec3(1, 0, 0)))
                   .normal;
    return r;
  };
}

// The exact comparisons of the cores with a radius (convex3/distance_compare.hpp).
primitives::CoreCompare core_compare(const Shape3& P0, const Pose3& pp, const Shape3& Q0, const Pose3& pq) {
  // The core shapes are kept alive with their points (a polytope's data is referenced).
  auto P = std::make_shared<const Shape3>(P0.core()), Q = std::make_shared<const Shape3>(Q0.core());
  auto cp = is_flat(*P) ? std::make_shared<const convex3::CorePoints>(*P->flat_shape())
                        : std::make_shared<const convex3::CorePoints>(P->polytope());
  auto cq = is_flat(*Q) ? std::make_shared<const convex3::CorePoints>(*Q->flat_shape())
                        : std::make_shared<const convex3::CorePoints>(Q->polytope());
  primitives::CoreCompare c;
  c.at = [P, Q, cp, cq, pp, pq](const Vec3& d, double lam, double rp, double rq, int* slope) {
    return convex3::distance_compare(*cp, pp, *cq, pq, d, lam, rp, rq, slope);
  };
  c.line = [P, Q, cp, cq, pp, pq](const Vec3& d, double rp, double rq) {
    return convex3::line_distance_compare(*cp, pp, *cq, pq, d, rp, rq);
  };
  return c;
}

}  // namespace

// ---- curved primitives (src/primitives/support3.cpp): the certified support-function engine ----
namespace {
bool is_curved(const Shape3& P, const Shape3& Q) { return P.curved() || Q.curved(); }
// The query `f` on the pair's support functions in engine coordinates.
template <class F>
auto curved_query(const front::Scale& scale, const Shape3& P, const Pose3& pose_p, const Shape3& Q,
                  const Pose3& pose_q, F&& f) {
  return f(primitives::support_of(P), engine_pose(scale, pose_p, "pose of P"), primitives::support_of(Q),
           engine_pose(scale, pose_q, "pose of Q"));
}
}  // namespace

// One query in engine coordinates: poses converted in (checked), the answer scaled back.
Depth3 Pair3::min_engine(const Pose3& pose_p, const Pose3& pose_q) const {
  if (mixed_) return mesh3::minimum(*mixed_, pose_p, pose_q);
  const front::Scale scale{exp_of(mesh_, scale_exp_)};
  if (is_curved(engine_P_, engine_Q_))
    return scale.answer(curved_query(scale, engine_P_, pose_p, engine_Q_, pose_q, [](auto&&... a) {
      return primitives::curved_minimum(a...);
    }));
  if (mesh_) {
    mesh3::SigmaKeepBounds* keep = mesh3::SigmaKeepBounds::active;
    if (keep) keep->bounds.reset();
    const Depth3 r = scale.answer(mesh3::minimum(mesh_->pair(), engine_pose(scale, pose_p, "pose of P"), engine_pose(scale, pose_q, "pose of Q")));
    if (keep && keep->bounds) keep->bounds = scale.answer(*keep->bounds);
    return r;
  }
  if (is_rounded(engine_P_, engine_Q_)) {
    const Pose3 ep = engine_pose(scale, pose_p, "pose of P"), eq = engine_pose(scale, pose_q, "pose of Q");
    return scale.answer(primitives::rounded_minimum(core_distance(engine_P_, ep, engine_Q_, eq),
                                                    core_compare(engine_P_, ep, engine_Q_, eq), engine_P_.radius(),
                                                    engine_Q_.radius()));
  }
  if (is_flat(engine_P_) || is_flat(engine_Q_))
    return scale.answer(flat_depth(engine_P_, engine_pose(scale, pose_p, "pose of P"), engine_Q_,
                                   engine_pose(scale, pose_q, "pose of Q"), nullptr));
  return scale.answer(minimum_depth(engine_P_.polytope(), engine_pose(scale, pose_p, "pose of P"),
                                    engine_Q_.polytope(), engine_pose(scale, pose_q, "pose of Q")));
}

Depth3 Pair3::along_engine(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const {
  if (mixed_) return mesh3::along(*mixed_, pose_p, pose_q, d, false);
  const front::Scale scale{exp_of(mesh_, scale_exp_)};
  if (is_curved(engine_P_, engine_Q_))
    return scale.answer(curved_query(scale, engine_P_, pose_p, engine_Q_, pose_q, [&](auto&&... a) {
      return primitives::curved_along(a..., d);
    }));
  if (mesh_)
    return scale.answer(mesh3::along(mesh_->pair(), engine_pose(scale, pose_p, "pose of P"), engine_pose(scale, pose_q, "pose of Q"), d, false));
  if (is_rounded(engine_P_, engine_Q_)) {
    const Pose3 ep = engine_pose(scale, pose_p, "pose of P"), eq = engine_pose(scale, pose_q, "pose of Q");
    return scale.answer(primitives::rounded_along(core_distance(engine_P_, ep, engine_Q_, eq),
                                                  core_compare(engine_P_, ep, engine_Q_, eq), engine_P_.radius(),
                                                  engine_Q_.radius(), d));
  }
  if (is_flat(engine_P_) || is_flat(engine_Q_))
    return scale.answer(flat_depth(engine_P_, engine_pose(scale, pose_p, "pose of P"), engine_Q_,
                                   engine_pose(scale, pose_q, "pose of Q"), &d));
  return scale.answer(directional_depth(engine_P_.polytope(), engine_pose(scale, pose_p, "pose of P"),
                                        engine_Q_.polytope(), engine_pose(scale, pose_q, "pose of Q"), d));
}

bool Pair3::overlapping(const Pose3& pose_p, const Pose3& pose_q) const {
  if (!mesh_ && !mixed_) return minimum(pose_p, pose_q).overlapping;
  check_pose(pose_p, "pose of P");
  check_pose(pose_q, "pose of Q");
  if (mixed_) return mesh3::overlapping(*mixed_, pose_p, pose_q);
  const front::Scale scale{exp_of(mesh_, scale_exp_)};
  return mesh3::overlapping(mesh_->pair(), engine_pose(scale, pose_p, "pose of P"), engine_pose(scale, pose_q, "pose of Q"));
}

Depth3 Pair3::minimum(const Pose3& pose_p, const Pose3& pose_q) const {
  check_pose(pose_p, "pose of P");
  check_pose(pose_q, "pose of Q");
  return min_engine(pose_p, pose_q);
}

Depth3 Pair3::along(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const {
  check_pose(pose_p, "pose of P");
  check_pose(pose_q, "pose of Q");
  front::check_direction(d);
  return along_engine(pose_p, pose_q, d);
}

Depth3 Pair3::separation(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const {
  if (mixed_) {
    check_pose(pose_p, "pose of P");
    check_pose(pose_q, "pose of Q");
    front::check_direction(d);
    return mesh3::along(*mixed_, pose_p, pose_q, d, true);
  }
  if (mesh_) {
    check_pose(pose_p, "pose of P");
    check_pose(pose_q, "pose of Q");
    front::check_direction(d);
    const front::Scale scale{exp_of(mesh_, scale_exp_)};
    return scale.answer(mesh3::along(mesh_->pair(), engine_pose(scale, pose_p, "pose of P"), engine_pose(scale, pose_q, "pose of Q"), d, true));
  }
  Depth3 r = along(pose_p, pose_q, d);
  r.kind = DepthKind::Separation;
  return r;
}

void Pair3::overlapping(std::span<const Pose3> poses_q, std::span<bool> out, unsigned threads) const {
  check_poses(poses_q, out.size(), exp_of(mesh_, scale_exp_));
  const Pose3 pose_p;
  front::parallel_for(poses_q.size(), threads, [&](std::size_t i) {
    out[i] = mesh_ || mixed_ ? overlapping(pose_p, poses_q[i]) : min_engine(pose_p, poses_q[i]).overlapping;
  });
}

void Pair3::minimum(std::span<const Pose3> poses_q, std::span<Depth3> out, unsigned threads) const {
  minimum(Pose3(), poses_q, out, threads);
}

void Pair3::along(std::span<const Pose3> poses_q, std::span<const Vec3> ds, std::span<Depth3> out,
                  unsigned threads) const {
  along(Pose3(), poses_q, ds, out, threads);
}

void Pair3::minimum(const Pose3& pose_p, std::span<const Pose3> poses_q, std::span<Depth3> out,
                    unsigned threads) const {
  check_pose(pose_p, "pose of P");
  check_poses(poses_q, out.size(), exp_of(mesh_, scale_exp_));
  engine_pose(front::Scale{exp_of(mesh_, scale_exp_)}, pose_p, "pose of P");
  front::parallel_for(poses_q.size(), threads, [&](std::size_t i) { out[i] = min_engine(pose_p, poses_q[i]); });
}

void Pair3::along(const Pose3& pose_p, std::span<const Pose3> poses_q, std::span<const Vec3> ds,
                  std::span<Depth3> out, unsigned threads) const {
  check_pose(pose_p, "pose of P");
  check_poses(poses_q, out.size(), exp_of(mesh_, scale_exp_));
  engine_pose(front::Scale{exp_of(mesh_, scale_exp_)}, pose_p, "pose of P");
  if (poses_q.empty()) return;
  check_directions(ds, poses_q.size());
  const bool one = ds.size() == 1;
  front::parallel_for(poses_q.size(), threads,
                      [&](std::size_t i) { out[i] = along_engine(pose_p, poses_q[i], ds[one ? 0 : i]); });
}

// ---- Signed distance and shape cast (issue 16; src/convex3/signed_distance3.cpp, cast3.cpp) ----
// The same numeric domain as σ and σ_d: the engines see the shapes and translations scaled by
// 2^-scale_exp_, every length and point of the answer is scaled back.
namespace {

Distance3 distance_answer(const front::Scale& scale, Distance3 r) {
  if (scale.identity()) return r;
  r.distance = scale.length(r.distance);
  r.lower_bound = scale.length(r.lower_bound);
  r.upper_bound = scale.length(r.upper_bound);
  r.translation = scale.vec(r.translation);
  r.witness_p = scale.vec(r.witness_p);
  r.witness_q = scale.vec(r.witness_q);
  return r;
}

Cast3 cast_answer(const front::Scale& scale, Cast3 r) {
  if (scale.identity()) return r;
  r.distance = scale.length(r.distance);  // +infinity stays
  r.lower_bound = scale.length(r.lower_bound);
  r.upper_bound = scale.length(r.upper_bound);
  r.translation = scale.vec(r.translation);
  r.witness_p = scale.vec(r.witness_p);
  r.witness_q = scale.vec(r.witness_q);
  return r;
}

}  // namespace

Distance3 Pair3::distance_engine(const Pose3& pose_p, const Pose3& pose_q) const {
  if (mixed_) return mesh3::signed_distance(*mixed_, pose_p, pose_q);
  const front::Scale scale{exp_of(mesh_, scale_exp_)};
  if (is_curved(engine_P_, engine_Q_))
    return distance_answer(scale, curved_query(scale, engine_P_, pose_p, engine_Q_, pose_q, [](auto&&... a) {
                             return primitives::curved_distance(a...);
                           }));
  if (mesh_)
    return distance_answer(scale, mesh3::signed_distance(mesh_->pair(), engine_pose(scale, pose_p, "pose of P"),
                                                         engine_pose(scale, pose_q, "pose of Q")));
  if (is_rounded(engine_P_, engine_Q_)) {
    const Pose3 ep = engine_pose(scale, pose_p, "pose of P"), eq = engine_pose(scale, pose_q, "pose of Q");
    return distance_answer(scale, primitives::rounded_distance(core_distance(engine_P_, ep, engine_Q_, eq),
                                                               core_compare(engine_P_, ep, engine_Q_, eq),
                                                               engine_P_.radius(), engine_Q_.radius()));
  }
  if (is_flat(engine_P_) || is_flat(engine_Q_))
    return distance_answer(scale, flat_distance(engine_P_, engine_pose(scale, pose_p, "pose of P"), engine_Q_,
                                                engine_pose(scale, pose_q, "pose of Q")));
  return distance_answer(scale, pendepth::signed_distance(engine_P_.polytope(), engine_pose(scale, pose_p, "pose of P"),
                                                          engine_Q_.polytope(), engine_pose(scale, pose_q, "pose of Q")));
}

Distance3 Pair3::signed_distance(const Pose3& pose_p, const Pose3& pose_q) const {
  check_pose(pose_p, "pose of P");
  check_pose(pose_q, "pose of Q");
  return distance_engine(pose_p, pose_q);
}

void Pair3::signed_distance(std::span<const Pose3> poses_q, std::span<Distance3> out, unsigned threads) const {
  signed_distance(Pose3(), poses_q, out, threads);
}

void Pair3::signed_distance(const Pose3& pose_p, std::span<const Pose3> poses_q, std::span<Distance3> out,
                            unsigned threads) const {
  check_pose(pose_p, "pose of P");
  check_poses(poses_q, out.size(), exp_of(mesh_, scale_exp_));
  engine_pose(front::Scale{exp_of(mesh_, scale_exp_)}, pose_p, "pose of P");
  front::parallel_for(poses_q.size(), threads, [&](std::size_t i) { out[i] = distance_engine(pose_p, poses_q[i]); });
}

Cast3 Pair3::cast(const Pose3& pose_p, const Pose3& pose_q, const Vec3& d) const {
  check_pose(pose_p, "pose of P");
  check_pose(pose_q, "pose of Q");
  front::check_direction(d);
  if (mixed_) return mesh3::cast(*mixed_, pose_p, pose_q, d);
  const front::Scale scale{exp_of(mesh_, scale_exp_)};
  if (mesh_)
    return cast_answer(scale, mesh3::cast(mesh_->pair(), engine_pose(scale, pose_p, "pose of P"), engine_pose(scale, pose_q, "pose of Q"), d));
  if (is_curved(engine_P_, engine_Q_))
    return cast_answer(scale, curved_query(scale, engine_P_, pose_p, engine_Q_, pose_q, [&](auto&&... a) {
                         return primitives::curved_cast(a..., d);
                       }));
  if (is_rounded(engine_P_, engine_Q_)) {
    const Pose3 ep = engine_pose(scale, pose_p, "pose of P"), eq = engine_pose(scale, pose_q, "pose of Q");
    return cast_answer(scale, primitives::rounded_cast(core_distance(engine_P_, ep, engine_Q_, eq),
                                                       core_compare(engine_P_, ep, engine_Q_, eq), engine_P_.radius(),
                                                       engine_Q_.radius(), d));
  }
  if (is_flat(engine_P_) || is_flat(engine_Q_))
    return cast_answer(scale, flat_cast(engine_P_, engine_pose(scale, pose_p, "pose of P"), engine_Q_,
                                        engine_pose(scale, pose_q, "pose of Q"), d));
  return cast_answer(scale, shape_cast(engine_P_.polytope(), engine_pose(scale, pose_p, "pose of P"),
                                       engine_Q_.polytope(), engine_pose(scale, pose_q, "pose of Q"), d));
}

// ---- warm start and trajectories (coherent motion, survey §3.3) -------------------------------
// The seed holds vertex indices of the engine shapes (scale-free); it belongs to this pair's
// engine polytopes (shared by copies of the pair).
Depth3 Pair3::minimum(const Pose3& pose_p, const Pose3& pose_q, WarmStart3& warm) const {
  check_pose(pose_p, "pose of P");
  check_pose(pose_q, "pose of Q");
  if (mesh_ || mixed_) return min_engine(pose_p, pose_q);  // no warm start on meshes
  if (is_flat(engine_P_) || is_flat(engine_Q_) || is_rounded(engine_P_, engine_Q_) || is_curved(engine_P_, engine_Q_))
    return min_engine(pose_p, pose_q);  // no warm start
  const front::Scale scale{exp_of(mesh_, scale_exp_)};
  const Pose3 ep = engine_pose(scale, pose_p, "pose of P"), eq = engine_pose(scale, pose_q, "pose of Q");
  const void *p = &engine_P_.polytope(), *q = &engine_Q_.polytope();
  convex3::ExpandSeed seed;
  static_assert(sizeof(seed.pairs) == sizeof(warm.pairs_));
  if (warm.valid_ && warm.p_ == p && warm.q_ == q) seed.pairs = warm.pairs_, seed.count = warm.count_, seed.valid = true;
  const Depth3 r = scale.answer(convex3::minimum_depth_seeded(engine_P_.polytope(), ep, engine_Q_.polytope(), eq, &seed));
  warm.p_ = p, warm.q_ = q, warm.pairs_ = seed.pairs, warm.count_ = seed.count, warm.valid_ = seed.valid;
  return r;
}

std::vector<Depth3> Pair3::trajectory(const Pose3& pose_p, std::span<const Pose3> poses_q, bool warm) const {
  check_pose(pose_p, "pose of P");
  check_poses(poses_q, poses_q.size(), exp_of(mesh_, scale_exp_));
  engine_pose(front::Scale{exp_of(mesh_, scale_exp_)}, pose_p, "pose of P");
  std::vector<Depth3> out(poses_q.size());
  WarmStart3 state;
  for (std::size_t i = 0; i < poses_q.size(); ++i)
    out[i] = warm ? minimum(pose_p, poses_q[i], state) : min_engine(pose_p, poses_q[i]);
  return out;
}

}  // namespace pendepth
