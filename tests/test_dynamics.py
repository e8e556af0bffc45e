"""Checks of the derived dynamics against independent references and closed forms.

1. Ideal chains: mass matrix and forward dynamics equal Pinocchio's CRBA and ABA.
2. Clearance joints out of contact: the angle block of M is the ideal M, the contact force is
   exactly zero and the journal floats freely (closed-form free-fall accelerations).
3. Every compiled function and every Jacobian block is finite at the singular states of the
   contact law (e = 0, delta = 0, v_t = 0 in contact, |e| = 1e-15), for every law and
   friction ramp; the exact Jacobian agrees with CasADi's central differences.
4. Locked joints equal the ideal chain with that joint held (reduced system and Pinocchio's
   ``buildReducedModel``).
5. Contact closed forms (shared/reference/clearance-physics.md): Hertz stiffness, the damping
   factor of each law, the friction ramps and their sign, where contact forces enter the
   equations, and the energies.

Everything is float64 with fixed seeds. Tolerances are relative to the largest entry of the
reference (norm-wise), stated at each check. Models are compiled once per structure per module
(and reused from ~/.cache/jointplay across runs).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import casadi as ca
import numpy as np
import pinocchio as pin
import pytest

import jointplay
from jointplay import Contact, Friction, Gravity, Joint, Link, Model, Robot
from jointplay.store.lookup import model_for

LAWS = ("lankarani-nikravesh", "hunt-crossley", "gonthier", "flores")
FRICTIONS = ("none", "linear", "smooth")
STEEL_E, STEEL_NU = 207e9, 0.3

# x(ce) of each law, copied from the table in shared/reference/clearance-physics.md (not from
# jointplay.derive.laws, so a wrong law is caught).
DAMPING_FACTOR: dict[str, Callable[[float], float]] = {
    "lankarani-nikravesh": lambda ce: 3.0 * (1.0 - ce**2) / 4.0,
    "hunt-crossley": lambda ce: 3.0 * (1.0 - ce) / 2.0,
    "gonthier": lambda ce: (1.0 - ce**2) / ce,
    "flores": lambda ce: 8.0 * (1.0 - ce) / (5.0 * ce),
}


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------


def assert_rel(actual: np.ndarray, expected: np.ndarray, tol: float, what: str = "") -> None:
    """max |actual - expected| <= tol * max |expected| (norm-wise relative, shapes equal)."""
    actual = np.asarray(actual, dtype=float)
    expected = np.asarray(expected, dtype=float)
    assert actual.shape == expected.shape, f"{what}: shape {actual.shape} != {expected.shape}"
    scale = float(np.max(np.abs(expected))) if expected.size else 0.0
    err = float(np.max(np.abs(actual - expected))) if expected.size else 0.0
    assert np.all(np.isfinite(actual)), f"{what}: non-finite values {actual}"
    assert err <= tol * scale, (
        f"{what}: max error {err:.3e} exceeds {tol:.0e} x max|expected| {scale:.3e}\n"
        f"actual   {actual}\nexpected {expected}")


def friction_of(kind: str) -> Friction:
    """'none', or modified Coulomb with the 'linear' or 'smooth' ramp."""
    if kind == "none":
        return Friction(law="none")
    return Friction(law="coulomb", ramp=kind)


def random_links(rng: np.random.Generator, k: int) -> tuple[Link, ...]:
    links = []
    for _ in range(k):
        length = rng.uniform(0.1, 1.0)
        links.append(Link(length=length, mass=rng.uniform(0.2, 5.0),
                          inertia=rng.uniform(1e-3, 0.3), com=rng.uniform(0.0, length)))
    return tuple(links)


def random_gravity(rng: np.random.Generator, magnitude: float = 9.81) -> Gravity:
    angle = rng.uniform(0.0, 2.0 * math.pi)
    return Gravity(True, (magnitude * math.cos(angle), magnitude * math.sin(angle)))


def random_joint(rng: np.random.Generator, kind: str) -> Joint:
    if kind in ("clearance", "locked_clearance"):
        rb = rng.uniform(8e-3, 12e-3)
        return Joint(kind=kind, angle=rng.uniform(-2.0, 2.0), bearing_radius=rb,
                     journal_radius=rb - rng.uniform(1e-5, 1e-4),
                     bearing_E=rng.uniform(70e9, 210e9), bearing_nu=rng.uniform(0.25, 0.35),
                     journal_E=rng.uniform(70e9, 210e9), journal_nu=rng.uniform(0.25, 0.35))
    return Joint(kind=kind, angle=rng.uniform(-2.0, 2.0))


def random_robot(rng: np.random.Generator, kinds: Sequence[str], *,
                 law: str = "lankarani-nikravesh", friction: str = "linear") -> Robot:
    k = len(kinds)
    return Robot(links=random_links(rng, k),
                 joints=tuple(random_joint(rng, kind) for kind in kinds),
                 name=f"test{k}",
                 payload_mass=rng.uniform(0.0, 2.0),
                 gravity=random_gravity(rng),
                 contact=Contact(law=law, restitution=rng.uniform(0.5, 0.95)),
                 friction=friction_of(friction))


def ideal_twin(robot: Robot) -> Robot:
    """The same links, payload and gravity with every joint ideal."""
    return Robot(links=robot.links, joints=tuple(Joint() for _ in robot.joints),
                 name=robot.name, payload_mass=robot.payload_mass, gravity=robot.gravity)


def mass_of(model: Model, q: np.ndarray, p: np.ndarray) -> np.ndarray:
    """model.mass_matrix, checked to be n x n (also for a single coordinate)."""
    mass = model.mass_matrix(q, p)
    assert mass.shape == (model.n_coordinates, model.n_coordinates)
    return mass


def pvec(robot: Robot) -> np.ndarray:
    return np.asarray(robot.parameter_values(), dtype=float)


def index(model: Model) -> dict[str, int]:
    return {name: i for i, name in enumerate(model.coordinates)}


def clearance(robot: Robot, joint: int) -> float:
    j = robot.joints[joint - 1]
    return j.bearing_radius - j.journal_radius


def hertz_stiffness(rb: float, rj: float, eb: float = STEEL_E, nub: float = STEEL_NU,
                    ej: float = STEEL_E, nuj: float = STEEL_NU) -> float:
    """K = 4 / (3 (sb + sj)) sqrt(Rb Rj / (Rb - Rj)), s = (1 - nu^2)/E (reference sheet)."""
    sb, sj = (1.0 - nub**2) / eb, (1.0 - nuj**2) / ej
    return 4.0 / (3.0 * (sb + sj)) * math.sqrt(rb * rj / (rb - rj))


def joint_stiffness(robot: Robot, joint: int) -> float:
    j = robot.joints[joint - 1]
    return hertz_stiffness(j.bearing_radius, j.journal_radius, j.bearing_E, j.bearing_nu,
                           j.journal_E, j.journal_nu)


def unit(angle: float) -> np.ndarray:
    return np.array([math.cos(angle), math.sin(angle)])


def chain_kinematics(robot: Robot, model: Model, x: np.ndarray,
                     udot: np.ndarray | None = None) -> dict[str, object]:
    """Independent numpy kinematics of the chain (eccentricities in the inertial frame)."""
    n = model.n_coordinates
    idx = index(model)
    q, u = x[:n], x[n:]
    a = np.zeros(n) if udot is None else np.asarray(udot)
    theta = omega = alpha = 0.0
    r, v, acc = np.zeros(2), np.zeros(2), np.zeros(2)
    com_pos, com_vel, omegas = [], [], []
    for i, (link, joint) in enumerate(zip(robot.links, robot.joints, strict=True), start=1):
        if joint.moves:
            j = idx[f"q{i}"]
            theta, omega, alpha = theta + q[j], omega + u[j], alpha + a[j]
        else:
            theta += joint.angle
        if joint.has_clearance:
            e = [idx[f"ex{i}"], idx[f"ey{i}"]]
            r, v, acc = r + q[e], v + u[e], acc + a[e]
        d = unit(theta)
        nrm = np.array([-d[1], d[0]])
        com_pos.append(r + link.com * d)
        com_vel.append(v + link.com * omega * nrm)
        omegas.append(omega)
        acc = acc + link.length * (alpha * nrm - omega**2 * d)
        v = v + link.length * omega * nrm
        r = r + link.length * d
    return {"com": com_pos, "com_vel": com_vel, "omega": omegas, "tip": r, "tip_vel": v,
            "tip_acc": acc}


@pytest.fixture(scope="module")
def compiled() -> Callable[[Robot], Model]:
    """Derive/compile each structure once per module (the on-disk cache spans runs)."""
    cache: dict[str, Model] = {}

    def get(robot: Robot) -> Model:
        key = robot.structure_hash()
        if key not in cache:
            cache[key] = model_for(robot)
        model = cache[key]
        assert model.parameters == [prm.name for prm in robot.parameters()]
        return model

    return get


# ---------------------------------------------------------------------------------------------
# 1. Ideal chains against Pinocchio
# ---------------------------------------------------------------------------------------------


def pinocchio_chain(robot: Robot) -> pin.Model:
    """Planar chain of RZ joints, joint i placed at the end of link i-1 (along its x axis)."""
    model = pin.Model()
    parent, offset = 0, 0.0
    for i, link in enumerate(robot.links, start=1):
        placement = pin.SE3(np.eye(3), np.array([offset, 0.0, 0.0]))
        jid = model.addJoint(parent, pin.JointModelRZ(), placement, f"joint{i}")
        model.addJointFrame(jid)  # buildReducedModel needs the frames
        # Only Izz matters in the plane; Ixx, Iyy just need to be positive.
        rot = np.diag([link.inertia + 0.5, link.inertia + 0.7, link.inertia])
        model.appendBodyToJoint(jid, pin.Inertia(link.mass, np.array([link.com, 0.0, 0.0]), rot),
                                pin.SE3.Identity())
        model.addBodyFrame(f"link{i}", jid, pin.SE3.Identity(), -1)
        parent, offset = jid, link.length
    payload = pin.Inertia(robot.payload_mass, np.array([offset, 0.0, 0.0]), np.zeros((3, 3)))
    model.appendBodyToJoint(parent, payload, pin.SE3.Identity())
    model.gravity.linear = np.array([*robot.gravity.vector, 0.0])
    return model


def pin_mass_and_aba(pmodel: pin.Model, q: np.ndarray, u: np.ndarray,
                     tau: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    data = pmodel.createData()
    mass = np.array(pin.crba(pmodel, data, q))
    mass = np.triu(mass) + np.triu(mass, 1).T  # CRBA fills the upper triangle
    acc = np.array(pin.aba(pmodel, data, q, u, tau))
    return mass, acc


# k = 5..8 (a model each) in the slow tier
@pytest.mark.parametrize("k", [pytest.param(k, marks=[pytest.mark.slow] if k > 4 else [])
                               for k in range(1, 9)])
def test_ideal_chain_matches_pinocchio(compiled: Callable[[Robot], Model], k: int) -> None:
    """M = CRBA and du/dt = ABA to 1e-10 (relative to max entry), random robots and states."""
    rng = np.random.default_rng(1000 + k)
    for _ in range(3):
        robot = random_robot(rng, ["ideal"] * k)
        model = compiled(robot)
        assert model.coordinates == [f"q{i}" for i in range(1, k + 1)]
        p = pvec(robot)
        pmodel = pinocchio_chain(robot)
        for _ in range(4):
            q = rng.uniform(-math.pi, math.pi, k)
            u = rng.uniform(-3.0, 3.0, k)
            tau = rng.uniform(-20.0, 20.0, k)
            mass_ref, acc_ref = pin_mass_and_aba(pmodel, q, u, tau)
            assert_rel(mass_of(model, q, p), mass_ref, 1e-10, f"k={k} mass matrix")
            xdot = model.forward_dynamics(np.r_[q, u], tau, p)
            assert np.array_equal(xdot[:k], u)
            assert_rel(xdot[k:], acc_ref, 1e-10, f"k={k} accelerations")


# ---------------------------------------------------------------------------------------------
# 2. Clearance joints out of contact
# ---------------------------------------------------------------------------------------------

CLEARANCE_KINDS = [["clearance"], ["clearance", "clearance"], ["ideal", "clearance", "clearance"]]


def inside_clearance(rng: np.random.Generator, robot: Robot, model: Model,
                     q_angles: np.ndarray) -> np.ndarray:
    """Coordinates with the given angles and every eccentricity strictly inside (|e| < c/2)."""
    q = np.zeros(model.n_coordinates)
    idx = index(model)
    nq = len(robot.moving_joints)
    q[:nq] = q_angles
    for i in robot.clearance_joints:
        e = rng.uniform(0.0, 0.5) * clearance(robot, i) * unit(rng.uniform(0, 2 * math.pi))
        q[[idx[f"ex{i}"], idx[f"ey{i}"]]] = e
    return q


@pytest.mark.parametrize("kinds", CLEARANCE_KINDS, ids=lambda ks: "-".join(ks))
def test_clearance_mass_matrix_is_ideal(compiled: Callable[[Robot], Model],
                                        kinds: list[str]) -> None:
    """Angle block of M equals the ideal M (at e = 0 and anywhere inside the clearance, since
    e is inertial); each eccentricity block is the outboard mass times I2. Tolerance 1e-12."""
    rng = np.random.default_rng(2000 + len(kinds))
    k = len(kinds)
    for _ in range(3):
        robot = random_robot(rng, kinds)
        model = compiled(robot)
        ideal = compiled(ideal_twin(robot))
        p, p_ideal = pvec(robot), pvec(ideal_twin(robot))
        idx = index(model)
        angles = rng.uniform(-math.pi, math.pi, k)
        mass_ideal = mass_of(ideal, angles, p_ideal)
        q_centred = np.r_[angles, np.zeros(model.n_coordinates - k)]
        for q in (q_centred, inside_clearance(rng, robot, model, angles)):
            mass = mass_of(model, q, p)
            assert_rel(mass[:k, :k], mass_ideal, 1e-12, "angle block")
            assert_rel(mass, mass.T, 1e-14, "symmetry")
            assert np.all(np.linalg.eigvalsh(mass) > 0)
            for a in robot.clearance_joints:
                for b in robot.clearance_joints:
                    outboard = sum(link.mass for link in robot.links[max(a, b) - 1:])
                    block = mass[np.ix_([idx[f"ex{a}"], idx[f"ey{a}"]],
                                        [idx[f"ex{b}"], idx[f"ey{b}"]])]
                    assert_rel(block, (outboard + robot.payload_mass) * np.eye(2), 1e-12,
                               f"e{a}-e{b} block")


@pytest.mark.parametrize("kinds", CLEARANCE_KINDS, ids=lambda ks: "-".join(ks))
def test_free_journal_at_rest_without_gravity(compiled: Callable[[Robot], Model],
                                              kinds: list[str]) -> None:
    """Zero gravity, no torque, at rest, |e| < c: contact forces exactly 0, f = 0, xdot = 0."""
    rng = np.random.default_rng(2100 + len(kinds))
    k = len(kinds)
    for _ in range(3):
        robot = jointplay.with_parameters(random_robot(rng, kinds),
                                          {"gravity.x": 0.0, "gravity.y": 0.0})
        model = compiled(robot)
        p = pvec(robot)
        q = inside_clearance(rng, robot, model, rng.uniform(-math.pi, math.pi, k))
        x = np.r_[q, np.zeros(model.n_coordinates)]
        tau = np.zeros(len(model.torque_joints))
        v_imp = rng.uniform(0.0, 0.5, len(model.clearance_joints))
        contact = model.contact(x, p, v_imp)
        assert np.all(contact["delta"] < 0)
        for key in ("f_n", "f_t", "f_x", "f_y"):
            assert np.all(contact[key] == 0.0), (key, contact[key])
        assert np.all(np.abs(model.forcing(x, tau, p, v_imp)) <= 1e-12)
        assert np.all(np.abs(model.forward_dynamics(x, tau, p, v_imp)) <= 1e-12)


def test_single_link_journal_falls_freely(compiled: Callable[[Robot], Model]) -> None:
    """One link, clearance at joint 1, |e| < c: the link is a free body. At rest d2e/dt2 = g
    and d2q/dt2 = 0; spinning at w, the centre of mass (link + payload, at c_tot along the
    link) is unaccelerated, so d2e/dt2 = g + c_tot w^2 (cos q, sin q). Tolerance 1e-12."""
    rng = np.random.default_rng(2200)
    for _ in range(5):
        robot = random_robot(rng, ["clearance"])
        model = compiled(robot)
        p = pvec(robot)
        g = np.array(robot.gravity.vector)
        link, mp = robot.links[0], robot.payload_mass
        c_tot = (link.mass * link.com + mp * link.length) / (link.mass + mp)
        q = inside_clearance(rng, robot, model, rng.uniform(-math.pi, math.pi, 1))
        tau = np.zeros(1)
        xdot = model.forward_dynamics(np.r_[q, np.zeros(3)], tau, p)
        assert_rel(xdot[3:], np.r_[0.0, g], 1e-12, "at rest")
        w = rng.uniform(-5.0, 5.0)
        u = np.r_[w, rng.uniform(-0.1, 0.1, 2)]
        assert np.all(model.contact(np.r_[q, u], p)["f_n"] == 0.0)
        xdot = model.forward_dynamics(np.r_[q, u], tau, p)
        assert_rel(xdot[3:], np.r_[0.0, g + c_tot * w**2 * unit(q[0])], 1e-12, "spinning")


def test_outboard_chain_falls_freely(compiled: Callable[[Robot], Model]) -> None:
    """kinds ideal-clearance-clearance, at rest, both journals inside their clearance.

    Links 2, 3 (and the payload) fall freely with g: their absolute angular accelerations are 0
    and journal 2 accelerates with g. Link 1 swings as a lone pendulum:
    a1 = m1 c1 (g x d1) / (I1 + m1 c1^2). So q1'' = a1, q2'' = -a1, q3'' = 0,
    e2'' = g - L1 a1 (-sin q1, cos q1) and e3'' = 0. Tolerance 1e-12.
    """
    rng = np.random.default_rng(2300)
    for _ in range(5):
        robot = random_robot(rng, ["ideal", "clearance", "clearance"])
        model = compiled(robot)
        p = pvec(robot)
        g = np.array(robot.gravity.vector)
        link1 = robot.links[0]
        q = inside_clearance(rng, robot, model, rng.uniform(-math.pi, math.pi, 3))
        d1 = unit(q[0])
        a1 = link1.mass * link1.com * (d1[0] * g[1] - d1[1] * g[0]) / (
            link1.inertia + link1.mass * link1.com**2)
        bearing_acc = link1.length * a1 * np.array([-d1[1], d1[0]])
        x = np.r_[q, np.zeros(7)]
        contact = model.contact(x, p)
        assert np.all(contact["f_x"] == 0.0) and np.all(contact["f_y"] == 0.0)
        xdot = model.forward_dynamics(x, np.zeros(3), p)
        assert model.coordinates == ["q1", "q2", "q3", "ex2", "ey2", "ex3", "ey3"]
        expected = np.r_[a1, -a1, 0.0, g - bearing_acc, 0.0, 0.0]
        assert_rel(xdot[7:], expected, 1e-12, "outboard free fall")


# ---------------------------------------------------------------------------------------------
# 3. Finiteness at the singular states, and the exact Jacobian against finite differences
# ---------------------------------------------------------------------------------------------


def two_clearance_robot(law: str, friction: str) -> Robot:
    """The 2-link chain with clearance at both joints (one compiled model per law x friction,
    shared by sections 3 and 5), with fixed random numbers."""
    return random_robot(np.random.default_rng(3000), ["clearance", "clearance"], law=law,
                        friction=friction)


def singular_states(robot: Robot, rng: np.random.Generator) -> dict[str, np.ndarray]:
    """States of the 2-link clearance chain [q1 q2 ex1 ey1 ex2 ey2 | speeds]."""
    c1, c2 = clearance(robot, 1), clearance(robot, 2)
    angles = np.array([0.4, -1.1])

    def state(e1: Sequence[float], e2: Sequence[float], speeds: np.ndarray) -> np.ndarray:
        return np.r_[angles, e1, e2, speeds]

    moving = np.r_[rng.uniform(-2, 2, 2), rng.uniform(-0.05, 0.05, 4)]
    return {
        "centred_moving": state([0.0, 0.0], [0.0, 0.0], moving),
        "centred_at_rest": state([0.0, 0.0], [0.0, 0.0], np.zeros(6)),
        "touching": state([c1, 0.0], [0.0, -c2], moving),  # delta = 0 exactly
        "touching_at_rest": state([c1, 0.0], [0.0, -c2], np.zeros(6)),
        # In contact, approaching along the normal, no sliding: v_t = 0 exactly.
        "sticking": state([c1 + 2e-6, 0.0], [0.0, c2 + 1e-6],
                          np.array([0.0, 0.0, 0.01, 0.0, 0.0, 0.02])),
        "sticking_at_rest": state([c1 + 2e-6, 0.0], [0.0, c2 + 1e-6], np.zeros(6)),
        "tiny": state([1e-15, 0.0], [0.6e-15, -0.8e-15], moving),
        "tiny_at_rest": state([1e-15, 0.0], [0.6e-15, -0.8e-15], np.zeros(6)),
    }


def all_outputs(model: Model, x: np.ndarray, tau: np.ndarray, p: np.ndarray,
                v_imp: np.ndarray) -> dict[str, np.ndarray]:
    n = model.n_coordinates
    xdot = model.forward_dynamics(x, tau, p, v_imp)
    out: dict[str, np.ndarray] = {
        "mass_matrix": model.mass_matrix(x[:n], p),
        "forcing": model.forcing(x, tau, p, v_imp),
        "forward_dynamics": xdot,
    }
    out.update({f"jacobian[{k}]": v for k, v in model.jacobian(x, tau, p, v_imp).items()})
    out.update({f"contact[{k}]": v for k, v in model.contact(x, p, v_imp).items()})
    out.update({f"energy[{k}]": np.array(v) for k, v in model.energy(x, p).items()})
    out.update({f"end_effector[{k}]": v
                for k, v in model.end_effector(x, xdot[n:], p).items()})
    return out


def non_finite_report(model: Model, outputs: dict[str, np.ndarray]) -> list[str]:
    bad = []
    for name, value in outputs.items():
        mask = ~np.isfinite(value)
        if mask.any():
            where = ""
            if name == "jacobian[p]":
                where = " columns " + ", ".join(model.parameters[j]
                                                for j in sorted(set(np.nonzero(mask)[1])))
            bad.append(f"{name}: {int(mask.sum())} non-finite{where}")
    return bad


# Each case derives and compiles a model of its own: the linear ramp of every law in the quick
# tier, the rest in the slow one.
@pytest.mark.parametrize("friction", [pytest.param(f, marks=[pytest.mark.slow] if f != "linear"
                                                   else []) for f in FRICTIONS])
@pytest.mark.parametrize("law", LAWS)
def test_finite_at_singular_states(compiled: Callable[[Robot], Model], law: str,
                                   friction: str) -> None:
    """Every function output and Jacobian block is finite at e = 0, delta = 0, v_t = 0 in
    contact and |e| = 1e-15, with the captured impact speed 0 (floored) or positive."""
    robot = two_clearance_robot(law, friction)
    model = compiled(robot)
    p = pvec(robot)
    rng = np.random.default_rng(3100)
    tau = rng.uniform(-1.0, 1.0, 2)
    failures = []
    for name, x in singular_states(robot, rng).items():
        contact = model.contact(x, p)
        if name.startswith("touching"):
            assert np.all(contact["delta"] == 0.0), contact["delta"]
        if name.startswith("sticking"):
            assert np.all(contact["v_t"] == 0.0) and np.all(contact["f_n"] > 0), contact
        for v_imp in (np.zeros(2), np.array([0.1, 0.3])):
            bad = non_finite_report(model, all_outputs(model, x, tau, p, v_imp))
            if bad:
                failures.append(f"{name}, v_imp={v_imp}: " + "; ".join(bad))
    assert not failures, "\n".join(failures)


def generic_contact_state(robot: Robot) -> tuple[np.ndarray, np.ndarray]:
    """Both joints penetrating and sliding (|v_t| away from the ramp corners), approaching."""
    c1, c2 = clearance(robot, 1), clearance(robot, 2)
    n1, n2 = unit(0.4), unit(2.3)
    t1, t2 = np.array([-n1[1], n1[0]]), np.array([-n2[1], n2[0]])
    e1, e2 = (c1 + 1.5e-6) * n1, (c2 + 0.7e-6) * n2
    u = np.array([0.7, -1.1])
    ed1 = 0.02 * n1 + 0.003 * t1
    ed2 = 0.01 * n2 - 0.004 * t2
    x = np.r_[0.3, -0.5, e1, e2, u, ed1, ed2]
    return x, np.array([0.05, 0.05])


@pytest.mark.parametrize("friction", FRICTIONS)
@pytest.mark.parametrize("law", LAWS)
def test_jacobian_matches_central_differences(compiled: Callable[[Robot], Model], law: str,
                                              friction: str) -> None:
    """The exact Jacobian of forward_dynamics against CasADi central differences (fd_method
    central on the compiled function, directions scaled so every input gets a sensible step:
    angles 1, eccentricities and radii 1e-7 m, speeds 1, eccentricity rates 1e-2 m/s, other
    parameters 1e-3 of their value). Block 'x' is the one integrators use; 'tau', 'p' and
    'v_imp' are checked the same way at this in-contact state. Tolerance: 1e-5 of each
    column's largest entry (floored at 1e-6 of the block's largest)."""
    robot = two_clearance_robot(law, friction)
    model = compiled(robot)
    p = pvec(robot)
    x, v_imp = generic_contact_state(robot)
    tau = np.array([0.3, -0.2])
    contact = model.contact(x, p, v_imp)
    assert np.all(contact["delta"] > 0) and np.all(contact["delta_dot"] > 0)
    speed = np.abs(contact["v_t"])
    for corner in (robot.friction.v0, robot.friction.v1):
        assert np.all(np.abs(speed - corner) > 1e-3 * corner + 1e-4), "too close to a kink"
    exact = model.jacobian(x, tau, p, v_imp)

    opts = {"enable_fd": True, "enable_forward": False, "enable_reverse": False,
            "enable_jacobian": False, "fd_method": "central",
            "fd_options": {"h": 1e-3, "h_iter": 0}}
    fd_function = ca.external("forward_dynamics", str(model.library), opts)
    inputs = {"x": x, "tau": tau, "p": p, "v_imp": v_imp}
    scales = {"x": np.r_[1.0, 1.0, np.full(4, 1e-7), 1.0, 1.0, np.full(4, 1e-2)],
              "tau": np.ones(2), "v_imp": np.full(2, 1e-2),
              # radii move the penetration: step them like the eccentricities
              "p": np.array([1e-7 if name.endswith("_radius") else 1e-3 * abs(value)
                             for name, value in zip(model.parameters, p, strict=True)])}
    failures = []
    for block in ("x", "tau", "p", "v_imp"):
        z = ca.MX.sym("z", inputs[block].size)
        args = [ca.DM(v) for v in inputs.values()]
        args[list(inputs).index(block)] += ca.DM(scales[block]) * z
        # Forward mode (J times the identity): the FD external offers no reverse mode.
        jac = ca.jtimes(fd_function(*args), z, ca.MX.eye(z.numel()))
        fd = ca.Function("fd", [z], [jac])
        scaled = np.array(fd(np.zeros(inputs[block].size)))
        exact_scaled = exact[block] * scales[block]
        assert np.all(np.isfinite(exact_scaled)), block
        col_scale = np.maximum(np.abs(exact_scaled).max(axis=0),
                               1e-6 * np.abs(exact_scaled).max())
        rel = np.abs(scaled - exact_scaled) / col_scale
        if rel.max() > 1e-5:
            worst = int(rel.max(axis=0).argmax())
            name = model.parameters[worst] if block == "p" else str(worst)
            failures.append(f"block {block}: column {name}: {rel.max():.2e}")
    assert not failures, "\n".join(failures)


# ---------------------------------------------------------------------------------------------
# 4. Locked joints
# ---------------------------------------------------------------------------------------------


@pytest.mark.parametrize(("k", "j"), [(2, 1), (3, 3), (4, 2), (4, 1)])
def test_locked_joint_equals_held_ideal_joint(compiled: Callable[[Robot], Model], k: int,
                                              j: int) -> None:
    """Joint j locked at phi = ideal chain with q_j = phi, u_j = 0, u_j' = 0 enforced:
    M_locked = M_ideal without row/column j; du/dt solves the reduced ideal system; both equal
    Pinocchio's buildReducedModel. Energies equal. Tolerance 1e-10 (M: 1e-12)."""
    rng = np.random.default_rng(4000 + 10 * k + j)
    kinds = ["ideal"] * k
    kinds[j - 1] = "locked"
    keep = [i for i in range(k) if i != j - 1]
    for _ in range(3):
        robot = random_robot(rng, kinds)
        phi = robot.joints[j - 1].angle
        ideal_robot = ideal_twin(robot)
        model, ideal = compiled(robot), compiled(ideal_robot)
        p, p_ideal = pvec(robot), pvec(ideal_robot)
        assert model.coordinates == [f"q{i + 1}" for i in keep]
        assert model.torque_joints == [i + 1 for i in keep]
        pmodel = pinocchio_chain(ideal_robot)
        q_ref = np.zeros(k)
        q_ref[j - 1] = phi
        reduced = pin.buildReducedModel(pmodel, [j], q_ref)
        reduced.gravity.linear = pmodel.gravity.linear
        for _ in range(3):
            q = rng.uniform(-math.pi, math.pi, k - 1)
            u = rng.uniform(-3.0, 3.0, k - 1)
            tau = rng.uniform(-20.0, 20.0, k - 1)
            q_full, u_full, tau_full = np.zeros(k), np.zeros(k), np.zeros(k)
            q_full[keep], u_full[keep], tau_full[keep] = q, u, tau
            q_full[j - 1] = phi
            mass_full = mass_of(ideal, q_full, p_ideal)
            mass = mass_of(model, q, p)
            assert_rel(mass, mass_full[np.ix_(keep, keep)], 1e-12, "locked mass matrix")
            forcing_full = ideal.forcing(np.r_[q_full, u_full], tau_full, p_ideal)
            acc_reduced = np.linalg.solve(mass_full[np.ix_(keep, keep)], forcing_full[keep])
            xdot = model.forward_dynamics(np.r_[q, u], tau, p)
            assert_rel(xdot[k - 1:], acc_reduced, 1e-10, "locked vs reduced ideal")
            mass_pin, acc_pin = pin_mass_and_aba(reduced, q, u, tau)
            assert_rel(mass, mass_pin, 1e-10, "locked vs pinocchio CRBA")
            assert_rel(xdot[k - 1:], acc_pin, 1e-10, "locked vs pinocchio ABA")
            energy = model.energy(np.r_[q, u], p)
            energy_full = ideal.energy(np.r_[q_full, u_full], p_ideal)
            for key in ("kinetic", "gravity"):
                assert energy[key] == pytest.approx(energy_full[key], rel=1e-12, abs=1e-12)


