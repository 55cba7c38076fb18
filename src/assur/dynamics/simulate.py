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

import numpy as np

from ..errors import ModelError
from ._sim_equations import ExactEquations, ReducedTable
from ._sim_machine import _events, _Machine, _pressures, _start
from ._sim_result import SimulationResult
# the constants of the right-hand side, importable from here as before the split
from ._sim_machine import CONTACT, ENERGY_STATES

__all__ = ["ReducedTable", "ExactEquations", "SimulationResult", "simulate",
           "simulate_model", "METHODS"]

#: stiff-capable methods of solve_ivp the simulation accepts
METHODS = ("Radau", "BDF", "LSODA")

#: a chamber pressure below −NEGATIVE [Pa] is reported in the result's message
NEGATIVE = 1e3
#: phase changes (lift-off, impact) after which a simulation is stopped as chattering
MAX_SWITCHES = 100


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
    coords = _checked(mechanism, circuit, t_end, method)
    k = len(coords)
    if g is None:
        g = mechanism.g
    mach = _Machine(_equations(mechanism, circuit, nodes, g), circuit, g)
    q0 = _start(s0, coords, circuit.branches)
    for j, c in enumerate(coords):
        if not mach.lo[j] <= q0[j] <= mach.hi[j]:
            raise ValueError(f"s0 = {q0[j]} m of {c!r} must lie between the stops "
                             f"{mach.lo[j]} m and {mach.hi[j]} m")
    t_eval = _output_times(t_eval, t_end)
    check_outputs_memory(k, t_eval.size)
    pinit = _pressures(p0, mach, q0, coords)
    max_step = t_end / 200 if max_step is None else max_step
    stroke = mach.hi - mach.lo
    atol = _tolerances(mach, circuit, pinit, t_end, stroke)
    y = np.concatenate([q0, np.zeros(k), pinit, np.zeros(len(mach.energy_names))])
    U0 = mach.oil_energy(y)
    free = _free_at_start(mach, y, q0)
    Tm0, Tl0 = mach.kinetic(y)
    run = _Run(mach, coords, stroke, y, free)
    run.integrate(t_end, t_eval, dict(method=method, rtol=rtol, atol=atol, max_step=max_step))
    return _result(mach, circuit, run, t_eval, (Tm0, Tl0, U0))


def check_outputs_memory(k, outputs) -> None:
    """Refuse a simulation of ``k`` coordinates whose ``outputs`` output times would
    need more than :func:`assur.core.inputs.max_memory`: at every output time the
    states, the rates, pressures, flows and forces of every coordinate and the mass
    matrix with its derivative, held twice (the phases' parts and the result).

    Raises
    ------
    ModelError
        Naming ``[simulation] outputs`` (or ``t_eval``), the estimate and the limit.

    Examples
    --------
    >>> import os
    >>> from unittest import mock
    >>> from assur.dynamics.simulate import check_outputs_memory
    >>> check_outputs_memory(1, 2001)  # fine
    >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "1 MiB"}):
    ...     check_outputs_memory(2, 10**6)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: simulation: 1e+06 output times would need about 1.27 GiB of memory (limit 1 MiB; set ASSUR_MAX_MEMORY to change it, or reduce [simulation] outputs (or t_eval))
    """
    from ..core.inputs import check_memory
    per = 16 * (24 * k + 3 * k * k + k ** 3 + len(ENERGY_STATES) + 8) + 24 * k
    check_memory(float(outputs), per, "simulation", unit="output times",
                 reduce="[simulation] outputs (or t_eval)")


def _checked(mechanism, circuit, t_end, method):
    """The mechanism's coordinates, checked against the method, the duration and the
    drive's cylinders (:func:`simulate`)."""
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
    return coords


