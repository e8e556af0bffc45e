"""The closed loop: the clearance robot stepped sample by sample with a control law added to
the scene's torques, and the laws it is run with (the internal-model step, PD, computed torque).

A run is declared diverged when its end-effector error leaves a bound or the plant cannot be
integrated; it stops there (jointplay.neural.study.comparison sets the bound).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from jointplay.common.errors import SimulationError
from jointplay.neural.control.imc import Controller
from jointplay.neural.control.imc_step import FLAGS
from jointplay.neural.control.internal_model import _inner_gains
from jointplay.neural.model.narx import Narx


@dataclass
class Run:
    """One closed-loop (or open-loop) run: absolute outputs and the torque added.

    A diverged run stops where it diverged: its arrays are shorter than the reference."""

    name: str
    t: np.ndarray
    y: np.ndarray
    tau: np.ndarray  # (N+1, nu) torque added to the scene's from each sample (last row 0)
    v: np.ndarray  # the outer loop's part (internal-model controllers), else zeros
    impacts: int
    seconds: float
    diverged: str = ""  # empty, or where and why the run was stopped
    flags: np.ndarray = field(default_factory=lambda: np.zeros((0, len(FLAGS))))
    states: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))  # controller states
    # The end effector's acceleration between samples (SUBSTEPS points per sample period,
    # (t_k, t_k+1]): times and (x, y) rows; empty when the plant gives no dense output.
    dense_t: np.ndarray = field(default_factory=lambda: np.zeros(0))
    dense_acceleration: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    impact_times: np.ndarray = field(default_factory=lambda: np.zeros(0))  # s
    # For the accuracy check (jointplay.neural.control.loop_accuracy): the plant's contact onsets
    # (time, joint, approach speed, eccentricity x, y), its energy balance per sample (J) and
    # the energy its contacts dissipated (J).
    impact_rows: list[tuple[float, int, float, float, float]] = field(default_factory=list)
    energy_balance: np.ndarray = field(default_factory=lambda: np.zeros(0))
    dissipated: float = 0.0

    @property
    def guard_counts(self) -> dict[str, int]:
        """Samples on which each guard flag was raised; 'episodes' counts distinct
        interventions (the network distrusted after having been trusted)."""
        if self.flags.size == 0:
            return {}
        out = {name: int(np.sum(self.flags[:, i] > 0.5)) for i, name in enumerate(FLAGS)}
        distrusted = self.flags[:, 0] > 0.5
        out["episodes"] = int(np.sum(distrusted[1:] & ~distrusted[:-1]) + distrusted[0])
        return out


Law = Callable[[int, np.ndarray], np.ndarray]


@dataclass(frozen=True)
class LoopConditions:
    """What the loop is exposed to beyond the scene: an unknown torque step on the plant,
    noise on every measured signal the controllers see, and a delay of the actuators."""

    disturbance: tuple[float, ...] = ()  # N m per driven joint, from disturbance_time on
    disturbance_time: float = 1.0
    noise: tuple[float, ...] = ()  # standard deviation per output (plant units); () none
    delay: int = 0  # samples between a law's output and the actuator
    seed: int = 0


NO_CONDITIONS = LoopConditions()  # the scene alone: no disturbance, noise or delay


def run_loop(scene: Any, reference: np.ndarray, law: Law, name: str,
             clearance_model: Any | None = None, *, limit: float = math.inf,
             conditions: LoopConditions = LoopConditions(), substeps: int = 1,
             contact: Sequence[int] = ()) -> Run:
    """Step the scene's clearance robot with ``law(k, y)`` added to the scene's torques.

    ``y`` holds the outputs of ``reference``'s columns: the plant's outputs, and after them
    the journal eccentricities of the joints ``contact``.

    ``limit``: the run stops, marked diverged, once the end-effector position error exceeds
    it (m), as it does when the plant can no longer be integrated. ``substeps`` > 1 (``bdf``
    plants) also records the end effector's acceleration at that many points per sample."""
    from jointplay.neural.model.inner_loop import contact_index, measure
    from jointplay.sim import Stepper

    stepper = Stepper(scene, model=clearance_model, substeps=substeps)
    joints = scene.robot.moving_joints
    index = [stepper.model.coordinates.index(f"q{j}") for j in joints]
    eccentricity = contact_index(stepper.model, contact)
    n = scene.run.n_outputs
    dt = scene.run.output_step
    nj = len(joints)
    y = np.zeros_like(reference)
    tau = np.zeros((n + 1, nj))
    applied = [np.zeros(nj)] * conditions.delay
    rng = np.random.default_rng(conditions.seed)
    noise = np.asarray(conditions.noise, dtype=float) if conditions.noise else None
    dist = np.asarray(conditions.disturbance, dtype=float) if conditions.disturbance else None
    tip = slice(2 * nj, 2 * nj + 2)
    diverged = ""
    last = n
    start = time.perf_counter()
    for k in range(n + 1):
        y[k] = measure(stepper, index, eccentricity)
        error = float(np.linalg.norm(y[k, tip] - reference[k, tip]))
        if not np.all(np.isfinite(y[k])) or error > limit:
            diverged = (f"end-effector error {error:.3g} m at t = {k * dt:.3f} s exceeds the "
                        f"divergence bound {limit:.3g} m")
            last = k
            break
        if k == n:
            break
        seen = y[k] + rng.normal(0.0, noise) if noise is not None else y[k]
        tau[k] = law(k, seen)
        out = tau[k]
        if conditions.delay:
            applied.append(tau[k])
            out = applied.pop(0)
        if dist is not None and k * dt >= conditions.disturbance_time - 1e-12:
            out = out + dist
        try:
            stepper.step(out)
        except SimulationError as err:
            diverged = f"the plant could not be integrated: {err}"
            last = k
            break
    keep = slice(0, last + 1)
    t = np.arange(n + 1) * dt
    dense_t, dense_a = stepper.dense_tip_acceleration()
    return Run(name, t[keep], y[keep], tau[keep], np.zeros_like(tau[keep]),
               len(stepper.impacts), time.perf_counter() - start, diverged,
               dense_t=dense_t, dense_acceleration=dense_a,
               # A journal starting in contact is recorded at t = 0 at zero speed: not a strike.
               impact_times=np.array([float(i[0]) for i in stepper.impacts if i[2] > 0]),
               impact_rows=list(stepper.impacts), energy_balance=stepper.energy_balance(),
               dissipated=stepper.dissipated)


