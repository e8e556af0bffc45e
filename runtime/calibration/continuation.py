"""Horizon continuation: fit a short leading window of the data first, then grow it.

Where joints with clearance start centred, each journal crosses its clearance and bounces
tens of times in the first tens of milliseconds; over the whole record the cost along the
direction the tip sees least (on the paper scene the difference of two clearances) is a
sawtooth of valleys a fraction of a micrometre wide, and a local fit from a start tens of
micrometres away stops in the first valley it meets. Over a window that holds only the first
impact of each journal the cost is one valley across the physical range (on the paper scene,
three truths, chi² along c2 - c3 with their sum and the friction at the truth, 61 points
0.5 µm apart across ±50 %: one minimum at 5 ms, two to five at 10 ms, ten to fifteen at
20 ms). The window is then grown geometrically, each stage's fit started at the
previous stage's estimate: a longer window narrows the valleys, and the previous estimate,
determined more and more precisely, lies in the true one. Short windows are cheap: each
stage's runs end at the window's end.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from jointplay.calibration.fit import multi_start
from jointplay.calibration.measured import Measured
from jointplay.calibration.parameters import FreeParameters
from jointplay.calibration.predict import Predictor, TrialFailed, whitened
from jointplay.common.errors import SimulationError


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


HELD_RELATIVE_STD = 1.0
"""A parameter whose standard deviation over a window, at the stage's start, exceeds this
fraction of its value (or of its physical range where its value is 0) is held at its current
value in that stage: a window too short to see it (friction over the first impacts: σ about
37 times its value at 5 ms on the paper scene) would otherwise drive it to a bound, from
which the later stages do not return."""


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


def window(measured: Measured, end: float) -> Measured:
    """The samples of ``measured`` up to ``end``."""
    keep = measured.t <= end * (1 + 1e-9)
    return Measured(f"{measured.source} up to {end:g} s", measured.t[keep], measured.columns,
                    measured.values[keep])


def continuation(predictor: Predictor, weights: np.ndarray, starts: np.ndarray,
                 stated: bool, max_evaluations: int, first: float, growth: float
                 ) -> tuple[np.ndarray, list[Stage], int]:
    """The estimate after the windows shorter than the record, the stages, and the runs
    they took. The first window's fit starts at ``starts[0]`` and tries the other starts
    only while its fit does not explain that window within the stated noise; each later
    stage starts at the previous estimate. A stage whose every run stops ends the
    continuation at the previous estimate (the full-record fit and its fallbacks follow)."""
    measured = predictor.measured
    ends = horizon_windows(measured.t, len(measured.columns), predictor.free.size, first,
                           growth)
    scene = predictor.scene
    step = scene.run.output_step
    x = starts[0]
    stages: list[Stage] = []
    runs = 0
    for k, end in enumerate(ends):
        part = window(measured, end)
        t_end = min(scene.run.t_end, math.ceil(end / step - 1e-9) * step)
        stage_scene = scene.with_run(t_end=t_end)
        probe = Predictor(stage_scene, predictor.model, predictor.free, part,
                          compiled=predictor.compiled)
        try:
            held = _unseen(probe, weights, x)
        except TrialFailed:
            runs += probe.counter.simulations
            break
        runs += probe.counter.simulations
        if held.all():
            continue
        stage = Predictor(stage_scene, predictor.model, _holding(predictor.free, x, held),
                          part, compiled=predictor.compiled)
        try:
            x_next, record = multi_start(stage, weights, starts if k == 0 else x[None, :],
                                         max_evaluations, stop_early=stated)
        except SimulationError:
            runs += stage.counter.simulations
            break
        runs += stage.counter.simulations
        best = min(record, key=lambda s: s.chi2)
        stages.append(Stage(float(end), int(part.t.size), best.start, tuple(x_next),
                            best.chi2, max(part.size - predictor.free.size, 1),
                            sum(s.evaluations for s in record), stage.counter.simulations,
                            best.message,
                            tuple(n for n, h in zip(predictor.free.names, held, strict=True)
                                  if h)))
        x = x_next
    return np.asarray(x, dtype=float), stages, runs


def _unseen(probe: Predictor, weights: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Which parameters the window cannot determine from ``x`` (relative std over
    HELD_RELATIVE_STD)."""
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
