"""Compiled position and analog kernel, generated per mechanism structure.

A mechanism is compiled (see :mod:`assur.mechanism`) into a small *program*: an
integer table ``ops`` whose rows are the structural groups in solving order, and a
parameter table ``params`` of shape ``(n_params, m)`` (one column per design).
This module turns the program into the source of one fused, parallel numba loop
over all elements (design, position) — straight-line code, every point's value,
first and second derivatives with respect to the ``k`` generalized coordinates
held in local variables (a second-order forward "jet") — so that the kinematic
analogs are exact to rounding and a sweep runs at the speed of hand-written
compiled code. Only the requested outputs are written to memory.

Every group is solved in closed form for the position; its velocity and
acceleration analogs come from the classical group-wise linear solve: the
closure equations differentiated once and twice (e.g. for an RRR dyad
``(C-A)·(C'-A') = r_a r_a'``), which share the position's 2x2 matrix.

The generated source depends only on the structure (group types, their
connections, k and the requested outputs), never on parameter values; it is
written to a cache directory (``$ASSUR_CACHE_DIR`` or ``~/.cache/assur``) and
compiled with numba's on-disk cache, so a structure is compiled once per machine.

Failures never produce NaN in a result: each element carries a status
(``-1`` assembled, else ``16·op + code``) and the amount by which the group's
inequality is violated; failed elements get zeros and the caller raises
:class:`assur.errors.AssemblyError` (or reports them, for batches).
"""

from __future__ import annotations

import hashlib
import math
import importlib.util
import os
import sys
import threading
from pathlib import Path

# ---- op codes -----------------------------------------------------------------
OP_FRAME = 0  # [op, out, px, py]
OP_RRR = 1  # [op, out, A, B, ra_ref, rb_ref, branch]
OP_CRANK = 2  # [op, out, A, r_ref, coord, angle0_param]
OP_SLIDE = 3  # [op, out, A, coord, s0_param, beta_param]
OP_RIGID = 4  # [op, out, P, Q, len_ref, trig_row, mode, base_p, opp_p, branch]
OP_RRP = 5  # [op, out, A, r_ref, L0, dirP, dirQ, trig_row, branch]
OP_ANGLE = 6  # [op, out_scalar, P, Q]
OP_DIST = 7  # [op, out_scalar, P, Q]

NCOL = 10

# ---- failure codes --------------------------------------------------------------
FAIL_TOO_FAR = 1  # distance between outer joints exceeds ra + rb
FAIL_TOO_CLOSE = 2  # distance between outer joints below |ra - rb|
FAIL_TRIANGLE = 3  # three given sides cannot form a triangle
FAIL_LINE = 4  # circle does not reach the slider line
FAIL_COINCIDENT = 5  # two points that must define a direction coincide
FAIL_DEAD_POINT = 6  # the group assembles but its Jacobian is singular
FAIL_CONTINUITY = 7  # a dyad opens or flattens between two consecutive positions

#: relative depth below zero of the interpolated squared triangle height that fails
#: the continuity check (see :func:`generate`)
CONTINUITY_TOL = 1e-9

#: |sin μ| of a dyad (μ the transmission angle) below which a position is a dead point.
#: At a dead point the squared triangle height h² is ~0 up to rounding (~ε·L²), so the
#: computed h, and with it sin μ, is only known to ~√ε ≈ 1.5e-8: below 1e-7 the analogs
#: (∝ 1/sin μ) are rounding noise and the position is reported as a dead point.
DEAD_POINT_TOL = 1e-7

#: elements per parallel work item
CHUNK = 256

_VERSION = "17"  # bump when the generator changes what it emits


class _Emitter:
    """Source emitter for one element's straight-line code."""

    def __init__(self, K):
        self.K = K
        self.lines = []
        self.pairs = [(a, b) for a in range(K) for b in range(a, K)]

    def __call__(self, line, indent=3):
        self.lines.append("    " * indent + line)


def _pt(s):
    return f"x{s}", f"y{s}"


def _d(v, a):
    return f"{v}_{a}"


def _dd(v, a, b):
    a, b = min(a, b), max(a, b)
    return f"{v}_{a}{b}"


def _lref(ref, K):
    """Expression and derivative literals of a length reference."""
    if ref >= 0:
        return f"params[{ref}, d]", ["0.0"] * K
    j = -ref - 1
    return f"q[{j}, e]", ["1.0" if a == j else "0.0" for a in range(K)]


