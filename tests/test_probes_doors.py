"""Probes of the newest doors: calibrate's measured files and flags, the settings files of
identify, control and control-study, the extras a command needs, the cache's folder, the
figure process, and the units of a results file.

Each probe satisfies the contract of :mod:`test_probes` (exit 0, 1, 2 or 130, one error line,
no traceback); a refusal is exit 2 before any work, naming the input, and leaves nothing it
made behind."""

from __future__ import annotations

from pathlib import Path

import pytest
from test_probes import ROOT, bad_input

from jointplay.cli import main
from jointplay.common import limits

SHORT_SCENE = (ROOT / "scenes" / "paper_4dof.toml").read_text(encoding="utf-8").replace(
    "t_end = 2.0 ", "t_end = 0.02 ")
GOOD_ROWS = "0.0,0.1\n0.001,0.1\n0.002,0.1\n"


def _calibrate(tmp: Path, csv: str | bytes = "time,tip_x\n" + GOOD_ROWS,
               *flags: str) -> list[str]:
    scene = tmp / "short.toml"
    scene.write_text(SHORT_SCENE, encoding="utf-8")
    measured = tmp / "m.csv"
    if isinstance(csv, bytes):
        measured.write_bytes(csv)
    else:
        measured.write_text(csv, encoding="utf-8")
    argv = ["calibrate", str(scene), "--measured", str(measured), "--out", str(tmp / "cal")]
    return argv + (list(flags) if "--free" in flags else ["--free", "friction.mu", *flags])


def _nothing_written(tmp: Path) -> None:
    assert sorted(p.name for p in tmp.iterdir()) == ["m.csv", "short.toml"]


# ---- calibrate: the measured file -----------------------------------------------------------

