"""``result.sol`` (dense output as a callable) and the SciPy-style fields of a result."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from sim_fixtures import clearance_joint, make_scene, robot_table

from jointplay.results.records import SimulationResult
from jointplay.results.solution import hermite
from jointplay.results.write import read_hdf5, write_hdf5
from jointplay.scene.definition import Scene
from jointplay.sim import simulate


def _scene(integrator: str) -> Scene:
    """A driven two-link arm with a dry, rubbing clearance joint: 15 contact phases in 50 ms,
    several inside one output interval (the case sampling aliases)."""
    robot = robot_table(2, [{"kind": "ideal"}, clearance_joint()], mu=0.1)
    return make_scene(robot, torques={"joint1": "0.5*sin(10*t)"}, integrator=integrator,
                      t_end=0.05, step=1e-5)


def _state(result: SimulationResult) -> np.ndarray:
    return np.hstack([result.q, result.u])


def _between(result: SimulationResult, fine: SimulationResult) -> np.ndarray:
    """The fine run's times that are not samples of the coarse one."""
    return ~np.isin(np.round(fine.t / 1e-9), np.round(result.t / 1e-9))


@pytest.fixture(scope="module")
def bdf_runs() -> tuple[SimulationResult, SimulationResult]:
    scene = _scene("bdf")
    return simulate(scene), simulate(scene.with_run(output_step=2.5e-4))


def test_scipy_fields(bdf_runs: tuple[SimulationResult, SimulationResult]) -> None:
    result, _ = bdf_runs
    assert result.success is True and result.status == 0
    assert "reached the end of the run" in result.message
    assert result.nfev == result.stats["rhs_evaluations"] > 0
    assert result.njev == result.stats["jacobian_evaluations"] > 0
    assert result.nlu == result.stats["lu_decompositions"] > 0


def test_bdf_sol_is_the_run_between_samples(
        bdf_runs: tuple[SimulationResult, SimulationResult]) -> None:
    """The driver never steps to outputs, so a run sampled 4x finer takes the same steps: the
    coarse run's sol must give its values between the coarse samples, to round-off."""
    result, fine = bdf_runs
    assert result.sol.method == "bdf"
    between = _between(result, fine)
    assert between.sum() == 3 * (result.n_samples - 1)
    scale = np.max(np.abs(_state(fine)), axis=0)
    err = np.abs(result.sol(fine.t[between]).T - _state(fine)[between]) / scale
    assert float(err.max()) < 1e-12
    np.testing.assert_array_equal(result.sol(result.t).T, _state(result))
    one = result.sol(float(fine.t[1]))
    assert one.shape == (_state(result).shape[1],)
    np.testing.assert_allclose(one, _state(fine)[1], rtol=1e-12, atol=1e-15)


def test_sol_refuses_times_outside_the_run(
        bdf_runs: tuple[SimulationResult, SimulationResult]) -> None:
    result, _ = bdf_runs
    with pytest.raises(ValueError, match=r"outside the run, \[0, 0.05\] s"):
        result.sol(0.06)
    with pytest.raises(ValueError, match="1-D array"):
        result.sol(np.zeros((2, 2)))


def test_sol_of_a_read_result_is_hermite_and_says_so(
        bdf_runs: tuple[SimulationResult, SimulationResult], tmp_path: Path) -> None:
    result, _ = bdf_runs
    write_hdf5(result, tmp_path / "run.h5")
    back = read_hdf5(tmp_path / "run.h5")
    assert back.sol.method == "hermite" and "read or rebuilt" in back.sol.accuracy
    np.testing.assert_allclose(back.sol(back.t).T, _state(result), rtol=0, atol=0)
    assert back.nfev == result.nfev and back.success


def test_cvodes_sol_within_the_runs_own_disagreement() -> None:
    """cvodes restarted from the samples: between samples it agrees with a run sampled
    there within a small multiple of how far two runs of the method are apart at their common
    samples (the eccentricity rates, stiff in contact, set that multiple: up to 3.8 measured; the
    Hermite interpolant of the samples is over 100 times further off)."""
    scene = _scene("cvodes")
    result, fine = simulate(scene), simulate(scene.with_run(output_step=2.5e-4))
    assert result.sol.method == "cvodes" and result.nlu > 0
    common = ~_between(result, fine)
    runs_apart = np.max(np.abs(_state(fine)[common] - _state(result)), axis=0)
    between = _between(result, fine)
    sol_apart = np.max(np.abs(result.sol(fine.t[between]).T - _state(fine)[between]), axis=0)
    assert np.all(sol_apart <= 5.0 * runs_apart + 1e-12), (sol_apart, runs_apart)
    from jointplay.results.solution import sample_solution

    hermite_apart = np.max(np.abs(sample_solution(result, "compared")(fine.t[between]).T
                                  - _state(fine)[between]), axis=0)
    assert np.all(hermite_apart > 100.0 * sol_apart), hermite_apart / sol_apart
    # The run sampled 4x finer cuts every interval into equal parts: intervals without a
    # contact change are read in one call, the rest time by time; both paths agree.
    inside = fine.t[between]
    one_by_one = np.concatenate([result.sol(inside[i:i + 2]) for i in range(0, 9, 2)], axis=1)
    scale = np.max(np.abs(_state(result)), axis=0)[:, None]
    apart = np.abs(result.sol(inside)[:, :10] - one_by_one) / scale
    assert float(apart.max()) < 1e-5, apart.max(axis=1)


def test_hermite_is_fourth_order() -> None:
    """Halving the sample spacing divides the error of a smooth interpolant by about 16."""
    errors = []
    for n in (41, 81):
        t = np.linspace(0.0, 1.0, n)
        x = np.sin(7.0 * t)[:, None]
        fn = hermite(t, x, 7.0 * np.cos(7.0 * t)[:, None])
        mid = 0.5 * (t[1:] + t[:-1])
        errors.append(float(np.max(np.abs(fn(mid)[:, 0] - np.sin(7.0 * mid)))))
    assert 14.0 < errors[0] / errors[1] < 18.0


def test_fixed_step_sol_is_hermite_with_its_accuracy_stated() -> None:
    result = simulate(_scene("rk4"))
    assert result.sol.method == "hermite"
    assert "h^4" in result.sol.accuracy and "fixed-step" in result.sol.accuracy
    assert result.nlu == 0 and result.njev == 0
    np.testing.assert_array_equal(result.sol(result.t).T, _state(result))


def test_a_pickled_result_travels_without_its_integrator(
        bdf_runs: tuple[SimulationResult, SimulationResult]) -> None:
    import pickle

    result, _ = bdf_runs
    copy = pickle.loads(pickle.dumps(result))
    assert copy.sol.method == "hermite" and result.sol.method == "bdf"
    np.testing.assert_array_equal(copy.q, result.q)