@pytest.mark.parametrize(("k", "j"), [(2, 2), (3, 1)])
def test_locked_clearance_joint_is_locked_joint_with_a_free_journal(
        compiled: Callable[[Robot], Model], k: int, j: int) -> None:
    """Joint j locked but with play: the angles behave as with a plain locked joint while the
    journal is inside the clearance (angle block of M equal), the journal coordinates carry
    the outboard mass, and at rest in zero gravity nothing accelerates (1e-12)."""
    rng = np.random.default_rng(5000 + 10 * k + j)
    kinds = ["ideal"] * k
    kinds[j - 1] = "locked_clearance"
    robot = random_robot(rng, kinds, friction="none")
    plain = Robot(links=robot.links,
                  joints=tuple(Joint(kind="locked", angle=jt.angle) if jt.kind ==
                               "locked_clearance" else jt for jt in robot.joints),
                  payload_mass=robot.payload_mass, gravity=robot.gravity)
    model, locked = compiled(robot), compiled(plain)
    n_angles = k - 1
    assert model.coordinates == [*locked.coordinates, f"ex{j}", f"ey{j}"]
    q = rng.uniform(-math.pi, math.pi, n_angles)
    e = 0.4 * clearance(robot, j) * unit(rng.uniform(0, 2 * math.pi))
    mass = mass_of(model, np.r_[q, e], pvec(robot))
    assert_rel(mass[:n_angles, :n_angles], mass_of(locked, q, pvec(plain)), 1e-12,
               "angle block")
    outboard = sum(link.mass for link in robot.links[j - 1:]) + robot.payload_mass
    assert_rel(mass[n_angles:, n_angles:], outboard * np.eye(2), 1e-12, "journal block")
    weightless = jointplay.with_parameters(robot, {"gravity.x": 0.0, "gravity.y": 0.0})
    xdot = model.forward_dynamics(np.r_[q, e, np.zeros(n_angles + 2)], np.zeros(n_angles),
                                  pvec(weightless))
    assert np.abs(xdot).max() <= 1e-12
    assert model.contact(np.r_[q, e, np.zeros(n_angles + 2)], pvec(robot))["f_n"][0] == 0.0


