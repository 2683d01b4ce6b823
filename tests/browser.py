"""Real servers and a real browser for the browser tests: JupyterLab or Voilà on a free
localhost port with throwaway configuration, and Debian's Chromium driven by Playwright."""

from __future__ import annotations

import base64
import contextlib
import http.client
import io
import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--headless",  # Playwright adds it too (headless=True); said here for whoever reads the log
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
ARTIFACTS = ROOT / "test-artifacts"
SCREENSHOTS = ROOT / "docs" / "screenshots"


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _wait_for(url: str, process: subprocess.Popen, log: Path, seconds: float = 90) -> None:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if process.poll() is not None:
            raise RuntimeError(f"server exited:\n{log.read_text()[-3000:]}")
        with contextlib.suppress(OSError, http.client.HTTPException):
            with urllib.request.urlopen(url, timeout=2) as response:
                if response.status == 200:
                    return
        time.sleep(0.3)
    raise RuntimeError(f"server did not answer {url} in {seconds} s:\n{log.read_text()[-3000:]}")


def start_on_free_port(
    command_for: Callable[[int], list[str]], log: Path, env: dict, attempts: int = 3
) -> tuple[subprocess.Popen, int]:
    """Start the server ``command_for(port)`` on a free port (its own port retries off), and
    again on another if the port was taken before it bound it (by a kernel, say): (the
    process, its port), once it answers at ``http://127.0.0.1:{port}/``."""
    for _attempt in range(attempts):
        port = free_port()
        with log.open("w") as out:
            process = subprocess.Popen(
                command_for(port), env=env, stdout=out, stderr=subprocess.STDOUT
            )
        url = f"http://127.0.0.1:{port}/"
        try:
            _wait_for(url, process, log)
            return process, port
        except (RuntimeError, http.client.HTTPException):  # the port was taken: another
            process.kill()
    raise AssertionError(f"the server did not start:\n{log.read_text()[-2000:]}")


@contextlib.contextmanager
def server(
    kind: str,
    workdir: Path,
    notebook: str | None = None,
    env: dict[str, str] | None = None,
    tree: Path = ROOT,
) -> Iterator[str]:
    """Start ``jupyter lab`` or ``voila`` on a copy of the lessons; yield its base URL.

    ``env`` adds variables to the server's environment (and so its kernels'), e.g.
    ``{"INTERP_PRESENTATION": "1"}``. Voilà without ``notebook`` serves the whole folder:
    each lesson is then at ``/voila/render/NAME.ipynb``.

    ``tree`` is the checkout whose lessons are served and whose ``interp`` the kernels import
    (first on their PYTHONPATH, ahead of whatever ``interp`` the environment has installed):
    this one by default, so the tests test the code beside them; another checkout to measure
    that one (``tests/bench_browser.py --tree``).
    """
    lessons = workdir / "lessons"
    shutil.copytree(tree / "lessons", lessons)
    path = os.environ.get("PYTHONPATH", "")
    env = {
        **os.environ,
        **(env or {}),
        "PYTHONPATH": os.pathsep.join([str(tree), *([path] if path else [])]),
        "JUPYTER_CONFIG_DIR": str(workdir / "config"),
        "JUPYTER_RUNTIME_DIR": str(workdir / "runtime"),
        "JUPYTERLAB_WORKSPACES_DIR": str(workdir / "workspaces"),
        "JUPYTERLAB_SETTINGS_DIR": str(workdir / "settings"),
    }
    env.pop("MPLBACKEND", None)  # the notebooks choose their own backend
    settings = workdir / "settings" / "@jupyterlab" / "apputils-extension"
    settings.mkdir(parents=True)
    (settings / "notification.jupyterlab-settings").write_text(
        json.dumps({"fetchNews": "false", "checkForUpdates": False})
    )
    # No autosave: a page must not write its outputs (widget views of its kernel) into the
    # lessons, or the next page to open a lesson starts with dead widgets in it.
    documents = workdir / "settings" / "@jupyterlab" / "docmanager-extension"
    documents.mkdir(parents=True)
    (documents / "plugin.jupyterlab-settings").write_text(json.dumps({"autosave": False}))
    root = ["--allow-root"] if hasattr(os, "geteuid") and os.geteuid() == 0 else []
    for _attempt in range(5):
        # A free port can be taken (by another server, or a kernel) before the server binds
        # it; then it must fail rather than move to the next port, or the tests would talk to
        # whoever holds this one.
        port = free_port()
        if kind == "lab":
            command = [
                sys.executable,
                "-m",
                "jupyter",
                "lab",
                "--no-browser",
                f"--port={port}",
                "--ServerApp.port_retries=0",
                "--ServerApp.ip=127.0.0.1",
                "--IdentityProvider.token=",
                "--ServerApp.password=",
                f"--ServerApp.root_dir={lessons}",
                "--LabApp.expose_app_in_browser=True",
                *root,
            ]
            ready = f"http://127.0.0.1:{port}/api/status"
        else:
            command = [
                sys.executable,
                "-m",
                "voila",
                "--no-browser",
                f"--port={port}",
                "--Voila.port_retries=0",
                "--Voila.ip=127.0.0.1",
                str(lessons / notebook) if notebook else str(lessons),
            ]
            ready = f"http://127.0.0.1:{port}/"
        log = workdir / f"{kind}.log"
        with log.open("w") as out:
            process = subprocess.Popen(
                command, cwd=workdir, env=env, stdout=out, stderr=subprocess.STDOUT
            )
        try:
            _wait_for(ready, process, log)
            _wait_for_log(f"127.0.0.1:{port}/", process, log)  # ours answered, not another
            break
        except RuntimeError:
            stop(process)
    else:
        raise RuntimeError(f"no {kind} server started in 5 attempts:\n{log.read_text()[-3000:]}")
    try:
        yield f"http://127.0.0.1:{port}"
    finally:
        stop(process)


