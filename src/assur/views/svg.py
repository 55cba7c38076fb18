"""The mechanism's drawing as an inline SVG string (no matplotlib, no browser script).

The same picture the page draws (:mod:`assur.views.geometry`): links in colours
(a rigid link of three or more points as its lightly filled outline), cylinders as
a barrel and a rod, frame pivots as triangles, joints as open circles, other points
as dots, every point and link labelled, weights as arrows down, wheels as grey
rectangles under the links (``<polygon class="wheel">``,
:func:`assur.views.geometry.wheel_outline`). :func:`svg` draws
some positions (the notebooks' ``_repr_html_``, :mod:`assur.views.notebook`);
:func:`frames` draws every position as one frame of an animation (the HTML report's
player, :func:`assur.views.report.drawing.animation`).

Examples
--------
>>> import numpy as np
>>> from assur import examples
>>> from assur.views.geometry import geometry
>>> s = svg(geometry(examples.hitch_003().solve(np.linspace(0.42, 0.67, 3))), [0, 2])
>>> s.startswith("<svg") and 'id="pt-56"' in s
True
"""

from __future__ import annotations

from html import escape

import numpy as np

from .geometry import convex_hull, wheel_outline

__all__ = ["svg", "frames"]

COLORS = ("#1f77b4", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
           "#bcbd22", "#17becf", "#ff7f0e")


def _f(v):
    return f"{v:.6g}"


def cylinder_parts(geo):
    """``{body: (barrel, rod)}`` [m]: the drawn lengths of each variable-length body's
    barrel and rod (fixed over the positions, overlapping at the shortest)."""
    out = {}
    for b in geo["bodies"]:
        if b["variable"] and len(b["points"]) >= 2:
            a = np.asarray(geo["points"][b["points"][0]])
            c = np.asarray(geo["points"][b["points"][1]])
            L = np.hypot(*(c - a).T)
            lmin, lmax = float(L.min()), float(L.max())
            barrel = 0.7 * lmin
            out[b["name"]] = (barrel, min(max(lmax - barrel + 0.08 * lmin, 0.35 * lmin),
                                          0.95 * lmin))
    return out


