"""Generated bad input for the sections and commands added after ``check`` (issue 27).

A seeded generator (the same cases on every run) mutates the sections the later
commands read — ``[[drive]]`` and ``[simulation]`` (``assur simulate``, ``cycles``),
``[design]`` (``sweep``, ``optimize``), ``[tolerances]`` (``tolerance``),
``[lift_test]`` and ``[[solve]]`` (``check``, ``analyze``), ``[motion]`` and
``[range]`` — with odd types, units, zero/negative/huge/NaN values, unicode, deep
nesting, renamed, dropped and duplicated keys and truncated files, and gives every
command options at and beyond their ranges and file arguments that are not files
(a FIFO, a directory, a symlink loop, a NUL byte, a 5,000-character path).

Every case must end as a user error or a clean load — never another exception — and
a file error must name the file, a line within the file and the key; when the key
it names is the one mutated, the line must be the mutated line. An option case must
exit 0, 1 or 2 with no traceback. Each case within 60 s; the memory any command may
plan is capped at :data:`MEMORY` (``ASSUR_MAX_MEMORY``), and the test process's
peak stays below :data:`PEAK`.

In all: 8 × 130 file cases, 3 × 80 option cases, 10 × 6 + 6 path cases and the
file's own command (simulate, cycles, sweep, tolerance, analyze) on one mutated file
of each kind that loads: more than 1,300 cases.
"""

from __future__ import annotations

import os
import random
import re
import resource
import time

import pytest
from typer.testing import CliRunner

from assur import io
from assur.errors import AssemblyError, ModelError, SingularPositionError
from assur.views.cli import app

runner = CliRunner()

#: the memory a command may plan for its arrays in these cases (ASSUR_MAX_MEMORY)
MEMORY = "256 MiB"
#: peak resident memory of the test process after its cases [bytes]
PEAK = 3 * 2**30
#: wall time of one case at most [s]
CASE_SECONDS = 60.0

#: bundled files and the sections of theirs the cases mutate
TARGETS = {
    "adapter_lab6": ("drive", "simulation", "range"),
    "crane_lv184a": ("drive", "simulation", "range"),
    "hitch_003_design": ("design",),
    "hitch_003_tolerances": ("tolerances",),
    "hitch_003": ("lift_test", "solve", "range", "cylinders", "machine"),
    "cleaning_lab3": ("motion", "range", "dynamics"),
}
#: the share of the cases each file gets (its load's cost: a tolerance file solves
#: its design's conditions for the nominal machine)
WEIGHTS = {"adapter_lab6": 5, "crane_lv184a": 5, "hitch_003_design": 5,
           "hitch_003_tolerances": 1, "hitch_003": 5, "cleaning_lab3": 4}
TEXTS = {name: io.bundled(name).read_text(encoding="utf-8") for name in TARGETS}

NUMBERS = ["0", "-0.0", "-1", "1", "2", "1e308", "-1e308", "1e-300", "5e-324", "1e999",
           "nan", "inf", "-inf", "9" * 40, "0.5", "123456789", "1e12", "2e7"]
UNITS = ["m", "mm", "km", "deg", "rad", "N", "kN", "MPa", "Pa", "kg", "s", "ms", "year",
         "rpm", "l/min", "cm^3", "mm^2/s", "kg/m^3", "%", "", "furlong", "m^-400",
         "km^1000", "parsec", "dimensionless"]
NAMES = ["S", "S1", "Smin", "Smax", "L4", "nope", "ГЦ", "56", "01", "phi3", "Y(99)",
         "Y56", "X0", "raise", "lower", "Radau", "hold", "piston"]
UNICODE = ["ф", "Ω", "\u200b", "😀", "\u202e", "Ⅻ", "ﬁ"]


