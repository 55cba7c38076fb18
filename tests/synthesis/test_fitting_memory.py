"""The memory guard of fitting's screening (:func:`assur.synthesis.fitting.fit_parameters`,
issue 27): ``screen`` candidate designs × the tabulated positions estimated and refused
before a candidate is drawn; a normal fit still runs."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.stats  # noqa: F401  (imported by fit_parameters: before the measurements)

from assur import examples
from assur.errors import ModelError
from assur.synthesis.fitting import Target, fit_parameters
from tests.helpers.memory import allocates_little, assert_refusal

S = [0.42, 0.47, 0.52, 0.57, 0.62, 0.67]  # seed 003 [m]
PHI6 = [88.458, 90.028, 92.817, 96.905, 102.615, 110.344]  # [deg]
TABLE = Target("phi6", "phi(6)", S, PHI6, scale=np.pi / 180, tolerance=0.0005, period=360)


def test_a_large_screen_is_refused_before_the_candidates(monkeypatch):
    m = examples.hitch_003(L7=0.7)
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    # 1e5 candidates × 6 positions × 2480 B: 1.4 GiB of kinematics without the guard
    with allocates_little(), pytest.raises(ModelError) as e:
        fit_parameters(m, {"L7": (0.6, 0.9)}, [TABLE], screen=100_000, starts=1)
    assert_refusal(str(e.value), "--screen")
    assert "screen = 100000 designs × 6 positions" in str(e.value)


def test_screen_1e9_under_the_default_limit(monkeypatch):
    m = examples.hitch_003(L7=0.7)
    monkeypatch.delenv("ASSUR_MAX_MEMORY", raising=False)
    with allocates_little(), pytest.raises(ModelError, match="--screen"):
        fit_parameters(m, {"L7": (0.6, 0.9)}, [TABLE], screen=10**9, starts=1)


def test_a_normal_fit_still_runs(monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    fit = fit_parameters(examples.hitch_003(L7=0.7), {"L7": (0.6, 0.9)}, [TABLE],
                         screen=16, starts=1)
    assert round(fit.params["L7"], 4) == 0.7522
