"""The test suite mirrors the package and cannot drift from it.

* Every module of ``src/assur`` with a public API of its own (names in its
  ``__all__`` defined there, not re-exported) has its test file:
  ``assur.a.b`` → ``tests/a/test_b.py``, a package's ``__init__`` ``assur.a`` →
  ``tests/a/test_a.py``, ``assur.x`` → ``tests/test_x.py``.
* Every test file outside ``tests/seeds`` (whole machines against their seeds),
  ``tests/docs`` and ``tests/robustness`` (cross-cutting checks) sits in the directory
  of a package of ``src/assur`` and is named ``test_<module>.py`` or
  ``test_<module>_<aspect>.py`` after a module of that package (``test_x.py`` for a
  private ``_x.py``).
* Test files import shared code from ``tests.helpers`` (or fixtures from a
  ``conftest.py``), never from another test file; nothing in ``tests/`` changes
  ``sys.path`` or the working directory.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import pytest

import assur
from tests.helpers import ROOT, TESTS

SRC = ROOT / "src" / "assur"
#: directories of tests that are not about one module
CROSS_CUTTING = {"seeds", "docs", "robustness", "helpers"}


def _public_modules():
    """Names of the modules whose ``__all__`` names something defined in them."""
    out = []
    for info in pkgutil.walk_packages(assur.__path__, "assur."):
        parts = info.name.split(".")[1:]
        if any(p.startswith("_") for p in parts):
            continue
        mod = importlib.import_module(info.name)
        source = Path(mod.__file__).read_text(encoding="utf-8")
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name)
            if inspect.isclass(obj) or inspect.isfunction(obj):
                own = obj.__module__ == info.name
            else:  # a constant: assigned at the module's top level
                own = re.search(rf"^{re.escape(name)}\s*(:[^=\n]*)?=", source, re.M) is not None
            if own:
                out.append(info.name)
                break
    return out


def _test_file(module):
    parts = module.split(".")[1:]
    mod = importlib.import_module(module)
    if mod.__file__.endswith("__init__.py"):
        return TESTS.joinpath(*parts, f"test_{parts[-1]}.py")
    return TESTS.joinpath(*parts[:-1], f"test_{parts[-1]}.py")


def test_the_module_list_is_not_empty():
    mods = _public_modules()
    assert "assur.core.statics" in mods and "assur.io" in mods and "assur.examples" in mods
    assert "assur.groups" not in mods  # re-exports only: its modules have the files


@pytest.mark.parametrize("module", _public_modules())
def test_every_public_module_has_its_test_file(module):
    path = _test_file(module)
    assert path.is_file(), f"{module} has no test file {path.relative_to(ROOT)}"
    tree = ast.parse(path.read_text(encoding="utf-8"))
    tests = [n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)
             and n.name.startswith("test_")]
    assert tests, f"{path.relative_to(ROOT)} holds no test"


def _test_files():
    return sorted(p for p in TESTS.rglob("test_*.py") if "__pycache__" not in p.parts)


def test_every_test_file_is_named_after_a_module_of_its_package():
    stray = []
    for path in _test_files():
        rel = path.relative_to(TESTS)
        if rel.parts[0] in CROSS_CUTTING or rel.as_posix() == "test_layout.py":
            continue
        package = SRC.joinpath(*rel.parts[:-1])
        if not (package / "__init__.py").is_file():
            stray.append(f"{rel}: src/assur/{'/'.join(rel.parts[:-1])} is no package")
            continue
        # a private module _x is tested in test_x.py
        modules = {p.stem.lstrip("_") for p in package.glob("*.py") if p.stem != "__init__"}
        modules |= {p.name for p in package.iterdir() if (p / "__init__.py").is_file()}
        modules.add(package.name)  # the package's own __init__
        name = path.stem[len("test_"):]
        if not any(name == m or name.startswith(m + "_") for m in modules):
            stray.append(f"{rel}: no module {name!r} (or {name.split('_')[0]!r}…) in "
                         f"src/assur/{'/'.join(rel.parts[:-1])}")
    assert not stray, "\n".join(stray)


def test_every_test_directory_is_a_package():
    dirs = {p.parent for p in TESTS.rglob("*.py") if "__pycache__" not in p.parts}
    missing = [str(d.relative_to(ROOT)) for d in dirs if not (d / "__init__.py").is_file()]
    assert not missing, missing


def test_tests_import_helpers_not_other_tests_and_leave_the_path_alone():
    bad = []
    for path in sorted(TESTS.rglob("*.py")):
        if "__pycache__" in path.parts or path == TESTS / "test_layout.py":
            continue
        text = path.read_text(encoding="utf-8")
        rel = path.relative_to(ROOT)
        for node in ast.walk(ast.parse(text)):
            names = []
            if isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module] + [f"{node.module}.{a.name}" for a in node.names]
            elif isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            for n in names:
                top = n.split(".")
                if top[0] in ("conftest", "seed_tables") or top[0].startswith("test_") or (
                        top[0] == "tests" and any(p.startswith("test_") or p == "conftest"
                                                  for p in top[1:])):
                    bad.append(f"{rel}:{node.lineno}: imports {n}")
        for what in ("sys.path.insert", "sys.path.append", "os.chdir("):
            if what in text:
                bad.append(f"{rel}: {what}")
    assert not bad, "\n".join(bad)
