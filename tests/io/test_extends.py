"""``extends = "base.toml"`` (``assur.io._extends``, docs/model-format.md): a model file
as overrides of another — tables merged key by key, arrays of tables merged by
``name`` (``unknown`` for ``[[solve]]``), other values replaced — with every error
located in the file (and at the line) of the key at fault."""

import re

import numpy as np
import pytest

from assur import io
from assur.io import ModelFileError
from tests.helpers import ROOT

#: the complete example of docs/model-format.md, the base of these tests
BASE = re.search(r"```toml\n(.*?)```", (ROOT / "docs" / "model-format.md").read_text(),
                 re.S).group(1)


def line_of(text, pattern):
    """1-based line of the first line of ``text`` that starts with ``pattern``."""
    return next(i for i, l in enumerate(text.splitlines(), 1) if l.startswith(pattern))


@pytest.fixture
def files(tmp_path):
    """Write ``{name: text}`` into tmp_path; return the path of the first."""
    def write(**texts):
        paths = []
        for name, text in texts.items():
            p = tmp_path / f"{name}.toml"
            p.write_text(text)
            paths.append(p)
        return paths[0]
    return write


def test_bundled_fixed_header_is_a_few_lines_over_the_seed_input():
    """header_000_fixed.toml extends header_000.toml: the same machine as the seed's
    input with L4 = 0.652 m, its own name, title and notes."""
    path = io.bundled("header_000_fixed")
    text = path.read_text()
    assert 'extends = "header_000.toml"' in text
    assert len([l for l in text.splitlines() if l.strip() and not l.startswith("#")]) < 20
    fixed = io.load(path)
    seed_text = io.bundled("header_000").read_text()
    full = seed_text.replace('L4 = "0.657 m"', 'L4 = "0.652 m"')
    ref = io.loads(full, name="full.toml").mechanism
    m = fixed.mechanism
    assert m.params["L4"] == 0.652 and ref.params["L4"] == 0.652
    assert dict(m.params) == dict(ref.params) and list(m.params) == list(ref.params)
    assert (m.groups, m.links, m.loads, m.cylinders, dict(m.tables)) == \
        (ref.groups, ref.links, ref.loads, ref.cylinders, dict(ref.tables))
    assert m.name == "header_000_fixed" and "illustrative" in m.title
    assert any("illustrative" in n for n in m.notes)
    r = m.solve(fixed.range)
    assert r.ok.all()


def test_override_a_parameter(files):
    child = files(child='extends = "base.toml"\n[params]\nL5 = "0.5 m"\n', base=BASE)
    m = io.load(child).mechanism
    b = io.load(child.parent / "base.toml").mechanism
    assert m.params["L5"] == 0.5 and b.params["L5"] == 0.48
    assert {k: v for k, v in m.params.items() if k not in ("L5", "L4")} == \
        {k: v for k, v in b.params.items() if k not in ("L5", "L4")}
    assert m.name == "lift" and m.groups[1:] != () and len(m.groups) == len(b.groups)
    # L4 is solved again with the new L5 (the [[solve]] entry comes from the base)
    assert m.params["L4"] != b.params["L4"]
    assert m.solve([0.42]).y("56")[0] == pytest.approx(0.2, abs=1e-12)


def test_override_a_group_by_name_and_append_one(files):
    """A [[groups]] entry with the name of a base group changes only the keys it
    gives; an entry with a new name is appended after the base's groups."""
    child = files(child='extends = "base.toml"\n'
                        '[[groups]]\nname = "II (4,5)"\nrb = "0.5 m"\n'
                        '[[groups]]\ntype = "rigid_point"\nname = "tip"\norigin = "05"\n'
                        'toward = "56"\nout = "T"\nlength = "0.1 m"\nangle = 90\n',
                  base=BASE)
    m = io.load(child).mechanism
    b = io.load(child.parent / "base.toml").mechanism
    names = [g.name for g in m.groups]
    assert names == [g.name for g in b.groups] + ["tip"]
    dyad = m.group("II (4,5)")
    assert dyad.rb == 0.5 and dyad.ra == "L4" and dyad.branch == 1
    assert m.group("I (2,3)") == b.group("I (2,3)")


