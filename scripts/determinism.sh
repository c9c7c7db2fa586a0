#!/usr/bin/env bash
# Determinism (docs/robustness.md): two builds of the CLI give the same answers bit for bit, at 1
# and at 2 threads — every 2D engine (convex, polygon × convex both ways, polygon × polygon by the
# no-fit polygon) and the 3D engines (σ and σ_d, with a rotation), 2,000 queries each, JSON Lines
# with shortest round-trip doubles (so equal text is equal bits).
# Usage: scripts/determinism.sh BUILD_A [BUILD_B]   (test.sh: build and build-asan)
set -euo pipefail
cd "$(dirname "$0")/.."
A=$1
B=${2:-$1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
data=examples/data
hulls=../shared/data/hulls

# queries N RANGE DIM: deterministic pseudo-random placements in [-RANGE, RANGE]; every other
# query has a direction (σ_d), the others the zero direction (σ).
queries() {
  awk -v n="$1" -v r="$2" -v dim="$3" 'BEGIN {
    s = 12345
    for (i = 0; i < n; i++) {
      line = ""
      for (k = 0; k < 2 * dim; k++) {
        s = (s * 1103515245 + 12345) % 2147483648
        v = (s / 2147483648 * 2 - 1) * (k < dim ? r : 1)
        if (k >= dim && i % 2 == 0) v = 0
        line = line (k ? "," : "") sprintf("%.17g", v)
      }
      print line
    }
  }'
}
queries 2000 8 2 > "$work/q_small.csv"
queries 2000 40 2 > "$work/q_large.csv"
queries 2000 1 3 > "$work/q3.csv"

cases=(
  "$data/octagon.wkt $data/hexagon.wkt q_small.csv"
  "$data/trousers_item0.wkt $data/trousers_item16.wkt q_large.csv"
  "$data/trousers_item16.wkt $data/trousers_item0.wkt q_large.csv"
  "$data/trousers_item0.wkt $data/trousers_item14.wkt q_large.csv"
  "$data/plate_with_hole.wkt $data/hexagon.wkt q_small.csv"
  "$hulls/hull00.obj $hulls/hull00.obj q3.csv --rotate-q 0.9,0.1,0.3,0.2"
)
fail=0
overlaps() { grep -c "\"overlapping\":true" "$1" || true; }
for c in "${cases[@]}"; do
  set -- $c
  p=$1 q=$2 file=$3
  shift 3
  "$A/bin/pendepth" batch "$p" "$q" --queries "$work/$file" --json --threads 1 "$@" > "$work/a1"
  "$A/bin/pendepth" batch "$p" "$q" --queries "$work/$file" --json --threads 2 "$@" > "$work/a2"
  "$B/bin/pendepth" batch "$p" "$q" --queries "$work/$file" --json --threads 2 "$@" > "$work/b2"
  rows=$(wc -l < "$work/a1")
  if cmp -s "$work/a1" "$work/a2" && cmp -s "$work/a1" "$work/b2" && [ "$rows" -gt 0 ]; then
    echo "determinism: $(basename "$p") × $(basename "$q"): $rows answers ($(overlaps "$work/a1") overlapping), identical ($A 1 and 2 threads, $B)"
  else
    echo "determinism: $(basename "$p") × $(basename "$q"): answers differ" >&2
    fail=1
  fi
done
exit $fail
