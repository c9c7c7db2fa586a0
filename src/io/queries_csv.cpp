// Batch query files: one `x,y,dx,dy` (2D) or `x,y,z,dx,dy,dz` (3D) per line (docs/design.md §3,
// `pendepth batch`).
//
// One pass over the text (src/io/csv_rows.hpp), no allocation per line, so 10⁵ queries
// parse in milliseconds. Errors name the source line. A header is accepted only as the first data
// line and only when it is exactly the expected names: anything else that is not numbers (a
// misspelt header, ';' separators, quoted fields, hexadecimal, a binary file) is an error, never
// silently skipped.
#include <pendepth/io.hpp>

#include "io/csv_rows.hpp"

namespace pendepth::io {
namespace {

// Rows of N = 2·dim numbers: offset then direction (src/io/csv_rows.hpp). `Query` is Query2 or
// Query3.
template <class Query, std::size_t N>
std::vector<Query> parse_rows(std::string_view text, std::string_view source, const detail::CsvLayout<N>& layout) {
  std::vector<Query> out;
  out.reserve(text.size() / (4 * N));
  detail::parse_csv_rows(text, source, layout, [&](const double (&v)[N], std::size_t line, auto&&) {
    Query q;
    for (std::size_t k = 0; k < N / 2; ++k) {
      q.t[k] = v[k];
      q.d[k] = v[N / 2 + k];
    }
    q.line = line;
    out.push_back(q);
  });
  return out;
}

constexpr detail::CsvLayout<4> kQueries2{{"x", "y", "dx", "dy"}, 6, " (a 3D query; the shapes are 2D)"};
constexpr detail::CsvLayout<6> kQueries3{{"x", "y", "z", "dx", "dy", "dz"}, 4, " (a 2D query; the shapes are 3D)"};

}  // namespace

std::vector<Query2> parse_queries_csv(std::string_view text, std::string_view source) {
  return parse_rows<Query2>(text, source, kQueries2);
}

std::vector<Query3> parse_queries3_csv(std::string_view text, std::string_view source) {
  return parse_rows<Query3>(text, source, kQueries3);
}

std::vector<Query3> read_queries3_csv(const std::filesystem::path& path) {
  return parse_queries3_csv(read_text_file(path), path.string());
}

std::vector<Query2> read_queries_csv(const std::filesystem::path& path) {
  return parse_queries_csv(read_text_file(path), path.string());
}

}  // namespace pendepth::io
