"""The controller to use, in one line of report.md and metrics.json, from how the residual
weight was chosen: whether the network earned its place against its linear base on
validation (``jointplay control`` says it again from its own runs:
:mod:`jointplay.neural.study.recommend`)."""

from __future__ import annotations

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


__all__ = ["recommend_from_identification"]
