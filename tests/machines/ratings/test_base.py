"""The rating contract: parameters, results, carried loads, names."""

import numpy as np
import pytest

from assur import examples
from assur.machines.ratings import (RatingResult, Series, carried_loads, check_names, param,
                                    rating_type)


def test_a_parameter_declares_its_role_and_quantity():
    with pytest.raises(ValueError, match="unknown rating parameter role"):
        param("place")
    with pytest.raises(ValueError, match="a value needs a quantity"):
        param("value")
    with pytest.raises(ValueError, match="a value needs a quantity"):
        param("point", "length")


def test_a_result_names_its_series():
    r = RatingResult(None, (Series("x", np.arange(3.0), "length", "x"),), "x", ())
    assert r.get("x").unit == "m"
    with pytest.raises(KeyError, match="no series 'G'"):
        r["G"]


def test_the_carried_loads_are_all_but_those_at_the_point():
    m = examples.hitch_003()
    assert carried_loads(m, "S6") is None            # its only load is at S6
    assert len(carried_loads(m, "56").loads) == 1


def test_names_are_checked_against_the_model():
    m = examples.loader_lab1()
    cls = rating_type("excavator_digging")
    assert check_names(m, cls("S9", "MPS", "09", "MPT", "01")) is None
    key, msg = check_names(m, cls("S9", "MPX", "09", "MPT", "01"))
    assert key == "bucket_cylinder" and "'MPX'" in msg
