// libFuzzer target: 2D queries on two convex polygons built from the bytes (exact hulls of small
// integer points; fuzz_shapes.hpp): σ, σ_d, complete separation, overlap, both engines (merge and
// depth field), batch = single, the no-fit polygon, with their invariants.
#include "fuzz_shapes.hpp"

PENDEPTH_FUZZ_TARGET(fuzz_query2_convex) {
  if (size > 1024) return 0;
  fuzz::Bytes b(data, size);
  const auto P = fuzz::shape2(b, 0, "P");
  const auto Q = fuzz::shape2(b, 0, "Q");
  if (!P || !Q) return 0;
  fuzz::check(P->is_convex() && Q->is_convex(), "a hull is not convex");
  fuzz::allowed([&] { fuzz::exercise2(b, *P, *Q); });
  return 0;
}
