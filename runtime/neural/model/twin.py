"""The network against its linear twin: residual weighting, and whether a model is usable.

The NARX network has a linear direct path that starts at the least-squares ARX fit, so the
trained model is "ARX + nonlinear residual" only loosely: training moves the linear part too.
Here the residual is made explicit and earns its place on data it was not trained on:

    model(alpha) = ARX + alpha (network - ARX),   alpha in [0, 1]

is again a network of the same shape (the last layer and the direct path are blended, and a
bilinear part where either has one: with ``lpv_base`` the linear model is the LPV-ARX fit;
both models share one normalisation), and alpha is chosen on the validation trajectories by the
free-run loss over windows (what the controller relies on). alpha = 0 is the ARX model itself,
so the chosen model is never worse than ARX on that loss.

A model is refused (identify writes it as ``narx.rejected.json``, never as ``narx.json``) when
on validation it is worse than persistence one step ahead or in free run, or worse than ARX in
free run; the message says by how much and what to change.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from jointplay.neural.model.narx import Narx, nrmse

# (deviations, added torques[, scheduling signals]) of one run
Segment = tuple[np.ndarray, ...]

ALPHAS = (0.0, 0.25, 0.5, 0.75, 1.0)


def blend(narx: Narx, arx: Narx, alpha: float) -> Narx:
    """ARX + alpha (network - ARX), as one network of the network's shape."""
    for name in ("regressor_mean", "regressor_scale", "increment_mean", "increment_scale"):
        if not np.array_equal(getattr(narx, name), getattr(arx, name)):
            raise ValueError(f"network and ARX model differ in {name}: cannot blend")
    if len(arx.weights) != 1:
        raise ValueError("the ARX model must be a single linear layer")
    w_arx, b_arx = arx.weights[0], arx.biases[0]
    direct = narx.linear if narx.linear is not None else np.zeros_like(w_arx)
    # A bilinear part (LPV-ARX base, or a network trained on one) is blended the same way.
    bilinear = None
    if narx.bilinear is not None or arx.bilinear is not None:
        zero = np.zeros_like(narx.bilinear if narx.bilinear is not None else arx.bilinear)
        bilinear = (alpha * (narx.bilinear if narx.bilinear is not None else zero)
                    + (1 - alpha) * (arx.bilinear if arx.bilinear is not None else zero))
    return replace(narx, weights=(*narx.weights[:-1], alpha * narx.weights[-1]),
                   biases=(*narx.biases[:-1], alpha * narx.biases[-1] + (1 - alpha) * b_arx),
                   linear=alpha * direct + (1 - alpha) * w_arx, bilinear=bilinear)


