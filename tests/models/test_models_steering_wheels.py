"""Seed 001 lab 4's two steering drives (steering_lab4.toml, steering_lab4_modern.toml)
draw their wheels and tabulate the Ackermann angle: two ``[[wheels]]`` on the kingpins
turning with the wheels' levers, rolling along the machine's axis (+y) straight ahead,
the lab's tyre width and an illustrative diameter said so in both languages; the
formula ``beta_ideal`` = arcctg(ctg α + A/L) (eq. 11), with β − β* = ``dbeta``."""

import math

import numpy as np
import pytest

from assur import io
from assur.machines import steering
from assur.views.geometry import geometry

#: (model, the wheels' links, their kingpins)
DRIVES = [("steering_lab4", ("w3", "w5"), ("03", "05")),
          ("steering_lab4_modern", ("w3", "w4"), ("03", "04"))]


@pytest.fixture(scope="module", params=DRIVES, ids=[d[0] for d in DRIVES])
def drive(request):
    name, links, kingpins = request.param
    m = io.load(io.bundled(name))
    return m, m.mechanism.analyze(m.range), links, kingpins


def test_the_wheels_turn_with_the_levers(drive):
    m, a, links, kingpins = drive
    mech = m.mechanism
    assert [(w.link, w.at, w.heading) for w in mech.wheels] == [
        (links[0], kingpins[0], 0.0), (links[1], kingpins[1], 0.0)]
    assert [w.name.translations["ru"] for w in mech.wheels] == ["левое колесо",
                                                                 "правое колесо"]
    g = geometry(a.kinematics)
    for w, link in zip(g["wheels"], links):
        np.testing.assert_allclose(w["heading"], a.kinematics.phi(link), rtol=0, atol=1e-15)
        # the lab's tyre width B = 500 mm, the illustrative diameter 1100 mm
        assert (w["width"], w["length"]) == (pytest.approx(0.5), pytest.approx(1.1))
    # the steer angles α, β are the headings less 90°: straight ahead they roll along +y
    np.testing.assert_allclose(np.array(g["wheels"][0]["heading"]) - math.pi / 2,
                               a.formula("alpha"), rtol=0, atol=1e-14)
    np.testing.assert_allclose(np.array(g["wheels"][1]["heading"]) - math.pi / 2,
                               a.formula("beta"), rtol=0, atol=1e-14)


def test_the_modern_drive_straight_ahead_rolls_along_the_axis():
    m = io.load(io.bundled("steering_lab4_modern"))
    g = geometry(m.mechanism.solve(np.array([0.0])))          # S = 0: straight ahead
    assert [w["heading"][0] for w in g["wheels"]] == [pytest.approx(math.pi / 2)] * 2


def test_the_illustrative_diameter_is_said_in_both_languages(drive):
    m = drive[0]
    notes = [n for n in m.mechanism.notes if "1100 mm" in n]
    assert len(notes) == 1 and "illustrative" in notes[0]
    assert "иллюстративный" in notes[0].translations["ru"]
    assert not m.warnings


def test_beta_ideal_is_ackermanns_and_dbeta_its_difference(drive):
    m, a, links, _ = drive
    A, L = (float(m.mechanism.params[k]) for k in ("A", "L"))
    alpha, beta, ideal = (a.formula(k) for k in ("alpha", "beta", "beta_ideal"))
    np.testing.assert_allclose(beta - ideal, a.formula("dbeta"), rtol=0, atol=1e-14)
    np.testing.assert_allclose(ideal, steering.ideal_outer_angle(alpha, A, L), rtol=1e-13,
                               atol=1e-15)
    turned = alpha > 1e-9   # ctg is infinite straight ahead
    np.testing.assert_allclose(1 / np.tan(ideal[turned]) - 1 / np.tan(alpha[turned]), A / L,
                               rtol=1e-10)
    assert (ideal[turned] < alpha[turned]).all()     # the outer wheel turns less
    f = next(f for f in m.mechanism.tables["formulas"] if f.name == "beta_ideal")
    assert f.unit == "deg" and "β*" in f.label and "β*" in f.label.translations["ru"]
