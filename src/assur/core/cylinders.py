"""Hydraulic cylinders: the description and the one home of their quantities.

A :class:`Cylinder` describes k identical cylinders acting on a length of the
mechanism (a generalized coordinate, or a passive named distance on a supply line).
The formulas here are the only place where its chamber areas, pressure, available
force, lift capacity and reserve are written; the array path
(:mod:`assur.machines.cylinders`, the reports), the outputs contract
(:mod:`assur.core.outputs`: the fused kernel, the design criteria, the
sensitivities) and the standard lift test (:mod:`assur.machines.hitch_lift`) all call
them, each in its own kind of number (arrays, symbols of a kernel, dual numbers).

Formulas (SI: m, N, Pa):

* chamber areas: piston side A_p = π·(D² − d2²)/4 (d2 = 0 but for a double-rod
  cylinder), rod side A_r = π·(D² − d²)/4;
* the pressurised chamber and its sign σ: +1 for the piston side (the cylinder
  pushes), −1 for the rod side (it pulls); for the pressure p, ``side = "auto"``
  picks, at each position, the chamber that holds the loads there (σ = sign F);
* the working direction of a stroke and its chamber σ_w (capacity and reserve):
  the way the cylinder moves to do the work — to lift the payload. Declared:
  ``side = "piston"`` (σ_w = +1, the cylinder extends, its piston side pushes) or
  ``"rod"`` (σ_w = −1, it retracts, its rod side pulls). ``"auto"``: once per
  stroke (per design), never per position, from the sign of the payload's virtual
  work along the stroke, W = Σ_i F_pay(q_i) over the stroke's positions, F_pay the
  actuator force of the loads that are not dead loads (:func:`stroke_work`);
  σ_w = +1 where W ≥ 0. A payload whose force changes sign along the stroke (a
  Z-bar bucket near the top of the lift) does not switch the chamber;
* largest working pressure p_max = p_relief − (Δp_throttle + Δp_line)
  (seed 001 lab 1 eq. 1);
* pressure p = σ·F/(η_m·k·A·η_h), F the actuator force of the loads by virtual
  work (seed 003: Pgc = Fgc/(k_gc·S_gc·η); seed 000: FS = P·Is/km), positive
  when the pressurised chamber holds the loads;
* available force F_max = k·p_max·A·η_h (seed 000: Fmax = p·SS·kg, there in kgf);
* lift capacity at a point, the vertical (downward) load the cylinders lift or
  hold there at p_max in the working direction:
  G = (σ_w·F_max,w·η_m − F_dead)/I with F_max,w the available force of the working
  chamber, I = ∂Y/∂q of the point and F_dead the actuator force of the dead loads
  (seed 003: G56 = k·p·η·S_gc/I56, GS6 with IS6; seed 001 lab 1 eqs. 8–10, 14 with
  the boom's weight). G is positive for a pushing and for a pulling cylinder alike:
  a pulling cylinder lifts the point as it shortens (I < 0, σ_w = −1);
* capacity reserve ΔG = (G − P)/P·100 % against the payload P alone (seed 003
  ΔGS65): G has already paid for the dead loads, so P is never a dead load;
* cylinders on one supply line share one pressure, by virtual work with every
  cylinder of the line as an actuator: p·Σ σ_i·k_i·A_i·η_h,i·∂L_i/∂q = F/η_m
  (seed 001 lab 4 eq. 15), L_i the cylinder's length (q itself for the driving
  cylinder, a named distance for a passive one).

Signs, on a lever pivoted at O with the payload P at its tip T (q the cylinder's
pin-to-pin length, I = ∂Y_T/∂q)::

    pushing (extend, σ_w = +1)            pulling (retract, σ_w = −1)

          O━━━━━━━━━A━━━━━━━━━T                      B (base)
                    ║ ↑ p·A_piston    ↓P             ║ ↑ p·A_rod
                    ║                                ║
                    B (base)              O━━━━━━━━━━A━━━━━━━━━T
                                                                ↓P
    I > 0: T rises as q grows             I < 0: T rises as q shrinks
    G = (+F_max,p·η_m − F_dead)/I > 0     G = (−F_max,r·η_m − F_dead)/I > 0

With equal areas (A_piston of the pusher = A_rod of the puller) the two mirror
images have the same capacity at the same cylinder length.

The formulas take a ``select(x, a, b)`` of the caller's kind of number — ``a``
where x ≥ 0, else ``b`` — so that a chamber chosen by the sign of a force is the
same choice over arrays, in a kernel and over dual numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, ClassVar, Union

import numpy as np

__all__ = ["Cylinder", "CylinderTerms", "piston_area", "chamber_area", "terms", "chamber_sign",
           "working_area", "pressure", "force_max", "stroke_work", "capacity", "reserve",
           "line_area", "line_pressure", "select_array"]

Ref = Union[str, float, int]


@dataclass(frozen=True)
class Cylinder:
    """Hydraulic cylinder(s) acting as the generalized coordinate ``coordinate`` — or,
    passive, on a length the mechanism determines (``distance``).

    A cylinder's force is positive when it pushes (its length grows under it)::

        piston side pressurised:   base o==[ p→ |=====o rod end     push  +p·A_piston
        rod side pressurised:      base o==[ ←p |=====o rod end     pull  −p·A_rod

    Parameters
    ----------
    name : str
    coordinate : str, optional
        The generalized coordinate (the cylinders' pin-to-pin length, or a slider's
        travel) [m]. Give it, or ``distance``.
    distance : str, optional
        A passive cylinder: the named distance (``[distances]``) that is its
        pin-to-pin length [m]; it follows the mechanism (seed 001 lab 4: the right
        cylinder S2 follows S1) and pushes with the pressure of its ``supply`` line.
    supply : str, optional
        The supply line: cylinders naming one line share one pressure, solved by
        virtual work with every cylinder of the line as an actuator (seed 001 lab 4
        eq. 15); one of them drives a coordinate, the others are passive.
    bore : float or str
        Piston diameter D [m].
    rod : float or str
        Rod diameter d [m] (used when the rod side is pressurised).
    rod2 : float or str
        A double-rod cylinder: the diameter of the second rod, on the piston side [m]
        (seed 001 lab 4, the modernised drive); its pushing area is π·(D² − d2²)/4.
    count : int or str
        Number of identical cylinders acting in parallel, k [-] (seed 003 k_gc = 2).
    eta_mech : float or str
        Mechanical efficiency of the linkage η_m [-]: the rod must push F/η_m
        (seed 000 km = 0.85).
    eta_hyd : float or str
        Hydraulic efficiency η_h [-]: pressure p = F/(k·A·η_h) (seed 003 η = 0.84,
        seed 000 kg = 0.96).
    p_relief : float or str
        Relief-valve setting p_relief [Pa].
    dp_throttle, dp_line : float or str
        Pressure losses at the throttle and in the line [Pa]; the largest working
        pressure is p_max = p_relief − (Δp_throttle + Δp_line) (001 lab 1 eq. 1).
    side : {"piston", "rod", "auto", "extend", "retract"}
        Which chamber is pressurised, i.e. the working direction of the stroke:
        ``"piston"`` (or ``"extend"``) — the cylinder extends to do the work, its
        piston area π·(D² − d2²)/4 pushes; ``"rod"`` (or ``"retract"``) — it
        retracts, the annulus π·(D² − d²)/4 pulls; ``"auto"`` — for the pressure, the chamber that gives the force the
        loads need at each position (a double-rod cylinder steering either way); for
        the capacity and reserve, the working chamber of the stroke from the sign of
        the payload's virtual work along it (:func:`stroke_work`).

    Examples
    --------
    The seed-003 hitch's two cylinders (values are model parameters):

    >>> from assur import examples
    >>> c = examples.hitch_003().cylinders[0]
    >>> c.name, c.coordinate, c.bore, c.count, c.side
    ('ГЦ', 'S', 'Dgc', 'kgc', 'piston')
    >>> from assur.core.cylinders import Cylinder
    >>> Cylinder("ГЦ", coordinate="S", bore=0.08, count=2, eta_hyd=0.84, p_relief=17.5e6).bore
    0.08
    >>> Cylinder("tilt", coordinate="S2", bore=0.1, rod=0.05, side="retract").side
    'rod'
    """

    name: str
    coordinate: str | None = None
    bore: Ref = 0.0
    rod: Ref = 0.0
    count: Ref = 1
    eta_mech: Ref = 1.0
    eta_hyd: Ref = 1.0
    p_relief: Ref = 0.0
    dp_throttle: Ref = 0.0
    dp_line: Ref = 0.0
    side: str = "piston"
    distance: str | None = None
    supply: str | None = None
    rod2: Ref = 0.0

    #: the working directions a ``side`` may name instead of its chamber
    DIRECTIONS: ClassVar = {"extend": "piston", "retract": "rod"}

    def __post_init__(self):  # a direction names its chamber (the model checks the rest)
        object.__setattr__(self, "side", self.DIRECTIONS.get(self.side, self.side))

    quantities: ClassVar = {"bore": "length", "rod": "length", "rod2": "length",
                            "count": "number", "eta_mech": "number", "eta_hyd": "number",
                            "p_relief": "pressure", "dp_throttle": "pressure",
                            "dp_line": "pressure"}
    flags: ClassVar = {"bore": "positive", "rod": "nonneg", "rod2": "nonneg", "count": "count",
                       "eta_mech": "fraction", "eta_hyd": "fraction", "p_relief": "nonneg",
                       "dp_throttle": "nonneg", "dp_line": "nonneg"}

    @property
    def length(self) -> str:
        """The name of the cylinder's length: its coordinate or its distance.

        Examples
        --------
        >>> from assur.core.cylinders import Cylinder
        >>> Cylinder("ГЦ1", coordinate="S1", bore=0.05).length
        'S1'
        >>> Cylinder("ГЦ2", distance="S2", supply="P", side="rod", bore=0.05).length  # passive
        'S2'
        """
        return self.coordinate if self.coordinate is not None else self.distance




def select_array(x, a, b):
    """``a`` where x ≥ 0, else ``b``, over numpy arrays (the array path's ``select``).

    Examples
    --------
    >>> from assur.core.cylinders import select_array
    >>> select_array([2.0, -1.0], 1.0, -1.0).tolist()
    [1.0, -1.0]
    """
    return np.where(np.asarray(x) >= 0, a, b)


def chamber_area(bore, rod, rod2, side):
    """Area of one chamber of one cylinder [m²], in any kind of number: ``"piston"``
    π·(D² − d2²)/4, ``"rod"`` π·(D² − d²)/4 (no checks: :func:`piston_area` checks).

    Examples
    --------
    >>> from assur.core.cylinders import chamber_area
    >>> round(chamber_area(0.08, 0.04, 0.0, "rod") * 1e4, 2)      # [cm²]
    37.7
    """
    d = rod if side == "rod" else rod2
    return 0.25 * math.pi * (bore * bore - d * d)


def piston_area(bore, rod=0.0, side="piston", rod2=0.0):
    """Pressurised area [m²] of a cylinder with bore D and rod d [m]: π·D²/4 on the
    piston side, π·(D² − d²)/4 on the rod side; a double-rod cylinder's piston side
    is the annulus around its second rod d2, π·(D² − d2²)/4.

    Examples
    --------
    >>> from assur.core.cylinders import piston_area
    >>> round(float(piston_area(0.08)), 6)                  # S_gc, seed 003 D = 80 mm [m²]
    0.005027
    >>> round(float(piston_area(0.08, 0.04, "rod")), 6)     # annulus, d = 40 mm [m²]
    0.00377
    >>> round(float(piston_area(0.08, rod2=0.04)), 6)       # double rod, piston side [m²]
    0.00377
    >>> piston_area(0.08, 0.09, "rod")
    Traceback (most recent call last):
    ...
    ValueError: rod side needs 0 < rod < bore, got rod 0.09, bore 0.08
    """
    if side not in ("piston", "rod"):
        raise ValueError("side must be one of: ['piston', 'rod']")
    bore = np.asarray(bore, float)
    if np.any(bore <= 0):
        raise ValueError(f"bore must be positive, got {bore}")
    rod, rod2 = np.asarray(rod, float), np.asarray(rod2, float)
    if side == "piston" and np.any(rod2 != 0) and (np.any(rod2 >= bore) or np.any(rod2 < 0)):
        raise ValueError(f"a double-rod cylinder needs 0 < rod2 < bore, got rod2 {rod2}, "
                         f"bore {bore}")
    if side == "rod" and (np.any(rod >= bore) or np.any(rod <= 0)):
        raise ValueError(f"rod side needs 0 < rod < bore, got rod {rod}, bore {bore}")
    return chamber_area(bore, rod, rod2, side)


@dataclass(frozen=True)
class CylinderTerms:
    """A cylinder's constants in a context's kind of number (:func:`terms`).

    Attributes
    ----------
    cylinder : Cylinder
    count, eta_mech, eta_hyd : number
        k, η_m, η_h [-].
    p_relief, p_max : number
        Relief setting and largest working pressure p_relief − (Δp_throttle + Δp_line)
        [Pa].
    area_piston, area_rod : number or None
        Chamber areas of one cylinder [m²]; the rod side's is None when the cylinder
        never uses it (its rod may be unknown).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.cylinders import terms
    >>> m = examples.hitch_003()
    >>> t = terms(m.cylinders[0], m.value_of)
    >>> float(t.count), round(float(t.p_max) / 1e6, 1), t.area_rod     # [-], [MPa]
    (2.0, 17.5, None)
    """

    cylinder: "Cylinder"
    count: object
    eta_mech: object
    eta_hyd: object
    p_relief: object
    p_max: object
    area_piston: object
    area_rod: object


def terms(cyl, value) -> CylinderTerms:
    """The constants of cylinder ``cyl`` from ``value(ref)`` (a number or parameter name
    → its value in the caller's kind of number).

    Examples
    --------
    The double-rod cylinder of seed 001 lab 4's modernised steering (illustrative):

    >>> from assur import examples
    >>> from assur.core.cylinders import terms
    >>> m = examples.steering_lab4_modern()
    >>> t = terms(m.cylinders[0], m.value_of)
    >>> round(float(t.area_piston) * 1e4, 2), round(float(t.area_rod) * 1e4, 2)   # [cm²]
    (65.97, 65.97)
    """
    v = value
    bore, rod2 = v(cyl.bore), v(cyl.rod2)
    a_p = chamber_area(bore, 0.0, rod2, "piston") if cyl.side != "rod" else None
    a_r = chamber_area(bore, v(cyl.rod), 0.0, "rod") if cyl.side != "piston" else None
    p_relief = v(cyl.p_relief)
    return CylinderTerms(cyl, v(cyl.count), v(cyl.eta_mech), v(cyl.eta_hyd), p_relief,
                         p_relief - (v(cyl.dp_throttle) + v(cyl.dp_line)), a_p, a_r)


def chamber_sign(t: CylinderTerms, F, select: Callable):
    """σ: +1 where the piston side is pressurised (the cylinder pushes), −1 where the
    rod side is (it pulls); for ``side = "auto"`` the sign of the actuator force F
    the loads need [-].

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.cylinders import chamber_sign, select_array, terms
    >>> m = examples.steering_lab4_modern()
    >>> t = terms(m.cylinders[0], m.value_of)
    >>> chamber_sign(t, [500.0, -20.0], select_array).tolist()     # side = "auto"
    [1.0, -1.0]
    """
    side = t.cylinder.side
    if side == "auto":
        return select(F, 1.0, -1.0)
    return 1.0 if side == "piston" else -1.0


def working_area(t: CylinderTerms, F, select: Callable):
    """Area of the pressurised chamber of one cylinder [m²] (:func:`chamber_sign`).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.cylinders import select_array, terms, working_area
    >>> m = examples.hitch_003()
    >>> round(float(working_area(terms(m.cylinders[0], m.value_of), 1.0, select_array)), 6)
    0.005027
    """
    side = t.cylinder.side
    if side == "auto":
        return select(F, t.area_piston, t.area_rod)
    return t.area_piston if side == "piston" else t.area_rod


def pressure(t: CylinderTerms, F, select: Callable):
    """Pressure in the pressurised chamber, p = σ·F/(η_m·k·A·η_h) [Pa], for the
    actuator force F [N] the loads need (seed 003: Pgc = Fgc/(k_gc·S_gc·η)).

    Examples
    --------
    Seed 003 table 4.1, Fgc = 129 614 N at S = 0.42 m (the table's Pgc = 15.349 MPa):

    >>> from assur import examples
    >>> from assur.core.cylinders import pressure, select_array, terms
    >>> m = examples.hitch_003()
    >>> round(float(pressure(terms(m.cylinders[0], m.value_of), 129614.0, select_array)) / 1e6, 3)
    15.349
    """
    s = chamber_sign(t, F, select)
    return s * F / (t.eta_mech * t.count * working_area(t, F, select) * t.eta_hyd)


def force_max(t: CylinderTerms, F, select: Callable, p=None):
    """Largest force of the k cylinders in their working chamber, k·p·A·η_h [N]
    (p: the largest working pressure unless given).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.cylinders import force_max, select_array, terms
    >>> m = examples.hitch_003()
    >>> round(float(force_max(terms(m.cylinders[0], m.value_of), 1.0, select_array)))  # [N]
    147781
    """
    p = t.p_max if p is None else p
    return t.count * p * working_area(t, F, select) * t.eta_hyd


def stroke_work(F_payload, F, axis=-1):
    """W: the payload's actuator force summed over the positions of a stroke [N] —
    its virtual work along the stroke per unit step — whose sign is the working
    direction of a ``side = "auto"`` cylinder (W ≥ 0: extend, the piston side works;
    W < 0: retract, the rod side). Without a payload (W = 0: only dead loads, or no
    loads) the sum of all the loads' force F decides. Over numpy arrays whose
    ``axis`` holds the positions of one stroke (kept, of length 1).

    Parameters
    ----------
    F_payload : array_like
        Actuator force of the loads that are not dead loads, F − F_dead [N], over the
        positions.
    F : array_like
        Actuator force of all the loads [N], same shape.
    axis : int
        The positions' axis.

    Examples
    --------
    A payload whose force changes sign near the end of the stroke (a Z-bar bucket
    passing over its pivot): one working direction for the whole stroke.

    >>> from assur.core.cylinders import stroke_work
    >>> stroke_work([[900.0, 400.0, -200.0]], [[1000.0, 500.0, -100.0]]).tolist()   # [N]
    [[1100.0]]
    >>> stroke_work([[0.0, 0.0]], [[-50.0, -70.0]]).tolist()   # dead loads only [N]
    [[-120.0]]
    """
    wp = np.sum(np.asarray(F_payload, float), axis=axis, keepdims=True)
    wa = np.sum(np.asarray(F, float), axis=axis, keepdims=True)
    return np.where(wp != 0.0, wp, wa)


def capacity(t: CylinderTerms, W, F_dead, I, select: Callable, p=None):
    """Lift capacity at a point in the working direction, G = (σ_w·F_max,w·η_m −
    F_dead)/I [N]: the vertical load at the point the cylinders lift (or hold) at
    pressure ``p`` (default p_max) with the chamber of the stroke's working direction
    σ_w, I = ∂Y/∂q of the point along the cylinder's coordinate, F_dead the actuator
    force of the dead loads (0 for none). W decides the working chamber of
    ``side = "auto"`` (:func:`stroke_work`, one value per stroke); a declared side
    ignores it.

    Examples
    --------
    Seed 003 table 4.1 at S = 0.42 m: I56 = 4.4594 (G56), IS6 = 4.7133 (GS6):

    >>> from assur import examples
    >>> from assur.core.cylinders import capacity, select_array, terms
    >>> m = examples.hitch_003()
    >>> t = terms(m.cylinders[0], m.value_of)
    >>> round(float(capacity(t, 1.0, 0.0, 4.7133, select_array)))   # GS6 [N]
    31354

    A pulling cylinder (``side = "rod"``, D = 80 mm, d = 40 mm, one cylinder at
    17.5 MPa): the point rises as it shortens, I < 0, and the capacity is positive:

    >>> from assur.core.cylinders import Cylinder
    >>> pull = terms(Cylinder("pull", coordinate="S", bore=0.08, rod=0.04, side="rod",
    ...                       p_relief=17.5e6), float)
    >>> round(float(capacity(pull, 0.0, 0.0, -2.0, select_array)))  # F_max,r/|I| [N]
    32987
    """
    s = chamber_sign(t, W, select)
    return (s * force_max(t, W, select, p) * t.eta_mech - F_dead) / I


def reserve(G, P):
    """Capacity reserve ΔG = (G − P)/P·100 [%] for a payload P [N] (seed 003 ΔGS65):
    G (:func:`capacity`) has already carried the dead loads, so P is the payload
    alone, never a dead load.

    Examples
    --------
    >>> from assur.core.cylinders import reserve
    >>> round(reserve(31354.0, 27500.0), 1)       # ΔGS65 at S = 0.42 m, table 4.1 [%]
    14.0
    """
    return (G - P) / P * 100.0


def line_area(members):
    """Effective area of a supply line along the driving coordinate,
    Σ σ_i·k_i·A_i·η_h,i·∂L_i/∂q [m²], of ``members``: ``(terms, rate)`` pairs, rate the
    cylinder's ∂L/∂q (1 for the driving cylinder). A line's cylinders each use one
    declared chamber.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.cylinders import line_area, terms
    >>> m = examples.steering_lab4()
    >>> a, b = (terms(c, m.value_of) for c in m.cylinders)
    >>> round(float(line_area([(a, 1.0), (b, 0.0)])) * 1e4, 3)   # the driver alone [cm²]
    31.172
    """
    total = 0.0
    for t, rate in members:
        s = 1.0 if t.cylinder.side == "piston" else -1.0
        a = t.area_piston if s > 0 else t.area_rod
        total = total + s * t.count * a * t.eta_hyd * rate
    return total


def line_pressure(driver: CylinderTerms, F, members):
    """Pressure of a supply line, p = (F/η_m)/Σ σ_i·k_i·A_i·η_h,i·∂L_i/∂q [Pa] (seed 001
    lab 4 eq. 15 with the exact analogs), F the actuator force of the loads along the
    driving cylinder's coordinate [N], ``members`` as for :func:`line_area`.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.cylinders import line_pressure, terms
    >>> m = examples.steering_lab4()
    >>> a, b = (terms(c, m.value_of) for c in m.cylinders)
    >>> round(float(line_pressure(a, 1000.0, [(a, 1.0)])) / 1e3, 1)   # the driver alone [kPa]
    320.8
    """
    return F / driver.eta_mech / line_area(members)