# ---------------------------------------------------------------------------------------------
# 5. Contact closed forms, force assembly and energies
# ---------------------------------------------------------------------------------------------


def contact_state(robot: Robot, model: Model, joint: int, penetration: float, angle: float,
                  normal_speed: float = 0.0, tangential_speed: float = 0.0) -> np.ndarray:
    """Two-link clearance chain at rest except joint `joint`: e = (c + delta) n(angle) and
    de/dt = normal_speed n + tangential_speed t. The other joint sits centred."""
    idx = index(model)
    x = np.zeros(model.n_state)
    x[:2] = [0.4, -1.1]
    n_vec = unit(angle)
    t_vec = np.array([-n_vec[1], n_vec[0]])
    e = [idx[f"ex{joint}"], idx[f"ey{joint}"]]
    x[e] = (clearance(robot, joint) + penetration) * n_vec
    x[[model.n_coordinates + i for i in e]] = normal_speed * n_vec + tangential_speed * t_vec
    return x


def test_hertz_stiffness_reference_numbers() -> None:
    """The reference sheet's steel numbers (3 significant figures)."""
    assert hertz_stiffness(10e-3, 9.5e-3) == pytest.approx(6.61e10, rel=1e-3)
    assert hertz_stiffness(10e-3, 9.9e-3) == pytest.approx(1.51e11, rel=1e-3)


