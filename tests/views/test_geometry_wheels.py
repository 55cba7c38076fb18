"""The wheels in the drawing's data (:func:`assur.views.geometry.geometry`'s key
``"wheels"``, :func:`~assur.views.geometry.wheel_outline`): each wheel's heading is its
link's angle plus the declared offset at every position, its outline a rectangle of
the diameter by the width centred on its point and turned by the heading, the bounds
hold it; a mechanism without wheels draws none and its bounds are its points'."""

import dataclasses
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples, io
from assur.views.geometry import geometry, wheel_outline
from tests.helpers import examples as n_examples


@pytest.fixture(scope="module")
def steering():
    m = io.load(io.bundled("steering_lab4"))
    return m.mechanism.solve(m.range)


def test_headings_are_the_links_angles_plus_the_offset(steering):
    g = geometry(steering)
    assert [(w["name"], w["point"]) for w in g["wheels"]] == [
        ({"en": "left wheel", "ru": "левое колесо"}, "03"),
        ({"en": "right wheel", "ru": "правое колесо"}, "05")]
    for w, link in zip(g["wheels"], ("w3", "w5")):
        np.testing.assert_allclose(w["heading"], steering.phi(link), rtol=0, atol=1e-15)
        assert (w["length"], w["width"]) == (pytest.approx(1.1), pytest.approx(0.5))
    # the lab's angles: α = φ(w3) − 90°, β = φ(w5) − 90°, both turning left (ccw)
    h = g["wheels"][0]["heading"]
    assert 0 < h[0] - math.pi / 2 < h[-1] - math.pi / 2
    json.dumps(g)  # JSON-ready
    # an offset given by a parameter (here the angle dphi1 of the model) adds to every
    # position
    m = steering.mechanism
    turned = m.with_wheels([dataclasses.replace(m.wheels[0], heading="dphi1")])
    kin = turned.solve(steering.q())
    np.testing.assert_allclose(geometry(kin)["wheels"][0]["heading"],
                               steering.phi("w3") + m.params["dphi1"], rtol=0, atol=1e-14)


def test_an_offset_and_a_wheel_without_a_link():
    m = examples.hitch_003()
    S = np.linspace(0.42, 0.67, 5)
    kin = m.wheel("on 5", at="45", diameter=0.4, width=0.1, link="5",
                  heading=-math.pi / 2).wheel("rear", at="01", diameter=1.2, width=0.3,
                                              heading=0.25).solve(S)
    on5, rear = geometry(kin)["wheels"]
    np.testing.assert_allclose(on5["heading"], kin.phi("5") - math.pi / 2, rtol=0, atol=1e-15)
    assert rear["heading"] == [0.25] * 5 and rear["name"] == "rear"


def test_a_batch_picks_its_design():
    m = examples.hitch_003().wheel("w", at="01", diameter="L3", width=0.3)
    L3 = float(m.params["L3"])
    kin = m.with_params(L3=np.array([L3, L3 * 1.01])).solve(np.array([[0.42, 0.5]] * 2))
    assert geometry(kin, design=1)["wheels"][0]["length"] == pytest.approx(L3 * 1.01)
    assert geometry(kin, design=0)["wheels"][0]["length"] == pytest.approx(L3)


@settings(max_examples=n_examples(100), deadline=None)
@given(x=st.floats(-5, 5), y=st.floats(-5, 5), h=st.floats(-7, 7), L=st.floats(0.05, 3),
       W=st.floats(0.02, 1))
def test_the_outline_is_the_rectangle_turned_by_the_heading(x, y, h, L, W):
    geo = {"points": {"P": [[x, y]]}}
    corners = np.array(wheel_outline(geo, {"point": "P", "heading": [h], "length": L,
                                           "width": W}, 0))
    assert corners.shape == (4, 2)
    d = corners - [x, y]
    np.testing.assert_allclose(np.hypot(*d.T), math.hypot(L / 2, W / 2), rtol=1e-12)
    # in the wheel's own axes (along the heading, across it): (∓L/2, ∓W/2), ccw
    u, v = np.array([math.cos(h), math.sin(h)]), np.array([-math.sin(h), math.cos(h)])
    np.testing.assert_allclose(d @ u, [-L / 2, L / 2, L / 2, -L / 2], atol=1e-12)
    np.testing.assert_allclose(d @ v, [-W / 2, -W / 2, W / 2, W / 2], atol=1e-12)
    # the sides: L along the heading, W across
    assert np.hypot(*(corners[1] - corners[0])) == pytest.approx(L, rel=1e-12)
    assert np.hypot(*(corners[2] - corners[1])) == pytest.approx(W, rel=1e-12)


def test_the_outline_turns_with_the_wheel(steering):
    g = geometry(steering)
    w = g["wheels"][0]
    c = np.array(g["points"]["03"][0])
    first = np.array(wheel_outline(g, w, 0)) - c
    last = np.array(wheel_outline(g, w, g["n"] - 1)) - c
    turn = w["heading"][-1] - w["heading"][0]
    R = np.array([[math.cos(turn), -math.sin(turn)], [math.sin(turn), math.cos(turn)]])
    np.testing.assert_allclose(last, first @ R.T, atol=1e-12)
    assert abs(turn) > 0.5    # the wheel does turn over the range [rad]
    # straight ahead the left wheel rolls along +y (the levers are at 90°): its long
    # sides are (nearly, the range starts at a small turn) parallel to y
    along = np.array(wheel_outline(g, w, 0))[1] - np.array(wheel_outline(g, w, 0))[0]
    assert abs(math.atan2(along[1], along[0]) - math.pi / 2) < math.radians(5)


def test_the_bounds_hold_the_wheels(steering):
    g = geometry(steering)
    x0, y0, x1, y1 = g["bounds"]
    corners = np.array([wheel_outline(g, w, i) for w in g["wheels"] for i in range(g["n"])])
    assert corners[..., 0].min() == pytest.approx(x0)
    assert corners[..., 1].max() == pytest.approx(y1)
    pts = np.array([v for p in g["points"].values() for v in p])
    assert x0 < pts[:, 0].min() and y1 > pts[:, 1].max()   # wider than the points


def test_no_wheels_no_change():
    kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 3))
    g = geometry(kin)
    assert g["wheels"] == []
    pts = np.array([v for p in g["points"].values() for v in p])
    assert g["bounds"] == [pts[:, 0].min(), pts[:, 1].min(), pts[:, 0].max(), pts[:, 1].max()]
    bare = examples.steering_lab4().with_wheels()
    stripped = geometry(bare.solve(examples.steering_lab4_range()))
    assert stripped["wheels"] == []
