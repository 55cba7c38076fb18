"""Source of the compiled position/analog kernel of a program structure.

A compiled mechanism (:class:`assur.core.program.Program`) is a table of integer rows,
one per structural group in solving order (the op code of its type first), plus the
measures (link angles, distances) to output. This module asks each group type to
emit its straight-line code (:meth:`assur.groups.base.Group.emit`, through the
toolkit of :mod:`assur.kernel.emit`) and wraps it in one fused loop over all
elements (design, position): every point's value, first and second derivatives
with respect to the ``k`` generalized coordinates are held in local variables (a
second-order forward jet), so the analogs are exact to rounding. Only the
requested outputs are written to memory.

Every conditional expression of the emitted code becomes a branch-free select
(:mod:`assur.kernel.select`): the element loop is one basic block, which keeps
numba's compile time linear in its length. Large structures get a composed kernel
instead (:mod:`assur.kernel.compose`, chosen by ``assur.core.program``).

The source depends only on the structure (group types, connections, k and the
requested outputs), never on parameter values: it is cached on disk and compiled
once per machine (:mod:`assur.kernel.cache`).
"""

from __future__ import annotations

import math
import re

from .ops import op
from .emit import (CODES_PER_OP, CONTINUITY_TOL, FAIL_COINCIDENT, FAIL_CONTINUITY,
                   Emitter, d, dd, fail, pt)
from .cache import helpers_tag
from .fold import fold
from .select import branchless
from .stream import STREAM_MIN

__all__ = ["generate", "hoisted", "chunk_loop", "continuity_check", "emit_atan2", "emit_measure",
           "quantities", "status_out", "copy_out", "CHUNK", "BUF_PAD", "BUF_ROW", "FORMAT"]

#: elements per work item of the element loop: long enough that each output row's
#: copy is a run of 8 kB (runs of 2 kB halved the copy's bandwidth), short enough
#: that the chunk buffer of a few dozen rows stays in a core's L2 cache
CHUNK = 1024

#: columns a kernel's chunk buffer has beyond the run of positions it holds: the
#: element before the run (the continuity check's left end) and one cache line, so
#: that the rows written at one position fall into different L1 sets (a stride of a
#: power of two put them all into two sets of the L1)
BUF_PAD = 9

#: row length of a kernel's chunk buffer when its runs are whole chunks
BUF_ROW = CHUNK + BUF_PAD

#: bump when the generator changes what it emits
FORMAT = "24"


#: Cephes atan (S. L. Moshier, atan.c): atan(x) = x + x·z·P(z)/Q(z), z = x², for
#: |x| ≤ 0.66; above, atan(x) = π/4 + atan((x − 1)/(x + 1)); MOREBITS is π/2 − fl(π/2)
_ATAN_P = (-8.750608600031904122785e-1, -1.615753718733365076637e1,
           -7.500855792314704667340e1, -1.228866684490136173410e2,
           -6.485021904942025371773e1)
_ATAN_Q = (2.485846490142306297962e1, 1.650270098316988542046e2,
           4.328810604912902668951e2, 4.853903996359136964868e2,
           1.945506571482613964425e2)
_MOREBITS = 6.123233995736765886130e-17
_PI_LO = 1.2246467991473532e-16  # π − fl(π)


