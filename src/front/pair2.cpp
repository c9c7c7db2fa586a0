// pendepth — Pair2: one front door over the 2D engines (include/pendepth/pendepth.hpp).
//
// The engine is chosen once, at construction, from the shapes' kinds and Prepare (the rule is
// documented at Prepare), and so is the path of every query kind: answers never depend on the
// order of the calls. Structures that serve one query kind only (the convex depth field for σ,
// PairDepth2's separation next to a no-fit polygon, the exported no-fit polygon) are built on
// first use, under std::call_once.
#include <pendepth/depth2_polygon_polygon.hpp>
#include <pendepth/depth2_polygon_convex.hpp>
#include <pendepth/nfp2.hpp>
#include <pendepth/pendepth.hpp>

#include "front/batch.hpp"
#include "front/checks.hpp"
#include "front/pair2_flat.hpp"
#include "convex2/convex_cast.hpp"
#include "front/scale.hpp"
#include "front/shape2_data.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "nonconvex2/boundary_distance.hpp"
#include "polygon2/query_impl.hpp"

#include <cmath>
#include <mutex>
#include <optional>

namespace pendepth {

const char* to_string(Engine2 e) {
  switch (e) {
    case Engine2::Convex: return "convex";
    case Engine2::PolygonConvex: return "polygon-convex";
    case Engine2::PolygonConvexSwapped: return "convex-polygon";
    case Engine2::PairPerQuery: return "pair-per-query";
    case Engine2::NoFitPolygon: return "no-fit-polygon";
    case Engine2::Flat: return "flat";
  }
  return "?";
}

namespace {

NoFitPolygonParts parts_of(const NoFitPolygon2& n) {
  return NoFitPolygonParts{n.polygons(), n.slits(), n.points()};
}

// The no-fit polygon's rings of two solid shapes (engine coordinates) from their shared per-shape
// sides (front/shape2_data.hpp), without the query structures (NoFitPolygon2::Impl, queries
// false): the same bits as NoFitPolygon2(P.polygon(), Q.polygon())'s export.
NoFitPolygonParts export_only(const Shape2& P, const Shape2& Q) {
  NoFitPolygon2::Impl I(front::shape_side(P, false), front::shape_side(Q, true), false);
  return NoFitPolygonParts{std::move(I.polys), std::move(I.slits), std::move(I.points)};
}

// The sizes of a shape's normal form: its largest coordinate and its smallest edge.
void add_extent(front::Extent& x, const Shape2& s) {
  for (const auto& ring : s.rings())
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 &a = ring[i], &b = ring[i + 1 == ring.size() ? 0 : i + 1];
      x.add_point(std::max(std::abs(a.x()), std::abs(a.y())));
      x.add_edge(a, b);
    }
}

// The pair's scale (src/front/scale.hpp): identity for every pair inside the comfort band.
front::Scale pair_scale(const Shape2& P, const Shape2& Q) {
  front::Extent x;
  add_extent(x, P);
  add_extent(x, Q);
  return front::Scale::for_pair(x, front::kBand2);
}

// `s` in engine coordinates: a copy scaled by 2^-e (exact, checked), with the same normal form
// and so the same feature numbering (scaling by a power of two keeps every orientation).
Shape2 engine_shape_fresh(const Shape2& s, const front::Scale& scale, const char* which) {
  auto rings = s.rings();
  if (s.dimension() < 2) {  // a point or a segment
    for (Vec2& p : rings[0]) p = scale.vec_to_engine(p, std::string(which) + " (" + s.name() + "):");
    return rings[0].size() == 1 ? Shape2::point(rings[0][0], s.name()) : Shape2::segment(rings[0][0], rings[0][1], s.name());
  }
  for (std::size_t k = 0; k < rings.size(); ++k)
    for (std::size_t i = 0; i < rings[k].size(); ++i)
      rings[k][i] = scale.vec_to_engine(rings[k][i], std::string(which) + " (" + s.name() + ") ring " +
                                                         std::to_string(k) + " vertex " + std::to_string(i) + ":");
  if (s.is_convex()) return Shape2(ConvexPolygon(rings[0], s.name()));
  return Shape2(Polygon(rings, s.name()));
}

// The same, made once per shape and exponent and shared by every pair scaled alike (with the
// scaled copy's per-shape caches): whether it throws, and what, depends only on the shape and
// the exponent, so a cached copy is what a fresh one would be.
Shape2 engine_shape(const Shape2& s, const front::Scale& scale, const char* which) {
  if (scale.identity()) return s;
  return front::scaled_shape(s, scale.e, [&] { return engine_shape_fresh(s, scale, which); });
}

// Parts in engine coordinates back to input coordinates.
NoFitPolygonParts scaled_back(NoFitPolygonParts parts, const front::Scale& scale) {
  if (scale.identity()) return parts;
  for (auto& poly : parts.polygons)
    for (auto& ring : poly)
      for (Vec2& v : ring) v = scale.vec(v);
  for (auto& s : parts.slits) s = {scale.vec(s[0]), scale.vec(s[1])};
  for (Vec2& v : parts.points) v = scale.vec(v);
  return parts;
}

}  // namespace

