"""How far a run's numbers can be trusted: the run checked against a second run of the same
scene at tolerances 10x tighter.

For a method whose error scales with its tolerance, the tighter run's own error is about a
tenth of the first run's, so their difference estimates the first run's error (measured on
the default scene against a converged reference: within a factor 1.5 at every tolerance from
1e-6 / 1e-5 to 1e-10; ``tests/test_accuracy.py`` holds it to a factor 3).

Impact sequences are compared row by row in onset order: two rows agree when they are at the
same joint, their onsets are within :data:`ONSET_TOLERANCE` and their approach speeds within
:data:`SPEED_TOLERANCE` (relative). The agreement horizon must not be later than the one a
converged reference would give, although the tighter run is itself off (by about a tenth of
the first run's deviation, more for event times): so the check compares with these
tolerances times :data:`CHECK_MARGIN`, and puts the horizon one onset tolerance before the
first row that differs (never before the last row that agrees). Measured on the default
scene at rtol / atol from 1e-4 to 1e-10, with margin 0.5 the horizon came out later than the
converged reference's in three of ten settings, with 0.3 in none. From the first row that
differs on, every impact of the run is marked tolerance-sensitive: its count, timing and
peaks change with the tolerance.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from jointplay.results.records import Impacts, SimulationResult

# Two impact sequences agree while their rows are at the same joints, in the same order, with
# onsets within ONSET_TOLERANCE (s; a tenth of a typical steel impact's 0.1 ms) and approach
# speeds within SPEED_TOLERANCE (relative).
ONSET_TOLERANCE = 1e-5
SPEED_TOLERANCE = 0.01
# The self-check compares with these tolerances times CHECK_MARGIN (see the module docstring).
CHECK_MARGIN = 0.3
# How much tighter the check run is (rtol and atol alike).
TIGHTER = 10.0


@dataclass(frozen=True)
class Accuracy:
    """A run's accuracy statement (SI units): ``result.accuracy`` after ``simulate(verify=True)``.

    The run is compared with the same run at tolerances 10x tighter (the check); ``check_*``
    describe the check. :meth:`lines` says it in words.

    Attributes
    ----------
    rtol : float
        The run's relative tolerance.
    atol : float
        Its absolute tolerance.
    check_rtol : float
        The check's relative tolerance (NaN for a fixed-step method, which is checked at a
        10x smaller step).
    check_atol : float
        The check's absolute tolerance (NaN likewise).
    tip_error_estimate : float
        m, the largest difference of the tip position from the check over the samples.
    tip_velocity_error_estimate : float
        m/s, the same for the tip velocity.
    energy_residual : float
        J, the largest ``|balance|`` of the run.
    check_energy_residual : float
        J, the same for the check.
    dissipated : float
        J, the energy taken out by contact over the run.
    agreement_horizon : float
        s, both runs have the same impact sequence up to this time.
    agreed_impacts : int
        The run's impacts before the horizon.
    tolerance_sensitive : numpy.ndarray
        (m,) bool, per impact of the run: at or after the horizon.
    impacts : int
        The run's impacts.
    check_impacts : int
        The check's impacts.
    impacts_per_joint : dict of int to (int, int)
        Per clearance joint: (run, check) impact counts.
    t_end : float
        s, the end of the run.
    check_wall_s : float
        s, the wall time the check took.
    """

    rtol: float
    atol: float
    check_rtol: float
    check_atol: float
    tip_error_estimate: float  # m, max over the samples of |tip - tip of the tighter run|
    tip_velocity_error_estimate: float  # m/s, the same for the tip velocity
    energy_residual: float  # J, max |balance| of this run
    check_energy_residual: float  # J, the same for the tighter run
    dissipated: float  # J, energy taken out by contact over the run
    agreement_horizon: float  # s, both runs have the same impact sequence up to this time
    agreed_impacts: int  # impacts of this run before the horizon
    tolerance_sensitive: np.ndarray  # (m,) bool per impact of this run: at or after the horizon
    impacts: int
    check_impacts: int
    impacts_per_joint: dict[int, tuple[int, int]] = field(default_factory=dict)  # (run, check)
    t_end: float = math.nan
    check_wall_s: float = math.nan

    @property
    def energy_residual_fraction(self) -> float:
        """The run's energy residual as a fraction of the energy dissipated (NaN if none)."""
        return self.energy_residual / self.dissipated if self.dissipated > 0 else math.nan

    @property
    def whole_sequence_agrees(self) -> bool:
        return self.agreement_horizon >= self.t_end

    def attributes(self) -> dict[str, Any]:
        """The scalar fields, for a results file's attributes."""
        return {"rtol": self.rtol, "atol": self.atol, "check_rtol": self.check_rtol,
                "check_atol": self.check_atol, "tip_error_estimate": self.tip_error_estimate,
                "tip_velocity_error_estimate": self.tip_velocity_error_estimate,
                "energy_residual": self.energy_residual,
                "check_energy_residual": self.check_energy_residual,
                "dissipated": self.dissipated, "agreement_horizon": self.agreement_horizon,
                "agreed_impacts": self.agreed_impacts, "impacts": self.impacts,
                "check_impacts": self.check_impacts, "t_end": self.t_end,
                "check_wall_s": self.check_wall_s,
                "onset_tolerance": ONSET_TOLERANCE, "speed_tolerance": SPEED_TOLERANCE}

    def lines(self) -> list[str]:
        """The statement in plain words, a few lines for the run's summary."""
        against = ("a 10x smaller step" if math.isnan(self.check_rtol) else
                   f"rtol {self.check_rtol:.0e}, atol {self.check_atol:.0e}")
        out = [f"  accuracy (checked against the same run at {against}):",
               f"    tip position error about {self.tip_error_estimate:.2g} m, velocity "
               f"{self.tip_velocity_error_estimate:.2g} m/s (max over the samples)"]
        energy = (f"    energy balance residual {self.energy_residual:.2g} J "
                  f"({self.check_energy_residual:.2g} J in the check)")
        if self.dissipated > 0:
            energy += (f", {100 * self.energy_residual_fraction:.2g} % of the "
                       f"{self.dissipated:.4g} J dissipated")
        out.append(energy)
        if self.whole_sequence_agrees:
            out.append(f"    impact sequence: all {self.impacts} impacts agree with the check "
                       f"(same joints and order, onsets within {ONSET_TOLERANCE * 1e6:g} us, "
                       f"approach speeds within {100 * SPEED_TOLERANCE:g} %)")
            return out
        sensitive = int(np.count_nonzero(self.tolerance_sensitive))
        out.append(f"    impact sequence agrees with the check up to t = "
                   f"{self.agreement_horizon:.6g} s ({self.agreed_impacts} impacts; same joints "
                   f"and order, onsets within {ONSET_TOLERANCE * 1e6:g} us, approach speeds "
                   f"within {100 * SPEED_TOLERANCE:g} %); the {sensitive} later impacts are "
                   "tolerance-sensitive: their count, times and peaks change with the tolerance")
        differing = [f"impacts {self.impacts} (check: {self.check_impacts})"] \
            if self.impacts != self.check_impacts else []
        differing += [f"joint {j} {a} (check: {b})"
                      for j, (a, b) in self.impacts_per_joint.items() if a != b]
        if differing:
            out.append("    counts that differ: " + ", ".join(differing))
        return out


