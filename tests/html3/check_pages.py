#!/usr/bin/env python3
"""The 3D HTML view in a real browser (issue 21; ctest label `browser`).

Writes pages with `pendepth depth ... --html` for the answers a view must survive (σ, σ_d, complete
separation, touching, not overlapping, a flat-ish shape, rotations, 1e200 and 1e-200 scales, a
pose beyond the double range),
checks that each page is self-contained and its scene JSON finite and normalised, opens it in
headless Chromium (WebGL in software: SwiftShader), reads the page's status marker from the DOM
(`data-pendepth-status="ok"`, set after the first frame; any script error sets "error") and checks
the screenshot is a picture: enough non-background pixels, many colours, coloured shapes.

  check_pages.py --pendepth BIN --data DIR --work DIR   the test (exit 77 = skipped: no Chromium)
  check_pages.py --shot PAGE.html OUT.png [--show M]    a screenshot (docs/images/demo3d.png)
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

WIDTH, HEIGHT = 1100, 720
PANEL = 346           # the page's panel column (viewer/template.html), not part of the 3D view
BACKGROUND = (0xf3, 0xf4, 0xf6)


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def browser(args, page, show=None):
    """Runs headless Chromium on a page; returns stdout (e.g. the DOM with --dump-dom)."""
    url = "file://" + os.path.abspath(page) + ("#show=" + show if show else "")
    with tempfile.TemporaryDirectory(prefix="pendepth-chromium-") as profile:
        cmd = [chromium(), "--headless", "--no-sandbox", "--disable-gpu-sandbox",
               "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
               "--hide-scrollbars", "--no-first-run", "--disable-extensions",
               "--user-data-dir=" + profile, "--window-size=%d,%d" % (WIDTH, HEIGHT),
               "--virtual-time-budget=10000"] + args + [url]
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    return r.stdout


def load(page, png, show=None):
    """Opens a page once: writes its screenshot to png, returns (status marker, error text)."""
    if os.path.exists(png):
        os.remove(png)
    dom = browser(["--screenshot=" + os.path.abspath(png), "--dump-dom"], page, show)
    if not os.path.exists(png):
        raise AssertionError("%s: Chromium wrote no screenshot" % page)
    m = re.search(r'<body[^>]*data-pendepth-status="([^"]*)"', dom)
    error = re.search(r'<div id="error">([^<]*)</div>', dom)
    return (m.group(1) if m else "missing"), (error.group(1) if error else "")


def scene_of(page):
    text = open(page, encoding="utf-8").read()
    if re.search(r'<(script|link|img)[^>]+(src|href)=', text):
        raise AssertionError("%s: loads an external resource" % page)
    m = re.search(r'<script id="pendepth-scene" type="application/json">(.*?)</script>', text, re.S)
    if not m:
        raise AssertionError("%s: no scene block" % page)

    def reject(c):
        raise AssertionError("%s: scene JSON holds %s" % (page, c))
    return json.loads(m.group(1), parse_constant=reject)


def check_scene(page, scene):
    coords = []
    for mesh in scene["meshes"]:
        coords += mesh["vertices"]
    for p in scene["points"]:
        coords += p["at"]
    for a in scene["arrows"]:
        coords += a["from"] + a["to"]
    bad = [x for x in coords if not math.isfinite(x) or abs(x) > 1.0001]
    if bad:
        raise AssertionError("%s: view coordinates outside [-1, 1]: %s" % (page, bad[:5]))
    if max(abs(x) for x in coords) < 0.49:
        raise AssertionError("%s: scene not normalised (largest coordinate %g)" % (page, max(map(abs, coords))))


def check_picture(png, name):
    from PIL import Image
    img = Image.open(png).convert("RGB")
    view = img.crop((PANEL, 0, img.width, img.height))
    counts = view.getcolors(maxcolors=view.width * view.height)  # [(count, (r, g, b))]
    n = view.width * view.height

    def share(keep):
        return sum(c for c, p in counts if keep(p))
    drawn = share(lambda p: max(abs(p[i] - BACKGROUND[i]) for i in range(3)) > 12)
    colours = len(counts)
    blue = share(lambda p: p[2] > p[0] + 40)                    # P
    red = share(lambda p: p[0] > p[2] + 40 and p[0] > p[1] + 25)  # Q (and the amber highlight)
    facts = "drawn %.1f%%, %d colours, blue %.1f%%, red %.1f%%" % (100 * drawn / n, colours, 100 * blue / n, 100 * red / n)
    # Not "blue and red": a highlighted face may cover all of P that shows (the flat case).
    saturated = share(lambda p: max(p) - min(p) > 40)
    if drawn < 0.03 * n or colours < 24 or saturated < 0.01 * n:
        raise AssertionError("%s: the screenshot looks blank or incomplete (%s)" % (name, facts))
    return facts


def cube(h=1.0, scale=1.0, z=1.0):
    return [(scale * x, scale * y, scale * z * c) for x in (-h, h) for y in (-h, h) for c in (-h, h)]


def write_off(path, points):
    with open(path, "w") as f:
        f.write("OFF\n%d 0 0\n" % len(points))
        for p in points:
            f.write("%r %r %r\n" % p)
    return path


def cases(data, work):
    hexp, ico = os.path.join(data, "hex_prism.off"), os.path.join(data, "icosahedron.obj")
    unit = write_off(os.path.join(work, "cube.off"), cube(0.5))
    slab = write_off(os.path.join(work, "slab.off"), cube(1.0, 1.0, 1e-9))  # flat-ish: 2 × 2 × 2e-9
    huge = write_off(os.path.join(work, "huge.off"), cube(0.5, 1e200))
    tiny = write_off(os.path.join(work, "tiny.off"), cube(0.5, 1e-200))
    edge = write_off(os.path.join(work, "edge.off"), cube(1.5, 1e308))  # ±1.5e308: Q + t overflows
    rot = ["--rotate-q", "0.95,0.1,0.2,0.2"]
    return [
        ("sigma", [hexp, ico, "--offset", "1.2,0.5,1.9"] + rot, "M"),
        ("sigma_d", [hexp, ico, "--offset", "1.2,0.5,1.9", "--direction", "1,0.3,0.2"] + rot, "M"),
        ("separation", [hexp, ico, "--offset=-0.5,0,1", "--direction", "0,0,-1", "--separate",
                        "--rotate-p", "0.9,0,0,0.3"], None),
        ("touching", [unit, unit, "--offset", "1,0,0"], "M"),
        ("apart", [unit, unit, "--offset", "3,0.5,0"], None),
        ("flat", [slab, unit, "--offset", "0.3,0.2,0.4"], "M"),
        ("huge", [huge, huge, "--offset", "5e199,2e199,1e199"], "M"),
        ("tiny", [tiny, tiny, "--offset", "5e-201,2e-201,1e-201", "--direction", "0,0,1"], "M"),
        ("overflow", [edge, edge, "--offset", "1e308,0,0"], None),
    ]


def run_tests(a):
    if not chromium():
        print("SKIPPED: no chromium (scripts/setup.sh installs Debian's chromium)")
        return 77
    os.makedirs(a.work, exist_ok=True)
    failures = 0
    for name, args, show in cases(a.data, a.work):
        page = os.path.join(a.work, name + ".html")
        try:
            r = subprocess.run([a.pendepth, "depth"] + args + ["--html", page], capture_output=True, text=True)
            if r.returncode != 0:
                raise AssertionError("%s: pendepth exit %d: %s" % (name, r.returncode, r.stderr.strip()))
            check_scene(page, scene_of(page))
            for layers in [None] + ([show] if show else []):
                label = name + ("#show=" + layers if layers else "")
                png = os.path.join(a.work, name + ("_" + layers if layers else "") + ".png")
                status, error = load(page, png, layers)
                if status != "ok":
                    raise AssertionError("%s: page status '%s' %s" % (label, status, error))
                print("ok   %-22s %s" % (label, check_picture(png, label)))
        except (AssertionError, subprocess.TimeoutExpired, KeyError, ValueError) as e:
            failures += 1
            print("FAIL %s" % e)
    # A 2D shape with --html is bad input, as --svg is for 3D.
    wkt = os.path.join(a.data, "hexagon.wkt")
    r = subprocess.run([a.pendepth, "depth", wkt, wkt, "--html", os.path.join(a.work, "2d.html")],
                       capture_output=True, text=True)
    if r.returncode != 2 or "--html" not in r.stderr:
        failures += 1
        print("FAIL 2D --html: exit %d, stderr %r" % (r.returncode, r.stderr))
    else:
        print("ok   2D --html rejected: %s" % r.stderr.strip())
    print("%d failure(s)" % failures)
    return 1 if failures else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--pendepth")
    p.add_argument("--data")
    p.add_argument("--work")
    p.add_argument("--shot", nargs=2, metavar=("PAGE", "PNG"))
    p.add_argument("--show", help="layers to show besides the default ones, e.g. M")
    a = p.parse_args()
    if a.shot:
        if not chromium():
            sys.exit("no chromium (scripts/setup.sh installs it)")
        status, error = load(a.shot[0], a.shot[1], a.show)
        if status != "ok":
            sys.exit("%s: page status '%s' %s" % (a.shot[0], status, error))
        print("%s: %s" % (a.shot[1], check_picture(a.shot[1], a.shot[0])))
        return 0
    if not (a.pendepth and a.data and a.work):
        p.error("--pendepth, --data and --work are required")
    return run_tests(a)


if __name__ == "__main__":
    sys.exit(main())