NoFitPolygonParts no_fit_polygon(const Shape2& P, const Shape2& Q) {
  if (P.dimension() < 2 || Q.dimension() < 2) return Pair2(P, Q, Prepare::Queries).no_fit_polygon();
  const front::Scale scale = pair_scale(P, Q);
  const Shape2 Pe = engine_shape(P, scale, "P"), Qe = engine_shape(Q, scale, "Q");
  return scaled_back(export_only(Pe, Qe), scale);
}

// Pair2::Impl answers in engine coordinates (P, Q scaled by 2^-scale.e, see src/front/scale.hpp);
// the public methods convert placements in and answers out.
struct Pair2::Impl {
  Shape2 input_P, input_Q;  // as given (P(), Q(), feature numbering)
  front::Scale scale;
  Shape2 P, Q;              // engine coordinates (the same objects when scale is the identity)
  Prepare prepare;
  Engine2 engine;

  // Convex × convex: σ by the depth field (built on the first σ query) or by the merge.
  bool use_field = false;
  mutable std::optional<DepthField> field;
  mutable std::once_flag field_once;

  // Polygon × convex (either way round): P' = the polygon, Q' = the convex shape.
  std::optional<PolygonDepth2> polygon;

  // Polygon × polygon.
  mutable std::optional<PairDepth2> pair;  // PairPerQuery: built at once; NoFitPolygon: separation only
  mutable std::once_flag pair_once;
  std::optional<NoFitPolygon2> nfp;

  // Signed distance and cast of non-overlapping placements (every engine), built on first use.
  mutable std::optional<nonconvex2::BoundaryPair2> boundary;
  mutable std::once_flag boundary_once;

  // A point or a segment against a solid (issue 16 item 4): the one engine of every query.
  std::optional<front::FlatPair2> flat;

  // The exported no-fit polygon (no_fit_polygon()).
  mutable std::optional<NoFitPolygonParts> exported;
  mutable std::once_flag export_once;

  Impl(Shape2 p, Shape2 q, Prepare prep)
      : input_P(std::move(p)),
        input_Q(std::move(q)),
        scale(pair_scale(input_P, input_Q)),
        P(engine_shape(input_P, scale, "P")),
        Q(engine_shape(input_Q, scale, "Q")),
        prepare(prep) {
    choose_engine();
    build();
  }

  void choose_engine() {
    if (P.dimension() < 2 || Q.dimension() < 2) {
      engine = Engine2::Flat;
      flat.emplace(P, Q);
    } else if (P.is_convex() && Q.is_convex()) {
      engine = Engine2::Convex;
      use_field = prepare == Prepare::Full ||
                  (prepare == Prepare::Auto && P.size() + Q.size() > Pair2::kFieldAutoSize);
    } else if (Q.is_convex()) {
      engine = Engine2::PolygonConvex;
    } else if (P.is_convex()) {
      engine = Engine2::PolygonConvexSwapped;
    } else if (prepare == Prepare::Full ||
               (prepare == Prepare::Auto && P.size() * Q.size() <= Pair2::kNfpAutoLimit)) {
      engine = Engine2::NoFitPolygon;
    } else {
      engine = Engine2::PairPerQuery;
    }
  }

