"""RK4 and Radau IIA at a fixed step, generated to C beside the model; onsets located by
interpolating the penetration between step ends, and the step redone with the captured speed.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass
from typing import Any, NoReturn

import casadi as ca
import numpy as np

from jointplay.common import interrupts
from jointplay.common.errors import GeneratedCodeError, SimulationError
from jointplay.sim.events import _EventState
from jointplay.sim.problem import (
    FIXED_BLOCK_STEPS,
    RADAU_NEWTON_TOLERANCE,
    _Accumulated,
    _nearest_contact_joint,
    _Problem,
    _Trajectory,
)

SUBDIVISION = 10
"""A Radau step that fails (its Newton iteration, a non-finite state) is taken as this many."""
MAX_SUBDIVISIONS = 3
"""How many times over a failed step is divided before the run stops (1000 shorter)."""


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
        # CasADi can swallow the KeyboardInterrupt raised inside one of its calls; the
        # interrupt is still recorded, and this loop can run for seconds.
        interrupts.raise_if_interrupted()
        out = step(x, tau[:, 3 * i:3 * i + 3], h, p, v)
        if method == "radau":
            x = out[0]
            newton.append(out[1])
        else:
            x = out
        states.append(x)
        drive = pr.drive_power_casadi(x, tau[:, 3 * i + 2], p, v)
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


@dataclass
class _Block:
    """Consecutive steps from one state, one row per step: the states at the step ends, the
    drive and dissipated powers there, and each joint's penetration and its rate."""

    states: np.ndarray
    powers: np.ndarray
    deltas: np.ndarray
    rates: np.ndarray
    failures: list[str | None]  # per step: why it cannot be accepted, or None

    def replace_from(self, j: int, redone: _Block) -> None:
        """Steps from j on are ``redone``'s."""
        for target, values in zip((self.states, self.powers, self.deltas, self.rates),
                                  (redone.states, redone.powers, redone.deltas, redone.rates),
                                  strict=True):
            target[j:] = values
        self.failures[j:] = redone.failures

    def first_failure(self, i: int) -> int:
        """The first step from i on that failed (the block's length if none did)."""
        return next((k for k in range(i, len(self.failures)) if self.failures[k]),
                    len(self.failures))


@dataclass
class _Accepted:
    """The end of the last accepted step (state, powers, penetrations and rates), and the drive
    work and dissipated energy integrated up to it by the trapezoidal rule."""

    x: np.ndarray
    power: np.ndarray
    delta: np.ndarray
    rate: np.ndarray
    work: float = 0.0
    dissipated: float = 0.0

    def accept(self, h: float, block: _Block, i: int, j: int) -> None:
        """Accept the block's steps i .. j-1."""
        chain = np.vstack([self.power, block.powers[i:j]])
        self.work += 0.5 * h * float(np.sum(chain[:-1, 0] + chain[1:, 0]))
        self.dissipated += 0.5 * h * float(np.sum(chain[:-1, 1] + chain[1:, 1]))
        self.x, self.power = block.states[j - 1], block.powers[j - 1]
        self.delta, self.rate = block.deltas[j - 1], block.rates[j - 1]


