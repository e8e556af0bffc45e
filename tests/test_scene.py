"""Scenes: the default, validation before anything is compiled, and the simulate command."""

from __future__ import annotations

import math
from pathlib import Path

import h5py
import numpy as np
import pytest

import jointplay.sim
from jointplay.cli import main
from jointplay.common.errors import DescriptionError
from jointplay.scene.definition import default_scene, load_scene
from jointplay.sim import load_scene_model

ROBOT = """
[robot]
name = "two"
[[robot.links]]
length = 0.3
mass = 1.0
inertia = 0.0075
com = 0.15
[[robot.links]]
length = 0.3
mass = 1.0
inertia = 0.0075
com = 0.15
[[robot.joints]]
kind = "ideal"
[[robot.joints]]
kind = "clearance"
"""


def write_scene(tmp_path: Path, head: str, robot: str = ROBOT) -> Path:
    path = tmp_path / "scene.toml"
    path.write_text(head + "\n" + robot)
    return path


def test_default_scene_is_the_papers_example() -> None:
    scene = default_scene()
    robot = scene.robot
    assert [j.kind for j in robot.joints] == ["locked", "clearance", "clearance", "locked"]
    assert [link.length for link in robot.links] == [0.30, 0.35, 0.30, 0.10]
    assert [link.mass for link in robot.links] == [3.0, 2.0, 1.5, 0.5]
    assert robot.payload_mass == 2.0
    assert robot.joints[1].bearing_radius - robot.joints[1].journal_radius == pytest.approx(30e-6)
    assert robot.contact.law == "lankarani-nikravesh" and robot.contact.restitution == 0.9
    assert (robot.friction.mu, robot.friction.v0, robot.friction.v1) == (0.05, 1e-4, 1e-2)
    assert scene.initial["q2"] == pytest.approx(-math.pi, abs=0)
    t = np.linspace(0, 2, 9)
    np.testing.assert_allclose(scene.torques[0].numpy(t), 4 * np.sin(2 * np.pi * t), atol=1e-14)
    np.testing.assert_allclose(scene.torques[1].numpy(t), 2 * np.sin(2 * np.pi * t), atol=1e-14)
    assert (scene.run.t_end, scene.run.output_step, scene.run.integrator) == (2.0, 1e-3,
                                                                               "bdf")


def test_a_scene_compiles_only_the_effects_it_asks_for(tmp_path: Path) -> None:
    path = write_scene(tmp_path, '[run]\nt_end = 0.01\n',
                       ROBOT + '[robot.friction]\nlaw = "none"\n')
    model = load_scene_model(load_scene(path))
    assert not [p for p in model.parameters if p.startswith("friction.")]
    assert model.structure.friction == "none"
    assert model.coordinates == ["q1", "q2", "ex2", "ey2"]  # joint 1 ideal: no play terms
    with_friction = load_scene_model(load_scene(write_scene(tmp_path, "", ROBOT)))
    assert "friction.mu" in with_friction.parameters
    assert with_friction.library != model.library


BAD_SCENES = [
    ("[run\nt_end = 1", "(toml)", "malformed TOML"),
    ("[runn]\nt_end = 1", "runn", "did you mean 'run'"),
    ("[run]\nt_end = 'two'", "run.t_end", "finite number"),
    ("[run]\nt_end = 0", "run.t_end", "> 0"),
    ("[run]\nt_end = -1.0", "run.t_end", "> 0"),
    ("[run]\nt_end = nan", "run.t_end", "finite number"),
    ("[run]\nrtol = inf", "run.rtol", "finite number"),
    ("[run]\nintegrator = 'cvode'", "run.integrator", "did you mean 'cvodes'"),
    ("[run]\nt_end = 1.0\noutput_step = 0.3", "run.output_step", "whole samples"),
    ("[run]\nintegrator = 'rk4'\nstep = 3e-4", "run.step", "divide"),
    ("[run]\nt_ned = 1.0", "run.t_ned", "did you mean 't_end'"),
    ("[torques]\njoint2 = \"__import__('os').system('true')\"", "torques.joint2", "__import__"),
    ("[torques]\njoint2 = 't.real'", "torques.joint2", "attribute"),
    ("[torques]\njoint2 = 'open(t)'", "torques.joint2", "open"),
    ("[torques]\njoint2 = '(lambda: 1)()'", "torques.joint2", ""),
    ("[torques]\njoint7 = 'sin(t)'", "torques.joint7", "unknown key"),
    ("[torques]\njoint2 = 'A*sin(t)'", "torques.joint2", "A"),
    ("[constants]\n__x = 1.0", "constants.__x", "identifier"),
    ("[initial]\nq7 = 1.0", "initial.q7", "unknown key"),
    ("[initial]\nq1 = 't'", "initial.q1", "must not depend on t"),
    ("[initial]\nex2 = 1.0", "initial.ex2", "inside its bearing"),
    ("[initial]\nq1 = true", "initial.q1", "finite number"),
]


@pytest.mark.parametrize(("head", "field", "message"), BAD_SCENES,
                         ids=[b[1] + ":" + b[2][:12] for b in BAD_SCENES])
