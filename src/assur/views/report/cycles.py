"""Seed 004's work-cycle sweep (:func:`assur.dynamics.cycles.sweep`) as tables,
figures and a self-contained HTML report that sets the model against the paper's
conclusions (``assur cycles``).

The paper (004_4ff0af19c30e8a3a.txt, after eq. 68 and its conclusions) states:

1. at T_c = 6 s separate motion needs max forces about 90 % (boom) and 30 %
   (stick) higher than combined motion;
2. with combined motion the dynamic components fall 3–8 times "depending on the
   cycle time";
3. combined motion is most effective for cycles under 11 s;
4. (its conclusion 3) with the standard pump (Q_h = 80 l/min) and a flow divider the
   max cylinder forces fall 1.16–2.00 times for the various manipulators, and their
   dynamic components 4 times.

Each becomes a :class:`Verdict` computed from the sweep's numbers
(:func:`conclusions`): *agrees* or *does not agree*, with the model's figures and
why. The criteria, stated in the report too: "about x %" holds within ±25 % of x
(:data:`ABOUT`); "3–8 times" holds when every ratio of the dynamic maxima (both
cylinders, every T_c) rounds into [3, 8]; "effective" means that separate motion
needs at least 10 % more force (:data:`EFFECTIVE`), and claim 3 holds when the
longest such cycle time is within 1 s of 11 s; claim 4 compares the drive's own
speeds (:func:`assur.dynamics.cycles.drive_cycles`: through the divider against
the whole flow to one cylinder at a time) — the forces' ratios of both cylinders
must round into [1.16, 2.00], the dynamic parts' be about 4. The paper does not say in which
order its separate motion runs: both orders are computed and a claim agrees when
one of them does, which the verdict names.

The basis (:data:`BASIS`, stated in the report and in every verdict's text): the
forces in the fed direction (:func:`assur.dynamics.cycles.fed_force`: the force the
chamber fed for the stroke must produce; a push against the motion — the stick's
braking at t = 0 — is held by the drained side, which the model does not feed)
against ideal combined motion (``combined_ideal``, eq. 61: its cycle lasts T_c).
Max |F| and combined motion with V1 = V2 (``combined_equal``, eq. 60: at "T_c = 6 s"
its cycle lasts 7.8 s on ЛВ-184А) are reported beside, and a verdict that they would
turn says so.

==================  ==============================================================
figure              what
==================  ==============================================================
``max_F1``          max |F1| of the boom's cylinder against T_c, per scenario
``max_F2``          max |F2| of the stick's cylinder (paper fig. 3)
``fed_F1``          max σ1·F1, the boom's force in the fed direction (σ_j = ±1 the sign
                    of the stroke, :func:`assur.dynamics.cycles.fed_sense`)
``fed_F2``          max σ2·F2, the stick's (the verdicts' basis)
``dynamic_F1``      max |F_d1|, the dynamic part (paper fig. 4)
``dynamic_F2``      max |F_d2|
``static``          max |F_s1|, |F_s2|, the static parts (they do not depend on T_c)
==================  ==============================================================

Forces are shown in kN in the figures, in N in the tables (HTML, CSV and XLSX).
"""

from __future__ import annotations

from pathlib import Path

from ...core.display import unit_system
from ...dynamics.cycles import PERIODS, SCENARIOS, strokes, sweep
from ...texts import localize
from ._canvas import new_figure, titled_axes, to_png_bytes
from ._cycles_text import _T, _t, verdict_word
from ._cycles_verdicts import (ABOUT, BASIS, EFFECTIVE, EQUAL, PAPER, SEPARATE, Verdict, _by,
                               conclusions, drive_sweep, pump_conclusions)
from .labels import check_lang, unit
from .tables import Column, Table, in_units, write_csv, write_frame_csv, write_xlsx

__all__ = ["FIGURES", "PAPER", "ABOUT", "EFFECTIVE", "BASIS", "EQUAL", "Verdict", "conclusions",
           "drive_sweep", "pump_conclusions", "tables",
           "figures", "drive_speeds", "verdict_word", "write_cycles_report"]

