"""Neural identification and the internal-model neural controller: exactness and bad input.

The network checks run on small random networks (fast, and independent of training luck);
one tiny end-to-end run covers data collection, training, saving, compiling and a closed loop.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np
import pytest

from jointplay.common.errors import DescriptionError
from jointplay.neural.model.narx import Narx, check_robot, load_narx, robot_identity, save_narx
from jointplay.neural.study.control_run import (
    ControllerSettings,
    compare,
    compile_controller,
    horizon_gain,
    load_lpv,
    load_twin,
    nominal_spectral_radius,
    resolve_settings,
)

OUTPUTS = ("q2", "q3", "dq2", "dq3", "tip_ax")


def random_narx(seed: int = 0, hidden: tuple[int, ...] = (5, 6), linear: bool = True,
                na: int = 2, nb: int = 2, context: dict | None = None,
                step: float = 0.03) -> Narx:
    """A random but well-scaled NARX with the output names the controller expects."""
    rng = np.random.default_rng(seed)
    ny, nu = len(OUTPUTS), 2
    n_phi = na * ny + nb * nu
    widths = [n_phi, *hidden, ny]
    weights = tuple(rng.normal(0, 0.6, (widths[i + 1], widths[i]))
                    for i in range(len(widths) - 1))
    biases = tuple(rng.normal(0, 0.1, widths[i + 1]) for i in range(len(widths) - 1))
    # Older inputs act much less than the newest: the one-step inverse is then stable (a
    # random network is otherwise as likely to be non-minimum-phase as not).
    weights[0][:, na * ny + nu:] *= 0.05
    direct = None
    if linear:
        direct = rng.normal(0, 0.05, (ny, n_phi))
        direct[:, na * ny: na * ny + nu] += rng.normal(0, 1.0, (ny, nu))  # input authority
        direct[:, na * ny + nu:] *= 0.05
    ctx = context if context is not None else {
        "robot": {"name": "test", "structure_hash": "0", "robot_hash": "0"},
        "plant": {"inner_loop": {"joints": [2, 3], "kp": [0.0, 0.0], "kd": [0.0, 0.0]},
                  "torque_limit": [1e6, 1e6]}}
    return Narx(
        output_names=OUTPUTS, output_units=("rad", "rad", "rad/s", "rad/s", "m/s^2"),
        input_names=("v2", "v3"), input_units=("N m", "N m"), output_lags=na, input_lags=nb,
        weights=weights, biases=biases, regressor_mean=rng.normal(0, 0.01, n_phi),
        regressor_scale=rng.uniform(0.5, 2.0, n_phi),
        increment_mean=rng.normal(0, 0.03 * step, ny),
        increment_scale=rng.uniform(0.3 * step, 1.5 * step, ny), output_scale=np.full(ny, 0.1),
        sample_time=1e-3, context=ctx, increment=(True, True, True, True, False), linear=direct)


def torch_net(model: Narx) -> tuple[Any, Any]:
    """The same network in PyTorch (float64), from the model's weights."""
    torch = pytest.importorskip("torch")
    layers: list = []
    for i, (w, b) in enumerate(zip(model.weights, model.biases, strict=True)):
        lin = torch.nn.Linear(w.shape[1], w.shape[0], dtype=torch.float64)
        with torch.no_grad():
            lin.weight.copy_(torch.tensor(w))
            lin.bias.copy_(torch.tensor(b))
        layers.append(lin)
        if i < len(model.weights) - 1:
            layers.append(torch.nn.Tanh())
    net = torch.nn.Sequential(*layers)
    direct = torch.tensor(model.linear)
    mu, sg = torch.tensor(model.regressor_mean), torch.tensor(model.regressor_scale)
    tm, ts = torch.tensor(model.increment_mean), torch.tensor(model.increment_scale)
    carry = torch.tensor(model.carry)

    def predict(phi: Any) -> Any:
        z = (phi - mu) / sg
        return carry * phi[..., : model.n_outputs] + tm + ts * (net(z) + z @ direct.T)
    return torch, predict


# ---- the network in CasADi --------------------------------------------------------------------

