"""Transfer ratios and real-time quantities from the exact analogs, methods of
:class:`assur.core.kinematics.Kinematics`.

The transfer ratio ``U_ij = φ_i'/φ_j'`` [-] and its derivative (seed 003 §3.1:
U43, U53, U65, U75), singular where link j is at rest (:data:`SINGULAR_RTOL`); the
velocity ``v = J·q̇`` and acceleration ``a = J·q̈ + q̇ᵀ·H·q̇`` of a point and the
angular velocity and acceleration of a link for any coordinate rates (DESIGN.md §2).
"""

from __future__ import annotations

import numpy as np

from ..errors import SingularPositionError

__all__ = ["Transfer", "SINGULAR_RTOL"]

#: |φ_j'| below this fraction of its largest magnitude over the range counts as zero
SINGULAR_RTOL = 1e-9


class Transfer:
    """Transfer ratios and real-time quantities of a
    :class:`~assur.core.kinematics.Kinematics` (a base class of it: it calls the
    analogs of :class:`~assur.core.analogs.Analogs`).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.transfer import Transfer
    >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
    >>> isinstance(r, Transfer), [round(float(v), 3) for v in r.ratio("5", "3")]   # U53
    (True, [0.666, 0.484])
    """

    # ---- ratios ------------------------------------------------------------------
    def _singular_mask(self, den, what, singular):
        scale = np.max(np.abs(den), axis=-1, keepdims=True) if den.ndim else abs(den)
        bad = np.abs(den) <= SINGULAR_RTOL * np.maximum(scale, 1e-300)
        if bad.any():
            if singular == "raise":
                idx = np.argwhere(bad)[0]
                from .diagnostics import coordinate_text
                qv = ", ".join(coordinate_text(self.mechanism, c,
                                               float(self._q[j].reshape(self.shape)[tuple(idx)]))
                               for j, c in enumerate(self.coordinates))
                raise SingularPositionError(
                    f"{what} is singular at {int(bad.sum())} position(s), first at {qv}: the "
                    f"denominator analog is zero there (the link is at rest, e.g. a dead "
                    f"point); use singular='mask' to get a masked array")
        return bad

    def ratio(self, i, j, wrt=None, singular="raise"):
        """Transfer ratio U_ij = φ_i'/φ_j' [-] (seed 003 §3.1: U43, U53, U65, U75).

        Parameters
        ----------
        i, j : str
            Link names.
        singular : {"raise", "mask"}
            Where φ_j' = 0 the ratio is undefined: raise :class:`SingularPositionError`
            (default) or return a :class:`numpy.ma.MaskedArray` masking those positions.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> [round(float(v), 3) for v in m.solve([0.42, 0.67]).ratio("5", "3")]
        [0.666, 0.484]

        U53 [-] as seed 003 table 3.1 prints it. Link 4 is at rest where its U43
        changes sign (between S = 0.420 and 0.448 m in the table), so U34 is
        singular there:

        >>> s0 = 0.44                                # Newton's method for φ4' = 0
        >>> for _ in range(6):
        ...     r = m.solve([s0])
        ...     s0 -= float(r.dphi("4")[0] / r.ddphi("4")[0])
        >>> round(s0, 4)                                             # S [m]
        0.4416
        >>> u = m.solve([0.42, s0]).ratio("3", "4", singular="mask")
        >>> round(float(u[0]), 2), u.mask.tolist()                  # U34 [-]
        (-43.45, [False, True])
        """
        if singular not in ("raise", "mask"):
            raise ValueError("singular must be one of: ['raise', 'mask']")
        wrt = wrt if wrt is not None or self.k == 1 else self.coordinates[0]
        num, den = self.dphi(i, wrt), self.dphi(j, wrt)
        bad = self._singular_mask(den, f"ratio U{i}{j} = φ{i}'/φ{j}'", singular)
        safe = np.where(bad, 1.0, den)
        r = num / safe
        return np.ma.masked_array(r, mask=bad) if singular == "mask" else r

    def dratio(self, i, j, wrt=None, singular="raise"):
        """Derivative dU_ij/dq = (φ_i''φ_j' − φ_i'φ_j'')/φ_j'² [1/m].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> [round(float(v), 3) for v in r.dratio("5", "3")]     # dU53/dS [1/m]
        [0.746, -2.313]
        """
        wrt = wrt if wrt is not None or self.k == 1 else self.coordinates[0]
        a, b = self.dphi(i, wrt), self.dphi(j, wrt)
        aa, bb = self.ddphi(i, wrt), self.ddphi(j, wrt)
        bad = self._singular_mask(b, f"dU{i}{j}/dq", singular)
        safe = np.where(bad, 1.0, b)
        r = (aa * b - a * bb) / safe ** 2
        return np.ma.masked_array(r, mask=bad) if singular == "mask" else r

    # ---- real-time quantities ----------------------------------------------------
    def _rates(self, qdot, qddot=None):
        qd = np.asarray(qdot, dtype=float)
        qd = np.broadcast_to(qd[..., None] if self.k == 1 else qd, self.shape + (self.k,))
        if qddot is None:
            return qd, None
        qdd = np.asarray(qddot, dtype=float)
        qdd = np.broadcast_to(qdd[..., None] if self.k == 1 else qdd, self.shape + (self.k,))
        return qd, qdd

    def velocity(self, point, qdot):
        """Velocity of a point v = J·q̇ [m/s], shape (..., 2), for coordinate rates q̇
        [m/s or rad/s] (scalar or array broadcastable to the result shape, ``(..., k)``
        for k > 1).

        Examples
        --------
        The rod extending at Ṡ = 0.05 m/s:

        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> v = r.velocity("56", 0.05)
        >>> v.shape, [round(float(c), 4) for c in v[0]]      # (vx, vy) at S = 0.42 [m/s]
        ((2, 2), [0.0627, 0.223])
        """
        qd, _ = self._rates(qdot)
        J = self._out(np.moveaxis(self._jet1(point), (0, 1), (-2, -1)))  # (...,2,k)
        return np.einsum("...ik,...k->...i", J, qd)

    def acceleration(self, point, qdot, qddot):
        """Acceleration a = J·q̈ + q̇ᵀ·H·q̇ of a point [m/s²], shape (..., 2).

        Examples
        --------
        The rod extending at a steady Ṡ = 0.05 m/s (S̈ = 0): a = Ṡ²·(d²X/dS², d²Y/dS²):

        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> [round(float(c), 4) for c in r.acceleration("56", 0.05, 0.0)[0]]  # [m/s²]
        [-0.0713, -0.0621]
        """
        qd, qdd = self._rates(qdot, qddot)
        J = self._out(np.moveaxis(self._jet1(point), (0, 1), (-2, -1)))
        H = self._out(np.moveaxis(self._jet2(point), (0, 1, 2), (-3, -2, -1)))
        return (np.einsum("...ik,...k->...i", J, qdd)
                + np.einsum("...k,...ikl,...l->...i", qd, H, qd))

    def angular_velocity(self, link, qdot):
        """ω = φ'·q̇ [rad/s].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> [round(float(w), 4) for w in r.angular_velocity("3", 0.05)]  # Ṡ = 0.05 m/s → [rad/s]
        [0.336, 0.3119]
        """
        qd, _ = self._rates(qdot)
        J = self._out(np.moveaxis(self._sd[self._s(link, "angle")], 0, -1))
        return np.einsum("...k,...k->...", J, qd)

    def angular_acceleration(self, link, qdot, qddot):
        """ε = φ'·q̈ + q̇ᵀ·φ''·q̇ [rad/s²].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> eps = r.angular_acceleration("3", 0.05, 0.01)      # Ṡ [m/s], S̈ [m/s²]
        >>> [round(float(e), 4) for e in eps]                  # [rad/s²]
        [-0.0664, 0.122]
        """
        qd, qdd = self._rates(qdot, qddot)
        i = self._s(link, "angle")
        J = self._out(np.moveaxis(self._sd[i], 0, -1))
        H = self._out(np.moveaxis(self._sdd[i], (0, 1), (-2, -1)))
        return np.einsum("...k,...k->...", J, qdd) + np.einsum("...k,...kl,...l->...", qd, H, qd)
