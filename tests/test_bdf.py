"""The compiled BDF integrator (run.integrator = "bdf"): located contact phases."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from jointplay.common.errors import DescriptionError
from jointplay.scene.definition import default_scene
from jointplay.sim import simulate


def _bdf(**run: object):  # type: ignore[no-untyped-def]
    return default_scene().with_run(integrator="bdf", t_end=0.006, **run)


def test_located_peaks_do_not_depend_on_the_output_step() -> None:
    """The peak of the first impact is located on the dense output, so a 1 ms and a 1 us
    output grid report the same value (to 1e-6 relative), and it is above every sample."""
    coarse = simulate(_bdf(output_step=1e-3))
    fine = simulate(_bdf(output_step=1e-6))
    assert len(coarse.impacts) >= 3
    np.testing.assert_allclose(coarse.impacts.peak_force[:3], fine.impacts.peak_force[:3],
                               rtol=1e-6)
    np.testing.assert_allclose(coarse.impacts.max_penetration[:3],
                               fine.impacts.max_penetration[:3], rtol=1e-6)
    for k, joint in enumerate(fine.clearance_joints):
        rows = fine.impacts.joint == joint
        assert np.max(fine.impacts.peak_force[rows]) >= np.max(fine.normal_force[:, k])
        assert np.max(fine.impacts.max_penetration[rows]) >= np.max(fine.penetration[:, k])


def test_a_run_without_peaks_is_the_same_run() -> None:
    """peaks=False skips locating the peak forces and nothing else: through the first impacts
    the motion, the tip, the impact table's other columns, the step count and (with
    sensitivities) the state's derivatives equal those of a run with peaks to the bit; the
    peak columns and the peaks' sensitivities are NaN, not a number that looks measured."""
    scene = _bdf().with_run(t_end=0.02)
    names = ("joint2.clearance", "friction.mu")
    for kwargs in ({}, {"sensitivities": names}):
        full = simulate(scene, **kwargs)  # type: ignore[arg-type]
        lean = simulate(scene, peaks=False, **kwargs)  # type: ignore[arg-type]
        assert len(full.impacts) >= 5
        assert full.stats["steps"] == lean.stats["steps"]
        for name in ("q", "u", "tip_position", "normal_force"):
            np.testing.assert_array_equal(getattr(lean, name), getattr(full, name))
        for column in ("time", "speed", "max_penetration", "separation_time", "impulse"):
            np.testing.assert_array_equal(getattr(lean.impacts, column),
                                          getattr(full.impacts, column))
        assert np.all(np.isfinite(full.impacts.peak_force))
        assert np.all(np.isnan(lean.impacts.peak_force))
        assert np.all(np.isnan(lean.impacts.peak_force_time))
        if kwargs:
            np.testing.assert_array_equal(lean.sensitivities.state, full.sensitivities.state)
            np.testing.assert_array_equal(lean.sensitivities.impact_times,
                                          full.sensitivities.impact_times)
            assert np.all(np.isfinite(full.sensitivities.impact_peaks))
            assert np.all(np.isnan(lean.sensitivities.impact_peaks))


def test_bdf_follows_cvodes_through_the_first_impacts() -> None:
    """Same scene, same tolerances: onset times and tip path agree with CVODES."""
    a = simulate(_bdf(rtol=1e-8, atol=1e-8))
    b = simulate(default_scene().with_run(integrator="cvodes", t_end=0.006, rtol=1e-8,
                                          atol=1e-8))
    np.testing.assert_allclose(a.impacts.time[:4], b.impacts.time[:4], atol=1e-6)
    np.testing.assert_allclose(a.impacts.speed[:4], b.impacts.speed[:4], rtol=1e-3)
    assert np.max(np.abs(a.tip_position - b.tip_position)) < 1e-6
    assert bool(np.all(a.impacts.separated[:4]))
    assert np.all((a.impacts.restitution[:4] > 0.85) & (a.impacts.restitution[:4] < 0.95))


# ---- one impact against closed forms -------------------------------------------------------

def _single_impact(law: str, ce: float, speed: float = 0.5, mu: float = 0.0):  # type: ignore[no-untyped-def]
    from sim_fixtures import make_scene, pin_in_bearing

    robot = pin_in_bearing(law=law, restitution=ce, clearance=30e-6, mu=mu)
    # with friction, off centre: a journal thrown from the centre hits radially, without slip
    scene = make_scene(robot, initial={"dex1": speed, "ey1": 15e-6 if mu else 0.0},
                       t_end=4e-4, output_step=1e-4, rtol=1e-10, atol=1e-10)
    return simulate(scene)


