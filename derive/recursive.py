"""The chain's dynamics by recursion over the links: cost linear in the link count.

Planar spatial algebra in the inertial frame N, about its origin O (Featherstone, "Rigid Body
Dynamics Algorithms", 2008, with planar 3-vectors in place of 6-vectors):

* a motion vector is (omega, v_O): the angular speed and the velocity of the body point that is
  at O; a force vector is (n_O, f_x, f_y), the moment about O and the force; their dot product
  is power. A body's momentum about O is h = I V with the 3x3 inertia
  I = [[Ic + m |c|^2, -m c_y, m c_x], [-m c_y, m, 0], [m c_x, 0, m]] (c: the centre of mass),
  and its equation of motion is f = dh/dt = I A + (dI/dt) V, A = dV/dt.
* joint i joins link i-1 to link i: V_i = X_i V_{i-1} + S_i nu_i, nu_i the speeds of joint i's
  own coordinates (the angle rate, then de_x, de_y). The eccentricity is measured in N, so
  the journal's motion relative to link i-1 includes omega_{i-1} z x e: X_i is not the
  identity but [[1, 0, 0], [e_y, 1, 0], [-e_x, 0, 1]]. S_i's columns are (1, J_y, -J_x) for
  the rotation about the journal centre J and (0, 1, 0), (0, 0, 1) for the eccentricity.
  The derivations below hold for any linear X_i (forces go back through X_i^T, by power).
* loads: gravity and the friction moments are forces on the links; the contact force acts on
  the journal and, reversed, on the bearing, so its power is F . de: it is the generalised
  force of (e_x, e_y). A drive torque is the generalised force of its joint's angle.

From these: the inverse dynamics by recursive Newton-Euler (RNEA) and the forward dynamics by
the articulated-body algorithm (ABA), straight-line CasADi SX; the mass matrix's columns are
the RNEA's derivative with respect to the accelerations (M e_j, see
:mod:`jointplay.derive.codegen`). The Jacobian
of the accelerations follows Carpentier and Mansard (RSS 2018): with ID(q, u, a) = M a - f,
da/dy = -M^-1 dID/dy at the computed a, dID/dy by AD of the RNEA (linear cost per input),
and M^-1 applied column by column through the ABA's articulated inertias, already computed
and passed to the solve with the entries of X and S (linear cost per column, no
trigonometry), never forming or factorising M.

The per-joint laws (contact, friction, film, wear) stay the symbolic derivation's
(:mod:`jointplay.derive.laws`): they are written with the link's absolute angle and rate as
placeholder symbols, bound here to the recursion's values.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import casadi as ca

from jointplay.robot.structure import CLEARANCE_KINDS, MOVING_KINDS, Structure

Vec = Any  # a 3 x 1 SX
Mat = Any  # a 3 x 3 SX


@dataclass
class Joint:
    """One joint's place in the recursion: the slots of its coordinates in q (angle first,
    then e_x, e_y), its transform X and subspace S, and the link it carries."""

    kind: str
    slots: list[int]
    X: Mat
    S: Any  # 3 x len(slots)
    bias: Vec  # dX/dt V_{i-1} + dS/dt nu_i
    inertia: Mat  # of the link (and the payload, for the last)
    inertia_rate_times_velocity: Vec  # (dI/dt) V
    velocity: Vec
    external: Vec  # gravity and friction moments on the link
    generalised: Any  # drive torque and contact force on this joint's coordinates
    # The link's (and payload's) mass, centre of mass and moment of inertia about it: the
    # inertia above in the form that solves I A = f without cancellation.
    rigid: tuple[Any, Any, Any, Any] | None = None


@dataclass
class Chain:
    """The chain's kinematics and loads, link by link, and what the outputs need."""

    joints: list[Joint]
    n: int
    thetas: list[Any]
    omegas: list[Any]
    kinetic: Any
    gravity_potential: Any
    tip: Any
    articulated: list[tuple[Any, Any, Mat]] = field(default_factory=list)  # U, D^-1, I^a


def _vec(a: Any, b: Any, c: Any) -> Vec:
    return ca.vertcat(a, b, c)


def _point_inertia(mass: Any, inertia: Any, cx: Any, cy: Any) -> Mat:
    return ca.vertcat(ca.horzcat(inertia + mass * (cx * cx + cy * cy), -mass * cy, mass * cx),
                      ca.horzcat(-mass * cy, mass, 0),
                      ca.horzcat(mass * cx, 0, mass))


