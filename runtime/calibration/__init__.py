"""Calibration: a scene's physical parameters estimated from measured motion.

Rooms: ``measured`` (reading and checking the measured file), ``parameters`` (free names,
start values, physical bounds), ``predict`` (the model's outputs at the measured times and
their Jacobian), ``fit`` (weighted least squares, multi-start), ``uncertainty`` (covariance,
correlations, what the data cannot determine), ``profiles`` (chi² along each parameter),
``result`` (what a calibration found, and its JSON form), ``report`` (calibration.json,
report.md and the figures, written all or none).
"""

from jointplay.calibration.api import CalibrationOptions, calibrate, prepare, run
from jointplay.calibration.measured import Measured, read_measured
from jointplay.calibration.result import CalibrationResult, Estimate

__all__ = ["CalibrationOptions", "CalibrationResult", "Estimate", "Measured", "calibrate",
           "prepare", "read_measured", "run"]
