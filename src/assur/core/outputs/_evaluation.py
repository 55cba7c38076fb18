"""Evaluating the fused kernel (:mod:`assur.core.outputs`): :func:`evaluate` and its
result :class:`Fused`, the planned kernel run over designs and positions (threads
over chunks), the reductions over positions, the static reactions of a solved range
(:func:`statics_outputs`).
"""

from __future__ import annotations

import time

import numpy as np

from ...errors import ModelError
from ...kernel import run as KR
from ...kernel import vector as KV
from ...kernel.source import CHUNK
from .. import diagnostics
from .. import cylinders as C
from ._kernel import _kernel, _literals, joint_list, stroke_cylinders, stroke_key
from ._notation import REDUCTIONS, output_unit, resolve_output

class Fused:
    """Outputs of :func:`evaluate`: arrays shaped like the coordinates (or, reduced,
    one value per design), with their units.

    Attributes
    ----------
    outputs : tuple of str
        The outputs as asked for.
    ok : ndarray of bool
        Where the mechanism assembled, shape (m, n) — or per design when reduced
        (all positions assembled).
    failures : int ndarray
        Number of failed positions per design.

    Examples
    --------
    >>> from assur import examples
    >>> f = examples.hitch_003().evaluate([0.42, 0.67], outputs=["p(ГЦ)", "Y(56)"])
    >>> [round(float(v) / 1e6, 2) for v in f["p(ГЦ)"]], f.units["p(ГЦ)"]   # table 4.1 [MPa]
    ([15.35, 16.06], 'Pa')
    >>> f.ok.tolist(), f.failures.tolist()
    ([True, True], [0])
    """

    def __init__(self, outputs, units, values, reduced, ok, failures, shape):
        self.outputs = tuple(outputs)
        self.units = dict(units)
        self._values = values
        self._reduced = reduced
        self.ok = ok
        self.failures = failures
        self.shape = shape

    def __getitem__(self, name):
        if self._reduced is not None:
            raise KeyError(f"the outputs were reduced over the positions: use .min({name!r}), "
                           f".max(…), .argmin(…) or .argmax(…)")
        return self._values[self._key(name)]

    def _key(self, name):
        key = name if name in self.outputs else None
        if key is None:
            norm = {o.replace(" ", ""): o for o in self.outputs}
            key = norm.get(str(name).replace(" ", ""))
        if key is None:
            raise KeyError(f"{name!r} is not an output; outputs: {list(self.outputs)}")
        return key

    def _red(self, name, op):
        if self._reduced is None:
            raise KeyError("evaluate(..., reduce=True) computes reductions over positions")
        return self._reduced[op][self._key(name)]

    def min(self, name):
        """Smallest value over the positions of each design that assembled, shape (m,).

        Examples
        --------
        >>> from assur import examples
        >>> S = [0.42, 0.5, 0.6, 0.67]                   # cylinder lengths [m]
        >>> r = examples.hitch_003().evaluate(S, outputs=["reserve(ГЦ, S6, P6)"],
        ...                                    reduce=True)
        >>> [round(float(v), 1) for v in r.min("reserve(ГЦ, S6, P6)")]   # ΔGS65 [%]
        [8.9]
        """
        return self._red(name, "min")

    def max(self, name):
        """Largest value over the positions of each design, shape (m,).

        Examples
        --------
        >>> from assur import examples
        >>> S = [0.42, 0.5, 0.6, 0.67]                   # cylinder lengths [m]
        >>> r = examples.hitch_003().evaluate(S, outputs=["reserve(ГЦ, S6, P6)"],
        ...                                    reduce=True)
        >>> [round(float(v), 1) for v in r.max("reserve(ГЦ, S6, P6)")]   # [%]
        [21.4]
        """
        return self._red(name, "max")

    def argmin(self, name):
        """Position index of the smallest value per design (−1: none assembled).

        Examples
        --------
        >>> from assur import examples
        >>> S = [0.42, 0.5, 0.6, 0.67]                   # cylinder lengths [m]
        >>> r = examples.hitch_003().evaluate(S, outputs=["reserve(ГЦ, S6, P6)"],
        ...                                    reduce=True)
        >>> r.argmin("reserve(ГЦ, S6, P6)").tolist()      # at S = 0.67 m, table 4.1
        [3]
        """
        return self._red(name, "argmin")

    def argmax(self, name):
        """Position index of the largest value per design (−1: none assembled).

        Examples
        --------
        >>> from assur import examples
        >>> S = [0.42, 0.5, 0.6, 0.67]                   # cylinder lengths [m]
        >>> r = examples.hitch_003().evaluate(S, outputs=["reserve(ГЦ, S6, P6)"],
        ...                                    reduce=True)
        >>> r.argmax("reserve(ГЦ, S6, P6)").tolist()      # at S = 0.5 m
        [1]
        """
        return self._red(name, "argmax")

    def __repr__(self):
        return f"Fused({list(self.outputs)}, shape={self.shape}, reduced={self._reduced is not None})"


