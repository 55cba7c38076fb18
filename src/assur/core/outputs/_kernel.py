"""The fused kernel's code generation (:mod:`assur.core.outputs`): the outputs'
formulas over symbols (:class:`_Fused`), the numbers of the loads and cylinders as
rows of the parameter table, the kernel's source and its compiled function (cached per
structure, loads and outputs), the joints of the reverse pass.
"""

from __future__ import annotations

import dataclasses

from ...groups import group_type
from ...groups.base import is_number
from ...kernel.cache import helpers_tag, load_source
from ...kernel.emit import Emitter
from ...kernel.fold import fold
from ...kernel.select import branchless
from ...kernel.source import BUF_ROW, CHUNK, chunk_loop, copy_out, hoisted, status_out
from ...kernel.stream import STREAM_MIN
from ...kernel.vector import ELEMENTS_START, vector_lines
from ...kernel.sym import Sym, Tracer, code
from ..gravity import GRAVITY
from ..loads import dead_load_links
from ._context import OutputContext

FORMAT = "8"


class _Fused(OutputContext):
    """Load and reaction context whose values are symbols of the generated code."""

    def __init__(self, mech, prog, tracer, rod_ends, literal_rows):
        super().__init__(mech, rod_ends)
        self.prog, self.t = prog, tracer
        self.literal_rows = literal_rows
        self.g = self.value(_G)

    # values ------------------------------------------------------------------------
    def point(self, p):
        s = self.prog.slot[p]
        return self.t.sym(f"x{s}"), self.t.sym(f"y{s}")

    def jet(self, p, a):
        s = self.prog.slot[p]
        return self.t.sym(f"x{s}_{a}"), self.t.sym(f"y{s}_{a}")

    def value(self, ref):
        """A coordinate, a parameter, or a number: the numbers of loads and cylinders are
        rows of the parameter table too (:func:`_literals`), so one kernel serves any
        of their values."""
        if isinstance(ref, str):
            if ref in self.mech.coordinates:
                return self.t.sym(f"q[{self.mech.coordinates.index(ref)}, e]")
            if ref == _G:
                return self.t.sym(f"params[{self.literal_rows[_G]}, d]")
            return self.t.sym(f"params[{self.prog.param_row(ref)}, d]")
        v = float(ref)
        if v in self.literal_rows:  # a number of the loads (first: rows fixed by them)
            return self.t.sym(f"params[{self.literal_rows[v]}, d]")
        if v in self.prog.literals:
            return self.t.sym(f"params[{self.prog.param_row(v)}, d]")
        return v   # a number of an output's text (a reserve's load): part of its key

    def inv(self, x):
        if isinstance(x, Sym):
            return self.t.new(f"1.0 / {x.name} if {x.name} != 0.0 else 0.0")
        return 1.0 / x if x != 0 else 0.0

    def nonzero(self, L, what):
        """Coincident spring ends give a non-finite element, caught after the kernel."""

    def has_point(self, p):
        return p in self.prog.slot

    def select(self, x, a, b):
        if not isinstance(x, Sym):
            return a if x >= 0 else b
        return self.t.new(f"{code(a)} if {x.name} >= 0.0 else {code(b)}")

    def stroke_load(self, cyl):
        """W of an ``auto`` cylinder: a row of the parameter table, one value per design,
        that :func:`assur.core.outputs.evaluate` fills from a first pass."""
        return self.t.sym(f"params[{self.literal_rows[stroke_key(cyl.name)]}, d]")


_G = "__gravity__"


def _valued(mech):
    """The loads and cylinders of a mechanism: the descriptions whose numbers are rows
    of the fused kernel's parameter table."""
    return tuple(mech.loads) + tuple(mech.cylinders)


def stroke_key(name):
    """The key of the parameter-table row of ``auto`` cylinder ``name``'s W."""
    return ("stroke", name)


def stroke_cylinders(mech):
    """The cylinders whose capacity needs W, one value per design: ``side = "auto"``,
    driving a coordinate, on no supply line."""
    return tuple(c for c in mech.cylinders
                 if c.side == "auto" and c.coordinate is not None and c.supply is None)


def _literals(mech, g, n0):
    """Rows (from ``n0``) of gravity, of every number the loads and cylinders give and
    of the W of each ``auto`` cylinder (:func:`stroke_key`; 1.0 until a first pass
    fills it), and their values: ``({value, _G or key: row}, [values])`` in a fixed
    order."""
    rows, values = {_G: n0}, [float(g)]
    for ld in _valued(mech):
        for f in dataclasses.fields(ld):
            v = getattr(ld, f.name)
            if is_number(v) and float(v) not in rows:
                rows[float(v)] = n0 + len(values)
                values.append(float(v))
    for c in stroke_cylinders(mech):
        rows[stroke_key(c.name)] = n0 + len(values)
        values.append(1.0)
    return rows, values


