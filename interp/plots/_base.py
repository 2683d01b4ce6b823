"""The contract every figure object keeps: parameters in, ``update(**params)`` to change them.

A plot draws its static parts (axes, labels, legend) once, in ``__init__``, and its changing parts
in :meth:`Plot.redraw`, from ``self.params``. ``update`` accepts only the names the plot was built
with, so a typo raises instead of being silently ignored.
"""

from __future__ import annotations

import math

from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.image import AxesImage
from matplotlib.text import Annotation
from matplotlib.transforms import Affine2D, IdentityTransform


def _same(a: object, b: object) -> bool:
    try:
        return bool(a == b)
    except (TypeError, ValueError):  # e.g. arrays: compare as changed
        return False


def place_pixels(image: AxesImage, width: int, height: int) -> None:
    """Put pixel (column, row) of ``image`` at (column, row) of its axes, rows going down, and
    fit the axes to the image; nothing when that is already so.

    ``AxesImage.set_extent`` sets its axes' limits and data limits each time, and the axes'
    callbacks run: 0.42-0.46 ms a call (timed), which a slider step that keeps the image's size need
    not pay.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> import numpy as np
    >>> image = plt.subplots()[1].imshow(np.zeros((1, 1)))
    >>> place_pixels(image, 4, 3)
    >>> ax = image.axes
    >>> [float(x) for x in (*image.get_extent(), *ax.get_xlim(), *ax.get_ylim())]
    [-0.5, 3.5, 2.5, -0.5, -0.5, 3.5, 2.5, -0.5]
    """
    extent = (-0.5, width - 0.5, height - 0.5, -0.5)
    ax = image.axes
    if (
        tuple(image.get_extent()) != extent
        or ax.get_xlim() != extent[:2]
        or ax.get_ylim() != extent[2:]
    ):
        image.set_extent(extent)
        ax.set_xlim(*extent[:2])
        ax.set_ylim(*extent[2:])


class PixelLabel(Annotation):
    """An annotation, with no arrow, whose text is anchored on a whole pixel (see
    :func:`label`)."""

    def update_positions(self, renderer: object) -> None:
        """Place the text as :class:`~matplotlib.text.Annotation` does, then move it by less
        than half a pixel, to anchor it on the nearest whole one (a position that is not
        finite is left as it is: matplotlib draws nothing there)."""
        super().update_positions(renderer)
        transform = self.get_transform()
        x, y = transform.transform(self.xyann)
        if math.isfinite(x) and math.isfinite(y):
            self.set_transform(transform + Affine2D().translate(round(x) - x, round(y) - y))


def label(
    ax: Axes, text: str, xy: tuple[float, float], offset: tuple[float, float], **kwargs: object
) -> PixelLabel:
    """``ax.annotate(text, xy, xytext=offset, textcoords="offset points", **kwargs)``, with the
    text moved to anchor it on the nearest whole pixel: a label that follows a point a slider
    moves.

    matplotlib places text a fraction of a pixel anywhere, and renders each glyph for its place
    within a pixel, so a label moved by fractions of a pixel changes its look at every step (it
    shimmers while a slider moves). Anchored on a whole pixel, a label's glyphs keep their
    places within a pixel wherever it goes (their offsets from the anchor are the string's
    own), so it looks the same everywhere; it is at most half a pixel from where ``annotate``
    puts it.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> ax = plt.subplots()[1]
    >>> note = label(ax, "A", (0.3, 0.4), (6, 4))
    >>> renderer = ax.figure.canvas.get_renderer()
    >>> note.update_positions(renderer)
    >>> x, y = note.get_transform().transform(note.xyann)
    >>> bool(round(x, 9) % 1 == round(y, 9) % 1 == 0)      # whole pixels
    True
    """
    if "arrowprops" in kwargs:  # the arrow would point from where annotate put the text
        raise TypeError("label draws no arrow: arrowprops is for ax.annotate")
    note = PixelLabel(text, xy, xytext=offset, textcoords="offset points", **kwargs)
    # Added as Axes.annotate adds one (add_artist would clip it to the axes).
    note.set_transform(IdentityTransform())
    if kwargs.get("clip_on", False) and note.get_clip_path() is None:
        note.set_clip_path(ax.patch)
    ax._add_text(note)
    return note


class Plot:
    """Base of the figure objects in :mod:`interp.plots`.

    Subclasses create their artists, then call ``super().__init__(**params)`` with every parameter
    they understand (their defaults); that stores them and draws once.

    Examples
    --------
    >>> class Counter(Plot):
    ...     def redraw(self):
    ...         self.drawn = self.params["n"]
    >>> c = Counter(n=1)
    >>> c.update(n=2); c.drawn
    2
    >>> c.update(m=3)
    Traceback (most recent call last):
    ...
    TypeError: Counter.update() has no parameter 'm'; it accepts: n
    """

    def __init__(self, **params: object) -> None:
        self.params: dict[str, object] = dict(params)
        self.redraw()

    def update(self, **params: object) -> None:
        """Change some parameters and redraw; unknown names raise ``TypeError``.

        Nothing is redrawn when every value is the one the plot already shows (a figure of two
        plots, one slider moving, recomputes only the plot that slider drives).
        """
        for name in params:
            if name not in self.params:
                raise TypeError(
                    f"{type(self).__name__}.update() has no parameter {name!r}; "
                    f"it accepts: {', '.join(self.params)}"
                )
        if all(_same(self.params[name], value) for name, value in params.items()):
            return
        self.params.update(params)
        self.redraw()

    def redraw(self) -> None:  # pragma: no cover - every plot overrides it
        """Draw the changing parts from ``self.params``."""
        raise NotImplementedError

    @property
    def dynamic(self) -> list[Artist] | None:
        """The artists :meth:`redraw` changes, so a live canvas can redraw just those over a
        saved background (blitting) while nothing else changes; None if the plot cannot say
        (then every change redraws the whole figure). A change to any other artist (axis
        limits, say) redraws the whole figure once (see :mod:`interp.apps._blit`)."""
        return None