def test_undamped_impact_matches_hertz() -> None:
    """ce = 1 (no damping): the located maximum penetration and peak force equal Hertz's
    closed form delta_max = ((n+1) m v^2 / (2K))^(1/(n+1)), F = K delta_max^n (to 1e-7), the
    contact lasts 2.943 delta_max / v (the constant is rounded: to 1e-3), the body leaves at
    the speed it came. Outputs are 0.1 ms apart: every value is located, not sampled."""
    from sim_fixtures import hertz_stiffness

    mass, speed, n = 2.0, 0.5, 1.5
    result = _single_impact("lankarani-nikravesh", 1.0, speed)
    k = hertz_stiffness(10e-3, 10e-3 - 30e-6)
    delta_max = ((n + 1) * mass * speed**2 / (2 * k)) ** (1 / (n + 1))
    phase = result.impacts
    assert phase.speed[0] == pytest.approx(speed, rel=1e-9)
    assert phase.max_penetration[0] == pytest.approx(delta_max, rel=1e-7)
    assert phase.peak_force[0] == pytest.approx(k * delta_max**n, rel=1e-7)
    assert phase.duration[0] == pytest.approx(2.943 * delta_max / speed, rel=1e-3)
    assert phase.restitution[0] == pytest.approx(1.0, abs=1e-8)
    assert bool(phase.separated[0])


@pytest.mark.parametrize(("law", "ce", "rel"), [
    ("lankarani-nikravesh", 0.95, 5e-3), ("hunt-crossley", 0.95, 5e-3),
    ("gonthier", 0.8, 0.05), ("gonthier", 0.5, 0.05),
    ("flores", 0.8, 0.02), ("flores", 0.5, 0.06),
])
def test_effective_restitution_of_each_law(law: str, ce: float, rel: float) -> None:
    """Exit / approach speed of one impact against the coefficient each law is built to give
    (L-N and H-C only near ce = 1; Gonthier and Flores over the range, approximately: the
    bounds are what the laws' derivations promise, measured 0.4 %, 0.2 %, 4 %, 2.5 %, 1.4 % and
    5.9 %)."""
    result = _single_impact(law, ce)
    assert result.impacts.restitution[0] == pytest.approx(ce, rel=rel)


def test_phase_energies_sum_to_the_run_dissipation() -> None:
    """Damping and friction energy per phase add up to the run's dissipation quadrature:
    nothing is dissipated outside a contact phase."""
    result = _single_impact("flores", 0.8, mu=0.3)
    phases = result.impacts
    total = float(np.sum(phases.damping_energy) + np.sum(phases.friction_energy))
    assert float(np.sum(phases.friction_energy)) > 0
    assert total == pytest.approx(result.energy["dissipated"][-1], rel=1e-8)


def test_table_torques_equal_the_same_expression(tmp_path: Path) -> None:
    """Torques reach the compiled loop as data: a table holding a piecewise-linear drive and
    the expression of the same function give the same run (to the integration tolerance)."""
    from sim_fixtures import clearance_joint, make_scene, robot_table

    from jointplay.scene.definition import scene_from_dict

    robot = robot_table(2, [{"kind": "ideal"}, clearance_joint()], restitution=0.8)
    expression = make_scene(robot, torques={"joint1": "2*min(t, 0.05) - max(t - 0.1, 0)",
                                            "joint2": "0.5*step(t - 0.02)"}, t_end=0.15)
    # the step at 0.02 s as two rows a hair before it: a table is piecewise linear
    table = tmp_path / "torques.csv"
    table.write_text("t,joint1,joint2\n0,0,0\n0.01999999999,0.03999999998,0\n"
                     "0.02,0.04,0.5\n0.05,0.1,0.5\n0.1,0.1,0.5\n0.15,0.05,0.5\n")
    data = {"name": "table", "robot": robot, "torques": {"table": str(table)},
            "run": {"t_end": 0.15, "output_step": 1e-3, "rtol": 1e-8, "atol": 1e-8}}
    tabled = scene_from_dict(data, source="test")
    a, b = simulate(expression), simulate(tabled)
    np.testing.assert_allclose(a.tau, b.tau, atol=1e-6)
    assert np.max(np.abs(a.q[:, 0] - b.q[:, 0])) < 1e-6


