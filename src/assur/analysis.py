"""One call for the whole worksheet: kinematics, forces, cylinders and stability.

``Mechanism.analyze(q)`` returns an :class:`Analysis`: the seed worksheets' §2–§6
as result objects (tables, reports and the page are views of it).
"""

from __future__ import annotations

from . import statics as _statics
from .inputs import check_finite
from .hydraulics import CylinderResult

__all__ = ["Analysis", "analyze", "gravity_of"]


class Analysis:
    """Results of :meth:`assur.Mechanism.analyze`.

    Attributes
    ----------
    kinematics : Kinematics
    statics : Statics
    cylinders : dict of str to CylinderResult
        By cylinder name.
    stability : StabilityResult or None
        When the mechanism has machine data (:meth:`Mechanism.with_machine`).
    solved : tuple of SolvedCondition
        The design conditions a model file fixed (shown in reports).
    """

    def __init__(self, kinematics, statics, cylinders, stability, solved=()):
        self.kinematics = kinematics
        self.statics = statics
        self.cylinders = cylinders
        self.stability = stability
        #: design conditions solved for the model (:class:`assur.synthesis.SolvedCondition`)
        self.solved = tuple(solved)

    @property
    def mechanism(self):
        return self.kinematics.mechanism

    def formula(self, name):
        """Values of the model's extra formula ``name`` over the positions [SI]
        (:class:`assur.columns.Formula`, ``[[tables.formulas]]``).

        Raises
        ------
        KeyError
            If the model declares no formula of that name (the message lists them).
        """
        from .columns import formulas_of
        found = {f.name: f for f in formulas_of(self.mechanism)}
        if name not in found:
            raise KeyError(f"no formula {name!r}; the model declares: {sorted(found)}")
        return found[name].evaluate(self.kinematics)

    def cylinder(self, name=None):
        """The result of one cylinder group (the only one when ``name`` is None)."""
        if name is None:
            if len(self.cylinders) != 1:
                raise ValueError(f"name the cylinder: one of {list(self.cylinders)}")
            return next(iter(self.cylinders.values()))
        return self.cylinders[name]


def gravity_of(mech) -> float:
    """The acceleration of gravity of a mechanism [m/s²]: the model's own
    (:attr:`Mechanism.gravity`, ``[model] gravity`` of a model file), else
    :data:`assur.statics.GRAVITY` (9.81)."""
    return float(_statics.GRAVITY if mech.gravity is None else mech.gravity)


def analyze(mech, q, params=None, qdot=None, qddot=None, g=None, **solve_kw):
    """Solve positions and analogs, forces, reactions, cylinders and stability.

    Parameters are those of :meth:`Mechanism.solve` and :func:`assur.statics.solve`;
    ``g`` [m/s²] defaults to the model's gravity (:func:`gravity_of`).
    """
    if g is None:
        g = gravity_of(mech)
    kin = mech.solve(q, params=params, **solve_kw)
    st = _statics.solve(kin, qdot=qdot, qddot=qddot, g=g)
    cyl = {c.name: CylinderResult(kin, st, c) for c in kin.mechanism.cylinders}
    stab = None
    machine = kin.mechanism.machine
    if machine is not None:
        stab = machine.evaluate(kin)
    result = Analysis(kin, st, cyl, stab)
    check_finite(result)  # never return NaN or inf
    return result
