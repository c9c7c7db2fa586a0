#!/usr/bin/env python3
"""Tables of bench/run_polygon2.sh:
simple polygon against convex polygon, pendepth against CGAL and Clipper.
Usage: tables_polygon2.py JSON CSV MD BUILD_TYPE
(BUILD_TYPE: CMAKE_BUILD_TYPE of the build dir; the tables are also written to stdout.)
"""
import csv, os, sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_tables import Results, finish, fmt_i, fmt_r, fmt_t  # noqa: E402

src, csv_path, md_path, btype = sys.argv[1:5]
res = Results(src)
runs = res.runs
ns, counter = res.ns, res.counter

# name = what/impl/shape/n/m
cases = sorted({tuple(n.split("/")[2:5]) for n in runs}, key=lambda c: ({"star": 0, "comb": 1}.get(c[0], 2), c[0], int(c[1]), int(c[2])))

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

finish(md_path, L, res.errors(), f"{res.run_line()}, pendepth build {btype}; CPU time.")
