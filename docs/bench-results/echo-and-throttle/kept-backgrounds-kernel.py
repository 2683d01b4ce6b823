"""Kept backgrounds (44e6b70), in a kernel alone: sweep a slider up and down twice, in
steps, with KEPT_BACKGROUNDS at 0 (one background, as before) and at its value, interleaved;
print the full redraws and the step times (update and blit). Run from the repository root with
.venv/bin/python."""
import sys, time
import numpy as np
import matplotlib
matplotlib.use("module://ipympl.backend_nbagg")
import interp.apps._live as live
from interp.apps import ALL
for kept in (0, live.KEPT_BACKGROUNDS, 0, live.KEPT_BACKGROUNDS):
    live.KEPT_BACKGROUNDS = kept
    for name, param, lo, hi, step in (("checkerboards_outside", "pitch", 5, 60, 1.0), ("approximations", "pitch", 5, 60, 1.0), ("st_mapping", "w2", 1, 10, 0.2)):
        app = ALL[name](); c = app.figure.canvas; c.syncing_data_url = False; app.blitter.draw()
        up = list(np.arange(lo, hi, step)); path = up + up[::-1] + up + up[::-1]
        times = []
        for v in path:
            t = time.perf_counter(); app.plot.update(**{param: float(v)}); app.blitter.draw(); times.append(time.perf_counter() - t)
        t = 1e3 * np.array(times)
        print("%-22s kept=%-9d steps %d full %3d  median %.1f  p90 %.1f  max %.1f  total %.0f ms" % (name, kept, len(t), app.blitter.full_draws, np.median(t), np.percentile(t, 90), t.max(), t.sum()))
