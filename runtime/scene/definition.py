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
    joint2 = "A*sin(2*pi*t)" # or: table = "torques.csv" (t, then one column per driven joint,
                             # covering [0, t_end]; hold_ends = true holds its end rows)
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
from jointplay.common.validation import Problems, check_keys, read_toml
from jointplay.robot import Joint, JointKind, Robot, load_robot, robot_from_dict
from jointplay.scene.expressions import FUNCTIONS, TimeFunction, parse_expression
from jointplay.scene.initial import check_journals as _check_journals
from jointplay.scene.initial import (
    coordinate_names,
    validate_initial,
)
from jointplay.scene.initial import finite_number as _finite_number
from jointplay.scene.initial import initial_numbers as _initial_numbers
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
    one number serves both. The defaults are the cheapest setting measured to meet the
    project's working accuracy on the default scene (tip error <= 1e-5 m, energy balance
    residual <= 0.1 % of the dissipated energy; see the README, "What accuracy costs").
    ``step`` is the fixed step of ``rk4`` and ``radau`` (it must
    divide ``output_step``). ``max_steps`` bounds the work between two outputs.
    """

    t_end: float = 2.0
    output_step: float = 1e-3
    integrator: str = "bdf"
    rtol: float = 2e-6
    atol: float = 3e-7
    step: float = 1e-5
    max_steps: int = 200_000

    def __post_init__(self) -> None:
        # Built from a file, flags or the API alike, the settings are checked here, once.
        _validate_run(self, None)

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

    def __post_init__(self) -> None:
        # One validation for every front door: a scene read from TOML, built by the API or
        # changed with dataclasses.replace is checked here, all problems reported together.
        problems = Problems()
        with problems.check():
            check_scene_name(self.name)
        with problems.check():
            if not isinstance(self.robot, Robot):
                raise _error("robot", f"must be a jointplay.Robot, got "
                             f"{type(self.robot).__name__}", None)
            driven = self.robot.moving_joints if self.robot.drive else ()
            if len(self.torques) != len(driven):
                raise _error("torques", f"needs one torque per driven joint "
                             f"({len(driven)}), got {len(self.torques)}", None)
        with problems.check():
            if not isinstance(self.run, RunSettings):
                raise _error("run", "must be a jointplay.RunSettings (use scene.with_run(...) "
                             "to change run settings)", None)
            _check_table_covers_run(self)
        with problems.check():
            if isinstance(self.robot, Robot):
                object.__setattr__(self, "initial", validate_initial(self.initial, self.robot))
        with problems.check():
            _check_journals(self.journals, self.initial, None)
        problems.raise_any(self.source)

    def with_run(self, **changes: Any) -> Scene:
        """The same scene with some run settings changed (validated)."""
        problems = Problems()
        for key in changes:
            if key not in _RUN_KEYS:
                problems.found.append(_error(
                    f"run.{key}", f"unknown run setting (allowed: {', '.join(_RUN_KEYS)})"
                    f"{did_you_mean(key, _RUN_KEYS)}", self.source))
        with problems.check():
            run = replace(self.run, **{k: v for k, v in changes.items() if k in _RUN_KEYS})
        problems.raise_any(self.source)
        scene = replace(self, run=run)
        if {"t_end", "output_step"} & set(changes):  # a new output grid
            check_torques_finite(scene)
        return scene

    def with_robot(self, robot: Robot) -> Scene:
        """The same scene with another robot (validated). The initial eccentricities of a
        joint that has no play in ``robot`` (its ideal counterpart, say) are left out; every
        other initial value must exist in ``robot``."""
        coords = set(coordinate_names(robot))
        initial = {k: v for k, v in self.initial.items()
                   if k in coords or k.removeprefix("d") in coords
                   or not k.removeprefix("d").startswith("e")}
        return replace(self, robot=robot, initial=initial)

    def with_initial(self, values: Mapping[str, float | str] | None = None,
                     **more: float | str) -> Scene:
        """The same scene with some initial coordinates or speeds changed, validated as the
        scene file's ``[initial]`` is: ``scene.with_initial(q2=0.1, dq2=0.0)``. Values may be
        numbers or constant expressions (``"-pi/2"``); unnamed ones keep their value."""
        raw = {**(values or {}), **more}
        initial = {**self.initial, **_initial_numbers(raw, self.constants, self.source)}
        return replace(self, initial=initial)

    def with_torques(self, values: Mapping[str, float | str] | None = None,
                     **more: float | str) -> Scene:
        """The same scene with other drive torques, validated as the scene file's
        ``[torques]`` is: ``scene.with_torques(joint2="3*sin(2*pi*t)")`` (expressions of t
        over the scene's constants; unnamed joints keep theirs) or ``table="torques.csv"``
        (relative to the scene file), which replaces every joint's torque."""
        raw = {**(values or {}), **more}
        base = Path(self.source).parent if self.source else None
        torques, texts = _torques(raw, self.robot, self.constants, base, self.source)
        if "table" not in raw:  # joints not named keep their torque
            keys = [f"joint{j}" for j in self.robot.moving_joints] if self.robot.drive else []
            kept = [key for key in keys if key not in raw]
            if kept and "table" in self.torque_text:
                raise _error("torques", f"the scene's torques come from a table; give "
                             f"{', '.join(kept)} an expression too, or another table",
                             self.source)
            functions = list(torques)
            for k, key in enumerate(keys):
                if key in kept:
                    functions[k] = self.torques[k]
                    texts[key] = self.torque_text.get(key, "")
            torques = tuple(functions)
        scene = replace(self, torques=torques, torque_text=texts)
        check_torques_finite(scene)
        return scene

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


def _positive_number(value: Any, where: str, source: str | None) -> float:
    number = _finite_number(value, where, source)
    if number <= 0:
        raise _error(where, f"must be > 0, got {value!r}", source)
    return number


def _validate_run(run: RunSettings, source: str | None) -> None:
    # Each setting by itself (all reported together), then how they fit one another.
    problems = Problems()
    for name, low, high in (("t_end", 0.0, limits.MAX_T_END),
                            ("output_step", limits.MIN_OUTPUT_STEP, math.inf),
                            ("step", limits.MIN_STEP, math.inf),
                            ("rtol", limits.MIN_RTOL, math.inf),
                            ("atol", limits.MIN_ATOL, math.inf)):
        with problems.check():
            value = _positive_number(getattr(run, name), f"run.{name}", source)
            if value > high:
                raise _error(f"run.{name}", f"must be at most {high:g}, got {value:g}", source)
            if value < low:
                raise _error(f"run.{name}", f"must be at least {low:g}, got {value:g}", source)
    with problems.check():
        if not isinstance(run.integrator, str) or run.integrator not in INTEGRATORS:
            hint = did_you_mean(str(run.integrator), INTEGRATORS)
            raise _error("run.integrator", f"must be one of {', '.join(INTEGRATORS)}, got "
                         f"{run.integrator!r}{hint}", source)
    with problems.check():
        if isinstance(run.max_steps, bool) or not isinstance(run.max_steps, int) \
                or not 1 <= run.max_steps <= limits.MAX_MAX_STEPS:
            raise _error("run.max_steps", f"must be an integer from 1 to "
                         f"{limits.MAX_MAX_STEPS}, got {run.max_steps!r}", source)
    with problems.check():
        if isinstance(run.rtol, (int, float)) and run.rtol >= 1:
            raise _error("run.rtol", f"must be < 1, got {run.rtol}", source)
    problems.raise_any()
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


def _run_settings(raw: Any, source: str | None) -> RunSettings:
    # The same checks as run settings built in Python: RunSettings checks its own values.
    problems = Problems()
    if not isinstance(raw, Mapping):
        check_keys(raw, _RUN_KEYS, "run", source)
    with problems.check():
        check_keys(raw, _RUN_KEYS, "run", source)
    try:
        run = RunSettings(**{k: v for k, v in raw.items() if k in _RUN_KEYS})
    except DescriptionError as err:
        problems.found.extend(err.problems)
    problems.raise_any(source)
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
    check_keys(raw, (*keys, "table", "hold_ends"), "torques", source)
    if raw and not robot.drive:
        raise _error("torques", "the robot's drive is disabled (drive.enabled = false); "
                     "remove [torques] or enable the drive", source)
    hold = raw.get("hold_ends", False)
    if "hold_ends" in raw and ("table" not in raw or not isinstance(hold, bool)):
        raise _error("torques.hold_ends", "is true or false, and only beside table = ...: it "
                     "holds a table's first and last rows outside its time range", source)
    if "table" in raw:
        if len(raw) > 1 + ("hold_ends" in raw):
            raise _error("torques.table", "give either a table or expressions, not both",
                         source)
        if not isinstance(raw["table"], str):
            raise _error("torques.table", "must be the path of a CSV file", source)
        path = (base / raw["table"]) if base is not None else Path(raw["table"])
        table = load_torque_table(path, columns=len(driven), field="torques.table",
                                  source=source)
        table_texts = {"table": str(raw["table"])}
        if hold:
            table_texts["hold_ends"] = "true"
        return tuple(table.column(i) for i in range(len(driven))), table_texts
    functions: list[TimeFunction] = []
    texts: dict[str, str] = {}
    problems = Problems()
    for key in keys:
        with problems.check():
            text = raw.get(key, "0")
            if isinstance(text, (int, float)) and not isinstance(text, bool):
                text = repr(float(text))
            if not isinstance(text, str):
                raise _error(f"torques.{key}", "must be an expression of t (a string) or a "
                             "number", source)
            functions.append(parse_expression(text, field=f"torques.{key}",
                                              constants=constants, source=source))
            texts[key] = text
    problems.raise_any(source)
    return tuple(functions), texts


def scene_inputs(scene: Scene) -> list[Path]:
    """The files a scene was read from (the scene, its torque table): never outputs."""
    if scene.source is None:
        return []
    paths = [Path(scene.source)]
    if "table" in scene.torque_text:
        paths.append(Path(scene.source).parent / scene.torque_text["table"])
    return paths


def _check_table_covers_run(scene: Scene) -> None:
    """A torque table must cover [0, run.t_end], unless ``hold_ends = true`` asks for its first
    and last rows to be held outside its range: a table that ends at 0.5 s for a 2 s run is
    otherwise a mistake that would pass unseen."""
    from jointplay.scene.tables import TableColumn

    if scene.torque_text.get("hold_ends") == "true":
        return
    t_end = scene.run.t_end
    for torque in scene.torques:
        if isinstance(torque, TableColumn):
            first, last = float(torque.times[0]), float(torque.times[-1])
            if first > 0.0 or last < t_end * (1 - 1e-12):
                raise _error("torques.table", f"covers t = {first:g} to {last:g} s, but the run "
                             f"lasts from 0 to run.t_end = {t_end:g} s; extend the table, "
                             "shorten the run, or add hold_ends = true to [torques] to hold "
                             "its first and last rows", None)


def check_scene_name(name: Any) -> None:
    """A scene's name: printed, written into results and file attributes, so one line of
    printable text (a NUL or a newline would break them, or fail only after the run)."""
    if not isinstance(name, str) or not name.strip():
        raise _error("name", f"must be a non-empty string, got {name!r}", None)
    bad = [c for c in name if not c.isprintable()]
    if bad:
        raise _error("name", f"must be printable text on one line, got the control character "
                     f"{bad[0]!r} in {name!r}", None)
    if len(name) > 200:
        raise _error("name", f"must be at most 200 characters, got {len(name)}", None)


def scene_from_dict(data: Mapping[str, Any], *, source: str | None = None,
                    base: Path | None = None, text: str = "") -> Scene:
    """Validate a parsed scene document; relative paths resolve against ``base``."""
    problems = Problems()
    with problems.check():
        if not isinstance(data, Mapping):
            raise _error("(top level)", "must be a table", source)
        if ("scene" in data or "parameters" in data) and "robot" not in data:
            raise _error("(file)", "is a sweep file (it has scene = ... or [parameters]), not "
                         "a scene; run it with: jointplay sweep FILE --out DIR", source)
        check_keys(data, _TOP_KEYS, "", source)
    problems.raise_any(source)
    robot: Robot | None = None
    with problems.check():
        if "robot" not in data:
            raise _error("robot", "is required: a [robot] table or the path of a robot file",
                         source)
        robot = _robot(data["robot"], base, source)
    name = data.get("name", robot.name if robot is not None else "scene")
    with problems.check():
        check_scene_name(name)
    with problems.check():
        if "description" in data and not isinstance(data["description"], str):
            raise _error("description", "must be a string", source)
    constants: dict[str, float] = {}
    with problems.check():
        constants = _constants(data.get("constants", {}), source)
    torques: tuple[TimeFunction, ...] = ()
    texts: dict[str, str] = {}
    initial: dict[str, Any] = {}
    raw_initial = data.get("initial", {})
    journals: Any = "centred"
    if isinstance(raw_initial, Mapping) and "journals" in raw_initial:
        raw_initial = dict(raw_initial)
        journals = raw_initial.pop("journals")
    with problems.check():
        initial = _initial_numbers(raw_initial, constants, source)
        if robot is not None:
            initial = validate_initial(initial, robot)
    with problems.check():
        _check_journals(journals, initial, source)
    if robot is not None:
        with problems.check():
            torques, texts = _torques(data.get("torques", {}), robot, constants, base, source)
    run = RunSettings()
    with problems.check():
        run = _run_settings(data.get("run", {}), source)
    if robot is not None and texts:
        with problems.check():
            _check_torques_finite(torques, texts, robot, run, source)
    problems.raise_any(source)
    assert robot is not None
    return Scene(name=name, robot=robot, torques=torques, torque_text=texts, initial=initial,
                 run=run, constants=constants, source=source, text=text,
                 journals=journals)


def check_torques_finite(scene: Scene) -> None:
    """Refuse a torque that is not finite at an output time, naming the joint and the time.

    The simulation evaluates the torques at every output time (for the results) and near them
    (inside the integrator); a torque such as ``1/(t - 0.3)`` would put NaN or inf into the
    results, so it is refused before anything runs.
    """
    _check_torques_finite(scene.torques, scene.torque_text, scene.robot, scene.run,
                          scene.source)


def _check_torques_finite(torques: tuple[TimeFunction, ...], torque_text: Mapping[str, str],
                          robot: Robot, run: RunSettings, source: str | None) -> None:
    import numpy as np

    t = np.arange(run.n_outputs + 1) * run.output_step
    keys = [f"joint{j}" for j in robot.moving_joints] if robot.drive else []
    for k, torque in enumerate(torques):
        values = np.asarray(torque.numpy(t), dtype=np.float64)
        bad = ~np.isfinite(values)
        if bad.any():
            i = int(np.argmax(bad))
            key = keys[k] if k < len(keys) else f"[{k}]"
            field_name = "torques.table" if "table" in torque_text else f"torques.{key}"
            text = torque_text.get(key)
            shown = f" {text!r}" if text else ""
            raise _error(field_name, f"the torque{shown} is {values[i]} at t = {t[i]:.9g} s "
                         "(an output time); every torque must be finite over [0, run.t_end]",
                         source)


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
    "validate_initial",
]
