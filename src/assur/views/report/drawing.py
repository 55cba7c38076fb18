"""Drawings of the mechanism at chosen positions and its animation over the range.

The drawing is made from the model's rigid bodies (:attr:`assur.Mechanism.bodies`):

* a rigid link with two points is a line between them; with three or more (a
  bell-crank, the implement with its centre of mass) a lightly filled polygon
  (their convex hull);
* a link of variable length (a hydraulic cylinder, also a passive one on a named
  distance) is a thick barrel from its base and a thin rod from its other end, of
  fixed lengths, so the rod slides out of the barrel over the stroke;
* frame pivots are hatched triangles; joints are open circles, other points
  (a centre of mass) dots; a weight is an arrow down labelled with its name;
* every point is labelled with its name, every link with its name in its colour;
* a wheel (:attr:`assur.Mechanism.wheels`) is a grey rectangle under the links, turned
  by its heading (:func:`assur.views.geometry.wheel_outline`; the patch's gid is
  ``"wheel"``).

:func:`draw` returns a figure with the mechanism at one or several positions
(the first drawn in colour with labels, the others as light outlines).
:func:`render_frames` renders the animation frames (Agg) and :func:`write_gif`
writes them as an animated GIF (Pillow, as ``matplotlib.animation.PillowWriter``
does); the HTML report plays the same positions as vector frames (:func:`animation`,
drawn by :mod:`assur.views.svg` without matplotlib).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.patches import Polygon, Rectangle

from ..geometry import convex_hull
from ...core.loads import Weight
from ...texts import localize
from ._canvas import new_figure
from .labels import check_lang, t, unit
from .tables import _View

__all__ = ["draw", "animation", "player", "render_frames", "write_gif"]


class _Geometry:
    """Point positions of one design over a set of positions: ``xy[name]`` (n, 2), in
    the display unit of length of the view (:attr:`_View.units`)."""

    def __init__(self, view, kin=None):
        kin = kin if kin is not None else view.kin
        mech = view.mech
        self.mech = mech
        self.kin = kin
        design = view.design if len(kin.shape) == 2 else None
        n = kin.shape[-1]

        def pick(a):
            a = np.asarray(a)
            if a.ndim == 2:
                a = a[design]
            return np.broadcast_to(a, (n,))

        self.n = n
        self.xy = {}
        per_m = 1.0 / view.units["length"].scale  # display units of length per metre
        for p in list(mech.frame_points) + list(kin.points):
            self.xy[p] = np.stack([pick(kin.x(p)), pick(kin.y(p))], axis=-1) * per_m
        self.q = {c: pick(kin.q(c)) for c in kin.coordinates}
        self.bodies = {b: v for b, v in mech.bodies.items()}
        # a passive cylinder (on a named distance) is drawn as a cylinder between its ends
        ends = {d.name: (d.a, d.b) for d in mech.distances}
        for c in mech.cylinders:
            if c.coordinate is None and c.distance in ends and c.name not in self.bodies:
                self.bodies[c.name] = {"points": list(ends[c.distance]), "variable": True}
        used = {}
        for b, v in self.bodies.items():
            for p in v["points"]:
                used.setdefault(p, []).append(b)
        self.joints = {p for p, bs in used.items() if len(bs) > 1 or p in mech.frame_points}
        self.weights = [(ld.point, ld.name or (ld.P if isinstance(ld.P, str) else "P"))
                        for ld in mech.loads if isinstance(ld, Weight)]
        # the wheels' corners at every position, (n, 4, 2) each (the shape of
        # assur.views.geometry.wheel_outline, in the view's unit of length)
        self.wheels = []
        if mech.wheels:
            from ..geometry import geometry, wheel_outline
            g = geometry(kin, design=design)
            self.wheels = [np.array([wheel_outline(g, w, i) for i in range(n)]) * per_m
                           for w in g["wheels"]]
        allxy = np.concatenate([v for v in self.xy.values()]) if self.xy else np.zeros((1, 2))
        ends = np.concatenate([allxy] + [w.reshape(-1, 2) for w in self.wheels])
        lo, hi = ends.min(axis=0), ends.max(axis=0)
        self.span = float(max(hi[0] - lo[0], hi[1] - lo[1], 1e-9))
        self.lo, self.hi = lo, hi
        self.centre = allxy.mean(axis=0)
        # fixed barrel and rod lengths of each variable link (a cylinder)
        self.cyl = {}
        for b, v in self.bodies.items():
            if v["variable"] and len(v["points"]) >= 2:
                p0, p1 = v["points"][:2]
                L = np.hypot(*(self.xy[p1] - self.xy[p0]).T)
                lmin, lmax = float(L.min()), float(L.max())
                barrel = 0.7 * lmin
                rod = min(max(lmax - barrel + 0.08 * lmin, 0.35 * lmin), 0.95 * lmin)
                self.cyl[b] = (barrel, rod)


def _ground(ax, x, y, h, color, alpha):
    """A hatched triangle under the frame pivot (x, y)."""
    tri = Polygon([(x, y), (x - 0.55 * h, y - h), (x + 0.55 * h, y - h)], closed=True,
                  facecolor="white", edgecolor=color, lw=1.0, alpha=alpha, zorder=3)
    ax.add_patch(tri)
    ax.add_patch(Rectangle((x - 0.8 * h, y - 1.35 * h), 1.6 * h, 0.35 * h, facecolor="none",
                           edgecolor=color, hatch="////", lw=0.0, alpha=alpha, zorder=3))
    ax.plot([x - 0.8 * h, x + 0.8 * h], [y - h, y - h], color=color, lw=1.0, alpha=alpha,
            zorder=3)


def _pose(ax, geo, i, ghost=False, labels=True, colors=None):
    """Draw the mechanism at position ``i``."""
    xy = {p: v[i] for p, v in geo.xy.items()}
    alpha = 0.25 if ghost else 1.0
    h = 0.035 * geo.span
    colors = colors or {}
    for ring in geo.wheels:  # under the links
        ax.add_patch(Polygon(ring[i], closed=True, facecolor=(0.33, 0.33, 0.33, 0.18 * alpha),
                             edgecolor=(0.2, 0.2, 0.2, alpha), lw=1.2, zorder=0.5, gid="wheel"))
    k = 0
    for b, v in geo.bodies.items():
        if b == "0":
            continue
        pts = [xy[p] for p in v["points"] if p in xy]
        if len(pts) < 1:
            continue
        col = "0.5" if ghost else colors.get(b, f"C{k % 10}")
        k += 1
        if b in geo.cyl:
            a, c = np.array(pts[0]), np.array(pts[1])
            L = float(np.hypot(*(c - a)))
            u = (c - a) / L if L > 0 else np.zeros(2)
            barrel, rod = geo.cyl[b]
            e1 = a + u * min(barrel, L)
            e2 = c - u * min(rod, L)
            ax.plot([a[0], e1[0]], [a[1], e1[1]], color="0.55" if ghost else "#4a7ab8", lw=7,
                    solid_capstyle="butt", alpha=alpha, zorder=2)
            ax.plot([e2[0], c[0]], [e2[1], c[1]], color="0.3" if ghost else "#222222", lw=2.2,
                    alpha=alpha, zorder=2.5)
            mid = a + u * 0.5 * min(barrel, L)
        else:
            hull = np.array(convex_hull(pts))
            if len(hull) >= 3:
                ax.add_patch(Polygon(hull, closed=True, facecolor=col, alpha=0.12 * alpha,
                                     edgecolor="none", zorder=1))
                ring = np.vstack([hull, hull[:1]])
                ax.plot(ring[:, 0], ring[:, 1], color=col, lw=2.2, alpha=alpha, zorder=2)
            elif len(hull) == 2:
                ax.plot(hull[:, 0], hull[:, 1], color=col, lw=2.6, alpha=alpha, zorder=2,
                        solid_capstyle="round")
            mid = np.mean(hull, axis=0) if len(hull) else np.array(pts[0])
        if labels and not ghost:
            d = mid - geo.centre
            off = 0.0 if not np.any(d) else 1.0
            ax.annotate(b, mid, textcoords="offset points",
                        xytext=(7 * off * np.sign(d[0] or 1), 7 * off * np.sign(d[1] or 1)),
                        color="#4a7ab8" if b in geo.cyl else col, fontsize=10,
                        fontweight="bold", fontstyle="italic", zorder=6,
                        bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.7))
    for p in geo.mech.frame_points:
        _ground(ax, *xy[p], h, "0.55" if ghost else "black", alpha)
    for p, (x, y) in xy.items():
        if p in geo.joints:
            ax.plot(x, y, "o", ms=6, mfc="white", mec="0.5" if ghost else "black", mew=1.3,
                    alpha=alpha, zorder=4)
        else:
            ax.plot(x, y, "o", ms=4, color="0.5" if ghost else "black", alpha=alpha, zorder=4)
        if labels and not ghost:
            d = np.array([x, y]) - geo.centre
            n = np.hypot(*d)
            off = d / n * 12 if n > 0 else np.array([8.0, 8.0])
            ax.annotate(p, (x, y), textcoords="offset points", xytext=tuple(off), fontsize=8,
                        ha="center", va="center", zorder=6)
    if not ghost:
        for p, name in geo.weights:
            if p in xy:
                x, y = xy[p]
                ax.annotate("", xy=(x, y - 0.12 * geo.span), xytext=(x, y),
                            arrowprops=dict(arrowstyle="-|>", color="C3", lw=1.5), zorder=5)
                ax.annotate(str(name), (x, y - 0.12 * geo.span), textcoords="offset points",
                            xytext=(4, 0), color="C3", fontsize=9, va="top")


def _limits(ax, geo):
    m = 0.12 * geo.span
    ax.set_xlim(geo.lo[0] - m, geo.hi[0] + m)
    ax.set_ylim(geo.lo[1] - 1.6 * m, geo.hi[1] + m)
    ax.set_aspect("equal", adjustable="box")


def _qtext(qs, v, i, lang):
    """The coordinates of position ``i`` (``qs``: coordinate → values [m or rad]) in the
    report's units."""
    parts = []
    for c, q in qs.items():
        val = float(v.degrees(np.degrees(q[i]))) if v.is_angle(c) else q[i]
        parts.append(f"{c} = {v.text(val, v.coord_unit(c), lang)}")
    return ", ".join(parts)


