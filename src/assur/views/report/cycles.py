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
one of them does, which the verdict names. "Combined" is ``combined_equal``
(eq. 60, V1 = V2); ``combined_ideal`` is tabulated and drawn beside it.

==================  ==============================================================
figure              what
==================  ==============================================================
``max_F1``          max |F1| of the boom's cylinder against T_c, per scenario
``max_F2``          max |F2| of the stick's cylinder (paper fig. 3)
``dynamic_F1``      max |F_d1|, the dynamic part (paper fig. 4)
``dynamic_F2``      max |F_d2|
``static``          max |F_s1|, |F_s2|, the static parts (they do not depend on T_c)
==================  ==============================================================

Forces are shown in kN in the figures, in N in the tables (HTML, CSV and XLSX).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...dynamics.cycles import PERIODS, SCENARIOS, strokes, sweep
from ...texts import Text, localize
from ._canvas import new_figure, titled_axes, to_png_bytes
from .html import data_uri
from .labels import check_lang, unit
from .tables import Column, Table, write_csv, write_xlsx

__all__ = ["FIGURES", "PAPER", "ABOUT", "EFFECTIVE", "Verdict", "conclusions",
           "drive_sweep", "pump_conclusions", "tables",
           "figures", "drive_speeds", "verdict_word", "write_cycles_report"]

FIGURES = ("max_F1", "max_F2", "dynamic_F1", "dynamic_F2", "static")

#: the paper's conclusions as numbers: the cycle time of claim 1 [s], the excess of
#: separate over combined max forces (boom, stick) [-], the range of the fall of the
#: dynamic parts [-], the cycle time under which combined motion is most effective [s]
PAPER = {"period": 6.0, "excess": (0.90, 0.30), "dynamic": (3.0, 8.0), "effective_below": 11.0,
         "pump_forces": (1.16, 2.00), "pump_dynamic": 4.0}
#: "about x": within this share of x [-]
ABOUT = 0.25
#: combined motion is "effective" while separate needs this much more force [-]
EFFECTIVE = 0.10
#: the separate orders (paper a: the stick first; b: the boom first)
SEPARATE = ("separate_second", "separate_first")
KN = 1e3

