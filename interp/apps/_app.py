"""The machinery every live figure shares: one figure, its controls, updates in place.

An app creates its figure once, under ``plt.ioff()`` and the package style, from a lesson
figure of :mod:`interp.plots.registry`, and never rebuilds it: a change of any control calls
the figure's ``update(**values)``, and then the canvas shows the result. The app holds no math
and no layout of its own: one control per parameter, with the parameter's range and label.

- With ipympl (``%matplotlib widget``) the canvas is itself a widget: the app shows the
  controls beside it, and each step is blitted (:mod:`interp.apps._blit`).
- Without it (the inline backend, a static HTML export), the app displays the figure as an image
  once, with a display id, and replaces that image after each change: the same call still
  shows a correct figure.

One slider step, in the order it runs: ``App._changed`` (the control's ``observe`` callback)
asks ``App.coalescer`` for a draw; ``App.refresh`` calls ``plot.update(**values)``;
``Blitter.draw`` puts the new pixels on the canvas and ipympl sends them to the page.
"""

from __future__ import annotations

import asyncio
import functools
import math
import os
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from html import escape

import ipywidgets as widgets
import matplotlib
import matplotlib.pyplot as plt
import numpy as np
from IPython.display import HTML, display
from matplotlib.figure import Figure

from interp.apps._blit import DRAW_LOCK, Blitter, Coalescer
from interp.plots import styled
from interp.plots.params import CAMERA_RANGES, Param
from interp.plots.registry import LessonFigure

#: Presentation mode: larger fonts and controls for a projector (see :func:`presentation`);
#: also on when the environment variable INTERP_PRESENTATION is 1 (``make present`` sets it).
_PRESENTATION = {"on": os.environ.get("INTERP_PRESENTATION") == "1"}

#: A live figure's readout (its key result, in words) is shown once the figure has not changed
#: for this long (seconds), not with every frame: while a slider is dragged the words could not
#: be read anyway, a screen reader announces the result once rather than twenty times a second,
#: and the page is spared a layout of new text on every frame.
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
#: The width of one control, in pixels: three to a row in a laptop's 848 px output area, with
#: room for the gaps between them.
CONTROL_WIDTH = 260
#: Presentation mode's page style: larger prose, and larger text in the apps' own controls
#: (each app's box has the class ``interp-app``).
PRESENTATION_CSS = """<style>
.jp-RenderedHTMLCommon, .jp-RenderedMarkdown { font-size: 21px; }
.jp-RenderedHTMLCommon h1 { font-size: 2em; } .jp-RenderedHTMLCommon h2 { font-size: 1.6em; }
.interp-app .widget-label, .interp-app .widget-readout, .interp-app .widget-dropdown select,
.interp-app .widget-inline-hbox label, .interp-app .lm-TabBar-tab,
.interp-readout { font-size: 19px !important; line-height: 1.4; }
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
        presenting = _PRESENTATION["on"]
        width, height = figure_size(figure_class.size, presenting)
        scale = PRESENTATION_TEXT if presenting else 1.0
        self.controls = {name: control(param) for name, param in figure_class.PARAMS.items()}
        self._style = {"font.size": 9 * scale}
        with DRAW_LOCK, styled(**self._style), plt.ioff():
            self.figure = new_figure((width, height))
            self.plot = figure_class(self.figure, **self.values)
            # Lay the figure out once, then freeze it: constrained layout would otherwise redo
            # its work (about half of a redraw) on every full draw, for a figure whose shape
            # never changes.
            self.figure.get_layout_engine().execute(self.figure)
            self.figure.set_layout_engine("none")
        for widget in self.controls.values():
            widget.layout.width = f"{round(CONTROL_WIDTH * scale)}px"
            widget.observe(self._changed, names="value")
        self._handle = None  # the static picture's display handle, once shown
        #: The figure's key result as text (a live region: screen readers announce changes).
        self.readout = widgets.HTML(self._readout_html())
        self._readout_handle = None
        self._readout_timer: asyncio.TimerHandle | None = None
        self.coalescer = Coalescer(self.refresh)
        self.blitter: Blitter | None = None
        canvas = self.figure.canvas
        if self.live:
            self.blitter = Blitter(self.figure, self.plot.dynamic)
        if isinstance(canvas, widgets.DOMWidget):  # ipympl's
            # Every frame whole: ipympl sends a frame as the pixels that changed since the last
            # unless the figure has transparent pixels, and a page that gets frames faster than
            # it loads them drops some, leaving the curves of earlier steps behind. A figure
            # whose background is all but opaque (alpha 254/255, which no eye sees) is sent
            # whole every time.
            self.figure.patch.set_alpha(WHOLE_FRAMES_ALPHA)
            canvas.header_visible = False
            canvas.toolbar_position = "left"
            # ipympl's view redraws its last picture whenever the widget's size changes; a view
            # that has no picture yet may stay blank. So the size is right before any view
            # exists, and a page that says it is ready gets a whole frame at once.
            canvas.manager.resize(*self.figure.bbox.size)
            canvas.on_msg(self._canvas_message)
            canvas.add_class("interp-app")
        self._update_disabled()

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

    def refresh(self) -> None:
        """Draw with the controls' values and show the result."""
        with DRAW_LOCK:
            with styled(**self._style):  # titles set now must look like those set at the start
                self.plot.update(**self.values)
            if self.blitter is not None:
                self.blitter.draw()
            elif self._handle is not None:
                self._handle.update(self.figure, metadata=self._image_metadata())
        self._update_disabled()
        if self.live:
            self._readout_soon()
        else:
            self._show_readout()

    def _update_disabled(self) -> None:
        """Disable the controls that do nothing with the others' values, saying why."""
        inactive = self.plot.inactive()
        for name, widget in self.controls.items():
            why = inactive.get(name, "")
            if widget.disabled != bool(why):
                widget.disabled = bool(why)
            widget.tooltip = why or None

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
        """After ipympl's own handler: a view that says it is ready gets the figure at once,
        without waiting for its request to draw (the page may show a blank canvas until then).
        """
        if content.get("type") == "initialized":
            with DRAW_LOCK:
                self.figure.canvas.draw()

    @property
    def live(self) -> bool:
        """Whether the figure is a live ipympl canvas."""
        return isinstance(self.figure.canvas, widgets.DOMWidget)

    @property
    def panel(self) -> widgets.Widget:
        """The controls: up to nine in rows of three; more in two tabs, the camera's first."""
        return controls_panel(self.controls)

    @property
    def widget(self) -> widgets.Widget:
        """The controls above the live figure and its readout (with ipympl), or the controls
        alone (the static figure is shown apart), in one box."""
        parts = [self.panel]
        if self.live:
            parts += [self.figure.canvas, self.readout]
        box = widgets.VBox(parts)
        box.add_class("interp-app")
        return box

    def _ipython_display_(self) -> None:
        """The controls, the figure and its readout, each an output of its own.

        The live canvas is displayed itself, not inside a box: ipympl then gives the output a
        picture of the figure (a PNG, for a notebook saved or exported before any page showed
        it), and the page's first view starts from that picture rather than a blank canvas.
        """
        if _PRESENTATION["on"]:  # larger prose and controls on the whole page
            display(HTML(PRESENTATION_CSS))
        panel = self.panel
        panel.add_class("interp-app")
        if self.live:
            display(panel)
            with DRAW_LOCK:
                display(self.figure.canvas)
            self.readout.add_class("interp-app")
            display(self.readout)
        else:  # a picture with alt text, the result as text, then the controls
            self._handle = display(self.figure, display_id=True, metadata=self._image_metadata())
            self._readout_handle = display(HTML(self.readout.value), display_id=True)
            display(panel)

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
            self.coalescer.request()  # latest value wins: see interp.apps._blit


