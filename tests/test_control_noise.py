"""The outer loop's horizon chosen for declared sensor noise
(jointplay.neural.control.noise_tuning).

The prediction (the stationary RMS of the twin's acceleration outputs, from the impulse
response of the loop linearised at rest) is checked against the same loop stepped with
sampled noise; the choice against the budget; the closed loop under noise against the
untold controller and PD (slow, on the session's identified model); bad input by flag.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from jointplay.common.errors import DescriptionError
from jointplay.neural.control.imc_settings import resolve_settings
from jointplay.neural.control.imc_step import build_step
from jointplay.neural.control.internal_model import _inner_gains
from jointplay.neural.control.loop import LoopConditions
from jointplay.neural.control.noise_tuning import (
    HORIZONS,
    NoiseTuning,
    _predicted_rms,
    linear_noise_loop,
    noise_vector,
    tune_to_noise,
)
from jointplay.neural.model.narx import Narx
from jointplay.neural.study.cases import NOISE, Case, declared
from jointplay.neural.study.control_run import NEURAL, ControllerSettings, compare

STUDY_NOISE = {"q2": NOISE["q"], "q3": NOISE["q"], "dq2": NOISE["dq"], "dq3": NOISE["dq"],
               **{k: v for k, v in NOISE.items() if k.startswith("tip")}}


def _declared(model: Narx) -> ControllerSettings:
    return ControllerSettings(measurement_noise=tuple(
        (n, STUDY_NOISE[n]) for n in model.output_names))


def _stepped(plant: Narx, settings: ControllerSettings, horizon: int | None,
             noise: np.ndarray) -> np.ndarray:
    """The loop stepped sample by sample (the CasADi step itself, no linearisation): the
    plant's acceleration outputs one sample ahead, per noise sample, less the same loop's
    response without noise (the twin's constant term moves it from rest: the noise's part
    is what is predicted)."""
    ny, nu = plant.n_outputs, plant.n_inputs
    q_idx, dq_idx, kp, kd = _inner_gains(plant)
    net = plant.casadi_function("net_next")
    accel = [i for i, c in enumerate(plant.carry) if c == 0.0]
    step = state = None
    if horizon is not None:
        step, layout = build_step(plant, replace(settings, horizon=horizon, guard=False))
        state = np.zeros(len(layout["state"]))
    runs = []
    for signal in (noise, np.zeros_like(noise)):
        hist, upast = [np.zeros(ny)] * plant.output_lags, [np.zeros(nu)] * plant.input_lags
        x, out = state, []
        for n in signal:
            u = -kp * n[q_idx] - kd * n[dq_idx]
            if step is not None:
                _, x, v, _, _ = step(hist[0] + n, np.zeros(ny), np.zeros(nu), x)
                u = u + np.asarray(v).ravel()
            y = np.asarray(net(np.concatenate([*hist, u, *upast[:-1]]))).ravel()
            hist, upast = [y, *hist[:-1]], [u, *upast[:-1]]
            out.append(y[accel])
        runs.append(np.array(out))
    return runs[0] - runs[1]


@pytest.mark.slow
def test_predicted_noise_equals_the_stepped_loop(identified: tuple[Path, Narx, Narx]) -> None:
    """The linearised loop's impulse response equals the stepped loop's (the twin is linear:
    to rounding), and the predicted RMS equals the stepped loop's under 30 000 samples of
    white noise to 5 % (the sampled RMS's own spread is about 2 %: the outputs are correlated
    over the filters' ~20 samples)."""
    arx = identified[2]
    settings = resolve_settings(arx, _declared(arx))
    std = noise_vector(arx, settings)
    accel = [i for i, c in enumerate(arx.carry) if c == 0.0]
    samples = np.random.default_rng(7).standard_normal((30000, arx.n_outputs)) * std
    for horizon in (None, 5, 20):
        a, b, c, d = linear_noise_loop(arx, settings, horizon, accel)
        for channel in (arx.output_index("dq3"), arx.output_index("tip_vx")):
            impulse = np.zeros((200, arx.n_outputs))
            impulse[0, channel] = std[channel]
            stepped = _stepped(arx, settings, horizon, impulse)
            state, linear = b @ impulse[0], [d @ impulse[0]]
            for _ in range(199):
                linear.append(c @ state)
                state = a @ state
            scale = np.max(np.abs(stepped))
            # The inner loop alone does not see the tip's velocity: both are zero there.
            assert scale > 0 or (horizon is None and channel != arx.output_index("dq3"))
            assert np.max(np.abs(np.array(linear) - stepped)) <= 1e-9 * scale
        sampled = float(np.sqrt(np.mean(np.sum(
            _stepped(arx, settings, horizon, samples)[1000:] ** 2, axis=1))))
        predicted = _predicted_rms(arx, settings, horizon, std, accel)
        assert predicted == pytest.approx(sampled, rel=0.05), horizon


@pytest.mark.slow
def test_the_shortest_horizon_within_the_budget_is_chosen(
        identified: tuple[Path, Narx, Narx]) -> None:
    _, narx, arx = identified
    settings, tuning = tune_to_noise(narx, arx, _declared(narx))
    assert settings.horizon == tuning.horizon > 5 and tuning.met
    ratios = dict(tuning.ratios)
    assert ratios[tuning.horizon] <= 1 + settings.noise_budget
    assert all(r > 1 + settings.noise_budget for h, r in ratios.items() if h < tuning.horizon)
    # Found to the sample, not to the coarse list's gap: one sample shorter is outside.
    assert ratios[tuning.horizon - 1] > 1 + settings.noise_budget
    # The outer loop adds to the noise: every ratio is above 1, and falls as the horizon grows.
    values = [ratios[h] for h in sorted(ratios)]
    assert all(r > 1 for r in values) and values == sorted(values, reverse=True)
    # A wider budget takes a shorter horizon.
    wide, _ = tune_to_noise(narx, arx, replace(_declared(narx), noise_budget=0.3))
    assert wide.horizon < settings.horizon


@pytest.mark.slow
def test_told_controller_adds_less_noise_than_the_untold(
        identified: tuple[Path, Narx, Narx]) -> None:
    """Under the study's sensor noise, on the default scene: the controller told the noise
    has a smaller RMS acceleration error than the same controller untold, within its budget
    (plus 5 % for the prediction and a 1 s run) of PD's, and tracks position no worse than
    PD."""
    from jointplay.scene.definition import default_scene

    _, narx, arx = identified
    scene = default_scene().with_run(t_end=1.0)
    told = _declared(narx)
    conditions = LoopConditions(noise=tuple(noise_vector(narx, resolve_settings(narx, told))),
                                seed=1)
    untold = compare(scene, narx, ControllerSettings(), arx=arx, analyse=False,
                     controllers=("PD", NEURAL), conditions=conditions)
    result = compare(scene, narx, told, arx=arx, analyse=False, controllers=(NEURAL,),
                     conditions=conditions, limit=untold.limit)
    pd = untold.metrics["PD"]["rms_acceleration_after"]
    assert result.noise_tuning is not None and result.noise_tuning.horizon > 5
    rms_told = result.metrics[NEURAL]["rms_acceleration_after"]
    assert rms_told < untold.metrics[NEURAL]["rms_acceleration_after"]
    assert rms_told < (1 + told.noise_budget + 0.05) * pd
    assert result.metrics[NEURAL]["max_position"] < untold.metrics["PD"]["max_position"]


def test_noise_flags_are_checked_by_name() -> None:
    from test_control import random_narx

    from jointplay.cli.neural_args import noise_pairs

    assert noise_pairs("dq2=4e-3, tip_vx=1e-3") == (("dq2", 4e-3), ("tip_vx", 1e-3))
    assert noise_pairs(None) == ()
    for bad in ("dq2", "dq2=x", "dq2=-1", "=3", "dq2=inf"):
        with pytest.raises(DescriptionError, match=r"--measurement-noise.*NAME=STD"):
            noise_pairs(bad)
    model = random_narx(3)
    with pytest.raises(DescriptionError, match=r"--measurement-noise.*'tip_vx' is not an output"):
        resolve_settings(model, ControllerSettings(measurement_noise=(("tip_vx", 1e-3),)))
    with pytest.raises(DescriptionError, match=r"--measurement-noise.*twice"):
        resolve_settings(model, ControllerSettings(measurement_noise=(("q2", 1.0), ("q2", 2.0))))
    with pytest.raises(DescriptionError, match="--noise-budget"):
        resolve_settings(model, ControllerSettings(noise_budget=0.0))
    # No noise on what the inner loop measures: the budget has nothing to be relative to.
    gains = {"joints": [2, 3], "kp": [100.0, 100.0], "kd": [1.0, 1.0]}
    with_pd = replace(model, context={**model.context, "plant": {
        **model.context["plant"], "inner_loop": gains}})
    with pytest.raises(DescriptionError, match="declare the noise of q2, q3, dq2, dq3"):
        tune_to_noise(with_pd, None, ControllerSettings(
            tracked=("q2", "q3"), measurement_noise=(("tip_ax", 0.1),)))


def test_study_refuses_its_own_noise_flag_and_declares_the_case_noise() -> None:
    from jointplay.cli import make_parser
    from jointplay.cli.study import study_plan
    from jointplay.scene.definition import default_scene

    args = make_parser().parse_args(["control-study", "--measurement-noise", "dq2=1e-3",
                                     "--quiet", "--out", "unused", "--seeds", "1"])
    with pytest.raises(DescriptionError, match=r"--measurement-noise.*noise case"):
        study_plan(args)
    scene = default_scene()
    quiet = Case("scene", 30e-6, (), LoopConditions())
    noisy = Case("noise", 30e-6, (), LoopConditions(noise=(1e-6,) * 9 + (0.0,)))
    base = ControllerSettings()
    assert declared(base, scene, quiet) is base
    told = declared(base, scene, noisy)
    assert told.measurement_noise[0] == ("q2", 1e-6) and len(told.measurement_noise) == 9


def test_study_sets_the_predicted_ratio_beside_the_measured_one() -> None:
    from jointplay.cli.study import noise_note

    def row(controller: str, seed: int, accel: float, **extra: float) -> dict[str, object]:
        return {"case": "noise", "controller": controller, "seed": seed,
                "rms_acceleration_after": accel, **extra}
    rows = [row("PD", -1, 0.5),
            *(row("neural IMC", s, a, horizon=h, predicted_noise_ratio=p)
              for s, a, h, p in ((0, 0.55, 20, 1.07), (1, 0.54, 22, 1.06)))]
    text = " ".join(noise_note(rows, undeclared=False))
    assert "chose horizon 20, 22" in text
    assert "neural IMC: RMS |Δa| after settling predicted 1.060-1.070x" in text
    assert "measured 1.080-1.100x PD's" in text
    assert noise_note(rows, undeclared=True)[0].startswith("Noise case: the controllers were not")


def test_a_budget_no_horizon_meets_is_said_plainly() -> None:
    tuning = NoiseTuning(horizon=100, budget=0.01, ratios=((5, 1.4), (100, 1.05)),
                         inner_only_rms=0.03, met=False)
    text = tuning.describe()
    assert "horizon 100" in text and "NO horizon up to" in text and "--noise-budget" in text
    assert HORIZONS[-1] == 100 and tuning.ratio == 1.05


def test_pairwise_filter_reduces_to_the_first_order_one_without_the_position() -> None:
    """With the position's noise far larger than its speed's, the pair's Kalman gain on the
    speed is the first-order filter's 1 - b and the position adds nothing; with the
    study's noise the position dominates the speed's estimate."""
    from test_control import random_narx

    from jointplay.neural.control.mismatch_filter import pair_gains, position_of

    assert [position_of(n) for n in ("dq7", "tip_vy", "q7", "tip_ax")] == \
        ["q7", "tip_y", None, None]
    model = random_narx(5)
    for b in (0.8, 0.9, 0.95):
        blind = resolve_settings(model, ControllerSettings(
            mismatch_filter=b, tracked=("q2", "q3"),
            measurement_noise=(("q2", 1e3), ("dq2", 4e-3))))
        (pg,) = pair_gains(model, blind)
        assert (pg.position, pg.velocity) == (0, 2)
        assert pg.gain[1, 1] == pytest.approx(1 - b, rel=1e-6)
        assert abs(pg.gain[1, 0]) * 1e3 < 1e-6 * (1 - b)  # a position residual of 1 sigma
    told = resolve_settings(model, ControllerSettings(
        tracked=("q2", "q3"), measurement_noise=(("q2", 3e-6), ("dq2", 4e-3))))
    (pg,) = pair_gains(model, told)
    assert pg.gain[1, 1] < 0.1 and pg.gain[1, 0] * 3e-6 > pg.gain[1, 1] * 4e-3
    # No pair without noise declared on both members; none without any noise.
    assert pair_gains(model, resolve_settings(model, ControllerSettings(
        tracked=("q2", "q3"), measurement_noise=(("dq2", 4e-3),)))) == []
    assert pair_gains(model, resolve_settings(model, ControllerSettings(
        tracked=("q2", "q3")))) == []


def test_pairwise_filter_follows_a_ramp_without_lag() -> None:
    """A mismatch growing at a constant rate (position a ramp, velocity its slope): the
    steady-state filter's fixed point is the signal itself, so its error dies out."""
    from test_control import random_narx

    from jointplay.neural.control.mismatch_filter import pair_gains

    model = random_narx(6)
    settings = resolve_settings(model, ControllerSettings(
        tracked=("q2", "q3"), measurement_noise=(("q3", 3e-6), ("dq3", 4e-3))))
    (pg,) = pair_gains(model, settings)
    t, slope = model.sample_time, 2e-3
    est = np.zeros(2)
    for k in range(3000):
        truth = np.array([slope * k * t, slope])
        pred = np.array([est[0] + t * est[1], est[1]])
        est = pred + pg.gain @ (truth - pred)
    assert est == pytest.approx(np.array([slope * 2999 * t, slope]), rel=1e-9)


def test_declared_noise_steps_run_as_casadi_code() -> None:
    from test_control import random_narx

    from jointplay.neural.control.imc import compile_controller
    from jointplay.neural.control.imc_kernel import kernel_source

    model = random_narx(7)
    settings = resolve_settings(model, ControllerSettings(
        horizon=2, tracked=("q2", "q3"), measurement_noise=(("q2", 3e-6), ("dq2", 4e-3))))
    with pytest.raises(ValueError, match="first-order mismatch filter only"):
        kernel_source(model, settings, None, "step")
    ctrl = compile_controller(model, settings)
    assert "_kernel(" not in ctrl.source
    # The compiled step is the CasADi function with the pairwise filter.
    state = ctrl.initial_state(np.zeros(model.n_outputs))
    y = np.linspace(-1e-3, 1e-3, model.n_outputs)
    out = ctrl.step(y, np.zeros(model.n_outputs), np.zeros(2), state)
    ref = ctrl.function(y, np.zeros(model.n_outputs), np.zeros(2), state)
    assert np.allclose(np.asarray(out[1]).ravel(), np.asarray(ref[1]).ravel(), rtol=1e-12,
                       atol=1e-15)
