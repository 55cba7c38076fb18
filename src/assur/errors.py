"""Typed exceptions of assur.

Every exception subclasses a built-in so that ``except ValueError`` keeps working,
and every message names what failed (group, links, values, position) so an
engineer can act on it without a debugger.
"""

from __future__ import annotations

__all__ = ["ModelError", "AssemblyError", "SingularPositionError", "ModelWarning",
           "MissingExtraError"]


class ModelError(ValueError):
    """A mechanism description is inconsistent (unknown point, duplicate name, bad value).

    Examples
    --------
    >>> from assur import Mechanism
    >>> from assur.errors import ModelError
    >>> Mechanism("m", coordinates=("S",)).frame("01", 0.0, 0.0).frame("01", 1.0, 0.0)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'm': point '01' is defined twice (again by frame point '01')
    >>> try:                          # a ModelError is a ValueError
    ...     Mechanism("m", coordinates=())
    ... except ValueError as e:
    ...     print(type(e).__name__, "-", e)
    ModelError - mechanism 'm': at least one generalized coordinate is needed
    """


class AssemblyError(ValueError):
    """A structural group cannot be assembled at some position.

    Attributes
    ----------
    group : str
        Name of the failing structural group.
    links : tuple of str
        Links of the group.
    coordinate : dict
        Generalized coordinate values of the first failing position [m or rad].
    design : int
        Index of the first failing design in a batch (0 for a single design).
    position : int
        Index of the first failing position along the range.
    amount : float
        By how much the violated inequality is violated [m].

    Examples
    --------
    Seed 003's hitch with a brace L4 = 0.95 m too long: the implement's dyad III
    cannot close at the lowest stroke:

    >>> from assur import examples
    >>> from assur.errors import AssemblyError
    >>> try:
    ...     examples.hitch_003(L4=0.95).solve([0.42, 0.67])          # S [m]
    ... except AssemblyError as e:
    ...     err = e
    >>> err.group, err.links, err.position, err.coordinate        # S [m]
    ('III (6,7)', ('6', '7'), 0, {'S': 0.42})
    >>> round(err.amount * 1000, 1)                 # |56–07| − (L6 + L7) [mm]
    50.3
    """

    def __init__(self, message, *, group=None, links=(), coordinate=None, design=0,
                 position=0, amount=None, failures=None):
        super().__init__(message)
        self.group = group
        self.links = tuple(links)
        self.coordinate = dict(coordinate or {})
        self.design = design
        self.position = position
        self.amount = amount
        #: per-element failure description (see :class:`assur.core.kinematics.Failures`)
        self.failures = failures


class SingularPositionError(ValueError):
    """A requested ratio or analog is singular (division by a zero analog) at some position.

    Examples
    --------
    Link 4 of seed 003's hitch stands still at S = 0.44158 m (φ4' = 0, found by
    Newton's method), so the ratio U34 = φ3'/φ4' does not exist there:

    >>> from assur import examples
    >>> from assur.errors import SingularPositionError
    >>> m = examples.hitch_003()
    >>> s0 = 0.44                                                   # S [m]
    >>> for _ in range(6):
    ...     r = m.solve([s0])
    ...     s0 -= float(r.dphi("4")[0] / r.ddphi("4")[0])
    >>> m.solve([0.42, s0]).ratio("3", "4")
    Traceback (most recent call last):
    ...
    assur.errors.SingularPositionError: ratio U34 = φ3'/φ4' is singular at 1 position(s), first at S = 0.44158: the denominator analog is zero there (the link is at rest, e.g. a dead point); use singular='mask' to get a masked array
    """


class ModelWarning(UserWarning):
    """Something in a model that is allowed but probably not meant (a parameter that
    nothing uses — a misspelt key?); the message names the file, line and key.

    Examples
    --------
    >>> import warnings
    >>> from assur.errors import ModelWarning
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     warnings.warn("hitch.toml, line 12: parameter 'L44' is not used", ModelWarning)
    >>> issubclass(ModelWarning, UserWarning), caught[0].category.__name__
    (True, 'ModelWarning')
    """


class MissingExtraError(ImportError):
    """A feature needs packages of an optional extra that are not installed (the page:
    ``assur[page]``; the Pareto search: ``assur[pareto]``; both: ``assur[all]``).

    Attributes
    ----------
    extra : str
        The extra that installs them.
    missing : tuple of str
        The modules not found.

    Examples
    --------
    >>> from assur.errors import MissingExtraError
    >>> e = MissingExtraError("page", ("fastapi", "uvicorn"), "the interactive page")
    >>> print(e)
    the interactive page needs fastapi, uvicorn (not installed): pip install 'assur[page]'
    >>> isinstance(e, ImportError), e.extra
    (True, 'page')
    """

    def __init__(self, extra: str, missing, what: str):
        self.extra, self.missing = extra, tuple(missing)
        super().__init__(f"{what} needs {', '.join(self.missing)} (not installed): "
                         f"pip install 'assur[{extra}]'")
