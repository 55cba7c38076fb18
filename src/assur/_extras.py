"""The optional extras of the package and the modules each provides: a feature that
needs one says which to install (:class:`assur.errors.MissingExtraError`) instead of
failing with a bare ``ModuleNotFoundError`` deep inside.

``pip install assur`` installs what checks, analyses, reports, simulations, sweeps
(on a local or remote Dask cluster, to Parquet) and single-objective searches need;
``assur[page]`` adds the interactive page (FastAPI, uvicorn, tomlkit), ``assur[pareto]``
the multi-objective search (pymoo); ``assur[all]`` both.
"""

from __future__ import annotations

import importlib.util

from .errors import MissingExtraError

__all__ = ["EXTRAS", "require"]

#: extra -> the top-level modules it installs (pyproject.toml [project.optional-dependencies])
EXTRAS = {"page": ("fastapi", "uvicorn", "tomlkit"),
          "pareto": ("pymoo",)}


def require(extra: str, what: str) -> None:
    """Raise :class:`~assur.errors.MissingExtraError` naming ``what`` (the feature) and
    the extra to install if a module of ``extra`` is missing (found without importing it).

    Examples
    --------
    >>> from assur._extras import EXTRAS, require
    >>> require("pareto", "the Pareto front")          # installed: nothing happens
    >>> EXTRAS["doc-example"] = ("no_such_module_here",)
    >>> require("doc-example", "an example feature")
    Traceback (most recent call last):
    ...
    assur.errors.MissingExtraError: an example feature needs no_such_module_here (not installed): pip install 'assur[doc-example]'
    >>> del EXTRAS["doc-example"]
    """
    missing = [m for m in EXTRAS[extra] if importlib.util.find_spec(m) is None]
    if missing:
        raise MissingExtraError(extra, missing, what)
