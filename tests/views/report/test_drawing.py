"""Drawings and animations (:mod:`assur.views.report.drawing`) of the seed-003 hitch:
the drawing at two positions draws every point of the mechanism where the kinematics
put it, a label per link; the animation's frames are of one size and show the
mechanism moving; the GIF plays them forward and back; the HTML report's vector
frames put every point where the kinematics do, at the same positions as the GIF's."""

import re

import numpy as np
import pytest
from PIL import Image

from assur.views.report.drawing import animation, draw, render_frames, write_gif


def test_the_drawing_puts_every_point_where_the_kinematics_do(hitch_analysis):
    a = hitch_analysis
    fig = draw(a, positions=[0, 9])
    ax = fig.axes[0]
    drawn = np.vstack([ln.get_xydata() for ln in ax.lines if len(ln.get_xydata())])
    for p in a.mechanism.points:
        for i in (0, 9):
            xy = a.kinematics.point(p)[i]
            assert np.hypot(*(drawn - xy).T).min() < 1e-9, (p, i)
    labels = {t.get_text() for t in ax.texts}
    assert {ln.name for ln in a.mechanism.links} <= labels


def test_frames_gif_and_pngs(hitch_analysis, tmp_path):
    frames = render_frames(hitch_analysis, frames=4, dpi=30)
    assert len(frames) == 4 and len({f.size for f in frames}) == 1
    assert frames[0].tobytes() != frames[-1].tobytes()  # the hitch moved
    with Image.open(write_gif(frames, tmp_path / "m.gif", duration=50)) as gif:
        assert gif.n_frames == 2 * 4 - 2 and gif.info["duration"] == 50
    with Image.open(write_gif(frames, tmp_path / "f.gif", bounce=False)) as gif:
        assert gif.n_frames == 4
    with pytest.raises(ValueError, match="no frames"):
        write_gif([], tmp_path / "none.gif")


def test_frames_of_a_two_coordinate_machine_are_at_most_the_asked_number(tmp_path):
    """A crane (two coordinates) is animated over its analysed positions: at most
    ``frames`` of them, evenly spaced, the first and the last among them."""
    from assur import io
    a = io.load(io.bundled("crane_lv185")).analyze()
    assert a.kinematics.shape[-1] > 5
    frames = render_frames(a, frames=3, dpi=20)
    assert len(frames) == 3
    assert frames[0].tobytes() != frames[-1].tobytes()


@pytest.mark.parametrize("frames", [3, 7])
def test_vector_frames_put_every_point_where_the_kinematics_do(hitch_analysis, frames):
    """Frame k of the HTML animation draws each joint at its solved position on the
    k-th of ``frames`` evenly spaced strokes over the range (y up: drawn at −y), and its
    caption names that stroke."""
    a = hitch_analysis
    anim = animation(a, frames=frames)
    groups = re.findall(r'<g class="frame"[^>]*>(.*?)</g></g>', anim["svg"])
    assert len(groups) == len(anim["captions"]) == frames
    S = np.linspace(a.kinematics.q()[0], a.kinematics.q()[-1], frames)
    kin = a.mechanism.solve(S)
    for k, body in enumerate(groups):
        circles = np.array([(float(x), float(y)) for x, y in
                            re.findall(r'<circle cx="([^"]+)" cy="([^"]+)"', body)])
        for p in ("23", "34", "56", "67"):
            xy = np.array([kin.x(p)[k], -kin.y(p)[k]])
            assert np.hypot(*(circles - xy).T).min() < 1e-5, (p, k)  # %.6g of metres
        assert anim["captions"][k] == f"S = {S[k]:.4g} m"


def test_vector_frames_of_a_two_coordinate_machine_are_its_analysed_positions():
    """A crane (two coordinates): at most ``frames`` of its analysed positions, the
    first and the last among them, as the GIF's."""
    from assur import io
    a = io.load(io.bundled("crane_lv185")).analyze()
    n = a.kinematics.shape[-1]
    anim = animation(a, frames=3)
    assert n > 3 and len(anim["captions"]) == 3
    q = {c: a.kinematics.q(c) for c in a.kinematics.coordinates}
    first = anim["captions"][0]
    assert all(f"{c} = " in first for c in q)
