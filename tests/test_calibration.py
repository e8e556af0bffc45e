"""jointplay.calibrate and ``jointplay calibrate``: parameters estimated from measured motion.

Recovery is checked on the paper arm with ideal joints (no impacts: a smooth cost), from
synthetic measurements made at tolerances 100x tighter than the fit's runs with 1 µm of
seeded noise: the estimates within 1e-3 relative of the truth, which lies inside the 95 %
intervals, chi²/dof within 0.85-1.15 (600-1000 degrees of freedom: its spread is ±0.06).
Two parameters the data cannot separate (the inertias of links 3 and 4, welded together by
the locked joint 4) are flagged. Every bad input exits 2 with one line and writes nothing.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import json
import math
import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import jointplay as jp
from jointplay.calibration import CalibrationOptions, Measured, calibrate
from jointplay.calibration.continuation import horizon_windows
from jointplay.calibration.fit import explaining_limit
from jointplay.calibration.report import report_text
from jointplay.cli import main
from jointplay.common.errors import DescriptionError

SCENES = Path(__file__).resolve().parents[1] / "scenes"
NOISE = 1e-6
FAST = CalibrationOptions(starts=2, scan_points=0, profile_points=5)


def _ideal_scene(t_end: float = 0.4) -> jp.Scene:
    scene = jp.default_scene()
    return scene.with_robot(jp.ideal_counterpart(scene.robot)).with_run(
        t_end=t_end, rtol=2e-8, atol=3e-9)


def _synthetic(scene: jp.Scene, truth: dict[str, float], seed: int,
               tighter: float = 100.0) -> Measured:
    """Tip measurements of ``scene`` with ``truth``, at tolerances ``tighter`` times tighter,
    + noise (the benchmark's draws: 1e4 times, noise seed the draw's number)."""
    exact = jp.simulate(scene.with_run(rtol=scene.run.rtol / tighter,
                                       atol=scene.run.atol / tighter), parameters=truth)
    rng = np.random.default_rng(seed)
    tip = exact.tip_position + NOISE * rng.standard_normal(exact.tip_position.shape)
    return Measured(f"synthetic seed {seed}", exact.t.copy(), ("tip_x", "tip_y"), tip)


def test_recovers_parameters_with_intervals_that_cover() -> None:
    scene = _ideal_scene()
    truth = {"payload.mass": 2.3, "link2.com": 0.19}
    result = calibrate(scene, _synthetic(scene, truth, seed=1), list(truth), noise=NOISE,
                       options=FAST.__class__(tighten=1.0, starts=2, scan_points=0,
                                              profile_points=5))
    for name, value in truth.items():
        estimate = result.estimates[name]
        assert abs(estimate.value - value) <= 1e-3 * value
        assert estimate.low95 <= value <= estimate.high95
        assert estimate.determined
        assert estimate.start == pytest.approx(2.0 if name == "payload.mass" else 0.175)
    assert 0.85 <= result.residuals["normalised_chi2"] <= 1.15
    assert result.jacobian_source == {n: "compiled sensitivities" for n in truth}
    assert not result.warnings
    assert result.simulations == sum(result.simulations_by_kind.values()) > 0
    # five points each, the middle one the estimate itself (its chi² known, not run again)
    assert result.simulations_by_kind["cost profiles"] == 4 * len(truth)
    profile = result.profiles["payload.mass"]
    assert len(profile["value"]) == 5 and min(profile["chi2"]) >= result.residuals["chi2"] - 1e-6


def test_horizon_continuation_grows_the_window_from_the_previous_estimate() -> None:
    """Windows of 0.05, 0.1, 0.2 s, then the whole 0.4 s record: each stage starts where the
    previous one ended and settles, the last stage is the reported fit (the basin check off:
    its local fits may end a little lower in the same basin, 0.003 in chi² here, and move
    the estimate there), and it recovers the truth."""
    scene = _ideal_scene()
    truth = {"payload.mass": 2.3, "link2.com": 0.19}
    options = CalibrationOptions(tighten=1.0, starts=1, scan_points=0, profile_points=0,
                                 horizon_first=0.05, horizon_growth=2.0, basins=False)
    result = calibrate(scene, _synthetic(scene, truth, seed=3), list(truth), noise=NOISE,
                       options=options)
    stages = result.stages
    assert [s.window_end for s in stages] == pytest.approx([0.05, 0.1, 0.2, 0.4])
    assert [s.samples for s in stages] == [51, 101, 201, 401]
    assert stages[0].start == pytest.approx((2.0, 0.175))
    for before, after in itertools.pairwise(stages):
        assert after.start == before.end
    assert stages[-1].end == tuple(result.values)
    # the windows' fits settle as the whole record's does (they only rank the tracks)
    assert all(s.message.startswith("settled") for s in stages)
    for name, value in truth.items():
        estimate = result.estimates[name]
        assert abs(estimate.value - value) <= 1e-3 * value
        assert estimate.low95 <= value <= estimate.high95 and estimate.determined
    assert result.simulations_by_kind["continuation windows"] > 0
    saved = result.to_dict()["continuation"]
    assert [s["window_end"] for s in saved] == pytest.approx([0.05, 0.1, 0.2, 0.4])
    assert "4 fits over growing windows" in report_text(result)


def test_the_last_window_is_left_out_after_a_window_no_track_explains() -> None:
    """Windows of 0.05-0.4 s before a 0.5 s record (under sqrt(2) times the last): data the
    model explains are fitted on all four; data from another link 2 centre of mass (not
    free) on the first three (the 0.2 s window explains nothing), then on the whole record."""
    scene = _ideal_scene(0.5)
    options = CalibrationOptions(tighten=1.0, starts=1, scan_points=0, profile_points=0,
                                 horizon_first=0.05, horizon_growth=2.0, basins=False)
    ends = {}
    for label, truth in (("explained", {"payload.mass": 2.3}),
                         ("misfit", {"payload.mass": 2.3, "link2.com": 0.21})):
        result = calibrate(scene, _synthetic(scene, truth, seed=3), ["payload.mass"],
                           noise=NOISE, options=options)
        ends[label] = [s.window_end for s in result.stages]
        at_02 = next(s for s in result.stages if s.window_end == pytest.approx(0.2))
        assert (at_02.chi2 > explaining_limit(at_02.dof)) == (label == "misfit")
    assert ends["explained"] == pytest.approx([0.05, 0.1, 0.2, 0.4, 0.5])
    assert ends["misfit"] == pytest.approx([0.05, 0.1, 0.2, 0.5])


def test_horizon_windows() -> None:
    t = np.arange(0, 2.0005, 1e-3)
    assert horizon_windows(t, 2, 3, 0.005, 2.0) == pytest.approx(
        [0.005 * 2**k for k in range(9)])
    assert horizon_windows(t, 2, 3, 0.005, 4.0) == pytest.approx([0.005, 0.02, 0.08, 0.32,
                                                                  1.28])
    # a first window holding too few numbers for the free parameters is lengthened
    assert horizon_windows(t, 1, 3, 0.001, 2.0)[0] == pytest.approx(0.008)
    assert horizon_windows(t[:4], 2, 3, 0.005, 2.0) == []


def test_parameters_the_data_cannot_separate_are_flagged() -> None:
    scene = _ideal_scene(0.2)
    truth = {"link3.inertia": 0.0125, "link4.inertia": 4.2e-4}
    result = calibrate(scene, _synthetic(scene, truth, seed=2), list(truth), noise=NOISE,
                       options=CalibrationOptions(tighten=1.0, starts=1, scan_points=0,
                                                  profile_points=0))
    for name, partner in (("link3.inertia", "link4.inertia"),
                          ("link4.inertia", "link3.inertia")):
        estimate = result.estimates[name]
        assert not estimate.determined
        assert estimate.high95 - estimate.low95 > estimate.value
        assert any(name in w and partner in w and "not determined" in w
                   for w in result.warnings)
    assert abs(result.correlation[0, 1]) > 0.99
    assert result.condition_number > 1e8


@pytest.mark.slow
def test_standard_deviation_matches_the_spread_over_noise_seeds() -> None:
    """The reported std against the spread of the estimates over 40 noise seeds: the
    sample std of 40 draws has a standard error of about 11 %, so the ratio must lie within
    three of them, 0.7-1.45."""
    scene = _ideal_scene(0.3)
    truth = {"payload.mass": 2.3, "link2.com": 0.19}
    options = CalibrationOptions(tighten=1.0, starts=1, scan_points=0, profile_points=0)
    estimates, stds = [], []
    for seed in range(40):
        result = calibrate(scene, _synthetic(scene, truth, seed=seed), list(truth),
                           noise=NOISE, start=truth, options=options)
        estimates.append(result.values)
        stds.append([e.std for e in result.estimates.values()])
    spread = np.std(estimates, axis=0, ddof=1)
    ratio = np.median(stds, axis=0) / spread
    assert np.all((ratio > 0.7) & (ratio < 1.45)), ratio


# ---- the command -------------------------------------------------------------------------

@pytest.fixture
def short_scene(tmp_path: Path) -> Path:
    text = (SCENES / "paper_4dof.toml").read_text()
    path = tmp_path / "short.toml"
    path.write_text(text.replace("t_end = 2.0 ", "t_end = 0.02 "))
    return path


def _csv(path: Path, header: str, rows: list[list[float | str]]) -> Path:
    path.write_text(header + "\n" + "\n".join(",".join(str(c) for c in r) for r in rows)
                    + "\n")
    return path


def _measured_csv(tmp_path: Path, scene_path: Path) -> Path:
    scene = jp.load_scene(str(scene_path))
    run = jp.simulate(scene.with_run(rtol=2e-10, atol=3e-11, output_step=5e-4),
                      parameters={"payload.mass": 2.2})
    rows = [[t, x, y] for t, (x, y) in zip(run.t, run.tip_position, strict=True)]
    return _csv(tmp_path / "measured.csv", "time,tip_x,tip_y", rows)


def test_command_writes_every_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """On the arm with ideal joints (a smooth cost), measured at half the output step: the
    model is sampled by its dense output between the run's samples."""
    text = (SCENES / "paper_4dof.toml").read_text().replace('kind = "clearance"',
                                                            'kind = "ideal"')
    text = re.sub(r"^e[xy][23] = 0.0\n", "", text, flags=re.M)
    scene_path = tmp_path / "ideal.toml"
    scene_path.write_text(text.replace("t_end = 2.0 ", "t_end = 0.1 "))
    measured = _measured_csv(tmp_path, scene_path)
    out = tmp_path / "cal"
    code = main(["calibrate", str(scene_path), "--measured", str(measured), "--free",
                 "payload.mass", "--noise", "tip_x=1e-6,tip_y=1e-6", "--out", str(out),
                 "--starts", "1", "--scan-points", "0", "--profile-points", "3", "--quiet"])
    assert code == 0
    assert sorted(p.name for p in out.iterdir()) == sorted(
        ["calibration.json", "report.md", "fit.png", "residuals.png", "profiles.png"])
    data = json.loads((out / "calibration.json").read_text())
    estimate = data["estimates"]["payload.mass"]
    assert estimate["value"] == pytest.approx(2.2, rel=1e-4)
    assert estimate["std"] > 0
    assert data["correlation"]["names"] == ["payload.mass"]
    assert {"rms", "chi2", "dof", "normalised_chi2"} <= set(data["residuals"])
    assert data["simulations"] > 0 and data["wall_time_s"] > 0
    assert "payload.mass" in (out / "report.md").read_text()
    assert capsys.readouterr().out == ""
    # the basin check runs by default; --no-basin-check skips it (no lines run)
    assert data["settings"]["basins"] is True
    assert data["simulations_by_kind"]["basin lines"] > 0
    skipped = tmp_path / "without"
    assert main(["calibrate", str(scene_path), "--measured", str(measured), "--free",
                 "payload.mass", "--noise", "1e-6", "--out", str(skipped), "--starts", "1",
                 "--scan-points", "0", "--profile-points", "0", "--no-basin-check",
                 "--quiet"]) == 0
    without = json.loads((skipped / "calibration.json").read_text())
    assert without["settings"]["basins"] is False
    assert without["simulations_by_kind"]["basin lines"] == 0
    assert without["estimates"]["payload.mass"]["value"] == pytest.approx(2.2, rel=1e-4)


