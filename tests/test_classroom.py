"""Classroom set-up: static exports keep their figures, Binder/JupyterHub configuration matches
the project's real dependencies and name, a student's install is light, presentation mode, and
the projector command."""

from __future__ import annotations

import base64
import importlib.metadata
import io
import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from nbconvert import HTMLExporter
from PIL import Image

from helpers import run_lesson

tomllib = pytest.importorskip("tomllib")  # Python 3.11+

ROOT = Path(__file__).resolve().parent.parent
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())
README = (ROOT / "README.md").read_text()


def test_static_html_export_has_every_figure(tmp_path):
    """Without live widgets (plain inline backend), a lesson exported to HTML shows each app's
    figure as a picture."""
    notebook = run_lesson(ROOT / "lessons" / "03_the_st_mapping.ipynb", tmp_path, "inline")
    html, _ = HTMLExporter().from_notebook_node(notebook)
    images = re.findall(r'<img[^>]*src="data:image/png;base64,([^"]+)"', html)
    app_cells = [c for c in notebook.cells if c.cell_type == "code" and "apps." in c.source]
    assert len(images) >= len(app_cells) >= 1
    for data in images:
        picture = np.asarray(Image.open(io.BytesIO(base64.b64decode(data))).convert("L"))
        assert picture.std() > 10, "a blank figure"
    assert "The s\u2013t mapping" in html and "interpolate first, then project" in html.lower()


def test_binder_installs_the_project_itself():
    lines = [
        line.split("#")[0].strip()
        for line in (ROOT / "binder" / "requirements.txt").read_text().splitlines()
    ]
    assert "." in lines, "binder must install the project, and so its declared dependencies"
    version = (ROOT / "binder" / "runtime.txt").read_text().strip()
    major, minor = map(int, version.removeprefix("python-").split("."))
    low = PYPROJECT["project"]["requires-python"].removeprefix(">=")
    assert (major, minor) >= tuple(map(int, low.split(".")))


def test_declared_dependencies_cover_what_the_lessons_use():
    declared = {re.split(r"[<>=\[ ]", d)[0].lower() for d in PYPROJECT["project"]["dependencies"]}
    assert {"numpy", "matplotlib", "ipywidgets", "jupyterlab", "ipympl"} <= declared
    imported = set()
    for path in (ROOT / "lessons").glob("*.ipynb"):
        for cell in json.loads(path.read_text())["cells"]:
            if cell["cell_type"] == "code":
                source = "".join(cell["source"])
                imported |= set(re.findall(r"^\s*(?:import|from)\s+(\w+)", source, re.M))
    standard = set(sys.stdlib_module_names)
    assert imported - standard - {"interp"} <= declared, imported


def test_readme_explains_hub_and_binder_with_this_repository():
    assert "binder/requirements.txt" in README
    assert "git-pull?repo=" in README  # the nbgitpuller link recipe
    assert "urlpath=lab/tree/" in README
    assert "make present" in README


#: The distribution's name: distinct on PyPI (`interp` alone is generic, its neighbours are
#: interpretability tools); the package it installs is still `import interp`.
DISTRIBUTION = "perspective-interp"


def test_the_distribution_is_perspective_interp_and_installs_import_interp():
    assert PYPROJECT["project"]["name"] == DISTRIBUTION
    assert set(importlib.metadata.packages_distributions()["interp"]) == {DISTRIBUTION}
    assert PYPROJECT["tool"]["setuptools"]["packages"]["find"]["include"] == ["interp*"]


def test_readme_binder_hub_and_website_name_the_same_distribution_and_repository():
    # the JupyterHub install line names the distribution, from the repository
    assert f'pip install "{DISTRIBUTION} @ git+https://github.com/YOUR-ORG/interp"' in README
    assert 'pip install "interp' not in README and "pip install interp" not in README
    # the nbgitpuller recipe pulls that repository into ~/interp and opens lessons/ from there
    recipe = re.search(r"https://HUB/hub/user-redirect/git-pull\?(\S+)", README).group(1)
    assert "repo=https%3A%2F%2Fgithub.com%2FYOUR-ORG%2Finterp" in recipe
    assert "urlpath=lab/tree/interp/lessons/01_the_problem.ipynb" in recipe
    # the website's launch buttons point at the same repository and lessons
    site = (ROOT / "site" / "book" / "_config.yml").read_text()
    assert "url: https://github.com/YOUR-ORG/interp" in site and "path_to_book: lessons" in site
    makefile = (ROOT / "Makefile").read_text()
    assert "REPO ?= https://github.com/YOUR-ORG/interp" in makefile
    # Binder installs the project itself, whatever its name
    assert DISTRIBUTION in (ROOT / "binder" / "requirements.txt").read_text()


#: What the lessons never need: the test, browser, OpenGL, website and hook tools.
DEVELOPMENT_ONLY = {
    "pytest", "playwright", "moderngl", "hypothesis", "ruff", "voila", "jupyter-book",
    "pre-commit", "pillow", "nbgrader",
}  # fmt: skip


