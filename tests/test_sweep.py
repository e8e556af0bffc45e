"""Parameter sweeps: parallel equals serial, dead workers and restarts lose nothing, bad files
fail before any work.

A 2-link arm with clearance at joint 2, simulated for 0.05 s, keeps every case well under a
second; one local cluster of two worker processes serves the whole module.
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import tomllib
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from jointplay.cli.sweep import register
from jointplay.common.errors import DescriptionError
from jointplay.sweep import (
    TABLE_NAME,
    Case,
    contact_metrics,
    load_sweep,
    run_sweep,
    sweep_from_dict,
)

TINY = """
name = "tiny"
[torques]
joint1 = "2*sin(2*pi*t)"
[initial]
q1 = "-pi/2"
[run]
t_end = 0.05
output_step = 1e-3
[robot]
name = "tiny"
[robot.payload]
mass = 0.2
[robot.friction]
law = "{friction}"
[[robot.links]]
length = 0.3
mass = 1.0
inertia = 0.0075
com = 0.15
[[robot.links]]
length = 0.3
mass = 1.0
inertia = 0.0075
com = 0.15
[[robot.joints]]
kind = "ideal"
[[robot.joints]]
kind = "clearance"
bearing_radius = 10e-3
journal_radius = 9.97e-3
"""

GRID = """
scene = "tiny.toml"
mode = "product"
[parameters."joint2.clearance"]
start = 2e-5
stop = 1e-4
num = 3
spacing = "log"
[parameters."friction.mu"]
values = [0.0, 0.1]
"""

# Columns that depend on the machine or on which worker ran a case, not on the case.
VARYING = {"wall_time_s", "simulation_time_s", "cpu_time_s", "worker", "ideal_reused",
           "series"}


def _write(tmp_path: Path, sweep: str, friction: str = "coulomb") -> Path:
    (tmp_path / "tiny.toml").write_text(TINY.format(friction=friction), encoding="utf-8")
    path = tmp_path / "sweep.toml"
    path.write_text(sweep, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def client() -> Any:
    from distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None, silence_logs=logging.CRITICAL)
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


def _logger(log: Path, kill_index: int | None = None,
            marker: Path | None = None, interrupt_after: int | None = None
            ) -> Callable[[Case], None]:
    """A hook run before each case where the case runs (defined inside a function so that
    Dask ships it to the workers by value): it logs the case key, and can kill its own worker
    the first time case ``kill_index`` starts, or interrupt after some cases."""

    def hook(case: Case) -> None:
        with open(log, "a", encoding="utf-8") as fh:
            fh.write(case.key + "\n")
        if kill_index is not None and marker is not None and case.index == kill_index \
                and not marker.exists():
            marker.touch()
            os._exit(1)
        if interrupt_after is not None:
            with open(log, encoding="utf-8") as fh:
                if len(fh.read().split()) > interrupt_after:
                    raise KeyboardInterrupt

    return hook


def _runs(log: Path) -> list[str]:
    return log.read_text(encoding="utf-8").split() if log.exists() else []


def _columns(table: Any) -> dict[str, list[Any]]:
    return {k: v for k, v in table.to_pydict().items() if k not in VARYING}


def test_local_cluster_equals_serial(tmp_path: Path, client: Any) -> None:
    from jointplay.results.write import read_hdf5

    sweep = load_sweep(_write(tmp_path, GRID))
    assert len(sweep.cases) == 6
    assert len({c.ideal_key for c in sweep.cases}) == 1  # clearance and friction only
    serial = run_sweep(sweep, tmp_path / "serial", workers=0, plots=False)
    parallel = run_sweep(sweep, tmp_path / "parallel", client=client, series=True)
    assert serial.ran == parallel.ran == 6 and serial.failed == parallel.failed == 0
    a, b = _columns(serial.table), _columns(parallel.table)
    assert a.keys() == b.keys()
    for name in a:
        assert a[name] == b[name], name  # bit for bit: the same compiled model and inputs
    assert a["case"] == list(range(6))
    assert len(set(a["key"])) == 6
    assert sum(serial.table.column("ideal_reused").to_pylist()) >= 5
    mu0 = [e for e, mu in zip(a["max_position_error"], a["friction.mu"], strict=True)
           if mu == 0.0]
    assert all(e > 0 for e in mu0) and mu0 == sorted(mu0)  # more play, more tip error
    assert np.allclose(np.array(a["joint2.journal_radius"]),
                       10e-3 - np.array(a["joint2.clearance"]), rtol=0, atol=1e-18)
    # The series reproduce the row's metrics.
    row = parallel.table.slice(5, 1).to_pylist()[0]
    result = read_hdf5(tmp_path / "parallel" / row["series"])
    assert result.ideal is not None
    err = np.linalg.norm(result.tip_position - result.ideal.tip_position, axis=1).max()
    assert err == row["max_position_error"]
    # Contact columns come from the phase table, never from the samples.
    expected = contact_metrics(result)
    for name in ("peak_normal_force_joint2", "max_penetration_joint2", "impacts_joint2",
                 "max_approach_speed_joint2", "peak_note", "impacts"):
        assert row[name] == expected[name], name
    rows = result.impacts.for_joint(2)
    assert row["impacts_joint2"] == len(rows) == row["impacts"] > 0
    assert row["max_approach_speed_joint2"] == rows.speed.max()
    if np.isnan(rows.peak_force).any():
        assert row["peak_normal_force_joint2"] is None and "not located" in row["peak_note"]
    else:
        assert row["peak_normal_force_joint2"] == rows.peak_force.max()
    assert sorted(p.name for p in parallel.plots) == ["friction.mu.png",
                                                      "joint2.clearance.png"]


def test_dead_worker_loses_no_case(tmp_path: Path, client: Any) -> None:
    sweep_text = GRID.replace("num = 3", "num = 2")
    sweep = load_sweep(_write(tmp_path, sweep_text))
    log, marker = tmp_path / "runs.log", tmp_path / "killed"
    victim = sweep.cases[1]
    result = run_sweep(sweep, tmp_path / "out", client=client,
                       hook=_logger(log, kill_index=1, marker=marker), plots=False)
    assert marker.exists()  # the worker running case 1 did die
    runs = _runs(log)
    assert runs.count(victim.key) == 2  # rerun on a live worker
    assert set(runs) == {c.key for c in sweep.cases}
    keys = result.table.column("key").to_pylist()
    assert sorted(keys) == sorted(c.key for c in sweep.cases)  # each case exactly once
    assert result.table.column("status").to_pylist() == ["ok"] * 4
    assert len(list((tmp_path / "out" / "cases").glob("*.json"))) == 4


def test_interrupted_sweep_resumes(tmp_path: Path, client: Any) -> None:
    path = _write(tmp_path, GRID)
    out = tmp_path / "out"
    log = tmp_path / "runs.log"
    with pytest.raises(KeyboardInterrupt):  # interrupted while the fourth case starts
        run_sweep(path, out, workers=0, hook=_logger(log, interrupt_after=3))
    done = {p.stem for p in (out / "cases").glob("*.json")}
    assert len(done) == 3 and set(_runs(log)[:3]) == done
    assert not (out / TABLE_NAME).exists()
    log.unlink()
    resumed = run_sweep(path, out, client=client, hook=_logger(log), plots=False)
    assert resumed.ran == 3 and resumed.reused == 3
    assert set(_runs(log)).isdisjoint(done) and len(_runs(log)) == 3
    assert len(set(resumed.table.column("key").to_pylist())) == 6
    # Once more: nothing to do, the same table.
    again = run_sweep(path, out, workers=0, hook=_logger(log), plots=False)
    assert again.ran == 0 and len(_runs(log)) == 3
    assert _columns(again.table) == _columns(resumed.table)
    # A grown sweep runs only its new cases; the command line does the same.
    (tmp_path / "sweep.toml").write_text(GRID.replace("[0.0, 0.1]", "[0.0, 0.1, 0.2]"),
                                         encoding="utf-8")
    parser = argparse.ArgumentParser()
    register(parser.add_subparsers())
    args = parser.parse_args(["sweep", str(path), "--out", str(out), "--workers", "0",
                              "--quiet"])
    assert args.func(args) == 0
    manifest = json.loads((out / "sweep.json").read_text(encoding="utf-8"))
    assert len(manifest["cases"]) == 9 and len(list((out / "cases").glob("*.json"))) == 9
    import pyarrow.parquet as pq

    table = pq.read_table(out / TABLE_NAME)
    assert table.num_rows == 9 and table.column("case").to_pylist() == list(range(9))


BAD = [
    ('[parameters."friction.muu"]\nvalues = [0.1]', "parameters.friction.muu",
     "did you mean 'friction.mu'"),
    ('[parameters."contact.law"]\nvalues = [1.0]', "parameters.contact.law", "structure"),
    ('[parameters."joint2.kind"]\nvalues = [1.0]', "parameters.joint2.kind", "structure"),
    ('[parameters."contact.stiffness"]\nvalues = [1.0]', "parameters.contact.stiffness",
     "structure"),
    ('[parameters."joint2.length"]\nvalues = [0.02]', "parameters.joint2.length",
     "cylindrical contact laws only"),
    ('[parameters."joint1.length"]\nvalues = [0.02]', "parameters.joint1.length",
     "only joints with clearance"),
    ('[parameters."joint1.angle"]\nvalues = [1.0]', "parameters.joint1.angle",
     "only locked joints"),
    ('[parameters."joint1.clearance"]\nvalues = [1e-5]', "parameters.joint1.clearance",
     "no clearance"),
    ('[parameters."friction.mu"]\nstart = 0.1\nstop = 0.1\nnum = 3',
     "parameters.friction.mu.stop", "empty"),
    ('[parameters."friction.mu"]\nstart = 0.0\nstop = 0.1\nnum = 0',
     "parameters.friction.mu.num", ">= 1"),
    ('[parameters."friction.mu"]\nvalues = []', "parameters.friction.mu.values", "non-empty"),
    ('[parameters."friction.mu"]\ndistribution = "gaussian"\nmean = 0.1\nstd = 0.01\n'
     'count = 4', "parameters.friction.mu.distribution", "uniform, normal, lognormal"),
    ('[parameters."friction.mu"]\ndistribution = "normal"\nmean = 0.1\nstd = -1.0\ncount = 4',
     "parameters.friction.mu.std", "> 0"),
    ('[parameters."friction.mu"]\ndistribution = "uniform"\nlow = 0.0\nhigh = 0.1',
     "parameters.friction.mu.count", "count"),
    ('[parameters."joint2.clearance"]\nvalues = [1e-5, 0.02]',
     "parameters.joint2.clearance", "case 1"),
    ('mode = "zip"\n[parameters."friction.mu"]\nvalues = [0.1, 0.2]\n'
     '[parameters."payload.mass"]\nvalues = [1.0]', "parameters.payload.mass", "zip"),
    ('[run]\nt_end = -1.0\n[parameters."friction.mu"]\nvalues = [0.1]', "run.t_end", "> 0"),
    ('[run]\noutput_step = 3e-7\n[parameters."friction.mu"]\nvalues = [0.1]',
     "run.output_step", "must divide run.t_end"),
    ('[parameters."friction.mu"]\nvalues = [0.1, 0.1]', "parameters.friction.mu.values",
     "twice"),
]


@pytest.mark.parametrize(("body", "field", "words"), BAD, ids=[b[1] for b in BAD])
def test_bad_sweep_is_refused_before_any_work(tmp_path: Path, body: str, field: str,
                                              words: str) -> None:
    path = _write(tmp_path, 'scene = "tiny.toml"\n' + body)
    with pytest.raises(DescriptionError) as info:
        run_sweep(path, tmp_path / "out")
    assert info.value.field == field
    assert words in str(info.value) and str(path) in str(info.value)
    assert not (tmp_path / "out").exists()  # nothing written


def test_effects_that_are_off_and_bad_options(tmp_path: Path) -> None:
    path = _write(tmp_path, 'scene = "tiny.toml"\n[parameters."friction.mu"]\nvalues = [0.1]',
                  friction="none")
    with pytest.raises(DescriptionError, match="friction is off") as info:
        load_sweep(path)
    assert info.value.field == "parameters.friction.mu"
    good = _write(tmp_path, GRID)
    with pytest.raises(DescriptionError) as info:
        run_sweep(good, tmp_path / "out", workers=-1)
    assert info.value.field == "--workers" and not (tmp_path / "out").exists()
    parser = argparse.ArgumentParser()
    register(parser.add_subparsers())
    args = parser.parse_args(["sweep", str(tmp_path / "missing.toml"), "--out",
                              str(tmp_path / "out")])
    with pytest.raises(DescriptionError, match="not found"):
        args.func(args)


@pytest.mark.slow
def test_sweep_of_a_cylindrical_contact_law(tmp_path: Path) -> None:
    """A base scene under Johnson's law: its journal length and clearance are parameters
    like any other; a longer journal is stiffer, so its peak force is higher."""
    text = TINY.format(friction="coulomb").replace(
        "[robot.friction]", '[robot.contact]\nstiffness = "johnson"\n[robot.friction]')
    (tmp_path / "tiny.toml").write_text(text + "length = 0.02\n", encoding="utf-8")
    path = tmp_path / "sweep.toml"
    path.write_text('scene = "tiny.toml"\n[parameters."joint2.length"]\nvalues = [0.005, 0.05]'
                    '\n[parameters."joint2.clearance"]\nvalues = [3e-5]\n', encoding="utf-8")
    sweep = load_sweep(path)
    assert sweep.scene.robot.structure().contact_stiffness == "johnson"
    table = _columns(run_sweep(sweep, tmp_path / "out", workers=0, plots=False).table)
    assert table["status"] == ["ok", "ok"]
    assert table["joint2.length"] == [0.005, 0.05]
    assert all(n > 0 for n in table["impacts"])
    assert table["peak_normal_force"][0] < table["peak_normal_force"][1]


def test_random_samples_are_seeded(tmp_path: Path) -> None:
    (tmp_path / "tiny.toml").write_text(TINY.format(friction="coulomb"), encoding="utf-8")
    text = """
