"""Simulation: conservation, hard cases that stay stable, convergence, independent references.

Tolerances are stated where they are used. Energy balances are relative to the energy that
moved during the run (``sim_fixtures.energy_scale``).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from sim_fixtures import (
    assert_finite,
    clearance_joint,
    hertz_stiffness,
    make_scene,
    pin_in_bearing,
    relative_balance,
    robot_table,
)

from jointplay.common.errors import DescriptionError, SimulationError
from jointplay.scene.definition import default_scene
from jointplay.sim import Stepper, simulate

LAWS = ("lankarani-nikravesh", "hunt-crossley", "gonthier", "flores")


def pendulum(**kwargs: object) -> dict[str, object]:
    """Two links, joint 1 ideal, joint 2 with 30 um clearance (unless told otherwise)."""
    clearance = float(kwargs.pop("clearance", 30e-6))  # type: ignore[arg-type]
    return robot_table(2, [{"kind": "ideal"}, clearance_joint(clearance)], **kwargs)  # type: ignore[arg-type]


# ---- conservation ----------------------------------------------------------------------------

@pytest.mark.parametrize("tol", [1e-6, 1e-9])
def test_energy_conserved_through_impacts_without_damping_or_friction(tol: float) -> None:
    """ce = 1, mu = 0: kinetic + gravity + contact energy is conserved through every impact,
    to the integrator's tolerance (balance / moved energy <= 10 x rtol)."""
    robot = pendulum(restitution=1.0, drive=False)
    result = simulate(make_scene(robot, initial={"q1": 0.0}, t_end=0.1, rtol=tol, atol=tol))
    assert len(result.impacts) > 5
    assert result.energy["dissipated"][-1] == pytest.approx(0.0, abs=1e-12)
    assert relative_balance(result) < 10 * tol


def test_drive_work_and_dissipation_close_the_balance() -> None:
    """Damping, friction and a drive: E - E0 - W + D stays at the tolerance level."""
    robot = pendulum(restitution=0.5, mu=0.1)
    scene = make_scene(robot, torques={"joint1": "2*sin(2*pi*t)", "joint2": "cos(3*t)"},
                       initial={"q1": -1.0}, t_end=0.2)
    result = simulate(scene)
    assert result.energy["dissipated"][-1] > 0
    assert abs(result.energy["drive_work"][-1]) > 1e-3
    assert relative_balance(result) < 1e-6


# ---- hard cases: finite results and a closed balance, or a clear error -----------------------

HARD_BALANCE = 1e-4  # relative, at rtol = atol = 1e-8


@pytest.mark.parametrize("clearance", [1e-6, 1e-3])
def test_clearance_from_one_micrometre_to_one_millimetre(clearance: float) -> None:
    robot = pendulum(clearance=clearance, restitution=0.8, mu=0.05)
    result = simulate(make_scene(robot, initial={"q1": -0.5}, t_end=0.1))
    assert_finite(result)
    assert relative_balance(result) < HARD_BALANCE
    assert np.max(result.penetration) < 0.05 * clearance + 2e-6


# The default law in the quick tier; the others (a model each) in the slow one.
@pytest.mark.parametrize("law", [pytest.param(law, marks=[pytest.mark.slow] * (law != LAWS[0]))
                                 for law in LAWS])
@pytest.mark.parametrize("ce", [0.1, 0.5, 1.0])
def test_every_damping_law_over_the_restitution_range(law: str, ce: float) -> None:
    robot = pendulum(law=law, restitution=ce)
    result = simulate(make_scene(robot, initial={"q1": 0.0}, t_end=0.05))
    assert_finite(result)
    assert len(result.impacts) >= 1
    assert relative_balance(result) < HARD_BALANCE


