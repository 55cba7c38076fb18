"""The lumped oil volume at the cylinder (seed 001 lab 6, node Y2 of fig. 6.2)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ...texts import Text
from .base import positive, register

__all__ = ["OilVolume", "BULK_MODULUS"]

#: effective bulk modulus of the oil with undissolved air (up to 6 %) and the
#: compliance of hoses, adiabatic, 1–20 MPa (lab 6, "to 1 %") [Pa]
BULK_MODULUS = 2.0e8


@register
@dataclass(frozen=True)
class OilVolume:
    """All the oil of the pressure line lumped at the cylinder, compressible.

    Lab 6 eqs. (1)–(2): the pump's flow moves the piston and compresses the oil,

    ``Q = A·Ṡ + ṗ1·V(S)/E_pr``,  ``V(S) = V0 + A·(S − S0)``,

    V0 the volume at the start of the stroke S0 [m³], A the pistons' area, E_pr
    the effective bulk modulus [Pa] (lab 6: 2.0e8 Pa, taken constant).

    Parameters
    ----------
    volume : float
        V0 [m³]: lines, valve and the cylinder's dead volume at S0.
    bulk_modulus : float
        E_pr [Pa] (default :data:`BULK_MODULUS`).
    coordinate : str, optional
        The generalized coordinate of the cylinder whose branch this oil volume is in
        (needed when the circuit drives more than one coordinate).
    name : str, optional

    Examples
    --------
    >>> from assur.dynamics.drive import OilVolume
    >>> oil = OilVolume(volume=3e-3)            # lab 6: 3 l [m³]
    >>> oil.bulk_modulus / 1e6                  # E_pr [MPa], lab 6's 2.0e8 Pa
    200.0
    >>> q = 8.64e-4                     # the pump's flow [m³/s], the piston held at S0
    >>> round(oil.bulk_modulus * q / oil.volume_at(0.0123, 0.0) / 1e6, 1)   # ṗ1 [MPa/s], eq. (2)
    57.6
    """

    volume: float
    bulk_modulus: float = BULK_MODULUS
    coordinate: str | None = None
    name: str | None = None

    type_name: ClassVar[str] = "oil_volume"
    title: ClassVar[Text] = Text("oil volume", ru="объём жидкости")
    role: ClassVar[str] = "volume"
    quantities: ClassVar = {"volume": "volume", "bulk_modulus": "pressure"}
    #: the oil's bulk modulus: 1 MPa (foam) … 100 GPa (beyond steel)
    spans: ClassVar = {"bulk_modulus": (1e6, 1e11)}

    def __post_init__(self):
        positive(self, "volume", "bulk_modulus")

    def volume_at(self, area, stroke):
        """V = V0 + A·(S − S0) [m³] for the pistons' area ``area`` [m²] and the stroke
        from the start ``stroke`` = S − S0 [m].

        Examples
        --------
        >>> import math
        >>> from assur.dynamics.drive import OilVolume
        >>> oil = OilVolume(volume=3e-3)                   # V0 [m³]
        >>> area = math.pi * 0.125 ** 2 / 4                # piston [m²]
        >>> round(oil.volume_at(area, 0.25) * 1e3, 3)      # [l] after a 250 mm stroke
        6.068
        """
        return self.volume + area * stroke
