"""The seeds' diagrams against the generalized coordinate (matplotlib, Agg).

Each function takes an :class:`~assur.analysis.Analysis` and returns a
:class:`matplotlib.figure.Figure` drawn on an Agg canvas (no pyplot, no GUI, no
global state), with a title, axis labels with units and a legend in Russian or
English (``lang``):

==============  =====================================================  ===========
name            what                                                   seed 003
==============  =====================================================  ===========
``angles``      link angles φ [°]                                      tables 2.1
``distances``   named distances [m] (seed 002: l7, l9)                 —
``analogs``     angular-velocity analogs dφ/dq [rad/m]                 fig. 3.1
``transmission`` transmission numbers I = dY/dq [-]                    fig. 3.2
``capacity``    lift capacity G at the transmission points [kN], with  fig. 4.1
                the load there
``force``       cylinder force [kN] with the available force           fig. 4.2
``pressure``    cylinder pressure [MPa] with p_max                     fig. 4.3
``reactions``   magnitudes of the joint reactions [kN]                 fig. 5.4
``hodograph``   Ry against Rx of the largest frame reaction [kN]       —
``stability``   steered axle's share of the weight [%], 20 % line      fig. 6.2
==============  =====================================================  ===========

:func:`figures` makes those whose data exist; :func:`save` writes PNG or SVG.
For k > 1 coordinates the abscissa is the position number.

Over a crank angle the abscissa is the angle in the tables' convention
(continuous, or wrapped to [0°, 360°)); the positions are drawn sorted by it, so
that a list such as seed 002's (14.679°, then −30° steps, then 188.229°) is one
curve, and a curve of angles is broken where it wraps from 360° to 0° instead of
drawing a line across the plot. A curve equal to one drawn before it (seed 002:
φ4 = φ3, the two arms of one lever) is drawn dashed with other markers and
labelled ``φ4 = φ3``, so both stay visible.
"""

from __future__ import annotations

import numpy as np

from ._canvas import new_figure, save, to_png_bytes
from ._curves import _Plot
# the canvas and the curves' helpers, importable from here as before the split
from ._canvas import titled_axes
from ._curves import broken, path_abscissa, plot_order, wrap_breaks
from ...texts import localize
from .labels import check_lang, symbol, t, unit

__all__ = ["figures", "save", "to_png_bytes", "FIGURES", "angles", "distances", "analogs",
           "transmission",
           "capacity", "force", "pressure", "reactions", "hodograph", "stability"]


def angles(analysis, lang="en", design=None, units=None):
    """Link angles φ [°] against the coordinate (seed 003 table 2.1).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import angles
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = angles(a).axes[0]
    >>> ax.get_title(), ax.get_xlabel(), ax.get_ylabel()
    ('Link angles', 'cylinder length S [m]', 'angle φ [deg]')
    >>> len(ax.lines)  # links 2, 3, 34, 4, 5, 6, 7
    7
    >>> [round(float(y), 1) for y in ax.lines[2].get_ydata()[:2]]  # φ34 [deg], table 2.1
    [-18.2, -8.4]
    """
    p = _Plot(analysis, lang, design, units)
    kin = p.v.kin
    fig, ax = p.axes(t("f_angles", lang), t("y_angle", lang), "deg")
    for link in kin.links:
        p.line(ax, p.v.phi_values(link), symbol("φ", link), angle=True)
    p.legend(fig, ax, len(kin.links))
    return p.done(fig, ax)


#: titles of the figures kept here (the lead may move them into :mod:`.labels`)
_TITLES = {"f_distances": {"en": "Named distances", "ru": "Расстояния между точками"},
           "y_distance": {"en": "distance", "ru": "расстояние"},
           "along": {"en": "along the rotation", "ru": "по вращению"}}


