"""Writing a :class:`SimulationResult` to HDF5 (lossless, self-describing) and CSV (one table).

Both writers go through a temporary file beside the target and rename it only when complete,
so an interrupted or failed write never leaves a truncated file under the final name.

HDF5 layout (format "jointplay-result", version 1); every array carries attrs "unit" and "doc":

* ``/``: the array fields (t, q, u, udot, tau, tip_*, radial_clearance, eccentricity, ...,
  parameters with attr names); attrs scene_name, integrator, coordinate_names, coordinate_units,
  clearance_joints, torque_joints, parameter_names, format, format_version. q, u and udot mix
  angles and lengths, so they also carry per-column "column_units".
* ``/impacts``: the contact-phase table, one row per phase, one dataset per column (time, joint,
  speed, eccentricity, then :data:`~jointplay.results.records.PHASE_FIELDS`), each with its unit;
  group attrs ``rows`` and ``columns``. Files written before the phase columns existed hold
  the first four only and read back with the others NaN (``separated`` False).
* ``/energy``: one dataset per energy component.
* ``/metadata``: string metadata as attrs, other values as JSON attrs of ``/metadata/json``;
  solver statistics as the JSON text dataset ``/metadata/stats``.
* ``/wear``: Archard wear (angle, bearing_depth, journal_depth, volume), when the robot asks
  for it (see :mod:`jointplay.results.wear`); CSV: ``RUN.wear.csv`` beside the samples.
* ``/accuracy``: the run's accuracy statement, when it was checked (``verify``): attributes
  ``tip_error_estimate`` (m), ``agreement_horizon`` (s), ``energy_residual`` (J) and the rest
  of :meth:`~jointplay.results.accuracy.Accuracy.attributes`, the per-joint impact counts of
  both runs, and the dataset ``tolerance_sensitive`` (one flag per row of ``/impacts``).
* ``/ideal``: the ideal-joint result, same layout (without format attrs), when present.
"""

from __future__ import annotations

import json
import os
import tempfile
from collections.abc import Iterable, Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_path
from jointplay.results import wear as wear_files
from jointplay.results.accuracy import Accuracy
from jointplay.results.records import PHASE_FIELDS, Impacts, SimulationResult

FORMAT = "jointplay-result"
FORMAT_VERSION = 1
# With compress=True, only datasets big enough for it to pay are compressed (gzip level 1 with
# shuffle: about 40 % smaller on smooth signals, but ~10x slower to write than raw).
_COMPRESS_MIN_BYTES = 1 << 14

# (field, unit, doc) for every array field; "coord" units depend on the coordinate.
_ARRAYS: list[tuple[str, str, str]] = [
    ("t", "s", "output times"),
    ("q", "coord", "generalized coordinates (columns: coordinate_names)"),
    ("u", "coord/s", "time derivatives of q"),
    ("udot", "coord/s^2", "accelerations from the model at each output sample"),
    ("tau", "N m", "drive torque of each moving joint (columns: torque_joints)"),
    ("tip_position", "m", "end effector position, x and y"),
    ("tip_velocity", "m/s", "end effector velocity, x and y"),
    ("tip_acceleration", "m/s^2", "end effector acceleration, x and y"),
    ("radial_clearance", "m", "Rb - Rj of each clearance joint (order: clearance_joints)"),
    ("eccentricity", "m", "journal centre minus bearing centre, (sample, joint, x/y)"),
    ("penetration", "m", "|e| - c; negative means no contact"),
    ("penetration_rate", "m/s", "time derivative of the penetration"),
    ("normal_force", "N", "normal contact force, >= 0"),
    ("friction_force", "N", "friction force on the journal along the tangent"),
    ("contact_force", "N", "total contact force on the journal, (sample, joint, x/y)"),
    ("sliding_speed", "m/s", "relative tangential speed in the contact"),
]
_IMPACTS: list[tuple[str, str, str]] = [
    ("time", "s", "onset of contact, located by event detection"),
    ("joint", "1", "1-based joint number"),
    ("speed", "m/s", "normal approach speed at onset (before flooring)"),
    ("eccentricity", "m", "journal centre minus bearing centre at onset (ex, ey)"),
]
# Every column of the contact-phase table, in order, with unit and meaning.
IMPACT_COLUMNS: tuple[tuple[str, str, str], ...] = (*_IMPACTS, *PHASE_FIELDS)


