"""Throughput benchmark of ``assur`` against a plain-numpy port of seed 003.

``make bench`` runs this file. What is measured, for N = 1e3, 1e5 and 1e6
positions of the cylinder length S evenly spaced over [0.42, 0.67] m (the seed's
own range, ``S := Smin, Smin + ΔS .. Smax``, with N instead of 10 positions):

(a) the cylinder–lever group I (2,3) alone, with φ3, φ3' and φ3'':
    ``assur`` — a :class:`assur.Mechanism` with frame points 01, 03, one
    ``cylinder_lever(..., branch=-1)`` and ``link("3", "03", "23")``, solved with
    ``outputs=["3"]`` — against the seed's closed forms φ3(S), dφ3(S) and the
    analytic φ3''(S) in numpy (``seed003_numpy.lever_phi3``).
(b) the whole seed-003 hitch: ``examples.hitch_003().solve(S)`` (all 10 points, all
    7 links, first *and* second analogs; once with the default continuity check and
    once with ``check_continuity=False``) against the seed's §2–§3 pipeline in numpy
    (``seed003_numpy.hitch``: all angles, all point coordinates, U43, U53, U65, U75,
    dφ3, φ41…φ71, I56, IS6 — first order only, because the seed has no second order).

(c) the full seed-003 pipeline (issue 3): ``examples.hitch_003().analyze(S)`` and
    then every value the numpy peer computes — §2–§3 as in (b), §4 cylinder force,
    pressure, capacity("56"), capacity("S6"), reserve("S6", P6), §5 the reactions
    the seed tabulates (R56, R07, R23, R05, R34, R45, R03, R01, plus its R67) with
    their magnitudes and the actuator force from the reactions, §6 axle reactions
    A, B, their shares, max_implement_weight and the seed's GS6max — against
    ``seed003_numpy.pipeline``: the seed's §2–§6 formulas as printed, in numpy.

For each line: the best time of several repetitions (≥ 5, ≥ 20 at N ≤ 1e3; more
until about a second has been spent) after a warm-up call, as positions per second, for
``assur`` and for the numpy peer, and their ratio. The two are timed interleaved in
the same process, so the ratio is what carries over between machines. The first
(cold) calls — numba loading its cache or compiling — are reported separately as
"start-up". The targets of the issues ((a) ≥ 1e8, (b) ≥ 2e7, (c) ≥ 1e7 positions/s
on the 2-core machine) are printed next to the figures.

Before any figure is trusted, the benchmark checks that ``assur`` and the numpy
peer agree on every compared quantity (e.g. max |Δφ3| < 1e-9 rad, max |ΔIS6| <
1e-9), and that the φ3'' formula matches a finite difference of φ3'. For (c) the
forces are compared relative to the largest |value| of each quantity (< 1e-9), the
seed's sign of R05, R34, R45 applied (the sign map of ``hitch_003.toml``); where
the printed formulas lose digits by cancellation (R56y at X67 = X56, i.e. at S = Sp)
the same formulas are re-evaluated in long double at those positions and assur is
judged against that, both figures printed. The peer is also checked against the
seed's tables 4.1, 5.1 and 6.1 at the printed precision on the seed's 10 positions.
These are printed checks of the benchmark, not tests.

These figures are ratios to a peer measured in the same process, for people to
read. Nothing here is — and no test should ever be — a timed assertion: the test
suite checks correctness only.

Usage: ``python benchmarks/run.py [--sizes 1e3,1e5,1e6] [--budget 1.0]``
"""

from __future__ import annotations

import argparse
import gc
import glob
import importlib.util
import math
import os
import platform
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seed003_numpy as peer  # noqa: E402  (plain numpy, does not import assur)

S_MIN, S_MAX = 0.42, 0.67
TARGET_A = 1e8  # positions/s, issue target for the cylinder–lever group alone
TARGET_B = 2e7  # positions/s, issue target for the whole hitch with analogs
TARGET_C = 1e7  # positions/s, issue 3 target for the full pipeline (analyze + all values)
TARGET_D = 1e7  # designs·positions/s, issue 7: reduced over positions in the kernel (same
                # order as (c); the issue names no number)
TARGET_SOLVE1, TARGET_ANALYZE1 = 20e-6, 50e-6  # s, issue 7: one position
TOL = 1e-9      # agreement: max |Δ| < TOL for every compared quantity (absolute)
TOL_REL = 1e-9  # (c) agreement: max |Δ| / max |peer| < TOL_REL for every quantity
HERE = os.path.dirname(os.path.abspath(__file__))

#: (c) the reactions seed 003 tabulates: seed name, assur pair (force of i on j) and
#: the sign of the seed's printed components relative to it ([[tables.signs]] of
#: hitch_003.toml);
#: R67 is computed by the seed (§5.1) but not tabulated
SEED_REACTIONS = (("R56", "5", "6", 1), ("R07", "0", "7", 1), ("R23", "2", "3", 1),
                  ("R05", "0", "5", -1), ("R34", "3", "4", -1), ("R45", "4", "5", -1),
                  ("R03", "0", "3", 1), ("R01", "0", "2", 1))
EXTRA_REACTIONS = (("R67", "6", "7", 1),)



# ---- timing ------------------------------------------------------------------------
def time_interleaved(funcs, min_reps, budget, max_reps=2000):
    """Best wall time of each callable, run interleaved (a, b, c, a, b, c, ...).

    Repeats at least ``min_reps`` times and until every callable has spent
    ``budget`` seconds in total (at most ``max_reps``). The garbage collector is
    off while timing. Returns (best times, repetitions, last results).
    """
    best = {k: math.inf for k in funcs}
    spent = {k: 0.0 for k in funcs}
    last = {}
    reps = 0
    gc.collect()
    gc.disable()
    try:
        while reps < min_reps or (min(spent.values()) < budget and reps < max_reps):
            for k, f in funcs.items():
                last.pop(k, None)  # free the previous result before the next call
                t0 = time.perf_counter()
                last[k] = f()
                dt = time.perf_counter() - t0
                best[k] = min(best[k], dt)
                spent[k] += dt
            reps += 1
    finally:
        gc.enable()
    return best, reps, last


