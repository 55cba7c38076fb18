"""Views of a tolerance analysis (:class:`assur.synthesis.tolerance.ToleranceResult`): tables
(per position and of each machine's worst value: nominal, Monte Carlo mean, σ and the
first-order σ, percentiles P1…P99), a histogram of the worst values, and an HTML
report; bilingual through :class:`assur.texts.Text`."""

from __future__ import annotations

import html as _html
from pathlib import Path

import numpy as np

from ...errors import ModelError
from ...texts import Text, localize
from ._canvas import new_figure, save, to_png_bytes
from .html import data_uri
from .labels import check_lang

__all__ = ["display_scale", "tolerance_tables", "tolerance_histogram", "tolerance_html",
           "write_tolerance"]

_T = {
    "title": Text("Tolerance analysis", ru="Анализ допусков"),
    "machines": Text("machines drawn", ru="разыграно машин"),
    "seed": Text("seed", ru="зерно генератора"),
    "fail": Text("share that does not assemble", ru="доля несобираемых"),
    "tols": Text("Tolerances", ru="Допуски"),
    "param": Text("parameter", ru="параметр"),
    "dist": Text("distribution", ru="распределение"),
    "pm": Text("±t", ru="±t"),
    "sigma": Text("σ", ru="σ"),
    "worst": Text("Worst value of each machine over the range",
                  ru="Худшее значение каждой машины по диапазону"),
    "output": Text("output", ru="выход"),
    "nominal": Text("nominal", ru="номинал"),
    "mean": Text("mean (MC)", ru="среднее (МК)"),
    "std": Text("σ (MC)", ru="σ (МК)"),
    "one": Text("one machine assembles: its values are shown, the spread σ (MC) needs two "
                "or more (—)", ru="собирается одна машина: показаны её значения, для "
                "разброса σ (МК) нужны две или больше (—)"),
    "lin": Text("σ (first order)", ru="σ (первый порядок)"),
    "reasons": Text("Machines that do not assemble", ru="Несобираемые машины"),
    "position": Text("Per position", ru="По положениям"),
    "count": Text("machines", ru="машин"),
    "min": Text("minimum over the range", ru="минимум по диапазону"),
    "max": Text("maximum over the range", ru="максимум по диапазону"),
}
_PCT = ("P1", "P5", "P50", "P95", "P99")
_SCALE = {"Pa": (1e6, "MPa"), "N": (1e3, "kN"), "m": (1e-3, "mm")}


def _l(key, lang):
    return localize(_T[key], lang)


def display_scale(r, o):
    """(SI per shown unit, the unit shown) of an output: MPa, kN, mm or SI.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
    >>> from assur.views.report.tolerance import display_scale
    >>> m = examples.hitch_003()
    >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
    >>> outputs = ["p(ГЦ)", "Y(56)", "G(ГЦ, S6)"]
    >>> r = monte_carlo(m, [0.45, 0.6], tol, outputs=outputs, samples=200, seed=1)  # S [m]
    >>> r.units  # SI inside
    {'p(ГЦ)': 'Pa', 'Y(56)': 'm', 'G(ГЦ, S6)': 'N'}
    >>> [display_scale(r, o) for o in r.outputs]  # [SI per unit shown], unit shown
    [(1000000.0, 'MPa'), (0.001, 'mm'), (1000.0, 'kN')]
    """
    u = r.units.get(o, "")
    k, shown = _SCALE.get(u, (1.0, u))
    return k, shown