def check_output_path(path: str | Path, flag: str = "--out",
                      inputs: Iterable[str | Path | None] = ()) -> Path:
    """Fail early, before any work, if ``path`` cannot become a file.

    The folder must exist and take a new file (tried, not guessed from permission bits), an
    existing ``path`` must be a regular file, and it must not be one of ``inputs`` (the scene
    it was made from). Temporary files of earlier runs that died writing ``path`` are removed.
    """
    from jointplay.common.files import describe_os_error, sweep_stale, temp_tag

    path = Path(path)
    if path.is_dir():
        raise DescriptionError(flag, f"{path} is a folder; give a file name", None)
    if path.exists() and not path.is_file():
        raise DescriptionError(flag, f"{path} exists and is not a regular file; give the name "
                               "of a file to write", None)
    for item in inputs:
        if item is not None and _same_file(path, Path(item)):
            raise DescriptionError(flag, f"{path} is an input of this run ({item}); writing "
                                   "it would overwrite the input: give another name", None)
    parent = path.parent
    if not parent.is_dir():
        raise DescriptionError(flag, f"folder {parent} does not exist", None)
    if not os.access(parent, os.W_OK | os.X_OK):
        raise DescriptionError(flag, f"cannot write to {parent}: permission denied", None)
    try:
        fd, probe = tempfile.mkstemp(prefix=f".{path.name}.{temp_tag()}.", suffix=".part",
                                     dir=parent)
        os.close(fd)
        os.unlink(probe)
    except OSError as err:
        raise DescriptionError(flag, f"cannot write to {parent}: {describe_os_error(err)}",
                               None) from None
    sweep_stale(parent, path.name)
    return path


def _same_file(a: Path, b: Path) -> bool:
    try:
        if a.exists() and b.exists():
            return os.path.samefile(a, b)
        return a.resolve() == b.resolve()
    except OSError:
        return False


def check_distinct_outputs(paths: Mapping[str, str | Path | None]) -> None:
    """Refuse two output flags naming one file (one result would silently replace the other)."""
    seen: dict[Path, str] = {}
    for flag, value in paths.items():
        if not value:
            continue
        resolved = Path(value).resolve()
        if resolved in seen:
            raise DescriptionError(flag, f"{value} is also given to {seen[resolved]}; give each "
                                   "output its own file", None)
        seen[resolved] = flag


# --------------------------------------------------------------------------------------- HDF5


def write_hdf5(result: SimulationResult, path: str | Path, *, compress: bool = False) -> None:
    """Write ``result`` (and its ideal counterpart) to an HDF5 file, atomically.

    ``compress`` gzips the large datasets: smaller files, slower writes; readers need nothing.
    """
    import h5py

    path = check_output_path(path)
    with atomic_path(path) as tmp, h5py.File(tmp, "w", track_order=True) as fh:
        fh.attrs["format"] = FORMAT
        fh.attrs["format_version"] = FORMAT_VERSION
        _write_group(fh, result, compress)
        if result.ideal is not None:
            _write_group(fh.create_group("ideal", track_order=True), result.ideal, compress)


def read_hdf5(path: str | Path) -> SimulationResult:
    """Read a file written by :func:`write_hdf5` back into an equal :class:`SimulationResult`."""
    import h5py

    with h5py.File(path, "r") as fh:
        fmt, version = fh.attrs.get("format"), fh.attrs.get("format_version")
        if fmt != FORMAT or version != FORMAT_VERSION:
            raise DescriptionError("format", f"expected {FORMAT} version {FORMAT_VERSION}, "
                                   f"found {fmt!r} version {version!r}", str(path))
        ideal = _read_group(fh["ideal"]) if "ideal" in fh else None
        return _read_group(fh, ideal)


