"""The valley check after the whole record's fit.

Over the whole record the cost along the clearances' rugged direction is a comb of valleys a
fraction of a nanometre wide: a fit can end a few valleys from the truth's with a chi² the
noise explains. Over the continuation's first lined window the valleys are wide enough for a
line of runs through the fit to resolve them: :func:`valley_check` finds the others there as
low as the fit's own, which widen the intervals (:func:`jointplay.calibration.basins.widened`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from jointplay.calibration.continuation import (
    ValleyScan,
    _lines_chi2,
    _window_problem,
    horizon_windows,
)
from jointplay.calibration.predict import Predictor, line_minima


@dataclass(frozen=True)
class ValleyCheck:
    """What :func:`valley_check` found: its window (s), the other valleys' floors along its
    line (a point and its chi² minus the fit's own valley's floor), the line's spacing per
    parameter, its runs, and its points' extent (lowest, highest; None without a line; a
    grid spacing either side where ``coarse``: too coarse for the fit's own valley)."""

    window_end: float
    rivals: tuple[tuple[np.ndarray, float], ...]
    spacing: np.ndarray
    runs: int
    extent: tuple[np.ndarray, np.ndarray] | None = None
    centre: np.ndarray | None = None
    """The point the line passes through (the fit it checks)."""
    coarse: bool = False


RESOLVED_POINTS = 3
"""A line resolves the valleys along it where the fit's own valley (its points within the
threshold of its floor) spans at least this many points: a valley as wide holds one of them."""


def valley_check(predictor: Predictor, weights: np.ndarray, best: np.ndarray,
                 scan: ValleyScan, looser: float, growth: float, within: float,
                 workers: int) -> ValleyCheck:
    """The valleys near ``best`` the search cannot tell from its own: along a line of
    ``scan.points`` runs over the first window of at least ``scan.window`` through ``best``
    along the rugged directions, ``scan.reach`` times ``scan.scale`` either side, each other
    valley whose floor lies within ``within`` of (or below) the floor of ``best``'s own."""
    measured, free = predictor.measured, predictor.free
    ends = horizon_windows(measured.t, len(measured.columns), free.size, scan.window, growth)
    if not ends:
        return ValleyCheck(0.0, (), np.zeros(free.size), 0)
    part, stage_scene = _window_problem(predictor, ends[0], looser)
    # The rugged directions only: a line along the weakest one too changed no interval's
    # coverage on the benchmark cases, and cost correct verdicts and half the check's runs.
    steps = np.linspace(-scan.reach, scan.reach, 2 * (scan.points // 2) + 1)
    directions, lines, values, runs = _lines_chi2(predictor, stage_scene, part, weights, best,
                                                  scan.scale, steps, workers)
    rivals: list[tuple[np.ndarray, float]] = []
    spacing, coarse = np.zeros(free.size), False
    for n, (line, chi2) in enumerate(zip(lines, values, strict=True)):
        own = _valley_floor(chi2, steps.size // 2)
        rivals += [(line[i], float(chi2[i] - chi2[own])) for i in line_minima(chi2)
                   if i != own and chi2[i] <= chi2[own] + within]
        coarse |= _valley_points(chi2, own, chi2[own] + within) < RESOLVED_POINTS
        spacing = np.maximum(spacing, np.abs(directions[n]) * (steps[1] - steps[0]))
    points = np.array([p for line in lines for p in line]).reshape(-1, free.size)
    extent = (points.min(axis=0), points.max(axis=0)) if len(points) else None
    if coarse:  # the search located the fit to within a grid spacing, and no closer
        scale = np.asarray(scan.scale)
        extent = (np.maximum(best - scale, free.lower), np.minimum(best + scale, free.upper))
    return ValleyCheck(float(ends[0]), tuple(rivals), spacing, runs, extent,
                       np.array(best, dtype=float), coarse)


def _valley_points(chi2: np.ndarray, floor: int, level: float) -> int:
    """How many adjacent points around index ``floor`` of a line lie at or below ``level``."""
    below = np.append(np.insert(np.isfinite(chi2) & (chi2 <= level), 0, False), False)  # padded
    low = floor - np.flatnonzero(~below[:floor + 1])[-1]
    high = np.flatnonzero(~below[floor + 2:])[0]
    return int(low + high + 1) if below[floor + 1] else 0


def _valley_floor(chi2: np.ndarray, i: int) -> int:
    """The index reached going downhill from index ``i`` along a line: the floor of its
    valley (``i`` itself where the value there is not finite)."""
    if not math.isfinite(chi2[i]):
        return i
    while True:
        lower = [j for j in (i - 1, i + 1) if 0 <= j < chi2.size
                 and math.isfinite(chi2[j]) and chi2[j] < chi2[i]]
        if not lower:
            return i
        i = min(lower, key=lambda j: chi2[j])
