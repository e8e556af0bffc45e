"""Scenes: a robot, the effects it calls for, drive torques, an initial state and run settings.

A scene is a TOML file of data. It is validated completely before anything is derived or
compiled, and never executed: torque expressions go through the restricted parser of
:mod:`jointplay.scene.expressions` and :mod:`jointplay.scene.tables`. Every error names the
file, the field and what is allowed.

    name = "two_link"
    [robot]                  # a robot description (see README), or robot = "robot.toml"
    ...
    [constants]              # named numbers usable in the expressions below
    A = 4.0
    [torques]                # per moving joint: an expression of t; absent joints get 0 N m
    joint2 = "A*sin(2*pi*t)" # or: table = "torques.csv" (t, then one column per driven joint)
    [initial]                # coordinates (q2, ex2, ...) and speeds (dq2, dex2, ...); default 0
    q2 = "-pi"
    journals = "resting"     # or "centred" (default): each journal at rest in its bearing
    [run]
    t_end = 2.0
    output_step = 1e-3
    integrator = "bdf"       # bdf | cvodes | idas | rk4 | radau
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from jointplay.common import limits
from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import check_keys, read_toml
from jointplay.robot import Joint, JointKind, Robot, load_robot, robot_from_dict
from jointplay.robot.structure import coordinate_layout
from jointplay.scene.expressions import FUNCTIONS, TimeFunction, parse_expression
from jointplay.scene.tables import load_torque_table

INTEGRATORS: tuple[str, ...] = ("bdf", "cvodes", "idas", "rk4", "radau")
ADAPTIVE: tuple[str, ...] = ("bdf", "cvodes", "idas")

_TOP_KEYS = ("name", "description", "robot", "constants", "torques", "initial", "run")
_RUN_KEYS = ("t_end", "output_step", "integrator", "rtol", "atol", "step", "max_steps")


@dataclass(frozen=True)
class RunSettings:
    """How a scene is integrated.

    ``rtol``/``atol`` set the adaptive integrators' local error tolerances; ``atol`` is
    absolute in scaled units (radians and rad/s for angles; fractions of the joint's radial
    clearance for eccentricities, and of the clearance per millisecond for their rates), so
    one number serves both. ``step`` is the fixed step of ``rk4`` and ``radau`` (it must
    divide ``output_step``). ``max_steps`` bounds the work between two outputs.
    """

    t_end: float = 2.0
    output_step: float = 1e-3
    integrator: str = "bdf"
    rtol: float = 1e-6
    atol: float = 1e-5
    step: float = 1e-5
    max_steps: int = 200_000

    @property
    def n_outputs(self) -> int:
        return round(self.t_end / self.output_step)

    @property
    def steps_per_output(self) -> int:
        return max(1, round(self.output_step / self.step))


@dataclass(frozen=True)
class Scene:
    """A validated scene. ``torques`` has one time function per driven joint, in order."""

    name: str
    robot: Robot
    torques: tuple[TimeFunction, ...]
    torque_text: dict[str, str]
    initial: dict[str, float]
    run: RunSettings = field(default_factory=RunSettings)
    constants: dict[str, float] = field(default_factory=dict)
    source: str | None = None
    text: str = ""  # the scene file as read, kept with the results
    # "centred": the journals start at the eccentricities [initial] gives (default 0, the
    # bearing centres); "resting": at rest, each journal in static equilibrium in its bearing
    # under gravity (solved by the runtime: jointplay.sim.equilibrium)
    journals: str = "centred"

    def with_run(self, **changes: Any) -> Scene:
        """The same scene with some run settings changed (validated)."""
        run = replace(self.run, **changes)
        _validate_run(run, self.source)
        scene = replace(self, run=run)
        if {"t_end", "output_step"} & set(changes):  # a new output grid
            check_torques_finite(scene)
        return scene

    def with_robot(self, robot: Robot) -> Scene:
        return replace(self, robot=robot)

    def with_journals(self, journals: str) -> Scene:
        """The same scene starting with the journals ``"centred"`` or ``"resting"``."""
        _check_journals(journals, self.initial, self.source)
        return replace(self, journals=journals)


def ideal_counterpart(robot: Robot) -> Robot:
    """The same robot with every clearance joint made ideal (and locked play made locked)."""
    kinds: dict[JointKind, JointKind] = {"clearance": "ideal", "locked_clearance": "locked"}
    joints = tuple(replace(j, kind=kinds.get(j.kind, j.kind)) for j in robot.joints)
    return replace(robot, joints=joints, name=f"{robot.name}_ideal")


def _error(field_name: str, message: str, source: str | None) -> DescriptionError:
    return DescriptionError(field_name, message, source)


def _finite_number(value: Any, where: str, source: str | None) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise _error(where, f"must be a finite number in SI units, got {value!r}", source)
    return float(value)


def _positive_number(value: Any, where: str, source: str | None) -> float:
    number = _finite_number(value, where, source)
    if number <= 0:
        raise _error(where, f"must be > 0, got {value!r}", source)
    return number


def _validate_run(run: RunSettings, source: str | None) -> None:
    for name in ("t_end", "output_step", "rtol", "atol", "step"):
        _positive_number(getattr(run, name), f"run.{name}", source)
    if run.integrator not in INTEGRATORS:
        hint = did_you_mean(str(run.integrator), INTEGRATORS)
        raise _error("run.integrator", f"must be one of {', '.join(INTEGRATORS)}, got "
                     f"{run.integrator!r}{hint}", source)
    for name, low, high in (("t_end", 0.0, limits.MAX_T_END),
                            ("output_step", limits.MIN_OUTPUT_STEP, math.inf),
                            ("step", limits.MIN_STEP, math.inf),
                            ("rtol", limits.MIN_RTOL, math.inf),
                            ("atol", limits.MIN_ATOL, math.inf)):
        value = getattr(run, name)
        if value > high:
            raise _error(f"run.{name}", f"must be at most {high:g}, got {value:g}", source)
        if value < low:
            raise _error(f"run.{name}", f"must be at least {low:g}, got {value:g}", source)
    if run.t_end / run.output_step > limits.MAX_OUTPUTS + 0.5:
        raise _error("run.output_step", f"gives {run.t_end / run.output_step:.3g} output "
                     f"samples over run.t_end = {run.t_end:g} s; at most "
                     f"{limits.MAX_OUTPUTS} are allowed (raise output_step or shorten t_end)",
                     source)
    if run.integrator not in ADAPTIVE and run.t_end / run.step > limits.MAX_FIXED_STEPS:
        raise _error("run.step", f"gives {run.t_end / run.step:.3g} fixed steps over "
                     f"run.t_end = {run.t_end:g} s; at most {limits.MAX_FIXED_STEPS} are "
                     "allowed", source)
    if run.output_step > run.t_end:
        raise _error("run.output_step", f"must not exceed run.t_end ({run.t_end}), got "
                     f"{run.output_step}", source)
    if abs(run.n_outputs * run.output_step - run.t_end) > 1e-9 * run.t_end:
        raise _error("run.output_step", f"must divide run.t_end ({run.t_end}) into whole "
                     f"samples, got {run.output_step}", source)
    if run.integrator not in ADAPTIVE and (run.step > run.output_step or abs(
            run.steps_per_output * run.step - run.output_step) > 1e-9 * run.output_step):
        raise _error("run.step", f"the fixed step must divide run.output_step "
                     f"({run.output_step}), got {run.step}", source)
    if run.rtol >= 1:
        raise _error("run.rtol", f"must be < 1, got {run.rtol}", source)
    if isinstance(run.max_steps, bool) or not isinstance(run.max_steps, int) \
            or not 1 <= run.max_steps <= limits.MAX_MAX_STEPS:
        raise _error("run.max_steps", f"must be an integer from 1 to {limits.MAX_MAX_STEPS}, "
                     f"got {run.max_steps!r}", source)


def _run_settings(raw: Any, source: str | None) -> RunSettings:
    check_keys(raw, _RUN_KEYS, "run", source)
    values: dict[str, Any] = {}
    for key, value in raw.items():
        if key == "integrator":
            if not isinstance(value, str):
                raise _error("run.integrator",
                             f"must be one of {', '.join(INTEGRATORS)}, got {value!r}", source)
            values[key] = value
        elif key == "max_steps":
            values[key] = value
        else:
            values[key] = _finite_number(value, f"run.{key}", source)
    run = RunSettings(**values)
    _validate_run(run, source)
    return run


def _robot(raw: Any, base: Path | None, source: str | None) -> Robot:
    if isinstance(raw, str):
        path = (base / raw) if base is not None else Path(raw)
        if path.is_dir():
            raise _error("robot", f"{str(path)!r} is a folder, not a robot description file; "
                         "give the path of a robot TOML file, or a [robot] table", source)
        if not path.exists():
            raise _error("robot", f"robot description {str(path)!r} not found; give a path "
                         "relative to the scene file, or a [robot] table", source)
        return load_robot(path)
    if not isinstance(raw, Mapping):
        raise _error("robot", "must be a table (a robot description) or the path of one",
                     source)
    return robot_from_dict(raw, source)


def _constants(raw: Any, source: str | None) -> dict[str, float]:
    check_keys(raw, tuple(raw) if isinstance(raw, Mapping) else (), "constants", source)
    out: dict[str, float] = {}
    for key, value in raw.items():
        if not key.isidentifier() or key.startswith("_") or key in ("t", "pi", "e"):
            raise _error(f"constants.{key}", "a constant's name must be a plain identifier "
                         "(letters, digits, underscores; not starting with _), and not t, pi "
                         "or e", source)
        if key in FUNCTIONS:
            raise _error(f"constants.{key}", f"{key!r} is the name of a function "
                         f"({key}(x)); choose another name for the constant", source)
        out[key] = _finite_number(value, f"constants.{key}", source)
    return out


def _torques(raw: Any, robot: Robot, constants: Mapping[str, float], base: Path | None,
             source: str | None) -> tuple[tuple[TimeFunction, ...], dict[str, str]]:
    driven = robot.moving_joints if robot.drive else ()
    keys = tuple(f"joint{j}" for j in driven)
    check_keys(raw, (*keys, "table"), "torques", source)
    if raw and not robot.drive:
        raise _error("torques", "the robot's drive is disabled (drive.enabled = false); "
                     "remove [torques] or enable the drive", source)
    if "table" in raw:
        if len(raw) > 1:
            raise _error("torques.table", "give either a table or expressions, not both",
                         source)
        if not isinstance(raw["table"], str):
            raise _error("torques.table", "must be the path of a CSV file", source)
        path = (base / raw["table"]) if base is not None else Path(raw["table"])
        table = load_torque_table(path, columns=len(driven), field="torques.table",
                                  source=source)
        return (tuple(table.column(i) for i in range(len(driven))),
                {"table": str(raw["table"])})
    functions: list[TimeFunction] = []
    texts: dict[str, str] = {}
    for key in keys:
        text = raw.get(key, "0")
        if isinstance(text, (int, float)) and not isinstance(text, bool):
            text = repr(float(text))
        if not isinstance(text, str):
            raise _error(f"torques.{key}", "must be an expression of t (a string) or a "
                         "number", source)
        functions.append(parse_expression(text, field=f"torques.{key}",
                                          constants=constants, source=source))
        texts[key] = text
    return tuple(functions), texts


def scene_inputs(scene: Scene) -> list[Path]:
    """The files a scene was read from (the scene, its torque table): never outputs."""
    if scene.source is None:
        return []
    paths = [Path(scene.source)]
    if "table" in scene.torque_text:
        paths.append(Path(scene.source).parent / scene.torque_text["table"])
    return paths


def coordinate_names(robot: Robot) -> list[str]:
    """Generalised coordinates in model order: moving angles, then (ex, ey) per clearance."""
    return [c.name for c in coordinate_layout(robot.structure())]


def _initial(raw: Any, robot: Robot, constants: Mapping[str, float],
             source: str | None) -> dict[str, float]:
    coords = coordinate_names(robot)
    allowed = (*coords, *[f"d{c}" for c in coords])
    check_keys(raw, allowed, "initial", source)
    out: dict[str, float] = {}
    for key, value in raw.items():
        if isinstance(value, str):
            expr = parse_expression(value, field=f"initial.{key}", constants=constants,
                                    source=source)
            if not expr.is_constant:
                raise _error(f"initial.{key}", "must not depend on t", source)
            value = float(expr.numpy(0.0))
        out[key] = _finite_number(value, f"initial.{key}", source)
    for j, joint in enumerate(robot.joints, start=1):
        if joint.has_clearance:
            ex, ey = out.get(f"ex{j}", 0.0), out.get(f"ey{j}", 0.0)
            if math.hypot(ex, ey) > 2 * (joint.bearing_radius - joint.journal_radius):
                raise _error(f"initial.ex{j}", "the journal must start inside its bearing: "
                             f"|e| <= 2 x the radial clearance "
                             f"({joint.bearing_radius - joint.journal_radius:g} m)", source)
    return out


JOURNAL_STARTS = ("centred", "resting")


def _check_journals(journals: Any, initial: Mapping[str, float], source: str | None) -> None:
    if journals not in JOURNAL_STARTS:
        raise _error("initial.journals", f"must be one of {', '.join(JOURNAL_STARTS)}, got "
                     f"{journals!r}", source)
    if journals == "resting":
        given = sorted(k for k, v in initial.items()
                       if (k.startswith("d") or k.startswith(("ex", "ey"))) and v != 0)
        if given:
            raise _error("initial.journals", "\"resting\" starts at rest with the journals "
                         "where they rest: leave out the speeds and eccentricities "
                         f"({', '.join(given)})", source)


def scene_from_dict(data: Mapping[str, Any], *, source: str | None = None,
                    base: Path | None = None, text: str = "") -> Scene:
    """Validate a parsed scene document; relative paths resolve against ``base``."""
    check_keys(data, _TOP_KEYS, "", source)
    if "robot" not in data:
        raise _error("robot", "is required: a [robot] table or the path of a robot file",
                     source)
    robot = _robot(data["robot"], base, source)
    name = data.get("name", robot.name)
    if not isinstance(name, str) or not name:
        raise _error("name", f"must be a non-empty string, got {name!r}", source)
    if "description" in data and not isinstance(data["description"], str):
        raise _error("description", "must be a string", source)
    constants = _constants(data.get("constants", {}), source)
    torques, texts = _torques(data.get("torques", {}), robot, constants, base, source)
    raw_initial = data.get("initial", {})
    journals = "centred"
    if isinstance(raw_initial, Mapping) and "journals" in raw_initial:
        raw_initial = dict(raw_initial)
        journals = raw_initial.pop("journals")
    initial = _initial(raw_initial, robot, constants, source)
    _check_journals(journals, initial, source)
    run = _run_settings(data.get("run", {}), source)
    scene = Scene(name=name, robot=robot, torques=torques, torque_text=texts, initial=initial,
                  run=run, constants=constants, source=source, text=text, journals=journals)
    check_torques_finite(scene)
    return scene


def check_torques_finite(scene: Scene) -> None:
    """Refuse a torque that is not finite at an output time, naming the joint and the time.

    The simulation evaluates the torques at every output time (for the results) and near them
    (inside the integrator); a torque such as ``1/(t - 0.3)`` would put NaN or inf into the
    results, so it is refused before anything runs.
    """
    import numpy as np

    run = scene.run
    t = np.arange(run.n_outputs + 1) * run.output_step
    keys = [f"joint{j}" for j in scene.robot.moving_joints] if scene.robot.drive else []
    for k, torque in enumerate(scene.torques):
        values = np.asarray(torque.numpy(t), dtype=np.float64)
        bad = ~np.isfinite(values)
        if bad.any():
            i = int(np.argmax(bad))
            key = keys[k] if k < len(keys) else f"[{k}]"
            field_name = "torques.table" if "table" in scene.torque_text else f"torques.{key}"
            text = scene.torque_text.get(key)
            shown = f" {text!r}" if text else ""
            raise _error(field_name, f"the torque{shown} is {values[i]} at t = {t[i]:.9g} s "
                         "(an output time); every torque must be finite over [0, run.t_end]",
                         scene.source)


def load_scene(path: str | Path) -> Scene:
    """Read and validate a scene file."""
    path = Path(path)
    data, text = read_toml(path, "scene")
    source = str(path)
    return scene_from_dict(data, source=source, base=path.parent, text=text)


def default_scene() -> Scene:
    """The built-in default: the paper's example (``scenes/paper_4dof.toml``)."""
    from importlib.resources import files

    return load_scene(str(files("jointplay.scenes") / "paper_4dof.toml"))


__all__ = [
    "INTEGRATORS",
    "Joint",
    "RunSettings",
    "Scene",
    "check_torques_finite",
    "coordinate_names",
    "default_scene",
    "ideal_counterpart",
    "load_scene",
    "scene_from_dict",
    "scene_inputs",
]
