"""check_memory's words for what is counted and what to reduce (issue 27): the
positions of a range as before, any other unit and the option or file key to
reduce, with the estimate and the limit."""

from __future__ import annotations

import pytest

from assur.core.inputs import check_memory
from assur.errors import ModelError
from tests.helpers.memory import assert_refusal


def test_positions_by_default(monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    with pytest.raises(ModelError) as e:
        check_memory(1e6, 8, "the range")
    assert str(e.value) == ("the range: 1e+06 positions would need about 7.63 MiB of memory "
                            "(limit 1 MiB; set ASSUR_MAX_MEMORY to change it, or use fewer "
                            "positions)")


def test_a_unit_and_what_to_reduce(monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    with pytest.raises(ModelError) as e:
        check_memory(1e9, 800, "sweep: samples = 1e+09", unit="designs",
                     reduce="the samples (--samples)")
    assert_refusal(str(e.value), "reduce the samples (--samples))")
    assert "1e+09 designs would need about 745 GiB" in str(e.value)
    check_memory(1024, 1024, "at the limit", unit="designs", reduce="--samples")  # fits