def _wait_for_log(text: str, process: subprocess.Popen, log: Path, seconds: float = 30) -> None:
    """Wait until the server's log says ``text`` (where it runs); fail if it exits first."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if text in log.read_text(errors="replace"):
            return
        if process.poll() is not None:
            raise RuntimeError(f"server exited:\n{log.read_text()[-3000:]}")
        time.sleep(0.2)
    raise RuntimeError(f"the server never said it runs at {text}:\n{log.read_text()[-3000:]}")


def stop(process: subprocess.Popen) -> None:
    """End a server: terminate, and kill it if it has not ended within 15 s."""
    process.terminate()
    try:
        process.wait(timeout=15)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


def sync_api():
    """Playwright's sync API. Without Playwright the browser tests are skipped, but not in CI
    (``CI`` set): there every browser test must run, so the import error is raised."""
    if os.environ.get("CI"):
        import playwright.sync_api

        return playwright.sync_api
    import pytest

    return pytest.importorskip("playwright.sync_api")


def need_chromium() -> None:
    """Skip the calling test without Chromium at :data:`CHROMIUM`; in CI, fail instead."""
    import pytest

    if not os.path.exists(CHROMIUM):
        if os.environ.get("CI"):
            pytest.fail(f"CI must have Chromium at {CHROMIUM} (apt-get install chromium)")
        pytest.skip(f"no Chromium at {CHROMIUM}")


def chromium(playwright):
    return playwright.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)


# ---------------------------------------------------------------- the apps in a lesson page
#
# What the page itself measures (tests/bench_browser.py and tests/test_browser_apps.py): an
# init script hooks ``drawImage`` on the 2D context of every ipympl figure canvas (the first
# <canvas> in ``.jupyter-matplotlib-canvas-div``: ipympl paints each new image into it with
# drawImage) and marks the canvas dirty; at the next animation frame (asked for then, not every
# frame: the probe must not keep the page drawing) it takes a snapshot of each dirty canvas
# (``createImageBitmap``) and records ``{t, h}``, ``t`` that frame's ``performance.now()`` and
# ``h`` a hash of the snapshot's pixels, whenever they differ from the last recorded frame. A
# worker hashes the snapshots, off the page's main thread: hashed there, they took 2.8 ms of it
# a picture at 820 x 474 and 8.2 ms at 1640 x 948 (a device pixel ratio of 2), in the frame
# about to be painted, which a student's page does not spend (the snapshot takes 0.1 ms).
# Where a page cannot start the worker, the probe hashes on the main thread as before. A frame
# is recorded a few ms after its time, in order. So a "frame" is a distinct picture as it is
# about to be painted, at most one per display frame; identical redraws are not counted. Input
# events (key and pointer) are recorded with their ``timeStamp``, on the same clock, and so is
# every ``toDataURL`` call, with the URL it made and whether ipympl's frame handler made it
# (``probe.dataUrls``, the last 40); and so is each frame decoded, with how
# (``probe.decodes``: an ``<img>`` given a blob URL, ``ImageDecoder`` or
# ``createImageBitmap``).

FRAME_PROBE = r"""
(() => {
  if (window.__probe) return;
  const probe = window.__probe = {frames: new Map(), dirty: new Set(), inputs: []};
  const isFigure = (c) => !!c && !!c.parentElement
      && c.parentElement.classList.contains('jupyter-matplotlib-canvas-div')
      && c === c.parentElement.firstElementChild;
  // A figure drawn into is looked at in the next animation frame, when what was drawn shows.
  // Only then: a callback every frame would keep the page drawing frames (and its compositor
  // and GPU process busy) while it waits, which a student's page does not do.
  let ticking = false;
  const drawImage = CanvasRenderingContext2D.prototype.drawImage;
  CanvasRenderingContext2D.prototype.drawImage = function (...args) {
    const result = drawImage.apply(this, args);
    if (isFigure(this.canvas)) {
      probe.dirty.add(this.canvas);
      if (!ticking) {
        ticking = true;
        requestAnimationFrame(tick);
      }
    }
    return result;
  };
  // FNV-1a over a 2D context's pixels: on the main thread (probe.hash), and in the worker below.
  const pixelHash = (context, width, height) => {
    const d = new Uint32Array(context.getImageData(0, 0, width, height).data.buffer);
    let h = 2166136261 ^ width ^ (height << 16);
    for (let i = 0; i < d.length; i++) h = Math.imul(h ^ d[i], 16777619);
    return h >>> 0;
  };
  probe.hash = (c) => (c.width && c.height ? pixelHash(c.getContext('2d'), c.width, c.height) : 0);
  // Snapshots waiting for their hash, per canvas in the order taken: each recorded (if its
  // picture is new) once it and every earlier one of its canvas are hashed.
  const waiting = new Map();
  const settle = (c) => {
    const queue = waiting.get(c);
    while (queue.length && queue[0].h !== undefined) {
      const {t, h} = queue.shift();
      probe.record(c, t, h);
    }
  };
  // Record that element c shows h (a picture's hash, or a label's text) from time t, if it
  // showed something else before, and tell whoever waits for it (probe.after): a benchmark
  // waiting does not poll the page in every animation frame (which would keep it drawing
  // frames a student's page does not draw).
  probe.waiters = new Set();
  probe.record = (c, t, h) => {
    let list = probe.frames.get(c);
    if (!list) probe.frames.set(c, list = []);
    if (list.length && list[list.length - 1].h === h) return;
    list.push({t, h});
    for (const w of [...probe.waiters]) if (w.c === c && t > w.t) w.done(t);
  };
  probe.after = (c, t, ms) => new Promise((resolve) => {
    const found = (probe.frames.get(c) || []).find((f) => f.t > t);
    if (found) return resolve(found.t);
    const w = {c, t, done: (at) => {
      probe.waiters.delete(w);
      clearTimeout(w.timer);
      resolve(at);
    }};
    w.timer = setTimeout(() => w.done(null), ms);
    probe.waiters.add(w);
  });
  let hasher = null;
  try {
    hasher = new Worker(URL.createObjectURL(new Blob([`
      const pixelHash = ${pixelHash};
      onmessage = ({data: {id, picture}}) => {
        const canvas = new OffscreenCanvas(picture.width, picture.height);
        const context = canvas.getContext('2d');
        context.drawImage(picture, 0, 0);
        picture.close();
        postMessage({id, h: pixelHash(context, canvas.width, canvas.height)});
      };`], {type: 'text/javascript'})));
  } catch (error) {
    hasher = null;  // e.g. a page whose content security policy forbids it
  }
  const byId = new Map();
  let serial = 0;
  // The page's own createImageBitmap, before the probe wraps it to count decodes (below): its
  // snapshots are not the frames' decodes.
  const snapshot = window.createImageBitmap.bind(window);
  if (hasher) {
    hasher.onmessage = ({data: {id, h}}) => {
      const entry = byId.get(id);
      byId.delete(id);
      entry.h = h;
      settle(entry.c);
    };
  }
  const tick = () => {
    const now = performance.now();
    for (const c of probe.dirty) {
      if (!waiting.has(c)) waiting.set(c, []);
      const entry = {c, t: now, h: undefined};
      waiting.get(c).push(entry);
      if (!hasher || !c.width || !c.height) {
        entry.h = probe.hash(c);
        settle(c);
        continue;
      }
      const id = ++serial;
      byId.set(id, entry);
      snapshot(c).then(
        (picture) => hasher.postMessage({id, picture}, [picture]),
        () => {
          byId.delete(id);
          entry.h = probe.hash(c);
          settle(c);
        });
    }
    probe.dirty.clear();
    ticking = false;
  };
  // When pictures of a canvas are encoded as data URLs (ipympl did it on every frame).
  probe.dataUrls = [];
  const toDataURL = HTMLCanvasElement.prototype.toDataURL;
  HTMLCanvasElement.prototype.toDataURL = function (...args) {
    const url = toDataURL.apply(this, args);
    // Called from within ipympl's handler of a new frame (its model's handle_binary)?
    const inFrame = /handle_binary/.test(new Error().stack || '');
    probe.dataUrls.push({t: performance.now(), url, inFrame});
    if (probe.dataUrls.length > 40) probe.dataUrls.shift();
    return url;
  };
  // How frames are decoded: <img> elements given a blob URL (ipympl's way), and decodes by
  // WebCodecs' ImageDecoder or createImageBitmap, with times.
  probe.decodes = [];
  const src = Object.getOwnPropertyDescriptor(HTMLImageElement.prototype, 'src');
  Object.defineProperty(HTMLImageElement.prototype, 'src', {
    ...src,
    set(value) {
      if (String(value).startsWith('blob:')) {
        probe.decodes.push({t: performance.now(), by: 'img'});
      }
      src.set.call(this, value);
    },
  });
  if (window.ImageDecoder) {
    const decode = ImageDecoder.prototype.decode;
    ImageDecoder.prototype.decode = function (...args) {
      probe.decodes.push({t: performance.now(), by: 'ImageDecoder'});
      return decode.apply(this, args);
    };
  }
  const createImageBitmap = window.createImageBitmap;
  window.createImageBitmap = function (...args) {
    probe.decodes.push({t: performance.now(), by: 'createImageBitmap'});
    return createImageBitmap.apply(this, args);
  };
  for (const type of ['keydown', 'pointerdown', 'pointermove', 'pointerup']) {
    window.addEventListener(type, (e) => probe.inputs.push({type, t: e.timeStamp}), true);
  }
  probe.of = (c) => probe.frames.get(c) || [];
  probe.last = (c) => { const l = probe.of(c); return l.length ? l[l.length - 1] : null; };
  probe.lastInput = (type) => {
    const found = probe.inputs.filter((e) => e.type === type);
    return found.length ? found[found.length - 1].t : null;
  };
})();
"""

#: The notebook JupyterLab shows (it keeps the others in the page, hidden).
VISIBLE = ".jp-NotebookPanel:not(.lm-mod-hidden)"

#: The notebook on show has a kernel that is connected and idle.
KERNEL_IDLE = """() => {
    const panel = window.jupyterapp && window.jupyterapp.shell.currentWidget;
    const kernel = panel && panel.sessionContext && panel.sessionContext.session
        && panel.sessionContext.session.kernel;
    return !!kernel && kernel.connectionStatus === 'connected' && kernel.status === 'idle';
}"""

#: Run code in the notebook's kernel, outside any cell; resolve to what it printed.
KERNEL_RUN = """async (code) => {
    const kernel = window.jupyterapp.shell.currentWidget.sessionContext.session.kernel;
    const future = kernel.requestExecute({code, silent: false, store_history: false});
    let out = '';
    future.onIOPub = (m) => {
        if (m.header.msg_type === 'stream') out += m.content.text;
        if (m.header.msg_type === 'error') out += '\\n!ERROR ' + m.content.evalue;
    };
    await future.done;
    return out;
}"""

#: A code cell that makes an app: ``apps.NAME()`` (an app of :data:`interp.apps.ALL`) or
#: ``apps.App(registry.CLASS)`` (a registry figure without an app function of its own).
APP_CELL = r"^apps\.(?:(\w+)\(\)|App\(registry\.(\w+)\))\s*$"

#: Each code cell of the notebook on show that makes an app: tag its output area with
#: ``data-app=NAME`` and return ``[name, execution count]``; an app a notebook makes again is
#: ``NAME@2``, ``NAME@3``... ``names`` maps what a cell calls
#: (an app function or a registry class) to the app's name (see :func:`app_name`).
TAG_APPS = """(names) => {
    const panel = window.jupyterapp.shell.currentWidget;
    const found = [], seen = {};
    panel.content.widgets.forEach((cell) => {
        if (cell.model.type !== 'code') return;
        const m = new RegExp(APP_CELL, 'm').exec(cell.model.sharedModel.getSource());
        if (!m) return;
        const base = names[m[1] || m[2]] || m[1] || m[2];
        seen[base] = (seen[base] || 0) + 1;
        const name = seen[base] === 1 ? base : base + '@' + seen[base];
        // The whole output area: an app's outputs are a script (naming the sliders), in
        // presentation mode a style, then the widget.
        const output = cell.node.querySelector('.jp-Cell-outputArea') || cell.node;
        output.setAttribute('data-app', name);
        found.push([name, cell.model.executionCount]);
    });
    return found;
}""".replace("APP_CELL", json.dumps(APP_CELL))

#: Python run in the kernel: the figure the cell's app (``Out[N]``) should show at its current
#: control values, drawn by a fresh app of the same kind, independently of the live canvas (a
#: plain Figure, no widget): a PNG as base64, at the live canvas's resolution. savefig draws
#: every artist, also those a live canvas blits (animated ones).
#:
#: ``constructed=False``: the fresh app is made as the lesson makes it, then its controls are
#: set to the live values as a slider does (App.set): so a difference from the live canvas
#: means the browser shows a stale, partial or broken picture. ``constructed=True``: the fresh
#: app is made with the live values as its defaults, so no update runs: a difference means an
#: update draws something else than a new app at the same values would.
TRUTH = """
import base64 as _b64, dataclasses as _dc, io as _io, json as _json
import matplotlib.pyplot as _plt
from matplotlib.figure import Figure as _Figure
from interp.plots.params import table as _table
_live = Out[{count}]
_values = dict(_live.values)
_kind = type(_live.plot)
if {constructed}:
    _params = {{k: _dc.replace(p, default=_values[k]) for k, p in _kind.PARAMS.items()}}
    _kind = type(_kind.__name__, (_kind,), {{"PARAMS": _table(**_params)}})