def emit_atan2(E, out, y, x, t):
    """``out = atan2(y, x)`` [rad] as branch-free code (selects, no libm call, two
    divisions), so the element loop stays vectorized: within 1 ulp of
    :func:`numpy.arctan2` on 2e6 random pairs over 10 decades (the earlier form with
    three divisions: 2 ulp), signed zeros as numpy; ``t`` prefixes the temporaries.

    Examples
    --------
    >>> import math
    >>> from assur.kernel.emit import Emitter
    >>> from assur.kernel.source import emit_atan2
    >>> E = Emitter(1)
    >>> emit_atan2(E, "phi", "dy", "dx", "t0")
    >>> code = "\\n".join(line.strip() for line in E.lines)
    >>> def atan2(y, x):                     # the emitted code run on numbers
    ...     ns = {"math": math, "dy": y, "dx": x}
    ...     exec(code, ns)
    ...     return ns["phi"]
    >>> [round(atan2(y, x), 6) for y, x in [(1.0, -1.0), (4.0, 3.0), (-0.0, -1.0)]]   # [rad]
    [2.356194, 0.927295, -3.141593]
    >>> max(abs(atan2(y, x) - math.atan2(y, x)) for y, x in [(1.0, -1.0), (4.0, 3.0), (-2.0, 0.5)]) < 1e-15
    True
    """
    p0, p1, p2, p3, p4 = (repr(v) for v in _ATAN_P)
    q0, q1, q2, q3, q4 = (repr(v) for v in _ATAN_Q)
    E(f"{t}ax = abs({x})")
    E(f"{t}ay = abs({y})")
    E(f"{t}mx = max({t}ax, {t}ay)")
    E(f"{t}mn = min({t}ax, {t}ay)")
    # r = mn/mx in [0, 1]; above 0.66 the argument is (r − 1)/(r + 1), written
    # (mn − mx)/(mn + mx): one division instead of two (and mn − mx is exact there)
    E(f"{t}big = {t}mn > 0.66 * {t}mx")
    E(f"{t}un = {t}mn - {t}mx if {t}big else {t}mn")
    E(f"{t}ud = {t}mn + {t}mx if {t}big else {t}mx")
    E(f"{t}u = {t}un / {t}ud if {t}mx > 0.0 else 0.0")
    E(f"{t}z = {t}u * {t}u")
    E(f"{t}pz = (((({p0} * {t}z + {p1}) * {t}z + {p2}) * {t}z + {p3}) * {t}z + {p4})")
    E(f"{t}qz = ((((({t}z + {q0}) * {t}z + {q1}) * {t}z + {q2}) * {t}z + {q3}) * {t}z"
      f" + {q4})")
    E(f"{t}at = {t}u * ({t}z * {t}pz / {t}qz) + {t}u")
    E(f"{t}at = {math.pi / 4!r} + ({t}at + {0.5 * _MOREBITS!r}) if {t}big else {t}at")
    E(f"{t}at = ({math.pi / 2!r} - {t}at) + {_MOREBITS!r} if {t}ay > {t}ax else {t}at")
    E(f"{t}at = ({math.pi!r} - {t}at) + {_PI_LO!r} if math.copysign(1.0, {x}) < 0.0 "
      f"else {t}at")
    E(f"{out} = math.copysign({t}at, {y})")


def emit_measure(E, i, kind, s_, P, Q):
    """Link angle (kind 'angle') or distance (kind 'distance') between two points.

    Examples
    --------
    >>> import math
    >>> from assur.kernel.emit import Emitter
    >>> from assur.kernel.source import emit_measure
    >>> E = Emitter(1)
    >>> emit_measure(E, 11, "angle", 0, 0, 1)   # angle s0 of the direction slot 0 → slot 1
    >>> ns = dict(math=math, st=-1, x0=0.0, y0=0.0, x1=1.0, y1=1.0,        # [m]
    ...           x0_0=0.0, y0_0=0.0, x1_0=0.0, y1_0=1.0,                  # [m/m]
    ...           x0_00=0.0, y0_00=0.0, x1_00=0.0, y1_00=0.0)              # [m/m²]
    >>> exec("\\n".join(line.strip() for line in E.lines), ns)
    >>> round(ns["s0"], 6), ns["s0_0"], ns["s0_00"], ns["st"]   # φ [rad], φ' [rad/m], φ'' [rad/m²]
    (0.785398, 0.5, -0.5, -1)
    >>> ns.update(x1=0.0, y1=0.0)                                # coincident points
    >>> exec("\\n".join(line.strip() for line in E.lines), ns)
    >>> ns["st"]                                                 # 16·11 + FAIL_COINCIDENT
    181
    """
    K = E.K
    px, py = pt(P)
    qx, qy = pt(Q)
    s = f"s{s_}"
    t = f"t{i}"
    E(f"{t}dx = {qx} - {px}")
    E(f"{t}dy = {qy} - {py}")
    E(f"{t}r2 = {t}dx * {t}dx + {t}dy * {t}dy")
    fail(E, i, FAIL_COINCIDENT, f"{t}r2 == 0.0")
    E(f"{t}ir2 = 1.0 / {t}r2 if {t}r2 > 0.0 else 0.0")
    for a in range(K):
        E(f"{t}dx_{a} = {d(qx, a)} - {d(px, a)}")
        E(f"{t}dy_{a} = {d(qy, a)} - {d(py, a)}")
    if kind == "angle":
        emit_atan2(E, s, f"{t}dy", f"{t}dx", t)
        for a in range(K):
            E(f"{t}c_{a} = {t}dx * {t}dy_{a} - {t}dy * {t}dx_{a}")
            E(f"{d(s, a)} = {t}c_{a} * {t}ir2")
        for a, b in E.pairs:
            # phi''_ab = [d'_b x d'_a + d x d''_ab]/r2 - 2 (d x d'_a)(d . d'_b)/r2^2
            E(f"{dd(s, a, b)} = (({t}dx_{b} * {t}dy_{a} - {t}dy_{b} * {t}dx_{a})"
              f" + ({t}dx * ({dd(qy, a, b)} - {dd(py, a, b)}) - {t}dy * "
              f"({dd(qx, a, b)} - {dd(px, a, b)}))) * {t}ir2"
              f" - 2.0 * {t}c_{a} * ({t}dx * {t}dx_{b} + {t}dy * {t}dy_{b}) * {t}ir2 * {t}ir2")
    else:
        E(f"{s} = math.sqrt({t}r2)")
        E(f"{t}il = 1.0 / {s} if {s} > 0.0 else 0.0")
        for a in range(K):
            E(f"{d(s, a)} = ({t}dx * {t}dx_{a} + {t}dy * {t}dy_{a}) * {t}il")
        for a, b in E.pairs:
            E(f"{dd(s, a, b)} = ({t}dx_{a} * {t}dx_{b} + {t}dy_{a} * {t}dy_{b}"
              f" + {t}dx * ({dd(qx, a, b)} - {dd(px, a, b)}) + {t}dy * "
              f"({dd(qy, a, b)} - {dd(py, a, b)}) - {d(s, a)} * {d(s, b)}) * {t}il")