def test_casadi_network_equals_pytorch() -> None:
    model = random_narx(1)
    torch, predict = torch_net(model)
    phi = np.random.default_rng(2).normal(0, 1, (64, model.n_regressor))
    ref = predict(torch.tensor(phi)).detach().numpy()
    fn = model.casadi_function()
    got = np.asarray(fn.map(64)(phi.T)).T
    assert np.max(np.abs(got - ref)) <= 1e-12 * max(1.0, float(np.max(np.abs(ref))))
    assert np.max(np.abs(model.predict(phi) - ref)) <= 1e-12 * max(1.0, float(np.max(
        np.abs(ref))))


def test_jacobian_equals_autograd_and_finite_differences() -> None:
    model = random_narx(3)
    torch, predict = torch_net(model)
    phi0 = np.random.default_rng(4).normal(0, 1, model.n_regressor)
    sym = ca.SX.sym("phi", model.n_regressor)
    jac = np.asarray(ca.Function("j", [sym], [ca.jacobian(model.casadi_function()(sym), sym)])(
        phi0))
    auto = torch.autograd.functional.jacobian(predict, torch.tensor(phi0)).numpy()
    assert np.max(np.abs(jac - auto)) <= 1e-12 * max(1.0, float(np.max(np.abs(auto))))
    h = 1e-6
    fd = np.column_stack([(model.predict(phi0 + h * e) - model.predict(phi0 - h * e)) / (2 * h)
                          for e in np.eye(model.n_regressor)])
    assert np.max(np.abs(jac - fd)) <= 1e-7 * max(1.0, float(np.max(np.abs(fd))))


def test_horizon_jacobian_equals_finite_differences() -> None:
    """J of the d-step rollout (input held) that the controller inverts."""
    model = random_narx(5)
    d = 6
    gain = horizon_gain(model, d)

    def rollout(v: np.ndarray) -> np.ndarray:
        y = np.zeros((model.output_lags, model.n_outputs))
        u = np.zeros((model.input_lags, model.n_inputs))
        for _ in range(d):
            u = np.vstack([v[None, :], u[:-1]])
            y = np.vstack([model.predict(model.regressor(y, u))[None, :], y[:-1]])
        return y[0]

    h = 1e-6
    fd = np.column_stack([(rollout(h * e) - rollout(-h * e)) / (2 * h) for e in np.eye(2)])
    assert np.max(np.abs(gain - fd)) <= 1e-7 * max(1.0, float(np.max(np.abs(fd))))


# ---- the controller ---------------------------------------------------------------------------

def _closed_loop_on_model(model: Narx, settings: ControllerSettings, d0: np.ndarray,
                          steps: int) -> tuple[np.ndarray, np.ndarray, Any]:
    """The network itself as the plant (a perfect model, no disturbance), r = 0."""
    ctrl = compile_controller(model, settings)
    y = np.tile(d0, (model.output_lags, 1))
    u = np.zeros((model.input_lags, model.n_inputs))
    state = ctrl.initial_state(d0)
    zeros = np.zeros(model.n_outputs)
    ys, targets = [], []
    y_d = d0.copy()
    for _ in range(steps):
        tau, state, v, pred = ctrl.step(y[0], zeros, np.zeros(model.n_inputs), state)
        u = np.vstack([v[None, :], u[:-1]])
        y_next = model.predict(model.regressor(y, u))
        assert np.allclose(pred, y_next, rtol=0, atol=1e-13)  # the internal model is the plant
        y = np.vstack([y_next[None, :], y[:-1]])
        y_d = settings.setpoint_filter * y_d
        ys.append(y_next)
        targets.append(y_d.copy())
        del tau
    return np.array(ys), np.array(targets), ctrl


