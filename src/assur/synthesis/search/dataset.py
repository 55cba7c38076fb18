"""A sweep's results as a Parquet dataset of parts, with its manifest
(:func:`assur.synthesis.search.scale.sweep_to`).

A sweep of N designs writes a folder::

    assur-sweep.parquet/
        _manifest.json                         the run: problem, seed, samples, units
        part-000000000000-000000016384.parquet designs 0 … 16383
        part-000000016384-000000032768.parquet …

Each part is the table of one chunk (:func:`part_table`: one row per design, the
design's index first) and carries its summary in its metadata (feasible designs, the
best one, the reasons counted by kind). A part is written under a hidden name and
renamed when complete, so a part file present is a part finished; a rerun with
``resume=True`` and the same problem, seed and number of samples computes only the
designs no part holds (:meth:`Dataset.missing`). ``pandas.read_parquet(folder)``
reads the whole table in design order (files whose names start with ``_`` or ``.``
are not data).

The table's schema carries, per column, its unit (the SI unit of the values; a
reserve in %) and a description; ``status`` is a dictionary (categorical) column of
the words :data:`STATUS_NAMES`; a criterion of a design that did not evaluate (it
does not assemble, the engine refused it, its point does not rise) is null, not 0.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import numpy as np

from ...errors import ModelError
from ._batch import ASSEMBLY, CONSTRAINT, ENGINE, FEASIBLE, LIFT

__all__ = ["Dataset", "part_table", "part_bytes", "write_table", "read_summary", "si_unit", "STATUS_NAMES",
           "MANIFEST"]

#: the manifest's file name in a dataset folder
MANIFEST = "_manifest.json"

#: the format written in the manifest
FORMAT = "assur-sweep/1"

#: the words of :attr:`Batch.status` in the table's ``status`` column
STATUS_NAMES = {FEASIBLE: "feasible", ASSEMBLY: "does not assemble", ENGINE: "refused by the engine",
                LIFT: "does not lift", CONSTRAINT: "constraint violated"}

_PART = re.compile(r"^part-(\d{12})-(\d{12})\.parquet$")

_PREFIX = {"k": 1e3, "M": 1e6, "G": 1e9, "m": 1e-3, "c": 1e-2, "µ": 1e-6, "u": 1e-6}


def si_unit(unit) -> str:
    """The SI unit of values shown in ``unit`` (an :class:`assur.core.quantities.Unit`):
    its text when its scale is 1, ``rad`` for degrees, the unit without its prefix
    (``MPa`` → ``Pa``, ``kN·m`` → ``N·m``).

    Examples
    --------
    >>> import math
    >>> from assur.core.quantities import Unit
    >>> from assur.synthesis.search.dataset import si_unit
    >>> si_unit(Unit("MPa", 1e6)), si_unit(Unit("mm", 1e-3)), si_unit(Unit("%"))
    ('Pa', 'm', '%')
    >>> si_unit(Unit("deg", math.pi / 180)), si_unit(None)
    ('rad', '')
    """
    if unit is None:
        return ""
    if unit.is_degrees:
        return "rad"
    if unit.scale == 1.0:
        return unit.text
    head = unit.text[:1]
    if head in _PREFIX and np.isclose(_PREFIX[head], unit.scale, rtol=1e-12, atol=0):
        return unit.text[1:]
    return f"{unit.text} / {unit.scale:g}"  # [SI]: one shown unit is `scale` SI units


def _columns(problem):
    """(name, kind, unit, description) of the table's columns."""
    cols = [("design", "index", "", "the design's index in the sweep (0-based)")]
    for v in problem.variables:
        cols.append((v.name, "variable", si_unit(v.unit),
                     f"design variable {v.name}, bounds {v.show(v.low)} … {v.show(v.high)}"))
    for c in problem.objectives:
        cols.append((f"objective: {c.sense} {c.name}", "objective", si_unit(c.unit),
                     f"objective ({c.sense}) {c.name}; null where the design did not "
                     f"evaluate"))
    for c in problem.constraints:
        rel = "≥" if c.limit.sense == "at_least" else "≤"
        lim = c.limit.value if isinstance(c.limit.value, str) else c.show(c.limit.value) \
            if c.limit.value is not None else c.limit.sense
        cols.append((f"constraint: {c.name}", "constraint", si_unit(c.unit),
                     f"the value of constraint {c.name} {rel} {lim}; null where the "
                     f"design did not evaluate"))
    cols += [("feasible", "feasible", "", "meets every constraint over every position"),
             ("status", "status", "", "feasible, or why not: " + ", ".join(
                 STATUS_NAMES.values())),
             ("failed_positions", "count", "", "positions at which the design does not "
                                               "assemble"),
             ("violation", "violation", "", "sum of the constraints' violations relative to "
                                            "their limits (a design that did not evaluate: "
                                            "1 + constraints + its share of failed positions)"),
             ("reason", "reason", "", "why the design is infeasible (empty if feasible)")]
    return cols


