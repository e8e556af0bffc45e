"""What `control` says about its runs: the settling window taken from the run, and every
controller that ends worse than the open loop or PD named (pure functions, fast)."""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from jointplay.neural.control.loop import LoopConditions, Run
from jointplay.neural.control.metrics import WORSE_MARGIN, worse_lines, worse_than_baselines
from jointplay.neural.study.comparison import RELEASE_GAP, engagement_end, release_end, settling


def _run(impacts: list[float]) -> Run:
    return Run("open loop", np.zeros(1), np.zeros((1, 1)), np.zeros((1, 1)), np.zeros((1, 1)),
               len(impacts), 0.0, impact_times=np.array(impacts))


def test_release_ends_at_the_first_gap_in_the_opening_impacts() -> None:
    # The paper scene's open loop at 0.1 mm (its impact times, ms): the release sequence ends
    # at 36.47 ms; two later impacts (made up) are past a gap and not part of it.
    times = [1e-3 * t for t in (4.51, 5.79, 6.34, 6.88, 7.71, 16.07, 16.2, 17.72, 17.96, 21.4,
                                22.87, 23.95, 23.96, 24.29, 24.68, 28.0, 28.4, 28.61, 30.08,
                                30.84, 31.17, 31.29, 31.73, 32.99, 33.18, 34.26, 34.72, 36.12,
                                36.47, 300.0, 310.0)]
    assert release_end(_run(times)) == pytest.approx(36.47e-3 + RELEASE_GAP)
    assert release_end(_run([])) == 0.0
    assert release_end(_run([0.5])) == 0.0  # no impact near the start: nothing released


def test_settling_is_the_later_of_engagement_and_release() -> None:
    dt = 1e-3
    ctrl = SimpleNamespace(settings=SimpleNamespace(engage=0.1, setpoint_filter=0.9))
    # 0.9^44 < 0.01 <= 0.9^43: the filter has let go 44 samples after engaging.
    assert engagement_end(0.1, 0.9, dt) == pytest.approx(0.144)
    short = settling({"open loop": _run([2e-3, 5e-3])}, {"ARX-IMC": ctrl}, dt)
    assert short.time == pytest.approx(0.144) and short.release_end == pytest.approx(0.015)
    assert "engages at 100 ms" in short.describe() and "144 ms" in short.describe()
    bouncing = _run([0.008 * k for k in range(1, 26)])  # impacts every 8 ms up to 0.2 s
    long = settling({"open loop": bouncing}, {"ARX-IMC": ctrl}, dt)
    assert long.time == pytest.approx(0.2 + RELEASE_GAP)
    # Baselines run alone share the window of the controllers run elsewhere.
    resting = settling({"open loop": _run([])}, {"ARX-IMC": ctrl}, dt)
    assert resting.release_end == 0 and "no release impacts" in resting.describe()
    alone = settling({"open loop": _run([2e-3])}, {}, dt, settle_after=0.144)
    assert alone.time == pytest.approx(0.144) and "settled by 144 ms" in alone.describe()


def test_every_controller_worse_than_a_baseline_is_named() -> None:
    base = {"max_position_engaged": 1.0, "max_velocity_engaged": 1.0,
            "max_acceleration_engaged": 1.0, "rms_acceleration_engaged": 1.0,
            "max_velocity_after": 1.0, "max_acceleration_after": 1.0,
            "rms_acceleration_after": 1.0,
            # over the whole run from t = 0 (the journals' release): not judged
            "max_position": 1.0, "rms_acceleration": 1.0}
    metrics = {"open loop": base,
               "PD": {**base, "rms_acceleration_after": 1.6},
               "ARX-IMC": {**base, "rms_acceleration_after": 0.5,
                           "max_position_engaged": 1 + WORSE_MARGIN / 2,  # a tie
                           "rms_acceleration": 1.005, "max_position": 1.2},  # before engaging
               "neural IMC": {**base, "rms_acceleration_after": 1.2}}
    found = {(c, k, b) for c, k, b, _ in worse_than_baselines(metrics)}
    assert found == {("PD", "rms_acceleration_after", "open loop"),
                     ("neural IMC", "rms_acceleration_after", "open loop")}
    assert WORSE_MARGIN == 0.01  # the 1 %
    lines = worse_lines(metrics)
    assert lines == ["PD is worse than no control (open loop) on RMS |Δa| after the transient "
                     "1.6x", "neural IMC is worse than no control (open loop) on RMS |Δa| "
                     "after the transient 1.2x"]


