"""Simulate a scene: stiff contact integrated with CVODES/IDAS or compiled fixed-step methods.

Impact velocity. The damping of every contact law needs the normal approach speed at the
onset of the current impact, an input of the model per clearance joint. Each joint carries a
contact flag; a quadrature of the indicator "this joint's penetration disagrees with its flag"
(d > 0 while flagged free, d < 0 while flagged in contact) is integrated alongside the state.
Output intervals in which every indicator stays zero are accepted as integrated; in an
interval where one turns positive, the first transition is located by bisection on the
integration end time to ``EVENT_TIME_TOLERANCE``, the flag flips there, an onset captures the
approach speed d'(t*) and is recorded, and integration restarts from the event. Penetration is
used, not its sign-crossings: CVODES's own event support (CasADi 3.8, experimental) finds a
crossing only within the integrator's last internal step and fails at stiff contact onsets.

State scaling. Angles are O(1) and eccentricities O(clearance); the integrators see
eccentricities in units of their joint's radial clearance (rates in clearance per ms), so one
absolute tolerance means the same for both.

Energy. The drive work (sum of tau_i dq_i/dt) and the energy taken out by contact damping and
friction are integrated as quadratures, so the balance
E(t) - E(0) - W_drive(t) + D(t) = 0 checks a run at every output sample.
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import casadi as ca
import numpy as np

from jointplay.errors import SimulationError
from jointplay.model import FastFunction, Model
from jointplay.results import Impacts, SimulationResult
from jointplay.scene import ADAPTIVE, Scene, ideal_counterpart

# Onsets are located to this many seconds: at 1 m/s the journal moves 1 nm in that time.
EVENT_TIME_TOLERANCE = 1e-9
# ... or once the penetration is within this fraction of the radial clearance of zero.
GAP_TOLERANCE = 1e-4
# Output intervals integrated per call of the adaptive integrators, at most: a call restarts
# the integrator, and what follows an event in a call is integrated again, so calls start at
# one interval after an event and double while none occurs.
CHUNK_OUTPUTS = 512
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


def _scaling(model: Model, p: np.ndarray) -> np.ndarray:
    """Per-state scale: 1 for angles, the joint's radial clearance for eccentricities."""
    scale = np.ones(model.n_state)
    n = model.n_coordinates
    for i, name in enumerate(model.coordinates):
        if name.startswith(("ex", "ey")):
            j = int(name[2:])
            rb = p[model.parameters.index(f"joint{j}.bearing_radius")]
            rj = p[model.parameters.index(f"joint{j}.journal_radius")]
            scale[i] = rb - rj
            scale[n + i] = (rb - rj) / RATE_SCALE_TIME
    return scale


class _Problem:
    """The compiled model, a parameter vector and torque functions, ready to integrate."""

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
        self.gap_tolerance = GAP_TOLERANCE * np.asarray(clearances, dtype=float)

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


