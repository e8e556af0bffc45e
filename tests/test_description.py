"""Robot descriptions: structure vs parameters, round trips, and bad input with clear errors."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest

import jointplay
from jointplay import DescriptionError, load_robot, robot_from_flags, uniform_chain, with_parameters
from jointplay.robot.robotio import robot_to_toml

PAPER = Path(jointplay.__file__).parent / "robots" / "paper_4dof.toml"


def test_paper_robot_structure_and_parameters() -> None:
    robot = jointplay.default_robot()
    assert robot.structure().as_dict() == {
        "links": 4, "joints": ["locked", "clearance", "clearance", "locked"], "gravity": True,
        "contact_law": "lankarani-nikravesh", "friction": "coulomb-linear", "drive": True}
    assert robot.moving_joints == (2, 3)
    assert robot.clearance_joints == (2, 3)
    values = dict(zip([p.name for p in robot.parameters()], robot.parameter_values(),
                      strict=True))
    assert values["joint2.bearing_radius"] - values["joint2.journal_radius"] == pytest.approx(
        3e-5, rel=1e-9)
    assert values["payload.mass"] == 2.0
    assert values["gravity.y"] == -9.81
    assert values["joint1.angle"] == pytest.approx(math.pi / 2)


def test_numbers_do_not_change_the_structure_hash() -> None:
    robot = jointplay.default_robot()
    heavier = jointplay.with_parameters(robot, {"payload.mass": 5.0, "friction.mu": 0.2,
                                                "joint2.journal_radius": 9.5e-3})
    assert heavier.structure_hash() == robot.structure_hash()
    assert heavier.parameter_values() != robot.parameter_values()
    no_friction = jointplay.Robot(links=robot.links, joints=robot.joints,
                                  friction=jointplay.Friction(law="none"))
    assert no_friction.structure_hash() != robot.structure_hash()
    assert not any(p.name.startswith("friction.") for p in no_friction.parameters())


def test_toml_round_trip(tmp_path: Path) -> None:
    robot = jointplay.default_robot()
    path = tmp_path / "robot.toml"
    path.write_text(robot_to_toml(robot))
    assert load_robot(path) == robot


def test_effects_absent_from_structure_have_no_parameters() -> None:
    robot = uniform_chain(3, gravity=jointplay.Gravity(enabled=False))
    names = [p.name for p in robot.parameters()]
    assert not any(n.startswith(("gravity.", "contact.", "friction.", "joint")) for n in names)


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "robot.toml"
    path.write_text(text)
    return path


LINK = "[[links]]\nlength = 0.3\nmass = 1.0\ninertia = 0.01\ncom = 0.15\n"
CLEARANCE = ('[[joints]]\nkind = "clearance"\nbearing_radius = 0.01\njournal_radius = 0.0099\n')


@pytest.mark.parametrize(
    ("text", "field", "message"),
    [
        ("links = []\n", "links", "non-empty array"),
        (LINK.replace("mass = 1.0", "mass = -1.0"), "links[1].mass", "must be > 0"),
        (LINK.replace("mass = 1.0", "mass = nan"), "links[1].mass", "finite number"),
        (LINK.replace("length = 0.3", "length = 0.0"), "links[1].length", "must be > 0"),
        (LINK.replace("inertia = 0.01", "inertia = -0.01"), "links[1].inertia", "must be > 0"),
        (LINK.replace("mass = 1.0", 'mass = "1 kg"'), "links[1].mass", "number in SI units"),
        (LINK.replace("mass = 1.0", "mas = 1.0"), "links[1].mas", "did you mean 'mass'"),
        (LINK + CLEARANCE.replace("0.0099", "0.01"), "joints[1].journal_radius",
         "smaller than bearing_radius"),
        (LINK + CLEARANCE.replace("0.0099", "0.02"), "joints[1].journal_radius",
         "smaller than bearing_radius"),
        (LINK + CLEARANCE + "journal_nu = 0.5\n", "joints[1].journal_nu", "(0, 0.5)"),
        (LINK + CLEARANCE + "bearing_nu = 0.0\n", "joints[1].bearing_nu", "(0, 0.5)"),
        (LINK + CLEARANCE + "bearing_E = -2e11\n", "joints[1].bearing_E", "must be > 0"),
        (LINK + '[[joints]]\nkind = ["clearance", "locked"]\n', "joints[1].kind", "one kind"),
        (LINK + '[[joints]]\nkind = "clearence"\n', "joints[1].kind", "did you mean 'clearance'"),
        (LINK + "[[joints]]\nkind = \"ideal\"\n[[joints]]\nkind = \"ideal\"\n", "joints",
         "one joint per link"),
        (LINK + "[frictoin]\nmu = 0.1\n", "frictoin", "did you mean 'friction'"),
        (LINK + "[friction]\nv0 = 0.1\nv1 = 0.01\n", "friction.v1", "must exceed"),
        (LINK + "[friction]\nv0 = -1e-4\n", "friction.v0", "must be >= 0"),
        (LINK + "[friction]\nv0 = 0.0\nv1 = 0.0\n", "friction.v1", "must be > 0"),
        (LINK + "[contact]\nrestitution = 1.5\n", "contact.restitution", "from 0.001 to 1"),
        (LINK + "[contact]\nlaw = \"hertz\"\n", "contact.law", "lankarani-nikravesh"),
        (LINK + "[gravity]\nvector = [0.0]\n", "gravity.vector", "[gx, gy]"),
        (LINK + '[[joints]]\nkind = "locked"\n', "joints", "at least one joint must move"),
        ("links = [\n", "(toml)", "malformed TOML"),
    ],
)
def test_bad_description_names_the_field(tmp_path: Path, text: str, field: str,
                                         message: str) -> None:
    path = _write(tmp_path, text)
    with pytest.raises(DescriptionError) as info:
        load_robot(path)
    assert info.value.field == field
    assert message in info.value.message
    assert str(path) in str(info.value)


def test_friction_from_zero_speed_is_accepted(tmp_path: Path) -> None:
    """v0 = 0: the dynamic correction ramps from zero speed (finite: see derive/laws.py)."""
    robot = load_robot(_write(tmp_path, LINK + CLEARANCE + "[friction]\nv0 = 0.0\n"))
    assert robot.friction.v0 == 0.0
    assert with_parameters(robot, {"friction.v0": 0.0}).friction.v0 == 0.0


@pytest.mark.parametrize(
    ("kwargs", "field", "message"),
    [
        ({"links": 0}, "--links", "from 1 to"),
        ({"links": "2.5"}, "--links", "integer"),
        ({"links": "two"}, "--links", "integer"),
        ({"links": 3, "clearance": "4"}, "--clearance", "out of range"),
        ({"links": 3, "clearance": "0"}, "--clearance", "out of range"),
        ({"links": 3, "clearance": "2", "locked": "2"}, "--locked", "two kinds"),
        ({"links": 3, "locked": "x"}, "--locked", "joint numbers"),
    ],
)
def test_bad_flags_name_the_flag(kwargs: dict, field: str, message: str) -> None:
    with pytest.raises(DescriptionError) as info:
        robot_from_flags(**kwargs)
    assert info.value.field == field
    assert message in info.value.message


def test_flags_build_the_requested_kinds() -> None:
    robot = robot_from_flags(6, clearance="2,5", locked="1", locked_clearance="6")
    assert [j.kind for j in robot.joints] == [
        "locked", "clearance", "ideal", "ideal", "clearance", "locked_clearance"]
    assert robot.clearance_joints == (2, 5, 6)
    assert robot.moving_joints == (2, 3, 4, 5)


def test_unknown_parameter_name_suggests_the_nearest() -> None:
    with pytest.raises(DescriptionError, match=r"did you mean 'link1\.mass'"):
        jointplay.with_parameters(uniform_chain(1), {"link1.mas": 2.0})


def _cli(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "jointplay.cli", *args], cwd=cwd,
                          capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize(
    "args",
    [
        ("derive", "--links", "0", "--out", "gen"),
        ("derive", "--links", "3", "--clearance", "7", "--out", "gen"),
        ("derive", "--links", "3", "--clearance", "2", "--locked", "2", "--out", "gen"),
        ("derive", "bad.toml", "--out", "gen"),
        ("derive", "missing.toml", "--out", "gen"),
        ("inspect", "bad.toml", "--out", "eq.md"),
        ("inspect", "--links", "2", "--out", "no/such/folder/eq.md"),
        ("build", "bad.toml"),
    ],
)
def test_cli_bad_input_exits_2_and_writes_nothing(tmp_path: Path, args: tuple[str, ...]) -> None:
    (tmp_path / "bad.toml").write_text(LINK + CLEARANCE.replace("0.0099", "0.0101"))
    before = sorted(p.name for p in tmp_path.rglob("*"))
    proc = _cli(*args, cwd=tmp_path)
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr.startswith("jointplay: error: ")
    assert "Traceback" not in proc.stderr
    assert sorted(p.name for p in tmp_path.rglob("*")) == before


@pytest.mark.slow
def test_cli_derive_and_inspect_write_their_outputs(tmp_path: Path) -> None:
    proc = _cli("derive", "--links", "2", "--clearance", "2", "--out", "gen", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert {p.name for p in (tmp_path / "gen").iterdir()} == {
        "model.c", "model_deferred.c", "layout.json", "robot.toml"}
    proc = _cli("inspect", str(tmp_path / "gen" / "robot.toml"), "--out", "eq.md", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    text = (tmp_path / "eq.md").read_text()
    for heading in ("## Coordinates", "## Parameters", "## Mass matrix", "## Forcing",
                    "## Contact and friction at clearance joint 2"):
        assert heading in text
    assert "$$" in text
    proc = _cli("inspect", "--links", "1", "--format", "latex", cwd=tmp_path)
    assert proc.returncode == 0
    assert "\\begin{align*}" in proc.stdout and "\\end{align*}" in proc.stdout
