"""Per-joint contact summaries read from the contact-phase table, never from output samples.

The largest output sample of the normal force is not the peak: an impact lasts microseconds
and a 1 ms output step falls anywhere in it (on the paper scene the sampled maximum was a
quarter of the true peak). So every summary here takes its peaks from the located columns of
:class:`~jointplay.results.records.Impacts`. Where those are NaN (a fixed-step run fills only the
onset columns, or a phase was not located), the peak is NaN and ``note`` says why; the
sampled maximum is kept beside it, under a name that says it is sampled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from jointplay.results.records import SimulationResult

FIXED_STEP = ("rk4", "radau")


@dataclass(frozen=True)
class JointContact:
    """What one clearance joint's contact phases add up to over a run (SI units)."""

    joint: int  # 1-based joint number
    impacts: int  # contact phases (onsets)
    max_approach_speed: float  # m/s, largest onset speed; NaN without impacts
    max_approach_speed_time: float  # s, its onset time
    peak_force: float  # N, largest located peak of the phases; 0 without contact; NaN: see note
    peak_force_time: float  # s
    max_penetration: float  # m, largest located penetration; 0 without contact; NaN: see note
    max_penetration_time: float  # s
    note: str | None  # why the peaks are not located (None: they are)
    sampled_peak_force: float  # N, largest output sample: NOT the peak (for comparison only)
    sampled_max_penetration: float  # m, largest output sample of max(0, delta)

    @property
    def located(self) -> bool:
        return self.note is None


def _argmax(values: np.ndarray, times: np.ndarray) -> tuple[float, float]:
    k = int(np.argmax(values))
    return float(values[k]), float(times[k])


def not_located_reason(result: SimulationResult) -> str:
    """Why a run's phase table has no peaks, in a few words."""
    if result.integrator in FIXED_STEP:
        return (f"not located: the fixed-step {result.integrator} run fills only the onset "
                "columns of the impact table")
    return "not located: the impact table of this run has no located peaks"


def joint_contact(result: SimulationResult, k: int) -> JointContact:
    """The summary of clearance joint number ``k`` (0-based column of the result)."""
    joint = int(result.clearance_joints[k])
    rows = result.impacts.for_joint(joint)
    sampled_force = float(np.max(result.normal_force[:, k])) if result.n_samples else 0.0
    sampled_pen = (max(0.0, float(np.max(result.penetration[:, k]))) if result.n_samples
                   else 0.0)
    nan = math.nan
    speed, speed_time = _argmax(rows.speed, rows.time) if len(rows) else (nan, nan)
    note: str | None = None
    if len(rows) == 0:
        if sampled_force > 0.0 or sampled_pen > 0.0:  # in contact, but no phase recorded
            force = pen = force_time = pen_time = nan
            note = "not located: contact without a recorded onset"
        else:  # never in contact: nothing to locate, the peak is zero
            force = pen = 0.0
            force_time = pen_time = nan
    elif np.isnan(rows.peak_force).any() or np.isnan(rows.max_penetration).any():
        force = pen = force_time = pen_time = nan
        note = not_located_reason(result)
    else:
        force, force_time = _argmax(rows.peak_force, rows.peak_force_time)
        pen, pen_time = _argmax(rows.max_penetration, rows.max_penetration_time)
    return JointContact(joint=joint, impacts=len(rows), max_approach_speed=speed,
                        max_approach_speed_time=speed_time, peak_force=force,
                        peak_force_time=force_time, max_penetration=pen,
                        max_penetration_time=pen_time, note=note,
                        sampled_peak_force=sampled_force, sampled_max_penetration=sampled_pen)


def joint_contacts(result: SimulationResult) -> list[JointContact]:
    """One summary per clearance joint, in the order of ``result.clearance_joints``."""
    return [joint_contact(result, k) for k in range(len(result.clearance_joints))]


def overall(values: list[float]) -> float:
    """The largest of per-joint values; NaN if any is NaN (an unknown could be the largest)."""
    if not values:
        return 0.0
    return math.nan if any(math.isnan(v) for v in values) else max(values)


__all__ = ["JointContact", "joint_contact", "joint_contacts", "not_located_reason", "overall"]