def _fail(E, i, code, amount, cond):
    """Record the first failure without branching (selects keep the loop vectorizable).

    ``amount`` (by how much the inequality is violated) is not tracked here — that
    select chain cost more than the geometry; :mod:`assur.mechanism` recomputes it for
    the elements it reports, from the same formulas.
    """
    E(f"st = {i * 16 + code} if ((st < 0) & ({cond})) else st")


def _emit_unit(E, i, p, q, cb, sb):
    """u = R(beta)(Q-P)/|Q-P| with jets, into u{i}x, u{i}y (+ _a, _ab).

    P and Q are points of one rigid link (the mechanism validates this), so |Q-P|
    is constant and u is a linear map of Q - P: u' = R(beta)(Q'-P')/|Q-P|, and
    likewise u''.
    """
    K = E.K
    px, py = _pt(p)
    qx, qy = _pt(q)
    t = f"t{i}"
    E(f"{t}dx = {qx} - {px}")
    E(f"{t}dy = {qy} - {py}")
    E(f"{t}r = math.sqrt({t}dx * {t}dx + {t}dy * {t}dy)")
    _fail(E, i, FAIL_COINCIDENT, "0.0", f"{t}r == 0.0")
    E(f"{t}ir = 1.0 / {t}r if {t}r > 0.0 else 0.0")
    E(f"{t}cb = {cb} * {t}ir")
    E(f"{t}sb = {sb} * {t}ir")
    E(f"u{i}x = {t}cb * {t}dx - {t}sb * {t}dy")
    E(f"u{i}y = {t}sb * {t}dx + {t}cb * {t}dy")
    for a in range(K):
        E(f"{t}dx_{a} = {_d(qx, a)} - {_d(px, a)}")
        E(f"{t}dy_{a} = {_d(qy, a)} - {_d(py, a)}")
        E(f"u{i}x_{a} = {t}cb * {t}dx_{a} - {t}sb * {t}dy_{a}")
        E(f"u{i}y_{a} = {t}sb * {t}dx_{a} + {t}cb * {t}dy_{a}")
    for a, b in E.pairs:
        E(f"{t}d2x = {_dd(qx, a, b)} - {_dd(px, a, b)}")
        E(f"{t}d2y = {_dd(qy, a, b)} - {_dd(py, a, b)}")
        E(f"{_dd(f'u{i}x', a, b)} = {t}cb * {t}d2x - {t}sb * {t}d2y")
        E(f"{_dd(f'u{i}y', a, b)} = {t}sb * {t}d2x + {t}cb * {t}d2y")


def _emit_zero_jets(E, v):
    for a in range(E.K):
        E(f"{_d(v, a)} = 0.0")
    for a, b in E.pairs:
        E(f"{_dd(v, a, b)} = 0.0")


