#!/usr/bin/env python3
"""Tables of bench/run_convex3.sh:
3D convex depth, pendepth against libccd, FCL, Bullet and the facet scan.
Usage: tables_convex3.py JSON CSV MD BUILD_TYPE
(BUILD_TYPE: CMAKE_BUILD_TYPE of the build dir; the tables are also written to stdout.)
"""
import csv, os, sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_tables import Results, finish, fmt_r, fmt_t  # noqa: E402

src, csv_path, md_path, btype = sys.argv[1:5]
res = Results(src)
runs = res.runs
ns, counter, ok = res.ns, res.counter, res.ok

def g2(x):
    return "—" if x is None else ("0" if x == 0 else f"{x:.2g}")

def sizes(prefix):
    return sorted({int(n.rsplit("/", 1)[1]) for n in runs if n.startswith(prefix)})

impls = [("pendepth", "pendepth σ"), ("bullet", "Bullet EPA"), ("ccd_epa", "libccd EPA"),
         ("ccd_epa_tight", "libccd EPA 1e-10"), ("ccd_mpr", "libccd MPR"),
         ("fcl_sd", "FCL signed dist."), ("fcl_epa", "FCL EPA (indep)")]
present = [(k, h) for k, h in impls if any(n.startswith(f"sigma/{k}/") for n in runs)]

