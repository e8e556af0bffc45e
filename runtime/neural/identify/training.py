"""Training the NARX network (its linear twin and base:
:mod:`jointplay.neural.identify.linear_fit`).

PyTorch, float64, CPU: one-step-ahead least squares (L-BFGS, full batch), then simulation
error on windows of the training trajectories (the controller runs the model in free run),
each phase stopped early on the validation loss. A free run that runs away is repaired before
the second phase and a phase whose loss goes NaN retried (FREE_RUN_ATTEMPTS), each repair
recorded in the history. torch is imported inside the training
function only, so importing jointplay does not import it. The exported weights are checked to
reproduce torch's predictions through CasADi."""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from jointplay.neural.identify.config import IdentifyConfig
from jointplay.neural.identify.linear_fit import (
    LPV_RIDGE,
    Segment,
    linear_fit,
    model_scheduling,
    regress,
    scale_floor,
    segments,
)
from jointplay.neural.identify.trajectories import Trajectory
from jointplay.neural.model.inner_loop import output_increments
from jointplay.neural.model.narx import Narx

# ---- the data a training sees ---------------------------------------------------------------

@dataclass(frozen=True)
class _Data:
    """Regressors and targets of the training and validation runs, and their scales."""

    segments: list[Segment]
    validation_segments: list[Segment]
    x: np.ndarray
    t: np.ndarray
    xv: np.ndarray
    tv: np.ndarray
    mu: np.ndarray  # regressor mean and scale
    sigma: np.ndarray
    tm: np.ndarray  # target mean and scale
    ts: np.ndarray
    ys: np.ndarray  # output scale
    increment: tuple[bool, ...]
    scheduling: tuple[str, ...]  # the scheduling signals at the regressor's end


def _training_data(train: Sequence[Trajectory], validation: Sequence[Trajectory],
                   config: IdentifyConfig, names: dict[str, Any], dt: float) -> _Data:
    skip = max(0, round(config.transient / dt))
    scheduled = names if config.scheduling else None
    seg_train = segments(train, skip, scheduled)
    seg_val = segments(validation, skip, scheduled)
    increment = output_increments(names["output_names"])
    carry = np.asarray(increment, dtype=float)
    x, t = regress(seg_train, config.output_lags, config.input_lags, carry)
    xv, tv = regress(seg_val, config.output_lags, config.input_lags, carry)
    output_scale = scale_floor(np.vstack([seg[0] for seg in seg_train]).std(0))
    return _Data(seg_train, seg_val, x, t, xv, tv, x.mean(0), scale_floor(x.std(0)), t.mean(0),
                 scale_floor(t.std(0)), output_scale, increment,
                 model_scheduling(names) if config.scheduling else ())


# ---- the network in torch -------------------------------------------------------------------

