"""``jointplay plot`` and ``jointplay compare`` on results files, and the derived quantities
their figures draw (film force, eccentricity ratio, release transient)."""

from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from test_output import make_result

from jointplay.cli import EXIT_BAD_INPUT, main
from jointplay.results.derived import (
    eccentricity_ratio,
    film_components,
    film_force,
    is_lubricated,
    release_transient_end,
)
from jointplay.results.look import differences, tip_difference
from jointplay.results.records import SimulationResult
from jointplay.results.wear import wear_profile
from jointplay.results.write import write_hdf5

FILM = 40.0  # N, the synthetic film's load along the line of centres


def lubricated(result: SimulationResult) -> SimulationResult:
    """The result with a film force FILM N towards the bearing centre added on every joint,
    the lubricant's parameters, and a wear record: every effect has its figure. Joint 3 has
    no impacts left (the film carries it), the case whose empty panels once broke the layout."""
    e = result.eccentricity
    normal = e / np.hypot(e[..., 0], e[..., 1])[..., None]
    bins = 360
    angle = (np.arange(bins) + 0.5) * 2 * np.pi / bins
    depth = np.stack([np.stack([1e-9 * (1 + np.cos(angle - k)) for k in range(2)])] * 2)
    return dataclasses.replace(
        result, contact_force=result.contact_force - FILM * normal,
        impacts=result.impacts.for_joint(2),
        parameter_names=[*result.parameter_names, "lubrication.viscosity",
                         "lubrication.transition"],
        parameters=np.r_[result.parameters, 0.04, 0.95],
        wear=wear_profile([2, 3], np.array([1e-12, 2e-12]), depth))


@pytest.fixture(scope="module")
def dry() -> SimulationResult:
    return make_result(n=200)


def test_film_force_is_what_the_dry_law_leaves(dry: SimulationResult) -> None:
    """The synthetic dry result's contact force is exactly -F_n n + F_t t: no film; the film
    added to it comes back as FILM N along the line of centres and nothing across it."""
    assert not is_lubricated(dry)
    scale = float(np.max(np.abs(dry.contact_force)))
    assert float(np.max(np.abs(film_force(dry)))) < 1e-12 * scale
    wet = lubricated(dry)
    assert is_lubricated(wet)
    along, across = film_components(wet)
    np.testing.assert_allclose(along, FILM, rtol=1e-12)
    assert float(np.max(np.abs(across))) < 1e-12 * FILM


def test_eccentricity_ratio_and_release_transient(dry: SimulationResult) -> None:
    ratio = eccentricity_ratio(dry)
    expected = np.hypot(dry.eccentricity[..., 0], dry.eccentricity[..., 1]) \
        / dry.radial_clearance
    np.testing.assert_allclose(ratio, expected, rtol=1e-15)
    assert ratio.min() > 0.97 and ratio.max() < 1.03  # c (1 +- 0.02) in the synthetic orbit
    # The synthetic impacts are evenly spread from the start (pauses shorter than the time
    # since the run began): no burst stands apart from the rest, so no release transient.
    assert release_transient_end(dry) is None
    # Joint 2's phases at 0.2-0.3 s and 0.8-0.9 s alone: the pause (0.5 s) is longer than
    # the 0.3 s since the start, so the first phase is the transient, ending at 0.3 s.
    rows = dry.impacts
    kept = (np.asarray(rows.joint) == 2) & np.isin(np.round(rows.time, 9), [0.2, 0.8])
    apart = type(rows)(**{name: np.asarray(getattr(rows, name))[kept]
                          for name in rows.column_names()})
    end, rule = release_transient_end(dataclasses.replace(dry, impacts=apart)) or (None, "")
    assert end == pytest.approx(0.3, abs=1e-12)
    assert rule == "end of the first impact burst"


def test_release_transient_without_impacts(dry: SimulationResult) -> None:
    """No impacts: the transient ends after the last early sample whose acceleration leaves
    the range of the second half; a run without such a sample has none."""
    quiet = dataclasses.replace(dry, impacts=dry.impacts.for_joint(99))
    assert release_transient_end(quiet) is None
    kicked = dry.tip_acceleration.copy()
    kicked[3] = 50.0 * np.max(np.abs(kicked))
    end, rule = release_transient_end(dataclasses.replace(quiet, tip_acceleration=kicked)) \
        or (None, "")
    assert end == float(dry.t[4]) and rule == "acceleration back in its later range"


