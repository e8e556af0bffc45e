"""Horizon continuation: fit a short leading window of the data first, then grow it.

Over the whole record the cost along the direction the data see least (on the paper scene the
clearances' difference) is a sawtooth of valleys a fraction of a micrometre wide, where a local
fit stops in the first it meets; over a window holding each journal's first impacts it is one
valley, or a few. The window grows geometrically, each stage started at the previous estimate
(a longer window narrows the valleys; that estimate lies in the true one); a stage's runs end
at its window's end.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass

import numpy as np

from jointplay.calibration.fit import CHI2_SIGMAS, explaining_limit, multi_start
from jointplay.calibration.measured import Measured
from jointplay.calibration.parameters import FreeParameters
from jointplay.calibration.predict import (
    Predictor,
    TrialFailed,
    chi2_at_points,
    line_minima,
    whitened,
)
from jointplay.common.errors import SimulationError
from jointplay.common.pool import parallel_map
from jointplay.scene.definition import Scene


@dataclass(frozen=True)
class Stage:
    """One stage of the continuation: its window, where its fit began and ended, its runs."""

    window_end: float
    samples: int
    start: tuple[float, ...]
    end: tuple[float, ...]
    chi2: float
    dof: int
    evaluations: int
    simulations: int
    message: str
    held: tuple[str, ...] = ()
    track: int = 0
    cpu_s: float = 0.0


HELD_RELATIVE_STD = 1.0
"""A parameter whose standard deviation over a window at the stage's start exceeds this
fraction of its value (or range, where 0) is held there: a window that barely sees it (the
friction over the first impacts) would drive it to a bound the later stages never leave."""


def horizon_windows(t: np.ndarray, columns: int, n_free: int, first: float,
                    growth: float) -> list[float]:
    """The windows' ends (s): ``first`` (lengthened until it holds at least twice as many
    numbers as free parameters), times ``growth`` each stage, before the last sample; the
    last stage, the whole record, is not in the list."""
    end = max(first, float(t[0]))
    while np.count_nonzero(t <= end * (1 + 1e-9)) * columns < 2 * n_free + 1 and end < t[-1]:
        end *= growth
    ends = []
    while end < t[-1] * (1 - 1e-9):
        ends.append(end)
        end *= growth
    return ends


def loosened(scene: Scene, factor: float) -> Scene:
    """``scene`` with its integrator's tolerances times ``factor`` (where it has them)."""
    run = scene.run
    if factor == 1 or run.integrator not in ("bdf", "cvodes", "idas"):
        return scene
    return scene.with_run(rtol=run.rtol * factor, atol=run.atol * factor)


WINDOW_MODEL_ERROR = 1.0
"""The most a window's runs at loosened tolerances may differ from those at the fit's own, as
a chi² at the best track's estimate: far inside the margins the tracks are compared by (a
loosening harmless on a short window can move a long one's chi² by thousands)."""


def window_looseness(predictor: Predictor, weights: np.ndarray, x: np.ndarray, end: float,
                     most: float) -> tuple[float, int]:
    """The loosest of ``most``, ``most``/10, ... , 1 (times the fit's tolerances) whose runs up
    to ``end`` stay within WINDOW_MODEL_ERROR of the fit's own at ``x``, and the runs. A run
    that stops is too loose; one that stops at the fit's tolerances leaves ``most``."""
    if not most > 1:
        return 1.0, 0
    runs = 0

    def outputs(factor: float) -> np.ndarray | None:
        nonlocal runs
        part, scene = _window_problem(predictor, end, factor)
        probe = predictor.over(scene, part)
        try:
            return probe.outputs(x, with_jacobian=False)
        except TrialFailed:
            return None
        finally:
            runs += probe.counter.simulations

    reference = outputs(1.0)
    if reference is None:
        return most, runs
    factor = most
    while factor > 1:
        loose = outputs(factor)
        if loose is not None and np.sum(whitened(loose - reference, weights)**2) \
                <= WINDOW_MODEL_ERROR:
            return factor, runs
        factor /= 10
    return 1.0, runs


