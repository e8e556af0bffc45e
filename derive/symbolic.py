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
    mass_matrix: sp.Matrix
    forcing: sp.Matrix  # M du/dt = forcing; contact enters via the placeholder symbols
    kinetic_energy: sp.Expr
    gravity_potential: sp.Expr
    tip_position: sp.Matrix  # 2 x 1, end of the last link (where the payload sits)
    timings: dict[str, float] = field(default_factory=dict)

    @property
    def n_coordinates(self) -> int:
        return len(self.q)

    @property
    def contact_potential(self) -> sp.Expr:
        return sp.Add(*[c.law.potential for c in self.clearance])


def derive(structure: Structure) -> SymbolicModel:
    """Derive the equations of motion for a robot structure (see ``Robot.structure()``)."""
    import time

    t0 = time.perf_counter()
    kinds: list[str] = list(structure.joints)
    params = parameter_layout(structure)
    psym = {p.name: sp.Symbol(p.symbol, real=True) for p in params}

    def P(name: str) -> sp.Symbol:
        return psym[name]

    N = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(N, 0)

    angles: list[Any] = []
    angle_speeds: list[Any] = []
    ecc: dict[int, tuple[Any, Any, Any, Any]] = {}
    for i, kind in enumerate(kinds, start=1):
        if kind in ("ideal", "clearance"):
            angles.append(me.dynamicsymbols(f"q{i}"))
            angle_speeds.append(me.dynamicsymbols(f"u{i}"))
        if kind in ("clearance", "locked_clearance"):
            ex, ey = me.dynamicsymbols(f"e_x{i} e_y{i}")
            vx, vy = me.dynamicsymbols(f"v_x{i} v_y{i}")
            ecc[i] = (ex, ey, vx, vy)
    q = list(angles) + [s for i in sorted(ecc) for s in ecc[i][:2]]
    u = list(angle_speeds) + [s for i in sorted(ecc) for s in ecc[i][2:]]

    drive = structure.drive
    torques: list[sp.Symbol] = []
    torque_joints: list[int] = []
    gravity = (P("gravity.x") * N.x + P("gravity.y") * N.y) if structure.gravity else None

    bodies: list[Any] = []
    loads: list[tuple[Any, Any]] = []
    clearance_terms: list[ClearanceJointTerms] = []
    gravity_potential: sp.Expr = sp.Integer(0)

    theta: sp.Expr = sp.Integer(0)
    omega: sp.Expr = sp.Integer(0)
    prev_frame = N
    prev_end = origin
    moving = iter(zip(angles, angle_speeds, strict=True))
    for i, kind in enumerate(kinds, start=1):
        omega_bearing, theta_bearing = omega, theta
        if kind in ("ideal", "clearance"):
            qi, ui = next(moving)
            theta, omega = theta + qi, omega + ui
        else:
            theta = theta + P(f"joint{i}.angle")
        frame = me.ReferenceFrame(f"L{i}")
        frame.orient_axis(N, N.z, theta)
        frame.set_ang_vel(N, omega * N.z)
        direction = sp.cos(theta) * N.x + sp.sin(theta) * N.y
        normal = -sp.sin(theta) * N.x + sp.cos(theta) * N.y

        if i in ecc:
            ex, ey, vx, vy = ecc[i]
            journal = prev_end.locatenew(f"J{i}", ex * N.x + ey * N.y)
            journal.set_vel(N, prev_end.vel(N) + vx * N.x + vy * N.y)
            fx, fy, ft = sp.symbols(f"F_x{i} F_y{i} F_t{i}", real=True)
            impact = sp.Symbol(f"v_imp{i}", real=True)
            force = fx * N.x + fy * N.y
            loads.append((journal, force))
            rb, rj = P(f"joint{i}.bearing_radius"), P(f"joint{i}.journal_radius")
            loads.append((frame, rj * ft * N.z))
            if i > 1:
                loads.append((prev_end, -force))
                loads.append((prev_frame, -rb * ft * N.z))
            law = laws.contact_terms(
                structure, i, ex, ey, vx, vy, omega_bearing, omega, impact, P)
            clearance_terms.append(ClearanceJointTerms(i, fx, fy, ft, impact, law,
                                                       (theta_bearing, theta),
                                                       (omega_bearing, omega)))
        else:
            journal = prev_end

        if drive and kind in ("ideal", "clearance"):
            tau = sp.Symbol(f"tau_{i}", real=True)
            torques.append(tau)
            torque_joints.append(i)
            loads.append((frame, tau * N.z))
            if i > 1:
                loads.append((prev_frame, -tau * N.z))

        com = journal.locatenew(f"G{i}", P(f"link{i}.com") * direction)
        com.set_vel(N, journal.vel(N) + P(f"link{i}.com") * omega * normal)
        end = journal.locatenew(f"E{i}", P(f"link{i}.length") * direction)
        end.set_vel(N, journal.vel(N) + P(f"link{i}.length") * omega * normal)
        mass = P(f"link{i}.mass")
        body = me.RigidBody(f"B{i}", com, frame, mass,
                            (me.outer(N.z, N.z) * P(f"link{i}.inertia"), com))
        bodies.append(body)
        if gravity is not None:
            loads.append((com, mass * gravity))
            gravity_potential -= mass * gravity.dot(com.pos_from(origin))
        prev_frame, prev_end = frame, end

    payload = me.Particle("payload", prev_end, P("payload.mass"))
    bodies.append(payload)
    if gravity is not None:
        loads.append((prev_end, P("payload.mass") * gravity))
        gravity_potential -= P("payload.mass") * gravity.dot(prev_end.pos_from(origin))
    t1 = time.perf_counter()

    kd = [qi.diff(me.dynamicsymbols._t) - ui for qi, ui in zip(q, u, strict=True)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    mass_matrix = kane.mass_matrix
    forcing = kane.forcing
    t2 = time.perf_counter()

    # Kinetic energy straight from the bodies (not from M), so an energy check is independent.
    kinetic = me.kinetic_energy(N, *bodies)
    tip = prev_end.pos_from(origin)
    tip_position = sp.Matrix([tip.dot(N.x), tip.dot(N.y)])
    t3 = time.perf_counter()

    return SymbolicModel(
        structure=structure,
        coordinates=coordinate_layout(structure),
        q=q,
        u=u,
        parameters=params,
        parameter_symbols=[psym[p.name] for p in params],
        torques=torques,
        torque_joints=torque_joints,
        clearance=clearance_terms,
        mass_matrix=mass_matrix,
        forcing=forcing,
        kinetic_energy=kinetic,
        gravity_potential=gravity_potential,
        tip_position=tip_position,
        timings={"kinematics": t1 - t0, "kane": t2 - t1, "energy": t3 - t2},
    )
