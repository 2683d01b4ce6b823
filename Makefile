# Two commands for a fresh clone (see README.md):
#   make lessons   install the package and what the lessons need into .venv, open them in JupyterLab
#   make test      install the development tools into .venv too, and run the whole test suite
# Also: make teacher (the teacher edition: every exercise solved, every prompt answered, run, and
# as HTML, in teacher/), make student (rewrite lessons/ from source/lessons/), make present (the
# lessons without code, large, for a projector), make slides (the lessons as live slides), make
# site (the course website, in build/site/), make course (an nbgrader course with autograded
# exercises, in course/), make bench (speed figures beside real OpenGL), make bench-browser
# (every app timed in Chromium), make handouts (print-ready figures), make install (only the
# install of make lessons), make clean.

PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
# What is installed into .venv, one stamp per set: the package alone (a student's install), the
# package with an extra (present: Voila; site: Jupyter Book; gl: moderngl), or everything (dev).
RUNTIME := $(VENV)/.installed
STAMP   := $(VENV)/.installed-dev
# nbgrader lives in a venv of its own: its JupyterLab extension breaks Voila's page (a console
# error) and would add its menus to the students' JupyterLab. It gets the package too (nbgrader
# runs the notebooks it grades) and nbgitpuller (whose merge the tests try).
NBGRADER_VENV := .venv-nbgrader
NBGRADER      := $(NBGRADER_VENV)/bin/nbgrader
NBGRADER_DONE := $(NBGRADER_VENV)/.installed
# The npm packages the site and the slides serve themselves: MathJax and reveal.js.
NPM_DONE := site/node_modules/.package-lock.json

# JupyterLab refuses to start as root unless told; containers often run as root.
LAB_ARGS ?= $(if $(filter 0,$(shell id -u)),--allow-root,)

# The versions the tests run on: the newest pyproject.toml allows (make test), and the oldest
# (make test-oldest, in a venv of its own with Python 3.10).
NEWEST := ci/newest.txt
OLDEST := ci/oldest.txt
OLDEST_PYTHON ?= python3.10
OLDEST_VENV   := .venv-oldest
OLDEST_DONE   := $(OLDEST_VENV)/.installed
# The kernel side only: the oldest venv has no Playwright, moderngl or the dev extra's pinned
# ruff, and Python 3.10 no tomllib, so the browser, OpenGL, site, slides, hooks and classroom
# files are left out by name (they run in make test on the newest versions), not skipped.
OLDEST_TESTS  ?= $(addprefix --ignore=,tests/test_precommit.py tests/test_browser.py \
	tests/test_browser_apps.py tests/test_browser_outside.py tests/test_opengl.py \
	interp/opengl.py tests/test_site.py tests/test_slides.py tests/test_classroom.py)

# The website's launch buttons and the slides' server (make site REPO=... HUB=...).
REPO ?= https://github.com/YOUR-ORG/interp
HUB  ?= https://HUB
# The nbgrader course folder: source/ is rewritten by make course, the rest is the teacher's.
COURSE ?= course

.PHONY: lessons install teacher student present slides site course test bench handouts lint clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(RUNTIME): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e .
	touch $@

$(VENV)/.installed-%: pyproject.toml $(NEWEST) | $(BIN)/python
	$(BIN)/python -m pip install --quiet -c $(NEWEST) -e ".[$*]"
	touch $@

$(NBGRADER_DONE): pyproject.toml
	test -x $(NBGRADER_VENV)/bin/python || $(PYTHON) -m venv $(NBGRADER_VENV)
	$(NBGRADER_VENV)/bin/python -m pip install --quiet --upgrade pip
	$(NBGRADER_VENV)/bin/python -m pip install --quiet "nbgrader>=0.9" "nbgitpuller>=1.2" -e .
	touch $@

$(NPM_DONE): site/package.json site/package-lock.json
	npm ci --prefix site --no-audit --no-fund --loglevel=error
	touch $@

install: $(RUNTIME)

lessons: $(RUNTIME)
	$(BIN)/jupyter lab --notebook-dir=lessons $(LAB_ARGS)