FIGURES = ("max_F1", "max_F2", "fed_F1", "fed_F2", "dynamic_F1", "dynamic_F2", "static")
KN = 1e3


def tables(df, lang="en"):
    """The sweep as :class:`assur.views.report.tables.Table` objects: one per scenario
    (T_c [s]; max |F|, |F_s|, |F_d| and the max force in the fed direction of both
    cylinders [N]; the duration [s]) and the ratios separate ÷ combined of both
    orders: max |F| and |F_d| against V1 = V2 (eq. 60), the forces in the fed
    direction and |F_d| against ideal combined motion (eq. 61, :data:`BASIS`).

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import strokes, sweep
    >>> from assur.views.report.cycles import tables
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> df = sweep(model.mechanism, *strokes(model.drive))  # T_c = 4…20 s, 4 scenarios
    >>> tabs = tables(df)
    >>> [t.id for t in tabs]
    ['combined_equal', 'combined_ideal', 'separate_second', 'separate_first', 'ratios']
    >>> tabs[0].title("en"), len(tabs[0])  # 17 cycle times
    ('Max cylinder forces over the cycle: combined, V1 = V2 (eq. 60)', 17)
    >>> round(float(tabs[-1]["F1_max_a/comb"][2]), 3)  # at T_c = 6 s: +79 % [-]
    1.794
    >>> round(float(tabs[-1]["F2_fed_a/ideal"][2]), 3)  # the stick, fed, eq. 61 [-]
    1.251
    """
    check_lang(lang)
    out = []
    lab = {"T": ("cycle time", "время цикла"), "duration": ("until the last rod arrives",
                                                            "до прихода последнего штока")}
    for j in (1, 2):
        lab[f"F{j}_max"] = (f"max |F{j}|", f"max |F{j}|")
        lab[f"Fs{j}_max"] = (f"max |F_s{j}|, static part", f"max |F_s{j}|, статическая")
        lab[f"Fd{j}_max"] = (f"max |F_d{j}|, dynamic part", f"max |F_d{j}|, динамическая")
        lab[f"F{j}_fed"] = (f"max F{j} in the fed direction",
                            f"max F{j} в направлении питаемой полости")
    cols = ("F1_max", "Fs1_max", "Fd1_max", "F1_fed", "F2_max", "Fs2_max", "Fd2_max", "F2_fed")
    for s in SCENARIOS:
        d = _by(df, s)
        columns = [Column("T", "s", d.index.to_numpy(dtype=float), dict(zip(("en", "ru"),
                                                                         lab["T"])))]
        columns += [Column(c, "N", d[c].to_numpy(dtype=float), dict(zip(("en", "ru"), lab[c])))
                    for c in cols]
        columns.append(Column("duration", "s", d["duration"].to_numpy(dtype=float),
                              dict(zip(("en", "ru"), lab["duration"]))))
        titles = {lg: localize(_T["table"], lg).format(localize(_T[f"scenario_{s}"], lg))
                  for lg in ("en", "ru")}
        out.append(Table(s, titles, tuple(columns)))
    comb, ideal = _by(df, EQUAL), _by(df, BASIS)
    columns = [Column("T", "s", comb.index.to_numpy(dtype=float), dict(zip(("en", "ru"),
                                                                        lab["T"])))]
    for base, name, ru, cs in ((comb, "comb", "совмещённое (ур. 60)",
                                ("F1_max", "F2_max", "Fd1_max", "Fd2_max")),
                               (ideal, "ideal", "идеальное совмещённое (ур. 61)",
                                ("F1_fed", "F2_fed", "Fd1_max", "Fd2_max"))):
        for s, tag in zip(SEPARATE, ("a", "b")):
            d = _by(df, s)
            for c in cs:
                columns.append(Column(
                    f"{c}_{tag}/{name}", "-", (d[c] / base[c]).to_numpy(float),
                    {"en": f"{c} separate ({tag}) ÷ "
                           + ("combined (eq. 60)" if name == "comb" else "ideal combined "
                              "(eq. 61)"),
                     "ru": f"{c} раздельное ({'а' if tag == 'a' else 'б'}) ÷ {ru}"}))
    out.append(Table("ratios", {lg: localize(_T["ratios"], lg) for lg in ("en", "ru")},
                     tuple(columns)))
    return out


