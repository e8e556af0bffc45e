"""Horizon continuation: fit a short leading window of the data first, then grow it.

Where joints with clearance start centred, each journal bounces tens of times in the first
tens of milliseconds; over the whole record the cost along the direction the tip sees least
(on the paper scene the difference of two clearances) is a sawtooth of valleys a fraction of a
micrometre wide, and a local fit from a start tens of micrometres away stops in the first one
it meets. Over a window holding only each journal's first impact the cost is one valley, or a
few. The window is grown geometrically, each stage's fit started at the previous estimate: a
longer window narrows the valleys, and the previous estimate lies in the true one. Short
windows are cheap: each stage's runs end at the window's end.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass

import numpy as np

from jointplay.calibration.fit import CHI2_SIGMAS, multi_start
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
    """One stage of the continuation: its window, where its fit began and ended, at what
    cost (``simulations``: runs of this stage, each ending at the window's end)."""

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
"""A parameter whose standard deviation over a window, at the stage's start, exceeds this
fraction of its value (or of its physical range where its value is 0) is held at its current
value in that stage: a window too short to see it (friction over the first impacts) would
otherwise drive it to a bound, from which the later stages do not return."""


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
"""The most the runs at a window's loosened tolerances may differ from those at the fit's
own, as a chi² (the whitened difference's sum of squares) at the best track's estimate: the
chi² of two fits then differ by about the model's error at most, far inside the margins the
tracks are compared by. A loosening that keeps a short window's runs within the noise can move
a long one's by thousands of chi², and would rank the tracks by the integrator's error."""


def window_looseness(predictor: Predictor, weights: np.ndarray, x: np.ndarray, end: float,
                     most: float) -> tuple[float, int]:
    """The loosest of ``most``, ``most``/10, ... , 1 (times the fit's tolerances) whose runs
    over the samples up to ``end`` stay within WINDOW_MODEL_ERROR of the fit's own at ``x``;
    and the runs it took. A run that stops counts as too loose; one that stops at the fit's
    own tolerances leaves ``most`` (the window's fits then meet the failure themselves)."""
    factors = []
    factor = most
    while factor > 1:
        factors.append(factor)
        factor /= 10
    if not factors:
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
    for factor in factors:
        loose = outputs(factor)
        if loose is not None and np.sum(whitened(loose - reference, weights)**2) \
                <= WINDOW_MODEL_ERROR:
            return factor, runs
    return 1.0, runs


def window(measured: Measured, end: float) -> Measured:
    """The samples of ``measured`` up to ``end``."""
    keep = measured.t <= end * (1 + 1e-9)
    return Measured(f"{measured.source} up to {end:g} s", measured.t[keep], measured.columns,
                    measured.values[keep])


@dataclass(frozen=True)
class ValleyScan:
    """Lines of ``points`` plain runs over the first window of at least ``window`` (s),
    through the best track's estimate along the directions the impacts make rugged, reaching
    ``reach`` times ``scale`` (one number per free parameter: for the clearances the grid's
    spacing) either side; its ``keep`` lowest local minima become tracks beside those carried."""

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
    first), the stages, and the runs they took.

    Each row of ``tracks`` is carried through the windows on its own, and dropped (see
    :func:`_surviving`) when it falls behind or joins a better one; a single track's first
    fit tries ``alternatives`` while it does not explain that window. A stage whose every run
    stops ends the continuation. The runs use the fit's tolerances times ``looser`` at most
    (:func:`window_looseness`). With ``valley``, from its window on each window first adds
    the lowest minima along lines through the best estimate as tracks (each later window's
    lines reaching ``growth`` times less far: its valleys are narrower, the tracks nearer
    them); before that window the parameters the lines do not move are held (a short window
    barely sees them and, left free, they absorb the clearances' misfit). With ``opening``,
    such lines through the best track's start replace it before the first window's fits."""
    measured = predictor.measured
    ends = horizon_windows(measured.t, len(measured.columns), predictor.free.size, first, growth)
    alive = [np.asarray(x, dtype=float) for x in tracks]
    labels = list(range(len(alive)))
    stages: list[Stage] = []
    runs = 0
    scanned = valley is None
    scans = 0
    for k, end in enumerate(ends):
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
        labels = [r[0] for r in kept]
        alive = [r[1] for r in kept]
    return np.array(alive).reshape(-1, predictor.free.size), stages, runs


def _line_minima(predictor: Predictor, stage_scene: Scene, part: Measured, weights: np.ndarray,
                 x: np.ndarray, scan: ValleyScan, workers: int) -> tuple[list[np.ndarray], int]:
    """The ``scan.keep`` lowest local minima of the window's chi² along ``scan``'s lines
    through ``x`` (across the directions :func:`_rugged` finds there), and the runs."""
    directions, runs = _rugged(predictor, stage_scene, part, weights, x, np.asarray(scan.scale))
    steps = np.linspace(-scan.reach, scan.reach, scan.points)
    lines, values, more = _lines_chi2(predictor, stage_scene, part, weights, x, directions,
                                      steps, workers)
    found: list[tuple[float, np.ndarray]] = []
    for line, chi2 in zip(lines, values, strict=True):
        found += [(chi2[i], line[i]) for i in line_minima(chi2)]
    found.sort(key=lambda f: f[0])
    return [point for _, point in found[:scan.keep]], runs + more


Fitted = tuple[list[tuple[int, np.ndarray, float]], list[tuple[int, np.ndarray, float]],
               list[Stage]]
"""A window's fits: (label, estimate, chi²) of each track fitted, those of the tracks the
window does not see (chi² inf, estimate unchanged), and the stages."""


def _window_fits(predictor: Predictor, stage_scene: Scene, part: Measured,
                 weights: np.ndarray, alive: list[np.ndarray], labels: list[int],
                 alternatives: np.ndarray | None, max_evaluations: int,
                 end: float, held_first: np.ndarray, workers: int) -> tuple[Fitted, int]:
    """Each track's fit over one window, on up to ``workers`` processes (a track whose every
    run stops ends there), and the runs; ``alternatives``: see :func:`continuation`. With
    several tracks each fit pauses after CHECKPOINT_EVALUATIONS, and goes on only while its
    chi² lies within the tracks' margin of the best (one further behind is dropped anyway)."""
    def fit(i: int, x: np.ndarray, budget: int
            ) -> tuple[tuple[Stage | None, np.ndarray] | None, int]:
        starts = alternatives if alternatives is not None else x[None, :]
        return _stage_fit(predictor, stage_scene, part, weights,
                          np.vstack([x, starts[1:]]), budget, end, labels[i], held_first)

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
    """The directions to scan at ``x`` among the parameters whose ``scale`` is not 0 (a step
    of 1 moves each by at most its ``scale``), and the runs: the eigenvectors of the window's
    scaled information matrix there, all but the weakest where more than one moves. The
    weakest is the smooth valley floor a local fit follows (on the paper scene the clearances'
    sum); the impacts make the others rugged (their difference)."""
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
    scene = predictor.scene
    step = scene.run.output_step
    t_end = min(scene.run.t_end, math.ceil(end / step - 1e-9) * step)
    return window(predictor.measured, end), loosened(scene.with_run(t_end=t_end), looser)


