"""The mechanism's drawing as plain data: what the page, the inline SVG and the DXF draw.

:func:`geometry` reads a solved :class:`~assur.core.kinematics.Kinematics` (one design)
through the public API of the mechanism — its frame points, rigid bodies
(:attr:`assur.Mechanism.bodies`), named distances and cylinders, weights — and
returns JSON-ready lists:

* ``points``: ``{name: [[x0, y0], [x1, y1], …]}`` over the positions [m];
* ``bodies``: ``[{"name", "points", "variable"}]`` — a body with ``variable``
  true is a link of variable length (a hydraulic cylinder, also a passive one on a
  named distance), drawn as a barrel and a rod;
* ``frame``: the frame pivots; ``joints``: points shared by two bodies or on the
  frame (drawn as open circles; other points, a centre of mass, as dots);
* ``weights``: ``[{"point", "name"}]``;
* ``wheels``: ``[{"name", "point", "heading", "length", "width"}]`` — the wheels of the
  mechanism (:attr:`assur.Mechanism.wheels`, ``[[wheels]]`` of a model file; empty
  without them): ``name`` a string or ``{"en": …, "ru": …}``, ``point`` the point it
  is centred on, ``heading`` its rolling direction at every position [rad, model
  frame: from +x, counter-clockwise] — the angle φ of its link plus the declared
  offset —, ``length`` its diameter and ``width`` its width [m]; drawn as the
  rectangle :func:`wheel_outline`;
* ``bounds``: ``[xmin, ymin, xmax, ymax]`` over every position [m] (the wheels'
  outlines included);
* ``q``: ``{coordinate: [values]}`` [m or rad].

Examples
--------
>>> import numpy as np
>>> from assur import examples
>>> g = geometry(examples.hitch_003().solve(np.linspace(0.42, 0.67, 3)))
>>> sorted(g["frame"]), len(g["points"]["56"])
(['01', '03', '05', '07'], 3)
>>> [b["name"] for b in g["bodies"] if b["variable"]]
['2']
"""

from __future__ import annotations

import numpy as np

__all__ = ["geometry", "pose", "convex_hull", "wheel_outline"]


def convex_hull(points) -> list:
    """Convex hull of a body's points, counter-clockwise, as ``[(x, y), …]`` [m]
    (Andrew's monotone chain; coordinates rounded to 1e-12 m so that coincident
    points count once; collinear points give their two ends) — the outline the
    page, the SVG, the DXF and the report's drawing give a body of three or more
    points.

    Examples
    --------
    >>> from assur.views.geometry import convex_hull
    >>> square = [(0, 0), (1, 0), (0.5, 0.5), (1, 1), (0, 1), (0, 0)]   # [m]
    >>> [tuple(float(c) for c in p) for p in convex_hull(square)]    # inner point dropped
    [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    >>> [tuple(float(c) for c in p) for p in convex_hull([(0, 0), (1, 1), (2, 2)])]
    [(0.0, 0.0), (2.0, 2.0)]
    """
    pts = sorted(set(map(tuple, np.round(np.asarray(points, dtype=float), 12))))
    if len(pts) <= 2:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _loads_weights(mech):
    from ..core.loads import Weight
    out = []
    for ld in mech.loads:
        if isinstance(ld, Weight):
            name = ld.name or (ld.P if isinstance(ld.P, str) else "P")
            out.append({"point": ld.point, "name": str(name)})
    return out


def _name(name):
    """A name as JSON: a plain string, or ``{"en": …, "ru": …}`` for a
    :class:`assur.texts.Text` with translations."""
    tr = getattr(name, "translations", None)
    return {"en": str(name), **tr} if tr else str(name)


def _wheels(kin, pick, design) -> list:
    """The ``wheels`` entries of :func:`geometry` (``pick``: one design's values over
    the positions; ``design``: the design of a batch, or None)."""
    from ..groups.base import ref_value
    mech = kin.mechanism

    def value(ref):  # one design's value of a parameter (an array over designs) [SI]
        v = np.asarray(ref_value(mech.params, ref), dtype=float)
        if v.ndim and design is not None and v.size > 1:
            v = v[design]
        return float(np.ravel(v)[0])

    out = []
    for w in mech.wheels:
        heading = value(w.heading) + (pick(kin.phi(w.link)) if w.link is not None
                                      else np.zeros(kin.shape[-1]))
        out.append({"name": _name(w.name), "point": w.at, "heading": heading.tolist(),
                    "length": value(w.diameter), "width": value(w.width)})
    return out


