"""Checks of a solved mechanism, methods of :class:`assur.core.kinematics.Kinematics`:
the angular analog of a direction between two points, the instantaneous centre of a
link (seed 003: I56 = φ6'·(X56 − Xp)), the closure residual of every group's
equations and the transmission angle of a dyad.
"""

from __future__ import annotations

import numpy as np

__all__ = ["KinematicChecks"]


class KinematicChecks:
    """The checks of a :class:`~assur.core.kinematics.Kinematics` (a base class of it:
    it calls the analogs of :class:`~assur.core.analogs.Analogs` and the singular
    positions of :class:`~assur.core.transfer.Transfer`).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.kinematic_checks import KinematicChecks
    >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
    >>> isinstance(r, KinematicChecks), bool(r.closure_residual().max() < 1e-12)   # [m]
    (True, True)
    """

    def direction_rate(self, a, b, wrt=None):
        """Angular-velocity analog of the direction from point ``a`` to point ``b``,
        dφ_ab/dq [rad/m or rad/rad] (of a rigid body through both points: its own).

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> [round(float(v), 3) for v in r.direction_rate("56", "67")]   # [rad/m]
        [0.295, 3.085]
        >>> [round(float(v), 3) for v in r.dphi("6")]           # link 6 through them
        [0.295, 3.085]
        """
        dx, dy = self.x(b) - self.x(a), self.y(b) - self.y(a)
        ddx, ddy = self.dx(b, wrt) - self.dx(a, wrt), self.dy(b, wrt) - self.dy(a, wrt)
        return (dx * ddy - dy * ddx) / (dx * dx + dy * dy)

    def instant_centre(self, link=None, wrt=None, *, points=None, singular="raise"):
        """Instantaneous centre of rotation of a link relative to the frame [m] — the one
        home of this check (the reports' table of it calls it).

        From the velocity analog of a point A of the link and its angular analog φ':
        ``P = A + (−A'_y, A'_x)/φ'``. Seed 003 finds it as the intersection of rockers
        5 and 7 (Xp) and checks I56 = φ6'·(X56 − Xp).

        Parameters
        ----------
        link : str, optional
            A named link (A its tail, φ' its :meth:`dphi`).
        points : (str, str), optional
            Instead of a link: two points A, B of one rigid body (φ' the
            :meth:`direction_rate` of A → B).
        singular : {"raise", "mask"}
            Where the link is at rest there is no centre: raise
            :class:`SingularPositionError` (default) or mask those positions
            (:class:`numpy.ma.MaskedArray`).

        Returns
        -------
        xp, yp : ndarray

        Examples
        --------
        The seed's check I56 = φ6'·(X56 − Xp) at S = 0.42 m:

        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> xp, yp = r.instant_centre("6")
        >>> round(float(xp[0]), 3), round(float(yp[0]), 3)      # [m]
        (-13.991, 4.449)
        >>> round(float(r.dphi("6")[0] * (r.x("56")[0] - xp[0])), 3)   # I56 [m/m], table 3.1
        4.459
        >>> xq, _ = r.instant_centre(points=("56", "67"))         # the same body [m]
        >>> bool(abs(xq[0] - xp[0]) < 1e-9)
        True
        """
        if points is None:
            lk = next(l for l in self.mechanism.links if l.name == link)
            a, what = lk.tail, f"instantaneous centre of link {link}"
            w = self.dphi(link, wrt)
        else:
            a, what = points[0], f"instantaneous centre of the body of {points[0]}, {points[1]}"
            w = self.direction_rate(points[0], points[1], wrt)
        # raises SingularPositionError where the link is at rest (no centre), or masks
        bad = self._singular_mask(w, what, singular)
        ws = np.where(bad, 1.0, w)
        ax, ay = self.x(a), self.y(a)
        vx, vy = self.dx(a, wrt), self.dy(a, wrt)
        xp, yp = ax - vy / ws, ay + vx / ws
        if singular == "mask":
            return np.ma.masked_array(xp, bad), np.ma.masked_array(yp, bad)
        return xp, yp

    def closure_residual(self):
        """Largest violation of any group's closure equations [m], shape ``shape``.

        Recomputes every constraint of every group from the returned points
        (:meth:`assur.groups.base.Group.closure`): lengths of links, rigid offsets,
        slider lines.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> res = examples.hitch_003().solve(np.linspace(0.42, 0.67, 10)).closure_residual()
        >>> res.shape, bool(res.max() < 1e-12)                  # [m]
        ((10,), True)
        """
        mech = self.mechanism
        res = np.zeros(self.shape)

        def P(p):
            return self.x(p), self.y(p)

        def val(ref):
            if isinstance(ref, str) and ref in self.coordinates:
                return self.q(ref)
            v = mech.value_of(ref)
            return np.asarray(v)[..., None] if np.ndim(v) else v

        for g in mech.groups:
            r = g.closure(P, val)
            if r is not None:
                res = np.maximum(res, r)
        return res

    def transmission_angle(self, group, degrees=False):
        """Transmission angle μ of a dyad: the angle at its middle joint between its
        two links [rad] (or [°]); 0 or π is a dead point.

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> [round(float(v), 1) for v in r.transmission_angle("III (6,7)", degrees=True)]
        [102.3, 53.3]
        """
        g = self.mechanism.group(group)
        cx, cy = self.x(g.out), self.y(g.out)
        ax, ay = self.x(g.a), self.y(g.a)
        bx, by = self.x(g.b), self.y(g.b)
        u = (ax - cx, ay - cy)
        v = (bx - cx, by - cy)
        mu = np.arctan2(np.abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1])
        return np.degrees(mu) if degrees else mu
