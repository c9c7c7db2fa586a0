#!/usr/bin/env bash
# pendepth demo: installs what the build needs (scripts/setup.sh: Debian packages), builds the
# library's quickstart programs (the front door, include/pendepth/pendepth.hpp), the Python package
# (installed for Debian's /usr/bin/python3) and the command-line tool, and runs them on
# examples/data (see its README for where the shapes come from).
# Pictures go to out/*.svg (2D) and out/*.html (3D: open in a browser, turn the scene around).
# BUILD=<dir> picks the build directory.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh  # installs the Debian packages the build needs (nothing when all are there)
BUILD=${BUILD:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DPENDEPTH_BUILD_PYTHON=ON >/dev/null
cmake --build "$BUILD" -j2 --target pendepth-cli example_quickstart example_quickstart3 _pendepth
mkdir -p out
pd="$BUILD/bin/pendepth"

echo "== the library: examples/quickstart.cpp (2D) and examples/quickstart3.cpp (3D), one header"
"$BUILD/bin/example_quickstart"
"$BUILD/bin/example_quickstart3"
data=examples/data

echo "== the Python package: installed for Debian's /usr/bin/python3, then examples/python/quickstart.py"
# The built package (extension + pure-Python files) goes to python3's site directory, so that
# `/usr/bin/python3 -c "import pendepth"` works from any directory afterwards.
site=$(/usr/bin/python3 -c 'import site; print(site.getsitepackages()[0])')
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
$SUDO mkdir -p "$site"
$SUDO rm -rf "$site/pendepth"
$SUDO cp -r "$BUILD/python/pendepth" "$site/pendepth"
echo "(installed in $site/pendepth)"
(cd / && /usr/bin/python3 -c "import pendepth; print('pendepth', pendepth.__version__, 'from', pendepth.__file__)")
/usr/bin/python3 examples/python/quickstart.py

echo "== octagon P fixed, hexagon Q at t = (2.5, 2): minimum depth σ  (out/demo.svg)"
"$pd" depth "$data/octagon.wkt" "$data/hexagon.wkt" --offset 2.5,2 --svg out/demo.svg
"$pd" depth "$data/octagon.wkt" "$data/hexagon.wkt" --offset 2.5,2 --json

echo "== same shapes, t = (-1, 2), along d = (1, 0.3): directional depth σ_d  (out/demo_directional.svg)"
"$pd" depth "$data/octagon.wkt" "$data/hexagon.wkt" --offset=-1,2 --direction 1,0.3 --json \
  --svg out/demo_directional.svg

echo "== real nesting pieces (ESICUP trousers items 14 and 16) at t = (1, 3)  (out/demo_nesting.svg)"
"$pd" depth "$data/trousers_item14.wkt" "$data/trousers_item16.wkt" --offset 1,3 --json \
  --svg out/demo_nesting.svg

echo "== non-convex P (ESICUP trousers item 0) against convex Q (item 16) at t = (8, 6): σ, σ_d up,"
echo "   and complete separation downwards (Q must leave the pocket entirely)  (out/demo_pocket.svg)"
"$pd" depth "$data/trousers_item0.wkt" "$data/trousers_item16.wkt" --offset 8,6 --svg out/demo_pocket.svg
"$pd" depth "$data/trousers_item0.wkt" "$data/trousers_item16.wkt" --offset 8,6 --direction 0,1 --json
"$pd" depth "$data/trousers_item0.wkt" "$data/trousers_item16.wkt" --offset 8,6 --direction 0,-1 --separate --json

echo "== a plate with a hole, the hexagon inside the hole overlapping its rim  (out/demo_hole.svg)"
"$pd" depth "$data/plate_with_hole.wkt" "$data/hexagon.wkt" --offset 3.5,2.5 --svg out/demo_hole.svg

echo "== two non-convex polygons: P = trousers item 0, Q = the plate with a hole. The no-fit polygon"
echo "   (placements of Q's origin where Q touches P) as WKT, then σ and σ_d up at t = (20, 2)"
echo "   (out/demo_nonconvex.svg: the no-fit polygon in the configuration panel)"
"$pd" nfp "$data/trousers_item0.wkt" "$data/plate_with_hole.wkt"
"$pd" depth "$data/trousers_item0.wkt" "$data/plate_with_hole.wkt" --offset 20,2 --svg out/demo_nonconvex.svg
"$pd" depth "$data/trousers_item0.wkt" "$data/plate_with_hole.wkt" --offset 20,2 --direction 0,1 --json

echo "== batch: offsets x,y and directions dx,dy (0,0 asks for σ)"
printf 'x,y,dx,dy\n2.5,2,0,0\n2.5,2,1,0\n-1,2,1,0.3\n10,10,0,0\n' > out/demo_queries.csv
"$pd" batch "$data/octagon.wkt" "$data/hexagon.wkt" --queries out/demo_queries.csv

echo "== bad input: exit status 2 and one line naming file, line and problem"
printf 'x,y,dx,dy\n1,2,3,4\n1,2,3\n' > out/demo_bad.csv
set +e
"$pd" batch "$data/octagon.wkt" "$data/hexagon.wkt" --queries out/demo_bad.csv >/dev/null
echo "(exit status $?)"
set -e

echo "== 3D: a hexagonal prism P fixed (examples/data/hex_prism.off), an icosahedron Q at"
echo "   t = (1.2, 0.5, 1.9) turned by the quaternion (0.95, 0.1, 0.2, 0.2): σ, then σ_d along (1, 0.3, 0.2)"
echo "   (out/demo3d.html, out/demo3d_directional.html: self-contained pages, open them in a browser)"
"$pd" depth "$data/hex_prism.off" "$data/icosahedron.obj" --offset 1.2,0.5,1.9 --rotate-q 0.95,0.1,0.2,0.2 \
  --html out/demo3d.html
"$pd" depth "$data/hex_prism.off" "$data/icosahedron.obj" --offset 1.2,0.5,1.9 --rotate-q 0.95,0.1,0.2,0.2 \
  --direction 1,0.3,0.2 --json --html out/demo3d_directional.html

# 3D: convex hulls of real game objects from the project's shared data, ../shared/data/hulls
# relative to the repository root (Jolt Physics' convex_hulls.bin, MIT licence; see
# ../shared/data/README.md). These files hold vertices only (no faces): point sets, whose convex
# hull the tool takes (a file with faces is read as a closed mesh; --hull forces the hull). These
# lines need that shared directory next to the repository.
hulls=../shared/data/hulls
if [ -d "$hulls" ]; then
  echo "== 3D: hull 7 P fixed (a flat slab), hull 12 Q at t = (-1, 0, -0.5): minimum depth σ"
  "$pd" depth "$hulls/hull07.obj" "$hulls/hull12.obj" --offset=-1,0,-0.5

  echo "== 3D: same placement along d = (0, 0, 1), and with Q rotated 45° about y (quaternion w,x,y,z)"
  "$pd" depth "$hulls/hull07.obj" "$hulls/hull12.obj" --offset=-1,0,-0.5 --direction 0,0,1 --json
  "$pd" depth "$hulls/hull07.obj" "$hulls/hull12.obj" --offset=-1,0,-0.5 --rotate-q 0.924,0,0.383,0 --json

  echo "== 3D batch: offsets x,y,z and directions dx,dy,dz (0,0,0 asks for σ)"
  printf 'x,y,z,dx,dy,dz\n-1,0,-0.5,0,0,0\n-1,0,-0.5,0,0,1\n-2,0.5,0,1,0,0\n9,9,9,0,0,0\n' > out/demo_queries3.csv
  "$pd" batch "$hulls/hull07.obj" "$hulls/hull12.obj" --queries out/demo_queries3.csv
else
  echo "(3D demo skipped: $hulls not found)"
fi
