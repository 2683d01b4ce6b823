"""The machinery every live figure shares: one figure, its controls, updates in place.

An app creates its figure once, under ``plt.ioff()`` and the package style, from a lesson
figure of :mod:`interp.plots.registry`, and never rebuilds it: a change of any control calls
the figure's ``update(**values)``, and then the canvas redraws. The app holds no math and no
layout of its own: one control per parameter, with the parameter's range and label.

- With ipympl (``%matplotlib widget``) the canvas is itself a widget: the app shows the
  controls beside it and redraws with ``draw_idle``.
- Without it (the inline backend, a static HTML export), the app displays the figure as an image
  once, with a display id, and replaces that image after each change: the same call still
  shows a correct figure.
"""

from __future__ import annotations

import asyncio
import math
import os
import time
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from html import escape

import ipywidgets as widgets
import matplotlib.pyplot as plt
import numpy as np
from IPython.display import HTML, Javascript, display

from interp._allocator import keep_freed_memory
from interp.apps._live import (
    DRAW_LOCK,
    FRAME_JS,
    LIVE_RATIO,
    QUIET_CURSORS_JS,
    RELEASED,
    SEND_HELD_JS,
    SHARPEN,
    Blitter,
    Coalescer,
    cheap_frames,
    drawn_at,
    take_turns,
)
from interp.plots import styled
from interp.plots.params import Param
from interp.plots.registry import LessonFigure

#: Presentation mode: larger fonts and controls for a projector (see :func:`presentation`);
#: also on when the environment variable INTERP_PRESENTATION is 1 (``make present`` sets it).
_PRESENTATION = {"on": os.environ.get("INTERP_PRESENTATION") == "1"}


#: Names every slider for screen readers. ipywidgets draws a slider's handle as an element of
#: role "slider" (with its value) but leaves it nameless, and the description beside it is not
#: tied to it; this sets the handle's ``aria-label`` to that description, for sliders drawn now
#: and later (one observer per page, which looks only when elements are added or a label
#: changes).
SLIDER_NAMES_JS = """
(() => {
  if (window.interpNameSliders) { window.interpNameSliders(); return; }
  const nameSliders = () => {
    for (const box of document.querySelectorAll('.widget-slider')) {
      const label = box.querySelector('.widget-label');
      const text = label ? label.textContent.trim() : '';
      if (!text) continue;
      for (const handle of box.querySelectorAll('[role="slider"]')) {
        if (handle.getAttribute('aria-label') !== text) handle.setAttribute('aria-label', text);
      }
    }
  };
  window.interpNameSliders = nameSliders;
  // Looked at again when elements are added (a slider drawn) or a label's text changes; not
  // for the text a slider step changes (its readout, the kernel's status, a prompt), as each
  // look goes through the whole page.
  const mayName = (mutation) =>
    (mutation.target.closest && mutation.target.closest('.widget-label'))
    || Array.from(mutation.addedNodes).some((node) => node.nodeType === Node.ELEMENT_NODE);
  new MutationObserver((mutations) => { if (mutations.some(mayName)) nameSliders(); })
      .observe(document.body, {childList: true, subtree: true});
  nameSliders();
})();
"""


#: A live figure's readout (its key result, in words) is shown once the figure has not changed
#: for this long (seconds), not with every frame: while a slider is dragged the words could not
#: be read anyway, a screen reader announces the result once rather than twenty times a second,
#: and the page is spared a layout of new text on every frame, which on a two-core machine
#: competes with the kernel drawing the next one (lesson 1's drag: 24 -> 31 frames a second,
#: medians of three interleaved runs).
READOUT_DELAY = 0.1


def presentation(on: bool = True) -> None:
    """Switch presentation mode for apps made afterwards: larger figures, fonts and controls.

    Examples
    --------
    >>> presentation(True); presentation(False)
    """
    _PRESENTATION["on"] = bool(on)