@pytest.mark.parametrize("law", LAWS)
def test_restitution_is_the_closed_form_for_every_exponent(law: str) -> None:
    """One impact of a free journal at 0.2 m/s, no friction: for F = K d^n (1 + x d'/v-) the
    rebound integrates exactly, x (1 + e) = ln((1 + x) / (1 - x e)), whatever n
    (sim_fixtures.restitution_closed_form). Every damping law at a low and a high ce, with
    n = 1, 1.5 and 2 as run-time parameters; rtol = atol = 1e-10 (measured deviation <= 1.2e-8)."""
    from sim_fixtures import restitution_closed_form

    from jointplay.derive.laws import damping_factor

    scene = make_scene(pin_in_bearing(law=law, restitution=0.5), initial={"dex1": 0.2},
                       t_end=2e-3, output_step=1e-4, rtol=1e-10, atol=1e-10)
    for ce in (0.3, 0.95):
        want = restitution_closed_form(float(damping_factor(law, ce)))
        for n in (1.0, 1.5, 2.0):
            result = simulate(scene, parameters={"contact.restitution": ce,
                                                 "contact.exponent": n})
            assert result.impacts.speed[0] == pytest.approx(0.2, rel=1e-9)
            assert result.impacts.restitution[0] == pytest.approx(want, rel=5e-8), (ce, n)


@pytest.mark.parametrize("mu", [0.0, 0.1, 0.3])
def test_friction_including_sticking(mu: float) -> None:
    """Hanging at rest under gravity, then a slow drive: the journal sits on the bearing with
    v_t near 0 (sticking) before it slides."""
    robot = pendulum(mu=mu, restitution=0.7) if mu > 0 else pendulum(restitution=0.7)
    scene = make_scene(robot, torques={"joint1": "0.5*t"}, initial={"q1": -math.pi / 2,
                                                                     "ey2": -30e-6},
                       t_end=0.1)
    result = simulate(scene)
    assert_finite(result)
    assert relative_balance(result) < HARD_BALANCE
    # In contact with the sliding speed below v0 (where c_d = 0): the sticking regime.
    in_contact = result.normal_force[:, 0] > 0
    assert np.any(np.abs(result.sliding_speed[in_contact, 0]) < 1e-4)


def test_grazing_contact() -> None:
    """The journal skims the bearing wall: a tangential speed and a tiny normal approach."""
    robot = pin_in_bearing(restitution=0.8, mu=0.1)
    scene = make_scene(robot, initial={"ex1": 30e-6 - 1e-9, "dey1": 0.05, "dex1": 1e-6},
                       t_end=0.01, output_step=1e-5)
    result = simulate(scene)
    assert_finite(result)
    assert relative_balance(result) < HARD_BALANCE
    assert len(result.impacts) >= 1
    assert np.min(result.impacts.speed) < 1e-3  # below the floor: grazing


def test_impact_at_one_metre_per_second() -> None:
    robot = pin_in_bearing(restitution=0.9)
    scene = make_scene(robot, initial={"dex1": 1.0}, t_end=2e-4, output_step=1e-7)
    result = simulate(scene)
    assert_finite(result)
    assert result.impacts.speed[0] == pytest.approx(1.0, rel=1e-6)
    assert relative_balance(result) < HARD_BALANCE


@pytest.mark.slow
def test_twenty_second_run() -> None:
    robot = pendulum(restitution=0.9, mu=0.05, payload=0.5)
    scene = make_scene(robot, torques={"joint1": "3*sin(2*pi*t)", "joint2": "sin(2*pi*t)"},
                       initial={"q1": -math.pi / 2}, t_end=20.0, rtol=1e-6, atol=1e-5)
    result = simulate(scene)
    assert_finite(result)
    assert relative_balance(result) < 1e-2


@pytest.mark.slow
def test_eight_links_all_with_clearance() -> None:
    robot = robot_table(8, [clearance_joint()] * 8, restitution=0.9, mu=0.05)
    result = simulate(make_scene(robot, initial={"q1": -1.2}, t_end=0.05, rtol=1e-6,
                                 atol=1e-5))
    assert_finite(result)
    assert relative_balance(result) < 1e-2