teacher: $(RUNTIME)
	$(BIN)/python -m interp.editions check || true
	$(BIN)/python -m interp.editions teacher --out teacher

student: $(RUNTIME)
	$(BIN)/python -m interp.editions student

# Voilà through interp.classroom: kernels of closed tabs are shut down after 5 idle minutes, and
# at most 30 run at once (python -m interp.classroom --help).
present: $(VENV)/.installed-present
	INTERP_PRESENTATION=1 $(BIN)/python -m interp.classroom lessons

# The lessons as reveal.js slides (a slide per ## heading), live, through the same server.
slides: $(VENV)/.installed-present $(NPM_DONE)
	$(BIN)/python site/build.py slides --out build/slides
	INTERP_PRESENTATION=1 JUPYTER_PATH=build/slides/jupyter $(BIN)/python -m interp.classroom \
		--template=interp-reveal build/slides/lessons

# The course website from the student edition, executed, offline: open build/site/html/index.html.
site: $(VENV)/.installed-site $(NPM_DONE)
	$(BIN)/python site/build.py site --out build/site --repo "$(REPO)" --hub "$(HUB)"

# An nbgrader course: $(COURSE)/source/lessons with a graded test cell per exercise, released
# into $(COURSE)/release/lessons. Grade with nbgrader from $(COURSE) (README: Grading).
course: $(RUNTIME) $(NBGRADER_DONE)
	$(BIN)/python -m interp.editions course --out $(COURSE)
	cd $(COURSE) && PATH="$(abspath $(NBGRADER_VENV))/bin:$$PATH" \
		nbgrader generate_assignment lessons --force

lint: $(STAMP)
	$(BIN)/ruff check --no-cache interp tests conftest.py site
	$(BIN)/ruff format --no-cache --check interp tests conftest.py site

# The suite runs in one process per CPU this process may use, at most 4 (pytest-xdist; each
# browser test file starts its own JupyterLab and Chromium), a test file at a time per process,
# so that each file's servers start once. TEST_JOBS=0 runs it in this one process.
TEST_JOBS ?= $(shell $(PYTHON) -c 'import os; n = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count(); print(max(1, min(4, n or 1)))')

test: lint $(NBGRADER_DONE) $(NPM_DONE)
	$(BIN)/python -m pytest -n $(TEST_JOBS) --dist loadfile
	$(MAKE) test-oldest

# The kernel-side tests (no browser, no OpenGL, no notebook tools beyond nbclient) on the oldest
# versions pyproject.toml allows.
$(OLDEST_DONE): pyproject.toml $(OLDEST)
	test -x $(OLDEST_VENV)/bin/python || $(OLDEST_PYTHON) -m venv $(OLDEST_VENV)
	$(OLDEST_VENV)/bin/python -m pip install --quiet --upgrade pip
	$(OLDEST_VENV)/bin/python -m pip install --quiet -c $(OLDEST) -e ".[test]"
	touch $@

.PHONY: test-oldest
test-oldest: $(OLDEST_DONE)
	$(OLDEST_VENV)/bin/python -m pytest -n $(TEST_JOBS) --dist loadfile -m "not browser and not opengl" $(OLDEST_TESTS)

bench: $(VENV)/.installed-gl
	$(BIN)/python -m interp.bench
	$(BIN)/python -m interp.bench_outside

# Every app in JupyterLab in Chromium: step latency, fps while dragging, settle time, final frame
# (tests/bench_browser.py --help; --fit measures whether each app fits the screen instead;
# --cpu adds the CPU each process and thread used a key step).
.PHONY: bench-browser
bench-browser: $(STAMP)
	$(BIN)/python tests/bench_browser.py

handouts: $(RUNTIME)
	$(BIN)/interp-figures --out handouts

# Leaves $(COURSE)/ alone: it holds the students' submissions and their grades.
clean:
	rm -rf $(VENV) $(NBGRADER_VENV) $(OLDEST_VENV) .pytest_cache .ruff_cache .hypothesis teacher release \
		gradebook.db build site/node_modules
