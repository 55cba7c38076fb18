"""The right-hand side of the simulated system (the drive's branches coupled through
the equations of motion), its start and its events (:mod:`assur.dynamics.simulate`)."""

from __future__ import annotations

import numpy as np

from ..errors import ModelError

#: how far past a stop (a fraction of the stroke) the piston is taken to hit it: a
#: piston that has just left a stop with zero speed and force may creep back by
#: rounding, which must not count as a new impact
CONTACT = 1e-9

#: the energy integrals after the states q, q̇, p (module docstring); ``divider``
#: only with a flow divider
ENERGY_STATES = ("pump", "relief", "line", "lumped_volume", "loads", "divider")


class _Machine:
    """Right-hand side of the system, vectorised over states (columns)."""

    def __init__(self, mech, circuit, g):
        self.mech = mech
        self.circuit = circuit
        br = circuit.branches
        self.k = k = len(br)
        self.Qp = circuit.pump_flow()
        self.sigma = np.array([b.sense for b in br], float)
        self.A = np.array([b.area for b in br])
        a = np.array([b.loss_coefficients(self.Qp) for b in br]).reshape(k, 3)
        self.a1, self.a2, self.a3 = a[:, 0], a[:, 1], a[:, 2]
        self.E = np.array([b.volume.bulk_modulus for b in br])
        self.V0 = np.array([b.volume.volume for b in br])
        self.q0 = np.array([b.stop for b in br])
        self.Qin = np.array([b.flow(self.Qp) for b in br])
        self.p_set = np.array([np.inf if b.relief is None else b.relief.setting for b in br])
        self.g_r = np.array([0.0 if b.relief is None else b.relief.conductance(q)
                             for b, q in zip(br, self.Qin)])
        self.lo = np.array([b.cylinder.s_min for b in br])
        self.hi = np.array([b.cylinder.s_max for b in br])
        self.A1 = np.diag(self.a1 * self.A)
        self.divider = k > 1
        self.energy_names = ENERGY_STATES[:5] + (("divider",) if self.divider else ())
        self.n = 3 * k + len(self.energy_names)
        self.nfev = 0
        self._c = lambda x: x[:, None]
        # column vectors of the constants (the solver's hot path)
        self.col = {n: getattr(self, n)[:, None] for n in ("sigma", "A", "a1", "a2", "a3",
                                                             "E", "Qin", "p_set", "g_r")}
        self.col["sA"] = self.col["sigma"] * self.col["A"]
        self.col["V0"], self.col["q0"] = self.V0[:, None], self.q0[:, None]
        self._sum = (lambda a: a[0]) if k == 1 else (lambda a: a.sum(0))

    def volume(self, q):
        """V_j [m³] at the coordinates q (k, m)."""
        return self.V0[:, None] + (self.A * self.sigma)[:, None] * (q - self.q0[:, None])

    def _dynamics(self, y, free, idx=None):
        """q, q̇, p, M, ∂M/∂q, Q, h, u, the line loss and q̈ at the states ``y``
        (shape (n, m)) with the coordinates ``free`` (bool (k,)) moving (their
        indices ``idx``)."""
        k, col = self.k, self.col
        q, p = y[:k], y[2 * k:3 * k]
        idx = np.flatnonzero(free) if idx is None else idx
        v = y[k:2 * k] if idx.size == k else y[k:2 * k] * free[:, None]
        M, dM, Q = self.mech.mechanics(q)
        Q = Q.T
        if k == 1:
            h = 0.5 * dM[:, 0, 0, 0] * v * v
        else:
            vt = v.T
            h = (np.einsum("mijl,mj,ml->im", dM, vt, vt)
                 - 0.5 * np.einsum("mjli,mj,ml->im", dM, vt, vt))
        u = col["sigma"] * v
        loss = col["a2"] * u + col["a3"] * u * np.abs(u)
        rhs = Q - h + col["sA"] * (p - loss)
        if idx.size == k == 1:
            acc = rhs / (M[:, 0, 0] + self.A1[0, 0])
        else:
            acc = np.zeros_like(v)
            if idx.size:
                Me = M + self.A1
                Mf = Me[:, idx[:, None], idx[None, :]]
                acc[idx] = np.linalg.solve(Mf, rhs[idx].T[..., None])[..., 0].T
        return q, v, p, M, dM, Q, h, u, loss, acc

    def _pdot(self, q, p, u):
        """ṗ, V, Q_r [Pa/s, m³, m³/s] (eq. 2 of every branch)."""
        col = self.col
        V = col["V0"] + col["sA"] * (q - col["q0"])
        if V.min() <= 0:
            j, i = np.argwhere(V <= 0)[0]
            raise ModelError(f"drive: the lumped oil volume V0 + A·σ·(q − q0) of "
                             f"{self.circuit.coordinates[j]!r} is not positive at "
                             f"{float(q[j, i]):.6g} m (V0 = {self.V0[j]:.6g} m³)")
        over = p > col["p_set"]
        Qr = np.where(over, col["g_r"] * (p - np.where(over, col["p_set"], 0.0)), 0.0) \
            if over.any() else 0.0 * p
        return col["E"] * (col["Qin"] - Qr - col["A"] * u) / V, V, Qr

    def terms(self, y, free):
        """Every derived quantity at the states ``y`` (shape (n, m)) with the
        coordinates ``free`` (bool (k,)) moving and the others resting on a stop."""
        c = self._c
        q, v, p, M, dM, Q, h, u, loss, acc = self._dynamics(y, free)
        sig, A = c(self.sigma), c(self.A)
        p2 = p - c(self.a1) * sig * acc - loss
        F = sig * A * p2
        R = np.einsum("mij,jm->im", M, acc) + h - Q - F  # the stops' reactions
        pdot, V, Qr = self._pdot(q, p, u)
        Qc = A * u
        Qin = c(self.Qin)
        pp = p.max(axis=0)
        return dict(q=q, v=v, p=p, acc=acc, p2=p2, F=F, R=R, pdot=pdot, M=M, dM=dM, Q=Q,
                    V=V, Qr=Qr, Qc=Qc, Qcomp=pdot * V / c(self.E), pp=pp,
                    P_pump=pp * self.Qp, P_relief=(p * Qr).sum(0),
                    P_line=(A * (c(self.a2) * u * u + c(self.a3) * u * u * np.abs(u))).sum(0),
                    P_lump=(p * p * A * u / (2 * c(self.E))).sum(0),
                    P_loads=-(Q * v).sum(0), P_divider=((pp - p) * Qin).sum(0))

    def rhs(self, free):
        """f(t, y) for solve_ivp (vectorized: y of shape (n, m))."""
        col, sm = self.col, self._sum
        Aa2, Aa3, AE = col["A"] * col["a2"], col["A"] * col["a3"], col["A"] / (2 * col["E"])
        Qin, Qp, div = col["Qin"], self.Qp, self.divider
        idx = np.flatnonzero(free)

        def f(t, y):
            self.nfev += 1
            q, v, p, M, dM, Q, h, u, loss, acc = self._dynamics(y, free, idx)
            pdot, V, Qr = self._pdot(q, p, u)
            pp = p.max(axis=0) if div else p[0]
            uu = u * u
            P = [pp * Qp, sm(p * Qr), sm(uu * (Aa2 + Aa3 * np.abs(u))), sm(p * p * u * AE),
                 -sm(Q * v)]
            if div:
                P.append(sm((pp - p) * Qin))
            return np.concatenate([v, acc, pdot, P])
        return f

    def kinetic(self, y):
        """(½·q̇ᵀ·M·q̇, ½·Σ a1·A·q̇²) [J] at one state ``y``."""
        k = self.k
        M, _, _ = self.mech.mechanics(y[:k, None])
        v = y[k:2 * k]
        return 0.5 * float(v @ M[0] @ v), 0.5 * float(np.sum(self.a1 * self.A * v * v))

    def oil_energy(self, y):
        """U = Σ p²·V/(2E) [J] at one state ``y``."""
        k = self.k
        p = y[2 * k:3 * k]
        return float(np.sum(p * p * self.volume(y[:k, None])[:, 0] / (2 * self.E)))

    def impact(self, y, free, j):
        """Stop coordinate ``j`` by a plastic impact: the free coordinates' velocities
        change by the impulse on j through M + diag(a1·A). Returns the kinetic energy
        lost [J] (y is changed in place)."""
        k = self.k
        idx = np.flatnonzero(free)
        M, _, _ = self.mech.mechanics(y[:k, None])
        Mf = (M[0] + self.A1)[np.ix_(idx, idx)]
        v = y[k + idx].copy()
        e = (idx == j).astype(float)
        w = np.linalg.solve(Mf, e)
        v1 = v - w * v[idx == j][0] / w[idx == j][0]
        v1[idx == j] = 0.0
        y[k + idx] = v1
        return 0.5 * float(v @ Mf @ v - v1 @ Mf @ v1)

    def resting(self, y, free, j):
        """True when the stop under coordinate ``j`` (resting with the coordinates
        ``free`` moving) pushes it: R_j ≥ 0 on the lower stop, ≤ 0 on the upper."""
        R = self.terms(y[:, None], free)["R"][j, 0]
        return R >= 0 if self.on_lower(y, j) else R <= 0

    def on_lower(self, y, j):
        return abs(y[j] - self.lo[j]) <= abs(y[j] - self.hi[j])


