// Shared by the libFuzzer targets (tests/fuzz, docs/robustness.md "Fuzzing"): a reader of the
// fuzzer's bytes, the one allowed exception (pendepth::InvalidInput), and the invariants every
// query answer must satisfy. A violated invariant aborts with a message, which libFuzzer reports
// as a crash and saves the input.
#pragma once

#include <pendepth/geometry.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string_view>

/// The entry point of a target: libFuzzer's, or, when the sources are compiled into the test
/// suite to replay the seed corpus (tests/fuzz_corpus), a function named after the target.
#ifdef PENDEPTH_FUZZ_REPLAY
#define PENDEPTH_FUZZ_TARGET(name) int name(const std::uint8_t* data, std::size_t size)
#else
#define PENDEPTH_FUZZ_TARGET(name) extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
#endif

namespace fuzz {

/// Aborts with a message (a crash for libFuzzer, which then saves the input).
[[noreturn]] inline void fail(const char* what, double a = 0, double b = 0) {
  std::fprintf(stderr, "fuzz invariant violated: %s (%.17g, %.17g)\n", what, a, b);
  std::abort();
}

inline void check(bool ok, const char* what, double a = 0, double b = 0) {
  if (!ok) fail(what, a, b);
}

/// Runs f; pendepth::InvalidInput is an allowed outcome (bad input, rejected with a message),
/// any other exception is a bug. Returns false if InvalidInput was thrown.
template <class F>
bool allowed(F&& f) {
  try {
    f();
    return true;
  } catch (const pendepth::InvalidInput& e) {
    // One line on a terminal: not empty, no control byte (input bytes are quoted as \xNN).
    const char* m = e.what();
    check(*m != '\0', "empty InvalidInput message");
    for (const char* c = m; *c; ++c)
      if (static_cast<unsigned char>(*c) < 0x20 || *c == 0x7F) {
        std::fprintf(stderr, "fuzz: InvalidInput message with control byte 0x%02X: %s\n", unsigned(static_cast<unsigned char>(*c)), m);
        std::abort();
      }
    return false;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: unexpected exception: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz: unexpected non-standard exception\n");
    std::abort();
  }
}

/// Consumes the fuzzer's bytes front to back; past the end every read gives zeros.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : p_(data), n_(size) {}
  std::size_t left() const { return n_ - i_; }
  std::uint8_t u8() { return i_ < n_ ? p_[i_++] : 0; }
  // Reads in sequence (the operands of | are unsequenced: GCC and clang would differ).
  std::uint16_t u16() {
    const unsigned lo = u8();
    return static_cast<std::uint16_t>(lo | unsigned(u8()) << 8);
  }
  std::uint32_t u32() {
    const std::uint32_t lo = u16();
    return lo | static_cast<std::uint32_t>(u16()) << 16;
  }
  /// An integer in [lo, hi].
  int range(int lo, int hi) { return lo + static_cast<int>(u16() % static_cast<unsigned>(hi - lo + 1)); }
  /// A signed 16-bit integer as a double (small integer coordinates: exact degeneracies are common).
  double i16() { return static_cast<double>(static_cast<std::int16_t>(u16())); }
  /// A double of any bit pattern that is finite with |x| <= limit (else a small integer).
  double finite(double limit) {
    const std::uint64_t lo = u32();
    const std::uint64_t bits = lo | static_cast<std::uint64_t>(u32()) << 32;
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x) || std::fabs(x) > limit) return static_cast<double>(static_cast<std::int8_t>(bits & 0xFF));
    return x;
  }
  /// A coordinate: mostly small integers (degenerate contacts), sometimes any double within
  /// `limit`, sometimes an integer scaled by a power of two (magnitude tests).
  double coord(double limit) {
    switch (u8() % 4) {
      case 0: return finite(limit);
      case 1: return std::ldexp(i16(), range(-20, 4));
      default: return static_cast<double>(static_cast<std::int8_t>(u8()));
    }
  }
  std::string_view rest() {
    std::string_view s(reinterpret_cast<const char*>(p_ + i_), n_ - i_);
    i_ = n_;
    return s;
  }

 private:
  const std::uint8_t* p_;
  std::size_t n_, i_ = 0;
};

/// The invariants of a depth answer (2D or 3D result type): finite, non-negative, the length of
/// its translation, a unit normal when positive, zero when not overlapping (σ, σ_d).
template <class Depth>
void check_depth(const Depth& r, bool separation = false) {
  check(std::isfinite(r.depth), "depth is not finite", r.depth);
  check(r.depth >= 0, "depth is negative", r.depth);
  for (int k = 0; k < r.translation.size(); ++k) {
    check(std::isfinite(r.translation[k]), "translation is not finite", r.translation[k]);
    check(std::isfinite(r.normal[k]), "normal is not finite", r.normal[k]);
    check(std::isfinite(r.witness_p[k]) && std::isfinite(r.witness_q[k]), "witness is not finite");
  }
  const double len = r.translation.stableNorm();  // no overflow for huge shapes
  check(std::fabs(len - r.depth) <= 1e-9 * (r.depth + 1e-300) + 1e-300 || len == r.depth,
        "depth is not the length of the translation", r.depth, len);
  if (r.depth > 0) check(std::fabs(r.normal.stableNorm() - 1) <= 1e-9, "normal is not a unit vector", r.normal.norm());
  if (!separation && !r.overlapping) check(r.depth == 0, "depth > 0 without overlap", r.depth);
}

}  // namespace fuzz
