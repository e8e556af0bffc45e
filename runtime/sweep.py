"""Parameter sweeps: one compiled model, many parameter vectors, run on a Dask cluster.

A sweep file (TOML, data only, never executed) names a base scene and the numbers to vary;
see ``docs/sweeps.md`` for the format. Everything is validated before any work starts, and a
sweep never changes the model's structure, so the model is compiled once (here, in the parent
process) and every worker loads it from the compile cache.

Faults lose nothing. Each finished case is written at once, atomically, as
``OUT/cases/<key>.json``, where the key hashes the case's full parameter vector, the base
scene (structure, torques, initial state) and the run settings. A restarted sweep skips every
case whose file exists, so rows are never computed twice nor lost; the Parquet table
``OUT/sweep.parquet`` is rebuilt from those files, atomically, at the end of every run. Cases
that fail in the simulation are recorded (status ``failed`` with the message) and the sweep
goes on; tasks on a worker that dies are rerun by Dask (and ``retries`` covers exceptions
outside the simulation).
"""

from __future__ import annotations

import argparse
import contextlib
import difflib
import hashlib
import itertools
import json
import logging
import math
import os
import re
import socket
import sys
import threading
import time
import uuid
import zlib
from collections import OrderedDict
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, fields, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay import interrupts, limits
from jointplay.description import (
    Robot,
    check_keys,
    parameter_layout,
    read_toml,
    with_parameters,
)
from jointplay.errors import DescriptionError, JointplayError, SimulationError
from jointplay.scene import RunSettings, Scene, default_scene, ideal_counterpart, load_scene

if TYPE_CHECKING:
    from jointplay.model import Model
    from jointplay.results import SimulationResult

MODES: tuple[str, ...] = ("product", "zip")
SPACINGS: tuple[str, ...] = ("linear", "log")
# Distribution -> its parameters, in numpy's conventions (lognormal: of the underlying normal).
DISTRIBUTIONS: dict[str, tuple[str, ...]] = {
    "uniform": ("low", "high"),
    "normal": ("mean", "std"),
    "lognormal": ("mu", "sigma"),
}
TOP_KEYS: tuple[str, ...] = ("name", "description", "scene", "mode", "seed", "count", "run",
                             "parameters")
RUN_KEYS: tuple[str, ...] = tuple(f.name for f in fields(RunSettings))
GRID_KEYS: tuple[str, ...] = ("start", "stop", "num", "spacing")
RANDOM_KEYS: tuple[str, ...] = ("distribution", "count", "seed")
MAX_CASES = limits.MAX_CASES
# Dask reruns a task whose worker died (up to distributed.scheduler.allowed-failures times);
# ``retries`` reruns a task that raised outside the simulation (a model that failed to load).
RETRIES = 2
# Bump when the meaning of a case key changes (old case files are then not reused).
# 2: contact columns from the located contact-phase table (1 had sampled maxima).
KEY_VERSION = 2
CONNECT_TIMEOUT = "20s"
TABLE_NAME = "sweep.parquet"
MANIFEST_NAME = "sweep.json"
CASES_DIR = "cases"
SERIES_DIR = "series"
PLOTS_DIR = "plots"
# Names of the model's structure: changing one changes the generated code.
_STRUCTURAL = ("contact.law", "contact.stiffness", "friction.law", "friction.ramp",
               "gravity.enabled", "drive.enabled", "links", "joints", "name")
_CLEARANCE_ALIAS = re.compile(r"joint(\d+)\.clearance")
# Failures of these stages are deterministic; a restart keeps them (unless retry_failed).
_STAGE_SIMULATION = "simulation"
_STAGE_WORKER = "worker"
_IDEAL_CACHE_SIZE = 16


class SweepError(JointplayError, RuntimeError):
    """A sweep could not run: no cluster at the address, or case files missing."""


# ---- the sweep description -----------------------------------------------------------------

@dataclass(frozen=True)
class Axis:
    """One swept name and its values, in order."""

    name: str
    kind: str  # "grid", "values" or "random"
    values: tuple[float, ...]
    log: bool = False  # values spread over decades: plot on a log axis


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


def _error(field_name: str, message: str, source: str | None) -> DescriptionError:
    return DescriptionError(field_name, message, source)


def _hint(word: str, choices: Iterable[str]) -> str:
    close = difflib.get_close_matches(word, list(choices), n=1)
    return f"; did you mean {close[0]!r}?" if close else ""


def _number(value: Any, where: str, source: str | None) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise _error(where, f"must be a finite number, got {value!r}", source)
    return float(value)


def _integer(value: Any, where: str, source: str | None, minimum: int,
             maximum: int | None = None) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
        raise _error(where, f"must be an integer >= {minimum}, got {value!r}", source)
    if maximum is not None and value > maximum:
        raise _error(where, f"must be at most {maximum}, got {value!r}", source)
    return value


