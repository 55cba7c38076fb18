"""Kinematic results: positions and exact analogs as named arrays.

Glossary (BRIEF.md): ``phi`` link angle φ [rad]; ``dphi`` angular-velocity analog
φ' = dφ/dq [rad/m or rad/rad]; ``ddphi`` second-order analog φ'' ; ``ratio(i, j)``
the transfer ratio U_ij = φ_i'/φ_j' [-]; ``transmission(point)`` the transmission
number I = dY/dS of a point [m/m] (the load P on the point gives the rod force
P·I/η by virtual work).

Shapes: a quantity is returned with the shape of the coordinates passed to
:meth:`assur.Mechanism.solve` — ``(n,)`` for one design, ``(m, n)`` for a batch —
plus trailing axes for derivatives: ``(..., k)`` for first-order and
``(..., k, k)`` for second-order analogs. When the mechanism has one coordinate
(k = 1) or ``wrt`` names one, those trailing axes are dropped.

Real-time quantities follow from the analogs for any coordinate rates
(DESIGN.md §2): ``v = J·q̇`` and ``a = J·q̈ + q̇ᵀ·H·q̇``.
"""

from __future__ import annotations

import numpy as np

from ..errors import SingularPositionError

__all__ = ["Kinematics", "SINGULAR_RTOL"]

#: |φ_j'| below this fraction of its largest magnitude over the range counts as zero
SINGULAR_RTOL = 1e-9


class _FramePoints(dict):
    """Frame points' (2, m, n) positions from the parameter table, made on first use."""

    __slots__ = ("_rows", "_params", "_shape")

    def __init__(self, rows, params, shape):   # starts empty (dict.__new__)
        self._rows, self._params, self._shape = rows, params, shape

    def __contains__(self, name):
        return name in self._rows

    def __missing__(self, name):
        rx, ry = self._rows[name]
        xy = np.stack([self._params[rx], self._params[ry]])[:, :, None]  # (2, m, 1)
        v = self[name] = np.broadcast_to(xy, self._shape)
        return v

    def items(self):
        return ((k, self[k]) for k in self._rows)

    def keys(self):
        return self._rows.keys()

    def __iter__(self):
        return iter(self._rows)

    def __len__(self):
        return len(self._rows)

    def sliced(self, sl):
        """The same points restricted to positions ``sl`` of the last axis."""
        return {k: v[sl] for k, v in self.items()}