BAD_INPUTS = [
    # (csv header, rows, extra flags, what the one line must name)
    ("time,tip_x", [[0.0, 0.1], [0.001, "nan"], [0.002, 0.1]], [], "row 3 column tip_x"),
    ("time,tip_x", [[0.0, 0.1], [0.002, 0.1], [0.001, 0.1]], [], "must increase strictly"),
    ("time,tip_x", [[0.0, 0.1], [0.001, 0.1]], [], "at least 3"),
    ("time,tip_x", [[0.0, 0.1], [0.01, 0.1], [0.05, 0.1]], [], "after the scene's run ends"),
    ("time,tip_x", [[-0.001, 0.1], [0.0, 0.1], [0.01, 0.1]], [], "before the run starts"),
    ("time,tip_z", [[0.0, 0.1], [0.001, 0.1], [0.002, 0.1]], [], "tip_z"),
    ("tip_x,tip_y", [[0.0, 0.1], [0.001, 0.1], [0.002, 0.1]], [], "time: column is missing"),
    ("time,tip_x", [[0.0, 0.1], [0.001, 0.1], [0.002, 0.1]], ["--free", "friction.muu"],
     "--free friction.muu"),
    ("time,tip_x", [[0.0, 0.1], [0.001, 0.1], [0.002, 0.1]], ["--free", "joint4.clearance"],
     "--free joint4.clearance"),
    ("time,tip_x", [[0.0, 0.1], [0.001, 0.1], [0.002, 0.1]], ["--start", "friction.mu=7"],
     "--start friction.mu"),
    ("time,tip_x", [[0.0, 0.1], [0.001, 0.1], [0.002, 0.1]], ["--noise", "tip_y=1e-6"],
     "--noise tip_y"),
    ("time,tip_x", [[0.0, 0.1], [0.001, 0.1], [0.002, 0.1]], ["--noise", "-1"], "--noise"),
]


@pytest.mark.parametrize(("header", "rows", "flags", "named"), BAD_INPUTS)
def test_bad_input_is_one_line_exit_2_nothing_written(
        tmp_path: Path, short_scene: Path, capsys: pytest.CaptureFixture[str], header: str,
        rows: list[list[float | str]], flags: list[str], named: str) -> None:
    measured = _csv(tmp_path / "m.csv", header, rows)
    out = tmp_path / "cal"
    args = ["calibrate", str(short_scene), "--measured", str(measured), "--out", str(out)]
    if "--free" not in flags:
        args += ["--free", "friction.mu"]
    code = main(args + flags)
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1 and named in err, err
    if "--free" not in flags and "--start" not in flags and "--noise" not in flags:
        assert str(measured) in err  # a problem of the file names the file
    assert not out.exists()


def test_a_parameter_the_model_does_not_have() -> None:
    """Friction acts in journals with play: the arm with ideal joints has none."""
    scene = _ideal_scene(0.01)
    data = Measured("m", np.array([0.0, 0.005, 0.01]), ("tip_x",), np.zeros((3, 1)))
    with pytest.raises(DescriptionError, match=r"free friction\.mu: is not a parameter"):
        calibrate(scene, data, ["friction.mu"])


def test_a_fit_that_does_not_explain_the_data_claims_nothing() -> None:
    """Noise stated 100x smaller than it is: chi²/dof near 1e4, so no estimate is reported as
    determined, one warning says why, and the interval spans the box the search covered."""
    scene = _ideal_scene(0.1)
    truth = {"payload.mass": 2.3}
    result = calibrate(scene, _synthetic(scene, truth, seed=3), list(truth), noise=NOISE / 100,
                       options=CalibrationOptions(tighten=1.0, starts=1, scan_points=0,
                                                  profile_points=0))
    assert result.fit_explains_data is False
    assert result.residuals["normalised_chi2"] > 1e3
    estimate = result.estimates["payload.mass"]
    assert not estimate.determined
    start = estimate.start
    assert estimate.low95 <= 0.5 * start and estimate.high95 >= 1.5 * start
    assert len(result.warnings) == 1 and "nothing is determined" in result.warnings[0]
    assert "larger than the noise" in result.warnings[0]


