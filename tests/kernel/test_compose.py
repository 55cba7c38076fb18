"""Composed kernels (:mod:`assur.kernel.compose`): the same values as the fused kernel,
bit for bit, and structures of 200 groups that solve.

Which path a structure takes is :data:`assur.kernel.compose.THRESHOLD`; the tests
force each one by setting it (and emptying the program's kernel caches)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from assur import Mechanism, PosePoint, examples
from assur.core import program as P
from assur.kernel import compose
from tests.helpers import ROOT, import_path, by_numpy

# the structures of the compile-time benchmark, defined once (benchmarks/structures.py)
hitch_plus_rigid = import_path("structures", ROOT / "benchmarks" / "structures.py").hitch_plus_rigid


@pytest.fixture
def force(monkeypatch):
    """``force("fused")`` / ``force("composed")``: the path of the next solves."""

    def set_path(path):
        monkeypatch.setattr(compose, "THRESHOLD", 10**9 if path == "fused" else 0)
        monkeypatch.setattr(P, "_KERNELS", {})
        monkeypatch.setattr(P, "_PROGRAMS", {})

    yield set_path
    # a mechanism of assur.examples (cached) keeps the programs compiled while the path
    # was forced: forget it, or a later test in this process gets the composed kernel
    # where it expects the fused one (the doctest of assur.kernel.compose.checks_continuity)
    for f in vars(examples).values():
        if callable(getattr(f, "cache_clear", None)):
            f.cache_clear()


def _execute(mech, q, check=True):
    """Raw kernel outputs of ``mech`` at ``q`` (shape (k, E), one design)."""
    prog = P.compile_program(mech)
    ptab = np.ascontiguousarray(prog.param_table(mech.params))
    by_numpy(mech.prepare, prog, ptab)  # the pose point's pre-pass: not what is compared
    return P.execute(prog, ptab, np.ascontiguousarray(q), q.shape[1], check)


def _composed(mech):
    """Whether the mechanism's kernel (in the current caches) is a composed one."""
    kern = P.compile_program(mech).kernel()
    return "group functions" in kern.py_func.__doc__


def _hitch_k2():
    """The hitch with the top link's length a second coordinate T (its implement's
    centre of mass fixed at S = Sp, T = L7)."""
    m = by_numpy(examples.hitch_003)
    groups = []
    for g in m.groups:
        if getattr(g, "rb", None) == "L7":
            g = replace(g, rb="T")
        if isinstance(g, PosePoint):
            g = replace(g, at=("Sp", "L7"))
        groups.append(g)
    return Mechanism("hitch_k2", coordinates=("S", "T"), params=m.params, groups=groups,
                     links=m.links)


@pytest.mark.parametrize("case", ["hitch", "hitch k=2"])
def test_composed_equals_fused(force, case):
    """Every output row, the status codes (failing positions included: S beyond the
    stroke, zeros there) and the continuity staging are bitwise equal."""
    if case == "hitch":
        mech = by_numpy(examples.hitch_003)
        q = np.linspace(0.30, 0.80, 501)[None, :]  # beyond Smin…Smax: some fail
    else:
        mech = by_numpy(_hitch_k2)
        s, t = np.meshgrid(np.linspace(0.40, 0.70, 21), np.linspace(0.2, 1.8, 11))
        q = np.stack([s.ravel(), t.ravel()])
    force("fused")
    a = _execute(mech, q)
    assert not _composed(mech)
    force("composed")
    b = _execute(mech, q)
    assert _composed(mech)
    assert (a["status"] >= 0).any() and (a["status"] < 0).any()
    for key in ("pv", "pd", "pdd", "sv", "sd", "sdd", "status"):
        assert a[key].shape == b[key].shape
        assert np.array_equal(a[key], b[key]), key
    failed = a["status"] >= 0
    assert not b["pv"][..., failed].any()


def test_composed_solve_equals_fused(force):
    """Through the public API (continuity check and angles included)."""
    S = np.linspace(0.42, 0.67, 200)
    m = by_numpy(examples.hitch_003)
    force("fused")
    getattr(m, "_cache", {}).clear()  # the mechanism's own cache of programs
    a = m.solve(S)
    assert not _composed(m)
    force("composed")
    getattr(m, "_cache", {}).clear()
    b = m.solve(S)
    assert _composed(m)
    for p in ("23", "34", "56", "67", "S6"):
        for f in ("x", "y", "dx", "dy", "ddx", "ddy"):
            assert np.array_equal(getattr(a, f)(p), getattr(b, f)(p)), (p, f)
    for l in ("3", "5", "6", "7"):
        for f in ("phi", "dphi", "ddphi"):
            assert np.array_equal(getattr(a, f)(l), getattr(b, f)(l)), (l, f)


def test_200_groups_solve():
    """A 200-group structure (composed kernel) compiles, solves, and matches the
    plain-numpy positions to 1e-9 m, the complex step of them for the first analogs
    and central differences of the first analogs for the second."""
    base = len(P.compile_program(hitch_plus_rigid(0)).rows)
    mech = hitch_plus_rigid(200 - base)
    prog = P.compile_program(mech)
    assert len(prog.rows) == 200
    assert len(prog.rows) + len(prog.measures) > compose.THRESHOLD
    assert _composed(mech)
    S = np.array([0.43, 0.50, 0.545, 0.61, 0.66])
    r = mech.solve(S)
    ref = mech.evaluate_positions({"S": S})
    h = 1e-30
    cs = mech.evaluate_positions({"S": S + 1j * h})
    dq = 1e-4
    rp = mech.solve(S + dq, check_continuity=False)
    rm = mech.solve(S - dq, check_continuity=False)
    rp2 = mech.solve(S + 2 * dq, check_continuity=False)
    rm2 = mech.solve(S - 2 * dq, check_continuity=False)
    pts = [p for p in prog.out_pts]
    assert len(pts) > 190
    for p in pts:
        for c, f in ((0, "x"), (1, "y")):
            v = getattr(r, f)(p)
            assert np.max(np.abs(v - ref[p][c])) <= 1e-9, (p, f)
            d1 = getattr(r, "d" + f)(p)
            assert np.allclose(d1, np.imag(cs[p][c]) / h, rtol=1e-9, atol=1e-9), (p, f)
            g = lambda rr: getattr(rr, "d" + f)(p)
            fd = (8 * (g(rp) - g(rm)) - (g(rp2) - g(rm2))) / (12 * dq)
            assert np.allclose(getattr(r, "dd" + f)(p), fd, rtol=1e-6, atol=1e-6), (p, f)
