"""The search of a mechanism's calibration (:mod:`jointplay.mechanism.calibration`): the
predictor of its outputs, and the multi-start and continuation that find the best fit.

Each impact that moves past a sample changes the residuals abruptly, so over many impacts the
cost is a comb of narrow valleys; over the first few it is one. A local fit runs from the
start and from each point of a seeded Latin hypercube within ±``spread`` of it over a first
window that holds :data:`FIRST_WINDOW_IMPACTS` impacts of a run at the start values (or a
shorter one, where no fit explains it: :data:`SHORTER_FIRST_WINDOWS`); the minima that
explain that window's data within the noise (the lowest, if none does) are tracks, each
fitted again over a window ``horizon_growth`` times longer, from its last estimate, up to
the whole record, where the lowest is the estimate. A record of fewer impacts is fitted
whole. The Jacobian is taken by central differences of whole runs (two per free parameter,
:data:`FD_STEP`; the mechanism's compiled sensitivities do not exist).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.calibration.continuation import horizon_windows, window
from jointplay.calibration.fit import (
    Optimum,
    Scan,
    Start,
    explaining_limit,
    least_squares_fit,
    multi_start,
    starts_around,
)
from jointplay.calibration.measured import Measured, grid_indices
from jointplay.calibration.options import CalibrationOptions
from jointplay.calibration.parameters import FreeParameters
from jointplay.calibration.predict import Counter, TrialFailed, whitened
from jointplay.common.errors import DescriptionError
from jointplay.mechanism.calibration_inputs import ACCELERATION, ENERGIES, RATE, clearance_joint
from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.model import MechanismModel, model_for

if TYPE_CHECKING:
    from jointplay.mechanism.calibration import MechanismProblem

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

    def over(self, scene: MechanismScene, measured: Measured | None = None
             ) -> MechanismPredictor:
        """This predictor's model and free parameters on ``scene`` and ``measured`` (default:
        its own), with its own count and cache (as :meth:`Predictor.over`)."""
        return MechanismPredictor(scene, self.model, self.free,
                                  self.measured if measured is None else measured)

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


def search(problem: MechanismProblem, predictor: MechanismPredictor
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
    """Whether the samples up to ``end`` hold more numbers than twice the free parameters
    (as :func:`horizon_windows` asks of a first window)."""
    return window(problem.measured, end).size >= 2 * problem.free.size + 1


def model_error(predictor: MechanismPredictor, optimum: Optimum) -> float:
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


def search_text(options: CalibrationOptions, windows: list[float]) -> str:
    """The search, in words, for the report."""
    text = (f"multi-start: a local fit from the start and from each of {options.starts - 1} "
            f"points within ±{options.spread:g} of it (relative)")
    if not windows:
        return text
    later = [f"{w:.4g} s" for w in windows[1:]] + ["the whole record"]
    return (f"{text}, over the first {windows[0]:.4g} s; then the fits that explain it, each "
            f"refitted from its last estimate over {', '.join(later)}")