class _AdaptiveIntegrator:
    """CVODES or IDAS over time-normalised intervals, with the event quadratures."""

    def __init__(self, problem: _Problem, plugin: str, rtol: float, atol: float,
                 max_steps: int) -> None:
        self.problem = problem
        self.plugin = plugin
        pr = problem
        model = pr.model
        z = ca.MX.sym("z", pr.nx)
        s = ca.MX.sym("s")
        p = ca.MX.sym("p", len(model.parameters))
        v_imp = ca.MX.sym("v_imp", pr.nc)
        flags = ca.MX.sym("in_contact", pr.nc)
        t0 = ca.MX.sym("t0")
        span = ca.MX.sym("span")
        hold = ca.MX.sym("u_hold", len(model.torque_joints))
        scale = ca.DM(pr.scale)
        x = z * scale
        t = t0 + s * span
        tau = pr.tau_casadi(t) + hold
        xdot = model.casadi_function("forward_dynamics")(x, tau, p, v_imp)
        drive_power = sum((tau[k] * x[pr.n + i] for k, i in enumerate(pr.angle_index)),
                          ca.MX(0))
        quad = []
        dissipation = ca.MX(0)
        if pr.nc:
            contact = model.casadi_function("contact")(x, p, v_imp)
            names = model.casadi_function("contact").name_out()
            delta = contact[names.index("delta")]
            dissipation = ca.sum1(contact[names.index("dissipation")])
            quad.append(ca.if_else(flags > 0.5, delta < 0, delta > 0))
        quad += [drive_power, dissipation]
        dae = {"x": z, "t": s, "p": ca.vertcat(p, v_imp, flags, t0, span, hold),
               "ode": span * xdot / scale, "quad": span * ca.vertcat(*quad)}
        self.dae = dae
        self.options = {"reltol": rtol, "abstol": atol, "max_num_steps": max_steps}
        self._cache: dict[int, FastFunction] = {}
        self._jacobian_calls: dict[int, int] = {}

    def _integrator(self, intervals: int) -> FastFunction:
        """The integrator over ``intervals`` outputs, bound to buffers: a call through them
        costs about half of one with numpy arrays, and runs sit on many short calls."""
        if intervals not in self._cache:
            grid = np.linspace(0.0, 1.0, intervals + 1)[1:]
            self._cache[intervals] = FastFunction(ca.integrator(
                f"{self.plugin}_{intervals}", self.plugin, self.dae, 0.0, grid, self.options))
        return self._cache[intervals]

    def run(self, x0: np.ndarray, t0: float, span: float, intervals: int, v_imp: np.ndarray,
            flags: np.ndarray, stats: _Accumulated) -> tuple[np.ndarray, np.ndarray]:
        """States (intervals, nx) and cumulative quadratures (intervals, nq) at the ends of
        ``intervals`` equal sub-intervals of [t0, t0 + span]."""
        pr = self.problem
        fast = self._integrator(intervals)
        integ = fast.function
        fast.inputs[integ.index_in("x0")][:] = x0 / pr.scale
        fast.inputs[integ.index_in("p")][:] = np.concatenate(
            [pr.p, v_imp, flags, [t0, span], pr.u_hold])
        try:
            fast.trigger()
        except RuntimeError as err:
            raise _integration_failure(self.plugin, t0, span, str(err), pr, x0, v_imp) \
                from None
        finally:
            # CVODES's counters restart with each call; CasADi's call counters accumulate
            # over the life of the buffer, so those are differenced.
            current = fast.stats()
            jac_calls = int(current.get("n_call_jacF", 0))
            current["n_call_jacF"] = jac_calls - self._jacobian_calls.get(intervals, 0)
            self._jacobian_calls[intervals] = jac_calls
            stats.add(current)
        out = {"xf": fast.outputs[integ.index_out("xf")].reshape((pr.nx, intervals),
                                                                 order="F"),
               "qf": fast.outputs[integ.index_out("qf")].reshape((-1, intervals), order="F")}
        xs = np.asarray(out["xf"]).T * pr.scale
        qs = np.asarray(out["qf"]).T
        if not (np.all(np.isfinite(xs)) and np.all(np.isfinite(qs))):
            bad = int(np.argmax(~np.all(np.isfinite(xs), axis=1)))
            raise SimulationError(t0 + span * (bad + 1) / intervals,
                                  "the state stopped being finite (NaN or Inf); tighten "
                                  "run.rtol / run.atol or check the parameters",
                                  _nearest_contact_joint(pr, x0, v_imp))
        return xs, qs


def _nearest_contact_joint(pr: _Problem, x: np.ndarray, v_imp: np.ndarray) -> int | None:
    if not pr.nc or not np.all(np.isfinite(x)):
        return None
    delta = pr.contact_at(x, v_imp)["delta"]
    return int(pr.model.clearance_joints[int(np.argmax(delta))])


