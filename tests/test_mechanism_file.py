"""Mechanism files: validated completely, refused with the field and the fix (exit 2, nothing
written), never executed; and the command line on a mechanism file."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from jointplay.cli import main
from jointplay.common.errors import DescriptionError
from jointplay.mechanism.reading import is_mechanism_file, load_mechanism_scene

SCENE = Path("scenes/slider_crank.toml")
TEXT = SCENE.read_text(encoding="utf-8")


def _variant(tmp_path: Path, old: str, new: str, count: int = 1) -> Path:
    assert TEXT.count(old) >= count, old
    path = tmp_path / "variant.toml"
    path.write_text(TEXT.replace(old, new, count), encoding="utf-8")
    return path


def _refused(path: Path) -> str:
    with pytest.raises(DescriptionError) as caught:
        load_mechanism_scene(path)
    return str(caught.value)


def test_the_scenes_read_and_are_mechanisms() -> None:
    for name in ("slider_crank", "slider_crank_0_1mm", "slider_crank_friction"):
        path = Path(f"scenes/{name}.toml")
        assert is_mechanism_file(path)
        scene = load_mechanism_scene(path)
        assert scene.name == name
    assert not is_mechanism_file(Path("scenes/paper_4dof.toml"))
    scene = load_mechanism_scene(SCENE)
    structure = scene.mechanism.structure()
    assert [j.name for j in structure.cut_joints] == ["slider_pin"]
    assert structure.driver is not None and structure.driver.name == "crank_pivot"
    joint = next(j for j in scene.mechanism.joints if j.name == "slider_pin")
    assert joint.radial_clearance == pytest.approx(0.5e-3, abs=1e-15)
    clearance_0_1 = next(j for j in load_mechanism_scene(
        "scenes/slider_crank_0_1mm.toml").mechanism.joints if j.name == "slider_pin")
    assert clearance_0_1.radial_clearance == pytest.approx(0.1e-3, abs=1e-15)


def test_a_loop_of_ideal_joints_is_refused_with_the_fix(tmp_path: Path) -> None:
    path = _variant(tmp_path, 'kind = "clearance"', 'kind = "ideal"')
    text = path.read_text(encoding="utf-8")
    text = re.sub(r"^(bearing|journal)_(radius|E|nu) = .*$", "", text, flags=re.MULTILINE)
    path.write_text(text, encoding="utf-8")
    message = _refused(path)
    assert "closes a loop" in message and "no clearance joint" in message
    assert 'kind = "clearance"' in message


@pytest.mark.parametrize(("old", "new", "field", "words"), [
    ("mass = 0.30", "mas = 0.30", "mechanism.bodies[1].mas", "did you mean 'mass'"),
    ('type = "prismatic"', 'type = "prismatc"', "mechanism.joints[3].type", "prismatic"),
    ('parent = "slider"', 'parent = "sldier"', "mechanism.joints[4].parent",
     "did you mean 'slider'"),
    ('joint = "crank_pivot"', 'joint = "guide"', "mechanism.driver.joint",
     "ideal revolute"),
    ("journal_radius = 10.0e-3", "journal_radius = 10.6e-3", "journal_radius",
     "smaller than bearing_radius"),
    ('angle = "2*pi*5000/60*t"', 'angle = "__import__(1)"', "mechanism.driver.angle",
     "not allowed"),
    ('angle = "2*pi*5000/60*t"', 'angle = "2*pi*t"\nspeed = 3.0', "mechanism.driver",
     "not both"),
    ("t_end = 0.012", "t_end = 0.0120001", "run.output_step", "divide"),
    ("mass = 0.21", "mass = -0.21", "mechanism.bodies[2].mass", "outside the range"),
])
def test_bad_fields_are_named_with_what_is_allowed(tmp_path: Path, old: str, new: str,
                                                   field: str, words: str) -> None:
    message = _refused(_variant(tmp_path, old, new))
    assert field in message and words in message, message


def test_a_body_held_by_clearance_joints_only_floats(tmp_path: Path) -> None:
    # The slider's guide removed: the slider hangs on the clearance joint alone, free in the
    # plane (x, y, angle).
    start = TEXT.index('name = "guide"')
    block_start = TEXT.rindex("[[mechanism.joints]]", 0, start)
    block_end = TEXT.index("[[mechanism.joints]]", start)
    path = tmp_path / "variant.toml"
    path.write_text(TEXT[:block_start] + TEXT[block_end:], encoding="utf-8")
    structure = load_mechanism_scene(path).mechanism.structure()
    floating = [j for j in structure.joints if j.type == "floating"]
    assert [j.child for j in floating] == ["slider"]
    # A body no joint touches is refused.
    path.write_text(TEXT.replace("[[mechanism.joints]]", '[[mechanism.bodies]]\nname = '
                                 '"extra"\nmass = 1.0\ninertia = 1.0\n\n[[mechanism.joints]]', 1),
                    encoding="utf-8")
    message = _refused(path)
    assert "'extra'" in message and "joined to nothing" in message


def test_the_command_refuses_with_exit_2_and_writes_nothing(tmp_path: Path,
                                                            capsys: pytest.CaptureFixture[str]
                                                            ) -> None:
    path = _variant(tmp_path, "mass = 0.30", "mas = 0.30")
    figures = tmp_path / "figures"
    assert main(["simulate", str(path), "--plot", str(figures)]) == 2
    assert "did you mean 'mass'" in capsys.readouterr().err
    assert not figures.exists()
    assert main(["simulate", str(SCENE), "--animate", str(tmp_path / "a.avi")]) == 2
    assert "must end in .gif or .mp4" in capsys.readouterr().err
    assert main(["simulate", str(SCENE), "--set", "crank.mas=1"]) == 2
    assert "--set crank.mas" in capsys.readouterr().err
    # A number of an effect the file switched off would change nothing: refused.
    assert main(["simulate", str(SCENE), "--set", "friction.mu=0.02"]) == 2
    assert "friction is off" in capsys.readouterr().err
    assert not list(tmp_path.glob("*.gif"))


def test_simulate_compare_ideal_plot(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    figures = tmp_path / "figures"
    csv = tmp_path / "run.csv"
    assert main(["simulate", str(SCENE), "--compare-ideal", "--plot", str(figures),
                 "--csv", str(csv), "--t-end", "0.003"]) == 0
    out = capsys.readouterr().out
    assert "impacts" in out and "from the ideal mechanism" in out and "accuracy" in out
    assert sorted(p.name for p in figures.iterdir()) == sorted([
        "slider_acceleration.png", "slider_velocity.png", "journal_orbit.png",
        "contact_force.png", "driving_torque.png"])
    header = csv.read_text(encoding="utf-8").splitlines()[0].split(",")
    assert header[:2] == ["time", "guide.position"] and "slider_pin.normal_force" in header
    assert len(csv.read_text(encoding="utf-8").splitlines()) == 302


def test_inspect_build_derive_and_the_python_api(tmp_path: Path,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    import jointplay

    assert main(["inspect", str(SCENE)]) == 0
    out = capsys.readouterr().out
    assert "slider_pin: revolute clearance, slider -> rod (cut: a force element)" in out
    assert "slider_pin.bearing_radius = 0.0105" in out
    assert main(["build", str(SCENE)]) == 0
    assert "guide.position, crank_pin.angle, t" in capsys.readouterr().out
    assert main(["derive", str(SCENE), "--out", str(tmp_path / "model")]) == 0
    text = (tmp_path / "model" / "model.c").read_text(encoding="utf-8")
    assert text.startswith("/* GENERATED FILE: DO NOT EDIT.") and "input hash: " in text
    with pytest.raises(DescriptionError, match="load_mechanism_scene"):
        jointplay.load_scene(SCENE)
    scene = jointplay.load_mechanism_scene(SCENE).with_run(t_end=0.002)
    result = jointplay.simulate_mechanism(scene, parameters={"crank_pin.parent_x": 0.04},
                                          compare_ideal=True)
    assert result.ideal is not None
    # A 0.04 m crank: the ideal slider starts at r + l.
    assert result.ideal["x"][0, 0] == pytest.approx(0.16, abs=1e-14)
    with pytest.raises(DescriptionError, match="jointplay inspect"):
        jointplay.simulate_mechanism(scene, parameters={"crank.length": 0.04})


def test_the_reference_page_lists_every_key() -> None:
    from jointplay.mechanism import reading

    page = Path("docs/reference/mechanism-file.md").read_text(encoding="utf-8")
    keys = [*(k for k in reading._TOP if k not in ("mechanism", "run")),
            "[[mechanism.bodies]]", "[[mechanism.joints]]",
            *(f"bodies.{k}" for k in reading._BODY), *(f"joints.{k}" for k in reading._JOINT),
            *(f"mechanism.driver.{k}" for k in reading._DRIVER),
            *(f"mechanism.gravity.{k}" for k in reading._GRAVITY),
            *(f"mechanism.contact.{k}" for k in reading._CONTACT),
            *(f"mechanism.friction.{k}" for k in reading._FRICTION),
            "[mechanism.torques]", "[[mechanism.forces]]",
            *(f"forces.{k}" for k in reading._FORCE),
            *(f"output.{k}" for k in reading._OUTPUT),
            *(f"run.{k}" for k in reading._RUN)]
    missing = [k for k in keys if f"`{k}`" not in page]
    assert not missing, f"keys missing from docs/reference/mechanism-file.md: {missing}"


def test_the_reference_pages_example_is_a_mechanism_file(tmp_path: Path) -> None:
    """The page's example (a shortened slider-crank) loads, and is the scene's mechanism."""
    page = Path("docs/reference/mechanism-file.md").read_text(encoding="utf-8")
    examples = re.findall(r"```toml\n(.*?)```", page, flags=re.DOTALL)
    assert len(examples) == 1
    path = tmp_path / "example.toml"
    path.write_text(examples[0], encoding="utf-8")
    example = load_mechanism_scene(path)
    assert example.mechanism.structure() == load_mechanism_scene(SCENE).mechanism.structure()
    assert example.output_coordinate == "guide.position"


def test_a_sweep_of_a_mechanism(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "slider_crank.toml").write_text(TEXT, encoding="utf-8")
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('scene = "slider_crank.toml"\nmode = "zip"\n[run]\nt_end = 0.002\n'
                     '[parameters."slider_pin.clearance"]\nvalues = [1e-4, 5e-4]\n'
                     '[parameters."rod.mass"]\nvalues = [0.21, 0.3]\n', encoding="utf-8")
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--out", str(out), "--quiet"]) == 0
    lines = (out / "mechanism_sweep.csv").read_text(encoding="utf-8").splitlines()
    header = lines[0].split(",")
    assert header[:4] == ["slider_pin.clearance", "rod.mass", "impacts", "impact_rate"]
    assert len(lines) == 3
    first = dict(zip(header, map(float, lines[1].split(",")), strict=True))
    assert first["slider_pin.clearance"] == 1e-4 and first["rod.mass"] == 0.21
    # Within its clearance and a penetration from the ideal mechanism's slider.
    assert 1e-4 <= first["slider_from_ideal_m"] < 2e-4
    assert first["output_from_ideal"] == first["slider_from_ideal_m"]  # the slider's output
    assert (out / "mechanism_sweep.png").is_file()
    sweep.write_text('scene = "slider_crank.toml"\n[parameters."rod.mas"]\nvalues = [0.2]\n',
                     encoding="utf-8")
    assert main(["sweep", str(sweep), "--out", str(tmp_path / "bad")]) == 2
    assert "rod.mas" in capsys.readouterr().err
    assert not (tmp_path / "bad").exists()


def test_calibrate_checks_a_mechanisms_outputs_at_the_door(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """An arm's joint angle is no output of the slider-crank (tests/test_mechanism_calibration
    calibrates one)."""
    measured = tmp_path / "measured.csv"
    measured.write_text("time,q2\n0,0\n", encoding="utf-8")
    assert main(["calibrate", str(SCENE), "--measured", str(measured), "--free",
                 "rod.mass", "--out", str(tmp_path / "cal")]) == 2
    assert "q2: is not an output of this mechanism" in capsys.readouterr().err
    assert not (tmp_path / "cal").exists()


def test_a_journal_through_its_bearing_stops_the_run(tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    """Rubber-soft contact (E = 10 MPa) lets the journal sink 16 mm into its bearing: the
    run stops (exit 1) at the onset of that contact, by its located deepest point, and writes
    nothing."""
    figures = tmp_path / "figures"
    assert main(["simulate", str(SCENE), "--set", "slider_pin.bearing_E=1e7", "--set",
                 "slider_pin.journal_E=1e7", "--no-verify", "--plot", str(figures)]) == 1
    err = capsys.readouterr().err
    assert "simulation stopped at t = 0.000227" in err and "into its bearing" in err
    assert not figures.exists()


def test_results_file_plot_and_compare(tmp_path: Path, capsys: pytest.CaptureFixture[str]
                                       ) -> None:
    import h5py

    from jointplay.mechanism.results import read_mechanism_result

    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    assert main(["simulate", str(SCENE), "--out", str(a), "--compare-ideal", "--t-end",
                 "0.003", "--no-verify", "--quiet"]) == 0
    assert main(["simulate", "scenes/slider_crank_0_1mm.toml", "--out", str(b), "--t-end",
                 "0.003", "--no-verify", "--quiet"]) == 0
    run = read_mechanism_result(a)
    assert run.coordinates == ["guide.position", "crank_pin.angle", "t"]
    assert run.output == "guide.position"  # the coordinate the figures follow, kept
    assert run.ideal is not None and len(run.impacts) > 3
    assert main(["plot", str(a), "--out", str(tmp_path / "plots")]) == 0
    assert (tmp_path / "plots" / "journal_orbit.png").is_file()
    capsys.readouterr()
    assert main(["compare", str(a), str(b), "--out", str(tmp_path / "cmp")]) == 0
    out = capsys.readouterr().out
    assert "| a | " in out and "| b | " in out
    assert sorted(p.name for p in (tmp_path / "cmp").iterdir()) == sorted([
        "slider_acceleration.png", "driving_torque.png", "journal_orbit.png",
        "contact_force.png"])
    with h5py.File(b, "r+") as fh:  # a changed file is refused
        fh["x"][0, 0] = 1.0
    assert main(["plot", str(b), "--out", str(tmp_path / "plots_b")]) == 2
    assert "changed after it was written" in capsys.readouterr().err
    assert not (tmp_path / "plots_b").exists()


def test_the_arms_entry_points_point_a_mechanism_to_its_own(tmp_path: Path) -> None:
    """jointplay.simulate, Stepper and read, given a mechanism, say which function takes it
    (they failed on a missing attribute)."""
    import jointplay
    from jointplay.mechanism.results import write_mechanism_result

    scene = load_mechanism_scene(SCENE).with_run(t_end=0.001)
    for entry in (jointplay.simulate, jointplay.Stepper):
        with pytest.raises(DescriptionError, match=r"simulate_mechanism\(scene\)") as info:
            entry(scene)  # type: ignore[arg-type]
        assert info.value.field == "scene"
    path = tmp_path / "crank.h5"
    write_mechanism_result(jointplay.simulate_mechanism(scene), path)
    with pytest.raises(DescriptionError, match="read_mechanism_result"):
        jointplay.read(path)
