"""Kept backgrounds (44e6b70), in a kernel alone.

Sweep a slider up and down twice, in steps, with ``KEPT_BACKGROUNDS`` at 0 (one background, as
before) and at its value, interleaved; print the full redraws and the step times (update and
blit). Run from the repository root: ``.venv/bin/python
docs/bench-results/echo-and-throttle/kept-backgrounds-kernel.py``.
"""

import time

import matplotlib
import numpy as np

matplotlib.use("module://ipympl.backend_nbagg")

import interp.apps._live as live
from interp.apps import ALL

#: (app, slider, low, high, step) of each sweep.
SWEEPS = (
    ("checkerboards_outside", "pitch", 5, 60, 1.0),
    ("approximations", "pitch", 5, 60, 1.0),
    ("st_mapping", "w2", 1, 10, 0.2),
)


def sweep(name: str, param: str, low: float, high: float, step: float) -> None:
    """Time one app's sweep and print a line."""
    app = ALL[name]()
    app.figure.canvas.syncing_data_url = False  # as when a page shows it
    app.blitter.draw()
    up = list(np.arange(low, high, step))
    times = []
    for value in up + up[::-1] + up + up[::-1]:
        start = time.perf_counter()
        app.plot.update(**{param: float(value)})
        app.blitter.draw()
        times.append(time.perf_counter() - start)
    ms = 1e3 * np.array(times)
    print(
        f"{name:22s} kept={live.KEPT_BACKGROUNDS:<9d} steps {len(ms)} "
        f"full {app.blitter.full_draws:3d}  median {np.median(ms):.1f}  "
        f"p90 {np.percentile(ms, 90):.1f}  max {ms.max():.1f}  total {ms.sum():.0f} ms"
    )


def main() -> None:
    kept = live.KEPT_BACKGROUNDS
    for setting in (0, kept, 0, kept):
        live.KEPT_BACKGROUNDS = setting
        for args in SWEEPS:
            sweep(*args)


if __name__ == "__main__":
    main()