def _load_signature(mech):
    """The loads and cylinders with each number replaced by the index of its value among
    their distinct numbers (the kernel's structure: which rows it reads, not their
    values)."""
    seen: dict = {}
    out = []
    for ld in _valued(mech):
        sig = [type(ld).__name__]
        for f in dataclasses.fields(ld):
            v = getattr(ld, f.name)
            sig.append(("#", seen.setdefault(float(v), len(seen))) if is_number(v) else v)
        out.append(tuple(sig))
    return tuple(out)


def joint_list(mech):
    """The joints of a mechanism's reverse-order pass, ``((i, j, point), …)`` (force of
    link i on link j at the point), traced once and kept with the mechanism."""
    return mech.memo(("outputs", "joints"), lambda: tuple(
        (i, j, pt) for (i, j), (pt, *_r) in _trace_reactions(mech).joints.items()))


def has_actuator(mech, c):
    """True if the reverse pass gives an actuator force for coordinate ``c``."""
    return c in mech.memo(("outputs", "actuators"), lambda: frozenset(_trace_reactions(mech).act))


def _traced_context(mech, prog, tracer, g):
    """The outputs' context over the symbols of ``tracer``: the numbers of the loads
    and cylinders as rows after the program's (:func:`_literals`), the groups' rod
    ends."""
    n0 = len(prog.param_names) + len(prog.literals) + prog.n_derived
    literal_rows, _ = _literals(mech, g, n0)
    topo = mech.topology

    def is_coord(ref):
        return isinstance(ref, str) and ref in mech.coordinates

    rod_ends = {e for g_ in mech.groups for e in g_.rod_ends(topo.group_links[g_.name],
                                                               is_coord)}
    return _Fused(mech, prog, tracer, rod_ends, literal_rows)


def _reverse(ctx):
    """Trace the reverse-order pass: each group's reactions, last to first."""
    topo = ctx.mech.topology
    for g_ in reversed(ctx.mech.groups):
        ctx.links = topo.group_links[g_.name]
        g_.reactions(ctx)


def _trace_reactions(mech):
    """The reaction context after tracing the loads and the reverse pass (into a
    throw-away emitter: only its joints and actuators are read)."""
    prog = mech.program()
    ctx = _traced_context(mech, prog, Tracer(Emitter(prog.k, order=1)), GRAVITY)
    ctx.apply_loads()
    _reverse(ctx)
    return ctx


_KERNELS: dict = {}


def _element_code(mech, prog, specs, g):
    """The element code of the fused kernel (:func:`_element_lines`), with the lines
    that depend on the design only hoisted: ``(body lines, hoisted lines)``."""
    return hoisted(_element_lines(mech, prog, specs, g))


def _element_lines(mech, prog, specs, g):
    """The element code of the fused kernel: the groups' position and jet code, then
    the loads and the reverse pass when the outputs need them, then ``o0, o1, …`` (the
    outputs); folded."""
    E = Emitter(prog.k, order=1)  # the outputs need first-order analogs at most
    for i, row in enumerate(prog.rows):
        group_type(row[0]).emit(E, i, tuple(row[1:]))
    ctx = _traced_context(mech, prog, Tracer(E), g)
    fns = {fn for fn, _ in specs}
    if fns & {"F", "Fdead", "Fr", "Rx", "Ry", "R", "Rm", "p", "G", "reserve"}:
        ctx.apply_loads()
    if fns & {"Fr", "Rx", "Ry", "R", "Rm"}:
        _reverse(ctx)
    for k_, (fn, args) in enumerate(specs):
        E(f"o{k_} = {code(ctx.output(fn, args))}")
    return fold(E.lines)


def _stores(nout, reduce):
    """The lines after each element (``post``: its status and outputs staged in the
    chunk buffers, branch-free) and after each chunk (``after``: the status, and the
    outputs copied out row by row or, reduced, one scalar pass over the buffer for the
    minimum, maximum and where they are)."""
    ind = " " * 16
    # the status is staged in a local buffer like the outputs (see assur.kernel.source)
    post = [ind + "j = e - e0", ind + "sbuf[j] = st", ind + "ok_ = st < 0"]
    after = [status_out(" " * 12).rstrip("\n")]
    post += [branchless(ind + f"buf[{k_}, j] = o{k_} if ok_ else 0.0") for k_ in range(nout)]
    if not reduce:
        return post, after + [copy_out(str(nout), indent=" " * 12).rstrip("\n")]
    post.append(branchless(ind + f"buf[{nout}, j] = 1.0 if ok_ else 0.0"))
    after += [f"            for r in range({nout}):",
              "                mn = math.inf",
              "                mx = -math.inf",
              "                amn = -1.0",
              "                amx = -1.0",
              "                for jj in range(e1 - e0):",
              f"                    if buf[{nout}, jj] > 0.0:",
              "                        v = buf[r, jj]",
              "                        if v < mn:",
              "                            mn = v",
              "                            amn = float(e0 + jj - d * npd)",
              "                        if v > mx:",
              "                            mx = v",
              "                            amx = float(e0 + jj - d * npd)",
              "                red[4 * r, c] = mn",
              "                red[4 * r + 1, c] = mx",
              "                red[4 * r + 2, c] = amn",
              "                red[4 * r + 3, c] = amx"]
    return post, after