class _Network:
    """Hidden tanh layers, and (with ``linear_path``) a linear direct path beside them, on
    normalised regressors; predicts the next outputs and runs itself in free run."""

    def __init__(self, torch: Any, config: IdentifyConfig, data: _Data) -> None:
        self.torch, self.dtype = torch, torch.float64
        self.linear_path = config.linear_path
        self.scheduling = data.scheduling
        self.na, self.nb = config.output_lags, config.input_lags
        self.m = max(self.na, self.nb) - 1
        self.ny = data.t.shape[1]
        layers: list[Any] = []
        width = data.x.shape[1]
        for h in config.hidden:
            layers += [torch.nn.Linear(width, h, dtype=self.dtype), torch.nn.Tanh()]
            width = h
        layers.append(torch.nn.Linear(width, self.ny, dtype=self.dtype))
        self.net = torch.nn.Sequential(*layers)
        # linear_input_gain: the hidden layers do not see the input lags (their entries of
        # the regressor are zeroed on the way in, their weights exported as 0), so the
        # model's gain from the added torque is its linear part's alone.
        self.hidden_mask: Any = None
        if config.linear_input_gain:
            mask = np.ones(data.x.shape[1])
            first = config.output_lags * data.t.shape[1]
            mask[first: data.x.shape[1] - len(data.scheduling)] = 0.0
            self.hidden_mask = torch.tensor(mask, dtype=self.dtype)
            with torch.no_grad():
                self.net[0].weight.mul_(self.hidden_mask)
        self.direct = torch.nn.Linear(data.x.shape[1], self.ny, bias=False, dtype=self.dtype)
        # (weight, bias, bilinear part or None) of the linear fit
        self.linear_start: tuple[Any, Any, Any] | None = None
        self.params = list(self.net.parameters())
        # lpv_base: the linear part is an LPV-ARX model (input gain affine in the scheduling
        # signals), a trainable bilinear part beside the direct path.
        self.bilinear_shape: tuple[int, int, int] | None = None
        self.bilinear: Any = None
        if config.lpv_base:
            ny = data.t.shape[1]
            n_u = data.x.shape[1] - config.output_lags * ny - len(data.scheduling)
            self.bilinear_shape = (config.output_lags * ny, n_u, len(data.scheduling))
            self.bilinear = torch.zeros((ny, n_u * len(data.scheduling)), dtype=self.dtype,
                                        requires_grad=True)
        if self.linear_path:
            self._start_linear(data)
            self.params += list(self.direct.parameters())
        if self.bilinear is not None:
            self.params.append(self.bilinear)
        self.mu, self.sigma, self.tm, self.ts, self.ys, self.carry = (
            self.tensor(a) for a in (data.mu, data.sigma, data.tm, data.ts, data.ys,
                                     np.asarray(data.increment, dtype=float)))

    def _start_linear(self, data: _Data) -> None:
        """Start from the least-squares linear model, with the hidden layers' output near
        zero: training then only has to add what is nonlinear."""
        weight, bias, bilinear = linear_fit(
            (data.x - data.mu) / data.sigma, (data.t - data.tm) / data.ts,
            LPV_RIDGE if self.bilinear_shape else 1e-9, self.bilinear_shape)
        self.linear_start = (self.tensor(weight), self.tensor(bias),
                             None if bilinear is None else self.tensor(bilinear))
        with self.torch.no_grad():
            self.direct.weight.copy_(self.tensor(weight))
            self.net[-1].bias.copy_(self.tensor(bias))
            self.net[-1].weight.mul_(0.01)
            if bilinear is not None:
                self.bilinear.copy_(self.tensor(bilinear))

    def tensor(self, a: Any) -> Any:
        return self.torch.tensor(a, dtype=self.dtype)

    def out(self, z: Any) -> Any:
        """Normalised increments (or values) from normalised regressors."""
        seen = z if self.hidden_mask is None else z * self.hidden_mask
        h = self.net(seen) + self.direct(z) if self.linear_path else self.net(seen)
        if self.bilinear_shape is not None:
            start, n_u, n_s = self.bilinear_shape
            zu, w = z[..., start: start + n_u], z[..., z.shape[-1] - n_s:]
            products = self.torch.cat([zu * w[..., i: i + 1] for i in range(n_s)], dim=-1)
            h = h + products @ self.bilinear.T
        return h

    def step(self, phi: Any) -> Any:
        """The next outputs from a regressor."""
        return self.carry * phi[..., :self.ny] + self.tm + self.ts * self.out(
            (phi - self.mu) / self.sigma)

    def free_run(self, d: Any, u: Any, w: Any) -> Any:
        """The model fed its own predictions, from the measured history of each window."""
        m, torch = self.m, self.torch
        hist = [d[:, m - i] for i in range(self.na)]
        outs = []
        for j in range(d.shape[1] - m - 1):
            k = m + j
            phi = torch.cat(hist + [u[:, k - i] for i in range(self.nb)] + [w[:, k]], dim=1)
            nxt = self.step(phi)
            outs.append(nxt)
            hist = [nxt, *hist[:-1]]
        return torch.stack(outs, dim=1)

    def sim_loss(self, d: Any, u: Any, w: Any) -> Any:
        return (((self.free_run(d, u, w) - d[:, self.m + 1:]) / self.ys) ** 2).mean()

    def state(self) -> tuple[dict[str, Any], dict[str, Any], Any]:
        return ({k: v.detach().clone() for k, v in self.net.state_dict().items()},
                {k: v.detach().clone() for k, v in self.direct.state_dict().items()},
                None if self.bilinear is None else self.bilinear.detach().clone())

    def restore(self, state: tuple[dict[str, Any], dict[str, Any], Any]) -> None:
        self.net.load_state_dict(state[0])
        self.direct.load_state_dict(state[1])
        if self.bilinear is not None:
            with self.torch.no_grad():
                self.bilinear.copy_(state[2])

    def windows(self, segments: Sequence[Segment], h: int) -> tuple[Any, Any, Any]:
        """Overlapping windows of ``h`` predicted samples (with the history before them)."""
        from jointplay.neural.model.twin import windows

        return tuple(self.tensor(a) for a in windows(segments, h, self.m))

    def export(self, data: _Data, names: dict[str, Any], dt: float,
               context: dict[str, Any]) -> Narx:
        linear = [mod for mod in self.net if isinstance(mod, self.torch.nn.Linear)]
        weights = [mod.weight.detach().numpy().astype(float).copy() for mod in linear]
        if self.hidden_mask is not None:
            weights[0] = weights[0] * self.hidden_mask.numpy()
        return Narx(weights=tuple(weights),
                    biases=tuple(mod.bias.detach().numpy().astype(float).copy()
                                 for mod in linear),
                    regressor_mean=data.mu, regressor_scale=data.sigma,
                    increment_mean=data.tm, increment_scale=data.ts, output_scale=data.ys,
                    output_lags=self.na, input_lags=self.nb, sample_time=dt, context=context,
                    increment=data.increment,
                    linear=(self.direct.weight.detach().numpy().astype(float).copy()
                            if self.linear_path else None), scheduling=self.scheduling,
                    bilinear=(None if self.bilinear is None
                              else self.bilinear.detach().numpy().astype(float).copy()),
                    **names)


