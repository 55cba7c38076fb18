"""A new structure never waits for the compiler on the interactive path (issue 28):
``assur check`` of a model whose structure no cache holds, in a process with fresh
kernel and numba caches and the default rule (``ASSUR_KERNELS`` unset), answers
without numba ever imported — no kernel compiled on any thread — and writes only the
numpy evaluations to the cache. A process that keeps calling a kernel that is not
compiled compiles it in the background (:func:`assur.kernel.vector.rent`) and then
uses it, with the same results to the last bit (the compiled and the numpy evaluation
of the same emitted operations, numba without fastmath; tests/kernel/test_vector.py)."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np

from assur import io
from assur.core import program as P
from assur.kernel import set_cache_dir
from assur.kernel import vector as KV

from tests.helpers import ROOT
from tests.helpers.new_structure import new_structure_model

CHECK = """
import sys
from pathlib import Path
from typer.testing import CliRunner
from assur.views.cli import app
r = CliRunner().invoke(app, ["check", sys.argv[1]])
assert r.exit_code == 0, r.output
print("numba" in sys.modules)
print(sorted(p.name for p in Path(sys.argv[2]).rglob("*") if p.is_file()))
"""


def test_check_of_a_new_structure_compiles_nothing(tmp_path):
    model = new_structure_model(tmp_path, extra=2, seed=11)
    env = {k: v for k, v in os.environ.items() if k != "ASSUR_KERNELS"}  # the default rule
    env.update(ASSUR_CACHE_DIR=str(tmp_path / "assur-cache"),
               NUMBA_CACHE_DIR=str(tmp_path / "numba-cache"), PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-c", CHECK, str(model), str(tmp_path)],
                         capture_output=True, text=True, env=env, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    numba, files = out.stdout.strip().splitlines()
    assert numba == "False"                  # numba never imported: nothing compiled
    files = eval(files)  # noqa: S307 — the list printed above
    assert any(f.startswith("v_") and f.endswith(".py") for f in files), files
    assert not [f for f in files if f.startswith(("k_", "c_")) or f.endswith((".nbi", ".nbc"))]


def test_a_kernel_in_steady_use_is_compiled_in_the_background(tmp_path, monkeypatch):
    set_cache_dir(tmp_path)  # no ready mark: the structure's kernel is not ready here
    KV.set_backend("auto")
    monkeypatch.setattr(KV, "RENT", 0.0)  # the first numpy call pays the rent
    try:
        mech = io.load(new_structure_model(tmp_path, extra=1, seed=5)).mechanism
        prog = P.compile_program(mech)
        ptab = np.ascontiguousarray(prog.param_table(mech.params))
        q = np.linspace(0.43, 0.66, 7)[None, :]
        first = P.execute(prog, ptab, q, 7, True)               # numpy; compiles behind
        assert KV.compiling(wait=True) is False
        kargs = (prog.rows, prog.measures, prog.k, tuple(prog.slot[p] for p in prog.out_pts),
                 tuple(prog.scal[s] for s in prog.out_sca))
        assert KV.is_ready(P._ready_key(kargs))                 # marked, in cache_dir
        assert KV.wanted(7, ready=lambda: True) is False        # compiled from now on
        used, run = [], P.KR.run
        monkeypatch.setattr(P.KR, "run", lambda kern, *a: used.append(KV.is_vector(kern))
                            or run(kern, *a))
        second = P.execute(prog, ptab, q, 7, True)
        assert used == [False]                                  # the compiled kernel ran
        assert np.array_equal(first["status"], second["status"])
        for k in ("pv", "pd", "pdd", "sv", "sd", "sdd"):  # to the last bit
            assert np.array_equal(first[k], second[k]), (k, np.abs(first[k] - second[k]).max())
    finally:
        KV.set_backend(None)
        set_cache_dir(None)
