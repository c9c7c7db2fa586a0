#!/usr/bin/env bash
# Runs bench_convex2 (2D convex depth: pendepth against the naive linear scans and Box2D) and
# prints the markdown tables kept in docs/benchmarks.md; raw results go to JSON and CSV.
#
# Usage: bench/run_convex2.sh [build-dir] [out-dir]
#   build-dir  default <repo>/build (configured as Release if it has no CMakeCache.txt)
#   out-dir    default <build-dir>/bench-results  (convex2.json, convex2.csv, convex2.md)
# Environment: MIN_TIME  seconds per benchmark and repetition (default 0.2)
#              REPS      repetitions; the tables use the median (default 3)
#              FILTER    --benchmark_filter regex (default: everything)
# Times are CPU time per query (less sensitive to other processes than wall time). A full run
# takes about 3 minutes on 2 cores.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$build/bench-results}
MIN_TIME=${MIN_TIME:-0.2}
REPS=${REPS:-3}
FILTER=${FILTER:-.}

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
btype=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt")
[ "$btype" = Release ] || echo "run_convex2: warning: $build is a '$btype' build, not Release" >&2
cmake --build "$build" --target bench_convex2 -j2
mkdir -p "$out"

echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
start=$(date +%s)
"$build/bin/bench_convex2" --benchmark_min_time="$MIN_TIME" --benchmark_repetitions="$REPS" \
  --benchmark_report_aggregates_only=true --benchmark_filter="$FILTER" \
  --benchmark_out="$out/convex2.json" --benchmark_out_format=json
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg); run took $(( $(date +%s) - start )) s"

/usr/bin/python3 - "$out/convex2.json" "$out/convex2.csv" "$out/convex2.md" <<'PY'
import csv, json, sys

src, csv_path, md_path = sys.argv[1:4]
with open(src) as f:
    data = json.load(f)

# One record per benchmark name: the median aggregate when repeated, else the single run.
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

def counter(name, key):
    b = runs.get(name)
    return None if b is None or b.get("error_occurred") else b.get(key)

sizes = sorted({int(n.rsplit("/", 1)[1]) for n in runs})
errors = [f"{n}: {b.get('error_message')}" for n, b in runs.items() if b.get("error_occurred")]

with open(csv_path, "w", newline="") as f:
    w = csv.writer(f)
    keys = ["n", "M_edges", "checked", "max_abs_diff_sigma", "max_abs_diff_field",
            "max_abs_diff_sigma_d", "field_nodes", "field_max_steps", "b2_err_max",
            "b2_err_median", "b2_err_shallow_max", "b2_err_shallow_median"]
    w.writerow(["name", "query", "implementation", "size", "cpu_ns", "real_ns", "iterations",
                "error"] + keys)
    for name, b in runs.items():
        query, impl, size = name.split("/")
        real = None if b.get("error_occurred") else b["real_time"] * scale[b["time_unit"]]
        w.writerow([name, query, impl, size, ns(name), real, b.get("iterations"),
                    b.get("error_message", "")] + [b.get(k, "") for k in keys])

lines = []
lines.append("| n = m | σ_d pendepth | σ_d naive scan | ratio | σ field | σ naive scan | ratio "
             "| σ merge | Box2D | ratio |")
lines.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for n in sizes:
    g = lambda q: ns(f"{q}/{n}")
    sd, sdn = g("sigma_d/pendepth"), g("sigma_d/naive_scan")
    sf, sn = g("sigma_field/pendepth"), g("sigma/naive_scan")
    sm, b2 = g("sigma_merge/pendepth"), g("sigma/box2d")
    lines.append(f"| {n:,} | {fmt_t(sd)} | {fmt_t(sdn)} | {fmt_r(sdn, sd)} | {fmt_t(sf)} "
                 f"| {fmt_t(sn)} | {fmt_r(sn, sf)} | {fmt_t(sm)} | {fmt_t(b2)} "
                 f"| {fmt_r(b2, sm)} |")
lines.append("")
lines.append("Ratios are reference time / pendepth time (> 1: pendepth faster). Box2D ratio: "
             "b2CollidePolygons / minimum_depth.")
lines.append("")
lines.append("| n = m | edges of M | field build | σ_d naive build+scan | vs σ_d pendepth "
             "| σ naive build+scan | vs σ field | σ merge / σ naive scan "
             "| Box2D + WorldManifold | vs σ merge |")
lines.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for n in sizes:
    g = lambda q: ns(f"{q}/{n}")
    edges = counter(f"sigma_d/pendepth/{n}", "M_edges")
    sd, sdb = g("sigma_d/pendepth"), g("sigma_d/naive_build_scan")
    sf, sb = g("sigma_field/pendepth"), g("sigma/naive_build_scan")
    sm, sn, b2w = g("sigma_merge/pendepth"), g("sigma/naive_scan"), g("sigma/box2d_world")
    lines.append(f"| {n:,} | {'—' if edges is None else f'{int(edges):,}'} "
                 f"| {fmt_t(g('field_build/pendepth'))} | {fmt_t(sdb)} | {fmt_r(sdb, sd)} "
                 f"| {fmt_t(sb)} | {fmt_r(sb, sf)} | {fmt_r(sm, sn)} | {fmt_t(b2w)} "
                 f"| {fmt_r(b2w, sm)} |")
lines.append("")
lines.append("| n = m | queries checked | max abs diff σ merge vs naive | σ field vs merge "
             "| σ_d vs naive | Box2D depth error max / median | shallow max / median |")
lines.append("|---:|---:|---:|---:|---:|---:|---:|")
g3 = lambda x: "—" if x is None else f"{x:.2g}"
for n in sizes:
    c = lambda k: counter(f"sigma_merge/pendepth/{n}", k)
    b = lambda k: counter(f"sigma/box2d/{n}", k)
    box = "—" if b("b2_err_max") is None else f"{g3(b('b2_err_max'))} / {g3(b('b2_err_median'))}"
    sh = ("—" if b("b2_err_shallow_max") is None
          else f"{g3(b('b2_err_shallow_max'))} / {g3(b('b2_err_shallow_median'))}")
    chk = c("checked")
    lines.append(f"| {n:,} | {'—' if chk is None else int(chk)} | {g3(c('max_abs_diff_sigma'))} "
                 f"| {g3(c('max_abs_diff_field'))} "
                 f"| {g3(counter(f'sigma_d/pendepth/{n}', 'max_abs_diff_sigma_d'))} "
                 f"| {box} | {sh} |")
if errors:
    lines.append("")
    lines.append("Errors: " + "; ".join(errors))
ctx = data.get("context", {})
lines.append("")
lines.append(f"Run: {ctx.get('date', '?')}, {ctx.get('num_cpus', '?')} CPUs at "
             f"{ctx.get('mhz_per_cpu', '?')} MHz, load {ctx.get('load_avg', '?')}, "
             f"library build {ctx.get('library_build_type', '?')}.")
text = "\n".join(lines) + "\n"
with open(md_path, "w") as f:
    f.write(text)
print()
print(text, end="")
PY
echo "results: $out/convex2.json, $out/convex2.csv, $out/convex2.md"
