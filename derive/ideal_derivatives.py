"""dID/dx of a chain of ideal (and locked) joints in closed form: a few operations an entry.

Why it is this simple (planar, every joint a pin): turning joint j by dq_j at fixed joint
speeds and accelerations turns everything beyond it rigidly about the joint's pin J_j, so
every point P beyond it keeps its motion relative to J_j, turned: d(P - J_j) = z x (P - J_j),
and the same for P' - J_j' and P'' - J_j'' (the turn is constant in time; planar turns
commute). A joint speed u_j enters a point's acceleration only through the centripetal terms
of the links from j on: dP''/du_j = 2 z x (P' - J_j'). No angular rate or acceleration
depends on q, and none of the accelerations on u other than so.

With the inverse dynamics as moments about the pins, ID_i = sum over the mass points m beyond
joint i of [I_m alpha_m + (c_m - J_i) x m_m (c_m'' - g)] - tau_i, those give, for rows i and
columns j (suffix sums over the bodies from joint k on: mass M_k, first moment Mc_k, momentum
Mv_k = sum m c', mass-weighted acceleration Ma_k = sum m c'', and P_k = sum m c . c'):

* dID_i/dq_j = (Mc_i - M_i J_i) . (g - J_j'')                                   (i >= j)
* dID_i/dq_j = (Mc_j - M_j J_j) . (g - J_j'') + (J_j - J_i) . (Ma_j - M_j J_j'') (i < j)
* dID_i/du_j = 2 [P_i - J_i . Mv_i - (Mc_i - M_i J_i) . J_j']                    (i >= j)
* dID_i/du_j = 2 [P_j - Mc_j . J_j' - J_i . (Mv_j - M_j J_j')]                    (i < j)

The derivation is the planar case of Carpentier and Mansard's RNEA derivatives (RSS 2018);
tests/test_formulations.py checks it against AD of the recursion's RNEA to 1e-12.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import casadi as ca

from jointplay.robot.structure import CLEARANCE_KINDS, MOVING_KINDS


def applies(structure: Any) -> bool:
    """Whether every joint is ideal or locked (no clearance), with at least one moving."""
    kinds = list(structure.joints)
    return (not any(kind in CLEARANCE_KINDS for kind in kinds)
            and any(kind in MOVING_KINDS for kind in kinds))


def _dot(a: Any, b: Any) -> Any:
    return a[0] * b[0] + a[1] * b[1]


def _point(distance: Any, pin: Any, pin_rate: Any, pin_acc: Any, theta: Any, omega: Any,
           alpha: Any) -> tuple[Any, Any, Any]:
    """Position, velocity and acceleration of the point ``distance`` along a link from its
    pin, the link at absolute angle ``theta``, rate ``omega`` and acceleration ``alpha``."""
    along = ca.vertcat(ca.cos(theta), ca.sin(theta))
    across = ca.vertcat(-along[1], along[0])
    return (pin + distance * along, pin_rate + distance * omega * across,
            pin_acc + distance * (alpha * across - omega * omega * along))


def residual_state_jacobian(structure: Any, acc: Any, slots: dict[tuple[int, str], int],
                            parameter: Any, thetas: Sequence[Any], omegas: Sequence[Any],
                            n: int) -> Any:
    """dID/dx (n x 2n, dense) at the accelerations ``acc``, for a chain where
    :func:`applies`; ``thetas``, ``omegas`` are the links' absolute angles and rates (as
    :func:`jointplay.derive.recursive.kinematics` gives them)."""
    zero = ca.SX.zeros(2, 1)
    gravity = (ca.vertcat(parameter("gravity.x"), parameter("gravity.y")) if structure.gravity
               else zero)
    pin, pin_rate, pin_acc = zero, zero, zero
    alpha: Any = ca.SX(0)
    pins: list[tuple[int | None, Any, Any, Any]] = []  # (slot, J, J', J'') per body
    points: list[list[tuple[Any, Any, Any, Any]]] = []  # (m, c, c', c'') per body
    k = structure.links
    for i, kind in enumerate(structure.joints, start=1):
        slot = slots[(i, "angle")] if kind in MOVING_KINDS else None
        if slot is not None:
            alpha = alpha + acc[slot]
        theta, omega = thetas[i - 1], omegas[i - 1]
        motion = (pin, pin_rate, pin_acc, theta, omega, alpha)
        body = [(parameter(f"link{i}.mass"), *_point(parameter(f"link{i}.com"), *motion))]
        end = _point(parameter(f"link{i}.length"), *motion)
        if i == k:  # the payload, a point mass at the tip
            body.append((parameter("payload.mass"), *end))
        pins.append((slot, pin, pin_rate, pin_acc))
        points.append(body)
        pin, pin_rate, pin_acc = end
    # Suffix sums over the bodies from each one outwards.
    sums: list[tuple[Any, Any, Any, Any, Any]] = [None] * k  # type: ignore[list-item]
    total: tuple[Any, Any, Any, Any, Any] = (ca.SX(0), zero, zero, zero, ca.SX(0))
    for b in range(k - 1, -1, -1):
        mass, first, momentum, weighted, p = total
        for m, c, cd, cdd in points[b]:
            mass, first = mass + m, first + m * c
            momentum, weighted = momentum + m * cd, weighted + m * cdd
            p = p + m * _dot(c, cd)
        total = sums[b] = (mass, first, momentum, weighted, p)
    # What a column j needs (its pin's motion; for rows inside it, i < j, the terms that do
    # not depend on the row: dq = D_j - J_i . B_j, du = 2 (E_j - J_i . V_j)), and a row i
    # (G_i = Mc_i - M_i J_i, H_i = P_i - J_i . Mv_i: rows from column j out, i >= j).
    moving = [b for b in range(k) if pins[b][0] is not None]
    column: dict[int, tuple[Any, Any, Any, Any, Any, Any]] = {}
    row: dict[int, tuple[Any, Any]] = {}
    for b in moving:
        _, J, Jd, Jdd = pins[b]
        M, Mc, Mv, Ma, P = sums[b]
        B, V = Ma - M * Jdd, Mv - M * Jd
        column[b] = (gravity - Jdd, Jd, _dot(Mc - M * J, gravity - Jdd) + _dot(J, B), B,
                     P - _dot(Mc, Jd), V)
        row[b] = (Mc - M * J, P - _dot(J, Mv))
    out = ca.SX(n, 2 * n)
    for bi in moving:
        si, J_i = pins[bi][0], pins[bi][1]
        G_i, H_i = row[bi]
        for bj in moving:
            sj = pins[bj][0]
            assert si is not None and sj is not None
            lift, Jd_j, D_j, B_j, E_j, V_j = column[bj]
            if bi >= bj:
                out[si, sj] = _dot(G_i, lift)
                out[si, n + sj] = 2 * (H_i - _dot(G_i, Jd_j))
            else:
                out[si, sj] = D_j - _dot(J_i, B_j)
                out[si, n + sj] = 2 * (E_j - _dot(J_i, V_j))
    return out
