"""Lubrication and wear as effects of a robot description: asked for, validated, compiled
only when asked; the lubricated paper arm simulated with its energy booked."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from jointplay import DescriptionError, load_robot, with_parameters
from jointplay.robot import Lubrication, Wear, robot_from_dict
from jointplay.robot.robotio import robot_to_toml

ROOT = Path(__file__).resolve().parent.parent
PAPER = ROOT / "generated" / "paper_4dof" / "robot.toml"


def _with_length(robot, length=10e-3):  # type: ignore[no-untyped-def]
    return replace(robot, joints=tuple(replace(j, length=length) if j.has_clearance else j
                                       for j in robot.joints))


def test_default_robot_is_untouched_by_the_effects() -> None:
    robot = load_robot(PAPER)
    assert "lubrication" not in robot.structure().as_dict()
    assert "wear" not in robot.structure().as_dict()
    names = [p.name for p in robot.parameters()]
    assert not any(n.startswith(("lubrication.", "wear.")) or (n.endswith(".length")
                   and n.startswith("joint")) for n in names)
    text = robot_to_toml(robot)
    assert "lubrication" not in text and "wear" not in text and "\nlength = 0.01" not in text
    # explicitly "none" is the same robot, the same structure hash
    same = replace(robot, lubrication=Lubrication(model="none"), wear=Wear(model="none"))
    assert same.structure_hash() == robot.structure_hash()


def test_effects_enter_structure_and_parameters_when_asked() -> None:
    robot = _with_length(load_robot(PAPER))
    lub = replace(robot, lubrication=Lubrication(model="long-bearing", viscosity=0.1))
    assert lub.structure().lubrication == "long-bearing"
    names = [p.name for p in lub.parameters()]
    assert {"joint2.length", "joint3.length", "lubrication.viscosity",
            "lubrication.transition"} <= set(names)
    assert lub.parameter_values()[names.index("lubrication.viscosity")] == 0.1
    worn = replace(robot, wear=Wear(model="archard"))
    assert {"wear.coefficient", "wear.hardness"} <= {p.name for p in worn.parameters()}
    changed = with_parameters(worn, {"wear.coefficient": 2e-4, "joint2.length": 0.02})
    assert changed.wear.coefficient == 2e-4 and changed.joints[1].length == 0.02
    assert changed.structure_hash() == worn.structure_hash()
    back = robot_from_dict(__import__("tomllib").loads(robot_to_toml(lub)))
    assert back == lub


@pytest.mark.parametrize("edit,field,message", [
    ({"lubrication": {"model": "short-bearing"}}, "joints[2].length", "is required by "
     "lubrication: the axial length of the journal and bearing in m; add e.g. length = 0.02"),
    ({"wear": {"model": "archard"}}, "joints[2].length", "is required by wear"),
    ({"lubrication": {"model": "finite"}}, "lubrication.model", "must be one of none, "
     "short-bearing, long-bearing"),
    ({"lubrication": {"transition": 1.0}}, "lubrication.transition", "in (0, 1)"),
    ({"lubrication": {"viscosity": -1.0}}, "lubrication.viscosity", "> 0"),
    ({"wear": {"hardness": 0.0}}, "wear.hardness", "> 0"),
    ({"wear": {"model": "archard", "coefficent": 1e-4}}, "wear.coefficent",
     "did you mean 'coefficient'"),
    ({"joint_length": -1.0}, "joints[2].length", "must be > 0"),
])
def test_bad_effect_input_names_the_field(edit: dict, field: str, message: str) -> None:
    import tomllib

    data = tomllib.loads(PAPER.read_text())
    length = edit.pop("joint_length", None)
    if length is not None:
        data["joints"][1]["length"] = length
    data.update(edit)
    with pytest.raises(DescriptionError) as err:
        robot_from_dict(data)
    assert err.value.field == field
    assert message in err.value.message


@pytest.fixture(scope="module")
def lubricated():  # type: ignore[no-untyped-def]
    from jointplay import simulate
    from jointplay.scene.definition import load_scene

    scene = load_scene(ROOT / "scenes" / "paper_4dof_lubricated.toml").with_run(t_end=0.4)
    return simulate(scene)


def test_lubricated_arm_books_its_energy(lubricated) -> None:  # type: ignore[no-untyped-def]
    """The film's work enters the dissipated energy, so the balance closes to the
    integration error, as for the dry arm (measured 1.9e-6 J over 2 s at the scene's
    tolerances, benchmarks/lubrication.py; here 0.4 s)."""
    balance = np.max(np.abs(lubricated.energy["balance"]))
    work = np.max(np.abs(lubricated.energy["drive_work"]))
    assert balance < 1e-3 * max(work, 1.0)
    assert lubricated.energy["dissipated"][-1] > 0


def test_lubricated_arm_floats_on_its_film(lubricated) -> None:  # type: ignore[no-untyped-def]
    """Under the arm's weight the film carries the journals without dry contact in 0.4 s:
    the eccentricity ratio stays below 1 and the total joint force is the film's."""
    ratio = np.linalg.norm(lubricated.eccentricity, axis=2) / lubricated.radial_clearance
    assert ratio.max() < 1.0
    assert len(lubricated.impacts) == 0 and np.all(lubricated.normal_force == 0)
    assert np.linalg.norm(lubricated.contact_force, axis=2).max() > 10.0  # carries the weight


@pytest.mark.parametrize("film", ["short-bearing",
                                  pytest.param("long-bearing", marks=pytest.mark.slow)])
def test_lubricated_and_worn_model_is_finite_at_singular_states(film: str) -> None:
    """The compiled model with a film and wear: every output and Jacobian block finite at
    e = 0, delta = 0 (film closed: eps = 1), v_t = 0 and |e| = 1e-15 (the dry law's checks,
    tests/test_dynamics.py), and the wear function's outputs too."""
    from test_dynamics import all_outputs, non_finite_report, singular_states, two_clearance_robot

    from jointplay.store.lookup import model_for

    robot = replace(_with_length(two_clearance_robot("hunt-crossley", "linear")),
                    lubrication=Lubrication(model=film), wear=Wear(model="archard"))
    model = model_for(robot)
    p = np.asarray(robot.parameter_values())
    rng = np.random.default_rng(3100)
    tau = rng.uniform(-1.0, 1.0, 2)
    failures = []
    for name, x in singular_states(robot, rng).items():
        for v_imp in (np.zeros(2), np.array([0.1, 0.3])):
            outputs = all_outputs(model, x, tau, p, v_imp)
            outputs.update({f"wear[{k}]": np.asarray(v) for k, v in
                            enumerate(model.function("wear")(x, p, v_imp))})
            bad = non_finite_report(model, outputs)
            if bad:
                failures.append(f"{name}, v_imp={v_imp}: " + "; ".join(bad))
    assert not failures, "\n".join(failures)
