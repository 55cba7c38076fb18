"""The reductions over the positions a criterion reads: the minimum, maximum and
where of each output per design (:mod:`assur.synthesis.search.criteria`)."""

from __future__ import annotations

import numpy as np

__all__ = ["REDUCTIONS", "Reductions", "jet_reductions"]

#: what a criterion may take of an output over the range
REDUCTIONS = ("min", "max", "span")


class Reductions:
    """Minimum, maximum and where over the positions of each design of a batch.

    Parameters
    ----------
    mins, maxs, argmins, argmaxs : dict of str to ndarray, shape (m,)
        Per output (SI units; positions as indices into the range).
    params : callable
        ``params(ref)`` → the value of a parameter name or number per design,
        shape (m,) [SI].

    Examples
    --------
    Two designs of the seed-003 hitch whose point 56 spans 0.20 … 1.04 m and
    0.25 … 0.98 m over 50 positions (lowest at the first, highest at the last):

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.synthesis.search import Limit, criterion
    >>> from assur.synthesis.search.criteria import Reductions
    >>> hitch = examples.hitch_003()
    >>> c = criterion("bound", {"quantity": "Y(56)", "of": "max"}, hitch,
    ...               limit=Limit(1.0, "at_least"))  # max Y56 ≥ 1 m
    >>> red = Reductions({"Y(56)": np.array([0.20, 0.25])}, {"Y(56)": np.array([1.04, 0.98])},
    ...                  {"Y(56)": np.array([0, 0])}, {"Y(56)": np.array([49, 49])},
    ...                  lambda ref: hitch.params[ref] if isinstance(ref, str) else ref)
    >>> red.mins["Y(56)"].tolist(), red.argmaxs["Y(56)"].tolist()  # [m], position indices
    ([0.2, 0.25], [49, 49])
    >>> round(float(red.param("L4")), 4)  # a parameter's value [m]
    0.6613
    """

    def __init__(self, mins, maxs, argmins, argmaxs, params):
        self.mins, self.maxs = mins, maxs
        self.argmins, self.argmaxs = argmins, argmaxs
        self.param = params

    def subset(self, mask) -> "Reductions":
        """The reductions of the designs where ``mask`` is True.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.synthesis.search import Limit, criterion
        >>> from assur.synthesis.search.criteria import Reductions
        >>> hitch = examples.hitch_003()
        >>> c = criterion("bound", {"quantity": "Y(56)", "of": "max"}, hitch,
        ...               limit=Limit(1.0, "at_least"))  # max Y56 ≥ 1 m
        >>> red = Reductions({"Y(56)": np.array([0.20, 0.25])}, {"Y(56)": np.array([1.04, 0.98])},
        ...                  {"Y(56)": np.array([0, 0])}, {"Y(56)": np.array([49, 49])},
        ...                  lambda ref: hitch.params[ref] if isinstance(ref, str) else ref)
        >>> second = red.subset([False, True])
        >>> second.mins["Y(56)"].tolist(), second.maxs["Y(56)"].tolist()  # [m]
        ([0.25], [0.98])
        """
        mask = np.asarray(mask)
        param = self.param

        def value(ref):
            return np.broadcast_to(param(ref), mask.shape)[mask]
        return Reductions(*({o: v[mask] for o, v in d.items()} for d in
                            (self.mins, self.maxs, self.argmins, self.argmaxs)), value)

    def of(self, output, how):
        """``min``, ``max`` or ``span`` of ``output`` per design [its unit].

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.synthesis.search import Limit, criterion
        >>> from assur.synthesis.search.criteria import Reductions
        >>> hitch = examples.hitch_003()
        >>> c = criterion("bound", {"quantity": "Y(56)", "of": "max"}, hitch,
        ...               limit=Limit(1.0, "at_least"))  # max Y56 ≥ 1 m
        >>> red = Reductions({"Y(56)": np.array([0.20, 0.25])}, {"Y(56)": np.array([1.04, 0.98])},
        ...                  {"Y(56)": np.array([0, 0])}, {"Y(56)": np.array([49, 49])},
        ...                  lambda ref: hitch.params[ref] if isinstance(ref, str) else ref)
        >>> np.round(red.of("Y(56)", "span"), 3).tolist()  # lift range [m]
        [0.84, 0.73]
        >>> red.of("Y(56)", "min").tolist()  # [m]
        [0.2, 0.25]
        """
        if how == "min":
            return self.mins[output]
        if how == "max":
            return self.maxs[output]
        return self.maxs[output] - self.mins[output]

    def where(self, output, how):
        """Position index of the ``min`` or ``max`` (``span``: of the max) per design.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.synthesis.search import Limit, criterion
        >>> from assur.synthesis.search.criteria import Reductions
        >>> hitch = examples.hitch_003()
        >>> c = criterion("bound", {"quantity": "Y(56)", "of": "max"}, hitch,
        ...               limit=Limit(1.0, "at_least"))  # max Y56 ≥ 1 m
        >>> red = Reductions({"Y(56)": np.array([0.20, 0.25])}, {"Y(56)": np.array([1.04, 0.98])},
        ...                  {"Y(56)": np.array([0, 0])}, {"Y(56)": np.array([49, 49])},
        ...                  lambda ref: hitch.params[ref] if isinstance(ref, str) else ref)
        >>> red.where("Y(56)", "min").tolist(), red.where("Y(56)", "span").tolist()
        ([0, 0], [49, 49])
        """
        return self.argmins[output] if how == "min" else self.argmaxs[output]


def jet_reductions(sens, params) -> Reductions:
    """:class:`Reductions` of one design from its exact sensitivities.

    Parameters
    ----------
    sens : assur.synthesis.sensitivity.Sensitivities
        Outputs over the positions of one design (``value`` of shape (n, outputs)).
    params : callable
        ``params(ref)`` as for :class:`Reductions`.

    Returns
    -------
    Reductions
        Per output, arrays of shape (1,): the minimum, maximum [its unit] and their
        positions (the first where several tie, as the kernel's reductions).

    Examples
    --------
    The bundled seed-003 design problem at the seed's design: the hitch point 56 is
    lowest (0.2 m, the seed's condition) at the first position, highest at the last.

    >>> from assur import io
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> sens, red = pb.jet(pb.x0)  # exact sensitivities at the seed's design
    >>> from assur.synthesis.search.criteria import jet_reductions
    >>> r = jet_reductions(sens, red.param)
    >>> round(float(r.mins["Y(56)"][0]), 6), int(r.argmins["Y(56)"][0])  # [m], position
    (0.2, 0)
    >>> round(float(r.maxs["Y(56)"][0]), 4), int(r.argmaxs["Y(56)"][0])  # [m], position
    (1.0432, 49)
    """
    v = np.asarray(sens.value)
    mins, maxs, amin, amax = {}, {}, {}, {}
    for j, o in enumerate(sens.outputs):
        col = v[:, j]
        amin[o], amax[o] = np.array([np.argmin(col)]), np.array([np.argmax(col)])
        mins[o], maxs[o] = col[amin[o]], col[amax[o]]
    return Reductions(mins, maxs, amin, amax, params)
