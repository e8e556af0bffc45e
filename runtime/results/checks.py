"""The checks a results file of the netCDF-4 layout passes before its numbers are used.

Every variable the reader takes must exist with the type and the shape its dimensions give
(the dimensions are the file's own: the lengths of its coordinate variables), every attribute
it parses must be text of the right form (JSON objects where JSON is stored), the coordinate
names must agree with the coordinate variables, and the output times must be finite and
increasing. A failed check is one :class:`~jointplay.common.errors.DescriptionError` naming the
file and the part at fault (see :func:`jointplay.results.integrity.damaged`).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.limits import MAX_OUTPUTS
from jointplay.results.integrity import LoadedGroup, damaged, shown
from jointplay.results.netcdf import _MOTION, IMPACT_COLUMNS, OPTIONAL_GROUPS, SAMPLE_FIELDS

# Coordinate variables (the dimensions) and the kind of values each holds.
_DIMENSIONS = {"time": "f", "coordinate": "text", "joint": "int", "axis": "text",
               "drive": "int", "parameter": "text", "impact": "int"}
_TEXT_ATTRIBUTES = ("scene_name", "integrator", "coordinate_names", "energy_components",
                    "metadata_text")
_JSON_ATTRIBUTES = ("solver_stats", "metadata_json")
# Largest sizes of the dimensions other than time (far beyond any robot jointplay builds).
_MAX_SMALL_DIMENSION = 100_000


def text(value: Any) -> str | None:
    """An attribute's text, or None if it is not text (or not UTF-8)."""
    if isinstance(value, bytes):
        try:
            return value.decode()
        except UnicodeDecodeError:
            return None
    if isinstance(value, np.ndarray) and value.shape == () and value.dtype.kind in "OSU":
        return text(value[()])
    return value if isinstance(value, str) else None


def check_result_group(group: LoadedGroup, path: str | Path) -> None:
    """Refuse ``group`` (the root or ``/ideal``) unless it holds a complete, consistent result."""
    where = group.name.rstrip("/")
    sizes = {dim: _check_dimension(group, dim, kind, path) for dim, kind in _DIMENSIONS.items()}
    if sizes["axis"] != 2:
        raise damaged(path, f"{where}/axis", f"has {sizes['axis']} entries, not 2 (x, y)")
    if sizes["time"] > MAX_OUTPUTS + 1:
        raise damaged(path, f"{where}/time", f"holds {sizes['time']} samples, more than a run "
                      f"can have ({MAX_OUTPUTS + 1})")
    for name in _TEXT_ATTRIBUTES:
        if text(group.attrs.get(name)) is None:
            raise damaged(path, f"{where}@{name}", "missing, or not text")
    for name in _JSON_ATTRIBUTES:
        _json_object(group, name, path)
    _check_coordinates(group, sizes, path)
    _check_times(group, path)
    for _, _, angle_name, offset_name, _, _ in _MOTION:
        _check_variable(group, angle_name, ("time", "coordinate"), "f", sizes, path)
        _check_variable(group, offset_name, ("time", "joint", "axis"), "f", sizes, path)
    for f in SAMPLE_FIELDS:
        _check_variable(group, f.variable, f.dims, "f", sizes, path)
    _check_variable(group, "radial_clearance", ("joint",), "f", sizes, path)
    _check_variable(group, "parameter_value", ("parameter",), "f", sizes, path)
    for name in str(text(group.attrs["energy_components"])).split():
        _check_variable(group, f"energy_{name}", ("time",), "f", sizes, path)
    for name, _, _ in IMPACT_COLUMNS:
        dims = ("impact", "axis") if name == "eccentricity" else ("impact",)
        kind = "int" if name in ("joint", "separated") else "f"
        _check_variable(group, f"impact_{name}", dims, kind, sizes, path)
    _check_impact_joints(group, path)
    for key in str(text(group.attrs["metadata_text"])).split():
        if text(group.attrs.get(key)) is None:
            raise damaged(path, f"{where}@{shown(key)}", "named in metadata_text but missing, "
                          "or not text")
    for name, hooks in OPTIONAL_GROUPS.items():
        if name in group.groups and hooks.check is not None:
            hooks.check(group.groups[name], path)


def _json_object(group: LoadedGroup, name: str, path: str | Path) -> dict[str, Any]:
    where = f"{group.name.rstrip('/')}@{name}"
    value = text(group.attrs.get(name))
    if value is None:
        raise damaged(path, where, "missing, or not text")
    try:
        parsed = json.loads(value)
    except (ValueError, RecursionError) as err:
        raise damaged(path, where, f"is not JSON ({type(err).__name__}: "
                      f"{str(err)[:80]})") from None
    if not isinstance(parsed, dict):
        raise damaged(path, where, f"is JSON {type(parsed).__name__}, not an object")
    return parsed


def _kind_ok(values: np.ndarray, kind: str) -> bool:
    if kind == "f":
        return values.dtype == np.float64
    if kind == "int":
        return values.dtype.kind in "iub" and values.dtype.itemsize <= 8
    return values.dtype.kind in "OS" and all(text(v) is not None for v in values.ravel())