import interp.apps._app as _app_module
# Where the app makes its figure (pyplot, in a checkout measured with --tree that predates it).
_maker = ((_app_module, "new_figure") if hasattr(_app_module, "new_figure") else (_plt, "figure"))
_new_figure = getattr(*_maker)
setattr(*_maker, lambda *a, **k: _Figure(figsize=k.get("figsize", a[0] if a else None)))
try:
    _fresh = type(_live)(_kind)
finally:
    setattr(*_maker, _new_figure)
if _fresh.values != _values:
    _fresh.set(**_values)
_buf = _io.BytesIO()
_fresh.figure.savefig(_buf, format="png", dpi=_live.figure.dpi, bbox_inches=None,
                      facecolor=_fresh.figure.get_facecolor())
print(_json.dumps({{"values": {{k: str(v) for k, v in _values.items()}},
                   "png": _b64.b64encode(_buf.getvalue()).decode()}}))
del _live, _fresh, _kind, _buf, _app_module, _new_figure, _maker
"""

#: Python run in the kernel: where endpoint A of the cell's app is drawn, in CSS pixels from the
#: canvas's top left corner, and the top view's axes box (x, y, width, height).
ENDPOINT_A = """
import json as _json
_app = Out[{count}]
_view = _app.plot.view
_ratio = getattr(_app.figure.canvas, "device_pixel_ratio", 1.0)
_h = _app.figure.bbox.height
_px, _py = _view.ax.transData.transform((-_view.points["A"][1], _view.points["A"][0]))
_box = _view.ax.bbox
print(_json.dumps([_px / _ratio, (_h - _py) / _ratio,
                   [_box.x0 / _ratio, (_h - _box.y1) / _ratio, _box.width / _ratio,
                    _box.height / _ratio]]))
