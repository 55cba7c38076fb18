"""Diagrams of a crank mechanism's dynamics (matplotlib, Agg): views of
:class:`assur.dynamics.crank.CrankDynamics`, :class:`assur.dynamics.flywheel.Flywheel` and
:class:`assur.dynamics.balancing.Balancing` (seed 001 lab 3, figs. 3.3, 3.4).

=====================  ==========================================================
name                   what
=====================  ==========================================================
``centre_of_mass``     the common centre of mass over a turn [mm], before and
                       after balancing, with A_x, A_y and the area (fig. 3.3)
``hodographs``         reaction hodographs R_y against R_x [N] of the model's
                       named reactions (fig. 3.4: R34), with inertia
``reduced_moment``     reduced moment on the crank with and without inertia, and
                       the driving moment [N·m] against the crank angle [°]
``reduced_inertia``    J_red [kg·m²] and dJ_red/dφ against the crank angle [°]
``energy_mass``        Wittenbauer's energy–mass diagram ΔE(J_red) with the
                       tangents of ω_max, ω_min, and ω(φ) with the flywheel
=====================  ==========================================================

:func:`figures` makes all that apply in one call. Crank angles are shown in
degrees wrapped to [0°, 360°) and sorted, so no line crosses a wrap.
"""

from __future__ import annotations

import numpy as np

from ._canvas import figure_legend, new_figure, titled_axes
from .labels import check_lang, t, unit
from .numbers import number, quantity

__all__ = ["figures", "centre_of_mass", "hodographs", "reduced_moment", "reduced_inertia",
           "energy_mass", "DYNAMICS_FIGURES"]

def _t(key, lang, *args):
    return t(f"dyn_{key}", check_lang(lang), *args)


def _units(dynamics, units):
    """The :class:`assur.core.display.DisplayUnits` of the figures (default: the model
    file's)."""
    from ...core.display import unit_system
    return unit_system(dynamics.kinematics.mechanism, units)


def _sorted_degrees(q, *ys):
    """Crank angles wrapped to [0°, 360°) and sorted, with the ys in that order; a
    position that repeats an earlier one a turn later (a full turn's 360° after its 0°)
    is drawn once.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.views.report.dynamics import _sorted_degrees
    >>> x, y = _sorted_degrees(np.radians([0.0, 90.0, 180.0, 270.0, 360.0]), [1, 2, 3, 4, 1])
    >>> x.tolist(), y.tolist()
    ([0.0, 90.0, 180.0, 270.0], [1, 2, 3, 4])
    """
    deg = np.mod(np.degrees(np.ravel(q)), 360.0)
    deg = np.where(np.isclose(deg, 360.0, rtol=0.0, atol=1e-9), 0.0, deg)
    _, first = np.unique(np.round(deg, 9), return_index=True)  # sorted, each angle once
    keep = np.sort(first)
    deg = deg[keep]
    order = np.argsort(deg, kind="stable")
    return (deg[order],) + tuple(np.ravel(y)[keep][order] for y in ys)


def _turn(du, ax, x):
    """The abscissa of a turn: the wrapped angles [°] ``x`` in the display unit, the
    axis limited to one turn."""
    shown, _ = du.convert(x, "deg")
    ax.set_xlim(0, float(du.convert(360.0, "deg")[0]))
    return shown


def _xlabel(lang, du, coordinate="φ"):
    return f"{_t('angle', lang, coordinate)} [{unit(du['angle'].text, lang)}]"


def _axis(du, kind, lang):
    """``[unit]`` of ``kind`` in the display units, for an axis label."""
    return f"[{unit(du[kind].text, lang)}]"


