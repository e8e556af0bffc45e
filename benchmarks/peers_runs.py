"""How the peers benchmark runs and scores every code: trajectories and error measures, the
event-driven LSODA driver the peers share (see peers.py), CPU timing, and the pairing of each
peer run with the jointplay run of nearest accuracy."""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from peers_rhs import PeerRhs

from jointplay.bench import final_state_error, run_counts, state_scale, timed_runs, tip_errors

REFERENCE_RTOL = 1e-10


# ---- trajectories and errors ----------------------------------------------------------------


@dataclass
class Trajectory:
    """What the error measures need, in the attribute names of a SimulationResult."""

    t: np.ndarray
    q: np.ndarray
    u: np.ndarray
    tip_position: np.ndarray
    tip_velocity: np.ndarray
    tip_acceleration: np.ndarray
    coordinate_names: list[str]
    clearance_joints: list[int]
    radial_clearance: np.ndarray
    stats: dict[str, Any] = field(default_factory=dict)


def initial_state(model: Any, scene: Any) -> np.ndarray:
    """The scene's initial state in the model's order (coordinates, then speeds)."""
    n = model.n_coordinates
    x0 = np.zeros(2 * n)
    for key, value in scene.initial.items():
        if key in model.coordinates:
            x0[model.coordinates.index(key)] = value
        elif key.startswith("d") and key[1:] in model.coordinates:
            x0[n + model.coordinates.index(key[1:])] = value
    return x0


def prefix(result: Any, samples: int) -> Trajectory:
    """The first ``samples`` output samples of a result (a shorter horizon of the same run)."""
    return Trajectory(t=result.t[:samples], q=result.q[:samples], u=result.u[:samples],
                      tip_position=result.tip_position[:samples],
                      tip_velocity=result.tip_velocity[:samples],
                      tip_acceleration=result.tip_acceleration[:samples],
                      coordinate_names=list(result.coordinate_names),
                      clearance_joints=list(result.clearance_joints),
                      radial_clearance=np.asarray(result.radial_clearance),
                      stats=dict(result.stats))


def errors(traj: Any, reference: Any) -> dict[str, float]:
    return {**tip_errors(traj, reference), "err_final_state": final_state_error(traj, reference)}


def trajectory_from_states(model: Any, p: np.ndarray, t: np.ndarray, xs: np.ndarray,
                           xdots: np.ndarray, clearance: np.ndarray) -> Trajectory:
    """Tip kinematics of states computed elsewhere (accelerations from that code's own rhs)."""
    n = model.n_coordinates
    ee = model.function("end_effector")
    tips = np.zeros((3, t.size, 2))
    for i in range(t.size):
        out = ee(xs[i], xdots[i, n:], p)
        for j in range(3):
            tips[j, i] = out[j]
    return Trajectory(t=t, q=xs[:, :n].copy(), u=xs[:, n:].copy(), tip_position=tips[0],
                      tip_velocity=tips[1], tip_acceleration=tips[2],
                      coordinate_names=list(model.coordinates),
                      clearance_joints=list(model.clearance_joints), radial_clearance=clearance)


# ---- the event-driven LSODA driver shared by the peers ------------------------------------------


class ContactGeometry:
    """Penetration and its rate per clearance joint, from the state alone."""

    def __init__(self, model: Any, p: np.ndarray) -> None:
        n = model.n_coordinates
        self.ix = [model.coordinates.index(f"ex{j}") for j in model.clearance_joints]
        self.iy = [model.coordinates.index(f"ey{j}") for j in model.clearance_joints]
        self.n = n
        self.c = np.array([p[model.parameters.index(f"joint{j}.bearing_radius")]
                           - p[model.parameters.index(f"joint{j}.journal_radius")]
                           for j in model.clearance_joints])

    def delta(self, x: np.ndarray, i: int) -> float:
        return math.hypot(x[self.ix[i]], x[self.iy[i]]) - float(self.c[i])

    def delta_dot(self, x: np.ndarray, i: int) -> float:
        ex, ey = x[self.ix[i]], x[self.iy[i]]
        e = max(math.hypot(ex, ey), 1e-300)
        return float((ex * x[self.n + self.ix[i]] + ey * x[self.n + self.iy[i]]) / e)


