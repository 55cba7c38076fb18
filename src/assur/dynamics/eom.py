"""Equations of motion of a mechanism with masses, from the engine's exact analogs.

For a mechanism of k generalized coordinates q (cylinder lengths [m] or crank
angles [rad]) whose links carry :class:`assur.core.loads.Mass` loads (mass m, centre S,
moment of inertia J about S), Lagrange's equations of the second kind are

.. math::

    M(q)\\,\\ddot q + h(q, \\dot q) = Q(q) + F

with (DESIGN.md §2: v_S = J_S·q̇, a_S = J_S·q̈ + q̇ᵀ·H_S·q̇; ω = φ'·q̇)

* the generalized mass matrix ``M = Σ m·J_Sᵀ·J_S + J·φ'·φ'ᵀ`` [kg, kg·m, kg·m²],
  J_S (2×k) the first analogs of S, φ' (k) the angular analogs of the link;
* its derivative ``∂M_ij/∂q_l = Σ m·(H_S[:, i, l]·J_S[:, j] + J_S[:, i]·H_S[:, j, l])
  + J·(φ''_il·φ'_j + φ'_i·φ''_jl)`` from the exact second analogs;
* the velocity terms (Christoffel symbols of the first kind)
  ``h_i = Σ_jl (∂M_ij/∂q_l − ½·∂M_jl/∂q_i)·q̇_j·q̇_l``;
* the generalized forces of the loads by virtual work ``Q_j = Σ F·∂r/∂q_j +
  Σ M·∂φ/∂q_j`` (weights m·g, forces, couples, springs;
  :func:`assur.core.statics.virtual_work_forces`);
* F the actuator forces along the coordinates (a cylinder's push [N], a crank's
  driving moment [N·m]).

For one coordinate S this is lab 6's eq. (7) (seed 001): ``M = m(S)`` is the
reduced mass (eq. 6: ``m(S) = m6·I_v² + J6·φ6'²``), ``h = ½·m'(S)·Ṡ²`` and
``Q = −P6·I(S)``; for a crank it is ``J_red·ε + ½·J_red'·ω² = M_drive + M_red``
(:func:`assur.dynamics.crank.reduced_inertia`).

Nothing is differentiated numerically: M and ∂M/∂q are sums of products of the
kernel's first and second analogs.
"""

from __future__ import annotations

import numpy as np

from ..errors import ModelError
from ..core.loads import masses_of
from .masses import design_value

__all__ = ["EquationsOfMotion", "equations_of_motion"]


