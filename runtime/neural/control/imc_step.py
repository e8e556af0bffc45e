"""The controller step as one CasADi SX function: both internal models' increments and trust,
the choice between them, the limits, and the next state (the law and the guard are described
in jointplay.neural.control.imc)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import casadi as ca
import numpy as np

from jointplay.neural.control.imc_settings import ControllerSettings
from jointplay.neural.control.internal_model import (
    _inner_gains,
    _rollout,
    affine_rollout,
    input_bound,
    is_linear,
    training_box,
)
from jointplay.neural.control.mismatch_filter import pair_gains
from jointplay.neural.model.narx import Narx
from jointplay.neural.model.scheduling import scheduling_values

STEP_NAME = "imc_step"
# What the flags output reports, one entry per sample (1.0 when it happened).
FLAGS = ("model_distrusted", "on_fallback_model", "inner_loop_only", "input_at_trust_bound",
         "torque_at_limit")


@dataclass
class _Branch:
    """One internal model's increment, trust, and next history (symbolic)."""

    dv: Any
    ok: Any
    e_f: Any
    hist_next: Any  # after advancing with the applied v: filled in later
    predict: Any  # function of the applied v -> next output


def _branch(model: Narx, s: ControllerSettings, hist: Any, upast: Any, v_prev: Any,
            e_f_prev: Any, dev: Any, target: Any, cm: np.ndarray, sym: Any,
            w: Any = None) -> _Branch:
    ny, nu, na, d = model.n_outputs, model.n_inputs, model.output_lags, s.horizon
    e = dev - hist[:ny]
    e_f = s.mismatch_filter * e_f_prev + (1 - s.mismatch_filter) * e
    pairs = pair_gains(model, s)
    if pairs:
        # Declared noise: position-velocity pairs estimated together (mismatch_filter.py).
        rows = [e_f[i] for i in range(ny)]
        t = model.sample_time
        for pg in pairs:
            ip, iv, k = pg.position, pg.velocity, pg.gain
            p_pred = e_f_prev[ip] + t * e_f_prev[iv]
            v_pred = e_f_prev[iv]
            rp, rv = e[ip] - p_pred, e[iv] - v_pred
            rows[ip] = p_pred + k[0, 0] * rp + k[0, 1] * rv
            rows[iv] = v_pred + k[1, 0] * rp + k[1, 1] * rv
        e_f = ca.vertcat(*rows)
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
        ws = sym.sym("w", model.n_scheduling)
        y_end = _rollout(model, hs, us, vp + dv, d, ws)
        linear = ca.Function("linearised", [hs, us, vp, ws, dv],
                             [y_end, ca.jacobian(y_end, dv)])
        step = sym.zeros(nu, 1)
        n0 = None
        w_now = w if model.n_scheduling else sym.zeros(0, 1)
        for _ in range(s.iterations):
            n_val, jac = linear(hist, upast, v_prev, w_now, step)
            n0 = n_val if n0 is None else n0
            cj = ca.mtimes(cmd, jac)
            residual = ca.mtimes(cmd, target - e_f - n_val)
            rhs = ca.mtimes(cj.T, residual) - s.regularisation * step
            step = step + ca.solve(ca.mtimes(cj.T, cj) + lam, rhs)
    if s.guard:
        lo, hi = training_box(model, s.trust_range)
        phi = ca.vertcat(hist, v_prev, upast[: (model.input_lags - 1) * nu],
                         *([w] if model.n_scheduling else []))
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
                              *[upast[i * nu:(i + 1) * nu] for i in range(nb - 1)],
                              *([w] if model.n_scheduling else [])))
    return _Branch(step, ok, e_f, None, predict)


