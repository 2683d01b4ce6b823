"""Shared look: the style sheet, and how affine and correct curves are told apart."""

from __future__ import annotations

import functools
from contextlib import AbstractContextManager
from pathlib import Path

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.axes import Axes

#: The package's style sheet.
STYLE = Path(__file__).resolve().parent.parent / "styles" / "interp.mplstyle"

#: Perspective-correct: solid blue with circles. Affine: dashed vermilion with squares.
#: Hue, line style and marker all differ, so a grayscale photocopy still tells them apart.
CORRECT = {"color": "#0072B2", "linestyle": "-", "marker": "o", "label": "perspective-correct"}
AFFINE = {"color": "#D55E00", "linestyle": "--", "marker": "s", "label": "affine"}
#: Further curves (mistakes, references): each a distinct style.
OTHERS = [
    {"color": "#009E73", "linestyle": "-.", "marker": "^"},
    {"color": "#CC79A7", "linestyle": ":", "marker": "v"},
    {"color": "#E69F00", "linestyle": (0, (5, 1, 1, 1, 1, 1)), "marker": "D"},
    {"color": "#000000", "linestyle": (0, (1, 2)), "marker": "x"},
]
#: Markers on a dense curve: about this many per curve.
MARKERS = 9


def styled(**rc: object) -> AbstractContextManager:
    """``with styled(): ...`` draws with the package's style sheet (and any rc settings given,
    e.g. ``styled(**{"font.size": 13.5})``)."""
    return plt.rc_context({**_style_sheet(), **rc})


@functools.cache
def _style_sheet() -> dict:
    """The style sheet's settings, read once."""
    return dict(matplotlib.rc_params_from_file(STYLE, use_default_template=False))


def markevery(n: int) -> int:
    """Marker spacing for a curve of n points."""
    return max(1, n // MARKERS)


def fit_y(ax: Axes, *values: object) -> None:
    """Set the y range to hold ``values`` (numbers or arrays), its ends on a grid.

    The grid's spacing is a quarter of the values' scale: their largest magnitude, less a
    fifth, rounded up to 1, 2 or 5 times a power of ten (values up to 1.25 share the grid of
    those up to 1). Each end lies a fifth of a spacing or more beyond the values. So an end
    moves only when a value crosses a grid line, a slider's small steps leave the axis as it
    is (a live figure need not redraw it), and values that come close together are shown
    close together, not magnified to fill the axes.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> ax = plt.subplots()[1]
    >>> fit_y(ax, 0.0, 1.0); [float(y) for y in ax.get_ylim()]
    [-0.25, 1.25]
    >>> fit_y(ax, 0.03, 0.97); [float(y) for y in ax.get_ylim()]   # a small change: the same
    [-0.25, 1.25]
    >>> fit_y(ax, 0.5, 0.5); [float(y) for y in ax.get_ylim()]     # flat: not magnified
    [0.375, 0.625]
    """
    every = np.concatenate([np.ravel(v) for v in values]).astype(float)
    low, high = float(every.min()), float(every.max())
    scale = max(abs(low), abs(high), 1e-9)  # values all but 0: a flat line at 0
    grid = nice_ceiling(0.8 * scale, (1, 2, 5)) / 4
    margin = grid / 5
    low = np.floor(round((low - margin) / grid, 9)) * grid
    high = np.ceil(round((high + margin) / grid, 9)) * grid
    set_limits(ax, y=(float(f"{low:.12g}"), float(f"{high:.12g}")))


def set_limits(
    ax: Axes, x: tuple[float, float] | None = None, y: tuple[float, float] | None = None
) -> None:
    """Set ``ax``'s x and y ranges to ``x`` and ``y`` (None: leave it), each only where it
    changes: setting a range marks the axes changed even when it is the same, and a live figure
    then redraws its axes, ticks and labels instead of only the curves that moved.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> ax = plt.subplots()[1]
    >>> set_limits(ax, x=(0, 2)); ax.stale = False
    >>> set_limits(ax, x=(0, 2)); ax.stale
    False
    """
    if x is not None and tuple(ax.get_xlim()) != tuple(x):
        ax.set_xlim(*x)
    if y is not None and tuple(ax.get_ylim()) != tuple(y):
        ax.set_ylim(*y)


def decades(low: float, high: float) -> tuple[float, float]:
    """The powers of ten just outside ``[low, high]`` (both > 0): a log axis's ends.

    Examples
    --------
    >>> decades(0.03, 2.0)
    (0.01, 10.0)
    >>> decades(0.01, 10.0)
    (0.01, 10.0)
    """
    return float(10.0 ** np.floor(np.log10(low))), float(10.0 ** np.ceil(np.log10(high)))


def nice_ceiling(x: float, steps: tuple[float, ...] = (1, 1.5, 2, 3, 4, 5, 6, 8)) -> float:
    """The smallest of ``steps`` times a power of ten that is >= x (x > 0).

    Examples
    --------
    >>> nice_ceiling(0.33), nice_ceiling(7.0), nice_ceiling(0.05)
    (0.4, 8.0, 0.05)
    >>> nice_ceiling(0.6, (1, 2, 5)), nice_ceiling(3.3, (1, 2, 5)), nice_ceiling(2e-10, (1, 2, 5))
    (1.0, 5.0, 2e-10)
    """
    power = 10.0 ** np.floor(np.log10(x))
    for m in (*steps, 10):
        if m * power >= x * (1 - 1e-12):
            return float(f"{m * power:.12g}")  # 12 digits: 0.30000000000000004 is 0.3
    raise AssertionError("unreachable")  # pragma: no cover


def bare(ax: Axes) -> None:
    """An axes that shows an image: no ticks."""
    ax.set_xticks([])
    ax.set_yticks([])
