"""The plant identification sees: the clearance robot under a fixed inner loop (a PD on the
moving joints around the ideal robot's motion, the scene's torques as feedforward). Its input
is the torque added to the PD's; its outputs are the deviations from the ideal robot of the
moving joints' angles and speeds and of the end effector's position, velocity and
acceleration."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.scene.expressions import TimeFunction

# Inner-loop defaults. The derivative gain is bounded by the journal: out of contact a link
# turns about its own centre of mass (link 2's inertia about it is 1/90 of the pinned arm's
# about joint 2), and a sampled derivative gain from about 20 N m s/rad on joint 2 makes the
# loop ring and the journals chatter (655 impacts at 37, 27 at 5; docs/control.md).
DEFAULT_KP = 200.0  # N m/rad
DEFAULT_KD = 5.0  # N m s/rad
# Torque limit of each actuator, as a multiple of the scene's peak torque on that joint.
LIMIT_FACTOR = 2.5


@dataclass(frozen=True)
class InnerLoop:
    """PD on the moving joints around the reference motion: tau = -kp dq_err - kd d(dq)."""

    joints: tuple[int, ...]
    kp: tuple[float, ...]
    kd: tuple[float, ...]

    def torque(self, deviation: np.ndarray) -> np.ndarray:
        n = len(self.joints)
        return -np.asarray(self.kp) * deviation[:n] - np.asarray(self.kd) * deviation[n:2 * n]


def output_names(joints: Sequence[int], contact: Sequence[int] = ()
                 ) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """Names and units of the plant's outputs (deviations from the ideal robot).

    ``contact``: clearance joints whose journal eccentricity (ex, ey: the journal centre's
    offset from the bearing's, in the bearing's frame) is measured as well, a bearing
    displacement sensor's signals. They come after the others, so that every other output
    keeps its place; the ideal robot's are 0, so their deviation is the eccentricity. Their
    rates are left out: a journal's velocity jumps at every impact (one step ahead, a piloted
    model with them predicted them worse than persistence); the lags carry the motion.
    """
    names = [f"q{j}" for j in joints] + [f"dq{j}" for j in joints] + \
        ["tip_x", "tip_y", "tip_vx", "tip_vy", "tip_ax", "tip_ay"]
    units = ["rad"] * len(joints) + ["rad/s"] * len(joints) + \
        ["m", "m", "m/s", "m/s", "m/s^2", "m/s^2"]
    names += [f"{a}{j}" for j in contact for a in ("ex", "ey")]
    units += ["m"] * (2 * len(contact))
    return tuple(names), tuple(units)


def contact_joints(names: Sequence[str]) -> tuple[int, ...]:
    """The joints whose journal eccentricity is among the outputs ``names``."""
    return tuple(int(n[2:]) for n in names if n.startswith("ex"))


def contact_index(model: Any, contact: Sequence[int]) -> list[int]:
    """The eccentricity coordinates of ``contact`` in a clearance model's state, in the
    outputs' order; a joint without play in ``model`` is refused by name."""
    missing = [j for j in contact if f"ex{j}" not in model.coordinates]
    if missing:
        raise DescriptionError("--model", f"the model measures the journal eccentricity of "
                               f"joint(s) {missing}, which have no clearance in this robot: "
                               "identify the model on this robot")
    return [model.coordinates.index(f"{a}{j}") for j in contact for a in ("ex", "ey")]


def output_increments(names: Sequence[str]) -> tuple[bool, ...]:
    """Angles, speeds, positions and velocities integrate the input: predicted as increments.
    Accelerations follow the torque directly: predicted as values."""
    return tuple(not n.startswith("tip_a") for n in names)


def input_names(joints: Sequence[int]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    return tuple(f"v{j}" for j in joints), tuple("N m" for _ in joints)


def measure(stepper: Any, angle_index: Sequence[int],
            eccentricity_index: Sequence[int] = ()) -> np.ndarray:
    """The plant's outputs (absolute) at the stepper's current sample; with
    ``eccentricity_index`` (:func:`contact_index`) the journals' eccentricities after the
    others."""
    x = stepper.x
    n = stepper.model.n_coordinates
    ee = stepper.end_effector()
    e = list(eccentricity_index)
    return np.concatenate([x[list(angle_index)], x[[n + i for i in angle_index]],
                           ee["position"], ee["velocity"], ee["acceleration"], x[e]])


def reference_outputs(ideal: Any, contact: Sequence[int] = ()) -> np.ndarray:
    """The same outputs for a simulated ideal-joint robot (rows: samples); its journals sit
    at their bearings' centres, so the eccentricity outputs of ``contact`` are 0."""
    return np.hstack([ideal.q, ideal.u, ideal.tip_position, ideal.tip_velocity,
                      ideal.tip_acceleration, np.zeros((ideal.q.shape[0], 2 * len(contact)))])


def default_limits(scene: Any) -> np.ndarray:
    """Actuator torque limits: LIMIT_FACTOR x the scene's peak torque on each joint."""
    t = np.linspace(0.0, scene.run.t_end, scene.run.n_outputs + 1)
    peaks = np.array([float(np.max(np.abs(f.numpy(t)))) for f in scene.torques])
    if peaks.size == 0 or not np.all(peaks > 0):
        raise DescriptionError("--torque-limit", "the scene has no torque on some driven joint, "
                               "so no default actuator limit can be inferred; give one per "
                               "driven joint, e.g. --torque-limit 10,5 (N m)")
    return LIMIT_FACTOR * peaks


def with_torques(scene: Any, torques: Sequence[TimeFunction]) -> Any:
    """The scene with other drive torques (and texts saying where they came from)."""
    return replace(scene, torques=tuple(torques),
                   torque_text={f"joint{j}": "excitation" for j in scene.robot.moving_joints})



def inner_loop_for(scene: Any, kp: Sequence[float], kd: Sequence[float]) -> InnerLoop:
    """The inner loop on the scene's moving joints; empty gains take the defaults."""
    joints = tuple(scene.robot.moving_joints)
    n = len(joints)
    return InnerLoop(joints, tuple(kp) or (DEFAULT_KP,) * n, tuple(kd) or (DEFAULT_KD,) * n)


def ideal_reference(scene: Any, ideal_model: Any | None = None) -> Any:
    """The ideal-joint robot under the scene's torques: the motion the controller tracks."""
    from jointplay.scene.definition import ideal_counterpart
    from jointplay.sim import load_scene_model, simulate

    model = ideal_model or load_scene_model(scene, ideal=True)
    return simulate(scene.with_robot(ideal_counterpart(scene.robot)), model=model)


__all__ = ["DEFAULT_KD", "DEFAULT_KP", "LIMIT_FACTOR", "InnerLoop", "contact_index",
           "contact_joints", "default_limits", "ideal_reference", "inner_loop_for",
           "input_names", "measure", "output_increments", "output_names", "reference_outputs",
           "with_torques"]