def window(measured: Measured, end: float) -> Measured:
    """The samples of ``measured`` up to ``end``."""
    keep = measured.t <= end * (1 + 1e-9)
    return Measured(f"{measured.source} up to {end:g} s", measured.t[keep], measured.columns,
                    measured.values[keep])


@dataclass(frozen=True)
class ValleyScan:
    """Lines of ``points`` plain runs over the first window of at least ``window`` (s) through
    the best track's estimate along the rugged directions, ``reach`` times ``scale`` (per
    parameter; the clearances' grid spacing) either side; the ``keep`` lowest minima become
    tracks."""

    window: float
    points: int
    reach: float
    keep: int
    scale: tuple[float, ...]

    @property
    def held_before(self) -> np.ndarray:
        """The parameters held before the scan's window (those its lines do not move)."""
        return np.asarray(self.scale) == 0


def continuation(predictor: Predictor, weights: np.ndarray, tracks: np.ndarray,
                 alternatives: np.ndarray, max_evaluations: int, first: float, growth: float,
                 valley: ValleyScan | None = None, looser: float = 1.0, workers: int = 1,
                 opening: ValleyScan | None = None) -> tuple[np.ndarray, list[Stage], int]:
    """The estimates after the windows shorter than the record (the surviving tracks, best
    first), the stages, and the runs.

    Each row of ``tracks`` is carried on its own, dropped (:func:`_surviving`) when it falls
    behind or joins a better one; a single track's first fit tries ``alternatives`` while it
    does not explain that window; a stage whose every run stops ends it. Runs use the fit's
    tolerances times ``looser`` at most (:func:`window_looseness`). With ``valley``, from its
    window on, the lowest minima along lines through the best estimate join the tracks (each
    later window's lines reaching ``growth`` times less far); before it, the parameters the
    lines do not move are held (left free they absorb the clearances' misfit). With
    ``opening``, such lines through the best track's start replace it before the first fits. The
    last window is left out where the record is under sqrt(``growth``) times it and no track
    explains the one before (refining a misfit's valley, it took 20-36 % of a fast case's time)."""
    measured = predictor.measured
    ends = horizon_windows(measured.t, len(measured.columns), predictor.free.size, first, growth)
    alive, labels = [np.asarray(x, dtype=float) for x in tracks], list(range(len(tracks)))
    stages: list[Stage] = []
    runs = scans = 0
    scanned, misfit = valley is None, False
    for k, end in enumerate(ends):
        if misfit and k == len(ends) - 1 and end * math.sqrt(growth) > measured.t[-1]:
            break
        # a longer window is never run looser than a shorter one needed
        looser, more = window_looseness(predictor, weights, alive[0], end, looser) \
            if alive else (looser, 0)
        runs += more
        part, stage_scene = _window_problem(predictor, end, looser)
        dof = max(part.size - predictor.free.size, 1)
        scans_here = []
        if k == 0 and opening is not None:
            # through the best grid point; its minima are fitted here, where valleys are widest
            scans_here.append(opening)
        if valley is not None and end >= valley.window * (1 - 1e-9):
            scanned = True
            # each later window's lines reach less far (narrower valleys, tracks nearer them)
            scans_here.append(dataclasses.replace(valley, reach=valley.reach / growth**scans))
            scans += 1
        for scan in scans_here:
            if not alive:
                break
            found, more = _line_minima(predictor, stage_scene, part, weights, alive[0], scan,
                                       workers)
            runs += more
            if found:  # the line passes through the best track's estimate: it replaces it
                first_label = max(labels) + 1
                alive = found + alive[1:]
                labels = list(range(first_label, first_label + len(found))) + labels[1:]
        held_first = (valley.held_before if valley is not None and not scanned
                      else np.zeros(predictor.free.size, dtype=bool))
        evaluations = max_evaluations if scanned else min(max_evaluations, WINDOW_EVALUATIONS)
        (fitted, unseen, window_stages), more = _window_fits(
            predictor, stage_scene, part, weights, alive, labels,
            alternatives if k == 0 and len(alive) == 1 else None, evaluations,
            float(end), held_first, workers)
        runs += more
        stages += window_stages
        if not fitted and not unseen:
            break
        kept = _surviving(fitted, dof, predictor.free) + unseen
        misfit = bool(fitted) and min(r[2] for r in fitted) > explaining_limit(dof)
        labels = [r[0] for r in kept]
        alive = [r[1] for r in kept]
    return np.array(alive).reshape(-1, predictor.free.size), stages, runs