def test_control_repeats_what_identify_warned_about(tmp_path: Path) -> None:
    from jointplay.cli.control import identification_warnings

    assert identification_warnings(tmp_path) == []  # no metrics.json: nothing to repeat
    (tmp_path / "metrics.json").write_text(json.dumps(
        {"warnings": ["the excitation is too small to identify the input's effect"]}))
    assert identification_warnings(tmp_path) == [
        "the model was identified with a warning: the excitation is too small to identify the "
        "input's effect"]


def test_an_imc_worse_than_no_control_is_retuned_or_sent_back_to_pd(
        monkeypatch: pytest.MonkeyPatch) -> None:
    import jointplay.cli.control as control_cli
    from jointplay.neural.control.imc import ControllerSettings
    from jointplay.neural.study.comparison import Settling

    after = {"max_velocity_after": 1.0, "max_acceleration_after": 1.0,
             "rms_acceleration_after": 1.0}
    comparison = SimpleNamespace(
        metrics={"open loop": after, "PD": {**after, "rms_acceleration_after": 0.5},
                 "ARX-IMC": {**after, "max_acceleration_after": 1.3}},
        runs={}, settling=Settling(0.144, 0.1, 0.144, 0.03), limit=1.0, noise_tuning=None)
    job = SimpleNamespace(scene=None, narx=None, arx=None, lpv=None,
                          settings=ControllerSettings(), model_dir=Path("."))
    args = SimpleNamespace(ct_omega=15.0, ct_zeta=0.2)
    horizons = []

    def fake_compare(scene: object, narx: object, settings: ControllerSettings,
                     **kwargs: object) -> SimpleNamespace:
        horizons.append(settings.horizon)
        assert kwargs["transient"] == 0.144 and kwargs["limit"] == 1.0  # the same window
        good = settings.horizon == 20
        metrics = {**after, "max_acceleration_after": 0.9 if good else 1.2}
        return SimpleNamespace(runs={"ARX-IMC": SimpleNamespace(diverged="")},
                               metrics={"ARX-IMC": metrics})

    monkeypatch.setattr(control_cli, "compare", fake_compare)
    monkeypatch.setattr(control_cli, "sensor_noise", lambda job: None)
    lines = control_cli.retune_lines(args, job, comparison)
    assert horizons == [10, 20]
    assert "retuned to horizon 20 it does not" in lines[-1]
    assert "ARX-IMC retuned (horizon 20)" in comparison.metrics

    # No retune helps: PD is not worse than no control, so the line says to use it.
    horizons.clear()
    comparison.metrics = {k: v for k, v in comparison.metrics.items() if "retuned" not in k}
    monkeypatch.setattr(control_cli, "compare", lambda *a, **k: SimpleNamespace(
        runs={"ARX-IMC": SimpleNamespace(diverged="")},
        metrics={"ARX-IMC": {**after, "rms_acceleration_after": 2.0}}))
    lines = control_cli.retune_lines(args, job, comparison)
    assert "at horizons 10, 20: use PD" in lines[-1]


def test_study_sets_the_network_against_both_linear_controllers() -> None:
    """The study's goal lines: the network's RMS acceleration error after settling over
    ARX-IMC's (goal 0.75) and over LPV-ARX-IMC's (goal: below 1), median and worst seed."""
    from jointplay.neural.study.cases import Case
    from jointplay.neural.study.comparison import LINEAR, LPV, NEURAL
    from jointplay.neural.study.report import ratio_goals

    key = "rms_acceleration_after"
    values = {NEURAL: (1.0, 3.0), LINEAR: (2.0, 4.0), LPV: (2.0, 2.0)}
    rows = [{"case": "scene", "controller": name, "seed": seed, key: v}
            for name, vs in values.items() for seed, v in zip((11, 12), vs, strict=True)]
    lines = ratio_goals(rows, [Case("scene", 30e-6, (), LoopConditions())])
    assert lines == [
        "- scene: neural IMC / ARX-IMC RMS |Δa| after settling: median 0.625, worst seed "
        "0.750 (goal <= 0.75 on the worst seed: met)",
        "- scene: neural IMC / LPV-ARX-IMC RMS |Δa| after settling: median 1.000, worst seed "
        "1.500 (goal < 1 on the worst seed: NOT met)"]