@pytest.mark.parametrize(("factor", "side"), [(1.25, "larger"), (0.5, "smaller")])
def test_a_chi2_outside_its_99_percent_range_claims_nothing(factor: float, side: str) -> None:
    """Noise stated 1.25x too small (chi²/dof near 1.56 on 401 degrees of freedom, its 99 %
    range 0.83-1.19) or 2x too large (near 0.25): nothing determined, one warning and the
    report's top say why; with the noise stated as it is, the same fit is determined."""
    scene = _ideal_scene(0.2)
    truth = {"payload.mass": 2.3}
    measured = _synthetic(scene, truth, seed=3)
    options = CalibrationOptions(tighten=1.0, starts=1, scan_points=0, profile_points=0)
    honest = calibrate(scene, measured, list(truth), noise=NOISE, options=options)
    assert honest.fit_explains_data and honest.estimates["payload.mass"].determined
    assert honest.warnings == ()
    wrong = calibrate(scene, measured, list(truth), noise=NOISE / factor, options=options)
    assert wrong.fit_explains_data is False
    assert not wrong.estimates["payload.mass"].determined
    assert len(wrong.warnings) == 1 and f"the residuals are {side} than the noise" \
        in wrong.warnings[0]
    assert "nothing is determined" in report_text(wrong)
    assert wrong.to_dict()["fit_explains_data"] is False


def test_the_noise_is_read_from_the_datas_scatter_through_the_impacts() -> None:
    """Paper scene with clearance (impacts), 2 s at 1 ms, tip (1 µm) and joint angles
    (5 µrad) over 5 noise seeds: each column's noise estimated from the data alone within
    4 of the estimate's own standard deviations (about 2.5 %) of the truth, and the same
    at 2 ms sampling; a misfit cannot move it (no model enters)."""
    from jointplay.calibration.noise import column_noise

    scene = jp.default_scene()
    exact = jp.simulate(scene.with_run(rtol=2e-10, atol=3e-11), parameters={
        "joint2.clearance": 23.949e-6, "joint3.clearance": 44.009e-6, "friction.mu": 0.071})
    clean = np.column_stack([exact.tip_position, exact.q[:, 1:3]])
    truth = np.array([1e-6, 1e-6, 5e-6, 5e-6])
    for seed, step in itertools.product(range(5), (1, 2)):
        rng = np.random.default_rng(seed)
        values = (clean + truth * rng.standard_normal(clean.shape))[::step]
        sigma, spread = column_noise(Measured("m", exact.t[::step], ("tip_x", "tip_y", "q2",
                                                                     "q3"), values))
        relative_std = np.sqrt(spread) / 2
        assert np.all(relative_std < 0.04)
        assert np.all(np.abs(sigma / truth - 1) <= 4 * relative_std), (seed, step, sigma)


def test_the_whiteness_test_sees_slow_waves_the_chi2_range_misses() -> None:
    """White residuals pass; a slow wave of a third of the noise (chi²/dof 1.06 on 1997,
    inside its 99 % range 0.92-1.08) fails the Ljung-Box test."""
    from jointplay.calibration.noise import residual_check

    rng = np.random.default_rng(0)
    white = rng.standard_normal((1000, 2))
    assert residual_check(white, np.ones(2), 1997, None, ("a", "b")) is None
    waves = white + 0.35 * np.sin(np.arange(1000) / 30)[:, None]
    found = residual_check(waves, np.ones(2), 1997, None, ("a", "b"))
    assert found is not None and "Ljung-Box" in found


@pytest.mark.parametrize(("flags", "named"), [
    (["--measured", "absent.csv"], "--measured: absent.csv does not exist"),
    (["--spread", "1.5"], "--spread: must lie between 0 and 1"),
    (["--starts", "0"], "--starts: must be >= 1"),
    (["--horizon-growth", "1"], "--horizon-growth: must be > 1"),
    (["--horizon-first", "-0.01"], "--horizon-first: must be >= 0"),
    (["--grid-points", "2"], "--grid-points: must be >= 3"),
    (["--grid-window", "-1"], "--grid-window: must be >= 0"),
    (["--grid-line-points", "2"], "--grid-line-points: must be 0 (no line) or >= 3"),
    (["--valley-check-points", "1"], "--valley-check-points: must be 0 (no check) or >= 3"),
    (["--seed", "-1"], "--seed: must be an integer >= 0, got -1"),
    (["--tighten", "inf"], "--tighten: must be a finite number >= 1"),
    # the scene's tolerances divided by it would fall below what a run accepts
    (["--tighten", "1e300", "--noise", "1e-6"], "--tighten: must be at most 2e+08"),
    (["--free", ""], "--free: is empty; give a value (NAME[,NAME...])"),
    (["--scheduler", ""], "--scheduler: is empty; give a value (ADDRESS)"),
])
def test_bad_flags_exit_2(tmp_path: Path, short_scene: Path,
                          capsys: pytest.CaptureFixture[str], flags: list[str],
                          named: str) -> None:
    measured = _csv(tmp_path / "m.csv", "time,tip_x", [[0.0, 0.1], [0.001, 0.1], [0.002, 0.1]])
    out = tmp_path / "cal"
    args = ["calibrate", str(short_scene), "--measured", str(measured), "--free",
            "friction.mu", "--out", str(out)]
    assert main(args + flags) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and named in err, err
    assert not out.exists()


def test_central_difference_fallback_agrees_with_the_sensitivities() -> None:
    """The Jacobian by central differences (used for a name the compiled sensitivities do
    not cover) against the compiled one, on the arm with ideal joints: 1e-4 relative to the
    largest entry (the differences' step is 1e-2 relative, truncation O(h²))."""
    from jointplay.calibration.api import prepare
    from jointplay.calibration.predict import Predictor

    scene = _ideal_scene(0.2)
    truth = {"payload.mass": 2.3, "link2.com": 0.19}
    problem = prepare(scene, _synthetic(scene, truth, seed=4), list(truth), noise=NOISE)
    compiled = Predictor(problem.scene, problem.model, problem.free, problem.measured)
    assert compiled.compiled == tuple(truth)
    fallback = Predictor(problem.scene, problem.model, problem.free, problem.measured)
    fallback.compiled = ()
    x = problem.free.start
    exact, approximate = compiled.jacobian(x), fallback.jacobian(x)
    for k in range(len(truth)):
        scale = np.abs(exact[:, :, k]).max()
        assert np.abs(approximate[:, :, k] - exact[:, :, k]).max() <= 1e-4 * scale
    assert fallback.counter.by_kind["plain"] == 1 + 2 * len(truth)


