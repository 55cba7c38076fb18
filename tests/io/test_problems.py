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
