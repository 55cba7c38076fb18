"""The solving entry points of :class:`~assur.core.mechanism.Mechanism`: they compile
the description (:mod:`assur.core.program`, cached with the mechanism through
:meth:`Mechanism.memo`), run it and wrap the result
(:class:`~assur.core.kinematics.Kinematics`), or hand over to the fused outputs
(:mod:`assur.core.outputs`); ``Mechanism.analyze`` hands over to
:mod:`assur.analysis`.

The functions here are the methods themselves (``Mechanism.solve is solve``): the
class lists them in its body.
"""

from __future__ import annotations

from typing import Mapping

import numpy as np

from . import diagnostics, inputs
from ..errors import AssemblyError, ModelError
from ..groups.base import is_number, ref_value
from .kinematics import Kinematics
from .program import compile_program, execute, trig_table


class _Values:
    """Reference values for the plain-numpy evaluation: ``val(ref)``, and the
    positions of the groups before one at other coordinates (``positions_at``)."""

    def __init__(self, mech, q, params):
        self.mech, self.q, self.params = mech, q, params

    def __call__(self, ref):
        if ref is None:
            return None
        if is_number(ref):
            return float(ref)
        if ref in self.q:
            return self.q[ref]
        return ref_value(self.params, ref)

    def positions_at(self, group, qvals):
        i = self.mech.groups.index(group)
        q = dict(zip(self.mech.coordinates, qvals))
        return self.mech.evaluate_positions(q, self.params, upto=i)


def value_of(self, ref, params=None):
    """Value of a reference (number or parameter name) as a float array over designs.

    Examples
    --------
    >>> from assur import examples
    >>> round(float(examples.hitch_003().value_of("L4")), 4)   # solved L4 [m], printed 0.6613
    0.6613
    >>> examples.hitch_003(L4=[0.6, 0.66]).value_of("L4").tolist()   # two designs [m]
    [0.6, 0.66]
    >>> examples.hitch_003().value_of("-X05").tolist()    # a signed name [m]
    -0.135
    """
    p = self.params if params is None else params
    return np.asarray(ref_value(p, ref), dtype=float)


def evaluate_positions(self, q, params=None, upto=None):
    """Point positions by the plain-numpy formulas of the groups (any dtype).

    This is the reference implementation used to check the compiled kernel
    (complex-step differentiation in the tests) and to explain failures. It does
    not check assembly.

    Parameters
    ----------
    q : mapping of coordinate name to array_like
        Generalized coordinate values [m or rad] (may be complex).
    params : mapping, optional
        Parameter values overriding the mechanism's (may be complex).
    upto : int, optional
        Evaluate only the groups before this index.

    Returns
    -------
    dict of str to (x, y) tuples of arrays [m]

    Examples
    --------
    >>> from assur import examples
    >>> pts = examples.hitch_003().evaluate_positions({"S": 0.42})     # S [m]
    >>> [round(float(v), 3) for v in pts["56"]]     # X56, Y56 [m], seed 003 table 2.2
    [1.131, 0.2]
    >>> sorted(examples.hitch_003().evaluate_positions({"S": 0.42}, upto=5))
    ['01', '03', '05', '07', '23']
    """
    p = dict(self.params)
    p.update(params or {})
    val = _Values(self, q, p)
    pts: dict = {}
    for g in self.groups[:upto]:
        g.evaluate(pts, val)
    return pts


