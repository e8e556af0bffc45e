"""``jointplay.calibrate``: a scene's physical parameters estimated from measured motion."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from jointplay.calibration.basins import neighbouring_basins, widened
from jointplay.calibration.basins import threshold as basin_threshold
from jointplay.calibration.continuation import TRACK_MARGIN, Stage, ValleyScan, continuation
from jointplay.calibration.fit import (
    Optimum,
    Scan,
    least_squares_fit,
    moved_to,
    residual_statistics,
    search_box,
    starts_around,
    timed,
)
from jointplay.calibration.grid import Grid, GridResult, grid_candidates, grid_scale, others_first
from jointplay.calibration.measured import Measured, checked_for_scene, noise_levels, read_measured
from jointplay.calibration.noise import column_noise, residual_check

# The options live in their own module; the name stays importable from here.
from jointplay.calibration.options import CalibrationOptions as CalibrationOptions
from jointplay.calibration.parameters import FreeParameters, free_parameters
from jointplay.calibration.predict import Predictor, chi2_at_points
from jointplay.calibration.result import CalibrationResult, Estimate
from jointplay.calibration.uncertainty import Uncertainty, uncertainty
from jointplay.calibration.valleys import valley_check
from jointplay.common.pool import on_cluster
from jointplay.scene.definition import Scene

if TYPE_CHECKING:
    from jointplay.mechanism.description import MechanismScene

VALLEY_CHECK_REACH = 0.2
"""How far the valley check's line reaches either side of the best fit, in grid spacings."""

VALLEY_CHECK_LOOSER = 3.0
"""The valley check's runs use the fit's tolerances times this (at the windows' 100 their chi²
are off by about the threshold it compares them with, 3.84)."""

GRID_LINE_REACH = 1.5
"""How far the grid window's line reaches either side of the best grid point, in grid spacings
(the true valley lies within half a spacing of a grid point, perhaps the best one's neighbour)."""


@dataclass(frozen=True)
class Problem:
    """A checked calibration problem: everything validated, nothing run."""

    scene: Scene
    model: Any
    measured: Measured
    free: FreeParameters
    sigma: np.ndarray
    options: CalibrationOptions
    noise_spread: np.ndarray | None = None
    """The relative variance of each column's estimated noise variance (None: stated)."""


def prepare(scene: Scene | MechanismScene, measured: str | Path | Measured,
            free: Sequence[str], *,
            noise: float | Mapping[str, float] | None = None,
            start: Mapping[str, float] | None = None,
            options: CalibrationOptions | None = None, model: Any = None) -> Problem:
    """Check every input (raises :class:`DescriptionError` naming the file or the name)."""
    from jointplay.sim import load_scene_model

    if _is_mechanism(scene):
        from jointplay.mechanism.calibration import prepare_mechanism

        return prepare_mechanism(scene, measured, free, noise=noise,  # type: ignore[arg-type, return-value]
                                 start=start, options=options, model=model)
    scene = cast(Scene, scene)
    options = options or CalibrationOptions()
    model = model or load_scene_model(scene)
    names = [free] if isinstance(free, str) else list(free)
    parameters = free_parameters(names, scene, model, start)
    data = measured if isinstance(measured, Measured) else read_measured(measured, model)
    data = checked_for_scene(data, scene, parameters.size)
    sigma = noise_levels(noise, data)
    spread = None
    if sigma is None:
        sigma, spread = column_noise(data)
    return Problem(_fit_scene(scene, data, options), model, data, parameters, sigma, options,
                   spread)