_KIND_NAMES = {"f": "float64", "int": "integers", "text": "text"}


def _check_dimension(group: LoadedGroup, dim: str, kind: str, path: str | Path) -> int:
    values = _variable(group, dim, path)
    if values.ndim != 1 or not _kind_ok(values, kind):
        raise damaged(path, f"{group.name.rstrip('/')}/{dim}", f"a dimension must be a 1-D "
                      f"variable of {_KIND_NAMES[kind]}, found {values.dtype} of shape "
                      f"{values.shape}")
    if dim != "time" and values.size > _MAX_SMALL_DIMENSION:
        raise damaged(path, f"{group.name.rstrip('/')}/{dim}", f"has {values.size} entries")
    return int(values.size)


def _variable(group: LoadedGroup, name: str, path: str | Path) -> np.ndarray:
    values = group.variables.get(name)
    if values is None:
        raise damaged(path, f"{group.name.rstrip('/')}/{name}", "missing")
    return values


def _check_variable(group: LoadedGroup, name: str, dims: tuple[str, ...], kind: str,
                    sizes: dict[str, int], path: str | Path) -> None:
    values = _variable(group, name, path)
    expected = tuple(sizes[d] for d in dims)
    where = f"{group.name.rstrip('/')}/{shown(name)}"
    if values.shape != expected:
        raise damaged(path, where, f"has shape {values.shape}, its dimensions "
                      f"({', '.join(dims)}) give {expected}")
    if not _kind_ok(values, kind):
        raise damaged(path, where, f"holds {values.dtype}, not {_KIND_NAMES[kind]}")


def _check_coordinates(group: LoadedGroup, sizes: dict[str, int], path: str | Path) -> None:
    where = group.name.rstrip("/")
    names = str(text(group.attrs["coordinate_names"])).split()
    if len(names) != sizes["coordinate"] + 2 * sizes["joint"]:
        raise damaged(path, f"{where}@coordinate_names", f"names {len(names)} coordinates; "
                      f"the dimensions give {sizes['coordinate']} angles and "
                      f"{sizes['joint']} journals ({sizes['coordinate'] + 2 * sizes['joint']})")
    angles = [text(v) for v in group.variables["coordinate"].tolist()]
    if names[:sizes["coordinate"]] != angles:
        raise damaged(path, f"{where}/coordinate", "does not match the first names of "
                      "coordinate_names")
    for dim in ("joint", "drive"):
        numbers = group.variables[dim].astype(np.int64)
        if np.any(numbers < 1) or np.unique(numbers).size != numbers.size:
            raise damaged(path, f"{where}/{dim}", "joint numbers must be distinct and >= 1")


def _check_times(group: LoadedGroup, path: str | Path) -> None:
    t = group.variables["time"]
    if not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
        raise damaged(path, f"{group.name.rstrip('/')}/time", "output times must be finite and "
                      "increasing")


def _check_impact_joints(group: LoadedGroup, path: str | Path) -> None:
    where = group.name.rstrip("/")
    joints = set(group.variables["joint"].astype(np.int64).tolist())
    if not set(group.variables["impact_joint"].astype(np.int64).tolist()) <= joints:
        raise damaged(path, f"{where}/impact_joint", "names a joint without clearance")
    if not set(group.variables["impact_separated"].astype(np.int64).tolist()) <= {0, 1}:
        raise damaged(path, f"{where}/impact_separated", "flags must be 0 or 1")


def check_wear(group: LoadedGroup, path: str | Path) -> None:
    sizes = {"joint": _check_dimension(group, "joint", "int", path),
             "angle": _check_dimension(group, "angle", "f", path)}
    for name in ("bearing_depth", "journal_depth"):
        _check_variable(group, name, ("joint", "angle"), "f", sizes, path)
    _check_variable(group, "volume", ("joint",), "f", sizes, path)


_ACCURACY_NUMBERS = ("rtol", "atol", "check_rtol", "check_atol", "tip_error_estimate",
                     "tip_velocity_error_estimate", "energy_residual", "check_energy_residual",
                     "dissipated", "agreement_horizon", "t_end", "check_wall_s",
                     "agreed_impacts", "impacts", "check_impacts")


def check_accuracy(group: LoadedGroup, path: str | Path) -> None:
    where = group.name.rstrip("/")
    for name in _ACCURACY_NUMBERS:
        value = group.attrs.get(name)
        if not (isinstance(value, int | float | np.integer | np.floating)
                and not isinstance(value, bool)):
            raise damaged(path, f"{where}@{name}", "missing, or not a number")
    sizes = {"joint": _check_dimension(group, "joint", "int", path),
             "impact": _check_dimension(group, "impact", "int", path)}
    for name in ("count_run", "count_check"):
        _check_variable(group, name, ("joint",), "int", sizes, path)
    _check_variable(group, "tolerance_sensitive", ("impact",), "int", sizes, path)
    for name in ("agreed_impacts", "impacts", "check_impacts"):
        value = float(group.attrs[name])
        if not (value.is_integer() and 0 <= value <= 1e12):
            raise damaged(path, f"{where}@{name}", "must be a count")
