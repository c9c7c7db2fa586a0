// Validation of a closed triangle mesh (include/pendepth/mesh3.hpp; docs/algorithms.md "Mesh
// validation"). Every decision is an exact predicate on the input doubles:
//   1. faces → triangles: a triangle must not be collinear (exact collinear3); a larger face must
//      be planar (exact orient3d) and strictly convex (every corner turning the same way by exact
//      orient2d in a projection that keeps its orientation, and winding once: exact polar-angle
//      comparisons of consecutive edges; O(k)) and is split into a fan;
//   2. edges (sorted half-edges): each undirected edge in exactly two triangles, once in each
//      direction (closed, edge-manifold, consistently oriented);
//   3. vertices: the triangles around a vertex form one fan (walk through the twins);
//   4. one connected surface;
//   5. no self-intersection: pairs of triangles whose closed bounding boxes meet (CGAL's
//      box_self_intersection_d — the project's box tree is 2D) are tested with CGAL's exact
//      triangle predicates (Epick: filtered, exact fallback): disjoint triangles must not meet;
//      triangles sharing only vertex v — T1 = (v, a, b), T2 = (v, c, d) — meet beyond v iff
//      segment ab meets T2 or cd meets T1 (the intersection is convex and contains v, so a ray
//      from v through another common point leaves each triangle through its opposite edge; the
//      nearer exit is in both); triangles sharing an edge overlap beyond it iff coplanar with
//      their third vertices on the same side of it;
//   6. volume: the exact sign of Σ det(a, b, c) (double with a forward error bound, GMP
//      rationals when the bound cannot decide); negative → every triangle reversed;
//   7. convexity: every edge convex (the opposite vertex of the neighbour triangle not above the
//      triangle's plane: exact orient3d). A connected closed embedded surface that is locally
//      convex at every edge bounds a convex body (Tietze–Nakajima), so this is exact.
// Complexity: O(n log n) for n triangles plus the box pairs (O(n) on meshes with well-shaped
// triangles).
#include <pendepth/mesh3.hpp>

#include "mesh3/mesh_impl.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace pendepth {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;

[[noreturn]] void fail(const io::MeshFile& f, std::size_t face, std::string_view name, const std::string& what) {
  throw InvalidInput(f.face_where(face) + ": " + std::string(name) + ": " + what);
}

// Exact sign of Σ det(a, b, c) over the triangles (6 × the signed volume).
int volume_sign(const std::vector<Vec3>& p, const std::vector<std::array<std::size_t, 3>>& tris, double& approx) {
  double sum = 0, mag = 0;
  for (const auto& t : tris) {
    const Vec3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    sum += a.x() * (b.y() * c.z() - b.z() * c.y()) + a.y() * (b.z() * c.x() - b.x() * c.z()) +
           a.z() * (b.x() * c.y() - b.y() * c.x());
    mag += std::abs(a.x()) * (std::abs(b.y() * c.z()) + std::abs(b.z() * c.y())) +
           std::abs(a.y()) * (std::abs(b.z() * c.x()) + std::abs(b.x() * c.z())) +
           std::abs(a.z()) * (std::abs(b.x() * c.y()) + std::abs(b.y() * c.x()));
  }
  approx = sum / 6;
  // Each term errs by ≤ 5u times its permanent, the running sum by ≤ n·u times the sum of the
  // permanents (u = 2^-53); twice that, plus an underflow allowance per term.
  const double n = static_cast<double>(tris.size());
  const double bound = mag * (n + 8) * 0x1p-52 + (n + 1) * 0x1p-1000;
  if (std::isfinite(sum) && std::isfinite(bound) && std::abs(sum) > bound) return sum > 0 ? 1 : -1;
  mpq_class s = 0;
  for (const auto& t : tris) {
    const Vec3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    mpq_class ax(a.x()), ay(a.y()), az(a.z()), bx(b.x()), by(b.y()), bz(b.z()), cx(c.x()), cy(c.y()), cz(c.z());
    s += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
  }
  return sgn(s);
}

