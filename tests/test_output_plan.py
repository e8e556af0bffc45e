"""Every command's output plan and all-or-nothing writes, probed with hostile paths and faults.

Each probe ends in exactly one of: exit 0 with complete files; exit 2 naming the clashing
paths before any work; exit 1 with one line naming the path and the cause, nothing left
behind. Clashes are probed through ``main`` with the work replaced by a trap (reaching it
fails the test); faults are injected into the low-level steps every write goes through
(``os.fsync`` of each finished temporary, ``write`` of the HDF5 bytes, the final renames).
"""

from __future__ import annotations

import errno
import itertools
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import jointplay
from jointplay.cli import main
from jointplay.common import files

REPO = Path(__file__).resolve().parents[1]
WEAR_SCENE = REPO / "scenes" / "paper_4dof_wear.toml"


class WorkStarted(Exception):
    """Raised by the trap standing in for the work: the command got past its checks."""


def _trap(*args: Any, **kwargs: Any) -> Any:
    raise WorkStarted


def snapshot(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() if p.is_file() else b"<dir>"
            for p in sorted(folder.rglob("*"))}


def refused_before_work(capsys: pytest.CaptureFixture[str], argv: list[str], folder: Path,
                        *names: str) -> str:
    """``argv`` exits 2 before any work, naming each of ``names``, and changes no file."""
    before = snapshot(folder)
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2, err
    line = err.strip()
    assert "\n" not in line and "Traceback" not in line, err
    for name in names:
        assert name in line, (name, line)
    assert snapshot(folder) == before
    return line


# ---- simulate: every pair of outputs, every output onto an input ----------------------------

def wear_scene_with_table(folder: Path) -> tuple[Path, Path]:
    """The wear scene (it has a wear table too) with its torques from a table file."""
    text = WEAR_SCENE.read_text(encoding="utf-8")
    start, end = text.index("[torques]"), text.index("[initial]")
    scene = folder / "scene.toml"
    scene.write_text(text[:start] + '[torques]\ntable = "torques.csv"\n\n' + text[end:],
                     encoding="utf-8")
    table = folder / "torques.csv"
    table.write_text("t,joint2,joint3\n0,0,0\n10,1,1\n", encoding="utf-8")
    return scene, table


# slot -> (flag value for a clash on the file named ``x``, or None when no name fits)
def _slot(slot: str, x: str) -> list[str] | None:
    if slot == "out":
        return ["--out", x]
    if slot == "csv":
        return ["--csv", x]
    if slot == "impacts":  # derived from --csv
        return ["--csv", x.removesuffix(".impacts.csv") + ".csv"] if x.endswith(
            ".impacts.csv") else None
    if slot == "wear":  # derived from --csv
        return ["--csv", x.removesuffix(".wear.csv") + ".csv"] if x.endswith(
            ".wear.csv") else None
    if slot == "figure":  # inside --plot
        return ["--plot", str(Path(x).parent)] if x.endswith("/plots/energy.png") else None
    if slot == "animate":
        return ["--animate", x]
    raise AssertionError(slot)


SLOTS = ("out", "csv", "impacts", "wear", "figure", "animate")
_FROM_CSV = {"csv", "impacts", "wear"}  # one flag: they cannot be given twice


def _name_for(slots: tuple[str, ...]) -> str:
    for slot, name in (("impacts", "r.impacts.csv"), ("wear", "r.wear.csv"),
                       ("figure", "plots/energy.png")):
        if slot in slots:
            return name
    return "r.gif"


# Pairs a single file can be both of (a figure is never named *.impacts.csv).
OUTPUT_PAIRS = [(a, b) for a, b in itertools.combinations(SLOTS, 2)
                if not {a, b} <= _FROM_CSV
                and _slot(a, "/d/" + _name_for((a, b))) and _slot(b, "/d/" + _name_for((a, b)))]


@pytest.fixture
def no_work(monkeypatch: pytest.MonkeyPatch) -> None:
    import jointplay.sim

    monkeypatch.setattr(jointplay.sim, "load_scene_model", _trap)
    monkeypatch.setattr(jointplay.sim, "simulate", _trap)


