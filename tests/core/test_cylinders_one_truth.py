"""One truth per quantity (issue 22): a cylinder's actuator force, pressure, lift
capacity and reserve are the same numbers whichever path computes them.

The paths:

* **report** — :meth:`assur.Mechanism.analyze` → :class:`assur.machines.cylinders.CylinderResult`
  (the tables, figures, the page), over numpy arrays;
* **kernel** — :meth:`assur.Mechanism.evaluate`, the fused outputs kernel
  (:mod:`assur.core.outputs`), symbols traced into compiled code;
* **criterion** — :meth:`assur.synthesis.search.Problem.evaluate` with the design
  criteria ``capacity``, ``pressure`` and bounds on ``reserve`` and ``F`` (the
  kernel's reductions over the positions, what a design search maximises);
* **lift test** — :func:`assur.machines.hitch_lift.lift_test` (ISO 789-2 style), at
  its own positions and pressure.

All four call the formulas of :mod:`assur.core.cylinders`; these tests hold them
equal to 1e-12 relative to the largest magnitude of the quantity over the
positions, on every bundled model and on 200 random mechanisms of four families
(random dimensions, loads, cylinder data; dead loads, ``side = "piston"``,
``"rod"`` and ``"auto"``, double-rod cylinders, counts, losses, two coordinates and
supply lines among them). Positions where an ``auto`` cylinder's force is within
1e-9 of zero are left out of the comparison of sign-dependent values (there the
chamber is a choice between two equal answers of opposite sign).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from assur import AssemblyError, ModelError, io
from assur.core import loads as L
from assur.machines.capacity import lifts
from assur.machines.hitch_lift import LiftTest, lift_test
from assur.synthesis.search import Problem, Variable, criterion

REL = 1e-12


def _close(name, a, b, scale=None):
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = max(float(np.max(np.abs(b), initial=0.0)) if scale is None else scale, 1e-300)
    err = np.abs(a - b)
    assert np.all(err <= REL * scale), \
        f"{name}: largest difference {err.max():.3g}, {err.max() / scale:.3g} relative"


def _capacity_points(mech, cyl, kin):
    """Points the cylinder lifts whose transmission number is nowhere near 0: the load
    points, the tabulated transmissions and the lift test's points."""
    names = [getattr(ld, "point", None) for ld in mech.loads]
    names += list(mech.tables.get("transmissions", ()) or ()) + ["56", "F610"]
    out = []
    wrt = cyl.coordinate if kin.k > 1 else None
    for p in dict.fromkeys(n for n in names if n):
        if p not in mech.points or not lifts(mech, cyl.coordinate, p):
            continue
        I = np.asarray(kin.transmission(p, wrt=wrt))
        if np.all(np.abs(I) > 1e-6 * np.max(np.abs(I))):
            out.append(p)
    return out[:4]


def _load(mech):
    """The reserve's load: the first weight's parameter, else 10 kN [N] (a number in an
    output's text is part of the kernel's structure: the random mechanisms keep one)."""
    for ld in mech.loads:
        if isinstance(ld, L.Weight) and isinstance(ld.P, str):
            return ld.P
    return 10000.0


def _auto_mask(cyl, F):
    """Where a comparison of sign-dependent values is meaningful."""
    if cyl.side != "auto":
        return np.ones(np.shape(F), bool)
    return np.abs(F) > 1e-9 * np.max(np.abs(F))


def _outputs(mech, cyl, kin):
    """The kernel outputs of a cylinder compared here (one list per structure)."""
    P, pts = _load(mech), _capacity_points(mech, cyl, kin)
    return ([f"F({cyl.coordinate})", f"p({cyl.name})"]
            + [f"G({cyl.name}, {p})" for p in pts]
            + [f"reserve({cyl.name}, {p}, {P})" for p in pts])


