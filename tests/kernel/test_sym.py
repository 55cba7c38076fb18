"""Traced symbols (:mod:`assur.kernel.sym`): random expressions over symbols and
numbers — arithmetic and the numpy functions the group and load code uses — traced
into lines of code that, run on numbers, give what the same expression gives on
those numbers directly (constants folded in Python, every other step one line)."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from assur.kernel.emit import Emitter
from assur.kernel.sym import Sym, Tracer
from tests.helpers import examples

# (name, arity, function): applied to traced symbols and to floats alike
OPS = [("+", 2, lambda a, b: a + b), ("-", 2, lambda a, b: a - b),
       ("*", 2, lambda a, b: a * b), ("/", 2, lambda a, b: a / (b * b + 1.5)),
       ("neg", 1, lambda a: -a), ("hypot", 2, np.hypot), ("atan2", 2, np.arctan2),
       ("sin", 1, np.sin), ("cos", 1, np.cos), ("sqrt", 1, lambda a: np.sqrt(a * a + 0.25)),
       ("pow", 1, lambda a: a ** 2), ("abs", 1, np.absolute)]


@st.composite
def programs(draw):
    """Steps (op, operand indices or constants) over three inputs."""
    steps = []
    for i in range(draw(st.integers(1, 12))):
        name, arity, _ = draw(st.sampled_from(OPS))
        args = [draw(st.one_of(st.integers(0, 2 + i), st.floats(-3, 3).map(lambda x: ("c", x))))
                for _ in range(arity)]
        steps.append((name, args))
    return steps


def run(steps, inputs):
    vals = list(inputs)
    fn = {name: f for name, _, f in OPS}
    for name, args in steps:
        ops = [a[1] if isinstance(a, tuple) else vals[min(a, len(vals) - 1)] for a in args]
        vals.append(fn[name](*ops))
    return vals[-1]


@settings(max_examples=examples(200), deadline=None)
@given(programs(), st.lists(st.floats(-5, 5), min_size=3, max_size=3))
def test_traced_code_computes_what_the_expression_computes(steps, x):
    E = Emitter(1)
    t = Tracer(E)
    out = run(steps, [t.sym(f"x{i}") for i in range(3)])
    want = run(steps, [float(v) for v in x])
    ns = {"math": math, **{f"x{i}": float(v) for i, v in enumerate(x)}}
    exec("\n".join(line.strip() for line in E.lines), ns)
    got = ns[out.name] if isinstance(out, Sym) else out
    np.testing.assert_allclose(got, float(want), rtol=1e-12, atol=1e-12)  # NaN = NaN
    # a line per traced operation at most (a step here is up to three; constants fold)
    assert len(E.lines) <= 3 * len(steps)


def test_numbers_fold_and_symbols_emit():
    E = Emitter(1)
    t = Tracer(E)
    x = t.sym("x7")
    assert E.lines == []  # an existing local emits nothing
    r = 2.0 * x * (0.5 * 4.0)
    assert isinstance(r, Sym) and len(E.lines) == 2
