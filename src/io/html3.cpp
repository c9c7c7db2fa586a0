// The 3D picture of a query: a self-contained HTML page (docs/design.md §3, `pendepth depth
// --html`, issue 21). depth_scene3 turns a Depth3 into a Scene3 (shapes, answer, M); html_page
// writes a scene as JSON into the viewer page built from viewer/ (three.js inlined at build
// time by cmake/viewer.cmake), so that the page needs no network.
//
// Coordinates are normalised here rather than in the browser: three.js keeps positions in
// float32, which overflows at 3e38 and flushes 1e-200 to zero. view = x·2^−k − c·2^−k with c the
// centre of the scene's box and 2^k >= its largest half-extent: scaling by a power of two is
// exact, and scaling before subtracting keeps every value finite up to the double range. Lengths
// are compared by their largest component, never squared (1e200² overflows, 1e-200² is 0).
#include <pendepth/io.hpp>

#include "io/json_fields.hpp"

#ifdef PENDEPTH_HTML_VIEWER
#include <pendepth/viewer_page.hpp>
#endif

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>

namespace pendepth::io {
namespace {

// Colours of the depth scene (the viewer takes every colour from the scene).
constexpr const char* kColorP = "#4a86c5";
constexpr const char* kColorQ = "#d9604c";
constexpr const char* kColorMove = "#1f9d55";
constexpr const char* kColorWitness = "#1f2328";
constexpr const char* kColorDirection = "#7b4fc9";
constexpr const char* kColorM = "#9b7fd4";
constexpr const char* kColorMFacet = "#d6336c";  // not the features' amber: a different space
constexpr double kQOpacity = 0.55, kGhostOpacity = 0.2, kMOpacity = 0.22;
constexpr double kDirectionLength = 0.6;  // the d arrow, in units of Q's largest box half-extent

std::string text(double x) {
  std::string s;
  append_double(s, x);
  return s;
}

std::string text(const Vec3& v) { return detail::vec3_text(v); }

double max_abs(const Vec3& v) { return v.cwiseAbs().maxCoeff(); }

// v / |v| without squaring v's components (0 for v = 0).
Vec3 unit(const Vec3& v) {
  const double s = max_abs(v);
  return s > 0 ? Vec3(v / s).normalized() : Vec3::Zero();
}

struct Box3 {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool empty() const { return !(lo.x() <= hi.x()); }
  Vec3 centre() const { return Vec3(std::ldexp(lo.x(), -1) + std::ldexp(hi.x(), -1), std::ldexp(lo.y(), -1) + std::ldexp(hi.y(), -1),
                                    std::ldexp(lo.z(), -1) + std::ldexp(hi.z(), -1)); }
  double half_extent() const {
    double h = 0;
    for (int i = 0; i < 3; ++i) h = std::max(h, std::ldexp(hi[i], -1) - std::ldexp(lo[i], -1));
    return h;
  }
};

Scene3::Highlight feature_highlight(const Feature3& f, const ConvexPolytope& X) {
  Scene3::Highlight h;
  const auto tris = X.triangles();
  const auto i = static_cast<std::size_t>(f.index);
  switch (f.kind) {
    case FeatureKind3::Vertex:
      if (f.index >= 0 && i < X.size()) h.vertices.push_back(f.index);
      break;
    case FeatureKind3::Edge:
      if (f.index >= 0 && i < 3 * tris.size()) h.edges.push_back({tris[i / 3][i % 3], tris[i / 3][(i + 1) % 3]});
      break;
    case FeatureKind3::Face:
      if (f.index >= 0 && i < tris.size()) {
        const int face = X.face_of_triangle(i);  // the whole true face, not one triangle of it
        for (std::size_t t = 0; t < tris.size(); ++t)
          if (X.face_of_triangle(t) == face) h.triangles.push_back(static_cast<int>(t));
      }
      break;
    case FeatureKind3::None: break;
  }
  return h;
}

bool all_finite(const std::vector<Vec3>& pts) {
  return std::all_of(pts.begin(), pts.end(), [](const Vec3& p) { return p.allFinite(); });
}

Scene3::Mesh mesh(std::string layer, std::string color, double opacity, std::vector<Vec3> vertices,
                  std::span<const std::array<int, 3>> triangles) {
  Scene3::Mesh m;
  m.layer = std::move(layer);
  m.color = std::move(color);
  m.opacity = opacity;
  m.vertices = std::move(vertices);
  m.triangles.assign(triangles.begin(), triangles.end());
  return m;
}

// M = P ⊕ (−Q) in placement coordinates, as the hull of the n·m vertex differences, with the facet
// whose outward normal is closest to `facet_normal` highlighted (none when it is zero).
void add_minkowski(Scene3& s, const std::vector<Vec3>& pw, const std::vector<Vec3>& qrot, const Depth3& r,
                   const Vec3& t, const Html3Options& opt) {
  const std::size_t pairs = pw.size() * qrot.size();
  if (pairs > opt.M_max_pairs) {
    s.notes.push_back("M not drawn: " + std::to_string(pw.size()) + " × " + std::to_string(qrot.size()) +
                      " vertex pairs (the view takes the hull of at most " + std::to_string(opt.M_max_pairs) + ").");
    return;
  }
  std::vector<Vec3> diff;
  diff.reserve(pairs);
  for (const Vec3& p : pw)
    for (const Vec3& q : qrot) diff.push_back(p - q);
  if (!all_finite(diff)) {
    s.notes.push_back("M not drawn: a vertex difference is not finite.");
    return;
  }
  std::optional<ConvexPolytope> M;
  try {
    M = ConvexPolytope::hull(diff, "M");
  } catch (const InvalidInput& e) {
    s.notes.push_back(std::string("M not drawn: ") + e.what());
    return;
  }
  s.layers.push_back({"M", "M = P ⊕ (−Q): placements t where they overlap", kColorM, false});
  Scene3::Mesh m = mesh("M", kColorM, kMOpacity, {M->vertices().begin(), M->vertices().end()}, M->triangles());
  m.highlight_color = kColorMFacet;
  const Vec3 u = unit(r.facet_normal);
  if (r.overlapping && u != Vec3::Zero()) {
    int best = -1;
    double best_dot = -2;
    for (std::size_t k = 0; k < m.triangles.size(); ++k) {
      const auto& tri = m.triangles[k];
      const Vec3 a = m.vertices[tri[0]];
      const Vec3 e1 = m.vertices[tri[1]] - a, e2 = m.vertices[tri[2]] - a;
      const double scale = std::max(max_abs(e1), max_abs(e2));
      const double dot = unit((e1 / scale).cross(e2 / scale)).dot(u);
      if (dot > best_dot) best_dot = dot, best = M->face_of_triangle(k);
    }
    for (std::size_t k = 0; k < m.triangles.size(); ++k)
      if (M->face_of_triangle(k) == best) m.highlight.triangles.push_back(static_cast<int>(k));
  }
  if (!m.highlight.triangles.empty()) s.notes.push_back("Pink (layer M): the facet of M where t + v lies.");
  s.meshes.push_back(std::move(m));
  s.points.push_back({"M", kColorWitness, "t", t});
  if (r.overlapping) s.arrows.push_back({"M", kColorMove, "t → t + v on ∂M", t, t + r.translation});
  s.numbers.push_back({"M", std::to_string(M->size()) + " vertices, " + std::to_string(M->face_count()) + " faces"});
}

// html_page takes finite scenes only. What overflows (a shape posed near the double range, an
// answer the numeric domain reports as infinite, docs/robustness.md) is left out of the picture
// with a note; the numbers panel still shows it. Layers left empty are removed.
void drop_non_finite(Scene3& s) {
  const auto label = [&](const std::string& layer) {
    for (const auto& l : s.layers)
      if (l.id == layer) return l.label;
    return layer;
  };
  std::vector<std::string> dropped;
  const auto note = [&](const std::string& what) { dropped.push_back(what); };
  std::erase_if(s.meshes, [&](const Scene3::Mesh& m) {
    if (all_finite(m.vertices)) return false;
    note(label(m.layer));
    return true;
  });
  std::erase_if(s.points, [&](const Scene3::Point& p) {
    if (p.at.allFinite()) return false;
    note(p.label);
    return true;
  });
  std::erase_if(s.arrows, [&](const Scene3::Arrow& a) {
    if (a.from.allFinite() && a.to.allFinite()) return false;
    note(a.label);
    return true;
  });
  std::erase_if(s.layers, [&](const Scene3::Layer& l) {
    const auto in = [&](const auto& items) {
      return std::any_of(items.begin(), items.end(), [&](const auto& x) { return x.layer == l.id; });
    };
    return !in(s.meshes) && !in(s.points) && !in(s.arrows);
  });
  if (dropped.empty()) return;
  std::string n = "Not drawn, a coordinate not finite (beyond the double range): ";
  for (std::size_t i = 0; i < dropped.size(); ++i) n += (i ? "; " : "") + dropped[i];
  s.notes.push_back(n + ".");
}

// ---- JSON ----

// A JSON string; '<' is escaped too, so that nothing in it can end the page's <script> block.
void append_string(std::string& out, std::string_view str) {
  out += '"';
  for (const char ch : str) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == '<') {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  out += '"';
}

// View coordinates: 7 significant digits are more than float32 keeps.
void append_view(std::string& out, double x) {
  char buf[32];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 7);
  out.append(buf, ptr);
}

struct Frame {
  int k = 0;
  Vec3 centre{0, 0, 0};  // already scaled by 2^−k
  Vec3 view(const Vec3& x) const {
    return Vec3(std::ldexp(x.x(), -k), std::ldexp(x.y(), -k), std::ldexp(x.z(), -k)) - centre;
  }
};

Frame frame_of(const Scene3& s) {
  Box3 box;
  const auto add = [&](const Vec3& p) {
    if (!p.allFinite()) {  // printed with %g: append_double (JSON) takes no NaN
      char buf[96];
      std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x(), p.y(), p.z());
      throw InvalidInput(std::string("html: the scene has a non-finite coordinate ") + buf);
    }
    box.add(p);
  };
  for (const auto& m : s.meshes)
    for (const Vec3& p : m.vertices) add(p);
  for (const auto& p : s.points) add(p.at);
  for (const auto& a : s.arrows) {
    add(a.from);
    add(a.to);
  }
  Frame f;
  if (box.empty()) return f;
  const double h = box.half_extent();
  if (h > 0) std::frexp(h, &f.k);  // h = m·2^k, m in [0.5, 1)
  const Vec3 c = box.centre();
  f.centre = Vec3(std::ldexp(c.x(), -f.k), std::ldexp(c.y(), -f.k), std::ldexp(c.z(), -f.k));
  return f;
}

