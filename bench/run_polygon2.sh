#!/usr/bin/env bash
# Runs bench_polygon2 (a simple polygon against a convex polygon, DHS §4: pendepth's implicit
# structure against CGAL's reduced convolution and Clipper's MinkowskiSum, each + a scan of the
# explicit sum) and prints the markdown tables kept in docs/benchmarks.md; raw results go to JSON
# and CSV.
#
# Usage: bench/run_polygon2.sh [build-dir] [out-dir]
#   build-dir  default <repo>/build (configured as Release if it has no CMakeCache.txt)
#   out-dir    default <build-dir>/bench-results  (polygon2.json, polygon2.csv, polygon2.md)
# Environment: MIN_TIME  seconds per benchmark and repetition (default 0.2)
#              REPS      repetitions; the tables use the median (default 1)
#              FILTER    --benchmark_filter regex (default: everything)
#              PENDEPTH_BENCH_N, PENDEPTH_BENCH_M   comma lists of sizes (see bench_polygon2.cpp)
#              PENDEPTH_BENCH_PEER_BUDGET          largest n·m for the CGAL peer (default 1e5)
#              PENDEPTH_BENCH_CLIPPER_BUDGET       largest n·m for the Clipper peer (default 1e4)
# Times are CPU time (less sensitive to other processes than wall time).
# The reduced run of docs/benchmarks.md (about 4 minutes on 2 loaded cores):
#   PENDEPTH_BENCH_N=10,100,1000,10000,100000 PENDEPTH_BENCH_M=4,100,1000 MIN_TIME=0.05 bench/run_polygon2.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$build/bench-results}
MIN_TIME=${MIN_TIME:-0.2}
REPS=${REPS:-1}
FILTER=${FILTER:-.}

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
btype=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt")
[ "$btype" = Release ] || echo "run_polygon2: warning: $build is a '$btype' build, not Release" >&2
cmake --build "$build" --target bench_polygon2 -j2
mkdir -p "$out"

echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
start=$(date +%s)
"$build/bin/bench_polygon2" --benchmark_min_time="$MIN_TIME" --benchmark_repetitions="$REPS" \
  --benchmark_report_aggregates_only=true --benchmark_filter="$FILTER" \
  --benchmark_out="$out/polygon2.json" --benchmark_out_format=json
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg); run took $(( $(date +%s) - start )) s"

/usr/bin/python3 - "$out/polygon2.json" "$out/polygon2.csv" "$out/polygon2.md" "$btype" <<'PY'
import csv, json, sys

src, csv_path, md_path, btype = sys.argv[1:5]
with open(src) as f:
    data = json.load(f)

runs = {}
for b in data["benchmarks"]:
    name = b.get("run_name", b["name"])
    if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
        continue
    if name in runs and runs[name].get("aggregate_name") == "median":
        continue
    runs[name] = b

scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}

def ns(name):
    b = runs.get(name)
    if b is None or b.get("error_occurred"):
        return None
    return b["cpu_time"] * scale[b["time_unit"]]

def counter(name, key):
    b = runs.get(name)
    return None if b is None or b.get("error_occurred") else b.get(key)

def fmt_t(x):
    if x is None:
        return "—"
    for unit, div in (("s", 1e9), ("ms", 1e6), ("µs", 1e3)):
        if x >= div:
            return f"{x / div:.3g} {unit}"
    return f"{x:.3g} ns"

def fmt_r(num, den):
    if num is None or den is None or den == 0:
        return "—"
    r = num / den
    return f"{r:,.0f}×" if r >= 100 else f"{r:.3g}×"

def fmt_i(x):
    return "—" if x is None else f"{int(x):,}"

# name = what/impl/shape/n/m
cases = sorted({tuple(n.split("/")[2:5]) for n in runs}, key=lambda c: (c[0] != "star", int(c[1]), int(c[2])))

with open(csv_path, "w", newline="") as f:
    w = csv.writer(f)
    keys = ["n", "m", "triangles", "boundary_vertices", "boundary_segments", "boundary_arcs", "bytes",
            "sum_vertices", "bytes_per_direction", "max_abs_diff", "differ", "checked", "overlapping"]
    w.writerow(["name", "what", "implementation", "shape", "n", "m", "cpu_ns", "iterations", "error"] + keys)
    for name, b in runs.items():
        what, impl, shape, n, m = name.split("/")
        w.writerow([name, what, impl, shape, n, m, ns(name), b.get("iterations"), b.get("error_message", "")]
                   + [b.get(k, "") for k in keys])