with open(csv_path, "w", newline="") as f:
    w = csv.writer(f)
    keys = ["queries", "failures", "exceptions", "no_contact", "err_max", "err_median", "verified",
            "ref_max_ulps", "hull_ms", "depth_mean", "P_vertices", "Q_vertices", "M_facets",
            "facets_ms", "max_ulps_exact", "max_diff_scan", "max_ulps_vs_public",
            "max_ulps_dk_vs_expand", "supports_sigma", "supports_expand", "work_mean", "work_max",
            "budget_share_max"]
    w.writerow(["name", "query", "implementation", "size", "cpu_ns", "real_ns", "iterations",
                "error"] + keys)
    for name, b in runs.items():
        query, impl, size = name.split("/")
        w.writerow([name, query, impl, size, ns(name), res.real_ns(name), b.get("iterations"),
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
hp = [(k, h) for k, h in impls if f"sigma_hulls/{k}/all" in runs]
if hp:  # σ on the shared real hulls (sigma_hulls/<impl>/all)
    t = {k: ns(f"sigma_hulls/{k}/all") for k, _ in hp}
    L.append("| shared real hulls | " + " | ".join(h for _, h in hp) + " | pendepth / Bullet |")
    L.append("|---|" + "---:|" * (len(hp) + 1))
    L.append("| time | " + " | ".join(fmt_t(t[k]) for k, _ in hp)
             + f" | {fmt_r(t.get('pendepth'), t.get('bullet'))} |")
    cells = []
    for k, _ in hp:
        name = f"sigma_hulls/{k}/all"
        c = lambda key: counter(name, key)
        cells.append("—" if not ok(name) else
                     f"{int(c('failures'))}/{int(c('queries'))} · {g2(c('err_max'))} / {g2(c('err_median'))}")
    L.append("| failures · max / median error | " + " | ".join(cells) + " | |")
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
L.append("| n = \\|P\\| (m = 64) | facets of M | σ_d pendepth | σ_d DK | σ_d expansion | σ_d facet scan "
         "| scan / pendepth "
         "| hull of P build | facet list build (O(n·m)) | exact check: queries, max ulp | max \\|scan − pendepth\\| |")
L.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for n in sizes("sigma_d/"):
    p, s = f"sigma_d/pendepth/{n}", f"sigma_d/facet_scan/{n}"
    c = lambda key: counter(p, key)
    v = c("verified")
    ex = "—" if v is None else (f"{int(v)}, {g2(c('max_ulps_exact'))}" if v else "none (too costly)")
    fac = c("M_facets")
    L.append(f"| {n:,} | {'—' if fac is None else f'{int(fac):,}'} | {fmt_t(ns(p))} "
             f"| {fmt_t(ns(f'sigma_d/dk/{n}'))} | {fmt_t(ns(f'sigma_d/expand/{n}'))} | {fmt_t(ns(s))} "
             f"| {fmt_r(ns(s), ns(p))} "
             f"| {fmt_t(None if c('hull_ms') is None else c('hull_ms') * 1e6)} "
             f"| {fmt_t(None if c('facets_ms') is None else c('facets_ms') * 1e6)} | {ex} "
             f"| {g2(c('max_diff_scan'))} |")

# σ, σ_d (DK) and σ_d (expansion) on the same queries: real hulls, generated sizes, hard inputs.
groups = [("hulls", "shared hulls"), ("small", "n = m"), ("small16", "m = 16"), ("hard", "hard")]
rows = []
for g, label in groups:
    keys = sorted({n.rsplit("/", 1)[1] for n in runs if n.startswith(f"{g}/sigma/")},
                  key=lambda k: (not k.isdigit(), int(k) if k.isdigit() else 0, k))
    for k in keys:
        rows.append((g, label, k))
if rows:
    L.append("")
    L.append("| input | \\|P\\| | \\|Q\\| | σ | σ_d DK | σ_d expansion | expansion / σ | DK / expansion "
             "| supports σ / σ_d | σ_d work mean / max (max share of budget) | max ulp DK vs expansion |")
    L.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for g, label, k in rows:
        a, b, e = f"{g}/sigma/{k}", f"{g}/sigma_d_dk/{k}", f"{g}/sigma_d_expand/{k}"
        c = lambda key: counter(e, key)
        name = f"{label} {k}" if g != "hulls" else "shared hulls (60 pairs)"
        pv, qv = c("P_vertices"), c("Q_vertices")
        wm, wx, share = c("work_mean"), c("work_max"), c("budget_share_max")
        work = "—" if wm is None else f"{wm:.0f} / {wx:.0f} ({share:.2f})"
        sup = "—" if c("supports_sigma") is None else f"{c('supports_sigma'):.1f} / {c('supports_expand'):.1f}"
        L.append(f"| {name} | {'—' if pv is None else f'{pv:.0f}'} | {'—' if qv is None else f'{qv:.0f}'} "
                 f"| {fmt_t(ns(a))} | {fmt_t(ns(b))} | {fmt_t(ns(e))} | {fmt_r(ns(e), ns(a))} "
                 f"| {fmt_r(ns(b), ns(e))} | {sup} | {work} | {g2(c('max_ulps_dk_vs_expand'))} |")
    L.append("")
    L.append("Median CPU time per query, the same placements and directions for the three columns. "
             "\\|P\\|, \\|Q\\|: mean hull vertices. expansion / σ < 1: σ_d faster than σ.")

# Signed distance and shape cast of disjoint real hulls (issue 16): distance/<impl>/hulls, cast/<impl>/hulls.
dist_impls = [("distance", "pendepth", "pendepth (exact)"),
              ("distance", "pendepth_exact", "pendepth, exact GJK loop only (before the fast path)"),
              ("distance", "bullet_gjk", "Bullet `btGjkPairDetector`"),
              ("distance", "bullet_gjk2", "Bullet `btGjkEpaSolver2::Distance`"), ("distance", "fcl_ccd", "FCL (libccd GJK)"),
              ("distance", "fcl_indep", "FCL (own GJK)"), ("cast", "pendepth", "pendepth (exact)"),
              ("cast", "bullet_gjk", "Bullet `btGjkConvexCast`")]
if any(n.startswith("distance/") or n.startswith("cast/") for n in runs):
    L.append("")
    L.append("| query | implementation | CPU µs / query | time / pendepth | failures | max \\|error\\| | max rel. error |")
    L.append("|---|---|---:|---:|---:|---:|---:|")
    for q, k, label in dist_impls:
        name = f"{q}/{k}/hulls"
        if not ok(name):
            continue
        c = lambda key: counter(name, key)
        L.append(f"| {q} | {label} | {fmt_t(ns(name))} | {fmt_r(ns(name), ns(f'{q}/pendepth/hulls'))} "
                 f"| {g2(c('failures'))} | {g2(c('err_max'))} | {g2(c('rel_err_max'))} |")

finish(md_path, L, res.errors(), f"{res.run_line()}, library build {res.library_build()}.")