def generate(ops, K, out_pts, out_sca):
    """Python source of the kernel for a program (see module docstring).

    Continuity (k = 1, when the caller passes ``check=True``): for every RRR dyad the
    squared height g = h² of its triangle over the base AB is positive at each solved
    position; with its exact derivative the cubic Hermite interpolant of g over each
    interval between consecutive positions of a design must stay positive too,
    otherwise the dyad flattens (dead point) or cannot assemble somewhere between the
    samples, and the mechanism cannot move from one position to the next on its branch.
    """
    E = _Emitter(K)
    ops = [list(map(int, r)) for r in ops]
    dyads = [i for i, r in enumerate(ops) if int(r[0]) == OP_RRR] if K == 1 else []
    for i, r in enumerate(ops):
        op, o = r[0], r[1]
        E(f"# op {i}: code {op}")
        if op == OP_FRAME:
            x, y = _pt(o)
            E(f"{x} = params[{r[2]}, d]")
            E(f"{y} = params[{r[3]}, d]")
            _emit_zero_jets(E, x)
            _emit_zero_jets(E, y)
        elif op == OP_RRR:
            A, B, refa, refb, sig = r[2], r[3], r[4], r[5], r[6]
            ax, ay = _pt(A)
            bx, by = _pt(B)
            x, y = _pt(o)
            ra, dra = _lref(refa, K)
            rb, drb = _lref(refb, K)
            t = f"t{i}"
            E(f"{t}ra = {ra}")
            E(f"{t}rb = {rb}")
            E(f"{t}dx = {bx} - {ax}")
            E(f"{t}dy = {by} - {ay}")
            E(f"{t}L = math.sqrt({t}dx * {t}dx + {t}dy * {t}dy)")
            _fail(E, i, FAIL_COINCIDENT, "0.0", f"{t}L == 0.0")
            _fail(E, i, FAIL_TOO_FAR, f"{t}L - ({t}ra + {t}rb)", f"{t}L > {t}ra + {t}rb")
            _fail(E, i, FAIL_TOO_CLOSE, f"abs({t}ra - {t}rb) - {t}L",
                  f"{t}L < abs({t}ra - {t}rb)")
            E(f"{t}iL = 1.0 / {t}L if {t}L > 0.0 else 0.0")
            E(f"{t}a = 0.5 * ({t}ra * {t}ra - {t}rb * {t}rb + {t}L * {t}L) * {t}iL")
            E(f"{t}h2 = {t}ra * {t}ra - {t}a * {t}a")
            E(f"{t}h = math.sqrt({t}h2) if {t}h2 > 0.0 else 0.0")
            E(f"{t}ux = {t}dx * {t}iL")
            E(f"{t}uy = {t}dy * {t}iL")
            E(f"{x} = {ax} + {t}a * {t}ux - ({sig}.0) * {t}h * {t}uy")
            E(f"{y} = {ay} + {t}a * {t}uy + ({sig}.0) * {t}h * {t}ux")
            E(f"{t}m11 = {x} - {ax}")
            E(f"{t}m12 = {y} - {ay}")
            E(f"{t}m21 = {x} - {bx}")
            E(f"{t}m22 = {y} - {by}")
            E(f"{t}det = {t}m11 * {t}m22 - {t}m12 * {t}m21")
            E(f"{t}rr = {t}ra * {t}rb")
            _fail(E, i, FAIL_DEAD_POINT, f"{t}det / {t}rr if {t}rr != 0.0 else 0.0",
                  f"abs({t}det) <= {DEAD_POINT_TOL!r} * abs({t}rr)")
            E(f"{t}idet = 1.0 / {t}det if {t}det != 0.0 else 0.0")
            for a in range(K):
                r1 = f"{t}ra * {dra[a]} + {t}m11 * {_d(ax, a)} + {t}m12 * {_d(ay, a)}"
                r2 = f"{t}rb * {drb[a]} + {t}m21 * {_d(bx, a)} + {t}m22 * {_d(by, a)}"
                E(f"{t}r1 = {r1}")
                E(f"{t}r2 = {r2}")
                E(f"{_d(x, a)} = ({t}r1 * {t}m22 - {t}m12 * {t}r2) * {t}idet")
                E(f"{_d(y, a)} = ({t}m11 * {t}r2 - {t}m21 * {t}r1) * {t}idet")
            if K == 1:
                # squared height g = cr²/L² with cr = (B-A) x (C-A), and its derivative
                E(f"{t}cr = {t}dx * {t}m12 - {t}dy * {t}m11")
                E(f"{t}dcr = ({_d(bx, 0)} - {_d(ax, 0)}) * {t}m12 + {t}dx * ({_d(y, 0)} - "
                  f"{_d(ay, 0)}) - ({_d(by, 0)} - {_d(ay, 0)}) * {t}m11 - {t}dy * ({_d(x, 0)} - "
                  f"{_d(ax, 0)})")
                E(f"{t}dL2 = 2.0 * ({t}dx * ({_d(bx, 0)} - {_d(ax, 0)}) + {t}dy * ({_d(by, 0)} - "
                  f"{_d(ay, 0)}))")
                E(f"g{i} = {t}cr * {t}cr * {t}iL * {t}iL")
                E(f"gd{i} = (2.0 * {t}cr * {t}dcr - {t}cr * {t}cr * {t}dL2 * {t}iL * {t}iL)"
                  f" * {t}iL * {t}iL")
            for a, b in E.pairs:
                va = f"({_d(x, a)} - {_d(ax, a)})", f"({_d(y, a)} - {_d(ay, a)})"
                vb = f"({_d(x, b)} - {_d(ax, b)})", f"({_d(y, b)} - {_d(ay, b)})"
                wa = f"({_d(x, a)} - {_d(bx, a)})", f"({_d(y, a)} - {_d(by, a)})"
                wb = f"({_d(x, b)} - {_d(bx, b)})", f"({_d(y, b)} - {_d(by, b)})"
                E(f"{t}r1 = {dra[a]} * {dra[b]} - ({va[0]} * {vb[0]} + {va[1]} * {vb[1]})"
                  f" + {t}m11 * {_dd(ax, a, b)} + {t}m12 * {_dd(ay, a, b)}")
                E(f"{t}r2 = {drb[a]} * {drb[b]} - ({wa[0]} * {wb[0]} + {wa[1]} * {wb[1]})"
                  f" + {t}m21 * {_dd(bx, a, b)} + {t}m22 * {_dd(by, a, b)}")
                E(f"{_dd(x, a, b)} = ({t}r1 * {t}m22 - {t}m12 * {t}r2) * {t}idet")
                E(f"{_dd(y, a, b)} = ({t}m11 * {t}r2 - {t}m21 * {t}r1) * {t}idet")
        elif op == OP_CRANK:
            A, refr, j, ph = r[2], r[3], r[4], r[5]
            ax, ay = _pt(A)
            x, y = _pt(o)
            rr, dr = _lref(refr, K)
            t = f"t{i}"
            E(f"{t}r = {rr}")
            E(f"{t}th = q[{j}, e] + params[{ph}, d]")
            E(f"{t}c = math.cos({t}th)")
            E(f"{t}s = math.sin({t}th)")
            E(f"{x} = {ax} + {t}r * {t}c")
            E(f"{y} = {ay} + {t}r * {t}s")
            # A = pivot + r(q)·(cos θ, sin θ): θ' = δ_aj; r may itself be a coordinate
            for a in range(K):
                ex, ey = "", ""
                if a == j:
                    ex += f" - {t}r * {t}s"
                    ey += f" + {t}r * {t}c"
                if dr[a] != "0.0":
                    ex += f" + {t}c"
                    ey += f" + {t}s"
                E(f"{_d(x, a)} = {_d(ax, a)}{ex}")
                E(f"{_d(y, a)} = {_d(ay, a)}{ey}")
            for a, b in E.pairs:
                ex, ey = "", ""
                if a == j and b == j:
                    ex += f" - {t}r * {t}c"
                    ey += f" - {t}r * {t}s"
                for u_, v_ in ((a, b), (b, a)):
                    # r'_u · θ'_v · (−sin, cos), both orders of the mixed derivative
                    if dr[u_] != "0.0" and v_ == j:
                        ex += f" - {t}s"
                        ey += f" + {t}c"
                E(f"{_dd(x, a, b)} = {_dd(ax, a, b)}{ex}")
                E(f"{_dd(y, a, b)} = {_dd(ay, a, b)}{ey}")
        elif op == OP_SLIDE:
            A, j, s0, trow = r[2], r[3], r[4], r[5]
            ax, ay = _pt(A)
            x, y = _pt(o)
            t = f"t{i}"
            E(f"{t}t = q[{j}, e] + params[{s0}, d]")
            E(f"{t}c = trig[{trow}, d]")
            E(f"{t}s = trig[{trow + 1}, d]")
            E(f"{x} = {ax} + {t}t * {t}c")
            E(f"{y} = {ay} + {t}t * {t}s")
            for a in range(K):
                extra = (f" + {t}c", f" + {t}s") if a == j else ("", "")
                E(f"{_d(x, a)} = {_d(ax, a)}{extra[0]}")
                E(f"{_d(y, a)} = {_d(ay, a)}{extra[1]}")
            for a, b in E.pairs:
                E(f"{_dd(x, a, b)} = {_dd(ax, a, b)}")
                E(f"{_dd(y, a, b)} = {_dd(ay, a, b)}")
        elif op == OP_RIGID:
            P, Q, lref, trow, mode = r[2], r[3], r[4], r[5], r[6]
            x, y = _pt(o)
            px, py = _pt(P)
            ell, dell = _lref(lref, K)
            t = f"t{i}"
            E(f"{t}l = {ell}")
            if mode == 1:
                E(f"{t}b = params[{r[7]}, d]")
                E(f"{t}o = params[{r[8]}, d]")
                _fail(E, i, FAIL_TRIANGLE, f"{t}l - ({t}b + {t}o)", f"{t}l > {t}b + {t}o")
                _fail(E, i, FAIL_TRIANGLE, f"{t}b - ({t}l + {t}o)", f"{t}b > {t}l + {t}o")
                _fail(E, i, FAIL_TRIANGLE, f"{t}o - ({t}l + {t}b)", f"{t}o > {t}l + {t}b")
            _emit_unit(E, i, P, Q, f"trig[{trow}, d]", f"trig[{trow + 1}, d]")
            E(f"{x} = {px} + {t}l * u{i}x")
            E(f"{y} = {py} + {t}l * u{i}y")
            for a in range(K):
                for c, pc in (("x", px), ("y", py)):
                    E(f"{_d(c + str(o), a)} = {_d(pc, a)} + {t}l * u{i}{c}_{a}"
                      + (f" + {dell[a]} * u{i}{c}" if dell[a] != "0.0" else ""))
            for a, b in E.pairs:
                for c, pc in (("x", px), ("y", py)):
                    extra = ""
                    if dell[a] != "0.0":
                        extra += f" + {dell[a]} * u{i}{c}_{b}"
                    if dell[b] != "0.0":
                        extra += f" + {dell[b]} * u{i}{c}_{a}"
                    E(f"{_dd(c + str(o), a, b)} = {_dd(pc, a, b)} + {t}l * "
                      f"{_dd(f'u{i}{c}', a, b)}{extra}")
        elif op == OP_RRP:
            A, refr, L0, dP_, dQ_, trow, sig = r[2], r[3], r[4], r[5], r[6], r[7], r[8]
            ax, ay = _pt(A)
            lx, ly = _pt(L0)
            x, y = _pt(o)
            rr, dr = _lref(refr, K)
            t = f"t{i}"
            if dP_ >= 0:
                _emit_unit(E, i, dP_, dQ_, f"trig[{trow}, d]", f"trig[{trow + 1}, d]")
            else:
                E(f"u{i}x = trig[{trow}, d]")
                E(f"u{i}y = trig[{trow + 1}, d]")
                _emit_zero_jets(E, f"u{i}x")
                _emit_zero_jets(E, f"u{i}y")
            E(f"{t}r = {rr}")
            E(f"{t}wx = {lx} - {ax}")
            E(f"{t}wy = {ly} - {ay}")
            E(f"{t}b = u{i}x * {t}wx + u{i}y * {t}wy")
            E(f"{t}c = {t}wx * {t}wx + {t}wy * {t}wy - {t}r * {t}r")
            E(f"{t}disc = {t}b * {t}b - {t}c")
            _fail(E, i, FAIL_LINE, f"abs(u{i}x * {t}wy - u{i}y * {t}wx) - {t}r", f"{t}disc < 0.0")
            E(f"{t}sq = math.sqrt({t}disc) if {t}disc > 0.0 else 0.0")
            E(f"{t}t = -{t}b + ({sig}.0) * {t}sq")
            E(f"{t}den = 2.0 * ({t}t + {t}b)")
            _fail(E, i, FAIL_DEAD_POINT, f"{t}den",
                  f"abs({t}den) <= {DEAD_POINT_TOL!r} * abs({t}r)")
            E(f"{t}iden = 1.0 / {t}den if {t}den != 0.0 else 0.0")
            E(f"{x} = {lx} + {t}t * u{i}x")
            E(f"{y} = {ly} + {t}t * u{i}y")
            for a in range(K):
                E(f"{t}wx_{a} = {_d(lx, a)} - {_d(ax, a)}")
                E(f"{t}wy_{a} = {_d(ly, a)} - {_d(ay, a)}")
                E(f"{t}b_{a} = u{i}x_{a} * {t}wx + u{i}y_{a} * {t}wy + u{i}x * {t}wx_{a}"
                  f" + u{i}y * {t}wy_{a}")
                E(f"{t}c_{a} = 2.0 * ({t}wx * {t}wx_{a} + {t}wy * {t}wy_{a}) - 2.0 * {t}r * {dr[a]}")
                E(f"{t}t_{a} = -(2.0 * {t}t * {t}b_{a} + {t}c_{a}) * {t}iden")
                E(f"{_d(x, a)} = {_d(lx, a)} + {t}t_{a} * u{i}x + {t}t * u{i}x_{a}")
                E(f"{_d(y, a)} = {_d(ly, a)} + {t}t_{a} * u{i}y + {t}t * u{i}y_{a}")
            for a, b in E.pairs:
                E(f"{t}wxab = {_dd(lx, a, b)} - {_dd(ax, a, b)}")
                E(f"{t}wyab = {_dd(ly, a, b)} - {_dd(ay, a, b)}")
                E(f"{t}bab = ({_dd(f'u{i}x', a, b)} * {t}wx + {_dd(f'u{i}y', a, b)} * {t}wy"
                  f" + u{i}x_{a} * {t}wx_{b} + u{i}y_{a} * {t}wy_{b}"
                  f" + u{i}x_{b} * {t}wx_{a} + u{i}y_{b} * {t}wy_{a}"
                  f" + u{i}x * {t}wxab + u{i}y * {t}wyab)")
                E(f"{t}cab = 2.0 * ({t}wx_{a} * {t}wx_{b} + {t}wy_{a} * {t}wy_{b} + {t}wx * {t}wxab"
                  f" + {t}wy * {t}wyab) - 2.0 * {dr[a]} * {dr[b]}")
                E(f"{t}tab = -(2.0 * {t}t_{a} * {t}t_{b} + 2.0 * {t}t_{a} * {t}b_{b}"
                  f" + 2.0 * {t}t_{b} * {t}b_{a} + 2.0 * {t}t * {t}bab + {t}cab) * {t}iden")
                for c, lc in (("x", lx), ("y", ly)):
                    E(f"{_dd(c + str(o), a, b)} = {_dd(lc, a, b)} + {t}tab * u{i}{c}"
                      f" + {t}t_{a} * u{i}{c}_{b} + {t}t_{b} * u{i}{c}_{a} + {t}t * "
                      f"{_dd(f'u{i}{c}', a, b)}")
        elif op in (OP_ANGLE, OP_DIST):
            P, Q = r[2], r[3]
            px, py = _pt(P)
            qx, qy = _pt(Q)
            s = f"s{o}"
            t = f"t{i}"
            E(f"{t}dx = {qx} - {px}")
            E(f"{t}dy = {qy} - {py}")
            E(f"{t}r2 = {t}dx * {t}dx + {t}dy * {t}dy")
            _fail(E, i, FAIL_COINCIDENT, "0.0", f"{t}r2 == 0.0")
            E(f"{t}ir2 = 1.0 / {t}r2 if {t}r2 > 0.0 else 0.0")
            for a in range(K):
                E(f"{t}dx_{a} = {_d(qx, a)} - {_d(px, a)}")
                E(f"{t}dy_{a} = {_d(qy, a)} - {_d(py, a)}")
            if op == OP_ANGLE:
                # the angle itself is atan2(dy, dx), taken after the kernel by numpy's
                # vectorized arctan2 (an order of magnitude faster than a scalar libm
                # call): the kernel outputs dy as the value and dx in an extra row
                E(f"{s} = {t}dy")
                E(f"{s}_dx = {t}dx")
                for a in range(K):
                    E(f"{t}c_{a} = {t}dx * {t}dy_{a} - {t}dy * {t}dx_{a}")
                    E(f"{_d(s, a)} = {t}c_{a} * {t}ir2")
                for a, b in E.pairs:
                    # phi''_ab = [d'_b x d'_a + d x d''_ab]/r2 - 2 (d x d'_a)(d . d'_b)/r2^2
                    E(f"{_dd(s, a, b)} = (({t}dx_{b} * {t}dy_{a} - {t}dy_{b} * {t}dx_{a})"
                      f" + ({t}dx * ({_dd(qy, a, b)} - {_dd(py, a, b)}) - {t}dy * "
                      f"({_dd(qx, a, b)} - {_dd(px, a, b)}))) * {t}ir2"
                      f" - 2.0 * {t}c_{a} * ({t}dx * {t}dx_{b} + {t}dy * {t}dy_{b}) * {t}ir2 * {t}ir2")
            else:
                E(f"{s} = math.sqrt({t}r2)")
                E(f"{t}il = 1.0 / {s} if {s} > 0.0 else 0.0")
                for a in range(K):
                    E(f"{_d(s, a)} = ({t}dx * {t}dx_{a} + {t}dy * {t}dy_{a}) * {t}il")
                for a, b in E.pairs:
                    E(f"{_dd(s, a, b)} = ({t}dx_{a} * {t}dx_{b} + {t}dy_{a} * {t}dy_{b}"
                      f" + {t}dx * ({_dd(qx, a, b)} - {_dd(px, a, b)}) + {t}dy * "
                      f"({_dd(qy, a, b)} - {_dd(py, a, b)}) - {_d(s, a)} * {_d(s, b)}) * {t}il")
        else:  # pragma: no cover
            raise ValueError(f"unknown op code {op}")
    # per-design values are loaded once per run of positions of a design, before the
    # element loop (so the loop reads only q and can be vectorized)
    import re as _re
    prows = sorted({int(m) for line in E.lines for m in _re.findall(r"params\[(\d+), d\]", line)})
    trows = sorted({int(m) for line in E.lines for m in _re.findall(r"trig\[(\d+), d\]", line)})
    body = [_re.sub(r"trig\[(\d+), d\]", r"T\1",
                    _re.sub(r"params\[(\d+), d\]", r"P\1", "    " + line)) for line in E.lines]
    hoist = "".join(f"            P{r} = params[{r}, d]\n" for r in prows)
    hoist += "".join(f"            T{r} = trig[{r}, d]\n" for r in trows)
    out = []
    w = out.append
    ind = "                "
    w(ind + "status[e] = st")
    # outputs go to a per-chunk buffer (one row per quantity, in L2) and are copied
    # row by row to OUT at the end of the chunk: a few long sequential streams instead
    # of one interleaved stream per quantity; failed elements get 0, never NaN
    quantities = []
    for s_ in out_pts:
        for v in (f"x{s_}", f"y{s_}"):
            quantities.append(v)
    for s_ in out_pts:
        for v in (f"x{s_}", f"y{s_}"):
            quantities += [_d(v, a) for a in range(K)]
    for s_ in out_pts:
        for v in (f"x{s_}", f"y{s_}"):
            quantities += [_dd(v, a, b) for a in range(K) for b in range(K)]
    quantities += [f"s{s_}" for s_ in out_sca]
    quantities += [_d(f"s{s_}", a) for s_ in out_sca for a in range(K)]
    quantities += [_dd(f"s{s_}", a, b) for s_ in out_sca for a in range(K) for b in range(K)]
    # the dx of every output angle (see OP_ANGLE), in the order of out_sca
    angle_slots = {int(r[1]) for r in ops if int(r[0]) == OP_ANGLE}
    quantities += [f"s{s_}_dx" for s_ in out_sca if s_ in angle_slots]
    nq = len(quantities)
    # then the squared triangle heights and slopes for the continuity check (a separate
    # pass): staged unconditionally (a conditional store would stop vectorization),
    # copied to gout only when checking
    for i in dyads:
        quantities += [f"g{i}", f"gd{i}"]
    if quantities:
        w(ind + "ok_ = st < 0")
        w(ind + "j = e - e0")
        for qi, v in enumerate(quantities):
            w(ind + f"buf[{qi}, j] = {v} if ok_ else 0.0")
    src = f'''"""Generated by assur._kernel (format {_VERSION}); do not edit."""
import math
import numpy as np
from numba import njit


@njit(cache=True, error_model="numpy", nogil=True)
def kernel(params, trig, q, npd, check, out, gout, status, amount, c_start, c_end):
    """Chunks c_start…c_end−1 of the elements. out: (NQ, E) outputs, rows in the order
    listed by the generator; gout: (2·dyads, E) squared heights and slopes when
    ``check``. Branch-free element loop (vectorizable); releases the GIL: callers
    run ranges in threads."""
    E = q.shape[1]
    NQ = {nq}
    NG = {len(quantities) - nq}
    if out.shape[0] != NQ or gout.shape[0] != NG or out.shape[1] != E:
        raise ValueError("assur kernel: output arrays do not match the program")
    buf = np.empty(({max(len(quantities), 1)}, {CHUNK}))
    # work items are runs of ≤ {CHUNK} positions of one design: the per-design values
    # are loop-invariant and the element loop is a plain counted loop (vectorizable)
    cpd = (npd + {CHUNK} - 1) // {CHUNK}
    for c in range(c_start, c_end):
        d = c // cpd
        e0 = d * npd + (c % cpd) * {CHUNK}
        e1 = min(d * npd + npd, e0 + {CHUNK})
        if e1 > e0:
{hoist}            for e in range(e0, e1):
                st = -1
''' + "\n".join(body) + "\n" + "\n".join(out) + "\n" + '''        for r in range(NQ):
            for j in range(e1 - e0):
                out[r, e0 + j] = buf[r, j]
        if check:
            for r in range(NG):
                for j in range(e1 - e0):
                    gout[r, e0 + j] = buf[NQ + r, j]
'''
    return src