@pytest.mark.parametrize("iterations", [1, 6])
def test_perfect_model_tracks_exactly(iterations: int) -> None:
    """One step ahead, no regularisation: the tracked outputs land on the filtered setpoint
    at every sample (exactly with Gauss-Newton iterations; to the linearisation error with the
    single AIMNC step)."""
    model = random_narx(7)
    settings = ControllerSettings(horizon=1, regularisation=0.0, setpoint_filter=0.6,
                                  mismatch_filter=0.5, tracked=("q2", "q3"),
                                  iterations=iterations)
    d0 = np.array([0.02, -0.015, 0.0, 0.0, 0.0])
    ys, targets, ctrl = _closed_loop_on_model(model, settings, d0, 40)
    err = np.max(np.abs(ys[:, :2] - targets[:, :2]))
    if iterations > 1:
        assert err < 1e-12
    else:
        assert err < 2e-2 * np.max(np.abs(d0))
    assert np.max(np.abs(ys[-1, :2])) < 1e-6  # and the filtered setpoint goes to zero
    # The linearisation agrees with what the loop does: it converges, and its radius is < 1.
    assert nominal_spectral_radius(ctrl, settle=200) < 1


def test_compiled_step_equals_casadi_and_loop_is_stable() -> None:
    model = random_narx(9)
    settings = ControllerSettings(horizon=4, tracked=("q2", "q3", "dq2", "dq3"))
    ctrl = compile_controller(model, settings)
    assert ctrl.library is not None and ctrl.library.is_file()
    assert "GENERATED FILE: DO NOT EDIT" in ctrl.source and model.checksum() in ctrl.source
    rng = np.random.default_rng(10)
    for _ in range(5):
        args = [rng.normal(0, 0.01, model.n_outputs), rng.normal(0, 0.01, model.n_outputs),
                rng.normal(0, 1, 2), rng.normal(0, 0.01, ctrl.n_state)]
        compiled = [*ctrl.step(*args), ctrl.last_flags]
        symbolic = [np.asarray(o).ravel() for o in ctrl.function(*args)]
        for a, b in zip(compiled, symbolic, strict=True):
            assert np.max(np.abs(a - b)) <= 1e-12 * max(1.0, float(np.max(np.abs(b))))
    assert np.isfinite(nominal_spectral_radius(ctrl, settle=200))


def test_torque_and_rate_limits_hold() -> None:
    model = random_narx(11)
    settings = resolve_settings(model, ControllerSettings(
        horizon=2, regularisation=0.0, tracked=("q2", "q3"), torque_limit=(0.5, 0.3),
        rate_limit=(100.0, 50.0)))
    ctrl = compile_controller(model, settings)
    state = ctrl.initial_state(np.array([1.0, -1.0, 0.0, 0.0, 0.0]))  # far off: saturates
    ff = np.array([0.2, -0.1])
    v_prev = np.zeros(2)
    for _ in range(30):
        tau, state, v, _ = ctrl.step(state[: model.n_outputs], np.zeros(model.n_outputs), ff,
                                     state)
        assert np.all(np.abs(tau + ff) <= np.array([0.5, 0.3]) + 1e-12)
        assert np.all(np.abs(v - v_prev) <= np.array([0.1, 0.05]) + 1e-12)
        v_prev = v


# ---- saved models and bad input -------------------------------------------------------------

def test_saved_model_round_trips_exactly(tmp_path: Path) -> None:
    model = random_narx(12)
    save_narx(model, tmp_path)
    back = load_narx(tmp_path)
    phi = np.random.default_rng(13).normal(0, 1, (10, model.n_regressor))
    assert np.array_equal(back.predict(phi), model.predict(phi))
    assert back.checksum() == model.checksum() and back.context == model.context
    data = json.loads((tmp_path / "narx.json").read_text())
    assert data["format"] == "jointplay-narx" and data["outputs"][4]["increment"] is False
    y = np.random.default_rng(14).normal(0, 0.01, (20, model.n_outputs))
    u = np.random.default_rng(15).normal(0, 0.1, (20, 2))
    assert np.allclose(back.free_run(y, u)[0], back.one_step(y, u)[0], rtol=1e-14, atol=1e-17)


def _mutate(path: Path, change: Any) -> None:
    data = json.loads(path.read_text())
    change(data)
    path.write_text(json.dumps(data))