# ---- training -------------------------------------------------------------------------------

def train_narx(train: Sequence[Trajectory], validation: Sequence[Trajectory],
               config: IdentifyConfig, names: dict[str, Any], dt: float,
               context: dict[str, Any], quiet: bool = False) -> tuple[Narx, dict[str, Any]]:
    """Train the network (PyTorch, float64); return the model and the loss history."""
    import torch

    threads, deterministic = torch.get_num_threads(), torch.are_deterministic_algorithms_enabled()
    # One thread: these matrices are small, and OpenMP threads waiting on a busy machine cost
    # ten times the arithmetic.
    torch.set_num_threads(1)
    torch.use_deterministic_algorithms(True)
    torch.manual_seed(config.seed)
    try:
        return _train(torch, train, validation, config, names, dt, context, quiet)
    finally:
        torch.set_num_threads(threads)
        torch.use_deterministic_algorithms(deterministic)


def _train(torch: Any, train: Sequence[Trajectory], validation: Sequence[Trajectory],
           config: IdentifyConfig, names: dict[str, Any], dt: float, context: dict[str, Any],
           quiet: bool) -> tuple[Narx, dict[str, Any]]:
    from tqdm import tqdm

    data = _training_data(train, validation, config, names, dt)
    net = _Network(torch, config, data)
    history: dict[str, list[Any]] = {"one_step_train": [], "one_step_validation": [],
                                              "free_run_train": [], "free_run_validation": []}
    total = config.one_step_iterations + config.multi_step_iterations
    start = time.perf_counter()
    with tqdm(total=total, disable=quiet, desc="training", unit="it") as bar:
        _one_step_phase(torch, net, data, config, history, bar)
        bar.n = config.one_step_iterations
        bar.refresh()
        if config.multi_step_iterations > 0:
            _free_run_phase(torch, net, data, config, history, bar)
    model = net.export(data, names, dt, context)
    err = _export_error(torch, net, model, data)
    history["seconds"] = [time.perf_counter() - start]
    history["export_check"] = [err]
    return model, history


def _one_step_phase(torch: Any, net: _Network, data: _Data, config: IdentifyConfig,
                    history: dict[str, list[Any]], bar: Any) -> None:
    """Phase 1: one step ahead, full batch."""
    zx, zt = net.tensor((data.x - data.mu) / data.sigma), net.tensor((data.t - data.tm) / data.ts)
    zxv = net.tensor((data.xv - data.mu) / data.sigma)
    ztv = net.tensor((data.tv - data.tm) / data.ts)
    opt = torch.optim.LBFGS(net.params, lr=1.0, max_iter=20, history_size=50,
                            line_search_fn="strong_wolfe")

    def closure() -> Any:
        opt.zero_grad()
        loss = ((net.out(zx) - zt) ** 2).mean()
        loss.backward()
        return loss

    def validate() -> float:
        with torch.no_grad():
            return float(((net.out(zxv) - ztv) ** 2).mean())

    _early_stopped(opt, closure, validate, net, config.one_step_iterations, config.patience,
                   best=math.inf, phase="one-step", history=history, bar=bar,
                   stop_on_nonfinite=False)