def test_start_at_e_zero_default_scene_runs() -> None:
    scene = default_scene().with_run(t_end=0.05)
    result = simulate(scene)
    assert_finite(result)
    assert np.all(result.eccentricity[0] == 0.0)
    assert len(result.impacts) >= 2  # both journals fall onto their bearings
    assert set(result.impacts.joint.tolist()) == {2, 3}
    # Onsets are located on the clearance circle, to the gap tolerance (1e-4 c).
    np.testing.assert_allclose(np.linalg.norm(result.impacts.eccentricity, axis=1), 30e-6,
                               rtol=1.1e-4)


# ---- divergence is an error, never a silent NaN -----------------------------------------------

def test_explicit_method_beyond_its_stability_limit_stops_with_a_message() -> None:
    robot = pin_in_bearing(restitution=0.9)
    scene = make_scene(robot, initial={"dex1": 1.0}, t_end=1e-3, output_step=1e-4,
                       integrator="rk4", step=1e-4)
    with pytest.raises(SimulationError, match=r"t = .*joint 1.*reduce run\.step"):
        simulate(scene)


@pytest.mark.parametrize("integrator", ["bdf", "cvodes"])
def test_work_limit_stops_with_a_message(integrator: str) -> None:
    scene = default_scene().with_run(t_end=0.02, max_steps=20, integrator=integrator)
    with pytest.raises(SimulationError, match=r"too many steps between outputs: raise "
                                              r"run\.max_steps"):
        simulate(scene)


# ---- fixed-step methods: convergence order ---------------------------------------------------

@pytest.mark.parametrize(("method", "order"), [("rk4", 4), ("radau", 5)])
def test_fixed_step_convergence_order(method: str, order: int) -> None:
    """Ideal joints, smooth drive: halving the step divides the error by about 2^order."""
    robot = robot_table(2, [{"kind": "ideal"}, {"kind": "ideal"}])
    base = make_scene(robot, torques={"joint1": "sin(5*t)", "joint2": "cos(7*t)"},
                      initial={"q1": -1.0, "q2": 0.5}, t_end=0.4, output_step=0.04,
                      rtol=1e-12, atol=1e-12)
    reference = simulate(base)
    errors = []
    steps = [0.02, 0.01, 0.005]
    for h in steps:
        result = simulate(base.with_run(integrator=method, step=h))
        errors.append(np.max(np.abs(result.q - reference.q)))
    rates = [math.log2(a / b) for a, b in itertools.pairwise(errors)]
    assert all(r > order - 0.6 for r in rates), (errors, rates)