@pytest.mark.parametrize("case, expected", [
    ("missing_dir", "does not exist"),
    ("missing_file", "has no narx.json"),
    ("not_json", "cannot be read as JSON"),
    ("edited_weight", "checksum mismatch"),
    ("bad_shape", "layer 2 weight has shape"),
    ("missing_key", "missing entries normalisation"),
    ("new_version", "format_version 99 is not supported"),
])
def test_bad_model_folders_name_the_problem(tmp_path: Path, case: str, expected: str) -> None:
    model = random_narx(16)
    folder = tmp_path / "model"
    if case != "missing_dir":
        folder.mkdir()
    if case not in ("missing_dir", "missing_file"):
        save_narx(model, folder)
    path = folder / "narx.json"
    if case == "not_json":
        path.write_text(path.read_text()[:200])
    elif case == "edited_weight":
        _mutate(path, lambda d: d["layers"][0]["weight"][0].__setitem__(0, 1.0))
    elif case == "bad_shape":
        broken = replace(model)  # valid object; break the file consistently (with checksum)
        data = broken.to_dict()
        data["layers"][1]["weight"] = data["layers"][1]["weight"][:-1]
        from jointplay.neural.model.narx import _checksum

        content = {k: data[k] for k in ("outputs", "inputs", "output_lags", "input_lags",
                                        "sample_time", "activation", "layers", "linear",
                                        "normalisation")}
        data["checksum"] = _checksum(content, data["context"])
        path.write_text(json.dumps(data))
    elif case == "missing_key":
        _mutate(path, lambda d: d.pop("normalisation"))
    elif case == "new_version":
        _mutate(path, lambda d: d.__setitem__("format_version", 99))
    with pytest.raises(DescriptionError) as err:
        load_narx(folder)
    assert err.value.field == "--model"
    assert expected in str(err.value)
    assert "jointplay identify" in str(err.value)


def test_model_for_another_robot_is_refused() -> None:
    from jointplay.robot import with_parameters
    from jointplay.scene.definition import default_scene

    robot = default_scene().robot
    model = random_narx(17, context={"robot": robot_identity(robot), "plant": {}})
    check_robot(model, robot, 1e-3, "m/narx.json")  # the same robot passes
    heavier = with_parameters(robot, {"payload.mass": 3.0})
    with pytest.raises(DescriptionError, match="different parameter values"):
        check_robot(model, heavier, 1e-3, "m/narx.json")
    other = replace(robot, joints=tuple(replace(j, kind="ideal") if j.kind == "clearance"
                                        else j for j in robot.joints))
    with pytest.raises(DescriptionError, match="different structure"):
        check_robot(model, other, 1e-3, "m/narx.json")
    with pytest.raises(DescriptionError, match="sampling period"):
        check_robot(model, robot, 2e-3, "m/narx.json")


def _parser() -> argparse.ArgumentParser:
    from jointplay.cli import control, identify, study

    parser = argparse.ArgumentParser(prog="jointplay")
    sub = parser.add_subparsers(dest="command", required=True)
    identify.register(sub)
    control.register(sub)
    study.register(sub)
    return parser


