"""The seed machines as ready models (:mod:`assur.examples`): every machine of the
module is its bundled model file (``src/assur/models/<name>.toml``) — the same groups,
parameters and loads — every ``*_range()`` the file's ``[range]``, and keyword
arguments override parameters without touching the cached model."""

import numpy as np
import pytest

from assur import examples, io

MACHINES = [n for n in examples.__all__ if not n.endswith("_range")]
RANGES = [n for n in examples.__all__ if n.endswith("_range")]


def test_the_lists_cover_the_module():
    assert len(MACHINES) >= 8 and len(RANGES) >= 6
    for r in RANGES:  # every range belongs to a machine (or a file) of the same name
        assert r[:-len("_range")] in MACHINES or io.bundled(r[:-len("_range")]).is_file()


@pytest.mark.parametrize("name", MACHINES)
def test_each_machine_is_its_bundled_file(name):
    mech = getattr(examples, name)()
    model = io.load(io.bundled(name))
    assert mech.params == model.mechanism.params
    assert mech.groups == model.mechanism.groups
    assert mech.loads == model.mechanism.loads
    assert mech.coordinates == model.mechanism.coordinates


@pytest.mark.parametrize("name", RANGES)
def test_each_range_is_its_files_range(name):
    model = io.load(io.bundled(name[:-len("_range")]))
    np.testing.assert_array_equal(getattr(examples, name)(), model.range)


def test_keywords_override_parameters_of_a_copy():
    base = examples.hitch_003()
    m = examples.hitch_003(L4=0.65, P6=np.array([20e3, 25e3]))
    assert m.params["L4"] == 0.65 and m.params["P6"].tolist() == [20e3, 25e3]
    assert examples.hitch_003().params == base.params  # the cached model is unchanged
    assert base.params["L4"] == pytest.approx(examples.HITCH_003_FOUND["L4"], abs=1e-9)
    with pytest.raises(ValueError, match="unknown parameter"):
        examples.combine_002(l99=1.0)
