"""``[design] positions`` too many for the memory limit (issue 27): refused when the
file loads, at the file, line and key, with the estimate and the limit; the bundled
design problem still loads."""

from __future__ import annotations

import pytest

from assur import io
from assur.io import ModelFileError
from tests.helpers.memory import allocates_little, assert_refusal

#: what loading a model file may allocate whatever it holds (the reader's buffer) [bytes]
READ = 100 * 1024**2
DESIGN = io.bundled("hitch_003_design").read_text(encoding="utf-8")


def _files(tmp_path, positions):
    (tmp_path / "hitch_003.toml").write_text(io.bundled("hitch_003").read_text(
        encoding="utf-8"), encoding="utf-8")
    text = DESIGN.replace("positions = 50", f"positions = {positions}")
    path = tmp_path / "design.toml"
    path.write_text(text, encoding="utf-8")
    return path, text.splitlines().index(f"positions = {positions}") + 1


@pytest.mark.parametrize("count", [100_000, 10**12])
def test_too_many_positions_name_the_file_line_and_key(tmp_path, count, monkeypatch):
    path, line = _files(tmp_path, count)
    io.load(io.bundled("hitch_003"))  # the base, built beforehand
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    with pytest.raises(ModelFileError) as e:
        io.load(path)
    msg = str(e.value)
    assert f"design.toml:{line}: design.positions: " in msg, msg
    assert_refusal(msg, "[design] positions")
    assert f"[design] positions = {count}:" in msg


def test_a_normal_design_file_still_loads(tmp_path, monkeypatch):
    path, _ = _files(tmp_path, 50)
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    assert io.load(path).design.positions == 50


def test_refused_before_the_positions_are_allocated(tmp_path, monkeypatch):
    path, _ = _files(tmp_path, 10**12)
    io.load(io.bundled("hitch_003"))
    monkeypatch.delenv("ASSUR_MAX_MEMORY", raising=False)  # 10¹² positions: 40 TiB
    # the reader's own buffer for a model file (64 MiB at most) is allowed for
    with allocates_little(READ), pytest.raises(ModelFileError, match=r"\[design\] positions"):
        io.load(path)
