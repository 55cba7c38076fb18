"""Work cycles of a machine driven by cylinders at constant rod speeds, and the
cylinder forces along them (seed 004: combined vs separate motion of a forestry
manipulator's boom and stick, eqs. 45, 60–62).

A cycle moves every coordinate q_j (a cylinder length) from ``start[j]`` to
``end[j]`` in segments; within a segment the rods move at constant speeds, so
q̈ = 0 and the forces the cylinders must supply are (:mod:`assur.dynamics.eom`)

    F(q, q̇) = h(q, q̇) − Q(q)          (static part F_s = −Q, dynamic part F_d = h)

— the paper's assumption (rigid hydraulics, constant V1, V2: "possible with two
circuits"); the jumps of speed at the segments' ends are not resolved.

Scenarios (cycle time T_c, strokes ΔS_j = |end_j − start_j|):

=====================  ====================================================  =========
scenario               speeds                                                eq.
=====================  ====================================================  =========
``combined_equal``     V1 = V2 = min_j ΔS_j/T_c, both from the start; the    (60)
                       longer stroke ends later
``combined_ideal``     V_j = ΔS_j/T_c: both start and end together           (61)
``separate_second``    V = ΣΔS_j/T_c, the second coordinate (the stick)      (62) a
                       first, then the first (the boom)
``separate_first``     V = ΣΔS_j/T_c, the first coordinate first             (62) b
=====================  ====================================================  =========

With constant speeds every dynamic term scales as 1/T_c² (h is quadratic in q̇),
so F_d·T_c² and any ratio of dynamic parts do not depend on T_c (BRIEF.md).

A cylinder is fed on one side: the chamber the valve feeds for the stroke's
direction (extending: the piston side; retracting: the rod side). The force *in the
fed direction* (:func:`fed_force`) is the part of F that this chamber must
produce; a force against it (a push on a retracting rod, e.g. the braking of the
stick at t = 0) is held by the drained side, which the paper's model does not feed
(seed 004: "усилие в штоковой полости гидроцилиндра привода рукояти", the stick's
force in its rod-side chamber, after eq. 68).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .eom import equations_of_motion

__all__ = ["SCENARIOS", "PERIODS", "Cycle", "cycle", "cycle_forces", "sweep", "strokes",
           "drive_cycles", "fed_sense", "fed_force"]

SCENARIOS = ("combined_equal", "combined_ideal", "separate_second", "separate_first")
#: seed 004's cycle times: 4 to 20 s by 1 s [s]
PERIODS = tuple(float(T) for T in range(4, 21))


def strokes(circuit):
    """``(start, end)`` [m] of the work cycle a drive sets: every cylinder from the
    stop where its fed chamber is smallest to the other one (a ``raise`` valve:
    s_min → s_max; ``lower``: s_max → s_min), in the circuit's order of coordinates
    (seed 004's crane: the boom S01 → S_max1, the stick from Φ1p0 to Φ1pmax).

    Parameters
    ----------
    circuit : assur.dynamics.drive.Circuit

    Returns
    -------
    tuple of ndarray, shape (k,)

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import strokes
    >>> start, end = strokes(io.load(io.bundled("crane_lv184a")).drive)   # seed 004
    >>> start.round(4).tolist(), end.round(4).tolist()   # (S1, S2) [m]: the stick retracts
    ([1.075, 2.179], [1.705, 1.3618])
    """
    start = np.array([b.stop for b in circuit.branches])
    end = np.array([b.cylinder.s_max if b.sense > 0 else b.cylinder.s_min
                    for b in circuit.branches])
    return start, end


@dataclass(frozen=True)
class Cycle:
    """Positions and rates of a cycle sampled in time.

    Attributes
    ----------
    scenario : str
    period : float
        The cycle time T_c [s] the speeds were set from.
    t : ndarray, shape (n,)
        Times [s] (the last one is when every coordinate has arrived).
    q, qdot : ndarray, shape (n, k)
        Coordinates [m] and rod speeds [m/s] (signed: towards ``end``).
    segment : ndarray of int, shape (n,)

    Examples
    --------
    >>> from assur.dynamics.cycles import cycle
    >>> c = cycle((1.0, 2.0), (1.6, 1.2), 8.0, "separate_second", samples=3)  # [m], [s]
    >>> c.scenario, c.period, c.segment.tolist()         # T_c [s]
    ('separate_second', 8.0, [0, 0, 0, 1, 1, 1])
    >>> c.q[-1].round(6).tolist(), round(float(c.t[-1]), 6)   # arrived [m] at [s]
    ([1.6, 1.2], 8.0)
    """

    scenario: str
    period: float
    t: np.ndarray
    q: np.ndarray
    qdot: np.ndarray
    segment: np.ndarray


def cycle(start, end, period, scenario, samples=41) -> Cycle:
    """The cycle of two coordinates from ``start`` to ``end`` [m] for a cycle time
    ``period`` [s] in ``scenario`` (:data:`SCENARIOS`), ``samples`` times per
    segment (its ends included).

    Raises
    ------
    ValueError
        An unknown scenario, a period ≤ 0, or not two coordinates with a stroke each.

    Examples
    --------
    >>> from assur.dynamics.cycles import cycle
    >>> start, end = (1.0, 2.0), (1.6, 1.2)        # [m]: strokes 0.6 and 0.8 m
    >>> c = cycle(start, end, 8.0, "combined_equal", samples=5)   # T_c = 8 s
    >>> c.qdot[0].round(4).tolist(), round(float(c.t[-1]), 3)  # eq. (60): V [m/s]; end [s]
    ([0.075, -0.075], 10.667)
    >>> c = cycle(start, end, 8.0, "combined_ideal", samples=5)
    >>> c.qdot[0].round(4).tolist(), round(float(c.t[-1]), 3)  # eq. (61) [m/s], [s]
    ([0.075, -0.1], 8.0)
    >>> cycle(start, end, 8.0, "together")
    Traceback (most recent call last):
    ...
    ValueError: scenario must be one of: ['combined_equal', 'combined_ideal', 'separate_second', 'separate_first'], got 'together'
    """
    if scenario not in SCENARIOS:
        raise ValueError(f"scenario must be one of: {list(SCENARIOS)}, got {scenario!r}")
    if not (np.isfinite(period) and period > 0):
        raise ValueError(f"period must be a time > 0 [s], got {period!r}")
    a, b = np.asarray(start, float), np.asarray(end, float)
    if a.shape != (2,) or b.shape != (2,) or np.any(a == b):
        raise ValueError("a cycle moves two coordinates, each by a non-zero stroke")
    stroke = np.abs(b - a)
    sense = np.sign(b - a)
    if scenario == "combined_equal":
        V = np.full(2, stroke.min() / period)
        first = stroke / V
        segs = [(first.min(), V * sense), (first.max() - first.min(),
                                           np.where(first > first.min(), V, 0.0) * sense)]
    elif scenario == "combined_ideal":
        segs = [(period, stroke / period * sense)]
    else:
        V = stroke.sum() / period
        order = (1, 0) if scenario == "separate_second" else (0, 1)
        segs = []
        for j in order:
            v = np.zeros(2)
            v[j] = V * sense[j]
            segs.append((stroke[j] / V, v))
    return _sampled(scenario, period, a, b, segs, samples)


def _sampled(scenario, period, a, b, segs, samples):
    """The :class:`Cycle` of segments ``(duration, velocity)`` from ``a`` to ``b``."""
    sense = np.sign(b - a)
    t0, q0 = 0.0, a.copy()
    ts, qs, vs, ss = [], [], [], []
    for i, (dur, v) in enumerate(segs):
        if dur <= 0:
            continue
        tt = np.linspace(0.0, dur, samples)
        ts.append(t0 + tt)
        qs.append(q0 + tt[:, None] * v)
        vs.append(np.broadcast_to(v, (samples, 2)))
        ss.append(np.full(samples, i))
        t0 += dur
        q0 = q0 + dur * v
    q = np.concatenate(qs)
    # arrive exactly (no rounding past a stop)
    q = np.where(sense > 0, np.minimum(q, b), np.maximum(q, b))
    return Cycle(scenario, float(period), np.concatenate(ts), q, np.concatenate(vs),
                 np.concatenate(ss))


def drive_cycles(circuit, samples=41):
    """The work cycle at the rod speeds a drive's pump sets (seed 004, §Г: the
    standard pump with a flow divider against separate motion), between the drive's
    stops (:func:`strokes`):

    * ``divider``: both rods from the start at V_j = s_j·Q/f_j (eqs. 65–66; f_j the
      fed area), each stopping at its end;
    * ``pump_second``, ``pump_first``: one rod at a time with the whole flow,
      V_j = Q/f_j (eqs. 67–68), the second coordinate (the stick) first or the
      first (the boom) first.

    Returns
    -------
    dict of str to Cycle
        ``period`` is the time the cycle takes [s].

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import drive_cycles
    >>> cycles = drive_cycles(io.load(io.bundled("crane_lv184a")).drive)   # seed 004
    >>> sorted(cycles)
    ['divider', 'pump_first', 'pump_second']
    >>> cycles["divider"].qdot[0].round(4).tolist()   # eqs. 65–66: V1, V2 [m/s]
    [0.0849, -0.2176]
    >>> [round(cycles[k].period, 2) for k in ("divider", "pump_second")]   # [s]
    [7.42, 5.59]
    """
    a, b = strokes(circuit)
    if a.shape != (2,):
        raise ValueError("a drive's cycle moves two coordinates")
    sense = np.sign(b - a)
    stroke = np.abs(b - a)
    Q = circuit.pump_flow()
    Vc = np.array([br.share * Q / br.area for br in circuit.branches])
    Vs = np.array([Q / br.area for br in circuit.branches])
    t = stroke / Vc
    slow = int(np.argmax(t))
    rest = np.zeros(2)
    rest[slow] = Vc[slow] * sense[slow]
    out = {"divider": _sampled("divider", float(t.max()), a, b,
                               [(float(t.min()), Vc * sense), (float(t.max() - t.min()), rest)],
                               samples)}
    for name, order in (("pump_second", (1, 0)), ("pump_first", (0, 1))):
        segs = []
        for j in order:
            v = np.zeros(2)
            v[j] = Vs[j] * sense[j]
            segs.append((float(stroke[j] / Vs[j]), v))
        out[name] = _sampled(name, float(sum(d for d, _ in segs)), a, b, segs, samples)
    return out


def cycle_forces(mechanism, cycles, g=None):
    """Cylinder forces along cycles: ``[(F, F_static), …]`` with arrays of shape
    (n, k) [N] (F = h − Q, F_static = −Q), for all the cycles' positions solved at
    once.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import cycle, cycle_forces, strokes
    >>> crane = io.load(io.bundled("crane_lv184a"))                    # seed 004
    >>> c = cycle(*strokes(crane.drive), 6.0, "combined_ideal", samples=5)   # T_c [s]
    >>> (F, Fs), = cycle_forces(crane.mechanism, [c], g=9.81)          # g [m/s²]
    >>> F.shape
    (5, 2)
    >>> (F[0] / 1e3).round(2).tolist(), (Fs[0] / 1e3).round(2).tolist()   # boom, stick [kN]
    ([52.02, 80.38], [43.55, 72.31])
    """
    q = np.concatenate([c.q for c in cycles])
    qd = np.concatenate([c.qdot for c in cycles])
    eom = equations_of_motion(mechanism.solve(q), g=g)
    F = eom.actuator_forces(qd, np.zeros_like(qd))
    Fs = -eom.generalized_forces
    out, i = [], 0
    for c in cycles:
        n = c.t.size
        out.append((F[i:i + n], Fs[i:i + n]))
        i += n
    return out


def fed_sense(c):
    """The fed direction σ_j = ±1 of each cylinder in a cycle: the sign of its stroke
    velocity (seed 004: every scenario of eqs. 60–62 and 65–68 moves each rod one
    way, so σ_j is one sign per cylinder per scenario; +1 extending, the piston side
    fed; −1 retracting, the rod side fed).

    Parameters
    ----------
    c : Cycle

    Returns
    -------
    ndarray, shape (k,)

    Raises
    ------
    ValueError
        A cylinder that does not move in the cycle, or moves both ways (no one fed
        side).

    Examples
    --------
    >>> from assur.dynamics.cycles import cycle, fed_sense
    >>> c = cycle((1.0, 2.0), (1.6, 1.2), 8.0, "separate_second", samples=3)  # [m], [s]
    >>> fed_sense(c).tolist()      # the first rod extends, the second retracts
    [1.0, -1.0]
    """
    v = np.asarray(c.qdot, dtype=float)
    up, down = (v > 0).any(axis=0), (v < 0).any(axis=0)
    bad = np.flatnonzero(up == down)
    if bad.size:
        j = int(bad[0])
        raise ValueError(f"cycle {c.scenario!r}: coordinate {j} "
                         + ("moves both ways" if up[j] else "does not move")
                         + ": no one fed side of its cylinder")
    return np.where(up, 1.0, -1.0)


def fed_force(c, F):
    """The largest force in the fed direction over a cycle, max_t σ_j·F_j(t) [N]
    (σ_j = :func:`fed_sense`): the force the fed chamber must produce (seed 004,
    after eq. 68: the stick's force in its rod-side chamber). Every sample counts,
    the held phases of separate motion too (the closed valve keeps that chamber
    loaded). A negative value: the fed chamber never pushes (the load drives the
    stroke, the drained side holds it).

    Parameters
    ----------
    c : Cycle
    F : array_like, shape (n, k)
        Forces along ``c`` [N] (F = h − Q, or a part of it), positive extending.

    Returns
    -------
    ndarray, shape (k,)

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import cycle, cycle_forces, fed_force, strokes
    >>> crane = io.load(io.bundled("crane_lv184a"))                    # seed 004
    >>> c = cycle(*strokes(crane.drive), 6.0, "combined_ideal")        # T_c [s]
    >>> (F, _), = cycle_forces(crane.mechanism, [c], g=9.81)           # g [m/s²]
    >>> (fed_force(c, F) / 1e3).round(1).tolist()   # boom (extends), stick (retracts) [kN]
    [148.8, 54.7]
    >>> (abs(F).max(axis=0) / 1e3).round(1).tolist()   # max |F|: the stick's push at t = 0
    [148.8, 80.4]
    """
    F = np.asarray(F, dtype=float)
    if F.shape != c.qdot.shape:
        raise ValueError(f"cycle {c.scenario!r}: forces of shape {F.shape}, the cycle has "
                         f"{c.qdot.shape}")
    return (fed_sense(c) * F).max(axis=0)


def sweep(mechanism, start, end, periods=PERIODS, scenarios=SCENARIOS, g=None,
          samples=41):
    """Largest |F_j|, |F_s,j| and |F_d,j| of every scenario and cycle time (seed 004:
    T_c from 4 to 20 s by 1 s), a pandas DataFrame with columns ``scenario``, ``T``
    [s], ``F1_max``, ``F2_max`` (the force), ``Fs1_max``, ``Fs2_max`` (its static part
    −Q), ``Fd1_max``, ``Fd2_max`` (its dynamic part h) [N], ``duration`` [s] (when
    the last rod arrives), and ``F1_fed``, ``F2_fed``, ``Fs1_fed``, ``Fs2_fed`` [N]:
    the largest force and static part in the fed direction (:func:`fed_force`).

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import strokes, sweep
    >>> crane = io.load(io.bundled("crane_lv184a"))                     # seed 004
    >>> d = sweep(crane.mechanism, *strokes(crane.drive), periods=[6.0]).set_index("scenario")
    >>> (d["F1_max"] / 1e3).round(1).tolist()     # the boom's largest force [kN], T_c = 6 s
    [156.4, 148.8, 280.6, 194.1]
    >>> ratio = d.loc["separate_second", "F1_max"] / d.loc["combined_equal", "F1_max"]
    >>> round(float(ratio), 2)      # [-] max |F|, against V1 = V2 (eq. 60)
    1.79
    >>> ratio = d.loc["separate_second", "F2_fed"] / d.loc["combined_ideal", "F2_fed"]
    >>> round(float(ratio), 2)      # [-] the stick, fed direction, eq. 61 (paper: ≈ 30 %)
    1.25
    """
    import pandas as pd
    cycles = [cycle(start, end, float(T), s, samples) for s in scenarios for T in periods]
    rows = []
    for c, (F, Fs) in zip(cycles, cycle_forces(mechanism, cycles, g)):
        Fd = F - Fs
        fed, fed_s = fed_force(c, F), fed_force(c, Fs)
        rows.append(dict(scenario=c.scenario, T=c.period, F1_max=np.abs(F[:, 0]).max(),
                         F2_max=np.abs(F[:, 1]).max(), Fs1_max=np.abs(Fs[:, 0]).max(),
                         Fs2_max=np.abs(Fs[:, 1]).max(), Fd1_max=np.abs(Fd[:, 0]).max(),
                         Fd2_max=np.abs(Fd[:, 1]).max(), duration=c.t[-1], F1_fed=fed[0],
                         F2_fed=fed[1], Fs1_fed=fed_s[0], Fs2_fed=fed_s[1]))
    return pd.DataFrame(rows)
