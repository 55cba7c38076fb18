"""The wheels in the report's drawing (:mod:`assur.views.report.drawing`): a patch
(gid ``"wheel"``) per wheel and drawn position, at the corners of
:func:`assur.views.geometry.wheel_outline` in the drawing's unit of length, inside the
axes' limits; the HTML report's animation frames carry them; a mechanism without
wheels draws none."""

import re

import numpy as np
import pytest

from assur import examples, io
from assur.views.geometry import geometry, wheel_outline
from assur.views.report.drawing import animation, draw


@pytest.fixture(scope="module")
def steering():
    return io.load(io.bundled("steering_lab4")).analyze()


def _wheels(fig):
    return [p for p in fig.axes[0].patches if p.get_gid() == "wheel"]


def test_a_patch_per_wheel_and_position_at_its_corners(steering):
    fig = draw(steering, positions=[0, 29], units="si")
    patches = _wheels(fig)
    assert len(patches) == 2 * 2          # two wheels, the colour pose and a ghost
    g = geometry(steering.kinematics)
    # the colour pose (position 0) is drawn last
    for patch, w in zip(patches[2:], g["wheels"]):
        np.testing.assert_allclose(patch.get_xy()[:4], wheel_outline(g, w, 0), atol=1e-12)
    ax = fig.axes[0]
    corners = np.vstack([p.get_xy() for p in patches])
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    assert x0 < corners[:, 0].min() and corners[:, 0].max() < x1
    assert y0 < corners[:, 1].min() and corners[:, 1].max() < y1
    # in millimetres (the file's units), the same corners ×1000
    mm = _wheels(draw(steering, positions=[0]))
    np.testing.assert_allclose(mm[0].get_xy()[:4], np.array(wheel_outline(g, g["wheels"][0], 0))
                               * 1e3, atol=1e-9)


def test_the_animation_frames_carry_the_wheels(steering):
    anim = animation(steering, frames=4)
    assert anim["svg"].count('<g class="frame"') == 4
    assert len(re.findall(r'<polygon class="wheel"', anim["svg"])) == 2 * 4


def test_no_wheels_no_patches(hitch_analysis):
    assert _wheels(draw(hitch_analysis)) == []
    m = examples.steering_lab4().with_wheels()
    assert _wheels(draw(m.analyze(examples.steering_lab4_range()))) == []