def draw(analysis, positions=None, lang="en", design=None, labels=True, width=7.0,
         height=5.5, units=None):
    """A drawing of the mechanism at some of the analysis' positions.

    Parameters
    ----------
    analysis : Analysis
    positions : sequence of int, optional
        Indices of the positions; the first is drawn in colour with labels, the
        others as light outlines. Default: the first and the last position.
    lang : {"en", "ru"}
    design : int, optional
        Design of a batch.
    labels : bool
        Label points and links.
    units : str or DisplayUnits, optional
        Display units of the axes and the coordinates (:mod:`assur.core.display`);
        default: the model file's.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> from assur import examples
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> from assur.views.report.drawing import draw
    >>> ax = draw(a).axes[0]  # the first (S = 0.42 m) and the last position
    >>> print(ax.get_title())
    Mini-tractor mounted-implement hitch (seed 003)
    S = 0.42 m; S = 0.67 m
    >>> [text.get_text() for text in ax.texts][:10]  # links, then frame pivots
    ['2', '3', '4', '5', '6', '7', '01', '03', '05', '07']
    >>> draw(a, positions=[4], lang="ru").axes[0].get_title().splitlines()[1]  # S [м]
    'S = 0,5311 м'
    >>> draw(a, positions=[10])
    Traceback (most recent call last):
    ...
    ValueError: positions must be in 0…9, got 10
    """
    check_lang(lang)
    v = _View(analysis, design, units=units)
    geo = _Geometry(v)
    if positions is None:
        positions = sorted({0, geo.n - 1})
    positions = [int(i) for i in positions]
    for i in positions:
        if not -geo.n <= i < geo.n:
            raise ValueError(f"positions must be in 0…{geo.n - 1}, got {i}")
    fig = new_figure(width, height)
    ax = fig.add_subplot()
    for i in positions[1:]:
        _pose(ax, geo, i, ghost=True)
    _pose(ax, geo, positions[0], labels=labels)
    _limits(ax, geo)
    ax.set_xlabel(f"{t('x_m', lang)} [{unit(v.units['length'].text, lang)}]")
    ax.set_ylabel(f"{t('y_m', lang)} [{unit(v.units['length'].text, lang)}]")
    ax.grid(True, alpha=0.3)
    shown = "; ".join(_qtext(geo.q, v, i, lang) for i in positions)
    ax.set_title(f"{localize(v.mech.title, lang)}\n{shown}", fontsize=10)
    return fig


