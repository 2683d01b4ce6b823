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


def real(value: object, name: str) -> float:
    """Return ``value`` as a finite Python float, or raise naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        if isinstance(value, np.ndarray) and value.shape == () and value.dtype.kind in "iuf":
            value = value.item()
        else:
            raise TypeError(f"{name} must be a real number, got {type(value).__name__}")
    value = float(value)
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


def index_array(value: object, name: str, count: int, shape: Sequence[int | None]) -> np.ndarray:
    """Return ``value`` as an int64 array of indices into ``count`` items, or raise."""
    array = np.asarray(value)
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


def choice(value: object, name: str, options: Sequence[str]) -> str:
    """Return ``value`` if it is one of ``options``, or raise naming ``name``."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, one of {list(options)}")
    if value not in options:
        raise ValueError(f"{name} must be one of {list(options)}, got {value!r}")
    return value