def _check_name(name: str, robot: Robot, source: str | None) -> None:
    """Accept a robot parameter or an alias; otherwise say exactly why the name is refused."""
    where = f"parameters.{name}"
    known = [p.name for p in robot.parameters()]
    if name in known:
        return
    aliases = [f"joint{j}.clearance" for j in robot.clearance_joints]
    match = _CLEARANCE_ALIAS.fullmatch(name)
    if match:
        j = int(match.group(1))
        if name in aliases:
            return
        if 1 <= j <= robot.n_links:
            raise _error(where, f"joint {j} is kind {robot.joints[j - 1].kind!r} and has no "
                         "clearance; joints with clearance: "
                         f"{', '.join(map(str, robot.clearance_joints)) or 'none'}", source)
        raise _error(where, f"joint {j} does not exist: joints are 1..{robot.n_links}", source)
    if name == "gravity.vector":
        raise _error(where, "is two parameters: vary gravity.x and/or gravity.y" if
                     robot.gravity.enabled else "gravity is disabled in the base scene "
                     "(gravity.enabled = false), and enabling it changes the model's "
                     "structure, which a sweep cannot do", source)
    if name in _STRUCTURAL or re.fullmatch(r"joint\d+\.kind", name):
        raise _error(where, "is part of the model's structure (it changes the generated "
                     "code), and every case of a sweep shares one compiled model: run one "
                     "sweep per value", source)
    n = robot.n_links
    superset = {p.name for p in parameter_layout({
        "links": n, "joints": ["locked_clearance"] * n, "gravity": True,
        "contact_law": "flores", "contact_stiffness": "johnson", "friction": "coulomb-linear",
        "drive": True})} | {"contact.exponent"}
    if name in superset:
        head, _, attr = name.partition(".")
        if head == "gravity":
            why = "gravity is disabled in the base scene (gravity.enabled = false)"
        elif head == "contact" and robot.clearance_joints:
            why = ("contact.exponent is Hertz's, and the base scene's contact.stiffness is "
                   f"{robot.contact.stiffness!r}")
        elif head == "contact":
            why = "the base robot has no clearance joint, so it has no contact model"
        elif attr == "length" and robot.joints[int(head[5:]) - 1].has_clearance:
            why = ("the axial length is a parameter of the cylindrical contact laws only "
                   "(contact.stiffness = johnson, liu, pereira), and the base scene's is "
                   f"{robot.contact.stiffness!r}")
        elif head == "friction":
            why = ("the base robot has no clearance joint" if not robot.clearance_joints
                   else "friction is off in the base scene (friction.law = \"none\")")
        else:
            j = int(head[5:])
            kind = robot.joints[j - 1].kind
            needs = "locked joints" if attr == "angle" else "joints with clearance"
            why = f"joint {j} is kind {kind!r}; only {needs} have {attr}"
        raise _error(where, f"is not a parameter of the base scene's model: {why}. Turning "
                     "an effect on changes the model's structure, which a sweep cannot do",
                     source)
    raise _error(where, "is not a parameter of the base scene's model"
                 f"{_hint(name, known + aliases)}", source)


def _axis(name: str, spec: Any, defaults: Mapping[str, Any], source: str | None) -> Axis:
    """The values of one swept name from its table: a grid, a list or random samples."""
    where = f"parameters.{name}"
    if not isinstance(spec, Mapping):
        raise _error(where, "must be a table: {start, stop, num[, spacing]}, {values = [...]} "
                     "or {distribution, ...}", source)
    forms = [form for form, present in (("values", "values" in spec),
                                        ("grid", any(k in spec for k in GRID_KEYS)),
                                        ("random", "distribution" in spec)) if present]
    if len(forms) != 1:
        raise _error(where, "give exactly one of: a grid (start, stop, num[, spacing]), a list "
                     "(values) or random samples (distribution, its parameters, count[, seed])"
                     + (f"; got {' and '.join(forms)}" if forms else ""), source)
    form = forms[0]
    if form == "values":
        check_keys(spec, ("values",), where, source)
        raw = spec["values"]
        if not isinstance(raw, list) or not raw:
            raise _error(f"{where}.values", "must be a non-empty list of numbers", source)
        if len(raw) > MAX_CASES:
            raise _error(f"{where}.values", f"lists {len(raw)} values; at most {MAX_CASES} are "
                         "allowed", source)
        values = [_number(v, f"{where}.values[{i}]", source) for i, v in enumerate(raw)]
        if len(set(values)) != len(values):
            raise _error(f"{where}.values", "lists a value twice (the cases would repeat)",
                         source)
        positive = all(v > 0 for v in values)
        log = positive and max(values) / min(values) >= 100
        return Axis(name, "values", tuple(values), log)
    if form == "grid":
        check_keys(spec, GRID_KEYS, where, source)
        for key in ("start", "stop", "num"):
            if key not in spec:
                raise _error(f"{where}.{key}", "is required for a grid (start, stop, num)",
                             source)
        start = _number(spec["start"], f"{where}.start", source)
        stop = _number(spec["stop"], f"{where}.stop", source)
        num = _integer(spec["num"], f"{where}.num", source, 1, MAX_CASES)
        spacing = spec.get("spacing", "linear")
        if spacing not in SPACINGS:
            raise _error(f"{where}.spacing", f"must be one of {', '.join(SPACINGS)}, got "
                         f"{spacing!r}{_hint(str(spacing), SPACINGS)}", source)
        if num > 1 and start == stop:
            raise _error(f"{where}.stop", f"the range is empty (start = stop = {start}); for "
                         "one value use values = [x] or num = 1", source)
        if spacing == "log":
            if start <= 0 or stop <= 0:
                raise _error(f"{where}.start" if start <= 0 else f"{where}.stop",
                             "a log grid needs start > 0 and stop > 0", source)
            grid = np.geomspace(start, stop, num, dtype=np.float64)
        else:
            grid = np.linspace(start, stop, num, dtype=np.float64)
        return Axis(name, "grid", tuple(float(v) for v in grid), spacing == "log")
    dist = spec["distribution"]
    if dist not in DISTRIBUTIONS:
        raise _error(f"{where}.distribution", f"must be one of {', '.join(DISTRIBUTIONS)}, "
                     f"got {dist!r}{_hint(str(dist), DISTRIBUTIONS)}", source)
    params = DISTRIBUTIONS[dist]
    check_keys(spec, (*RANDOM_KEYS, *params), where, source)
    for key in params:
        if key not in spec:
            raise _error(f"{where}.{key}", f"is required for a {dist} distribution "
                         f"({', '.join(params)})", source)
    a, b = (_number(spec[key], f"{where}.{key}", source) for key in params)
    if dist == "uniform" and not a < b:
        raise _error(f"{where}.high", f"must exceed low ({a}), got {b}", source)
    if dist in ("normal", "lognormal") and b <= 0:
        raise _error(f"{where}.{params[1]}", f"must be > 0, got {b}", source)
    if "count" in spec:
        count = _integer(spec["count"], f"{where}.count", source, 1, MAX_CASES)
    elif "count" in defaults:
        count = defaults["count"]
    else:
        raise _error(f"{where}.count", "random samples need a count (here or at the top "
                     "level of the sweep file)", source)
    seed = _integer(spec["seed"], f"{where}.seed", source, 0) if "seed" in spec \
        else defaults["seed"]
    # One stream per name: adding or removing another swept name leaves these samples alone.
    rng = np.random.default_rng(np.random.SeedSequence([seed, zlib.crc32(name.encode())]))
    if dist == "uniform":
        samples = rng.uniform(a, b, count)
    elif dist == "normal":
        samples = rng.normal(a, b, count)
    else:
        samples = rng.lognormal(a, b, count)
    return Axis(name, "random", tuple(float(v) for v in samples), dist == "lognormal")