def distances(analysis, lang="en", design=None, units=None):
    """Named distances [m] against the coordinate (seed 002: the helper vectors l7 =
    |C–O6|, l9 = |A–O3|); None without named distances.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import distances
    >>> a = examples.combine_002().analyze(examples.combine_002_range())  # seed 002
    >>> ax = distances(a).axes[0]
    >>> [line.get_label() for line in ax.lines], ax.get_ylabel()
    (['l9', 'l7'], 'distance [m]')
    >>> hitch = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> distances(hitch) is None  # the hitch names no distances
    True
    """
    p = _Plot(analysis, lang, design, units)
    v = p.v
    if not v.mech.distances:
        return None
    fig, ax = p.axes(_TITLES["f_distances"][p.lang], _TITLES["y_distance"][p.lang], "m")
    for dist in v.mech.distances:
        p.line(ax, v.pick(v.kin.length(dist.name)), dist.name)
    p.legend(fig, ax, len(v.mech.distances))
    return p.done(fig, ax)


def analogs(analysis, lang="en", design=None, units=None):
    """Angular-velocity analogs dφ/dq (seed 003 fig. 3.1 dφ3(S)).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import analogs
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = analogs(a).axes[0]
    >>> ax.get_ylabel()
    'analog dφ/dS [rad/m]'
    >>> [round(float(y), 3) for y in ax.lines[1].get_ydata()[:3]]  # dφ3 [rad/m], table 3.1
    [6.719, 5.743, 5.294]
    >>> ax.lines[2].get_linestyle()  # dφ34 = dφ3 (one lever): drawn dashed over it
    '--'
    >>> round(float(ax.lines[2].get_ydata()[0]), 3)  # dφ34 at S = 0.420 m [rad/m]
    6.719
    """
    p = _Plot(analysis, lang, design, units)
    kin, v = p.v.kin, p.v
    ylabel = t("y_analog", lang, p.c)
    if v.rate_sign(p.c) != 1:  # the seeds' convention: along the crank's rotation
        ylabel += " · sign " + p.c + "' (" + _TITLES["along"][p.lang] + ")"
    fig, ax = p.axes(t("f_analogs", lang), ylabel, v.analog_unit(p.c))
    n = 0
    for sfx, w, c in v.wrts():
        for link in kin.links:  # along the crank's rotation where the tables say so
            if not v.moves_link(c, link):  # 0 along a coordinate that does not turn it
                continue
            lab = symbol("φ", link, prime=True) + (f" ({c})" if sfx else "")
            p.line(ax, v.rate_sign(c) * v.pick(kin.dphi(link, w)), lab)
            n += 1
    p.legend(fig, ax, n)
    return p.done(fig, ax)


def transmission(analysis, lang="en", design=None, units=None):
    """Transmission numbers I = dY/dq of the model's transmission points (seed 003
    fig. 3.2 I56, IS6); None without transmission points.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import transmission
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = transmission(a).axes[0]
    >>> ax.get_ylabel(), len(ax.lines)  # I56 and IS6
    ('transmission number I [-]', 2)
    >>> [round(float(y), 3) for y in ax.lines[1].get_ydata()[:3]]  # IS6 [-], table 3.1
    [4.713, 4.483, 4.419]
    """
    p = _Plot(analysis, lang, design, units)
    kin, v = p.v.kin, p.v
    pts = list(v.mech.tables.get("transmissions", ()))
    if not pts:
        return None
    fig, ax = p.axes(t("f_transmission", lang), t("y_transmission", lang),
                     v.transmission_unit(p.c))
    n = 0
    for sfx, w, c in v.wrts():
        for pt in pts:
            if not v.moves_point(c, pt):  # 0 along a coordinate that does not move it
                continue
            p.line(ax, v.rate_sign(c) * v.pick(kin.transmission(pt, wrt=w)),
                   symbol("I", pt) + (f" ({c})" if sfx else ""))
            n += 1
    p.legend(fig, ax, n)
    return p.done(fig, ax)