def _point_inertia_rate_times(mass: Any, cx: Any, cy: Any, dcx: Any, dcy: Any,
                              velocity: Vec) -> Vec:
    """(dI/dt) V for a mass at c moving at dc/dt."""
    w, vx, vy = velocity[0], velocity[1], velocity[2]
    return _vec(2 * mass * (cx * dcx + cy * dcy) * w - mass * dcy * vx + mass * dcx * vy,
                -mass * dcy * w, mass * dcx * w)


def _gravity_force(mass: Any, cx: Any, cy: Any, gravity: tuple[Any, Any] | None) -> Vec:
    if gravity is None:
        return ca.SX.zeros(3, 1)
    gx, gy = gravity
    return _vec(cx * mass * gy - cy * mass * gx, mass * gx, mass * gy)


def _with_point_mass(rigid: tuple[Any, Any, Any, Any], mass: Any, x: Any, y: Any
                     ) -> tuple[Any, Any, Any, Any]:
    """A rigid body's (mass, centre x, y, inertia about the centre) with a point mass added."""
    m, cx, cy, inertia_c = rigid
    total = m + mass
    # The new centre, as offsets from the old one and the point (no large |c|^2 subtracted).
    share = mass / total
    dx, dy = x - cx, y - cy
    inertia = inertia_c + m * share * share * (dx * dx + dy * dy) + mass * (1 - share) * (
        1 - share) * (dx * dx + dy * dy)
    return total, cx + share * dx, cy + share * dy, inertia


def rigid_solve(rigid: tuple[Any, Any, Any, Any], force: Vec) -> Vec:
    """I^-1 f for a rigid body given by its mass, centre and inertia about the centre: the
    angular acceleration from the moment about the centre, then the acceleration of the body
    point at O."""
    mass, cx, cy, inertia_c = rigid
    moment, fx, fy = force[0], force[1], force[2]
    alpha = (moment + cy * fx - cx * fy) / inertia_c
    return _vec(alpha, fx / mass + alpha * cy, fy / mass - alpha * cx)


def kinematics(structure: Structure, q: Any, u: Any, slots: dict[tuple[int, str], int],
               parameter: Any) -> tuple[list[Any], list[Any]]:
    """Every link's absolute angle and rate (the laws' placeholders are bound to these)."""
    thetas, omegas = [], []
    theta: Any = ca.SX(0)
    omega: Any = ca.SX(0)
    for i, kind in enumerate(structure.joints, start=1):
        if kind in MOVING_KINDS:
            theta = theta + q[slots[(i, "angle")]]
            omega = omega + u[slots[(i, "angle")]]
        else:
            theta = theta + parameter(f"joint{i}.angle")
        thetas.append(theta)
        omegas.append(omega)
    return thetas, omegas


@dataclass(frozen=True)
class Base:
    """What a part of the chain hangs from, when it does not start at the ground: the
    absolute angle and rate of the link before its first joint, and the position and
    velocity of that link's end (where the first joint's bearing is)."""

    theta: Any
    omega: Any
    end_x: Any
    end_y: Any
    end_vx: Any
    end_vy: Any


