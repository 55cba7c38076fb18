"""Checks of written reports shared by the report tests."""

from __future__ import annotations

import csv
import math
from pathlib import Path


def assert_csvs_clean(directory: Path, name: str) -> list[Path]:
    """Every CSV table in ``directory`` has unique headers and only finite numbers,
    none written ``-0.0``; returns the files (at least one)."""
    files = sorted(Path(directory).glob("*.csv"))
    assert files, f"{name}: no CSV file in {directory}"
    for f in files:
        with open(f, encoding="utf-8") as fh:
            rows = list(csv.reader(fh))
        assert len(set(rows[0])) == len(rows[0]), f"{name}: {f.name}: duplicate headers"
        for row in rows[1:]:
            for cell in row:
                assert math.isfinite(float(cell)), f"{name}: {f.name} holds {cell}"
                assert cell != "-0.0", f"{name}: {f.name} holds -0.0"
    return files