def test_a_group_with_its_type_replaces_the_base_entry(files):
    """An entry that gives ``type`` is complete: the base's keys (here ``angle``) are
    dropped, so the rigid point can change form; it keeps its place."""
    child = files(child='extends = "base.toml"\n'
                        '[[groups]]\ntype = "rigid_point"\nname = "arm 34"\norigin = "03"\n'
                        'toward = "23"\nout = "34"\nlength = "L34"\nbase = "L3"\n'
                        'opposite = "0.4 m"\nbranch = 1\nlinks = ["3"]\n',
                  base=re.sub(r"(?ms)^\[\[solve\]\].*", "", BASE))
    m = io.load(child).mechanism  # the base's `angle` is gone: no "both forms" error
    b = io.load(child.parent / "base.toml").mechanism
    assert [g.name for g in m.groups] == [g.name for g in b.groups]
    assert m.group("arm 34") != b.group("arm 34")


def test_solve_entries_merge_by_unknown(files):
    child = files(child='extends = "base.toml"\n[[solve]]\nunknown = "L4"\nequals = "0.25 m"\n',
                  base=BASE)
    model = io.load(child)
    assert len(model.solved) == 1 and model.solved[0].condition.target == 0.25
    assert model.mechanism.solve([0.42]).y("56")[0] == pytest.approx(0.25, abs=1e-12)


def test_nested_extends_and_arrays_of_values_replaced(files):
    top = files(top='extends = "mid.toml"\n[params]\nL3 = "0.21 m"\n',
                mid='extends = "base.toml"\n[model]\nname = "mid"\nnotes = ["only this"]\n'
                    '[params]\nL3 = "0.205 m"\nL5 = "0.49 m"\n',
                base=BASE)
    m = io.load(top).mechanism
    assert (m.name, m.notes) == ("mid", ("only this",))
    assert (m.params["L3"], m.params["L5"]) == (0.21, 0.49)
    assert m.coordinates == ("S",)


def test_a_cycle_is_refused(files):
    a = files(a='extends = "b.toml"\n[params]\nL3 = "0.2 m"\n',
              b='# b\nextends = "a.toml"\n', )
    with pytest.raises(ModelFileError) as exc:
        io.load(a)
    e = exc.value
    assert e.key_path == "extends" and e.file.endswith("b.toml") and e.line == 2
    assert "cycle" in e.problem and "a.toml → b.toml → a.toml" in e.problem


def test_a_file_extending_itself_is_refused(files):
    a = files(a='extends = "a.toml"\n')
    with pytest.raises(ModelFileError, match=r"a\.toml:1: extends: .*cycle"):
        io.load(a)


def test_a_missing_base_file(files):
    a = files(a='# a fix of a missing base\n\nextends = "nowhere/base.toml"\n[params]\nL3 = 1\n')
    with pytest.raises(ModelFileError) as exc:
        io.load(a)
    e = exc.value
    assert (e.file, e.line, e.key_path) == (str(a), 3, "extends")
    assert 'cannot read the base file "nowhere/base.toml": no such file' in e.problem


def test_extends_must_be_a_path(files):
    a = files(a='extends = 3\n')
    with pytest.raises(ModelFileError, match=r"a\.toml:1: extends: expected the path"):
        io.load(a)


def test_an_error_in_a_base_key_is_located_in_the_base_file(files):
    bad = BASE.replace('L56 = "1.035 m"', 'L56 = "1.035 kg"')
    child = files(child='extends = "base.toml"\n[params]\nL5 = "0.5 m"\n', base=bad)
    with pytest.raises(ModelFileError) as exc:
        io.load(child)
    e = exc.value
    base = child.parent / "base.toml"
    assert e.file == str(base) and e.key_path == "params.L56"
    assert e.line == line_of(bad, "L56 =")
    assert str(e).startswith(f"{base}:{e.line}: params.L56: ")