@dataclass
class EventRun:
    xs: np.ndarray  # (samples, nx)
    v_imp: np.ndarray  # (samples, nc), the impact speeds in force at each sample
    nfev: int
    njev: int
    steps: int
    events: int
    impacts: int


def _contact_event(geometry: ContactGeometry, i: int, in_contact: bool
                   ) -> Callable[[float, np.ndarray], float]:
    """The terminal event of joint ``i``'s next transition: penetration crossing zero upwards
    while free, or downwards while in contact."""
    def event(_t: float, y: np.ndarray) -> float:
        d = geometry.delta(y, i)
        return -d if in_contact else d
    event.terminal = True  # type: ignore[attr-defined]
    event.direction = 1.0  # type: ignore[attr-defined]
    return event


def _first_event(sol: Any, nc: int) -> tuple[int, float, np.ndarray]:
    """The joint whose transition came first, its time and the state there."""
    fired = [i for i in range(nc) if sol.t_events[i].size]
    te = min(float(sol.t_events[i][0]) for i in fired)
    i = next(i for i in fired if float(sol.t_events[i][0]) == te)
    return i, te, np.asarray(sol.y_events[i][0], dtype=float)


def integrate_with_impacts(rhs: Callable[[float, np.ndarray, np.ndarray], np.ndarray],
                           x0: np.ndarray, grid: np.ndarray, geometry: ContactGeometry,
                           rtol: float, atol: np.ndarray, max_events: int = 100_000
                           ) -> EventRun:
    """LSODA through ``solve_ivp``, stopping at every contact transition (see the module
    docstring); ``rhs(t, x, v_imp)`` is the code under test."""
    from scipy.integrate import solve_ivp

    nc = geometry.c.size
    flags = np.array([geometry.delta(x0, i) > 0 for i in range(nc)], dtype=bool)
    v_imp = np.array([geometry.delta_dot(x0, i) if flags[i] else 0.0 for i in range(nc)])
    xs = np.zeros((grid.size, x0.size))
    vs = np.zeros((grid.size, nc))
    xs[0], vs[0] = x0, v_imp
    nfev = njev = steps = events = 0
    impacts = int(flags.sum())
    t, x, k = float(grid[0]), x0.copy(), 1  # k: next output sample to fill
    while k < grid.size:
        evs = [_contact_event(geometry, i, bool(flags[i])) for i in range(nc)]
        current = v_imp.copy()
        sol = solve_ivp(lambda tt, y, v=current: rhs(tt, y, v), (t, float(grid[-1])), x,
                        method="LSODA", t_eval=grid[k:], events=evs or None, rtol=rtol,
                        atol=atol)
        if sol.status == -1:
            raise RuntimeError(f"LSODA failed at t = {sol.t[-1] if sol.t.size else t:.6g} s: "
                               f"{sol.message}")
        nfev += int(sol.nfev)
        njev += int(sol.njev)
        steps += int(getattr(sol, "nsteps", 0) or 0)
        filled = np.asarray(sol.t, dtype=float).size  # a list when no sample was reached
        if filled:
            xs[k:k + filled] = np.asarray(sol.y, dtype=float).T
            vs[k:k + filled] = current
        k += filled
        if sol.status != 1:
            break
        i, t, x = _first_event(sol, nc)
        events += 1
        if flags[i]:
            flags[i] = False
        else:
            flags[i] = True
            v_imp[i] = geometry.delta_dot(x, i)
            impacts += 1
        if events > max_events:
            raise RuntimeError(f"more than {max_events} contact transitions")
        if k < grid.size and grid[k] <= t:  # an output sample exactly at the event
            xs[k], vs[k] = x, v_imp
            k += 1
    return EventRun(xs=xs, v_imp=vs, nfev=nfev, njev=njev, steps=steps, events=events,
                    impacts=impacts)


# ---- timing helpers ------------------------------------------------------------------------------


