"""Every check that can fail runs before the work: output names no write could honour, paths
under a file, names near the length limit, and the accuracy check at the documented limits.
Each probe satisfies the contract of :mod:`test_probes`."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from test_probes import bad_input, check_contract

import jointplay
from jointplay.cli import main
from jointplay.sim import tighter_settings

# ---- every check that can fail runs before the work -------------------------------------------

SHORT = ["simulate", "--t-end", "0.01", "--no-verify", "--quiet"]


@pytest.mark.parametrize(("flag", "under"), [("--out", "x.h5"), ("--plot", "figs"),
                                             ("--csv", "x.csv"), ("--animate", "x.gif"),
                                             ("--out", "deeper/x.h5")])
def test_an_output_under_a_file_is_refused_before_the_run(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], flag: str, under: str) -> None:
    blocker = tmp_path / "a.h5"
    blocker.write_bytes(b"not a folder")
    bad_input(capsys, [*SHORT, flag, str(blocker / under)], flag, "which is a file")
    assert blocker.read_bytes() == b"not a folder" and list(tmp_path.iterdir()) == [blocker]


@pytest.mark.parametrize(("argv", "flag", "word"), [
    ([*SHORT, "--out", ""], "--out", "is empty"),
    ([*SHORT, "--plot", ""], "--plot", "is empty"),
    ([*SHORT, "--csv", ""], "--csv", "is empty"),
    ([*SHORT, ""], "scene", "is empty"),
    (["plot", "run.h5", "--out", ""], "--out", "is empty"),
    ([*SHORT, "--out", "newdir/"], "--out", "names a folder"),
    ([*SHORT, "--out", "-"], "--out", "standard output"),
    ([*SHORT, "--csv", "-"], "--csv", "standard output"),
    ([*SHORT, "--out", "r" * 253 + ".h5"], "--out", "at most 255"),
    ([*SHORT, "--out", os.fsdecode(b"\xffrun.h5")], "--out", "not valid UTF-8"),
    ([*SHORT, "--plot", os.fsdecode(b"figs\xff")], "--plot", "not valid UTF-8"),
])
def test_odd_output_names_are_refused(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                      monkeypatch: pytest.MonkeyPatch, argv: list[str],
                                      flag: str, word: str) -> None:
    monkeypatch.chdir(tmp_path)
    bad_input(capsys, argv, flag, word)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("length", [225, 226, 227])
def test_long_names_write_again(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                monkeypatch: pytest.MonkeyPatch, length: int) -> None:
    """A legal name near the 255-byte limit is written, then written over: the temporary and
    set-aside names are short hashes, never longer than the name."""
    monkeypatch.chdir(tmp_path)
    out = "r" * (length - 3) + ".h5"
    csv = "c" * (length - 4) + ".csv"
    for _ in range(2):
        code = main([*SHORT, "--out", out, "--csv", csv])
        err = capsys.readouterr().err
        check_contract(code, err)
        assert code == 0, err
    assert (tmp_path / out).is_file() and (tmp_path / csv).is_file()
    assert [p.name for p in tmp_path.iterdir() if p.name.endswith(".part")] == []


def test_accuracy_check_at_the_smallest_tolerance_is_clamped(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """--rtol 1e-14 (the documented minimum): the check's rtol is clamped to it, said so,
    and the run completes with its file (no exit 2 after the work)."""
    out = tmp_path / "run.h5"
    code = main(["simulate", "--t-end", "0.01", "--rtol", "1e-14", "--verify", "--out",
                 str(out)])
    captured = capsys.readouterr()
    check_contract(code, captured.err)
    assert code == 0, captured.err
    assert "run.rtol 1e-14 (not 1e-15) is clamped" in captured.out
    assert out.is_file()
    scene = jointplay.default_scene().with_run(integrator="rk4", t_end=1e-3, output_step=1e-3,
                                               step=5e-12)
    assert tighter_settings(scene) == {"step": 1e-12}
    scene = scene.with_run(step=1e-5)
    assert tighter_settings(scene)["step"] == pytest.approx(1e-6, rel=1e-12)


def test_accuracy_check_impossible_at_the_limits_is_refused_before_the_run(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad_input(capsys, ["simulate", "--t-end", "1e-3", "--integrator", "rk4", "--step", "1e-12",
                       "--verify", "--out", str(tmp_path / "run.h5")], "--verify", "limits")
    assert list(tmp_path.iterdir()) == []
    scene = jointplay.default_scene().with_run(rtol=1e-14, atol=1e-20)
    with pytest.raises(jointplay.DescriptionError, match="verify"):
        jointplay.simulate(scene, verify=True)


def test_derive_under_a_file_is_refused_before_deriving(tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]
                                                        ) -> None:
    blocker = tmp_path / "a.h5"
    blocker.write_bytes(b"x")
    bad_input(capsys, ["derive", "--out", str(blocker / "model")], "--out", "which is a file")
