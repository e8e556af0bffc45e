"""Result files (HDF5, CSV) and figures, on a synthetic but self-consistent result."""

from __future__ import annotations

import dataclasses
import math
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import h5py
import numpy as np
import pytest

import jointplay
from jointplay.common.errors import DescriptionError
from jointplay.results.animate import (
    animate_result,
    arm_points,
    check_animation_path,
    frame_indices,
)
from jointplay.results.plots import (
    BURST_GAP,
    BURST_MAX,
    first_burst,
    impact_positions,
    plot_contact_timeline,
    plot_result,
)
from jointplay.results.records import PHASE_FIELDS, Impacts, SimulationResult
from jointplay.results.write import (
    impacts_csv_path,
    read_hdf5,
    write_csv,
    write_hdf5,
    write_hdf5_v1,
)

LENGTHS = np.array([0.40, 0.30, 0.25, 0.15])
MASSES = np.array([2.0, 1.5, 1.0, 0.5])
CLEARANCE = {2: (50e-6, 5.0, 0.7), 3: (80e-6, 3.0, -1.3)}  # joint: (c, f, sweep rate rad/s)
STIFFNESS, FRICTION, AMPLITUDE = 1e10, 0.1, 0.02
# Integral of sin(x)^1.5 over [0, pi] = sqrt(pi) Gamma(5/4) / Gamma(7/4).
SIN_15_INTEGRAL = math.sqrt(math.pi) * math.gamma(1.25) / math.gamma(1.75)


