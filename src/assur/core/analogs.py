"""Positions and exact analogs of points, links and distances by name: the
accessors of :class:`assur.core.kinematics.Kinematics` over the kernel's arrays.

A point's position [m], its first analogs ∂(x, y)/∂q [m/m or m/rad] and second
analogs; a link's angle φ [rad] and its analogs φ', φ'' (a link declared with
:meth:`~assur.Mechanism.link`, or any body a group names); a named distance and its
analogs. Shapes as the module :mod:`assur.core.kinematics` describes them.
"""

from __future__ import annotations

import numpy as np

__all__ = ["Analogs"]


class Analogs:
    """The positions and analogs of a :class:`~assur.core.kinematics.Kinematics` by
    the name of a point, link or distance (a base class of it: it reads the arrays
    the result holds, ``_pv``, ``_pd``, ``_pdd`` of the points, ``_sv``, ``_sd``,
    ``_sdd`` of the links and distances, ``_frame`` of the frame points).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.analogs import Analogs
    >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
    >>> isinstance(r, Analogs), [round(float(v), 3) for v in r.dy("56")]   # I56 [m/m]
    (True, [4.459, 2.621])
    """

    # ---- points ------------------------------------------------------------------
    def value(self, point):
        """Position of any point (frame points included), shape (2, m, n) [m].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> r.value("56").shape
        (2, 1, 2)
        >>> [round(float(v), 3) for v in r.value("56")[:, 0, 0]]  # X56, Y56 [m], table 2.2
        [1.131, 0.2]
        >>> [float(v) for v in r.value("01")[:, 0, 1]]           # frame pivot 01 [m]
        [0.415, 0.563]
        """
        return self._val(point)

    def jacobian(self, point):
        """First analogs ∂(x, y)/∂q of a point, shape (2, k, m, n) [m/m or m/rad].

        Examples
        --------
        >>> from assur import examples
        >>> J = examples.hitch_003().solve([0.42, 0.67]).jacobian("56")
        >>> J.shape
        (2, 1, 1, 2)
        >>> [round(float(v), 3) for v in J[1, 0, 0]]   # dY56/dS = I56 [m/m], table 3.1
        [4.459, 2.621]
        """
        return self._jet1(point)

    def hessian(self, point):
        """Second analogs ∂²(x, y)/∂q∂q of a point, shape (2, k, k, m, n).

        Examples
        --------
        >>> from assur import examples
        >>> H = examples.hitch_003().solve([0.42, 0.67]).hessian("56")
        >>> H.shape
        (2, 1, 1, 1, 2)
        >>> [round(float(v), 3) for v in H[1, 0, 0, 0]]    # d²Y56/dS² [1/m]
        [-24.851, -7.64]
        """
        return self._jet2(point)

    def x(self, point):
        """X coordinate of a point [m].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])
        >>> [round(float(v), 3) for v in r.x("56")]    # X56 [m], seed 003 table 2.2
        [1.131, 1.003]
        """
        return self._out(self._val(point)[0])

    def y(self, point):
        """Y coordinate of a point [m].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])
        >>> [round(float(v), 3) for v in r.y("S6")]    # YS6 [m], seed 003 table 2.2
        [0.333, 1.487]
        """
        return self._out(self._val(point)[1])

    def point(self, point):
        """Position of a point, shape (..., 2) [m].

        Examples
        --------
        >>> from assur import examples
        >>> p = examples.hitch_003().solve([0.42, 0.67]).point("67")
        >>> p.shape, [round(float(v), 3) for v in p[-1]]   # X67, Y67 at S = 0.67 [m], table 2.2
        ((2, 2), [0.824, 1.526])
        """
        return self._out(np.moveaxis(self._val(point), 0, -1))

    def dx(self, point, wrt=None):
        """Velocity analog dX/dq of a point [m/m or m/rad].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])
        >>> [round(float(v), 3) for v in r.dx("56")]       # dX56/dS [m/m]
        [1.253, -1.7]
        """
        return self._d1(self._jet1(point)[0], wrt)

    def dy(self, point, wrt=None):
        """Velocity analog dY/dq of a point [m/m or m/rad].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])
        >>> [round(float(v), 3) for v in r.dy("56")]       # I56 [m/m], seed 003 table 3.1
        [4.459, 2.621]
        """
        return self._d1(self._jet1(point)[1], wrt)

    def ddx(self, point, wrt=None):
        """Acceleration analog d²X/dq² of a point [1/m or m/rad²].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])
        >>> [round(float(v), 3) for v in r.ddx("56")]      # d²X56/dS² [1/m]
        [-28.517, -6.286]
        """
        return self._d2(self._jet2(point)[0], wrt)

    def ddy(self, point, wrt=None):
        """Acceleration analog d²Y/dq² of a point [1/m or m/rad²].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])
        >>> [round(float(v), 3) for v in r.ddy("56")]      # dI56/dS [1/m]
        [-24.851, -7.64]
        """
        return self._d2(self._jet2(point)[1], wrt)

    def transmission(self, point, axis="y", wrt=None):
        """Transmission number I = dY/dS (``axis="y"``) or dX/dS of a point [m/m].

        Seed 003 §3.1: I56 = dφ3·U53·L56·cos φ5 = dY56/dS; IS6 = dY_S6/dS.
        A vertical load P [N] at the point needs the rod force P·I (before efficiency).

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])
        >>> [round(float(v), 3) for v in r.transmission("S6")]   # seed 003 table 3.1
        [4.713, 4.933]
        """
        if axis not in ("x", "y"):
            raise ValueError("axis must be one of: ['x', 'y']")
        return self.dy(point, wrt) if axis == "y" else self.dx(point, wrt)

    # ---- links -------------------------------------------------------------------
    def _body_link(self, link):
        """Angle points of a body named in a group (not declared with ``.link``), or
        None."""
        if link in self._sidx and self._kinds[link] == "angle":
            return None
        topo = self.mechanism.topology
        if link in topo.bodies and link != "0":
            pq = topo.angle_points(link)
            if pq is not None and all(self.has_point(p) for p in pq):
                return pq
        return None

    def phi(self, link, degrees=False):
        """Angle φ of a link from +x, counter-clockwise [rad] (or [°]).

        ``link`` is a link declared with :meth:`~assur.Mechanism.link`, or any link a
        group names (its angle is the direction from its first point to its second,
        e.g. pivot → joint; a slider block or a sleeve turns with its guide or rod),
        continuous along the positions.

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> [round(float(v), 1) for v in r.phi("5", degrees=True)]   # table 2.1 [°]
        [-15.7, 33.0]
        >>> [round(float(v), 4) for v in r.phi("5")]                 # [rad]
        [-0.2739, 0.5753]
        """
        pq = self._body_link(link)
        if pq is not None:
            d = self._val(pq[1]) - self._val(pq[0])
            v = self._out(np.unwrap(np.arctan2(d[1], d[0]), axis=-1))
        else:
            v = self._out(self._sv[self._s(link, "angle")])
        return np.degrees(v) if degrees else v

    def dphi(self, link, wrt=None):
        """Angular-velocity analog φ' = dφ/dq [rad/m or rad/rad].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> [round(float(v), 3) for v in r.dphi("3")]   # dφ3 [rad/m], seed 003 table 3.1
        [6.719, 6.239]
        """
        if self._body_link(link) is not None:
            return self._d1(self.body_rates(link)[0], wrt)
        return self._d1(self._sd[self._s(link, "angle")], wrt)

    def ddphi(self, link, wrt=None):
        """Angular-acceleration analog φ'' = d²φ/dq² [rad/m² or rad/rad²].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> [round(float(v), 2) for v in r.ddphi("3")]            # [rad/m²]
        [-53.42, 23.86]
        """
        if self._body_link(link) is not None:
            return self._d2(self.body_rates(link)[1], wrt)
        return self._d2(self._sdd[self._s(link, "angle")], wrt)

    def length(self, name):
        """A named distance [m].

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().distance("d57", "05", "67", angle="57")   # |05–67|
        >>> [round(float(v), 3) for v in m.solve([0.42, 0.67]).length("d57")]   # [m]
        [1.037, 1.253]
        """
        return self._out(self._sv[self._s(name, "distance")])

    def dlength(self, name, wrt=None):
        """First analog of a named distance [m/m].

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().distance("d57", "05", "67", angle="57")   # |05–67|
        >>> [round(float(v), 3) for v in m.solve([0.42, 0.67]).dlength("d57")]  # [m/m]
        [2.083, -0.028]
        """
        return self._d1(self._sd[self._s(name, "distance")], wrt)

    def ddlength(self, name, wrt=None):
        """Second analog of a named distance [1/m].

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().distance("d57", "05", "67", angle="57")   # |05–67|
        >>> [round(float(v), 3) for v in m.solve([0.42, 0.67]).ddlength("d57")]  # [1/m]
        [-23.535, -7.693]
        """
        return self._d2(self._sdd[self._s(name, "distance")], wrt)

    def body_rates(self, body):
        """Angular analogs of a body: (φ', φ''), shapes (k, m, n) and (k, k, m, n)
        [rad/m or rad/rad]; zero for the frame. A single-point body (a slider block, a
        sleeve) turns with its guide (:meth:`assur.core.topology.Topology.angle_points`).

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])          # S [m]
        >>> w1, w2 = r.body_rates("5")
        >>> w1.shape, [round(float(v), 3) for v in w1[0, 0]]     # φ5' [rad/m], table 3.1
        ((1, 1, 2), [4.475, 3.019])
        >>> float(abs(r.body_rates("0")[0]).max())              # the frame does not turn
        0.0
        """
        k, m, n = self.k, self.m, self.n
        pq = self.mechanism.topology.angle_points(body)
        if pq is None:
            return np.zeros((k, m, n)), np.zeros((k, k, m, n))
        P, Q = pq
        d = self._val(Q) - self._val(P)  # (2, m, n)
        d1 = self._jet1(Q) - self._jet1(P)  # (2, k, m, n)
        d2 = self._jet2(Q) - self._jet2(P)  # (2, k, k, m, n)
        r2 = d[0] ** 2 + d[1] ** 2
        c1 = d[0] * d1[1] - d[1] * d1[0]  # (k, m, n)
        w1 = c1 / r2
        dot1 = d[0] * d1[0] + d[1] * d1[1]
        w2 = np.empty((k, k, m, n))
        for a in range(k):
            for b in range(k):
                num = (d1[0, b] * d1[1, a] - d1[1, b] * d1[0, a]) + (d[0] * d2[1, a, b]
                                                                   - d[1] * d2[0, a, b])
                w2[a, b] = num / r2 - 2 * c1[a] * dot1[b] / r2**2
        return w1, w2

    # ---- the stored arrays by name -----------------------------------------------
    def _val(self, point):
        """(2, m, n) position of any point, frame points included."""
        if point in self._frame:
            return self._frame[point]
        return self._pv[self._p(point)]

    def _jet1(self, point):
        """(2, k, m, n) first analogs (zero for frame points)."""
        if point in self._frame:
            return np.zeros((2, self.k, self.m, self.n))
        return self._pd[self._p(point)]

    def _jet2(self, point):
        """(2, k, k, m, n) second analogs (zero for frame points)."""
        if point in self._frame:
            return np.zeros((2, self.k, self.k, self.m, self.n))
        return self._pdd[self._p(point)]

    def _p(self, point):
        try:
            return self._pidx[point]
        except KeyError:
            raise KeyError(f"no point {point!r} in this result; points: {list(self._pidx)}") \
                from None

    def _s(self, name, kind=None):
        if name not in self._sidx or (kind and self._kinds[name] != kind):
            have = [s for s in self._sidx if kind is None or self._kinds[s] == kind]
            raise KeyError(f"no {kind or 'link/distance'} {name!r} in this result; have: {have}")
        return self._sidx[name]

    def _out(self, a):
        """(m, n, *tail) -> shape + tail."""
        tail = a.shape[2:]
        return a.reshape(self.shape + tail)

    def _wrt(self, wrt):
        if wrt is None:
            return 0 if self.k == 1 else None
        if wrt not in self.coordinates:
            raise KeyError(f"unknown coordinate {wrt!r}; coordinates: {self.coordinates}")
        return self.coordinates.index(wrt)

    def _d1(self, arr, wrt):
        """arr: (k, m, n) -> shape (+ (k,))"""
        j = self._wrt(wrt)
        if j is None:
            return self._out(np.moveaxis(arr, 0, -1))
        return self._out(arr[j])

    def _d2(self, arr, wrt):
        """arr: (k, k, m, n)"""
        j = self._wrt(wrt)
        if j is None:
            return self._out(np.moveaxis(arr, (0, 1), (-2, -1)))
        return self._out(arr[j, j])
