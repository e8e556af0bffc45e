"""``jointplay calibrate`` on a mechanism: the slider-crank with 0.1 mm of radial clearance
and Coulomb friction in the rod-slider pin, simulated for its first millisecond (six
impacts) and for a revolution at known values with noise of a fixed seed; the fit recovers
them within its stated intervals. Bad input is refused at the door, naming the field, exit status 2,
nothing written."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp
from jointplay.calibration import CalibrationOptions, Measured
from jointplay.cli import main
from jointplay.common.errors import DescriptionError
from jointplay.mechanism import load_mechanism_scene, simulate_mechanism

SCENES = Path(__file__).resolve().parents[1] / "scenes"
TRUTH = {"slider_pin.clearance": 1.02e-4, "friction.mu": 0.013}
NOISE = 1e-6  # m, on the slider's position and the journal's eccentricity
COLUMNS = ("guide.position", "slider_pin.ex", "slider_pin.ey")


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """slider_crank_friction.toml at 0.1 mm of clearance (the bearing 10.1 mm), 1 ms."""
    text = (SCENES / "slider_crank_friction.toml").read_text(encoding="utf-8")
    for old, new in (("bearing_radius = 10.5e-3", "bearing_radius = 10.1e-3"),
                     ("t_end = 0.012 ", "t_end = 0.001 ")):
        assert old in text
        text = text.replace(old, new)
    path = tmp_path_factory.mktemp("scene") / "slider_crank_0_1mm_friction.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def measured(scene_file: Path) -> Path:
    """The truth's run at tolerances 1000x tighter than the scene's, plus white noise."""
    scene = load_mechanism_scene(scene_file)
    journal = 10.1e-3 - TRUTH["slider_pin.clearance"]
    run = simulate_mechanism(scene.with_run(rtol=1e-12, atol=1e-12), parameters={
        "slider_pin.journal_radius": journal, "friction.mu": TRUTH["friction.mu"]})
    exact = np.column_stack([run.coordinate("guide.position"), run.eccentricity[:, 0, 0],
                             run.eccentricity[:, 0, 1]])
    noisy = exact + NOISE * np.random.default_rng(0).standard_normal(exact.shape)
    path = scene_file.parent / "measured.csv"
    np.savetxt(path, np.column_stack([run.t, noisy]), delimiter=",", comments="",
               header="time," + ",".join(COLUMNS), fmt="%.17g")
    return path


def test_recovers_clearance_and_friction_within_the_intervals(scene_file: Path,
                                                              measured: Path) -> None:
    """From the scene's values (0.1 mm, mu 0.01: 2 % and 23 % off), the noise stated."""
    scene = load_mechanism_scene(scene_file)
    result = jp.calibrate(scene, measured, list(TRUTH), noise=NOISE)
    assert result.fit_explains_data, result.warnings
    for name, truth in TRUTH.items():
        e = result.estimates[name]
        assert e.determined, result.warnings
        assert e.low95 <= truth <= e.high95, e
        assert e.high95 - e.low95 < 0.02 * truth  # an interval that says something
    assert result.jacobian_source == dict.fromkeys(TRUTH, "central differences")
    assert len(result.starts) >= CalibrationOptions().starts  # every start fitted


def _revolution(folder: Path, truth: dict[str, float]) -> tuple[Path, Path]:
    """The slider-crank of this file over one revolution (12 ms, 16 impacts), and its measured
    table: the run at ``truth`` at 1e-12, plus white noise of the fixed seed."""
    text = (SCENES / "slider_crank_friction.toml").read_text(encoding="utf-8")
    text = text.replace("bearing_radius = 10.5e-3", "bearing_radius = 10.1e-3")
    scene_path = folder / "slider_crank_0_1mm_friction.toml"
    scene_path.write_text(text, encoding="utf-8")
    scene = load_mechanism_scene(scene_path)
    assert scene.run.t_end == 0.012
    run = simulate_mechanism(scene.with_run(rtol=1e-12, atol=1e-12), parameters={
        "slider_pin.journal_radius": 10.1e-3 - truth["slider_pin.clearance"],
        "friction.mu": truth["friction.mu"]})
    exact = np.column_stack([run.coordinate("guide.position"), run.eccentricity[:, 0, 0],
                             run.eccentricity[:, 0, 1]])
    noisy = exact + NOISE * np.random.default_rng(0).standard_normal(exact.shape)
    table = folder / "measured.csv"
    np.savetxt(table, np.column_stack([run.t, noisy]), delimiter=",", comments="",
               header="time," + ",".join(COLUMNS), fmt="%.17g")
    return scene_path, table


