"""The identification data: every trajectory's excitation planned from one seeded generator
per trajectory, then simulated (in worker processes where there are cores).

Each trajectory drives the ideal robot with a base torque (the scene's own, random-phase
multisines, amplitude-modulated steps) to get a reference motion, and the clearance robot,
under the inner loop around that reference, with an added torque v of amplitude-modulated
pseudo-random steps (holds from one sample up, so the response within one sample is
identifiable) plus a random-phase multisine. Training, validation and test trajectories are
separate realisations; the test base torques include a family never used in training (a
swept sine)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.pool import parallel_map
from jointplay.neural.identify.config import IdentifyConfig
from jointplay.neural.identify.excitation import (
    Chirp,
    Retimed,
    aprbs,
    describe_torque,
    random_multisine,
    step_torque,
)
from jointplay.neural.model.inner_loop import (
    InnerLoop,
    contact_index,
    ideal_reference,
    measure,
    reference_outputs,
    with_torques,
)
from jointplay.scene.expressions import TimeFunction

SPLITS = ("train", "validation", "test")
TRAIN_FAMILIES = ("scene", "multisine", "steps")
SCENE_TRAIN_FAMILIES = ("scene", "scene-family", "scene-family")  # base_motions "scene-family"
# The scene's family: its drive torques times a scale, at a rate and shifted in time, each
# drawn uniformly (training runs with base_motions "scene-family", and the closed-loop
# choice's motions: jointplay.neural.study.closed_loop_choice.scene_family_motions).
SCENE_FAMILY_SCALE = (0.75, 1.25)  # x the scene's torques
SCENE_FAMILY_RATE = (0.75, 1.33)  # x the scene's time
SCENE_FAMILY_SHIFT = 0.25  # the largest time shift, x the run's duration
TEST_FAMILIES = ("chirp", "multisine", "steps")
ARRAYS = ("t", "y", "r", "v", "tau_base", "tau_inner")  # a trajectory's sampled signals


@dataclass
class Trajectory:
    """One identification run, sampled every ``dt``: absolute outputs ``y``, the reference's
    ``r``, the added torque ``v`` (applied from each sample to the next), the base torque
    (feedforward) and the inner loop's torque."""

    split: str
    family: str
    seed: int
    t: np.ndarray
    y: np.ndarray
    r: np.ndarray
    v: np.ndarray
    tau_base: np.ndarray
    tau_inner: np.ndarray
    description: dict[str, Any] = field(default_factory=dict)

    @property
    def deviation(self) -> np.ndarray:
        return self.y - self.r


@dataclass
class _Task:
    split: str
    family: str
    seed: int
    scene: Any
    v: np.ndarray
    inner: InnerLoop
    description: dict[str, Any]
    contact: tuple[int, ...] = ()  # joints whose journal eccentricity is measured


# ---- planning -----------------------------------------------------------------------------

def robot_variants(scene: Any, config: IdentifyConfig) -> list[tuple[dict[str, float], Any]]:
    """The robots the training and validation runs span (``config.clearances`` x
    ``config.payloads``), each with what was changed; the scene's own robot alone when
    neither is given."""
    from jointplay.robot import with_parameters

    robot = scene.robot
    clearances = config.clearances or (None,)
    payloads = config.payloads or (None,)
    out = []
    for payload in payloads:
        for clearance in clearances:
            values: dict[str, float] = {}
            changed: dict[str, float] = {}
            if clearance is not None:
                changed["clearance"] = float(clearance)
                for j in robot.clearance_joints:
                    bearing = robot.joints[j - 1].bearing_radius
                    if not clearance < bearing:
                        raise DescriptionError("--clearances", f"{clearance:g} m is not below "
                                               f"joint {j}'s bearing radius {bearing:g} m")
                    values[f"joint{j}.journal_radius"] = bearing - clearance
            if payload is not None:
                changed["payload"] = float(payload)
                values["payload.mass"] = float(payload)
            out.append((changed, scene.with_robot(with_parameters(robot, values)) if values
                        else scene))
    return out