def part_table(batch, start=0, reasons=None):
    """The :class:`pyarrow.Table` of a batch whose first design has index ``start``:
    one row per design (the columns of :func:`_columns`), units and descriptions in
    the fields' metadata, ``status`` as named categories, null criteria where a design
    did not evaluate.

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.dataset import part_table
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> X = np.array([pb.x0, pb.sample(27, seed=1)[26]])  # the seed's design; one that fails
    >>> t = part_table(pb.evaluate(X), start=100)
    >>> t.column("design").to_pylist(), t.column("status").to_pylist()
    ([100, 101], ['feasible', 'does not assemble'])
    >>> obj = "objective: maximize min reserve(ГЦ, S6, P6)"
    >>> [None if v is None else round(v, 3) for v in t.column(obj).to_pylist()]  # [%]
    [8.941, None]
    >>> t.schema.field("constraint: max p(ГЦ)").metadata[b"unit"]
    b'Pa'
    """
    import pyarrow as pa
    pb = batch.problem
    evaluated = (batch.status == FEASIBLE) | (batch.status == CONSTRAINT)
    missing = ~evaluated
    arrays = [pa.array(np.arange(start, start + len(batch), dtype=np.int64))]
    arrays += [pa.array(batch.X[:, j]) for j in range(len(pb.variables))]
    arrays += [pa.array(batch.objectives[:, j], mask=missing) for j in range(len(pb.objectives))]
    arrays += [pa.array(batch.values[:, j], mask=missing) for j in range(len(pb.constraints))]
    names = list(STATUS_NAMES.values())
    codes = np.asarray(batch.status, np.int8)
    arrays += [pa.array(batch.feasible),
               pa.DictionaryArray.from_arrays(pa.array(codes), pa.array(names)),
               pa.array(np.asarray(batch.failed_positions, np.int64)),
               pa.array(batch.violation),
               pa.array(batch.reasons if reasons is None else reasons,
                        pa.string()).dictionary_encode()]
    fields = [pa.field(name, a.type, metadata={"unit": unit, "kind": kind,
                                               "description": text})
              for (name, kind, unit, text), a in zip(_columns(pb), arrays)]
    meta = {"assur.problem": json.dumps({"name": pb.name, "positions": pb.n_positions,
                                         "identity": pb.identity,
                                         "variables": list(pb.names)})}
    return pa.Table.from_arrays(arrays, schema=pa.schema(fields, metadata=meta))


def _summary(batch, start, reasons):
    """A part's summary: designs, feasible ones, the best (index, objective [SI]),
    the infeasible designs counted by the kind of their reason."""
    feas = batch.feasible
    best = batch.best()
    counts: dict = {}
    from collections import Counter
    for r, k in Counter(reasons).items():
        if r:
            key = r.split(" at position")[0].split(" = ")[0]
            counts[key] = counts.get(key, 0) + int(k)
    return {"start": int(start), "stop": int(start + len(batch)), "feasible": int(feas.sum()),
            "best": None if best < 0 else [int(start + best),
                                           float(batch.objectives[best, 0])],
            "reasons": counts}