def _line_minima(predictor: Predictor, stage_scene: Scene, part: Measured, weights: np.ndarray,
                 x: np.ndarray, scan: ValleyScan, workers: int) -> tuple[list[np.ndarray], int]:
    """The ``scan.keep`` lowest local minima of the window's chi² along ``scan``'s lines
    through ``x`` (across the directions :func:`_rugged` finds there), and the runs."""
    steps = np.linspace(-scan.reach, scan.reach, scan.points)
    _, lines, values, runs = _lines_chi2(predictor, stage_scene, part, weights, x, scan.scale,
                                         steps, workers)
    found: list[tuple[float, np.ndarray]] = []
    for line, chi2 in zip(lines, values, strict=True):
        found += [(chi2[i], line[i]) for i in line_minima(chi2)]
    found.sort(key=lambda f: f[0])
    return [point for _, point in found[:scan.keep]], runs


Fitted = tuple[list[tuple[int, np.ndarray, float]], list[tuple[int, np.ndarray, float]],
               list[Stage]]
"""A window's fits: (label, estimate, chi²) of each track fitted, those of the tracks the
window does not see (chi² inf, estimate unchanged), and the stages."""


def _window_fits(predictor: Predictor, stage_scene: Scene, part: Measured,
                 weights: np.ndarray, alive: list[np.ndarray], labels: list[int],
                 alternatives: np.ndarray | None, max_evaluations: int,
                 end: float, held_first: np.ndarray, workers: int) -> tuple[Fitted, int]:
    """Each track's fit over one window, on up to ``workers`` processes (a track whose every
    run stops ends), and the runs. With several tracks each fit pauses after
    CHECKPOINT_EVALUATIONS and goes on only while within the tracks' margin of the best."""
    def fit(i: int, x: np.ndarray, budget: int
            ) -> tuple[tuple[Stage | None, np.ndarray] | None, int]:
        starts = x[None, :] if alternatives is None else np.vstack([x, alternatives[1:]])
        return _stage_fit(predictor, stage_scene, part, weights, starts, budget, end,
                          labels[i], held_first)

    pause = min(max_evaluations, CHECKPOINT_EVALUATIONS) if len(alive) > 1 else max_evaluations
    done = parallel_map(lambda i: fit(i, alive[i], pause), len(alive), workers)
    runs = sum(stage_runs for _, stage_runs in done)
    at_pause = [(i, r[0]) for i, (r, _) in enumerate(done) if r is not None and r[0] is not None]
    paused = [(i, stage) for i, stage in at_pause if stage.evaluations >= pause]
    if pause < max_evaluations and paused:
        best, dof = min(s.chi2 for _, s in at_pause), max(part.size - predictor.free.size, 1)
        going = [(i, stage) for i, stage in paused if stage.chi2 <= best + track_margin(best, dof)]
        more = parallel_map(lambda j: fit(going[j][0], np.asarray(going[j][1].end),
                                          max_evaluations - pause), len(going), workers)
        for (i, first), (result, stage_runs) in zip(going, more, strict=True):
            runs += stage_runs
            if result is not None and result[0] is not None:
                second, x_next = result
                done[i] = (dataclasses.replace(
                    second, start=first.start, evaluations=first.evaluations + second.evaluations,
                    simulations=first.simulations + second.simulations,
                    cpu_s=first.cpu_s + second.cpu_s), x_next), 0
    fitted: list[tuple[int, np.ndarray, float]] = []
    unseen: list[tuple[int, np.ndarray, float]] = []
    stages: list[Stage] = []
    for i, (result, _) in enumerate(done):
        if result is None:
            continue  # every run of this track stopped: the track ends
        stage, x_next = result
        if stage is None:
            unseen.append((labels[i], alive[i], math.inf))
        else:
            stages.append(stage)
            fitted.append((labels[i], x_next, stage.chi2))
    return (fitted, unseen, stages), runs


