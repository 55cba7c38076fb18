"""Constraints and objectives of a design search: one registry, one contract.

A criterion turns the reductions over the positions of every design of a batch
(minimum and maximum of fused-kernel outputs, :mod:`assur.core.outputs`) into one number
per design. A **constraint** holds when that number is at least (``at_least``) or at
most (``at_most``) its limit; an **objective** is that number maximised or
minimised. Every criterion declares the outputs it reads (:attr:`Criterion.outputs`)
so that a batch asks the kernel for all of them in one call, and the distances it
needs added to the mechanism (:attr:`Criterion.distances`, for transmission angles).

Kinds (the ``type`` of a ``[[design.constraints]]`` entry; docs/design.md):

=====================  ===========================================================
``bound``              ``of`` (``min``, ``max`` or ``span`` = max − min over the
                       range) of any output, e.g. ``Y(56)`` [its unit]
``capacity``           minimum lift capacity ``G(cylinder, point)`` over the range [N]
``pressure``           maximum pressure ``p(cylinder)`` over the range, at most the
                       relief setting by default [Pa]
``transmission_angle`` the smallest angle between two links at their common joint
                       over the range (both links rigid) [rad]
``box``                the point stays in ``x = [low, high]``, ``y = [low, high]`` over
                       the range: the smallest distance inside the box [m]
=====================  ===========================================================

Every criterion that reads a capacity (``G(c, p)`` or ``reserve(c, p, P)``) also
requires the point to rise with the coordinate over the whole range, ``I(p) > 0``:
a capacity through a transmission number of 0 or below means the cylinder cannot
lift there (:func:`assur.machines.capacity.check_lifts` says the same for one design).

Gradients
---------
A criterion whose value is the minimum or maximum over the positions of fused
outputs (``bound`` with ``of = "min"``, ``"max"`` or ``"span"``, ``capacity``,
``pressure``, ``box``, ``transmission_angle``) has an exact gradient with respect to
the design variables (:attr:`Criterion.gradient`): the derivative, by the
forward-mode dual numbers of :mod:`assur.synthesis.sensitivity`, of the output **at the
position where the minimum or maximum is taken** (the active position). A min/max
over positions is not differentiable where two positions tie; there the derivative at
the arg-min/arg-max is one element of the Clarke subdifferential (Danskin's theorem:
the gradient of the active piece), the usual subgradient of a max–min objective, and
it is the gradient wherever the active position is unique. A ``transmission_angle``
is a function of the smallest or largest distance between the links' far ends (fused
outputs too): its gradient is the chain rule through the law of cosines at that
position, defined while the links are not in line. A kind without an exact gradient declares
``gradient = None`` (the default of the contract): it is not replaced by finite
differences, and a polish skips it with a note.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from ...core.outputs import parse_output
from ...errors import ModelError
from ...groups.base import signed_name
from ._kinds import CRITERIA, _cylinder
from ._reductions import REDUCTIONS, Reductions, jet_reductions
# the kinds' contract, importable from here as before the split
from ._kinds import _Kind

__all__ = ["Criterion", "Limit", "CRITERIA", "REDUCTIONS", "criterion", "Reductions",
           "lift_outputs", "jet_reductions"]


@dataclass(frozen=True)
class Limit:
    """The bound of a constraint: a number [SI], a parameter name (its value per
    design), or ``"original"`` (the value of the file's own design).

    Examples
    --------
    The bundled seed-003 design problem keeps the hitch point 56 as low as the seed's
    design goes ("original"), and the pressure within the relief setting (None: the
    kind's default limit):

    >>> from assur import io
    >>> from assur.synthesis.search import Limit
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))
    >>> [(c.name, c.limit.value, c.limit.sense) for c in pb.constraints]  # doctest: +NORMALIZE_WHITESPACE
    [('min Y(56)', 'original', 'at_most'), ('max Y(56)', 'original', 'at_least'),
     ('max p(ГЦ)', None, 'at_most')]
    >>> Limit(0.2, "below")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: a limit is at_least or at_most, got 'below'
    """

    value: object
    sense: str  # "at_least" | "at_most"

    def __post_init__(self):
        if self.sense not in ("at_least", "at_most"):
            raise ModelError(f"a limit is at_least or at_most, got {self.sense!r}")


@dataclass(frozen=True)
class Criterion:
    """One constraint or objective (see the module docstring for the kinds).

    Attributes
    ----------
    kind : str
        A key of :data:`CRITERIA`.
    name : str
        How results and messages name it (e.g. ``"min reserve(ГЦ, S6, P6)"``).
    outputs : tuple of str
        Fused-kernel outputs it reads (reduced over the positions).
    distances : tuple of (name, a, b)
        Distances the mechanism must have for its outputs (added by the problem).
    args : dict
        Kind-specific settings (quantity, reduction, points, links).
    limit : Limit or None
        For a constraint; None for an objective.
    sense : str or None
        ``"maximize"`` or ``"minimize"`` for an objective.
    unit : assur.core.quantities.Unit or None
        The unit to show its values in (the one the file wrote the limit in).
    gradient : callable or None
        ``gradient(sens, red)`` → d(value)/d(variables), shape (number of variables,)
        [value unit / variable unit, SI], from the exact sensitivities ``sens``
        (:class:`assur.synthesis.sensitivity.Sensitivities` of :attr:`outputs` at one design over
        the positions, parameters = the design variables) and their reductions ``red``
        (:func:`jet_reductions`); None for a kind without an exact gradient (see the
        module docstring). A property: the kind's own ``gradient`` bound to this
        criterion.

    Examples
    --------
    The seed-003 hitch's highest position of the hitch point 56 as a constraint,
    and its lift capacity there as an objective:

    >>> from assur import examples
    >>> from assur.synthesis.search import Limit, criterion
    >>> hitch = examples.hitch_003()
    >>> top = criterion("bound", {"quantity": "Y(56)", "of": "max"}, hitch,
    ...                 limit=Limit(1.0, "at_least"))  # [m]
    >>> top.name, top.outputs, top.unit.text
    ('max Y(56)', ('Y(56)',), 'm')
    >>> g = criterion("capacity", {"point": "56"}, hitch, sense="maximize")
    >>> g.name, g.show(29825.4)  # [N]
    ('min G(ГЦ, 56)', '29825.4 N')
    """

    kind: str
    name: str
    outputs: tuple
    args: dict
    distances: tuple = ()
    limit: Limit | None = None
    sense: str | None = None
    unit: object = None

    @property
    def gradient(self):
        """``gradient(sens, red)`` → d(value)/d(variables), or None (see the class
        attributes).

        Examples
        --------
        d(max Y56)/d(variables) of the bundled seed-003 design problem at the seed's
        design; the frame pivot's height Y01 (second variable) lifts the top position
        2.62 times as much, as a central difference of two evaluated designs says:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> sens, red = pb.jet(pb.x0)  # exact sensitivities at the seed's design
        >>> top = pb.constraints[1]
        >>> top.name, round(float(top.gradient(sens, red)[1]), 3)  # [m/m]
        ('max Y(56)', 2.621)
        >>> step = np.array([0, 1e-6, 0, 0, 0, 0, 0, 0])  # Y01 ± 1 µm [m]
        >>> b = pb.evaluate([pb.x0 + step, pb.x0 - step])
        >>> round(float(b.values[0, 1] - b.values[1, 1]) / 2e-6, 3)  # [m/m]
        2.621
        """
        g = CRITERIA[self.kind].gradient
        return None if g is None else partial(g, self)

    def bound_gradient(self, names) -> np.ndarray:
        """d(limit)/d(variables) of a constraint, shape (len(names),) [SI]: ±1 for the
        variable a limit names (``"p_relief"``, ``"-a"``), 0 for a number,
        ``"original"`` or a parameter that is not a variable.

        Examples
        --------
        The seed-003 hitch's pressure held within its relief setting ``Pgc_max``: a
        variable only when that parameter is one.

        >>> from assur import examples
        >>> from assur.synthesis.search import Limit, criterion
        >>> c = criterion("pressure", {"cylinder": "ГЦ"}, examples.hitch_003(),
        ...               limit=Limit(None, "at_most"))
        >>> c.args["relief"], c.bound_gradient(["X01", "Pgc_max"]).tolist()
        ('Pgc_max', [0.0, 1.0])
        >>> c.bound_gradient(["X01", "Y01"]).tolist()
        [0.0, 0.0]
        """
        v = self.limit.value
        if v is None:
            v = CRITERIA[self.kind].limit_ref(self)
        g = np.zeros(len(names))
        if isinstance(v, str) and v != "original":
            base = signed_name(v)
            name, sign = (base, -1.0) if base is not None else (v.strip(), 1.0)
            if name in names:
                g[list(names).index(name)] = sign
        return g

    def margin_gradient(self, sens, red, names) -> np.ndarray:
        """d(:meth:`margin`)/d(variables) of a constraint at one design, shape
        (len(names),) [SI]: the gradient of the value less (``at_least``) or minus
        (``at_most``) that of the limit (:meth:`bound_gradient`).

        Examples
        --------
        In the bundled seed-003 design problem, ``max Y(56) ≥ original`` has the
        gradient of its value as margin gradient, ``min Y(56) ≤ original`` minus it:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> sens, red = pb.jet(pb.x0)  # exact sensitivities at the seed's design
        >>> low, top = pb.constraints[:2]
        >>> np.round(top.margin_gradient(sens, red, pb.names)[:2], 3).tolist()  # X01, Y01 [m/m]
        [-0.022, 2.621]
        >>> np.round(low.margin_gradient(sens, red, pb.names)[:2], 3).tolist()  # [m/m]
        [0.131, -4.457]
        """
        if self.gradient is None:
            raise ModelError(f"constraint {self.name}: a {self.kind} criterion has no exact "
                             f"gradient")
        g = self.gradient(sens, red) - self.bound_gradient(names)
        return g if self.limit.sense == "at_least" else -g

    def value(self, red: Reductions) -> np.ndarray:
        """The criterion's value per design, shape (m,) [SI].

        Examples
        --------
        ``max Y(56)`` of two designs of the seed-003 hitch:

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
        >>> c.value(red).tolist()  # [m]
        [1.04, 0.98]
        """
        return CRITERIA[self.kind].value(self, red)

    def where(self, red: Reductions) -> np.ndarray:
        """Position index where the value is taken, per design (−1: not one position).

        Examples
        --------
        ``max Y(56)`` of two designs of the seed-003 hitch, both at the last of 50
        positions:

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
        >>> c.where(red).tolist()
        [49, 49]
        """
        return CRITERIA[self.kind].where(self, red)

    def bound(self, red: Reductions, original=None) -> np.ndarray:
        """The limit per design [SI] (``original``: this criterion's value for the
        file's own design, used by ``"original"``).

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
        >>> float(c.bound(red))  # the number of the limit [m]
        1.0
        >>> low = criterion("bound", {"quantity": "Y(56)", "of": "min"}, hitch,
        ...                 limit=Limit("original", "at_most"))
        >>> float(low.bound(red, original=0.2))  # the seed's own Y56(Smin) [m]
        0.2
        >>> low.bound(red)
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: constraint min Y(56): 'original' needs the value of the file's own design
        """
        v = self.limit.value
        if isinstance(v, str) and v == "original":
            if original is None:
                raise ModelError(f"constraint {self.name}: 'original' needs the value of the "
                                 f"file's own design")
            return np.asarray(original, float)
        if v is None:
            return CRITERIA[self.kind].default_limit(self, red)
        return np.asarray(red.param(v), float)

    def margin(self, red: Reductions, original=None) -> np.ndarray:
        """Value − limit (``at_least``) or limit − value (``at_most``), shape (m,):
        the constraint holds where ≥ 0 [SI].

        Examples
        --------
        ``max Y(56) ≥ 1 m``: the first design holds by 40 mm, the second misses by 20 mm.

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
        >>> np.round(c.margin(red), 3).tolist()  # [m]
        [0.04, -0.02]
        """
        val, lim = self.value(red), self.bound(red, original)
        return val - lim if self.limit.sense == "at_least" else lim - val

    def scale(self, red: Reductions, original=None) -> np.ndarray:
        """A positive size to normalise violations by: |limit|, or 1 where it is 0.

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
        >>> float(c.scale(red))  # |1 m| [m]
        1.0
        >>> zero = criterion("bound", {"quantity": "Y(56)", "of": "min"}, hitch,
        ...                  limit=Limit(0.0, "at_least"))
        >>> float(zero.scale(red))  # a zero limit scales by 1 [m]
        1.0
        >>> float(criterion("bound", {"quantity": "Y(56)"}, hitch,
        ...                 limit=Limit(-0.5, "at_least")).scale(red))  # [m]
        0.5
        """
        b = np.abs(self.bound(red, original))
        return np.where(b > 0, b, 1.0)

    def show(self, si) -> str:
        """A value in the criterion's unit, e.g. ``"27.5 kN"``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.search import Limit, criterion
        >>> top = criterion("bound", {"quantity": "Y(56)", "of": "max"}, examples.hitch_003(),
        ...                 limit=Limit(1.0, "at_least"))
        >>> top.show(1.0431634014)  # 6 significant digits [m]
        '1.04316 m'
        """
        u = self.unit
        if u is None:
            return f"{float(si):.6g}"
        return f"{float(u.of(si)):.6g} {u.text}"


def criterion(kind, args, mech, *, limit=None, sense=None, unit=None):
    """Make a :class:`Criterion` of ``kind`` (a key of :data:`CRITERIA`).

    Parameters
    ----------
    kind : str
    args : dict
        Its settings in SI (``quantity``/``of`` for a bound, ``cylinder``/``point``
        for a capacity, ``cylinder`` for a pressure, ``links`` for a transmission
        angle, ``point``/``x``/``y`` [m] for a box).
    mech : Mechanism
    limit : Limit, optional
        For a constraint.
    sense : {"maximize", "minimize"}, optional
        For an objective.
    unit : assur.core.quantities.Unit, optional

    Examples
    --------
    The lift range of the seed-003 hitch as a constraint, and its lift capacity at
    the implement's centre of mass S6 as an objective:

    >>> from assur import examples
    >>> from assur.synthesis.search import Limit, criterion
    >>> hitch = examples.hitch_003()
    >>> span = criterion("bound", {"quantity": "Y(56)", "of": "span"}, hitch,
    ...                  limit=Limit(0.8, "at_least"))  # [m]
    >>> span.name, span.kind
    ('span Y(56)', 'bound')
    >>> criterion("capacity", {"point": "S6"}, hitch, sense="maximize").outputs
    ('G(ГЦ, S6)',)
    >>> criterion("volume", {}, hitch, sense="maximize")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: unknown criterion type 'volume': one of ['bound', 'box', 'capacity', 'pressure', 'transmission_angle']
    """
    if kind not in CRITERIA:
        raise ModelError(f"unknown criterion type {kind!r}: one of {sorted(CRITERIA)}")
    if (limit is None) == (sense is None):
        raise ModelError("a criterion is a constraint (a limit) or an objective (a sense)")
    if sense is not None and sense not in ("maximize", "minimize"):
        raise ModelError(f"an objective is maximize or minimize, got {sense!r}")
    args = dict(args)
    if kind == "pressure":
        cyl = next(c for c in mech.cylinders if c.name == _cylinder(args, mech))
        args["relief"] = cyl.p_relief
    name, outs, dists, quantity = CRITERIA[kind].make(args, mech)
    if unit is None:
        from ...core.quantities import DEFAULT_UNITS, Unit
        unit = DEFAULT_UNITS.get(quantity, Unit("-")) if quantity else Unit("-")
    return Criterion(kind, name, tuple(outs), args, tuple(dists), limit, sense, unit)


def lift_outputs(outputs, mech):
    """The transmission-number outputs whose positivity the capacity outputs among
    ``outputs`` need, ``{"I(S6)": "S6"}`` (``"I(S6, S)"`` for k > 1 coordinates).

    Examples
    --------
    A capacity at 56 and a reserve at S6 of the seed-003 hitch need both points to
    rise with S; a height needs nothing:

    >>> from assur import examples
    >>> from assur.synthesis.search.criteria import lift_outputs
    >>> lift_outputs(["G(ГЦ, 56)", "Y(56)", "reserve(ГЦ, S6, P6)"], examples.hitch_003())
    {'I(56)': '56', 'I(S6)': 'S6'}
    """
    out = {}
    cyls = {c.name: c for c in mech.cylinders}
    for o in outputs:
        fn, args = parse_output(o)
        if fn in ("G", "reserve") and args[0] in cyls:
            tail = f", {cyls[args[0]].coordinate}" if len(mech.coordinates) > 1 else ""
            out[f"I({args[1]}{tail})"] = args[1]
    return out
