# Developer entry points. `make run` and `make test` set everything up on a fresh Debian machine
# with Python 3.11; re-running them only reinstalls when requirements*.txt changed.

SHELL := /bin/bash
.DEFAULT_GOAL := help

PYTHON      ?= python3.11
VENV        ?= .venv
PY          := $(VENV)/bin/python
# Two stamps: `make run` installs the app's runtime pins only (requirements.txt); `make test`,
# lint and bench the test and lint pins as well (requirements-dev.txt).
RUN_STAMP   := $(VENV)/.requirements-run.stamp
STAMP       := $(VENV)/.requirements.stamp
PORT        ?= 8501
# Optional: HOST=127.0.0.1 to listen on loopback only (Streamlit's default is every interface).
HOST        ?=
CHROMIUM    ?= /usr/bin/chromium
# Extra pytest arguments, e.g. make test PYTEST_ARGS="-m 'not e2e' -x" or PYTEST_ARGS="-n 2".
PYTEST_ARGS ?=

# One BLAS/OpenMP thread: on 2 cores, threaded BLAS made small linear algebra up to 20x slower.
THREADS_ENV := OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1

export PIP_DISABLE_PIP_VERSION_CHECK := 1

.PHONY: help venv venv-run run test lint bench docker-lint chromium clean distclean

help:
	@echo "make run          set up .venv and start the app on http://localhost:$(PORT)"
	@echo "make test         set up .venv (+ Debian chromium if root) and run all tests"
	@echo "make lint         ruff check"
	@echo "make bench        run every script in benchmarks/"
	@echo "make docker-lint  hadolint Dockerfile"
	@echo "make clean        remove caches and test artefacts (keeps .venv)"

venv: $(STAMP)

venv-run: $(RUN_STAMP)

# A venv with python3.11 (installs python3-venv when root and it is missing).
$(PY):
	@if ! $(PYTHON) -c 'import ensurepip, venv' >/dev/null 2>&1; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y python3-venv; \
	  else \
	    echo "$(PYTHON) has no venv/ensurepip: sudo apt-get install python3-venv" >&2; exit 1; \
	  fi; \
	fi
	$(PYTHON) -m venv $(VENV)

# The stamps live inside .venv, so deleting .venv also forces a reinstall. The test stamp
# implies the runtime one (requirements-dev.txt includes requirements.txt).
$(RUN_STAMP): requirements.txt | $(PY)
	@if [ -f $(STAMP) ] && [ $(STAMP) -nt requirements.txt ]; then \
	  echo "runtime pins already installed (with the test pins)"; \
	else \
	  $(PY) -m pip install --no-input -r requirements.txt; \
	fi
	@touch $@

$(STAMP): requirements.txt requirements-dev.txt | $(PY)
	$(PY) -m pip install --no-input -r requirements-dev.txt
	@touch $@ $(RUN_STAMP)

run: venv-run
	$(THREADS_ENV) $(PY) -m streamlit run app.py \
	  --server.port $(PORT) $(if $(HOST),--server.address $(HOST)) \
	  --server.headless true --browser.gatherUsageStats false

# Debian's chromium for the browser tests (Playwright's own browser download fails here).
chromium:
	@if [ ! -x $(CHROMIUM) ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "Installing Debian chromium for the browser tests..."; \
	    apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y chromium fonts-liberation; \
	  else \
	    echo "NOTE: $(CHROMIUM) missing and not root: browser tests will be skipped" \
	         "(sudo apt-get install chromium)." >&2; \
	  fi; \
	fi

test: venv chromium
	$(THREADS_ENV) $(PY) -m pytest $(PYTEST_ARGS)

lint: venv
	$(PY) -m ruff check .

# Each benchmarks/<name>.py runs as `python -m benchmarks.<name>` from the repository root, so it
# imports aerostat_core as the tests do (files starting with "_" are skipped).
bench: venv
	@shopt -s nullglob; status=0; ran=0; \
	for script in benchmarks/*.py; do \
	  name=$$(basename "$$script" .py); \
	  case "$$name" in _*) continue;; esac; \
	  echo "=== benchmarks.$$name"; ran=1; \
	  $(THREADS_ENV) $(PY) -m "benchmarks.$$name" || status=1; \
	done; \
	[ $$ran = 1 ] || echo "no scripts in benchmarks/"; \
	exit $$status

docker-lint: venv
	$(VENV)/bin/hadolint Dockerfile

clean:
	rm -rf artifacts .pytest_cache .ruff_cache .hypothesis
	find . -path ./$(VENV) -prune -o -type d -name __pycache__ -prune -exec rm -rf {} +

distclean: clean
	rm -rf $(VENV)