def check_paths(mech, q):
    """Compare the report, kernel and criterion paths on every cylinder of ``mech`` at
    positions ``q``; returns how many quantities were compared."""
    q = np.asarray(q, float)
    # static loads: the kernel has no inertia (a rod's [motion] adds it to analyze)
    a = mech.analyze(q, qdot=np.zeros_like(q), qddot=np.zeros_like(q))
    kin = a.kinematics
    compared = 0
    for cyl in mech.cylinders:
        rep = a.cylinders[cyl.name]
        if cyl.supply is not None:   # a supply line: its pressure (and the driver's F)
            fused = mech.evaluate(q, outputs=[f"p({cyl.name})"])
            _close(f"p({cyl.name}) kernel", fused[f"p({cyl.name})"], rep.pressure)
            compared += 1
            continue
        c = cyl.coordinate
        F = a.statics.actuator_force(c)
        ok = _auto_mask(cyl, F)
        P = _load(mech)
        pts = _capacity_points(mech, cyl, kin)
        fused = mech.evaluate(q, outputs=_outputs(mech, cyl, kin))
        _close(f"F({c}) kernel", fused[f"F({c})"], F)
        _close(f"p({cyl.name}) kernel", fused[f"p({cyl.name})"][ok], rep.pressure[ok],
               np.max(np.abs(rep.pressure)))
        G = {p: rep.capacity(p) for p in pts}
        R = {p: rep.reserve(p, mech.value_of(P) if isinstance(P, str) else P) for p in pts}
        for p in pts:
            _close(f"G({cyl.name}, {p}) kernel", fused[f"G({cyl.name}, {p})"][ok], G[p][ok],
                   np.max(np.abs(G[p])))
            _close(f"reserve({cyl.name}, {p}) kernel",
                   fused[f"reserve({cyl.name}, {p}, {P})"][ok], R[p][ok],
                   max(100.0, float(np.max(np.abs(R[p])))))
        compared += 2 + 2 * len(pts)
        if not np.all(ok):
            continue
        # the design criteria: reductions over the positions in the kernel
        var = next(n for n in mech.params if np.ndim(mech.params[n]) == 0
                   and float(mech.params[n]) != 0.0)
        v0 = float(mech.params[var])
        objs = [criterion("pressure", {"cylinder": cyl.name}, mech, sense="minimize"),
                criterion("bound", {"quantity": f"F({c})", "of": "max"}, mech,
                          sense="minimize")]
        objs += [criterion("capacity", {"cylinder": cyl.name, "point": p}, mech,
                           sense="maximize") for p in pts]
        objs += [criterion("bound", {"quantity": f"reserve({cyl.name}, {p}, {P})",
                                     "of": "min"}, mech, sense="maximize") for p in pts]
        pb = Problem(mech, q, [Variable(var, v0 - abs(v0) * 1e-3, v0 + abs(v0) * 1e-3)],
                     objectives=objs)
        b = pb.evaluate(pb.x0[None])
        rises = all(np.all(np.asarray(kin.transmission(p, wrt=c if kin.k > 1 else None)) > 0)
                    for p in pts)
        assert bool(b.feasible[0]) == rises, b.reason(0)
        if not rises:
            continue
        _close("pressure criterion", b.objective(0)[0], np.max(rep.pressure),
               np.max(np.abs(rep.pressure)))
        _close("F criterion", b.objective(1)[0], np.max(F), np.max(np.abs(F)))
        for i, p in enumerate(pts):
            _close(f"capacity criterion at {p}", b.objective(2 + i)[0], np.min(G[p]),
                   np.max(np.abs(G[p])))
            _close(f"reserve criterion at {p}", b.objective(2 + len(pts) + i)[0],
                   np.min(R[p]), max(100.0, float(np.max(np.abs(R[p])))))
        compared += 2 + 2 * len(pts)
    return compared


def check_lift_test(mech, test, s_range):
    """The lift test's forces are the capacity of the report path and of the kernel at
    the test's positions and pressure (p_relief·share, no losses)."""
    cyl = mech.cylinders[0]
    try:
        r = lift_test(mech, test, s_range)
    except ModelError as e:   # a hitch that does not lift (a pulling chamber, …)
        assert "does not rise" in str(e)
        return 0
    pr = float(np.ravel(mech.value_of(cyl.p_relief))[0])
    rep = mech.analyze(r.s, qdot=np.zeros_like(r.s), qddot=np.zeros_like(r.s)).cylinders[cyl.name]
    for p, got in ((test.hitch, r.hitch_force), (test.frame, r.frame_force)):
        if p is None:
            continue
        _close(f"lift test at {p}, report", got, rep.capacity(p, pressure=r.pressure))
    # the kernel: the same cylinder whose working pressure is the test's
    dp = sum(float(np.ravel(mech.value_of(v))[0]) for v in (cyl.dp_throttle, cyl.dp_line))
    test_cyl = dataclasses.replace(cyl, p_relief=test.pressure_share * pr + dp)
    variant = mech.with_cylinders([test_cyl] + list(mech.cylinders[1:]))
    outs = _outputs(variant, test_cyl, variant.solve(r.s))
    key = f"G({cyl.name}, {test.hitch})"
    assert key in outs
    _close("lift test at the hitch, kernel", r.hitch_force,
           variant.evaluate(r.s, outputs=outs)[key])
    return 1


