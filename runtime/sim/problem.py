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

from jointplay.common.errors import DescriptionError
from jointplay.common.validation import Problems
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
        c["lu_decompositions"] = c.get("lu_decompositions", 0) + int(stats.get("nlinsetups", 0))


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

    # The method a fixed-step run that fails is told to use instead.
    adaptive_fallback = "cvodes"

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
        # Forward sensitivities to integrate beside the state (bdf only), or None.
        self.sensitivity: Any = None
        # Whether the compiled loop locates each contact phase's peak normal force.
        self.peaks = True
        # The Newton matrix of the compiled loop's steps ("auto", "full", "reduced").
        self.newton = "auto"

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

    def eccentricity_at(self, x: np.ndarray, i: int) -> tuple[float, float]:
        """Clearance joint i's (index into the clearance joints) eccentricity at state x."""
        joint = int(self.model.clearance_joints[i])
        ex, ey = (float(x[self.model.coordinates.index(f"{axis}{joint}")])
                  for axis in ("ex", "ey"))
        return ex, ey

    def drive_power_casadi(self, x: Any, tau: Any, p: Any, v_imp: Any) -> Any:
        """The drives' power at state x with torques tau (W), in a CasADi graph."""
        return sum((tau[kk] * x[self.n + ii] for kk, ii in enumerate(self.angle_index)),
                   ca.MX(0))

    def drive_power_at(self, x: np.ndarray, tau: np.ndarray, v_imp: np.ndarray) -> float:
        """The drives' power at state x with torques tau (W)."""
        return float(sum(tau[kk] * x[self.n + ii] for kk, ii in enumerate(self.angle_index)))



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
    # With sensitivities: d x / d p at the samples (n_t, nx, ns) and the phases' records
    sensitivity: Any = None
    phase_sensitivity: Any = None


def _initial_state(model: Model, scene: Scene, p: np.ndarray | None = None) -> np.ndarray:
    x0 = np.zeros(model.n_state)
    n = model.n_coordinates
    for key, value in scene.initial.items():
        if key.startswith("d") and key[1:] in model.coordinates:
            x0[n + model.coordinates.index(key[1:])] = value
        elif key in model.coordinates:
            x0[model.coordinates.index(key)] = value
    if getattr(scene, "journals", "centred") == "resting" and model.clearance_joints:
        from jointplay.sim.equilibrium import static_equilibrium

        params = p if p is not None else _parameter_vector(model, scene, None)
        slot = model.layout.parameter_slot
        clearances = {j: float(params[slot("joint", j, "bearing_radius")]
                               - params[slot("joint", j, "journal_radius")])
                      for j in model.clearance_joints}
        x0, _ = static_equilibrium(model, params, x0, clearances)
    return x0



def _parameter_vector(model: Model, scene: Scene,
                      parameters: Mapping[str, float] | Sequence[float] | None) -> np.ndarray:
    """The run's parameter vector: the scene robot's numbers, with ``parameters`` (by name, or
    a whole vector) checked exactly as the same numbers in a robot file would be (finite, in
    their physical range, a clearance left, ...), all problems named at once."""
    defaults = np.asarray(scene.robot.parameter_values(), dtype=float)
    if parameters is None:
        return defaults
    if isinstance(parameters, Mapping):
        from jointplay.robot.description import CLEARANCE_ALIAS, resolve_aliases

        aliases = {str(k): v for k, v in parameters.items() if CLEARANCE_ALIAS.fullmatch(str(k))}
        try:
            parameters = resolve_aliases(scene.robot, parameters)
        except DescriptionError as err:
            raise err.with_source("parameters") from None
        # the journal radii the aliases set are checked under the aliases' names
        derived = {f"joint{CLEARANCE_ALIAS.fullmatch(k).group(1)}.journal_radius"  # type: ignore[union-attr]
                   for k in aliases}
        problems = Problems()
        vec = defaults.copy()
        values: dict[str, float] = {}
        for name, value in parameters.items():
            with problems.check():
                if name not in model.parameters:
                    from jointplay.robot.description import unknown_parameter

                    raise unknown_parameter(str(name), scene.robot)
                values[name] = vec[model.parameters.index(name)] = _as_number(value, name)
        with problems.check():
            check_parameters(scene, {**{k: v for k, v in values.items() if k not in derived},
                                     **aliases})
        problems.raise_any("parameters")
        check_law_ranges(model, vec)
        return vec
    vec = _whole_vector(model, parameters)
    check_parameters(scene, dict(zip(model.parameters, vec.tolist(), strict=True)))
    check_law_ranges(model, vec)
    return vec


