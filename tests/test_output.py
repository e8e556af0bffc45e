"""Result files (HDF5, CSV) and figures, on a synthetic but self-consistent result."""

from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import h5py
import numpy as np
import pytest

from jointplay.errors import DescriptionError
from jointplay.output import read_hdf5, write_csv, write_hdf5
from jointplay.plots import impact_positions, plot_result
from jointplay.results import Impacts, SimulationResult

LENGTHS = np.array([0.40, 0.30, 0.25, 0.15])
MASSES = np.array([2.0, 1.5, 1.0, 0.5])
CLEARANCE = {2: (50e-6, 5.0, 0.7), 3: (80e-6, 3.0, -1.3)}  # joint: (c, f, sweep rate rad/s)
STIFFNESS, FRICTION, AMPLITUDE = 1e10, 0.1, 0.02


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
            "parameter_names": ["link1.length", "link2.length", "gravity.y"],
            "parameters": np.array([0.4, 0.3, -9.81])}


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
        impact_rows += [(k / f, joint, c * AMPLITUDE * om,
                         c * np.cos(0.3 * joint + nu * k / f), c * np.sin(0.3 * joint + nu * k / f))
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
                      np.array([r[3:] for r in impact_rows]).reshape(-1, 2))
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


@pytest.mark.parametrize("compress", [False, True])
def test_hdf5_round_trip(result: SimulationResult, tmp_path: Path, compress: bool) -> None:
    path = tmp_path / "run.h5"
    write_hdf5(result, path, compress=compress)
    back = read_hdf5(path)
    assert_same(result, back)
    assert back.ideal is not None
    assert sorted(os.listdir(tmp_path)) == ["run.h5"]
    with h5py.File(path, "r") as fh:
        assert (fh["q"].compression == "gzip") is compress  # 500 x 8 doubles: 31 KiB


def test_hdf5_layout(result: SimulationResult, tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    write_hdf5(result, path)
    with h5py.File(path, "r") as fh:
        assert fh.attrs["format"] == "jointplay-result"
        assert fh.attrs["format_version"] == 1
        assert list(fh.attrs["coordinate_names"]) == result.coordinate_names
        assert fh["q"].attrs["unit"] == "rad or m"
        assert list(fh["q"].attrs["column_units"])[-1] == "m"
        assert fh["u"].attrs["unit"] == "rad/s or m/s"
        assert list(fh["udot"].attrs["column_units"])[:1] == ["rad/s^2"]
        assert fh["tip_velocity"].attrs["unit"] == "m/s"
        assert fh["energy/balance"].attrs["unit"] == "J"
        assert all("doc" in ds.attrs for ds in fh["impacts"].values())
        assert fh["metadata"].attrs["model_hash"] == "0123abcd"
        assert fh["metadata/json"].attrs["versions"].startswith("{")
        assert list(fh["parameters"].attrs["names"]) == result.parameter_names
        assert fh["ideal/q"].shape == (result.n_samples, 4)
        assert fh["ideal/eccentricity"].shape == (result.n_samples, 0, 2)


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
    assert sorted(os.listdir(tmp_path)) == ["run.csv"]


def test_failed_hdf5_write_leaves_nothing(result: SimulationResult, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "run.h5"
    calls = []
    original = h5py.Group.create_dataset

    def failing(self: h5py.Group, *args: Any, **kwargs: Any) -> Any:
        calls.append(args[0])
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
    assert os.listdir(tmp_path) == ["run.csv"]


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
    names = ["end_effector.png", "orbit_joint2.png", "orbit_joint3.png", "contact_force.png",
             "energy.png"]
    assert [p.name for p in paths] == names
    assert sorted(os.listdir(folder)) == sorted(names)
    for p in paths:
        data = p.read_bytes()
        assert data.startswith(PNG), p.name
        assert len(data) > 20_000, p.name


def test_plots_without_ideal_or_clearance(tmp_path: Path) -> None:
    paths = plot_result(make_result(n=100, ideal=False), tmp_path / "a")
    assert len(paths) == 5
    paths = plot_result(make_ideal(100), tmp_path / "b")
    assert [p.name for p in paths] == ["end_effector.png", "energy.png"]


def test_plots_module_imports_no_matplotlib() -> None:
    code = "import sys, jointplay.plots, jointplay.output; assert 'matplotlib' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], check=True)
