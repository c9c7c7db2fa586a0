// pendepth — command-line tool (DESIGN.md §3).
//
//   pendepth depth P Q [--offset X,Y] [--direction X,Y] [--separate] [--json] [--svg FILE]
//   pendepth batch P Q --queries FILE [--json]
//
// Exit status: 0 success, 2 bad input (one line on stderr naming file, line and problem),
// 1 internal error. Shapes: .wkt (2D convex polygons); .obj/.off/.stl are 3D, not supported yet.
#include <pendepth/depth2.hpp>
#include <pendepth/io.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace {

using pendepth::ConvexPolygon;
using pendepth::Depth2;
using pendepth::InvalidInput;
using pendepth::Vec2;
namespace io = pendepth::io;

ConvexPolygon load_shape(const std::string& path, const char* name) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".wkt") {
    try {
      return io::read_convex_polygon(path, name);
    } catch (const InvalidInput& e) {
      const std::string msg = e.what();
      if (msg.find("not convex") != std::string::npos || msg.find("self-intersecting") != std::string::npos)
        throw InvalidInput(msg + " (non-convex polygons are not supported yet)");
      throw;
    }
  }
  if (ext == ".obj" || ext == ".off" || ext == ".stl")
    throw InvalidInput(path + ": 3D shapes are not supported yet (" + ext + ")");
  throw InvalidInput(path + ": unknown shape format '" + ext + "' (expected .wkt)");
}

// "X,Y" from an option value; the option name goes into the error message.
Vec2 parse_vec(const std::string& text, const char* option) {
  double v[2];
  std::size_t count = 0;
  std::string_view rest = text;
  for (;;) {
    const std::size_t comma = rest.find(',');
    std::string_view f = rest.substr(0, comma);
    while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
    while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
    if (!f.empty() && f.front() == '+') f.remove_prefix(1);
    double x = 0;
    auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), x);
    if (f.empty() || ec == std::errc::invalid_argument || ptr != f.data() + f.size())
      throw InvalidInput(std::string(option) + ": expected X,Y (two numbers), got '" + text + "'");
    if (ec == std::errc::result_out_of_range || !std::isfinite(x))
      throw InvalidInput(std::string(option) + ": non-finite number in '" + text + "'");
    if (count < 2) v[count] = x;
    ++count;
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  if (count == 3) throw InvalidInput(std::string(option) + ": 3D vectors are not supported yet (2D shapes)");
  if (count != 2) throw InvalidInput(std::string(option) + ": expected X,Y (two numbers), got '" + text + "'");
  return Vec2(v[0], v[1]);
}