def _run_overrides(raw: Any, scene: Scene, source: str | None) -> Scene:
    check_keys(raw, RUN_KEYS, "run", source)
    changes: dict[str, Any] = {}
    for key, value in raw.items():
        if key == "integrator":
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
    m = re.fullmatch(r"(links|joints)\[(\d+)\]\.(\w+)", field_name)
    if m:
        return f"{m.group(1)[:-1]}{m.group(2)}.{m.group(3)}"
    if field_name.startswith("gravity.vector."):
        return f"gravity.{field_name.rsplit('.', 1)[1]}"
    return field_name


def _case_robot(base: Robot, index: int, swept: Mapping[str, float], source: str | None
                ) -> tuple[Robot, dict[str, float]]:
    """The case's robot and the parameters it sets (clearance aliases resolved)."""
    params = {name: value for name, value in swept.items()
              if not _CLEARANCE_ALIAS.fullmatch(name)}
    for name, value in swept.items():
        m = _CLEARANCE_ALIAS.fullmatch(name)
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
        if e > 2 * c:
            raise _error("parameters", f"case {index}: the initial eccentricity of joint {j} "
                         f"({e:g} m) exceeds twice its radial clearance ({c:g} m)", source)


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
    return {
        "torques": torques,
        "initial": {k: _hex(v) for k, v in sorted(scene.initial.items())},
        "run": {f.name: (_hex(getattr(run, f.name)) if isinstance(getattr(run, f.name), float)
                         else getattr(run, f.name)) for f in fields(run)},
    }


def case_key(scene: Scene, robot: Robot) -> str:
    """Hash of the full parameter vector, the structure, the base scene and the run."""
    doc = {
        "version": KEY_VERSION,
        "structure": robot.structure(),
        "parameters": {p.name: _hex(v) for p, v in zip(robot.parameters(),
                                                         robot.parameter_values(), strict=True)},
        "scene": _scene_fingerprint(scene),
    }
    text = json.dumps(doc, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:32]


def sweep_from_dict(data: Mapping[str, Any], *, source: str | None = None,
                    base: Path | None = None, text: str = "") -> Sweep:
    """Validate a parsed sweep document completely; relative paths resolve against ``base``."""
    check_keys(data, TOP_KEYS, "", source)
    raw_scene = data.get("scene")
    if not isinstance(raw_scene, str) or not raw_scene:
        raise _error("scene", "is required: the path of a scene file (relative to the sweep "
                     "file) or \"default\"", source)
    if raw_scene == "default":
        scene = default_scene()
    else:
        path = (base / raw_scene) if base is not None else Path(raw_scene)
        if not path.is_file():
            raise _error("scene", f"scene file {str(path)!r} not found; give a path relative "
                         "to the sweep file, or \"default\"", source)
        scene = load_scene(path)
    scene = _run_overrides(data.get("run", {}), scene, source)
    name = data.get("name", f"{scene.name}_sweep")
    if not isinstance(name, str) or not name:
        raise _error("name", f"must be a non-empty string, got {name!r}", source)
    if "description" in data and not isinstance(data["description"], str):
        raise _error("description", "must be a string", source)
    mode = data.get("mode", "product")
    if mode not in MODES:
        raise _error("mode", f"must be one of {', '.join(MODES)}, got {mode!r}"
                     f"{_hint(str(mode), MODES)}", source)
    defaults: dict[str, Any] = {"seed": _integer(data.get("seed", 0), "seed", source, 0)}
    if "count" in data:
        defaults["count"] = _integer(data["count"], "count", source, 1, MAX_CASES)
    raw = data.get("parameters")
    if not isinstance(raw, Mapping) or not raw:
        raise _error("parameters", "must be a non-empty table naming what to vary, e.g. "
                     "[parameters.\"friction.mu\"] values = [0.0, 0.1]", source)
    robot = scene.robot
    for key in raw:
        _check_name(key, robot, source)
    for key in raw:
        m = _CLEARANCE_ALIAS.fullmatch(key)
        if m and f"joint{m.group(1)}.journal_radius" in raw:
            raise _error(f"parameters.{key}", f"sets joint{m.group(1)}.journal_radius, which "
                         "is also swept: vary one of the two", source)
    axes = tuple(_axis(key, spec, defaults, source) for key, spec in raw.items())
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
    cases: list[Case] = []
    seen: dict[str, int] = {}
    for index, combo in enumerate(combos):
        swept = dict(zip((a.name for a in axes), combo, strict=True))
        case_robot, params = _case_robot(robot, index, swept, source)
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
    return Sweep(name=name, scene=scene, mode=mode, axes=axes, cases=tuple(cases),
                 source=source, text=text)


def load_sweep(path: str | Path) -> Sweep:
    """Read and validate a sweep file (TOML, data only)."""
    path = Path(path)
    data, text = read_toml(path, "sweep")
    source = str(path)
    return sweep_from_dict(data, source=source, base=path.parent, text=text)