def test_study_splits_the_acceleration_error_into_sample_mean_and_within_sample() -> None:
    """With the split of RMS |Δa| after settling in the rows, the study says each internal
    model's within-sample part, how far the network's alone sits against ARX-IMC's whole
    error, and the network over ARX-IMC on the sample-mean part (median, worst seed)."""
    from jointplay.neural.control.metrics import SPLIT_METRICS
    from jointplay.neural.study.cases import Case
    from jointplay.neural.study.comparison import LINEAR, LPV, NEURAL
    from jointplay.neural.study.report import split_lines

    mean_key, within_key = SPLIT_METRICS
    parts = {NEURAL: ((0.8, 0.6), (2.4, 1.8)), LINEAR: ((1.6, 1.2), (3.2, 2.4)),
             LPV: ((1.6, 1.2), (1.6, 1.2))}  # per seed: (sample-mean, within-sample)
    rows = [{"case": "scene", "controller": name, "seed": seed, mean_key: m, within_key: w,
             "rms_acceleration_after": float(np.hypot(m, w))}
            for name, ps in parts.items() for seed, (m, w) in zip((11, 12), ps, strict=True)]
    lines = split_lines(rows, Case("scene", 30e-6, (), LoopConditions()))
    assert lines == [
        "- scene: RMS |Δa| after settling within the sample periods (the acceleration's "
        "profile inside each period, which no model of the sampled outputs predicts), median "
        "m/s²: ARX-IMC 1.8, LPV-ARX-IMC 1.2, neural IMC 1.2",
        "- scene: the neural IMC's within-sample part alone is 0.375 (median), 0.450 (worst "
        "seed) of ARX-IMC's RMS |Δa| after settling: the lowest ratio the neural IMC could "
        "reach with that part as it is; on the sample-mean part, neural IMC / ARX-IMC is "
        "median 0.625, worst seed 0.750"]
    baselines_only = [dict(r, **{within_key: float("nan")}) for r in rows]
    assert split_lines(baselines_only, Case("scene", 30e-6, (), LoopConditions())) == []


def test_the_whole_run_is_judged_from_the_outer_loops_engagement() -> None:
    """What happens before the outer loop engages (the journals' release, every row the inner
    loop alone) is in the whole-run columns and not in the "_engaged" ones."""
    from jointplay.neural.control.metrics import run_metrics

    n, nj, engaged = 200, 2, 100
    t = np.arange(n) * 1e-3
    reference = np.zeros((n, 2 * nj + 6))

    def run(before: float, after: float) -> Run:
        y = np.zeros_like(reference)
        y[:engaged, 2 * nj] = before  # tip x error
        y[engaged:, 2 * nj] = after
        return Run("r", t, y, np.zeros((n, nj)), np.zeros((n, nj)), 0, 0.0)

    opened = run_metrics(run(1.0, 0.1), reference, nj, 150, engaged=engaged)
    released = run_metrics(run(1.5, 0.1), reference, nj, 150, engaged=engaged)
    assert released["max_position"] == 1.5 and opened["max_position"] == 1.0
    assert released["max_position_engaged"] == opened["max_position_engaged"] == 0.1
    worse = run_metrics(run(1.0, 0.2), reference, nj, 150, engaged=engaged)
    assert worse["max_position_engaged"] == 0.2
    metrics = {"open loop": opened, "ARX-IMC": released, "neural IMC": worse}
    assert {(c, k) for c, k, b, _ in worse_than_baselines(metrics)} == {
        ("neural IMC", "max_position_engaged")}


