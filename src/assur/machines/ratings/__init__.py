"""Ratings of machines in the manner of the standards, one home for all of them
(docs/ratings.md): a rating kind per model-file ``[[rating]] type``, its parameters,
its definition in our words with the standard cited, and its result as named arrays
with their quantities (:mod:`assur.machines.ratings.base`, the registry
:mod:`assur.machines.ratings._registry`).

* ``crane_chart`` — a crane's load chart (:mod:`assur.machines.ratings.crane`);
* ``excavator_digging`` — the digging forces of an excavator's or a backhoe's arm,
  ISO 6015 (:mod:`assur.machines.ratings.digging`);
* ``loader_tipping``, ``loader_breakout``, ``loader_lift`` — a loader's static
  tipping load and rated operating capacity, breakout forces and lift capacity,
  ISO 14397-1 and -2 (:mod:`assur.machines.ratings.loader`).

Examples
--------
>>> from assur.machines.ratings import registry
>>> [(name, cls.standard) for name, cls in registry().items()][:1]
[('crane_chart', 'ISO 4301-1, ISO 10245-1')]
"""

from __future__ import annotations

from ._registry import rating_type, register, registry
from .base import (ROLES, Param, Rating, RatingResult, Series, carried_loads, check_names,
                   declared, names_of, need_cylinders, number, param, with_loads_of)
from .stability import machine_of, tipping_load
from . import crane as _crane  # noqa: F401  (registers crane_chart)
from . import digging as _digging  # noqa: F401  (registers excavator_digging)
from . import loader as _loader  # noqa: F401  (registers the loader ratings)

__all__ = ["ROLES", "Param", "param", "Series", "RatingResult", "Rating", "carried_loads",
           "with_loads_of", "declared", "check_names", "need_cylinders", "number", "names_of",
           "register", "registry", "rating_type", "tipping_load", "machine_of"]
