"""Where a sweep's cases run when neither ``--workers`` nor a cluster is given: this process
runs the first case, and the rest go to a local Dask cluster only when that saves more than
the cluster's start-up; one line says which and why."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from test_sweep import GRID, _write

from jointplay.cli import main
from jointplay.sweep import run as sweep_run
from jointplay.sweep.run import CLUSTER_START_S, engine_choice, run_sweep


def test_engine_choice_weighs_the_saving_against_the_start_up() -> None:
    # 11 cases of 0.6 s on 2 workers: 6.6 s here, a cluster saves 3.3 s < its start-up.
    cluster, why = engine_choice(0.6, 11, 2)
    assert not cluster
    assert why.startswith("the other 11 cases run in this process: the first case took "
                          "0.6 s here, so about 6.6 s, and a cluster of 2 workers would save "
                          "at most 3.3 s of that")
    assert "--workers N" in why
    # 40 cases of 3 s on 2 workers: 120 s here, the cluster saves 60 s.
    cluster, why = engine_choice(3.0, 40, 2)
    assert cluster
    assert "local Dask cluster of 2 workers" in why and "saves about 60 s" in why
    assert "--workers 0" in why
    # Exactly break-even stays here; one worker never gains.
    remaining = 10
    even = 2 * CLUSTER_START_S / remaining
    assert not engine_choice(even, remaining, 2)[0]
    assert engine_choice(even * 1.01, remaining, 2)[0]
    cluster, why = engine_choice(100.0, 50, 1)
    assert not cluster and "one core" in why


@pytest.fixture
def no_cluster(monkeypatch: pytest.MonkeyPatch) -> list[Any]:
    """Record what would go to a cluster instead of starting one."""
    sent: list[Any] = []

    @contextlib.contextmanager
    def fake_client(client: Any, scheduler: Any, workers: Any) -> Iterator[str]:
        sent.append(("client", client, scheduler, workers))
        yield "cluster"

    def fake_run(cluster: Any, pending: Any, out: Path, **kwargs: Any) -> None:
        from jointplay.sweep.case import run_case
        from jointplay.sweep.records import record

        sent.append(("cases", [c.key for c in pending]))
        for case in pending:  # run here, so the table is whole
            record(out, run_case(case, series=kwargs["series"], hook=kwargs["hook"],
                                 verify=kwargs["verify"]))
            kwargs["progress"].update(1)

    monkeypatch.setattr(sweep_run, "_dask_client", fake_client)
    monkeypatch.setattr(sweep_run, "_run_dask", fake_run)
    monkeypatch.setattr(sweep_run, "default_workers", lambda: 2)
    return sent


def test_cheap_cases_run_in_this_process(tmp_path: Path, no_cluster: list[Any],
                                         capsys: pytest.CaptureFixture[str]) -> None:
    path = _write(tmp_path, GRID)
    assert main(["sweep", str(path), "--out", str(tmp_path / "out")]) == 0
    assert no_cluster == []  # no cluster was started
    said = [line for line in capsys.readouterr().out.splitlines()
            if "the other 5 cases run in this process: the first case took " in line]
    assert len(said) == 1 and said[0].startswith("sweep "), said


def test_costly_cases_go_to_a_local_cluster(tmp_path: Path, no_cluster: list[Any],
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(sweep_run, "CLUSTER_START_S", 0.0)  # any saving pays for it
    result = run_sweep(_write(tmp_path, GRID), tmp_path / "out", plots=False)
    assert result.engine.startswith("the other 5 cases run on a local Dask cluster of 2 "
                                    "workers: the first case took ")
    assert no_cluster[0] == ("client", None, None, None)
    assert len(no_cluster[1][1]) == 5 and result.ran == 6 and result.failed == 0


def test_given_workers_or_one_case_decide(tmp_path: Path, no_cluster: list[Any]) -> None:
    path = _write(tmp_path, GRID)
    result = run_sweep(path, tmp_path / "serial", workers=0, plots=False)
    assert result.engine == "the cases run in this process (--workers 0)" and not no_cluster
    result = run_sweep(path, tmp_path / "dask", workers=2, plots=False)
    assert result.engine == "the cases run on a local Dask cluster of 2 workers (--workers)"
    assert no_cluster[0] == ("client", None, None, 2)
    one = _write(tmp_path, GRID.replace("num = 3", "num = 1").replace("[0.0, 0.1]", "[0.1]"))
    result = run_sweep(one, tmp_path / "one", plots=False)
    assert result.engine == "the cases run in this process: at most one case to run"
