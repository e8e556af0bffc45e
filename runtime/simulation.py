"""Deprecated alias: the simulator is the package :mod:`jointplay.sim`."""

from jointplay.sim import Stepper, load_scene_model, simulate
from jointplay.sim.problem import RATE_SCALE_TIME

__all__ = ["RATE_SCALE_TIME", "Stepper", "load_scene_model", "simulate"]