"""


#: Every app output on show has a figure canvas that has been drawn.
ALL_DRAWN = f"""() => Array.from(document.querySelectorAll('{VISIBLE} [data-app]')).every(o => {{
    const c = o.querySelector('.jupyter-matplotlib-canvas-div canvas');
    const frame = c && window.__probe.last(c);
    return !!frame && c.width > 0 && frame.h !== 0;
}})"""


def app_name(called: str) -> str:
    """The name of the app a cell makes, from what it calls: an app function's name as it is
    (``checkerboards``), a registry class by its figure's name with underscores
    (``LinearOnScreen`` -> ``linear_on_screen``). The names of :data:`interp.apps.ALL` follow
    the same rule, so an app has one name however a lesson makes it."""
    from interp.plots import registry

    figure = getattr(registry, called, None)
    if isinstance(figure, type) and issubclass(figure, registry.LessonFigure):
        return figure.name.replace("-", "_")
    return called


def app_names() -> dict[str, str]:
    """What cells may call -> the app's name, for :data:`TAG_APPS`."""
    from interp.plots import registry

    return {cls.__name__: app_name(cls.__name__) for cls in registry.FIGURES.values()}


def base_app(name: str) -> str:
    """The app an instance name is of: ``texture_filtering@2`` -> ``texture_filtering``."""
    return name.split("@")[0]