def calibrate(scene: Scene | MechanismScene, measured: str | Path | Measured,
              free: Sequence[str], *,
              noise: float | Mapping[str, float] | None = None,
              start: Mapping[str, float] | None = None,
              options: CalibrationOptions | None = None, model: Any = None
              ) -> CalibrationResult:
    """Estimate the ``free`` parameters of ``scene``'s robot from ``measured`` motion.

    A weighted least-squares fit of simulated to measured samples (the Jacobian from the
    compiled sensitivities), then the estimates' 95 % intervals and correlations, the cost
    profiles, and whether the fit explains the data within the noise.

    Parameters
    ----------
    scene : Scene or MechanismScene
        The scene that was measured; a mechanism scene is calibrated on its outputs
        (:mod:`jointplay.mechanism.calibration`).
    measured : str, pathlib.Path or Measured
        A CSV path (``time``, and any of ``tip_x``, ``tip_y``, ``q2``, ...), a results file
        (.h5) or a :class:`~jointplay.calibration.Measured`.
    free : sequence of str
        The parameters to estimate, by the names ``--set`` takes, plus ``jointN.clearance``.
    noise : float or mapping of str to float, optional
        The sensors' standard deviations (one number, or one per column); without it each
        column's noise is estimated from the data's sample-to-sample scatter.
    start : mapping of str to float, optional
        Start values (default: the scene's).
    options : CalibrationOptions, optional
        How the fit runs (default: ``CalibrationOptions()``).
    model : Model, optional
        The compiled model of the scene's robot (default: loaded for it).

    Returns
    -------
    CalibrationResult
        The estimates with their intervals, the residuals and the verdicts;
        ``result.to_dict()`` is ``calibration.json``.

    Raises
    ------
    DescriptionError
        For bad input (a column, a parameter name, an option), naming it and the fix.
    SimulationError
        When the runs stop at every start.

    Examples
    --------
    A payload recovered from 0.1 s of tip positions with 1 µm of noise (the ideal-joint arm:
    a smooth cost, one start):

    >>> import numpy as np
    >>> import jointplay
    >>> from jointplay.calibration import Measured
    >>> scene = jointplay.default_scene()
    >>> scene = scene.with_robot(jointplay.ideal_counterpart(scene.robot)).with_run(t_end=0.1)
    >>> truth = jointplay.simulate(scene, parameters={"payload.mass": 2.3})
    >>> noise = 1e-6 * np.random.default_rng(0).standard_normal(truth.tip_position.shape)
    >>> measured = Measured("synthetic", truth.t, ("tip_x", "tip_y"), truth.tip_position + noise)
    >>> options = jointplay.CalibrationOptions(tighten=1.0, starts=1, scan_points=0,
    ...                                        profile_points=0, horizon_first=0, basins=False)
    >>> result = jointplay.calibrate(scene, measured, ["payload.mass"], noise=1e-6,
    ...                              options=options)
    >>> estimate = result.estimates["payload.mass"]
    >>> round(estimate.value, 2), estimate.determined, result.fit_explains_data
    (2.3, True, True)
    """
    return run(prepare(scene, measured, free, noise=noise, start=start, options=options,
                       model=model))


def _is_mechanism(scene: Any) -> bool:
    from jointplay.mechanism.description import MechanismScene

    return isinstance(scene, MechanismScene)


def run(problem: Problem) -> CalibrationResult:
    """Fit a prepared problem and state its uncertainty (on ``options.scheduler``, if given)."""
    if _is_mechanism(problem.scene):
        from jointplay.mechanism.calibration import run_mechanism

        return run_mechanism(problem)  # type: ignore[arg-type]
    with on_cluster(problem.options.scheduler):
        return _run(problem)


