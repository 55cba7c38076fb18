"""The compiled form of a mechanism: a typed, immutable :class:`Program`.

:func:`compile_program` asks every group for its program row
(:meth:`assur.groups.base.Group.compile`) through a :class:`CompileContext`
(:mod:`assur.core.compile_context`); the
rows, the measures and the requested outputs are the *structure* from which the
kernel is generated (:mod:`assur.kernel.source`) — parameter values never enter it.
Programs are cached per structure, so solving the same mechanism with other
parameters or coordinates does not rebuild them.

A program evaluates in three steps: :meth:`Program.param_table` (one column per
design), the groups' pre-passes (``prepare``, e.g. a point fixed at a pose), and
:func:`execute` (the kernel, the continuity pass, the angles).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

import numpy as np

from ..errors import ModelError
from ..groups import group_type
from ..groups.base import is_number, ref_value, signed_name
from ..kernel import emit as KE
from ..kernel import run as KR
from ..kernel import vector as KV
from ..kernel.compose import checks_continuity, load_kernel
from .compile_context import CompileContext

__all__ = ["Program", "CompileContext", "compile_program", "execute", "trig_table"]


@dataclass(frozen=True)
class Program:
    """A compiled mechanism (structure only; see the module docstring).

    Attributes
    ----------
    rows : tuple of tuple of int
        ``(op, *row)`` per group in solving order.
    measures : tuple of (str, int, int, int)
        ``(kind, scalar slot, P slot, Q slot)`` of link angles and distances.
    k : int
        Number of generalized coordinates.
    slot, scal : mapping of str to int
        Slots of the points and of the measures.
    kinds : mapping of str to str
        ``"angle"`` or ``"distance"`` for each measure.
    out_pts, out_sca : tuple of str
        Points and measures written by the kernel.
    frame_rows : mapping of str to (int, int)
        Parameter rows of the frame points' x and y.
    param_names : tuple of str
        Names of the first rows of the parameter table.
    literals : tuple of float
        Values of the next rows (numbers written in the groups).
    n_derived : int
        Rows after the literals, filled by pre-passes.
    trig : tuple
        Fixed angles: ``("angle", row)`` or ``("triangle", pb, pl, po, branch)``.
    prepares : tuple of (int, object)
        Group index and data of each pre-pass.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.groups import group_type
    >>> prog = examples.hitch_003().program()
    >>> [group_type(r[0]).type_name for r in prog.rows][4:]  # doctest: +NORMALIZE_WHITESPACE
    ['cylinder_lever', 'rigid_point', 'dyad', 'rigid_point', 'dyad', 'pose_point',
     'rigid_point']
    >>> prog.k, prog.slot["56"], prog.kinds["6"]
    (1, 7, 'angle')
    """

    rows: tuple
    measures: tuple
    k: int
    slot: Mapping[str, int]
    scal: Mapping[str, int]
    kinds: Mapping[str, str]
    out_pts: tuple
    out_sca: tuple
    frame_rows: Mapping[str, tuple]
    param_names: tuple
    literals: tuple
    n_derived: int
    trig: tuple
    prepares: tuple
    _kernels: dict = field(default_factory=dict, compare=False, repr=False)

    @property
    def continuity_rows(self) -> tuple:
        """Indices of the groups checked for continuity between positions (k = 1).

        Examples
        --------
        >>> from assur import examples
        >>> prog = examples.hitch_003().program()
        >>> prog.continuity_rows        # the cylinder–lever group and the two dyads
        (4, 6, 8)
        """
        c = self._kernels.get("continuity")
        if c is None:
            c = self._kernels["continuity"] = tuple(
                i for i, r in enumerate(self.rows) if group_type(r[0]).continuity)
        return c

    def layout(self, out_pts: tuple, out_sca: tuple) -> tuple:
        """What a run writing ``out_pts``/``out_sca`` needs besides its kernel (made
        once per output set): the first and end rows of the six output blocks
        (points' values, first and second analogs, then the scalars'), the rows of
        the angles among the scalars (unwrapped along a range), and the index of each
        point and scalar.

        Examples
        --------
        One point (x, y) and one link angle, k = 1:

        >>> from assur import examples
        >>> prog = examples.hitch_003().program()
        >>> blocks, angles, pidx, sidx = prog.layout(("56",), ("6",))
        >>> blocks
        ((0, 2), (2, 4), (4, 6), (6, 7), (7, 8), (8, 9))
        >>> angles, pidx, sidx
        ((0,), {'56': 0}, {'6': 0})
        """
        key = ("layout", out_pts, out_sca)
        lay = self._kernels.get(key)
        if lay is None:
            k, npo, nso = self.k, len(out_pts), len(out_sca)
            sizes = (npo * 2, npo * 2 * k, npo * 2 * k * k, nso, nso * k, nso * k * k)
            ends = tuple(int(v) for v in np.cumsum(sizes))
            lay = self._kernels[key] = (
                tuple(zip((0,) + ends[:-1], ends)),
                tuple(i for i, s in enumerate(out_sca) if self.kinds[s] == "angle"),
                {p: i for i, p in enumerate(out_pts)}, {s: i for i, s in enumerate(out_sca)})
        return lay

    def param_row(self, ref) -> int:
        """Row of a number (literal) or a parameter name.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> prog = m.program()
        >>> prog.param_row("L3"), prog.param_row(0.61)    # L3; the 610 mm of the test frame
        (8, 32)
        >>> round(float(prog.param_table(m.params)[32, 0]), 3)  # [m]
        0.61
        """
        if is_number(ref):
            return len(self.param_names) + self.literals.index(float(ref))
        return self.param_names.index(ref)

    def param_table(self, params: Mapping) -> np.ndarray:
        """Parameter table, shape (rows, m): parameters, literals, derived rows (0).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> prog = m.program()
        >>> ptab = prog.param_table(m.params)
        >>> ptab.shape, round(float(ptab[prog.param_row("L3"), 0]), 3)   # L3 [m]
        ((36, 1), 0.2)
        >>> prog.param_table({**m.params, "L4": [0.60, 0.66]}).shape      # two designs
        (36, 2)
        >>> prog.param_table({**m.params, "L4": [0.60, 0.66], "L7": [0.7, 0.75, 0.8]})
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: parameter 'L4' has 2 designs, others 3
        """
        rows = [np.atleast_1d(np.asarray(ref_value(params, n), dtype=float))
                for n in self.param_names]
        m = max([r.shape[0] for r in rows] + [1])
        for name, r in zip(self.param_names, rows):
            if r.shape[0] not in (1, m):
                raise ModelError(f"parameter {name!r} has {r.shape[0]} designs, others {m}")
        ptab = np.zeros((len(rows) + len(self.literals) + self.n_derived, m))
        for i, r in enumerate(rows):
            ptab[i] = r
        for j, v in enumerate(self.literals):
            ptab[len(rows) + j] = v
        return ptab

    def kernel(self, out_pts=None, out_sca=None, vector=False):
        """The compiled kernel writing ``out_pts``/``out_sca`` (default: the program's);
        with ``vector``, its numpy evaluation (:mod:`assur.kernel.vector`).

        Examples
        --------
        The hitch's point 56 at S = Smin by the numpy evaluation (no compilation),
        called as :func:`execute` calls it: rows x, y, then ∂x/∂S, ∂y/∂S, …:

        >>> import numpy as np
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> prog = m.program(["56"])
        >>> kern = prog.kernel(vector=True)
        >>> ptab, trig, _ = m.prepared(prog)
        >>> q = np.array([[0.42]])                                  # S [m]
        >>> out, amount, status = np.empty((6, 1)), np.empty(1), np.empty(1, dtype=np.int64)
        >>> _ = kern(ptab, trig, q, 1, False, out, amount, status, 0, 1)
        >>> bool(status[0] < 0)                                     # assembled
        True
        >>> round(float(out[1, 0]), 4)         # Y56(Smin), seed 003 §2.2 condition [m]
        0.2
        >>> round(float(out[3, 0]), 3)         # I56 = dY56/dS, seed 003 table 3.1 [m/m]
        4.459
        """
        default = out_pts is None and out_sca is None
        fn = self._kernels.get(("all outputs", vector)) if default else None
        if fn is not None:
            return fn
        op = tuple(self.out_pts if out_pts is None else out_pts)
        os_ = tuple(self.out_sca if out_sca is None else out_sca)
        key = (op, os_, vector)
        fn = self._kernels.get(key)
        if fn is None:
            fn = _kernel_for(self.rows, self.measures, self.k,
                             tuple(self.slot[p] for p in op), tuple(self.scal[s] for s in os_),
                             vector)
            self._kernels[key] = fn
        if default:
            self._kernels[("all outputs", vector)] = fn
        return fn


_KERNELS: dict = {}


def _kernel_for(rows, measures, k, out_pts, out_sca, vector=False):
    key = (rows, measures, k, out_pts, out_sca, vector)
    fn = _KERNELS.get(key)
    if fn is None:
        load = KV.load_vector if vector else load_kernel
        fn = _KERNELS[key] = load(rows, measures, k, out_pts, out_sca)
    return fn


_PROGRAMS: dict = {}


def _signed_refs(mech) -> tuple:
    """The signed references (``"-a"``) the groups and loads of ``mech`` use: rows of
    the parameter table after the parameters, each −(its parameter)."""
    import dataclasses
    out = []
    for item in tuple(mech.groups) + tuple(mech.loads):
        if not dataclasses.is_dataclass(item):
            continue
        for f in dataclasses.fields(item):
            v = getattr(item, f.name)
            for r in (v if isinstance(v, tuple) else (v,)):  # a pose: one per coordinate
                if signed_name(r) is not None and r not in out:
                    out.append(r)
    return tuple(out)


def compile_program(mech, outputs=None) -> Program:
    """The :class:`Program` of a mechanism and the outputs it asks for (cached per
    structure: the groups, links, distances, coordinates and parameter names).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.program import compile_program
    >>> m = examples.hitch_003()
    >>> prog = compile_program(m, ["56", "6"])
    >>> prog.out_pts, prog.out_sca
    (('56',), ('6',))
    >>> compile_program(m.with_params(L4=0.65), ["56", "6"]) is prog   # same structure
    True
    >>> compile_program(m, ["57"])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: unknown outputs ['57']; points: ['01', '03', ...
    """
    outputs = None if outputs is None else tuple(outputs)
    names = tuple(mech.params) + _signed_refs(mech)
    key = (mech.groups, mech.links, mech.distances, mech.coordinates, names, outputs)
    try:
        prog = _PROGRAMS.get(key)
    except TypeError:  # an unhashable literal somewhere: compile without caching
        key, prog = None, None
    if prog is not None:
        return prog
    c = CompileContext(mech.coordinates, names)
    rows = []
    for i, g in enumerate(mech.groups):
        c.current = i
        for o in g.outputs():
            c.slot(o)
        rows.append((g.op,) + tuple(g.compile(c)))
    rows = tuple(tuple(int(v) for v in c.resolve(r)) for r in rows)
    trig = tuple((t[0],) + tuple(c.resolve(x) for x in t[1:]) for t in c.trig)
    frame_rows = {n: c.resolve(v) for n, v in c.frame_rows.items()}
    prepares = tuple((i, c.resolve(data)) for i, data in c.prepares)
    slot = dict(c.slots)
    scal, kinds, measures = {}, {}, []
    for l in mech.links:
        scal[l.name] = len(scal)
        kinds[l.name] = "angle"
        measures.append(("angle", scal[l.name], slot[l.tail], slot[l.head]))
    for dd_ in mech.distances:
        scal[dd_.name] = len(scal)
        kinds[dd_.name] = "distance"
        measures.append(("distance", scal[dd_.name], slot[dd_.a], slot[dd_.b]))
    if outputs is None:
        out_pts = tuple(p for p in slot if p not in frame_rows)
        out_sca = tuple(scal)
    else:
        bad = [o for o in outputs if o not in slot and o not in scal]
        if bad:
            raise ModelError(f"unknown outputs {bad}; points: {list(slot)}, links and "
                             f"distances: {list(scal)}")
        out_pts = tuple(o for o in outputs if o in slot and o not in frame_rows)
        out_sca = tuple(o for o in outputs if o in scal)
    prog = Program(rows=rows, measures=tuple(measures), k=len(mech.coordinates),
                   slot=MappingProxyType(slot), scal=MappingProxyType(scal),
                   kinds=MappingProxyType(kinds), out_pts=out_pts, out_sca=out_sca,
                   frame_rows=MappingProxyType(frame_rows), param_names=c.param_names,
                   literals=tuple(c.literals), n_derived=c.derived, trig=trig,
                   prepares=prepares)
    if key is not None:
        if len(_PROGRAMS) > 256:
            _PROGRAMS.clear()
        _PROGRAMS[key] = prog
    return prog


def trig_table(prog: Program, ptab: np.ndarray) -> np.ndarray:
    """cos and sin of every fixed angle of the program, per design, shape (2·n, m).

    A triangle-defined angle is ``branch·acos((b² + l² − o²)/(2·b·l))`` (seed 000
    DELFI); its argument is clipped here only so that the table is finite — a
    triangle that cannot close is detected and reported by the kernel.

    Examples
    --------
    The hitch's fixed angles: the arm 34 at φBD = 22° (seed 003 §1.2), the axis 56
    (0°), the centre of mass S6 at φS6 = atan(Y6/X6) − φ6(Sp) (seed 003 §1.4, a
    derived row filled by its pre-pass) and the test frame (−90°):

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.core.program import trig_table
    >>> m = examples.hitch_003()
    >>> prog = m.program()
    >>> ptab, _, _ = m.prepared(prog)                 # parameters, pre-passes run
    >>> tt = trig_table(prog, ptab)                   # rows cos, sin per angle
    >>> tt.shape
    (8, 1)
    >>> angles = np.degrees(np.arctan2(tt[1::2, 0], tt[0::2, 0]))
    >>> [round(float(a), 3) for a in angles]          # [°]
    [22.0, 0.0, -79.683, -90.0]
    """
    m = ptab.shape[1]
    out = np.empty((max(2 * len(prog.trig), 1), m))
    for i, item in enumerate(prog.trig):
        if item[0] == "angle":
            beta = ptab[item[1]]
        else:
            _, pb, pl, po, br = item
            b, ell, o = ptab[pb], ptab[pl], ptab[po]
            den = 2.0 * b * ell
            c = np.divide(b * b + ell * ell - o * o, den, out=np.ones(m), where=den > 0)
            beta = br * np.arccos(np.clip(c, -1.0, 1.0))
        out[2 * i] = np.cos(beta)
        out[2 * i + 1] = np.sin(beta)
    return out


#: subdivisions of an interval the continuity check flags, and how often a flagged
#: sub-interval is subdivided again, before the flag is believed
REFINE_POINTS = 32
REFINE_DEPTH = 3
#: intervals refined per call at most (beyond: the flags stand, as reported)
REFINE_MAX = 256


def _refine_continuity(prog, ptab, qarr, n, status, flagged, rows, depth):
    """Re-check flagged intervals on a finer grid of solved positions.

    The cubic Hermite check is exact for smooth squared heights, but near another
    group's dead point the analogs grow like 1/sin μ and the cubic overshoots although
    the triangle stays open; a flag stands only if the group fails on the finer grid
    too (refined again, up to :data:`REFINE_DEPTH` levels).
    """
    if depth >= REFINE_DEPTH:
        return
    for e in flagged[:REFINE_MAX]:
        d = e // n
        q = np.linspace(qarr[0, e - 1], qarr[0, e], REFINE_POINTS + 1)[None, :]
        sub = execute(prog, np.ascontiguousarray(ptab[:, d:d + 1]), q, q.shape[1], True,
                      rows=rows, out_pts=(), depth=depth + 1)
        if (sub["status"] < 0).all():
            status[e] = -1


def _output_array(out_buffer, nrows, E):
    """The array a run writes its outputs into, shape (nrows, E): a new one, or
    ``out_buffer`` after checking that it fits (float64, C order, writeable)."""
    if out_buffer is None:
        return np.empty((nrows, E))
    if (out_buffer.shape != (nrows, E) or out_buffer.dtype != np.float64
            or not out_buffer.flags.c_contiguous or not out_buffer.flags.writeable):
        raise ValueError(f"out: this solve writes {nrows} output rows × {E} designs·"
                         f"positions into one writeable C-ordered float64 array; the one given "
                         f"is {out_buffer.dtype} of shape {out_buffer.shape}: give a result of "
                         f"the same outputs and size")
    return out_buffer


def _unwrap_angles(sv, ang, n):
    """Make the kernel's angles (principal values, atan2; rows ``ang`` of the scalars
    ``sv``, shape (scalars, E)) continuous along the positions of each design, in
    place (releases the GIL; two threads on large ranges)."""
    rows_a = np.array(ang, dtype=np.int64)
    if sv.shape[1] >= 65536 and len(ang) > 1:
        for f in [KR.pool().submit(KR.unwrap_rows, sv, rows_a[h::2].copy(), n)
                  for h in range(2)]:
            f.result()
    else:
        KR.unwrap_rows(sv, rows_a, n)


_RKEYS: dict = {}


def _ready_key(kargs) -> str:
    """The ready mark's key of the compiled kernel of ``kargs`` (:func:`_kernel_for`'s
    arguments), made once per process."""
    key = _RKEYS.get(kargs)
    if key is None:
        key = _RKEYS[kargs] = KV.ready_key("kinematics", *kargs)
    return key


def _compile_later(kargs, cont, args, rkey):
    """What compiles the kernel of ``kargs`` in the background (:func:`assur.kernel.vector.rent`):
    it is loaded, run on copies of one call's arrays ``args`` (its signature compiled)
    and marked ready."""
    def compile_():
        ptab, trig, qarr, n, check, out, amount, status = (
            a.copy() if isinstance(a, np.ndarray) else a for a in args)
        kern = _kernel_for(*kargs, False)
        gout = amount if checks_continuity(kern) else np.empty(
            (2 * len(cont), qarr.shape[1] if check else 1))
        KR.run(kern, ptab, trig, qarr, n, check, out, gout, status)
        KV.mark_ready(rkey)
    return compile_


def execute(prog: Program, ptab, qarr, n, check=False, rows=None, out_pts=None, out_sca=(),
            depth=0, trig=None, out_buffer=None):
    """Run the kernel; returns the raw output arrays and the status per element.

    ``rows`` (a prefix of the program's groups) and ``out_pts``/``out_sca`` run a
    part of the program (pre-passes at a pose, refinements of the continuity check).
    ``out_buffer``: the array to write the outputs into, shape (rows, k·E) as the
    returned ``out`` (float64, C order), instead of a new one.

    Examples
    --------
    The hitch's point 56 at both ends of the stroke, the way
    :meth:`~assur.Mechanism.solve` runs it:

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.core.program import execute
    >>> m = examples.hitch_003()
    >>> prog = m.program(["56"])
    >>> ptab, trig, _ = m.prepared(prog)
    >>> res = execute(prog, ptab, np.array([[0.42, 0.67]]), 2, True, trig=trig)  # S [m]
    >>> (res["status"] < 0).tolist()                        # both assembled
    [True, True]
    >>> [round(float(v), 4) for v in res["pv"][res["pidx"]["56"], 1]]   # Y56 [m]
    [0.2, 1.0432]
    """
    k, E = qarr.shape
    if rows is None:
        names_p = prog.out_pts if out_pts is None else tuple(out_pts)
        names_s = prog.out_sca if out_pts is None else tuple(out_sca)
        kargs = (prog.rows, prog.measures, prog.k, tuple(prog.slot[p] for p in names_p),
                 tuple(prog.scal[s] for s in names_s))
    else:
        names_p, names_s = tuple(out_pts), tuple(out_sca)
        kargs = (rows, (), k, tuple(prog.slot[p] for p in names_p), ())
    # numpy evaluates the same code while the compiled kernel is not ready (a new
    # structure: never compiled on the calling thread for a few positions) and for the
    # first small calls of a process (no numba start-up): assur.kernel.vector
    rkey = _ready_key(kargs)
    vector = KV.wanted(E, ready=lambda: KV.is_ready(rkey))
    kern = _kernel_for(*kargs, vector)
    npo, nso = len(names_p), len(names_s)
    blocks, ang, pidx, sidx = prog.layout(names_p, names_s)
    out = _output_array(out_buffer, blocks[-1][1], E)
    parts = [out[a:b] for a, b in blocks]
    sv = parts[3].reshape(nso, E)
    status = np.empty(E, dtype=np.int64)
    # the depth of a continuity failure, written by that pass at its failures only
    amount = np.empty(E)
    rows_ = prog.rows if rows is None else rows
    cont = (prog.continuity_rows if rows is None else
            [i for i, r in enumerate(rows_) if group_type(r[0]).continuity]) if k == 1 else []
    # a fused kernel checks continuity itself (depths in ``amount``); a composed one
    # stages the squared heights and slopes in ``gout`` for the separate pass
    fused = checks_continuity(kern)
    gout = amount if fused else np.empty((2 * len(cont), E if check else 1))
    trig = trig_table(prog, ptab) if trig is None else trig
    t0 = time.perf_counter()
    nfail = KR.run(kern, ptab, trig, qarr, n, check, out, gout, status)
    KV.settle(rkey, vector, time.perf_counter() - t0, _compile_later(
        kargs, cont, (ptab, trig, qarr, n, check, out, amount, status), rkey))
    if check and cont:
        if not fused:
            codes = np.array([i * KE.CODES_PER_OP + KE.FAIL_CONTINUITY for i in cont],
                             dtype=np.int64)
            nfail = KR.check_continuity(gout, qarr, n, status, amount, codes)
        if nfail:
            flagged = np.flatnonzero((status % KE.CODES_PER_OP == KE.FAIL_CONTINUITY)
                                     & (status >= 0))
            _refine_continuity(prog, ptab, qarr, n, status, flagged, rows_, depth)
            out[:, (status % KE.CODES_PER_OP == KE.FAIL_CONTINUITY) & (status >= 0)] = 0.0

    if check and n > 1 and ang:
        _unwrap_angles(sv, ang, n)
    return dict(pv=parts[0].reshape(npo, 2, E), pd=parts[1].reshape(npo, 2, k, E),
                pdd=parts[2].reshape(npo, 2, k, k, E), sv=sv, sd=parts[4].reshape(nso, k, E),
                sdd=parts[5].reshape(nso, k, k, E), status=status, amount=amount,
                out_pts=names_p, out_sca=names_s, out=out, pidx=pidx, sidx=sidx)
