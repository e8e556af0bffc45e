"""Hostile and careless use of the command line: every probe ends in one of four ways.

* exit 0 with finite, complete results;
* exit 2 naming the field at fault;
* exit 1 with a one-line cause;
* exit 130 (interrupted), leaving no file that looks complete and no ``failed`` sweep row.

No probe may show a traceback (that takes ``--debug``). Validation probes run the command in
this process (they stop before any model is loaded); interrupts, disk limits and signals run
it as a subprocess, which gets a real SIGINT at the phase named.
"""

from __future__ import annotations

import contextlib
import json
import os
import resource
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import h5py
import numpy as np
import pytest

from jointplay.cli import main
from jointplay.common.files import STALE_AGE_S, sweep_stale, temp_tag

ROOT = Path(__file__).resolve().parents[1]
PAPER_SCENE = (ROOT / "scenes" / "paper_4dof.toml").read_text(encoding="utf-8")
ONE_LINK = """name = "one_link"
[robot]
name = "probe_one_link"
[[robot.links]]
length = 0.3
mass = 1.0
inertia = 0.0075
com = 0.15
[[robot.joints]]
kind = "ideal"
[torques]
joint1 = "sin(2*pi*t)"
[run]
t_end = 0.2
"""


def paper_scene(tmp: Path, name: str = "scene.toml", **replace: str) -> Path:
    """The paper scene with lines replaced (``old line -> new line``), written to ``tmp``."""
    text = PAPER_SCENE
    for old, new in replace.items():
        assert old in text
        text = text.replace(old, new)
    path = tmp / name
    path.write_text(text, encoding="utf-8")
    return path


# ---- the contract ---------------------------------------------------------------------------

def check_contract(code: int, stderr: str) -> None:
    """What every probe must satisfy, whatever its outcome."""
    assert "Traceback" not in stderr, stderr
    assert code in (0, 1, 2, 130), (code, stderr)
    errors = [line for line in stderr.splitlines() if line.startswith("jointplay: error:")]
    if code in (1, 2):
        assert len(errors) == 1, stderr
    if code == 130:
        assert "jointplay: interrupted" in stderr


def bad_input(capsys: pytest.CaptureFixture[str], argv: list[str], field: str,
              *words: str) -> str:
    """Run in this process; expect exit 2 naming ``field`` (and the ``words``)."""
    code = main(argv)
    err = capsys.readouterr().err
    check_contract(code, err)
    assert code == 2, err
    line = next(line for line in err.splitlines() if line.startswith("jointplay: error:"))
    assert f"{field}:" in line, line
    for word in words:
        assert word in line, line
    return line


def no_temporaries(folder: Path) -> None:
    assert [p.name for p in folder.rglob("*.part")] == []


# Columns of the contact-phase table that are NaN, by definition, for a phase still in contact
# at the end of the run (no separation, so no exit speed or restitution).
_OPEN_PHASE_NAN = ("impact_separation_time", "impact_exit_speed", "impact_restitution")