_T = {
    "report": Text("Work cycles of the manipulator: combined and separate motion (seed 004)",
                   ru="Рабочие циклы манипулятора: совмещённое и раздельное движение "
                      "(источник 004)"),
    "scenario_combined_equal": Text("combined, V1 = V2 (eq. 60)",
                                    ru="совмещённое, V1 = V2 (ур. 60)"),
    "scenario_combined_ideal": Text("ideal combined, both end together (eq. 61)",
                                    ru="идеальное совмещённое, окончание одновременно "
                                       "(ур. 61)"),
    "scenario_separate_second": Text("separate (a): the stick, then the boom (eq. 62)",
                                     ru="раздельное (а): рукоять, затем стрела (ур. 62)"),
    "scenario_separate_first": Text("separate (b): the boom, then the stick (eq. 62)",
                                    ru="раздельное (б): стрела, затем рукоять (ур. 62)"),
    "T": Text("cycle time T_c", ru="время цикла T_ц"),
    "max_F1": Text("Max force of the boom's cylinder |F1|", ru="Максимальное усилие "
                   "гидроцилиндра подъёма стрелы |F1|"),
    "max_F2": Text("Max force of the stick's cylinder |F2|", ru="Максимальное усилие "
                   "гидроцилиндра привода рукояти |F2|"),
    "dynamic_F1": Text("Max dynamic part of the boom cylinder's force |F_d1|",
                       ru="Максимальная динамическая составляющая усилия гидроцилиндра "
                          "подъёма стрелы |F_d1|"),
    "dynamic_F2": Text("Max dynamic part of the stick cylinder's force |F_d2|",
                       ru="Максимальная динамическая составляющая усилия гидроцилиндра "
                          "привода рукояти |F_d2|"),
    "static": Text("Max static parts |F_s1| (solid), |F_s2| (dashed)",
                   ru="Максимальные статические составляющие |F_s1| (сплошные), |F_s2| "
                      "(штриховые)"),
    "table": Text("Max cylinder forces over the cycle: {0}",
                  ru="Максимальные усилия гидроцилиндров за цикл: {0}"),
    "ratios": Text("Separate ÷ combined (V1 = V2)", ru="Раздельное ÷ совмещённое (V1 = V2)"),
    "pump_table": Text("At the drive's speeds: through the divider; separate (a), (b)",
                       ru="При скоростях привода: через делитель; раздельно (а), (б)"),
    "drive": Text("Rod speeds of the drive (eqs. 63–68)",
                  ru="Скорости штоков привода (ур. 63–68)"),
    "conclusions": Text("The paper's conclusions against the model",
                        ru="Выводы статьи и модель"),
    "claim": Text("the paper", ru="статья"),
    "model": Text("the model", ru="модель"),
    "verdict": Text("verdict", ru="вывод"),
    "why": Text("why", ru="почему"),
    "agrees": Text("agrees", ru="согласуется"),
    "disagrees": Text("does not agree", ru="не согласуется"),
    "criteria": Text("Criteria: “about x %” holds within ±{0:.0f} % of x; “3–8 times” when "
                     "every ratio of the dynamic maxima (both cylinders, every T_c) rounds into "
                     "[3, 8]; combined motion is “effective” while separate motion needs at "
                     "least {1:.0f} % more force. The paper does not say in which order its "
                     "separate motion runs: both are computed, and a claim agrees when one "
                     "does. Strokes: {2}.",
                     ru="Критерии: «около x %» — в пределах ±{0:.0f} % от x; «в 3–8 раз» — "
                        "если каждое отношение динамических максимумов (оба цилиндра, все "
                        "T_ц) после округления лежит в [3, 8]; совмещение «эффективно», пока "
                        "при раздельном движении усилие больше не менее чем на {1:.0f} %. "
                        "Порядок раздельного движения в статье не указан: рассчитаны оба, "
                        "и вывод согласуется, если согласуется один из них. Ходы: {2}."),
    "slips": Text("The paper's slips and how the model resolves them",
                  ru="Описки статьи и как они разрешены в модели"),
    "figures": Text("Figures", ru="Рисунки"),
    "tables": Text("Tables", ru="Таблицы"),
    "c1_claim": Text("At T_c = {0:g} s separate motion gives a max force of the {1} about "
                     "{2:.0f} % higher than combined motion.",
                     ru="При T_ц = {0:g} с и раздельном движении максимальное усилие {1} "
                        "больше примерно на {2:.0f} %, чем при совмещении движений."),
    "boom": Text("boom's cylinder", ru="гидроцилиндра подъёма стрелы"),
    "stick": Text("stick's cylinder", ru="гидроцилиндра привода рукояти"),
    "c1_model": Text("{0:+.0f} % with the stick first (a), {1:+.0f} % with the boom first (b)",
                     ru="{0:+.0f} % при движении сначала рукояти (а), {1:+.0f} % — сначала "
                        "стрелы (б)"),
    "c1_yes": Text("order {0} is within ±{1:.0f} % of the paper's {2:.0f} %",
                   ru="порядок {0} в пределах ±{1:.0f} % от {2:.0f} % статьи"),
    "c1_no": Text("neither order comes within ±{0:.0f} % of the paper's {1:.0f} %: the excess "
                  "is the separate motion's dynamic part at V = ΣΔS/T_c, which depends on the "
                  "strokes (the paper's S_max2 and Φ1p0 disagree, see below) and on which "
                  "link moves first; the paper gives neither",
                  ru="ни один порядок не попадает в ±{0:.0f} % от {1:.0f} % статьи: превышение "
                     "— это динамическая составляющая раздельного движения при V = ΣΔS/T_ц, "
                     "она зависит от ходов (S_max2 и Φ1p0 статьи не согласованы, см. ниже) и "
                     "от того, какое звено движется первым; статья не приводит ни того, ни "
                     "другого"),
    "c2_claim": Text("With combined motion the dynamic components fall {0:g}–{1:g} times, "
                     "depending on the cycle time.",
                     ru="При совмещении движений динамические составляющие уменьшаются в "
                        "{0:g}–{1:g} раз в зависимости от времени цикла."),
    "c2_model": Text("(a) {0:.1f}–{1:.1f}×, (b) {2:.1f}–{3:.1f}× (boom and stick, every T_c); "
                     "the ratios vary with T_c by at most {4:.1e}",
                     ru="(а) {0:.1f}–{1:.1f}×, (б) {2:.1f}–{3:.1f}× (стрела и рукоять, все "
                        "T_ц); с T_ц отношения меняются не более чем на {4:.1e}"),
    "c2_yes": Text("order {0} falls within {1:g}–{2:g}×; but the ratio does not depend on T_c: "
                   "at constant rod speeds every dynamic term scales as 1/T_c²",
                   ru="порядок {0} попадает в {1:g}–{2:g}×; но отношение не зависит от T_ц: "
                      "при постоянных скоростях штоков каждая динамическая составляющая "
                      "пропорциональна 1/T_ц²"),
    "c2_no": Text("no order keeps every ratio within {0:g}–{1:g}×; at constant rod speeds "
                  "every dynamic term scales as 1/T_c², so the ratio cannot depend on T_c",
                  ru="ни при одном порядке все отношения не лежат в {0:g}–{1:g}×; при "
                     "постоянных скоростях штоков каждая динамическая составляющая "
                     "пропорциональна 1/T_ц², и отношение не может зависеть от T_ц"),
    "c3_claim": Text("Combined motion is most effective for cycles under {0:g} s.",
                     ru="Совмещение операций особенно эффективно при T_ц < {0:g} с."),
    "c3_model": Text("separate motion needs ≥ {0:.0f} % more force up to T_c = {1} (the "
                     "gain of combined motion: {2}; at long cycles it tends to the static "
                     "parts' {3:+.0f} %, the paths differ)",
                     ru="при раздельном движении усилие больше на ≥ {0:.0f} % до T_ц = {1} "
                        "(выигрыш совмещения: {2}; при длинных циклах он стремится к {3:+.0f} % "
                        "статических составляющих — траектории различны)"),
    "gain_at": Text("{0:+.0f} % at {1:g} s", ru="{0:+.0f} % при {1:g} с"),
    "none": Text("no cycle time", ru="ни при каком времени цикла"),
    "c3_yes": Text("the gain falls below {0:.0f} % within 1 s of {1:g} s: the dynamic part "
                   "falls as 1/T_c² while the static part stays",
                   ru="выигрыш падает ниже {0:.0f} % в пределах 1 с от {1:g} с: динамическая "
                      "составляющая падает как 1/T_ц², статическая остаётся"),
    "c3_no": Text("the gain falls below {0:.0f} % at another cycle time than {1:g} s: where "
                  "depends on the ratio of the dynamic to the static part, i.e. on the strokes "
                  "and masses (the paper's strokes are uncertain)",
                  ru="выигрыш падает ниже {0:.0f} % не при {1:g} с: это зависит от отношения "
                     "динамической составляющей к статической, т. е. от ходов и масс (ходы "
                     "статьи неопределённы)"),
    "c4_claim": Text("With the standard pump (Q_h = 80 l/min) and a flow divider the max "
                     "cylinder forces fall {0:.2f}–{1:.2f} times (for the various manipulators).",
                     ru="При установке штатного насоса (Q_h = 80 л/мин) и делителя потока "
                        "максимальные усилия гидроцилиндров снижаются в {0:.2f}–{1:.2f} раза "
                        "(для различных манипуляторов)."),
    "c5_claim": Text("… and the dynamic components of the forces fall {0:g} times.",
                     ru="… а динамические составляющие усилий снижаются в {0:g} раза."),
    "c4_model": Text("separate (the whole flow, V = Q/f) ÷ divider (V = Q/(2f)): (a) {0:.2f} "
                     "(boom), {1:.2f} (stick); (b) {2:.2f}, {3:.2f}; the cycle takes {4:.2f} s "
                     "with the divider, {5:.2f} s separate",
                     ru="раздельное (весь поток, V = Q/f) ÷ с делителем (V = Q/(2f)): (а) "
                        "{0:.2f} (стрела), {1:.2f} (рукоять); (б) {2:.2f}, {3:.2f}; цикл длится "
                        "{4:.2f} с с делителем, {5:.2f} с раздельно"),
    "c4_yes": Text("order {0}: both ratios within {1:g}–{2:g}", ru="порядок {0}: оба отношения "
                   "в пределах {1:g}–{2:g}"),
    "c4_no": Text("no order keeps both ratios within {0:g}–{1:g}: the gain depends on the "
                  "crane's static loads, which the divider does not change",
                  ru="ни при одном порядке оба отношения не лежат в {0:g}–{1:g}: выигрыш "
                     "зависит от статических нагрузок крана, которых делитель не меняет"),
    "c5_yes": Text("order {0}: both ratios within ±{1:.0f} % of {2:g}",
                   ru="порядок {0}: оба отношения в пределах ±{1:.0f} % от {2:g}"),
    "c5_no": Text("no order keeps both ratios within ±{0:.0f} % of {1:g}: with the whole flow "
                  "a rod moves 1/s_j times faster, its dynamic terms (∝ V²) 1/s_j² = 4 times "
                  "larger at the same position, but the maxima fall where the paths differ",
                  ru="ни при одном порядке оба отношения не лежат в пределах ±{0:.0f} % от "
                     "{1:g}: при всём потоке шток движется в 1/s_j раз быстрее, его "
                     "динамические составляющие (∝ V²) в 1/s_j² = 4 раза больше в том же "
                     "положении, но максимумы приходятся на разные положения"),
    "speed_row": Text("{0}: f = {1:.4g} m², rod side {2:.4g} m²",
                      ru="{0}: f = {1:.4g} м², штоковая полость {2:.4g} м²"),
    "combined": Text("combined, divider", ru="совмещённое, делитель"),
    "separate": Text("separate", ru="раздельное"),
    "piston": Text("piston side", ru="поршневая полость"),
    "rod": Text("rod side", ru="штоковая полость"),
}