# ---- one case, on a worker -----------------------------------------------------------------

_LOCAL = threading.local()
_IDEAL_LOCK = threading.Lock()
_IDEAL_CACHE: OrderedDict[str, SimulationResult | BaseException] = OrderedDict()


def _model(scene: Scene, ideal: bool) -> Model:
    """This thread's loaded model of the scene's structure (a compiled library is not shared
    between threads, whose calls would race on its buffers)."""
    from jointplay.simulation import load_scene_model

    models: dict[tuple[str, bool], Model] = _LOCAL.__dict__.setdefault("models", {})
    key = (scene.robot.structure_hash(), ideal)
    if key not in models:
        models[key] = load_scene_model(scene, ideal=ideal)
    return models[key]


def _ideal_result(case: Case, model: Model) -> tuple[SimulationResult, bool]:
    """The ideal-joint run of the case, shared by every case with the same ideal robot.

    The ideal robot has no clearance, contact or friction parameters, so cases that vary only
    those share one ideal run (deterministic: reusing it gives the very same numbers).
    Returns the result and whether it was reused.
    """
    from jointplay.simulation import simulate

    with _IDEAL_LOCK:
        hit = _IDEAL_CACHE.get(case.ideal_key)
        if hit is not None:
            _IDEAL_CACHE.move_to_end(case.ideal_key)
    if hit is None:
        scene = case.scene.with_robot(ideal_counterpart(case.scene.robot))
        try:
            hit = simulate(scene, model=model, quiet=True)
        except Exception as err:  # deterministic: remembered like a result
            interrupts.raise_if_interrupted()  # not an interrupt, which is no result at all
            hit = err
        with _IDEAL_LOCK:
            _IDEAL_CACHE[case.ideal_key] = hit
            while len(_IDEAL_CACHE) > _IDEAL_CACHE_SIZE:
                _IDEAL_CACHE.popitem(last=False)
        reused = False
    else:
        reused = True
    if isinstance(hit, BaseException):
        raise hit
    return hit, reused


@dataclass(frozen=True)
class CaseOutcome:
    """What a case sends back: its row, and the full result when series are kept."""

    key: str
    row: dict[str, Any]
    result: SimulationResult | None = None


# Contact columns from the contact-phase table (located, never sampled), overall and per
# joint; None (null in the table, NaN in pandas) where the run did not locate them.
CONTACT_METRICS: tuple[tuple[str, str], ...] = (
    ("peak_normal_force", "float"), ("max_penetration", "float"), ("impacts", "int"),
    ("max_approach_speed", "float"))


def metric_columns(clearance_joints: Sequence[int]) -> list[tuple[str, str]]:
    """(column, type) of the summary metrics, type one of float, int, str."""
    cols = [("max_position_error", "float"), ("max_velocity_error", "float"),
            ("max_acceleration_error", "float"), ("rms_position_error", "float")]
    for name, kind in CONTACT_METRICS:
        cols += [(name, kind)] + [(f"{name}_joint{j}", kind) for j in clearance_joints]
    cols += [("peak_note", "str"), ("energy_dissipated", "float"),
             ("energy_balance_error", "float")]
    cols += [(name, "int") for name in ("steps", "rhs_evaluations", "jacobian_evaluations",
                                        "error_test_failures", "integrator_calls", "events")]
    cols += [("simulation_time_s", "float"), ("wall_time_s", "float"), ("cpu_time_s", "float")]
    return cols


def _metrics(result: SimulationResult, ideal: SimulationResult) -> dict[str, Any]:
    def worst(a: np.ndarray, b: np.ndarray) -> float:
        return float(np.max(np.linalg.norm(a - b, axis=1)))

    pos = np.linalg.norm(result.tip_position - ideal.tip_position, axis=1)
    out: dict[str, Any] = {
        "max_position_error": float(np.max(pos)),
        "max_velocity_error": worst(result.tip_velocity, ideal.tip_velocity),
        "max_acceleration_error": worst(result.tip_acceleration, ideal.tip_acceleration),
        "rms_position_error": float(np.sqrt(np.mean(pos**2))),
        "energy_dissipated": float(result.energy["dissipated"][-1]),
        "energy_balance_error": float(np.max(np.abs(result.energy["balance"]))),
        "simulation_time_s": float(result.stats["wall_time_s"]),
    }
    out.update(contact_metrics(result))
    for name in ("steps", "rhs_evaluations", "jacobian_evaluations", "error_test_failures",
                 "integrator_calls", "events"):
        out[name] = int(result.stats.get(name, 0))
    return out


def _number_or_none(value: float) -> float | None:
    return None if math.isnan(value) else float(value)


def contact_metrics(result: SimulationResult) -> dict[str, Any]:
    """Peak force, max penetration, impact count and largest approach speed, overall and per
    clearance joint, from the contact-phase table; ``peak_note`` says why peaks are None."""
    from jointplay.contacts import joint_contacts, overall

    joints = joint_contacts(result)
    out: dict[str, Any] = {"impacts": len(result.impacts)}
    for c in joints:
        out[f"peak_normal_force_joint{c.joint}"] = _number_or_none(c.peak_force)
        out[f"max_penetration_joint{c.joint}"] = _number_or_none(c.max_penetration)
        out[f"impacts_joint{c.joint}"] = c.impacts
        out[f"max_approach_speed_joint{c.joint}"] = _number_or_none(c.max_approach_speed)
    out["peak_normal_force"] = _number_or_none(overall([c.peak_force for c in joints]))
    out["max_penetration"] = _number_or_none(overall([c.max_penetration for c in joints]))
    speeds = [c.max_approach_speed for c in joints if c.impacts]
    out["max_approach_speed"] = max(speeds) if speeds else None
    notes = sorted({f"joint {c.joint}: {c.note}" for c in joints if c.note is not None})
    out["peak_note"] = "; ".join(notes) if notes else None
    return out


