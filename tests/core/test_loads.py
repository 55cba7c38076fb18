"""Springs with a count, their lengths and forces in table 5.1; second-order analogs
in table 3.1 when a model asks (issue 10; seed 001 lab 2 eq. 4: k springs)."""

import numpy as np
import pytest
from tests.helpers import examples as n_examples
from hypothesis import given, settings, strategies as st

from assur import io
from assur.io import ModelFileError
from assur.views.report import seed_tables
from tests.helpers.mechanisms import LIFT

SPRING = ('[[loads]]\ntype = "spring"\nname = "k1"\na = "03"\nb = "45"\nrate = "20 kN/m"\n'
          'free_length = "0.3 m"\npreload = "150 N"\n{count}\n')


def lift(count="", extra=""):
    text = LIFT.replace("[[cylinders]]", SPRING.format(count=count) + "\n[[cylinders]]")
    return io.loads(text.replace("[tables]", "[tables]\n" + extra), name="spring.toml")


def test_a_count_multiplies_the_springs_force():
    m1, m3 = lift(), lift("count = 3")
    a1, a3 = m1.mechanism.analyze(m1.range), m3.mechanism.analyze(m3.range)
    kin = a1.kinematics
    f_w = 27500.0 * kin.transmission("56")  # the weight P at 56 [N]
    # the springs' part of the cylinder force triples
    np.testing.assert_allclose(a3.statics.actuator_force("S") - f_w,
                               3 * (a1.statics.actuator_force("S") - f_w), rtol=1e-10)
    # and the reactions agree with virtual work
    np.testing.assert_allclose(a3.statics.actuator_force_from_reactions("S"),
                               a3.statics.actuator_force("S"), rtol=1e-9)


def test_spring_columns_in_table_5_1():
    m = lift("count = 2")
    a = m.mechanism.analyze(m.range)
    kin = a.kinematics
    t51 = next(t for t in seed_tables(a) if t.id == "5.1")
    L = np.hypot(kin.x("45") - kin.x("03"), kin.y("45") - kin.y("03"))
    T = 150.0 + 20e3 * (L - 0.3)
    np.testing.assert_allclose(t51["L_k1"], L, rtol=1e-14)
    np.testing.assert_allclose(t51["T_k1"], T, rtol=1e-12)
    np.testing.assert_allclose(t51["F_k1"], 2 * T, rtol=1e-12)
    assert t51.column("F_k1").unit == "N" and "пружин" in t51.column("F_k1").label["ru"]


@pytest.mark.parametrize("count,message", [("count = 0", "positive whole number"),
                                           ("count = 1.5", "whole"),
                                           ('count = "2 m"', "plain number")])
def test_a_bad_count_is_located(count, message):
    with pytest.raises(ModelFileError) as exc:
        lift(count)
    assert exc.value.key_path.endswith(".count") and message in str(exc.value)


def test_second_order_analogs_only_when_asked():
    plain = lift()
    t31 = next(t for t in seed_tables(plain.mechanism.analyze(plain.range)) if t.id == "3.1")
    assert not any(s.startswith("dd") for s in t31.symbols)
    m = lift(extra="second_order = true")
    a = m.mechanism.analyze(m.range)
    kin = a.kinematics
    t31 = next(t for t in seed_tables(a) if t.id == "3.1")
    for link in kin.links:
        np.testing.assert_array_equal(t31[f"ddphi{link}"], kin.ddphi(link))
    np.testing.assert_array_equal(t31["dU53"], kin.dratio("5", "3"))


@settings(max_examples=n_examples(20), deadline=None)
@given(s=st.floats(0.43, 0.66))
def test_second_order_columns_are_finite_differences_of_the_first(s):
    m = lift(extra="second_order = true").mechanism
    h = 1e-6
    kp, km, k0 = m.solve([s + h]), m.solve([s - h]), m.solve([s])
    for link in ("3", "5"):
        fd = (kp.dphi(link) - km.dphi(link)) / (2 * h)
        np.testing.assert_allclose(k0.ddphi(link), fd, rtol=1e-5, atol=1e-6)
    fd = (kp.ratio("5", "3") - km.ratio("5", "3")) / (2 * h)
    np.testing.assert_allclose(k0.dratio("5", "3"), fd, rtol=1e-5, atol=1e-6)


def test_second_order_must_be_true_or_false():
    with pytest.raises(ModelFileError) as exc:
        lift(extra='second_order = "yes"')
    assert exc.value.key_path == "tables.second_order"


@pytest.mark.parametrize("count", ["", "count = 3"])
def test_the_fused_kernel_counts_the_springs_too(count):
    from assur.core import statics
    m = lift(count)
    kin = m.mechanism.solve(m.range)
    fa = statics.solve(kin, method="array")
    ff = statics.solve(kin, method="fused")
    np.testing.assert_allclose(ff.actuator_force("S"), fa.actuator_force("S"), rtol=1e-12)
    np.testing.assert_allclose(ff.reaction("0", "5"), fa.reaction("0", "5"), rtol=1e-12,
                               atol=1e-9)
