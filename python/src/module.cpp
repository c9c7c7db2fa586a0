// pendepth — Python bindings of the front door (include/pendepth/pendepth.hpp): Shape2, Pair2,
// Shape3, Pair3, no_fit_polygon. Only the front door is bound, not the engines.
//
// Batches: placements arrive as numpy arrays, are copied into std::vector<Vec2/Vec3> (Eigen's
// fixed-size vectors may need an alignment numpy does not promise), the C++ batch runs with the
// GIL released, and the answers are copied into numpy arrays. The C++ batches are bit-identical
// to single calls whatever the thread count; so are these, and a single (2,) / (3,) point is a
// batch of one. Errors: pendepth::InvalidInput becomes pendepth.InvalidInput (a ValueError) with
// the C++ message.
#include <pendepth/nesting.hpp>
#include <pendepth/pendepth.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "primitives/support3.hpp"
#include "front/checks.hpp"

namespace py = pybind11;
using namespace pendepth;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

/// Points given as an (N, D) array or one (D,) point.
template <int D>
struct Points {
  std::vector<Eigen::Matrix<double, D, 1>> v;
  bool single = false;
};

template <int D>
Points<D> points(const py::object& obj, const char* what) {
  Array a = py::cast<Array>(obj);
  Points<D> r;
  if (a.ndim() == 1 && a.shape(0) == D) {
    r.single = true;
  } else if (!(a.ndim() == 2 && a.shape(1) == D)) {
    throw InvalidInput(std::string(what) + ": expected an (N, " + std::to_string(D) + ") array or one (" +
                       std::to_string(D) + ",) point, got shape " + shape_text(a));
  }
  const std::size_t n = r.single ? 1 : static_cast<std::size_t>(a.shape(0));
  r.v.resize(n);
  const double* p = a.data();
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) r.v[i][k] = p[i * D + k];
  return r;
}

/// One (3,) point (Shape3.point, Shape3.segment).
Vec2 vec2_of(const py::object& obj, const std::string& what) {
  const Points<2> p = points<2>(obj, what.c_str());
  if (!p.single) throw InvalidInput(what + ": expected one (2,) point");
  return p.v[0];
}

Vec3 vec3_of(const py::object& obj, const std::string& what) {
  const Points<3> p = points<3>(obj, what.c_str());
  if (!p.single) throw InvalidInput(what + ": expected one (3,) point");
  return p.v[0];
}

std::vector<Vec2> ring(const py::object& obj, const std::string& what) {
  Array a = py::cast<Array>(obj);
  if (a.ndim() != 2 || a.shape(1) != 2)
    throw InvalidInput(what + ": expected an (n, 2) array of vertices, got shape " + shape_text(a));
  std::vector<Vec2> r(static_cast<std::size_t>(a.shape(0)));
  const double* p = a.data();
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = Vec2(p[2 * i], p[2 * i + 1]);
  return r;
}

unsigned thread_count(const py::object& threads) {
  if (threads.is_none()) return 0;
  const long n = py::cast<long>(threads);
  if (n < 0) throw InvalidInput("threads must be None (every core) or a count >= 0, got " + std::to_string(n));
  return static_cast<unsigned>(n);
}

Prepare prepare_of(const std::string& s) {
  if (s == "auto") return Prepare::Auto;
  if (s == "queries") return Prepare::Queries;
  if (s == "full") return Prepare::Full;
  throw InvalidInput("prepare must be \"auto\", \"queries\" or \"full\", got \"" + s + "\"");
}

const char* kind_name(DepthKind k) {
  switch (k) {
    case DepthKind::Minimum: return "minimum";
    case DepthKind::Directional: return "directional";
    case DepthKind::Separation: return "separation";
  }
  return "minimum";
}

// ---- numpy output helpers ----

py::array_t<double> vectors(std::size_t n, int d) {
  return py::array_t<double>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), d});
}
py::array_t<double> scalars(std::size_t n) { return py::array_t<double>(static_cast<py::ssize_t>(n)); }

/// A batch of one answer given as a single point: (1,) -> 0-d scalar, (1, D) -> (D,).
py::object squeeze(const py::array& a, bool single) {
  if (!single) return a;
  if (a.ndim() == 1) return a.attr("__getitem__")(0);  // numpy scalar (float64 / bool_ / int64)
  return a.attr("__getitem__")(0);                     // row view (D,)
}

/// Runs a batch in chunks with a progress bar on sys.stderr, or in one call. run(begin, end) is
/// called with the GIL released.
template <class Run>
void chunked(std::size_t n, bool progress, Run&& run) {
  if (!progress || n == 0) {
    py::gil_scoped_release nogil;
    run(std::size_t{0}, n);
    return;
  }
  py::object err = py::module_::import("sys").attr("stderr");
  const std::size_t chunk = std::max<std::size_t>(256, (n + 99) / 100);
  const int width = 40;
  for (std::size_t b = 0; b < n; b += chunk) {
    const std::size_t e = std::min(n, b + chunk);
    {
      py::gil_scoped_release nogil;
      run(b, e);
    }
    const int filled = static_cast<int>(static_cast<double>(e) / static_cast<double>(n) * width);
    std::string bar = "\rpendepth [" + std::string(filled, '#') + std::string(width - filled, '.') + "] " +
                      std::to_string(e) + "/" + std::to_string(n);
    if (e == n) bar += "\n";
    err.attr("write")(bar);
    err.attr("flush")();
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
}

// ---- wrappers keeping what pickling needs ----

struct PyPair2 {
  Pair2 pair;
  std::string prepare;
};

struct PyPair3 {
  Pair3 pair;
  std::string prepare;
};

/// Results of a 2D batch (or of one query given as a single point).
struct Result2 {
  py::object depth, translation, normal, witness_p, witness_q, feature_p, feature_q, overlapping;
  std::string kind, engine;
  py::object pair, offsets, directions;
  std::size_t size = 0;
  bool single = false;
};

struct Result3 {
  py::object depth, translation, normal, facet_normal, witness_p, witness_q, feature_p, feature_q,
      lower_bound, upper_bound, candidates, overlapping, piece_p, piece_q;
  std::string kind;
  std::size_t size = 0;
  bool single = false;
};

template <class V>
void put(double* p, std::size_t i, const V& v) {
  for (int k = 0; k < v.size(); ++k) p[i * v.size() + k] = v[k];
}

py::array_t<std::int64_t> features(std::size_t n) {
  return py::array_t<std::int64_t>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), 2});
}

Result2 result2(const std::vector<Depth2>& out, bool single, const py::object& pair, py::object offsets,
                py::object directions, DepthKind kind, const std::string& engine) {
  const std::size_t n = out.size();
  auto depth = scalars(n);
  auto tr = vectors(n, 2), nr = vectors(n, 2), wp = vectors(n, 2), wq = vectors(n, 2);
  auto fp = features(n), fq = features(n);
  py::array_t<bool> ov(static_cast<py::ssize_t>(n));
  double *pd = depth.mutable_data(), *pt = tr.mutable_data(), *pn = nr.mutable_data(), *pp = wp.mutable_data(),
         *pq = wq.mutable_data();
  std::int64_t *pfp = fp.mutable_data(), *pfq = fq.mutable_data();
  bool* po = ov.mutable_data();
  for (std::size_t i = 0; i < n; ++i) {
    const Depth2& r = out[i];
    pd[i] = r.depth;
    put(pt, i, r.translation);
    put(pn, i, r.normal);
    put(pp, i, r.witness_p);
    put(pq, i, r.witness_q);
    pfp[2 * i] = static_cast<int>(r.feature_p.kind);
    pfp[2 * i + 1] = r.feature_p.index;
    pfq[2 * i] = static_cast<int>(r.feature_q.kind);
    pfq[2 * i + 1] = r.feature_q.index;
    po[i] = r.overlapping;
  }
  Result2 r;
  r.depth = squeeze(depth, single);
  r.translation = squeeze(tr, single);
  r.normal = squeeze(nr, single);
  r.witness_p = squeeze(wp, single);
  r.witness_q = squeeze(wq, single);
  r.feature_p = squeeze(fp, single);
  r.feature_q = squeeze(fq, single);
  r.overlapping = squeeze(ov, single);
  r.kind = kind_name(kind);
  r.engine = engine;
  r.pair = pair;
  r.offsets = std::move(offsets);
  r.directions = std::move(directions);
  r.size = n;
  r.single = single;
  return r;
}

Result3 result3(const std::vector<Depth3>& out, bool single, DepthKind kind) {
  const std::size_t n = out.size();
  auto depth = scalars(n), lo = scalars(n), hi = scalars(n);
  auto tr = vectors(n, 3), nr = vectors(n, 3), fn = vectors(n, 3), wp = vectors(n, 3), wq = vectors(n, 3);
  auto fp = features(n), fq = features(n);
  py::array_t<std::int64_t> cand(static_cast<py::ssize_t>(n)), pp(static_cast<py::ssize_t>(n)), pq(static_cast<py::ssize_t>(n));
  py::array_t<bool> ov(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const Depth3& r = out[i];
    pp.mutable_data()[i] = r.piece_p, pq.mutable_data()[i] = r.piece_q;
    depth.mutable_data()[i] = r.depth;
    lo.mutable_data()[i] = r.lower_bound;
    hi.mutable_data()[i] = r.upper_bound;
    put(tr.mutable_data(), i, r.translation);
    put(nr.mutable_data(), i, r.normal);
    put(fn.mutable_data(), i, r.facet_normal);
    put(wp.mutable_data(), i, r.witness_p);
    put(wq.mutable_data(), i, r.witness_q);
    fp.mutable_data()[2 * i] = static_cast<int>(r.feature_p.kind);
    fp.mutable_data()[2 * i + 1] = r.feature_p.index;
    fq.mutable_data()[2 * i] = static_cast<int>(r.feature_q.kind);
    fq.mutable_data()[2 * i + 1] = r.feature_q.index;
    cand.mutable_data()[i] = static_cast<std::int64_t>(r.candidates);
    ov.mutable_data()[i] = r.overlapping;
  }
  Result3 r;
  r.depth = squeeze(depth, single);
  r.lower_bound = squeeze(lo, single);
  r.upper_bound = squeeze(hi, single);
  r.translation = squeeze(tr, single);
  r.normal = squeeze(nr, single);
  r.facet_normal = squeeze(fn, single);
  r.witness_p = squeeze(wp, single);
  r.witness_q = squeeze(wq, single);
  r.feature_p = squeeze(fp, single);
  r.feature_q = squeeze(fq, single);
  r.candidates = squeeze(cand, single);
  r.overlapping = squeeze(ov, single);
  r.piece_p = squeeze(pp, single);
  r.piece_q = squeeze(pq, single);
  r.kind = kind_name(kind);
  r.size = n;
  r.single = single;
  return r;
}