# ---- every bundled model ------------------------------------------------------------

def _bundled():
    import importlib.resources as res
    return sorted(p.name[:-5] for p in res.files("assur.models").iterdir()
                  if p.name.endswith(".toml"))


@pytest.mark.parametrize("name", _bundled())
def test_every_bundled_model_one_truth(name):
    try:
        model = io.load(io.bundled(name))
    except (ModelError, AssemblyError):
        pytest.skip(f"{name} does not assemble (kept as its seed prints it)")
    mech = getattr(model, "mechanism", None)
    if mech is None or not mech.cylinders or getattr(model, "range", None) is None:
        pytest.skip(f"{name} has no cylinder over a range")
    q = np.asarray(model.range)
    q = q[:: max(1, len(q) // 12)]
    try:
        mech.solve(q)
    except AssemblyError:
        pytest.skip(f"{name} does not assemble over its range")
    assert check_paths(mech, q) > 0
    if getattr(model, "lift_test", None) is not None:
        assert check_lift_test(mech, model.lift_test, (float(q.min()), float(q.max()))) == 1


# ---- random mechanisms ------------------------------------------------------------
# Random dimensions, loads and cylinder data on the structures of bundled machines:
# the values are parameters and literal rows of one compiled kernel per structure,
# so each configuration below compiles its kernels once (its examples then cost
# ~0.3 s each). Random numbers are drawn so that no two of them coincide (the
# kernel's rows are keyed by value).

def _run(strategy, positions, lift=False):
    """Check the paths on 25 mechanisms of ``strategy`` (those that assemble at
    ``positions(range)``; with ``lift``, the lift test too)."""

    @given(strategy)
    @settings(max_examples=25, suppress_health_check=[HealthCheck.too_slow,
                                                      HealthCheck.filter_too_much])
    def run(case):
        mech, extra = case
        q = positions(extra)
        try:
            mech.solve(q)
        except AssemblyError:
            assume(False)
        assert check_paths(mech, q) > 0
        if lift:
            check_lift_test(mech, extra, (float(q.min()), float(q.max())))

    run()


@functools.lru_cache(maxsize=None)
def _model(name):
    return io.load(io.bundled(name))


def _scaled(mech, factors):
    """Lengths of ``mech`` scaled by the factors (one per length parameter)."""
    from assur.core.quantities import parameter_quantities
    qs = parameter_quantities(mech)
    lengths = [n for n in mech.params if qs.get(n) == "length"]
    return mech.with_params(**{n: float(mech.params[n]) * f
                               for n, f in zip(lengths, factors)})


class _Numbers:
    """Draws floats that never coincide within one mechanism (hypothesis likes the
    bounds of a range: two losses of 0.1 MPa would share one row of the kernel and
    make another structure): the k-th is scaled by 1 + k·1e-7."""

    def __init__(self, draw):
        self.draw, self.k = draw, 0

    def __call__(self, lo, hi):
        self.k += 1
        return self.draw(st.floats(lo, hi)) * (1.0 + self.k * 1e-7)


def _cylinder(num, base, side, double, count):
    bore = num(0.06, 0.12)
    return dataclasses.replace(
        base, bore=bore, rod=bore * num(0.3, 0.7),
        rod2=bore * num(0.25, 0.6) if double else 0.0, count=count,
        eta_mech=num(0.8, 0.95), eta_hyd=num(0.8, 0.95), p_relief=num(10e6, 25e6),
        dp_throttle=num(0.1e6, 1e6), dp_line=num(0.1e6, 1e6), side=side)


#: (side, double rod, dead loads) of the random cylinders
CONFIGS = [("piston", False, True), ("rod", False, False), ("auto", True, False),
           ("auto", False, True)]


@st.composite
def hitches(draw, config):
    model = _model("hitch_003")
    m = _scaled(model.mechanism, [draw(st.floats(0.985, 1.015)) for _ in range(30)])
    side, double, dead = config
    num = _Numbers(draw)
    cyl = _cylinder(num, m.cylinders[0], side, double, float(draw(st.sampled_from([2, 3]))))
    loads = [L.Weight("S6", num(5e3, 40e3)), L.Mass("3", num(20.0, 200.0), "34", J=num(1.0, 5.0)),
             L.PointForce("67", num(-3e3, -1e3), num(1e3, 3e3))]
    m = m.with_loads(loads).with_cylinders([cyl]).with_tables(
        dead_loads=["3"] if dead else [])
    return m, model.lift_test


@pytest.mark.parametrize("config", CONFIGS, ids=lambda c: "-".join(map(str, c)))
def test_random_hitches_one_truth(config):
    """The 003 hitch's structure (one coordinate, a lift test): 4 × 25 mechanisms."""
    _run(hitches(config), lambda test: np.linspace(0.43, 0.66, 6), lift=True)


@st.composite
def loaders(draw, config):
    model = _model("loader_lab1")
    m = _scaled(model.mechanism, [draw(st.floats(0.99, 1.01)) for _ in range(30)])
    side, double, _ = config
    count = float(draw(st.sampled_from([2, 3])))
    num = _Numbers(draw)
    cyls = [_cylinder(num, c, side, double, count) for c in m.cylinders]
    loads = [L.Mass("3", num(100.0, 400.0), "S3", J=num(1.0, 9.0)), L.Weight("S9", num(2e3, 12e3))]
    return m.with_loads(loads).with_cylinders(cyls), model.range


@pytest.mark.parametrize("config", [CONFIGS[0], CONFIGS[2]],
                         ids=lambda c: "-".join(map(str, c)))
def test_random_loaders_one_truth(config):
    """Two coordinates, the boom's mass a dead load (seed 001 lab 1 eq. 14): 2 × 25."""
    _run(loaders(config), lambda rng: np.asarray(rng)[::9])


@st.composite
def steerings(draw, name):
    model = _model(name)
    m = _scaled(model.mechanism, [draw(st.floats(0.995, 1.005)) for _ in range(30)])
    num = _Numbers(draw)
    M = num(500.0, 4000.0)
    loads = [dataclasses.replace(ld, M=M) for ld in m.loads]
    if name == "steering_lab4_modern":   # the double-rod cylinder, side = "auto"
        cyls = [_cylinder(num, m.cylinders[0], "auto", True, 1.0)]
    else:                                # a supply line: piston side and rod side
        bore = num(0.05, 0.08)
        count = float(draw(st.sampled_from([2, 3])))
        cyls = [dataclasses.replace(c, bore=bore, rod=bore * num(0.3, 0.6), count=count)
                for c in m.cylinders]
    return m.with_loads(loads).with_cylinders(cyls), model.range


@pytest.mark.parametrize("name", ["steering_lab4", "steering_lab4_modern"])
def test_random_steerings_one_truth(name):
    """A supply line (seed 001 lab 4) and a double-rod cylinder picking its chamber:
    2 × 25 mechanisms."""
    _run(steerings(name), lambda rng: np.asarray(rng)[::3])


# ---- side = "auto" with a lift test ---------------------------------------------------

def test_auto_side_with_a_lift_test_checks_and_analyses(tmp_path):
    """The 003 hitch with ``side = "auto"`` (a rod given): ``assur check`` ends with its
    summary, not a traceback, and the lift test's forces are the capacity's."""
    from assur.views.cli import app
    src = io.bundled("hitch_003").read_text(encoding="utf-8")
    text = src.replace('p_relief = "Pgc_max"\n', 'p_relief = "Pgc_max"\nside = "auto"\n'
                                                 'rod = "40 mm"\n', 1)
    assert text != src
    f = tmp_path / "hitch_auto.toml"
    f.write_text(text, encoding="utf-8")
    r = CliRunner().invoke(app, ["check", str(f)])
    assert r.exit_code == 0, r.output
    assert "Traceback" not in r.output
    model = io.load(f)
    assert model.mechanism.cylinders[0].side == "auto"
    q = np.asarray(model.range)
    assert check_lift_test(model.mechanism, model.lift_test, (float(q.min()),
                                                              float(q.max()))) == 1
