"""Cost profiles: chi² along each free parameter, the others held at their estimates.

Held, not re-optimised: a profile then costs one run per point, and beside the quadratic
that the covariance predicts (chi²_min + ((p - p̂)/σ_cond)², σ_cond the conditional standard
deviation with the others fixed) it shows whether the linearisation behind the intervals
holds, and where impacts make the cost jump or a second minimum appear.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from jointplay.calibration.predict import Predictor, TrialFailed, whitened
from jointplay.calibration.uncertainty import Uncertainty

PROFILE_SIGMAS = 4.0
"""Half-width of a profile, in standard deviations of the estimate (others held)."""
UNDETERMINED_SPAN = 0.5
"""Half-width, relative to the value, of the profile of a parameter without a finite std."""


def cost_profiles(predictor: Predictor, optimum: Any, spread: Uncertainty,
                  points: int) -> dict[str, dict[str, list[float]]]:
    """``{name: {"value": [...], "chi2": [...], "quadratic": [...]}}`` (empty if points=0)."""
    if points == 0:
        return {}
    free = predictor.free
    measured = predictor.measured
    best = optimum.values
    chi2_min = float(np.sum(optimum.residuals**2))
    jtj_diag = np.sum(optimum.jacobian**2, axis=0)
    out: dict[str, dict[str, list[float]]] = {}
    for k, name in enumerate(free.names):
        sigma_held = 1.0 / math.sqrt(jtj_diag[k]) if jtj_diag[k] > 0 else math.inf
        if math.isfinite(spread.std[k]):
            half = PROFILE_SIGMAS * float(spread.std[k])
        else:
            half = UNDETERMINED_SPAN * (abs(best[k]) or 1.0)
        grid = np.linspace(max(best[k] - half, free.lower[k]),
                           min(best[k] + half, free.upper[k]), points)
        chi2 = []
        for value in grid:
            x = best.copy()
            x[k] = value
            try:
                residual = whitened(predictor.outputs(x, with_jacobian=False) - measured.values,
                                    optimum.sigma)
                chi2.append(float(np.sum(residual**2)))
            except TrialFailed:
                chi2.append(math.nan)
        quadratic = chi2_min + ((grid - best[k]) / sigma_held) ** 2
        out[name] = {"value": grid.tolist(), "chi2": chi2, "quadratic": quadratic.tolist(),
                     "estimate": [float(best[k])], "chi2_min": [chi2_min]}
    return out