def hoisted(lines):
    """The element loop's body (one level deeper, conditional expressions as branch-free
    selects) with per-design reads ``params[r, d]``, ``trig[r, d]`` replaced by locals
    ``P{r}``, ``T{r}``, and the lines that load those locals once per run of positions of
    a design (so the loop reads only q and can be vectorized).

    Examples
    --------
    >>> from assur.kernel.source import hoisted
    >>> body, hoist = hoisted(["            t6ra = params[28, d]",
    ...                        "            t6cb = trig[4, d] if st < 0 else 0.0"])
    >>> [line.strip() for line in body]
    ['t6ra = P28', 't6cb = _sel(st < 0, T4, 0.0)']
    >>> print(hoist, end="")
                P28 = params[28, d]
                T4 = trig[4, d]
    """
    prows = sorted({int(m) for line in lines for m in re.findall(r"params\[(\d+), d\]", line)})
    trows = sorted({int(m) for line in lines for m in re.findall(r"trig\[(\d+), d\]", line)})
    body = [branchless(re.sub(r"trig\[(\d+), d\]", r"T\1",
                              re.sub(r"params\[(\d+), d\]", r"P\1", "    " + line)))
            for line in lines]
    hoist = "".join(f"            P{r} = params[{r}, d]\n" for r in prows)
    hoist += "".join(f"            T{r} = trig[{r}, d]\n" for r in trows)
    return body, hoist


def status_out(indent: str, offset: str = "") -> str:
    """The copy of a chunk's staged status codes ``sbuf`` to ``status`` (after the
    element loop), indented by ``indent``; ``offset`` (e.g. ``" + e0 - ep"``) is the
    column in ``sbuf`` of element e0.

    Examples
    --------
    >>> from assur.kernel.source import status_out
    >>> print(status_out("        ", " + e0 - ep"), end="")
            for j in range(e1 - e0):
                status[e0 + j] = sbuf[j + e0 - ep]
    """
    return (f"{indent}for j in range(e1 - e0):\n"
            f"{indent}    status[e0 + j] = sbuf[j{offset}]\n")


def copy_out(nrows: str, offset: str = "", indent: str = "        ") -> str:
    """The copy of a work item's ``nrows`` staged output rows ``buf`` to ``out``
    (after the element loop; ``offset`` as in :func:`status_out`): with streaming
    stores when the kernel's ``stream`` is set (:mod:`assur.kernel.stream`), else
    element by element.

    Examples
    --------
    >>> from assur.kernel.source import copy_out
    >>> print(copy_out("NQ"), end="")
            if stream:
                for r in range(NQ):
                    _stream(out, r, e0, buf, r, 0, e1 - e0)
            else:
                for r in range(NQ):
                    for j in range(e1 - e0):
                        out[r, e0 + j] = buf[r, j]
    """
    col = f"0{offset}" if offset else "0"
    col = col.replace("0 + ", "")
    return (f"{indent}if stream:\n"
            f"{indent}    for r in range({nrows}):\n"
            f"{indent}        _stream(out, r, e0, buf, r, {col}, e1 - e0)\n"
            f"{indent}else:\n"
            f"{indent}    for r in range({nrows}):\n"
            f"{indent}        for j in range(e1 - e0):\n"
            f"{indent}            out[r, e0 + j] = buf[r, j{offset}]\n")