def _integration_failure(plugin: str, t0: float, span: float, message: str, pr: _Problem,
                         x0: np.ndarray, v_imp: np.ndarray) -> SimulationError:
    flag = message.rsplit("returned", 1)[-1].split(".")[0].strip(' "') if "returned" in message \
        else message.splitlines()[-1][:200]
    advice = {
        "CV_TOO_MUCH_WORK": "too many steps between outputs: raise run.max_steps or relax "
                            "run.rtol / run.atol",
        "IDA_TOO_MUCH_WORK": "too many steps between outputs: raise run.max_steps or relax "
                             "run.rtol / run.atol",
    }.get(flag.strip('"'), "the step size collapsed (error test or Newton failures "
                           "repeated); the contact may be too stiff for the tolerances, or "
                           "the motion has diverged: relax run.rtol / run.atol, or check the "
                           "parameters")
    return SimulationError(t0, f"{plugin} failed in [{t0:.9g}, {t0 + span:.9g}] s "
                               f"({flag}): {advice}",
                           _nearest_contact_joint(pr, x0, v_imp))


@dataclass
class _Trajectory:
    """Outputs filled in sample by sample."""

    x: np.ndarray
    v_imp: np.ndarray
    work: np.ndarray
    dissipated: np.ndarray
    impacts: list[tuple[float, int, float, float, float]] = field(default_factory=list)


class _EventState:
    """Contact flags and captured impact speeds of every clearance joint."""

    def __init__(self, pr: _Problem, x0: np.ndarray, t0: float,
                 impacts: list[tuple[float, int, float, float, float]]) -> None:
        self.pr = pr
        self.flags = np.zeros(pr.nc)
        self.v_imp = np.zeros(pr.nc)
        self.impacts = impacts
        if pr.nc:
            c = pr.contact_at(x0, self.v_imp)
            for i in np.flatnonzero(c["delta"] > 0):
                self.onset(int(i), t0, float(c["delta_dot"][i]), x0)

    def onset(self, i: int, t: float, speed: float, x: np.ndarray) -> None:
        """Joint i (index into the clearance joints) comes into contact at state x."""
        self.flags[i] = 1.0
        self.v_imp[i] = speed
        joint = int(self.pr.model.clearance_joints[i])
        ex, ey = (float(x[self.pr.model.coordinates.index(f"{axis}{joint}")])
                  for axis in ("ex", "ey"))
        self.impacts.append((t, joint, speed, ex, ey))

    def gap(self, x: np.ndarray) -> np.ndarray:
        """Per joint: > 0 where the penetration disagrees with the joint's flag."""
        delta = self.pr.contact_at(x, self.v_imp)["delta"]
        return np.where(self.flags > 0.5, -delta, delta)

    def switch(self, x: np.ndarray, t: float, joints: np.ndarray) -> None:
        """Flip the flags of ``joints`` (indices into the clearance joints) at state x."""
        c = self.pr.contact_at(x, self.v_imp)
        for i in joints:
            i = int(i)
            if self.flags[i] < 0.5:
                self.onset(i, t, float(c["delta_dot"][i]), x)
            else:
                self.flags[i] = 0.0


def _initial_state(model: Model, scene: Scene) -> np.ndarray:
    x0 = np.zeros(model.n_state)
    n = model.n_coordinates
    for key, value in scene.initial.items():
        if key.startswith("d") and key[1:] in model.coordinates:
            x0[n + model.coordinates.index(key[1:])] = value
        elif key in model.coordinates:
            x0[model.coordinates.index(key)] = value
    return x0