def solve(self, q, params: Mapping | None = None, *, outputs=None, on_failure="raise",
          check_continuity=True, out=None):
    """Positions and exact kinematic analogs over the generalized coordinate(s).

    Parameters
    ----------
    q : array_like, shape (n,) or (m, n) for k = 1; shape (..., k) for k > 1
        Values of the generalized coordinate(s) [m or rad]. A 2-D array (k = 1)
        holds one row of positions per design.
    params : mapping, optional
        Parameter overrides; array values of shape (m,) make a batch.
    outputs : iterable of str, optional
        Point, link and distance names to return (default: all). Asking for
        fewer makes large sweeps faster (only those are written to memory).
    on_failure : {"raise", "report"}
        ``"raise"`` (default) raises :class:`AssemblyError` at the first
        position that cannot assemble; ``"report"`` returns the result with
        its ``ok`` mask and ``failures`` (values at failed elements are 0,
        never NaN).
    check_continuity : bool
        For k = 1, check that no dyad opens or passes a dead point *between*
        consecutive positions (cubic Hermite of the squared triangle height).
    out : Kinematics, optional
        An earlier result of this mechanism with the same ``outputs`` and as many
        designs × positions: this solve writes into its memory instead of new
        memory (a sweep of one size repeated many times; fresh memory costs the
        OS's zeroing of every page on first touch). The earlier result then
        holds this solve's values; keep using only the one returned.

    Returns
    -------
    Kinematics

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> r = m.solve(np.linspace(0.42, 0.67, 10))      # S [m]
    >>> np.round(r.phi("6", degrees=True)[[0, -1]], 1)  # seed 003 table 2.1 [°]
    array([ 88.5, 110.3])
    >>> np.round(r.transmission("56")[[0, -1]], 3)     # I56 = dY56/dS, table 3.1
    array([4.459, 2.621])

    A batch of designs, and failures reported instead of raised:

    >>> b = m.solve([0.42, 0.67], params={"L4": [0.60, 0.66, 0.95]}, on_failure="report")
    >>> b.ok
    array([[ True,  True],
           [ True,  True],
           [False,  True]])
    >>> print(b.failures[0].split(":")[0])  # the first failure: group, links, where
    RRR dyad 'III (6,7)' (links 6, 7) cannot assemble at position 0 (S = 0.42) of design 2
    """
    if on_failure not in ("raise", "report"):
        raise ValueError("on_failure must be one of: ['raise', 'report']")
    inputs.check_params(self, params)
    mech = self.with_params(**params) if params else self
    prog = mech.program(outputs)
    ptab, trig, pose_failures = mech.prepared(prog)
    qarr, shape, m, n = mech.coordinate_array(q, ptab.shape[1])
    if ptab.shape[1] == 1 and m > 1:
        ptab, trig = np.repeat(ptab, m, axis=1), np.repeat(trig, m, axis=1)
    elif ptab.shape[1] != m:
        raise ModelError(f"mechanism {self.name!r}: parameters describe {ptab.shape[1]} "
                         f"designs but the coordinates {m}")
    check = bool(check_continuity and len(self.coordinates) == 1 and n > 1)
    buf = None
    if out is not None:
        if not isinstance(out, Kinematics):
            raise ValueError(f"out must be a result of Mechanism.solve (Kinematics), got "
                             f"{type(out).__name__}")
        if out.output_buffer is None:
            raise ValueError("out must be a whole result of Mechanism.solve, not a part "
                             "of one (Kinematics.positions)")
        buf = out.output_buffer
    res = execute(prog, ptab, qarr, n, check, trig=trig, out_buffer=buf)
    status = res["status"]
    ok = (status < 0).reshape(m, n)   # a status ≥ 0 is a failure's code
    all_ok = bool(ok.all())
    if pose_failures and all_ok:
        raise pose_failures[0]
    kin = Kinematics(mech, prog, qarr.reshape((len(self.coordinates), m, n)), res, shape,
                     ok=ok, params=ptab)
    if not all_ok:
        if on_failure == "raise":
            raise diagnostics.assembly_error(mech, prog, ptab, qarr, status, res["amount"],
                                             n, ok)
        kin.failures = diagnostics.describe_failures(mech, prog, ptab, qarr, status,
                                                     res["amount"], n)
    return kin


def evaluate(self, q, params=None, *, outputs, reduce=False, on_failure="raise", g=None):
    """Only the ``outputs`` asked for (e.g. ``["G(ГЦ, 56)", "Rx(0, 5)", "F(S)"]``),
    computed by one fused kinematics + statics kernel per structure; with
    ``reduce=True`` their minimum, maximum and where over the positions of each
    design, without storing the positions. See :mod:`assur.core.outputs` for the
    output functions and their units.

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> f = examples.hitch_003().evaluate(np.linspace(0.42, 0.67, 10),
    ...                                   outputs=["G(ГЦ, 56)", "p(ГЦ)"])
    >>> round(float(f["G(ГЦ, 56)"][0]))      # lift capacity at 56 [N]
    33139
    >>> round(float(f["p(ГЦ)"][-1] / 1e6), 2)  # pressure [MPa]
    16.06
    """
    from .outputs import evaluate   # imported when used: it brings numba
    return evaluate(self, q, params, outputs, reduce=reduce, on_failure=on_failure, g=g)


def program(self, outputs=None):
    """The compiled :class:`~assur.core.program.Program` writing ``outputs`` (cached).

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> prog = m.program(["56", "6"])
    >>> prog.out_pts, prog.out_sca, m.program(["56", "6"]) is prog
    (('56',), ('6',), True)
    >>> len(m.program().out_pts), m.program().k    # all moving points; one coordinate
    (7, 1)
    """
    key = None if outputs is None else tuple(outputs)
    return self.memo(("program", key), lambda: compile_program(self, key))


def prepared(self, prog):
    """The parameter table of this mechanism's values for ``prog``, shape (rows, m),
    its fixed angles' cos/sin table and the failures of its pre-passes (cached: the
    mechanism is immutable): callers must not write to them.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.hitch_003(L4=[0.60, 0.66])            # two designs
    >>> prog = m.program()
    >>> ptab, trig, failures = m.prepared(prog)
    >>> [round(float(v), 2) for v in ptab[prog.param_row("L4")]], failures  # L4 [m]
    ([0.6, 0.66], [])
    >>> m.prepared(prog)[0] is ptab                        # cached
    True
    """
    def make():
        ptab = np.ascontiguousarray(prog.param_table(self.params))
        failures = self.prepare(prog, ptab)
        return prog, ptab, trig_table(prog, ptab), failures

    # the entry holds the program: its id names no other program while it is kept
    _, ptab, trig, failures = self.memo(("prepared", id(prog)), make)
    return ptab, trig, failures


