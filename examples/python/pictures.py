"""Pictures (2D, Python): pendepth.plot draws P, Q at t, Q after the move, and the configuration
panel (the no-fit polygon, t and the move). Writes out/python_plot.png (matplotlib, Agg)."""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pendepth  # noqa: E402

data = pathlib.Path(__file__).resolve().parent.parent / "data"
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path("out")
out.mkdir(parents=True, exist_ok=True)

P = pendepth.Shape2.from_file(str(data / "trousers_item0.wkt"))
Q = pendepth.Shape2.from_file(str(data / "trousers_item16.wkt"))
pair = pendepth.Pair2(P, Q)
fig, axes, r = pendepth.plot(pair, [8, 6], direction=[0, 1])
fig.savefig(out / "python_plot.png", dpi=80)
print(f"sigma_d = {r.depth!r} ({r.engine}); picture in {out / 'python_plot.png'}")

# Jupyter shows shapes and results as SVG (_repr_svg_).
svg = P._repr_svg_()
assert svg.startswith("<svg") and pair.minimum(np.array([8.0, 6.0]))._repr_svg_().startswith("<svg")
