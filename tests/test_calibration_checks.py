"""The calibration's checks around a fit: the windows' tolerances chosen against the noise,
the basin check along the directions the data see where some parameters are inseparable,
and the intervals of the parameters a valley check's rivals carry with them."""

from __future__ import annotations

import numpy as np

import jointplay as jp
from jointplay.calibration import Measured
from jointplay.calibration.basins import _carried, _line_points
from jointplay.calibration.continuation import WINDOW_MODEL_ERROR, window_looseness
from jointplay.calibration.parameters import free_parameters
from jointplay.calibration.predict import Predictor
from jointplay.calibration.uncertainty import Z95, uncertainty
from jointplay.calibration.valleys import ValleyCheck


def _paper_predictor() -> Predictor:
    scene = jp.default_scene().with_run(t_end=0.04)
    exact = jp.simulate(scene.with_run(rtol=2e-11, atol=3e-12))
    measured = Measured("noiseless", exact.t.copy(), ("tip_x", "tip_y"),
                        exact.tip_position.copy())
    model = jp.load_scene_model(scene)
    free = free_parameters(["joint2.clearance", "joint3.clearance"], scene, model, None)
    return Predictor(scene.with_run(rtol=2e-9, atol=3e-10), model, free, measured)


def test_window_tolerances_follow_the_noise() -> None:
    """A noise far above the integrator's error allows the loosest tolerances asked for; a
    noise far below it (1e-13 m: the runs 10 and 100 times looser differ from the fit's own
    by more than a chi² of WINDOW_MODEL_ERROR) leaves the fit's own; one run at the fit's
    tolerances and one per factor tried."""
    predictor = _paper_predictor()
    x = predictor.free.start
    loose, runs = window_looseness(predictor, np.array([1e-3, 1e-3]), x, 0.04, 100.0)
    assert (loose, runs) == (100.0, 2)
    tight, runs = window_looseness(predictor, np.array([1e-13, 1e-13]), x, 0.04, 100.0)
    assert (tight, runs) == (1.0, 3)
    assert WINDOW_MODEL_ERROR == 1.0
    assert window_looseness(predictor, np.array([1e-13, 1e-13]), x, 0.04, 1.0) == (1.0, 0)


def _inseparable_jacobian() -> np.ndarray:
    """Three parameters, the first two acting only through their sum (two moduli through
    the contact stiffness), the third (a friction) correlated with that sum."""
    rng = np.random.default_rng(7)
    a, b = rng.standard_normal(200), rng.standard_normal(200)
    return np.column_stack([a, a, 0.3 * a + b])


def test_basin_lines_follow_the_directions_the_data_see() -> None:
    """With an inseparable pair the covariance is infinite and its axes give no line; the
    covariance within the seen directions gives one line per seen direction (two of three),
    none along the pair's difference."""
    jac = _inseparable_jacobian()
    values = np.array([2.0, 2.0, 5.0])
    lower, upper = np.zeros(3), np.full(3, 10.0)
    spread = uncertainty(jac, values, lower, upper, ("E1", "E2", "mu"))
    assert not spread.determined[0] and not spread.determined[1] and spread.determined[2]
    assert _line_points(values, spread.covariance, lower, upper) == []
    assert spread.seen_covariance is not None
    lines = _line_points(values, spread.seen_covariance, lower, upper)
    assert len(lines) == 2
    for line in lines:
        steps = np.array(line) - values
        # no step moves the two moduli apart: the data cannot see their difference
        np.testing.assert_allclose(steps[:, 0], steps[:, 1], rtol=1e-9, atol=1e-12)


