"""A printed table read as fitting targets (:mod:`assur.synthesis.fitting`, ``assur fit``).

The CSV's first row is the header: the coordinate, then one column per quantity,
each ``expression [unit]`` — the expression as in ``[[tables.formulas]]``
(``phi(5)``, ``dphi(3)``, ``dphi(5)/dphi(3)``), the unit the values are printed in
(``deg``, ``1/m``, ``-``, ``mm``; pint spelling). Each value keeps the precision it
is printed with: its tolerance is half a unit of its last digit (``21.199`` →
0.0005, ``40`` → 0.5). A decimal comma is read as a point. A column of link angles
``phi(l)`` in degrees is compared modulo 360°. Empty cells are skipped.
"""

from __future__ import annotations

import csv
import io as _io
import math
import re
from pathlib import Path

import numpy as np

from ..errors import ModelError
from ._units import _base_factor

__all__ = ["read_targets", "MAX_TABLE_BYTES"]

#: the size of a printed table at most [bytes]
MAX_TABLE_BYTES = 16 * 2**20

_HEADER = re.compile(r"^\s*(.+?)\s*\[\s*(.*?)\s*\]\s*$")


def _scale(unit, where):
    """SI value of one ``unit``."""
    if unit in ("", "-"):
        return 1.0
    try:
        f = _base_factor(unit)
    except Exception:  # pint raises several types for an unreadable unit
        f = None
    if f is None or not math.isfinite(f) or f <= 0:
        raise ModelError(f"{where}: cannot read the unit {unit!r}")
    return f


def _tolerance(cell):
    """Half a unit of the last printed digit of ``cell`` (a number as printed)."""
    text = cell.strip().lower()
    mant = text.split("e")[0]
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    exp = int(text.split("e")[1]) if "e" in text else 0
    return 0.5 * 10.0 ** (exp - decimals)


def read_targets(path, mechanism):
    """Targets of :func:`assur.synthesis.fitting.fit_parameters` from a CSV table as printed.

    Parameters
    ----------
    path : str or Path
    mechanism : Mechanism
        One coordinate, named by the first column.

    Returns
    -------
    list of Target

    Raises
    ------
    ModelError
        Naming the file, the row or column and what is wrong.
    """
    from . import read_model_bytes

    path = Path(path)
    # a regular file of at most MAX_TABLE_BYTES, checked before it is opened (a FIFO
    # would block), UTF-8 text, no cell beyond the csv module's field limit
    data = read_model_bytes(path, str(path), what="printed table (CSV)",
                            limit=MAX_TABLE_BYTES)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        line = data[:e.start].count(b"\n") + 1
        raise ModelError(f"{path}: line {line}: not UTF-8 text (byte {data[e.start]:#04x}); "
                         f"save the table as UTF-8") from None
    reader = csv.reader(_io.StringIO(text, newline=""))
    try:
        rows = [r for r in reader if any(c.strip() for c in r)]
    except csv.Error as e:
        raise ModelError(f"{path}: line {reader.line_num}: {e}") from None
    if len(rows) < 2:
        raise ModelError(f"{path}: expected a header and at least one row")
    if len(rows[0]) < 2:
        raise ModelError(f"{path}: expected the coordinate's column and at least one column "
                         f"of values, found only {rows[0][0]!r}")
    head = []
    for j, cell in enumerate(rows[0]):
        m = _HEADER.match(cell)
        if not m:
            raise ModelError(f"{path}: column {j + 1}: expected a header 'quantity [unit]', "
                             f"found {cell!r}")
        head.append((m.group(1), m.group(2), _scale(m.group(2), f"{path}: column {j + 1}")))
    coord, _, qscale = head[0]
    if coord not in mechanism.coordinates or len(mechanism.coordinates) != 1:
        raise ModelError(f"{path}: the first column must be the coordinate "
                         f"{list(mechanism.coordinates)}, found {coord!r}")

    def number(i, j, cell):
        try:
            v = float(cell.strip().replace(",", "."))
        except ValueError:
            raise ModelError(f"{path}: row {i + 1}, column {j + 1}: expected a number, found "
                             f"{cell!r}") from None
        if not math.isfinite(v):
            raise ModelError(f"{path}: row {i + 1}, column {j + 1}: not finite: {cell!r}")
        return v

    seen = {}
    for i, r in enumerate(rows[1:], start=1):
        q0 = number(i, 0, r[0])
        if q0 in seen:
            raise ModelError(f"{path}: row {i + 1}: {coord} = {r[0].strip()} [{head[0][1]}] "
                             f"again (row {seen[q0] + 1}): give each position once")
        seen[q0] = i

    from ..synthesis.fitting import Target

    targets = []
    for j, (expr, unit, scale) in enumerate(head[1:], start=1):
        q, v, tol = [], [], []
        for i, r in enumerate(rows[1:], start=1):
            if j >= len(r) or not r[j].strip():
                continue
            q.append(number(i, 0, r[0]) * qscale)
            v.append(number(i, j, r[j]))
            tol.append(_tolerance(r[j].replace(",", ".")))
        if not v:
            continue
        period = 360.0 if unit == "deg" and expr.replace(" ", "").startswith("phi(") else None
        try:
            targets.append(Target(expr, expr, np.array(q), np.array(v), scale=scale,
                                  tolerance=np.array(tol), period=period))
        except ModelError as e:
            raise ModelError(f"{path}: column {j + 1}: {e}") from None
    if not targets:
        raise ModelError(f"{path}: no values under the columns "
                         f"{[h[0] for h in head[1:]]}")
    for t in targets:
        try:
            t._formula.check(mechanism)
        except ModelError as e:
            raise ModelError(f"{path}: column {t.name!r}: {e}") from None
    return targets