template <int D>
py::array_t<double> to_array(const std::vector<Eigen::Matrix<double, D, 1>>& v) {
  auto a = vectors(v.size(), D);
  for (std::size_t i = 0; i < v.size(); ++i) put(a.mutable_data(), i, v[i]);
  return a;
}

py::list rings_of(const Shape2& s) {
  py::list l;
  for (const auto& r : s.rings()) l.append(to_array<2>(r));
  return l;
}

Shape2 make_shape2(const py::object& outer, const py::object& holes, const std::string& name) {
  if (py::hasattr(outer, "exterior") && py::hasattr(outer, "interiors")) {
    // A shapely Polygon (or anything shaped like one): its rings' coordinates, x and y.
    if (!holes.is_none() && py::len(holes) != 0)
      throw InvalidInput(name + ": holes given both in the polygon object and as holes=");
    py::module_ np = py::module_::import("numpy");
    auto coords = [&](const py::handle& r) -> py::object {
      py::object a = np.attr("asarray")(py::list(r.attr("coords")), "float64");
      if (a.attr("ndim").cast<int>() == 2 && a.attr("shape").cast<py::tuple>()[1].cast<int>() > 2)
        a = a.attr("__getitem__")(py::make_tuple(py::slice(0, a.attr("shape").cast<py::tuple>()[0].cast<py::ssize_t>(), 1),
                                                  py::slice(0, 2, 1)));
      return a;
    };
    std::vector<std::vector<Vec2>> hs;
    std::size_t k = 1;
    for (const py::handle& h : outer.attr("interiors")) hs.push_back(ring(coords(h), name + " hole " + std::to_string(k++)));
    return Shape2(ring(coords(outer.attr("exterior")), name + " outer ring"), std::move(hs), name);
  }
  std::vector<std::vector<Vec2>> hs;
  if (!holes.is_none()) {
    std::size_t k = 1;
    for (const py::handle& h : holes) hs.push_back(ring(py::reinterpret_borrow<py::object>(h), name + " hole " + std::to_string(k++)));
  }
  return Shape2(ring(outer, name + " outer ring"), std::move(hs), name);
}

std::vector<Pose3> poses(const Points<3>& ts, const py::object& rotations, bool& single) {
  single = ts.single;
  std::vector<Pose3> ps(ts.v.size());
  for (std::size_t i = 0; i < ps.size(); ++i) ps[i].translation = ts.v[i];
  if (rotations.is_none()) return ps;
  Points<4> qs = points<4>(rotations, "rotations");
  if (qs.v.size() != ps.size() && qs.v.size() != 1)
    throw InvalidInput("rotations: " + std::to_string(qs.v.size()) + " quaternions for " + std::to_string(ps.size()) +
                       " translations (give one, or one per translation)");
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const Eigen::Vector4d& q = qs.v[qs.v.size() == 1 ? 0 : i];
    ps[i].rotation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);  // w, x, y, z
  }
  return ps;
}

/// The checks Pair3's batches make, made before a chunked (progress) run so that a bad entry is
/// reported by its index in the whole batch and nothing runs.
void check_poses(const std::vector<Pose3>& ps) {
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const std::string what = "batch: pose " + std::to_string(i);
    front::check_placement(ps[i].translation, what + " translation");
    if (!front::finite(ps[i].rotation.coeffs()))
      throw InvalidInput(what + " rotation " + front::text(ps[i].rotation.coeffs()) + " is not finite");
    if (ps[i].rotation.coeffs().isZero(0)) throw InvalidInput(what + " rotation is the zero quaternion");
  }
}

py::object nfp_object(const NoFitPolygonParts& n) {
  py::list polys;
  for (const auto& poly : n.polygons) {
    py::list rings;
    for (const auto& r : poly) rings.append(to_array<2>(r));
    polys.append(rings);
  }
  py::array_t<double> slits(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n.slits.size()), 2, 2});
  for (std::size_t i = 0; i < n.slits.size(); ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) slits.mutable_data()[4 * i + 2 * j + k] = n.slits[i][j][k];
  py::object types = py::module_::import("types");
  return types.attr("SimpleNamespace")(py::arg("polygons") = polys, py::arg("slits") = slits,
                                       py::arg("points") = to_array<2>(n.points));
}

Result3 along3(const PyPair3& p, const py::object& translations, const py::object& directions, const py::object& rotations,
               const py::object& threads, bool progress, DepthKind kind) {
  bool single = false;
  std::vector<Pose3> ps = poses(points<3>(translations, "translations"), rotations, single);
  Points<3> ds = points<3>(directions, "directions");
  const unsigned th = thread_count(threads);
  std::vector<Depth3> out(ps.size());
  const bool one = ds.v.size() == 1;
  if (progress) {
    check_poses(ps);
    if (!one && ds.v.size() != ps.size())
      throw InvalidInput("batch: " + std::to_string(ds.v.size()) + " directions for " + std::to_string(ps.size()) +
                         " poses (give one direction, or one per pose)");
    for (std::size_t i = 0; i < ds.v.size(); ++i) front::check_direction(ds.v[i], "batch: direction " + std::to_string(i));
  }
  if (kind == DepthKind::Separation && !(p.pair.P().is_convex() && p.pair.Q().is_convex())) {
    // Meshes: complete separation is not σ_d (the ray may meet O again); Pair3::separation per pose.
    if (!one && ds.v.size() != ps.size())
      throw InvalidInput("batch: " + std::to_string(ds.v.size()) + " directions for " + std::to_string(ps.size()) +
                         " poses (give one direction, or one per pose)");
    for (std::size_t i = 0; i < ps.size(); ++i) out[i] = p.pair.separation(Pose3(), ps[i], ds.v[one ? 0 : i]);
    return result3(out, single, kind);
  }
  chunked(ps.size(), progress, [&](std::size_t b, std::size_t e) {
    std::span<const Vec3> d = one || ds.v.size() != ps.size() ? std::span<const Vec3>(ds.v)
                                                              : std::span<const Vec3>(ds.v).subspan(b, e - b);
    p.pair.along(std::span<const Pose3>(ps).subspan(b, e - b), d, std::span<Depth3>(out).subspan(b, e - b), th);
  });
  return result3(out, single, kind);
}

// ---- 3D signed distance and shape cast (issue 16): results as SimpleNamespace of arrays ----
/// Fields shared by Distance3 and Cast3 into numpy arrays (squeezed for a single query).
template <class R>
py::object distance_like(const std::vector<R>& out, bool single) {
  const std::size_t n = out.size();
  auto dist = scalars(n);
  auto tr = vectors(n, 3), nr = vectors(n, 3), wp = vectors(n, 3), wq = vectors(n, 3);
  auto fp = features(n), fq = features(n);
  py::array_t<bool> ov(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const R& r = out[i];
    dist.mutable_data()[i] = r.distance;
    put(tr.mutable_data(), i, r.translation);
    put(nr.mutable_data(), i, r.normal);
    put(wp.mutable_data(), i, r.witness_p);
    put(wq.mutable_data(), i, r.witness_q);
    fp.mutable_data()[2 * i] = static_cast<int>(r.feature_p.kind), fp.mutable_data()[2 * i + 1] = r.feature_p.index;
    fq.mutable_data()[2 * i] = static_cast<int>(r.feature_q.kind), fq.mutable_data()[2 * i + 1] = r.feature_q.index;
    ov.mutable_data()[i] = r.overlapping;
  }
  py::dict d;
  d["distance"] = squeeze(dist, single);
  d["translation"] = squeeze(tr, single);
  d["normal"] = squeeze(nr, single);
  d["witness_p"] = squeeze(wp, single);
  d["witness_q"] = squeeze(wq, single);
  d["feature_p"] = squeeze(fp, single);
  d["feature_q"] = squeeze(fq, single);
  d["overlapping"] = squeeze(ov, single);
  if constexpr (requires { out[0].hit; }) {
    py::array_t<bool> hit(static_cast<py::ssize_t>(n));
    for (std::size_t i = 0; i < n; ++i) hit.mutable_data()[i] = out[i].hit;
    d["hit"] = squeeze(hit, single);
  }
  // The certified bracket (a rounded cast's [lower, upper]; equal to distance when exact) and the
  // mesh pieces the features index (-1 for convex pairs).
  auto lo = scalars(n), hi = scalars(n);
  py::array_t<std::int64_t> pp(static_cast<py::ssize_t>(n)), pq(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    lo.mutable_data()[i] = out[i].lower_bound, hi.mutable_data()[i] = out[i].upper_bound;
    pp.mutable_data()[i] = out[i].piece_p, pq.mutable_data()[i] = out[i].piece_q;
  }
  d["lower_bound"] = squeeze(lo, single);
  d["upper_bound"] = squeeze(hi, single);
  d["piece_p"] = squeeze(pp, single);
  d["piece_q"] = squeeze(pq, single);
  return py::module_::import("types").attr("SimpleNamespace")(**d);
}

