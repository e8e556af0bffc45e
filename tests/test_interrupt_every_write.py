"""An interrupt at every write: no temporary, no half-made output, survives any moment.

The write phase of ``simulate`` (results file, CSV, figures) and of ``calibrate`` (its five
files) runs once with every call that changes the file system counted (``open`` for writing,
``os.open``, ``fsync``, ``replace``, ``link``, ``mkdir``, ``rmdir``, ``unlink``), then once
more for each of them with SIGINT sent to the process right before it or right after it
(SIGTERM right after it). After each: no ``.part`` file anywhere, and the
outputs are all there and complete, or none is (a file that existed before is there as it
was, and a folder the command made is gone).

The figures' pixels are replaced by a fixed PNG (drawing them is no write, and took most of
the time); every byte still goes through the writers the command uses."""

from __future__ import annotations

import builtins
import io
import os
import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest

from jointplay.cli import main
from jointplay.common import interrupts

PNG = b"\x89PNG\r\n\x1a\n" + b"\0" * 64
# Right after each write (the moment before the next is the same but for the Python between
# them), SIGINT and SIGTERM; before the first, SIGINT too.
MOMENTS = (("after", "int"), ("after", "term"))
FIRST_MOMENTS = (("before", "int"), *MOMENTS)
_CALLS = ("open", "fsync", "replace", "link", "mkdir", "rmdir", "unlink", "rename")


class WritePoints:
    """Counts the calls that change files under ``root``; with ``at`` set, raises the
    interrupt before (``when="before"``) or after the call of that number, once."""

    def __init__(self, root: Path, at: int | None = None, when: str = "after",
                 kind: str = "int") -> None:
        self.root, self.at, self.when, self.signal = str(root), at, when, kind
        self.count = 0
        self.fired = False

    def _mine(self, target: Any) -> bool:
        try:
            path = os.fspath(target)
        except TypeError:  # a file descriptor (fsync)
            return True
        return isinstance(path, str) and os.path.abspath(path).startswith(self.root)

    def _interrupt(self) -> None:
        """A real signal to this process: its handler runs as it would (raising, or only
        recording where the command defers Ctrl-C)."""
        self.fired = True
        signal.raise_signal(signal.SIGINT if self.signal == "int" else signal.SIGTERM)

    def point(self, target: Any, call: Callable[[], Any]) -> Any:
        if self.fired or not self._mine(target):
            return call()
        self.count += 1
        if self.count == self.at and self.when == "before":
            self._interrupt()
        try:
            return call()
        finally:  # also after a call that failed (a folder that exists, a file that does not)
            if self.count == self.at and self.when == "after":
                self._interrupt()


@contextmanager
def counted(monkeypatch: pytest.MonkeyPatch, points: WritePoints) -> Iterator[None]:
    real = {name: getattr(os, name) for name in _CALLS}
    real_open = builtins.open

    def wrap(name: str) -> Callable[..., Any]:
        def call(*args: Any, **kwargs: Any) -> Any:
            if name == "open" and not (len(args) > 1 and args[1] & (os.O_WRONLY | os.O_RDWR
                                                                     | os.O_CREAT)):
                return real[name](*args, **kwargs)
            return points.point(args[0], lambda: real[name](*args, **kwargs))
        return call

    def opened(file: Any, mode: str = "r", *args: Any, **kwargs: Any) -> Any:
        if not any(c in mode for c in "wax+"):
            return real_open(file, mode, *args, **kwargs)
        return points.point(file, lambda: real_open(file, mode, *args, **kwargs))

    with monkeypatch.context() as m:
        for name in _CALLS:
            m.setattr(os, name, wrap(name))
        m.setattr(builtins, "open", opened)
        m.setattr(io, "open", opened)
        yield


def _state(paths: list[Path]) -> list[bytes | None]:
    return [p.read_bytes() if p.is_file() else None for p in paths]


def _check_after(tmp: Path, outputs: list[Path], before: list[bytes | None],
                 complete: Callable[[list[Path]], None], made: Path | None,
                 moment: tuple[int, str, str]) -> None:
    assert [p.relative_to(tmp) for p in tmp.rglob("*.part*")] == [], moment
    now = _state(outputs)
    if now == before:
        if made is not None:
            assert not made.exists(), ("the folder the command made is left behind", moment)
        return
    assert all(n is not None for n in now), ("some outputs written, others not", moment)
    assert all(n != b for n, b in zip(now, before, strict=True) if b is not None), \
        ("some outputs replaced, others not", moment)
    complete(outputs)


# ---- simulate ---------------------------------------------------------------------------------

def _simulate_outputs(tmp: Path, full: bool) -> list[Path]:
    return [tmp / "r.h5", *([tmp / "r.csv", tmp / "r.impacts.csv"] if full else [])]


def _simulate(tmp: Path, full: bool) -> int:
    more = ["--csv", str(tmp / "r.csv"), "--plot", str(tmp / "plots")] if full else []
    return main(["simulate", "--t-end", "0.005", "--quiet", "--out", str(tmp / "r.h5"), *more])


def _simulate_complete(outputs: list[Path]) -> None:
    import jointplay

    assert jointplay.read(outputs[0]).t.size > 0
    if len(outputs) > 1:
        assert outputs[1].read_text(encoding="utf-8").startswith("t")
        pngs = sorted(outputs[0].parent.joinpath("plots").glob("*.png"))
        assert pngs and all(p.read_bytes() == PNG for p in pngs)


