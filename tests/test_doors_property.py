"""Property-based: generated scene, robot and sweep documents, valid and broken, through both
front doors. The TOML door writes the document to a file and reads it; the API door makes the
same changes to the built-in scene through the Python API (``with_parameters`` and
``with_robot``, ``with_initial``, ``with_run``, ``with_torques``; the sweep's cases through
``simulate``'s ``parameters=`` check). Neither may raise anything but a
:class:`DescriptionError`; every refusal names fields of the sections that were changed; and
both doors give the same verdict, field for field. Nothing is simulated.
"""

from __future__ import annotations

import json
import math
import tomllib
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from jointplay import DescriptionError, default_scene, load_scene
from jointplay.robot import with_parameters
from jointplay.robot.description import parameter_name
from jointplay.scene.definition import Scene
from jointplay.sim.problem import check_parameters
from jointplay.sweep.spec import load_sweep

SCENE_FILE = Path(__file__).resolve().parent.parent / "scenes" / "paper_4dof.toml"
BASE_DOCUMENT = tomllib.loads(SCENE_FILE.read_text(encoding="utf-8"))
BASE = default_scene()
PARAMETERS = [p.name for p in BASE.robot.parameters()]
# Misspelt names: each has a TOML place (a table that exists) and an API name.
MISSPELT = ["link1.lenght", "joint2.bearing_radus", "contact.exponet", "friction.muu"]
INITIAL_KEYS = ["q2", "q3", "ex2", "ey2", "ex3", "ey3", "dq2", "dq3", "dex2", "dey3", "q9",
                "qq2", "dq7", "ex4"]
RUN_KEYS = ["t_end", "output_step", "integrator", "rtol", "atol", "step", "max_steps",
            "t_edn", "foo"]
TORQUE_KEYS = ["joint2", "joint3", "joint9"]

SPECIAL = [0.0, -1.0, 1.0, 1e300, -1e300, 1e-300, 5e-324, math.nan, math.inf, -math.inf,
           0.5, 1e-3, 2.0, 1e-5]
numbers = st.one_of(st.sampled_from(SPECIAL),
                    st.floats(min_value=-1e6, max_value=1e6, allow_nan=False),
                    st.floats(allow_nan=True, allow_infinity=True))


def near_default(name: str) -> st.SearchStrategy[float]:
    """A plausible value: the default scaled by 0.5 to 2 (or the default of a zero)."""
    default = BASE.robot.parameter_values()[PARAMETERS.index(name)] \
        if name in PARAMETERS else 1.0
    return st.floats(min_value=0.5, max_value=2.0).map(lambda f: default * f)


@st.composite
def robot_edits(draw: st.DrawFn) -> dict[str, Any]:
    names = draw(st.lists(st.sampled_from(PARAMETERS + MISSPELT), max_size=3, unique=True))
    edits: dict[str, Any] = {}
    for name in names:
        edits[name] = draw(st.one_of(numbers, near_default(name), st.just("x")))
    return edits


initial_values = st.one_of(numbers, st.sampled_from(["-pi/2", "pi", "t", "sin(", "1e-5"]))
run_values = st.one_of(numbers, st.integers(-5, 10**6), st.sampled_from(
    ["bdf", "rk4", "cvodes", "rk5", "x"]))
torque_values = st.one_of(st.sampled_from(["sin(t)", "2*t", "1/t", "1/(t-0.5)", "sin(",
                                           "__import__('os')", "A*t", "exp(1000*t)"]),
                          st.floats(min_value=-100, max_value=100))


@st.composite
def scene_edits(draw: st.DrawFn) -> dict[str, dict[str, Any]]:
    return {
        "robot": draw(robot_edits()),
        "initial": draw(st.dictionaries(st.sampled_from(INITIAL_KEYS), initial_values,
                                        max_size=2)),
        "run": draw(st.dictionaries(st.sampled_from(RUN_KEYS), run_values, max_size=2)),
        "torques": draw(st.dictionaries(st.sampled_from(TORQUE_KEYS), torque_values,
                                        max_size=2)),
    }


# ---- the TOML door -------------------------------------------------------------------------------

def toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{json.dumps(k)} = {toml_value(v)}"
                               for k, v in value.items()) + "}"
    raise TypeError(type(value))


def toml_document(data: dict[str, Any]) -> str:
    """Every top-level key on one line (inline tables): enough for these documents."""
    return "\n".join(f"{json.dumps(k)} = {toml_value(v)}" for k, v in data.items()) + "\n"


def place_parameter(robot: dict[str, Any], name: str, value: Any) -> None:
    """Write one robot parameter where a robot file has it."""
    owner, attribute = name.split(".", 1)
    for table, prefix in (("links", "link"), ("joints", "joint")):
        if owner.startswith(prefix) and owner[len(prefix):].isdigit():
            robot[table][int(owner[len(prefix):]) - 1][attribute] = value
            return
    if owner == "gravity":
        robot["gravity"]["vector"]["xy".index(attribute)] = value
        return
    robot.setdefault(owner, {})[attribute] = value


def scene_document(edits: dict[str, dict[str, Any]]) -> dict[str, Any]:
    data = json.loads(json.dumps(BASE_DOCUMENT))  # a deep copy
    for name, value in edits["robot"].items():
        place_parameter(data["robot"], name, value)
    data["initial"].update(edits["initial"])
    data["run"].update(edits["run"])
    data["torques"].update(edits["torques"])
    return data