def chain(structure: Structure, q: Any, u: Any, tau: Any, slots: dict[tuple[int, str], int],
          torque_slots: dict[int, int], parameter: Any, contact: dict[int, tuple[Any, Any, Any]],
          thetas: Sequence[Any], omegas: Sequence[Any], base: Base | None = None) -> Chain:
    """Walk the chain from the ground (or from ``base``): positions, velocities, inertias
    and loads of every link.

    ``contact`` maps a clearance joint to its law's (F_x, F_y, F_t) on the journal;
    ``parameter(name)`` gives a parameter's SX.
    """
    n = q.numel()
    gravity = (parameter("gravity.x"), parameter("gravity.y")) if structure.gravity else None
    end_x: Any = ca.SX(0)
    end_y: Any = ca.SX(0)
    end_vx: Any = ca.SX(0)
    end_vy: Any = ca.SX(0)
    velocity: Vec = ca.SX.zeros(3, 1)
    omega_before: Any = ca.SX(0)
    if base is not None:
        end_x, end_y, end_vx, end_vy = base.end_x, base.end_y, base.end_vx, base.end_vy
        omega_before = base.omega
        # (omega, the velocity of the base link's point at O) from its end's velocity.
        velocity = _vec(base.omega, end_vx + base.omega * end_y, end_vy - base.omega * end_x)
    joints: list[Joint] = []
    kinetic: Any = ca.SX(0)
    potential: Any = ca.SX(0)
    k = structure.links
    for i, kind in enumerate(structure.joints, start=1):
        theta, omega = thetas[i - 1], omegas[i - 1]
        own: list[int] = []
        columns: list[Vec] = []
        generalised: list[Any] = []
        jx, jy, jvx, jvy = end_x, end_y, end_vx, end_vy
        X: Mat = ca.SX.eye(3)
        bias: Vec = ca.SX.zeros(3, 1)
        if kind in CLEARANCE_KINDS:
            a, b = slots[(i, "ex")], slots[(i, "ey")]
            ex, ey, vx, vy = q[a], q[b], u[a], u[b]
            jx, jy, jvx, jvy = end_x + ex, end_y + ey, end_vx + vx, end_vy + vy
            X = ca.vertcat(ca.horzcat(1, 0, 0), ca.horzcat(ey, 1, 0), ca.horzcat(-ex, 0, 1))
            bias = bias + omega_before * _vec(0, vy, -vx)
        if kind in MOVING_KINDS:
            s = slots[(i, "angle")]
            own.append(s)
            columns.append(_vec(1, jy, -jx))
            bias = bias + u[s] * _vec(0, jvy, -jvx)
            generalised.append(tau[torque_slots[i]] if i in torque_slots else ca.SX(0))
        if kind in CLEARANCE_KINDS:
            own += [slots[(i, "ex")], slots[(i, "ey")]]
            columns += [_vec(0, 1, 0), _vec(0, 0, 1)]
            fx, fy, _ = contact[i]
            generalised += [fx, fy]
        velocity = ca.mtimes(X, velocity)
        for column, s in zip(columns, own, strict=True):
            velocity = velocity + column * u[s]
        cos, sin = ca.cos(theta), ca.sin(theta)
        length, com = parameter(f"link{i}.length"), parameter(f"link{i}.com")
        mass, inertia_c = parameter(f"link{i}.mass"), parameter(f"link{i}.inertia")
        cx, cy = jx + com * cos, jy + com * sin
        dcx, dcy = jvx - com * omega * sin, jvy + com * omega * cos
        end_x, end_y = jx + length * cos, jy + length * sin
        end_vx, end_vy = jvx - length * omega * sin, jvy + length * omega * cos
        inertia = _point_inertia(mass, inertia_c, cx, cy)
        rate = _point_inertia_rate_times(mass, cx, cy, dcx, dcy, velocity)
        external = _gravity_force(mass, cx, cy, gravity)
        kinetic = kinetic + (mass * (dcx * dcx + dcy * dcy) + inertia_c * omega * omega) / 2
        if gravity is not None:
            potential = potential - mass * (gravity[0] * cx + gravity[1] * cy)
        rigid = (mass, cx, cy, inertia_c)
        if i == k:  # the payload, a point mass at the tip
            payload = parameter("payload.mass")
            rigid = _with_point_mass(rigid, payload, end_x, end_y)
            inertia = inertia + _point_inertia(payload, 0, end_x, end_y)
            rate = rate + _point_inertia_rate_times(payload, end_x, end_y, end_vx, end_vy,
                                                    velocity)
            external = external + _gravity_force(payload, end_x, end_y, gravity)
            kinetic = kinetic + payload * (end_vx * end_vx + end_vy * end_vy) / 2
            if gravity is not None:
                potential = potential - payload * (gravity[0] * end_x + gravity[1] * end_y)
        S = ca.horzcat(*columns) if columns else ca.SX(3, 0)
        joints.append(Joint(kind, own, X, S, bias, inertia, rate, velocity, external,
                            ca.vertcat(*generalised) if generalised else ca.SX(0, 1), rigid))
        omega_before = omega
    # Friction moments: R_j F_t on the journal's link, -R_b F_t on the bearing's.
    for i, (_, _, ft) in contact.items():
        joints[i - 1].external = joints[i - 1].external + _vec(
            parameter(f"joint{i}.journal_radius") * ft, 0, 0)
        if i > 1:
            joints[i - 2].external = joints[i - 2].external - _vec(
                parameter(f"joint{i}.bearing_radius") * ft, 0, 0)
    return Chain(joints, n, list(thetas), list(omegas), kinetic, potential,
                 ca.vertcat(end_x, end_y))


