#!/bin/sh
# Validation and convex decomposition time of every mesh file in DIR (CGAL's sample meshes:
# /tmp/cgaldata/data/meshes, or build/cgal_data/data/meshes), each under a watchdog of CAP seconds.
# Usage: bench/run_mesh_decompose.sh BUILD_DIR MESH_DIR [CAP]
build=${1:-build}; dir=${2:-$build/cgal_data/data/meshes}; cap=${3:-60}
for f in "$dir"/*.off "$dir"/*.obj; do
  [ -e "$f" ] || continue
  out=$(timeout -s KILL "$cap" "$build/bin/mesh_decompose_times" "$f")
  rc=$?
  if [ $rc -eq 137 ]; then echo "$out >${cap}s (killed: decomposition not finished)"; else echo "$out"; fi
done