def _rugged(predictor: Predictor, stage_scene: Scene, part: Measured, weights: np.ndarray,
            x: np.ndarray, scale: np.ndarray) -> tuple[list[np.ndarray], int]:
    """The directions to scan at ``x`` among the parameters whose ``scale`` is not 0 (a unit
    step moves each by at most its ``scale``), and the runs: the eigenvectors of the window's
    scaled information matrix but the weakest where more than one moves (the smooth valley
    floor a local fit follows; the impacts make the others rugged)."""
    probe = predictor.over(stage_scene, part)
    try:
        jac = whitened(probe.jacobian(x), weights)
    except TrialFailed:
        return [], probe.counter.simulations
    moving = scale > 0
    scaled = jac[:, moving] * scale[moving]
    _, vectors = np.linalg.eigh(scaled.T @ scaled)
    out = []
    for v in vectors.T[1:] if vectors.shape[1] > 1 else vectors.T:
        direction = np.zeros(scale.size)
        direction[moving] = v * scale[moving]
        out.append(direction / np.max(np.abs(direction[moving]) / scale[moving]))
    return out, probe.counter.simulations


def _window_problem(predictor: Predictor, end: float, looser: float) -> tuple[Measured, Scene]:
    """The samples up to ``end`` and the scene whose runs end at the output step holding it,
    at the fit's tolerances times ``looser``."""
    scene, step = predictor.scene, predictor.scene.run.output_step
    t_end = min(scene.run.t_end, math.ceil(end / step - 1e-9) * step)
    return window(predictor.measured, end), loosened(scene.with_run(t_end=t_end), looser)


def _lines_chi2(predictor: Predictor, stage_scene: Scene, part: Measured, weights: np.ndarray,
                x: np.ndarray, scale: tuple[float, ...], steps: np.ndarray, workers: int
                ) -> tuple[list[np.ndarray], list[list[np.ndarray]], list[np.ndarray], int]:
    """The rugged directions at ``x`` (:func:`_rugged`), the lines through it along them
    (``x + s direction`` for each of ``steps``, inside the bounds), the window's chi² along
    each, and the runs."""
    directions, runs = _rugged(predictor, stage_scene, part, weights, x, np.asarray(scale))
    free, probe = predictor.free, predictor.over(stage_scene, part)
    lines = [[np.clip(x + s * direction, free.lower, free.upper) for s in steps]
             for direction in directions]
    every, more = chi2_at_points(probe, weights, [p for line in lines for p in line], workers)
    values = [np.array(every[n * steps.size:(n + 1) * steps.size]) for n in range(len(lines))]
    return directions, lines, values, runs + more