def inverse_dynamics(chain_: Chain, acceleration: Any) -> Any:
    """RNEA: ID(q, u, a) = M a - f, the generalised forces that give the accelerations."""
    out = ca.SX.zeros(chain_.n, 1)
    forces: list[Vec] = []
    previous: Vec = ca.SX.zeros(3, 1)
    for joint in chain_.joints:
        a = ca.mtimes(joint.X, previous) + joint.bias
        for column, s in enumerate(joint.slots):
            a = a + joint.S[:, column] * acceleration[s]
        forces.append(ca.mtimes(joint.inertia, a) + joint.inertia_rate_times_velocity
                      - joint.external)
        previous = a
    for index in range(len(chain_.joints) - 1, -1, -1):
        joint = chain_.joints[index]
        if joint.slots:
            torque = ca.mtimes(joint.S.T, forces[index]) - joint.generalised
            for row, s in enumerate(joint.slots):
                out[s] = torque[row]
        if index > 0:
            forces[index - 1] = forces[index - 1] + ca.mtimes(joint.X.T, forces[index])
    return out


def _small_inverse(D: Any) -> Any:
    """The inverse of a symmetric positive definite 1x1, 2x2 or 3x3 SX, by cofactors."""
    size = D.shape[0]
    if size == 1:
        return 1 / D
    if size == 2:
        det = D[0, 0] * D[1, 1] - D[0, 1] * D[1, 0]
        inv_det = 1 / det
        return ca.vertcat(ca.horzcat(D[1, 1] * inv_det, -D[0, 1] * inv_det),
                          ca.horzcat(-D[1, 0] * inv_det, D[0, 0] * inv_det))
    cof = ca.SX(3, 3)
    for r in range(3):
        for c in range(3):
            r1, r2 = [x for x in range(3) if x != r]
            c1, c2 = [x for x in range(3) if x != c]
            cof[r, c] = (-1) ** (r + c) * (D[r1, c1] * D[r2, c2] - D[r1, c2] * D[r2, c1])
    inv_det = 1 / (D[0, 0] * cof[0, 0] + D[0, 1] * cof[0, 1] + D[0, 2] * cof[0, 2])
    return cof.T * inv_det


def articulate(chain_: Chain) -> None:
    """The ABA's inward pass on inertias only (a function of q): every joint's U = I^A S,
    D^-1 = (S^T U)^-1 and the articulated inertia it passes on, I^a."""
    joints = chain_.joints
    articulated: list[Mat] = [j.inertia for j in joints]
    factors: list[tuple[Any, Any, Mat]] = [None] * len(joints)  # type: ignore[list-item]
    for index in range(len(joints) - 1, -1, -1):
        joint = joints[index]
        IA = articulated[index]
        if joint.slots:
            U = ca.mtimes(IA, joint.S)
            Dinv = _small_inverse(ca.mtimes(joint.S.T, U))
            # A joint free in all three directions passes no inertia on, exactly.
            Ia = (ca.SX.zeros(3, 3) if len(joint.slots) == 3
                  else IA - ca.mtimes([U, Dinv, U.T]))
        else:
            U, Dinv, Ia = ca.SX(3, 0), ca.SX(0, 0), IA
        factors[index] = (U, Dinv, Ia)
        if index > 0:
            X = joint.X
            articulated[index - 1] = articulated[index - 1] + ca.mtimes([X.T, Ia, X])
    chain_.articulated = factors


def forward_dynamics(chain_: Chain, generalised: Any | None = None) -> Any:
    """ABA: the accelerations; with ``generalised`` (an n-vector) instead M^-1 of it (velocity
    terms and loads left out), which is how the Jacobian applies M^-1 to its columns."""
    joints = chain_.joints
    if not chain_.articulated:
        articulate(chain_)
    solve_only = generalised is not None
    bias_forces: list[Vec] = [
        ca.SX.zeros(3, 1) if solve_only else j.inertia_rate_times_velocity - j.external
        for j in joints]
    stored: list[Any] = [None] * len(joints)
    for index in range(len(joints) - 1, -1, -1):
        joint = joints[index]
        U, Dinv, Ia = chain_.articulated[index]
        pA = bias_forces[index]
        if joint.slots:
            applied = (ca.vertcat(*[generalised[s] for s in joint.slots])
                       if generalised is not None else joint.generalised)
            u_prime = applied - ca.mtimes(joint.S.T, pA)
            stored[index] = u_prime
            if len(joint.slots) == 3:
                # S is invertible, U D^-1 = S^-T and I^a = 0: p^a = S^-T applied, exactly.
                pa = _inverse_transpose_times(joint.S, applied)
            else:
                pa = pA + ca.mtimes(U, ca.mtimes(Dinv, u_prime))
                if not solve_only:
                    pa = pa + ca.mtimes(Ia, joint.bias)
        else:
            pa = pA
            if not solve_only:
                pa = pa + ca.mtimes(Ia, joint.bias)
        if index > 0:
            bias_forces[index - 1] = bias_forces[index - 1] + ca.mtimes(joint.X.T, pa)
    out = ca.SX.zeros(chain_.n, 1)
    previous: Vec = ca.SX.zeros(3, 1)
    for index, joint in enumerate(joints):
        U, Dinv, _ = chain_.articulated[index]
        a = ca.mtimes(joint.X, previous)
        if not solve_only:
            a = a + joint.bias
        if len(joint.slots) == 3:  # D^-1 U^T = S^-1
            acc = ca.mtimes(Dinv, stored[index]) - _inverse_times(joint.S, a)
            for row, s in enumerate(joint.slots):
                out[s] = acc[row]
            a = a + ca.mtimes(joint.S, acc)
        elif joint.slots:
            acc = ca.mtimes(Dinv, stored[index] - ca.mtimes(U.T, a))
            for row, s in enumerate(joint.slots):
                out[s] = acc[row]
            a = a + ca.mtimes(joint.S, acc)
        previous = a
    return out