# How the free-run phase is retried when its loss goes non-finite: each attempt starts from
# the best state so far, with a smaller L-BFGS step, windows lengthened from short to the full
# length (a short free run cannot run away before the gradient sees it), and then a penalty
# on the hidden layers' weights (a smaller residual is a smoother, more stable one).
@dataclass(frozen=True)
class _Attempt:
    lr: float  # L-BFGS step
    windows: tuple[float, ...]  # window lengths in turn, x the configured window
    penalty: float  # on the hidden layers' squared weights


FREE_RUN_ATTEMPTS = (
    _Attempt(1.0, (1.0,), 0.0),
    _Attempt(0.1, (0.125, 0.5, 1.0), 0.0),
    _Attempt(0.02, (0.125, 0.5, 1.0), 1e-3),
)
# Shrink factors tried on the residual before the free-run phase when the one-step network
# runs away in free run (1: as trained; 0: the least-squares linear start).
RESIDUAL_SHRINK = (1.0, 0.5, 0.25, 0.1, 0.0)
RUNAWAY = 10.0


def _free_run_phase(torch: Any, net: _Network, data: _Data, config: IdentifyConfig,
                    history: dict[str, list[Any]], bar: Any) -> None:
    """Phase 2: simulation error on windows (what the controller relies on).

    A free run that is not finite is never left to stand: the residual is first shrunk
    until the one-step network runs stably in free run, and a phase whose loss goes NaN is
    retried (:data:`FREE_RUN_ATTEMPTS`); every repair is recorded in ``history["repairs"]``."""
    repairs: list[dict[str, Any]] = history.setdefault("repairs", [])
    dvw, uvw, wvw = net.windows(data.validation_segments, config.window)

    def validate() -> float:
        with torch.no_grad():
            return float(net.sim_loss(dvw, uvw, wvw))

    _stabilise_start(torch, net, validate, repairs)
    for number, attempt in enumerate(FREE_RUN_ATTEMPTS, start=1):
        outcome = "iterations"
        for fraction in attempt.windows:
            length = max(5, round(config.window * fraction))
            outcome = _free_run_attempt(torch, net, data, config, history, bar, length,
                                        attempt.lr, attempt.penalty, validate)
            if outcome == "nonfinite":
                break
        if outcome != "nonfinite":
            if number > 1:
                repairs[-1]["cured"] = True
            return
        following = FREE_RUN_ATTEMPTS[number] if number < len(FREE_RUN_ATTEMPTS) else None
        repairs.append({
            "phase": "free-run", "problem": f"training loss not finite (attempt {number}, "
                                            f"L-BFGS step {attempt.lr:g})",
            "action": ("restored the best state and retried with L-BFGS step "
                       f"{following.lr:g}, windows of "
                       + ", ".join(f"{max(5, round(config.window * f))}"
                                   for f in following.windows)
                       + " samples in turn"
                       + (f", hidden-weight penalty {following.penalty:g}"
                          if following.penalty else "")
                       if following else "restored the best state; free-run training "
                                         "stopped there"),
            "cured": False})