def imc_law(ctrl: Controller, reference: np.ndarray, tau_ff: np.ndarray,
            log: dict[str, list[np.ndarray]]) -> Law:
    """The compiled internal-model step as a law; logs v, the prediction, flags, states.

    For the first ``settings.engage`` seconds the outer loop waits (v = 0, the inner PD
    alone, within the actuator limits); it then starts its internal models from the last
    measured deviations. The models were identified without that start-up (the journals
    falling from the centred start onto their bearings), and acting on it with them drove v
    to 0.42 N m and left the journals bouncing well past it (docs/control.md)."""
    state: list[np.ndarray] = []
    s = ctrl.settings
    engage = round((s.engage or 0.0) / ctrl.model.sample_time)
    q, dq, kp, kd = _inner_gains(ctrl.model)
    limit = np.asarray(s.torque_limit, dtype=float)
    nu, ny = ctrl.model.n_inputs, ctrl.model.n_outputs

    past: list[np.ndarray] = []  # measured deviations while waiting, newest first

    def law(k: int, y: np.ndarray) -> np.ndarray:
        dev = y - reference[k]
        if k <= engage:
            # The models start from the measured history (v was zero), as in training.
            state[:] = [ctrl.initial_state(dev, np.array(past) if past else None)]
            past.insert(0, dev)
            del past[4:]
        log["states"].append(state[0])
        if k < engage:
            inner = -kp * dev[q] - kd * dev[dq] if q else np.zeros(nu)
            log["v"].append(np.zeros(nu))
            log["y_pred"].append(np.zeros(ny))
            log["flags"].append(np.zeros(len(FLAGS)))
            return np.asarray(np.clip(tau_ff[k] + inner, -limit, limit) - tau_ff[k])
        tau, nxt, v, pred = ctrl.step(y, reference[k], tau_ff[k], state[0])
        state[0] = nxt
        log["v"].append(v)
        log["y_pred"].append(pred)
        log["flags"].append(ctrl.last_flags)
        return tau
    return law


def pd_law(narx: Narx, reference: np.ndarray, kp: Sequence[float] = (),
           kd: Sequence[float] = ()) -> Law:
    """PD on the moving joints around the reference (default: the inner loop's gains)."""
    q, dq, kp0, kd0 = _inner_gains(narx)
    p_gain = np.asarray(kp, dtype=float) if len(kp) else kp0
    d_gain = np.asarray(kd, dtype=float) if len(kd) else kd0

    def law(k: int, y: np.ndarray) -> np.ndarray:
        dev = y - reference[k]
        return np.asarray(-p_gain * dev[q] - d_gain * dev[dq])
    return law


def computed_torque_law(scene: Any, ideal: Any, reference: np.ndarray, omega: float,
                        zeta: float) -> Law:
    """Computed torque with the ideal-joint model: tau = M(q)(qdd_r + kd e' + kp e) - f0(q,
    qdot); the scene's torque at the sample is subtracted because the stepper adds it."""
    from jointplay.scene.definition import ideal_counterpart
    from jointplay.sim import load_scene_model

    model = load_scene_model(scene, ideal=True)
    p = np.asarray(ideal_counterpart(scene.robot).parameter_values(), dtype=float)
    nj = len(scene.robot.moving_joints)
    no_contact = np.zeros(0)
    zero = np.zeros(nj)
    kp, kd = omega ** 2, 2 * zeta * omega
    qdd_r = ideal.udot
    tau_scene = ideal.tau

    def law(k: int, y: np.ndarray) -> np.ndarray:
        q, qd = y[:nj], y[nj:2 * nj]
        e, ed = reference[k, :nj] - q, reference[k, nj:2 * nj] - qd
        x = np.concatenate([q, qd])
        a = qdd_r[k] + kd * ed + kp * e
        f0 = model.forcing(x, zero, p, no_contact)
        b = np.column_stack([model.forcing(x, unit, p, no_contact) - f0
                             for unit in np.eye(nj)])  # f is affine in the torques
        tau = np.linalg.solve(b, model.mass_matrix(q, p) @ a - f0)
        return np.asarray(tau - tau_scene[k])
    return law


__all__ = ["NO_CONDITIONS", "Law", "LoopConditions", "Run", "computed_torque_law", "imc_law",
           "pd_law", "run_loop"]
