"""Identification never fails silently: an input too small to identify and runs too short for
the free-run windows are warned about; a free run that runs away or a training loss that goes
NaN is repaired, and the repair recorded. Synthetic linear plants (fast, seeded)."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np
import pytest

from jointplay.neural.identify.pipeline import (
    MIN_INPUT_SHARE,
    IdentifyConfig,
    Trajectory,
    data_warnings,
    input_names,
    output_names,
)

JOINTS = (2, 3)


def _names() -> dict[str, Any]:
    out, out_units = output_names(JOINTS)
    inp, inp_units = input_names(JOINTS)
    return {"output_names": out, "output_units": out_units, "input_names": inp,
            "input_units": inp_units}


def _trajectory(rng: np.random.Generator, split: str, n: int, input_gain: float) -> Trajectory:
    """One run of a stable linear plant (10 outputs, 2 inputs; the same plant in every run)
    driven by the input ``v`` (its effect scaled by ``input_gain``) and by a disturbance the
    input does not explain."""
    ny, nu = 10, 2
    plant = np.random.default_rng(0)
    a = 0.9 * np.eye(ny) + 0.01 * plant.standard_normal((ny, ny))
    b = plant.standard_normal((ny, nu))
    v = np.repeat(rng.standard_normal((n // 10 + 1, nu)), 10, axis=0)[:n]
    w = 0.1 * rng.standard_normal((n, ny))
    y = np.zeros((n, ny))
    for k in range(n - 1):
        y[k + 1] = a @ y[k] + input_gain * b @ v[k] + w[k]
    return Trajectory(split=split, family="multisine", seed=0, t=np.arange(n) * 1e-3, y=y,
                      r=np.zeros_like(y), v=v, tau_base=np.zeros((n, nu)),
                      tau_inner=np.zeros((n, nu)))


@pytest.mark.parametrize("gain, warned", [(1.0, False), (1e-9, True)])
def test_too_small_excitation_is_warned_about(gain: float, warned: bool) -> None:
    rng = np.random.default_rng(3)
    train = [_trajectory(rng, "train", 600, gain) for _ in range(3)]
    validation = [_trajectory(rng, "validation", 600, gain)]
    config = IdentifyConfig(duration=0.6, window=100)
    warnings = data_warnings(train, validation, 0, config, _names(), 1e-3)
    assert any("too small to identify" in w for w in warnings) is warned
    assert MIN_INPUT_SHARE > 0


def test_too_short_duration_is_warned_about() -> None:
    rng = np.random.default_rng(4)
    train = [_trajectory(rng, "train", 200, 1.0)]
    validation = [_trajectory(rng, "validation", 200, 1.0)]
    config = IdentifyConfig(duration=0.2, window=200)
    warnings = data_warnings(train, validation, 50, config, _names(), 1e-3)
    assert any("--duration 0.2 s leaves 0.15 s" in w for w in warnings)
    long_enough = IdentifyConfig(duration=0.2, window=100)
    assert not any("--duration" in w
                   for w in data_warnings(train, validation, 50, long_enough, _names(), 1e-3))


# ---- training repairs ---------------------------------------------------------------------------

def _network(config: IdentifyConfig) -> tuple[Any, Any, Any]:
    torch = pytest.importorskip("torch")
    from jointplay.neural.identify.training import _Network, _training_data

    rng = np.random.default_rng(5)
    train = [_trajectory(rng, "train", 200, 1.0) for _ in range(2)]
    validation = [_trajectory(rng, "validation", 100, 1.0)]
    data = _training_data(train, validation, config, _names(), 1e-3)
    torch.manual_seed(0)
    return torch, _Network(torch, config, data), data


def test_runaway_free_run_start_is_shrunk_and_recorded() -> None:
    from jointplay.neural.identify.training import _stabilise_start

    config = IdentifyConfig(hidden=(6,), window=20, transient=0.0)
    torch, net, data = _network(config)
    dvw, uvw, wvw = net.windows(data.validation_segments, config.window)

    def validate() -> float:
        with torch.no_grad():
            return float(net.sim_loss(dvw, uvw, wvw))

    linear = validate()  # the network starts at the linear fit (residual x 0.01)
    with torch.no_grad():  # a residual that makes the free run explode
        net.net[-1].weight.mul_(1e3)
    runaway = validate()
    assert not runaway <= 10 * linear
    repairs: list[dict[str, Any]] = []
    _stabilise_start(torch, net, validate, repairs)
    assert len(repairs) == 1 and repairs[0]["cured"]
    assert "runs away" in repairs[0]["problem"] and "residual shrunk" in repairs[0]["action"]
    assert validate() <= 10 * linear
    # A start that is already stable is left alone, and nothing is recorded.
    before = validate()
    _stabilise_start(torch, net, validate, repairs)
    assert len(repairs) == 1 and validate() == before


def test_nan_free_run_phase_is_retried_and_reported(monkeypatch: pytest.MonkeyPatch) -> None:
    import jointplay.neural.identify.training as training

    config = IdentifyConfig(hidden=(6,), window=40, transient=0.0, multi_step_iterations=2)
    torch, net, data = _network(config)
    calls: list[tuple[int, float, float]] = []

    def attempt(torch: Any, net: Any, data: Any, config: IdentifyConfig, history: Any,
                bar: Any, length: int, lr: float, penalty: float, validate: Any) -> str:
        calls.append((length, lr, penalty))
        return "nonfinite" if lr == 1.0 else "patience"  # the first attempt goes NaN

    monkeypatch.setattr(training, "_free_run_attempt", attempt)
    history: dict[str, list[Any]] = {}
    training._free_run_phase(torch, net, data, config, history, None)
    assert calls == [(40, 1.0, 0.0), (5, 0.1, 0.0), (20, 0.1, 0.0), (40, 0.1, 0.0)]
    (repair,) = history["repairs"]
    assert repair["cured"] and "not finite" in repair["problem"]
    assert "L-BFGS step 0.1" in repair["action"] and "5, 20, 40" in repair["action"]

    calls.clear()
    monkeypatch.setattr(training, "_free_run_attempt",
                        lambda *args, **kwargs: "nonfinite")  # never cured
    history = {}
    training._free_run_phase(torch, net, data, config, history, None)
    assert len(history["repairs"]) == len(training.FREE_RUN_ATTEMPTS)
    assert not any(r["cured"] for r in history["repairs"])
    assert "stopped there" in history["repairs"][-1]["action"]


def test_report_names_every_repair() -> None:
    from jointplay.neural.identify.evaluation import _repair_lines

    metrics = {"training_history": {"repairs": [
        {"phase": "free-run", "problem": "training loss not finite (attempt 1, L-BFGS step 1)",
         "action": "restored the best state and retried", "cured": True}]}}
    text = "\n".join(_repair_lines(metrics))
    assert "training loss not finite" in text and "(cured)" in text
    assert "no repair was needed" in "\n".join(_repair_lines({"training_history": {}}))


def _issue_metrics() -> dict[str, Any]:
    """metrics.json as the `best` preset wrote it for the paper scene: the network kept at
    alpha = 0 in closed loop (its LPV-ARX base saved), that base diverging in free run on 6
    of 10 test outputs, and ARX the lowest free-run loss."""
    outputs = ["q2", "q3", "dq2", "dq3", "tip_x", "tip_y", "tip_vx", "tip_vy", "tip_ax",
               "tip_ay"]
    nrmse = [0.5, 0.6, 2e5, float("inf"), 3e3, 0.7, 1e4, 5e6, 0.9, 4e8]
    return {
        "outputs": outputs,
        "test": {"narx": {"free_run": {"nrmse": nrmse}}},
        "free_run_loss": {"window": 200, "scheduling": "x",
                          "validation": {"model": 9.1, "arx": 0.31, "lpv_arx": 9.1},
                          "test": {"model": 12.0, "arx": 0.52, "lpv_arx": 12.0}},
        "residual": {"alpha": 0.0, "closed_loop": {
            "chosen": "alpha=0", "alpha": 0.0, "margin": 0.02, "best_other": "alpha=0.5",
            "score_by_candidate": {"alpha=0": 1.0, "alpha=0.5": 1.04, "ARX twin": 1.31}}},
    }


def test_report_leads_with_the_choice_in_the_terms_of_its_tables() -> None:
    """The report's head: the controller to use, the criterion with its scores, and what the
    tables below say of the same models (divergence counted as the tables print it, the
    `best` column named), before any table."""
    from jointplay.neural.identify.recommendation import choice_lines

    head = "\n".join(choice_lines(_issue_metrics(), lpv_base=True))
    assert head.startswith("## The choice\n\n**Controller to use: LPV-ARX-IMC")
    assert "alpha=0: 1x, alpha=0.5: 1.04x, ARX twin: 1.31x" in head
    assert "The saved model is the LPV-ARX base (alpha = 0)" in head
    # 2e5, inf, 3e3, 1e4, 5e6, 4e8: the six the tables print as "diverges"
    assert ("diverges on 6 of 10 outputs (dq2, dq3, tip_x, tip_vx, tip_vy, tip_ay)"
            in head)
    assert "(the `best` column) is ARX on the validation runs; ARX on the test runs" in head
    assert "Free run is not the criterion here" in head
    assert "|" not in head  # no table in the lead


def test_report_lead_agrees_with_a_network_that_wins_in_free_run() -> None:
    """Chosen on the free-run criterion and lowest in the `best` column everywhere: the lead
    says so and does not claim another model ranks first."""
    from jointplay.neural.identify.recommendation import choice_lines

    metrics = _issue_metrics()
    metrics["test"]["narx"]["free_run"]["nrmse"] = [0.5] * 10
    metrics["free_run_loss"]["validation"] = {"model": 0.2, "arx": 0.3, "lpv_arx": 0.25}
    metrics["free_run_loss"]["test"] = {"model": 0.4, "arx": 0.5, "lpv_arx": 0.45}
    metrics["residual"] = {"alpha": 1.0, "free_run_loss": 0.2, "free_run_loss_arx": 0.3}
    head = "\n".join(choice_lines(metrics, lpv_base=False))
    assert "**Controller to use: neural IMC, on the free-run criterion" in head
    assert "Decided by the free-run loss on the validation runs" in head
    assert "diverges" not in head and "another model first" not in head
    assert "the saved model on the validation runs; the saved model on the test runs" in head


# ---- the LPV-ARX baseline -----------------------------------------------------------------------

def _scheduled_run(rng: np.random.Generator, n: int) -> Trajectory:
    """A plant whose input gain follows the arm's configuration (b(k) = b (1 + 0.8 cos q2)),
    as a joint's response to torque follows the inverse inertia, with q2 sweeping."""
    ny, nu = 10, 2
    plant = np.random.default_rng(0)
    a = 0.9 * np.eye(ny)
    b = plant.standard_normal((ny, nu))
    t = np.arange(n) * 1e-3
    q = np.column_stack([np.pi * np.sin(2 * np.pi * t * (1 + rng.random())),
                         np.zeros(n)])
    r = np.zeros((n, ny))
    r[:, :2] = q
    r[:, 2:4] = np.gradient(q, t, axis=0)
    v = np.repeat(rng.standard_normal((n // 10 + 1, nu)), 10, axis=0)[:n]
    d = np.zeros((n, ny))
    for k in range(n - 1):
        d[k + 1] = a @ d[k] + (1 + 0.8 * np.cos(q[k, 0])) * (b @ v[k])
    return Trajectory(split="train", family="multisine", seed=0, t=t, y=r + d, r=r, v=v,
                      tau_base=np.zeros((n, nu)), tau_inner=np.zeros((n, nu)))


def test_lpv_arx_sees_what_arx_cannot() -> None:
    from jointplay.neural.identify.linear_fit import fit_arx, model_scheduling, segments
    from jointplay.neural.identify.lpv import fit_lpv_arx, scheduled_segments
    from jointplay.neural.identify.lpv import window_loss as lpv_loss
    from jointplay.neural.identify.pipeline import output_increments
    from jointplay.neural.model.twin import window_loss, windows

    rng = np.random.default_rng(6)
    train = [_scheduled_run(rng, 1500) for _ in range(3)]
    test = [_scheduled_run(rng, 1500)]
    names = _names()
    arx = fit_arx(segments(train, 0), names, 2, 2, 1e-3)
    lpv = fit_lpv_arx(scheduled_segments(train, 0, 2), 2, 2,
                      output_increments(names["output_names"]))
    d, u, _ = windows(segments(test, 0), 100, arx.history)
    arx_loss = window_loss(arx, d, u, arx.output_scale)
    lpv_test = lpv_loss(lpv, scheduled_segments(test, 0, 2), 100, arx.output_scale)
    # The plant is exactly LPV in the input gain: the scheduled model is near exact in free run,
    # the time-invariant one is not.
    assert lpv_test < 1e-6 * max(arx_loss, 1e-300) or lpv_test < 1e-12
    assert arx_loss > 1e-3
    # The same model as the controller runs it (one linear layer and a bilinear part, the
    # scheduling signals computed from the reference and the feedforward) predicts the same.
    as_narx = lpv.as_narx(names, model_scheduling(names), 1e-3, arx.output_scale, {})
    d, u, w = windows(segments(test, 0, names), 100, arx.history)
    pred = as_narx.free_run(d[0], u[0], w[0])
    seg = scheduled_segments(test, 0, 2)[0]
    direct = lpv.free_run(*(a[None, : d.shape[1]] for a in seg))[0]
    assert np.max(np.abs(pred - direct)) <= 1e-12 * np.max(np.abs(direct))
    # An ARX model with the scheduling signals as further regressors cannot express a gain
    # that the configuration multiplies: it stays far from the LPV model.
    sched_arx = fit_arx(segments(train, 0, names), names, 2, 2, 1e-3,
                        scheduling=model_scheduling(names))
    assert window_loss(sched_arx, d, u, arx.output_scale, w) > 1e3 * lpv_test


# ---- data over the operating range ------------------------------------------------------------

def test_training_runs_span_the_clearances_and_payloads_asked_for() -> None:
    """Training and validation runs cycle through every clearance x payload pair (the test
    runs stay on the scene's robot), and a model made so is accepted on each of those robots
    and refused on another."""
    from dataclasses import replace

    from test_control import random_narx

    from jointplay.common.errors import DescriptionError
    from jointplay.neural.identify.pipeline import _context, default_limits, inner_loop_for
    from jointplay.neural.identify.trajectories import _plan
    from jointplay.neural.model.narx import check_robot
    from jointplay.robot import with_parameters
    from jointplay.scene.definition import default_scene

    scene = default_scene()
    config = IdentifyConfig(n_train=4, n_validation=2, n_test=1, duration=0.3,
                            clearances=(30e-6, 100e-6), payloads=(3.0,))
    inner = inner_loop_for(scene, (), ())
    tasks = _plan(scene, config, inner, default_limits(scene))
    seen = []
    for task in tasks:
        robot = task.scene.robot
        gap = robot.joints[1].bearing_radius - robot.joints[1].journal_radius
        seen.append((task.split, round(gap * 1e6, 6), robot.payload_mass))
    assert seen[:4] == [("train", 30.0, 3.0), ("train", 100.0, 3.0)] * 2
    assert seen[4:6] == [("validation", 30.0, 3.0), ("validation", 100.0, 3.0)]
    assert seen[6] == ("test", 30.0, 2.0)  # the scene's own robot
    assert tasks[1].description["robot"] == {"clearance": 100e-6, "payload": 3.0}
    context = _context(scene, config, inner, default_limits(scene))
    model = replace(random_narx(1), context=context)
    dt = scene.run.output_step
    check_robot(model, scene.robot, dt, "model")  # the scene's robot itself
    wide = with_parameters(scene.robot, {"joint2.journal_radius": 0.0099,
                                         "joint3.journal_radius": 0.0099,
                                         "payload.mass": 3.0})  # 100 µm, 3 kg
    check_robot(model, wide, dt, "model")
    other = with_parameters(scene.robot, {"payload.mass": 5.0})
    with pytest.raises(DescriptionError, match="different parameter values"):
        check_robot(model, other, dt, "model")
    with pytest.raises(DescriptionError, match="clearances"):
        IdentifyConfig(clearances=(-1e-6,))


def test_scene_family_base_motions_are_the_scenes_torques_retimed() -> None:
    """--base-motions scene-family: the training and validation runs are driven by the
    scene's torques, then by the scene's torques, every joint alike, at an amplitude, rate and
    time shift drawn per run from the scene family's ranges (numpy as drawn); the test runs
    keep their families, and the draws are not the closed-loop choice's motions."""
    from jointplay.neural.identify.excitation import Retimed
    from jointplay.neural.identify.pipeline import default_limits, inner_loop_for
    from jointplay.neural.identify.trajectories import (
        SCENE_FAMILY_RATE,
        SCENE_FAMILY_SCALE,
        TEST_FAMILIES,
        TRAIN_FAMILIES,
        _plan,
    )
    from jointplay.neural.study.closed_loop_choice import scene_family_motions
    from jointplay.scene.definition import default_scene

    scene = default_scene()
    inner = inner_loop_for(scene, (), ())
    limits = default_limits(scene)
    config = IdentifyConfig(n_train=5, n_validation=3, n_test=3, duration=0.5, seed=7,
                            base_motions="scene-family")
    tasks = _plan(scene, config, inner, limits)
    families = [(t.split, t.family) for t in tasks]
    assert families == ([("train", f) for f in ("scene", "scene-family", "scene-family",
                                                 "scene", "scene-family")]
                        + [("validation", f) for f in ("scene", "scene-family",
                                                        "scene-family")]
                        + [("test", f) for f in TEST_FAMILIES])
    t = np.linspace(0.0, 0.5, 51)
    draws = []
    for task in tasks:
        if task.family == "scene":
            assert list(task.scene.torques) == list(scene.torques)
        if task.family != "scene-family":
            continue
        first = task.scene.torques[0]
        draw = (first.scale, first.rate, first.shift)
        assert SCENE_FAMILY_SCALE[0] <= draw[0] <= SCENE_FAMILY_SCALE[1]
        assert SCENE_FAMILY_RATE[0] <= draw[1] <= SCENE_FAMILY_RATE[1]
        assert 0 <= draw[2] <= 0.25 * 0.5
        for f, own in zip(task.scene.torques, scene.torques, strict=True):
            assert isinstance(f, Retimed) and (f.scale, f.rate, f.shift) == draw
            assert np.allclose(f.numpy(t), draw[0] * own.numpy(draw[1] * t + draw[2]),
                               rtol=0, atol=1e-12)
        assert task.description["base"][0]["kind"] == "retimed"
        draws.append(draw)
    assert len(set(draws)) == len(draws) == 5  # a draw per run
    chosen_on = {(m.torques[0].scale, m.torques[0].rate, m.torques[0].shift)
                 for _, m in scene_family_motions(scene, config)}
    assert not chosen_on & set(draws)
    mixed = _plan(scene, replace(config, base_motions="mixed"), inner, limits)
    assert [t.family for t in mixed[:3]] == list(TRAIN_FAMILIES)
    assert [t.family for t in mixed[-3:]] == list(TEST_FAMILIES)
    with pytest.raises(Exception, match="mixed or scene-family"):
        IdentifyConfig(base_motions="scene")


def test_control_study_hands_its_identification_flags_to_identify(tmp_path: Any) -> None:
    """control-study's --identify-* flags (and --train, --scheduling, --lpv-base) reach the
    identification of every model unchanged, and their defaults are the settings' preset."""
    from jointplay.cli import make_parser
    from jointplay.cli.study import study_plan

    out = str(tmp_path / "study")
    plan = study_plan(make_parser().parse_args([
        "control-study", "--out", out, "--train", "24", "--validation", "2", "--test", "2",
        "--duration", "2.0", "--identify-iterations", "40,20", "--scheduling", "--lpv-base",
        "--identify-residual-by", "closed-loop-scene", "--identify-hidden", "24,24",
        "--identify-linear-input-gain", "--identify-base-motions", "scene-family",
        "--identify-scene-motions", "3", "--identify-lags", "3,1", "--identify-window", "50",
        "--identify-base-fraction", "0.2"]))
    config = IdentifyConfig(**plan.identify_args)
    assert (config.n_train, config.n_validation, config.n_test, config.duration) == (
        24, 2, 2, 2.0)
    assert (config.one_step_iterations, config.multi_step_iterations) == (40, 20)
    assert config.scheduling and config.lpv_base and config.linear_input_gain
    assert (config.residual_by, config.base_motions, config.scene_motions) == (
        "closed-loop-scene", "scene-family", 3)
    assert (config.hidden, config.output_lags, config.input_lags, config.window,
            config.base_fraction) == ((24, 24), 3, 1, 50, 0.2)
    from jointplay.neural.study.settings import preset_settings

    for preset in ("paper", "best"):
        default = IdentifyConfig(**study_plan(make_parser().parse_args(
            ["control-study", "--out", out, "--preset", preset])).identify_args)
        assert default == replace(preset_settings(preset).identify, seed=0, workers=0)


def _scheduled_runs(seed: int) -> tuple[list[Trajectory], list[Trajectory]]:
    """Two training runs and one validation run with scheduling signals."""
    rng = np.random.default_rng(seed)
    train = [_scheduled_run(rng, 300) for _ in range(2)]
    return train, [replace(_scheduled_run(rng, 300), split="validation")]


def _train_small(train: list[Trajectory], validation: list[Trajectory],
                 **flags: Any) -> tuple[Any, dict[str, Any]]:
    """A network of 4 hidden nodes with the scheduling signals, a few iterations."""
    from jointplay.neural.identify.training import train_narx

    config = IdentifyConfig(hidden=(4,), window=20, transient=0.0, one_step_iterations=3,
                            multi_step_iterations=2, scheduling=True, **flags)
    return train_narx(train, validation, config, _names(), 1e-3, {}, quiet=True)


def test_network_trained_with_scheduling_signals_exports_them() -> None:
    """--scheduling: the network's regressor ends with the scheduling signals, the exported
    model reproduces torch's predictions (train_narx checks to 1e-9) and its free run takes
    the signals from the runs' reference and feedforward."""
    pytest.importorskip("torch")
    from jointplay.neural.model.scheduling import scheduling_names, trajectory_scheduling

    train, validation = _scheduled_runs(8)
    names = _names()
    model, history = _train_small(train, validation)
    assert model.scheduling == scheduling_names(JOINTS)
    assert model.n_regressor == 2 * 10 + 2 * 2 + 8
    assert history["export_check"][0] < 1e-9
    run = validation[0]
    w = trajectory_scheduling(run, names["output_names"], names["input_names"])
    assert np.all(np.isfinite(model.free_run(run.deviation, run.v, w)))
    with pytest.raises(ValueError, match="scheduling signals"):
        model.free_run(run.deviation, run.v)


def test_network_on_an_lpv_arx_base_starts_at_the_lpv_fit_and_is_never_worse() -> None:
    """--lpv-base: the network's linear part is the LPV-ARX fit (fit_arx(lpv=True) predicts as
    jointplay.neural.identify.lpv's model), training keeps and exports a bilinear part, and the
    residual weighed against that base is never worse than it in free run on validation."""
    pytest.importorskip("torch")
    from jointplay.neural.identify.linear_fit import fit_arx, model_scheduling, segments
    from jointplay.neural.identify.lpv import fit_lpv_arx, scheduled_segments
    from jointplay.neural.identify.pipeline import output_increments
    from jointplay.neural.model.twin import select_residual

    train, validation = _scheduled_runs(9)
    names = _names()
    base = fit_arx(segments(train, 0, names), names, 2, 2, 1e-3,
                   scheduling=model_scheduling(names), lpv=True)
    lpv = fit_lpv_arx(scheduled_segments(train, 0, 2), 2, 2,
                      output_increments(names["output_names"]))
    d, u, w = segments(validation, 0, names)[0]
    phi = base.regressors(d, u, w)
    direct = lpv.predict(phi[:, : -base.n_scheduling], w[1:-1], d[1:-1])
    # The same least squares up to the ridge (1e-6 per sample), which here acts on
    # normalised targets with their mean removed: equal to 1e-4 of the largest prediction.
    assert np.max(np.abs(base.predict(phi) - direct)) <= 1e-4 * np.max(np.abs(direct))
    model, history = _train_small(train, validation, lpv_base=True)
    assert model.bilinear is not None and model.bilinear.shape == base.bilinear.shape
    assert history["export_check"][0] < 1e-9
    _, selection = select_residual(model, base, segments(validation, 0, names), 20)
    assert selection.losses[selection.alpha] <= selection.arx_loss
    with pytest.raises(Exception, match="scheduling"):
        IdentifyConfig(lpv_base=True)


def test_linear_input_gain_keeps_the_torque_out_of_the_hidden_layers() -> None:
    """--linear-input-gain: the hidden layers never see the input lags (exported as zero
    weights, and torch's predictions match the export to 1e-9), so the model's response to
    a change of the added torque is its linear part's alone, the direct path's and the
    bilinear (LPV) part's, at every regressor; the other regressors still reach the
    hidden layers, and the flag needs the linear path."""
    pytest.importorskip("torch")
    train, validation = _scheduled_runs(10)
    rng = np.random.default_rng(11)
    model, history = _train_small(train, validation, lpv_base=True, linear_input_gain=True)
    assert history["export_check"][0] < 1e-9
    ny, nu = 10, 2
    first = model.weights[0]
    inputs = slice(2 * ny, 2 * ny + 2 * nu)
    assert not np.any(first[:, inputs])
    assert np.all(np.abs(first[:, : 2 * ny]).max(axis=0) > 0)
    # The prediction's change with the input lags equals the same change of the model with
    # its hidden layers' output removed (the last layer's weights zeroed): the linear part.
    linear_only = replace(model, weights=(*model.weights[:-1], np.zeros_like(model.weights[-1])))
    phi = np.array([np.concatenate([rng.normal(model.regressor_mean, model.regressor_scale)])
                    for _ in range(5)])
    shifted = phi.copy()
    shifted[:, inputs] += rng.normal(0, 1.0, (5, 2 * nu)) * model.regressor_scale[inputs]
    np.testing.assert_allclose(model.predict(shifted) - model.predict(phi),
                               linear_only.predict(shifted) - linear_only.predict(phi),
                               rtol=0, atol=1e-12 * np.abs(model.predict(phi)).max())
    with pytest.raises(Exception, match="linear direct path"):
        IdentifyConfig(linear_input_gain=True, linear_path=False)
