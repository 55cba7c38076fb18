"""Simulation in time of a mechanism driven by a hydraulic circuit (seed 001 lab 6).

The machine (pump + lines + cylinder + mechanism) has one generalized coordinate,
the cylinders' pin-to-pin length S. Its mathematical model is lab 6's system
(2), (3), (7), with the turbulent term corrected (BRIEF.md):

.. math::

    \\dot p_1 &= \\frac{E_{pr}}{V_0 + A\\,(S - S_0)}\\,(Q_p - Q_r(p_1) - A\\dot S)
        && \\text{(2): flows at the lumped node}\\\\
    p_2 &= p_1 - (a_1\\ddot S + a_2\\dot S + a_3\\dot S|\\dot S|) && \\text{(3): line losses}\\\\
    m(S)\\,\\ddot S + \\tfrac12 m'(S)\\,\\dot S^2 &= A\\,p_2 + Q(S) && \\text{(7)}

with Q_p = q·n·η0 the pump's flow, Q_r the relief valve's, A the pressurised area
of the cylinders, m(S) the reduced mass and Q(S) the generalized force of the loads
(lab 6: −P6·I(S)), both from the engine's equations of motion
(:mod:`assur.dynamics.eom`). Substituting (3) into (7):
``(m + a1·A)·S̈ = A·(p1 − a2·Ṡ − a3·Ṡ|Ṡ|) − ½·m'·Ṡ² + Q``.

How m(S), m'(S), Q(S) enter: the mechanism is solved once at ``nodes`` evenly
spaced lengths between the cylinder's stops; m and its exact derivative m' (from
the second analogs) define a cubic Hermite interpolant whose derivative is the m'
the equation uses — so the kinetic energy ½·m·Ṡ² is exactly consistent with (7)
and the energy balance closes to the integrator's tolerance. Q is interpolated by
a cubic spline through its exact values.

End stops: the piston rests on a stop while the force pushes it into it (phase
``rest``); the simulation starts resting on ``s_min`` until A·p1 + Q(S) > 0
(event *lift-off*), and a piston reaching a stop is stopped there (event *end of
stroke*; its kinetic energy and the oil column's are lost in the impact, which
the energy balance records). *relief opens* is recorded when p1 reaches the
relief setting. Integration: :func:`scipy.integrate.solve_ivp` with a
stiff-capable method (``"Radau"`` by default; ``"BDF"``, ``"LSODA"``), restarted at
each terminal event.

Energy balance (each term integrated with the states, [J])::

    W_pump = W_relief + W_line + W_impact + ΔT_mech + ΔT_line + W_loads + W_oil

W_loads = −∫Q·Ṡ dt (for weights: the rise of their potential energy); W_oil =
ΔU − ∫p1²·A·Ṡ/(2E) dt, U = p1²·V/(2E) the elastic energy of the lumped oil (the
integral is the share of the pump's work the lumped model hands to the new oil
entering a growing volume: eq. (2) is linear in p/E).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import ModelError
from .eom import equations_of_motion

__all__ = ["ReducedTable", "SimulationResult", "simulate", "simulate_model", "METHODS"]

#: stiff-capable methods of solve_ivp the simulation accepts
METHODS = ("Radau", "BDF", "LSODA")

#: how far past a stop (a fraction of the stroke) the piston is taken to hit it: a
#: piston that has just left a stop with zero speed and force may creep back by
#: rounding, which must not count as a new impact
CONTACT = 1e-9
#: phase changes (lift-off, impact) after which a simulation is stopped as chattering
MAX_SWITCHES = 100

#: the state vector: S, Ṡ, p1, then the energy integrals W_pump, W_relief, W_line,
#: the lumped-volume term and W_loads (module docstring)


class ReducedTable:
    """m(S), m'(S) and Q(S) of a one-coordinate mechanism at evenly spaced nodes,
    interpolated (cubic Hermite for m with its exact m', cubic spline for Q).

    Parameters
    ----------
    S : ndarray, shape (n,)
        Evenly spaced nodes [m].
    m, dm : ndarray, shape (n,)
        Reduced mass [kg] and its exact derivative [kg/m] at the nodes.
    Q : ndarray, shape (n,)
        Generalized force of the loads [N] at the nodes.
    """

    def __init__(self, S, m, dm, Q):
        from scipy.interpolate import CubicSpline
        self.S = np.asarray(S, dtype=float)
        self.h = float(self.S[1] - self.S[0])
        self.m, self.dm, self.Q = (np.asarray(a, dtype=float) for a in (m, dm, Q))
        self.dQ = CubicSpline(self.S, self.Q)(self.S, 1)

    @classmethod
    def from_mechanism(cls, mech, s_min, s_max, nodes=801, g=None):
        """Solve ``mech`` at ``nodes`` lengths on [s_min, s_max] and tabulate."""
        S = np.linspace(s_min, s_max, int(nodes))
        eom = equations_of_motion(mech.solve(S), g=g)
        m, dm = eom.reduced_mass()
        return cls(S, m, dm, eom.generalized_forces)

    def _hermite(self, s, y, dy):
        n = self.S.size
        x = (np.asarray(s, dtype=float) - self.S[0]) / self.h
        i = np.clip(np.floor(x), 0, n - 2).astype(int)
        t = x - i
        t2, t3 = t * t, t * t * t
        y0, y1, d0, d1 = y[i], y[i + 1], dy[i] * self.h, dy[i + 1] * self.h
        val = (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * d0 + (3 * t2 - 2 * t3) * y1 \
            + (t3 - t2) * d1
        der = ((6 * t2 - 6 * t) * (y0 - y1) + (3 * t2 - 4 * t + 1) * d0
               + (3 * t2 - 2 * t) * d1) / self.h
        return val, der

    def __call__(self, s):
        """(m, dm/dS, Q) at the lengths ``s`` [kg, kg/m, N]."""
        m, dm = self._hermite(s, self.m, self.dm)
        Q, _ = self._hermite(s, self.Q, self.dQ)
        return m, dm, Q


@dataclass
class SimulationResult:
    """The motion of the machine in time, in the manner of scipy's OdeResult.

    Attributes
    ----------
    status : int
        0: reached ``t_end``; −1: the integration failed (``message`` says why).
    message : str
    success : bool
    t : ndarray, shape (n,)
        Times [s].
    q, qdot, qddot : ndarray, shape (n,)
        S [m], Ṡ [m/s], S̈ [m/s²].
    p1, p2 : ndarray
        Pressure at the pump and at the cylinder [Pa] (lab 6 figs. 6.3; eq. 3).
    p1dot : ndarray
        ṗ1 [Pa/s] (fig. 6.4).
    flows : dict of ndarray
        ``pump``, ``relief``, ``cylinder`` (A·Ṡ), ``compression`` (ṗ1·V/E) [m³/s].
    force : ndarray
        The cylinders' force A·p2 [N].
    load : ndarray
        The load on the rods −Q(S) (lab 6: P6·I(S)) [N].
    reduced_mass, reduced_mass_derivative : ndarray
        m(S) [kg], m'(S) [kg/m].
    phase : ndarray of str
        ``"rest"`` or ``"moving"`` at each time.
    events : dict of list of float
        Times of ``lift-off``, ``end of stroke``, ``relief opens`` [s].
    energy : dict of float
        The balance's terms at the end [J] (module docstring) and ``residual``.
    nfev, njev, nlu : int
        Right-hand-side and Jacobian evaluations, LU decompositions (all phases).
    coordinate : str
    steady_speed : float
        Q_p/A [m/s].
    """

    status: int
    message: str
    t: np.ndarray
    q: np.ndarray
    qdot: np.ndarray
    qddot: np.ndarray
    p1: np.ndarray
    p2: np.ndarray
    p1dot: np.ndarray
    flows: dict
    force: np.ndarray
    load: np.ndarray
    reduced_mass: np.ndarray
    reduced_mass_derivative: np.ndarray
    phase: np.ndarray
    events: dict
    energy: dict
    nfev: int
    njev: int
    nlu: int
    coordinate: str
    steady_speed: float
    states: np.ndarray = field(repr=False, default=None)

    @property
    def success(self) -> bool:
        return self.status >= 0

    def to_frame(self):
        """A pandas DataFrame of the time series (SI units, the seed's symbols)."""
        import pandas as pd
        c = self.coordinate
        cols = {"t": self.t, c: self.q, f"d{c}": self.qdot, f"dd{c}": self.qddot,
                "p1": self.p1, "p2": self.p2, "dp1": self.p1dot, "F": self.force,
                "P_load": self.load, "m_red": self.reduced_mass,
                "dm_red": self.reduced_mass_derivative}
        cols.update({f"Q_{k}": v for k, v in self.flows.items()})
        return pd.DataFrame(cols)


class _Machine:
    """Right-hand side of the system, vectorised over states (columns)."""

    def __init__(self, table, circuit, s0):
        self.table = table
        self.A = circuit.area
        self.a1, self.a2, self.a3 = circuit.loss_coefficients()
        self.E = circuit.volume.bulk_modulus
        self.V0 = circuit.volume.volume
        self.s0 = s0
        self.Qp = circuit.pump_flow()
        self.circuit = circuit
        self.nfev = 0

    def volume(self, s):
        return self.V0 + self.A * (s - self.s0)

    def terms(self, y, moving):
        """Every derived quantity at the states ``y`` (shape (8,) or (8, n))."""
        s, v, p = y[0], y[1], y[2]
        A, E = self.A, self.E
        m, dm, Q = self.table(s)
        V = self.volume(s)
        if np.any(V <= 0):
            raise ModelError(f"drive: the lumped oil volume V0 + A·(S − S0) is not positive "
                             f"at S = {float(np.min(s)):.6g} m (V0 = {self.V0:.6g} m³)")
        Qr = self.circuit.relief_flow(p)
        if moving:
            loss = self.a2 * v + self.a3 * v * np.abs(v)
            acc = (A * (p - loss) - 0.5 * dm * v * v + Q) / (m + self.a1 * A)
            p2 = p - self.a1 * acc - loss
        else:
            v = 0.0 * v
            loss = 0.0 * v
            acc = 0.0 * v
            p2 = p
        Qc = A * v
        pdot = E * (self.Qp - Qr - Qc) / V
        return dict(s=s, v=v, p=p, acc=acc, p2=p2, pdot=pdot, m=m, dm=dm, Q=Q, V=V,
                    Qr=Qr, Qc=Qc, Qcomp=pdot * V / E,
                    P_pump=p * self.Qp, P_relief=p * Qr,
                    P_line=A * (self.a2 * v * v + self.a3 * v * v * np.abs(v)),
                    P_lump=p * p * A * v / (2 * E), P_loads=-Q * v)

    def rhs(self, moving):
        """f(t, y) for solve_ivp: the same equations as :meth:`terms` on Python floats
        (one state at a time, the solver's hot path)."""
        tab = self.table
        S0, h, last = float(tab.S[0]), tab.h, tab.S.size - 2
        mv, dmv = tab.m.tolist(), (tab.dm * h).tolist()
        Qv, dQv = tab.Q.tolist(), (tab.dQ * h).tolist()
        A, E, V0, s0, Qp = self.A, self.E, self.V0, self.s0, self.Qp
        a1, a2, a3 = self.a1, self.a2, self.a3
        rv = self.circuit.relief
        if rv is not None:
            p_set = rv.setting
            g_r = rv.conductance(Qp)
        A1 = a1 * A

        def f(t, y):
            self.nfev += 1
            s, v, p = float(y[0]), float(y[1]), float(y[2])
            x = (s - S0) / h
            i = min(max(int(x // 1), 0), last)
            u = x - i
            u2 = u * u
            u3 = u2 * u
            h00, h10, h01, h11 = 2 * u3 - 3 * u2 + 1, u3 - 2 * u2 + u, 3 * u2 - 2 * u3, u3 - u2
            Q = h00 * Qv[i] + h10 * dQv[i] + h01 * Qv[i + 1] + h11 * dQv[i + 1]
            Qr = g_r * (p - p_set) if rv is not None and p > p_set else 0.0
            V = V0 + A * (s - s0)
            if moving:
                m = h00 * mv[i] + h10 * dmv[i] + h01 * mv[i + 1] + h11 * dmv[i + 1]
                dm = ((6 * u2 - 6 * u) * (mv[i] - mv[i + 1]) + (3 * u2 - 4 * u + 1) * dmv[i]
                      + (3 * u2 - 2 * u) * dmv[i + 1]) / h
                loss = a2 * v + a3 * v * abs(v)
                acc = (A * (p - loss) - 0.5 * dm * v * v + Q) / (m + A1)
                P_line = A * (a2 * v * v + a3 * v * v * abs(v))
            else:
                v = acc = P_line = 0.0
            return [v, acc, E * (Qp - Qr - A * v) / V, p * Qp, p * Qr, P_line,
                    p * p * A * v / (2 * E), -Q * v]
        return f

    def kinetic(self, y):
        """(½·m·Ṡ², ½·a1·A·Ṡ²) [J]."""
        m, _, _ = self.table(y[0])
        return 0.5 * m * y[1] ** 2, 0.5 * self.a1 * self.A * y[1] ** 2

    def oil_energy(self, y):
        """U = p1²·V/(2E) [J]."""
        return y[2] ** 2 * self.volume(y[0]) / (2 * self.E)


def simulate(mechanism, circuit, t_end, *, p0=0.0, s0=None, t_eval=None, nodes=801,
             method="Radau", rtol=1e-6, max_step=None, g=None):
    """Simulate the lift of a mechanism by a hydraulic circuit (lab 6).

    Parameters
    ----------
    mechanism : Mechanism
        One generalized coordinate, the cylinders' length S, with masses (its
        ``mass`` loads) and any other loads.
    circuit : assur.drive.Circuit
        The drive (pump, relief valve, valve, lines, oil volume, cylinder).
    t_end : float
        Duration [s].
    p0 : float
        Pressure in the line at t = 0 [Pa].
    s0 : float, optional
        S at t = 0 [m] (default: the lower stop ``s_min``, where V = V0).
    t_eval : array_like, optional
        Output times [s] (default: 2001 evenly spaced over [0, t_end]).
    nodes : int
        Nodes of the m(S), Q(S) table (:class:`ReducedTable`).
    method : {"Radau", "BDF", "LSODA"}
    rtol : float
        Relative tolerance of solve_ivp (absolute ones: 1e-9·stroke, 1e-9·speed,
        1e-3 Pa and 1e-6·(pump power × t_end) for the energy integrals).
    max_step : float, optional
        Largest step [s] (default t_end/200, so a start-up oscillation is resolved).
    g : float, optional
        Gravity [m/s²] (default: the mechanism's).

    Returns
    -------
    SimulationResult
        A failed integration is returned (``status = −1``) with what was computed.

    Raises
    ------
    ValueError
        A bad method, duration or starting point; a circuit on another coordinate.
    ModelError
        A mechanism that does not assemble over the stroke or has no masses.
    """
    from scipy.integrate import solve_ivp
    if method not in METHODS:
        raise ValueError(f"method must be one of: {list(METHODS)}, got {method!r}")
    if not (np.isfinite(t_end) and t_end > 0):
        raise ValueError(f"t_end must be a finite time > 0 [s], got {t_end!r}")
    cyl = circuit.cylinder
    coords = mechanism.coordinates
    if len(coords) != 1 or cyl.coordinate != coords[0]:
        raise ValueError(f"the drive's cylinder moves {cyl.coordinate!r}; the mechanism's "
                         f"coordinates are {list(coords)} (one cylinder coordinate is "
                         f"simulated)")
    s_min, s_max = cyl.s_min, cyl.s_max
    s0 = s_min if s0 is None else float(s0)
    if not s_min <= s0 <= s_max:
        raise ValueError(f"s0 = {s0} m must lie between the stops {s_min} m and {s_max} m")
    if g is None:
        from ..analysis import gravity_of
        g = gravity_of(mechanism)
    table = ReducedTable.from_mechanism(mechanism, s_min, s_max, nodes, g)
    mach = _Machine(table, circuit, s_min)
    t_eval = np.linspace(0.0, t_end, 2001) if t_eval is None else np.asarray(t_eval, float)
    if t_eval.ndim != 1 or not t_eval.size or not np.all(np.diff(t_eval) > 0) \
            or t_eval[0] < 0 or t_eval[-1] > t_end:
        raise ValueError(f"t_eval must be increasing times within [0, {t_end}] s")
    if not (np.isfinite(p0) and p0 >= 0):
        raise ValueError(f"p0 must be a finite pressure ≥ 0 [Pa], got {p0!r}")
    max_step = t_end / 200 if max_step is None else max_step
    stroke = s_max - s_min
    W_scale = mach.Qp * max(abs(p0), 1e6) * t_end
    atol = np.array([1e-9 * stroke, 1e-9 * circuit.steady_speed(), 1e-3]
                    + [1e-6 * W_scale] * 5)

    y = np.array([s0, 0.0, float(p0), 0, 0, 0, 0, 0], dtype=float)
    d0 = mach.terms(y, False)
    U0 = mach.oil_energy(y)
    at_stop = s0 in (s_min, s_max)
    moving = not (at_stop and _pushes_into_stop(mach, y, s0 == s_max, d0))
    rv = circuit.relief
    events_log = {"lift-off": [], "end of stroke": [], "relief opens": []}
    W_impact = 0.0
    chunks = []
    t = 0.0
    status, message = 0, "reached t_end"
    nfev = njev = nlu = 0
    switches = 0
    while t < t_end:
        if switches > MAX_SWITCHES:
            status, message = -1, (f"stopped at t = {t:.6g} s after {switches} lift-offs and "
                                   f"impacts: the piston chatters on a stop")
            break
        switches += 1
        evs, names = [], []
        if rv is not None:
            def relief(tt, yy):
                return yy[2] - rv.setting
            relief.direction = 1
            evs.append(relief)
            names.append("relief opens")
        if moving:
            def top(tt, yy):
                return yy[0] - (s_max + CONTACT * stroke)
            top.terminal, top.direction = True, 1

            def bottom(tt, yy):  # a piston just lifted off is not back on its stop
                return yy[0] - (s_min - CONTACT * stroke)
            bottom.terminal, bottom.direction = True, -1
            evs += [top, bottom]
            names += ["end of stroke", "end of stroke"]
        else:
            top_stop = abs(y[0] - s_max) <= abs(y[0] - s_min)

            def release(tt, yy, top_stop=top_stop):
                d = mach.terms(yy, False)
                F = mach.A * d["p"] + d["Q"]
                return -F if top_stop else F
            release.terminal, release.direction = True, 1
            evs.append(release)
            names.append("lift-off")
        sol = solve_ivp(mach.rhs(moving), (t, t_end), y, method=method, rtol=rtol, atol=atol,
                        max_step=max_step, events=evs, dense_output=True)
        nfev += sol.nfev
        njev += sol.njev
        nlu += sol.nlu
        t1 = float(sol.t[-1])
        sel = t_eval[(t_eval >= t) & ((t_eval < t1) | ((t_eval <= t1) & (t1 >= t_end)))]
        if sel.size:
            chunks.append((sol.sol(sel), moving))
        for name, te in zip(names, sol.t_events):
            events_log[name] += [float(x) for x in te if x > t or t == 0.0]
        if sol.status < 0:
            status, message = -1, f"integration failed at t = {t1:.6g} s: {sol.message}"
            break
        y = sol.y[:, -1].copy()
        t = t1
        if sol.status == 1:  # a terminal event: switch phase
            if moving:
                hit_top = len(sol.t_events[names.index("end of stroke")]) > 0
                y[0] = s_max if hit_top else s_min
                W_impact += sum(mach.kinetic(y))
                y[1] = 0.0
                moving = False
            else:
                moving = True
    if not chunks:
        raise ValueError("no output time inside the simulated interval")
    Y = np.concatenate([c for c, _ in chunks], axis=1)
    mov = np.concatenate([np.full(c.shape[1], mv) for c, mv in chunks])
    d_m = mach.terms(Y, True)
    d_r = mach.terms(Y, False)
    d = {k: np.where(mov, d_m[k], d_r[k]) for k in d_m}
    tt = t_eval[:Y.shape[1]]
    yf = y
    Tm1, Tl1 = mach.kinetic(yf)
    Tm0, Tl0 = mach.kinetic(np.array([s0, 0.0, p0]))
    energy = {"pump": float(yf[3]), "relief": float(yf[4]), "line": float(yf[5]),
              "impact": W_impact, "mechanism_kinetic": float(Tm1 - Tm0),
              "line_kinetic": float(Tl1 - Tl0), "loads": float(yf[7]),
              "oil": float(mach.oil_energy(yf) - U0 - yf[6]),
              "oil_elastic": float(mach.oil_energy(yf) - U0), "lumped_volume": float(yf[6])}
    energy["residual"] = energy["pump"] - (energy["relief"] + energy["line"] + energy["impact"]
                                           + energy["mechanism_kinetic"]
                                           + energy["line_kinetic"] + energy["loads"]
                                           + energy["oil"])
    return SimulationResult(
        status=status, message=message, t=tt, q=Y[0], qdot=d["v"], qddot=d["acc"],
        p1=Y[2], p2=d["p2"], p1dot=d["pdot"],
        flows={"pump": np.full(tt.shape, mach.Qp), "relief": d["Qr"], "cylinder": d["Qc"],
               "compression": d["Qcomp"]},
        force=mach.A * d["p2"], load=-d["Q"], reduced_mass=d["m"],
        reduced_mass_derivative=d["dm"], phase=np.where(mov, "moving", "rest"),
        events=events_log, energy=energy, nfev=nfev, njev=njev, nlu=nlu,
        coordinate=coords[0], steady_speed=circuit.steady_speed(), states=Y)


def _pushes_into_stop(mach, y, top, d):
    """True when the force on the rods pushes the piston into its stop."""
    F = mach.A * d["p"] + d["Q"]
    return F >= 0 if top else F <= 0


def simulate_model(model, **options):
    """:func:`simulate` of a loaded model file: its mechanism, its ``[[drive]]``
    circuit and its ``[simulation]`` section (duration, p0, method, outputs);
    ``options`` override them (``t_end``, ``p0``, ``method``, ``t_eval``, …).

    Raises
    ------
    ModelError
        The model has no ``[[drive]]`` or no duration.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics import simulate_model
    >>> r = simulate_model(io.load(io.bundled("adapter_lab6")))   # seed 001 lab 6
    >>> round(r.steady_speed, 4)                  # Q/A [m/s], the lab's 0.0704
    0.0704
    >>> round(r.events["lift-off"][0], 3)         # [s]
    0.083
    """
    if model.drive is None:
        raise ModelError(f"model {model.name!r} has no hydraulic drive: add [[drive]] entries "
                         f"(docs/simulation.md)")
    sim = model.simulation
    if sim is not None:
        options.setdefault("t_end", sim.duration)
        options.setdefault("p0", sim.p0)
        options.setdefault("method", sim.method)
        options.setdefault("t_eval", np.linspace(0.0, options["t_end"], sim.outputs))
    if "t_end" not in options:
        raise ModelError(f"model {model.name!r}: give the duration ([simulation] duration, "
                         f"or t_end=…)")
    t_end = options.pop("t_end")
    return simulate(model.mechanism, model.drive, t_end, **options)
