"""The residual weight chosen in closed loop (identify --residual-by closed-loop): the
candidate with the lowest RMS acceleration error after settling on the validation motions
wins, ties go to the simpler model, a diverged run never wins, and only validation motions
other than the scene's own are run. The closed-loop runs are replaced by a stand-in whose
error is a known function of the candidate (the runs themselves are tested elsewhere)."""

from __future__ import annotations

import math
from dataclasses import replace
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from jointplay.neural.identify.pipeline import IdentifyConfig, output_names
from jointplay.neural.model.narx import Narx
from jointplay.neural.model.twin import ALPHAS, blend
from jointplay.neural.study.closed_loop_choice import (
    CLOSED_LOOP_ALPHAS,
    MARGIN,
    TWIN,
    choose_in_closed_loop,
    earns_its_place,
    label,
)


def _linear(seed: int) -> Narx:
    """A one-layer model of the plant's 10 outputs, 2 inputs, lags 2 and 2 (shapes only)."""
    rng = np.random.default_rng(seed)
    names, units = output_names((2, 3))
    ny, nx = len(names), 2 * len(names) + 4
    return Narx(weights=(0.1 * rng.standard_normal((ny, nx)),), biases=(np.zeros(ny),),
                regressor_mean=np.zeros(nx), regressor_scale=np.ones(nx),
                increment_mean=np.zeros(ny), increment_scale=np.ones(ny),
                output_scale=np.ones(ny), output_lags=2, input_lags=2, sample_time=1e-3,
                increment=(True,) * ny, output_names=names, output_units=units,
                input_names=("v2", "v3"), input_units=("N m", "N m"))


def _alpha_of(model: Narx, base: Narx) -> float | None:
    """The blend's weight from its linear path ((1 - alpha) x the base's); None: the twin."""
    if model.linear is None:
        return None
    return 1.0 - float(np.linalg.norm(model.linear) / np.linalg.norm(base.weights[0]))


def _stand_in(monkeypatch: pytest.MonkeyPatch, base: Narx, error: Any) -> list[Any]:
    """Closed-loop runs replaced: each candidate's RMS |Δa| after settling is
    ``error(alpha)`` (None: the twin; infinity: the run diverged)."""
    import jointplay.neural.control.imc as imc
    import jointplay.neural.study.comparison as comparison

    # Modules that the choice imports on first use bind compare by name: imported now, with
    # the real one, they keep it after this test (else a later test would get the stand-in).
    import jointplay.neural.study.control_run
    import jointplay.neural.study.runs  # noqa: F401

    calls: list[Any] = []

    def compare(scene: Any, model: Narx, settings: Any, **kw: Any) -> Any:
        calls.append((scene, kw.get("controllers")))
        if kw.get("controllers") == ("open loop",):
            return SimpleNamespace(runs={"open loop": SimpleNamespace(impact_times=[])},
                                   limit=1.0)
        value = error(_alpha_of(model, base)) * (2.0 if scene.name == "second" else 1.0)
        run = SimpleNamespace(diverged="bound" if math.isinf(value) else "")
        return SimpleNamespace(runs={comparison.NEURAL: run},
                               metrics={comparison.NEURAL: {"rms_acceleration_after": value}})

    monkeypatch.setattr(comparison, "compare", compare)
    monkeypatch.setattr(imc, "compile_controller", lambda *a, **k: None)
    return calls


def _motion(name: str) -> tuple[str, Any]:
    return name, SimpleNamespace(name=name, run=SimpleNamespace(output_step=1e-3))


def test_the_lowest_closed_loop_error_wins_and_a_diverged_run_never_does(
        monkeypatch: pytest.MonkeyPatch) -> None:
    base, network = _linear(1), _linear(2)
    # Best at 0.5; the full network diverges; the twin is worse than every blend.
    calls = _stand_in(monkeypatch, base, lambda a: 3.0 if a is None else
                      math.inf if a > 0.9 else 1.0 + (a - 0.5) ** 2)
    model, choice = choose_in_closed_loop(network, base, _linear(3),
                                          [_motion("first"), _motion("second")], ALPHAS)
    assert choice.chosen == label(0.5) and choice.alpha == 0.5
    assert model.linear is not None
    np.testing.assert_allclose(model.linear, blend(network, base, 0.5).linear, rtol=0,
                               atol=0)
    # the score is the geometric mean of the ratios to the base (alpha = 0) over the runs
    assert choice.score[label(0.5)] == pytest.approx(1.0 / 1.25, rel=1e-12)
    assert choice.score[label(0.0)] == 1.0 and math.isinf(choice.score[label(1.0)])
    assert choice.rms[TWIN] == [3.0, 6.0]
    assert choice.summary()["score_by_candidate"][label(1.0)] is None  # no infinity in JSON
    # one open loop per motion, then every candidate on each
    assert sum(c[1] == ("open loop",) for c in calls) == 2
    assert len(calls) == 2 * (1 + 1 + len(ALPHAS))


