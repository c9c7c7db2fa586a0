// ConvexPolytope::hull: validation, exact hull, reduction to a strictly convex vertex set,
// half-edges, and the inner DK hierarchy (docs/algorithms.md §R4.2 step 1: hull libraries keep
// non-extreme points on facets and edges — CGAL issue #3192 — so the vertex set is filtered
// exactly).
//
// A hull vertex v is a proper extreme point iff its incident triangles span at least three
// distinct planes: a point in the relative interior of a facet sees one plane, of an edge two,
// while a true vertex is the apex of >= 3 facets. Non-extreme vertices are dropped and the hull
// of the remaining points is recomputed (all of them are extreme, so nothing more is dropped).
#include "convex3/polytope_data.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>
#include <sstream>

namespace pendepth {

using convex3::PolytopeData;
using predicates::collinear3;
using predicates::orient3d;

namespace {

[[noreturn]] void fail(std::string_view name, const std::string& what) {
  std::ostringstream os;
  os << name << ": " << what;
  throw InvalidInput(os.str());
}

// Four affinely independent points among ids (exact), or throws.
std::array<int, 4> find_tetrahedron(const std::vector<Vec3>& p, const std::vector<int>& ids,
                                    std::string_view name) {
  if (ids.empty()) fail(name, "no points (a polytope needs 4 affinely independent points)");
  int a = ids[0], b = -1, c = -1, d = -1;
  for (int i : ids)
    if (p[i] != p[a]) { b = i; break; }
  if (b < 0) fail(name, "all points coincide (need 4 affinely independent points)");
  for (int i : ids)
    if (!collinear3(p[a], p[b], p[i])) { c = i; break; }
  if (c < 0) fail(name, "all points are collinear (flat input; need 4 affinely independent points)");
  for (int i : ids)
    if (orient3d(p[a], p[b], p[c], p[i]) != 0) { d = i; break; }
  if (d < 0) fail(name, "all points are coplanar (flat input; need 4 affinely independent points)");
  return {a, b, c, d};
}

// Vertices of the triangulated hull that are not proper extreme points.
std::vector<char> non_extreme(const std::vector<Vec3>& p, const std::vector<std::array<int, 3>>& tris) {
  std::vector<std::vector<int>> inc(p.size());
  for (int f = 0; f < static_cast<int>(tris.size()); ++f)
    for (int v : tris[f]) inc[v].push_back(f);
  std::vector<char> bad(p.size(), 0);
  auto on_plane = [&](int f, int g) {  // triangle g lies in the plane of triangle f
    const auto& t = tris[f];
    for (int x : tris[g])  // shared vertices are skipped: exact zeros cost a GMP fallback
      if (x != t[0] && x != t[1] && x != t[2] && orient3d(p[t[0]], p[t[1]], p[t[2]], p[x]) != 0)
        return false;
    return true;
  };
  for (std::size_t v = 0; v < p.size(); ++v) {
    if (inc[v].empty()) continue;
    int f1 = inc[v][0], f2 = -1;
    bool third = false;
    for (int g : inc[v]) {
      if (on_plane(f1, g)) continue;
      if (f2 < 0) { f2 = g; continue; }
      if (!on_plane(f2, g)) { third = true; break; }
    }
    bad[v] = !third;
  }
  return bad;
}

}  // namespace

ConvexPolytope ConvexPolytope::hull(std::span<const Vec3> points, std::string_view name) {
  auto d = std::make_shared<PolytopeData>();
  d->name = std::string(name);
  std::vector<Vec3> pts(points.begin(), points.end());
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!pts[i].allFinite()) fail(name, "point " + std::to_string(i) + " has a non-finite coordinate");