class _Kernels:
    """The fused kernel of a plan, compiled or evaluated by numpy, made when first
    asked for (:func:`assur.kernel.vector.wanted` chooses per call)."""

    def __init__(self, mech, prog, specs, reduce, g):
        self._args = (mech, prog, specs, reduce, g)
        self._made: dict = {}
        self._key = None

    @property
    def ready_key(self) -> str:
        """The compiled kernel's key among the ready marks (:func:`assur.kernel.vector.ready_key`)."""
        if self._key is None:
            from ._kernel import kernel_key
            self._key = KV.ready_key("outputs", repr(kernel_key(*self._args[:4])))
        return self._key

    def get(self, vector):
        k = self._made.get(vector)
        if k is None:
            k = self._made[vector] = _kernel(*self._args, vector=vector)
        return k


def _plan(mech, specs, reduce, g):
    """The kernels, the full parameter table (with the cylinders' constants and the
    loads' numbers), the trig table and the pre-pass failures of a mechanism's own
    values."""
    prog = mech.program()
    ptab, trig, pose_failures = mech.prepared(prog)
    kern = _Kernels(mech, prog, specs, reduce, g)
    extra = [np.array([v]) for v in _literals(mech, g, ptab.shape[0])[1]]
    if extra:
        md = max([ptab.shape[1]] + [v.shape[0] for v in extra])
        ptab = np.concatenate([np.broadcast_to(ptab, (ptab.shape[0], md))]
                              + [np.broadcast_to(v, (md,))[None] for v in extra])
        trig = np.broadcast_to(trig, (trig.shape[0], md))
    ptab = np.ascontiguousarray(ptab, dtype=float)
    trig = np.ascontiguousarray(trig)
    return kern, ptab, trig, pose_failures


def evaluate(mech, q, params=None, outputs=(), *, reduce=False, on_failure="raise", g=None):
    """Selected outputs of the fused kinematics + statics kernel.

    Parameters
    ----------
    mech : Mechanism
    q : array_like
        Coordinates as for :meth:`Mechanism.solve` [m or rad].
    params : mapping, optional
        Parameter overrides (arrays over designs make a batch).
    outputs : sequence of str
        What to compute (see the module docstring), e.g. ``["G(ГЦ, 56)", "Rx(0, 5)"]``.
    reduce : bool
        Reduce each output over the positions of each design (min, max, argmin,
        argmax) in the kernel instead of storing it.
    on_failure : {"raise", "report"}
        As for :meth:`Mechanism.solve`; with ``"report"`` failed elements are left
        out of the outputs (0) and of the reductions, and counted in ``failures``.
    g : float, optional
        Gravity [m/s²] for masses (default: the model's).

    Returns
    -------
    Fused

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import evaluate
    >>> m = examples.hitch_003()
    >>> f = evaluate(m, [0.42, 0.67], outputs=["G(ГЦ, S6)", "reserve(ГЦ, S6, P6)"])
    >>> [round(float(v)) for v in f["G(ГЦ, S6)"]]              # GS6 [N], table 4.1
    [31354, 29959]
    >>> [round(float(v), 1) for v in f["reserve(ГЦ, S6, P6)"]]  # ΔGS65 [%], table 4.1
    [14.0, 8.9]
    >>> [round(float(v)) for v in evaluate(m, [0.42], outputs=["GS6max"])["GS6max"]]
    [50645]
    """
    from .. import inputs

    if on_failure not in ("raise", "report"):
        raise ValueError("on_failure must be one of: ['raise', 'report']")
    if not outputs:
        raise ModelError("evaluate: name at least one output, e.g. outputs=['Y(56)']")
    specs = tuple(resolve_output(mech, o) for o in outputs)
    inputs.check_params(mech, params)
    m_ = mech.with_params(**params) if params else mech
    g = m_.g if g is None else float(g)
    plan = m_.memo(("outputs", "plan", specs, bool(reduce), g), lambda: _plan(m_, specs, reduce, g))
    per_pos = 8.0 * (m_.program().k + 2 + (0 if reduce else len(specs)))
    qarr, shape, m, n = m_.coordinate_array(q, plan[1].shape[1], per_pos)
    plan = _with_strokes(m_, specs, plan, qarr, m, n, g)
    out, red, status, ptab = _run(m_, plan, qarr, m, n, len(specs), reduce)
    E = qarr.shape[1]
    failed = status >= 0
    if failed.any() and on_failure == "raise":
        raise diagnostics.assembly_error(m_, m_.program(), ptab, qarr, status, np.zeros(E), n,
                                         ~failed.reshape(m, n))
    nfail = failed.reshape(m, n).sum(axis=1)
    units = {o: output_unit(mech, s_) for o, s_ in zip(outputs, specs)}
    if reduce:
        res = _reductions(red, outputs, m, n)
        _check_finite(res["min"], "minimum", nfail < n)
        _check_finite(res["max"], "maximum", nfail < n)
        return Fused(outputs, units, None, res, nfail == 0, nfail, (m,))
    vals = {}
    for k_, (o, (fn, _)) in enumerate(zip(outputs, specs)):
        v = out[k_]
        if fn == "phi" and n > 1:
            v = np.unwrap(v.reshape(m, n), axis=1)
        vals[o] = v.reshape(shape)
    if not np.isfinite(out).all():  # one pass; name the output only when one is not
        _check_finite(vals, "value")
    return Fused(outputs, units, vals, None, ~failed.reshape(shape), nfail, shape)