constexpr const char* kShape2Doc = R"(A validated 2D shape: a simple polygon, convex or not, possibly with holes.

Shape2(outer, holes=[], name="shape")
    outer: an (n, 2) array of vertices (either orientation, closing vertex optional), or a
           shapely Polygon (any object with .exterior.coords and .interiors; then no holes=).
    holes: a list of (k, 2) arrays.
Raises pendepth.InvalidInput (a ValueError) naming the shape, the ring (0 = outer, k = hole k)
and the vertex when the rings are not simple, cross each other, or are degenerate.

A single convex ring is kept in the convex normal form and uses the convex engines. Immutable,
cheap to copy, picklable (by its rings).)";

constexpr const char* kPair2Doc = R"(A pair of 2D shapes: P fixed, Q moving, with the per-pair work done once.

Pair2(P, Q, prepare="auto")
    prepare: "queries" (only what every query needs), "full" (every per-pair structure: the
             depth field of two convex shapes, the no-fit polygon of two non-convex ones), or
             "auto" (decided from the sizes, see the C++ Prepare).
Conventions: Q is placed at the offset t (Q + t); the translation in a result is the move to
apply to Q after t so that the interiors become disjoint (Q + t + translation touches P);
depth = |translation|; normal = translation / depth (the direction d normalised for along and
separation); witness points are in world coordinates (P's frame). Touching is not overlapping
(depth 0). For non-convex shapes overlap means t in O, the open overlap set.

Queries take offsets as an (N, 2) array or one (2,) point, threads=None (every core) or a
count (1 = the calling thread), and progress=False (True: chunks the batch and draws a
progress bar on stderr). They release the GIL while they run. Batch answers equal the single
calls bit for bit, whatever the thread count. Non-finite offsets, zero or non-finite
directions raise pendepth.InvalidInput naming the index; nothing runs then.
Picklable (by its two shapes and prepare).)";

constexpr const char* kMinimumDoc = R"(minimum(offsets, threads=None, progress=False) -> Depth2Result

sigma: the shortest translation of Q + t that separates the interiors of P and Q + t.
offsets: (N, 2) array (results (N,) and (N, 2)) or one (2,) point (scalar results, (2,)
vectors). depth >= 0; 0 (and zero vectors) when P and Q + t do not overlap. The normal is the
outward unit normal of M = P + (-Q) (of the boundary of O for non-convex shapes) where the move
ends. Raises InvalidInput for non-finite offsets.)";

constexpr const char* kAlongDoc = R"(along(offsets, directions, threads=None, progress=False) -> Depth2Result

sigma_d: the shortest translation of Q + t along the direction d that separates the interiors
(depth >= sigma). directions: (N, 2), one per offset, or one (2,) direction for all; any
non-zero finite length. translation = depth * d / |d|. Raises InvalidInput for non-finite
offsets and zero or non-finite directions.)";

constexpr const char* kSeparationDoc = R"(separation(offsets, directions, threads=None, progress=False) -> Depth2Result

Complete separation along d: the shortest move along d after which Q can slide on to infinity
without overlapping P. Positive also when Q + t does not overlap P but the ray meets P later
(then overlapping is False). Same arguments as along. Raises InvalidInput for non-finite
offsets and zero or non-finite directions.)";

constexpr const char* kOverlappingDoc = R"(overlapping(offsets, threads=None, progress=False) -> (N,) bool array or bool

Exact: do the interiors of P and Q + t overlap? Touching placements are not overlapping.
Raises InvalidInput for non-finite offsets.)";

constexpr const char* kShape3Doc = R"(A validated convex polytope (the convex hull of a point set), hierarchy built once.

Shape3.hull(points, name="points"): points an (n, 3) array. Shape3.from_file(path): .obj, .off
or .stl (ASCII or binary), the hull of the file's vertices. Raise pendepth.InvalidInput for
non-finite or flat input (fewer than 4 affinely independent points) and unreadable files.
Picklable (by its vertices).)";

constexpr const char* kPair3Doc = R"(A pair of 3D shapes: P at the identity pose, Q posed per query.
Non-convex meshes (Shape3.from_file of a closed non-convex mesh) are answered on their convex
pieces: overlapping, along, separation, signed_distance (apart) exact; minimum as certified
bounds (lower_bound <= sigma <= upper_bound = depth); cast is for convex shapes.

Pair3(P, Q, prepare="auto")
Queries take translations of Q as an (N, 3) array or one (3,) point, and rotations=None
(identity) or quaternions (N, 4) / one (4,) as w, x, y, z (any non-zero length; normalised).
Results are in the world frame: translation is the move to apply to Q after its pose,
depth = |translation|, lower_bound == upper_bound == depth (exact methods). threads,
progress, the GIL and bit-identity as in Pair2. Raises InvalidInput for non-finite
translations, zero or non-finite quaternions and directions, naming the index.
Picklable (by its two shapes and prepare).)";

// A directional 2D batch (along, separation): offsets and directions as arrays or single points,
// checked whole before any query, run in chunks with the GIL released; query(pair, ts, ds, out,
// threads) is the C++ batch call.
template <class Query>
Result2 directional2(const py::object& self, const py::object& offsets, const py::object& directions,
                     const py::object& threads, bool progress, DepthKind kind, Query&& query) {
  const PyPair2& p = self.cast<const PyPair2&>();
  Points<2> ts = points<2>(offsets, "offsets");
  Points<2> ds = points<2>(directions, "directions");
  const unsigned th = thread_count(threads);
  std::vector<Depth2> out(ts.v.size());
  if (progress) front::check_batch<Vec2>(ts.v, ds.v, out.size(), true);
  const bool one = ds.v.size() == 1;
  chunked(ts.v.size(), progress, [&](std::size_t b, std::size_t e) {
    // one direction for all, or a count mismatch the C++ batch reports: pass ds whole
    std::span<const Vec2> d = one || ds.v.size() != ts.v.size() ? std::span<const Vec2>(ds.v)
                                                                 : std::span<const Vec2>(ds.v).subspan(b, e - b);
    query(p.pair, std::span<const Vec2>(ts.v).subspan(b, e - b), d, std::span<Depth2>(out).subspan(b, e - b), th);
  });
  return result2(out, ts.single, self, py::cast<Array>(offsets).attr("copy")(), py::cast<Array>(directions).attr("copy")(),
                 kind, to_string(p.pair.engine()));
}

// Signed distance and cast answers (Distance2 / Cast2) as a namespace of numpy arrays: distance
// (N,), translation, normal, witness_p, witness_q (N, 2), feature_p / feature_q (N, 2) [kind,
// index], overlapping (N,) bool, and hit (N,) bool for a cast; scalars and (2,) for one point.
template <class R>
py::object distance_result(const std::vector<R>& out, bool single) {
  const std::size_t n = out.size();
  auto dist = scalars(n);
  auto tr = vectors(n, 2), nr = vectors(n, 2), wp = vectors(n, 2), wq = vectors(n, 2);
  auto fp = features(n), fq = features(n);
  py::array_t<bool> ov(static_cast<py::ssize_t>(n)), hit(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const R& r = out[i];
    dist.mutable_data()[i] = r.distance;
    put(tr.mutable_data(), i, r.translation);
    put(nr.mutable_data(), i, r.normal);
    put(wp.mutable_data(), i, r.witness_p);
    put(wq.mutable_data(), i, r.witness_q);
    fp.mutable_data()[2 * i] = static_cast<int>(r.feature_p.kind);
    fp.mutable_data()[2 * i + 1] = r.feature_p.index;
    fq.mutable_data()[2 * i] = static_cast<int>(r.feature_q.kind);
    fq.mutable_data()[2 * i + 1] = r.feature_q.index;
    ov.mutable_data()[i] = r.overlapping;
    if constexpr (requires { r.hit; }) hit.mutable_data()[i] = r.hit;
  }
  py::dict d;
  d["distance"] = squeeze(dist, single);
  d["translation"] = squeeze(tr, single);
  d["normal"] = squeeze(nr, single);
  d["witness_p"] = squeeze(wp, single);
  d["witness_q"] = squeeze(wq, single);
  d["feature_p"] = squeeze(fp, single);
  d["feature_q"] = squeeze(fq, single);
  d["overlapping"] = squeeze(ov, single);
  if constexpr (requires { R{}.hit; }) d["hit"] = squeeze(hit, single);
  return py::module_::import("types").attr("SimpleNamespace")(**d);
}

// Lean σ / σ_d answers (DepthValue2, issue 19 item 1) as a namespace of numpy arrays: depth (N,),
// translation (N, 2), overlapping (N,) bool; scalars and (2,) for one point.
py::object value_result(const std::vector<DepthValue2>& out, bool single) {
  const std::size_t n = out.size();
  auto depth = scalars(n);
  auto tr = vectors(n, 2);
  py::array_t<bool> ov(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    depth.mutable_data()[i] = out[i].depth;
    put(tr.mutable_data(), i, out[i].translation);
    ov.mutable_data()[i] = out[i].overlapping;
  }
  py::dict d;
  d["depth"] = squeeze(depth, single);
  d["translation"] = squeeze(tr, single);
  d["overlapping"] = squeeze(ov, single);
  return py::module_::import("types").attr("SimpleNamespace")(**d);
}

constexpr const char* kDepthValueDoc = R"(depth_value(offsets) -> namespace

Lean sigma for nesting loops: depth (N,), translation (N, 2) and overlapping (N,) bool, bit for bit
those of minimum(offsets), without normal, witnesses and features (on the no-fit polygon engine
they are not computed). Raises InvalidInput for non-finite offsets.)";

constexpr const char* kDirectionalDepthValueDoc = R"(directional_depth_value(offsets, directions) -> namespace

