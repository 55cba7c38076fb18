"""``--positions`` of a design problem (:func:`assur.io.load_problem`, issue 27): one
design over that many positions must fit in memory, refused before the positions are
allocated; a kernel call of many designs × positions is refused by the problem itself
(:mod:`assur.synthesis.search.problem`)."""

from __future__ import annotations

import pytest

from assur import io
from assur.errors import ModelError
from assur.io import load_problem
from tests.helpers.memory import allocates_little, assert_refusal


def test_too_many_positions_are_refused_before_the_linspace(monkeypatch):
    load_problem(io.bundled("hitch_003_design"))  # the file, loaded and cached
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    # 1e8 positions: 800 MB of coordinates without the guard; loading the file again
    # (another count) may take the reader's buffer (64 MiB at most)
    with allocates_little(100 * 1024**2), pytest.raises(ModelError) as e:
        load_problem(io.bundled("hitch_003_design"), positions=10**8)
    assert_refusal(str(e.value), "--positions")
    assert "--positions 100000000: 1e+08 positions" in str(e.value)


def test_a_normal_count_still_loads(monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    assert load_problem(io.bundled("hitch_003_design"), positions=6).n_positions == 6
