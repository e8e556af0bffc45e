"""The study's cases: a trajectory and what the loop is exposed to (see
jointplay.neural.study.control_study for the list), each turned into a scene."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.neural.control.imc_settings import ControllerSettings
from jointplay.neural.control.loop import LoopConditions

CASES = ("scene", "slow", "fast", "offset", "disturbance", "noise", "delay")
# Measurement noise, standard deviation per output kind: a 21-bit encoder's angle, its
# 1 ms difference for speeds, and comparable figures for the end effector.
# The journals' eccentricities (--contact-outputs): an eddy-current displacement sensor's
# 0.1 µm.
NOISE = {"q": 3e-6, "dq": 4e-3, "tip_x": 1e-6, "tip_y": 1e-6, "tip_vx": 1e-3, "tip_vy": 1e-3,
         "tip_ax": 0.05, "tip_ay": 0.05, "ex": 1e-7, "ey": 1e-7}


@dataclass(frozen=True)
class Case:
    name: str
    clearance: float  # m, radial, of every clearance joint
    torques: tuple[str, ...]  # expressions per driven joint
    conditions: LoopConditions
    contact: tuple[int, ...] = ()  # joints whose journal eccentricity the models measure


def case_list(scene: Any, names: Sequence[str], clearances: Sequence[float],
              nominal: float, contact: Sequence[int] = ()) -> list[Case]:
    """The cases ``names``; ``contact``: the joints whose journal eccentricity the models
    measure (the noise case puts noise on those sensors too)."""
    text = [scene.torque_text.get(f"joint{j}", "0") for j in scene.robot.moving_joints]
    t_end = scene.run.t_end

    def scaled(factor: float, freq: float) -> tuple[str, ...]:
        return tuple(_retime(t, factor, freq) for t in text)
    out = []
    for name in names:
        cond = LoopConditions()
        torques = tuple(text)
        if name == "slow":
            torques = scaled(1.25, 0.5)
        elif name == "fast":
            torques = scaled(0.5, 2.0)
        elif name == "offset":
            torques = tuple(f"{0.15 * p:g} + 0.75*({t}) + {_retime(t, 0.25, 3.0)}"
                            for t, p in zip(text, _peaks(scene), strict=True))
        elif name == "disturbance":
            peaks = _peaks(scene)
            cond = LoopConditions(disturbance=tuple(0.05 * p for p in peaks),
                                  disturbance_time=min(1.0, 0.5 * t_end))
        elif name == "noise":
            cond = LoopConditions(noise=noise_levels(scene, contact), seed=1)
        elif name == "delay":
            cond = LoopConditions(delay=1)
        out.append(Case(name, nominal, torques, cond, tuple(contact)))
    for c in clearances:
        if not math.isclose(c, nominal, rel_tol=1e-9):
            out.append(Case(f"clearance {c * 1e6:g} µm", c, tuple(text), LoopConditions(),
                            tuple(contact)))
    return out


def _retime(text: str, factor: float, freq: float) -> str:
    """The torque expression at another amplitude and (for sin(2*pi*t) forms) frequency."""
    return f"{factor:g}*({text.replace('2*pi*t', f'2*pi*{freq:g}*t')})"


def _peaks(scene: Any) -> list[float]:
    t = np.linspace(0.0, scene.run.t_end, scene.run.n_outputs + 1)
    return [float(np.max(np.abs(f.numpy(t)))) for f in scene.torques]


def noise_levels(scene: Any, contact: Sequence[int] = ()) -> tuple[float, ...]:
    from jointplay.neural.identify.pipeline import output_names

    names, _ = output_names(scene.robot.moving_joints, contact)
    return tuple(NOISE[n.rstrip("0123456789")] for n in names)


def declared(settings: ControllerSettings, scene: Any, case: Case) -> ControllerSettings:
    """The settings a case's internal-model controllers run with: a case with measurement
    noise declares it (as a sensor's data sheet would), unless the settings already declare
    some noise."""
    if not case.conditions.noise or settings.measurement_noise:
        return settings
    from jointplay.neural.identify.pipeline import output_names

    names, _ = output_names(scene.robot.moving_joints, case.contact)
    return replace(settings, measurement_noise=tuple(
        (n, float(std)) for n, std in zip(names, case.conditions.noise, strict=True) if std))


def case_scene(scene: Any, case: Case) -> Any:
    from jointplay.neural.identify.pipeline import with_torques
    from jointplay.robot import with_parameters
    from jointplay.scene.expressions import parse_expression

    robot = scene.robot
    values = {}
    for j in robot.clearance_joints:
        values[f"joint{j}.journal_radius"] = robot.joints[j - 1].bearing_radius - case.clearance
    out = scene.with_robot(with_parameters(robot, values)) if values else scene
    torques = [parse_expression(t, field="torques", constants=scene.constants)
               for t in case.torques]
    out = with_torques(out, torques)
    return replace(out, torque_text={f"joint{j}": t for j, t in zip(
        scene.robot.moving_joints, case.torques, strict=True)})


def nominal_clearance(scene: Any) -> float:
    robot = scene.robot
    values = {robot.joints[j - 1].bearing_radius - robot.joints[j - 1].journal_radius
              for j in robot.clearance_joints}
    if len(values) != 1:
        raise DescriptionError("scene", "the study needs every clearance joint to have the same "
                               f"radial clearance; they have {sorted(values)}")
    return values.pop()


__all__ = ["CASES", "NOISE", "Case", "case_list", "case_scene", "declared", "noise_levels",
           "nominal_clearance"]
