"""The typed exceptions (:mod:`assur.errors`): each subclasses a built-in (so that
``except ValueError`` keeps working), an assembly failure names the first failing
design and position the kernel's report agrees with and survives pickling (Dask
sends it between processes), a singular ratio is raised where ``singular="mask"``
masks. (A model's doubtful parts warn with a :class:`ModelWarning`:
tests/groups/test_crank.py.)"""

import pickle

import numpy as np
import pytest

from assur import examples
from assur.errors import AssemblyError, ModelError, ModelWarning, SingularPositionError


def test_every_error_is_a_value_error_and_the_warning_a_user_warning():
    for cls in (ModelError, AssemblyError, SingularPositionError):
        assert issubclass(cls, ValueError)
    assert issubclass(ModelWarning, UserWarning)
    with pytest.raises(ValueError, match="unknown parameter"):
        examples.hitch_003(Lx=1.0)


def test_assembly_error_names_the_first_failure_of_the_report():
    """A batch of two designs, the second with a brace too long near the lowest stroke
    (the range run downwards, so that it fails at its end): the error's design,
    position and coordinate are those of the first element the report marks failed."""
    m = examples.hitch_003(L4=np.array([0.661283167, 0.95]))
    S = np.linspace(0.67, 0.42, 11)
    q = np.tile(S, (2, 1))
    report = m.solve(q, on_failure="report")
    ok = np.asarray(report.ok).reshape(2, len(S))
    assert ok[0].all() and not ok[1].all()
    first = int(np.flatnonzero(~ok[1])[0])
    assert first > 0
    with pytest.raises(AssemblyError) as exc:
        m.solve(q)
    e = exc.value
    assert (e.design, e.position) == (1, first)
    assert e.coordinate == {"S": pytest.approx(S[first])}
    assert e.group and e.links and e.amount > 0
    again = pickle.loads(pickle.dumps(e))
    assert type(again) is AssemblyError and str(again) == str(e)
    assert (again.group, again.links, again.design, again.position, again.amount) == \
        (e.group, e.links, e.design, e.position, e.amount)


def test_singular_ratio_is_raised_where_the_mask_is():
    """Near S = 0.44158 m link 4 of the hitch stands still (φ4' = 0): U34 = φ3'/φ4'
    is singular there — masked with singular="mask", raised otherwise."""
    m = examples.hitch_003()
    s0 = 0.44
    for _ in range(6):  # Newton's method on φ4'(S) = 0
        r = m.solve([s0])
        s0 -= float(r.dphi("4")[0] / r.ddphi("4")[0])
    kin = m.solve([0.42, s0, 0.6])
    masked = kin.ratio("3", "4", singular="mask")
    assert np.ma.getmaskarray(masked).tolist() == [False, True, False]
    with pytest.raises(SingularPositionError, match="singular at 1 position"):
        kin.ratio("3", "4")

