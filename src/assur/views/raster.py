"""The mechanism's animation frames as raster images drawn with Pillow (no matplotlib):
the picture of :mod:`assur.views.svg` — links in colours (a rigid link of three or more
points as its lightly filled outline), cylinders as a barrel and a rod, frame pivots
as triangles, joints as open circles, other points as dots, points and links
labelled, weights as arrows down, wheels as grey rectangles — with a caption per
frame, for the GIF of ``assur analyze`` and of ``assur simulate``
(:func:`assur.views.report.drawing.render_frames`).

Each frame is drawn at twice its size and reduced (anti-aliased lines and text), a few
milliseconds a frame where a matplotlib figure took a tenth of a second.

Examples
--------
>>> import numpy as np
>>> from assur import examples
>>> from assur.views.geometry import geometry
>>> g = geometry(examples.hitch_003().solve(np.linspace(0.42, 0.67, 3)))
>>> imgs = images(g, [0, 2], 320, 250, ["S = 0.42 m", "S = 0.67 m"], title="hitch")
>>> len(imgs), imgs[0].size, imgs[0].mode, imgs[0].tobytes() != imgs[1].tobytes()
(2, (320, 250), 'RGB', True)
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .geometry import convex_hull, wheel_outline
from .svg import COLORS, cylinder_parts, view_span

__all__ = ["images"]

#: supersampling factor (drawn this many times larger, then reduced)
_SS = 2


@lru_cache(maxsize=8)
def _font(size: int):
    """DejaVu Sans (matplotlib's own font: Latin, Cyrillic, Greek) at ``size`` px."""
    from pathlib import Path

    import matplotlib
    from PIL import ImageFont
    path = Path(matplotlib.get_data_path()) / "fonts" / "ttf" / "DejaVuSans.ttf"
    return ImageFont.truetype(str(path), size)


def _fitted(text: str, font, width: float) -> str:
    """``text`` cut at a word with "…" to fit ``width`` px in ``font``."""
    if font.getlength(text) <= width:
        return text
    words = text.split(" ")
    while len(words) > 1 and font.getlength(" ".join(words) + " …") > width:
        words.pop()
    return " ".join(words) + " …"


def _rgb(color: str):
    c = color.lstrip("#")
    if len(c) == 3:
        c = "".join(ch * 2 for ch in c)
    return tuple(int(c[k:k + 2], 16) for k in (0, 2, 4))


def _faint(rgb, alpha):
    """``rgb`` over white with opacity ``alpha``."""
    return tuple(int(round(255 - alpha * (255 - v))) for v in rgb)


def images(geo: dict, positions, width: int, height: int, captions=None, title=None,
           labels: bool = True) -> list:
    """The positions of ``geo`` (:func:`assur.views.geometry.geometry`) as RGB images of
    ``width`` × ``height`` px on one fixed view (the bounds over every position), each
    with ``title`` and its caption above the drawing.

    Parameters
    ----------
    geo : dict
    positions : sequence of int
        The positions drawn, one image each, in order.
    width, height : int
        Image size [px].
    captions : sequence of str, optional
        A line per image (the coordinates of its position).
    title : str, optional
        A line above every caption (the machine's title).
    labels : bool
        Label points and links.

    Returns
    -------
    list of PIL.Image.Image

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.geometry import geometry
    >>> from assur.views.raster import images
    >>> g = geometry(examples.hitch_003().solve(np.array([0.42])))
    >>> images(g, [0], 200, 150)[0].size
    (200, 150)
    """
    from PIL import Image, ImageDraw

    W, H = width * _SS, height * _SS
    lines = [s for s in (title,) if s]
    head = int(round((0.055 * H) * (len(lines) + (1 if captions else 0)))) + 4 * _SS
    x0, y0, x1, y1 = geo["bounds"]
    span = view_span(geo)
    m = 0.08 * span
    sx = (W - 2 * 6 * _SS) / (x1 - x0 + 2 * m)
    sy = (H - head - 6 * _SS) / (y1 - y0 + 2 * m)
    s = min(sx, sy)
    ox = (W - s * (x1 - x0)) / 2 - s * x0
    oy = head + (H - head + s * (y1 - y0)) / 2 + s * y0

    def px(p):
        return (ox + s * p[0], oy - s * p[1])

    cyl = cylinder_parts(geo)
    small = _font(max(int(0.028 * H), 8))
    big = _font(max(int(0.034 * H), 9))
    out = []
    for k, i in enumerate(positions):
        img = Image.new("RGB", (W, H), "white")
        d = ImageDraw.Draw(img)
        y = 2 * _SS
        for text in lines + ([captions[k]] if captions else []):
            d.text((W / 2, y), _fitted(text, big, W - 8 * _SS), fill=(0, 0, 0), font=big,
                   anchor="ma")
            y += int(0.055 * H)
        _pose(d, geo, i, cyl, span, px, s, small, labels)
        # each output pixel the mean of its _SS × _SS drawn pixels (a box filter: the
        # antialiasing of a supersampled drawing; a Lanczos resize cost 13 ms a frame)
        out.append(img.reduce(_SS))
    return out


def _pose(d, geo, i, cyl, span, px, s, font, labels):
    """One position drawn on ``d`` (the shapes of :func:`assur.views.svg._pose`)."""
    xy = {p: px(v[i]) for p, v in geo["points"].items()}
    lw = max(int(round(1.5 * _SS)), 1)
    allp = np.array(list(xy.values()))
    centre = allp.mean(axis=0)
    for w in geo.get("wheels", ()):  # under the links
        if w["point"] in xy:
            d.polygon([px(c) for c in wheel_outline(geo, w, i)],
                      fill=_faint((85, 85, 85), 0.18), outline=(51, 51, 51), width=lw)
    k = 0
    for b in geo["bodies"]:
        if b["name"] == "0":
            continue
        pts = [xy[p] for p in b["points"] if p in xy]
        col = _rgb(COLORS[k % len(COLORS)])
        k += 1
        if b["name"] in cyl and len(pts) >= 2:
            a, c = np.array(pts[0]), np.array(pts[1])
            L = float(np.hypot(*(c - a))) or 1e-12
            u = (c - a) / L
            barrel, rod = (v * s for v in cyl[b["name"]])
            e1, e2 = a + u * min(barrel, L), c - u * min(rod, L)
            d.line([tuple(a), tuple(e1)], fill=_rgb("#4a7ab8"), width=6 * _SS)
            d.line([tuple(e2), tuple(c)], fill=(34, 34, 34), width=2 * _SS)
            mid = a + u * 0.5 * min(barrel, L)
        else:
            hull = convex_hull(pts)
            if len(hull) >= 3:
                d.polygon([tuple(p) for p in hull], fill=_faint(col, 0.12), outline=col,
                          width=2 * _SS)
            elif len(hull) == 2:
                d.line([tuple(p) for p in hull], fill=col, width=2 * _SS)
            mid = np.mean(np.array(hull), axis=0) if hull else np.array(pts[0])
        if labels:
            d.text((mid[0] + 4 * _SS, mid[1] - 4 * _SS), str(b["name"]), fill=col, font=font,
                   anchor="ls")
    hh = 0.035 * span * s
    for p in geo["frame"]:
        x, y = xy[p]
        d.polygon([(x, y), (x - 0.55 * hh, y + hh), (x + 0.55 * hh, y + hh)], fill="white",
                  outline=(0, 0, 0), width=lw)
    joints = set(geo["joints"])
    for p, (x, y) in xy.items():
        r = (0.011 if p in joints else 0.007) * span * s
        d.ellipse([x - r, y - r, x + r, y + r], fill="white" if p in joints else "black",
                  outline=(0, 0, 0), width=lw)
        if labels:
            dv = np.array([x, y]) - centre
            n = float(np.hypot(*dv)) or 1.0
            off = 0.045 * span * s
            d.text((x + dv[0] / n * off, y + dv[1] / n * off), str(p), fill=(0, 0, 0),
                   font=font, anchor="mm")
    red = _rgb("#d62728")
    for w in geo["weights"]:
        if w["point"] in xy:
            x, y = xy[w["point"]]
            L = 0.12 * span * s
            d.line([(x, y), (x, y + L)], fill=red, width=lw)
            d.polygon([(x, y + L), (x - 0.15 * L, y + 0.75 * L), (x + 0.15 * L, y + 0.75 * L)],
                      fill=red)
            d.text((x + 0.2 * L, y + L), str(w["name"]), fill=red, font=font, anchor="ls")
