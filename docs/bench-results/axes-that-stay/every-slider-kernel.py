"""Every slider of every app, stepped in a kernel alone: full redraws and step times (ms).

Each slider 24 steps up from its default (down where there is no room), back, and to its
default again; a drop-down through its options three times. It measures the ``interp`` of
the checkout it is in (a worktree's copy measures that worktree):
``.venv/bin/python docs/bench-results/axes-that-stay/every-slider-kernel.py [APP ...]``.
"""

import sys
import time
from pathlib import Path

import matplotlib
import numpy as np

matplotlib.use("module://ipympl.backend_nbagg")
# The interp of the checkout this file is in (not the one the environment installed).
sys.path.insert(0, str(Path(__file__).resolve().parents[3]))
import ipywidgets as widgets

from interp.apps import ALL

STEPS = 24
only = sys.argv[1:]
for name, make in ALL.items():
    if only and name not in only:
        continue
    app = make()
    app.figure.canvas.syncing_data_url = False
    app.blitter.draw()
    for pname, w in app.controls.items():
        if isinstance(w, widgets.Dropdown):
            values = [o for o in w.options if o != w.value] + [w.value]
            values = values * 3
        else:
            step = w.step
            lo, hi = w.min, w.max
            v0 = w.value
            vals = []
            if isinstance(w, widgets.FloatLogSlider):
                cur = np.log10(v0)
                path = [cur + k * step for k in range(1, STEPS + 1)]
                if path[-1] > hi:
                    path = [cur - k * step for k in range(1, STEPS + 1)]
                path = [min(max(p, lo), hi) for p in path]
                vals = [10**p for p in path]
            else:
                path = [v0 + k * step for k in range(1, STEPS + 1)]
                if path[-1] > hi:
                    path = [v0 - k * step for k in range(1, STEPS + 1)]
                vals = [type(v0)(min(max(p, lo), hi)) for p in path]
            values = vals + vals[::-1][1:] + [v0]
        full0 = app.blitter.full_draws
        times = []
        for v in values:
            t = time.perf_counter()
            app.plot.update(**{**app.values, pname: v})
            app.blitter.draw()
            times.append(1e3 * (time.perf_counter() - t))
        # put back
        app.plot.update(**app.values)
        app.blitter.draw()
        ms = np.array(times)
        print(
            f"{name:22s} {pname:14s} steps {len(ms):3d} full {app.blitter.full_draws - full0:3d}  "
            f"median {np.median(ms):5.1f}  p90 {np.percentile(ms, 90):5.1f}  max {ms.max():5.1f}",
            flush=True,
        )
