"""The static equilibrium of a clearance robot at rest: each journal resting in its bearing.

With every speed zero, the journals' eccentricities ``e`` and the drive torques ``tau`` that
hold the arm at its initial angles are solved together so that every acceleration vanishes:

    forward_dynamics([q0, e; 0], tau, p)[accelerations] = 0

(as many equations as coordinates; as many unknowns, 2 per clearance joint plus one torque per
driven joint). The mass matrix is invertible, so this is the generalised forces balancing:
gravity on each link carried by its contact force, the arm held by the drives. Newton's
method on the compiled model's exact Jacobian, with a backtracking line search on the
residual; it starts from each journal moved to the bearing wall in the direction it falls
(at the centre there is no contact force, and no Jacobian to start from).
"""

from __future__ import annotations

import numpy as np

from jointplay.common.errors import SimulationError

TOLERANCE = 1e-9  # largest |acceleration| accepted at the solution (rad/s^2, m/s^2)
MAX_ITERATIONS = 60


def static_equilibrium(model: object, p: np.ndarray, x0: np.ndarray,
                       clearances: dict[int, float]) -> tuple[np.ndarray, np.ndarray]:
    """The state at rest with each journal in equilibrium in its bearing (arm angles as in
    ``x0``, every speed zero) and the holding torques; ``clearances``: radial clearance per
    clearance joint (m). Raises SimulationError naming the residual when it finds none."""
    n = model.n_coordinates  # type: ignore[attr-defined]
    coords = list(model.coordinates)  # type: ignore[attr-defined]
    joints = list(model.clearance_joints)  # type: ignore[attr-defined]
    ecc = [coords.index(f"{axis}{j}") for j in joints for axis in ("ex", "ey")]
    ntau = len(model.torque_joints)  # type: ignore[attr-defined]
    if len(ecc) + ntau != n:
        raise SimulationError(0.0, "the static equilibrium needs a drive torque on every moving "
                              f"joint ({n - len(ecc)} angles, {ntau} driven)")
    x = np.asarray(x0, dtype=float).copy()
    x[n:] = 0.0

    def residual(e: np.ndarray, tau: np.ndarray) -> np.ndarray:
        xx = x.copy()
        xx[ecc] = e
        return np.asarray(model.forward_dynamics(xx, tau, p)).ravel()[n:]  # type: ignore[attr-defined]

    def jac(e: np.ndarray, tau: np.ndarray) -> np.ndarray:
        xx = x.copy()
        xx[ecc] = e
        blocks = model.jacobian(xx, tau, p)  # type: ignore[attr-defined]
        jx, jt = np.asarray(blocks["x"])[n:], np.asarray(blocks["tau"])[n:]
        return np.hstack([jx[:, ecc], jt])

    # Start: at rest, each joint carries the weight of everything beyond it and nothing else
    # (the drive torques are moments), so each journal rests against its bearing in the
    # direction of gravity; the penetration that carries the weight is found on a log scale
    # (the contact law is far too stiff for Newton to find it from the wall), then Newton
    # polishes every unknown together, the holding torques included.
    names = list(model.parameters)  # type: ignore[attr-defined]
    gravity = np.array([p[names.index("gravity.x")], p[names.index("gravity.y")]]) \
        if "gravity.x" in names else np.array([0.0, -1.0])
    down = gravity / np.hypot(*gravity) if np.hypot(*gravity) > 0 else np.array([0.0, -1.0])
    tau = np.zeros(ntau)

    def held(e: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        jt = jac(e, np.zeros(ntau))[:, len(ecc):]
        t = np.linalg.lstsq(jt, -residual(e, np.zeros(ntau)), rcond=None)[0]
        return t, residual(e, t)

    depths = np.full(len(joints), 1e-8)
    grid = np.geomspace(1e-13, 1e-3, 41)

    def placed(d: np.ndarray) -> np.ndarray:
        return np.concatenate([(clearances[j] + d[i]) * down for i, j in enumerate(joints)])

    for _ in range(2):  # each joint's depth in turn, the others held (twice over)
        for i in range(len(joints)):
            rows = [ecc[2 * i], ecc[2 * i + 1]]
            sizes = []
            for depth in grid:
                d = depths.copy()
                d[i] = depth
                with np.errstate(all="ignore"):
                    _, r_try = held(placed(d))
                size = float(np.linalg.norm(r_try[rows]))
                sizes.append(size if np.isfinite(size) else np.inf)
            depths[i] = grid[int(np.argmin(sizes))]
    e = placed(depths)
    with np.errstate(all="ignore"):
        tau, _ = held(e)
    r = residual(e, tau)
    scale = float(np.hypot(*gravity))  # accelerations are measured against gravity's
    for _ in range(MAX_ITERATIONS):
        size = float(np.max(np.abs(r)))
        if size < TOLERANCE * max(1.0, scale):
            return _state(x, ecc, e), tau
        step = np.linalg.lstsq(jac(e, tau), -r, rcond=None)[0]
        lam = 1.0
        while lam > 1e-6:
            e_try, tau_try = e + lam * step[: len(ecc)], tau + lam * step[len(ecc):]
            r_try = residual(e_try, tau_try)
            if np.all(np.isfinite(r_try)) and np.max(np.abs(r_try)) < size:
                e, tau, r = e_try, tau_try, r_try
                break
            lam /= 2
        else:
            break
    raise SimulationError(0.0, "no static equilibrium of the journals was found: the largest "
                          f"acceleration left is {float(np.max(np.abs(r))):.3g} after "
                          f"{MAX_ITERATIONS} Newton steps; start the scene from given "
                          "eccentricities ([initial] ex2 = ..., ey2 = ...) instead")


def _state(x: np.ndarray, ecc: list[int], e: np.ndarray) -> np.ndarray:
    out = x.copy()
    out[ecc] = e
    return out


__all__ = ["MAX_ITERATIONS", "TOLERANCE", "static_equilibrium"]