def _source(mech, prog, specs, reduce, g):
    """Source of the fused kernel (see the module docstring of
    :mod:`assur.core.outputs`)."""
    body_lines, pre = _element_code(mech, prog, specs, g)
    body = "\n".join(body_lines)
    nout = len(specs)
    post, after = _stores(nout, reduce)
    src = f'''"""Generated by assur.core.outputs (format {FORMAT}, helpers {helpers_tag()}); do not edit."""
import math
import numpy as np
from numba import njit
from assur.kernel.select import sel as _sel
from assur.kernel.stream import store_fence as _fence, stream_copy as _stream


@njit(cache=True, error_model="numpy", nogil=True)
def kernel(params, trig, q, npd, out, red, status, c_start, c_end):
    """Fused kernel: chunks c_start…c_end−1 (runs of ≤ {CHUNK} positions of one
    design); out: ({nout}, E) outputs or red: (4·{nout}, chunks) min, max, argmin,
    argmax per chunk."""
    buf = np.empty(({nout + 1}, {BUF_ROW}))  # constant shape (see assur.kernel.source)
    sbuf = np.empty({CHUNK}, dtype=np.int64)
    stream = out.shape[0] * out.shape[1] >= {STREAM_MIN}  # streaming stores
{chunk_loop(pre)}{body}
''' + "\n".join(post) + "\n" + "\n".join(after) + "\n    if stream:\n        _fence()\n"
    return src


def _vector_source(mech, prog, specs, reduce, g):
    """Source of the fused kernel evaluated by numpy (:mod:`assur.kernel.vector`): the
    same element code over all elements at once, the compiled kernel's signature and
    results (the reductions per work item by :func:`assur.kernel.vector.reduce_chunks`)."""
    head, body = vector_lines(_element_lines(mech, prog, specs, g))
    outs = ", ".join(f"o{k_}" for k_ in range(len(specs)))
    ind = " " * 8
    return f'''"""Generated by assur.core.outputs (numpy, format {FORMAT}); do not edit."""
import numpy as np
from assur.kernel.vector import _sel, math, max, min, reduce_chunks

VECTOR = True


def kernel(params, trig, q, npd, out, red, status, c_start, c_end):
    """All elements at once, as numpy arrays (c_start, c_end: the whole range; the
    compiled fused kernel's signature). out: ({len(specs)}, E) outputs or red:
    (4·{len(specs)}, work items) min, max, argmin, argmax per work item."""
    E = q.shape[1]
{ELEMENTS_START}''' + "\n".join(head + body) + f"""
{ind}ok_ = np.broadcast_to(st < 0, (E,))
{ind}status[:] = st
{ind}outs = ({outs},)
{ind}if red.shape[0]:
{ind}    reduce_chunks(outs, ok_, npd, E, red)
{ind}else:
{ind}    for k_, o in enumerate(outs):
{ind}        out[k_] = _sel(ok_, o, 0.0)
"""


def kernel_key(mech, prog, specs, reduce) -> tuple:
    """What the fused outputs kernel of a structure, its loads and outputs is made of
    (its cache key; the values of the loads are rows of the parameter table)."""
    return (prog.rows, tuple(prog.slot.items()), _load_signature(mech), mech.links,
            mech.distances, dead_load_links(mech), specs, bool(reduce), prog.param_names,
            prog.literals)


def _kernel(mech, prog, specs, reduce, g, vector=False):
    """The fused kernel of a structure, its loads and outputs (cached): compiled, or
    with ``vector`` evaluated by numpy."""
    key = kernel_key(mech, prog, specs, reduce) + (bool(vector),)
    try:
        hit = _KERNELS.get(key)
    except TypeError:  # an unhashable value in a load: trace every time
        key, hit = None, None
    if hit is None:
        make = _vector_source if vector else _source
        hit = load_source(make(mech, prog, specs, reduce, g))
        if key is not None:
            _KERNELS[key] = hit
    return hit