def figure_of(name: str):
    """The registry figure class an app draws (app names use underscores, figures hyphens)."""
    from interp.plots import registry

    return registry.FIGURES[base_app(name).replace("_", "-")]


def lesson_apps(notebook: str, folder: Path | None = None) -> list[str]:
    """The apps a lesson makes, in order (its cells that are just ``apps.NAME()`` or
    ``apps.App(registry.CLASS)``); one made again is ``NAME@2`` (as :data:`TAG_APPS` tags it)."""
    import re

    cells = json.loads(((folder or ROOT / "lessons") / notebook).read_text())["cells"]
    names: list[str] = []
    for cell in cells:
        if cell["cell_type"] == "code":
            for function, cls in re.findall(APP_CELL, "".join(cell["source"]), re.M):
                name = app_name(function or cls)
                made = sum(base_app(n) == name for n in names)
                names.append(name if not made else f"{name}@{made + 1}")
    return names


def lessons(tree: Path = ROOT) -> dict[str, list[str]]:
    """Every lesson notebook of ``tree`` that makes an app, and the apps it makes."""
    found = {}
    for path in sorted((tree / "lessons").glob("*.ipynb")):
        names = lesson_apps(path.name, path.parent)
        if names:
            found[path.name] = names
    return found


#: Python run in the kernel: where its ``interp`` comes from.
KERNEL_INTERP = "import interp, pathlib; print(pathlib.Path(interp.__file__).parent.parent)"