def min_reps_for(n):
    return 20 if n <= 1e3 else 5


# ---- assur side ----------------------------------------------------------------------
def lever_mechanism(assur, p):
    """Group I (2,3) of seed 003 alone: frame 01, 03, cylinder 01–23, lever 03–23."""
    keys = ("X01", "Y01", "X03", "Y03", "L3")
    return (assur.Mechanism("lever_003", coordinates=("S",), params={k: p[k] for k in keys},
                            title="Seed 003 group I (2,3)")
            .frame("01", "X01", "Y01").frame("03", "X03", "Y03")
            .cylinder_lever("I (2,3)", base="01", pivot="03", out="23", lever="L3", s="S",
                            branch=-1, links=("2", "3"))
            .link("3", "03", "23"))


def solve_lever(mech, S):
    r = mech.solve(S, outputs=["3"])
    return r.phi("3"), r.dphi("3"), r.ddphi("3")


# ---- agreement -----------------------------------------------------------------------
def wrap(a):
    """Angle difference mapped to (−π, π] (assur unwraps along the positions)."""
    return (a + math.pi) % (2.0 * math.pi) - math.pi


class Check:
    """Collects max |Δ| per quantity and whether it is within tolerance."""

    def __init__(self):
        self.rows = []  # (label, max|Δ|, tolerance, ok)

    def add(self, label, a, b, angle=False):
        a = np.asarray(a, dtype=float)
        b = np.asarray(b, dtype=float)
        d = np.abs(wrap(a - b) if angle else a - b)
        dmax = float(np.max(d)) if d.size else 0.0
        tol = TOL
        ok = bool(np.all(np.isfinite(a))) and bool(np.all(np.isfinite(b))) and dmax < tol
        self.rows.append((label, dmax, tol, ok))

    def group(self, label, pairs, angle=False):
        """Several quantities reported as one line (the worst of them)."""
        c = Check()
        for name, a, b in pairs:
            c.add(name, a, b, angle)
        name, dmax, tol, _ = max(c.rows, key=lambda r: (not r[3], r[1] / r[2]))
        self.rows.append((f"{label}, worst {name}", dmax, tol, c.ok))

    @property
    def ok(self):
        return all(r[3] for r in self.rows)


def check_lever(res, ref):
    c = Check()
    c.add("φ3 [rad]", res[0], ref[0], angle=True)
    c.add("φ3' [rad/m]", res[1], ref[1])
    c.add("φ3'' [rad/m²]", res[2], ref[2])
    return c


def check_hitch(r, g):
    c = Check()
    c.group("angles φ2 φ3 φ34 φ4 φ5 φ6 φ7 [rad]",
            [(f"φ{k}", r.phi(k), g[f"phi{'12' if k == '2' else k}"])
             for k in ("2", "3", "34", "4", "5", "6", "7")], angle=True)
    c.group("points X, Y of 23 34 45 56 67 S6 [m]",
            [(f"{ax}{p}", getattr(r, ax.lower())(p), g[f"{ax}{p}"])
             for p in ("23", "34", "45", "56", "67", "S6") for ax in ("X", "Y")])
    c.group("U43 U53 U65 U75 [-]",
            [(f"U{i}{j}", r.ratio(i, j), g[f"U{i}{j}"])
             for i, j in (("4", "3"), ("5", "3"), ("6", "5"), ("7", "5"))])
    c.group("dφ3, φ41 φ51 φ61 φ71 [rad/m]",
            [(f"dφ{k}", r.dphi(k), g[f"dphi{k}"]) for k in ("3", "4", "5", "6", "7")])
    c.add("I56 [m/m]", r.transmission("56"), g["I56"])
    c.add("IS6 [m/m]", r.transmission("S6"), g["IS6"])
    return c


def fd_check_ddphi3():
    """φ3'' (seed 001 lab 5 form) against a central difference of φ3' (seed 003)."""
    h = 1e-6
    S = np.linspace(S_MIN + h, S_MAX - h, 1001)
    _, d, dd = peer.lever_phi3(S)
    fd = (peer.lever_phi3(S + h)[1] - peer.lever_phi3(S - h)[1]) / (2 * h)
    fd1 = (peer.lever_phi3(S + h)[0] - peer.lever_phi3(S - h)[0]) / (2 * h)
    return (float(np.max(np.abs(fd - dd) / np.max(np.abs(dd)))),
            float(np.max(np.abs(fd1 - d) / np.max(np.abs(d)))))


# ---- (c) the full pipeline ------------------------------------------------------------
KIN_PHI = ("2", "3", "34", "4", "5", "6", "7")
KIN_POINTS = ("23", "34", "45", "56", "67", "S6")
KIN_RATIOS = (("4", "3"), ("5", "3"), ("6", "5"), ("7", "5"))


def where_b(mech, n, budget):
    """Where (b)'s time goes at N = n: the generated kernel alone writing into outputs
    allocated once (no continuity check, no unwrap), against filling fresh memory of
    the same size (the first touch of each page, which the OS zeroes) — the part of a
    fresh result that no kernel can avoid."""
    from assur.kernel import run as KR
    from assur.core.program import execute

    prog = mech.program()
    ptab, trig, _ = mech.prepared(prog)
    q = np.ascontiguousarray(np.linspace(S_MIN, S_MAX, n)[None, :])
    raw = execute(prog, ptab, q, n)               # the outputs' layout, and a warm-up
    out, status, amount = np.empty_like(raw["out"]), np.empty(n, np.int64), np.empty(n)
    kern = prog.kernel()
    funcs = {"kernel": lambda: KR.run(kern, ptab, trig, q, n, False, out, amount, status),
             "fill": lambda: np.empty_like(out).fill(0.0)}
    best, _, _ = time_interleaved(funcs, min_reps_for(n), 0.5 * budget)
    print(f"    where the time goes at N={fmt_n(n)}: the kernel alone into outputs allocated "
          f"once {best['kernel'] * 1e3:.1f} ms ({rate(n, best['kernel']):.3e} positions/s); "
          f"filling fresh memory of the result's size ({out.nbytes / n:.0f} B/position) "
          f"{best['fill'] * 1e3:.1f} ms (the OS zeroes each new page on first touch)")