def verdict_word(agrees, lang="en"):
    """The verdict "agrees" or "does not agree" in ``lang``.

    Examples
    --------
    >>> from assur.views.report.cycles import verdict_word
    >>> verdict_word(True), verdict_word(False), verdict_word(False, "ru")
    ('agrees', 'does not agree', 'не согласуется')
    """
    return localize(_T["agrees" if agrees else "disagrees"], check_lang(lang))


def _t(key, lang, *args):
    s = localize(_T[key], lang)
    return s.format(*args) if args else s


@dataclass(frozen=True)
class Verdict:
    """One of the paper's conclusions set against the model.

    Attributes
    ----------
    key : str
        ``boom_excess``, ``stick_excess``, ``dynamic_fall`` or ``effective_below``
        (:func:`conclusions`); ``pump_forces`` or ``pump_dynamic``
        (:func:`pump_conclusions`).
    claim, model, why : str
        The paper's statement, the model's figures, the reason (in the language
        asked).
    agrees : bool
    numbers : dict
        The computed values the verdict rests on.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import strokes, sweep
    >>> from assur.views.report.cycles import conclusions
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> df = sweep(model.mechanism, *strokes(model.drive))  # T_c = 4…20 s, 4 scenarios
    >>> v = conclusions(df)[0]
    >>> v.key, v.agrees, v.model  # the boom's excess at T_c = 6 s; the paper: about 90 %
    ('boom_excess', True, '+79 % with the stick first (a), +24 % with the boom first (b)')
    >>> round(v.numbers["excess"]["separate_second"], 3)  # separate ÷ combined − 1 [-]
    0.794
    """

    key: str
    claim: str
    model: str
    agrees: bool
    why: str
    numbers: dict


