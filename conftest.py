"""Collection rules for the whole repository (the tests' own fixtures are in tests/)."""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")  # no screen: every figure in the tests and doctests is drawn with Agg


def pytest_ignore_collect(collection_path: Path, config) -> bool | None:
    """Skip interp/opengl.py's doctests where no OpenGL context can be made, except in CI.

    tests/test_opengl.py then reports its tests as skipped, with the reason; under CI=true
    a missing OpenGL is a failure instead.
    """
    if collection_path.name != "opengl.py" or os.environ.get("CI"):
        return None
    try:
        from interp import opengl

        opengl.context()
    except (ImportError, RuntimeError):
        return True
    return None


@pytest.fixture(autouse=True)
def _close_figures():
    """Every test and doctest closes the pyplot figures it opened (apps open one each)."""
    yield
    import matplotlib.pyplot as plt

    plt.close("all")
