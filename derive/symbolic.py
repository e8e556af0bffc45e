"""Equations of motion of a planar serial chain with clearance joints, by Kane's method.

Formulation (chosen for derivation speed and for readable equations):

* Generalised coordinates: the relative angle q_i of every joint that moves, then the
  eccentricity (ex_i, ey_i) of every clearance joint, expressed in the inertial frame N (as in
  Flores and Ambrosio's clearance-joint papers). Speeds are u = dq/dt, so M(q) du/dt = f.
* Every link frame is oriented directly from N by its absolute angle theta_i (a sum of
  relative angles and locked offsets), and point positions and velocities are written in N
  components. Chaining frames link to link makes sympy multiply direction-cosine matrices,
  which grows the expressions several-fold and slows Kane's method by ~2.5x at 8 links.
* Contact enters the equations as placeholder symbols per clearance joint: the force (Fx, Fy)
  on the journal (N components) and the friction force Ft. The contact and friction laws are
  separate expressions (see :mod:`jointplay.derive.laws`), substituted when the C is emitted.
  This keeps the mass matrix and forcing small and readable, and lets the same equations serve
  every contact law. The normal force acts along the line of centres, so it has no moment
  about either joint centre; friction acts at the contact points and gives the moments
  Rj Ft on the journal's link and -Rb Ft on the bearing's link.
* Nothing is solved symbolically: the linear solve for the accelerations and all Jacobians are
  done by CasADi (see :mod:`jointplay.derive.codegen`). Differentiating solved accelerations in
  sympy is what makes naive derivations take minutes at 12 links.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import sympy as sp
from sympy.physics import mechanics as me

from jointplay.derive import laws
from jointplay.robot.structure import (
    Coordinate,
    Parameter,
    Structure,
    coordinate_layout,
    parameter_layout,
)


@dataclass
class ClearanceJointTerms:
    """Symbols and law expressions of one clearance joint (index is the 1-based joint)."""

    index: int
    force_x: sp.Symbol  # placeholder: contact force on the journal, N x component
    force_y: sp.Symbol
    force_t: sp.Symbol  # placeholder: friction force on the journal, along the tangent
    impact_speed: sp.Symbol  # input: normal approach speed captured at the onset of contact
    law: laws.ContactTerms
    # Absolute angles of the bearing's link (i-1, 0 for the ground) and the journal's link (i).
    angles: tuple[sp.Expr, sp.Expr] = (sp.Integer(0), sp.Integer(0))
    speeds: tuple[sp.Expr, sp.Expr] = (sp.Integer(0), sp.Integer(0))  # their rates


@dataclass
class SymbolicModel:
    structure: Structure
    coordinates: list[Coordinate]
    q: list[sp.Expr]  # dynamic symbols q(t)
    u: list[sp.Expr]  # dynamic symbols u(t) = dq/dt
    parameters: list[Parameter]
    parameter_symbols: list[sp.Symbol]
    torques: list[sp.Symbol]  # one per moving joint, empty if the drive is off
    torque_joints: list[int]
    clearance: list[ClearanceJointTerms]
    # Kane's closed form; None for the recursive formulation, which builds these from the
    # chain itself (see jointplay.derive.recursive).
    mass_matrix: sp.Matrix | None
    forcing: sp.Matrix | None  # M du/dt = forcing; contact enters via the placeholder symbols
    kinetic_energy: sp.Expr | None
    gravity_potential: sp.Expr | None
    tip_position: sp.Matrix | None  # 2 x 1, end of the last link (where the payload sits)
    timings: dict[str, float] = field(default_factory=dict)
    formulation: str = "closed"
    template: JointTemplate | None = None  # the recursive formulation's generic joint laws

    @property
    def n_coordinates(self) -> int:
        return len(self.q)

    @property
    def contact_potential(self) -> sp.Expr:
        return sp.Add(*[c.law.potential for c in self.clearance])


# Joint kinds whose relative angle is a coordinate, and those with an eccentricity (ex, ey).
_MOVING = ("ideal", "clearance")
_ECCENTRIC = ("clearance", "locked_clearance")


@dataclass(frozen=True)
class _Coordinates:
    """The dynamic symbols: every moving joint's angle and rate, every clearance joint's
    eccentricity and its rate (by 1-based joint), and q, u in slot order."""

    angles: list[Any]
    angle_speeds: list[Any]
    eccentricity: dict[int, tuple[Any, Any, Any, Any]]  # joint -> (ex, ey, vx, vy)
    q: list[Any]
    u: list[Any]


@dataclass
class _Chain:
    """What walking the chain from the ground to the tip collects for Kane's method."""

    frame: Any  # the inertial frame N
    origin: Any
    gravity: Any  # the gravity vector, or None when the structure has no gravity
    bodies: list[Any] = field(default_factory=list)
    loads: list[tuple[Any, Any]] = field(default_factory=list)
    clearance: list[ClearanceJointTerms] = field(default_factory=list)
    torques: list[sp.Symbol] = field(default_factory=list)
    torque_joints: list[int] = field(default_factory=list)
    gravity_potential: sp.Expr = sp.S.Zero
    tip: Any = None  # the end point of the last link, where the payload sits