@pytest.mark.parametrize("argv, flag", [
    (["control", "--model", "/nonexistent/model"], "--model"),
    (["identify", "--out", "/tmp/x", "--lags", "2"], "--lags"),
    (["identify", "--out", "/tmp/x", "--hidden", "13,0"], "--hidden"),
    (["identify", "--out", "/tmp/x", "--kp", "1,2,3"], "--kp"),
    (["identify", "--out", "/tmp/x", "--duration", "-1"], "--duration"),
    (["identify", "--out", "/tmp/x", "--iterations", "1"], "--iterations"),
    (["control-study", "--out", "/tmp/x", "--seeds", "0"], "--seeds"),
    (["control-study", "--out", "/tmp/x", "--first-seed", "-1"], "--first-seed"),
    (["control-study", "--out", "/tmp/x", "--cases", "scene,foo"], "--cases"),
    (["control-study", "--out", "/tmp/x", "--train", "0"], "--train"),
    (["control-study", "--out", "/tmp/x", "--identify-iterations", "1"],
     "--identify-iterations"),
    (["identify", "--out", "/tmp/x", "--lpv-base", "--preset", "paper"], "--lpv-base"),
    (["control-study", "--out", "/tmp/x", "--lpv-base", "--preset", "paper"], "--lpv-base"),
    (["control-study", "--out", "/tmp/x", "--identify-hidden", "0"], "--identify-hidden"),
    (["control-study", "--out", "/tmp/x", "--identify-window", "1"], "--identify-window"),
    (["identify", "--out", "/tmp/x", "--residual-by", "closed-loop", "--validation", "1"],
     "--residual-by"),
    (["control-study", "--out", "/tmp/x", "--identify-residual-by", "closed-loop",
      "--validation", "1"], "--identify-residual-by"),
    (["identify", "--out", "/tmp/x", "--base-fraction", "0"], "--base-fraction"),
    (["control-study", "--out", "/tmp/x", "--identify-base-fraction", "1.5"],
     "--identify-base-fraction"),
    (["control-study", "--out", "/tmp/x", "--identify-lags", "2"], "--identify-lags"),
    (["identify", "--out", "/tmp/x", "--scene-motions", "0"], "--scene-motions"),
    (["control-study", "--out", "/tmp/x", "--identify-scene-motions", "17"],
     "--identify-scene-motions"),
])
def test_commands_reject_bad_flags(argv: list[str], flag: str) -> None:
    """DescriptionError is what the command line turns into exit status 2."""
    args = _parser().parse_args(argv)
    with pytest.raises(DescriptionError) as err:
        args.func(args)
    assert err.value.field.startswith(flag)


def test_neural_room_holds_no_command_line() -> None:
    """The commands live in jointplay.cli; the neural modules hold no argparse and no cmd_*."""
    import ast

    import jointplay.neural

    folder = Path(jointplay.neural.__file__).parent
    for path in sorted(folder.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        imports = {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import)
                   for alias in node.names}
        imports |= {node.module for node in ast.walk(tree)
                    if isinstance(node, ast.ImportFrom) and node.module}
        assert "argparse" not in imports, path.name
        commands = [node.name for node in ast.walk(tree) if isinstance(node, ast.FunctionDef)
                    and (node.name.startswith("cmd_") or node.name == "register")]
        assert not commands, (path.name, commands)


def test_control_rejects_bad_settings_for_the_model(tmp_path: Path) -> None:
    model = random_narx(18)
    for settings, flag in ((ControllerSettings(horizon=0), "--horizon"),
                           (ControllerSettings(tracked=("tip_q",)), "--track"),
                           (ControllerSettings(mismatch_filter=1.0), "--mismatch-filter"),
                           (ControllerSettings(torque_limit=(1.0,)), "--torque-limit")):
        with pytest.raises(DescriptionError) as err:
            resolve_settings(model, settings)
        assert err.value.field == flag


def test_import_jointplay_stays_free_of_torch() -> None:
    code = ("import sys, jointplay, jointplay.neural.model.narx, "
            "jointplay.neural.study.control_run, jointplay.neural.identify.pipeline; "
            "sys.exit('torch' in sys.modules)")
    assert subprocess.run([sys.executable, "-c", code], check=False).returncode == 0


# ---- end to end (tiny) ------------------------------------------------------------------------

