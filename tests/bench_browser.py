"""How live every app feels in a real browser: ``make bench-browser`` (or
``python tests/bench_browser.py``).

Every app of every lesson, in a real JupyterLab on a free localhost port, in Debian's Chromium
through Playwright, at the default figure size (viewport 1500 x 1100, device pixel ratio 1):

- step: a keyboard arrow on the focused slider, to the first changed picture on the figure's
  canvas; median and p90 over ``--steps`` steps, each once the previous one has settled;
- drag: the slider's handle dragged back and forth with the mouse for ``--seconds`` s, a move
  each animation frame as a real mouse's moves arrive (``--drag``), counting distinct pictures
  shown per second while the button is down ("fps"), and the mouse moves made ("moves", a
  second);
- settle: from mouse-up to the last change of the canvas (waiting until nothing changed for
  0.8 s with the kernel idle), and how many pictures were shown after mouse-up;
- each row drags ``--drags`` times alike, from the same place (what was dragged is taken back
  there between drags, unmeasured), and gives the medians of the drags' figures and the
  longest settle: one mouse-up is one sample of a time that varies from one to the next by
  tens of ms;
- final: whether the picture left on screen is the figure at the final value: the canvas's
  pixels against the same app drawn afresh in the kernel at its controls' values
  (``browser.TRUTH``), and the slider's readout against the kernel's value.

First the floor under every app: a slider whose value the kernel writes into a text label
(:data:`FLOOR_CELL`), stepped with the keyboard as the apps are, to the animation frame that
shows the kernel's answer. It is the round trip every step makes (JupyterLab, the Jupyter
server, the kernel and back) without a figure: an app's step cannot be faster. Then the floor
under every figure (:data:`FLOOR_PICTURE_CELL`): an interp app whose figure, of the size of
the largest default figure, is one image that a step only shifts, stepped and dragged as the
apps are: an app's step costs that, plus its own computing and drawing. It is measured in a
notebook of its own, and again at the end of lesson 6's notebook (:data:`FLOOR_LESSON`), after
all of the lesson's cells have run: a lesson's page (its prose, equations and apps) costs the
browser more in every frame than a page of one cell. The HiDPI run starts with the first.

For lessons 1-2 the same again with endpoint A dragged by the mouse in the figure (small
mouse moves with the button held, instead of key presses). And once more for the
checkerboards of lesson 6 (its first app) at device pixel ratio 2 (a HiDPI screen).

Every app a lesson makes is measured once (a lesson that makes one twice: the first), by its
first slider that changes the whole figure; an app with no slider (the mipmap pyramid, a
drop-down list alone) is listed as not measured.

Times are measured in the page, with ``performance.now()``: the input event's ``timeStamp``
and the animation frame at which the canvas's pixels first differ (``browser.FRAME_PROBE``:
``drawImage`` into a figure canvas marks it and asks for the next animation frame, which
hashes the marked canvases). So "frames" are distinct pictures about to be painted, at most one
per display frame; Playwright's round trips are not in the figures.

The machine is shared and noisy: the output starts with the CPU count and load average, before
and after, so runs can be compared.

``--cpu`` (Linux) adds, under each app's row, where the CPU went during its key steps: the
CPU time each process and thread used (the kernel, the Jupyter server, Chromium's renderer
main thread, compositor, decoders, ...), read from ``/proc`` before and after, in ms a step,
the waits between steps included. On two CPUs, the browser's share competes with the kernel's.

``--slider APP=PARAM`` steps and drags an app by another of its sliders (lesson 6's checks per
side: ``--slider checkerboards_outside=frequency``).

``--tree DIR`` measures another checkout instead of this one: its lessons, and its ``interp`` in
the kernels (first on their PYTHONPATH) and here (for the apps' parameters). So the same script
measures the apps before and after a change, e.g. in a worktree at an older commit
(``git worktree add ../before COMMIT``); the header says which ``interp`` the kernels imported
and at which commit. Apps a checkout lacks are not measured; what an older app cannot do (no
blitting, no readout) is simply not used.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from browser import (
    CHROMIUM,
    CONTROL,
    FRAME_PROBE,
    ROOT,
    app_root,
    canvas_pixels,
    chromium,
    endpoint_a,
    figure_canvas,
    is_blank,
    kernel_interp,
    kernel_truth,
    lessons,
    mismatch,
    open_lesson,
    open_voila_apps,
    overflow,
    server,
    show_file_browser,
    shutdown_kernels,
    slider_for,
    steady_box,
    wait_idle,
    write_all_apps_notebook,
)

#: The slider each app is stepped and dragged with (the mipmap pyramid has a drop-down only).
STEP_PARAM = {app: name for app, name in CONTROL.items() if app != "mipmap_pyramid"}

#: Apps whose endpoints the mouse drags in the figure (lessons 1-2).
DRAGGABLE = ("the_problem", "projecting_a_line")

#: A picture counts as the right one when at most this fraction of its pixels differ.
TOLERANCE = 0.001

VIEWPORT = {"width": 1440, "height": 900}

#: Where the first lesson's kernel imported ``interp`` from (filled in by :func:`bench_lesson`).
KERNEL_INTERP: list[str] = []


def machine_line() -> str:
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    return f"{os.cpu_count()} CPUs, load average {load} (1, 5, 15 min)"


def chromium_version() -> str:
    try:
        out = subprocess.run([CHROMIUM, "--version"], capture_output=True, text=True, timeout=20)
        return out.stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def percentile(values: list[float], q: float) -> float:
    """The q-th percentile (nearest rank, so p90 of 15 steps is the 14th)."""
    ordered = sorted(values)
    rank = max(1, round(q / 100 * len(ordered) + 0.4999))
    return ordered[min(rank, len(ordered)) - 1]


def figure_param(name: str, param: str):
    from interp.plots import registry

    return registry.FIGURES[name.replace("_", "-")].PARAMS[param]


def tree_line(tree: Path) -> str:
    """The checkout measured: its path and commit."""
    try:
        out = subprocess.run(
            ["git", "-C", str(tree), "log", "-1", "--format=%h %s"],
            capture_output=True,
            text=True,
            timeout=20,
        )
        commit = out.stdout.strip()[:100] or "not a git checkout"
        dirty = subprocess.run(
            ["git", "-C", str(tree), "status", "--porcelain", "--", "interp", "lessons"],
            capture_output=True,
            text=True,
            timeout=20,
        ).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        commit, dirty = "unknown", ""
    return f"{tree} at {commit}" + (" (interp/ or lessons/ changed since)" if dirty else "")


# ------------------------------------------------------------------------ in-page readings


def last_frame_time(page, canvas) -> float:
    return page.evaluate("c => (window.__probe.last(c) || {t: 0}).t", canvas)


def frames_between(page, canvas, start: float, end: float) -> list[float]:
    return page.evaluate(
        "([c, a, b]) => window.__probe.of(c).filter(f => f.t > a && f.t <= b).map(f => f.t)",
        [canvas, start, end],
    )


def last_input(page, kind: str) -> float:
    return page.evaluate("k => window.__probe.lastInput(k)", kind)


def first_frame_after(page, canvas, t: float, timeout: float = 10.0) -> float | None:
    """Wait for a picture after page time ``t``; its time, or None if none came. The probe
    says when one comes (``probe.after``): nothing polls the page meanwhile."""
    return page.evaluate(
        "([c, t, ms]) => window.__probe.after(c, t, ms)", [canvas, t, timeout * 1000]
    )


# ------------------------------------------------------------------------------ the actions


def timed_steps(page, shown_after, act, event: str, steps: int) -> tuple[list[float], int]:
    """``act(i)`` for i = 1 to ``steps``, each after the last has settled: the latencies (ms)
    from the input ``event`` to what ``shown_after(t)`` finds first shown after page time t
    (:func:`first_frame_after` a figure's canvas), and how many steps showed nothing."""
    latencies, misses = [], 0
    for i in range(1, steps + 1):
        act(i)
        t_in = last_input(page, event)
        shown = shown_after(t_in)
        if shown is None:
            misses += 1
        else:
            latencies.append(shown - t_in)
        wait_idle(page, quiet_ms=100)
    return latencies, misses


def step_with_keys(page, handle, canvas, key: str, steps: int) -> tuple[list[float], int]:
    """Press ``key`` on the focused slider handle ``steps`` times (:func:`timed_steps`)."""
    handle.focus()
    return timed_steps(
        page,
        lambda t: first_frame_after(page, canvas, t),
        lambda i: page.keyboard.press(key),
        "keydown",
        steps,
    )


def step_with_mouse(page, start: tuple[float, float], dx: float, canvas, steps: int):
    """Press at ``start``, then move ``dx`` px ``steps`` times (:func:`timed_steps`); release."""
    x, y = start
    page.mouse.move(x, y)
    page.mouse.down()
    wait_idle(page, quiet_ms=150)
    result = timed_steps(
        page,
        lambda t: first_frame_after(page, canvas, t),
        lambda i: page.mouse.move(x + dx * i, y),
        "pointermove",
        steps,
    )
    page.mouse.up()
    wait_idle(page, quiet_ms=300)
    return result


#: A drag made in the page, one mouse move per animation frame, as Chrome delivers a real
#: mouse's moves (it aligns them to frames, at most one each): the pointer and mouse events a
#: real drag dispatches, to the element under the pointer, with the button held.
DRAG_JS = """
([x, y, amplitude, seconds, period]) => new Promise((resolve) => {
  const fire = (kind, cx, cy, buttons) => {
    const target = document.elementFromPoint(cx, cy) || document.body;
    const init = {clientX: cx, clientY: cy, screenX: cx, screenY: cy, bubbles: true,
                  cancelable: true, composed: true, view: window, button: 0, buttons};
    target.dispatchEvent(new PointerEvent('pointer' + kind,
      {...init, pointerId: 1, pointerType: 'mouse', isPrimary: true}));
    target.dispatchEvent(new MouseEvent('mouse' + kind, init));
  };
  let moves = 0;
  fire('move', x, y, 0);
  fire('down', x, y, 1);
  const t0 = performance.now();
  const frame = (now) => {
    const t = (now - t0) / 1000;
    if (t >= seconds) {
      fire('move', x + amplitude, y, 1);
      fire('up', x + amplitude, y, 0);
      resolve(moves + 1);
      return;
    }
    const phase = (t / period) % 1;
    const tri = phase < 0.25 ? 4 * phase : phase < 0.75 ? 2 - 4 * phase : 4 * phase - 4;
    fire('move', x + amplitude * tri, y, 1);
    moves += 1;
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
})
"""


def drag(
    page, start: tuple[float, float], amplitude: float, seconds: float, by: str = "page"
) -> int:
    """Hold the button at ``start`` and move back and forth by ``amplitude`` px for
    ``seconds``; let go a quarter period past a whole number of periods (at ``start`` +
    ``amplitude``), so the final value differs from the first. The number of moves made.

    ``by="page"``: a move each animation frame, made in the page (:data:`DRAG_JS`), as a
    real mouse's moves arrive. ``by="playwright"``: ``page.mouse.move`` every 16 ms; each
    waits for the browser to take the move in, so on a busy 2-core machine the moves come
    at about 26 a second, and the drag then has fewer new values than a real one."""
    x, y = start
    period = seconds / (int(seconds / 1.2) + 0.25)
    if by == "page":
        return page.evaluate(DRAG_JS, [x, y, amplitude, seconds, period])
    page.mouse.move(x, y)
    page.mouse.down()
    t0 = time.perf_counter()
    moves = 0
    while True:
        t = time.perf_counter() - t0
        if t >= seconds:
            break
        phase = (t / period) % 1.0
        tri = 4 * phase if phase < 0.25 else 2 - 4 * phase if phase < 0.75 else 4 * phase - 4
        page.mouse.move(x + amplitude * tri, y)
        moves += 1
        wait = 0.016 - (time.perf_counter() - t0 - t)
        if wait > 0:
            time.sleep(wait)
    page.mouse.move(x + amplitude, y)
    page.mouse.up()
    return moves + 1


def measure_drag(page, canvas, start, amplitude, args, count, readout, tag) -> dict:
    """Drag (:func:`repeated_drags`), then: fps while the button was down, settle times,
    pictures after mouse-up, and whether the final picture is the figure at the final value
    (if not, and ``--save``, both pictures go to that folder as TAG-shown.png and
    TAG-truth.png)."""
    row = repeated_drags(page, canvas, start, amplitude, args)
    values, truth = kernel_truth(page, count)
    shown = canvas_pixels(canvas)
    wrong = mismatch(shown, truth)
    if wrong > TOLERANCE and args.save:
        save_pictures(args.save, tag, shown, truth)
    value_agrees = True
    if readout is not None:
        value_agrees = readout_agrees(readout, values)
    return {
        **row,
        "final_mismatch": wrong,
        "final_right": wrong <= TOLERANCE and value_agrees and not is_blank(shown),
        "readout_agrees": value_agrees,
    }


def repeated_drags(page, canvas, start, amplitude, args) -> dict:
    """:func:`measured_drag` ``args.drags`` times alike, from ``start``, each after the handle
    (or endpoint) is taken back there from where the last let go (:func:`put_back`): a row of
    the medians of the drags' figures, with the longest settle (``settle_worst_ms``) and every
    drag's pictures a second and settle, in order (``fps_each``, ``settles_ms``); counts of
    pictures are the first drag's.

    One drag is one sample: the same drag's settle varies from one mouse-up to the next by
    more than the target's margin (in one run, the clipping app's five drags settled in 56 to
    122 ms), so a row is judged by the medians of several."""
    x, y = start
    drags = []
    for k in range(args.drags):
        if k:  # a drag lets go at start + amplitude
            put_back(page, (x + amplitude, y), start)
        drags.append(measured_drag(page, canvas, start, amplitude, args))
    row = dict(drags[0])
    for key in ("fps", "moves_per_s", "settle_ms", "drag_busy", "drag_cpu_ms_per_frame"):
        row[key] = statistics.median(drag[key] for drag in drags)
    row["settle_worst_ms"] = max(drag["settle_ms"] for drag in drags)
    row["fps_each"] = [round(drag["fps"], 1) for drag in drags]
    row["settles_ms"] = [round(drag["settle_ms"], 1) for drag in drags]
    return row


def put_back(page, where: tuple[float, float], start: tuple[float, float]) -> None:
    """Drag what is at ``where`` (a slider's handle, an endpoint) back to ``start`` in a few
    moves, unmeasured, and wait until the page is quiet: the next drag then covers the same
    values as the first (a drag from ``where`` would reach twice as far from ``start``, past a
    slider's end where its room was measured)."""
    page.mouse.move(*where)
    page.mouse.down()
    page.mouse.move(*start, steps=4)
    page.mouse.up()
    wait_idle(page, quiet_ms=300, timeout=60)


def measured_drag(page, canvas, start, amplitude, args) -> dict:
    """:func:`drag`, then wait until the page is quiet: fps while the button was down, mouse
    moves a second, settle time, pictures after mouse-up, and how busy the machine's CPUs were
    in the drag (:func:`machine_ticks`)."""
    busy_before = machine_ticks()
    moves = drag(page, start, amplitude, args.seconds, args.drag)
    busy_after = machine_ticks()
    t_down, t_up = last_input(page, "pointerdown"), last_input(page, "pointerup")
    wait_idle(page, quiet_ms=800, timeout=60)
    during = frames_between(page, canvas, t_down, t_up)
    after = frames_between(page, canvas, t_up, float("inf"))
    return {
        "fps": len(during) / ((t_up - t_down) / 1000),
        "moves_per_s": moves / ((t_up - t_down) / 1000),
        "frames_during": len(during),
        "settle_ms": (after[-1] - t_up) if after else 0.0,
        "frames_after_release": len(after),
        "drag_busy": busy_share(busy_before, busy_after),
        "drag_cpu_ms_per_frame": cpu_ms_per_frame(busy_before, busy_after, len(during)),
    }


def save_pictures(folder: Path, tag: str, shown, truth) -> None:
    from PIL import Image

    folder.mkdir(parents=True, exist_ok=True)
    Image.fromarray(shown).save(folder / f"{tag}-shown.png")
    Image.fromarray(truth).save(folder / f"{tag}-truth.png")


def readout_agrees(readout: tuple, values: dict[str, str]) -> bool:
    """The slider's readout shows the kernel's value (to half a step)."""
    locator, param, name = readout
    text = locator.inner_text().strip()
    try:
        return abs(float(text) - float(values[name])) <= param.step / 2 + 1e-9
    except ValueError:
        return False


# ---------------------------------------------------------------------------------- per app


def _cpu_kind(command: str) -> str | None:
    """Which part of the benchmark a process is, from its command line; None: not one."""
    if "ipykernel" in command:
        return "kernel"
    if "chromium" in command:
        for kind in ("renderer", "gpu-process", "utility"):
            if f"--type={kind}" in command:
                return f"chromium {kind}"
        return "chromium browser"
    if "jupyter" in command:
        return "server"
    return None


#: Clock ticks a second: the unit of the CPU times in ``/proc``.
CLOCK_TICK = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100


def cpu_times() -> dict[tuple[str, str, str], tuple[str, float]]:
    """CPU time (s) of every thread of the kernels, the server and Chromium, from ``/proc``:
    (kind, pid, tid) -> (thread name, user + system time); empty where there is no ``/proc``."""
    found = {}
    for pid in os.listdir("/proc") if os.path.isdir("/proc") else ():
        if not pid.isdigit():
            continue
        try:
            kind = _cpu_kind(Path(f"/proc/{pid}/cmdline").read_text().replace("\0", " "))
            tids = os.listdir(f"/proc/{pid}/task") if kind else ()
        except OSError:
            continue
        for tid in tids:
            try:
                stat = Path(f"/proc/{pid}/task/{tid}/stat").read_text()
            except OSError:
                continue
            name = stat[stat.find("(") + 1 : stat.rfind(")")]
            fields = stat[stat.rfind(")") + 2 :].split()
            found[(kind, pid, tid)] = (name, (int(fields[11]) + int(fields[12])) / CLOCK_TICK)
    return found


def cpu_per_step(before: dict, after: dict, steps: int) -> dict[str, float]:
    """CPU ms a step per process kind and thread name, between two :func:`cpu_times`, largest
    first (under 0.5 ms left out)."""
    used: dict[str, float] = {}
    for key, (name, seconds) in after.items():
        spent = seconds - before.get(key, (name, 0.0))[1]
        if spent > 0:
            kind, pid, tid = key
            label = f"{kind} {'main' if tid == pid else name}"
            used[label] = used.get(label, 0.0) + 1000 * spent / max(steps, 1)
    return {k: round(v, 1) for k, v in sorted(used.items(), key=lambda kv: -kv[1]) if v >= 0.5}


def slider_drag(slider) -> tuple[tuple[float, float], float]:
    """Where a drag of ``slider``'s handle starts (the handle's centre) and how far it goes each
    way (px): 40, less where the track ends sooner; negative where that end is to the right."""
    box = steady_box(slider.locator(".noUi-handle"))
    track = slider.locator(".noUi-target").bounding_box()
    centre = (box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    room = min(centre[0] - track["x"], track["x"] + track["width"] - centre[0])
    amplitude = max(8.0, min(40.0, room - 4))
    if centre[0] + amplitude > track["x"] + track["width"]:
        amplitude = -amplitude
    return centre, amplitude


def bench_slider(page, name: str, count: int, args, label: str) -> dict:
    root = app_root(page, name)
    param_name = STEP_PARAM[name]
    param = figure_param(name, param_name)
    slider = slider_for(root, param.label)
    slider.scroll_into_view_if_needed()
    canvas_locator = figure_canvas(root)
    canvas = canvas_locator.element_handle()
    handle = slider.locator(".noUi-handle")
    up = param.default + args.steps * param.step <= param.high
    key = "ArrowRight" if up else "ArrowLeft"
    before = cpu_times() if args.cpu else {}
    latencies, misses = step_with_keys(page, handle, canvas, key, args.steps)
    cpu = cpu_per_step(before, cpu_times(), args.steps) if args.cpu else None
    centre, amplitude = slider_drag(slider)
    readout = (slider.locator(".widget-readout"), param, param_name)
    row = measure_drag(page, canvas, centre, amplitude, args, count, readout, name + label)
    row.update(input=f"{label} slider '{param.label}'", **summary(latencies, misses))
    if cpu is not None:
        row["cpu_ms_per_step"] = cpu
    return row


def bench_endpoint(page, name: str, count: int, args, label: str) -> dict:
    root = app_root(page, name)
    canvas_locator = figure_canvas(root)
    canvas_locator.scroll_into_view_if_needed()
    canvas = canvas_locator.element_handle()
    box = steady_box(canvas_locator)
    ax, ay, axes = endpoint_a(page, count)
    start = (box["x"] + ax, box["y"] + ay)
    latencies, misses = step_with_mouse(page, start, 3.0, canvas, args.steps)
    # The steps moved A by 3 px each: drag from where it is now.
    ax, ay, axes = endpoint_a(page, count)
    start = (box["x"] + ax, box["y"] + ay)
    room = min(ax - axes[0], axes[0] + axes[2] - ax) - 6
    amplitude = max(8.0, min(40.0, room))
    if ax + amplitude > axes[0] + axes[2]:
        amplitude = -amplitude
    row = measure_drag(page, canvas, start, amplitude, args, count, None, name + "-A" + label)
    row.update(input="mouse on endpoint A", **summary(latencies, misses))
    return row


def summary(latencies: list[float], misses: int) -> dict:
    if not latencies:
        return {"median_ms": float("nan"), "p90_ms": float("nan"), "steps": 0, "misses": misses}
    return {
        "median_ms": statistics.median(latencies),
        "p90_ms": percentile(latencies, 90),
        "steps": len(latencies),
        "misses": misses,
        "latencies_ms": [round(x, 1) for x in latencies],
    }


def new_page(context):
    page = context.new_page()
    page.errors = []
    page.on("console", lambda m: m.type == "error" and page.errors.append(m.text))
    page.on("pageerror", lambda e: page.errors.append(str(e)))
    return page


def bench_lesson(context, base, notebook, names, args, label="", only=None) -> list[dict]:
    """Run All in a fresh kernel and measure the lesson's apps. A figure left blank by Run All
    (the frontend-not-ready race) cannot be measured: then run the lesson again, up to three
    times, and note how often it happened."""
    names = [name for name in names if "@" not in name and (not only or name in only)]
    blank_runs = []
    for attempt in range(3):
        page = new_page(context)
        counts = open_lesson(page, base, notebook, drawn_within=10)
        if not KERNEL_INTERP:
            KERNEL_INTERP.append(str(kernel_interp(page)))
        blank = [n for n in names if is_blank(canvas_pixels(figure_canvas(app_root(page, n))))]
        if blank:
            blank_runs.append(blank)
            print(f"  ({notebook}, run {attempt + 1}: blank after Run All: {', '.join(blank)})")
        if not blank or attempt == 2:
            break
        shutdown_kernels(page)
        page.close()
    rows = []
    try:
        for name in names:
            drags_a = name in DRAGGABLE and not args.no_endpoints
            for kind in ["slider", "endpoint"] if drags_a else ["slider"]:
                t0 = time.monotonic()
                try:
                    if name not in STEP_PARAM:
                        raise LookupError("no slider")
                    if name in blank:
                        raise RuntimeError("blank after Run All in 3 of 3 runs: not measured")
                    bench = bench_slider if kind == "slider" else bench_endpoint
                    row = bench(page, name, counts[name], args, label)
                except Exception as error:  # one app's failure must not lose the others' rows
                    row = {"error": f"{type(error).__name__}: {str(error).splitlines()[0]}"}
                row.update(
                    app=name + ("" if kind == "slider" else " (drag A)") + label,
                    lesson=notebook,
                    blank_runs=sum(name in b for b in blank_runs),
                    runs=attempt + 1,
                    seconds=round(time.monotonic() - t0, 1),
                )
                rows.append(row)
                print(format_row(row), flush=True)
                if row.get("cpu_ms_per_step"):
                    print(format_cpu(row["cpu_ms_per_step"]), flush=True)
        for row in rows:
            row["console_errors"] = list(page.errors)
    finally:
        shutdown_kernels(page)
        page.close()
    return rows


# ----------------------------------------------------------------------------- the floor

#: The floor under every app: a slider whose value the kernel writes into a text label, no
#: figure. A step is the same round trip an app's step makes (the key press, the slider's
#: message to the kernel, the kernel's answer, the page showing it), without any drawing.
FLOOR_CELL = """\
import ipywidgets as widgets
slider = widgets.IntSlider(value=50, min=0, max=100, description="floor")
label = widgets.Label("50")
label.add_class("interp-floor")
slider.observe(lambda change: setattr(label, "value", str(change["new"])), "value")
widgets.HBox([slider, label])
"""

#: When the label's text changes: the animation frame after, recorded as the probe records
#: pictures (``probe.record``, with the text for the picture).
FLOOR_PROBE = """() => {
    const label = document.querySelector('.interp-floor');
    new MutationObserver(() => requestAnimationFrame(
        () => window.__probe.record(label, performance.now(), label.textContent)
    )).observe(label, {subtree: true, childList: true, characterData: true});
}"""


def first_text_after(page, t: float, timeout: float = 10.0) -> float | None:
    """Wait for the floor's label to change after page time ``t`` (:data:`FLOOR_PROBE`); the
    frame's time, or None if it did not (``probe.after``: nothing polls the page)."""
    return page.evaluate(
        "([t, ms]) => window.__probe.after(document.querySelector('.interp-floor'), t, ms)",
        [t, timeout * 1000],
    )


def open_cell(
    context,
    base: str,
    folder: Path,
    name: str,
    code: str,
    drawn_within: float,
    after: str | None = None,
):
    """A new page with a notebook ending in one code cell, ``code``, written to
    ``folder/name`` and run (:func:`open_lesson`): the cell alone, or after every cell of the
    lesson ``after`` (a notebook in ``folder``)."""
    import nbformat

    if after is None:
        notebook = nbformat.v4.new_notebook()
        notebook.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3"}
    else:
        notebook = nbformat.read(folder / after, as_version=4)
    notebook.cells.append(nbformat.v4.new_code_cell(code))
    nbformat.write(notebook, folder / name)
    page = new_page(context)
    try:
        open_lesson(page, base, name, drawn_within=drawn_within)
    except BaseException:
        with contextlib.suppress(Exception):
            shutdown_kernels(page)
        page.close()
        raise
    return page


def bench_floor(context, base: str, folder: Path, steps: int) -> dict:
    """Key presses on the floor's slider (:data:`FLOOR_CELL`), each to the frame that shows the
    kernel's answer: the part of every app's step that is not its figure's."""
    page = open_cell(context, base, folder, "interp_floor.ipynb", FLOOR_CELL, drawn_within=1)
    try:
        page.locator(".interp-floor").wait_for()
        page.evaluate(FLOOR_PROBE)
        page.locator(".widget-slider .noUi-handle").first.focus()
        latencies, misses = timed_steps(
            page,
            lambda t: first_text_after(page, t),
            lambda i: page.keyboard.press("ArrowRight" if i % 2 else "ArrowLeft"),
            "keydown",
            steps,
        )
        return {"app": "floor: slider -> text", "floor": True, **summary(latencies, misses)}
    finally:
        shutdown_kernels(page)
        page.close()


#: The floor under every figure: one ipympl figure as large as lesson 6's checkerboard app's,
#: made as ipympl's examples make one (``plt.ioff()``, the canvas beside a slider), whose image a
#: slider replaces by one of a set of arrays computed beforehand, redrawn with matplotlib's
#: documented blitting (``copy_from_bbox`` after each full draw, then ``restore_region``,
#: ``draw_artist``, ``blit``). A step computes nothing: what an app's step costs beyond it is its
#: own computing and drawing.
FLOOR_PICTURE_CELL = """\
%matplotlib widget
import ipywidgets as widgets
import matplotlib.pyplot as plt
import numpy as np

from interp.apps._app import figure_size
from interp.plots.registry import Checkerboards

u, v = np.meshgrid(np.linspace(0, 1, 320), np.linspace(0, 1, 240))
frames = [((np.floor(8 * (u + k / 100) ** 1.5) + np.floor(8 * v)) % 2) for k in range(101)]
with plt.ioff():
    fig, ax = plt.subplots(figsize=figure_size(Checkerboards.size, False))
image = ax.imshow(frames[50], cmap="gray", animated=True)
fig.canvas.header_visible = False
background = None

def on_draw(event):
    global background
    background = fig.canvas.copy_from_bbox(fig.bbox)
    fig.draw_artist(image)

fig.canvas.mpl_connect("draw_event", on_draw)
floor = widgets.IntSlider(50, 0, 100, description="floor shift")

def step(change):
    image.set_data(frames[change["new"]])
    if background is None:
        fig.canvas.draw()
        return
    fig.canvas.restore_region(background)
    fig.draw_artist(image)
    fig.canvas.blit(fig.bbox)

floor.observe(step, names="value")
widgets.VBox([floor, fig.canvas])
"""


def machine_ticks() -> tuple[int, int]:
    """The machine's CPU time so far, in clock ticks over all CPUs: (busy, all), from the first
    line of ``/proc/stat``; (0, 0) where there is none. Busy is user, nice, system, irq and
    softirq time; all adds idle and I/O wait. Time the hypervisor gave to other machines
    (steal) is in neither."""
    try:
        fields = [int(x) for x in Path("/proc/stat").read_text().split("\n")[0].split()[1:8]]
        user, nice, system, idle, iowait, irq, softirq = fields
    except (OSError, ValueError):
        return 0, 0
    busy = user + nice + system + irq + softirq
    return busy, busy + idle + iowait


def busy_share(before: tuple[int, int], after: tuple[int, int]) -> float:
    """How busy the machine's CPUs were between two :func:`machine_ticks`, 0 to 1 (NaN: not
    known)."""
    spent = after[1] - before[1]
    return (after[0] - before[0]) / spent if spent > 0 else math.nan


def cpu_ms_per_frame(before: tuple[int, int], after: tuple[int, int], frames: int) -> float:
    """The CPU time the whole machine spent between two :func:`machine_ticks`, in ms a frame
    shown (NaN: not known)."""
    busy = after[0] - before[0]
    return 1000 * busy / CLOCK_TICK / frames if frames and after[1] > before[1] else math.nan


#: The lesson whose page the picture floor is measured in a second time, after its own cells:
#: lesson 6, the page of the checkerboards (and of the HiDPI run).
FLOOR_LESSON = "06_checkerboards.ipynb"


def bench_floor_picture(
    context, base: str, folder: Path, args, label: str = "", after: str | None = None
) -> dict:
    """Key presses and a drag on the picture floor's slider (:data:`FLOOR_PICTURE_CELL`): what
    every app's step costs before its own computing and drawing; in a notebook of its own, or
    at the end of the lesson ``after``, whose page (every cell, every app, run) a student's
    step also pays for."""
    name = "interp_floor_picture.ipynb"
    page = open_cell(context, base, folder, name, FLOOR_PICTURE_CELL, 10, after=after)
    try:
        # The floor's figure and slider are the page's last.
        canvas = page.locator(".jupyter-matplotlib-canvas-div").last.locator("canvas").first
        canvas.wait_for()
        handle = page.locator(".widget-slider .noUi-handle").last
        handle.scroll_into_view_if_needed()
        before = cpu_times() if args.cpu else {}
        latencies, misses = step_with_keys(page, handle, canvas.element_handle(), "ArrowRight",
                                           args.steps)  # fmt: skip
        cpu = cpu_per_step(before, cpu_times(), args.steps) if args.cpu else None
        box = steady_box(handle)
        centre = (box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
        return {
            "app": (
                "floor: slider -> picture"
                if after is None
                else "floor: picture, lesson " + after[:2].lstrip("0")
            )
            + label,
            "floor": "picture",
            **({"cpu_ms_per_step": cpu} if cpu is not None else {}),
            **repeated_drags(page, canvas.element_handle(), centre, 40.0, args),
            "console_errors": list(page.errors),
            **summary(latencies, misses),
        }
    finally:
        shutdown_kernels(page)
        page.close()


# ---------------------------------------------------------------------------------- output

HEADER = (
    f"{'app':<28} {'median':>7} {'p90':>7} {'fps':>6} {'moves':>6} {'settle':>7} {'worst':>7} "
    f"{'after':>5} "
    f"{'busy':>5} {'CPU/pic':>7} {'final right?':<14} notes"
)


def format_row(row: dict) -> str:
    if row.get("error", "").startswith("LookupError"):
        return f"{row['app']:<28} not measured: it has no slider"
    if "error" in row:
        return f"{row['app']:<28} failed: {row['error']}"
    if row.get("floor") and row["floor"] != "picture":
        return (
            f"{row['app']:<28} {row['median_ms']:>5.0f}ms {row['p90_ms']:>5.0f}ms "
            f"{'':>6} {'':>6} {'':>7} {'':>7} {'':>5} {'':>5} {'':>7} {'':<14} "
            "no figure: the round trip every step makes"
            + (f"; {row['misses']} steps showed nothing" if row.get("misses") else "")
        )
    if row.get("floor"):  # the picture floor: a drag like an app's, no final picture to check
        final, notes = "", ["nothing computed: an image shifted"]
    else:
        final = "yes" if row["final_right"] else f"NO ({row['final_mismatch']:.1%} px)"
        if not row["readout_agrees"]:
            final = "NO (readout)"
        notes = []
        if row.get("blank_runs"):
            notes.append(f"blank after Run All in {row['blank_runs']} of {row['runs']} runs")
    if row.get("misses"):
        notes.append(f"{row['misses']} steps {'showed' if row.get('floor') else 'drew'} nothing")
    return (
        f"{row['app']:<28} {row['median_ms']:>5.0f}ms {row['p90_ms']:>5.0f}ms "
        f"{row['fps']:>6.1f} {row.get('moves_per_s', math.nan):>6.1f} "
        f"{row['settle_ms']:>5.0f}ms {row.get('settle_worst_ms', row['settle_ms']):>5.0f}ms "
        f"{row['frames_after_release']:>5} "
        f"{row.get('drag_busy', math.nan):>5.0%} "
        f"{row.get('drag_cpu_ms_per_frame', math.nan):>5.0f}ms "
        f"{final:<14} {'; '.join(notes)}"
    )


#: The targets, as ratios to the picture floor measured in the same run: an app's step median
#: at most this many times the floor's, and its drag at least this share of the floor's
#: pictures a second.
STEP_RATIO, FPS_RATIO = 1.6, 0.6
#: In absolute terms: lesson 6's checkerboards dragged by pitch show at least this many
#: distinct pictures a second.
CHECKERBOARDS_FPS = 12.0


def ratios(row: dict, floor: dict) -> tuple[float, float]:
    """A row's step median over the floor's, and its pictures a second over the floor's (NaN
    where either is not measured).

    Examples
    --------
    >>> ratios({"median_ms": 48.0, "fps": 20.0}, {"median_ms": 40.0, "fps": 25.0})
    (1.2, 0.8)
    """
    nan = math.nan
    step = row.get("median_ms", nan) / floor.get("median_ms", nan)
    fps = row.get("fps", nan) / floor.get("fps", nan) if floor.get("fps") else nan
    return round(step, 3), round(fps, 3)


def missed(row: dict, floor: dict) -> list[str]:
    """Which targets a row misses, against ``floor`` (a row not measured misses nothing).

    Examples
    --------
    >>> floor = {"median_ms": 40.0, "fps": 25.0}
    >>> missed({"app": "depth", "median_ms": 70.0, "fps": 14.0}, floor)
    ['step 1.75x the floor', 'drag 0.56x the floor']
    >>> missed({"app": "checkerboards_outside", "median_ms": 50.0, "fps": 11.0}, floor)
    ['drag 0.44x the floor', 'drag 11.0 fps < 12']
    """
    step, fps = ratios(row, floor)
    found = []
    if step == step and step > STEP_RATIO:
        found.append(f"step {step:.2f}x the floor")
    if fps == fps and fps < FPS_RATIO:
        found.append(f"drag {fps:.2f}x the floor")
    if row["app"].startswith("checkerboards") and row.get("fps", math.inf) < CHECKERBOARDS_FPS:
        found.append(f"drag {row['fps']:.1f} fps < {CHECKERBOARDS_FPS:.0f}")
    return found


def format_verdict(rows: list[dict]) -> str:
    """The lines after the table: each app's ratios to the picture floor of the same run, and
    which rows meet the targets."""
    floors = [row for row in rows if row.get("floor") == "picture" and "median_ms" in row]
    if not floors:
        return "no picture floor measured: no ratios"
    floor = floors[0]
    measured = [
        row for row in rows if "median_ms" in row and "error" not in row and not row.get("floor")
    ]
    lines = [
        f"ratios to the picture floor (step {floor['median_ms']:.1f} ms, drag "
        f"{floor.get('fps', math.nan):.1f} fps); targets: step <= {STEP_RATIO}x, drag >= "
        f"{FPS_RATIO}x, lesson 6's checkerboards >= {CHECKERBOARDS_FPS:.0f} fps"
    ]
    for row in measured:
        step, fps = ratios(row, floor)
        misses = missed(row, floor)
        lines.append(
            f"  {row['app']:<34} step {step:5.2f}x  drag {fps:5.2f}x  "
            + ("ok" if not misses else "missed: " + ", ".join(misses))
        )
    met = sum(not missed(row, floor) for row in measured)
    lines.append(f"met by {met} of {len(measured)} rows")
    return "\n".join(lines)


def format_cpu(used: dict[str, float]) -> str:
    """The lines under an app's row that say where the CPU went in its key steps."""
    text = f"CPU ms a key step, {sum(used.values()):.0f} in all: " + ", ".join(
        f"{label} {ms:.1f}" for label, ms in used.items()
    )
    return textwrap.fill(text, 100, initial_indent="    ", subsequent_indent="      ")


# ------------------------------------------------------------------------ fits the screen

#: Where each app is measured: (label, viewport, JupyterLab with the file browser or Voilà).
SCREENS = (
    ("Lab 1280x800", {"width": 1280, "height": 800}),
    ("Lab 1920x1080", {"width": 1920, "height": 1080}),
    ("Voila pres. 1280x720", {"width": 1280, "height": 720}),
)


def fit(browser, tree: Path = ROOT) -> dict[str, dict[str, dict]]:
    """For each app and screen: how many CSS px it reaches past the visible right edge
    (``browser.overflow``), and its height."""
    names = [name for names in lessons(tree).values() for name in names]
    found = {name: {} for name in names}
    with tempfile.TemporaryDirectory() as tmp, server("lab", Path(tmp), tree=tree) as base:
        context = browser.new_context(viewport=SCREENS[0][1])
        context.add_init_script(FRAME_PROBE)
        for notebook, apps in lessons(tree).items():
            page = new_page(context)
            open_lesson(page, base, notebook, file_browser=True)
            for label, viewport in SCREENS[:2]:
                page.set_viewport_size(viewport)
                show_file_browser(page)
                for name in apps:
                    found[name][label] = overflow(app_root(page, name))
            shutdown_kernels(page)
            page.close()
        context.close()
    with tempfile.TemporaryDirectory() as tmp:
        env = {"INTERP_PRESENTATION": "1"}
        with server("voila", Path(tmp), env=env, tree=tree) as base:
            write_all_apps_notebook(Path(tmp) / "lessons" / "all_apps.ipynb", names)
            label, viewport = SCREENS[2]
            context = browser.new_context(viewport=viewport)
            context.route(
                "https://cdn.jsdelivr.net/npm/@fortawesome/**",
                lambda route: route.fulfill(status=200, content_type="text/css", body=""),
            )
            page = new_page(context)
            open_voila_apps(page, f"{base}/voila/render/all_apps.ipynb", names)
            for name in names:
                found[name][label] = overflow(page.locator(f'[data-app="{name}"]').first)
            context.close()
    return found


def print_fit(found: dict[str, dict[str, dict]]) -> None:
    print("px past the visible right edge (> 0: cut off or scrolled sideways); figure width")
    print(f"{'app':<20}" + "".join(f"{label:>24}" for label, _ in SCREENS) + "   app height")
    for name, screens in found.items():
        cells = []
        for label, _ in SCREENS:
            m = screens[label]
            cells.append(f"{m['overflow']:>+6} (fig {m['width']:>4} px)".rjust(24))
        heights = "/".join(str(screens[label]["height"]) for label, _ in SCREENS)
        print(f"{name:<20}" + "".join(cells) + f"   {heights}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=int, default=15, help="slider steps per app (15)")
    parser.add_argument("--seconds", type=float, default=3.0, help="length of each drag (3 s)")
    parser.add_argument(
        "--drags", type=int, default=5, help="drags per row, judged by their medians (5)"
    )
    parser.add_argument("--only", nargs="*", help="only these apps (names as in apps.ALL)")
    parser.add_argument("--json", type=Path, help="also write the rows to this JSON file")
    parser.add_argument("--save", type=Path, help="save wrong final pictures in this folder")
    parser.add_argument(
        "--fit", action="store_true", help="measure instead whether each app fits the screen"
    )
    parser.add_argument("--no-dpr2", action="store_true", help="skip the HiDPI run")
    parser.add_argument(
        "--cpu",
        action="store_true",
        help="under each app, the CPU each process and thread used a key step (Linux)",
    )
    parser.add_argument("--no-endpoints", action="store_true", help="skip dragging A")
    parser.add_argument(
        "--slider",
        action="append",
        default=[],
        metavar="APP=PARAM",
        help="step and drag APP by its slider PARAM instead of the usual one"
        " (e.g. checkerboards_outside=frequency); may be given again for other apps",
    )
    parser.add_argument(
        "--no-floor",
        action="store_true",
        help="skip the floors (a slider and a text label; a slider and a picture)",
    )
    parser.add_argument(
        "--drag",
        choices=("page", "playwright"),
        default="page",
        help="how drags move the mouse: a move per animation frame made in the page, as a real"
        " mouse's arrive (default), or Playwright's page.mouse.move every 16 ms",
    )
    parser.add_argument(
        "--tree",
        type=Path,
        default=ROOT,
        help="the checkout to measure: its lessons and its interp (default: this one)",
    )
    args = parser.parse_args(argv)
    if args.drags < 1:
        parser.error(f"--drags must be at least 1, got {args.drags}")
    args.tree = args.tree.resolve()
    sys.path.insert(0, str(args.tree))  # the apps' parameters come from the checkout measured
    for choice in args.slider:
        app, _, param = choice.partition("=")
        if app not in STEP_PARAM:
            parser.error(f"--slider {choice}: no app {app!r} with sliders, in {list(STEP_PARAM)}")
        try:
            slider = figure_param(app, param).step is not None
        except KeyError:
            slider = False
        if not slider:
            parser.error(f"--slider {choice}: {app} has no slider {param!r}")
        STEP_PARAM[app] = param
    if not os.path.exists(CHROMIUM):
        print(f"no Chromium at {CHROMIUM} (apt-get install chromium)", file=sys.stderr)
        return 2
    from playwright.sync_api import sync_playwright

    if args.fit:
        with sync_playwright() as playwright:
            browser = chromium(playwright)
            found = fit(browser, args.tree)
            browser.close()
        print_fit(found)
        if args.json:
            args.json.write_text(json.dumps(found, indent=1))
        return 0
    started = time.monotonic()
    before = machine_line()
    print(f"interp browser benchmark, {time.strftime('%Y-%m-%d %H:%M')}, {platform.node()}")
    print(f"{chromium_version()}; viewport {VIEWPORT['width']}x{VIEWPORT['height']}")
    print(f"machine before: {before}")
    print(f"measuring {tree_line(args.tree)}")
    print(
        "step: key press -> first changed canvas picture (median, p90 of "
        f"{args.steps}); fps: distinct pictures/s during a {args.seconds:g} s mouse drag; "
        f"moves: mouse moves/s in it (made by {args.drag}); "
        "settle: mouse-up -> last change (worst: the longest); fps, moves, settle, busy and "
        f"CPU/pic: medians of {args.drags} drags; after: pictures shown after the first "
        "drag's mouse-up; busy: how busy "
        "the machine's CPUs were during the drag; CPU/pic: the machine's CPU time in it, per "
        "picture shown"
    )
    print(HEADER)
    rows = []
    with tempfile.TemporaryDirectory() as tmp, server("lab", Path(tmp), tree=args.tree) as base:
        folder = Path(tmp) / "lessons"  # the server's copy of the lessons
        with sync_playwright() as playwright:
            browser = chromium(playwright)
            context = browser.new_context(viewport=VIEWPORT)
            context.add_init_script(FRAME_PROBE)
            if not args.no_floor:
                rows.append(bench_floor(context, base, folder, args.steps))
                print(format_row(rows[-1]), flush=True)
                for after in (None, FLOOR_LESSON):
                    rows.append(bench_floor_picture(context, base, folder, args, after=after))
                    print(format_row(rows[-1]), flush=True)
                    if rows[-1].get("cpu_ms_per_step"):
                        print(format_cpu(rows[-1]["cpu_ms_per_step"]), flush=True)
            for notebook, names in lessons(args.tree).items():
                if args.only and not set(names) & set(args.only):
                    continue
                rows += bench_lesson(context, base, notebook, names, args, only=args.only)
            context.close()
            hidpi = lessons(args.tree)["06_checkerboards.ipynb"][:1]  # its checkerboards
            if not args.no_dpr2 and (not args.only or set(hidpi) & set(args.only)):
                context = browser.new_context(viewport=VIEWPORT, device_scale_factor=2)
                context.add_init_script(FRAME_PROBE)
                if not args.no_floor:
                    rows.append(bench_floor_picture(context, base, folder, args, label=" @2x"))
                    print(format_row(rows[-1]), flush=True)
                rows += bench_lesson(
                    context, base, "06_checkerboards.ipynb", hidpi, args, label=" @2x",
                    only=hidpi,
                )  # fmt: skip
                context.close()
            browser.close()
    after = machine_line()
    errors = sorted({e for row in rows for e in row.get("console_errors", [])})
    print()
    print(format_verdict(rows))
    print("machine after:  " + after)
    print(f"kernels imported interp from {KERNEL_INTERP[0] if KERNEL_INTERP else '?'}")
    print(f"console errors: {len(errors)}" + "".join(f"\n  {e[:200]}" for e in errors))
    print(f"total {time.monotonic() - started:.0f} s")
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(
            json.dumps({"machine_before": before, "machine_after": after, "rows": rows}, indent=1)
        )
        print(f"wrote {args.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
