"""Neighbouring basins: the other minima of the whole record's cost that the data cannot
tell from the best one (impacts make the cost a field of basins a few standard deviations
apart, whose floor can stay flat far beyond one basin's curvature).

The check: lines of plain runs through the best fit along each principal axis of its
confidence ellipsoid; a local fit from each of the lowest line minima (at most :data:`FITS`)
within the threshold plus :data:`SLACK` of the best's chi², a lower one replacing the best.
The intervals are widened to hold every point found within the threshold (:data:`CONFIDENCE`),
and a parameter in which another basin's minimum lies outside the best's interval is not
determined.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from dataclasses import dataclass

import numpy as np

from jointplay.calibration.continuation import loosened
from jointplay.calibration.fit import Start, multi_start
from jointplay.calibration.predict import Predictor, chi2_at_points, line_minima
from jointplay.calibration.uncertainty import MAX_RELATIVE_STD, Z95, Uncertainty
from jointplay.calibration.valleys import RESOLVED_POINTS, ValleyCheck

CONFIDENCE = 0.95
"""The intervals' confidence level: a point within ``chi2.ppf(CONFIDENCE, 1)`` (3.84) of the
lowest chi² lies inside every parameter's profile-likelihood interval at that level."""
REACH_SIGMAS = 5.0
"""How far each line's fine part reaches either side of the best fit, in standard deviations."""
STEP_SIGMAS = 1.0
"""The fine part's spacing in standard deviations (a basin is two to three wide)."""
FAR_SIGMAS = (8.0, 16.0, 32.0)
"""Points beyond the fine part, in standard deviations (the rugged floor can stay flat that far)."""
SLACK = 10.0
"""chi² above the threshold still worth a local fit from a line's minimum."""
FITS = 2
"""Local fits from the lines' minima at most."""
WARN_WIDENING = 1.25
"""The lines' points widen an interval silently up to this factor of its half-width (a smooth
cost departs that little from its quadratic); beyond it a warning says so."""
OTHER_CENTRES = 1
"""Other whole-record minima (within the threshold plus SLACK of the best) the lines also go
through, at most."""
LOOSER = 1.0
"""The lines' runs use the fit's tolerances times this: their chi² decide which points widen
the intervals (within 3.84 of the lowest), so they must be accurate to well under that."""


@dataclass(frozen=True)
class Basins:
    """What the check found: the best fit (the given one or a lower one), the rivals (other
    basins' minima within ``threshold`` of its chi²), its local fits, and the lines' runs."""

    best: np.ndarray
    best_chi2: float
    rivals: tuple[Start, ...]
    threshold: float
    fits: tuple[Start, ...]
    line_runs: int
    region: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros((0, 0)))
    """The lines' points within ``threshold`` of the lowest chi² found (one per row)."""


def threshold() -> float:
    """The chi² rise that bounds each parameter's profile-likelihood interval."""
    from scipy.stats import chi2

    return float(chi2.ppf(CONFIDENCE, 1))


def neighbouring_basins(predictor: Predictor, weights: np.ndarray, best: np.ndarray,
                        best_chi2: float, covariance: np.ndarray, max_evaluations: int,
                        workers: int, others: tuple[Start, ...] = (),
                        axes: np.ndarray | None = None) -> Basins:
    """The check described above, around ``best`` (chi² ``best_chi2``, ``covariance`` its
    estimates' covariance); ``others``: earlier local fits of the same cost (the other tracks'),
    whose minima count as rivals too; ``axes``: the covariance whose principal axes the lines
    follow (default ``covariance``; :attr:`Uncertainty.seen_covariance` where some parameters
    are undetermined, so the directions the data see are still checked)."""
    free, limit = predictor.free, threshold()
    axes = covariance if axes is None else axes
    points = _line_points(best, axes, free.lower, free.upper)
    for other in _other_centres(best, best_chi2, covariance, others, limit + SLACK):
        points += _line_points(other, axes, free.lower, free.upper)
    if not points:
        return _with_rivals(best, best_chi2, covariance, others, Basins(
            best, best_chi2, (), limit, (), 0))
    probe = predictor.over(loosened(predictor.scene, LOOSER))
    every = [best, *(p for line in points for p in line)]
    values, line_runs = chi2_at_points(probe, weights, every, workers)
    centre, rest = values[0], values[1:]
    lowest = min((v for v in values if math.isfinite(v)), default=centre)
    region = np.array([x for x, v in zip(every, values, strict=True)
                       if math.isfinite(v) and v <= lowest + limit]).reshape(-1, free.size)
    found: list[tuple[float, np.ndarray]] = []
    for n, line in enumerate(points):  # every line has the same points
        chi2 = np.array(rest[n * len(line):(n + 1) * len(line)])
        found += [(float(chi2[i]), line[i]) for i in line_minima(chi2)
                  if chi2[i] <= centre + limit + SLACK]
    found.sort(key=lambda f: f[0])
    starts = np.array([x for _, x in found[:FITS]]).reshape(-1, free.size)
    fits: list[Start] = []
    if len(starts):
        _, fits = multi_start(predictor, weights, starts, max_evaluations, stop_early=False,
                              workers=workers, settle=True, give_up=True)
    return _with_rivals(best, best_chi2, covariance, others, Basins(
        best, best_chi2, (), limit, tuple(fits), line_runs, region))


