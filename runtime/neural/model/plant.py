"""The plant the controllers are identified on and judged by.

The control metrics compare the clearance robot with the ideal one to fractions of a
micrometre and of a milli-g. At the scenes' former default tolerances (rtol 1e-6, atol 1e-5) the
integrator's own error is larger than that: PD's RMS acceleration error after 50 ms is 2.8x
its converged value and its largest position error 1.4x (docs/control.md, "The plant"). So
``identify``, ``control`` and ``control-study`` integrate the plant (and the ideal robot it is
compared with) with the ``bdf`` integrator at PLANT_TOLERANCE (unless the scene already asks
for less): one setting for every controller and every comparison. ``bdf`` also gives the state
between samples, from which the acceleration errors are evaluated densely (SUBSTEPS points per
sample): the acceleration jumps at every sample where a controller changes its torque, and a
value taken once per sample sees only one side of each jump.
"""

from __future__ import annotations

from typing import Any

# rtol = atol for the plant and the reference in every closed loop and every identification
# run. At 1e-9 PD's three goal metrics are within 0.05 % of their values at 1e-10 (1e-8:
# 0.25 %), for 1.2x the cost of the default tolerances.
PLANT_TOLERANCE = 1e-9
# Points per sample at which the acceleration error is evaluated. On the default scene the RMS
# error after 50 ms at 10 points is within 0.5 % of its value at 20 for every controller; the
# once-per-sample value differed from it by up to 14 % (the internal-model controllers).
SUBSTEPS = 10


def control_plant(scene: Any, tolerance: float = PLANT_TOLERANCE) -> Any:
    """The scene integrated by ``bdf`` with tolerances tightened to ``tolerance`` (kept where
    the scene's own are tighter)."""
    run = scene.run
    rtol, atol = min(run.rtol, tolerance), min(run.atol, tolerance)
    if (rtol, atol, run.integrator) == (run.rtol, run.atol, "bdf"):
        return scene
    return scene.with_run(integrator="bdf", rtol=rtol, atol=atol)


__all__ = ["PLANT_TOLERANCE", "SUBSTEPS", "control_plant"]
