"""Masses of the links, their motion and inertia loads, the reduced moment and the
reduced moment of inertia of a mechanism driven by one coordinate (a crank).

Seed 001 lab 3 (grain-cleaning mechanism): "the kinetostatic analysis is done by
Assur groups in reverse order with the forces and moments of inertia acting on the
links; it gives the reduced moment (the moment acting on the crank L1) over the
crank angle". Here:

* :class:`LinkMass` — a link's mass m [kg], its centre of mass (an existing named
  point, or a point given in the link's own frame: ``along`` its first→second
  point and ``offset`` to the left of that line [m]) and its moment of inertia J
  about the centre [kg·m²]. :func:`with_masses` adds them to a mechanism as
  :class:`assur.core.loads.Mass` loads (a centre given in the link's frame becomes a
  ``rigid_point`` group, so its motion is the engine's exact analogs).
* :func:`crank_dynamics` — one call: the motion of every centre of mass, inertia
  forces ``−m·a_S`` and moments ``−J·ε``, the joint reactions with inertia
  (:func:`assur.core.statics.solve`), the reduced moments and the reduced moment of
  inertia, the common centre of mass (:mod:`assur.dynamics.balancing`), and the flywheel
  (:mod:`assur.dynamics.flywheel`) on request.

Definitions (one coordinate φ, the crank angle [rad]; ω = φ̇, ε = φ̈)::

    J_red(φ)   = Σ [ m·|dr_S/dφ|² + J·(dφ_i/dφ)² ]                     [kg·m²]
    J_red'(φ)  = Σ [ 2m·(dr_S/dφ)·(d²r_S/dφ²) + 2J·(dφ_i/dφ)(d²φ_i/dφ²) ]
    T          = ½·J_red·ω²          (kinetic energy of the links)        [J]
    M_red      = Σ (F·v + M·ω_i)/ω   (reduced moment of the loads)        [N·m]
               = Σ F·dr/dφ + Σ M·dφ_i/dφ      (virtual work, exact analogs)
    M_red,in   = −(J_red·ε + ½·J_red'·ω²)     (of the inertia loads alone)

J_red = Σ[m·|v_S|² + J·ω_i²]/ω² exactly (the velocities are the analogs times ω).
M_red is counter-clockwise positive on the crank; the driving moment the crank's
bearing must supply is ``M_drive = −M_red`` (:meth:`assur.core.statics.Statics.actuator_force`),
and it is found a second time from the joint reactions group by group in reverse
order (:meth:`~assur.core.statics.Statics.actuator_force_from_reactions`). The power
balance ``M_drive·ω + Σ F·v + Σ M·ω_i = 0`` (all loads, inertia included) is
:meth:`CrankDynamics.power_residual`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core import statics as _statics
from ..core.loads import masses_of
from ..errors import ModelError
from .masses import LinkMass, design_value, with_masses

__all__ = ["LinkMass", "with_masses", "masses_of", "MassMotion", "CrankDynamics",
           "crank_dynamics", "reduced_inertia", "design_value"]

@dataclass(frozen=True)
class MassMotion:
    """Motion and inertia loads of one mass over the positions (arrays of the
    kinematics' shape; vectors with a trailing axis of 2).

    Attributes
    ----------
    link, point : str
    m : ndarray
        Mass [kg] (per design).
    J : ndarray
        Moment of inertia about the centre [kg·m²].
    position : ndarray, shape (..., 2)
        Centre of mass r_S [m].
    velocity_analog, acceleration_analog : ndarray, shape (..., 2)
        dr_S/dφ [m/rad], d²r_S/dφ² [m/rad²].
    velocity, acceleration : ndarray, shape (..., 2)
        v_S = r_S'·ω [m/s], a_S = r_S'·ε + r_S''·ω² [m/s²].
    omega, epsilon : ndarray
        Angular velocity ω_i [rad/s] and acceleration ε_i [rad/s²] of the link.
    inertia_force : ndarray, shape (..., 2)
        −m·a_S [N].
    inertia_moment : ndarray
        −J·ε_i [N·m], counter-clockwise positive.

    Examples
    --------
    The rocker 4 of the grain-cleaning mechanism (seed 001 lab 3, illustrative
    masses) over a crank turn at ω = −30 rad/s:

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
    >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
    >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
    >>> s4 = dyn.masses[3]
    >>> s4.link, s4.point, float(s4.m[0]), s4.inertia_force.shape    # [kg]
    ('4', 'S4', 80.0, (73, 2))
    >>> round(float(np.hypot(*s4.acceleration.T).max()), 2)          # largest |a_S4| [m/s²]
    54.08
    """

    link: str
    point: str
    m: np.ndarray
    J: np.ndarray
    position: np.ndarray
    velocity_analog: np.ndarray
    acceleration_analog: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray
    inertia_force: np.ndarray
    inertia_moment: np.ndarray


def _rates(kin, qdot, qddot):
    """q̇, q̈ as (m, n) arrays [rad/s, rad/s²]."""
    shape = (kin.m, kin.n)
    qd = np.asarray(qdot, dtype=float)
    qdd = np.zeros(()) if qddot is None else np.asarray(qddot, dtype=float)
    try:
        qd = np.broadcast_to(qd, kin.shape).reshape(shape)
        qdd = np.broadcast_to(qdd, kin.shape).reshape(shape)
    except ValueError:
        raise ValueError(f"qdot, qddot must be scalars or arrays broadcastable to the "
                         f"positions' shape {kin.shape}, got {np.shape(qdot)} and "
                         f"{np.shape(qddot)}") from None
    if not (np.isfinite(qd).all() and np.isfinite(qdd).all()):
        raise ValueError("qdot and qddot must be finite")
    return qd, qdd


def _single_coordinate(kin, where):
    if kin.k != 1:
        raise ValueError(f"{where} needs a mechanism of one generalized coordinate (a crank); "
                         f"this one has {list(kin.coordinates)}")


def reduced_inertia(kin):
    """Reduced moment of inertia J_red(φ) [kg·m²] and its derivative dJ_red/dφ
    [kg·m²/rad] of the masses of ``kin.mechanism``, arrays (m, n).

    ``J_red = Σ m·|r_S'|² + J·φ_i'²``, ``J_red' = Σ 2m·r_S'·r_S'' + 2J·φ_i'·φ_i''``
    from the exact first- and second-order analogs (' = d/dφ).

    Examples
    --------
    The grain-cleaning mechanism of seed 001 lab 3 (illustrative masses) at
    φ1 = 0° and 90°:

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics.crank import reduced_inertia
    >>> model = io.load(io.bundled("cleaning_lab3"))
    >>> Jr, dJr = reduced_inertia(model.mechanism.solve(np.radians([0.0, 90.0])))
    >>> [round(float(v), 4) for v in Jr[0]]       # J_red [kg·m²]
    [0.0931, 0.6306]
    >>> [round(float(v), 4) for v in dJr[0]]      # dJ_red/dφ [kg·m²/rad]
    [0.5659, -0.6074]
    """
    _single_coordinate(kin, "reduced_inertia")
    Jr = np.zeros((kin.m, kin.n))
    dJr = np.zeros((kin.m, kin.n))
    for ld in masses_of(kin.mechanism):
        m = design_value(kin, ld.m)
        J = design_value(kin, ld.J)
        d1 = kin.jacobian(ld.point)[:, 0]  # (2, m, n)
        d2 = kin.hessian(ld.point)[:, 0, 0]
        w1, w2 = kin.body_rates(ld.link)
        w1, w2 = w1[0], w2[0, 0]
        Jr = Jr + m * (d1[0] ** 2 + d1[1] ** 2) + J * w1 ** 2
        dJr = dJr + 2 * m * (d1[0] * d2[0] + d1[1] * d2[1]) + 2 * J * w1 * w2
    return Jr, dJr


class CrankDynamics:
    """Dynamics of a one-coordinate (crank) mechanism over the positions.

    Produced by :func:`crank_dynamics`. Arrays have the kinematics' shape
    (``(n,)`` for one design, ``(m, n)`` for a batch); vectors add an axis of 2.

    Attributes
    ----------
    kinematics : Kinematics
    coordinate : str
    q : ndarray
        Crank angle φ [rad].
    qdot, qddot : ndarray
        ω [rad/s] and ε [rad/s²] of the crank at every position.
    statics : Statics
        Joint reactions and driving moment *with* the inertia loads.
    statics_without_inertia : Statics
        The same without inertia (weights and applied loads only).
    masses : tuple of MassMotion
    reduced_inertia, reduced_inertia_derivative : ndarray
        J_red [kg·m²] and dJ_red/dφ [kg·m²/rad].
    reduced_moment : ndarray
        M_red of all loads, inertia included [N·m] (virtual work).
    reduced_moment_without_inertia : ndarray
        M_red of the applied loads and weights alone [N·m].
    reduced_moment_of_inertia_loads : ndarray
        The difference: the reduced moment of the inertia loads [N·m]; equals
        −(J_red·ε + ½·J_red'·ω²) (the tests hold it so).
    driving_moment : ndarray
        −M_red: the moment the drive applies to the crank [N·m] (virtual work).
    driving_moment_from_reactions : ndarray
        The same from the joint reactions in reverse order [N·m].
    kinetic_energy : ndarray
        T = ½·J_red·ω² [J].
    centre : CentreOfMassPath
        The common centre of mass of the moving links (:mod:`assur.dynamics.balancing`).

    Examples
    --------
    The grain-cleaning mechanism of seed 001 lab 3 (illustrative masses) over a
    crank turn in steps of 5°:

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
    >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
    >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
    >>> dyn.coordinate, dyn.q.shape, len(dyn.masses)
    ('j1', (73,), 9)
    >>> round(float(dyn.kinetic_energy.max()), 1)        # T [J]
    355.5
    >>> gap = dyn.driving_moment - dyn.driving_moment_from_reactions   # two routes [N·m]
    >>> bool(np.abs(gap).max() < 1e-9)
    True
    """

    def __init__(self, kin, qdot, qddot, g):
        _single_coordinate(kin, "crank_dynamics")
        self.kinematics = kin
        self.coordinate = kin.coordinates[0]
        self.g = g
        if not masses_of(kin.mechanism):
            raise ModelError(f"mechanism {kin.mechanism.name!r} has no masses on moving links: "
                             f"add them (with_masses, [[loads]] type = \"mass\")")
        qd, qdd = _rates(kin, qdot, qddot)
        self._qd, self._qdd = qd, qdd
        o = kin.reshape
        self.q = kin.q()
        self.qdot, self.qddot = o(qd), o(qdd)
        self.statics = _statics.solve(kin, qdot=o(qd), qddot=o(qdd), g=g, method="array")
        self.statics_without_inertia = _statics.solve(kin, g=g, method="array")
        Jr, dJr = reduced_inertia(kin)
        self._Jr, self._dJr = Jr, dJr
        self.reduced_inertia = o(Jr)
        self.reduced_inertia_derivative = o(dJr)
        self.driving_moment = self.statics.actuator_force(self.coordinate)
        self.reduced_moment = -self.driving_moment
        self.reduced_moment_without_inertia = -self.statics_without_inertia.actuator_force(
            self.coordinate)
        self.reduced_moment_of_inertia_loads = (self.reduced_moment
                                                - self.reduced_moment_without_inertia)
        self.driving_moment_from_reactions = self.statics.actuator_force_from_reactions(
            self.coordinate)
        self.kinetic_energy = o(0.5 * Jr * qd ** 2)
        self.masses = tuple(self._motion(ld) for ld in masses_of(kin.mechanism))
        from .balancing import common_centre
        self.centre = common_centre(kin)

    def _motion(self, ld):
        kin, qd, qdd = self.kinematics, self._qd, self._qdd
        o = kin.reshape
        m = design_value(kin, ld.m)
        J = design_value(kin, ld.J)
        d1 = kin.jacobian(ld.point)[:, 0]
        d2 = kin.hessian(ld.point)[:, 0, 0]
        w1, w2 = kin.body_rates(ld.link)
        w1, w2 = w1[0], w2[0, 0]
        v = d1 * qd
        a = d1 * qdd + d2 * qd ** 2
        eps = w1 * qdd + w2 * qd ** 2

        def vec(x):
            return o(np.moveaxis(x, 0, -1))

        return MassMotion(
            link=ld.link, point=ld.point, m=m[:, 0], J=J[:, 0],
            position=vec(kin.value(ld.point)), velocity_analog=vec(d1),
            acceleration_analog=vec(d2), velocity=vec(v), acceleration=vec(a),
            omega=o(w1 * qd), epsilon=o(eps), inertia_force=vec(-m * a),
            inertia_moment=o(-J * eps))

    # ---- views and checks ------------------------------------------------------------
    def reaction(self, i, j, inertia=True):
        """Force of link i on link j at their joint over the positions, shape (..., 2)
        [N] — the hodograph's points (with or without the inertia loads).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.crank import crank_dynamics
        >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
        >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
        >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
        >>> [round(float(v)) for v in dyn.reaction("0", "1")[18]]    # φ1 = 90°, R01 [N]
        [6959, -2844]
        >>> static = dyn.reaction("0", "1", inertia=False)
        >>> [round(float(v), 1) for v in static[18]]                 # [N]
        [125.4, 17.4]
        """
        st = self.statics if inertia else self.statics_without_inertia
        return st.reaction(i, j)

    @property
    def joints(self):
        """Every joint with a reaction: ``[(point, i, j), ...]``.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.crank import crank_dynamics
        >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
        >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
        >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
        >>> len(dyn.joints), ("O1", "0", "1") in dyn.joints    # the crank bearing O1
        (13, True)
        """
        return self.statics.joints

    def power_terms(self):
        """The power of every load [W], shape (terms, …): F·v of each point force
        (weights and inertia forces included) at the velocity of its point, then
        M·ω_i of each moment (inertia moments included) at its link's angular
        velocity.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.crank import crank_dynamics
        >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
        >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
        >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
        >>> dyn.power_terms().shape      # (terms, positions): forces, then moments
        (28, 73)
        >>> round(float(dyn.power_terms()[:, 18].sum()), 1)   # Σ at φ1 = 90° [W]
        -8800.4
        """
        kin = self.kinematics
        forces, couples, _ = _statics.applied_loads(kin, self.qdot, self.qddot, self.g)
        terms = []
        for link, pt, fx, fy in forces:
            v = kin.jacobian(pt)[:, 0] * self._qd
            terms.append(np.broadcast_to(fx * v[0] + fy * v[1], (kin.m, kin.n)))
        for link, M in couples:
            w1, _ = kin.body_rates(link)
            terms.append(np.broadcast_to(M * w1[0] * self._qd, (kin.m, kin.n)))
        return np.stack([kin.reshape(t) for t in terms])

    def load_power(self):
        """Σ F·v + Σ M·ω_i of all applied loads, weights and inertia loads [W]
        (the sum of :meth:`power_terms`).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.crank import crank_dynamics
        >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
        >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
        >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
        >>> [round(float(dyn.load_power()[i]), 1) for i in (0, 18)]   # φ1 = 0°, 90° [W]
        [7015.0, -8800.4]
        """
        return self.power_terms().sum(axis=0)

    def power_residual(self):
        """``M_drive·ω + Σ F·v + Σ M·ω_i`` [W] with the driving moment from the joint
        reactions (reverse-order pass) and the powers from the velocities: zero to
        rounding when the two routes agree (the power balance).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.crank import crank_dynamics
        >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
        >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
        >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
        >>> bool(np.abs(dyn.power_residual()).max() < 1e-6)   # [W], vs loads of ~10 kW
        True
        >>> round(float(np.abs(dyn.load_power()).max()))     # [W]
        11312
        """
        return self.driving_moment_from_reactions * self.qdot + self.load_power()

    def equilibrium_residual(self):
        """Largest |ΣF| [N] and |ΣM| [N·m] of any moving link with the inertia loads
        (Newton–Euler in d'Alembert form), recomputed from loads and reactions.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.crank import crank_dynamics
        >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
        >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
        >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
        >>> f, mo = dyn.equilibrium_residual()
        >>> f.shape, bool(f.max() < 1e-6), bool(mo.max() < 1e-6)   # [N], [N·m]
        ((73,), True, True)
        """
        return self.statics.equilibrium_residual()

    def flywheel(self, delta=None, J_flywheel=None, omega_mean=None):
        """The flywheel by the energy–mass method (:func:`assur.dynamics.flywheel.flywheel`)
        from this result's J_red(φ) and reduced moment without inertia; ``omega_mean``
        defaults to the mean |ω| of the positions [rad/s].

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.crank import crank_dynamics
        >>> model = io.load(io.bundled("cleaning_lab3"))   # seed 001 lab 3, illustrative
        >>> kin = model.mechanism.solve(np.radians(np.arange(0.0, 361.0, 5.0)))  # φ1 [rad]
        >>> dyn = crank_dynamics(kin, qdot=-30.0)          # ω [rad/s], clockwise
        >>> fw = dyn.flywheel(delta=0.05)
        >>> round(fw.J_flywheel, 3)                            # J_f [kg·m²]
        7.555
        >>> round(fw.omega_min, 2), round(fw.omega_max, 2)     # [rad/s]
        (29.25, 30.75)
        >>> round(dyn.flywheel(J_flywheel=15.0).delta, 4)   # a larger flywheel: δ [-]
        0.0258
        """
        from .flywheel import flywheel
        if omega_mean is None:
            omega_mean = float(np.mean(np.abs(self.qdot)))
        if self.kinematics.m != 1:
            raise ValueError("flywheel: one design at a time (this result holds "
                             f"{self.kinematics.m})")
        return flywheel(np.ravel(self.q), np.ravel(self.reduced_inertia),
                        np.ravel(self.reduced_moment_without_inertia), omega_mean,
                        delta=delta, J_flywheel=J_flywheel,
                        dJ_red=np.ravel(self.reduced_inertia_derivative))

    def __repr__(self):
        return (f"CrankDynamics({self.kinematics.mechanism.name!r}, shape={self.kinematics.shape}, "
                f"masses={len(self.masses)})")


def crank_dynamics(source, qdot, qddot=None, g=None, q=None):
    """Kinetostatics with inertia, reduced moments and inertia, and the common
    centre of mass of a crank mechanism — one call.

    Parameters
    ----------
    source : Analysis, Kinematics or Mechanism
        The solved mechanism (its masses are its ``mass`` loads; add them with
        :func:`with_masses`). A Mechanism is solved at ``q``.
    qdot : float or array_like
        Crank angular velocity ω [rad/s], signed (the seeds' crank turns clockwise:
        ω < 0), a constant or an array over the positions.
    qddot : float or array_like, optional
        Crank angular acceleration ε [rad/s²] (default 0: steady rotation).
    g : float, optional
        Gravity [m/s²] (default: the mechanism's, :attr:`assur.Mechanism.g`).
    q : array_like, optional
        Crank angles [rad] when ``source`` is a Mechanism.

    Returns
    -------
    CrankDynamics

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> model = io.load(io.bundled("cleaning_lab3"))
    >>> dyn = crank_dynamics(model.mechanism.solve(model.range), qdot=-30.0)
    >>> bool(np.abs(dyn.power_residual()).max() < 1e-9 * np.abs(dyn.load_power()).max() + 1e-6)
    True
    """
    from ..core.kinematics import kinematics_of
    kin = kinematics_of(source, q, "crank_dynamics")
    if g is None:
        g = kin.mechanism.g
    return CrankDynamics(kin, qdot, qddot, g)
