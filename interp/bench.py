"""Benchmark: ``python -m interp.bench`` prints how fast the library is, beside real OpenGL.

For a ground plane of 512 triangles (16 x 16 quads) it times, at 256², 512² and 1024²:

- ``rasterize`` in perspective and affine mode (clip, scan-convert, depth-test, interpolate,
  spread into an image);
- the same draw on Mesa's llvmpipe through EGL, two ways, so nobody mistakes one for the other:
  *same contract* (draw, read both buffers back, and make the arrays ``rasterize`` returns:
  float64 values and a coverage mask) and *bare* (draw and read the raw colour buffer back);
- the ratio of ``rasterize`` to the same-contract llvmpipe (target: at most 1x at 512² with
  the C allocator as Python starts it, in both modes).

The three are measured interleaved (interp, llvmpipe, llvmpipe bare, interp, ...), so a busy
machine slows them alike. Then one slider step of the checkerboard lesson at 512² (both modes,
texture lookup, error map; target: at most 30 ms), and the lesson's live app at its default size
as the browser gets it: one slider step computed and blitted (target: at most 60 ms), and the
whole-figure PNG frame sent to the browser (written as ipympl writes it, with Pillow), timed on
its own (not with a second redraw). Times are medians of repeated runs.
"""

from __future__ import annotations

import argparse
import platform
import time
from collections.abc import Callable
from functools import partial

import numpy as np

import interp
from interp.scenes import checker_views

SIZES = (256, 512, 1024)
RATIO_TARGET = 1.0
STEP_TARGET_MS = 30.0
APP_TARGET_MS = 60.0


def png_frame(rgba: np.ndarray) -> bytes:
    """An RGBA image as the PNG file ipympl sends the browser for a frame (Pillow's defaults).

    Examples
    --------
    >>> png_frame(np.zeros((2, 3, 4), np.uint8))[:4]
    b'\\x89PNG'
    """
    import io

    from PIL import Image

    with io.BytesIO() as out:
        Image.fromarray(rgba).save(out, format="png")
        return out.getvalue()


def median_ms(run: Callable[[], object], repeat: int) -> float:
    """Median wall time of ``run()`` in milliseconds, after one warm-up call."""
    run()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return 1e3 * float(np.median(times))


def scene() -> interp.Scene:
    """The benchmark's scene: 512 triangles filling most of the view."""
    return interp.ground_plane(interp.Camera(height=1.0, pitch=20, yaw=30, distance=3.0))


def opengl_renderers() -> dict | None:
    try:
        from interp import opengl

        opengl.context()
    except (ImportError, RuntimeError) as error:
        print(f"(no OpenGL: {error})")
        return None
    return {
        (n, mode): opengl.Renderer(n, n, mode) for n in SIZES for mode in ("perspective", "affine")
    }


def interleaved_ms(runs: dict[str, Callable[[], object]], repeat: int) -> dict[str, float]:
    """Median wall time of each run in milliseconds, the runs taken in turn ``repeat`` times."""
    for run in runs.values():
        run()  # warm up
    times: dict[str, list[float]] = {name: [] for name in runs}
    for _ in range(repeat):
        for name, run in runs.items():
            start = time.perf_counter()
            run()
            times[name].append(time.perf_counter() - start)
    return {name: 1e3 * float(np.median(t)) for name, t in times.items()}


