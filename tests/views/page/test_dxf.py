"""DXF drawings (:mod:`assur.views.page.dxf`; issue 13): a layer per link, the pivots
as points at the solved positions, one group per position; ``assur dxf``."""

import numpy as np
import pytest

from assur import examples
from assur.io import bundled


def test_write_dxf_layers_per_link_and_points(tmp_path):
    import ezdxf

    from assur.views.page.dxf import write_dxf
    kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 6))
    path = write_dxf(kin, tmp_path / "hitch.dxf", positions=[0, 5])
    doc = ezdxf.readfile(path)
    layers = {l.dxf.name for l in doc.layers}
    assert {f"link_{n}" for n in ("2", "3", "4", "5", "6", "7")} <= layers
    assert doc.layers.get("link_2").dxf.linetype == "DASHED"   # the cylinder
    msp = doc.modelspace()
    points = msp.query('POINT[layer=="pivots"]')
    frame = msp.query('POINT[layer=="frame_pivots"]')
    assert len(frame) == 2 * 4 and len(points) == 2 * 7       # 2 positions
    assert len(doc.groups) == 2
    names = sorted(name for name, _ in doc.groups)
    assert names == ["S=0.42 m", "S=0.67 m"]
    # link 6 (56, 67, S6, F610): a closed polyline through the solved points [mm]
    poly = msp.query('LWPOLYLINE[layer=="link_6"]')
    assert len(poly) == 2 and poly[0].closed
    xy = {(round(x, 6), round(y, 6)) for x, y, *_ in poly[0].get_points()}
    assert (round(kin.x("67")[0] * 1e3, 6), round(kin.y("67")[0] * 1e3, 6)) in xy
    with pytest.raises(ValueError, match="positions must be in 0…5"):
        write_dxf(kin, tmp_path / "x.dxf", positions=[6])



def test_cli_dxf(tmp_path):
    import ezdxf
    from typer.testing import CliRunner

    from assur.views.cli import app
    out = tmp_path / "h.dxf"
    r = CliRunner().invoke(app, ["dxf", str(bundled("hitch_003")), "--at", "0.42,0.5",
                                 "-o", str(out)])
    assert r.exit_code == 0, r.output
    doc = ezdxf.readfile(out)
    assert len(doc.groups) == 2
    assert sorted(n for n, _ in doc.groups) == ["S=0.42 m", "S=0.5 m"]
    r = CliRunner().invoke(app, ["dxf", str(bundled("hitch_003")), "--at", "0.8",
                                 "-o", str(out)])
    assert r.exit_code == 1 and "0.42 … 0.67 m" in r.output

