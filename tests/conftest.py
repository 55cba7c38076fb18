"""Test configuration: the kernel cache of the tests, hypothesis profiles, shared fixtures.

* Paths come from :mod:`tests.helpers` (``ROOT``, ``SHARED`` …, computed from this
  file): no test depends on the working directory. ``tests`` is a package, so a test
  imports shared code as ``tests.helpers.<module>`` (pytest puts the project's root
  on ``sys.path`` for it).
* Generated kernels go to a cache of the tests' own (``<project>/.assur-test-cache``,
  git-ignored) unless ``ASSUR_CACHE_DIR`` is set: a test run never writes into the
  user's ``~/.cache/assur``, and repeated runs reuse their compiled kernels.
* Hypothesis profiles: ``ci`` (the default when ``CI`` is set, as in ``.ci/run``):
  derandomized — a fixed seed, the same examples on every run — and every property
  test at its full number of examples; ``dev`` (the default otherwise): random
  seeds and a fifth of the examples (at least 10), for quick local runs; ``deep``:
  random seeds, every example, and the property tests that report their worst error
  ratio as a ``target`` hill-climb towards larger ones (a hunt by hand). Choose one
  with ``--hypothesis-profile=ci`` or ``ASSUR_HYPOTHESIS=ci``. Property tests size
  their example counts with :func:`tests.helpers.examples`.
* Kernels are evaluated by numpy (``ASSUR_KERNELS=numpy`` unless set: the same emitted
  code as the compiled kernels, with their results to rounding — held by
  ``tests/kernel/test_vector.py`` and ``tests/core/test_outputs.py`` on random
  mechanisms of every group type and the bundled models), so that a test of the
  formulas does not pay numba's compilation of its structure (2–10 s each, a
  cold run compiled ~270 of them). The compiled kernels run in ``tests/kernel``
  and in tests marked ``compiled`` (:func:`kernel_backend`): those about the
  compiled path itself (threads, streaming, composed kernels) and those that make
  thousands of calls of one structure (a simulation).
* Every test leaves ``os.environ`` as it found it (:func:`restore_environ`: a Dask
  cluster, for one, sets thread counts in the process that starts it).
"""

import os

import pytest
from hypothesis import settings

from tests.helpers import PROFILE, ROOT

os.environ.setdefault("ASSUR_CACHE_DIR", str(ROOT / ".assur-test-cache"))
os.environ.setdefault("ASSUR_KERNELS", "numpy")
settings.load_profile(PROFILE)


@pytest.fixture(autouse=True)
def kernel_backend(request):
    """Compiled kernels (``numba``) for the tests in ``tests/kernel`` and those marked
    ``compiled``; the process's backend (``$ASSUR_KERNELS``, numpy in the tests) for
    the others."""
    from assur.kernel import vector as KV

    path = request.node.path
    compiled = (request.node.get_closest_marker("compiled") is not None
                or (path.parent.name == "kernel" and path.parent.parent.name == "tests"))
    if not compiled:
        yield
        return
    KV.set_backend("numba")
    try:
        yield
    finally:
        KV.set_backend(None)


@pytest.fixture(autouse=True)
def restore_environ():
    """Snapshot ``os.environ`` before every test and put it back afterwards (what a
    test adds is removed, what it changes or removes is restored)."""
    saved = _environ()
    yield
    now = _environ()
    for key in now.keys() - saved.keys():
        del os.environ[key]
    for key, value in saved.items():
        if now.get(key) != value:
            os.environ[key] = value


def _environ():
    """``os.environ`` without pytest's own ``PYTEST_CURRENT_TEST`` (set per phase)."""
    return {k: v for k, v in os.environ.items() if k != "PYTEST_CURRENT_TEST"}


@pytest.fixture(scope="session")
def hitch_analysis():
    """The seed-003 hitch analysed over the seed's range (``examples.hitch_003()`` at
    ``examples.hitch_003_range()``), once per session; tests must not change it."""
    from assur import examples
    return examples.hitch_003().analyze(examples.hitch_003_range())


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