def _equations(mechanism, circuit, nodes, g):
    """M, ∂M/∂q and Q: a :class:`ReducedTable` over the stroke of one coordinate, else
    :class:`ExactEquations`."""
    if len(circuit.branches) == 1 and nodes is not None:
        c = circuit.branches[0].cylinder
        return ReducedTable.from_mechanism(mechanism, c.s_min, c.s_max, nodes, g)
    return ExactEquations(mechanism, g)


def _output_times(t_eval, t_end):
    """The output times [s]: 2001 over [0, t_end] by default, else checked."""
    t_eval = np.linspace(0.0, t_end, 2001) if t_eval is None else np.asarray(t_eval, float)
    if t_eval.ndim != 1 or not t_eval.size or not np.all(np.diff(t_eval) > 0) \
            or t_eval[0] < 0 or t_eval[-1] > t_end:
        raise ValueError(f"t_eval must be increasing times within [0, {t_end}] s")
    return t_eval


def _tolerances(mach, circuit, pinit, t_end, stroke):
    """solve_ivp's absolute tolerances of the states: 1e-9·stroke, 1e-9·speed, 1e-3 Pa
    and 1e-6·(pump power × t_end) for the energy integrals."""
    k = mach.k
    speeds = np.abs(circuit.steady_speeds())
    W_scale = mach.Qp * max(float(np.max(np.abs(pinit))), 1e6) * t_end
    return np.concatenate([1e-9 * stroke, 1e-9 * speeds, np.full(k, 1e-3),
                           np.full(len(mach.energy_names), 1e-6 * W_scale)])


def _free_at_start(mach, y, q0):
    """Which coordinates move at t = 0: those off their stops, and those whose stop
    does not push them there."""
    at_stop = (q0 == mach.lo) | (q0 == mach.hi)
    free = ~at_stop
    for j in np.flatnonzero(at_stop):
        if not mach.resting(y, free, j):
            free[j] = True
    return free


class _Run:
    """One simulation's phases: solve_ivp from a phase change (a lift-off, an end of
    stroke) to the next, the states at the output times, the events and the counts."""

    def __init__(self, mach, coords, stroke, y, free):
        self.mach, self.coords, self.stroke = mach, coords, stroke
        self.y, self.free = y, free
        self.events = {"lift-off": [], "end of stroke": [], "relief opens": []}
        self.log = []
        self.W_impact = 0.0
        self.chunks = []
        self.status, self.message = 0, "reached t_end"
        self.nfev = self.njev = self.nlu = 0

    def integrate(self, t_end, t_eval, options):
        """Integrate to ``t_end`` (or a failure, or chattering); ``options`` of
        solve_ivp (method, rtol, atol, max_step)."""
        from scipy.integrate import solve_ivp
        mach, free = self.mach, self.free
        t = 0.0
        switches = 0
        while t < t_end:
            if switches > MAX_SWITCHES:
                self.status, self.message = -1, (f"stopped at t = {t:.6g} s after {switches} "
                                                 f"lift-offs and impacts: a piston chatters "
                                                 f"on a stop")
                break
            switches += 1
            evs, what = _events(mach, free, self.stroke)
            sol = solve_ivp(mach.rhs(free.copy()), (t, t_end), self.y, **options, events=evs,
                            dense_output=True, vectorized=True)
            self.nfev += sol.nfev
            self.njev += sol.njev
            self.nlu += sol.nlu
            t1 = float(sol.t[-1])
            self._record(sol, what, t, t1, t_eval, t_end)
            if sol.status < 0:
                self.status, self.message = -1, (f"integration failed at t = {t1:.6g} s: "
                                                 f"{sol.message}")
                break
            self.y = sol.y[:, -1].copy()
            t = t1
            if sol.status == 1:  # a terminal event: switch phase
                self._switch(sol, what, t1)

    def _record(self, sol, what, t, t1, t_eval, t_end):
        """The states at the output times of this phase, and its events."""
        sel = t_eval[(t_eval >= t) & ((t_eval < t1) | ((t_eval <= t1) & (t1 >= t_end)))]
        if sel.size:
            self.chunks.append((sol.sol(sel), self.free.copy()))
        for (name, j), te in zip(what, sol.t_events):
            for x in te:
                if x > t or t == 0.0:
                    self.events[name].append(float(x))
                    self.log.append((float(x), name, self.coords[j]))

    def _switch(self, sol, what, t1):
        """The phase change of the terminal event at ``t1``: an end of stroke stops its
        piston by a plastic impact; a lift-off frees it."""
        y, free, k = self.y, self.free, self.mach.k
        fired = [(name, j) for (name, j), te in zip(what, sol.t_events)
                 if name != "relief opens" and len(te) and te[-1] == t1]
        name, j = fired[0]
        if name == "end of stroke":
            lo, hi = self.mach.lo, self.mach.hi
            top = y[j] > 0.5 * (lo[j] + hi[j])
            y[j] = hi[j] if top else lo[j]
            self.W_impact += self.mach.impact(y, free, j)
            y[k + j] = 0.0
            free[j] = False
        else:
            free[j] = True


