"""Stops for states no real robot reaches, checked while a run goes on and before its results
are used: a journal driven through its bearing, an energy balance that no longer closes, and
any derived quantity that is not finite.

Inputs that are each plausible can still combine into an impossible run (a fast initial spin
into a tight bearing, say): the contact laws then leave the small-deformation domain they were
derived for and the numbers mean nothing, although the integrator succeeds. Such a run stops
with a :class:`~jointplay.common.errors.SimulationError` naming the joint, the time and the
input most likely at fault (exit 1 on the command line); nothing is written.
The bounds are :data:`jointplay.common.limits.MAX_PENETRATION_FRACTION` and
:data:`jointplay.common.limits.MAX_ENERGY_RESIDUAL` (docs/reference/limits-and-errors.md lists
them).

The penetration is read where it is largest, not only at the output samples: the compiled
``bdf`` locates each contact phase's deepest point (where the penetration rate is zero) and
every located maximum is checked, after each stretch of the run and on the final table; the
output samples are checked too (the other methods locate no maximum). So the output step,
which never changes the integration, never changes the verdict.

``run.plausibility`` (:data:`jointplay.scene.definition.PLAUSIBILITY`) makes the two physical
checks a setting: ``"stop"`` (the default) raises, ``"warn"`` lets the run finish, warns once
(:class:`PlausibilityWarning`) and marks the result (``result.implausible``, kept in the
results file), ``"off"`` checks neither. Numbers that are not finite always stop the run.
"""

from __future__ import annotations

import warnings
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.common import limits
from jointplay.common.errors import SimulationError

if TYPE_CHECKING:
    from jointplay.results.records import Impacts, SimulationResult
    from jointplay.sim.problem import _Problem, _Trajectory

# Below this (J) an energy residual is rounding, whatever the run's energies: a robot at rest
# has a balance of a few 1e-12 J on energies of 0.
ENERGY_RESIDUAL_FLOOR = 1.0e-6


class PlausibilityWarning(UserWarning):
    """A run left the physical domain and was kept because ``run.plausibility = "warn"``."""


def likely_input(pr: _Problem) -> str:
    """The inputs most likely to have driven a run out of the physical domain."""
    from jointplay.scene.definition import RunSettings

    run = pr.scene.run
    if run.integrator in ("bdf", "cvodes", "idas") and (run.rtol >= 1e-2 or run.atol >= 1.0):
        return (f"the tolerances (run.rtol = {run.rtol:g}, run.atol = {run.atol:g}; the "
                f"defaults are {RunSettings.rtol:g} and {RunSettings.atol:g})")
    if run.integrator not in ("bdf", "cvodes", "idas"):
        return (f"the fixed step first: reduce run.step (now {run.step:g} s) or use an "
                "adaptive integrator; else the initial speeds or the drive torques")
    speeds = {k: v for k, v in pr.scene.initial.items() if k.startswith("d") and v != 0.0}
    if speeds:
        name, value = max(speeds.items(), key=lambda kv: abs(kv[1]))
        unit = "rad/s" if name.startswith("dq") else "m/s"
        return (f"the initial speeds ([initial] {name} = {value:g} {unit}), or the drive "
                "torques")
    return "the drive torques ([torques]) or the contact parameters (E, exponent, masses)"


