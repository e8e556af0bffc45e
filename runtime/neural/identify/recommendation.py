"""The controller to use, in one line of report.md and metrics.json, from how the residual
weight was chosen: whether the network earned its place against its linear base on
validation (``jointplay control`` says it again from its own runs:
:mod:`jointplay.neural.study.recommend`)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

# The rows of ``jointplay control`` that run each model (jointplay.neural.study.comparison).
LINEAR, LPV, NEURAL = "ARX-IMC", "LPV-ARX-IMC", "neural IMC"


def recommend_from_identification(residual: dict[str, Any], lpv_base: bool) -> str:
    """One line for report.md: the controller to use, from how the residual weight was
    chosen (``residual``: metrics.json's ``residual``)."""
    base = "LPV-ARX" if lpv_base else "ARX"
    base_row = LPV if lpv_base else LINEAR
    closed = residual.get("closed_loop")
    alpha = float(residual.get("alpha", 0.0))
    if closed:
        scores = closed.get("score_by_candidate", {})
        other = closed.get("best_other")
        margin = float(closed.get("margin", 0.0))
        best = (f"the best other candidate, {other}, scored "
                + ("diverged" if scores.get(other) is None else f"{scores[other]:.3g}x")
                + " its error" if other else "no other candidate ran")
        if closed.get("chosen") == "ARX twin":
            return (f"Controller to use: {LINEAR} (the saved model is the ARX twin): in "
                    f"closed loop on validation it beat the {base} base by more than "
                    f"{margin:.0%} on every motion (score {scores.get('ARX twin', 0):.3g}).")
        if alpha == 0:
            return (f"Controller to use: {base_row} (the saved network is its {base} base, "
                    f"alpha = 0): in closed loop on validation no candidate beat the {base} "
                    f"base by more than {margin:.0%} on every motion ({best}).")
        return (f"Controller to use: {NEURAL}: in closed loop on validation the network "
                f"(alpha = {alpha:g}) beat its {base} base on every motion, score "
                f"{scores.get(closed.get('chosen'), 0):.3g}x its error (needed: at most "
                f"{1 - margin:.3g}x).")
    if alpha == 0:
        return (f"Controller to use: {base_row} (the saved network is its {base} base, "
                f"alpha = 0): the network did not improve on it in free run on validation. "
                "`jointplay control` compares them in closed loop.")
    return (f"Controller to use: {NEURAL}, on the free-run criterion (alpha = {alpha:g}: "
            f"validation loss {residual['free_run_loss']:.4g} against the {base} base's "
            f"{residual['free_run_loss_arx']:.4g}); that criterion does not predict the closed "
            "loop: `jointplay control` compares them there.")


# A free-run NRMSE at or above this (or not finite) is printed "diverges" in the tables.
DIVERGED_NRMSE = 1e3
_BASELINE_NAMES = {"model": "the saved model", "arx": "ARX", "lpv_arx": "LPV-ARX"}


def diverged_outputs(nrmse: Sequence[float], outputs: Sequence[str]) -> list[str]:
    """The outputs whose free-run NRMSE the tables print as "diverges"."""
    return [name for value, name in zip(nrmse, outputs, strict=True)
            if not math.isfinite(value) or abs(value) >= DIVERGED_NRMSE]


def choice_lines(metrics: dict[str, Any], lpv_base: bool) -> list[str]:
    """The head of report.md: the controller to use and why, then what the tables below say
    about the same models and why that does not overturn the choice (or that it is a
    different question), in the tables' own terms."""
    residual = metrics.get("residual")
    if not residual:
        return []
    base = "LPV-ARX" if lpv_base else "ARX"
    closed = residual.get("closed_loop")
    alpha = float(residual.get("alpha", 0.0))
    saved = (f"the {base} base (alpha = 0)" if alpha == 0
             else f"the network ({base} + {alpha:g} x the residual)")
    if closed and closed.get("chosen") == "ARX twin":
        saved = "the ARX twin"
    lines = ["## The choice", "",
             f"**{recommend_from_identification(residual, lpv_base)}**", ""]
    if closed:
        scores = ", ".join(f"{k}: " + ("diverged" if v is None else f"{v:.3g}x")
                           for k, v in closed.get("score_by_candidate", {}).items())
        criterion = ("Decided in closed loop: each candidate ran as the controller on the "
                     "validation motions, scored by its RMS end-effector acceleration error "
                     f"as a ratio to the {base} base's (lower is better): {scores}.")
    else:
        criterion = ("Decided by the free-run loss on the validation runs (the model "
                     "simulated open loop from the inputs alone): no candidate ran as the "
                     "controller.")
    outputs = metrics.get("outputs", [])
    test = metrics.get("test", {}).get("narx", {}).get("free_run", {}).get("nrmse", [])
    away = diverged_outputs(test, outputs) if len(test) == len(outputs) else []
    tables = [f"- The saved model is {saved}; the tables call it `narx` and \"saved model\"."]
    if away:
        tables.append(f"- In free run on the test runs it diverges on {len(away)} of "
                      f"{len(outputs)} outputs ({', '.join(away)}).")
    losses = metrics.get("free_run_loss")
    if losses:
        best = {part: min(losses[part], key=lambda k: losses[part][k])
                for part in ("validation", "test")}
        said = "; ".join(f"{_BASELINE_NAMES[best[p]]} on the {p} runs" for p in best)
        tables.append(f"- The lowest free-run loss (the `best` column) is {said}.")
        if any(b != "model" for b in best.values()):
            tables.append(
                "- So the free-run tables rank another model first. " + (
                    "Free run is not the criterion here: the controller corrects its model "
                    "with the measured mismatch every sample, and the closed-loop scores above "
                    "decide." if closed else
                    "The free-run criterion weighs only the network against its "
                    f"{base} base on the validation runs" + (
                        "; LPV-ARX was not a candidate (`--lpv-base` makes it the base)"
                        if not lpv_base else "") + "."))
    return [*lines, criterion, "",
            "What the tables below say about the same models (they judge each as a "
            "simulator, in free run, not as a controller):", "", *tables,
            "- `jointplay control --model DIR` runs ARX-IMC, LPV-ARX-IMC and the neural IMC "
            "side by side in closed loop and says which did best there.", ""]


__all__ = ["DIVERGED_NRMSE", "choice_lines", "diverged_outputs", "recommend_from_identification"]
