"""The four-bar scene (scenes/four_bar.toml) against what no one here wrote.

- it loads, simulates from the command line with ``--compare-ideal --plot``, and its ideal
  mechanism's rocker angle is Freudenstein's closed-form position analysis;
- as the clearance of its three clearance pins goes to 0 with stiff contact, the rocker's
  angle converges to that closed form at first order;
- with restitution 1 and no friction (mu = 0) the energy balance closes, the driver's work
  included, to the integration error.

The closed form: crank a, coupler b, rocker c, ground d, crank angle theta, rocker angle phi
(both from the ground line, the rocker's from its own pivot). Freudenstein's equation
K1 cos phi - K2 cos theta + K3 = cos(theta - phi), with K1 = d / a, K2 = d / c and
K3 = (a^2 - b^2 + c^2 + d^2) / (2 a c), is a quadratic in tan(phi / 2):
A tan^2 + B tan + C = 0, A = cos theta - K1 - K2 cos theta + K3, B = -2 sin theta,
C = K1 - (K2 + 1) cos theta + K3; one root is the rocker up, the other down.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from jointplay.cli import main
from jointplay.mechanism.model import model_for
from jointplay.mechanism.reading import load_mechanism_scene
from jointplay.mechanism.simulate import simulate_mechanism

SCENE = "scenes/four_bar.toml"
CRANK, COUPLER, ROCKER, GROUND = 1.0, 4.0, 2.5, 3.0  # m, as in the scene
BEARING = 0.06  # m, every clearance pin's bearing radius in the scene
PINS = ("crank_pin", "coupler_pin", "rocker_pivot")


def crank_angle(t: np.ndarray) -> np.ndarray:
    return 6.0 * np.sin(0.75 * np.pi * t)


def rocker_angle(theta: np.ndarray, up: bool = True) -> np.ndarray:
    """Freudenstein's rocker angle for crank angle theta."""
    k1, k2 = GROUND / CRANK, GROUND / ROCKER
    k3 = (CRANK**2 - COUPLER**2 + ROCKER**2 + GROUND**2) / (2 * CRANK * ROCKER)
    a = np.cos(theta) - k1 - k2 * np.cos(theta) + k3
    b = -2 * np.sin(theta)
    c = k1 - (k2 + 1) * np.cos(theta) + k3
    root = np.sqrt(b * b - 4 * a * c)
    return 2 * np.arctan((-b - root if up else -b + root) / (2 * a))