class PenetrationWatch:
    """Wraps a run's progress bar: each time the integration reports new output samples, their
    penetrations are checked against the contact law's domain before the run goes on; the
    located maxima of the contact phases are checked with :meth:`check_located`. With
    ``run.plausibility = "warn"`` the first finding is kept in ``findings`` and the run goes
    on; with ``"off"`` nothing is checked."""

    def __init__(self, progress: Any, pr: _Problem, traj: _Trajectory) -> None:
        self.progress = progress
        self.pr = pr
        self.traj = traj
        self.mode = pr.scene.run.plausibility
        self.findings: list[str] = []
        self.checked = 0  # output samples 1..checked are checked
        model = pr.model
        self.columns = [(model.coordinates.index(f"ex{j}"), model.coordinates.index(f"ey{j}"))
                        for j in model.clearance_joints]
        self.clearance = np.array([pr.scale[ix] for ix, _ in self.columns])
        slots = [model.layout.parameter_slot("joint", j, "journal_radius")
                 for j in model.clearance_joints]
        self.journal_radius = np.asarray(pr.p[slots], dtype=float)
        self.limit = limits.MAX_PENETRATION_FRACTION * self.journal_radius

    def update(self, n: int = 1) -> Any:
        upto = min(self.checked + int(n), self.traj.x.shape[0] - 1)
        if self.columns and upto > self.checked:
            self.check(slice(self.checked + 1, upto + 1))
        self.checked = upto
        return self.progress.update(n)

    def check(self, rows: slice) -> None:
        """The output samples ``rows`` of the trajectory."""
        if self.mode == "off" or self.findings:
            return
        x = self.traj.x[rows]
        for k, (ix, iy) in enumerate(self.columns):
            delta = np.hypot(x[:, ix], x[:, iy]) - self.clearance[k]
            over = delta > self.limit[k]
            if over.any():
                i = int(np.argmax(over))
                self._found(k, float(delta[i]), (rows.start + i) * self.pr.scene.run.output_step,
                            "at an output sample")
                return

    def check_located(self, column: np.ndarray, penetration: np.ndarray,
                      time: np.ndarray) -> None:
        """Located maxima of contact phases: the 0-based clearance ``column`` of each, its
        largest penetration (m) and when (s). NaN (not located) is skipped."""
        if self.mode == "off" or self.findings or not self.columns:
            return
        column = np.asarray(column, dtype=int)
        with np.errstate(invalid="ignore"):
            over = np.asarray(penetration, dtype=float) > self.limit[column]
        if over.any():
            rows = np.flatnonzero(over)
            i = int(rows[np.argmin(np.asarray(time, dtype=float)[rows])])
            self._found(int(column[i]), float(penetration[i]), float(time[i]),
                        "located: the deepest point of a contact phase")

    def check_impacts(self, impacts: Impacts) -> None:
        """The located maxima of a run's contact-phase table (1-based joint numbers)."""
        if len(impacts) == 0:
            return
        joints = list(self.pr.model.clearance_joints)
        column = np.array([joints.index(int(j)) for j in impacts.joint], dtype=int)
        self.check_located(column, impacts.max_penetration, impacts.max_penetration_time)

    def _found(self, k: int, delta: float, t: float, where: str) -> None:
        joint = int(self.pr.model.clearance_joints[k])
        radius = self.journal_radius[k]
        error = SimulationError(
            t, f"the journal has penetrated its bearing by {delta * 1e3:.3g} mm "
            f"({100 * delta / radius:.3g} % of its {radius * 1e3:.3g} mm radius; {where}), "
            f"beyond the {100 * limits.MAX_PENETRATION_FRACTION:g} % the contact law "
            "describes: no real joint reaches this state; check "
            f"{likely_input(self.pr)}", joint)
        if self.mode == "stop":
            raise error
        self.findings.append(finding(error))


def check_result(result: SimulationResult, pr: _Problem) -> list[str]:
    """Every per-sample quantity (and the wear) is finite, and the energy balance closes.
    Returns what is implausible where ``run.plausibility`` is ``"warn"`` (raises where it is
    ``"stop"``; the balance is not checked where it is ``"off"``)."""
    _check_finite(result)
    mode = pr.scene.run.plausibility
    if mode == "off":
        return []
    try:
        _check_energy(result, pr)
    except SimulationError as err:
        if mode == "stop":
            raise
        return [finding(err)]
    return []


def finding(error: SimulationError) -> str:
    """What a stop would have said, for a run that goes on: where, and why."""
    where = f" at joint {error.joint}" if error.joint is not None else ""
    return f"at t = {error.time:.9g} s{where}: {error.cause}"


def implausible(findings: list[str], pr: _Problem, result: SimulationResult
                ) -> SimulationResult:
    """The result marked with what was found implausible (``run.plausibility = "warn"``),
    after one warning line; unchanged where nothing was found."""
    if not findings:
        return result
    text = "; ".join(findings)
    warnings.warn(f"implausible run kept (run.plausibility = \"warn\"): {text}",
                  PlausibilityWarning, stacklevel=3)
    result.metadata["implausible"] = text
    return result


