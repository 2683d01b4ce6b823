"""Shared look: the style sheet, and how affine and correct curves are told apart."""

from __future__ import annotations

from contextlib import AbstractContextManager
from pathlib import Path

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


def styled() -> AbstractContextManager:
    """``with styled(): ...`` draws with the package's style sheet."""
    return plt.style.context(STYLE)


def markevery(n: int) -> int:
    """Marker spacing for a curve of n points."""
    return max(1, n // MARKERS)


def fit_y(ax: Axes, *values: object) -> None:
    """Set the y range to span ``values`` (numbers or arrays), with a 5% margin."""
    every = np.concatenate([np.ravel(v) for v in values])
    low, high = float(every.min()), float(every.max())
    pad = 0.05 * max(high - low, 1e-9)
    ax.set_ylim(low - pad, high + pad)


def bare(ax: Axes) -> None:
    """An axes that shows an image: no ticks."""
    ax.set_xticks([])
    ax.set_yticks([])