def test_reduced_newton_matrix_equals_the_full_one(monkeypatch: pytest.MonkeyPatch) -> None:
    """The paper scene's state Jacobian is [0 D; Jq Jv]: forced to the n x n Newton matrix
    I - c Jv - c^2 Jq D (``newton="reduced"``; the stat says so), the run through five
    impacts takes the same steps as through the full 2n x 2n LU and agrees to 1e-10 relative
    (the two solves differ by round-off only). With 6 coordinates, below the driver's
    threshold of 12, the default takes the full LU. JOINTPLAY_NEWTON overrides the keyword;
    a matrix it does not know is refused, naming ``newton``."""
    scene = _bdf(rtol=1e-9, atol=1e-9)
    reduced = simulate(scene, newton="reduced")
    full = simulate(scene, newton="full")
    default = simulate(scene)
    monkeypatch.setenv("JOINTPLAY_NEWTON", "full")
    overridden = simulate(scene, newton="reduced")
    assert overridden.stats["reduced_lu_decompositions"] == 0
    monkeypatch.setenv("JOINTPLAY_NEWTON", "reduced")
    assert simulate(scene).stats["reduced_lu_decompositions"] > 0
    with pytest.raises(DescriptionError, match="newton: must be one of auto, full, reduced"):
        simulate(scene, newton="sparse")
    import jointplay.sim as sim_module

    def no_work(*args: object, **kwargs: object) -> None:
        raise AssertionError("a model was loaded before the bad matrix was refused")

    monkeypatch.setattr(sim_module, "load_scene_model", no_work)
    with pytest.raises(DescriptionError, match="newton"):  # refused before any work
        simulate(scene, newton="sparse", compare_ideal=True)
    assert reduced.stats["reduced_lu_decompositions"] == reduced.stats["lu_decompositions"] > 0
    assert full.stats["reduced_lu_decompositions"] == 0 < full.stats["lu_decompositions"]
    assert default.stats["reduced_lu_decompositions"] == 0
    assert default.stats["steps"] == full.stats["steps"]
    assert reduced.stats["steps"] == full.stats["steps"]
    assert len(reduced.impacts) == len(full.impacts) >= 5
    state_reduced = np.hstack([reduced.q, reduced.u])
    state_full = np.hstack([full.q, full.u])
    scale = np.max(np.abs(state_full), axis=0)
    assert float(np.max(np.abs(state_reduced - state_full) / scale)) < 1e-10
    np.testing.assert_allclose(reduced.impacts.time, full.impacts.time, rtol=0, atol=1e-12)
    np.testing.assert_allclose(reduced.impacts.peak_force, full.impacts.peak_force, rtol=1e-10)


def test_event_scan_normal_forces_equal_the_contact_functions() -> None:
    """The event scan samples the normal forces through the model's ``normal_force`` (the
    contact function's f_n alone). It equals contact's f_n to the bit on random states, and a
    model without it (generated before it existed) scans through ``contact``: the same phase
    table, to the bit."""
    import dataclasses

    from jointplay.results.records import Impacts
    from jointplay.store.lookup import model_for
    from jointplay.store.model import load_model

    scene = _bdf(output_step=1e-3)
    model = model_for(scene.robot)
    rng = np.random.default_rng(7)
    normal, contact = model.function("normal_force"), model.function("contact")
    p = np.asarray(model.default_parameters, dtype=float)
    clearance_rows = [model.coordinates.index(f"e{axis}{j}") for j in model.clearance_joints
                      for axis in "xy"]
    for _ in range(20):
        x = rng.normal(size=model.n_state)
        x[clearance_rows] *= 40e-6  # about the clearance: some joints in contact, some not
        v_imp = rng.uniform(0.01, 1.0, size=len(model.clearance_joints))
        f_n = np.asarray(normal(x, p, v_imp)[0], dtype=float).ravel()
        expected = np.asarray(contact(x, p, v_imp)[3], dtype=float).ravel()
        assert np.array_equal(f_n, expected)
        assert np.any(f_n > 0)
    with_function = simulate(scene, model=model)
    older = load_model(model.folder)
    older.layout = dataclasses.replace(older.layout, functions={
        k: v for k, v in older.layout.functions.items() if k != "normal_force"})
    without = simulate(scene, model=older)
    assert len(with_function.impacts) >= 3
    for name in Impacts.column_names():
        np.testing.assert_array_equal(getattr(with_function.impacts, name),
                                      getattr(without.impacts, name), err_msg=name)
