"""The wheels in the inline SVG (:mod:`assur.views.svg`): one ``<polygon class="wheel">``
per wheel and drawn position — in the still drawing, its ghosts and every frame of the
animation — through the corners of :func:`assur.views.geometry.wheel_outline` (y up:
drawn at −y), under the links; none without wheels."""

import re

import numpy as np
import pytest

from assur import examples, io
from assur.views.geometry import geometry, wheel_outline
from assur.views.svg import frames, svg


@pytest.fixture(scope="module")
def geo():
    m = io.load(io.bundled("steering_lab4"))
    return geometry(m.mechanism.solve(m.range))


def _wheels(s):
    return [np.array([[float(v) for v in p.split(",")] for p in m.split()])
            for m in re.findall(r'<polygon class="wheel" points="([^"]+)"', s)]


def test_the_wheels_at_their_corners(geo):
    s = svg(geo, [3])
    drawn = _wheels(s)
    assert len(drawn) == 2
    for poly, w in zip(drawn, geo["wheels"]):
        want = np.array(wheel_outline(geo, w, 3)) * [1, -1]
        np.testing.assert_allclose(poly, want, atol=1e-5)
    # under the links: before the first link's line
    assert s.index('class="wheel"') < s.index("<line")
    # inside the view box
    vx, vy, vw, vh = map(float, re.search(r'viewBox="([^"]*)"', s).group(1).split())
    allp = np.vstack(drawn)
    assert (allp[:, 0] >= vx).all() and (allp[:, 0] <= vx + vw).all()
    assert (allp[:, 1] >= vy).all() and (allp[:, 1] <= vy + vh).all()


def test_ghosts_and_frames_draw_them_too(geo):
    assert len(_wheels(svg(geo, [0, 5, geo["n"] - 1]))) == 2 * 3
    f = frames(geo, [0, 10, 20])
    assert f.count('<g class="frame"') == 3 and f.count('class="wheel"') == 2 * 3


def test_no_wheels_no_polygons():
    m = examples.steering_lab4()
    q = examples.steering_lab4_range()
    bare = svg(geometry(m.with_wheels().solve(q)))
    assert 'class="wheel"' not in bare
    assert 'class="wheel"' not in svg(geometry(examples.hitch_003().solve([0.42, 0.67])))
    # the rest of the drawing is the same picture
    full = svg(geometry(m.solve(q)))
    assert full.count("<line") == bare.count("<line")
    assert full.count("<circle") == bare.count("<circle")