def _clear(tmp: Path, outputs: list[Path], existing: bool) -> None:
    """Back to the start: no outputs (or the earlier run's), no figures folder."""
    for path in [*outputs, *(tmp / "plots").glob("*")]:
        path.unlink(missing_ok=True)
    if (tmp / "plots").exists():
        (tmp / "plots").rmdir()
    if existing:  # an earlier run's files: kept as they were, or all replaced
        for path in outputs:
            path.write_bytes(b"an earlier run\n")


@pytest.fixture
def fixed_figures(monkeypatch: pytest.MonkeyPatch) -> None:
    from jointplay.common import figures

    monkeypatch.setattr(figures, "png_bytes", lambda fig, dpi=None: PNG)
    monkeypatch.setenv("JOINTPLAY_FIGURE_PROCESS", "0")


@pytest.mark.parametrize(("full", "existing"), [
    (False, True),
    pytest.param(True, False, marks=pytest.mark.slow),
    pytest.param(True, True, marks=pytest.mark.slow)])
def test_simulate_interrupted_at_every_write(tmp_path: Path, full: bool, existing: bool,
                                             monkeypatch: pytest.MonkeyPatch,
                                             capsys: pytest.CaptureFixture[str],
                                             fixed_figures: None) -> None:
    """The results file over an earlier one; with ``full``, the CSV tables and the figures
    too (about 60 writes)."""
    outputs = _simulate_outputs(tmp_path, full)
    _clear(tmp_path, outputs, existing)
    before = _state(outputs)
    probe = WritePoints(tmp_path)
    with counted(monkeypatch, probe):
        assert _simulate(tmp_path, full) == 0
    total = probe.count
    assert total >= (10 if full else 5), total
    _clear(tmp_path, outputs, existing)
    completed = 0
    for at in range(1, total + 1):
        for when, kind in MOMENTS if at > 1 else FIRST_MOMENTS:
            probe = WritePoints(tmp_path, at, when, kind)
            with counted(monkeypatch, probe):
                try:
                    code = _simulate(tmp_path, full)
                except SystemExit as stop:
                    code = int(stop.code or 0)
            capsys.readouterr()
            assert probe.fired, (at, when)
            assert code in (130, 143), (at, when, kind, code)
            _check_after(tmp_path, outputs, before, _simulate_complete,
                         tmp_path / "plots" if full and not existing else None,
                         (at, when, kind))
            if _state(outputs) != before:  # the last moments: all written; start again
                completed += 1
                _clear(tmp_path, outputs, existing)
    assert completed < total  # most interrupts left the outputs as they were


# ---- calibrate --------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def calibration(tmp_path_factory: pytest.TempPathFactory) -> Any:
    """A small calibration's result (payload mass on the ideal arm, a few samples)."""
    import numpy as np

    import jointplay
    from jointplay.calibration.api import CalibrationOptions, calibrate
    from jointplay.calibration.measured import Measured
    from jointplay.scene.definition import ideal_counterpart

    base = jointplay.default_scene().with_run(t_end=0.02)
    scene = base.with_robot(ideal_counterpart(base.robot))
    run = jointplay.simulate(scene)
    rows = np.arange(0, run.t.size, 4)
    data = Measured("m", run.t[rows], ("tip_x", "tip_y"), run.tip_position[rows])
    options = CalibrationOptions(starts=1, scan_points=0, profile_points=3, horizon_first=0.0,
                                 grid_window=0.0, valley_check_points=0, basins=False)
    return calibrate(scene, data, ["payload.mass"], noise=1e-6, options=options)


def test_calibrate_interrupted_at_every_write(tmp_path: Path, calibration: Any,
                                              monkeypatch: pytest.MonkeyPatch,
                                              fixed_figures: None) -> None:
    from jointplay.calibration.report import FILES, output_plan, write_report

    out = tmp_path / "deep" / "cal"
    outputs = [out / name for name in FILES]

    def write() -> None:
        with interrupts.installed():
            write_report(calibration, out, output_plan(out, {}), "jointplay calibrate")

    def complete(paths: list[Path]) -> None:
        import json

        assert json.loads(paths[0].read_text(encoding="utf-8"))["estimates"]
        assert all(p.stat().st_size > 0 for p in paths)

    probe = WritePoints(tmp_path)
    with counted(monkeypatch, probe):
        write()
    total = probe.count
    assert total >= 2 * len(FILES), total
    for path in outputs:
        path.unlink()
    out.rmdir()
    out.parent.rmdir()
    for at in range(1, total + 1):
        for when, kind in MOMENTS if at > 1 else FIRST_MOMENTS:
            probe = WritePoints(tmp_path, at, when, kind)
            with counted(monkeypatch, probe), pytest.raises((KeyboardInterrupt, SystemExit)):
                write()
            _check_after(tmp_path, outputs, [None] * len(outputs), complete, out.parent,
                         (at, when, kind))
            if out.exists():
                for path in outputs:
                    path.unlink()
                out.rmdir()
                out.parent.rmdir()
            assert list(tmp_path.iterdir()) == [], (at, when, kind)


def test_a_program_that_ran_an_interrupted_command_goes_on(tmp_path: Path) -> None:
    """After a command ended by an interrupt (exit 130) in a program that imports jointplay,
    the next write is not refused as interrupted: the interrupt was reported once."""
    from jointplay.common.files import atomic_write_text

    with interrupts.installed(), pytest.raises(KeyboardInterrupt):
        signal.raise_signal(signal.SIGINT)
    assert not interrupts.interrupted()
    atomic_write_text(tmp_path / "after.txt", "written\n")
    assert (tmp_path / "after.txt").read_text(encoding="utf-8") == "written\n"
