"""``jointplay.calibrate`` on a mechanism: its parameters estimated from measured outputs.

The same weighted least squares as the serial arms' (:mod:`jointplay.calibration.fit`),
the same uncertainty, residual check, result and report; what differs is the search. The
arms' global stage (a grid of the clearances, valley lines, basin and valley checks) is tuned
to their records; here the search is a multi-start and a continuation. Each impact that moves
past a sample changes the residuals abruptly, so over many impacts the cost is a comb of
narrow valleys; over the first few it is one. A local fit runs from the start and from each
point of a seeded Latin hypercube within ±``spread`` of it over a first window that holds
:data:`FIRST_WINDOW_IMPACTS` impacts of a run at the start values (or a shorter one, where
no fit explains it: :data:`SHORTER_FIRST_WINDOWS`); the minima that explain
that window's data within the noise (the lowest, if none does) are tracks, each fitted again
over a window ``horizon_growth`` times longer, from its last estimate, up to the whole record,
where the lowest is the estimate. A record of fewer impacts is fitted whole. The Jacobian is
taken by central differences of whole runs (two per free parameter, :data:`FD_STEP`; the
mechanism's compiled sensitivities do not exist).

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
from typing import Any

import numpy as np

from jointplay.calibration.api import CalibrationOptions, estimates_at, judged_fit
from jointplay.calibration.basins import Basins, widened
from jointplay.calibration.basins import threshold as basin_threshold
from jointplay.calibration.continuation import horizon_windows, window
from jointplay.calibration.fit import (
    Optimum,
    Scan,
    Start,
    explaining_limit,
    least_squares_fit,
    multi_start,
    starts_around,
    timed,
)
from jointplay.calibration.measured import Measured, checked_for_scene, grid_indices, noise_levels
from jointplay.calibration.noise import column_noise
from jointplay.calibration.parameters import FreeParameters
from jointplay.calibration.predict import (
    Counter,
    TrialFailed,
    chi2_at_points,
    whitened,
)
from jointplay.calibration.profiles import PROFILE_SIGMAS, UNDETERMINED_SPAN
from jointplay.calibration.result import CalibrationResult
from jointplay.calibration.uncertainty import Uncertainty, uncertainty
from jointplay.common.errors import DescriptionError
from jointplay.mechanism.calibration_inputs import (
    ACCELERATION,
    ENERGIES,
    RATE,
    clearance_joint,
    mechanism_free_parameters,
    on_output_grid,
    read_mechanism_measured,
)
from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.model import MechanismModel, model_for

ARMS_ONLY = ("horizon_first", "grid_window", "grid_points",
             "grid_candidates", "window_looser", "valley_window", "valley_points",
             "valley_keep", "grid_line_points", "valley_check_points", "basins")
"""Options of the arms' global stage and checks, which a mechanism's search does not run."""
FIRST_WINDOW_IMPACTS = 6
"""The continuation's first window ends halfway between this impact of a run at the start
values and the next: on the 0.1 mm slider-crank with friction, the first millisecond, where a
multi-start finds the truth (over 4 ms the cost along mu jumps by tens of thousands between
values 0.001 apart)."""
RETRY_NUDGE = 1e-9
"""A run that stops at the fit's tolerances (1000 times the scene's) is run again with the
parameters moved by this, relative: such a stop (the step size collapsing at a grazing
contact) comes at isolated values (one at 6-digit-rounded values did not recur), and the
move is 1e-5 of the narrowest interval measured."""
SHORTER_FIRST_WINDOWS = 3
"""How many times over the first window is shortened (by ``horizon_growth``) where no
start's fit explains it: at 0.055 mm the first millisecond holds more impacts than at the
start's 0.1 mm, and on 2 of 5 noise seeds every start ended in another valley there."""
SAME_TRACK = 1e-4
"""Tracks whose ends differ by at most this, relative, in every parameter are one track: fits
from different starts that meet on one valley floor end a few 1e-5 apart (its width over a
revolution, relative, is about 2e-4)."""
FD_STEP = 1e-5
"""Central-difference step, relative to the parameter's magnitude. Over a window of many
impacts a valley of the cost is narrow (along mu on the slider-crank over 4 ms, chi² rises
by 50 within 2e-6 of its floor): a step of 1e-2 spans several valleys, and the fit stopped
in none (over 12 ms: mu 21 % off); steps of 1e-4 and 1e-6 gave the same fits to 1e-4
relative. The runs' own error (tolerances 1000 times the scene's) is far below the step."""
MODEL_ERROR_LIMIT = 1.0
"""The most that runs at tolerances 10 times looser than the fit's may differ from its own at
the estimate, as a chi² (the whitened difference's sum of squares), for any verdict to stand:
a bound on the fit's own runs' error (10 times tighter runs can stop where the fit's are
already at 1e-12). Beyond it the record may outlast the time over which the motion is known
to the noise. Measured on the slider-crank with friction over a revolution: 3e-4 to 0.18 at
six truths, and 1.2e5 at one (0.14 mm, mu 0.018; 7.4 over its first 4 ms), whose fit
reported intervals 4e-12 m wide (runs 10 times tighter than the fit's differ by 1.1e5); at
the estimates on Exudyn's data (benchmarks/mechanism_calibration.py, 5 seeds), 1.5e-4 to
1.9 at four truths and 3,400 to 18,000 at that one."""
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
    return scene.with_run(t_end=min(run.t_end, steps * run.output_step),
                          rtol=run.rtol / options.tighten, atol=run.atol / options.tighten)