def measured_contact(scene: Any, config: IdentifyConfig) -> tuple[int, ...]:
    """The joints whose journal eccentricity the model measures: every clearance joint of
    the scene's robot with ``config.contact_outputs``, else none."""
    return tuple(scene.robot.clearance_joints) if config.contact_outputs else ()


def _plan(scene: Any, config: IdentifyConfig, inner: InnerLoop,
          limits: np.ndarray) -> list[_Task]:
    """Every trajectory's excitation, drawn from one seeded generator per trajectory; the
    training and validation runs cycle through the robot variants (:func:`robot_variants`)."""
    run_scene = scene.with_run(t_end=config.duration)
    variants = robot_variants(run_scene, config)
    tasks: list[_Task] = []
    counts = {"train": config.n_train, "validation": config.n_validation, "test": config.n_test}
    for s_index, split in enumerate(SPLITS):
        families = (TEST_FAMILIES if split == "test" else
                    SCENE_TRAIN_FAMILIES if config.base_motions == "scene-family"
                    else TRAIN_FAMILIES)
        for i in range(counts[split]):
            seed = int(np.random.SeedSequence([config.seed, s_index, i]).generate_state(1)[0])
            rng = np.random.default_rng(seed)
            family = families[i % len(families)]
            base = _base_torques(rng, family, split, scene, config, inner, limits)
            v = _added_torque(rng, run_scene.run.n_outputs, scene.run.output_step, config,
                              limits)
            description = {"base": [describe_torque(f) for f in base],
                           "added": "aprbs(1..100 samples) + multisine(0.1..10 Hz)",
                           "added_peak": (config.input_fraction * limits).tolist()}
            robot_scene = run_scene
            if split != "test" and (config.clearances or config.payloads):
                changed, robot_scene = variants[i % len(variants)]
                description["robot"] = changed
            tasks.append(_Task(split, family, seed, with_torques(robot_scene, base), v, inner,
                               description, measured_contact(scene, config)))
    return tasks


def _base_torques(rng: np.random.Generator, family: str, split: str, scene: Any,
                  config: IdentifyConfig, inner: InnerLoop,
                  limits: np.ndarray) -> list[TimeFunction]:
    """The feedforward of one trajectory: it drives the ideal robot to the reference."""
    if family == "scene":
        return list(scene.torques)
    if family == "scene-family":
        return list(scene_family_torques(rng, scene, config.duration))
    if family == "multisine":
        band = (0.2, 4.0) if split == "test" else (0.2, 3.0)
        return [random_multisine(rng, config.base_fraction * lim, *band, config.duration)
                for lim in limits]
    if family == "steps":
        return [step_torque(rng, config.base_fraction * lim, config.duration, 0.1, 0.4, 0.01,
                            f"joint{j}") for lim, j in zip(limits, inner.joints, strict=True)]
    return [Chirp(0.6 * config.base_fraction * lim, 0.2, 3.0, config.duration,
                  float(rng.uniform(0, 2 * np.pi))) for lim in limits]


def scene_family_torques(rng: np.random.Generator, scene: Any,
                         duration: float) -> list[Retimed]:
    """The scene's drive torques, every joint alike, times a scale, at a rate and shifted in
    time, each drawn uniformly from the ranges of the scene's family (SCENE_FAMILY_SCALE,
    _RATE, _SHIFT): a motion of the size and shape the controller is judged on."""
    scale = float(rng.uniform(*SCENE_FAMILY_SCALE))
    rate = float(rng.uniform(*SCENE_FAMILY_RATE))
    shift = float(rng.uniform(0.0, SCENE_FAMILY_SHIFT * duration))
    return [Retimed(f, scale, rate, shift) for f in scene.torques]