def build_step(model: Narx, settings: ControllerSettings, fallback: Narx | None = None,
               sym: Any = ca.SX) -> tuple[ca.Function, dict[str, Any]]:
    """The controller step as a CasADi function (see jointplay.neural.control.imc for the law).

    Inputs: y (measured outputs), r (the reference's outputs), tau_ff (the feedforward torque
    at this sample, for the actuator limit) and state. Outputs: tau (torque to add to the
    feedforward: PD + v), state_next, v, y_pred (the internal model's deviation at k+1) and
    flags (see FLAGS).
    """
    s = settings
    m = model
    fallback = _usable_fallback(m, s, fallback)
    ny, nu, d = m.n_outputs, m.n_inputs, s.horizon
    names = _state_names(m, fallback)
    y = sym.sym("y", ny)
    r = sym.sym("r", ny)
    tau_ff = sym.sym("tau_ff", nu)
    state = sym.sym("state", len(names))
    x = _split_state(state, m, fallback)
    v_prev = x.upast[:nu]

    dev = y - r
    target = (s.setpoint_filter ** d) * x.y_d
    cm = _tracking_matrix(m, s)
    # The scheduling signals from the reference and the feedforward at this sample
    # (jointplay.neural.model.scheduling), for the models that take them.
    w = None
    for candidate in (m, fallback):
        if candidate is not None and candidate.n_scheduling:
            w = scheduling_values(candidate.scheduling, m.output_names, m.input_names, r, tau_ff)
    main = _branch(m, s, x.hist, x.upast, v_prev, x.e_f, dev, target, cm, sym, w)
    use_main = ca.logic_and(main.ok, x.hold <= 0)
    back = None
    if fallback is not None:
        back = _branch(fallback, s, x.hist_f, x.upast, v_prev, x.e_f_f, dev, target, cm, sym,
                       w)
        use_back = ca.logic_and(ca.logic_not(use_main), back.ok)
        step = ca.if_else(use_main, main.dv, ca.if_else(use_back, back.dv, -v_prev))
    else:
        use_back = ca.DM(0.0)
        step = ca.if_else(use_main, main.dv, -v_prev)
    inner_only = ca.logic_not(ca.logic_or(use_main, use_back))
    v_try, v_trusted, v_new, tau = _limited(m, s, dev, tau_ff, v_prev, step, sym)
    state_next, y_pred, distrusted = _next_state(m, s, x, main, back, use_main, v_new)
    at_bound = ca.mmax(ca.vertcat(ca.fabs(v_trusted - v_try) > 0)) if s.guard else ca.DM(0.0)
    at_limit = ca.mmax(ca.vertcat(ca.fabs(v_new - v_trusted) > 0))
    flags = ca.vertcat(distrusted, use_back, inner_only, at_bound, at_limit)
    fn = ca.Function(STEP_NAME, [y, r, tau_ff, state],
                     [tau, state_next, v_new, y_pred, flags],
                     ["y", "r", "tau_ff", "state"],
                     ["tau", "state_next", "v", "y_pred", "flags"])
    output_names = list(m.output_names)
    layout = {
        "inputs": {"y": output_names, "r": output_names, "tau_ff": list(m.input_names)},
        "state": names,
        "outputs": {"tau": list(m.input_names), "v": list(m.input_names),
                    "y_pred": output_names, "flags": list(FLAGS)},
    }
    return fn, layout


def _usable_fallback(m: Narx, s: ControllerSettings, fallback: Narx | None) -> Narx | None:
    """The fallback the step runs: checked against the model, none without the guard."""
    if len(s.torque_limit) != m.n_inputs:
        raise ValueError("resolve the settings first (resolve_settings)")
    if fallback is not None and (fallback.output_names != m.output_names
                                 or fallback.input_names != m.input_names):
        raise ValueError("the fallback model must have the same outputs and inputs")
    if fallback is not None and not s.guard:
        return None
    return fallback


def _state_names(m: Narx, fallback: Narx | None) -> list[str]:
    """The state vector's entries in order: the internal models' histories, the past inputs,
    the mismatch filters, the filtered setpoint and the fallback's two counters."""
    names = list(m.output_names)
    out = [f"y_hat[k-{i}].{n}" for i in range(m.output_lags) for n in names]
    if fallback is not None:
        out += [f"y_hat_fallback[k-{i}].{n}" for i in range(fallback.output_lags)
                for n in names]
    out += [f"v[k-{i + 1}].{n}" for i in range(m.input_lags) for n in m.input_names]
    out += [f"e_f.{n}" for n in names]
    if fallback is not None:
        out += [f"e_f_fallback.{n}" for n in names]
    return out + [f"y_d.{n}" for n in names] + ["fallback_hold", "fallback_episodes"]


@dataclass(frozen=True)
class _State:
    """The step's state vector cut into its parts (symbolic), in :func:`_state_names` order;
    the fallback's parts are None without a fallback."""

    hist: Any
    hist_f: Any
    upast: Any
    e_f: Any
    e_f_f: Any
    y_d: Any
    hold: Any
    episodes: Any


def _split_state(state: Any, m: Narx, fallback: Narx | None) -> _State:
    ny = m.n_outputs
    naf = fallback.output_lags if fallback is not None else 0
    at = 0

    def take(n: int) -> Any:
        nonlocal at
        part = state[at: at + n]
        at += n
        return part
    hist = take(m.output_lags * ny)
    hist_f = take(naf * ny) if fallback is not None else None
    upast = take(m.input_lags * m.n_inputs)
    e_f = take(ny)
    e_f_f = take(ny) if fallback is not None else None
    y_d = take(ny)
    hold, episodes = take(1), take(1)
    assert at == state.numel(), "the state's parts and its names disagree"
    return _State(hist, hist_f, upast, e_f, e_f_f, y_d, hold, episodes)


