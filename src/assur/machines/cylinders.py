"""Cylinders over the positions of an analysis: forces, pressure, capacity, reserve.

The results the reports and the page show (:class:`CylinderResult`, one per
cylinder group; :class:`SupplyLine`, cylinders sharing one pressure). Every number
is a formula of :mod:`assur.core.cylinders` — the one home of a cylinder's
quantities, which the outputs kernel, the design criteria, the sensitivities and the
lift test call too — evaluated on the analysis' arrays: the actuator force F of the
loads by virtual work, the transmission numbers I = ∂Y/∂q and the actuator force of
the dead loads.

The pressure is that of the chamber holding the loads at each position; the capacity
and reserve are in the working direction of the stroke, the same chamber at every
position of it (:mod:`assur.core.cylinders`, its sign diagram).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np

from ..core import cylinders as C
from ..core.cylinders import piston_area
from ..errors import ModelError, SingularPositionError

__all__ = ["piston_area", "CylinderResult", "SupplyLine", "cylinder_results",
           "supply_pressure_from_reactions"]


class CylinderResult:
    """Forces, pressure and capacity of one cylinder group over the positions.

    Attributes
    ----------
    cylinder : Cylinder
    area : float or ndarray
        Pressurised area of one cylinder A [m²].
    p_max : float or ndarray
        Largest working pressure [Pa].
    force : ndarray
        Actuator force of the model's loads by virtual work F [N] (all k cylinders).
    force_required : ndarray
        F/η_m [N].
    pressure : ndarray
        F_req/(k·A·η_h) [Pa].
    force_max : float or ndarray
        k·p_max·A·η_h [N].

    Examples
    --------
    >>> from assur import examples
    >>> cyl = examples.hitch_003().analyze([0.42, 0.67]).cylinder("ГЦ")
    >>> [round(float(p)) for p in cyl.pressure]     # Pgc, seed 003 table 4.1 [Pa]
    [15348729, 16063717]
    >>> round(float(cyl.force_max))                  # 2·17.5 MPa·S_gc·0.84 [N]
    147781
    """

    def __init__(self, kin, statics, cyl, g=None):
        self.cylinder = cyl
        #: gravity for the masses among the dead loads [m/s²] (None: the model's)
        self.g = g
        self.kinematics = kin
        self.statics = statics
        mech = kin.mechanism

        def val(ref):
            v = np.asarray(mech.value_of(ref), float)
            if v.ndim == 1 and v.shape[0] > 1:
                v = v.reshape((-1,) + (1,) * (len(kin.shape) - 1))
            elif v.ndim == 1:
                v = v[0]
            return v

        self._val = val
        self.supply_line = None
        # the cylinder's constants do not depend on the positions: made once per
        # mechanism (and shape of its batch), then shared by every analysis of it
        hit = mech.memo(("cylinders", "terms", cyl.name, len(kin.shape)),
                        lambda: (cyl, C.terms(cyl, val)))
        #: the cylinder's constants (:class:`assur.core.cylinders.CylinderTerms`)
        self.terms = hit[1] if hit[0] is cyl else C.terms(cyl, val)
        t = self.terms
        self.count, self.eta_mech, self.eta_hyd, self.p_max = (t.count, t.eta_mech, t.eta_hyd,
                                                               t.p_max)
        if cyl.coordinate is None or statics is None:  # a passive cylinder: its line
            return                                   # sets it (SupplyLine)
        F = self.force = statics.actuator_force(cyl.coordinate)
        self.force_required = F / self.eta_mech
        #: +1 where the piston side is pressurised (push), −1 the rod side (pull)
        self.sign = C.chamber_sign(t, F, C.select_array)
        self.area = C.working_area(t, F, C.select_array)
        self.pressure = C.pressure(t, F, C.select_array)
        self.force_max = C.force_max(t, F, C.select_array)

    def chamber_area(self, side):
        """Area of one chamber of one cylinder [m²]: ``"piston"`` (π·(D² − d2²)/4) or
        ``"rod"`` (π·(D² − d²)/4).

        Examples
        --------
        The left cylinder of seed 001 lab 4's steering (D = 63 mm, d = 32 mm,
        illustrative):

        >>> from assur import examples
        >>> a = examples.steering_lab4().analyze([0.51, 0.662])   # S1 [m]
        >>> cyl = a.cylinders["ГЦ1"]
        >>> round(float(cyl.chamber_area("piston")), 6)   # π·D²/4 [m²]
        0.003117
        >>> round(float(cyl.chamber_area("rod")), 6)      # π·(D² − d²)/4 [m²]
        0.002313
        """
        c = self.cylinder
        return piston_area(self._val(c.bore), self._val(c.rod), side, self._val(c.rod2))

    def share(self, bore=None):
        """Share of the maximum force used, F_req/F_max [-] (seed 000 Табл. 5, for the
        bores D = 80, 63, 50 mm: pass ``bore`` [m] to evaluate a candidate).

        Examples
        --------
        >>> from assur import examples
        >>> cyl = examples.hitch_003().analyze([0.42, 0.67]).cylinder("ГЦ")
        >>> [round(float(v), 3) for v in cyl.share()]             # D = 80 mm [-]
        [0.877, 0.918]
        >>> [round(float(v), 3) for v in cyl.share(bore=0.063)]   # too small: > 1 [-]
        [1.414, 1.48]
        """
        if bore is None:
            return self.force_required / self.force_max
        t = C.terms(dataclasses.replace(self.cylinder, bore=float(bore)), self._val)
        return self.force_required / C.force_max(t, self.force, C.select_array)

    def capacity(self, point, dead_loads=None, pressure=None, singular="raise"):
        """Lift capacity at ``point`` in the working direction: the vertical load [N] the
        cylinders lift (or hold) there at p_max, G = (σ_w·F_max,w·η_m − F_dead)/I(point),
        I = ∂Y/∂q along this cylinder's coordinate q, σ_w and F_max,w of the working
        chamber (:attr:`working_sign`, :func:`assur.core.cylinders.capacity`); positive
        for a pulling cylinder as for a pushing one.

        Parameters
        ----------
        point : str
            A point this cylinder moves (:func:`assur.machines.capacity.lifts`).
        dead_loads : Mechanism or sequence of str, optional
            Loads carried besides the load at the point (seed 001 lab 1 eq. 14: the
            boom's own weight): a mechanism whose loads they are, or the names of
            links whose loads they are (:func:`assur.machines.capacity.dead_load_mechanism`);
            ``()`` for none. Default: the model's dead loads (``[tables]
            dead_loads``), none if it declares none (seed 003 G56, GS6).
        pressure : float, optional
            The pressure [Pa] instead of p_max (the standard lift test's share of the
            relief setting, :mod:`assur.machines.hitch_lift`).
        singular : {"raise", "empty"}
            Where the point does not rise (I = 0): raise, or leave the value empty
            (NaN, a table's empty cell; :mod:`assur.views.report.tables`).

        Raises
        ------
        ModelError
            If this cylinder does not move ``point`` (the capacity is undefined).
        SingularPositionError
            If the point does not rise at some position (I = 0 there).

        Examples
        --------
        >>> from assur import examples
        >>> cyl = examples.hitch_003().analyze([0.42, 0.67]).cylinder("ГЦ")
        >>> [round(float(g)) for g in cyl.capacity("56")]   # G56, seed 003 table 4.1 [N]
        [33139, 56377]
        >>> [round(float(g)) for g in cyl.capacity("S6")]   # GS6, table 4.1 [N]
        [31354, 29959]
        >>> cyl.capacity("07")   # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: hitch_003: capacity of cylinder 'ГЦ' on S at '07' is undefined...
        """
        from .capacity import check_lifts, dead_load_mechanism
        kin = self.kinematics
        if self.supply_line is not None:
            raise ModelError(f"cylinder {self.cylinder.name!r} shares the supply line "
                             f"{self.supply_line!r}: its capacity at one point is not "
                             f"defined (the line's pressure is)")
        check_lifts(kin.mechanism, self.cylinder.coordinate, point, self.cylinder.name)
        if dead_loads is None or not hasattr(dead_loads, "loads"):
            dead_loads = dead_load_mechanism(kin.mechanism, dead_loads)
        I = kin.transmission(point, wrt=self.cylinder.coordinate if kin.k > 1 else None)
        bad = np.abs(I) <= 1e-12 * np.max(np.abs(I))
        if singular == "empty":
            fdead = self._dead_force(dead_loads)
            G = C.capacity(self.terms, self.stroke_load, fdead, np.where(bad, 1.0, I),
                           C.select_array, p=pressure)
            return np.where(bad, np.nan, G)
        if np.any(bad):
            raise SingularPositionError(f"capacity at {point!r}: its transmission number is 0 "
                                        f"at {int(bad.sum())} position(s) (the point does not "
                                        f"rise there)")
        fdead = self._dead_force(dead_loads)
        return C.capacity(self.terms, self.stroke_load, fdead, I, C.select_array, p=pressure)

    def _dead_force(self, dead):
        """Actuator force of the loads of mechanism ``dead`` along this cylinder's
        coordinate [N], in the kinematics' shape (0.0 for None)."""
        if dead is None:
            return 0.0
        from ..core.statics import virtual_work_forces
        kin = self.kinematics
        g = kin.mechanism.g if self.g is None else self.g
        f = virtual_work_forces(_with_loads(kin, dead), g=g)[self.cylinder.coordinate]
        return kin.reshape(np.broadcast_to(f, (kin.m, kin.n)))

    @functools.cached_property
    def stroke_load(self):
        """W, the payload's actuator force summed over the positions of each design's
        stroke [N] (:func:`assur.core.cylinders.stroke_work`): its sign is the working
        direction of a ``side = "auto"`` cylinder — one chamber for the capacity at
        every position — in the kinematics' shape. The payload: the model's loads but
        its dead loads (``[tables] dead_loads``).

        Examples
        --------
        >>> from assur import examples
        >>> cyl = examples.hitch_003().analyze([0.42, 0.67]).cylinder("ГЦ")
        >>> [round(float(w)) for w in cyl.stroke_load]     # Fgc(0.42) + Fgc(0.67) [N]
        [265266, 265266]
        """
        from .capacity import dead_load_mechanism
        kin = self.kinematics
        F = np.broadcast_to(np.asarray(self.force, float).reshape(kin.m, kin.n), (kin.m, kin.n))
        fd = self._dead_force(dead_load_mechanism(kin.mechanism))
        fd = np.broadcast_to(np.reshape(fd, (kin.m, kin.n)) if np.ndim(fd) else fd, F.shape)
        W = C.stroke_work(F - fd, F, axis=1)
        return kin.reshape(np.broadcast_to(W, (kin.m, kin.n)))

    @property
    def working_sign(self):
        """σ_w of the working direction: +1 the cylinder extends to do the work (its
        piston side), −1 it retracts (its rod side) — declared by ``side``, or for
        ``"auto"`` from :attr:`stroke_load`; the kinematics' shape (a number for a
        declared side).

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().analyze([0.42, 0.67]).cylinder("ГЦ").working_sign
        1.0
        """
        if self.cylinder.side != "auto":
            return C.chamber_sign(self.terms, 1.0, C.select_array)
        return C.chamber_sign(self.terms, self.stroke_load, C.select_array)

    def reserve(self, point, P):
        """Capacity reserve (G − P)/P·100 [%] for a payload P [N] at the point (003 ΔGS65):
        G, in the working direction, has carried the model's dead loads already.

        Examples
        --------
        >>> from assur import examples
        >>> cyl = examples.hitch_003().analyze([0.42, 0.67]).cylinder("ГЦ")
        >>> [round(float(v), 1) for v in cyl.reserve("S6", 27500.0)]  # ΔGS65, table 4.1 [%]
        [14.0, 8.9]
        """
        return C.reserve(self.capacity(point), P)


def _with_loads(kin, mech_with_loads):
    """The kinematics ``kin`` seen with another mechanism's loads (same geometry)."""
    import copy
    k2 = copy.copy(kin)
    k2.mechanism = mech_with_loads
    return k2


class SupplyLine:
    """Cylinders on one supply line: one pressure, solved by virtual work with every
    cylinder of the line as an actuator (seed 001 lab 4 eqs. 13–15).

    The line's one driving cylinder (a) drives the coordinate q; the passive ones (i)
    have lengths L_i(q) the mechanism determines (named distances). With the chamber
    signs σ (+1 piston side, −1 rod side), counts k, areas A and efficiencies η_h::

        p · [σ_a·k_a·A_a·η_h,a + Σ_i σ_i·k_i·A_i·η_h,i·∂L_i/∂q] = F / η_m,a

    F the actuator force of the loads along q by virtual work. The rod force of each
    cylinder is then σ·p·k·A·η_h (positive pushing). A negative p means the loads
    drive the cylinders the other way: the line of the other chambers is the one
    pressurised (seed 001 lab 4: the other turn).

    Attributes
    ----------
    name : str
    coordinate : str
    pressure : ndarray
        The line's pressure p [Pa], shape of the kinematics.
    members : dict of str to CylinderResult
        Every cylinder of the line, with ``pressure`` = p, ``force`` and
        ``force_required`` its rod force [N] and ``rate`` = ∂L/∂q [-].

    Examples
    --------
    Seed 001 lab 4's steering (illustrative dimensions): the left cylinder ГЦ1 drives
    S1, the passive right one ГЦ2 pulls with its rod side on the same line "P".

    >>> from assur import examples
    >>> from assur.machines.cylinders import SupplyLine
    >>> a = examples.steering_lab4().analyze([0.51, 0.662])        # S1 [m]
    >>> line = SupplyLine(a.kinematics, a.statics, "P", a.mechanism.cylinders)
    >>> line.coordinate, list(line.members)
    ('S1', ['ГЦ1', 'ГЦ2'])
    >>> [round(float(p) / 1e6, 3) for p in line.pressure]          # [MPa]
    [6.353, 8.294]
    >>> [round(float(f)) for f in line.members["ГЦ2"].force]       # pulls [N]
    [-14694, -19184]
    """

    def __init__(self, kin, statics, name, cylinders):
        self.name = name
        active = [c for c in cylinders if c.coordinate is not None]
        if len(active) != 1:
            raise ModelError(f"supply line {name!r}: expected exactly one cylinder that drives "
                             f"a coordinate, found {len(active)}")
        a = active[0]
        self.coordinate = a.coordinate
        wrt = a.coordinate if kin.k > 1 else None
        self.members = {}
        for c in cylinders:
            r = CylinderResult(kin, None, c)
            r.supply_line = name
            r.sign = 1.0 if c.side == "piston" else -1.0
            r.area = r.terms.area_piston if c.side == "piston" else r.terms.area_rod
            r.rate = 1.0 if c is a else kin.dlength(c.distance, wrt=wrt)
            r.force_max = C.force_max(r.terms, r.sign, C.select_array)
            self.members[c.name] = r
        members = [(r.terms, r.rate) for r in self.members.values()]
        #: Σ σ·k·A·η_h·∂L/∂q [m²]: the line's effective area along q
        self.effective_area = C.line_area(members) * np.ones(kin.shape)
        ra = self.members[a.name]
        F = statics.actuator_force(a.coordinate)
        bad = self.effective_area == 0
        if np.any(bad):
            raise SingularPositionError(
                f"supply line {name!r}: the cylinders' effective area along "
                f"{a.coordinate!r} is 0 at {int(bad.sum())} position(s): the line's pressure "
                f"does no work there")
        self.pressure = C.line_pressure(ra.terms, F, members) * np.ones(kin.shape)
        for r in self.members.values():
            r.pressure = self.pressure
            r.force_required = r.sign * self.pressure * r.count * r.area * r.eta_hyd
            r.force = r.force_required


def cylinder_results(kin, statics, g=None):
    """``{name: CylinderResult}`` of every cylinder of the mechanism, in their order;
    the cylinders of a supply line share its pressure (:class:`SupplyLine`).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.cylinders import cylinder_results
    >>> a = examples.hitch_003().analyze([0.42])
    >>> res = cylinder_results(a.kinematics, a.statics)
    >>> list(res), round(float(res["ГЦ"].force[0]))     # Fgc, seed 003 table 4.1 [N]
    (['ГЦ'], 129614)
    >>> a = examples.steering_lab4().analyze([0.51])   # two cylinders on line "P"
    >>> res = cylinder_results(a.kinematics, a.statics)
    >>> [(name, r.supply_line) for name, r in res.items()]
    [('ГЦ1', 'P'), ('ГЦ2', 'P')]
    """
    mech = kin.mechanism
    lines = {}
    for c in mech.cylinders:
        if c.supply is not None:
            lines.setdefault(c.supply, []).append(c)
    solved = {}
    for name, cyls in lines.items():
        solved.update(SupplyLine(kin, statics, name, cyls).members)
    return {c.name: solved[c.name] if c.name in solved else CylinderResult(kin, statics, c, g=g)
            for c in mech.cylinders}


def supply_pressure_from_reactions(kin, line, g=None):
    """The pressure of a supply line from the joint reactions [Pa] — the check of
    :class:`SupplyLine`'s virtual work by the second route (DESIGN.md §4).

    The reverse-order pass gives the driving cylinder's force F_r that holds the
    loads, and F_u that holds the passive cylinders' pushes at a unit pressure
    (each applied to its two pins as an axial force σ·k·A·η_h). The driving cylinder
    supplies σ_a·k_a·A_a·η_h,a·p = F_r/η_m + p·F_u, so
    p = (F_r/η_m)/(σ_a·k_a·A_a·η_h,a − F_u).

    Parameters
    ----------
    kin : Kinematics
        Of a mechanism with the cylinders of ``line``.
    line : str
        The supply line's name.
    g : float, optional
        Gravity [m/s²] (default: the mechanism's).

    Examples
    --------
    The steering of seed 001 lab 4 (illustrative dimensions): the same pressure as
    the virtual work of :class:`SupplyLine`.

    >>> from assur import examples
    >>> from assur.machines.cylinders import supply_pressure_from_reactions
    >>> a = examples.steering_lab4().analyze([0.51, 0.662])        # S1 [m]
    >>> p = supply_pressure_from_reactions(a.kinematics, "P")
    >>> [round(float(v) / 1e6, 3) for v in p]                      # [MPa]
    [6.353, 8.294]
    >>> float(abs(p - a.cylinders["ГЦ1"].pressure).max()) < 1e-3   # [Pa]
    True
    >>> supply_pressure_from_reactions(a.kinematics, "Q")
    Traceback (most recent call last):
    ...
    KeyError: "no supply line 'Q'; lines: ['P']"
    """
    from ..core import statics as st
    mech = kin.mechanism
    cyls = [c for c in mech.cylinders if c.supply == line]
    if not cyls:
        raise KeyError(f"no supply line {line!r}; lines: "
                       f"{sorted({c.supply for c in mech.cylinders if c.supply})}")
    g = mech.g if g is None else g
    a = next(c for c in cyls if c.coordinate is not None)
    loads_r = st.solve(kin, g=g, method="array").actuator_force_from_reactions(a.coordinate)
    dist = {d.name: d for d in mech.distances}
    unit = mech.with_loads()
    for c in cyls:
        if c is a:
            continue
        push = C.line_area([(CylinderResult(kin, None, c).terms, 1.0)])  # σ·k·A·η_h [m²]
        d = dist[c.distance]
        # an axial push P of the passive cylinder: a spring of constant tension −P
        unit = unit.spring(f"{c.name} at 1 Pa", d.a, d.b, 0.0, 0.0,
                           float(np.asarray(-push).ravel()[0]))
    ku = _with_loads(kin, unit)
    unit_r = st.solve(ku, g=g, method="array").actuator_force_from_reactions(a.coordinate)
    ra = CylinderResult(kin, None, a)
    own = C.line_area([(ra.terms, 1.0)])
    return (loads_r / ra.eta_mech) / (own - unit_r)
