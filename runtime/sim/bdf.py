"""The default method: jointplay's compiled BDF, a whole run in one call (see driver.c).

Python sets the run up (parameters, scaling, torques as data) and reads its results; the
steps, the event search, the impact-speed capture and the per-phase records all happen in C.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from jointplay.results.records import Impacts
from jointplay.results.wear import wear_profile
from jointplay.sim.native import NativeIntegrator, raise_for_status
from jointplay.sim.problem import (
    MAX_EVENTS_PER_OUTPUT,
    _Accumulated,
    _nearest_contact_joint,
    _Problem,
    _Trajectory,
)

# Calls into C per run (see run_bdf).
PROGRESS_CALLS = 20


def native_integrator(pr: _Problem) -> NativeIntegrator:
    model = pr.model
    run = pr.scene.run
    ecc = np.array([[model.coordinates.index(f"ex{j}"), model.coordinates.index(f"ey{j}")]
                    for j in model.clearance_joints], dtype=np.int32).reshape(-1, 2)
    clearance = np.array([pr.scale[i] for i in ecc[:, 0]]) if ecc.size else np.zeros(0)
    return NativeIntegrator(model, pr.p, pr.scale, ecc, clearance,
                            np.asarray(pr.angle_index, dtype=np.int32), pr.torques,
                            rtol=run.rtol, atol=run.atol, max_steps=run.max_steps,
                            max_events=MAX_EVENTS_PER_OUTPUT, sensitivities=pr.sensitivity,
                            peaks=pr.peaks, newton=pr.newton)


def torque_fields(pr: _Problem) -> list[str]:
    return [f"torques.joint{j}" for j in pr.model.torque_joints]


def phase_table(pr: _Problem, rows: np.ndarray, t_end: float) -> Impacts:
    """The driver's phase rows as the typed table (1-based joints, derived columns)."""
    joints = np.asarray(pr.model.clearance_joints, dtype=int)
    col = {name: rows[:, k] for k, name in enumerate((
        "joint", "time", "speed", "ex", "ey", "peak_force", "peak_force_time",
        "max_penetration", "max_penetration_time", "separation_time", "exit_speed",
        "impulse", "damping_energy", "friction_energy"))}
    separated = np.isfinite(col["separation_time"])
    end = np.where(separated, col["separation_time"], t_end)
    with np.errstate(invalid="ignore", divide="ignore"):
        restitution = np.where(separated, col["exit_speed"] / col["speed"], np.nan)
    return Impacts(
        time=col["time"].copy(), joint=joints[col["joint"].astype(int)] if rows.size
        else np.zeros(0, dtype=int), speed=col["speed"].copy(),
        eccentricity=np.stack([col["ex"], col["ey"]], axis=1),
        onset_angle=np.arctan2(col["ey"], col["ex"]),
        peak_force=col["peak_force"].copy(), peak_force_time=col["peak_force_time"].copy(),
        max_penetration=col["max_penetration"].copy(),
        max_penetration_time=col["max_penetration_time"].copy(),
        separation_time=col["separation_time"].copy(), exit_speed=col["exit_speed"].copy(),
        duration=end - col["time"], restitution=restitution,
        impulse=col["impulse"].copy(), damping_energy=col["damping_energy"].copy(),
        friction_energy=col["friction_energy"].copy(), separated=separated)


def close_open_phases(integ: NativeIntegrator, pr: _Problem, rows: np.ndarray,
                      final: np.ndarray) -> np.ndarray:
    """Phases still open at the end get their quadratures up to the end of the run."""
    rows = rows.copy()
    nx = pr.nx
    for r in np.flatnonzero(~np.isfinite(rows[:, 9])):
        j = int(rows[r, 0])
        for k in range(3):
            rows[r, 11 + k] += final[nx + 1 + 3 * j + k]
    return rows


def run_bdf(pr: _Problem, x0: np.ndarray, traj: _Trajectory, stats: _Accumulated,
            progress: Any) -> Impacts:
    """Integrate the scene; fill ``traj`` at the output times; return the phase table."""
    run = pr.scene.run
    n_out = run.n_outputs
    t = np.arange(1, n_out + 1) * run.output_step
    integ = native_integrator(pr)
    integ.reset(x0)
    traj.x[0] = x0
    if integ.n_sensitivities:
        traj.sensitivity = np.zeros((n_out + 1, pr.nx, integ.n_sensitivities))
        traj.sensitivity[0] = pr.sensitivity.initial.T
    _, speeds = integ.flags()
    traj.v_imp[0] = speeds
    nx = pr.nx
    # A run is a few calls, each over a fixed share of the simulated time (never tied to the
    # output step, so outputs never change the integration): enough for a progress bar and a
    # prompt Ctrl-C between calls, while each call stays whole in C.
    bounds = np.linspace(0.0, float(t[-1]), PROGRESS_CALLS + 1)[1:]
    done = 0
    for bound in bounds:
        upto = int(np.searchsorted(t, bound, side="right"))
        values, v_out, status = integ.integrate(float(bound), t[done:upto])
        if status:
            _add_counts(stats, integ)
            raise_for_status(status, integ, torque_fields(pr),
                             lambda: _joint_at_failure(pr, integ))
        rows = slice(done + 1, upto + 1)
        traj.x[rows] = values[:, :nx]
        traj.work[rows] = values[:, nx]
        if pr.nc:  # per joint: impulse, damping energy, friction energy
            per_joint = values[:, nx + 1:nx + 1 + 3 * pr.nc].reshape(upto - done, pr.nc, 3)
            traj.dissipated[rows] = per_joint[:, :, 1:].sum(axis=(1, 2))
        traj.v_imp[rows] = v_out
        if integ.n_sensitivities:
            traj.sensitivity[rows] = integ.sensitivity_rows(values)
        if pr.nc and hasattr(progress, "check_located"):  # the phases' deepest points so far
            located = integ.phases()
            progress.check_located(located[:, 0], located[:, 7], located[:, 8])
        progress.update(upto - done)
        done = upto
    _add_counts(stats, integ)
    wear = integ.wear()
    if wear is not None:
        traj.wear = wear_profile(list(pr.model.clearance_joints), *wear)
    if integ.n_sensitivities:
        traj.phase_sensitivity = integ.phase_sensitivities()
    phase_rows = close_open_phases(integ, pr, integ.phases(), integ.current())
    return phase_table(pr, phase_rows, float(t[-1]))


def _add_counts(stats: _Accumulated, integ: NativeIntegrator) -> None:
    counts = integ.stats()
    for key in ("steps", "rhs_evaluations", "jacobian_evaluations", "error_test_failures",
                "events", "impacts"):
        stats.counts[key] += counts[key]
    stats.counts["integrator_calls"] += 1
    stats.counts["lu_decompositions"] = counts["lu_decompositions"]
    # Of those, the ones of the n x n Newton matrix the second-order form reduces to (all of
    # them where the state Jacobian is [0 D; Jq Jv] and the model has 12 coordinates or more,
    # or JOINTPLAY_NEWTON=reduced; none with JOINTPLAY_NEWTON=full).
    stats.counts["reduced_lu_decompositions"] = counts["reduced_lu_decompositions"]
    stats.counts["newton_failures"] = counts["newton_failures"]
    if integ.n_sensitivities:  # the Jacobians at each step's end the sensitivities take
        stats.counts["sensitivity_jacobians"] = counts["sensitivity_jacobians"]


def _joint_at_failure(pr: _Problem, integ: NativeIntegrator) -> int | None:
    current = integ.current()[:pr.nx]
    _, speeds = integ.flags()
    return _nearest_contact_joint(pr, current, speeds)
