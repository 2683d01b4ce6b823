"""What happens after a slider is let go: the kernel's log of values and frames, and the page's
decodes and pictures, around the mouse-up of each of several drags of lesson 6's checkerboards.

``.venv/bin/python docs/bench-results/after-release/after-release.py [DRAGS] [RATIO]``
(defaults 6 and 2: a HiDPI screen). The drags are the benchmark's (``tests/bench_browser.py``:
a move each animation frame for 3 s, back and forth on the pitch slider, 40 px each way, less
where the track ends sooner, each from the same place: the handle is put back between drags).
All times are ms after the page's pointerup, on one clock (the kernel's ``time.time()`` and
the page's ``performance.timeOrigin + performance.now()``, on the same machine): the kernel's
log of values, of the release message (``interp_released``, sent only on a screen of ratio
above 1), of each ``refresh`` (computing and drawing a value), each frame drawn (with its
ratio) and each frame sent; the page's decodes started and done, and its pictures.
Environment: ``TREE=DIR`` measures another checkout (its lessons and its ``interp``, as the
benchmark's ``--tree``).
"""

import argparse
import json
import os
import statistics
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "tests"))

import bench_browser as bb  # noqa: E402
from browser import (  # noqa: E402
    FRAME_PROBE,
    app_root,
    chromium,
    figure_canvas,
    kernel_run,
    open_lesson,
    server,
    shutdown_kernels,
    slider_for,
)
from playwright.sync_api import sync_playwright  # noqa: E402

NAME = "checkerboards_outside"

#: Run in the kernel: log every value the pitch slider brings, every refresh, every frame the
#: app draws (with the ratio it is drawn at) and sends, every sharpening, and the page's release
#: message; times by ``time.time()``, the clock the page's times are put on.
LOG = r"""
import time
_app = Out[%d]; _canvas = _app.figure.canvas; LOG = []
def _logged(owner, attr, tag, info=lambda *a, **k: ""):
    inner = getattr(owner, attr)
    def outer(*a, **k):
        t = time.time(); result = inner(*a, **k)
        LOG.append((t, time.time(), tag, info(*a, **k))); return result
    setattr(owner, attr, outer)
_logged(_app, "_draw_frame", "frame",
        lambda following: f"ratio {_app._frame_ratio(following)} pitch {_app.values['pitch']}")
_logged(_app, "_sharpen", "sharpen")
_logged(_app, "refresh", "refresh")
_logged(_canvas, "send_binary", "send")
_logged(_canvas, "handle_interp_released", "released")
_app.controls["pitch"].observe(
    lambda change: LOG.append((time.time(), time.time(), "value", change["new"])),
    names="value")
"""

#: Print the log from 120 ms before the page's pointerup (``UP``, seconds since the epoch, set
#: first), and clear it.
DUMP = r"""
import json
_t0 = UP
print(json.dumps([(round((a - _t0) * 1e3, 1), round((b - a) * 1e3, 1), tag, str(i))
                  for a, b, tag, i in LOG if a > _t0 - 0.12]))
LOG.clear()
"""

PAGE = """(c) => {
  const up = window.__probe.lastInput('pointerup');
  const since = (list) => list.filter(e => e.t > up - 30).map(e => Math.round(e.t - up));
  return {up: performance.timeOrigin + up, decodes: since(window.__probe.decodes),
          done: since(window.__decoded), pictures: since(window.__probe.of(c))};
}"""

#: Run in the page before its scripts: when each ``ImageDecoder`` decode is done.
DECODED = """(() => {
  window.__decoded = [];
  if (!window.ImageDecoder) return;
  const decode = ImageDecoder.prototype.decode;
  ImageDecoder.prototype.decode = function (...args) {
    return decode.apply(this, args).then((result) => {
      window.__decoded.push({t: performance.now()});
      return result;
    });
  };
})();"""


def main() -> None:
    drags = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    ratio = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
    tree = Path(os.environ.get("TREE", ROOT))
    settles = []
    with tempfile.TemporaryDirectory() as tmp, server("lab", Path(tmp), tree=tree) as base:
        with sync_playwright() as playwright:
            browser = chromium(playwright)
            context = browser.new_context(viewport=bb.VIEWPORT, device_scale_factor=ratio)
            context.add_init_script(FRAME_PROBE)
            context.add_init_script(DECODED)
            page = bb.new_page(context)
            counts = open_lesson(page, base, "06_checkerboards.ipynb", drawn_within=10)
            kernel_run(page, LOG % counts[NAME])
            root = app_root(page, NAME)
            slider = slider_for(root, bb.figure_param(NAME, "pitch").label)
            slider.scroll_into_view_if_needed()
            canvas = figure_canvas(root).element_handle()
            args = argparse.Namespace(seconds=3.0, drag="page")
            print(f"{tree}, device pixel ratio {ratio}")
            centre, amplitude = bb.slider_drag(slider)  # as the benchmark's drags
            for k in range(drags):
                if k:  # the last drag let go at centre + amplitude
                    bb.put_back(page, (centre[0] + amplitude, centre[1]), centre)
                row = bb.measured_drag(page, canvas, centre, amplitude, args)
                seen = page.evaluate(PAGE, canvas)
                dump = f"UP = {seen['up'] / 1e3!r}\n" + DUMP
                log = json.loads(kernel_run(page, dump).strip().splitlines()[-1])
                settles.append(row["settle_ms"])
                print(
                    f"drag {k}: settle {row['settle_ms']:.0f} ms, "
                    f"{row['frames_after_release']} pictures after mouse-up, "
                    f"{row['fps']:.1f} pictures/s in the drag"
                )
                print(
                    f"  page: decodes started at {seen['decodes']}, done {seen['done']}, "
                    f"pictures at {seen['pictures']}"
                )
                for t, took, tag, info in log:
                    spent = f"took {took}" if took else ""
                    print(f"  kernel {t:7.1f} ms  {tag:8s} {info:24s} {spent}")
            print(
                f"settle, ms: {sorted(round(s) for s in settles)}, median "
                f"{statistics.median(settles):.0f}"
            )
            shutdown_kernels(page)


if __name__ == "__main__":
    main()