def test_an_error_in_a_merged_group_key_is_located_where_the_key_is(files):
    """In a group merged from both files, a key of the base is located in the base, a
    key of the child in the child."""
    child_text = ('extends = "base.toml"\n\n[[groups]]\nname = "II (4,5)"\n'
                  'rb = "0.5 deg"\n')
    child = files(child=child_text, base=BASE)
    with pytest.raises(ModelFileError) as exc:
        io.load(child)
    e = exc.value
    assert (e.file, e.line, e.key_path) == (str(child), 5, "groups[2].rb")
    bad = BASE.replace('ra = "L4"', 'ra = "L44"')
    child = files(child='extends = "base.toml"\n[[groups]]\nname = "II (4,5)"\nrb = "0.5 m"\n',
                  base=bad)
    with pytest.raises(ModelFileError) as exc:
        io.load(child)
    e = exc.value
    assert (e.file, e.key_path) == (str(child.parent / "base.toml"), "groups[2].ra")
    assert e.line == line_of(bad, 'ra = "L44"')


def test_an_error_in_the_child_is_located_in_the_child(files):
    child = files(child='extends = "base.toml"\n[params]\nL5 = "0.5 m"\nL3 = "-0.2 m"\n',
                  base=BASE)
    with pytest.raises(ModelFileError) as exc:
        io.load(child)
    e = exc.value
    assert (e.file, e.line, e.key_path) == (str(child), 4, "params.L3")
    assert "positive length" in e.problem


def test_an_unknown_key_in_the_child(files):
    child = files(child='extends = "base.toml"\n[model]\nnme = "x"\n', base=BASE)
    with pytest.raises(ModelFileError) as exc:
        io.load(child)
    assert (exc.value.file, exc.value.line, exc.value.key_path) == (str(child), 3, "model.nme")


def test_a_solve_failure_of_a_base_condition_names_the_base(files):
    """The condition is the base's; the parameter the child changed makes it fail: the
    error is located at the base's [[solve]] header."""
    child = files(child='extends = "base.toml"\n[params]\nL56 = "0.1 m"\n', base=BASE)
    with pytest.raises(ModelFileError) as exc:
        io.load(child)
    e = exc.value
    assert e.key_path == "solve[0]" and e.file == str(child.parent / "base.toml")
    assert e.line == line_of(BASE, "[[solve]]")


def test_loads_resolves_relative_to_source_or_cwd(files, monkeypatch):
    child = files(child='extends = "base.toml"\n[params]\nL5 = "0.5 m"\n', base=BASE)
    text = child.read_text()
    assert io.loads(text, name="c.toml", source=child).mechanism.params["L5"] == 0.5
    monkeypatch.chdir(child.parent)
    assert io.loads(text, name="c.toml").mechanism.params["L5"] == 0.5
    np.testing.assert_array_equal(io.loads(text).range, io.load(child).range)


def test_the_documented_override_example_loads(tmp_path):
    """The `extends` example of docs/model-format.md over the bundled hitch: only rb of
    group II (4,5) changes, and L4 is solved for the new target."""
    blocks = re.findall(r"```toml\n(.*?)```", (ROOT / "docs" / "model-format.md").read_text(),
                        re.S)
    text = next(b for b in blocks if b.startswith('extends = "hitch_003.toml"'))
    (tmp_path / "hitch_003.toml").write_text(io.bundled("hitch_003").read_text())
    (tmp_path / "mine.toml").write_text(text)
    model = io.load(tmp_path / "mine.toml")
    base = io.load(io.bundled("hitch_003")).mechanism
    g = model.mechanism.group("II (4,5)")
    assert g.rb == 0.5 and (g.a, g.b, g.ra, g.branch) == ("34", "05", "L4", 1)
    assert base.group("II (4,5)").rb == "L5"
    assert model.mechanism.solve([0.42]).y("56")[0] == pytest.approx(0.25, abs=1e-12)
    assert [s.condition.unknown for s in model.solved] == ["L4", "Sp", "L7"]