#: The box an app's figure must fit, in inches at 100 dpi: a notebook's output area on a
#: 1280 x 800 laptop screen with JupyterLab's file browser open is 848 px wide.
FIT = (8.2, 6.0)
#: In presentation mode: what fits on a 1280 x 720 projector beside a row or two of controls.
FIT_PRESENTATION = (11.6, 5.0)
#: How much larger text is in presentation mode.
PRESENTATION_TEXT = 1.5
#: Presentation mode's page style: larger prose and controls (Voilà and JupyterLab).
PRESENTATION_CSS = """<style>
.jp-RenderedHTMLCommon, .jp-RenderedMarkdown { font-size: 21px; }
.jp-RenderedHTMLCommon h1 { font-size: 2em; } .jp-RenderedHTMLCommon h2 { font-size: 1.6em; }
.widget-label, .widget-readout, .widget-dropdown select, .widget-inline-hbox label,
.interp-readout { font-size: 19px !important; line-height: 1.4; }
.widget-slider .noUi-handle { transform: scale(1.3); }
</style>"""


def figure_size(size: tuple[float, float], presentation: bool) -> tuple[float, float]:
    """The size an app draws a figure of nominal ``size`` at: shrunk to fit :data:`FIT` (or, in
    presentation mode, grown by up to 1.4 within :data:`FIT_PRESENTATION`), shape kept.

    Examples
    --------
    >>> figure_size((9.5, 2.9), False)          # too wide for a laptop's notebook: shrunk
    (8.2, 2.5)
    >>> figure_size((6.5, 5.0), True)           # a projector: larger, but no taller than fits
    (6.5, 5.0)
    """
    width, height = size
    box_width, box_height = FIT_PRESENTATION if presentation else FIT
    scale = min(1.4 if presentation else 1.0, box_width / width, box_height / height)
    return round(width * scale, 2), round(height * scale, 2)