def chunk_loop(hoist: str, lead: bool = False) -> str:
    """The loop over work items (runs of ≤ CHUNK positions of one design: per-design
    values are loop-invariant, the element loop a plain counted loop), with the
    ``hoist`` lines before each run, up to the start of an element (``st = -1``).

    The elements e0…e1−1 of a work item are written; the element loop runs from
    ``ep``: e0, or with ``lead`` and ``check`` the element before e0 when it belongs to
    the same design (computed again, not written: the continuity check of the interval
    that ends at e0 needs it).

    Examples
    --------
    >>> from assur.kernel.source import chunk_loop
    >>> print(chunk_loop("            P28 = params[28, d]\\n"), end="")
        cpd = (npd + 1024 - 1) // 1024
        for c in range(c_start, c_end):
            d = c // cpd
            e0 = d * npd + (c % cpd) * 1024
            e1 = min(d * npd + npd, e0 + 1024)
            ep = e0
            if e1 > e0:
                P28 = params[28, d]
                for e in range(ep, e1):
                    st = -1
    >>> [ln.strip() for ln in chunk_loop("", lead=True).splitlines() if ln.strip().startswith("ep =")]
    ['ep = e0 - 1 if check and e0 > d * npd else e0']
    """
    ep = ("e0 - 1 if check and e0 > d * npd else e0") if lead else "e0"
    return (f"    cpd = (npd + {CHUNK} - 1) // {CHUNK}\n"
            "    for c in range(c_start, c_end):\n"
            "        d = c // cpd\n"
            f"        e0 = d * npd + (c % cpd) * {CHUNK}\n"
            f"        e1 = min(d * npd + npd, e0 + {CHUNK})\n"
            f"        ep = {ep}\n"
            "        if e1 > e0:\n"
            f"{hoist}            for e in range(ep, e1):\n"
            "                st = -1\n")


def continuity_check(indent):
    """Lines of the continuity check of one work item, after its element loop.

    For every interval between consecutive elements ``ep + j − 1``, ``ep + j`` (both
    assembled) and every group ``k`` staged in ``buf`` rows ``_CROWS[k]``,
    ``_CROWS[k] + 1`` (squared triangle height g and its slope gd): the cubic Hermite
    interpolant of g over the interval must not dip below ``−CONTINUITY_TOL·max(g)``
    (the group neither flattens nor opens between the samples). A failing interval
    marks its right-hand element with the group's status code ``_CCODES[k]`` and the
    depth [m²] in ``amount``; the first failing group of an interval counts, and an
    element so marked is not the left end of a checked interval (as
    :func:`assur.kernel.run.check_continuity`). Counts the failures in ``nfail``.
    A loop over the groups (their rows and codes are constant arrays of the module):
    the code, and numba's compile time, do not grow with the number of groups.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.kernel.source import continuity_check
    >>> code = ("def check(sbuf, buf, q, ep, e1, amount, _CROWS, _CCODES):\\n    nfail = 0\\n"
    ...         + continuity_check("    ") + "    return nfail\\n")
    >>> ns = {}
    >>> exec(code, ns)
    >>> sbuf = np.array([-1, -1])                          # both positions assembled
    >>> buf = np.array([[0.01, 0.01], [-1.0, 1.0]])        # g [m²] and dg/dq [m²/m] of a dyad
    >>> amount = np.zeros(2)
    >>> ns["check"](sbuf, buf, np.array([[0.0, 0.1]]), 0, 2, amount, np.array([0]), np.array([103]))
    1
    >>> int(sbuf[1]), round(float(amount[1]), 4)           # the dyad's code, the depth [m²]
    (103, -0.015)
    """
    i0 = indent
    lines = [f"{i0}for j in range(1, e1 - ep):",
             f"{i0}    if sbuf[j] >= 0 or sbuf[j - 1] >= 0:",
             f"{i0}        continue",
             f"{i0}    hs = q[0, ep + j] - q[0, ep + j - 1]",
             f"{i0}    h = abs(hs)",
             f"{i0}    for k in range(_CROWS.shape[0]):",
             f"{i0}        r = _CROWS[k]",
             f"{i0}        g0 = buf[r, j - 1]",
             f"{i0}        d0 = buf[r + 1, j - 1]",
             f"{i0}        g1 = buf[r, j]",
             f"{i0}        d1 = buf[r + 1, j]",
             f"{i0}        mn = min(g0, g1)",
             f"{i0}        if mn - (4.0 / 27.0) * h * (abs(d0) + abs(d1)) > 0.0:",
             f"{i0}            continue",
             f"{i0}        for ii in range(1, 16):",
             f"{i0}            t = ii / 16.0",
             f"{i0}            t2 = t * t",
             f"{i0}            t3 = t2 * t",
             f"{i0}            v = ((2.0 * t3 - 3.0 * t2 + 1.0) * g0",
             f"{i0}                 + (t3 - 2.0 * t2 + t) * hs * d0",
             f"{i0}                 + (-2.0 * t3 + 3.0 * t2) * g1 + (t3 - t2) * hs * d1)",
             f"{i0}            if v < mn:",
             f"{i0}                mn = v",
             f"{i0}        if mn < -{CONTINUITY_TOL!r} * max(g0, g1):",
             f"{i0}            sbuf[j] = _CCODES[k]",
             f"{i0}            amount[ep + j] = mn",
             f"{i0}            nfail += 1",
             f"{i0}            break"]
    return "\n".join(lines) + "\n"


