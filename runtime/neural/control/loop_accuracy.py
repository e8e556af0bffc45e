"""How far a closed-loop run's numbers can be trusted: the run checked against the same loop
with the plant (and the ideal reference it tracks) integrated at tolerances 10x tighter, as
``simulate(..., verify=True)`` checks a simulation (:mod:`jointplay.results.accuracy`).

The controllers act on the plant's outputs, so the check is a closed loop too: the difference
between the two runs is the integration error of the whole loop as the controllers see it.
The statement has the same parts as a simulation's: the estimated largest error of the end
effector's position (and velocity), the energy balance residual of the plant against the
energy its contacts dissipated, and the agreement horizon of the impact sequence (up to which
both runs strike the same joints in the same order, onsets and approach speeds within the
tolerances of :mod:`jointplay.results.accuracy`). ``control-study --verify`` records it per
case and controller; the same columns as ``sweep --verify``.
"""

from __future__ import annotations

import statistics
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from jointplay.neural.control.loop import Run
    from jointplay.results.accuracy import Accuracy
    from jointplay.scene.definition import Scene

# The columns a verified run adds to its row (study.csv and study.json): the first three are
# the sweep's (jointplay.sweep.metrics.ACCURACY_METRICS); the energy dissipated puts the
# residual in proportion, and the note says where the two runs did not end alike.
ACCURACY_COLUMNS = ("tip_error_estimate", "agreement_horizon", "accuracy_energy_residual",
                    "energy_dissipated", "accuracy_note")


def plant_tolerances(scene: Scene) -> tuple[float, float]:
    """(rtol, atol) of the plant every closed loop of ``scene`` runs on."""
    from jointplay.neural.model.plant import control_plant

    run = control_plant(scene).run
    return run.rtol, run.atol


def check_tolerance(scene: Scene) -> float:
    """rtol = atol of the check's plant: 10x tighter than the tighter of the run's two."""
    from jointplay.results.accuracy import TIGHTER

    return min(plant_tolerances(scene)) / TIGHTER


def loop_accuracy(run: Run, check: Run, *, scene: Scene, check_tol: float) -> Accuracy:
    """The accuracy statement of the closed-loop ``run`` from ``check``, the same loop with
    the plant at rtol = atol = ``check_tol``; compared where both have samples (a loop
    stopped as diverged has fewer, and ``accuracy_note`` says so)."""
    from jointplay.results.accuracy import statement

    nj = len(scene.robot.moving_joints)
    rtol, atol = plant_tolerances(scene)
    return statement(_record(run, nj), _record(check, nj),
                     clearance_joints=scene.robot.clearance_joints, t_end=float(run.t[-1]),
                     rtol=rtol, atol=atol, check_rtol=check_tol, check_atol=check_tol,
                     check_wall_s=check.seconds)


def _record(run: Run, nj: int) -> Any:
    from jointplay.results.accuracy import RunRecord
    from jointplay.results.records import Impacts

    rows = run.impact_rows
    impacts = Impacts(time=np.array([r[0] for r in rows], dtype=float),
                      joint=np.array([r[1] for r in rows], dtype=int),
                      speed=np.array([r[2] for r in rows], dtype=float),
                      eccentricity=np.array([[r[3], r[4]] for r in rows],
                                            dtype=float).reshape(-1, 2))
    tip = 2 * nj
    return RunRecord(run.y[:, tip:tip + 2], run.y[:, tip + 2:tip + 4], impacts,
                     run.energy_balance, run.dissipated)


def accuracy_columns(accuracy: Accuracy, run: Run, check: Run) -> dict[str, Any]:
    """The columns of :data:`ACCURACY_COLUMNS` for one verified run."""
    note = ""
    if run.diverged != check.diverged or run.t.size != check.t.size:
        def end(r: Run) -> str:
            return (f"stopped at t = {r.t[-1]:.3f} s ({r.diverged})" if r.diverged
                    else "ran to the end")
        note = (f"the run {end(run)}, the check {end(check)}: compared over "
                f"{min(run.t.size, check.t.size)} samples")
    return {"tip_error_estimate": accuracy.tip_error_estimate,
            "agreement_horizon": accuracy.agreement_horizon,
            "accuracy_energy_residual": accuracy.energy_residual,
            "energy_dissipated": accuracy.dissipated, "accuracy_note": note}


def accuracy_lines(rows: Sequence[dict[str, Any]], cases: Sequence[Any],
                   check_tol: float) -> list[str]:
    """study.md's accuracy table: per case and controller, over the seeds, the largest
    estimated tip error, the earliest agreement horizon and the largest energy residual."""
    verified = [r for r in rows if "tip_error_estimate" in r]
    if not verified:
        return []
    lines = [f"Accuracy (each run checked against the same loop with the plant at rtol = atol "
             f"= {check_tol:.0e}, `--verify`; over the seeds: the largest tip error estimate "
             "and energy residual, the earliest agreement horizon of the impact sequence):",
             "", "| case | controller | runs | tip error estimate m | agreement horizon s "
             "| energy residual J | residual / dissipated |", "|---|---|---:|---:|---:|---:|---:|"]
    notes = []
    for case in cases:
        mine = [r for r in verified if r["case"] == case.name]
        for name in dict.fromkeys(r["controller"] for r in mine):
            runs = [r for r in mine if r["controller"] == name]
            residual = max(runs, key=lambda r: r["accuracy_energy_residual"])
            fractions = [r["accuracy_energy_residual"] / r["energy_dissipated"]
                         for r in runs if r["energy_dissipated"] > 0]
            fraction = f"{100 * max(fractions):.3g} %" if fractions else "-"
            lines.append(
                f"| {case.name} | {name} | {len(runs)} | "
                f"{max(r['tip_error_estimate'] for r in runs):.2g} | "
                f"{min(r['agreement_horizon'] for r in runs):.4g} | "
                f"{residual['accuracy_energy_residual']:.2g} | {fraction} |")
            notes += [f"- {case.name}, {name}, seed {r['seed']}: {r['accuracy_note']}"
                      for r in runs if r["accuracy_note"]]
    median = statistics.median(r["tip_error_estimate"] for r in verified)
    lines += ["", f"Median tip error estimate over all {len(verified)} runs: {median:.2g} m."]
    if notes:
        lines += ["", "Runs whose check ended differently (compared where both have "
                  "samples):", "", *notes]
    return [*lines, ""]


__all__ = ["ACCURACY_COLUMNS", "accuracy_columns", "accuracy_lines", "check_tolerance",
           "loop_accuracy", "plant_tolerances"]