def _run_adaptive(pr: _Problem, x0: np.ndarray, traj: _Trajectory, stats: _Accumulated,
                  progress: Any) -> None:
    run = pr.scene.run
    integ = _AdaptiveIntegrator(pr, run.integrator, run.rtol, run.atol, run.max_steps)
    dt = run.output_step
    n_out = run.n_outputs
    events = _EventState(pr, x0, 0.0, traj.impacts)
    nc = pr.nc
    k = 0
    x = x0.copy()
    traj.x[0] = x
    traj.v_imp[0] = events.v_imp
    chunk = 1 if nc else n_out  # without clearance nothing can interrupt a call
    while k < n_out:
        m = min(chunk, n_out - k)
        xs, qs = integ.run(x, k * dt, m * dt, m, events.v_imp, events.flags, stats)
        hits = np.flatnonzero(np.any(qs[:, :nc] > 0, axis=1)) if nc else np.array([], int)
        accept = int(hits[0]) if hits.size else m
        for j in range(accept):
            traj.x[k + j + 1] = xs[j]
            traj.work[k + j + 1] = traj.work[k] + qs[j, nc]
            traj.dissipated[k + j + 1] = traj.dissipated[k] + qs[j, nc + 1]
            traj.v_imp[k + j + 1] = events.v_imp
        if accept:
            x = xs[accept - 1]
            k += accept
            progress.update(accept)
        if accept < m:
            x = _resolve_interval(integ, pr, x, k * dt, dt, events, traj, k, stats)
            k += 1
            progress.update(1)
            chunk = 1
        else:
            chunk = min(2 * chunk, CHUNK_OUTPUTS)


def _resolve_interval(integ: _AdaptiveIntegrator, pr: _Problem, x: np.ndarray, ta: float,
                      dt: float, events: _EventState, traj: _Trajectory, k: int,
                      stats: _Accumulated) -> np.ndarray:
    """Integrate [ta, ta + dt] through every contact transition in it; store sample k+1."""
    nc = pr.nc
    tb = ta + dt
    t_cur, x_cur = ta, x
    work, dissipated = traj.work[k], traj.dissipated[k]
    for _ in range(MAX_EVENTS_PER_OUTPUT):
        xs, qs = integ.run(x_cur, t_cur, tb - t_cur, 1, events.v_imp, events.flags, stats)
        if not np.any(qs[0, :nc] > 0):
            traj.x[k + 1] = xs[0]
            traj.work[k + 1] = work + qs[0, nc]
            traj.dissipated[k + 1] = dissipated + qs[0, nc + 1]
            traj.v_imp[k + 1] = events.v_imp
            return xs[0]
        # Locate the first transition in (t_cur, tb]: Illinois regula falsi on the gap of
        # the joints that crossed, bisection when the crossing came and went inside.
        lo, x_lo = t_cur, x_cur
        hi, x_hi, q_hi = tb, xs[0], qs[0]
        g_lo, g_hi = events.gap(x_lo), events.gap(x_hi)
        kept = 0  # +1 / -1: how many times in a row lo / hi stayed put
        while hi - lo > EVENT_TIME_TOLERANCE:
            crossed = g_hi > 0
            if np.any(crossed) and np.all(g_hi[crossed] < pr.gap_tolerance[crossed]):
                break
            if np.any(crossed):
                lo_weight = 0.5 if kept >= 2 else 1.0
                hi_weight = 0.5 if kept <= -2 else 1.0
                a, b = lo_weight * g_lo[crossed], hi_weight * g_hi[crossed]
                frac = float(np.min(-a / np.maximum(b - a, 1e-300)))
                frac = min(max(frac, 0.01), 0.99)
            else:
                frac = 0.5
            mid = lo + frac * (hi - lo)
            xm, qm = integ.run(x_lo, lo, mid - lo, 1, events.v_imp, events.flags, stats)
            if np.any(qm[0, :nc] > 0):
                hi, x_hi, q_hi, g_hi = mid, xm[0], qm[0], events.gap(xm[0])
                kept = kept + 1 if kept > 0 else 1
            else:
                work += qm[0, nc]
                dissipated += qm[0, nc + 1]
                lo, x_lo, g_lo = mid, xm[0], events.gap(xm[0])
                kept = kept - 1 if kept < 0 else -1
        work += q_hi[nc]
        dissipated += q_hi[nc + 1]
        events.switch(x_hi, hi, np.flatnonzero(q_hi[:nc] > 0))
        stats.counts["events"] += 1
        t_cur, x_cur = hi, x_hi
        if t_cur >= tb:
            traj.x[k + 1] = x_cur
            traj.work[k + 1] = work
            traj.dissipated[k + 1] = dissipated
            traj.v_imp[k + 1] = events.v_imp
            return x_cur
    raise SimulationError(ta, f"more than {MAX_EVENTS_PER_OUTPUT} contact transitions in one "
                          "output interval (contact chatter); raise "
                          "contact.impact_speed_floor or tighten the tolerances",
                          _nearest_contact_joint(pr, x, events.v_imp))


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
    newton_iterations = pr.model.layout.data["functions"]["radau_step"]["newton_iterations"]
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


