// SVG picture of one 2D depth query (docs/design.md §3, `pendepth depth --svg`).
//
// Left panel, the workspace: P, Q + t, Q + t + v (v = the separating translation), the move and
// the witness point; the direction d is a glyph in the legend. Right panel (optional), the
// configuration space at the same scale: M = P ⊕ (−Q), the placement t and the arrow t → t + v,
// which ends on ∂M (DHS Lemma 2.1).
// Coordinates are mapped to pixels here (y up), so stroke widths and text sizes are in pixels
// whatever the input scale, and outlines are decimated: a vertex closer than half a pixel to the
// last one drawn is skipped, so a 10⁶-gon costs a few thousand points. O(n + m).
#include <pendepth/io.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>

namespace pendepth::io {
namespace {

constexpr double kPanelPx = 560;      // the larger panel extent, pixels
constexpr double kMarginPx = 30;      // around each panel
constexpr double kLegendPx = 96;      // legend band at the top
constexpr double kGapPx = 50;         // between the panels
constexpr double kDecimatePx = 0.5;   // drop vertices closer than this to the last one drawn

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
  void add(const Vec2& p) {
    x0 = std::min(x0, p.x());
    y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x());
    y1 = std::max(y1, p.y());
  }
  void add(std::span<const Vec2> pts, const Vec2& shift = Vec2(0, 0)) {
    for (const Vec2& p : pts) add(p + shift);
  }
  double w() const { return x1 - x0; }
  double h() const { return y1 - y0; }
};

// World → pixel map of one panel: y flipped, origin at the panel's top-left corner.
struct View {
  Box box;
  double scale = 1, ox = 0, oy = 0;
  double px(double x) const { return ox + (x - box.x0) * scale; }
  double py(double y) const { return oy + (box.y1 - y) * scale; }
};

class Writer {
 public:
  std::string s;
  Writer& operator<<(std::string_view t) {
    s += t;
    return *this;
  }
  Writer& num(double x) {  // pixels: two decimals are plenty
    char buf[32];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, std::abs(x) < 5e-3 ? 0.0 : x,
                                   std::chars_format::fixed, 2);
    const char* end = ptr;
    while (end > buf && end[-1] == '0') --end;  // "12.50" → "12.5", "3.00" → "3."
    if (end > buf && end[-1] == '.') --end;
    s.append(buf, static_cast<std::size_t>(end - buf));
    return *this;
  }
  Writer& point(const View& v, const Vec2& p) {
    num(v.px(p.x()));
    s += ',';
    return num(v.py(p.y()));
  }
};

void polygon(Writer& w, const View& v, std::span<const Vec2> pts, const Vec2& shift, std::string_view style) {
  w << "<polygon " << style << " points=\"";
  double lx = 0, ly = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = v.px(pts[i].x() + shift.x()), y = v.py(pts[i].y() + shift.y());
    if (i > 0 && std::hypot(x - lx, y - ly) < kDecimatePx) continue;
    if (i > 0) w << " ";
    w.num(x) << ",";
    w.num(y);
    lx = x;
    ly = y;
  }
  w << "\"/>\n";
}

// A shape of one or more rings: one ring is a <polygon>; several (outer ring and holes, or the
// rings of a union boundary) one <path> with the even-odd rule, so holes stay unfilled.
void shape(Writer& w, const View& v, const std::vector<std::vector<Vec2>>& rings, const Vec2& shift,
           std::string_view style) {
  if (rings.size() == 1) return polygon(w, v, rings.front(), shift, style);
  w << "<path fill-rule=\"evenodd\" " << style << " d=\"";
  for (const auto& ring : rings) {
    double lx = 0, ly = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const double x = v.px(ring[i].x() + shift.x()), y = v.py(ring[i].y() + shift.y());
      if (i > 0 && std::hypot(x - lx, y - ly) < kDecimatePx) continue;
      w << (i == 0 ? "M" : " L");
      w.num(x) << ",";
      w.num(y);
      lx = x;
      ly = y;
    }
    w << " Z";
  }
  w << "\"/>\n";
}

void arrow(Writer& w, const View& v, const Vec2& a, const Vec2& b, std::string_view color, std::string_view marker) {
  w << "<line x1=\"";
  w.num(v.px(a.x())) << "\" y1=\"";
  w.num(v.py(a.y())) << "\" x2=\"";
  w.num(v.px(b.x())) << "\" y2=\"";
  w.num(v.py(b.y())) << "\" stroke=\"" << color << "\" stroke-width=\"2\" marker-end=\"url(#" << marker << ")\"/>\n";
}

