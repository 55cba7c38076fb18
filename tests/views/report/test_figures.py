"""The report's diagrams (:mod:`assur.views.report.figures`) of the seed-003 hitch: the
curves are the analysis' numbers in the units of their axes — link angles in degrees,
capacities in kN against S — a name picks figures, in Russian the same curves; a
figure is saved as PNG or SVG, and as PNG bytes."""

import numpy as np
import pytest

from assur.views.report import figures as F


def test_the_curves_are_the_analysis_numbers(hitch_analysis):
    a = hitch_analysis
    kin = a.kinematics
    figs = F.figures(a)
    assert list(figs) == [n for n in F.FIGURES if n in figs] and {"angles", "capacity"} <= \
        set(figs)
    angles = figs["angles"].axes[0].lines
    links = [ln.name for ln in a.mechanism.links]
    assert len(angles) == len(links)
    for line, name in zip(angles, links):
        np.testing.assert_allclose(line.get_xdata(), kin.q().ravel(), rtol=1e-12)
        np.testing.assert_allclose(line.get_ydata(), np.degrees(kin.phi(name)), rtol=1e-12)
    cap = figs["capacity"].axes[0].lines[0]
    np.testing.assert_allclose(cap.get_ydata(), a.cylinder().capacity("56") / 1e3, rtol=1e-12)
    ru = F.figures(a, "ru", names=["capacity"])
    assert list(ru) == ["capacity"]
    np.testing.assert_array_equal(ru["capacity"].axes[0].lines[0].get_ydata(),
                                  cap.get_ydata())
    assert ru["capacity"].axes[0].get_xlabel() != figs["capacity"].axes[0].get_xlabel()


def test_saving(hitch_analysis, tmp_path):
    fig = F.angles(hitch_analysis)
    png, svg = F.save(fig, tmp_path / "a.png"), F.save(fig, tmp_path / "a.svg")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert svg.read_text(encoding="utf-8").lstrip().startswith(("<?xml", "<svg"))
    assert F.to_png_bytes(fig, dpi=40)[:4] == b"\x89PNG"
    with pytest.raises(ValueError):
        F.save(fig, tmp_path / "a.pdf")
