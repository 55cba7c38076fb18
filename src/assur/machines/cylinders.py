"""Hydraulic cylinders: areas, working pressure, available force, lift capacity.

Formulas (SI: m, N, Pa):

* piston area A = π·D²/4, or the annulus π·(D² − d²)/4 on the rod side;
* largest working pressure p_max = p_relief − (Δp_throttle + Δp_line)
  (seed 001 lab 1 eq. 1);
* force the rods must supply F_req = F/η_m, with F the actuator force of the
  loads by virtual work (seed 000: FS = P·Is/km);
* pressure p = F_req/(k·A·η_h) (seed 003: Pgc = Fgc/(k_gc·S_gc·η));
* available force F_max = k·p_max·A·η_h (seed 000: Fmax = p·SS·kg, there in kgf);
* lift capacity at a point, the vertical load the cylinders hold at p_max:
  G = (F_max·η_m − F_dead)/I with I = dY/dS of the point and F_dead the actuator
  force of the loads carried besides it (seed 003: G56 = k·p·η·S_gc/I56,
  GS6 with IS6; seed 001 lab 1 eqs. 8–10, 14 with the boom's weight);
* capacity reserve ΔG = (G − P)/P·100 % (seed 003 ΔGS65);
* cylinders on one supply line (:class:`SupplyLine`) share one pressure p; by
  virtual work with every cylinder of the line as an actuator,
  p·Σ σ_i·k_i·A_i·η_h,i·∂L_i/∂q = F/η_m, σ = +1 for a pressurised piston side
  (push), −1 for a rod side (pull), L_i the cylinder's length (the coordinate q
  itself for the driving cylinder, a named distance for a passive one) — seed 001
  lab 4 eq. 15, p_н = M_c·(φ3′ + φ5′)/(π·(2R² − r²)), with the exact analogs;
* a double-rod cylinder pushes with π·(D² − d2²)/4 and pulls with π·(D² − d²)/4.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import ModelError, SingularPositionError

__all__ = ["piston_area", "CylinderResult", "SupplyLine", "cylinder_results",
           "supply_pressure_from_reactions"]


def piston_area(bore, rod=0.0, side="piston", rod2=0.0):
    """Pressurised area [m²] of a cylinder with bore D and rod d [m]: π·D²/4 on the
    piston side, π·(D² − d²)/4 on the rod side; a double-rod cylinder's piston side
    is the annulus around its second rod d2, π·(D² − d2²)/4.

    Examples
    --------
    >>> from assur.machines.cylinders import piston_area
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
    rod2 = np.asarray(rod2, float)
    if side == "piston" and np.any(rod2 != 0):
        if np.any(rod2 >= bore) or np.any(rod2 < 0):
            raise ValueError(f"a double-rod cylinder needs 0 < rod2 < bore, got rod2 {rod2}, "
                             f"bore {bore}")
        return 0.25 * math.pi * (bore**2 - rod2**2)
    if side == "rod":
        rod = np.asarray(rod, float)
        if np.any(rod >= bore) or np.any(rod <= 0):
            raise ValueError(f"rod side needs 0 < rod < bore, got rod {rod}, bore {bore}")
        return 0.25 * math.pi * (bore**2 - rod**2)
    return 0.25 * math.pi * bore**2


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
        # the cylinder's numbers do not depend on the positions: made once per
        # mechanism (and shape of its batch), then shared by every analysis of it
        key = (cyl.name, len(kin.shape))
        hit = mech.memo(("hydraulics: constants",) + key, lambda: (cyl, self._constants()))
        const = hit[1] if hit[0] is cyl else self._constants()
        self.count, self.eta_mech, self.eta_hyd, self.p_max = const
        if cyl.coordinate is None or statics is None:  # a passive cylinder: its line
            return                                   # sets it (SupplyLine)
        hit = mech.memo(("hydraulics: areas",) + key, lambda: (cyl, self._areas()))
        areas = hit[1] if hit[0] is cyl else self._areas()
        self.force = statics.actuator_force(cyl.coordinate)
        self.force_required = self.force / self.eta_mech
        if cyl.side == "auto":  # the chamber that gives the force's sign (double rod)
            #: +1 where the piston side is pressurised (push), −1 the rod side (pull)
            self.sign = np.where(self.force >= 0, 1.0, -1.0)
            self.area = np.where(self.sign > 0, areas["piston"], areas["rod"])
            self.pressure = np.abs(self.force_required) / (self.count * self.area
                                                           * self.eta_hyd)
            self.force_max = self.count * self.p_max * self.area * self.eta_hyd
        else:
            self.sign = 1.0 if cyl.side == "piston" else -1.0
            self.area = areas[cyl.side]
            # k·A·η_h and the largest force k·p_max·A·η_h do not depend on the positions
            hit = mech.memo(("hydraulics: one chamber",) + key, lambda: (
                cyl, self.count * self.area * self.eta_hyd,
                self.count * self.p_max * self.area * self.eta_hyd))
            kae, self.force_max = hit[1:] if hit[0] is cyl else (
                self.count * self.area * self.eta_hyd,
                self.count * self.p_max * self.area * self.eta_hyd)
            self.pressure = self.force_required / kae

    def _constants(self):
        """count, η_m, η_h and p_max [Pa] from the mechanism's parameters."""
        cyl, val = self.cylinder, self._val
        return (val(cyl.count), val(cyl.eta_mech), val(cyl.eta_hyd),
                val(cyl.p_relief) - (val(cyl.dp_throttle) + val(cyl.dp_line)))

    def _areas(self):
        """The areas [m²] of the chambers the cylinder uses (both for ``side =
        "auto"``)."""
        sides = ("piston", "rod") if self.cylinder.side == "auto" else (self.cylinder.side,)
        return {sd: self.chamber_area(sd) for sd in sides}

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
        c = self.cylinder
        rod, rod2 = self._val(c.rod), self._val(c.rod2)
        if c.side == "auto":
            area = np.where(self.sign > 0, piston_area(bore, rod, "piston", rod2),
                            piston_area(bore, rod, "rod"))
        else:
            area = piston_area(bore, rod, c.side, rod2)
        fmax = self.count * self.p_max * area * self.eta_hyd
        return self.force_required / fmax

    def capacity(self, point, dead_loads=None):
        """Lift capacity at ``point``: the vertical load [N] the cylinders hold there at
        p_max, G = (F_max·η_m − F_dead)/I(point), I = ∂Y/∂q along this cylinder's
        coordinate q.

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
        if np.any(bad):
            raise SingularPositionError(f"capacity at {point!r}: its transmission number is 0 "
                                        f"at {int(bad.sum())} position(s) (the point does not "
                                        f"rise there)")
        fdead = 0.0
        if dead_loads is not None:
            from ..core.statics import virtual_work_forces
            kd = _with_loads(kin, dead_loads)
            from ..analysis import gravity_of
            g = gravity_of(kin.mechanism) if self.g is None else self.g
            f = virtual_work_forces(kd, g=g)[self.cylinder.coordinate]
            fdead = kin.reshape(np.broadcast_to(f, (kin.m, kin.n)))
        return (self.force_max * self.eta_mech - fdead) / I

    def reserve(self, point, P):
        """Capacity reserve (G − P)/P·100 [%] for a load P [N] at the point (003 ΔGS65).

        Examples
        --------
        >>> from assur import examples
        >>> cyl = examples.hitch_003().analyze([0.42, 0.67]).cylinder("ГЦ")
        >>> [round(float(v), 1) for v in cyl.reserve("S6", 27500.0)]  # ΔGS65, table 4.1 [%]
        [14.0, 8.9]
        """
        return (self.capacity(point) - P) / P * 100.0


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
        den = 0.0
        for c in cylinders:
            r = CylinderResult(kin, statics, c)
            r.supply_line = name
            r.sign = 1.0 if c.side == "piston" else -1.0
            r.area = r.chamber_area(c.side)
            r.rate = 1.0 if c is a else kin.dlength(c.distance, wrt=wrt)
            r.force_max = r.count * r.p_max * r.area * r.eta_hyd
            den = den + r.sign * r.count * r.area * r.eta_hyd * r.rate
            self.members[c.name] = r
        #: Σ σ·k·A·η_h·∂L/∂q [m²]: the line's effective area along q
        self.effective_area = den * np.ones(kin.shape)
        ra = self.members[a.name]
        F = statics.actuator_force(a.coordinate)
        bad = self.effective_area == 0
        if np.any(bad):
            raise SingularPositionError(
                f"supply line {name!r}: the cylinders' effective area along "
                f"{a.coordinate!r} is 0 at {int(bad.sum())} position(s): the line's pressure "
                f"does no work there")
        self.pressure = F / ra.eta_mech / self.effective_area
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
    from ..analysis import gravity_of
    mech = kin.mechanism
    cyls = [c for c in mech.cylinders if c.supply == line]
    if not cyls:
        raise KeyError(f"no supply line {line!r}; lines: "
                       f"{sorted({c.supply for c in mech.cylinders if c.supply})}")
    g = gravity_of(mech) if g is None else g
    a = next(c for c in cyls if c.coordinate is not None)
    loads_r = st.solve(kin, g=g, method="array").actuator_force_from_reactions(a.coordinate)
    dist = {d.name: d for d in mech.distances}
    unit = mech.with_loads()
    for c in cyls:
        if c is a:
            continue
        r = CylinderResult(kin, None, c)
        push = (1.0 if c.side == "piston" else -1.0) * r.count * r.chamber_area(c.side) \
            * r.eta_hyd
        d = dist[c.distance]
        # an axial push P of the passive cylinder: a spring of constant tension −P
        unit = unit.spring(f"{c.name} at 1 Pa", d.a, d.b, 0.0, 0.0,
                           float(np.asarray(-push).ravel()[0]))
    ku = _with_loads(kin, unit)
    unit_r = st.solve(ku, g=g, method="array").actuator_force_from_reactions(a.coordinate)
    ra = CylinderResult(kin, None, a)
    own = (1.0 if a.side == "piston" else -1.0) * ra.count * ra.chamber_area(a.side) \
        * ra.eta_hyd
    return (loads_r / ra.eta_mech) / (own - unit_r)