@pytest.mark.usefixtures("no_work")
@pytest.mark.parametrize(("first", "second"), OUTPUT_PAIRS)
def test_simulate_outputs_that_coincide(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                        first: str, second: str) -> None:
    scene, _ = wear_scene_with_table(tmp_path)
    x = str(tmp_path / _name_for((first, second)))
    a, b = _slot(first, x), _slot(second, x)
    assert a is not None and b is not None
    if first == "figure" or second == "figure":
        (tmp_path / "plots").mkdir()
    line = refused_before_work(capsys, ["simulate", str(scene), *a, *b], tmp_path,
                               a[0], b[0], Path(x).name)
    assert "same file" in line or "lies in" in line


@pytest.mark.usefixtures("no_work")
@pytest.mark.parametrize("input_kind", ["scene", "torque table"])
@pytest.mark.parametrize("slot", SLOTS)
def test_simulate_output_onto_an_input(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                       slot: str, input_kind: str) -> None:
    """Each output, given or derived, refused where it would be the scene or its table;
    links and ``..`` do not hide it."""
    scene, table = wear_scene_with_table(tmp_path)
    name = {"impacts": "in.impacts.csv", "wear": "in.wear.csv",
            "figure": "plots/energy.png"}.get(slot, "in.toml")
    target = tmp_path / name
    target.parent.mkdir(exist_ok=True)
    if input_kind == "scene":
        text = scene.read_text(encoding="utf-8").replace('"torques.csv"', f'"{table}"')
        scene.unlink()
        target.write_text(text, encoding="utf-8")
        scene = target
    else:
        shutil.move(table, target)
        text = scene.read_text(encoding="utf-8").replace("torques.csv", name)
        scene.write_text(text, encoding="utf-8")
    (tmp_path / "sub").mkdir()
    spelled = str(tmp_path / "sub" / ".." / name)  # the same file, spelled otherwise
    flags = (["--plot", str(tmp_path / "sub" / ".." / "plots")] if slot == "figure"
             else _slot(slot, spelled))
    assert flags is not None
    line = refused_before_work(capsys, ["simulate", str(scene), *flags], tmp_path,
                               flags[0], f"input {input_kind}", Path(name).name)
    assert "overwrite the input" in line or "would hold the input" in line


