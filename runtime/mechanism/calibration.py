"""``jointplay.calibrate`` on a mechanism: its parameters estimated from measured outputs.

The same weighted least squares as the serial arms' (:mod:`jointplay.calibration.fit`),
the same uncertainty, residual check, result and report; what differs is the search
(:mod:`jointplay.mechanism.calibration_search`: a multi-start over the first impacts,
continued over growing windows to the whole record), where the arms run a grid of the
clearances, valley lines and basin and valley checks tuned to their records.

What the verdicts rest on: the other starts' (or tracks') minima and the cost profiles'
points (one run per point along each parameter, the others held) are minima and points of
the same cost; any of them within chi² + 3.84 of the best lies inside the 95 %
profile-likelihood interval and widens it, and a parameter in which another minimum lies
there, outside the best's own interval, is not determined
(:func:`jointplay.calibration.basins.widened`). A fit whose residuals are not the noise
determines nothing, as for the arms.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from jointplay.calibration.api import CalibrationOptions, judged_fit, result_of
from jointplay.calibration.basins import Basins, widened
from jointplay.calibration.basins import threshold as basin_threshold
from jointplay.calibration.fit import Optimum, Start, moved_to, multi_start, timed
from jointplay.calibration.measured import Measured, checked_for_scene, noise_levels
from jointplay.calibration.noise import column_noise
from jointplay.calibration.parameters import FreeParameters
from jointplay.calibration.profiles import cost_profiles
from jointplay.calibration.result import CalibrationResult
from jointplay.calibration.uncertainty import Uncertainty, uncertainty
from jointplay.common.errors import DescriptionError
from jointplay.mechanism.calibration_inputs import (
    ACCELERATION,
    ENERGIES,
    RATE,
    mechanism_free_parameters,
    on_output_grid,
    read_mechanism_measured,
)
from jointplay.mechanism.calibration_search import (
    MODEL_ERROR_LIMIT,
    MechanismPredictor,
    search,
    search_text,
)
from jointplay.mechanism.calibration_search import model_error as fit_model_error
from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.model import MechanismModel, model_for

ARMS_ONLY = ("horizon_first", "grid_window", "grid_points",
             "grid_candidates", "window_looser", "valley_window", "valley_points",
             "valley_keep", "grid_line_points", "valley_check_points", "basins")
"""Options of the arms' global stage and checks, which a mechanism's search does not run."""
LOWER_ELSEWHERE = 1.0
"""A profile's point this much below the best chi² is another, lower basin: a local fit
starts there."""


@dataclass(frozen=True)
class MechanismProblem:
    """A checked calibration problem of a mechanism: everything validated, nothing run."""

    scene: MechanismScene
    model: MechanismModel
    measured: Measured
    free: FreeParameters
    sigma: np.ndarray
    options: CalibrationOptions
    noise_spread: np.ndarray | None = None


def prepare_mechanism(scene: MechanismScene, measured: str | Path | Measured,
                      free: Sequence[str], *, noise: float | Mapping[str, float] | None = None,
                      start: Mapping[str, float] | None = None,
                      options: CalibrationOptions | None = None,
                      model: MechanismModel | None = None) -> MechanismProblem:
    """Check every input (raises :class:`DescriptionError` naming the file or the name)."""
    options = options or CalibrationOptions()
    _check_options(options)
    model = model or model_for(scene.mechanism)
    names = [free] if isinstance(free, str) else list(free)
    parameters = mechanism_free_parameters(names, scene, model, start)
    data = (measured if isinstance(measured, Measured)
            else read_mechanism_measured(measured, model))
    if isinstance(measured, Measured):
        _check_columns(data, model)
    data = on_output_grid(checked_for_scene(data, scene, parameters.size), scene)  # type: ignore[arg-type]
    sigma = noise_levels(noise, data)
    spread = None
    if sigma is None:
        sigma, spread = column_noise(data)
    return MechanismProblem(_fit_scene(scene, data, options), model, data, parameters, sigma,
                            options, spread)


def calibrate_mechanism(scene: MechanismScene, measured: str | Path | Measured,
                        free: Sequence[str], *,
                        noise: float | Mapping[str, float] | None = None,
                        start: Mapping[str, float] | None = None,
                        options: CalibrationOptions | None = None,
                        model: MechanismModel | None = None) -> CalibrationResult:
    """Estimate the ``free`` parameters of a mechanism from ``measured`` outputs (see the
    module docstring and :func:`jointplay.calibrate`)."""
    return run_mechanism(prepare_mechanism(scene, measured, free, noise=noise, start=start,
                                           options=options, model=model))


def _check_options(options: CalibrationOptions) -> None:
    default = CalibrationOptions()
    for name in ARMS_ONLY:
        if getattr(options, name) != getattr(default, name):
            raise DescriptionError(f"options.{name}", "belongs to the serial arms' global "
                                   "stage and checks; a mechanism is fitted by a multi-start "
                                   "and a continuation (options.starts, options.spread, "
                                   "options.horizon_growth): leave it at its default")


def _check_columns(measured: Measured, model: MechanismModel) -> None:
    from jointplay.mechanism.calibration_inputs import output_columns

    allowed = output_columns(model)
    for column in measured.columns:
        if column not in allowed:
            raise DescriptionError(column, "is not an output of this mechanism; allowed: "
                                   + ", ".join(allowed), measured.source)


def _fit_scene(scene: MechanismScene, measured: Measured, options: CalibrationOptions
               ) -> MechanismScene:
    """The scene the fit runs: tolerances tightened, the run ending at the last measured
    sample."""
    run = scene.run
    steps = max(1, round(measured.t[-1] / run.output_step))
    rtol, atol = options.tightened(run.rtol, run.atol)
    return scene.with_run(t_end=min(run.t_end, steps * run.output_step), rtol=rtol, atol=atol)




def run_mechanism(problem: MechanismProblem) -> CalibrationResult:
    """Fit a prepared problem (see the module docstring)."""
    from jointplay.common.pool import on_cluster

    with on_cluster(problem.options.scheduler):
        return _run(problem)


def _run(problem: MechanismProblem) -> CalibrationResult:
    wall0, cpu0 = timed()
    opts, free = problem.options, problem.free
    predictor = MechanismPredictor(problem.scene, problem.model, free, problem.measured)
    optimum, windows = search(problem, predictor)
    spread = uncertainty(optimum.jacobian, optimum.values, free.lower, free.upper, free.names)
    profiles, profile_runs, lower = _profiles(predictor, optimum, spread, opts)
    if lower is not None:  # a profile crossed a lower basin: fit from there, once
        _, more = multi_start(predictor, problem.sigma, lower[None, :],  # type: ignore[arg-type]
                              opts.max_evaluations, stop_early=False, settle=True)
        optimum = dataclasses.replace(optimum, starts=optimum.starts + tuple(more))
        if not more[0].failed and more[0].chi2 < _chi2(optimum):
            optimum = moved_to(predictor, optimum, np.array(more[0].end))  # type: ignore[arg-type]
            spread = uncertainty(optimum.jacobian, optimum.values, free.lower, free.upper,
                                 free.names)
            profiles, runs, _ = _profiles(predictor, optimum, spread, opts)
            profile_runs += runs
    found = _basins(optimum, spread, profiles)
    low, high, determined, rival_warnings = widened(spread, found, free.names)
    spread = dataclasses.replace(spread, low95=low, high95=high, determined=determined,
                                 warnings=spread.warnings + tuple(rival_warnings))
    fitted = predictor.outputs(optimum.values)
    model_error = fit_model_error(predictor, optimum)
    distrust = None
    if not model_error <= MODEL_ERROR_LIMIT:
        distrust = (f"runs at tolerances 10 times looser than the fit's differ from its own "
                    f"by chi² {model_error:.3g} at the estimate (more than "
                    f"{MODEL_ERROR_LIMIT:g}): over this record the runs are not known to "
                    "follow the motion within the noise")
    stats, misfit, spread, warnings = judged_fit(
        fitted, problem.measured, free, optimum, spread, problem.noise_spread, opts.spread,
        distrust, "Fit a shorter record, over which runs 10 times looser agree",
        reached=optimum.values)
    stats["model_error_chi2"] = model_error if math.isfinite(model_error) else None
    wall1, cpu1 = timed()
    units = dict(zip(problem.model.coordinates, problem.model.units, strict=True))
    settings = {**{k: v for k, v in dataclasses.asdict(opts).items() if k not in ARMS_ONLY},
                "search": search_text(opts, windows),
                "units": {c: _unit(c, units) for c in problem.measured.columns}}
    return result_of(problem, optimum, spread, (fitted, stats, warnings, misfit is None),
                     profiles, {"fits": predictor.counter.simulations,
                                "cost profiles": profile_runs},
                     (wall1 - wall0, cpu1 - cpu0),
                     {name: "central differences" for name in free.names}, settings)




def _chi2(optimum: Optimum) -> float:
    return float(np.sum(optimum.residuals**2))


def _profiles(predictor: MechanismPredictor, optimum: Optimum, spread: Uncertainty,
              opts: CalibrationOptions
              ) -> tuple[dict[str, dict[str, list[float]]], int, np.ndarray | None]:
    """The cost profiles (:func:`jointplay.calibration.profiles.cost_profiles`), the runs,
    and the lowest point found where it lies LOWER_ELSEWHERE below the best (else None)."""
    profiles, runs = cost_profiles(predictor, optimum, spread,  # type: ignore[arg-type]
                                   opts.profile_points, opts.workers)
    found = [(chi2, k, value) for k, name in enumerate(predictor.free.names) if name in profiles
             for value, chi2 in zip(profiles[name]["value"], profiles[name]["chi2"], strict=True)
             if math.isfinite(chi2)]
    lowest, k, value = min(found, default=(math.inf, 0, 0.0))
    if not lowest < _chi2(optimum) - LOWER_ELSEWHERE:
        return profiles, runs, None
    lower = np.array(optimum.values, dtype=float)
    lower[k] = value
    return profiles, runs, lower


def _basins(optimum: Optimum, spread: Uncertainty,
            profiles: dict[str, dict[str, list[float]]]) -> Basins:
    """What the search saw of the cost beside the best fit: the other starts' minima within
    the threshold (each basin once: more than half a standard deviation from those counted)
    and the profiles' points within it."""
    limit = basin_threshold()
    best, best_chi2 = optimum.values, _chi2(optimum)
    std = np.sqrt(np.clip(np.diag(spread.covariance), 0.0, None))
    std = np.where(np.isfinite(std), std, 0.0)
    kept, rivals = [best], []
    for s in sorted(optimum.starts, key=lambda s: s.chi2):
        x = np.asarray(s.end, dtype=float)
        if s.failed or not s.chi2 <= best_chi2 + limit:
            continue
        if any(np.all(np.abs(x - other) <= 0.5 * std) for other in kept):
            continue
        kept.append(x)
        rivals.append(Start(tuple(best), tuple(x), s.chi2, 0, "another start's minimum"))
    region = []
    names = list(profiles)
    for k, name in enumerate(names):
        for value, chi2 in zip(profiles[name]["value"], profiles[name]["chi2"], strict=True):
            if math.isfinite(chi2) and chi2 <= best_chi2 + limit:
                region.append(np.where(np.arange(len(names)) == k, value, best))
    return Basins(best, best_chi2, tuple(rivals), limit, (), 0,
                  np.array(region).reshape(-1, best.size))


def _unit(column: str, units: dict[str, str]) -> str:
    base = column.removeprefix(ACCELERATION).removeprefix(RATE)
    if base in units:
        unit = units[base]
        return (f"{unit}/s²" if column.startswith(ACCELERATION)
                else f"{unit}/s" if column.startswith(RATE) else unit)
    if column == "driving_torque":
        return "N m"
    if column in ENERGIES:
        return "J"
    return "N" if column.endswith("normal_force") else "m"
