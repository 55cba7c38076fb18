"""Every numeric option of the command line is range-checked by its type (issue 27):
the boundary values pass, the values beyond are usage errors (exit status 2) that
name the option and the allowed range; counts may be written 2e7."""

import re

import pytest
import typer
from typer.testing import CliRunner

from assur.io import bundled
from assur.views.cli import app
from assur.views.cli._types import COUNT, DURATION, SEED, Address, Count, Numbers

runner = CliRunner()

NO_FILE = "no/such/model.toml"  # an accepted option reaches the command: exit 1, no such file


def _flat(text: str) -> str:
    """The output without rich's panel borders, on one line."""
    return " ".join(re.sub(r"[│╭╮╰╯─]", " ", text).split())


def _args(command, option, value):
    head = [command, NO_FILE]
    if command == "fit":
        head += ["table.csv", "--fit", "L4=0.5:0.8"]
    if command == "analyze":
        head += ["--format", "csv"]
    return head + [option, value]


# (command, option, smallest accepted, largest accepted or None, the range's words)
OPTIONS = [
    ("sweep", "--samples", "1", None, "≥ 1"),
    ("sweep", "--chunk", "1", None, "≥ 1"),
    ("sweep", "--positions", "2", None, "≥ 2"),
    ("sweep", "--workers", "0", None, "≥ 0"),
    ("sweep", "--seed", "0", "4294967295", "0 … 4294967295"),
    ("optimize", "--popsize", "1", None, "≥ 1"),
    ("optimize", "--maxiter", "1", None, "≥ 1"),
    ("optimize", "--chunk", "1", None, "≥ 1"),
    ("optimize", "--positions", "2", None, "≥ 2"),
    ("optimize", "--workers", "0", None, "≥ 0"),
    ("optimize", "--seed", "0", "4294967295", "0 … 4294967295"),
    ("tolerance", "--samples", "2", None, "≥ 2"),
    ("tolerance", "--seed", "0", "4294967295", "0 … 4294967295"),
    ("fit", "--screen", "1", None, "≥ 1"),
    ("fit", "--starts", "1", None, "≥ 1"),
    ("tables", "--columns", "1", None, "≥ 1"),
    ("analyze", "--frames", "0", None, "≥ 0"),
    ("analyze", "--jobs", "0", None, "≥ 0"),
    ("serve", "--port", "0", "65535", "0 … 65535"),
]


def _below(low: str) -> str:
    return str(int(low) - 1)


@pytest.mark.parametrize("command,option,low,high,words", OPTIONS,
                         ids=[f"{c}{o}" for c, o, *_ in OPTIONS])
def test_count_options_accept_their_bounds_and_refuse_beyond(command, option, low, high,
                                                             words):
    for ok in [low, f"{int(low) + 1}.0", "2e1"] + ([high] if high else ["1e9"]):
        r = runner.invoke(app, _args(command, option, ok))
        assert r.exit_code == 1 and "no such file" in r.output, (ok, r.output)
    bad = [_below(low), "2.5", "nan", "inf", "-inf", "1e400", "ten", ""]
    if high:
        bad += [str(int(high) + 1), str(2**64)]
    for value in bad:
        r = runner.invoke(app, _args(command, option, value))
        out = _flat(r.output)
        assert r.exit_code == 2, (value, r.output)
        assert f"Invalid value for '{option}'" in out and words in out, (value, out)
        assert "Traceback" not in r.output and "no such file" not in out


@pytest.mark.parametrize("value", ["1e-9", "0.3", "3600", "1e6"])
def test_duration_accepts_finite_positive_seconds(value):
    r = runner.invoke(app, ["simulate", NO_FILE, "--duration", value])
    assert r.exit_code == 1 and "no such file" in r.output, r.output


@pytest.mark.parametrize("value", ["0", "-1", "-0.0", "nan", "NaN", "inf", "-inf", "1e999",
                                   "1 year", ""])
def test_duration_refuses_nan_zero_negative_infinite(value):
    """Issue 27: ``--duration nan`` or ``-1`` was silently replaced by the file's
    duration (exit 0); now a usage error naming the option and the range."""
    r = runner.invoke(app, ["simulate", NO_FILE, "--duration", value])
    out = _flat(r.output)
    assert r.exit_code == 2, (value, r.output)
    assert "'--duration'" in out and "a finite number > 0 s" in out, out


def test_duration_refused_before_the_file_is_simulated():
    """A real drive's file: ``nan`` never reaches the simulation (it used to run the
    file's duration and exit 0)."""
    r = runner.invoke(app, ["simulate", str(bundled("adapter_lab6")), "-o", "unused",
                            "--duration", "nan"])
    assert r.exit_code == 2 and "'--duration'" in _flat(r.output)


