"""jointplay against the tools a user would otherwise reach for, on the same robot and scene.

In one process, on the scene's robot (default: the paper's 4-link arm, clearance at joints 2
and 3, Coulomb friction) and the same sympy equations (``jointplay.derive.derive``: Kane's
method, the contact placeholders bound to the law expressions exactly as the C emitter binds
them):

(a) PyDy: ``pydy.system.System`` with the Cython backend (``generator='cython'``) for the
    right-hand side, integrated by SciPy's LSODA. PyDy's own ``System.integrate`` calls
    ``odeint`` (LSODA), which cannot stop at events; the impact-speed capture below needs
    them, so LSODA is driven through ``solve_ivp(method='LSODA', events=...)``.
(b) what a newcomer writes: ``sympy.lambdify`` of M and f (NumPy), ``numpy.linalg.solve``,
    the same ``solve_ivp`` LSODA driver.
(c) Pinocchio's ABA as the right-hand side of the ideal-joint version of the robot,
    integrated by CVODES through CasADi (the integrator of jointplay's ideal run) at the same
    tolerances, with Pinocchio's analytical ABA derivatives as the Jacobian; the same
    Python-callback path is also driven by jointplay's compiled functions, so the two
    right-hand sides are compared from one calling path, and jointplay's own ``simulate`` of
    the ideal scene is timed beside them. Per call: ``pin.aba`` from Python against jointplay's
    ``forward_dynamics`` through ``FastFunction`` (inputs written, ``trigger``, output read).
(d) jointplay: ``simulate`` with its default integrator (the compiled BDF: a whole run in one
    call into C, contact onsets located on its dense output), swept over tolerances;
(e) jointplay's compiled right-hand side in the peers' own LSODA driver: the same integration
    as (a) and (b), so that the cost of the right-hand side and that of the integration
    scheme can be told apart.

Impact speed. Every code captures it by jointplay's rule: each clearance joint carries
a contact flag; when its penetration crosses zero upwards while flagged free, the integration
stops there (event location), the approach speed d(delta)/dt is captured as that joint's
``v_imp`` (floored by the law at ``contact.impact_speed_floor``), the flag flips, and the
integration restarts. A downward crossing while flagged in contact flips the flag back.

Accuracy. Every run is compared with one reference, jointplay's CVODES at rtol = atol = 1e-10
over the same output grid: the maximum over samples of the end-effector position error (the
matching measure), velocity and acceleration errors, and the final-state error in scaled units.
Tolerances are swept for every code, and each peer run is paired with the jointplay run whose
position error is nearest (in ratio): the report gives both errors and the ratio of CPU times
(peer / jointplay). Absolute tolerances are the same scaled ones for every code (rad; radial
clearance for eccentricities, clearance per ms for their rates).

Costs: CPU seconds (``time.process_time``) of a whole run, median of ``--repeats`` runs; code
generation and compilation are timed once and reported separately.

    python benchmarks/peers.py --out out/bench/peers
    python benchmarks/peers.py --quick            # a small smoke run
"""

from __future__ import annotations

import argparse
import functools
import math
import os
import statistics
import sys
import tempfile
import time
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from jointplay.bench import (
    final_state_error,
    machine_facts,
    markdown_table,
    run_counts,
    state_scale,
    timed_runs,
    tip_errors,
    to_csv,
)
from jointplay.cli.args import prepare_out_dir
from jointplay.common.files import atomic_write_text
from jointplay.common.timing import per_call_seconds

REFERENCE_RTOL = 1e-10
JOINTPLAY_RTOLS = (1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8, 1e-9)
PEER_RTOLS = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8)
NEWCOMER_RTOLS = (1e-6,)
IDEAL_RTOLS = (1e-6, 1e-8)
PYDY_GOAL = 10.0  # jointplay at least this many times faster than PyDy at equal accuracy
ABA_GOAL = 2.0  # jointplay's ideal-joint rhs within this factor of pin.aba per call


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


# ---- the shared symbolic equations ---------------------------------------------------------------


@dataclass
class Equations:
    """M(q) du/dt = f(x, tau, p, v_imp) with the contact laws substituted, as sympy."""

    symbolic: Any
    mass_matrix: Any
    forcing: Any
    derive_s: float


def equations(robot: Any) -> Equations:
    from jointplay.derive import derive

    t0 = time.process_time()
    sm = derive(robot.structure())
    binding = {}
    for c in sm.clearance:  # what build_functions binds the placeholders to
        binding[c.force_x] = c.law.force_x
        binding[c.force_y] = c.law.force_y
        binding[c.force_t] = c.law.friction_force
    forcing = sm.forcing.xreplace(binding)
    return Equations(symbolic=sm, mass_matrix=sm.mass_matrix, forcing=forcing,
                     derive_s=time.process_time() - t0)


def parameter_values(eq: Equations, robot: Any) -> dict[Any, float]:
    values = dict(zip(eq.symbolic.parameter_symbols, robot.parameter_values(), strict=True))
    for c in eq.symbolic.clearance:
        values[c.impact_speed] = 0.0
    return values


