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

from pathlib import Path
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


FOUR_BAR = """
name = "four_bar"
[initial]
rocker_pivot.angle = 1.5
crank_pin.angle = 1.0
[mechanism.driver]
joint = "crank_pivot"
speed = 20.0
start = 0.3
[[mechanism.bodies]]
name = "crank"
mass = 0.1
inertia = 1e-4
com = [0.025, 0.0]
[[mechanism.bodies]]
name = "coupler"
mass = 0.2
inertia = 5e-4
com = [0.06, 0.01]
[[mechanism.bodies]]
name = "rocker"
mass = 0.15
inertia = 3e-4
com = [0.05, 0.0]
[[mechanism.joints]]
name = "crank_pivot"
parent = "ground"
child = "crank"
[[mechanism.joints]]
name = "crank_pin"
parent = "crank"
child = "coupler"
at_parent = [0.05, 0.0]
[[mechanism.joints]]
name = "rocker_pivot"
parent = "ground"
child = "rocker"
at_parent = [0.10, 0.0]
[[mechanism.joints]]
name = "rocker_pin"
kind = "clearance"
parent = "rocker"
child = "coupler"
at_parent = [0.10, 0.0]
at_child = [0.12, 0.0]
bearing_radius = 10.5e-3
journal_radius = 10.0e-3
[run]
t_end = 0.2
output_step = 1e-3
"""


def test_ideal_four_bar_is_the_circles_intersection_and_its_energy_balance(tmp_path: Any
                                                                        ) -> None:
    """A four-bar (a second loop shape, a rocker instead of a slider, the centre of mass off
    the coupler's line): the ideal mechanism's rocker pin at the intersection of the circles
    about the crank pin (radius 0.12 m) and the rocker pivot (0.10 m), on the assembly the
    [initial] table chose; its driving torque times the crank speed equal to the rate of
    change of its energy (central differences of the closed-form energy)."""
    path = tmp_path / "four_bar.toml"
    path.write_text(FOUR_BAR, encoding="utf-8")
    scene = load_mechanism_scene(path)
    result = simulate_mechanism(scene, compare_ideal=True)
    ideal = result.ideal
    assert ideal is not None
    omega, start = 20.0, 0.3

    def pose(t: np.ndarray) -> tuple[np.ndarray, ...]:
        theta = start + omega * t
        pin = 0.05 * np.stack([np.cos(theta), np.sin(theta)])
        pivot = np.array([[0.10], [0.0]])
        d = pivot - pin
        dist = np.hypot(*d)
        along = (0.12**2 - 0.10**2 + dist**2) / (2 * dist)
        across = np.sqrt(0.12**2 - along**2)
        unit = d / dist
        normal = np.stack([-unit[1], unit[0]])
        tip = pin + along * unit + across * normal  # the assembly with the rocker up
        return theta, pin, tip, pivot

    _, _, tip, pivot = pose(result.t)
    rocker = np.arctan2(tip[1] - pivot[1], tip[0] - pivot[0])
    k = result.coordinates.index("rocker_pivot.angle")
    np.testing.assert_allclose(np.unwrap(ideal["x"][:, k]), np.unwrap(rocker), rtol=0,
                               atol=1e-12)

    def energy(t: np.ndarray) -> np.ndarray:
        h = 1e-7
        total = np.zeros(t.shape)
        for part in ("crank", "coupler", "rocker"):
            coms, angles = [], []
            for dt in (-h, 0.0, h):
                theta, pin, tip, pivot = pose(t + dt)
                if part == "crank":
                    angle, com = theta, 0.5 * pin
                elif part == "coupler":
                    angle = np.arctan2(tip[1] - pin[1], tip[0] - pin[0])
                    com = pin + 0.06 * np.stack([np.cos(angle), np.sin(angle)]) \
                        + 0.01 * np.stack([-np.sin(angle), np.cos(angle)])
                else:
                    angle = np.arctan2(tip[1] - pivot[1], tip[0] - pivot[0])
                    com = pivot + 0.05 * np.stack([np.cos(angle), np.sin(angle)])
                coms.append(com)
                angles.append(np.unwrap(angle))
            mass, inertia = {"crank": (0.1, 1e-4), "coupler": (0.2, 5e-4),
                             "rocker": (0.15, 3e-4)}[part]
            v = (coms[2] - coms[0]) / (2 * h)
            w = (angles[2] - angles[0]) / (2 * h)
            total += 0.5 * mass * (v**2).sum(0) + 0.5 * inertia * w**2 + mass * G * coms[1][1]
        return total

    h = 1e-5
    power = (energy(result.t + h) - energy(result.t - h)) / (2 * h)
    scale = np.max(np.abs(power))
    np.testing.assert_allclose(ideal["driving_torque"] * omega, power, rtol=0,
                               atol=1e-4 * scale)