def cpu_runs(fn: Callable[[], Any], repeats: int) -> tuple[Any, list[float]]:
    out, cpu = None, []
    for _ in range(max(1, repeats)):
        c0 = time.process_time()
        out = fn()
        cpu.append(time.process_time() - c0)
    return out, cpu


def spread(cpu: Sequence[float]) -> dict[str, float]:
    return {"cpu_median_s": statistics.median(cpu), "cpu_min_s": min(cpu),
            "cpu_max_s": max(cpu), "repeats": len(cpu)}


# ---- (a), (b): peers on the clearance model ---------------------------------------------------


def run_peer(peer: PeerRhs, model: Any, scene: Any, reference: Any, rtol: float,
             repeats: int) -> dict[str, Any]:
    p = model.parameter_vector()
    grid = np.arange(scene.run.n_outputs + 1) * scene.run.output_step
    geometry = ContactGeometry(model, p)
    scale = state_scale(reference)
    x0 = initial_state(model, scene)

    def once() -> EventRun:
        return integrate_with_impacts(peer.rhs, x0, grid, geometry, rtol, rtol * scale)

    try:
        run, cpu = cpu_runs(once, repeats)
    except RuntimeError as err:
        return {"code": peer.name, "rtol": rtol, "t_end": scene.run.t_end, "status": "failed",
                "note": str(err)}
    xdots = np.array([peer.rhs(float(t), run.xs[i], run.v_imp[i]) for i, t in enumerate(grid)])
    traj = trajectory_from_states(model, p, grid, run.xs, xdots, geometry.c)
    return {"code": peer.name, "rtol": rtol, "t_end": scene.run.t_end, "status": "ok",
            **spread(cpu), **errors(traj, reference), "steps": run.steps,
            "rhs_evaluations": run.nfev, "jacobian_evaluations": run.njev,
            "impacts": run.impacts, "events": run.events}


def jointplay_sweep(scene: Any, model: Any, reference: Any, rtols: Sequence[float],
                    repeats: int, label: str = "jointplay (compiled BDF)",
                    integrator: str = "bdf") -> list[dict[str, Any]]:
    import warnings

    from jointplay.sim.plausibility import PlausibilityWarning

    rows = []
    for rtol in rtols:
        # A loose tolerance may leave the physical domain: kept and marked, not lost.
        cfg = scene.with_run(integrator=integrator, rtol=rtol, atol=rtol, plausibility="warn")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", PlausibilityWarning)
            timed = timed_runs(cfg, model, repeats)
        implausible = timed.result is not None and timed.result.implausible
        row: dict[str, Any] = {"code": label, "rtol": rtol, "t_end": cfg.run.t_end,
                               "status": "ok" if timed.result is not None else "failed",
                               "note": ("implausible (kept: plausibility = warn)"
                                        if implausible else timed.failure or ""),
                               **run_counts(timed.result)}
        if timed.result is not None:
            row.update(spread(timed.cpu_s))
            row.update(errors(timed.result, reference))
        rows.append(row)
    return rows


def match(peer_rows: Sequence[dict[str, Any]], jp_rows: Sequence[dict[str, Any]]
          ) -> list[dict[str, Any]]:
    """Pair every successful peer run with the jointplay run of nearest position error."""
    pairs = []
    ok = [r for r in jp_rows if r["status"] == "ok" and r["err_position"] > 0]
    for peer in peer_rows:
        if peer["status"] != "ok" or not ok:
            continue
        best = min(ok, key=lambda r: abs(math.log(r["err_position"] / peer["err_position"])))
        pairs.append({
            "code": peer["code"], "t_end": peer["t_end"], "peer_rtol": peer["rtol"],
            "peer_err_position": peer["err_position"],
            "peer_err_velocity": peer["err_velocity"], "peer_cpu_s": peer["cpu_median_s"],
            "jp_rtol": best["rtol"], "jp_err_position": best["err_position"],
            "jp_err_velocity": best["err_velocity"], "jp_cpu_s": best["cpu_median_s"],
            "error_ratio": peer["err_position"] / best["err_position"],
            "speedup": peer["cpu_median_s"] / best["cpu_median_s"],
        })
    return pairs
