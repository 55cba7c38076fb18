"""Compiled position and analog kernel: one fused, parallel loop over positions.

A mechanism is compiled (see :mod:`assur.mechanism`) into a small *program*: an
integer table ``ops`` whose rows are the structural groups in solving order, and a
parameter table ``params`` of shape ``(n_params, m)`` (one column per design).
This kernel interprets the program for every element (design, position) in a
single pass, carrying for each point its value, first and second derivatives with
respect to the ``k`` generalized coordinates (a second-order forward "jet"), so
the kinematic analogs are exact to rounding — no finite differences anywhere.

Every group is solved in closed form for the position; its velocity and
acceleration analogs come from the classical group-wise linear solve: the
closure equations differentiated once and twice (e.g. for an RRR dyad
``(C-A)·(C'-A') = r_a r_a'``), which share the position's 2x2 matrix.

Intermediate points live in a small per-thread scratch buffer; only the
requested outputs are written to memory, so a sweep that asks for one angle
and its analogs moves 24 bytes per position.

Element status codes (``status`` array, 0 = assembled) are decoded into
:class:`assur.errors.AssemblyError` messages by :mod:`assur.mechanism`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

# ---- op codes -----------------------------------------------------------------
OP_FRAME = 0  # [op, out, px, py]
OP_RRR = 1  # [op, out, A, B, ra_ref, rb_ref, branch]
OP_CRANK = 2  # [op, out, A, r_ref, coord, angle0_param]
OP_SLIDE = 3  # [op, out, A, coord, s0_param, beta_param]
OP_RIGID = 4  # [op, out, P, Q, len_ref, beta_param, mode, base_p, opp_p, branch]
OP_RRP = 5  # [op, out, A, r_ref, L0, dirP, dirQ, beta_param, branch]
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

#: Relative size of the closure Jacobian below which a position is a dead point.
DEAD_POINT_TOL = 1e-12


@njit(cache=True, inline="always")
def _ref(ref, params, d, q, e):
    """Value of a length reference: >= 0 a parameter row, < 0 a coordinate."""
    if ref >= 0:
        return params[ref, d]
    return q[-ref - 1, e]


@njit(cache=True)
def _unit(P, dP, ddP, p, qq, beta, K, u, du, ddu):
    """Unit vector of ``Q - P`` rotated by ``beta`` with its jets.

    Writes into ``u`` (2,), ``du`` (2, K), ``ddu`` (2, K, K). Returns the
    length |Q - P| [m] (0 signals coincident points).
    """
    dx = P[qq, 0] - P[p, 0]
    dy = P[qq, 1] - P[p, 1]
    r = math.sqrt(dx * dx + dy * dy)
    if r == 0.0:
        return 0.0
    cb = math.cos(beta)
    sb = math.sin(beta)
    # rotated, not normalised: v = R(beta) (Q - P), |v| = r
    vx = cb * dx - sb * dy
    vy = sb * dx + cb * dy
    ux = vx / r
    uy = vy / r
    u[0] = ux
    u[1] = uy
    # derivatives of v
    for a in range(K):
        ddx = dP[qq, 0, a] - dP[p, 0, a]
        ddy = dP[qq, 1, a] - dP[p, 1, a]
        dvx = cb * ddx - sb * ddy
        dvy = sb * ddx + cb * ddy
        pa = ux * dvx + uy * dvy  # r'_a
        du[0, a] = (dvx - ux * pa) / r
        du[1, a] = (dvy - uy * pa) / r
    for a in range(K):
        ddxa = dP[qq, 0, a] - dP[p, 0, a]
        ddya = dP[qq, 1, a] - dP[p, 1, a]
        dvxa = cb * ddxa - sb * ddya
        dvya = sb * ddxa + cb * ddya
        pa = ux * dvxa + uy * dvya
        for b in range(K):
            ddxb = dP[qq, 0, b] - dP[p, 0, b]
            ddyb = dP[qq, 1, b] - dP[p, 1, b]
            dvxb = cb * ddxb - sb * ddyb
            dvyb = sb * ddxb + cb * ddyb
            pb = ux * dvxb + uy * dvyb
            d2x = ddP[qq, 0, a, b] - ddP[p, 0, a, b]
            d2y = ddP[qq, 1, a, b] - ddP[p, 1, a, b]
            d2vx = cb * d2x - sb * d2y
            d2vy = sb * d2x + cb * d2y
            # d(p_a)/db = u'_b . v'_a + u . v''_ab
            dpa_b = du[0, b] * dvxa + du[1, b] * dvya + ux * d2vx + uy * d2vy
            # u''_ab = (v''_ab - u'_b p_a - u dp_a/db)/r - (v'_a - u p_a) p_b / r^2
            ddu[0, a, b] = (d2vx - du[0, b] * pa - ux * dpa_b) / r - (dvxa - ux * pa) * pb / (r * r)
            ddu[1, a, b] = (d2vy - du[1, b] * pa - uy * dpa_b) / r - (dvya - uy * pa) * pb / (r * r)
    return r


@njit(cache=True)
def _run_element(ops, params, q, e, d, K, P, dP, ddP, Sv, Sd, Sdd, u, du, ddu, rr):
    """Solve all groups for one element. Returns (status, op index, code, amount)."""
    nops = ops.shape[0]
    for i in range(nops):
        op = ops[i, 0]
        o = ops[i, 1]
        if op == OP_FRAME:
            P[o, 0] = params[ops[i, 2], d]
            P[o, 1] = params[ops[i, 3], d]
        elif op == OP_RRR:
            A = ops[i, 2]
            B = ops[i, 3]
            refa = ops[i, 4]
            refb = ops[i, 5]
            sig = float(ops[i, 6])
            ra = _ref(refa, params, d, q, e)
            rb = _ref(refb, params, d, q, e)
            # radius jets: coordinate refs have unit first derivative
            for a in range(K):
                rr[0, a] = 0.0
                rr[1, a] = 0.0
            if refa < 0:
                rr[0, -refa - 1] = 1.0
            if refb < 0:
                rr[1, -refb - 1] = 1.0
            dx = P[B, 0] - P[A, 0]
            dy = P[B, 1] - P[A, 1]
            L = math.sqrt(dx * dx + dy * dy)
            if L == 0.0:
                return i, FAIL_COINCIDENT, 0.0
            if L > ra + rb:
                return i, FAIL_TOO_FAR, L - (ra + rb)
            if L < abs(ra - rb):
                return i, FAIL_TOO_CLOSE, abs(ra - rb) - L
            aa = (ra * ra - rb * rb + L * L) / (2.0 * L)
            h2 = ra * ra - aa * aa
            h = math.sqrt(h2) if h2 > 0.0 else 0.0
            ux = dx / L
            uy = dy / L
            cx = P[A, 0] + aa * ux - sig * h * uy
            cy = P[A, 1] + aa * uy + sig * h * ux
            P[o, 0] = cx
            P[o, 1] = cy
            # Jacobian rows: (C-A)^T, (C-B)^T
            m11 = cx - P[A, 0]
            m12 = cy - P[A, 1]
            m21 = cx - P[B, 0]
            m22 = cy - P[B, 1]
            det = m11 * m22 - m12 * m21
            if abs(det) <= DEAD_POINT_TOL * (ra * rb + 1e-300):
                return i, FAIL_DEAD_POINT, det / (ra * rb)
            for a in range(K):
                r1 = ra * rr[0, a] + m11 * dP[A, 0, a] + m12 * dP[A, 1, a]
                r2 = rb * rr[1, a] + m21 * dP[B, 0, a] + m22 * dP[B, 1, a]
                dP[o, 0, a] = (r1 * m22 - m12 * r2) / det
                dP[o, 1, a] = (m11 * r2 - m21 * r1) / det
            for a in range(K):
                for b in range(K):
                    va_x = dP[o, 0, a] - dP[A, 0, a]
                    va_y = dP[o, 1, a] - dP[A, 1, a]
                    vb_x = dP[o, 0, b] - dP[A, 0, b]
                    vb_y = dP[o, 1, b] - dP[A, 1, b]
                    wa_x = dP[o, 0, a] - dP[B, 0, a]
                    wa_y = dP[o, 1, a] - dP[B, 1, a]
                    wb_x = dP[o, 0, b] - dP[B, 0, b]
                    wb_y = dP[o, 1, b] - dP[B, 1, b]
                    r1 = (rr[0, a] * rr[0, b] - (va_x * vb_x + va_y * vb_y)
                          + m11 * ddP[A, 0, a, b] + m12 * ddP[A, 1, a, b])
                    r2 = (rr[1, a] * rr[1, b] - (wa_x * wb_x + wa_y * wb_y)
                          + m21 * ddP[B, 0, a, b] + m22 * ddP[B, 1, a, b])
                    ddP[o, 0, a, b] = (r1 * m22 - m12 * r2) / det
                    ddP[o, 1, a, b] = (m11 * r2 - m21 * r1) / det
        elif op == OP_CRANK:
            A = ops[i, 2]
            r = _ref(ops[i, 3], params, d, q, e)
            j = ops[i, 4]
            th = q[j, e] + params[ops[i, 5], d]
            c = math.cos(th)
            s = math.sin(th)
            P[o, 0] = P[A, 0] + r * c
            P[o, 1] = P[A, 1] + r * s
            for a in range(K):
                jd = 1.0 if a == j else 0.0
                dP[o, 0, a] = dP[A, 0, a] - r * s * jd
                dP[o, 1, a] = dP[A, 1, a] + r * c * jd
            for a in range(K):
                for b in range(K):
                    jd = 1.0 if (a == j and b == j) else 0.0
                    ddP[o, 0, a, b] = ddP[A, 0, a, b] - r * c * jd
                    ddP[o, 1, a, b] = ddP[A, 1, a, b] - r * s * jd
        elif op == OP_SLIDE:
            A = ops[i, 2]
            j = ops[i, 3]
            t = q[j, e] + params[ops[i, 4], d]
            beta = params[ops[i, 5], d]
            c = math.cos(beta)
            s = math.sin(beta)
            P[o, 0] = P[A, 0] + t * c
            P[o, 1] = P[A, 1] + t * s
            for a in range(K):
                jd = 1.0 if a == j else 0.0
                dP[o, 0, a] = dP[A, 0, a] + c * jd
                dP[o, 1, a] = dP[A, 1, a] + s * jd
            for a in range(K):
                for b in range(K):
                    ddP[o, 0, a, b] = ddP[A, 0, a, b]
                    ddP[o, 1, a, b] = ddP[A, 1, a, b]
        elif op == OP_RIGID:
            p = ops[i, 2]
            qq = ops[i, 3]
            ell = _ref(ops[i, 4], params, d, q, e)
            mode = ops[i, 6]
            if mode == 0:
                beta = params[ops[i, 5], d]
            else:
                # triangle: sides base (origin->toward), ell (origin->new), opp (toward->new)
                base = params[ops[i, 7], d]
                opp = params[ops[i, 8], d]
                if ell > base + opp:
                    return i, FAIL_TRIANGLE, ell - (base + opp)
                if base > ell + opp:
                    return i, FAIL_TRIANGLE, base - (ell + opp)
                if opp > ell + base:
                    return i, FAIL_TRIANGLE, opp - (ell + base)
                cosb = (base * base + ell * ell - opp * opp) / (2.0 * base * ell)
                if cosb > 1.0:
                    cosb = 1.0
                elif cosb < -1.0:
                    cosb = -1.0
                beta = float(ops[i, 9]) * math.acos(cosb)
            r = _unit(P, dP, ddP, p, qq, beta, K, u, du, ddu)
            if r == 0.0:
                return i, FAIL_COINCIDENT, 0.0
            P[o, 0] = P[p, 0] + ell * u[0]
            P[o, 1] = P[p, 1] + ell * u[1]
            for a in range(K):
                dP[o, 0, a] = dP[p, 0, a] + ell * du[0, a]
                dP[o, 1, a] = dP[p, 1, a] + ell * du[1, a]
                for b in range(K):
                    ddP[o, 0, a, b] = ddP[p, 0, a, b] + ell * ddu[0, a, b]
                    ddP[o, 1, a, b] = ddP[p, 1, a, b] + ell * ddu[1, a, b]
        elif op == OP_RRP:
            A = ops[i, 2]
            refr = ops[i, 3]
            r = _ref(refr, params, d, q, e)
            for a in range(K):
                rr[0, a] = 0.0
            if refr < 0:
                rr[0, -refr - 1] = 1.0
            L0 = ops[i, 4]
            dp_ = ops[i, 5]
            dq_ = ops[i, 6]
            beta = params[ops[i, 7], d]
            sig = float(ops[i, 8])
            if dp_ >= 0:
                if _unit(P, dP, ddP, dp_, dq_, beta, K, u, du, ddu) == 0.0:
                    return i, FAIL_COINCIDENT, 0.0
            else:
                u[0] = math.cos(beta)
                u[1] = math.sin(beta)
                for a in range(K):
                    du[0, a] = 0.0
                    du[1, a] = 0.0
                    for b in range(K):
                        ddu[0, a, b] = 0.0
                        ddu[1, a, b] = 0.0
            wx = P[L0, 0] - P[A, 0]
            wy = P[L0, 1] - P[A, 1]
            bb = u[0] * wx + u[1] * wy
            cc = wx * wx + wy * wy - r * r
            disc = bb * bb - cc
            if disc < 0.0:
                # distance from A to the line minus r
                dist = abs(u[0] * wy - u[1] * wx)
                return i, FAIL_LINE, dist - r
            t = -bb + sig * math.sqrt(disc)
            den = 2.0 * (t + bb)
            if abs(den) <= DEAD_POINT_TOL * (abs(r) + 1e-300):
                return i, FAIL_DEAD_POINT, den
            P[o, 0] = P[L0, 0] + t * u[0]
            P[o, 1] = P[L0, 1] + t * u[1]
            # t'_a stored in rr[1, a]
            for a in range(K):
                wxa = dP[L0, 0, a] - dP[A, 0, a]
                wya = dP[L0, 1, a] - dP[A, 1, a]
                ba = du[0, a] * wx + du[1, a] * wy + u[0] * wxa + u[1] * wya
                ca = 2.0 * (wx * wxa + wy * wya) - 2.0 * r * rr[0, a]
                rr[1, a] = -(2.0 * t * ba + ca) / den
            for a in range(K):
                ta = rr[1, a]
                wxa = dP[L0, 0, a] - dP[A, 0, a]
                wya = dP[L0, 1, a] - dP[A, 1, a]
                ba = du[0, a] * wx + du[1, a] * wy + u[0] * wxa + u[1] * wya
                dP[o, 0, a] = dP[L0, 0, a] + ta * u[0] + t * du[0, a]
                dP[o, 1, a] = dP[L0, 1, a] + ta * u[1] + t * du[1, a]
                for b in range(K):
                    tb = rr[1, b]
                    wxb = dP[L0, 0, b] - dP[A, 0, b]
                    wyb = dP[L0, 1, b] - dP[A, 1, b]
                    bbb = du[0, b] * wx + du[1, b] * wy + u[0] * wxb + u[1] * wyb
                    wxab = ddP[L0, 0, a, b] - ddP[A, 0, a, b]
                    wyab = ddP[L0, 1, a, b] - ddP[A, 1, a, b]
                    bab = (ddu[0, a, b] * wx + ddu[1, a, b] * wy
                           + du[0, a] * wxb + du[1, a] * wyb
                           + du[0, b] * wxa + du[1, b] * wya
                           + u[0] * wxab + u[1] * wyab)
                    cab = 2.0 * (wxa * wxb + wya * wyb + wx * wxab + wy * wyab) - 2.0 * rr[0, a] * rr[0, b]
                    tab = -(2.0 * ta * tb + 2.0 * ta * bbb + 2.0 * tb * ba + 2.0 * t * bab + cab) / den
                    ddP[o, 0, a, b] = (ddP[L0, 0, a, b] + tab * u[0] + ta * du[0, b]
                                       + tb * du[0, a] + t * ddu[0, a, b])
                    ddP[o, 1, a, b] = (ddP[L0, 1, a, b] + tab * u[1] + ta * du[1, b]
                                       + tb * du[1, a] + t * ddu[1, a, b])
        elif op == OP_ANGLE or op == OP_DIST:
            p = ops[i, 2]
            qq = ops[i, 3]
            dx = P[qq, 0] - P[p, 0]
            dy = P[qq, 1] - P[p, 1]
            r2 = dx * dx + dy * dy
            if r2 == 0.0:
                return i, FAIL_COINCIDENT, 0.0
            if op == OP_ANGLE:
                Sv[o] = math.atan2(dy, dx)
                for a in range(K):
                    dxa = dP[qq, 0, a] - dP[p, 0, a]
                    dya = dP[qq, 1, a] - dP[p, 1, a]
                    ca = dx * dya - dy * dxa  # d x d'_a
                    Sd[o, a] = ca / r2
                    for b in range(K):
                        dxb = dP[qq, 0, b] - dP[p, 0, b]
                        dyb = dP[qq, 1, b] - dP[p, 1, b]
                        d2x = ddP[qq, 0, a, b] - ddP[p, 0, a, b]
                        d2y = ddP[qq, 1, a, b] - ddP[p, 1, a, b]
                        # phi''_ab = [d'_b x d'_a + d x d''_ab]/r2 - 2 (d x d'_a)(d . d'_b)/r2^2
                        Sdd[o, a, b] = ((dxb * dya - dyb * dxa) + (dx * d2y - dy * d2x)) / r2 \
                            - 2.0 * ca * (dx * dxb + dy * dyb) / (r2 * r2)
            else:
                rlen = math.sqrt(r2)
                Sv[o] = rlen
                for a in range(K):
                    dxa = dP[qq, 0, a] - dP[p, 0, a]
                    dya = dP[qq, 1, a] - dP[p, 1, a]
                    Sd[o, a] = (dx * dxa + dy * dya) / rlen
                for a in range(K):
                    dxa = dP[qq, 0, a] - dP[p, 0, a]
                    dya = dP[qq, 1, a] - dP[p, 1, a]
                    for b in range(K):
                        dxb = dP[qq, 0, b] - dP[p, 0, b]
                        dyb = dP[qq, 1, b] - dP[p, 1, b]
                        d2x = ddP[qq, 0, a, b] - ddP[p, 0, a, b]
                        d2y = ddP[qq, 1, a, b] - ddP[p, 1, a, b]
                        Sdd[o, a, b] = (dxa * dxb + dya * dyb + dx * d2x + dy * d2y
                                        - Sd[o, a] * Sd[o, b]) / rlen
    return -1, 0, 0.0


@njit(cache=True, parallel=True)
def run(ops, params, q, n_per_design, n_points, n_scalars, K,
        out_pts, out_sca, Pv, Pd, Pdd, Sv, Sd, Sdd, status, amount, chunk):
    """Interpret ``ops`` for every element.

    Parameters
    ----------
    ops : int64 array, shape (n_ops, NCOL)
    params : float64 array, shape (n_params, m)
    q : float64 array, shape (K, E)
        Generalized coordinates of every element; element ``e`` belongs to
        design ``e // n_per_design``.
    out_pts, out_sca : int64 arrays
        Scratch slots of the points and scalars to write out.
    Pv, Pd, Pdd : float64 arrays, shapes (len(out_pts), 2, E), (…, 2, K, E), (…, 2, K, K, E)
    Sv, Sd, Sdd : float64 arrays, shapes (len(out_sca), E), (…, K, E), (…, K, K, E)
    status : int64 array, shape (E,)
        ``-1`` where assembled, else the index of the first failing op.
    amount : float64 array, shape (E,)
        Failure code * 1 (in ``status``' companion, see below) and amount [m].
    """
    E = q.shape[1]
    nchunks = (E + chunk - 1) // chunk
    nop = out_pts.shape[0]
    nos = out_sca.shape[0]
    for c in prange(nchunks):
        P = np.zeros((n_points, 2))
        dP = np.zeros((n_points, 2, K))
        ddP = np.zeros((n_points, 2, K, K))
        Ss = np.zeros(max(n_scalars, 1))
        Sds = np.zeros((max(n_scalars, 1), K))
        Sdds = np.zeros((max(n_scalars, 1), K, K))
        u = np.zeros(2)
        du = np.zeros((2, K))
        ddu = np.zeros((2, K, K))
        rr = np.zeros((2, K))
        e0 = c * chunk
        e1 = min(E, e0 + chunk)
        for e in range(e0, e1):
            d = e // n_per_design
            i, code, amt = _run_element(ops, params, q, e, d, K, P, dP, ddP, Ss, Sds, Sdds,
                                        u, du, ddu, rr)
            status[e] = i
            if i >= 0:
                amount[e] = amt
                status[e] = i * 16 + code
                continue
            for k in range(nop):
                s = out_pts[k]
                for x in range(2):
                    Pv[k, x, e] = P[s, x]
                    for a in range(K):
                        Pd[k, x, a, e] = dP[s, x, a]
                        for b in range(K):
                            Pdd[k, x, a, b, e] = ddP[s, x, a, b]
            for k in range(nos):
                s = out_sca[k]
                Sv[k, e] = Ss[s]
                for a in range(K):
                    Sd[k, a, e] = Sds[s, a]
                    for b in range(K):
                        Sdd[k, a, b, e] = Sdds[s, a, b]