def test_radau_reduced_newton_step_equals_the_full_one() -> None:
    """The generated Radau step reduces its Newton matrix I - h A (x) J to the speeds' half
    (J = [0 I; Jq Jv]). One step from inside the paper scene's first impact (at its peak
    force, where Jq holds the contact stiffness) equals the same simplified Newton written
    with the full 6n x 6n matrix, built here from the model's own forward dynamics and state
    Jacobian: the state to 1e-9 of each component's size and the last Newton update to 1e-4
    relative (measured: 1.0e-12 and 1.4e-6; a 1 % error in the matrix gives 2.5e-9 and 0.15).
    """
    import casadi as ca

    from jointplay import generated, load_model
    from jointplay.derive.fixed_step import RADAU_A, RADAU_NEWTON_ITERATIONS

    run = simulate(default_scene().with_run(integrator="bdf", t_end=0.003, rtol=1e-9,
                                            atol=1e-9))
    peak = float(run.impacts.peak_force_time[0])
    x0 = np.asarray(run.sol(np.array([peak]))).ravel()
    model = load_model(generated.folders()["paper_4dof"])
    library = str(model.library)
    fd = ca.external("forward_dynamics", library)
    jac_state = ca.external("jac_state", library)
    radau_step = ca.external("radau_step", library)
    nx = fd.size1_in(0)
    assert x0.size == nx
    p = np.asarray(run.parameters, dtype=float)
    v_imp = np.zeros(fd.size1_in(3))
    v_imp[list(run.clearance_joints).index(int(run.impacts.joint[0]))] = run.impacts.speed[0]
    assert np.max(model.contact(x0, p, v_imp)["delta"]) > 0  # in contact: Jq is stiff
    tau = np.array([[0.3, 0.25, 0.2], [-0.2, -0.1, 0.0]])
    h = 1e-4  # ten times the scene's step: in contact, 8 iterations do not reach round-off

    # The previous formulation: simplified Newton on all 3 nx stage unknowns at once.
    a = ca.DM(RADAU_A)
    jac = ca.DM(jac_state(x0, tau[:, 0], p, v_imp))
    newton_inv = ca.solve(ca.DM.eye(3 * nx) - h * ca.kron(a, jac), ca.DM.eye(3 * nx))
    z = ca.DM.zeros(nx, 3)
    for _ in range(RADAU_NEWTON_ITERATIONS):
        slopes = ca.horzcat(*[fd(x0 + z[:, i], tau[:, i], p, v_imp) for i in range(3)])
        update = -ca.mtimes(newton_inv, ca.vec(z - h * ca.mtimes(slopes, a.T)))
        z = z + ca.reshape(update, nx, 3)
        increment = float(ca.norm_inf(update))
    full = np.asarray(x0 + z[:, 2]).ravel()

    reduced, reduced_increment = radau_step(x0, tau, h, p, v_imp)
    reduced = np.asarray(reduced).ravel()
    scale = np.maximum(np.abs(x0), np.abs(full - x0))
    # Not converged after the fixed iterations at this step (the last update is well above
    # round-off), so the result and the update depend on the Newton matrix, not only on the
    # stage equations' root.
    assert increment > 1e-12
    assert float(np.max(np.abs(reduced - full) / scale)) < 1e-9
    assert float(reduced_increment) == pytest.approx(increment, rel=1e-4)


@pytest.mark.slow
def test_fixed_step_methods_agree_with_cvodes_through_impacts() -> None:
    """The paper scene for 20 ms: RK4 and Radau at 2 us agree with CVODES at 1e-10 to 1 um at
    the tip (onsets between step ends are located by interpolation: first order in h)."""
    scene = default_scene().with_run(t_end=0.02)
    reference = simulate(scene.with_run(rtol=1e-10, atol=1e-10))
    firm = int(np.sum(reference.impacts.speed > 1e-2))
    for method in ("rk4", "radau"):
        result = simulate(scene.with_run(integrator=method, step=2e-6))
        err = np.max(np.linalg.norm(result.tip_position - reference.tip_position, axis=1))
        assert err < 1e-6, (method, err)
        assert int(np.sum(result.impacts.speed > 1e-2)) == firm


@pytest.mark.parametrize("integrator", ["bdf", "cvodes"])
def test_every_adaptive_method_agrees_with_idas(integrator: str) -> None:
    """Three independent integrators, event tolerances following rtol / atol: at 1e-10 the
    tip path and the onset times agree with IDAS (measured: 2.5e-9 m and 6e-12 s for bdf,
    3.6e-9 m and 2.3e-11 s for CVODES)."""
    scene = default_scene().with_run(t_end=0.1, rtol=1e-10, atol=1e-10)
    a = simulate(scene.with_run(integrator=integrator))
    b = simulate(scene.with_run(integrator="idas"))
    assert np.max(np.abs(a.tip_position - b.tip_position)) < 1e-8
    # The first impacts happen at the same times; later ones drift with the state's small
    # differences, amplified by repeated impacts (and grazing onsets are ill-conditioned).
    np.testing.assert_allclose(a.impacts.time[:5], b.impacts.time[:5], atol=1e-9)