def verdict(call: Callable[[], Any]) -> set[str] | None:
    """None when accepted, else the fields refused (named as the parameter vector names
    them). Anything but a DescriptionError fails the test: never a traceback."""
    try:
        call()
    except DescriptionError as err:
        found = {parameter_name(p.field) for p in err.problems}
        assert all(found), err
        return found
    return None


def through_toml(data: dict[str, Any], folder: Path) -> set[str] | None:
    path = folder / "scene.toml"
    path.write_text(toml_document(data), encoding="utf-8")
    return verdict(lambda: load_scene(path))


# ---- the API door --------------------------------------------------------------------------------

def through_api(edits: dict[str, dict[str, Any]]) -> tuple[set[str], set[str]]:
    """The same changes through the Python API; (fields refused, steps refused)."""
    refused: set[str] = set()
    steps: set[str] = set()
    scene: Scene = BASE

    def step(name: str, change: Callable[[Scene], Scene]) -> None:
        nonlocal scene
        found = verdict(lambda: change(scene))
        if found is None:
            scene = change(scene)
        else:
            refused.update(found)
            steps.add(name)

    if edits["robot"]:
        step("robot", lambda s: s.with_robot(with_parameters(s.robot, edits["robot"])))
    if edits["initial"]:
        step("initial", lambda s: s.with_initial(edits["initial"]))
    if edits["run"]:
        step("run", lambda s: s.with_run(**edits["run"]))
    if edits["torques"]:
        step("torques", lambda s: s.with_torques(edits["torques"]))
    return refused, steps


def section(field: str) -> str:
    head = field.split(".", 1)[0].split("[", 1)[0]
    return head if head in ("initial", "run", "torques") else "robot"


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("doors")


@settings(max_examples=250, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(edits=scene_edits())
def test_scene_documents_get_the_same_verdict_through_both_doors(
        edits: dict[str, dict[str, Any]], folder: Path) -> None:
    by_file = through_toml(scene_document(edits), folder)
    by_api, api_steps = through_api(edits)
    event("accepted" if by_file is None else "refused")
    assert (by_file is None) == (not by_api), (edits, by_file, by_api)
    if by_file is None:
        return
    edited = {name for name, changes in edits.items() if changes}
    assert {section(f) for f in by_file} <= edited, (edits, by_file)
    assert {section(f) for f in by_api} <= edited, (edits, by_api)
    # A refused robot leaves nothing to check the file's initial state and torques against;
    # the API checks them against the robot it still has. Compare what both could check.
    compared = {"robot", "run"} if "robot" in api_steps else edited

    def keep(found: set[str]) -> set[str]:
        return {f for f in found if section(f) in compared}

    assert keep(by_file) == keep(by_api), (edits, by_file, by_api)


# ---- robot documents -----------------------------------------------------------------------------

@settings(max_examples=100, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(edits=robot_edits())
def test_robot_documents_get_the_same_verdict_through_both_doors(
        edits: dict[str, Any], folder: Path) -> None:
    from jointplay import load_robot

    data = json.loads(json.dumps(BASE_DOCUMENT["robot"]))
    for name, value in edits.items():
        place_parameter(data, name, value)
    path = folder / "robot.toml"
    path.write_text(toml_document(data), encoding="utf-8")
    by_file = verdict(lambda: load_robot(path))
    by_api = verdict(lambda: with_parameters(BASE.robot, edits))
    event("accepted" if by_file is None else "refused")
    assert by_file == by_api, (edits, by_file, by_api)


# ---- sweep documents -----------------------------------------------------------------------------

@st.composite
def sweep_axis(draw: st.DrawFn) -> tuple[str, list[Any]]:
    name = draw(st.sampled_from(PARAMETERS))
    values = draw(st.lists(st.one_of(numbers, near_default(name)), min_size=1, max_size=3,
                           unique_by=lambda v: repr(v)))
    return name, values


@settings(max_examples=100, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(axis=sweep_axis(), t_end=st.sampled_from([0.5, 1.0, -1.0, math.nan]))
def test_sweep_documents_refuse_what_the_api_refuses(axis: tuple[str, list[Any]], t_end: float,
                                                     folder: Path) -> None:
    name, values = axis
    data = {"scene": str(SCENE_FILE), "run": {"t_end": t_end},
            "parameters": {name: {"values": values}}}
    path = folder / "sweep.toml"
    path.write_text(toml_document(data), encoding="utf-8")
    by_file = verdict(lambda: load_sweep(path))
    # the API: the run settings, then each case's parameters as simulate(parameters=) gets them
    run_refused = verdict(lambda: BASE.with_run(t_end=t_end))
    cases_refused = [verdict(lambda v=v: check_parameters(BASE, {name: v})) for v in values]
    api_refuses = run_refused is not None or any(c is not None for c in cases_refused)
    event("accepted" if by_file is None else "refused")
    if by_file is None:
        assert not api_refuses, (data, run_refused, cases_refused)
        return
    assert all(f.startswith(("run.", "parameters")) for f in by_file), by_file
    assert api_refuses or _repeats(values), (data, by_file)


def _repeats(values: list[Any]) -> bool:
    """Two values that give the same parameter vector (a sweep refuses repeated cases)."""
    seen = [float(v).hex() for v in values if isinstance(v, float)]
    return len(set(seen)) < len(seen)
