"""The approximate internal-model-based neural controller (AIMNC), its baselines and metrics.

Structure (see docs/control.md for the reasoning). The plant the network identified is the
clearance robot under a joint PD around the ideal robot's motion; its input is the torque v
added to the PD's, its outputs y the deviations from the ideal robot. At every sample k the
controller

1. compares the measured deviation with the internal model's free-run prediction,
   e(k) = y(k) - y^(k), and filters it, e_f(k) = b e_f(k-1) + (1 - b) e(k) (unity DC gain);
2. runs the network d samples ahead with the input held, linearised about the previous input:
   y^(k+d) ~ N0(k) + J(k) dv, with N0 the prediction at v(k) = v(k-1) and J = dN/dv (CasADi);
3. solves the regularised inverse on the tracked outputs (rows of C, scaled),
   dv = ((CJ)'(CJ) + lam I)^-1 (CJ)' C (y_d(k+d) - e_f(k) - N0(k)),
   with the setpoint filter y_d(k+1) = a y_d(k) + (1 - a) r(k+1), r = 0 in deviation
   coordinates (the reference is the ideal motion itself);
4. limits the rate of v and the total actuator torque (feedforward + PD + v), keeping the
   limited v as the model's input (no wind-up), and advances the internal model with it.

With d = 1 and C = I this is the textbook one-step law. The horizon d is what makes it work on a
robot: torque reaches position through two integrations, so the one-step gain is tiny, its
inverse cancels the sampling zero near -1 (ringing), and the network cannot resolve a 1 ms
response of a journal that flies across its clearance. Ten samples ahead the response is the
well-identified, contact-averaged one.

The step (network, rollout, Jacobian, solve, filters, limits, and the inner PD) is one CasADi
function, generated to C and compiled through the same cache as the robot models.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field
from importlib.metadata import version
from pathlib import Path
from typing import TYPE_CHECKING, Any

import casadi as ca
import numpy as np

from jointplay.errors import DescriptionError
from jointplay.files import atomic_path, atomic_write_text
from jointplay.narx import MODEL_FILE, Narx, check_robot, load_narx

if TYPE_CHECKING:
    from matplotlib.figure import Figure

STEP_NAME = "aimnc_step"
DEFAULT_TRANSIENT = 0.05  # s: journals settling from e = 0, reported separately
CONTROLLERS = ("open loop", "PD", "computed torque", "AIMNC")


@dataclass(frozen=True)
class ControllerSettings:
    """The controller's tuning; every field has a command-line flag of the same name."""

    horizon: int = 10  # d: samples ahead the prediction is matched
    regularisation: float = 1e-3  # lam, in units of the scaled outputs per (N m)^2
    setpoint_filter: float = 0.0  # a
    mismatch_filter: float = 0.9  # b
    tracked: tuple[str, ...] = ()  # outputs in C; default: see default_tracked
    scales: tuple[float, ...] = ()  # error of each tracked output that counts as 1
    torque_limit: tuple[float, ...] = ()  # |feedforward + PD + v| per joint, N m
    rate_limit: tuple[float, ...] = ()  # |dv/dt| per joint, N m/s
    iterations: int = 1  # Gauss-Newton steps on the linearisation (1: the AIMNC law)