def _blank_row(case: Case) -> dict[str, Any]:
    return {"key": case.key, "status": "ok", "error": None, "error_type": None,
            "error_stage": None, "error_time": None, "error_joint": None,
            "parameters": {**case.swept, **case.parameters}, "ideal_reused": None,
            "worker": f"{socket.gethostname()}:{os.getpid()}", "series": None}


def run_case(case: Case, *, series: bool = False,
             hook: Callable[[Case], None] | None = None) -> CaseOutcome:
    """Simulate one case and summarise it; a simulation that fails gives a ``failed`` row.

    Runs on a worker (or in this process): the model is loaded from the compile cache once
    per worker thread. ``hook(case)`` is called first (instrumentation and fault injection).
    """
    from jointplay.simulation import simulate

    if hook is not None:
        hook(case)
    start, cpu = time.perf_counter(), time.process_time()
    row = _blank_row(case)
    model = _model(case.scene, ideal=False)
    ideal_model = _model(case.scene, ideal=True)
    full: SimulationResult | None = None
    stage = "ideal robot"
    try:
        ideal, reused = _ideal_result(case, ideal_model)
        row["ideal_reused"] = reused
        stage = "robot"
        result = simulate(case.scene, model=model, quiet=True)
    except Exception as err:
        # An interrupt that compiled code turned into an error is no outcome: the case is
        # simply not done, and the next run picks it up.
        interrupts.raise_if_interrupted()
        message = err.cause if isinstance(err, SimulationError) else str(err)
        row.update(status="failed", error=f"{stage}: {message or type(err).__name__}",
                   error_type=type(err).__name__, error_stage=_STAGE_SIMULATION,
                   error_time=getattr(err, "time", None), error_joint=getattr(err, "joint",
                                                                              None))
    else:
        metrics = _metrics(result, ideal)
        # None marks a peak the integrator does not locate (see peak_note); anything else
        # must be finite: never an "ok" row with NaN in it.
        bad = [name for name, value in metrics.items()
               if isinstance(value, float) and not math.isfinite(value)]
        if bad:
            row.update(status="failed", error=f"robot: non-finite {', '.join(bad)}",
                       error_type="SimulationError", error_stage=_STAGE_SIMULATION)
        else:
            row.update(metrics)
            if series:
                full = replace(result, ideal=ideal)
    row["wall_time_s"] = time.perf_counter() - start
    # CPU seconds of the process: well below wall time when other work shares the cores.
    row["cpu_time_s"] = time.process_time() - cpu
    return CaseOutcome(case.key, row, full)


def _worker_failure(case: Case, err: BaseException) -> CaseOutcome:
    """A row for a case whose task could not finish (its worker kept dying, or it raised)."""
    row = _blank_row(case)
    row.update(status="failed", error=f"worker: {err}" if str(err) else "worker: "
               f"{type(err).__name__}", error_type=type(err).__name__, error_stage=_STAGE_WORKER,
               worker=None)
    return CaseOutcome(case.key, row, None)


# ---- durable per-case files ----------------------------------------------------------------

def _case_path(out: Path, key: str) -> Path:
    return out / CASES_DIR / f"{key}.json"