class App:
    """A lesson figure with one control per parameter.

    Parameters
    ----------
    figure_class : type of LessonFigure
        From :data:`interp.plots.registry.FIGURES`: it says which parameters there are, their
        ranges and labels, and how to draw.

    Examples
    --------
    >>> from interp.plots.registry import STMapping
    >>> app = App(STMapping)
    >>> app.set(w2=9.0)
    >>> app.plot.gap.derived
    (0.75, 0.5)
    """

    def __init__(self, figure_class: type[LessonFigure]) -> None:
        keep_freed_memory()  # sliders feel live: numpy's temporaries are recycled
        presenting = _PRESENTATION["on"]
        width, height = figure_size(figure_class.size, presenting)
        scale = PRESENTATION_TEXT if presenting else 1.0
        self.controls = {name: control(param) for name, param in figure_class.PARAMS.items()}
        self._style = {"font.size": 9 * scale}
        with DRAW_LOCK, styled(**self._style), plt.ioff():  # see interp.apps._live.DRAW_LOCK
            self.figure = plt.figure(figsize=(width, height))
            self.plot = figure_class(self.figure, **self.values)
            # Lay the figure out once, then freeze it: constrained layout would otherwise redo
            # its work (about half of a redraw) on every slider step, for a figure whose shape
            # never changes.
            self.figure.get_layout_engine().execute(self.figure)
            self.figure.set_layout_engine("none")
        take_turns(self.figure.canvas)
        # The app redraws its figure itself on every change. pyplot's auto-draw (on under
        # %matplotlib widget) turned each changed artist into a draw_idle, which ipympl sends
        # to the browser, which asks back for a full redraw: one more whole frame after every
        # blitted one.
        self.figure.stale_callback = None
        for widget in self.controls.values():
            if presenting:  # three controls to a row on a 1280 px projector
                widget.layout.width = "380px"
            widget.observe(self._changed, names="value")
        self._handle = None  # the figure is drawn already; displaying it shows that drawing
        #: The figure's key result as text (a live region: screen readers announce changes).
        self.readout = widgets.HTML(self._readout_html())
        self._readout_handle = None
        self._readout_timer: asyncio.TimerHandle | None = None
        self.blitter = Blitter(self.figure, self.plot.dynamic, self.plot.backdrop)
        #: Draws the live frames of a HiDPI screen, at :data:`LIVE_RATIO` (made when needed).
        self.live_blitter: Blitter | None = None
        self._sharpen_timer: asyncio.TimerHandle | None = None
        self.coalescer = Coalescer(lambda: self.refresh(following=self.coalescer.following))
        if self.live:
            cheap_frames(self.figure.canvas)
            # ipympl's view redraws its last image whenever the widget's size changes; a view
            # that has not received an image yet fails there ("HTMLImageElement ... 'broken'
            # state") and may stay blank. So the size is right before any view exists, and
            # each view that reports ready gets a full frame at once.
            self.figure.canvas.manager.resize(*self.figure.bbox.size)
            self.figure.canvas.on_msg(self._canvas_message)

    @property
    def values(self) -> dict[str, object]:
        """The controls' current values, by name."""
        return {name: widget.value for name, widget in self.controls.items()}

    def set(self, **values: object) -> None:
        """Set several controls at once and redraw once (as a slider drag does per step)."""
        for name in values:
            if name not in self.controls:
                raise TypeError(f"no control named {name!r}; controls: {list(self.controls)}")
        with self._holding():
            for name, value in values.items():
                self.controls[name].value = value
        self.refresh()

    def refresh(self, following: bool = False) -> None:
        """Draw with the controls' values and show the result.

        ``following``: the change follows the last one within a moment (a drag, a key held
        down); on a HiDPI screen its frame is then drawn at :data:`LIVE_RATIO`, and the figure
        again at the screen's ratio once the changes stop.
        """
        with DRAW_LOCK:  # a slider's thread, ipympl's and a cell's take turns
            # Stale before the update: a cell changed the figure itself (a label, say), which
            # the blit's background does not know; then pyplot's full redraw must still come.
            changed_outside = self.figure.stale
            if changed_outside:  # no saved background has that change
                for blitter in (self.blitter, self.live_blitter):
                    if blitter is not None:
                        blitter.forget()
            with styled(**self._style):  # titles set now must look like those set at the start
                self.plot.update(**self.values)
            if self.live:
                self._draw_frame(following)  # at once: no round trip through the browser
                self.figure.stale = changed_outside
            elif self._handle is not None:
                self._handle.update(self.figure, metadata=self._image_metadata())
        if self.live:
            self._readout_soon()
        else:
            self._show_readout()

    def _frame_ratio(self, following: bool) -> float:
        """The device pixel ratio to draw the next frame at: the screen's, or
        :data:`LIVE_RATIO` for a change that follows another on a HiDPI screen whose page
        scales frames up (it says so once it has decoded a frame of ours), inside a running
        event loop (which draws the sharp frame afterwards), unless the page has just said
        that the control was let go (:data:`RELEASED`)."""
        canvas = self.figure.canvas
        shown = canvas.device_pixel_ratio
        if not (following and shown > LIVE_RATIO):
            return shown
        if not getattr(canvas, "interp_scaled_frames", False):
            return shown
        if time.monotonic() - getattr(canvas, "interp_released_at", -math.inf) <= RELEASED:
            return shown
        try:
            asyncio.get_running_loop()
        except RuntimeError:
            return shown
        return LIVE_RATIO

    def _draw_frame(self, following: bool) -> None:
        """Send a frame of the live figure as it is, drawn at :meth:`_frame_ratio`; one below
        the screen's is followed by a sharp one once no change has come for :data:`SHARPEN`."""
        ratio = self._frame_ratio(following)
        if self._sharpen_timer is not None:
            self._sharpen_timer.cancel()
            self._sharpen_timer = None
        if ratio == self.figure.canvas.device_pixel_ratio:
            self.blitter.draw()
            return
        if self.live_blitter is None:
            self.live_blitter = Blitter(self.figure, self.plot.dynamic, self.plot.backdrop)
        try:
            with drawn_at(self.figure.canvas, ratio):
                self.live_blitter.draw()
        finally:  # whatever happened, the screen's ratio follows
            self._sharpen_timer = asyncio.get_running_loop().call_later(SHARPEN, self._sharpen)

    def _sharpen(self) -> None:
        """Draw the figure, unchanged since its last frame, at the screen's ratio (unless a
        change is about to be drawn: its frame sets the timer again)."""
        self._sharpen_timer = None
        if self.coalescer.pending:
            return
        with DRAW_LOCK:
            stale = self.figure.stale
            self.blitter.draw()
            self.figure.stale = stale

    def _readout_soon(self) -> None:
        """Show the readout once the figure has stopped changing for :data:`READOUT_DELAY`
        (at once where no event loop runs: a script, a test)."""
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:
            self._show_readout()
            return
        if self._readout_timer is not None:
            self._readout_timer.cancel()
        self._readout_timer = loop.call_later(READOUT_DELAY, self._show_readout)

    def _show_readout(self) -> None:
        """Put the readout of the figure as it is now on the page."""
        self._readout_timer = None
        with DRAW_LOCK:
            html = self._readout_html()
        self.readout.value = html  # the same text again changes nothing (traitlets compares)
        if self._readout_handle is not None:
            self._readout_handle.update(HTML(html))

    def _canvas_message(self, canvas: object, content: dict, buffers: list) -> None:
        """After ipympl's own handler: send a fresh full frame to a view that just appeared.

        A page that appears may not scale frames of a lower ratio up (a page reloaded does not
        run the apps' page script again): until it says it does, frames are sharp.
        """
        if content.get("type") == "initialized":
            with DRAW_LOCK:
                canvas.interp_scaled_frames = False
                self.figure.canvas._force_full = True
                self.blitter.draw()

    @property
    def live(self) -> bool:
        """Whether the figure is a live ipympl canvas."""
        return isinstance(self.figure.canvas, widgets.DOMWidget)

    @property
    def widget(self) -> widgets.Widget:
        """The controls in rows that wrap, and with ipympl the live figure below them, where it
        has the whole width of the page."""
        panel = widgets.Box(
            list(self.controls.values()),
            layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
        )
        if self.live:
            self.figure.canvas.header_visible = False
            self.figure.canvas.toolbar_position = "left"
            return widgets.VBox([panel, self.figure.canvas, self.readout])
        return panel

    def _ipython_display_(self) -> None:
        if _PRESENTATION["on"]:  # larger prose and controls on the whole page
            display(HTML(PRESENTATION_CSS))
        # One script: the sliders' names, and with ipympl the frames' fast path.
        display(
            Javascript(
                SLIDER_NAMES_JS + (FRAME_JS + QUIET_CURSORS_JS + SEND_HELD_JS if self.live else "")
            )
        )
        if self.live:
            display(self.widget)
        else:  # a picture with alt text, the result as text, then the controls
            self._handle = display(self.figure, display_id=True, metadata=self._image_metadata())
            self._readout_handle = display(HTML(self.readout.value), display_id=True)
            display(self.widget)

    def _readout_html(self) -> str:
        text = self.plot.readout()
        if not text:
            return ""
        return f'<p class="interp-readout" role="status" aria-live="polite">{escape(text)}</p>'

    def _image_metadata(self) -> dict:
        """Alt text for the static picture: the figure's title and its key result."""
        alt = f"{self.plot.title}. {self.plot.readout()}".strip()
        return {"image/png": {"alt": alt}}

    _holding_depth = 0

    @contextmanager
    def _holding(self) -> Iterator[None]:
        """While inside, control changes do not redraw (``set`` redraws once at the end)."""
        self._holding_depth += 1
        try:
            yield
        finally:
            self._holding_depth -= 1

    def _changed(self, change: dict) -> None:
        if self._holding_depth == 0:
            self.coalescer.request()  # latest value wins: see interp.apps._live


