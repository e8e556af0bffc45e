"""The problem a run integrates: model, parameter vector, torques, state scaling, contact flags.

State scaling. Angles are O(1) and eccentricities O(clearance); the integrators see
eccentricities in units of their joint's radial clearance (rates in clearance per ms), so one
absolute tolerance means the same for both.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import casadi as ca
import numpy as np

from jointplay.common.hints import did_you_mean
from jointplay.scene.definition import Scene, ideal_counterpart
from jointplay.store.model import Model

# The CVODES / IDAS route locates an onset or separation to EVENT_TIME_FRACTION * rtol of
# RATE_SCALE_TIME, or once the penetration is within EVENT_GAP_FRACTION * atol of the
# clearance from zero: both follow the run's tolerances, so tightening rtol / atol converges
# the impact sequence (fixed numbers did not: a 1e-4 c gap at 0.02 m/s is 1.5e-7 s late).
# Tighter fractions (1e-2, 1e-3) changed no error at rtol 1e-6 ... 1e-10 and cost more calls.
EVENT_TIME_FRACTION = 1
EVENT_GAP_FRACTION = 1
# Output intervals integrated per call of the adaptive integrators, at most: a call restarts
# the integrator, and what follows an event in a call is integrated again, so calls start at
# one interval after an event and double while none occurs.
CHUNK_OUTPUTS = 512
# Fixed steps (rk4, radau) evaluated per call into C, at most: Python's Ctrl-C handler runs
# between calls, so this bounds how long an interrupt waits.
FIXED_BLOCK_STEPS = 1000
# More transitions than this inside one output interval means contact chatter.
MAX_EVENTS_PER_OUTPUT = 2000
# Eccentricity rates are scaled by clearance / this time (s).
RATE_SCALE_TIME = 1e-3
# Radau's simplified Newton must have settled to this (scaled units) for a step to count.
RADAU_NEWTON_TOLERANCE = 1e-6



@dataclass
class _Accumulated:
    """Solver statistics summed over every integrator call of a run."""

    counts: dict[str, int] = field(default_factory=lambda: {
        "steps": 0, "rhs_evaluations": 0, "jacobian_evaluations": 0, "error_test_failures": 0,
        "integrator_calls": 0, "events": 0, "impacts": 0})

    def add(self, stats: Mapping[str, Any]) -> None:
        c = self.counts
        c["integrator_calls"] += 1
        c["steps"] += int(stats.get("nsteps", 0))
        c["rhs_evaluations"] += int(stats.get("nfevals", 0))
        c["jacobian_evaluations"] += int(stats.get("n_call_jacF", 0))
        c["error_test_failures"] += int(stats.get("netfails", 0))


def _scaling(model: Model, p: np.ndarray) -> np.ndarray:
    """Per-state scale: 1 for angles, the joint's radial clearance for eccentricities."""
    scale = np.ones(model.n_state)
    n = model.n_coordinates
    layout = model.layout
    for i, coordinate in enumerate(layout.coordinates):
        if coordinate.kind != "angle":
            rb = p[layout.parameter_slot("joint", coordinate.joint, "bearing_radius")]
            rj = p[layout.parameter_slot("joint", coordinate.joint, "journal_radius")]
            scale[i] = rb - rj
            scale[n + i] = (rb - rj) / RATE_SCALE_TIME
    return scale


class _Problem:
    """The compiled model, a parameter vector and torque functions, ready to integrate."""

    def __init__(self, model: Model, scene: Scene, p: np.ndarray) -> None:
        self.model = model
        self.scene = scene
        self.p = p
        self.n = model.n_coordinates
        self.nx = model.n_state
        self.nc = len(model.clearance_joints)
        self.scale = _scaling(model, p)
        self.torques = scene.torques
        # Torques added to the scene's and held over an integration (closed-loop control).
        self.u_hold = np.zeros(len(model.torque_joints))
        self.angle_index = [model.coordinates.index(f"q{j}") for j in model.torque_joints]
        if "contact.impact_speed_floor" in model.parameters:
            self.speed_floor = float(p[model.parameters.index("contact.impact_speed_floor")])
        else:
            self.speed_floor = 0.0
        self._contact = model.function("contact") if self.nc else None
        # An onset or separation is located once the gap is within this of zero (m).
        clearances = [self.scale[model.coordinates.index(f"ex{j}")]
                      for j in model.clearance_joints]
        run = scene.run
        self.gap_tolerance = EVENT_GAP_FRACTION * run.atol * np.asarray(clearances, dtype=float)
        self.event_time_tolerance = EVENT_TIME_FRACTION * run.rtol * RATE_SCALE_TIME

    def tau(self, t: np.ndarray | float) -> np.ndarray:
        """Drive torques at times t: shape (len(t), ntau)."""
        t_arr = np.atleast_1d(np.asarray(t, dtype=float))
        cols = [np.broadcast_to(np.asarray(f.numpy(t_arr), dtype=float), t_arr.shape)
                for f in self.torques]
        out = np.stack(cols, axis=1) if cols else np.zeros((t_arr.size, 0))
        return out + self.u_hold

    def tau_casadi(self, t: Any) -> Any:
        return ca.vertcat(*[f.casadi(t) for f in self.torques]) if self.torques \
            else ca.MX(0, 1)

    def contact_at(self, x: np.ndarray, v_imp: np.ndarray) -> dict[str, np.ndarray]:
        assert self._contact is not None
        out = self._contact(x, self.p, v_imp)
        return dict(zip(self._contact.function.name_out(), out, strict=True))



def _nearest_contact_joint(pr: _Problem, x: np.ndarray, v_imp: np.ndarray) -> int | None:
    if not pr.nc or not np.all(np.isfinite(x)):
        return None
    delta = pr.contact_at(x, v_imp)["delta"]
    return int(pr.model.clearance_joints[int(np.argmax(delta))])



@dataclass
class _Trajectory:
    """Outputs filled in sample by sample."""

    x: np.ndarray
    v_imp: np.ndarray
    work: np.ndarray
    dissipated: np.ndarray
    impacts: list[tuple[float, int, float, float, float]] = field(default_factory=list)
    wear: Any = None  # jointplay.results.wear.WearProfile, from a method that integrates it


def _initial_state(model: Model, scene: Scene) -> np.ndarray:
    x0 = np.zeros(model.n_state)
    n = model.n_coordinates
    for key, value in scene.initial.items():
        if key.startswith("d") and key[1:] in model.coordinates:
            x0[n + model.coordinates.index(key[1:])] = value
        elif key in model.coordinates:
            x0[model.coordinates.index(key)] = value
    return x0



def _parameter_vector(model: Model, scene: Scene,
                      parameters: Mapping[str, float] | Sequence[float] | None) -> np.ndarray:
    defaults = np.asarray(scene.robot.parameter_values(), dtype=float)
    if parameters is None:
        return defaults
    if isinstance(parameters, Mapping):
        vec = defaults.copy()
        for name, value in parameters.items():
            if name not in model.parameters:

                hint = did_you_mean(name, model.parameters)
                raise KeyError(f"{name!r} is not a parameter of this model{hint}")
            vec[model.parameters.index(name)] = float(value)
        return vec
    return model.parameter_vector(parameters)


def load_scene_model(scene: Scene, *, ideal: bool = False) -> Model:
    """The compiled model of the scene's robot (or of its ideal-joint counterpart).

    A model already generated (checked in, or in the cache) is loaded without sympy; a new
    structure is derived once.
    """
    from jointplay.store.lookup import model_for

    robot = ideal_counterpart(scene.robot) if ideal else scene.robot
    return model_for(robot)


