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

:class:`Kinematics` holds the kernel's arrays; its methods come by concern from
:class:`~assur.core.analogs.Analogs` (positions and analogs of points, links and
distances by name), :class:`~assur.core.transfer.Transfer` (transfer ratios,
real-time velocities and accelerations) and
:class:`~assur.core.kinematic_checks.KinematicChecks` (instantaneous centre,
transmission angle, closure residual).
"""

from __future__ import annotations

import numpy as np

from .analogs import Analogs
from .kinematic_checks import KinematicChecks
from .transfer import SINGULAR_RTOL, Transfer

__all__ = ["Kinematics", "SINGULAR_RTOL"]


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


class Kinematics(Analogs, Transfer, KinematicChecks):
    """Positions and kinematic analogs of a mechanism over its coordinate range.

    Produced by :meth:`assur.Mechanism.solve`; not constructed directly. Besides its
    own methods (what it holds, the coordinates, the table) it has those of
    :class:`~assur.core.analogs.Analogs` (``x``, ``dy``, ``phi``, ``dphi``,
    ``length``, ``transmission``, …), :class:`~assur.core.transfer.Transfer`
    (``ratio``, ``velocity``, …) and :class:`~assur.core.kinematic_checks.KinematicChecks`
    (``instant_centre``, ``transmission_angle``, ``closure_residual``, …).

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
    path : HeldPath or None
        The held path the positions lie on (:mod:`assur.core.held`; set by
        :meth:`assur.io.Model.analyze` for a ``[range]`` with held coordinates): its
        transmission numbers along the path are tabulated too. None otherwise.

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
        self.path = None
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
        if self.path is not None:
            b.path = self.path.part(i0, i1)
        b._frame = self._frame.sliced(sl) if hasattr(self._frame, "sliced") else \
            {k: v[sl] for k, v in self._frame.items()}
        return b

    # ---- what the result holds ---------------------------------------------------
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

    # ---- coordinates -------------------------------------------------------------
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

    # ---- tables ------------------------------------------------------------------
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

        Along a held path (:mod:`assur.core.held`) the transmission numbers along the
        path, ``I<point>_path`` = dY/ds, come with the partial ones:

        >>> from assur import io
        >>> f = io.load(io.bundled("loader_lab1_level")).analyze().kinematics.to_frame()
        >>> [c for c in f.columns if c.startswith("IS9")]
        ['IS9_S', 'IS9_S1', 'IS9_path']
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
            if self.path is not None:   # along a held path: dY/ds with the held following
                cols[f"I{p}_path"] = self.path.transmission(self, p).ravel()
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