class _FixedSteps:
    """Blocks of fixed steps of the scene's method, evaluated in C and checked: a non-finite
    state or an unconverged Newton iteration stops the run with a message."""

    def __init__(self, pr: _Problem, events: _EventState, stats: _Accumulated) -> None:
        run = pr.scene.run
        self.pr, self.events, self.stats = pr, events, stats
        self.method, self.h = run.integrator, run.step
        self.depth = 0  # how many times these steps were divided (see finer)
        self._step = pr.model.casadi_function(f"{self.method}_step")
        m = min(run.steps_per_output, FIXED_BLOCK_STEPS)
        batch = _steps_function(self._step, pr, self.method, m)
        single = _steps_function(self._step, pr, self.method, 1)
        self._batches = {m: batch, 1: single}
        self._fractions = _stage_fractions(self.method)
        newton_iterations = pr.model.layout.functions["radau_step"].newton_iterations
        if newton_iterations is None:  # the generator always records it (derive/codegen.py)
            raise GeneratedCodeError("layout.json gives the radau_step no newton_iterations; "
                                     "regenerate the model with `jointplay derive`")
        self._evals_per_step = 4 if self.method == "rk4" else 3 * (1 + newton_iterations)

    def block(self, state: np.ndarray, t_start: np.ndarray,
              v_imp: np.ndarray | None = None) -> _Block:
        """The steps starting at the times ``t_start``, the first from ``state``, with the
        impact speeds ``v_imp`` (the captured ones by default)."""
        fn = self._batch_of(t_start.size)
        interrupts.raise_if_interrupted()
        out = [np.asarray(o) for o in fn(state, self._stage_torques(t_start), self.h,
                                         self.pr.p, self.events.v_imp if v_imp is None
                                         else v_imp)]
        counts = self.stats.counts
        counts["steps"] += t_start.size
        counts["rhs_evaluations"] += self._evals_per_step * t_start.size
        if self.method == "radau":
            counts["jacobian_evaluations"] += t_start.size
        states = out[0].T
        # A step that failed is reported only if it would be accepted: one computed after an
        # onset with the speed of no impact (or of the last) is redone anyway.
        failures: list[str | None] = [None] * t_start.size
        finite = np.all(np.isfinite(states), axis=1)
        newton = out[4].ravel() if self.method == "radau" else np.zeros(t_start.size)
        limit = RADAU_NEWTON_TOLERANCE * np.max(self.pr.scale)
        for k in np.flatnonzero(~finite | (newton > limit)):
            failures[k] = (
                f"{self.method} at step {self.h:g} s produced a non-finite state: the step "
                "is beyond the method's stability limit for this contact stiffness; reduce "
                f"run.step or use {self.pr.adaptive_fallback}" if not finite[k] else
                f"Radau's Newton iteration did not converge (last update {newton[k]:.3g}); "
                "reduce run.step")
        return _Block(states, out[1].T, out[2].T, out[3].T, failures)

    def finer(self) -> _FixedSteps:
        """These steps, :data:`SUBDIVISION` times shorter (for one step that failed)."""
        finer = copy.copy(self)
        finer.h, finer.depth = self.h / SUBDIVISION, self.depth + 1
        return finer

    def fail(self, block: _Block, j: int, state: np.ndarray, t_start: float) -> NoReturn:
        """Stop the run at step j of ``block`` (which failed), taken from ``state``."""
        why = str(block.failures[j])
        if self.depth:
            why += (f" (the step of {self.h * SUBDIVISION ** self.depth:g} s failed, and so "
                    f"did its parts down to {self.h:g} s)")
        raise SimulationError(t_start, why,
                              _nearest_contact_joint(self.pr, state, self.events.v_imp))

    def approach_speeds(self, accepted: _Accepted) -> np.ndarray:
        """The impact speeds, with every joint out of contact given the speed at which it
        closes at the accepted end: the speed of an impact met within the next step, to
        first order (the captured one belongs to the last impact, or to none)."""
        free = self.events.flags < 0.5
        return np.where(free, np.maximum(accepted.rate, 0.0), self.events.v_imp)

    def _batch_of(self, size: int) -> ca.Function:
        if size not in self._batches:
            self._batches[size] = _steps_function(self._step, self.pr, self.method, size)
        return self._batches[size]

    def _stage_torques(self, t_start: np.ndarray) -> np.ndarray:
        times = (t_start[:, None] + self.h * self._fractions[None, :]).ravel()
        return self.pr.tau(times).T  # (ntau, 3 * steps)


def _run_fixed(pr: _Problem, x0: np.ndarray, traj: _Trajectory, stats: _Accumulated,
               progress: Any) -> None:
    """RK4 or Radau at a fixed step; onsets located by interpolation between step ends."""
    run = pr.scene.run
    events = _EventState(pr, x0, 0.0, traj.impacts)
    steps = _FixedSteps(pr, events, stats)
    x = x0.copy()
    traj.x[0] = x
    traj.v_imp[0] = events.v_imp
    start = pr.contact_at(x, events.v_imp) if pr.nc else {}
    accepted = _Accepted(x, _power_at(pr, events, x, 0.0), start.get("delta", np.zeros(0)),
                         start.get("delta_dot", np.zeros(0)))
    for k in range(run.n_outputs):
        t_start = k * run.output_step + run.step * np.arange(run.steps_per_output)
        # An output interval of many steps is taken in blocks: a call into C is never long
        # enough to hold off Ctrl-C, and the unrolled graph of one block stays small.
        for first in range(0, t_start.size, FIXED_BLOCK_STEPS):
            _advance(steps, accepted, t_start[first:first + FIXED_BLOCK_STEPS])
        traj.x[k + 1] = accepted.x
        traj.work[k + 1] = accepted.work
        traj.dissipated[k + 1] = accepted.dissipated
        traj.v_imp[k + 1] = events.v_imp
        progress.update(1)


def _power_at(pr: _Problem, events: _EventState, state: np.ndarray, t: float) -> np.ndarray:
    """The drive power and the power dissipated in contact at one state."""
    drive = pr.drive_power_at(state, pr.tau(t)[0], events.v_imp)
    diss = float(np.sum(pr.contact_at(state, events.v_imp)["dissipation"])) if pr.nc else 0.0
    return np.array([drive, diss])