def part_bytes(batch, start=0):
    """A part as Parquet bytes (its table, its summary in the schema's metadata under
    ``assur.part``) and the summary: what a worker returns for a chunk.

    Examples
    --------
    >>> import io as bio
    >>> import pyarrow.parquet as pq
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.dataset import part_bytes
    >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
    >>> data, summary = part_bytes(pb.evaluate(pb.draw(1, 0, 50)), start=0)
    >>> summary["stop"], pq.read_table(bio.BytesIO(data)).num_rows
    (50, 50)
    """
    import pyarrow as pa
    import pyarrow.parquet as pq
    reasons = batch.reasons
    table = part_table(batch, start, reasons)
    summary = _summary(batch, start, reasons)
    meta = dict(table.schema.metadata or {})
    meta[b"assur.part"] = json.dumps(summary).encode("utf-8")
    table = table.replace_schema_metadata(meta)
    buf = pa.BufferOutputStream()
    write_table(table, buf)
    return buf.getvalue().to_pybytes(), summary


def write_table(table, where):
    """Write a part's table as Parquet: dictionaries for the status and the reason
    only, statistics for the design index only (a float column's dictionary and
    statistics cost 10× the writing and save nothing on random values).

    Examples
    --------
    >>> import io as bio
    >>> import pyarrow as pa
    >>> import pyarrow.parquet as pq
    >>> from assur.synthesis.search.dataset import write_table
    >>> buf = bio.BytesIO()
    >>> write_table(pa.table({"design": [0, 1], "X01": [0.4, 0.41]}), buf)
    >>> pq.read_table(bio.BytesIO(buf.getvalue())).num_rows
    2
    """
    import pyarrow.parquet as pq
    names = set(table.column_names)
    pq.write_table(table, where, use_dictionary=[c for c in ("status", "reason") if c in names],
                   write_statistics=[c for c in ("design",) if c in names])


def read_summary(path) -> dict:
    """The summary a part file carries (its footer only is read).

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.dataset import part_bytes, read_summary
    >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
    >>> data, summary = part_bytes(pb.evaluate(pb.draw(1, 0, 20)), start=0)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = Path(d) / "part.parquet"
    ...     _ = p.write_bytes(data)
    ...     read_summary(p) == summary
    True
    """
    import pyarrow.parquet as pq
    meta = pq.read_schema(path).metadata or {}
    if b"assur.part" not in meta:
        raise ModelError(f"{path}: not a part of an assur sweep (no assur.part metadata)")
    return json.loads(meta[b"assur.part"])


