#!/usr/bin/env bash
# Installs the Debian packages pendepth needs to build, test and benchmark (C++ and the Python
# package python/, for Debian's /usr/bin/python3), npm for the 3D viewer's three.js (viewer/,
# fetched by the build) and Chromium for the test that opens the viewer's pages (tests/html3).
# Idempotent: skips apt entirely when everything is already installed.
set -euo pipefail
PKGS=(cmake g++ make pkg-config libeigen3-dev libgmp-dev libmpfr-dev libcgal-dev libcgal-demo libgtest-dev libgmock-dev
      libbenchmark-dev libcli11-dev nlohmann-json3-dev libbox2d-dev
      libccd-dev libfcl-dev libbullet-dev libpolyclipping-dev libtbb-dev
      pybind11-dev python3-dev python3-numpy python3-pytest python3-hypothesis python3-dask
      python3-distributed python3-pandas python3-matplotlib python3-shapely
      chromium fonts-dejavu-core python3-pil
      clang libfuzzer-14-dev libclang-rt-14-dev)  # the fuzz stage of scripts/test.sh (scripts/fuzz.sh;
      # clang -fsanitize=fuzzer,address links libclang_rt.fuzzer and .asan_static, which only
      # clang's Recommends would bring)
# npm: Debian's package, unless an npm is already on the PATH (NodeSource's nodejs bundles one and
# conflicts with Debian's npm package).
command -v npm >/dev/null 2>&1 || PKGS+=(npm)
missing=()
for p in "${PKGS[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