# ---- post-processing ------------------------------------------------------------------------

def _mapped(model: Model, name: str, columns: Sequence[np.ndarray]) -> list[np.ndarray]:
    """Evaluate a compiled function on many samples at once (inputs as columns)."""
    fn = model.casadi_function(name)
    n = columns[0].shape[1] if columns[0].ndim == 2 else 1
    out = fn.map(n)(*columns)
    out = out if isinstance(out, (list, tuple)) else [out]
    return [np.asarray(o) for o in out]


def _assemble(pr: _Problem, traj: _Trajectory, t: np.ndarray, stats: dict[str, Any],
              wall: float, ideal: SimulationResult | None) -> SimulationResult:
    model, p, n, nc = pr.model, pr.p, pr.n, pr.nc
    xs = traj.x.T
    tau = pr.tau(t)
    ps = np.repeat(p[:, None], t.size, axis=1)
    vs = traj.v_imp.T
    xdot = _mapped(model, "forward_dynamics", [xs, tau.T, ps, vs])[0]
    udot = xdot[n:].T
    tip = _mapped(model, "end_effector", [xs, udot.T, ps])
    energy_parts = _mapped(model, "energy", [xs, ps])
    energy = {name: energy_parts[i].ravel()
              for i, name in enumerate(("kinetic", "gravity", "contact", "total"))}
    energy["drive_work"] = traj.work.copy()
    energy["dissipated"] = traj.dissipated.copy()
    energy["balance"] = energy["total"] - energy["total"][0] - traj.work + traj.dissipated
    if nc:
        c = _mapped(model, "contact", [xs, ps, vs])
        names = model.casadi_function("contact").name_out()
        get = {name: c[i].T for i, name in enumerate(names)}
        ecc = np.stack([traj.x[:, [model.coordinates.index(f"ex{j}"),
                                   model.coordinates.index(f"ey{j}")]]
                        for j in model.clearance_joints], axis=1)
        clearance = np.array([p[model.parameters.index(f"joint{j}.bearing_radius")]
                              - p[model.parameters.index(f"joint{j}.journal_radius")]
                              for j in model.clearance_joints])
        contact_force = np.stack([get["f_x"], get["f_y"]], axis=2)
    else:
        zeros = np.zeros((t.size, 0))
        get = {k: zeros for k in ("delta", "delta_dot", "f_n", "f_t", "v_t")}
        ecc = np.zeros((t.size, 0, 2))
        clearance = np.zeros(0)
        contact_force = np.zeros((t.size, 0, 2))
    impacts = traj.impacts
    stats = {**stats, "impacts": len(impacts), "wall_time_s": wall,
             "realtime_factor": wall / float(t[-1]) if t[-1] > 0 else math.nan}
    return SimulationResult(
        scene_name=pr.scene.name,
        integrator=pr.scene.run.integrator,
        t=t,
        coordinate_names=list(model.coordinates),
        q=traj.x[:, :n].copy(),
        u=traj.x[:, n:].copy(),
        udot=udot,
        tau=tau,
        torque_joints=list(model.torque_joints),
        tip_position=tip[0].T,
        tip_velocity=tip[1].T,
        tip_acceleration=tip[2].T,
        clearance_joints=list(model.clearance_joints),
        radial_clearance=clearance,
        eccentricity=ecc,
        penetration=get["delta"],
        penetration_rate=get["delta_dot"],
        normal_force=get["f_n"],
        friction_force=get["f_t"],
        contact_force=contact_force,
        sliding_speed=get["v_t"],
        impacts=Impacts(time=np.array([i[0] for i in impacts], float),
                        joint=np.array([i[1] for i in impacts], int),
                        speed=np.array([i[2] for i in impacts], float),
                        eccentricity=np.array([i[3:] for i in impacts], float).reshape(-1, 2)),
        energy=energy,
        parameter_names=list(model.parameters),
        parameters=p.copy(),
        stats=stats,
        metadata=_metadata(pr),
        ideal=ideal,
    )


