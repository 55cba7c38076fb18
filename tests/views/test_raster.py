"""The GIF's frames drawn with Pillow (:mod:`assur.views.raster`): one fixed view over
every position (a position drawn twice is the same image, the frame pivots stay put
while the links move), the drawing inside the image under its caption lines, a title
too long for the width cut at a word."""

from __future__ import annotations

import numpy as np
from PIL import ImageChops

from assur import examples
from assur.views.geometry import geometry
from assur.views.raster import images


def _ink(img, box=None):
    """The bounding box of what is not white in ``img`` (or its ``box``)."""
    part = img.crop(box) if box else img
    return ImageChops.invert(part.convert("L")).point(lambda v: 255 if v > 40 else 0).getbbox()


def test_one_view_over_every_position():
    kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 5))
    g = geometry(kin)
    a, b, c = images(g, [0, 0, 4], 400, 320, ["first", "first", "last"], title="hitch")
    assert a.tobytes() == b.tobytes()
    assert a.tobytes() != c.tobytes()
    head = int(0.12 * 320)  # the title and caption lines
    assert _ink(a, (0, 0, 400, head)) is not None  # the captions are written
    left, top, right, bottom = _ink(a, (0, head, 400, 320))
    assert left > 0 and right < 400 and bottom < 320 - head  # the drawing fits
    # the frame pivots do not move: where positions 0 and 4 differ is the moving links
    diff = ImageChops.difference(a, c).crop((0, head, 400, 320)).convert("L")
    moved = int((np.asarray(diff) > 40).sum())
    assert 0 < moved < 0.5 * 400 * (320 - head)


def test_a_long_title_is_cut_at_a_word():
    g = geometry(examples.hitch_003().solve(np.array([0.42])))
    long = "Подъёмно-навесное устройство " * 6
    img = images(g, [0], 300, 240, ["S = 0,42 м"], title=long)[0]
    left, _, right, _ = _ink(img, (0, 0, 300, 20))
    assert left > 0 and right < 300