Lean sigma_d: depth, translation and overlapping of along(offsets, directions), bit for bit.
directions: (N, 2) or one (2,) for all. Raises InvalidInput for non-finite offsets and zero or
non-finite directions.)";

constexpr const char* kSignedDistanceDoc = R"(signed_distance(offsets, threads=None, progress=False) -> namespace

Signed distance (FCL / Drake / Coal convention): distance > 0 when P and Q + t are apart (their
Euclidean distance), 0 touching, -sigma overlapping. translation = -distance * normal brings Q
into touching contact; witness_q - witness_p = distance * normal (witness_q on the unmoved
Q + t); normal points from P towards Q (0 when touching). Returns a namespace of arrays:
distance (N,), translation, normal, witness_p, witness_q (N, 2), feature_p, feature_q (N, 2)
[kind, index], overlapping (N,) bool; scalars and (2,) vectors for one (2,) point. Batch
answers equal single calls bit for bit. Raises InvalidInput for non-finite offsets.)";

constexpr const char* kCastDoc = R"(cast(offsets, directions) -> namespace

Shape cast (time of impact): the smallest s >= 0 with Q + t + s * d/|d| touching P; 0 when
touching or overlapping, inf (hit False) when never. directions: (N, 2) or one (2,) for all.
Returns the fields of signed_distance (distance = s, translation = s * d/|d|, normal the
outward normal of M at the entry, witnesses the contact point) plus hit (N,) bool. Raises
InvalidInput for non-finite offsets and zero or non-finite directions.)";

}  // namespace