def control(param: Param) -> widgets.ValueWidget:
    """The widget for one parameter: a drop-down for choices, else a slider; its value not
    echoed (:func:`no_echo`)."""
    if param.options is not None:
        widget = choice(str(param.default), param.options, param.label)
    elif param.kind is int:
        widget = int_slider(int(param.default), int(param.low), int(param.high), param.label)
    else:
        widget = slider(
            float(param.default),
            float(param.low),
            float(param.high),
            float(param.step),
            param.label,
            log=param.log,
            readout_format=param.fmt,
        )
    return no_echo(widget)


def no_echo(widget: widgets.ValueWidget) -> widgets.ValueWidget:
    """``widget``, whose kernel side no longer echoes each value the page sends back to it.

    ipywidgets 8 answers every change made in a page with an ``echo_update`` message, so that
    other pages showing the same kernel's widget follow. A slider dragged sends a change per
    mouse move; each echo was one more message for the kernel to send, the server to pass on
    and the page to take in, on the two cores the kernel's drawing shares. An app's controls
    live in one page (a student's, or a teacher's projector), so the echo of their ``value``
    is turned off, as ipywidgets lets a trait do (its ``echo_update`` metadata), for this
    widget only: a second browser tab on the same kernel no longer follows a slider dragged in
    the first. Values set in the kernel (``App.set``) still reach the page. (traitlets reads
    a widget's own ``_<trait>_metadata`` before the trait's; a ``Union`` trait would write
    over it, which the controls' value traits are not.)

    Examples
    --------
    >>> slider = no_echo(widgets.IntSlider(3))
    >>> slider.trait_metadata("value", "echo_update"), slider.trait_metadata("value", "sync")
    (False, True)
    """
    for name in ("value", "index"):  # what a page changes: a drop-down sends its index
        if widget.has_trait(name) and widget.trait_metadata(name, "sync"):
            setattr(widget, f"_{name}_metadata", {"echo_update": False})  # for this one only
    return widget


