# regimemap: `make figures` regenerates figures/, `make test` runs the tests,
# `make lint` runs ruff and mypy, `make bench` the benchmarks.
# Both create the virtual environment .venv when it is missing.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: all venv figures test lint bench clean distclean

all: figures

venv: $(STAMP)

$(STAMP): pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	@touch $(STAMP)

# The design sheet and the motion figures are drawn while `figures` draws the maps
# (one process per core): the three run side by side, and make fails if any fails.
figures: $(STAMP)
	$(BIN)/regimemap caisson --example > $(VENV)/goda.toml
	@set -e; \
	$(BIN)/regimemap caisson $(VENV)/goda.toml -o figures/caisson-sheet.png > /dev/null & sheet=$$!; \
	$(BIN)/regimemap dynamics-figures --out figures --format png,svg \
	    --cache .cache/dynamics-figures & motion=$$!; \
	$(BIN)/regimemap figures --out figures --format png,svg --set all; \
	wait $$sheet; wait $$motion

test: $(STAMP)
	$(BIN)/python -m pytest -q

lint: $(STAMP)
	$(BIN)/ruff check src tests bench
	$(BIN)/mypy

bench: $(STAMP)
	$(BIN)/python bench/bench.py

clean:
	rm -rf .pytest_cache .hypothesis .mypy_cache .ruff_cache .cache build src/*.egg-info
	find . -name __pycache__ -type d -prune -exec rm -rf {} +

distclean: clean
	rm -rf $(VENV)