scene = "tiny.toml"
mode = "zip"
seed = 7
count = 5
[parameters."friction.mu"]
distribution = "uniform"
low = 0.05
high = 0.15
[parameters."payload.mass"]
distribution = "lognormal"
mu = -1.0
sigma = 0.2
[parameters."contact.restitution"]
distribution = "normal"
mean = 0.8
std = 0.02
count = 5
seed = 3
"""
    data = tomllib.loads(text)
    one = sweep_from_dict(data, base=tmp_path)
    two = sweep_from_dict(data, base=tmp_path)
    assert [c.swept for c in one.cases] == [c.swept for c in two.cases]
    assert len(one.cases) == 5
    mu = np.array([c.swept["friction.mu"] for c in one.cases])
    assert np.all((mu >= 0.05) & (mu < 0.15)) and mu.dtype == np.float64
    other = sweep_from_dict({**data, "seed": 8}, base=tmp_path)
    assert [c.swept["friction.mu"] for c in other.cases] != list(mu)
    # The restitution has its own seed: the top-level seed leaves it alone.
    assert [c.swept["contact.restitution"] for c in other.cases] == \
        [c.swept["contact.restitution"] for c in one.cases]


def test_run_output_step_of_a_sweep(tmp_path: Path) -> None:
    """[run] output_step in a sweep file sets every case's output samples (and its key)."""
    base = load_sweep(_write(tmp_path, GRID))
    fine = load_sweep(_write(tmp_path, GRID + "[run]\noutput_step = 5e-4\n"))
    assert {c.scene.run.output_step for c in fine.cases} == {5e-4}
    assert {c.scene.run.output_step for c in base.cases} == {1e-3}
    assert not {c.key for c in fine.cases} & {c.key for c in base.cases}