def assur_pipeline(mech, S, P6):
    """``mech.analyze(S)``, then every value ``seed003_numpy.pipeline`` computes, read
    through the public API (this is what is timed). Keys follow the peer's names;
    reactions are kept as assur gives them (force of i on j, shape (n, 2))."""
    a = mech.analyze(S)
    kin, st, cyl, stab = a.kinematics, a.statics, a.cylinder("ГЦ"), a.stability
    v = {}
    # §2–§3
    for k in KIN_PHI:
        v[f"phi{'12' if k == '2' else k}"] = kin.phi(k)
    for pt in KIN_POINTS:
        v[f"X{pt}"] = kin.x(pt)
        v[f"Y{pt}"] = kin.y(pt)
    for i, j in KIN_RATIOS:
        v[f"U{i}{j}"] = kin.ratio(i, j)
    for k in ("3", "4", "5", "6", "7"):
        v[f"dphi{k}"] = kin.dphi(k)
    v["I56"] = kin.transmission("56")
    v["IS6"] = kin.transmission("S6")
    # §4
    v["Fgc"] = cyl.force
    v["Pgc"] = cyl.pressure
    v["G56"] = cyl.capacity("56")
    v["GS6"] = cyl.capacity("S6")
    v["dGS65"] = cyl.reserve("S6", P6)
    # §5
    for name, i, j, _ in SEED_REACTIONS + EXTRA_REACTIONS:
        r = st.reaction(i, j)
        v[name + "_ij"] = r
        v[name] = np.hypot(r[:, 0], r[:, 1])
    v["Fgc_R"] = st.actuator_force_from_reactions("S")
    # §6
    v["Ra"] = stab.reaction("A")
    v["Rb"] = stab.reaction("B")
    v["dRa"] = stab.share("A")
    v["dRb"] = stab.share("B")
    v["Gmax"] = stab.max_implement_weight
    v["GS6max"] = a.formula("GS6max")
    return v


#: the values of (c) that the fused kernel computes (§4–§6, without §2–§3)
FUSED_KEYS = ("Fgc", "Pgc", "G56", "GS6", "dGS65", "Fgc_R", "Ra", "Rb", "dRa", "dRb")


def fused_outputs():
    """The outputs of the fused pipeline (c'): §4 force, pressure, capacities, reserve;
    §5 the tabulated reactions and the force from them; X(S6) for §6."""
    outs = ["F(S)", "p(ГЦ)", "G(ГЦ, 56)", "G(ГЦ, S6)", "reserve(ГЦ, S6, P6)", "Fr(S)",
            "X(S6)"]
    for _, i, j, _ in SEED_REACTIONS + EXTRA_REACTIONS:
        outs += [f"Rx({i}, {j})", f"Ry({i}, {j})"]
    return outs


def fused_pipeline(mech, S, outs, stability):
    """(c'): ``mech.evaluate(S, outputs=…)`` — one fused kernel writes only these
    values — then the axle reactions from X(S6) (``assur.machines.stability.axle_reactions``)."""
    f = mech.evaluate(S, outputs=outs)
    machine, weight = stability
    st = stability_module().axle_reactions(machine, weight, f["X(S6)"])
    v = {"Fgc": f["F(S)"], "Pgc": f["p(ГЦ)"], "G56": f["G(ГЦ, 56)"], "GS6": f["G(ГЦ, S6)"],
         "dGS65": f["reserve(ГЦ, S6, P6)"], "Fgc_R": f["Fr(S)"]}
    for name, i, j, _ in SEED_REACTIONS + EXTRA_REACTIONS:
        v[name + "_ij"] = np.stack([f[f"Rx({i}, {j})"], f[f"Ry({i}, {j})"]], -1)
    v.update(Ra=st.reaction("A"), Rb=st.reaction("B"), dRa=st.share("A"), dRb=st.share("B"))
    return v


def stability_module():
    from assur.machines import stability
    return stability


def check_fused(vf, va):
    """Worst relative difference of (c') against the array pipeline (c) per value."""
    rows = []
    keys = list(FUSED_KEYS) + [n + "_ij" for n, *_ in SEED_REACTIONS + EXTRA_REACTIONS]
    for k in keys:
        a, b = np.asarray(vf[k], float), np.asarray(va[k], float)
        d = float(np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300))
        rows.append((k, d, bool(np.all(np.isfinite(a))) and d < TOL_REL))
    return rows


def pipeline_pairs(v):
    """(label, group, assur array, peer key) for every compared quantity of (c)."""
    out = [(k, "§4 Fgc Pgc G56 GS6 ΔGS65", v[k], k) for k in ("Fgc", "Pgc", "G56", "GS6",
                                                                "dGS65")]
    for name, _, _, sign in SEED_REACTIONS + EXTRA_REACTIONS:
        r = v[name + "_ij"]
        grp = "§5 R…x, R…y (seed sign) of R56 R07 R67 R23 R05 R34 R45 R03 R01"
        out.append((f"{name}x", grp, sign * r[:, 0], f"{name}x"))
        out.append((f"{name}y", grp, sign * r[:, 1], f"{name}y"))
        out.append((name, "§5 |R| of R56 R07 R67 R23 R05 R34 R45 R03 R01", v[name], name))
    out.append(("Fgc", "§5 Fgc = |R23|: actuator_force_from_reactions", v["Fgc_R"], "R23"))
    out += [(k, "§6 Ra Rb ΔRa ΔRb GS6max", v[k], k) for k in ("Ra", "Rb", "dRa", "dRb",
                                                             "GS6max")]
    out.append(("Gmax", "§6 max_implement_weight (not in the seed)", v["Gmax"], "Gmax"))
    return out


