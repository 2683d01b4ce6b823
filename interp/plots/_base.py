"""The contract every figure object keeps: parameters in, ``update(**params)`` to change them.

A plot draws its static parts (axes, labels, legend) once, in ``__init__``, and its changing parts
in :meth:`Plot.redraw`, from ``self.params``. ``update`` accepts only the names the plot was built
with, so a typo raises instead of being silently ignored.
"""

from __future__ import annotations


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
        """Change some parameters and redraw; unknown names raise ``TypeError``."""
        for name in params:
            if name not in self.params:
                raise TypeError(
                    f"{type(self).__name__}.update() has no parameter {name!r}; "
                    f"it accepts: {', '.join(self.params)}"
                )
        self.params.update(params)
        self.redraw()

    def redraw(self) -> None:  # pragma: no cover - every plot overrides it
        """Draw the changing parts from ``self.params``."""
        raise NotImplementedError
