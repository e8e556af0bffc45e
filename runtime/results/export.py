"""Results in the ecosystem's shapes: an ``xarray.Dataset`` and a ``pandas.DataFrame``.

Both carry the SI unit of every variable (xarray: ``attrs["unit"]`` per variable; pandas:
``frame.attrs["units"]``, a column -> unit mapping), and both copy the data, so changing
them never changes the result they came from. pandas and xarray are imported here only.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.results.write import _ARRAYS, IMPACT_COLUMNS

if TYPE_CHECKING:
    from jointplay.results.records import Impacts, SimulationResult

# Dimensions of every per-sample array of a result (the first is always "time").
_DIMS: dict[str, tuple[str, ...]] = {
    "q": ("time", "coordinate"), "u": ("time", "coordinate"), "udot": ("time", "coordinate"),
    "tau": ("time", "torque_joint"),
    "tip_position": ("time", "axis"), "tip_velocity": ("time", "axis"),
    "tip_acceleration": ("time", "axis"),
    "eccentricity": ("time", "joint", "axis"), "contact_force": ("time", "joint", "axis"),
    "penetration": ("time", "joint"), "penetration_rate": ("time", "joint"),
    "normal_force": ("time", "joint"), "friction_force": ("time", "joint"),
    "sliding_speed": ("time", "joint"),
}
_TIP = ("tip_position", "tip_velocity", "tip_acceleration")


def result_dataset(result: SimulationResult) -> Any:
    """The samples of ``result`` as an ``xarray.Dataset``.

    Dimensions: ``time`` (s), ``joint`` (the clearance joints, 1-based numbers), ``coordinate``
    (q2, ex2, ...), ``torque_joint`` (the driven joints), ``axis`` (x, y) and ``parameter``.
    q, u and udot mix angles and lengths: their per-coordinate units are the coordinate
    ``unit`` beside ``coordinate``. Energies are ``energy_<name>``; with an ideal counterpart
    its end-effector arrays are ``ideal_tip_*`` (the same output times). The contact-phase
    table is not per sample: it is ``result.impacts.to_pandas()``.
    """
    from jointplay.common.extras import require

    require("xarray", "to_xarray()")
    import xarray as xr

    units = {name: unit for name, unit, _ in _ARRAYS}
    docs = {name: doc for name, _, doc in _ARRAYS}
    coord_units = result.coordinate_units
    data_vars: dict[str, Any] = {}
    for name, dims in _DIMS.items():
        unit = units[name]
        if unit.startswith("coord"):
            unit = f"rad{unit.removeprefix('coord')} or m{unit.removeprefix('coord')}"
        data_vars[name] = xr.Variable(dims, np.array(getattr(result, name), dtype=np.float64),
                                      {"unit": unit, "doc": docs[name]})
    data_vars["radial_clearance"] = xr.Variable(
        ("joint",), np.array(result.radial_clearance, dtype=np.float64),
        {"unit": "m", "doc": docs["radial_clearance"]})
    for name, values in result.energy.items():
        data_vars[f"energy_{name}"] = xr.Variable(("time",), np.array(values, dtype=np.float64),
                                                  {"unit": "J", "doc": f"energy: {name}"})
    if result.ideal is not None:
        for name in _TIP:
            data_vars[f"ideal_{name}"] = xr.Variable(
                ("time", "axis"), np.array(getattr(result.ideal, name), dtype=np.float64),
                {"unit": units[name], "doc": f"{docs[name]}, ideal joints"})
    data_vars["parameters"] = xr.Variable(("parameter",),
                                          np.array(result.parameters, dtype=np.float64),
                                          {"unit": "SI", "doc": "parameter vector the run used"})
    coords = {
        "time": ("time", np.array(result.t, dtype=np.float64), {"unit": "s"}),
        "joint": ("joint", np.array(result.clearance_joints, dtype=np.int64),
                  {"doc": "1-based number of each clearance joint"}),
        "coordinate": ("coordinate", list(result.coordinate_names)),
        "unit": ("coordinate", coord_units),
        "torque_joint": ("torque_joint", np.array(result.torque_joints, dtype=np.int64),
                         {"doc": "1-based number of each driven joint"}),
        "axis": ("axis", ["x", "y"]),
        "parameter": ("parameter", list(result.parameter_names)),
    }
    attrs = {"scene_name": result.scene_name, "integrator": result.integrator,
             "impacts": len(result.impacts)}
    return xr.Dataset(data_vars, coords=coords, attrs=attrs)


def impacts_frame(impacts: Impacts) -> Any:
    """The contact-phase table as a ``pandas.DataFrame``, one row per phase, onset order.

    The onset eccentricity becomes two columns, ``eccentricity_x`` and ``eccentricity_y``;
    ``joint`` is int64 and ``separated`` bool; every other column float64 (NaN where the run
    did not locate the value). ``frame.attrs["units"]`` maps each column to its unit.
    """
    from jointplay.common.extras import require

    require("xarray", "to_pandas()", modules=("pandas",))
    import pandas as pd

    columns: dict[str, np.ndarray] = {}
    units: dict[str, str] = {}
    for name, unit, _ in IMPACT_COLUMNS:
        values = np.asarray(getattr(impacts, name))
        if name == "eccentricity":
            ecc = values.reshape(-1, 2).astype(np.float64)
            columns["eccentricity_x"], columns["eccentricity_y"] = ecc[:, 0], ecc[:, 1]
            units["eccentricity_x"] = units["eccentricity_y"] = unit
            continue
        kind = np.int64 if name == "joint" else bool if name == "separated" else np.float64
        columns[name] = values.astype(kind)
        units[name] = unit
    frame = pd.DataFrame(columns, index=pd.RangeIndex(len(impacts), name="phase"))
    frame.attrs["units"] = units
    return frame


__all__ = ["impacts_frame", "result_dataset"]