def kernel_interp(page) -> Path:
    """The checkout whose ``interp`` the kernel of the notebook on show imports."""
    return Path(kernel_run(page, KERNEL_INTERP).strip())


def open_lesson(
    page, base: str, notebook: str, file_browser: bool = False, drawn_within: float = 30
) -> dict[str, int]:
    """Open ``notebook`` in JupyterLab with a fresh kernel and a fresh workspace, Run All, wait
    until the kernel is idle again and every figure is drawn (at most ``drawn_within`` s);
    tag each app's output with ``data-app=NAME`` and return {app name: Out number}.

    The page needs :data:`FRAME_PROBE` (``context.add_init_script(FRAME_PROBE)``).
    """
    page.goto(f"{base}/lab/tree/{notebook}?reset")
    page.wait_for_selector(".jp-Notebook", timeout=60_000)
    page.wait_for_function(KERNEL_IDLE, timeout=90_000)
    if not file_browser:
        page.evaluate("window.jupyterapp.shell.collapseLeft()")
    page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
    # Run All has started when the first cell shows [*] or a number.
    page.wait_for_function(
        f"""() => Array.from(document.querySelectorAll('{VISIBLE} .jp-InputPrompt'))
               .some(p => /\\[[*0-9]/.test(p.textContent))""",
        timeout=30_000,
    )
    wait_idle(page, quiet_ms=500, timeout=180)
    counts = dict(page.evaluate(TAG_APPS, app_names()))
    # Give every figure time to be drawn; a figure still blank after that is left for the
    # caller to see (and fail on).
    with contextlib.suppress(Exception):  # playwright's TimeoutError
        page.wait_for_function(ALL_DRAWN, timeout=drawn_within * 1000, polling=100)
    wait_idle(page, quiet_ms=300, timeout=60)
    return counts


def wait_idle(page, quiet_ms: float = 300, timeout: float = 60) -> None:
    """Wait until the kernel has been idle, and no figure has changed, for ``quiet_ms``."""
    page.evaluate("() => { window.__idleSince = null; }")
    try:
        _wait_quiet(page, quiet_ms, timeout)
    except Exception as error:  # playwright's TimeoutError: say what was still going on
        raise TimeoutError(f"not idle within {timeout} s: {page_state(page)}") from error


def _wait_quiet(page, quiet_ms: float, timeout: float) -> None:
    page.wait_for_function(
        """([quiet, idle]) => {
            if (!eval(idle)()) { window.__idleSince = null; return false; }
            const now = performance.now();
            let last = 0;
            for (const list of window.__probe.frames.values())
                if (list.length) last = Math.max(last, list[list.length - 1].t);
            window.__idleSince = window.__idleSince || now;
            return now - Math.max(last, window.__idleSince) >= quiet;
        }""",
        arg=[quiet_ms, KERNEL_IDLE],
        timeout=timeout * 1000,
        polling=50,
    )