class Kinematics:
    """Positions and kinematic analogs of a mechanism over its coordinate range.

    Produced by :meth:`assur.Mechanism.solve`; not constructed directly.

    Attributes
    ----------
    mechanism : Mechanism
        The (parameter-resolved) mechanism.
    coordinates : tuple of str
        Names of the generalized coordinates.
    shape : tuple of int
        Shape of every quantity (without derivative axes).
    ok : ndarray of bool, shape (m, n)
        True where the mechanism assembled.
    failures : list of str
        Messages of failed elements when solved with ``on_failure="report"``.

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> r = examples.hitch_003().solve(np.linspace(0.42, 0.67, 10))   # S [m]
    >>> r.coordinates, r.shape, bool(r.ok.all())
    (('S',), (10,), True)
    >>> [round(float(v), 3) for v in r.y("56")[[0, -1]]]   # Y56 [m], seed 003 table 2.2
    [0.2, 1.043]
    """

    def __init__(self, mechanism, prog, q, raw, shape, ok, params):
        self.mechanism = mechanism
        self.coordinates = mechanism.coordinates
        self.k = len(self.coordinates)
        self._q = q  # (k, m, n)
        self.m, self.n = q.shape[1], q.shape[2]
        self.shape = tuple(shape)
        self.ok = ok
        self.failures = []
        # the index of each point and scalar among the outputs (shared, read only)
        self._pidx = raw.get("pidx") or {p: i for i, p in enumerate(raw["out_pts"])}
        self._sidx = raw.get("sidx") or {s: i for i, s in enumerate(raw["out_sca"])}
        self._kinds = prog.kinds
        k, m, n = self.k, self.m, self.n
        self._pv = raw["pv"].reshape(-1, 2, m, n)
        self._pd = raw["pd"].reshape(-1, 2, k, m, n)
        self._pdd = raw["pdd"].reshape(-1, 2, k, k, m, n)
        self._sv = raw["sv"].reshape(-1, m, n)
        # frame points are design constants: served from the parameters, not the kernel
        self._frame = _FramePoints(prog.frame_rows, params, (2, m, n))
        self._sd = raw["sd"].reshape(-1, k, m, n)
        self._sdd = raw["sdd"].reshape(-1, k, k, m, n)
        #: the kernel's one output buffer that every array above is a view of (one
        #: finiteness check for all of them); None if the arrays came otherwise
        self._buffer = raw.get("out")

    def _positions(self, i0, i1):
        """The same result restricted to positions i0:i1 (views, no copies)."""
        import copy
        b = copy.copy(self)
        sl = (Ellipsis, slice(i0, i1))
        b._q = self._q[sl]
        b.n = b._q.shape[-1]
        b.shape = (self.m, b.n) if len(self.shape) == 2 else (b.n,)
        b.ok = self.ok[sl]
        b._pv, b._pd, b._pdd = self._pv[sl], self._pd[sl], self._pdd[sl]
        b._sv, b._sd, b._sdd = self._sv[sl], self._sd[sl], self._sdd[sl]
        b._buffer = None   # the views are of part of the buffer
        b._frame = self._frame.sliced(sl) if hasattr(self._frame, "sliced") else \
            {k: v[sl] for k, v in self._frame.items()}
        return b

    # ---- helpers -----------------------------------------------------------------
    @property
    def output_buffer(self):
        """The one array, shape (output rows, m·n), that the kernel wrote and every
        position, analog, angle and distance of this result views — what
        ``Mechanism.solve(..., out=result)`` writes into again; None for a part of a
        result (:meth:`positions`).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> r = m.solve([0.42, 0.67])                             # S [m]
        >>> r.output_buffer.shape, r.positions(0, 1).output_buffer is None
        ((63, 2), True)
        >>> r2 = m.solve([0.5, 0.6], out=r)                       # reuses its memory
        >>> r2.output_buffer is r.output_buffer, round(float(r2.q()[0]), 2)   # S [m]
        (True, 0.5)
        """
        return self._buffer

    @property
    def points(self):
        """Names of the moving points in this result (frame points are available too).

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().solve([0.42]).points
        ('23', '34', '45', '56', '67', 'S6', 'F610')
        >>> examples.hitch_003().solve([0.42], outputs=["56"]).points
        ('56',)
        """
        return tuple(self._pidx)

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

    def has_point(self, point) -> bool:
        """True if the result holds the point (all points unless solved with ``outputs``).

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42], outputs=["56"])
        >>> r.has_point("56"), r.has_point("01"), r.has_point("S6")   # 01: a frame point
        (True, True, False)
        """
        return point in self._pidx or point in self._frame

    def first_nonfinite(self):
        """``(what, element)`` of the first value that is NaN or infinite (positions,
        analogs, link angles and distances), or None — one pass over the arrays.

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67])
        >>> print(r.first_nonfinite())
        None
        >>> r.output_buffer[0, 1] = float("nan")     # spoil X23 at the second position
        >>> r.first_nonfinite()
        ("position of point '23'", 1)
        """
        if self._buffer is not None and np.isfinite(self._buffer).all():
            return None   # the common case: one check of the buffer the arrays view
        for what, arr, names in (("position of point", self._pv, list(self._pidx)),
                                 ("first analog of point", self._pd, list(self._pidx)),
                                 ("second analog of point", self._pdd, list(self._pidx)),
                                 ("angle or length of", self._sv, list(self._sidx)),
                                 ("analog of", self._sd, list(self._sidx))):
            if arr.size and not np.isfinite(arr).all():
                idx = np.argwhere(~np.isfinite(arr))[0]
                return f"{what} {names[int(idx[0])]!r}", int(np.ravel_multi_index(
                    tuple(idx[-2:]), arr.shape[-2:]))
        return None

    def has_all_points(self) -> bool:
        """True if the result holds every point of the mechanism (not solved with
        ``outputs=`` for some of them).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> m.solve([0.42]).has_all_points(), m.solve([0.42], outputs=["56"]).has_all_points()
        (True, False)
        """
        return all(self.has_point(p) for p in self.mechanism.points)

    def positions(self, i0, i1):
        """The same result restricted to positions i0:i1 (views, no copies).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> r = examples.hitch_003().solve(np.linspace(0.42, 0.67, 10))   # S [m]
        >>> p = r.positions(8, 10)
        >>> p.shape, [round(float(v), 3) for v in p.q()]             # S [m]
        ((2,), [0.642, 0.67])
        >>> [round(float(v), 1) for v in p.phi("6", degrees=True)]   # table 2.1 [°]
        [105.8, 110.3]
        """
        return self._positions(i0, i1)

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

    def reshape(self, a):
        """An array of shape ``(m, n, *tail)`` in the result's shape (``shape + tail``).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.55, 0.67])    # one design: shape (3,)
        >>> r.ok.shape, r.reshape(r.ok).shape, r.reshape(np.zeros((1, 3, 2))).shape
        ((1, 3), (3,), (3, 2))
        """
        return self._out(a)

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

    @property
    def links(self):
        """Names of the links (angles) in this result.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().solve([0.42]).links
        ('2', '3', '34', '4', '5', '6', '7')
        """
        return tuple(s for s in self._sidx if self._kinds[s] == "angle")

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

    # ---- coordinates and points ---------------------------------------------------
    def q(self, name=None):
        """Generalized coordinate values [m or rad].

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67], params={"L4": [0.65, 0.66]})
        >>> r.q().shape, r.q("S")[1].tolist()          # 2 designs × 2 positions; S [m]
        ((2, 2), [0.42, 0.67])
        """
        j = 0 if name is None and self.k == 1 else self.coordinates.index(name)
        return self._out(self._q[j])

    def q_table(self):
        """All generalized coordinates as one C-contiguous array, shape (k, m·n)
        [m or rad], in the order of :attr:`coordinates` (a view: do not write to it).

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42, 0.67], params={"L4": [0.65, 0.66]})
        >>> r.q_table().tolist()        # S [m] of design 0, then design 1
        [[0.42, 0.67, 0.42, 0.67]]
        """
        return np.ascontiguousarray(self._q.reshape(self.k, self.m * self.n))

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

    # ---- links -------------------------------------------------------------------------
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

    # ---- real-time quantities ------------------------------------------------------
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

    # ---- checks ----------------------------------------------------------------------
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

    # ---- tables ----------------------------------------------------------------------
    def to_frame(self, degrees=True):
        """A pandas DataFrame of every quantity under the seeds' symbols.

        Columns: the coordinate(s); ``phi<link>`` [° if ``degrees``], ``dphi<link>``,
        ``ddphi<link>``; ``X<point>``, ``Y<point>``, ``dX…``, ``dY…``, ``ddX…``, ``ddY…``;
        ``U<i><j>`` for the ratios and ``I<point>`` for the transmission numbers listed
        in the mechanism's ``tables`` (seed 003: U43, U53, U65, U75, I56, IS6);
        ``<distance>`` for named distances. For k > 1 the analog columns carry the
        coordinate name (``dphi3_S1``). A batch gets a (design, position) index.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> f = examples.hitch_003().solve(np.linspace(0.42, 0.67, 10)).to_frame()
        >>> f.shape, list(f.columns[:4])
        ((10, 70), ['S', 'phi2', 'dphi2', 'ddphi2'])
        >>> [round(float(v), 3) for v in f["U53"].iloc[[0, -1]]]   # seed 003 table 3.1 [-]
        [0.666, 0.484]
        >>> [round(float(v), 1) for v in f["phi6"].iloc[[0, -1]]]  # table 2.1 [°]
        [88.5, 110.3]
        """
        import pandas as pd

        cols = {}
        for j, c in enumerate(self.coordinates):
            cols[c] = self._q[j].ravel()
        suffixes = [""] if self.k == 1 else [f"_{c}" for c in self.coordinates]
        wrts = [None] if self.k == 1 else list(self.coordinates)
        for name in self._sidx:
            kind = self._kinds[name]
            if kind == "angle":
                cols[f"phi{name}"] = (self.phi(name, degrees=degrees)).ravel()
                for sfx, w in zip(suffixes, wrts):
                    cols[f"dphi{name}{sfx}"] = self.dphi(name, w).ravel()
                    cols[f"ddphi{name}{sfx}"] = self.ddphi(name, w).ravel()
            else:
                cols[name] = self.length(name).ravel()
                for sfx, w in zip(suffixes, wrts):
                    cols[f"d{name}{sfx}"] = self.dlength(name, w).ravel()
        for p in self._pidx:
            cols[f"X{p}"] = self.x(p).ravel()
            cols[f"Y{p}"] = self.y(p).ravel()
            for sfx, w in zip(suffixes, wrts):
                cols[f"dX{p}{sfx}"] = self.dx(p, w).ravel()
                cols[f"dY{p}{sfx}"] = self.dy(p, w).ravel()
                cols[f"ddX{p}{sfx}"] = self.ddx(p, w).ravel()
                cols[f"ddY{p}{sfx}"] = self.ddy(p, w).ravel()
        tab = self.mechanism.tables
        for i, j in tab.get("ratios", ()):
            for sfx, w in zip(suffixes, wrts):
                r = self.ratio(i, j, w, singular="mask")
                # singular positions are missing (pandas NA), never a number
                cols[f"U{i}{j}{sfx}"] = pd.array(np.ma.getdata(r).ravel(), dtype="Float64",
                                                 ) if not np.ma.is_masked(r) else \
                    pd.arrays.FloatingArray(np.ma.getdata(r).ravel(),
                                            np.ma.getmaskarray(r).ravel())
        for p in tab.get("transmissions", ()):
            for sfx, w in zip(suffixes, wrts):
                cols[f"I{p}{sfx}"] = self.transmission(p, wrt=w).ravel()
        index = None
        if len(self.shape) == 2 or self.m > 1:
            index = pd.MultiIndex.from_product([range(self.m), range(self.n)],
                                               names=["design", "position"])
        return pd.DataFrame(cols, index=index)

    def _repr_html_(self):
        """Summary, drawing and positions in a notebook (:mod:`assur.views.notebook`)."""
        from ..views.notebook import kinematics_html
        return kinematics_html(self)

    def __repr__(self):
        return (f"Kinematics({self.mechanism.name!r}, shape={self.shape}, "
                f"points={len(self._pidx)}, links={len(self.links)})")


def kinematics_of(source, q=None, who="this function"):
    """The :class:`Kinematics` of ``source``: an Analysis (its kinematics), a
    Kinematics (itself) or a Mechanism, solved at the coordinates ``q`` (required
    then; a ValueError naming ``who`` otherwise)."""
    kin = getattr(source, "kinematics", source)
    if hasattr(kin, "solve") and not hasattr(kin, "jacobian"):
        if q is None:
            raise ValueError(f"{who}(mechanism, …) needs the coordinates q")
        kin = kin.solve(q)
    return kin