def drive_speeds(circuit):
    """Rod speeds of a drive's cylinders fed by its pump (seed 004 eqs. 63–68): rows
    ``(coordinate, side, area [m²], combined speed [m/s], separate speed [m/s])``,
    combined = the divider's share s_j·Q/f, separate = the whole flow Q/f, for the
    piston and the rod side of each cylinder.

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.cycles import drive_speeds
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> rows = drive_speeds(model.drive)  # the pump's 80 l/min
    >>> [(c, side, round(f * 1e4, 2)) for c, side, f, _, _ in rows][:2]  # area [cm²]
    [('S1', 'piston', 78.54), ('S1', 'rod', 47.37)]
    >>> [round(v, 4) for v in rows[0][3:]]  # boom rod, combined and separate [m/s]
    [0.0849, 0.1698]
    """
    Q = circuit.pump_flow()
    rows = []
    for b in circuit.branches:
        c = b.cylinder
        for side, f in (("piston", c.area), ("rod", c.count * c.rod_side_area)):
            rows.append((b.coordinate, side, f, b.share * Q / f, Q / f))
    return rows


def _shown(du, values, si):
    """Values [``si``: ``"N"`` or ``"s"``] in the display units ``du`` (None: forces in
    kN, times in s): ``(values, unit)``."""
    import numpy as np
    values = np.asarray(values, dtype=float)
    if du is None:
        return (values / KN, "kN") if si == "N" else (values, si)
    v, u = du.convert(values, si)
    return np.asarray(v, dtype=float), u


def _curves(df, lang, key, col, title, du=None):
    f = new_figure()
    sym = {"F1_max": "|F1|", "F2_max": "|F2|", "Fd1_max": "|F_d1|", "Fd2_max": "|F_d2|",
           "F1_fed": "σ1·F1", "F2_fed": "σ2·F2"}
    fu, tu = _shown(du, 0.0, "N")[1], _shown(du, 0.0, "s")[1]
    ax = titled_axes(f, localize(_T[title], lang), f"{_t('T', lang)} [{unit(tu, lang)}]",
                     f"max {sym[col[0]]} [{unit(fu, lang)}]")
    for i, s in enumerate(SCENARIOS):
        d = _by(df, s)
        ls = "-" if s.startswith("combined") else "--"
        for c, style in zip(col, (ls, ":")):
            ax.plot(_shown(du, d.index, "s")[0], _shown(du, d[c], "N")[0], style, marker="o",
                    ms=3, color=f"C{i}",
                    label=_t(f"scenario_{s}", lang) + ("" if len(col) == 1 else f" — {c}"))
    ax.legend(fontsize="small")
    return f


def figures(df, lang="en", units=None, mechanism=None):
    """``{name: Figure}`` of :data:`FIGURES` for a sweep.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import strokes, sweep
    >>> from assur.views.report.cycles import figures
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> df = sweep(model.mechanism, *strokes(model.drive))  # T_c = 4…20 s, 4 scenarios
    >>> figs = figures(df)
    >>> list(figs)
    ['max_F1', 'max_F2', 'fed_F1', 'fed_F2', 'dynamic_F1', 'dynamic_F2', 'static']
    >>> ax = figs["max_F2"].axes[0]
    >>> ax.get_title(), ax.get_ylabel(), len(ax.lines)  # a curve per scenario
    ("Max force of the stick's cylinder |F2|", 'max |F2| [kN]', 4)
    >>> round(float(ax.lines[0].get_ydata()[2]), 1)  # combined, T_c = 6 s [kN]
    78.3
    >>> ax = figs["fed_F2"].axes[0]  # the stick retracts: its rod side is fed
    >>> ax.get_ylabel(), round(float(ax.lines[1].get_ydata()[2]), 1)  # eq. 61, 6 s [kN]
    ('max σ2·F2 [kN]', 54.7)
    """
    check_lang(lang)
    du = None if units is None and mechanism is None else unit_system(mechanism, units)
    out = {name: _curves(df, lang, name, (c,), name, du) for name, c in (
        ("max_F1", "F1_max"), ("max_F2", "F2_max"), ("fed_F1", "F1_fed"), ("fed_F2", "F2_fed"),
        ("dynamic_F1", "Fd1_max"), ("dynamic_F2", "Fd2_max"))}
    f = new_figure()
    fu, tu = _shown(du, 0.0, "N")[1], _shown(du, 0.0, "s")[1]
    ax = titled_axes(f, _t("static", lang), f"{_t('T', lang)} [{unit(tu, lang)}]",
                     f"max |F_s| [{unit(fu, lang)}]")
    for i, s in enumerate(SCENARIOS):
        d = _by(df, s)
        T = _shown(du, d.index, "s")[0]
        ax.plot(T, _shown(du, d["Fs1_max"], "N")[0], "-", color=f"C{i}",
                label=_t(f"scenario_{s}", lang))
        ax.plot(T, _shown(du, d["Fs2_max"], "N")[0], "--", color=f"C{i}")
    ax.legend(fontsize="small")
    out["static"] = f
    return out


