"""``Mechanism.solve(..., out=earlier)``: the kernel writes into the memory of an
earlier result instead of new memory, and the result is the same as a fresh solve's,
bit for bit; a result of another size, a part of a result or another object is
refused with a message saying what was expected."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples

HITCH = examples.hitch_003()
S_MIN, S_MAX = 0.42, 0.67  # seed 003 stroke [m]


def arrays(kin):
    """Every output of a result: positions and analogs of all points, values and
    analogs of all links, as one list."""
    out = []
    for p in kin.points:
        out += [kin.value(p), kin.jacobian(p), kin.hessian(p)]
    for link in kin.links:
        out += [kin.phi(link), kin.dphi(link), kin.ddphi(link)]
    return out


def same(a, b):
    xs, ys = arrays(a), arrays(b)
    return len(xs) == len(ys) and all(np.array_equal(x, y) for x, y in zip(xs, ys))


@settings(max_examples=20, deadline=None)
@given(st.integers(2, 300), st.floats(S_MIN, S_MAX), st.floats(S_MIN, S_MAX))
def test_out_gives_the_fresh_result_in_the_earlier_memory(n, s0, s1):
    S = np.linspace(s0, s1, n)
    earlier = HITCH.solve(np.linspace(S_MIN, S_MAX, n)[::-1])
    buf = earlier.output_buffer
    got = HITCH.solve(S, out=earlier)
    assert got.output_buffer is buf          # no new memory for the outputs
    assert same(got, HITCH.solve(S))


def test_out_over_a_batch_of_designs_and_with_failures_reported():
    S = np.linspace(S_MIN, S_MAX, 40)
    params = {"L4": [0.60, 0.66, 0.95]}      # the third design does not assemble at S_MIN
    earlier = HITCH.solve(S[::-1], params=params, on_failure="report")
    got = HITCH.solve(S, params=params, on_failure="report", out=earlier)
    fresh = HITCH.solve(S, params=params, on_failure="report")
    assert not fresh.ok.all()
    assert np.array_equal(got.ok, fresh.ok) and got.failures == fresh.failures
    assert same(got, fresh)


def test_out_of_another_size_is_refused_with_both_sizes():
    earlier = HITCH.solve(np.linspace(S_MIN, S_MAX, 50))
    with pytest.raises(ValueError, match=r"× 10 designs·positions.*shape \(\d+, 50\).*same "
                                         r"outputs and size"):
        HITCH.solve(np.linspace(S_MIN, S_MAX, 10), out=earlier)
    with pytest.raises(ValueError, match="same outputs and size"):
        HITCH.solve(np.linspace(S_MIN, S_MAX, 50), outputs=["S6"], out=earlier)


def test_out_must_be_a_whole_result():
    earlier = HITCH.solve(np.linspace(S_MIN, S_MAX, 50))
    with pytest.raises(ValueError, match="not a part of one"):
        HITCH.solve(np.linspace(S_MIN, S_MAX, 10), out=earlier.positions(0, 10))
    with pytest.raises(ValueError, match="got ndarray"):
        HITCH.solve(np.linspace(S_MIN, S_MAX, 10), out=np.empty((63, 10)))
