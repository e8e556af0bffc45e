"""Cost profiles: chi² along each free parameter, the others held at their estimates (one run
per point). Beside the quadratic the covariance predicts (chi²_min + ((p - p̂)/σ_cond)², σ_cond
the standard deviation with the others fixed) a profile shows whether the linearisation behind
the intervals holds, and where impacts make the cost jump or a second minimum appear.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from jointplay.calibration.predict import Predictor, chi2_at_points
from jointplay.calibration.uncertainty import Uncertainty

PROFILE_SIGMAS = 4.0
"""Half-width of a profile, in standard deviations of the estimate (others held)."""
UNDETERMINED_SPAN = 0.5
"""Half-width, relative to the value, of the profile of a parameter without a finite std."""


def cost_profiles(predictor: Predictor, optimum: Any, spread: Uncertainty, points: int,
                  workers: int = 1) -> tuple[dict[str, dict[str, list[float]]], int]:
    """``{name: {"value": [...], "chi2": [...], "quadratic": [...]}}`` (empty if points=0;
    chi² NaN where the run stops), and the runs, made on up to ``workers`` processes; for an
    arm's and a mechanism's predictor alike."""
    if points == 0:
        return {}, 0
    free, best = predictor.free, optimum.values
    chi2_min = float(np.sum(optimum.residuals**2))
    jtj_diag = np.sum(optimum.jacobian**2, axis=0)
    grids = []
    for k in range(free.size):
        half = (PROFILE_SIGMAS * float(spread.std[k]) if math.isfinite(spread.std[k])
                else UNDETERMINED_SPAN * (abs(best[k]) or 1.0))
        grids.append(np.linspace(max(best[k] - half, free.lower[k]),
                                 min(best[k] + half, free.upper[k]), points))
    every = [np.where(np.arange(free.size) == k, value, best)
             for k, grid in enumerate(grids) for value in grid]
    # its own count (the runs are returned, not counted twice) and cache (one run a point);
    # the estimate itself (each profile's middle) is not run again: its chi² is chi2_min
    probe = predictor.over(predictor.scene)
    away = [x for x in every if not np.array_equal(x, best)]
    found, runs = chi2_at_points(probe, optimum.sigma, away, workers)
    rest = iter(found)
    values = [chi2_min if np.array_equal(x, best) else next(rest) for x in every]
    out: dict[str, dict[str, list[float]]] = {}
    for k, name in enumerate(free.names):
        sigma_held = 1.0 / math.sqrt(jtj_diag[k]) if jtj_diag[k] > 0 else math.inf
        chi2 = [v if math.isfinite(v) else math.nan
                for v in values[k * points:(k + 1) * points]]
        quadratic = chi2_min + ((grids[k] - best[k]) / sigma_held) ** 2
        out[name] = {"value": grids[k].tolist(), "chi2": chi2,
                     "quadratic": quadratic.tolist(), "estimate": [float(best[k])],
                     "chi2_min": [chi2_min]}
    return out, runs
