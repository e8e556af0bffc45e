"""Which controller to use, in one line, from one comparison's runs, as ``jointplay control``
says it (``identify`` says it from validation: :mod:`jointplay.neural.identify.recommendation`):
the controller with the lowest RMS end-effector acceleration error after settling (the
goal's metric), where a simpler one within
:data:`jointplay.neural.control.metrics.WORSE_MARGIN` of it is preferred (a tie is not a
reason for a network), and a controller that diverged or drew a warning is not recommended
while one that did not is there.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass

from jointplay.neural.control.metrics import WORSE_MARGIN
from jointplay.neural.study.comparison import CONTROLLERS, LINEAR, LPV, NEURAL

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
            why.append(f"{mine / metrics[other][METRIC]:.3f}x {other}'s")
    line = f"use {chosen}: " + ", ".join(why) + ")"
    if chosen != best:
        line += (f"; {best} is within {WORSE_MARGIN:.0%} of it ({value:.3g}), a tie, and "
                 f"{chosen} is the simpler controller")
    elif NEURAL in metrics and chosen != NEURAL and NEURAL in pool:
        ratio = metrics[NEURAL][METRIC] / mine
        line += f"; the neural IMC has {ratio:.3f}x its error"
    if NEURAL in metrics and residual_weight == 0:
        line += ("; the network's residual weight is 0 (it did not beat its linear base on "
                 "validation), so the neural IMC runs that linear model")
    excluded = [n for n in ran if n in warned and n not in pool]
    if excluded:
        line += f"; not recommended for their warnings: {', '.join(excluded)}"
    return Recommendation(chosen, line)


__all__ = ["METRIC", "Recommendation", "recommend_from_runs"]