void append_point(std::string& out, const Frame& f, const Vec3& p) {
  const Vec3 v = f.view(p);
  out += '[';
  append_view(out, v.x());
  out += ',';
  append_view(out, v.y());
  out += ',';
  append_view(out, v.z());
  out += ']';
}

template <class Range, class Each>
void append_array(std::string& out, const Range& range, Each&& each) {
  out += '[';
  bool first = true;
  for (const auto& x : range) {
    if (!first) out += ',';
    first = false;
    each(x);
  }
  out += ']';
}

std::string scene_json(const Scene3& s) {
  const Frame f = frame_of(s);
  std::string out = "{\"title\":";
  append_string(out, s.title);
  out += ",\"layers\":";
  append_array(out, s.layers, [&](const Scene3::Layer& l) {
    out += "{\"id\":";
    append_string(out, l.id);
    out += ",\"label\":";
    append_string(out, l.label);
    out += ",\"color\":";
    append_string(out, l.color);
    out += l.visible ? ",\"visible\":true}" : ",\"visible\":false}";
  });
  const auto append_int = [&](int i) { out += std::to_string(i); };
  out += ",\"meshes\":";
  append_array(out, s.meshes, [&](const Scene3::Mesh& m) {
    out += "{\"layer\":";
    append_string(out, m.layer);
    out += ",\"color\":";
    append_string(out, m.color);
    out += ",\"opacity\":";
    append_view(out, m.opacity);
    out += ",\"vertices\":[";
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      if (i) out += ',';
      const Vec3 v = f.view(m.vertices[i]);
      append_view(out, v.x());
      out += ',';
      append_view(out, v.y());
      out += ',';
      append_view(out, v.z());
    }
    out += "],\"triangles\":[";
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        if (t || k) out += ',';
        const int v = m.triangles[t][k];
        if (v < 0 || static_cast<std::size_t>(v) >= m.vertices.size())
          throw InvalidInput("html: a triangle names vertex " + std::to_string(v) + " of a mesh of " +
                             std::to_string(m.vertices.size()));
        append_int(v);
      }
    }
    out += "],\"highlight\":{\"color\":";
    append_string(out, m.highlight_color);
    out += ",\"triangles\":";
    append_array(out, m.highlight.triangles, append_int);
    out += ",\"edges\":[";
    for (std::size_t e = 0; e < m.highlight.edges.size(); ++e) {
      if (e) out += ',';
      append_int(m.highlight.edges[e][0]);
      out += ',';
      append_int(m.highlight.edges[e][1]);
    }
    out += "],\"vertices\":";
    append_array(out, m.highlight.vertices, append_int);
    out += "}}";
  });
  out += ",\"points\":";
  append_array(out, s.points, [&](const Scene3::Point& p) {
    out += "{\"layer\":";
    append_string(out, p.layer);
    out += ",\"color\":";
    append_string(out, p.color);
    out += ",\"label\":";
    append_string(out, p.label);
    out += ",\"at\":";
    append_point(out, f, p.at);
    out += '}';
  });
  out += ",\"arrows\":";
  append_array(out, s.arrows, [&](const Scene3::Arrow& a) {
    out += "{\"layer\":";
    append_string(out, a.layer);
    out += ",\"color\":";
    append_string(out, a.color);
    out += ",\"label\":";
    append_string(out, a.label);
    out += ",\"from\":";
    append_point(out, f, a.from);
    out += ",\"to\":";
    append_point(out, f, a.to);
    out += '}';
  });
  out += ",\"numbers\":";
  append_array(out, s.numbers, [&](const std::array<std::string, 2>& row) {
    out += '[';
    append_string(out, row[0]);
    out += ',';
    append_string(out, row[1]);
    out += ']';
  });
  std::vector<std::string> notes = s.notes;
  notes.push_back("View coordinates: (x − c) / 2^" + std::to_string(f.k) + ", c = " +
                  text(Vec3(std::ldexp(f.centre.x(), f.k), std::ldexp(f.centre.y(), f.k), std::ldexp(f.centre.z(), f.k))) +
                  "; z is up.");
  out += ",\"notes\":";
  append_array(out, notes, [&](const std::string& n) { append_string(out, n); });
  out += '}';
  return out;
}

}  // namespace

