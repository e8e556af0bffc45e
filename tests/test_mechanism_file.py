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


def test_a_body_no_ideal_joint_places_is_refused(tmp_path: Path) -> None:
    # The slider's guide removed: the slider hangs on the clearance joint alone.
    start = TEXT.index('name = "guide"')
    block_start = TEXT.rindex("[[mechanism.joints]]", 0, start)
    block_end = TEXT.index("[[mechanism.joints]]", start)
    path = tmp_path / "variant.toml"
    path.write_text(TEXT[:block_start] + TEXT[block_end:], encoding="utf-8")
    message = _refused(path)
    assert "slider" in message and "place" in message


def test_the_command_refuses_with_exit_2_and_writes_nothing(tmp_path: Path,
                                                            capsys: pytest.CaptureFixture[str]
                                                            ) -> None:
    path = _variant(tmp_path, "mass = 0.30", "mas = 0.30")
    figures = tmp_path / "figures"
    assert main(["simulate", str(path), "--plot", str(figures)]) == 2
    assert "did you mean 'mass'" in capsys.readouterr().err
    assert not figures.exists()
    assert main(["simulate", str(SCENE), "--animate", str(tmp_path / "a.gif")]) == 2
    assert "--animate" in capsys.readouterr().err
    assert main(["simulate", str(SCENE), "--set", "crank.mas=1"]) == 2
    assert "--set crank.mas" in capsys.readouterr().err
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