  void build() {
    switch (engine) {
      case Engine2::Flat: break;
      case Engine2::Convex:
        if (prepare == Prepare::Full) depth_field();
        break;
      case Engine2::PolygonConvex: polygon.emplace(polygon_engine_of(P, Q)); break;
      case Engine2::PolygonConvexSwapped: polygon.emplace(polygon_engine_of(Q, P)); break;
      case Engine2::PairPerQuery: pair.emplace(pair_engine_of(P, Q)); break;
      case Engine2::NoFitPolygon:
        nfp.emplace(nfp_from_impl(std::make_unique<NoFitPolygon2::Impl>(front::shape_side(P, false), front::shape_side(Q, true))));
        break;
    }
  }

  const DepthField& depth_field() const {
    std::call_once(field_once, [&] { field.emplace(P.convex(), Q.convex()); });
    return *field;
  }

  const PairDepth2& pair_engine() const {
    std::call_once(pair_once, [&] {
      if (!pair) pair.emplace(pair_engine_of(P, Q));
    });
    return *pair;
  }

  // PolygonDepth2 with the polygon's shared triangulation: the same bits as
  // PolygonDepth2(p.polygon(), c.convex()).
  static PolygonDepth2 polygon_engine_of(const Shape2& p, const Shape2& c) {
    return polygon_depth_from_impl(std::make_unique<PolygonDepth2::Impl>(p.polygon(), c.convex(), &front::shape_cache(p).triangles(p.polygon())));
  }

  // PairDepth2 on the shapes' shared per-shape sides (front/shape2_data.hpp): the same bits as
  // PairDepth2(P.polygon(), Q.polygon()), without re-triangulating per pair.
  static PairDepth2 pair_engine_of(const Shape2& p, const Shape2& q) {
    return pair_from_impl(std::make_unique<PairDepth2::Impl>(front::shape_side(p, false), front::shape_side(q, true)));
  }

  bool swapped() const { return engine == Engine2::PolygonConvexSwapped; }

  // An answer of the swapped problem (Q fixed at 0, P placed at −t, moved by v') mapped back:
  // Q + t overlaps P exactly when P − t overlaps Q, so v = −v', features swap, and a point x of
  // the swapped frame after the move is x + t + v in P's frame.
  static Depth2 back(Depth2 r, const Vec2& t) {
    const Vec2 zero(0, 0);
    r.translation = zero - r.translation;  // 0 − x, never −0
    r.normal = zero - r.normal;
    std::swap(r.feature_p, r.feature_q);
    if (r.overlapping || r.depth > 0) {
      const Vec2 shift = t + r.translation;
      const Vec2 wp = r.witness_q + shift, wq = r.witness_p + shift;
      r.witness_p = wp;
      r.witness_q = wq;
    }
    return r;
  }

  // ---- single queries on validated input (t finite; d finite and non-zero) ----

  bool overlapping(const Vec2& t) const {
    switch (engine) {
      case Engine2::Flat: return flat->overlapping(t);
      case Engine2::Convex: return directional_depth(P.convex(), Q.convex(), t, Vec2(1, 0)).overlapping;
      case Engine2::PolygonConvex: return polygon->overlapping(t);
      case Engine2::PolygonConvexSwapped: return polygon->overlapping(-t);
      case Engine2::PairPerQuery: return pair->overlapping(t);
      case Engine2::NoFitPolygon: return nfp->overlapping(t);
    }
    return false;
  }

  Depth2 minimum(const Vec2& t) const {
    switch (engine) {
      case Engine2::Flat: return flat->minimum(t);
      case Engine2::Convex:
        return use_field ? depth_field().minimum(t) : minimum_depth(P.convex(), Q.convex(), t);
      case Engine2::PolygonConvex: return polygon->minimum(t);
      case Engine2::PolygonConvexSwapped: return back(polygon->minimum(-t), t);
      case Engine2::PairPerQuery: return pair->minimum(t);
      case Engine2::NoFitPolygon: return nfp->minimum(t);
    }
    return {};
  }