def write_cycles_report(model, outdir, lang="en", formats=("csv", "xlsx", "png", "html"),
                        periods=PERIODS, g=None, units=None):
    """Seed 004's sweep of a model with a drive (every scenario, T_c = 4…20 s; the
    strokes from :func:`assur.dynamics.cycles.strokes`) written as
    ``cycles_<scenario>.csv``, ``cycles_ratios.csv``, ``cycles_conclusions.csv``,
    ``cycles.xlsx``, ``cycles_<figure>.png`` and ``cycles.html``.

    Returns
    -------
    (DataFrame, list of Verdict, list of Path)
        The sweep, the verdicts and the files written.

    Raises
    ------
    ModelError
        A model without a drive (its strokes come from the cylinders' stops); a
        value of a table that is NaN or infinite
        (:func:`assur.core.inputs.check_table`: nothing is written).
    ValueError
        A mechanism that is not of two coordinates.

    Examples
    --------
    >>> import tempfile
    >>> from assur import io
    >>> from assur.views.report.cycles import write_cycles_report
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> with tempfile.TemporaryDirectory() as d:
    ...     df, verdicts, files = write_cycles_report(model, d, formats=("csv",))
    >>> len(df), [p.name for p in files][-3:]  # 4 scenarios × 17 cycle times
    (68, ['cycles_ratios.csv', 'cycles_pump.csv', 'cycles_conclusions.csv'])
    >>> [v.key for v in verdicts if v.agrees]
    ['boom_excess', 'stick_excess', 'dynamic_fall', 'pump_forces', 'pump_dynamic']
    >>> write_cycles_report(io.load(io.bundled("hitch_003")), "unused")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: model 'hitch_003' has no hydraulic drive: its cycle runs between ...
    """
    import pandas as pd

    from ...errors import ModelError
    check_lang(lang)
    if model.drive is None:
        raise ModelError(f"model {model.name!r} has no hydraulic drive: its cycle runs between "
                         f"its cylinders' stops (add [[drive]] entries, docs/simulation.md)")
    start, end = strokes(model.drive)
    df = sweep(model.mechanism, start, end, periods=periods, g=g)
    dd = drive_sweep(model, g)
    verdicts = conclusions(df, lang) + pump_conclusions(dd, lang)
    tabs = tables(df, lang)
    cols = [Column("duration", "s", dd["duration"].to_numpy(float),
                   {"en": "the cycle's time", "ru": "время цикла"})]
    cols += [Column(c, "N", dd[c].to_numpy(float), {"en": f"max |{c[:-4]}|",
                                                     "ru": f"max |{c[:-4]}|"})
             for c in ("F1_max", "F2_max", "Fd1_max", "Fd2_max")]
    cols += [Column(c, "N", dd[c].to_numpy(float),
                    {"en": f"max {c[:-4]} in the fed direction",
                     "ru": f"max {c[:-4]} в направлении питаемой полости"})
             for c in ("F1_fed", "F2_fed")]
    tabs.append(Table("pump", {lg: localize(_T["pump_table"], lg) for lg in ("en", "ru")},
                      tuple(cols)))
    du = unit_system(model.mechanism, units)  # the tables, figures and texts shown in these
    tabs = [in_units(tab, du) for tab in tabs]
    # no NaN or infinity in any file: the scenarios the figures draw and every table,
    # checked before anything is written (naming the table, column and row)
    from ...core.inputs import check_table
    check_table("cycles (scenarios)", df)
    for tab in tabs:
        check_table(f"cycles_{tab.id}", {f"{c.symbol} [{c.unit}]": c.values
                                         for c in tab.columns})
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    files = []
    if "csv" in formats:
        for tab in tabs:
            files.append(write_csv(tab, out / f"cycles_{tab.id}.csv", lang))
        p = out / "cycles_conclusions.csv"
        files.append(write_frame_csv(pd.DataFrame(
            [(v.key, v.claim, v.model, v.agrees, v.why) for v in verdicts],
            columns=["key", "claim", "model", "agrees", "why"]), p, lang))
    if "xlsx" in formats:
        files.append(write_xlsx(tabs, out / "cycles.xlsx", lang=lang))
    figs = figures(df, lang, du, model.mechanism) if {"png", "html"} & set(formats) else {}
    pngs = {name: to_png_bytes(f) for name, f in figs.items()}
    if "png" in formats:
        for name, data in pngs.items():
            p = out / f"cycles_{name}.png"
            p.write_bytes(data)
            files.append(p)
    if "html" in formats:
        p = out / "cycles.html"
        p.write_text(_document(model, lang, start, end, verdicts, tabs, figs, pngs, du),
                     encoding="utf-8")
        files.append(p)
    return df, verdicts, files


