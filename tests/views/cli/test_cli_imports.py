"""What each light command imports (issue 28): ``import assur`` loads none of the
heavy libraries; ``assur --version`` and ``--help`` answer without numba, scipy,
pandas, matplotlib, pint or pydantic; ``assur check`` of a file without optional
sections imports no figure, table-builder, rating, tolerance or dynamics module and
never numba (fresh caches); ``assur analyze --format csv,xlsx`` never matplotlib.

Each runs as a whole process (the command's own imports, not this test session's)
and prints the modules it ended with.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from assur import io

from tests.helpers import ROOT

#: run the command named by argv as `assur` does, then print the imported modules
RUN = """
import atexit, json, sys
atexit.register(lambda: print("MODULES=" + json.dumps(sorted(sys.modules))))
args = json.loads(sys.argv[1])
if args == ["import"]:
    import assur
else:
    from assur.views.cli import app
    app(args, prog_name="assur")
"""

HEAVY = ("numba", "scipy", "pandas", "matplotlib", "pint", "pydantic")


def _modules(tmp_path, args):
    env = dict(os.environ, ASSUR_CACHE_DIR=str(tmp_path / "assur-cache"),
               NUMBA_CACHE_DIR=str(tmp_path / "numba-cache"), PYTHONPATH=str(ROOT))
    env.pop("ASSUR_KERNELS", None)  # the default rule: numpy until a kernel is ready
    out = subprocess.run([sys.executable, "-c", RUN, json.dumps(args)], capture_output=True,
                         text=True, env=env, cwd=tmp_path)
    assert out.returncode == 0, out.stderr + out.stdout
    line = next(s for s in out.stdout.splitlines() if s.startswith("MODULES="))
    return set(json.loads(line[len("MODULES="):]))


def _loaded(modules, names):
    return sorted(n for n in names if n in modules or any(m.startswith(n + ".")
                                                          for m in modules))


def test_import_assur_loads_no_heavy_library(tmp_path):
    assert _loaded(_modules(tmp_path, ["import"]), HEAVY + ("numpy",)) == []


@pytest.mark.parametrize("option", ["--version", "--help"])
def test_version_and_help_answer_without_heavy_libraries(tmp_path, option):
    assert _loaded(_modules(tmp_path, [option]), HEAVY) == []


def test_check_imports_only_what_the_file_needs(tmp_path):
    mods = _modules(tmp_path, ["check", str(io.bundled("hitch_003"))])
    assert "assur.io" in mods  # the command ran
    # (scipy.optimize: the hitch's [[solve]] conditions are solved by brentq)
    assert _loaded(mods, ("numba", "matplotlib", "pandas",
                          "assur.views.report.tables", "assur.views.report.figures",
                          "assur.machines.ratings", "assur.synthesis.tolerance",
                          "assur.dynamics.balancing")) == []


def test_a_file_with_ratings_reads_them(tmp_path):
    """The ratings' reader is imported when the file has ``[[rating]]`` (the lazy
    import above is not a reader skipped)."""
    mods = _modules(tmp_path, ["check", str(io.bundled("frontloader_zbar"))])
    assert "assur.machines.ratings" in mods


def test_tables_without_figures_never_import_matplotlib(tmp_path):
    mods = _modules(tmp_path, ["analyze", str(io.bundled("hitch_003")), "-o",
                               str(tmp_path / "out"), "--format", "csv,xlsx"])
    assert (tmp_path / "out" / "tables.xlsx").is_file()
    assert _loaded(mods, ("matplotlib",)) == []  # (PIL: openpyxl imports it)
