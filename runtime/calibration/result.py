"""What a calibration found (:class:`CalibrationResult`), and its JSON form, which is
``calibration.json``."""

from __future__ import annotations

import dataclasses
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
    """Everything a calibration found; ``to_dict()`` is ``calibration.json``.

    Attributes
    ----------
    scene_name : str
        The scene's name.
    measured : Measured
        The measured samples that were fitted.
    estimates : dict of str to Estimate
        Per free parameter: ``value``, ``std``, ``low95``, ``high95``, ``start`` and whether the
        data ``determined`` it.
    covariance : numpy.ndarray
        The estimates' covariance.
    correlation : numpy.ndarray
        Their correlation matrix.
    condition_number : float
        Of the weighted Jacobian at the fit: large means parameters the data cannot separate.
    residuals : dict
        The residuals' statistics: chi², its normalised value (chi²/dof), per column RMS.
    noise : dict of str to float
        The noise per column, stated or estimated.
    noise_stated : bool
        Whether the noise was given (else estimated from the data's sample-to-sample scatter).
    fitted : numpy.ndarray
        The model's samples at the estimates, as the measured columns.
    starts : tuple of Start
        Each start of the multi-start: where it began and ended, at what cost.
    simulations : int
        The runs the calibration took.
    simulations_by_kind : dict of str to int
        The same, by what they were for.
    jacobian_source : dict of str to str
        Per free parameter, where its derivatives came from.
    wall_time_s : float
        s, wall time.
    cpu_time_s : float
        s, processor time of this process and its workers.
    warnings : tuple of str
        What the user must know: parameters not determined, a fit that does not explain the data.
    settings : dict
        The options and tolerances the fit ran with.
    fit_explains_data : bool or None
        Whether chi² is within its two-sided 99 % range (widened by an estimated noise's own
        spread) and the residuals pass the Ljung-Box whiteness test (None: not judged).
    stages : tuple of Stage
        The stages of the horizon continuation, in order.
    profiles : dict
        Per free parameter: the cost profile's values and chi².
    grid : GridResult or None
        The global stage's grid, when it ran.

    Examples
    --------
    >>> import numpy as np
    >>> import jointplay
    >>> from jointplay.calibration import Measured
    >>> scene = jointplay.default_scene()
    >>> scene = scene.with_robot(jointplay.ideal_counterpart(scene.robot)).with_run(t_end=0.1)
    >>> truth = jointplay.simulate(scene, parameters={"link2.com": 0.19})
    >>> noise = 1e-6 * np.random.default_rng(1).standard_normal(truth.tip_position.shape)
    >>> measured = Measured("synthetic", truth.t, ("tip_x", "tip_y"), truth.tip_position + noise)
    >>> options = jointplay.CalibrationOptions(tighten=1.0, starts=1, scan_points=0,
    ...                                        profile_points=0, horizon_first=0, basins=False)
    >>> result = jointplay.calibrate(scene, measured, ["link2.com"], noise=1e-6, options=options)
    >>> result.names, round(float(result.values[0]), 3)
    (['link2.com'], 0.19)
    >>> bool(result.estimates["link2.com"].low95 <= 0.19 <= result.estimates["link2.com"].high95)
    True
    >>> "estimates" in result.to_dict()  # the calibration.json document
    True
    """

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
            "estimates": {e.name: {"value": e.value, "std": number(e.std), "low95": e.low95,
                                   "high95": e.high95, "start": e.start, "determined": e.determined}
                          for e in self.estimates.values()},
            "correlation": {"names": self.names,
                            "matrix": [[number(v) for v in row] for row in self.correlation]},
            "condition_number": number(self.condition_number),
            "residuals": self.residuals,
            "noise": {"stated": self.noise_stated, "std": self.noise},
            "starts": [{**dataclasses.asdict(s), "chi2": number(s.chi2)} for s in self.starts],
            "simulations": self.simulations,
            "simulations_by_kind": self.simulations_by_kind,
            "jacobian": self.jacobian_source,
            "wall_time_s": self.wall_time_s,
            "cpu_time_s": self.cpu_time_s,
            "warnings": list(self.warnings),
            "fit_explains_data": self.fit_explains_data,
            "continuation": [{**dataclasses.asdict(s), "chi2": number(s.chi2)}
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