def _whole_vector(model: Model, parameters: Any) -> np.ndarray:
    """A whole parameter vector given as a sequence: one finite number per parameter."""
    try:
        vec = np.asarray(parameters, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise DescriptionError("parameters", "must be a mapping of parameter names to numbers "
                               "or a sequence of numbers, one per parameter") from None
    if vec.ndim != 1 or vec.size != len(model.parameters):
        first = ", ".join(model.parameters[:3])
        raise DescriptionError("parameters", f"has {vec.size} numbers; the model has "
                               f"{len(model.parameters)} parameters ({first}, ...: "
                               "model.parameters): give one per parameter, or a mapping of "
                               "names to numbers")
    bad = ~np.isfinite(vec)
    if bad.any():
        name = model.parameters[int(np.argmax(bad))]
        raise DescriptionError(f"parameters[{int(np.argmax(bad))}]", f"({name}) must be a "
                               f"finite number, got {vec[bad][0]}")
    return vec


def _as_number(value: Any, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise DescriptionError(name, f"must be a number, got {value!r}")
    try:
        return float(value)
    except OverflowError:  # an integer beyond float64 (10**400)
        raise DescriptionError(name, f"must be a finite number, got an integer of "
                               f"{len(str(abs(int(value))))} digits") from None


def check_parameters(scene: Scene, values: Mapping[str, float]) -> None:
    """Refuse overrides the scene's robot would refuse in its file, naming each by its
    parameter name (``link1.length``); the eccentricities of ``[initial]`` must still start
    inside the bearing the new radii make."""
    from jointplay.robot import with_parameters
    from jointplay.robot.description import clearance_aliases, parameter_name

    known = {p.name for p in scene.robot.parameters()} | set(clearance_aliases(scene.robot))
    robot_values = {k: float(v) for k, v in values.items() if k in known}
    try:
        robot = with_parameters(scene.robot, robot_values)
        scene.with_robot(robot)  # the initial state, checked against the new radii
    except DescriptionError as err:
        raise err.renamed(parameter_name).with_source("parameters") from None


def check_law_ranges(model: Model, p: np.ndarray) -> None:
    """Parameters given at run time (``simulate(scene, parameters=...)``, sweeps, a whole
    vector) must stay inside the range of the compiled contact law, as the scene's own are
    when it is read: Pereira's law was fitted for PEREIRA_CLEARANCE_RANGE only (below it its
    stiffness runs away, and a 1 um clearance gave NaN states)."""
    from jointplay.common.errors import DescriptionError
    from jointplay.robot.description import PEREIRA_CLEARANCE_RANGE

    if model.structure.contact_stiffness != "pereira":
        return
    low, high = PEREIRA_CLEARANCE_RANGE
    layout = model.layout
    for j in model.clearance_joints:
        rb = float(p[layout.parameter_slot("joint", j, "bearing_radius")])
        rj = float(p[layout.parameter_slot("joint", j, "journal_radius")])
        c = rb - rj
        if not low <= c < high:
            raise DescriptionError(
                f"parameters: joint{j}.bearing_radius - joint{j}.journal_radius",
                f"gives a radial clearance of {c:.6g} m, outside the range the Pereira "
                f"contact law was fitted for ({low:g} m <= c < {high:g} m); choose radii in "
                "that range or another contact.stiffness (johnson, liu)")


def load_scene_model(scene: Scene, *, ideal: bool = False) -> Model:
    """The compiled model of the scene's robot (or of its ideal-joint counterpart).

    A model already generated (checked in, or in the cache) is loaded without sympy; a new
    structure is derived once.

    Parameters
    ----------
    scene : Scene
        The scene.
    ideal : bool, default False
        The model of :func:`ideal_counterpart` of the scene's robot instead.

    Returns
    -------
    Model
        The loaded model, its default parameters the robot's numbers.
    """
    from jointplay.store.lookup import model_for

    robot = ideal_counterpart(scene.robot) if ideal else scene.robot
    return model_for(robot)


