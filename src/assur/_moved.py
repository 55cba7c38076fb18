"""Old module paths of assur 0.1, kept working for one release.

The package was laid out in layers (docs/architecture.md); every module that moved
is listed here, old name → new name, and imports of the old name keep working with
a :class:`DeprecationWarning` that names the new one (the CHANGELOG lists the same
moves). The old names go in the next release.

Examples
--------
>>> import warnings
>>> from assur._moved import new_name
>>> new_name("assur.hydraulics"), new_name("assur.report.tables")
('assur.machines.cylinders', 'assur.views.report.tables')
>>> print(new_name("assur.core.statics"))     # not an old name
None
>>> with warnings.catch_warnings(record=True) as w:
...     warnings.simplefilter("always")
...     from assur.hydraulics import piston_area
>>> piston_area.__module__, w[0].category.__name__
('assur.core.cylinders', 'DeprecationWarning')
>>> str(w[0].message)
'assur.hydraulics moved to assur.machines.cylinders; the old name goes in the next release'
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
import types
import warnings

__all__ = ["MOVED", "MOVED_PACKAGES", "MOVED_NAMES", "new_name", "install"]

#: modules that moved, old name → new name
MOVED = {
    "assur.app.geometry": "assur.views.geometry",
    "assur.balancing": "assur.dynamics.balancing",
    "assur.capacity": "assur.machines.capacity",
    "assur.chains": "assur.core.chains",
    "assur.cli": "assur.views.cli",
    "assur.columns": "assur.core.columns",
    "assur.conditioner": "assur.machines.conditioner",
    "assur.design.files": "assur.io.problems",
    "assur.diagnostics": "assur.core.diagnostics",
    "assur.display": "assur.views.notebook",
    "assur.fitting": "assur.synthesis.fitting",
    "assur.flywheel": "assur.dynamics.flywheel",
    "assur.fused": "assur.core.outputs",
    "assur.hydraulics": "assur.machines.cylinders",
    "assur.inertia": "assur.dynamics.crank",
    "assur.inputs": "assur.core.inputs",
    "assur.kinematics": "assur.core.kinematics",
    "assur.lift_test": "assur.machines.hitch_lift",
    "assur.loads": "assur.core.loads",
    "assur.mechanism": "assur.core.mechanism",
    "assur.motion": "assur.core.motion",
    "assur.program": "assur.core.program",
    "assur.quantities": "assur.core.quantities",
    "assur.stability": "assur.machines.stability",
    "assur.statics": "assur.core.statics",
    "assur.steering": "assur.machines.steering",
    "assur.tolerance": "assur.synthesis.tolerance",
    "assur.topology": "assur.core.topology",
}

#: packages that moved with their submodules, old name → new name
MOVED_PACKAGES = {
    "assur.app": "assur.views.page",
    "assur.design": "assur.synthesis.search",
    "assur.drive": "assur.dynamics.drive",
    "assur.report": "assur.views.report",
    "assur.sensitivity": "assur.synthesis.sensitivity",
}


def new_name(old: str) -> str | None:
    """The new name of the old module ``old``, or None if it did not move.

    Examples
    --------
    >>> from assur._moved import new_name
    >>> new_name("assur.fused"), new_name("assur.design.criteria")
    ('assur.core.outputs', 'assur.synthesis.search.criteria')
    """
    if old in MOVED:
        return MOVED[old]
    for o, n in MOVED_PACKAGES.items():
        if old == o or old.startswith(o + "."):
            return n + old[len(o):]
    return None


#: names that moved to another module, old dotted name → new dotted name
MOVED_NAMES = {
    "assur.design.load_problem": "assur.io.problems.load_problem",
    "assur.loads.Cylinder": "assur.core.cylinders.Cylinder",
}


_MISSING = object()


class _OldModule(types.ModuleType):
    """An old module name: its attributes are the new module's (or, for a name that
    moved elsewhere, :data:`MOVED_NAMES`')."""

    def __getattr__(self, name):
        new = importlib.import_module(self.__dict__["_new_name"])
        found = getattr(new, name, _MISSING)
        if found is not _MISSING:
            return found
        moved = MOVED_NAMES.get(f"{self.__name__}.{name}")
        if moved is None:
            raise AttributeError(f"module {self.__name__!r} has no attribute {name!r}")
        module, attr = moved.rsplit(".", 1)
        return getattr(importlib.import_module(module), attr)

    def __dir__(self):
        return dir(importlib.import_module(self.__dict__["_new_name"]))


class _Aliases:  # a meta path finder and loader by protocol (importlib.abc costs
    # importlib.resources at start-up: 30 ms of every `import assur`)
    """Finds an old module name and makes it a view of its new module."""

    def find_spec(self, name, path=None, target=None):
        new = new_name(name)
        if new is None:
            return None
        is_pkg = hasattr(importlib.import_module(new), "__path__")
        return importlib.util.spec_from_loader(name, self, is_package=is_pkg)

    def create_module(self, spec):
        new = new_name(spec.name)
        warnings.warn(f"{spec.name} moved to {new}; the old name goes in the next release",
                      DeprecationWarning, stacklevel=2)  # the importer: importlib is skipped
        module = _OldModule(spec.name, f"Moved to :mod:`{new}`.")
        module._new_name = new
        return module

    def exec_module(self, module):
        """Nothing to run: the attributes are the new module's."""


def install() -> None:
    """Put the finder of old names first on :data:`sys.meta_path` (once).

    Examples
    --------
    >>> import sys
    >>> from assur._moved import install
    >>> install()
    >>> sum(type(f).__name__ == "_Aliases" for f in sys.meta_path)
    1
    """
    if not any(isinstance(f, _Aliases) for f in sys.meta_path):
        sys.meta_path.insert(0, _Aliases())