# ---- results ---------------------------------------------------------------------------------

def test_result_contents_and_compare_ideal() -> None:
    scene = default_scene().with_run(t_end=0.05)
    result = simulate(scene, compare_ideal=True)
    n = result.t.size
    assert n == 51
    assert result.coordinate_names == ["q2", "q3", "ex2", "ey2", "ex3", "ey3"]
    assert result.eccentricity.shape == (n, 2, 2)
    assert result.ideal is not None
    assert result.ideal.coordinate_names == ["q2", "q3"]
    assert result.ideal.impacts.time.size == 0
    # The clearance robot sags by about the clearance in each of two joints.
    sag = np.max(np.abs(result.tip_position - result.ideal.tip_position))
    assert 1e-5 < sag < 1e-3
    for key in ("steps", "rhs_evaluations", "jacobian_evaluations", "events", "impacts",
                "wall_time_s"):
        assert key in result.stats
    np.testing.assert_allclose(result.radial_clearance, [30e-6, 30e-6], rtol=1e-12)
    assert result.metadata["model_input_hash"]


def test_parameters_change_without_recompiling() -> None:
    scene = default_scene().with_run(t_end=0.02)
    a = simulate(scene)
    b = simulate(scene, parameters={"payload.mass": 4.0})
    assert b.parameters[b.parameter_names.index("payload.mass")] == 4.0
    assert not np.allclose(a.q, b.q)
    with pytest.raises(DescriptionError, match=r"did you mean 'payload\.mass'"):
        simulate(scene, parameters={"payload.mas": 4.0})


def test_stepper_follows_simulate() -> None:
    """Stepping sample by sample with no added torque reproduces simulate (to tolerance)."""
    scene = default_scene().with_run(t_end=0.05, rtol=1e-10, atol=1e-10)
    result = simulate(scene)
    stepper = Stepper(scene)
    states = [stepper.x.copy()] + [stepper.step([0.0, 0.0]).copy() for _ in range(50)]
    # Both runs are within their global error of the solution (at 1e-10, bdf and IDAS agree
    # to 2.5e-9 m at the tip, 0.45 m out): the stepper lands on every sample, simulate on 20
    # calls; measured 1.6e-8 rad.
    assert np.max(np.abs(np.array(states)[:, :2] - result.q[:, :2])) < 3e-8
    assert len(stepper.impacts) == len(result.impacts)


# ---- outside references -----------------------------------------------------------------------

@pytest.mark.parametrize(("law", "ce", "speed"), [("hunt-crossley", 0.8, 0.1),
                                                  ("flores", 0.5, 1.0),
                                                  ("lankarani-nikravesh", 0.9, 0.5)])
def test_pin_impact_matches_exudyn(law: str, ce: float, speed: float) -> None:
    """A free body thrown against the bearing wall: rebound speed, peak force and contact
    duration agree with Exudyn's hollow-sphere contact with the same K, n and damping (1%)."""
    from exudyn_reference import exudyn_pin_impact

    clearance, mass = 30e-6, 2.0
    robot = pin_in_bearing(law=law, restitution=ce, clearance=clearance, mass=mass)
    t_hit = clearance / speed
    scene = make_scene(robot, initial={"dex1": speed}, t_end=round(t_hit + 3e-4, 7),
                       output_step=1e-7, rtol=1e-10, atol=1e-10)
    result = simulate(scene)
    reference = exudyn_pin_impact(mass=mass, stiffness=hertz_stiffness(10e-3, 10e-3 - clearance),
                                  exponent=1.5, restitution=ce, law=law, clearance=clearance,
                                  journal_radius=10e-3 - clearance, impact_speed=speed)
    delta = result.penetration[:, 0]
    inside = delta > 0
    first = int(np.argmax(inside))
    last = first + int(np.argmin(inside[first:])) - 1  # end of the first contact
    # Separation between the last sample in contact and the next, by linear interpolation.
    t = result.t
    t_sep = t[last] + (t[last + 1] - t[last]) * delta[last] / (delta[last] - delta[last + 1])
    duration = t_sep - result.impacts.time[0]
    rebound = abs(result.u[last + 2, 0])  # free flight after separation
    assert first > 0 and not inside[last + 1]
    assert rebound == pytest.approx(reference["rebound_speed"], rel=1e-2)
    assert np.max(result.normal_force) == pytest.approx(reference["peak_force"], rel=1e-2)
    assert duration == pytest.approx(reference["contact_duration"], rel=1e-2)


