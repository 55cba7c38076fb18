"""The two-link arm of tests.helpers.ratings as a fixture."""

import pytest

from tests.helpers.ratings import ARM


@pytest.fixture
def arm_text():
    """The two-link arm's model file (add a [[rating]] table)."""
    return ARM