L = []
L.append("| shape | n | m | build pendepth | CGAL | ratio | Clipper | ratio | ∂O vertices / arcs | bytes | CGAL sum vertices | 8 fixed directions: build / bytes per direction |")
L.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for shape, n, m in cases:
    t = f"{shape}/{n}/{m}"
    bp, bc, bk = ns(f"build/pendepth/{t}"), ns(f"build/cgal/{t}"), ns(f"build/clipper/{t}")
    c = lambda k: counter(f"build/pendepth/{t}", k)
    L.append(f"| {shape} | {int(n):,} | {int(m):,} | {fmt_t(bp)} | {fmt_t(bc)} | {fmt_r(bc, bp)} | {fmt_t(bk)} "
             f"| {fmt_r(bk, bp)} | {fmt_i(c('boundary_vertices'))} / {fmt_i(c('boundary_arcs'))} | {fmt_i(c('bytes'))} "
             f"| {fmt_i(counter(f'build/cgal/{t}', 'sum_vertices'))} "
             f"| {fmt_t(ns(f'build/pendepth_fixed8/{t}'))} / {fmt_i(counter(f'build/pendepth_fixed8/{t}', 'bytes_per_direction'))} |")
L.append("")
L.append("Ratios: peer time / pendepth time (> 1: pendepth faster).")
L.append("")
L.append("| shape | n | m | σ_d fast | σ_d fixed dir | σ_d scan ∂O | σ | σ_d CGAL scan | ratio | σ CGAL scan | ratio | σ_d Clipper scan | σ Clipper scan |")
L.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for shape, n, m in cases:
    t = f"{shape}/{n}/{m}"
    g = lambda q: ns(f"{q}/{t}")
    sd, sf, ss, sm = g("sigma_d/pendepth"), g("sigma_d/pendepth_fixed"), g("sigma_d/pendepth_scan"), g("sigma/pendepth")
    cd, cs = g("sigma_d/cgal_scan"), g("sigma/cgal_scan")
    kd, ks = g("sigma_d/clipper_scan"), g("sigma/clipper_scan")
    L.append(f"| {shape} | {int(n):,} | {int(m):,} | {fmt_t(sd)} | {fmt_t(sf)} | {fmt_t(ss)} | {fmt_t(sm)} | {fmt_t(cd)} "
             f"| {fmt_r(cd, sd)} | {fmt_t(cs)} | {fmt_r(cs, sm)} | {fmt_t(kd)} | {fmt_t(ks)} |")
L.append("")
L.append("Query ratios: scan of the explicit sum / pendepth (σ_d: fast path; σ: minimum).")
L.append("")
L.append("| shape | n | m | CGAL σ_d / σ: max abs diff (count > 1e-6 of checked) | Clipper σ_d / σ |")
L.append("|---|---:|---:|---|---|")
g2 = lambda x: "—" if x is None else f"{x:.2g}"
for shape, n, m in cases:
    t = f"{shape}/{n}/{m}"
    def agree(impl):
        parts = []
        for q in ("sigma_d", "sigma"):
            nm = f"{q}/{impl}_scan/{t}"
            if counter(nm, "checked") is None:
                parts.append("—")
            else:
                parts.append(f"{g2(counter(nm, 'max_abs_diff'))} ({int(counter(nm, 'differ'))} of {int(counter(nm, 'checked'))})")
        return " / ".join(parts)
    if counter(f"sigma_d/cgal_scan/{t}", "checked") is None and counter(f"sigma_d/clipper_scan/{t}", "checked") is None:
        continue
    L.append(f"| {shape} | {int(n):,} | {int(m):,} | {agree('cgal')} | {agree('clipper')} |")
errors = [f"{n}: {b.get('error_message')}" for n, b in runs.items() if b.get("error_occurred")]
if errors:
    L.append("")
    L.append("Errors: " + "; ".join(errors))
ctx = data.get("context", {})
L.append("")
L.append(f"Run: {ctx.get('date', '?')}, {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, "
         f"load {ctx.get('load_avg', '?')}, pendepth build {btype}; CPU time.")
text = "\n".join(L) + "\n"
with open(md_path, "w") as f:
    f.write(text)
print()
print(text, end="")
PY
echo "results: $out/polygon2.json, $out/polygon2.csv, $out/polygon2.md"
