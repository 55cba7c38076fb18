"""Local refinement with exact gradients (:mod:`assur.synthesis.sensitivity.refine`):
SLSQP raises the smallest output over the positions, stays in its bounds, and stops
where the output computed independently (an analysis of the refined design) is what
it reports and no feasible step along the variables improves it; the scaling of
the variables maps their bounds to [0, 1] and evaluates each point once."""

import numpy as np
import pytest

from assur import examples
from assur.synthesis.sensitivity.refine import Scaled, local_refine


def smallest_capacity(m, q, **params):
    """min over q of the lift capacity at 56 by the cylinder, through analyze()."""
    return float(np.min(m.with_params(**params).analyze(q).cylinder().capacity("56")))


def test_the_refined_design_is_a_local_optimum():
    m = examples.hitch_003()
    q = [0.42, 0.545, 0.67]
    bounds = {"X01": (0.40, 0.43), "Y01": (0.55, 0.58)}
    r = local_refine(m, q, "G(ГЦ, 56)", bounds)
    assert r.success and r.value >= r.start_value
    assert r.start_value == pytest.approx(smallest_capacity(m, q), rel=1e-9)
    assert r.value == pytest.approx(smallest_capacity(m, q, **r.params), rel=1e-9)
    for name, (lo, hi) in bounds.items():
        assert lo <= r.params[name] <= hi
        for step in (-1e-4, 1e-4):
            moved = r.params[name] + step
            if lo <= moved <= hi:
                other = smallest_capacity(m, q, **{**r.params, name: moved})
                assert other <= r.value * (1 + 1e-7), (name, step)


def test_scaled_variables():
    calls = []
    ev = Scaled([0.40, 1.0], [0.43, 1.0], lambda x: calls.append(x) or float(x.sum()))
    np.testing.assert_allclose(ev.span, [0.03, 1.0])  # a fixed variable is scaled by 1
    np.testing.assert_allclose(ev.x([0.5, 0.0]), [0.415, 1.0])
    np.testing.assert_allclose(ev.z(ev.x([0.25, 0.0])), [0.25, 0.0])
    assert ev([0.5, 0.0]) == ev([0.5, 0.0]) == pytest.approx(1.415) and ev.count == 1
    clipped = Scaled([0.40], [0.43], fn=None, clip=True)
    np.testing.assert_allclose(clipped.x([1.2]), [0.43])