def _sequence_agreement(run: Impacts, check: Impacts, onset_tolerance: float,
                        speed_tolerance: float) -> int:
    """How many leading rows of the two impact tables agree (see the module docstring)."""
    n = min(len(run), len(check))
    for i in range(n):
        larger = max(abs(float(run.speed[i])), abs(float(check.speed[i])))
        if (int(run.joint[i]) != int(check.joint[i])
                or abs(float(run.time[i]) - float(check.time[i])) > onset_tolerance
                or abs(float(run.speed[i]) - float(check.speed[i])) > speed_tolerance * larger):
            return i
    return n


def agreement_horizon(run: Impacts, check: Impacts, t_end: float, *,
                      onset_tolerance: float = ONSET_TOLERANCE,
                      speed_tolerance: float = SPEED_TOLERANCE, lead: float = 0.0
                      ) -> tuple[float, int]:
    """(horizon in s, agreeing rows): the time up to which both tables hold the same impacts.

    The horizon is the earlier onset of the first row that differs (or that only one table
    has), less ``lead`` (but not before the last row that agrees); ``t_end`` when the whole
    sequences agree.
    """
    agreed = _sequence_agreement(run, check, onset_tolerance, speed_tolerance)
    following = [float(table.time[agreed]) for table in (run, check) if len(table) > agreed]
    if not following:
        return float(t_end), agreed
    last_agreed = float(run.time[agreed - 1]) if agreed else 0.0
    return max(min(following) - lead, last_agreed), agreed