def _angles(t: np.ndarray, scale: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Joint angles q_i = a_i sin(w_i t + p_i) with exact first and second derivatives."""
    a = scale * np.array([0.8, 0.5, 0.4, 0.3])
    w = np.array([2.0, 3.0, 5.0, 7.0]) * np.pi
    p = np.array([0.0, 0.5, 1.0, 1.5])
    arg = np.outer(t, w) + p
    return a * np.sin(arg), a * w * np.cos(arg), -a * w**2 * np.sin(arg)


def _tip(q: np.ndarray, u: np.ndarray, a: np.ndarray) -> tuple[np.ndarray, ...]:
    """Forward kinematics of the chain (absolute angles are cumulative sums)."""
    th, om, al = np.cumsum(q, axis=1), np.cumsum(u, axis=1), np.cumsum(a, axis=1)
    c, s = np.cos(th), np.sin(th)
    pos = np.stack([(LENGTHS * c).sum(1), (LENGTHS * s).sum(1)], axis=1)
    vel = np.stack([(-LENGTHS * om * s).sum(1), (LENGTHS * om * c).sum(1)], axis=1)
    acc = np.stack([(LENGTHS * (-al * s - om**2 * c)).sum(1),
                    (LENGTHS * (al * c - om**2 * s)).sum(1)], axis=1)
    return pos, vel, acc


def _energy(t: np.ndarray, u: np.ndarray, y: np.ndarray, contact: np.ndarray) -> dict[str, Any]:
    kinetic = 0.5 * (MASSES * u[:, :4] ** 2).sum(1)
    gravity = 9.81 * MASSES.sum() * y
    total = kinetic + gravity + contact
    dissipated = 0.01 * t
    balance = 1e-7 * np.sin(40.0 * t)
    drive_work = total - total[0] + dissipated - balance
    return {"kinetic": kinetic, "gravity": gravity, "contact": contact, "total": total,
            "drive_work": drive_work, "dissipated": dissipated, "balance": balance}


def _common(t: np.ndarray, names: list[str], q: np.ndarray, u: np.ndarray,
            udot: np.ndarray) -> dict[str, Any]:
    return {"scene_name": "two-clearance arm", "integrator": "cvodes", "t": t,
            "coordinate_names": names, "q": q, "u": u, "udot": udot,
            "tau": np.cos(np.outer(t, [1.0, 2.0, 3.0, 4.0])), "torque_joints": [1, 2, 3, 4],
            "parameter_names": [*(f"link{i}.length" for i in range(1, 5)), "gravity.y"],
            "parameters": np.r_[LENGTHS, -9.81]}


def make_ideal(n: int = 500) -> SimulationResult:
    t = np.linspace(0.0, 1.0, n)
    q, u, a = _angles(t, 1.0)
    pos, vel, acc = _tip(q, u, a)
    empty = np.zeros((n, 0))
    return SimulationResult(
        **_common(t, ["q1", "q2", "q3", "q4"], q, u, a),
        tip_position=pos, tip_velocity=vel, tip_acceleration=acc, clearance_joints=[],
        radial_clearance=np.zeros(0), eccentricity=np.zeros((n, 0, 2)), penetration=empty,
        penetration_rate=empty, normal_force=empty, friction_force=empty,
        contact_force=np.zeros((n, 0, 2)), sliding_speed=empty,
        impacts=Impacts(np.zeros(0), np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros((0, 2))),
        energy=_energy(t, u, pos[:, 1], np.zeros(n)), stats={"steps": 321},
        metadata={"compare": "ideal joints"})


def make_result(n: int = 500, ideal: bool = True) -> SimulationResult:
    """Journal centres orbit just outside the clearance circle now and then (Hertz contact)."""
    t = np.linspace(0.0, 1.0, n)
    q, u, a = _angles(t, 1.002)
    ecc, decc, ddecc, pen, rate, fn, ft, fc, vs = ([] for _ in range(9))
    impact_rows = []
    for joint, (c, f, nu) in CLEARANCE.items():
        om = 2.0 * np.pi * f
        r = c * (1.0 + AMPLITUDE * np.sin(om * t))
        dr, ddr = c * AMPLITUDE * om * np.cos(om * t), -c * AMPLITUDE * om**2 * np.sin(om * t)
        phi = 0.3 * joint + nu * t
        nrm = np.stack([np.cos(phi), np.sin(phi)], axis=1)
        tan = np.stack([-np.sin(phi), np.cos(phi)], axis=1)
        ecc.append(r[:, None] * nrm)
        decc.append(dr[:, None] * nrm + (r * nu)[:, None] * tan)
        ddecc.append((ddr - r * nu**2)[:, None] * nrm + (2.0 * dr * nu)[:, None] * tan)
        pen.append(r - c)
        rate.append(dr)
        fn.append(STIFFNESS * np.maximum(r - c, 0.0) ** 1.5)
        ft.append(-FRICTION * fn[-1] * np.sign(nu))
        fc.append(-fn[-1][:, None] * nrm + ft[-1][:, None] * tan)
        vs.append(r * nu)
        # At an onset r = c: the journal centre sits on the clearance circle, at angle phi.
        # Each phase is half a period of r - c = c A sin(om t): peak a quarter period in,
        # separation at the half, exit speed = approach speed, impulse in closed form.
        peak_force = STIFFNESS * (c * AMPLITUDE) ** 1.5
        impulse = peak_force / om * SIN_15_INTEGRAL
        impact_rows += [(k / f, joint, c * AMPLITUDE * om,
                         c * np.cos(0.3 * joint + nu * k / f), c * np.sin(0.3 * joint + nu * k / f),
                         0.3 * joint + nu * k / f, peak_force, (k + 0.25) / f, c * AMPLITUDE,
                         (k + 0.25) / f, (k + 0.5) / f, c * AMPLITUDE * om, 0.5 / f, 1.0,
                         impulse, 0.0, FRICTION * abs(nu) * c * impulse, True)
                        for k in range(1, int(f))]
    e = np.stack(ecc, axis=1)
    q_all = np.hstack([q, e.reshape(n, -1)])
    u_all = np.hstack([u, np.stack(decc, axis=1).reshape(n, -1)])
    a_all = np.hstack([a, np.stack(ddecc, axis=1).reshape(n, -1)])
    pos, vel, acc = _tip(q, u, a)
    pos, vel = pos + e.sum(1), vel + np.stack(decc, axis=1).sum(1)
    acc = acc + np.stack(ddecc, axis=1).sum(1)
    pen_arr = np.stack(pen, axis=1)
    contact = (STIFFNESS / 2.5 * np.maximum(pen_arr, 0.0) ** 2.5).sum(1)
    impact_rows.sort()
    impacts = Impacts(np.array([r[0] for r in impact_rows]),
                      np.array([r[1] for r in impact_rows], dtype=np.int64),
                      np.array([r[2] for r in impact_rows]),
                      np.array([r[3:5] for r in impact_rows]).reshape(-1, 2),
                      **{name: np.array([r[5 + i] for r in impact_rows],
                                        dtype=bool if name == "separated" else np.float64)
                         for i, (name, _, _) in enumerate(PHASE_FIELDS)})
    names = ["q1", "q2", "q3", "q4", "ex2", "ey2", "ex3", "ey3"]
    return SimulationResult(
        **_common(t, names, q_all, u_all, a_all),
        tip_position=pos, tip_velocity=vel, tip_acceleration=acc, clearance_joints=[2, 3],
        radial_clearance=np.array([c for c, _, _ in CLEARANCE.values()]), eccentricity=e,
        penetration=pen_arr, penetration_rate=np.stack(rate, axis=1),
        normal_force=np.stack(fn, axis=1), friction_force=np.stack(ft, axis=1),
        contact_force=np.stack(fc, axis=1), sliding_speed=np.stack(vs, axis=1),
        impacts=impacts, energy=_energy(t, u_all, pos[:, 1], contact),
        stats={"steps": 1234, "rhs_evaluations": 5678, "events": len(impact_rows),
               "wall_time": 0.125, "converged": True},
        metadata={"scene": "[robot]\nname = \"arm\"\n", "model_hash": "0123abcd",
                  "versions": {"jointplay": "0.1.0", "numpy": np.__version__},
                  "n_links": 4, "tags": ["synthetic", "test"], "note": None,
                  "looks_like_json": "{\"a\": 1}"},
        ideal=make_ideal(n) if ideal else None)


@pytest.fixture(scope="module")
def result() -> SimulationResult:
    return make_result()


def assert_same(a: Any, b: Any, where: str = "result") -> None:
    """Exact equality, field by field, including dtypes, shapes and Python types."""
    if dataclasses.is_dataclass(a):
        assert type(a) is type(b), where
        for f in dataclasses.fields(a):
            assert_same(getattr(a, f.name), getattr(b, f.name), f"{where}.{f.name}")
    elif isinstance(a, np.ndarray):
        assert isinstance(b, np.ndarray), where
        assert (a.dtype, a.shape) == (b.dtype, b.shape), where
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), where
    elif isinstance(a, dict):
        assert list(a) == list(b) or where.endswith("metadata"), where
        assert set(a) == set(b), where
        for key in a:
            assert_same(a[key], b[key], f"{where}[{key!r}]")
    else:
        assert type(a) is type(b) and a == b, where
        if isinstance(a, list):
            assert [type(x) for x in a] == [type(x) for x in b], where


def test_result_is_consistent(result: SimulationResult) -> None:
    """The fixture itself: derivatives match finite differences, impacts are contact onsets."""
    dt = result.t[1] - result.t[0]
    for x, dx in ((result.q, result.u), (result.u, result.udot),
                  (result.tip_position, result.tip_velocity)):
        assert np.allclose(np.gradient(x, dt, axis=0)[2:-2], dx[2:-2],
                           rtol=1e-3, atol=1e-3 * np.abs(dx).max())
    for k, joint in enumerate(result.clearance_joints):
        times = result.impacts.time[result.impacts.joint == joint]
        delta = np.interp(times, result.t, result.penetration[:, k])
        assert np.allclose(delta, 0.0, atol=1e-8)
        hits = impact_positions(result, k)
        assert np.allclose(np.hypot(hits[:, 0], hits[:, 1]), result.radial_clearance[k],
                           rtol=1e-3)
        # The hand-made phase peaks bound the sampled force from above and are nearly reached.
        rows = result.impacts.for_joint(joint)
        assert np.all(rows.separated)
        sampled = result.normal_force[:, k]
        assert sampled.max() <= rows.peak_force.max() * (1 + 1e-12)
        assert sampled.max() >= 0.99 * rows.peak_force.max()
        at_peak = np.interp(rows.peak_force_time, result.t, sampled)
        assert np.allclose(at_peak, rows.peak_force, rtol=1e-2)


@pytest.mark.parametrize("compress", [False, True])
def test_hdf5_round_trip(result: SimulationResult, tmp_path: Path, compress: bool) -> None:
    """Every field, exactly (dtype, shape, value, Python type), ideal run included."""
    path = tmp_path / "run.h5"
    write_hdf5(result, path, compress=compress)
    back = jointplay.read(path)
    assert_same(result, back)
    assert back.ideal is not None
    assert read_hdf5 is jointplay.read  # the earlier name stays
    assert sorted(os.listdir(tmp_path)) == ["run.h5"]
    longer = make_result(n=600, ideal=False)  # 600 x 4 doubles: above the 16 KiB threshold
    write_hdf5(longer, tmp_path / "longer.h5", compress=compress)
    with h5py.File(tmp_path / "longer.h5", "r") as fh:
        assert (fh["joint_angle"].compression == "gzip") is compress
        assert fh["impact_time"].compression is None  # small: never compressed


def test_hdf5_is_cf_netcdf(result: SimulationResult, tmp_path: Path) -> None:
    """xarray (and any netCDF reader) sees named dimensions, coordinates and CF units."""
    import xarray as xr

    path = tmp_path / "run.h5"
    write_hdf5(result, path)
    with xr.open_dataset(path) as ds:
        assert ds.attrs["Conventions"] == "CF-1.11"
        assert ds.attrs["format_version"] == 3
        assert ds.attrs["model_hash"] == "0123abcd"  # string metadata: attributes of its own
        assert dict(ds.sizes) == {"time": 500, "coordinate": 4, "joint": 2, "axis": 2,
                                  "drive": 4, "parameter": 5, "impact": 6}
        assert list(ds["coordinate"].values) == ["q1", "q2", "q3", "q4"]
        assert list(ds["joint"].values) == [2, 3] and list(ds["axis"].values) == ["x", "y"]
        assert ds["joint_angle"].dims == ("time", "coordinate")
        assert ds["journal_offset"].dims == ("time", "joint", "axis")
        assert ds["eccentricity"].dims == ("time", "joint", "axis")
        assert ds["impact_peak_force"].dims == ("impact",)
        assert ds["impact_eccentricity"].dims == ("impact", "axis")
        for name, var in ds.variables.items():
            assert "long_name" in var.attrs, name
            if var.dtype.kind in "fiu":
                assert "units" in var.attrs, name
        units = {name: ds[name].attrs["units"] for name in (
            "time", "joint_angle", "joint_angular_velocity", "journal_offset_acceleration",
            "tip_velocity", "drive_torque", "energy_balance", "impact_impulse")}
        assert units == {"time": "s", "joint_angle": "rad", "joint_angular_velocity": "rad s-1",
                         "journal_offset_acceleration": "m s-2", "tip_velocity": "m s-1",
                         "drive_torque": "N m", "energy_balance": "J",
                         "impact_impulse": "N s"}
        # the journal offsets are the q columns of ex, ey; the eccentricity equals them here
        ex3 = result.coordinate_names.index("ex3")
        assert np.array_equal(ds["journal_offset"].sel(joint=3, axis="x"), result.q[:, ex3])
        assert float(ds["impact_time"][0]) == result.impacts.time[0]
    with xr.open_dataset(path, group="ideal") as ideal:
        assert ideal.sizes["joint"] == 0 and ideal["tip_position"].dims == ("time", "axis")


def test_hdf5_of_the_earlier_layout_still_reads(result: SimulationResult,
                                                tmp_path: Path) -> None:
    """Files of format_version 1 (plain HDF5), also those written before the phase columns
    existed: onset columns intact, the phase columns NaN."""
    path = tmp_path / "old.h5"
    write_hdf5_v1(result, path)
    assert_same(result, jointplay.read(path))
    with h5py.File(path, "r+") as fh:
        for group in (fh, fh["ideal"]):
            table = group["impacts"]
            for name, _, _ in PHASE_FIELDS:
                del table[name]
            for attr in ("rows", "columns", "doc"):
                del table.attrs[attr]
    back = read_hdf5(path)
    for name in ("time", "joint", "speed", "eccentricity"):
        assert_same(getattr(result.impacts, name), getattr(back.impacts, name), name)
    assert len(back.impacts) == 6
    for name, _, _ in PHASE_FIELDS:
        values = getattr(back.impacts, name)
        assert values.shape == (6,), name
        if name == "separated":
            assert values.dtype == bool and not values.any()
        else:
            assert np.isnan(values).all(), name
    assert_same(result.q, back.q)


def test_optional_groups_hook(result: SimulationResult, tmp_path: Path,
                              monkeypatch: pytest.MonkeyPatch) -> None:
    """An optional part of a result is one entry of OPTIONAL_GROUPS: written into a group
    named after the result's attribute when present, read back into the same attribute."""
    from jointplay.results import netcdf

    def write(group: Any, value: dict[str, float]) -> None:
        for key, number in value.items():
            group.attrs[key] = number

    def read(group: Any) -> dict[str, float]:
        return {key: float(value) for key, value in group.attrs.items()}

    monkeypatch.setitem(netcdf.OPTIONAL_GROUPS, "wear", netcdf.OptionalGroup(write, read))
    summary = {"tip_error_estimate": 2.5e-6, "energy_residual": 1e-9}
    with_part = dataclasses.replace(result, wear=summary)
    path = tmp_path / "run.h5"
    write_hdf5(with_part, path)
    with h5py.File(path, "r") as fh:
        assert fh["wear"].attrs["tip_error_estimate"] == 2.5e-6
        assert "wear" not in fh["ideal"]  # the ideal run holds none
    assert_same(with_part, jointplay.read(path))


def test_hdf5_without_ideal(tmp_path: Path) -> None:
    plain = make_result(n=50, ideal=False)
    write_hdf5(plain, tmp_path / "plain.h5")
    assert_same(plain, read_hdf5(tmp_path / "plain.h5"))


def test_read_rejects_other_files(tmp_path: Path) -> None:
    with h5py.File(tmp_path / "other.h5", "w") as fh:
        fh["x"] = 1.0
    with pytest.raises(DescriptionError, match="jointplay-result"):
        read_hdf5(tmp_path / "other.h5")


def test_csv(result: SimulationResult, tmp_path: Path) -> None:
    path = tmp_path / "run.csv"
    write_csv(result, path)
    header = path.read_text(encoding="utf-8").splitlines()[0].split(",")
    table = np.loadtxt(path, delimiter=",", skiprows=1)
    assert table.shape == (result.n_samples, len(header))
    assert len(set(header)) == len(header)
    col = {name: table[:, i] for i, name in enumerate(header)}
    assert header[0] == "t [s]"
    expected = {
        "t [s]": result.t, "q2 [rad]": result.q[:, 1], "dq2 [rad/s]": result.u[:, 1],
        "ddq2 [rad/s^2]": result.udot[:, 1], "ex3 [m]": result.q[:, 6],
        "dey3 [m/s]": result.u[:, 7], "ddex2 [m/s^2]": result.udot[:, 4],
        "tau4 [N m]": result.tau[:, 3], "tip_x [m]": result.tip_position[:, 0],
        "tip_vy [m/s]": result.tip_velocity[:, 1],
        "tip_ax [m/s^2]": result.tip_acceleration[:, 0], "delta2 [m]": result.penetration[:, 0],
        "ddelta3 [m/s]": result.penetration_rate[:, 1], "f_n2 [N]": result.normal_force[:, 0],
        "f_t3 [N]": result.friction_force[:, 1], "f_y2 [N]": result.contact_force[:, 0, 1],
        "v_slide3 [m/s]": result.sliding_speed[:, 1],
        "energy_total [J]": result.energy["total"],
        "energy_balance [J]": result.energy["balance"],
    }
    assert result.ideal is not None
    expected["ideal_q4 [rad]"] = result.ideal.q[:, 3]
    expected["ideal_tip_y [m]"] = result.ideal.tip_position[:, 1]
    for name, values in expected.items():
        assert np.array_equal(col[name], values), name  # %.17g round-trips exactly
    assert sorted(os.listdir(tmp_path)) == ["run.csv", "run.impacts.csv"]


def test_csv_impact_table(result: SimulationResult, tmp_path: Path) -> None:
    """RUN.impacts.csv beside the samples: one row per phase, units in the header."""
    written = write_csv(result, tmp_path / "run.csv")
    assert written == [tmp_path / "run.csv", tmp_path / "run.impacts.csv"]
    assert impacts_csv_path(tmp_path / "run.txt") == tmp_path / "run.txt.impacts.csv"
    path = tmp_path / "run.impacts.csv"
    header = path.read_text(encoding="utf-8").splitlines()[0].split(",")
    assert header[:6] == ["time [s]", "joint", "speed [m/s]", "eccentricity_x [m]",
                          "eccentricity_y [m]", "onset_angle [rad]"]
    assert "peak_force [N]" in header and "impulse [N s]" in header
    assert header[-1] == "separated"
    table = np.loadtxt(path, delimiter=",", skiprows=1)
    assert table.shape == (len(result.impacts), len(header))
    col = {name: table[:, i] for i, name in enumerate(header)}
    imp = result.impacts
    for name, values in (("time [s]", imp.time), ("speed [m/s]", imp.speed),
                         ("eccentricity_y [m]", imp.eccentricity[:, 1]),
                         ("peak_force [N]", imp.peak_force),
                         ("max_penetration_time [s]", imp.max_penetration_time),
                         ("friction_energy [J]", imp.friction_energy),
                         ("joint", imp.joint), ("separated", imp.separated)):
        assert np.array_equal(col[name], values), name


def test_csv_impact_table_not_located_and_empty(tmp_path: Path) -> None:
    """Phase columns a run did not fill are written as nan; a run without impacts gets a
    header-only table."""
    plain = make_result(n=50, ideal=False)
    onsets = plain.impacts
    only_onsets = dataclasses.replace(plain, impacts=Impacts(
        onsets.time, onsets.joint, onsets.speed, onsets.eccentricity))
    write_csv(only_onsets, tmp_path / "a.csv")
    table = np.loadtxt(tmp_path / "a.impacts.csv", delimiter=",", skiprows=1)
    assert np.array_equal(table[:, 0], onsets.time)
    assert np.isnan(table[:, 6]).all()
    write_csv(make_ideal(20), tmp_path / "b.csv")
    lines = (tmp_path / "b.impacts.csv").read_text(encoding="utf-8").splitlines()
    assert len(lines) == 1 and lines[0].startswith("time [s],joint,")


def test_impacts_to_pandas(result: SimulationResult) -> None:
    frame = result.impacts.to_pandas()
    imp = result.impacts
    assert len(frame) == len(imp) and frame.index.name == "phase"
    assert list(frame.columns[:5]) == ["time", "joint", "speed", "eccentricity_x",
                                       "eccentricity_y"]
    assert frame["joint"].dtype == np.int64 and frame["separated"].dtype == bool
    assert np.array_equal(frame["peak_force"].to_numpy(), imp.peak_force)
    assert np.array_equal(frame["eccentricity_x"].to_numpy(), imp.eccentricity[:, 0])
    assert frame.attrs["units"]["max_penetration"] == "m"
    assert frame.attrs["units"]["eccentricity_y"] == "m"
    frame.loc[0, "peak_force"] = -1.0  # a copy: the result is untouched
    assert imp.peak_force[0] > 0
    by_joint = frame.groupby("joint")["peak_force"].max()
    assert by_joint.to_dict() == {j: imp.for_joint(j).peak_force.max() for j in (2, 3)}
    assert len(Impacts(np.zeros(0), np.zeros(0, dtype=np.int64), np.zeros(0),
                       np.zeros((0, 2))).to_pandas()) == 0


def test_to_xarray(result: SimulationResult) -> None:
    ds = result.to_xarray()
    assert ds.sizes["time"] == result.n_samples
    assert list(ds["joint"].values) == [2, 3]
    assert list(ds["coordinate"].values) == result.coordinate_names
    assert list(ds["unit"].values) == ["rad"] * 4 + ["m"] * 4
    assert ds["q"].dims == ("time", "coordinate")
    assert ds["eccentricity"].dims == ("time", "joint", "axis")
    assert ds["normal_force"].dims == ("time", "joint")
    assert ds["tau"].dims == ("time", "torque_joint")
    assert ds["normal_force"].attrs["unit"] == "N"
    assert ds["time"].attrs["unit"] == "s"
    assert np.array_equal(ds["q"].sel(coordinate="ex3").values, result.q[:, 6])
    assert np.array_equal(ds["normal_force"].sel(joint=3).values, result.normal_force[:, 1])
    assert np.array_equal(ds["contact_force"].sel(joint=2, axis="y").values,
                          result.contact_force[:, 0, 1])
    assert np.array_equal(ds["energy_balance"].values, result.energy["balance"])
    assert result.ideal is not None
    assert np.array_equal(ds["ideal_tip_position"].values, result.ideal.tip_position)
    assert float(ds["parameters"].sel(parameter="gravity.y")) == -9.81
    assert ds.attrs["impacts"] == 6
    one = ds.sel(time=0.5, method="nearest")
    assert one["q"].shape == (8,)
    ideal = make_ideal(30).to_xarray()
    assert ideal.sizes["joint"] == 0 and ideal["eccentricity"].shape == (30, 0, 2)


def test_failed_hdf5_write_leaves_nothing(result: SimulationResult, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "run.h5"
    calls = []
    original = h5py.Group.create_dataset

    def failing(self: h5py.Group, *args: Any, **kwargs: Any) -> Any:
        calls.append(args[0] if args else kwargs["name"])
        if len(calls) > 1:
            raise RuntimeError("disk on fire")
        return original(self, *args, **kwargs)

    monkeypatch.setattr(h5py.Group, "create_dataset", failing)
    with pytest.raises(RuntimeError, match="disk on fire"):
        write_hdf5(result, path)
    assert len(calls) == 2
    assert os.listdir(tmp_path) == []


def test_failed_write_keeps_previous_file(result: SimulationResult, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "run.csv"
    write_csv(result, path)
    before = path.read_bytes()

    def failing(*args: Any, **kwargs: Any) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(np, "savetxt", failing)
    with pytest.raises(KeyboardInterrupt):
        write_csv(result, path)
    assert path.read_bytes() == before
    assert sorted(os.listdir(tmp_path)) == ["run.csv", "run.impacts.csv"]


@pytest.mark.parametrize("writer", [write_hdf5, write_csv])
@pytest.mark.parametrize("case", ["missing", "folder", "readonly"])
def test_bad_output_path(result: SimulationResult, tmp_path: Path, writer: Any, case: str,
                         monkeypatch: pytest.MonkeyPatch) -> None:
    if case == "missing":
        target = tmp_path / "no" / "such" / "run.out"
    elif case == "folder":
        target = tmp_path / "run.out"
        target.mkdir()
    else:
        locked = tmp_path / "locked"
        locked.mkdir(mode=0o500)
        target = locked / "run.out"
        if os.geteuid() == 0:  # root may write anywhere: deny it the way permissions would
            real_access = os.access
            monkeypatch.setattr(os, "access", lambda p, mode: Path(p) != locked
                                and real_access(p, mode))
    with pytest.raises(DescriptionError) as info:
        writer(result, target)
    assert info.value.field == "--out"
    assert str(target.parent if case != "folder" else target) in info.value.message
    assert not target.is_file()
    assert [p.name for p in tmp_path.rglob("*") if p.is_file()] == []


PNG = b"\x89PNG\r\n\x1a\n"


def test_plots(result: SimulationResult, tmp_path: Path) -> None:
    folder = tmp_path / "plots"
    paths = plot_result(result, folder)
    # in the order they are drawn: the costliest first (plots.figure_jobs)
    names = ["end_effector.png", "energy.png", "contact_timeline_joint2.png",
             "contact_timeline_joint3.png", "contact_force.png", "eccentricity_ratio.png",
             "orbit_joint2.png", "orbit_joint3.png"]
    assert [p.name for p in paths] == names
    assert sorted(os.listdir(folder)) == sorted(names)
    for p in paths:
        data = p.read_bytes()
        assert data.startswith(PNG), p.name
        assert len(data) > 20_000, p.name


def test_plots_without_ideal_or_clearance(tmp_path: Path) -> None:
    paths = plot_result(make_result(n=100, ideal=False), tmp_path / "a")
    assert len(paths) == 8
    paths = plot_result(make_ideal(100), tmp_path / "b")
    assert [p.name for p in paths] == ["end_effector.png", "energy.png"]


def test_plots_module_imports_no_matplotlib() -> None:
    code = ("import sys, jointplay.results.plots, jointplay.results.write, "
            "jointplay.results.animate, jointplay.results.export; "
            "assert not {'matplotlib', 'pandas', 'xarray'} & set(sys.modules)")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_first_burst_rule(result: SimulationResult) -> None:
    """The burst ends at the first pause longer than BURST_GAP times the time since the run
    began; the run's length does not enter."""
    rows = result.impacts.for_joint(2)  # phases 0.2-0.3, 0.4-0.5, ...: pauses of 0.1 s
    assert BURST_GAP == 1.0
    # from t0 = 0: 0.1 s pauses after 0.3 s and more since the release never end it
    assert first_burst(rows, 0.0) == (0.2, rows.separation_time[min(len(rows), BURST_MAX) - 1])
    # from t0 = 0.25: the first pause (0.1 s) is longer than the 0.05 s since then
    assert first_burst(rows, 0.25) == (0.2, 0.3)
    assert np.isnan(first_burst(rows.for_joint(9), 0.0)[0])


def test_contact_timeline_marks_located_peaks_or_says_not_located(
        result: SimulationResult, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """With a filled table the located peaks are drawn (stems up to each peak); with onset
    columns only, the figure says the peaks are not located and draws no peak."""
    import jointplay.results.plots as plots

    figures: list[Any] = []
    original = plots.save

    def keep(fig: Any, path: Path) -> Path:
        figures.append(fig)
        return original(fig, path)

    monkeypatch.setattr(plots, "save", keep)
    plot_contact_timeline(result, 0, tmp_path / "a.png")
    onsets = result.impacts
    bare = dataclasses.replace(result, integrator="rk4", impacts=Impacts(
        onsets.time, onsets.joint, onsets.speed, onsets.eccentricity))
    plot_contact_timeline(bare, 0, tmp_path / "b.png")
    located, bare_fig = (fig.axes[0] for fig in figures)
    labels = [line.get_label() for line in located.lines]
    assert "located peak" in labels
    peak_line = located.lines[labels.index("located peak")]
    assert np.array_equal(peak_line.get_ydata(), result.impacts.for_joint(2).peak_force)
    assert "located peak" not in [line.get_label() for line in bare_fig.lines]
    texts = " ".join(t.get_text() for t in bare_fig.texts)
    assert "not located" in texts and "rk4" in texts
    assert (tmp_path / "b.png").read_bytes().startswith(PNG)


def test_arm_points_end_at_the_tip(result: SimulationResult) -> None:
    """The animation's kinematics (sum of relative angles, eccentricity at clearance joints)
    reproduce the result's tip position."""
    points = arm_points(result)
    assert points.shape == (result.n_samples, 5, 2)
    assert np.allclose(points[:, 0], 0.0)
    assert np.max(np.abs(points[:, -1] - result.tip_position)) < 1e-14


def test_animation_gif(tmp_path: Path) -> None:
    from PIL import Image

    small = make_result(n=40, ideal=False)
    path = animate_result(small, tmp_path / "arm.gif", max_frames=4)
    assert path == tmp_path / "arm.gif"
    assert os.listdir(tmp_path) == ["arm.gif"]  # no temporary file left
    with Image.open(path) as image:
        assert image.format == "GIF" and image.n_frames == 4
    assert list(frame_indices(40, 4)) == [0, 13, 26, 39]
    assert list(frame_indices(3, 10)) == [0, 1, 2]


def test_animation_refuses_bad_files(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from matplotlib import animation

    with pytest.raises(DescriptionError, match=r"must end in \.gif or \.mp4"):
        check_animation_path(tmp_path / "arm.avi")
    monkeypatch.setattr(animation.writers, "is_available", lambda name: False)
    with pytest.raises(DescriptionError, match="needs the ffmpeg program") as info:
        check_animation_path(tmp_path / "arm.mp4")
    assert info.value.field == "--animate"
    check_animation_path(tmp_path / "arm.gif")  # Pillow needs no program
    assert os.listdir(tmp_path) == []