class MechanismPredictor:
    """``outputs(x)`` (n_t, n_columns) and ``jacobian(x)`` (central differences) of the
    measured columns at free-parameter values ``x``; the interface of
    :class:`jointplay.calibration.predict.Predictor`, which the fit asks of it."""

    compiled: tuple[str, ...] = ()
    retreats_from_failures = True
    """A fit steps back from a trial point whose run stops (at the fit's tolerances a run
    near a grazing impact can) instead of ending there (see _local_fit)."""

    def __init__(self, scene: MechanismScene, model: MechanismModel, free: FreeParameters,
                 measured: Measured) -> None:
        self.scene = scene
        self.model = model
        self.free = free
        self.measured = measured
        self.counter = Counter()
        grid = grid_indices(measured.t, scene.run.output_step)
        assert grid is not None  # checked at the door (on_output_grid)
        self._grid = grid
        self._cache: dict[bytes, np.ndarray] = {}

    def __getstate__(self) -> dict[str, Any]:
        # For a piece sent to a Dask worker: the compiled model does not pickle
        state = dict(self.__dict__)
        state["model"], state["_cache"] = None, {}
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__dict__.update(state)
        self.model = model_for(self.scene.mechanism)

    def outputs(self, x: np.ndarray, *, with_jacobian: bool = True) -> np.ndarray:
        key = np.asarray(x, dtype=float).tobytes()
        if key not in self._cache:
            self._cache.clear()  # a fit asks for one point at a time
            self._cache[key] = self._run(np.asarray(x, dtype=float))
        return self._cache[key]

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        jac = np.zeros((*self.outputs(x).shape, self.free.size))
        for k in range(self.free.size):
            jac[:, :, k] = self._difference(x, k)
        return jac

    def _difference(self, x: np.ndarray, k: int) -> np.ndarray:
        """d outputs / d x[k]: central, or one-sided where one side's run stops; where both
        stop (a run at the fit's tolerances can, near a grazing impact), a step 10 and then
        100 times longer."""
        for scale in (1.0, 10.0, 100.0):
            h = scale * FD_STEP * (abs(x[k]) if x[k] != 0 else 1e-2)
            up, down = x.copy(), x.copy()
            up[k] = min(x[k] + h, self.free.upper[k])
            down[k] = max(x[k] - h, self.free.lower[k])
            sides = []
            for point in (up, down):
                try:
                    sides.append((point, self._run(point)))
                except TrialFailed:
                    continue
            if len(sides) == 1:
                sides.append((x, self.outputs(x)))
            if len(sides) == 2 and sides[0][0][k] != sides[1][0][k]:
                (a, y_a), (b, y_b) = sides
                return (y_a - y_b) / (a[k] - b[k])
        raise TrialFailed(f"the runs either side of {self.free.names[k]} = {x[k]:.6g} "
                          "stopped, at steps up to 100 times the usual")

    def values(self, x: np.ndarray) -> dict[str, float]:
        """The mechanism's parameters at ``x`` (a clearance as its journal's radius)."""
        out: dict[str, float] = {}
        joints = {j.name: j for j in self.scene.mechanism.joints}
        for name, value in zip(self.free.names, x, strict=True):
            joint = clearance_joint(name, self.scene)
            if joint is None:
                out[name] = float(value)
            else:
                out[f"{joint}.journal_radius"] = (joints[joint].clearance["bearing_radius"]
                                                  - float(value))
        return out

    def window(self, end: float) -> MechanismPredictor:
        """This predictor over the samples up to ``end``, its runs ending at the output step
        that holds it; their runs are counted with this one's."""
        step = self.scene.run.output_step
        t_end = min(self.scene.run.t_end, math.ceil(end / step - 1e-9) * step)
        part = MechanismPredictor(self.scene.with_run(t_end=t_end), self.model, self.free,
                                  window(self.measured, end))
        part.counter = self.counter
        return part

    def impact_times(self, x: np.ndarray) -> np.ndarray:
        """The onsets (s) of a run at ``x``."""
        return np.asarray(self._simulate(np.asarray(x, dtype=float)).impacts.time)

    def _run(self, x: np.ndarray) -> np.ndarray:
        result = self._simulate(x)
        return np.column_stack([_column(result, c)[self._grid] for c in self.measured.columns])

    def _simulate(self, x: np.ndarray) -> Any:
        """The run at ``x``; where it stops, the run at ``x`` moved by RETRY_NUDGE
        (relative) instead, and TrialFailed where that stops too."""
        from jointplay.common.errors import SimulationError
        from jointplay.mechanism.simulate import simulate_mechanism

        described = ", ".join(f"{n} = {v:.6g}" for n, v in zip(self.free.names, x,
                                                                 strict=True))
        for point in (x, x + RETRY_NUDGE * np.where(x != 0, np.abs(x), 1.0)):
            try:
                scene = self.scene.with_mechanism(
                    self.scene.mechanism.with_values(self.values(point)))
                result = simulate_mechanism(scene, model=self.model)
            except DescriptionError as err:
                raise TrialFailed(f"the run at {described} stopped: {err}") from None
            except SimulationError as err:
                self.counter.add("plain")
                stopped = err
                continue
            self.counter.add("plain")
            return result
        raise TrialFailed(f"the run at {described} stopped: {stopped}") from None


