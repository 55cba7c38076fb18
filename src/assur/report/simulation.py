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

Pressures are shown in MPa, lengths in m, as lab 6 prints them.
"""

from __future__ import annotations

import base64
import html
import io as _io
from pathlib import Path

import numpy as np

from .figures import new_figure, titled_axes
from .labels import check_lang, t, unit

__all__ = ["figures", "time_series", "summary", "write_simulation_report", "FIGURES"]

FIGURES = ("pressure", "pressure_rate", "coordinate", "speed", "acceleration", "reduced_mass")
MPA = 1e6


def figures(result, lang="en"):
    """``{name: Figure}`` of :data:`FIGURES` for a simulation result."""
    check_lang(lang)
    c = result.coordinate
    tx = f"{t('sim_time', lang)} [{unit('s', lang)}]"
    out = {}

    def fig(name, title, ylabel):
        f = new_figure()
        out[name] = f
        return titled_axes(f, title, tx, ylabel)

    ax = fig("pressure", t("sim_p", lang), f"p [{unit('MPa', lang)}]")
    ax.plot(result.t, result.p1 / MPA, label="p1")
    ax.plot(result.t, result.p2 / MPA, "--", label="p2")
    ax.legend()
    ax = fig("pressure_rate", t("sim_dp", lang), f"dp1/dt [{unit('MPa/s', lang)}]")
    ax.plot(result.t, result.p1dot / MPA)
    ax = fig("coordinate", t("sim_s", lang, c), f"{c} [{unit('m', lang)}]")
    ax.plot(result.t, result.q)
    ax = fig("speed", t("sim_v", lang, c), f"d{c}/dt [{unit('m/s', lang)}]")
    ax.plot(result.t, result.qdot, label=f"d{c}/dt")
    ax.axhline(result.steady_speed, color="k", lw=0.8, ls=":", label=t("sim_steady", lang))
    ax.legend()
    ax = fig("acceleration", t("sim_a", lang, c), f"d²{c}/dt² [{unit('m/s²', lang)}]")
    ax.plot(result.t, result.qddot)
    f = new_figure()
    ax = titled_axes(f, t("sim_m", lang, c), f"{c} [{unit('m', lang)}]", f"m [{unit('kg', lang)}]")
    order = np.argsort(result.q, kind="stable")
    ax.plot(result.q[order], result.reduced_mass[order], label="m")
    ax2 = ax.twinx()
    ax2.plot(result.q[order], result.reduced_mass_derivative[order], "--", color="C1",
             label="m'")
    ax2.set_ylabel(f"m' [{unit('kg/m', lang)}]")
    out["reduced_mass"] = f
    return out


def time_series(result):
    """The time series as a pandas DataFrame with units in the column names (t [s],
    S [m], dS/dt [m/s], d²S/dt² [m/s²], p1, p2 [MPa], dp1/dt [MPa/s], flows [l/min],
    force and load [kN], m [kg], m' [kg/m])."""
    import pandas as pd
    c = result.coordinate
    cols = {"t [s]": result.t, f"{c} [m]": result.q, f"d{c}/dt [m/s]": result.qdot,
            f"d2{c}/dt2 [m/s2]": result.qddot, "p1 [MPa]": result.p1 / MPA,
            "p2 [MPa]": result.p2 / MPA, "dp1/dt [MPa/s]": result.p1dot / MPA,
            "F [kN]": result.force / 1e3, "P_load [kN]": result.load / 1e3,
            "m [kg]": result.reduced_mass, "m' [kg/m]": result.reduced_mass_derivative,
            "phase": result.phase}
    cols.update({f"Q_{k} [l/min]": v * 60e3 for k, v in result.flows.items()})
    # + 0.0: never a -0.0 in a table
    return pd.DataFrame({k: v if k == "phase" else np.asarray(v, float) + 0.0
                         for k, v in cols.items()})


def summary(result, lang="en"):
    """Rows ``(label, value, unit)`` of the status, events and energy balance."""
    rows = [(t("sim_status", lang, result.message), "", ""),
            (t("sim_steady_line", lang, result.steady_speed, result.nfev), "", "")]
    for name, times in result.events.items():
        for x in times:
            rows.append((t(f"sim_ev_{name}", lang), f"{x:.4f}", unit("s", lang)))
    for key in ("pump", "relief", "line", "impact", "mechanism_kinetic", "line_kinetic",
                "loads", "oil", "residual"):
        rows.append((t(f"sim_en_{key}", lang), f"{result.energy[key]:.6g}", unit("J", lang)))
    return rows


def _png(fig):
    buf = _io.BytesIO()
    fig.savefig(buf, format="png", dpi=110)
    return buf.getvalue()


def write_simulation_report(result, outdir, title="", lang="en",
                            formats=("csv", "png", "html", "gif"), mechanism=None,
                            frame_step=0.1):
    """Write ``simulation.csv``, ``simulation_summary.csv``, the figures
    (``sim_<name>.png``), ``simulation.html`` (self-contained) and, given the
    ``mechanism``, ``simulation.gif``: its drawing at S(t) every ``frame_step``
    seconds, played in real time (:func:`assur.report.drawing.render_frames`).

    Returns
    -------
    list of Path
        The files written.
    """
    check_lang(lang)
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    files = []
    if "csv" in formats:
        p = out / "simulation.csv"
        time_series(result).to_csv(p, index=False)
        files.append(p)
        import pandas as pd
        p = out / "simulation_summary.csv"
        pd.DataFrame(summary(result, lang), columns=["item", "value", "unit"]).to_csv(
            p, index=False)
        files.append(p)
    figs = figures(result, lang) if ("png" in formats or "html" in formats) else {}
    pngs = {name: _png(f) for name, f in figs.items()}
    if "png" in formats:
        for name, data in pngs.items():
            p = out / f"sim_{name}.png"
            p.write_bytes(data)
            files.append(p)
    gif_uri = None
    if "gif" in formats and mechanism is not None:
        from .drawing import render_frames, write_gif
        ts = np.arange(0.0, result.t[-1] + 1e-9, frame_step)
        frames = render_frames(mechanism.analyze(np.interp(ts, result.t, result.q)), frames=0,
                               lang=lang)
        p = write_gif(frames, out / "simulation.gif", duration=int(round(frame_step * 1e3)),
                      bounce=False)
        files.append(p)
        gif_uri = "data:image/gif;base64," + base64.b64encode(p.read_bytes()).decode("ascii")
    if "html" in formats:
        esc = html.escape
        parts = [f"<!doctype html><html lang='{lang}'><head><meta charset='utf-8'>"
                 f"<title>{esc(title or t('sim_report', lang))}</title>"
                 "<style>body{font-family:sans-serif;max-width:60em;margin:auto}"
                 "td{padding:2px 8px}img{max-width:100%}</style></head><body>",
                 f"<h1>{esc(t('sim_report', lang))}</h1>",
                 f"<h2>{esc(title)}</h2>" if title else "", "<table>"]
        for label, value, u in summary(result, lang):
            parts.append(f"<tr><td>{esc(label)}</td><td>{esc(value)}</td><td>{esc(u)}</td></tr>")
        parts.append("</table>")
        if gif_uri:
            parts.append(f"<figure><img alt='motion' src='{gif_uri}'></figure>")
        for name, data in pngs.items():
            uri = "data:image/png;base64," + base64.b64encode(data).decode("ascii")
            parts.append(f"<figure><img alt='{esc(name)}' src='{uri}'></figure>")
        parts.append("</body></html>")
        p = out / "simulation.html"
        p.write_text("\n".join(parts), encoding="utf-8")
        files.append(p)
    return files
