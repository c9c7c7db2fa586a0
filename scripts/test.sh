#!/usr/bin/env bash
# The README's test command: installs what the build needs (Debian packages), builds everything
# (library, CLI, tests, benchmarks, examples) in Release and runs the whole test suite; then
# builds and runs the tests once more under AddressSanitizer + UndefinedBehaviorSanitizer.
# Usage: scripts/test.sh [--no-sanitize]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
JOBS=${JOBS:-2}

echo "== Release build + tests =="
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$JOBS"
ctest --test-dir build --output-on-failure -j"$JOBS"

if [ "${1:-}" != "--no-sanitize" ]; then
  echo "== ASan + UBSan build + tests =="
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DPENDEPTH_SANITIZE=ON \
        -DPENDEPTH_BUILD_BENCH=OFF -DPENDEPTH_BUILD_EXAMPLES=OFF >/dev/null
  cmake --build build-asan -j"$JOBS"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j"$JOBS" -LE package
fi