def _by(df, scenario):
    d = df[df["scenario"] == scenario].set_index("T").sort_index()
    if d.empty:
        raise ValueError(f"the sweep has no scenario {scenario!r}")
    return d


def conclusions(df, lang="en", paper=PAPER, about=ABOUT, effective=EFFECTIVE):
    """The paper's conclusions against a sweep (:func:`assur.dynamics.cycles.sweep`
    over every scenario and cycle time) as a list of :class:`Verdict`.

    Raises
    ------
    ValueError
        A sweep without a scenario or without the paper's cycle time.

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics.cycles import strokes, sweep
    >>> from assur.views.report.cycles import conclusions
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> df = sweep(model.mechanism, *strokes(model.drive))  # T_c = 4…20 s, 4 scenarios
    >>> [v.key for v in conclusions(df)]
    ['boom_excess', 'stick_excess', 'dynamic_fall', 'effective_below']
    >>> [v.key for v in conclusions(df) if v.agrees]  # claims 1 (boom) and 2 hold
    ['boom_excess', 'dynamic_fall']
    >>> conclusions(df)[3].numbers["T_star"]  # combined motion gains ≥ 10 % up to [s]
    9.0
    >>> conclusions(df[df["T"] != 6.0])
    Traceback (most recent call last):
    ...
    ValueError: the sweep has no cycle time T = 6.0 s (the paper's claim 1)
    """
    check_lang(lang)
    comb = _by(df, "combined_equal")
    sep = {s: _by(df, s) for s in SEPARATE}
    T0 = paper["period"]
    if T0 not in comb.index:
        raise ValueError(f"the sweep has no cycle time T = {T0} s (the paper's claim 1)")
    names = {"separate_second": "a" if lang == "en" else "а",
             "separate_first": "b" if lang == "en" else "б"}
    out = []
    for j, link in enumerate(("boom", "stick")):
        col = f"F{j + 1}_max"
        target = paper["excess"][j]
        ex = {s: float(sep[s].loc[T0, col] / comb.loc[T0, col] - 1) for s in SEPARATE}
        ok = [s for s in SEPARATE if abs(ex[s] - target) <= about * target]
        why = (_t("c1_yes", lang, names[ok[0]], 100 * about, 100 * target) if ok
               else _t("c1_no", lang, 100 * about, 100 * target))
        out.append(Verdict(f"{link}_excess", _t("c1_claim", lang, T0, _t(link, lang),
                                                100 * target),
                           _t("c1_model", lang, *(100 * ex[s] for s in SEPARATE)), bool(ok),
                           why, {"excess": ex, "target": target}))
    lo, hi = paper["dynamic"]
    ratios, spread = {}, 0.0
    for s in SEPARATE:
        r = np.stack([(sep[s][f"Fd{j}_max"] / comb[f"Fd{j}_max"]).to_numpy()
                      for j in (1, 2)])
        ratios[s] = (float(r.min()), float(r.max()))
        spread = max(spread, float((r.max(axis=1) / r.min(axis=1) - 1).max()))
    ok = [s for s in SEPARATE if round(ratios[s][0], 1) >= lo and round(ratios[s][1], 1) <= hi]
    out.append(Verdict("dynamic_fall", _t("c2_claim", lang, lo, hi),
                       _t("c2_model", lang, *ratios["separate_second"],
                          *ratios["separate_first"], spread), bool(ok),
                       _t("c2_yes", lang, names[ok[0]], lo, hi) if ok
                       else _t("c2_no", lang, lo, hi),
                       {"ratios": ratios, "spread": spread}))
    Tb = paper["effective_below"]
    gain = np.max([[sep[s][c] / comb[c] - 1 for c in ("F1_max", "F2_max")] for s in SEPARATE],
                  axis=(0, 1))
    Ts = comb.index.to_numpy(dtype=float)
    eff = Ts[gain >= effective]
    T_star = float(eff.max()) if eff.size else None
    agrees = T_star is not None and abs(T_star - Tb) <= 1.0
    static = max(float(sep[s][c].max() / comb[c].max() - 1) for s in SEPARATE
                 for c in ("Fs1_max", "Fs2_max"))
    gains = ", ".join(_t("gain_at", lang, 100 * float(gain[Ts == x][0]), x)
                      for x in sorted({T0, Tb, Ts[-1]}) if x in Ts)
    out.append(Verdict("effective_below", _t("c3_claim", lang, Tb),
                       _t("c3_model", lang, 100 * effective,
                          f"{T_star:g} {unit('s', lang)}" if T_star is not None
                          else _t("none", lang), gains, 100 * static), agrees,
                       (_t("c3_yes", lang, 100 * effective, Tb) if agrees
                        else _t("c3_no", lang, 100 * effective, Tb)),
                       {"T_star": T_star, "gain": dict(zip(Ts.tolist(), gain.tolist()))}))
    return out


