"""``[lift_test] positions`` too many for the memory limit (issue 27): refused when the
file loads, at the file, line and key (as every other error of the section), with
the estimate and the limit."""

from __future__ import annotations

import pytest

from assur import io
from assur.io import ModelFileError
from tests.helpers.memory import assert_refusal

HITCH = io.bundled("hitch_003").read_text(encoding="utf-8")


@pytest.mark.parametrize("count", [100_000, 10**12])
def test_too_many_positions_name_the_file_line_and_key(count, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    bad = f"positions = {count}"
    text = HITCH.replace("positions = 6", bad)
    line = text.splitlines().index(bad) + 1
    with pytest.raises(ModelFileError) as e:
        io.loads(text, name="h.toml")
    msg = str(e.value)
    assert msg.startswith(f"h.toml:{line}: lift_test.positions: "), msg
    assert_refusal(msg, "[lift_test] positions")


def test_a_normal_file_still_loads(monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    assert io.loads(HITCH, name="h.toml").lift_test.positions == 6