PENDULUM_ARM = """
name = "pendulum"
[initial]
q1 = 1.0
[run]
t_end = 0.3
output_step = 1e-3
rtol = 1e-10
atol = 1e-10
[robot]
name = "pendulum"
[robot.friction]
mu = 0.1
[[robot.links]]
length = 0.3
mass = 1.0
inertia = 0.0075
com = 0.15
[[robot.joints]]
kind = "clearance"
bearing_radius = 10e-3
journal_radius = 9.5e-3
"""

PENDULUM_MECHANISM = """
name = "pendulum"
[initial]
link.angle = 1.0
[mechanism.friction]
mu = 0.1
[[mechanism.bodies]]
name = "link"
mass = 1.0
inertia = 0.0075
com = [0.15, 0.0]
[[mechanism.joints]]
name = "pin"
kind = "clearance"
parent = "ground"
child = "link"
bearing_radius = 10e-3
journal_radius = 9.5e-3
[run]
t_end = 0.3
output_step = 1e-3
rtol = 1e-10
atol = 1e-10
"""


def test_a_body_held_by_its_clearance_joint_is_the_serial_arms_link(tmp_path: Any) -> None:
    """A 0.3 m link hanging by a clearance joint from the ground, with gravity and friction:
    as a mechanism, a floating body held by a cut clearance joint (this derivation); as a
    robot, the serial arm's one-link model (Kane's method in sympy, derived apart). Same
    impacts (onsets measured within 2.7e-8 s), same orbit (1.1e-9 m apart) over 38 impacts
    in 0.3 s."""
    import jointplay

    (tmp_path / "arm.toml").write_text(PENDULUM_ARM, encoding="utf-8")
    (tmp_path / "mechanism.toml").write_text(PENDULUM_MECHANISM, encoding="utf-8")
    arm = jointplay.simulate(jointplay.load_scene(tmp_path / "arm.toml"))
    mechanism = simulate_mechanism(load_mechanism_scene(tmp_path / "mechanism.toml"))
    assert mechanism.coordinates == ["link.x", "link.y", "link.angle", "t"]
    assert len(arm.impacts) == len(mechanism.impacts) > 20
    np.testing.assert_allclose(mechanism.impacts.time, arm.impacts.time, rtol=0, atol=1e-7)
    np.testing.assert_allclose(mechanism.impacts.peak_force, arm.impacts.peak_force,
                               rtol=1e-5)
    np.testing.assert_allclose(mechanism.eccentricity[:, 0, :], arm.eccentricity[:, 0, :],
                               rtol=0, atol=1e-8)
    np.testing.assert_allclose(mechanism.coordinate("link.angle"), arm.q[:, 0], rtol=0,
                               atol=1e-7)


LOADS = """[mechanism.torques]
crank_pin = "0.5*sin(2*pi*500*t)"

[[mechanism.forces]]
name = "gas"
body = "slider"
x = "-200*cos(2*pi*250*t)"
y = "30"

[mechanism.gravity]"""


def test_applied_loads_in_the_ideal_mechanism_and_the_energy_balance(tmp_path: Any) -> None:
    """A force on the slider, F_x = -200 cos(2 pi 250 t) N (and 30 N across the guide, which
    the guide takes), and a torque tau_pin across the crank pin (on the rod, its reaction on
    the crank): the ideal driving torque is Lagrange's less the loads' generalised force on
    theta, F_x s'(theta) + tau_pin (psi'(theta) - 1); with restitution 1 the energy balance,
    the loads' work included, closes as without loads."""
    text = Path(SCENE).read_text(encoding="utf-8").replace("[mechanism.gravity]", LOADS, 1)
    path = tmp_path / "loads.toml"
    path.write_text(text, encoding="utf-8")
    scene = load_mechanism_scene(path)
    result = simulate_mechanism(scene.with_run(output_step=1e-4), compare_ideal=True)
    assert result.ideal is not None
    theta = OMEGA * result.t
    force = -200 * np.cos(2 * np.pi * 250 * result.t)
    pin = 0.5 * np.sin(2 * np.pi * 500 * result.t)
    root = np.sqrt(L**2 - R**2 * np.sin(theta) ** 2)
    ds = -R * np.sin(theta) - R**2 * np.sin(theta) * np.cos(theta) / root
    psi = np.arcsin(-R * np.sin(theta) / L)
    dpsi = -R * np.cos(theta) / (L * np.cos(psi))
    h = 1e-4
    j_plus, _ = _inertia_and_gravity(theta + h)
    j_minus, _ = _inertia_and_gravity(theta - h)
    torque = (0.5 * (j_plus - j_minus) / (2 * h) * OMEGA**2 + _inertia_and_gravity(theta)[1]
              - force * ds - pin * (dpsi - 1))
    scale = np.max(np.abs(torque))
    np.testing.assert_allclose(result.ideal["driving_torque"], torque, rtol=0,
                               atol=1e-6 * scale)
    elastic = scene.with_mechanism(scene.mechanism.with_values({"contact.restitution": 1.0}))
    run = simulate_mechanism(elastic)
    work = np.max(np.abs(run.drive_work))
    assert np.max(np.abs(run.energy_residual)) < 5e-6 * work