class Dataset:
    """The folder of a sweep's parts and its manifest.

    Parameters
    ----------
    path : str or os.PathLike
        The folder (made if missing). A single Parquet file there (an older sweep's
        table) is replaced; a folder that is not an assur sweep is refused.
    problem : Problem
    samples : int
        Designs of the sweep.
    seed : int
    resume : bool
        Keep the parts of an earlier run of the same problem, seed and samples (else
        they are removed).

    Examples
    --------
    Two parts of a sweep of 30 designs written, the third missing:

    >>> import tempfile
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.dataset import Dataset, part_bytes
    >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     ds = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1).open()
    ...     for a, b in ((0, 10), (20, 30)):
    ...         ds.write(*part_bytes(pb.evaluate(pb.draw(1, a, b)), start=a))
    ...     again = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1, resume=True).open()
    ...     again.missing(), again.done
    ([(10, 20)], 20)
    """

    def __init__(self, path, problem, samples, seed, resume=False):
        self.path = Path(path)
        self.problem = problem
        self.samples, self.seed, self.resume = int(samples), int(seed), bool(resume)
        self.summaries: list = []

    # ---- the manifest ------------------------------------------------------------------
    def manifest(self) -> dict:
        """What the run is (written to :data:`MANIFEST`; a resumed run must match).

        Examples
        --------
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> m = Dataset("s.parquet", pb, samples=1000, seed=3).manifest()
        >>> m["samples"], m["seed"], m["columns"]["X01"]["unit"]
        (1000, 3, 'm')
        """
        from ... import __version__
        from .problem import BLOCK
        return {"format": FORMAT, "assur": __version__, "problem": self.problem.name,
                "identity": self.problem.identity, "samples": self.samples,
                "seed": self.seed, "block": BLOCK, "positions": self.problem.n_positions,
                "variables": list(self.problem.names),
                "columns": {n: {"unit": u, "kind": k, "description": t}
                            for n, k, u, t in _columns(self.problem)}}

    def open(self):
        """Check the folder, write the manifest and read the finished parts (with
        ``resume``) or remove them (without); returns self.

        Raises
        ------
        ModelError
            The folder is not an assur sweep, or (``resume``) it is one of another
            problem, seed or number of samples.

        Examples
        --------
        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset, part_bytes
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> d = tempfile.mkdtemp()
        >>> (Path(d) / "s.parquet").mkdir()
        >>> _ = (Path(d) / "s.parquet" / "notes.txt").write_text("mine")
        >>> Dataset(f"{d}/s.parquet", pb, samples=10, seed=1).open()  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: .../s.parquet: the folder is not an assur sweep (no _manifest.json); choose another output (-o)
        """
        p = self.path
        if p.is_file() or p.is_symlink() and not p.is_dir():
            p.unlink()  # a single-file table of an older sweep: replaced, as before
        if p.is_dir():
            entries = [e for e in p.iterdir() if not e.name.startswith(".")]
            if entries and not (p / MANIFEST).is_file():
                raise ModelError(f"{p}: the folder is not an assur sweep (no {MANIFEST}); "
                                 f"choose another output (-o)")
        else:
            try:
                p.mkdir(parents=True)
            except OSError as e:
                raise ModelError(f"{p}: cannot make the folder: {e.strerror or e}") from None
        mine = self.manifest()
        if self.resume and (p / MANIFEST).is_file():
            try:
                old = json.loads((p / MANIFEST).read_text(encoding="utf-8"))
            except (OSError, ValueError) as e:
                raise ModelError(f"{p / MANIFEST}: cannot read the manifest: {e}") from None
            for k, what in (("identity", "the model, its variables or positions"),
                            ("seed", "--seed"), ("samples", "--samples"),
                            ("block", "the sampling (another assur version)")):
                if old.get(k) != mine[k]:
                    raise ModelError(f"{p}: cannot resume: {what} differ from the run there "
                                     f"({k}: {old.get(k)!r} there, {mine[k]!r} now); rerun "
                                     f"without --resume to start again")
            self.summaries = [read_summary(f) for f in self._parts()]
        else:
            for f in self._parts():
                f.unlink()
            self.summaries = []
        for f in p.glob(".part-*.tmp"):  # a part being written when a run ended
            f.unlink()
        self._write_json(MANIFEST, {**mine, "complete": False})
        return self

    def _parts(self):
        return sorted(f for f in self.path.iterdir() if _PART.match(f.name))

    def _write_json(self, name, data):
        tmp = self.path / f".{name}.tmp"
        tmp.write_text(json.dumps(data, indent=1, ensure_ascii=False), encoding="utf-8")
        os.replace(tmp, self.path / name)

    # ---- parts -------------------------------------------------------------------------
    @property
    def done(self) -> int:
        """Designs the finished parts hold.

        Examples
        --------
        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset, part_bytes
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> d = tempfile.mkdtemp()
        >>> ds = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1).open()
        >>> ds.write(*part_bytes(pb.evaluate(pb.draw(1, 0, 10)), start=0))
        >>> ds.done
        10
        """
        return sum(s["stop"] - s["start"] for s in self.summaries)

    def missing(self) -> list:
        """The ranges ``(start, stop)`` of designs no finished part holds, in order.

        Examples
        --------
        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset, part_bytes
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> d = tempfile.mkdtemp()
        >>> ds = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1).open()
        >>> ds.write(*part_bytes(pb.evaluate(pb.draw(1, 10, 20)), start=10))
        >>> ds.missing()
        [(0, 10), (20, 30)]
        """
        out, at = [], 0
        for s in sorted(self.summaries, key=lambda s: s["start"]):
            if s["start"] > at:
                out.append((at, s["start"]))
            at = max(at, s["stop"])
        if at < self.samples:
            out.append((at, self.samples))
        return out

    def write(self, data, summary):
        """Write a part's bytes (hidden name, then renamed) and keep its summary.

        Examples
        --------
        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset, part_bytes
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> d = tempfile.mkdtemp()
        >>> ds = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1).open()
        >>> ds.write(*part_bytes(pb.evaluate(pb.draw(1, 0, 30)), start=0))
        >>> sorted(p.name for p in ds.path.iterdir())
        ['_manifest.json', 'part-000000000000-000000000030.parquet']
        """
        a, b = summary["start"], summary["stop"]
        name = f"part-{a:012d}-{b:012d}.parquet"
        tmp = self.path / f".{name}.tmp"
        try:
            tmp.write_bytes(data)
            os.replace(tmp, self.path / name)
        except OSError as e:
            raise ModelError(f"{self.path / name}: cannot write the part: "
                             f"{e.strerror or e}") from None
        self.summaries.append(summary)

    def close(self, seconds=None):
        """Mark the run complete in the manifest (every design written).

        Examples
        --------
        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset, part_bytes
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> d = tempfile.mkdtemp()
        >>> ds = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1).open()
        >>> import json
        >>> ds.write(*part_bytes(pb.evaluate(pb.draw(1, 0, 30)), start=0))
        >>> ds.close(seconds=0.1)
        >>> json.loads((ds.path / "_manifest.json").read_text(encoding="utf-8"))["complete"]
        True
        """
        self._write_json(MANIFEST, {**self.manifest(), "complete": True,
                                    "parts": len(self.summaries), "seconds": seconds})

    # ---- the summary -------------------------------------------------------------------
    def feasible(self) -> int:
        """Feasible designs in the finished parts.

        Examples
        --------
        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset, part_bytes
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> d = tempfile.mkdtemp()
        >>> ds = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1).open()
        >>> ds.write(*part_bytes(pb.evaluate(pb.draw(1, 0, 30)), start=0))
        >>> ds.feasible()
        0
        """
        return sum(s["feasible"] for s in self.summaries)

    def best(self):
        """(index, objective [SI]) of the best feasible design of the finished parts
        for the first objective, or None.

        Examples
        --------
        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset, part_bytes
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> d = tempfile.mkdtemp()
        >>> ds = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1).open()
        >>> ds.write(*part_bytes(pb.evaluate(pb.draw(1, 0, 30)), start=0))
        >>> ds.best() is None
        True
        """
        pb = self.problem
        if not pb.objectives:
            return None
        sign = -1.0 if pb.objectives[0].sense == "maximize" else 1.0
        cands = [s["best"] for s in self.summaries if s["best"] is not None]
        return min(cands, key=lambda c: (sign * c[1], c[0])) if cands else None

    def reasons(self) -> dict:
        """Infeasible designs of the finished parts counted by the kind of reason.

        Examples
        --------
        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.dataset import Dataset, part_bytes
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> d = tempfile.mkdtemp()
        >>> ds = Dataset(f"{d}/s.parquet", pb, samples=30, seed=1).open()
        >>> ds.write(*part_bytes(pb.evaluate(pb.draw(1, 0, 30)), start=0))
        >>> sum(ds.reasons().values())
        30
        """
        out: dict = {}
        for s in self.summaries:
            for k, n in s["reasons"].items():
                out[k] = out.get(k, 0) + n
        return out