def test_a_fit_runs_sensitivities_only_where_it_asks_for_the_jacobian(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """A local fit's residuals come from runs without sensitivities, except its first; the
    Jacobian, asked for at the accepted points only, takes a run with them there. The fit is
    the same, to the bit, as one whose every evaluation carries them (a run's outputs do not
    depend on whether it integrates sensitivities), at fewer sensitivity runs; and a
    predictor for held parameters shares its parent's last run."""
    from jointplay.calibration import fit as fit_module
    from jointplay.calibration.api import prepare
    from jointplay.calibration.continuation import _holding
    from jointplay.calibration.predict import Predictor

    scene = _ideal_scene(0.2)
    truth = {"payload.mass": 2.3, "link2.com": 0.19}
    problem = prepare(scene, _synthetic(scene, truth, seed=5), list(truth), noise=NOISE)
    weights = np.full(2, NOISE)
    x0 = problem.free.start
    asked: list[bytes] = []

    def fitted(every: bool) -> tuple[Any, Predictor]:
        predictor = Predictor(problem.scene, problem.model, problem.free, problem.measured)
        outputs, jacobian = predictor.outputs, predictor.jacobian

        def tracked(x: np.ndarray) -> np.ndarray:
            asked.append(np.asarray(x, float).tobytes())
            return jacobian(x)

        if every:
            monkeypatch.setattr(predictor, "outputs",
                                lambda x, with_jacobian=True: outputs(x, with_jacobian=True))
        monkeypatch.setattr(predictor, "jacobian", tracked)
        return fit_module._local_fit(predictor, weights, x0, 40), predictor

    asked.clear()
    lean, lean_predictor = fitted(every=False)
    jacobian_points = len(asked)
    full, full_predictor = fitted(every=True)
    assert lean.end == full.end and lean.chi2 == full.chi2
    assert lean.evaluations == full.evaluations >= jacobian_points >= 2
    counts = lean_predictor.counter.by_kind
    assert counts["sensitivities"] == jacobian_points
    assert counts["plain"] == lean.evaluations - 1
    assert full_predictor.counter.by_kind["sensitivities"] == full.evaluations
    held = lean_predictor.for_free(_holding(problem.free, np.array(lean.end),
                                            np.array([False, True])))
    held.jacobian(np.array(lean.end))
    assert held.counter.simulations == 0 and held.free.upper[1] < problem.free.upper[1]


def test_a_whole_record_fit_settles_within_a_tenth_of_a_standard_deviation() -> None:
    """A whole-record fit ends once its next step lies within SETTLED_SIGMAS standard
    deviations of its best point: at fewer runs than SciPy's own tolerances take, within
    that distance (in the metric of the Jacobian) of where they
    end and at a chi² a hundredth from theirs, on the arm with ideal joints (a smooth
    cost). With ``relative`` (the friction's fit before the grid) it also ends once its
    next step moves each parameter by less than that fraction: no later, within twice that
    fraction of the full fit's estimate."""
    from jointplay.calibration import fit as fit_module
    from jointplay.calibration.api import prepare
    from jointplay.calibration.predict import Predictor, whitened

    scene = _ideal_scene(0.2)
    truth = {"payload.mass": 2.3, "link2.com": 0.19}
    problem = prepare(scene, _synthetic(scene, truth, seed=5), list(truth), noise=NOISE)
    weights = np.full(2, NOISE)

    def fitted(settle: bool, relative: float = 0.0) -> tuple[Any, Predictor]:
        predictor = Predictor(problem.scene, problem.model, problem.free, problem.measured)
        _, record = fit_module.multi_start(predictor, weights, problem.free.start[None, :],
                                           40, stop_early=False, settle=settle,
                                           relative=relative)
        return record[0], predictor

    settled, _ = fitted(True)
    full, predictor = fitted(False)  # SciPy's ftol or xtol ends it
    assert settled.message.startswith("settled") and not full.message.startswith("settled")
    assert settled.evaluations < full.evaluations
    jacobian = whitened(predictor.jacobian(np.array(full.end)), weights)
    distance = np.linalg.norm(jacobian @ (np.array(settled.end) - np.array(full.end)))
    assert distance < fit_module.SETTLED_SIGMAS
    assert abs(settled.chi2 - full.chi2) < 0.01
    coarse, _ = fitted(True, relative=1e-2)
    assert coarse.message.endswith("or 0.01 of its values")
    assert coarse.evaluations <= settled.evaluations
    assert np.all(np.abs(np.array(coarse.end) - full.end) <= 2e-2 * np.abs(full.end))


class _Banana:
    """A stand-in predictor: Rosenbrock's valley in two entries of 25 x 2 outputs (a fit creeps
    along it), the other 48 held ``offset`` from the data whatever the parameters."""

    def __init__(self, offset: float) -> None:
        from types import SimpleNamespace

        self.free = SimpleNamespace(size=2, lower=np.full(2, -5.0), upper=np.full(2, 5.0))
        self.measured = SimpleNamespace(size=50, values=np.zeros((25, 2)))
        self.offset = offset

    def outputs(self, x: np.ndarray, with_jacobian: bool = True) -> np.ndarray:
        y = np.full((25, 2), self.offset)
        y[0] = 10.0 * (x[1] - x[0] ** 2), 1.0 - x[0]
        return y

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        jac = np.zeros((25, 2, 2))
        jac[0] = [[-20.0 * x[0], 10.0], [-1.0, 0.0]]
        return jac


def test_a_fit_that_cannot_reach_a_chi2_the_noise_explains_gives_up_at_its_pace() -> None:
    """With ``give_up``, a fit whose chi² lies above the explaining limit ends once, at the
    pace of its last PACE_EVALUATIONS evaluations or more, the rest of its evaluations could
    not bring it there: on a misfit creeping along Rosenbrock's valley (chi² about 1,200
    against a limit of 97) it stops after PACE_EVALUATIONS or a few more, at its best point
    so far, where the same fit without it goes on; a fit the data can explain never gives
    up (the same fit either way)."""
    from jointplay.calibration import fit as fit_module

    start, weights = np.array([-1.2, 1.0]), np.ones(2)

    def fitted(offset: float, give_up: bool) -> Any:
        return fit_module._local_fit(_Banana(offset), weights, start, 40,  # type: ignore[arg-type]
                                     give_up=give_up)

    creeping, full = fitted(5.0, True), fitted(5.0, False)
    assert creeping.message.startswith("gave up: chi²") and "too slowly" in creeping.message
    assert fit_module.PACE_EVALUATIONS <= creeping.evaluations < full.evaluations
    assert full.chi2 <= creeping.chi2 < 48 * 25.0 + 24.2  # below the start's chi²
    assert fit_module.explaining_limit(48) < full.chi2
    assert fitted(0.0, True) == fitted(0.0, False)


def test_a_multi_start_without_a_usable_fit_stops_saying_why(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Where every start stopped, one SimulationError names the first failure; where none
    stopped but none reached a finite chi² (a fit settled at a point it never evaluated), the
    same error says so instead of failing on an empty choice. The fits are stand-ins."""
    from types import SimpleNamespace

    from jointplay.calibration import fit as fit_module
    from jointplay.common.errors import SimulationError

    predictor = SimpleNamespace(measured=SimpleNamespace(size=20), free=SimpleNamespace(size=1))
    starts = np.array([[1.0], [2.0]])
    stopped = [fit_module.Start((x,), (x,), math.inf, 0, f"the run at x = {x:g} stopped",
                                failed=True) for x in (1.0, 2.0)]
    unfinished = [fit_module.Start((x,), (x,), math.inf, 3, "settled") for x in (1.0, 2.0)]

    def next_of(fits: Any, *_: Any) -> Any:
        return next(fits)

    for outcomes, expected in ((stopped, "stopped: the run at x = 1 stopped"),
                               (unfinished, "stopped: no finite chi²")):
        monkeypatch.setattr(fit_module, "_local_fit", functools.partial(next_of, iter(outcomes)))
        with pytest.raises(SimulationError, match="every start of the calibration " + expected):
            fit_module.multi_start(predictor, np.ones(1), starts, 5,  # type: ignore[arg-type]
                                   stop_early=False)


def test_window_track_fits_pause_and_only_those_near_the_best_go_on(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """With several tracks each window fit pauses after CHECKPOINT_EVALUATIONS; of those
    that used them all, only the ones within the tracks' margin (50 here) of the best go
    on, from where they paused, with the rest of the evaluations; their stage adds both
    parts. The fits are stand-ins: this is the rule, not the runs."""
    from types import SimpleNamespace

    from jointplay.calibration import continuation

    calls: list[tuple[int, int, float]] = []
    after_pause = {0: 100.0, 1: 120.0, 2: 500.0}  # each track's chi² where it paused

    def stand_in(predictor: Any, scene: Any, part: Any, weights: Any, starts: np.ndarray,
                 budget: int, end: float, label: int, held: Any) -> Any:
        first = not any(c[0] == label for c in calls)
        calls.append((label, budget, float(starts[0][0])))
        used = budget if first and label != 0 else 3  # track 0 settles before the pause
        chi2 = after_pause[label] - (0.0 if first else 10.0)
        stage = continuation.Stage(end, 500, tuple(starts[0]), tuple(starts[0] + 1), chi2,
                                   999, used, used + 1, "stand-in", (), label, 0.5)
        return (stage, starts[0] + 1), used + 1

    monkeypatch.setattr(continuation, "_stage_fit", stand_in)
    predictor = SimpleNamespace(free=SimpleNamespace(size=1))
    alive = [np.array([10.0]), np.array([20.0]), np.array([30.0])]
    (fitted, unseen, stages), runs = continuation._window_fits(
        predictor, None, SimpleNamespace(size=1000), np.ones(1), alive, [0, 1, 2], None, 40,
        0.64, np.zeros(1, dtype=bool), 1)
    pause = continuation.CHECKPOINT_EVALUATIONS
    assert calls == [(0, pause, 10.0), (1, pause, 20.0), (2, pause, 30.0),
                     (1, 40 - pause, 21.0)]
    assert [(label, chi2) for label, _, chi2 in fitted] == [(0, 100.0), (1, 110.0), (2, 500.0)]
    assert unseen == [] and runs == 4 + (pause + 1) * 2 + 4
    assert (stages[1].start, stages[1].end) == ((20.0,), (22.0,))
    assert (stages[1].evaluations, stages[1].simulations) == (pause + 3, pause + 1 + 4)


def test_grid_local_minima_and_track_pruning() -> None:
    """The grid's local minima (diagonal neighbours included) and the rule that carries
    tracks from one window to the next: a track more than TRACK_MARGIN (50) above the best
    one, or 5 sqrt(2 dof) where that is less, either times the best's chi²/dof where that
    exceeds 1, is dropped, and so is one that has joined a better track."""
    from jointplay.calibration.continuation import _surviving
    from jointplay.calibration.grid import _local_minima
    from jointplay.calibration.parameters import FreeParameters

    cost = np.array([[5.0, 4.0, 5.0, 9.0],
                     [4.0, 1.0, 4.0, 9.0],
                     [5.0, 4.0, 6.0, 0.5],
                     [9.0, 9.0, 9.0, 9.0]])
    assert sorted(_local_minima(cost)) == [(1, 1), (2, 3)]
    free = FreeParameters(("a", "b"), np.array([1.0, 1.0]), np.array([0.0, 0.0]),
                          np.array([2.0, 2.0]))
    dof = 200  # 5 sqrt(400) = 100: the margin is TRACK_MARGIN, 50
    tracks = [(0, np.array([1.0, 1.0]), 240.5), (1, np.array([1.2, 0.8]), 190.0),
              (2, np.array([1.2, 0.8 + 1e-6]), 200.0), (3, np.array([0.9, 1.1]), 239.0)]
    kept = _surviving(tracks, dof, free)
    assert [label for label, _, _ in kept] == [1, 3]
    dof = 8  # 5 sqrt(16) = 20 < 50: the margin is 20
    tracks = [(0, np.array([1.0, 1.0]), 27.5), (1, np.array([1.2, 0.8]), 7.0),
              (3, np.array([0.9, 1.1]), 26.0)]
    assert [label for label, _, _ in _surviving(tracks, dof, free)] == [1, 3]
    # the best does not explain the window (chi²/dof 2.5): the margin is 2.5 x 50 = 125
    dof = 200
    tracks = [(0, np.array([1.0, 1.0]), 626.0), (1, np.array([1.2, 0.8]), 500.0),
              (3, np.array([0.9, 1.1]), 624.0)]
    assert [label for label, _, _ in _surviving(tracks, dof, free)] == [1, 3]


def test_grid_finds_the_true_valley_of_the_clearances() -> None:
    """Paper scene, 30 ms of tip position: the grid's best candidate lies within one grid
    spacing of the true clearances (truth 23.9 and 44.0 µm, start 30 µm each, a draw whose
    local fits from the start ended far away)."""
    from jointplay.calibration.grid import Grid, grid_candidates
    from jointplay.calibration.parameters import free_parameters
    from jointplay.calibration.predict import Predictor

    scene = jp.default_scene().with_run(t_end=0.03)
    truth = {"joint2.clearance": 23.949e-6, "joint3.clearance": 44.009e-6,
             "friction.mu": 0.07099}
    exact = jp.simulate(scene.with_run(rtol=2e-11, atol=3e-12), parameters=truth)
    rng = np.random.default_rng(4)
    tip = exact.tip_position + NOISE * rng.standard_normal(exact.tip_position.shape)
    measured = Measured("synthetic", exact.t.copy(), ("tip_x", "tip_y"), tip)
    model = jp.load_scene_model(scene)
    free = free_parameters(list(truth), scene, model, {"friction.mu": 0.07099})
    fit_scene = scene.with_run(rtol=2e-9, atol=3e-10)
    predictor = Predictor(fit_scene, model, free, measured)
    found = grid_candidates(predictor, np.array([NOISE, NOISE]), free.start,
                            Grid(0.02, 11, 0.5, 3, 100.0))
    # 121 points, and 2-4 runs choosing the window's tolerances (window_looseness)
    assert found is not None and found.points_per_axis == 11
    assert 121 + 2 <= found.simulations <= 121 + 4
    spacing = 30e-6 / 10
    best = found.candidates[0]
    assert abs(best[0] - truth["joint2.clearance"]) <= spacing
    assert abs(best[1] - truth["joint3.clearance"]) <= spacing
    assert best[2] == truth["friction.mu"]
    assert list(found.chi2) == sorted(found.chi2)
    # the same grid on two forked processes: the same numbers
    again = grid_candidates(predictor, np.array([NOISE, NOISE]), free.start,
                            Grid(0.02, 11, 0.5, 3, 100.0), workers=2)
    assert again is not None and again.simulations == found.simulations
    assert np.array_equal(again.candidates, found.candidates) and again.chi2 == found.chi2


@pytest.mark.slow
def test_the_grid_line_finds_the_true_valley_the_grid_point_misses() -> None:
    """Paper scene, the first 40 ms of benchmark draw 8 (truth c2 = 28.43 µm, c3 = 25.96 µm,
    1 µm noise of seed 8; it ended 9 % away without the line), from the best grid point
    (27, 27) µm with the friction the first stage fitted. The 20 ms window's fit from that
    point stays in a valley about 1 µm from the truth along c2 - c3, 30-50 above the truth's
    floor in chi². The line through the point (151 runs, 1.5 grid spacings of 2 µm either
    side: 40 nm apart) has a minimum in the true valley, 50-100 nm wide, and the fit from
    it is the best track: within 60 nm of the truth along c2 - c3, its chi² within 10 of
    the truth's."""
    from jointplay.calibration.continuation import ValleyScan, continuation
    from jointplay.calibration.parameters import free_parameters
    from jointplay.calibration.predict import Predictor, chi2_at

    scene = jp.default_scene().with_run(t_end=0.04)
    truth = {"joint2.clearance": 2.843105704616211e-05,
             "joint3.clearance": 2.5955424033972185e-05, "friction.mu": 0.0347698799935777}
    measured = _synthetic(scene, truth, 8, tighter=1e4)  # as the benchmark makes draw 8
    model = jp.load_scene_model(scene)
    free = free_parameters(list(truth), scene, model, None)
    predictor = Predictor(scene.with_run(rtol=2e-9, atol=3e-10), model, free, measured)
    weights = np.array([NOISE, NOISE])
    grid_point = np.array([27e-6, 27e-6, 0.03483679])
    other = np.array([39e-6, 15e-6, 0.03483679])
    line = ValleyScan(0.02, 151, 1.5, 3, (2e-6, 2e-6, 0.0))

    def tracks(opening: ValleyScan | None) -> tuple[np.ndarray, list[Any], int]:
        # the valley lines' window lies beyond the record: until it the friction is held
        found, stages, runs = continuation(predictor, weights, np.array([grid_point, other]),
                                           grid_point[None, :], 40, 0.02, 2.0,
                                           dataclasses.replace(line, window=0.32),
                                           looser=100.0, workers=2, opening=opening)
        assert {s.window_end for s in stages} == {0.02}  # one window: the record's half
        return found, stages, runs

    plain, plain_stages, plain_runs = tracks(None)
    lined, lined_stages, lined_runs = tracks(line)
    # the line's 3 minima in the grid point's place: 4 fits instead of 2, and the line's
    # runs with one for its direction (and one per fit that checks what the window sees)
    assert len(plain_stages) == 2 and len(lined_stages) == 4
    assert lined_runs == (plain_runs + 151 + 1 + sum(s.simulations + 1 for s in lined_stages)
                          - sum(s.simulations + 1 for s in plain_stages))
    window = Predictor(predictor.scene.with_run(t_end=0.02, rtol=2e-7, atol=3e-8), model,
                       free, Measured("20 ms", measured.t[:21], measured.columns,
                                      measured.values[:21]))
    x_truth = np.array(list(truth.values()))
    x_truth[2] = grid_point[2]  # held at the first stage's value, as the tracks are
    (chi2_truth, chi2_fit, chi2_line), _ = chi2_at(window, weights,
                                                   [x_truth, plain[0], lined[0]])
    difference = lambda x: (x[0] - x[1]) / 2  # noqa: E731  (half of c2 - c3)
    assert abs(difference(plain[0]) - difference(x_truth)) >= 0.5e-6
    assert abs(difference(lined[0]) - difference(x_truth)) <= 60e-9
    assert chi2_line <= chi2_truth + 10 < chi2_fit
    # held (to 1e-12 of its value) by the fits, and not moved by the line
    assert lined[0][2] == pytest.approx(grid_point[2], rel=1e-10)
    assert plain[0][2] == pytest.approx(grid_point[2], rel=1e-10)


@pytest.mark.slow
def test_paper_scene_clearances_recovered_from_half_a_range_away() -> None:
    """Paper scene, 2 s of tip position at 1 ms with 1 µm of noise (seed 3), truth
    c2 = 23.9 µm, c3 = 44.0 µm, mu = 0.071 (benchmark draw 3), calibrated from the scene's
    values (30 µm, 30 µm, 0.05) with the default global stage: the friction first, the
    grid, several tracks through the windows, the lines at 0.32 s. The local fits alone
    had ended at +115 % / -58 % here. Each estimate within 0.2 % (goal: 2 % for the
    clearances, 5 % for the friction), the fit explaining the data (chi² within 5 sigma of
    its dof), each interval holding the truth, one local fit on the whole record."""
    scene = jp.default_scene()
    truth = {"joint2.clearance": 23.949e-6, "joint3.clearance": 44.009e-6,
             "friction.mu": 0.07099}
    exact = jp.simulate(scene.with_run(rtol=2e-10, atol=3e-11), parameters=truth)
    rng = np.random.default_rng(3)
    tip = exact.tip_position + NOISE * rng.standard_normal(exact.tip_position.shape)
    measured = Measured("synthetic", exact.t.copy(), ("tip_x", "tip_y"), tip)
    result = calibrate(scene, measured, list(truth), noise=NOISE,
                       options=CalibrationOptions(profile_points=0))
    # 256 points, and 2-4 runs choosing the window's tolerances
    assert result.grid is not None and 256 + 2 <= result.grid.simulations <= 256 + 4
    assert max(s.track for s in result.stages) >= 1  # more than one track was carried
    assert result.fit_explains_data
    basin_fits = len(result.starts) - 1
    assert 0 <= basin_fits <= 2  # one whole-record fit, then the basin check's (at most 2)
    for name, value in truth.items():
        estimate = result.estimates[name]
        assert abs(estimate.value - value) <= 2e-3 * value, name
        assert estimate.low95 <= value <= estimate.high95, name
        # determined, or a warning that says why not
        assert estimate.determined or any(w.startswith(name) for w in result.warnings), name
    assert result.to_dict()["grid"]["axes"] == ["joint2.clearance", "joint3.clearance"]


def _spread(values: np.ndarray, std: np.ndarray) -> Any:
    from jointplay.calibration.uncertainty import Z95, Uncertainty

    n = values.size
    return Uncertainty(np.diag(std**2), std, np.eye(n), 1.0, values - Z95 * std,
                       values + Z95 * std, np.ones(n, dtype=bool), ())


def test_basins_widen_the_intervals_to_every_point_found_inside_them() -> None:
    """A rival minimum outside the best's interval (within the threshold) widens it to hold
    the rival's basin and makes the parameters it differs in not determined, each warning
    naming the other; a line's point within the threshold but outside the interval widens
    it and says so, the verdict kept; without either nothing changes."""
    from jointplay.calibration.basins import Basins, threshold, widened
    from jointplay.calibration.fit import Start

    names = ("joint2.clearance", "joint3.clearance", "friction.mu")
    values = np.array([30e-6, 30e-6, 0.05])
    std = np.array([10e-9, 10e-9, 2e-6])
    spread = _spread(values, std)
    limit = threshold()
    assert limit == pytest.approx(3.841458820694124)
    nothing = Basins(values, 4000.0, (), limit, (), 10, values[None, :])
    low, high, determined, warnings = widened(spread, nothing, names)
    assert np.array_equal(low, spread.low95) and np.array_equal(high, spread.high95)
    assert determined.all() and warnings == []

    rival_end = values + np.array([25e-9, -25e-9, 0.0])
    rival = Start(tuple(values), tuple(rival_end), 4001.5, 0, "rival basin")
    far_point = values + np.array([0.0, 0.0, 5e-6])
    found = Basins(values, 4000.0, (rival,), limit, (), 10,
                   np.vstack([values, far_point]))
    low, high, determined, warnings = widened(spread, found, names)
    half = np.sqrt(limit - 1.5) * std
    assert high[0] == pytest.approx(rival_end[0] + half[0])
    assert low[1] == pytest.approx(rival_end[1] - half[1])
    assert low[0] == spread.low95[0] and high[1] == spread.high95[1]
    assert high[2] == pytest.approx(far_point[2]) and low[2] == spread.low95[2]
    assert list(determined) == [False, False, True]
    assert len(warnings) == 3
    assert warnings[0].startswith("joint2.clearance is not determined") and \
        "joint3.clearance" in warnings[0]
    assert warnings[2].startswith("friction.mu: the cost is not the quadratic") and \
        "2.5 of its standard deviations" in warnings[2]
    # a point just outside (a smooth cost's departure from its quadratic): widened, silently
    near = values + np.array([0.0, 0.0, 2.1 * std[2]])
    found = Basins(values, 4000.0, (), limit, (), 10, near[None, :])
    low, high, determined, warnings = widened(spread, found, names)
    assert high[2] == pytest.approx(near[2]) and determined.all() and warnings == []


@pytest.mark.slow
def test_the_valley_check_finds_the_truths_valley_beside_a_fit_one_valley_off() -> None:
    """Paper scene, the first 0.4 s of benchmark draw 1 (truth c2 = 26.115 µm, c3 =
    25.648 µm, 1 µm noise of seed 1), through the whole-record fit the benchmark ends in,
    95 nm from the truth along c2 - c3 (the truth 7.3 lower in chi² over the whole record).
    The check's line over 0.32 s (along the clearances' rugged direction, c2 - c3 here: 161
    runs 5 nm apart, and one run for the direction) finds a valley lower than the fit's own
    within 10 nm of the truth along c2 - c3."""
    from jointplay.calibration.basins import threshold
    from jointplay.calibration.continuation import ValleyScan
    from jointplay.calibration.parameters import free_parameters
    from jointplay.calibration.predict import Predictor
    from jointplay.calibration.valleys import valley_check

    scene = jp.default_scene().with_run(t_end=0.4)
    truth = {"joint2.clearance": 2.6115015813241887e-05,
             "joint3.clearance": 2.5647520029289975e-05, "friction.mu": 0.06452591229266325}
    fit = np.array([2.6209656136012523e-05, 2.555290264998431e-05, 0.06452812978038709])
    measured = _synthetic(scene, truth, 1, tighter=1e4)  # as the benchmark makes draw 1
    model = jp.load_scene_model(scene)
    free = free_parameters(list(truth), scene, model, None)
    predictor = Predictor(scene.with_run(rtol=2e-9, atol=3e-10), model, free, measured)
    check = valley_check(predictor, np.array([NOISE, NOISE]), fit,
                         ValleyScan(0.32, 161, 0.2, 1, (2e-6, 2e-6, 0.0)), 3.0, 2.0,
                         threshold(), workers=2)
    assert check.window_end == pytest.approx(0.32) and check.runs == 161 + 1
    assert not check.coarse  # a smooth excitation: the line resolves the fit's own valley
    assert check.extent is not None  # the lines' ends, 80 steps of its spacing either side
    assert np.all(check.extent[1] - check.extent[0]
                  == pytest.approx(160 * check.spacing, rel=1e-6, abs=1e-15))
    assert check.spacing[2] == 0 and 4e-9 <= max(check.spacing) <= 5e-9 * (1 + 1e-9)
    difference = lambda x: (x[0] - x[1]) / 2  # noqa: E731  (half of c2 - c3)
    x_truth = np.array(list(truth.values()))
    assert abs(difference(fit) - difference(x_truth)) >= 80e-9
    lowest, rise = min(check.rivals, key=lambda r: r[1])
    assert rise < 0
    assert abs(difference(lowest) - difference(x_truth)) <= 10e-9


def test_the_valley_check_rivals_leave_the_clearances_not_determined() -> None:
    """A valley the check found along the clearances' line within the threshold of the
    fit's own, outside their intervals, leaves both clearances not determined, each interval
    widened to hold its point give or take the line's spacing, and to span the whole line
    where the check knows its extent, and a warning naming the window, the partner and the
    interval; one inside the intervals, or a parameter the line does not move (the
    friction), changes nothing."""
    from jointplay.calibration.basins import Basins, threshold, widened
    from jointplay.calibration.valleys import ValleyCheck

    names = ("joint2.clearance", "joint3.clearance", "friction.mu")
    values = np.array([26.21e-6, 25.55e-6, 0.0645])
    std = np.array([5e-9, 5e-9, 2e-6])
    spread = _spread(values, std)
    limit = threshold()
    nothing = Basins(values, 4000.0, (), limit, (), 10, values[None, :])
    spacing = np.array([5e-9, 4.2e-9, 0.0])
    inside = values + np.array([5e-9, -4.2e-9, 0.0])
    far = values + np.array([-100e-9, 84e-9, 0.0])
    quiet = ValleyCheck(0.32, ((inside, 0.9),), spacing, 162)
    low, high, determined, warnings = widened(spread, nothing, names, quiet)
    assert np.array_equal(low, spread.low95) and np.array_equal(high, spread.high95)
    assert determined.all() and warnings == []
    check = ValleyCheck(0.32, ((inside, 0.9), (far, -6.1)), spacing, 162)
    low, high, determined, warnings = widened(spread, nothing, names, check)
    assert list(determined) == [False, False, True]
    assert low[0] == pytest.approx(far[0] - spacing[0]) and high[0] == spread.high95[0]
    assert high[1] == pytest.approx(far[1] + spacing[1]) and low[1] == spread.low95[1]
    assert low[2] == spread.low95[2] and high[2] == spread.high95[2]
    assert len(warnings) == 2
    assert warnings[0].startswith("joint2.clearance is not determined by the search: over "
                                  "the first 0.32 s 1 other valley(s)")
    assert "joint3.clearance" in warnings[0] and "(the lowest -6.1)" in warnings[0]
    # the line's extent (0.2 grid spacings of 2 µm either side along c2 - c3, as the check
    # runs it): both clearances' intervals span it, the friction's stays its own
    extent = (values + np.array([-400e-9, -336e-9, 0.0]), values + np.array([400e-9, 336e-9,
                                                                            0.0]))
    lined = ValleyCheck(0.32, ((inside, 0.9), (far, -6.1)), spacing, 162, extent)
    low, high, determined, warnings = widened(spread, nothing, names, lined)
    assert list(determined) == [False, False, True]
    assert low[:2] == pytest.approx(extent[0][:2]) and high[:2] == pytest.approx(extent[1][:2])
    assert low[2] == spread.low95[2] and high[2] == spread.high95[2]
    assert f"spans the check's line, {extent[0][0]:.6g} to {extent[1][0]:.6g}" in warnings[0]
    # a quiet check changes nothing, its extent whatever it is
    quiet = ValleyCheck(0.32, ((inside, 0.9),), spacing, 162, extent)
    low, high, determined, _ = widened(spread, nothing, names, quiet)
    assert np.array_equal(low, spread.low95) and determined.all()


def test_the_valley_floor_is_reached_downhill() -> None:
    """From a point on a line, the floor of its own valley: downhill through the steepest
    neighbour, stopping where neither neighbour is lower; a point that is not finite is
    its own."""
    from jointplay.calibration.valleys import _valley_floor

    chi2 = np.array([5.0, 1.0, 3.0, 4.0, 2.5, 0.5, 6.0])
    assert _valley_floor(chi2, 3) == 5  # through the lower neighbour: 4 -> 2.5 -> 0.5
    assert _valley_floor(chi2, 2) == 1 and _valley_floor(chi2, 4) == 5
    assert _valley_floor(chi2, 1) == 1 and _valley_floor(chi2, 6) == 5
    assert _valley_floor(np.array([1.0, np.inf, 0.0]), 1) == 1


def test_other_tracks_whole_record_fits_are_rivals_and_centres() -> None:
    """The other tracks' whole-record fits: one within the threshold in another basin is a
    rival (once, however many fits ended in it), one below the best becomes the best, one
    in the best's own basin or above the threshold is not a rival; the lowest one in another
    basin within the threshold plus SLACK is where the lines also go through."""
    from jointplay.calibration.basins import (
        OTHER_CENTRES,
        SLACK,
        Basins,
        _other_centres,
        _with_rivals,
        threshold,
    )
    from jointplay.calibration.fit import Start

    best = np.array([30e-6, 30e-6, 0.05])
    covariance = np.diag([10e-9, 10e-9, 2e-6]) ** 2
    limit = threshold()

    def fit(offset: list[float], chi2: float, failed: bool = False) -> Start:
        return Start(tuple(best), tuple(best + np.array(offset)), chi2, 5, "", failed)

    other_basin = fit([700e-9, -700e-9, 0.0], 4002.0)
    same_basin = fit([2e-9, 0.0, 0.0], 4001.0)
    too_high = fit([-300e-9, 300e-9, 0.0], 4000.0 + limit + 1.0)
    failed = fit([-500e-9, 0.0, 0.0], 3000.0, failed=True)
    others = (other_basin, fit([701e-9, -700e-9, 0.0], 4002.5), same_basin, too_high, failed)
    empty = Basins(best, 4000.0, (), limit, (), 0)
    found = _with_rivals(best, 4000.0, covariance, others, empty)
    assert np.array_equal(found.best, best) and found.best_chi2 == 4000.0
    assert [r.end for r in found.rivals] == [other_basin.end]
    lower = fit([0.0, 50e-9, 0.0], 3990.0)
    found = _with_rivals(best, 4000.0, covariance, (lower,), empty)
    assert np.array_equal(found.best, lower.end) and found.best_chi2 == 3990.0
    assert found.rivals == ()  # the given best lies 10 above the new one
    centres = _other_centres(best, 4000.0, covariance, others, limit + SLACK)
    assert OTHER_CENTRES == 1 and len(centres) == 1
    assert np.array_equal(centres[0], np.array(other_basin.end))
    assert _other_centres(best, 4000.0, covariance, (same_basin, failed), limit + SLACK) == []


def test_the_basin_lines_also_go_through_another_track_fit(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """On the arm with ideal joints: another whole-record fit within the threshold plus
    SLACK, in another basin, doubles the basin check's line runs (the same lines through it); one
    above that, or in the best's own basin, adds none. The earlier fits reach the check with
    the noise stated or estimated (both weight the residuals by the noise)."""
    from jointplay.calibration import api
    from jointplay.calibration.api import prepare
    from jointplay.calibration.basins import SLACK, neighbouring_basins, threshold
    from jointplay.calibration.fit import Start, least_squares_fit
    from jointplay.calibration.predict import Predictor
    from jointplay.calibration.uncertainty import uncertainty

    scene = _ideal_scene(0.2)
    truth = {"payload.mass": 2.3, "link2.com": 0.19}
    measured = _synthetic(scene, truth, seed=6)
    problem = prepare(scene, measured, list(truth), noise=NOISE,
                      options=CalibrationOptions(tighten=1.0))
    free = problem.free
    predictor = Predictor(problem.scene, problem.model, free, problem.measured)
    optimum = least_squares_fit(predictor, problem.sigma, free.start[None, :], 40)
    chi2 = float(np.sum(optimum.residuals**2))
    spread = uncertainty(optimum.jacobian, optimum.values, free.lower, free.upper, free.names)

    def check(others: tuple[Start, ...]) -> int:
        return neighbouring_basins(predictor, optimum.sigma, optimum.values, chi2,
                                   spread.covariance, 40, 1, others=others).line_runs

    alone = check(())
    away = optimum.values + 3 * spread.std * np.array([1.0, 0.0])
    near = Start(tuple(away), tuple(away), chi2 + 5.0, 3, "")
    high = Start(tuple(away), tuple(away), chi2 + threshold() + SLACK + 1.0, 3, "")
    same = Start(tuple(optimum.values), tuple(optimum.values + 0.1 * spread.std), chi2, 3, "")
    assert alone > 1 and check((near,)) - 1 == 2 * (alone - 1)  # the best's own run once
    assert check((high, same)) == alone

    given: list[tuple[Start, ...]] = []
    real = api.neighbouring_basins

    def recorded(*args: Any, others: tuple[Start, ...] = (), **kwargs: Any) -> Any:
        given.append(others)
        return real(*args, others=others, **kwargs)

    monkeypatch.setattr(api, "neighbouring_basins", recorded)
    options = CalibrationOptions(tighten=1.0, starts=1, scan_points=0, profile_points=0,
                                 horizon_first=0)
    calibrate(scene, measured, list(truth), noise=NOISE, options=options)
    calibrate(scene, measured, list(truth), options=options)
    # with the noise estimated from the data's scatter the fits' chi² are in its units too
    assert len(given) == 2 and len(given[0]) >= 1 and len(given[1]) >= 1


def test_at_least_two_tracks_reach_the_whole_record(monkeypatch: pytest.MonkeyPatch) -> None:
    """Before the whole-record fits the tracks are ranked by one run each: those more than
    TRACK_MARGIN above the best are dropped, but never the WHOLE_RECORD_TRACKS best; that
    many tracks or fewer are kept without a run."""
    from jointplay.calibration import api
    from jointplay.calibration.continuation import TRACK_MARGIN

    values = {0: 4000.0, 1: 4000.0 + 3 * TRACK_MARGIN, 2: 4000.0 + 2 * TRACK_MARGIN,
              3: 4000.0 + TRACK_MARGIN / 2}
    monkeypatch.setattr(api, "chi2_at_points", lambda predictor, weights, points, workers: (
        [values[int(p[0])] for p in points], len(points)))
    tracks = np.array([[0.0], [1.0], [2.0], [3.0]])
    kept, runs = api._ranked(None, np.ones(1), tracks, 1)  # type: ignore[arg-type]
    assert api.WHOLE_RECORD_TRACKS == 2
    assert kept[:, 0].tolist() == [0.0, 3.0] and runs == 4
    far = np.array([[0.0], [1.0], [2.0]])
    kept, runs = api._ranked(None, np.ones(1), far, 1)  # type: ignore[arg-type]
    assert kept[:, 0].tolist() == [0.0, 2.0] and runs == 3
    kept, runs = api._ranked(None, np.ones(1), far[:2], 1)  # type: ignore[arg-type]
    assert kept[:, 0].tolist() == [0.0, 1.0] and runs == 0


def test_on_a_quadratic_cost_the_basin_lines_stay_inside_the_intervals() -> None:
    """Where the cost is the quadratic its covariance describes (no impacts), every point of
    the lines within the threshold lies inside each parameter's Wald interval: the check
    widens nothing on a smooth cost (random covariances, three parameters)."""
    from jointplay.calibration.basins import (
        FAR_SIGMAS,
        REACH_SIGMAS,
        STEP_SIGMAS,
        _line_points,
        threshold,
    )
    from jointplay.calibration.uncertainty import Z95

    rng = np.random.default_rng(7)
    per_side = round(REACH_SIGMAS / STEP_SIGMAS) + sum(f > REACH_SIGMAS for f in FAR_SIGMAS)
    for _ in range(20):
        a = rng.standard_normal((3, 3))
        covariance = a @ a.T + 1e-3 * np.eye(3)
        best = rng.standard_normal(3)
        lines = _line_points(best, covariance, np.full(3, -np.inf), np.full(3, np.inf))
        assert len(lines) == 3 and all(len(line) == 2 * per_side for line in lines)
        information = np.linalg.inv(covariance)
        std = np.sqrt(np.diag(covariance))
        for line in lines:
            for x in line:
                rise = float((x - best) @ information @ (x - best))
                if rise <= threshold():
                    assert np.all(np.abs(x - best) <= Z95 * std * (1 + 1e-9))
    assert _line_points(np.zeros(2), np.full((2, 2), np.inf), np.zeros(2), np.ones(2)) == []


@pytest.mark.slow
def test_the_valley_check_runs_only_where_the_noise_explains_the_residuals() -> None:
    """The paper scene's first 0.1 s of tip, clearances and friction free, a small global
    stage (valley lines and check from 40 ms): with the noise stated as it is the check runs
    (a line along the clearances' rugged direction and the run choosing it); stated 100
    times too small, chi²/dof is far outside its range, nothing can be determined, and the
    check's runs are skipped."""
    scene = jp.default_scene().with_run(t_end=0.1)
    truth = {"joint2.clearance": 30.3e-6, "joint3.clearance": 29.8e-6, "friction.mu": 0.05}
    measured = _synthetic(scene, truth, seed=0)
    options = CalibrationOptions(profile_points=0, grid_points=5, grid_line_points=0,
                                 valley_window=0.04, valley_points=9, valley_check_points=9)
    right = calibrate(scene, measured, list(truth), noise=NOISE, options=options)
    assert right.fit_explains_data
    assert right.simulations_by_kind["valley check"] == 9 + 1
    wrong = calibrate(scene, measured, list(truth), noise=NOISE / 100, options=options)
    assert not wrong.fit_explains_data
    assert wrong.simulations_by_kind["valley check"] == 0
    assert not any(e.determined for e in wrong.estimates.values())


def test_options_refuse_what_would_fail_after_work_began() -> None:
    """Each option the search uses is checked on construction (a negative seed once failed
    inside NumPy after the first runs), and the fit's tolerances (the scene's divided by
    ``tighten``) may not fall below what a run accepts: the error names ``tighten``."""
    from jointplay.calibration.options import CalibrationOptions
    from jointplay.common.errors import DescriptionError

    for bad in ({"seed": -1}, {"seed": 1.5}, {"seed": True}, {"valley_points": 2},
                {"valley_keep": 0}, {"valley_window": -0.1}, {"tighten": math.inf}):
        with pytest.raises(DescriptionError) as caught:
            CalibrationOptions(**bad)  # type: ignore[arg-type]
        assert caught.value.field == f"options.{next(iter(bad))}"
    assert CalibrationOptions(tighten=10.0).tightened(1e-6, 1e-9) == (1e-7, 1e-10)
    with pytest.raises(DescriptionError, match="must be at most 1e\\+06") as caught:
        CalibrationOptions(tighten=1e7).tightened(1e-8, 1e-9)
    assert caught.value.field == "options.tighten"
