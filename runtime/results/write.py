"""Writing a :class:`SimulationResult` to a results file (netCDF-4/CF, lossless,
self-describing) and CSV (one table), and reading the file back (:func:`read`).

The results file's layout is described in :mod:`jointplay.results.netcdf`. It is built in
memory and written with plain file I/O through a temporary file beside the target, renamed
only when complete, so an interrupted or failed write never leaves a truncated file under the
final name; inside a command every output is renamed together at the end
(:func:`~jointplay.common.files.all_or_nothing`).

:func:`read` also reads the earlier plain-HDF5 layout (format "jointplay-result", version 1:
arrays at the root with attrs "unit" and "doc", the phase table in ``/impacts``, energies in
``/energy``, metadata in ``/metadata``, wear in ``/wear``, the ideal run in ``/ideal``).
"""

from __future__ import annotations

import contextlib
import json
import os
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common import interrupts
from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_path
from jointplay.results import wear as wear_files
from jointplay.results.netcdf import to_json
from jointplay.results.records import PHASE_FIELDS, Impacts, SimulationResult

FORMAT = "jointplay-result"
FORMAT_VERSION = 1  # of the legacy layout read by _read_group; the current: netcdf.py
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
    from jointplay.common.names import temp_stem

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
    probe = parent / f".{temp_stem(path.name)}.{temp_tag()}.{os.urandom(4).hex()}.part"
    try:
        # Made and removed with Ctrl-C deferred: an interrupt in between leaves no probe.
        with interrupts.deferred():
            try:
                os.close(os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
            finally:
                with contextlib.suppress(FileNotFoundError):
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


# --------------------------------------------------------------------------------------- HDF5


def write_hdf5(result: SimulationResult, path: str | Path, *, compress: bool = False,
               checksums: bool = True) -> None:
    """Write ``result`` (and its ideal counterpart) as a netCDF-4/CF file, atomically.

    The file is built in memory and written with plain file I/O (see
    :func:`~jointplay.common.files.write_hdf5_in_memory`): a full disk is a one-line
    :class:`~jointplay.common.errors.FileError` and leaves nothing behind. ``compress`` gzips
    the large variables: smaller files, slower writes; readers need nothing. ``checksums``
    (the default) stores every numeric variable with HDF5's Fletcher-32 and the file's
    SHA-256 digest (:mod:`jointplay.results.integrity`); without them the file is the
    unchecked version 2 of the layout, as written before checksums existed. The layout is
    described in :mod:`jointplay.results.netcdf`.
    """
    from jointplay.common.files import write_hdf5_in_memory
    from jointplay.results import netcdf

    path = check_output_path(path)

    def build(fh: Any) -> None:
        netcdf.write_file(netcdf.NetcdfGroup(fh, checksums=checksums), result, compress)

    # HDF5 1.10's format: a one-chunk variable needs no chunk index (a file of short runs
    # keeps its size with Fletcher-32), and HDF5 checksums its own headers too.
    write_hdf5_in_memory(path, build, libver=_CHECKED_LIBVER if checksums else None)


_CHECKED_LIBVER = ("v110", "v110")


def read(path: str | Path) -> SimulationResult:
    """Read a results file: the :class:`SimulationResult` that ``jointplay simulate --out`` (or
    :func:`write_hdf5`) stored, equal, field by field, to the one that was written.

    Every check of :func:`read_checked` is made first. Files of the earlier layouts
    (``format_version`` 1 and 2, without checksums) are read as well.

    Parameters
    ----------
    path : str or pathlib.Path
        The results file (.h5, netCDF-4).

    Returns
    -------
    SimulationResult
        The result, with its ideal counterpart when the run had one.

    Raises
    ------
    DescriptionError
        Naming the file and the part at fault, for a file that fails a check (not a results
        file, truncated, a checksum that does not match).

    Examples
    --------
    >>> import jointplay
    >>> from jointplay.results.write import write_hdf5
    >>> result = jointplay.simulate(jointplay.default_scene().with_run(t_end=0.01))
    >>> write_hdf5(result, "run.h5")
    >>> again = jointplay.read("run.h5")
    >>> again.scene_name, again.t.shape, bool((again.q == result.q).all())
    ('paper_4dof', (11,), True)
    """
    return read_checked(path)[0]


def read_checked(path: str | Path) -> tuple[SimulationResult, bool]:
    """The result in ``path`` and whether its checksums were verified (False: a file
    written before results files carried them, read unchecked).

    Before anything is trusted: ``path`` must be a regular, non-empty file (nothing else is
    opened: a FIFO, a device); every variable's stored size must back its declared shape;
    the digest and HDF5's Fletcher-32 of every chunk must match; every variable must have
    the type and shape its dimensions give, every attribute the form the layout gives it.
    """
    import h5py

    from jointplay.results import checks, integrity, netcdf, units

    integrity.regular_file(path)
    try:
        with h5py.File(path, "r") as fh:
            root = integrity.load(fh, path)
    except DescriptionError:
        raise
    except OSError as err:
        raise _unreadable(path, err) from None
    except _DAMAGE as err:
        raise integrity.damaged(path, "/", f"{type(err).__name__}: {err}") from None
    checked = integrity.verify(root, path)
    fmt, version = _text(root.attrs.get("format")), root.attrs.get("format_version")
    known = (1, netcdf.UNCHECKED_VERSION, netcdf.FORMAT_VERSION)
    if fmt == "jointplay-mechanism":  # the mechanism results' FORMAT
        raise DescriptionError("format", "this is a mechanism's results file: read it with "
                               "jointplay.mechanism.results.read_mechanism_result", str(path))
    if fmt != FORMAT or not isinstance(version, int | np.integer) or version not in known:
        raise DescriptionError("format", f"expected {FORMAT} version {netcdf.FORMAT_VERSION} "
                               f"(or 1, 2), found {integrity.shown(fmt)} version "
                               f"{integrity.shown(version)}", str(path))
    if version == netcdf.FORMAT_VERSION and not checked:
        raise integrity.damaged(path, integrity.DIGEST_ATTRIBUTE, "missing: a version 3 file "
                                "always carries its checksum")
    try:
        if version == 1:
            ideal = _read_group(root["ideal"]) if "ideal" in root.groups else None
            return _read_group(root, ideal), checked
        for group in (root, *([root.groups["ideal"]] if "ideal" in root.groups else [])):
            checks.check_result_group(group, path)
            units.convert_units(group, path)  # a unit edited since: converted, or refused
        return netcdf.read_file(root), checked
    except DescriptionError:
        raise
    except _DAMAGE as err:  # what the checks above do not foresee still reads as damage
        raise integrity.damaged(path, "/", f"{type(err).__name__}: {err}") from None


# What a damaged file can make h5py, numpy or json raise while it is read.
_DAMAGE = (KeyError, ValueError, TypeError, IndexError, AttributeError, OverflowError,
           UnicodeError, RuntimeError, MemoryError)


def _unreadable(path: str | Path, err: OSError) -> DescriptionError:
    from jointplay.common.files import describe_os_error

    detail = " ".join(describe_os_error(err).split())
    return DescriptionError("HDF5", f"cannot be read as a results file ({detail}); "
                            "give a file written by `jointplay simulate --out RUN.h5`",
                            str(path))


read_hdf5 = read
"""The name :func:`read` had before the results file became netCDF-4 (kept for callers)."""


def _text(value: Any) -> Any:
    return value.decode() if isinstance(value, bytes) else value


def _dataset(group: Any, name: str, data: np.ndarray, unit: str, doc: str,
             compress: bool = False) -> None:
    """A dataset of the version-1 layout (kept to write such files in tests of the reader)."""
    data = np.asarray(data)
    big = compress and data.nbytes >= _COMPRESS_MIN_BYTES and all(data.shape)
    opts: dict[str, Any] = {"compression": "gzip", "compression_opts": 1, "shuffle": True}
    ds = group.create_dataset(name, data=data, **(opts if big else {}))
    ds.attrs["unit"] = unit
    ds.attrs["doc"] = doc


def _strings(values: list[str]) -> np.ndarray:
    import h5py

    return np.array(values, dtype=h5py.string_dtype())


def write_hdf5_v1(result: SimulationResult, path: str | Path) -> None:
    """The version-1 layout (plain HDF5, no dimensions), for tests that the reader keeps
    reading files written before the netCDF-4 layout."""
    import h5py

    with atomic_path(path) as tmp, h5py.File(tmp, "w", track_order=True) as fh:
        fh.attrs["format"] = FORMAT
        fh.attrs["format_version"] = 1
        _write_group(fh, result, False)
        if result.ideal is not None:
            _write_group(fh.create_group("ideal", track_order=True), result.ideal, False)


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
    meta = group.create_group("metadata", track_order=True)
    as_json = meta.create_group("json", track_order=True)
    for key, value in r.metadata.items():
        if isinstance(value, str):
            meta.attrs[key] = value
        else:
            as_json.attrs[key] = to_json(value)
    meta.create_dataset("stats", data=to_json(r.stats), dtype=h5py.string_dtype())


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
        **arrays,
    )


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
    :func:`impacts_csv_path` beside it (phases are events, not samples), and the wear table
    when the result has one; return the paths.

    The files are one result: written together (:func:`~jointplay.common.files.all_or_nothing`),
    so either all appear or none does, and a previous set stays as it was.
    """
    from jointplay.common.files import OutputPlan, all_or_nothing

    plan = OutputPlan()
    path = check_output_path(plan.file("--csv", path))
    phases = check_output_path(plan.file("--csv", impacts_csv_path(path), "the phase table"))
    side = [phases]
    if result.wear is not None:
        side.append(check_output_path(plan.file("--csv", wear_files.csv_path(path),
                                                "the wear table")))
    plan.check()
    heads, cols, fmts = zip(*impact_csv_columns(result.impacts), strict=True)
    rows = np.column_stack([np.asarray(c, dtype=np.float64) for c in cols]) if len(
        result.impacts) else np.zeros((0, len(heads)))
    headers, columns = zip(*csv_columns(result), strict=True)
    table = np.column_stack([np.asarray(c, dtype=np.float64) for c in columns])
    with all_or_nothing(plan):
        with atomic_path(phases) as tmp:
            np.savetxt(tmp, rows, fmt=list(fmts), delimiter=",", header=",".join(heads),
                       comments="", encoding="utf-8")
        if result.wear is not None:
            wear_files.write_csv(result.wear, side[-1])
        with atomic_path(path) as tmp:
            np.savetxt(tmp, table, fmt="%.17g", delimiter=",", header=",".join(headers),
                       comments="", encoding="utf-8")
    return [path, *side]