def _value(rng: random.Random) -> str:
    """A TOML value as text, of any kind."""
    kind = rng.choice(["number", "number", "quantity", "quantity", "quantity", "name",
                       "bool", "array", "table", "string", "nest", "date"])
    if kind == "number":
        return rng.choice(NUMBERS)
    if kind == "quantity":
        return f'"{rng.choice(NUMBERS)} {rng.choice(UNITS)}"'
    if kind == "name":
        return f'"{rng.choice(NAMES)}"'
    if kind == "bool":
        return rng.choice(["true", "false"])
    if kind == "array":
        return "[" + ", ".join(rng.choice(NUMBERS[:8] + ['"0.4 m"', '"x"', "true"])
                               for _ in range(rng.randint(0, 4))) + "]"
    if kind == "table":
        return "{ " + ", ".join(f"{rng.choice(['low', 'high', 'from', 'to', 'count', 'x'])}"
                                f" = {rng.choice(NUMBERS[:8])}"
                                for _ in range(rng.randint(0, 3))) + " }"
    if kind == "string":
        return '"' + "".join(rng.choice(UNICODE + ["a", " ", "[red]", "{0}"])
                             for _ in range(rng.randint(0, 12))) + '"'
    if kind == "nest":
        d = rng.randint(2, 300)
        return "[" * d + "1" + "]" * d
    return "1979-05-27"


def _sections(text: str, wanted) -> list[int]:
    """Indices of the lines (``key = value`` and headers) inside the ``wanted``
    top-level sections."""
    out, current = [], None
    for i, line in enumerate(text.splitlines()):
        m = re.match(r"^\s*\[\[?\s*([A-Za-z_]+)", line)
        if m:
            current = m.group(1)
        if current in wanted and line.strip() and not line.lstrip().startswith("#"):
            out.append(i)
    return out


class Case:
    """One mutated file: its name, text and, for a value mutation, the key and the
    (1-based) line mutated."""

    def __init__(self, name, text, how, key=None, line=None):
        self.name, self.text, self.how, self.key, self.line = name, text, how, key, line

    def __repr__(self):
        return f"Case({self.name}, {self.how}, key={self.key}, line={self.line})"


def _mutate(rng: random.Random, name: str) -> Case:
    text = TEXTS[name]
    lines = text.splitlines()
    idx = _sections(text, TARGETS[name])
    i = rng.choice(idx)
    head, sep, tail = lines[i].partition("=")
    key = head.strip().strip('"') if sep else None
    how = rng.choice(["value"] * 6 + ["key", "drop", "duplicate", "truncate", "unicode",
                                      "inline"])
    if how == "value" and sep:
        lines[i] = f"{head.rstrip()} = {_value(rng)}"
        return Case(name, "\n".join(lines) + "\n", how, key, i + 1)
    if how == "key" and sep:
        lines[i] = f"{rng.choice(['x', 'durat1on', 'ГЦ', 'low', 'type'])} ={tail}"
    elif how == "drop":
        lines[i] = "# dropped"
    elif how == "duplicate":
        lines.insert(i + 1, lines[i])
    elif how == "truncate":
        cut = sum(len(x) + 1 for x in lines[:i]) + rng.randint(0, len(lines[i]))
        return Case(name, text[:cut], how)
    elif how == "unicode":
        j = rng.randint(0, len(lines[i]))
        lines[i] = lines[i][:j] + rng.choice(UNICODE) + lines[i][j:]
    else:  # a value written as an inline table of the value
        if sep:
            lines[i] = f"{head.rstrip()} = {{ value = {tail.strip() or '1'} }}"
    return Case(name, "\n".join(lines) + "\n", how)


def _cases(part: int, count: int) -> list[Case]:
    rng = random.Random(27_000 + part)
    names = [n for n, w in WEIGHTS.items() for _ in range(w)]
    return [_mutate(rng, rng.choice(names)) for _ in range(count)]


def _flat(key_path: str) -> list[str]:
    """``drive[3].speed`` → ``["drive", "speed"]``."""
    return [k for k in re.split(r"[.\[\]]", key_path) if k and not k.isdigit()]