def _run(problem: Problem) -> CalibrationResult:
    from jointplay.calibration.profiles import cost_profiles

    wall0, cpu0 = timed()
    opts = problem.options
    predictor = Predictor(problem.scene, problem.model, problem.free, problem.measured)
    starts = starts_around(problem.free, opts.starts, opts.spread, opts.seed)
    scan: Scan | None = Scan(opts.scan_points, opts.spread, opts.refine)
    stages: list[Stage] = []
    stage_runs = 0
    grid = valley = None
    weights, centre = problem.sigma, starts[0]
    if opts.horizon_first > 0:
        if opts.grid_window > 0:
            centre, runs = others_first(predictor, weights, starts[0], opts.window_looser,
                                        opts.max_evaluations)
            stage_runs += runs
            grid = grid_candidates(predictor, weights, centre, Grid(
                opts.grid_window, opts.grid_points, opts.spread, opts.grid_candidates,
                opts.window_looser), opts.workers)
        tracks, first, opening = starts[:1], opts.horizon_first, None
        if grid is not None and len(grid.candidates):
            tracks, first = grid.candidates, grid.window_end
            stage_runs += grid.simulations
            scale = grid_scale(problem.free, centre, grid, opts.spread)
            if opts.valley_window > 0:
                valley = ValleyScan(opts.valley_window, opts.valley_points, 2.0,
                                    opts.valley_keep, scale)
            if opts.grid_line_points > 0:
                opening = ValleyScan(grid.window_end, opts.grid_line_points, GRID_LINE_REACH,
                                     opts.valley_keep, scale)
        survivors, stages, runs = continuation(
            predictor, weights, tracks, starts, opts.max_evaluations, first,
            opts.horizon_growth, valley, opts.window_looser, opts.workers, opening)
        stage_runs += runs
        survivors, runs = _ranked(predictor, weights, survivors, opts.workers)
        stage_runs += runs
        if len(survivors):
            # The tracks alone start the whole-record fit: a multi-start and a scan there never
            # found a lower minimum on the benchmark's cases (a cost rugged at tens of nanometres).
            starts, scan = survivors, None
        else:
            starts = np.vstack([survivors, starts[1:]])
    leading = len(starts) - (opts.starts - 1) if scan is not None else len(starts)
    optimum = least_squares_fit(predictor, problem.sigma, starts, opts.max_evaluations, scan,
                                leading=leading, workers=opts.workers, give_up=True)
    if stages:
        stages.append(_whole_stage(problem, optimum.starts[:leading]))
    drift = _drift(centre, optimum.values, valley.held_before) \
        if grid is not None and valley is not None else 0.0
    free, check, line_runs = problem.free, None, 0
    spread = uncertainty(optimum.jacobian, optimum.values, free.lower, free.upper, free.names)
    if opts.basins:
        found = neighbouring_basins(predictor, optimum.sigma, optimum.values,
                                    float(np.sum(optimum.residuals**2)), spread.covariance,
                                    opts.max_evaluations, opts.workers,
                                    others=optimum.starts, axes=spread.seen_covariance)
        line_runs = found.line_runs
        optimum = dataclasses.replace(optimum, starts=optimum.starts + found.fits)
        if not np.array_equal(found.best, optimum.values):  # a lower minimum: moved there
            optimum = moved_to(predictor, optimum, found.best)
            spread = uncertainty(optimum.jacobian, optimum.values, free.lower, free.upper,
                                 free.names)
    fitted = predictor.outputs(optimum.values)
    if opts.basins:
        # The valley check only decides which estimates stay determined: skipped where none can
        # be (the noise does not explain the residuals, or the held parameters drifted).
        if valley is not None and opts.valley_check_points > 0 and drift <= HELD_DRIFT \
                and residual_check(fitted - problem.measured.values, optimum.sigma,
                                   problem.measured.size - free.size, problem.noise_spread,
                                   problem.measured.columns) is None:
            check = valley_check(predictor, weights, optimum.values, ValleyScan(
                opts.valley_window, opts.valley_check_points, VALLEY_CHECK_REACH, 1,
                valley.scale), VALLEY_CHECK_LOOSER, opts.horizon_growth, basin_threshold(),
                opts.workers)
        low, high, determined, rival_warnings = widened(spread, found, free.names, check)
        spread = dataclasses.replace(spread, low95=low, high95=high, determined=determined,
                                     warnings=spread.warnings + tuple(rival_warnings))
    distrust = None
    if drift > HELD_DRIFT:
        names = ", ".join(n for n, h in zip(free.names, valley.held_before, strict=True) if h) \
            if valley is not None else ""
        distrust = (f"{names}, held through the first windows at its fit with the clearances "
                    f"at their start, ended {drift:.0%} from there: the windows chose the "
                    "clearances' valley under another model, and it may not be the truth's")
    stats, misfit, spread, warnings = judged_fit(fitted, problem.measured, free, optimum,
                                                 spread, problem.noise_spread, opts.spread,
                                                 distrust)
    profiles, profile_runs = cost_profiles(predictor, optimum, spread, opts.profile_points,
                                           opts.workers)
    wall1, cpu1 = timed()
    by_kind = {**predictor.counter.by_kind, "continuation windows": stage_runs,
               "valley check": check.runs if check else 0, "basin lines": line_runs,
               "cost profiles": profile_runs}
    source = {name: ("compiled sensitivities" if name in predictor.compiled
                     else "central differences") for name in free.names}
    return result_of(problem, optimum, spread, (fitted, stats, warnings, misfit is None),
                     profiles, by_kind, (wall1 - wall0, cpu1 - cpu0), source,
                     dataclasses.asdict(opts), stages=tuple(stages), grid=grid)


