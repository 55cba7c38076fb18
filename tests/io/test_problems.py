"""Design problems of model files (:mod:`assur.io.problems`): the positions a design is
checked at are the file's range, or that many evenly spaced between its ends; a
problem's variables come from the file and from ``--var``-style texts with their
bounds around the file's values; a file without a design section is refused."""

import numpy as np
import pytest

from assur import io
from assur.errors import ModelError
from assur.io.problems import load_problem, positions_of


def test_positions_are_the_range_or_evenly_spaced_between_its_ends():
    model = io.load(io.bundled("hitch_003"))
    np.testing.assert_array_equal(positions_of(model), model.range)
    six = positions_of(model, 6)
    np.testing.assert_allclose(six, np.linspace(model.range[0], model.range[-1], 6),
                               rtol=0, atol=1e-15)


def test_variables_from_the_file_and_from_texts():
    path = io.bundled("hitch_003_design")
    pb = load_problem(path, positions=6)
    L4 = io.load(path).mechanism.params["L4"]
    more = load_problem(path, variables=["L4=±20 mm"], positions=6)
    assert more.names == pb.names + ("L4",) and more.n_positions == 6
    np.testing.assert_allclose(more.bounds[-1], [L4 - 0.02, L4 + 0.02], rtol=0, atol=1e-12)
    X = more.sample(4, seed=2)
    lo, hi = np.asarray(more.bounds).T
    assert X.shape == (4, len(more.names)) and ((lo <= X) & (X <= hi)).all()
    with pytest.raises(ModelError):
        load_problem(io.bundled("hitch_003"))  # no [design]


def test_problems_are_cached_by_content_not_by_path(tmp_path):
    """An edited file gives a new problem (a notebook or a long-lived cluster used the
    old limits: 1389 feasible designs where the edited file gives 208); the same
    content at another path is the same problem; the recipe carries the content with
    its extends chain, so it rebuilds where the folder is gone."""
    import pickle
    import shutil

    d = tmp_path / "m"
    d.mkdir()
    shutil.copy(io.bundled("hitch_003"), d / "hitch_003.toml")
    text = io.bundled("hitch_003_design").read_text(encoding="utf-8")
    design = d / "hitch_003_design.toml"
    design.write_text(text, encoding="utf-8")
    a = load_problem(design, positions=5)
    assert load_problem(design, positions=5) is a
    assert load_problem(io.bundled("hitch_003_design"), positions=5) is a  # same bytes
    design.write_text(text.replace('X01 = { within = "30 mm" }', 'X01 = { within = "5 mm" }'),
                      encoding="utf-8")
    b = load_problem(design, positions=5)
    assert b is not a and b.bounds[0, 1] - b.bounds[0, 0] < 0.0101
    data = pickle.dumps(b)
    assert str(d).encode() not in data.replace(str(design).encode(), b"")  # only as shown
    shutil.rmtree(d)
    from assur.io import problems
    problems._cache.clear()  # as in a fresh worker process
    c = pickle.loads(data)
    assert c is not b
    np.testing.assert_array_equal(c.bounds, b.bounds)
    assert c.identity == b.identity