class _KaneLike:
    """The attributes of a KanesMethod that ``pydy.system.System`` reads."""

    def __init__(self, eq: Equations, forcing: Any) -> None:
        import sympy as sp
        from sympy.physics.mechanics import dynamicsymbols

        t = dynamicsymbols._t
        sm = eq.symbolic
        n = len(sm.q)
        self.q = sp.Matrix(sm.q)
        self.u = sp.Matrix(sm.u)
        self.mass_matrix = eq.mass_matrix
        self.forcing = forcing
        self.mass_matrix_full = sp.diag(sp.eye(n), eq.mass_matrix)
        self.forcing_full = sp.Matrix.vstack(self.u, forcing)
        self._qdot = self.q.diff(t)
        self._udot = self.u.diff(t)
        self._uaux = sp.Matrix()

    def kindiffdict(self) -> dict[Any, Any]:
        from sympy.physics.mechanics import dynamicsymbols

        return {qi.diff(dynamicsymbols._t): ui for qi, ui in zip(self.q, self.u, strict=True)}


def fast_torques(scene: Any) -> Callable[[float], np.ndarray]:
    """The scene's drive torques as one cheap scalar function of t for the Python peers.

    A scene's expressions evaluate through NumPy (about 24 us each per scalar call, more than
    a compiled right-hand side); the same text goes through ``sympy.lambdify`` with the math
    module here, checked against the scene's own evaluation. Tables keep the scene's path.
    """
    import sympy as sp

    fns = scene.torques
    slow = lambda t: np.array([float(f.numpy(t)) for f in fns])  # noqa: E731
    if not fns or "table" in scene.torque_text:
        return slow
    t_sym = sp.Symbol("t", real=True)
    names = {k: sp.Float(v) for k, v in scene.constants.items()}
    try:
        exprs = [sp.sympify(scene.torque_text[k], locals={**names, "t": t_sym})
                 for k in scene.torque_text]
        fast = sp.lambdify([t_sym], exprs, "math")
    except (sp.SympifyError, SyntaxError, TypeError, ValueError):
        return slow
    for t in np.linspace(0.0, scene.run.t_end, 17):
        if not np.allclose(fast(float(t)), slow(float(t)), rtol=1e-12, atol=1e-12):
            return slow

    def torques(t: float) -> np.ndarray:
        return np.array(fast(t), dtype=float)

    return torques


@dataclass
class PeerRhs:
    name: str
    rhs: Callable[[float, np.ndarray, np.ndarray], np.ndarray]
    build_s: float
    per_call_us: float = math.nan
    note: str = ""


def pydy_rhs(eq: Equations, robot: Any, scene: Any, build_dir: Path) -> PeerRhs:
    """PyDy's System with the Cython generator; torques as specifieds, v_imp as constants."""
    from pydy.system import System
    from sympy.physics.mechanics import dynamicsymbols

    sm = eq.symbolic
    taus = [dynamicsymbols(s.name) for s in sm.torques]
    forcing = eq.forcing.xreplace(dict(zip(sm.torques, taus, strict=True)))
    kane = _KaneLike(eq, forcing)
    values = parameter_values(eq, robot)
    probe = System(kane)  # which symbols the equations actually use
    constants = {s: v for s, v in values.items() if s in probe.constants_symbols}
    torques = fast_torques(scene)

    def specified(_x: np.ndarray, t: float) -> np.ndarray:
        return torques(t)

    # PyDy's second specifieds format fixes the order of the torque symbols (a set otherwise).
    system = System(kane, constants=constants,
                    specifieds={"symbols": taus, "values": specified} if taus else None)
    c0 = time.process_time()
    w0 = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        f = system.generate_ode_function(generator="cython", tmp_dir=str(build_dir),
                                         constants_arg_type="array",
                                         specifieds_arg_type="function")
    build_s = time.perf_counter() - w0
    del c0
    order = list(system.constants_symbols)
    p = np.array([constants[s] for s in order])
    v_slots = [order.index(c.impact_speed) for c in sm.clearance]

    def rhs(t: float, x: np.ndarray, v_imp: np.ndarray) -> np.ndarray:
        p[v_slots] = v_imp
        return np.array(f(x, t, specified, p))

    return PeerRhs("PyDy (Cython) + LSODA", rhs, build_s)


def newcomer_rhs(eq: Equations, robot: Any, scene: Any) -> PeerRhs:
    """``sympy.lambdify`` (NumPy) of M and f, ``numpy.linalg.solve`` for the accelerations."""
    import sympy as sp

    sm = eq.symbolic
    n = len(sm.q)
    qs = sp.symbols(f"x0:{2 * n}", real=True)
    plain = dict(zip([*sm.q, *sm.u], qs, strict=True))
    values = parameter_values(eq, robot)
    params = list(values)
    args = [*qs, *sm.torques, *params]
    w0 = time.perf_counter()
    mass = sp.lambdify(args, eq.mass_matrix.xreplace(plain))
    force = sp.lambdify(args, eq.forcing.xreplace(plain))
    build_s = time.perf_counter() - w0
    p = np.array([values[s] for s in params])
    v_slots = [params.index(c.impact_speed) for c in sm.clearance]
    torques = fast_torques(scene)

    def rhs(t: float, x: np.ndarray, v_imp: np.ndarray) -> np.ndarray:
        p[v_slots] = v_imp
        a = [*x, *torques(t), *p]
        acc = np.linalg.solve(np.asarray(mass(*a), dtype=float),
                              np.asarray(force(*a), dtype=float).ravel())
        return np.concatenate([x[n:], acc])

    return PeerRhs("sympy.lambdify + LSODA", rhs, build_s)