def test_identify_and_control_end_to_end(tmp_path: Path) -> None:
    pytest.importorskip("torch")
    from jointplay.neural.identify.pipeline import IdentifyConfig, identify, read_datasets
    from jointplay.scene.definition import default_scene

    scene = default_scene()
    config = IdentifyConfig(duration=0.12, n_train=1, n_validation=1, n_test=1, hidden=(4, 4),
                            one_step_iterations=3, multi_step_iterations=2, window=20,
                            workers=1)
    out = tmp_path / "model"
    # One training run of 70 samples for 24 regressors: neither the network nor its ARX start
    # can beat persistence on validation. The model is refused, kept as narx.rejected.json
    # with the report saying why, and control will not load it.
    from jointplay.neural.identify.pipeline import ModelRejected
    from jointplay.neural.model.narx import REJECTED_FILE

    with pytest.raises(ModelRejected, match="worse than persistence"):
        identify(scene, out, config, quiet=True)
    for name in (REJECTED_FILE, "arx.json", "datasets.h5", "metrics.json", "report.md"):
        assert (out / name).is_file()
    assert not (out / "narx.json").exists()
    assert "REJECTED" in (out / "report.md").read_text()
    with pytest.raises(DescriptionError, match="identification rejected its model"):
        load_narx(out)
    metrics = json.loads((out / "metrics.json").read_text())
    model = load_narx(out, filename=REJECTED_FILE)  # explicitly, for the plumbing below
    check_robot(model, scene.robot, scene.run.output_step, out)
    assert model.hidden == (4, 4) and model.output_names[:4] == ("q2", "q3", "dq2", "dq3")
    assert set(metrics["test"]) == {"narx", "arx", "persistence"}
    trajectories, meta = read_datasets(out / "datasets.h5")
    assert [t.split for t in trajectories] == ["train", "validation", "test"]
    assert trajectories[-1].family == "chirp" and meta["sample_time"] == 1e-3
    assert (out / "arx.json").is_file()
    short = scene.with_run(t_end=0.06)
    result = compare(short, model, ControllerSettings(horizon=3), arx=load_twin(out, model),
                     lpv=load_lpv(out))
    assert set(result.metrics) == {"open loop", "PD", "computed torque", "ARX-IMC",
                                   "LPV-ARX-IMC", "neural IMC"}
    for m in result.metrics.values():
        assert all(np.isfinite(v) for v in m.values())
    assert all(us > 0 for us in result.per_call_us.values())
    from jointplay.neural.study.control_plots import plot_comparison

    drawn = plot_comparison(result, short, tmp_path / "plots")  # what `control --plot` draws
    assert [p.name for p in drawn] == ["control_tracking.png", "control_error.png",
                                       "control_joints.png", "control_torque.png"]
    assert all(p.stat().st_size > 0 for p in drawn)
    # A failed rerun into the same folder leaves the finished model as it was.
    before = {name: (out / name).read_bytes() for name in (REJECTED_FILE, "metrics.json")}
    import jointplay.neural.identify.pipeline as identify_module

    def failing(*args: Any, **kwargs: Any) -> None:
        raise RuntimeError("training failed")

    original = identify_module.train_narx
    identify_module.train_narx = failing  # type: ignore[assignment]
    try:
        with pytest.raises(RuntimeError, match="training failed"):
            identify(scene, out, config, quiet=True)
    finally:
        identify_module.train_narx = original
    assert {name: (out / name).read_bytes() for name in before} == before
    assert sorted(p.name for p in out.iterdir()) == ["arx.json", "datasets.h5", "lpv.json",
                                                      "metrics.json", REJECTED_FILE,
                                                      "report.md"]


def test_training_data_with_nan_is_refused() -> None:
    from jointplay.neural.identify.pipeline import Trajectory, check_finite

    n = 5
    good = Trajectory(split="train", family="multisine", seed=0, t=np.arange(n) * 1e-3,
                      y=np.zeros((n, 3)), r=np.zeros((n, 3)), v=np.zeros((n, 2)),
                      tau_base=np.zeros((n, 2)), tau_inner=np.zeros((n, 2)))
    check_finite([good])
    y = good.y.copy()
    y[3, 1] = np.nan
    bad = replace(good, y=y)
    with pytest.raises(DescriptionError, match=r"non-finite y at sample 3, column 1"):
        check_finite([good, bad])


def test_step_vector_flags_follow_the_processor(tmp_path: Path,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    import platform

    from jointplay.neural.control.imc import _vector_flags

    info = tmp_path / "cpuinfo"
    info.write_text("processor\t: 0\nflags\t\t: fpu sse2 avx avx2 fma bmi2\n")
    monkeypatch.setattr(platform, "machine", lambda: "x86_64")
    assert _vector_flags(str(info)) == ("-mavx2", "-mfma")
    info.write_text("processor\t: 0\nflags\t\t: fpu sse2 avx\n")
    assert _vector_flags(str(info)) == ()
    assert _vector_flags(str(tmp_path / "missing")) == ()
    monkeypatch.setattr(platform, "machine", lambda: "aarch64")
    info.write_text("flags\t\t: avx2 fma\n")
    assert _vector_flags(str(info)) == ()