// Splits face f (k ≥ 3 vertices) into triangles, or throws.
void triangulate_face(const io::MeshFile& file, std::size_t f, std::string_view name,
                      std::vector<std::array<std::size_t, 3>>& tris, std::vector<std::size_t>& face_of) {
  const std::size_t b = file.face_start[f], e = file.face_start[f + 1], k = e - b;
  const auto idx = [&](std::size_t i) { return file.indices[b + i]; };
  const auto pt = [&](std::size_t i) -> const Vec3& { return file.points[idx(i)]; };
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j)
      if (idx(i) == idx(j)) fail(file, f, name, "the face repeats vertex " + file.vertex_name(idx(i)));
  if (k == 3) {
    if (predicates::collinear3(pt(0), pt(1), pt(2)))
      fail(file, f, name, "zero-area face (its three vertices are collinear)");
    tris.push_back({idx(0), idx(1), idx(2)});
    face_of.push_back(f);
    return;
  }
  std::size_t c = 2;
  while (c < k && predicates::collinear3(pt(0), pt(1), pt(c))) ++c;
  if (c == k) fail(file, f, name, "zero-area face (its " + std::to_string(k) + " vertices are collinear)");
  for (std::size_t i = 2; i < k; ++i)
    if (predicates::orient3d(pt(0), pt(1), pt(c), pt(i)) != 0)
      fail(file, f, name, "a face of " + std::to_string(k) + " vertices is not planar (vertex " + file.vertex_name(idx(i)) +
                              " is off the plane of the first three): give triangles");
  // Drop the axis along which the plane's normal has a non-zero component: orient2d of the
  // projections then has the sign of the in-plane orientation (times a fixed sign).
  int drop = 0;
  const auto proj = [&](const Vec3& v, int d) { return d == 0 ? Vec2(v.y(), v.z()) : d == 1 ? Vec2(v.z(), v.x()) : Vec2(v.x(), v.y()); };
  while (predicates::orient2d(proj(pt(0), drop), proj(pt(1), drop), proj(pt(c), drop)) == 0) ++drop;
  // Strictly convex ⇔ every corner turns the same way (exact orient2d, no collinear corner) and
  // the boundary winds once: the edge directions, turning monotonically, pass the +x direction
  // exactly once (exact polar-angle comparisons). O(k).
  const auto q = [&](std::size_t i) { return proj(pt(i % k), drop); };
  const int turn = predicates::orient2d(q(0), q(1), q(2));
  std::size_t wraps = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const int s = predicates::orient2d(q(i), q(i + 1), q(i + 2));
    if (s == 0 || s != turn)
      fail(file, f, name, "a face of " + std::to_string(k) + " vertices is not a strictly convex polygon (its corner at vertex " +
                              file.vertex_name(idx((i + 1) % k)) + (s == 0 ? " is straight" : " turns the other way") +
                              "): give triangles");
    // Edge i+1's direction angle below edge i's (turning left) or above it (turning right): a wrap.
    const int c = predicates::compare_angle(q(i), q(i + 1), q(i + 1), q(i + 2));
    if (c == turn) ++wraps;
  }
  if (wraps != 1)
    fail(file, f, name, "a face of " + std::to_string(k) + " vertices winds " + std::to_string(wraps) +
                            " times around its interior (a star polygon): give triangles");
  for (std::size_t i = 1; i + 1 < k; ++i) {
    tris.push_back({idx(0), idx(i), idx(i + 1)});
    face_of.push_back(f);
  }
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