def test_a_revolution_is_fitted_through_growing_windows(tmp_path: Path) -> None:
    """Over a revolution the cost is a comb of narrow valleys: fitted whole from the scene's
    values, mu ended 21 % off. The multi-start runs over the first impacts (about 1 ms), its
    fits are refitted over 2, 4 and 8 ms and the whole record: both truths inside intervals
    under 0.1 % wide, the estimates within 0.03 % (measured over noise seeds 0-4: within
    0.009 %, intervals 0.02 % and 0.04 % wide, every one holding the truth)."""
    scene_path, table = _revolution(tmp_path, TRUTH)
    result = jp.calibrate(load_mechanism_scene(scene_path), table, list(TRUTH), noise=NOISE)
    assert "refitted from its last estimate over 0.002011 s, 0.004021 s, 0.008042 s, the " \
        "whole record" in result.settings["search"]
    assert result.fit_explains_data, result.warnings
    for name, truth in TRUTH.items():
        e = result.estimates[name]
        assert e.determined, result.warnings
        assert e.low95 <= truth <= e.high95, e
        assert e.high95 - e.low95 < 1e-3 * truth
        assert abs(e.value - truth) < 3e-4 * truth


def test_a_record_the_runs_cannot_resolve_determines_nothing(tmp_path: Path) -> None:
    """At 0.14 mm and mu 0.018 a revolution depends on the integrator's last digits: runs 10
    times looser than the fit's differ from them by chi² 1.2e5 (measured) at the estimate,
    whose intervals came out 4e-12 m wide. Nothing is determined, one warning says why and
    what to do, and each interval spans the search's box about the start and the estimate,
    which holds the truth."""
    truth = {"slider_pin.clearance": 1.4e-4, "friction.mu": 0.018}
    scene_path, table = _revolution(tmp_path, truth)
    result = jp.calibrate(load_mechanism_scene(scene_path), table, list(truth), noise=NOISE)
    assert result.residuals["model_error_chi2"] > 1e4
    assert len(result.warnings) == 1
    assert "10 times looser" in result.warnings[0]
    assert "Fit a shorter record" in result.warnings[0]
    for name, value in truth.items():
        e = result.estimates[name]
        assert not e.determined
        assert e.low95 <= value <= e.high95, e


def test_the_command_writes_every_file(scene_file: Path, measured: Path, tmp_path: Path,
                                       capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "cal"
    code = main(["calibrate", str(scene_file), "--measured", str(measured), "--free",
                 "slider_pin.clearance,friction.mu", "--out", str(out), "--starts", "2",
                 "--profile-points", "5"])
    printed = capsys.readouterr().out
    assert code == 0
    assert sorted(p.name for p in out.iterdir()) == sorted(
        ["calibration.json", "report.md", "fit.png", "residuals.png", "profiles.png"])
    data = json.loads((out / "calibration.json").read_text())
    for name, truth in TRUTH.items():
        estimate = data["estimates"][name]
        assert estimate["low95"] <= truth <= estimate["high95"], estimate
    assert data["settings"]["units"]["guide.position"] == "m"
    assert "noise estimated from the data's scatter" in printed
    assert "slider_pin.clearance = " in printed


def test_a_parameter_no_output_depends_on_is_not_determined(scene_file: Path,
                                                           tmp_path: Path) -> None:
    """The slider does not turn: its inertia enters no output (data at the scene's values)."""
    scene = load_mechanism_scene(scene_file)
    run = simulate_mechanism(scene.with_run(rtol=1e-12, atol=1e-12))
    noisy = run.coordinate("guide.position") + NOISE * np.random.default_rng(1).standard_normal(
        run.t.size)
    data = Measured("at the scene's values", run.t, ("guide.position",), noisy[:, None])
    result = jp.calibrate(scene, data, ["slider.inertia"], noise=NOISE,
                          options=CalibrationOptions(starts=1, scan_points=0,
                                                     profile_points=0))
    assert result.fit_explains_data, result.warnings
    assert not result.estimates["slider.inertia"].determined
    assert any("do not depend on it" in w for w in result.warnings), result.warnings
    # The profiles' runs are counted once, in one process as on several.
    profiled = jp.calibrate(scene, data, ["slider.inertia"], noise=NOISE,
                            options=CalibrationOptions(starts=1, scan_points=0,
                                                       profile_points=3, workers=1))
    assert profiled.simulations_by_kind == {**result.simulations_by_kind, "cost profiles": 3}
    assert profiled.simulations == result.simulations + 3


BAD = [
    # (extra arguments, csv text or None for the measured fixture, what the line must name)
    (["--free", "slider_pin.clerance"], None, "--free slider_pin.clerance"),
    (["--free", "crank_pin.clearance"], None, "--free crank_pin.clearance"),
    (["--free", "q2"], None, "--free q2"),
    (["--free", "slider_pin.clearance,slider_pin.journal_radius"], None,
     "--free slider_pin.journal_radius"),
    (["--free", "friction.mu", "--start", "friction.mu=9"], None, "--start friction.mu"),
    (["--free", "friction.mu", "--noise", "tip_x=1e-6"], None, "--noise tip_x"),
    (["--free", "friction.mu", "--grid-window", "0.01"], None, "--grid-window"),
    (["--free", "friction.mu", "--horizon-first", "0.01"], None, "--horizon-first"),
    # the fit's tolerances (the scene's divided by it) would fall below what a run accepts
    (["--free", "friction.mu", "--tighten", "1e300"], None, "--tighten: must be at most"),
    (["--free", "friction.mu"], "time,tip_x\n0,0\n1e-5,0\n2e-5,0\n", "tip_x"),
    (["--free", "friction.mu"], "time,t\n0,0\n1e-5,0\n2e-5,0\n", "t: is the model's clock"),
    (["--free", "friction.mu"], "time,guide.position\n0,0\n1e-5,0\n1.5e-5,0\n",
     "not on the run's output grid"),
    (["--free", "friction.mu"], "time,guide.position\n0,0\n1e-5,0\n0.5,0\n",
     "after the scene's run ends"),
    (["--free", "friction.mu"], "time,guide.position\n0,0\n1e-5,nan\n2e-5,0\n",
     "row 3 column guide.position"),
]


@pytest.mark.parametrize(("flags", "table", "named"), BAD)
def test_bad_input_is_one_line_exit_2_nothing_written(
        scene_file: Path, measured: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str],
        flags: list[str], table: str | None, named: str) -> None:
    data = measured
    if table is not None:
        data = tmp_path / "bad.csv"
        data.write_text(table, encoding="utf-8")
    out = tmp_path / "cal"
    code = main(["calibrate", str(scene_file), "--measured", str(data), "--out", str(out),
                 *flags])
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1 and named in err, err
    assert not out.exists()