def drive_sweep(model, g=None):
    """Max |F_j| and |F_d,j| [N] of the cycles at the drive's own speeds
    (:func:`assur.dynamics.cycles.drive_cycles`), a DataFrame with columns
    ``scenario`` (``divider``, ``pump_second``, ``pump_first``), ``duration`` [s],
    ``F1_max``, ``F2_max``, ``Fd1_max``, ``Fd2_max``.

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.cycles import drive_sweep
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> dd = drive_sweep(model).set_index("scenario")
    >>> dd.index.tolist()
    ['divider', 'pump_second', 'pump_first']
    >>> [round(float(x), 2) for x in dd["duration"]]  # the pump's 80 l/min [s]
    [7.42, 5.59, 5.59]
    >>> d = dd["Fd1_max"]  # twice the boom's speed: 4 times its dynamic force [-]
    >>> round(float(d["pump_second"] / d["divider"]), 3)
    4.0
    """
    import pandas as pd

    from ...dynamics.cycles import cycle_forces, drive_cycles
    cs = drive_cycles(model.drive)
    rows = []
    for (name, c), (F, Fs) in zip(cs.items(), cycle_forces(model.mechanism, list(cs.values()),
                                                            g)):
        Fd = np.abs(F - Fs).max(axis=0)
        Fm = np.abs(F).max(axis=0)
        rows.append(dict(scenario=name, duration=c.period, F1_max=Fm[0], F2_max=Fm[1],
                         Fd1_max=Fd[0], Fd2_max=Fd[1]))
    return pd.DataFrame(rows)