def _check_finite(result: SimulationResult) -> None:
    arrays: dict[str, Any] = {
        name: getattr(result, name) for name in (
            "q", "u", "udot", "tau", "tip_position", "tip_velocity", "tip_acceleration",
            "eccentricity", "penetration", "penetration_rate", "normal_force",
            "friction_force", "contact_force", "sliding_speed")}
    arrays.update({f"energy.{k}": v for k, v in result.energy.items()})
    for name, values in arrays.items():
        values = np.asarray(values, dtype=float)
        bad = ~np.isfinite(values.reshape(values.shape[0], -1)) if values.size else None
        if bad is not None and bad.any():
            i = int(np.argmax(bad.any(axis=1)))
            raise SimulationError(float(result.t[i]), f"{name} is not finite from here on; "
                                  "the inputs drive the model outside the range of float64 "
                                  "numbers (see the plausible ranges in "
                                  "docs/reference/limits-and-errors.md)")
    wear = result.wear
    if wear is not None:
        for name in ("bearing_depth", "journal_depth", "volume"):
            values = np.asarray(getattr(wear, name), dtype=float)
            if not np.isfinite(values).all():
                raise SimulationError(float(result.t[-1]), f"the wear {name.replace('_', ' ')}"
                                      " is not finite: check wear.coefficient and "
                                      "wear.hardness")


def _check_energy(result: SimulationResult, pr: _Problem) -> None:
    energy = result.energy
    balance = np.abs(np.asarray(energy["balance"], dtype=float))
    if balance.size == 0:
        return
    total = np.asarray(energy["total"], dtype=float)
    scale = max(float(np.max(np.abs(energy["kinetic"]))),
                float(np.max(np.abs(energy["drive_work"]))),
                float(np.max(np.abs(energy["dissipated"]))),
                float(np.max(np.abs(total - total[0]))))
    bound = max(limits.MAX_ENERGY_RESIDUAL * scale, ENERGY_RESIDUAL_FLOOR)
    over = balance > bound
    if over.any():
        i = int(np.argmax(over))
        raise SimulationError(
            float(result.t[i]), f"the energy balance no longer closes: its residual is "
            f"{balance[i]:.3g} J, more than {100 * limits.MAX_ENERGY_RESIDUAL:g} % of the "
            f"run's largest energy ({scale:.3g} J), so the integration has lost the "
            f"physics; tighten run.rtol / run.atol (or a smaller run.step), or check "
            f"{likely_input(pr)}")


# Samples of the dense grid a failed run's torques are inspected on (about 8 MB per torque).
_DENSE_SAMPLES = 1 << 20
# A torque whose peak between output times exceeds its peak at them this many times over
# is called singular there: a smooth torque, however fast, gives a ratio close to 1.
_SPIKE_RATIO = 100.0


def singular_torque(pr: _Problem, t_stop: float) -> str | None:
    """After a failed integration: the cause, when a drive torque is not finite or has a
    spike between the output times (``1/(t - 0.3005)`` with outputs every ms), which the
    check at the output times could not see and the integrator cannot follow; else None."""
    run = pr.scene.run
    if not pr.torques:
        return None
    outputs = np.arange(run.n_outputs + 1) * run.output_step
    near = t_stop + run.output_step * np.linspace(-1.0, 1.0, 20001)
    dense = np.concatenate([np.linspace(0.0, run.t_end, _DENSE_SAMPLES),
                            near[(near >= 0.0) & (near <= run.t_end)]])
    keys = [f"joint{j}" for j in pr.scene.robot.moving_joints] if pr.scene.robot.drive else []
    for k, torque in enumerate(pr.torques):
        with np.errstate(all="ignore"):
            values = np.abs(np.broadcast_to(np.asarray(torque.numpy(dense), dtype=float),
                                            dense.shape))
            at_outputs = np.abs(np.asarray(torque.numpy(outputs), dtype=float))
        bad = ~np.isfinite(values)
        peak = float(np.max(at_outputs)) if at_outputs.size else 0.0
        spike = values > _SPIKE_RATIO * max(peak, 1e-300)
        if not (bad.any() or spike.any()):
            continue
        i = int(np.argmax(bad)) if bad.any() else int(np.argmax(np.where(spike, values, 0.0)))
        key = keys[k] if k < len(keys) else f"[{k}]"
        text = pr.scene.torque_text.get(key)
        shown = f" ({text!r})" if text else ""
        what = (f"is {values[i]} at t = {dense[i]:.9g} s" if bad.any() else
                f"reaches {values[i]:.3g} N m near t = {dense[i]:.9g} s (at most {peak:.3g} N m "
                "at the output times)")
        return (f"the drive torque torques.{key}{shown} {what}, between the output times: the "
                "integrator cannot follow a torque that is singular there; make every torque "
                "finite and bounded over [0, run.t_end]")
    return None
