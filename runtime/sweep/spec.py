"""A sweep file, read and validated whole: the base scene, its run overrides, the swept axes
and every case (a parameter vector with its scene and its content key)."""

from __future__ import annotations

import hashlib
import itertools
import json
import math
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, fields
from pathlib import Path
from typing import Any

from jointplay.common import limits
from jointplay.common.errors import DescriptionError, JointplayError
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import Problems, check_keys, read_toml
from jointplay.robot import Robot, with_parameters
from jointplay.robot.description import parameter_name
from jointplay.scene.definition import (
    RunSettings,
    Scene,
    default_scene,
    ideal_counterpart,
    load_scene,
)
from jointplay.sweep.axes import (
    CLEARANCE_ALIAS,
    MAX_CASES,
    Axis,
    _error,
    _integer,
    _number,
    check_name,
    read_axis,
)

MODES: tuple[str, ...] = ("product", "zip")
TOP_KEYS: tuple[str, ...] = ("name", "description", "scene", "mode", "seed", "count", "run",
                             "parameters")
RUN_KEYS: tuple[str, ...] = tuple(f.name for f in fields(RunSettings))
# Bump when the meaning of a case key changes (old case files are then not reused).
# 2: contact columns from the located contact-phase table (1 had sampled maxima).
KEY_VERSION = 2


class SweepError(JointplayError, RuntimeError):
    """A sweep could not run: no cluster at the address, or case files missing."""


@dataclass(frozen=True)
class Case:
    """One parameter vector of a sweep, with the scene that runs it.

    ``swept`` holds the names as written in the sweep file (aliases included); ``parameters``
    the robot parameters the case sets (aliases resolved), which ``scene.robot`` carries.
    """

    index: int
    key: str
    ideal_key: str
    swept: dict[str, float]
    parameters: dict[str, float]
    scene: Scene


@dataclass(frozen=True)
class Sweep:
    """A validated sweep: the base scene (run overrides applied), its axes and its cases."""

    name: str
    scene: Scene
    mode: str
    axes: tuple[Axis, ...]
    cases: tuple[Case, ...]
    source: str | None = None
    text: str = ""

    @property
    def swept_names(self) -> list[str]:
        return [axis.name for axis in self.axes]

    @property
    def parameter_names(self) -> list[str]:
        """Every column of case parameters: the swept names, then what aliases resolve to."""
        names = self.swept_names
        extra = [n for n in (self.cases[0].parameters if self.cases else {}) if n not in names]
        return names + extra




def _run_overrides(raw: Any, scene: Scene, source: str | None) -> Scene:
    check_keys(raw, RUN_KEYS, "run", source)
    changes: dict[str, Any] = {}
    for key, value in raw.items():
        if key in ("integrator", "plausibility"):  # names, checked by RunSettings
            changes[key] = value
        elif key == "max_steps":
            changes[key] = _integer(value, "run.max_steps", source, 1, limits.MAX_MAX_STEPS)
        else:
            changes[key] = _number(value, f"run.{key}", source)
    try:
        return scene.with_run(**changes)
    except DescriptionError as err:
        raise _error(err.field, err.message, source) from None


def _robot_field_to_name(field_name: str) -> str:
    """``joints[2].journal_radius`` -> ``joint2.journal_radius`` (names of the vector)."""
    return parameter_name(field_name)


def _case_robot(base: Robot, index: int, swept: Mapping[str, float], source: str | None
                ) -> tuple[Robot, dict[str, float]]:
    """The case's robot and the parameters it sets (clearance aliases resolved)."""
    params = {name: value for name, value in swept.items()
              if not CLEARANCE_ALIAS.fullmatch(name)}
    for name, value in swept.items():
        m = CLEARANCE_ALIAS.fullmatch(name)
        if m:
            j = int(m.group(1))
            bearing = params.get(f"joint{j}.bearing_radius", base.joints[j - 1].bearing_radius)
            params[f"joint{j}.journal_radius"] = bearing - value
    try:
        return with_parameters(base, params), params
    except DescriptionError as err:
        name = _robot_field_to_name(err.field)
        culprit = name
        alias = re.fullmatch(r"joint(\d+)\.(journal|bearing)_radius", name)
        if name not in swept and alias and f"joint{alias.group(1)}.clearance" in swept:
            culprit = f"joint{alias.group(1)}.clearance"
            name += f" (bearing_radius - {culprit})"
        where = f"parameters.{culprit}" if culprit in swept else "parameters"
        values = ", ".join(f"{k} = {v:.6g}" for k, v in swept.items())
        raise _error(where, f"case {index} ({values}) is not a valid robot: {name}: "
                     f"{err.message}", source) from None


