"""Typed exceptions of assur.

Every exception subclasses a built-in so that ``except ValueError`` keeps working,
and every message names what failed (group, links, values, position) so an
engineer can act on it without a debugger.
"""

from __future__ import annotations

__all__ = ["ModelError", "AssemblyError", "SingularPositionError", "ModelWarning"]


class ModelError(ValueError):
    """A mechanism description is inconsistent (unknown point, duplicate name, bad value)."""


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
        #: per-element failure description (see :class:`assur.kinematics.Failures`)
        self.failures = failures


class SingularPositionError(ValueError):
    """A requested ratio or analog is singular (division by a zero analog) at some position."""


class ModelWarning(UserWarning):
    """Something in a model that is allowed but probably not meant (a parameter that
    nothing uses — a misspelt key?); the message names the file, line and key."""
