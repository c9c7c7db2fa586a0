// Private: run-time instruction-set dispatch of the hot query paths (issue 16).
//
// The library is built for the portable x86-64 baseline (SSE2, no FMA instruction: std::fma is a
// call into libm that spills every live register). The hottest query entries — σ by expansion
// (convex3/minimum_expand.cpp) and the signed distance of convex polytopes
// (convex3/signed_distance3.cpp) — have a second copy of their whole call tree compiled for
// x86-64-v3 (AVX2, FMA, BMI1/2, …): an entry function marked PENDEPTH_V3_CLONE, which GCC
// `flatten`s (every call below it inlined into it and compiled for that target), chosen once per
// call by use_v3(). Only that clone carries the target: no translation unit is compiled with
// -march flags, so no inline function of a shared header is ever emitted (COMDAT) with AVX
// instructions that a baseline caller could link to.
//
// The same bits on both paths: -ffp-contract=off stays (no a·b + c is fused), GCC does not
// reassociate without -ffast-math, and an explicit std::fma is exact whether it is the
// instruction or libm's software routine; tests/convex3/test_isa_dispatch.cpp compares both
// paths bit for bit, and the identity dumps (scripts/sigma_identity.py) keep their hashes with
// either path (PENDEPTH_ISA=baseline).
#pragma once

#ifndef PENDEPTH_V3_CLONES  // -DPENDEPTH_V3_CLONES=0 builds without the clones
// Optimised, unsanitised GCC ≥ 12 builds only: under AddressSanitizer (-O1 -g) flattening the
// call trees took > 12 min and 6–13 GB per translation unit (measured), and at -O0 there is
// nothing to gain. Those builds run the portable path, which the tests compare with the clones
// bit for bit in the Release build (and scripts/determinism.sh compares the two builds' CLIs).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12 && \
    defined(__OPTIMIZE__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define PENDEPTH_V3_CLONES 1
#else
#define PENDEPTH_V3_CLONES 0
#endif
#endif
#if PENDEPTH_V3_CLONES
/// The attributes of a clone: the call tree inlined and compiled for x86-64-v3.
#define PENDEPTH_V3_CLONE [[gnu::target("arch=x86-64-v3"), gnu::flatten]]
#endif

namespace pendepth::isa {

/// Whether the x86-64-v3 clones answer: initially true when the processor (and the OS) support
/// x86-64-v3 and the environment variable PENDEPTH_ISA is not `baseline`; false where the clones
/// are not built. A reference, so that tests and benchmarks can force the baseline (set it to
/// false) — setting it to true on a processor without those instructions is the caller's error.
/// Not synchronised: set it before queries run on other threads.
bool& use_v3();

/// Whether this build and this processor could run the clones (what use_v3() starts from,
/// ignoring PENDEPTH_ISA).
bool v3_available();

}  // namespace pendepth::isa