def _read_row(out: Path, key: str) -> dict[str, Any] | None:
    """The case's row, or None when it has none or one that is damaged or of another shape
    (that case then runs again instead of breaking the table)."""
    try:
        row = json.loads(_case_path(out, key).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return row if _valid_row(row, key) else None


_INT_METRICS = frozenset(name for name, kind in metric_columns(()) if kind == "int")
_TEXT_FIELDS = ("error", "error_type", "error_stage", "worker", "series", "peak_note")


def _is_number(value: Any, integer: bool = False) -> bool:
    if isinstance(value, bool):
        return False
    return isinstance(value, int) if integer else isinstance(value, (int, float))


def _valid_row(row: Any, key: str) -> bool:
    """A row as :func:`run_case` writes it: the types :func:`build_table` needs, and finite
    metrics when its status is ok."""
    if not isinstance(row, dict) or row.get("key") != key or \
            row.get("status") not in ("ok", "failed"):
        return False
    params = row.get("parameters")
    if not isinstance(params, dict) or not all(_is_number(v) for v in params.values()):
        return False
    if any(row.get(name) is not None and not isinstance(row[name], str)
           for name in _TEXT_FIELDS):
        return False
    if row.get("ideal_reused") is not None and not isinstance(row["ideal_reused"], bool):
        return False
    if row.get("error_time") is not None and not _is_number(row["error_time"]):
        return False
    if row.get("error_joint") is not None and not _is_number(row["error_joint"], True):
        return False
    fixed = {"key", "status", "parameters", "ideal_reused", "error_time", "error_joint",
             *_TEXT_FIELDS}
    for name, value in row.items():
        if name in fixed or value is None:
            continue
        if not _is_number(value, name in _INT_METRICS):
            return False
        if row["status"] == "ok" and not math.isfinite(value):
            return False
    return True


def _is_finished(row: dict[str, Any] | None, out: Path, *, series: bool,
                 retry_failed: bool) -> bool:
    if row is None:
        return False
    if row.get("status") == "ok":
        return not series or (row.get("series") is not None
                              and (out / row["series"]).is_file())
    return row.get("error_stage") == _STAGE_SIMULATION and not retry_failed


def _record(out: Path, outcome: CaseOutcome) -> dict[str, Any]:
    """Write the case's series (if any), then its row: the row file marks the case done."""
    from jointplay.files import atomic_write_text

    row = dict(outcome.row)
    if outcome.result is not None:
        from jointplay.output import write_hdf5

        rel = f"{SERIES_DIR}/{outcome.key}.h5"
        write_hdf5(outcome.result, out / rel)
        row["series"] = rel
    atomic_write_text(_case_path(out, outcome.key), json.dumps(row, sort_keys=True))
    return row


# ---- the table and the figures -------------------------------------------------------------

def build_table(sweep: Sweep, out: str | Path) -> Any:
    """The sweep's table (``pyarrow.Table``) from the case files, written atomically."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    from jointplay.files import atomic_path

    out = Path(out)
    rows = []
    missing = []
    for case in sweep.cases:
        row = _read_row(out, case.key)
        if row is None:
            missing.append(case.index)
        else:
            rows.append((case, row))
    if missing:
        raise SweepError(f"{len(missing)} case(s) of the sweep have no result in "
                         f"{out / CASES_DIR} (first: case {missing[0]}); run the sweep again "
                         "to finish them")
    clearance = list(sweep.scene.robot.clearance_joints)
    columns: dict[str, Any] = {
        "case": pa.array([c.index for c, _ in rows], pa.int64()),
        "key": pa.array([c.key for c, _ in rows], pa.string()),
        "status": pa.array([r["status"] for _, r in rows], pa.string()),
    }
    for name in sweep.parameter_names:
        columns[name] = pa.array([r["parameters"].get(name) for _, r in rows], pa.float64())
    types = {"float": pa.float64(), "int": pa.int64(), "str": pa.string()}
    for name, kind in metric_columns(clearance):
        columns[name] = pa.array([r.get(name) for _, r in rows], types[kind])
    for name, kind in (("ideal_reused", pa.bool_()), ("error", pa.string()),
                       ("error_type", pa.string()), ("error_stage", pa.string()),
                       ("error_time", pa.float64()), ("error_joint", pa.int64()),
                       ("worker", pa.string()), ("series", pa.string())):
        columns[name] = pa.array([r.get(name) for _, r in rows], kind)
    meta = {"jointplay.sweep": sweep.text, "jointplay.sweep_name": sweep.name,
            "jointplay.scene": sweep.scene.name,
            "jointplay.swept": json.dumps(sweep.swept_names),
            "jointplay.mode": sweep.mode}
    table = pa.table(columns).replace_schema_metadata(meta)
    with atomic_path(out / TABLE_NAME) as tmp:
        pq.write_table(table, tmp)
    return table


MAX_PLOT_LINES = 10
PLOT_METRICS: tuple[tuple[str, str, str], ...] = (
    ("max_position_error", "max tip position error", "m"),
    ("max_velocity_error", "max tip velocity error", "m/s"),
    ("max_acceleration_error", "max tip acceleration error", "m/s²"),
    ("energy_dissipated", "energy dissipated", "J"),
    ("peak_normal_force", "peak normal force (located)", "N"),
    ("max_penetration", "max penetration (located)", "m"),
    ("impacts", "impacts", "count"),
    ("max_approach_speed", "largest approach speed", "m/s"),
)


def plot_sweep(sweep: Sweep, table: Any, folder: str | Path) -> list[Path]:
    """One PNG per swept name: the main metrics of every successful case against it.

    In a product sweep, cases sharing the values of the other swept names are joined by a
    line (one line per combination, up to ``MAX_PLOT_LINES``), so each line is a 1-D cut.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.ticker import NullFormatter

    from jointplay.files import atomic_path

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    data = table.to_pydict()
    ok = np.array([s == "ok" for s in data["status"]], dtype=bool)
    paths = []
    for axis in sweep.axes:
        x = np.asarray(data[axis.name], dtype=np.float64)
        others = [a.name for a in sweep.axes if a.name != axis.name]
        groups: dict[tuple[float, ...], list[int]] = {}
        for i in range(len(x)):
            groups.setdefault(tuple(data[o][i] for o in others), []).append(i)
        lines = sweep.mode == "product" and len(groups) <= MAX_PLOT_LINES
        fig = Figure(figsize=(14.0, 6.4), layout="constrained")
        FigureCanvasAgg(fig)
        axs = fig.subplots(2, 4, squeeze=False, sharex=True)
        for ax, (col, label, unit) in zip(axs.ravel(), PLOT_METRICS, strict=True):
            y = np.array([np.nan if v is None else v for v in data[col]], dtype=np.float64)
            keep = ok & np.isfinite(y)
            if lines:
                for n, (values, members) in enumerate(groups.items()):
                    idx = np.array([i for i in members if keep[i]], dtype=int)
                    idx = idx[np.argsort(x[idx], kind="stable")]
                    name = ", ".join(f"{o} = {v:.3g}" for o, v in zip(others, values,
                                                                      strict=True))
                    ax.plot(x[idx], y[idx], "o-", ms=4, lw=1.0, color=f"C{n % 10}",
                            label=name or None)
            else:
                ax.plot(x[keep], y[keep], "o", ms=3, color="C0", alpha=0.7)
            ax.set_title(label, fontsize=10)
            ax.set_ylabel(unit)
            if not keep.any() and ok.any():  # e.g. peaks of fixed-step runs: never located
                ax.text(0.5, 0.5, "not located\n(see the peak_note column)", ha="center",
                        va="center", transform=ax.transAxes, color="C3")
            if axis.log:
                ax.set_xscale("log")
                ticks = sorted(set(axis.values))
                if len(ticks) <= 8:  # label the swept values themselves
                    ax.set_xticks(ticks, [f"{v:.3g}" for v in ticks])
                    ax.tick_params(axis="x", labelrotation=35)
                ax.xaxis.set_minor_formatter(NullFormatter())
            ax.grid(True, alpha=0.3)
        for ax in axs[-1]:
            ax.set_xlabel(axis.name)
        if lines and others:
            axs[0, 0].legend(fontsize=8)
        failed = int(np.sum(~ok))
        note = f", {failed} failed case(s) not shown" if failed else ""
        fig.suptitle(f"{sweep.name}: {len(x)} cases against {axis.name}{note}")
        path = folder / f"{axis.name}.png"
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format="png", dpi=110)
        paths.append(path)
    return paths


