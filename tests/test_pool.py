"""The worker pool (calibration, identification, study): a dead or stuck worker is detected and
the run goes on with the same numbers; a piece's error is raised here; Ctrl-C prints the
command's one line and leaves no worker behind; the pieces run on a Dask cluster give the same
numbers as here."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from functools import partial
from pathlib import Path

import pytest

from jointplay.common import pool


def _stuck_in_a_worker(parent: int, index: int) -> int:
    if os.getpid() != parent and index >= 2:
        time.sleep(30)
    return index * index


def _killed_in_a_worker(parent: int, index: int) -> int:
    if os.getpid() != parent and index == 2:
        os.kill(os.getpid(), signal.SIGKILL)
    return index * index


def test_stuck_workers_give_way_to_this_process(monkeypatch: pytest.MonkeyPatch,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    """A pool that sends nothing back for STALL_S seconds is killed; the pieces not yet back
    run here, in order, and the numbers are those of a run without workers."""
    monkeypatch.setattr(pool, "STALL_S", 1.0)
    started = time.monotonic()
    assert pool.parallel_map(partial(_stuck_in_a_worker, os.getpid()), 5, 2) \
        == [0, 1, 4, 9, 16]
    assert time.monotonic() - started < 20  # not the workers' 30 s sleep
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "sent nothing back for 1 s" in err and "3 remaining pieces" in err


def test_a_killed_worker_is_detected_and_its_pieces_run_here(
        capsys: pytest.CaptureFixture[str]) -> None:
    """A worker killed mid-piece (SIGKILL) breaks the pool; one line says so and the pieces
    not back run here, with the numbers of a run without workers."""
    assert pool.parallel_map(partial(_killed_in_a_worker, os.getpid()), 5, 2) \
        == [0, 1, 4, 9, 16]
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "lost a worker process" in err


def _fails_at_three(index: int) -> int:
    if index == 3:
        raise ValueError("piece 3 failed")
    return index


def test_each_piece_reported_as_it_comes_back_and_an_error_raised_here(
        capsys: pytest.CaptureFixture[str]) -> None:
    """``on_result`` sees every piece once (a progress bar), those back from the workers and
    those run here after a lost worker alike; a piece's exception reaches the caller."""
    seen: list[int] = []
    assert pool.parallel_map(partial(_killed_in_a_worker, os.getpid()), 5, 2,
                             label="study", on_result=seen.append) == [0, 1, 4, 9, 16]
    assert sorted(seen) == [0, 1, 4, 9, 16]
    assert "the study's worker processes lost a worker" in capsys.readouterr().err
    for workers in (1, 2):
        with pytest.raises(ValueError, match="piece 3 failed"):
            pool.parallel_map(_fails_at_three, 5, workers)


def test_no_worker_outlives_the_map() -> None:
    """Every forked worker is gone once the map returns."""
    import multiprocessing

    # Children of earlier tests in this session (a figure process, say) are not the map's.
    before = set(multiprocessing.active_children())
    assert pool.parallel_map(lambda i: os.getpid(), 4, 2) is not None
    assert set(multiprocessing.active_children()) - before == set()


_INTERRUPTED = textwrap.dedent("""
    import os, sys, time
    sys.argv[0] = "jointplay"  # the command's own behaviour on Ctrl-C
    from jointplay.common import interrupts
    from jointplay.common import pool

    folder = sys.argv[1]

    def job(index):
        open(os.path.join(folder, str(os.getpid())), "w").close()
        time.sleep(60)
        return index

    with interrupts.installed():
        pool.parallel_map(job, 4, 2)
""")


def test_ctrl_c_prints_one_line_and_stops_every_worker(tmp_path: Path) -> None:
    """Ctrl-C at a terminal reaches the whole process group: the workers ignore it, the
    command stops them and prints only ``jointplay: interrupted`` (exit 130)."""
    process = subprocess.Popen([sys.executable, "-c", _INTERRUPTED, str(tmp_path)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               start_new_session=True)
    deadline = time.monotonic() + 60
    while len(list(tmp_path.iterdir())) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)
    pids = [int(p.name) for p in tmp_path.iterdir()]
    assert len(pids) == 2, "the workers did not start"
    os.killpg(process.pid, signal.SIGINT)
    out, err = process.communicate(timeout=30)
    assert (process.returncode, out, err) == (130, "", "jointplay: interrupted\n")
    time.sleep(0.2)
    for pid in pids:
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)


def _square(index: int) -> int:
    return index * index


def test_pieces_on_a_dask_cluster_and_an_unreachable_scheduler(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Through a scheduler's address the pieces give the numbers of a run here; an address
    that does not answer is an error naming --scheduler."""
    distributed = pytest.importorskip("distributed")
    from jointplay.common.errors import DescriptionError

    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            pool.on_cluster(cluster.scheduler_address):
        assert pool.parallel_map(_square, 5, 2) == [0, 1, 4, 9, 16]
    monkeypatch.setattr(pool, "CONNECT_TIMEOUT_S", 2.0)
    with pytest.raises(DescriptionError, match="--scheduler"), \
            pool.on_cluster("tcp://127.0.0.1:9"):
        pass


def test_a_predictor_travels_pickled_with_its_model_reloaded() -> None:
    """A predictor sent to a cluster's worker reloads the compiled model there and predicts
    the same outputs."""
    import pickle

    import numpy as np

    import jointplay as jp
    from jointplay.calibration import Measured
    from jointplay.calibration.parameters import free_parameters
    from jointplay.calibration.predict import Predictor
    from jointplay.sim import load_scene_model

    scene = jp.default_scene().with_run(t_end=0.01)
    model = load_scene_model(scene)
    t = np.arange(1, 11) * scene.run.output_step
    measured = Measured("test", t, ("tip_x",), np.zeros((t.size, 1)))
    free = free_parameters(["friction.mu"], scene, model)
    predictor = Predictor(scene, model, free, measured)
    copy = pickle.loads(pickle.dumps(predictor))
    assert "_cache" in pickle.loads(pickle.dumps(predictor)).__dict__
    assert pickle.dumps(predictor).count(b"casadi") == 0  # the model itself stays behind
    np.testing.assert_array_equal(copy.outputs(free.start, with_jacobian=False),
                                  predictor.outputs(free.start, with_jacobian=False))
