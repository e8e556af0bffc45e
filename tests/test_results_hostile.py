"""Results files that are damaged or hostile are refused with one line, never read as other
numbers; replay and compare trust a file only after their checks.

The files come from :mod:`hostile_files` (seeded), made from one real run of the paper scene
(50 ms, with its ideal counterpart) shared by the module.
"""

from __future__ import annotations

import dataclasses
import subprocess
import sys
from collections import Counter
from pathlib import Path
from typing import Any

import h5py
import numpy as np
import pytest
from hostile_files import Hostile, make_hostile_files
from test_output import assert_same

import jointplay
from jointplay.cli import EXIT_BAD_INPUT, main
from jointplay.common.errors import DescriptionError
from jointplay.results import integrity
from jointplay.results.records import SimulationResult
from jointplay.results.write import read_checked, write_hdf5

# Forged files (digest written again over the edit) that may read: the edit changed numbers
# the layout allows (a NaN in a state, an impact, a parameter), or added what the reader
# ignores. Every other forged edit breaks the layout and must be refused.
_FORGED_MAY_READ = ("NaN in joint_angle", "inf in tip_position", "NaN in parameter_value",
                    "NaN in impact_time", "-inf in energy_total", "NaN in ideal/joint_angle",
                    "metadata_json run settings odd", "extra attribute", "extra variable",
                    "extra group")


@pytest.fixture(scope="module")
def base(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, SimulationResult]:
    result = jointplay.simulate(jointplay.default_scene().with_run(t_end=0.05),
                                compare_ideal=True, quiet=True)
    path = tmp_path_factory.mktemp("base") / "run.h5"
    write_hdf5(result, path)
    return path, result


@pytest.fixture(scope="module")
def hostile(base: tuple[Path, SimulationResult],
            tmp_path_factory: pytest.TempPathFactory) -> list[Hostile]:
    return make_hostile_files(base[0], tmp_path_factory.mktemp("hostile"))


def test_checked_file_round_trip(base: tuple[Path, SimulationResult]) -> None:
    """Every numeric variable is chunked with Fletcher-32; the digest matches; the result
    reads back equal, checked; xarray still opens the file."""
    import xarray as xr

    path, result = base
    back, checked = read_checked(path)
    assert checked
    assert_same(dataclasses.replace(result, accuracy=None), back)
    numeric: list[h5py.Dataset] = []
    with h5py.File(path, "r") as fh:
        fh.visititems(lambda name, obj: numeric.append(obj) if isinstance(obj, h5py.Dataset)
                      and obj.dtype.kind in "fiub" else None)
        assert len(numeric) > 90  # 47 in the run, 47 in its ideal counterpart
        assert all(ds.fletcher32 and ds.chunks for ds in numeric)
        assert len(fh.attrs[integrity.DIGEST_ATTRIBUTE]) == 64
    with xr.open_dataset(path) as ds:
        np.testing.assert_array_equal(ds["time"].values, result.t)


