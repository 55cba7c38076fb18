"""Fixtures of the dynamics tests."""

import pytest

from assur import io


@pytest.fixture(scope="package")
def example():
    """The bundled grain-cleaning ten-bar of seed 001 lab 3 (``cleaning_lab3.toml``):
    its model and its kinematics over the file's range; tests must not change them."""
    model = io.load(io.bundled("cleaning_lab3"))
    kin = model.mechanism.solve(model.range)
    return model, kin
