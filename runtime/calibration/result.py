"""What a calibration found (:class:`CalibrationResult`), and its JSON form, which is
``calibration.json``."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from jointplay.calibration.continuation import Stage
from jointplay.calibration.fit import Start
from jointplay.calibration.grid import GridResult
from jointplay.calibration.measured import Measured


@dataclass(frozen=True)
class Estimate:
    """One free parameter's estimate, standard deviation and 95 % interval."""

    name: str
    value: float
    std: float
    low95: float
    high95: float
    start: float
    determined: bool


@dataclass(frozen=True)
class CalibrationResult:
    """Everything a calibration found; ``to_dict()`` is ``calibration.json``."""

    scene_name: str
    measured: Measured
    estimates: dict[str, Estimate]
    covariance: np.ndarray
    correlation: np.ndarray
    condition_number: float
    residuals: dict[str, Any]
    noise: dict[str, float]
    noise_stated: bool
    fitted: np.ndarray
    starts: tuple[Start, ...]
    simulations: int
    simulations_by_kind: dict[str, int]
    jacobian_source: dict[str, str]
    wall_time_s: float
    cpu_time_s: float
    warnings: tuple[str, ...]
    settings: dict[str, Any]
    fit_explains_data: bool | None = None
    """The residuals are the noise: chi² in its 99 % range, and white (runs test)."""
    stages: tuple[Stage, ...] = ()
    profiles: dict[str, dict[str, list[float]]] = field(default_factory=dict)
    grid: GridResult | None = None

    @property
    def names(self) -> list[str]:
        return list(self.estimates)

    @property
    def values(self) -> np.ndarray:
        return np.array([e.value for e in self.estimates.values()])

    def to_dict(self) -> dict[str, Any]:
        def number(v: float) -> float | str | None:
            return float(v) if math.isfinite(v) else (None if math.isnan(v) else str(v))

        return {
            "scene": self.scene_name,
            "measured": {"source": self.measured.source, "columns": list(self.measured.columns),
                         "samples": int(self.measured.t.size),
                         "t_first": float(self.measured.t[0]),
                         "t_last": float(self.measured.t[-1])},
            "estimates": {e.name: {"value": e.value, "std": number(e.std),
                                   "low95": e.low95, "high95": e.high95, "start": e.start,
                                   "determined": e.determined}
                          for e in self.estimates.values()},
            "correlation": {"names": self.names,
                            "matrix": [[number(v) for v in row] for row in self.correlation]},
            "condition_number": number(self.condition_number),
            "residuals": self.residuals,
            "noise": {"stated": self.noise_stated, "std": self.noise},
            "starts": [{"start": list(s.start), "end": list(s.end), "chi2": number(s.chi2),
                        "evaluations": s.evaluations, "message": s.message,
                        "failed": s.failed} for s in self.starts],
            "simulations": self.simulations,
            "simulations_by_kind": self.simulations_by_kind,
            "jacobian": self.jacobian_source,
            "wall_time_s": self.wall_time_s,
            "cpu_time_s": self.cpu_time_s,
            "warnings": list(self.warnings),
            "fit_explains_data": self.fit_explains_data,
            "continuation": [{"window_end": s.window_end, "samples": s.samples,
                              "start": list(s.start), "end": list(s.end),
                              "chi2": number(s.chi2), "dof": s.dof,
                              "evaluations": s.evaluations, "simulations": s.simulations,
                              "held": list(s.held), "track": s.track,
                              "message": s.message}
                             for s in self.stages],
            "grid": None if self.grid is None else {
                "axes": list(self.grid.axes), "points_per_axis": self.grid.points_per_axis,
                "window_end": self.grid.window_end, "simulations": self.grid.simulations,
                "candidates": [list(map(float, c)) for c in self.grid.candidates],
                "chi2": [number(v) for v in self.grid.chi2]},
            "settings": self.settings,
            "profiles": self.profiles,
        }


__all__ = ["CalibrationResult", "Estimate"]
