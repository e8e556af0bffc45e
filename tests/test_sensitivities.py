"""Forward sensitivities through contact events (simulate(..., sensitivities=[...])).

Checked against closed forms (a journal in free flight: its position's derivative with
respect to gravity, and its first contact time's with respect to gravity and the clearance)
and against central differences of whole runs (jointplay.sim.sensitivity_check): the
differences at rtol = atol = 1e-13, their step h = 1e-3 relative (the noise of a run at that
tolerance is ~1e-10 relative, and its cube root ~5e-4; measured, h = 3e-3 was worse by
truncation and 1e-4 by noise), checked for stability against h / 2; the sensitivities from a
run at the same settings. Agreement is normwise: the largest difference over the samples (or
impacts) over the largest central difference; the state and the tip between impacts.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from sim_fixtures import make_scene, pin_in_bearing

from jointplay.common.errors import DescriptionError
from jointplay.results.sensitivities import Sensitivities
from jointplay.robot import with_parameters
from jointplay.sim import simulate
from jointplay.sim.sensitivity_check import compare_with_differences, parameter_value

SCENES = Path(__file__).resolve().parents[1] / "scenes"
TIGHT = {"rtol": 1e-13, "atol": 1e-13}
# Goals: 1e-5 between impacts (state, tip), 1e-4 for the event times and peak forces.
BETWEEN_IMPACTS = 1e-5
EVENTS = 1e-4


def _falling_pin(t_end: float = 0.012, **robot: Any) -> Any:
    """A journal in a bearing, falling under gravity from the centre and bouncing (e = 0.8):
    one clearance joint, no friction."""
    table = pin_in_bearing(restitution=0.8, **robot)
    table["gravity"] = {"enabled": True, "vector": [0.0, -9.81]}
    return make_scene(table, t_end=t_end, output_step=1e-4, **TIGHT)


def test_state_is_the_same_with_sensitivities() -> None:
    scene = _falling_pin()
    plain = simulate(scene)
    with_sens = simulate(scene, sensitivities=["joint1.clearance", "gravity.y"])
    assert plain.sensitivities is None
    assert np.array_equal(plain.q, with_sens.q) and np.array_equal(plain.u, with_sens.u)
    assert np.array_equal(plain.impacts.time, with_sens.impacts.time)
    assert np.array_equal(plain.impacts.peak_force, with_sens.impacts.peak_force)
    assert plain.stats["steps"] == with_sens.stats["steps"]


def test_directional_forcing_equals_the_full_input_blocks(monkeypatch: pytest.MonkeyPatch
                                                          ) -> None:
    """The step's forcing along the named directions by forward-mode AD (the model's
    forward_dynamics_input_directions) gives the sensitivities the full input blocks give (a
    model generated before it had only those), to round-off, through three impacts."""
    from jointplay.derive import deferred

    scene = _falling_pin()
    names = ["gravity.y", "joint1.clearance", "link1.mass", "contact.restitution",
             "joint1.bearing_E"]  # five: two calls of four directions, one half empty
    directional = simulate(scene, sensitivities=names).sensitivities
    monkeypatch.setattr(deferred, "INPUT_DIRECTIONAL", "not generated")
    blocks = simulate(scene, sensitivities=names).sensitivities
    assert len(names) > deferred.INPUT_DIRECTIONS
    for field in ("state", "tip_position", "tip_velocity", "impact_times", "impact_peaks"):
        a, b = np.asarray(getattr(directional, field)), np.asarray(getattr(blocks, field))
        scale = np.max(np.abs(b), axis=tuple(range(b.ndim - 1)), keepdims=True)
        np.testing.assert_allclose(a / scale, b / scale, rtol=0, atol=1e-9, err_msg=field)


def test_free_flight_closed_form() -> None:
    """Centred journal thrown along x with gravity along x: e(t) = v0 t + g t^2 / 2 until
    |e| = c at tau, so de/dg = t^2 / 2, du/dg = t, and dtau/dg = -(tau^2 / 2) / (v0 + g tau),
    dtau/dc = 1 / (v0 + g tau)."""
    v0, g, c = 0.02, 3.0, 30e-6
    table = pin_in_bearing(clearance=c)
    table["gravity"] = {"enabled": True, "vector": [g, 0.0]}
    scene = make_scene(table, t_end=2e-3, output_step=1e-4, initial={"dex1": v0}, **TIGHT)
    result = simulate(scene, sensitivities=["gravity.x", "joint1.clearance"])
    sens = result.sensitivities
    tau = (-v0 + math.sqrt(v0**2 + 2 * g * c)) / g
    assert len(result.impacts) >= 1
    assert result.impacts.time[0] == pytest.approx(tau, rel=1e-9)
    free = result.t < tau
    t = result.t[free]
    ex = result.coordinate_names.index("ex1")
    n = len(result.coordinate_names)
    np.testing.assert_allclose(sens.state[free, ex, 0], t**2 / 2, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(sens.state[free, n + ex, 0], t, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(sens.tip_position[free, 0, 0], t**2 / 2, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(sens.state[free, :, 1], 0.0, atol=1e-15)
    speed = v0 + g * tau
    assert sens.impact_times[0, 0] == pytest.approx(-(tau**2 / 2) / speed, rel=1e-8)
    assert sens.impact_times[0, 1] == pytest.approx(1 / speed, rel=1e-8)


def _check(name: str, row: dict[str, float], key: str, goal: float) -> None:
    """The reference is good to the goal (its change from h to h / 2), and the sensitivity
    agrees with it to the goal, give or take that change."""
    assert row[f"{key}_stability"] < goal, (name, key, row)
    assert row[key] < goal + row[f"{key}_stability"], (name, key, row)


def test_single_clearance_joint_against_central_differences() -> None:
    """Three impacts of a frictionless journal: gravity, the clearance, the mass, the
    restitution and the bearing's Young's modulus (the contact stiffness)."""
    scene = _falling_pin()
    names = ("gravity.y", "joint1.clearance", "link1.mass", "contact.restitution",
             "joint1.bearing_E")
    report = compare_with_differences(scene, names)
    for name, row in report.items():
        for key in ("state", "tip", "velocity"):
            _check(name, row, key, BETWEEN_IMPACTS)
        for key in ("times", "peaks"):
            _check(name, row, key, EVENTS)


def test_paper_scene_against_central_differences() -> None:
    """The paper scene's first four impacts (two clearance joints, friction, a payload): the
    clearance, the journal friction, the payload, a length and a contact stiffness."""
    import jointplay

    scene = jointplay.load_scene(SCENES / "paper_4dof.toml").with_run(
        t_end=0.005, output_step=2.5e-4, **TIGHT)
    names = ("joint2.clearance", "friction.mu", "payload.mass", "link3.length",
             "joint3.bearing_E")
    report = compare_with_differences(scene, names)
    for name, row in report.items():
        # Friction moves the tip by less than 1e-9 m per unit mu in these 5 ms: its central
        # difference is noise there (4e-4 from h to h / 2); its state and tip velocity are not.
        outputs = ("state", "velocity") if name == "friction.mu" else ("state", "tip",
                                                                       "velocity")
        for key in outputs:
            _check(name, row, key, BETWEEN_IMPACTS)
        for key in ("times", "peaks"):
            _check(name, row, key, EVENTS)


def test_error_control_makes_them_follow_the_tolerances() -> None:
    """With the sensitivities in the error test, a run at rtol = atol = 1e-10 meets the goals
    against the central differences at 1e-13 (without, it misses them by 5x: 4.6e-5 on the
    tip); it takes more steps, and its state moves within the tolerances."""
    names = ("gravity.y", "joint1.clearance", "contact.restitution")
    scene = _falling_pin().with_run(rtol=1e-10, atol=1e-10)
    plain = simulate(scene)
    controlled = simulate(scene, sensitivities=names, sensitivity_error_control=True)
    assert controlled.stats["steps"] > plain.stats["steps"]
    assert len(controlled.impacts) == len(plain.impacts)
    # the state moves, but no farther from a run at 1e-13 than the run without
    reference = simulate(_falling_pin())
    moved = np.max(np.abs(controlled.tip_position - reference.tip_position))
    assert moved <= np.max(np.abs(plain.tip_position - reference.tip_position))
    report = compare_with_differences(scene, names, reference=_falling_pin(),
                                      error_control=True)
    for name, row in report.items():
        for key in ("state", "tip", "velocity"):
            _check(name, row, key, BETWEEN_IMPACTS)
        for key in ("times", "peaks"):
            _check(name, row, key, EVENTS)


def test_sliding_with_friction_against_central_differences() -> None:
    """A journal set on its bearing's wall and sent sliding along it (2 cm/s, mu = 0.1):
    one contact phase, persistent, the friction ramp crossed as the sliding reverses; the
    state's derivative with respect to the friction coefficient and the bearing's modulus
    after the onset, against central differences (h = 1e-3 relative, checked against h / 2)."""
    table = pin_in_bearing(restitution=0.8, mu=0.1)
    table["gravity"] = {"enabled": True, "vector": [0.0, -9.81]}
    scene = make_scene(table, t_end=0.03, output_step=1e-4, initial={"ey1": -0.999 * 30e-6,
                                                                      "dex1": 0.02}, **TIGHT)
    names = ("friction.mu", "joint1.bearing_E")
    result = simulate(scene, sensitivities=names)
    assert len(result.impacts) == 1 and not result.impacts.separated[0]
    after = result.t > 2e-3
    for k, name in enumerate(names):
        value = parameter_value(result, name)
        fd = []
        for h in (1e-3 * value, 5e-4 * value):
            plus = simulate(scene, parameters={name: value + h})
            minus = simulate(scene, parameters={name: value - h})
            fd.append((np.hstack([plus.q, plus.u]) - np.hstack([minus.q, minus.u]))[after]
                      / (2 * h))
        scale = np.max(np.abs(fd[0]))
        assert np.max(np.abs(fd[1] - fd[0])) < BETWEEN_IMPACTS * scale, name
        error = np.max(np.abs(result.sensitivities.state[after, :, k] - fd[0]))
        assert error < BETWEEN_IMPACTS * scale, (name, error / scale)


def test_clearance_is_a_settable_parameter() -> None:
    scene = _falling_pin(t_end=4e-3)
    by_clearance = simulate(scene, parameters={"joint1.clearance": 40e-6})
    by_radius = simulate(scene, parameters={"joint1.journal_radius": 10e-3 - 40e-6})
    assert np.array_equal(by_clearance.q, by_radius.q)
    with pytest.raises(DescriptionError, match=r"joint1\.journal_radius"):
        simulate(scene, parameters={"joint1.clearance": 40e-6,
                                    "joint1.journal_radius": 9.9e-3})
    with pytest.raises(DescriptionError, match=r"joint1\.clearance: must be a radial"):
        simulate(scene, parameters={"joint1.clearance": -1e-6})
    robot = with_parameters(scene.robot, {"joint1.clearance": 40e-6})
    joint = robot.joints[0]
    assert joint.bearing_radius - joint.journal_radius == pytest.approx(40e-6, rel=1e-9)
    assert joint.bearing_radius == scene.robot.joints[0].bearing_radius


@pytest.mark.parametrize(("names", "match"), [
    (["friction.mu"], "friction.mu.*not a parameter"),
    (["gravity.yy"], "gravity.yy.*did you mean 'gravity.y'"),
    (["joint2.clearance"], "joint2.clearance.*did you mean 'joint1.clearance'"),
    (["gravity.y", "gravity.y"], "named twice"),
])
def test_names_the_model_does_not_have(names: list[str], match: str) -> None:
    with pytest.raises(DescriptionError, match=match):
        simulate(_falling_pin(t_end=1e-3), sensitivities=names)


def test_other_integrators_refuse() -> None:
    scene = _falling_pin(t_end=1e-3).with_run(integrator="cvodes")
    with pytest.raises(DescriptionError, match="bdf"):
        simulate(scene, sensitivities=["gravity.y"])


def test_result_object() -> None:
    scene = _falling_pin(t_end=4e-3)
    result = simulate(scene, sensitivities=("gravity.y", "link1.mass"))
    sens = result.sensitivities
    assert isinstance(sens, Sensitivities)
    assert sens.names == ("gravity.y", "link1.mass")
    assert np.array_equal(sens.t, result.t)
    n_t, n_x = result.t.size, 2 * len(result.coordinate_names)
    assert sens.state.shape == (n_t, n_x, 2)
    assert sens.tip_position.shape == sens.tip_velocity.shape == (n_t, 2, 2)
    assert sens.impact_times.shape == sens.impact_peaks.shape == (len(result.impacts), 2)
    assert sens.column("link1.mass") == 1
    with pytest.raises(ValueError):
        sens.state[0, 0, 0] = 1.0
    data = sens.to_dict()
    assert data["names"] == ["gravity.y", "link1.mass"]
    assert np.array_equal(np.asarray(data["impact_times"]), sens.impact_times)


def test_resting_journals_start_with_their_equilibrium_derivative() -> None:
    """Journals resting in their bearings start where the accelerations vanish, which
    depends on the parameters: d x0 / d p (implicit function theorem) against central
    differences of the equilibrium itself (h = 1e-4 relative; its residual is 1e-9). The
    weights are left out: at this hanging pose the equilibrium search fails for a payload or
    a gravity moved by 1e-4 (the search, not the derivative)."""
    import jointplay

    scene = jointplay.load_scene(SCENES / "paper_4dof.toml").with_journals("resting") \
        .with_run(t_end=1e-3, output_step=1e-3)
    names = ("joint2.clearance", "joint3.clearance", "joint3.bearing_E")
    sens = simulate(scene, sensitivities=names).sensitivities
    base = simulate(scene.with_run(t_end=1e-3))
    for k, name in enumerate(names):
        value = parameter_value(base, name)
        h = 1e-4 * value
        plus = simulate(scene, parameters={name: value + h})
        minus = simulate(scene, parameters={name: value - h})
        fd = (np.hstack([plus.q, plus.u])[0] - np.hstack([minus.q, minus.u])[0]) / (2 * h)
        assert np.max(np.abs(fd)) > 0
        np.testing.assert_allclose(sens.state[0, :, k], fd, rtol=0,
                                   atol=1e-5 * np.max(np.abs(fd)), err_msg=name)