def _pose(geo, i, cyl, span, ghost, labels, ids=True):
    xy = {p: (v[i][0], -v[i][1]) for p, v in geo["points"].items()}  # SVG y is down
    fs, hh = 0.028 * span, 0.035 * span
    op = ' opacity="0.3"' if ghost else ""
    out, k = [f"<g{op}>"], 0
    allp = np.array(list(xy.values()))
    centre = allp.mean(axis=0)
    for w in geo.get("wheels", ()):  # under the links
        if w["point"] in xy:
            ps = " ".join(f"{_f(x)},{_f(-y)}" for x, y in wheel_outline(geo, w, i))
            out.append(f'<polygon class="wheel" points="{ps}" fill="#555" fill-opacity="0.18" '
                       f'stroke="#333" stroke-width="1.5" vector-effect="non-scaling-stroke"/>')
    for b in geo["bodies"]:
        if b["name"] == "0":
            continue
        pts = [xy[p] for p in b["points"] if p in xy]
        col = "#888" if ghost else COLORS[k % len(COLORS)]
        k += 1
        if b["name"] in cyl and len(pts) >= 2:
            a, c = np.array(pts[0]), np.array(pts[1])
            L = float(np.hypot(*(c - a))) or 1e-12
            u = (c - a) / L
            barrel, rod = cyl[b["name"]]
            e1, e2 = a + u * min(barrel, L), c - u * min(rod, L)
            out.append(f'<line x1="{_f(a[0])}" y1="{_f(a[1])}" x2="{_f(e1[0])}" '
                       f'y2="{_f(e1[1])}" stroke="#4a7ab8" stroke-width="9" '
                       f'vector-effect="non-scaling-stroke"/>')
            out.append(f'<line x1="{_f(e2[0])}" y1="{_f(e2[1])}" x2="{_f(c[0])}" '
                       f'y2="{_f(c[1])}" stroke="#222" stroke-width="3" '
                       f'vector-effect="non-scaling-stroke"/>')
            mid = a + u * 0.5 * min(barrel, L)
        else:
            hull = convex_hull(pts)
            if len(hull) >= 3:
                ps = " ".join(f"{_f(x)},{_f(y)}" for x, y in hull)
                out.append(f'<polygon points="{ps}" fill="{col}" fill-opacity="0.12" '
                           f'stroke="{col}" stroke-width="2.5" '
                           f'vector-effect="non-scaling-stroke"/>')
            elif len(hull) == 2:
                (x1, y1), (x2, y2) = hull
                out.append(f'<line x1="{_f(x1)}" y1="{_f(y1)}" x2="{_f(x2)}" y2="{_f(y2)}" '
                           f'stroke="{col}" stroke-width="3" stroke-linecap="round" '
                           f'vector-effect="non-scaling-stroke"/>')
            mid = np.mean(np.array(hull), axis=0) if hull else np.array(pts[0])
        if labels and not ghost:
            out.append(f'<text x="{_f(mid[0] + 0.3 * fs)}" y="{_f(mid[1] - 0.3 * fs)}" '
                       f'font-size="{_f(1.1 * fs)}" fill="{col}" font-style="italic" '
                       f'font-weight="bold">{escape(b["name"])}</text>')
    for p in geo["frame"]:
        x, y = xy[p]
        out.append(f'<polygon points="{_f(x)},{_f(y)} {_f(x - 0.55 * hh)},{_f(y + hh)} '
                   f'{_f(x + 0.55 * hh)},{_f(y + hh)}" fill="#fff" stroke="#000" '
                   f'stroke-width="1.2" vector-effect="non-scaling-stroke"/>')
    joints = set(geo["joints"])
    for p, (x, y) in xy.items():
        j = p in joints
        pid = "" if ghost or not ids else f' id="pt-{escape(p, quote=True)}"'
        out.append(f'<circle{pid} cx="{_f(x)}" cy="{_f(y)}" r="{_f((0.011 if j else 0.007) * span)}" '
                   f'fill="{"#fff" if j else "#000"}" stroke="#000" stroke-width="1.3" '
                   f'vector-effect="non-scaling-stroke"/>')
        if labels and not ghost:
            d = np.array([x, y]) - centre
            n = float(np.hypot(*d)) or 1.0
            out.append(f'<text x="{_f(x + d[0] / n * 1.4 * fs)}" y="{_f(y + d[1] / n * 1.4 * fs)}" '
                       f'font-size="{_f(fs)}" text-anchor="middle" dominant-baseline="middle">'
                       f'{escape(p)}</text>')
    if not ghost:
        for w in geo["weights"]:
            if w["point"] in xy:
                x, y = xy[w["point"]]
                L = 0.12 * span
                out.append(f'<line x1="{_f(x)}" y1="{_f(y)}" x2="{_f(x)}" y2="{_f(y + L)}" '
                           f'stroke="#d62728" stroke-width="1.5" '
                           f'vector-effect="non-scaling-stroke"/>')
                out.append(f'<polygon points="{_f(x)},{_f(y + L)} {_f(x - 0.15 * L)},'
                           f'{_f(y + 0.75 * L)} {_f(x + 0.15 * L)},{_f(y + 0.75 * L)}" '
                           f'fill="#d62728"/>')
                out.append(f'<text x="{_f(x + 0.2 * L)}" y="{_f(y + L)}" font-size="{_f(fs)}" '
                           f'fill="#d62728">{escape(w["name"])}</text>')
    out.append("</g>")
    return out