Mesh3 Mesh3::validate(const io::MeshFile& file, std::string_view name) {
  auto impl = std::make_shared<Impl>();
  impl->name = std::string(name);
  impl->source = file.source;
  impl->points = file.points;
  const std::size_t nf = file.faces();
  if (nf == 0) throw InvalidInput(file.source + ": " + std::string(name) + ": no faces");
  // A MeshFile may be built by hand: its structure is checked, not assumed.
  if (file.face_start.front() != 0 || file.face_start.back() != file.indices.size())
    throw InvalidInput(file.source + ": " + std::string(name) + ": face_start does not span the indices");
  for (std::size_t f = 0; f < nf; ++f) {
    if (file.face_start[f + 1] < file.face_start[f] + 3)
      fail(file, f, name, "a face needs at least 3 vertices");
    for (std::size_t i = file.face_start[f]; i < file.face_start[f + 1]; ++i) {
      const std::size_t v = file.indices[i];
      if (v >= file.points.size())
        fail(file, f, name, "vertex index " + file.vertex_name(v) + " is out of range (" +
                                std::to_string(file.points.size()) + " vertices)");
      if (!file.points[v].allFinite()) fail(file, f, name, "vertex " + file.vertex_name(v) + " is not finite");
    }
  }
  auto& tris = impl->triangles;
  auto& face_of = impl->face_of;
  for (std::size_t f = 0; f < nf; ++f) triangulate_face(file, f, name, tris, face_of);
  const std::vector<Vec3>& p = impl->points;
  const std::size_t n = tris.size();
  const auto where = [&](std::size_t t) { return file.face_where(face_of[t]); };
  const auto vname = [&](std::size_t v) { return file.vertex_name(v); };
  const auto edge_name = [&](std::size_t a, std::size_t b) { return "edge " + vname(a) + "-" + vname(b); };

  // 2. Edges: half-edge h = 3t + k goes tris[t][k] → tris[t][k+1].
  std::vector<std::size_t> he(3 * n);
  std::iota(he.begin(), he.end(), std::size_t(0));
  const auto from = [&](std::size_t h) { return tris[h / 3][h % 3]; };
  const auto to = [&](std::size_t h) { return tris[h / 3][(h % 3 + 1) % 3]; };
  const auto key = [&](std::size_t h) { return std::make_tuple(std::min(from(h), to(h)), std::max(from(h), to(h)), h); };
  std::sort(he.begin(), he.end(), [&](std::size_t x, std::size_t y) { return key(x) < key(y); });
  std::vector<std::size_t> twin(3 * n);
  for (std::size_t i = 0; i < he.size();) {
    std::size_t j = i;
    const auto lo = std::min(from(he[i]), to(he[i])), hi = std::max(from(he[i]), to(he[i]));
    while (j < he.size() && std::min(from(he[j]), to(he[j])) == lo && std::max(from(he[j]), to(he[j])) == hi) ++j;
    const std::size_t h = he[i];
    if (j - i == 1)
      fail(file, face_of[h / 3], name,
           "the mesh is not closed: " + edge_name(from(h), to(h)) + " belongs to this face only");
    if (j - i > 2) {
      std::string list;
      for (std::size_t q = i; q < j && q < i + 4; ++q) list += (q > i ? "; " : "") + where(he[q] / 3);
      throw InvalidInput(where(h / 3) + ": " + std::string(name) + ": non-manifold " + edge_name(lo, hi) + ": shared by " +
                         std::to_string(j - i) + " faces (" + list + (j - i > 4 ? "; ..." : "") + ")");
    }
    const std::size_t g = he[i + 1];
    if (from(h) == from(g))
      throw InvalidInput(where(h / 3) + ": " + std::string(name) + ": inconsistent orientation: this face and " +
                         where(g / 3) + " both use " + edge_name(from(h), to(h)) + " in the direction " + vname(from(h)) +
                         " → " + vname(to(h)));
    twin[h] = g;
    twin[g] = h;
    i = j;
  }

  // 3. Vertices: one fan each. Corner (t, k) is vertex tris[t][k]; the next triangle around it is
  // the twin of the half-edge entering it.
  {
    std::vector<char> seen(3 * n, 0);
    std::vector<std::size_t> fan_of(p.size(), ~std::size_t(0));
    for (std::size_t c0 = 0; c0 < 3 * n; ++c0) {
      if (seen[c0]) continue;
      const std::size_t v = from(c0);
      if (fan_of[v] != ~std::size_t(0))
        throw InvalidInput(where(c0 / 3) + ": " + std::string(name) + ": non-manifold vertex " + vname(v) +
                           ": its faces form more than one fan (this face and " + where(fan_of[v]) + " are in different fans)");
      fan_of[v] = c0 / 3;
      std::size_t c = c0;
      do {
        seen[c] = 1;
        const std::size_t in = 3 * (c / 3) + (c % 3 + 2) % 3;  // the half-edge entering v in this triangle
        c = twin[in];                                           // leaves v in the next triangle
      } while (c != c0);
    }
  }

  // 4. One connected surface.
  {
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    for (std::size_t h = 0; h < 3 * n; ++h) parent[find_root(parent, h / 3)] = find_root(parent, twin[h] / 3);
    for (std::size_t t = 1; t < n; ++t)
      if (find_root(parent, t) != find_root(parent, 0))
        throw InvalidInput(where(t) + ": " + std::string(name) + ": the mesh has more than one closed surface (this face is not connected to " +
                           where(0) + "); give one closed surface per shape");
  }

  // 5. Self-intersections.
  {
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
    std::vector<Box> boxes;
    boxes.reserve(n);
    for (std::size_t t = 0; t < n; ++t) {
      double lo[3], hi[3];
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min({p[tris[t][0]][a], p[tris[t][1]][a], p[tris[t][2]][a]});
        hi[a] = std::max({p[tris[t][0]][a], p[tris[t][1]][a], p[tris[t][2]][a]});
      }
      boxes.emplace_back(lo, hi, t);
    }
    const auto P = [&](std::size_t v) { return P3(p[v].x(), p[v].y(), p[v].z()); };
    std::pair<std::size_t, std::size_t> worst{n, n};
    std::string worst_what;
    auto check = [&](const Box& x, const Box& y) {
      std::size_t s = x.info(), t = y.info();
      if (s > t) std::swap(s, t);
      const auto& A = tris[s];
      const auto& B = tris[t];
      int shared = 0, ia = -1, ib = -1;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (A[i] == B[j]) ++shared, ia = i, ib = j;
      bool bad = false;
      std::string what;
      if (shared == 0) {
        bad = CGAL::do_intersect(K::Triangle_3(P(A[0]), P(A[1]), P(A[2])), K::Triangle_3(P(B[0]), P(B[1]), P(B[2])));
        what = "intersect";
      } else if (shared == 1) {
        const K::Segment_3 sa(P(A[(ia + 1) % 3]), P(A[(ia + 2) % 3])), sb(P(B[(ib + 1) % 3]), P(B[(ib + 2) % 3]));
        bad = CGAL::do_intersect(sa, K::Triangle_3(P(B[0]), P(B[1]), P(B[2]))) ||
              CGAL::do_intersect(sb, K::Triangle_3(P(A[0]), P(A[1]), P(A[2])));
        what = "intersect beyond their shared vertex " + vname(A[ia]);
      } else if (shared == 2) {
        // Shared edge u-w; a, b the third vertices.
        std::vector<std::size_t> sh;
        std::size_t a = 0, b = 0;
        for (int i = 0; i < 3; ++i) {
          if (std::find(B.begin(), B.end(), A[i]) == B.end()) a = A[i];
          else sh.push_back(A[i]);
          if (std::find(A.begin(), A.end(), B[i]) == A.end()) b = B[i];
        }
        const std::size_t u = sh[0], w = sh[1];
        bad = predicates::orient3d(p[u], p[w], p[a], p[b]) == 0 &&
              CGAL::coplanar_orientation(P(u), P(w), P(a), P(b)) != CGAL::NEGATIVE;
        what = "overlap (folded onto each other across their shared " + edge_name(u, w) + ")";
      } else {
        bad = true;
        what = "coincide (same three vertices)";
      }
      if (bad && std::make_pair(s, t) < worst) worst = {s, t}, worst_what = what;
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), check);
    if (worst.first < n)
      throw InvalidInput(where(worst.first) + ": " + std::string(name) + ": self-intersection: this face and " +
                         where(worst.second) + " " + worst_what);
  }

  // 6. Volume.
  double vol = 0;
  const int sign = volume_sign(p, tris, vol);
  if (sign == 0) fail(file, face_of[0], name, "the mesh encloses zero volume");
  if (sign < 0) {
    impl->flipped = true;
    vol = -vol;
  }
  impl->volume = vol;

  // 7. Convexity: for half-edge h in triangle (a, b, c), the neighbour's vertex opposite the edge
  // must not be strictly outside (orient3d > 0 in the outward orientation).
  std::size_t reflex = 0;
  for (std::size_t h = 0; h < 3 * n; h += 1) {
    const std::size_t g = twin[h];
    if (g < h) continue;
    const auto& T = tris[h / 3];
    const std::size_t d = tris[g / 3][(g % 3 + 2) % 3];
    const int o = predicates::orient3d(p[T[0]], p[T[1]], p[T[2]], p[d]) * sign;
    if (o > 0) ++reflex;
  }
  impl->reflex_edges = reflex;
  impl->convex = reflex == 0;
  if (impl->flipped)
    for (auto& t : tris) std::swap(t[1], t[2]);
  Mesh3 m;
  m.impl_ = std::move(impl);
  return m;
}

std::span<const Vec3> Mesh3::points() const { return impl_->points; }
std::span<const std::array<std::size_t, 3>> Mesh3::triangles() const { return impl_->triangles; }
std::size_t Mesh3::face_of(std::size_t t) const { return impl_->face_of[t]; }
bool Mesh3::convex() const { return impl_->convex; }
std::size_t Mesh3::reflex_edges() const { return impl_->reflex_edges; }
bool Mesh3::flipped() const { return impl_->flipped; }
double Mesh3::volume() const { return impl_->volume; }
const std::string& Mesh3::name() const { return impl_->name; }
const std::string& Mesh3::source() const { return impl_->source; }

std::vector<Vec3> Mesh3::used_points() const {
  std::vector<char> used(impl_->points.size(), 0);
  for (const auto& t : impl_->triangles)
    for (std::size_t v : t) used[v] = 1;
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) out.push_back(impl_->points[i]);
  return out;
}

const ConvexDecomposition3& Mesh3::decomposition() const {
  std::call_once(impl_->decomposed, [&] { impl_->decomposition = convex_decomposition(*this); });
  return *impl_->decomposition;
}

}  // namespace pendepth