def _dataset(group: Any, name: str, data: np.ndarray, unit: str, doc: str,
             compress: bool = False) -> None:
    data = np.asarray(data)
    big = compress and data.nbytes >= _COMPRESS_MIN_BYTES and all(data.shape)
    opts: dict[str, Any] = {"compression": "gzip", "compression_opts": 1, "shuffle": True}
    ds = group.create_dataset(name, data=data, **(opts if big else {}))
    ds.attrs["unit"] = unit
    ds.attrs["doc"] = doc


def _strings(values: list[str]) -> np.ndarray:
    import h5py

    return np.array(values, dtype=h5py.string_dtype())


def _to_json(value: Any) -> str:
    def default(obj: Any) -> Any:
        if isinstance(obj, np.ndarray | np.generic):
            return obj.tolist()
        if isinstance(obj, Path):
            return str(obj)
        raise TypeError(f"cannot store {type(obj).__name__} in a result file")

    return json.dumps(value, default=default)


def _write_group(group: Any, r: SimulationResult, compress: bool) -> None:
    import h5py

    group.attrs["scene_name"] = r.scene_name
    group.attrs["integrator"] = r.integrator
    group.attrs["coordinate_names"] = _strings(r.coordinate_names)
    units = r.coordinate_units
    group.attrs["coordinate_units"] = _strings(units)
    group.attrs["clearance_joints"] = np.asarray(r.clearance_joints, dtype=np.int64)
    group.attrs["torque_joints"] = np.asarray(r.torque_joints, dtype=np.int64)
    group.attrs["parameter_names"] = _strings(r.parameter_names)
    for name, unit, doc in _ARRAYS:
        by_column = unit.startswith("coord")  # q, u, udot: angles and lengths side by side
        per = unit.removeprefix("coord")
        _dataset(group, name, getattr(r, name), f"rad{per} or m{per}" if by_column else unit,
                 doc, compress)
        if by_column:
            group[name].attrs["column_units"] = _strings([u + per for u in units])
    _dataset(group, "parameters", r.parameters, "SI", "parameter vector the run used")
    group["parameters"].attrs["names"] = _strings(r.parameter_names)

    impacts = group.create_group("impacts", track_order=True)
    impacts.attrs["doc"] = "contact phases, one row per phase in onset order"
    impacts.attrs["rows"] = len(r.impacts)
    impacts.attrs["columns"] = _strings([name for name, _, _ in IMPACT_COLUMNS])
    for name, unit, doc in IMPACT_COLUMNS:
        _dataset(impacts, name, getattr(r.impacts, name), unit, doc)
    energy = group.create_group("energy", track_order=True)
    for name, values in r.energy.items():
        _dataset(energy, name, values, "J", f"energy: {name}", compress)

    if r.wear is not None:
        wear_files.write_group(group, r.wear)
    if r.accuracy is not None:
        write_accuracy_group(group, r.accuracy)
    meta = group.create_group("metadata", track_order=True)
    as_json = meta.create_group("json", track_order=True)
    for key, value in r.metadata.items():
        if isinstance(value, str):
            meta.attrs[key] = value
        else:
            as_json.attrs[key] = _to_json(value)
    meta.create_dataset("stats", data=_to_json(r.stats), dtype=h5py.string_dtype())


def _str_list(values: Any) -> list[str]:
    return [v.decode() if isinstance(v, bytes) else str(v) for v in np.asarray(values).tolist()]


def _int_list(values: Any) -> list[int]:
    return [int(v) for v in np.asarray(values).ravel()]


