"""Masses of links (:mod:`assur.dynamics.masses`): a mass's centre given by along/offset
lies at P + along·u + offset·n of its link's points; masses are refused with the
reason; ``masses_of`` lists the masses on moving links and ``design_value`` gives a
value per design. On the bundled ``cleaning_lab3.toml``
(tests/dynamics/conftest.py)."""

import numpy as np
import pytest

from assur.core.loads import Mass
from assur.dynamics.masses import LinkMass, design_value, masses_of, with_masses
from assur.errors import ModelError


def test_link_mass_errors(example):
    model, _ = example
    mech = model.mechanism
    with pytest.raises(ModelError, match="unknown or fixed link"):
        with_masses(mech, [LinkMass("0", 1.0)])
    with pytest.raises(ModelError, match="m = -1"):
        with_masses(mech, [LinkMass("4", -1.0)])
    with pytest.raises(ModelError, match="either as point"):
        with_masses(mech, [LinkMass("4", 1.0, point="S4", along=0.1)])
    with pytest.raises(ModelError, match="exists already"):
        with_masses(mech, [LinkMass("4", 1.0, along=0.1, name="S4")])



def test_centre_in_the_link_frame(example):
    """A centre given by along/offset is P + along·u + offset·n of the link's points."""
    model, _ = example
    mech = with_masses(model.mechanism, [LinkMass("6", 2.0, along=0.3, offset=0.07,
                                                  name="X6")])
    kin = mech.solve(model.range)
    P, Q = kin.point("E"), kin.point("C6")
    u = (Q - P) / np.hypot(*(Q - P).T)[:, None]
    n = np.stack([-u[:, 1], u[:, 0]], -1)
    assert np.allclose(kin.point("X6"), P + 0.3 * u + 0.07 * n, rtol=0, atol=1e-12)



def test_masses_of_and_design_values(example):
    model, kin = example
    ms = masses_of(model.mechanism)
    assert ms and all(isinstance(m, Mass) and m.link != "0" for m in ms)
    assert len(ms) == sum(1 for ld in model.mechanism.loads
                          if isinstance(ld, Mass) and ld.link != "0")
    m0 = ms[0]
    assert np.all(design_value(kin, m0.m) == model.mechanism.value_of(m0.m))
    assert design_value(kin, 2.5) == 2.5
