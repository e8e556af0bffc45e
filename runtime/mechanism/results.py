"""A mechanism run's results file: HDF5, written whole and atomically, read back checked.

Layout (root attributes ``format`` = "jointplay-mechanism", ``version``; every array a
dataset of float64 in SI units, names as :class:`MechanismResult`'s fields): ``t``, ``x``,
``acceleration``, ``eccentricity``, ``normal_force``, ``penetration``, ``driving_torque``,
``kinetic``, ``potential``, ``contact_potential``, ``drive_work``, ``dissipated``; the group
``impacts`` (one dataset per column of the located contact phases); the group ``ideal``
(``x``, ``acceleration``, ``driving_torque``) when the run was compared with the ideal
mechanism. The attributes ``coordinates``, ``units``, ``cut_joints`` (JSON), ``clearance``,
``rtol``, ``atol``, ``integrator`` (and ``step`` at a fixed step), ``stats`` (JSON), ``output``
(the coordinate the figures follow) and
``accuracy`` (the statement's lines, when checked). The attribute ``sha256`` is the hash of
every dataset's name and bytes: a file changed since is refused when read.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
import stat
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.mechanism.simulate import MechanismResult
from jointplay.results.records import Impacts

FORMAT = "jointplay-mechanism"
VERSION = 1
ARRAYS = ("t", "x", "acceleration", "eccentricity", "normal_force", "penetration",
          "driving_torque", "kinetic", "potential", "contact_potential", "drive_work",
          "dissipated", "clearance")
IDEAL = ("x", "acceleration", "driving_torque")


def _datasets(result: MechanismResult) -> dict[str, np.ndarray]:
    out = {name: np.asarray(getattr(result, name), dtype=float) for name in ARRAYS}
    for f in dataclasses.fields(Impacts):
        out[f"impacts/{f.name}"] = np.asarray(getattr(result.impacts, f.name))
    if result.ideal is not None:
        out |= {f"ideal/{k}": np.asarray(result.ideal[k], dtype=float) for k in IDEAL}
    return out


def _digest(datasets: dict[str, np.ndarray]) -> str:
    h = hashlib.sha256()
    for name in sorted(datasets):
        value = np.ascontiguousarray(datasets[name])
        h.update(name.encode())
        h.update(str(value.dtype).encode())
        h.update(str(value.shape).encode())
        h.update(value.tobytes())
    return h.hexdigest()


def write_mechanism_result(result: MechanismResult, path: str | Path) -> None:
    from jointplay.common.files import write_hdf5_in_memory

    datasets = _datasets(result)

    def build(fh: Any) -> None:
        for name, value in datasets.items():
            fh.create_dataset(name, data=value)
        attrs = fh.attrs
        attrs["format"], attrs["version"], attrs["name"] = FORMAT, VERSION, result.name
        attrs["coordinates"] = json.dumps(result.coordinates)
        attrs["units"] = json.dumps(result.units)
        attrs["cut_joints"] = json.dumps(result.cut_joints)
        attrs["rtol"], attrs["atol"] = result.rtol, result.atol
        attrs["integrator"] = result.integrator
        if result.step is not None:
            attrs["step"] = result.step
        attrs["output"] = result.output
        attrs["stats"] = json.dumps({k: float(v) for k, v in result.stats.items()})
        if result.accuracy is not None:
            attrs["accuracy"] = "\n".join(result.accuracy.lines())
        attrs["sha256"] = _digest(datasets)

    write_hdf5_in_memory(path, build)


def is_mechanism_result(path: str | Path) -> bool:
    """Whether ``path`` is a mechanism results file (False for anything else, read or not)."""
    import h5py

    try:
        # Only a regular file is opened: HDF5 would wait forever on a FIFO, and the readers
        # that take it next refuse a FIFO or a device in one line.
        if not stat.S_ISREG(os.stat(path).st_mode):
            return False
        with h5py.File(path, "r") as fh:
            return bool(fh.attrs.get("format") == FORMAT)
    except (OSError, ValueError):
        return False


def read_mechanism_result(path: str | Path, argument: str = "RUN.h5") -> MechanismResult:
    """Read a mechanism results file back (DescriptionError: not one, or changed since)."""
    import h5py

    try:
        regular = stat.S_ISREG(os.stat(path).st_mode)
    except OSError as err:
        raise DescriptionError(argument, f"{path} cannot be read ({err})") from None
    if not regular:
        raise DescriptionError(argument, f"{path} is not a regular file (a folder, device, "
                               "FIFO or socket); give a mechanism results file (.h5)")
    try:
        fh = h5py.File(path, "r")
    except (OSError, ValueError) as err:
        raise DescriptionError(argument, f"{path} is not a readable HDF5 file ({err})") from None
    with fh:
        if fh.attrs.get("format") != FORMAT or int(fh.attrs.get("version", 0)) != VERSION:
            raise DescriptionError(argument, f"{path} is not a mechanism results file of "
                                   f"version {VERSION}")
        datasets: dict[str, np.ndarray] = {}
        fh.visititems(lambda name, obj: datasets.__setitem__(name, obj[()])
                      if isinstance(obj, h5py.Dataset) else None)
        if _digest(datasets) != fh.attrs.get("sha256"):
            raise DescriptionError(argument, f"{path} was changed after it was written (its "
                                   "checksum does not match): simulate the run again")
        attrs = dict(fh.attrs)
    impacts = Impacts(**{f.name: datasets[f"impacts/{f.name}"]
                         for f in dataclasses.fields(Impacts)})
    ideal = ({k: datasets[f"ideal/{k}"] for k in IDEAL} if "ideal/x" in datasets else None)
    # The array fields, by the names the file stores them under (checked by the dataclass).
    arrays: dict[str, Any] = {k: datasets[k] for k in ARRAYS}
    result = MechanismResult(
        name=str(attrs["name"]), coordinates=json.loads(attrs["coordinates"]),
        units=json.loads(attrs["units"]), cut_joints=json.loads(attrs["cut_joints"]),
        impacts=impacts, stats=json.loads(attrs["stats"]), rtol=float(attrs["rtol"]),
        atol=float(attrs["atol"]), ideal=ideal, output=str(attrs.get("output", "")),
        integrator=str(attrs.get("integrator", "bdf")),
        step=float(attrs["step"]) if "step" in attrs else None,
        **arrays)
    if "accuracy" in attrs:
        result.notes.append(str(attrs["accuracy"]))
    return result
