"""Forward sensitivities of a run: what the compiled loop needs, and the outputs from its rows.

The state's sensitivities, the onset times' and the impact speeds' are integrated and carried
through the events in driver.c (see its "forward sensitivities" section). Here: the named
parameters as directions in the parameter vector (:mod:`jointplay.robot.derived`), the initial
state's derivative, and the derived outputs:

- tip position and velocity: d tip/dq S_q is the tip velocity at speeds S_q (the generated
  velocity is J(q) u, linear in u), d(J u)/dq S_q the polarised second derivative
  (H[u+w, u+w] - H[u-w, u-w]) / 4 of the generated acceleration at zero udot (H[u, u]), and
  J S_u the velocity at speeds S_u: all exact. Their explicit dependence on parameters (link
  lengths, fixed joint angles) is a central difference in the parameter alone: exact for a
  length (the tip is affine in each), about 1e-11 relative for an angle (step 1e-5).
- a phase's peak normal force F(x, p, v_imp) at its located maximum t*: dF/dp = F_x S(t*) +
  F_p dp + F_v dv_imp/dp (the shift of t* drops out, dF/dt = 0 there), a directional central
  difference of the generated normal force along (S, dp, dv_imp/dp), the largest component's
  move 3e-3 of its own scale (the penetration for the eccentricities), extrapolated from two
  steps (Richardson): a 3x larger or smaller step moves them by under 1e-7 relative.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.results.sensitivities import Sensitivities
from jointplay.sim.native import SensitivityInputs
from jointplay.sim.problem import _Problem

# Relative size of the parameters' move in the central differences of the tip above.
RELATIVE_STEP = 1e-5
# Relative size of the largest move of a component (the penetration, a parameter, a speed) in
# the differences of the peak force, extrapolated (Richardson) from h and 2 h: their error is
# O(h^4). Measured on the falling journal's peaks: steps of 1e-2 and 1e-3 moved them by under
# 1e-7 relative from 3e-3's; the O(h^2) difference alone needed steps so small that rounding
# the radii (c = Rb - Rj) left 1e-6.
PEAK_STEP = 3e-3


def sensitivity_inputs(pr: _Problem, names: Sequence[str], x0: np.ndarray,
                       error_control: bool = False) -> SensitivityInputs:
    """The named parameters' directions, their clearance changes, d x0 / d p, and their
    sizes (for the error test, with ``error_control``)."""
    from jointplay.robot.derived import parameter_directions

    model = pr.model
    if len(set(names)) != len(names):
        repeated = next(n for n in names if list(names).count(n) > 1)
        raise DescriptionError("sensitivities", f"{repeated!r} is named twice; name each "
                               "parameter once")
    directions = parameter_directions(list(names), model.parameters, pr.scene.robot)
    slot = model.layout.parameter_slot
    clearance = np.array([[d[slot("joint", j, "bearing_radius")]
                           - d[slot("joint", j, "journal_radius")]
                           for j in model.clearance_joints] for d in directions])
    clearance = clearance.reshape(len(names), len(model.clearance_joints))
    # A parameter's size: its value (the clearance, for jointN.clearance), 1 where it is 0.
    clearances = np.array([pr.p[slot("joint", j, "bearing_radius")]
                           - pr.p[slot("joint", j, "journal_radius")]
                           for j in model.clearance_joints])
    values = np.array([pr.p[model.parameters.index(name)] if name in model.parameters
                       else float(np.sum(dc * clearances))
                       for name, dc in zip(names, clearance, strict=True)])
    sizes = np.where(np.abs(values) > 0, np.abs(values), 1.0)
    return SensitivityInputs(directions, clearance, _initial_sensitivity(pr, directions, x0),
                             sizes, error_control)


def _initial_sensitivity(pr: _Problem, directions: np.ndarray, x0: np.ndarray) -> np.ndarray:
    """d x0 / d p (ns, nx): zero for initial values given as numbers; for journals resting
    in their bearings, the implicit function theorem on the equilibrium's residual (the
    accelerations at rest, zero over the eccentricities and the holding torques)."""
    model = pr.model
    ns, nx, n = directions.shape[0], model.n_state, model.n_coordinates
    if getattr(pr.scene, "journals", "centred") != "resting" or not model.clearance_joints:
        return np.zeros((ns, nx))
    from jointplay.sim.equilibrium import static_equilibrium

    slot = model.layout.parameter_slot
    clearances = {j: float(pr.p[slot("joint", j, "bearing_radius")]
                           - pr.p[slot("joint", j, "journal_radius")])
                  for j in model.clearance_joints}
    x_rest, tau = static_equilibrium(model, pr.p, x0, clearances)
    ecc = [model.coordinates.index(f"{axis}{j}") for j in model.clearance_joints
           for axis in ("ex", "ey")]
    blocks = model.jacobian(x_rest, tau, pr.p)
    jx, jt, jp = (np.asarray(blocks[k])[n:] for k in ("x", "tau", "p"))
    unknowns = np.linalg.solve(np.hstack([jx[:, ecc], jt]), -jp @ directions.T)
    out = np.zeros((ns, nx))
    out[:, ecc] = unknowns[:len(ecc)].T
    return out


def _end_effector(pr: _Problem, x: np.ndarray, p: np.ndarray) -> list[np.ndarray]:
    """Tip position, velocity, acceleration (each (n_t, 2)) at states x (n_t, nx), udot 0."""
    from jointplay.sim.assemble import _mapped

    udot = np.zeros((pr.n, x.shape[0]))
    ps = p[:, None] if p.ndim == 1 else p.T
    return [o.T for o in _mapped(pr.model, "end_effector", [x.T, udot, ps])]


def tip_sensitivities(pr: _Problem, x: np.ndarray, S: np.ndarray,
                      directions: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """d tip position and d tip velocity (n_t, 2, ns) from states x (n_t, nx) and their
    sensitivities S (n_t, nx, ns); see the module docstring."""
    n = pr.n
    n_t, ns = x.shape[0], S.shape[2]
    d_pos, d_vel = np.zeros((n_t, 2, ns)), np.zeros((n_t, 2, ns))
    q, u = x[:, :n], x[:, n:]
    for k in range(ns):
        sq, su = S[:, :n, k], S[:, n:, k]
        d_pos[:, :, k] = _end_effector(pr, np.hstack([q, sq]), pr.p)[1]
        along_u = _end_effector(pr, np.hstack([q, su]), pr.p)[1]
        # H[u, sq] by polarisation, sq scaled to u's size (no cancellation between the two)
        size_u, size_s = np.linalg.norm(u, axis=1), np.linalg.norm(sq, axis=1)
        alpha = np.where((size_u > 0) & (size_s > 0), size_u / np.where(size_s > 0, size_s, 1),
                         0.0)[:, None]
        plus = _end_effector(pr, np.hstack([q, u + alpha * sq]), pr.p)[2]
        minus = _end_effector(pr, np.hstack([q, u - alpha * sq]), pr.p)[2]
        with np.errstate(invalid="ignore", divide="ignore"):
            curvature = np.where(alpha > 0, (plus - minus) / (4 * np.where(alpha > 0, alpha, 1)),
                                 0.0)
        d_vel[:, :, k] = curvature + along_u
        explicit = _explicit_tip(pr, x, directions[k])
        if explicit is not None:
            d_pos[:, :, k] += explicit[0]
            d_vel[:, :, k] += explicit[1]
    return d_pos, d_vel


def _explicit_tip(pr: _Problem, x: np.ndarray, direction: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray] | None:
    """The tip position's and velocity's partial derivative along a parameter direction at
    fixed state (central difference in the parameters alone), or None when it is zero."""
    touched = np.flatnonzero(direction)
    h = RELATIVE_STEP * max(float(np.max(np.abs(pr.p[touched]))), 1e-3) / float(
        np.max(np.abs(direction[touched])))
    plus = _end_effector(pr, x, pr.p + h * direction)
    minus = _end_effector(pr, x, pr.p - h * direction)
    d_pos, d_vel = (plus[0] - minus[0]) / (2 * h), (plus[1] - minus[1]) / (2 * h)
    if not (np.any(d_pos) or np.any(d_vel)):
        return None
    return d_pos, d_vel


def peak_sensitivities(pr: _Problem, records: np.ndarray, joints: np.ndarray,
                       penetration: np.ndarray, directions: np.ndarray) -> np.ndarray:
    """d peak normal force / d p (n_phases, ns) from the loop's phase records (dtau, then at
    the peak x, S, v_imp, dv_imp), the phases' joint indices (0-based among the clearance
    joints) and maximum penetrations; a phase with no force peak gets 0, and every phase NaN
    where the run located no peaks (``simulate(..., peaks=False)``)."""
    model = pr.model
    nx, nc, ns = model.n_state, pr.nc, directions.shape[0]
    m = records.shape[0]
    if not pr.peaks:
        return np.full((m, ns), np.nan)
    out = np.zeros((m, ns))
    if not m or not ns:
        return out
    x = records[:, ns:ns + nx]
    S = records[:, ns + nx:ns + nx + ns * nx].reshape(m, ns, nx)
    v = records[:, ns + nx + ns * nx:ns + nx + ns * nx + nc]
    dv = records[:, ns + nx + ns * nx + nc:].reshape(m, nc, ns)
    rows = np.flatnonzero(np.all(np.isfinite(x), axis=1))
    if not rows.size:
        return out
    # Each component's scale: a share of the penetration for the eccentricities (the force
    # is K delta^n there), the impact speeds' size for the speeds, 1 rad for the angles.
    speed = np.maximum(np.max(np.abs(v[rows]), axis=1, initial=0.0), 1e-3)[:, None]
    scale_x = np.maximum(np.abs(x[rows]), 1.0)
    scale_x[:, pr.n:] = np.maximum(np.abs(x[rows, pr.n:]), speed)
    for j in model.clearance_joints:
        for axis in ("ex", "ey"):
            col = model.coordinates.index(f"{axis}{j}")
            scale_x[:, col] = np.maximum(np.abs(penetration[rows]), 1e-12)
    scale_p = np.maximum(np.abs(pr.p), 1e-12)
    for k in range(ns):
        dx, dp, dvk = S[rows, k, :], directions[k], dv[rows, :, k]
        ratio = np.max(np.abs(dx) / scale_x, axis=1)
        ratio = np.maximum(ratio, np.max(np.abs(dp) / scale_p))
        ratio = np.maximum(ratio, np.max(np.abs(dvk) / speed, axis=1, initial=0.0))
        h = np.where(ratio > 0, PEAK_STEP / np.where(ratio > 0, ratio, 1), 0.0)

        def difference(step: np.ndarray, dx: np.ndarray = dx, dp: np.ndarray = dp,
                       dvk: np.ndarray = dvk) -> np.ndarray:
            forces = []
            for sign in (1.0, -1.0):
                xs = x[rows] + sign * step[:, None] * dx
                ps = pr.p[None, :] + sign * step[:, None] * dp[None, :]
                vs = v[rows] + sign * step[:, None] * dvk
                f = _normal_forces(pr, xs, ps, vs)
                forces.append(f[np.arange(rows.size), joints[rows]])
            safe = np.where(step > 0, step, 1.0)
            return np.where(step > 0, (forces[0] - forces[1]) / (2 * safe), 0.0)

        # Richardson's extrapolation of two central differences: error O(h^4)
        out[rows, k] = (4 * difference(h) - difference(2 * h)) / 3
    return out


def _normal_forces(pr: _Problem, x: np.ndarray, p: np.ndarray, v: np.ndarray) -> np.ndarray:
    from jointplay.sim.assemble import _mapped

    name = "normal_force" if "normal_force" in pr.model.layout.functions else "contact"
    outputs = _mapped(pr.model, name, [x.T, p.T, v.T])
    return outputs[0 if name == "normal_force" else 3].T


def assemble_sensitivities(pr: _Problem, names: Sequence[str], inputs: SensitivityInputs,
                           t: np.ndarray, x: np.ndarray, S: np.ndarray,
                           records: np.ndarray, phase_joints: np.ndarray,
                           penetration: np.ndarray) -> Sensitivities:
    """The result's :class:`Sensitivities` from the loop's outputs."""
    directions = inputs.directions
    ns = directions.shape[0]
    d_pos, d_vel = tip_sensitivities(pr, x, S, directions)
    times = records[:, :ns] if records.size else np.zeros((0, ns))
    peaks = peak_sensitivities(pr, records, phase_joints, penetration, directions)
    return Sensitivities(names=tuple(names), t=t, state=S, tip_position=d_pos,
                         tip_velocity=d_vel, impact_times=times, impact_peaks=peaks)
