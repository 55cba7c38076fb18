"""Wheels drawn on a mechanism (:mod:`assur.core.wheels`, :meth:`Mechanism.wheel`,
:attr:`Mechanism.wheels`): drawing data kept through every copy, checked against the
mechanism's points, links and parameters, and without effect on the solve."""

import pickle

import numpy as np
import pytest

from assur import examples
from assur.core.wheels import Wheel
from assur.errors import ModelError


def test_a_wheel_is_kept_and_changes_nothing_of_the_solve():
    m = examples.hitch_003()
    w = m.wheel("rear", at="01", diameter=1.1, width=0.3, link="3", heading=0.5)
    assert m.wheels == () and w.wheels == (Wheel("rear", "01", 1.1, 0.3, "3", 0.5),)
    S = np.linspace(0.42, 0.67, 4)
    a, b = m.solve(S), w.solve(S)
    for p in m.points:
        np.testing.assert_array_equal(a.point(p), b.point(p))
    # kept by data copies (a parameter changed) and by structural copies
    assert w.with_params(L3=0.21).wheels == w.wheels
    assert w.distance("d57", "05", "67").wheels == w.wheels
    assert pickle.loads(pickle.dumps(w.wheels[0])) == w.wheels[0]
    assert w.with_wheels().wheels == () and len(w.with_wheels(w.wheels * 2).wheels) == 2


@pytest.mark.parametrize("kw,message", [
    (dict(at="99"), "wheel 'w' is at unknown point '99'"),
    (dict(link="9"), "wheel 'w' heads along unknown link '9'"),
    (dict(diameter="Dw"), "wheel 'w': diameter refers to 'Dw', which is not a parameter"),
    (dict(width=-0.3), "wheel 'w': width must be positive, got -0.3"),
    (dict(diameter=0.0), "wheel 'w': diameter must be positive, got 0.0"),
    (dict(heading=float("nan")), "wheel 'w': heading = nan is not finite"),
])
def test_what_a_wheel_refers_to_is_checked(kw, message):
    args = dict(at="01", diameter=1.1, width=0.3) | kw
    with pytest.raises(ModelError, match=message.replace("(", r"\(")):
        examples.hitch_003().wheel("w", **args)
    with pytest.raises(ModelError, match="wheels must be"):
        examples.hitch_003().with_wheels(["w"])


def test_parameters_and_group_links_are_accepted():
    m = examples.hitch_003()
    w = m.wheel("w", at="56", diameter="L3", width="L3", link="5").wheels[0]
    assert (w.diameter, w.width, w.link) == ("L3", "L3", "5")
