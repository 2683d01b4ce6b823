"""Apps of lessons 1-3: a segment seen by a 1D camera, its s-t mapping, the gap."""

from __future__ import annotations

from matplotlib.backend_bases import MouseEvent
from matplotlib.figure import Figure

from interp import plots
from interp.apps._app import App, int_slider, slider
from interp.lerp import project_to_image_plane, s_from_t


def _endpoint_controls(A=(-1.5, -2.0), B=(2.5, -8.0), d=2.0) -> dict:
    return {
        "A_x": slider(A[0], -4.5, 4.5, 0.05, "A: x"),
        "A_w": slider(-A[1], 0.5, 9.5, 0.05, "A: depth w"),
        "B_x": slider(B[0], -4.5, 4.5, 0.05, "B: x"),
        "B_w": slider(-B[1], 0.5, 9.5, 0.05, "B: depth w"),
        "d": slider(d, 0.2, 4.0, 0.05, "image plane d"),
    }


class _DragsEndpoints(App):
    """Lets the mouse drag A and B in a :class:`~interp.plots.LineView`."""

    view: plots.LineView
    _dragging: str | None = None

    def _connect_drag(self) -> None:
        canvas = self.figure.canvas
        canvas.mpl_connect("button_press_event", self._press)
        canvas.mpl_connect("motion_notify_event", self._move)
        canvas.mpl_connect("button_release_event", self._release)

    def _press(self, event: MouseEvent) -> None:
        if event.inaxes is not self.view.ax or event.xdata is None:
            return
        radius = 0.04 * (self.view.ax.get_xlim()[1] - self.view.ax.get_xlim()[0])
        self._dragging = self.view.nearest_endpoint(event.xdata, event.ydata, radius)

    def _move(self, event: MouseEvent) -> None:
        if self._dragging is None or event.inaxes is not self.view.ax or event.xdata is None:
            return
        name = self._dragging
        w_control, x_control = self.controls[f"{name}_w"], self.controls[f"{name}_x"]
        self.set(
            **{
                f"{name}_w": min(max(float(event.xdata), w_control.min), w_control.max),
                f"{name}_x": min(max(float(event.ydata), x_control.min), x_control.max),
            }
        )

    def _release(self, event: MouseEvent) -> None:
        self._move(event)  # the browser may drop the last moves: end where the mouse let go
        self._dragging = None

    @staticmethod
    def _points(values: dict) -> tuple[tuple[float, float], tuple[float, float]]:
        return (values["A_x"], -values["A_w"]), (values["B_x"], -values["B_w"])


class TheProblem(_DragsEndpoints):
    """Lesson 1: the midpoint of the image is not the image of the midpoint. Drag A and B."""

    def __init__(self) -> None:
        def build(figure: Figure) -> None:
            self.view = plots.LineView(figure.add_subplot())

        super().__init__(_endpoint_controls(), (6.5, 4.5), build)
        self._connect_drag()

    def draw(self, **v: float) -> None:
        A, B = self._points(v)
        self.view.update(A=A, B=B, d=v["d"])
        a, b = (project_to_image_plane(P, v["d"]) for P in (A, B))
        m = project_to_image_plane(self.view.points["M"], v["d"])
        s_m = (m - a) / (b - a) if b != a else 0.5
        self.view.ax.set_title(
            f"M, the middle of AB, shows at s = {s_m:.3f} of the image, not 0.5", fontsize=9
        )


class ProjectingALine(_DragsEndpoints):
    """Lesson 2: equally spaced samples on the image, the rays, the attribute and s-t curve."""

    def __init__(self) -> None:
        controls = {**_endpoint_controls(), "samples": int_slider(8, 1, 32, "samples")}

        def build(figure: Figure) -> None:
            axes = figure.subplots(1, 3, gridspec_kw={"width_ratios": [1.3, 1, 1]})
            self.view = plots.LineView(axes[0], samples=8)
            self.strip = plots.ImageStrip(axes[1])
            self.curve = plots.STCurve(axes[2], samples=8)

        super().__init__(controls, (9.5, 3.4), build)
        self._connect_drag()

    def draw(self, **v: float) -> None:
        A, B = self._points(v)
        self.view.update(A=A, B=B, d=v["d"], samples=v["samples"])
        self.strip.update(w1=v["A_w"], w2=v["B_w"])
        self.curve.update(w1=v["A_w"], w2=v["B_w"], samples=v["samples"])
        self.view.ax.set_title(
            f"the midpoint of AB shows at s = {s_from_t(0.5, v['A_w'], v['B_w']):.3f}", fontsize=9
        )


class STMapping(App):
    """Lesson 3: the family of s-t curves, and where the gap |t - s| peaks."""

    def __init__(self) -> None:
        controls = {
            "w1": slider(1.0, 0.1, 10.0, 0.01, "w1"),
            "w2": slider(4.0, 0.1, 10.0, 0.01, "w2"),
        }

        def build(figure: Figure) -> None:
            axes = figure.subplots(1, 2)
            self.family = plots.STFamily(axes[0])
            self.gap = plots.GapPlot(axes[1])

        super().__init__(controls, (9.0, 4.2), build)

    def draw(self, **v: float) -> None:
        self.family.update(ratio=v["w2"] / v["w1"])
        self.gap.update(w1=v["w1"], w2=v["w2"])


def the_problem() -> TheProblem:
    """Lesson 1's app: drag A and B, change the image-plane distance d."""
    return TheProblem()


def projecting_a_line() -> ProjectingALine:
    """Lesson 2's app: top view, attribute along the image, and s-t curve, linked."""
    return ProjectingALine()


def st_mapping() -> STMapping:
    """Lesson 3's app: the s-t curves for a depth ratio, and the gap's peak."""
    return STMapping()