@dataclass(frozen=True)
class _Link:
    """One link's frame and its absolute angle and rate, with those of the link before it
    (the bearing's: the ground's for the first link)."""

    index: int
    frame: Any
    theta: sp.Expr
    omega: sp.Expr
    theta_bearing: sp.Expr
    omega_bearing: sp.Expr


def derive(structure: Structure, formulation: str = "closed") -> SymbolicModel:
    """Derive the equations of motion for a robot structure (see ``Robot.structure()``).

    ``formulation`` is where the emitted dynamics come from (see
    :data:`jointplay.derive.codegen.FORMULATIONS`)."""
    t0 = time.perf_counter()
    params = parameter_layout(structure)
    psym = {p.name: sp.Symbol(p.symbol, real=True) for p in params}

    def P(name: str) -> sp.Symbol:
        return psym[name]

    coordinates = _coordinates(list(structure.joints))
    if formulation == "recursive":
        return _joint_laws_only(structure, coordinates, params, psym, t0)
    chain = _walk_chain(structure, coordinates, P)
    t1 = time.perf_counter()

    kd = [qi.diff(me.dynamicsymbols._t) - ui
          for qi, ui in zip(coordinates.q, coordinates.u, strict=True)]
    kane = me.KanesMethod(chain.frame, q_ind=coordinates.q, u_ind=coordinates.u, kd_eqs=kd)
    kane.kanes_equations(chain.bodies, chain.loads)
    t2 = time.perf_counter()

    # Kinetic energy straight from the bodies (not from M), so an energy check is independent.
    kinetic = me.kinetic_energy(chain.frame, *chain.bodies)
    tip = chain.tip.pos_from(chain.origin)
    tip_position = sp.Matrix([tip.dot(chain.frame.x), tip.dot(chain.frame.y)])
    t3 = time.perf_counter()

    return SymbolicModel(
        structure=structure,
        coordinates=coordinate_layout(structure),
        q=coordinates.q,
        u=coordinates.u,
        parameters=params,
        parameter_symbols=[psym[p.name] for p in params],
        torques=chain.torques,
        torque_joints=chain.torque_joints,
        clearance=chain.clearance,
        mass_matrix=kane.mass_matrix,
        forcing=kane.forcing,
        kinetic_energy=kinetic,
        gravity_potential=chain.gravity_potential,
        tip_position=tip_position,
        timings={"kinematics": t1 - t0, "kane": t2 - t1, "energy": t3 - t2},
        formulation="closed",
    )


@dataclass(frozen=True)
class JointTemplate:
    """One clearance joint's laws, derived once with generic symbols for the recursive
    formulation: its eccentricity and rates, its links' absolute angles and rates (bearing's,
    journal's), the captured impact speed, and its own parameters (``joint_parameters``, by
    attribute). ``parameter`` maps a parameter name to its symbol, ``joint0.<attribute>``
    standing for the joint's own. The emitter binds these per joint."""

    law: laws.ContactTerms
    eccentricity: tuple[sp.Symbol, sp.Symbol, sp.Symbol, sp.Symbol]  # ex, ey, vx, vy
    angles: tuple[sp.Symbol, sp.Symbol]
    speeds: tuple[sp.Symbol, sp.Symbol]
    impact_speed: sp.Symbol
    joint_parameters: dict[str, sp.Symbol]
    parameter: Callable[[str], sp.Symbol]


