"""Synthesis: search the design space of a mechanism (issue 12, docs/design.md).

* :mod:`assur.synthesis.search.problem` — design variables, a :class:`Problem` and the
  evaluation of whole batches of designs in the fused kernel (:class:`Batch`:
  values, feasibility, and for every infeasible design its reason; its module
  ``_batch``);
* :mod:`assur.synthesis.search.criteria` — the constraints and objectives (one registry),
  their values and exact gradients (the kinds in ``_kinds``, the reductions over the
  positions in ``_reductions``);
* :mod:`assur.synthesis.search.search` — differential evolution over whole populations
  (scipy, ``vectorized=True``) and NSGA-II (pymoo) for several objectives;
* :mod:`assur.synthesis.search.polish` — the SLSQP polish of differential evolution's optimum
  with the criteria's exact gradients (:mod:`assur.synthesis.sensitivity`), by the one
  local refiner :func:`assur.synthesis.refine.refine`;
* :mod:`assur.synthesis.search.scale` — chunks of designs on Dask (a LocalCluster or an
  existing scheduler), results to Parquet.

A problem is read from a model file's ``[design]`` by :func:`assur.io.load_problem`
(files are the layer above).
"""

from .criteria import CRITERIA, Criterion, Limit, criterion
from .problem import Batch, Problem, Variable

__all__ = ["Problem", "Variable", "Batch", "Criterion", "Limit", "CRITERIA", "criterion"]
