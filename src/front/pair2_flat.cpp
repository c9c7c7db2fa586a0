// Pair2 with a point or a segment: the roles and the swap (src/front/pair2_flat.hpp).
#include "front/pair2_flat.hpp"

#include <utility>

namespace pendepth::front {

namespace {

const Shape2& solid_of(const Shape2& P, const Shape2& Q) {
  if (P.dimension() < 2 && Q.dimension() < 2)
    throw InvalidInput("pair: P (" + P.name() + ") and Q (" + Q.name() +
                       ") are both lower-dimensional (a point or a segment); one of them must be a solid polygon");
  return Q.dimension() < 2 ? P : Q;
}

const Shape2& flat_of(const Shape2& P, const Shape2& Q) { return Q.dimension() < 2 ? Q : P; }

const Vec2 kZero(0, 0);

// The answer of the swapped problem (Q fixed at 0, P placed at −t and moved by v') mapped back
// (as Pair2's convex × polygon swap): v = −v', features swap, a point x of the swapped frame after
// the move is x + t + v in P's frame; the signed distance's witnesses are on the unmoved shapes.
Depth2 back(Depth2 r, const Vec2& t) {
  r.translation = kZero - r.translation;
  r.normal = kZero - r.normal;
  std::swap(r.feature_p, r.feature_q);
  if (r.overlapping || r.depth > 0) {
    const Vec2 shift = t + r.translation;
    const Vec2 wp = r.witness_q + shift, wq = r.witness_p + shift;
    r.witness_p = wp;
    r.witness_q = wq;
  }
  return r;
}

}  // namespace

FlatPair2::FlatPair2(const Shape2& P, const Shape2& Q)
    : swapped(Q.dimension() == 2),
      engine(solid_of(P, Q).rings(), solid_of(P, Q).is_convex(), flat_of(P, Q).flat_vertices()) {}

bool FlatPair2::overlapping(const Vec2& t) const { return engine.overlapping(swapped ? kZero - t : t); }

Depth2 FlatPair2::minimum(const Vec2& t) const { return swapped ? back(engine.minimum(kZero - t), t) : engine.minimum(t); }

Depth2 FlatPair2::along(const Vec2& t, const Vec2& d) const {
  return swapped ? back(engine.along(kZero - t, kZero - d), t) : engine.along(t, d);
}

Depth2 FlatPair2::separation(const Vec2& t, const Vec2& d) const {
  return swapped ? back(engine.separation(kZero - t, kZero - d), t) : engine.separation(t, d);
}

Distance2 FlatPair2::signed_distance(const Vec2& t) const {
  if (!swapped) return engine.signed_distance(t);
  Distance2 r = engine.signed_distance(kZero - t);
  r.translation = kZero - r.translation;
  r.normal = kZero - r.normal;
  std::swap(r.feature_p, r.feature_q);
  const Vec2 wp = r.witness_q + t, wq = r.witness_p + t;
  r.witness_p = wp;
  r.witness_q = wq;
  return r;
}

Cast2 FlatPair2::cast(const Vec2& t, const Vec2& d) const {
  if (!swapped) return engine.cast(t, d);
  Cast2 r = engine.cast(kZero - t, kZero - d);
  r.translation = kZero - r.translation;
  r.normal = kZero - r.normal;
  std::swap(r.feature_p, r.feature_q);
  if (r.hit && !r.overlapping) {
    const Vec2 shift = t + r.translation;
    const Vec2 wp = r.witness_q + shift, wq = r.witness_p + shift;
    r.witness_p = wp;
    r.witness_q = wq;
  }
  return r;
}

NoFitPolygonParts FlatPair2::parts() const {
  NoFitPolygonParts p = engine.parts();
  if (swapped)  // M of the swapped pair is −M (a half turn keeps every ring's orientation)
    for (auto& poly : p.polygons)
      for (auto& ring : poly)
        for (Vec2& v : ring) v = kZero - v;
  return p;
}

}  // namespace pendepth::front