def quantities(K, out_pts, out_sca):
    """Names of the output rows, in order: point values, first, second analogs, then
    the measures likewise.

    Examples
    --------
    >>> from assur.kernel.source import quantities
    >>> quantities(1, (7,), (5,))     # point 56 (slot 7) and φ6 (measure 5) of the hitch
    ['x7', 'y7', 'x7_0', 'y7_0', 'x7_00', 'y7_00', 's5', 's5_0', 's5_00']
    """
    qs = [v for s_ in out_pts for v in (f"x{s_}", f"y{s_}")]
    qs += [d(v, a) for s_ in out_pts for v in (f"x{s_}", f"y{s_}") for a in range(K)]
    qs += [dd(v, a, b) for s_ in out_pts for v in (f"x{s_}", f"y{s_}") for a in range(K)
           for b in range(K)]
    qs += [f"s{s_}" for s_ in out_sca]
    qs += [d(f"s{s_}", a) for s_ in out_sca for a in range(K)]
    qs += [dd(f"s{s_}", a, b) for s_ in out_sca for a in range(K) for b in range(K)]
    return qs


def emit_program(rows, measures, K):
    """The element code of a program structure: every group's positions and jets in
    order, then the measures (the arguments of :func:`generate`). Returns the
    :class:`~assur.kernel.emit.Emitter` holding the lines and the indices of the
    groups checked for continuity (k = 1) — shared by the compiled kernel and its
    numpy evaluation (:mod:`assur.kernel.vector`)."""
    E = Emitter(K)
    cont = []
    for i, row in enumerate(rows):
        gt = op(row[0])
        E(f"# group {i}: {gt.type_name}")
        gt.emit(E, i, tuple(int(v) for v in row[1:]))
        if gt.continuity and K == 1:
            cont.append(i)
    n = len(rows)
    for j, (kind, s_, P, Q) in enumerate(measures):
        E(f"# measure {j}: {kind}")
        emit_measure(E, n + j, kind, s_, P, Q)
    E.lines = fold(E.lines)
    return E, cont


