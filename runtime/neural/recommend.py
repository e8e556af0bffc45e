"""Which controller to use, in one line, from the measurements at hand.

Two places say it. ``identify`` (report.md, metrics.json) says it from how the residual
weight was chosen: whether the network earned its place against its linear base on
validation. ``control`` says it from its own runs: the controller with the lowest RMS
end-effector acceleration error after settling (the goal's metric), where a simpler one
within :data:`jointplay.neural.metrics.WORSE_MARGIN` of it is preferred (a tie is not a
reason for a network), and a controller that diverged or drew a warning is not recommended
while one that did not is there.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass
from typing import Any

from jointplay.neural.comparison import CONTROLLERS, LINEAR, LPV, NEURAL
from jointplay.neural.metrics import WORSE_MARGIN

METRIC = "rms_acceleration_after"
METRIC_LABEL = "RMS |Δa| after settling"


@dataclass(frozen=True)
class Recommendation:
    """The controller to use and the one line that says why."""

    controller: str
    line: str


def recommend_from_runs(metrics: dict[str, dict[str, float]], warned: Collection[str] = (),
                        residual_weight: float | None = None) -> Recommendation | None:
    """The controller to use from one comparison's metrics (None: no closed-loop controller
    ran). ``warned``: controllers that drew a warning; ``residual_weight``: the network's
    (0: the neural IMC runs its linear base)."""
    ran = [n for n in CONTROLLERS if n != "open loop" and n in metrics
           and not metrics[n].get("diverged") and metrics[n].get(METRIC, 0.0) > 0]
    pool = [n for n in ran if n not in warned] or ran
    if not pool:
        return None
    best = min(pool, key=lambda n: metrics[n][METRIC])
    value = metrics[best][METRIC]
    # The simplest controller within the tie margin of the best (CONTROLLERS runs from the
    # simplest to the network).
    chosen = next(n for n in pool if metrics[n][METRIC] <= value * (1 + WORSE_MARGIN))
    mine = metrics[chosen][METRIC]
    why = [f"lowest {METRIC_LABEL} in this run ({mine:.3g} m/s²"]
    for other in (LINEAR, LPV):
        if other != chosen and other in metrics and metrics[other].get(METRIC, 0) > 0:
            why.append(f"{mine / metrics[other][METRIC]:.3g}x {other}'s")
    line = f"use {chosen}: " + ", ".join(why) + ")"
    if chosen != best:
        line += (f"; {best} is within {WORSE_MARGIN:.0%} of it ({value:.3g}), a tie, and "
                 f"{chosen} is the simpler controller")
    elif NEURAL in metrics and chosen != NEURAL and NEURAL in pool:
        ratio = metrics[NEURAL][METRIC] / mine
        line += f"; the neural IMC has {ratio:.3g}x its error"
    if NEURAL in metrics and residual_weight == 0:
        line += ("; the network's residual weight is 0 (it did not beat its linear base on "
                 "validation), so the neural IMC runs that linear model")
    excluded = [n for n in ran if n in warned and n not in pool]
    if excluded:
        line += f"; not recommended for their warnings: {', '.join(excluded)}"
    return Recommendation(chosen, line)


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


__all__ = ["METRIC", "Recommendation", "recommend_from_identification", "recommend_from_runs"]
