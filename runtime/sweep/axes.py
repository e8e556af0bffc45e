"""The swept names of a sweep file and their values: which names a sweep may vary, and each
name's values from a grid, a list or seeded random samples, validated field by field."""

from __future__ import annotations

import math
import re
import zlib
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from jointplay.common import limits
from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import check_keys
from jointplay.robot import Robot
from jointplay.robot.structure import Parameter, Structure, parameter_layout

SPACINGS: tuple[str, ...] = ("linear", "log")
# Distribution -> its parameters, in numpy's conventions (lognormal: of the underlying normal).
DISTRIBUTIONS: dict[str, tuple[str, ...]] = {
    "uniform": ("low", "high"),
    "normal": ("mean", "std"),
    "lognormal": ("mu", "sigma"),
}
GRID_KEYS: tuple[str, ...] = ("start", "stop", "num", "spacing")
RANDOM_KEYS: tuple[str, ...] = ("distribution", "count", "seed")
MAX_CASES = limits.MAX_CASES
# Names of the model's structure: changing one changes the generated code.
_STRUCTURAL = ("contact.law", "contact.stiffness", "friction.law", "friction.ramp",
               "gravity.enabled", "drive.enabled", "links", "joints", "name")
CLEARANCE_ALIAS = re.compile(r"joint(\d+)\.clearance")


@dataclass(frozen=True)
class Axis:
    """One swept name and its values, in order."""

    name: str
    kind: str  # "grid", "values" or "random"
    values: tuple[float, ...]
    log: bool = False  # values spread over decades: plot on a log axis


def _error(field_name: str, message: str, source: str | None) -> DescriptionError:
    return DescriptionError(field_name, message, source)


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


def check_name(name: str, robot: Robot, source: str | None) -> None:
    """Accept a robot parameter or an alias; otherwise say exactly why the name is refused."""
    where = f"parameters.{name}"
    known = [p.name for p in robot.parameters()]
    if name in known:
        return
    aliases = [f"joint{j}.clearance" for j in robot.clearance_joints]
    match = CLEARANCE_ALIAS.fullmatch(name)
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
    # Every parameter any structure of this many links can have, to explain a missing one.
    superset = {p.name: p for stiffness in (None, "johnson") for p in parameter_layout(Structure(
        links=n, joints=("locked_clearance",) * n, gravity=True, contact_law="flores",
        contact_stiffness=stiffness, friction_law="coulomb", friction_ramp="linear",
        drive=True, lubrication="short-bearing", wear="archard"))}
    if name in superset:
        why = _why_absent(superset[name], robot)
        raise _error(where, f"is not a parameter of the base scene's model: {why}. Turning "
                     "an effect on changes the model's structure, which a sweep cannot do",
                     source)
    raise _error(where, "is not a parameter of the base scene's model"
                 f"{did_you_mean(name, known + aliases)}", source)


def read_axis(name: str, spec: Any, defaults: Mapping[str, Any], source: str | None) -> Axis:
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
    if forms[0] == "values":
        return _values_axis(name, spec, where, source)
    if forms[0] == "grid":
        return _grid_axis(name, spec, where, source)
    return _random_axis(name, spec, defaults, where, source)


def _values_axis(name: str, spec: Mapping[str, Any], where: str, source: str | None) -> Axis:
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


def _grid_axis(name: str, spec: Mapping[str, Any], where: str, source: str | None) -> Axis:
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
                     f"{spacing!r}{did_you_mean(str(spacing), SPACINGS)}", source)
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


def _random_axis(name: str, spec: Mapping[str, Any], defaults: Mapping[str, Any], where: str,
                 source: str | None) -> Axis:
    dist = spec["distribution"]
    if dist not in DISTRIBUTIONS:
        raise _error(f"{where}.distribution", f"must be one of {', '.join(DISTRIBUTIONS)}, "
                     f"got {dist!r}{did_you_mean(str(dist), DISTRIBUTIONS)}", source)
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


def _why_absent(prm: Parameter, robot: Robot) -> str:
    """Why the base robot's model has no slot for a parameter some other structure has."""
    if prm.owner == "gravity":
        return "gravity is disabled in the base scene (gravity.enabled = false)"
    if prm.owner == "contact" and robot.clearance_joints:
        return ("contact.exponent is Hertz's, and the base scene's contact.stiffness is "
                f"{robot.contact.stiffness!r}")
    if prm.owner == "contact":
        return "the base robot has no clearance joint, so it has no contact model"
    if prm.owner == "friction":
        return ("the base robot has no clearance joint" if not robot.clearance_joints
                else "friction is off in the base scene (friction.law = \"none\")")
    if prm.owner in ("lubrication", "wear"):
        return f"{prm.owner} is off in the base scene ({prm.owner}.model = \"none\")"
    j = prm.index or 0
    kind = robot.joints[j - 1].kind
    if prm.attribute == "length" and robot.joints[j - 1].has_clearance:
        return ("the axial length is a parameter of the cylindrical contact laws only "
                "(contact.stiffness = johnson, liu, pereira) and of lubrication and wear, and "
                f"the base scene's contact.stiffness is {robot.contact.stiffness!r} with "
                "neither effect")
    needs = "locked joints" if prm.attribute == "angle" else "joints with clearance"
    return f"joint {j} is kind {kind!r}; only {needs} have {prm.attribute}"
