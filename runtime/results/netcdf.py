"""A :class:`SimulationResult` as a netCDF-4 file (HDF5 underneath) in the CF conventions.

Any netCDF reader sees named dimensions, coordinate variables and a ``units`` (UDUNITS) and
``long_name`` on every numeric variable: ``xarray.open_dataset("run.h5")``, ncdump, Panoply,
MATLAB's ``ncread``. :func:`read_result` gives back the very result that was written.

Layout (``format = "jointplay-result"``, ``format_version = 3``; version 2 is the same layout
without checksums, see :mod:`jointplay.results.integrity`):

* dimensions ``time`` (output samples), ``coordinate`` (the joint-angle coordinates q2, q3,
  ...), ``joint`` (the clearance joints, coordinate variable: their 1-based numbers),
  ``axis`` (x, y), ``drive`` (the driven joints), ``parameter`` (names), ``impact`` (the
  contact phases, numbered from 1);
* per sample: ``joint_angle``, ``joint_angular_velocity``, ``joint_angular_acceleration``
  (time, coordinate); the journal-centre coordinates ex, ey of each clearance joint and their
  rates as ``journal_offset*`` (time, joint, axis); ``drive_torque``; ``tip_*``; the contact
  quantities (time, joint[, axis]); ``energy_<component>`` (time);
* the contact-phase table as ``impact_<column>`` variables along ``impact``;
* the scene's and the run's provenance as global attributes (``Conventions = "CF-1.11"``,
  ``scene_name``, ``integrator``, every string metadata item under its own name, the rest as
  JSON in ``metadata_json``, the solver statistics as JSON in ``solver_stats``);
* the ideal-joint counterpart in the group ``/ideal`` (same layout), and the optional groups of
  :data:`OPTIONAL_GROUPS` (``/wear``, ``/accuracy``) when the result holds them.

Adding an optional part of a result to the file is one entry in :data:`OPTIONAL_GROUPS`: the
result's attribute name, a function writing the value into a new group and one reading it back
(see :func:`_write_wear` and :func:`_read_wear`).
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from jointplay.results.records import PHASE_FIELDS, Impacts, SimulationResult, eccentricity_columns

FORMAT = "jointplay-result"
FORMAT_VERSION = 3
UNCHECKED_VERSION = 2
"""The same layout written without checksums (before they existed, or ``checksums=False``)."""
CONVENTIONS = "CF-1.11"
# gzip level 1 with shuffle, only where it pays (see write_hdf5's ``compress``).
_COMPRESS_MIN_BYTES = 1 << 14

# UDUNITS spellings of the units the records' docstrings write as "m/s^2" and so on.
UDUNITS = {"s": "s", "m": "m", "m/s": "m s-1", "m/s^2": "m s-2", "rad": "rad",
           "rad/s": "rad s-1", "rad/s^2": "rad s-2", "N": "N", "N m": "N m", "N s": "N s",
           "J": "J", "1": "1", "bool": "1", "m^3": "m3"}


class Field(NamedTuple):
    """A per-sample array of the result and its variable in the file."""

    attribute: str  # field of SimulationResult
    variable: str  # name in the file
    dims: tuple[str, ...]
    units: str
    long_name: str


# Per-sample arrays stored as they are (q, u and udot are split by unit, see _write_motion).
SAMPLE_FIELDS: tuple[Field, ...] = (
    Field("tau", "drive_torque", ("time", "drive"), "N m", "drive torque of each driven joint"),
    Field("tip_position", "tip_position", ("time", "axis"), "m", "end effector position"),
    Field("tip_velocity", "tip_velocity", ("time", "axis"), "m s-1", "end effector velocity"),
    Field("tip_acceleration", "tip_acceleration", ("time", "axis"), "m s-2",
          "end effector acceleration"),
    Field("eccentricity", "eccentricity", ("time", "joint", "axis"), "m",
          "journal centre minus bearing centre"),
    Field("penetration", "penetration", ("time", "joint"), "m",
          "penetration |e| - c (negative: no contact)"),
    Field("penetration_rate", "penetration_rate", ("time", "joint"), "m s-1",
          "time derivative of the penetration"),
    Field("normal_force", "normal_force", ("time", "joint"), "N", "normal contact force"),
    Field("friction_force", "friction_force", ("time", "joint"), "N",
          "friction force on the journal along the tangent"),
    Field("contact_force", "contact_force", ("time", "joint", "axis"), "N",
          "total contact force on the journal"),
    Field("sliding_speed", "sliding_speed", ("time", "joint"), "m s-1",
          "relative tangential speed in the contact"),
)
# q, u, udot: angle columns (rad) along "coordinate", journal offsets (m) along joint x axis.
_MOTION = (("q", "", "joint_angle", "journal_offset", "", "position"),
           ("u", " s-1", "joint_angular_velocity", "journal_offset_velocity", "time derivative",
            "velocity"),
           ("udot", " s-2", "joint_angular_acceleration", "journal_offset_acceleration",
            "second time derivative", "acceleration"))
_IMPACT_ONSET = (("time", "s", "onset of contact, located by event detection"),
                 ("joint", "1", "1-based number of the joint in contact"),
                 ("speed", "m/s", "normal approach speed at onset (before flooring)"),
                 ("eccentricity", "m", "journal centre minus bearing centre at onset"))
IMPACT_COLUMNS: tuple[tuple[str, str, str], ...] = (*_IMPACT_ONSET, *PHASE_FIELDS)


# Attributes of the format itself: metadata items of these names go into metadata_json.
_RESERVED = frozenset({"Conventions", "title", "source", "format", "format_version", "comment",
                       "scene_name", "integrator", "coordinate_names", "energy_components",
                       "solver_stats", "metadata_text", "metadata_json", "history"})


class OptionalGroup(NamedTuple):
    """An optional part of a result, stored in a group of its own when present."""

    write: Callable[[Any, Any], None]  # (new group, value)
    read: Callable[[Any], Any]  # (group) -> value
    # (group read into memory, file path): raises if the group cannot be read (see checks.py)
    check: Callable[[Any, Any], None] | None = None


def _write_wear(group: Any, wear: Any) -> None:
    nc, bins = np.asarray(wear.bearing_depth).reshape(len(wear.joints), -1).shape
    group.dimensions = {"joint": nc, "angle": bins}
    _variable(group, "joint", ("joint",), np.asarray(wear.joints, dtype=np.int64), "1",
              "1-based number of the clearance joint")
    _variable(group, "angle", ("angle",), wear.angle, "rad",
              "angular bin centre, in the frame of the surface's link")
    _variable(group, "bearing_depth", ("joint", "angle"), wear.bearing_depth, "m",
              "mean worn depth over the bin on the bearing")
    _variable(group, "journal_depth", ("joint", "angle"), wear.journal_depth, "m",
              "mean worn depth over the bin on the journal")
    _variable(group, "volume", ("joint",), wear.volume, "m3", "worn volume of each surface")
    group.attrs["comment"] = ("Archard wear integrated over the run; the geometry is not "
                              "updated with it")


def _read_wear(group: Any) -> Any:
    from jointplay.results.wear import WearProfile

    return WearProfile(joints=[int(j) for j in group.variables["joint"][...]],
                       angle=group.variables["angle"][...],
                       bearing_depth=group.variables["bearing_depth"][...],
                       journal_depth=group.variables["journal_depth"][...],
                       volume=group.variables["volume"][...])


def _write_accuracy(group: Any, accuracy: Any) -> None:
    """``/accuracy``: the statement's numbers as attributes (SI units: ``tip_error_estimate``
    in m, ``agreement_horizon`` in s, ``energy_residual`` in J, ...), the per-joint impact
    counts of the run and of its check, and one tolerance-sensitive flag per impact."""
    group.attrs["comment"] = ("the run checked against the same run at tolerances 10x "
                              "tighter: estimated errors, energy residuals, agreement horizon")
    for key, value in accuracy.attributes().items():
        group.attrs[key] = value
    joints = sorted(accuracy.impacts_per_joint)
    flags = np.asarray(accuracy.tolerance_sensitive, dtype=bool)
    group.dimensions = {"joint": len(joints), "impact": flags.size}
    _variable(group, "joint", ("joint",), np.asarray(joints, dtype=np.int64), "1",
              "1-based number of the clearance joint")
    _variable(group, "impact", ("impact",), np.arange(flags.size, dtype=np.int64), "1",
              "index of the contact phase (the row of the impacts table)")
    for name, column, what in (("count_run", 0, "this run"), ("count_check", 1, "the check")):
        _variable(group, name, ("joint",),
                  np.asarray([accuracy.impacts_per_joint[j][column] for j in joints],
                             dtype=np.int64), "1", f"impacts of {what} at each joint")
    _variable(group, "tolerance_sensitive", ("impact",), flags.astype(np.int8), "1",
              "1: the impact is at or after the agreement horizon (changes with tolerance)")


def _read_accuracy(group: Any) -> Any:
    from jointplay.results.accuracy import Accuracy

    a = dict(group.attrs)
    joints = [int(j) for j in group.variables["joint"][...]]
    counts = {j: (int(r), int(c)) for j, r, c in zip(
        joints, group.variables["count_run"][...], group.variables["count_check"][...],
        strict=True)}
    fields = ("rtol", "atol", "check_rtol", "check_atol", "tip_error_estimate",
              "tip_velocity_error_estimate", "energy_residual", "check_energy_residual",
              "dissipated", "agreement_horizon", "t_end", "check_wall_s")
    return Accuracy(**{k: float(a[k]) for k in fields},
                    agreed_impacts=int(a["agreed_impacts"]), impacts=int(a["impacts"]),
                    check_impacts=int(a["check_impacts"]), impacts_per_joint=counts,
                    tolerance_sensitive=np.asarray(group.variables["tolerance_sensitive"][...],
                                                   dtype=bool))


def _check_wear(group: Any, path: Any) -> None:
    from jointplay.results.checks import check_wear

    check_wear(group, path)


def _check_accuracy(group: Any, path: Any) -> None:
    from jointplay.results.checks import check_accuracy

    check_accuracy(group, path)


OPTIONAL_GROUPS: dict[str, OptionalGroup] = {
    "wear": OptionalGroup(_write_wear, _read_wear, _check_wear),
    "accuracy": OptionalGroup(_write_accuracy, _read_accuracy, _check_accuracy),
}
"""Result attribute -> how its value is stored in the group of that name (None: no group)."""


# ------------------------------------------------------------------------ netCDF-4 on h5py


class NetcdfGroup:
    """The few netCDF-4 operations the layout needs, written with h5py directly.

    A netCDF-4 file is an HDF5 file whose dimensions are HDF5 dimension scales: each
    coordinate variable is made a scale (with the ``_Netcdf4Dimid`` netCDF gives it), and
    every variable has the scales of its dimensions attached. h5netcdf writes the same
    structure, about ten times slower for a file of this many small variables (measured in
    ``benchmarks/results_file.py``); the tests read these files with xarray's h5netcdf engine.
    """

    def __init__(self, h5group: Any, first_dimid: int = 0, checksums: bool = True) -> None:
        self._group = h5group
        # Fletcher-32 on every numeric variable (chunked, as HDF5 filters require); HDF5
        # cannot filter variable-length strings: the file's digest covers those.
        self.checksums = checksums
        self._sizes: dict[str, int] = {}
        self._scales: dict[str, Any] = {}
        self._next_dimid = first_dimid

    @property
    def attrs(self) -> Any:
        return self._group.attrs

    @property
    def h5group(self) -> Any:
        """The h5py group underneath."""
        return self._group

    @property
    def dimensions(self) -> dict[str, int]:
        return dict(self._sizes)

    @dimensions.setter
    def dimensions(self, sizes: dict[str, int]) -> None:
        self._sizes.update({name: int(size) for name, size in sizes.items()})

    def create_variable(self, name: str, dims: tuple[str, ...], data: Any = None,
                        dtype: Any = None, **options: Any) -> Any:
        values = np.asarray(data)
        expected = tuple(self._sizes[d] for d in dims)
        if values.shape != expected:  # a layout error, never a user's: say exactly what
            raise ValueError(f"variable {name}: shape {values.shape} != {dims} {expected}")
        if self.checksums and values.dtype.kind != "O":
            options = {**options, "fletcher32": True}
        ds = self._group.create_dataset(name, data=values, dtype=dtype, **options)
        if dims == (name,):  # a coordinate variable: the dimension itself
            ds.make_scale(name)
            ds.attrs["_Netcdf4Dimid"] = np.int32(self._next_dimid)
            self._next_dimid += 1
            self._scales[name] = ds
        else:
            for axis, dim in enumerate(dims):
                ds.dims[axis].attach_scale(self._scales[dim])
        return ds

    def create_group(self, name: str) -> NetcdfGroup:
        return NetcdfGroup(self._group.create_group(name, track_order=True), self._next_dimid,
                           self.checksums)


class StoredGroup:
    """A group of a results file opened for reading (h5py underneath)."""

    def __init__(self, h5group: Any) -> None:
        import h5py

        self.attrs = h5group.attrs
        self.variables = h5group
        self.groups = {k: StoredGroup(v) for k, v in h5group.items()
                       if isinstance(v, h5py.Group)}


# ------------------------------------------------------------------------------------ writing


def _variable(group: Any, name: str, dims: tuple[str, ...], data: Any, units: str | None,
              long_name: str, compress: bool = False, **attrs: Any) -> Any:
    import h5py

    values = np.asarray(data)
    kwargs: dict[str, Any] = {}
    if values.dtype.kind in "UO":
        kwargs["dtype"] = h5py.string_dtype()
        values = values.astype(object)
    elif compress and values.nbytes >= _COMPRESS_MIN_BYTES and all(values.shape):
        kwargs.update(compression="gzip", compression_opts=1, shuffle=True)
    var = group.create_variable(name, dims, data=values, **kwargs)
    if units is not None:
        var.attrs["units"] = units
    var.attrs["long_name"] = long_name
    for key, value in attrs.items():
        var.attrs[key] = value
    return var


def to_json(value: Any) -> str:
    """Metadata and statistics as JSON text (arrays as lists, paths as strings)."""
    def default(obj: Any) -> Any:
        if isinstance(obj, np.ndarray | np.generic):
            return obj.tolist()
        if isinstance(obj, Path):
            return str(obj)
        raise TypeError(f"cannot store {type(obj).__name__} in a result file")

    return json.dumps(value, default=default)


def write_result(group: Any, r: SimulationResult, compress: bool = False) -> None:
    """Write ``r`` into an open h5netcdf group (the file's root, or ``/ideal``)."""
    columns = eccentricity_columns(r.coordinate_names, r.clearance_joints)
    offset_cols = {c for pair in columns.values() for c in pair}
    angle_cols = [i for i in range(len(r.coordinate_names)) if i not in offset_cols]
    n_impacts = len(r.impacts)
    group.dimensions = {"time": r.t.size, "coordinate": len(angle_cols),
                        "joint": len(r.clearance_joints), "axis": 2,
                        "drive": len(r.torque_joints), "parameter": len(r.parameter_names),
                        "impact": n_impacts}
    _variable(group, "time", ("time",), r.t, "s", "time since the start of the run",
              compress, standard_name="time", axis="T")
    _variable(group, "coordinate", ("coordinate",),
              np.array([r.coordinate_names[i] for i in angle_cols], dtype=object), None,
              "joint-angle coordinate (relative angle of the joint)")
    _variable(group, "joint", ("joint",), np.asarray(r.clearance_joints, dtype=np.int64), "1",
              "1-based number of the clearance joint")
    _variable(group, "axis", ("axis",), np.array(["x", "y"], dtype=object), None,
              "axis of the base frame")
    _variable(group, "drive", ("drive",), np.asarray(r.torque_joints, dtype=np.int64), "1",
              "1-based number of the driven joint")
    _variable(group, "parameter", ("parameter",), np.array(r.parameter_names, dtype=object),
              None, "model parameter name")
    _variable(group, "impact", ("impact",), np.arange(1, n_impacts + 1, dtype=np.int64), "1",
              "contact phase number, in onset order")
    nc = len(r.clearance_joints)
    offset_index = [c for j in r.clearance_joints for c in columns[j]]
    for attribute, per, angle_name, offset_name, what, kind in _MOTION:
        values = np.asarray(getattr(r, attribute))
        prefix = f"{what} of the " if what else ""
        _variable(group, angle_name, ("time", "coordinate"), values[:, angle_cols],
                  f"rad{per}", f"{prefix}joint angle", compress)
        _variable(group, offset_name, ("time", "joint", "axis"),
                  values[:, offset_index].reshape(values.shape[0], nc, 2), f"m{per}",
                  f"journal centre {kind} coordinates (ex, ey) relative to the bearing centre",
                  compress)
    for f in SAMPLE_FIELDS:
        _variable(group, f.variable, f.dims, getattr(r, f.attribute), f.units, f.long_name,
                  compress)
    _variable(group, "radial_clearance", ("joint",), r.radial_clearance, "m",
              "radial clearance Rb - Rj")
    for name, values in r.energy.items():
        _variable(group, f"energy_{name}", ("time",), values, "J", f"energy: {name}", compress)
    _variable(group, "parameter_value", ("parameter",), r.parameters, "1",
              "parameter vector the run used, each in the SI unit its name implies (see the "
              "model's layout.json)")
    for name, unit, doc in IMPACT_COLUMNS:
        values = np.asarray(getattr(r.impacts, name))
        extra: dict[str, Any] = {}
        if name == "eccentricity":
            dims: tuple[str, ...] = ("impact", "axis")
            values = values.reshape(n_impacts, 2)
        else:
            dims = ("impact",)
        if name == "separated":
            values = values.astype(np.int8)
            extra = {"flag_values": np.array([0, 1], dtype=np.int8),
                     "flag_meanings": "still_in_contact_at_end separated"}
        elif name == "joint":
            values = values.astype(np.int64)
        _variable(group, f"impact_{name}", dims, values, UDUNITS[unit], doc, **extra)
    group.attrs["scene_name"] = r.scene_name
    group.attrs["integrator"] = r.integrator
    # the full coordinate order (angles and journal offsets interleaved as the model has them)
    group.attrs["coordinate_names"] = " ".join(r.coordinate_names)
    group.attrs["energy_components"] = " ".join(r.energy)
    group.attrs["solver_stats"] = to_json(r.stats)
    # string metadata (the scene's text, its source) readable as attributes of their own
    text = {k: v for k, v in r.metadata.items()
            if isinstance(v, str) and k.isidentifier() and k not in _RESERVED}
    for key, value in text.items():
        group.attrs[key] = value
    group.attrs["metadata_text"] = " ".join(text)
    group.attrs["metadata_json"] = to_json({k: v for k, v in r.metadata.items()
                                             if k not in text})
    for attribute, hooks in OPTIONAL_GROUPS.items():
        part = getattr(r, attribute, None)
        if part is not None:
            hooks.write(group.create_group(attribute), part)


def write_file(fh: Any, r: SimulationResult, compress: bool = False) -> None:
    """The whole file: root attributes, the result, its ideal counterpart in ``/ideal``, and
    (written through a :class:`NetcdfGroup` with checksums) the digest of it all."""
    from jointplay import __version__

    fh.attrs["Conventions"] = CONVENTIONS
    fh.attrs["title"] = f"jointplay simulation of scene {r.scene_name!r}"
    fh.attrs["source"] = f"jointplay {__version__}"
    fh.attrs["format"] = FORMAT
    fh.attrs["format_version"] = (FORMAT_VERSION if getattr(fh, "checksums", False)
                                  else UNCHECKED_VERSION)
    write_result(fh, r, compress)
    if r.ideal is not None:
        ideal = fh.create_group("ideal")
        ideal.attrs["comment"] = "the same scene with ideal joints"
        write_result(ideal, r.ideal, compress)
    if getattr(fh, "checksums", False):  # last: the digest covers everything above
        from jointplay.results.integrity import stamp

        stamp(fh.h5group)


# ------------------------------------------------------------------------------------ reading


def _values(group: Any, name: str) -> np.ndarray:
    return np.asarray(group.variables[name][...])


def _text(value: Any) -> str:
    return value.decode() if isinstance(value, bytes) else str(value)


def read_result(group: Any, ideal: SimulationResult | None = None) -> SimulationResult:
    """The result stored in an open h5netcdf group by :func:`write_result`."""
    attrs = group.attrs
    names = _text(attrs["coordinate_names"]).split()
    clearance = [int(j) for j in _values(group, "joint")]
    columns = eccentricity_columns(names, clearance)
    offset_index = [c for j in clearance for c in columns[j]]
    angle_cols = [i for i in range(len(names)) if i not in set(offset_index)]
    t = _values(group, "time")
    motion: dict[str, Any] = {}
    for attribute, _, angle_name, offset_name, _, _ in _MOTION:
        values = np.empty((t.size, len(names)))
        values[:, angle_cols] = _values(group, angle_name)
        values[:, offset_index] = _values(group, offset_name).reshape(t.size, -1)
        motion[attribute] = values
    arrays: dict[str, Any] = {f.attribute: _values(group, f.variable) for f in SAMPLE_FIELDS}
    table: dict[str, np.ndarray] = {}
    for name, _, _ in IMPACT_COLUMNS:
        values = _values(group, f"impact_{name}")
        table[name] = values.astype(bool) if name == "separated" else values
    energy = {name: _values(group, f"energy_{name}")
              for name in _text(attrs["energy_components"]).split()}
    metadata: dict[str, Any] = {key: _text(attrs[key])
                                for key in _text(attrs["metadata_text"]).split()}
    metadata.update(json.loads(_text(attrs["metadata_json"])))
    optional: dict[str, Any] = {attribute: hooks.read(group.groups[attribute])
                for attribute, hooks in OPTIONAL_GROUPS.items() if attribute in group.groups}
    return SimulationResult(
        scene_name=_text(attrs["scene_name"]), integrator=_text(attrs["integrator"]),
        t=t, coordinate_names=names, torque_joints=[int(j) for j in _values(group, "drive")],
        clearance_joints=clearance, radial_clearance=_values(group, "radial_clearance"),
        impacts=Impacts(**table), energy=energy,
        parameter_names=[_text(n) for n in _values(group, "parameter")],
        parameters=_values(group, "parameter_value"),
        stats=json.loads(_text(attrs["solver_stats"])), metadata=metadata, ideal=ideal,
        **motion, **arrays, **optional)


def read_file(fh: Any) -> SimulationResult:
    ideal = read_result(fh.groups["ideal"]) if "ideal" in fh.groups else None
    return read_result(fh, ideal)
