# regimemap: `make figures` regenerates figures/, `make test` runs the tests (`make test-fast`
# the quick ones, `make test-portable` those marked portable again at each of numpy's CPU
# dispatch levels, `make test-stress` the interrupts at random moments), `make lint` runs ruff
# and mypy, `make bench` the benchmarks, `make docs` builds the documentation site into
# docs/_build/html.
# Both create the virtual environment .venv when it is missing.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
DOCS_STAMP := $(VENV)/.docs-installed

.PHONY: all venv figures test test-fast test-deep test-stress test-portable lint bench docs clean distclean

all: figures

venv: $(STAMP)

$(STAMP): pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	@touch $(STAMP)

# The design sheet, the motion figures and the lifetime figures (Goda's caisson over 50 years:
# the exceedance curve and the design chart) are drawn while `figures` draws the maps (one
# process per core): they run side by side, and make fails if any fails.  The design chart
# (21 widths x 5000 lifetimes, one core) is the longest of them: it starts first, and the
# exceedance curve runs beside it rather than before it.
figures: $(STAMP)
	$(BIN)/regimemap caisson --example > $(VENV)/goda.toml
	@set -e; \
	$(BIN)/regimemap lifetime $(VENV)/goda.toml --jobs 1 --quiet --width 10:25:21 --target 0.1 \
	    -o figures/lifetime-chart-goda.png -o figures/lifetime-chart-goda.svg > /dev/null & chart=$$!; \
	$(BIN)/regimemap lifetime $(VENV)/goda.toml --jobs 1 --quiet \
	    -o figures/lifetime-goda.png -o figures/lifetime-goda.svg > /dev/null & life=$$!; \
	$(BIN)/regimemap caisson $(VENV)/goda.toml -o figures/caisson-sheet.png > /dev/null & sheet=$$!; \
	$(BIN)/regimemap dynamics-figures --out figures --format png,svg \
	    --cache .cache/dynamics-figures & motion=$$!; \
	$(BIN)/regimemap figures --out figures --format png,svg --set all; \
	wait $$sheet; wait $$motion; wait $$life; wait $$chart

# `make test`: every test and doctest, on every core (pytest-xdist; worksteal evens out the long
# ones).  `make test-fast`: the edit loop -- engine, io, validation, layers -- without the tests
# marked render, subprocess or slow (pyproject.toml lists the markers).
# `make test-deep`: the deep tier (the long reference integrations, the solver sweeps beyond their
# spread sample, the whole figure sets, the README run and the other tests of over ~1.5 s), which
# the other two leave out so that `make test` stays near three minutes on two cores; CI runs it
# after `make test`.
# `make test-stress`: the stress tier (Ctrl-C 1-5 times at random moments, 50 runs across the
# commands; a few minutes), which the other two leave out; CI runs it after `make test-deep`.
TEST_FAST := not render and not subprocess and not slow and not stress and not deep
# Python's bytecode cache stays on for the tests whatever the shell says (PYTHONDONTWRITEBYTECODE):
# without it every xdist worker rewrites the asserts of every test module and every `regimemap`
# a test starts compiles the package again -- ten seconds a worker before the first test.
PYTEST := env -u PYTHONDONTWRITEBYTECODE $(BIN)/python -m pytest

test: $(STAMP)
	$(PYTEST) -q -n auto --dist worksteal -m "not stress and not deep"

test-fast: $(STAMP)
	$(PYTEST) -q -n auto --dist worksteal -m "$(TEST_FAST)"

test-deep: $(STAMP)
	$(PYTEST) -q -n auto --dist worksteal -m deep

test-stress: $(STAMP)
	$(PYTEST) -q -n auto --dist worksteal -m stress

# `make test-portable`: the tests marked portable (pinned numbers, the same bits within a run) once
# per numpy dispatch level of this CPU above the baseline, the highest dropped first
# (NPY_DISABLE_CPU_FEATURES; on an AVX-512 machine "X86_V4 ...", then "X86_V3 X86_V4 ..."), so that
# an assertion that holds on this CPU only fails here; it says which levels this CPU lacks.
test-portable: $(STAMP)
	$(BIN)/python tests/cpu_levels.py -q -p no:cacheprovider

# ruff's rules (pyproject.toml, [tool.ruff.lint]) include the complexity limits -- C901,
# PLR0912, PLR0913, PLR0915 -- so a function that outgrows them fails here.  sp-repo-review runs
# the Scientific Python development guide's checks on the repository (the skipped ones, and why,
# in [tool.repo-review]); it prints the failures only.
lint: $(STAMP)
	$(BIN)/ruff check src tests bench conftest.py
	$(BIN)/mypy
	$(BIN)/sp-repo-review --show err .

bench: $(STAMP)
	$(BIN)/python bench/bench.py

# The documentation site (docs/conf.py): warnings are errors.  The html build runs the
# gallery's scripts (docs/examples; all of them in a fresh tree, as in CI, else those that
# changed: rm -rf docs/auto_examples runs them all) and the commands of the pages; the
# doctest build runs every >>> example of the pages and of the docstrings the API shows.
$(DOCS_STAMP): pyproject.toml $(STAMP)
	$(BIN)/python -m pip install --quiet -e '.[docs]'
	@touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)
	$(BIN)/sphinx-build -b html -W --keep-going -q -d docs/_build/doctrees docs docs/_build/html
	$(BIN)/sphinx-build -b doctest -W --keep-going -q -d docs/_build/doctrees docs docs/_build/doctest

.PHONY: dist

# `make dist`: the sdist and the wheel into dist/ (python -m build, in an isolated environment with
# the build requirements of pyproject.toml), checked by twine.  The version is git's (setuptools-scm);
# building writes it into src/regimemap/_version.py, so the editable install is then brought to
# the same version (its metadata and that file agree).
dist: $(STAMP)
	rm -rf dist
	$(BIN)/python -m build --outdir dist .
	$(BIN)/twine check --strict dist/*
	$(BIN)/python -m pip install --quiet --no-deps --no-build-isolation -e .

clean:
	rm -rf .pytest_cache .hypothesis .mypy_cache .ruff_cache .cache build dist src/*.egg-info
	find . -name __pycache__ -type d -prune -exec rm -rf {} +

distclean: clean
	rm -rf $(VENV)
