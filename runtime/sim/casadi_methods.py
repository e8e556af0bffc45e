"""CVODES and IDAS through CasADi, with the contact events located from Python.

The reference route (``run.integrator = "cvodes"`` or ``"idas"``): SUNDIALS's own solvers,
independent of jointplay's compiled BDF, used to cross-check it. Each contact flag has a
quadrature of the indicator "this joint's penetration disagrees with its flag"; output
intervals where every indicator stays zero are accepted, and in one where one does not, the
first transition is located by Illinois regula falsi on the penetration (to
tolerances that follow rtol and atol, see ``jointplay.sim.problem``), the flag flips there and the
integration restarts from the event. CasADi 3.8's own event support finds a crossing only
within the integrator's last internal step and failed at stiff contact onsets.
"""

from __future__ import annotations

import contextlib
import io
import sys
from collections.abc import Iterator
from typing import Any

import casadi as ca
import numpy as np

from jointplay.common import interrupts
from jointplay.common.errors import SimulationError
from jointplay.sim.events import _EventState
from jointplay.sim.problem import (
    CHUNK_OUTPUTS,
    MAX_EVENTS_PER_OUTPUT,
    _Accumulated,
    _nearest_contact_joint,
    _Problem,
    _Trajectory,
)
from jointplay.store.model import FastFunction


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
        drive_power = pr.drive_power_casadi(x, tau, p, v_imp)
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
            with _solver_messages():
                fast.trigger()
        except RuntimeError as err:
            if "KeyboardInterrupt" in str(err):  # CasADi's word for Ctrl-C in a callback
                raise KeyboardInterrupt from None
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



@contextlib.contextmanager
def _solver_messages() -> Iterator[None]:
    """SUNDIALS's messages, printed through CasADi to ``sys.stderr``, held during a call and
    passed on after it, except after Ctrl-C: then they only repeat the interrupt ("rhsQ
    failed: KeyboardInterrupt", "the quadrature right-hand side routine failed"), and an
    interrupted command prints one line."""
    held, real = io.StringIO(), sys.stderr
    sys.stderr = held
    try:
        yield
    finally:
        sys.stderr = real
        text = held.getvalue()
        if text and not interrupts.interrupted() and "KeyboardInterrupt" not in text:
            real.write(text)


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
        while hi - lo > pr.event_time_tolerance:
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