@pytest.mark.parametrize("law", LAWS)
def test_normal_force_is_hertz_at_rest(compiled: Callable[[Robot], Model], law: str) -> None:
    """Zero velocity, penetration delta: f_n = K delta^n (1e-12), K from the formula, incl.
    the sheet's 6.61e10 N/m^1.5 (Rb 10 mm, Rj 9.5 mm steel); other materials and exponents;
    contact energy = K delta^(n+1)/(n+1); f = -f_n n."""
    base = two_clearance_robot(law, "none")
    model = compiled(base)
    cases = [
        ({"joint1.bearing_radius": 10e-3, "joint1.journal_radius": 9.5e-3, "joint1.bearing_E":
          STEEL_E, "joint1.journal_E": STEEL_E, "joint1.bearing_nu": STEEL_NU,
          "joint1.journal_nu": STEEL_NU, "contact.exponent": 1.5}, 6.61e10),
        ({"joint1.bearing_radius": 10e-3, "joint1.journal_radius": 9.9e-3, "joint1.bearing_E":
          STEEL_E, "joint1.journal_E": STEEL_E, "joint1.bearing_nu": STEEL_NU,
          "joint1.journal_nu": STEEL_NU, "contact.exponent": 1.5}, 1.51e11),
        ({"joint1.bearing_E": 70e9, "joint1.bearing_nu": 0.33, "contact.exponent": 1.0}, None),
        ({"joint1.journal_E": 110e9, "joint1.journal_nu": 0.34, "contact.exponent": 2.0}, None),
    ]
    for values, sheet_k in cases:
        robot = jointplay.with_parameters(base, values)
        p = pvec(robot)
        stiffness = joint_stiffness(robot, 1)
        if sheet_k is not None:
            assert stiffness == pytest.approx(sheet_k, rel=1e-3)
        exponent = robot.contact.exponent
        for delta, angle in ((1e-7, 0.3), (2e-6, -2.0), (5e-6, 4.0)):
            x = contact_state(robot, model, 1, delta, angle)
            contact = model.contact(x, p, np.array([0.2, 0.2]))
            assert contact["delta"][0] == pytest.approx(delta, rel=1e-8)
            assert contact["delta_dot"][0] == 0.0 and contact["delta"][1] < 0
            d = contact["delta"][0]
            f_n = stiffness * d**exponent
            assert contact["f_n"][0] == pytest.approx(f_n, rel=1e-12)
            assert contact["f_n"][1] == 0.0
            assert contact["f_t"][0] == 0.0
            assert_rel(np.r_[contact["f_x"][0], contact["f_y"][0]], -f_n * unit(angle), 1e-12,
                       "force direction")
            energy = model.energy(x, p)
            assert energy["contact"] == pytest.approx(
                stiffness * d ** (exponent + 1) / (exponent + 1), rel=1e-12)


