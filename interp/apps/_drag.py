"""Dragging the endpoints A and B of lessons 1 and 2 with the mouse."""

from __future__ import annotations

from matplotlib.backend_bases import MouseEvent

from interp.apps._app import App, on_slider
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
        before = (w_control.value, x_control.value)
        with self._holding():  # on the sliders' steps, as the page has them (see on_slider)
            w_control.value = on_slider(w_control, float(event.xdata))
            x_control.value = on_slider(x_control, float(event.ydata))
        if (w_control.value, x_control.value) == before:
            return  # within the same steps: the same picture
        # Latest position wins, as for a slider: drawing each mouse move in turn would leave
        # seconds of stale frames after the mouse was let go.
        self.coalescer.request()

    def _release(self, event: MouseEvent) -> None:
        self._move(event)  # the browser may drop the last moves: end where the mouse let go
        self._dragging = None
