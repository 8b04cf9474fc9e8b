# The two commands a fresh machine needs: `make book` and `make test` (and `make lab`).
# Every job is tools/make.py, the same code that Windows runs as `py tools\make.py JOB`:
# it creates .venv, installs what that job needs from requirements.lock, then runs it.
PYTHON  ?= python3
PY      := .venv/bin/python
export LABKIT_TIME ?= virtual
# Dates printed by tools (ros2 bag info, default bag names) must not depend on the machine.
export TZ ?= UTC

.PHONY: setup venv test unit nbval browser book book-exec lab bench clean

# Everything the suite needs: .venv (every pin), .venv-rosref where real rclpy's wheels exist
setup: venv wine

venv:
	$(PYTHON) tools/make.py setup

# Windows CPython in Wine for tests/platform/test_windows_wine.py; nothing where wine is missing
.PHONY: wine
wine: venv
	$(PY) tools/wine_env.py prepare --if-wine

# The real-ROS reference (Jazzy rclpy + Fast DDS wheels, Linux x86_64, cp311/cp312 only)
# that tests/dds and benchmarks/bench_dds.py talk to; part of `setup` where it can exist.
.PHONY: rosref
rosref: venv

# Whole suite: labkit unit tests + conformance scripts + nbval over every notebook.
test: setup
	$(PYTHON) tools/make.py test

unit: setup
	$(PYTHON) tools/make.py unit

nbval: setup
	$(PYTHON) tools/make.py nbval

# Offline HTML book: only the `book` set-up (no test tools, no real rclpy); npm ci (only
# when node_modules is missing or stale), vendor RequireJS/ipywidgets/MathJax into
# book/_static/vendor, then jupyter-book build from the stored outputs (tools/book_build.py).
book:
	$(PYTHON) tools/make.py book

# Re-execute every notebook in place (virtual time: same outputs every run).
book-exec: setup
	$(PYTHON) tools/make.py book-exec

# JupyterLab, live time, on a working copy of the book in lab/ (git ignores it):
# autosave never touches the shipped notebooks (see labkit/tools/lab.py). Only the
# learner's set-up (`labkit[lab]`); `labkit lab` is the same command once installed.
lab:
	$(PYTHON) tools/make.py lab

bench: setup
	$(PYTHON) tools/make.py bench

# On demand, not part of `make test`: tests/core, the no-cyclonedds test and ch02 through
# nbval on Linux aarch64 (an arm64 Debian 12 root under qemu-user; root, ~5x slower Python)
.PHONY: arm64
arm64:
	$(PYTHON) tools/qemu_arm64.py

clean:
	rm -rf book/_build .pytest_cache
