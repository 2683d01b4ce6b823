# Two commands for a fresh clone (see README.md):
#   make lessons   install everything into .venv and open the lessons in JupyterLab
#   make test      install everything into .venv and run the whole test suite
# Also: make teacher (the teacher edition: every exercise solved, every prompt answered, run, and
# as HTML, in teacher/), make student (rewrite lessons/ from source/lessons/), make present (the
# lessons without code, large, for a projector), make bench (speed figures beside real OpenGL),
# make bench-browser (every app timed in Chromium), make handouts (print-ready figures), make clean.

PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-dev
# nbgrader lives in a venv of its own: its JupyterLab extension breaks Voila's page (a console
# error) and would add its menus to the students' JupyterLab. Only the nbgrader test uses it.
NBGRADER_VENV := .venv-nbgrader
NBGRADER      := $(NBGRADER_VENV)/bin/nbgrader

# JupyterLab refuses to start as root unless told; containers often run as root.
LAB_ARGS ?= $(if $(filter 0,$(shell id -u)),--allow-root,)

.PHONY: lessons teacher student present test bench bench-browser handouts lint clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(STAMP): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e ".[dev]"
	touch $@

$(NBGRADER):
	$(PYTHON) -m venv $(NBGRADER_VENV)
	$(NBGRADER_VENV)/bin/python -m pip install --quiet --upgrade pip
	$(NBGRADER_VENV)/bin/python -m pip install --quiet "nbgrader>=0.9"

lessons: $(STAMP)
	$(BIN)/jupyter lab --notebook-dir=lessons $(LAB_ARGS)

teacher: $(STAMP)
	$(BIN)/python -m interp.editions check || true
	$(BIN)/python -m interp.editions teacher --out teacher

student: $(STAMP)
	$(BIN)/python -m interp.editions student

# Voilà through interp.classroom: kernels of closed tabs are shut down after 5 idle minutes, and
# at most 30 run at once (python -m interp.classroom --help).
present: $(STAMP)
	INTERP_PRESENTATION=1 $(BIN)/python -m interp.classroom lessons

lint: $(STAMP)
	$(BIN)/ruff check --no-cache interp tests conftest.py
	$(BIN)/ruff format --no-cache --check interp tests conftest.py

test: lint $(NBGRADER)
	$(BIN)/python -m pytest

bench: $(STAMP)
	$(BIN)/python -m interp.bench

# Every app in JupyterLab in Chromium: step latency, fps while dragging, settle time, final frame
# (tests/bench_browser.py --help; --fit measures whether each app fits the screen instead).
bench-browser: $(STAMP)
	$(BIN)/python tests/bench_browser.py

handouts: $(STAMP)
	$(BIN)/interp-figures --out handouts

clean:
	rm -rf $(VENV) $(NBGRADER_VENV) .pytest_cache .ruff_cache .hypothesis teacher release gradebook.db