# ---- running a sweep -----------------------------------------------------------------------

@dataclass(frozen=True)
class SweepResult:
    """How a run of a sweep went; ``table`` is the ``pyarrow.Table`` written to ``path``."""

    table: Any
    path: Path
    cases: int
    ran: int
    reused: int
    failed: int
    wall_time_s: float
    plots: list[Path]


def default_workers() -> int:
    """min(usable cores, 4): more processes than cores only adds contention."""
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, 4))


def _check_out(out: Path, flag: str) -> Path:
    if out.exists() and not out.is_dir():
        raise _error(flag, f"{out} exists and is not a folder", None)
    target = out
    while not target.exists():
        target = target.parent
    if not os.access(target, os.W_OK | os.X_OK):
        raise _error(flag, f"cannot write to {target}: permission denied", None)
    return out


def _write_manifest(sweep: Sweep, out: Path) -> None:
    from jointplay.files import atomic_write_text

    doc = {"name": sweep.name, "source": sweep.source, "scene": sweep.scene.name,
           "mode": sweep.mode, "swept": sweep.swept_names, "sweep_file": sweep.text,
           "cases": [{"case": c.index, "key": c.key, "parameters": {**c.swept, **c.parameters}}
                     for c in sweep.cases]}
    atomic_write_text(out / MANIFEST_NAME, json.dumps(doc, indent=1))


@contextlib.contextmanager
def _dask_client(client: Any, scheduler: str | None, workers: int | None) -> Iterator[Any]:
    """The given client, or one to the cluster at ``scheduler``, or to a new local cluster
    (closed again on the way out)."""
    if client is not None:
        yield client
        return
    from distributed import Client

    with contextlib.ExitStack() as stack:
        if scheduler:
            try:
                client = Client(scheduler, timeout=CONNECT_TIMEOUT)
            except (OSError, TimeoutError) as err:
                raise SweepError(f"cannot reach the Dask scheduler at {scheduler!r}: {err}") \
                    from None
        else:
            # Workers stopped mid-task by an interrupt leave semaphores that the resource
            # tracker (a process that takes its warning options from ours) cleans up, with a
            # warning that is no concern of the user's.
            option = "ignore:resource_tracker:UserWarning"
            if option not in sys.warnoptions:
                sys.warnoptions.append(option)
            cluster = stack.enter_context(_local_cluster(workers or default_workers()))
            client = Client(cluster)
        stack.callback(client.close)
        yield client


@contextlib.contextmanager
def _local_cluster(workers: int) -> Iterator[Any]:
    """A local cluster whose worker processes ignore SIGINT.

    Ctrl-C at a terminal reaches the whole process group; this process alone must stop the
    sweep, in order (a worker interrupted on its own prints tracebacks and loses its case).
    Workers are forked from a fork server started with SIGINT ignored, which they inherit;
    this process ignores SIGINT only while that server starts, a few milliseconds.
    """
    import multiprocessing

    import dask
    from distributed import LocalCluster

    settings = {}
    if "forkserver" in multiprocessing.get_all_start_methods():
        from multiprocessing import forkserver

        with interrupts.ignoring():
            forkserver.ensure_running()
        settings["distributed.worker.multiprocessing-method"] = "forkserver"
    # Started whole even when Ctrl-C comes meanwhile (then closed, and the interrupt raised).
    # Worker logs only at CRITICAL: a worker that loses its scheduler when a sweep is
    # interrupted logs errors that are no concern of the user's; failed cases come back as
    # rows and errors.
    cluster = None
    try:
        with interrupts.deferred(), dask.config.set(settings):
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address=None, silence_logs=logging.CRITICAL)
        yield cluster
    finally:
        if cluster is not None:
            cluster.close()


def _run_dask(client: Any, pending: Sequence[Case], out: Path, *, series: bool,
              hook: Callable[[Case], None] | None, progress: Any) -> None:
    """Submit every pending case; record each as it completes, in completion order."""
    from distributed import as_completed

    token = uuid.uuid4().hex[:8]
    by_key = {f"jointplay-case-{c.key}-{token}": c for c in pending}
    futures = client.map(run_case, list(pending), key=list(by_key), series=series, hook=hook,
                         retries=RETRIES, pure=False)
    try:
        for future in as_completed(futures):
            case = by_key.pop(future.key)
            try:
                outcome = future.result()
            except Exception as err:  # KilledWorker, or a task that kept raising
                interrupts.raise_if_interrupted()
                if _is_interrupt(err):  # the worker was interrupted: the case is not done
                    future.release()
                    continue
                outcome = _worker_failure(case, err)
            except KeyboardInterrupt:
                if interrupts.interrupted():  # ours, not the worker's
                    raise
                future.release()
                continue
            future.release()
            _record(out, outcome)
            progress.update(1)
    finally:
        if by_key:  # interrupted: nothing left running on the cluster
            client.cancel([f for f in futures if f.key in by_key])


def _is_interrupt(err: BaseException) -> bool:
    """Whether a task's error is an interrupt of the worker (Dask may rebuild its type)."""
    return isinstance(err, KeyboardInterrupt) or type(err).__name__ == "KeyboardInterrupt"


def _check_options(client: Any, workers: int | None, scheduler: str | None) -> None:
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or not 0 <= workers <= limits.MAX_WORKERS):
        raise _error("--workers", f"must be an integer from 0 to {limits.MAX_WORKERS}, got "
                     f"{workers!r}", None)
    if scheduler and (client is not None or workers is not None):
        raise _error("--scheduler", "uses the workers of an existing cluster: give no "
                     "--workers (and no client) with it", None)
    if client is not None and workers is not None:
        raise _error("--workers", "a client brings its own workers; give one or the other",
                     None)