def svg(geo: dict, positions=None, width: int = 560, height: int = 420,
        labels: bool = True) -> str:
    """The drawing at some positions as an SVG element.

    Parameters
    ----------
    geo : dict
        :func:`assur.views.geometry.geometry`'s data.
    positions : sequence of int, optional
        Indices of the positions; the first is drawn in colour with labels, the
        others as light outlines. Default: the first and the last.
    width, height : int
        Size of the element [px].

    Returns
    -------
    str
        ``<svg …>…</svg>`` (coordinates in m, y up).

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.geometry import geometry
    >>> from assur.views.svg import svg
    >>> g = geometry(examples.hitch_003().solve(np.linspace(0.42, 0.67, 3)))   # S [m]
    >>> s = svg(g, positions=[2, 0], width=400, height=300)   # S = 0.67 m in colour
    >>> s.startswith("<svg"), 'width="400" height="300"' in s   # [px]
    (True, True)
    >>> s.count('<g opacity="0.3">'), s.count('id="pt-')   # one ghost; the labelled points
    (1, 11)
    """
    positions = _positions(geo, positions)
    span = view_span(geo)
    cyl = cylinder_parts(geo)
    body = []
    for i in positions[1:]:
        body += _pose(geo, i, cyl, span, True, False)
    body += _pose(geo, positions[0], cyl, span, False, labels)
    return _element(geo, width, height, "".join(body))


def frames(geo: dict, positions=None, width: int = 640, height: int = 500,
           labels: bool = True, element_id: str = "anim-svg") -> str:
    """Every position (or the chosen ones) as one frame of an animation: an SVG
    element holding a group ``<g class="frame">`` per frame, the first shown, the others
    ``display="none"`` (a script shows one at a time; printed, the first is seen). For an
    HTML document: the element names no namespace address, as HTML needs none.

    Parameters
    ----------
    geo : dict
        :func:`assur.views.geometry.geometry`'s data.
    positions : sequence of int, optional
        The positions drawn, in the order played. Default: every one.
    width, height : int
        Size of the element [px].
    labels : bool
        Label points and links in every frame.
    element_id : str
        The element's ``id`` (the player finds its frames by it).

    Returns
    -------
    str
        ``<svg id=…>…</svg>`` (coordinates in m, y up; one view box for every frame).

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.geometry import geometry
    >>> from assur.views.svg import frames
    >>> g = geometry(examples.hitch_003().solve(np.linspace(0.42, 0.67, 4)))   # S [m]
    >>> s = frames(g)
    >>> s.count('<g class="frame"'), s.count('<g class="frame" display="none"')
    (4, 3)
    >>> 'id="pt-' in s        # point ids are the page's, not repeated in every frame
    False
    """
    n = geo["n"]
    positions = list(range(n)) if positions is None else _positions(geo, positions)
    span = view_span(geo)
    cyl = cylinder_parts(geo)
    body = []
    for k, i in enumerate(positions):
        hidden = "" if k == 0 else ' display="none"'
        body.append(f'<g class="frame"{hidden}>')
        body += _pose(geo, i, cyl, span, False, labels, ids=False)
        body.append("</g>")
    return _element(geo, width, height, "".join(body), element_id, xmlns=False)


def _positions(geo, positions):
    n = geo["n"]
    positions = sorted({0, n - 1}) if positions is None else [int(i) for i in positions]
    for i in positions:
        if not -n <= i < n:
            raise ValueError(f"positions must be in 0…{n - 1}, got {i}")
    return positions


def view_span(geo):
    """The larger side of the bounds over every position [m] (the scale of marks)."""
    x0, y0, x1, y1 = geo["bounds"]
    return max(x1 - x0, y1 - y0, 1e-6)


def _element(geo, width, height, body, element_id=None, xmlns=True):
    """The ``<svg>`` element around ``body``; without ``xmlns`` for an element inside an
    HTML document (which names no address then)."""
    x0, y0, x1, y1 = geo["bounds"]
    m = 0.12 * view_span(geo)
    eid = f' id="{escape(element_id, quote=True)}"' if element_id else ""
    ns = ' xmlns="http://www.w3.org/2000/svg"' if xmlns else ""
    return (f'<svg{ns}{eid} width="{width}" height="{height}" '
            f'viewBox="{_f(x0 - m)} {_f(-(y1 + m))} {_f(x1 - x0 + 2 * m)} '
            f'{_f(y1 - y0 + 2.6 * m)}" preserveAspectRatio="xMidYMid meet" '
            f'font-family="sans-serif">' + body + "</svg>")
