"""docs/outputs.md documents every output file and every column the bundled models
produce: a new column or file without its line in the reference fails here."""

import re
from pathlib import Path

import pytest

from assur import io
from assur.views.report import seed_tables, write_report
from tests.helpers import DOCS

DOC = DOCS / "outputs.md"


def _alt(names):
    return "(?:" + "|".join(re.escape(str(n)) for n in sorted(names, key=len, reverse=True)) + ")"


def _placeholders(mech=None):
    """What each placeholder of the reference stands for in ``mech`` (its coordinates,
    points, links, axles); ``<formula>`` is the model's own and checked by name."""
    if mech is None:
        return {"<name>": r"\w+", "<formula>": None, "<n>": "[0-9]+"}
    links = [l.name for l in mech.links] + list(mech.bodies)
    axles = list(mech.machine.machine.axles) if mech.machine is not None else []
    springs = [ld.name for ld in mech.loads if type(ld).__name__ == "Spring"]
    return {"<c>": _alt(mech.coordinates), "<p>": _alt(mech.points + mech.frame_points),
            "<l>": _alt(links), "<i><j>": _alt(links) + _alt(links),
            "<axle>": _alt([a.lower() for a in axles] + axles) if axles else "(?!)",
            "<d>": _alt([d.name for d in mech.distances]) if mech.distances else "(?!)",
            "<s>": _alt(springs) if springs else "(?!)",
            "<formula>": None, "<name>": r"\w+", "<value>": r"-?[0-9][0-9.e+-]*",
            "<n>": "[0-9]+"}


def _patterns(section, mech=None):
    """Regexes of the backticked names in the first cell of the rows of ``section``,
    the placeholders standing for the names of ``mech``."""
    PLACEHOLDER = _placeholders(mech)
    text = DOC.read_text(encoding="utf-8")
    part = text.split(f"## {section}", 1)[1].split("\n## ", 1)[0]
    pats = []
    for row in part.splitlines():
        if not row.startswith("| `"):
            continue
        for name in re.findall(r"`([^`]+)`", row.split("|")[1]):
            if PLACEHOLDER.get(name, "") is None:
                continue
            rx = re.escape(name)
            for ph, sub in PLACEHOLDER.items():
                if sub is not None:
                    rx = rx.replace(re.escape(ph), sub)
            suffix = "(?:_" + PLACEHOLDER["<c>"] + ")?" if mech is not None else ""
            pats.append(re.compile(rx + suffix))  # the _<c> suffix of k > 1
    return pats


def _models():
    return [p.stem for p in sorted(Path(io.bundled("hitch_003")).parent.glob("*.toml"))]


def _assembling(name):
    model = io.load(io.bundled(name))
    try:  # as `assur analyze` does: dynamics, lift test and all
        return model, model.analyze()
    except Exception:  # a bundled file kept as printed (header_000): it cannot assemble
        return model, None


@pytest.mark.parametrize("name", _models())
def test_every_column_is_documented(name):
    model, a = _assembling(name)
    if a is None:
        pytest.skip(f"{name} does not assemble (kept as the seed prints it)")
    pats = _patterns("Columns", model.mechanism)
    own = set(model.mechanism.tables.get("symbols", {}).values())
    own |= set(model.mechanism.tables.get("reactions", {}))
    own |= {f.name for f in model.mechanism.tables.get("formulas", ())}
    for tab in seed_tables(a):
        for c in tab.columns:
            if c.symbol in own or c.symbol.rstrip("xy") in own:
                continue  # the model's own names: documented as renames/formulas
            assert any(p.fullmatch(c.symbol) for p in pats), \
                f"{name}: column {c.symbol!r} of table {tab.id} is not in docs/outputs.md"


@pytest.mark.parametrize("name", ["hitch_003", "cleaning_lab3"])
def test_every_file_is_documented(tmp_path, name):
    _, a = _assembling(name)
    files = [f for fs in write_report(a, tmp_path, formats=("csv", "xlsx", "png", "gif"),
                                      frames=3).values() for f in fs]
    pats = _patterns("Files")
    for f in files:
        assert any(p.fullmatch(Path(f).name) for p in pats), \
            f"{Path(f).name} is not in docs/outputs.md"
    assert len(files) > 10