def _joint_template(structure: Structure, psym: dict[str, sp.Symbol]) -> JointTemplate:
    """The laws of a generic clearance joint (every joint's are this one's, rebound): sympy's
    Max/Min canonicalisation costs about a second per law, so a law is built once, not once
    per joint."""
    own: dict[str, sp.Symbol] = {}

    def parameter(name: str) -> sp.Symbol:
        if name.startswith("joint0."):
            attribute = name.split(".", 1)[1]
            return own.setdefault(attribute, sp.Symbol(f"{attribute}_j", real=True))
        return psym[name]

    ex, ey, vx, vy = sp.symbols("e_x e_y v_x v_y", real=True)
    angles = sp.symbols("theta_b theta_j", real=True)
    speeds = sp.symbols("omega_b omega_j", real=True)
    impact = sp.Symbol("v_imp", real=True)
    law = laws.contact_terms(structure, 0, ex, ey, vx, vy, speeds[0], speeds[1], impact,
                             parameter)
    return JointTemplate(law, (ex, ey, vx, vy), angles, speeds, impact, own, parameter)


def _joint_laws_only(structure: Structure, coordinates: _Coordinates, params: list[Parameter],
                     psym: dict[str, sp.Symbol], t0: float) -> SymbolicModel:
    """What the recursive formulation takes from the derivation: the laws of a clearance
    joint, written with its links' absolute angles and rates as symbols (the recursion binds
    them, joint by joint), so that a law's size does not grow with the joint's place in the
    chain nor the derivation's time with the number of joints."""
    template = _joint_template(structure, psym) if coordinates.eccentricity else None
    clearance = []
    for i in coordinates.eccentricity:
        assert template is not None
        fx, fy, ft = sp.symbols(f"F_x{i} F_y{i} F_t{i}", real=True)
        clearance.append(ClearanceJointTerms(i, fx, fy, ft, template.impact_speed,
                                             template.law, template.angles, template.speeds))
    torque_joints = ([i for i, kind in enumerate(structure.joints, start=1) if kind in _MOVING]
                     if structure.drive else [])
    return SymbolicModel(
        structure=structure, coordinates=coordinate_layout(structure), q=coordinates.q,
        u=coordinates.u, parameters=params, parameter_symbols=[psym[p.name] for p in params],
        torques=[sp.Symbol(f"tau_{i}", real=True) for i in torque_joints],
        torque_joints=torque_joints, clearance=clearance, mass_matrix=None, forcing=None,
        kinetic_energy=None, gravity_potential=None, tip_position=None,
        timings={"kinematics": time.perf_counter() - t0, "kane": 0.0, "energy": 0.0},
        formulation="recursive", template=template)


def _coordinates(kinds: list[str]) -> _Coordinates:
    angles: list[Any] = []
    angle_speeds: list[Any] = []
    ecc: dict[int, tuple[Any, Any, Any, Any]] = {}
    for i, kind in enumerate(kinds, start=1):
        if kind in _MOVING:
            angles.append(me.dynamicsymbols(f"q{i}"))
            angle_speeds.append(me.dynamicsymbols(f"u{i}"))
        if kind in _ECCENTRIC:
            ex, ey = me.dynamicsymbols(f"e_x{i} e_y{i}")
            vx, vy = me.dynamicsymbols(f"v_x{i} v_y{i}")
            ecc[i] = (ex, ey, vx, vy)
    q = list(angles) + [s for i in sorted(ecc) for s in ecc[i][:2]]
    u = list(angle_speeds) + [s for i in sorted(ecc) for s in ecc[i][2:]]
    return _Coordinates(angles, angle_speeds, ecc, q, u)


def _walk_chain(structure: Structure, coordinates: _Coordinates,
                P: Callable[[str], sp.Symbol]) -> _Chain:
    """Every link's body and every load on it, from the ground to the payload at the tip; the
    order of bodies and loads is the order Kane's method sums them in."""
    N = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(N, 0)
    gravity = (P("gravity.x") * N.x + P("gravity.y") * N.y) if structure.gravity else None
    chain = _Chain(frame=N, origin=origin, gravity=gravity)

    theta: sp.Expr = sp.Integer(0)
    omega: sp.Expr = sp.Integer(0)
    prev_frame = N
    prev_end = origin
    moving = iter(zip(coordinates.angles, coordinates.angle_speeds, strict=True))
    for i, kind in enumerate(structure.joints, start=1):
        omega_bearing, theta_bearing = omega, theta
        if kind in _MOVING:
            qi, ui = next(moving)
            theta, omega = theta + qi, omega + ui
        else:
            theta = theta + P(f"joint{i}.angle")
        frame = me.ReferenceFrame(f"L{i}")
        frame.orient_axis(N, N.z, theta)
        frame.set_ang_vel(N, omega * N.z)
        link = _Link(i, frame, theta, omega, theta_bearing, omega_bearing)
        if i in coordinates.eccentricity:
            journal = _clearance_joint(chain, structure, link, coordinates.eccentricity[i],
                                       prev_end, prev_frame, P)
        else:
            journal = prev_end
        if structure.drive and kind in _MOVING:
            _drive_torque(chain, link, prev_frame)
        prev_frame, prev_end = frame, _link_body(chain, link, journal, P)
    _payload(chain, prev_end, P)
    return chain