@pytest.mark.parametrize("law", LAWS)
def test_damping_factor_of_each_law(compiled: Callable[[Robot], Model], law: str) -> None:
    """f_n = K d^n (1 + x(ce) d'/v-) with x(ce) from the sheet's table; v- floored at
    contact.impact_speed_floor; clamped at 0 when separating fast. Tolerance 1e-12."""
    base = two_clearance_robot(law, "none")
    model = compiled(base)
    x_of = DAMPING_FACTOR[law]
    for ce in (0.3, 0.6, 0.9, 1.0):
        robot = jointplay.with_parameters(base, {"contact.restitution": ce,
                                                 "contact.impact_speed_floor": 1e-3})
        p = pvec(robot)
        stiffness = joint_stiffness(robot, 1)
        n_exp = robot.contact.exponent
        # (approach speed, captured impact speed v_imp, effective v- after the floor)
        for rate, v_imp, v_minus in ((0.2, 0.2, 0.2), (0.1, 0.2, 0.2), (-0.05, 0.2, 0.2),
                                     (2e-3, 0.0, 1e-3), (5e-4, 2e-4, 1e-3)):
            x = contact_state(robot, model, 1, 1.5e-6, 1.2, normal_speed=rate)
            contact = model.contact(x, p, np.array([v_imp, 0.0]))
            d, d_dot = contact["delta"][0], contact["delta_dot"][0]
            assert d_dot == pytest.approx(rate, rel=1e-12)
            expected = stiffness * d**n_exp * (1.0 + x_of(ce) * d_dot / v_minus)
            assert contact["f_n"][0] == pytest.approx(expected, rel=1e-12), (ce, rate, v_imp)
            if rate == v_imp:
                assert contact["f_n"][0] == pytest.approx(
                    stiffness * d**n_exp * (1.0 + x_of(ce)), rel=1e-12)
        if x_of(ce) > 0:  # separating faster than v-/x: the damping would pull; clamped to 0
            x = contact_state(robot, model, 1, 1.5e-6, 1.2, normal_speed=-2.0 * 0.2 / x_of(ce))
            assert model.contact(x, p, np.array([0.2, 0.0]))["f_n"][0] == 0.0


