"""The ``[dynamics]`` section of model files (:mod:`assur.io._dynamics`,
docs/crank-dynamics.md): values in SI, errors with the file, line and key."""

import pytest

from assur import io
from assur.dynamics.balancing import CounterMass

BASE = io.bundled("cleaning_lab3").read_text(encoding="utf-8")
HEAD = BASE[:BASE.index("[dynamics]")]


def test_the_bundled_section():
    d = io.load(io.bundled("cleaning_lab3")).dynamics
    assert d.delta == 0.05 and d.flywheel is None and d.objective == "amplitudes"
    assert d.counter_masses == (CounterMass("3", (0.0, 30.0), (-0.3, 0.3), (-0.1, 0.1)),
                                CounterMass("1", (0.0, 20.0), (-0.1, 0.1), (-0.1, 0.1)))


def test_no_section_and_a_given_flywheel():
    assert io.loads(HEAD, name="x.toml").dynamics is None
    d = io.loads(HEAD + '[dynamics]\nflywheel = "7.5 kg*m^2"\n', name="x.toml").dynamics
    assert d.flywheel == 7.5 and d.delta is None and d.counter_masses == ()


@pytest.mark.parametrize("extra, where, words", [
    ('[dynamics]\ndelta = 0.05\nflywheel = "1 kg*m^2"\n', "dynamics", "not both"),
    ("[dynamics]\ndelta = 3\n", "dynamics.delta", "in (0, 2)"),
    ('[dynamics]\nflywheel = "2 kg"\n', "dynamics.flywheel", "moment of inertia"),
    ('[dynamics]\nobjective = "volume"\n', "dynamics.objective", "amplitudes"),
    ('[dynamics]\ndelat = 0.1\n', "dynamics.delat", 'did you mean "delta"'),
    ('[[dynamics.counter_masses]]\nlink = "33"\nmass = ["0 kg", "1 kg"]\n',
     "dynamics.counter_masses[0].link", 'did you mean "3"'),
    ('[[dynamics.counter_masses]]\nlink = "3"\nmass = ["2 kg", "1 kg"]\n',
     "dynamics.counter_masses[0].mass", "low ≤ high"),
    ('[[dynamics.counter_masses]]\nlink = "3"\nmass = ["0 kg", "1 m"]\n',
     "dynamics.counter_masses[0].mass[1]", "mass"),
])
def test_errors_name_the_line_and_key(extra, where, words):
    with pytest.raises(io.ModelFileError) as e:
        io.loads(HEAD + extra, name="x.toml")
    msg = str(e.value)
    line = HEAD.count("\n") + 2
    assert f"x.toml:" in msg and where in msg and words in msg, msg
    assert int(msg.split(":")[1]) >= line - 1, msg