def centre_of_mass(dynamics, lang="en", balancing=None, units=None):
    """The common centre of mass of the moving links over the turn, about its mean
    position [mm] (seed 001 lab 3 fig. 3.3), before and, with ``balancing``, after
    the counter-masses (the dot marks the first position).

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> from assur.views.report.dynamics import centre_of_mass
    >>> model = io.load(io.bundled("cleaning_lab3"))  # the ten-bar of seed 001 lab 3
    >>> kin = model.mechanism.solve(model.range)  # a turn of the crank, 1° steps
    >>> dyn = crank_dynamics(kin, qdot=-30.0)  # clockwise at 30 rad/s
    >>> ax = centre_of_mass(dyn).axes[0]
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('x − x̄ [mm]', 'y − ȳ [mm]')
    >>> print(ax.lines[0].get_label())  # amplitudes [mm], area [mm²], mean position [mm]
    without counter-masses: A_x = 3.951 mm, A_y = 3.742 mm, area 3.709 mm²
    about its mean (x̄, ȳ) = (889.8, 46.2) mm
    """
    lang = check_lang(lang)
    du = _units(dynamics, units)
    fig = new_figure(6.4, 5.0)
    ax = titled_axes(fig, _t("f_com", lang), f"x − x̄ {_axis(du, 'length', lang)}",
                     f"y − ȳ {_axis(du, 'length', lang)}")
    paths = [(dynamics.centre, _t("before", lang))]
    if balancing is not None:
        paths.append((balancing.after, _t("after", lang)))
    for c, label in paths:
        x, y = np.ravel(c.x), np.ravel(c.y)
        xm, ym = x.mean(), y.mean()
        x, y = du.value(x - xm, "length"), du.value(y - ym, "length")
        amp = _t("amp", lang, quantity(float(np.ravel(c.amplitude_x)[0]), "length", du, lang),
                 quantity(float(np.ravel(c.amplitude_y)[0]), "length", du, lang),
                 quantity(float(np.ravel(c.area)[0]), "area", du, lang))
        where = _t("mean", lang, number(du.value(xm, "length"), None, lang),
                   number(du.value(ym, "length"), None, lang), unit(du["length"].text, lang))
        ax.plot(np.append(x, x[0]), np.append(y, y[0]), lw=1.5,
                label=f"{label}: {amp}\n{where}")
        ax.plot(x[:1], y[:1], "o", color=ax.lines[-1].get_color(), ms=4)
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize="small")
    return fig


def hodographs(dynamics, lang="en", reactions=None, units=None):
    """Hodographs of joint reactions over the turn: R_y against R_x [N], with the
    inertia loads (seed 001 lab 3 fig. 3.4, R34).

    ``reactions``: ``{name: (i, j)}`` (the force of link i on link j); default the
    model's named reactions (``tables["reactions"]``), else every joint with the
    frame.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> from assur.views.report.dynamics import hodographs
    >>> model = io.load(io.bundled("cleaning_lab3"))  # the ten-bar of seed 001 lab 3
    >>> kin = model.mechanism.solve(model.range)  # a turn of the crank, 1° steps
    >>> dyn = crank_dynamics(kin, qdot=-30.0)  # clockwise at 30 rad/s
    >>> ax = hodographs(dyn).axes[0]
    >>> [line.get_label() for line in ax.lines[:-1:2]]  # the model's named reactions
    ['R34', 'R38', 'R89', 'R01', 'R03']
    >>> len(ax.lines[0].get_xdata())  # 361 positions, closed
    362
    >>> ax = hodographs(dyn, reactions={"R01": ("0", "1")}).axes[0]  # frame on crank 1
    >>> ax.lines[0].get_label(), ax.get_xlabel()
    ('R01', 'R_x [N]')
    """
    lang = check_lang(lang)
    if reactions is None:
        reactions = dynamics.statics.named_reactions() or {
            f"R{i}{j}": (i, j) for _, i, j in dynamics.joints if "0" in (i, j)}
    du = _units(dynamics, units)
    fig = new_figure(6.4, 5.0)
    ax = titled_axes(fig, _t("f_hodo", lang), f"{_t('force_x', lang)} {_axis(du, 'force', lang)}",
                     f"{_t('force_y', lang)} {_axis(du, 'force', lang)}")
    for name, (i, j) in reactions.items():
        r = du.value(np.asarray(dynamics.reaction(i, j)).reshape(-1, 2), "force")
        ax.plot(np.append(r[:, 0], r[0, 0]), np.append(r[:, 1], r[0, 1]), lw=1.3, label=name)
        ax.plot(r[:1, 0], r[:1, 1], "o", color=ax.lines[-1].get_color(), ms=4)
    ax.plot([0], [0], "+", color="0.2", ms=10)
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize="small")
    return fig


