#!/usr/bin/env bash
# The soak of docs/robustness.md: random queries over every kind of shape pair (2D convex,
# polygon × convex both ways, polygon × polygon; 3D convex polytopes), one pair in four at a
# random power-of-two scale, every answer checked against a second method or a property
# (tests/soak/test_soak.cpp). CI runs 3,000 placements inside the test suite; this runs many.
# Usage: scripts/soak.sh [PLACEMENTS] [SEED]   (default 1,200,000 placements ≈ 10⁷ engine calls)
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
PLACEMENTS=${1:-1200000}
SEED=${2:-$(date +%s)}
BUILD=${BUILD:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j"${JOBS:-2}" --target test_soak
PENDEPTH_SOAK_PLACEMENTS=$PLACEMENTS PENDEPTH_SOAK_SEED=$SEED "$BUILD/bin/test_soak"