def test_file_without_checksums_reads_unchecked(base: tuple[Path, SimulationResult],
                                                tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    """A file of the layout before checksums (version 2) reads equal and says, where its
    numbers are used (plot, compare), that they are unchecked; a checked file says nothing."""
    _, result = base
    old = tmp_path / "old.h5"
    write_hdf5(result, old, checksums=False)
    with h5py.File(old, "r") as fh:
        assert fh.attrs["format_version"] == 2
        assert integrity.DIGEST_ATTRIBUTE not in fh.attrs
        assert not fh["joint_angle"].fletcher32
    back, checked = read_checked(old)
    assert not checked
    assert_same(dataclasses.replace(result, accuracy=None), back)
    assert main(["compare", str(base[0]), str(old), "--out", str(tmp_path / "d"),
                 "--no-replay"]) == 0
    out = capsys.readouterr().out
    assert out.count("read unchecked") == 1 and f"{old}: written before" in out


def test_generator_makes_every_kind(hostile: list[Hostile]) -> None:
    names = Counter(h.path.name.split(".")[0].rstrip("0123456789") for h in hostile)
    assert len(hostile) >= 200
    assert names["flip"] >= 100 and names["cut"] >= 15 and names["edit"] >= 60
    assert names["forged"] >= 30


@pytest.mark.slow
def test_read_gives_the_original_or_refuses(base: tuple[Path, SimulationResult],
                                            hostile: list[Hostile]) -> None:
    """Every damaged file reads back equal to the original or is refused with jointplay's
    one-line error; no edit through h5py survives the digest; forged files that break the
    layout are refused."""
    original = jointplay.read(base[0])
    outcomes: Counter[str] = Counter()
    wrong: list[str] = []
    for h in hostile:
        try:
            back = jointplay.read(h.path)
        except DescriptionError as err:
            outcomes["refused"] += 1
            if "\n" in str(err):
                wrong.append(f"{h.what}: error of several lines")
            continue
        except Exception as err:  # the failure this test exists to catch: name the file
            wrong.append(f"{h.what}: raw {type(err).__name__}: {err}")
            continue
        if h.path.name.startswith("edit"):
            wrong.append(f"{h.what}: an edit the digest should have caught was read")
        try:
            assert_same(original, back)
            outcomes["equal"] += 1
        except AssertionError as err:
            if not (h.forged and h.what.startswith(_FORGED_MAY_READ)):
                wrong.append(f"{h.what}: read with other numbers ({err})")
            outcomes["forged read"] += 1
    assert not wrong, "\n".join(wrong)
    assert outcomes["refused"] >= 200, outcomes


@pytest.mark.parametrize("what, says", [
    ("a FIFO", "is a FIFO (named pipe), not a results file"),
    ("a folder", "is a folder, not a results file"),
    ("/dev/zero", "is a character device, not a results file"),
    ("an empty file", "is empty (0 bytes)"),
    ("a CSV file", "cannot be read as a results file"),
    ("huge time", "declares shape (10000000000,)"),
    ("joint_angle one sample short (digest written again)",
     "has shape (50, 2), its dimensions (time, coordinate) give (51, 2)"),
    ("joint_angle one sample short", "does not match its checksum"),
    ("time not increasing (digest written again)", "must be finite and increasing"),
    ("solver_stats nested deep (digest written again)", "is not JSON"),
    ("external link for energy_total", "a results file holds no links to elsewhere"),
])
def test_refusals_say_what_is_wrong(hostile: list[Hostile], what: str, says: str) -> None:
    path = next(h.path for h in hostile if h.what == what)
    with pytest.raises(DescriptionError) as caught:
        jointplay.read(path)
    assert says in str(caught.value)


def test_refused_links(hostile: list[Hostile]) -> None:
    for name, says in (("dangling.h5", "which does not exist"), ("loop.h5", "cannot read it"),
                       ("device.h5", "is a character device")):
        path = next(h.path for h in hostile if h.path.name == name)
        with pytest.raises(DescriptionError) as caught:
            jointplay.read(path)
        assert says in str(caught.value), caught.value


def test_fifo_and_device_through_the_cli(hostile: list[Hostile], tmp_path: Path) -> None:
    """Run as a user would: a FIFO does not block, /dev/zero says what it is (exit 2)."""
    fifo = next(h.path for h in hostile if h.path.name == "fifo.h5")
    for path, says in ((fifo, "FIFO"), (Path("/dev/zero"), "character device")):
        done = subprocess.run([sys.executable, "-m", "jointplay.cli", "plot", str(path),
                               "--out", str(tmp_path / "d")], capture_output=True, text=True,
                              timeout=120)
        assert done.returncode == EXIT_BAD_INPUT, done.stderr
        lines = done.stderr.strip().splitlines()
        assert len(lines) == 1 and says in lines[0], done.stderr
    assert not (tmp_path / "d").exists()


def _check_cli(hostile: list[Hostile], base: Path, tmp_path: Path,
               capsys: pytest.CaptureFixture[str], replay: bool) -> Counter[str]:
    """plot and compare on each file: exit 0 (a file read equal) or 2 with one line; never
    a traceback or an internal error."""
    wrong: list[str] = []
    codes: Counter[str] = Counter()
    flags = [] if replay else ["--no-replay"]
    for k, h in enumerate(hostile):
        for argv in (["plot", str(h.path), "--out", str(tmp_path / f"p{k}"), *flags],
                     ["compare", str(base), str(h.path), "--out", str(tmp_path / f"c{k}"),
                      "--no-replay"]):
            code = main(argv)
            err = capsys.readouterr().err
            codes[str(code)] += 1
            lines = err.strip().splitlines()
            if code not in (0, EXIT_BAD_INPUT) or "Traceback" in err or "internal error" in err \
                    or (code == EXIT_BAD_INPUT and len(lines) != 1):
                wrong.append(f"{argv[0]} {h.what}: exit {code}: {err.strip()}")
    assert not wrong, "\n".join(wrong)
    return codes


# One file of each kind for the default tier (the slow test below takes every file).
_SAMPLE = ("fifo.h5", "folder.h5", "device.h5", "dangling.h5", "loop.h5", "empty.h5",
           "text.h5", "random.h5", "signature.h5", "flip000.h5",
           "flip001.h5", "flip002.h5", "edit000.h5", "edit011.h5", "edit030.h5", "edit060.h5",
           "forged000.h5", "forged011.h5", "forged034.h5")


def test_cli_refuses_a_sample_in_one_line(hostile: list[Hostile],
                                          base: tuple[Path, SimulationResult], tmp_path: Path,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    """A file of each kind through plot and compare."""
    sample = [h for h in hostile if h.path.name in _SAMPLE]
    sample += [h for h in hostile if h.path.name.startswith("cut")][::6]
    assert len(sample) >= 20
    codes = _check_cli(sample, base[0], tmp_path, capsys, replay=False)
    assert codes[str(EXIT_BAD_INPUT)] >= 2 * (len(sample) - 5), codes


@pytest.mark.slow
def test_cli_refuses_every_file_in_one_line(hostile: list[Hostile],
                                            base: tuple[Path, SimulationResult],
                                            tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    """All of them, plot with replay (the file's scene run again where the file reads)."""
    codes = _check_cli(hostile, base[0], tmp_path, capsys, replay=True)
    assert codes[str(EXIT_BAD_INPUT)] >= 400, codes


# ------------------------------------------------------------------------------------ replay


def _no_compiling(monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(*args: Any, **kwargs: Any) -> Any:
        raise AssertionError("compiled or simulated before the checks")

    monkeypatch.setattr("jointplay.sim.load_scene_model", refuse)
    monkeypatch.setattr("jointplay.sim.simulate", refuse)


def _with_nan(values: np.ndarray) -> np.ndarray:
    changed = values.copy()
    changed[7, 0] = np.nan
    return changed


def _with_metadata(result: SimulationResult, **changes: Any) -> SimulationResult:
    return dataclasses.replace(result, metadata={**result.metadata, **changes})


def test_replay_checks_before_compiling(base: tuple[Path, SimulationResult],
                                        monkeypatch: pytest.MonkeyPatch) -> None:
    """Settings that do not give the file's samples (t_end = 1e5 s over 50 ms of samples),
    settings beyond the limits, another model's hash, NaN samples: refused before anything
    is compiled or run."""
    from jointplay.sim.dense import replay

    result = jointplay.read(base[0])
    run = result.metadata["run"]
    _no_compiling(monkeypatch)
    cases = [
        (_with_metadata(result, run={**run, "t_end": 1e5}), "t_end = 100000 s"),
        (_with_metadata(result, run={**run, "t_end": 1e9}), "cannot be read again"),
        (_with_metadata(result, run={**run, "output_step": 1e-4}), "do not give the file's"),
        (_with_metadata(result, model_input_hash="0" * 64), "not the one that made the file"),
        (dataclasses.replace(result, q=_with_nan(result.q)), "NaN"),
    ]
    for changed, says in cases:
        solution, why = replay(changed)
        assert solution is None and says in why, why


def test_replay_nan_is_never_a_match(base: tuple[Path, SimulationResult],
                                     monkeypatch: pytest.MonkeyPatch) -> None:
    """A run again that gives a NaN where the file holds a number is a mismatch, not a match
    (NaN compares false with any bound)."""
    import jointplay.sim
    from jointplay.sim.dense import replay

    result = jointplay.read(base[0])
    solution, how = replay(result)
    assert solution is not None, how
    real = jointplay.sim.simulate

    def poisoned(*args: Any, **kwargs: Any) -> SimulationResult:
        again = real(*args, **kwargs)
        return dataclasses.replace(again, q=_with_nan(again.q))

    monkeypatch.setattr(jointplay.sim, "simulate", poisoned)
    solution, how = replay(result)
    assert solution is None and "does not reproduce the file (apart by nan" in how


# ----------------------------------------------------------------------------------- compare


def test_compare_is_symmetric_and_zero_against_itself() -> None:
    """The same run at output steps of 1 ms and 0.5 ms differs, at the times both share, by
    no more than the integrator's working accuracy; swapping them gives the same numbers."""
    from jointplay.results.look import differences

    scene = jointplay.default_scene().with_run(t_end=0.05)
    coarse = jointplay.simulate(scene, quiet=True)
    fine = jointplay.simulate(scene.with_run(output_step=5e-4), quiet=True)
    one = differences([("coarse", coarse), ("fine", fine)])[1]
    other = differences([("fine", fine), ("coarse", coarse)])[1]
    assert one.max_tip_difference == other.max_tip_difference
    assert one.max_tip_difference_time == other.max_tip_difference_time
    assert one.compared_samples == other.compared_samples == coarse.n_samples
    assert one.max_tip_difference < 1e-6, one.max_tip_difference