  Depth2 along(const Vec2& t, const Vec2& d) const {
    switch (engine) {
      case Engine2::Flat: return flat->along(t, d);
      case Engine2::Convex: return directional_depth(P.convex(), Q.convex(), t, d);
      case Engine2::PolygonConvex: return polygon->along(t, d);
      case Engine2::PolygonConvexSwapped: return back(polygon->along(-t, -d), t);
      case Engine2::PairPerQuery: return pair->along(t, d);
      case Engine2::NoFitPolygon: return nfp->along(t, d);
    }
    return {};
  }

  // The lean queries: the no-fit polygon's own, else the full answer's fields.
  DepthValue2 minimum_value(const Vec2& t) const {
    if (engine == Engine2::NoFitPolygon) return nfp->depth_value(t);
    const Depth2 r = minimum(t);
    return {r.depth, r.translation, r.overlapping};
  }
  DepthValue2 along_value(const Vec2& t, const Vec2& d) const {
    if (engine == Engine2::NoFitPolygon) return nfp->directional_depth_value(t, d);
    const Depth2 r = along(t, d);
    return {r.depth, r.translation, r.overlapping};
  }

  Depth2 separation(const Vec2& t, const Vec2& d) const {
    switch (engine) {
      case Engine2::Flat: return flat->separation(t, d);
      case Engine2::Convex: return separation_depth(P.convex(), Q.convex(), t, d);
      case Engine2::PolygonConvex: return polygon->separation(t, d);
      case Engine2::PolygonConvexSwapped:
        return back(polygon->separation(-t, -d), t);
      case Engine2::PairPerQuery:
      case Engine2::NoFitPolygon: return pair_engine().separation(t, d);
    }
    return {};
  }

  // Signed distance (issue 16 item 2): overlapping placements from the engine's σ (Distance2's
  // witness_q is on the unmoved Q), the others on the boundaries (src/nonconvex2/boundary_distance).
  const nonconvex2::BoundaryPair2& boundary_engine() const {
    std::call_once(boundary_once, [&] {  // the edge trees are per shape (shape_side.hpp)
      boundary.emplace(P.polygon(), Q.polygon(), front::shape_cache(P).edge_tree(P.polygon()), front::shape_cache(Q).edge_tree(Q.polygon()));
    });
    return *boundary;
  }

  Distance2 signed_distance(const Vec2& t) const {
    if (flat) return flat->signed_distance(t);
    if (!overlapping(t)) {
      // Two convex shapes with n + m > 64: the nearest vertex of M located by binary searches,
      // then measured exactly on its few segments (src/convex2/convex_cast.hpp); smaller pairs
      // and the rest: the boundary search (faster below about 64 + 64 vertices, measured in
      // bench_convex2: 1.9 against 4.1 µs at 16 + 16, 7.7 against 5.4 µs at 64 + 64).
      if (engine == Engine2::Convex && P.size() + Q.size() > 64)
        if (const auto v = convex2::convex_nearest_vertex(P.convex(), Q.convex(), t))
          return boundary_engine().distance_near(t, (*v)[0], (*v)[1]);
      return boundary_engine().distance(t);
    }
    return polygon2::overlap_distance(minimum(t));
  }

  // Shape cast (issue 16 item 3): 0 when overlapping, else the first contact: the ray's entry
  // into M in O(log) for two convex shapes (the boundaries when the line is tangent to M), the
  // first boundary contact for the others.
  Cast2 cast(const Vec2& t, const Vec2& d) const {
    if (flat) return flat->cast(t, d);
    if (!overlapping(t)) {
      if (engine == Engine2::Convex)
        if (auto r = convex2::convex_cast(P.convex(), Q.convex(), t, d)) return *r;
      return boundary_engine().cast(t, d);
    }
    Cast2 r;
    r.hit = r.overlapping = true;
    return r;
  }

