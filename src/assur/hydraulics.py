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
* capacity reserve ΔG = (G − P)/P·100 % (seed 003 ΔGS65).
"""

from __future__ import annotations

import math

import numpy as np

from .errors import SingularPositionError

__all__ = ["piston_area", "CylinderResult"]


def piston_area(bore, rod=0.0, side="piston"):
    """Pressurised area [m²] of a cylinder with bore D and rod d [m]."""
    if side not in ("piston", "rod"):
        raise ValueError("side must be one of: ['piston', 'rod']")
    bore = np.asarray(bore, float)
    if np.any(bore <= 0):
        raise ValueError(f"bore must be positive, got {bore}")
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
        self.count = val(cyl.count)
        self.eta_mech = val(cyl.eta_mech)
        self.eta_hyd = val(cyl.eta_hyd)
        self.area = piston_area(val(cyl.bore), val(cyl.rod), cyl.side)
        self.p_max = val(cyl.p_relief) - (val(cyl.dp_throttle) + val(cyl.dp_line))
        self.force = statics.actuator_force(cyl.coordinate)
        self.force_required = self.force / self.eta_mech
        self.pressure = self.force_required / (self.count * self.area * self.eta_hyd)
        self.force_max = self.count * self.p_max * self.area * self.eta_hyd

    def share(self, bore=None):
        """Share of the maximum force used, F_req/F_max [-] (seed 000 Табл. 5, for the
        bores D = 80, 63, 50 mm: pass ``bore`` [m] to evaluate a candidate)."""
        if bore is None:
            return self.force_required / self.force_max
        fmax = self.count * self.p_max * piston_area(bore, self._val(self.cylinder.rod),
                                                     self.cylinder.side) * self.eta_hyd
        return self.force_required / fmax

    def capacity(self, point, dead_loads=None):
        """Lift capacity at ``point``: the vertical load [N] the cylinders hold there at
        p_max, G = (F_max·η_m − F_dead)/I(point), I = ∂Y/∂q along this cylinder's
        coordinate q.

        Parameters
        ----------
        point : str
            A point this cylinder moves (:func:`assur.capacity.lifts`).
        dead_loads : Mechanism or sequence of str, optional
            Loads carried besides the load at the point (seed 001 lab 1 eq. 14: the
            boom's own weight): a mechanism whose loads they are, or the names of
            links whose loads they are (:func:`assur.capacity.dead_load_mechanism`);
            ``()`` for none. Default: the model's dead loads (``[tables]
            dead_loads``), none if it declares none (seed 003 G56, GS6).

        Raises
        ------
        ModelError
            If this cylinder does not move ``point`` (the capacity is undefined).
        SingularPositionError
            If the point does not rise at some position (I = 0 there).
        """
        from .capacity import check_lifts, dead_load_mechanism
        kin = self.kinematics
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
            from .statics import virtual_work_forces
            kd = _with_loads(kin, dead_loads)
            from .analysis import gravity_of
            g = gravity_of(kin.mechanism) if self.g is None else self.g
            f = virtual_work_forces(kd, g=g)[self.cylinder.coordinate]
            fdead = kin.reshape(np.broadcast_to(f, (kin.m, kin.n)))
        return (self.force_max * self.eta_mech - fdead) / I

    def reserve(self, point, P):
        """Capacity reserve (G − P)/P·100 [%] for a load P [N] at the point (003 ΔGS65)."""
        return (self.capacity(point) - P) / P * 100.0


def _with_loads(kin, mech_with_loads):
    """The kinematics ``kin`` seen with another mechanism's loads (same geometry)."""
    import copy
    k2 = copy.copy(kin)
    k2.mechanism = mech_with_loads
    return k2
