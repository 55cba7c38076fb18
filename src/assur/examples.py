"""The seed machines as ready models, loaded from the bundled model files.

Each machine is defined once, in ``src/assur/models/*.toml`` (format:
``docs/model-format.md``); the functions here load those files (once per process)
and return their :class:`~assur.Mechanism`, with the seed's point and link
numbering:

* :func:`hitch_003` — mini-tractor mounted-implement hitch (МН of МСХА), seed 003,
  ``hitch_003.toml``: L4, Sp and L7 are solved from the seed's three Find conditions.
* :func:`header_000` — combine header lift, seed 000, ``header_000.toml``: its input
  cannot assemble.
* :func:`header_000_fixed` — the same header with an illustrative L4 = 0.652 m that
  assembles, ``header_000_fixed.toml``.

Each ``*_range()`` gives the seed's positions of the generalized coordinate (the
file's ``[range]``). :func:`assur.io.load` gives the whole :class:`assur.io.Model`
(range, solved conditions, source).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .mechanism import Mechanism

__all__ = ["hitch_003", "hitch_003_range", "header_000", "header_000_fixed", "header_000_range"]

#: seed 003: the exact roots of its three Find blocks (printed rounded to 4 digits:
#: L4 = 0.6613, Sp = 0.4694, L7 = 0.7522; the printed tables used these values).
#: ``hitch_003.toml`` solves them again from the conditions; the roots agree to 1e-9.
HITCH_003_FOUND = {"L4": 0.661283167, "Sp": 0.469356940, "L7": 0.752169525}


@lru_cache(maxsize=None)
def _model(name):
    from . import io  # pydantic and pint are needed only when a file is read
    return io.load(io.bundled(name))


def _mechanism(name, params) -> Mechanism:
    m = _model(name).mechanism
    return m.with_params(**params) if params else m


def hitch_003(**params) -> Mechanism:
    """Mounted-implement hitch of a mini-tractor, seed ``003_b1551261b108abd1.txt``
    (bundled file ``hitch_003.toml``).

    Three structural groups (seed §2): I (2,3) the cylinder–lever group — cylinder
    2 from frame pivot 01 to point 23 of the lever 3 pivoted at 03; the lever's arm
    34 at φBD = 22° from it; II (4,5) the RRR dyad brace 4 – lower link 5 (pivot 05),
    with the suspension axis 56 on link 5 at L56; III (6,7) the RRR dyad implement 6
    – top link 7 (pivot 07). The implement's centre of mass S6 is fixed by its offset
    (X6, Y6) from 56 at the working stroke Sp (seed: φS6 := 2π + atan(Y6/X6) − φ6(Sp)).

    Generalized coordinate ``S``: cylinder pin-to-pin length [m], 0.420…0.670.

    Parameters
    ----------
    **params
        Overrides of any parameter, e.g. ``L4=0.6613`` or arrays for a batch (the
        machine's axles and weights follow ``L``, ``a``, ``b``, ``P_mcxa``, ``P_gr``).

    Notes
    -----
    Seed slips resolved here (BRIEF.md): ``φBD … [м]`` is an angle (22°);
    L4, Sp and L7 are the roots of the seed's Find blocks, solved from the conditions
    Y56(Smin) = 0.2 m, Y56(Sp) = 0.4 m, φ6(Sp) = 90° (they agree with
    :data:`HITCH_003_FOUND` to 1e-9). The seed's check X23s, Y23s uses
    φ12 = φ13 − acos(…), which is not the cylinder's direction; the cylinder angle
    here is the direction 01 → 23 (φ12 = π − φ13 − acos((S² + L13² − L3²)/(2·S·L13)))
    and closes the loop exactly.
    """
    return _mechanism("hitch_003", params)


def hitch_003_range() -> np.ndarray:
    """Seed 003 §1.3: S from Smin = 0.420 to Smax = 0.670 m in Npol = 10 positions [m]."""
    return np.array(_model("hitch_003").range)


def _header(name, params) -> Mechanism:
    params = dict(params)
    # the centre-of-mass offset dXN, dYN is XN − X56_0, YN − Y56_0 (seed 000: X := XN − 0.767)
    p = _model(name).mechanism.params
    if {"XN", "X56_0"} & params.keys() and "dXN" not in params:
        params["dXN"] = params.get("XN", p["XN"]) - params.get("X56_0", p["X56_0"])
    if {"YN", "Y56_0"} & params.keys() and "dYN" not in params:
        params["dYN"] = params.get("YN", p["YN"]) - params.get("Y56_0", p["Y56_0"])
    return _mechanism(name, params)


def header_000(**params) -> Mechanism:
    """Combine header lift, seed ``000_04e80bfff5466283.txt`` (bundled file
    ``header_000.toml``).

    Cylinder from 01 to point 23 of the bell-crank 3 pivoted at 03 (lever L3); the
    bell-crank's second arm L4 ends at 46, its triangle closed by L34
    (DELFI = acos((L3² + L4² − L34²)/(2·L3·L4)), FI4 = FI3 − DELFI); the RRR dyad
    link 6 (46–56) and rocker 5 (05–56) carries the header, centre of mass offset
    (XN − 0.767, YN − 0.355) from 56 at S = 0.650 m (FIS6).

    **The seed's input cannot assemble**: L4 = 0.657 > L3 + L34 = 0.65234 m, so
    DELFI = acos(1.0199) is complex — the source of every ``…i`` in its tables.
    :meth:`~assur.Mechanism.solve` raises :class:`~assur.AssemblyError` saying so.

    Parameters
    ----------
    **params
        Overrides of any parameter; overriding ``XN``, ``YN``, ``X56_0`` or ``Y56_0``
        also updates the offsets ``dXN``, ``dYN`` derived from them.
    """
    return _header("header_000", params)


def header_000_fixed(**params) -> Mechanism:
    """The combine header lift of seed 000 with L4 = 0.652 m instead of the printed
    0.657 m, so that the bell-crank's triangle closes (bundled file
    ``header_000_fixed.toml``). **Illustrative**: 0.652 m is not a seed value; the
    cylinder–lever group (FI3, DFI3) is exactly the seed's.

    Parameters
    ----------
    **params
        Overrides of any parameter (see :func:`header_000`).
    """
    return _header("header_000_fixed", params)


def header_000_range() -> np.ndarray:
    """Seed 000: S_AA from 0.650 to 0.800 m in steps of 0.010 m [m]."""
    return np.array(_model("header_000").range)