  const NoFitPolygonParts& no_fit_polygon() const {
    std::call_once(export_once, [&] {
      if (flat) {
        exported.emplace(scaled_back(flat->parts(), scale));
        return;
      }
      exported.emplace(scaled_back(nfp ? parts_of(*nfp) : export_only(P, Q), scale));
    });
    return *exported;
  }
};

Pair2::Pair2(Shape2 P, Shape2 Q, Prepare prepare)
    : impl_(std::make_shared<const Impl>(std::move(P), std::move(Q), prepare)) {}

namespace {

// A placement in engine coordinates; throws InvalidInput naming it when it has none (see
// src/front/scale.hpp). The identity scale returns t unchanged.
Vec2 engine_placement(const front::Scale& scale, const Vec2& t, std::string_view what = "placement") {
  return scale.vec_to_engine(t, [&] { return std::string(what) + " " + front::text(t) + ":"; });
}

// Every placement of a batch in engine coordinates, checked before any query runs.
void check_batch_scale(const front::Scale& scale, std::span<const Vec2> ts) {
  if (scale.identity()) return;
  for (std::size_t i = 0; i < ts.size(); ++i) engine_placement(scale, ts[i], "batch: placement " + std::to_string(i));
}

}  // namespace

// The hot path of the three queries (issue 19 item 1): an ordinary pair (identity scale) and a
// finite placement go straight to the engine; everything else takes the checked path, which
// throws the boundary's messages.
namespace {
bool plain(const front::Scale& scale, const Vec2& t) { return scale.identity() && std::isfinite(t.x()) && std::isfinite(t.y()); }
}  // namespace

bool Pair2::overlapping(const Vec2& t) const {
  const Impl& I = *impl_;
  if (plain(I.scale, t)) [[likely]]
    return I.overlapping(t);
  front::check_placement(t);
  return I.overlapping(engine_placement(I.scale, t));
}

Depth2 Pair2::minimum(const Vec2& t) const {
  const Impl& I = *impl_;
  if (plain(I.scale, t)) [[likely]]
    return I.minimum(t);
  front::check_placement(t);
  return I.scale.answer(I.minimum(engine_placement(I.scale, t)));
}

Depth2 Pair2::along(const Vec2& t, const Vec2& d) const {
  const Impl& I = *impl_;
  if (plain(I.scale, t) && std::isfinite(d.x()) && std::isfinite(d.y()) && (d.x() != 0 || d.y() != 0)) [[likely]]
    return I.along(t, d);
  front::check_placement(t);
  front::check_direction(d);
  return I.scale.answer(I.along(engine_placement(I.scale, t), d));
}

namespace {
// A lean answer in engine coordinates back to input units (as Scale::answer does for Depth2).
DepthValue2 scaled_value(const front::Scale& scale, DepthValue2 r) {
  if (scale.identity()) return r;
  r.depth = scale.length(r.depth);
  r.translation = scale.vec(r.translation);
  return r;
}
}  // namespace

DepthValue2 Pair2::depth_value(const Vec2& t) const {
  const Impl& I = *impl_;
  if (plain(I.scale, t)) [[likely]]
    return I.minimum_value(t);
  front::check_placement(t);
  return scaled_value(I.scale, I.minimum_value(engine_placement(I.scale, t)));
}

DepthValue2 Pair2::directional_depth_value(const Vec2& t, const Vec2& d) const {
  const Impl& I = *impl_;
  if (plain(I.scale, t) && std::isfinite(d.x()) && std::isfinite(d.y()) && (d.x() != 0 || d.y() != 0)) [[likely]]
    return I.along_value(t, d);
  front::check_placement(t);
  front::check_direction(d);
  return scaled_value(I.scale, I.along_value(engine_placement(I.scale, t), d));
}

Depth2 Pair2::separation(const Vec2& t, const Vec2& d) const {
  front::check_placement(t);
  front::check_direction(d);
  const Impl& I = *impl_;
  return I.scale.answer(I.separation(engine_placement(I.scale, t), d));
}

