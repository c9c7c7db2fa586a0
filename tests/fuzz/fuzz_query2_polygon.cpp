// libFuzzer target: 2D queries on polygons built from the bytes (fuzz_shapes.hpp): convex, star-
// shaped or orthogonal grid polygons with holes, in any combination (polygon × convex either way,
// polygon × polygon per query and on the no-fit polygon), with their invariants.
#include "fuzz_shapes.hpp"

PENDEPTH_FUZZ_TARGET(fuzz_query2_polygon) {
  if (size > 1024) return 0;
  fuzz::Bytes b(data, size);
  const int kinds = b.u8();
  const auto P = fuzz::shape2(b, kinds % 3, "P");
  const auto Q = fuzz::shape2(b, (kinds / 3) % 3, "Q");
  if (!P || !Q) return 0;
  fuzz::allowed([&] { fuzz::exercise2(b, *P, *Q); });
  return 0;
}
