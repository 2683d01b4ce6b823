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
  its figures are pictures) and saved with its outputs, beside one HTML page per lesson;
- the **course edition**, for grading with nbgrader (``make course``): the source, with each
  exercise's checker call moved out of the answer cell into a locked, graded test cell of its own
  (``assert verdict, verdict``: a checker's verdict is truthy when the function is right, and its
  message becomes the feedback), written as nbgrader's ``source/lessons/`` in a course folder;
- the **slides edition**, for ``make slides``: the student edition with reveal.js slide types in
  each cell's ``slideshow`` metadata, derived from the lesson's structure (see
  :func:`slides_edition`), so that the slides follow the lessons.

Command line (from the repository's root)::

    python -m interp.editions student    # write lessons/ from source/lessons/
    python -m interp.editions check      # exit 1 if lessons/ differs from what it would write
    python -m interp.editions teacher    # build teacher/: executed notebooks and HTML
    python -m interp.editions course --out course    # an nbgrader course folder
    python -m interp.editions slides --out build/slides/lessons    # notebooks for the slides
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
            target.with_suffix(".html").write_text(with_alt_text(page, notebook))
            written.append(target.with_suffix(".html"))
        print(f"{path.name}: {len(verdicts(notebook))} exercise solved, no error", flush=True)
    return written


def figure_alts(cell: nbformat.NotebookNode) -> list[tuple[str, str]]:
    """The pictures among a cell's outputs that carry alt text (the apps put it in the output's
    metadata), as (base64 PNG, alt text) pairs.

    Examples
    --------
    >>> output = nbformat.v4.new_output(
    ...     "display_data", {"image/png": "iVBO"}, metadata={"image/png": {"alt": "A & B"}})
    >>> figure_alts(nbformat.v4.new_code_cell(outputs=[output]))
    [('iVBO', 'A & B')]
    """
    return [
        (output.data["image/png"], output.metadata["image/png"]["alt"])
        for output in cell.get("outputs", [])
        if "image/png" in output.get("data", {})
        and "alt" in output.get("metadata", {}).get("image/png", {})
    ]


def with_alt_text(page: str, notebook: nbformat.NotebookNode) -> str:
    """``page``, nbconvert's HTML of ``notebook``, with each figure's alt text (which the apps
    put in their outputs' metadata, and nbconvert's template leaves out) on its ``<img>``.

    Examples
    --------
    >>> output = nbformat.v4.new_output(
    ...     "display_data", {"image/png": "iVBO"}, metadata={"image/png": {"alt": "A & B"}})
    >>> notebook = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(outputs=[output])])
    >>> with_alt_text('<img alt="No description" src="data:image/png;base64,iVBO">', notebook)
    '<img alt="A &amp; B" src="data:image/png;base64,iVBO">'
    """
    from html import escape

    alt = {png.strip(): text for cell in notebook.cells for png, text in figure_alts(cell)}

    def labelled(match: re.Match) -> str:
        text = alt.get(match["data"].strip())
        if text is None:
            return match[0]
        others = re.sub(r'\s*\balt="[^"]*"', "", match["others"])  # nbconvert's placeholder
        return f'<img alt="{escape(text)}"{others} src="data:image/png;base64,{match["data"]}"'

    return re.sub(
        r'<img(?P<others>[^>]*?)\s+src="data:image/png;base64,(?P<data>[^"]*)"', labelled, page
    )


#: Points of each exercise's graded test cell (a list of prompts earns one point per prompt).
EXERCISE_POINTS = 5

#: Ends an exercise cell in the source: the call to its checker on the student's function.
CHECKER_CALL = re.compile(r"\n+check\.(\w+)\((\w+)\)\s*$")

#: nbgrader's configuration for a course folder made by :func:`write_course` (written once: the
#: teacher may add to it).
COURSE_CONFIG = f'''"""nbgrader's configuration for this course folder, written by `make course`
(python -m interp.editions course), which rewrites source/lessons/ and leaves the rest alone.

From this folder: nbgrader generate_assignment lessons; copy each student's notebooks into
submitted/STUDENT/lessons/; nbgrader autograde lessons; nbgrader generate_feedback lessons.
"""

c = get_config()  # noqa: F821 (nbgrader provides it)
c.CourseDirectory.course_id = "interp"
c.ClearSolutions.code_stub = {{"python": {CODE_STUB!r}}}
c.ClearSolutions.text_stub = "YOUR ANSWER HERE"
# Autograding runs each lesson top to bottom: its figures take a few seconds a cell.
c.Execute.timeout = 300
'''


def graded_test(exercise: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The locked, graded test cell of an exercise: its checker's call, asserted.

    Examples
    --------
    >>> source = "def f(x):\\n    return x\\n\\n\\ncheck.project(f)"
    >>> cell = nbformat.v4.new_code_cell(source, id="01-07")
    >>> test = graded_test(cell)
    >>> print(test.source)
    # Graded by nbgrader: the checker must say ✓ (this cell is locked).
    verdict = check.project(f)
    assert verdict, verdict
    verdict
    >>> test.id, test.metadata.nbgrader["grade_id"], test.metadata.nbgrader["points"]
    ('01-07-test', 'check-01-07', 5)
    """
    match = CHECKER_CALL.search(exercise.source)
    if match is None:
        raise ValueError(f"an exercise must end with its checker call:\n{exercise.source}")
    name, function = match.groups()
    source = (
        "# Graded by nbgrader: the checker must say ✓ (this cell is locked).\n"
        f"verdict = check.{name}({function})\n"
        "assert verdict, verdict\n"
        "verdict"
    )
    grading = {
        "grade": True,
        "grade_id": f"check-{exercise.id}",
        "locked": True,
        "points": EXERCISE_POINTS,
        "schema_version": 3,
        "solution": False,
        "task": False,
    }
    return nbformat.v4.new_code_cell(
        source, id=f"{exercise.id}-test", metadata={"nbgrader": grading}
    )


def course_edition(source: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The lesson as an nbgrader assignment: each exercise an answer cell (the function, its
    solution between the markers) followed by its graded test cell; everything else as in the
    source (the prompts' answer cells are nbgrader's manually graded answers already).

    Examples
    --------
    >>> exercise = "def f(x):\\n    ### BEGIN SOLUTION\\n    return x\\n    ### END SOLUTION\\n\\n"
    >>> exercise += "\\ncheck.project(f)"
    >>> nb = nbformat.v4.new_notebook()
    >>> nb.cells = [nbformat.v4.new_code_cell(exercise, id="01-07", metadata={"nbgrader": {
    ...     "solution": True, "grade": False, "grade_id": "exercise-01-07", "locked": False}})]
    >>> answer, test = course_edition(nb).cells
    >>> print(answer.source)
    def f(x):
        ### BEGIN SOLUTION
        return x
        ### END SOLUTION
    >>> test.source.splitlines()[1:3]
    ['verdict = check.project(f)', 'assert verdict, verdict']
    """
    course = copy.deepcopy(source)
    course.cells = []
    for cell in source.cells:
        cell = copy.deepcopy(cell)
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
        course.cells.append(cell)
        if is_exercise(cell):
            test = graded_test(cell)
            cell.source = CHECKER_CALL.sub("", cell.source)
            course.cells.append(test)
    return course


def write_course(root: Path, out: Path) -> list[Path]:
    """Make ``out`` an nbgrader course folder: ``source/lessons/`` from the lessons' sources
    (rewritten, stale lessons removed) and ``nbgrader_config.py`` (only if there is none).
    Everything else in ``out`` (release, submissions, grades) is left alone."""
    lessons = Path(out) / "source" / "lessons"
    lessons.mkdir(parents=True, exist_ok=True)
    names = {path.name for path in sources(root)}
    for stale in lessons.glob("*.ipynb"):
        if stale.name not in names:
            stale.unlink()
    written = []
    for path in sources(root):
        target = lessons / path.name
        target.write_text(text(course_edition(nbformat.read(path, as_version=4))))
        written.append(target)
    config = Path(out) / "nbgrader_config.py"
    if not config.exists():
        config.write_text(COURSE_CONFIG)
        written.append(config)
    return written


#: What starts a new slide: a level-2 heading (a level-1 heading is the title slide).
SLIDE_HEADING = re.compile(r"^#{1,2} ")


def slides_edition(student: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The student edition with reveal.js slide types (cell metadata ``slideshow.slide_type``):

    - the title and each ``##`` heading start a slide;
    - each figure (an app) starts a sub-slide, below the prose that introduces it, so that a
      figure with its sliders has the screen to itself; prose that goes on after a figure, in
      the same section, is the next sub-slide;
    - the set-up cell and the exercise's code (its verdict means nothing without the code,
      which slides do not show) are skipped;
    - everything else stays on the slide before it.

    Examples
    --------
    >>> nb = nbformat.v4.new_notebook()
    >>> nb.cells = [nbformat.v4.new_markdown_cell("# Title"),
    ...             nbformat.v4.new_code_cell("%matplotlib widget"),
    ...             nbformat.v4.new_markdown_cell("## A section"),
    ...             nbformat.v4.new_code_cell("interp.t_from_s(0.5, 1, 3)"),
    ...             nbformat.v4.new_code_cell("apps.st_mapping()"),
    ...             nbformat.v4.new_markdown_cell("More about it."),
    ...             nbformat.v4.new_code_cell("def f():\\n    " + CODE_STUB.splitlines()[1])]
    >>> [c.metadata.slideshow["slide_type"] for c in slides_edition(nb).cells]
    ['slide', 'skip', 'slide', '-', 'subslide', 'subslide', 'skip']
    """
    slides = copy.deepcopy(student)
    setup = next((c for c in slides.cells if c.cell_type == "code"), None)
    after_figure = False
    for cell in slides.cells:
        code = cell.cell_type == "code"
        if not code and SLIDE_HEADING.match(cell.source):
            kind, after_figure = "slide", False
        elif cell is setup or (code and "raise NotImplementedError" in cell.source):
            kind = "skip"
        elif code and re.match(r"apps\.\w+\(", cell.source.strip()):
            kind, after_figure = "subslide", True
        elif not code and after_figure:
            kind, after_figure = "subslide", False
        else:
            kind = "-"
        cell.metadata["slideshow"] = {"slide_type": kind}
    return slides


def write_slides(root: Path, out: Path) -> list[Path]:
    """Write the slides edition of every lesson into ``out``; return the files written."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for path in sources(root):
        target = out / path.name
        student = student_edition(nbformat.read(path, as_version=4))
        target.write_text(text(slides_edition(student)))
        written.append(target)
    return written


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m interp.editions COMMAND [--root DIR] [--out DIR]``; see the module's doc."""
    parser = argparse.ArgumentParser(prog="python -m interp.editions", description=__doc__)
    parser.add_argument("command", choices=["student", "check", "teacher", "course", "slides"])
    parser.add_argument("--root", type=Path, default=Path.cwd(), help="the repository's root")
    parser.add_argument(
        "--out",
        type=Path,
        default=None,
        help="where to build (teacher/, course/, build/slides/lessons/)",
    )
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
    elif args.command == "course":
        for path in write_course(args.root, args.out or args.root / "course"):
            print(f"wrote {path}")
    elif args.command == "slides":
        for path in write_slides(args.root, args.out or args.root / "build" / "slides" / "lessons"):
            print(f"wrote {path}")
    else:
        build_teacher(args.root, args.out or args.root / "teacher")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
