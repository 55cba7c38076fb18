"""The fast paths of issue 7's speed work give the same answers as the paths they
replace: the continuity check inside the fused kernel (across work items and
designs) against the separate pass of composed kernels; the fused statics a
mechanism switches to after :data:`assur.core.statics.FUSED_AFTER` small analyses against
the array pass; small kernel calls in the calling thread; and the generated element
loop stores only to kernel-local buffers (LLVM's run-time overlap check against the
caller's arrays sent it to the 4× slower scalar loop, depending on the addresses)."""

from __future__ import annotations

import re

import numpy as np

from assur import Mechanism, examples
from assur.core import statics
from assur.core import program as P
from assur.kernel import compose
from assur.kernel import emit as KE
from assur.kernel import run as KR
from assur.kernel.source import CHUNK, generate


def _crank_dyad():
    """A crank and a dyad that cannot close for q in (1.3125, 1.829) rad: |AB|² =
    10 − 6 sin q must stay ≥ (ra − rb)² = 2.05² (seed-free, as tests/test_hardening)."""
    return (Mechanism("crank-dyad", coordinates=("q",), params=dict(ra=2.65, rb=0.6))
            .frame("O", 0.0, 0.0).frame("B", 0.0, 3.0)
            .crank("crank", pivot="O", out="A", radius=1.0, q="q", links=("1",))
            .dyad("II", a="A", b="B", out="C", ra="ra", rb="rb", branch=1, links=("2", "3")))


def _run(mech, q, n, path, monkeypatch):
    monkeypatch.setattr(compose, "THRESHOLD", 10**9 if path == "fused" else 0)
    monkeypatch.setattr(P, "_KERNELS", {})
    monkeypatch.setattr(P, "_PROGRAMS", {})
    monkeypatch.setattr(P, "REFINE_DEPTH", 0)  # the raw flags of both checks
    prog = P.compile_program(mech)
    m = q.shape[1] // n
    ptab = np.ascontiguousarray(np.repeat(prog.param_table(mech.params), m, axis=1))
    return P.execute(prog, ptab, np.ascontiguousarray(q), n, True)


def test_in_kernel_continuity_equals_the_separate_pass(monkeypatch):
    """Two designs of 2·CHUNK + 1 positions; the dyad opens between samples at the
    end of a work item (the interval CHUNK − 1 → CHUNK spans two work items), inside
    one, at the last position, and between the designs (not an interval)."""
    n = 2 * CHUNK + 1
    q1 = np.empty(n)
    q1[:CHUNK] = np.linspace(0.0, 1.25, CHUNK)
    q1[CHUNK:] = np.linspace(1.9, 2.5, n - CHUNK)   # jumps over the gap at CHUNK
    q1[100] = 1.9                                    # and back at 100 → 101
    q2 = np.linspace(2.5, 2.0, n)
    q2[-1] = 1.0                                     # the last interval
    q = np.concatenate([q1, q2])[None, :]
    fused = _run(_crank_dyad(), q, n, "fused", monkeypatch)
    composed = _run(_crank_dyad(), q, n, "composed", monkeypatch)
    code = 3 * KE.CODES_PER_OP + KE.FAIL_CONTINUITY
    flagged = np.flatnonzero(fused["status"] == code)
    assert set(flagged) >= {CHUNK, 100, 2 * n - 1}
    assert n not in flagged  # the first position of the second design
    assert np.array_equal(fused["status"], composed["status"])
    assert np.array_equal(fused["amount"][flagged], composed["amount"][flagged])
    assert (fused["amount"][flagged] < 0).all()


def test_statics_switch_to_the_fused_kernel_after_a_few_calls(monkeypatch):
    calls = []
    real = statics._solve_fused

    def counting(kin, g):
        calls.append(kin.n)
        return real(kin, g)

    monkeypatch.setattr(statics, "_solve_fused", counting)
    m = examples.hitch_003().with_params(L5=0.48)  # a mechanism of this test alone
    q = np.array([0.5])
    res = [m.analyze(q).statics for _ in range(statics.FUSED_AFTER + 2)]
    assert calls == [1, 1]  # the calls after FUSED_AFTER
    a, b = res[0], res[-1]
    for _, i, j in a.joints:
        ra, rb = a.reaction(i, j), b.reaction(i, j)
        assert np.allclose(rb, ra, rtol=1e-9, atol=1e-9 * np.abs(ra).max()), (i, j)
    assert np.allclose(b.actuator_force(), a.actuator_force(), rtol=1e-9)


def test_small_kernel_calls_stay_in_the_calling_thread(monkeypatch):
    def no_pool():
        raise AssertionError("a small problem went to the thread pool")

    monkeypatch.setattr(KR, "pool", no_pool)
    monkeypatch.setattr(KR, "threads", lambda: 2)
    assert KR.threads_for(257, 257) == 1  # a condition's scan: 257 designs, 1 position
    m = examples.hitch_003()
    m.solve(np.linspace(0.42, 0.67, 1000))
    m.solve(np.full((257, 1), 0.5), params={"L5": np.linspace(0.47, 0.49, 257)})
    assert KR.threads_for(10**6, 10**6 // CHUNK) == 2


def test_element_loop_stores_only_to_local_buffers():
    prog = P.compile_program(examples.hitch_003())
    src = generate(prog.rows, prog.measures, prog.k, tuple(prog.slot[p] for p in prog.out_pts),
                   tuple(prog.scal[s] for s in prog.out_sca))
    lines = src.splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.strip().startswith("for e in range("))
    indent = len(lines[start]) - len(lines[start].lstrip())
    body = []
    for ln in lines[start + 1:]:
        if ln.strip() and len(ln) - len(ln.lstrip()) <= indent:
            break
        body.append(ln)
    stores = {m.group(1) for ln in body for m in [re.match(r"\s*(\w+)\[", ln)] if m}
    assert stores == {"buf", "sbuf"}, stores


def test_link_angles_of_the_kernel_agree_with_numpy_arctan2():
    """The kernel's branch-free atan2 (Cephes atan, assur.kernel.source.emit_atan2)
    against numpy's on every quadrant, the axes and both signs of zero."""
    rng = np.random.default_rng(7)
    q = np.concatenate([np.linspace(-np.pi, np.pi, 4001), rng.uniform(-4, 4, 4000),
                        [0.0, np.pi / 2, np.pi, -np.pi / 2, -np.pi, 1e-300, -1e-300]])
    m = (Mechanism("crank", coordinates=("q",), params={"r": 0.37})
         .frame("O", 0.25, -0.5)
         .crank("crank", pivot="O", out="A", radius="r", q="q", links=("1",))
         .link("1", "O", "A"))
    r = m.solve(q, check_continuity=False)  # principal values, not unwrapped
    ref = np.arctan2(r.y("A") - (-0.5), r.x("A") - 0.25)
    assert np.max(np.abs(r.phi("1") - ref)) <= 1e-15
    assert np.array_equal(np.signbit(r.phi("1")), np.signbit(ref))
    # the angle's analogs are those of the direction: φ' = 1, φ'' = 0 for a crank
    assert np.allclose(r.dphi("1"), 1.0, rtol=0, atol=1e-12)
    assert np.allclose(r.ddphi("1"), 0.0, rtol=0, atol=1e-12)