def pump_conclusions(dd, lang="en", paper=PAPER, about=ABOUT):
    """The paper's conclusion 3 (the standard pump with a divider against separate
    motion) against :func:`drive_sweep`'s ``dd``: two :class:`Verdict` (``pump_forces``,
    ``pump_dynamic``).

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.cycles import drive_sweep, pump_conclusions
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> forces, dynamic = pump_conclusions(drive_sweep(model))
    >>> forces.key, forces.agrees, dynamic.key, dynamic.agrees
    ('pump_forces', True, 'pump_dynamic', True)
    >>> [round(x, 2) for x in forces.numbers["ratios"]["pump_second"]]  # boom, stick [-]
    [1.39, 1.43]
    """
    check_lang(lang)
    d = dd.set_index("scenario")
    names = {"pump_second": "a" if lang == "en" else "а",
             "pump_first": "b" if lang == "en" else "б"}
    r = {s: [float(d.loc[s, f"F{j}_max"] / d.loc["divider", f"F{j}_max"]) for j in (1, 2)]
         for s in names}
    rd = {s: [float(d.loc[s, f"Fd{j}_max"] / d.loc["divider", f"Fd{j}_max"]) for j in (1, 2)]
          for s in names}
    lo, hi = paper["pump_forces"]
    target = paper["pump_dynamic"]
    model = _t("c4_model", lang, *r["pump_second"], *r["pump_first"],
               float(d.loc["divider", "duration"]), float(d.loc["pump_second", "duration"]))
    ok = [s for s in names if all(lo <= round(x, 2) <= hi for x in r[s])]
    okd = [s for s in names if all(abs(x - target) <= about * target for x in rd[s])]
    model_d = _t("c4_model", lang, *rd["pump_second"], *rd["pump_first"],
                 float(d.loc["divider", "duration"]), float(d.loc["pump_second", "duration"]))
    return [Verdict("pump_forces", _t("c4_claim", lang, lo, hi), model, bool(ok),
                    _t("c4_yes", lang, names[ok[0]], lo, hi) if ok
                    else _t("c4_no", lang, lo, hi), {"ratios": r}),
            Verdict("pump_dynamic", _t("c5_claim", lang, target), model_d, bool(okd),
                    _t("c5_yes", lang, names[okd[0]], 100 * about, target) if okd
                    else _t("c5_no", lang, 100 * about, target), {"ratios": rd})]


def tables(df, lang="en"):
    """The sweep as :class:`assur.views.report.tables.Table` objects: one per scenario
    (T_c [s]; max |F|, |F_s|, |F_d| of both cylinders [N]; the duration [s]) and the
    ratios separate ÷ combined (V1 = V2) of both orders.

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
    """
    check_lang(lang)
    out = []
    lab = {"T": ("cycle time", "время цикла"), "duration": ("until the last rod arrives",
                                                            "до прихода последнего штока")}
    for j in (1, 2):
        lab[f"F{j}_max"] = (f"max |F{j}|", f"max |F{j}|")
        lab[f"Fs{j}_max"] = (f"max |F_s{j}|, static part", f"max |F_s{j}|, статическая")
        lab[f"Fd{j}_max"] = (f"max |F_d{j}|, dynamic part", f"max |F_d{j}|, динамическая")
    cols = ("F1_max", "Fs1_max", "Fd1_max", "F2_max", "Fs2_max", "Fd2_max")
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
    comb = _by(df, "combined_equal")
    columns = [Column("T", "s", comb.index.to_numpy(dtype=float), dict(zip(("en", "ru"),
                                                                        lab["T"])))]
    for s, tag in zip(SEPARATE, ("a", "b")):
        d = _by(df, s)
        for c in ("F1_max", "F2_max", "Fd1_max", "Fd2_max"):
            columns.append(Column(f"{c}_{tag}/comb", "-", (d[c] / comb[c]).to_numpy(float),
                                  {"en": f"{c} separate ({tag}) ÷ combined",
                                   "ru": f"{c} раздельное ({'а' if tag == 'a' else 'б'}) ÷ "
                                         f"совмещённое"}))
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