def ramp(kind: str, speed: float, v0: float, v1: float) -> float:
    s = min(max((abs(speed) - v0) / (v1 - v0), 0.0), 1.0)
    return s if kind == "linear" else s * s * (3.0 - 2.0 * s)


@pytest.mark.parametrize("kind", ["linear", "smooth"])
@pytest.mark.parametrize("law", LAWS)
def test_friction_ramp_and_direction(compiled: Callable[[Robot], Model], law: str,
                                     kind: str) -> None:
    """f_t = -mu c_d(|v_t|) f_n sign(v_t): c_d = 0 below v0, the ramp between, 1 above v1;
    sliding backwards gives the opposite sign (|v_t| in c_d, not v_t). Tolerance 1e-12."""
    base = two_clearance_robot(law, kind)
    model = compiled(base)
    robot = jointplay.with_parameters(base, {"friction.mu": 0.3, "friction.v0": 1e-4,
                                             "friction.v1": 1e-2})
    p = pvec(robot)
    v0, v1 = 1e-4, 1e-2
    delta, angle = 2e-6, -0.7
    n_vec = unit(angle)
    t_vec = np.array([-n_vec[1], n_vec[0]])
    stiffness = joint_stiffness(robot, 1)
    checked_full = False
    for speed in (0.5 * v0, v0 + 0.1 * (v1 - v0), v0 + 0.5 * (v1 - v0), v0 + 0.8 * (v1 - v0),
                  3.0 * v1):
        for sign in (1.0, -1.0):
            x = contact_state(robot, model, 1, delta, angle, tangential_speed=sign * speed)
            contact = model.contact(x, p, np.array([0.1, 0.1]))
            assert contact["v_t"][0] == pytest.approx(sign * speed, rel=1e-12)
            assert abs(contact["delta_dot"][0]) <= 1e-16
            f_n = contact["f_n"][0]
            assert f_n == pytest.approx(stiffness * contact["delta"][0] ** 1.5, rel=1e-12)
            c_d = ramp(kind, speed, v0, v1)
            f_t = -0.3 * c_d * f_n * sign
            assert contact["f_t"][0] == pytest.approx(f_t, rel=1e-12, abs=1e-14 * f_n)
            if c_d > 0:
                assert np.sign(contact["f_t"][0]) == -sign  # opposes sliding, both ways
            checked_full |= c_d == 1.0
            assert_rel(np.r_[contact["f_x"][0], contact["f_y"][0]], -f_n * n_vec + f_t * t_vec,
                       1e-12, "total contact force")
    assert checked_full