def test_a_table_with_a_byte_order_mark_reads_as_without(scene_file: Path, measured: Path,
                                                         tmp_path: Path) -> None:
    """A spreadsheet's CSV starts with a UTF-8 byte-order mark: the same samples."""
    from jointplay.mechanism.calibration_inputs import read_mechanism_measured
    from jointplay.mechanism.model import model_for

    model = model_for(load_mechanism_scene(scene_file).mechanism)
    marked = tmp_path / "marked.csv"
    marked.write_bytes(b"\xef\xbb\xbf" + measured.read_bytes())
    plain, bom = read_mechanism_measured(measured, model), read_mechanism_measured(marked, model)
    assert bom.columns == plain.columns == COLUMNS
    np.testing.assert_array_equal(bom.t, plain.t)
    np.testing.assert_array_equal(bom.values, plain.values)


def test_friction_of_a_frictionless_mechanism_is_refused() -> None:
    scene = load_mechanism_scene(SCENES / "slider_crank_0_1mm.toml")
    data = Measured("m", np.array([0.0, 1e-5, 2e-5]), ("guide.position",), np.zeros((3, 1)))
    with pytest.raises(DescriptionError, match=r"free friction\.mu: .*friction is off"):
        jp.calibrate(scene, data, ["friction.mu"])


def test_a_results_file_gives_the_coordinates_and_eccentricities(
        scene_file: Path, tmp_path: Path) -> None:
    from jointplay.mechanism.calibration import prepare_mechanism

    run = tmp_path / "run.h5"
    assert main(["simulate", str(scene_file), "--no-verify", "--quiet", "--out",
                 str(run)]) == 0
    problem = prepare_mechanism(load_mechanism_scene(scene_file), run, ["friction.mu"],
                                noise=NOISE)
    assert problem.measured.columns == ("guide.position", "crank_pin.angle", "slider_pin.ex",
                                        "slider_pin.ey")
    assert problem.measured.t.size == 101
    other = tmp_path / "other.h5"
    other.write_text("not HDF5", encoding="utf-8")
    with pytest.raises(DescriptionError, match="not a mechanism results file"):
        prepare_mechanism(load_mechanism_scene(scene_file), other, ["friction.mu"])


