"""The wheels in the GIF's frames (:mod:`assur.views.raster`): the same view with and
without the ``wheels`` of the drawing's data differs only where the wheels are — at
both sides of the steering axle — and a mechanism without wheels draws as before."""

import numpy as np
from PIL import ImageChops

from assur import examples, io
from assur.views.geometry import geometry
from assur.views.raster import images


def test_the_wheels_are_drawn_at_both_sides():
    m = io.load(io.bundled("steering_lab4"))
    g = geometry(m.mechanism.solve(m.range))
    bare = dict(g, wheels=[])
    (a,), (b,) = images(g, [0], 400, 300), images(bare, [0], 400, 300)
    box = ImageChops.difference(a, b).getbbox()
    assert box is not None
    left, top, right, bottom = box
    # (the wheels span about 0.65 × 0.5 of the view; no resampling blur widens them)
    assert right - left > 0.6 * 400 and bottom - top > 0.45 * 300
    # the middle of the axle (no wheel there) is the same in both
    mid = ImageChops.difference(a.crop((190, 0, 210, 300)), b.crop((190, 0, 210, 300)))
    assert mid.getbbox() is None


def test_without_wheels_nothing_changes():
    g = geometry(examples.hitch_003().solve(np.linspace(0.42, 0.67, 3)))
    assert g["wheels"] == []
    a = images(g, [1], 200, 150)[0]
    b = images({k: v for k, v in g.items() if k != "wheels"}, [1], 200, 150)[0]
    assert a.tobytes() == b.tobytes()