def _other_centres(best: np.ndarray, best_chi2: float, covariance: np.ndarray,
                   others: tuple[Start, ...], within: float) -> list[np.ndarray]:
    """The OTHER_CENTRES lowest minima of ``others`` within ``within`` of the best's chi² in
    another basin (over half a standard deviation away in some parameter): a lower basin a
    basin or two from one of them can lie beyond the best's lines."""
    std = np.sqrt(np.clip(np.diag(covariance), 0.0, None))
    near = sorted((s for s in others if not s.failed and math.isfinite(s.chi2)
                   and s.chi2 <= best_chi2 + within
                   and np.any(np.abs(np.asarray(s.end) - best) > 0.5 * std)),
                  key=lambda s: s.chi2)
    return [np.asarray(s.end, dtype=float) for s in near[:OTHER_CENTRES]]


def _with_rivals(best: np.ndarray, best_chi2: float, covariance: np.ndarray,
                 others: tuple[Start, ...], found: Basins) -> Basins:
    """``found`` with its best the lowest minimum among ``best``, its fits and ``others``,
    and the others within its threshold, each basin once, as its rivals."""
    std = np.sqrt(np.clip(np.diag(covariance), 0.0, None))
    candidates = [(best_chi2, np.asarray(best, dtype=float))]
    candidates += [(s.chi2, np.asarray(s.end, dtype=float)) for s in found.fits + others
                   if not s.failed and math.isfinite(s.chi2)]
    candidates.sort(key=lambda c: c[0])
    new_chi2, new_best = candidates[0]
    rivals: list[Start] = []
    kept: list[np.ndarray] = [new_best]
    for chi2_value, x in candidates[1:]:
        if chi2_value > new_chi2 + found.threshold or any(
                np.all(np.abs(x - other) <= 0.5 * std) for other in kept):
            continue  # beyond the threshold, or the same basin as one already counted
        kept.append(x)
        rivals.append(Start(tuple(new_best), tuple(x), chi2_value, 0, "rival basin"))
    return dataclasses.replace(found, best=new_best, best_chi2=new_chi2, rivals=tuple(rivals))


def _line_points(best: np.ndarray, covariance: np.ndarray, lower: np.ndarray,
                 upper: np.ndarray) -> list[list[np.ndarray]]:
    """The lines' points along ``covariance``'s principal axes, clipped to the bounds, centre
    left out; none where the covariance is not finite."""
    if not np.all(np.isfinite(covariance)):
        return []
    eigenvalues, vectors = np.linalg.eigh(covariance)
    side = np.concatenate([np.arange(STEP_SIGMAS, REACH_SIGMAS + 1e-9, STEP_SIGMAS),
                           [s for s in FAR_SIGMAS if s > REACH_SIGMAS]])
    steps = np.concatenate([-side[::-1], side])
    axes = [math.sqrt(value) * vector
            for value, vector in zip(eigenvalues, vectors.T, strict=True) if value > 0]
    return [[np.clip(best + s * axis, lower, upper) for s in steps] for axis in axes]


