"""The seed machines as ready models, loaded from the bundled model files.

Each machine is defined once, in ``src/assur/models/*.toml`` (format:
``docs/model-format.md``); the functions here load those files (once per process)
and return their :class:`~assur.Mechanism`, with the seed's point and link
numbering:

* :func:`hitch_003` — mini-tractor mounted-implement hitch (МН of МСХА), seed 003,
  ``hitch_003.toml``: L4, Sp and L7 are solved from the seed's three Find conditions.
* :func:`header_000` — combine header lift, seed 000, ``header_000.toml``: its input
  cannot assemble.
* :func:`header_000_fixed` — the same header with an illustrative L4 = 0.652 m that
  assembles, ``header_000_fixed.toml``.
* :func:`combine_002` — the crank-driven six-bar of a combine, seed 002,
  ``combine_002.toml`` (l2 = 1.0 m; :func:`combine_002_printed`, the printed
  l2 = 0.1 m, cannot assemble); :func:`combine_002_range` the seed's 13 crank
  positions, :func:`combine_002_turn_range` a full clockwise turn.
* :func:`steering_lab4` — steering of a power unit's steered axle, seed 001 lab 4,
  base drive with two cylinders in one closed chain (``steering_lab4.toml``), and
  :func:`steering_lab4_modern`, its slider-crank drive with one double-rod cylinder
  (``steering_lab4_modern.toml``); illustrative dimensions, the lab's loads.

Each ``*_range()`` gives the seed's positions of the generalized coordinate (the
file's ``[range]``). :func:`assur.io.load` gives the whole :class:`assur.io.Model`
(range, solved conditions, source).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .core.mechanism import Mechanism

__all__ = ["hitch_003", "hitch_003_range", "header_000", "header_000_fixed", "header_000_range",
           "combine_002", "combine_002_printed", "combine_002_range", "combine_002_turn_range",
           "loader_lab1", "loader_lab1_range",
           "steering_lab4", "steering_lab4_modern", "steering_lab4_range",
           "steering_lab4_modern_range"]

#: seed 003: the exact roots of its three Find blocks (printed rounded to 4 digits:
#: L4 = 0.6613, Sp = 0.4694, L7 = 0.7522; the printed tables used these values).
#: ``hitch_003.toml`` solves them again from the conditions; the roots agree to 1e-9.
HITCH_003_FOUND = {"L4": 0.661283167, "Sp": 0.469356940, "L7": 0.752169525}


@lru_cache(maxsize=None)
def _model(name):
    from . import io  # pydantic and pint are needed only when a file is read
    return io.load(io.bundled(name))


def _mechanism(name, params) -> Mechanism:
    m = _model(name).mechanism
    return m.with_params(**params) if params else m


def hitch_003(**params) -> Mechanism:
    """Mounted-implement hitch of a mini-tractor, seed ``003_b1551261b108abd1.txt``
    (bundled file ``hitch_003.toml``).

    Three structural groups (seed §2): I (2,3) the cylinder–lever group — cylinder
    2 from frame pivot 01 to point 23 of the lever 3 pivoted at 03; the lever's arm
    34 at φBD = 22° from it; II (4,5) the RRR dyad brace 4 – lower link 5 (pivot 05),
    with the suspension axis 56 on link 5 at L56; III (6,7) the RRR dyad implement 6
    – top link 7 (pivot 07). The implement's centre of mass S6 is fixed by its offset
    (X6, Y6) from 56 at the working stroke Sp (seed: φS6 := 2π + atan(Y6/X6) − φ6(Sp)).

    Generalized coordinate ``S``: cylinder pin-to-pin length [m], 0.420…0.670.

    Parameters
    ----------
    **params
        Overrides of any parameter, e.g. ``L4=0.6613`` or arrays for a batch (the
        machine's axles and weights follow ``L``, ``a``, ``b``, ``P_mcxa``, ``P_gr``).

    Notes
    -----
    Seed slips resolved here (BRIEF.md): ``φBD … [м]`` is an angle (22°);
    L4, Sp and L7 are the roots of the seed's Find blocks, solved from the conditions
    Y56(Smin) = 0.2 m, Y56(Sp) = 0.4 m, φ6(Sp) = 90° (they agree with
    :data:`HITCH_003_FOUND` to 1e-9). The seed's check X23s, Y23s uses
    φ12 = φ13 − acos(…), which is not the cylinder's direction; the cylinder angle
    here is the direction 01 → 23 (φ12 = π − φ13 − acos((S² + L13² − L3²)/(2·S·L13)))
    and closes the loop exactly.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> round(float(m.params["L4"]), 4)     # root of the seed's first Find block [m]
    0.6613
    >>> r = m.solve([0.42, 0.67])           # S at Smin and Smax [m]
    >>> [round(float(v), 1) for v in r.phi("6", degrees=True)]   # φ6, table 2.1 [deg]
    [88.5, 110.3]
    """
    return _mechanism("hitch_003", params)


def hitch_003_range() -> np.ndarray:
    """Seed 003 §1.3: S from Smin = 0.420 to Smax = 0.670 m in Npol = 10 positions [m].

    Examples
    --------
    >>> from assur import examples
    >>> s = examples.hitch_003_range()      # S [m]
    >>> len(s), round(float(s[0]), 3), round(float(s[1]), 3), round(float(s[-1]), 3)
    (10, 0.42, 0.448, 0.67)
    """
    return np.array(_model("hitch_003").range)


def _header(name, params) -> Mechanism:
    params = dict(params)
    # the centre-of-mass offset dXN, dYN is XN − X56_0, YN − Y56_0 (seed 000: X := XN − 0.767)
    p = _model(name).mechanism.params
    if {"XN", "X56_0"} & params.keys() and "dXN" not in params:
        params["dXN"] = params.get("XN", p["XN"]) - params.get("X56_0", p["X56_0"])
    if {"YN", "Y56_0"} & params.keys() and "dYN" not in params:
        params["dYN"] = params.get("YN", p["YN"]) - params.get("Y56_0", p["Y56_0"])
    return _mechanism(name, params)


def header_000(**params) -> Mechanism:
    """Combine header lift, seed ``000_04e80bfff5466283.txt`` (bundled file
    ``header_000.toml``).

    Cylinder from 01 to point 23 of the bell-crank 3 pivoted at 03 (lever L3); the
    bell-crank's second arm L4 ends at 46, its triangle closed by L34
    (DELFI = acos((L3² + L4² − L34²)/(2·L3·L4)), FI4 = FI3 − DELFI); the RRR dyad
    link 6 (46–56) and rocker 5 (05–56) carries the header, centre of mass offset
    (XN − 0.767, YN − 0.355) from 56 at S = 0.650 m (FIS6).

    **The seed's input cannot assemble**: L4 = 0.657 > L3 + L34 = 0.65234 m, so
    DELFI = acos(1.0199) is complex — the source of every ``…i`` in its tables.
    :meth:`~assur.Mechanism.solve` raises :class:`~assur.AssemblyError` saying so.

    Parameters
    ----------
    **params
        Overrides of any parameter; overriding ``XN``, ``YN``, ``X56_0`` or ``Y56_0``
        also updates the offsets ``dXN``, ``dYN`` derived from them.

    Examples
    --------
    >>> from assur import examples
    >>> examples.header_000().solve([0.65])   # S [m] # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.AssemblyError: rigid point 'arm 46' (link 3) fails at position 0 (S = 0.65): ... L4 exceeds L3 + L34 = 0.65234 m by 4.66 mm
    """
    return _header("header_000", params)


def header_000_fixed(**params) -> Mechanism:
    """The combine header lift of seed 000 with L4 = 0.652 m instead of the printed
    0.657 m, so that the bell-crank's triangle closes (bundled file
    ``header_000_fixed.toml``). **Illustrative**: 0.652 m is not a seed value; the
    cylinder–lever group (FI3, DFI3) is exactly the seed's.

    Parameters
    ----------
    **params
        Overrides of any parameter (see :func:`header_000`).

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.header_000_fixed()
    >>> float(m.params["L4"])                 # the illustrative L4 [m]
    0.652
    >>> r = m.solve([0.65, 0.80])             # S at both ends of the seed's range [m]
    >>> [round(float(v), 1) for v in r.phi("5", degrees=True)]   # rocker 5 [deg]
    [-11.7, 69.2]
    """
    return _header("header_000_fixed", params)


def header_000_range() -> np.ndarray:
    """Seed 000: S_AA from 0.650 to 0.800 m in steps of 0.010 m [m].

    Examples
    --------
    >>> from assur import examples
    >>> s = examples.header_000_range()       # S_AA [m]
    >>> len(s), round(float(s[0]), 3), round(float(s[1]), 3), round(float(s[-1]), 3)
    (16, 0.65, 0.66, 0.8)
    """
    return np.array(_model("header_000").range)


def combine_002(**params) -> Mechanism:
    """Crank-driven six-bar of a combine, seed ``002_e16fe39845bb7e76.txt`` (bundled
    file ``combine_002.toml``).

    Loop 1 (seed eq. 2.3): crank l1 = O1A, coupler l2 = AB, rocker l3 = B→O3 with
    O3 = O1 + l10∠j10; loop 2 (eq. 2.4): l4 = O3→C continues the rocker beyond O3
    (j4 = j3), l5 = CD, l6 = D→O6 with O6 = O3 + l8∠j8. The helper vectors l9 = A→O3
    and l7 = C→O6 (eqs. 2.5, 2.9–2.10) are named distances with their angles j9, j7.
    The crank turns clockwise (φ1' = −1, eq. 2.20): its :class:`assur.core.motion.Motion`.

    Generalized coordinate ``j1``: the crank angle [rad].

    Notes
    -----
    Seed slips resolved (BRIEF.md): l2 is printed 0,1 m but is 1.0 m (with 0.1 the
    first dyad cannot close: :func:`combine_002_printed`); the lost fixed angles
    j10 = −7.125°, j8 = +12.54° are restored from the seed's withheld table.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.combine_002()
    >>> float(m.params["l2"])                 # the corrected coupler l2 [m]
    1.0
    >>> r = m.solve(examples.combine_002_range()[[0, -1]])   # positions 1 and 13 [rad]
    >>> [round(float(v), 1) for v in r.phi("3", degrees=True)]   # rocker 3 at its extremes [deg]
    [-78.8, -37.2]
    >>> [bool(abs(v) < 1e-3) for v in r.dphi("3")]               # dφ3/dj1 ≈ 0 there [-]
    [True, True]
    """
    return _mechanism("combine_002", params)


def combine_002_printed(**params) -> Mechanism:
    """Seed 002's six-bar with l2 = 0.1 m as its table 2.2 prints it
    (``combine_002_printed.toml``): :meth:`~assur.Mechanism.solve` raises the
    :class:`~assur.AssemblyError` of the first dyad (521 mm short at j1 = 14.679°).

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.combine_002_printed()
    >>> float(m.params["l2"])                 # as table 2.2 prints it [m]
    0.1
    >>> m.solve(examples.combine_002_range()[:1])   # j1 = 14.679° [rad] # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.AssemblyError: RRR dyad 'dyad 2-3' (links 2, 3) cannot assemble at position 0 (j1 = 14.679°): ... by 521 mm
    """
    return _mechanism("combine_002_printed", params)


def combine_002_range() -> np.ndarray:
    """Seed 002's 13 crank positions [rad]: j1 = 14.679° and steps of −30° (written
    continuously along the clockwise turn: 14.679°, −15.321°, …, −315.321°), then
    position 13 at 188.229° (written −171.771°).

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> j1 = np.degrees(examples.combine_002_range())   # [deg]
    >>> len(j1), [round(float(v), 3) for v in j1[[0, 1, 11, 12]]]
    (13, [14.679, -15.321, -315.321, -171.771])
    """
    return np.array(_model("combine_002").range)


def combine_002_turn_range() -> np.ndarray:
    """A full clockwise turn from j1 = 14.679°, one position per degree (361 positions,
    ``combine_002_turn.toml``) [rad].

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> j1 = np.degrees(examples.combine_002_turn_range())   # [deg]
    >>> len(j1), round(float(j1[0]), 3), round(float(j1[1] - j1[0]), 3), round(float(j1[-1]), 3)
    (361, 14.679, -1.0, -345.321)
    """
    return np.array(_model("combine_002_turn").range)


def loader_lab1(**params) -> Mechanism:
    """The mini-loader lift device of seed 001 lab 1 (``loader_lab1.toml``), with
    illustrative dimensions: two coordinates, the boom cylinder S and the traverse
    cylinder S1 (two cylinders side by side in each), the boom's own weight as a dead
    load of the capacity (lab eq. 14) and the machine on two axles (eqs. 15–18).

    The lab gives no dimensions; these are chosen so that the capacity at the
    suspension axis 09 with the boom's weight is about 11.5 kN and the
    steerability-limited mass at 09 about 800 kg, as the lab reports.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.loader_lab1()
    >>> m.coordinates                          # boom cylinder S, traverse cylinder S1
    ('S', 'S1')
    >>> r = m.solve(examples.loader_lab1_range()[[0, -1]])   # (S, S1) [m]
    >>> [round(float(v), 3) for v in r.y("09")]              # height of the suspension axis [m]
    [1.016, 3.751]
    """
    return _mechanism("loader_lab1", params)


def loader_lab1_range() -> np.ndarray:
    """The grid of (S, S1) of ``loader_lab1.toml`` [m], shape (n_S·n_S1, 2), S
    varying slowest.

    Examples
    --------
    >>> from assur import examples
    >>> g = examples.loader_lab1_range()       # (S, S1) [m]
    >>> g.shape
    (104, 2)
    >>> [round(float(v), 3) for v in g[0]], [round(float(v), 3) for v in g[-1]]
    ([1.001, 0.8], [1.647, 0.92])
    """
    return np.array(_model("loader_lab1").range)


def steering_lab4(**params) -> Mechanism:
    """Steering of the steered axle of УЭС-2-250А, seed 001 lab 4, base drive (bundled
    file ``steering_lab4.toml``; illustrative dimensions, the lab's A, L and eq. 17).

    The cylinder–lever group (left cylinder S1 on the left wheel's lever 3), the arm
    34 at Δφ1, the RRR dyad tie rod 4 – right arm 5, the right wheel's lever 6 at Δφ2
    (point 76), and the passive right cylinder S2 = |07–76| (eq. 10) on the supply
    line of S1 (piston side of S1, rod side of S2; eq. 15). Resisting moments M_c on
    both wheels oppose a left turn (S1 extends).

    Generalized coordinate ``S1``: the left cylinder's pin-to-pin length [m].

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.steering_lab4()
    >>> r = m.solve(examples.steering_lab4_range()[[0, -1]])   # S1 [m]
    >>> [round(float(v), 1) for v in r.phi("w3", degrees=True)]   # left wheel's lever [deg]
    [92.9, 142.0]
    >>> [round(float(v), 1) for v in r.phi("w5", degrees=True)]   # right wheel's lever [deg]
    [92.8, 126.2]
    """
    return _mechanism("steering_lab4", params)


def steering_lab4_range() -> np.ndarray:
    """The positions of ``steering_lab4.toml``: S1 from a small left turn to full lock [m].

    Examples
    --------
    >>> from assur import examples
    >>> s = examples.steering_lab4_range()    # S1 [m]
    >>> len(s), round(float(s[0]), 3), round(float(s[-1]), 3)
    (30, 0.51, 0.662)
    """
    return np.array(_model("steering_lab4").range)


def steering_lab4_modern(**params) -> Mechanism:
    """The modernised steering drive of seed 001 lab 4 (bundled file
    ``steering_lab4_modern.toml``; illustrative dimensions): one double-rod cylinder
    whose two rod ends (two slider inputs on S) drive the wheels' levers 3 and 4
    through the links 2 and 5 (eqs. 18–25).

    Generalized coordinate ``S``: the rod's travel from straight ahead [m].

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.steering_lab4_modern()
    >>> r = m.solve([0.0, 0.06])               # rod travel S [m]
    >>> [round(float(v), 1) for v in r.phi("w3", degrees=True)]   # left wheel's lever [deg]
    [90.0, 115.4]
    >>> [round(float(v), 1) for v in r.phi("w4", degrees=True)]   # right wheel's lever [deg]
    [90.0, 108.1]
    """
    return _mechanism("steering_lab4_modern", params)


def steering_lab4_modern_range() -> np.ndarray:
    """The positions of ``steering_lab4_modern.toml``: the rod's travel [m].

    Examples
    --------
    >>> from assur import examples
    >>> s = examples.steering_lab4_modern_range()   # rod travel S [m]
    >>> len(s), round(float(s[0]), 3), round(float(s[-1]), 3)
    (13, 0.0, 0.06)
    """
    return np.array(_model("steering_lab4_modern").range)


def spout_lab5(**params) -> Mechanism:
    """Silage-spout rotation mechanism of a forage harvester, seed
    ``001_4447446e88a18ffc.txt`` lab 5 (bundled file ``spout_lab5.toml``): the
    cylinder turns the arc lever 3 about 03; its arm 34 drives the arc lever 4 and the
    spout's base radius 5 about the spout axis 05. Dimensions fitted to the lab's
    table 5.1 by :func:`assur.synthesis.fitting.fit_parameters`; in a horizontal plane (no
    gravity), with an illustrative rod motion and spout inertia."""
    return _mechanism("spout_lab5", params)


def spout_lab5_range() -> np.ndarray:
    """S = 0.35 … 0.51 m by 0.01 m [m] (table 5.1 prints every other one)."""
    return _model("spout_lab5").range


def conditioner_lab2(**params) -> Mechanism:
    """Pressing device of a mower-conditioner's rollers, seed
    ``001_4447446e88a18ffc.txt`` lab 2, the four-bar (bundled file
    ``conditioner_lab2.toml``, illustrative): k springs pull the upper roller's rocker;
    the coordinate Y is the distance between the rollers' centres
    (:mod:`assur.machines.conditioner`)."""
    return _mechanism("conditioner_lab2", params)


def conditioner_lab2_sixbar(**params) -> Mechanism:
    """The same device as a six-bar (lab 2 fig. 2.2; ``conditioner_lab2_sixbar.toml``
    extends ``conditioner_lab2.toml``): the springs act on a lever that drives the
    rocker through a link; its lever geometry fitted (:mod:`assur.synthesis.fitting`) so that
    p_c stays at 20 kN/m over Y (illustrative)."""
    return _mechanism("conditioner_lab2_sixbar", params)


def conditioner_lab2_range() -> np.ndarray:
    """Y = 205 … 240 mm by 5 mm [m]: gaps of 5 … 40 mm between rollers of 200 mm."""
    return _model("conditioner_lab2").range
