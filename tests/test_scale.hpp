// How much of each randomized suite to run. Release runs everything; Debug and sanitizer builds
// (NDEBUG undefined, assertions on) run a fixed fraction with the same generators and seeds, so
// CI's ASan + UBSan pass stays within its time budget.
#pragma once

namespace pendepth_test {
#ifdef NDEBUG
inline constexpr int kDivisor = 1;
#else
inline constexpr int kDivisor = 8;
#endif
/// A Release iteration count scaled for this build (at least 1).
constexpr int scaled(int release_count) { return release_count / kDivisor > 0 ? release_count / kDivisor : 1; }
}  // namespace pendepth_test
