"""The parameters a lesson figure takes: each with its default, its range and its label.

One table serves three readers: the live apps make a slider or a drop-down from each
:class:`Param`, ``interp-figures`` checks ``--set`` values against it before drawing, and
``interp-figures --list`` prints it. So a range is written once, here or beside its figure in
:mod:`interp.plots.registry`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

from interp.camera import Camera
from interp.scenes import LESSON_CAMERA

Value = float | int | str


@dataclass(frozen=True)
class Param:
    """One parameter of a figure.

    Parameters
    ----------
    default : float, int or str
        Its value unless set; its type is the parameter's type.
    low, high : float, optional
        The range of a number, both ends included.
    step : float, optional
        A slider's step (for ``log`` parameters, a step of the power of ten).
    label : str
        What a slider or the figure list calls it.
    options : tuple of str, optional
        The choices of a str parameter.
    log : bool
        The slider moves in powers of ten.
    fmt : str
        How a slider shows a number.

    Examples
    --------
    >>> pitch = Param(15.0, -10.0, 90.0, 0.5, "pitch (deg)")
    >>> pitch.check("pitch", 30)
    30.0
    >>> pitch.check("pitch", 95)
    Traceback (most recent call last):
    ...
    ValueError: pitch must be in [-10, 90], got 95
    >>> pitch.parse("pitch", "12.5")
    12.5
    """

    default: Value
    low: float | None = None
    high: float | None = None
    step: float | None = None
    label: str = ""
    options: tuple[str, ...] | None = None
    log: bool = False
    fmt: str = ".2f"

    @property
    def kind(self) -> type:
        """float, int or str."""
        return type(self.default)

    def check(self, name: str, value: object) -> Value:
        """``value`` as this parameter's type, or a ``TypeError``/``ValueError`` naming ``name``."""
        if self.options is not None:
            if value not in self.options:
                raise ValueError(f"{name} must be one of {', '.join(self.options)}; got {value!r}")
            return str(value)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise TypeError(f"{name} must be a number, got {type(value).__name__}")
        if self.kind is int:
            if float(value) != int(value):
                raise ValueError(f"{name} must be a whole number, got {value}")
            value = int(value)
        else:
            value = float(value)
            if not math.isfinite(value):
                raise ValueError(f"{name} must be finite, got {value}")
        if (self.low is not None and value < self.low) or (
            self.high is not None and value > self.high
        ):
            raise ValueError(f"{name} must be in {self.range}, got {value:g}")
        return value

    def parse(self, name: str, text: str) -> Value:
        """Read a command-line string as this parameter (then :meth:`check` it)."""
        if self.kind is str:
            return self.check(name, text)
        try:
            number = float(text) if len(text) <= 40 else math.nan  # no 5000-digit numbers
        except ValueError:
            raise ValueError(f"{name} must be a number, got {text!r}") from None
        if not math.isfinite(number):
            raise ValueError(f"{name} must be a finite number of at most 40 characters")
        return self.check(name, number)

    @property
    def range(self) -> str:
        """The allowed values in words: ``[-10, 90]`` or ``a, b, c``."""
        if self.options is not None:
            return ", ".join(self.options)
        return f"[{self.low:g}, {self.high:g}]"


#: The camera's parameters (see :class:`~interp.camera.Camera`), defaults taken from a camera.
CAMERA_RANGES = {
    "height": (-0.5, 4.0, 0.01, "height"),
    "pitch": (-10.0, 90.0, 0.5, "pitch (deg)"),
    "yaw": (-180.0, 180.0, 1.0, "yaw (deg)"),
    "distance": (0.0, 8.0, 0.05, "distance"),
    "fovy": (10.0, 120.0, 1.0, "field of view (deg)"),
    "near": (0.001, 1.0, 0.05, "near plane"),
    "roll": (-180.0, 180.0, 1.0, "roll (deg)"),
}


def table(**params: Param) -> Mapping[str, Param]:
    """A figure's parameters as a read-only mapping (classes share it; nobody may change it).

    Examples
    --------
    >>> table(w1=Param(1.0, 0.1, 10.0, 0.01, "w1"))["w1"].default
    1.0
    """
    return MappingProxyType(params)


def camera_params(
    camera: Camera = LESSON_CAMERA, roll: bool = False, **defaults: float
) -> dict[str, Param]:
    """Parameters for height, pitch, yaw, distance, field of view and near plane (and roll),
    with defaults from ``camera`` unless given in ``defaults``.

    Examples
    --------
    >>> params = camera_params(height=0.3)
    >>> params["height"].default, params["pitch"].default, "roll" in params
    (0.3, 15.0, False)
    """
    params = {}
    for name, (low, high, step, label) in CAMERA_RANGES.items():
        if name == "roll" and not roll:
            continue
        params[name] = Param(
            float(defaults.get(name, getattr(camera, name))),
            low,
            high,
            step,
            label,
            log=name == "near",
            fmt=".3f" if name == "near" else ".2f",
        )
    return params


def camera_from(values: dict[str, object], base: Camera = LESSON_CAMERA) -> Camera:
    """The camera that parameter values describe (fields they do not name come from ``base``).

    Examples
    --------
    >>> camera_from({"pitch": 40.0, "frequency": 8}).pitch
    40.0
    """
    fields = {name: float(values[name]) for name in CAMERA_RANGES if name in values}
    return Camera(**{**base.__dict__, **fields})