def _column(result: Any, name: str) -> np.ndarray:
    """One output of a mechanism run by its ``simulate --csv`` name."""
    if name in ENERGIES:
        return np.asarray(getattr(result, name))
    if name.startswith(ACCELERATION):
        return np.asarray(result.coordinate_acceleration(name.removeprefix(ACCELERATION)))
    if name.startswith(RATE):
        return np.asarray(result.rate(name.removeprefix(RATE)))
    if name in result.coordinates:
        return np.asarray(result.coordinate(name))
    joint, _, what = name.rpartition(".")
    j = result.cut_joints.index(joint)
    if what == "normal_force":
        return np.asarray(result.normal_force[:, j])
    return np.asarray(result.eccentricity[:, j, 0 if what == "ex" else 1])


def run_mechanism(problem: MechanismProblem) -> CalibrationResult:
    """Fit a prepared problem (see the module docstring)."""
    from jointplay.calibration.workers import on_cluster

    with on_cluster(problem.options.scheduler):
        return _run(problem)


def _run(problem: MechanismProblem) -> CalibrationResult:
    wall0, cpu0 = timed()
    opts, free = problem.options, problem.free
    predictor = MechanismPredictor(problem.scene, problem.model, free, problem.measured)
    optimum, windows = _search(problem, predictor)
    spread = uncertainty(optimum.jacobian, optimum.values, free.lower, free.upper, free.names)
    profiles, profile_runs, lower = _profiles(predictor, optimum, spread, opts)
    if lower is not None:  # a profile crossed a lower basin: fit from there, once
        _, more = multi_start(predictor, problem.sigma, lower[None, :],  # type: ignore[arg-type]
                              opts.max_evaluations, stop_early=False, settle=True)
        optimum = dataclasses.replace(optimum, starts=optimum.starts + tuple(more))
        if not more[0].failed and more[0].chi2 < _chi2(optimum):
            optimum = _moved_to(predictor, optimum, np.array(more[0].end))
            spread = uncertainty(optimum.jacobian, optimum.values, free.lower, free.upper,
                                 free.names)
            profiles, runs, _ = _profiles(predictor, optimum, spread, opts)
            profile_runs += runs
    found = _basins(optimum, spread, profiles)
    low, high, determined, rival_warnings = widened(spread, found, free.names)
    spread = dataclasses.replace(spread, low95=low, high95=high, determined=determined,
                                 warnings=spread.warnings + tuple(rival_warnings))
    fitted = predictor.outputs(optimum.values)
    model_error = _model_error(predictor, optimum)
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
    return _result(problem, predictor, optimum, spread, fitted, stats, warnings, profiles,
                   profile_runs, misfit is None, (wall1 - wall0, cpu1 - cpu0), windows)