def _check_initial(scene: Scene, robot: Robot, index: int, source: str | None) -> None:
    for j in robot.clearance_joints:
        joint = robot.joints[j - 1]
        e = math.hypot(scene.initial.get(f"ex{j}", 0.0), scene.initial.get(f"ey{j}", 0.0))
        c = joint.bearing_radius - joint.journal_radius
        if e > c * (1 + 1e-9):
            raise _error("parameters", f"case {index}: the initial eccentricity of joint {j} "
                         f"({e:g} m) exceeds its radial clearance ({c:g} m)", source)


def _hex(value: float) -> str:
    return float(value).hex()


def _scene_fingerprint(scene: Scene) -> dict[str, Any]:
    """What, besides the parameter vector, decides a simulation's outcome."""
    torques: dict[str, Any] = dict(scene.torque_text)
    if "table" in torques:  # the CSV's content, not its name
        path = Path(torques["table"])
        if scene.source and not path.is_absolute():
            path = Path(scene.source).parent / path
        try:
            torques["table_sha256"] = hashlib.sha256(path.read_bytes()).hexdigest()
        except OSError:
            torques["table_sha256"] = None
    run = scene.run
    out: dict[str, Any] = {
        "torques": torques,
        "initial": {k: _hex(v) for k, v in sorted(scene.initial.items())},
        "run": {f.name: (_hex(getattr(run, f.name)) if isinstance(getattr(run, f.name), float)
                         else getattr(run, f.name)) for f in fields(run)
                # the default stop leaves the keys of earlier sweeps as they were
                if not (f.name == "plausibility" and run.plausibility == "stop")},
    }
    if scene.journals != "centred":  # the resting start (centred keys stay as they were)
        out["journals"] = scene.journals
    return out


def case_key(scene: Scene, robot: Robot) -> str:
    """Hash of the full parameter vector, the structure, the base scene and the run."""
    doc = {
        "version": KEY_VERSION,
        "structure": robot.structure().as_dict(),
        "parameters": {p.name: _hex(v) for p, v in zip(robot.parameters(),
                                                         robot.parameter_values(), strict=True)},
        "scene": _scene_fingerprint(scene),
    }
    text = json.dumps(doc, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:32]


def sweep_from_dict(data: Mapping[str, Any], *, source: str | None = None,
                    base: Path | None = None, text: str = "") -> Sweep:
    """Validate a parsed sweep document completely; relative paths resolve against ``base``."""
    # The parts that do not depend on one another are all checked, then reported together.
    problems = Problems()
    with problems.check():
        check_keys(data, TOP_KEYS, "", source)
    problems.raise_any(source)
    scene = None
    with problems.check():
        scene = _run_overrides(data.get("run", {}), _base_scene(data, source, base), source)
    name = data.get("name", f"{scene.name}_sweep" if scene is not None else "sweep")
    with problems.check():
        if not isinstance(name, str) or not name:
            raise _error("name", f"must be a non-empty string, got {name!r}", source)
    with problems.check():
        if "description" in data and not isinstance(data["description"], str):
            raise _error("description", "must be a string", source)
    mode = data.get("mode", "product")
    with problems.check():
        if mode not in MODES:
            raise _error("mode", f"must be one of {', '.join(MODES)}, got {mode!r}"
                         f"{did_you_mean(str(mode), MODES)}", source)
    defaults: dict[str, Any] = {"seed": 0}
    with problems.check():
        defaults["seed"] = _integer(data.get("seed", 0), "seed", source, 0)
    with problems.check():
        if "count" in data:
            defaults["count"] = _integer(data["count"], "count", source, 1, MAX_CASES)
    axes: tuple[Axis, ...] = ()
    if scene is not None:
        with problems.check():
            axes = _axes(data.get("parameters"), scene.robot, defaults, source)
    problems.raise_any(source)
    assert scene is not None
    cases = _cases(scene, axes, mode, source)
    return Sweep(name=name, scene=scene, mode=mode, axes=axes, cases=tuple(cases),
                 source=source, text=text)