def wheel_outline(geo: dict, wheel: dict, i: int) -> list:
    """The corners of a wheel at position ``i``: a rectangle of the wheel's ``length``
    along its heading and ``width`` across it, centred on its point, counter-clockwise
    from the rear right corner, ``[[x, y], …]`` [m] — the shape the page, the SVG, the
    DXF and the report's drawing give a wheel.

    Parameters
    ----------
    geo : dict
        :func:`geometry`'s data (its ``points``).
    wheel : dict
        One of its ``wheels``.
    i : int
        The position.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.geometry import geometry, wheel_outline
    >>> m = examples.hitch_003().wheel("rear", at="01", diameter=1.1, width=0.3)   # [m]
    >>> g = geometry(m.solve([0.42]))                     # S [m]; 01 at (0.415, 0.563)
    >>> [[round(c, 3) for c in p] for p in wheel_outline(g, g["wheels"][0], 0)]
    [[-0.135, 0.413], [0.965, 0.413], [0.965, 0.713], [-0.135, 0.713]]
    """
    x, y = geo["points"][wheel["point"]][i]
    h = wheel["heading"][i]
    u = np.array([np.cos(h), np.sin(h)]) * (0.5 * wheel["length"])
    v = np.array([-np.sin(h), np.cos(h)]) * (0.5 * wheel["width"])
    c = np.array([x, y], dtype=float)
    return [(c + a * u + b * v).tolist() for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]


def geometry(kin, design=None) -> dict:
    """The drawing data of a solved mechanism over its positions.

    Parameters
    ----------
    kin : Kinematics
        A solve of one design (positions shape ``(n,)``), or of a batch with
        ``design`` given.
    design : int, optional
        The design of a batch (``kin.shape == (designs, n)``).

    Returns
    -------
    dict
        JSON-ready (lists of floats), see the module notes. Coordinates [m].

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.geometry import geometry
    >>> g = geometry(examples.hitch_003().solve(np.linspace(0.42, 0.67, 3)))   # S [m]
    >>> g["n"], g["q"], g["joints"]              # positions, S [m], pivots
    (3, {'S': [0.42, 0.545, 0.67]}, ['01', '03', '05', '07', '23', '34', '45', '56', '67'])
    >>> [round(v, 3) for v in g["bounds"]]       # xmin, ymin, xmax, ymax [m]
    [0.135, 0.184, 1.994, 1.526]
    """
    mech = kin.mechanism
    n = kin.shape[-1]
    if len(kin.shape) == 2 and design is None:
        raise ValueError(f"a batch of {kin.shape[0]} designs: give design=")

    def pick(a):
        a = np.asarray(a, dtype=float)
        if a.ndim == 2:
            a = a[design]
        return np.broadcast_to(a, (n,))

    xy = {}
    for p in list(mech.frame_points) + list(kin.points):
        xy[p] = np.stack([pick(kin.x(p)), pick(kin.y(p))], axis=-1)
    bodies = [{"name": str(b), "points": [p for p in v["points"] if p in xy],
               "variable": bool(v["variable"])} for b, v in mech.bodies.items()]
    names = {b["name"] for b in bodies}
    ends = {d.name: (d.a, d.b) for d in mech.distances}
    for c in mech.cylinders:  # a passive cylinder on a named distance
        if c.coordinate is None and c.distance in ends and c.name not in names:
            bodies.append({"name": str(c.name), "points": list(ends[c.distance]),
                           "variable": True})
    used = {}
    for b in bodies:
        for p in b["points"]:
            used.setdefault(p, []).append(b["name"])
    frame = list(mech.frame_points)
    joints = sorted(p for p, bs in used.items() if len(bs) > 1 or p in frame)
    wheels = _wheels(kin, pick, design)
    allxy = np.concatenate(list(xy.values())) if xy else np.zeros((1, 2))
    if wheels:  # the view holds the wheels' outlines too
        allxy = np.concatenate([allxy] + [np.array(wheel_outline({"points": xy}, w, i))
                                          for w in wheels for i in range(n)])
    lo, hi = allxy.min(axis=0), allxy.max(axis=0)
    return {
        "points": {p: v.tolist() for p, v in xy.items()},
        "bodies": bodies,
        "frame": frame,
        "joints": joints,
        "weights": _loads_weights(mech),
        "wheels": wheels,
        "bounds": [float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])],
        "q": {c: pick(kin.q(c)).tolist() for c in kin.coordinates},
        "n": int(n),
    }


def pose(geo: dict, i: int) -> dict:
    """The points of position ``i`` of :func:`geometry`'s data: ``{name: (x, y)}`` [m].

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.geometry import geometry, pose
    >>> g = geometry(examples.hitch_003().solve(np.linspace(0.42, 0.67, 3)))   # S [m]
    >>> [round(v, 4) for v in pose(g, 0)["56"]]   # the suspension axis at S = 0.42 m [m]
    [1.1314, 0.2]
    >>> pose(g, 3)
    Traceback (most recent call last):
    ...
    ValueError: position must be in 0…2, got 3
    """
    n = geo["n"]
    if not -n <= i < n:
        raise ValueError(f"position must be in 0…{n - 1}, got {i}")
    return {p: tuple(v[i]) for p, v in geo["points"].items()}