def _search(problem: MechanismProblem, predictor: MechanismPredictor
            ) -> tuple[Optimum, list[float]]:
    """The best fit over the whole record (see the module docstring), and the windows' ends
    the continuation went through (none: the record was fitted whole)."""
    opts, sigma = problem.options, problem.sigma
    starts = starts_around(problem.free, opts.starts, opts.spread, opts.seed)
    ends = _windows(problem, predictor)
    if not ends:
        scan = Scan(opts.scan_points, opts.spread, opts.refine)
        return least_squares_fit(predictor, sigma, starts, opts.max_evaluations, scan,  # type: ignore[arg-type]
                                 leading=len(starts), workers=opts.workers), []
    # The first window: where no start's fit explains it, shorter ones (each a factor
    # horizon_growth) while they hold enough samples, SHORTER_FIRST_WINDOWS at most.
    tracks, explained = _first_tracks(problem, predictor, starts, ends[0])
    for _ in range(SHORTER_FIRST_WINDOWS):
        shorter = ends[0] / opts.horizon_growth
        if explained or not _enough(problem, shorter):
            break
        ends.insert(0, shorter)
        tracks, explained = _first_tracks(problem, predictor, starts, shorter)
    for end in [*ends[1:], None]:
        part = predictor if end is None else predictor.window(end)
        _, record = multi_start(part, sigma, tracks, opts.max_evaluations,  # type: ignore[arg-type]
                                stop_early=False, workers=opts.workers, settle=end is None)
        tracks, _ = _tracks(record, part)
    best = tracks[0]
    residuals = whitened(predictor.outputs(best) - predictor.measured.values, sigma)
    jacobian = whitened(predictor.jacobian(best), sigma)
    return Optimum(best, sigma, residuals, jacobian, tuple(record)), ends


def _first_tracks(problem: MechanismProblem, predictor: MechanismPredictor,
                  starts: np.ndarray, end: float) -> tuple[np.ndarray, bool]:
    """Every start fitted over the samples up to ``end``: :func:`_tracks` of the fits."""
    part = predictor.window(end)
    _, record = multi_start(part, problem.sigma, starts,  # type: ignore[arg-type]
                            problem.options.max_evaluations, stop_early=False,
                            workers=problem.options.workers)
    return _tracks(record, part)