def capacity(analysis, lang="en", design=None, units=None):
    """Lift capacity G [kN] at the transmission points with the load acting there
    (seed 003 fig. 4.1); None without cylinders.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import capacity
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = capacity(a).axes[0]
    >>> [line.get_label() for line in ax.lines][1:]
    ['G S6', 'load P6 = 27.5 kN']
    >>> round(float(ax.lines[1].get_ydata()[-1]), 2)  # GS6 at S = 0.670 m [kN], table 4.1: 29.959
    29.96
    """
    from .tables import _capacity

    p = _Plot(analysis, lang, design, units)
    v = p.v
    if not v.a.cylinders:
        return None
    fig, ax = p.axes(t("f_capacity", lang), t("y_capacity", lang), "N")
    n = 0
    several = len(v.a.cylinders) > 1
    loads_drawn = set()
    for name, res in v.a.cylinders.items():
        for pt in v.transmission_points():
            if not v.moves_point(res.cylinder.coordinate, pt):  # undefined: not its chain
                continue
            g, _ = _capacity(v, res, pt)
            p.line(ax, g, symbol("G", pt) + (f" ({localize(name, lang)})" if several else ""))
            n += 1
            if pt in loads_drawn:
                continue
            loads_drawn.add(pt)
            for wname, P in v.weights_at(pt)[:1]:
                ax.axhline(p.y(ax, P), ls="--", lw=1, color="0.3",
                           label=t("load", lang, wname, v.text(P, "N", lang)))
                n += 1
    p.legend(fig, ax, n)
    return p.done(fig, ax)


def force(analysis, lang="en", design=None, units=None):
    """Cylinder force [kN] by virtual work with the available force F_max (seed 003
    fig. 4.2); None without cylinders.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import force
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = force(a).axes[0]
    >>> ax.get_ylabel(), ax.lines[1].get_label()  # F_max: the cylinder's available force
    ('force F [kN]', 'available Fₘₐₓ = 147.8 kN')
    >>> round(float(ax.lines[0].get_ydata()[0]), 1)  # Fgc at S = 0.420 m [kN], table 4.1: 129.614
    129.6
    """
    p = _Plot(analysis, lang, design, units)
    v = p.v
    if not v.a.cylinders:
        return None
    fig, ax = p.axes(t("f_force", lang), t("y_force", lang), "N")
    n = 0
    for name, res in v.a.cylinders.items():
        p.line(ax, v.pick(res.force), f"{symbol('F', res.cylinder.length)} ({localize(name, lang)})")
        fm = v.pick(res.force_max)  # over positions for a double-rod cylinder (side auto)
        fmax = float(fm[0])
        if np.ptp(fm) > 0:
            p.line(ax, fm, t("force_max", lang, v.text(float(np.max(fm)), "N", lang)))
        elif fmax > 0:
            ax.axhline(p.y(ax, fmax), ls="--", lw=1, color="C3",
                       label=t("force_max", lang, v.text(fmax, "N", lang)))
        n += 2
    p.legend(fig, ax, n)
    return p.done(fig, ax)


def pressure(analysis, lang="en", design=None, units=None):
    """Cylinder pressure [MPa] with the largest working pressure p_max (seed 003
    fig. 4.3); None without cylinders.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import pressure
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = pressure(a).axes[0]
    >>> ax.get_ylabel(), ax.lines[1].get_label()
    ('pressure p [MPa]', 'pₘₐₓ = 17.5 MPa')
    >>> round(float(max(ax.lines[0].get_ydata())), 2)  # largest Pgc [MPa], table 4.1: 16.064
    16.06
    """
    p = _Plot(analysis, lang, design, units)
    v = p.v
    if not v.a.cylinders:
        return None
    fig, ax = p.axes(t("f_pressure", lang), t("y_pressure", lang), "Pa")
    n = 0
    for name, res in v.a.cylinders.items():
        p.line(ax, v.pick(res.pressure),
               f"{symbol('p', res.cylinder.length)} ({localize(name, lang)})")
        pmax = v.scalar(res.p_max)
        if pmax > 0:
            ax.axhline(p.y(ax, pmax), ls="--", lw=1, color="C3",
                       label=t("p_max", lang, v.text(pmax, "Pa", lang)))
        n += 2
    p.legend(fig, ax, n)
    return p.done(fig, ax)