@pytest.mark.parametrize("kind", ["linear", "smooth"])
def test_friction_ramp_from_zero_speed(compiled: Callable[[Robot], Model], kind: str) -> None:
    """v0 = 0 (the correction ramps from zero speed) is accepted and stays finite: the
    direction floor is then v1/1000, so f_t = -mu c_d f_n v_t / max(|v_t|, v1/1000), exact
    (= -mu c_d f_n sign(v_t)) above the floor, within 1e-3 mu f_n below it. At v_t = 0 in
    contact every output and every Jacobian block is finite, and the slope d f_t / d v_t
    (central differences on a grid through 0) stays below 2 mu f_n / v1. Tolerance 1e-12."""
    base = two_clearance_robot("lankarani-nikravesh", kind)
    model = compiled(base)
    mu, v1 = 0.3, 1e-2
    robot = jointplay.with_parameters(base, {"friction.mu": mu, "friction.v0": 0.0,
                                             "friction.v1": v1})
    assert robot.friction.v0 == 0.0
    p = pvec(robot)
    floor = 1e-3 * v1
    delta, angle = 2e-6, 0.9
    stiffness = joint_stiffness(robot, 1)
    for speed in (0.0, 1e-9, 0.3 * floor, floor, 2.0 * floor, 0.5 * v1, 3.0 * v1):
        for sign in (1.0, -1.0):
            x = contact_state(robot, model, 1, delta, angle, tangential_speed=sign * speed)
            contact = model.contact(x, p, np.array([0.1, 0.1]))
            f_n = contact["f_n"][0]
            assert f_n == pytest.approx(stiffness * contact["delta"][0] ** 1.5, rel=1e-12)
            c_d = ramp(kind, speed, 0.0, v1)
            f_t = -mu * c_d * f_n * sign * speed / max(speed, floor)
            assert contact["f_t"][0] == pytest.approx(f_t, rel=1e-12, abs=1e-14 * f_n)
            assert abs(contact["f_t"][0] + mu * c_d * f_n * np.sign(sign * speed)) \
                <= 1e-3 * mu * f_n * (1 + 1e-12)
            if speed >= floor:
                assert contact["f_t"][0] == pytest.approx(-mu * c_d * f_n * sign, rel=1e-12)
    # Finite at v_t = 0 in contact, values and derivatives, with the impact speed floored.
    rng = np.random.default_rng(3200)
    tau = rng.uniform(-1.0, 1.0, 2)
    failures = []
    for name, x in singular_states(robot, rng).items():
        for v_imp in (np.zeros(2), np.array([0.1, 0.3])):
            bad = non_finite_report(model, all_outputs(model, x, tau, p, v_imp))
            if bad:
                failures.append(f"{name}, v_imp={v_imp}: " + "; ".join(bad))
    assert not failures, "\n".join(failures)
    # No new stiffness: the slope through v_t = 0 stays within the ramp's own 2 mu f_n / v1.
    speeds = np.linspace(-3.0 * floor, 3.0 * floor, 61)
    h = 1e-3 * floor
    for v in speeds:
        ends = [model.contact(contact_state(robot, model, 1, delta, angle,
                                            tangential_speed=v + d), p)["f_t"][0]
                for d in (-h, h)]
        f_n = model.contact(contact_state(robot, model, 1, delta, angle,
                                          tangential_speed=v), p)["f_n"][0]
        assert abs(ends[1] - ends[0]) / (2 * h) <= 2.0 * mu * f_n / v1 * (1 + 1e-6), v


def test_friction_none_gives_no_tangential_force(compiled: Callable[[Robot], Model]) -> None:
    robot = two_clearance_robot("lankarani-nikravesh", "none")
    model = compiled(robot)
    p = pvec(robot)
    for speed in (-1.0, -1e-3, 0.0, 1e-3, 1.0):
        x = contact_state(robot, model, 1, 2e-6, 0.5, tangential_speed=speed)
        contact = model.contact(x, p)
        assert contact["f_n"][0] > 0 and contact["f_t"][0] == 0.0