class EquationsOfMotion:
    """M(q), ∂M/∂q and Q(q) of a mechanism over the positions of a solution.

    Produced by :func:`equations_of_motion`. Arrays have the kinematics' shape
    (``(n,)`` for one design, ``(m, n)`` for a batch) followed by the coordinate
    axes.

    Attributes
    ----------
    kinematics : Kinematics
    coordinates : tuple of str
    g : float
        Gravity the weights of the masses were taken with [m/s²].
    mass_matrix : ndarray, shape (..., k, k)
        Generalized mass matrix M(q) [kg for lengths, kg·m² for angles].
    mass_matrix_derivative : ndarray, shape (..., k, k, k)
        ``[..., i, j, l] = ∂M_ij/∂q_l``.
    generalized_forces : ndarray, shape ``shape`` (k = 1) or ``shape + (k,)``
        Q(q) of the mechanism's loads (weights of the masses included), positive
        along the coordinates [N or N·m]; the actuators hold the mechanism still
        with F = −Q.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics import equations_of_motion
    >>> mech = io.load(io.bundled("adapter_lab6")).mechanism   # seed 001 lab 6
    >>> eom = equations_of_motion(mech, [0.55, 0.675, 0.8])     # S [m]
    >>> eom.coordinates, eom.g, eom.mass_matrix.shape           # g [m/s²]
    (('S',), 9.81, (3, 1, 1))
    >>> (eom.generalized_forces / 1e3).round(2).tolist()   # Q(S) [kN]: the weight resists
    [-58.56, -58.94, -59.05]
    """

    def __init__(self, kin, g):
        from ..core import statics
        self.kinematics = kin
        self.coordinates = kin.coordinates
        self.g = float(g)
        masses = masses_of(kin.mechanism)
        if not masses:
            raise ModelError(f"mechanism {kin.mechanism.name!r} has no masses on moving links: "
                             f"its equations of motion are empty (add [[loads]] type = \"mass\")")
        k, m, n = kin.k, kin.m, kin.n
        M = np.zeros((m, n, k, k))
        dM = np.zeros((m, n, k, k, k))
        for ld in masses:
            mass = design_value(kin, ld.m)[..., None, None]  # (m, 1, 1, 1)
            J = design_value(kin, ld.J)[..., None, None]
            J1 = np.moveaxis(kin.jacobian(ld.point), (0, 1), (-2, -1))  # (m, n, 2, k)
            H = np.moveaxis(kin.hessian(ld.point), (0, 1, 2), (-3, -2, -1))  # (m, n, 2, k, k)
            w1, w2 = kin.body_rates(ld.link)
            w1 = np.moveaxis(w1, 0, -1)  # (m, n, k)
            w2 = np.moveaxis(w2, (0, 1), (-2, -1))  # (m, n, k, k)
            M += mass * np.einsum("mnci,mncj->mnij", J1, J1) \
                + J * np.einsum("mni,mnj->mnij", w1, w1)
            HJ = np.einsum("mncil,mncj->mnijl", H, J1)
            wJ = np.einsum("mnil,mnj->mnijl", w2, w1)
            dM += mass[..., None] * (HJ + np.swapaxes(HJ, -3, -2)) \
                + J[..., None] * (wJ + np.swapaxes(wJ, -3, -2))
        F = statics.virtual_work_forces(kin, g=g)
        Q = -np.stack([F[c] for c in kin.coordinates], axis=-1)  # (m, n, k)
        self._M, self._dM, self._Q = M, dM, Q
        o = kin.reshape
        self.mass_matrix = o(M)
        self.mass_matrix_derivative = o(dM)
        self.generalized_forces = self._out(Q)

    # ---- rates -------------------------------------------------------------------------
    def _qd(self, qdot, what="qdot"):
        kin = self.kinematics
        q = np.asarray(qdot, dtype=float)
        if kin.k == 1 and (q.ndim == 0 or q.shape[-1] != 1 or q.shape == kin.shape):
            q = q[..., None]
        try:
            return np.broadcast_to(q, kin.shape + (kin.k,)).reshape(kin.m, kin.n, kin.k)
        except ValueError:
            raise ValueError(f"{what} must broadcast to the positions' shape {kin.shape} "
                             f"(with a trailing axis of {kin.k} coordinates), got "
                             f"{np.shape(qdot)}") from None

    def _out(self, a, tail=1):
        a = self.kinematics.reshape(a)
        return a[..., 0] if self.kinematics.k == 1 and tail == 1 else a

    def velocity_terms(self, qdot):
        """h(q, q̇) = Σ_jl (∂M_ij/∂q_l − ½·∂M_jl/∂q_i)·q̇_j·q̇_l [N or N·m], shape
        ``shape`` (k = 1) or ``shape + (k,)``: the Coriolis and centrifugal forces of
        the variable mass matrix (½·m'(S)·Ṡ² in lab 6's eq. 7).

        Parameters
        ----------
        qdot : array_like
            Coordinate rates q̇ [m/s or rad/s], broadcastable to ``shape`` (k = 1) or
            ``shape + (k,)``.

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import equations_of_motion
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism   # seed 001 lab 6
        >>> eom = equations_of_motion(mech, [0.55, 0.675, 0.8])     # S [m]
        >>> h = eom.velocity_terms(0.0704)        # at lab 6's steady Ṡ [m/s]
        >>> h.round(1).tolist()                   # ½·m'(S)·Ṡ² [N]
        [-810.0, 41.1, 598.8]
        >>> m, dm = eom.reduced_mass()
        >>> bool(abs(h - 0.5 * dm * 0.0704 ** 2).max() < 1e-9)   # lab 6 eq. (7) [N]
        True
        """
        qd = self._qd(qdot)
        dM = self._dM
        h = (np.einsum("mnijl,mnj,mnl->mni", dM, qd, qd)
             - 0.5 * np.einsum("mnjli,mnj,mnl->mni", dM, qd, qd))
        return self._out(h)

    def kinetic_energy(self, qdot):
        """T = ½·q̇ᵀ·M·q̇ [J], shape ``shape``.

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import equations_of_motion
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism   # seed 001 lab 6
        >>> eom = equations_of_motion(mech, [0.55, 0.675, 0.8])     # S [m]
        >>> eom.kinetic_energy(0.0704).round(1).tolist()   # at Ṡ = 0.0704 m/s [J]
        [128.0, 97.4, 130.6]
        """
        qd = self._qd(qdot)
        return self.kinematics.reshape(0.5 * np.einsum("mni,mnij,mnj->mn", qd, self._M, qd))

    def actuator_forces(self, qdot, qddot):
        """Inverse dynamics: the actuator forces F = M·q̈ + h − Q [N or N·m] that move
        the mechanism with q̇, q̈ (shape as :meth:`velocity_terms`).

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import equations_of_motion
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism   # seed 001 lab 6
        >>> eom = equations_of_motion(mech, [0.55, 0.675, 0.8])     # S [m]
        >>> F = eom.actuator_forces(0.0704, 0.0)   # Ṡ [m/s], S̈ = 0 [m/s²]
        >>> (F / 1e3).round(2).tolist()            # the cylinder's push [kN]
        [57.75, 58.99, 59.65]
        >>> (eom.actuator_forces(0.0, 0.0) / 1e3).round(2).tolist()   # holding: −Q [kN]
        [58.56, 58.94, 59.05]
        """
        qd, qdd = self._qd(qdot), self._qd(qddot, "qddot")
        F = (np.einsum("mnij,mnj->mni", self._M, qdd)
             + np.einsum("mnijl,mnj,mnl->mni", self._dM, qd, qd)
             - 0.5 * np.einsum("mnjli,mnj,mnl->mni", self._dM, qd, qd) - self._Q)
        return self._out(F)

    def accelerations(self, qdot, forces):
        """Forward dynamics: q̈ = M⁻¹·(Q + F − h) [m/s² or rad/s²] for actuator
        forces ``forces`` [N or N·m] (shape as :meth:`velocity_terms`).

        Raises
        ------
        ModelError
            Where M is singular (a coordinate that moves no mass).

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import equations_of_motion
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism   # seed 001 lab 6
        >>> eom = equations_of_motion(mech, [0.55, 0.675, 0.8])     # S [m]
        >>> hold = -eom.generalized_forces           # the force that holds it [N]
        >>> eom.accelerations(0.0, hold).round(9).tolist()   # at rest [m/s²]
        [0.0, 0.0, 0.0]
        >>> F = 17e6 * 0.0122718                     # 17 MPa on the 125 mm piston [N]
        >>> eom.accelerations(0.0, F).round(3).tolist()      # S̈ [m/s²]
        [2.905, 3.807, 2.838]
        """
        qd, F = self._qd(qdot), self._qd(forces, "forces")
        h = (np.einsum("mnijl,mnj,mnl->mni", self._dM, qd, qd)
             - 0.5 * np.einsum("mnjli,mnj,mnl->mni", self._dM, qd, qd))
        rhs = self._Q + F - h
        det = np.linalg.det(self._M)
        scale = np.prod(np.abs(np.diagonal(self._M, axis1=-2, axis2=-1)), axis=-1)
        bad = ~(np.abs(det) > 1e-12 * scale)
        if bad.any():
            i = np.argwhere(bad)[0]
            raise ModelError(f"mechanism {self.kinematics.mechanism.name!r}: the mass matrix "
                             f"is singular at design {int(i[0])}, position {int(i[1])} (a "
                             f"coordinate moves no mass)")
        return self._out(np.linalg.solve(self._M, rhs[..., None])[..., 0])

    # ---- one coordinate ---------------------------------------------------------------
    def reduced_mass(self):
        """m(q) and dm/dq for one coordinate (lab 6 eq. 6 and m'(S)) [kg, kg/m] — or
        J_red and dJ_red/dφ for a crank [kg·m², kg·m²/rad].

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import equations_of_motion
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism   # seed 001 lab 6
        >>> eom = equations_of_motion(mech, [0.55, 0.675, 0.8])     # S [m]
        >>> m, dm = eom.reduced_mass()
        >>> (m / 1e3).round(3).tolist()    # m(S) [t], lab 6 eq. (6)
        [51.646, 39.313, 52.709]
        >>> (dm / 1e3).round(1).tolist()   # m'(S) [t/m]: least near mid-stroke
        [-326.9, 16.6, 241.6]
        """
        if self.kinematics.k != 1:
            raise ValueError(f"reduced_mass needs one coordinate; this mechanism has "
                             f"{list(self.coordinates)}")
        o = self.kinematics.reshape
        return o(self._M[..., 0, 0]), o(self._dM[..., 0, 0, 0])

    def __repr__(self):
        return (f"EquationsOfMotion({self.kinematics.mechanism.name!r}, "
                f"shape={self.kinematics.shape}, k={self.kinematics.k})")


def equations_of_motion(source, q=None, g=None):
    """The equations of motion M(q)·q̈ + h(q, q̇) = Q(q) + F of a mechanism.

    Parameters
    ----------
    source : Analysis, Kinematics or Mechanism
        The solved mechanism (a Mechanism is solved at ``q``); its masses are its
        ``mass`` loads.
    q : array_like, optional
        Coordinates [m or rad] when ``source`` is a Mechanism.
    g : float, optional
        Gravity [m/s²] (default: the mechanism's, :attr:`assur.Mechanism.g`).

    Returns
    -------
    EquationsOfMotion

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics import equations_of_motion
    >>> from assur.dynamics.crank import reduced_inertia
    >>> model = io.load(io.bundled("cleaning_lab3"))
    >>> kin = model.mechanism.solve(model.range)
    >>> eom = equations_of_motion(kin)
    >>> m, dm = eom.reduced_mass()
    >>> Jr, dJr = reduced_inertia(kin)
    >>> bool(np.allclose(m, Jr.reshape(m.shape), rtol=1e-12))
    True
    """
    from ..core.kinematics import kinematics_of
    kin = kinematics_of(source, q, "equations_of_motion")
    if g is None:
        g = kin.mechanism.g
    return EquationsOfMotion(kin, g)
