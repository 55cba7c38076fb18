"""Dynamics of mechanisms in time: equations of motion from the exact analogs
(:mod:`assur.dynamics.eom`) and their simulation coupled with a hydraulic drive
(:mod:`assur.dynamics.simulate`, components in :mod:`assur.dynamics.drive`)."""

from .eom import EquationsOfMotion, equations_of_motion
from .simulate import SimulationResult, simulate, simulate_model

__all__ = ["EquationsOfMotion", "equations_of_motion", "SimulationResult", "simulate",
           "simulate_model"]