def jointplay_lsoda_rhs(model: Any, scene: Any) -> PeerRhs:
    """jointplay's compiled forward dynamics in the peers' LSODA driver: the same integration
    as (a) and (b), so only the right-hand side differs."""
    fd = model.function("forward_dynamics")
    fd.inputs[2][:] = model.parameter_vector()
    torques = fast_torques(scene)

    def rhs(t: float, x: np.ndarray, v_imp: np.ndarray) -> np.ndarray:
        fd.inputs[0][:] = x
        fd.inputs[1][:] = torques(t)
        fd.inputs[3][:] = v_imp
        fd.trigger()
        return fd.outputs[0].copy()

    return PeerRhs("jointplay rhs + LSODA (same driver)", rhs, 0.0)


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
    rows = []
    for rtol in rtols:
        cfg = scene.with_run(integrator=integrator, rtol=rtol, atol=rtol)
        timed = timed_runs(cfg, model, repeats)
        row: dict[str, Any] = {"code": label, "rtol": rtol, "t_end": cfg.run.t_end,
                               "status": "ok" if timed.result is not None else "failed",
                               "note": timed.failure or "", **run_counts(timed.result)}
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


# ---- (c): Pinocchio on the ideal-joint robot -------------------------------------------------


def pinocchio_model(robot: Any) -> Any:
    """The ideal robot as a planar RZ chain; locked joints removed by buildReducedModel."""
    import pinocchio as pin

    model = pin.Model()
    parent, offset = 0, 0.0
    for i, link in enumerate(robot.links, start=1):
        jid = model.addJoint(parent, pin.JointModelRZ(),
                             pin.SE3(np.eye(3), np.array([offset, 0.0, 0.0])), f"joint{i}")
        model.addJointFrame(jid)
        inertia = np.diag([link.inertia + 0.5, link.inertia + 0.7, link.inertia])
        model.appendBodyToJoint(jid, pin.Inertia(link.mass, np.array([link.com, 0.0, 0.0]),
                                                 inertia), pin.SE3.Identity())
        parent, offset = jid, link.length
    model.appendBodyToJoint(parent, pin.Inertia(robot.payload_mass,
                                                np.array([offset, 0.0, 0.0]),
                                                np.zeros((3, 3))), pin.SE3.Identity())
    model.gravity.linear = np.array([*robot.gravity.vector, 0.0]) if robot.gravity.enabled \
        else np.zeros(3)
    locked = [i for i, j in enumerate(robot.joints, start=1) if j.kind == "locked"]
    if locked:
        q_ref = np.array([j.angle if j.kind == "locked" else 0.0 for j in robot.joints])
        gravity = model.gravity.linear.copy()
        model = pin.buildReducedModel(model, locked, q_ref)
        model.gravity.linear = gravity
    return model


class _JacobianCallback(ca.Callback):
    """d(rhs)/d(x, tau), called back into Python; the third input (the output) is unused."""

    def __init__(self, name: str, jac: Callable[[np.ndarray, np.ndarray],
                                                tuple[np.ndarray, np.ndarray]],
                 nx: int, ntau: int, opts: Mapping[str, Any]) -> None:
        ca.Callback.__init__(self)
        self._jac_fn, self._nx, self._ntau = jac, nx, ntau
        self.construct(f"jac_{name}", dict(opts))

    def get_n_in(self) -> int:
        return 3

    def get_n_out(self) -> int:
        return 2

    def get_sparsity_in(self, i: int) -> Any:
        return ca.Sparsity.dense([self._nx, self._ntau][i], 1) if i < 2 \
            else ca.Sparsity(self._nx, 1)

    def get_sparsity_out(self, i: int) -> Any:
        return ca.Sparsity.dense(self._nx, [self._nx, self._ntau][i])

    def eval(self, arg: Sequence[Any]) -> list[Any]:
        jx, jt = self._jac_fn(np.asarray(arg[0]).ravel(), np.asarray(arg[1]).ravel())
        return [jx, jt]


class _RhsCallback(ca.Callback):
    """The right-hand side f(x, tau), called back into Python, with its Jacobian; counts its
    calls."""

    def __init__(self, name: str, fn: Callable[[np.ndarray, np.ndarray], np.ndarray],
                 jac: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
                 nx: int, ntau: int) -> None:
        ca.Callback.__init__(self)
        self._name, self._fn, self._jac_fn = name, fn, jac
        self._nx, self._ntau = nx, ntau
        self.calls = 0
        self.construct(name, {})

    def get_n_in(self) -> int:
        return 2

    def get_n_out(self) -> int:
        return 1

    def get_sparsity_in(self, i: int) -> Any:
        return ca.Sparsity.dense([self._nx, self._ntau][i], 1)

    def get_sparsity_out(self, i: int) -> Any:
        return ca.Sparsity.dense(self._nx, 1)

    def eval(self, arg: Sequence[Any]) -> list[Any]:
        self.calls += 1
        return [self._fn(np.asarray(arg[0]).ravel(), np.asarray(arg[1]).ravel())]

    def has_jacobian(self) -> bool:
        return True

    def get_jacobian(self, _name: str, _inames: Any, _onames: Any,
                     opts: Mapping[str, Any]) -> Any:
        # Kept on self: CasADi holds no reference to a Python callback.
        self._jac_callback = _JacobianCallback(self._name, self._jac_fn, self._nx,
                                                self._ntau, opts)
        return self._jac_callback