def _enough(problem: MechanismProblem, end: float) -> bool:
    """Whether the samples up to ``end`` hold more numbers than twice the free parameters."""
    measured = problem.measured
    count = np.count_nonzero(measured.t <= end * (1 + 1e-9)) * len(measured.columns)
    return bool(count >= 2 * problem.free.size + 1)


def _model_error(predictor: MechanismPredictor, optimum: Optimum) -> float:
    """chi² of the difference between runs at tolerances 10 times looser than the fit's and
    its own, at the estimate (inf where the looser run stops)."""
    run = predictor.scene.run
    looser = MechanismPredictor(predictor.scene.with_run(rtol=run.rtol * 10,
                                                         atol=run.atol * 10),
                                predictor.model, predictor.free, predictor.measured)
    looser.counter = predictor.counter
    try:
        difference = looser.outputs(optimum.values) - predictor.outputs(optimum.values)
    except TrialFailed:
        return math.inf
    residual = whitened(difference, optimum.sigma)
    return float(residual @ residual)


def _windows(problem: MechanismProblem, predictor: MechanismPredictor) -> list[float]:
    """The continuation's windows' ends (s), the whole record not among them: from halfway
    between the FIRST_WINDOW_IMPACTS-th impact of a run at the start values and the next,
    ``horizon_growth`` times longer each (none where that run has no more impacts, or
    stops: the fit on the whole record meets the failure itself)."""
    try:
        onsets = predictor.impact_times(problem.free.start)
    except TrialFailed:
        return []
    if onsets.size <= FIRST_WINDOW_IMPACTS:
        return []
    first = 0.5 * (onsets[FIRST_WINDOW_IMPACTS - 1] + onsets[FIRST_WINDOW_IMPACTS])
    measured = problem.measured
    return horizon_windows(measured.t, len(measured.columns), problem.free.size, first,
                           problem.options.horizon_growth)


def _tracks(record: list[Start], part: MechanismPredictor) -> tuple[np.ndarray, bool]:
    """The fits' ends that explain the window's data within the noise, lowest first, each
    once (ends within SAME_TRACK of one kept are one track), and whether any does (if none,
    the lowest alone)."""
    fitted = sorted((s for s in record if not s.failed), key=lambda s: s.chi2)
    limit = explaining_limit(part.measured.size - part.free.size)
    kept: list[np.ndarray] = []
    for s in fitted:
        end = np.asarray(s.end, dtype=float)
        if (s.chi2 <= limit or not kept) and not any(
                np.all(np.abs(end - k) <= SAME_TRACK * np.abs(k)) for k in kept):
            kept.append(end)
    return np.array(kept), bool(fitted) and fitted[0].chi2 <= limit


def _chi2(optimum: Optimum) -> float:
    return float(np.sum(optimum.residuals**2))


def _moved_to(predictor: MechanismPredictor, optimum: Optimum, x: np.ndarray) -> Optimum:
    residuals = whitened(predictor.outputs(x) - predictor.measured.values, optimum.sigma)
    jacobian = whitened(predictor.jacobian(x), optimum.sigma)
    return Optimum(x, optimum.sigma, residuals, jacobian, optimum.starts)


