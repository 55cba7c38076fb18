"""One call for the whole worksheet: kinematics, forces, cylinders and stability.

``Mechanism.analyze(q)`` returns an :class:`Analysis`: the seed worksheets' §2–§6
as result objects (tables, reports and the page are views of it).
"""

from __future__ import annotations

from .core import statics as _statics
from .core.inputs import check_finite
from .machines.cylinders import cylinder_results
from .core.motion import rod_rates
from .texts import Text

__all__ = ["Analysis", "analyze", "gravity_of", "add_dynamics", "add_lift_test"]


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
    dynamics : CrankDynamics or None
        Kinetostatics with inertia of a crank machine at its ``[motion]`` speed
        (:func:`add_dynamics`, :mod:`assur.dynamics.crank`).
    flywheel : Flywheel or None
        The flywheel of ``[dynamics]`` (:mod:`assur.dynamics.flywheel`).
    balancing : Balancing or None
        The counter-masses of ``[dynamics]`` (:mod:`assur.dynamics.balancing`).
    lift_test : LiftTestResult or None
        The standard lift test of a hitch (ISO 789-2; :func:`add_lift_test`).
    notes : list of str
        What the analysis left out and why (e.g. masses without a crank speed).
    model_warnings : tuple of str
        The model file's warnings (unused parameters), shown in the report.
    source : str or None
        The model file's name (``hitch_003.toml``, no folders), when the analysis
        is a model file's (:meth:`assur.io.Model.analyze`); shown in the report.

    Examples
    --------
    >>> from assur import examples
    >>> a = examples.hitch_003().analyze([0.42, 0.67])      # S [m]
    >>> list(a.cylinders), a.kinematics.shape
    (['ГЦ'], (2,))
    >>> [round(float(f)) for f in a.statics.actuator_force()]   # Fgc, seed 003 table 4.1 [N]
    [129614, 135652]
    >>> a.stability.steerable.tolist(), a.dynamics is None, a.notes
    ([True, True], True, [])
    """

    def __init__(self, kinematics, statics, cylinders, stability, solved=()):
        self.kinematics = kinematics
        self.statics = statics
        self.cylinders = cylinders
        self.stability = stability
        #: design conditions solved for the model (:class:`assur.synthesis.conditions.SolvedCondition`)
        self.solved = tuple(solved)
        self.dynamics = None
        self.flywheel = None
        self.balancing = None
        self.lift_test = None
        self.notes = []
        self.model_warnings = ()
        self.source = None
        #: the coordinate rates (q̇, q̈) of the statics (a rod's [motion]), or None
        self.rates = None

    @property
    def mechanism(self):
        """The analysed mechanism (that of :attr:`kinematics`).

        Examples
        --------
        >>> from assur import examples
        >>> a = examples.hitch_003().analyze([0.42])
        >>> a.mechanism.name, a.mechanism.coordinates
        ('hitch_003', ('S',))
        """
        return self.kinematics.mechanism

    def formula(self, name):
        """Values of the model's extra formula ``name`` over the positions [SI]
        (:class:`assur.core.columns.Formula`, ``[[tables.formulas]]``).

        Raises
        ------
        KeyError
            If the model declares no formula of that name (the message lists them).

        Examples
        --------
        Seed 003 §6 prints a flagged "maximum lift capacity" GS6max; its model file
        declares it as a formula:

        >>> from assur import examples
        >>> a = examples.hitch_003().analyze([0.42, 0.67])
        >>> [round(float(v)) for v in a.formula("GS6max")]   # table 6.1, as printed [N]
        [50645, 57569]
        >>> a.formula("G_max")
        Traceback (most recent call last):
        ...
        KeyError: "no formula 'G_max'; the model declares: ['GS6max']"
        """
        from .core.columns import formulas_of
        found = {f.name: f for f in formulas_of(self.mechanism)}
        if name not in found:
            raise KeyError(f"no formula {name!r}; the model declares: {sorted(found)}")
        return found[name].evaluate(self.kinematics)

    def cylinder(self, name=None):
        """The result of one cylinder group (the only one when ``name`` is None).

        Examples
        --------
        >>> from assur import examples
        >>> a = examples.hitch_003().analyze([0.42, 0.67])
        >>> [round(float(g)) for g in a.cylinder().capacity("56")]   # G56, table 4.1 [N]
        [33139, 56377]
        >>> examples.steering_lab4().analyze([0.51]).cylinder()   # two cylinders
        Traceback (most recent call last):
        ...
        ValueError: name the cylinder: one of ['ГЦ1', 'ГЦ2']
        """
        if name is None:
            if len(self.cylinders) != 1:
                raise ValueError(f"name the cylinder: one of {list(self.cylinders)}")
            return next(iter(self.cylinders.values()))
        return self.cylinders[name]

    def _repr_html_(self):
        """Summary, drawing and the seed-like tables in a notebook (:mod:`assur.views.notebook`)."""
        from .views.notebook import analysis_html
        return analysis_html(self)


def gravity_of(mech) -> float:
    """Deprecated: :attr:`assur.Mechanism.g` [m/s²] (goes in the next release).

    Examples
    --------
    >>> import warnings
    >>> from assur import examples
    >>> from assur.analysis import gravity_of
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", DeprecationWarning)
    ...     gravity_of(examples.hitch_003())                  # [m/s²]
    9.81
    """
    import warnings
    warnings.warn("assur.analysis.gravity_of(m) is m.g (assur.Mechanism.g); the old name goes "
                  "in the next release", DeprecationWarning, stacklevel=2)
    return mech.g


def analyze(mech, q, params=None, qdot=None, qddot=None, g=None, **solve_kw):
    """Solve positions and analogs, forces, reactions, cylinders and stability.

    Parameters are those of :meth:`Mechanism.solve` and :func:`assur.core.statics.solve`;
    ``g`` [m/s²] defaults to the model's gravity (:attr:`assur.Mechanism.g`).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.analysis import analyze
    >>> a = analyze(examples.hitch_003(), [0.42, 0.67])
    >>> [round(float(v)) for v in a.cylinder("ГЦ").capacity("S6")]   # GS6, table 4.1 [N]
    [31354, 29959]
    """
    if g is None:
        g = mech.g
    kin = mech.solve(q, params=params, **solve_kw)
    notes = []
    if qdot is None and qddot is None:
        rates = rod_rates(kin)   # the rods' [motion]: inertia loads without Python
        if rates is not None:
            qdot, qddot = rates
            # the motions themselves are shown with the model (in the user's units)
            notes.append(Text(f"{mech.name}: inertia loads at the rod motion of [motion]",
                              ru=f"{mech.name}: силы инерции при движении штока по "
                                 f"[motion]"))
    st = _statics.solve(kin, qdot=qdot, qddot=qddot, g=g)
    cyl = cylinder_results(kin, st, g=g)
    stab = None
    machine = kin.mechanism.machine
    if machine is not None:
        stab = machine.evaluate(kin)
    result = Analysis(kin, st, cyl, stab)
    result.notes.extend(notes)
    #: the coordinate rates the statics used (q̇, q̈), or None: static
    result.rates = None if qdot is None and qddot is None else (qdot, qddot)
    check_finite(result)  # never return NaN or inf
    return result


def add_dynamics(analysis, spec=None):
    """Add the crank dynamics to ``analysis`` (in place; returns it): the kinetostatics
    with inertia at the crank's speed, the reduced moment and moment of inertia, the
    common centre of mass (:func:`assur.dynamics.crank.crank_dynamics`), the flywheel and the
    balancing that ``spec`` asks for (seed 001 lab 3; docs/crank-dynamics.md).

    They apply to a mechanism of one crank-angle coordinate with masses on its moving
    links; the speed and direction come from its motion (``[motion]``,
    :meth:`Mechanism.with_motion`). A mechanism without masses is left as it is; one
    with masses but no speed gets a note saying why its inertia loads are missing.

    Parameters
    ----------
    analysis : Analysis
        One design.
    spec : DynamicsSpec, optional
        The ``[dynamics]`` section (:attr:`assur.io.Model.dynamics`): ``delta`` (a
        target coefficient of speed irregularity δ [-]) or ``flywheel`` (a given J_f
        [kg·m²]), ``counter_masses`` and ``objective`` for balancing.

    Raises
    ------
    ModelError
        When ``spec`` asks for a flywheel or balancing the mechanism cannot have (no
        crank coordinate, no masses, no speed, positions that are not one turn).

    Examples
    --------
    The grain-cleaning mechanism of seed 001 lab 3 (illustrative masses; its crank
    turns at 30 rad/s clockwise, ``[motion]``) over one turn in steps of 5°, with the
    flywheel for δ = 0.05 of its ``[dynamics]`` (without its balancing, which takes
    longer):

    >>> import dataclasses
    >>> import numpy as np
    >>> from assur import examples, io
    >>> from assur.analysis import add_dynamics
    >>> model = io.load(io.bundled("cleaning_lab3"))
    >>> a = model.mechanism.analyze(np.radians(np.arange(0.0, 361.0, 5.0)))   # φ1 [rad]
    >>> spec = dataclasses.replace(model.dynamics, counter_masses=())
    >>> a = add_dynamics(a, spec)
    >>> round(float(a.dynamics.kinetic_energy.max()), 1)     # T = ½·J_red·ω² [J]
    355.5
    >>> round(a.flywheel.J_flywheel, 2)                      # J_f [kg·m²]
    7.56

    The hitch has no crank: it is left as it is, unless a spec asks for a flywheel:

    >>> h = examples.hitch_003().analyze([0.42])
    >>> add_dynamics(h).dynamics is None
    True
    >>> add_dynamics(h, spec)   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: hitch_003: [dynamics] needs one crank-angle coordinate and ...
    """
    from .errors import ModelError
    from .dynamics.crank import crank_dynamics, masses_of

    kin = analysis.kinematics
    mech = kin.mechanism
    asks = spec is not None and (spec.delta is not None or spec.flywheel is not None
                                 or bool(spec.counter_masses))
    crank = kin.k == 1 and mech.coordinate_kind(kin.coordinates[0]) == "angle"
    if not crank or not masses_of(mech):
        if asks:
            raise ModelError(f"{mech.name}: [dynamics] needs one crank-angle coordinate and "
                             f"masses on the moving links ([[loads]] type = \"mass\")")
        return analysis
    c = kin.coordinates[0]
    motion = mech.motion(c)
    if motion is None or not motion.has_speed:
        if asks:
            raise ModelError(f"{mech.name}: [dynamics] needs the speed of the crank {c}: "
                             f"add [motion] {c} = {{ direction = \"cw\", speed = \"300 rpm\" }}")
        analysis.notes.append(Text(
            f"{mech.name}: the links have masses but the crank {c} has no speed ([motion]): "
            f"inertia loads, reduced moment and flywheel are not computed",
            ru=f"{mech.name}: у звеньев есть массы, но скорость кривошипа {c} не задана "
               f"([motion]): силы инерции, приведённый момент и маховик не рассчитаны"))
        return analysis
    qdot, qddot = motion.rates(kin.q(c))
    dyn = crank_dynamics(kin, qdot, qddot)
    analysis.dynamics = dyn
    if spec is not None and (spec.delta is not None or spec.flywheel is not None):
        analysis.flywheel = dyn.flywheel(delta=spec.delta, J_flywheel=spec.flywheel)
    if spec is not None and spec.counter_masses:
        from .dynamics.balancing import balance
        analysis.balancing = balance(kin, spec.counter_masses, spec.objective)
    check_finite(analysis)
    return analysis


def add_lift_test(analysis, test, s_range=None):
    """Add the standard lift test of a three-point hitch (ISO 789-2 / SAE J283,
    :func:`assur.machines.hitch_lift.lift_test`) to ``analysis`` (in place; returns it).

    Parameters
    ----------
    analysis : Analysis
        One design of a one-coordinate mechanism.
    test : LiftTest or None
        The model file's ``[lift_test]`` (:attr:`assur.io.Model.lift_test`); None
        leaves the analysis as it is.
    s_range : (float, float), optional
        The cylinder's travel [m]; default: the analysis' positions' extremes.

    Examples
    --------
    The seed-003 hitch with its model file's ``[lift_test]`` (not in the seed: six
    heights, 90 % of the relief pressure):

    >>> from assur import io
    >>> from assur.analysis import add_lift_test
    >>> model = io.load(io.bundled("hitch_003"))
    >>> a = add_lift_test(model.mechanism.analyze([0.42, 0.67]), model.lift_test)
    >>> [round(float(h), 3) for h in a.lift_test.height]   # Y56 [m]
    [0.2, 0.369, 0.537, 0.706, 0.875, 1.043]
    >>> round(a.lift_test.hitch_minimum), round(a.lift_test.frame_minimum)   # [N]
    (29825, 28669)
    """
    if test is None:
        return analysis
    from .machines.hitch_lift import lift_test
    kin = analysis.kinematics
    if s_range is None:
        q = kin.q()
        s_range = (float(q.min()), float(q.max()))
    analysis.lift_test = lift_test(kin.mechanism, test, s_range)
    return analysis