def _cvodes_callback_run(name: str, fn: Callable[[np.ndarray, np.ndarray], np.ndarray],
                         jac: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
                         scene: Any, x0: np.ndarray, rtol: float) -> tuple[np.ndarray, int]:
    """CVODES over the output grid with the rhs and its Jacobian called back into Python."""
    rhs = _RhsCallback(name, fn, jac, x0.size, len(scene.torques))
    x = ca.MX.sym("x", x0.size)
    t = ca.MX.sym("t")
    tau = ca.vertcat(*[f.casadi(t) for f in scene.torques])
    grid = np.arange(1, scene.run.n_outputs + 1) * scene.run.output_step
    integ = ca.integrator(f"cvodes_{name}", "cvodes", {"x": x, "t": t, "ode": rhs(x, tau)},
                          0.0, grid, {"reltol": rtol, "abstol": rtol,
                                      "max_num_steps": scene.run.max_steps})
    out = integ(x0=x0)
    xs = np.vstack([x0, np.asarray(out["xf"]).T])
    return xs, rhs.calls


@dataclass
class _IdealRhs:
    """The ideal-joint right-hand side and its Jacobian, from jointplay and from Pinocchio,
    each as f(x, tau) and J(x, tau) -> (d/dx, d/dtau)."""

    jp_fd: Callable[[np.ndarray, np.ndarray], np.ndarray]
    jp_jac: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]
    pin_fd: Callable[[np.ndarray, np.ndarray], np.ndarray]
    pin_jac: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]


