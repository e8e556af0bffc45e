"""How good an identified model is: one-step and free-run NRMSE and fit per output against
persistence and the ARX twin, as tables and as the model folder's report."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from jointplay.neural.identify.config import IdentifyConfig
from jointplay.neural.identify.recommendation import DIVERGED_NRMSE, choice_lines
from jointplay.neural.identify.trajectories import Trajectory
from jointplay.neural.model.inner_loop import contact_joints
from jointplay.neural.model.narx import Narx, fit_percent, nrmse


def evaluate(models: dict[str, Narx | None], trajectories: Sequence[Trajectory], skip: int,
             history: int) -> dict[str, Any]:
    """One-step and free-run NRMSE / fit per output over ``trajectories`` (concatenated).

    ``None`` stands for persistence: y(k+1) = y(k) one step ahead, and the first sample held
    in free run.
    """
    out: dict[str, Any] = {}
    for name, model in models.items():
        preds_one, preds_free, truth = [], [], []
        for tr in trajectories:
            d, u = tr.deviation[skip:], tr.v[skip:]
            w = None
            if model is not None and model.n_scheduling:
                from jointplay.neural.model.scheduling import trajectory_scheduling

                w = trajectory_scheduling(tr, model.output_names, model.input_names)[skip:]
            truth.append(d[history + 1:])
            if model is None:
                preds_one.append(d[history: -1])
                preds_free.append(np.repeat(d[history: history + 1], d.shape[0] - history - 1,
                                            axis=0))
            else:
                preds_one.append(model.one_step(d, u, w))
                with np.errstate(all="ignore"):
                    preds_free.append(model.free_run(d, u, w))
        y = np.vstack(truth)
        one, free = np.vstack(preds_one), np.vstack(preds_free)
        free = np.where(np.isfinite(free), free, np.sign(np.nan_to_num(free)) * 1e300)
        with np.errstate(all="ignore"):
            out[name] = {"one_step": {"nrmse": nrmse(one, y).tolist(),
                                      "fit": fit_percent(one, y).tolist()},
                         "free_run": {"nrmse": nrmse(free, y).tolist(),
                                      "fit": fit_percent(free, y).tolist()}}
    return out


def _fmt(value: float, kind: str = "nrmse") -> str:
    if not math.isfinite(value) or abs(value) >= DIVERGED_NRMSE:
        return "diverges"
    if kind == "fit":
        return f"{value:.1f}"
    return f"{value:.4f}" if value < 10 else f"{value:.1f}"


def metrics_table(metrics: dict[str, Any], outputs: Sequence[str], kind: str = "nrmse") -> str:
    """Markdown: NRMSE (or fit %) per output, one-step and free run, for each model."""
    models = list(metrics)
    head = "| output | " + " | ".join(f"{m} 1-step | {m} free run" for m in models) + " |"
    rule = "|---|" + "---|---|" * len(models)
    lines = [head, rule]
    for i, name in enumerate(outputs):
        cells = []
        for m in models:
            cells += [_fmt(metrics[m]["one_step"][kind][i], kind),
                      _fmt(metrics[m]["free_run"][kind][i], kind)]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    cells = []
    for m in models:
        for mode in ("one_step", "free_run"):
            vals = np.asarray(metrics[m][mode][kind], dtype=float)
            cells.append(_fmt(float(np.mean(np.clip(vals, -1e3, 1e3))), kind))
    lines.append("| **mean** | " + " | ".join(cells) + " |")
    return "\n".join(lines)



def identify_report(scene: Any, model: Narx, metrics: dict[str, Any],
                    config: IdentifyConfig) -> str:
    inner = model.context["plant"]["inner_loop"]
    contact = list(contact_joints(model.output_names))
    lines = [
        f"# Identification of {scene.name}",
        "",
        *choice_lines(metrics, config.lpv_base),
        "## The model and its errors",
        "",
        f"NARX: {model.n_regressor} regressors ({model.output_lags} output lags, "
        f"{model.input_lags} input lags) -> hidden {list(model.hidden)} (tanh)"
        f"{' + linear direct path' if model.linear is not None else ''}"
        f"{' + bilinear part (LPV-ARX input gain)' if model.bilinear is not None else ''} -> "
        f"{model.n_outputs} outputs; sample time {model.sample_time:g} s."
        + (" The hidden layers do not see the input lags: the input gain is the linear "
           "part's." if config.linear_input_gain else ""),
        f"Plant: clearance robot under a joint PD (kp {inner['kp']}, kd {inner['kd']}) around "
        "the ideal robot's motion; outputs are deviations from it"
        + (f", and the journal eccentricities of joints {contact} (the ideal robot's are 0)."
           if contact else "."),
        f"Trajectories: {metrics['trajectories']} of {config.duration:g} s; test families "
        f"{metrics['test_families']} (fresh realisations; the chirp is never used in "
        "training)"
        + ("; the training and validation runs are driven by the scene's torques and by "
           "the scene's torques at other amplitudes, rates and time shifts (--base-motions "
           "scene-family)" if config.base_motions == "scene-family" else "")
        + f". The first {config.transient:g} s of each (journals settling from e = 0) are "
        "left out.",
        f"Time: simulate {metrics['seconds']['simulate']:.1f} s, train "
        f"{metrics['seconds']['train']:.1f} s.",
        "",
        "NRMSE on the test trajectories (RMS error / standard deviation of the output; fit % "
        "= 100 (1 - NRMSE)); `persistence` is y(k+1) = y(k) one step ahead and the first "
        "sample held in free run; `arx` is a linear model on the same regressor:",
        "",
        metrics_table(metrics["test"], metrics["outputs"]),
        "",
        "Fit % on the same trajectories:",
        "",
        metrics_table(metrics["test"], metrics["outputs"], "fit"),
        "",
    ]
    res = metrics.get("residual")
    if res:
        tried = ", ".join(f"{a}: {v:.4g}" for a, v in res["free_run_loss_by_alpha"].items())
        # With --lpv-base the linear model the residual is weighed against is LPV-ARX.
        base = "LPV-ARX" if config.lpv_base else "ARX"
        closed = res.get("closed_loop")
        lines += [
            (f"Network = {base} + alpha x (nonlinear residual), alpha chosen on the validation "
             f"trajectories by the free-run loss over {config.window}-sample windows: "
             f"alpha = {res['alpha']:g} (loss by alpha: {tried}; persistence "
             f"{res['free_run_loss_persistence']:.4g}). "
             + ("The residual improves on the linear model on validation."
                if res["alpha"] > 0 and res["free_run_loss"] < res["free_run_loss_arx"]
                else _no_residual_reason(res, base))) if not closed
            else _closed_loop_lines(closed, base, tried, res),
            f"Validation, mean one-step NRMSE: model {res['one_step_nrmse']:.4g}, {base} "
            f"{res['one_step_nrmse_arx']:.4g}, persistence "
            f"{res['one_step_nrmse_persistence']:.4g}.",
            "",
        ]
        dropped = res.get("scheduling_dropped")
        if dropped:
            lines += [
                "With the scheduling signals, no blend beat the ARX twin without them on "
                f"validation (free-run loss {dropped['best_blend_loss']:.4g} against "
                f"{dropped['twin_loss']:.4g}): the saved model is the ARX twin, and the "
                "network does no work.", ""]
        if not res["usable"]:
            lines += ["**REJECTED**: " + "; ".join(res["problems"]) + ".", ""]
    lines += _baseline_lines(metrics)
    lines += _repair_lines(metrics)
    warnings = metrics.get("warnings") or []
    if warnings:
        lines += ["## Warnings", "", *[f"- **warning**: {w}" for w in warnings], ""]
    return "\n".join(lines)


def _closed_loop_lines(closed: dict[str, Any], base: str, tried: str,
                       res: dict[str, Any]) -> str:
    """The residual weight chosen in closed loop: by what, among what, and what was saved."""
    def ratio(v: float | None) -> str:
        return "diverged" if v is None else f"{v:.4g}"

    scores = ", ".join(f"{k}: {ratio(v)}" for k, v in closed["score_by_candidate"].items())
    chosen = closed["chosen"]
    motions = ("motions of the scene's own family" if closed.get("motions") == "scene family"
               else "the validation runs' motions")
    what = ("the ARX twin without the scheduling signals: the network does no work"
            if chosen == "ARX twin" else
            f"the {base} model itself: the network does no work" if closed["alpha"] == 0
            else f"{base} + {closed['alpha']:g} x the residual")
    return (f"Network = {base} + alpha x (nonlinear residual), alpha chosen in closed loop: "
            "each candidate ran as the internal-model controller (default settings) on "
            f"{motions} ({'; '.join(closed['runs'])}), scored by its RMS "
            "end-effector acceleration error after "
            f"{closed['settle_s'] * 1e3:.0f} ms, as a ratio to the {base} model's (geometric "
            f"mean over the runs): {scores}. Saved: {what}. Free-run validation loss by "
            f"alpha, reported, not the criterion: {tried}; persistence "
            f"{res['free_run_loss_persistence']:.4g}.")


def _no_residual_reason(res: dict[str, Any], base: str = "ARX") -> str:
    """Why the residual weight is 0, from the losses (an unstable free run is said as such);
    ``base``: the linear model it was weighed against."""
    net, arx = res["network_free_run_loss"], res["free_run_loss_arx"]
    if not math.isfinite(net) or net > 10 * arx:
        return (f"The trained network's free run is unstable on validation (loss {net:.4g} "
                f"against the linear model's {arx:.4g}), and no residual weight improves on "
                f"the linear model: the saved network is the {base} model.")
    return ("The residual does not improve on the linear model on validation (network "
            f"{net:.4g}, linear {arx:.4g}): the saved network is the {base} model.")


def _baseline_lines(metrics: dict[str, Any]) -> list[str]:
    """The saved model against both linear models in free run (validation and test)."""
    losses = metrics.get("free_run_loss")
    if not losses:
        return []
    lines = [f"Free-run loss over {losses['window']}-sample windows (mean squared error / output "
             "scale; lower is better) of the saved model, its ARX twin and an LPV-ARX model "
             f"(coefficients affine in {losses['scheduling']}; least squares):", "",
             "| runs | saved model | ARX | LPV-ARX | best |", "|---|---|---|---|---|"]
    for part in ("validation", "test"):
        row = losses[part]
        best = min(row, key=lambda k: row[k])
        names = {"model": "saved model", "arx": "ARX", "lpv_arx": "LPV-ARX"}
        lines.append(f"| {part} | {row['model']:.4g} | {row['arx']:.4g} | "
                     f"{row['lpv_arx']:.4g} | {names[best]} |")
    return [*lines, ""]


def _repair_lines(metrics: dict[str, Any]) -> list[str]:
    """What training did when a loss went non-finite (nothing is left silent)."""
    repairs = metrics.get("training_history", {}).get("repairs") or []
    if not repairs:
        return ["Training: no loss went non-finite; no repair was needed.", ""]
    lines = ["## Training repairs", ""]
    for r in repairs:
        lines.append(f"- {r['phase']}: {r['problem']}; {r['action']} "
                     f"({'cured' if r.get('cured') else 'NOT cured'})")
    return [*lines, ""]


__all__ = ["evaluate", "identify_report", "metrics_table"]