def check_pipeline(v, g, S):
    """Relative agreement of (c), one row per group: (label, max rel Δ vs the float64
    peer, note, ok). Positions where the float64 peer differs by ≥ TOL_REL are
    re-evaluated with the peer's formulas in long double and judged against that."""
    rows = []
    kin = check_hitch_values(v, g)
    name, dmax, _, ok = max(kin.rows, key=lambda r: (not r[3], r[1]))
    rows.append(("§2–§3 angles, points, U, analogs, I56, IS6 (absolute)", name, dmax, "", ok))
    pairs = pipeline_pairs(v)
    rel = {}
    bad = np.zeros(len(S), dtype=bool)
    for label, grp, a, key in pairs:
        b = g[key]
        scale = float(np.max(np.abs(b)))
        d = np.abs(np.asarray(a, float) - b) / scale
        rel[(label, grp)] = (d, scale)
        bad |= ~(d < TOL_REL)
    idx = np.flatnonzero(bad)
    gl = peer.pipeline(S[idx].astype(np.longdouble)) if idx.size else None
    groups = {}
    for label, grp, a, key in pairs:
        d, scale = rel[(label, grp)]
        dmax = float(np.max(d))
        finite = bool(np.all(np.isfinite(a))) and bool(np.all(np.isfinite(g[key])))
        note, ok = "", finite and dmax < TOL_REL
        if finite and not ok:
            dl = float(np.max(np.abs(np.asarray(a, float)[idx] - gl[key]) / scale))
            dp = float(np.max(np.abs(g[key][idx] - gl[key]) / scale))
            ok = dl < TOL_REL
            d1 = float(np.max(np.abs(g["X67"][idx] - g["X56"][idx])))
            where = (f"1 position, S = {S[idx[0]]:.7f} m" if idx.size == 1 else
                     f"{idx.size} positions, S in [{S[idx].min():.7f}, {S[idx].max():.7f}] m")
            note = (f"{where}, |X67 − X56| ≤ {d1:.1e} m: assur vs the peer in long double "
                    f"{dl:.1e}, float64 peer vs long double {dp:.1e}")
        groups.setdefault(grp, []).append((label, dmax, note, ok))
    for grp, items in groups.items():
        label, dmax, note, _ = max(items, key=lambda r: r[1])
        rows.append((grp, label, dmax, note, all(r[3] for r in items)))
    return rows, idx


def check_hitch_values(v, g):
    """As :func:`check_hitch`, on the values read by :func:`assur_pipeline`."""
    c = Check()
    c.group("angles", [(k, v[k], g[k]) for k in v if k.startswith("phi")], angle=True)
    c.group("points", [(f"{ax}{p}", v[f"{ax}{p}"], g[f"{ax}{p}"])
                       for p in KIN_POINTS for ax in ("X", "Y")])
    c.group("ratios", [(f"U{i}{j}", v[f"U{i}{j}"], g[f"U{i}{j}"]) for i, j in KIN_RATIOS])
    c.group("analogs", [(f"dφ{k}", v[f"dphi{k}"], g[f"dphi{k}"])
                        for k in ("3", "4", "5", "6", "7")])
    c.add("I56", v["I56"], g["I56"])
    c.add("IS6", v["IS6"], g["IS6"])
    c.rows = [(lab.split("worst ")[-1], d, t, ok) for lab, d, t, ok in c.rows]
    return c