def reduced_moment(dynamics, lang="en", units=None):
    """Reduced moment of all loads (inertia included) and without inertia, and the
    driving moment from the reactions [N·m], against the crank angle [°].

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> from assur.views.report.dynamics import reduced_moment
    >>> model = io.load(io.bundled("cleaning_lab3"))  # the ten-bar of seed 001 lab 3
    >>> kin = model.mechanism.solve(model.range)  # a turn of the crank, 1° steps
    >>> dyn = crank_dynamics(kin, qdot=-30.0)  # clockwise at 30 rad/s
    >>> ax = reduced_moment(dyn).axes[0]
    >>> ax.get_xlabel(), ax.get_ylabel(), len(ax.lines)
    ('crank angle j1 [deg]', 'M [N·m]', 3)
    >>> round(float(np.max(ax.lines[0].get_ydata())), 1)  # largest M_red, inertia included [N·m]
    349.7
    """
    lang = check_lang(lang)
    du = _units(dynamics, units)
    fig = new_figure()
    ax = titled_axes(fig, _t("f_mred", lang), _xlabel(lang, du, dynamics.coordinate),
                     f"M {_axis(du, 'moment', lang)}")
    x, a, b, c = _sorted_degrees(dynamics.q, *(du.value(m, "moment") for m in (
        dynamics.reduced_moment, dynamics.reduced_moment_without_inertia,
        dynamics.driving_moment_from_reactions)))
    x = _turn(du, ax, x)
    ax.plot(x, a, label="M red: " + _t("m_all", lang))
    ax.plot(x, b, label="M red: " + _t("m_static", lang))
    ax.plot(x, c, "--", label="M d: " + _t("m_drive", lang))
    figure_legend(fig, "bottom", ncols=2, fontsize="small")
    return fig


def reduced_inertia(dynamics, lang="en", units=None):
    """J_red [kg·m²] and dJ_red/dφ [kg·m²/rad] against the crank angle [°].

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> from assur.views.report.dynamics import reduced_inertia
    >>> model = io.load(io.bundled("cleaning_lab3"))  # the ten-bar of seed 001 lab 3
    >>> kin = model.mechanism.solve(model.range)  # a turn of the crank, 1° steps
    >>> dyn = crank_dynamics(kin, qdot=-30.0)  # clockwise at 30 rad/s
    >>> fig = reduced_inertia(dyn)
    >>> len(fig.axes), fig.axes[0].get_title()  # J_red, and dJ_red/dφ on a twin axis
    (2, 'Reduced moment of inertia')
    >>> J = fig.axes[0].lines[0].get_ydata()
    >>> round(float(np.min(J)), 4), round(float(np.max(J)), 4)  # J_red over the turn [kg·m²]
    (0.0074, 0.7909)
    """
    lang = check_lang(lang)
    du = _units(dynamics, units)
    fig = new_figure()
    ax = titled_axes(fig, _t("f_jred", lang), _xlabel(lang, du, dynamics.coordinate),
                     f"J red {_axis(du, 'inertia', lang)}")
    x, J, dJ = _sorted_degrees(dynamics.q, du.value(dynamics.reduced_inertia, "inertia"),
                               du.value(dynamics.reduced_inertia_derivative,
                                        "inertia_per_angle"))
    x = _turn(du, ax, x)
    ax.plot(x, J, color="C0", label="J red")
    ax2 = ax.twinx()
    ax2.plot(x, dJ, color="C1", ls="--", label="dJ red/dφ")
    ax2.set_ylabel(f"dJ red/dφ {_axis(du, 'inertia_per_angle', lang)}")
    figure_legend(fig, "bottom", ncols=2, fontsize="small")
    return fig


