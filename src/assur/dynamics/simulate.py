"""Simulation in time of a mechanism driven by a hydraulic circuit: seed 001 lab 6's
adapter lift (one cylinder) and seed 004's crane (boom and stick, two cylinders fed
by one pump through a flow divider).

The machine has k generalized coordinates, the cylinders' pin-to-pin lengths q_j
[m], each moved by one branch of the circuit (:class:`assur.dynamics.drive.Branch`: its
valve, lines, lumped oil volume and relief valve). Its mathematical model is lab
6's system (2), (3), (7) for every branch, with the turbulent term corrected
(BRIEF.md), coupled through the mechanism's equations of motion:

.. math::

    \\dot p_j &= \\frac{E_j}{V_j(q_j)}\\,(s_j Q_p - Q_{r,j}(p_j) - A_j u_j)
        && \\text{(2): flows at branch j's node}\\\\
    p_{2,j} &= p_j - (a_{1,j}\\dot u_j + a_{2,j} u_j + a_{3,j} u_j|u_j|)
        && \\text{(3): its line losses}\\\\
    M(q)\\,\\ddot q + h(q, \\dot q) &= Q(q) + F,\\quad F_j = \\sigma_j A_j p_{2,j}
        && \\text{(7), Lagrange}

with u_j = σ_j·q̇_j the rod's speed in the fed sense (σ = +1: the valve's
``raise``, the piston side fed; −1: ``lower``, the rod side), A_j the fed area,
V_j = V0_j + A_j·σ_j·(q_j − q0_j) (q0_j the stop where the fed chamber is
smallest), Q_p = q·n·η0 the pump's flow, s_j the flow divider's share (seed 004
eqs. 63–66; 1 for one cylinder), Q_r,j the relief valve's flow, and M(q), h(q, q̇),
Q(q) the mass matrix, velocity terms and generalized forces of the loads from the
engine's equations of motion (:mod:`assur.dynamics.eom`, exact analogs).
Substituting (3) into (7): ``(M + diag(a1·A))·q̈ = Q − h + σ·A·(p − a2·u − a3·u|u|)``.
For k = 1 this is lab 6: m(S)·S̈ + ½·m'(S)·Ṡ² = A·p2 + Q(S).

The divider is ideal: it delivers s_j·Q_p to each branch whatever the loads, so
the pump works at the highest branch pressure p_p = max_j p_j and the divider
throttles the others (its loss Σ (p_p − p_j)·s_j·Q_p).

How M, ∂M/∂q, Q enter: for one coordinate the mechanism is solved once at
``nodes`` evenly spaced lengths between the stops; m and its exact derivative m'
(from the second analogs) define a cubic Hermite interpolant whose derivative is
the m' the equation uses, Q a cubic Hermite through its exact values and spline
slopes (:class:`ReducedTable`). For k > 1 (or ``nodes=None``) the mechanism is
solved at the states themselves at every evaluation (:class:`ExactEquations`; the
solver's Jacobian columns in one batch). Either way h is built from the ∂M/∂q that
goes with M, so the kinetic energy ½·q̇ᵀ·M·q̇ is exactly consistent with (7) and
the energy balance closes to the integrator's tolerance.

End stops, per cylinder: a piston rests on a stop while the stop's reaction R_j
(the generalized force that keeps q̈_j = 0) pushes it there; a run starts with the
pistons on their stops resting where R_j does so, and a resting piston lifts off
when R_j reaches zero (event *lift-off*). A piston reaching a stop is stopped there
by a plastic impact on its coordinate (event *end of stroke*): the other
coordinates' velocities change by the impulse through M + diag(a1·A), and the
kinetic energy lost is recorded. *relief opens* is recorded when p_j reaches its
relief setting. Integration: :func:`scipy.integrate.solve_ivp` with a
stiff-capable method (``"Radau"`` by default; ``"BDF"``, ``"LSODA"``), restarted
at each terminal event.

Energy balance (each term integrated with the states, [J])::

    W_pump = W_relief + W_divider + W_line + W_impact + ΔT_mech + ΔT_line
             + W_loads + W_oil

W_pump = ∫p_p·Q_p dt; W_loads = −∫Q·q̇ dt (for weights: the rise of their
potential energy); W_oil = ΔU − Σ∫p_j²·A_j·u_j/(2E_j) dt, U = Σ p_j²·V_j/(2E_j)
the elastic energy of the lumped oil (the integral is the share of the pump's work
the lumped model hands to the new oil entering a growing volume: eq. (2) is linear
in p/E).

Not modelled: the drained side of a cylinder (an overrunning load — one that
pushes a rod in its fed sense — is held by nothing but the fed chamber, whose
pressure then falls below zero: start such a crane where its loads resist, or
from ``p0 = "hold"``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import ModelError
from .eom import equations_of_motion

__all__ = ["ReducedTable", "ExactEquations", "SimulationResult", "simulate",
           "simulate_model", "METHODS"]

#: stiff-capable methods of solve_ivp the simulation accepts
METHODS = ("Radau", "BDF", "LSODA")

#: how far past a stop (a fraction of the stroke) the piston is taken to hit it: a
#: piston that has just left a stop with zero speed and force may creep back by
#: rounding, which must not count as a new impact
CONTACT = 1e-9
#: a chamber pressure below −NEGATIVE [Pa] is reported in the result's message
NEGATIVE = 1e3
#: phase changes (lift-off, impact) after which a simulation is stopped as chattering
MAX_SWITCHES = 100

#: the energy integrals after the states q, q̇, p (module docstring); ``divider``
#: only with a flow divider
ENERGY_STATES = ("pump", "relief", "line", "lumped_volume", "loads", "divider")


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

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics import equations_of_motion
    >>> from assur.dynamics.simulate import ReducedTable
    >>> mech = io.load(io.bundled("adapter_lab6")).mechanism     # seed 001 lab 6
    >>> S = np.linspace(0.55, 0.8, 51)                            # nodes [m]
    >>> eom = equations_of_motion(mech, S)
    >>> m, dm = eom.reduced_mass()
    >>> table = ReducedTable(S, m, dm, eom.generalized_forces)
    >>> m_mid, dm_mid, Q_mid = table(0.6775)                      # between two nodes [m]
    >>> round(float(m_mid), 2), round(float(Q_mid), 2)            # m [kg], Q [N]
    (39358.64, -58977.48)
    >>> exact = equations_of_motion(mech, [0.6775])               # solved there
    >>> round(float(exact.reduced_mass()[0][0]), 2), round(float(exact.generalized_forces[0]), 2)
    (39358.64, -58977.48)
    """

    def __init__(self, S, m, dm, Q):
        from scipy.interpolate import CubicSpline
        self.S = np.asarray(S, dtype=float)
        self.h = float(self.S[1] - self.S[0])
        self.m, self.dm, self.Q = (np.asarray(a, dtype=float) for a in (m, dm, Q))
        self.dQ = CubicSpline(self.S, self.Q)(self.S, 1)

    @classmethod
    def from_mechanism(cls, mech, s_min, s_max, nodes=801, g=None):
        """Solve ``mech`` at ``nodes`` lengths on [s_min, s_max] and tabulate.

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics.simulate import ReducedTable
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism    # seed 001 lab 6
        >>> table = ReducedTable.from_mechanism(mech, 0.55, 0.8, nodes=51)   # stops [m]
        >>> table.S.size, round(table.h * 1e3, 6)                    # nodes, spacing [mm]
        (51, 5.0)
        >>> round(float(table.m[0]), 1)                              # m(S_min) [kg]
        51646.3
        """
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


    def mechanics(self, q):
        """M, ∂M/∂q and Q at the states' coordinates ``q`` (shape (1, m)) as arrays of
        shapes (m, 1, 1), (m, 1, 1, 1), (m, 1) [kg, kg/m, N].

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.simulate import ReducedTable
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism    # seed 001 lab 6
        >>> table = ReducedTable.from_mechanism(mech, 0.55, 0.8, nodes=51)
        >>> M, dM, Q = table.mechanics(np.array([[0.55, 0.675, 0.8]]))   # S [m]
        >>> M.shape, dM.shape, Q.shape
        ((3, 1, 1), (3, 1, 1, 1), (3, 1))
        >>> (M[:, 0, 0] / 1e3).round(3).tolist()      # m(S) at the nodes [t]
        [51.646, 39.313, 52.709]
        """
        if q.shape[1] == 1:  # the solver's hot path: one state, on Python floats
            m, dm, Q = self._scalar(float(q[0, 0]))
            return np.array([[[m]]]), np.array([[[[dm]]]]), np.array([[Q]])
        m, dm, Q = self(q[0])
        return m[:, None, None], dm[:, None, None, None], Q[:, None]

    def _scalar(self, s):
        """(m, dm/dS, Q) at one length, the same cubic Hermite as :meth:`__call__`."""
        if not hasattr(self, "_lists"):
            h = self.h
            self._lists = (self.m.tolist(), (self.dm * h).tolist(), self.Q.tolist(),
                           (self.dQ * h).tolist())
        mv, dmv, Qv, dQv = self._lists
        h = self.h
        x = (s - self.S[0]) / h
        i = min(max(int(x // 1), 0), self.S.size - 2)
        u = x - i
        u2 = u * u
        u3 = u2 * u
        h00, h10, h01, h11 = 2 * u3 - 3 * u2 + 1, u3 - 2 * u2 + u, 3 * u2 - 2 * u3, u3 - u2
        Q = h00 * Qv[i] + h10 * dQv[i] + h01 * Qv[i + 1] + h11 * dQv[i + 1]
        m = h00 * mv[i] + h10 * dmv[i] + h01 * mv[i + 1] + h11 * dmv[i + 1]
        dm = ((6 * u2 - 6 * u) * (mv[i] - mv[i + 1]) + (3 * u2 - 4 * u + 1) * dmv[i]
              + (3 * u2 - 2 * u) * dmv[i + 1]) / h
        return m, dm, Q


class ExactEquations:
    """M(q), ∂M/∂q and Q(q) of a mechanism of k coordinates evaluated exactly at the
    states (the engine solved there, :func:`assur.dynamics.equations_of_motion`).

    Parameters
    ----------
    mechanism : Mechanism
    g : float
        Gravity [m/s²].

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics.simulate import ExactEquations
    >>> exact = ExactEquations(io.load(io.bundled("adapter_lab6")).mechanism, g=9.81)
    >>> M, dM, Q = exact.mechanics(np.array([[0.675]]))    # S [m], one state
    >>> round(float(M[0, 0, 0]), 1), round(float(Q[0, 0]), 1)   # m [kg], Q [N]
    (39313.4, -58944.8)
    """

    def __init__(self, mechanism, g):
        self.mechanism = mechanism
        self.g = float(g)
        self.k = len(mechanism.coordinates)

    def mechanics(self, q):
        """M (m, k, k), ∂M/∂q (m, k, k, k) and Q (m, k) at the coordinates ``q``
        (shape (k, m)) [kg or kg·m², their derivatives, N or N·m].

        Raises
        ------
        AssemblyError
            A state where the mechanism does not assemble.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.simulate import ExactEquations
        >>> exact = ExactEquations(io.load(io.bundled("adapter_lab6")).mechanism, g=9.81)
        >>> M, dM, Q = exact.mechanics(np.array([[0.55, 0.8]]))   # two states, S [m]
        >>> (M[:, 0, 0] / 1e3).round(3).tolist(), (Q[:, 0] / 1e3).round(2).tolist()  # [t], [kN]
        ([51.646, 52.709], [-58.56, -59.05])
        >>> exact.mechanics(np.array([[2.0]]))   # far past the stroke [m]  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        assur.errors.AssemblyError: cylinder–lever group 'I (2,3)' (links 2, 3) cannot assemble at position 0 (S = 2): ...
        """
        k, m = self.k, q.shape[1]
        pos = q[0] if k == 1 else q.T
        eom = equations_of_motion(self.mechanism.solve(pos, check_continuity=False),
                                  g=self.g)
        return (eom.mass_matrix.reshape(m, k, k), eom.mass_matrix_derivative.reshape(m, k, k, k),
                np.reshape(eom.generalized_forces, (m, k)))


@dataclass
class SimulationResult:
    """The motion of the machine in time, in the manner of scipy's OdeResult.

    Arrays over the coordinates have shape (n,) for one coordinate and (n, k) for
    k > 1 (columns in the order of :attr:`coordinates`).

    Attributes
    ----------
    status : int
        0: reached ``t_end``; −1: the integration failed (``message`` says why).
    message : str
    success : bool
    t : ndarray, shape (n,)
        Times [s].
    q, qdot, qddot : ndarray
        q [m], q̇ [m/s], q̈ [m/s²].
    p1, p2 : ndarray
        Pressure at each branch's node and at its cylinder [Pa] (lab 6 fig. 6.3;
        eq. 3).
    p1dot : ndarray
        ṗ1 [Pa/s] (fig. 6.4).
    pump_pressure : ndarray, shape (n,)
        The pump's pressure max_j p1_j [Pa] (= p1 for one cylinder).
    flows : dict of ndarray
        ``pump`` (n,), and per branch ``relief``, ``cylinder`` (A·u), ``compression``
        (ṗ1·V/E) [m³/s].
    force : ndarray
        The cylinders' forces σ·A·p2 along the coordinates [N].
    load : ndarray
        The loads on the rods −Q(q) (lab 6: P6·I(S)) [N].
    reduced_mass, reduced_mass_derivative : ndarray
        m(S) [kg], m'(S) [kg/m]; for k > 1 the diagonal M_jj and ∂M_jj/∂q_j.
    mass_matrix : ndarray, shape (n, k, k)
        M(q) [kg].
    phase : ndarray of str
        ``"rest"`` or ``"moving"`` at each time (k > 1: shape (n, k)).
    events : dict of list of float
        Times of ``lift-off``, ``end of stroke``, ``relief opens`` [s] (every
        coordinate's).
    event_log : list of (float, str, str)
        (time [s], event, coordinate), in time order.
    energy : dict of float
        The balance's terms at the end [J] (module docstring) and ``residual``.
    nfev, njev, nlu : int
        Right-hand-side and Jacobian evaluations, LU decompositions (all phases).
    coordinates : tuple of str
    coordinate : str
        The first coordinate.
    steady_speed : float or ndarray
        s_j·Q_p/A_j along the coordinates [m/s] (lab 6: Q/A; seed 004 eqs. 65–66).

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics import simulate
    >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
    >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
    >>> r.status, r.message
    (0, 'reached t_end')
    >>> r.q.round(4).tolist()                   # S [m]
    [0.55, 0.5576, 0.5818]
    >>> [round(t, 3) for t in r.events["lift-off"]]   # [s]
    [0.083]
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
    coordinates: tuple
    steady_speed: object
    pump_pressure: np.ndarray = field(repr=False, default=None)
    mass_matrix: np.ndarray = field(repr=False, default=None)
    event_log: list = field(default_factory=list)
    states: np.ndarray = field(repr=False, default=None)

    @property
    def success(self) -> bool:
        """True unless the integration failed (``status`` ≥ 0).

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> r.success, r.status
        (True, 0)
        """
        return self.status >= 0

    @property
    def coordinate(self) -> str:
        """The first coordinate.

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> r.coordinate, r.coordinates
        ('S', ('S',))
        """
        return self.coordinates[0]

    @property
    def k(self) -> int:
        """The number of coordinates (cylinders) k.

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> r.k, r.q.shape                # one coordinate: arrays of shape (n,)
        (1, (3,))
        """
        return len(self.coordinates)

    def column(self, a, j):
        """The coordinate ``j``'s column of an array over the coordinates (the array
        itself for one coordinate).

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> (r.column(r.p1, 0) / 1e6).round(2).tolist()   # p1 of S [MPa]
        [0.0, 8.18, 3.07]
        """
        a = np.asarray(a)
        return a if self.k == 1 else a[:, j]

    def to_frame(self):
        """A pandas DataFrame of the time series (SI units, the seed's symbols; with
        k > 1 coordinates a branch's columns end with its coordinate).

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> df = r.to_frame()
        >>> df.shape, list(df.columns[:7])
        ((3, 15), ['t', 'S', 'dS', 'ddS', 'p1', 'p2', 'dp1'])
        >>> round(float(df["Q_pump"].iloc[0]) * 60e3, 2)   # [l/min]
        51.84
        """
        import pandas as pd
        cols = {"t": self.t}
        for j, c in enumerate(self.coordinates):
            sfx = "" if self.k == 1 else f"_{c}"
            col = lambda a: self.column(a, j)  # noqa: E731
            cols.update({c: col(self.q), f"d{c}": col(self.qdot), f"dd{c}": col(self.qddot),
                         f"p1{sfx}": col(self.p1), f"p2{sfx}": col(self.p2),
                         f"dp1{sfx}": col(self.p1dot), f"F{sfx}": col(self.force),
                         f"P_load{sfx}": col(self.load), f"m_red{sfx}": col(self.reduced_mass),
                         f"dm_red{sfx}": col(self.reduced_mass_derivative)})
            cols.update({f"Q_{name}{sfx}": col(v) for name, v in self.flows.items()
                         if name != "pump"})
        cols["Q_pump"] = self.flows["pump"]
        if self.k > 1:
            cols["p_pump"] = self.pump_pressure
        return pd.DataFrame(cols)


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


def simulate(mechanism, circuit, t_end, *, p0=0.0, s0=None, t_eval=None, nodes=801,
             method="Radau", rtol=1e-6, max_step=None, g=None):
    """Simulate the motion of a mechanism driven by a hydraulic circuit (lab 6's
    lift; seed 004's crane with a flow divider).

    Parameters
    ----------
    mechanism : Mechanism
        Its generalized coordinates are the cylinders' lengths [m], with masses
        (its ``mass`` loads) and any other loads.
    circuit : assur.dynamics.drive.Circuit
        The drive: a pump, and per cylinder its branch (valve, lines, oil volume,
        relief valve); a flow divider for several cylinders.
    t_end : float
        Duration [s].
    p0 : float, sequence of float or "hold"
        Pressure in each branch at t = 0 [Pa]; ``"hold"``: the pressure that holds
        each rod still against the loads, −σ_j·Q_j(q)/A_j (0 where the load pushes
        a rod into its stop).
    s0 : float, sequence or mapping of str to float, optional
        The coordinates at t = 0 [m] (default: each cylinder on the stop where its
        fed chamber is smallest: s_min when raising, s_max when lowering).
    t_eval : array_like, optional
        Output times [s] (default: 2001 evenly spaced over [0, t_end]).
    nodes : int or None
        Nodes of the m(S), Q(S) table of one coordinate (:class:`ReducedTable`);
        None: the equations of motion evaluated exactly at every state
        (:class:`ExactEquations`, always so for k > 1).
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
        A bad method, duration or starting point; a circuit whose cylinders do not
        move the mechanism's coordinates.
    ModelError
        A mechanism that does not assemble over the stroke or has no masses; a rod
        that ``p0 = "hold"`` cannot hold.

    Examples
    --------
    >>> from assur import io
    >>> model = io.load(io.bundled("adapter_lab6"))
    >>> r = simulate(model.mechanism, model.drive, 1.0, t_eval=[0.0, 0.5, 1.0])
    >>> r.status, r.coordinates, round(r.steady_speed, 4)
    (0, ('S',), 0.0704)
    """
    from scipy.integrate import solve_ivp
    if method not in METHODS:
        raise ValueError(f"method must be one of: {list(METHODS)}, got {method!r}")
    if not (np.isfinite(t_end) and t_end > 0):
        raise ValueError(f"t_end must be a finite time > 0 [s], got {t_end!r}")
    coords = tuple(mechanism.coordinates)
    if sorted(circuit.coordinates) != sorted(coords):
        raise ValueError(f"the drive's cylinders move {list(circuit.coordinates)}; the "
                         f"mechanism's coordinates are {list(coords)} (a cylinder on each "
                         f"coordinate is simulated)")
    if circuit.coordinates != coords:
        raise ValueError(f"the drive's cylinders ({list(circuit.coordinates)}) must follow "
                         f"the mechanism's coordinates {list(coords)} (the divider's shares "
                         f"follow the cylinders)")
    k = len(coords)
    if g is None:
        g = mechanism.g
    br = circuit.branches
    if k == 1 and nodes is not None:
        c = br[0].cylinder
        mech = ReducedTable.from_mechanism(mechanism, c.s_min, c.s_max, nodes, g)
    else:
        mech = ExactEquations(mechanism, g)
    mach = _Machine(mech, circuit, g)
    lo, hi = mach.lo, mach.hi
    q0 = _start(s0, coords, br)
    for j, c in enumerate(coords):
        if not lo[j] <= q0[j] <= hi[j]:
            raise ValueError(f"s0 = {q0[j]} m of {c!r} must lie between the stops {lo[j]} m "
                             f"and {hi[j]} m")
    t_eval = np.linspace(0.0, t_end, 2001) if t_eval is None else np.asarray(t_eval, float)
    if t_eval.ndim != 1 or not t_eval.size or not np.all(np.diff(t_eval) > 0) \
            or t_eval[0] < 0 or t_eval[-1] > t_end:
        raise ValueError(f"t_eval must be increasing times within [0, {t_end}] s")
    pinit = _pressures(p0, mach, q0, coords)
    max_step = t_end / 200 if max_step is None else max_step
    stroke = hi - lo
    speeds = np.abs(circuit.steady_speeds())
    W_scale = mach.Qp * max(float(np.max(np.abs(pinit))), 1e6) * t_end
    atol = np.concatenate([1e-9 * stroke, 1e-9 * speeds, np.full(k, 1e-3),
                           np.full(len(mach.energy_names), 1e-6 * W_scale)])

    y = np.concatenate([q0, np.zeros(k), pinit, np.zeros(len(mach.energy_names))])
    U0 = mach.oil_energy(y)
    at_stop = (q0 == lo) | (q0 == hi)
    free = ~at_stop
    for j in np.flatnonzero(at_stop):
        if not mach.resting(y, free, j):
            free[j] = True
    Tm0, Tl0 = mach.kinetic(y)
    events_log = {"lift-off": [], "end of stroke": [], "relief opens": []}
    log = []
    W_impact = 0.0
    chunks = []
    t = 0.0
    status, message = 0, "reached t_end"
    nfev = njev = nlu = 0
    switches = 0
    while t < t_end:
        if switches > MAX_SWITCHES:
            status, message = -1, (f"stopped at t = {t:.6g} s after {switches} lift-offs and "
                                   f"impacts: a piston chatters on a stop")
            break
        switches += 1
        evs, what = _events(mach, free, stroke)
        sol = solve_ivp(mach.rhs(free.copy()), (t, t_end), y, method=method, rtol=rtol,
                        atol=atol, max_step=max_step, events=evs, dense_output=True,
                        vectorized=True)
        nfev += sol.nfev
        njev += sol.njev
        nlu += sol.nlu
        t1 = float(sol.t[-1])
        sel = t_eval[(t_eval >= t) & ((t_eval < t1) | ((t_eval <= t1) & (t1 >= t_end)))]
        if sel.size:
            chunks.append((sol.sol(sel), free.copy()))
        for (name, j), te in zip(what, sol.t_events):
            for x in te:
                if x > t or t == 0.0:
                    events_log[name].append(float(x))
                    log.append((float(x), name, coords[j]))
        if sol.status < 0:
            status, message = -1, f"integration failed at t = {t1:.6g} s: {sol.message}"
            break
        y = sol.y[:, -1].copy()
        t = t1
        if sol.status == 1:  # a terminal event: switch phase
            fired = [(name, j) for (name, j), te in zip(what, sol.t_events)
                     if name != "relief opens" and len(te) and te[-1] == t1]
            name, j = fired[0]
            if name == "end of stroke":
                top = y[j] > 0.5 * (lo[j] + hi[j])
                y[j] = hi[j] if top else lo[j]
                W_impact += mach.impact(y, free, j)
                y[k + j] = 0.0
                free[j] = False
            else:
                free[j] = True
    if not chunks:
        raise ValueError("no output time inside the simulated interval")
    parts = [mach.terms(Y, fr) for Y, fr in chunks]
    d = {key: np.concatenate([p[key] for p in parts], axis=0 if key in ("M", "dM") else -1)
         for key in parts[0]}
    Y = np.concatenate([Y for Y, _ in chunks], axis=1)
    moving = np.concatenate([np.broadcast_to(fr[:, None], (k, Yc.shape[1]))
                             for Yc, fr in chunks], axis=1)
    tt = t_eval[:Y.shape[1]]
    Tm1, Tl1 = mach.kinetic(y)
    E = {name: float(y[3 * k + i]) for i, name in enumerate(mach.energy_names)}
    U1 = mach.oil_energy(y)
    energy = {"pump": E["pump"], "relief": E["relief"], "line": E["line"],
              "impact": W_impact, "mechanism_kinetic": Tm1 - Tm0,
              "line_kinetic": Tl1 - Tl0, "loads": E["loads"],
              "oil": U1 - U0 - E["lumped_volume"], "oil_elastic": U1 - U0,
              "lumped_volume": E["lumped_volume"], "divider": E.get("divider", 0.0)}
    energy["residual"] = energy["pump"] - sum(energy[n] for n in (
        "relief", "divider", "line", "impact", "mechanism_kinetic", "line_kinetic", "loads",
        "oil"))
    log.sort()
    P = Y[2 * k:3 * k]
    for j in np.flatnonzero(P.min(axis=1) < -NEGATIVE):
        i = int(np.argmin(P[j]))
        message += (f"; p1 of {coords[j]} falls to {P[j, i] / 1e6:.4g} MPa at t = {tt[i]:.4g} "
                    f"s: a load overruns the rod (its drained side is not modelled)")
    for v in events_log.values():
        v.sort()

    def out(a):  # (k, n) -> (n,) or (n, k)
        return a[0] if k == 1 else a.T
    M = d["M"]
    diag = np.arange(k)
    return SimulationResult(
        status=status, message=message, t=tt, q=out(Y[:k]), qdot=out(d["v"]),
        qddot=out(d["acc"]), p1=out(Y[2 * k:3 * k]), p2=out(d["p2"]), p1dot=out(d["pdot"]),
        flows={"pump": np.full(tt.shape, mach.Qp), "relief": out(d["Qr"]),
               "cylinder": out(d["Qc"]), "compression": out(d["Qcomp"])},
        force=out(d["F"]), load=out(-d["Q"]), reduced_mass=out(M[:, diag, diag].T),
        reduced_mass_derivative=out(d["dM"][:, diag, diag, diag].T),
        phase=out(np.where(moving, "moving", "rest")), events=events_log, energy=energy,
        nfev=nfev, njev=njev, nlu=nlu, coordinates=coords,
        steady_speed=float(circuit.steady_speeds()[0]) if k == 1
        else circuit.steady_speeds(), pump_pressure=d["pp"], mass_matrix=M, event_log=log,
        states=Y)


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
        if sim.start:
            options.setdefault("s0", dict(sim.start))
        options.setdefault("method", sim.method)
        options.setdefault("t_eval", np.linspace(0.0, options["t_end"], sim.outputs))
    if "t_end" not in options:
        raise ModelError(f"model {model.name!r}: give the duration ([simulation] duration, "
                         f"or t_end=…)")
    t_end = options.pop("t_end")
    return simulate(model.mechanism, model.drive, t_end, **options)