@pytest.mark.parametrize("law", LAWS)
def test_contact_kinematics(compiled: Callable[[Robot], Model], law: str) -> None:
    """delta_dot = n.e' and v_t = t.e' + w_journal Rj - w_bearing Rb (contact-point velocities),
    with the bearing on moving link 1 (joint 2). Tolerance 1e-12."""
    robot = two_clearance_robot(law, "linear")
    model = compiled(robot)
    p = pvec(robot)
    rng = np.random.default_rng(5100)
    rb, rj = robot.joints[1].bearing_radius, robot.joints[1].journal_radius
    for _ in range(5):
        angle = rng.uniform(0, 2 * math.pi)
        x = contact_state(robot, model, 2, rng.uniform(1e-7, 5e-6), angle)
        x[6:8] = rng.uniform(-3.0, 3.0, 2)  # u1, u2
        e_dot = rng.uniform(-0.05, 0.05, 2)
        x[10:12] = e_dot
        n_vec = unit(angle)
        t_vec = np.array([-n_vec[1], n_vec[0]])
        w_bearing, w_journal = x[6], x[6] + x[7]
        contact = model.contact(x, p)
        assert contact["delta_dot"][1] == pytest.approx(n_vec @ e_dot, rel=1e-12)
        v_t = t_vec @ e_dot + w_journal * rj - w_bearing * rb
        assert contact["v_t"][1] == pytest.approx(v_t, rel=1e-12)


@pytest.mark.parametrize("joint", [1, 2])
def test_contact_forces_enter_the_equations(compiled: Callable[[Robot], Model],
                                            joint: int) -> None:
    """Generalised forces at zero gravity, angles not rotating, one joint sliding in contact:
    the contact force enters the eccentricity rows of its joint, the friction moments Rj F_t
    (journal link) and -Rb F_t (bearing link) enter the angle rows, drive torques enter their
    own angle rows (relative angles). Joint 1: f = tau + [Rj F_t, 0, F_x, F_y, 0, 0];
    joint 2: f = tau + [(Rj - Rb) F_t, Rj F_t, 0, 0, F_x, F_y]. Tolerance 1e-12."""
    base = two_clearance_robot("hunt-crossley", "linear")
    model = compiled(base)
    robot = jointplay.with_parameters(base, {"gravity.x": 0.0, "gravity.y": 0.0,
                                             "friction.mu": 0.2})
    p = pvec(robot)
    rb, rj = robot.joints[joint - 1].bearing_radius, robot.joints[joint - 1].journal_radius
    tau = np.array([1.3, -0.6])
    x = contact_state(robot, model, joint, 3e-6, 2.1, normal_speed=0.01, tangential_speed=0.05)
    contact = model.contact(x, p, np.array([0.1, 0.1]))
    j = joint - 1
    f_x, f_y, f_t = contact["f_x"][j], contact["f_y"][j], contact["f_t"][j]
    assert contact["f_n"][j] > 0 and f_t != 0 and contact["f_n"][1 - j] == 0
    expected = np.r_[tau, 0.0, 0.0, 0.0, 0.0]
    if joint == 1:
        expected += [rj * f_t, 0.0, f_x, f_y, 0.0, 0.0]
    else:
        expected += [(rj - rb) * f_t, rj * f_t, 0.0, 0.0, f_x, f_y]
    assert_rel(model.forcing(x, tau, p, np.array([0.1, 0.1])), expected, 1e-12, "forcing")


ENERGY_KINDS = [["ideal"] * 3, ["clearance", "clearance"], ["ideal", "clearance", "clearance"],
                ["ideal", "locked", "ideal"]]


@pytest.mark.parametrize("kinds", ENERGY_KINDS, ids=lambda ks: "-".join(ks))
def test_energy_and_end_effector(compiled: Callable[[Robot], Model], kinds: list[str]) -> None:
    """kinetic = 0.5 u^T M u = sum of body energies (numpy kinematics); gravity potential =
    -sum m g.r; contact = sum K d+^(n+1)/(n+1); total = the sum; end-effector position,
    velocity and acceleration = numpy kinematics. Tolerance 1e-12."""
    rng = np.random.default_rng(5300 + len(kinds))
    for _ in range(4):
        robot = random_robot(rng, kinds)
        model = compiled(robot)
        p = pvec(robot)
        n = model.n_coordinates
        nq = len(robot.moving_joints)
        q = np.r_[rng.uniform(-math.pi, math.pi, nq), np.zeros(n - nq)]
        idx = index(model)
        for i in robot.clearance_joints:  # penetrating by up to 3 um, or not
            e = (clearance(robot, i) + rng.uniform(-3e-6, 3e-6)) * unit(rng.uniform(0, 7))
            q[[idx[f"ex{i}"], idx[f"ey{i}"]]] = e
        u = np.r_[rng.uniform(-3.0, 3.0, nq), rng.uniform(-0.05, 0.05, n - nq)]
        x = np.r_[q, u]
        energy = model.energy(x, p)
        kin = chain_kinematics(robot, model, x)
        kinetic = 0.5 * robot.payload_mass * kin["tip_vel"] @ kin["tip_vel"]
        g = np.array(robot.gravity.vector)
        potential = -robot.payload_mass * g @ kin["tip"]
        for link, v, w, r in zip(robot.links, kin["com_vel"], kin["omega"], kin["com"],
                                 strict=True):
            kinetic += 0.5 * link.mass * v @ v + 0.5 * link.inertia * w**2
            potential -= link.mass * g @ r
        assert energy["kinetic"] == pytest.approx(0.5 * u @ mass_of(model, q, p) @ u,
                                                  rel=1e-12)
        assert energy["kinetic"] == pytest.approx(kinetic, rel=1e-12)
        assert energy["gravity"] == pytest.approx(potential, rel=1e-12, abs=1e-12)
        contact_energy = 0.0
        if robot.clearance_joints:
            n_exp = robot.contact.exponent
            deltas = model.contact(x, p)["delta"]
            for i, d in zip(robot.clearance_joints, deltas, strict=True):
                contact_energy += joint_stiffness(robot, i) * max(d, 0.0) ** (n_exp + 1) / (
                    n_exp + 1)
        assert energy["contact"] == pytest.approx(contact_energy, rel=1e-12, abs=1e-300)
        assert energy["total"] == pytest.approx(
            energy["kinetic"] + energy["gravity"] + energy["contact"], rel=1e-12, abs=1e-12)
        udot = rng.uniform(-10.0, 10.0, n)
        kin = chain_kinematics(robot, model, x, udot)
        tip = model.end_effector(x, udot, p)
        assert_rel(tip["position"], kin["tip"], 1e-12, "tip position")
        assert_rel(tip["velocity"], kin["tip_vel"], 1e-12, "tip velocity")
        assert_rel(tip["acceleration"], kin["tip_acc"], 1e-12, "tip acceleration")