def _base_scene(data: Mapping[str, Any], source: str | None, base: Path | None) -> Scene:
    raw_scene = data.get("scene")
    if not isinstance(raw_scene, str) or not raw_scene:
        raise _error("scene", "is required: the path of a scene file (relative to the sweep "
                     "file) or \"default\"", source)
    if raw_scene == "default":
        return default_scene()
    path = (base / raw_scene) if base is not None else Path(raw_scene)
    if not path.is_file():
        raise _error("scene", f"scene file {str(path)!r} not found; give a path relative "
                     "to the sweep file, or \"default\"", source)
    return load_scene(path)


def _axes(raw: Any, robot: Robot, defaults: Mapping[str, Any], source: str | None
          ) -> tuple[Axis, ...]:
    """The axes of the ``parameters`` table, every name checked before any value."""
    if not isinstance(raw, Mapping) or not raw:
        raise _error("parameters", "must be a non-empty table naming what to vary, e.g. "
                     "[parameters.\"friction.mu\"] values = [0.0, 0.1]", source)
    problems = Problems()
    for key in raw:
        with problems.check():
            check_name(key, robot, source)
    problems.raise_any(source)
    for key in raw:
        m = CLEARANCE_ALIAS.fullmatch(key)
        if m and f"joint{m.group(1)}.journal_radius" in raw:
            raise _error(f"parameters.{key}", f"sets joint{m.group(1)}.journal_radius, which "
                         "is also swept: vary one of the two", source)
    return tuple(read_axis(key, spec, defaults, source) for key, spec in raw.items())


def _combinations(axes: tuple[Axis, ...], mode: str, source: str | None
                  ) -> Iterable[tuple[float, ...]]:
    sizes = [len(axis.values) for axis in axes]
    if mode == "zip":
        for axis in axes[1:]:
            if len(axis.values) != sizes[0]:
                raise _error(f"parameters.{axis.name}", f"mode = \"zip\" needs every swept "
                             f"name to have as many values: {axes[0].name} has {sizes[0]}, "
                             f"{axis.name} has {len(axis.values)}", source)
        total = sizes[0]
        combos: Iterable[tuple[float, ...]] = zip(*(a.values for a in axes), strict=True)
    else:
        total = math.prod(sizes)
        combos = itertools.product(*(a.values for a in axes))
    if total > MAX_CASES:
        raise _error("parameters", f"{total} cases is more than the {MAX_CASES} a sweep may "
                     "have", source)
    return combos


def _cases(scene: Scene, axes: tuple[Axis, ...], mode: str, source: str | None
           ) -> list[Case]:
    cases: list[Case] = []
    seen: dict[str, int] = {}
    for index, combo in enumerate(_combinations(axes, mode, source)):
        swept = dict(zip((a.name for a in axes), combo, strict=True))
        case_robot, params = _case_robot(scene.robot, index, swept, source)
        _check_initial(scene, case_robot, index, source)
        case_scene = scene.with_robot(case_robot)
        key = case_key(scene, case_robot)
        if key in seen:
            raise _error("parameters", f"cases {seen[key]} and {index} are the same parameter "
                         "vector (a value repeats)", source)
        seen[key] = index
        ideal = ideal_counterpart(case_robot)
        cases.append(Case(index=index, key=key, ideal_key=case_key(scene, ideal), swept=swept,
                          parameters=params, scene=case_scene))
    return cases


def load_sweep(path: str | Path) -> Sweep:
    """Read and validate a sweep file (TOML, data only)."""
    path = Path(path)
    data, text = read_toml(path, "sweep")
    source = str(path)
    return sweep_from_dict(data, source=source, base=path.parent, text=text)