def _metadata(pr: _Problem) -> dict[str, Any]:
    from importlib.metadata import version

    scene = pr.scene
    return {
        "scene": scene.text,
        "scene_source": scene.source or "",
        "torques": dict(scene.torque_text),
        "run": {k: getattr(scene.run, k) for k in ("t_end", "output_step", "integrator",
                                                    "rtol", "atol", "step", "max_steps")},
        "model_input_hash": pr.model.layout.input_hash,
        "model_name": pr.model.name,
        "versions": {pkg: version(pkg) for pkg in ("jointplay", "casadi", "numpy")},
    }


# ---- public entry point ---------------------------------------------------------------------

def _parameter_vector(model: Model, scene: Scene,
                      parameters: Mapping[str, float] | Sequence[float] | None) -> np.ndarray:
    defaults = np.asarray(scene.robot.parameter_values(), dtype=float)
    if parameters is None:
        return defaults
    if isinstance(parameters, Mapping):
        vec = defaults.copy()
        for name, value in parameters.items():
            if name not in model.parameters:
                import difflib

                close = difflib.get_close_matches(name, model.parameters, n=1)
                hint = f"; did you mean {close[0]!r}?" if close else ""
                raise KeyError(f"{name!r} is not a parameter of this model{hint}")
            vec[model.parameters.index(name)] = float(value)
        return vec
    return model.parameter_vector(parameters)


def load_scene_model(scene: Scene, *, ideal: bool = False) -> Model:
    """The compiled model of the scene's robot (or of its ideal-joint counterpart).

    A model already generated (checked in, or in the cache) is loaded without sympy; a new
    structure is derived once.
    """
    from jointplay.derive import model_for

    robot = ideal_counterpart(scene.robot) if ideal else scene.robot
    return model_for(robot)


def simulate(scene: Scene, *, model: Model | None = None,
             parameters: Mapping[str, float] | Sequence[float] | None = None,
             compare_ideal: bool = False, quiet: bool = True) -> SimulationResult:
    """Simulate ``scene`` and return every output as numpy arrays.

    ``parameters`` overrides numbers of the scene's robot by name (``{"friction.mu": 0.1}``)
    or replaces the whole vector; this never recompiles. ``compare_ideal`` also simulates the
    same scene with ideal joints (``result.ideal``). Raises :class:`SimulationError` with the
    time, the joint and the cause when the integration cannot go on.
    """
    from tqdm import tqdm

    model = model or load_scene_model(scene)
    p = _parameter_vector(model, scene, parameters)
    ideal_result = None
    if compare_ideal:
        ideal_scene = scene.with_robot(ideal_counterpart(scene.robot))
        ideal_model = load_scene_model(scene, ideal=True)
        ideal_params = None
        if isinstance(parameters, Mapping):
            ideal_params = {k: v for k, v in parameters.items()
                            if k in ideal_model.parameters}
        ideal_result = simulate(ideal_scene, model=ideal_model,
                                parameters=ideal_params, quiet=quiet)
    pr = _Problem(model, scene, p)
    run = scene.run
    n_out = run.n_outputs
    t = np.arange(n_out + 1) * run.output_step
    traj = _Trajectory(x=np.zeros((n_out + 1, model.n_state)),
                       v_imp=np.zeros((n_out + 1, pr.nc)),
                       work=np.zeros(n_out + 1), dissipated=np.zeros(n_out + 1))
    x0 = _initial_state(model, scene)
    stats = _Accumulated()
    start = time.perf_counter()
    with tqdm(total=n_out, disable=quiet, delay=2.0, unit="out", leave=False,
              desc=f"{scene.name} ({run.integrator})") as progress:
        if run.integrator in ADAPTIVE:
            _run_adaptive(pr, x0, traj, stats, progress)
        else:
            _run_fixed(pr, x0, traj, stats, progress)
    wall = time.perf_counter() - start
    counts: dict[str, Any] = dict(stats.counts)
    return _assemble(pr, traj, t, counts, wall, ideal_result)


