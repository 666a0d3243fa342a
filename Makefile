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

# The design sheet, the motion figures and the lifetime figures (Goda's caisson over 50 years:
# the exceedance curve and the design chart) are drawn while `figures` draws the maps (one
# process per core): they run side by side, and make fails if any fails.
figures: $(STAMP)
	$(BIN)/regimemap caisson --example > $(VENV)/goda.toml
	@set -e; \
	$(BIN)/regimemap caisson $(VENV)/goda.toml -o figures/caisson-sheet.png > /dev/null & sheet=$$!; \
	$(BIN)/regimemap dynamics-figures --out figures --format png,svg \
	    --cache .cache/dynamics-figures & motion=$$!; \
	( $(BIN)/regimemap lifetime $(VENV)/goda.toml --jobs 1 --quiet \
	    -o figures/lifetime-goda.png -o figures/lifetime-goda.svg > /dev/null && \
	  $(BIN)/regimemap lifetime $(VENV)/goda.toml --jobs 1 --quiet --width 10:25:21 --target 0.1 \
	    -o figures/lifetime-chart-goda.png -o figures/lifetime-chart-goda.svg > /dev/null ) & life=$$!; \
	$(BIN)/regimemap figures --out figures --format png,svg --set all; \
	wait $$sheet; wait $$motion; wait $$life

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