def _ideal_rhs(model: Any, pm: Any, data: Any) -> _IdealRhs:
    import pinocchio as pin

    n = model.n_coordinates
    p = model.parameter_vector()
    fd = model.function("forward_dynamics")
    jac = model.function("jac_forward_dynamics")
    fd.inputs[2][:] = p

    def jp_fd(xx: np.ndarray, tt: np.ndarray) -> np.ndarray:
        fd.inputs[0][:] = xx
        fd.inputs[1][:] = tt
        fd.trigger()
        return fd.outputs[0].copy()

    def jp_jac(xx: np.ndarray, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        blocks = jac(xx, tt, p, np.zeros(0), np.zeros(0))
        return blocks[0], blocks[1]

    def pin_fd(xx: np.ndarray, tt: np.ndarray) -> np.ndarray:
        return np.concatenate([xx[n:], pin.aba(pm, data, xx[:n], xx[n:], tt)])

    eye, zeros = np.eye(n), np.zeros((n, n))

    def pin_jac(xx: np.ndarray, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        pin.computeABADerivatives(pm, data, xx[:n], xx[n:], tt)
        minv = np.triu(data.Minv) + np.triu(data.Minv, 1).T
        jx = np.block([[zeros, eye], [data.ddq_dq, data.ddq_dv]])
        return jx, np.vstack([np.zeros((n, n)), minv])

    return _IdealRhs(jp_fd=jp_fd, jp_jac=jp_jac, pin_fd=pin_fd, pin_jac=pin_jac)


def pinocchio_section(scene: Any, repeats: int, rtols: Sequence[float]
                      ) -> tuple[list[dict[str, Any]], dict[str, Any]]:
    from jointplay.scene.definition import ideal_counterpart
    from jointplay.simulation import load_scene_model

    ideal_scene = scene.with_robot(ideal_counterpart(scene.robot))
    model = load_scene_model(scene, ideal=True)
    n = model.n_coordinates
    pm = pinocchio_model(ideal_scene.robot)
    data = pm.createData()
    if pm.nq != n:
        raise RuntimeError(f"Pinocchio model has {pm.nq} coordinates, jointplay's {n}")
    rhs = _ideal_rhs(model, pm, data)
    per_call = _ideal_per_call(model, pm, data, rhs)
    return _ideal_callback_rows(ideal_scene, model, rhs, repeats, rtols), per_call


def _ideal_per_call(model: Any, pm: Any, data: Any, rhs: _IdealRhs) -> dict[str, Any]:
    """Per call: pin.aba against jointplay's forward dynamics, and both Jacobians; how far
    they agree at a random state."""
    import pinocchio as pin

    n = model.n_coordinates
    p = model.parameter_vector()
    fd = model.function("forward_dynamics")
    jac = model.function("jac_forward_dynamics")
    rng = np.random.default_rng(7)
    x = rng.uniform(-1.0, 1.0, 2 * n)
    tau = rng.uniform(-2.0, 2.0, n)
    check = np.max(np.abs(model.forward_dynamics(x, tau, p)[n:]
                          - np.asarray(pin.aba(pm, data, x[:n], x[n:], tau))))
    jp_check = np.max(np.abs(rhs.jp_jac(x, tau)[0] - rhs.pin_jac(x, tau)[0]))

    q_arr, v_arr, t_arr = x[:n].copy(), x[n:].copy(), tau.copy()
    fd.inputs[0][:] = x
    fd.inputs[1][:] = tau
    fd.inputs[2][:] = p
    per_call = {
        "pin_aba_us": per_call_seconds(lambda: pin.aba(pm, data, q_arr, v_arr, t_arr)) * 1e6,
        "jp_trigger_us": per_call_seconds(fd.trigger) * 1e6,
        "jp_in_trigger_out_us": per_call_seconds(lambda: rhs.jp_fd(x, tau)) * 1e6,
        "jp_call_us": per_call_seconds(lambda: fd(x, tau, p, np.zeros(0))) * 1e6,
        "pin_aba_derivatives_us": per_call_seconds(
            lambda: pin.computeABADerivatives(pm, data, q_arr, v_arr, t_arr)) * 1e6,
        "jp_jacobian_us": per_call_seconds(jac.trigger) * 1e6,
        "max_abs_diff_aba": float(check),
        "max_abs_diff_jacobian": float(jp_check),
    }
    per_call["ratio"] = per_call["jp_in_trigger_out_us"] / per_call["pin_aba_us"]
    return per_call


def _ideal_callback_rows(ideal_scene: Any, model: Any, rhs: _IdealRhs, repeats: int,
                         rtols: Sequence[float]) -> list[dict[str, Any]]:
    """CVODES with each right-hand side called back into Python, and jointplay's simulate,
    at each tolerance, against the ideal scene's tight reference."""
    p = model.parameter_vector()
    tight = timed_runs(ideal_scene.with_run(integrator="cvodes", rtol=REFERENCE_RTOL,
                                            atol=REFERENCE_RTOL), model, 1)
    reference = tight.result
    assert reference is not None, tight.failure
    x0 = initial_state(model, ideal_scene)
    grid = reference.t
    rows = []
    for rtol in rtols:
        for label, fn, jfn in (("Pinocchio ABA, CVODES via Python callback", rhs.pin_fd,
                                rhs.pin_jac),
                               ("jointplay rhs, CVODES via Python callback", rhs.jp_fd,
                                rhs.jp_jac)):
            (xs, calls), cpu = cpu_runs(functools.partial(
                _cvodes_callback_run, label.split()[0].lower(), fn, jfn, ideal_scene, x0, rtol),
                repeats)
            taus = np.array([[float(f.numpy(t)) for f in ideal_scene.torques] for t in grid])
            xdots = np.array([fn(xs[i], taus[i]) for i in range(grid.size)])
            traj = trajectory_from_states(model, p, grid, xs, xdots, np.zeros(0))
            rows.append({"code": label, "rtol": rtol, "t_end": ideal_scene.run.t_end,
                         "status": "ok", **spread(cpu), **errors(traj, reference),
                         "rhs_evaluations": calls})
        rows += jointplay_sweep(ideal_scene, model, reference, [rtol], repeats,
                                label="jointplay simulate (compiled, no callback)")
    return rows


# ---- driver -------------------------------------------------------------------------------------

ROW_COLUMNS: list[tuple[str, str, str]] = [
    ("code", "code", "{}"),
    ("t_end", "horizon s", "{:g}"),
    ("rtol", "rtol", "{:.0e}"),
    ("status", "status", "{}"),
    ("cpu_median_s", "CPU s (median)", "{:.3f}"),
    ("cpu_min_s", "min", "{:.3f}"),
    ("cpu_max_s", "max", "{:.3f}"),
    ("err_position", "pos err m", "{:.2e}"),
    ("err_velocity", "vel err m/s", "{:.2e}"),
    ("err_acceleration", "acc err m/s²", "{:.2e}"),
    ("err_final_state", "final-state err", "{:.2e}"),
    ("rhs_evaluations", "rhs evals", "{}"),
    ("impacts", "impacts", "{}"),
    ("note", "note", "{}"),
]
PAIR_COLUMNS: list[tuple[str, str, str]] = [
    ("code", "peer", "{}"),
    ("t_end", "horizon s", "{:g}"),
    ("peer_rtol", "peer rtol", "{:.0e}"),
    ("peer_err_position", "peer pos err m", "{:.2e}"),
    ("jp_rtol", "jointplay rtol", "{:.0e}"),
    ("jp_err_position", "jointplay pos err m", "{:.2e}"),
    ("error_ratio", "err ratio", "{:.2f}"),
    ("peer_cpu_s", "peer CPU s", "{:.3f}"),
    ("jp_cpu_s", "jointplay CPU s", "{:.3f}"),
    ("speedup", "peer / jointplay", "{:.1f}"),
]
CSV_KEYS = ["section", "code", "t_end", "rtol", "status", "note", "repeats", "cpu_median_s",
            "cpu_min_s", "cpu_max_s", "err_position", "err_velocity", "err_acceleration",
            "err_final_state", "steps", "rhs_evaluations", "jacobian_evaluations", "events",
            "impacts", "peer_rtol", "peer_err_position", "peer_err_velocity", "peer_cpu_s",
            "jp_rtol", "jp_err_position", "jp_err_velocity", "jp_cpu_s", "error_ratio",
            "speedup"]


def _horizon(scene: Any, t_end: float | None) -> Any:
    if t_end is None or t_end >= scene.run.t_end:
        return scene
    return scene.with_run(t_end=t_end)


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("scene", nargs="?", help="scene file (default: the paper scene)")
    parser.add_argument("--out", help="folder for peers.csv and peers.md")
    parser.add_argument("--t-end", type=float, help="horizon of jointplay and PyDy (default: "
                                                    "the scene's)")
    parser.add_argument("--pydy-t-end", type=float, help="shorter horizon for PyDy")
    parser.add_argument("--newcomer-t-end", type=float,
                        help="shorter horizon for the lambdify peer (it is slow)")
    parser.add_argument("--repeats", type=int, default=3,
                        help="timed runs per configuration (default 3)")
    parser.add_argument("--newcomer-repeats", type=int, default=1,
                        help="timed runs of the lambdify peer (default 1)")
    parser.add_argument("--pydy-rtols", default=",".join(f"{r:g}" for r in PEER_RTOLS))
    parser.add_argument("--quick", action="store_true", help="a small smoke run")
    return parser


def _say(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


class _JointplayRuns:
    """jointplay's tolerance sweep per horizon, run once each, in the order first asked for."""

    def __init__(self, model: Any, reference: Any, rtols: Sequence[float], repeats: int):
        self.model, self.reference, self.rtols, self.repeats = model, reference, rtols, repeats
        self.by_horizon: dict[float, list[dict[str, Any]]] = {}
        self.rows: list[dict[str, Any]] = []

    def reference_for(self, s: Any) -> Trajectory:
        return prefix(self.reference, s.run.n_outputs + 1)

    def rows_for(self, s: Any) -> list[dict[str, Any]]:
        if s.run.t_end not in self.by_horizon:
            _say(f"jointplay sweep over {s.run.t_end:g} s")
            self.by_horizon[s.run.t_end] = jointplay_sweep(s, self.model, self.reference_for(s),
                                                           self.rtols, self.repeats)
            self.rows.extend(self.by_horizon[s.run.t_end])
        return self.by_horizon[s.run.t_end]


@dataclass
class _Findings:
    """Everything the report states."""

    scene: Any
    pydy_scene: Any
    newcomer_scene: Any
    reference_cpu_s: float
    repeats: int
    newcomer_repeats: int
    rows: list[dict[str, Any]]
    peer_rows: list[dict[str, Any]]
    pairs: list[dict[str, Any]]
    jp_by_horizon: dict[float, list[dict[str, Any]]]
    per_call_peer: dict[str, float]
    per_call: dict[str, Any]
    build: dict[str, float]
    load_start: str


def main(argv: Sequence[str] | None = None) -> int:
    args = _parser().parse_args(argv)

    from jointplay.scene.definition import default_scene, load_scene
    from jointplay.simulation import load_scene_model

    scene = load_scene(args.scene) if args.scene else default_scene()
    if args.quick:
        args.t_end = args.t_end or 0.02
        args.newcomer_t_end = min(args.newcomer_t_end or 0.01, 0.01)
        args.repeats = 1
    scene = _horizon(scene, args.t_end)
    pydy_scene = _horizon(scene, args.pydy_t_end)
    newcomer_scene = _horizon(scene, args.newcomer_t_end)
    pydy_rtols = [float(r) for r in args.pydy_rtols.split(",") if r.strip()]
    jp_rtols = JOINTPLAY_RTOLS[::3] if args.quick else JOINTPLAY_RTOLS
    out = prepare_out_dir(args.out) if args.out else None
    load_start = " ".join(f"{v:.2f}" for v in os.getloadavg())

    model = load_scene_model(scene)
    _say(f"reference: jointplay cvodes rtol {REFERENCE_RTOL:g} over {scene.run.t_end:g} s")
    ref_timed = timed_runs(scene.with_run(integrator="cvodes", rtol=REFERENCE_RTOL,
                                          atol=REFERENCE_RTOL), model, 1)
    assert ref_timed.result is not None, ref_timed.failure
    jp = _JointplayRuns(model, ref_timed.result, jp_rtols, args.repeats)
    jp.rows_for(scene)
    _say("deriving the shared sympy equations")
    eq = equations(scene.robot)
    build: dict[str, float] = {"sympy derivation (shared)": eq.derive_s}
    per_call_peer, peer_rows = _peers(eq, scene, model, jp, build, [
        (pydy_scene, rtol, args.repeats) for rtol in pydy_rtols],
        (newcomer_scene, args.newcomer_repeats))
    rows = jp.rows + peer_rows
    pairs: list[dict[str, Any]] = []
    for code in dict.fromkeys(r["code"] for r in peer_rows):
        mine = [r for r in peer_rows if r["code"] == code]
        pairs += match(mine, jp.by_horizon[mine[0]["t_end"]])

    _say("Pinocchio (ideal joints)")
    ideal_rows, per_call = pinocchio_section(scene, args.repeats, IDEAL_RTOLS)
    rows.extend(ideal_rows)
    text = _report(_Findings(
        scene=scene, pydy_scene=pydy_scene, newcomer_scene=newcomer_scene,
        reference_cpu_s=ref_timed.cpu_s[0], repeats=args.repeats,
        newcomer_repeats=args.newcomer_repeats, rows=rows, peer_rows=peer_rows, pairs=pairs,
        jp_by_horizon=jp.by_horizon, per_call_peer=per_call_peer, per_call=per_call,
        build=build, load_start=load_start))
    print(text)
    if out is not None:
        table = [{"section": "run", **r} for r in rows] + \
                [{"section": "matched", **q} for q in pairs]
        atomic_write_text(out / "peers.csv", to_csv(table, CSV_KEYS))
        atomic_write_text(out / "peers.md", text)
        print(f"wrote {out / 'peers.csv'}\nwrote {out / 'peers.md'}")
    return 0


def _peers(eq: Equations, scene: Any, model: Any, jp: _JointplayRuns, build: dict[str, float],
           pydy_runs: Sequence[tuple[Any, float, int]], newcomer_run: tuple[Any, int]
           ) -> tuple[dict[str, float], list[dict[str, Any]]]:
    """Build PyDy's and the lambdify right-hand sides (their build times into ``build``);
    their cost per call; then PyDy and jointplay's rhs in the same driver at ``pydy_runs``
    (horizon, rtol, repeats), and the lambdify peer once."""
    with tempfile.TemporaryDirectory(prefix="jointplay-peers-") as tmp:
        _say("PyDy: generating and compiling the Cython right-hand side")
        pydy = pydy_rhs(eq, scene.robot, scene, Path(tmp) / "pydy")
        build["PyDy codegen + Cython compile (wall)"] = pydy.build_s
        _say("sympy.lambdify")
        newcomer = newcomer_rhs(eq, scene.robot, scene)
        build["sympy.lambdify (wall)"] = newcomer.build_s
        per_call_peer = _peer_per_call(model, scene, pydy, newcomer)
        same_driver = jointplay_lsoda_rhs(model, scene)
        runs = [(pydy, s, rtol, repeats) for s, rtol, repeats in pydy_runs]
        runs += [(same_driver, s, rtol, repeats) for s, rtol, repeats in pydy_runs]
        runs += [(newcomer, newcomer_run[0], rtol, newcomer_run[1]) for rtol in NEWCOMER_RTOLS]
        return per_call_peer, _peer_runs(runs, model, jp)


def _peer_per_call(model: Any, scene: Any, pydy: PeerRhs, newcomer: PeerRhs
                   ) -> dict[str, float]:
    """Per right-hand-side call of each code at a probe state, and how far they agree."""
    x_probe = np.zeros(model.n_state)
    x_probe[0] = -math.pi
    v0 = np.full(len(model.clearance_joints), 0.1)
    per_call_peer = {
        "PyDy rhs (us/call)": per_call_seconds(lambda: pydy.rhs(0.1, x_probe, v0)) * 1e6,
        "lambdify rhs (us/call)": per_call_seconds(
            lambda: newcomer.rhs(0.1, x_probe, v0), repeats=3) * 1e6,
    }
    fd = model.function("forward_dynamics")
    fd.inputs[0][:] = x_probe
    fd.inputs[2][:] = model.parameter_vector()
    fd.inputs[3][:] = v0
    per_call_peer["jointplay forward_dynamics trigger (us/call)"] = \
        per_call_seconds(fd.trigger) * 1e6
    p = model.parameter_vector()
    tau01 = np.array([float(f.numpy(0.1)) for f in scene.torques])
    agree = float(np.max(np.abs(pydy.rhs(0.1, x_probe, v0)
                                - model.forward_dynamics(x_probe, tau01, p, v0))))
    agree_nc = float(np.max(np.abs(newcomer.rhs(0.1, x_probe, v0)
                                   - model.forward_dynamics(x_probe, tau01, p, v0))))
    per_call_peer["max |PyDy rhs - jointplay rhs| at a probe state"] = agree
    per_call_peer["max |lambdify rhs - jointplay rhs| at a probe state"] = agree_nc
    return per_call_peer


def _peer_runs(runs: Sequence[tuple[PeerRhs, Any, float, int]], model: Any,
               jp: _JointplayRuns) -> list[dict[str, Any]]:
    """Each peer at each tolerance over its horizon (jointplay's sweep there first)."""
    peer_rows: list[dict[str, Any]] = []
    for peer, peer_scene, rtol, repeats in runs:
        jp.rows_for(peer_scene)
        _say(f"{peer.name}: rtol {rtol:g} over {peer_scene.run.t_end:g} s")
        row = run_peer(peer, model, peer_scene, jp.reference_for(peer_scene), rtol, repeats)
        peer_rows.append(row)
        _say(f"  {row.get('cpu_median_s', math.nan):.2f} s CPU, position error "
             f"{row.get('err_position', math.nan):.2e} m")
    return peer_rows


def _goal_lines(f: _Findings) -> list[str]:
    """The verdicts on the two goals, and the facts beside them."""
    scene = f.scene
    pydy_pairs = [q for q in f.pairs if q["code"].startswith("PyDy")]
    matched = [q for q in pydy_pairs if 0.5 <= q["error_ratio"] <= 2.0]
    md = []
    if matched:
        best = min(matched, key=lambda q: abs(math.log(q["error_ratio"])))
        verdict = "met" if best["speedup"] >= PYDY_GOAL else "NOT met"
        md.append(f"- >= {PYDY_GOAL:g}x faster than PyDy at equal accuracy: {verdict}: "
                  f"{best['speedup']:.1f}x at position error {best['peer_err_position']:.2e} m "
                  f"(PyDy rtol {best['peer_rtol']:g}) vs {best['jp_err_position']:.2e} m "
                  f"(jointplay rtol {best['jp_rtol']:g}), over {best['t_end']:g} s; every "
                  "matched pair: " + ", ".join(f"{q['speedup']:.1f}x" for q in matched))
    else:
        md.append(f"- >= {PYDY_GOAL:g}x faster than PyDy at equal accuracy: no PyDy run "
                  "could be matched within a factor 2 in error (see the tables)")
    md += _driver_lines(f)
    us_pydy = f.per_call_peer["PyDy rhs (us/call)"]
    us_jp = f.per_call_peer["jointplay forward_dynamics trigger (us/call)"]
    md.append(f"- per right-hand-side call: PyDy {us_pydy:.1f} us, lambdify "
              f"{f.per_call_peer['lambdify rhs (us/call)']:.0f} us, jointplay {us_jp:.2f} us "
              f"(PyDy / jointplay {us_pydy / us_jp:.0f}x)")
    per_call = f.per_call
    verdict = "met" if per_call["ratio"] <= ABA_GOAL else "NOT met"
    md.append(f"- ideal-joint rhs within {ABA_GOAL:g}x of Pinocchio's ABA per call (both "
              f"called from Python with numpy arrays): {verdict}: jointplay "
              f"{per_call['jp_in_trigger_out_us']:.2f} us vs pin.aba "
              f"{per_call['pin_aba_us']:.2f} us ({per_call['ratio']:.2f}x); trigger alone "
              f"{per_call['jp_trigger_us']:.2f} us")
    default_jp = next((r for r in f.jp_by_horizon[scene.run.t_end]
                       if r["rtol"] == scene.run.rtol and r["status"] == "ok"), None)
    if default_jp is not None:
        md.append(f"- jointplay at the scene's tolerance (rtol {scene.run.rtol:g}): "
                  f"{default_jp['cpu_median_s']:.3f} s CPU for {scene.run.t_end:g} s "
                  f"simulated, position error {default_jp['err_position']:.2e} m")
    return md


def _driver_lines(f: _Findings) -> list[str]:
    """PyDy against jointplay's rhs in the same driver, and the work each integration did."""
    md = []
    same = {r["rtol"]: r for r in f.peer_rows
            if r["code"].startswith("jointplay rhs") and r["status"] == "ok"}
    driver_pairs = [(r, same[r["rtol"]]) for r in f.peer_rows if r["code"].startswith("PyDy")
                    and r["status"] == "ok" and r["rtol"] in same]
    if driver_pairs:
        md.append("- PyDy against jointplay's rhs in the same LSODA driver (same tolerance, so "
                  "only the right-hand side differs): " + ", ".join(
                      f"rtol {a['rtol']:g}: {a['cpu_median_s'] / b['cpu_median_s']:.1f}x "
                      f"(errors {a['err_position']:.1e} / {b['err_position']:.1e} m)"
                      for a, b in driver_pairs))
    jp_at = {r["rtol"]: r for r in f.jp_by_horizon[f.pydy_scene.run.t_end]
             if r["status"] == "ok"}
    for r in f.peer_rows:
        if r["code"].startswith("PyDy") and r["status"] == "ok" \
                and r["rtol"] == f.scene.run.rtol and r["rtol"] in jp_at:
            j = jp_at[r["rtol"]]
            md.append(f"- work at rtol {r['rtol']:g}: jointplay's simulate {j['steps']} steps, "
                      f"{j['rhs_evaluations']} rhs and {j['jacobian_evaluations']} Jacobian "
                      f"evaluations; LSODA (PyDy) {r['rhs_evaluations']} rhs evaluations "
                      f"(finite-difference Jacobians included), {r['jacobian_evaluations']} "
                      "Jacobians")
    return md


def _report(f: _Findings) -> str:
    scene = f.scene
    md = ["# jointplay and its peers", "",
          f"Scene: {scene.source or scene.name}; horizon {scene.run.t_end:g} s (PyDy "
          f"{f.pydy_scene.run.t_end:g} s, lambdify {f.newcomer_scene.run.t_end:g} s), output "
          f"every {scene.run.output_step:g} s. Reference: jointplay CVODES rtol = atol = "
          f"{REFERENCE_RTOL:g} ({f.reference_cpu_s:.2f} s CPU). CPU times are medians of "
          f"{f.repeats} runs (lambdify: {f.newcomer_repeats}).", "",
          "## Goals", "", *_goal_lines(f)]
    md += ["", "## Peer / jointplay at matched accuracy", "",
           "Each peer run is paired with the jointplay run whose end-effector position error "
           "is nearest; `err ratio` = peer error / jointplay error (within 0.5-2 counts as "
           "matched), `peer / jointplay` = ratio of CPU times.", "",
           markdown_table(f.pairs, PAIR_COLUMNS), "",
           "## Per call", "",
           *(f"- {k}: {v:.3g}" for k, v in f.per_call_peer.items()),
           *(f"- {k}: {v:.3g}" for k, v in f.per_call.items()), "",
           "## Code generation and compilation (once, not in the run times)", "",
           *(f"- {k}: {v:.2f} s" for k, v in f.build.items()), "",
           "## Every run", "", markdown_table(f.rows, ROW_COLUMNS), "",
           "## Machine", "", f"- load average (1/5/15 min) at the start: {f.load_start}",
           *(f"- {k}: {v}" for k, v in machine_facts().items()), ""]
    return "\n".join(md)


if __name__ == "__main__":
    sys.exit(main())
