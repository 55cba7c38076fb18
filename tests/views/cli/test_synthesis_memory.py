"""The client's memory of a large sweep (issue 26): ``assur sweep --samples 1e7``
streams its results to the Parquet dataset chunk by chunk, so the process's peak
resident memory does not grow with the number of designs.

Bound: 2 GiB peak RSS for 1e7 designs (measured 0.45–0.6 GB with the kernel in the
cache: the interpreter, numpy, pyarrow and one chunk; up to 1.0 GB when the process
compiles the kernel first — numba's compiler — on a busy machine). Before issue 26 the client held every result and
concatenated them: 5.9 GB at 1e7 designs — and even the streamed run reached 1.4 GB
while each chunk's reference cycles waited for a full garbage collection. Two
positions per design keep the run within about a minute.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pyarrow.parquet as pq
import pytest

from assur.io import bundled

#: the peak resident memory allowed to the sweep's process [bytes]
BOUND = 2 << 30


@pytest.mark.slow
def test_a_sweep_of_1e7_designs_stays_below_2_gib(tmp_path):
    out = tmp_path / "s.parquet"
    assur = Path(sys.executable).parent / "assur"
    with open(tmp_path / "out.txt", "w") as so, open(tmp_path / "err.txt", "w") as se:
        p = subprocess.Popen([str(assur), "sweep", str(bundled("hitch_003_design")),
                              "--samples", "1e7", "--positions", "2", "--chunk", "65536",
                              "-o", str(out)], stdout=so, stderr=se)
    try:
        _, status, usage = os.wait4(p.pid, 0)  # this child's own peak, not other tests'
    except BaseException:
        p.kill()
        raise
    p.returncode = os.waitstatus_to_exitcode(status)
    assert p.returncode == 0, (tmp_path / "err.txt").read_text()
    peak = usage.ru_maxrss * 1024  # KiB on Linux
    assert peak < BOUND, f"peak RSS {peak / 2**30:.2f} GiB ≥ {BOUND / 2**30:g} GiB"
    parts = sorted(out.glob("part-*.parquet"))
    assert sum(pq.read_metadata(f).num_rows for f in parts) == 10_000_000
    stdout = " ".join((tmp_path / "out.txt").read_text().split())
    assert "10000000 designs × 2 positions on this process" in stdout