def test_another_starts_minimum_within_the_threshold_leaves_the_parameter_undetermined(
        ) -> None:
    """The verdict's glue, without runs: a second start ending 10 standard deviations away,
    chi² 1 above the best, lies inside the 95 % profile-likelihood interval; the interval
    spans it and the parameter is not determined. Profile points within the threshold widen
    the interval too; one 4 above the best does not."""
    from jointplay.calibration.basins import widened
    from jointplay.calibration.fit import Optimum, Start
    from jointplay.calibration.uncertainty import uncertainty
    from jointplay.mechanism.calibration import _basins

    residuals = np.full(10, 1.0)  # chi² 10
    jacobian = np.full((10, 1), 10.0 / np.sqrt(10.0))  # std 0.1
    starts = (Start((1.0,), (1.0,), 10.0, 5, "best"), Start((3.0,), (2.0,), 11.0, 5, "other"))
    optimum = Optimum(np.array([1.0]), np.ones(1), residuals, jacobian, starts)
    spread = uncertainty(jacobian, optimum.values, np.array([0.0]), np.array([10.0]), ("p",))
    assert spread.std[0] == pytest.approx(0.1)
    found = _basins(optimum, spread, {})
    low, high, determined, warnings = widened(spread, found, ("p",))
    assert not determined[0] and low[0] < 1.0 - 0.19 and high[0] >= 2.0
    assert "other minimum" in warnings[0]
    alone = dataclasses.replace(optimum, starts=starts[:1])
    profiles = {"p": {"value": [0.5, 1.25, 1.5], "chi2": [14.5, 12.0, 14.0]}}
    low, high, determined, _ = widened(spread, _basins(alone, spread, profiles), ("p",))
    assert determined[0] and high[0] == 1.25 and low[0] == pytest.approx(1.0 - 1.96 * 0.1,
                                                                       rel=1e-3)


class _Walled:
    """A predictor of one parameter whose model is the line y = x (data at 1.0, 10 samples)
    and whose runs stop between 0.9 and 1.1, where a Gauss-Newton step from 0 lands."""

    compiled: tuple[str, ...] = ()

    def __init__(self, retreats: bool) -> None:
        from jointplay.calibration.parameters import FreeParameters
        from jointplay.calibration.predict import Counter

        self.retreats_from_failures = retreats
        self.free = FreeParameters(("p",), np.array([0.0]), np.array([-5.0]), np.array([5.0]))
        self.measured = Measured("line", np.arange(10.0), ("y",), np.ones((10, 1)))
        self.counter = Counter()

    def outputs(self, x: np.ndarray, *, with_jacobian: bool = True) -> np.ndarray:
        from jointplay.calibration.predict import TrialFailed

        if 0.9 < x[0] < 1.1:
            raise TrialFailed(f"the run at p = {x[0]:.6g} stopped")
        return np.full((10, 1), float(x[0]))

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        return np.ones((10, 1, 1))


def test_a_mechanisms_fit_steps_back_from_a_run_that_stops() -> None:
    """A trial run that stops ends an arm's local fit; a mechanism's predictor retreats: SciPy
    shrinks its trust region and the fit goes on, ending nearer the data than it began."""
    from jointplay.calibration.fit import _local_fit

    ends = _local_fit(_Walled(retreats=False), np.ones(1), np.array([0.0]), 40)  # type: ignore[arg-type]
    assert ends.failed and "stopped" in ends.message
    goes_on = _local_fit(_Walled(retreats=True), np.ones(1), np.array([0.0]), 40)  # type: ignore[arg-type]
    assert not goes_on.failed
    assert 0.5 < goes_on.end[0] <= 0.9 and goes_on.chi2 < 10.0  # chi² 10 at the start


@pytest.mark.slow
def test_the_benchmark_on_exudyns_data_runs(tmp_path: Path) -> None:
    """``benchmarks/mechanism_calibration.py --quick --seeds 1``: Exudyn's revolution at the
    example's truth, calibrated from the scene's values; both intervals hold the truth, both
    parameters determined, the table and the CSV written."""
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[1]
    done = subprocess.run([sys.executable, "benchmarks/mechanism_calibration.py", "--out",
                           str(tmp_path), "--quick", "--seeds", "1"], cwd=root,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    table = (tmp_path / "mechanism_calibration.md").read_text(encoding="utf-8")
    assert "| 0.102 | 0.013 | stated | 2 of 2 | 2 (0) |" in table, table
    rows = (tmp_path / "mechanism_calibration.csv").read_text(encoding="utf-8").splitlines()
    assert len(rows) == 2


def test_the_continuations_growth_is_a_mechanisms_option_its_first_window_is_not(
        scene_file: Path, measured: Path) -> None:
    """``horizon_growth`` shapes a mechanism's continuation too; ``horizon_first`` belongs to
    the arms (a mechanism's first window holds its first impacts) and is refused, naming it."""
    from jointplay.mechanism.calibration import prepare_mechanism

    scene = load_mechanism_scene(scene_file)
    problem = prepare_mechanism(scene, measured, ["friction.mu"], noise=NOISE,
                                options=CalibrationOptions(horizon_growth=3.0))
    assert problem.options.horizon_growth == 3.0
    with pytest.raises(DescriptionError, match=r"options\.horizon_growth") as info:
        prepare_mechanism(scene, measured, ["friction.mu"], noise=NOISE,
                          options=CalibrationOptions(horizon_first=0.01))
    assert info.value.field == "options.horizon_first"
