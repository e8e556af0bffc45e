"""What a simulation returns: every quantity as numpy arrays over the output times.

Arrays are float64, indexed by output sample first. ``nc`` is the number of clearance joints
(``clearance_joints`` gives their 1-based joint numbers, in the order of the second axis).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass(frozen=True)
class Impacts:
    """One row per impact (onset of contact at a clearance joint), in time order."""

    time: np.ndarray  # (m,) s, onset of contact located by event detection
    joint: np.ndarray  # (m,) int, 1-based joint number
    speed: np.ndarray  # (m,) m/s, normal approach speed d(delta)/dt at onset (before flooring)
    eccentricity: np.ndarray  # (m, 2) m, journal centre minus bearing centre at onset

    def __len__(self) -> int:
        return int(self.time.size)


@dataclass(frozen=True)
class SimulationResult:
    """A simulated trajectory and everything derived from it (SI units throughout)."""

    scene_name: str
    integrator: str  # "cvodes", "idas", "rk4" or "radau"
    t: np.ndarray  # (N,) s
    coordinate_names: list[str]  # e.g. ["q2", "q3", "ex2", "ey2", "ex3", "ey3"]
    q: np.ndarray  # (N, n) coordinates: rad for angles, m for eccentricities
    u: np.ndarray  # (N, n) their time derivatives
    udot: np.ndarray  # (N, n) accelerations (from the model at each output sample)
    tau: np.ndarray  # (N, ntau) N m, drive torque of each moving joint
    torque_joints: list[int]  # 1-based joints the columns of tau belong to
    tip_position: np.ndarray  # (N, 2) m, end effector (tip of the last link, payload)
    tip_velocity: np.ndarray  # (N, 2) m/s
    tip_acceleration: np.ndarray  # (N, 2) m/s^2
    clearance_joints: list[int]
    radial_clearance: np.ndarray  # (nc,) m, Rb - Rj of each clearance joint
    eccentricity: np.ndarray  # (N, nc, 2) m, journal centre minus bearing centre
    penetration: np.ndarray  # (N, nc) m, |e| - c (negative: no contact)
    penetration_rate: np.ndarray  # (N, nc) m/s
    normal_force: np.ndarray  # (N, nc) N, >= 0
    friction_force: np.ndarray  # (N, nc) N, on the journal along the tangent
    contact_force: np.ndarray  # (N, nc, 2) N, total contact force on the journal, x and y
    sliding_speed: np.ndarray  # (N, nc) m/s
    impacts: Impacts
    # Energy (J), each (N,): kinetic, gravity (potential), contact (elastic potential), total
    # (their sum), drive_work (work done by the drive torques since t0), dissipated (by contact
    # damping and friction since t0), and balance = total - total[0] - drive_work + dissipated,
    # which is zero for an exact solution.
    energy: dict[str, np.ndarray]
    parameter_names: list[str]
    parameters: np.ndarray  # the parameter vector the run used
    stats: dict[str, Any]  # solver statistics: steps, rhs / jacobian evaluations, events, wall time
    metadata: dict[str, Any] = field(default_factory=dict)  # scene text, versions, model hash
    ideal: SimulationResult | None = None  # the same scene with ideal joints (--compare-ideal)

    @property
    def n_samples(self) -> int:
        return int(self.t.size)