def _energy(mach, y, W_impact, Tm0, Tl0, U0):
    """The energy balance's terms at the end [J] and its residual (module docstring)."""
    k = mach.k
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
    return energy


def _overrun(message, Y, coords, tt):
    """``message`` with a note for each branch whose pressure falls below −NEGATIVE."""
    k = len(coords)
    P = Y[2 * k:3 * k]
    for j in np.flatnonzero(P.min(axis=1) < -NEGATIVE):
        i = int(np.argmin(P[j]))
        message += (f"; p1 of {coords[j]} falls to {P[j, i] / 1e6:.4g} MPa at t = {tt[i]:.4g} "
                    f"s: a load overruns the rod (its drained side is not modelled)")
    return message


def _result(mach, circuit, run, t_eval, start):
    """The :class:`SimulationResult` of a run; ``start``: the kinetic energies of the
    mechanism and the lines and the oil's elastic energy at t = 0 [J]."""
    k, coords = mach.k, run.coords
    if not run.chunks:
        raise ValueError("no output time inside the simulated interval")
    parts = [mach.terms(Y, fr) for Y, fr in run.chunks]
    d = {key: np.concatenate([p[key] for p in parts], axis=0 if key in ("M", "dM") else -1)
         for key in parts[0]}
    Y = np.concatenate([Y for Y, _ in run.chunks], axis=1)
    moving = np.concatenate([np.broadcast_to(fr[:, None], (k, Yc.shape[1]))
                             for Yc, fr in run.chunks], axis=1)
    tt = t_eval[:Y.shape[1]]
    energy = _energy(mach, run.y, run.W_impact, *start)
    run.log.sort()
    message = _overrun(run.message, Y, coords, tt)
    for v in run.events.values():
        v.sort()

    def out(a):  # (k, n) -> (n,) or (n, k)
        return a[0] if k == 1 else a.T
    M = d["M"]
    diag = np.arange(k)
    return SimulationResult(
        status=run.status, message=message, t=tt, q=out(Y[:k]), qdot=out(d["v"]),
        qddot=out(d["acc"]), p1=out(Y[2 * k:3 * k]), p2=out(d["p2"]), p1dot=out(d["pdot"]),
        flows={"pump": np.full(tt.shape, mach.Qp), "relief": out(d["Qr"]),
               "cylinder": out(d["Qc"]), "compression": out(d["Qcomp"])},
        force=out(d["F"]), load=out(-d["Q"]), reduced_mass=out(M[:, diag, diag].T),
        reduced_mass_derivative=out(d["dM"][:, diag, diag, diag].T),
        phase=out(np.where(moving, "moving", "rest")), events=run.events, energy=energy,
        nfev=run.nfev, njev=run.njev, nlu=run.nlu, coordinates=coords,
        steady_speed=float(circuit.steady_speeds()[0]) if k == 1
        else circuit.steady_speeds(), pump_pressure=d["pp"], mass_matrix=M,
        event_log=run.log, states=Y)


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