@pytest.mark.usefixtures("no_work")
def test_a_link_to_an_input_is_the_input(tmp_path: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    scene, _ = wear_scene_with_table(tmp_path)
    (tmp_path / "link.h5").symlink_to(scene)
    os.link(scene, tmp_path / "hard.h5")
    for out in ("link.h5", "hard.h5"):
        refused_before_work(capsys, ["simulate", str(scene), "--out", str(tmp_path / out)],
                            tmp_path, out, "input scene")


# ---- the other commands -----------------------------------------------------------------------

def test_inspect_and_derive_never_write_over_the_robot(tmp_path: Path, monkeypatch:
                                                       pytest.MonkeyPatch,
                                                       capsys: pytest.CaptureFixture[str]
                                                       ) -> None:
    import jointplay.derive

    monkeypatch.setattr(jointplay.derive, "derive", _trap)
    monkeypatch.setattr(jointplay.derive, "write_generated", _trap)
    robot = tmp_path / "robot.toml"
    shutil.copy(REPO / "generated" / "paper_4dof" / "robot.toml", robot)
    os.chdir(tmp_path)
    refused_before_work(capsys, ["inspect", "robot.toml", "--out", "robot.toml"], tmp_path,
                        "--out", "input robot")
    refused_before_work(capsys, ["derive", "robot.toml", "--out", "."], tmp_path,
                        "--out", "robot.toml", "input robot")
    shutil.copy(robot, tmp_path / "model.c")
    refused_before_work(capsys, ["derive", "model.c", "--out", "."], tmp_path,
                        "model.c", "input robot")


@pytest.mark.parametrize(("flags", "names"), [
    (["--out", "{scene}"], ["--out", "input scene"]),
    (["--out", "{tmp}/model/runs.h5"], ["--out", "input --model"]),
    (["--out", "{tmp}/plots/runs.h5", "--plot", "{tmp}/plots"], ["--out", "--plot"]),
    (["--plot", "{tmp}/model"], ["--plot", "input --model"]),
])
def test_control_outputs(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                         monkeypatch: pytest.MonkeyPatch, flags: list[str],
                         names: list[str]) -> None:
    import jointplay.cli.control as control

    monkeypatch.setattr(control, "load_narx", _trap)  # checked before the model is read
    scene, _ = wear_scene_with_table(tmp_path)
    (tmp_path / "model").mkdir()
    argv = ["control", str(scene), "--model", str(tmp_path / "model"),
            *[f.format(scene=scene, tmp=tmp_path) for f in flags]]
    refused_before_work(capsys, argv, tmp_path, *names)


@pytest.mark.parametrize("name", ["report.md", "metrics.json", "datasets.h5", "narx.json"])
def test_identify_never_writes_over_its_scene(tmp_path: Path, name: str,
                                              capsys: pytest.CaptureFixture[str],
                                              monkeypatch: pytest.MonkeyPatch) -> None:
    import jointplay.cli.identify as identify

    monkeypatch.setattr(identify, "identify_model", _trap)
    scene, _ = wear_scene_with_table(tmp_path)
    shutil.move(scene, tmp_path / name)
    refused_before_work(capsys, ["identify", str(tmp_path / name), "--out", str(tmp_path)],
                        tmp_path, "--out", name, "input scene")


@pytest.mark.parametrize("name", ["sweep.json", "sweep.parquet", "cases/s.toml",
                                  "plots/s.png"])
def test_sweep_never_writes_over_its_sweep_file(tmp_path: Path, name: str,
                                                capsys: pytest.CaptureFixture[str],
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    import jointplay.cli.sweep as sweep

    monkeypatch.setattr(sweep, "run_sweep", _trap)
    text = (REPO / "scenes" / "sweep_clearance.toml").read_text(encoding="utf-8")
    shutil.copy(REPO / "scenes" / "paper_4dof.toml", tmp_path / "paper_4dof.toml")
    target = tmp_path / "out" / name
    target.parent.mkdir(parents=True)
    target.write_text(text.replace('"paper_4dof.toml"', f'"{tmp_path / "paper_4dof.toml"}"'),
                      encoding="utf-8")
    refused_before_work(capsys, ["sweep", str(target), "--out", str(tmp_path / "out")],
                        tmp_path, "--out", "input sweep")


def test_bench_and_study_never_write_over_their_scene(tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str],
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    import jointplay.cli.bench as bench
    import jointplay.cli.study as study

    monkeypatch.setattr(bench, "fidelity", _trap)
    monkeypatch.setattr(bench, "prepare_out_dir", _trap)
    monkeypatch.setattr(study, "identify_models", _trap)
    scene, _ = wear_scene_with_table(tmp_path)
    report = tmp_path / "report"
    report.mkdir()
    shutil.move(scene, report / "fidelity.md")
    text = (report / "fidelity.md").read_text(encoding="utf-8")
    (report / "fidelity.md").write_text(text.replace('"torques.csv"',
                                                     f'"{tmp_path / "torques.csv"}"'),
                                        encoding="utf-8")
    refused_before_work(capsys, ["bench", "fidelity", str(report / "fidelity.md"), "--out",
                                 str(report)], tmp_path, "--out", "input scene")
    shutil.move(report / "fidelity.md", report / "study.md")
    refused_before_work(capsys, ["control-study", str(report / "study.md"), "--out",
                                 str(report)], tmp_path, "--out", "input scene", "study.md")


def test_plan_refuses_an_output_inside_an_input_folder(tmp_path: Path) -> None:
    plan = files.OutputPlan()
    plan.input("--model", tmp_path)
    plan.file("--out", tmp_path / "deep" / "r.h5")
    with pytest.raises(jointplay.DescriptionError, match="inside the input --model"):
        plan.check()
    fine = files.OutputPlan()
    fine.input("scene", tmp_path / "s.toml")
    fine.folder("--plot", tmp_path, pattern="*.png")
    fine.file("--out", tmp_path / "r.h5")  # beside the figures, not one of them
    fine.check()


# ---- faults while writing: exit 1, one line, nothing left -------------------------------------

@pytest.fixture(scope="module")
def short_run() -> jointplay.SimulationResult:
    """A real run with its ideal counterpart, computed once for the write probes."""
    scene = jointplay.default_scene().with_run(t_end=0.01)
    return jointplay.simulate(scene, compare_ideal=True, quiet=True)


class Faults:
    """Counts the low-level steps of writing and fails the n-th of one kind."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch, kind: str, at: int,
                 error: int = errno.ENOSPC, name: str = "") -> None:
        self.calls = {"fsync": 0, "replace": 0}
        self.kind, self.at, self.error, self.name = kind, at, error, name
        real_fsync, real_replace = os.fsync, os.replace

        def fsync(fd: int) -> None:
            # with ``name``: only the temporaries of that output count
            if not name or f".{name}." in os.readlink(f"/proc/self/fd/{fd}"):
                self._step("fsync")
            real_fsync(fd)

        def replace(src: Any, dst: Any) -> None:
            self._step("replace")
            real_replace(src, dst)

        monkeypatch.setattr(files.os, "fsync", fsync)
        monkeypatch.setattr(files.os, "replace", replace)

    def _step(self, kind: str) -> None:
        self.calls[kind] += 1
        if kind == self.kind and self.calls[kind] == self.at:
            raise OSError(self.error, os.strerror(self.error))


def _simulate_argv(folder: Path, plot: bool = True) -> list[str]:
    return ["simulate", "--out", str(folder / "run.h5"), "--csv", str(folder / "run.csv"),
            *(["--plot", str(folder / "plots")] if plot else []), "--quiet",
            "--no-verify"]  # the writes are under test here, not the accuracy check


@pytest.fixture
def canned(monkeypatch: pytest.MonkeyPatch, short_run: jointplay.SimulationResult) -> None:
    """simulate returns the stored run at once: the probes exercise the writing only."""
    import jointplay.sim

    class Ready:
        name, coordinates = "paper_4dof", short_run.coordinate_names

    monkeypatch.setattr(jointplay.sim, "load_scene_model", lambda scene: Ready())
    monkeypatch.setattr(jointplay.sim, "simulate", lambda *a, **k: short_run)


def _probe(folder: Path, kind: str, at: int, plot: bool, monkeypatch: pytest.MonkeyPatch,
           capsys: pytest.CaptureFixture[str]) -> None:
    """A fault at the ``at``-th step of ``kind``: exit 1, one line naming a file of the run in
    ``folder`` and the cause, and the folder exactly as it was."""
    before = snapshot(folder)
    Faults(monkeypatch, kind, at)
    code = main(_simulate_argv(folder, plot))
    err = capsys.readouterr().err.strip()
    assert code == 1, (kind, at, err)
    assert "\n" not in err and "no space left on device" in err, err
    assert err.startswith(f"jointplay: error: {folder}"), err
    assert snapshot(folder) == before, (kind, at)  # nothing new, nothing half-new


@pytest.mark.usefixtures("canned")
def test_simulate_writes_everything_or_nothing(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str],
                                               monkeypatch: pytest.MonkeyPatch,
                                               short_run: jointplay.SimulationResult) -> None:
    """A full disk at each write (the results file, the phase table, the samples) and at
    each final rename, into an empty folder and over a previous complete set: exit 1, one
    line naming the file and the cause, no new file, the previous set as it was."""
    complete = tmp_path / "complete"
    complete.mkdir()
    probe = Faults(monkeypatch, "none", 0)
    assert main(_simulate_argv(complete, plot=False)) == 0
    assert probe.calls["fsync"] == probe.calls["replace"] == len(list(complete.iterdir())) == 3
    assert_same_run(short_run, jointplay.read(complete / "run.h5"))
    capsys.readouterr()
    for kind in ("fsync", "replace"):
        for at in (1, 2, 3):
            fresh = tmp_path / f"{kind}{at}"
            fresh.mkdir()
            _probe(fresh, kind, at, False, monkeypatch, capsys)
            previous = tmp_path / f"{kind}{at}previous"
            shutil.copytree(complete, previous)
            _probe(previous, kind, at, False, monkeypatch, capsys)


@pytest.mark.slow
@pytest.mark.usefixtures("canned")
def test_figures_are_part_of_all_or_nothing(tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str],
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """With --plot: eleven files (results, CSV, impacts table, eight figures); a full disk at
    the first figure, or at the last rename over a previous set, leaves the folder as it was
    (the figure folder it created removed)."""
    complete = tmp_path / "complete"
    complete.mkdir()
    probe = Faults(monkeypatch, "none", 0)
    assert main(_simulate_argv(complete)) == 0
    n_files = len([p for p in complete.rglob("*") if p.is_file()])
    assert probe.calls["fsync"] == probe.calls["replace"] == n_files == 11
    capsys.readouterr()
    fresh = tmp_path / "fresh"
    fresh.mkdir()
    _probe(fresh, "fsync", 4, True, monkeypatch, capsys)
    assert list(fresh.iterdir()) == []  # no empty plots/ either
    previous = tmp_path / "previous"
    shutil.copytree(complete, previous)
    _probe(previous, "replace", 10, True, monkeypatch, capsys)


def assert_same_run(a: jointplay.SimulationResult, b: jointplay.SimulationResult) -> None:
    from test_output import assert_same

    assert_same(a, b)


@pytest.mark.parametrize("error", [errno.ENOSPC, errno.EDQUOT, errno.EROFS, errno.EIO])
def test_hdf5_bytes_that_cannot_be_written(tmp_path: Path, error: int,
                                           monkeypatch: pytest.MonkeyPatch,
                                           short_run: jointplay.SimulationResult) -> None:
    """The results file's bytes go out through a plain write: its error is an OSError of
    Python's, reported naming the file, never a crash inside HDF5."""
    import builtins

    real_open = builtins.open

    class Full:
        def __init__(self, fh: Any) -> None:
            self.fh = fh

        def write(self, data: bytes) -> int:
            self.fh.write(data[: len(data) // 2])
            raise OSError(error, os.strerror(error))

        def __enter__(self) -> Full:
            return self

        def __exit__(self, *exc: Any) -> None:
            self.fh.close()

    def opening(path: Any, mode: str = "r", *args: Any, **kwargs: Any) -> Any:
        fh = real_open(path, mode, *args, **kwargs)
        return Full(fh) if mode == "wb" and ".part" in str(path) else fh

    monkeypatch.setattr(builtins, "open", opening)
    with pytest.raises(jointplay.JointplayError) as info:
        from jointplay.results.write import write_hdf5

        write_hdf5(short_run, tmp_path / "run.h5")
    assert str(info.value).startswith(f"{tmp_path / 'run.h5'}: cannot write: "
                                      f"{os.strerror(error).lower()}")
    assert list(tmp_path.iterdir()) == []


def test_control_and_identify_files_fail_cleanly(tmp_path: Path,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    """The control runs' file and the identification data: a full disk at the write gives
    the one-line error and no file."""
    from jointplay.neural.control.loop import Run
    from jointplay.neural.identify.datasets import read_datasets, write_datasets
    from jointplay.neural.identify.trajectories import ARRAYS, Trajectory
    from jointplay.neural.study.comparison import Comparison, write_runs

    t = np.linspace(0.0, 0.1, 11)
    run = Run("PD", t, np.zeros((11, 2)), np.ones((11, 1)), np.zeros((11, 1)), 0, 0.1,
              flags=np.zeros((11, 5)))
    comparison = Comparison({"PD": run}, np.zeros((11, 2)), {"PD": {"rms": 1.0}}, 0, 1.0)
    outputs = (("q2", "rad"), ("tip_x", "m"))
    write_runs(tmp_path / "runs.h5", comparison, {"scene": "s"}, outputs)
    import xarray as xr

    with xr.open_dataset(tmp_path / "runs.h5", group="PD") as pd_run:
        assert pd_run["output_q2"].attrs["units"] == "rad"
        assert pd_run["torque"].attrs["units"] == "N m"
    arrays = {name: np.zeros((11, 1)) for name in ARRAYS}
    trajectory = Trajectory("train", "chirp", 1, description={}, **arrays)
    write_datasets(tmp_path / "datasets.h5", [trajectory], {"m": 1})
    assert len(read_datasets(tmp_path / "datasets.h5")[0]) == 1
    for name, write in (("runs.h5", lambda p: write_runs(p, comparison, {}, outputs)),
                        ("datasets.h5", lambda p: write_datasets(p, [trajectory], {}))):
        folder = tmp_path / f"full-{name}"
        folder.mkdir()
        Faults(monkeypatch, "fsync", 1)
        with pytest.raises(jointplay.JointplayError, match="no space left on device"):
            write(folder / name)
        assert list(folder.iterdir()) == []


# ---- a real full filesystem -------------------------------------------------------------------

def _in_small_filesystem(size: str, argv: list[str], folder: Path) -> subprocess.CompletedProcess:
    """Run ``jointplay argv`` with ``folder`` a tmpfs of ``size`` in a private mount
    namespace, then list what the command left there."""
    script = (f"mount -t tmpfs -o size={size} tmpfs {folder} || exit 99; "
              f"{sys.executable} -m jointplay.cli {' '.join(argv)}; rc=$?; "
              f"echo LEFT; ls -A {folder}; exit $rc")
    return subprocess.run(["unshare", "-rm", "sh", "-c", script], capture_output=True,
                          text=True, timeout=600, check=False)


@pytest.mark.parametrize(("size", "cause"), [("64k", "results file"), ("320k", "csv")])
def test_full_filesystem(tmp_path: Path, size: str, cause: str) -> None:
    """On a real full disk: the results file does not fit (64 KiB), or it fits and the CSV
    beside it does not (320 KiB): exit 1, one line, and nothing left on the disk."""
    if shutil.which("unshare") is None:
        pytest.skip("needs unshare to mount a small filesystem")
    folder = tmp_path / "small"
    folder.mkdir()
    check = subprocess.run(["unshare", "-rm", "sh", "-c",
                            f"mount -t tmpfs -o size=64k tmpfs {folder}"],
                           capture_output=True, check=False)
    if check.returncode != 0:
        pytest.skip("mounting a filesystem is not permitted here")
    proc = _in_small_filesystem(size, ["simulate", "--t-end", "0.3", "--quiet",
                                       "--out", str(folder / "run.h5"),
                                       "--csv", str(folder / "run.csv")], folder)
    err = proc.stderr.strip()
    assert proc.returncode == 1, (proc.returncode, proc.stderr)
    assert "\n" not in err and "no space left on device" in err, err
    assert proc.stdout.split("LEFT")[-1].strip() == ""


def test_a_plan_owns_only_its_outputs(tmp_path: Path) -> None:
    """Writes outside the plan (the model cache) are not held back until the end."""
    plan = files.OutputPlan()
    plan.file("--out", tmp_path / "r.txt")
    with files.all_or_nothing(plan):
        files.atomic_write_text(tmp_path / "cache.txt", "now")
        assert (tmp_path / "cache.txt").read_text() == "now"
        files.atomic_write_text(tmp_path / "r.txt", "later")
        assert not (tmp_path / "r.txt").exists()
    assert (tmp_path / "r.txt").read_text() == "later"


@pytest.mark.slow
def test_sweep_table_and_figures_all_or_nothing(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str],
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    """A full disk at the last figure (the table is complete by then): exit 1, one line,
    neither the table nor any figure;
    the finished cases stay (a sweep resumes from them) and the next run completes."""
    sweep = tmp_path / "tiny.toml"
    sweep.write_text(f'name = "tiny"\nscene = "{REPO / "scenes" / "paper_4dof.toml"}"\n'
                     'mode = "product"\n[run]\nt_end = 0.005\n'
                     '[parameters."joint2.clearance"]\nvalues = [5.0e-5, 1.0e-4]\n',
                     encoding="utf-8")
    argv = ["sweep", str(sweep), "--workers", "0", "--series", "--quiet"]
    complete = tmp_path / "complete"
    probe = Faults(monkeypatch, "none", 0, name="png")
    assert main([*argv, "--out", str(complete)]) == 0
    last = probe.calls["fsync"]  # the figures' writes (the compile cache's do not count)
    figures = sorted(p.name for p in (complete / "plots").iterdir())
    assert len(figures) == last > 0 and (complete / "sweep.parquet").is_file()
    capsys.readouterr()
    out = tmp_path / "full"
    Faults(monkeypatch, "fsync", last, name="png")
    assert main([*argv, "--out", str(out)]) == 1
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and err.startswith(f"jointplay: error: {out / 'plots'}"), err
    assert "no space left on device" in err
    assert sorted(p.name for p in out.iterdir()) == ["cases", "series", "sweep.json"]
    assert len(list((out / "cases").iterdir())) == len(list((out / "series").iterdir())) == 2
    Faults(monkeypatch, "none", 0)
    assert main([*argv, "--out", str(out)]) == 0
    assert sorted(p.name for p in (out / "plots").iterdir()) == figures
    assert jointplay.read(next((out / "series").iterdir())).ideal is not None


@pytest.mark.parametrize("failure", [OSError(errno.EIO, "I/O error"), KeyboardInterrupt()])
def test_a_rename_that_fails_puts_everything_back(tmp_path: Path, failure: BaseException,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    """An error or a Ctrl-C between the final renames: the earlier files are back, the new
    ones gone, no temporary stays."""
    plan = files.OutputPlan()
    names = ["a.txt", "b.txt", "c.txt"]
    for name in names:
        plan.file("--out", tmp_path / name)
    (tmp_path / "a.txt").write_text("old a")
    (tmp_path / "c.txt").write_text("old c")
    real_replace, calls = os.replace, []

    def replace(src: Any, dst: Any) -> None:
        calls.append(dst)
        if len(calls) == 3:
            raise failure
        real_replace(src, dst)

    monkeypatch.setattr(files.os, "replace", replace)
    expected = files.FileError if isinstance(failure, OSError) else KeyboardInterrupt
    with pytest.raises(expected), files.all_or_nothing(plan):
        for name in names:
            files.atomic_write_text(tmp_path / name, f"new {name[0]}")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt", "c.txt"]
    assert (tmp_path / "a.txt").read_text() == "old a"
    assert (tmp_path / "c.txt").read_text() == "old c"


@pytest.mark.slow
def test_control_writes_everything_or_nothing(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str],
                                              monkeypatch: pytest.MonkeyPatch,
                                              identified: tuple[Path, Any, Any]) -> None:
    """`control --out --plot` on the session's model: the runs file opens in xarray with a
    group per controller; a full disk at the runs file (written after the figures) leaves
    neither it nor any figure, and no empty --plot folder."""
    import xarray as xr

    model, _, _ = identified
    scene = tmp_path / "short.toml"
    scene.write_text((REPO / "scenes" / "paper_4dof.toml").read_text(encoding="utf-8")
                     .replace("t_end = 2.0", "t_end = 0.1"), encoding="utf-8")
    argv = ["control", str(scene), "--model", str(model), "--quiet"]
    probe = Faults(monkeypatch, "none", 0)
    code = main([*argv, "--out", str(tmp_path / "runs.h5"), "--plot", str(tmp_path / "plots")])
    assert code in (0, 3), capsys.readouterr().err
    with xr.open_dataset(tmp_path / "runs.h5") as root:
        controllers = json.loads(root.attrs["controllers"])
        assert root["time"].attrs["units"] == "s" and "output_q2" in root
    with xr.open_dataset(tmp_path / "runs.h5", group=controllers[0]) as run:
        assert run["torque"].attrs["units"] == "N m"
    assert probe.calls["fsync"] > 1
    capsys.readouterr()
    full = tmp_path / "full"
    full.mkdir()
    Faults(monkeypatch, "fsync", 1, name="runs.h5")
    code = main([*argv, "--out", str(full / "runs.h5"), "--plot", str(full / "plots")])
    err = capsys.readouterr().err.strip()
    assert code == 1 and "\n" not in err and "no space left on device" in err, err
    assert list(full.iterdir()) == []


def test_identify_model_folder_all_or_nothing(tmp_path: Path,
                                              monkeypatch: pytest.MonkeyPatch) -> None:
    """The model folder's files are staged and moved in together: a full disk at any of
    them is one error naming the file in the model folder (not its staging copy), and a
    folder the run created is gone; without a fault every file is in place."""
    import jointplay.neural.identify.pipeline as ident
    from jointplay.neural.model.narx import MODEL_FILE

    names = [ident.DATASETS_FILE, ident.METRICS_FILE, ident.REPORT_FILE, ident.ARX_FILE,
             ident.LPV_FILE, MODEL_FILE]

    runs = itertools.count()

    def staged(scene: Any, stage: Path, *args: Any) -> dict[str, Any]:
        run = next(runs)  # each run's files differ from the last's
        for name in names:
            files.atomic_write_text(stage / name, f"{name} of run {run}")
        return {}

    monkeypatch.setattr(ident, "_identify_into", staged)
    config = ident.IdentifyConfig()
    for name in names:
        out = tmp_path / f"full-{name}"
        Faults(monkeypatch, "fsync", 1, name=name)
        with pytest.raises(files.FileError) as info:
            ident.identify(jointplay.default_scene(), out, config, quiet=True)
        assert info.value.path == str(out / name)
        assert not out.exists()
    for k, name in enumerate(names):  # a rename that fails: the earlier model stays whole
        out = tmp_path / f"rename-{name}"
        Faults(monkeypatch, "none", 0)
        ident.identify(jointplay.default_scene(), out, config, quiet=True)
        before = snapshot(out)
        Faults(monkeypatch, "replace", len(names) + k + 1)  # after the staging writes
        with pytest.raises(files.FileError):
            ident.identify(jointplay.default_scene(), out, config, quiet=True)
        # the model file goes first (never beside another run's data); the rest as before
        assert snapshot(out) == {n: v for n, v in before.items() if n != MODEL_FILE}


# ---- plot and compare: the figure folder against the results files read --------------------

@pytest.mark.parametrize("command", ["plot", "compare"])
def test_plot_and_compare_never_write_over_a_results_file(
        tmp_path: Path, command: str, capsys: pytest.CaptureFixture[str],
        short_run: jointplay.SimulationResult) -> None:
    """--out naming a results file the command reads is refused before any work (exit 2)."""
    from jointplay.results.write import write_hdf5

    run = tmp_path / "run.h5"
    write_hdf5(short_run, run)
    runs = [str(run)] if command == "plot" else [str(run), str(run)]
    refused_before_work(capsys, [command, *runs, "--out", str(run), "--no-replay"], tmp_path,
                        "--out", str(run))


@pytest.mark.parametrize("command", ["plot", pytest.param("compare", marks=pytest.mark.slow)])
def test_plot_and_compare_figures_all_or_nothing(
        tmp_path: Path, command: str, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch, short_run: jointplay.SimulationResult) -> None:
    """A full disk at the last figure: exit 1, one line naming the figure folder and the
    cause, no figure and no folder left; then the same command writes them all."""
    from jointplay.results.write import write_hdf5

    run = tmp_path / "run.h5"
    write_hdf5(short_run, run)
    runs = [str(run)] if command == "plot" else [str(run), str(run)]
    complete = tmp_path / "complete"
    probe = Faults(monkeypatch, "none", 0, name="png")
    assert main([command, *runs, "--out", str(complete), "--no-replay"]) == 0
    figures = sorted(p.name for p in complete.iterdir())
    assert len(figures) == probe.calls["fsync"] > 1
    capsys.readouterr()
    out = tmp_path / "full"
    Faults(monkeypatch, "fsync", len(figures), name="png")
    assert main([command, *runs, "--out", str(out), "--no-replay"]) == 1
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and err.startswith(f"jointplay: error: {out}"), err
    assert "no space left on device" in err
    assert not out.exists()
    Faults(monkeypatch, "none", 0)
    assert main([command, *runs, "--out", str(out), "--no-replay"]) == 0
    assert sorted(p.name for p in out.iterdir()) == figures
