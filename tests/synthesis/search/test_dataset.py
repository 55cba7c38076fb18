"""A sweep's Parquet dataset (:mod:`assur.synthesis.search.dataset`, issue 26): the
table's schema carries units and descriptions, ``status`` is named categories, a
design that does not assemble has null criteria (not 0.0); parts and a manifest; a
resumed run computes only the missing designs and equals an uninterrupted one; a run
of another seed is not resumed; a folder that is not a sweep is refused."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pyarrow.parquet as pq
import pytest

from assur import io
from assur.errors import ModelError
from assur.io import load_problem
from assur.synthesis.search.dataset import MANIFEST, STATUS_NAMES, Dataset
from assur.synthesis.search.problem import ASSEMBLY, FEASIBLE
from assur.synthesis.search.scale import Chunk, Executor, sweep, sweep_to


@pytest.fixture(scope="module")
def problem():
    return load_problem(io.bundled("hitch_003_design"), positions=6)  # pivots ±30 mm


def _frame(path):
    return pd.read_parquet(path).sort_values("design").reset_index(drop=True)


def test_units_categories_and_nulls(problem, tmp_path):
    r = sweep_to(problem, tmp_path / "s.parquet", samples=3000, seed=4,
                 executor=Executor(chunk=1000))
    b = sweep(problem, samples=3000, seed=4)
    df = _frame(tmp_path / "s.parquet")
    assert df["design"].tolist() == list(range(3000))
    np.testing.assert_array_equal(df[list(problem.names)].to_numpy(), b.X)
    # status: named categories, the same as the batch's codes
    assert str(df["status"].dtype) == "category"
    assert set(df["status"].cat.categories) == set(STATUS_NAMES.values())
    assert df["status"].tolist() == [STATUS_NAMES[int(s)] for s in b.status]
    # criteria: null where a design does not assemble, the values elsewhere
    obj = f"objective: maximize {problem.objectives[0].name}"
    asm = b.status == ASSEMBLY
    assert asm.sum() > 10
    assert df.loc[asm, obj].isna().all()
    assert not df.loc[b.status == FEASIBLE, obj].isna().any()
    np.testing.assert_array_equal(df.loc[~asm & (b.status != 3), obj].to_numpy(),
                                  b.objectives[~asm & (b.status != 3), 0])
    # units and descriptions in the schema: SI (the pressure in Pa), a reserve in %
    part = sorted((tmp_path / "s.parquet").glob("part-*.parquet"))[0]
    schema = pq.read_schema(part)
    meta = {f.name: {k.decode(): v.decode() for k, v in f.metadata.items()} for f in schema}
    assert meta["X01"]["unit"] == "m" and "bounds" in meta["X01"]["description"]
    assert meta["constraint: max p(ГЦ)"]["unit"] == "Pa"
    assert meta[obj]["unit"] == "%"
    man = json.loads((tmp_path / "s.parquet" / MANIFEST).read_text(encoding="utf-8"))
    assert man["complete"] and man["samples"] == 3000 and man["seed"] == 4
    assert man["columns"]["constraint: max p(ГЦ)"]["unit"] == "Pa"
    assert r.feasible == int(b.feasible.sum()) and r.best[0] == b.best()


def test_resume_computes_only_the_missing_designs(problem, tmp_path):
    out = tmp_path / "s.parquet"
    ds = Dataset(out, problem, samples=2500, seed=7).open()
    from assur.synthesis.search.scale import run_chunk
    for a, b in ((0, 500), (1500, 2000)):  # an interrupted run: two parts written
        ds.write(*run_chunk(problem, Chunk(a, b, seed=7, out="part")))
    computed = []
    ex = Executor(chunk=400, progress=lambda done, total: computed.append((done, total)))
    r = sweep_to(problem, out, samples=2500, seed=7, executor=ex, resume=True)
    assert (r.resumed, r.computed) == (1000, 1500) and computed[-1] == (1500, 1500)
    whole = sweep_to(problem, tmp_path / "w.parquet", samples=2500, seed=7)
    pd.testing.assert_frame_equal(_frame(out), _frame(tmp_path / "w.parquet"))
    assert (r.feasible, r.best, r.reasons) == (whole.feasible, whole.best, whole.reasons)
    # another seed is not resumed; without resume the parts are replaced
    with pytest.raises(ModelError, match=r"cannot resume: --seed differ"):
        sweep_to(problem, out, samples=2500, seed=8, resume=True)
    again = sweep_to(problem, out, samples=100, seed=8)
    assert again.resumed == 0 and len(_frame(out)) == 100


def test_a_folder_that_is_not_a_sweep_is_refused_and_a_file_replaced(problem, tmp_path):
    other = tmp_path / "mine"
    other.mkdir()
    (other / "notes.txt").write_text("keep me")
    with pytest.raises(ModelError, match="not an assur sweep"):
        sweep_to(problem, other, samples=10, seed=1)
    assert (other / "notes.txt").read_text() == "keep me"
    old = tmp_path / "old.parquet"
    old.write_bytes(b"PAR1 an older sweep's single file")
    sweep_to(problem, old, samples=10, seed=1)
    assert old.is_dir() and len(_frame(old)) == 10