HELD_DRIFT = 0.05
"""The relative change of a parameter the early windows hold beyond which nothing is reported
determined: the windows chose the clearances' valley under another model (right choices moved
it by 1.2 % at most)."""


def _whole_stage(problem: Problem, fits: Sequence[Any]) -> Stage:
    """The whole record's stage: the best of ``fits`` (the local fits on it)."""
    whole = min(fits, key=lambda s: s.chi2)
    return Stage(float(problem.measured.t[-1]), int(problem.measured.t.size), whole.start,
                 whole.end, whole.chi2, max(problem.measured.size - problem.free.size, 1),
                 whole.evaluations, whole.evaluations, whole.message)


def _drift(held: np.ndarray, fitted: np.ndarray, mask: np.ndarray) -> float:
    """The largest relative change from ``held`` to ``fitted`` in ``mask`` (0 where none)."""
    scale = np.maximum(np.abs(fitted[mask]), 1e-300)
    return float(np.max(np.abs(fitted[mask] - held[mask]) / scale, initial=0.0))


WHOLE_RECORD_TRACKS = 2
"""The tracks fitted on the whole record at least (ranked by their chi² there at their last
window's estimates, two basins can come the wrong way round)."""


def _ranked(predictor: Predictor, weights: np.ndarray, tracks: np.ndarray, workers: int
            ) -> tuple[np.ndarray, int]:
    """The tracks worth a local fit on the whole record, best first, and the runs: ranked by
    their chi² there, those over TRACK_MARGIN above the best dropped but the WHOLE_RECORD_TRACKS
    best (that many or fewer are kept without a run)."""
    if len(tracks) <= WHOLE_RECORD_TRACKS:
        return tracks, 0
    values, runs = chi2_at_points(predictor, weights, list(tracks), workers)
    chi2 = np.array(values)
    if not np.isfinite(chi2).any():
        return tracks, runs
    order = np.argsort(chi2)
    keep = [i for k, i in enumerate(order)
            if k < WHOLE_RECORD_TRACKS or chi2[i] <= chi2[order[0]] + TRACK_MARGIN]
    return tracks[keep], runs


def result_of(problem: Any, optimum: Optimum, spread: Uncertainty,
              judged: tuple[np.ndarray, dict[str, Any], list[str], bool],
              profiles: dict[str, dict[str, list[float]]], runs: dict[str, int],
              seconds: tuple[float, float], jacobian_source: dict[str, str],
              settings: dict[str, Any], *, stages: tuple[Stage, ...] = (),
              grid: GridResult | None = None) -> CalibrationResult:
    """The result of an arm's or a mechanism's calibration: ``judged`` the fitted outputs,
    residual statistics, warnings and whether the fit explains the data; ``runs`` the runs
    by kind; ``settings`` those beside the run's tolerances; ``stages`` and ``grid`` what
    the arms' search adds."""
    fitted, stats, warnings, explains = judged
    run, measured = problem.scene.run, problem.measured
    return CalibrationResult(
        scene_name=problem.scene.name, measured=measured,
        estimates=estimates_at(optimum.values, problem.free, spread, explains),
        covariance=spread.covariance, correlation=spread.correlation,
        condition_number=spread.condition_number, residuals=stats,
        noise=dict(zip(measured.columns, map(float, optimum.sigma), strict=True)),
        noise_stated=problem.noise_spread is None, fitted=fitted, starts=optimum.starts,
        simulations=sum(runs.values()), simulations_by_kind=runs,
        jacobian_source=jacobian_source, wall_time_s=seconds[0], cpu_time_s=seconds[1],
        warnings=tuple(warnings),
        settings={"rtol": run.rtol, "atol": run.atol, "t_end": run.t_end,
                  "output_step": run.output_step, **settings,
                  "profile": "others fixed at their estimates"},
        fit_explains_data=explains, profiles=profiles, stages=stages, grid=grid)


