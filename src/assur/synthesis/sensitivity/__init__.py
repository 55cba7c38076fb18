"""Exact sensitivities: derivatives of any output with respect to any parameter.

:func:`sensitivities` gives ∂(output)/∂(parameter) over the positions for the
outputs of :mod:`assur.core.outputs` (``Y(56)``, ``dY(S6)``, ``phi(6)``, ``F(S)``,
``p(ГЦ)``, ``G(ГЦ, 56)``, ``reserve(ГЦ, S6, P6)``, ``Rx(0, 5)``, ``R(5, 6)``…) and
the numeric parameters of the model (pivot coordinates, link lengths, angles, bores,
loads, efficiencies, the pose of a point fixed at a pose).

How (the choice and why)
------------------------
Forward-mode jets in the parameters carried through the engine's own group code:
every parameter is a dual number (:mod:`assur.synthesis.sensitivity.dual`) whose parts are
themselves duals in the generalized coordinates, and the plain-numpy position
formulas of each group (:meth:`assur.groups.base.Group.evaluate`, the same code the
kernel's analogs are tested against), the loads' ``apply`` and each group's
``reactions`` (the code :mod:`assur.core.outputs` traces into its kernel) run on them.
The result carries, exactly to rounding, the value, the kinematic analogs ∂/∂q, the
sensitivities ∂/∂p and the mixed ∂²/∂q∂p — which is what the derivative of a
cylinder force F = −Σ F_load·∂r/∂q, of a pressure and of a capacity
G = k·p_max·A·η_h·η_m/(∂Y/∂q) needs.

The reference they are checked against is :func:`assur.synthesis.sensitivity.cstep.complex_step`:
the same plain-numpy code, without parameter jets, with one parameter given an
imaginary step (the tests on random mechanisms of every group family; the timing in
``benchmarks/sensitivity.py``).

Why not the alternatives:

* *Symbolic differentiation in the generated kernel* would need a third jet order
  in every group's hand-written ``emit`` (the kernel's analog code is written per
  group, not traced) — a change to every group type and to the kernel's speed
  that the sweeps depend on, for a quantity needed at one design at a time.
* *The implicit-function theorem on the closure equations* needs the partials of
  every group's closure with respect to its inputs and references, which the group
  contract does not expose, and a second application for the analogs.
* Duals through the group code need nothing new from a group: a group type that
  evaluates in plain numpy (the contract; complex step already relies on it) has
  exact sensitivities, and the reactions and loads are the very code of the
  kernel. Arrays stay vectorized over designs and positions; the P parameters are a
  trailing axis. The Monte Carlo of :mod:`assur.synthesis.tolerance` runs through the compiled
  kernel; the jets serve gradients and first-order stack-ups at a design.

The tests hold every derivative against complex step of the same formulas
(random mechanisms of every group type and the seed 003 hitch).

Parameters held fixed: the ``[[solve]]`` roots of a model file (L4, Sp, L7 of
seed 003) are parameters like the others — a derivative with respect to X01 keeps
L4 as built (a manufactured length does not re-solve itself); ask for L4 to see
its own effect.

Examples
--------
>>> from assur import examples
>>> from assur.synthesis.sensitivity import sensitivities
>>> m = examples.hitch_003()
>>> s = sensitivities(m, [0.45, 0.6], params=["X01", "Dgc"], outputs=["Y(56)", "p(ГЦ)"])
>>> s.jacobian.shape
(2, 2, 2)
>>> round(float(s.d("Y(56)", "Dgc")[0]), 12)
0.0
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...errors import ModelError
from ...core import cylinders as C
from ...core.outputs import OutputContext, output_unit, resolve_output
from ...groups.base import is_number, signed_name
from .dual import Dual, base, variables, where

__all__ = ["sensitivities", "Sensitivities", "numeric_parameters", "jet_outputs", "jet_context"]

_SI = {"length": "m", "angle": "rad", "force": "N", "pressure": "Pa", "mass": "kg",
       "moment": "N·m", "stiffness": "N/m", "inertia": "kg·m²", "number": "-",
       "acceleration": "m/s²", "angular_velocity": "rad/s"}


def numeric_parameters(mech) -> tuple:
    """The parameters of ``mech`` the groups, loads, cylinders or machine use, in the
    model's order (those a sensitivity may be taken with respect to).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.sensitivity import numeric_parameters
    >>> p = numeric_parameters(examples.hitch_003())
    >>> len(p), p[:4], p[-3:]
    (29, ('X01', 'Y01', 'X03', 'Y03'), ('L4', 'Sp', 'L7'))
    >>> "Smin" in p                        # used only by [range] and [[solve]]
    False
    """
    from ...core.quantities import parameter_quantities
    used = parameter_quantities(mech)
    return tuple(p for p in mech.params if p in used)


def _param_unit(mech, name) -> str:
    from ...core.quantities import parameter_quantities
    q = parameter_quantities(mech).get(name)
    return _SI.get(q, "-")


def _qderiv(x, a):
    """∂x/∂q_a of a dual in the parameters whose parts are duals in q (0 if constant)."""
    if not isinstance(x, Dual):
        return 0.0

    def inner(v):
        return v.der[..., a] if isinstance(v, Dual) else 0.0

    return Dual(inner(x.val), inner(x.der))


class _JetContext(OutputContext):
    """Load and reaction context over jets (the array twin of :mod:`assur.core.outputs`'s
    symbolic one): the loads' virtual work, the reverse-order pass and the outputs,
    with the formulas of :mod:`assur.core.outputs` (its docstring lists them)."""

    def __init__(self, mech, pts, value, g, rod_ends, params, q3, shape):
        super().__init__(mech, rod_ends)
        self.pts = pts
        self._value = value
        self.g = g
        self.params, self.q3, self.shape = tuple(params), q3, tuple(shape)
        self.size = q3.shape[1:]   # (designs, positions)

    def point(self, p):
        return self.pts[p]

    def jet(self, p, a):
        x, y = self.pts[p]
        return _qderiv(x, a), _qderiv(y, a)

    def value(self, ref):
        return self._value(ref)

    def plain(self, v):
        """``(values, derivatives)`` of a dual of this context (:func:`_plain`)."""
        return _plain(v, self.size, len(self.params))

    def inv(self, x):
        return 1.0 / x

    def nonzero(self, L, what):
        if np.any(base(L) == 0):
            raise ModelError(f"{what}: its direction is undefined at some position")

    def has_point(self, p):
        return p in self.pts

    def select(self, x, a, b):
        return where(base(x) >= 0, a, b)

    def stroke_load(self, cyl):
        j = self.mech.coordinates.index(cyl.coordinate)
        F = np.broadcast_to(base(-self.vw[j]), self.size)
        Fd = np.broadcast_to(base(-self.vw_dead[j]), self.size)
        return C.stroke_work(F - Fd, F, axis=-1)   # a constant: W only picks a chamber


@dataclass(frozen=True)
class Sensitivities:
    """Values and exact sensitivities of outputs over the positions.

    Attributes
    ----------
    outputs : tuple of str
        The outputs, as asked for (:mod:`assur.core.outputs` names).
    params : tuple of str
        The parameters differentiated with respect to.
    value : ndarray, shape (*shape, outputs)
        The outputs [their units, SI].
    jacobian : ndarray, shape (*shape, outputs, params)
        ∂output/∂parameter [output unit / parameter unit, SI].
    q : ndarray
        The positions [m or rad].
    units : mapping of str to str
        The SI unit of each output.
    param_units : mapping of str to str
        The SI unit of each parameter.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.sensitivity import sensitivities
    >>> s = sensitivities(examples.hitch_003(), [0.42, 0.67], params=["X01", "L4"],
    ...                   outputs=["Y(56)", "F(S)"])             # S [m]
    >>> s
    Sensitivities(2 outputs × 2 params, positions (2,))
    >>> s.units["F(S)"], s.param_units["X01"]
    ('N', 'm')
    >>> [round(float(v)) for v in s.value[:, 1]]               # Fgc, table 4.1 [N]
    [129614, 135652]
    """

    outputs: tuple
    params: tuple
    value: np.ndarray
    jacobian: np.ndarray
    q: np.ndarray
    units: dict = field(default_factory=dict)
    param_units: dict = field(default_factory=dict)

    def _o(self, output):
        if output in self.outputs:
            return self.outputs.index(output)
        norm = [o.replace(" ", "") for o in self.outputs]
        key = str(output).replace(" ", "")
        if key not in norm:
            raise KeyError(f"{output!r} is not an output; outputs: {list(self.outputs)}")
        return norm.index(key)

    def d(self, output, param):
        """∂output/∂param over the positions [output unit / parameter unit].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import sensitivities
        >>> s = sensitivities(examples.hitch_003(), [0.42, 0.67], params=["X01", "L4"],
        ...                   outputs=["F(S)"])                      # S [m]
        >>> [round(float(v)) for v in s.d("F(S)", "X01")]            # ∂Fgc/∂X01 [N/m]
        [288195, -149913]
        >>> s.d("F(S)", "Dgc")
        Traceback (most recent call last):
        ...
        KeyError: "'Dgc' is not among the parameters ['X01', 'L4']"
        """
        if param not in self.params:
            raise KeyError(f"{param!r} is not among the parameters {list(self.params)}")
        return self.jacobian[..., self._o(output), self.params.index(param)]

    def gradient(self, output):
        """∂output/∂(every parameter) over the positions, shape (*shape, params)
        [output unit / parameter unit], in the order of :attr:`params`.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import sensitivities
        >>> s = sensitivities(examples.hitch_003(), [0.42, 0.67], params=["X01", "L4"],
        ...                   outputs=["Y(56)", "F(S)"])             # S [m]
        >>> g = s.gradient("F(S)")                                   # shape (positions, params)
        >>> g.shape, [round(float(v)) for v in g[0]]                 # ∂Fgc/∂(X01, L4) at S = 0.42 m [N/m]
        ((2, 2), [288195, -145543])
        """
        return self.jacobian[..., self._o(output), :]

    def values(self, output):
        """The output itself over the positions [its unit].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import sensitivities
        >>> s = sensitivities(examples.hitch_003(), [0.42, 0.67], params=["L4"],
        ...                   outputs=["Y(56)", "F(S)"])             # S [m]
        >>> [round(float(v), 3) for v in s.values("Y(56)")]         # Y56(Smin) = 0.2 m by the Find [m]
        [0.2, 1.043]
        >>> [round(float(v)) for v in s.values("F (S)")]            # spaces are ignored; table 4.1 [N]
        [129614, 135652]
        """
        return self.value[..., self._o(output)]

    def unit(self, output, param) -> str:
        """The unit of ∂output/∂param, e.g. ``"Pa/m"``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import sensitivities
        >>> s = sensitivities(examples.hitch_003(), [0.42], params=["Dgc", "phiBD"],
        ...                   outputs=["p(ГЦ)", "Y(56)"])            # S [m]
        >>> s.unit("p(ГЦ)", "Dgc"), s.unit("Y(56)", "phiBD")
        ('Pa/m', 'm/rad')
        """
        return f"{self.units[self.outputs[self._o(output)]]}/{self.param_units[param]}"

    def __repr__(self):
        return (f"Sensitivities({len(self.outputs)} outputs × {len(self.params)} params, "
                f"positions {self.value.shape[:-1]})")


def jet_outputs(mech, q, params, outputs, g=None, values=None, step=None):
    """The outputs as duals in ``params`` (the engine of :func:`sensitivities`).

    Parameters
    ----------
    mech : Mechanism
    q : array_like
        Positions as for :meth:`Mechanism.solve` [m or rad].
    params : sequence of str
        Parameters to differentiate with respect to.
    outputs : sequence of str
        :mod:`assur.core.outputs` output names.
    g : float, optional
        Gravity [m/s²] (default: the model's).
    values : mapping, optional
        Values of the parameters (overrides, arrays over designs) [SI].
    step : (str, callable), optional
        Replace one parameter's value v by ``fn(v)`` (the complex-step references of
        the tests give it an imaginary step: the outputs are then complex).

    Returns
    -------
    list of Dual
        One per output: ``.val`` the values (any nesting of duals in q consumed:
        plain arrays), ``.der`` the derivatives, trailing axis over ``params``.
    qarr : ndarray, shape (k, m, n)
    shape : tuple

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.sensitivity import jet_outputs
    >>> res, q3, shape, mech = jet_outputs(examples.hitch_003(), [0.42, 0.67], ["L4"], ["Y(56)"])
    >>> value, der = res[0]                 # Y56 [m] and ∂Y56/∂L4 [m/m]
    >>> q3.shape, shape, der.shape          # (k, designs, positions); der: trailing params axis
    ((1, 1, 2), (2,), (1, 2, 1))
    >>> [round(float(v), 3) for v in value[0]], [round(float(v), 4) for v in der[0, :, 0]]
    ([0.2, 1.043], [-2.1958, -1.9565])
    """
    specs = [resolve_output(mech, o) for o in outputs]
    need = any(fn in ("Rx", "Ry", "R", "Rm", "Fr") for fn, _ in specs)
    ctx = jet_context(mech, q, params, g=g, values=values, step=step, reactions=need)
    res = [ctx.plain(ctx.output(fn, args)) for fn, args in specs]
    return res, ctx.q3, ctx.shape, ctx.mech


def jet_context(mech, q, params=(), *, g=None, values=None, step=None, reactions=True):
    """The outputs' context (:class:`assur.core.outputs.OutputContext`) over dual numbers: the
    positions and their analogs at ``q`` as duals in ``params`` (and, nested, in the
    coordinates), the loads applied and, with ``reactions``, the joint reactions of
    the reverse pass — the engine of :func:`jet_outputs`.

    Parameters
    ----------
    mech : Mechanism
    q : array_like
        Positions as for :meth:`Mechanism.solve` [m or rad].
    params : sequence of str, optional
        Parameters to differentiate with respect to (none: derivatives of length 0).
    g, values, step
        As for :func:`jet_outputs`.
    reactions : bool, optional
        Run the groups' reactions in reverse order (needed by ``Rx``, ``Ry``, ``R``,
        ``Rm``, ``Fr``). Default True.

    Returns
    -------
    OutputContext
        Its ``output(fn, args)`` gives a dual; ``plain(v)`` turns one into
        ``(values, derivatives)`` arrays, shape (designs, positions) and
        (designs, positions, len(params)). ``mech`` (with ``values`` applied),
        ``params``, ``q3`` (k, designs, positions) and ``shape`` are attributes.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.sensitivity import jet_context
    >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67], ["L4"])
    >>> y, dy = ctx.plain(ctx.output("Y", ("56",)))   # Y56 [m], ∂Y56/∂L4 [m/m]
    >>> [round(float(v), 3) for v in y[0]], [round(float(v), 4) for v in dy[0, :, 0]]
    ([0.2, 1.043], [-2.1958, -1.9565])
    """
    from ...core import inputs

    params = tuple(params)
    unknown = [p for p in params if p not in mech.params]
    if unknown:
        raise ModelError(f"{mech.name}: {unknown} are not parameters; parameters: "
                         f"{list(mech.params)}")
    if values:
        inputs.check_params(mech, values)
        mech = mech.with_params(**values)
    g = mech.g if g is None else float(g)
    raw = {p: np.asarray(mech.value_of(p), float) for p in mech.params}
    m = max([v.size for v in raw.values()] + [1])

    def per_design(v):
        v = np.asarray(v, float)
        return v.reshape(-1, 1) if v.ndim == 1 and v.size > 1 else (v[0] if v.ndim == 1 else v)

    qarr, shape, m, n = mech.coordinate_array(q, m)
    k = len(mech.coordinates)
    q3 = qarr.reshape(k, m, n)
    eye = np.eye(k)
    qd = {c: Dual(Dual(q3[j], np.broadcast_to(eye[j], (m, n, k))), 0.0)
          for j, c in enumerate(mech.coordinates)}
    pvals = dict(zip(params, variables([per_design(raw[p]) for p in params])))
    allp = {p: pvals.get(p, per_design(raw[p])) for p in mech.params}
    if step is not None:
        allp[step[0]] = step[1](allp[step[0]])

    def value(ref):
        if ref is None:
            return 0.0
        if is_number(ref):
            return float(ref)
        if ref in qd:
            return qd[ref]
        if ref == "__gravity__":
            return g
        s = signed_name(ref)
        if s is not None:
            return -allp[s]
        return allp[ref]

    pts = mech.evaluate_positions(qd, allp)
    topo = mech.topology

    def is_coord(ref):
        return isinstance(ref, str) and ref in mech.coordinates

    rod_ends = {e for g_ in mech.groups for e in g_.rod_ends(topo.group_links[g_.name],
                                                               is_coord)}
    ctx = _JetContext(mech, pts, value, g, rod_ends, params, q3, shape)
    ctx.apply_loads()
    if reactions:
        for g_ in reversed(mech.groups):
            ctx.links = topo.group_links[g_.name]
            g_.reactions(ctx)
    return ctx


def _plain(v, shape, P):
    """(value, derivatives) of an output as arrays of ``shape`` and ``shape + (P,)``
    (the parts in q, if any, are the value's own: their derivatives are dropped)."""
    if not isinstance(v, Dual):
        return np.broadcast_to(np.asarray(base(v)), shape), np.zeros(shape + (P,))
    return (np.broadcast_to(np.asarray(base(v.val)), shape),
            np.broadcast_to(np.asarray(base(v.der)), shape + (P,)))


def sensitivities(source, q=None, params=None, outputs=(), *, values=None, g=None,
                  check=True):
    """Exact derivatives of outputs with respect to parameters over the positions.

    Parameters
    ----------
    source : Mechanism or assur.io.Model
        The mechanism (a loaded model gives its mechanism and, without ``q``, its range).
    q : array_like, optional
        Positions as for :meth:`Mechanism.solve` [m or rad]: shape (n,) or (m, n) for
        one coordinate, (..., k) for k.
    params : sequence of str, optional
        Parameters to differentiate with respect to (default: every numeric
        parameter the model uses, :func:`numeric_parameters`).
    outputs : sequence of str
        Outputs in :mod:`assur.core.outputs` notation, e.g. ``["G(ГЦ, S6)", "p(ГЦ)",
        "Y(56)", "Rx(0, 5)"]``.
    values : mapping, optional
        Parameter values to evaluate at (arrays over designs) [SI].
    g : float, optional
        Gravity [m/s²] (default: the model's).
    check : bool
        Solve the positions with the kernel first, so that a position that cannot
        assemble raises :class:`~assur.errors.AssemblyError` naming the group
        (the jets themselves do not check assembly).

    Returns
    -------
    Sensitivities
        ``jacobian`` of shape (n, outputs, params) for one design, (m, n, outputs,
        params) for a batch.

    Raises
    ------
    ModelError
        Unknown outputs or parameters.
    AssemblyError
        A position does not assemble (``check=True``).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.sensitivity import sensitivities
    >>> s = sensitivities(examples.hitch_003(), [0.42, 0.67], params=["L4", "Dgc"],
    ...                   outputs=["Y(56)", "p(ГЦ)"])            # S [m]
    >>> s.jacobian.shape                                        # (positions, outputs, params)
    (2, 2, 2)
    >>> [round(float(v), 4) for v in s.d("Y(56)", "L4")]        # ∂Y56/∂L4 [m/m]
    [-2.1958, -1.9565]
    >>> p = s.values("p(ГЦ)")                                   # table 4.1 [Pa]
    >>> [round(float(v)) for v in p]
    [15348729, 16063717]
    >>> dp = s.d("p(ГЦ)", "Dgc")                                # ∂p/∂Dgc [Pa/m]
    >>> [round(float(a / b), 9) for a, b in zip(dp, -2 * p / 0.080)]   # = −2p/D, D = 80 mm [-]
    [1.0, 1.0]
    """
    mech = getattr(source, "mechanism", source)
    if q is None:
        if not hasattr(source, "range"):
            raise ModelError("sensitivities: give the positions q (a Mechanism has no range)")
        q = source.range
    if not outputs:
        raise ModelError("sensitivities: name at least one output, e.g. outputs=['Y(56)']")
    params = numeric_parameters(mech) if params is None else tuple(params)
    if check:
        mech.solve(q, values, check_continuity=False)
    res, q3, shape, m2 = jet_outputs(mech, q, params, outputs, g=g, values=values)
    val = np.stack([r[0] for r in res], axis=-1)  # (m, n, O)
    jac = np.stack([r[1] for r in res], axis=-2)  # (m, n, O, P)
    for name, arr in (("value", val), ("derivative", jac)):
        bad = ~np.isfinite(arr)
        if bad.any():
            idx = tuple(int(i) for i in np.argwhere(bad)[0])
            raise ModelError(f"sensitivities: {name} of {outputs[idx[2]]} at position "
                             f"{idx[1]} is not finite (a singular position)")
    out_shape = tuple(shape)
    val = val.reshape(out_shape + (len(outputs),))
    jac = jac.reshape(out_shape + (len(outputs), len(params)))
    qs = q3[0].reshape(out_shape) if len(m2.coordinates) == 1 else \
        np.moveaxis(q3, 0, -1).reshape(out_shape + (len(m2.coordinates),))
    units = {o: output_unit(m2, o) for o in outputs}
    return Sensitivities(tuple(outputs), params, val, jac, qs, units,
                         {p: _param_unit(m2, p) for p in params})
