# assur — the two commands of the README (`make demo`, `make test`) and `make bench`.
# Each target creates .venv when missing and installs the project with the extras it needs.

PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.assur-installed

.PHONY: demo test test-fast bench clean serve chromium

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip

$(STAMP): pyproject.toml | $(PY)
	$(PY) -m pip install -q -e '.[test]'
	@touch $(STAMP)

demo: $(STAMP)
	$(VENV)/bin/assur demo

# Debian's chromium for the page's end-to-end test (apt-get when missing; .ci/chromium.sh)
chromium:
	bash .ci/chromium.sh

test: $(STAMP) chromium
	$(PY) -m pytest -n 2 --durations=10

test-fast: $(STAMP) chromium
	$(PY) -m pytest -n 2 -m "not slow"

bench: $(STAMP)
	$(PY) benchmarks/run.py
	$(PY) benchmarks/simulate.py
	$(PY) benchmarks/design.py
	$(PY) benchmarks/sensitivity.py
	$(PY) benchmarks/page.py

# the interactive page for the seed-003 hitch (docs/page.md)
serve: $(STAMP)
	$(VENV)/bin/assur serve examples/hitch_003.toml

clean:
	rm -rf $(VENV) assur-demo .pytest_cache .hypothesis build dist src/*.egg-info
	find . -name __pycache__ -type d -prune -exec rm -rf {} +
