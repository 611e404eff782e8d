# ballrace — every target creates .venv when it is missing.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
export PYVISTA_OFF_SCREEN := true
export MPLBACKEND := Agg

.PHONY: all venv validate test test-fem test-all bench clean

all: test

venv: $(STAMP)

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip setuptools wheel
	$(BIN)/python -m pip install --quiet -e ".[all]"
	touch $(STAMP)

## The main job: analytic reference checks (and quick FE checks), summary table, report in reports/latest/
validate: $(STAMP)
	$(BIN)/ballrace validate --report reports/latest

## Default test suite (analytic + quick FE level), well under 15 minutes
test: $(STAMP)
	$(BIN)/python -m pytest -m "not slow" -q

## Standard-level FE checks (slow)
test-fem: $(STAMP)
	$(BIN)/python -m pytest -m "slow" -q

test-all: $(STAMP)
	$(BIN)/python -m pytest -q

## Benchmarks (by hand): throughput and accuracy figures
bench: $(STAMP)
	$(BIN)/python -m pytest benchmarks -q --benchmark-only --benchmark-columns=min,mean,max,rounds

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache .hypothesis .benchmarks reports/latest