def _check_case(case: Case):
    source = io.bundled(case.name)
    t0 = time.perf_counter()
    try:
        io.loads(case.text, name=source.name, source=source)
    except io.ModelFileError as e:
        n = case.text.count("\n") + 1
        assert e.file and 1 <= e.line <= max(n, 1) + 1, (case, str(e))
        assert e.key_path or e.problem.startswith("TOML syntax"), (case, str(e))
        assert f":{e.line}:" in str(e), (case, str(e))
        if (case.how == "value" and e.file == source.name and e.key_path
                and _flat(e.key_path)[-1:] == [case.key]):
            assert e.line == case.line, (case, str(e))
    except (ModelError, AssemblyError, SingularPositionError) as e:
        assert str(e).strip(), case   # a message, never an empty one
    assert time.perf_counter() - t0 < CASE_SECONDS, case


@pytest.fixture(autouse=True)
def _memory_cap(monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", MEMORY)


@pytest.mark.slow
@pytest.mark.parametrize("part", range(8))
def test_fuzz_mutated_sections(part):
    """130 mutated files per part: a user error at the right file:line and key, or a
    clean load; nothing else."""
    failures = []
    for case in _cases(part, 130):
        try:
            _check_case(case)
        except Exception as e:  # noqa: BLE001 - every failing case listed, not the first
            failures.append(f"{case!r}: {type(e).__name__}: {e}"[:400])
    assert not failures, f"{len(failures)} cases:\n" + "\n".join(failures[:25])
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024 < PEAK


def test_the_generator_reaches_every_section():
    """The cases cover every targeted section of every file, each kind of mutation,
    and values that load cleanly as well as errors (so the suite tests both)."""
    cases = [c for part in range(8) for c in _cases(part, 130)]
    assert len(cases) >= 1000
    hows = {c.how for c in cases}
    assert hows >= {"value", "key", "drop", "duplicate", "truncate", "unicode", "inline"}
    for name, sections in TARGETS.items():
        lines = TEXTS[name].splitlines()
        hit = set()
        for c in cases:
            if c.name == name and c.line:
                for s in sections:
                    if c.line - 1 in _sections(TEXTS[name], (s,)):
                        hit.add(s)
        assert hit == set(sections), (name, hit)
        assert lines


# ---- the commands' options ---------------------------------------------------------

NO_FILE = "no/such/model.toml"
OPTION_VALUES = ["0", "1", "2", "-1", "2e7", "1e9", "1e308", "nan", "inf", "-inf", "",
                 " ", "x", "ünï", "18446744073709551616", "1.5", "0x10", "[red]x[/red]",
                 "1e-300", "4294967296", "tcp://", "localhost:0", "ru", "imperial"]
#: command → its options that take a value
COMMANDS = {
    "check": [],
    "analyze": ["--format", "--lang", "--units", "--draw-at", "--frames", "--jobs"],
    "tables": ["--columns", "--lang", "--units", "--table"],
    "simulate": ["--duration", "--lang", "--units"],
    "cycles": ["--lang", "--units"],
    "sweep": ["--samples", "--seed", "--positions", "--chunk", "--workers", "--scheduler",
              "--var"],
    "optimize": ["--popsize", "--maxiter", "--seed", "--positions", "--chunk", "--workers",
                 "--scheduler", "--var", "--lang"],
    "tolerance": ["--samples", "--seed", "--lang"],
    "fit": ["--screen", "--starts", "--outlier", "--fit"],
    "dxf": ["--at"],
}


def _option_args(rng: random.Random, tmp):
    command = rng.choice(sorted(COMMANDS))
    args = [command, NO_FILE]
    if command == "fit":
        args += ["table.csv", "--fit", "L4=0.5:0.8"]
    if command in ("analyze", "simulate", "cycles", "sweep", "optimize", "tolerance", "dxf"):
        args += ["-o", str(tmp / "out")]
    for _ in range(rng.randint(1, 3)):
        if COMMANDS[command]:
            args += [rng.choice(COMMANDS[command]), rng.choice(OPTION_VALUES)]
    return args


def _assert_clean(r, args):
    assert r.exit_code in (0, 1, 2), (args, r.exit_code, r.output)
    assert r.exception is None or isinstance(r.exception, SystemExit), (args, r.exception)
    assert "Traceback" not in r.output, (args, r.output)


@pytest.mark.parametrize("part", range(3))
def test_fuzz_command_options(part, tmp_path):
    """80 commands per part with one to three options at and beyond their ranges
    (the model file missing: what reaches the command fails there, exit 1)."""
    rng = random.Random(2700 + part)
    for _ in range(80):
        args = _option_args(rng, tmp_path)
        t0 = time.perf_counter()
        r = runner.invoke(app, args)
        _assert_clean(r, args)
        assert time.perf_counter() - t0 < CASE_SECONDS, args


# ---- file arguments that are not model files ---------------------------------------

def _odd_paths(tmp):
    fifo = tmp / "fifo.toml"
    os.mkfifo(fifo)
    loop = tmp / "loop.toml"
    loop.symlink_to(tmp / "loop2.toml")
    (tmp / "loop2.toml").symlink_to(loop)
    (tmp / "dir.toml").mkdir()
    return {"fifo": str(fifo), "symlink loop": str(loop), "directory": str(tmp / "dir.toml"),
            "NUL": str(tmp / "a\x00b.toml"), "long": str(tmp / ("x" * 5000 + ".toml")),
            "missing": str(tmp / "none.toml")}


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_file_arguments_that_are_not_files(command, tmp_path):
    """Each command given a FIFO, a directory, a symlink loop, a NUL byte, a
    5,000-character path or a missing file: one message (exit 1 or 2), no hang."""
    for what, path in _odd_paths(tmp_path).items():
        args = [command, path]
        if command == "fit":
            args += [str(io.bundled("hitch_003")), "--fit", "L4=0.5:0.8"]
            args[1:3] = [str(io.bundled("hitch_003")), path]   # the table is the odd one
        if command in ("analyze", "simulate", "cycles", "sweep", "optimize", "tolerance",
                       "dxf"):
            args += ["-o", str(tmp_path / "out")]
        t0 = time.perf_counter()
        r = runner.invoke(app, args)
        _assert_clean(r, args)
        assert r.exit_code in (1, 2), (what, args, r.output)
        assert time.perf_counter() - t0 < CASE_SECONDS, (what, args)


@pytest.mark.parametrize("what", ["fifo", "symlink loop", "directory", "NUL", "long",
                                  "missing"])
def test_extends_of_a_path_that_is_not_a_file(what, tmp_path):
    """``extends`` naming a FIFO, a directory, a symlink loop, a NUL byte, a long path
    or a missing file: a ModelFileError at the ``extends`` key's line."""
    path = _odd_paths(tmp_path)[what].replace("\x00", "\\u0000")   # TOML's escape
    text = f'extends = "{path}"\n\n[model]\nname = "x"\n'
    with pytest.raises(io.ModelFileError) as e:
        io.loads(text, name="child.toml", source=tmp_path / "child.toml")
    assert e.value.line == 1 and e.value.key_path == "extends", str(e.value)


# ---- the commands on mutated files that load -----------------------------------------

#: the command each file's sections serve, with settings that keep a run short
RUNS = {
    "adapter_lab6": ["simulate", "--duration", "0.02"],
    "crane_lv184a": ["cycles"],
    "hitch_003_design": ["sweep", "--samples", "8", "--positions", "3"],
    "hitch_003_tolerances": ["tolerance", "--samples", "8"],
    "hitch_003": ["analyze", "--format", "csv"],
    "cleaning_lab3": ["analyze", "--format", "csv"],
}


def _clean_cases(per_file: int):
    """The first ``per_file`` mutated files of each name that load without an error."""
    out = {name: [] for name in RUNS}
    for part in range(8):
        for case in _cases(part, 130):
            if len(out[case.name]) >= per_file:
                continue
            src = io.bundled(case.name)
            try:
                io.loads(case.text, name=src.name, source=src)
            except (ModelError, AssemblyError, SingularPositionError):
                continue
            out[case.name].append(case)
    return [c for cases in out.values() for c in cases]


#: a second command of a file (run on the same mutated cases): optimize, dxf
SECOND_RUNS = {
    "hitch_003_design": ["optimize", "--popsize", "5", "--maxiter", "2", "--positions", "3",
                         "--no-polish"],
    "hitch_003": ["dxf", "--at", "0.5,0.6"],
}
#: where each command writes
OUTPUTS = {"sweep": "out.parquet", "dxf": "out.dxf"}


@pytest.mark.slow
@pytest.mark.parametrize("case, run", [(c, RUNS[c.name]) for c in _clean_cases(1)]
                         + [(c, SECOND_RUNS[c.name]) for c in _clean_cases(1)
                            if c.name in SECOND_RUNS], ids=repr)
def test_the_command_on_a_mutated_file_that_loads(case, run, tmp_path):
    """The file's own command (and optimize, dxf) on a mutated file that loads: its
    results or one message (exit 0 or 1), no traceback; what it writes after exit 0
    has no NaN or infinity (the commands check)."""
    path = tmp_path / io.bundled(case.name).name
    text = case.text
    m = re.search(r'^extends = "([^"]+)"', text, re.M)
    if m:  # the base beside it, as in the package
        base = m.group(1)
        (tmp_path / base).write_text(io.bundled(base[:-5]).read_text(encoding="utf-8"),
                                     encoding="utf-8")
    path.write_text(text, encoding="utf-8")
    command, *extra = run
    out = tmp_path / OUTPUTS.get(command, "out")
    args = [command, str(path), *extra, "-o", str(out)]
    t0 = time.perf_counter()
    r = runner.invoke(app, args)
    _assert_clean(r, args)
    assert r.exit_code in (0, 1), (args, r.output)
    assert time.perf_counter() - t0 < CASE_SECONDS, args
    if r.exit_code == 0:
        assert out.exists(), args
        assert _not_finite_written(out) == [], args


_NOT_FINITE = re.compile(r"(?<![\w.])[-+]?(nan|inf|infinity)(?![\w.])", re.I)


def _not_finite_written(out):
    """The files under ``out`` that hold a NaN or an infinite value: a CSV, HTML, TOML
    or DXF file with the word (nan, inf) as a value, a Parquet file with a NaN or an
    infinite float (a null, a design that did not evaluate, is not one)."""
    import pyarrow.compute as pc
    import pyarrow.parquet as pq

    bad = []
    files = [out] if out.is_file() else sorted(p for p in out.rglob("*") if p.is_file())
    for f in files:
        if f.suffix in (".csv", ".html", ".toml", ".dxf", ""):
            text = f.read_text(encoding="utf-8-sig", errors="replace")
            if f.suffix == ".html":  # the values of the tables, not the page's script
                text = re.sub(r"<script.*?</script>|<svg.*?</svg>|data:[^\"')]*", "", text,
                              flags=re.S)
            if _NOT_FINITE.search(text):
                bad.append(f.name)
        elif f.suffix == ".parquet":
            table = pq.read_table(f)
            for name in table.column_names:
                col = table[name]
                if col.type in ("double", "float") and (
                        pc.any(pc.is_nan(col)).as_py()
                        or pc.any(pc.is_inf(col)).as_py()):
                    bad.append(f"{f.name}:{name}")
    return bad


def test_the_check_of_written_files_finds_nan_and_inf(tmp_path):
    """The check above can fail: a NaN in a CSV, an infinity in a table of an HTML
    report and a NaN in a Parquet column are found; finite numbers, the word
    "information" and a null are not."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    (tmp_path / "ok.csv").write_text("S;F\n0,42;1e-5\ninformation;\n", encoding="utf-8")
    (tmp_path / "ok.html").write_text('<img src="data:image/png;base64,AB/nan/+inf=">',
                                      encoding="utf-8")
    assert _not_finite_written(tmp_path) == []
    (tmp_path / "t.csv").write_text("S,F\n0.42,nan\n", encoding="utf-8")
    (tmp_path / "r.html").write_text("<td>-inf</td><script>x = NaN</script>",
                                     encoding="utf-8")
    pq.write_table(pa.table({"a": [1.0, float("nan")], "b": [1.0, None]}),
                   tmp_path / "d.parquet")
    assert _not_finite_written(tmp_path) == ["d.parquet:a", "r.html", "t.csv"]
