# The two commands a fresh machine needs: `make book` and `make test`.
# Both create .venv and install the pinned dependencies first (`make setup`).
PY      := .venv/bin/python
PIP     := .venv/bin/pip
STAMP   := .venv/.installed
export LABKIT_TIME ?= virtual
# Dates printed by tools (ros2 bag info, default bag names) must not depend on the machine.
export TZ ?= UTC

.PHONY: setup test unit nbval browser book book-exec lab bench clean

setup: $(STAMP) rosref wine

# Windows CPython in Wine for tests/platform/test_windows_wine.py; nothing where wine is missing
.PHONY: wine
wine: $(STAMP)
	$(PY) tools/wine_env.py prepare --if-wine

# The real-ROS reference (Jazzy rclpy + Fast DDS wheels, cp311/cp312 only) that tests/dds
# and benchmarks/bench_dds.py talk to. Its own venv, never inside .venv (see benchmarks/README.md).
ROSREF       := .venv-rosref
ROSREF_STAMP := $(ROSREF)/.installed
ROSREF_PY    ?= $(shell command -v python3.11 || command -v python3.12 || echo python3)

.PHONY: rosref
rosref: $(ROSREF_STAMP)

$(ROSREF_STAMP): requirements-rosref.lock
	test -x $(ROSREF)/bin/python || $(ROSREF_PY) -m venv $(ROSREF)
	$(ROSREF)/bin/pip install -q --upgrade pip
	$(ROSREF)/bin/pip install -q -r requirements-rosref.lock
	touch $(ROSREF_STAMP)

$(STAMP): requirements.lock pyproject.toml
	test -x $(PY) || python3 -m venv .venv
	$(PIP) install -q --upgrade pip
	$(PIP) install -q -r requirements.lock
	$(PIP) install -q --no-deps -e .
	touch $(STAMP)

# Whole suite: labkit unit tests + conformance scripts + nbval over every notebook.
test: setup
	$(PY) -m pytest -q tests book

unit: setup
	$(PY) -m pytest -q tests

nbval: setup
	$(PY) -m pytest -q book

# Offline HTML book: npm ci (only when node_modules is missing or stale),
# vendor RequireJS/ipywidgets/MathJax into book/_static/vendor, then
# jupyter-book build from the stored outputs (see tools/book_build.py).
book: setup
	$(PY) tools/book_build.py

# Re-execute every notebook in place (virtual time: same outputs every run).
book-exec: setup
	$(PY) -m labkit.tools.execute_notebooks book

# JupyterLab, live time, on a working copy of the book in lab/ (git ignores it):
# autosave never touches the shipped notebooks (see labkit/tools/lab.py).
lab: setup
	$(PY) -m labkit.tools.lab

bench: setup
	for f in benchmarks/*.py; do echo "== $$f"; $(PY) $$f || exit 1; done

clean:
	rm -rf book/_build .pytest_cache
