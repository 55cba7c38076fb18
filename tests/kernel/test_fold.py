"""Constant folding of the emitted element code (:mod:`assur.kernel.fold`; issue 7's
code-generation speed-ups change no answer): random straight-line programs over
literals 0, ±1 and finite values evaluate to the same numbers folded and unfolded (up
to the sign of a zero), and every bundled model's element code, folded and not, gives
the same outputs, analogs and status codes. (Streaming stores:
tests/kernel/test_stream.py.)
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from tests.helpers import examples, by_numpy
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples as bundled_examples
from assur import io
from assur.kernel import source as KS
from assur.groups import group_type
from assur.kernel import vector as KV
from assur.kernel.emit import Emitter
from assur.kernel.fold import fold

# ---- folding ------------------------------------------------------------------------

_LITERALS = ("0.0", "1.0", "-1.0", "(-1.0)", "2.5", "0.0 * 0.0")


@st.composite
def _programs(draw):
    """Lines ``v{i} = a op b`` (and ``c if test else d``) over earlier names, the
    inputs x0…x2 and literals; returns the lines and the final name."""
    names = ["x0", "x1", "x2"]
    lines = []
    for i in range(draw(st.integers(3, 14))):
        pick = st.one_of(st.sampled_from(names), st.sampled_from(_LITERALS))
        a, b = draw(pick), draw(pick)
        kind = draw(st.sampled_from(["+", "-", "*", "/", "neg", "if", "lit"]))
        if kind == "neg":
            expr = f"-({a})"
        elif kind == "if":
            expr = f"{a} if {b} > 0.0 else {draw(pick)}"
        elif kind == "lit":
            expr = draw(st.sampled_from(_LITERALS))
        elif kind == "/":
            expr = f"{a} / ({b} + 7.25)"   # never a division by zero on the inputs
        else:
            expr = f"{a} {kind} {b}"
        lines.append(f"    v{i} = {expr}")
        names.append(f"v{i}")
    return lines, names[-1]


def _run(lines, x):
    ns = {"x0": x[0], "x1": x[1], "x2": x[2]}
    exec("\n".join(line.strip() for line in lines), ns)
    return ns


@settings(max_examples=examples(300), deadline=None)
@given(prog=_programs(), x=st.lists(st.floats(-50.0, 50.0), min_size=3, max_size=3))
def test_folding_keeps_every_value(prog, x):
    """Folded and unfolded programs give equal values (−0.0 == 0.0) wherever the
    unfolded one's values are finite (an element that is not finite is a failed one,
    whose outputs the kernel writes as 0)."""
    lines, _ = prog
    want = _run(lines, x)
    got = _run(fold(lines), x)
    for name, v in want.items():
        if name.startswith("v") and math.isfinite(v) and all(
                math.isfinite(want[n]) for n in want if n.startswith("v")):
            assert got[name] == v, (name, lines, fold(lines))


def test_folding_simplifies_the_hitch():
    """The seed-003 hitch's element code loses the frame points' zero analogs."""
    prog = by_numpy(bundled_examples.hitch_003).program()
    E = Emitter(prog.k)
    for i, row in enumerate(prog.rows):
        group_type(row[0]).emit(E, i, tuple(int(v) for v in row[1:]))
    raw = "\n".join(E.lines)
    folded = "\n".join(fold(E.lines))
    assert raw.count(" * ") > folded.count(" * ")
    assert "* x0_0" in raw and "* x0_0" not in folded


@pytest.mark.parametrize("name", ["hitch_003", "header_000_fixed", "combine_002",
                                  "steering_lab4", "loader_lab1", "conditioner_lab2_sixbar",
                                  "cleaning_lab3", "spout_lab5", "crane_lv185"])
def test_folded_code_equals_unfolded_on_bundled_models(name, monkeypatch):
    """The numpy evaluation of a bundled model's element code over its range, folded
    (as every kernel is) and not: equal outputs, analogs and status codes."""
    model = by_numpy(io.load, io.bundled(name))
    mech = model.mechanism
    q = np.atleast_2d(np.asarray(model.range, dtype=float))
    q = q.reshape(-1, len(mech.coordinates)).T if len(mech.coordinates) > 1 else q
    q = np.ascontiguousarray(q[:, :KV.SMALL])
    prog = mech.program()
    ptab, trig, _ = by_numpy(mech.prepared, prog)  # a pose point's pre-pass
    pts = tuple(prog.slot[p] for p in prog.out_pts)
    sca = tuple(prog.scal[s] for s in prog.out_sca)
    nq = len(KS.quantities(prog.k, pts, sca))

    def run():
        src = KV.generate_vector(prog.rows, prog.measures, prog.k, pts, sca)
        ns = {}
        exec(compile(src, f"<vector {name}>", "exec"), ns)
        E = q.shape[1]
        out, amount, status = np.empty((nq, E)), np.zeros(E), np.empty(E, dtype=np.int64)
        ns["kernel"](ptab, trig, q, E, True, out, amount, status, 0, 1)
        return out, status

    out_f, st_f = run()
    monkeypatch.setattr(KS, "fold", lambda lines: list(lines))
    out_u, st_u = run()
    assert np.array_equal(st_f, st_u)
    assert np.array_equal(out_f, out_u), name