def tolerance_tables(r, lang="en"):
    """``{"tolerance_worst": DataFrame, "tolerance_positions": DataFrame}`` in the
    units shown (MPa, kN, mm).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
    >>> from assur.views.report.tolerance import tolerance_tables
    >>> m = examples.hitch_003()
    >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
    >>> r = monte_carlo(m, [0.45, 0.6], tol, outputs=["p(ГЦ)"], samples=200, seed=1)  # S [m]
    >>> tabs = tolerance_tables(r)
    >>> worst = tabs["tolerance_worst"].iloc[0]
    >>> worst["output"], worst["unit"], round(float(worst["nominal"]), 3)  # [MPa]
    ('p(ГЦ) (maximum over the range)', 'MPa', 15.429)
    >>> round(float(worst["σ (MC)"]), 3)  # spread of the worst pressure [MPa]
    0.013
    >>> pos = tabs["tolerance_positions"]
    >>> pos["q"].tolist(), [round(float(x), 3) for x in pos["p(ГЦ) σ (first order) [MPa]"]]
    ([0.45, 0.6], [0.009, 0.013])
    """
    import pandas as pd
    lang = check_lang(lang)
    from ...synthesis.tolerance import worst_kind
    n_ok = int(r.assembled.sum())
    if n_ok == 0:
        raise ModelError(f"none of the {r.samples.shape[0]} machines drawn assembles: no "
                         f"distribution to report (machine {r.reasons[0][0]}: "
                         f"{r.reasons[0][2]})" if r.reasons else "no machine was drawn")
    rows = []
    for o in r.outputs:
        k, u = display_scale(r, o)
        j = r.outputs.index(o)
        how = worst_kind(o)
        nom = r.nominal[:, j].min() if how == "min" else r.nominal[:, j].max()
        w = r.worst(o)
        # σ of one machine is undefined: None (no number, which check_table lets pass),
        # an empty cell in the CSV and the workbook, "—" in the report (na_rep), a note
        row = {_l("output", lang): f"{o} ({_l(how, lang)})", "unit": u,
               _l("nominal", lang): nom / k, _l("mean", lang): w.mean() / k,
               _l("std", lang): w.std(ddof=1) / k if n_ok > 1 else None}
        row.update({p: v / k for p, v in zip(_PCT, r.worst_percentiles(o))})
        rows.append(row)
    worst = pd.DataFrame(rows)
    cols = {"q": r.q}
    for o in r.outputs:
        k, u = display_scale(r, o)
        j = r.outputs.index(o)
        cols[f"{o} {_l('nominal', lang)} [{u}]"] = r.nominal[:, j] / k
        cols[f"{o} {_l('std', lang)} [{u}]"] = (r.std(o) / k if n_ok > 1
                                                else np.full(len(r.q), None, dtype=object))
        cols[f"{o} {_l('lin', lang)} [{u}]"] = r.linear_sigma[:, j] / k
        for p, v in zip(_PCT, r.percentiles(o).T):
            cols[f"{o} {p} [{u}]"] = v / k
    return {"tolerance_worst": worst, "tolerance_positions": pd.DataFrame(cols)}


