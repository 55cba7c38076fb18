"""Input checks (:mod:`assur.core.inputs`): the fast finiteness check agrees with
numpy's on any array, a request is refused exactly when its memory estimate passes
the limit ``ASSUR_MAX_MEMORY`` gives, and ``params_problem`` says what
``check_params`` raises — for every value, not only the documented ones."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from assur import examples
from assur.core.inputs import all_finite, bytes_per_position, check_memory, check_params, \
    fmt_bytes, max_memory, params_problem
from assur.errors import ModelError
from tests.helpers import examples as n_examples


@settings(max_examples=n_examples(200), deadline=None)
@given(hnp.arrays(np.float64, hnp.array_shapes(min_dims=0, max_dims=2, max_side=40),
                  elements=st.floats(allow_nan=True, allow_infinity=True)))
def test_all_finite_is_numpys_isfinite(v):
    assert all_finite(v) == bool(np.isfinite(v).all())
    if v.ndim == 0:
        assert all_finite(float(v)) == bool(np.isfinite(v))


@pytest.mark.parametrize("text, size", [("500 MiB", 500 * 2**20), ("2 GiB", 2 * 2**30),
                                        ("123456789", 123456789)])
def test_the_limit_is_read_from_the_environment(monkeypatch, text, size):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", text)
    assert max_memory() == size


def test_a_request_is_refused_exactly_above_the_limit(monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    per = bytes_per_position(examples.hitch_003())
    assert per > 0
    fits = 2**20 // per
    check_memory(fits, per, "range.S")  # at the limit: accepted
    with pytest.raises(ModelError, match=r"range\.S.*limit 1 MiB; set ASSUR_MAX_MEMORY"):
        check_memory(fits + 1, per, "range.S")
    assert fmt_bytes(2**20) == "1 MiB" and fmt_bytes(1536) == "1.5 KiB"


@settings(max_examples=n_examples(60), deadline=None)
@given(st.floats(-2.0, 2.0), st.floats(0.0, 1.5))
def test_params_problem_is_what_check_params_raises(L4, eta):
    m = examples.hitch_003()
    params = {"L4": L4, "eta": eta}
    problem = params_problem(m, params)
    try:
        check_params(m, params)
    except ModelError as e:
        assert problem == str(e)
    else:
        assert problem is None
    assert (problem is None) == (1e-6 <= L4 and 0.01 <= eta <= 1)
