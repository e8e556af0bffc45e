"""What the controller asks of an internal model: the range it was trained on, the inner loop
it was identified under, and its d-step rollouts with the input held (symbolic, and for a
linear model as constant matrices)."""

from __future__ import annotations

from typing import Any

import casadi as ca
import numpy as np

from jointplay.neural.model.narx import Narx


def training_box(model: Narx, margin: float) -> tuple[np.ndarray, np.ndarray]:
    """The regressor range the model was trained on, widened by ``margin`` x its width on
    each side (models saved without a range: mean -+ 4 standard deviations)."""
    rng = model.context.get("training_range")
    if rng:
        # The range may cover scheduling signals this model does not take (at its end).
        lo = np.asarray(rng["regressor_min"], dtype=float)[: model.n_regressor]
        hi = np.asarray(rng["regressor_max"], dtype=float)[: model.n_regressor]
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


def is_linear(model: Narx) -> bool:
    """A time-invariant linear model (its rollouts are constant matrices): one layer, no
    scheduling signals."""
    return len(model.weights) == 1 and not model.n_scheduling


def _rollout(model: Narx, hist: Any, upast: Any, v: Any, d: int, w: Any = None) -> Any:
    """y^(k+d) with the input held at v over the horizon (symbolic); the scheduling signals
    ``w`` (for a model that takes them) held at their current values."""
    net = model.casadi_function("net")
    ny, nu, na, nb = model.n_outputs, model.n_inputs, model.output_lags, model.input_lags
    ys = [hist[i * ny:(i + 1) * ny] for i in range(na)]
    us = [v] + [upast[i * nu:(i + 1) * nu] for i in range(nb - 1)]
    ws = [w] if model.n_scheduling else []
    for _ in range(d):
        nxt = net(ca.vertcat(*ys, *us, *ws))
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



def horizon_gain(narx: Narx, horizon: int) -> np.ndarray:
    """d y^(k+d) / d v with v held for ``horizon`` samples, from rest (ny x nu)."""
    f = narx.casadi_function()
    ny, nu = narx.n_outputs, narx.n_inputs
    v = ca.MX.sym("v", nu)
    ys: list[Any] = [ca.DM.zeros(ny)] * narx.output_lags
    us: list[Any] = [v] + [ca.DM.zeros(nu)] * (narx.input_lags - 1)
    # Scheduling signals at their training mean (a gain at a typical operating point).
    ws = [ca.DM(narx.regressor_mean[narx.n_regressor - narx.n_scheduling:])] \
        if narx.n_scheduling else []
    for _ in range(horizon):
        nxt = f(ca.vertcat(*ys, *us, *ws))
        ys = [nxt, *ys[:-1]]
        us = [v, *us[:-1]]
    return np.asarray(ca.Function("gain", [v], [ca.jacobian(ys[0], v)])(np.zeros(nu)))


__all__ = ["affine_rollout", "horizon_gain", "input_bound", "is_linear", "training_box"]