PYBIND11_MODULE(_pendepth, m) {
  m.doc() = "pendepth: exact penetration depth of 2D and 3D shapes (the C++ front door, pendepth.hpp).";
  m.attr("__version__") = PENDEPTH_VERSION;  // the CMake project version
  py::options options;
  options.disable_function_signatures();  // the docstrings start with their Python signatures

  static py::exception<InvalidInput> invalid(m, "InvalidInput", PyExc_ValueError);
  invalid.attr("__module__") = "pendepth";
  invalid.attr("__doc__") =
      "Invalid input (bad shapes, non-finite placements, zero directions, unreadable files): a "
      "ValueError carrying the C++ message, which names the shape, ring and vertex, or the batch index.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(invalid.ptr(), e.what());
    }
  });

  m.attr("FEATURE_NONE") = 0;
  m.attr("FEATURE_VERTEX") = 1;
  m.attr("FEATURE_EDGE") = 2;
  m.attr("FEATURE_FACE") = 3;

  // ---- results ----
  py::class_<Result2>(m, "Depth2Result", R"(Answers of a 2D query batch (numpy arrays, world frame).

depth (N,), translation (N, 2), normal (N, 2), witness_p (N, 2), witness_q (N, 2),
overlapping (N,) bool, feature_p / feature_q (N, 2) int64 as [kind, index] (kind 0 none,
1 vertex, 2 edge), kind ("minimum", "directional", "separation"), engine (the pair's engine).
A query given as one (2,) point has scalars and (2,) vectors instead.)")
      .def_readonly("depth", &Result2::depth, "length of the translation, >= 0")
      .def_readonly("translation", &Result2::translation, "move to apply to Q after its offset t")
      .def_readonly("normal", &Result2::normal, "unit direction of the translation (0 when not overlapping)")
      .def_readonly("witness_p", &Result2::witness_p, "point of P's boundary touching the moved Q")
      .def_readonly("witness_q", &Result2::witness_q, "point of the moved Q's boundary touching P")
      .def_readonly("feature_p", &Result2::feature_p, "[kind, index] of P's feature at the contact")
      .def_readonly("feature_q", &Result2::feature_q, "[kind, index] of Q's feature at the contact")
      .def_readonly("overlapping", &Result2::overlapping, "do the interiors of P and Q + t overlap")
      .def_readonly("kind", &Result2::kind)
      .def_readonly("engine", &Result2::engine)
      .def_readonly("pair", &Result2::pair, "the Pair2 asked")
      .def_readonly("offsets", &Result2::offsets, "the offsets asked, (N, 2) or (2,)")
      .def_readonly("directions", &Result2::directions, "the directions asked, or None")
      .def("__len__", [](const Result2& r) { return r.size; })
      .def("__repr__", [](const Result2& r) {
        return "<pendepth.Depth2Result " + r.kind + ", " + (r.single ? "one placement" : std::to_string(r.size) + " placements") +
               ", engine " + r.engine + ">";
      });

  py::class_<Result3>(m, "Depth3Result", R"(Answers of a 3D query batch (numpy arrays, world frame).

depth (N,), translation, normal, facet_normal, witness_p, witness_q (N, 3), lower_bound,
upper_bound (N,) (equal to depth: exact methods), candidates (N,) int64 (work counter),
overlapping (N,) bool, feature_p / feature_q (N, 2) int64 [kind, index] (kind 0 none,
1 vertex, 2 edge = level-0 half-edge id, 3 face = triangle id), piece_p / piece_q (N,) int64
(a mesh pair: the convex pieces, Shape3 decomposition order, whose features feature_p /
feature_q index; -1 for convex pairs), kind. A query given as one (3,) point has scalars and
(3,) vectors instead.)")
      .def_readonly("depth", &Result3::depth)
      .def_readonly("translation", &Result3::translation)
      .def_readonly("normal", &Result3::normal)
      .def_readonly("facet_normal", &Result3::facet_normal)
      .def_readonly("witness_p", &Result3::witness_p)
      .def_readonly("witness_q", &Result3::witness_q)
      .def_readonly("feature_p", &Result3::feature_p)
      .def_readonly("feature_q", &Result3::feature_q)
      .def_readonly("lower_bound", &Result3::lower_bound)
      .def_readonly("upper_bound", &Result3::upper_bound)
      .def_readonly("candidates", &Result3::candidates)
      .def_readonly("overlapping", &Result3::overlapping)
      .def_readonly("piece_p", &Result3::piece_p)
      .def_readonly("piece_q", &Result3::piece_q)
      .def_readonly("kind", &Result3::kind)
      .def("__len__", [](const Result3& r) { return r.size; })
      .def("__repr__", [](const Result3& r) {
        return "<pendepth.Depth3Result " + r.kind + ", " + (r.single ? "one pose" : std::to_string(r.size) + " poses") + ">";
      });

  // ---- Shape2 ----
  py::class_<Shape2>(m, "Shape2", kShape2Doc)
      .def(py::init(&make_shape2), py::arg("outer"), py::arg("holes") = py::none(), py::arg("name") = "shape")
      .def_static("from_wkt", [](const std::string& text, const std::string& name) { return Shape2::from_wkt(text, name); },
                  py::arg("text"), py::arg("name") = "shape",
                  "from_wkt(text, name=\"shape\") -> Shape2\n\nOne POLYGON ((...), (...)) in WKT. Raises InvalidInput \"NAME:LINE: problem\".")
      .def_static("from_file", [](const std::string& path, const std::string& name) { return Shape2::from_file(path, name); },
                  py::arg("path"), py::arg("name") = "shape",
                  "from_file(path, name=\"shape\") -> Shape2\n\nA .wkt file. Raises InvalidInput \"PATH:LINE: problem\".")
      // Points and segments (issue 16 item 4; docs/design.md "Lower-dimensional shapes").
      .def_static("point", [](const py::object& p, const std::string& name) { return Shape2::point(vec2_of(p, name), name); },
                  py::arg("p"), py::arg("name") = "point", "point(p, name=\"point\") -> Shape2: a point (dimension 0).")
      .def_static("segment", [](const py::object& a, const py::object& b, const std::string& name) {
                    return Shape2::segment(vec2_of(a, name), vec2_of(b, name), name);
                  }, py::arg("a"), py::arg("b"), py::arg("name") = "segment",
                  "segment(a, b, name=\"segment\") -> Shape2: a segment (dimension 1). Pairs with any solid Shape2.")
      .def_property_readonly("dimension", &Shape2::dimension, "2 for a polygon, 0 for a point, 1 for a segment.")
      .def_property_readonly("is_convex", &Shape2::is_convex)
      .def_property_readonly("hole_count", &Shape2::hole_count)
      .def_property_readonly("name", &Shape2::name)
      .def("rotated", &Shape2::rotated, py::arg("degrees"),
           "rotated(degrees) -> Shape2\n\nThe shape turned counter-clockwise about its origin: exact for multiples of 90, "
           "else each coordinate rotated once with the rounded cos and sin.")
      .def("rings", &rings_of,
           "rings() -> list of (k, 2) arrays\n\nThe rings in normal form: the outer ring counter-clockwise first, then the holes clockwise, as (k, 2) arrays.")
      .def("input_vertex", [](const Shape2& s, std::size_t v) { auto a = s.input_vertex(v); return py::make_tuple(a[0], a[1]); },
           py::arg("vertex"), "input_vertex(vertex) -> (ring, index)\n\n(ring, index) as given on input of the vertex a result feature names.")
      .def("__len__", &Shape2::size)
      .def("__repr__", [](const Shape2& s) {
        if (s.dimension() < 2) return "<pendepth.Shape2 '" + s.name() + "': " + (s.dimension() == 0 ? "point" : "segment") + ">";
        return "<pendepth.Shape2 '" + s.name() + "': " + std::to_string(s.size()) + " vertices, " +
               (s.is_convex() ? "convex" : std::to_string(s.hole_count()) + " holes") + ">";
      })
      .def(py::pickle([](const Shape2& s) {
                        if (s.dimension() < 2) return py::make_tuple(rings_of(s), s.name(), s.dimension());
                        return py::make_tuple(rings_of(s), s.name());
                      },
                      [](const py::tuple& st) {
                        py::list rings = st[0];
                        if (st.size() > 2) {  // a point or a segment: its vertices
                          const auto v = ring(rings[0], "state");
                          const std::string name = st[1].cast<std::string>();
                          return v.size() == 1 ? Shape2::point(v[0], name) : Shape2::segment(v.at(0), v.at(1), name);
                        }
                        py::list holes;
                        for (std::size_t k = 1; k < rings.size(); ++k) holes.append(rings[k]);
                        return make_shape2(rings[0], holes, st[1].cast<std::string>());
                      }));

  m.def("trajectory", [](const Shape2& P, const Shape2& Q, const py::object& offsets, const py::object& angles,
                         bool warm) {
        const Points<2> ts = points<2>(offsets, "offsets");
        const Array a = py::cast<Array>(angles);
        if (!(a.ndim() == 1 && static_cast<std::size_t>(a.shape(0)) == ts.v.size()) && !(a.ndim() == 0 && ts.single))
          throw InvalidInput("angles: expected one angle (degrees) per offset, got shape " + shape_text(a));
        std::vector<Placement2> pl(ts.v.size());
        for (std::size_t i = 0; i < pl.size(); ++i) pl[i] = {ts.v[i], a.data()[i]};
        std::vector<Depth2> out;
        {
          py::gil_scoped_release nogil;
          out = trajectory(P, Q, pl, warm);
        }
        // The result's pair: P and Q at the first angle (what its picture shows).
        const py::object first = pl.empty() ? py::none() : py::cast(PyPair2{Pair2(P, Q.rotated(pl[0].degrees)), "auto"});
        return result2(out, ts.single, first, py::cast<Array>(offsets).attr("copy")(), py::none(), DepthKind::Minimum,
                       "trajectory");
      }, py::arg("P"), py::arg("Q"), py::arg("offsets"), py::arg("angles"), py::kw_only(), py::arg("warm") = true,
      R"(trajectory(P, Q, offsets, angles, warm=True) -> Depth2Result

sigma along a 2D path: Q rotated counter-clockwise by angles[i] degrees about its origin (exact at quarter
turns, one rounding per coordinate otherwise),
then placed at offsets[i]. One pair per run of equal angles (warm=False: a pair per placement); the
answers equal Pair2(P, Q rotated by a).minimum(t) bit for bit. The result's pair is P with Q at the first
angle; engine is "trajectory".)");

  m.def("no_fit_polygon", [](const Shape2& P, const Shape2& Q) {
        NoFitPolygonParts n;
        {
          py::gil_scoped_release nogil;
          n = no_fit_polygon(P, Q);
        }
        return nfp_object(n);
      }, py::arg("P"), py::arg("Q"),
      R"(no_fit_polygon(P, Q) -> namespace(polygons, slits, points)

The no-fit polygon of P and Q: the boundary of O = {t : int P and int(Q + t) overlap}.

Returns a namespace with polygons (a list of polygons, each a list of rings as (k, 2) arrays:
outer counter-clockwise, then holes clockwise), slits ((s, 2, 2): touching segments inside O)
and points ((p, 2): exact fits). Vertices rounded to the nearest double.)");

  // Whole nesting instances (pendepth.hpp no_fit_polygons, nesting.hpp).
  m.def("no_fit_polygons", [](const std::vector<Shape2>& shapes, const py::object& rotations, const py::object& threads) {
        // One list of angles for every shape, or one list per shape; None: 0 only.
        std::vector<std::vector<double>> rot;
        if (rotations.is_none()) rot = {{0.0}};
        else {
          const py::sequence seq = rotations;
          const bool per_shape = seq.size() > 0 && py::isinstance<py::sequence>(seq[0]);
          if (per_shape) rot = py::cast<std::vector<std::vector<double>>>(rotations);
          else rot = {py::cast<std::vector<double>>(rotations)};
        }
        const unsigned n = thread_count(threads);
        std::vector<NoFitPolygonEntry> e;
        {
          py::gil_scoped_release nogil;
          e = no_fit_polygons(shapes, rot, n);
        }
        py::list out;
        for (const NoFitPolygonEntry& x : e) out.append(py::make_tuple(x.i, x.rotation_i, x.j, x.rotation_j, nfp_object(x.nfp)));
        return out;
      }, py::arg("shapes"), py::arg("rotations") = py::none(), py::arg("threads") = py::none(),
      R"(no_fit_polygons(shapes, rotations=None, threads=None) -> list of (i, rotation_i, j, rotation_j, nfp)

The no-fit polygons of a whole instance: for every ordered pair (i, j) of shapes (i == j too) and
every rotation a of shape i and b of shape j (degrees; quarter turns exact, other angles rounded
once), nfp = no_fit_polygon(shapes[i].rotated(a), shapes[j].rotated(b)), in the order i, a, j, b.
rotations: one list of angles for every shape, or one list per shape (None: 0 only). Built in
parallel (threads: None = every core); the result does not depend on the thread count.)");
  m.def("read_nesting_instance", [](const std::string& path) {
        const NestingInstance inst = read_nesting_instance(path);
        py::object ns = py::module_::import("types").attr("SimpleNamespace");
        py::list items;
        for (const NestingItem& it : inst.items)
          items.append(ns(py::arg("id") = it.id, py::arg("demand") = it.demand, py::arg("shape") = it.shape,
                          py::arg("allowed_orientations") = it.allowed_orientations));
        return ns(py::arg("name") = inst.name, py::arg("items") = items);
      }, py::arg("path"),
      R"(read_nesting_instance(path) -> namespace(name, items)

An ESICUP / jagua-rs JSON nesting instance: items[k] = namespace(id, demand, shape (a Shape2,
validated once), allowed_orientations (degrees; [0.0] when absent)). Bad input raises InvalidInput
"PATH: item K (id X): problem".)");

  // ---- Pair2 ----
  py::class_<PyPair2>(m, "Pair2", kPair2Doc)
      .def(py::init([](const Shape2& P, const Shape2& Q, const std::string& prepare) {
             const Prepare p = prepare_of(prepare);
             py::gil_scoped_release nogil;
             return PyPair2{Pair2(P, Q, p), prepare};
           }),
           py::arg("P"), py::arg("Q"), py::arg("prepare") = "auto")
      .def_property_readonly("P", [](const PyPair2& p) { return p.pair.P(); })
      .def_property_readonly("Q", [](const PyPair2& p) { return p.pair.Q(); })
      .def_property_readonly("prepare", [](const PyPair2& p) { return p.prepare; })
      .def_property_readonly("engine", [](const PyPair2& p) { return std::string(to_string(p.pair.engine())); },
                             "The engine answering: \"convex\", \"polygon-convex\", \"convex-polygon\" (P convex, Q a polygon), \"pair-per-query\" or \"no-fit-polygon\".")
      .def("no_fit_polygon", [](const PyPair2& p) {
             const NoFitPolygonParts* n;
             {
               py::gil_scoped_release nogil;
               n = &p.pair.no_fit_polygon();
             }
             return nfp_object(*n);
           }, "no_fit_polygon() -> namespace(polygons, slits, points)\n\nThe pair's no-fit polygon (see pendepth.no_fit_polygon), built on first use.")
      .def("overlapping", [](const py::object& self, const py::object& offsets, const py::object& threads, bool progress) -> py::object {
             const PyPair2& p = self.cast<const PyPair2&>();
             Points<2> ts = points<2>(offsets, "offsets");
             const unsigned th = thread_count(threads);
             std::unique_ptr<bool[]> out(new bool[ts.v.size()]());
             if (progress) front::check_batch<Vec2>(ts.v, {}, ts.v.size(), false);
             chunked(ts.v.size(), progress, [&](std::size_t b, std::size_t e) {
               std::span<bool> o(out.get() + b, e - b);
               p.pair.overlapping(std::span<const Vec2>(ts.v).subspan(b, e - b), o, th);
             });
             if (ts.single) return py::bool_(out[0]);
             py::array_t<bool> a(static_cast<py::ssize_t>(ts.v.size()));
             std::copy(out.get(), out.get() + ts.v.size(), a.mutable_data());
             return a;
           }, py::arg("offsets"), py::kw_only(), py::arg("threads") = py::none(), py::arg("progress") = false, kOverlappingDoc)
      .def("minimum", [](const py::object& self, const py::object& offsets, const py::object& threads, bool progress) {
             const PyPair2& p = self.cast<const PyPair2&>();
             Points<2> ts = points<2>(offsets, "offsets");
             const unsigned th = thread_count(threads);
             std::vector<Depth2> out(ts.v.size());
             if (progress) front::check_batch<Vec2>(ts.v, {}, out.size(), false);
             chunked(ts.v.size(), progress, [&](std::size_t b, std::size_t e) {
               p.pair.minimum(std::span<const Vec2>(ts.v).subspan(b, e - b), std::span<Depth2>(out).subspan(b, e - b), th);
             });
             return result2(out, ts.single, self, Array(py::cast<Array>(offsets)).attr("copy")(), py::none(),
                            DepthKind::Minimum, to_string(p.pair.engine()));
           }, py::arg("offsets"), py::kw_only(), py::arg("threads") = py::none(), py::arg("progress") = false, kMinimumDoc)
      .def("along", [](const py::object& self, const py::object& offsets, const py::object& directions, const py::object& threads,
                       bool progress) {
             return directional2(self, offsets, directions, threads, progress, DepthKind::Directional,
                                 [](const Pair2& pair, auto ts, auto ds, auto out, unsigned th) { pair.along(ts, ds, out, th); });
           }, py::arg("offsets"), py::arg("directions"), py::kw_only(), py::arg("threads") = py::none(),
           py::arg("progress") = false, kAlongDoc)
      .def("separation", [](const py::object& self, const py::object& offsets, const py::object& directions,
                            const py::object& threads, bool progress) {
             return directional2(self, offsets, directions, threads, progress, DepthKind::Separation,
                                 [](const Pair2& pair, auto ts, auto ds, auto out, unsigned th) { pair.separation(ts, ds, out, th); });
           }, py::arg("offsets"), py::arg("directions"), py::kw_only(), py::arg("threads") = py::none(),
           py::arg("progress") = false, kSeparationDoc)
      .def("signed_distance", [](const PyPair2& p, const py::object& offsets, const py::object& threads, bool progress) {
             Points<2> ts = points<2>(offsets, "offsets");
             const unsigned th = thread_count(threads);
             std::vector<Distance2> out(ts.v.size());
             if (progress) front::check_batch<Vec2>(ts.v, {}, out.size(), false);
             chunked(ts.v.size(), progress, [&](std::size_t b, std::size_t e) {
               p.pair.signed_distance(std::span<const Vec2>(ts.v).subspan(b, e - b), std::span<Distance2>(out).subspan(b, e - b), th);
             });
             return distance_result(out, ts.single);
           }, py::arg("offsets"), py::kw_only(), py::arg("threads") = py::none(), py::arg("progress") = false, kSignedDistanceDoc)
      .def("depth_value", [](const PyPair2& p, const py::object& offsets) {
             Points<2> ts = points<2>(offsets, "offsets");
             front::check_batch<Vec2>(ts.v, {}, ts.v.size(), false);
             std::vector<DepthValue2> out(ts.v.size());
             {
               py::gil_scoped_release nogil;
               for (std::size_t i = 0; i < out.size(); ++i) out[i] = p.pair.depth_value(ts.v[i]);
             }
             return value_result(out, ts.single);
           }, py::arg("offsets"), kDepthValueDoc)
      .def("directional_depth_value", [](const PyPair2& p, const py::object& offsets, const py::object& directions) {
             Points<2> ts = points<2>(offsets, "offsets"), ds = points<2>(directions, "directions");
             front::check_batch<Vec2>(ts.v, ds.v, ts.v.size(), true);
             std::vector<DepthValue2> out(ts.v.size());
             {
               py::gil_scoped_release nogil;
               for (std::size_t i = 0; i < out.size(); ++i) out[i] = p.pair.directional_depth_value(ts.v[i], ds.v[ds.v.size() == 1 ? 0 : i]);
             }
             return value_result(out, ts.single);
           }, py::arg("offsets"), py::arg("directions"), kDirectionalDepthValueDoc)
      .def("cast", [](const PyPair2& p, const py::object& offsets, const py::object& directions) {
             Points<2> ts = points<2>(offsets, "offsets"), ds = points<2>(directions, "directions");
             front::check_batch<Vec2>(ts.v, ds.v, ts.v.size(), true);
             std::vector<Cast2> out(ts.v.size());
             {
               py::gil_scoped_release nogil;
               for (std::size_t i = 0; i < out.size(); ++i) out[i] = p.pair.cast(ts.v[i], ds.v[ds.v.size() == 1 ? 0 : i]);
             }
             return distance_result(out, ts.single);
           }, py::arg("offsets"), py::arg("directions"), kCastDoc)
      .def("__repr__", [](const PyPair2& p) {
        return "<pendepth.Pair2 P='" + p.pair.P().name() + "' Q='" + p.pair.Q().name() + "' engine " +
               to_string(p.pair.engine()) + ", prepare \"" + p.prepare + "\">";
      })
      .def(py::pickle([](const PyPair2& p) { return py::make_tuple(p.pair.P(), p.pair.Q(), p.prepare); },
                      [](const py::tuple& st) {
                        const std::string prep = st[2].cast<std::string>();
                        return PyPair2{Pair2(st[0].cast<Shape2>(), st[1].cast<Shape2>(), prepare_of(prep)), prep};
                      }));

  // ---- Shape3 ----
  py::class_<Shape3>(m, "Shape3", kShape3Doc)
      .def_static("hull", [](const py::object& pts, const std::string& name) {
                    Array a = py::cast<Array>(pts);
                    if (a.ndim() != 2 || a.shape(1) != 3)
                      throw InvalidInput(name + ": expected an (n, 3) array of points, got shape " + shape_text(a));
                    std::vector<Vec3> v(static_cast<std::size_t>(a.shape(0)));
                    for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec3(a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]);
                    py::gil_scoped_release nogil;
                    return Shape3::hull(v, name);
                  }, py::arg("points"), py::arg("name") = "points",
                  "hull(points, name=\"points\") -> Shape3\n\nExact convex hull of an (n, 3) array. Raises InvalidInput for non-finite or flat input.")
      .def_static("from_file", [](const std::string& path, const std::string& name, bool hull) { return Shape3::from_file(path, name, hull); },
                  py::arg("path"), py::arg("name") = "shape", py::arg("hull") = false,
                  "from_file(path, name=\"shape\", hull=False) -> Shape3\n\nA .obj, .off, .stl or .ply file: without faces the hull of its vertices; with faces a closed mesh\n(validated; a convex one takes the convex path, a non-convex one is answered piece by piece: with another mesh, a polytope,\na point or a solid primitive; segments and flat polygons are refused); hull=True: the\nhull of the vertices, faces ignored. Raises InvalidInput \"PATH:LINE: problem\".")
      // Lower-dimensional shapes and primitives (docs/python.md "Primitives").
      .def_static("point", [](const py::object& p, const std::string& name) { return Shape3::point(vec3_of(p, name), name); },
                  py::arg("p"), py::arg("name") = "point", "point(p, name=\"point\") -> Shape3: a point (dimension 0).")
      .def_static("segment", [](const py::object& a, const py::object& b, const std::string& name) {
                    return Shape3::segment(vec3_of(a, name), vec3_of(b, name), name);
                  }, py::arg("a"), py::arg("b"), py::arg("name") = "segment", "segment(a, b, name=\"segment\") -> Shape3: a segment (dimension 1).")
      .def_static("flat", [](const py::object& pts, const std::string& name) {
                    Array a = py::cast<Array>(pts);
                    if (a.ndim() != 2 || a.shape(1) != 3)
                      throw InvalidInput(name + ": expected an (n, 3) array of points, got shape " + shape_text(a));
                    std::vector<Vec3> v(static_cast<std::size_t>(a.shape(0)));
                    for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec3(a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]);
                    return Shape3::flat(v, name);
                  }, py::arg("points"), py::arg("name") = "points",
                  "flat(points, name=\"points\") -> Shape3\n\nThe convex hull of a point set of dimension 0, 1 or 2 (a point, a segment, a flat polygon).\nPaired with a solid shape only.")
      .def_static("box", &Shape3::box, py::arg("hx"), py::arg("hy"), py::arg("hz"), py::arg("name") = "box",
                  "box(hx, hy, hz, name=\"box\") -> Shape3: the box of half extents hx, hy, hz centred at the origin.")
      .def_static("sphere", &Shape3::sphere, py::arg("r"), py::arg("name") = "sphere",
                  "sphere(r, name=\"sphere\") -> Shape3: the ball of radius r at the origin (a point ⊕ ball).")
      .def_static("capsule", &Shape3::capsule, py::arg("r"), py::arg("h"), py::arg("name") = "capsule",
                  "capsule(r, h, name=\"capsule\") -> Shape3: the segment (0,0,-h)-(0,0,h) ⊕ ball of radius r.")
      .def_static("cylinder", &Shape3::cylinder, py::arg("r"), py::arg("h"), py::arg("name") = "cylinder",
                  "cylinder(r, h, name=\"cylinder\") -> Shape3: radius r about the z axis, z in [-h, h] (curved: certified brackets).")
      .def_static("cone", &Shape3::cone, py::arg("r"), py::arg("h"), py::arg("name") = "cone",
                  "cone(r, h, name=\"cone\") -> Shape3: base radius r at z = -h, apex (0, 0, h) (curved: certified brackets).")
      .def_static("ellipsoid", &Shape3::ellipsoid, py::arg("a"), py::arg("b"), py::arg("c"), py::arg("name") = "ellipsoid",
                  "ellipsoid(a, b, c, name=\"ellipsoid\") -> Shape3: semi-axes a, b, c along x, y, z (curved: certified brackets).")
      .def_static("rounded", &Shape3::rounded, py::arg("core"), py::arg("r"), py::arg("name") = "rounded",
                  "rounded(core, r, name=\"rounded\") -> Shape3: core ⊕ ball of radius r (r >= 0).")
      .def_property_readonly("dimension", &Shape3::dimension, "3 for a solid (rounded shapes included); 0, 1, 2 for a point, segment, flat polygon.")
      .def_property_readonly("radius", &Shape3::radius, "The rounding radius (0 without rounding).")
      .def_property_readonly("core", &Shape3::core, "The shape without its rounding.")
      .def_property_readonly("is_convex", &Shape3::is_convex)
      .def_property_readonly("name", &Shape3::name)
      .def_property_readonly("vertices", [](const Shape3& s) {
             if (s.flat_shape()) {
               auto v = s.flat_vertices();
               return to_array<3>(std::vector<Vec3>(v.begin(), v.end()));
             }
             auto v = s.polytope().vertices();
             return to_array<3>(std::vector<Vec3>(v.begin(), v.end()));
           }, "The hull's vertices, (n, 3) (of the core for a rounded shape; a lower-dimensional core's vertices).")
      .def_property_readonly("triangles", [](const Shape3& s) {
             auto t = s.polytope().triangles();
             py::array_t<std::int64_t> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(t.size()), 3});
             for (std::size_t i = 0; i < t.size(); ++i)
               for (int k = 0; k < 3; ++k) a.mutable_data()[3 * i + k] = t[i][k];
             return a;
           }, "The hull's triangles (indices into vertices, counter-clockwise seen from outside), (k, 3).")
      .def("__len__", &Shape3::size)
      .def("__repr__", [](const Shape3& s) { return "<pendepth.Shape3 '" + s.name() + "': " + std::to_string(s.size()) + " vertices>"; })
      .def(py::pickle([](const Shape3& s) {
                        if (!s.is_convex())  // its hull would come back: refuse rather than change the shape
                          throw InvalidInput("pickle: " + s.name() + " is a non-convex mesh; pickling meshes is not supported yet");
                        const Shape3 c = s.core();
                        if (const auto* k = c.curved())  // curved primitives: their parameters
                          return py::make_tuple("curved", static_cast<int>(k->kind), k->a, k->b, k->c, c.name(), s.radius(), s.name());
                        std::vector<Vec3> v;
                        if (c.flat_shape()) v.assign(c.flat_vertices().begin(), c.flat_vertices().end());
                        else v.assign(c.polytope().vertices().begin(), c.polytope().vertices().end());
                        return py::make_tuple(to_array<3>(v), c.name(), s.radius(), s.name(), c.dimension());
                      },
                      [](const py::tuple& st) {
                        if (py::isinstance<py::str>(st[0])) {  // a curved primitive (see above)
                          const int kind = st[1].cast<int>();
                          const double a = st[2].cast<double>(), b = st[3].cast<double>(), c = st[4].cast<double>();
                          const std::string name = st[5].cast<std::string>();
                          const Shape3 core = kind == static_cast<int>(primitives::Curved3::Kind::Cylinder) ? Shape3::cylinder(a, b, name)
                                              : kind == static_cast<int>(primitives::Curved3::Kind::Cone)   ? Shape3::cone(a, b, name)
                                                                                                               : Shape3::ellipsoid(a, b, c, name);
                          const double r = st[6].cast<double>();
                          return r > 0 ? Shape3::rounded(core, r, st[7].cast<std::string>()) : core;
                        }
                        Array a = py::cast<Array>(st[0]);
                        std::vector<Vec3> v(static_cast<std::size_t>(a.shape(0)));
                        for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec3(a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]);
                        const std::string name = st[1].cast<std::string>();
                        if (st.size() < 5) return Shape3::hull(v, name);
                        const Shape3 core = st[4].cast<int>() < 3 ? Shape3::flat(v, name) : Shape3::hull(v, name);
                        const double r = st[2].cast<double>();
                        return r > 0 ? Shape3::rounded(core, r, st[3].cast<std::string>()) : core;
                      }));

  // ---- (1+δ)-approximate σ of huge 3D point sets (include/pendepth/approximate.hpp) ----
  m.def("approximate_minimum_depth", [](const py::object& P, const py::object& Q, double delta, const py::object& translation,
                                        const py::object& rotation) {
          auto cloud = [](const py::object& o, const char* what) {
            Array a = py::cast<Array>(o);
            if (a.ndim() != 2 || a.shape(1) != 3)
              throw InvalidInput(std::string(what) + ": expected an (n, 3) array of points, got shape " + shape_text(a));
            std::vector<Vec3> v(static_cast<std::size_t>(a.shape(0)));
            for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec3(a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]);
            return v;
          };
          const std::vector<Vec3> vp = cloud(P, "P"), vq = cloud(Q, "Q");
          Pose3 pose_q;
          if (!translation.is_none()) {
            Points<3> t = points<3>(translation, "translation");
            if (!t.single) throw InvalidInput("translation: expected one (3,) vector");
            pose_q.translation = t.v[0];
          }
          if (!rotation.is_none()) {
            Points<4> q = points<4>(rotation, "rotation");
            if (!q.single) throw InvalidInput("rotation: expected one (4,) quaternion w, x, y, z");
            pose_q.rotation = Eigen::Quaterniond(q.v[0][0], q.v[0][1], q.v[0][2], q.v[0][3]);
          }
          ApproxDepth3 r;
          {
            py::gil_scoped_release nogil;
            r = approximate_minimum_depth(vp, Pose3(), vq, pose_q, delta);
          }
          py::dict d;
          d["depth"] = r.depth, d["lower_bound"] = r.lower_bound, d["upper_bound"] = r.upper_bound;
          d["normal"] = py::make_tuple(r.normal.x(), r.normal.y(), r.normal.z());
          d["translation"] = py::make_tuple(r.translation.x(), r.translation.y(), r.translation.z());
          d["converged"] = r.converged, d["overlapping"] = r.overlapping;
          d["kernel_p"] = r.kernel_p, d["kernel_q"] = r.kernel_q;
          return d;
        },
        py::arg("P"), py::arg("Q"), py::arg("delta"), py::arg("translation") = py::none(), py::arg("rotation") = py::none(),
        "approximate_minimum_depth(P, Q, delta, translation=None, rotation=None) -> dict\n\n"
        "Certified (1+delta)-approximate minimum depth of the convex hulls of two (n, 3) point arrays, Q posed by\n"
        "translation (3,) and rotation (w, x, y, z), without building the hulls. Keys: depth (== upper_bound, the\n"
        "length of a separating move), lower_bound, upper_bound (lower <= sigma <= upper <= (1+delta)*lower when\n"
        "converged), normal, translation, converged, overlapping, kernel_p, kernel_q. delta in [1e-9, 1).");

  // ---- Pair3 ----
  auto pose_batch = [](const py::object& translations, const py::object& rotations, bool& single) {
    Points<3> ts = points<3>(translations, "translations");
    return poses(ts, rotations, single);
  };
  py::class_<PyPair3>(m, "Pair3", kPair3Doc)
      .def(py::init([](const Shape3& P, const Shape3& Q, const std::string& prepare) {
             return PyPair3{Pair3(P, Q, prepare_of(prepare)), prepare};
           }),
           py::arg("P"), py::arg("Q"), py::arg("prepare") = "auto")
      .def_property_readonly("P", [](const PyPair3& p) { return p.pair.P(); })
      .def_property_readonly("Q", [](const PyPair3& p) { return p.pair.Q(); })
      .def_property_readonly("prepare", [](const PyPair3& p) { return p.prepare; })
      .def("overlapping", [pose_batch](const PyPair3& p, const py::object& translations, const py::object& rotations,
                                       const py::object& threads, bool progress) -> py::object {
             bool single = false;
             std::vector<Pose3> ps = pose_batch(translations, rotations, single);
             const unsigned th = thread_count(threads);
             std::unique_ptr<bool[]> out(new bool[ps.size()]());
             if (progress) check_poses(ps);
             chunked(ps.size(), progress, [&](std::size_t b, std::size_t e) {
               p.pair.overlapping(std::span<const Pose3>(ps).subspan(b, e - b), std::span<bool>(out.get() + b, e - b), th);
             });
             if (single) return py::bool_(out[0]);
             py::array_t<bool> a(static_cast<py::ssize_t>(ps.size()));
             std::copy(out.get(), out.get() + ps.size(), a.mutable_data());
             return a;
           }, py::arg("translations"), py::arg("rotations") = py::none(), py::kw_only(), py::arg("threads") = py::none(),
           py::arg("progress") = false,
           "overlapping(translations, rotations=None, threads=None, progress=False) -> (N,) bool or bool\n\n"
           "Exact: do the interiors of P and the posed Q overlap? Touching is not overlapping.")
      .def("minimum", [pose_batch](const PyPair3& p, const py::object& translations, const py::object& rotations,
                                   const py::object& threads, bool progress) {
             bool single = false;
             std::vector<Pose3> ps = pose_batch(translations, rotations, single);
             const unsigned th = thread_count(threads);
             std::vector<Depth3> out(ps.size());
             if (progress) check_poses(ps);
             chunked(ps.size(), progress, [&](std::size_t b, std::size_t e) {
               p.pair.minimum(std::span<const Pose3>(ps).subspan(b, e - b), std::span<Depth3>(out).subspan(b, e - b), th);
             });
             return result3(out, single, DepthKind::Minimum);
           }, py::arg("translations"), py::arg("rotations") = py::none(), py::kw_only(), py::arg("threads") = py::none(),
           py::arg("progress") = false,
           "minimum(translations, rotations=None, threads=None, progress=False) -> Depth3Result\n\n"
           "sigma, exact: the shortest translation of the posed Q separating the interiors (world frame);\n"
           "lower_bound == upper_bound == depth. 0 and zero vectors when not overlapping.\n"
           "rotations: None, (N, 4) or one (4,) quaternion w, x, y, z.")
      .def("along", [](const PyPair3& p, const py::object& translations, const py::object& directions,
                       const py::object& rotations, const py::object& threads, bool progress) {
             return along3(p, translations, directions, rotations, threads, progress, DepthKind::Directional);
           }, py::arg("translations"), py::arg("directions"), py::arg("rotations") = py::none(), py::kw_only(),
           py::arg("threads") = py::none(), py::arg("progress") = false,
           "along(translations, directions, rotations=None, threads=None, progress=False) -> Depth3Result\n\n"
           "sigma_d, exact: the shortest translation of the posed Q along d (world frame) separating the\n"
           "interiors; directions (N, 3) or one (3,) for all, any non-zero finite length.\n"
           "Raises InvalidInput for zero or non-finite directions.")
      .def("separation", [](const PyPair3& p, const py::object& translations, const py::object& directions,
                            const py::object& rotations, const py::object& threads, bool progress) {
             // Pair3::separation is along with kind Separation (the ray leaves the convex M once)
             return along3(p, translations, directions, rotations, threads, progress, DepthKind::Separation);
           }, py::arg("translations"), py::arg("directions"), py::arg("rotations") = py::none(), py::kw_only(),
           py::arg("threads") = py::none(), py::arg("progress") = false,
           "separation(translations, directions, rotations=None, threads=None, progress=False) -> Depth3Result\n\n"
           "Complete separation along d: for convex shapes the ray leaves M once, so this is sigma_d\n"
           "(along) with kind \"separation\"; for meshes the last exit of the ray from the overlap set.\n"
           "Raises InvalidInput for zero or non-finite directions.")
      // ---- signed distance and shape cast (issue 16) ----
      .def("signed_distance", [pose_batch](const PyPair3& p, const py::object& translations, const py::object& rotations,
                                           const py::object& threads, bool progress) {
             bool single = false;
             std::vector<Pose3> ps = pose_batch(translations, rotations, single);
             const unsigned th = thread_count(threads);
             std::vector<Distance3> out(ps.size());
             if (progress) check_poses(ps);
             chunked(ps.size(), progress, [&](std::size_t b, std::size_t e) {
               p.pair.signed_distance(std::span<const Pose3>(ps).subspan(b, e - b), std::span<Distance3>(out).subspan(b, e - b), th);
             });
             return distance_like(out, single);
           }, py::arg("translations"), py::arg("rotations") = py::none(), py::kw_only(), py::arg("threads") = py::none(),
           py::arg("progress") = false,
           "signed_distance(translations, rotations=None, threads=None, progress=False) -> namespace\n\n"
           "Exact signed distance (FCL / Drake convention): > 0 apart (Euclidean distance), 0 touching,\n"
           "-sigma overlapping. Fields: distance, translation (moves Q into touching contact), normal\n"
           "(from P towards Q), witness_p, witness_q (on the unmoved Q), feature_p, feature_q (kind: 0 none,\n"
           "1 vertex, 2 edge, 3 face; index), lower_bound, upper_bound, overlapping, piece_p, piece_q (meshes:\n"
           "the convex pieces the features index; -1 for convex pairs).")
      .def("cast", [pose_batch](const PyPair3& p, const py::object& translations, const py::object& directions,
                                const py::object& rotations) {
             bool single = false;
             std::vector<Pose3> ps = pose_batch(translations, rotations, single);
             Points<3> ds = points<3>(directions, "directions");
             if (ds.v.size() != 1 && ds.v.size() != ps.size())
               throw InvalidInput("cast: " + std::to_string(ds.v.size()) + " directions for " + std::to_string(ps.size()) +
                                  " poses (give one direction, or one per pose)");
             std::vector<Cast3> out(ps.size());
             {
               py::gil_scoped_release nogil;
               for (std::size_t i = 0; i < ps.size(); ++i) out[i] = p.pair.cast(Pose3(), ps[i], ds.v[ds.v.size() == 1 ? 0 : i]);
             }
             return distance_like(out, single);
           }, py::arg("translations"), py::arg("directions"), py::arg("rotations") = py::none(),
           "cast(translations, directions, rotations=None) -> namespace\n\n"
           "Shape cast (time of impact): the smallest s >= 0 such that Q moved by s*d/|d| touches P; inf\n"
           "and hit False when it never does, 0 when already touching or overlapping. Fields: distance,\n"
           "translation, normal (outward normal of P - Q at the contact), witness_p, witness_q (the\n"
           "contact point), feature_p, feature_q, hit, overlapping, lower_bound <= the exact entry <=\n"
           "upper_bound (equal to distance for polytopes and flat shapes; a certified bracket for rounded\n"
           "shapes, distance its upper end; inf on a miss), piece_p, piece_q (meshes, as signed_distance).")
      .def("trajectory", [pose_batch](const PyPair3& p, const py::object& translations, const py::object& rotations,
                                      bool warm) {
             bool single = false;
             const std::vector<Pose3> ps = pose_batch(translations, rotations, single);
             std::vector<Depth3> out;
             {
               py::gil_scoped_release nogil;
               out = p.pair.trajectory(Pose3(), ps, warm);
             }
             return result3(out, single, DepthKind::Minimum);
           }, py::arg("translations"), py::arg("rotations") = py::none(), py::kw_only(), py::arg("warm") = true,
           "trajectory(translations, rotations=None, warm=True) -> Depth3Result\n\n"
           "sigma at every pose of a path, in order, each warm-started from the previous one (warm=False:\n"
           "each from scratch). Equal to minimum() bit for bit but `candidates` (the support queries).")
      .def("__repr__", [](const PyPair3& p) {
        return "<pendepth.Pair3 P='" + p.pair.P().name() + "' Q='" + p.pair.Q().name() + "'>";
      })
      .def(py::pickle([](const PyPair3& p) { return py::make_tuple(p.pair.P(), p.pair.Q(), p.prepare); },
                      [](const py::tuple& st) {
                        const std::string prep = st[2].cast<std::string>();
                        return PyPair3{Pair3(st[0].cast<Shape3>(), st[1].cast<Shape3>(), prepare_of(prep)), prep};
                      }));

  // ---- generalized depth PD_g (issue 18; include/pendepth/motion.hpp) ----
  m.def("generalized_depth", [](const Shape2& P, const Shape2& Q, const py::object& offset, double min_degrees,
                                double max_degrees, std::size_t max_probes, double tolerance, std::size_t max_intervals) {
        Points<2> t = points<2>(offset, "offset");
        if (!t.single) throw InvalidInput("offset: expected one (2,) point");
        GeneralizedOptions2 o;
        o.min_degrees = min_degrees, o.max_degrees = max_degrees, o.max_probes = max_probes, o.tolerance = tolerance;
        o.max_intervals = max_intervals;
        GeneralizedDepth2 r;
        {
          py::gil_scoped_release nogil;
          r = generalized_depth(P, Q, t.v[0], o);
        }
        return py::module_::import("types").attr("SimpleNamespace")(
            py::arg("kind") = "generalized", py::arg("depth") = r.depth, py::arg("lower_bound") = r.lower_bound,
            py::arg("upper_bound") = r.upper_bound, py::arg("angle") = r.angle,
            py::arg("translation") = to_array<2>(std::vector<Vec2>{r.translation}).attr("reshape")(2),
            py::arg("sigma") = r.sigma, py::arg("sigma_at_angle") = r.sigma_at_angle, py::arg("overlapping") = r.overlapping,
            py::arg("rotation_exact") = r.rotation_exact, py::arg("converged") = r.converged, py::arg("probes") = r.probes,
            py::arg("intervals") = r.intervals);
      }, py::arg("P"), py::arg("Q"), py::arg("offset"), py::kw_only(), py::arg("min_degrees") = -180.0,
      py::arg("max_degrees") = 180.0, py::arg("max_probes") = 512, py::arg("tolerance") = 1e-6,
      py::arg("max_intervals") = 4000,
      R"(generalized_depth(P, Q, offset, *, min_degrees=-180, max_degrees=180, max_probes=512, tolerance=1e-6, max_intervals=4000)

2D generalized depth PD_g: Q (placed at offset) may rotate about its reference point by an angle in
[min_degrees, max_degrees] (the range must contain 0) and translate; the cost of a motion is the
largest displacement of Q's points. Returns a namespace: depth (= upper_bound, the cost of the
motion found), lower_bound (certified), angle (degrees; Q's coordinates as Shape2 rotated by it),
translation (2,), sigma (translational depth, >= depth), sigma_at_angle, overlapping,
rotation_exact, converged (gap <= tolerance * depth), probes, intervals (angle intervals bounded by the
branch and bound, at most max_intervals). Convex pairs: PD_g = sigma.)");
  m.def("generalized_depth", [](const Shape3& P, const Shape3& Q, const py::object& translation, const py::object& rotation,
                                std::size_t max_probes, double tolerance) {
        Points<3> t = points<3>(translation, "translation");
        if (!t.single) throw InvalidInput("translation: expected one (3,) point");
        bool single = true;
        std::vector<Pose3> pose = poses(t, rotation, single);
        GeneralizedOptions3 o;
        o.max_probes = max_probes, o.tolerance = tolerance;
        GeneralizedDepth3 r;
        {
          py::gil_scoped_release nogil;
          r = generalized_depth(P, Pose3(), Q, pose.at(0), o);
        }
        auto quat = [](const Eigen::Quaterniond& w) {
          py::array_t<double> q(4);
          q.mutable_data()[0] = w.w(), q.mutable_data()[1] = w.x(), q.mutable_data()[2] = w.y(), q.mutable_data()[3] = w.z();
          return q;
        };
        auto vec = [](const Vec3& v) { return to_array<3>(std::vector<Vec3>{v}).attr("reshape")(3); };
        return py::module_::import("types").attr("SimpleNamespace")(
            py::arg("kind") = "generalized", py::arg("depth") = r.depth, py::arg("lower_bound") = r.lower_bound,
            py::arg("upper_bound") = r.upper_bound, py::arg("rotation") = quat(r.rotation),
            py::arg("translation") = vec(r.translation), py::arg("pose_rotation") = quat(r.pose.rotation),
            py::arg("pose_translation") = vec(r.pose.translation), py::arg("sigma") = r.sigma,
            py::arg("overlapping") = r.overlapping, py::arg("converged") = r.converged, py::arg("probes") = r.probes);
      }, py::arg("P"), py::arg("Q"), py::arg("translation"), py::arg("rotation") = py::none(), py::kw_only(),
      py::arg("max_probes") = 64, py::arg("tolerance") = 1e-9,
      R"(generalized_depth(P, Q, translation, rotation=None, *, max_probes=64, tolerance=1e-9)

3D generalized depth PD_g (P at the identity, Q posed by translation (3,) and rotation (4,) w, x, y,
z). Convex polytopes: PD_g = sigma by the theorem. Meshes (either shape non-convex): certified
lower bound (the convex pieces' bound) and the cheapest verified motion found by a local search over
rotations from the translational answer (at most max_probes rotations). Returns a namespace: depth
(= upper_bound), lower_bound, upper_bound, rotation (4,) and translation (3,) of the motion (Q turned
about its placed reference point, then moved), pose_rotation (4,) and pose_translation (3,) (Q's pose
after the motion, verified not to overlap P), sigma (translational, >= depth), overlapping,
converged (upper - lower <= tolerance * upper), probes.)");
}
