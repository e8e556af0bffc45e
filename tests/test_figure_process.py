"""The figure process of ``jointplay simulate --plot``: it draws the same files as the command's
own process; when it fails, hangs or is never given figures, the figures are still drawn (or
the process is gone), with one line saying why, and nothing waits without a bound."""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

from jointplay.common import figure_process
from jointplay.common import figures as figure_module
from jointplay.common.figure_process import FigureProcess, _asks_for_figures
from jointplay.results.plots import plot_result
from jointplay.results.records import SimulationResult


@pytest.fixture(scope="module")
def synthetic() -> SimulationResult:
    from test_output import make_result

    return make_result(n=200)


@pytest.fixture
def here(synthetic: SimulationResult, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
         ) -> list[Path]:
    """The figures of ``synthetic`` drawn in this process: what every path must write."""
    monkeypatch.setattr(figure_module, "WORKERS", 1)
    return plot_result(synthetic, tmp_path / "here")


def _same_files(expected: list[Path], got: list[Path]) -> None:
    assert [p.name for p in got] == [p.name for p in expected]
    for a, b in zip(expected, got, strict=True):
        assert a.read_bytes() == b.read_bytes(), b.name
    folder = got[0].parent
    assert sorted(p.name for p in folder.iterdir()) == sorted(p.name for p in got)