def prepare(self, prog, ptab):
    """Run the groups' pre-passes (derived per-design rows, e.g. a point fixed at
    a pose). Returns the :class:`AssemblyError` of poses that cannot assemble
    (their rows stay 0); the caller raises them unless the main range fails
    earlier, which gives the more useful message.

    Examples
    --------
    Seed 003's centre of mass S6 is given by its offset (X6, Y6) from 56 at the
    pose S = Sp; the pre-pass turns it into a length and an angle on link 6:

    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> prog = m.program()
    >>> ptab = prog.param_table(m.params)
    >>> gi, data = prog.prepares[0]
    >>> m.groups[gi].name, float(ptab[data[1], 0])            # before: 0
    ('centre of mass S6', 0.0)
    >>> m.prepare(prog, ptab)                                  # no failure
    []
    >>> round(float(ptab[data[1], 0]), 3)           # |56–S6| = hypot(X6, Y6) [m]
    0.871
    """
    failures = []
    for gi, data in prog.prepares:
        g = self.groups[gi]

        def positions_at(qpose, points, gi=gi, g=g):
            res = execute(prog, ptab, np.ascontiguousarray(qpose), 1, False,
                          rows=prog.rows[:gi], out_pts=points)
            st = res["status"]
            if (st >= 0).any():
                e = int(np.flatnonzero(st >= 0)[0])
                msg, _, _ = diagnostics.failure_message(self, prog, ptab, qpose, st,
                                                        res["amount"], 1, e)
                at = {c: float(v) for c, v in zip(self.coordinates, qpose[:, e])}
                pose = ", ".join(diagnostics.coordinate_text(self, c, v)
                                 for c, v in at.items())
                failures.append(AssemblyError(
                    f"{g.kind} {g.name!r} is defined at the pose {pose}, where the "
                    f"mechanism cannot assemble: {msg}", group=g.name,
                    links=g.group_links(), coordinate=at, design=e))
            return {p: (res["pv"][j, 0], res["pv"][j, 1])
                    for j, p in enumerate(res["out_pts"])}

        g.prepare(data, ptab, positions_at)
    return failures


def coordinate_array(self, q, m_params, per_position=None):
    """The coordinates ``q`` as a (k, m·n) array, their result shape, m and n;
    checked (:func:`assur.core.inputs.coordinates_array`) before anything is allocated.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> qa, shape, m_, n = m.coordinate_array([0.42, 0.67], 3)   # S [m], 3 designs
    >>> qa.shape, shape, m_, n
    ((1, 6), (3, 2), 3, 2)
    >>> m.coordinate_array([0.42, float("nan")], 1)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': the generalized coordinate value at index (1,) is not finite (nan)
    """
    k = len(self.coordinates)
    if (k == 1 and m_params == 1 and type(q) is np.ndarray and q.ndim == 1
            and q.dtype == np.float64 and 0 < q.size <= 4096 and q.flags.c_contiguous
            and inputs.all_finite(q)):
        return q.reshape(1, q.size), q.shape, 1, q.size   # the common small case
    # real, finite floats of a size that fits in memory, or a ModelError
    a = inputs.coordinates_array(q, self, m_params, per_position)
    if k == 1:
        if a.ndim == 0:
            a = a[None]
        shape = a.shape
        if a.ndim == 1:
            a2 = np.broadcast_to(a, (m_params, a.shape[0])) if m_params > 1 else a[None]
            if m_params > 1:
                shape = a2.shape
        elif a.ndim == 2:
            a2 = a
        else:
            raise ModelError(f"coordinates must have shape (n,) or (m, n), got {a.shape}")
        m, n = a2.shape
        return np.ascontiguousarray(a2.reshape(1, m * n)), shape, m, n
    if a.shape[-1] != k:
        raise ModelError(f"mechanism {self.name!r} has {k} coordinates {self.coordinates}: "
                         f"q must have a trailing axis of length {k}, got shape {a.shape}")
    if a.ndim == 1:
        a = a[None]
    shape = a.shape[:-1]
    if a.ndim == 2:
        a = np.broadcast_to(a, (m_params,) + a.shape) if m_params > 1 else a[None]
        if m_params > 1:
            shape = a.shape[:-1]
    m, n = a.shape[0], a.shape[1]
    qa = np.moveaxis(a, -1, 0).reshape(k, m * n)
    return np.ascontiguousarray(qa), shape, m, n
