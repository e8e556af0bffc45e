"""The internal-model controller step: the law, its guard, and the compiled C.

The plant the models identified is the clearance robot under a joint PD around the ideal
robot's motion; its input is the torque v added to the PD's, its outputs y the deviations from
the ideal robot. At every sample k the step, for its internal model M (the NARX network, or the
linear ARX twin),

1. compares the measured deviation with M's free-run prediction, e(k) = y(k) - y^(k), and
   filters it, e_f(k) = b e_f(k-1) + (1 - b) e(k) (unity DC gain);
2. runs M d samples ahead with the input held, linearised about the previous input:
   y^(k+d) ~ N0(k) + J(k) dv (for the ARX model N0 is a constant matrix times the state and J
   a constant);
3. solves the regularised inverse on the tracked outputs (rows of C, scaled),
   dv = ((CJ)'(CJ) + lam I)^-1 (CJ)' C (y_d(k+d) - e_f(k) - N0(k));
4. limits the rate of v, keeps v inside what the model was trained on and the total actuator
   torque inside its limits, and advances the internal models with the v applied.

The guard. A network is trustworthy only where it was trained. The step checks, every sample,
that the internal model's regressor and its d-step prediction lie inside the training range
(widened by a margin), that they are finite, and that the mismatch on the tracked outputs stays
below a bound (filtered, like the mismatch the law uses: a single impact does not trip it; a
model running away does). When a check fails, the step uses the fallback model's increment
instead (the ARX twin runs in parallel, always advanced with the applied input), re-seeds the
network's history from it and stays on the fallback for a hold time that doubles with each
episode; when the fallback fails its own checks too, the outer loop lets go (v ramps to zero,
the inner PD alone). Every intervention comes out in the step's flags, and the closed loop
counts them.

The step is one CasADi SX function, generated to C and compiled through the robot models'
cache. Its cost is what the controller costs: see benchmarks/control_step.py.
"""

from __future__ import annotations

import hashlib
import json
import math
import time
from dataclasses import asdict, dataclass, field, replace
from importlib.metadata import version
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.neural.narx import Narx

STEP_NAME = "imc_step"
# What the flags output reports, one entry per sample (1.0 when it happened).
FLAGS = ("model_distrusted", "on_fallback_model", "inner_loop_only", "input_at_trust_bound",
         "torque_at_limit")
# The loop kernel is a few kilobytes: -O3 compiles it in about a second and vectorises its
# column sums (2x faster than -O2 here, benchmarks/control_step.py). CasADi's straight-line
# code (iterations > 1) keeps the models' -O1: -O2 compiled it 2.5x longer for no gain.
STEP_CFLAGS = ("-O3", "-fPIC", "-shared", "-fno-math-errno")
SX_CFLAGS = ("-O1", "-fPIC", "-shared", "-fno-math-errno")


@dataclass(frozen=True)
class ControllerSettings:
    """The controller's tuning; every field has a command-line flag of the same name."""

    horizon: int = 5  # d: samples ahead the prediction is matched (5: as good as 10, half
    # the cost; 3 lost 4x in acceleration on one of two seeds: docs/control.md)
    regularisation: float = 1e-3  # lam, in units of the scaled outputs per (N m)^2
    setpoint_filter: float = 0.9  # a: the target leaves the deviation measured at
    # engagement over about 10 samples instead of at once (median RMS |Δa| over 10 seeds,
    # offset case 1.33e-3 -> 1.25e-3, scene 9.9e-4 -> 9.8e-4; docs/control.md)
    mismatch_filter: float = 0.9  # b
    tracked: tuple[str, ...] = ()  # outputs in C; default: see default_tracked
    scales: tuple[float, ...] = ()  # error of each tracked output that counts as 1
    torque_limit: tuple[float, ...] = ()  # |feedforward + PD + v| per joint, N m
    rate_limit: tuple[float, ...] = ()  # |dv/dt| per joint, N m/s
    iterations: int = 1  # Gauss-Newton steps on the linearisation (1: the AIMNC law)
    guard: bool = True  # trust region and fallback (off only to show what it prevents)
    trust_input: float = 2.0  # |v| <= this x the largest |v| in training
    trust_range: float = 0.5  # regressor within the training range widened by this x its width
    trust_mismatch: float = 10.0  # |C e| (scaled tracked mismatch) at most this
    fallback_hold: int = 100  # samples on the fallback after a first intervention
    # s the outer loop waits at the start (v = 0, the inner PD alone) before it starts its
    # models from the measured history; None: twice the start-up the model's training runs
    # left out (the journals falling from the centred start and bouncing, which no joint
    # torque prevents; engaging at its end the IMC still removed the decaying bounce in a
    # few samples: offset case, median RMS |Δa| 2.15e-3 against 1.25e-3; docs/control.md).
    engage: float | None = None