def test_the_figure_process_draws_the_same_files(synthetic: SimulationResult,
                                                 here: list[Path], tmp_path: Path,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    with FigureProcess() as process:
        drawn = plot_result(synthetic, tmp_path / "process", process=process)
    _same_files(here, drawn)
    assert capsys.readouterr().err == ""  # nothing went wrong: nothing said


@pytest.mark.parametrize(("bootstrap", "why"), [
    ("import sys; sys.stderr.write('boom\\n'); sys.exit(3)", "exit status 3: boom"),
    ("import sys; sys.stdout.write('not a pickle')", "its answer could not be read"),
])
def test_a_failing_process_leaves_the_figures_to_this_one(
        synthetic: SimulationResult, here: list[Path], tmp_path: Path, bootstrap: str,
        why: str, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setattr(figure_process, "_BOOTSTRAP", bootstrap)
    with FigureProcess() as process:
        drawn = plot_result(synthetic, tmp_path / "failed", process=process)
    _same_files(here, drawn)
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and why in err and "drawing the figures here" in err, err


def test_a_hanging_process_is_killed_after_the_timeout(
        synthetic: SimulationResult, here: list[Path], tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setattr(figure_process, "_BOOTSTRAP", "import time; time.sleep(600)")
    monkeypatch.setattr(figure_process, "TIMEOUT_S", 1.0)
    start = time.perf_counter()
    with FigureProcess() as process:
        proc = process._proc
        assert proc is not None
        drawn = plot_result(synthetic, tmp_path / "hung", process=process)
    assert time.perf_counter() - start < 60.0  # the timeout, then this process's drawing
    assert proc.poll() is not None  # killed, not left behind
    _same_files(here, drawn)
    assert "did not finish within 1 s" in capsys.readouterr().err


def test_a_process_never_given_figures_is_stopped() -> None:
    with FigureProcess() as process:
        proc = process._proc
        assert proc is not None
    assert proc.poll() is not None


@pytest.mark.parametrize(("argv", "asks"), [
    (["simulate", "--compare-ideal", "--out", "run.h5", "--plot", "plots"], True),
    (["--debug", "simulate", "scene.toml", "--plot=plots"], True),
    (["simulate", "--out", "run.h5"], False),
    (["simulate", "--plot", "plots", "--help"], False),
    (["plot", "run.h5", "--out", "plots"], False),
    ([], False),
])
def test_the_command_line_that_starts_it_early(argv: list[str], asks: bool) -> None:
    assert _asks_for_figures(argv) is asks


def test_the_program_draws_its_figures_in_the_figure_process(tmp_path: Path) -> None:
    """`python -m jointplay.cli simulate --plot` (the program: the process starts before the
    packages import) writes every figure and says nothing about the figure process."""
    done = subprocess.run(
        [sys.executable, "-m", "jointplay.cli", "simulate", "--t-end", "0.02", "--no-verify",
         "--quiet", "--plot", "plots"], cwd=tmp_path, capture_output=True, text=True,
        timeout=600)
    assert done.returncode == 0, done.stderr
    assert "figure process" not in done.stderr, done.stderr
    names = sorted(p.name for p in (tmp_path / "plots").iterdir())
    assert names == sorted(["end_effector.png", "energy.png", "orbit_joint2.png",
                            "orbit_joint3.png", "contact_force.png",
                            "contact_timeline_joint2.png", "contact_timeline_joint3.png",
                            "eccentricity_ratio.png"])


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().split(")")[-1].split()[0]
    except OSError:
        return False
    return state != "Z"  # a zombie has ended; its parent (or init) has yet to reap it


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="reads /proc (Linux)")
@pytest.mark.slow
def test_ctrl_c_stops_the_figure_process_too(tmp_path: Path) -> None:
    """Ctrl-C (SIGINT to the whole process group) while the figure process loads matplotlib:
    the command ends with status 130, writes nothing, and leaves no figure process behind."""
    import os
    import signal

    proc = subprocess.Popen(
        [sys.executable, "-m", "jointplay.cli", "simulate", "--compare-ideal", "--out",
         "run.h5", "--plot", "plots"], cwd=tmp_path, stdout=subprocess.PIPE,
        stderr=subprocess.PIPE, start_new_session=True)
    children = Path(f"/proc/{proc.pid}/task/{proc.pid}/children")
    deadline = time.monotonic() + 30.0
    started: list[int] = []
    while not started and time.monotonic() < deadline and proc.poll() is None:
        started = [int(p) for p in children.read_text().split()]
        time.sleep(0.01)
    assert started, "no figure process was started"
    time.sleep(0.3)
    os.killpg(proc.pid, signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert b"jointplay: interrupted" in err
    deadline = time.monotonic() + 10.0
    while _alive(started[0]) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not _alive(started[0])
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def _fake_job(index: int, parent: int, die_in_copy: bool) -> Path:
    """A figure job without matplotlib: it saves known bytes as figures.save would (and,
    with ``die_in_copy``, ends the process at once when it runs in the forked copy)."""
    import os

    if die_in_copy and os.getpid() != parent:
        os._exit(3)
    path = Path(f"figure{index}.png")
    assert figure_module._captured is not None
    figure_module._captured.append((path, f"bytes of {index}".encode() * (index + 1)))
    return path


@pytest.mark.skipif(sys.platform != "linux", reason="forks")
@pytest.mark.parametrize("die_in_copy", [False, True])
def test_the_two_drawers_return_every_figure_in_job_order(die_in_copy: bool) -> None:
    """The figure process shares its jobs with a forked copy of itself; whatever each takes,
    and even when the copy dies mid-way (its jobs then drawn by the first), the figures come
    back once each, in job order, as one process would draw them."""
    import functools
    import os

    jobs = [functools.partial(_fake_job, i, os.getpid(), die_in_copy and i % 3 == 1)
            for i in range(9)]
    expected = figure_module.capture(
        [functools.partial(_fake_job, i, os.getpid(), False) for i in range(9)])
    assert figure_process.drawn_on_two_cpus(jobs) == expected


def test_a_stopped_process_is_killed_and_said_so(
        synthetic: SimulationResult, here: list[Path], tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    """The figure process stopped (SIGSTOP) while the command waits: after STOPPED_S it is
    killed, one line says why, and the figures are drawn here, not after TIMEOUT_S."""
    import os
    import signal

    monkeypatch.setattr(figure_process, "STOPPED_S", 1.0)
    start = time.perf_counter()
    with FigureProcess() as process:
        proc = process._proc
        assert proc is not None
        os.kill(proc.pid, signal.SIGSTOP)
        drawn = plot_result(synthetic, tmp_path / "stopped", process=process)
    assert time.perf_counter() - start < figure_process.TIMEOUT_S / 2
    assert proc.poll() is not None  # killed, not left behind
    _same_files(here, drawn)
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "it was stopped (SIGSTOP) for 1 s" in err, err