def test_ideal_joint_simulation_matches_pinocchio() -> None:
    """Ideal joints: jointplay's run equals one driven by Pinocchio's ABA with the same
    integrator (CVODES, same tolerances) to the integrator's tolerance."""
    import casadi as ca
    import pinocchio as pin

    robot = robot_table(3, [{"kind": "ideal"}] * 3, payload=0.5)
    scene = make_scene(robot, torques={"joint1": "2*sin(3*t)", "joint2": "cos(2*t)",
                                       "joint3": "0.3"},
                       initial={"q1": -1.0, "q2": 0.4, "q3": -0.2, "dq1": 0.5}, t_end=0.5,
                       output_step=0.01, rtol=1e-10, atol=1e-10)
    result = simulate(scene)

    pmodel = pin.Model()
    parent = 0
    placement = pin.SE3.Identity()
    for link in scene.robot.links:
        jid = pmodel.addJoint(parent, pin.JointModelRZ(), placement, "rz")
        inertia = pin.Inertia(link.mass, np.array([link.com, 0.0, 0.0]),
                              np.diag([1e-9, 1e-9, link.inertia]))
        pmodel.appendBodyToJoint(jid, inertia, pin.SE3.Identity())
        parent, placement = jid, pin.SE3(np.eye(3), np.array([link.length, 0.0, 0.0]))
    pmodel.appendBodyToJoint(parent, pin.Inertia(0.5, np.array([0.3, 0.0, 0.0]),
                                                 np.zeros((3, 3))), pin.SE3.Identity())
    pmodel.gravity = pin.Motion(np.array([0.0, -9.81, 0.0]), np.zeros(3))
    data = pmodel.createData()

    class Aba(ca.Callback):  # Pinocchio's ABA as the right-hand side, in CVODES
        def __init__(self) -> None:
            ca.Callback.__init__(self)
            self.construct("aba", {"enable_fd": True})

        def get_n_in(self) -> int:
            return 2

        def get_sparsity_in(self, i: int) -> ca.Sparsity:
            return ca.Sparsity.dense(6 if i == 0 else 1, 1)

        def get_sparsity_out(self, i: int) -> ca.Sparsity:
            return ca.Sparsity.dense(6, 1)

        def eval(self, args: list[ca.DM]) -> list[ca.DM]:
            x, t = np.asarray(args[0]).ravel(), float(args[1])
            tau = np.array([2 * math.sin(3 * t), math.cos(2 * t), 0.3])
            a = pin.aba(pmodel, data, x[:3], x[3:], tau)
            return [ca.DM(np.concatenate([x[3:], a]))]

    aba = Aba()
    xs, ts = ca.MX.sym("x", 6), ca.MX.sym("t")
    integ = ca.integrator("pin", "cvodes", {"x": xs, "t": ts, "ode": aba(xs, ts)}, 0.0,
                          result.t[1:], {"reltol": 1e-10, "abstol": 1e-10})
    x0 = np.array([-1.0, 0.4, -0.2, 0.5, 0.0, 0.0])
    reference = np.asarray(integ(x0=x0)["xf"]).T
    np.testing.assert_allclose(result.q[1:], reference[:, :3], atol=5e-8)
    np.testing.assert_allclose(result.u[1:], reference[:, 3:], atol=5e-7)