def test_valley_rivals_widen_the_intervals_they_carry() -> None:
    """A rival valley 10 standard deviations along the first parameter (the clearance the
    check's line moves) carries the correlated second (a friction the line holds) by its
    regression on the first: the second's interval is widened to hold that value give or
    take 1.96 of its standard deviations; an uncorrelated third keeps its interval."""
    rng = np.random.default_rng(3)
    c, m, u = (rng.standard_normal(400) for _ in range(3))
    basis, _ = np.linalg.qr(np.column_stack([c, m]))
    u -= basis @ (basis.T @ u)  # the third's column orthogonal to the others: uncorrelated
    jac = np.column_stack([c, 0.8 * c + 0.6 * m, u])
    values = np.array([30.0, 5.0, 7.0])
    names = ("c", "mu", "u")
    spread = uncertainty(jac, values, np.full(3, -100.0), np.full(3, 100.0), names)
    std = spread.std
    rival = values + np.array([10 * std[0], 0.0, 0.0])
    check = ValleyCheck(0.32, ((rival, 1.0),), np.array([0.1 * std[0], 0.0, 0.0]), 0,
                        None, values.copy())
    low, high = spread.low95.copy(), spread.high95.copy()
    determined = spread.determined.copy()
    warnings: list[str] = []
    _carried(check, names, spread, (low, high, determined, warnings))
    covariance = spread.covariance
    shifted = values[1] + covariance[1, 0] / covariance[0, 0] * (rival[0] - values[0])
    assert abs(shifted - values[1]) > 5 * std[1]  # outside the fit's own interval
    np.testing.assert_allclose([low[1], high[1]],
                               [min(spread.low95[1], shifted - Z95 * std[1]),
                                max(spread.high95[1], shifted + Z95 * std[1])], rtol=1e-12)
    assert low[2] == spread.low95[2] and high[2] == spread.high95[2]
    assert determined[1] and determined[2]  # still narrow beside their values
    assert len(warnings) == 1 and warnings[0].startswith("mu: its interval is widened")


def test_the_carried_interval_spans_the_whole_line() -> None:
    """Where the check's line reaches 20 standard deviations either side (its extent), the
    carried parameter's interval holds its regression value at both ends, as the moved
    parameters' intervals span the line: a truth beside the fit's valley on the side away
    from the rival stays inside."""
    rng = np.random.default_rng(3)
    c, m, u = (rng.standard_normal(400) for _ in range(3))
    jac = np.column_stack([c, 0.8 * c + 0.6 * m, u])
    values = np.array([30.0, 5.0, 7.0])
    names = ("c", "mu", "u")
    spread = uncertainty(jac, values, np.full(3, -100.0), np.full(3, 100.0), names)
    std, covariance = spread.std, spread.covariance
    reach = np.array([20 * std[0], 0.0, 0.0])
    check = ValleyCheck(0.32, ((values + reach / 2, 1.0),), np.array([0.1 * std[0], 0, 0]), 0,
                        (values - reach, values + reach), values.copy())
    low, high = spread.low95.copy(), spread.high95.copy()
    _carried(check, names, spread, (low, high, spread.determined.copy(), []))
    slope = covariance[1, 0] / covariance[0, 0]
    ends = values[1] + slope * np.array([-reach[0], reach[0]])
    np.testing.assert_allclose([low[1], high[1]],
                               [ends.min() - Z95 * std[1], ends.max() + Z95 * std[1]],
                               rtol=1e-12)