class Stepper:
    """The scene's robot advanced one sample at a time, with torques added and held (ZOH).

    For closed-loop control and identification: ``step(u)`` integrates one sample period with
    the scene's own torques plus ``u`` held constant, through contact events exactly as
    :func:`simulate` does (adaptive integrators only), and returns the new state.
    """

    def __init__(self, scene: Scene, *, model: Model | None = None,
                 parameters: Mapping[str, float] | Sequence[float] | None = None,
                 sample_time: float | None = None) -> None:
        run = scene.run
        if run.integrator not in ADAPTIVE:
            raise ValueError(f"Stepper needs an adaptive integrator ({', '.join(ADAPTIVE)}), "
                             f"got {run.integrator!r}")
        self.model = model or load_scene_model(scene)
        self.scene = scene
        self._pr = _Problem(self.model, scene, _parameter_vector(self.model, scene, parameters))
        self._integ = _AdaptiveIntegrator(self._pr, run.integrator, run.rtol, run.atol,
                                          run.max_steps)
        self.sample_time = float(sample_time or run.output_step)
        self.stats = _Accumulated()
        self.reset()

    @property
    def parameters(self) -> np.ndarray:
        return self._pr.p

    def reset(self, x0: np.ndarray | None = None) -> None:
        """Back to t = 0 at ``x0`` (default: the scene's initial state)."""
        self.t = 0.0
        self.x = (np.asarray(x0, dtype=float).copy() if x0 is not None
                  else _initial_state(self.model, self.scene))
        self.impacts: list[tuple[float, int, float, float, float]] = []
        self._events = _EventState(self._pr, self.x, 0.0, self.impacts)
        self.work = 0.0
        self.dissipated = 0.0

    def step(self, u: Sequence[float] | np.ndarray) -> np.ndarray:
        """Advance one sample with the added torques ``u`` (one per driven joint, N m)."""
        pr = self._pr
        pr.u_hold[:] = np.asarray(u, dtype=float)
        traj = _Trajectory(x=np.zeros((2, pr.nx)), v_imp=np.zeros((2, pr.nc)),
                           work=np.array([self.work, 0.0]),
                           dissipated=np.array([self.dissipated, 0.0]), impacts=self.impacts)
        self.x = _resolve_interval(self._integ, pr, self.x, self.t, self.sample_time,
                                   self._events, traj, 0, self.stats)
        self.t += self.sample_time
        self.work, self.dissipated = float(traj.work[1]), float(traj.dissipated[1])
        return self.x

    def end_effector(self) -> dict[str, np.ndarray]:
        """Tip position, velocity and acceleration at the current state and held torque."""
        pr = self._pr
        xdot = self.model.forward_dynamics(self.x, pr.tau(self.t)[0], pr.p,
                                           self._events.v_imp)
        return self.model.end_effector(self.x, xdot[pr.n:], pr.p)