void Pair2::overlapping(std::span<const Vec2> ts, std::span<bool> out, unsigned threads) const {
  front::check_batch<Vec2>(ts, {}, out.size(), false);
  const Impl& I = *impl_;
  check_batch_scale(I.scale, ts);
  front::parallel_for(ts.size(), threads,
                      [&](std::size_t i) { out[i] = I.overlapping(engine_placement(I.scale, ts[i])); });
}

void Pair2::minimum(std::span<const Vec2> ts, std::span<Depth2> out, unsigned threads) const {
  front::check_batch<Vec2>(ts, {}, out.size(), false);
  const Impl& I = *impl_;
  check_batch_scale(I.scale, ts);
  front::parallel_for(ts.size(), threads, [&](std::size_t i) {
    out[i] = I.scale.answer(I.minimum(engine_placement(I.scale, ts[i])));
  });
}

namespace {

// A directional batch: query(t, d) for every placement (in engine coordinates), with ds[i] or
// the one direction ds[0]; answers scaled back.
template <class Query>
void directional_batch(const front::Scale& scale, std::span<const Vec2> ts, std::span<const Vec2> ds,
                       std::span<Depth2> out, unsigned threads, Query&& query) {
  front::check_batch<Vec2>(ts, ds, out.size(), true);
  check_batch_scale(scale, ts);
  if (ts.empty()) return;
  const bool one = ds.size() == 1;
  front::parallel_for(ts.size(), threads, [&](std::size_t i) {
    out[i] = scale.answer(query(engine_placement(scale, ts[i]), ds[one ? 0 : i]));
  });
}

}  // namespace

void Pair2::along(std::span<const Vec2> ts, std::span<const Vec2> ds, std::span<Depth2> out,
                  unsigned threads) const {
  const Impl& I = *impl_;
  directional_batch(I.scale, ts, ds, out, threads, [&](const Vec2& t, const Vec2& d) { return I.along(t, d); });
}

void Pair2::separation(std::span<const Vec2> ts, std::span<const Vec2> ds, std::span<Depth2> out,
                       unsigned threads) const {
  const Impl& I = *impl_;
  directional_batch(I.scale, ts, ds, out, threads,
                    [&](const Vec2& t, const Vec2& d) { return I.separation(t, d); });
}

namespace {

// A Distance2 or Cast2 in engine coordinates back to input units (as Scale::answer for Depth2;
// an infinite cast distance stays infinite).
template <class R>
R scaled_answer(const front::Scale& scale, R r) {
  if (scale.identity()) return r;
  r.distance = scale.length(r.distance);
  r.translation = scale.vec(r.translation);
  r.witness_p = scale.vec(r.witness_p);
  r.witness_q = scale.vec(r.witness_q);
  return r;
}

}  // namespace

Distance2 Pair2::signed_distance(const Vec2& t) const {
  front::check_placement(t);
  const Impl& I = *impl_;
  return scaled_answer(I.scale, I.signed_distance(engine_placement(I.scale, t)));
}

Cast2 Pair2::cast(const Vec2& t, const Vec2& d) const {
  front::check_placement(t);
  front::check_direction(d);
  const Impl& I = *impl_;
  return scaled_answer(I.scale, I.cast(engine_placement(I.scale, t), d));
}

void Pair2::signed_distance(std::span<const Vec2> ts, std::span<Distance2> out, unsigned threads) const {
  front::check_batch<Vec2>(ts, {}, out.size(), false);
  const Impl& I = *impl_;
  check_batch_scale(I.scale, ts);
  front::parallel_for(ts.size(), threads, [&](std::size_t i) {
    out[i] = scaled_answer(I.scale, I.signed_distance(engine_placement(I.scale, ts[i])));
  });
}

const Pair2::NoFitPolygon& Pair2::no_fit_polygon() const { return impl_->no_fit_polygon(); }
const Shape2& Pair2::P() const { return impl_->input_P; }
const Shape2& Pair2::Q() const { return impl_->input_Q; }
Engine2 Pair2::engine() const { return impl_->engine; }

}  // namespace pendepth