def _stage_fit(predictor: Predictor, stage_scene: Scene, part: Measured, weights: np.ndarray,
               starts: np.ndarray, max_evaluations: int, end: float,
               label: int, held_first: np.ndarray
               ) -> tuple[tuple[Stage | None, np.ndarray] | None, int]:
    """One track's fit over one window from ``starts[0]`` (the others tried while it does not
    explain it): (its stage, None where the window sees no parameter, and its estimate), or
    None where its runs stop; and the runs."""
    x = starts[0]
    cpu0 = time.process_time()
    probe = predictor.over(stage_scene, part)
    try:
        held = _unseen(probe, weights, x) | held_first
    except TrialFailed:
        return None, probe.counter.simulations
    runs = probe.counter.simulations
    if held.all():
        return (None, x), runs
    stage = probe.for_free(_holding(predictor.free, x, held))
    try:
        x_next, record = multi_start(stage, weights, starts, max_evaluations, stop_early=True,
                                     settle=True)
    except SimulationError:
        return None, runs + stage.counter.simulations
    runs += stage.counter.simulations
    best, names = min(record, key=lambda s: s.chi2), predictor.free.names
    return (Stage(end, int(part.t.size), best.start, tuple(x_next), best.chi2,
                  max(part.size - predictor.free.size, 1),
                  sum(s.evaluations for s in record), stage.counter.simulations,
                  best.message, tuple(n for n, h in zip(names, held, strict=True) if h),
                  label, time.process_time() - cpu0), np.asarray(x_next, dtype=float)), runs


CHECKPOINT_EVALUATIONS = 15
"""Evaluations after which a window's track fits pause to compare their chi² (nine in ten end
sooner; one that does not can creep down a rugged valley for all its evaluations)."""

WINDOW_EVALUATIONS = 20
"""Evaluations at most per window before the valley lines (which only bring each track near
its valley; the later windows, with far narrower valleys, get the full count)."""

TRACK_MARGIN = 50.0
"""A track whose chi² over a window lies more than this above the best track's is dropped
(see :func:`track_margin`): the truth lies above the best fit by a chi² on as many degrees of
freedom as free parameters (over 21 once in 10⁴ for three), and windows' fits stop a few short
of their floor. The whole-record stage ranks the surviving tracks by it too."""

SAME_ESTIMATE = 1e-4
"""Two tracks whose estimates differ by less than this fraction of each parameter's value
(or physical range, where the value is 0) have joined: the worse one is dropped."""


def _surviving(results: list[tuple[int, np.ndarray, float]], dof: int,
               free: FreeParameters) -> list[tuple[int, np.ndarray, float]]:
    """The tracks worth carrying to the next window, best first."""
    ordered = sorted(results, key=lambda r: r[2])
    best = ordered[0][2] if ordered else math.inf
    kept: list[tuple[int, np.ndarray, float]] = []
    for label, x, chi2 in ordered:
        scale = np.where(x != 0, np.abs(x), free.upper - free.lower)
        if not chi2 > best + track_margin(best, dof) and not any(
                np.all(np.abs(x - other) <= SAME_ESTIMATE * scale) for _, other, _ in kept):
            kept.append((label, x, chi2))
    return kept


def track_margin(best: float, dof: int) -> float:
    """How far above the best track's chi² (``best``, on ``dof``) a track is dropped: growing
    with a misfit of the best (chi²/dof over 1), which the tracks' chi² differ by too."""
    return min(TRACK_MARGIN, CHI2_SIGMAS * math.sqrt(2 * dof)) * max(1.0, best / dof)


def _unseen(probe: Predictor, weights: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Which parameters the window cannot determine at ``x`` (relative std > HELD_RELATIVE_STD)."""
    free = probe.free
    jac = whitened(probe.jacobian(x), weights)
    scale = np.where(x != 0, np.abs(x), free.upper - free.lower)
    information = (jac * scale).T @ (jac * scale)
    try:
        std = np.sqrt(np.abs(np.diag(np.linalg.pinv(information))))
    except np.linalg.LinAlgError:
        return np.zeros(free.size, dtype=bool)
    return np.asarray(std > HELD_RELATIVE_STD)


def _holding(free: FreeParameters, x: np.ndarray, held: np.ndarray) -> FreeParameters:
    """``free`` with the ``held`` parameters' bounds closed around their values in ``x``."""
    if not held.any():
        return free
    width = 1e-12 * np.maximum(np.abs(x), 1e-300)
    lower = np.where(held, np.maximum(x - width, free.lower), free.lower)
    upper = np.where(held, np.minimum(x + width, free.upper), free.upper)
    return dataclasses.replace(free, lower=lower, upper=upper)