def finite_hdf5(path: Path) -> None:
    """Every number in the file is finite (a complete result), except the columns a phase
    without separation leaves NaN, and only in those rows."""
    with h5py.File(path, "r") as fh:
        assert fh.attrs["format"] == "jointplay-result"
        separated = fh["impact_separated"][()] if "impact_separated" in fh else None

        def visit(name: str, obj: Any) -> None:
            if not (isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f"):
                return
            values = obj[()]
            if name in _OPEN_PHASE_NAN and separated is not None:
                assert np.all(np.isfinite(values[separated.astype(bool)])), name
                return
            assert np.all(np.isfinite(values)), name

        fh.visititems(visit)


# ---- bad input: exit 2 naming the field, before any work -------------------------------------

@pytest.mark.parametrize(("line", "new", "field", "word"), [
    ("output_step = 1.0e-3", "output_step = 1e-300", "run.output_step", "at least"),
    ("t_end = 2.0 ", "t_end = 1e7 ", "run.t_end", "at most"),
    ("output_step = 1.0e-3", "output_step = 1e-8", "run.output_step", "output samples"),
    ("rtol = 2.0e-6", "rtol = 1e-300", "run.rtol", "at least"),
    ("integrator = \"bdf\"", "integrator = \"bdf\"\nmax_steps = 10000000000000",
     "run.max_steps", "integer from 1"),
    ("step = 1.0e-5", "step = 1e-300", "run.step", "at least"),
])
def test_run_limits(tmp_path: Path, capsys: pytest.CaptureFixture[str], line: str, new: str,
                    field: str, word: str) -> None:
    scene = paper_scene(tmp_path, **{line: new})
    bad_input(capsys, ["simulate", str(scene), "--out", str(tmp_path / "r.h5")], field, word)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


def test_t_end_flag_limit(capsys: pytest.CaptureFixture[str]) -> None:
    bad_input(capsys, ["simulate", "--t-end", "1e7"], "--t-end", "at most")
    # the flag is fine, the number of outputs it implies is not: named where it is set
    bad_input(capsys, ["simulate", "--t-end", "1e4"], "run.output_step", "output samples")


def test_torque_not_finite_at_an_output_time(tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    scene = paper_scene(tmp_path, **{'joint2 = "4*sin(2*pi*t)"':
                                     'joint2 = "sin(2*pi*(t-0.3))/(t-0.3)"'})
    bad_input(capsys, ["simulate", str(scene), "--csv", str(tmp_path / "r.csv")],
              "torques.joint2", "t = 0.3 s", "nan")
    assert not (tmp_path / "r.csv").exists()


def test_torque_not_finite_at_zero_names_the_torque(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    scene = paper_scene(tmp_path, **{'joint3 = "2*sin(2*pi*t)"': 'joint3 = "log(t)"'})
    line = bad_input(capsys, ["simulate", str(scene)], "torques.joint3", "t = 0 s", "-inf")
    assert "stiffness" not in line and "contact" not in line


def test_constant_named_like_a_function(tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    scene = paper_scene(tmp_path, **{"[torques]": "[constants]\nsin = 1\n\n[torques]"})
    bad_input(capsys, ["simulate", str(scene)], "constants.sin", "function")


def test_robot_path_is_a_folder(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scene = tmp_path / "scene.toml"
    scene.write_text('robot = "/"\n', encoding="utf-8")
    line = bad_input(capsys, ["simulate", str(scene)], "robot", "is a folder")
    assert "not found" not in line


@pytest.mark.parametrize("kind", ["device", "folder", "huge", "binary"])
def test_scene_file_that_is_no_scene(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                     kind: str) -> None:
    path = tmp_path / "scene.toml"
    if kind == "device":
        path = Path("/dev/zero")
    elif kind == "folder":
        path.mkdir()
    elif kind == "huge":
        path.write_text("# " + "x" * (2 << 20) + "\n", encoding="utf-8")
    else:
        path.write_bytes(b"name = \"\xff\xfe\"\n")
    started = time.perf_counter()
    bad_input(capsys, ["simulate", str(path)], "(file)")
    assert time.perf_counter() - started < 10  # refused, not read until memory runs out


def test_fifo_scene_is_refused_without_blocking(tmp_path: Path) -> None:
    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)
    proc = run_cli(["simulate", str(fifo)], timeout=60)  # a hang fails by the timeout
    check_contract(proc.returncode, proc.stderr)
    assert proc.returncode == 2 and "not a regular file" in proc.stderr


@pytest.mark.parametrize(("flags", "field", "word"), [
    (["--out", "{scene}"], "--out", "input"),
    (["--csv", "{scene}"], "--csv", "input"),
    (["--out", "{tmp}/r", "--csv", "{tmp}/r"], "--csv", "same file"),
    (["--out", "{tmp}/no/such/r.h5"], "--out", "does not exist"),
    (["--out", "{tmp}"], "--out", "folder"),
    (["--out", "/dev/null"], "--out", "not a regular file"),
    (["--set", "friction.mu=nan"], "--set friction.mu", "finite"),
])
def test_output_paths_checked_before_work(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                          flags: list[str], field: str, word: str) -> None:
    scene = paper_scene(tmp_path)
    before = scene.read_bytes()
    argv = ["simulate", str(scene),
            *[f.format(scene=scene, tmp=tmp_path) for f in flags]]
    bad_input(capsys, argv, field, word)
    assert scene.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


def test_unwritable_out_folder_is_found_before_the_run(capsys: pytest.CaptureFixture[str]
                                                       ) -> None:
    folder = Path("/proc/self")  # takes no new file, whoever runs the tests (root included)
    if not folder.is_dir():
        pytest.skip("needs /proc")
    bad_input(capsys, ["simulate", "--out", str(folder / "run.h5")], "--out", "cannot write")


def test_sweep_sizes(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('scene = "default"\n[parameters."friction.mu"]\nstart = 0.0\n'
                     'stop = 0.2\nnum = 10000000000\n', encoding="utf-8")
    bad_input(capsys, ["sweep", str(sweep), "--out", str(tmp_path / "o")],
              "parameters.friction.mu.num", "at most")
    sweep.write_text('scene = "default"\n[run]\noutput_step = 1e-300\n'
                     '[parameters."friction.mu"]\nvalues = [0.0, 0.1]\n', encoding="utf-8")
    bad_input(capsys, ["sweep", str(sweep), "--out", str(tmp_path / "o")], "run.output_step")
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize(("flags", "field", "word"), [
    (["--duration", "1e9"], "--duration", "at most"),
    (["--duration", "1e4"], "--duration", "samples"),
    (["--hidden", "100000"], "--hidden", "from 1 to 4096"),
    (["--train", "100000"], "--train", "from 1 to 10000"),
    (["--train", "5000", "--validation", "5000", "--test", "1"],
     "--train/--validation/--test", "at most"),
    (["--lags", "1000,2"], "--lags", "from 1 to 100"),
    (["--window", "100000000"], "--window", "from 2 to"),
])
def test_identify_sizes(tmp_path: Path, capsys: pytest.CaptureFixture[str], flags: list[str],
                        field: str, word: str) -> None:
    out = tmp_path / "model"
    bad_input(capsys, ["identify", "--out", str(out), *flags], field, word)
    assert not out.exists()  # no empty model folder either


# ---- sweeps: damaged case files ----------------------------------------------------------------

def test_damaged_case_files_are_rerun(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "one.toml").write_text(ONE_LINK.replace("t_end = 0.2", "t_end = 0.05"),
                                       encoding="utf-8")
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('scene = "one.toml"\n[parameters."link1.mass"]\nvalues = [1.0, 2.0, 3.0]\n',
                     encoding="utf-8")
    out = tmp_path / "out"
    argv = ["sweep", str(sweep), "--out", str(out), "--workers", "0", "--quiet"]
    assert main(argv) == 0
    files = sorted((out / "cases").glob("*.json"))
    first = {f.name: json.loads(f.read_text()) for f in files}
    damage: list[Callable[[dict[str, Any]], Any]] = [
        lambda row: row.update(parameters="oops"),
        lambda row: row.update(impacts="3"),
        lambda row: row.update(max_position_error=float("nan")),
    ]
    for path, hurt in zip(files, damage, strict=True):
        row = json.loads(path.read_text())
        hurt(row)
        path.write_text(json.dumps(row))
    killed = out / "cases" / f".{files[0].name}.{temp_tag().split('p')[0]}p{_dead_pid()}.x.part"
    killed.write_text("{")  # the temporary file of a write that was killed
    assert main(argv) == 0
    assert not killed.exists()
    check_contract(0, capsys.readouterr().err)
    again = {f.name: json.loads(f.read_text()) for f in sorted((out / "cases").glob("*.json"))}
    assert again.keys() == first.keys()
    for name, row in again.items():
        assert row["status"] == "ok"
        assert row["parameters"] == first[name]["parameters"]
        assert row["max_position_error"] == first[name]["max_position_error"]
    import pyarrow.parquet as pq

    table = pq.read_table(out / "sweep.parquet").to_pydict()
    assert table["status"] == ["ok"] * 3


# ---- stale temporaries -------------------------------------------------------------------------

def _dead_pid() -> int:
    proc = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True)
    return int(proc.stdout)


def test_sweep_stale(tmp_path: Path) -> None:
    host = temp_tag().split("p")[0]
    dead = tmp_path / f".run.h5.{host}p{_dead_pid()}.abc.part"
    alive = tmp_path / f".run.h5.{temp_tag()}.def.part"  # this process: writing it now
    other_host = tmp_path / ".run.h5.jffffffp1.ghi.part"
    old_style = tmp_path / ".run.csv.k2j3h4.part"
    stale_dir = tmp_path / f".identify.{host}p{_dead_pid()}.jkl.part"
    stale_dir.mkdir()
    (stale_dir / "narx.json").write_text("{}")
    result = tmp_path / "run.h5"
    for path in (dead, alive, other_host, old_style, result):
        path.write_text("x")
    assert sweep_stale(tmp_path, "run.h5") == 1
    assert not dead.exists() and alive.exists() and other_host.exists()
    old = time.time() - STALE_AGE_S - 60
    os.utime(other_host, (old, old))
    os.utime(old_style, (old, old))
    assert sweep_stale(tmp_path) == 3  # the other host's, the old-style one, the folder
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([alive.name, result.name])


# ---- subprocess probes -------------------------------------------------------------------------

def run_cli(argv: list[str], *, env: dict[str, str] | None = None, timeout: float = 120,
            cwd: Path | None = None,
            preexec_fn: Callable[[], None] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "jointplay.cli", *argv], capture_output=True,
                          text=True, timeout=timeout, env={**os.environ, **(env or {})},
                          cwd=cwd, preexec_fn=preexec_fn)


def interrupt_when(argv: list[str], ready: str, delay: float, *, sig: int = signal.SIGINT,
                   code: str | None = None, on_stderr: bool = False, group: bool = False,
                   timeout: float = 60) -> tuple[int, str]:
    """Start the command, wait for ``ready`` in its output (stdout, or stderr where progress
    bars go), then ``delay`` s, then send it ``sig``. Returns the exit status and stderr.

    ``code`` replaces the command by a Python program (for probes that need a hook inside);
    ``group`` signals the command's whole process group, as Ctrl-C at a terminal does.
    """
    command = [sys.executable, "-c", code] if code else [sys.executable, "-m",
                                                          "jointplay.cli", *argv]
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env={**os.environ, "PYTHONUNBUFFERED": "1"},
                            start_new_session=group)
    watched = proc.stderr if on_stderr else proc.stdout
    assert watched is not None
    seen = b""
    try:
        while ready.encode() not in seen:
            chunk = os.read(watched.fileno(), 4096)
            assert chunk, f"the command ended before {ready!r}"
            seen += chunk
        time.sleep(delay)
        if group:
            os.killpg(proc.pid, sig)
        else:
            proc.send_signal(sig)
        _, err = proc.communicate(timeout=timeout)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL) if group else proc.kill()
            proc.wait()
    return proc.returncode, (seen.decode(errors="replace") if on_stderr else "") + err.decode(
        errors="replace")


def test_simulate_finite_and_complete(tmp_path: Path) -> None:
    # also: a temporary file left by a killed writer of the same output is removed
    host = temp_tag().split("p")[0]
    leftover = tmp_path / f".run.h5.{host}p{_dead_pid()}.abc.part"
    leftover.write_text("x")
    proc = run_cli(["simulate", "--t-end", "0.2", "--out", str(tmp_path / "run.h5"),
                    "--csv", str(tmp_path / "run.csv"), "--quiet"])
    check_contract(proc.returncode, proc.stderr)
    assert proc.returncode == 0
    finite_hdf5(tmp_path / "run.h5")
    table = np.loadtxt(tmp_path / "run.csv", delimiter=",", skiprows=1)
    assert table.shape[0] == 201 and np.all(np.isfinite(table))
    no_temporaries(tmp_path)


def test_interrupt_during_integration(tmp_path: Path) -> None:
    code, err = interrupt_when(["simulate", "--t-end", "500", "--out", str(tmp_path / "r.h5"),
                                "--csv", str(tmp_path / "r.csv")], "ready in", 0.5)
    check_contract(code, err)
    assert code == 130, err
    assert list(tmp_path.iterdir()) == []


_WRITE_HOOK = """
import os, signal, sys
import jointplay.results.netcdf as output
real = output.write_result
def interrupted(group, *args):
    os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C in the middle of the HDF5 write
    try:
        return real(group, *args)
    except KeyboardInterrupt:
        if {swallow}:  # as a library might: the run must still end as interrupted
            return None
        raise
output.write_result = interrupted
print("ready", flush=True)
from jointplay.cli import main
sys.exit(main(["simulate", "--t-end", "0.1", "--quiet", "--out", {out!r}]))
"""


@pytest.mark.parametrize("swallow", [False, True])
def test_interrupt_during_hdf5_write(tmp_path: Path, swallow: bool) -> None:
    out = str(tmp_path / "r.h5")
    code, err = interrupt_when([], "ready", 0.0, sig=0,
                               code=_WRITE_HOOK.format(swallow=swallow, out=out))
    check_contract(code, err)
    assert code == 130, err
    assert list(tmp_path.iterdir()) == []


def test_sigterm_leaves_no_temporary(tmp_path: Path) -> None:
    code, err = interrupt_when(["simulate", "--t-end", "500", "--out", str(tmp_path / "r.h5")],
                               "ready in", 0.3, sig=signal.SIGTERM)
    assert "Traceback" not in err
    assert code == 143, err
    assert list(tmp_path.iterdir()) == []


def _limit_file_size() -> None:
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write past the limit fails with EFBIG
    resource.setrlimit(resource.RLIMIT_FSIZE, (64 << 10, 64 << 10))


@pytest.fixture(scope="module")
def paper_compiled() -> None:
    """The paper model compiled in the cache, so that a probe with a file-size limit does
    not meet it compiling."""
    proc = run_cli(["simulate", "--t-end", "0.01", "--quiet"])
    assert proc.returncode == 0, proc.stderr


@pytest.mark.usefixtures("paper_compiled")
def test_output_that_does_not_fit(tmp_path: Path) -> None:
    out = tmp_path / "run.csv"
    proc = run_cli(["simulate", "--t-end", "0.3", "--csv", str(out), "--quiet"],
                   preexec_fn=_limit_file_size)
    check_contract(proc.returncode, proc.stderr)
    assert proc.returncode == 1
    assert f"{out}: cannot write: file too large" in proc.stderr
    assert list(tmp_path.iterdir()) == []


def test_unwritable_cache(tmp_path: Path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("x")
    proc = run_cli(["simulate", "--t-end", "0.01", "--quiet"],
                   env={"JOINTPLAY_CACHE": str(blocker / "cache")})
    check_contract(proc.returncode, proc.stderr)
    assert proc.returncode == 1
    assert str(blocker / "cache") in proc.stderr and "JOINTPLAY_CACHE" in proc.stderr


@pytest.fixture(scope="module")
def one_link_cache(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """A model cache holding a derived and compiled 1-link model, and its scene."""
    root = tmp_path_factory.mktemp("cache")
    scene = root / "one.toml"
    scene.write_text(ONE_LINK, encoding="utf-8")
    proc = run_cli(["simulate", str(scene), "--quiet"], env={"JOINTPLAY_CACHE": str(root / "c")})
    assert proc.returncode == 0, proc.stderr
    return root / "c", scene


@pytest.mark.parametrize("damage", ["model.c", pytest.param("layout.json", marks=pytest.mark.slow),
                                    pytest.param("robot.toml", marks=pytest.mark.slow),
                                    "model.so"])
def test_cache_heals(tmp_path: Path, one_link_cache: tuple[Path, Path], damage: str) -> None:
    import shutil

    cache, scene = one_link_cache
    shutil.copytree(cache, tmp_path / "c")
    env = {"JOINTPLAY_CACHE": str(tmp_path / "c")}
    if damage == "model.so":  # a library that does not load, with a matching marker
        entry = next((tmp_path / "c" / "build").iterdir())
        (entry / "model.so").write_bytes(b"not a library")
        marker = json.loads((entry / "complete.json").read_text())
        import hashlib

        marker["sha256"] = hashlib.sha256(b"not a library").hexdigest()
        (entry / "complete.json").write_text(json.dumps(marker))
    else:
        folder = next((tmp_path / "c" / "models").iterdir())
        if damage == "model.c":
            with open(folder / "model.c", "ab") as fh:
                fh.write(b"\xff")
        elif damage == "layout.json":
            (folder / "layout.json").write_text("{}")
        else:
            (folder / "robot.toml").write_text("links = [[[")
    out = tmp_path / "run.h5"
    proc = run_cli(["simulate", str(scene), "--quiet", "--out", str(out)], env=env)
    check_contract(proc.returncode, proc.stderr)
    assert proc.returncode == 0, proc.stderr
    notes = [line for line in proc.stderr.splitlines() if line.startswith("jointplay: note:")]
    assert len(notes) == 1 and "again" in notes[0], proc.stderr
    finite_hdf5(out)
    proc = run_cli(["simulate", str(scene), "--quiet"], env=env)
    assert proc.returncode == 0 and proc.stderr == "", proc.stderr  # healed for good


def long_sweep(tmp_path: Path) -> Path:
    """Two cases that each run long enough to be interrupted (the CVODES route, 2000 s)."""
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('scene = "default"\n[run]\nt_end = 2000.0\noutput_step = 0.01\n'
                     'integrator = "cvodes"\n[parameters."friction.mu"]\nvalues = [0.0, 0.1]\n',
                     encoding="utf-8")
    return sweep


def test_interrupted_sweep_keeps_no_row(tmp_path: Path) -> None:
    sweep = long_sweep(tmp_path)
    out = tmp_path / "out"
    code, err = interrupt_when(["sweep", str(sweep), "--out", str(out), "--workers", "0"],
                               "sweep ", 1.5)
    check_contract(code, err)
    assert code == 130, err
    assert list((out / "cases").glob("*.json")) == []  # not done, so not failed: rerun
    assert not (out / "sweep.parquet").exists()
    no_temporaries(out)


@pytest.mark.slow
@pytest.mark.parametrize(("delay", "group", "busy_port"),
                         [(0.5, True, False), (5.0, True, False), (5.0, False, True)])
def test_interrupted_sweep_with_workers_keeps_no_row(tmp_path: Path, delay: float,
                                                     group: bool, busy_port: bool) -> None:
    """Ctrl-C while the local cluster starts, and while its workers run cases: sent to the
    whole process group (a terminal) and to the sweep's process alone; once with the usual
    port of a cluster's HTTP server (8787) taken, as by another cluster running."""
    sweep = long_sweep(tmp_path)
    out = tmp_path / "out"
    with contextlib.ExitStack() as stack:
        if busy_port:
            sock = stack.enter_context(socket.socket())
            with contextlib.suppress(OSError):  # taken already: the same condition
                sock.bind(("", 8787))
                sock.listen()
        code, err = interrupt_when(["sweep", str(sweep), "--out", str(out), "--workers", "2"],
                                   "sweep ", delay, group=group)
    check_contract(code, err)
    assert code == 130, err
    assert "UserWarning" not in err
    assert list((out / "cases").glob("*.json")) == []
    no_temporaries(out)


@pytest.mark.parametrize("workers", ["1", "2"])
def test_interrupted_identify_leaves_no_model(tmp_path: Path, workers: str) -> None:
    out = tmp_path / "model"
    code, err = interrupt_when(["identify", "--out", str(out), "--duration", "20", "--train",
                                "2", "--validation", "1", "--test", "1", "--workers", workers],
                               "simulating", 1.0, on_stderr=True)
    check_contract(code, err)
    assert code == 130, err
    assert not out.exists()


@pytest.mark.slow
def test_interrupted_control_writes_nothing(tmp_path: Path) -> None:
    model = tmp_path / "model"
    # Two training runs: with one, the model on the accurate plant is a hair worse than
    # persistence on validation and refused.
    proc = run_cli(["identify", "--out", str(model), "--train", "2", "--validation", "1",
                    "--test", "1", "--duration", "0.3", "--iterations", "1,1", "--workers", "1",
                    "--quiet", "--preset", "paper"], timeout=300)
    assert proc.returncode == 0, proc.stderr
    out = tmp_path / "runs.h5"
    code, err = interrupt_when(["control", "--model", str(model), "--out", str(out)],
                               "scene ", 1.0)
    check_contract(code, err)
    assert code == 130, err
    assert not out.exists()
    no_temporaries(tmp_path)


@pytest.mark.parametrize(("error", "cause"), [
    (OSError(28, "No space left on device"),
     "no space left on device; free some space or write elsewhere"),
    (OSError("Unable to synchronously create file (unable to open file: name = 'r.h5', "
             "errno = 30, error message = 'Read-only file system')"),
     "read-only file system; write elsewhere"),
    (PermissionError(13, "Permission denied"),
     "permission denied; write elsewhere or change the permissions"),
])
def test_io_errors_are_one_line(error: OSError, cause: str) -> None:
    """The causes an I/O error is reported with, h5py's errno-in-the-text included."""
    from jointplay.common.files import file_error

    message = str(file_error("/data/run.h5", error))
    assert message == f"/data/run.h5: cannot write: {cause}"
