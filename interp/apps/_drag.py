"""Dragging the endpoints A and B of lessons 1 and 2 with the mouse."""

from __future__ import annotations

from matplotlib.backend_bases import MouseEvent

from interp.apps._app import App
from interp.plots.registry import LessonFigure


class DragEndpoints(App):
    """An app whose figure has a top view (``plot.view``, a :class:`~interp.plots.LineView`)
    whose endpoints A and B the mouse can drag; the sliders follow."""

    _dragging: str | None = None

    def __init__(self, figure_class: type[LessonFigure]) -> None:
        super().__init__(figure_class)
        canvas = self.figure.canvas
        canvas.mpl_connect("button_press_event", self._press)
        canvas.mpl_connect("motion_notify_event", self._move)
        canvas.mpl_connect("button_release_event", self._release)

    def _press(self, event: MouseEvent) -> None:
        view = self.plot.view
        if event.inaxes is not view.ax or event.xdata is None:
            return
        radius = 0.04 * (view.ax.get_xlim()[1] - view.ax.get_xlim()[0])
        self._dragging = view.nearest_endpoint(event.xdata, event.ydata, radius)

    def _move(self, event: MouseEvent) -> None:
        if self._dragging is None or event.inaxes is not self.plot.view.ax or event.xdata is None:
            return
        name = self._dragging
        w_control, x_control = self.controls[f"{name}_w"], self.controls[f"{name}_x"]
        with self._holding():
            w_control.value = min(max(float(event.xdata), w_control.min), w_control.max)
            x_control.value = min(max(float(event.ydata), x_control.min), x_control.max)
        # Latest position wins, as for a slider: the browser sends a move every 33 ms, and
        # drawing each in turn left seconds of stale frames after the mouse was let go.
        self.coalescer.request()

    def _release(self, event: MouseEvent) -> None:
        self._move(event)  # the browser may drop the last moves: end where the mouse let go
        self._dragging = None
