"""The drawing of the mechanism at chosen positions as DXF, for the design office's CAD.

:func:`write_dxf` writes one DXF file (R2010, drawing units millimetres) with

* one layer per link, ``link_<name>`` (``link_0`` the frame): a rigid link of two
  points is a LINE, of three or more a closed LWPOLYLINE through its points (their
  convex hull), a cylinder (a link of variable length) a LINE on a layer whose
  linetype is ``DASHED``;
* every joint and point as a POINT on the layer ``pivots`` (frame pivots also on
  ``frame_pivots``) with its name as TEXT on ``labels``;
* every wheel (:attr:`assur.Mechanism.wheels`) as a closed LWPOLYLINE through the
  corners of :func:`assur.views.geometry.wheel_outline` on the layer ``wheels``;
* each position as a DXF GROUP named after its coordinate values (``S=0.42 m``).

Coordinates are the model's x, y [m] times 1000 [mm].

Examples
--------
>>> import numpy as np, tempfile, pathlib, ezdxf
>>> from assur import examples
>>> kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 5))
>>> with tempfile.TemporaryDirectory() as d:
...     p = write_dxf(kin, pathlib.Path(d) / "hitch.dxf", positions=[0, 4])
...     doc = ezdxf.readfile(p)
>>> sorted(l.dxf.name for l in doc.layers if l.dxf.name.startswith("link_"))[:3]
['link_0', 'link_2', 'link_3']
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..geometry import convex_hull, geometry, pose, wheel_outline

__all__ = ["write_dxf", "dxf_bytes"]

#: AutoCAD colour indices given to the links in turn
_COLORS = (1, 3, 5, 6, 4, 2, 30, 140, 200, 94)


def _label(geo, i, mech):
    parts = []
    for c, q in geo["q"].items():
        if mech.coordinate_kind(c) == "angle":
            parts.append(f"{c}={np.degrees(q[i]):.6g} deg")
        else:
            parts.append(f"{c}={q[i]:.6g} m")
    return ", ".join(parts)


def _document(kin, positions, design=None):
    import ezdxf
    from ezdxf import units

    geo = geometry(kin, design=design)
    n = geo["n"]
    positions = list(range(n)) if positions is None else [int(i) for i in positions]
    if not positions:
        raise ValueError("positions: give at least one position")
    for i in positions:
        if not -n <= i < n:
            raise ValueError(f"positions must be in 0…{n - 1}, got {i}")
    doc = ezdxf.new("R2010", setup=True)
    doc.units = units.MM
    msp = doc.modelspace()
    span = max(geo["bounds"][2] - geo["bounds"][0], geo["bounds"][3] - geo["bounds"][1], 1e-6)
    h = 0.02 * span * 1e3  # text height [mm]
    for k, b in enumerate(geo["bodies"]):
        name = f"link_{b['name']}"
        if name not in doc.layers:
            layer = doc.layers.add(name, color=_COLORS[k % len(_COLORS)])
            if b["variable"]:
                layer.dxf.linetype = "DASHED"
    for name, color in (("pivots", 7), ("frame_pivots", 7), ("labels", 8)):
        doc.layers.add(name, color=color)
    if geo["wheels"]:
        doc.layers.add("wheels", color=8)
    mech = kin.mechanism
    for i in positions:
        xy = {p: (x * 1e3, y * 1e3) for p, (x, y) in pose(geo, i).items()}
        ents = []
        for w in geo["wheels"]:
            corners = [(x * 1e3, y * 1e3) for x, y in wheel_outline(geo, w, i)]
            ents.append(msp.add_lwpolyline(corners, close=True, dxfattribs={"layer": "wheels"}))
        for b in geo["bodies"]:
            pts = [xy[p] for p in b["points"] if p in xy]
            layer = f"link_{b['name']}"
            if b["name"] == "0":
                continue  # the frame is its pivots
            hull = convex_hull(pts)
            if len(hull) == 2 or (b["variable"] and len(pts) >= 2):
                a, c = (pts[0], pts[1]) if b["variable"] else (hull[0], hull[1])
                ents.append(msp.add_line(a, c, dxfattribs={"layer": layer}))
            elif len(hull) >= 3:
                ents.append(msp.add_lwpolyline(hull, close=True, dxfattribs={"layer": layer}))
        for p, (x, y) in xy.items():
            layer = "frame_pivots" if p in geo["frame"] else "pivots"
            ents.append(msp.add_point((x, y), dxfattribs={"layer": layer}))
            ents.append(msp.add_text(p, height=h, dxfattribs={"layer": "labels",
                                                              "insert": (x + h, y + h)}))
        group = doc.groups.new(_label(geo, i, mech)[:250] or f"position {i}")
        group.extend(ents)
    return doc


def write_dxf(kin, path, positions=None, design=None) -> Path:
    """Write the mechanism at some of its positions as a DXF file.

    Parameters
    ----------
    kin : Kinematics or Analysis
        A solve of the mechanism (an analysis' kinematics are used).
    path : str or Path
        The ``.dxf`` file written.
    positions : sequence of int, optional
        Indices of the positions drawn (default: all).
    design : int, optional
        The design of a batch.

    Returns
    -------
    Path

    Examples
    --------
    >>> import pathlib, tempfile
    >>> import ezdxf
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.page.dxf import write_dxf
    >>> kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 3))   # S [m]
    >>> with tempfile.TemporaryDirectory() as d:
    ...     path = write_dxf(kin, pathlib.Path(d) / "hitch.dxf", positions=[0, 2])
    ...     doc = ezdxf.readfile(path)
    >>> path.name, sorted(g for g, _ in doc.groups)      # one group per position
    ('hitch.dxf', ['S=0.42 m', 'S=0.67 m'])
    >>> doc.layers.get("link_2").dxf.linetype            # the cylinder
    'DASHED'
    """
    kin = getattr(kin, "kinematics", kin)
    doc = _document(kin, positions, design)
    path = Path(path)
    doc.saveas(path)
    return path


def dxf_bytes(kin, positions=None, design=None) -> bytes:
    """The DXF file of :func:`write_dxf` as bytes (UTF-8 text).

    Examples
    --------
    >>> import io
    >>> import ezdxf
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.page.dxf import dxf_bytes
    >>> kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 3))   # S [m]
    >>> data = dxf_bytes(kin, positions=[1])
    >>> doc = ezdxf.read(io.StringIO(data.decode("utf-8")))
    >>> [g for g, _ in doc.groups]
    ['S=0.545 m']
    >>> p = [e for e in doc.modelspace() if e.dxftype() == "POINT"
    ...      and e.dxf.layer == "frame_pivots"]
    >>> sorted((round(e.dxf.location.x, 1), round(e.dxf.location.y, 1)) for e in p)  # [mm]
    [(135.0, 480.0), (250.0, 1112.0), (415.0, 563.0), (415.0, 895.0)]
    >>> dxf_bytes(kin, positions=[3])
    Traceback (most recent call last):
    ...
    ValueError: positions must be in 0…2, got 3
    """
    import io
    kin = getattr(kin, "kinematics", kin)
    doc = _document(kin, positions, design)
    buf = io.StringIO()
    doc.write(buf)
    return buf.getvalue().encode("utf-8")