def _profiles(predictor: MechanismPredictor, optimum: Optimum, spread: Uncertainty,
              opts: CalibrationOptions
              ) -> tuple[dict[str, dict[str, list[float]]], int, np.ndarray | None]:
    """chi² along each parameter, the others held at the best fit (the arms' form:
    :func:`jointplay.calibration.profiles.cost_profiles`), the runs, and the lowest point
    found where it lies LOWER_ELSEWHERE below the best (else None)."""
    free, best = predictor.free, optimum.values
    points = opts.profile_points
    if points == 0:
        return {}, 0, None
    chi2_min = _chi2(optimum)
    jtj = np.sum(optimum.jacobian**2, axis=0)
    grids = []
    for k in range(free.size):
        half = (PROFILE_SIGMAS * float(spread.std[k]) if math.isfinite(spread.std[k])
                else UNDETERMINED_SPAN * (abs(best[k]) or 1.0))
        grids.append(np.linspace(max(best[k] - half, free.lower[k]),
                                 min(best[k] + half, free.upper[k]), points))
    every = [np.where(np.arange(free.size) == k, value, best)
             for k, grid in enumerate(grids) for value in grid]
    values, runs = chi2_at_points(predictor, optimum.sigma, every,  # type: ignore[arg-type]
                                  opts.workers)
    out: dict[str, dict[str, list[float]]] = {}
    for k, name in enumerate(free.names):
        held = 1.0 / math.sqrt(jtj[k]) if jtj[k] > 0 else math.inf
        out[name] = {"value": grids[k].tolist(),
                     "chi2": [v if math.isfinite(v) else math.nan
                              for v in values[k * points:(k + 1) * points]],
                     "quadratic": (chi2_min + ((grids[k] - best[k]) / held) ** 2).tolist(),
                     "estimate": [float(best[k])], "chi2_min": [chi2_min]}
    finite = [(v, x) for v, x in zip(values, every, strict=True) if math.isfinite(v)]
    lowest = min(finite, key=lambda f: f[0]) if finite else None
    lower = lowest[1] if lowest and lowest[0] < chi2_min - LOWER_ELSEWHERE else None
    return out, runs, lower


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


def _result(problem: MechanismProblem, predictor: MechanismPredictor, optimum: Optimum,
            spread: Uncertainty, fitted: np.ndarray, stats: dict[str, Any],
            warnings: list[str], profiles: dict[str, dict[str, list[float]]],
            profile_runs: int, explains: bool, seconds: tuple[float, float],
            windows: list[float]) -> CalibrationResult:
    free = problem.free
    estimates = estimates_at(optimum.values, free, spread, explains)
    run = problem.scene.run
    units = dict(zip(problem.model.coordinates, problem.model.units, strict=True))
    return CalibrationResult(
        scene_name=problem.scene.name, measured=problem.measured, estimates=estimates,
        covariance=spread.covariance, correlation=spread.correlation,
        condition_number=spread.condition_number, residuals=stats,
        noise=dict(zip(problem.measured.columns, map(float, optimum.sigma), strict=True)),
        noise_stated=problem.noise_spread is None, fitted=fitted, starts=optimum.starts,
        simulations=predictor.counter.simulations + profile_runs,
        simulations_by_kind={"fits": predictor.counter.simulations,
                             "cost profiles": profile_runs},
        jacobian_source={name: "central differences" for name in free.names},
        wall_time_s=seconds[0], cpu_time_s=seconds[1], warnings=tuple(warnings),
        settings={"rtol": run.rtol, "atol": run.atol, "t_end": run.t_end,
                  "output_step": run.output_step,
                  **{k: v for k, v in dataclasses.asdict(problem.options).items()
                     if k not in ARMS_ONLY},
                  "search": _search_text(problem.options, windows),
                  "profile": "others fixed at their estimates",
                  "units": {c: _unit(c, units) for c in problem.measured.columns}},
        fit_explains_data=explains, profiles=profiles)


def _search_text(options: CalibrationOptions, windows: list[float]) -> str:
    """The search, in words, for the report."""
    text = (f"multi-start: a local fit from the start and from each of {options.starts - 1} "
            f"points within ±{options.spread:g} of it (relative)")
    if not windows:
        return text
    later = [f"{w:.4g} s" for w in windows[1:]] + ["the whole record"]
    return (f"{text}, over the first {windows[0]:.4g} s; then the fits that explain it, each "
            f"refitted from its last estimate over {', '.join(later)}")


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