def _read_group(group: Any, ideal: SimulationResult | None = None) -> SimulationResult:
    arrays = {name: group[name][()] for name, _, _ in _ARRAYS}
    table = group["impacts"]
    # Columns a file lacks (written before the phase columns existed) come back NaN.
    impacts = Impacts(**{name: table[name][()] for name, _, _ in IMPACT_COLUMNS
                         if name in table})
    energy = {name: ds[()] for name, ds in group["energy"].items()}
    meta = group["metadata"]
    metadata: dict[str, Any] = {str(k): str(v) for k, v in meta.attrs.items()}
    metadata.update({str(k): json.loads(v) for k, v in meta["json"].attrs.items()})
    stats_text = meta["stats"][()]
    stats = json.loads(stats_text.decode() if isinstance(stats_text, bytes) else stats_text)
    return SimulationResult(
        scene_name=str(group.attrs["scene_name"]),
        integrator=str(group.attrs["integrator"]),
        coordinate_names=_str_list(group.attrs["coordinate_names"]),
        torque_joints=_int_list(group.attrs["torque_joints"]),
        clearance_joints=_int_list(group.attrs["clearance_joints"]),
        impacts=impacts,
        energy=energy,
        parameter_names=_str_list(group.attrs["parameter_names"]),
        parameters=group["parameters"][()],
        stats=stats,
        metadata=metadata,
        ideal=ideal,
        wear=wear_files.read_group(group["wear"]) if "wear" in group else None,
        accuracy=read_accuracy_group(group["accuracy"]) if "accuracy" in group else None,
        **arrays,
    )


# ----------------------------------------------------------------------------------- accuracy

def write_accuracy_group(parent: Any, accuracy: Accuracy) -> None:
    """``/accuracy``: the accuracy statement's numbers as attributes (SI units), the per-joint
    impact counts of the run and its check, and one tolerance-sensitive flag per impact."""
    group = parent.create_group("accuracy", track_order=True)
    group.attrs["doc"] = ("the run checked against the same run at tolerances 10x tighter: "
                          "estimated errors, energy residuals, agreement horizon")
    for key, value in accuracy.attributes().items():
        group.attrs[key] = value
    joints = sorted(accuracy.impacts_per_joint)
    group.attrs["count_joints"] = np.asarray(joints, dtype=np.int64)
    group.attrs["count_run"] = np.asarray([accuracy.impacts_per_joint[j][0] for j in joints],
                                          dtype=np.int64)
    group.attrs["count_check"] = np.asarray([accuracy.impacts_per_joint[j][1] for j in joints],
                                            dtype=np.int64)
    _dataset(group, "tolerance_sensitive", accuracy.tolerance_sensitive.astype(bool), "1",
             "per row of /impacts: at or after the agreement horizon (changes with tolerance)")


def read_accuracy_group(group: Any) -> Accuracy:
    a = dict(group.attrs)
    joints = [int(j) for j in a["count_joints"]]
    counts = {j: (int(r), int(c)) for j, r, c in zip(joints, a["count_run"], a["count_check"],
                                                      strict=True)}
    fields = {name: a[name] for name in ("rtol", "atol", "check_rtol", "check_atol",
                                         "tip_error_estimate", "tip_velocity_error_estimate",
                                         "energy_residual", "check_energy_residual",
                                         "dissipated", "agreement_horizon", "t_end",
                                         "check_wall_s")}
    return Accuracy(**{k: float(v) for k, v in fields.items()},
                    agreed_impacts=int(a["agreed_impacts"]), impacts=int(a["impacts"]),
                    check_impacts=int(a["check_impacts"]), impacts_per_joint=counts,
                    tolerance_sensitive=np.asarray(group["tolerance_sensitive"][()], dtype=bool))


# ---------------------------------------------------------------------------------------- CSV


def csv_columns(result: SimulationResult) -> Iterator[tuple[str, np.ndarray]]:
    """The flat table as (header, column) pairs; headers carry the unit, e.g. ``q2 [rad]``."""
    yield "t [s]", result.t
    yield from _motion_columns(result, "")
    for k, j in enumerate(result.torque_joints):
        yield f"tau{j} [N m]", result.tau[:, k]
    for k, j in enumerate(result.clearance_joints):
        yield f"delta{j} [m]", result.penetration[:, k]
        yield f"ddelta{j} [m/s]", result.penetration_rate[:, k]
        yield f"f_n{j} [N]", result.normal_force[:, k]
        yield f"f_t{j} [N]", result.friction_force[:, k]
        yield f"f_x{j} [N]", result.contact_force[:, k, 0]
        yield f"f_y{j} [N]", result.contact_force[:, k, 1]
        yield f"v_slide{j} [m/s]", result.sliding_speed[:, k]
    for name, values in result.energy.items():
        yield f"energy_{name} [J]", values
    if result.ideal is not None:
        yield from _motion_columns(result.ideal, "ideal_")


