"""How a calibration runs: :class:`CalibrationOptions`, the options of
:func:`jointplay.calibration.calibrate` (``jointplay calibrate``'s flags), each checked on
construction."""

from __future__ import annotations

import math
from dataclasses import dataclass

from jointplay.common.errors import DescriptionError
from jointplay.common.limits import MAX_CALIBRATION_RUNS


@dataclass(frozen=True)
class CalibrationOptions:
    """How the fit runs: the options of :func:`calibrate` (``jointplay calibrate``'s flags).

    The defaults are what ``jointplay calibrate`` uses; the results do not depend on
    ``workers``.

    Attributes
    ----------
    tighten : float
        The runs of the fit use the scene's tolerances divided by this (a 1 µm sensor needs a
        model far more accurate than the scene's working accuracy of about 3 µm at the tip).
    starts : int
        Starts of the multi-start at most: the first the given start, the rest a Latin
        hypercube within ±``spread`` (relative) of it, run only while the best fit does not
        explain the data within the stated noise; only without the continuation
        (``horizon_first`` 0): with it, the tracks it carries are the whole-record fit's
        starts.
    spread : float
        The relative half-width of the region the starts and the grid cover.
    seed : int
        Seed of the Latin hypercube.
    max_evaluations : int
        Least-squares evaluations per start.
    profile_points : int
        Points of each cost profile (0: none).
    scan_points : int
        Runs along the weakest direction of the first optimum (0: no scan), local fits from
        the ``refine`` lowest minima along it; only without the continuation, as ``starts``.
    refine : int
        See ``scan_points``.
    horizon_first : float
        The first window (s) of the horizon continuation, grown by ``horizon_growth`` each stage
        up to the whole record, each stage started at the last one's estimate (0: no
        continuation, the fit starts on the whole record from ``starts``, then the scan).
    horizon_growth : float
        See ``horizon_first``.
    grid_window : float
        The window (s) of the global stage: a grid of ``grid_points`` values of each free
        clearance across ±``spread`` of the start, its runs at the fit's tolerances times
        ``window_looser`` at most (as are the runs on every window shorter than the record:
        each window the loosest of ``window_looser``, a tenth of it, ..., 1 whose runs stay
        within a chi² of 1 of the fit's own at the best estimate), whose
        ``grid_candidates`` lowest local minima each start a track of the continuation, from
        ``grid_window`` on (0: no grid; the continuation starts at ``horizon_first`` from the
        start).
    grid_points : int
        See ``grid_window``.
    grid_candidates : int
        See ``grid_window``.
    window_looser : float
        See ``grid_window``.
    valley_window : float
        The valley lines' first window, s (see :func:`continuation`).
    valley_points : int
        Runs per valley line.
    valley_keep : int
        Minima kept per valley line (and per grid line).
    grid_line_points : int
        Runs on the grid's window along the clearances' rugged directions (those of the valley
        lines) through the best grid point, GRID_LINE_REACH grid spacings either side, whose
        ``valley_keep`` lowest minima take that point's place as tracks (0: no line): over 20 ms
        the valleys along c2 - c3 on the paper scene are 50-100 nm wide, the truth's the lowest
        by about 20, and a fit from a grid point 2 µm from the next stays in the one it starts
        in.
    valley_check_points : int
        With the basin check on: runs over the valley lines' first window along the
        clearances' rugged directions (those of the valley lines) through the best fit,
        VALLEY_CHECK_REACH grid spacings either side; a parameter the lines move whose
        interval misses another valley there within the basin threshold of the fit's own is
        not determined, its interval widened to span the lines (:func:`valley_check`; 0: no
        check). Run only where the noise explains the residuals (otherwise nothing is
        determined).
    basins : bool
        Look for the other minima of the whole record's cost near the best fit, which the data
        cannot tell from it, and widen the intervals to hold them
        (:mod:`jointplay.calibration.basins`).
    workers : int
        Processes for the grid's runs, the tracks' fits and the lines' runs.
    scheduler : str or None
        The address of a Dask scheduler whose cluster runs the independent pieces instead of
        local processes (None: local).
    """

    tighten: float = 1000.0
    starts: int = 6
    spread: float = 0.5
    seed: int = 0
    max_evaluations: int = 40
    profile_points: int = 13
    scan_points: int = 201
    refine: int = 3
    horizon_first: float = 0.005
    horizon_growth: float = 2.0
    grid_window: float = 0.02
    grid_points: int = 16
    grid_candidates: int = 4
    window_looser: float = 100.0
    valley_window: float = 0.32
    valley_points: int = 81
    valley_keep: int = 3
    grid_line_points: int = 151
    valley_check_points: int = 161
    basins: bool = True
    workers: int = 2
    scheduler: str | None = None

    def __post_init__(self) -> None:
        checks = (("tighten", self.tighten >= 1, "must be >= 1"),
                  ("starts", self.starts >= 1, "must be >= 1"),
                  ("scan_points", self.scan_points == 0 or self.scan_points >= 3,
                   "must be 0 (no scan) or >= 3"),
                  ("refine", self.refine >= 1, "must be >= 1"),
                  ("horizon_first", self.horizon_first >= 0,
                   "must be >= 0 (s; 0: no continuation)"),
                  ("horizon_growth", self.horizon_growth > 1, "must be > 1"),
                  ("grid_window", self.grid_window >= 0, "must be >= 0 (s; 0: no grid)"),
                  ("grid_points", self.grid_points >= 3, "must be >= 3"),
                  ("grid_candidates", self.grid_candidates >= 1, "must be >= 1"),
                  ("grid_line_points", self.grid_line_points == 0
                   or self.grid_line_points >= 3, "must be 0 (no line) or >= 3"),
                  ("valley_check_points", self.valley_check_points == 0
                   or self.valley_check_points >= 3, "must be 0 (no check) or >= 3"),
                  ("window_looser", self.window_looser >= 1, "must be >= 1"),
                  ("workers", self.workers >= 1, "must be >= 1"),
                  ("spread", 0 < self.spread < 1, "must lie between 0 and 1 (relative)"),
                  ("max_evaluations", self.max_evaluations >= 1, "must be >= 1"),
                  ("profile_points", self.profile_points == 0 or self.profile_points >= 3,
                   "must be 0 (no profiles) or >= 3"))
        for name, ok, allowed in checks:
            if not ok:
                raise DescriptionError(f"options.{name}",
                                       f"{allowed}, got {getattr(self, name)!r}")
        # Each stage's runs bounded before any work (10**10 scan points once ran a fit and
        # then out of memory); the grid runs at most grid_points squared.
        bounds = (("starts", self.starts), ("scan_points", self.scan_points),
                  ("grid_line_points", self.grid_line_points),
                  ("valley_check_points", self.valley_check_points),
                  ("profile_points", self.profile_points), ("valley_points", self.valley_points),
                  ("grid_points", self.grid_points ** 2))
        for name, runs in bounds:
            if runs > MAX_CALIBRATION_RUNS:
                most = math.isqrt(MAX_CALIBRATION_RUNS) if name == "grid_points" \
                    else MAX_CALIBRATION_RUNS
                raise DescriptionError(f"options.{name}", f"must be at most {most} (runs of "
                                       f"one stage of the fit), got {getattr(self, name)!r}")