def test_the_recommended_controller_is_the_simplest_within_the_tie_margin() -> None:
    from jointplay.neural.study.recommend import recommend_from_runs

    def row(rms: float, diverged: float = 0.0) -> dict[str, float]:
        return {"rms_acceleration_after": rms, "diverged": diverged}

    metrics = {"open loop": row(2e-3), "PD": row(1e-3), "computed torque": row(1.2e-3),
               "ARX-IMC": row(4.2e-4), "LPV-ARX-IMC": row(3.0e-4),
               "neural IMC": row(3.0e-4 * (1 + WORSE_MARGIN / 2))}
    advice = recommend_from_runs(metrics, residual_weight=0.0)
    assert advice is not None and advice.controller == "LPV-ARX-IMC"
    assert "0.714x ARX-IMC's" in advice.line
    assert "the neural IMC has 1.005x its error" in advice.line
    assert "runs that linear model" in advice.line
    # The network better by more than the margin: it.
    metrics["neural IMC"] = row(2.8e-4)
    advice = recommend_from_runs(metrics, residual_weight=0.25)
    assert advice is not None and advice.controller == "neural IMC"
    assert "0.933x LPV-ARX-IMC's" in advice.line
    # A controller that drew a warning or diverged is passed over while another is there.
    advice = recommend_from_runs(metrics, warned={"neural IMC"})
    assert advice is not None and advice.controller == "LPV-ARX-IMC"
    assert "not recommended for their warnings: neural IMC" in advice.line
    metrics["LPV-ARX-IMC"] = row(1e-4, diverged=1.0)
    advice = recommend_from_runs(metrics)
    assert advice is not None and advice.controller == "neural IMC"
    assert recommend_from_runs({"open loop": row(1.0)}) is None


@pytest.mark.slow
def test_a_detuned_controller_warns_and_the_tuned_one_does_not() -> None:
    """On the paper scene the inner loop's PD is no worse than the open loop where it can act
    (its whole-run figures include the journals' release, which it cannot prevent), so no
    line; the same PD with a derivative gain above the chatter bound (25 N m s/rad on joint
    2: docs/control.md) rings and is named."""
    from jointplay.neural.control.imc import ControllerSettings
    from jointplay.neural.study.comparison import compare
    from jointplay.neural.study.runs import _dummy_model
    from jointplay.scene.definition import default_scene

    scene = default_scene()
    scene = scene.with_run(t_end=0.6)
    model = _dummy_model(scene)
    tuned = compare(scene, model, ControllerSettings(), controllers=("open loop", "PD"),
                    analyse=False)
    assert worse_lines(tuned.metrics) == []
    detuned = compare(scene, model, ControllerSettings(), controllers=("open loop", "PD"),
                      analyse=False, pd_kd=(25.0, 5.0))
    lines = worse_lines(detuned.metrics)
    assert len(lines) == 1 and lines[0].startswith("PD is worse than no control (open loop)")
    assert "RMS |Δa| after the transient" in lines[0]


def test_a_bounded_run_is_not_warned_about_for_its_linearisation_alone() -> None:
    """The linearisation takes the model as its own plant: above 1 it is reported, and warned
    about only with the run's own evidence (the guard acting, or a larger tip error than the
    open loop's from engagement on)."""
    from jointplay.neural.study.comparison import verdict

    n = 50
    run = Run("neural IMC", np.arange(n) * 1e-3, np.zeros((n, 10)), np.zeros((n, 2)),
              np.zeros((n, 2)), 0, 0.0)
    base = {"max_position_engaged": 1e-4}
    comparison = SimpleNamespace(
        metrics={"open loop": base, "neural IMC": {"max_position_engaged": 5e-5}},
        limit=4e-4, nominal_radius={"neural IMC": 1.0013},
        local_radius={"neural IMC": np.array([1.0014, 1.0015])})
    text, warn = verdict("neural IMC", run, comparison)  # type: ignore[arg-type]
    assert not warn and "unstable (spectral radius 1.0013)" in text
    comparison.metrics["neural IMC"] = {"max_position_engaged": 1.5e-4}
    text, warn = verdict("neural IMC", run, comparison)  # type: ignore[arg-type]
    assert warn and "exceeds the open loop's by more than 1%" in text
