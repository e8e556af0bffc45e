"""The global stage: a coarse grid of the free clearances on a short leading window.

Over the first tens of milliseconds the cost over the free clearances is a handful of valleys
a few micrometres apart and about 2 µm wide; a grid at about that spacing finds them at one
short run per point. Its lowest minima, the other parameters held (the window barely sees
them), start the continuation's tracks.
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass

import numpy as np

from jointplay.calibration.continuation import _holding, _window_problem, loosened, window_looseness
from jointplay.calibration.fit import multi_start, search_box
from jointplay.calibration.parameters import FreeParameters
from jointplay.calibration.predict import Predictor, chi2_at_points
from jointplay.common.errors import SimulationError

CLEARANCE_NAME = re.compile(r"joint\d+\.clearance")
OTHERS_FIRST_RELATIVE = 1e-3
"""The fit of the others before the grid ends once its next step moves each by less than this
fraction (with the clearances at their start the cost is rugged at a millionth of the friction;
the value only seeds the grid and the first windows, which allow a drift of 5 %)."""


@dataclass(frozen=True)
class Grid:
    """How the grid runs: a window ending at ``window_end`` (s), at most ``points`` values of
    each free clearance (at most ``points`` squared runs in all) across ±``spread`` of the
    start, at the fit's tolerances times ``looser`` at most; ``candidates``: the lowest local
    minima kept."""

    window_end: float
    points: int
    spread: float
    candidates: int
    looser: float


@dataclass(frozen=True)
class GridResult:
    """The candidates (best first), their window chi², the grid's axes and its runs (those
    that chose its tolerances included)."""

    candidates: np.ndarray
    chi2: tuple[float, ...]
    axes: tuple[str, ...]
    points_per_axis: int
    window_end: float
    simulations: int


def clearance_axes(names: tuple[str, ...]) -> list[int]:
    """The indices of the free radial clearances."""
    return [k for k, name in enumerate(names) if CLEARANCE_NAME.fullmatch(name)]


def others_first(predictor: Predictor, weights: np.ndarray, start: np.ndarray,
                 looser: float, max_evaluations: int) -> tuple[np.ndarray, int]:
    """``start`` with the free parameters other than the clearances fitted over the whole
    record, the clearances held, at the fit's tolerances times ``looser`` at most; and the
    runs. The grid holds them, and the whole record sees them far better than its window (the
    friction moves the tip by millimetres over 2 s, and barely over the first 20 ms)."""
    free = predictor.free
    axes = clearance_axes(free.names)
    if not axes or len(axes) == free.size:
        return start, 0
    held = np.zeros(free.size, dtype=bool)
    held[axes] = True
    looser, runs = window_looseness(predictor, weights, start, float(predictor.measured.t[-1]),
                                    looser)
    probe = predictor.over(loosened(predictor.scene, looser)).for_free(
        _holding(free, start, held))
    try:
        x, _ = multi_start(probe, weights, start[None, :], max_evaluations, stop_early=False,
                           settle=True, relative=OTHERS_FIRST_RELATIVE)
    except SimulationError:
        return start, runs + probe.counter.simulations
    x = np.asarray(x, dtype=float)
    x[axes] = start[axes]
    return x, runs + probe.counter.simulations


def grid_candidates(predictor: Predictor, weights: np.ndarray, start: np.ndarray,
                    grid: Grid, workers: int = 1) -> GridResult | None:
    """The lowest local minima of the window's chi² over a grid of the free clearances,
    the other free parameters at ``start``; None where no clearance is free or the record
    is no longer than the window."""
    free = predictor.free
    axes = clearance_axes(free.names)
    if not axes or grid.window_end >= predictor.measured.t[-1]:
        return None
    per_axis = min(max(3, math.floor((grid.points ** 2) ** (1.0 / len(axes)) + 1e-9)),
                   grid.points)
    values = [_axis(free, start, k, grid.spread, per_axis) for k in axes]
    looser, checks = window_looseness(predictor, weights, start, grid.window_end, grid.looser)
    part, coarse = _window_problem(predictor, grid.window_end, looser)
    probe = predictor.over(coarse, part)
    indices = list(itertools.product(range(per_axis), repeat=len(axes)))

    def point(index: tuple[int, ...]) -> np.ndarray:
        """The start with the grid's axes set to the values at ``index``."""
        x = start.copy()
        x[axes] = [values[a][i] for a, i in enumerate(index)]
        return x

    values_chi2, runs = chi2_at_points(probe, weights, [point(i) for i in indices], workers)
    # ``indices`` run in row-major order, the order of a reshape
    chi2 = np.array(values_chi2, dtype=float).reshape((per_axis,) * len(axes))
    minima = _local_minima(chi2)
    minima.sort(key=lambda index: chi2[index])
    chosen = minima[:grid.candidates]
    return GridResult(np.array([point(index) for index in chosen]).reshape(-1, free.size),
                      tuple(float(chi2[i]) for i in chosen),
                      tuple(free.names[k] for k in axes), per_axis, float(part.t[-1]),
                      runs + checks)


def grid_scale(free: FreeParameters, start: np.ndarray, grid: GridResult,
               spread: float) -> tuple[float, ...]:
    """Per free parameter, the grid's spacing (the clearances: how far the grid leaves each
    one uncertain) or 0 (the others, fitted over the whole record before the grid)."""
    axes = {k: _axis(free, start, k, spread, grid.points_per_axis)
            for k, name in enumerate(free.names) if name in grid.axes}
    return tuple(float(axes[k][1] - axes[k][0]) if k in axes else 0.0 for k in range(free.size))


def _axis(free: FreeParameters, start: np.ndarray, k: int, spread: float,
          count: int) -> np.ndarray:
    low, high = search_box(free, start, spread)
    return np.linspace(low[k], high[k], count)


def _local_minima(chi2: np.ndarray) -> list[tuple[int, ...]]:
    """Grid points no higher than any neighbour (the corners' diagonals included)."""
    padded = np.pad(chi2, 1, constant_values=np.inf)
    return [index for index in itertools.product(*(range(n) for n in chi2.shape))
            if math.isfinite(chi2[index])
            and chi2[index] <= padded[tuple(slice(i, i + 3) for i in index)].min()]
