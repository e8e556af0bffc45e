"""Mechanisms at a fixed step (run.integrator = "rk4" or "radau"): each method's order on
free flight, agreement with the compiled BDF at tight tolerances through a revolution of
impacts, the energy balance, and the errors a user meets."""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pytest

from jointplay.cli import main
from jointplay.common.errors import DescriptionError, SimulationError
from jointplay.mechanism import load_mechanism_scene, simulate_mechanism
from jointplay.mechanism.results import read_mechanism_result, write_mechanism_result

SCENE = Path("scenes/slider_crank.toml")
TENTH = Path("scenes/slider_crank_0_1mm.toml")


@pytest.mark.parametrize(("method", "order"), [("rk4", 4.0), ("radau", 5.0)])
def test_order_on_free_flight(method: str, order: float) -> None:
    """Over the 0.2 ms before the first impact (at 0.227 ms) the journal flies free: halving
    the step divides the change of the end state by 2^order (RK4: 4; 3-stage Radau IIA: 5).
    Measured: 4.001, 4.001, 4.000 and 4.97, 4.99."""
    span = 2e-4
    base = load_mechanism_scene(SCENE).with_run(t_end=span, output_step=span / 2)
    steps = 3 if method == "rk4" else 2
    ends = [simulate_mechanism(base.with_run(integrator=method, step=span / 2 ** k)).x[-1]
            for k in range(1, steps + 3)]
    changes = np.array([np.max(np.abs(a - b)[:3]) for a, b in itertools.pairwise(ends)])
    rates = np.log2(changes[:-1] / changes[1:])
    assert np.all(np.abs(rates - order) < 0.1), rates


@pytest.mark.parametrize("method", ["rk4", "radau"])
def test_agrees_with_the_bdf_through_a_revolution(method: str) -> None:
    """The 0.1 mm slider-crank over one revolution (15 impacts) at a step of 0.1 µs against
    the compiled BDF at rtol = atol = 1e-12: the slider within 1 µm (measured 0.40 µm with
    rk4, 0.55 µm with radau), the same impacts, each onset within 1 µs (0.49 / 0.70 µs: the
    onsets are interpolated between step ends)."""
    scene = load_mechanism_scene(TENTH)
    reference = simulate_mechanism(scene.with_run(rtol=1e-12, atol=1e-12))
    result = simulate_mechanism(scene.with_run(integrator=method, step=1e-7))
    slider = result.coordinate("guide.position") - reference.coordinate("guide.position")
    assert np.max(np.abs(slider)) < 1e-6
    assert len(result.impacts) == len(reference.impacts) == 15
    assert np.max(np.abs(result.impacts.time - reference.impacts.time)) < 1e-6
    assert np.all(np.isnan(result.impacts.peak_force))  # a fixed step locates no peaks
    force, _, located = result.largest_contact_force(1)
    assert not located and force == pytest.approx(np.max(result.normal_force[:, 0]))
    assert result.integrator == method and result.step == 1e-7


FOUR_BAR = Path("scenes/four_bar.toml")


def test_radau_through_the_four_bars_plastic_impacts() -> None:
    """The four-bar's near-plastic impacts (Flores' law at restitution 0.001) stop a Newton
    iteration met with the speed of no impact, or with a Jacobian out of contact: those steps
    are retaken (with the closing speed, then in parts) and the first 0.03 s at 10 µs agree
    with the BDF at 1e-12: the same three impacts, onsets within 2 µs (measured 0, 1.2 and
    0.16 µs), every coordinate within 5e-5 (measured 2.9e-5: each impact ends within one
    step, so the onset speed interpolated over that step is off; at 0.1 µs, 4.5e-8)."""
    scene = load_mechanism_scene(FOUR_BAR).with_run(t_end=0.03)
    reference = simulate_mechanism(scene.with_run(rtol=1e-12, atol=1e-12))
    result = simulate_mechanism(scene.with_run(integrator="radau", step=1e-5))
    assert result.stats["subdivided_steps"] > 0  # the parts were needed
    np.testing.assert_array_equal(result.impacts.joint, reference.impacts.joint)
    assert len(reference.impacts) == 3
    assert np.max(np.abs(result.impacts.time - reference.impacts.time)) < 2e-6
    n = len(result.coordinates) - 1  # the coordinates, the drive's time aside
    assert np.max(np.abs(result.x[:, :n] - reference.x[:, :n])) < 5e-5


def test_radau_stops_where_its_parts_fail_too(monkeypatch: pytest.MonkeyPatch) -> None:
    """A Newton iteration that never converges (its tolerance made 0) fails the step, its
    tenths, hundredths and thousandths (an update of exactly 0 passes, so a few parts do):
    the run stops within its first step with one message that says so, naming the step and
    the smallest part."""
    import jointplay.sim.fixed as fixed

    monkeypatch.setattr(fixed, "RADAU_NEWTON_TOLERANCE", 0.0)
    scene = load_mechanism_scene(TENTH).with_run(integrator="radau", step=1e-6, t_end=1e-4)
    with pytest.raises(SimulationError, match=r"did not converge .*reduce run\.step \(the "
                       r"step of 1e-06 s failed, and so did its parts down to 1e-09 s\)"
                       ) as info:
        simulate_mechanism(scene)
    assert info.value.time < 1e-6