def _added_torque(rng: np.random.Generator, n: int, dt: float, config: IdentifyConfig,
                  limits: np.ndarray) -> np.ndarray:
    """The identified input v, per sample: pseudo-random steps plus a multisine."""
    v = np.zeros((n + 1, len(limits)))
    for c, lim in enumerate(limits):
        peak = config.input_fraction * lim
        v[:n, c] = aprbs(rng, n, 0.6 * peak, 1, 100)
        v[:n, c] += random_multisine(rng, 0.4 * peak, 0.1, 10.0,
                                     config.duration).numpy(np.arange(n) * dt)
    return v


# ---- simulating ---------------------------------------------------------------------------

_MODELS: dict[str, Any] = {}


def _models(scene: Any) -> tuple[Any, Any]:
    from jointplay.sim import load_scene_model

    key = scene.robot.structure_hash()
    if key not in _MODELS:
        _MODELS[key] = (load_scene_model(scene), load_scene_model(scene, ideal=True))
    return _MODELS[key]


def run_task(task: _Task) -> Trajectory:
    """Simulate one identification trajectory (a worker's job)."""
    from jointplay.sim import Stepper

    clearance, ideal_model = _models(task.scene)
    ideal = ideal_reference(task.scene, ideal_model)
    r = reference_outputs(ideal, task.contact)
    stepper = Stepper(task.scene, model=clearance)
    angle_index = [clearance.coordinates.index(f"q{j}") for j in task.inner.joints]
    eccentricity = contact_index(clearance, task.contact)
    n = task.scene.run.n_outputs
    y = np.zeros_like(r)
    tau_inner = np.zeros((n + 1, len(task.inner.joints)))
    for k in range(n + 1):
        y[k] = measure(stepper, angle_index, eccentricity)
        if k == n:
            break
        tau_inner[k] = task.inner.torque(y[k] - r[k])
        stepper.step(tau_inner[k] + task.v[k])
    return Trajectory(task.split, task.family, task.seed, ideal.t, y, r, task.v.copy(),
                      ideal.tau.copy(), tau_inner, task.description)


def collect(scene: Any, config: IdentifyConfig, inner: InnerLoop, limits: np.ndarray,
            quiet: bool = False) -> list[Trajectory]:
    """Simulate every planned trajectory, in parallel processes when there are cores."""
    from tqdm import tqdm

    tasks = _plan(scene, config, inner, limits)
    workers = config.workers or min(4, os.cpu_count() or 1)
    workers = max(1, min(workers, len(tasks)))
    _models(scene)  # compile (or load) once before any worker starts
    with tqdm(total=len(tasks), disable=quiet, unit="traj", desc="simulating") as bar:
        # forked workers inherit the loaded models; they use numpy and CasADi only
        return parallel_map(lambda i: run_task(tasks[i]), len(tasks), workers,
                            label="identification", on_result=lambda _: bar.update(1))


def check_finite(trajectories: Sequence[Trajectory]) -> None:
    """Refuse training data with NaN or Inf, naming the run, the sample and the column."""
    for k, traj in enumerate(trajectories):
        for name in ARRAYS:
            values = np.asarray(getattr(traj, name), dtype=float)
            bad = np.argwhere(~np.isfinite(values))
            if bad.size:
                where = ", column ".join(str(int(i)) for i in bad[0])
                raise DescriptionError(
                    "training data", f"run {k} ({traj.split}, {traj.family}) has a non-finite "
                    f"{name} at sample {where}: identification needs finite data; check the "
                    "scene's torques and limits")


__all__ = ["ARRAYS", "SCENE_FAMILY_RATE", "SCENE_FAMILY_SCALE", "SCENE_FAMILY_SHIFT",
           "SCENE_TRAIN_FAMILIES", "SPLITS", "TEST_FAMILIES", "TRAIN_FAMILIES", "Trajectory",
           "check_finite", "collect", "run_task", "scene_family_torques"]