def _animation_kinematics(v, frames):
    """The solve on a finer grid of the coordinate (one coordinate, one design), else the
    analysis' own positions."""
    if frames and v.k == 1 and len(v.kin.shape) == 1:
        q = v.kin.q()
        from ...errors import AssemblyError
        c = v.coords[0]
        lo, hi = q[0], q[-1]
        if v.is_angle(c) and float(np.ptp(q)) > np.pi:
            # a crank over more than half a turn: animate one whole turn from the first
            # position, in its direction of rotation (else the way the positions go)
            mo = v.mech.motion(c)
            sense = mo.direction if mo is not None else (1 if q[-1] >= q[0] else -1)
            hi = lo + sense * 2.0 * np.pi
        try:
            return v.mech.solve(np.linspace(lo, hi, int(frames)))
        except AssemblyError:
            # the finer grid crosses a position the user's own range does not: animate the
            # analysed positions only (the report's warnings already name any failure)
            pass
    return v.kin


def _shown(n, frames):
    """The positions drawn as frames: every one (``frames <= 0`` or no more than
    ``frames``), else ``frames`` of them evenly spaced."""
    if frames <= 0 or n <= frames:
        return list(range(n))
    return np.unique(np.linspace(0, n - 1, int(frames)).round().astype(int)).tolist()