def test_make_lessons_installs_only_the_package_and_its_runtime_dependencies():
    makefile = (ROOT / "Makefile").read_text()
    assert re.search(r"^lessons: \$\(RUNTIME\)$", makefile, re.M)
    runtime = re.search(r"^\$\(RUNTIME\):.*\n\t(.+)$", makefile, re.M).group(1)
    assert runtime.endswith("pip install --quiet -e .")
    runtime_names = {
        re.split(r"[<>=\[ ]", d)[0].lower() for d in PYPROJECT["project"]["dependencies"]
    }
    assert not runtime_names & DEVELOPMENT_ONLY
    assert re.search(r"^test: lint ", makefile, re.M)
    assert re.search(r"^lint: \$\(STAMP\)$", makefile, re.M)
    assert "STAMP   := $(VENV)/.installed-dev" in makefile  # make test: pip install -e ".[dev]"
    dev = {
        re.split(r"[<>=\[ ]", d)[0].lower()
        for d in PYPROJECT["project"]["optional-dependencies"]["dev"]
    }
    assert {"playwright", "ruff", "pre-commit"} <= dev
    assert f"{DISTRIBUTION}" in dev  # with the gl, present, site and test extras
    test = {
        re.split(r"[<>=\[ ]", d)[0].lower()
        for d in PYPROJECT["project"]["optional-dependencies"]["test"]
    }
    assert {"pytest", "hypothesis", "nbclient"} <= test


def test_presentation_flag_from_the_environment():
    code = "from interp.apps import _app; print(_app._PRESENTATION['on'])"
    for value, expected in (("1", "True"), ("0", "False")):
        out = subprocess.run(
            [sys.executable, "-c", code],
            capture_output=True,
            text=True,
            env={"INTERP_PRESENTATION": value, "PATH": ""},
            check=True,
        )
        assert out.stdout.strip() == expected


def test_make_present_serves_the_lessons_with_voila_in_presentation_mode():
    makefile = (ROOT / "Makefile").read_text()
    recipe = re.search(r"^present:.*\n\t(.+)$", makefile, re.M).group(1)
    assert "INTERP_PRESENTATION=1" in recipe and "-m interp.classroom lessons" in recipe
    # interp.classroom is Voilà with culling and a cap (tests/test_browser.py serves a page).
    from interp.classroom import voila_arguments

    assert any("ClassroomKernelManager" in a for a in voila_arguments(300, 60, 30))


def test_the_classroom_culler_waits_for_a_page_to_connect_then_culls_it_when_closed(tmp_path):
    """Voilà runs a page's cells, then the browser loads the page and connects to the kernel;
    the idle clock starts when the cells finish. A kernel whose page has not connected yet is
    kept for ``page_wait`` seconds however idle (CI once culled one after 3 s of a busy
    machine's page load: the page's figure never came); once its page has connected and
    closed, the kernel is culled as Jupyter culls. Real kernels, with their idle clocks set
    back instead of waited out."""
    import asyncio
    import time
    from datetime import timedelta

    from jupyter_server._tz import utcnow

    from interp.classroom import ClassroomKernelManager

    async def scenario() -> list[bool]:
        manager = ClassroomKernelManager(
            cull_idle_timeout=3, cull_interval=1000, page_wait=60, connection_dir=str(tmp_path)
        )
        alive = []
        try:
            loading, closed = await manager.start_kernel(), await manager.start_kernel()
            for kernel_id in (loading, closed):
                await manager.get_kernel(kernel_id).ready
                manager.get_kernel(kernel_id).last_activity = utcnow() - timedelta(seconds=10)
            manager.notify_connect(closed)  # the page connected...
            manager.notify_disconnect(closed)  # ...and its tab was closed
            for kernel_id in (loading, closed):
                await manager.cull_kernel_if_idle(kernel_id)
            alive += [loading in manager.list_kernel_ids(), closed in manager.list_kernel_ids()]
            # Started 55 s ago: still waiting for its page, kept. Started 65 s ago: the wait is
            # over, a page that never came: culled. (Its start time set back, not waited out.)
            manager._unconnected[loading] = time.monotonic() - 55
            await manager.cull_kernel_if_idle(loading)
            alive.append(loading in manager.list_kernel_ids())
            manager._unconnected[loading] -= 10
            await manager.cull_kernel_if_idle(loading)
            alive.append(loading in manager.list_kernel_ids())
            alive.append(not manager._unconnected)  # nothing left behind
        finally:
            await manager.shutdown_all()
        return alive

    assert asyncio.run(scenario()) == [True, False, True, False, True]


def test_the_package_ships_no_jupyter_settings():
    """Installing the package changes nobody's JupyterLab: no data files (a file under
    ``etc/jupyter`` would enable a server extension or change settings for every notebook of
    the environment), and no folder of settings to copy."""
    setuptools = PYPROJECT["tool"]["setuptools"]
    assert "data-files" not in setuptools
    assert not (ROOT / "jupyter-config").exists()
    makefile = (ROOT / "Makefile").read_text()
    assert "etc/jupyter" not in makefile