def load_seed_tables():
    """tests/helpers/seed_tables.py by path (tables 4.1, 5.1, 6.1 and the helpers table,
    decimals)."""
    path = os.path.join(HERE, os.pardir, "tests", "helpers", "seed_tables.py")
    spec = importlib.util.spec_from_file_location("seed_tables_bench", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def check_peer_tables():
    """The numpy peer on the seed's 10 positions against tables 4.1, 5.1, 6.1 at the
    printed precision: per table (name, columns, worst |Δ|/(½·10^−d), column, ok)."""
    st = load_seed_tables()
    S = np.linspace(S_MIN, S_MAX, 10)  # seed §1.3: S := Smin, Smin + ΔS .. Smax
    g = peer.pipeline(S)
    out = []
    for name, text in (("4.1", st.T003_4_1), ("5.1", st.T003_5_1), ("6.1", st.T003_6_1)):
        t, dec = st.table(text), st.decimals(text)
        if not np.allclose(np.round(S, 3), t["S"]):
            out.append((name, 0, math.inf, "S", False))
            continue
        worst, col = 0.0, ""
        cols = [c for c in t if c != "S"]
        for c in cols:
            key = "R23" if (name == "5.1" and c == "Fgc") else c  # table 5.1: Fgc = R23
            half = 0.5 * 10.0 ** (-dec[c])
            w = float(np.max(np.abs(g[key] - t[c]))) / half
            if w > worst:
                worst, col = w, c
        out.append((name, len(cols), worst, col, worst <= 1.0 + 1e-9))
    return out


# ---- start-up --------------------------------------------------------------------------
def cache_dirs(pkg_dir):
    """Directories where numba may keep assur's compiled kernels."""
    dirs = [pkg_dir]
    from assur.kernel import cache_dir  # generated kernels live outside the package
    dirs.append(str(cache_dir()))
    if os.environ.get("NUMBA_CACHE_DIR"):
        dirs.append(os.environ["NUMBA_CACHE_DIR"])
    return dirs


def cache_snapshot(dirs):
    """Numba cache files (index and data) with their modification times."""
    snap = {}
    for d in dirs:
        for f in glob.glob(os.path.join(d, "**", "*.nb[ic]"), recursive=True):
            try:
                snap[f] = os.path.getmtime(f)
            except OSError:
                pass
    return snap


def cold(f, dirs):
    """Time one cold call; say whether numba compiled (wrote cache files) or loaded."""
    before = cache_snapshot(dirs)
    t0 = time.perf_counter()
    f()
    dt = time.perf_counter() - t0
    after = cache_snapshot(dirs)
    k = sum(1 for p, t in after.items() if before.get(p) != t)
    return dt, (f"numba compiled: {k} cache files written" if k else
                "nothing compiled: numba cache loaded")


# ---- printing -------------------------------------------------------------------------
def fmt_n(n):
    e = int(round(math.log10(n)))
    return f"1e{e}" if 10 ** e == n else f"{n:g}"


def rate(n, t):
    return n / t if t > 0 else math.inf


HEAD = (f"  {'N':>5}  {'variant':<33} {'reps':>4}  {'assur ms':>9} {'assur pos/s':>11}  "
        f"{'numpy ms':>9} {'numpy pos/s':>11}  {'assur/numpy':>11}  {'target':>7}  {'met':>3}")


def line(n, variant, reps, ta, tn, target):
    ra, rn = rate(n, ta), rate(n, tn)
    return (f"  {fmt_n(n):>5}  {variant:<33} {reps:>4}  {ta * 1e3:>9.3f} {ra:>11.3e}  "
            f"{tn * 1e3:>9.3f} {rn:>11.3e}  {ra / rn:>10.2f}x  {target:>7.0e}  "
            f"{'yes' if ra >= target else 'no':>3}")


def print_checks(title, checks):
    print(f"  agreement assur vs numpy peer ({title}); pass if max|Δ| < {TOL:g} (absolute)")
    for n, c in checks:
        for label, dmax, tol, ok in c.rows:
            print(f"    N={fmt_n(n):>4}  {label:<52} max|Δ| = {dmax:9.2e}  "
                  f"{'ok' if ok else 'MISMATCH'}")


TARGET_CHECK = 0.5  # s, issue 7: a warm `assur check` of a bundled model
#: modules a check of a bundled model should not import (each costs 0.1–0.6 s)
HEAVY = ("numba", "pint", "scipy", "matplotlib", "pandas", "jinja2", "openpyxl")
_CHECK_MODULES = """
import sys
from assur.views.cli import app
sys.argv = ["assur", "check", sys.argv[1]]
try:
    app()
except SystemExit:
    pass
print(" ".join(m for m in {heavy!r} if m in sys.modules) or "none", file=sys.stderr)
"""


def run_child(cmd, env):
    """Wall and CPU (user + system) seconds of one child process; its exit status."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    err = p.stderr.read().decode()
    p.stderr.close()
    return wall, ru.ru_utime + ru.ru_stime, os.waitstatus_to_exitcode(status), err


def startup_section(reps):
    """Warm `assur check` of a bundled model and the CLI's import, each in fresh
    processes (hyperfine-like: one warm-up run, then the best and median of ``reps``)."""
    from assur import io
    model = str(io.bundled("hitch_003"))
    # as a user's shell runs it: Python caches bytecode (this session may have set
    # PYTHONDONTWRITEBYTECODE, which makes every import compile its module again)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    cmds = {"assur check hitch_003.toml": [sys.executable, "-m", "assur", "check", model],
            "python -c 'import assur.views.cli'": [sys.executable, "-c", "import assur.views.cli"],
            "python -c 'import assur'": [sys.executable, "-c", "import assur"],
            "python -c 'import numpy' (floor)": [sys.executable, "-c", "import numpy"]}
    print(f"command start-up (fresh processes: one warm-up run, then best / median of {reps}; "
          f"wall and CPU = user + system)")
    for label, cmd in cmds.items():
        code, _ = run_child(cmd, env)[2:]
        if code != 0:
            print(f"    {label:<34} FAILED (exit {code})")
            continue
        runs = sorted(run_child(cmd, env)[:2] for _ in range(reps))
        walls = [r[0] for r in runs]
        cpus = sorted(r[1] for r in runs)
        tail = ""
        if label.startswith("assur check"):
            tail = (f"   target ≤ {TARGET_CHECK:.1f} s  "
                    f"{'yes' if walls[0] <= TARGET_CHECK else 'no'}")
        print(f"    {label:<34} best {walls[0]:6.3f} s  median {walls[len(walls) // 2]:6.3f} s"
              f"  CPU {cpus[0]:6.3f} s{tail}")
    err = run_child([sys.executable, "-c", _CHECK_MODULES.format(heavy=HEAVY), model], env)[3]
    print(f"    heavy modules a check imports ({', '.join(HEAVY)}): "
          f"{err.strip().splitlines()[-1] if err.strip() else '?'}")


def compile_section(sizes):
    """Cold compile time of the kinematics kernel against the number of groups (issue
    7), one fresh process and kernel cache per structure (``compile_time.py``)."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import compile_time

    from assur.kernel import compose

    print("compile time: first solve of a new structure, cold caches, one process each")
    print("  rigid: examples.hitch_003() (10 groups) + rigid points; chain: cylinder–lever "
          "+ RRR dyads, each with its own frame point")
    print(f"  fused kernel up to {compose.THRESHOLD} groups + measures, composed above "
          f"(assur.kernel.compose); 'lines' = lines of the fused source")
    compile_time.table(sizes=tuple(sizes), out=lambda s: print("  " + s, flush=True))


def spread_section(procs, budget):
    """The same calls in ``procs`` fresh processes: min, median, max over the processes
    of each process's best time (issue 7: no 2x jumps between processes;
    ``spread.py``)."""
    import spread

    print(f"spread between processes: the best time of each call in each of {procs} fresh "
          "processes (spread.py)")
    worst = spread.table(procs, budget, out=lambda s: print("  " + s, flush=True))
    print(f"  largest max/min {worst:.2f}x (issue 7: below 2x; on a shared machine other "
          "work moves single figures too)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default="1e3,1e5,1e6",
                    help="comma-separated numbers of positions (default 1e3,1e5,1e6)")
    ap.add_argument("--budget", type=float, default=1.0,
                    help="seconds to spend per callable and size before stopping repeats")
    ap.add_argument("--spread-procs", type=int, default=5,
                    help="fresh processes of the spread section (default 5; 0: skip it)")
    ap.add_argument("--startup-reps", type=int, default=7,
                    help="fresh processes of the command start-up section (default 7; 0: "
                         "skip it)")
    ap.add_argument("--compile-sizes", default="5,10,20,50,100,200",
                    help="group counts of the compile-time section (default "
                         "5,10,20,50,100,200; empty: skip it)")
    args = ap.parse_args(argv)
    sizes = [int(float(s)) for s in args.sizes.split(",")]

    # ---- start-up: import and first (cold) calls ------------------------------------
    spec = importlib.util.find_spec("assur")
    pkg_dir = os.path.dirname(spec.origin)
    t0 = time.perf_counter()
    import numba

    import assur
    from assur import examples
    t_import = time.perf_counter() - t0

    lever = lever_mechanism(assur, peer.PARAMS)
    hitch = examples.hitch_003()
    hp = dict(hitch.params)
    # the model solves L4, Sp, L7 from the seed's Find conditions (the exact roots agree
    # with the 9-digit values to 1e-9): the peer evaluates the seed's formulas at the
    # model's solved lengths, so both compute the same mechanism
    for k in ("L4", "Sp", "L7"):
        assert abs(float(hp[k]) - peer.PARAMS[k]) < 1e-9, k
        peer.PARAMS[k] = float(hp[k])
    peer_all = {**peer.PARAMS, **peer.LOAD}
    same = set(peer_all) <= set(hp) and \
        all(abs(float(hp[k]) - v) <= 1e-12 for k, v in peer_all.items())
    signs = {n: (i, j, sg) for n, i, j, sg in SEED_REACTIONS}
    S0 = np.linspace(S_MIN, S_MAX, 1000)
    dirs = cache_dirs(pkg_dir)
    t_cold_a, how_a = cold(lambda: solve_lever(lever, S0), dirs)
    t_cold_b, how_b = cold(lambda: hitch.solve(S0), dirs)
    t0 = time.perf_counter()
    peer.hitch(S0)
    t_cold_np = time.perf_counter() - t0
    t_cold_c, how_c = cold(lambda: assur_pipeline(hitch, S0, peer.LOAD["P6"]), dirs)
    from assur.core.columns import column_signs
    printed = column_signs(hitch)
    same_signs = hitch.analyze(S0[:2]).statics.named_reactions() == \
        {n: (i, j) for n, (i, j, _) in signs.items()} and \
        all(printed.get(f"{n}{c}", 1) == sg for n, (_, _, sg) in signs.items() for c in "xy")

    print("assur benchmark — positions per second, assur vs a plain-numpy port of seed 003")
    print(f"  python {platform.python_version()}, numpy {np.__version__}, numba "
          f"{numba.__version__}, assur {getattr(assur, '__version__', '?')}")
    try:
        layer = numba.threading_layer()
    except ValueError:  # no numba-parallel code has run in this process
        layer = "not started"
    try:
        affinity = len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not on Linux
        affinity = os.cpu_count()
    print(f"  machine: {platform.machine()}, os.cpu_count() = {os.cpu_count()}, usable CPUs = "
          f"{affinity}; numba threads = {numba.get_num_threads()} (NUMBA_NUM_THREADS = "
          f"{numba.config.NUMBA_NUM_THREADS}, threading layer {layer})")
    print(f"  S evenly spaced over [{S_MIN}, {S_MAX}] m; best of the repetitions after a "
          f"warm-up call; assur and numpy timed interleaved in this process")
    print(f"  seed003_numpy.PARAMS + LOAD == the parameters of examples.hitch_003(): "
          f"{'yes' if same else 'NO'}")
    print(f"  hitch_003 seed reaction names and printed signs == this benchmark's "
          f"(R05, R34, R45 printed with sign −1, [[tables.signs]]): "
          f"{'yes' if same_signs else 'NO'}")
    print()
    print("start-up (cold first calls in this process, not part of the figures below)")
    print(f"  import assur (+ numba)                             {t_import:8.3f} s")
    print(f"  first solve, group (a), N=1e3                      {t_cold_a:8.3f} s   ({how_a})")
    print(f"  first solve, hitch_003 (b), N=1e3                  {t_cold_b:8.3f} s   ({how_b})")
    print(f"  first call, numpy peer (b), N=1e3                  {t_cold_np:8.3f} s")
    print(f"  first analyze + values, hitch_003 (c), N=1e3       {t_cold_c:8.3f} s   ({how_c})")
    print()

    ok_all = True

    # ---- (a) the cylinder–lever group alone -----------------------------------------
    print("(a) cylinder–lever group I (2,3) alone: φ3, φ3', φ3''")
    print("    assur: Mechanism(frame 01, 03; cylinder_lever branch=-1; link 3)"
          ".solve(S, outputs=['3'])")
    print("    numpy: φ3 = acos((L3²+L13²−S²)/(2·L3·L13)) − φ13, φ3' = dφ3(S) (seed 003 §3.1),")
    print("           φ3'' = 2·[S⁴ − (L3² − L13²)²]/(4·L13²·L3² − [S² − (L13² + L3²)]²)^(3/2)")
    fd2, fd1 = fd_check_ddphi3()
    ok_fd = fd2 < 1e-6 and fd1 < 1e-6
    ok_all &= ok_fd
    print(f"    check of the closed forms: φ3' vs central difference of φ3: max rel. err "
          f"{fd1:.1e}; φ3'' vs central difference of φ3': {fd2:.1e} "
          f"({'ok' if ok_fd else 'WRONG FORMULA'})")
    print(HEAD)
    checks = []
    for n in sizes:
        S = np.linspace(S_MIN, S_MAX, n)
        funcs = {"assur": lambda: solve_lever(lever, S), "numpy": lambda: peer.lever_phi3(S)}
        for f in funcs.values():  # warm-up at this size
            f()
        best, reps, last = time_interleaved(funcs, min_reps_for(n), args.budget)
        print(line(n, "solve(S, outputs=['3'])", reps, best["assur"], best["numpy"], TARGET_A))
        checks.append((n, check_lever(last["assur"], last["numpy"])))
        del last
    print_checks("φ3, φ3', φ3''", checks)
    ok_all &= all(c.ok for _, c in checks)
    print()

    # ---- (b) the whole hitch ---------------------------------------------------------
    print("(b) whole seed-003 hitch: examples.hitch_003().solve(S) vs the seed's §2–§3 in numpy")
    print("    assur: 10 points, 7 links, positions + first + second analogs (all outputs)")
    print("    numpy: all angles and points, U43 U53 U65 U75, dφ3, φ41…φ71, I56, IS6 — first "
          "order only:")
    print("           the seed has no second-order analogs, so assur does more work per position")
    print(HEAD)
    checks = []
    for n in sizes:
        S = np.linspace(S_MIN, S_MAX, n)
        earlier = hitch.solve(S)
        funcs = {"cc": lambda: hitch.solve(S),
                 "nocc": lambda: hitch.solve(S, check_continuity=False),
                 "out": lambda: hitch.solve(S, out=earlier),
                 "numpy": lambda: peer.hitch(S)}
        for f in funcs.values():
            f()
        best, reps, last = time_interleaved(funcs, min_reps_for(n), args.budget)
        print(line(n, "solve(S)", reps, best["cc"], best["numpy"], TARGET_B))
        print(line(n, "solve(S, check_continuity=False)", reps, best["nocc"], best["numpy"],
                   TARGET_B))
        print(line(n, "solve(S, out=earlier result)", reps, best["out"], best["numpy"],
                   TARGET_B))
        checks.append((n, check_hitch(last["cc"], last["numpy"])))
        checks.append((n, check_hitch(last["out"], last["numpy"])))
        del last, earlier
    print_checks("hitch_003", checks)
    where_b(hitch, sizes[-1], args.budget)
    ok_all &= all(c.ok for _, c in checks)
    print()

    # ---- (c) the full pipeline -------------------------------------------------------
    P6 = peer.LOAD["P6"]
    print("(c) full seed-003 pipeline §2–§6: positions, analogs, cylinder force/pressure/lift "
          "capacity, joint reactions, stability")
    print("    assur: a = examples.hitch_003().analyze(S), then every value below read from a "
          "(what is timed):")
    print("           §2–§3 as in (b); a.cylinder('ГЦ').force, .pressure, .capacity('56'), "
          ".capacity('S6'), .reserve('S6', P6);")
    print("           a.statics.reaction(i, j) and |R| for R56 R07 R67 R23 R05 R34 R45 R03 R01, "
          ".actuator_force_from_reactions('S');")
    print("           a.stability.reaction('A'/'B'), .share('A'/'B'), .max_implement_weight, "
          "a.formula('GS6max')")
    print("    numpy: seed003_numpy.pipeline — the seed's §2–§6 formulas as printed (§5.1–5.3 "
          "closed forms), + the 20 % limit")
    print("    for reference (not measured here): an independent plain-numpy implementation "
          "≈ 4e5 positions/s, Exudyn ≈ 1e4 positions/s")
    tabs = check_peer_tables()
    ok_tab = all(t[4] for t in tabs)
    ok_all &= ok_tab
    print("    numpy peer vs the seed's printed tables on its 10 positions (pass if every "
          "|Δ| ≤ ½ unit of the last printed digit):")
    for name, ncol, worst, col, ok in tabs:
        print(f"      table {name}: {ncol:>2} columns × 10 rows, worst |Δ| = {worst:.2f} "
              f"half-units ({col})  {'ok' if ok else 'MISMATCH'}")
    print(HEAD)
    checks = []
    for n in sizes:
        S = np.linspace(S_MIN, S_MAX, n)
        funcs = {"full": lambda: assur_pipeline(hitch, S, P6),
                 "numpy": lambda: peer.pipeline(S)}
        for f in funcs.values():
            f()
        best, reps, last = time_interleaved(funcs, min_reps_for(n), args.budget)
        print(line(n, "analyze(S) + all values", reps, best["full"], best["numpy"], TARGET_C))
        checks.append((n, check_pipeline(last["full"], last["numpy"], S)))
        del last
    print(f"  agreement assur vs numpy peer (full pipeline); pass if max|Δ|/max|peer| < "
          f"{TOL_REL:g} per quantity (§2–§3: max|Δ| < {TOL:g})")
    for n, (rows, idx) in checks:
        for grp, label, dmax, note, ok in rows:
            print(f"    N={fmt_n(n):>4}  {grp:<62} worst {label:<6} {dmax:9.2e}  "
                  f"{'ok' if ok and not note else 'ok*' if ok else 'MISMATCH'}")
            if note:
                print(f"            * {label}: {note}")
        ok_all &= all(r[4] for r in rows)
    if any(idx.size for _, (_, idx) in checks):
        print(f"    * ok*: the float64 peer differs by ≥ {TOL_REL:g} where the printed §5.1 "
              f"R56y = −(P6·e1 − R56x·c1)/d1 cancels")
        print(f"      (d1 = X67 − X56 = 0 at S = Sp = {peer.PARAMS['Sp']} m, link 6 vertical; "
              f"relative error ≈ 1e-16 m/|d1|, carried into")
        print("      R07y, R67y and §5.2–5.3); there the same printed formulas evaluated in "
              "long double (untimed) agree with assur.")
    print()

    # ---- (c') the fused pipeline -----------------------------------------------------
    outs = fused_outputs()
    carry = hitch.machine
    mach = carry.machine_for({r: float(np.atleast_1d(hitch.params[r])[0])
                              for r in carry.ref_names()})
    stab = (mach, float(hitch.value_of(carry.weight)))
    print("(c') the same §4–§6 values from the fused kinematics + statics kernel (issue 7)")
    print(f"    assur: examples.hitch_003().evaluate(S, outputs=[{len(outs)} outputs: F(S), "
          "p(ГЦ), G(ГЦ, 56), G(ГЦ, S6), reserve(ГЦ, S6, P6), Fr(S),")
    print("           X(S6), Rx/Ry of the 9 tabulated joints]) + axle reactions from X(S6) — "
          "one generated loop writes only these")
    print("    numpy: seed003_numpy.pipeline (as in (c), which also computes §2–§3)")
    per_pos = 8 * (len(outs) + 2)
    print(f"    memory per position: {per_pos} B (outputs, q, status) against "
          f"{int(__import__('assur').inputs.bytes_per_position(hitch))} B estimated for "
          "analyze()")
    print(HEAD)
    fchecks = []
    for n in sizes:
        S = np.linspace(S_MIN, S_MAX, n)
        funcs = {"fused": lambda: fused_pipeline(hitch, S, outs, stab),
                 "numpy": lambda: peer.pipeline(S)}
        for f in funcs.values():
            f()
        best, reps, last = time_interleaved(funcs, min_reps_for(n), args.budget)
        print(line(n, "evaluate(S, outputs=…) + axles", reps, best["fused"], best["numpy"],
                   TARGET_C))
        fchecks.append((n, check_fused(last["fused"], assur_pipeline(hitch, S, P6))))
        del last
    print(f"  agreement fused vs analyze (c); pass if max|Δ|/max|value| < {TOL_REL:g}")
    for n, rows in fchecks:
        k, d, _ = max(rows, key=lambda r: r[1])
        ok = all(r[2] for r in rows)
        print(f"    N={fmt_n(n):>4}  {len(rows)} values  worst {k:<8} {d:9.2e}  "
              f"{'ok' if ok else 'MISMATCH'}")
        ok_all &= ok
    print()

    # ---- (d) a batch of designs reduced in the kernel ---------------------------------
    M, npos = 10**5, 50
    rng = np.random.default_rng(3)
    pert = {k: float(hitch.params[k]) * (1 + 0.01 * rng.standard_normal(M))
            for k in ("L3", "L5", "L6", "L7", "XS6", "YS6") if k in hitch.params}
    Sd = np.broadcast_to(np.linspace(S_MIN, S_MAX, npos), (M, npos))
    out_d = ["reserve(ГЦ, S6, P6)"]
    md = 1000
    pert_small = {k: v[:md] for k, v in pert.items()}

    def reduce_d():
        return hitch.evaluate(Sd, pert, outputs=out_d, reduce=True, on_failure="report")

    def array_d():
        a = hitch.analyze(Sd[:md], params=pert_small, on_failure="report")
        return a.cylinder("ГЦ").reserve("S6", P6).min(axis=1)

    print(f"(d) minimum capacity reserve ΔGS65 over {npos} positions for each of {M:.0e} "
          f"designs (±1 % on {', '.join(pert)}), reduced in the kernel")
    print("    assur: evaluate(S, params, outputs=['reserve(ГЦ, S6, P6)'], reduce=True) — "
          "no position stored")
    print(f"    peer:  analyze(S, params) + .reserve('S6', P6).min(axis=1) on the first {md} "
          "designs (the array pass)")
    from assur.kernel.source import CHUNK
    print(f"    memory per position: 16 B (q, status) + {4 * 8 * len(out_d)} B per work item "
          f"(a run of ≤ {CHUNK} positions of one design: here one per design) for the "
          f"reductions")
    reduce_d()
    array_d()
    best, reps, last = time_interleaved({"d": reduce_d, "a": array_d}, 3, args.budget)
    rd, ra = M * npos / best["d"], md * npos / best["a"]
    dmin = float(np.max(np.abs(last["d"].min(out_d[0])[:md] - last["a"])))
    ok = dmin < 1e-9 * float(np.max(np.abs(last["a"])))
    print(f"    assur {best['d'] * 1e3:9.1f} ms  {rd:.3e} designs·positions/s;  array pass "
          f"{ra:.3e}/s;  ratio {rd / ra:.1f}x;  target {TARGET_D:.0e}  "
          f"{'yes' if rd >= TARGET_D else 'no'};  min agrees to {dmin:.1e} %  "
          f"{'ok' if ok else 'MISMATCH'}")
    ok_all &= ok
    del last
    print()

    # ---- one position ------------------------------------------------------------------
    q1 = np.array([0.5])
    one = {"solve": lambda: hitch.solve(q1), "analyze": lambda: hitch.analyze(q1),
           "evaluate": lambda: hitch.evaluate(q1, outputs=["G(ГЦ, 56)"])}
    best, reps, _ = time_interleaved(one, 200, 0.3 * args.budget)
    print("one position (dynamics calls the mechanism thousands of times, the page once per "
          "slider move):")
    for k, tgt in (("solve", TARGET_SOLVE1), ("analyze", TARGET_ANALYZE1),
                   ("evaluate", TARGET_ANALYZE1)):
        print(f"    {k + '(S = 0.5)':<22} {best[k] * 1e6:9.1f} µs   target ≤ {tgt * 1e6:.0f} µs  "
              f"{'yes' if best[k] <= tgt else 'no'}")
    print()
    if args.startup_reps:
        startup_section(args.startup_reps)
        print()
    if args.spread_procs:
        spread_section(args.spread_procs, 0.3 * args.budget)
        print()
    if args.compile_sizes:
        compile_section([int(v) for v in args.compile_sizes.split(",")])
        print()
    print("targets (issues): (a) ≥ 1e8, (b) ≥ 2e7, (c) and (c') ≥ 1e7 positions/s, (d) ≥ 1e7 "
          "designs·positions/s on this 2-core machine; 'met' compares the assur column only.")
    print("These are throughputs and ratios to a numpy peer in the same process, for reading; "
          "no test asserts on time.")
    if not ok_all:
        print("AGREEMENT CHECK FAILED: the figures above do not compare like with like.")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
