"""Fixed-step integrators emitted beside the dynamics (used by :mod:`jointplay.derive.codegen`):
classical RK4 and 3-stage Radau IIA with a fixed number of Newton iterations."""

from __future__ import annotations

import casadi as ca

from jointplay.derive.to_casadi import emitted_function

# Radau IIA, 3 stages (Hairer & Wanner, Solving ODEs II, Table 5.6): stiffly accurate, so the
# last stage is the step's result.
_S6 = 6 ** 0.5
RADAU_C = ((4 - _S6) / 10, (4 + _S6) / 10, 1.0)
RADAU_A = (((88 - 7 * _S6) / 360, (296 - 169 * _S6) / 1800, (-2 + 3 * _S6) / 225),
           ((296 + 169 * _S6) / 1800, (88 + 7 * _S6) / 360, (-2 - 3 * _S6) / 225),
           ((16 - _S6) / 36, (16 + _S6) / 36, 1 / 9))
RADAU_NEWTON_ITERATIONS = 8


def fixed_step_functions(fn_fd: ca.Function, fn_jac_state: ca.Function
                         ) -> tuple[ca.Function, ca.Function]:
    """One step of explicit RK4 and of implicit Radau IIA, as C with no solver library.

    Torques enter at the stage times, so a time-varying drive keeps each method's order. The
    Radau step solves its stage equations by simplified Newton with the exact Jacobian at
    the step's start, its Newton matrix reduced to the speeds' half and inverted once per
    step; a fixed iteration count keeps it a plain loop,
    and the size of the last update is returned so the caller can reject a step that did
    not converge.
    """
    nx = fn_fd.size1_in(0)
    x = ca.MX.sym("x", nx)
    h = ca.MX.sym("h")
    p = ca.MX.sym("p", fn_fd.size1_in(2))
    v = ca.MX.sym("v_imp", fn_fd.size1_in(3))
    tau = ca.MX.sym("tau_stages", fn_fd.size1_in(1), 3)
    names = ["x", "tau_stages", "h", "p", "v_imp"]

    def f(state: ca.MX, column: int) -> ca.MX:
        return fn_fd(state, tau[:, column], p, v)

    k1 = f(x, 0)
    k2 = f(x + h / 2 * k1, 1)
    k3 = f(x + h / 2 * k2, 1)
    k4 = f(x + h * k3, 2)
    rk4 = emitted_function("rk4_step", [x, tau, h, p, v], [x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)],
                      names, ["x_next"])

    a = ca.DM(RADAU_A)
    jac_x = fn_jac_state(x, tau[:, 0], p, v)
    # The state Jacobian is [0 I; Jq Jv] (x = [q; u]), so the Newton system
    # (I - h A (x) J) dz = -r reduces exactly to one of half the size for the speeds' parts:
    # (I - h A (x) Jv - h^2 A^2 (x) Jq) du = -r_u - h (A (x) Jq) r_q, dq = -r_q + h (A (x) I) du;
    # its inverse is formed once per step (a QR of 3n rows instead of 6n).
    n = nx // 2
    jac_q, jac_u = jac_x[n:, :n], jac_x[n:, n:]
    a_mx = ca.MX(a)
    speed_inv = ca.solve(ca.MX.eye(3 * n) - h * ca.kron(a_mx, jac_u)
                         - h * h * ca.kron(ca.MX(a @ a), jac_q), ca.MX.eye(3 * n), "qr")
    a_jac_q = h * ca.kron(a_mx, jac_q)
    a_eye = h * ca.kron(a_mx, ca.MX.eye(n))
    z = ca.MX.zeros(nx, 3)  # stage increments x_i - x, one column per stage
    increment = ca.MX(0)
    for _ in range(RADAU_NEWTON_ITERATIONS):
        slopes = ca.horzcat(*[f(x + z[:, i], i) for i in range(3)])
        residual = z - h * ca.mtimes(slopes, a.T)  # nx x 3, a column per stage
        r_q, r_u = ca.vec(residual[:n, :]), ca.vec(residual[n:, :])
        d_u = -ca.mtimes(speed_inv, r_u + ca.mtimes(a_jac_q, r_q))
        d_q = -r_q + ca.mtimes(a_eye, d_u)
        update = ca.vertcat(ca.reshape(d_q, n, 3), ca.reshape(d_u, n, 3))
        z = z + update
        increment = ca.norm_inf(update)
    radau = emitted_function("radau_step", [x, tau, h, p, v], [x + z[:, 2], increment],
                        names, ["x_next", "newton_increment"])
    return rk4, radau