def widened(spread: Uncertainty, basins: Basins, names: tuple[str, ...],
            check: ValleyCheck | None = None
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """The 95 % intervals widened to hold each rival's basin (its minimum ± sqrt(threshold -
    its rise) of the best's standard deviations) and every line point within the threshold;
    which parameters stay determined (no rival outside the best's interval); a warning for
    each interval a rival widens, or a line point by over WARN_WIDENING. With ``check`` (the
    valley check), see :func:`_unexcluded` and :func:`_carried`."""
    low, high = spread.low95.copy(), spread.high95.copy()
    determined = spread.determined.copy()
    warnings: list[str] = []
    std = np.where(np.isfinite(spread.std), spread.std, 0.0)
    ends = np.array([r.end for r in basins.rivals]).reshape(-1, len(names))
    region = basins.region.reshape(-1, len(names))
    rival_outside = (ends < spread.low95) | (ends > spread.high95)
    region_outside = (region < spread.low95) | (region > spread.high95)
    if len(ends):
        rise = np.array([r.chi2 - basins.best_chi2 for r in basins.rivals])
        half = np.sqrt(np.clip(basins.threshold - rise, 0.0, None))[:, None] * std[None, :]
        low = np.minimum(low, np.min(ends - half, axis=0))
        high = np.maximum(high, np.max(ends + half, axis=0))
    if len(region):
        low = np.minimum(low, np.min(region, axis=0))
        high = np.maximum(high, np.max(region, axis=0))
    best = basins.best
    inside = f"inside its {CONFIDENCE:.0%} profile-likelihood interval"
    for k, name in enumerate(names):
        if rival_outside[:, k].any():
            determined[k] = False
            rows = np.flatnonzero(rival_outside[:, k])
            far = float(np.max(np.abs(ends[rows, k] - best[k])))
            partners = sorted({names[j] for j in range(len(names)) if j != k
                               and rival_outside[rows, j].any()})
            with_ = (f"; they differ in {', '.join(partners)} too, which cannot be told "
                     "apart from it" if partners else "")
            warnings.append(
                f"{name} is not determined by the data: {len(rows)} other minimum(s) of the "
                f"cost lie within chi² + {basins.threshold:.3g} of the best ({inside}), up "
                f"to {far:.4g} from the estimate{with_}; its interval spans them")
        elif region_outside[:, k].any():
            far = float(np.max(np.abs(region[region_outside[:, k], k] - best[k])))
            if far <= WARN_WIDENING * (spread.high95[k] - spread.low95[k]) / 2:
                continue
            warnings.append(
                f"{name}: the cost is not the quadratic its covariance describes (impacts make "
                f"it rugged); points within chi² + "
                f"{basins.threshold:.3g} of the best ({inside}) lie up to {far:.4g} from the "
                f"estimate, {far / std[k] if std[k] > 0 else math.inf:.3g} of its standard "
                "deviations: its interval is widened to hold them")
    if check is not None:
        _unexcluded(check, names, basins.threshold, (low, high, determined, warnings),
                    spread.low95, spread.high95)
        _carried(check, names, spread, (low, high, determined, warnings))
    return low, high, determined, warnings


def _carried(check: ValleyCheck, names: tuple[str, ...], spread: Uncertainty,
             verdict: tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]) -> None:
    """``verdict`` changed in place for the parameters the valley check's lines do not move
    (the friction): in each rival valley, and along the line the clearances' intervals now
    span, they take other values, carried by their correlation with the clearances. That
    shift (regressed on the moved parameters) ± 1.96 standard deviations widens their
    intervals; the verdict follows the widened ones."""
    low, high, determined, warnings = verdict
    moved = check.spacing > 0
    covariance = spread.seen_covariance if spread.seen_covariance is not None \
        else spread.covariance
    if not (check.rivals or check.coarse) or check.centre is None or not moved.any() \
            or moved.all() or not np.all(np.isfinite(covariance)):
        return
    points = np.array([p for p, _ in check.rivals]).reshape(-1, len(names))
    outside = ((points < spread.low95) | (points > spread.high95))[:, moved].any(axis=1)
    if not (outside.any() or check.coarse):
        return
    fixed = ~moved
    regression = covariance[np.ix_(fixed, moved)] @ np.linalg.pinv(
        covariance[np.ix_(moved, moved)])
    # The rivals, and (as the clearances' intervals span the check's whole line, which can
    # pass beside a valley's floor) the corners of the line's extent in the moved parameters.
    reached = [points[outside][:, moved]]
    if check.extent is not None:
        bounds = [(check.extent[0][k], check.extent[1][k]) for k in np.flatnonzero(moved)]
        reached.append(np.array(list(itertools.product(*bounds))))
    shifted = check.centre[fixed] + (np.vstack(reached) - check.centre[moved]) @ regression.T
    half = Z95 * np.sqrt(np.clip(np.diag(covariance)[fixed], 0.0, None))
    partners = ", ".join(names[j] for j in np.flatnonzero(moved))
    for n, k in enumerate(np.flatnonzero(fixed)):
        new_low = min(low[k], float(shifted[:, n].min() - half[n]))
        new_high = max(high[k], float(shifted[:, n].max() + half[n]))
        if max(low[k] - new_low, new_high - high[k]) <= 1e-9 * (high[k] - low[k]):
            continue  # uncorrelated: carried by round-off only
        low[k], high[k] = new_low, new_high
        value = (spread.low95[k] + spread.high95[k]) / 2
        scale = abs(value) if value != 0 else 1.0
        if (high[k] - low[k]) / 2 > Z95 * MAX_RELATIVE_STD * scale:
            determined[k] = False
        warnings.append(
            f"{names[k]}: its interval is widened to {low[k]:.6g} to {high[k]:.6g} to hold "
            f"its values in the other valleys the valley check found or could not exclude "
            f"along {partners} (carried by its correlation with them)")