def test_a_check_too_coarse_for_the_fits_valley_leaves_what_it_moves_undetermined() -> None:
    """The fit's own valley spanning fewer than RESOLVED_POINTS of the check's line (valleys as
    narrow could lie unseen between its points; a fit a valley off was once reported
    determined so): the parameter the line moves is not determined, its interval spans the
    check's extent (a grid spacing either side), one warning says why; the correlated
    parameter the line holds is carried over that extent; the uncorrelated one keeps its
    interval and verdict. The width is counted over adjacent points at or below the level."""
    from jointplay.calibration.basins import Basins, threshold, widened
    from jointplay.calibration.valleys import RESOLVED_POINTS, _valley_points

    chi2 = np.array([9.0, 1.0, 2.0, 3.0, 9.0, 0.0, 9.0, 3.0])
    assert [_valley_points(chi2, i, chi2[i] + 3.5) for i in (1, 5)] == [3, 1]
    assert _valley_points(np.array([1.0, np.inf, 1.0]), 1, np.inf) == 0  # a run that stopped
    assert RESOLVED_POINTS == 3
    rng = np.random.default_rng(3)
    c, m, u = (rng.standard_normal(400) for _ in range(3))
    basis, _ = np.linalg.qr(np.column_stack([c, m]))
    u -= basis @ (basis.T @ u)
    jac = np.column_stack([c, 0.8 * c + 0.6 * m, u])
    values = np.array([30.0, 5.0, 7.0])
    names = ("c", "mu", "u")
    spread = uncertainty(jac, values, np.full(3, -100.0), np.full(3, 100.0), names)
    grid = np.array([2000 * spread.std[0], 0.0, 0.0])  # mu carried past MAX_RELATIVE_STD
    nothing = Basins(values, 4000.0, (), threshold(), (), 10, values[None, :])
    for coarse in (False, True):
        check = ValleyCheck(0.32, (), np.array([0.1 * spread.std[0], 0, 0]), 162,
                            (values - grid, values + grid), values.copy(), coarse)
        low, high, determined, warnings = widened(spread, nothing, names, check)
        if not coarse:  # no rival: nothing changes
            assert determined.all() and warnings == []
            continue
        assert list(determined) == [False, False, True]
        np.testing.assert_allclose([low[0], high[0]], [values[0] - grid[0], values[0] + grid[0]],
                                   rtol=1e-15)
        slope = spread.covariance[1, 0] / spread.covariance[0, 0]
        np.testing.assert_allclose(high[1] - low[1], 2 * abs(slope) * grid[0]
                                   + 2 * Z95 * spread.std[1], rtol=1e-9)
        np.testing.assert_allclose([low[2], high[2]], [spread.low95[2], spread.high95[2]],
                                   rtol=1e-15)  # the carried shift of an uncorrelated one: 0
        assert warnings[0].startswith("c is not determined by the search: over the first "
                                      "0.32 s the fit's own valley spans fewer than 3 "
                                      "points")
        assert "a grid spacing either side" in warnings[0] and len(warnings) == 2


def test_a_distrusted_search_reports_nothing_determined() -> None:
    """Residuals that are the noise, but a reason to distrust the search's valley (a held
    parameter that ended far from its held value): nothing is determined, each interval
    spans the searched box, one warning gives the reason and what to do; the fit still
    explains the data. Without the reason the verdicts are the covariance's."""
    from jointplay.calibration.api import judged_fit
    from jointplay.calibration.fit import Optimum
    from jointplay.calibration.parameters import FreeParameters

    rng = np.random.default_rng(5)
    t = np.arange(400) * 1e-3
    noise = 1e-6 * rng.standard_normal((t.size, 2))
    measured = Measured("synthetic", t, ("tip_x", "tip_y"), noise)
    fitted = np.zeros_like(noise)
    sigma = np.array([1e-6, 1e-6])
    free = FreeParameters(("joint2.clearance", "friction.mu"), np.array([3e-5, 0.05]),
                          np.array([1e-9, 0.0]), np.array([1e-2, 1.0]))
    jac = rng.standard_normal((2 * t.size, 2)) * np.array([1e9, 1e4])
    values = np.array([3.1e-5, 0.048])
    spread = uncertainty(jac, values, free.lower, free.upper, free.names)
    optimum = Optimum(values, sigma, (noise / sigma).ravel(), jac, ())
    _, misfit, trusted, warnings = judged_fit(fitted, measured, free, optimum, spread, None,
                                              0.5)
    assert misfit is None and trusted.determined.all() and not warnings
    reason = "friction.mu, held through the first windows, ended 40% from there"
    _, misfit, distrusted, warnings = judged_fit(fitted, measured, free, optimum, spread,
                                                 None, 0.5, reason)
    assert misfit is None and not distrusted.determined.any()
    np.testing.assert_allclose(distrusted.low95, [1.5e-5, 0.025])
    np.testing.assert_allclose(distrusted.high95, [4.5e-5, 0.075])
    assert len(warnings) == 1 and warnings[0].startswith(f"nothing is determined: {reason}")
    assert "--start" in warnings[0]
