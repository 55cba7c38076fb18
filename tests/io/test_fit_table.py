"""Reading ``assur fit``'s printed table (:mod:`assur.io._fit_table`, issue 27): what is
not a regular UTF-8 CSV table of positions is one message naming the file (and the
line or row), never a hang or a traceback."""

from __future__ import annotations

import os

import pytest

from assur import examples, io
from assur.errors import ModelError

HEAD = "S [m],Y(56) [m]\n"


@pytest.fixture(scope="module")
def hitch():
    return examples.hitch_003()


def _table(tmp_path, data: bytes | str, name="t.csv"):
    p = tmp_path / name
    p.write_bytes(data.encode("utf-8") if isinstance(data, str) else data)
    return p


def test_a_table_as_printed_gives_its_targets(tmp_path, hitch):
    t = io.read_targets(_table(tmp_path, HEAD + "0.42,0.2\n0.5,0.4\n"), hitch)
    assert [x.name for x in t] == ["Y(56)"] and list(t[0].positions) == [0.42, 0.5]


@pytest.mark.parametrize("data, words", [
    (HEAD + "0.42,0.2\n0.42,0.2\n", "row 3: S = 0.42 [m] again (row 2)"),
    ("S [m]\n0.42\n", "only 'S [m]'"),
    (HEAD + "0.42,\n0.5,\n", "no values under the columns ['Y(56)']"),
    (HEAD.encode() + b"0.42,0.2\xe9\n", "line 2: not UTF-8 text (byte 0xe9)"),
    (HEAD + "0.42," + "1" * 140_000 + "\n", "line 2: field larger than field limit"),
    (HEAD, "expected a header and at least one row"),
])
def test_a_bad_table_is_one_message(tmp_path, hitch, data, words):
    p = _table(tmp_path, data)
    with pytest.raises(ModelError) as e:
        io.read_targets(p, hitch)
    assert str(e.value).startswith(str(p)) and words in str(e.value), str(e.value)


def test_a_fifo_or_a_directory_is_refused_before_it_is_opened(tmp_path, hitch):
    fifo = tmp_path / "t.csv"
    os.mkfifo(fifo)   # opening it would block until a writer came
    with pytest.raises(ModelError, match="not a regular file .* expected a printed table"):
        io.read_targets(fifo, hitch)
    with pytest.raises(ModelError, match="is a directory; expected a printed table"):
        io.read_targets(tmp_path, hitch)


def test_a_table_larger_than_the_limit(tmp_path, hitch, monkeypatch):
    from assur.io import _fit_table
    monkeypatch.setattr(_fit_table, "MAX_TABLE_BYTES", 2**20)
    p = _table(tmp_path, HEAD + "0.42,0.2\n" * 200_000)   # 1.8 MiB
    with pytest.raises(ModelError, match="the file has 1.7 MiB; a printed table may have at "
                                         "most 1 MiB"):
        io.read_targets(p, hitch)
