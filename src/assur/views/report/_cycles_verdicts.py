"""The paper's conclusions (seed 004) set against a work-cycle sweep: the
:class:`Verdict` of each claim (:mod:`assur.views.report.cycles`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._cycles_text import _t
from .labels import check_lang, unit

__all__ = ["PAPER", "ABOUT", "EFFECTIVE", "BASIS", "EQUAL", "Verdict", "conclusions",
           "drive_sweep", "pump_conclusions"]

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
#: the paper's cycle-time basis: ideal combined motion (eq. 61: both rods start and
#: end together, the cycle lasts T_c), with the forces in the fed direction
BASIS = "combined_ideal"
#: combined motion with V1 = V2 (eq. 60), shown beside the basis: its cycle lasts
#: longer than T_c (the longer stroke ends later)
EQUAL = "combined_equal"


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
    >>> v.key, v.agrees  # the boom's excess at T_c = 6 s; the paper: about 90 %
    ('boom_excess', True)
    >>> print(v.model)  # doctest: +NORMALIZE_WHITESPACE
    eq. 61, ideal combined motion, force in the fed direction: +89 % with the stick
    first (a), +30 % with the boom first (b); max |F|: +89 % (a), +30 % (b). Against
    V1 = V2 (eq. 60; its cycle at T_c = 6 s lasts 7.8 s): +79 % (a), +24 % (b) in the
    fed direction; max |F|: +79 % (a), +24 % (b)
    >>> round(v.numbers["excess"]["separate_second"], 3)  # separate ÷ combined − 1 [-]
    0.886
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


def conclusions(df, lang="en", paper=PAPER, about=ABOUT, effective=EFFECTIVE, basis=BASIS):
    """The paper's conclusions against a sweep (:func:`assur.dynamics.cycles.sweep`
    over every scenario and cycle time) as a list of :class:`Verdict`.

    The basis (:data:`BASIS`): the forces in the fed direction
    (:func:`assur.dynamics.cycles.fed_force`) against ideal combined motion (eq. 61,
    whose cycle lasts T_c); max |F| and combined motion with V1 = V2 (eq. 60, whose
    cycle lasts longer than T_c) are reported beside, and a verdict that those would
    turn says so in its ``why``.

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
    >>> [v.key for v in conclusions(df) if v.agrees]  # claims 1 (boom, stick) and 2 hold
    ['boom_excess', 'stick_excess', 'dynamic_fall']
    >>> v = conclusions(df)[1]   # the stick at T_c = 6 s, fed direction, eq. 61 [-]
    >>> round(v.numbers["excess"]["separate_second"], 3), v.numbers["basis"]
    (0.251, 'combined_ideal')
    >>> round(v.numbers["max_equal"]["separate_second"], 3)   # max |F| against eq. 60 [-]
    0.132
    >>> conclusions(df[df["T"] != 6.0])
    Traceback (most recent call last):
    ...
    ValueError: the sweep has no cycle time T = 6.0 s (the paper's claim 1)
    """
    check_lang(lang)
    comb = _by(df, basis)
    equal = _by(df, EQUAL)
    sep = {s: _by(df, s) for s in SEPARATE}
    T0 = paper["period"]
    if T0 not in comb.index or T0 not in equal.index:
        raise ValueError(f"the sweep has no cycle time T = {T0} s (the paper's claim 1)")
    names = {"separate_second": "a" if lang == "en" else "а",
             "separate_first": "b" if lang == "en" else "б"}
    based = _t(f"basis_{basis}", lang)
    lasts = float(equal.loc[T0, "duration"])
    out = []
    for j, link in enumerate(("boom", "stick")):
        target = paper["excess"][j]

        def excess(base, kind):
            col = f"F{j + 1}_{kind}"
            return {s: float(sep[s].loc[T0, col] / base.loc[T0, col] - 1) for s in SEPARATE}

        ex, ex_max = excess(comb, "fed"), excess(comb, "max")
        ex_eq, ex_eq_max = excess(equal, "fed"), excess(equal, "max")
        ok = [s for s in SEPARATE if abs(ex[s] - target) <= about * target]
        ok_old = [s for s in SEPARATE if abs(ex_eq_max[s] - target) <= about * target]
        why = (_t("c1_yes", lang, names[ok[0]], 100 * about, 100 * target) if ok
               else _t("c1_no", lang, 100 * about, 100 * target))
        if bool(ok_old) != bool(ok):
            why += _t("c1_old_yes" if ok_old else "c1_old_no", lang, T0, lasts)
        out.append(Verdict(
            f"{link}_excess", _t("c1_claim", lang, T0, _t(link, lang), 100 * target),
            _t("c1_model", lang, based, *(100 * ex[s] for s in SEPARATE),
               *(100 * ex_max[s] for s in SEPARATE), T0, lasts,
               *(100 * ex_eq[s] for s in SEPARATE), *(100 * ex_eq_max[s] for s in SEPARATE)),
            bool(ok), why,
            {"excess": ex, "target": target, "basis": basis, "max": ex_max,
             "fed_equal": ex_eq, "max_equal": ex_eq_max, "equal_lasts": lasts}))
    lo, hi = paper["dynamic"]

    def fall(base):
        ratios, spread = {}, 0.0
        for s in SEPARATE:
            r = np.stack([(sep[s][f"Fd{j}_max"] / base[f"Fd{j}_max"]).to_numpy()
                          for j in (1, 2)])
            ratios[s] = (float(r.min()), float(r.max()))
            spread = max(spread, float((r.max(axis=1) / r.min(axis=1) - 1).max()))
        return ratios, spread

    ratios, spread = fall(comb)
    ratios_eq, spread_eq = fall(equal)

    def within(rs):
        return [s for s in SEPARATE if round(rs[s][0], 1) >= lo and round(rs[s][1], 1) <= hi]

    ok, ok_old = within(ratios), within(ratios_eq)
    why = _t("c2_yes", lang, names[ok[0]], lo, hi) if ok else _t("c2_no", lang, lo, hi)
    if bool(ok_old) != bool(ok):
        why += _t("c2_old_yes" if ok_old else "c2_old_no", lang)
    out.append(Verdict("dynamic_fall", _t("c2_claim", lang, lo, hi),
                       _t("c2_model", lang, _t(f"scenario_{basis}", lang),
                          *ratios["separate_second"], *ratios["separate_first"],
                          *ratios_eq["separate_second"], *ratios_eq["separate_first"],
                          max(spread, spread_eq)), bool(ok), why,
                       {"ratios": ratios, "ratios_equal": ratios_eq,
                        "spread": max(spread, spread_eq), "basis": basis}))
    Tb = paper["effective_below"]
    Ts = comb.index.to_numpy(dtype=float)

    def longest(base, kind):
        cols = [f"F{j}_{kind}" for j in (1, 2)]
        gain = np.max([[sep[s][c] / base[c] - 1 for c in cols] for s in SEPARATE], axis=(0, 1))
        eff = Ts[gain >= effective]
        return gain, float(eff.max()) if eff.size else None

    gain, T_star = longest(comb, "fed")
    _, T_old = longest(equal, "max")
    agrees = T_star is not None and abs(T_star - Tb) <= 1.0
    static = max(float(sep[s][c].max() / comb[c].max() - 1) for s in SEPARATE
                 for c in ("Fs1_fed", "Fs2_fed"))
    gains = ", ".join(_t("gain_at", lang, 100 * float(gain[Ts == x][0]), x)
                      for x in sorted({T0, Tb, Ts[-1]}) if x in Ts)

    def when(T):
        return f"{T:g} {unit('s', lang)}" if T is not None else _t("none", lang)

    if agrees:
        why = _t("c3_yes", lang, 100 * effective, Tb)
    elif T_star == Ts[-1]:
        why = _t("c3_never", lang, 100 * effective, Ts[-1], 100 * static)
    else:
        why = _t("c3_no", lang, 100 * effective, Tb)
    out.append(Verdict("effective_below", _t("c3_claim", lang, Tb),
                       _t("c3_model", lang, based, 100 * effective, when(T_star), gains,
                          100 * static, when(T_old)), agrees, why,
                       {"T_star": T_star, "gain": dict(zip(Ts.tolist(), gain.tolist())),
                        "T_star_max_equal": T_old, "basis": basis}))
    return out


def drive_sweep(model, g=None):
    """Max |F_j| and |F_d,j| [N] of the cycles at the drive's own speeds
    (:func:`assur.dynamics.cycles.drive_cycles`), a DataFrame with columns
    ``scenario`` (``divider``, ``pump_second``, ``pump_first``), ``duration`` [s],
    ``F1_max``, ``F2_max``, ``Fd1_max``, ``Fd2_max``, and ``F1_fed``, ``F2_fed`` [N],
    the largest forces in the fed direction
    (:func:`assur.dynamics.cycles.fed_force`).

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

    from ...dynamics.cycles import cycle_forces, drive_cycles, fed_force
    cs = drive_cycles(model.drive)
    rows = []
    for (name, c), (F, Fs) in zip(cs.items(), cycle_forces(model.mechanism, list(cs.values()),
                                                            g)):
        Fd = np.abs(F - Fs).max(axis=0)
        Fm = np.abs(F).max(axis=0)
        fed = fed_force(c, F)
        rows.append(dict(scenario=name, duration=c.period, F1_max=Fm[0], F2_max=Fm[1],
                         Fd1_max=Fd[0], Fd2_max=Fd[1], F1_fed=fed[0], F2_fed=fed[1]))
    return pd.DataFrame(rows)


def pump_conclusions(dd, lang="en", paper=PAPER, about=ABOUT):
    """The paper's conclusion 3 (the standard pump with a divider against separate
    motion) against :func:`drive_sweep`'s ``dd``: two :class:`Verdict` (``pump_forces``:
    the forces in the fed direction, max |F| beside; ``pump_dynamic``: max |F_d|).

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.cycles import drive_sweep, pump_conclusions
    >>> model = io.load(io.bundled("crane_lv184a"))  # seed 004's ЛВ-184А manipulator
    >>> forces, dynamic = pump_conclusions(drive_sweep(model))
    >>> forces.key, forces.agrees, dynamic.key, dynamic.agrees
    ('pump_forces', True, 'pump_dynamic', True)
    >>> [round(x, 2) for x in forces.numbers["ratios"]["pump_second"]]  # boom, stick [-]
    [1.39, 1.3]
    >>> [round(x, 2) for x in forces.numbers["ratios_max"]["pump_second"]]  # max |F| [-]
    [1.39, 1.43]
    """
    check_lang(lang)
    d = dd.set_index("scenario")
    names = {"pump_second": "a" if lang == "en" else "а",
             "pump_first": "b" if lang == "en" else "б"}

    zero = [c for c in ("F1_fed", "F2_fed", "F1_max", "F2_max", "Fd1_max", "Fd2_max")
            if float(d.loc["divider", c]) == 0.0]
    if zero:  # a pump so slow that a force vanishes: the ratios would be 0/0
        from ...errors import ModelError
        raise ModelError(f"the work cycles: {', '.join(zero)} with the flow divider {'is' if len(zero) == 1 else 'are'} 0 N "
                         f"(its cycle takes {float(d.loc['divider', 'duration']):.6g} s), "
                         f"so the ratios of separate motion to the divider are undefined; "
                         f"check the pump's displacement, speed and eta_volumetric")

    def ratio(kind, f="F"):
        return {s: [float(d.loc[s, f"{f}{j}_{kind}"] / d.loc["divider", f"{f}{j}_{kind}"])
                    for j in (1, 2)] for s in names}

    r, rm, rd = ratio("fed"), ratio("max"), ratio("max", "Fd")
    # the ratios the verdicts print: a force of 0 with the divider (a pump so slow that
    # the dynamic parts vanish) makes one 0/0 — refused, never printed as nan
    from ...core.inputs import check_table
    check_table("cycles_conclusions (separate ÷ divider) [-]", {
        "scenario": list(names),
        **{f"{col}{j}_{kind}": [rs[s][j - 1] for s in names]
           for col, kind, rs in (("F", "fed", r), ("F", "max", rm), ("Fd", "max", rd))
           for j in (1, 2)}})
    lo, hi = paper["pump_forces"]
    target = paper["pump_dynamic"]
    times = (float(d.loc["divider", "duration"]), float(d.loc["pump_second", "duration"]))
    model = _t("c4_model", lang, *r["pump_second"], *r["pump_first"], *rm["pump_second"],
               *rm["pump_first"], *times)
    ok = [s for s in names if all(lo <= round(x, 2) <= hi for x in r[s])]
    ok_old = [s for s in names if all(lo <= round(x, 2) <= hi for x in rm[s])]
    why = _t("c4_yes", lang, names[ok[0]], lo, hi) if ok else _t("c4_no", lang, lo, hi)
    if bool(ok_old) != bool(ok):
        why += _t("c4_old_yes" if ok_old else "c4_old_no", lang)
    okd = [s for s in names if all(abs(x - target) <= about * target for x in rd[s])]
    model_d = _t("c5_model", lang, *rd["pump_second"], *rd["pump_first"], *times)
    return [Verdict("pump_forces", _t("c4_claim", lang, lo, hi), model, bool(ok), why,
                    {"ratios": r, "ratios_max": rm}),
            Verdict("pump_dynamic", _t("c5_claim", lang, target), model_d, bool(okd),
                    _t("c5_yes", lang, names[okd[0]], 100 * about, target) if okd
                    else _t("c5_no", lang, 100 * about, target), {"ratios": rd})]