def animation(analysis, frames=30, lang="en", design=None, units=None) -> dict:
    """The animation over the range as vector frames for the HTML report's player: no
    raster, no matplotlib (the positions are those of :func:`render_frames`).

    Returns
    -------
    dict
        ``{"svg": "<svg …>", "captions": [str per frame]}`` — the frames as one SVG
        element (:func:`assur.views.svg.frames`), each caption the coordinates of its
        frame in the report's units.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.drawing import animation
    >>> a = examples.hitch_003().analyze([0.42, 0.67])  # S [m]
    >>> anim = animation(a, frames=3)
    >>> anim["svg"].count('<g class="frame"'), anim["captions"]
    (3, ['S = 0.42 m', 'S = 0.545 m', 'S = 0.67 m'])
    >>> animation(a, frames=3, lang="ru")["captions"][1]
    'S = 0,545 м'
    """
    from ..geometry import geometry
    from ..svg import frames as svg_frames

    check_lang(lang)
    v = _View(analysis, design, units=units)
    kin = _animation_kinematics(v, frames)
    geo = geometry(kin, design=v.design if len(kin.shape) == 2 else None)
    q = {c: np.asarray(vals) for c, vals in geo["q"].items()}
    shown = _shown(geo["n"], frames)
    return {"svg": svg_frames(geo, shown),
            "captions": [_qtext(q, v, i, lang) for i in shown]}


_PLAYER = """<figure id="animation">{svg}
<figcaption>{title}: <span id="anim-q">{first}</span></figcaption>
<div class="player"><button type="button" id="anim-play">{play}</button>
<input type="range" id="anim-pos" min="0" max="{last}" value="0" aria-label="{position}"></div>
</figure>
<script>
(function () {{
  var frames = document.querySelectorAll("#anim-svg > g.frame");
  var captions = {captions};
  var pos = document.getElementById("anim-pos"), cap = document.getElementById("anim-q");
  var i = 0, dir = 1, bounce = {bounce}, timer = null;
  function show(k) {{
    frames[i].setAttribute("display", "none"); frames[k].removeAttribute("display");
    i = k; pos.value = k; cap.textContent = captions[k];
  }}
  function step() {{
    var n = i + dir;
    if (n < 0 || n >= frames.length) {{
      if (bounce) {{ dir = -dir; n = i + dir; }} else {{ n = 0; }}
    }}
    show(n);
  }}
  function toggle() {{ if (timer) {{ clearInterval(timer); timer = null; }} else if (frames.length > 1) {{ timer = setInterval(step, {interval}); }} }}
  document.getElementById("anim-play").addEventListener("click", toggle);
  pos.addEventListener("input", function () {{ if (timer) toggle(); show(+pos.value); }});
  toggle();
}})();
</script>"""