def _inverse_times(S: Any, v: Vec) -> Vec:
    """S^-1 v for a three-column S = [[1, 0, 0], [s1, 1, 0], [s2, 0, 1]]."""
    return _vec(v[0], v[1] - S[1, 0] * v[0], v[2] - S[2, 0] * v[0])


def _inverse_transpose_times(S: Any, w: Vec) -> Vec:
    """S^-T w for a three-column S = [[1, 0, 0], [s1, 1, 0], [s2, 0, 1]]."""
    return _vec(w[0] - S[1, 0] * w[1] - S[2, 0] * w[2], w[1], w[2])


def _has_angle(joint: Joint) -> bool:
    return len(joint.slots) in (1, 3)


def _has_eccentricity(joint: Joint) -> bool:
    return joint.kind in CLEARANCE_KINDS


def factor_vector(chain_: Chain) -> Any:
    """What every M^-1 solve reuses, as one vector: per joint, the entries of X and S that
    vary (e_y, -e_x; J_y, -J_x), U (joints with fewer than three coordinates) and D^-1. A
    solve then costs a few multiplications per joint, with no trigonometry."""
    if not chain_.articulated:
        articulate(chain_)
    parts = []
    for joint, (U, Dinv, _) in zip(chain_.joints, chain_.articulated, strict=True):
        if _has_eccentricity(joint):
            parts += [joint.X[1, 0], joint.X[2, 0]]
        if _has_angle(joint):
            parts += [joint.S[1, 0], joint.S[2, 0]]
        if joint.slots and len(joint.slots) < 3:
            parts.append(ca.vec(U))
        if joint.slots:
            parts.append(ca.vec(Dinv))
    return ca.vertcat(*parts) if parts else ca.SX(0, 1)


def with_factors(chain_: Chain, factors: Any) -> Chain:
    """The chain as far as an M^-1 solve needs it (X, S and the articulated factors), read
    from ``factors`` (as laid out by :func:`factor_vector`), so that a solve takes them as
    an input and nothing else."""
    offset = 0

    def take(count: int) -> Any:
        nonlocal offset
        offset += count
        return factors[offset - count:offset]

    articulated = []
    joints = []
    zero = ca.SX.zeros(3, 1)
    for joint in chain_.joints:
        size = len(joint.slots)
        X: Any = ca.SX.eye(3)
        if _has_eccentricity(joint):
            x10, x20 = ca.vertsplit(take(2))
            X = ca.vertcat(ca.horzcat(1, 0, 0), ca.horzcat(x10, 1, 0), ca.horzcat(x20, 0, 1))
        columns = []
        if _has_angle(joint):
            s10, s20 = ca.vertsplit(take(2))
            columns.append(_vec(1, s10, s20))
        if _has_eccentricity(joint):
            columns += [_vec(0, 1, 0), _vec(0, 0, 1)]
        S = ca.horzcat(*columns) if columns else ca.SX(3, 0)
        U: Any = ca.SX(3, 0)
        Dinv: Any = ca.SX(0, 0)
        if size and size < 3:
            U = ca.reshape(take(3 * size), 3, size)
        if size:
            Dinv = ca.reshape(take(size * size), size, size)
        articulated.append((U, Dinv, ca.SX.zeros(3, 3)))
        joints.append(Joint(joint.kind, joint.slots, X, S, zero, ca.SX.zeros(3, 3), zero, zero,
                            zero, ca.SX(0, 1)))
    view = Chain(joints, chain_.n, chain_.thetas, chain_.omegas, chain_.kinetic,
                 chain_.gravity_potential, chain_.tip)
    view.articulated = articulated
    return view