def _advance(steps: _FixedSteps, accepted: _Accepted, t_start: np.ndarray) -> None:
    """Take the steps starting at ``t_start``: accept them up to the first whose penetration
    disagrees with a joint's contact flag, switch the flags there, redo the rest with the
    captured impact speed if a contact began, and go on."""
    m = t_start.size
    block = steps.block(accepted.x, t_start)
    i = 0
    while i < m:
        j = min(_first_disagreement(steps.events, block.deltas, i, m), block.first_failure(i))
        if j > i:  # accept steps i .. j-1
            accepted.accept(steps.h, block, i, j)
        if j == m:
            break
        if block.failures[j]:
            _take_failed_step(steps, accepted, float(t_start[j]), block, j)
            i = j + 1
            if i < m:  # the block's later steps followed the failed one: redone
                block.replace_from(i, steps.block(accepted.x, t_start[i:]))
        elif _switch_flags(steps, accepted, block, t_start, j):
            # Steps from j on used a stale impact speed: redo them with the captured one.
            block.replace_from(j, steps.block(accepted.x, t_start[j:]))
            i = j  # step j is accepted by the scan (its flags now agree)
        else:
            accepted.accept(steps.h, block, j, j + 1)
            i = j + 1


def _take_failed_step(steps: _FixedSteps, accepted: _Accepted, t: float, block: _Block,
                      j: int) -> None:
    """Take the step from t that failed as step j of ``block``, or stop the run.

    A step that meets an onset does so with the last impact's speed (or none): under a
    damping law built for low restitution, a slow one makes contact a wall that no Newton
    iteration gets through. Retaken with each free joint's closing speed, the step locates
    its onset and is taken again with the speed captured there. A step that still fails is
    taken as :data:`SUBDIVISION` shorter ones (each of them handled so in turn), at most
    :data:`MAX_SUBDIVISIONS` times over. Radau's failures are its own step's (L-stable, it
    checks its iteration); RK4's non-finite state grew over the steps before, and stops the
    run at once."""
    if steps.method != "radau":
        steps.fail(block, j, accepted.x, t)
    start = np.array([t])
    retaken = steps.block(accepted.x, start, steps.approach_speeds(accepted))
    flags = steps.events.flags > 0.5
    if not retaken.failures[0] and np.any(~flags & (retaken.deltas[0] > 0)):
        _switch_flags(steps, accepted, retaken, start, 0)
        captured = steps.block(accepted.x, start)
        accepted.accept(steps.h, retaken if captured.failures[0] else captured, 0, 1)
        return
    if steps.depth == MAX_SUBDIVISIONS:
        steps.fail(block, j, accepted.x, t)
    finer = steps.finer()
    steps.stats.counts["subdivided_steps"] = steps.stats.counts.get("subdivided_steps", 0) + 1
    _advance(finer, accepted, t + finer.h * np.arange(SUBDIVISION))


def _first_disagreement(events: _EventState, deltas: np.ndarray, i: int, m: int) -> int:
    """The first step from i on where a joint's penetration disagrees with its flag (m if
    none does)."""
    if not events.pr.nc:
        return m
    flags = events.flags > 0.5
    disagree = np.where(flags, deltas[i:] < 0, deltas[i:] > 0)
    rows = np.flatnonzero(disagree.any(axis=1))
    return i + int(rows[0]) if rows.size else m


def _switch_flags(steps: _FixedSteps, accepted: _Accepted, block: _Block, t_start: np.ndarray,
                  j: int) -> bool:
    """Clear the flags of joints that separated at step j and record the onsets there, each
    located by interpolating the penetration between the accepted end and step j's end.
    Returns whether a contact began."""
    events, h = steps.events, steps.h
    delta_j = block.deltas[j]
    flags = events.flags > 0.5
    separated = flags & (delta_j < 0)
    onset = ~flags & (delta_j > 0)
    events.flags[separated] = 0.0
    steps.stats.counts["events"] += int(np.sum(separated) + np.sum(onset))
    delta_prev, rate_prev, x = accepted.delta, accepted.rate, accepted.x
    for c in np.flatnonzero(onset):
        theta = min(max(-delta_prev[c] / (delta_j[c] - delta_prev[c]), 0.0), 1.0)
        events.onset(int(c), float(t_start[j] + theta * h),
                     float(rate_prev[c] + theta * (block.rates[j][c] - rate_prev[c])),
                     x + theta * (block.states[j] - x))
    return bool(np.any(onset))
