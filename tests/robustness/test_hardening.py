"""Issue 8: one regression test per class of failure (no traceback, no NaN, no
runaway memory, whatever the input)."""

from __future__ import annotations

import json
import re
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from typer.testing import CliRunner

from assur import examples, io
from assur.core import inputs
from assur.views.cli import app
from assur.errors import AssemblyError, ModelError

runner = CliRunner()
HITCH = io.bundled("hitch_003").read_text(encoding="utf-8")


def _file(tmp_path, text, name="m.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def _check(path):
    r = runner.invoke(app, ["check", str(path)])
    assert r.exception is None or isinstance(r.exception, SystemExit), r.exception
    assert "Traceback" not in r.output
    return r


def test_markup_in_user_text_printed_literally(tmp_path):
    p = _file(tmp_path, HITCH.replace('en = "Mini-tractor', 'en = "[/bold] Mini-tractor'))
    r = _check(p)
    assert r.exit_code == 0 and "[/bold] Mini-tractor" in r.output
    # an error on line 100: ":100:" stays, it is not an emoji code
    lines = HITCH.splitlines()
    lines += [""] * (99 - len(lines)) if len(lines) < 99 else []
    text = "\n".join(lines[:99]) + '\nL9 = "1 furlongs^2"\n' + "\n".join(lines[99:])
    bad = HITCH.replace('L3 = "0.200 m"', 'L3 = "[/x] m"')
    r = _check(_file(tmp_path, bad, "[red]x.toml"))
    assert r.exit_code == 1 and "[red]x.toml:" in r.output and "[/x]" in r.output
    r = runner.invoke(app, ["analyze", str(p), "-o", str(tmp_path / "[/o]"), "--lang", "[/l]"])
    assert r.exit_code == 1 and "[/l]" in r.output
    r = runner.invoke(app, ["analyze", str(p), "-o", str(tmp_path / "o"), "--draw-at", "[/d]"])
    assert r.exit_code == 2 and "[/d]" in r.output  # a usage error (issue 27)
    assert text  # the 100-line file below
    deep = HITCH.replace("[range]", "\n" * 40 + "[range]").replace(
        'Smax = "0.670 m"', 'Smax = "0.670 m"\nbad = "1 foo"')
    line = deep.splitlines().index('bad = "1 foo"') + 1
    r = _check(_file(tmp_path, deep, "long.toml"))
    flat = "".join(r.output.split())
    assert f"long.toml:{line}:" in flat and "💯" not in r.output


def test_numbers_the_parser_cannot_hold(tmp_path):
    for extra, what in ((f"ZZ = {'9' * 400}", "1e300"), ('ZZ = "1 km^1000"', "km^1000"),
                        ('ZZ = "1e999 m"', "finite"), (f"ZZ = {'7' * 5000}", "4000 digits")):
        text = HITCH.replace("eta = 0.84", "eta = 0.84\n" + extra)
        line = text.splitlines().index(extra) + 1
        with pytest.raises(io.ModelFileError) as e:
            io.loads(text, name="n.toml")
        assert e.value.line == line and e.value.key_path in ("params.ZZ", "ZZ"), str(e.value)
        assert what in str(e.value)


def test_ranges_without_bounds_are_refused_with_the_memory_estimate(tmp_path):
    for rng, key in (("count = 1000000000", "range.S.count"),
                     (f"count = {2**63 - 1}", "range.S.count"),
                     ("count = 20000000", "range.S.count"),
                     ('step = "1e-9 m"', "range.S.step"), ("step = 5e-324", "range.S.step")):
        text = HITCH.replace("count = 10", rng)
        with pytest.raises(io.ModelFileError) as e:
            io.loads(text, name="r.toml")
        assert e.value.key_path == key and re.search(r"limit [0-9.]+ GiB", str(e.value)), \
            str(e.value)
        assert "of memory" in str(e.value)


def test_memory_limit_is_settable(monkeypatch):
    monkeypatch.setenv(inputs.MAX_MEMORY_ENV, "1 MiB")
    assert inputs.max_memory() == 1024**2
    with pytest.raises(ModelError, match="limit 1 MiB"):
        examples.hitch_003().solve(np.linspace(0.42, 0.67, 10000))
    monkeypatch.setenv(inputs.MAX_MEMORY_ENV, "lots")
    with pytest.raises(ModelError, match="ASSUR_MAX_MEMORY"):
        inputs.max_memory()


REFUSAL = textwrap.dedent("""
    import json, re, resource, sys, time, tracemalloc
    from assur import io
    text = io.bundled("hitch_003").read_text(encoding="utf-8")
    text = text.replace("count = 10", sys.argv[1])
    if len(sys.argv) > 2:  # a second coordinate: a grid
        text = re.sub(r'at = [{] S = "(\\w+)" [}]', r'at = { S = "\\1", T = 0.45 }', text)
        text = (text.replace('coordinates = ["S"]', 'coordinates = ["S", "T"]')
                .replace('rb = "L7"', 'rb = "T"')
                .replace("[frame]", "T = { from = 0.4, to = 0.5, count = %s }\\n\\n[frame]"
                         % sys.argv[2]))
    io._units.registry()  # pint's registry is built once per process: not the refusal
    tracemalloc.start()
    t = time.perf_counter()
    try:
        io.loads(text, name="big.toml")
        msg = None
    except io.ModelFileError as e:
        msg = str(e)
    dt = time.perf_counter() - t
    peak = tracemalloc.get_traced_memory()[1]
    # the peak RSS of this process image: getrusage's ru_maxrss would also count the
    # forking pytest worker's memory before exec (Linux keeps the larger), VmHWM does not
    hwm = [l for l in open("/proc/self/status") if l.startswith("VmHWM:")]
    rss = int(hwm[0].split()[1]) * 1024 if hwm else \
        resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(json.dumps(dict(msg=msg, seconds=dt, peak=peak, rss=rss)))
""")


@pytest.mark.parametrize("args", [["count = 1000000000"], ["count = 100000", "100000"]])
def test_resource_refusal_is_fast_and_small(args):
    """1e9 positions, or a grid of 1e10: refused before any allocation — peak memory
    < 200 MB (the refusal's time is printed by the script, not asserted: no timed
    assertions in tests)."""
    out = subprocess.run([sys.executable, "-c", REFUSAL] + args, capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    res = json.loads(out.stdout.strip().splitlines()[-1])
    assert res["msg"] and "positions would need about" in res["msg"], res
    assert re.search(r"limit [0-9.]+ GiB", res["msg"]), res["msg"]
    assert res["peak"] < 200e6, res     # Python + numpy allocations during the refusal
    assert res["rss"] < 400e6, res      # the whole process, imports included


def test_inputs_that_are_not_regular_files(tmp_path):
    p = _file(tmp_path, HITCH)
    for bad, words in ((tmp_path, "is a directory"), ("/dev/zero", "not a regular file"),
                       ("x" * 300 + ".toml", "too long"), ("nope.toml", "no such file")):
        r = _check(bad)
        assert r.exit_code == 1 and words in r.output, r.output
    afile = tmp_path / "afile"
    afile.write_text("x")
    for out, words in ((afile, "not a directory"), (afile / "sub", "cannot create"),
                       ("", "empty")):
        r = runner.invoke(app, ["analyze", str(p), "-o", str(out), "--format", "csv"])
        assert r.exit_code in (1, 2) and words in r.output, r.output
    r = runner.invoke(app, ["demo", "--lang", "de", "-o", str(tmp_path / "d")])
    assert r.exit_code == 1 and "--lang must be one of" in r.output


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "model.toml"
    os.mkfifo(fifo)
    out = subprocess.run([sys.executable, "-m", "assur", "check", str(fifo)],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 1 and "not a regular file" in out.stderr
    assert "Traceback" not in out.stderr


def test_deep_nesting(tmp_path):
    for extra in ("ZZ = " + "[" * 500 + "]" * 500, ".".join(["zz"] * 300) + " = 1"):
        text = HITCH.replace("eta = 0.84", "eta = 0.84\n" + extra)
        with pytest.raises(io.ModelFileError, match="nested more than 32") as e:
            io.loads(text, name="d.toml")
        assert e.value.line == text.splitlines().index(extra) + 1 and e.value.key_path


def test_inconsistent_physical_data(tmp_path):
    text = HITCH.replace('count = "kgc"', 'count = "kgc"\nside = "rod"\nrod = "90 mm"')
    with pytest.raises(io.ModelFileError, match="0 < rod < bore") as e:
        io.loads(text, name="rod.toml")
    assert e.value.key_path == "cylinders[0].rod"
    # a pose point whose offsets are literals, not parameter names
    m = io.loads(HITCH.replace('dx = "X6"', 'dx = "0.857 m"').replace('dy = "Y6"',
                                                                       'dy = "0.156 m"'))
    ref = io.load(io.bundled("hitch_003"))
    np.testing.assert_allclose(m.mechanism.solve(m.range).x("S6"),
                               ref.mechanism.solve(ref.range).x("S6"), rtol=0, atol=1e-12)


def test_unused_coordinate_is_an_error():
    text = (HITCH.replace('coordinates = ["S"]', 'coordinates = ["S", "T"]')
            .replace('at = { S = "Sp" }', 'at = { S = "Sp", T = 0 }')
            .replace("[frame]", "T = { from = 0, to = 1, count = 1000 }\n\n[frame]"))
    with pytest.raises(io.ModelFileError, match='coordinate "T" is not used') as e:
        io.loads(text, name="u.toml")
    assert e.value.key_path == "model.coordinates[1]"


@pytest.mark.parametrize("edit, words", [
    (('L6 = "0.515 m"', 'L6 = "1e200 m"'), "at most 10000 m"),
    (("eta = 0.84", "eta = 5e-324"), "efficiency in [0.01, 1]"),
    (("kgc = 2", "kgc = 5e-324"), "whole number (a count) from 1 to"),
    (('Dgc = "80 mm"', 'Dgc = "1e-200 m"'), "at least 1e-06 m"),
    (('Dgc = "80 mm"', 'Dgc = "1e200 m"'), "at most 10000 m"),
    (('P6 = "27.5 kN"', "P6 = 1.7e308"), "force of at most 1e+12 N"),
])
def test_non_finite_results_after_a_clean_check_are_refused(edit, words):
    with pytest.raises(io.ModelFileError, match=__import__("re").escape(words)) as e:
        io.loads(HITCH.replace(*edit), name="p.toml")
    assert e.value.key_path.startswith("params."), str(e.value)


def test_non_finite_results_through_params_are_refused():
    m = examples.hitch_003()
    q = np.linspace(0.42, 0.67, 5)
    with pytest.raises(ModelError, match="at most 10000 m"):
        m.solve(q, params={"L6": 1e200})
    with pytest.raises(ModelError, match="at least 1e-06 m"):
        m.solve(q, params={"L4": -0.66})
    with pytest.raises(ModelError, match="efficiency"):
        m.analyze(q, params={"eta": 5e-324})
    a = m.analyze(q)
    inputs.check_finite(a)  # the guard passes on a sound model …
    a.cylinders["ГЦ"].pressure = a.cylinders["ГЦ"].pressure * np.inf
    with pytest.raises(ModelError, match="pressure of cylinder 'ГЦ' is inf"):
        inputs.check_finite(a)  # … and names the quantity otherwise


def test_slowness_on_size_units_are_parsed_once_per_unit():
    from assur.io import _units
    _units._unit_problem.cache_clear()
    extra = "".join(f'U{i} = "{i} mm"\n' for i in range(2000))
    io.loads(HITCH.replace("eta = 0.84", "eta = 0.84\n" + extra))
    info = _units._unit_problem.cache_info()
    assert info.misses < 20 and info.hits > 2000, info


@pytest.mark.parametrize("q, words", [
    ([], "no positions"), (np.zeros((0, 0)), "no positions"),
    ([[0.5, 0.6], [0.5]], "ragged"), (None, "are None"), ("abc", "text"),
])
def test_python_api_edges(q, words):
    with pytest.raises(ModelError, match=words):
        examples.hitch_003().solve(q)


def test_python_api_params_and_memory():
    m = examples.hitch_003()
    q = np.linspace(0.42, 0.67, 5)
    with pytest.raises(ModelError, match="parameter 'L4' must be a number"):
        m.solve(q, params={"L4": "abc"})
    with pytest.raises(ModelError, match="unknown parameter"):
        m.solve(q, params={"nope": 1.0})
    # 1e8 positions: refused from the estimate, before numpy allocates the results
    q8 = np.broadcast_to(np.float64(0.5), (10**8,))
    with pytest.raises(ModelError, match=r"would need about .* GiB of memory \(limit [0-9.]+ GiB"):
        m.solve(q8)


def test_false_continuity_error_near_a_dead_point(monkeypatch):
    """The cubic Hermite check between two positions can overshoot where analogs are
    huge (near another group's dead point, ~1/sin μ) although the triangle stays open.
    A flagged interval is therefore solved again on a finer grid (assur.core.program,
    REFINE_POINTS × REFINE_DEPTH levels) and the flag stands only if the group fails
    there too: a spurious flag is cleared, a real one (the dyad opens between the
    samples) is still reported."""
    from assur import Mechanism
    from assur.core import program
    from assur.kernel import run as KR

    m = (Mechanism("crank-dyad", coordinates=("q",), params=dict(ra=2.65, rb=0.6))
         .frame("O", 0.0, 0.0).frame("B", 0.0, 3.0)
         .crank("crank", pivot="O", out="A", radius=1.0, q="q", links=("1",))
         .dyad("II", a="A", b="B", out="C", ra="ra", rb="rb", branch=1, links=("2", "3")))
    from assur.kernel import emit as KE

    real = KR.run
    calls = []
    code = 3 * KE.CODES_PER_OP + KE.FAIL_CONTINUITY  # the dyad, group 3

    def spurious(kernel, params, trig, q, npd, check, out, amount, status):
        """The kernel (which checks continuity itself), plus a false flag on the first
        interval of a 2-point range."""
        nfail = real(kernel, params, trig, q, npd, check, out, amount, status)
        if check and q.shape[1] == 2 and not calls:
            calls.append(1)
            status[1], amount[1] = code, -19.8
            nfail += 1
        return nfail

    monkeypatch.setattr(KR, "run", spurious)
    r = m.solve([0.0, 0.1])            # flagged, refined, cleared: the dyad stays open
    assert calls and r.ok.all()
    assert abs(float(r.x("C")[1])) > 0  # the outputs of the cleared element are kept
    calls.clear()
    with pytest.raises(AssemblyError, match="cannot move continuously"):
        m.solve([0.0, 2.0])            # really opens between q = 1.32 and 1.82
    monkeypatch.setattr(program, "REFINE_DEPTH", 0)
    calls.clear()
    with pytest.raises(AssemblyError, match="dips to -19.8"):
        m.solve([0.0, 0.1])            # without refinement the false flag would stand


def test_two_force_columns_agree_for_a_double_rod_cylinder():
    """Two slider inputs on one coordinate (a double-rod cylinder driving two
    sliders): the generalized force from the reactions is the sum of both actuators,
    equal to the virtual-work force (it was half of it)."""
    from assur import Mechanism
    m = (Mechanism("double rod", coordinates=("S",))
         .frame("O1", 0.0, 0.0).frame("O2", 0.0, 1.0)
         .slider_input("left", origin="O1", out="P1", s="S", direction=0.3, links=("a",))
         .slider_input("right", origin="O2", out="P2", s="S", direction=-0.2, links=("b",))
         .force("P1", 100.0, -40.0).force("P2", -25.0, 60.0))
    s = m.analyze(np.linspace(0.1, 0.5, 5)).statics
    vw, rx = s.actuator_force("S"), s.actuator_force_from_reactions("S")
    assert np.allclose(vw, rx, rtol=1e-12, atol=1e-9), (vw, rx)
    expect = -(100.0 * np.cos(0.3) - 40.0 * np.sin(0.3)) - (-25.0 * np.cos(-0.2)
                                                             + 60.0 * np.sin(-0.2))
    assert np.allclose(vw, expect)


def test_a_spring_count_that_is_not_whole_is_called_a_count_not_cylinders():
    # perturbed inputs: a spring's count of 2.01 names the spring, and no cylinders
    from assur import io
    model = io.load(io.bundled("conditioner_lab2"))
    mech = model.mechanism
    with pytest.raises(ModelError) as e:
        mech.with_params(k_s=2.01).analyze(model.range)
    msg = str(e.value)
    assert "spring 'sp'.count" in msg and "whole number (a count) from 1 to" in msg
    assert "cylinders" not in msg