def angle_gap(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """|a - b| on the circle (rad)."""
    return np.abs(np.angle(np.exp(1j * (a - b))))


@pytest.fixture(scope="module")
def scene() -> Any:
    return load_mechanism_scene(SCENE)


@pytest.fixture(scope="module")
def model(scene: Any) -> Any:
    return model_for(scene.mechanism)


def test_the_closed_form_is_the_vector_loop() -> None:
    """The test's own closed form closes the loop: the coupler's length between the crank
    pin and the rocker's tip is b at every crank angle, on both assemblies."""
    theta = np.linspace(-np.pi, np.pi, 721)
    for up in (True, False):
        phi = rocker_angle(theta, up)
        pin = CRANK * np.stack([np.cos(theta), np.sin(theta)])
        tip = np.array([[GROUND], [0.0]]) + ROCKER * np.stack([np.cos(phi), np.sin(phi)])
        np.testing.assert_allclose(np.hypot(*(tip - pin)), COUPLER, rtol=0, atol=1e-12)
        assert np.all(np.sin(phi[::60]) > 0) == up  # the rocker up stays up


def test_loads_simulates_and_its_ideal_mechanism_is_freudensteins(scene: Any, model: Any
                                                                 ) -> None:
    assert [b.name for b in scene.mechanism.bodies] == ["crank", "coupler", "rocker"]
    result = simulate_mechanism(scene.with_run(t_end=0.2), model=model, compare_ideal=True)
    assert np.all(np.isfinite(result.x))
    assert len(result.impacts) >= 1  # the journals leave their centres and strike
    ideal = result.ideal
    assert ideal is not None
    k = result.coordinates.index("rocker.angle")
    theta = crank_angle(result.t)
    assert np.max(angle_gap(ideal["x"][:, k], rocker_angle(theta))) < 1e-12
    # with 5 mm of play in three pins the rocker departs from it by 2.86 mrad per mm of
    # clearance, as in the convergence test below
    gap = angle_gap(result.coordinate("rocker.angle"), rocker_angle(theta))
    assert 2.0 * 5e-3 < np.max(gap) < 4.0 * 5e-3


def test_clearance_to_zero_converges_to_freudenstein_at_first_order(scene: Any, model: Any
                                                                   ) -> None:
    """The three pins' clearance c from 5 mm to 0.05 mm, the contact stiffened with it
    (E = 207 GPa x 5 mm / c, so that Hertz's penetration stays a fixed fraction of c), a
    quarter of a second (the crank turns 3.3 rad) at tight tolerance: the rocker's largest
    distance from the closed form falls with c at order 1 (measured: 2.86 c, 2.87 c, 2.91 c
    in radians per metre of clearance)."""
    errors = []
    clearances = (5e-3, 5e-4, 5e-5)
    for c in clearances:
        stiffness = 207e9 * 5e-3 / c
        values: dict[str, float] = {}
        for pin in PINS:
            values |= {f"{pin}.journal_radius": BEARING - c, f"{pin}.bearing_E": stiffness,
                       f"{pin}.journal_E": stiffness}
        run = scene.with_mechanism(scene.mechanism.with_values(values)).with_run(
            t_end=0.25, rtol=1e-8, atol=1e-8)
        result = simulate_mechanism(run, model=model)
        error = np.max(angle_gap(result.coordinate("rocker.angle"),
                                 rocker_angle(crank_angle(result.t))))
        assert 2.0 * c < error < 4.0 * c
        errors.append(error)
    orders = np.log10(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 0.97) & (orders < 1.03)), (errors, orders)


def test_energy_balance_closes_with_restitution_one_and_no_friction(scene: Any, model: Any
                                                                   ) -> None:
    """ce = 1 (Flores' damping factor 8 (1 - ce) / (5 ce) is then 0) and mu = 0: kinetic +
    potential + contact energy - the driver's work stays constant through every impact, to
    the integration error, which falls as the tolerance is tightened (measured over 0.5 s,
    some 600 impacts: 8.2e-4 of the driver's largest work at rtol = atol = 1e-6, 5.7e-7 at
    1e-9)."""
    mechanism = scene.mechanism.with_values({"contact.restitution": 1.0, "friction.mu": 0.0})
    residuals = []
    for tol in (1e-6, 1e-9):
        run = scene.with_mechanism(mechanism).with_run(t_end=0.5, rtol=tol, atol=tol)
        result = simulate_mechanism(run, model=model)
        assert len(result.impacts) >= 3
        assert np.max(np.abs(result.dissipated)) < 1e-9
        work = np.max(np.abs(result.drive_work))
        assert work > 10.0  # J: the driver works
        residuals.append(np.max(np.abs(result.energy_residual)) / work)
    assert residuals[1] < 1e-5, residuals
    assert residuals[1] < residuals[0] / 30, residuals


@pytest.mark.slow
def test_simulate_compare_ideal_plot_from_the_command_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    figures = tmp_path / "figures"
    assert main(["simulate", SCENE, "--compare-ideal", "--plot", str(figures)]) == 0
    out = capsys.readouterr().out
    assert "from the ideal mechanism" in out and "accuracy" in out
    for pin in PINS:
        assert f"{pin}: " in out
    pngs = sorted(p.name for p in figures.iterdir())
    assert "journal_orbit.png" in pngs and "driving_torque.png" in pngs
    assert all((figures / p).stat().st_size > 1000 for p in pngs)