  std::vector<int> ids(pts.size());
  std::iota(ids.begin(), ids.end(), 0);
  std::vector<std::array<int, 3>> tris;
  for (int pass = 0;; ++pass) {
    auto seed = find_tetrahedron(pts, ids, name);
    tris = convex3::incremental_hull(pts, ids, seed);
    auto bad = non_extreme(pts, tris);
    std::vector<int> keep;
    bool dropped = false;
    std::vector<char> used(pts.size(), 0);
    for (const auto& t : tris)
      for (int v : t) used[v] = 1;
    for (int i : ids) {
      if (!used[i]) continue;
      if (bad[i]) dropped = true;
      else keep.push_back(i);
    }
    if (!dropped) break;
    ids = std::move(keep);
  }

  // Compact to vertex ids 0..n-1 in input order.
  std::vector<int> newid(pts.size(), -1);
  for (const auto& t : tris)
    for (int v : t) newid[v] = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (newid[i] == 0) {
      newid[i] = static_cast<int>(d->v.size());
      d->v.push_back(pts[i]);
      d->input_index.push_back(i);
    }
  for (auto& t : tris) {
    for (int& v : t) v = newid[v];
    d->tris.push_back(t);
  }

  convex3::DKLevel base;
  base.fv.reserve(3 * d->tris.size());
  for (const auto& t : d->tris) base.fv.insert(base.fv.end(), t.begin(), t.end());
  bool ok = convex3::build_twins(base.fv, base.twin);
  (void)ok;
  assert(ok && "hull surface is not a closed 2-manifold");
  base.verts.resize(d->v.size());
  std::iota(base.verts.begin(), base.verts.end(), 0);
  d->vertex_he.assign(d->v.size(), -1);
  for (int h = 0; h < static_cast<int>(base.fv.size()); ++h) {
    d->vertex_he[base.fv[h]] = h;
    int g = base.twin[h];
    if (h < g && orient3d(d->v[base.fv[h]], d->v[base.target(h)], d->v[base.target(base.next(h))],
                          d->v[base.target(base.next(g))]) != 0)
      d->edges.push_back(h);
  }
  d->levels.push_back(std::move(base));
  convex3::build_dk_hierarchy(*d);

  ConvexPolytope P;
  P.d_ = std::move(d);
  return P;
}

ConvexPolytope ConvexPolytope::scaled(int exponent) const {
  auto d = std::make_shared<PolytopeData>(*d_);  // the caches' copies start empty
  for (std::size_t i = 0; i < d->v.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = d_->v[i][k], y = std::ldexp(x, exponent);
      if (!std::isfinite(y) || std::ldexp(y, -exponent) != x)
        fail(d->name, "vertex " + std::to_string(i) + " cannot be scaled by 2^" + std::to_string(exponent) +
                          " exactly");
      d->v[i][k] = y;
    }
  ConvexPolytope P;
  P.d_ = std::move(d);
  return P;
}

std::size_t ConvexPolytope::size() const { return d_->v.size(); }
const convex3::PolytopeData& convex3::data_of(const ConvexPolytope& P) { return *P.d_; }
const Vec3& ConvexPolytope::operator[](std::size_t i) const { return d_->v[i]; }
std::span<const Vec3> ConvexPolytope::vertices() const { return d_->v; }
std::span<const std::array<int, 3>> ConvexPolytope::triangles() const { return d_->tris; }
int ConvexPolytope::twin(int h) const { return d_->levels[0].twin[h]; }
std::size_t ConvexPolytope::input_index(std::size_t i) const { return d_->input_index[i]; }
const std::string& ConvexPolytope::name() const { return d_->name; }
std::size_t ConvexPolytope::hierarchy_levels() const { return d_->levels.size(); }
std::vector<std::size_t> ConvexPolytope::level_sizes() const {
  std::vector<std::size_t> s;
  for (const auto& l : d_->levels) s.push_back(l.verts.size());
  return s;
}
std::vector<std::array<int, 3>> ConvexPolytope::level_triangles(std::size_t i) const {
  const auto& fv = d_->levels.at(i).fv;
  std::vector<std::array<int, 3>> t(fv.size() / 3);
  for (std::size_t f = 0; f < t.size(); ++f) t[f] = {fv[3 * f], fv[3 * f + 1], fv[3 * f + 2]};
  return t;
}

}  // namespace pendepth
