#!/usr/bin/python3
"""Scaling plot of issue 19 item 4: build time against n for combs, stars and spirals.

Runs the scale benchmarks of bench_nonconvex2 (`build/pendepth/scale-<family>/<n>/6`: one
NoFitPolygon2 build of P of about n vertices against an L-shape of 6) and of bench_polygon2
(`build/pendepth/<family>/<n>/<m>`: one PolygonDepth2 build, i.e. the polygon × convex union
boundary, P against a convex Q of m vertices), one process each, and draws both as log-log curves
of CPU time against n with dashed n and n² reference slopes.

Usage: bench/plot_scaling.py [build-dir] [out.svg]   (defaults: build, docs/scaling.svg)
Environment: SCALE_N   comma list of n (default 1000,3000,10000,30000,100000)
             POLY_M    m of the polygon × convex benchmarks (default 100)
             JSON_IN   reuse this directory's nonconvex2_scale.json / polygon2_scale.json
                       instead of running the benchmarks (re-plot only)
Needs Debian's /usr/bin/python3 with python3-matplotlib (scripts/setup.sh installs it).
The JSON outputs are kept next to the SVG's build directory: <build>/bench-results/.
"""
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def run(binary, flt, env_extra, out):
    env = dict(os.environ, **env_extra)
    cmd = [binary, f"--benchmark_filter={flt}", f"--benchmark_out={out}", "--benchmark_out_format=json",
           "--benchmark_min_time=0"]
    print(" ".join(f"{k}={v}" for k, v in env_extra.items()), " ".join(cmd), flush=True)
    subprocess.run(cmd, env=env, check=True)


def load(path):
    with open(path) as f:
        data = json.load(f)
    return data


def series(data, prefix):
    """{family: [(n, cpu ms)]} for benchmark names prefix<family>/<n>/<m>."""
    out = {}
    for b in data["benchmarks"]:
        name = b["name"]
        if not name.startswith(prefix) or b.get("run_type", "iteration") != "iteration":
            continue
        family = name[len(prefix):].split("/")[0]
        unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
        n = b.get("n", float(name.split("/")[-2]))
        out.setdefault(family, []).append((n, b["cpu_time"] * unit))
    for v in out.values():
        v.sort()
    return out


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    svg = sys.argv[2] if len(sys.argv) > 2 else "docs/scaling.svg"
    sizes = os.environ.get("SCALE_N", "1000,3000,10000,30000,100000")
    m = os.environ.get("POLY_M", "100")
    res = os.environ.get("JSON_IN") or os.path.join(build, "bench-results")
    os.makedirs(res, exist_ok=True)
    nc_json = os.path.join(res, "nonconvex2_scale.json")
    pg_json = os.path.join(res, "polygon2_scale.json")
    if not os.environ.get("JSON_IN"):
        print(f"load before: {open('/proc/loadavg').read().split()[:3]}", flush=True)
        run(os.path.join(build, "bin", "bench_nonconvex2"), "^build/pendepth/scale-",
            {"PENDEPTH_BENCH_SCALE_N": sizes, "PENDEPTH_BENCH_N": "10", "PENDEPTH_BENCH_NFP_BUDGET": "0"}, nc_json)
        run(os.path.join(build, "bin", "bench_polygon2"), "^build/pendepth/(star|comb|spiral)/",
            {"PENDEPTH_BENCH_N": sizes, "PENDEPTH_BENCH_M": m, "PENDEPTH_BENCH_PEER_BUDGET": "0"}, pg_json)
        print(f"load after: {open('/proc/loadavg').read().split()[:3]}", flush=True)
    nc = series(load(nc_json), "build/pendepth/scale-")
    pg = series(load(pg_json), "build/pendepth/")
    load_avg = load(pg_json)["context"].get("load_avg", [])

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), sharey=False)
    colors = {"comb": "tab:blue", "comb45": "tab:purple", "star": "tab:red", "spiral": "tab:green"}
    panels = [(axes[0], nc, "no-fit polygon (NoFitPolygon2) vs an L of 6"),
              (axes[1], pg, f"polygon × convex (PolygonDepth2) vs convex Q of {m}")]
    for ax, data, title in panels:
        lo_n = hi_n = None
        anchor = None
        for family, pts in sorted(data.items()):
            ns = [p[0] for p in pts]
            ts = [p[1] for p in pts]
            ax.loglog(ns, ts, "o-", color=colors.get(family), label=family)
            lo_n = min(ns) if lo_n is None else min(lo_n, min(ns))
            hi_n = max(ns) if hi_n is None else max(hi_n, max(ns))
            anchor = max(anchor or 0, ts[0])
        if lo_n:
            xs = [lo_n, hi_n]
            ax.loglog(xs, [anchor, anchor * hi_n / lo_n], "k--", lw=0.8, label="slope n")
            ax.loglog(xs, [anchor, anchor * (hi_n / lo_n) ** 2], "k:", lw=0.8, label="slope n²")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("n (vertices of P)")
        ax.set_ylabel("build, CPU ms (one build)")
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("pendepth build time against n (bench_nonconvex2 / bench_polygon2; load "
                 + ", ".join(f"{x:.1f}" for x in load_avg) + ")", fontsize=10)
    fig.tight_layout()
    fig.savefig(svg)
    print(f"wrote {svg}")
    for label, data in (("nonconvex2", nc), ("polygon2", pg)):
        for family, pts in sorted(data.items()):
            print(label, family, " ".join(f"{int(n)}:{t:.1f}ms" for n, t in pts))


if __name__ == "__main__":
    main()