def test_energy_balance_with_elastic_contact() -> None:
    """Restitution 1, no friction: kinetic + potential + contact energy - drive work closes
    to 2e-7 of the largest kinetic energy over a revolution (measured 1.6e-7; the work is the
    trapezoidal rule over the steps)."""
    scene = load_mechanism_scene(TENTH)
    scene = scene.with_mechanism(scene.mechanism.with_values({"contact.restitution": 1.0}))
    result = simulate_mechanism(scene.with_run(integrator="rk4", step=1e-7))
    assert result.dissipated[-1] == 0.0 and len(result.impacts) > 50
    assert np.max(np.abs(result.energy_residual)) < 2e-7 * np.max(result.kinetic)


def test_settings_and_errors(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scene = load_mechanism_scene(TENTH)
    with pytest.raises(DescriptionError, match=r"must divide run\.output_step") as info:
        scene.with_run(integrator="rk4", step=3e-7)
    assert info.value.field == "run.step"
    with pytest.raises(DescriptionError, match="for a mechanism") as info:
        scene.with_run(integrator="cvodes")
    assert info.value.field == "run.integrator"
    with pytest.raises(SimulationError, match=r"reduce run\.step or use bdf \(the contact of "
                                              r"slider_pin\)"):
        simulate_mechanism(scene.with_run(integrator="rk4", step=1e-5, t_end=0.001))
    assert main(["simulate", str(TENTH), "--integrator", "idas"]) == 2
    assert "a mechanism runs with bdf, rk4, radau" in capsys.readouterr().err
    text = TENTH.read_text(encoding="utf-8").replace("[run]\n", '[run]\nintegrator = "radau"\n'
                                                     "step = 5.0e-7\n")
    path = tmp_path / "radau.toml"
    path.write_text(text, encoding="utf-8")
    run = load_mechanism_scene(path).run
    assert (run.integrator, run.step, run.steps_per_output) == ("radau", 5e-7, 20)


def test_the_command_states_accuracy_and_keeps_the_method(tmp_path: Path,
                                                          capsys: pytest.CaptureFixture[str]
                                                          ) -> None:
    out = tmp_path / "run.h5"
    assert main(["simulate", str(TENTH), "--integrator", "rk4", "--step", "1e-6", "--t-end",
                 "0.002", "--verify", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "against the same run at rk4 step 1e-07 s; this run rk4 step 1e-06 s" in text
    assert "on the samples: a fixed step locates no peaks" in text
    back = read_mechanism_result(out)
    assert (back.integrator, back.step) == ("rk4", 1e-6)
    write_mechanism_result(back, tmp_path / "again.h5")
    assert read_mechanism_result(tmp_path / "again.h5").step == 1e-6


def test_applied_loads_enter_each_stage(tmp_path: Path) -> None:
    """A torque varying in time on the crank pin and a force on the slider, at a fixed step:
    the loads are evaluated at RK4's stage times, so the run agrees with the BDF at 1e-12
    (slider within 1e-7 m; measured 2.3e-8 m) and the drive work with it (within 0.5 %;
    measured 0.14 %)."""
    text = TENTH.read_text(encoding="utf-8").replace(
        "[run]", '[mechanism.torques]\ncrank_pin = "0.5*sin(1000*t)"\n\n[[mechanism.forces]]\n'
        'name = "gas"\nbody = "slider"\nx = "-20"\ny = "0"\n\n[run]')
    path = tmp_path / "loads.toml"
    path.write_text(text, encoding="utf-8")
    scene = load_mechanism_scene(path)
    reference = simulate_mechanism(scene.with_run(rtol=1e-12, atol=1e-12))
    result = simulate_mechanism(scene.with_run(integrator="rk4", step=1e-7))
    slider = result.coordinate("guide.position") - reference.coordinate("guide.position")
    assert np.max(np.abs(slider)) < 1e-7
    assert len(result.impacts) == len(reference.impacts)
    assert result.drive_work[-1] == pytest.approx(reference.drive_work[-1], rel=5e-3)


def test_the_skipped_check_is_priced_as_ten_runs(monkeypatch: pytest.MonkeyPatch,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    """At a fixed step the accuracy check reruns at a step 10x shorter: past the budget the
    command skips it and says so, the estimate being ten times the run."""
    import jointplay.cli.simulate as simulate_cli

    monkeypatch.setattr(simulate_cli, "VERIFY_BUDGET_S", 0.0)
    assert main(["simulate", str(TENTH), "--integrator", "rk4", "--step", "1e-6", "--t-end",
                 "0.001"]) == 0
    out = capsys.readouterr().out
    assert "accuracy not checked: the check (the same run at a step 10x shorter)" in out
    assert "against the same run" not in out
