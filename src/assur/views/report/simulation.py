"""Views of a simulation in time (:class:`assur.dynamics.SimulationResult`): the
time series as CSV, the diagrams of seed 001 lab 6 (figs. 6.3–6.7) and a
self-contained HTML report.

=================  ===============================================================
figure             what
=================  ===============================================================
``pressure``       p1 at the pump and p2 at the cylinder [MPa] against t (fig. 6.3)
``pressure_rate``  dp1/dt [MPa/s] (fig. 6.4)
``coordinate``     S [m] (fig. 6.5)
``speed``          dS/dt [m/s] with the steady speed Q/A (fig. 6.6)
``acceleration``   d²S/dt² [m/s²] (fig. 6.7)
``reduced_mass``   m(S) [kg] and m'(S) [kg/m] over the stroke
=================  ===============================================================

Pressures are shown in MPa, lengths in m, as lab 6 prints them. With k > 1
coordinates (seed 004's crane) every figure has a curve per branch, the pressure
figure the pump's pressure too, and ``reduced_mass`` shows the diagonal of M(q(t)).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ...texts import Text, localize
from ._canvas import new_figure, titled_axes, to_png_bytes
from .labels import check_lang, formatted, t, unit
from .numbers import number

__all__ = ["figures", "time_series", "summary", "write_simulation_report", "check_frames",
           "FIGURES"]

FIGURES = ("pressure", "pressure_rate", "coordinate", "speed", "acceleration", "reduced_mass")


#: texts of the k-coordinate simulation (the lab-6 ones are in :mod:`.labels`)
_TEXT = {
    "divider": Text("lost in the flow divider", ru="потери в делителе потока"),
    "pump": Text("pump pressure p_p = max p1", ru="давление насоса p_p = max p1"),
    "mass": Text("Diagonal of the mass matrix M_jj", ru="Диагональ матрицы масс M_jj"),
    "steady": Text("steady rod speed s·Q/A of {0} = {1} {2}",
                   ru="установившаяся скорость штока s·Q/A {0} = {1} {2}"),
    "evals": Text("{0} evaluations of the right-hand side",
                  ru="{0} вычислений правой части"),
}


#: without display units: an SI unit → the lab's unit and its factor (lab 6 prints
#: pressures in MPa, forces in kN, flows in l/min)
_LAB = {"Pa": ("MPa", 1e-6), "Pa/s": ("MPa/s", 1e-6), "N": ("kN", 1e-3),
        "m³/s": ("l/min", 6e4)}


def _units(units, mechanism):
    """The display units (:mod:`assur.core.display`) of ``units`` for ``mechanism``, or
    None for none asked (the lab's units: m, MPa, kN, l/min)."""
    from ...core.display import unit_system
    if units is None and mechanism is None:
        return None
    return unit_system(mechanism, units)


def _in(du, values, text):
    """``values`` given in ``text`` (SI) shown in the display units ``du``: ``(values,
    unit)`` (:meth:`~assur.core.display.DisplayUnits.convert`: a rate ``Pa/s`` or a mass
    per length ``kg/m`` in the system's units of their parts); ``du`` None: in the
    lab's units (:data:`_LAB`)."""
    values = np.asarray(values, dtype=float)
    if du is None:
        shown, factor = _LAB.get(text, (text, 1.0))
        return values * factor, shown
    v, u = du.convert(values, text)
    return np.asarray(v, float), u


def _tx(key, lang, *args):
    s = localize(_TEXT[key], lang)
    return formatted(s, lang, *args) if args else s


def figures(result, lang="en", units=None, mechanism=None):
    """``{name: Figure}`` of :data:`FIGURES` for a simulation result (with k > 1
    coordinates every branch's curve, labelled by its coordinate).

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics import simulate
    >>> from assur.views.report.simulation import figures
    >>> model = io.load(io.bundled("adapter_lab6"))  # seed 001 lab 6
    >>> r = simulate(model.mechanism, model.drive, 1.0, t_eval=[0.0, 0.5, 1.0])  # t [s]
    >>> figs = figures(r)
    >>> print(*figs)
    pressure pressure_rate coordinate speed acceleration reduced_mass
    >>> [f.axes[0].get_ylabel() for f in figs.values()][:4]
    ['p [MPa]', 'dp1/dt [MPa/s]', 'S [m]', 'dS/dt [m/s]']
    >>> [line.get_label() for line in figs["speed"].axes[0].lines]
    ['dS/dt', 'Q/A (steady speed)']
    >>> round(float(figs["speed"].axes[0].lines[1].get_ydata()[0]), 4)  # Q/A [m/s], lab 6: 0.0704
    0.0704
    """
    check_lang(lang)
    du = _units(units, mechanism)
    cs = result.coordinates
    k = len(cs)
    tag = (lambda j: "") if k == 1 else (lambda j: f" ({cs[j]})")
    tt, tu = _in(du, result.t, "s")
    tx = f"{t('sim_time', lang)} [{unit(tu, lang)}]"
    pu = _in(du, 0.0, "Pa")[1]
    out = {}

    def col(a, j, text):
        return _in(du, result.column(a, j), text)[0]

    def fig(name, title, ylabel):
        f = new_figure()
        out[name] = f
        return titled_axes(f, title, tx, ylabel)

    ax = fig("pressure", t("sim_p", lang), f"p [{unit(pu, lang)}]")
    for j in range(k):
        ax.plot(tt, col(result.p1, j, "Pa"), label="p1" + tag(j))
        ax.plot(tt, col(result.p2, j, "Pa"), "--", label="p2" + tag(j))
    if k > 1:
        ax.plot(tt, _in(du, result.pump_pressure, "Pa")[0], ":", color="k", lw=0.8,
                label=_tx("pump", lang))
    ax.legend()
    ax = fig("pressure_rate", t("sim_dp", lang),
             f"dp1/dt [{unit(_in(du, 0.0, 'Pa/s')[1], lang)}]")
    for j in range(k):
        ax.plot(tt, col(result.p1dot, j, "Pa/s"), label="dp1/dt" + tag(j))
    if k > 1:
        ax.legend()
    names = ", ".join(cs)
    lu, vu, au = (_in(du, 0.0, x)[1] for x in ("m", "m/s", "m/s²"))
    ax = fig("coordinate", t("sim_s", lang, names), f"{names} [{unit(lu, lang)}]")
    for j, c in enumerate(cs):
        ax.plot(tt, col(result.q, j, "m"), label=c)
    if k > 1:
        ax.legend()
    ax = fig("speed", t("sim_v", lang, names), f"d{names}/dt [{unit(vu, lang)}]")
    steady = _in(du, np.atleast_1d(result.steady_speed), "m/s")[0]
    for j, c in enumerate(cs):
        ax.plot(tt, col(result.qdot, j, "m/s"), label=f"d{c}/dt")
        ax.axhline(steady[j], color=f"C{j}", lw=0.8, ls=":", label=t("sim_steady", lang)
                   + tag(j))
    ax.legend()
    ax = fig("acceleration", t("sim_a", lang, names), f"d²{names}/dt² [{unit(au, lang)}]")
    for j, c in enumerate(cs):
        ax.plot(tt, col(result.qddot, j, "m/s²"), label=f"d²{c}/dt²")
    if k > 1:
        ax.legend()
    f = new_figure()
    if k == 1:
        c = cs[0]
        mu, du_ = _in(du, 0.0, "kg")[1], _in(du, 0.0, "kg/m")[1]
        ax = titled_axes(f, t("sim_m", lang, c), f"{c} [{unit(lu, lang)}]",
                         f"m [{unit(mu, lang)}]")
        order = np.argsort(result.q, kind="stable")
        q = _in(du, result.q, "m")[0]
        ax.plot(q[order], _in(du, result.reduced_mass, "kg")[0][order], label="m")
        ax2 = ax.twinx()
        ax2.plot(q[order], _in(du, result.reduced_mass_derivative, "kg/m")[0][order], "--",
                 color="C1", label="m'")
        ax2.set_ylabel(f"m' [{unit(du_, lang)}]")
    else:
        mu = _in(du, 0.0, "kg")[1]
        ax = titled_axes(f, _tx("mass", lang), tx, f"M_jj [{unit(mu, lang)}]")
        for j, c in enumerate(cs):
            ax.plot(tt, col(result.reduced_mass, j, "kg"), label=f"M ({c}, {c})")
        ax.legend()
    out["reduced_mass"] = f
    return out


def time_series(result, units=None, mechanism=None):
    """The time series as a pandas DataFrame with units in the column names (t [s],
    S [m], dS/dt [m/s], d²S/dt² [m/s²], p1, p2 [MPa], dp1/dt [MPa/s], flows [l/min],
    force and load [kN], m [kg], m' [kg/m]); with k > 1 coordinates a branch's
    columns carry its coordinate (``p1 S2 [MPa]``), and the pump's pressure
    ``p_pump [MPa]`` is added.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics import simulate
    >>> from assur.views.report.simulation import time_series
    >>> model = io.load(io.bundled("adapter_lab6"))  # seed 001 lab 6
    >>> r = simulate(model.mechanism, model.drive, 1.0, t_eval=[0.0, 0.5, 1.0])  # t [s]
    >>> df = time_series(r)
    >>> list(df.columns[:5])
    ['t [s]', 'S [m]', 'dS/dt [m/s]', 'd2S/dt2 [m/s2]', 'p1 [MPa]']
    >>> [round(float(x), 3) for x in df["S [m]"]]  # the rod from its stop S = 0.55 m [m]
    [0.55, 0.582, 0.615]
    >>> [round(float(x), 2) for x in df["p1 [MPa]"]]  # pump pressure rising [MPa]
    [0.0, 3.07, 4.64]
    """
    import pandas as pd
    du = _units(units, mechanism)
    cs = result.coordinates
    k = len(cs)
    cols = {}

    def put(name, values, si):
        """A column of ``values`` [``si``] in the display units (or the lab's)."""
        v, u = _in(du, values, si)
        cols[f"{name} [{'m/s2' if du is None and u == 'm/s²' else u}]"] = v

    put("t", result.t, "s")
    for j, c in enumerate(cs):
        col = (lambda a: result.column(a, j))  # noqa: E731
        b = "" if k == 1 else f" {c}"
        put(c, col(result.q), "m")
        put(f"d{c}/dt", col(result.qdot), "m/s")
        put(f"d2{c}/dt2", col(result.qddot), "m/s²")
        put(f"p1{b}", col(result.p1), "Pa")
        put(f"p2{b}", col(result.p2), "Pa")
        put(f"dp1/dt{b}", col(result.p1dot), "Pa/s")
        put(f"F{b}", col(result.force), "N")
        put(f"P_load{b}", col(result.load), "N")
        put(f"m{b}", col(result.reduced_mass), "kg")
        put(f"m'{b}", col(result.reduced_mass_derivative), "kg/m")
        cols[f"phase{b}"] = col(result.phase)
        for n, v in result.flows.items():
            if n != "pump":
                put(f"Q_{n}{b}", col(v), "m³/s")
    put("Q_pump", result.flows["pump"], "m³/s")
    if k > 1:
        put("p_pump", result.pump_pressure, "Pa")
    # + 0.0: never a -0.0 in a table
    return pd.DataFrame({n: v if n.startswith("phase") else np.asarray(v, float) + 0.0
                         for n, v in cols.items()})


def summary(result, lang="en", units=None, mechanism=None):
    """Rows ``(label, value, unit)`` of the status, events and energy balance.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics import simulate
    >>> from assur.views.report.simulation import summary
    >>> model = io.load(io.bundled("adapter_lab6"))  # seed 001 lab 6
    >>> r = simulate(model.mechanism, model.drive, 1.0, t_eval=[0.0, 0.5, 1.0])  # t [s]
    >>> rows = summary(r)
    >>> rows[0]
    ('status: reached t_end', '', '')
    >>> rows[2]  # the rod leaves its stop [s]
    ('lift-off from the stop', '0.0828', 's')
    >>> [row[0] for row in rows][3:5]  # then the energy balance [J]
    ['work of the pump', 'lost in the relief valve']
    >>> summary(r, "ru")[0]
    ('результат: расчёт доведён до t_end', '', '')
    """
    # a run that reached its end says so in the report's language; any other message
    # (a stop, a solver failure) is the engine's own text
    du = _units(units, mechanism)
    done = result.status == 0 and result.message == "reached t_end"
    rows = [(t("sim_status", lang, t("sim_reached", lang) if done else result.message),
             "", "")]
    steady, vu = _in(du, np.atleast_1d(result.steady_speed), "m/s")
    times, tu = _in(du, 1.0, "s")
    tu = unit(tu, lang)
    if len(result.coordinates) == 1:
        rows.append((t("sim_steady_line", lang, number(float(steady[0]), None, lang),
                       result.nfev, unit(vu, lang)), "", ""))
        for name, ts in result.events.items():
            for x in ts:
                rows.append((t(f"sim_ev_{name}", lang), number(x * times, 4, lang), tu))
    else:
        for c, v in zip(result.coordinates, steady):
            rows.append((_tx("steady", lang, c, number(float(v), None, lang), unit(vu, lang)),
                         "", ""))
        rows.append((_tx("evals", lang, result.nfev), "", ""))
        for x, name, c in result.event_log:
            rows.append((f"{t(f'sim_ev_{name}', lang)} ({c})", number(x * times, 4, lang), tu))
    keys = ["pump", "relief", "line", "impact", "mechanism_kinetic", "line_kinetic", "loads",
            "oil", "residual"]
    if len(result.coordinates) > 1:
        keys.insert(2, "divider")
    for key in keys:
        label = _tx(key, lang) if key == "divider" else t(f"sim_en_{key}", lang)
        energy, eu = _in(du, result.energy[key], "J")
        rows.append((label, number(float(energy), None, lang, 6), unit(eu, lang)))
    return rows


#: memory one animation frame takes [bytes]: the GIF's RGB and palette images
#: (6.4 × 5.0 in at 80 dpi), the HTML player's vector frame, the frame's time,
#: coordinates and caption
FRAME_BYTES = 512 * 400 * 4 + 16384


def check_frames(duration, frame_step=0.1, mechanism=None,
                 formats=("csv", "png", "html", "gif")) -> None:
    """Refuse an animation of a simulation of ``duration`` seconds, one frame every
    ``frame_step`` seconds, that would need more than
    :func:`assur.core.inputs.max_memory` (every frame is held until the GIF and the
    HTML player are written), before anything is allocated or written; nothing to
    check without a mechanism or without ``gif`` and ``html`` among the ``formats``.

    Raises
    ------
    ModelError
        Naming ``[simulation] duration`` (``--duration``), the estimate and the limit.

    Examples
    --------
    >>> import os
    >>> from unittest import mock
    >>> from assur import io
    >>> from assur.views.report.simulation import check_frames
    >>> model = io.load(io.bundled("adapter_lab6"))  # seed 001 lab 6
    >>> check_frames(4.5, mechanism=model.mechanism)  # 46 frames: fine
    >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "2 GiB"}):
    ...     check_frames(365.25 * 86400, mechanism=model.mechanism)  # a year [s]
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: the animation of 3.156e+07 s, a frame every 0.1 s: 3.156e+08 frames would need about 240 TiB of memory (limit 2 GiB; set ASSUR_MAX_MEMORY to change it, or reduce [simulation] duration (or --duration))
    """
    from ...core.inputs import bytes_per_position, check_memory
    if mechanism is None or not {"gif", "html"} & set(formats):
        return
    frames = math.floor(float(duration) / frame_step + 1e-9) + 1
    check_memory(frames, FRAME_BYTES + bytes_per_position(mechanism),
                 f"the animation of {float(duration):.4g} s, a frame every {frame_step:g} s",
                 unit="frames", reduce="[simulation] duration (or --duration)")


def write_simulation_report(result, outdir, title="", lang="en",
                            formats=("csv", "png", "html", "gif"), mechanism=None,
                            frame_step=0.1, model=None, units=None):
    """Write ``simulation.csv``, ``simulation_summary.csv``, the figures
    (``simulation_<name>.png``), ``simulation.html`` (self-contained, the look of the
    analysis report: :mod:`assur.views.report.document`) and, given the
    ``mechanism`` (or the ``model``: its mechanism, title, file and drive among the
    inputs), its drawing at q(t) every ``frame_step`` seconds played in real
    time: as vector frames in the HTML (:func:`assur.views.report.drawing.player`) and
    as ``simulation.gif`` (:func:`assur.views.report.drawing.render_frames`).

    ``units`` (a system of :data:`assur.core.display.SYSTEMS`) shows every value in
    those display units; default, given a mechanism: its file's (``[display] units``,
    else the units the file writes); without one, the lab's (m, MPa, kN, l/min).

    Returns
    -------
    list of Path
        The files written.

    Raises
    ------
    ModelError
        A value of the time series or of the energy balance is NaN or infinite
        (:func:`assur.core.inputs.check_table`): nothing is written.

    Examples
    --------
    >>> import tempfile
    >>> import pandas as pd
    >>> from assur import io
    >>> from assur.dynamics import simulate
    >>> from assur.views.report.simulation import write_simulation_report
    >>> model = io.load(io.bundled("adapter_lab6"))  # seed 001 lab 6
    >>> r = simulate(model.mechanism, model.drive, 1.0, t_eval=[0.0, 0.5, 1.0])  # t [s]
    >>> with tempfile.TemporaryDirectory() as d:
    ...     files = write_simulation_report(r, d, formats=("csv",))
    ...     items = pd.read_csv(files[1])["item"].tolist()
    ...     n = len(pd.read_csv(files[0]))
    >>> [p.name for p in files], n  # the time series: one row per time of t_eval
    (['simulation.csv', 'simulation_summary.csv'], 3)
    >>> items[2]
    'lift-off from the stop'
    """
    check_lang(lang)
    if model is not None:
        mechanism = model.mechanism if mechanism is None else mechanism
        title = title or localize(model.mechanism.title, lang)
    if len(result.t):  # the frames must fit in memory: refused before anything is written
        check_frames(float(result.t[-1]), frame_step, mechanism, formats)
    # every format shows these values: a NaN or an infinity is refused before any file
    # (the time series' every column, the energy balance), naming column and time
    from ...core.inputs import check_table
    series = time_series(result, units, mechanism)
    check_table("simulation.csv", series)
    check_table("simulation_summary.csv (energy balance) [J]",
                {k: [v] for k, v in result.energy.items()}, key="")
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    files = []
    if "csv" in formats:
        # the analysis' CSV dialect: in Russian ";" and the decimal comma (UTF-8, BOM)
        import pandas as pd

        from .tables import write_frame_csv
        files.append(write_frame_csv(series, out / "simulation.csv", lang))
        files.append(write_frame_csv(pd.DataFrame(summary(result, lang, units, mechanism),
                                                  columns=["item", "value", "unit"]),
                                     out / "simulation_summary.csv", lang))
    figs = figures(result, lang, units, mechanism) if {"png", "html"} & set(formats) else {}
    pngs = {name: to_png_bytes(f) for name, f in figs.items()}
    if "png" in formats:
        for name, data in pngs.items():
            p = out / f"simulation_{name}.png"
            p.write_bytes(data)
            files.append(p)
    motion = None
    if mechanism is not None and ("gif" in formats or "html" in formats):
        ts = np.arange(0.0, result.t[-1] + 1e-9, frame_step)
        q = np.asarray(result.q)
        qf = np.interp(ts, result.t, q) if q.ndim == 1 else np.column_stack(
            [np.interp(ts, result.t, q[:, j]) for j in range(q.shape[1])])
        motion = mechanism.analyze(qf)
    if "gif" in formats and motion is not None:
        from .drawing import render_frames, write_gif
        frames = render_frames(motion, frames=0, lang=lang, units=units)
        p = write_gif(frames, out / "simulation.gif", duration=int(round(frame_step * 1e3)),
                      bounce=False)
        files.append(p)
    player_html = None
    if "html" in formats and motion is not None:
        # the mechanism at q(t) every frame_step, played in real time as vector frames
        from .drawing import animation, player
        anim = animation(motion, frames=0, lang=lang, units=units)
        anim["captions"] = [f"t = {number(tk, None, lang, 3)} {unit('s', lang)}; {c}"
                            for tk, c in zip(ts, anim["captions"])]
        player_html = player(anim, lang, interval=frame_step * 1e3, bounce=False,
                             title=t("sim_motion", lang))
    if "html" in formats:
        p = out / "simulation.html"
        captioned = {name: (data, figs[name].axes[0].get_title()) for name, data in pngs.items()}
        p.write_text(_document(result, title, lang, captioned, player_html, model, mechanism,
                               units), encoding="utf-8")
        files.append(p)
    return files


def _document(result, title, lang, figures, player_html, model, mechanism, units=None):
    """The simulation report as a document (:mod:`assur.views.report.document`): the
    model's inputs and its drive, the run's status as the verdict, the events and the
    energy balance, the numbered figures and the motion."""
    from .document import drive_rows, model_rows, render_document
    source = model.source.name if model is not None and model.source else None
    inputs = []
    if mechanism is not None:
        inputs += model_rows(mechanism, lang, units, source=source)
        if model is not None and model.drive is not None:
            inputs.append(drive_rows(model.drive, lang, units, mechanism))
    rows = summary(result, lang, units, mechanism)
    verdict = {"status": "ok" if result.status == 0 else "fail", "text": rows[0][0],
               "href": "results"}
    sections = [{"anchor": "results", "title": t("sim_results", lang),
                 "header": (t("quantity", lang), t("value", lang), t("unit", lang)),
                 "rows": rows[1:], "notes": []}]
    notes = [localize(n, lang) for n in mechanism.notes] if mechanism is not None else []
    return render_document(
        lang=lang, title=title or t("sim_report", lang), kind=t("sim_report", lang),
        name=mechanism.name if mechanism is not None else "", source=source, inputs=inputs,
        verdicts=[verdict], sections=sections, figures=figures, player=player_html,
        notes=notes)