def _start(s0, coords, branches):
    """The coordinates at t = 0 [m] (shape (k,))."""
    k = len(coords)
    q0 = np.array([b.stop for b in branches], float)
    if s0 is None:
        return q0
    if isinstance(s0, dict):
        bad = sorted(set(s0) - set(coords))
        if bad:
            raise ValueError(f"s0 names {bad}, not coordinates of the mechanism "
                             f"({list(coords)})")
        for c, v in s0.items():
            q0[coords.index(c)] = float(v)
        return q0
    a = np.atleast_1d(np.asarray(s0, float))
    if a.shape != (k,):
        raise ValueError(f"s0 must give {k} coordinate(s) {list(coords)}, got {s0!r}")
    return a.copy()


def _pressures(p0, mach, q0, coords):
    """The branches' pressures at t = 0 [Pa] (shape (k,))."""
    k = mach.k
    if isinstance(p0, str):
        if p0 != "hold":
            raise ValueError(f'p0 must be a pressure [Pa] or "hold", got {p0!r}')
        _, _, Q = mach.mech.mechanics(q0[:, None])
        p = -mach.sigma * Q[0] / mach.A
        for j in range(k):
            if p[j] < 0:
                if q0[j] not in (mach.lo[j], mach.hi[j]):
                    raise ModelError(f"drive: at {coords[j]} = {q0[j]:.6g} m the loads push "
                                     f"the rod in its fed sense ({-Q[0, j]:.6g} N): its chamber"
                                     f" cannot hold it (the drained side is not modelled)")
                p[j] = 0.0
        return p
    p = np.broadcast_to(np.asarray(p0, float), (k,)).copy() if np.ndim(p0) == 0 \
        else np.asarray(p0, float)
    if p.shape != (k,) or not (np.all(np.isfinite(p)) and np.all(p >= 0)):
        raise ValueError(f"p0 must be a finite pressure ≥ 0 [Pa] (or one per coordinate "
                         f"{list(coords)}), got {p0!r}")
    return p


def _events(mach, free, stroke):
    """The events of a phase and their (name, coordinate index)."""
    evs, what = [], []
    k = mach.k
    for j in range(k):
        if np.isfinite(mach.p_set[j]):
            def relief(t, y, j=j):
                return y[2 * k + j] - mach.p_set[j]
            relief.direction = 1
            evs.append(relief)
            what.append(("relief opens", j))
        if free[j]:
            def top(t, y, j=j):
                return y[j] - (mach.hi[j] + CONTACT * stroke[j])
            top.terminal, top.direction = True, 1

            def bottom(t, y, j=j):  # a piston just lifted off is not back on its stop
                return y[j] - (mach.lo[j] - CONTACT * stroke[j])
            bottom.terminal, bottom.direction = True, -1
            evs += [top, bottom]
            what += [("end of stroke", j), ("end of stroke", j)]
        else:
            fr = free.copy()

            def release(t, y, j=j, fr=fr):
                R = mach.terms(y[:, None], fr)["R"][j, 0]
                return -R if mach.on_lower(y, j) else R
            release.terminal, release.direction = True, 1
            evs.append(release)
            what.append(("lift-off", j))
    return evs, what
