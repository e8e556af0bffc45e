"""Scenes: a robot, the effects it calls for, drive torques, an initial state and run settings.

A scene is a TOML file of data. It is validated completely before anything is derived or
compiled, and never executed: torque expressions go through the restricted parser of
:mod:`jointplay.scene.expressions` and :mod:`jointplay.scene.tables`. Every error names the
file, the field and what is allowed.

    name = "two_link"
    [robot]                  # a robot (docs/reference/robot-file.md), or robot = "robot.toml"
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

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import Problems, check_keys, read_toml
from jointplay.robot import Joint, JointKind, Robot, load_robot, robot_from_dict
from jointplay.scene.expressions import TimeFunction
from jointplay.scene.initial import check_journals as _check_journals
from jointplay.scene.initial import check_resting as _check_resting
from jointplay.scene.initial import check_resting_depth as check_resting_depth
from jointplay.scene.initial import (
    coordinate_names,
    validate_initial,
)
from jointplay.scene.initial import initial_numbers as _initial_numbers

# The run settings live in their own module; their names stay importable from here.
from jointplay.scene.run_settings import _RUN_KEYS as _RUN_KEYS
from jointplay.scene.run_settings import ADAPTIVE as ADAPTIVE
from jointplay.scene.run_settings import INTEGRATORS as INTEGRATORS
from jointplay.scene.run_settings import PLAUSIBILITY as PLAUSIBILITY
from jointplay.scene.run_settings import Plausibility as Plausibility
from jointplay.scene.run_settings import RunSettings as RunSettings
from jointplay.scene.run_settings import run_settings_from_table
from jointplay.scene.torques import (
    check_finite,
    check_table_covers_run,
    read_constants,
    read_torques,
)

# The settings of identification, the controller and studies may sit in a scene file too
# (jointplay.neural.study.settings reads them; a simulation ignores them).
_SETTINGS_KEYS = ("preset", "identify", "control", "study")
_TOP_KEYS = ("name", "description", "robot", "constants", "torques", "initial", "run",
             *_SETTINGS_KEYS)
@dataclass(frozen=True)
class Scene:
    """A validated scene: a robot, its drive torques, its initial state and how to integrate it.

    Validated on construction (every problem reported together); change one with
    :meth:`with_run`, :meth:`with_robot`, :meth:`with_initial`, :meth:`with_torques` or
    :meth:`with_journals`, each of which returns a new, validated scene.

    Attributes
    ----------
    name : str
        The scene's name (it names output files).
    robot : Robot
        The robot.
    torques : tuple of callables
        One time function per driven joint, in order: ``torque(t)`` in N m.
    torque_text : dict of str to str
        The torque expressions as written, by joint (``{"joint2": "A*sin(2*pi*t)"}``).
    initial : dict of str to float
        Initial coordinates and rates by name; the rest start at 0.
    run : RunSettings
        How the scene is integrated.
    constants : dict of str to float
        The named constants the torque expressions use.
    source : str or None
        The file the scene was read from (None when built in Python).
    text : str
        The scene file as read, kept with the results.
    journals : {"centred", "resting"}
        ``"centred"``: the journals start at the eccentricities ``initial`` gives (default 0,
        the bearing centres); ``"resting"``: at rest, each journal in static equilibrium in its
        bearing under gravity (solved at run time: :mod:`jointplay.sim.equilibrium`).

    Examples
    --------
    >>> import jointplay
    >>> scene = jointplay.default_scene()
    >>> scene.name, scene.robot.clearance_joints, scene.run.t_end
    ('paper_4dof', (2, 3), 2.0)
    >>> short = scene.with_run(t_end=0.1, output_step=5e-4)
    >>> short.run.t_end, short.run.n_outputs, scene.run.t_end  # a new scene; the first unchanged
    (0.1, 200, 2.0)
    """

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
            check_table_covers_run(self.torques, self.torque_text, self.run.t_end)
        with problems.check():
            if isinstance(self.robot, Robot):
                object.__setattr__(self, "initial", validate_initial(self.initial, self.robot))
        with problems.check():
            _check_journals(self.journals, self.initial, None)
            if isinstance(self.robot, Robot):
                _check_resting(self.journals, self.robot)
                if self.journals == "resting" and isinstance(self.run, RunSettings) \
                        and self.run.plausibility == "stop":
                    check_resting_depth(self.robot)
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
        torques, texts = read_torques(raw, self.robot, self.constants, base, self.source)
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
    """The same robot with every clearance joint made ideal (and locked play made locked).

    Parameters
    ----------
    robot : Robot
        The robot with clearance joints.

    Returns
    -------
    Robot
        The robot with ideal joints, named ``NAME_ideal``: what ``compare_ideal`` simulates.
    """
    kinds: dict[JointKind, JointKind] = {"clearance": "ideal", "locked_clearance": "locked"}
    joints = tuple(replace(j, kind=kinds.get(j.kind, j.kind)) for j in robot.joints)
    return replace(robot, joints=joints, name=f"{robot.name}_ideal")


def _error(field_name: str, message: str, source: str | None) -> DescriptionError:
    return DescriptionError(field_name, message, source)


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


def scene_inputs(scene: Scene) -> list[Path]:
    """The files a scene was read from (the scene, its torque table): never outputs."""
    if scene.source is None:
        return []
    paths = [Path(scene.source)]
    if "table" in scene.torque_text:
        paths.append(Path(scene.source).parent / scene.torque_text["table"])
    return paths


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
    """Build a validated :class:`Scene` from a parsed scene document (a scene file's tables).

    Parameters
    ----------
    data : mapping
        The document: ``name``, ``robot`` (a file name or a robot table), and the optional
        ``[constants]``, ``[torques]``, ``[initial]`` and ``[run]`` tables.
    source : str, optional
        Where the document came from, named in error messages.
    base : pathlib.Path, optional
        The folder that a relative robot file name resolves against.
    text : str, default ""
        The document as written, kept with the results.

    Returns
    -------
    Scene
        The scene.

    Raises
    ------
    DescriptionError
        Naming the field and the fix; several problems come together as
        :class:`DescriptionErrors`.
    """
    problems = Problems()
    with problems.check():
        if not isinstance(data, Mapping):
            raise _error("(top level)", "must be a table", source)
        if "robot" not in data and data and all(k in ("scene", *_SETTINGS_KEYS) for k in data) \
                and any(k in data for k in _SETTINGS_KEYS):
            raise _error("(file)", "is a settings file (preset, scene, [identify], [control], "
                         "[study]), not a scene; run it with: jointplay control-study FILE "
                         "--out DIR (or identify, control)", source)
        if ("scene" in data or "parameters" in data) and "robot" not in data:
            from jointplay.sweep.spec import TOP_KEYS as SWEEP_KEYS

            # A key neither a sweep's nor a settings file's: a misspelling, named with the
            # nearest key rather than calling the file a sweep.
            stray = [k for k in data if k not in SWEEP_KEYS and k not in _SETTINGS_KEYS]
            if stray:
                raise _error(stray[0], "is a key of neither a sweep file nor a settings file"
                             + (did_you_mean(stray[0], (*SWEEP_KEYS, *_SETTINGS_KEYS))
                                or f" (sweep: {', '.join(SWEEP_KEYS)}; settings: scene, "
                                f"{', '.join(_SETTINGS_KEYS)})"), source)
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
        constants = read_constants(data.get("constants", {}), source)
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
            torques, texts = read_torques(data.get("torques", {}), robot, constants, base, source)
    run = RunSettings()
    with problems.check():
        run = run_settings_from_table(data.get("run", {}), source)
    if robot is not None and texts:
        with problems.check():
            check_finite(torques, texts, robot, run, source)
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
    check_finite(scene.torques, scene.torque_text, scene.robot, scene.run,
                          scene.source)


def load_scene(path: str | Path) -> Scene:
    r"""Read and validate a scene file (TOML; data only, never executed).

    Parameters
    ----------
    path : str or pathlib.Path
        The scene file; a relative robot file name in it resolves against its folder.

    Returns
    -------
    Scene
        The scene.

    Raises
    ------
    DescriptionError
        When the file is missing, is not TOML, or a field is invalid: the message names the
        file, the field and the fix.

    Examples
    --------
    >>> from pathlib import Path
    >>> import jointplay
    >>> robot = jointplay.uniform_chain(2, ["ideal", "clearance"], name="two_link")
    >>> _ = Path("two_link.toml").write_text(jointplay.robot_to_toml(robot))
    >>> _ = Path("swing.toml").write_text('''
    ... name = "swing"
    ... robot = "two_link.toml"
    ... [torques]
    ... joint1 = "2.0*sin(2*pi*t)"
    ... [run]
    ... t_end = 0.5
    ... ''')
    >>> scene = jointplay.load_scene("swing.toml")
    >>> scene.name, scene.robot.clearance_joints, scene.run.t_end
    ('swing', (2,), 0.5)
    >>> scene.torque_text  # joint 2 has no torque given: zero
    {'joint1': '2.0*sin(2*pi*t)', 'joint2': '0'}
    """
    path = Path(path)
    data, text = read_toml(path, "scene")
    source = str(path)
    if isinstance(data.get("mechanism"), dict):
        raise DescriptionError("mechanism", "this is a mechanism file, which `jointplay "
                               "simulate`, `inspect`, `build`, `derive` and `sweep` take "
                               "(from Python: jointplay.load_mechanism_scene and "
                               "jointplay.simulate_mechanism); this command or function takes "
                               "the scene of a serial arm only", source)
    return scene_from_dict(data, source=source, base=path.parent, text=text)


def default_scene() -> Scene:
    """The built-in default: the paper's example (``scenes/paper_4dof.toml``).

    The paper's 4-link arm (joints 1 and 4 locked, clearance at joints 2 and 3, a 2 kg
    payload) driven by sinusoidal torques at joints 2 and 3 for 2 s from the bearing centres.

    Returns
    -------
    Scene
        The scene, as :func:`load_scene` reads it.

    Examples
    --------
    >>> import jointplay
    >>> scene = jointplay.default_scene()
    >>> scene.name, scene.robot.n_links, scene.robot.clearance_joints
    ('paper_4dof', 4, (2, 3))
    >>> sorted(scene.torque_text)
    ['joint2', 'joint3']
    """
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