@pytest.mark.parametrize("cell", ["1e200", "1e308", "-1e7", "1.0000001e6"])
def test_calibrate_refuses_a_huge_finite_cell(tmp_path: Path, cell: str,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    argv = _calibrate(tmp_path, f"time,tip_x\n0.0,0.1\n0.001,{cell}\n0.002,0.1\n")
    bad_input(capsys, argv, "row 3 column tip_x", "within", "m.csv")
    _nothing_written(tmp_path)


def test_calibrate_a_huge_angle_is_named_in_radians(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    argv = _calibrate(tmp_path, "time,q2\n0.0,0.1\n0.001,2e6\n0.002,0.1\n")
    bad_input(capsys, argv, "row 3 column q2", "rad")


def test_calibrate_reads_a_byte_order_mark(tmp_path: Path) -> None:
    """A spreadsheet's CSV starts with a UTF-8 byte-order mark: read as without one."""
    from jointplay.calibration.measured import read_measured
    from jointplay.scene.definition import load_scene
    from jointplay.sim import load_scene_model

    path = tmp_path / "m.csv"
    path.write_bytes(b"\xef\xbb\xbf" + ("time,tip_x\n" + GOOD_ROWS).encode())
    plain = tmp_path / "plain.csv"
    plain.write_text("time,tip_x\n" + GOOD_ROWS, encoding="utf-8")
    scene = tmp_path / "short.toml"
    scene.write_text(SHORT_SCENE, encoding="utf-8")
    model = load_scene_model(load_scene(str(scene)))
    marked, unmarked = read_measured(path, model), read_measured(plain, model)
    assert marked.columns == unmarked.columns == ("tip_x",)
    assert (marked.t == unmarked.t).all() and (marked.values == unmarked.values).all()


@pytest.mark.parametrize(("noise", "field"), [
    ("1e-320", "--noise"), ("5e-324", "--noise"), (f"{limits.MIN_NOISE / 2:g}", "--noise"),
    ("tip_x=1e-300", "--noise tip_x")])
def test_calibrate_refuses_a_noise_below_the_floor(tmp_path: Path, noise: str, field: str,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    bad_input(capsys, _calibrate(tmp_path, "time,tip_x\n" + GOOD_ROWS, "--noise", noise),
              field, "at least")
    _nothing_written(tmp_path)


@pytest.mark.parametrize(("flag", "value", "field"), [
    ("--start", "friction.mu=0.1,friction.mu=0.2", "--start"),
    ("--start", "friction.mu=0.1, friction.mu =0.1", "--start"),
    ("--noise", "tip_x=1e-6,tip_x=2e-6", "--noise"),
])
def test_calibrate_refuses_a_name_given_twice(tmp_path: Path, flag: str, value: str, field: str,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    bad_input(capsys, _calibrate(tmp_path, "time,tip_x\n" + GOOD_ROWS, flag, value), field,
              "twice")
    _nothing_written(tmp_path)


@pytest.mark.parametrize(("flag", "value"), [
    ("--scan-points", "10000000000"), ("--scan-points", str(limits.MAX_CALIBRATION_RUNS + 1)),
    ("--grid-points", "1000000"), ("--grid-points", "317"),
    ("--grid-line-points", "100001"), ("--valley-check-points", "10000000"),
    ("--profile-points", "1000000"), ("--starts", "1000000")])
def test_calibrate_bounds_each_stage_before_any_work(tmp_path: Path, flag: str, value: str,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    bad_input(capsys, _calibrate(tmp_path, "time,tip_x\n" + GOOD_ROWS, flag, value), flag,
              "at most")
    _nothing_written(tmp_path)


@pytest.mark.parametrize(("out", "words"), [
    ("-", ("standard output",)), ("x" * 300, ("300 bytes",)), ("x" * 300 + "/cal", ("300",)),
    ("", ("empty",))])
def test_calibrate_refuses_an_out_no_folder_can_take(
        tmp_path: Path, out: str, words: tuple[str, ...], monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    argv = _calibrate(tmp_path, "time,tip_x\n" + GOOD_ROWS)
    argv[argv.index("--out") + 1] = out
    bad_input(capsys, argv, "--out", *words)
    _nothing_written(tmp_path)


# ---- identify, control-study and their settings ---------------------------------------------

def _settings(tmp: Path, text: str) -> Path:
    path = tmp / "settings.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize(("argv", "field", "words"), [
    (["--set", "identify.transient=5", "--duration", "0.3"], "identify.transient",
     ("too few samples",)),
    (["--set", "identify.transient=2.0", "--duration", "2.0"], "identify.transient",
     ("too few samples",)),
    (["--set", "identify.transient=0.299", "--duration", "0.3"], "identify.transient", ()),
    (["--set", "control.tracked=q9"], "control.tracked", ("'q9'", "q2, q3")),
    (["--set", "control.tracked=tip_z"], "control.tracked", ("did you mean 'tip_y'",)),
    (["--set", "control.tracked=tip_x,tip_x"], "control.tracked", ("twice",)),
    (["--set", "control.tracked=ex2"], "control.tracked", ("'ex2'",)),
])
def test_identify_checks_its_settings_before_any_work(
        tmp_path: Path, argv: list[str], field: str, words: tuple[str, ...],
        capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("torch")
    out = tmp_path / "deep" / "er" / "model"
    bad_input(capsys, ["identify", "--out", str(out), "--quiet", *argv], field, *words)
    assert list(tmp_path.iterdir()) == []  # no folder made, not even a parent


@pytest.mark.slow  # builds the plant's models first (35 s on a busy machine)
def test_identify_failing_at_work_leaves_no_folder_it_made(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The model folder and the parents identify made for it are removed again when the
    work fails (here, the first step of it)."""
    pytest.importorskip("torch")
    from jointplay.neural.identify import pipeline
    from jointplay.scene.definition import default_scene

    def fail(*args: object, **kwargs: object) -> None:
        raise RuntimeError("the work failed")

    monkeypatch.setattr(pipeline, "_identify_into", fail)
    with pytest.raises(RuntimeError, match="the work failed"):
        pipeline.identify(default_scene(), tmp_path / "a" / "b" / "model",
                          pipeline.IdentifyConfig())
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("text", "field", "words"), [
    ('scene = "default"\npresett = "best"\n', "presett", ("did you mean 'preset'",)),
    ('scene = "default"\n[identfy]\nseed = 1\n', "identfy", ("did you mean 'identify'",)),
    ('presett = "best"\n[identify]\nseed = 1\n', "presett", ("did you mean 'preset'",)),
    ('[study]\ncases = ["scene", "scene"]\n', "study.cases", ("'scene' twice",)),
    ('[control]\ntracked = ["q9"]\n', "control.tracked", ("'q9'",)),
    ('[control]\nmeasurement_noise = "q2=1e-6,q2=2e-6"\n', "control.measurement_noise", ()),
])
def test_control_study_settings_file_is_checked_before_any_work(
        tmp_path: Path, text: str, field: str, words: tuple[str, ...],
        capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("torch")
    settings = _settings(tmp_path, text)
    out = tmp_path / "study" / "out"
    bad_input(capsys, ["control-study", str(settings), "--out", str(out), "--quiet"], field,
              *words)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["settings.toml"]


def test_cases_given_twice_on_the_command_line(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("torch")
    bad_input(capsys, ["control-study", "--cases", "scene,fast,scene", "--out",
                       str(tmp_path / "o"), "--quiet"], "--cases", "twice")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("text", "field", "words"), [
    ('scene = "default"\npresett = "best"\n', "presett", ("did you mean 'preset'",)),
    ('scene = "default"\n[identfy]\nseed = 1\n', "identfy", ("did you mean 'identify'",)),
    ('scene = "default"\n[parameterz."friction.mu"]\nvalues = [0.1]\n', "parameterz",
     ("did you mean 'parameters'",)),
])
def test_simulate_names_a_misspelt_key_of_a_settings_or_sweep_file(
        tmp_path: Path, text: str, field: str, words: tuple[str, ...],
        capsys: pytest.CaptureFixture[str]) -> None:
    path = _settings(tmp_path, text)
    bad_input(capsys, ["simulate", str(path), "--out", str(tmp_path / "r.h5")], field, *words)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["settings.toml"]


@pytest.mark.parametrize(("argv", "usage", "hint"), [
    (["simulate", "--t-edn", "0.1"], "jointplay simulate", "did you mean '--t-end'?"),
    (["simulate", "--out=r.h5", "--plto", "p"], "jointplay simulate", "did you mean '--plot'?"),
    (["calibrate", "--measured", "m.csv", "--free", "friction.mu", "--out", "o", "--nosie",
      "1e-6"], "jointplay calibrate", "did you mean '--noise'?"),
    (["cache", "prune", "--max-sise", "1G"], "jointplay cache prune", "'--max-size'"),
    (["simulate", "a.toml", "b.toml"], "jointplay simulate", ""),
])
def test_a_misspelt_option_gets_the_command_usage_and_the_nearest_option(
        argv: list[str], usage: str, hint: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2
    assert f"usage: {usage}" in err and "unrecognized arguments" in err, err
    assert hint in err and "Traceback" not in err


# ---- the cache's folder ---------------------------------------------------------------------

@pytest.mark.parametrize("action", [["clear"], ["list"], ["prune", "--older-than", "0s"]])
@pytest.mark.parametrize("under", [False, True])
def test_cache_refuses_a_cache_that_is_a_file(
        tmp_path: Path, action: list[str], under: bool, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    plain = tmp_path / "plain"
    plain.write_text("mine\n", encoding="utf-8")
    monkeypatch.setenv("JOINTPLAY_CACHE", str(plain / "c" if under else plain))
    bad_input(capsys, ["cache", *action], "JOINTPLAY_CACHE", "not a folder" if not under
              else "which is a file")
    assert plain.read_text(encoding="utf-8") == "mine\n"
    assert [p.name for p in tmp_path.iterdir()] == ["plain"]


def test_cache_says_an_empty_variable_counts_as_unset(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setenv("JOINTPLAY_CACHE", "")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert main(["cache", "list"]) == 0
    out = capsys.readouterr().out
    assert f"cache {tmp_path / 'jointplay'} (default: JOINTPLAY_CACHE is empty" in out
    assert main(["cache", "clear"]) == 0
    assert "JOINTPLAY_CACHE is empty, which counts as unset" in capsys.readouterr().out


# ---- the units of a results file --------------------------------------------------------------

@pytest.fixture(scope="module")
def results_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    import jointplay
    from jointplay.results.write import write_hdf5

    path = tmp_path_factory.mktemp("units") / "run.h5"
    write_hdf5(jointplay.simulate(jointplay.default_scene().with_run(t_end=0.01)), path)
    return path


def _with_units(base: Path, target: Path, changes: dict[str, str]) -> Path:
    """A copy of ``base`` with the units of variables changed and its checksum stamped again
    over the edit (as a tool that rescaled them would)."""
    import shutil

    import h5py

    from jointplay.results import integrity

    shutil.copyfile(base, target)
    with h5py.File(target, "r+") as fh:
        for name, unit in changes.items():
            fh[name].attrs["units"] = unit
        fh.attrs[integrity.DIGEST_ATTRIBUTE] = integrity.digest(integrity.load(fh, target))
    return target


@pytest.mark.parametrize(("variable", "unit", "attribute", "scale"), [
    ("tip_position", "mm", "tip_position", 1e-3),
    ("tip_velocity", "mm s-1", "tip_velocity", 1e-3),
    ("tip_acceleration", "m/s^2", "tip_acceleration", 1.0),
    ("joint_angle", "deg", "q", None),
    ("eccentricity", "um", "eccentricity", 1e-6),
    ("drive_torque", "kN m", "tau", 1e3),
])
def test_a_units_attribute_of_the_same_kind_is_converted(
        results_file: Path, tmp_path: Path, variable: str, unit: str, attribute: str,
        scale: float | None) -> None:
    import math

    import numpy as np

    import jointplay

    original = jointplay.read(results_file)
    edited = jointplay.read(_with_units(results_file, tmp_path / "e.h5", {variable: unit}))
    before, after = getattr(original, attribute), getattr(edited, attribute)
    if scale is None:  # the angles: only the angle columns are in degrees
        angles = [i for i, n in enumerate(original.coordinate_names) if n.startswith("q")]
        np.testing.assert_allclose(after[:, angles], before[:, angles] * math.pi / 180,
                                   rtol=1e-15)
    else:
        np.testing.assert_allclose(after, before * scale, rtol=1e-15)


@pytest.mark.parametrize(("variable", "unit"), [
    ("tip_position", "kg"), ("time", "m"), ("joint_angle", "furlong"), ("tip_position", ""),
    ("impact_joint", "m"), ("energy_total", "N"), ("tip_velocity", "m s-2")])
def test_a_units_attribute_of_another_kind_is_refused(
        results_file: Path, tmp_path: Path, variable: str, unit: str) -> None:
    import jointplay
    from jointplay.common.errors import DescriptionError

    edited = _with_units(results_file, tmp_path / "e.h5", {variable: unit})
    with pytest.raises(DescriptionError, match=f"{variable}@units") as caught:
        jointplay.read(edited)
    assert str(edited) in str(caught.value)


def test_units_parse_the_writer_s_every_unit() -> None:
    from jointplay.results.units import expected_units, parse

    for unit in set(expected_units().values()):
        read = parse(unit)
        assert read is not None and read[0] == 1.0, unit
