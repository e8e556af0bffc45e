"""The slider-crank with a clearance joint checked against what jointplay did not write.

The Exudyn model (tests/exudyn_slider_crank.py: Exudyn's kinematic tree, mass matrix and DOPRI5,
the contact force written there from the laws' definitions) is checked first on its own:

1. its accelerations and driving torque between steps (from the equations of motion written
   there) equal Exudyn's at the steps;
2. as the clearance goes to 0 (Hertz contact of steel, so stiffer as it closes) the slider's
   motion approaches the closed form s(theta) = r cos theta + sqrt(l^2 - r^2 sin^2 theta);
3. with restitution 1 and no friction, energy balances: the change of the mechanism's
   kinetic, weight and contact energy equals the driver's work; with restitution 0.9 and
   friction the mechanism only loses energy.

Then jointplay's slider-crank (scenes/slider_crank.toml, the compiled BDF) is compared with it
(the ``jointplay`` tests below).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from exudyn_slider_crank import (
    SliderCrank,
    contact,
    driver_work,
    ideal_slider,
    mechanical_energy,
    rod_and_slider_accelerations,
    simulate,
)

REVOLUTION = 2.0 * math.pi / SliderCrank().crank_speed  # 0.012 s at 5000 rpm


def ideal_slider_velocity(theta: np.ndarray, m: SliderCrank) -> np.ndarray:
    r, rl, w = m.crank_length, m.rod_length, m.crank_speed
    s = np.sin(theta)
    return -r * w * s - r * r * w * s * np.cos(theta) / np.sqrt(rl * rl - (r * s) ** 2)


@pytest.fixture(scope="module")
def short_run():
    """The benchmark's first 3 ms (four impacts and a contact phase)."""
    return simulate(SliderCrank(mu=0.01), 0.003, rtol=1e-10, atol=1e-12)


def test_equations_between_steps_match_exudyn(short_run) -> None:
    run = short_run
    m = run.model
    assert len(run.impacts) >= 3
    torque_scale = 0.0
    worst = {"rod": 0.0, "slider": 0.0, "torque": 0.0}
    for k in range(1, run.t.size):
        cont = contact(m, run.q[k], run.v[k], None if math.isnan(run.approach[k - 1])
                       else run.approach[k - 1])
        rod_tt, slider_tt = rod_and_slider_accelerations(m, run.q[k], run.v[k], cont)
        # Exudyn integrates the relative angle phi; psi'' = theta'' + phi'' with theta'' ~ 1e-6
        worst["rod"] = max(worst["rod"], abs(rod_tt - run.a[k, 0] - run.a[k, 1]))
        worst["slider"] = max(worst["slider"], abs(slider_tt - run.a[k, 2]))
        exudyn_torque = -m.flywheel_inertia * run.a[k, 0]
        torque = run.at(np.array([run.t[k]]))["driving_torque"][0]
        worst["torque"] = max(worst["torque"], abs(torque - exudyn_torque))
        torque_scale = max(torque_scale, abs(exudyn_torque))
    rod_scale = np.max(np.abs(run.a[:, 1]))
    slider_scale = np.max(np.abs(run.a[:, 2]))
    # Round-off only (the flywheel's 1e8 kg m^2 against the rod's 1e-3 costs ~11 digits of
    # the crank's acceleration): measured ~1e-12 relative for the rod and slider, ~5e-9 for
    # the torque.
    assert worst["rod"] <= 1e-9 * rod_scale, worst
    assert worst["slider"] <= 1e-9 * slider_scale, worst
    assert worst["torque"] <= 1e-6 * torque_scale, worst
    # The driver holds the crank's speed: the flywheel's angle departs by < 1e-9 rad.
    assert np.max(np.abs(run.q[:, 0] - m.crank_speed * run.t)) < 1e-9


def test_located_peaks_bound_the_sampled_forces(short_run) -> None:
    run = short_run
    for imp in run.impacts:
        assert imp.onset < imp.peak_time < imp.separation
        inside = (run.t >= imp.onset) & (run.t <= imp.separation)
        sampled = run.at(run.t[inside])["normal_force"]
        assert imp.peak_force >= np.max(sampled) * (1.0 - 1e-12)
        # the located peak is a peak: the force there equals the located value
        at_peak = run.at(np.array([imp.peak_time]))["normal_force"][0]
        assert abs(at_peak - imp.peak_force) <= 1e-6 * imp.peak_force


@pytest.mark.slow
def test_clearance_to_zero_approaches_the_closed_form() -> None:
    """Half a revolution at radial clearances 0.1 mm, 10 um and 1 um (~25 s)."""
    half = 0.5 * REVOLUTION
    grid = np.linspace(0.0, half, 601)
    errors = []
    for c in (1e-4, 1e-5, 1e-6):
        m = SliderCrank(bearing_radius=10.0e-3 + c)
        run = simulate(m, half, rtol=1e-9, atol=1e-12)
        out = run.at(grid)
        theta = m.crank_speed * grid
        position = np.max(np.abs(out["slider_position"]
                                 - ideal_slider(theta, m.crank_length, m.rod_length)))
        velocity = np.max(np.abs(out["slider_velocity"] - ideal_slider_velocity(theta, m)))
        deepest = max(max(contact(m, q, v, None).penetration, 0.0)
                      for q, v in zip(run.q, run.v, strict=True))
        # Geometry alone bounds the position error by (1 + r / sqrt(l^2 - r^2)) |e| with
        # |e| <= c + deepest penetration (the journal stays within that of the bearing).
        r, rl = m.crank_length, m.rod_length
        assert position <= (1.0 + r / math.sqrt(rl * rl - r * r)) * (c + deepest)
        errors.append((position, velocity))
    # Each tenfold smaller clearance: the position error falls by over 3x and the velocity
    # error by over 2x (measured 6.8x and 5.1x; 3.1x and 3.1x: Hertz contact stiffens only as
    # c^-1/2, so the penetration shrinks slower than the clearance).
    for (p0, v0), (p1, v1) in itertools.pairwise(errors):
        assert p1 < p0 / 3.0 and v1 < v0 / 2.0, errors


@pytest.mark.slow
def test_energy_balance_with_restitution_one() -> None:
    """One revolution, ce = 1, mu = 0: no energy is lost, the driver's work is all (~25 s)."""
    m = SliderCrank(restitution=1.0)
    run = simulate(m, REVOLUTION, rtol=1e-10, atol=1e-12)
    assert len(run.impacts) >= 10
    energy = mechanical_energy(run, run.t)
    work = driver_work(run)
    residual = energy - energy[0] - work
    # The driver's work swings by ~120 J within the revolution; the balance holds to ~1e-7 of
    # that (measured 1.2e-5 J: Simpson's rule across the steps where a contact ends).
    assert np.max(np.abs(residual)) <= 1e-6 * np.max(np.abs(work))


@pytest.mark.slow
def test_restitution_and_friction_only_take_energy() -> None:
    m = SliderCrank(restitution=0.9, mu=0.01)
    run = simulate(m, 0.004, rtol=1e-10, atol=1e-12)
    energy = mechanical_energy(run, run.t)
    loss = -(energy - energy[0] - driver_work(run))
    scale = np.max(np.abs(driver_work(run)))
    # The loss never decreases (beyond quadrature error, 1e-7 of the work) and is real.
    assert np.min(np.diff(loss)) >= -1e-7 * scale
    assert loss[-1] > 1e-3 * scale