def test_friction_on_a_turning_bearing_balances_its_dissipation(tmp_path: Any) -> None:
    """The four-bar's clearance joint has its bearing on the rocker, which turns: with
    restitution 1 and friction (mu 0.2), all that contact takes out is friction's, Ft v_t
    with v_t from both bodies' rates; the work of the friction force and of its moments on
    journal and bearing must equal it, so the energy balance closes (measured: 2.1e-7 J of
    4.2e-3 J dissipated at rtol = atol = 1e-9)."""
    path = tmp_path / "four_bar.toml"
    path.write_text(FOUR_BAR.replace("[mechanism.driver]", "[mechanism.friction]\nmu = 0.2\n"
                                     "\n[mechanism.driver]", 1), encoding="utf-8")
    scene = load_mechanism_scene(path)
    mechanism = scene.mechanism.with_values({"contact.restitution": 1.0})
    result = simulate_mechanism(scene.with_mechanism(mechanism).with_run(rtol=1e-9, atol=1e-9))
    friction = float(result.impacts.friction_energy.sum())
    assert friction > 1e-3  # J
    assert result.dissipated[-1] == pytest.approx(friction, rel=1e-6)
    assert np.max(np.abs(result.energy_residual)) < 1e-4 * friction


def test_the_ideal_mechanism_at_once_equals_sample_by_sample(scene: Any, model: Any) -> None:
    """The ideal motion solved for every sample at once from the clearance run's states
    equals the same solved sample by sample, each from the last (to round-off)."""
    from jointplay.mechanism.simulate import ideal_motion

    result = simulate_mechanism(scene, model=model, compare_ideal=True)
    assert result.ideal is not None
    one_by_one = ideal_motion(model, model.parameter_vector(scene.mechanism), result.t)
    for key in ("x", "acceleration", "driving_torque"):
        scale = np.max(np.abs(one_by_one[key]))
        np.testing.assert_allclose(result.ideal[key], one_by_one[key], rtol=0,
                                   atol=1e-12 * scale)


LOCKED = """
name = "locked_pair"
[initial]
a.angle = 1.0
[mechanism.friction]
mu = 0.1
[[mechanism.bodies]]
name = "a"
mass = 1.0
inertia = 0.0075
com = [0.15, 0.0]
[[mechanism.bodies]]
name = "b"
mass = 0.5
inertia = 0.002
com = [0.05, 0.0]
[[mechanism.joints]]
name = "pin"
kind = "clearance"
parent = "ground"
child = "a"
bearing_radius = 10e-3
journal_radius = 9.5e-3
[[mechanism.joints]]
name = "weld"
kind = "locked"
parent = "a"
child = "b"
at_parent = [0.3, 0.0]
angle = 1.5707963267948966
[run]
t_end = 0.2
output_step = 1e-3
rtol = 1e-10
atol = 1e-10
"""


def test_a_locked_joint_makes_one_rigid_body(tmp_path: Any) -> None:
    """Body b welded to body a by a locked joint at a's far end, at 90 degrees, hanging by a
    clearance joint: the same motion as one body of the pair's combined mass, centre of mass
    and inertia (parallel axes)."""
    (tmp_path / "pair.toml").write_text(LOCKED, encoding="utf-8")
    pair = simulate_mechanism(load_mechanism_scene(tmp_path / "pair.toml"))
    mass = 1.5
    com_a, com_b = np.array([0.15, 0.0]), np.array([0.3, 0.05])  # in a's frame
    com = (1.0 * com_a + 0.5 * com_b) / mass
    inertia = (0.0075 + 1.0 * np.sum((com_a - com) ** 2)
               + 0.002 + 0.5 * np.sum((com_b - com) ** 2))
    bodies_start = LOCKED.index("[[mechanism.bodies]]")
    joints_start = LOCKED.index("[[mechanism.joints]]")
    weld_start = LOCKED.index("[[mechanism.joints]]", joints_start + 1)
    single = (LOCKED[:bodies_start]
              + f"[[mechanism.bodies]]\nname = \"a\"\nmass = {mass!r}\n"
                f"inertia = {float(inertia)!r}\ncom = [{float(com[0])!r}, {float(com[1])!r}]\n\n"
              + LOCKED[joints_start:weld_start] + LOCKED[LOCKED.index("[run]"):])
    (tmp_path / "single.toml").write_text(single, encoding="utf-8")
    one = simulate_mechanism(load_mechanism_scene(tmp_path / "single.toml"))
    assert len(pair.impacts) == len(one.impacts) > 5
    np.testing.assert_allclose(pair.eccentricity, one.eccentricity, rtol=0, atol=1e-9)
    np.testing.assert_allclose(pair.coordinate("a.angle"), one.coordinate("a.angle"), rtol=0,
                               atol=1e-8)