def tolerance_histogram(r, output, lang="en"):
    """Histogram of each machine's worst value of ``output`` over the range, with the
    nominal value and P5/P95 marked (a matplotlib Figure).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
    >>> from assur.views.report.tolerance import tolerance_histogram
    >>> m = examples.hitch_003()
    >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
    >>> r = monte_carlo(m, [0.45, 0.6], tol, outputs=["p(ГЦ)"], samples=200, seed=1)  # S [m]
    >>> ax = tolerance_histogram(r, "p(ГЦ)").axes[0]
    >>> ax.get_title(), ax.get_xlabel()
    ('p(ГЦ): maximum over the range', '[MPa]')
    >>> [line.get_label() for line in ax.lines]
    ['nominal', 'P5', 'P95']
    >>> round(float(ax.lines[0].get_xdata()[0]), 3)  # the nominal design's worst [MPa]
    15.429
    """
    lang = check_lang(lang)
    from ...synthesis.tolerance import worst_kind
    k, u = display_scale(r, output)
    w = r.worst(output) / k
    j = r.outputs.index(output)
    how = worst_kind(output)
    nom = (r.nominal[:, j].min() if how == "min" else r.nominal[:, j].max()) / k
    fig = new_figure()
    ax = fig.add_subplot()
    ax.hist(w, bins=min(60, max(10, w.size // 25)), color="#5b8cc0", alpha=0.85)
    ax.axvline(nom, color="k", lw=1.5, label=_l("nominal", lang))
    p5, p95 = np.percentile(w, [5, 95])
    ax.axvline(p5, color="#c05b5b", ls="--", label="P5")
    ax.axvline(p95, color="#c05b5b", ls=":", label="P95")
    ax.set_title(f"{output}: {_l(how, lang)}", fontsize=10)
    ax.set_xlabel(f"[{u}]")
    ax.set_ylabel(_l("count", lang))
    ax.grid(True, alpha=0.35)
    ax.legend(fontsize=8)
    return fig


def _table_html(df):
    # an undefined value (None: σ of one machine) is "—"
    return df.fillna("—").to_html(index=False, float_format=lambda x: f"{x:.5g}", border=0,
                                  classes="tab")


def tolerance_html(r, mech, lang="en", figures=None):
    """The HTML report of a tolerance analysis (a str).

    Examples
    --------
    >>> import re
    >>> from assur import examples
    >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
    >>> from assur.views.report.tolerance import tolerance_html
    >>> m = examples.hitch_003()
    >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
    >>> r = monte_carlo(m, [0.45, 0.6], tol, outputs=["p(ГЦ)"], samples=200, seed=1)  # S [m]
    >>> page = tolerance_html(r, m)
    >>> re.findall(r"<h2>(.*?)</h2>", page)
    ['Tolerances', 'Worst value of each machine over the range', 'Per position']
    >>> re.search(r"<p>(.*?)</p>", page).group(1)
    'machines drawn: 200; seed: 1; share that does not assemble: 0 %'
    """
    lang = check_lang(lang)
    tabs = tolerance_tables(r, lang)
    e = _html.escape
    title = localize(getattr(mech, "title", "") or mech.name, lang)
    parts = [f"<!DOCTYPE html><html lang='{lang}'><head><meta charset='utf-8'>"
             f"<title>{e(_l('title', lang))}: {e(title)}</title>"
             "<style>body{font-family:sans-serif;max-width:70em;margin:auto}"
             "table.tab{border-collapse:collapse}table.tab td,table.tab th"
             "{border:1px solid #ccc;padding:2px 6px;text-align:right}</style></head><body>",
             f"<h1>{e(_l('title', lang))}: {e(title)}</h1>",
             f"<p>{e(_l('machines', lang))}: {r.samples.shape[0]}; {e(_l('seed', lang))}: "
             f"{r.seed}; {e(_l('fail', lang))}: {100 * r.failure_share:.3g} %</p>",
             f"<p>{e(_l('one', lang))}</p>" if r.assembled.sum() == 1 else "",
             f"<h2>{e(_l('tols', lang))}</h2><table class='tab'><tr><th>"
             f"{e(_l('param', lang))}</th><th>{e(_l('dist', lang))}</th><th>"
             f"{e(_l('sigma', lang))} [SI]</th></tr>"]
    for t in r.tolerances:
        parts.append(f"<tr><td>{e(t.param)}</td><td>{e(t.dist)}</td><td>{t.sigma:.4g}</td></tr>")
    parts.append("</table>")
    parts.append(f"<h2>{e(_l('worst', lang))}</h2>{_table_html(tabs['tolerance_worst'])}")
    for o, fig in (figures or {}).items():
        parts.append(f"<figure><img alt='{e(o)}' src='{data_uri(to_png_bytes(fig))}'>"
                     "</figure>")
    parts.append(f"<h2>{e(_l('position', lang))}</h2>"
                 f"{_table_html(tabs['tolerance_positions'])}")
    if r.reasons:
        parts.append(f"<h2>{e(_l('reasons', lang))}</h2><ul>")
        parts += [f"<li>#{d}: {e(msg)}</li>" for d, _, msg in r.reasons]
        parts.append("</ul>")
    parts.append("</body></html>")
    return "\n".join(parts)


def write_tolerance(r, mech, out, lang="en", formats=("csv", "xlsx", "html", "png")):
    """Write the tables (CSV, XLSX), the histograms (PNG) and the HTML report into the
    directory ``out``; returns the paths written.

    Raises
    ------
    ModelError
        No machine assembles, or a value of a table is NaN or infinite
        (:func:`assur.core.inputs.check_table`): nothing is written.

    Examples
    --------
    >>> import tempfile
    >>> from assur import examples
    >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
    >>> from assur.views.report.tolerance import write_tolerance
    >>> m = examples.hitch_003()
    >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
    >>> r = monte_carlo(m, [0.45, 0.6], tol, outputs=["p(ГЦ)"], samples=200, seed=1)  # S [m]
    >>> with tempfile.TemporaryDirectory() as d:
    ...     files = write_tolerance(r, m, d, lang="ru", formats=("csv", "html"))
    ...     page = files[-1].read_text(encoding="utf-8")
    >>> [p.name for p in files]
    ['tolerance_worst.csv', 'tolerance_positions.csv', 'tolerance.html']
    >>> "Анализ допусков" in page
    True
    """
    from ...core.inputs import check_table
    tabs = tolerance_tables(r, lang)
    for name, df in tabs.items():  # no NaN or infinity in any file: checked first
        check_table(name, df)      # (σ of one machine: None, shown empty or "—")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    files = []
    if "csv" in formats:
        for name, df in tabs.items():
            p = out / f"{name}.csv"
            df.to_csv(p, index=False)
            files.append(p)
    if "xlsx" in formats:
        import pandas as pd
        p = out / "tolerance.xlsx"
        with pd.ExcelWriter(p, engine="openpyxl") as w:
            for name, df in tabs.items():
                df.to_excel(w, sheet_name=name[:31], index=False)
        files.append(p)
    figs = {}
    if r.assembled.any():
        figs = {o: tolerance_histogram(r, o, lang) for o in r.outputs}
    if "png" in formats:
        for i, (o, fig) in enumerate(figs.items()):
            files.append(save(fig, out / f"tolerance_hist_{i + 1}.png"))
    if "html" in formats:
        p = out / "tolerance.html"
        p.write_text(tolerance_html(r, mech, lang, figs), encoding="utf-8")
        files.append(p)
    return files