def table(
    gl: dict | None, repeat: int, with_app: bool = False, with_target: bool = False
) -> list[str]:
    s = scene()
    draw = partial(interp.rasterize, s.clip, s.uv, s.triangles)
    lines = [
        f"{'size':>6} {'mode':>12} {'interp ms':>10} {'llvmpipe ms':>12} {'ratio':>7} "
        f"{'llvmpipe bare ms':>17}"
    ]
    ratios = {}
    for n in SIZES:
        for mode in ("perspective", "affine"):
            runs: dict[str, Callable[[], object]] = {"interp": partial(draw, n, n, mode)}
            if gl is not None:
                renderer = gl[(n, mode)]

                def same_contract(renderer=renderer) -> object:
                    image = renderer.draw(s.clip, s.uv, s.triangles)
                    return image.values.astype(np.float64), image.covered

                def bare(renderer=renderer) -> bytes:
                    renderer.render(s.clip, s.uv, s.triangles)
                    return renderer._attribute.read()

                runs |= {"llvmpipe": same_contract, "bare": bare}
            ms = interleaved_ms(runs, repeat)
            if gl is None:
                lines.append(f"{n:>5}² {mode:>12} {ms['interp']:>10.2f} {'-':>12} {'-':>7}")
                continue
            ratio = ratios[(n, mode)] = ms["interp"] / ms["llvmpipe"]
            lines.append(
                f"{n:>5}² {mode:>12} {ms['interp']:>10.2f} {ms['llvmpipe']:>12.2f} "
                f"{ratio:>6.2f}x {ms['bare']:>17.2f}"
            )
    if with_target and ratios:
        at_512 = [ratios[(512, mode)] for mode in ("perspective", "affine")]
        verdict = "ok" if max(at_512) <= RATIO_TARGET else "over"
        lines.append(
            f"rasterize at 512² against llvmpipe, same contract: perspective {at_512[0]:.2f}x, "
            f"affine {at_512[1]:.2f}x (target at most {RATIO_TARGET:.0f}x: {verdict})"
        )
    subdivided = median_ms(partial(draw, 512, 512, "subdivided"), repeat)
    lines.append(f"{512:>5}² {'subdivided':>12} {subdivided:>10.2f}")
    for filtered in (True, False):
        step = median_ms(partial(checker_views, s, 512, 512, 8, filtered), repeat)
        texture = "filtered" if filtered else "nearest"
        verdict = "ok" if step <= STEP_TARGET_MS else "over"
        lines.append(
            f"slider step 512², both modes, {texture} texture, error map: {step:.1f} ms "
            f"(target {STEP_TARGET_MS:.0f} ms: {verdict})"
        )
    if with_app:
        lines.extend(app_lines(repeat))
    return lines


def app_lines(repeat: int) -> list[str]:
    """One slider step of the checkerboard app as a live canvas does it: compute, blit, and the
    PNG frame for the browser (timed on its own)."""
    import matplotlib

    matplotlib.use("agg")

    from interp import apps
    from interp.apps._blit import Blitter

    app = apps.checkerboards()
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    pitches = iter(np.tile([14.0, 16.0], 10_000))

    def step() -> None:
        app.set(pitch=next(pitches))
        blitter.draw()

    def frame() -> bytes:
        return png_frame(np.asarray(app.figure.canvas.buffer_rgba()))

    def full_redraw() -> None:
        app.set(pitch=next(pitches))
        app.figure.canvas.draw()

    size = app.values["resolution"]
    ms = interleaved_ms({"step": step, "frame": frame, "full": full_redraw}, repeat)
    verdict = "ok" if ms["step"] <= APP_TARGET_MS else "over"
    return [
        f"checkerboard app, {size} panels: slider step computed and blitted {ms['step']:.1f} ms "
        f"(target {APP_TARGET_MS:.0f} ms: {verdict}); PNG frame {ms['frame']:.1f} ms; "
        f"the same step with a full redraw instead of the blit {ms['full']:.1f} ms",
    ]


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(
        prog="python -m interp.bench",
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--repeat", type=int, default=15, help="runs per figure (default 15)")
    args = parser.parse_args(argv)
    gl = opengl_renderers()
    renderer = interp.opengl.renderer() if gl else "none"
    print(
        f"interp benchmark: {platform.python_implementation()} {platform.python_version()}, "
        f"numpy {np.__version__}, {platform.machine()}, OpenGL renderer: {renderer}"
    )
    print(f"scene: ground plane, {len(scene().triangles)} triangles; medians of {args.repeat} runs")
    print("\n".join(table(gl, args.repeat, with_target=True, with_app=True)))


if __name__ == "__main__":
    main()