def _curves(df, lang, key, col, title):
    f = new_figure()
    sym = {"F1_max": "|F1|", "F2_max": "|F2|", "Fd1_max": "|F_d1|", "Fd2_max": "|F_d2|"}
    ax = titled_axes(f, localize(_T[title], lang), f"{_t('T', lang)} [{unit('s', lang)}]",
                     f"max {sym[col[0]]} [{unit('kN', lang)}]")
    for i, s in enumerate(SCENARIOS):
        d = _by(df, s)
        ls = "-" if s.startswith("combined") else "--"
        for c, style in zip(col, (ls, ":")):
            ax.plot(d.index, d[c] / KN, style, marker="o", ms=3, color=f"C{i}",
                    label=_t(f"scenario_{s}", lang) + ("" if len(col) == 1 else f" — {c}"))
    ax.legend(fontsize="small")
    return f


def figures(df, lang="en"):
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
    ['max_F1', 'max_F2', 'dynamic_F1', 'dynamic_F2', 'static']
    >>> ax = figs["max_F2"].axes[0]
    >>> ax.get_title(), ax.get_ylabel(), len(ax.lines)  # a curve per scenario
    ("Max force of the stick's cylinder |F2|", 'max |F2| [kN]', 4)
    >>> round(float(ax.lines[0].get_ydata()[2]), 1)  # combined, T_c = 6 s [kN]
    78.3
    """
    check_lang(lang)
    out = {name: _curves(df, lang, name, (c,), name) for name, c in (
        ("max_F1", "F1_max"), ("max_F2", "F2_max"), ("dynamic_F1", "Fd1_max"),
        ("dynamic_F2", "Fd2_max"))}
    f = new_figure()
    ax = titled_axes(f, _t("static", lang), f"{_t('T', lang)} [{unit('s', lang)}]",
                     f"max |F_s| [{unit('kN', lang)}]")
    for i, s in enumerate(SCENARIOS):
        d = _by(df, s)
        ax.plot(d.index, d["Fs1_max"] / KN, "-", color=f"C{i}", label=_t(f"scenario_{s}",
                                                                          lang))
        ax.plot(d.index, d["Fs2_max"] / KN, "--", color=f"C{i}")
    ax.legend(fontsize="small")
    out["static"] = f
    return out


_TEMPLATE = """<!doctype html>
<html lang="{{ lang }}"><head><meta charset="utf-8"><title>{{ title }}</title>
<style>body{font-family:sans-serif;max-width:64em;margin:auto;padding:0 1em}
table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;padding:2px 6px;
text-align:right}td.l,th.l{text-align:left}.yes{color:#060;font-weight:bold}
.no{color:#a00;font-weight:bold}img{max-width:100%}</style></head><body>
<h1>{{ report }}</h1><h2>{{ title }}</h2>
<section id="conclusions"><h2>{{ L.conclusions }}</h2>
<table><tr><th class="l">{{ L.claim }}</th><th class="l">{{ L.model }}</th>
<th class="l">{{ L.verdict }}</th><th class="l">{{ L.why }}</th></tr>
{% for v in verdicts %}<tr><td class="l">{{ v.claim }}</td><td class="l">{{ v.model }}</td>
<td class="l {{ 'yes' if v.agrees else 'no' }}">{{ L.agrees if v.agrees else L.disagrees }}</td>
<td class="l">{{ v.why }}</td></tr>
{% endfor %}</table><p>{{ criteria }}</p></section>
<section id="slips"><h2>{{ L.slips }}</h2><ul>{% for n in notes %}<li>{{ n }}</li>{% endfor %}
</ul></section>
<section id="drive"><h2>{{ L.drive }}</h2>
<table><tr><th class="l"></th><th class="l"></th><th>f [{{ m2 }}]</th>
<th>{{ L.combined }} [{{ ms }}]</th><th>{{ L.separate }} [{{ ms }}]</th></tr>
{% for r in drive %}<tr><td class="l">{{ r[0] }}</td><td class="l">{{ r[1] }}</td>
<td>{{ "%.4g"|format(r[2]) }}</td><td>{{ "%.3f"|format(r[3]) }}</td>
<td>{{ "%.3f"|format(r[4]) }}</td></tr>{% endfor %}</table></section>
<section id="figures"><h2>{{ L.figures }}</h2>
{% for f in figures %}<figure><img alt="{{ f.name }}" src="{{ f.uri }}"></figure>{% endfor %}
</section>
<section id="tables"><h2>{{ L.tables }}</h2>
{% for tab in tables %}<h3>{{ tab.title }}</h3><table><tr>{% for h in tab.header %}
<th>{{ h }}</th>{% endfor %}</tr>{% for row in tab.rows %}<tr>{% for x in row %}
<td>{{ x }}</td>{% endfor %}</tr>{% endfor %}</table>{% endfor %}</section>
</body></html>
"""


def _cell(x, u):
    return f"{x:.0f}" if u == "N" else (f"{x:.3f}" if u == "-" else f"{x:.4g}")


def write_cycles_report(model, outdir, lang="en", formats=("csv", "xlsx", "png", "html"),
                        periods=PERIODS, g=None):
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
        A model without a drive (its strokes come from the cylinders' stops).
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
    ['boom_excess', 'dynamic_fall', 'pump_forces', 'pump_dynamic']
    >>> write_cycles_report(io.load(io.bundled("hitch_003")), "unused")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: model 'hitch_003' has no hydraulic drive: its cycle runs between ...
    """
    import jinja2
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
    tabs.append(Table("pump", {lg: localize(_T["pump_table"], lg) for lg in ("en", "ru")},
                      tuple(cols)))
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    files = []
    if "csv" in formats:
        for tab in tabs:
            files.append(write_csv(tab, out / f"cycles_{tab.id}.csv"))
        p = out / "cycles_conclusions.csv"
        pd.DataFrame([(v.key, v.claim, v.model, v.agrees, v.why) for v in verdicts],
                     columns=["key", "claim", "model", "agrees", "why"]).to_csv(p, index=False)
        files.append(p)
    if "xlsx" in formats:
        files.append(write_xlsx(tabs, out / "cycles.xlsx"))
    figs = figures(df, lang) if {"png", "html"} & set(formats) else {}
    pngs = {name: to_png_bytes(f) for name, f in figs.items()}
    if "png" in formats:
        for name, data in pngs.items():
            p = out / f"cycles_{name}.png"
            p.write_bytes(data)
            files.append(p)
    if "html" in formats:
        coords = model.drive.coordinates
        stroke_text = "; ".join(f"{c}: {a:.4g} → {b:.4g} {unit('m', lang)}"
                                for c, a, b in zip(coords, start, end))
        L = {k: localize(v, lang) for k, v in _T.items()}
        drive = [(c, _t(side, lang), f, vc, vs) for c, side, f, vc, vs in
                 drive_speeds(model.drive)]
        views = [{"title": tab.title(lang), "header": [c.header for c in tab.columns],
                  "rows": [[_cell(x, c.unit) for x, c in zip(row, tab.columns)]
                           for row in zip(*(c.values for c in tab.columns))]}
                 for tab in tabs]
        env = jinja2.Environment(autoescape=True, undefined=jinja2.StrictUndefined)
        text = env.from_string(_TEMPLATE).render(
            lang=lang, L=L, report=L["report"], title=localize(model.mechanism.title, lang),
            verdicts=verdicts, criteria=_t("criteria", lang, 100 * ABOUT, 100 * EFFECTIVE,
                                           stroke_text),
            notes=[localize(n, lang) for n in model.mechanism.notes],
            drive=drive, m2=unit("m²", lang), ms=unit("m/s", lang),
            figures=[{"name": n, "uri": data_uri(d)} for n, d in pngs.items()],
            tables=views)
        p = out / "cycles.html"
        p.write_text(text, encoding="utf-8")
        files.append(p)
    return df, verdicts, files