def _max_distance(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.max(np.linalg.norm(a - b, axis=1))) if a.size else 0.0


def compare_runs(result: SimulationResult, check: SimulationResult, *, rtol: float,
                 atol: float, check_rtol: float, check_atol: float) -> Accuracy:
    """The accuracy statement of ``result`` from a tighter run ``check`` of the same scene."""
    return statement(
        RunRecord(result.tip_position, result.tip_velocity, result.impacts,
                  result.energy["balance"], float(result.energy["dissipated"][-1])),
        RunRecord(check.tip_position, check.tip_velocity, check.impacts,
                  check.energy["balance"], float(check.energy["dissipated"][-1])),
        clearance_joints=result.clearance_joints, t_end=float(result.t[-1]), rtol=rtol,
        atol=atol, check_rtol=check_rtol, check_atol=check_atol,
        check_wall_s=float(check.stats.get("wall_time_s", math.nan)))


@dataclass(frozen=True)
class RunRecord:
    """What the statement compares of a run, on the same output samples from t = 0 (a run
    stopped early has fewer: the two are compared where both have samples)."""

    tip_position: np.ndarray  # (N, 2) m
    tip_velocity: np.ndarray  # (N, 2) m/s
    impacts: Impacts
    energy_balance: np.ndarray  # (N,) J
    dissipated: float  # J, at the end


def statement(run: RunRecord, check: RunRecord, *, clearance_joints: Sequence[int],
              t_end: float, rtol: float, atol: float, check_rtol: float, check_atol: float,
              check_wall_s: float = math.nan) -> Accuracy:
    """The accuracy statement of ``run`` from ``check``, the same run at tighter settings
    (simulations, and the closed loops of :mod:`jointplay.neural.control.loop_accuracy`)."""
    horizon, agreed = agreement_horizon(run.impacts, check.impacts, t_end,
                                        onset_tolerance=ONSET_TOLERANCE * CHECK_MARGIN,
                                        speed_tolerance=SPEED_TOLERANCE * CHECK_MARGIN,
                                        lead=ONSET_TOLERANCE)
    sensitive = np.arange(len(run.impacts)) >= agreed
    per_joint = {int(j): (int(np.count_nonzero(run.impacts.joint == j)),
                          int(np.count_nonzero(check.impacts.joint == j)))
                 for j in clearance_joints}
    n = min(len(run.tip_position), len(check.tip_position))
    return Accuracy(
        rtol=rtol, atol=atol, check_rtol=check_rtol, check_atol=check_atol,
        tip_error_estimate=_max_distance(run.tip_position[:n], check.tip_position[:n]),
        tip_velocity_error_estimate=_max_distance(run.tip_velocity[:n],
                                                  check.tip_velocity[:n]),
        energy_residual=float(np.max(np.abs(run.energy_balance))),
        check_energy_residual=float(np.max(np.abs(check.energy_balance))),
        dissipated=run.dissipated,
        agreement_horizon=horizon, agreed_impacts=agreed, tolerance_sensitive=sensitive,
        impacts=len(run.impacts), check_impacts=len(check.impacts),
        impacts_per_joint=per_joint, t_end=t_end, check_wall_s=check_wall_s)
