// Exact 3D oracle (see oracle3_cgal.hpp). The only file of test_oracle3 that sees CGAL: Epeck
// (lazy exact rationals) for the hulls, then plain GMP rationals for planes, distances and exits.
#include "oracle3/oracle3_cgal.hpp"

// The oracle runs on one thread. Without this, CGAL's lazy numbers guard each exact evaluation
// with std::call_once (a futex system call per evaluated node).
// CGAL configured as in the library (src/mesh3 uses CGAL too: its thread-local defaults must match).

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/squared_distance_3.h>
#include <gmpxx.h>
#include <mpfr.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <type_traits>

namespace oracle3 {

using K = CGAL::Epeck;
using FT = K::FT;
using ET = FT::ET;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Q3 = std::array<mpq_class, 3>;

namespace {

// Epeck's exact type is mpq_class, CGAL::Gmpq or boost's gmp_rational depending on the
// configuration; all wrap an mpq_t.
// (Templates, so that only the matching branch is instantiated.)
template <class E>
mpq_class to_mpq(const E& x) {
  if constexpr (std::is_same_v<E, mpq_class>) return x;
  else if constexpr (requires { x.backend().data(); }) return mpq_class(x.backend().data());
  else return mpq_class(x.mpq());
}
template <class E = ET>
E to_et(const mpq_class& q) {
  if constexpr (std::is_same_v<E, mpq_class>) return q;
  else return E(q.get_mpq_t());
}

// q rounded to the nearest double (MPFR rounds correctly).
double round_to_double(const mpq_class& q) {
  mpfr_t x;
  mpfr_init2(x, 53);
  mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
  double r = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return r;
}

// sqrt(q), q >= 0, to the nearest double: 256-bit sqrt then one rounding to 53 bits.
double sqrt_to_double(const mpq_class& q) {
  if (sgn(q) < 0) throw std::logic_error("oracle3: sqrt of a negative rational");
  mpfr_t x;
  mpfr_init2(x, 256);
  mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(x, x, MPFR_RNDN);
  double r = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return r;
}

bool is_double(const mpq_class& q, double& out) {
  out = round_to_double(q);
  return std::isfinite(out) && mpq_class(out) == q;
}

mpq_class dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Q3 sub(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Q3 exact(const Vec3& v) { return {mpq_class(v.x()), mpq_class(v.y()), mpq_class(v.z())}; }
Vec3 rounded_unit(const Q3& u) {
  Vec3 r(round_to_double(u[0]), round_to_double(u[1]), round_to_double(u[2]));
  // Rescale by a power of two first: components may under/overflow in double.
  double m = r.cwiseAbs().maxCoeff();
  if (m == 0 || !std::isfinite(m)) {
    // Exact rescale in rationals (rare: extreme magnitudes).
    mpq_class big = abs(u[0]);
    for (int i = 1; i < 3; ++i)
      if (abs(u[i]) > big) big = abs(u[i]);
    Q3 s{u[0] / big, u[1] / big, u[2] / big};
    r = Vec3(round_to_double(s[0]), round_to_double(s[1]), round_to_double(s[2]));
  } else {
    int e = 0;
    std::frexp(m, &e);
    r = Vec3(std::ldexp(r.x(), -e), std::ldexp(r.y(), -e), std::ldexp(r.z(), -e));
  }
  return r.normalized();
}

struct Plane {
  Q3 u;       // outward, not normalised
  mpq_class h;  // u·x ≤ h on the polytope
  mpq_class n2;  // |u|²
};

}  // namespace

struct ExactHull::Impl {
  std::vector<Q3> v;                        // hull vertices, exact
  std::vector<Plane> planes;                // one per triangle
  std::vector<std::pair<int, int>> edges;   // vertex index pairs
  std::vector<std::array<int, 3>> tris;     // one per plane, CCW from outside