def test_contact_metrics_from_the_table() -> None:
    """Located peaks from a hand-made table; a table with onsets only gives None + a note."""
    import dataclasses

    from test_output import make_result

    from jointplay.results.records import Impacts

    result = make_result(n=200, ideal=False)
    m = contact_metrics(result)
    imp = result.impacts
    for j in (2, 3):
        rows = imp.for_joint(j)
        assert m[f"peak_normal_force_joint{j}"] == rows.peak_force.max()
        assert m[f"max_penetration_joint{j}"] == rows.max_penetration.max()
        assert m[f"impacts_joint{j}"] == len(rows)
        assert m[f"max_approach_speed_joint{j}"] == rows.speed.max()
    assert m["peak_normal_force"] == imp.peak_force.max()
    assert m["peak_normal_force"] > result.normal_force.max()  # samples miss the peak
    assert m["max_penetration"] == imp.max_penetration.max()
    assert m["max_approach_speed"] == imp.speed.max()
    assert (m["impacts"], m["peak_note"]) == (6, None)
    bare = dataclasses.replace(result, integrator="radau", impacts=Impacts(
        imp.time, imp.joint, imp.speed, imp.eccentricity))
    m = contact_metrics(bare)
    assert m["peak_normal_force"] is None and m["max_penetration_joint3"] is None
    assert m["impacts"] == 6 and m["max_approach_speed"] == imp.speed.max()
    assert "joint 2: not located" in m["peak_note"] and "radau" in m["peak_note"]
    json.dumps(m, allow_nan=False)  # the case file stays plain JSON


def test_sweep_cases_can_state_their_accuracy(tmp_path: Path) -> None:
    """With verify, each case carries its own accuracy statement (the same numbers as the
    case simulated alone with verify=True); a sweep finished without it runs again."""
    from jointplay.sim import simulate

    (tmp_path / "tiny.toml").write_text(TINY.format(friction="coulomb"), encoding="utf-8")
    path = tmp_path / "sweep.toml"
    path.write_text('scene = "tiny.toml"\n[parameters."friction.mu"]\nvalues = [0.1]\n',
                    encoding="utf-8")
    sweep = load_sweep(path)
    plain = _columns(run_sweep(sweep, tmp_path / "out", workers=0, plots=False).table)
    assert "tip_error_estimate" not in plain
    checked = run_sweep(sweep, tmp_path / "out", workers=0, plots=False, verify=True)
    assert checked.ran == 1
    table = _columns(checked.table)
    for k, case in enumerate(sweep.cases):
        alone = simulate(case.scene, verify=True).accuracy
        assert alone is not None
        assert table["tip_error_estimate"][k] == alone.tip_error_estimate
        assert table["agreement_horizon"][k] == alone.agreement_horizon
        assert table["accuracy_energy_residual"][k] == alone.energy_residual
