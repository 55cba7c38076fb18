"""A change of the page (:meth:`assur.views.page.session.PageModel.load`) builds the
edited model from the file's data read once (:meth:`assur.io.ParsedText.with_values`):
on every bundled model, for edits that load and edits that do not, the model is the
one :func:`assur.io.loads` reads from the edited text — to the last bit — and a bad
value is the same error, with the same message at the same key and line."""

import math
import struct
from importlib.resources import files

import numpy as np
import pytest

from assur import io
from assur.errors import AssemblyError, ModelError
from assur.views.page.session import PageModel

MODELS = sorted(p.name[:-5] for p in files("assur.models").iterdir()
                if p.name.endswith(".toml"))


def _same(a, b, where="model", seen=None):
    """Assert ``a`` and ``b`` hold the same values to the last bit (floats by their
    bits, arrays by their bytes, objects by their attributes); ``where`` names the
    attribute path in the message."""
    seen = set() if seen is None else seen
    if (id(a), id(b)) in seen:
        return
    seen.add((id(a), id(b)))
    assert type(a) is type(b), f"{where}: {type(a).__name__} != {type(b).__name__}"
    if isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape, where
        if a.dtype == object:
            for i, (x, y) in enumerate(zip(a.ravel(), b.ravel())):
                _same(x, y, f"{where}[{i}]", seen)
        else:
            assert a.tobytes() == b.tobytes(), f"{where}: arrays differ"
    elif isinstance(a, (float, np.floating)):
        assert struct.pack("<d", float(a)) == struct.pack("<d", float(b)), \
            f"{where}: {a!r} != {b!r}"
    elif isinstance(a, (str, bytes, int, bool, type(None), np.integer, np.bool_)):
        assert a == b, f"{where}: {a!r} != {b!r}"
    elif isinstance(a, dict) or hasattr(a, "keys") and hasattr(a, "__getitem__"):
        assert list(a.keys()) == list(b.keys()), f"{where}: keys differ"
        for k in a.keys():
            _same(a[k], b[k], f"{where}[{k!r}]", seen)
    elif isinstance(a, (list, tuple, set, frozenset)):
        assert len(a) == len(b), f"{where}: lengths {len(a)} != {len(b)}"
        if isinstance(a, (set, frozenset)):
            a, b = sorted(a, key=repr), sorted(b, key=repr)
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{where}[{i}]", seen)
    elif callable(a) and not hasattr(a, "__dict__") or isinstance(a, type):
        assert a is b, f"{where}: {a!r} is not {b!r}"
    elif hasattr(a, "__dict__") or hasattr(a, "__slots__"):
        names = sorted(set(getattr(a, "__dict__", {}))
                       | {s for c in type(a).__mro__ for s in getattr(c, "__slots__", ())})
        for n in names:
            if n == "_memo":  # values derived on demand (programs, prepared tables)
                continue
            _same(getattr(a, n, None), getattr(b, n, None), f"{where}.{n}", seen)
    else:
        assert a == b, f"{where}: {a!r} != {b!r}"


def _edits(pm):
    """A few changes of the page: the first editable length (by a few tenths of a per
    cent, and a thousand times), the first editable value of another unit, a crank's
    speed; and values a builder refuses (a negative mass, a count of 2.5)."""
    from assur.core.display import kind_of
    editable = [p for p in pm.parameters() if p["editable"] and p["value"]]
    out = []
    length = next((p for p in editable if kind_of(p["unit"]) == "length"), None)
    if length is not None:
        v = length["file_value"]
        out += [{length["name"]: round(v * 1.003, 9)}, {length["name"]: v * 1e3}]
    other = next((p for p in editable if p["unit"] not in ("m", "-")
                  and kind_of(p["unit"]) != "length"), None)
    if other is not None:
        out += [{other["name"]: other["file_value"] * 0.997},
                {other["name"]: -abs(other["file_value"]) - 1.0}]
    count = next((p for p in editable if p["integer"]), None)
    if count is not None:
        out.append({count["name"]: 2.5})
    speed = next((p for p in editable if p["name"].startswith("speed-")), None)
    if speed is not None:
        out.append({speed["name"]: speed["file_value"] * 1.01})
    if length is not None and other is not None:  # two at once
        out.append({length["name"]: length["file_value"] * 0.999,
                    other["name"]: other["file_value"] * 1.002})
    return out


def _outcome(make):
    try:
        return make(), None
    except (ModelError, AssemblyError) as e:
        return None, e


@pytest.mark.slow
@pytest.mark.parametrize("name", MODELS)
def test_a_change_builds_the_model_a_fresh_read_of_the_edited_text_gives(name):
    path = io.bundled(name)
    try:
        pm = PageModel.from_path(path)
    except (ModelError, AssemblyError):
        pytest.skip(f"{name}: the file itself does not load (the page shows its error)")
    edits = _edits(pm)
    assert edits, f"{name}: nothing to edit"
    errors = 0
    for values in edits:
        text = pm.edited_text(values)
        fresh, e_fresh = _outcome(lambda: io.loads(text, name=pm.name, source=pm.source))
        fast, e_fast = _outcome(lambda: pm._build(values, text))
        if e_fresh is not None:
            errors += 1
            assert type(e_fast) is type(e_fresh), (values, e_fresh, e_fast)
            assert str(e_fast) == str(e_fresh), values
            assert getattr(e_fast, "line", None) == getattr(e_fresh, "line", None)
            assert getattr(e_fast, "key_path", None) == getattr(e_fresh, "key_path", None)
            continue
        assert e_fast is None, (values, e_fast)
        _same(fast, fresh, f"{name} {values}")
        for k, v in values.items():
            if not k.startswith("speed-") and pm.editable[k]["unit"] == "m":
                assert math.isclose(fast.mechanism.params[k], float(v), rel_tol=1e-15)


def test_the_data_a_change_builds_from_are_those_of_the_edited_text():
    """The replaced values are the TOML values of the edited text, the file's data are
    not changed by a change, and the line index stays that of the edited text."""
    pm = PageModel.from_path(io.bundled("loader_lab1_level"))   # extends loader_lab1
    before = repr(pm._parsed.data)
    values = {"S_level": 1.1, "X01": -0.25}
    text = pm.edited_text(values)
    fresh = io.parse_text(text, pm.name, source=pm.source)
    new = {pm._paths[k]: w for k, w in
           (("S_level", "1.1 m"), ("X01", "-0.25 m"))}
    assert pm._parsed.with_values(new).data == fresh.data
    assert repr(pm._parsed.data) == before
    assert dict(pm._parsed.index) == dict(fresh.index)


def test_a_speed_is_replaced_in_motion():
    pm = PageModel.from_path(io.bundled("cleaning_lab3"))
    assert pm._paths["speed-j1"] == ("motion", "j1", "speed")
    m = pm.load({"speed-j1": 300.0})
    fresh = io.loads(pm.edited_text({"speed-j1": 300.0}), name=pm.name, source=pm.source)
    assert m.mechanism.motion("j1").speed == fresh.mechanism.motion("j1").speed
    assert abs(abs(m.mechanism.motion("j1").speed) - 300.0 * 2 * np.pi / 60) < 1e-12