def _unexcluded(check: ValleyCheck, names: tuple[str, ...],
                limit: float, verdict: tuple[np.ndarray, np.ndarray, np.ndarray, list[str]],
                low95: np.ndarray, high95: np.ndarray) -> None:
    """``verdict`` (low, high, determined, warnings) changed in place for the valley check's
    rivals outside the intervals ``low95`` to ``high95``, and for a coarse check: such a
    parameter's interval spans the check's extent (its lines resolve only the valleys they
    cross near their floors)."""
    low, high, determined, warnings = verdict
    spacing = check.spacing
    moved = spacing > 0
    points = np.array([p for p, _ in check.rivals]).reshape(-1, len(names))
    rise = np.array([r for _, r in check.rivals])
    outside = ((points < low95) | (points > high95)) & moved
    for k, name in enumerate(names):
        rows = np.flatnonzero(outside[:, k])
        coarse = check.coarse and moved[k] and check.extent is not None
        if not (rows.size or coarse):
            continue
        determined[k] = False
        if rows.size:
            low[k] = min(low[k], float(np.min(points[rows, k])) - spacing[k])
            high[k] = max(high[k], float(np.max(points[rows, k])) + spacing[k])
        if check.extent is not None:
            low[k] = min(low[k], float(check.extent[0][k]))
            high[k] = max(high[k], float(check.extent[1][k]))
        if coarse:
            warnings.append(
                f"{name} is not determined by the search: over the first {check.window_end:g} "
                f"s the fit's own valley spans fewer than {RESOLVED_POINTS} points of the "
                f"valley check's line ({spacing[k]:.3g} apart), and valleys as narrow could lie "
                f"unseen between them: its interval spans a grid spacing either side, "
                f"{low[k]:.6g} to {high[k]:.6g}")
            continue
        partners = sorted(names[j] for j in np.flatnonzero(moved) if j != k)
        along = f" along {name} and {', '.join(partners)}" if partners else ""
        nearest = rows[np.argmin(rise[rows])]
        far = float(np.max(np.abs(points[rows, k] - (low95[k] + high95[k]) / 2)))
        warnings.append(
            f"{name} is not determined by the search: over the first {check.window_end:g} "
            f"s {rows.size} other valley(s) of the cost{along} lie within chi² + {limit:.3g} "
            f"of the fit's own (the lowest {rise[nearest]:+.3g}), up to {far:.4g} from the "
            "estimate; over the whole record those valleys are too narrow for the search to "
            "tell which holds the lowest minimum: its interval spans the check's line, "
            f"{low[k]:.6g} to {high[k]:.6g} (the other parameters' estimates are those of "
            "the fit's valley)")
