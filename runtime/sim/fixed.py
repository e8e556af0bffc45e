"""RK4 and Radau IIA at a fixed step, generated to C beside the model; onsets located by
interpolating the penetration between step ends, and the step redone with the captured speed.
"""

from __future__ import annotations

import math
from typing import Any

import casadi as ca
import numpy as np

from jointplay.common.errors import SimulationError
from jointplay.sim.events import _EventState
from jointplay.sim.problem import (
    RADAU_NEWTON_TOLERANCE,
    _Accumulated,
    _nearest_contact_joint,
    _Problem,
    _Trajectory,
)


def _steps_function(step: ca.Function, pr: _Problem, method: str, steps: int) -> ca.Function:
    """x0 -> states after each of ``steps`` steps, with powers, penetrations and rates."""
    model = pr.model
    x0 = ca.MX.sym("x0", pr.nx)
    tau = ca.MX.sym("tau", len(model.torque_joints), 3 * steps)
    h = ca.MX.sym("h")
    p = ca.MX.sym("p", len(model.parameters))
    v = ca.MX.sym("v_imp", pr.nc)
    contact = model.casadi_function("contact") if pr.nc else None
    names = contact.name_out() if contact is not None else []
    x = x0
    states, deltas, rates, powers, newton = [], [], [], [], []
    for i in range(steps):
        out = step(x, tau[:, 3 * i:3 * i + 3], h, p, v)
        if method == "radau":
            x = out[0]
            newton.append(out[1])
        else:
            x = out
        states.append(x)
        tau_end = tau[:, 3 * i + 2]
        drive = sum((tau_end[kk] * x[pr.n + ii] for kk, ii in enumerate(pr.angle_index)),
                    ca.MX(0))
        diss = ca.MX(0)
        if contact is not None:
            c = contact(x, p, v)
            deltas.append(c[names.index("delta")])
            rates.append(c[names.index("delta_dot")])
            diss = ca.sum1(c[names.index("dissipation")])
        powers.append(ca.vertcat(drive, diss))
    empty = ca.MX(0, steps)
    outs = [ca.horzcat(*states), ca.horzcat(*powers),
            ca.horzcat(*deltas) if deltas else empty, ca.horzcat(*rates) if rates else empty,
            ca.horzcat(*newton) if newton else empty]
    return ca.Function(f"{method}_x{steps}", [x0, tau, h, p, v], outs)


def _stage_fractions(method: str) -> np.ndarray:
    if method == "rk4":
        return np.array([0.0, 0.5, 1.0])
    return np.array([(4 - math.sqrt(6)) / 10, (4 + math.sqrt(6)) / 10, 1.0])


