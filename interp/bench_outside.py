"""Speed of issue 11's figures: ``python -m interp.bench_outside``.

For each new app it times one slider step as a live app takes it (the figure's ``update``, then
a blitted redraw with Agg, as :class:`interp.apps._live.Blitter` does) beside the app it
extends, so the difference is what the outside view or the filtering panels add (target: at
most 30 ms). Medians of repeated steps between two camera positions, after warming up.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from interp._allocator import keep_freed_memory

#: The most the outside view or the filtering panels may add to a slider step, in ms.
ADDED_TARGET_MS = 30.0


def step_times(figure_class: type, repeat: int, control: str = "pitch") -> dict[str, float]:
    """Median ms of a slider step of ``figure_class``'s app: compute (``update``), blit, both
    (wall time), and the process's CPU time for both (which other programs on a busy machine
    do not inflate)."""
    import matplotlib

    matplotlib.use("agg")
    from interp.apps._app import App

    app = App(figure_class)
    app.blitter.draw()
    start = float(app.values[control])
    values = [start, start + 1.0]
    compute, blit, cpu = [], [], []
    for k in range(repeat + 2):
        app.plot.update(**{control: values[k % 2]})
        t0, c0 = time.perf_counter(), time.process_time()
        app.plot.update(**{control: values[(k + 1) % 2]})
        t1 = time.perf_counter()
        app.blitter.draw()
        t2, c2 = time.perf_counter(), time.process_time()
        if k >= 2:
            compute.append(t1 - t0)
            blit.append(t2 - t1)
            cpu.append(c2 - c0)
    return {
        "compute": 1e3 * float(np.median(compute)),
        "blit": 1e3 * float(np.median(blit)),
        "step": 1e3 * float(np.median(np.add(compute, blit))),
        "cpu": 1e3 * float(np.median(cpu)),
    }


def lines(repeat: int) -> list[str]:
    from interp.plots import registry

    out = []
    pairs: list[tuple[str, type, type | None]] = [
        ("checkerboards + outside view", registry.CheckerboardsOutside, registry.Checkerboards),
        ("clipping + outside view", registry.ClippingOutside, registry.Clipping),
        ("outside view alone", registry.OutsideViewFigure, None),
        ("texture filtering", registry.TextureFiltering, None),
    ]
    for label, new, old in pairs:
        t = step_times(new, repeat)
        line = (
            f"{label:30s} step {t['step']:6.1f} ms (compute {t['compute']:5.1f}, "
            f"blit {t['blit']:5.1f}; CPU {t['cpu']:5.1f})"
        )
        if old is not None:
            base = step_times(old, repeat)
            added, added_cpu = t["step"] - base["step"], t["cpu"] - base["cpu"]
            verdict = "ok" if added <= ADDED_TARGET_MS else "over"
            line += (
                f"\n{'':30s} without it {base['step']:6.1f} ms (CPU {base['cpu']:5.1f}): adds "
                f"{added:5.1f} ms, CPU {added_cpu:5.1f} (target {ADDED_TARGET_MS:.0f}: {verdict})"
            )
        out.append(line)
    return out


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(prog="python -m interp.bench_outside", description=__doc__)
    parser.add_argument("--repeat", type=int, default=15, help="steps per figure (default 15)")
    args = parser.parse_args(argv)
    keep_freed_memory()  # as the live apps run
    print("\n".join(lines(args.repeat)))


if __name__ == "__main__":
    main()
