"""The numpy evaluation of a structure's kernel (:mod:`assur.kernel.vector`, the first
small calls of a process that has not loaded numba) gives the compiled kernel's
answers to the last bit (the same operations in the same order; numba without
fastmath): outputs, first and second analogs, status codes and continuity depths, on
random mechanisms of every group type (the samples of the group contract test,
including parameters that cannot assemble), on two bundled models over their ranges
(one per kind of structure), and in the continuity check's corner cases (within and
across the compiled kernel's work items). And a process that only checks a
bundled model never imports numba (nor pint, scipy, matplotlib, pandas)."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from tests.helpers import examples, by_numpy
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import io
from assur.core import program as P
from assur.groups import registry
from assur.kernel import emit as KE
from assur.kernel import run as KR
from assur.kernel import vector as KV

from tests.helpers.analogs import SETTINGS
from tests.helpers.groups import SAMPLES
from tests.helpers.mechanisms import crank_dyad

KEYS = ("pv", "pd", "pdd", "sv", "sd", "sdd")


def _execute(mech, q, n, vector, monkeypatch, check=True, params=None):
    """Run ``mech``'s program over ``q`` (k, E), E = m·n, by the numpy evaluation
    (``vector``) or the compiled kernel."""
    monkeypatch.setattr(KV, "wanted", lambda elements, ready=None: vector)
    prog = P.compile_program(mech)
    ptab = np.ascontiguousarray(prog.param_table(dict(mech.params, **(params or {}))))
    m = q.shape[1] // n
    if ptab.shape[1] == 1 and m > 1:
        ptab = np.ascontiguousarray(np.repeat(ptab, m, axis=1))
    res = P.execute(prog, ptab, np.ascontiguousarray(q, dtype=float), n, check)
    assert callable(getattr(prog.kernel(vector=vector), "py_func", None)) != vector
    return res


def _same(a, b, what):
    assert np.array_equal(a["status"], b["status"]), (what, a["status"], b["status"])
    for k in KEYS:  # to the last bit: the same operations in the same order
        x, y = a[k], b[k]
        assert np.array_equal(x, y, equal_nan=True), (what, k, np.abs(x - y).max(initial=0))
    bad = a["status"] % KE.CODES_PER_OP == KE.FAIL_CONTINUITY
    assert np.array_equal(a["amount"][bad], b["amount"][bad]), what


@pytest.mark.parametrize("type_name", sorted(registry()))
@settings(SETTINGS, max_examples=examples(15))
@given(data=st.data())
def test_vector_equals_compiled_on_every_group_type(type_name, data):
    sample = SAMPLES[type_name]
    b = sample.build(data)
    case = by_numpy(b.build)  # the case's own solves: not what is compared
    M, n, k = case.Q.shape
    q = case.Q.transpose(2, 0, 1).reshape(k, M * n)
    params = {}
    if sample.breaks is not None and data.draw(st.booleans(), label="break it"):
        params = {key: np.broadcast_to(np.asarray(v, dtype=float), (M,)).copy()
                  if b.batch else float(np.ravel(v)[0])
                  for key, v in sample.breaks(b).items()}
    with pytest.MonkeyPatch.context() as mp:
        got = _execute(case.mech, q, n, True, mp, params=params)
        want = _execute(case.mech, q, n, False, mp, params=params)
    _same(got, want, type_name)


# a model of one coordinate (a cylinder, pose and rigid points, dyads) and one of two
# (a crane); every group type is compared on random mechanisms above
@pytest.mark.parametrize("name", ["hitch_003", "crane_lv185"])
def test_vector_equals_compiled_on_bundled_models(name, monkeypatch):
    model = by_numpy(io.load, io.bundled(name))
    mech = model.mechanism
    q = np.atleast_2d(np.asarray(model.range, dtype=float))
    q = q.reshape(-1, len(mech.coordinates)).T if len(mech.coordinates) > 1 else q
    q = q[:, :KV.SMALL]
    got = _execute(mech, q, q.shape[1], True, monkeypatch)
    want = _execute(mech, q, q.shape[1], False, monkeypatch)
    _same(got, want, name)


def test_vector_continuity_equals_compiled(monkeypatch):
    """Two designs of 100 positions of a crank and dyad that opens between samples:
    inside a design, at consecutive intervals (a marked element is not the left end of
    a checked interval), at the last position, and between the designs (not an
    interval)."""
    n = 100
    q1 = np.linspace(0.0, 2.5, n)
    q1[40:43] = [1.0, 1.9, 1.0]  # out and back: two failing intervals in a row
    q2 = np.linspace(2.5, 2.0, n)
    q2[-1] = 1.0
    q = np.concatenate([q1, q2])[None, :]
    monkeypatch.setattr(P, "REFINE_DEPTH", 0)  # the raw flags of both checks
    got = _execute(crank_dyad(), q, n, True, monkeypatch)
    want = _execute(crank_dyad(), q, n, False, monkeypatch)
    code = 3 * KE.CODES_PER_OP + KE.FAIL_CONTINUITY
    flagged = np.flatnonzero(want["status"] == code)
    assert {41, 2 * n - 1} <= set(flagged) and n not in flagged
    _same(got, want, "continuity")
    assert (got["amount"][flagged] < 0).all()


def test_vector_continuity_across_work_items_equals_compiled(monkeypatch):
    """One design of 2·CHUNK + 1 positions whose dyad opens between samples on both
    sides of the first work item's end: the compiled kernel computes a work item's
    first interval from its left end again, unmarked, and the numpy evaluation checks
    that interval the same way (two failing intervals in a row across the boundary)."""
    from assur.kernel.source import CHUNK
    n = 2 * CHUNK + 1
    q = np.linspace(0.0, 2.5, n)
    q[CHUNK - 2:CHUNK + 1] = [1.0, 1.9, 1.0]   # out and back over CHUNK − 2 … CHUNK
    q = q[None, :]
    monkeypatch.setattr(P, "REFINE_DEPTH", 0)  # the raw flags of both checks
    got = _execute(crank_dyad(), q, n, True, monkeypatch)
    want = _execute(crank_dyad(), q, n, False, monkeypatch)
    code = 3 * KE.CODES_PER_OP + KE.FAIL_CONTINUITY
    # CHUNK − 1 is marked in the first work item and is still the left end of the
    # second's first interval (within one work item it would not be)
    assert {CHUNK - 1, CHUNK} <= set(np.flatnonzero(want["status"] == code))
    _same(got, want, "continuity across work items")


def test_small_unwrap_equals_compiled():
    rng = np.random.default_rng(7)
    sv = np.cumsum(rng.uniform(-2.0, 2.0, (3, 2 * 40)), axis=1)
    sv = np.arctan2(np.sin(sv), np.cos(sv))  # principal values with jumps
    rows = np.array([0, 2], dtype=np.int64)
    small, big = sv.copy(), sv.copy()
    KR._unwrap_small(small, rows, 40)
    n = max(KR.UNWRAP_NUMPY, KV.LARGE) + 1  # the compiled unwrap, numba loaded or not
    KR.unwrap_rows(np.zeros((1, n)), np.array([0], dtype=np.int64), n)
    KR._compiled["unwrap"](big, rows, 40)
    assert np.array_equal(small, big)
    assert np.array_equal(small[1], sv[1])


def test_the_numpy_path_is_taken_a_limited_number_of_times(monkeypatch):
    monkeypatch.delitem(sys.modules, "numba", raising=False)  # as if numba were not loaded
    KV.set_backend("auto")  # the default rule
    KV.set_calls(2)
    try:
        assert KV.calls_left() == 2
        assert not KV.wanted(KV.SMALL + 1) and KV.calls_left() == 2  # too big
        assert KV.wanted(1) and KV.wanted(KV.SMALL)
        assert not KV.wanted(1) and KV.calls_left() == 0
    finally:
        KV.set_calls(None)
    with pytest.raises(ValueError):
        KV.set_calls(-1)


CHECK = """
import sys
from typer.testing import CliRunner
from assur.views.cli import app
from assur import io
r = CliRunner().invoke(app, ["check", str(io.bundled("hitch_003"))])
assert r.exit_code == 0, r.output
print(sorted(m for m in ("numba", "pint", "scipy", "matplotlib", "pandas", "jinja2",
                         "openpyxl") if m in sys.modules))
"""


def test_check_of_a_bundled_model_imports_no_heavy_module():
    out = subprocess.run([sys.executable, "-c", CHECK], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "[]", out.stdout


def test_calls_left_is_a_plain_int():
    """The module's own elementwise ``max`` is numpy's: ``calls_left`` used it and
    returned an ``np.int64`` where its annotation says ``int`` (found writing its
    doctest)."""
    KV.set_calls(7)
    try:
        left = KV.calls_left()
        assert type(left) is int and left in (0, 7)
    finally:
        KV.set_calls(None)
