#!/usr/bin/env python3
"""Tables of bench/run_nonconvex2.sh:
two non-convex polygons, pendepth (NoFitPolygon2, PairDepth2) against CGAL and Clipper.
Usage: tables_nonconvex2.py JSON CSV MD BUILD_TYPE
(BUILD_TYPE: CMAKE_BUILD_TYPE of the build dir; the tables are also written to stdout.)
Build times are divided by the counter `pairs` (a nesting benchmark builds every pair of its
instance per iteration), so every time in the tables is per pair or per query.
"""
import csv, os, sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_tables import Results, finish, fmt_i, fmt_r, fmt_t  # noqa: E402

src, csv_path, md_path, btype = sys.argv[1:5]
res = Results(src)
runs = res.runs
ns, counter = res.ns, res.counter

ORDER = {"albano": 0, "shirts": 1, "trousers": 2, "star": 3}
# name = what/impl/case/n/m
all_cases = sorted({tuple(n.split("/")[2:5]) for n in runs}, key=lambda c: (ORDER.get(c[0].split("-")[0], 9), int(c[1]), int(c[2])))
cases = [c for c in all_cases if "-" not in c[0]]
KIND = {"convex": 0, "mixed": 1, "nonconvex": 2}
split_cases = sorted([c for c in all_cases if "-" in c[0]],
                     key=lambda c: (ORDER.get(c[0].split("-")[0], 9), KIND.get(c[0].split("-", 1)[1], 9)))


def per_pair(name):
    t = ns(name)
    p = counter(name, "pairs")
    return None if t is None or not p else t / p


with open(csv_path, "w", newline="") as f:
    w = csv.writer(f)
    keys = ["n", "m", "pairs", "candidates", "pieces", "rings", "slits", "points", "bytes", "sum_vertices",
            "max_abs_diff", "differ", "checked", "overlapping"]
    w.writerow(["name", "what", "implementation", "case", "n", "m", "cpu_ns", "iterations", "error"] + keys)
    for name, b in runs.items():
        what, impl, case, n, m = name.split("/")
        w.writerow([name, what, impl, case, n, m, ns(name), b.get("iterations"), b.get("error_message", "")]
                   + [b.get(k, "") for k in keys])

L = []
L.append("| case | pairs | n | m | build pendepth NFP | CGAL | ratio | Clipper | ratio | NFP pieces / rings (per pair) | slits / points (total) | bytes per pair | CGAL sum vertices |")
L.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for case, n, m in cases:
    t = f"{case}/{n}/{m}"
    bp, bc, bk = per_pair(f"build/pendepth/{t}"), per_pair(f"build/cgal/{t}"), per_pair(f"build/clipper/{t}")
    c = lambda k: counter(f"build/pendepth/{t}", k)
    L.append(f"| {case} | {fmt_i(c('pairs'))} | {int(n):,} | {int(m):,} | {fmt_t(bp)} | {fmt_t(bc)} | {fmt_r(bc, bp)} "
             f"| {fmt_t(bk)} | {fmt_r(bk, bp)} | {fmt_i(c('pieces'))} / {fmt_i(c('rings'))} "
             f"| {fmt_i(c('slits'))} / {fmt_i(c('points'))} | {fmt_i(c('bytes'))} "
             f"| {fmt_i(counter(f'build/cgal/{t}', 'sum_vertices'))} |")
L.append("")
L.append("Build ratios: peer time / pendepth time (> 1: pendepth faster). Nesting pieces: n, m = the largest piece sizes.")
if split_cases:
    L.append("")
    L.append("| pairs of | convex pieces | pairs | build pendepth NFP | CGAL | ratio |")
    L.append("|---|---|---:|---:|---:|---:|")
    total = {}  # instance -> [pairs, pendepth time, CGAL time] summed over its kinds
    for k, (case, n, m) in enumerate(split_cases):
        t = f"{case}/{n}/{m}"
        bp, bc = per_pair(f"build/pendepth/{t}"), per_pair(f"build/cgal/{t}")
        inst, kind = case.split("-", 1)
        label = {"convex": "both", "mixed": "one", "nonconvex": "neither"}.get(kind, kind)
        pairs = counter(f"build/pendepth/{t}", "pairs")
        L.append(f"| {inst} | {label} | {fmt_i(pairs)} | {fmt_t(bp)} | {fmt_t(bc)} | {fmt_r(bc, bp)} |")
        acc = total.setdefault(inst, [0, 0.0, 0.0])
        if pairs and bp is not None and bc is not None:
            acc[0] += pairs
            acc[1] += bp * pairs
            acc[2] += bc * pairs
        if k + 1 == len(split_cases) or split_cases[k + 1][0].split("-")[0] != inst:
            p, sp, sc = acc
            if p:
                L.append(f"| {inst} | **all pairs** | {fmt_i(p)} | {fmt_t(sp / p)} | {fmt_t(sc / p)} | {fmt_r(sc, sp)} |")
    L.append("")
    L.append("Build by convexity of the pair: every ordered pair of each instance, split by how many of its two pieces are "
             "convex; 'all pairs' is the pair-weighted mean of the rows above it.")
L.append("")
L.append("| case | n | m | σ NFP | σ PairDepth2 | σ CGAL scan | ratio | σ Clipper scan | ratio | σ_d NFP | σ_d PairDepth2 | σ_d CGAL scan | ratio | σ_d Clipper scan | ratio |")
L.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for case, n, m in cases:
    t = f"{case}/{n}/{m}"
    g = lambda q: ns(f"{q}/{t}")
    sn, sp, sc, sk = g("sigma/pendepth_nfp"), g("sigma/pendepth_pair"), g("sigma/cgal_scan"), g("sigma/clipper_scan")
    dn, dp, dc, dk = g("sigma_d/pendepth_nfp"), g("sigma_d/pendepth_pair"), g("sigma_d/cgal_scan"), g("sigma_d/clipper_scan")
    L.append(f"| {case} | {int(n):,} | {int(m):,} | {fmt_t(sn)} | {fmt_t(sp)} | {fmt_t(sc)} | {fmt_r(sc, sn)} | {fmt_t(sk)} "
             f"| {fmt_r(sk, sn)} | {fmt_t(dn)} | {fmt_t(dp)} | {fmt_t(dc)} | {fmt_r(dc, dn)} | {fmt_t(dk)} | {fmt_r(dk, dn)} |")
L.append("")
L.append("Query ratios: scan of the explicit sum / NoFitPolygon2 query (> 1: pendepth faster).")
L.append("")
L.append("| case | n | m | PairDepth2 σ / σ_d vs NFP: max abs diff (count > 1e-6·scale of checked) | CGAL scan σ / σ_d | Clipper scan σ / σ_d |")
L.append("|---|---:|---:|---|---|---|")
g2 = lambda x: "—" if x is None else f"{x:.2g}"
for case, n, m in cases:
    t = f"{case}/{n}/{m}"

    def agree(impl):
        parts = []
        for q in ("sigma", "sigma_d"):
            nm = f"{q}/{impl}/{t}"
            if counter(nm, "checked") is None:
                parts.append("—")
            else:
                parts.append(f"{g2(counter(nm, 'max_abs_diff'))} ({int(counter(nm, 'differ'))} of {int(counter(nm, 'checked'))})")
        return " / ".join(parts)

    L.append(f"| {case} | {int(n):,} | {int(m):,} | {agree('pendepth_pair')} | {agree('cgal_scan')} | {agree('clipper_scan')} |")

finish(md_path, L, res.errors(), f"{res.run_line()}, pendepth build {btype}; CPU time.")