def player(anim, lang="en", interval=120, bounce=True, title=None) -> str:
    """The HTML of the animation's player: the frames of :func:`animation`, a caption
    with the shown frame's position, a play/pause button and a slider, and the inline
    script that plays them (forward and back with ``bounce``, else from the start
    again), one frame every ``interval`` ms. User text is escaped.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.drawing import animation, player
    >>> html = player(animation(examples.hitch_003().analyze([0.42, 0.67]), frames=3))
    >>> html.count('<g class="frame"'), 'id="anim-q">S = 0.42 m<' in html
    (3, True)
    """
    import html as _html
    import json

    esc = _html.escape
    captions = json.dumps(list(anim["captions"]), ensure_ascii=True).replace("</", "<\\/")
    return _PLAYER.format(
        svg=anim["svg"], title=esc(title or t("animation", lang)),
        first=esc(anim["captions"][0]), play=esc(t("play", lang)),
        last=len(anim["captions"]) - 1, position=esc(t("position", lang)),
        captions=captions, bounce="true" if bounce else "false", interval=int(interval))


def render_frames(analysis, frames=30, lang="en", design=None, dpi=80, width=6.4, height=5.0,
                  units=None):
    """Frames of the animation over the range, as PIL images (``width`` × ``height``
    in at ``dpi``).

    The mechanism is solved again on ``frames`` evenly spaced values of its
    coordinate (one coordinate and one design; otherwise at most ``frames`` of the
    analysis' positions, evenly spaced among them, are drawn; ``frames=0``: every
    one of the analysis' positions, e.g. the instants of a simulation), on one fixed
    view, drawn with Pillow (:mod:`assur.views.raster`: the picture of the HTML
    report's player) under the machine's title and the frame's coordinates.

    Returns
    -------
    list of PIL.Image.Image

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.drawing import render_frames
    >>> a = examples.hitch_003().analyze([0.42, 0.67])  # S [m]
    >>> frames = render_frames(a, frames=2, dpi=40)  # 6.4 × 5.0 in at 40 dpi
    >>> len(frames), frames[0].size, frames[0].mode
    (2, (256, 200), 'RGB')
    >>> frames[0].tobytes() != frames[1].tobytes()  # the hitch moved
    True
    """
    from ..geometry import geometry
    from ..raster import images

    check_lang(lang)
    v = _View(analysis, design, units=units)
    kin = _animation_kinematics(v, frames)
    geo = geometry(kin, design=v.design if len(kin.shape) == 2 else None)
    q = {c: np.asarray(vals) for c, vals in geo["q"].items()}
    shown = _shown(geo["n"], frames)
    return images(geo, shown, int(round(width * dpi)), int(round(height * dpi)),
                  [_qtext(q, v, i, lang) for i in shown], title=localize(v.mech.title, lang))


def _palette(frames):
    """The frames as palette images sharing one palette (no dithering): small GIF and
    PNG files, and a GIF that stores only what changes."""
    from PIL import Image
    picks = [frames[0], frames[len(frames) // 2], frames[-1]]
    w, h = picks[0].size
    sheet = Image.new("RGB", (w * len(picks), h))
    for k, f in enumerate(picks):
        sheet.paste(f.convert("RGB"), (k * w, 0))
    pal = sheet.quantize(colors=64, dither=Image.Dither.NONE)
    return [f.convert("RGB").quantize(palette=pal, dither=Image.Dither.NONE) for f in frames]


def write_gif(frames, path, duration=120, bounce=True) -> Path:
    """Write frames (PIL images) as an animated GIF that loops forever.

    Parameters
    ----------
    frames : list of PIL.Image.Image
    path : str or Path
    duration : int
        Time per frame [ms].
    bounce : bool
        Play forward then backward (the mechanism goes up and down).

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from PIL import Image
    >>> from assur.views.report.drawing import write_gif
    >>> frames = [Image.new("RGB", (64, 48), c) for c in ("white", "grey", "black")]
    >>> with tempfile.TemporaryDirectory() as d:
    ...     with Image.open(write_gif(frames, Path(d) / "m.gif")) as gif:
    ...         n, loop, ms = gif.n_frames, gif.info["loop"], gif.info["duration"]
    >>> n, loop, ms  # 3 forward, 1 back (the ends not repeated); loops forever; [ms]
    (4, 0, 120)
    >>> write_gif([], "m.gif")
    Traceback (most recent call last):
    ...
    ValueError: no frames to write
    """
    if not frames:
        raise ValueError("no frames to write")
    seq = _palette(list(frames))
    seq = seq + (seq[-2:0:-1] if bounce else [])
    path = Path(path)
    seq[0].save(path, format="GIF", save_all=True, append_images=seq[1:], duration=duration,
                loop=0)
    return path