def _with_strokes(mech, specs, plan, qarr, m, n, g):
    """The plan with the W of each ``side = "auto"`` cylinder whose capacity or reserve
    is asked for written into its parameter-table row, one value per design: a first
    kernel pass gives the actuator forces of all the loads and of the dead loads at
    every position, summed over each design's positions by
    :func:`assur.core.cylinders.stroke_work` (failed positions count 0). The plan
    itself when no such output is asked for."""
    autos = [c for c in stroke_cylinders(mech)
             if any(fn in ("G", "reserve") and args[0] == c.name for fn, args in specs)]
    if not autos:
        return plan
    pre = tuple(s_ for c in autos for s_ in (("F", (c.coordinate,)), ("Fdead", (c.coordinate,))))
    pplan = mech.memo(("outputs", "plan", pre, False, g), lambda: _plan(mech, pre, False, g))
    out = _run(mech, pplan, qarr, m, n, len(pre))[0].reshape(len(pre), m, n)
    kernels, ptab, trig, pose_failures = plan
    if ptab.shape[1] == 1 and m > 1:
        ptab, trig = np.repeat(ptab, m, axis=1), np.repeat(trig, m, axis=1)
    else:
        ptab = ptab.copy()
    rows, values = _literals(mech, g, 0)
    offset = ptab.shape[0] - len(values)
    for i, c in enumerate(autos):
        F, Fd = out[2 * i], out[2 * i + 1]
        ptab[offset + rows[stroke_key(c.name)]] = C.stroke_work(F - Fd, F, axis=1)[:, 0]
    return kernels, np.ascontiguousarray(ptab), np.ascontiguousarray(trig), pose_failures


