// Private: the paths of the no-fit polygon export (nfp_rings.cpp), exposed so that tests can run
// each one and compare it with the oracle. nfp_export (nfp_impl.hpp) picks the first that applies.
#pragma once

#include "nonconvex2/nfp_impl.hpp"

namespace pendepth {

enum class NfpExportPath {
  Any,      // what nfp_export does: Convex if both shapes are convex, else Linked, else General
  Convex,   // nfp_export_convex: whole pieces of a convex sum, by angle
  Linked,   // every vertex starts one piece and ends one, no vertex inside a piece: pieces are edges
  General,  // pieces grouped by exact line, cut into elementary segments (slits, pinches)
};

/// The export by one path: false (nothing written) when that path does not apply; General and Any
/// always apply. The same output, bit for bit, whichever path applies.
bool nfp_export_by(NoFitPolygon2::Impl& nfp, NfpExportPath path);

/// The path the last nfp_export / nfp_export_by call on this thread took (Convex, Linked or
/// General), for tests.
NfpExportPath nfp_export_last_path();

}  // namespace pendepth