_lock = threading.Lock()
_loaded: dict[str, object] = {}


def cache_dir() -> Path:
    """Directory of generated kernels (``$ASSUR_CACHE_DIR`` or ``~/.cache/assur``)."""
    d = os.environ.get("ASSUR_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "assur")
    p = Path(d) / "kernels"
    p.mkdir(parents=True, exist_ok=True)
    return p


_by_structure: dict = {}
_pool = None


def check_continuity(gout, q, npd, status, amount, codes):
    """Run :func:`continuity` over all elements, split over the CPUs in threads."""
    E = q.shape[1]
    nthreads = min(os.cpu_count() or 1, max(1, E // 65536))
    if nthreads <= 1:
        return continuity(gout, q, npd, status, amount, codes, 0, E)
    per = (E + nthreads - 1) // nthreads
    pool = _get_pool()
    futs = [pool.submit(continuity, gout, q, npd, status, amount, codes, i * per,
                        min(E, (i + 1) * per)) for i in range(nthreads)]
    return sum(f.result() for f in futs)


def _get_pool():
    global _pool
    if _pool is None:
        from concurrent.futures import ThreadPoolExecutor
        _pool = ThreadPoolExecutor(max_workers=os.cpu_count(), thread_name_prefix="assur")
    return _pool


def run(kernel, params, trig, q, npd, check, out, gout, status, amount):
    """Run a generated kernel over all elements, split over the CPUs in threads (the
    kernel releases the GIL); small problems run in the calling thread."""
    E = q.shape[1]
    nchunks = (E // npd) * ((npd + CHUNK - 1) // CHUNK)  # designs × runs per design
    nthreads = min(os.cpu_count() or 1, max(1, nchunks // 8))
    if nthreads <= 1:
        kernel(params, trig, q, npd, check, out, gout, status, amount, 0, nchunks)
        return
    per = (nchunks + nthreads - 1) // nthreads
    futs = [_get_pool().submit(kernel, params, trig, q, npd, check, out, gout, status, amount,
                         i * per, min(nchunks, (i + 1) * per)) for i in range(nthreads)]
    for f in futs:
        f.result()


def get_kernel(ops, K, out_pts, out_sca):
    """The compiled kernel for a program structure (generated, cached, loaded once)."""
    skey = (ops.tobytes(), ops.shape, K, tuple(out_pts), tuple(out_sca))
    fn = _by_structure.get(skey)
    if fn is not None:
        return fn
    fn = _load(generate(ops, K, out_pts, out_sca))
    _by_structure[skey] = fn
    return fn


def _load(src):
    key = hashlib.sha1(src.encode()).hexdigest()[:20]
    with _lock:
        fn = _loaded.get(key)
        if fn is not None:
            return fn
        path = cache_dir() / f"k_{key}.py"
        if not path.exists() or path.read_text() != src:
            tmp = path.with_suffix(f".{os.getpid()}.tmp")
            tmp.write_text(src)
            os.replace(tmp, path)
        name = f"assur_kernel_{key}"
        spec = importlib.util.spec_from_file_location(name, path)
        mod = importlib.util.module_from_spec(spec)
        sys.modules[name] = mod
        spec.loader.exec_module(mod)
        _loaded[key] = mod.kernel
        return mod.kernel


def _continuity_impl():
    from numba import njit

    @njit(cache=True, nogil=True, error_model="numpy")
    def continuity(gout, q, npd, status, amount, codes, e_start, e_end):
        """Cubic-Hermite check of every dyad's squared height between consecutive
        positions of each design (see :func:`generate`), for the right-hand elements
        e_start…e_end−1; marks the right-hand element of a failing interval with the
        dyad's code. Returns the number of failures."""
        nfail = 0
        for e in range(max(e_start, 1), e_end):
            if e % npd == 0 or status[e] >= 0 or status[e - 1] >= 0:
                continue
            h = q[0, e] - q[0, e - 1]
            for k in range(codes.shape[0]):
                g0 = gout[2 * k, e - 1]
                d0 = gout[2 * k + 1, e - 1]
                g1 = gout[2 * k, e]
                d1 = gout[2 * k + 1, e]
                mn = min(g0, g1)
                if mn - (4.0 / 27.0) * abs(h) * (abs(d0) + abs(d1)) > 0.0:
                    continue
                for i in range(1, 16):
                    t = i / 16.0
                    t2 = t * t
                    t3 = t2 * t
                    v = ((2.0 * t3 - 3.0 * t2 + 1.0) * g0 + (t3 - 2.0 * t2 + t) * h * d0
                         + (-2.0 * t3 + 3.0 * t2) * g1 + (t3 - t2) * h * d1)
                    if v < mn:
                        mn = v
                if mn < -CONT_TOL * max(g0, g1):
                    status[e] = codes[k]
                    amount[e] = mn
                    nfail += 1
                    break
        return nfail

    return continuity


CONT_TOL = CONTINUITY_TOL
continuity = _continuity_impl()


def _unwrap_impl():
    from numba import njit

    @njit(cache=True, nogil=True)
    def unwrap_rows(sv, rows, n):
        """Make angles continuous along positions, in place: sv shape (ns, E), E = m·n;
        each run of n positions (one design) starts at its principal value [rad]."""
        m = sv.shape[1] // n
        two_pi = 2.0 * math.pi
        for job in range(rows.shape[0] * m):
            r = rows[job // m]
            d = job % m
            off = 0.0
            prev = sv[r, d * n]
            for i in range(d * n + 1, (d + 1) * n):
                cur = sv[r, i]
                step = cur - prev
                if step > math.pi:
                    off -= two_pi
                elif step < -math.pi:
                    off += two_pi
                prev = cur
                sv[r, i] = cur + off

    return unwrap_rows


unwrap_rows = _unwrap_impl()