def page_state(page) -> str:
    """The kernel's status and each figure's last change, for messages when a wait fails."""
    return page.evaluate(
        """() => {
            const panel = window.jupyterapp && window.jupyterapp.shell.currentWidget;
            const kernel = panel && panel.sessionContext && panel.sessionContext.session
                && panel.sessionContext.session.kernel;
            const now = performance.now();
            const figures = Array.from(window.__probe.frames.entries()).map(([c, l]) =>
                `${c.width}x${c.height}: ${l.length} pictures, last ${(now - l[l.length - 1].t)
                    .toFixed(0)} ms ago`);
            return `kernel ${kernel ? kernel.status + '/' + kernel.connectionStatus : 'none'}; `
                + figures.join('; ');
        }"""
    )


def shutdown_kernels(page) -> None:
    """Shut down every kernel of the JupyterLab page's server (a lesson's page is done)."""
    page.evaluate("async () => { await window.jupyterapp.serviceManager.sessions.shutdownAll(); }")


def shutdown_kernel(page) -> None:
    """Shut down the kernel of the notebook on show (only that one)."""
    page.evaluate(
        "async () => { await window.jupyterapp.shell.currentWidget.sessionContext.shutdown(); }"
    )


def kernel_run(page, code: str) -> str:
    """Run ``code`` in the kernel of the notebook on show (not in a cell); what it printed."""
    out = page.evaluate(KERNEL_RUN, code)
    if "!ERROR" in out:
        raise RuntimeError(f"kernel code failed: {out}")
    return out


def app_root(page, name: str):
    """The outputs of the cell that made app ``name`` (after :func:`open_lesson`)."""
    return page.locator(f'{VISIBLE} [data-app="{name}"]').first


def figure_canvas(root):
    return root.locator(".jupyter-matplotlib-canvas-div canvas").first


def canvas_pixels(canvas) -> np.ndarray:
    """The canvas's own pixels (not a screenshot), RGBA, shape (height, width, 4)."""
    url = canvas.evaluate("c => c.width && c.height ? c.toDataURL('image/png') : ''")
    if not url:
        return np.zeros((0, 0, 4), dtype=np.uint8)
    return png_array(url.split(",", 1)[1])


def png_array(b64: str) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(base64.b64decode(b64))).convert("RGBA"))


def kernel_truth(page, count: int, constructed: bool = False) -> tuple[dict[str, str], np.ndarray]:
    """The figure the app in ``Out[count]`` should show at its controls' values, drawn afresh
    in the kernel (see :data:`TRUTH`): (the values, RGBA pixels)."""
    code = TRUTH.format(count=count, constructed=constructed)
    answer = json.loads(kernel_run(page, code))
    return answer["values"], png_array(answer["png"])


def mismatch(shown: np.ndarray, truth: np.ndarray) -> float:
    """The fraction of pixels that differ (by more than 2 levels in a channel) between the
    shown canvas and the truth; 1.0 if their sizes differ by more than a pixel."""
    if shown.size == 0 or abs(shown.shape[0] - truth.shape[0]) > 1:
        return 1.0
    if abs(shown.shape[1] - truth.shape[1]) > 1:
        return 1.0
    h, w = min(shown.shape[0], truth.shape[0]), min(shown.shape[1], truth.shape[1])
    a = shown[:h, :w, :3].astype(int)
    b = truth[:h, :w, :3].astype(int)
    return float(np.mean(np.any(np.abs(a - b) > 2, axis=2)))


def is_blank(pixels: np.ndarray) -> bool:
    """A canvas with no picture: no pixels at all, or every pixel the same."""
    return pixels.size == 0 or bool(np.all(pixels == pixels[0, 0]))


def endpoint_a(page, count: int) -> tuple[float, float, list[float]]:
    """Where endpoint A of the app in ``Out[count]`` is drawn (CSS px from the canvas's top
    left) and the top view's axes box (x, y, width, height), asked of the kernel."""
    x, y, box = json.loads(kernel_run(page, ENDPOINT_A.format(count=count)))
    return x, y, box


def steady_box(locator, timeout: float = 10.0) -> dict:
    """``locator``'s bounding box once it has stopped moving (the same in three reads 50 ms
    apart). After a scroll, JupyterLab renders the cells coming into view and the page can
    still shift: a mouse press at a box measured too early misses the slider's handle."""
    deadline = time.monotonic() + timeout
    boxes = [locator.bounding_box()]
    while time.monotonic() < deadline:
        time.sleep(0.05)
        boxes.append(locator.bounding_box())
        if boxes[-1] is not None and boxes[-3:] == [boxes[-1]] * 3:
            break
    return boxes[-1]


