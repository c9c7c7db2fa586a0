#!/usr/bin/env python3
"""Tables of bench/run_convex2.sh:
2D convex depth, pendepth against the naive scans and Box2D.
Usage: tables_convex2.py JSON CSV MD BUILD_TYPE
(BUILD_TYPE: CMAKE_BUILD_TYPE of the build dir; the tables are also written to stdout.)
"""
import csv, os, sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_tables import Results, finish, fmt_r, fmt_t  # noqa: E402

src, csv_path, md_path, btype = sys.argv[1:5]
res = Results(src)
runs = res.runs
ns, counter = res.ns, res.counter

sizes = sorted({int(n.rsplit("/", 1)[1]) for n in runs})

with open(csv_path, "w", newline="") as f:
    w = csv.writer(f)
    keys = ["n", "M_edges", "checked", "max_abs_diff_sigma", "max_abs_diff_field",
            "max_abs_diff_sigma_d", "field_nodes", "field_max_steps", "b2_err_max",
            "b2_err_median", "b2_err_shallow_max", "b2_err_shallow_median"]
    w.writerow(["name", "query", "implementation", "size", "cpu_ns", "real_ns", "iterations",
                "error"] + keys)
    for name, b in runs.items():
        query, impl, size = name.split("/")
        w.writerow([name, query, impl, size, ns(name), res.real_ns(name), b.get("iterations"),
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

finish(md_path, lines, res.errors(), f"{res.run_line()}, library build {res.library_build()}.")