@pytest.mark.parametrize("value", ["1e-3", "20", "1e300"])
def test_outlier_accepts_positive(value):
    r = runner.invoke(app, _args("fit", "--outlier", value))
    assert r.exit_code == 1 and "no such file" in r.output, r.output


@pytest.mark.parametrize("value", ["0", "-1", "nan", "inf"])
def test_outlier_refuses_nonpositive_and_nonfinite(value):
    r = runner.invoke(app, _args("fit", "--outlier", value))
    out = _flat(r.output)
    assert r.exit_code == 2 and "'--outlier'" in out and "> 0" in out, out


def test_a_count_written_2e7_is_that_count():
    assert COUNT("2e7") == 20_000_000 and COUNT("2.0e1") == 20 and COUNT(" 7 ") == 7
    assert COUNT("10_000") == 10_000 and COUNT(str(2**70)) == 2**70


def test_sweep_2e1_samples(tmp_path):
    """``--samples 2e1`` draws 20 designs (was refused: integers only)."""
    out = tmp_path / "s.parquet"
    r = runner.invoke(app, ["sweep", str(bundled("hitch_003_design")), "--samples", "2e1",
                            "--positions", "2", "--workers", "0", "-o", str(out)])
    assert r.exit_code == 0, r.output
    assert "20 designs × 2 positions" in _flat(r.output)
    import pandas as pd
    assert len(pd.read_parquet(out)) == 20


@pytest.mark.parametrize("command,extra", [("dxf", ["--at"]), ("analyze", ["--draw-at"])])
@pytest.mark.parametrize("value", ["nan", "0.5,nan", "inf", "-inf", "x", ",", "0.5;0.6"])
def test_positions_must_be_finite_numbers(command, extra, value):
    """``dxf --at nan`` on a crank exited 0; every spelling of a non-number is now a
    usage error naming the option."""
    r = runner.invoke(app, [command, str(bundled("combine_002")), *extra, value])
    out = _flat(r.output)
    assert r.exit_code == 2, (value, r.output)
    assert f"'{extra[0]}'" in out and "Traceback" not in r.output, out


def test_dxf_duplicate_positions_drawn_once(tmp_path):
    """``dxf --at 0.5,0.5`` raised ezdxf's 'GROUP already exists'; now one group."""
    import ezdxf

    out = tmp_path / "h.dxf"
    r = runner.invoke(app, ["dxf", str(bundled("hitch_003")), "--at", "0.5,0.5,0.42",
                            "-o", str(out)])
    assert r.exit_code == 0, r.output
    assert sorted(g for g, _ in ezdxf.readfile(out).groups) == ["S=0.42 m", "S=0.5 m"]
    r = runner.invoke(app, ["dxf", str(bundled("combine_002")), "--at", "10,10,10.0001",
                            "-o", str(out)])
    assert r.exit_code == 0, r.output
    assert len(ezdxf.readfile(out).groups) == 1


def test_dxf_at_on_a_crank_in_range_still_draws(tmp_path):
    out = tmp_path / "c.dxf"
    r = runner.invoke(app, ["dxf", str(bundled("combine_002")), "--at", "90°,180",
                            "-o", str(out)])
    assert r.exit_code == 0, r.output


def test_the_types_directly():
    assert Count(0, 65535)("65535") == 65535 and SEED("0") == 0
    assert DURATION("5e-1") == 0.5
    assert Numbers()("1, 2,") == (1.0, 2.0)
    for parse, value in [(COUNT, True), (COUNT, "0x10"), (SEED, "4294967296"),
                         (DURATION, "0"), (Numbers(), " , ")]:
        with pytest.raises(typer.BadParameter):
            parse(value)


@pytest.mark.parametrize("value", ["not a url", "tcp://host", "host", "http://host:8786",
                                   "tcp://host:0", "tcp://host:65536", "tcp://ho st:8786",
                                   "tcp://host:8786/x", "inproc://x/1/2", ""])
def test_scheduler_address_refused_with_a_usage_error(value):
    r = runner.invoke(app, ["sweep", NO_FILE, "--scheduler", value])
    out = _flat(r.output)
    assert r.exit_code == 2, (value, r.output)
    assert "'--scheduler'" in out and "host:port" in out and "Traceback" not in r.output


@pytest.mark.parametrize("value,normal", [("127.0.0.1:8786", "tcp://127.0.0.1:8786"),
                                          ("TCP://node-1.cluster:8786",
                                           "tcp://node-1.cluster:8786"),
                                          ("tls://[::1]:1", "tls://[::1]:1")])
def test_scheduler_addresses_accepted(value, normal):
    assert Address()(value) == normal