def _stabilise_start(torch: Any, net: _Network, validate: Callable[[], float],
                     repairs: list[dict[str, Any]]) -> None:
    """Shrink the hidden layers' output until the one-step network's free run is finite and
    no worse than the least-squares linear start (shrink 0), so the free-run phase starts
    from a stable model instead of one whose gradient is NaN."""
    last = net.net[-1]
    with torch.no_grad():
        weight, bias = last.weight.detach().clone(), last.bias.detach().clone()
        direct = net.direct.weight.detach().clone()
        bilinear = None if net.bilinear is None else net.bilinear.detach().clone()
    linear = net.linear_start

    def set_shrink(c: float) -> None:
        with torch.no_grad():
            last.weight.copy_(c * weight)
            if linear is not None:  # blend the direct path and the bias back to the linear fit
                last.bias.copy_(c * bias + (1 - c) * linear[1])
                net.direct.weight.copy_(c * direct + (1 - c) * linear[0])
                if bilinear is not None:
                    net.bilinear.copy_(c * bilinear + (1 - c) * linear[2])

    losses: dict[float, float] = {}
    for c in (1.0, 0.0):
        set_shrink(c)
        val = validate()
        losses[c] = val if math.isfinite(val) else math.inf
    # Runaway: not finite, or RUNAWAY x the linear start's loss (a free run that grows by
    # orders of magnitude is unstable, not merely inaccurate).
    if losses[1.0] <= RUNAWAY * losses[0.0]:
        set_shrink(1.0)
        return
    for c in RESIDUAL_SHRINK[1:-1]:
        set_shrink(c)
        val = validate()
        losses[c] = val if math.isfinite(val) else math.inf
    best = min(losses, key=lambda c: (losses[c], -c))
    set_shrink(best)
    repairs.append({"phase": "free-run start",
                    "problem": f"the one-step network's free run on validation runs away (loss "
                               f"{losses[1.0]:.4g} against {losses[0.0]:.4g} for the linear "
                               "start)",
                    "action": f"residual shrunk to {best:g} x (loss by shrink: "
                              + ", ".join(f"{c:g}: {v:.4g}" for c, v in losses.items()) + ")",
                    "cured": math.isfinite(losses[best])})


def _free_run_attempt(torch: Any, net: _Network, data: _Data, config: IdentifyConfig,
                      history: dict[str, list[Any]], bar: Any, length: int, lr: float,
                      penalty: float, validate: Callable[[], float]) -> str:
    """One early-stopped L-BFGS run on windows of ``length`` samples; how it ended."""
    dw, uw, ww = net.windows(data.segments, length)
    hidden = [p for layer in net.net if isinstance(layer, torch.nn.Linear)
              for p in (layer.weight,)]
    opt = torch.optim.LBFGS(net.params, lr=lr, max_iter=10, history_size=50,
                            line_search_fn="strong_wolfe")

    def closure() -> Any:
        opt.zero_grad()
        loss = net.sim_loss(dw, uw, ww)
        if penalty:
            loss = loss + penalty * sum((w ** 2).mean() for w in hidden)
        loss.backward()
        return loss

    # A diverged L-BFGS step gives NaN: recorded as null (the run stops there and keeps its
    # best state); metrics.json holds no NaN.
    return _early_stopped(opt, closure, validate, net, config.multi_step_iterations,
                          config.patience, best=validate(), phase="free-run", history=history,
                          bar=bar, stop_on_nonfinite=True)


def _early_stopped(opt: Any, closure: Callable[[], Any], validate: Callable[[], float],
                   net: _Network, iterations: int, patience: int, *, best: float, phase: str,
                   history: dict[str, list[Any]], bar: Any,
                   stop_on_nonfinite: bool) -> str:
    """Optimiser steps until ``iterations``, or ``patience`` steps without a better validation
    loss than ``best``; the network is left at its best state. Returns how it ended:
    "iterations", "patience" or "nonfinite"."""
    key = phase.replace("-", "_")
    best_state, stale, outcome = net.state(), 0, "iterations"
    for _ in range(iterations):
        loss = float(opt.step(closure).detach())
        val = validate()
        history[f"{key}_train"].append(loss if math.isfinite(loss) else None)
        history[f"{key}_validation"].append(val if math.isfinite(val) else None)
        bar.update(1)
        bar.set_postfix(phase=phase, train=f"{loss:.3g}", val=f"{val:.3g}")
        if stop_on_nonfinite and not math.isfinite(loss):
            outcome = "nonfinite"
            break
        if val < best * (1 - 1e-4):
            best, best_state, stale = val, net.state(), 0
        else:
            stale += 1
            if stale >= patience:
                outcome = "patience"
                break
    net.restore(best_state)
    return outcome


def _export_error(torch: Any, net: _Network, model: Narx, data: _Data) -> float:
    """float64 check: the exported weights reproduce torch's predictions through CasADi."""
    xv = data.xv
    with torch.no_grad():
        ref = net.step(net.tensor(xv[:256])).numpy()
    got = np.asarray(model.casadi_function().map(min(256, xv.shape[0]))(xv[:256].T)).T
    err = float(np.max(np.abs(got - ref) / data.ys))
    if not err < 1e-9:
        raise RuntimeError(f"exported network differs from the trained one by {err:.3g} "
                           "(output scales)")
    return err


__all__ = ["train_narx"]
