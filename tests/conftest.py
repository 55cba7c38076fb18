"""Test configuration: paths, the kernel cache of the tests, hypothesis profiles.

* The tests read ``../shared/`` from the project root and import ``seed_tables.py``
  from beside them.
* Generated kernels go to a cache of the tests' own (``<project>/.assur-test-cache``,
  git-ignored) unless ``ASSUR_CACHE_DIR`` is set: a test run never writes into the
  user's ``~/.cache/assur``, and repeated runs reuse their compiled kernels.
* Hypothesis profiles: ``ci`` (the default when ``CI`` is set, as in ``.ci/run``):
  derandomized — a fixed seed, the same examples on every run — and every property
  test at its full number of examples; ``dev`` (the default otherwise): random
  seeds and a fifth of the examples (at least 10), for quick local runs. Choose one
  with ``--hypothesis-profile=ci`` or ``ASSUR_HYPOTHESIS=ci``. Property tests size
  their example counts with :func:`examples`.
"""

import os
import sys

import pytest
from hypothesis import settings

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(__file__))
os.chdir(ROOT)
os.environ.setdefault("ASSUR_CACHE_DIR", os.path.join(ROOT, ".assur-test-cache"))

settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
settings.register_profile("dev", deadline=None)
PROFILE = os.environ.get("ASSUR_HYPOTHESIS") or ("ci" if os.environ.get("CI") else "dev")
settings.load_profile(PROFILE)


def examples(n: int) -> int:
    """Examples of a property test: ``n`` in the ``ci`` profile, n/5 (≥ 10) in ``dev``."""
    return n if PROFILE == "ci" else max(10, n // 5)


@pytest.fixture
def page_log(request):
    """``page_log(line)``: show a measurement of the page's tests in the terminal
    (without xdist, whose workers keep their output) and append it to
    ``.pytest_cache/assur-page.log``."""
    from pathlib import Path

    def log(line):
        tr = request.config.pluginmanager.get_plugin("terminalreporter")
        if tr is not None and "PYTEST_XDIST_WORKER" not in os.environ:
            tr.write_line(line)
        path = Path(request.config.rootpath) / ".pytest_cache" / "assur-page.log"
        path.parent.mkdir(exist_ok=True)
        with open(path, "a", encoding="utf-8") as f:
            f.write(line.strip() + "\n")

    return log
