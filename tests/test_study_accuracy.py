"""The closed loops' accuracy statement (``control-study --verify``): the stepped plant's energy
balance against the conservation law, the statement of the baselines' loops against a
converged loop, and (slow, on the session's identified model) a tiny study's files."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from jointplay.scene.definition import default_scene

SHORT = 0.15  # s of the default scene: its release impacts and the first swing


def test_stepper_energy_balance_counts_the_added_torque() -> None:
    """The balance closes with a torque added on every joint (its work counted): at rtol =
    atol = 1e-9 to 1e-6 of the work done, although that work is 2.4x the scene's own."""
    from jointplay.sim import Stepper

    scene = default_scene().with_run(t_end=SHORT, integrator="bdf", rtol=1e-9, atol=1e-9)
    free, pushed = Stepper(scene), Stepper(scene)
    added = np.ones(len(pushed.model.torque_joints))
    for _ in range(scene.run.n_outputs):
        free.step(np.zeros_like(added))
        pushed.step(added)
    for stepper in (free, pushed):
        balance = stepper.energy_balance()
        assert balance.shape == (scene.run.n_outputs + 1,) and balance[0] == 0.0
        assert np.max(np.abs(balance)) < 1e-6 * stepper.work
    assert pushed.work > 2 * free.work  # the added torque's work is in it


@pytest.fixture(scope="module")
def baseline_loops() -> tuple[list[dict[str, Any]], dict[str, Any], dict[str, Any], Any]:
    """The study's baseline loops on the default scene's first 0.15 s: the verified rows,
    the loops themselves (the plant at the study's tolerance) and the converged loops (the
    plant at rtol = atol = 1e-12)."""
    from jointplay.neural.control.imc import ControllerSettings
    from jointplay.neural.study.comparison import compare
    from jointplay.neural.study.control_study import case_list, case_scene, nominal_clearance
    from jointplay.neural.study.runs import (
        BASELINES,
        STUDY_JOBS,
        _dummy_model,
        _run_unit,
        study_engagement,
    )

    scene = default_scene().with_run(t_end=SHORT)
    case = case_list(scene, ["scene"], (), nominal_clearance(scene))[0]
    case_run = case_scene(scene, case)
    settings = ControllerSettings()
    STUDY_JOBS.clear()
    STUDY_JOBS.append((case, case_run, None, settings, None, True))
    try:
        rows = _run_unit(0)
    finally:
        STUDY_JOBS.clear()

    def loops(tolerance: float | None) -> dict[str, Any]:
        return compare(case_run, _dummy_model(case_run), settings, controllers=BASELINES,
                       analyse=False, conditions=case.conditions, plant_tolerance=tolerance,
                       settle_after=study_engagement(settings, case_run.run.output_step)).runs
    return rows, loops(None), loops(1e-12), case_run


def test_study_rows_state_each_loops_accuracy(
        baseline_loops: tuple[list[dict[str, Any]], dict[str, Any], dict[str, Any], Any]
) -> None:
    """Per controller: the tip error estimate within a factor 3 of the error against the
    converged loop, the agreement horizon never later than the true one (the converged
    loop's impacts at the stated tolerances), the energy residual a small part of the
    dissipation."""
    from jointplay.neural.control.loop_accuracy import ACCURACY_COLUMNS, _record
    from jointplay.results.accuracy import agreement_horizon

    rows, runs, converged, scene = baseline_loops
    assert [r["controller"] for r in rows] == ["open loop", "PD", "computed torque"]
    nj = len(scene.robot.moving_joints)
    tip = slice(2 * nj, 2 * nj + 2)
    for row in rows:
        assert set(ACCURACY_COLUMNS) <= set(row) and row["accuracy_note"] == ""
        run, reference = runs[row["controller"]], converged[row["controller"]]
        true_error = float(np.max(np.linalg.norm(run.y[:, tip] - reference.y[:, tip], axis=1)))
        assert true_error / 3 <= row["tip_error_estimate"] <= 3 * true_error, row
        truth, _ = agreement_horizon(_record(run, nj).impacts, _record(reference, nj).impacts,
                                     SHORT)
        assert row["agreement_horizon"] <= truth, row
        assert row["energy_dissipated"] > 0
        assert row["accuracy_energy_residual"] < 1e-4 * row["energy_dissipated"], row


