"""Argument checks shared by every public function.

A student who passes a wrong argument should read *which* argument is wrong and *what* it must
be, not a traceback from deep inside numpy. Each helper here returns the cleaned value or raises
``TypeError`` (wrong kind of thing) or ``ValueError`` (right kind, wrong value).
"""

from __future__ import annotations

import numbers
from collections.abc import Sequence

import numpy as np

#: The largest image side ``rasterize`` and the texture helpers accept: big enough for print,
#: small enough that a typo (``width=10**6``) cannot exhaust memory.
MAX_SIZE = 4096
#: The largest magnitude of any number the library takes: coordinates, attributes, parameters,
#: depths. Beyond it a value is surely a mistake, and products on the way could overflow.
MAX_MAGNITUDE = 1e12
#: The smallest depth or scale (w, near, far, d, aspect, size) the library takes, so that
#: ``1/w`` and its kin stay below 1e12 too.
MIN_POSITIVE = 1e-12


def real(value: object, name: str) -> float:
    """Return ``value`` as a finite Python float, or raise naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        if isinstance(value, np.ndarray) and value.shape == () and value.dtype.kind in "iuf":
            value = value.item()
        else:
            raise TypeError(f"{name} must be a real number, got {type(value).__name__}")
    try:
        value = float(value)
    except OverflowError:  # an int beyond any float, e.g. 10**400
        raise ValueError(
            f"{name} must be finite, got an integer of {len(str(value))} digits"
        ) from None
    if not np.isfinite(value):
        raise ValueError(f"{name} must be finite, got {value}")
    return value


def real_in(
    value: object,
    name: str,
    low: float | None = None,
    high: float | None = None,
    *,
    low_open: bool = False,
    high_open: bool = False,
) -> float:
    """Return ``value`` as a float within the given bounds, or raise naming ``name``."""
    x = real(value, name)
    too_low = low is not None and (x <= low if low_open else x < low)
    too_high = high is not None and (x >= high if high_open else x > high)
    if too_low or too_high:
        left = "-inf" if low is None else f"{low:g}"
        right = "inf" if high is None else f"{high:g}"
        bracket = ("(" if low_open or low is None else "[") + f"{left}, {right}"
        bracket += ")" if high_open or high is None else "]"
        raise ValueError(f"{name} must be in {bracket}, got {x:g}")
    return x


def number(value: object, name: str) -> float:
    """A finite float in ``[-MAX_MAGNITUDE, MAX_MAGNITUDE]``."""
    return real_in(value, name, -MAX_MAGNITUDE, MAX_MAGNITUDE)


def scale(value: object, name: str) -> float:
    """A depth or other scale: a float in ``[MIN_POSITIVE, MAX_MAGNITUDE]``."""
    return real_in(value, name, MIN_POSITIVE, MAX_MAGNITUDE)


def positive_int(value: object, name: str, cap: int = MAX_SIZE) -> int:
    """Return ``value`` as an int in ``[1, cap]``, or raise naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__}")
    value = int(value)
    if not 1 <= value <= cap:
        raise ValueError(f"{name} must be an integer in [1, {cap}], got {value}")
    return value


