# assur — the two commands of the README (`make demo`, `make test`) and `make bench`.
# Each target creates .venv when missing and installs the project with the extras it needs.

PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.assur-installed

.PHONY: demo test test-fast bench clean

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip

$(STAMP): pyproject.toml | $(PY)
	$(PY) -m pip install -q -e '.[test]'
	@touch $(STAMP)

demo: $(STAMP)
	$(VENV)/bin/assur demo

test: $(STAMP)
	$(PY) -m pytest -n 2 --durations=10

test-fast: $(STAMP)
	$(PY) -m pytest -n 2 -m "not slow"

bench: $(STAMP)
	$(PY) benchmarks/run.py
	$(PY) benchmarks/simulate.py
	$(PY) benchmarks/design.py
	$(PY) benchmarks/sensitivity.py

clean:
	rm -rf $(VENV) assur-demo .pytest_cache .hypothesis build dist src/*.egg-info
	find . -name __pycache__ -type d -prune -exec rm -rf {} +