def test_bad_scenes_name_the_file_field_and_fix(tmp_path: Path, head: str, field: str,
                                                message: str,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    path = write_scene(tmp_path, head)
    with pytest.raises(DescriptionError) as info:
        load_scene(path)
    assert info.value.field == field
    assert message in info.value.message
    assert str(path) in str(info.value)
    out = tmp_path / "run.h5"
    assert main(["simulate", str(path), "--out", str(out), "--quiet"]) == 2
    assert not out.exists()
    assert f"{field}" in capsys.readouterr().err


def test_bad_robot_inside_a_scene(tmp_path: Path) -> None:
    path = write_scene(tmp_path, "", ROBOT.replace("mass = 1.0", "mass = -1.0", 1))
    with pytest.raises(DescriptionError, match=r"links\[1\]\.mass: must be > 0"):
        load_scene(path)
    with pytest.raises(DescriptionError, match="robot: is required"):
        load_scene(write_scene(tmp_path, "", ""))


def test_missing_scene_file(tmp_path: Path) -> None:
    assert main(["simulate", str(tmp_path / "nope.toml"), "--quiet"]) == 2


@pytest.mark.parametrize("flag", ["--out", "--csv"])
def test_unwritable_output_path_is_refused_before_running(tmp_path: Path, flag: str) -> None:
    target = tmp_path / "missing" / "run.out"
    assert main(["simulate", "--t-end", "0.01", flag, str(target), "--quiet"]) == 2
    assert not target.parent.exists()


def test_bad_override_flags(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["simulate", "--t-end", "-1", "--quiet"]) == 2
    assert "--t-end" in capsys.readouterr().err
    assert main(["simulate", "--set", "payload.mas=3", "--quiet"]) == 2
    assert "did you mean 'payload.mass'" in capsys.readouterr().err
    assert main(["simulate", "--set", "friction.mu=abc", "--quiet"]) == 2


def test_interrupted_run_leaves_no_result_file(tmp_path: Path,
                                               monkeypatch: pytest.MonkeyPatch) -> None:
    def interrupted(*args: object, **kwargs: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(jointplay.sim, "simulate", interrupted)
    out = tmp_path / "run.h5"
    assert main(["simulate", "--t-end", "0.01", "--out", str(out), "--quiet"]) == 130
    assert list(tmp_path.iterdir()) == []


def test_simulate_command_writes_results_and_plots(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    out, csv, plots = tmp_path / "run.h5", tmp_path / "run.csv", tmp_path / "plots"
    code = main(["simulate", "--t-end", "0.02", "--compare-ideal", "--out", str(out),
                 "--csv", str(csv), "--plot", str(plots), "--set", "payload.mass=2.5"])
    assert code == 0
    text = capsys.readouterr().out
    assert "x real time" in text and "error vs ideal joints" in text
    with h5py.File(out) as f:
        assert f["time"].shape == (21,)
        assert f["joint_angle"].shape == (21, 2) and f["journal_offset"].shape == (21, 2, 2)
        assert "ideal" in f
        assert f["impact_time"].shape[0] >= 2
        names = [n.decode() if isinstance(n, bytes) else n for n in f["parameter"][()]]
        assert f["parameter_value"][names.index("payload.mass")] == 2.5
    header = csv.read_text().splitlines()[0]
    assert header.startswith("t [s],") and "delta2 [m]" in header
    phases = (tmp_path / "run.impacts.csv").read_text().splitlines()
    assert phases[0].startswith("time [s],joint,speed [m/s],")
    with h5py.File(out) as f:
        assert len(phases) - 1 == f["impact_time"].shape[0]
    assert sorted(p.name for p in plots.iterdir()) == [
        "contact_force.png", "contact_timeline_joint2.png", "contact_timeline_joint3.png",
        "eccentricity_ratio.png", "end_effector.png", "energy.png", "orbit_joint2.png",
        "orbit_joint3.png"]
    # Per joint: impacts and approach speed from the table; a peak that is not located says
    # so, and a sampled maximum is labelled as sampled.
    for line in text.splitlines():
        if "normal force" in line:
            assert "(located)" in line or "not located" in line or "sampled" in line, line
    assert "joint 2: " in text and "largest approach speed" in text
    assert "wrote " + str(tmp_path / "run.impacts.csv") in text


def test_output_step_flag_and_run_settings_through_set(tmp_path: Path,
                                                       capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "run.h5"
    assert main(["simulate", "--t-end", "0.004", "--output-step", "1e-4", "--out", str(out),
                 "--quiet"]) == 0
    with h5py.File(out) as f:
        assert f["time"].shape == (41,)
        assert f["time"][1] == pytest.approx(1e-4, rel=1e-12)
    assert main(["simulate", "--t-end", "0.004", "--set", "run.output_step=5e-4",
                 "--out", str(out), "--quiet"]) == 0
    with h5py.File(out) as f:
        assert f["time"].shape == (9,)
    for flags, field, message in (
            (["--output-step", "3e-7"], "--output-step", "must divide run.t_end"),
            (["--output-step=-1e-3"], "--output-step", "must be > 0"),
            (["--output-step", "1"], "--output-step", "must not exceed run.t_end"),
            (["--set", "run.output_step=3e-7"], "--set run.output_step", "must divide"),
            (["--set", "run.integrator=1"], "--set run.integrator", "must be one of bdf"),
            (["--set", "run.max_steps=2.5"], "--set run.max_steps", "whole number"),
            (["--animate", str(tmp_path / "arm.avi")], "--animate", ".gif or .mp4")):
        assert main(["simulate", "--t-end", "0.01", *flags, "--quiet"]) == 2, flags
        err = capsys.readouterr().err
        assert f"{field}: " in err and message in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.h5"]


def test_loading_a_generated_model_does_not_import_sympy() -> None:
    """The runtime finds and loads a model generated before without the derivation."""
    import subprocess
    import sys

    code = ("import sys\n"
            "from jointplay.scene.definition import default_scene\n"
            "from jointplay.sim import load_scene_model, simulate\n"
            "scene = default_scene().with_run(t_end=0.002)\n"
            "simulate(scene, model=load_scene_model(scene))\n"
            "assert 'sympy' not in sys.modules, 'sympy was imported'\n")
    subprocess.run([sys.executable, "-c", code], check=True)
