"""The inline SVG drawing (:mod:`assur.views.svg`): every labelled joint is a
circle at its solved position (y up: drawn at −y), inside the view box; a ghost per
extra position; positions out of range are refused."""

import re

import numpy as np
import pytest

from assur import examples
from assur.views.geometry import geometry
from assur.views.svg import svg


@pytest.fixture(scope="module")
def solved():
    return examples.hitch_003().solve(np.linspace(0.42, 0.67, 3))


def test_joints_at_their_solved_positions(solved):
    g = geometry(solved)
    s = svg(g, [2])
    vx, vy, vw, vh = map(float, re.search(r'viewBox="([^"]*)"', s).group(1).split())
    circles = dict((m[0], (float(m[1]), float(m[2]))) for m in
                   re.findall(r'<circle id="pt-([^"]+)" cx="([^"]+)" cy="([^"]+)"', s))
    assert set(g["joints"]) <= set(circles)
    for p, (cx, cy) in circles.items():
        x, y = solved.point(p)[2]
        assert cx == pytest.approx(x, abs=1e-5) and cy == pytest.approx(-y, abs=1e-5), p
        assert vx <= cx <= vx + vw and vy <= cy <= vy + vh


def test_ghosts_and_bad_positions(solved):
    g = geometry(solved)
    assert svg(g, [0, 1, 2]).count('<g opacity="0.3">') == 2
    assert svg(g, [1]).count('<g opacity="0.3">') == 0
    with pytest.raises(ValueError, match=r"positions must be in 0…2"):
        svg(g, [3])
