"""Drawings and animations (:mod:`assur.views.report.drawing`) of the seed-003 hitch:
the drawing at two positions draws every point of the mechanism where the kinematics
put it, a label per link; the animation's frames are of one size and show the
mechanism moving; the GIF plays them forward and back; the PNG frames read back."""

import io

import numpy as np
import pytest
from PIL import Image

from assur.views.report.drawing import draw, frames_png_bytes, render_frames, write_gif


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
    pngs = frames_png_bytes(frames)
    assert [Image.open(io.BytesIO(bytes(b))).size for b in pngs] == [f.size for f in frames]
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
