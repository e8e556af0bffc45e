"""Calibration: a scene's physical parameters estimated from measured motion.

The public names are re-exported here; the method, stage by stage: docs/how-to/calibrate.md.
"""

from jointplay.calibration.api import CalibrationOptions, calibrate, prepare, run
from jointplay.calibration.measured import Measured, read_measured
from jointplay.calibration.result import CalibrationResult, Estimate

__all__ = ["CalibrationOptions", "CalibrationResult", "Estimate", "Measured", "calibrate",
           "prepare", "read_measured", "run"]
