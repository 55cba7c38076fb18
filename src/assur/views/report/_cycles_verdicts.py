"""The paper's conclusions (seed 004) set against a work-cycle sweep: the
:class:`Verdict` of each claim (:mod:`assur.views.report.cycles`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._cycles_text import _t
from .labels import check_lang, unit

__all__ = ["PAPER", "ABOUT", "EFFECTIVE", "Verdict", "conclusions", "drive_sweep",
           "pump_conclusions"]

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
