"""The fit: weighted least squares on the compiled model, from several starts where needed.

``scipy.optimize.least_squares`` (trust-region reflective, inside the physical bounds,
``x_scale="jac"``) on the residuals whitened by the noise, the Jacobian from the model's
sensitivities; where an optimum does not explain the data, restarts from a Latin hypercube
around the first start.
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from jointplay.calibration.measured import Measured
from jointplay.calibration.parameters import FreeParameters
from jointplay.calibration.predict import Predictor, TrialFailed, chi2_at, line_minima, whitened
from jointplay.common.errors import SimulationError
from jointplay.common.pool import parallel_map

CHI2_SIGMAS = 5.0
"""A fit whose chi² exceeds dof + CHI2_SIGMAS sqrt(2 dof) does not explain the data within
the stated noise: the next start is tried."""


@dataclass(frozen=True)
class Start:
    """One start of the multi-start: where it began, where it ended, at what cost."""

    start: tuple[float, ...]
    end: tuple[float, ...]
    chi2: float
    evaluations: int
    message: str
    failed: bool = False


@dataclass(frozen=True)
class Optimum:
    values: np.ndarray
    sigma: np.ndarray
    residuals: np.ndarray
    jacobian: np.ndarray
    starts: tuple[Start, ...]


def moved_to(predictor: Predictor, optimum: Optimum, x: np.ndarray) -> Optimum:
    """``optimum`` moved to ``x`` (a lower minimum): its residuals and Jacobian there."""
    residuals = whitened(predictor.outputs(x) - predictor.measured.values, optimum.sigma)
    jacobian = whitened(predictor.jacobian(x), optimum.sigma)
    return Optimum(x, optimum.sigma, residuals, jacobian, optimum.starts)


def starts_around(free: FreeParameters, count: int, spread: float, seed: int) -> np.ndarray:
    """``count`` starts: the first one given, then a seeded Latin hypercube in the box of
    ±``spread`` (relative) around it, inside the physical bounds."""
    from scipy.stats import qmc

    first = free.start
    if count <= 1:
        return first[None, :]
    low, high = search_box(free, first, spread)
    sample = qmc.LatinHypercube(d=free.size, seed=seed).random(count - 1)
    return np.vstack([first, low + sample * (high - low)])


def search_box(free: FreeParameters, centre: np.ndarray, spread: float
               ) -> tuple[np.ndarray, np.ndarray]:
    """The box of ±``spread`` (relative; absolute where a value is 0) around ``centre``,
    inside the physical bounds: its lowest and highest corners."""
    width = np.where(centre != 0, spread * np.abs(centre), spread)
    return np.maximum(centre - width, free.lower), np.minimum(centre + width, free.upper)


def least_squares_fit(predictor: Predictor, sigma: np.ndarray, starts: np.ndarray,
                      max_evaluations: int, scan: Scan | None = None,
                      leading: int = 1, workers: int = 1, give_up: bool = False) -> Optimum:
    """The best optimum over ``starts``, ``sigma`` the noise (stated or estimated). The first
    ``leading`` starts come first (more than one: each fitted, on up to ``workers`` processes,
    the best kept); then, while the fit does not explain the data, the scan of the weakest
    direction (when asked) and the rest of ``starts`` (a multi-start's). Each fit settles
    (``give_up``: see :func:`multi_start`)."""
    ending = {"settle": True, "give_up": give_up}
    best, record = multi_start(predictor, sigma, starts[:leading], max_evaluations,
                               stop_early=leading == 1, workers=workers, **ending)
    if scan is not None and scan.points > 0 and not _explains(record, predictor):
        seeds = scan_weakest_direction(predictor, sigma, best, starts[0], scan)
        best, more = multi_start(predictor, sigma, np.vstack([best, seeds]), max_evaluations,
                                 stop_early=True, **ending)
        record += more[1:]
    if len(starts) > leading and not _explains(record, predictor):
        best, more = multi_start(predictor, sigma, np.vstack([best, starts[leading:]]),
                                 max_evaluations, stop_early=True, **ending)
        record += more[1:]
    residuals = whitened(predictor.outputs(best) - predictor.measured.values, sigma)
    jacobian = whitened(predictor.jacobian(best), sigma)
    return Optimum(best, sigma, residuals, jacobian, tuple(record))


@dataclass(frozen=True)
class Scan:
    """The scan of the weakest direction: ``points`` runs along the line through the first
    optimum in the direction the data see least, across ±``spread`` of the start; local fits
    from the ``refine`` lowest local minima of chi² along it."""

    points: int
    spread: float
    refine: int


def scan_weakest_direction(predictor: Predictor, weights: np.ndarray, best: np.ndarray,
                           start: np.ndarray, scan: Scan) -> np.ndarray:
    """Starts for local fits: the lowest local minima of chi² along the line through the
    first fit in the direction the data determine least, where impacts make the cost rugged
    (one run per point; a basin narrower than the spacing can be missed)."""
    free = predictor.free
    jac = whitened(predictor.jacobian(best), weights)
    width = np.where(start != 0, scan.spread * np.abs(start), scan.spread)
    _, vectors = np.linalg.eigh((jac * width).T @ (jac * width))
    direction = vectors[:, 0] * width  # a unit step moves each parameter by its box width
    ends = []
    for sign in (-1.0, 1.0):
        step = np.inf
        for k in range(free.size):
            if direction[k] != 0:
                bound = free.upper[k] if sign * direction[k] > 0 else free.lower[k]
                step = min(step, (bound - best[k]) / (sign * direction[k]))
        ends.append(sign * min(step, 1.0))
    line = np.linspace(ends[0], ends[1], scan.points)
    points = [np.clip(best + s * direction, free.lower, free.upper) for s in line]
    chi2, _ = chi2_at(predictor, weights, points)
    minima = line_minima(np.array(chi2))
    return np.array([points[i] for i in minima[:scan.refine]]).reshape(-1, free.size)


def explaining_limit(dof: int) -> float:
    """The highest chi² that explains the data within the stated noise on ``dof`` degrees of
    freedom (at least one): dof + CHI2_SIGMAS sqrt(2 dof)."""
    dof = max(dof, 1)
    return dof + CHI2_SIGMAS * math.sqrt(2 * dof)


def _explains(record: list[Start], predictor: Predictor) -> bool:
    lowest = min(start.chi2 for start in record)
    return lowest <= explaining_limit(predictor.measured.size - predictor.free.size)


def multi_start(predictor: Predictor, weights: np.ndarray, starts: np.ndarray,
                max_evaluations: int, stop_early: bool, workers: int = 1, settle: bool = False,
                relative: float = 0.0, give_up: bool = False) -> tuple[np.ndarray, list[Start]]:
    """Local fits from ``starts``, the best kept: in turn with ``stop_early`` (none after one
    that explains the data), else on up to ``workers`` forked processes (runs counted in
    ``predictor``). With ``settle``, each ends once settled (SETTLED_SIGMAS) or once its next
    step moves every parameter by less than ``relative`` of its value; with ``give_up``, once
    it cannot explain the data at its pace (PACE_EVALUATIONS)."""
    accept = explaining_limit(predictor.measured.size - predictor.free.size)
    best: np.ndarray | None = None
    best_chi2 = math.inf
    done: list[Start] = []
    if stop_early or workers <= 1:
        for x0 in starts:
            done.append(_local_fit(predictor, weights, x0, max_evaluations, settle, relative,
                                   give_up))
            if stop_early and done[-1].chi2 <= accept:
                break
    else:
        def fit(i: int) -> tuple[Start, dict[str, int]]:
            # counted here, in the worker: one worker may run several fits in turn
            before = dict(predictor.counter.by_kind)
            start = _local_fit(predictor, weights, starts[i], max_evaluations, settle,
                               relative, give_up)
            return start, {k: v - before.get(k, 0) for k, v in predictor.counter.by_kind.items()}

        for start, counts in parallel_map(fit, len(starts), workers):
            done.append(start)
            for kind, n in counts.items():
                predictor.counter.simulations += n
                predictor.counter.by_kind[kind] = predictor.counter.by_kind.get(kind, 0) + n
    for start in done:
        if not start.failed and start.chi2 < best_chi2:
            best, best_chi2 = np.array(start.end), start.chi2
    if best is None:
        first = next((s.message for s in done if s.failed), "no finite chi²")
        raise SimulationError(math.nan, f"every start of the calibration stopped: {first}")
    return best, done


SETTLED_SIGMAS = 0.1
"""A local fit ends at its best point once its next step lies within this many standard
deviations of it (the Jacobian's metric there, scaled by sqrt(chi²/dof) where above one): such
a step changes chi² by hundredths, below the integrator's scatter, where SciPy's ``xtol`` goes
on shrinking the trust region through rejected runs."""


PACE_EVALUATIONS = 10
"""Evaluations over which ``give_up`` judges a fit's pace (on the whole record a misfit creeps
down a rugged valley for all its evaluations, refining estimates the report cannot trust)."""


class _Settled(Exception):
    """The fit ends at its best point: settled, or (with a message) given up."""


def _local_fit(predictor: Predictor, weights: np.ndarray, x0: np.ndarray,
               max_evaluations: int, settle: bool = False, relative: float = 0.0,
               give_up: bool = False) -> Start:
    from scipy.optimize import least_squares

    free, measured = predictor.free, predictor.measured
    dof = max(measured.size - free.size, 1)
    x0 = np.clip(x0, free.lower, free.upper)
    # The first evaluation is always followed by a Jacobian there; a later one only where its
    # step is accepted (the impacts make the cost rugged), so it runs without sensitivities (a
    # fifth to a third of the cost) and the Jacobian, when asked for, takes a run with them.
    evaluations = [0]
    last: list[Any] = [None, math.inf]  # the last point evaluated and its chi²
    # the accepted point: (x, whitened Jacobian, chi²)
    best: list[tuple[np.ndarray, np.ndarray, float] | None] = [None]
    accepted: list[tuple[int, float]] = []  # (evaluations, chi²) at each accepted point
    limit = explaining_limit(dof) if give_up else math.inf

    def residuals(x: np.ndarray) -> np.ndarray:
        if settle and best[0] is not None and (_within(x, best[0], dof) or _small(
                x, best[0][0], relative)):
            raise _Settled
        if (why := gave_up()) is not None:
            raise _Settled(why)
        wanted = evaluations[0] == 0
        evaluations[0] += 1
        try:
            r = whitened(predictor.outputs(x, with_jacobian=wanted) - measured.values, weights)
        except TrialFailed:
            # A predictor that retreats (a mechanism's) gives SciPy a non-finite residual,
            # on which it shrinks its trust region; the first point's failure ends the fit.
            if evaluations[0] == 1 or not getattr(predictor, "retreats_from_failures", False):
                raise
            last[0], last[1] = np.array(x), math.inf
            return np.full(measured.size, np.inf)
        last[0], last[1] = np.array(x), float(r @ r)
        return r

    def gave_up() -> str | None:
        # above the limit, and at its pace over the last PACE_EVALUATIONS evaluations or more
        # the rest would not bring it there (None: the fit goes on)
        done = evaluations[0]
        earlier = [(n, chi2) for n, chi2 in accepted if n <= done - PACE_EVALUATIONS]
        if not earlier or not limit < accepted[-1][1] < math.inf:
            return None
        (n, before), now = earlier[-1], accepted[-1][1]
        if now - (before - now) / (done - n) * (max_evaluations - done) <= limit:
            return None
        return (f"gave up: chi² {now:.6g} does not explain the data (above {limit:.6g}), and "
                f"its last {done - n} evaluations lowered it by {before - now:.3g}, too slowly "
                "to get there")

    def jacobian(x: np.ndarray) -> np.ndarray:
        # SciPy asks for the Jacobian only at a point it accepts, just after evaluating it
        jac = whitened(predictor.jacobian(x), weights)
        chi2 = last[1] if np.array_equal(last[0], x) else math.inf
        best[0] = (np.array(x), jac, chi2)
        accepted.append((evaluations[0], chi2))
        return jac

    try:
        fit = least_squares(residuals, x0, jac=jacobian, bounds=(free.lower, free.upper),
                            x_scale="jac", method="trf", max_nfev=max_evaluations)
    except TrialFailed as err:
        return Start(tuple(x0), tuple(x0), math.inf, 0, str(err), failed=True)
    except _Settled as why:
        assert best[0] is not None  # only raised once a point was accepted
        x, _, chi2 = best[0]
        return Start(tuple(x0), tuple(x), chi2, evaluations[0], str(why) or "settled: the next "
                     f"step lies within {SETTLED_SIGMAS} standard deviations of the best point"
                     + (f" or {relative:g} of its values" if relative else ""))
    return Start(tuple(x0), tuple(fit.x), 2.0 * float(fit.cost), int(fit.nfev), str(fit.message))


def _within(x: np.ndarray, best: tuple[np.ndarray, np.ndarray, float], dof: int) -> bool:
    """Whether ``x`` lies within SETTLED_SIGMAS standard deviations of the best point in the
    metric of its (whitened) Jacobian, scaled by the misfit sqrt(chi²/dof) where above one;
    ``best``: that point, its Jacobian and its chi²."""
    centre, jac, chi2 = best
    if not math.isfinite(chi2):
        return False
    moved = float(np.linalg.norm(jac @ (np.asarray(x, float) - centre)))
    return moved < SETTLED_SIGMAS * math.sqrt(max(1.0, chi2 / dof))


def _small(x: np.ndarray, centre: np.ndarray, relative: float) -> bool:
    """Whether ``x`` moves every parameter by at most ``relative`` of its value at
    ``centre`` (never, with ``relative`` 0)."""
    return relative > 0 and bool(np.all(np.abs(x - centre) <= relative * np.abs(centre)))


def timed() -> tuple[float, float]:
    """Wall and CPU seconds; the CPU seconds include the worker processes that have ended
    (the grid's, the tracks' and the lines' pieces run in forked processes)."""
    children = os.times()
    return (time.perf_counter(),
            time.process_time() + children.children_user + children.children_system)


def residual_statistics(measured: Measured, fitted: np.ndarray, sigma: np.ndarray,
                        n_free: int) -> dict[str, Any]:
    """Per-column RMS of the residuals, chi² against the noise, dof and chi²/dof."""
    raw = fitted - measured.values
    chi2 = float(np.sum((raw / sigma[None, :]) ** 2))
    dof = measured.size - n_free
    return {
        "rms": {c: float(np.sqrt(np.mean(raw[:, k] ** 2))) for k, c in enumerate(measured.columns)},
        "max_abs": {c: float(np.max(np.abs(raw[:, k]))) for k, c in enumerate(measured.columns)},
        "chi2": chi2,
        "dof": int(dof),
        "normalised_chi2": chi2 / dof if dof > 0 else math.nan,
        "samples": int(measured.t.size),
    }