def _clearance_joint(chain: _Chain, structure: Structure, link: _Link,
                     eccentricity: tuple[Any, Any, Any, Any], bearing: Any, bearing_frame: Any,
                     P: Callable[[str], sp.Symbol]) -> Any:
    """The journal of link i, offset from the bearing (the end of link i-1) by the
    eccentricity; adds the placeholder contact force and friction moments (and their
    reactions on link i-1) and the joint's law. Returns the journal point."""
    N, i = chain.frame, link.index
    ex, ey, vx, vy = eccentricity
    journal = bearing.locatenew(f"J{i}", ex * N.x + ey * N.y)
    journal.set_vel(N, bearing.vel(N) + vx * N.x + vy * N.y)
    fx, fy, ft = sp.symbols(f"F_x{i} F_y{i} F_t{i}", real=True)
    impact = sp.Symbol(f"v_imp{i}", real=True)
    force = fx * N.x + fy * N.y
    chain.loads.append((journal, force))
    rb, rj = P(f"joint{i}.bearing_radius"), P(f"joint{i}.journal_radius")
    chain.loads.append((link.frame, rj * ft * N.z))
    if i > 1:
        chain.loads.append((bearing, -force))
        chain.loads.append((bearing_frame, -rb * ft * N.z))
    law = laws.contact_terms(
        structure, i, ex, ey, vx, vy, link.omega_bearing, link.omega, impact, P)
    chain.clearance.append(ClearanceJointTerms(i, fx, fy, ft, impact, law,
                                               (link.theta_bearing, link.theta),
                                               (link.omega_bearing, link.omega)))
    return journal


def _drive_torque(chain: _Chain, link: _Link, bearing_frame: Any) -> None:
    """The drive torque of a moving joint: on link i, its reaction on link i-1."""
    N, i = chain.frame, link.index
    tau = sp.Symbol(f"tau_{i}", real=True)
    chain.torques.append(tau)
    chain.torque_joints.append(i)
    chain.loads.append((link.frame, tau * N.z))
    if i > 1:
        chain.loads.append((bearing_frame, -tau * N.z))


def _link_body(chain: _Chain, link: _Link, journal: Any, P: Callable[[str], sp.Symbol]) -> Any:
    """Link i's rigid body, hinged at ``journal``, and its weight; returns the link's end."""
    N, i, theta, omega = chain.frame, link.index, link.theta, link.omega
    direction = sp.cos(theta) * N.x + sp.sin(theta) * N.y
    normal = -sp.sin(theta) * N.x + sp.cos(theta) * N.y
    com = journal.locatenew(f"G{i}", P(f"link{i}.com") * direction)
    com.set_vel(N, journal.vel(N) + P(f"link{i}.com") * omega * normal)
    end = journal.locatenew(f"E{i}", P(f"link{i}.length") * direction)
    end.set_vel(N, journal.vel(N) + P(f"link{i}.length") * omega * normal)
    mass = P(f"link{i}.mass")
    body = me.RigidBody(f"B{i}", com, link.frame, mass,
                        (me.outer(N.z, N.z) * P(f"link{i}.inertia"), com))
    chain.bodies.append(body)
    if chain.gravity is not None:
        chain.loads.append((com, mass * chain.gravity))
        chain.gravity_potential -= mass * chain.gravity.dot(com.pos_from(chain.origin))
    return end


def _payload(chain: _Chain, tip: Any, P: Callable[[str], sp.Symbol]) -> None:
    """The payload, a point mass at the tip of the last link, and its weight."""
    mass = P("payload.mass")
    chain.bodies.append(me.Particle("payload", tip, mass))
    if chain.gravity is not None:
        chain.loads.append((tip, mass * chain.gravity))
        chain.gravity_potential -= mass * chain.gravity.dot(tip.pos_from(chain.origin))
    chain.tip = tip
