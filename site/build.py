"""Build the course website and the lecture slides, both offline.

``python site/build.py site --out build/site [--repo URL] [--hub URL]`` (``make site``)
    The website, a Jupyter Book (v1, Sphinx), from the **student edition** (``lessons/``): each
    lesson run top to bottom with the static ``inline`` backend (its figures become pictures;
    the sliders, which need a kernel, are left out), the handout PDF built by ``interp-figures``,
    MathJax copied from the npm package in ``site/node_modules``. The pages are in
    ``OUT/html/``; they load nothing from another site.

``python site/build.py slides --out build/slides`` (``make slides``)
    The slides: ``OUT/lessons/``, the slides edition of every lesson (slide boundaries from the
    lesson's structure, see ``interp.editions.slides_edition``), and ``OUT/jupyter/``, Voilà's
    ``interp-reveal`` template (Voilà's ``reveal`` template with reveal.js's style sheets, jQuery
    and Font Awesome served by Voilà itself, not from a CDN). Serve them with
    ``JUPYTER_PATH=OUT/jupyter voila --template=interp-reveal OUT/lessons``.

``npm ci --prefix site`` must have run first (``make`` does it).
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

import nbformat

from interp import editions

ROOT = Path(__file__).resolve().parent.parent
SITE = ROOT / "site"
NODE = SITE / "node_modules"

#: Output types that need a live kernel to mean anything: the apps' controls.
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


def _node_package(name: str) -> Path:
    path = NODE / name
    if not (path / "package.json").exists():
        raise SystemExit(f"{path} is missing: run `npm ci --prefix site` (make does it)")
    return path


def static_lesson(path: Path, workdir: Path) -> nbformat.NotebookNode:
    """A student lesson, run with static figures, without the outputs that need a kernel."""
    notebook = nbformat.read(path, as_version=4)
    editions.run(notebook, workdir)
    problems = editions.errors(notebook)
    if problems:
        raise RuntimeError(f"{path.name}: {problems}")
    for cell in notebook.cells:
        if cell.cell_type == "code":
            cell.outputs = [o for o in cell.outputs if WIDGET_VIEW not in o.get("data", {})]
            # The figure's alt text (an app's title and key result, in its output's metadata),
            # where MyST-NB looks for it: the cell's image options.
            alts = {text for _, text in editions.figure_alts(cell)}
            if len(alts) == 1:
                cell.metadata["mystnb"] = {"image": {"alt": alts.pop()}}
    notebook.metadata.pop("widgets", None)
    return notebook


def _config(repo: str, hub: str, binder: str, branch: str) -> str:
    import yaml  # Jupyter Book's own dependency

    config = yaml.safe_load((SITE / "book" / "_config.yml").read_text())
    config["repository"].update(url=repo, branch=branch)
    config["launch_buttons"].update(jupyterhub_url=hub, binderhub_url=binder)
    return yaml.safe_dump(config, sort_keys=False, allow_unicode=True)


def build_site(
    out: Path,
    repo: str = "https://github.com/YOUR-ORG/interp",
    hub: str = "https://HUB",
    binder: str = "https://mybinder.org",
    branch: str = "main",
    lessons: Sequence[Path] | None = None,
    handout: Sequence[str] | None = None,
) -> Path:
    """Build the website into ``out``; return the folder of its HTML pages.

    ``lessons`` (default: every lesson in ``lessons/``) and ``handout`` (the figures in the
    handout; default: all) let the tests build a smaller site the same way."""
    out = Path(out).resolve()
    book = out / "src"
    shutil.rmtree(book, ignore_errors=True)
    (book / "_extra").mkdir(parents=True)
    lessons = sorted((ROOT / "lessons").glob("*.ipynb")) if lessons is None else lessons
    with tempfile.TemporaryDirectory() as work:
        # The handout is drawn by another process while the lessons run: two cores, both busy.
        handouts = Path(work) / "handouts"
        figures = [sys.executable, "-m", "interp.figures", "--out", str(handouts)]
        figures += ["--format", "pdf", *(["--only", *handout] if handout else [])]
        drawing = subprocess.Popen(figures, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        try:
            for path in lessons:
                start = time.perf_counter()
                notebook = static_lesson(path, Path(work))
                (book / path.name).write_text(editions.text(notebook))
                print(f"{path.name}: run in {time.perf_counter() - start:.1f} s", flush=True)
        finally:
            _, errors = drawing.communicate()
        if drawing.returncode != 0:
            raise RuntimeError(f"interp-figures failed: {errors.decode()[-2000:]}")
        shutil.copy(handouts / "handout.pdf", book / "handout.pdf")
    shutil.copytree(
        SITE / "book", book, dirs_exist_ok=True, ignore=shutil.ignore_patterns("__pycache__")
    )
    (book / "_config.yml").write_text(_config(repo, hub, binder, branch))
    toc = {"format": "jb-book", "root": "intro", "chapters": [{"file": p.stem} for p in lessons]}
    (book / "_toc.yml").write_text(json.dumps(toc, indent=1) + "\n")  # JSON is YAML too
    shutil.copytree(_node_package("mathjax") / "es5", book / "_extra" / "mathjax")
    shutil.rmtree(out / "_build", ignore_errors=True)
    command = [
        str(Path(sys.executable).parent / "jupyter-book"),
        "build",
        str(book),
        "--path-output",
        str(out),
        "--warningiserror",
        "--keep-going",
    ]
    # Its own report names the folder it builds in, which moves to OUT/html: shown on failure only
    built = subprocess.run(command, capture_output=True, text=True)
    if built.returncode != 0:
        raise RuntimeError(f"jupyter-book failed:\n{built.stdout[-5000:]}\n{built.stderr[-5000:]}")
    html = out / "html"
    shutil.rmtree(html, ignore_errors=True)
    shutil.move(out / "_build" / "html", html)
    return html


#: Voilà's reveal template, with everything it would fetch from a CDN served by Voilà instead.
TEMPLATE = "interp-reveal"


def build_slides(out: Path) -> Path:
    """Write the slide notebooks and the slides' Voilà template into ``out``; return the
    folder of the notebooks."""
    out = Path(out).resolve()
    lessons = out / "lessons"
    shutil.rmtree(lessons, ignore_errors=True)
    editions.write_slides(ROOT, lessons)
    template = out / "jupyter" / "voila" / "templates" / TEMPLATE
    shutil.rmtree(template, ignore_errors=True)
    shutil.copytree(SITE / "slides", template)
    static = template / "static"
    reveal = _node_package("reveal.js")
    shutil.copytree(reveal / "dist", static / "revealjs" / "dist")  # not reveal.js: Voilà's
    shutil.copytree(_node_package("jquery") / "dist", static / "jquery")
    fontawesome = _node_package("@fortawesome/fontawesome-free")
    for part in ("css", "webfonts"):
        shutil.copytree(fontawesome / part, static / "fontawesome" / part)
    return lessons


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python site/build.py", description=__doc__)
    parser.add_argument("what", choices=["site", "slides"])
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--repo", default="https://github.com/YOUR-ORG/interp")
    parser.add_argument("--hub", default="https://HUB", help="the JupyterHub's address")
    parser.add_argument("--binder", default="https://mybinder.org")
    parser.add_argument("--branch", default="main")
    args = parser.parse_args(argv)
    start = time.perf_counter()
    if args.what == "site":
        html = build_site(args.out, args.repo, args.hub, args.binder, args.branch)
        print(f"the website is in {html} ({time.perf_counter() - start:.0f} s)")
    else:
        lessons = build_slides(args.out)
        print(f"the slides are in {lessons}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