Scene3 depth_scene3(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q, const Pose3& pose_q,
                    const Depth3& r, const Html3Options& opt) {
  const Eigen::Matrix3d Rp = pose_p.matrix(), Rq = pose_q.matrix();
  std::vector<Vec3> pw, qrot, qw;
  for (const Vec3& p : P.vertices()) pw.push_back(Rp * p + pose_p.translation);
  for (const Vec3& q : Q.vertices()) {
    qrot.push_back(Rq * q);
    qw.push_back(qrot.back() + pose_q.translation);
  }
  const bool moved = r.overlapping && !r.translation.isZero(0);

  Scene3 s;
  const char* query = r.kind == DepthKind::Minimum       ? "σ (minimum depth)"
                      : r.kind == DepthKind::Directional ? "σ_d (depth along d)"
                                                         : "complete separation along d";
  s.title = std::string("pendepth depth: ") + query + (r.overlapping ? ", depth " + text(r.depth) : ", not overlapping");
  s.layers.push_back({"P", "P (fixed): " + opt.p_label, kColorP, true});
  s.layers.push_back({"Q", "Q at its pose: " + opt.q_label, kColorQ, true});
  s.meshes.push_back(mesh("P", kColorP, 1, pw, P.triangles()));
  s.meshes.push_back(mesh("Q", kColorQ, kQOpacity, qw, Q.triangles()));
  if (r.overlapping) s.meshes[0].highlight = feature_highlight(r.feature_p, P);
  if (moved) {
    std::vector<Vec3> qm;
    for (const Vec3& q : qw) qm.push_back(q + r.translation);
    s.layers.push_back({"Q_moved", "Q after the move v (ghost)", kColorQ, true});
    s.meshes.push_back(mesh("Q_moved", kColorQ, kGhostOpacity, std::move(qm), Q.triangles()));
    s.meshes.back().highlight = feature_highlight(r.feature_q, Q);
  } else if (r.overlapping) {
    s.meshes[1].highlight = feature_highlight(r.feature_q, Q);
  }
  if (r.overlapping) {
    s.layers.push_back({"move", "the move v (from the witness on Q)", kColorMove, true});
    s.layers.push_back({"witness", "witness points", kColorWitness, true});
    if (moved) s.arrows.push_back({"move", kColorMove, "the move v", r.witness_q - r.translation, r.witness_q});
    s.points.push_back({"witness", kColorWitness, "the witness on P", r.witness_p});
    if (r.witness_q != r.witness_p) s.points.push_back({"witness", kColorWitness, "the witness on Q", r.witness_q});
  }
  if (opt.direction && !opt.direction->isZero(0)) {
    Box3 qbox;
    for (const Vec3& q : qw) qbox.add(q);
    const Vec3 from = qbox.centre();
    const Vec3 to = from + kDirectionLength * qbox.half_extent() * unit(*opt.direction);
    if (to.allFinite()) {
      s.layers.push_back({"direction", "direction d (from Q's centre)", kColorDirection, true});
      s.arrows.push_back({"direction", kColorDirection, "d", from, to});
    }
  }

  s.numbers.push_back({"query", query});
  s.numbers.push_back({"overlapping", r.overlapping ? "yes" : "no (touching counts as not overlapping)"});
  s.numbers.push_back({"depth", text(r.depth)});
  if (r.overlapping) {
    s.numbers.push_back({"bounds", "[" + text(r.lower_bound) + ", " + text(r.upper_bound) + "]"});
    s.numbers.push_back({"translation v", text(r.translation)});
    s.numbers.push_back({"normal", text(r.normal)});
    s.numbers.push_back({"facet normal (M)", text(r.facet_normal)});
    s.numbers.push_back({"witness on P", text(r.witness_p)});
    s.numbers.push_back({"witness on Q", text(r.witness_q)});
    s.numbers.push_back({"feature of P", detail::feature3_text(r.feature_p, P)});
    s.numbers.push_back({"feature of Q", detail::feature3_text(r.feature_q, Q)});
  }
  s.numbers.push_back({"offset t", text(pose_q.translation)});
  if (opt.direction) s.numbers.push_back({"direction d", text(*opt.direction)});
  const auto quaternion = [](const Pose3& pose) {
    const auto& q = pose.rotation;
    return text(q.w()) + ", " + text(q.x()) + ", " + text(q.y()) + ", " + text(q.z()) + " (w, x, y, z)";
  };
  if (!pose_p.rotation.coeffs().isApprox(Eigen::Quaterniond::Identity().coeffs(), 0) || !pose_p.translation.isZero(0))
    s.numbers.push_back({"pose of P", "rotation " + quaternion(pose_p) + ", translation " + text(pose_p.translation)});
  if (!pose_q.rotation.coeffs().isApprox(Eigen::Quaterniond::Identity().coeffs(), 0))
    s.numbers.push_back({"rotation of Q", quaternion(pose_q)});
  s.numbers.push_back({"shapes", "P " + std::to_string(P.size()) + ", Q " + std::to_string(Q.size()) + " hull vertices"});
  if (r.overlapping)
    s.notes.push_back("Amber: the features of P and of the moved Q that span the facet of M where the move ends.");
  if (opt.draw_M) add_minkowski(s, pw, qrot, r, pose_q.translation, opt);
  drop_non_finite(s);
  return s;
}

std::string html_page(const Scene3& scene) {
#ifdef PENDEPTH_HTML_VIEWER
  const std::string json = scene_json(scene);
  std::string page;
  page.reserve(detail::kViewerHead.size() + json.size() + detail::kViewerTail.size());
  page += detail::kViewerHead;
  page += json;
  page += detail::kViewerTail;
  return page;
#else
  (void)scene;
  throw InvalidInput("html: pendepth was built without the HTML viewer (PENDEPTH_HTML_VIEWER=OFF)");
#endif
}

void write_html(const std::filesystem::path& path, const Scene3& scene) {
  const std::string page = html_page(scene);
  std::ofstream out(path, std::ios::binary);
  if (out) out.write(page.data(), static_cast<std::streamsize>(page.size()));
  if (out) out.close();
  if (!out)
    throw WriteError(path.string() + ": cannot write file (" + (errno ? std::strerror(errno) : "write error") + ")");
}

}  // namespace pendepth::io
