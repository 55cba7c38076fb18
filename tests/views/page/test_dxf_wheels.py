"""The wheels in the DXF drawing (:mod:`assur.views.page.dxf`): a layer ``wheels`` with
one closed LWPOLYLINE per wheel and position at the corners of
:func:`assur.views.geometry.wheel_outline` [mm], in that position's group; no such layer
without wheels."""

import numpy as np

from assur import examples, io
from assur.views.geometry import geometry, wheel_outline
from assur.views.page.dxf import write_dxf


def test_the_wheels_layer_and_its_closed_polylines(tmp_path):
    import ezdxf

    m = io.load(io.bundled("steering_lab4"))
    kin = m.mechanism.solve(m.range)
    doc = ezdxf.readfile(write_dxf(kin, tmp_path / "steering.dxf", positions=[0, 29]))
    assert "wheels" in {layer.dxf.name for layer in doc.layers}
    polys = doc.modelspace().query('LWPOLYLINE[layer=="wheels"]')
    assert len(polys) == 2 * 2 and all(p.closed for p in polys)
    g = geometry(kin)
    want = [np.array(wheel_outline(g, w, i)) * 1e3 for i in (0, 29) for w in g["wheels"]]
    got = [np.array([(x, y) for x, y, *_ in p.get_points()]) for p in polys]
    for a, b in zip(got, want):
        np.testing.assert_allclose(a, b, atol=1e-6)
    # each position's group holds its two wheels
    for name, group in doc.groups:
        assert sum(e.dxftype() == "LWPOLYLINE" and e.dxf.layer == "wheels"
                   for e in group) == 2, name


def test_no_wheels_no_layer(tmp_path):
    import ezdxf

    kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 3))
    doc = ezdxf.readfile(write_dxf(kin, tmp_path / "hitch.dxf"))
    assert "wheels" not in {layer.dxf.name for layer in doc.layers}
    assert len(doc.modelspace().query('LWPOLYLINE[layer=="wheels"]')) == 0
