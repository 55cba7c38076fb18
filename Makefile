# assur — the two commands of the README (`make demo`, `make test`), `make bench`,
# `make docs` (the documentation site) and `make wheel-check` (the release artefacts).
# Each target creates .venv when missing and installs the project with the extras it needs.

PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.assur-installed
CORE_STAMP := $(VENV)/.assur-core-installed
PAGE_STAMP := $(VENV)/.assur-page-installed
DOCS_STAMP := $(VENV)/.assur-docs-installed
RELEASE_STAMP := $(VENV)/.assur-release-installed
#: bundled models that must fail `assur check` (the seeds as printed cannot assemble)
EXPECTED_FAIL := header_000 combine_002_printed

.PHONY: demo test test-fast lint bench docs wheel-check clean serve chromium

# Packages are installed without compiling their bytecode (--no-compile): Python
# compiles a module when it is first imported, so an install does not compile the
# thousands of modules a command never imports (make demo's install: 70 s -> 35 s).
PIP := $(PY) -m pip install -q --no-compile

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PIP) --upgrade pip

# the package and its dependencies (what `make demo` needs) …
$(CORE_STAMP): pyproject.toml | $(PY)
	$(PIP) -e .
	@touch $(CORE_STAMP)

# … with the interactive page's (`make serve`) …
$(PAGE_STAMP): pyproject.toml | $(PY)
	$(PIP) -e '.[page]'
	@touch $(PAGE_STAMP) $(CORE_STAMP)

# … and every extra with the test tools (pytest, hypothesis, Playwright, import-linter …)
$(STAMP): pyproject.toml | $(PY)
	$(PIP) -e '.[test]'
	@touch $(STAMP) $(CORE_STAMP) $(PAGE_STAMP)

demo: $(CORE_STAMP)
	$(VENV)/bin/assur demo

# Debian's chromium for the page's end-to-end test (apt-get when missing; .ci/chromium.sh)
chromium:
	bash .ci/chromium.sh

# the layers of the package import one way (pyproject.toml [tool.importlinter],
# docs/architecture.md)
lint: $(STAMP)
	$(VENV)/bin/lint-imports

# The tests write their bytecode caches (pytest's rewritten test modules too) even
# where the environment says not to (PYTHONDONTWRITEBYTECODE): a later run, and every
# subprocess a test starts, then compiles nothing again (collection 18 s -> 9 s).
TEST_ENV := env -u PYTHONDONTWRITEBYTECODE

test: $(STAMP) chromium
	$(TEST_ENV) $(PY) -m pytest -n 2 --dist worksteal --durations=10

test-fast: $(STAMP) chromium
	$(TEST_ENV) $(PY) -m pytest -n 2 --dist worksteal -m "not slow"

bench: $(STAMP)
	$(PY) benchmarks/run.py
	$(PY) benchmarks/simulate.py
	$(PY) benchmarks/design.py
	$(PY) benchmarks/sensitivity.py
	$(PY) benchmarks/page.py
	$(PY) benchmarks/report.py
	$(PY) benchmarks/latency.py
	$(PY) benchmarks/scale.py

# the interactive page for the seed-003 hitch (docs/page.md)
serve: $(PAGE_STAMP)
	$(VENV)/bin/assur serve examples/hitch_003.toml

# The documentation site, offline, warnings as errors; a broken gallery example fails it.
$(DOCS_STAMP): pyproject.toml | $(PY)
	$(PIP) -e '.[docs]'
	@touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)
	MPLBACKEND=Agg $(PY) -m sphinx -b html -W --keep-going -q docs docs/_build/html
	@echo "docs: docs/_build/html/index.html"

# Wheel and sdist built (python -m build), the wheel installed into a fresh venv
# outside the checkout, and `assur check` run there on every bundled model (package
# data): the seeds that cannot assemble must fail with one message, the others pass.
$(RELEASE_STAMP): pyproject.toml | $(PY)
	$(PIP) -e '.[release]'
	@touch $(RELEASE_STAMP)

wheel-check: $(RELEASE_STAMP)
	rm -rf dist
	$(PY) -m build --outdir dist . > dist.log 2>&1 || (cat dist.log; exit 1)
	@if grep -Ei "deprecat|SetuptoolsWarning|BuildBackendWarning" dist.log; then \
		echo "wheel-check: the build printed a setuptools warning"; exit 1; fi
	@rm -f dist.log
	@tar -tzf dist/assur-*.tar.gz | grep -q "src/assur/models/hitch_003.toml" \
		|| (echo "wheel-check: the sdist lacks the bundled models"; exit 1)
	@tar -tzf dist/assur-*.tar.gz | grep -q "/LICENSE$$" \
		|| (echo "wheel-check: the sdist lacks LICENSE"; exit 1)
	@set -e; tmp=$$(mktemp -d); trap 'rm -rf "$$tmp"' EXIT; \
	$(PYTHON) -m venv "$$tmp/venv"; \
	"$$tmp/venv/bin/python" -m pip install -q --no-compile dist/assur-*.whl; \
	cd "$$tmp"; \
	"$$tmp/venv/bin/assur" --version; \
	"$$tmp/venv/bin/python" -m assur --version; \
	models=$$("$$tmp/venv/bin/python" -c "import importlib.resources as r; print(' '.join(sorted(p.name[:-5] for p in r.files('assur.models').iterdir() if p.name.endswith('.toml'))))"); \
	test -n "$$models"; n=0; \
	for name in $$models; do \
		file=$$("$$tmp/venv/bin/python" -c "from assur.io import bundled; print(bundled('$$name'))"); \
		case "$$file" in "$$tmp"/*) ;; *) echo "wheel-check: $$name is not in the installed wheel: $$file"; exit 1;; esac; \
		if echo " $(EXPECTED_FAIL) " | grep -q " $$name "; then \
			if "$$tmp/venv/bin/assur" check "$$file" > out.txt 2>&1; then \
				echo "wheel-check: $$name should not assemble"; cat out.txt; exit 1; fi; \
			grep -q "cannot" out.txt && ! grep -q Traceback out.txt \
				|| (echo "wheel-check: $$name failed without its message"; cat out.txt; exit 1); \
			echo "ok: $$name cannot assemble (as the seed prints it)"; \
		else \
			"$$tmp/venv/bin/assur" check "$$file" > out.txt 2>&1 || (cat out.txt; exit 1); \
			echo "ok: $$name"; \
		fi; n=$$((n + 1)); \
	done; \
	echo "wheel-check: $$n bundled models checked from the installed wheel"

clean:
	rm -rf $(VENV) assur-demo .pytest_cache .hypothesis build dist src/*.egg-info \
		docs/_build docs/_generated docs/api docs/api.md docs/auto_gallery docs/auto_tutorials
	find . -name __pycache__ -type d -prune -exec rm -rf {} +