def test_ties_go_to_the_linear_base(monkeypatch: pytest.MonkeyPatch) -> None:
    base, network = _linear(1), _linear(2)
    _stand_in(monkeypatch, base, lambda a: 1.0)
    _, choice = choose_in_closed_loop(network, base, _linear(3), [_motion("first")], ALPHAS)
    assert choice.chosen == label(0.0) and choice.alpha == 0.0
    _, choice = choose_in_closed_loop(network, base, None, [_motion("first")], ALPHAS)
    assert choice.chosen == label(0.0)


def test_a_gain_within_the_margin_keeps_the_linear_base(monkeypatch: pytest.MonkeyPatch) -> None:
    """The network replaces its base only when better on every run and by more than MARGIN
    in the geometric mean; among the candidates that are, ties go to the twin."""
    base, network = _linear(1), _linear(2)
    # 1.5 % better everywhere: within the margin.
    _stand_in(monkeypatch, base, lambda a: 1.1 if a is None else 1.0 - 0.015 * (a > 0))
    model, choice = choose_in_closed_loop(network, base, _linear(3),
                                          [_motion("first"), _motion("second")], ALPHAS)
    assert choice.chosen == label(0.0) and choice.alpha == 0.0
    assert choice.best_other() == label(0.25)  # the first of the equal blends
    assert choice.summary()["margin"] == MARGIN
    np.testing.assert_allclose(model.predict(np.ones(24)), base.predict(np.ones(24)),
                               rtol=0, atol=1e-15)
    # 3 % better: beyond it.
    _stand_in(monkeypatch, base, lambda a: 1.1 if a is None else 1.0 - 0.03 * (a or 0))
    _, choice = choose_in_closed_loop(network, base, _linear(3), [_motion("first")], ALPHAS)
    assert choice.chosen == label(1.0)
    # The twin and a blend equally good, both beyond the margin: the twin.
    _stand_in(monkeypatch, base, lambda a: 0.9 if a is None or a == 0.5 else 1.0)
    _, choice = choose_in_closed_loop(network, base, _linear(3), [_motion("first")], ALPHAS)
    assert choice.chosen == TWIN


def test_earning_its_place_needs_every_run() -> None:
    assert earns_its_place([0.95, 0.97])
    assert not earns_its_place([0.985, 0.99])  # geometric mean above 1 - MARGIN
    assert not earns_its_place([0.80, 1.001])  # much better on average, worse on one run
    assert not earns_its_place([0.9, math.inf])  # a diverged run
    assert not earns_its_place([])


def test_only_validation_motions_other_than_the_scene_are_run() -> None:
    from jointplay.neural.identify.pipeline import default_limits, inner_loop_for
    from jointplay.neural.study.closed_loop_choice import validation_motions
    from jointplay.scene.definition import default_scene

    scene = default_scene()
    config = IdentifyConfig(duration=0.3, n_train=2, n_validation=3, n_test=1,
                            residual_by="closed-loop", clearances=(3e-5, 1e-4))
    motions = validation_motions(scene, config, inner_loop_for(scene, (), ()),
                                 default_limits(scene))
    # validation runs 0, 1, 2 drive the scene's torques, a multisine, steps
    assert [d for d, _ in motions] == ["multisine (clearance 0.0001)", "steps (clearance 3e-05)"]
    assert all(s.run.t_end == pytest.approx(0.3) for _, s in motions)
    with pytest.raises(Exception, match="validation 2 or more"):
        IdentifyConfig(n_validation=1, residual_by="closed-loop")
    with pytest.raises(Exception, match="free-run, closed-loop or closed-loop-scene"):
        IdentifyConfig(residual_by="loss")