def integer_in(value: object, name: str, low: int, high: int) -> int:
    """Return ``value`` as an int in ``[low, high]``, or raise naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__}")
    value = int(value)
    if not low <= value <= high:
        raise ValueError(f"{name} must be an integer in [{low}, {high}], got {value}")
    return value


def float_array(value: object, name: str, shape: Sequence[int | None] | None = None) -> np.ndarray:
    """Return ``value`` as a finite float64 array of the given shape (None = any length).

    Raises TypeError if ``value`` is not numeric and ValueError for a wrong shape, NaN or inf.
    """
    try:
        array = np.asarray(value)
    except (ValueError, TypeError) as error:  # ragged nested lists
        raise ValueError(f"{name} must be a rectangular array of numbers: {error}") from None
    if array.dtype.kind not in "biuf" or array.dtype.kind == "b":
        raise TypeError(f"{name} must be an array of real numbers, got dtype {array.dtype}")
    array = array.astype(np.float64, copy=False)
    if shape is not None:
        expected = "(" + ", ".join("N" if n is None else str(n) for n in shape) + ")"
        if array.ndim != len(shape) or any(
            n is not None and n != m for n, m in zip(shape, array.shape, strict=True)
        ):
            raise ValueError(f"{name} must have shape {expected}, got {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must not contain NaN or inf")
    return array


def in_range(array: np.ndarray, name: str, low: float, high: float, what: str = "") -> np.ndarray:
    """Return ``array`` if all its values lie in ``[low, high]``, or raise naming ``name``.

    ``what`` says in words why, e.g. ``"a view depth, in front of the camera"``.
    """
    if array.size and (array.min() < low or array.max() > high):
        why = f" ({what})" if what else ""
        raise ValueError(
            f"{name} must hold values in [{low:g}, {high:g}]{why}, got values in "
            f"[{array.min():g}, {array.max():g}]"
        )
    return array


def number_array(value: object, name: str) -> np.ndarray:
    """A finite float array whose values lie in ``[-MAX_MAGNITUDE, MAX_MAGNITUDE]``."""
    return in_range(float_array(value, name), name, -MAX_MAGNITUDE, MAX_MAGNITUDE)


def depth_array(value: object, name: str) -> np.ndarray:
    """A finite float array of view depths (or other scales): values in
    ``[MIN_POSITIVE, MAX_MAGNITUDE]``."""
    array = float_array(value, name)
    return in_range(array, name, MIN_POSITIVE, MAX_MAGNITUDE, "> 0: in front of the camera")


def broadcast(**arrays: np.ndarray) -> list[np.ndarray]:
    """The arrays broadcast to one shape, or a ValueError naming them and their shapes."""
    try:
        return list(np.broadcast_arrays(*arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{name} {array.shape}" for name, array in arrays.items())
        names = ", ".join(arrays)
        raise ValueError(f"{names} must broadcast together, got shapes {shapes}") from None


def index_array(value: object, name: str, count: int, shape: Sequence[int | None]) -> np.ndarray:
    """Return ``value`` as an int64 array of indices into ``count`` items, or raise."""
    try:
        array = np.asarray(value)
    except (ValueError, TypeError) as error:  # ragged nested lists
        raise ValueError(f"{name} must be a rectangular array of integers: {error}") from None
    if array.size == 0 and array.dtype.kind == "f":  # np.asarray([]) is float
        array = array.astype(np.int64)
    if array.dtype.kind not in "iu":
        raise TypeError(f"{name} must be an array of integers, got dtype {array.dtype}")
    expected = "(" + ", ".join("M" if n is None else str(n) for n in shape) + ")"
    if array.ndim != len(shape) or any(
        n is not None and n != m for n, m in zip(shape, array.shape, strict=True)
    ):
        raise ValueError(f"{name} must have shape {expected}, got {array.shape}")
    array = array.astype(np.int64)
    if array.size and (array.min() < 0 or array.max() >= count):
        raise ValueError(
            f"{name} must hold indices in [0, {count - 1}], got values in "
            f"[{array.min()}, {array.max()}]"
        )
    return array


def bool_image(value: object, name: str, shape: tuple[int, ...]) -> np.ndarray:
    """Return ``value`` as a bool array of the given shape, or raise naming ``name``."""
    try:
        array = np.asarray(value)
    except (ValueError, TypeError):  # ragged nested lists
        array = None
    if array is None or array.dtype != bool or array.shape != shape:
        raise ValueError(f"{name} must be a bool image of shape {shape}")
    return array


def choice(value: object, name: str, options: Sequence[str]) -> str:
    """Return ``value`` if it is one of ``options``, or raise naming ``name``."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, one of {list(options)}")
    if value not in options:
        raise ValueError(f"{name} must be one of {list(options)}, got {value!r}")
    return value
