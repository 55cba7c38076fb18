"""The cache of ``[[solve]]`` roots (``assur.io._solve_cache``): a hit gives the roots
of a fresh solve without solving; a corrupt, stale or foreign entry is ignored and
the conditions solved again; edits of the file change the key; the directory
follows ``ASSUR_CACHE_DIR``."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from assur import io
from assur.synthesis import conditions as synthesis
from assur.io import _solve_cache

HITCH = io.bundled("hitch_003")


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """Entries in a directory of this test; counts the calls of solve_conditions."""
    monkeypatch.setattr(_solve_cache, "directory", lambda: tmp_path / "solve")
    calls = []
    real = synthesis.solve_conditions

    def counting(mech, conds, *a, **kw):
        calls.append([c.unknown for c in conds])
        return real(mech, conds, *a, **kw)

    monkeypatch.setattr(synthesis, "solve_conditions", counting)
    return tmp_path / "solve", calls


def roots(model):
    return {s.condition.unknown: s.value for s in model.solved}


def entry(directory):
    files = list(directory.glob("*.json"))
    assert len(files) == 1, files
    return files[0]


def test_hit_gives_the_fresh_roots_without_solving(cache):
    directory, calls = cache
    fresh = io.load(HITCH)
    assert calls == [["L4", "Sp", "L7"]]
    cached = io.load(HITCH)
    assert calls == [["L4", "Sp", "L7"]]  # not solved again
    assert roots(cached) == roots(fresh)
    # seed 003 §2.2–2.3: the exact Find roots (BRIEF.md, printed to 4 digits)
    assert roots(cached) == pytest.approx({"L4": 0.661283167, "Sp": 0.469356940,
                                           "L7": 0.752169525}, abs=1e-9)
    for a, b in zip(fresh.solved, cached.solved):
        assert a.condition == b.condition
        assert (a.residual, a.evaluations, a.notes) == (b.residual, b.evaluations, b.notes)
    assert dict(cached.mechanism.params) == dict(fresh.mechanism.params)


@pytest.mark.parametrize("garbage", ["", "{not json", '{"roots": 3}', '{"roots": [{"unknown": '
                                     '"L4"}]}', json.dumps({"roots": []})])
def test_corrupt_entry_is_ignored_and_rewritten(cache, garbage):
    directory, calls = cache
    fresh = io.load(HITCH)
    path = entry(directory)
    path.write_text(garbage)
    again = io.load(HITCH)
    assert len(calls) == 2
    assert roots(again) == roots(fresh)
    assert [r["unknown"] for r in json.loads(path.read_text())["roots"]] == ["L4", "Sp", "L7"]


def test_cached_root_whose_residual_fails_is_solved_again(cache):
    directory, calls = cache
    fresh = io.load(HITCH)
    path = entry(directory)
    data = json.loads(path.read_text())
    data["roots"][1]["value"] += 1e-6  # Sp off by 1 µm: Y56(Sp) misses 0.4 m
    path.write_text(json.dumps(data))
    again = io.load(HITCH)
    assert len(calls) == 2
    assert roots(again) == roots(fresh)
    assert json.loads(path.read_text())["roots"][1]["value"] == roots(fresh)["Sp"]


def test_entry_of_other_unknowns_is_ignored(cache):
    directory, calls = cache
    fresh = io.load(HITCH)
    path = entry(directory)
    data = json.loads(path.read_text())
    data["roots"][0]["unknown"] = "L5"
    path.write_text(json.dumps(data))
    assert roots(io.load(HITCH)) == roots(fresh)
    assert len(calls) == 2


def test_an_edit_of_the_file_is_a_new_entry(cache):
    directory, calls = cache
    text = HITCH.read_text(encoding="utf-8")
    a = io.loads(text, source=HITCH)
    edited = text.replace('equals = "0.2 m"', 'equals = "0.21 m"', 1)
    assert edited != text
    b = io.loads(edited, source=HITCH)
    assert len(calls) == 2 and len(list(directory.glob("*.json"))) == 2
    assert roots(b)["L4"] != roots(a)["L4"]


def test_unwritable_cache_solves(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setattr(_solve_cache, "directory", lambda: blocker / "solve")
    assert roots(io.load(HITCH))["L4"] == pytest.approx(0.661283167, abs=1e-9)


def test_directory_follows_assur_cache_dir():
    # conftest sets ASSUR_CACHE_DIR for the tests
    assert _solve_cache.directory() == Path(os.environ["ASSUR_CACHE_DIR"]) / "solve"


def test_a_cached_check_does_not_import_scipy_optimize(tmp_path):
    code = ("import sys; from assur import io; io.load(io.bundled('hitch_003')); "
            "print('scipy.optimize' in sys.modules)")
    env = dict(os.environ)
    runs = [subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           env=env, check=True).stdout.split()[-1] for _ in range(2)]
    assert runs[1] == "False"