def _fit_scene(scene: Scene, measured: Measured, options: CalibrationOptions) -> Scene:
    """The scene the fit runs: tolerances tightened, ending at the last sample's output step."""
    run = scene.run
    steps = max(1, math.ceil(measured.t[-1] / run.output_step - 1e-9))
    changes: dict[str, Any] = {"t_end": min(run.t_end, steps * run.output_step)}
    if run.integrator in ("bdf", "cvodes", "idas"):
        changes["rtol"], changes["atol"] = options.tightened(run.rtol, run.atol)
    return scene.with_run(**changes)


def estimates_at(values: np.ndarray, free: FreeParameters, spread: Uncertainty,
                 explains: bool) -> dict[str, Estimate]:
    """Each free parameter's estimate at ``values`` with its interval; none is determined
    where the fit does not explain the data (``explains`` false)."""
    determined = spread.determined & explains
    return {name: Estimate(name, float(values[k]), float(spread.std[k]),
                           float(spread.low95[k]), float(spread.high95[k]),
                           float(free.start[k]), bool(determined[k]))
            for k, name in enumerate(free.names)}


def judged_fit(fitted: np.ndarray, measured: Measured, free: FreeParameters,
               optimum: Optimum, spread: Uncertainty, noise_spread: np.ndarray | None,
               box_spread: float, distrust: str | None = None, advice: str | None = None,
               reached: np.ndarray | None = None
               ) -> tuple[dict[str, Any], str | None, Uncertainty, list[str]]:
    """The fit's residual statistics, why the residuals are not the noise (None: they are),
    its intervals (spanning the searched box, ``box_spread`` of the start either side, where
    they are not, or where ``distrust`` says why the search's valley cannot be trusted,
    ``advice`` what to do then; with ``reached``, the same box about that point too) and its
    warnings; for a scene's and a mechanism's fit alike."""
    stats = residual_statistics(measured, fitted, optimum.sigma, free.size)
    misfit = residual_check(fitted - measured.values, optimum.sigma, stats["dof"],
                            noise_spread, measured.columns)
    warnings = list(spread.warnings)
    reason = "; and ".join(r for r in (misfit, distrust) if r is not None) or None
    if reason is not None:
        # nothing is determined: the intervals span the box the search covered
        low, high = spread.low95, spread.high95
        for box_low, box_high in [search_box(free, box, box_spread) for box in
                                  [free.start, *([] if reached is None else [reached])]]:
            low, high = np.minimum(low, box_low), np.maximum(high, box_high)
        spread = dataclasses.replace(spread, low95=low, high95=high,
                                     determined=np.zeros(free.size, dtype=bool))
        advices = []
        if misfit is not None:
            advices.append("State the noise if you know it, or free what the model may lack")
        if distrust is not None:
            advices.append(advice or "Start from values nearer the truth (--start), or "
                           "measure a longer or slower motion")
        warnings = [f"nothing is determined: {reason}; each interval spans the box the "
                    f"search covered (±{box_spread:g} of the start"
                    f"{'' if reached is None else ' and of the estimate'}). "
                    f"{'. '.join(advices)}"]
    return stats, misfit, spread, warnings + _bound_warnings(optimum.values, free)


def _bound_warnings(values: np.ndarray, free: FreeParameters) -> list[str]:
    return [f"{name} ended on its physical bound ({values[k]:.6g}): the optimum may lie outside "
            "the range the model accepts" for k, name in enumerate(free.names)
            if values[k] <= free.lower[k] or values[k] >= free.upper[k]]