def slider(
    value: float,
    low: float,
    high: float,
    step: float,
    description: str,
    log: bool = False,
    readout_format: str = ".2f",
) -> widgets.ValueWidget:
    """A float slider that updates while it is dragged.

    With ``log``, ``low`` and ``high`` are the value's bounds and the slider moves in powers
    of ten.
    """
    common = {
        "description": description,
        "continuous_update": True,
        "readout_format": readout_format,
        "style": {"description_width": "initial"},
    }
    if log:
        return widgets.FloatLogSlider(
            value=value,
            base=10,
            min=float(np.log10(low)),
            max=float(np.log10(high)),
            step=step,
            **common,
        )
    return widgets.FloatSlider(value=value, min=low, max=high, step=step, **common)


def on_slider(control: widgets.FloatSlider, value: float) -> float:
    """The value ``control``'s slider in the page takes for ``value``: within its range and on
    its steps, computed as that slider computes it.

    The page's slider (noUiSlider, drawn by ipywidgets) snaps a value the kernel sets to its
    steps, in percent of its range, and sends the result back when it is not the very same
    number, as a change made in the page. An endpoint dragged in lesson 2's figure set A's
    depth to 7.743...; the page answered 7.75, and the app drew a second frame for each mouse
    move, and one more after the mouse was let go. So the kernel sets what the page would:
    sometimes not the decimal itself (8.450000000000001 for 8.45), which is why this copies
    the page's arithmetic rather than rounding to the step.

    Examples
    --------
    >>> depth = widgets.FloatSlider(min=0.5, max=9.5, step=0.05)
    >>> on_slider(depth, 7.743134378535013), on_slider(depth, 8.452230210293749)
    (7.75, 8.450000000000001)
    >>> on_slider(depth, 0.1), on_slider(depth, 9.49)
    (0.5, 9.5)
    """
    low, high, step = float(control.min), float(control.max), float(control.step)
    if value <= low:
        return low
    if value >= high:
        return high
    span = high - low
    percent = 100 * (value - low) / span  # noUiSlider's toStepping, one range from 0 to 100 %
    if percent >= 100:  # getStep keeps 100 as it is
        return high
    steps = 100 * step / span
    ratio = percent / steps
    whole = math.floor(ratio)
    if ratio - whole >= 0.5:  # JavaScript's Math.round (x - floor(x) is exact; x + 0.5 is not)
        whole += 1
    percent = whole * steps  # its getStep
    if percent >= 100:  # clamped to the range
        return high
    return percent * span / 100 + low  # its fromStepping


def int_slider(value: int, low: int, high: int, description: str) -> widgets.IntSlider:
    """An integer slider that updates while it is dragged."""
    return widgets.IntSlider(
        value=value,
        min=low,
        max=high,
        description=description,
        continuous_update=True,
        style={"description_width": "initial"},
    )


def choice(value: str, options: Iterable[str], description: str) -> widgets.Dropdown:
    """A drop-down list."""
    return widgets.Dropdown(
        value=value,
        options=list(options),
        description=description,
        style={"description_width": "initial"},
    )
