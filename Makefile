# ballrace — every target creates .venv when it is missing.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
export PYVISTA_OFF_SCREEN := true
export MPLBACKEND := Agg

.PHONY: all venv cholmod validate validate-sweep test test-fem test-all bench docs test-docs fuzz clean

all: test

venv: $(STAMP)

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip setuptools wheel
	$(BIN)/python -m pip install --quiet -e ".[all]"
	@echo "installed; the FE check uses pypardiso (pip, Linux/Windows x86-64) or SciPy's"
	@echo "SuperLU; for the optional CHOLMOD speed-up run 'make cholmod' (apt, root/sudo)."
	touch $(STAMP)

## Optional FE speed-up: CHOLMOD (scikit-sparse) instead of pypardiso.  It runs
## `apt-get install libsuitesparse-dev libopenblas0-pthread` as root (or `sudo -n`) and then
## pip-installs scikit-sparse 0.4.16 into the venv; skip it and pypardiso is used.
cholmod: $(STAMP)
	@echo "make cholmod: apt-get install -y libsuitesparse-dev libopenblas0-pthread (needs root"
	@echo "or passwordless sudo), then pip install scikit-sparse==0.4.16 (the extra fem-cholmod)."
	@echo "Optional: skip it and the FE check uses pypardiso."
	@SUDO=""; [ "$$(id -u)" = 0 ] || SUDO="sudo -n"; \
	command -v apt-get >/dev/null 2>&1 || { echo "no apt-get here: install SuiteSparse by hand"; exit 1; }; \
	$$SUDO true 2>/dev/null || { echo "neither root nor passwordless sudo: skipped"; exit 1; }; \
	DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq libsuitesparse-dev \
	    libopenblas0-pthread >/dev/null \
	  || { $$SUDO apt-get update -qq >/dev/null && DEBIAN_FRONTEND=noninteractive \
	       $$SUDO apt-get install -y -qq libsuitesparse-dev libopenblas0-pthread >/dev/null; }
	$(BIN)/python -m pip install --quiet "scikit-sparse==0.4.16"
	@$(BIN)/python -c "from ballrace.fem.solvers import chosen_solver as c; print('FE solver now:', c())"

## The main job: analytic reference checks (and quick FE checks), summary table, report in reports/latest/
validate: $(STAMP)
	$(BIN)/ballrace validate --report reports/latest

## On-demand FE sweep "where Hertz holds" (Hertz vs exact gap over conformity x a/(fD) x race,
## validation/cases/fem_hertz_limits.toml; docs/fem-sweep.md), 2 dask workers, report in
## reports/out/sweep/; SWEEP_LEVEL=standard for the standard mesh (longer)
SWEEP_LEVEL ?= quick
validate-sweep: $(STAMP)
	$(BIN)/ballrace validate --cases fem_hertz_limits.toml --fem $(SWEEP_LEVEL) --workers 2 \
	  --report reports/out/sweep

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
	rm -f analytic/_ldkernel*.so
	rm -rf docs/_build docs/auto_gallery docs/api/generated docs/cases docs/cli docs/sg_execution_times.rst