def generate(rows, measures, K, out_pts, out_sca):
    """Python source of the kernel of a program structure.

    Parameters
    ----------
    rows : sequence of tuple of int
        One row per group in solving order: ``(op, *group_row)``.
    measures : sequence of (kind, scalar_slot, P, Q)
        Link angles (``"angle"``) and distances (``"distance"``) between points.
    K : int
        Number of generalized coordinates.
    out_pts, out_sca : sequence of int
        Slots of the points and measures to write.

    Continuity (k = 1): every group type with ``continuity`` emits the squared height
    ``g{i}`` of its triangle and its slope ``gd{i}``; the kernel stages them and
    checks, between consecutive positions, that the cubic Hermite interpolant stays
    positive (the group neither flattens nor opens between samples,
    :func:`continuity_check`; the composed kernels of large structures leave that to
    :func:`assur.kernel.run.check_continuity`).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.kernel.source import generate, quantities
    >>> prog = examples.hitch_003().program()
    >>> pts = tuple(prog.slot[p] for p in prog.out_pts)
    >>> sca = tuple(prog.scal[s] for s in prog.out_sca)
    >>> src = generate(prog.rows, prog.measures, prog.k, pts, sca)
    >>> [ln.strip() for ln in src.splitlines() if ln.strip().startswith("# group")][4:7]
    ['# group 4: cylinder_lever', '# group 5: rigid_point', '# group 6: dyad']
    >>> f"NQ = {len(quantities(prog.k, pts, sca))}" in src    # 7 points, 7 angles: 63 rows
    True
    >>> _ = compile(src, "kernel", "exec")                     # valid Python
    """
    E, cont = emit_program(rows, measures, K)
    # per-design values are loaded once per run of positions of a design, before the
    # element loop (so the loop reads only q and can be vectorized)
    body, hoist = hoisted(E.lines)
    qs = quantities(K, out_pts, out_sca)
    nq = len(qs)
    # the squared triangle heights and slopes of the continuity check, staged
    # unconditionally (a conditional store would stop vectorization) and checked
    # after the element loop of each work item, while they are in cache
    for i in cont:
        qs += [f"g{i}", f"gd{i}"]
    check = continuity_check(" " * 16) if cont else ""
    crows = ", ".join(str(nq + 2 * k) for k in range(len(cont)))
    ccodes = ", ".join(str(i * CODES_PER_OP + FAIL_CONTINUITY) for i in cont)
    ind = "                "
    # the status is staged in a local buffer too: the element loop then stores only
    # to kernel-local memory, so LLVM vectorizes it without a run-time overlap check
    # against the caller's arrays (that check failed, and the scalar loop ran 4×
    # slower, whenever ``status`` happened to lie within a few kB of ``q``)
    out = [ind + "j = e - ep", ind + "sbuf[j] = st"]
    # outputs go to a per-chunk buffer (one row per quantity, in L2) and are copied
    # row by row at the end of the chunk: a few long sequential streams instead of
    # one interleaved stream per quantity; failed elements get 0, never NaN
    if qs:
        out.append(ind + "ok_ = st < 0")
        out += [branchless(ind + f"buf[{qi}, j] = {v} if ok_ else 0.0")
                for qi, v in enumerate(qs)]
    return f'''"""Generated by assur.kernel.source (format {FORMAT}, helpers {helpers_tag()}); do not edit."""
import math
import numpy as np
from numba import njit
from assur.kernel.select import sel as _sel
from assur.kernel.stream import store_fence as _fence, stream_copy as _stream

CHECKS_CONTINUITY = True  # see assur.kernel.compose.checks_continuity
# buf rows of the squared heights of the groups checked for continuity, their codes
_CROWS = np.array([{crows}], dtype=np.int64)
_CCODES = np.array([{ccodes}], dtype=np.int64)


@njit(cache=True, error_model="numpy", nogil=True)
def kernel(params, trig, q, npd, check, out, amount, status, c_start, c_end):
    """Chunks c_start…c_end−1 of the elements. out: (NQ, E) outputs, rows in the order
    of assur.kernel.source.quantities. With ``check`` (k = 1) the continuity of every
    dyad between consecutive positions is checked here: failures get the group's
    code in ``status`` and the depth in ``amount`` (E,); returns their number.
    Branch-free element loop (vectorizable); releases the GIL: callers run ranges
    in threads."""
    E = q.shape[1]
    NQ = {nq}
    if out.shape[0] != NQ or out.shape[1] != E or (check and amount.shape[0] != E):
        raise ValueError("assur kernel: output arrays do not match the program")
    # constant shapes: a buffer row stride known at compile time lets LLVM vectorize
    # the element loop's stores (a run-time stride made the loop 4× slower)
    buf = np.empty(({max(len(qs), 1)}, {BUF_ROW}))
    sbuf = np.empty({CHUNK + 1}, dtype=np.int64)
    stream = NQ * E >= {STREAM_MIN}  # outputs far beyond the caches: streaming stores
    nfail = 0
    # work items are runs of ≤ {CHUNK} positions of one design: the per-design values
    # are loop-invariant and the element loop is a plain counted loop (vectorizable)
{chunk_loop(hoist, lead=bool(cont))}''' + "\n".join(body) + "\n" + "\n".join(out) + "\n" + (
        "            if check:\n" + check if check else "") + status_out(" " * 8, " + e0 - ep") + \
        copy_out("NQ", " + e0 - ep") + '''    if stream:
        _fence()
    return nfail
'''