  explicit Impl(const std::vector<Q3>& pts) {
    std::vector<Point> cp;
    cp.reserve(pts.size());
    for (const auto& p : pts) cp.emplace_back(FT(to_et(p[0])), FT(to_et(p[1])), FT(to_et(p[2])));
    Mesh mesh;
    CGAL::convex_hull_3(cp.begin(), cp.end(), mesh);
    if (mesh.number_of_faces() == 0) throw std::logic_error("oracle3: degenerate (flat) point set");
    std::map<Mesh::Vertex_index, int> id;
    for (auto vi : mesh.vertices()) {
      const Point& p = mesh.point(vi);
      id[vi] = static_cast<int>(v.size());
      v.push_back({to_mpq(CGAL::exact(p.x())), to_mpq(CGAL::exact(p.y())), to_mpq(CGAL::exact(p.z()))});
    }
    for (auto f : mesh.faces()) {
      std::array<int, 3> t{};
      int k = 0;
      for (auto vi : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
        if (k == 3) throw std::logic_error("oracle3: non-triangular hull face");
        t[k++] = id[vi];
      }
      tris.push_back(t);
      Plane pl;
      pl.u = cross(sub(v[t[1]], v[t[0]]), sub(v[t[2]], v[t[0]]));  // CCW from outside
      pl.h = dot(pl.u, v[t[0]]);
      pl.n2 = dot(pl.u, pl.u);
      planes.push_back(pl);
    }
    for (auto e : mesh.edges()) {
      edges.emplace_back(id[mesh.vertex(e, 0)], id[mesh.vertex(e, 1)]);
    }
    // Orientation sanity: every vertex on or below every plane (exact; cheap enough for tests).
    for (const auto& pl : planes)
      if (dot(pl.u, v[0]) > pl.h) throw std::logic_error("oracle3: hull facet oriented inwards");
    // Solid iff some vertex lies strictly below some facet plane (a flat hull lies in all of them).
    for (const auto& pl : planes)
      for (const auto& x : v) solid = solid || dot(pl.u, x) < pl.h;
  }
  bool solid = false;
};

namespace {
std::vector<Q3> exact_points(std::span<const Vec3> pts) {
  std::vector<Q3> e;
  e.reserve(pts.size());
  for (const auto& p : pts) e.push_back(exact(p));
  return e;
}
// x ↦ R x + t1 − t2 in exact arithmetic (each double product is exact in mpq).
std::vector<Q3> exact_points(std::span<const Vec3> pts, const Eigen::Matrix3d& R, const Vec3& t1, const Vec3& t2) {
  std::vector<Q3> e;
  e.reserve(pts.size());
  for (const auto& p : pts) {
    Q3 x;
    for (int i = 0; i < 3; ++i)
      x[i] = mpq_class(R(i, 0)) * mpq_class(p.x()) + mpq_class(R(i, 1)) * mpq_class(p.y()) +
             mpq_class(R(i, 2)) * mpq_class(p.z()) + mpq_class(t1[i]) - mpq_class(t2[i]);
    e.push_back(x);
  }
  return e;
}
}  // namespace

ExactHull::ExactHull(std::span<const Vec3> pts) : impl_(std::make_unique<Impl>(exact_points(pts))) {}
ExactHull::ExactHull(std::span<const Vec3> pts, const Eigen::Matrix3d& R, const Vec3& t1, const Vec3& t2)
    : impl_(std::make_unique<Impl>(exact_points(pts, R, t1, t2))) {}
ExactHull::~ExactHull() = default;
ExactHull::ExactHull(ExactHull&&) noexcept = default;
ExactHull& ExactHull::operator=(ExactHull&&) noexcept = default;
std::size_t ExactHull::vertices() const { return impl_->v.size(); }
std::size_t ExactHull::facets() const { return impl_->planes.size(); }
bool ExactHull::solid() const { return impl_->solid; }

double ExactHull::gap(const Vec3& x) const {
  Q3 e = exact(x);
  // Compare (u·x − h)/|u| between planes exactly through signed squares.
  bool have = false;
  mpq_class best_num, best_n2;  // best = best_num / sqrt(best_n2), best_num signed
  for (const auto& pl : impl_->planes) {
    mpq_class num = dot(pl.u, e) - pl.h;
    if (!have) {
      best_num = num, best_n2 = pl.n2, have = true;
      continue;
    }
    // num/√n2 > best_num/√best_n2 ?
    int s1 = sgn(num), s2 = sgn(best_num);
    bool greater;
    if (s1 != s2) greater = s1 > s2;
    else {
      mpq_class a = num * num * best_n2, b = best_num * best_num * pl.n2;
      greater = s1 >= 0 ? a > b : a < b;
    }
    if (greater) best_num = num, best_n2 = pl.n2;
  }
  double mag = sqrt_to_double(best_num * best_num / best_n2);
  return sgn(best_num) < 0 ? -mag : mag;
}

ExactHull::ExactHull(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

ExactDifference::ExactDifference(std::span<const Vec3> p_points, std::span<const Vec3> q_points,
                                 const Eigen::Matrix3d& R, const Vec3& tq, const Vec3& tp) {
  // Hull vertices of each side first (exact), then all pairwise differences p − q'.
  ExactHull hp(p_points);
  ExactHull hq(q_points, R, tq, tp);
  std::vector<Q3> diff;
  diff.reserve(hp.vertices() * hq.vertices());
  for (const auto& p : hp.impl().v)
    for (const auto& q : hq.impl().v) diff.push_back(sub(p, q));
  m_ = std::make_unique<ExactHull>(std::make_unique<ExactHull::Impl>(diff));
}

ExactDifference::ExactDifference(std::span<const Vec3> p_points, std::span<const Vec3> q_points,
                                 const Eigen::Matrix3d& R, const Vec3& tq, const Vec3& tp, bool raw_q) {
  // raw_q: P's raw points too (the hull of every difference is M all the same), so that P may be
  // lower-dimensional as well when the differences span a solid.
  const std::vector<Q3> ps = raw_q ? exact_points(p_points) : ExactHull(p_points).impl().v;
  const std::vector<Q3> qs = raw_q ? exact_points(q_points, R, tq, tp) : ExactHull(q_points, R, tq, tp).impl().v;
  std::vector<Q3> diff;
  for (const auto& p : ps)
    for (const auto& q : qs) diff.push_back(sub(p, q));
  m_ = std::make_unique<ExactHull>(std::make_unique<ExactHull::Impl>(diff));
}

ExactDifference::~ExactDifference() = default;

namespace {
// Exact location of 0: sets overlapping / on_boundary; true iff 0 ∈ int M.
bool locate(const std::vector<Plane>& planes, Answer& a) {
  bool zero = false;
  for (const auto& pl : planes) {
    if (sgn(pl.h) < 0) return false;  // 0 strictly outside
    zero = zero || sgn(pl.h) == 0;
  }
  a.on_boundary = zero;
  a.overlapping = !zero;
  return !zero;
}
}  // namespace

Answer ExactDifference::sigma() const {
  const auto& planes = m_->impl().planes;
  Answer a;
  const Plane* best = nullptr;
  if (!locate(planes, a)) return a;
  mpq_class best2;
  for (const auto& pl : planes) {
    mpq_class d2 = pl.h * pl.h / pl.n2;
    if (!best || d2 < best2) best = &pl, best2 = d2;
  }
  a.depth = sqrt_to_double(best2);
  for (const auto& pl : planes)
    if (pl.h * pl.h / pl.n2 == best2) a.normals.push_back(rounded_unit(pl.u));
  return a;
}

Answer ExactDifference::sigma_d(const Vec3& d) const {
  const auto& planes = m_->impl().planes;
  Answer a;
  if (!locate(planes, a)) return a;
  Q3 e = exact(d);
  bool have = false;
  mpq_class best;
  for (const auto& pl : planes) {
    mpq_class ud = dot(pl.u, e);
    if (sgn(ud) <= 0) continue;
    mpq_class s = pl.h / ud;
    if (!have || s < best) best = s, have = true;
  }
  if (!have) throw std::logic_error("oracle3: bounded M has no facet facing d");
  a.depth = sqrt_to_double(best * best * dot(e, e));
  for (const auto& pl : planes) {
    mpq_class ud = dot(pl.u, e);
    if (sgn(ud) > 0 && pl.h / ud == best) a.normals.push_back(rounded_unit(pl.u));
  }
  return a;
}

std::vector<Vec3> ExactDifference::boundary_doubles() const {
  const auto& I = m_->impl();
  std::vector<Vec3> out;
  auto push = [&](const Q3& x) {
    Vec3 r;
    for (int i = 0; i < 3; ++i)
      if (!is_double(x[i], r[i])) return;
    out.push_back(r);
  };
  for (const auto& v : I.v) push(v);
  for (const auto& [a, b] : I.edges) {
    Q3 m;
    for (int i = 0; i < 3; ++i) m[i] = (I.v[a][i] + I.v[b][i]) / 2;
    push(m);
  }
  return out;
}


double ExactDifference::signed_distance() const {
  const auto& I = m_->impl();
  Answer a;
  if (locate(I.planes, a)) return -sigma().depth;
  if (a.on_boundary) return 0;
  // 0 outside: the exact minimum over M's boundary triangles of the squared distance (CGAL, Epeck).
  const Point o(0, 0, 0);
  auto pt = [&](int k) { return Point(FT(to_et(I.v[k][0])), FT(to_et(I.v[k][1])), FT(to_et(I.v[k][2]))); };
  bool have = false;
  mpq_class best;
  for (const auto& t : I.tris) {
    const FT d2 = CGAL::squared_distance(o, K::Triangle_3(pt(t[0]), pt(t[1]), pt(t[2])));
    const mpq_class q = to_mpq(CGAL::exact(d2));
    if (!have || q < best) best = q, have = true;
  }
  return sqrt_to_double(best);
}

CastAnswer ExactDifference::cast(const Vec3& d) const {
  const auto& planes = m_->impl().planes;
  const Q3 e = exact(d);
  // The ray s·d (s >= 0) lies in u·x <= h for s in [lo, hi] per plane; intersect.
  mpq_class lo = 0, hi;
  bool bounded = false, strict = true;
  for (const auto& pl : planes) {
    const mpq_class ud = dot(pl.u, e);
    if (sgn(ud) == 0) {
      if (sgn(pl.h) < 0) return {};
      if (sgn(pl.h) == 0) strict = false;
      continue;
    }
    const mpq_class s = pl.h / ud;
    if (sgn(ud) < 0) {
      if (s > lo) lo = s;
    } else if (!bounded || s < hi) {
      hi = s, bounded = true;
    }
  }
  if (!bounded || lo > hi) return {};
  CastAnswer r;
  r.hit = true;
  r.grazing = !strict || lo == hi;
  r.distance = sqrt_to_double(lo * lo * dot(e, e));
  return r;
}

}  // namespace oracle3
