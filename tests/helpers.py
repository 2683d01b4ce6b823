"""Scenes the tests share."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import nbformat
import numpy as np
import pytest
from matplotlib.collections import LineCollection
from nbclient import NotebookClient

import interp

LESSONS = Path(__file__).resolve().parent.parent / "lessons"
#: nbgrader's own environment (make test installs it; see the Makefile for why it is apart).
NBGRADER_BIN = LESSONS.parent / ".venv-nbgrader" / "bin"


def run_lesson(path: Path, workdir: Path, backend: str = "widget") -> nbformat.NotebookNode:
    """Execute a lesson top to bottom in a fresh kernel, with ``%matplotlib <backend>``."""
    notebook = nbformat.read(path, as_version=4)
    if backend != "widget":
        setup = notebook.cells[1]
        assert "%matplotlib widget" in setup.source
        setup.source = setup.source.replace("%matplotlib widget", f"%matplotlib {backend}")
    client = NotebookClient(
        notebook, timeout=120, kernel_name="python3", resources={"metadata": {"path": str(workdir)}}
    )
    client.execute()
    return notebook


def random_scene(rng: np.random.Generator, n_triangles: int, behind: bool = False):
    """Random triangles in view space, projected with a real perspective matrix.

    With ``behind``, some vertices lie behind the camera or before the near plane, so the
    rasterizer must clip. Returns (clip, attributes, triangles).
    """
    P = interp.perspective(70, 4 / 3, 0.5, 20)
    centres = np.column_stack(
        [
            rng.uniform(-3, 3, n_triangles),
            rng.uniform(-2, 2, n_triangles),
            rng.uniform(-12, -2, n_triangles),
        ]
    )
    spread = 4.0 if behind else 1.5
    view = centres.repeat(3, axis=0) + rng.uniform(-spread, spread, (3 * n_triangles, 3))
    if behind:
        view[::5, 2] = rng.uniform(-1.0, 2.0, len(view[::5]))  # near plane at -0.5
    clip = np.column_stack([view, np.ones(len(view))]) @ P.T
    attributes = rng.uniform(0, 1, (len(view), 3))
    triangles = np.arange(3 * n_triangles).reshape(-1, 3)
    return clip, attributes, triangles


def shown_arrays(figure):
    """Every number the figure displays: line data, images, line collections."""
    for ax in figure.axes:
        for line in ax.lines:
            yield np.asarray(line.get_xydata(), float)
        for image in ax.images:
            data = image.get_array()
            yield np.ma.compressed(data) if np.ma.isMaskedArray(data) else np.asarray(data)
        for collection in ax.collections:
            if isinstance(collection, LineCollection):
                for segment in collection.get_segments():
                    yield np.asarray(segment, float)


def need_nbgrader() -> None:
    """Skip the test where nbgrader is not installed, except under ``CI=true`` (a failure)."""
    if not (NBGRADER_BIN / "nbgrader").exists():
        if os.environ.get("CI"):
            pytest.fail(f"CI must have nbgrader in {NBGRADER_BIN} (make test installs it)")
        pytest.skip(f"no nbgrader in {NBGRADER_BIN} (make test installs it)")


def nbgrader(*args: str, cwd: Path, timeout: float = 600) -> subprocess.CompletedProcess:
    """Run nbgrader in ``cwd`` (a course folder) and return its result; it must succeed."""
    # nbgrader runs alembic (for its gradebook) as a subprocess: its venv's bin must be on PATH
    env = {**os.environ, "PATH": f"{NBGRADER_BIN}{os.pathsep}{os.environ['PATH']}"}
    env["JUPYTER_CONFIG_DIR"] = str(cwd / ".jupyter")
    env.pop("MPLBACKEND", None)
    result = subprocess.run(
        [str(NBGRADER_BIN / "nbgrader"), *args],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=timeout,
    )
    assert result.returncode == 0, result.stderr[-4000:]
    return result


#: The lessons' single source (the teacher's), with nbgrader's markers.
SOURCES = LESSONS.parent / "source" / "lessons"


def cells(number: int) -> list[nbformat.NotebookNode]:
    """The cells of lesson ``number``'s source."""
    (path,) = SOURCES.glob(f"{number:02d}_*.ipynb")
    return nbformat.read(path, as_version=4).cells


def prose(number: int) -> str:
    """A lesson's text as students read it (markdown cells that are not teacher answers), its
    line breaks made spaces."""
    text = [c.source for c in cells(number) if c.cell_type == "markdown" and not c.metadata]
    return " ".join(" ".join(text).split())


def answers(number: int) -> str:
    """The teacher's answers and solutions, line breaks made spaces."""
    return " ".join(" ".join(c.source for c in cells(number) if "nbgrader" in c.metadata).split())


def shown(name: str, **settings):
    """The registry figure ``name`` drawn on a plain Figure at its app size."""
    from matplotlib.figure import Figure

    from interp.plots.registry import FIGURES

    figure_class = FIGURES[name]
    return figure_class(Figure(figsize=figure_class.size), **settings)
