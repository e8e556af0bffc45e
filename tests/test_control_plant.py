"""The plant the control metrics are measured on: its setting, the dense acceleration, and
the outer loop's start (fast checks)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from test_control import random_narx
from test_control_guard import linear_twin

from jointplay.neural.control.imc import training_box
from jointplay.neural.model.plant import PLANT_TOLERANCE, SUBSTEPS, control_plant
from jointplay.neural.study.control_run import ControllerSettings, compile_controller, imc_law
from jointplay.scene.definition import default_scene
from jointplay.sim import Stepper


def test_control_plant_tightens_the_tolerances_and_keeps_tighter_ones() -> None:
    scene = default_scene().with_run(integrator="cvodes")
    plant = control_plant(scene)
    assert (plant.run.integrator, plant.run.rtol, plant.run.atol) == (
        "bdf", PLANT_TOLERANCE, PLANT_TOLERANCE)
    tight = default_scene().with_run(rtol=1e-11, atol=1e-12)
    assert control_plant(tight) is tight


def test_dense_acceleration_ends_each_period_on_the_sample() -> None:
    """The last of the substeps is the sample itself: there the dense acceleration equals the
    one the stepper reports at the sample (the same state, the same held torque), and the
    state equals a stepper's without substeps to the integrator's tolerance."""
    scene = control_plant(default_scene().with_run(t_end=0.02))
    dense = Stepper(scene, substeps=SUBSTEPS)
    plain = Stepper(scene, model=dense.model)
    at_samples = []
    for k in range(20):
        u = np.array([0.01 * np.sin(k), -0.02])
        dense.step(u)
        plain.step(u)
        at_samples.append(dense.end_effector()["acceleration"])
        assert np.allclose(dense.x, plain.x, rtol=0, atol=1e-7)
    t, a = dense.dense_tip_acceleration()
    assert t.size == 20 * SUBSTEPS and np.all(np.diff(t) > 0)
    assert np.allclose(t[SUBSTEPS - 1::SUBSTEPS], 1e-3 * np.arange(1, 21), rtol=0, atol=1e-15)
    assert np.allclose(a[SUBSTEPS - 1::SUBSTEPS], np.array(at_samples), rtol=1e-12, atol=1e-9)
    # Between samples it is not a copy of the sample values (the journals fall and bounce).
    assert np.max(np.abs(a[::SUBSTEPS] - a[SUBSTEPS - 1::SUBSTEPS])) > 1e-3


def test_outer_loop_waits_then_starts_from_the_measured_history() -> None:
    base = random_narx(41)
    plant = {**base.context["plant"], "inner_loop": {"joints": [2, 3], "kp": [200.0, 200.0],
                                                     "kd": [5.0, 5.0]}}
    model = replace(base, context={**base.context, "plant": plant})
    settings = ControllerSettings(horizon=2, tracked=("q2", "q3"), engage=0.003)
    ctrl = compile_controller(model, settings, fallback=linear_twin(model))
    n = 10
    rng = np.random.default_rng(42)
    reference = rng.normal(0, 1e-4, (n, model.n_outputs))
    log: dict[str, list[np.ndarray]] = {"v": [], "y_pred": [], "flags": [], "states": []}
    law = imc_law(ctrl, reference, np.zeros((n, 2)), log)
    measured = [reference[k] + rng.normal(0, 1e-5, model.n_outputs) for k in range(n)]
    kp, kd = 200.0, 5.0
    for k in range(3):  # waiting: the inner PD alone, v = 0
        tau = law(k, measured[k])
        dev = measured[k] - reference[k]
        assert np.allclose(tau, -kp * dev[:2] - kd * dev[2:4], rtol=1e-12, atol=0)
        assert not np.any(log["v"][-1])
    law(3, measured[3])  # engaged: the models start from the last two measured deviations
    start = log["states"][-1]
    lo, hi = training_box(model, 0.0)
    ny = model.n_outputs
    for lag, k in enumerate((3, 2)):
        expected = np.clip(measured[k] - reference[k], lo[:ny], hi[:ny])
        assert np.array_equal(start[lag * ny:(lag + 1) * ny], expected)


def test_acceleration_split_adds_in_squares_to_the_rms_after_the_transient() -> None:
    """RMS |Δa| after the transient = sqrt(sample-mean part² + within-sample part²); an
    error constant over each period has no within-sample part, and a zigzag of zero mean
    inside each period no sample-mean part; a run without dense output gives NaN."""
    from jointplay.neural.control.loop import Run
    from jointplay.neural.control.metrics import SPLIT_METRICS, run_metrics

    rng = np.random.default_rng(3)
    n, nj, transient = 40, 2, 7
    y = np.zeros((n + 1, 2 * nj + 6))
    reference = np.zeros_like(y)
    t = np.arange(n + 1) * 1e-3
    dense_t = (np.arange(n * SUBSTEPS) + 1) * 1e-3 / SUBSTEPS
    dense_reference = rng.normal(size=(n * SUBSTEPS + 1, 2))

    def metrics(error: np.ndarray) -> dict[str, float]:
        run = Run("r", t, y, np.zeros((n + 1, nj)), np.zeros((n + 1, nj)), 0, 0.0,
                  dense_t=dense_t, dense_acceleration=dense_reference[1:] + error)
        return run_metrics(run, reference, nj, transient, dense_reference)

    mean_key, within_key = SPLIT_METRICS
    mixed = metrics(rng.normal(size=(n * SUBSTEPS, 2)))
    assert np.hypot(mixed[mean_key], mixed[within_key]) == pytest.approx(
        mixed["rms_acceleration_after"], rel=1e-12)
    assert mixed[mean_key] > 0 and mixed[within_key] > 0
    level = np.repeat(rng.normal(size=(n, 2)), SUBSTEPS, axis=0)
    flat = metrics(level)
    assert flat[within_key] == pytest.approx(0.0, abs=1e-14)
    assert flat[mean_key] == pytest.approx(
        np.sqrt(np.mean(np.sum(level[transient * SUBSTEPS:] ** 2, axis=1))), rel=1e-12)
    zigzag = np.tile(np.where(np.arange(SUBSTEPS) % 2 == 0, 1.0, -1.0)[:, None] * [3.0, 4.0],
                     (n, 1))
    inside = metrics(zigzag)
    assert inside[mean_key] == pytest.approx(0.0, abs=1e-14)
    assert inside[within_key] == pytest.approx(5.0, rel=1e-12)
    plain = run_metrics(Run("r", t, y, np.zeros((n + 1, nj)), np.zeros((n + 1, nj)), 0, 0.0),
                        reference, nj, transient)
    assert all(np.isnan(plain[k]) for k in SPLIT_METRICS)