// d scaled by a power of two so its larger component lies in [1, 2): the same direction (the
// scaling is exact unless the other component is 2^-1000 times smaller), and d.norm() can neither
// underflow nor overflow inside the library.
Vec2 rescale_direction(const Vec2& d) {
  const int e = std::ilogb(std::max(std::abs(d.x()), std::abs(d.y())));
  return Vec2(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
}

void write_stdout(const std::string& s) { std::fwrite(s.data(), 1, s.size(), stdout); }

struct DepthArgs {
  std::string p, q, offset, direction, svg;
  bool separate = false, json = false;
};

int run_depth(const DepthArgs& a) {
  const ConvexPolygon P = load_shape(a.p, "P");
  const ConvexPolygon Q = load_shape(a.q, "Q");
  const Vec2 t = a.offset.empty() ? Vec2(0, 0) : parse_vec(a.offset, "--offset");
  std::optional<Vec2> d;
  Depth2 r;
  if (!a.direction.empty()) {
    d = parse_vec(a.direction, "--direction");
    if (d->x() == 0 && d->y() == 0) throw InvalidInput("--direction: the direction is zero");
    const Vec2 u = rescale_direction(*d);
    r = a.separate ? pendepth::separation_depth(P, Q, t, u) : pendepth::directional_depth(P, Q, t, u);
  } else {
    r = pendepth::minimum_depth(P, Q, t);
  }
  if (!a.svg.empty()) io::write_svg(a.svg, P, Q, t, r, io::SvgOptions{d, true});
  std::string out;
  if (a.json) {
    io::append_json(out, r, P, Q);
    out += '\n';
  } else {
    out = io::summary(r, P, Q);
  }
  write_stdout(out);
  return 0;
}

struct BatchArgs {
  std::string p, q, queries;
  bool json = false;
};

int run_batch(const BatchArgs& a) {
  ConvexPolygon P = load_shape(a.p, "P");
  ConvexPolygon Q = load_shape(a.q, "Q");
  const std::vector<io::Query2> queries = io::read_queries_csv(a.queries);

  // σ goes through the preprocessed field, built once and only if some query asks for it.
  const bool any_minimum = std::any_of(queries.begin(), queries.end(),
                                       [](const io::Query2& q) { return q.d.x() == 0 && q.d.y() == 0; });
  std::optional<pendepth::DepthQuery2> field;
  if (any_minimum) field.emplace(std::move(P), std::move(Q));
  const ConvexPolygon& PP = field ? field->P() : P;
  const ConvexPolygon& QQ = field ? field->Q() : Q;

  constexpr std::size_t kFlushBytes = 1 << 20;
  std::string out;
  out.reserve(kFlushBytes + 4096);
  if (!a.json) out += "depth,tx,ty\n";
  for (const io::Query2& q : queries) {
    Depth2 r;
    try {
      r = (q.d.x() == 0 && q.d.y() == 0) ? field->minimum(q.t)
                                         : pendepth::directional_depth(PP, QQ, q.t, rescale_direction(q.d));
    } catch (const InvalidInput& e) {  // the library's word on this query, with its line
      throw InvalidInput(a.queries + ":" + std::to_string(q.line) + ": " + e.what());
    }
    if (a.json) {
      io::append_json(out, r, PP, QQ);
      out += '\n';
    } else {
      io::append_csv_row(out, r);
    }
    if (out.size() >= kFlushBytes) {
      write_stdout(out);
      out.clear();
    }
  }
  write_stdout(out);
  return 0;
}

std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pendepth: exact intersection (penetration) depth of two shapes.\n"
               "P is fixed, Q moves; Q is placed at the offset t. Shapes: .wkt POLYGON files "
               "(convex, 2D)."};
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 2 bad input (one line on stderr: FILE:LINE: problem).");

  DepthArgs da;
  CLI::App* depth = app.add_subcommand(
      "depth", "Depth of one placement: the minimum σ, or σ_d along --direction, or the complete separation.");
  depth->add_option("P", da.p, "fixed shape file (.wkt)")->required()->type_name("FILE");
  depth->add_option("Q", da.q, "moving shape file (.wkt)")->required()->type_name("FILE");
  depth->add_option("--offset", da.offset, "placement t of Q (default 0,0); negative: --offset=-1,2")
      ->type_name("X,Y");
  CLI::Option* dir =
      depth->add_option("--direction", da.direction, "compute σ_d along d instead of σ")->type_name("X,Y");
  depth->add_flag("--separate", da.separate, "complete separation along --direction")->needs(dir);
  depth->add_flag("--json", da.json, "print one JSON object instead of a summary");
  depth->add_option("--svg", da.svg, "also draw the query into this SVG file")->type_name("FILE");

  BatchArgs ba;
  CLI::App* batch = app.add_subcommand(
      "batch", "Many placements: CSV lines x,y,dx,dy (dx,dy = 0,0 asks for σ). Prints CSV depth,tx,ty.");
  batch->add_option("P", ba.p, "fixed shape file (.wkt)")->required()->type_name("FILE");
  batch->add_option("Q", ba.q, "moving shape file (.wkt)")->required()->type_name("FILE");
  batch->add_option("--queries", ba.queries, "CSV file of queries x,y,dx,dy")->required()->type_name("FILE");
  batch->add_flag("--json", ba.json, "print JSON Lines (one object per query) instead of CSV");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "pendepth: %s (see pendepth --help)\n", one_line(e.what()).c_str());
    return 2;
  }

  try {
    if (depth->parsed()) return run_depth(da);
    return run_batch(ba);
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "%s\n", one_line(e.what()).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pendepth: internal error: %s\n", one_line(e.what()).c_str());
    return 1;
  }
}