@dataclass
class Controller:
    """A compiled controller step, bound to preallocated buffers."""

    model: Narx
    fallback: Narx | None
    settings: ControllerSettings
    function: ca.Function  # the CasADi step (uncompiled), for checks and analysis
    library: Path | None
    compile_seconds: float
    source: str
    fast: Any = None  # FastFunction over the compiled step
    n_state: int = 0
    layout: dict[str, Any] = field(default_factory=dict)

    @property
    def narx(self) -> Narx:
        return self.model

    def initial_state(self, deviation: np.ndarray,
                      past: np.ndarray | None = None) -> np.ndarray:
        """Internal models started at the measured deviation, no added torque, no mismatch.

        ``past``: earlier measured deviations, newest first (rows), for the models' older
        lags (without them every lag holds ``deviation``: a history at rest)."""
        m = self.model
        # The models start at the nearest output they were trained on: the plant's first
        # sample can lie outside (the journals start centred, off their resting point, and
        # the first 50 ms of every training run are left out).
        lo, hi = training_box(m, 0.0)
        rows = [np.asarray(deviation, dtype=float)]
        if past is not None:
            rows += list(np.atleast_2d(np.asarray(past, dtype=float)))

        def history(lags: int) -> np.ndarray:
            return np.concatenate([np.clip(rows[min(i, len(rows) - 1)], lo[: m.n_outputs],
                                           hi[: m.n_outputs]) for i in range(lags)])
        parts = [history(m.output_lags)]
        if self.fallback is not None:
            parts.append(history(self.fallback.output_lags))
        parts += [np.zeros(m.input_lags * m.n_inputs), np.zeros(m.n_outputs)]
        if self.fallback is not None:
            parts.append(np.zeros(m.n_outputs))
        parts += [np.asarray(deviation, dtype=float), np.zeros(2)]
        return np.concatenate(parts)

    def step(self, y: np.ndarray, r: np.ndarray, tau_ff: np.ndarray,
             state: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(added torque, next state, v, predicted deviation) through the compiled code; the
        flags of the step are in :attr:`last_flags`."""
        f = self.fast
        f.inputs[0][:] = y
        f.inputs[1][:] = r
        f.inputs[2][:] = tau_ff
        f.inputs[3][:] = state
        f.trigger()
        return (f.outputs[0].copy(), f.outputs[1].copy(), f.outputs[2].copy(),
                f.outputs[3].copy())

    @property
    def last_flags(self) -> np.ndarray:
        return np.asarray(self.fast.outputs[4]).copy()


# ---- settings ---------------------------------------------------------------------------------

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
    # The axis along which the tip moved most in the training data (driven by the same
    # torques). Choosing it from the network's own d-step gain, as before, picked the axis
    # along the arm for two of ten seeds at d = 5, and those loops failed (docs/control.md).
    del horizon
    axis = max("xy", key=lambda a: float(narx.output_scale[narx.output_index(f"tip_{a}")]))
    out = [f"tip_{axis}", f"tip_v{axis}"]
    for j in joints[len(joints) - (narx.n_inputs - 1):] if narx.n_inputs > 1 else []:
        out += [f"q{j}", f"dq{j}"]
    return tuple(out)


def resolve_settings(narx: Narx, settings: ControllerSettings) -> ControllerSettings:
    """Fill defaults from the model and check every value against it (errors name the flag)."""
    plant = narx.context.get("plant", {})
    nu = narx.n_inputs
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
             and 1 <= settings.iterations <= 20, "an integer from 1 to 20"),
            ("--trust-input", settings.trust_input, math.isfinite(settings.trust_input)
             and settings.trust_input > 0, "a positive number"),
            ("--trust-range", settings.trust_range, math.isfinite(settings.trust_range)
             and settings.trust_range >= 0, "a number >= 0"),
            ("--trust-mismatch", settings.trust_mismatch,
             math.isfinite(settings.trust_mismatch) and settings.trust_mismatch > 0,
             "a positive number"),
            ("--fallback-hold", settings.fallback_hold, isinstance(settings.fallback_hold, int)
             and settings.fallback_hold >= 1, "an integer >= 1"),
            ("--engage", settings.engage, settings.engage is None
             or (math.isfinite(settings.engage) and settings.engage >= 0), "a number >= 0")):
        if not ok:
            raise DescriptionError(flag, f"must be {allowed}, got {value!r}")
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
    engage = settings.engage if settings.engage is not None else 2.0 * float(
        plant.get("transient", 0.0))
    return replace(settings, tracked=tuple(tracked), scales=tuple(float(s) for s in scales),
                   torque_limit=tuple(float(v) for v in limits),
                   rate_limit=tuple(float(v) for v in rates), engage=engage)


def training_box(model: Narx, margin: float) -> tuple[np.ndarray, np.ndarray]:
    """The regressor range the model was trained on, widened by ``margin`` x its width on
    each side (models saved without a range: mean -+ 4 standard deviations)."""
    rng = model.context.get("training_range")
    if rng:
        lo = np.asarray(rng["regressor_min"], dtype=float)
        hi = np.asarray(rng["regressor_max"], dtype=float)
    else:
        lo = model.regressor_mean - 4 * model.regressor_scale
        hi = model.regressor_mean + 4 * model.regressor_scale
    width = np.maximum(hi - lo, 1e-12 * np.maximum(1.0, np.abs(hi)))
    return lo - margin * width, hi + margin * width


def input_bound(model: Narx, factor: float) -> np.ndarray:
    """|v| allowed per input: ``factor`` x the largest |v| of the training data."""
    ny, nu, na = model.n_outputs, model.n_inputs, model.output_lags
    lo, hi = training_box(model, 0.0)
    cols = slice(na * ny, na * ny + nu)
    return factor * np.maximum(np.abs(lo[cols]), np.abs(hi[cols]))


def _inner_gains(narx: Narx) -> tuple[list[int], list[int], np.ndarray, np.ndarray]:
    """Output indices of the PD's angle and speed deviations, and its gains."""
    inner = narx.context.get("plant", {}).get("inner_loop", {})
    joints = inner.get("joints", [])
    if not joints:
        return [], [], np.zeros(0), np.zeros(0)
    q = [narx.output_index(f"q{j}") for j in joints]
    dq = [narx.output_index(f"dq{j}") for j in joints]
    return q, dq, np.asarray(inner["kp"], dtype=float), np.asarray(inner["kd"], dtype=float)


# ---- one internal model inside the step -----------------------------------------------------

def is_linear(model: Narx) -> bool:
    return len(model.weights) == 1


def _rollout(model: Narx, hist: Any, upast: Any, v: Any, d: int) -> Any:
    """y^(k+d) with the input held at v over the horizon (symbolic)."""
    net = model.casadi_function("net")
    ny, nu, na, nb = model.n_outputs, model.n_inputs, model.output_lags, model.input_lags
    ys = [hist[i * ny:(i + 1) * ny] for i in range(na)]
    us = [v] + [upast[i * nu:(i + 1) * nu] for i in range(nb - 1)]
    for _ in range(d):
        nxt = net(ca.vertcat(*ys, *us))
        ys = [nxt, *ys[:-1]]
        us = [v, *us[:-1]]
    return ys[0]


def affine_rollout(model: Narx, d: int) -> tuple[np.ndarray, np.ndarray, np.ndarray,
                                                  np.ndarray]:
    """For a linear model: y^(k+d) = Mh hist + Mu upast + Mv v + c, exactly (constants)."""
    ny, nu = model.n_outputs, model.n_inputs
    hist = ca.MX.sym("h", model.output_lags * ny)
    upast = ca.MX.sym("u", model.input_lags * nu)
    v = ca.MX.sym("v", nu)
    y = _rollout(model, hist, upast, v, d)
    f = ca.Function("aff", [hist, upast, v], [ca.jacobian(y, hist), ca.jacobian(y, upast),
                                              ca.jacobian(y, v), y])
    mh, mu, mv, c = (np.asarray(a) for a in f(np.zeros(hist.numel()),
                                              np.zeros(upast.numel()), np.zeros(nu)))
    return mh, mu, mv, c.ravel()


@dataclass
class _Branch:
    """One internal model's increment, trust, and next history (symbolic)."""

    dv: Any
    ok: Any
    e_f: Any
    hist_next: Any  # after advancing with the applied v: filled in later
    predict: Any  # function of the applied v -> next output


def _branch(model: Narx, s: ControllerSettings, hist: Any, upast: Any, v_prev: Any,
            e_f_prev: Any, dev: Any, target: Any, cm: np.ndarray, sym: Any) -> _Branch:
    ny, nu, na, d = model.n_outputs, model.n_inputs, model.output_lags, s.horizon
    e = dev - hist[:ny]
    e_f = s.mismatch_filter * e_f_prev + (1 - s.mismatch_filter) * e
    cmd = ca.DM(cm)
    lam = s.regularisation * ca.DM.eye(nu)
    if is_linear(model):
        mh, mu, mv, c = affine_rollout(model, d)
        n0 = ca.mtimes(ca.DM(mh), hist) + ca.mtimes(ca.DM(mu), upast) \
            + ca.mtimes(ca.DM(mv), v_prev) + ca.DM(c)
        cj = cm @ mv
        gain = np.linalg.solve(cj.T @ cj + s.regularisation * np.eye(nu), cj.T)
        step = ca.mtimes(ca.DM(gain), ca.mtimes(cmd, target - e_f - n0))
    else:
        dv = sym.sym("dv", nu)
        hs = sym.sym("h", na * ny)
        us = sym.sym("u", upast.numel())
        vp = sym.sym("vp", nu)
        y_end = _rollout(model, hs, us, vp + dv, d)
        linear = ca.Function("linearised", [hs, us, vp, dv], [y_end, ca.jacobian(y_end, dv)])
        step = sym.zeros(nu, 1)
        n0 = None
        for _ in range(s.iterations):
            n_val, jac = linear(hist, upast, v_prev, step)
            n0 = n_val if n0 is None else n0
            cj = ca.mtimes(cmd, jac)
            residual = ca.mtimes(cmd, target - e_f - n_val)
            rhs = ca.mtimes(cj.T, residual) - s.regularisation * step
            step = step + ca.solve(ca.mtimes(cj.T, cj) + lam, rhs)
    if s.guard:
        lo, hi = training_box(model, s.trust_range)
        phi = ca.vertcat(hist, v_prev, upast[: (model.input_lags - 1) * nu])
        checks = [phi - ca.DM(lo), ca.DM(hi) - phi,  # >= 0 inside the box
                  n0 - ca.DM(lo[:ny]), ca.DM(hi[:ny]) - n0,
                  s.trust_mismatch - ca.fabs(ca.mtimes(cmd, e_f))]
        worst = ca.mmin(ca.vertcat(*checks))
        # NaN compares false: a non-finite regressor or increment is distrusted too.
        ok = ca.logic_and(worst >= 0, ca.mmin(ca.vertcat(ca.fabs(step) < 1e300)) > 0)
    else:
        ok = ca.DM(1.0)
    net = model.casadi_function("net_next")
    nb = model.input_lags

    def predict(v_new: Any) -> Any:
        return net(ca.vertcat(*[hist[i * ny:(i + 1) * ny] for i in range(na)], v_new,
                              *[upast[i * nu:(i + 1) * nu] for i in range(nb - 1)]))
    return _Branch(step, ok, e_f, None, predict)


def build_step(model: Narx, settings: ControllerSettings, fallback: Narx | None = None,
               sym: Any = ca.SX) -> tuple[ca.Function, dict[str, Any]]:
    """The controller step as a CasADi function (see the module docstring for the law).

    Inputs: y (measured outputs), r (the reference's outputs), tau_ff (the feedforward torque
    at this sample, for the actuator limit) and state. Outputs: tau (torque to add to the
    feedforward: PD + v), state_next, v, y_pred (the internal model's deviation at k+1) and
    flags (see FLAGS).
    """
    s = settings
    m = model
    ny, nu, na, nb, d = m.n_outputs, m.n_inputs, m.output_lags, m.input_lags, s.horizon
    if len(s.torque_limit) != nu:
        raise ValueError("resolve the settings first (resolve_settings)")
    if fallback is not None and (fallback.output_names != m.output_names
                                 or fallback.input_names != m.input_names):
        raise ValueError("the fallback model must have the same outputs and inputs")
    if fallback is not None and not s.guard:
        fallback = None
    naf = fallback.output_lags if fallback is not None else 0
    n_state = na * ny + naf * ny + nb * nu + ny + (ny if fallback else 0) + ny + 2

    y = sym.sym("y", ny)
    r = sym.sym("r", ny)
    tau_ff = sym.sym("tau_ff", nu)
    state = sym.sym("state", n_state)
    at = 0

    def take(n: int) -> Any:
        nonlocal at
        part = state[at: at + n]
        at += n
        return part
    hist = take(na * ny)
    hist_f = take(naf * ny) if fallback is not None else None
    upast = take(nb * nu)
    e_f_prev = take(ny)
    e_f_prev_f = take(ny) if fallback is not None else None
    y_d = take(ny)
    hold, episodes = take(1), take(1)
    v_prev = upast[:nu]

    dev = y - r
    target = (s.setpoint_filter ** d) * y_d
    rows = [m.output_index(name) for name in s.tracked]
    cm = np.zeros((len(rows), ny))
    for i, (row, scale) in enumerate(zip(rows, s.scales, strict=True)):
        cm[i, row] = 1.0 / scale
    main = _branch(m, s, hist, upast, v_prev, e_f_prev, dev, target, cm, sym)
    use_main = ca.logic_and(main.ok, hold <= 0)
    if fallback is not None:
        back = _branch(fallback, s, hist_f, upast, v_prev, e_f_prev_f, dev, target, cm, sym)
        use_back = ca.logic_and(ca.logic_not(use_main), back.ok)
        step = ca.if_else(use_main, main.dv, ca.if_else(use_back, back.dv, -v_prev))
    else:
        use_back = ca.DM(0.0)
        step = ca.if_else(use_main, main.dv, -v_prev)
    inner_only = ca.logic_not(ca.logic_or(use_main, use_back))
    rate = ca.DM([rl * m.sample_time for rl in s.rate_limit])
    step = ca.fmin(ca.fmax(step, -rate), rate)
    v_try = v_prev + step
    if s.guard:
        bound = ca.DM(input_bound(m, s.trust_input))
        v_trusted = ca.fmin(ca.fmax(v_try, -bound), bound)
    else:
        v_trusted = v_try
    q_idx, dq_idx, kp, kd = _inner_gains(m)
    inner = (-ca.DM(kp) * dev[q_idx] - ca.DM(kd) * dev[dq_idx]) if q_idx else sym.zeros(nu, 1)
    limit = ca.DM([lim if math.isfinite(lim) else 1e300 for lim in s.torque_limit])
    v_new = ca.fmin(ca.fmax(v_trusted, -limit - tau_ff - inner), limit - tau_ff - inner)
    total = ca.fmin(ca.fmax(tau_ff + inner + v_new, -limit), limit)
    tau = total - tau_ff

    y_next = main.predict(v_new)
    new_hist = ca.vertcat(y_next, hist[: (na - 1) * ny])
    parts = []
    if fallback is not None:
        assert hist_f is not None
        yf_next = back.predict(v_new)
        new_hist_f = ca.vertcat(yf_next, hist_f[: (naf - 1) * ny])
        # Off the network, its history follows the fallback's (a sane restart point).
        if naf == na:
            new_hist = ca.if_else(use_main, new_hist, new_hist_f)
        e_f_main = ca.if_else(use_main, main.e_f, back.e_f)
        parts = [new_hist, new_hist_f]
    else:
        e_f_main = main.e_f
        parts = [new_hist]
    distrusted = ca.logic_not(main.ok)
    first = ca.logic_and(distrusted, hold <= 0)
    episodes_next = episodes + ca.if_else(first, 1, 0)
    # 2^(episodes - 1) without a pow: the hold doubles with each episode, up to 64x.
    doubling = ca.DM([2.0 ** i for i in range(7)])
    length = s.fallback_hold * ca.mmax(ca.if_else(
        ca.DM(np.arange(7)) <= ca.fmax(episodes_next - 1, 0), doubling, ca.DM.zeros(7)))
    hold_next = ca.if_else(distrusted, length, ca.fmax(hold - 1, 0))
    new_upast = ca.vertcat(v_new, upast[: (nb - 1) * nu])
    parts += [new_upast, e_f_main]
    if fallback is not None:
        parts.append(back.e_f)
    parts += [s.setpoint_filter * y_d, hold_next, episodes_next]
    state_next = ca.vertcat(*parts)
    at_bound = ca.mmax(ca.vertcat(ca.fabs(v_trusted - v_try) > 0)) if s.guard else ca.DM(0.0)
    at_limit = ca.mmax(ca.vertcat(ca.fabs(v_new - v_trusted) > 0))
    flags = ca.vertcat(distrusted, use_back, inner_only, at_bound, at_limit)
    fn = ca.Function(STEP_NAME, [y, r, tau_ff, state],
                     [tau, state_next, v_new, new_hist[:ny], flags],
                     ["y", "r", "tau_ff", "state"],
                     ["tau", "state_next", "v", "y_pred", "flags"])
    names = list(m.output_names)
    state_names = [f"y_hat[k-{i}].{n}" for i in range(na) for n in names]
    if fallback is not None:
        state_names += [f"y_hat_fallback[k-{i}].{n}" for i in range(naf) for n in names]
    state_names += [f"v[k-{i + 1}].{n}" for i in range(nb) for n in m.input_names]
    state_names += [f"e_f.{n}" for n in names]
    if fallback is not None:
        state_names += [f"e_f_fallback.{n}" for n in names]
    state_names += [f"y_d.{n}" for n in names] + ["fallback_hold", "fallback_episodes"]
    layout = {
        "inputs": {"y": names, "r": names, "tau_ff": list(m.input_names)},
        "state": state_names,
        "outputs": {"tau": list(m.input_names), "v": list(m.input_names),
                    "y_pred": names, "flags": list(FLAGS)},
    }
    assert len(state_names) == n_state
    return fn, layout


# ---- C, compile, cost ---------------------------------------------------------------------

def _header(model: Narx, fallback: Narx | None, settings: ControllerSettings,
            layout: dict[str, Any], body: str) -> str:
    settings_text = json.dumps(asdict(settings), default=str)
    kind = "linear ARX" if is_linear(model) else "NARX network"
    return (
        "/* GENERATED FILE: DO NOT EDIT.\n"
        " * Regenerated by `jointplay control` from the model folder's narx.json/arx.json.\n"
        f" * controller: {STEP_NAME} (internal-model control, {kind} inside"
        f"{', ARX fallback' if fallback is not None else ''})\n"
        f" * generator: jointplay.neural.imc {version('jointplay')}, casadi {version('casadi')}\n"
        f" * model checksum: {model.checksum()}\n"
        f" * fallback checksum: {fallback.checksum() if fallback is not None else '-'}\n"
        f" * robot hash: {model.context.get('robot', {}).get('robot_hash', '?')}\n"
        f" * code sha256: {hashlib.sha256(body.encode()).hexdigest()}\n"
        f" * settings: {settings_text}\n"
        f" * state[{len(layout['state'])}]: {', '.join(layout['state'])}\n"
        f" * flags: {', '.join(FLAGS)}\n"
        f" * outputs y: {', '.join(layout['inputs']['y'])}\n"
        " */\n")


def generate_c(model: Narx, settings: ControllerSettings, fallback: Narx | None = None
               ) -> tuple[str, ca.Function, dict[str, Any]]:
    fn, layout = build_step(model, settings, fallback)
    gen = ca.CodeGenerator("imc.c", {"with_header": False, "verbose": False})
    gen.add(fn)
    body = gen.dump()
    return _header(model, fallback, settings, layout, body) + body, fn, layout


def compile_controller(model: Narx, settings: ControllerSettings, fallback: Narx | None = None,
                       compiled: bool = True, kernel: bool = True) -> Controller:
    """Build, generate, compile (through the cache) and load the controller step.

    ``kernel``: compile the loop kernel (jointplay.neural.imc_kernel) rather than CasADi's
    straight-line code for the same function (one Gauss-Newton iteration only)."""
    from jointplay.store.build import compile_source
    from jointplay.store.model import FastFunction

    settings = resolve_settings(model, settings)
    if kernel and settings.iterations == 1:
        from jointplay.neural.imc_kernel import kernel_library_source

        fn, layout = build_step(model, settings, fallback)
        body = kernel_library_source(model, settings, fallback, fn, STEP_NAME)
        source = _header(model, fallback, settings, layout, body) + body
        cflags = STEP_CFLAGS
    else:
        source, fn, layout = generate_c(model, settings, fallback)
        cflags = SX_CFLAGS
    library, seconds = (None, 0.0)
    external = fn
    if compiled:
        library, seconds = compile_source(source, cflags=cflags)
        external = ca.external(STEP_NAME, str(library))
    return Controller(model, fallback if settings.guard else None, settings, fn, library,
                      seconds, source, FastFunction(external), len(layout["state"]), layout)


def per_call_us(ctrl: Controller, repeat: int = 5, number: int = 20000) -> float:
    """Median CPU time of one compiled step through the buffer path, in microseconds (CPU
    time of this process: on a shared machine wall time also counts the others' work)."""
    f = ctrl.fast
    f.inputs[3][:] = ctrl.initial_state(np.zeros(ctrl.model.n_outputs))
    best = []
    for _ in range(repeat):
        t0 = time.process_time()
        for _ in range(number):
            f.trigger()
        best.append((time.process_time() - t0) / number)
    return float(np.median(best) * 1e6)


def _loop_functions(ctrl: Controller) -> tuple[ca.Function, ca.Function]:
    """The loop with the internal model as its own plant: state -> next state, and its
    Jacobian."""
    fn = ctrl.function
    ny = ctrl.model.n_outputs
    x = ca.MX.sym("x", ctrl.n_state)
    nxt = fn(x[:ny], ca.DM.zeros(ny), ca.DM.zeros(ctrl.model.n_inputs), x)[1]
    return ca.Function("loop", [x], [nxt]), ca.Function("loop_jac", [x], [ca.jacobian(nxt, x)])


def _radius(jac: np.ndarray, ctrl: Controller) -> float:
    """Spectral radius of the loop while the primary model is in charge.

    The fallback model runs in parallel, driven by the applied input but feeding nothing
    back, and the hold counters are bookkeeping: the Jacobian is block-triangular, and their
    eigenvalues (the fallback's own free-run poles, and 1 for the episode counter) say
    nothing about this loop. They are left out."""
    keep = [i for i, name in enumerate(ctrl.layout["state"])
            if not name.startswith(("y_hat_fallback", "e_f_fallback", "fallback_"))]
    sub = jac[np.ix_(keep, keep)]
    if not np.all(np.isfinite(sub)):
        return math.inf
    return float(np.max(np.abs(np.linalg.eigvals(sub))))


def nominal_spectral_radius(ctrl: Controller, settle: int = 3000) -> float:
    """Spectral radius of the loop with the internal model as the plant, linearised at the
    equilibrium it settles to (one operating point: see local_spectral_radii)."""
    loop, loop_jac = _loop_functions(ctrl)
    state = ctrl.initial_state(np.zeros(ctrl.model.n_outputs))
    for _ in range(settle):
        state = np.asarray(loop(state)).ravel()
        if not np.all(np.isfinite(state)):
            return math.inf
    return _radius(np.asarray(loop_jac(state)), ctrl)


def local_spectral_radii(ctrl: Controller, states: np.ndarray) -> np.ndarray:
    """The same linearisation at controller states visited along a closed-loop run."""
    _, loop_jac = _loop_functions(ctrl)
    return np.array([_radius(np.asarray(loop_jac(x)), ctrl) for x in states])


__all__ = ["FLAGS", "STEP_NAME", "Controller", "ControllerSettings", "affine_rollout",
           "build_step", "compile_controller", "default_tracked", "generate_c", "horizon_gain",
           "input_bound", "is_linear", "local_spectral_radii", "nominal_spectral_radius",
           "per_call_us", "resolve_settings", "training_box"]
