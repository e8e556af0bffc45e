"""Mechanisms: the slider-crank against what no one here wrote.

- the ideal mechanism (``--compare-ideal``) against the closed form s(theta) = r cos theta +
  sqrt(l^2 - r^2 sin^2 theta), its derivatives, and the driving torque of Lagrange's equation
  for the one coordinate theta, tau = J'(theta) omega^2 / 2 + V'(theta) (J, V from the closed
  form, J' by a central difference);
- the clearance model converging to that closed form as the clearance goes to 0 with stiff
  contact, at first order (the journal can sit anywhere in its clearance circle);
- the energy balance with restitution 1 and no friction, the driver's work included.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from jointplay.mechanism.model import model_for
from jointplay.mechanism.reading import load_mechanism_scene
from jointplay.mechanism.simulate import simulate_mechanism

SCENE = "scenes/slider_crank.toml"
R, L = 0.05, 0.12  # crank and rod lengths of the scene (m)
OMEGA = 2 * np.pi * 5000 / 60  # rad/s
M_CRANK, I_CRANK, M_ROD, I_ROD, M_SLIDER = 0.30, 1.0e-4, 0.21, 2.5e-4, 0.14
G = 9.81


@pytest.fixture(scope="module")
def scene() -> Any:
    return load_mechanism_scene(SCENE)


@pytest.fixture(scope="module")
def model(scene: Any) -> Any:
    return model_for(scene.mechanism)


def slider(theta: np.ndarray) -> np.ndarray:
    return R * np.cos(theta) + np.sqrt(L**2 - R**2 * np.sin(theta) ** 2)


def _inertia_and_gravity(theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """J(theta) (kg m^2: T = J theta'^2 / 2) and V'(theta) (N m) of the ideal slider-crank,
    from the closed form; the rod's angle psi from sin psi = -r sin theta / l."""
    psi = np.arcsin(-R * np.sin(theta) / L)
    dpsi = -R * np.cos(theta) / (L * np.cos(psi))
    d_crank = 0.5 * R * np.array([-np.sin(theta), np.cos(theta)])
    d_rod = 2 * d_crank + 0.5 * L * np.array([-np.sin(psi), np.cos(psi)]) * dpsi
    root = np.sqrt(L**2 - R**2 * np.sin(theta) ** 2)
    d_slider = -R * np.sin(theta) - R**2 * np.sin(theta) * np.cos(theta) / root
    inertia = (M_CRANK * (d_crank**2).sum(0) + I_CRANK + M_ROD * (d_rod**2).sum(0)
               + I_ROD * dpsi**2 + M_SLIDER * d_slider**2)
    return inertia, G * (M_CRANK * d_crank[1] + M_ROD * d_rod[1])


def test_ideal_mechanism_is_the_closed_form(scene: Any, model: Any) -> None:
    result = simulate_mechanism(scene.with_run(t_end=0.012, output_step=1e-4), model=model,
                                compare_ideal=True)
    ideal = result.ideal
    assert ideal is not None
    theta = OMEGA * result.t
    k = result.coordinates.index("guide.position")
    n = len(result.coordinates)
    s = slider(theta)
    root = np.sqrt(L**2 - R**2 * np.sin(theta) ** 2)
    ds = -R * np.sin(theta) - R**2 * np.sin(theta) * np.cos(theta) / root
    dds = (-R * np.cos(theta) - R**2 * np.cos(2 * theta) / root
           - R**4 * np.sin(theta) ** 2 * np.cos(theta) ** 2 / root**3)
    np.testing.assert_allclose(ideal["x"][:, k], s, rtol=0, atol=1e-14)
    np.testing.assert_allclose(ideal["x"][:, n + k], ds * OMEGA, rtol=0, atol=1e-11)
    np.testing.assert_allclose(ideal["acceleration"][:, k], dds * OMEGA**2, rtol=0,
                               atol=1e-7)
    # Lagrange: tau = J'(theta) omega^2 / 2 + V'(theta) at constant speed.
    h = 1e-4
    j_plus, _ = _inertia_and_gravity(theta + h)
    j_minus, _ = _inertia_and_gravity(theta - h)
    torque = 0.5 * (j_plus - j_minus) / (2 * h) * OMEGA**2 + _inertia_and_gravity(theta)[1]
    scale = np.max(np.abs(torque))
    assert scale > 100.0  # N m: the inertia torque of 5000 rpm dominates
    np.testing.assert_allclose(ideal["driving_torque"], torque, rtol=0, atol=1e-6 * scale)


def test_clearance_to_zero_converges_to_the_closed_form_at_first_order(scene: Any, model: Any
                                                                     ) -> None:
    """Contact stiffened as the clearance shrinks (E = 2e13 Pa at c = 0.1 mm, times 1e-4 / c:
    Hertz's penetration ~ E^(-2/3) c^(1/3) then stays a fixed fraction of c, about 3 %; at a
    fixed E it would fall only as c^(1/3) and dominate), half a revolution at tight
    tolerance: the slider's largest distance from s(theta) is the clearance and a little more
    (1.0 to 1.2 c), and falls with c at order 1."""
    errors = []
    clearances = (1e-4, 1e-5, 1e-6)
    for c in clearances:
        stiffness = 2e13 * 1e-4 / c
        mechanism = scene.mechanism.with_values({
            "slider_pin.journal_radius": 10.5e-3 - c, "slider_pin.bearing_E": stiffness,
            "slider_pin.journal_E": stiffness})
        run = scene.with_mechanism(mechanism).with_run(t_end=0.006, rtol=1e-8, atol=1e-8)
        result = simulate_mechanism(run, model=model)
        error = np.max(np.abs(result.coordinate("guide.position")
                              - slider(OMEGA * result.t)))
        assert 1.0 * c <= error <= 1.2 * c
        errors.append(error)
    orders = np.log10(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 0.95) & (orders < 1.05)), (errors, orders)