def _reactions(v):
    """[(name, i, j)] of every joint, seed names first (as table 5.1)."""
    st = v.a.statics
    named = {(i, j): name for name, (i, j) in st.named_reactions().items()}
    out, done = [], set()
    for (i, j), name in list(named.items()) + [((i, j), f"R{i}{j}") for _, i, j in st.joints]:
        if frozenset((i, j)) not in done:
            done.add(frozenset((i, j)))
            out.append((name, i, j))
    return out


def reactions(analysis, lang="en", design=None, units=None):
    """Magnitudes of the joint reactions [kN] (seed 003 fig. 5.4); None without loads.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import reactions
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = reactions(a).axes[0]
    >>> ax.get_ylabel(), len(ax.lines)  # one curve per joint
    ('reaction |R| [kN]', 9)
    >>> round(float(ax.lines[0].get_ydata()[0]), 2)  # R56 at S = 0.420 m [kN], table 5.1: 48.480
    48.48
    """
    p = _Plot(analysis, lang, design, units)
    v = p.v
    if not v.mech.loads:
        return None
    fig, ax = p.axes(t("f_reactions", lang) + _static(analysis, lang), t("y_reaction", lang),
                     "N", width=7.2)
    rs = _reactions(v)
    markers = "osv^Dx+<>pP*h"
    for k, (name, i, j) in enumerate(rs):
        # reactions equal in magnitude (a two-force link) overlap: distinct markers show it
        p.line(ax, v.pick(v.a.statics.reaction_magnitude(i, j)),
               symbol("R", name[1:] if name.startswith("R") else name),
               marker=markers[k % len(markers)], markersize=4, markerfacecolor="none")
    p.legend(fig, ax, len(rs))
    return p.done(fig, ax)


def hodograph(analysis, lang="en", design=None, units=None):
    """Hodograph of the largest frame reaction: its y against its x component [kN]
    (the force of the frame on the link) over the positions, equal scales, with the
    first and last positions marked and the direction of travel; None without
    loads.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import hodograph
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = hodograph(a).axes[0]
    >>> ax.get_title()  # the largest frame reaction: the cylinder's pivot 01
    'Hodograph of reaction R01 (0 → 2)'
    >>> [line.get_label() for line in ax.lines[1:]]
    ['start: S = 0.42 m', 'end: S = 0.67 m']
    >>> round(float(ax.lines[0].get_ydata()[0]), 2)  # R01y at S = 0.420 m [kN], table 5.1: 129.558
    129.56
    """
    p = _Plot(analysis, lang, design, units)
    v = p.v
    if not v.mech.loads:
        return None
    st = v.a.statics
    best = None
    for name, i, j in _reactions(v):
        if "0" not in (i, j):
            continue
        link = j if i == "0" else i
        r = st.reaction("0", link)
        rx = np.asarray(v.units.convert(v.pick(r[..., 0]), "N")[0], dtype=float)
        ry = np.asarray(v.units.convert(v.pick(r[..., 1]), "N")[0], dtype=float)
        peak = float(np.max(np.hypot(rx, ry)))
        if best is None or peak > best[0]:
            best = (peak, name, link, rx, ry)
    if best is None:
        return None
    _, name, link, rx, ry = best
    title = t("f_hodograph", lang, f"{name} (0 → {link})") + _static(analysis, lang)
    fig = new_figure(6.0, 5.0)
    ax = fig.add_subplot()
    ax.set_title(title)
    fu = unit(v.units["force"].text, lang)
    ax.set_xlabel(f"Rx [{fu}]")
    ax.set_ylabel(f"Ry [{fu}]")
    ax.grid(True, alpha=0.35)
    # over a grid of two coordinates the reaction sweeps an area: points, not a path
    ax.plot(rx, ry, "o" if p.is_map else "-o", ms=3, color="C0", zorder=2)
    c = v.coords[0]
    for k, key, style in ((0, "start", dict(marker="o", color="C2")),
                          (-1, "end", dict(marker="s", color="C3"))):
        if v.k == 1:
            qtxt = f"{c} = {v.text(v.coord_values(c)[k], v.coord_unit(c), lang)}"
        else:
            qtxt = v.at_text(range(len(rx))[k], lang)
        ax.plot(rx[k], ry[k], ls="none", ms=8, zorder=3, label=f"{t(key, lang)}: {qtxt}",
                **style)
    if len(rx) > 1 and not p.is_map:  # the direction of travel, at the middle of the curve
        m = (len(rx) - 1) // 2
        ax.annotate("", xy=(rx[m + 1], ry[m + 1]), xytext=(rx[m], ry[m]),
                    arrowprops=dict(arrowstyle="-|>", color="C0", lw=1.5), zorder=3)
    span = max(np.ptp(rx), np.ptp(ry), 1e-12)
    if np.hypot(np.mean(rx), np.mean(ry)) < 3 * span:  # the origin is near: show it
        ax.plot([0], [0], "k+", ms=10)
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize="small")
    return fig


