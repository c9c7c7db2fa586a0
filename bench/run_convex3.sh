#!/usr/bin/env bash
# Runs bench_convex3 (3D convex depth: pendepth's σ against libccd, FCL and Bullet float64; σ_d
# against the linear facet scan) and prints the markdown tables kept in docs/benchmarks.md; raw
# results go to JSON and CSV.
#
# Usage: bench/run_convex3.sh [build-dir] [out-dir]
#   build-dir  default <repo>/build (configured as Release if it has no CMakeCache.txt)
#   out-dir    default <build-dir>/bench-results  (convex3.json, convex3.csv, convex3.md)
# Environment: MIN_TIME  seconds per benchmark and repetition (default 0.1)
#              REPS      repetitions; the tables use the median (default 3)
#              FILTER    --benchmark_filter regex (default: everything)
# Times are CPU time per query. A full run takes about 10 minutes on 2 cores, most of it in the
# one-off set-up of the σ_d series at n = 10⁶ (hull ≈ 1 min, O(n·m) facet list of M ≈ 4 min);
# FILTER='/(8|64|512|4096|32768)$' leaves that out.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$build/bench-results}
MIN_TIME=${MIN_TIME:-0.1}
REPS=${REPS:-3}
FILTER=${FILTER:-.}

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
btype=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt")
[ "$btype" = Release ] || echo "run_convex3: warning: $build is a '$btype' build, not Release" >&2
cmake --build "$build" --target bench_convex3 -j2
mkdir -p "$out"

echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
start=$(date +%s)
"$build/bin/bench_convex3" --benchmark_min_time="$MIN_TIME" --benchmark_repetitions="$REPS" \
  --benchmark_report_aggregates_only=true --benchmark_filter="$FILTER" \
  --benchmark_out="$out/convex3.json" --benchmark_out_format=json
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg); run took $(( $(date +%s) - start )) s"

/usr/bin/python3 - "$out/convex3.json" "$out/convex3.csv" "$out/convex3.md" <<'PY'
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

def ok(name):
    b = runs.get(name)
    return b is not None and not b.get("error_occurred")

def ns(name):
    return runs[name]["cpu_time"] * scale[runs[name]["time_unit"]] if ok(name) else None

def counter(name, key):
    return runs[name].get(key) if ok(name) else None

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

def g2(x):
    return "—" if x is None else ("0" if x == 0 else f"{x:.2g}")

def sizes(prefix):
    return sorted({int(n.rsplit("/", 1)[1]) for n in runs if n.startswith(prefix)})

impls = [("pendepth", "pendepth σ"), ("bullet", "Bullet EPA"), ("ccd_epa", "libccd EPA"),
         ("ccd_epa_tight", "libccd EPA 1e-10"), ("ccd_mpr", "libccd MPR"),
         ("fcl_sd", "FCL signed dist."), ("fcl_epa", "FCL EPA (indep)")]
present = [(k, h) for k, h in impls if any(n.startswith(f"sigma/{k}/") for n in runs)]
errors = [f"{n}: {b.get('error_message')}" for n, b in runs.items() if b.get("error_occurred")]

with open(csv_path, "w", newline="") as f:
    w = csv.writer(f)
    keys = ["queries", "failures", "exceptions", "no_contact", "err_max", "err_median", "verified",
            "ref_max_ulps", "hull_ms", "depth_mean", "P_vertices", "Q_vertices", "M_facets",
            "facets_ms", "max_ulps_exact", "max_diff_scan"]
    w.writerow(["name", "query", "implementation", "size", "cpu_ns", "real_ns", "iterations",
                "error"] + keys)
    for name, b in runs.items():
        query, impl, size = name.split("/")
        real = b["real_time"] * scale[b["time_unit"]] if ok(name) else None
        w.writerow([name, query, impl, size, ns(name), real, b.get("iterations"),
                    b.get("error_message", "")] + [b.get(k, "") for k in keys])

L = []
L.append("| n = m | " + " | ".join(h for _, h in present) + " | Bullet / pendepth |")
L.append("|---:|" + "---:|" * (len(present) + 1))
for n in sizes("sigma/"):
    t = {k: ns(f"sigma/{k}/{n}") for k, _ in present}
    L.append(f"| {n:,} | " + " | ".join(fmt_t(t[k]) for k, _ in present)
             + f" | {fmt_r(t.get('bullet'), t.get('pendepth'))} |")
L.append("")
L.append("Median CPU time per σ query. Last column: Bullet time / pendepth time (> 1: pendepth faster).")
L.append("")
L.append("| n = m | " + " | ".join(h for _, h in present) + " |")
L.append("|---:|" + "---:|" * len(present))
for n in sizes("sigma/"):
    cells = []
    for k, _ in present:
        name = f"sigma/{k}/{n}"
        if not ok(name):
            cells.append("—")
            continue
        c = lambda key: counter(name, key)
        cells.append(f"{int(c('failures'))}/{int(c('queries'))} · {g2(c('err_max'))} / "
                     f"{g2(c('err_median'))}")
    L.append(f"| {n:,} | " + " | ".join(cells) + " |")
L.append("")
L.append("Cells: failures/queries · max / median |depth − exact|.")
L.append("")
L.append("| n = m | hulls build (P + Q) | queries verified by O(n·m) reference | max error vs reference (ulp) | mean exact σ |")
L.append("|---:|---:|---:|---:|---:|")
for n in sizes("sigma/"):
    name = f"sigma/pendepth/{n}"
    c = lambda key: counter(name, key)
    v = c("verified")
    L.append(f"| {n:,} | {fmt_t(None if c('hull_ms') is None else c('hull_ms') * 1e6)} "
             f"| {'—' if v is None else int(v)} "
             f"| {g2(c('ref_max_ulps')) if v else 'certified (lower = upper)'} "
             f"| {g2(c('depth_mean'))} |")
L.append("")
L.append("| n = \\|P\\| (m = 64) | facets of M | σ_d pendepth | σ_d facet scan | scan / pendepth "
         "| hull of P build | facet list build (O(n·m)) | exact check: queries, max ulp | max \\|scan − pendepth\\| |")
L.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for n in sizes("sigma_d/"):
    p, s = f"sigma_d/pendepth/{n}", f"sigma_d/facet_scan/{n}"
    c = lambda key: counter(p, key)
    v = c("verified")
    ex = "—" if v is None else (f"{int(v)}, {g2(c('max_ulps_exact'))}" if v else "none (too costly)")
    fac = c("M_facets")
    L.append(f"| {n:,} | {'—' if fac is None else f'{int(fac):,}'} | {fmt_t(ns(p))} | {fmt_t(ns(s))} "
             f"| {fmt_r(ns(s), ns(p))} "
             f"| {fmt_t(None if c('hull_ms') is None else c('hull_ms') * 1e6)} "
             f"| {fmt_t(None if c('facets_ms') is None else c('facets_ms') * 1e6)} | {ex} "
             f"| {g2(c('max_diff_scan'))} |")
if errors:
    L.append("")
    L.append("Errors: " + "; ".join(errors))
ctx = data.get("context", {})
L.append("")
L.append(f"Run: {ctx.get('date', '?')}, {ctx.get('num_cpus', '?')} CPUs at "
         f"{ctx.get('mhz_per_cpu', '?')} MHz, load {ctx.get('load_avg', '?')}, "
         f"library build {ctx.get('library_build_type', '?')}.")
text = "\n".join(L) + "\n"
with open(md_path, "w") as f:
    f.write(text)
print()
print(text, end="")
PY
echo "results: $out/convex3.json, $out/convex3.csv, $out/convex3.md"
