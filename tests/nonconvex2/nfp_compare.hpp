// Bit-for-bit comparisons shared by the no-fit polygon tests that check a fast or pruned path
// against the method before it (test_nfp_dop.cpp, test_nfp_strip.cpp, test_nfp_trim.cpp,
// test_nfp_pairs.cpp): each returns "" when the two are the same, else where they first differ.
#pragma once

#include <pendepth/nfp2.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "nonconvex2/nfp_impl.hpp"

namespace nonconvex2_test {

/// Two classifications' pieces: the same count, candidates and exact ends (compare_params), in order.
inline std::string piece_difference(const std::vector<pendepth::nonconvex2::NfpPiece>& got,
                                    const std::vector<pendepth::nonconvex2::NfpPiece>& ref) {
  namespace nc = pendepth::nonconvex2;
  if (got.size() != ref.size()) return "piece count " + std::to_string(got.size()) + " vs " + std::to_string(ref.size());
  const pendepth::Vec2 o(0, 0);
  for (std::size_t k = 0; k < ref.size(); ++k) {
    const nc::Ray& E = ref[k].E;
    if (!(got[k].E.p0 == E.p0 && got[k].E.q0 == E.q0 && got[k].E.p1 == E.p1 && got[k].E.q1 == E.q1))
      return "piece " + std::to_string(k) + " candidate";
    if (nc::compare_params(got[k].lo, ref[k].lo, E, o) != 0) return "piece " + std::to_string(k) + " lo";
    if (nc::compare_params(got[k].hi, ref[k].hi, E, o) != 0) return "piece " + std::to_string(k) + " hi";
  }
  return "";
}

/// Two exported no-fit polygons: the same polygons, rings and vertices, slits and points, bit for bit.
inline std::string nfp_difference(const pendepth::NoFitPolygon2& a, const pendepth::NoFitPolygon2& b) {
  auto count = [](const char* what, std::size_t x, std::size_t y) {
    return std::string(what) + " count " + std::to_string(x) + " vs " + std::to_string(y);
  };
  if (a.polygons().size() != b.polygons().size()) return count("polygon", a.polygons().size(), b.polygons().size());
  for (std::size_t i = 0; i < a.polygons().size(); ++i) {
    const std::string at = "polygon " + std::to_string(i);
    if (a.polygons()[i].size() != b.polygons()[i].size()) return count((at + " ring").c_str(), a.polygons()[i].size(), b.polygons()[i].size());
    for (std::size_t r = 0; r < a.polygons()[i].size(); ++r) {
      const auto &x = a.polygons()[i][r], &y = b.polygons()[i][r];
      const std::string ring = at + " ring " + std::to_string(r);
      if (x.size() != y.size()) return count((ring + " vertex").c_str(), x.size(), y.size());
      for (std::size_t v = 0; v < x.size(); ++v)
        if (!(x[v].x() == y[v].x() && x[v].y() == y[v].y())) return ring + " vertex " + std::to_string(v);
    }
  }
  if (a.slits().size() != b.slits().size()) return count("slit", a.slits().size(), b.slits().size());
  for (std::size_t i = 0; i < a.slits().size(); ++i)
    for (int e = 0; e < 2; ++e)
      if (!(a.slits()[i][e] == b.slits()[i][e])) return "slit " + std::to_string(i);
  if (a.points().size() != b.points().size()) return count("point", a.points().size(), b.points().size());
  for (std::size_t i = 0; i < a.points().size(); ++i)
    if (!(a.points()[i] == b.points()[i])) return "point " + std::to_string(i);
  return "";
}

/// Sets one method switch (`nfp_dop_mode()`, `nfp_strip_mode()`, `nfp_pairs_mode()`) and the trimming
/// mode for a scope, and restores both defaults on exit, also when a failed assertion returns early.
class ScopedModes {
 public:
  ScopedModes(int& mode, int value, int mode_default, int trim) : mode_(mode), default_(mode_default) {
    mode_ = value;
    pendepth::nonconvex2::nfp_trim_mode() = trim;
  }
  ~ScopedModes() {
    mode_ = default_;
    pendepth::nonconvex2::nfp_trim_mode() = pendepth::nonconvex2::kTrimAuto;
  }
  ScopedModes(const ScopedModes&) = delete;
  ScopedModes& operator=(const ScopedModes&) = delete;

 private:
  int& mode_;
  int default_;
};

}  // namespace nonconvex2_test