def stability(analysis, lang="en", design=None, units=None):
    """Share of the total weight on the steered axle [%] with the rule's limit
    (seed 003 fig. 6.2); None without machine data.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import stability
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> ax = stability(a).axes[0]
    >>> [line.get_label() for line in ax.lines]
    ['steered axle A', 'limit 20 %']
    >>> [round(float(y), 1) for y in ax.lines[0].get_ydata()[:3]]  # dRa [%], table 6.1
    [23.8, 23.5, 23.5]
    """
    p = _Plot(analysis, lang, design, units)
    v = p.v
    st = v.a.stability
    if st is None:
        return None
    fig, ax = p.axes(t("f_stability", lang), t("y_share", lang), "%")
    p.line(ax, v.pick(st.steered_share), t("steered_axle", lang, st.steered), color="C0")
    lim = 100.0 * st.min_share
    ax.axhline(lim, ls="--", lw=1.2, color="C3", label=t("min_share", lang, lim))
    ax.axhspan(min(0.0, ax.get_ylim()[0]), lim, color="C3", alpha=0.08)
    top = max(float(np.max(v.pick(st.steered_share))), lim)
    ax.set_ylim(0, top * 1.25 + 1)
    ax.legend(fontsize="small")
    return p.done(fig, ax)


def _static(analysis, lang):
    """`` (without inertia)`` for the figures of the static reactions of a machine whose
    report also draws them with the inertia loads (crank dynamics), else nothing."""
    return t("without_inertia", lang) if getattr(analysis, "dynamics", None) is not None \
        else ""


#: name -> function, in the report's order
FIGURES = {"angles": angles, "distances": distances, "analogs": analogs, "transmission": transmission,
           "capacity": capacity, "force": force, "pressure": pressure, "reactions": reactions,
           "hodograph": hodograph, "stability": stability}


def figures(analysis, lang="en", design=None, names=None, units=None) -> dict:
    """Every diagram whose data exist, ``{name: Figure}`` in :data:`FIGURES` order (a
    diagram with nothing to draw for this machine is left out).

    Parameters
    ----------
    analysis : Analysis
    lang : {"en", "ru"}
    design : int, optional
        Design of a batch (required for a batch).
    names : iterable of str, optional
        A subset of :data:`FIGURES`.
    units : str or DisplayUnits, optional
        The display units of every axis and legend (:mod:`assur.core.display`);
        default: the model file's ``[display] units``, else ``"file"``.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import figures
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> print(*figures(a))  # the hitch names no distances
    angles analogs transmission capacity force pressure reactions hodograph stability
    >>> figs = figures(a, "ru", names=["force"])
    >>> figs["force"].axes[0].get_title()
    'Сила на ГЦ'
    >>> figures(a, names=["speed"])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: figure names must be among: ['angles', 'distances', ...]; got ['speed']
    """
    check_lang(lang)
    names = list(FIGURES) if names is None else list(names)
    bad = [n for n in names if n not in FIGURES]
    if bad:
        raise ValueError(f"figure names must be among: {list(FIGURES)}; got {bad}")
    out = {}
    for n in names:
        fig = FIGURES[n](analysis, lang, design, units)
        # a figure with nothing drawn on it (e.g. a capacity diagram of a machine with
        # no load to lift, link angles of a machine whose only link is a cylinder) is
        # not a figure of this machine
        if fig is not None and any(ax.has_data() for ax in fig.axes):
            out[n] = fig
    return out
