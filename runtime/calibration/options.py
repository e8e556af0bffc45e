""":class:`CalibrationOptions`, the options of :func:`jointplay.calibration.calibrate`."""

from __future__ import annotations

import math
from dataclasses import dataclass

from jointplay.common.errors import DescriptionError
from jointplay.common.limits import MAX_CALIBRATION_RUNS, MIN_ATOL, MIN_RTOL

_AT_LEAST = {"valley_points": 3, "valley_keep": 1, "starts": 1, "refine": 1, "grid_points": 3,
             "grid_candidates": 1, "window_looser": 1, "workers": 1, "max_evaluations": 1}
_WINDOWS = {"valley_window": "no lines", "horizon_first": "no continuation",
            "grid_window": "no grid"}
_RUNS = {"scan_points": "no scan", "grid_line_points": "no line",
         "valley_check_points": "no check", "profile_points": "no profiles"}
"""The options' lower bounds: counts, windows (s, 0: the stage off) and run counts (0: off)."""


@dataclass(frozen=True)
class CalibrationOptions:
    """How the fit runs: the options of :func:`calibrate` (``jointplay calibrate``'s flags,
    whose defaults these are); the results do not depend on ``workers``.

    Attributes
    ----------
    tighten : float
        The fit's runs use the scene's tolerances divided by this (a 1 µm sensor needs a model
        far more accurate than the scene's working accuracy of about 3 µm at the tip).
    starts : int
        Starts of the multi-start at most (the given one, then a Latin hypercube within
        ±``spread``) while the best fit does not explain the data; not with the continuation.
    spread : float
        The relative half-width of the region the starts and the grid cover.
    seed : int
        Seed of the Latin hypercube.
    max_evaluations : int
        Least-squares evaluations per start.
    profile_points : int
        Points of each cost profile (0: none).
    scan_points : int
        Runs along the weakest direction of the first optimum (0: no scan); only without the
        continuation.
    refine : int
        How many of the scan's lowest minima start a local fit.
    horizon_first : float
        The first window (s) of the horizon continuation, each stage started at the last one's
        estimate (0: no continuation; the fit starts on the whole record from ``starts``).
    horizon_growth : float
        The factor each window of the continuation grows by, up to the whole record.
    grid_window : float
        The window (s) of the global stage: a grid over ±``spread`` of the start in each free
        clearance, whose lowest local minima each start a track of the continuation from this
        window on (0: no grid; the continuation starts at ``horizon_first`` from the start).
    grid_points : int
        Grid values of each free clearance.
    grid_candidates : int
        How many of the grid's lowest local minima start a track.
    window_looser : float
        Runs on windows shorter than the record (the grid's too) use the fit's tolerances times
        the loosest of this, a tenth of it, ..., 1 within a chi² of 1 of the fit's own.
    valley_window : float
        The valley lines' first window, s (see :func:`continuation`).
    valley_points : int
        Runs per valley line.
    valley_keep : int
        Minima kept per valley line (and per grid line).
    grid_line_points : int
        Runs on the grid's window along the clearances' rugged directions through the best grid
        point, GRID_LINE_REACH grid spacings either side, whose ``valley_keep`` lowest minima
        replace it as tracks (0: no line): the valleys are far narrower than a grid spacing.
    valley_check_points : int
        With ``basins``, runs over the valley lines' first window along the clearances' rugged
        directions through the best fit, VALLEY_CHECK_REACH grid spacings either side, whose
        rival valleys, or a line too coarse for the fit's own valley, leave a parameter
        undetermined (:func:`valley_check`; 0: no check); run only where the noise explains
        the residuals (otherwise nothing is determined).
    basins : bool
        Look for the whole record's other minima the data cannot tell from the best fit, and
        widen the intervals to hold them (:mod:`jointplay.calibration.basins`).
    workers : int
        Processes for the grid's runs, the tracks' fits and the lines' runs.
    scheduler : str or None
        The address of a Dask scheduler whose cluster runs the independent pieces (None: local
        processes).
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
        checks = [("tighten", math.isfinite(self.tighten) and self.tighten >= 1,
                   "must be a finite number >= 1"),
                  ("seed", isinstance(self.seed, int) and not isinstance(self.seed, bool)
                   and self.seed >= 0, "must be an integer >= 0"),
                  ("horizon_growth", self.horizon_growth > 1, "must be > 1"),
                  ("spread", 0 < self.spread < 1, "must lie between 0 and 1 (relative)")]
        checks += [(name, getattr(self, name) >= least, f"must be >= {least}")
                   for name, least in _AT_LEAST.items()]
        checks += [(name, getattr(self, name) >= 0, f"must be >= 0 (s; 0: {off})")
                   for name, off in _WINDOWS.items()]
        checks += [(name, getattr(self, name) == 0 or getattr(self, name) >= 3,
                    f"must be 0 ({off}) or >= 3") for name, off in _RUNS.items()]
        for name, ok, allowed in checks:
            if not ok:
                raise DescriptionError(f"options.{name}",
                                       f"{allowed}, got {getattr(self, name)!r}")
        # Each stage's runs bounded before any work (too many would run out of memory).
        for name in ("starts", *_RUNS, "valley_points", "grid_points"):
            grid = name == "grid_points"  # the grid runs grid_points squared
            if getattr(self, name) ** (2 if grid else 1) > MAX_CALIBRATION_RUNS:
                most = math.isqrt(MAX_CALIBRATION_RUNS) if grid else MAX_CALIBRATION_RUNS
                raise DescriptionError(f"options.{name}", f"must be at most {most} (runs of "
                                       f"one stage of the fit), got {getattr(self, name)!r}")

    def tightened(self, rtol: float, atol: float) -> tuple[float, float]:
        """A scene's ``rtol`` and ``atol`` divided by ``tighten``; a :class:`DescriptionError`
        naming ``tighten`` where they would fall below what a run accepts."""
        most = min(rtol / MIN_RTOL, atol / MIN_ATOL)
        if self.tighten > most:
            raise DescriptionError("options.tighten", f"must be at most {most:.3g} with this "
                                   f"scene's tolerances (run.rtol {rtol:g}, run.atol {atol:g}: "
                                   f"the fit's may not fall below {MIN_RTOL:g} and "
                                   f"{MIN_ATOL:g}), got {self.tighten!r}")
        return rtol / self.tighten, atol / self.tighten