void dot(Writer& w, const View& v, const Vec2& p, double radius, std::string_view style) {
  w << "<circle cx=\"";
  w.num(v.px(p.x())) << "\" cy=\"";
  w.num(v.py(p.y())) << "\" r=\"";
  w.num(radius) << "\" " << style << "/>\n";
}

void label(Writer& w, double x, double y, std::string_view text, std::string_view style = "") {
  w << "<text x=\"";
  w.num(x) << "\" y=\"";
  w.num(y) << "\" " << style << ">" << text << "</text>\n";
}

Vec2 vertex_mean(std::span<const Vec2> pts) {
  Vec2 c(0, 0);
  for (const Vec2& p : pts) c += p;
  return c / double(pts.size());
}

std::string shortest(double x) {
  std::string s;
  append_double(s, x);
  return s;
}

}  // namespace

void write_svg(const std::filesystem::path& path, const SvgScene& scene, const Vec2& t, const Depth2& r,
               const SvgOptions& options) {
  for (const auto* rings : {&scene.P, &scene.Q})
    if (rings->empty() || rings->front().empty()) throw InvalidInput("write_svg: P and Q need an outer ring");
  const Vec2 v = r.translation;
  const bool moved = r.overlapping && r.depth > 0;

  // Workspace panel contents and extent; the direction arrow's length is a fraction of the view.
  View A;
  A.box.add(scene.P.front());
  A.box.add(scene.Q.front(), t);
  if (moved) A.box.add(scene.Q.front(), t + v);
  const Vec2 qc = vertex_mean(scene.Q.front()) + t;

  const bool draw_M = options.draw_M && !scene.config.empty();
  View B;
  if (draw_M) {
    for (const auto& ring : scene.config) B.box.add(ring);
    for (const auto& seg : scene.config_segments) B.box.add(seg);
    for (const Vec2& p : scene.config_points) B.box.add(p);
    B.box.add(t);
    B.box.add(t + v);
  }

  // One scale for both panels so lengths compare; the larger extent gets kPanelPx pixels.
  double extent = std::max(A.box.w(), A.box.h());
  if (draw_M) extent = std::max({extent, B.box.w(), B.box.h()});
  const double scale = extent > 0 ? kPanelPx / extent : 1;
  A.scale = B.scale = scale;
  A.ox = kMarginPx;
  A.oy = kMarginPx + kLegendPx;
  double width = A.ox + A.box.w() * scale + kMarginPx;
  double height = A.oy + A.box.h() * scale + kMarginPx;
  if (draw_M) {
    B.ox = width - kMarginPx + kGapPx;
    B.oy = A.oy;
    width = B.ox + B.box.w() * scale + kMarginPx + 80;  // room for the "t + v" label
    height = std::max(height, B.oy + B.box.h() * scale + kMarginPx);
  }
  width = std::max(width, 520.0);

  Writer w;
  w.s.reserve(1 << 16);
  w << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 ";
  w.num(width) << " ";
  w.num(height) << "\" width=\"";
  w.num(width) << "\" height=\"";
  w.num(height) << "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  w << "<defs>\n"
       "<marker id=\"head-dark\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" "
       "markerHeight=\"6\" orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#222\"/></marker>\n"
       "<marker id=\"head-green\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" "
       "markerHeight=\"6\" orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#2a9d2a\"/></marker>\n"
       "</defs>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

  // Legend.
  const char* kind = r.kind == DepthKind::Minimum       ? "minimum depth σ"
                     : r.kind == DepthKind::Directional ? "directional depth σ_d"
                                                        : "complete separation along d";
  label(w, kMarginPx, 24,
        std::string(kind) + " = " + shortest(r.depth) + (r.overlapping ? "" : "  (interiors do not overlap)"),
        "font-weight=\"bold\"");
  label(w, kMarginPx, 44,
        "t = (" + shortest(t.x()) + ", " + shortest(t.y()) + ")   move v = (" + shortest(v.x()) + ", " +
            shortest(v.y()) + ")");
  double lx = kMarginPx;
  auto swatch = [&](std::string_view style, std::string_view text) {
    w << "<rect x=\"";
    w.num(lx) << "\" y=\"58\" width=\"18\" height=\"12\" " << style << "/>\n";
    label(w, lx + 24, 69, text);
    lx += 24 + 8.0 * double(text.size()) + 14;
  };
  swatch("fill=\"#a6cee3\" stroke=\"#1f78b4\"", "P (fixed)");
  swatch("fill=\"#fb9a99\" fill-opacity=\"0.6\" stroke=\"#e31a1c\"", "Q + t");
  if (moved) swatch("fill=\"none\" stroke=\"#e31a1c\" stroke-dasharray=\"4 3\"", "Q + t + v");
  if (draw_M) swatch("fill=\"#f2f2f2\" stroke=\"#888\"", scene.config_label);
  if (options.direction && options.direction->norm() > 0) {  // a 28-pixel glyph along d̂, y up
    const Vec2 u = options.direction->normalized();
    const double cx = lx + 14, cy = 64;
    w << "<line x1=\"";
    w.num(cx - 14 * u.x()) << "\" y1=\"";
    w.num(cy + 14 * u.y()) << "\" x2=\"";
    w.num(cx + 14 * u.x()) << "\" y2=\"";
    w.num(cy - 14 * u.y()) << "\" stroke=\"#2a9d2a\" stroke-width=\"2\" marker-end=\"url(#head-green)\"/>\n";
    label(w, lx + 34, 69, "direction d = (" + shortest(options.direction->x()) + ", " +
                              shortest(options.direction->y()) + ")", "fill=\"#2a9d2a\"");
  }

  // Workspace.
  label(w, A.ox, A.oy - 8, "workspace", "fill=\"#555\"");
  shape(w, A, scene.P, Vec2(0, 0), "fill=\"#a6cee3\" stroke=\"#1f78b4\" stroke-width=\"1.5\"");
  shape(w, A, scene.Q, t,
          "fill=\"#fb9a99\" fill-opacity=\"0.6\" stroke=\"#e31a1c\" stroke-width=\"1.5\"");
  // A point or a segment (fewer than 3 vertices): its vertices as dots, so a point shows.
  for (const auto& [rings, at, color] : {std::tuple{&scene.P, Vec2(0, 0), "#1f78b4"}, std::tuple{&scene.Q, t, "#e31a1c"}})
    if (rings->front().size() < 3)
      for (const Vec2& p : rings->front()) dot(w, A, p + at, 3, std::string("fill=\"") + color + "\"");
  if (moved) {
    shape(w, A, scene.Q, t + v,
            "fill=\"none\" stroke=\"#e31a1c\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\"");
    arrow(w, A, qc, qc + v, "#222", "head-dark");
    dot(w, A, r.witness_p, 4, "fill=\"#222\"");
    label(w, A.px(r.witness_p.x()) + 7, A.py(r.witness_p.y()) - 7, "witness", "fill=\"#222\"");
  }

  // Configuration space.
  if (draw_M) {
    label(w, B.ox, B.oy - 8, "configuration space (same scale)", "fill=\"#555\"");
    shape(w, B, scene.config, Vec2(0, 0), "fill=\"#f2f2f2\" stroke=\"#888\" stroke-width=\"1\"");
    // Slits and isolated points of the configuration set: lower-dimensional, drawn on top.
    for (const auto& seg : scene.config_segments) {
      w << "<line x1=\"";
      w.num(B.px(seg[0].x())) << "\" y1=\"";
      w.num(B.py(seg[0].y())) << "\" x2=\"";
      w.num(B.px(seg[1].x())) << "\" y2=\"";
      w.num(B.py(seg[1].y())) << "\" stroke=\"#6a3d9a\" stroke-width=\"2\" class=\"slit\"/>\n";
    }
    for (const Vec2& p : scene.config_points) dot(w, B, p, 3, "fill=\"#6a3d9a\" class=\"fit-point\"");
    if (moved) {
      arrow(w, B, t, t + v, "#222", "head-dark");
      label(w, B.px(t.x() + v.x()) + 7, B.py(t.y() + v.y()) - 7, scene.config_target, "fill=\"#222\"");
    }
    dot(w, B, t, 4, "fill=\"#e31a1c\"");
    label(w, B.px(t.x()) + 7, B.py(t.y()) + 14, "t", "fill=\"#e31a1c\"");
  }
  w << "</svg>\n";

  // Every failure counts: the open, the write, and the flush on close (a full disk shows there).
  errno = 0;
  std::ofstream out(path, std::ios::binary);
  if (out) out.write(w.s.data(), std::streamsize(w.s.size()));
  if (out) out.close();
  if (!out)
    throw WriteError(path.string() + ": cannot write file (" + (errno ? std::strerror(errno) : "write error") + ")");
}


void write_svg(const std::filesystem::path& path, const ConvexPolygon& P, const ConvexPolygon& Q,
               const Vec2& t, const Depth2& r, const SvgOptions& options) {
  SvgScene scene;
  scene.P.emplace_back(P.vertices().begin(), P.vertices().end());
  scene.Q.emplace_back(Q.vertices().begin(), Q.vertices().end());
  if (options.draw_M) scene.config.push_back(minkowski_difference(P, Q));
  write_svg(path, scene, t, r, options);
}

}  // namespace pendepth::io