def slider_for(root, label: str):
    """The slider of an app whose description is exactly ``label``."""
    label = root.page.get_by_text(label, exact=True)
    return root.locator(".widget-slider").filter(has=label).first


OVERFLOW = """(root) => {
    // How far the app (figure and controls) reaches past what can be seen without scrolling
    // sideways: the nearest clipping or scrolling ancestor, and the window.
    const controls = root.querySelectorAll('.widget-slider, .widget-dropdown');
    const parts = [root.querySelector('.jupyter-matplotlib-canvas-div'), ...controls]
        .filter(Boolean);
    let right = 0;
    for (const el of parts) right = Math.max(right, el.getBoundingClientRect().right);
    let limit = document.documentElement.clientWidth, by = 'window';
    for (let el = root; el && el !== document.body; el = el.parentElement) {
        const style = getComputedStyle(el);
        const right = el.getBoundingClientRect().right;
        if (style.overflowX !== 'visible' && right < limit) {
            limit = right;
            by = el.className.split(' ')[0] + ' (overflow-x: ' + style.overflowX + ')';
        }
    }
    const canvas = root.querySelector('.jupyter-matplotlib-canvas-div');
    return {overflow: Math.round(right - limit), right: Math.round(right),
            limit: Math.round(limit), by,
            width: canvas ? Math.round(canvas.getBoundingClientRect().width) : 0,
            height: Math.round(root.getBoundingClientRect().height)};
}"""


def overflow(root) -> dict[str, int]:
    """How many CSS px app ``root`` reaches past the visible width (``overflow`` > 0: cut off
    or scrolled), with the right edges compared and the figure's width and the app's height."""
    return root.evaluate(OVERFLOW)


def write_all_apps_notebook(path: Path, names: list[str]) -> None:
    """A notebook that makes every app in ``names``, one cell each (for measuring layout in
    Voilà with one kernel instead of one per lesson: Voilà lays out every notebook alike).
    Apps without a function in :data:`interp.apps.ALL` are made from their registry figure, as
    their lessons make them."""
    import nbformat

    from interp import apps

    def make(name: str) -> str:
        if name in apps.ALL:
            return f"apps.{name}()"
        return f"apps.App(registry.{figure_of(name).__name__})"

    setup = "%matplotlib widget\nfrom interp import apps\nfrom interp.plots import registry"
    cells = [nbformat.v4.new_code_cell(setup)]
    cells += [nbformat.v4.new_code_cell(make(name)) for name in names]
    notebook = nbformat.v4.new_notebook(cells=cells)
    notebook.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3"}
    nbformat.write(notebook, path)


def open_voila_apps(page, url: str, names: list[str]) -> None:
    """Load a Voilà page that makes the apps ``names`` in order; tag each app's output
    ``data-app=NAME``. (Voilà's template links Font Awesome from a CDN; without internet
    route it away first, as the tests do.)"""
    page.goto(url, timeout=180_000)
    page.locator(".jupyter-matplotlib-canvas-div").nth(len(names) - 1).wait_for(timeout=180_000)
    page.evaluate(
        """(names) => {
            const canvases = document.querySelectorAll('.jupyter-matplotlib-canvas-div');
            canvases.forEach((c, i) => {
                const output = c.closest('.jp-OutputArea-output') || c.closest('.widget-vbox');
                output.setAttribute('data-app', names[i]);
            });
        }""",
        names,
    )


def show_file_browser(page) -> None:
    """JupyterLab's left panel open on the file browser (as on a laptop, by default)."""
    page.evaluate(
        "() => { window.jupyterapp.shell.expandLeft(); "
        "window.jupyterapp.shell.activateById('filebrowser'); }"
    )
    page.wait_for_timeout(300)  # the panels lay themselves out again


#: The control moved in each app: one that changes the whole figure (a slider, else a
#: drop-down list).
CONTROL = {
    "the_problem": "A_w",
    "projecting_a_line": "A_w",
    "st_mapping": "w2",
    "depth": "w2",
    "attributes": "w2",
    "colour_quad": "pitch",
    "checkerboards": "pitch",
    "checkerboards_outside": "pitch",
    "uv_images": "pitch",
    "outside_view": "pitch",
    "linear_on_screen": "pitch",
    "barycentrics": "pitch",
    "shader": "pitch",
    "clipping": "pitch",
    "clipping_outside": "pitch",
    "approximations": "pitch",
    "texture_filtering": "pitch",
    "mipmap_pyramid": "frequency",
}