def test_energy_balance_closes_with_restitution_one(scene: Any, model: Any) -> None:
    """ce = 1, no friction: kinetic + potential + contact energy - the driver's work stays
    constant through every impact, to the integration error, which falls with the
    tolerance (measured: 1.9e-4 of the driver's largest work at rtol = atol = 1e-6, 1.8e-6 at
    1e-9, 1e-7 at 1e-10)."""
    mechanism = scene.mechanism.with_values({"contact.restitution": 1.0})
    residuals = []
    for tol in (1e-6, 1e-9):
        result = simulate_mechanism(scene.with_mechanism(mechanism).with_run(rtol=tol, atol=tol),
                                    model=model)
        assert len(result.impacts) > 10
        assert np.max(np.abs(result.dissipated)) < 1e-9
        work = np.max(np.abs(result.drive_work))
        assert work > 10.0  # J: the driver works
        residuals.append(np.max(np.abs(result.energy_residual)) / work)
    assert residuals[1] < 5e-6
    assert residuals[1] < residuals[0] / 30


def test_the_run_locates_its_impacts(scene: Any, model: Any) -> None:
    result = simulate_mechanism(scene, model=model)
    impacts = result.impacts
    assert len(impacts) > 5
    # Each located peak is at least every sampled force of its phase, and within the phase.
    for i in range(len(impacts)):
        start = impacts.time[i]
        end = impacts.separation_time[i] if np.isfinite(impacts.separation_time[i]) \
            else result.t[-1]
        assert start <= impacts.peak_force_time[i] <= end
        inside = (result.t >= start) & (result.t <= end)
        if inside.any():
            assert impacts.peak_force[i] >= np.max(result.normal_force[inside, 0]) * (1 - 1e-9)
    # The eccentricity at each onset is on the clearance circle.
    radius = np.hypot(impacts.eccentricity[:, 0], impacts.eccentricity[:, 1])
    np.testing.assert_allclose(radius, result.clearance[0], rtol=1e-6)