def test_plot_command_draws_every_effect_and_warns_nothing(dry: SimulationResult,
                                                           tmp_path: Path) -> None:
    """From the file, in a fresh interpreter with every warning an error: all figures of a
    lubricated, wearing run with clearance and an ideal twin, and nothing on stderr."""
    run = tmp_path / "wet.h5"
    write_hdf5(lubricated(dry), run)
    out = tmp_path / "figures"
    done = subprocess.run([sys.executable, "-W", "error", "-m", "jointplay.cli", "plot",
                           str(run), "--out", str(out)], capture_output=True, text=True,
                          env={**os.environ, "PYTHONWARNINGS": "error"}, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    # in the order they are drawn: the costliest first (plots.figure_jobs)
    names = ["end_effector.png", "energy.png", "contact_timeline_joint2.png",
             "contact_timeline_joint3.png", "contact_force.png", "eccentricity_ratio.png",
             "film_force.png", "orbit_joint2.png", "orbit_joint3.png", "wear.png"]
    assert sorted(os.listdir(out)) == sorted(names)
    lines = done.stdout.splitlines()
    assert lines[0].startswith("wet.h5: orbits by cubic Hermite between the samples: ")
    assert lines[1:] == [f"wrote {out / name}" for name in names]


def test_compare_command(dry: SimulationResult, tmp_path: Path,
                         capsys: pytest.CaptureFixture[str]) -> None:
    shifted = dataclasses.replace(dry, tip_position=dry.tip_position + np.array([3e-4, -4e-4]))
    fewer = dataclasses.replace(shifted, impacts=shifted.impacts.for_joint(2))
    paths = [tmp_path / "a.h5", tmp_path / "b.h5"]
    write_hdf5(dry, paths[0])
    write_hdf5(fewer, paths[1])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a library warning fails the command
        assert main(["compare", *map(str, paths), "--out", str(tmp_path / "cmp")]) == 0
    captured = capsys.readouterr()
    assert captured.err == ""
    printed = captured.out
    lines = printed.splitlines()
    assert lines[0].startswith("a: orbits by cubic Hermite between the samples: ")
    lines = lines[2:]  # each run says where its orbits come from, then the table
    assert lines[0].split()[:3] == ["run", "integrator", "impacts"]
    a_row, b_row = lines[2].split(), lines[3].split()
    assert a_row[:3] == ["a", dry.integrator, str(len(dry.impacts))]
    assert b_row[:3] == ["b", dry.integrator, str(len(dry.impacts.for_joint(2)))]
    assert "reference" in a_row and "0.0005 m" in lines[3]  # |(3, -4)| 1e-4 m
    assert sorted(os.listdir(tmp_path / "cmp")) == sorted(
        ["compare_tip.png", "compare_orbit_joint2.png", "compare_orbit_joint3.png",
         "compare_contact_force.png", "compare_impacts.png", "compare_energy.png"])
    rows = differences([("a", dry), ("b", fewer)])
    assert rows[1].max_tip_difference == pytest.approx(5e-4, rel=1e-9)
    assert rows[0].max_tip_difference == 0.0


def test_tip_difference_on_other_sample_times(dry: SimulationResult) -> None:
    """Runs at other output steps are compared at the times both share, never through an
    interpolant, and the same numbers come back with the runs swapped."""
    coarse = make_result(n=101, ideal=False)
    fine = make_result(n=201, ideal=False)  # every other sample is one of coarse's
    t, gap = tip_difference(fine, coarse)
    np.testing.assert_allclose(t, coarse.t, rtol=0.0, atol=1e-15)
    # The same smooth path at the same instants: equal to rounding of the sample times.
    assert float(gap.max()) < 1e-12 * float(np.ptp(coarse.tip_position))
    t_swapped, gap_swapped = tip_difference(coarse, fine)
    np.testing.assert_array_equal(t_swapped, t)
    np.testing.assert_array_equal(gap_swapped, gap)
    # 200 and 101 samples over the same second share only the first and the last instant.
    t, gap = tip_difference(coarse, dry)
    np.testing.assert_array_equal(t, [0.0, 1.0])


@pytest.mark.parametrize("argv, says", [
    (["plot", "missing.h5", "--out", "d"], "missing.h5: no such file"),
    (["compare", "one.h5", "--out", "d"], "two or more results files"),
])
def test_look_refuses_bad_input(argv: list[str], says: str, tmp_path: Path,
                                capsys: pytest.CaptureFixture[str],
                                monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(argv) == EXIT_BAD_INPUT
    assert says in capsys.readouterr().err
    assert not (tmp_path / "d").exists()


def test_plot_refuses_a_file_that_is_not_a_result(tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "notes.h5"
    bad.write_text("not HDF5")
    assert main(["plot", str(bad), "--out", str(tmp_path / "d")]) == EXIT_BAD_INPUT
    assert "is not a jointplay results file" in capsys.readouterr().err


def test_replay_gives_a_read_result_its_dense_output(tmp_path: Path) -> None:
    """The file's scene, settings and parameters run again reproduce its samples, so the
    read result gets the run's own dense output back; a file whose samples the scene does
    not reproduce is refused, with the reason."""
    from jointplay.results.look import read_result
    from jointplay.scene.definition import default_scene
    from jointplay.sim import simulate
    from jointplay.sim.dense import replay

    run = tmp_path / "run.h5"
    assert main(["simulate", "--t-end", "0.05", "--out", str(run), "--quiet"]) == 0
    back = read_result(run)
    solution, how = replay(back)
    assert solution is not None and solution.method == "bdf", how
    assert "matching the file's to 0 " in solution.accuracy
    fresh = simulate(default_scene().with_run(t_end=0.05))
    times = np.linspace(0.0, 0.05, 777)
    np.testing.assert_array_equal(solution(times), fresh.sol(times))

    changed = dataclasses.replace(back, q=back.q * (1 + 1e-6))
    solution, how = replay(changed)
    assert solution is None and "does not reproduce the file" in how