def windows(segments: Sequence[Segment], length: int,
            history: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Overlapping free-run windows (stride length/2): outputs (B, history + length + 1, ny),
    inputs (B, ..., nu) and scheduling signals (B, ..., nw; nw may be 0). Segments shorter
    than a window give one window each, as long as the shortest allows."""
    m, h = history, length
    segs = [(seg[0], seg[1], seg[2] if len(seg) > 2 else np.zeros((seg[0].shape[0], 0)))
            for seg in segments]
    ds, us, ws = [], [], []
    for d, u, w in segs:
        for s in range(m, d.shape[0] - h, max(1, h // 2)):
            ds.append(d[s - m: s + h + 1])
            us.append(u[s - m: s + h + 1])
            ws.append(w[s - m: s + h + 1])
    if not ds:
        h = min(d.shape[0] for d, _, _ in segs) - m - 1
        ds = [d[: m + h + 1] for d, _, _ in segs]
        us = [u[: m + h + 1] for _, u, _ in segs]
        ws = [w[: m + h + 1] for _, _, w in segs]
    return np.array(ds), np.array(us), np.array(ws)


def window_loss(model: Narx | None, d: np.ndarray, u: np.ndarray, scale: np.ndarray,
                w: np.ndarray | None = None) -> float:
    """Mean squared free-run error over windows, each output divided by ``scale``; ``w``:
    the windows' scheduling signals (for a model that takes them).

    ``None`` is persistence: the window's first sample held."""
    m, na, nb = (model.history, model.output_lags, model.input_lags) if model else (
        0, 1, 1)
    truth = d[:, m + 1:]
    if model is None:
        pred = np.repeat(d[:, m: m + 1], truth.shape[1], axis=1)
    else:
        hist = [d[:, m - i] for i in range(na)]
        out = []
        with np.errstate(all="ignore"):
            for j in range(truth.shape[1]):
                k = m + j
                parts = hist + [u[:, k - i] for i in range(nb)]
                if model.n_scheduling:
                    if w is None:
                        raise ValueError("this model needs its scheduling signals")
                    parts.append(w[:, k, : model.n_scheduling])
                nxt = model.predict(np.concatenate(parts, axis=1))
                out.append(nxt)
                hist = [nxt, *hist[:-1]]
        pred = np.stack(out, axis=1)
    with np.errstate(all="ignore"):
        loss = float(np.mean(((pred - truth) / scale) ** 2))
    return loss if np.isfinite(loss) else float("inf")


@dataclass(frozen=True)
class Selection:
    """The residual weight chosen on validation and the losses behind the choice."""

    alpha: float
    losses: dict[float, float]  # validation free-run loss per alpha tried
    arx_loss: float
    network_loss: float  # alpha = 1: the trained network as it came out of training
    persistence_loss: float


def select_residual(narx: Narx, arx: Narx, segments: Sequence[Segment],
                    window: int, alphas: Sequence[float] = ALPHAS) -> tuple[Narx, Selection]:
    """The blend with the lowest validation free-run loss (ties go to the smaller alpha)."""
    d, u, w = windows(segments, window, narx.history)
    scale = narx.output_scale
    losses = {float(a): window_loss(blend(narx, arx, a), d, u, scale, w) for a in alphas}
    best = min(losses, key=lambda a: (losses[a], a))
    selection = Selection(best, losses, losses.get(0.0, window_loss(arx, d, u, scale, w)),
                          losses.get(1.0, window_loss(narx, d, u, scale, w)),
                          window_loss(None, d, u, scale))
    return blend(narx, arx, best), selection


def one_step_nrmse(model: Narx | None, segments: Sequence[Segment],
                   history: int) -> float:
    """Mean over outputs of the one-step NRMSE over the segments (None: persistence)."""
    preds, truth = [], []
    for d, u, *w in segments:
        truth.append(d[history + 1:])
        preds.append(d[history:-1] if model is None else
                     model.one_step(d, u, w[0] if w else None))
    with np.errstate(all="ignore"):
        value = float(np.mean(nrmse(np.vstack(preds), np.vstack(truth))))
    return value if np.isfinite(value) else float("inf")


@dataclass(frozen=True)
class Verdict:
    usable: bool
    problems: tuple[str, ...]
    figures: dict[str, float]

    def message(self) -> str:
        return ("; ".join(self.problems) + ". Give more or longer training runs (--train, "
                "--duration), more iterations (--iterations), or a smaller network (--hidden); "
                "the model was written as narx.rejected.json, not as a usable narx.json")


def judge(model: Narx, arx: Narx, selection: Selection,
          segments: Sequence[Segment], window: int, against_linear: bool = True) -> Verdict:
    """Is the chosen model better than persistence and no worse than ARX on validation?

    ``against_linear`` False: the model was chosen against the linear one by another
    criterion (the closed loop), and its free-run loss against ARX is reported only."""
    d, u, w = windows(segments, window, model.history)
    free = window_loss(model, d, u, model.output_scale, w)
    figures = {
        "one_step_nrmse": one_step_nrmse(model, segments, model.history),
        "one_step_nrmse_arx": one_step_nrmse(arx, segments, model.history),
        "one_step_nrmse_persistence": one_step_nrmse(None, segments, model.history),
        "free_run_loss": free,
        "free_run_loss_arx": selection.arx_loss,
        "free_run_loss_persistence": selection.persistence_loss,
    }
    problems = []
    if not all(np.isfinite(v) for v in (figures["one_step_nrmse"], free)):
        problems.append("its validation predictions are not finite")
    if not figures["one_step_nrmse"] < figures["one_step_nrmse_persistence"]:
        problems.append(f"one step ahead it is worse than persistence on validation (mean "
                        f"NRMSE {figures['one_step_nrmse']:.3g} against "
                        f"{figures['one_step_nrmse_persistence']:.3g})")
    if not free < selection.persistence_loss:
        problems.append(f"in free run it is worse than persistence on validation (loss "
                        f"{free:.3g} against {selection.persistence_loss:.3g})")
    if against_linear and not free <= selection.arx_loss * (1 + 1e-9):
        problems.append(f"in free run it is worse than the linear ARX model on validation "
                        f"(loss {free:.3g} against {selection.arx_loss:.3g})")
    return Verdict(not problems, tuple(problems), figures)


def describe(selection: Selection, verdict: Verdict) -> dict[str, Any]:
    return {"alpha": selection.alpha,
            "free_run_loss_by_alpha": {f"{a:g}": v for a, v in selection.losses.items()},
            "network_free_run_loss": selection.network_loss,
            "usable": verdict.usable, "problems": list(verdict.problems), **verdict.figures}


__all__ = ["ALPHAS", "Selection", "Verdict", "blend", "describe", "judge", "one_step_nrmse",
           "select_residual", "window_loss", "windows"]