@dataclass
class Controller:
    """A compiled controller step, bound to preallocated buffers."""

    narx: Narx
    settings: ControllerSettings
    function: ca.Function  # the CasADi step (uncompiled), for checks and analysis
    library: Path | None
    compile_seconds: float
    source: str
    fast: Any = None  # FastFunction over the compiled step
    n_state: int = 0
    layout: dict[str, Any] = field(default_factory=dict)

    def initial_state(self, deviation: np.ndarray) -> np.ndarray:
        """Internal model started at the measured deviation, no added torque, no mismatch."""
        m = self.narx
        state = np.zeros(self.n_state)
        ny, nu = m.n_outputs, m.n_inputs
        state[: m.output_lags * ny] = np.tile(deviation, m.output_lags)
        off = m.output_lags * ny + m.input_lags * nu + ny
        state[off: off + ny] = deviation
        return state

    def step(self, y: np.ndarray, r: np.ndarray, tau_ff: np.ndarray,
             state: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(added torque, next state, v, predicted deviation) through the compiled code."""
        f = self.fast
        f.inputs[0][:] = y
        f.inputs[1][:] = r
        f.inputs[2][:] = tau_ff
        f.inputs[3][:] = state
        f.trigger()
        return (f.outputs[0].copy(), f.outputs[1].copy(), f.outputs[2].copy(),
                f.outputs[3].copy())


# ---- building the step ------------------------------------------------------------------------

def horizon_gain(narx: Narx, horizon: int) -> np.ndarray:
    """d y^(k+d) / d v with v held for ``horizon`` samples, from rest (ny x nu)."""
    f = narx.casadi_function()
    ny, nu = narx.n_outputs, narx.n_inputs
    v = ca.MX.sym("v", nu)
    ys: list[Any] = [ca.DM.zeros(ny)] * narx.output_lags
    us: list[Any] = [v] + [ca.DM.zeros(nu)] * (narx.input_lags - 1)
    for _ in range(horizon):
        nxt = f(ca.vertcat(*ys, *us))
        ys = [nxt, *ys[:-1]]
        us = [v, *us[:-1]]
    return np.asarray(ca.Function("gain", [v], [ca.jacobian(ys[0], v)])(np.zeros(nu)))


def default_tracked(narx: Narx, horizon: int) -> tuple[str, ...]:
    """The end effector's position and velocity along the axis the torques move it most, and
    the angle and speed of the last nu - 1 moving joints.

    Near a stretched configuration (the paper's arm hangs almost straight) the other axis runs
    along the arm, where the joints have next to no authority: asking for it makes the inverse
    ill-conditioned. Velocities are tracked with the positions because they give the loop its
    damping; the joint rows pin the configuration the end-effector rows leave free.
    """
    joints = narx.context.get("plant", {}).get("inner_loop", {}).get("joints", [])
    names = narx.output_names
    if not joints or not {"tip_x", "tip_y", "tip_vx", "tip_vy"} <= set(names):
        return tuple(n for n in names if n.startswith("q"))[: narx.n_inputs] \
            or names[: narx.n_inputs]
    gain = horizon_gain(narx, horizon)
    axis = max("xy", key=lambda a: float(np.linalg.norm(gain[narx.output_index(f"tip_{a}")])))
    out = [f"tip_{axis}", f"tip_v{axis}"]
    for j in joints[len(joints) - (narx.n_inputs - 1):] if narx.n_inputs > 1 else []:
        out += [f"q{j}", f"dq{j}"]
    return tuple(out)


def resolve_settings(narx: Narx, settings: ControllerSettings) -> ControllerSettings:
    """Fill defaults from the model and check every value against it (errors name the flag)."""
    plant = narx.context.get("plant", {})
    nu = narx.n_inputs
    tracked = settings.tracked or default_tracked(narx, max(1, settings.horizon))
    for name in tracked:
        if name not in narx.output_names:
            raise DescriptionError("--track", f"{name!r} is not an output of the model "
                                   f"(outputs: {', '.join(narx.output_names)})")
    if len(set(tracked)) != len(tracked):
        raise DescriptionError("--track", "names an output twice")
    scales = settings.scales or tuple(float(narx.output_scale[narx.output_index(n)])
                                      for n in tracked)
    if len(scales) != len(tracked) or not all(s > 0 and math.isfinite(s) for s in scales):
        raise DescriptionError("--scales", f"needs one positive number per tracked output "
                               f"({len(tracked)}), got {list(scales)}")
    limits = settings.torque_limit or tuple(plant.get("torque_limit", ())) or (math.inf,) * nu
    if len(limits) != nu or not all(v > 0 for v in limits):
        raise DescriptionError("--torque-limit", f"needs {nu} positive values, got "
                               f"{list(limits)}")
    rates = settings.rate_limit or tuple(10.0 * v if math.isfinite(v) else math.inf
                                         for v in limits)
    if len(rates) != nu or not all(v > 0 for v in rates):
        raise DescriptionError("--rate-limit", f"needs {nu} positive values, got {list(rates)}")
    for flag, value, ok, allowed in (
            ("--horizon", settings.horizon, isinstance(settings.horizon, int)
             and 1 <= settings.horizon <= 500, "an integer from 1 to 500"),
            ("--lambda", settings.regularisation, math.isfinite(settings.regularisation)
             and settings.regularisation >= 0, "a finite number >= 0"),
            ("--setpoint-filter", settings.setpoint_filter,
             0 <= settings.setpoint_filter < 1, "a number in [0, 1)"),
            ("--mismatch-filter", settings.mismatch_filter,
             0 <= settings.mismatch_filter < 1, "a number in [0, 1)"),
            ("--iterations", settings.iterations, isinstance(settings.iterations, int)
             and 1 <= settings.iterations <= 20, "an integer from 1 to 20")):
        if not ok:
            raise DescriptionError(flag, f"must be {allowed}, got {value!r}")
    return ControllerSettings(settings.horizon, settings.regularisation,
                              settings.setpoint_filter, settings.mismatch_filter,
                              tuple(tracked), tuple(float(s) for s in scales),
                              tuple(float(v) for v in limits), tuple(float(v) for v in rates),
                              settings.iterations)


def _inner_gains(narx: Narx) -> tuple[list[int], list[int], np.ndarray, np.ndarray]:
    """Output indices of the PD's angle and speed deviations, and its gains."""
    inner = narx.context.get("plant", {}).get("inner_loop", {})
    joints = inner.get("joints", [])
    if not joints:
        return [], [], np.zeros(0), np.zeros(0)
    q = [narx.output_index(f"q{j}") for j in joints]
    dq = [narx.output_index(f"dq{j}") for j in joints]
    return q, dq, np.asarray(inner["kp"], dtype=float), np.asarray(inner["kd"], dtype=float)


def build_step(narx: Narx, settings: ControllerSettings,
               sym: Any = ca.SX) -> tuple[ca.Function, dict[str, Any]]:
    """The controller step as a CasADi function (see the module docstring for the law).

    Inputs: y (measured outputs), r (the reference's outputs), tau_ff (the feedforward torque
    at this sample, for the actuator limit) and state. Outputs: tau (torque to add to the
    feedforward: PD + v), state_next, v, y_pred (the model's deviation at k+1).
    """
    s = settings
    m = narx
    ny, nu, na, nb, d = m.n_outputs, m.n_inputs, m.output_lags, m.input_lags, s.horizon
    if len(s.torque_limit) != nu:
        raise ValueError("resolve the settings first (resolve_settings)")
    net = m.casadi_function("narx_network")
    n_state = na * ny + nb * nu + 2 * ny

    # d-step rollout with the input held at v: y^(k+d) and y^(k+1).
    yh = sym.sym("y_hist", na * ny)
    uh = sym.sym("u_past", nb * nu)  # v(k-1) ... v(k-nb)
    v = sym.sym("v", nu)
    ys = [yh[i * ny:(i + 1) * ny] for i in range(na)]
    us = [v] + [uh[i * nu:(i + 1) * nu] for i in range(nb - 1)]
    for _ in range(d):
        nxt = net(ca.vertcat(*ys, *us))
        ys = [nxt, *ys[:-1]]
        us = [v, *us[:-1]]
    rollout = ca.Function("aimnc_rollout", [yh, uh, v], [ys[0]], ["y_hist", "u_past", "v"],
                          ["y_end"])
    dv = sym.sym("dv", nu)
    vprev_sym = sym.sym("v_prev", nu)
    y_end = rollout(yh, uh, vprev_sym + dv)
    linear = ca.Function("aimnc_linearised", [yh, uh, vprev_sym, dv],
                         [y_end, ca.jacobian(y_end, dv)],
                         ["y_hist", "u_past", "v_prev", "dv"], ["n", "j"])

    y = sym.sym("y", ny)
    r = sym.sym("r", ny)
    tau_ff = sym.sym("tau_ff", nu)
    state = sym.sym("state", n_state)
    hist = state[: na * ny]
    upast = state[na * ny: na * ny + nb * nu]
    e_f_prev = state[na * ny + nb * nu: na * ny + nb * nu + ny]
    y_d = state[na * ny + nb * nu + ny:]
    v_prev = upast[:nu]

    dev = y - r
    e = dev - hist[:ny]
    e_f = s.mismatch_filter * e_f_prev + (1 - s.mismatch_filter) * e
    target = (s.setpoint_filter ** d) * y_d
    rows = [m.output_index(name) for name in s.tracked]
    c = np.zeros((len(rows), ny))
    for i, (row, scale) in enumerate(zip(rows, s.scales, strict=True)):
        c[i, row] = 1.0 / scale
    cm = ca.DM(c)
    lam = s.regularisation * ca.DM.eye(nu)
    step = sym.zeros(nu, 1)
    for _ in range(s.iterations):
        n_val, jac = linear(hist, upast, v_prev, step)
        cj = ca.mtimes(cm, jac)
        residual = ca.mtimes(cm, target - e_f - n_val)
        rhs = ca.mtimes(cj.T, residual) - s.regularisation * step
        step = step + ca.solve(ca.mtimes(cj.T, cj) + lam, rhs)
    rate = ca.DM([rl * m.sample_time for rl in s.rate_limit])
    step = ca.fmin(ca.fmax(step, -rate), rate)
    q_idx, dq_idx, kp, kd = _inner_gains(m)
    inner = (-ca.DM(kp) * dev[q_idx] - ca.DM(kd) * dev[dq_idx]) if q_idx else sym.zeros(nu, 1)
    limit = ca.DM([lim if math.isfinite(lim) else 1e300 for lim in s.torque_limit])
    v_new = ca.fmin(ca.fmax(v_prev + step, -limit - tau_ff - inner), limit - tau_ff - inner)
    total = ca.fmin(ca.fmax(tau_ff + inner + v_new, -limit), limit)
    tau = total - tau_ff
    y_next = net(ca.vertcat(*[hist[i * ny:(i + 1) * ny] for i in range(na)], v_new,
                            *[upast[i * nu:(i + 1) * nu] for i in range(nb - 1)]))
    new_hist = ca.vertcat(y_next, hist[: (na - 1) * ny])
    new_upast = ca.vertcat(v_new, upast[: (nb - 1) * nu])
    y_d_next = s.setpoint_filter * y_d
    state_next = ca.vertcat(new_hist, new_upast, e_f, y_d_next)
    fn = ca.Function(STEP_NAME, [y, r, tau_ff, state], [tau, state_next, v_new, y_next],
                     ["y", "r", "tau_ff", "state"], ["tau", "state_next", "v", "y_pred"])
    layout = {
        "inputs": {"y": list(m.output_names), "r": list(m.output_names),
                   "tau_ff": list(m.input_names)},
        "state": ([f"y_hat[k-{i}].{n}" for i in range(na) for n in m.output_names]
                  + [f"v[k-{i + 1}].{n}" for i in range(nb) for n in m.input_names]
                  + [f"e_f.{n}" for n in m.output_names]
                  + [f"y_d.{n}" for n in m.output_names]),
        "outputs": {"tau": list(m.input_names), "v": list(m.input_names),
                    "y_pred": list(m.output_names)},
    }
    return fn, layout


def _header(narx: Narx, settings: ControllerSettings, layout: dict[str, Any], body: str) -> str:
    settings_text = json.dumps(asdict(settings), default=str)
    return (
        "/* GENERATED FILE: DO NOT EDIT.\n"
        " * Regenerated by `jointplay control` from the model folder's narx.json.\n"
        f" * controller: {STEP_NAME} (approximate internal-model neural control)\n"
        f" * generator: jointplay.control {version('jointplay')}, casadi {version('casadi')}\n"
        f" * network checksum: {narx.checksum()}\n"
        f" * robot hash: {narx.context.get('robot', {}).get('robot_hash', '?')}\n"
        f" * code sha256: {hashlib.sha256(body.encode()).hexdigest()}\n"
        f" * settings: {settings_text}\n"
        f" * inputs: y[{len(layout['inputs']['y'])}], r[{len(layout['inputs']['r'])}], "
        f"tau_ff[{len(layout['inputs']['tau_ff'])}], state[{len(layout['state'])}]\n"
        f" * outputs: tau[{len(layout['outputs']['tau'])}], state_next[{len(layout['state'])}]"
        f", v[{len(layout['outputs']['v'])}], y_pred[{len(layout['outputs']['y_pred'])}]\n"
        f" * outputs y: {', '.join(layout['inputs']['y'])}\n"
        " */\n")


def generate_c(narx: Narx, settings: ControllerSettings) -> tuple[str, ca.Function,
                                                                 dict[str, Any]]:
    fn, layout = build_step(narx, settings)
    gen = ca.CodeGenerator("aimnc.c", {"with_header": False, "verbose": False})
    gen.add(fn)
    body = gen.dump()
    return _header(narx, settings, layout, body) + body, fn, layout


def compile_controller(narx: Narx, settings: ControllerSettings,
                       compiled: bool = True) -> Controller:
    """Build, generate, compile (through the cache) and load the controller step."""
    from jointplay.build import compile_source
    from jointplay.model import FastFunction

    settings = resolve_settings(narx, settings)
    source, fn, layout = generate_c(narx, settings)
    library, seconds = (None, 0.0)
    external = fn
    if compiled:
        library, seconds = compile_source(source)
        external = ca.external(STEP_NAME, str(library))
    ctrl = Controller(narx, settings, fn, library, seconds, source, FastFunction(external),
                      len(layout["state"]), layout)
    return ctrl


def per_call_us(ctrl: Controller, repeat: int = 5, number: int = 20000) -> float:
    """Median time of one compiled step through the buffer path, in microseconds."""
    f = ctrl.fast
    f.inputs[3][:] = ctrl.initial_state(np.zeros(ctrl.narx.n_outputs))
    best = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            f.trigger()
        best.append((time.perf_counter() - t0) / number)
    return float(np.median(best) * 1e6)


def nominal_spectral_radius(ctrl: Controller, settle: int = 3000) -> float:
    """Spectral radius of the loop with the network itself as the plant, linearised at the
    equilibrium it settles to: below 1 means nominally (perfect-model) stable."""
    fn = ctrl.function
    ny = ctrl.narx.n_outputs
    x = ca.MX.sym("x", ctrl.n_state)
    zeros_y = ca.DM.zeros(ny)
    zeros_u = ca.DM.zeros(ctrl.narx.n_inputs)
    nxt = fn(x[:ny], zeros_y, zeros_u, x)[1]
    loop = ca.Function("loop", [x], [nxt])
    loop_jac = ca.Function("loop_jac", [x], [ca.jacobian(nxt, x)])
    state = ctrl.initial_state(np.zeros(ny))
    for _ in range(settle):
        state = np.asarray(loop(state)).ravel()
        if not np.all(np.isfinite(state)):
            return math.inf
    jac = np.asarray(loop_jac(state))
    return float(np.max(np.abs(np.linalg.eigvals(jac))))


# ---- closed loop ------------------------------------------------------------------------------

@dataclass
class Run:
    """One closed-loop (or open-loop) run: absolute outputs and the torque added."""

    name: str
    t: np.ndarray
    y: np.ndarray
    tau: np.ndarray  # (N+1, nu) torque added to the scene's from each sample (last row 0)
    v: np.ndarray  # the outer loop's part (AIMNC), else zeros
    impacts: int
    seconds: float


Law = Callable[[int, np.ndarray], np.ndarray]


def run_loop(scene: Any, reference: np.ndarray, law: Law, name: str,
             clearance_model: Any | None = None) -> Run:
    """Step the scene's clearance robot with ``law(k, y)`` added to the scene's torques."""
    from jointplay.identify import measure
    from jointplay.simulation import Stepper

    stepper = Stepper(scene, model=clearance_model)
    joints = scene.robot.moving_joints
    index = [stepper.model.coordinates.index(f"q{j}") for j in joints]
    n = scene.run.n_outputs
    y = np.zeros_like(reference)
    tau = np.zeros((n + 1, len(joints)))
    start = time.perf_counter()
    for k in range(n + 1):
        y[k] = measure(stepper, index)
        if k == n:
            break
        tau[k] = law(k, y[k])
        stepper.step(tau[k])
    t = np.arange(n + 1) * scene.run.output_step
    return Run(name, t, y, tau, np.zeros_like(tau), len(stepper.impacts),
               time.perf_counter() - start)


def aimnc_law(ctrl: Controller, reference: np.ndarray, tau_ff: np.ndarray,
              log: dict[str, list[np.ndarray]]) -> Law:
    state: list[np.ndarray] = []

    def law(k: int, y: np.ndarray) -> np.ndarray:
        if k == 0:
            state[:] = [ctrl.initial_state(y - reference[0])]
        tau, nxt, v, pred = ctrl.step(y, reference[k], tau_ff[k], state[0])
        state[0] = nxt
        log["v"].append(v)
        log["y_pred"].append(pred)
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
    from jointplay.scene import ideal_counterpart
    from jointplay.simulation import load_scene_model

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


# ---- metrics ----------------------------------------------------------------------------------

METRICS = ("position", "velocity", "acceleration")
_SLICES = {"position": slice(0, 2), "velocity": slice(2, 4), "acceleration": slice(4, 6)}


def tip_errors(run: Run, reference: np.ndarray, nj: int) -> dict[str, np.ndarray]:
    """|end-effector error| per sample (Euclidean norm over x, y) for each quantity."""
    base = 2 * nj
    return {k: np.linalg.norm(run.y[:, base + s.start: base + s.stop]
                              - reference[:, base + s.start: base + s.stop], axis=1)
            for k, s in _SLICES.items()}


def run_metrics(run: Run, reference: np.ndarray, nj: int, transient: int) -> dict[str, float]:
    err = tip_errors(run, reference, nj)
    out: dict[str, float] = {}
    for k, e in err.items():
        out[f"max_{k}"] = float(np.max(e))
        out[f"max_{k}_after"] = float(np.max(e[transient:]))
        out[f"rms_{k}"] = float(np.sqrt(np.mean(e ** 2)))
        out[f"rms_{k}_after"] = float(np.sqrt(np.mean(e[transient:] ** 2)))
    out["max_torque_added"] = float(np.max(np.abs(run.tau)))
    out["impacts"] = float(run.impacts)
    return out


def metrics_table(metrics: dict[str, dict[str, float]], transient_s: float) -> str:
    """Markdown table: every controller side by side, and the open-loop / controller ratio."""
    cols = [("max_position", "max \\|Δp\\| [m]"), ("max_velocity", "max \\|Δv\\| [m/s]"),
            ("max_acceleration", "max \\|Δa\\| [m/s²]"),
            ("rms_acceleration", "RMS \\|Δa\\| [m/s²]")]
    ms = f"{transient_s * 1e3:g} ms"
    head = ("| controller | " + " | ".join(f"{label}" for _, label in cols)
            + f" | after {ms}: max \\|Δv\\| | max \\|Δa\\| | RMS \\|Δa\\| | impacts |")
    lines = [head, "|---" * (len(cols) + 5) + "|"]
    base = metrics.get("open loop")
    for name, mt in metrics.items():
        cells = [f"{mt[k]:.3g}" for k, _ in cols]
        cells += [f"{mt['max_velocity_after']:.3g}", f"{mt['max_acceleration_after']:.3g}",
                  f"{mt['rms_acceleration_after']:.3g}", f"{mt['impacts']:.0f}"]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    if base is not None:
        for name, mt in metrics.items():
            if name == "open loop":
                continue
            keys = [k for k, _ in cols] + ["max_velocity_after", "max_acceleration_after",
                                            "rms_acceleration_after"]
            cells = [f"{base[k] / mt[k]:.3g}x" if mt[k] > 0 else "-" for k in keys]
            lines.append(f"| reduction, {name} | " + " | ".join(cells) + " | |")
    return "\n".join(lines)


# ---- plots ------------------------------------------------------------------------------------

def _figure(rows: int, cols: int, width: float, height: float) -> tuple[Figure, np.ndarray]:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    return fig, fig.subplots(rows, cols, squeeze=False, sharex=True)


def _save(fig: Figure, path: Path) -> Path:
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=130)
    return path


def plot_runs(runs: dict[str, Run], reference: np.ndarray, joints: Sequence[int],
              folder: Path, scene_name: str) -> list[Path]:
    """Figures like the paper's 10 (responses) and 11 (errors), and the torques."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise DescriptionError("--plot", f"cannot create folder {folder}: {err}") from None
    nj = len(joints)
    base = 2 * nj
    t = next(iter(runs.values())).t
    labels = (("displacement", "m"), ("velocity", "m/s"), ("acceleration", "m/s²"))
    colors = {"open loop": "C3", "PD": "C2", "computed torque": "C4", "AIMNC": "C0"}
    paths = []
    fig, axes = _figure(3, 2, 12, 9)
    for row, (label, unit) in enumerate(labels):
        for c, comp in enumerate("xy"):
            ax = axes[row, c]
            col = base + 2 * row + c
            ax.plot(t, reference[:, col], "k--", lw=0.9, label="ideal joints (reference)")
            for name in ("open loop", "AIMNC"):
                if name in runs:
                    ax.plot(t, runs[name].y[:, col], color=colors[name], lw=1.0,
                            label="clearance, " + ("no control" if name == "open loop"
                                                   else "AIMNC"))
            ax.set_ylabel(f"{comp} {label} [{unit}]")
            ax.grid(True, alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    fig.suptitle(f"{scene_name}: end-effector response with and without control")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=3)
    paths.append(_save(fig, folder / "control_response.png"))

    fig, axes = _figure(3, 1, 10, 9)
    for row, (label, unit) in enumerate(labels):
        ax = axes[row, 0]
        floor = math.inf
        for name, run in runs.items():
            e = tip_errors(run, reference, nj)[METRICS[row]]
            floor = min(floor, 0.01 * float(np.median(e[1:])) if e.size > 1 else 1e-12)
            ax.semilogy(t[1:], np.maximum(e[1:], 1e-15), color=colors.get(name, "C5"),
                        lw=1.2 if name in ("open loop", "AIMNC") else 0.7, label=name)
        if math.isfinite(floor) and floor > 0:
            ax.set_ylim(bottom=floor)  # both runs start on the reference: e(0) = 0
        ax.set_ylabel(f"|{label} error| [{unit}]")
        ax.grid(True, which="both", alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle(f"{scene_name}: end-effector error vs the ideal-joint robot")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=4)
    paths.append(_save(fig, folder / "control_error.png"))

    fig, axes = _figure(nj, 1, 10, 2.6 * nj + 1)
    for j in range(nj):
        ax = axes[j, 0]
        for name, run in runs.items():
            if name == "open loop":
                continue
            ax.plot(t, run.tau[:, j], color=colors.get(name, "C5"), lw=0.9,
                    label=f"{name}: added torque")
        if "AIMNC" in runs:
            ax.plot(t, runs["AIMNC"].v[:, j], color="C1", lw=0.9, label="AIMNC: outer loop v")
        ax.set_ylabel(f"joint {joints[j]} torque [N m]")
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=4)
    paths.append(_save(fig, folder / "control_torque.png"))
    return paths


# ---- the whole comparison -----------------------------------------------------------------

@dataclass
class Comparison:
    runs: dict[str, Run]
    reference: np.ndarray
    metrics: dict[str, dict[str, float]]
    transient: int
    per_call_us: float
    spectral_radius: float
    controller: Controller


def compare(scene: Any, narx: Narx, settings: ControllerSettings, *,
            transient: float = DEFAULT_TRANSIENT, ct_omega: float = 15.0,
            ct_zeta: float = 0.2, pd_kp: Sequence[float] = (), pd_kd: Sequence[float] = (),
            controllers: Sequence[str] = CONTROLLERS, quiet: bool = True,
            analyse: bool = True) -> Comparison:
    """Run the scene with every controller against the ideal robot's motion.

    ``analyse`` also measures the compiled step's cost and the nominal spectral radius.
    """
    from jointplay.identify import ideal_reference, reference_outputs
    from jointplay.simulation import load_scene_model

    ideal = ideal_reference(scene)
    reference = reference_outputs(ideal)
    ctrl = compile_controller(narx, settings)
    cost = per_call_us(ctrl) if analyse else math.nan
    radius = nominal_spectral_radius(ctrl) if analyse else math.nan
    model = load_scene_model(scene)
    nj = len(scene.robot.moving_joints)
    runs: dict[str, Run] = {}
    for name in controllers:
        log: dict[str, list[np.ndarray]] = {"v": [], "y_pred": []}
        if name == "open loop":
            law: Law = lambda k, y: np.zeros(nj)  # noqa: E731
        elif name == "PD":
            law = pd_law(narx, reference, pd_kp, pd_kd)
        elif name == "computed torque":
            law = computed_torque_law(scene, ideal, reference, ct_omega, ct_zeta)
        else:
            law = aimnc_law(ctrl, reference, ideal.tau, log)
        run = run_loop(scene, reference, law, name, model)
        if log["v"]:
            run.v[: len(log["v"])] = np.array(log["v"])
        runs[name] = run
        if not quiet:
            print(f"  {name}: {run.seconds:.1f} s, {run.impacts} impacts", flush=True)
    k0 = max(0, round(transient / scene.run.output_step))
    metrics = {name: run_metrics(run, reference, nj, k0) for name, run in runs.items()}
    return Comparison(runs, reference, metrics, k0, cost, radius, ctrl)


def write_runs(path: Path, comparison: Comparison, meta: dict[str, Any]) -> None:
    import h5py

    with atomic_path(path) as tmp, h5py.File(tmp, "w") as f:
        f.attrs["format"] = "jointplay-control"
        f.attrs["meta"] = json.dumps(meta, default=str)
        f.create_dataset("reference", data=comparison.reference)
        for name, run in comparison.runs.items():
            g = f.create_group(name)
            for key in ("t", "y", "tau", "v"):
                g.create_dataset(key, data=getattr(run, key))
            g.attrs["metrics"] = json.dumps(comparison.metrics[name])


# ---- the command ------------------------------------------------------------------------------

def _floats(text: str | None, flag: str, count: int | None = None,
            positive: bool = True) -> tuple[float, ...]:
    from jointplay.identify import _floats as parse

    return parse(text, flag, count, positive)


def test_case_scenes(model_dir: Path, scene: Any) -> list[tuple[str, Any]]:
    """Scenes driven by the base torques of the stored test trajectories."""
    from jointplay.expressions import TableColumn, parse_expression
    from jointplay.identify import Chirp, Multisine, read_datasets, with_torques

    path = model_dir / "datasets.h5"
    if not path.is_file():
        raise DescriptionError("--test-cases", f"{path} is missing; the model folder has no "
                               "stored test trajectories (run `jointplay identify` again)")
    trajectories, meta = read_datasets(path)
    out = []
    for tr in (t for t in trajectories if t.split == "test"):
        torques: list[Any] = []
        for i, desc in enumerate(tr.description.get("base", [])):
            kind = desc.get("kind")
            if kind == "multisine":
                torques.append(Multisine(np.array(desc["amplitude"]), np.array(desc["frequency"]),
                                         np.array(desc["phase"])))
            elif kind == "chirp":
                torques.append(Chirp(desc["amplitude"], desc["f0"], desc["f1"],
                                     desc["duration"], desc["phase"]))
            elif kind == "steps":
                torques.append(TableColumn(f"joint{i}", np.array(desc["times"]),
                                           np.array(desc["values"])))
            else:
                torques.append(parse_expression(desc["text"], field="torques",
                                                constants=scene.constants))
        duration = float(tr.t[-1])
        out.append((f"test {tr.family}", with_torques(scene.with_run(t_end=duration), torques)))
    del meta
    return out


def cmd_control(args: argparse.Namespace) -> int:
    """``jointplay control``: validate, compile, run every controller, report and plot."""
    from jointplay.identify import _load_scene_arg

    scene = _load_scene_arg(args.scene, args.quiet)
    model_dir = Path(args.model)
    narx = load_narx(model_dir)
    check_robot(narx, scene.robot, scene.run.output_step, model_dir / MODEL_FILE)
    tracked = tuple(n.strip() for n in args.track.split(",") if n.strip()) if args.track else ()
    settings = ControllerSettings(
        horizon=args.horizon, regularisation=args.lambda_, setpoint_filter=args.setpoint_filter,
        mismatch_filter=args.mismatch_filter, tracked=tracked,
        scales=_floats(args.scales, "--scales"),
        torque_limit=_floats(args.torque_limit, "--torque-limit"),
        rate_limit=_floats(args.rate_limit, "--rate-limit"), iterations=args.iterations)
    settings = resolve_settings(narx, settings)
    nj = len(scene.robot.moving_joints)
    pd_kp = _floats(args.pd_kp, "--pd-kp", nj)
    pd_kd = _floats(args.pd_kd, "--pd-kd", nj, positive=False)
    for flag, value in (("--ct-omega", args.ct_omega), ("--ct-zeta", args.ct_zeta)):
        if not (math.isfinite(value) and value > 0):
            raise DescriptionError(flag, f"must be a positive number, got {value}")
    if not (math.isfinite(args.transient) and 0 <= args.transient < scene.run.t_end):
        raise DescriptionError("--transient", f"must be in [0, run.t_end), got {args.transient}")
    if args.plot:
        plot = Path(args.plot)
        if plot.exists() and not plot.is_dir():
            raise DescriptionError("--plot", f"{plot} exists and is not a folder")
        try:
            plot.mkdir(parents=True, exist_ok=True)
        except OSError as err:
            raise DescriptionError("--plot", f"cannot create folder {plot}: {err}") from None
    if args.out:
        from jointplay.output import check_output_path
        from jointplay.scene import scene_inputs

        check_output_path(args.out, "--out",
                          inputs=[*scene_inputs(scene), model_dir / MODEL_FILE,
                                  model_dir / "datasets.h5"])
    cases = test_case_scenes(model_dir, scene) if args.test_cases else []

    quiet = args.quiet
    if not quiet:
        print(f"scene {scene.name}: reference = ideal-joint robot under the scene's torques; "
              f"plant = compiled clearance model; controller every {scene.run.output_step:g} s")
    comparison = compare(scene, narx, settings, transient=args.transient,
                         ct_omega=args.ct_omega, ct_zeta=args.ct_zeta, pd_kp=pd_kp,
                         pd_kd=pd_kd, quiet=quiet)
    table = metrics_table(comparison.metrics, args.transient)
    ctrl = comparison.controller
    lines = [
        "",
        f"End-effector errors vs the ideal-joint robot ({scene.name}, {scene.run.t_end:g} s; "
        "norms over x, y):",
        "",
        table,
        "",
        f"AIMNC: horizon {settings.horizon}, lambda {settings.regularisation:g}, setpoint "
        f"filter {settings.setpoint_filter:g}, mismatch filter {settings.mismatch_filter:g}, "
        f"tracked {', '.join(settings.tracked)}; inner PD kp "
        f"{narx.context['plant']['inner_loop']['kp']}, kd "
        f"{narx.context['plant']['inner_loop']['kd']}; PD baseline kp "
        f"{list(pd_kp) or narx.context['plant']['inner_loop']['kp']}, kd "
        f"{list(pd_kd) or narx.context['plant']['inner_loop']['kd']}; computed torque omega "
        f"{args.ct_omega:g} rad/s, zeta {args.ct_zeta:g}",
        f"compiled controller step: {comparison.per_call_us:.2f} us per call (buffer path; "
        f"compile {ctrl.compile_seconds:.2f} s, 0 if cached); nominal loop spectral radius "
        f"{comparison.spectral_radius:.6f} "
        f"({'stable' if comparison.spectral_radius < 1 else 'NOT stable'})",
    ]
    if scene.name == "paper_4dof":
        lines.append("paper (its robot, with control): max |Δp| 2.4e-4 m, max |Δv| 7.7e-3 m/s, "
                     "acceleration error reduced tenfold")
    case_rows = []
    for label, case_scene in cases:
        sub = compare(case_scene, narx, settings, transient=args.transient,
                      controllers=("PD", "AIMNC"), quiet=True, analyse=False)
        pd_m, ai_m = sub.metrics["PD"], sub.metrics["AIMNC"]
        bounded = bool(np.all(np.isfinite(sub.runs["AIMNC"].y))) and \
            ai_m["max_position"] < 10 * pd_m["max_position"]
        case_rows.append(f"| {label} | {pd_m['max_position']:.3g} | {ai_m['max_position']:.3g} "
                         f"| {pd_m['max_velocity_after']:.3g} | "
                         f"{ai_m['max_velocity_after']:.3g} | "
                         f"{np.max(np.abs(sub.runs['AIMNC'].v)):.3g} | "
                         f"{'yes' if bounded else 'NO'} |")
    if case_rows:
        lines += ["", "Closed loop on the stored test excitations (never used in training):", "",
                  "| case | PD max \\|Δp\\| [m] | AIMNC max \\|Δp\\| [m] | PD max \\|Δv\\| after "
                  "[m/s] | AIMNC max \\|Δv\\| after [m/s] | AIMNC max \\|v\\| [N m] | bounded |",
                  "|---|---|---|---|---|---|---|", *case_rows]
    text = "\n".join(lines)
    written = []
    if args.plot:
        written += [str(p) for p in plot_runs(comparison.runs, comparison.reference,
                                              scene.robot.moving_joints, Path(args.plot),
                                              scene.name)]
        atomic_write_text(Path(args.plot) / "control.md", text.strip() + "\n")
        written.append(str(Path(args.plot) / "control.md"))
    if args.out:
        write_runs(Path(args.out), comparison,
                   {"settings": asdict(settings), "scene": scene.name,
                    "per_call_us": comparison.per_call_us,
                    "spectral_radius": comparison.spectral_radius,
                    "network_checksum": narx.checksum()})
        written.append(args.out)
    if not quiet:
        print(text)
        for path in written:
            print(f"wrote {path}")
    return 0


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``control`` to a ``jointplay`` argument parser's subcommands."""
    d = ControllerSettings()
    p = subparsers.add_parser(
        "control", help="closed-loop runs of the neural controller and baselines against the "
                        "ideal robot's motion",
        description="Track the ideal-joint robot's motion with the clearance robot: open loop, "
                    "PD, computed torque (ideal model) and the approximate internal-model "
                    "neural controller (compiled), side by side.")
    p.add_argument("scene", nargs="?", help="scene file (TOML); default: the paper scene")
    p.add_argument("--model", required=True, metavar="MODEL_DIR",
                   help="folder written by `jointplay identify`")
    p.add_argument("--plot", metavar="DIR", help="write figures and the table (control.md) here")
    p.add_argument("--out", metavar="RUN.h5", help="write every run and the metrics (HDF5)")
    p.add_argument("--horizon", type=int, default=d.horizon,
                   help="samples ahead the prediction is matched (default %(default)s)")
    p.add_argument("--lambda", dest="lambda_", type=float, default=d.regularisation,
                   help="regularisation of the inverse (default %(default)s)")
    p.add_argument("--setpoint-filter", type=float, default=d.setpoint_filter,
                   help="a in y_d(k+1) = a y_d(k) + (1 - a) r(k+1) (default %(default)s)")
    p.add_argument("--mismatch-filter", type=float, default=d.mismatch_filter,
                   help="b of the first-order mismatch filter (default %(default)s)")
    p.add_argument("--iterations", type=int, default=d.iterations,
                   help="linearisations per step (default %(default)s: the AIMNC law)")
    p.add_argument("--track", help="outputs the controller matches, e.g. q2,q3 (default: the "
                                   "moving joints' angles)")
    p.add_argument("--scales", help="error of each tracked output that counts as 1 (default: "
                                    "its spread in the training data)")
    p.add_argument("--torque-limit", help="actuator limits per driven joint, N m (default: "
                                          "the model's)")
    p.add_argument("--rate-limit", help="limit on the outer loop's torque rate per driven "
                                        "joint, N m/s (default: 10 x the torque limit)")
    p.add_argument("--pd-kp", help="PD baseline stiffness per driven joint, N m/rad (default: "
                                   "the inner loop's)")
    p.add_argument("--pd-kd", help="PD baseline damping per driven joint, N m s/rad (default: "
                                   "the inner loop's)")
    p.add_argument("--ct-omega", type=float, default=15.0,
                   help="computed-torque baseline bandwidth, rad/s (default %(default)s)")
    p.add_argument("--ct-zeta", type=float, default=0.2,
                   help="computed-torque baseline damping ratio (default %(default)s)")
    p.add_argument("--transient", type=float, default=DEFAULT_TRANSIENT,
                   help="seconds at the start reported separately (journals settling; "
                        "default %(default)s)")
    p.add_argument("--test-cases", action="store_true",
                   help="also run PD and AIMNC on the model's stored test excitations")
    p.add_argument("--quiet", action="store_true", help="no progress, no report")
    p.set_defaults(func=cmd_control)
    return p


__all__ = ["CONTROLLERS", "Comparison", "Controller", "ControllerSettings", "Run",
           "build_step", "compare", "compile_controller", "computed_torque_law",
           "generate_c", "metrics_table", "nominal_spectral_radius", "per_call_us", "plot_runs",
           "register", "resolve_settings", "run_loop", "run_metrics"]
