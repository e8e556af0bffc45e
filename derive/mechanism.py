"""Derive and emit a mechanism's model: a tree of bodies with cut clearance joints.

The kinematics are written body by body from the ground out, as CasADi SX in the tree's
coordinates z = (q, clock): each body's angle and origin, its centre of mass and its joint
points. The equations of motion are d'Alembert's principle projected on the coordinates
(Kane's equations with generalised speeds u = dq/dt):

    sum_b  J_b^T (m_b a_b - F_b) + J_phi,b^T (I_b alpha_b - M_b) = 0,

M(q) q'' = Q - bias, with J_b = d r_b / d q, the accelerations split into J_b q'' and the
rest. Each cut clearance joint is a force element: its eccentricity e = journal centre
(child's point) - bearing centre (parent's point), its laws exactly those of the serial
arms' joints (:func:`jointplay.derive.laws.contact_terms`: Hertz's pin-in-hole stiffness,
Lankarani-Nikravesh or another damping law, the modified Coulomb friction), the force on the
journal and its reaction on the bearing, friction's moments Rj Ft and -Rb Ft.

The driver's angle theta(t) enters through the clock coordinate; the driving torque is the
driven joint's row of the same principle, d r / d theta in place of d r / d q, with the
accelerations computed: an output, not an input. Nothing is solved in sympy; the laws are
sympy expressions converted once (:class:`SympyToCasadi`).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Any, cast

import casadi as ca
import sympy as sp

from jointplay.derive import laws
from jointplay.derive.fixed_step import RADAU_NEWTON_ITERATIONS, fixed_step_functions
from jointplay.derive.to_casadi import SympyToCasadi
from jointplay.mechanism.structure import (
    MechanismStructure,
    coordinates,
    parameter_names,
)

CONTACT_OUTPUTS = ("delta", "delta_dot", "v_t", "f_n", "f_t", "f_x", "f_y", "dissipation")


@dataclass
class _Frame:
    angle: Any  # SX
    origin: Any  # SX 2-vector

    def point(self, local: Any) -> Any:
        c, s = ca.cos(self.angle), ca.sin(self.angle)
        return self.origin + ca.vertcat(c * local[0] - s * local[1], s * local[0] + c * local[1])


@dataclass
class _Equations:
    x: Any
    tau: Any
    p: Any
    v_imp: Any
    accelerations: Any  # q'' (n), clock included (0)
    driving_torque: Any  # scalar (0 without a driver)
    driver_rate: Any
    load_power: Any  # the applied loads' power (W)
    kinetic: Any
    potential: Any
    contact_potential: Any
    contact: dict[str, Any]
    gaps: list[Any]  # delta, rate, ex, ey (nc each)
    closure: Any  # e of the cut joints (2 nc)
    closure_bias: Any  # gamma: e'' = J_q q'' + gamma
    closure_jacobian: Any  # d e / d q (2 nc x n)
    closure_theta: Any  # d e / d theta (2 nc)
    ideal_residual: Any  # (R_q, R_theta) at given accelerations, without contact
    acc_input: Any
    points: Any  # every body's origin (2 per body) and angle


def derive(structure: MechanismStructure) -> _Equations:
    coords = coordinates(structure)
    n = len(coords)
    names = parameter_names(structure)
    q = ca.SX.sym("q", n)
    u = ca.SX.sym("u", n)
    x = ca.vertcat(q, u)
    tau = ca.SX.sym("tau", len(structure.load_inputs))
    p = ca.SX.sym("p", len(names))
    ncut = len(structure.cut_joints)
    v_imp = ca.SX.sym("v_imp", ncut)

    def P(name: str) -> Any:
        return p[names.index(name)]

    index: dict[str, int] = {}  # each joint's first coordinate
    for i, c in enumerate(coords):
        if c.joint is not None:
            index.setdefault(c.joint, i)
    # The kinematics take the driven angle as its own symbol th (with rates thd, thdd); it is
    # replaced by theta(clock) at the end.
    th, thd, thdd = ca.SX.sym("th"), ca.SX.sym("thd"), ca.SX.sym("thdd")
    frames: dict[str, _Frame] = {"ground": _Frame(ca.SX(0), ca.SX.zeros(2))}
    for joint in structure.tree_joints:
        parent = frames[joint.parent]
        j = joint.name
        if joint.type == "floating":  # a body held by clearance joints only: x, y, angle
            k = index[j]
            frames[joint.child] = _Frame(q[k + 2], ca.vertcat(q[k], q[k + 1]))
            continue
        at_parent = ca.vertcat(P(f"{j}.parent_x"), P(f"{j}.parent_y"))
        at_child = ca.vertcat(P(f"{j}.child_x"), P(f"{j}.child_y"))
        if joint.type == "prismatic":
            axis = ca.vertcat(P(f"{j}.axis_x"), P(f"{j}.axis_y"))
            angle = parent.angle + P(f"{j}.angle")
            pin = parent.point(at_parent + q[index[j]] * axis)
        else:
            relative = th if joint.driven else (
                P(f"{j}.angle") if joint.kind == "locked" else q[index[j]])
            angle = parent.angle + relative
            pin = parent.point(at_parent)
        child = _Frame(angle, ca.SX.zeros(2))
        child.origin = pin - child.point(at_child)
        frames[joint.child] = child
    qf, uf = q[:n - 1], u[:n - 1]
    z, zd = ca.vertcat(qf, th), ca.vertcat(uf, thd)

    def velocity(r: Any) -> Any:
        return ca.jtimes(r, z, zd)

    def bias(r: Any) -> Any:
        """The acceleration of r without its q'' part: d/dt (J z') - J_q q''."""
        return ca.jtimes(velocity(r), z, zd) + ca.jacobian(r, th) * thdd

    gravity = ca.vertcat(P("gravity.x"), P("gravity.y")) if structure.gravity else None
    contact, gaps, applied, contact_potential = _cut_joints(structure, frames, z, zd, v_imp,
                                                             p, names)
    mass_matrix = ca.SX.zeros(n - 1, n - 1)
    forcing = ca.SX.zeros(n - 1)  # inertial bias and gravity
    contact_forcing = ca.SX.zeros(n - 1)
    kinetic, potential = ca.SX(0), ca.SX(0)
    acc_in = ca.SX.sym("a", n)
    driving_parts = []
    for body in structure.bodies:
        frame = frames[body]
        com = frame.point(ca.vertcat(P(f"{body}.com_x"), P(f"{body}.com_y")))
        m, inertia = P(f"{body}.mass"), P(f"{body}.inertia")
        J, Jphi = ca.jacobian(com, qf), ca.jacobian(frame.angle, qf)
        v, omega = velocity(com), velocity(frame.angle)
        b_com, b_phi = bias(com), bias(frame.angle)
        mass_matrix += m * (J.T @ J) + inertia * (Jphi.T @ Jphi)
        forcing -= m * (J.T @ b_com) + inertia * (Jphi.T @ b_phi)
        kinetic += 0.5 * m * ca.dot(v, v) + 0.5 * inertia * omega**2
        if gravity is not None:
            forcing += J.T @ (m * gravity)
            potential -= m * ca.dot(gravity, com)
        # The driven joint's row: d r / d theta against the inertial and applied forces.
        dr, dphi = ca.jacobian(com, th), ca.jacobian(frame.angle, th)
        driving_parts.append((dr, dphi, m, inertia, J, Jphi, b_com, b_phi))
    for point, force in applied["forces"]:
        contact_forcing += ca.jacobian(point, qf).T @ force
    for angle, moment in applied["moments"]:
        contact_forcing += ca.jacobian(angle, qf).T * moment
    # Applied loads (the input tau): torques across revolute joints, forces at points.
    loads = _loads(structure, frames, tau, P)
    for point, force in loads["forces"]:
        forcing += ca.jacobian(point, qf).T @ force
    for angle, moment in loads["moments"]:
        forcing += ca.jacobian(angle, qf).T * moment
    load_power = sum((ca.dot(velocity(point), force) for point, force in loads["forces"]),
                     ca.SX(0))
    load_power += sum((velocity(angle) * moment for angle, moment in loads["moments"]),
                      ca.SX(0))
    acc_free = ca.solve(mass_matrix, forcing + contact_forcing)

    def driver_row(acc: Any, with_contact: bool) -> Any:
        row = ca.SX(0)
        for dr, dphi, m, inertia, J, Jphi, b_com, b_phi in driving_parts:
            a, alpha = J @ acc + b_com, Jphi @ acc + b_phi
            row += m * ca.dot(dr, a) + inertia * dphi * alpha
            if gravity is not None:
                row -= m * ca.dot(dr, gravity)
        for point, force in loads["forces"]:
            row -= ca.dot(ca.jacobian(point, th), force)
        for angle, moment in loads["moments"]:
            row -= ca.jacobian(angle, th) * moment
        if with_contact:
            for point, force in applied["forces"]:
                row -= ca.dot(ca.jacobian(point, th), force)
            for angle, moment in applied["moments"]:
                row -= ca.jacobian(angle, th) * moment
        return row

    driving = driver_row(acc_free, True)
    ideal_theta = driver_row(acc_in[:n - 1], False)
    ideal_q = mass_matrix @ acc_in[:n - 1] - forcing
    closure = ca.vertcat(*applied["e"]) if ncut else ca.SX(0, 1)
    e_jac = ca.jacobian(closure, qf) if ncut else ca.SX(0, n - 1)
    e_theta = ca.jacobian(closure, th) if ncut else ca.SX(0, 1)
    gamma = bias(closure) if ncut else ca.SX(0, 1)
    points = ca.vertcat(*[ca.vertcat(frames[b].origin, frames[b].angle)
                          for b in structure.bodies])
    # theta(clock) and its rates through the clock (whose rate u_t is 1).
    clock, clock_rate = q[n - 1], u[n - 1]
    if structure.driver is None:
        theta = ca.SX(0)
    elif structure.driver_angle is None:
        theta = P("driver.start") + P("driver.speed") * clock
    else:
        from jointplay.scene.expressions import parse_expression

        theta = parse_expression(structure.driver_angle,
                                 field="mechanism.driver.angle").casadi(clock)
    d1 = ca.jacobian(theta, clock)
    d2 = ca.jacobian(d1, clock)
    rates = ca.densify(ca.vertcat(theta, d1 * clock_rate, d2 * clock_rate**2))

    def bind(expr: Any) -> Any:
        return ca.substitute(expr, ca.vertcat(th, thd, thdd), rates)

    acc = ca.vertcat(acc_free, ca.SX(0))
    return _Equations(x=x, tau=tau, p=p, v_imp=v_imp, accelerations=bind(acc),
                      driving_torque=bind(driving), driver_rate=bind(thd),
                      load_power=bind(load_power),
                      kinetic=bind(kinetic), potential=bind(potential),
                      contact_potential=bind(contact_potential),
                      contact={k: bind(v) for k, v in contact.items()},
                      gaps=[bind(g) for g in gaps], closure=bind(closure),
                      closure_bias=bind(gamma), closure_jacobian=bind(e_jac),
                      closure_theta=bind(e_theta),
                      ideal_residual=bind(ca.vertcat(ideal_q, ideal_theta)),
                      acc_input=acc_in, points=bind(points))


def _loads(structure: MechanismStructure, frames: dict[str, _Frame], tau: Any,
           P: Any) -> dict[str, list[Any]]:
    """The applied torques (on a joint's child, the reaction on its parent) and forces (at a
    body's point), from the input tau in the order of ``structure.load_inputs``."""
    loads: dict[str, list[Any]] = {"forces": [], "moments": []}
    joints = {j.name: j for j in structure.joints}
    k = 0
    for name in structure.torque_joints:
        joint = joints[name]
        loads["moments"] += [(frames[joint.child].angle, tau[k]),
                             (frames[joint.parent].angle, -tau[k])]
        k += 1
    for name, body in structure.forces:
        point = frames[body].point(ca.vertcat(P(f"{name}.at_x"), P(f"{name}.at_y")))
        loads["forces"].append((point, ca.vertcat(tau[k], tau[k + 1])))
        k += 2
    return loads


def _cut_joints(structure: MechanismStructure, frames: dict[str, _Frame], q: Any, qd: Any,
                v_imp: Any, p: Any, names: list[str]
                ) -> tuple[dict[str, Any], list[Any], dict[str, Any], Any]:
    """Each cut clearance joint's eccentricity, laws, force and moments."""
    outputs: dict[str, list[Any]] = {k: [] for k in CONTACT_OUTPUTS}
    deltas, rates, exs, eys = [], [], [], []
    applied: dict[str, Any] = {"forces": [], "moments": [], "e": []}
    potential = ca.SX(0)
    symbols = {name: sp.Symbol(name.replace(".", "__"), real=True) for name in names}
    for k, joint in enumerate(structure.cut_joints, start=1):
        j = joint.name
        bearing_frame, journal_frame = frames[joint.parent], frames[joint.child]

        def P(name: str, j: str = j) -> sp.Symbol:
            owner, _, key = name.partition(".")
            return symbols[f"{j}.{key}" if owner.startswith("joint") else name]

        bearing = bearing_frame.point(ca.vertcat(p[names.index(f"{j}.parent_x")],
                                                 p[names.index(f"{j}.parent_y")]))
        journal = journal_frame.point(ca.vertcat(p[names.index(f"{j}.child_x")],
                                                 p[names.index(f"{j}.child_y")]))
        e = journal - bearing
        e_rate = ca.jtimes(e, q, qd)
        w_b = ca.jtimes(bearing_frame.angle, q, qd)
        w_j = ca.jtimes(journal_frame.angle, q, qd)
        ex, ey, vx, vy, wb, wj, vi = sp.symbols("e_x e_y v_x v_y w_b w_j v_i", real=True)
        terms = laws.contact_terms(cast(Any, structure), k, ex, ey, vx, vy, wb, wj, vi, P)
        leaves = {ex: e[0], ey: e[1], vx: e_rate[0], vy: e_rate[1], wb: w_b, wj: w_j,
                  vi: v_imp[k - 1]}
        leaves |= {symbols[name]: p[i] for i, name in enumerate(names)}
        convert = SympyToCasadi(leaves)
        fx, fy, ft = (convert(terms.force_x), convert(terms.force_y),
                      convert(terms.friction_force))
        for key, expr in zip(CONTACT_OUTPUTS, (terms.penetration, terms.penetration_rate,
                                               terms.sliding_speed, terms.normal_force,
                                               terms.friction_force, terms.force_x,
                                               terms.force_y, terms.dissipation), strict=True):
            outputs[key].append(convert(expr))
        deltas.append(convert(terms.penetration))
        rates.append(convert(terms.penetration_rate))
        exs.append(e[0])
        eys.append(e[1])
        force = ca.vertcat(fx, fy)
        rb, rj = convert(P("joint.bearing_radius")), convert(P("joint.journal_radius"))
        applied["forces"] += [(journal, force), (bearing, -force)]
        applied["moments"] += [(journal_frame.angle, rj * ft), (bearing_frame.angle, -rb * ft)]
        applied["e"].append(e)
        potential += convert(terms.potential)
    contact = {k: ca.vertcat(*v) if v else ca.SX(0, 1) for k, v in outputs.items()}
    stack = [ca.vertcat(*g) if g else ca.SX(0, 1) for g in (deltas, rates, exs, eys)]
    return contact, stack, applied, potential


def functions(structure: MechanismStructure) -> list[ca.Function]:
    """The compiled functions, named and with the slots the simulator calls."""
    eq = derive(structure)
    x, tau, p, v = eq.x, eq.tau, eq.p, eq.v_imp
    n = x.shape[0] // 2
    xdot = ca.vertcat(x[n:], eq.accelerations)
    opts = {"cse": True}
    fd = ca.Function("forward_dynamics", [x, tau, p, v], [xdot],
                     ["x", "tau", "p", "v_imp"], ["xdot"], opts)
    jac = ca.Function("jac_forward_dynamics", [x, tau, p, v], [ca.jacobian(xdot, x)],
                      ["x", "tau", "p", "v_imp"], ["jac_x"], opts)
    contact = ca.Function("contact", [x, p, v],
                          [ca.densify(eq.contact[k]) for k in CONTACT_OUTPUTS],
                          ["x", "p", "v_imp"], list(CONTACT_OUTPUTS), opts)
    gaps = ca.Function("gaps", [x, p], [ca.densify(g) for g in eq.gaps], ["x", "p"],
                       ["delta", "rate", "ex", "ey"], opts)
    power = ca.Function("drive_power", [x, tau, p, v],
                        [ca.densify(eq.driving_torque * eq.driver_rate + eq.load_power)],
                        ["x", "tau", "p", "v_imp"], ["power"], opts)
    # Dense outputs: a structural zero (no driver, no contact) is still a value per sample.
    outputs = ca.Function("outputs", [x, tau, p, v],
                          [ca.densify(e) for e in (
                              eq.driving_torque, eq.driver_rate, eq.kinetic, eq.potential,
                              eq.contact_potential, eq.accelerations, eq.points)],
                          ["x", "tau", "p", "v_imp"],
                          ["driving_torque", "driver_rate", "kinetic", "potential",
                           "contact_potential", "acceleration", "points"], opts)
    closure = ca.Function("closure", [x, p],
                          [eq.closure, eq.closure_jacobian, eq.closure_theta,
                           eq.closure_bias],
                          ["x", "p"], ["e", "e_q", "e_theta", "gamma"], opts)
    ideal = ca.Function("ideal_residual", [x, eq.acc_input, tau, p], [eq.ideal_residual],
                        ["x", "a", "tau", "p"], ["residual"], opts)
    # The fixed-step methods (run.integrator = "rk4" or "radau"), as for the serial arms; the
    # runtime reads Radau's Newton iteration count (its cost per step) from the library.
    rk4, radau = fixed_step_functions(fd, jac)
    iterations = ca.Function("radau_newton_iterations", [], [ca.DM(RADAU_NEWTON_ITERATIONS)],
                             [], ["iterations"])
    return [fd, jac, contact, gaps, power, outputs, closure, ideal, rk4, radau, iterations]


GENERATOR_FILES = ("mechanism.py", "laws.py", "to_casadi.py", "fixed_step.py")


def generator_version() -> str:
    from pathlib import Path

    h = hashlib.sha256()
    for name in GENERATOR_FILES:
        h.update((Path(__file__).parent / name).read_bytes())
    return h.hexdigest()[:12]


def emit(structure: MechanismStructure, name: str, input_hash: str) -> str:
    """The C source of a mechanism's model, stamped."""
    from importlib.metadata import version

    gen = ca.CodeGenerator("model.c", {"with_header": False, "verbose": False,
                                       "casadi_int": "long long int"})
    for fn in functions(structure):
        gen.add(fn)
    body = gen.dump()
    return ("/* GENERATED FILE: DO NOT EDIT.\n"
            f" * mechanism: {name}\n"
            f" * generator: jointplay.derive.mechanism {generator_version()}, casadi "
            f"{version('casadi')}, sympy {version('sympy')}\n"
            f" * input hash: {input_hash}\n"
            " * Regenerated on demand into the build cache from the mechanism's structure.\n"
            " */\n" + body)