#: The names matplotlib gives ipympl's backend (``%matplotlib widget``, ``ipympl``).
IPYMPL_BACKENDS = ("widget", "ipympl", "module://ipympl.backend_nbagg")


def new_figure(size: tuple[float, float]) -> Figure:
    """A figure of ``size`` inches: on a live canvas of ours where ipympl is the backend, else
    pyplot's.

    ipykernel handles widget messages on a thread beside the one that runs cells, so ipympl's
    own full draws (the page's requests) can run while a cell builds another app under the
    style sheet's rcParams; the canvas takes :data:`DRAW_LOCK` for them, as the apps do for
    theirs. It is made as pyplot makes one for ipympl (a canvas and its manager), without
    pyplot's list of open figures, which would keep every app's figure alive.

    Examples
    --------
    >>> new_figure((2.0, 1.0)).get_size_inches().tolist()
    [2.0, 1.0]
    """
    if matplotlib.get_backend() not in IPYMPL_BACKENDS:
        return plt.figure(figsize=size)
    from ipympl.backend_nbagg import FigureManager

    figure = Figure(figsize=size)
    FigureManager(_taking_turns_canvas()(figure), 0)
    return figure


@functools.cache
def _taking_turns_canvas() -> type:
    """ipympl's canvas class, extended: its full draws take :data:`DRAW_LOCK`. (Made on first
    use: importing ipympl's backend registers its hooks in IPython, which only ``%matplotlib
    widget`` should do.)"""
    from ipympl.backend_nbagg import Canvas

    class TakingTurnsCanvas(Canvas):
        def draw(self) -> None:
            with DRAW_LOCK:
                super().draw()

    return TakingTurnsCanvas


#: The live figure's background alpha: below 1, so that ipympl sends every frame whole.
WHOLE_FRAMES_ALPHA = 254 / 255

#: At most this many controls are shown in one group of rows.
ROWS_OF_CONTROLS = 9


def controls_panel(controls: dict[str, widgets.Widget]) -> widgets.Widget:
    """The controls in rows of three; with more than :data:`ROWS_OF_CONTROLS`, in two tabs,
    "camera" (the camera's sliders) and "scene" (the rest), so that controls and figure fit on
    a 1280 x 720 screen together.

    Examples
    --------
    >>> sliders = {name: widgets.FloatSlider() for name in "abc"}
    >>> type(controls_panel(sliders)).__name__
    'GridBox'
    """

    def grid(names: list[str]) -> widgets.GridBox:
        return widgets.GridBox(
            [controls[n] for n in names],
            layout=widgets.Layout(grid_template_columns="repeat(3, max-content)"),
        )

    names = list(controls)
    camera = [n for n in names if n in CAMERA_RANGES]
    rest = [n for n in names if n not in CAMERA_RANGES]
    if len(names) <= ROWS_OF_CONTROLS or not camera or not rest:
        return grid(names)
    tabs = widgets.Tab([grid(camera), grid(rest)])
    tabs.set_title(0, "camera")
    tabs.set_title(1, "scene")
    return tabs


def control(param: Param) -> widgets.ValueWidget:
    """The widget for one parameter: a drop-down for choices, else a slider."""
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
