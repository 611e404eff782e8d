# ballrace — every target creates .venv when it is missing.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
export PYVISTA_OFF_SCREEN := true
export MPLBACKEND := Agg

.PHONY: all venv validate test test-fem test-all bench docs test-docs fuzz clean

all: test

venv: $(STAMP)

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip setuptools wheel
	$(BIN)/python -m pip install --quiet -e ".[all]"
	@# Sparse solver for the FE check (docs/fem.md): CHOLMOD needs SuiteSparse headers and
	@# OpenBLAS from apt (root or passwordless sudo); without them fall back to pip-only
	@# pypardiso (MKL, ~1 GB).  pyamg (in the fem extra) and SuperLU remain as last resorts.
	@SUDO=""; [ "$$(id -u)" = 0 ] || SUDO="sudo -n"; \
	if command -v apt-get >/dev/null 2>&1 && $$SUDO true 2>/dev/null; then \
	  { DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq libsuitesparse-dev \
	      libopenblas0-pthread >/dev/null 2>&1 \
	    || { $$SUDO apt-get update -qq >/dev/null 2>&1 && \
	         DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq libsuitesparse-dev \
	           libopenblas0-pthread >/dev/null 2>&1; } \
	    || echo "note: apt-get install of SuiteSparse failed"; }; \
	else echo "note: no apt-get/root: skipping SuiteSparse (CHOLMOD)"; fi
	@$(BIN)/python -m pip install --quiet "scikit-sparse==0.4.16" 2>/dev/null \
	  || { echo "note: scikit-sparse (CHOLMOD) unavailable; installing pypardiso instead"; \
	       $(BIN)/python -m pip install --quiet pypardiso \
	       || echo "note: pypardiso unavailable; the FE check will use pyamg or SuperLU"; }
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

## Long fuzz run of the solvers (tests/test_fuzz.py): 10^4 fresh random cases for the static
## load distribution, fewer for the slower solvers; summary (cases, refusals, convergence
## failures, worst residual per entry point) in .hypothesis/fuzz-report.jsonl
fuzz: $(STAMP)
	@mkdir -p .hypothesis && rm -f .hypothesis/fuzz-report.jsonl
	HYPOTHESIS_PROFILE=fuzz BALLRACE_FUZZ_REPORT=.hypothesis/fuzz-report.jsonl \
	  $(BIN)/python -m pytest tests/test_fuzz.py -q -p no:cacheprovider; \
	  status=$$?; cat .hypothesis/fuzz-report.jsonl; exit $$status

## Benchmarks (by hand): throughput and accuracy figures
bench: $(STAMP)
	$(BIN)/python -m pytest benchmarks -q --benchmark-only --benchmark-columns=min,mean,max,rounds

## Documentation site -> docs/_build/html/index.html (runs the gallery; warnings are errors)
docs: $(STAMP)
	$(BIN)/python -m sphinx -b html -E -W --keep-going docs docs/_build/html

## The site's own checks (CI): build it, then its links/API/case tests and the slow gallery script
test-docs: docs
	BALLRACE_DOCS_HTML=docs/_build/html $(BIN)/python -m pytest -q tests/test_docs.py \
	  tests/test_gallery.py

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache .hypothesis .benchmarks reports/latest
	rm -rf docs/_build docs/auto_gallery docs/api/generated docs/cases docs/sg_execution_times.rst
