"""Statistics, not one run: the controllers over training seeds, trajectories and clearances.

``jointplay control-study`` identifies a model per seed (and per clearance size), then runs the
baselines once per case and both internal-model controllers once per case and seed. A case is
a trajectory and what the loop is exposed to:

- ``scene``: the scene's torques;
- ``slow``, ``fast``: other frequencies and amplitudes (0.5 Hz at 1.25x, 2 Hz at 0.5x);
- ``offset``: two harmonics and a constant offset;
- ``disturbance``: the scene, and a torque step on the plant at 1 s that no model knows;
- ``noise``: the scene, with white noise on every signal the controllers measure; the
  internal-model controllers are told the noise and choose their horizon for it
  (jointplay.neural.control.noise_tuning; ``--undeclared-noise``: they are not told);
- ``delay``: the scene, with one sample of actuator delay;
- ``clearance <c>``: the scene's trajectory on a robot whose clearance joints have radial
  clearance c, with models identified on that robot.

It reports the median and the worst seed of every metric per controller and case
(``study.md``, ``study.csv``), checks the goals, and plots the statistics (``study_*.png``).
Model folders are kept under ``OUT/models`` and reused when the command is run again; runs go
through a process pool (``--workers``).
"""

from __future__ import annotations

from jointplay.neural.study.cases import (
    CASES,
    NOISE,
    Case,
    case_list,
    case_scene,
    declared,
    noise_levels,
    nominal_clearance,
)
from jointplay.neural.study.report import PAPER, goal_checks, plot_study, summarise, summary_table
from jointplay.neural.study.runs import (
    BASELINES,
    GOAL_METRICS,
    REPORTED,
    ensure_models,
)

__all__ = ["BASELINES", "CASES", "GOAL_METRICS", "NOISE", "PAPER", "REPORTED", "Case",
           "case_list", "case_scene", "declared", "ensure_models", "goal_checks",
           "noise_levels", "nominal_clearance", "plot_study", "summarise",
           "summary_table"]
