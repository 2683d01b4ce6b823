"""Speed of the apps with an outside view or texture filtering: ``python -m interp.bench_outside``.

For each app it times one slider step (pitch) as a live app takes it: the figure's ``update``,
then a blitted redraw with Agg (as :class:`interp.apps._blit.Blitter` does), and, apart, the
whole-figure PNG frame sent to the browser (as ipympl writes it). Beside each app that extends an
older one (the checkerboards and the clipping app with the outside view) it times the older app
in the same rounds, interleaved, so that a busy machine slows both alike; and it times the
outside view's own share of the step (its ``redraw``, inside the step). The texture-filtering
app is set beside lesson 6's checkerboard app, whose filtered/nearest switch it teaches. Target:
the outside view or the filtering panels add at most 30 ms to a step. Medians of repeated
steps, after warming up.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from interp.bench import png_frame

#: The most the outside view or the filtering panels may add to a slider step, in ms.
ADDED_TARGET_MS = 30.0


class _Stepper:
    """One app, stepped between two pitches, its times kept."""

    def __init__(self, figure_class: type) -> None:
        from interp.apps._app import App

        self.app = App(figure_class)
        self.app.blitter.draw()
        start = float(self.app.values["pitch"])
        self.pitches = [start, start + 1.0]
        self.times: dict[str, list[float]] = {
            name: [] for name in ("compute", "blit", "frame", "own", "cpu")
        }
        self.steps = 0
        outside = getattr(self.app.plot, "outside", None)
        if outside is not None:  # time the outside view's own redraw, inside the step
            redraw = outside.redraw

            def timed() -> None:
                start = time.perf_counter()
                redraw()
                self._own += time.perf_counter() - start

            outside.redraw = timed
        self._own = 0.0

    def step(self, keep: bool) -> None:
        self._own = 0.0
        self.steps += 1
        t0, c0 = time.perf_counter(), time.process_time()
        self.app.plot.update(pitch=self.pitches[self.steps % 2])
        t1 = time.perf_counter()
        self.app.blitter.draw()
        t2, c2 = time.perf_counter(), time.process_time()
        png_frame(np.asarray(self.app.figure.canvas.buffer_rgba()))
        t3 = time.perf_counter()
        if keep:
            for name, seconds in zip(
                ("compute", "blit", "frame", "own", "cpu"),
                (t1 - t0, t2 - t1, t3 - t2, self._own, c2 - c0),
                strict=True,
            ):
                self.times[name].append(seconds)

    def ms(self) -> dict[str, float]:
        times = {name: 1e3 * float(np.median(t)) for name, t in self.times.items()}
        steps = np.add(self.times["compute"], self.times["blit"])
        times["step"] = 1e3 * float(np.median(steps))
        return times


def measure(figure_classes: dict[str, type], repeat: int) -> dict[str, dict[str, float]]:
    """Median ms per app (compute, blit, step = both, frame, the outside view's own share),
    the apps stepped in turn, ``repeat`` rounds after two to warm up."""
    import matplotlib

    matplotlib.use("agg")
    steppers = {label: _Stepper(figure_class) for label, figure_class in figure_classes.items()}
    for k in range(repeat + 2):
        for stepper in steppers.values():
            stepper.step(keep=k >= 2)
    return {label: stepper.ms() for label, stepper in steppers.items()}


def lines(repeat: int) -> list[str]:
    from interp.plots import registry

    apps = {
        "checkerboards": registry.Checkerboards,
        "checkerboards + outside view": registry.CheckerboardsOutside,
        "clipping": registry.Clipping,
        "clipping + outside view": registry.ClippingOutside,
        "outside view alone": registry.OutsideViewFigure,
        "texture filtering": registry.TextureFiltering,
    }
    ms = measure(apps, repeat)
    out = []
    for label, t in ms.items():
        line = (
            f"{label:29s} step {t['step']:5.1f} ms (compute {t['compute']:5.1f}, blit "
            f"{t['blit']:5.1f}; CPU {t['cpu']:5.1f}); PNG frame {t['frame']:5.1f} ms"
        )
        if "+" in label:
            line += (
                f"\n{'':29s} adds {_added(t, ms[label.split(' +')[0]])} to the step without it; "
                f"the outside view's own redraw {t['own']:4.1f} ms"
            )
        if label == "texture filtering":  # a new app: beside lesson 6's, whose filter it teaches
            line += f"\n{'':29s} {_added(t, ms['checkerboards'])} against the checkerboard app"
        out.append(line)
    return out


def _added(times: dict[str, float], base: dict[str, float]) -> str:
    """What one app's step costs more than another's, against :data:`ADDED_TARGET_MS`."""
    added, added_cpu = times["step"] - base["step"], times["cpu"] - base["cpu"]
    verdict = "ok" if added <= ADDED_TARGET_MS else "over"
    return f"{added:+5.1f} ms (CPU {added_cpu:+5.1f}; target {ADDED_TARGET_MS:.0f}: {verdict})"


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(prog="python -m interp.bench_outside", description=__doc__)
    parser.add_argument("--repeat", type=int, default=15, help="rounds (default 15)")
    args = parser.parse_args(argv)
    print("\n".join(lines(args.repeat)))


if __name__ == "__main__":
    main()