def _motion_columns(r: SimulationResult, prefix: str) -> Iterator[tuple[str, np.ndarray]]:
    units = r.coordinate_units
    for i, (name, unit) in enumerate(zip(r.coordinate_names, units, strict=True)):
        yield f"{prefix}{name} [{unit}]", r.q[:, i]
    for i, (name, unit) in enumerate(zip(r.coordinate_names, units, strict=True)):
        yield f"{prefix}d{name} [{unit}/s]", r.u[:, i]
    for i, (name, unit) in enumerate(zip(r.coordinate_names, units, strict=True)):
        yield f"{prefix}dd{name} [{unit}/s^2]", r.udot[:, i]
    for key, values, unit in (("", r.tip_position, "m"), ("v", r.tip_velocity, "m/s"),
                              ("a", r.tip_acceleration, "m/s^2")):
        yield f"{prefix}tip_{key}x [{unit}]", values[:, 0]
        yield f"{prefix}tip_{key}y [{unit}]", values[:, 1]


def impacts_csv_path(path: str | Path) -> Path:
    """Where the contact-phase table goes beside the samples: ``RUN.csv`` -> ``RUN.impacts.csv``."""
    path = Path(path)
    stem = path.name.removesuffix(".csv") if path.suffix == ".csv" else path.name
    return path.with_name(f"{stem}.impacts.csv")


def impact_csv_columns(impacts: Impacts) -> Iterator[tuple[str, np.ndarray, str]]:
    """(header, column, number format) of the phase table; headers carry the unit."""
    for name, unit, _ in IMPACT_COLUMNS:
        values = np.asarray(getattr(impacts, name))
        if name == "eccentricity":
            ecc = values.reshape(-1, 2)
            yield f"eccentricity_x [{unit}]", ecc[:, 0], "%.17g"
            yield f"eccentricity_y [{unit}]", ecc[:, 1], "%.17g"
        elif name in ("joint", "separated"):  # integers: joint number, 1 = separated
            yield name, values.astype(np.int64), "%d"
        else:
            yield f"{name} [{unit}]", values, "%.17g"


def write_csv(result: SimulationResult, path: str | Path) -> list[Path]:
    """Write one row per output sample to ``path`` and one row per contact phase to
    :func:`impacts_csv_path` beside it (phases are events, not samples); return both paths.

    Each file is written atomically; the phase table first, so a samples file under its
    final name always has its phase table beside it, and a samples file that cannot be
    written takes the phase table with it.
    """
    path = check_output_path(path)
    phases = check_output_path(impacts_csv_path(path))
    side = [phases]
    if result.wear is not None:
        side.append(check_output_path(wear_files.csv_path(path)))
    heads, cols, fmts = zip(*impact_csv_columns(result.impacts), strict=True)
    rows = np.column_stack([np.asarray(c, dtype=np.float64) for c in cols]) if len(
        result.impacts) else np.zeros((0, len(heads)))
    with atomic_path(phases) as tmp:
        np.savetxt(tmp, rows, fmt=list(fmts), delimiter=",", header=",".join(heads),
                   comments="", encoding="utf-8")
    headers, columns = zip(*csv_columns(result), strict=True)
    table = np.column_stack([np.asarray(c, dtype=np.float64) for c in columns])
    try:
        if result.wear is not None:
            wear_files.write_csv(result.wear, side[-1])
        with atomic_path(path) as tmp:
            np.savetxt(tmp, table, fmt="%.17g", delimiter=",", header=",".join(headers),
                       comments="", encoding="utf-8")
    except BaseException:
        # the files are one result: without its samples the tables must not stay behind
        for table_path in side:
            table_path.unlink(missing_ok=True)
        raise
    return [path, *side]
