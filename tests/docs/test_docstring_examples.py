"""Every public function, class and method has an example that runs (issue 14).

*Public* means: named in the ``__all__`` of a module of ``assur`` whose dotted path
has no underscored part (a class or a function, counted once in the module that
defines it), and every method and property such a class defines without a leading
underscore.  An example is a ``>>>`` line in the docstring the user sees
(``inspect.getdoc``, so a method that keeps its base class's docstring shows that
example).  The examples themselves run as doctests: ``--doctest-modules`` over
``src/assur`` in ``pyproject.toml``, so a broken example fails the suite.

Run as a script to list what lacks an example, optionally for some modules only::

    python tests/docs/test_docstring_examples.py assur.groups.base assur.core.kinematics
"""
from __future__ import annotations

import importlib
import inspect
import pkgutil
import sys

import assur


def _modules():
    yield assur
    for info in pkgutil.walk_packages(assur.__path__, "assur."):
        if any(part.startswith("_") for part in info.name.split(".")[1:]):
            continue
        yield importlib.import_module(info.name)


def public_objects():
    """``(module, qualified name, kind, object)`` of every public object, each once."""
    seen = set()
    for module in _modules():
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name)
            if not (inspect.isclass(obj) or inspect.isfunction(obj)):
                continue
            key = (obj.__module__, obj.__qualname__)
            if key in seen:
                continue
            seen.add(key)
            yield obj.__module__, obj.__qualname__, "class" if inspect.isclass(obj) else "function", obj
            if not inspect.isclass(obj):
                continue
            for attr, raw in vars(obj).items():
                if attr.startswith("_"):
                    continue
                if isinstance(raw, property):
                    kind, member = "property", raw
                elif inspect.isfunction(getattr(raw, "__func__", raw)):
                    kind, member = "method", getattr(obj, attr)
                else:
                    continue
                yield obj.__module__, f"{obj.__qualname__}.{attr}", kind, member


def has_example(obj) -> bool:
    return ">>>" in (inspect.getdoc(obj) or "")


def missing(modules=()):
    return [(mod, qual, kind) for mod, qual, kind, obj in public_objects()
            if (not modules or mod in modules) and not has_example(obj)]


def test_the_public_api_is_found():
    """The lister sees the entry points, so an empty 'missing' list means something."""
    names = {(mod, qual) for mod, qual, _, _ in public_objects()}
    assert ("assur.analysis", "analyze") in names
    assert ("assur.core.mechanism", "Mechanism.solve") in names
    assert ("assur.core.kinematics", "Kinematics") in names
    assert len(names) > 700


def test_every_public_object_has_an_example():
    lacking = missing()
    assert not lacking, (f"{len(lacking)} public objects have no example (>>>) in their "
                         "docstring:\n" + "\n".join(f"  {m}.{q} ({k})" for m, q, k in lacking))


if __name__ == "__main__":
    rows = missing(tuple(sys.argv[1:]))
    for mod, qual, kind in rows:
        print(f"{mod}.{qual}  ({kind})")
    print(f"{len(rows)} without an example")