def energy_mass(flywheel, lang="en", units=None):
    """Wittenbauer's energy–mass diagram: ΔE [J] against J_red [kg·m²], with the
    tangents of slopes ω_max²/2 and ω_min²/2 meeting at (−J_f, −T0); and the crank
    speed |ω| [rad/s] over the turn with that flywheel.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> from assur.views.report.dynamics import energy_mass
    >>> model = io.load(io.bundled("cleaning_lab3"))  # the ten-bar of seed 001 lab 3
    >>> kin = model.mechanism.solve(model.range)  # a turn of the crank, 1° steps
    >>> dyn = crank_dynamics(kin, qdot=-30.0)  # clockwise at 30 rad/s
    >>> fw = dyn.flywheel(0.05)  # coefficient of speed fluctuation δ = 0.05
    >>> fig = energy_mass(fw)
    >>> [ax.get_title() for ax in fig.axes]
    ['Energy–mass diagram and the flywheel', 'crank speed |ω|']
    >>> fig.axes[0].lines[-1].get_label()  # the flywheel's moment of inertia [kg·m²]
    'they meet at (−J_f, −T0): J_f = 7.569 kg·m², δ = 0.05'
    """
    lang = check_lang(lang)
    from ...core.display import unit_system
    du = unit_system(None, units)
    fig = new_figure(9.6, 4.2)
    ax, ax2 = fig.subplots(1, 2)
    J = du.value(np.ravel(flywheel.reduced_inertia), "inertia")
    E = du.value(np.ravel(flywheel.energy), "energy")
    ax.plot(J, E, lw=1.4, label="ΔE(J red)")
    # the tangents meet far away at (−J_f, −T0): drawn across the curve's own box
    x0, y0 = -du.value(flywheel.J_flywheel, "inertia"), -du.value(flywheel.T0, "energy")
    # the slope ω²/2 [J per kg·m²] in the units shown
    per = du.value(1.0, "energy") / du.value(1.0, "inertia")
    pad_x, pad_y = 0.08 * np.ptp(J), 0.15 * np.ptp(E)
    jx = np.array([J.min() - pad_x, J.max() + pad_x])
    for w in (flywheel.omega_max, flywheel.omega_min):
        ax.plot(jx, y0 + 0.5 * w ** 2 * per * (jx - x0), color="0.4", lw=0.8, ls="--")
    ax.set_xlim(*jx)
    ax.set_ylim(E.min() - pad_y, E.max() + pad_y)
    ax.plot([], [], color="0.4", lw=0.8, ls="--", label=_t("wit_tan", lang))
    ax.plot([], [], " ", label=_t("fw", lang, quantity(flywheel.J_flywheel, "inertia", du, lang),
                                  number(flywheel.delta, None, lang)))
    ax.set_title(_t("f_wit", lang))
    ax.set_xlabel(f"J red {_axis(du, 'inertia', lang)}")
    ax.set_ylabel(f"{_t('energy', lang)} {_axis(du, 'energy', lang)}")
    ax.grid(True, alpha=0.35)
    ax.legend(fontsize="small", loc="lower right")
    x, w = _sorted_degrees(flywheel.q, du.value(flywheel.omega, "angular_velocity"))
    ax2.plot(_turn(du, ax2, x), w, color="C2")
    for v in (flywheel.omega_max, flywheel.omega_min, flywheel.omega_mean):
        ax2.axhline(du.value(v, "angular_velocity"), color="0.5", lw=0.7, ls=":")
    ax2.set_title(_t("omega", lang))
    ax2.set_xlabel(_xlabel(lang, du))
    ax2.set_ylabel(f"|ω| {_axis(du, 'angular_velocity', lang)}")
    ax2.grid(True, alpha=0.35)
    return fig


#: the figures of :func:`figures`, in order
DYNAMICS_FIGURES = ("centre_of_mass", "hodographs", "reduced_moment", "reduced_inertia",
                    "energy_mass")


def figures(dynamics, lang="en", flywheel=None, balancing=None, units=None):
    """Every dynamics figure that applies, ``{name: Figure}`` (the energy–mass
    diagram only with a ``flywheel``; the balanced path only with ``balancing``).

    Parameters
    ----------
    dynamics : CrankDynamics
        :func:`assur.dynamics.crank.crank_dynamics` (one design).
    lang : {"en", "ru"}
    flywheel : Flywheel, optional
        :meth:`CrankDynamics.flywheel`.
    balancing : Balancing, optional
        :func:`assur.dynamics.balancing.balance`.
    units : str or DisplayUnits, optional
        The display units (:mod:`assur.core.display`); default: the model file's.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.crank import crank_dynamics
    >>> from assur.views.report.dynamics import figures
    >>> model = io.load(io.bundled("cleaning_lab3"))  # the ten-bar of seed 001 lab 3
    >>> kin = model.mechanism.solve(model.range)  # a turn of the crank, 1° steps
    >>> dyn = crank_dynamics(kin, qdot=-30.0)  # clockwise at 30 rad/s
    >>> list(figures(dyn))
    ['centre_of_mass', 'hodographs', 'reduced_moment', 'reduced_inertia']
    >>> figs = figures(dyn, "ru", flywheel=dyn.flywheel(0.05))  # δ = 0.05
    >>> list(figs)[-1], figs["reduced_moment"].axes[0].get_xlabel()
    ('energy_mass', 'угол кривошипа j1 [°]')
    """
    lang = check_lang(lang)
    if dynamics.kinematics.m != 1:
        raise ValueError(f"figures of one design at a time; this result holds "
                         f"{dynamics.kinematics.m}")
    du = _units(dynamics, units)
    out = {"centre_of_mass": centre_of_mass(dynamics, lang, balancing, du),
           "hodographs": hodographs(dynamics, lang, units=du),
           "reduced_moment": reduced_moment(dynamics, lang, du),
           "reduced_inertia": reduced_inertia(dynamics, lang, du)}
    if flywheel is not None:
        out["energy_mass"] = energy_mass(flywheel, lang, du)
    return out