def _reductions(red, outputs, m, n):
    """The kernel's per-chunk reductions ``red`` (4·outputs, chunks) reduced over the
    chunks of each design: ``{"min" | "max" | "argmin" | "argmax": {output: (m,)}}``."""
    r = red.reshape(len(outputs), 4, m, (n + CHUNK - 1) // CHUNK)
    res = {op: {} for op in REDUCTIONS}
    rows = np.arange(m)
    for k_, o in enumerate(outputs):
        mn, mx = r[k_, 0], r[k_, 1]
        imn, imx = np.argmin(mn, axis=1), np.argmax(mx, axis=1)
        res["min"][o] = mn[rows, imn]
        res["max"][o] = mx[rows, imx]
        res["argmin"][o] = r[k_, 2][rows, imn].astype(np.int64)
        res["argmax"][o] = r[k_, 3][rows, imx].astype(np.int64)
    return res


def _run(mech, plan, qarr, m, n, nspecs, reduce=False):
    """Run a planned fused kernel (:func:`_plan`) over checked coordinates ``qarr``
    (k, m·n): returns ``(out, red, status, ptab)`` — outputs (nspecs, m·n), 0 at failed
    elements (status ≥ 0), or the per-chunk reductions. Raises the failure of a
    pre-pass pose when every element assembled."""
    kernels, ptab, trig, pose_failures = plan
    if ptab.shape[1] == 1 and m > 1:
        ptab, trig = np.repeat(ptab, m, axis=1), np.repeat(trig, m, axis=1)
    elif ptab.shape[1] != m:
        raise ModelError(f"mechanism {mech.name!r}: parameters describe {ptab.shape[1]} "
                         f"designs but the coordinates {m}")
    E = qarr.shape[1]
    nchunks = m * ((n + CHUNK - 1) // CHUNK)
    out = np.empty((0 if reduce else nspecs, E))
    red = np.empty((4 * nspecs if reduce else 0, nchunks))
    status = np.empty(E, dtype=np.int64)
    rkey = kernels.ready_key
    # numpy while the compiled kernel is not ready (never compiled on the calling
    # thread for a few positions), and for a process's first small calls
    vector = KV.wanted(E, ready=lambda: KV.is_ready(rkey))
    kern = kernels.get(vector)
    t0 = time.perf_counter()
    _call(kern, ptab, trig, qarr, n, out, red, status, nchunks, 1 if vector else
          KR.threads_for(E, nchunks))
    def compile_():  # run by the background compilation, on copies of this call's arrays
        p_, t_, q_, o_, r_, s_ = (a.copy() for a in (ptab, trig, qarr, out, red, status))
        _call(kernels.get(False), p_, t_, q_, n, o_, r_, s_, nchunks, 1)
        KV.mark_ready(rkey)
    KV.settle(rkey, vector, time.perf_counter() - t0, compile_)
    if pose_failures and not (status >= 0).any():
        raise pose_failures[0]
    return out, red, status, ptab


def _call(kern, ptab, trig, qarr, n, out, red, status, nchunks, nthreads):
    """A fused outputs kernel over every work item, split over ``nthreads`` threads."""
    if nthreads <= 1:
        kern(ptab, trig, qarr, n, out, red, status, 0, nchunks)
        return
    per = (nchunks + nthreads - 1) // nthreads
    futs = [KR.pool().submit(kern, ptab, trig, qarr, n, out, red, status, i * per,
                             min(nchunks, (i + 1) * per)) for i in range(nthreads)]
    for f in futs:
        f.result()


def statics_outputs(kin, g):
    """The static joint reactions and actuator forces of every position of ``kin``
    from the fused kernel: ``(joints, specs, out)`` with ``joints`` the mechanism's
    ``(i, j, point)`` (:func:`joint_list`), ``specs`` the outputs — Rx, Ry, Rm of each
    joint, then F, Fr of each coordinate — and ``out`` their values, shape
    (len(specs), m, n) [N, N·m], 0 where the mechanism did not assemble. The
    coordinates are those ``kin`` was solved at (checked then); the plan — kernel,
    parameter table, output list — is made once per mechanism (what does not depend
    on the positions)."""
    mech = kin.mechanism

    def make():
        joints_ = joint_list(mech)
        specs = [(f, (i, j)) for i, j, _ in joints_ for f in ("Rx", "Ry", "Rm")]
        specs += [(f, (c,)) for c in mech.coordinates for f in ("F", "Fr")]
        specs = tuple(specs)
        return joints_, specs, _plan(mech, specs, False, g)

    joints_, specs, plan = mech.memo(("outputs", "statics", g), make)
    m, n = kin.m, kin.n
    qarr = kin.q_table()
    out = _run(mech, plan, qarr, m, n, len(specs))[0]
    if not np.isfinite(out).all():  # one pass; name the output only when one is not
        _check_finite({f"{f}{tuple(a)}": v for (f, a), v in zip(specs, out)}, "value")
    return joints_, specs, out.reshape(len(specs), m, n)


def _check_finite(values, what, where=None):
    """Never return NaN or inf: name the output that is not finite (``where``: the
    designs that count, e.g. those with an assembled position)."""
    for name, v in values.items():
        v = np.asarray(v)
        bad = ~np.isfinite(v)
        if where is not None:
            bad &= np.asarray(where)
        if bad.any():
            idx = tuple(int(i) for i in np.argwhere(bad)[0])
            raise ModelError(f"output {name}: {what} at {idx} is not finite ({v[idx]!r}): "
                             f"a singular position (e.g. a transmission number of 0)")
