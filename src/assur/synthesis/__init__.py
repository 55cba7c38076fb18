"""Synthesis (docs/architecture.md): design conditions — Mathcad's Given/Find —
(:mod:`~assur.synthesis.conditions`), parameters fitted to a printed table
(:mod:`~assur.synthesis.fitting`), exact sensitivities
(:mod:`~assur.synthesis.sensitivity`), tolerance analysis
(:mod:`~assur.synthesis.tolerance`) and the search of the design space
(:mod:`~assur.synthesis.search`).

``assur.synthesis`` was the module of design conditions before 0.2: its names are
found here for one more release, with a :class:`DeprecationWarning`.
"""

from __future__ import annotations


def __getattr__(name):
    import importlib
    import warnings

    conditions = importlib.import_module(".conditions", __name__)
    if name.startswith("__") or not hasattr(conditions, name):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    warnings.warn(f"assur.synthesis.{name} moved to assur.synthesis.conditions.{name}; the "
                  f"old name goes in the next release", DeprecationWarning, stacklevel=2)
    return getattr(conditions, name)