def _run_fixed(pr: _Problem, x0: np.ndarray, traj: _Trajectory, stats: _Accumulated,
               progress: Any) -> None:
    """RK4 or Radau at a fixed step; onsets located by interpolation between step ends."""
    run = pr.scene.run
    method, h, m = run.integrator, run.step, run.steps_per_output
    step = pr.model.casadi_function(f"{method}_step")
    batch = _steps_function(step, pr, method, m)
    single = _steps_function(step, pr, method, 1)
    fractions = _stage_fractions(method)
    events = _EventState(pr, x0, 0.0, traj.impacts)
    nc = pr.nc
    x = x0.copy()
    traj.x[0] = x
    traj.v_imp[0] = events.v_imp
    newton_iterations = pr.model.layout.functions["radau_step"].newton_iterations
    evals_per_step = 4 if method == "rk4" else 3 * (1 + newton_iterations)

    def stage_torques(t_start: np.ndarray) -> np.ndarray:
        times = (t_start[:, None] + h * fractions[None, :]).ravel()
        return pr.tau(times).T  # (ntau, 3 * steps)

    def power_at(state: np.ndarray, t: float) -> np.ndarray:
        tau = pr.tau(t)[0]
        drive = sum(tau[kk] * state[pr.n + ii] for kk, ii in enumerate(pr.angle_index))
        diss = float(np.sum(pr.contact_at(state, events.v_imp)["dissipation"])) if nc else 0.0
        return np.array([drive, diss])

    def evaluate(fn: ca.Function, state: np.ndarray, t_start: np.ndarray) -> list[np.ndarray]:
        out = [np.asarray(o) for o in fn(state, stage_torques(t_start), h, pr.p,
                                         events.v_imp)]
        stats.counts["steps"] += t_start.size
        stats.counts["rhs_evaluations"] += evals_per_step * t_start.size
        if method == "radau":
            stats.counts["jacobian_evaluations"] += t_start.size
        states = out[0].T
        finite = np.all(np.isfinite(states), axis=1)
        if not np.all(finite):
            bad = int(np.argmin(finite))
            raise SimulationError(float(t_start[bad]), f"{method} at step {h:g} s produced a "
                                  "non-finite state: the step is beyond the method's stability "
                                  "limit for this contact stiffness; reduce run.step or use "
                                  "cvodes", _nearest_contact_joint(pr, state, events.v_imp))
        if method == "radau":
            newton = out[4].ravel()
            if np.any(newton > RADAU_NEWTON_TOLERANCE * np.max(pr.scale)):
                bad = int(np.argmax(newton > RADAU_NEWTON_TOLERANCE * np.max(pr.scale)))
                raise SimulationError(float(t_start[bad]), "Radau's Newton iteration did not "
                                      f"converge (last update {newton[bad]:.3g}); reduce "
                                      "run.step", _nearest_contact_joint(pr, state,
                                                                         events.v_imp))
        return [states, out[1].T, out[2].T, out[3].T]

    power_prev = power_at(x, 0.0)
    start = pr.contact_at(x, events.v_imp) if nc else {}
    delta_prev = start.get("delta", np.zeros(0))
    rate_prev = start.get("delta_dot", np.zeros(0))
    work = dissipated = 0.0
    batches = {m: batch, 1: single}

    def batch_of(size: int) -> ca.Function:
        if size not in batches:
            batches[size] = _steps_function(step, pr, method, size)
        return batches[size]

    for k in range(run.n_outputs):
        t_start = k * run.output_step + h * np.arange(m)
        states, powers, deltas, rates = evaluate(batch, x, t_start)
        i = 0
        while i < m:
            # The first step from i on where a joint's penetration disagrees with its flag.
            j = m
            if nc:
                flags = events.flags > 0.5
                disagree = np.where(flags, deltas[i:] < 0, deltas[i:] > 0)
                rows = np.flatnonzero(disagree.any(axis=1))
                j = i + int(rows[0]) if rows.size else m
            if j > i:  # accept steps i .. j-1; powers by the trapezoidal rule
                chain = np.vstack([power_prev, powers[i:j]])
                work += 0.5 * h * float(np.sum(chain[:-1, 0] + chain[1:, 0]))
                dissipated += 0.5 * h * float(np.sum(chain[:-1, 1] + chain[1:, 1]))
                x, power_prev = states[j - 1], powers[j - 1]
                delta_prev, rate_prev = deltas[j - 1], rates[j - 1]
            if j == m:
                break
            flags = events.flags > 0.5
            separated = flags & (deltas[j] < 0)
            onset = ~flags & (deltas[j] > 0)
            events.flags[separated] = 0.0
            stats.counts["events"] += int(np.sum(separated) + np.sum(onset))
            for c in np.flatnonzero(onset):
                theta = min(max(-delta_prev[c] / (deltas[j][c] - delta_prev[c]), 0.0), 1.0)
                events.onset(int(c), float(t_start[j] + theta * h),
                             float(rate_prev[c] + theta * (rates[j][c] - rate_prev[c])),
                             x + theta * (states[j] - x))
            if np.any(onset):
                # Steps from j on used a stale impact speed: redo them with the captured one.
                redone = evaluate(batch_of(m - j), x, t_start[j:])
                for target, values in zip((states, powers, deltas, rates), redone,
                                          strict=True):
                    target[j:] = values
            i = j  # step j is accepted by the scan (its flags now agree, or it is redone)
            if not np.any(onset):
                chain = np.vstack([power_prev, powers[j:j + 1]])
                work += 0.5 * h * float(np.sum(chain[:-1, 0] + chain[1:, 0]))
                dissipated += 0.5 * h * float(np.sum(chain[:-1, 1] + chain[1:, 1]))
                x, power_prev, delta_prev, rate_prev = states[j], powers[j], deltas[j], rates[j]
                i = j + 1
        traj.x[k + 1] = x
        traj.work[k + 1] = work
        traj.dissipated[k + 1] = dissipated
        traj.v_imp[k + 1] = events.v_imp
        progress.update(1)