def _tracking_matrix(m: Narx, s: ControllerSettings) -> np.ndarray:
    """C: one row per tracked output, 1 / its scale in that output's column."""
    rows = [m.output_index(name) for name in s.tracked]
    cm = np.zeros((len(rows), m.n_outputs))
    for i, (row, scale) in enumerate(zip(rows, s.scales, strict=True)):
        cm[i, row] = 1.0 / scale
    return cm


def _limited(m: Narx, s: ControllerSettings, dev: Any, tau_ff: Any, v_prev: Any, step: Any,
             sym: Any) -> tuple[Any, Any, Any, Any]:
    """v after the rate limit (v_try), inside the trust bound (v_trusted) and inside the
    actuator limits with the feedforward and the inner PD (v_new), and the torque to add."""
    rate = ca.DM([rl * m.sample_time for rl in s.rate_limit])
    step = ca.fmin(ca.fmax(step, -rate), rate)
    v_try = v_prev + step
    if s.guard:
        bound = ca.DM(input_bound(m, s.trust_input))
        v_trusted = ca.fmin(ca.fmax(v_try, -bound), bound)
    else:
        v_trusted = v_try
    q_idx, dq_idx, kp, kd = _inner_gains(m)
    inner = (-ca.DM(kp) * dev[q_idx] - ca.DM(kd) * dev[dq_idx]) if q_idx \
        else sym.zeros(m.n_inputs, 1)
    limit = ca.DM([lim if math.isfinite(lim) else 1e300 for lim in s.torque_limit])
    v_new = ca.fmin(ca.fmax(v_trusted, -limit - tau_ff - inner), limit - tau_ff - inner)
    total = ca.fmin(ca.fmax(tau_ff + inner + v_new, -limit), limit)
    return v_try, v_trusted, v_new, total - tau_ff


def _next_state(m: Narx, s: ControllerSettings, x: _State, main: _Branch,
                back: _Branch | None, use_main: Any, v_new: Any) -> tuple[Any, Any, Any]:
    """(next state, the internal model's predicted deviation at k+1, whether the network was
    distrusted): the models advanced with the applied v, the counters of the hold."""
    ny, na, nb, nu = m.n_outputs, m.output_lags, m.input_lags, m.n_inputs
    y_next = main.predict(v_new)
    new_hist = ca.vertcat(y_next, x.hist[: (na - 1) * ny])
    if back is not None:
        naf = x.hist_f.numel() // ny
        yf_next = back.predict(v_new)
        new_hist_f = ca.vertcat(yf_next, x.hist_f[: (naf - 1) * ny])
        # Off the network, its history follows the fallback's (a sane restart point).
        if naf == na:
            new_hist = ca.if_else(use_main, new_hist, new_hist_f)
        e_f_main = ca.if_else(use_main, main.e_f, back.e_f)
        parts = [new_hist, new_hist_f]
    else:
        e_f_main = main.e_f
        parts = [new_hist]
    distrusted, hold_next, episodes_next = _hold(s, main.ok, x.hold, x.episodes)
    new_upast = ca.vertcat(v_new, x.upast[: (nb - 1) * nu])
    parts += [new_upast, e_f_main]
    if back is not None:
        parts.append(back.e_f)
    parts += [s.setpoint_filter * x.y_d, hold_next, episodes_next]
    return ca.vertcat(*parts), new_hist[:ny], distrusted


def _hold(s: ControllerSettings, ok: Any, hold: Any, episodes: Any) -> tuple[Any, Any, Any]:
    """(distrusted, next hold, next episode count): a first distrust after a trusted spell
    starts an episode; the hold doubles with each, up to 64x ``fallback_hold``."""
    distrusted = ca.logic_not(ok)
    first = ca.logic_and(distrusted, hold <= 0)
    episodes_next = episodes + ca.if_else(first, 1, 0)
    # 2^(episodes - 1) without a pow: the hold doubles with each episode, up to 64x.
    doubling = ca.DM([2.0 ** i for i in range(7)])
    length = s.fallback_hold * ca.mmax(ca.if_else(
        ca.DM(np.arange(7)) <= ca.fmax(episodes_next - 1, 0), doubling, ca.DM.zeros(7)))
    hold_next = ca.if_else(distrusted, length, ca.fmax(hold - 1, 0))
    return distrusted, hold_next, episodes_next

__all__ = ["FLAGS", "STEP_NAME", "build_step"]
