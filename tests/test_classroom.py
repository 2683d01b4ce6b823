"""Classroom set-up: static exports keep their figures, Binder/JupyterHub configuration matches
the project's real dependencies, presentation mode, and the projector command."""

from __future__ import annotations

import base64
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