def _document(model, lang, start, end, verdicts, tabs, figs, pngs, du):
    """The work-cycle report as a document (:mod:`assur.views.report.document`): the
    model's inputs and drive, the paper's conclusions as verdicts (agrees: ok, does
    not: fail) with the criteria, the drive's rod speeds, the numbered tables and
    figures, the paper's slips among the notes."""
    from .document import drive_rows, model_rows, render_document
    from .numbers import number
    L = {k: localize(v, lang) for k, v in _T.items()}
    source = model.source.name if model.source else None
    coords = model.drive.coordinates
    lu = du["length"]
    stroke_text = "; ".join(f"{c}: {number(float(lu.of(a)), None, lang)} → "
                            f"{number(float(lu.of(b)), None, lang)} {unit(lu.text, lang)}"
                            for c, a, b in zip(coords, start, end))
    marks = [{"status": "ok" if v.agrees else "fail", "href": None,
              "text": f"{L['claim']}: {v.claim} {L['model']}: {v.model} — "
                      f"{L['agrees'] if v.agrees else L['disagrees']}: {v.why}"}
             for v in verdicts]
    au, vu = du["area"], du["velocity"]
    drive = [(c, _t(side, lang), number(float(au.of(f)), None, lang),
              number(float(vu.of(vc)), None, lang), number(float(vu.of(vs)), None, lang))
             for c, side, f, vc, vs in drive_speeds(model.drive)]
    sections = [{"anchor": "drive-speeds", "title": L["drive"],
                 "header": ("", "", f"f [{unit(au.text, lang)}]",
                            f"{L['combined']} [{unit(vu.text, lang)}]",
                            f"{L['separate']} [{unit(vu.text, lang)}]"),
                 "rows": drive, "notes": []}]
    return render_document(
        lang=lang, title=localize(model.mechanism.title, lang), kind=L["report"],
        name=model.name, source=source,
        inputs=model_rows(model.mechanism, lang, du, source=source)
        + [drive_rows(model.drive, lang, du, model.mechanism)],
        verdicts=marks, verdicts_title=L["conclusions"],
        verdicts_notes=[_t("criteria", lang, 100 * ABOUT, 100 * EFFECTIVE, stroke_text)],
        sections=sections, tables=tabs,
        figures={n: (d, figs[n].axes[0].get_title()) for n, d in pngs.items()},
        notes=[localize(n, lang) for n in model.mechanism.notes])
