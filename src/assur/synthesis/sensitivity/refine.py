"""Moved: the local refinement with exact gradients is :mod:`assur.synthesis.refine`,
the one local refiner (issue 22). ``local_refine``, ``Refined`` and ``Scaled`` are
found here for one more release, with a :class:`DeprecationWarning` naming their new
module; the old names go in the next release.

Examples
--------
>>> import warnings
>>> with warnings.catch_warnings(record=True) as w:
...     warnings.simplefilter("always")
...     from assur.synthesis.sensitivity.refine import local_refine
>>> local_refine.__module__, w[0].category.__name__
('assur.synthesis.refine', 'DeprecationWarning')
>>> print(w[0].message)
assur.synthesis.sensitivity.refine.local_refine moved to assur.synthesis.refine.local_refine; the old name goes in the next release
"""

from __future__ import annotations

__all__: list = []  # the moved names are not this module's own

#: the names that moved to :mod:`assur.synthesis.refine`
MOVED = ("local_refine", "Refined", "Scaled")


def __getattr__(name):
    import importlib
    import warnings

    if name not in MOVED:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    warnings.warn(f"{__name__}.{name} moved to assur.synthesis.refine.{name}; the old name "
                  f"goes in the next release", DeprecationWarning, stacklevel=2)
    return getattr(importlib.import_module("assur.synthesis.refine"), name)

