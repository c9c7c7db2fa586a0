// libFuzzer target: the batch query readers, 2D and 3D. Invariants: only InvalidInput (one
// printable line); accepted queries are finite, their source lines strictly increasing and
// within the text.
#include <pendepth/io.hpp>

#include "fuzz_common.hpp"

#include <algorithm>

namespace {

template <class Queries>
void check_queries(const Queries& qs, std::string_view text) {
  const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
  std::size_t last = 0;
  for (const auto& q : qs) {
    fuzz::check(q.t.allFinite() && q.d.allFinite(), "non-finite query accepted");
    fuzz::check(q.line > last && q.line <= lines, "query line numbers", double(q.line), double(last));
    last = q.line;
  }
}

}  // namespace

PENDEPTH_FUZZ_TARGET(fuzz_queries_csv) {
  if (size > 4096) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fuzz::allowed([&] { check_queries(pendepth::io::parse_queries_csv(text, "q.csv"), text); });
  fuzz::allowed([&] { check_queries(pendepth::io::parse_queries3_csv(text, "q.csv"), text); });
  return 0;
}
