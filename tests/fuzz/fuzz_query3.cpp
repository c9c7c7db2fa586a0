// libFuzzer target: 3D queries on two convex polytopes built from the bytes (exact hulls of small
// integer points, fuzz_shapes.hpp): σ with its certified bounds, σ_d, overlap, rotated poses, with
// their invariants.
#include "fuzz_shapes.hpp"

PENDEPTH_FUZZ_TARGET(fuzz_query3) {
  if (size > 1024) return 0;
  fuzz::Bytes b(data, size);
  const auto P = fuzz::shape3(b, "P");
  const auto Q = fuzz::shape3(b, "Q");
  if (!P || !Q) return 0;
  fuzz::allowed([&] { fuzz::exercise3(b, *P, *Q); });
  return 0;
}
