"""A mechanism run's accuracy statement: the same run at tolerances 10x tighter (at a step
10x smaller for ``rk4`` and ``radau``).

As for the serial arms (:mod:`jointplay.results.accuracy`), the tighter run's own error is
about a tenth of the run's, so their difference estimates the run's error. A mechanism with a
clearance joint is chaotic once impacts follow each other closely: the difference grows
from the integration error to the size of the clearance. The statement says from when: the
*agreement horizon* (both runs have the same impacts, at the same joints, with onsets and
approach speeds within the arms' tolerances, up to it) and the time from which the sliders'
positions (and the journals' eccentricities) of the two runs differ by more than
:data:`POSITION_TOLERANCE`. Before it, trajectories can be compared; after it, only their
statistics (impact rates, force distributions, orbits' extent) mean anything.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.model import MechanismModel
from jointplay.mechanism.simulate import MechanismResult, simulate_mechanism
from jointplay.results.accuracy import (
    CHECK_MARGIN,
    ONSET_TOLERANCE,
    SPEED_TOLERANCE,
    TIGHTER,
    agreement_horizon,
)

# m: positions of two runs closer than this agree (a micrometre: the slider-crank's target for
# its first revolution, a hundredth of its 0.1 mm clearance variant's clearance).
POSITION_TOLERANCE = 1e-6


@dataclass(frozen=True)
class MechanismAccuracy:
    setting: str  # how this run was integrated ("1e-09 / 1e-09", "rk4 step 1e-07 s")
    check_setting: str  # the tighter run's ("rtol / atol 1e-10 / 1e-10", "rk4 step 1e-08 s")
    position_error: float  # m, max over samples before `departs` (all samples if never)
    velocity_error: float  # m/s, the same for the rates of the positions
    departs: float | None  # s, first sample where positions differ by > POSITION_TOLERANCE
    final_difference: float  # m, max position difference over the whole run
    agreement_horizon: float  # s
    agreed_impacts: int
    impacts: int
    check_impacts: int
    energy_residual: float  # J, max |balance| of this run
    t_end: float
    # contact statistics of this run and of the tighter one after `departs` (see
    # MechanismResult.contact_statistics); empty when the runs never depart
    statistics: tuple[dict[str, float], ...] = ()

    def lines(self) -> list[str]:
        out = [f"accuracy (against the same run at {self.check_setting}; this run "
               f"{self.setting}):"]
        remedy = "shorten the step" if "step" in self.setting else "tighten the tolerances"
        if self.departs is None:
            out.append(f"  positions (sliders, journals) within {self.position_error:.2g} m "
                       f"and rates within {self.velocity_error:.2g} m/s over the whole run "
                       f"({self.t_end:g} s)")
        else:
            out.append(f"  positions within {self.position_error:.2g} m up to "
                       f"{self.departs:.6g} s; from there the two runs differ by more than "
                       f"{POSITION_TOLERANCE:g} m (by up to {self.final_difference:.2g} m by "
                       f"{self.t_end:g} s): after it this run's trajectory is not known to "
                       f"{POSITION_TOLERANCE:g} m; compare statistics, or {remedy}")
        if self.agreement_horizon >= self.t_end:
            out.append(f"  impacts: the same {self.impacts} in both runs")
        else:
            out.append(f"  impacts: the first {self.agreed_impacts} agree (up to "
                       f"{self.agreement_horizon:.6g} s); {self.impacts} here, "
                       f"{self.check_impacts} in the tighter run")
        if self.statistics:
            mine, other = self.statistics
            forces = (f", median peak force {mine['median_peak_force']:.3g} / "
                      f"{other['median_peak_force']:.3g} N, largest "
                      f"{mine['largest_peak_force']:.3g} / {other['largest_peak_force']:.3g} N"
                      if np.isfinite(mine["largest_peak_force"]) else "")  # located: bdf only
            out.append(f"  after {self.departs:.6g} s, this run / the tighter one: "
                       f"{mine['impacts']:.0f} / {other['impacts']:.0f} impacts, in contact "
                       f"{100 * mine['contact_fraction']:.0f} % / "
                       f"{100 * other['contact_fraction']:.0f} % of the time{forces}")
        out.append(f"  energy balance closes to {self.energy_residual:.2g} J")
        return out


def _positions(result: MechanismResult) -> np.ndarray:
    """Every length-valued coordinate (sliders) and eccentricity component, per sample."""
    columns = [result.x[:, k] for k, unit in enumerate(result.units) if unit == "m"]
    columns += [result.eccentricity[:, j, k] for j in range(len(result.cut_joints))
                for k in range(2)]
    return np.stack(columns, axis=1) if columns else np.zeros((len(result.t), 0))


def _rates(result: MechanismResult) -> np.ndarray:
    n = len(result.coordinates)
    columns = [result.x[:, n + k] for k, unit in enumerate(result.units) if unit == "m"]
    return np.stack(columns, axis=1) if columns else np.zeros((len(result.t), 0))


def compare(result: MechanismResult, check: MechanismResult) -> MechanismAccuracy:
    diff = np.max(np.abs(_positions(result) - _positions(check)), axis=1, initial=0.0)
    rate_diff = np.max(np.abs(_rates(result) - _rates(check)), axis=1, initial=0.0)
    over = np.flatnonzero(diff > POSITION_TOLERANCE)
    upto = int(over[0]) if over.size else len(diff)
    horizon, agreed = agreement_horizon(
        result.impacts, check.impacts, float(result.t[-1]),
        onset_tolerance=CHECK_MARGIN * ONSET_TOLERANCE,
        speed_tolerance=CHECK_MARGIN * SPEED_TOLERANCE, lead=ONSET_TOLERANCE)
    departs = float(result.t[upto]) if over.size else None
    statistics = () if departs is None else (result.contact_statistics(departs),
                                             check.contact_statistics(departs))
    return MechanismAccuracy(
        setting=_setting(result, False), check_setting=_setting(check, True),
        position_error=float(np.max(diff[:upto], initial=0.0)),
        velocity_error=float(np.max(rate_diff[:upto], initial=0.0)),
        departs=departs, statistics=statistics,
        final_difference=float(np.max(diff, initial=0.0)),
        agreement_horizon=horizon, agreed_impacts=agreed, impacts=len(result.impacts),
        check_impacts=len(check.impacts),
        energy_residual=float(np.max(np.abs(result.energy_residual))),
        t_end=float(result.t[-1]))


def _setting(result: MechanismResult, named: bool) -> str:
    """How a run was integrated, as the statement prints it (the tolerances ``named`` in the
    tighter run's, where they are read first)."""
    if result.step is not None:
        return f"{result.integrator} step {result.step:g} s"
    return f"{'rtol / atol ' if named else ''}{result.rtol:g} / {result.atol:g}"


def with_accuracy(result: MechanismResult, scene: MechanismScene,
                  model: MechanismModel | None = None) -> MechanismResult:
    """The result with its statement (the tighter run is simulated here)."""
    run = scene.run
    if run.integrator == "bdf":
        tighter = scene.with_run(rtol=run.rtol / TIGHTER, atol=run.atol / TIGHTER,
                                 max_steps=run.max_steps * 10)
    else:
        tighter = scene.with_run(step=run.step / TIGHTER)
    check = simulate_mechanism(tighter, model=model)
    result.accuracy = compare(result, check)
    return result