def run_sweep(sweep: Sweep | str | Path, out: str | Path, *, client: Any = None,
              workers: int | None = None, scheduler: str | None = None, series: bool = False,
              retry_failed: bool = False, plots: bool = True, quiet: bool = True,
              hook: Callable[[Case], None] | None = None) -> SweepResult:
    """Run every case of ``sweep`` not already finished in ``out``; write the table and plots.

    Cases run on ``client`` (a ``distributed.Client``) if given, else on the cluster at
    ``scheduler``, else on a new local cluster of ``workers`` processes (default
    :func:`default_workers`); ``workers=0`` runs them one by one in this process, without
    Dask. ``series`` also keeps each case's full time series (``out/series/<key>.h5``).
    Failed simulations are kept as ``failed`` rows; ``retry_failed`` runs them again.
    ``hook(case)`` runs before each case, where the case runs.
    """
    from tqdm import tqdm

    from jointplay.files import sweep_stale
    from jointplay.simulation import load_scene_model

    started = time.perf_counter()
    if not isinstance(sweep, Sweep):
        sweep = load_sweep(sweep)
    out = _check_out(Path(out), "--out")
    _check_options(client, workers, scheduler)
    # Compile once here, so that local workers (and any sharing the cache) only load.
    load_scene_model(sweep.scene)
    load_scene_model(sweep.scene, ideal=True)
    pending = [c for c in sweep.cases
               if not _is_finished(_read_row(out, c.key), out, series=series,
                                   retry_failed=retry_failed)]
    reused = len(sweep.cases) - len(pending)
    serial = workers == 0 and client is None and not scheduler
    with contextlib.ExitStack() as stack:
        cluster = None
        if pending and not serial:  # before anything is written: it may fail to connect
            cluster = stack.enter_context(_dask_client(client, scheduler, workers))
        (out / CASES_DIR).mkdir(parents=True, exist_ok=True)
        for folder in (out, out / CASES_DIR, out / SERIES_DIR, out / PLOTS_DIR):
            sweep_stale(folder)  # temporaries of a run that was killed
        if series:
            (out / SERIES_DIR).mkdir(exist_ok=True)
        _write_manifest(sweep, out)
        progress = stack.enter_context(tqdm(total=len(sweep.cases), initial=reused,
                                            disable=quiet, unit="case", desc=sweep.name,
                                            dynamic_ncols=True))
        if cluster is not None:
            _run_dask(cluster, pending, out, series=series, hook=hook, progress=progress)
        else:
            for case in pending:
                _record(out, run_case(case, series=series, hook=hook))
                progress.update(1)
    table = build_table(sweep, out)
    figures = plot_sweep(sweep, table, out / PLOTS_DIR) if plots else []
    failed = sum(1 for s in table.column("status").to_pylist() if s != "ok")
    return SweepResult(table=table, path=out / TABLE_NAME, cases=len(sweep.cases),
                       ran=len(pending), reused=reused, failed=failed,
                       wall_time_s=time.perf_counter() - started, plots=figures)


# ---- command line --------------------------------------------------------------------------

def cmd_sweep(args: argparse.Namespace) -> int:
    """``jointplay sweep``: validate, run what is not done yet, write the table and plots."""
    sweep = load_sweep(args.sweep)
    _check_options(None, args.workers, args.scheduler)
    quiet = bool(args.quiet)
    if not quiet:
        where = (f"the cluster at {args.scheduler}" if args.scheduler
                 else "this process" if args.workers == 0
                 else f"{args.workers or default_workers()} local worker process(es)")
        print(f"sweep {sweep.name}: {len(sweep.cases)} case(s) of scene {sweep.scene.name} "
              f"({sweep.mode} of {', '.join(sweep.swept_names)}) on {where}")
    result = run_sweep(sweep, args.out, workers=args.workers, scheduler=args.scheduler,
                       series=args.series, retry_failed=args.retry_failed, quiet=quiet)
    if not quiet:
        print(f"{result.cases} case(s): {result.ran} run, {result.reused} reused from "
              f"{Path(args.out) / CASES_DIR}, {result.failed} failed; "
              f"{result.wall_time_s:.1f} s")
        print(f"wrote {result.path}")
        for path in result.plots:
            print(f"wrote {path}")
    return 0


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``sweep`` command to the ``jointplay`` command's subparsers."""
    parser = subparsers.add_parser(
        "sweep", help="simulate a scene for many parameter vectors (Dask), one table out",
        description="Run every case of a sweep file on a Dask cluster (a local one by "
                    "default). Finished cases are kept in OUT/cases/ and skipped when the "
                    "same sweep runs again; the table is OUT/sweep.parquet.")
    parser.add_argument("sweep", help="sweep file (TOML); see docs/sweeps.md")
    parser.add_argument("--out", required=True, help="folder for the table, case files, "
                                                     "plots and series")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="use the Dask cluster at this address (tcp://host:8786) instead "
                             "of starting a local one")
    parser.add_argument("--workers", type=int, metavar="N",
                        help=f"local worker processes (default min(cores, 4) = "
                             f"{default_workers()}); 0 runs the cases in this process")
    parser.add_argument("--series", action="store_true",
                        help="also write every case's full time series (OUT/series/KEY.h5)")
    parser.add_argument("--retry-failed", action="store_true",
                        help="run cases that failed before again (they are kept otherwise)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar, no summary")
    parser.set_defaults(func=cmd_sweep)
    return parser


__all__ = ["Axis", "Case", "CaseOutcome", "Sweep", "SweepError", "SweepResult", "build_table",
           "case_key", "cmd_sweep", "contact_metrics", "default_workers", "load_sweep",
           "metric_columns", "plot_sweep", "register", "run_case", "run_sweep",
           "sweep_from_dict"]
