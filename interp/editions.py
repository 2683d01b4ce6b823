"""The two editions of the lessons, made from one source.

``source/lessons/NN_*.ipynb`` is the only copy a teacher edits (nbgrader's course layout: the
assignment is called ``lessons``). Each source lesson carries

- each of its exercises (the lesson's function, its recap quiz, lesson 7's worked example) in
  one code cell marked as nbgrader's "autograded answer" (cell metadata ``nbgrader.solution``),
  the solution between ``### BEGIN SOLUTION`` and ``### END SOLUTION`` lines, followed by the
  call to its checker in :mod:`interp.check`;
- under the figure of every "Try this" list, a markdown cell marked as nbgrader's "manually
  graded answer", holding a written answer to each prompt between the same markers.

From it this module makes

- the **student edition**, committed in ``lessons/``: the solution replaced by nbgrader's own stub
  (``# YOUR CODE HERE`` / ``raise NotImplementedError()``), the answer cells left out, no outputs,
  nbgrader's metadata dropped, cell ids kept;
- the **teacher edition**, built into ``teacher/`` by ``make teacher``: every cell kept, the
  markers removed, each notebook run top to bottom (with the static ``inline`` backend, so that
  its figures are pictures) and saved with its outputs, beside one HTML page per lesson.

Command line (from the repository's root)::

    python -m interp.editions student    # write lessons/ from source/lessons/
    python -m interp.editions check      # exit 1 if lessons/ differs from what it would write
    python -m interp.editions teacher    # build teacher/: executed notebooks and HTML
"""

from __future__ import annotations

import argparse
import copy
import re
import sys
from collections.abc import Sequence
from pathlib import Path

import nbformat

#: The lines that open and close a solution: nbgrader's defaults.
BEGIN, END = "### BEGIN SOLUTION", "### END SOLUTION"

#: What replaces a code solution in the student edition: nbgrader's default code stub, so that
#: ``nbgrader generate_assignment`` and this module make the same exercise cells.
CODE_STUB = "# YOUR CODE HERE\nraise NotImplementedError()"

#: Added to the first cell of each teacher notebook.
TEACHER_NOTE = (
    "\n\n> **Teacher edition**: every exercise is solved and every *Try this* prompt answered. "
    "It was run with the static `inline` backend, so its figures are pictures; run it again "
    "for live sliders. Students get `lessons/`, made from the same source by "
    "`python -m interp.editions student`."
)


def is_solution(cell: nbformat.NotebookNode) -> bool:
    """Whether nbgrader's metadata marks ``cell`` as a solution (an exercise or an answer).

    Examples
    --------
    >>> is_solution(nbformat.v4.new_markdown_cell("x", metadata={"nbgrader": {"solution": True}}))
    True
    """
    return bool(cell.get("metadata", {}).get("nbgrader", {}).get("solution", False))


def is_answer(cell: nbformat.NotebookNode) -> bool:
    """Whether ``cell`` is a written answer to a list of prompts (a markdown solution cell)."""
    return cell.cell_type == "markdown" and is_solution(cell)


def is_exercise(cell: nbformat.NotebookNode) -> bool:
    """Whether ``cell`` is an exercise (a code solution cell)."""
    return cell.cell_type == "code" and is_solution(cell)


def _solution_regions(source: str, stub: str | None) -> str:
    """``source`` with each solution region replaced by ``stub`` (indented like its BEGIN line),
    or, with ``stub=None``, with only the marker lines removed."""
    lines, out, inside = source.split("\n"), [], False
    for line in lines:
        if BEGIN in line:
            if inside:
                raise ValueError(f"nested {BEGIN!r} in:\n{source}")
            inside = True
            if stub is not None:
                indent = re.match(r"\s*", line).group(0)
                out.extend(indent + s for s in stub.split("\n"))
        elif END in line:
            if not inside:
                raise ValueError(f"{END!r} without {BEGIN!r} in:\n{source}")
            inside = False
        elif not inside or stub is None:
            out.append(line)
    if inside:
        raise ValueError(f"{BEGIN!r} without {END!r} in:\n{source}")
    return "\n".join(out)


def _plain(cell: nbformat.NotebookNode) -> nbformat.NotebookNode:
    cell = copy.deepcopy(cell)
    cell.metadata.pop("nbgrader", None)
    if cell.cell_type == "code":
        cell.outputs, cell.execution_count = [], None
    return cell


