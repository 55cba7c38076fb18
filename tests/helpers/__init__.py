"""Code shared by the tests: paths, the hypothesis profiles and example counts.

The modules beside this one hold what several test files use (the seed tables,
the random-mechanism builders of the property tests, small mechanisms); a test
file imports them as ``tests.helpers.<module>``, never another test file.
"""

from __future__ import annotations

import os
from pathlib import Path

from hypothesis import settings

#: the project (the checkout: src/, docs/, tests/ …)
ROOT = Path(__file__).resolve().parents[2]
#: the tests' directory
TESTS = ROOT / "tests"
#: the documentation sources
DOCS = ROOT / "docs"
#: the shared material beside the project (``../shared``: the seeds, the brief)
SHARED = ROOT.parent / "shared"
#: the seed documents
SEEDS = SHARED / "seeds"

settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
settings.register_profile("dev", deadline=None)
settings.register_profile("deep", deadline=None, print_blob=True)
#: the hypothesis profile of this run (see tests/conftest.py)
PROFILE = os.environ.get("ASSUR_HYPOTHESIS") or ("ci" if os.environ.get("CI") else "dev")
#: whether the property tests that report their worst error ratio as a hypothesis
#: ``target`` also hill-climb towards larger ratios after generating their examples
#: (``Phase.target``): in the ``deep`` profile only — a hunt for the worst case, run
#: by hand (``ASSUR_HYPOTHESIS=deep``), which roughly doubles those tests' time
TARGETING = PROFILE == "deep"


def examples(n: int) -> int:
    """Examples of a property test: ``n`` in the ``ci`` and ``deep`` profiles, n/5 (≥ 10)
    in ``dev``."""
    return n if PROFILE in ("ci", "deep") else max(10, n // 5)


def import_path(name: str, path: Path):
    """Import the module or package at ``path`` (a ``.py`` file or a directory with
    ``__init__.py``) as ``name``, without touching ``sys.path``; a package's
    submodules then import as ``name.<sub>``."""
    import importlib.util
    import sys

    if name in sys.modules:
        return sys.modules[name]
    path = Path(path)
    if path.is_dir():
        spec = importlib.util.spec_from_file_location(
            name, path / "__init__.py", submodule_search_locations=[str(path)])
    else:
        spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[name]
        raise
    return module


def by_numpy(make, *args):
    """``make(*args)`` with numpy evaluating the kernel calls, the backend restored
    after: in a test of the compiled kernels, a model's load (its ``[[solve]]``
    conditions) or a pose point's pre-pass (a few small calls of structures of their
    own) compiles none of their kernels, only those the test is about."""
    from assur.kernel import vector as KV

    was = KV.backend()
    KV.set_backend("numpy")
    try:
        return make(*args)
    finally:
        KV.set_backend(was)


def python_output(code: str) -> str:
    """The standard output of ``code`` run by this interpreter in a fresh process
    (stripped): what a module imports on its own, away from the test session's."""
    import subprocess
    import sys

    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       check=True)
    return r.stdout.strip()