def test_scene_family_motions_are_the_scenes_torques_retimed_never_the_scene_run() -> None:
    """--residual-by closed-loop-scene: the motions are the scene's own torques, every joint
    alike, at a drawn amplitude, rate and time shift (numpy and CasADi agree), on the
    scene's robot, seeded by the identification's seed."""
    import casadi as ca

    from jointplay.neural.identify.trajectories import SCENE_FAMILY_RATE, SCENE_FAMILY_SCALE
    from jointplay.neural.study.closed_loop_choice import (
        SCENE_FAMILY_MOTIONS,
        scene_family_motions,
    )
    from jointplay.scene.definition import default_scene

    scene = default_scene()
    config = IdentifyConfig(duration=0.5, seed=7, residual_by="closed-loop-scene",
                            n_validation=1)
    motions = scene_family_motions(scene, config)
    assert len(motions) == SCENE_FAMILY_MOTIONS
    t = np.linspace(0.0, 0.5, 101)
    ts = ca.SX.sym("t")
    for description, run in motions:
        assert "scene's torques" in description and run.robot is scene.robot
        assert run.run.t_end == pytest.approx(0.5)
        first = run.torques[0]
        scale, rate, shift = first.scale, first.rate, first.shift
        assert SCENE_FAMILY_SCALE[0] <= scale <= SCENE_FAMILY_SCALE[1]
        assert SCENE_FAMILY_RATE[0] <= rate <= SCENE_FAMILY_RATE[1]
        assert 0 <= shift <= 0.25 * 0.5 and (scale, rate, shift) != (1.0, 1.0, 0.0)
        for f, own in zip(run.torques, scene.torques, strict=True):
            assert (f.scale, f.rate, f.shift) == (scale, rate, shift)
            assert np.allclose(f.numpy(t), scale * own.numpy(rate * t + shift), rtol=0,
                               atol=1e-12)
            symbolic = ca.Function("f", [ts], [f.casadi(ts)])
            assert float(symbolic(0.3)) == pytest.approx(float(f.numpy(0.3)), abs=1e-12)
    again = scene_family_motions(scene, config)
    assert [d for d, _ in again] == [d for d, _ in motions]
    other = scene_family_motions(scene, IdentifyConfig(duration=0.5, seed=8))
    assert [d for d, _ in other] != [d for d, _ in motions]
    more = scene_family_motions(scene, replace(config, scene_motions=3))
    assert [d for d, _ in more][:2] == [d for d, _ in motions] and len(more) == 3
    with pytest.raises(Exception, match="scene_motions"):
        IdentifyConfig(scene_motions=0)


def test_the_report_says_what_chose_the_weight_and_what_was_saved(
        monkeypatch: pytest.MonkeyPatch) -> None:
    from jointplay.neural.identify.evaluation import _closed_loop_lines

    base, network = _linear(1), _linear(2)
    res = {"free_run_loss_persistence": 1.0}
    _stand_in(monkeypatch, base, lambda a: 1.0 if a is None else 2.0)
    _, choice = choose_in_closed_loop(network, base, _linear(3), [_motion("first")], ALPHAS)
    text = _closed_loop_lines(choice.summary(), "LPV-ARX", "0: 0.5", res)
    assert "chosen in closed loop" in text and "first" in text
    assert "the ARX twin without the scheduling signals: the network does no work" in text
    _stand_in(monkeypatch, base, lambda a: math.inf if a is None or a > 0.9 else 1.0 - a / 2)
    _, choice = choose_in_closed_loop(network, base, _linear(3), [_motion("first")], ALPHAS)
    text = _closed_loop_lines(choice.summary(), "LPV-ARX", "0: 0.5", res)
    assert "Saved: LPV-ARX + 0.75 x the residual" in text
    assert "alpha=1: diverged" in text and "ARX twin: diverged" in text
    assert "the validation runs' motions" in text
    family = _closed_loop_lines(replace(choice, motions="scene family").summary(), "LPV-ARX",
                                "0: 0.5", res)
    assert "motions of the scene's own family" in family and "validation runs'" not in family


@pytest.mark.slow
def test_identify_runs_each_candidate_in_closed_loop(tmp_path: Any) -> None:
    """End to end on the paper scene (tiny: 0.2 s runs, a 4-node network): every candidate
    ran in closed loop on the one validation motion that is not the scene's, and the weight
    saved is the one with the lowest error there (the model may still be refused)."""
    pytest.importorskip("torch")
    import contextlib
    import json

    from jointplay.neural.identify.pipeline import ModelRejected
    from jointplay.neural.study.closed_loop_choice import identify_model
    from jointplay.scene.definition import default_scene

    config = IdentifyConfig(duration=0.2, n_train=1, n_validation=2, n_test=1, hidden=(4,),
                            one_step_iterations=2, multi_step_iterations=0, window=20,
                            workers=1, scheduling=True, lpv_base=True,
                            residual_by="closed-loop")
    out = tmp_path / "model"
    with contextlib.suppress(ModelRejected):  # refused or not, the choice is recorded
        identify_model(default_scene(), out, config, quiet=True)
    closed = json.loads((out / "metrics.json").read_text())["residual"]["closed_loop"]
    assert closed["runs"] == ["multisine (scene robot)"]
    rms = closed["rms_acceleration_after"]
    assert set(rms) == {TWIN, *(label(a) for a in CLOSED_LOOP_ALPHAS)}
    finite = {k: v[0] for k, v in rms.items() if v[0] is not None}
    assert finite and all(v > 0 for v in finite.values())
    base = finite.get(label(0.0))
    earned = {k: v for k, v in finite.items() if base and k != label(0.0)
              and earns_its_place([v / base])}
    assert closed["chosen"] == (min(earned, key=lambda k: (earned[k], list(rms).index(k)))
                                if earned else label(0.0))
    assert "chosen in closed loop" in (out / "report.md").read_text()