def _lines_chi2(predictor: Predictor, stage_scene: Scene, part: Measured, weights: np.ndarray,
                x: np.ndarray, directions: list[np.ndarray], steps: np.ndarray, workers: int
                ) -> tuple[list[list[np.ndarray]], list[np.ndarray], int]:
    """The lines through ``x`` (``x + s direction`` for each of ``steps``, inside the
    bounds, one per direction), the window's chi² along each, and the runs."""
    free, probe = predictor.free, predictor.over(stage_scene, part)
    lines = [[np.clip(x + s * direction, free.lower, free.upper) for s in steps]
             for direction in directions]
    every, runs = chi2_at_points(probe, weights, [p for line in lines for p in line], workers)
    values = [np.array(every[n * steps.size:(n + 1) * steps.size]) for n in range(len(lines))]
    return lines, values, runs


def _stage_fit(predictor: Predictor, stage_scene: Scene, part: Measured, weights: np.ndarray,
               starts: np.ndarray, max_evaluations: int, end: float,
               label: int, held_first: np.ndarray
               ) -> tuple[tuple[Stage | None, np.ndarray] | None, int]:
    """One track's fit over one window from ``starts[0]`` (the others tried while it does
    not explain the window): (its stage record, or None where the window sees none of the
    parameters, and its estimate), or None where its runs stop; and the runs."""
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
    best = min(record, key=lambda s: s.chi2)
    names = predictor.free.names
    return (Stage(end, int(part.t.size), best.start, tuple(x_next), best.chi2,
                  max(part.size - predictor.free.size, 1),
                  sum(s.evaluations for s in record), stage.counter.simulations,
                  best.message, tuple(n for n, h in zip(names, held, strict=True) if h),
                  label, time.process_time() - cpu0), np.asarray(x_next, dtype=float)), runs


CHECKPOINT_EVALUATIONS = 15
"""Evaluations after which a window's track fits pause to compare their chi² (over nine in
ten end sooner on the benchmark's cases; one that does not can creep down a rugged valley for
all its evaluations, on paper-fast-tip 36 s at 1.28 s, and end far behind the best)."""

WINDOW_EVALUATIONS = 20
"""Least-squares evaluations at most per window before the line scan (those windows only have to
bring each track near its valley; the later ones, with far narrower valleys, get the full count)."""

TRACK_MARGIN = 50.0
"""A track whose chi² over a window lies more than this above the best track's is dropped
(or more than CHI2_SIGMAS sqrt(2 dof), where that is less; either times the best track's
chi²/dof where that exceeds 1). Two fits of the same data differ in chi² by the model's
difference, not by the noise: the true parameters lie above the best fit by a chi² of 3 degrees
of freedom for three free parameters (over 21 once in 10⁴), and the windows' fits stop short of
their floor by a few more. The whole-record stage ranks the surviving tracks by this margin."""

SAME_ESTIMATE = 1e-4
"""Two tracks whose estimates differ by less than this fraction of each parameter's value
(or physical range, where the value is 0) have joined: the worse one is dropped."""


def _surviving(results: list[tuple[int, np.ndarray, float]], dof: int,
               free: FreeParameters) -> list[tuple[int, np.ndarray, float]]:
    """The tracks worth carrying to the next window, best first."""
    ordered = sorted(results, key=lambda r: r[2])
    if not ordered:
        return []
    best = ordered[0][2]
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