@pytest.mark.slow
def test_control_study_verify_writes_the_accuracy_per_run(
        tmp_path: Path, identified: tuple[Path, Any, Any]) -> None:
    """``control-study --verify`` on a tiny study (one seed, the scene case, 0.15 s): every
    row of study.csv and study.json carries the accuracy columns, study.md the table."""
    from jointplay.cli import main
    from jointplay.neural.control.loop_accuracy import ACCURACY_COLUMNS

    folder, narx, _ = identified
    text = (Path(__file__).parents[1] / "scenes" / "paper_4dof.toml").read_text()
    scene_file = tmp_path / "short.toml"
    scene_file.write_text(text.replace("t_end = 2.0 ", f"t_end = {SHORT} "))
    joint = default_scene().robot.joints[1]
    seed = narx.context["training"]["seed"]
    out = tmp_path / "study"
    # The session's model, where the study looks for it: not identified again.
    size = joint.bearing_radius - joint.journal_radius
    shutil.copytree(folder, out / "models" / f"{size * 1e6:g}um" / f"seed{seed}")
    assert main(["control-study", str(scene_file), "--out", str(out), "--seeds", "1",
                 "--first-seed", str(seed), "--cases", "scene", "--workers", "1", "--quiet",
                 "--verify", "--preset", "paper"]) in (0, 3)
    with (out / "study.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    stored = json.loads((out / "study.json").read_text())["rows"]
    assert {r["controller"] for r in rows} == {"open loop", "PD", "computed torque",
                                               "ARX-IMC", "LPV-ARX-IMC", "neural IMC"}
    for row, kept in zip(rows, stored, strict=True):
        assert all(name in row for name in ACCURACY_COLUMNS)
        assert 0 < float(row["tip_error_estimate"]) < 1e-6, row
        assert 0 < float(row["agreement_horizon"]) <= SHORT
        assert 0 <= kept["accuracy_energy_residual"] < 1e-4 * kept["energy_dissipated"]
    md = (out / "study.md").read_text()
    assert "Accuracy (each run checked" in md and "| scene | neural IMC | 1 |" in md


def test_a_check_that_ends_differently_is_compared_where_both_ran() -> None:
    """A loop stopped as diverged in only one of the two runs: the estimate covers the
    samples both have, and the note says where each ended."""
    from jointplay.neural.control.loop import Run
    from jointplay.neural.control.loop_accuracy import accuracy_columns, loop_accuracy

    scene = default_scene().with_run(t_end=0.004)
    nj = len(scene.robot.moving_joints)
    t = np.arange(5) * 1e-3
    y = np.zeros((5, 2 * nj + 6))
    y[:, 2 * nj] = [0.0, 1e-6, 2e-6, 3e-6, 4e-6]
    zero = np.zeros((5, nj))
    run = Run("PD", t, y, zero, zero, 0, 0.1, energy_balance=np.zeros(5), dissipated=1.0)
    shifted = y[:3].copy()
    shifted[:, 2 * nj] += 5e-7
    check = Run("PD", t[:3], shifted, zero[:3], zero[:3], 0, 0.1,
                diverged="end-effector error above the bound", energy_balance=np.zeros(3),
                dissipated=1.0)
    accuracy = loop_accuracy(run, check, scene=scene, check_tol=1e-10)
    columns = accuracy_columns(accuracy, run, check)
    assert columns["tip_error_estimate"] == pytest.approx(5e-7)
    assert columns["agreement_horizon"] == pytest.approx(0.004)
    assert "the run ran to the end, the check stopped at t = 0.002 s" in columns["accuracy_note"]
    assert "compared over 3 samples" in columns["accuracy_note"]