def student_edition(source: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The lesson as students get it: exercises blank, answers left out, no outputs.

    Examples
    --------
    >>> nb = nbformat.v4.new_notebook()
    >>> exercise = "def f(x):\\n    ### BEGIN SOLUTION\\n    return 2 * x\\n    ### END SOLUTION"
    >>> nb.cells = [nbformat.v4.new_code_cell(exercise, metadata={"nbgrader": {"solution": True}})]
    >>> print(student_edition(nb).cells[0].source)
    def f(x):
        # YOUR CODE HERE
        raise NotImplementedError()
    """
    student = copy.deepcopy(source)
    student.cells = []
    for cell in source.cells:
        if is_answer(cell):
            continue
        plain = _plain(cell)
        if is_exercise(cell):
            plain.source = _solution_regions(cell.source, CODE_STUB)
        student.cells.append(plain)
    return student


def teacher_edition(source: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The lesson with its solutions and answers, the markers removed, not yet executed.

    Examples
    --------
    >>> nb = nbformat.v4.new_notebook()
    >>> answer = "**Answers**\\n\\n### BEGIN SOLUTION\\n- Yes.\\n### END SOLUTION"
    >>> marked = {"nbgrader": {"solution": True}}
    >>> nb.cells = [nbformat.v4.new_code_cell("1")]
    >>> nb.cells.append(nbformat.v4.new_markdown_cell(answer, metadata=marked))
    >>> print(teacher_edition(nb).cells[1].source)
    **Answers**
    <BLANKLINE>
    - Yes.
    """
    teacher = copy.deepcopy(source)
    teacher.cells = []
    for cell in source.cells:
        plain = _plain(cell)
        if is_solution(cell):
            plain.source = _solution_regions(cell.source, None)
        teacher.cells.append(plain)
    if teacher.cells and teacher.cells[0].cell_type == "markdown":
        teacher.cells[0].source += TEACHER_NOTE
    return teacher


def sources(root: Path) -> list[Path]:
    """The source lessons under ``root``, in order."""
    return sorted((Path(root) / "source" / "lessons").glob("[0-9][0-9]_*.ipynb"))


def text(notebook: nbformat.NotebookNode) -> str:
    """How a notebook is stored: nbformat's own JSON, ending in a newline."""
    return nbformat.writes(notebook) + "\n"


def write_student(root: Path) -> list[Path]:
    """Write ``lessons/`` from ``source/lessons/``; return the files written."""
    written = []
    for path in sources(root):
        target = Path(root) / "lessons" / path.name
        target.write_text(text(student_edition(nbformat.read(path, as_version=4))))
        written.append(target)
    return written


def stale_student(root: Path) -> list[str]:
    """Names of the lessons in ``lessons/`` that differ from what :func:`write_student` makes,
    or that it would add or remove."""
    made = {p.name: text(student_edition(nbformat.read(p, as_version=4))) for p in sources(root)}
    stored = {p.name: p.read_text() for p in (Path(root) / "lessons").glob("*.ipynb")}
    names = made.keys() | stored.keys()
    return sorted(name for name in names if made.get(name) != stored.get(name))


def run(notebook: nbformat.NotebookNode, workdir: Path, timeout: int = 300) -> None:
    """Execute ``notebook`` in place, in a fresh kernel, with ``%matplotlib inline`` (the first
    code cell's ``%matplotlib widget`` is put back afterwards, so the saved notebook is live
    when run again)."""
    from nbclient import NotebookClient

    setup = next(cell for cell in notebook.cells if cell.cell_type == "code")
    if "%matplotlib widget" not in setup.source:
        raise ValueError("the first code cell must start with %matplotlib widget")
    setup.source = setup.source.replace("%matplotlib widget", "%matplotlib inline")
    try:
        NotebookClient(
            notebook,
            timeout=timeout,
            kernel_name="python3",
            resources={"metadata": {"path": str(workdir)}},
        ).execute()
    finally:
        setup.source = setup.source.replace("%matplotlib inline", "%matplotlib widget")


def errors(notebook: nbformat.NotebookNode) -> list[str]:
    """Every error or stderr output of an executed notebook."""
    return [
        f"cell {cell.get('id')}: {output.get('evalue') or output.get('text')}"
        for cell in notebook.cells
        for output in cell.get("outputs", [])
        if output.output_type == "error"
        or (output.output_type == "stream" and output.name == "stderr")
    ]


def verdicts(notebook: nbformat.NotebookNode) -> list[str]:
    """What the checkers said in an executed notebook (their plain-text outputs)."""
    return [
        output.data["text/plain"]
        for cell in notebook.cells
        if cell.cell_type == "code" and "check." in cell.source
        for output in cell.get("outputs", [])
        if output.output_type == "execute_result"
    ]


def build_teacher(root: Path, out: Path, html: bool = True) -> list[Path]:
    """Build the teacher edition of every lesson into ``out``: executed notebooks, and HTML.

    Raises RuntimeError if a lesson raises an error or a checker rejects its solution.
    """
    from nbconvert import HTMLExporter

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for path in sources(root):
        notebook = teacher_edition(nbformat.read(path, as_version=4))
        run(notebook, out)
        problems = errors(notebook) + [v for v in verdicts(notebook) if not v.startswith("✓")]
        if problems or not verdicts(notebook):
            raise RuntimeError(f"{path.name}: {problems or 'no checker ran'}")
        target = out / path.name
        target.write_text(text(notebook))
        written.append(target)
        if html:
            page, _ = HTMLExporter().from_notebook_node(notebook)
            target.with_suffix(".html").write_text(page)
            written.append(target.with_suffix(".html"))
        print(f"{path.name}: {len(verdicts(notebook))} exercise solved, no error", flush=True)
    return written


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m interp.editions {student,check,teacher} [--root DIR] [--out DIR]``."""
    parser = argparse.ArgumentParser(prog="python -m interp.editions", description=__doc__)
    parser.add_argument("command", choices=["student", "check", "teacher"])
    parser.add_argument("--root", type=Path, default=Path.cwd(), help="the repository's root")
    parser.add_argument("--out", type=Path, default=None, help="teacher/: where to build")
    args = parser.parse_args(argv)
    if not sources(args.root):
        parser.error(f"no source lessons in {args.root / 'source' / 'lessons'}")
    if args.command == "student":
        for path in write_student(args.root):
            print(f"wrote {path}")
    elif args.command == "check":
        stale = stale_student(args.root)
        if stale:
            print("lessons/ is out of date; run `python -m interp.editions student`:", *stale)
            return 1
        print("lessons/ matches source/lessons/")
    else:
        build_teacher(args.root, args.out or args.root / "teacher")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
