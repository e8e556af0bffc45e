"""Quantities derived from a result's arrays for figures and comparisons: the eccentricity
ratio, the lubricant film's force, the end of the release transient, the dense orbit."""

from __future__ import annotations

import math

import numpy as np

from jointplay.results.records import SimulationResult

# Dense orbits: at least this many points per output interval, and per integrator step; at
# most MAX_DENSE_POINTS in all (a figure cannot show more); PHASE_POINTS across each contact
# phase.
DENSE_PER_SAMPLE = 10
DENSE_PER_STEP = 4
MAX_DENSE_POINTS = 400_001
PHASE_POINTS = 32


def is_lubricated(result: SimulationResult) -> bool:
    """Whether the run's model has a lubricant film (its parameters carry a viscosity)."""
    return "lubrication.viscosity" in result.parameter_names


def parameter(result: SimulationResult, name: str) -> float | None:
    """A parameter of the run by name, or None if the model has none of that name."""
    if name not in result.parameter_names:
        return None
    return float(result.parameters[result.parameter_names.index(name)])


def eccentricity_ratio(result: SimulationResult) -> np.ndarray:
    """epsilon = |e| / c per sample and clearance joint, (N, nc): 1 where dry contact begins."""
    return np.hypot(result.eccentricity[..., 0], result.eccentricity[..., 1]) \
        / result.radial_clearance


def _line_of_centres(eccentricity: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unit normal n = e/|e| and tangent t = z x n, (..., 2) each; n = (1, 0) at e = 0."""
    size = np.hypot(eccentricity[..., 0], eccentricity[..., 1])
    safe = np.where(size > 0.0, size, 1.0)
    nx = np.where(size > 0.0, eccentricity[..., 0] / safe, 1.0)
    ny = np.where(size > 0.0, eccentricity[..., 1] / safe, 0.0)
    return np.stack([nx, ny], axis=-1), np.stack([-ny, nx], axis=-1)


def film_force(result: SimulationResult) -> np.ndarray:
    """The lubricant film's force on each journal, (N, nc, 2) N, x and y.

    The contact force on the journal is the dry law's -F_n n + F_t t plus the film's; the
    film's part is what remains of ``contact_force`` after the dry part (zero to round-off
    without a lubricant).
    """
    n, t = _line_of_centres(result.eccentricity)
    dry = -result.normal_force[..., None] * n + result.friction_force[..., None] * t
    return result.contact_force - dry


def film_components(result: SimulationResult) -> tuple[np.ndarray, np.ndarray]:
    """The film force along the line of centres, positive towards the bearing centre (the
    load it carries), and across it (along t), (N, nc) N each."""
    n, t = _line_of_centres(result.eccentricity)
    film = film_force(result)
    return -(film * n).sum(axis=-1), (film * t).sum(axis=-1)


def release_transient_end(result: SimulationResult) -> tuple[float, str] | None:
    """When the release transient is over, and by which rule; None when nothing swamps the
    rest of the run.

    With impacts: the end of the first impact burst of every joint (see
    :func:`jointplay.results.plots.first_burst`). Without (a lubricated joint takes up the
    load without a dry impact): just after the last sample of the first half of the run whose
    end-effector acceleration leaves the range the second half keeps (its 0.5-99.5 %
    percentiles, widened by half their span). Either must end within the first half.
    """
    from jointplay.results.plots import first_burst

    if result.n_samples < 4:
        return None
    t0, span = float(result.t[0]), float(result.t[-1] - result.t[0])
    ends = [first_burst(result.impacts.for_joint(j), t0)[1] for j in result.clearance_joints]
    ends = [e for e in ends if np.isfinite(e)]
    if ends:
        end = max(ends)
        return (end, "end of the first impact burst") if end <= t0 + 0.5 * span else None
    acceleration = result.tip_acceleration
    later = result.t >= t0 + 0.5 * span
    lo, hi = np.percentile(acceleration[later], [0.5, 99.5], axis=0)
    lo, hi = lo - 0.5 * (hi - lo), hi + 0.5 * (hi - lo)
    outside = np.any((acceleration < lo) | (acceleration > hi), axis=1) & ~later
    if not outside.any():
        return None
    end = float(result.t[min(int(np.flatnonzero(outside)[-1]) + 1, result.n_samples - 1)])
    return (end, "acceleration back in its later range") \
        if end <= t0 + 0.5 * span else None


def dense_times(result: SimulationResult) -> np.ndarray:
    """A time grid finer than both the output samples and the integrator's steps, with
    PHASE_POINTS more across every contact phase (onset to separation: microseconds that a
    uniform grid would step over)."""
    intervals = max(result.n_samples - 1, 1)
    steps = int(result.stats.get("steps", 0) or 0)
    # Whole subdivisions of every output interval: a method restarted from the samples
    # (cvodes, idas) then reads an interval's points in one call.
    per = max(DENSE_PER_SAMPLE, math.ceil(DENSE_PER_STEP * steps / intervals))
    per = max(1, min(per, (MAX_DENSE_POINTS - 1) // intervals))
    t0, t1 = float(result.t[0]), float(result.t[-1])
    grids = [np.linspace(t0, t1, intervals * per + 1)]
    impacts = result.impacts
    ends = np.where(np.isfinite(impacts.separation_time), impacts.separation_time,
                    impacts.time)
    for start, end in zip(impacts.time, ends, strict=True):
        if np.isfinite(start) and end > start:
            grids.append(np.linspace(start, min(end, t1), PHASE_POINTS))
    return np.unique(np.clip(np.concatenate(grids), t0, t1))


def dense_eccentricity(result: SimulationResult) -> tuple[np.ndarray, np.ndarray, str]:
    """Times, eccentricities (M, nc, 2) m on :func:`dense_times`, from ``result.sol``, and a
    few words on where they come from."""
    times = dense_times(result)
    sol = result.sol
    x = sol(times)
    columns = result.eccentricity_columns
    ecc = np.stack([x[list(columns[j]), :].T for j in result.clearance_joints], axis=1) \
        if result.clearance_joints else np.zeros((times.size, 0, 2))
    source = (f"dense output of the {sol.method} run" if sol.method != "hermite"
              else "cubic Hermite between samples")
    return times, ecc, source
