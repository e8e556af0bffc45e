"""The recursion's mass matrix and the Jacobians of its accelerations, as CasADi functions
(used by :mod:`jointplay.derive.codegen` for the recursive formulation): straight-line or
looped columns, the chain rule through each link's pose and twist for long chains of
clearance joints (:mod:`jointplay.derive.recursive_chain_rule`), AD of the ABA for short
ones, -M^-1 dID/dy through the articulated factors otherwise, with dID/dy of chains of ideal
(and locked) joints in closed form (:mod:`jointplay.derive.ideal_derivatives`)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import casadi as ca

from jointplay.derive import ideal_derivatives, recursive_chain_rule
from jointplay.derive.symbolic import SymbolicModel
from jointplay.derive.to_casadi import emitted_function
from jointplay.robot.structure import CLEARANCE_KINDS, MOVING_KINDS

if TYPE_CHECKING:
    from jointplay.derive.codegen import _Inputs

# From this many coordinates on, the recursion's state Jacobian differentiates the inverse
# dynamics a pass of columns at a time in a loop (C the size of a few recursions' tangents,
# growing linearly with the chain) instead of as straight-line code (C quadratic in the chain,
# but AD there skips what a column's seed does not reach). Measured on 20 and 32 clearance
# joints (60 and 96 coordinates; `python benchmarks/formulations.py --links 20,32 --structures
# clearance --no-paper --closed-up-to 0 --pinocchio` with `--looped-from 1`, then `1000`):
# straight-line code was 2.3x and 8.2x cheaper per call, for 1.08x and 1.31x the build time
# and 1.4x and 2.3x gcc's peak memory (1.3 GB at 96 coordinates). Beyond the measured range
# the loop keeps the build bounded. (Runs one after the other on a loaded 2-core machine.)
# Chains of clearance joints only take the chain rule before this (CHAIN_RULE_FROM).
LOOPED_STATE_JACOBIAN_FROM = 100
# From this many coordinates on, a chain of clearance joints takes the state Jacobian by the
# chain rule through each link's pose and twist (jointplay.derive.recursive_chain_rule: C
# that grows linearly with the chain) instead of AD of the ABA (straight-line, C quadratic in
# the chain). Measured side by side on 8, 12, 16 and 24 clearance joints (24 to 72
# coordinates; `python benchmarks/formulations.py --links 8,12,16,24 --structures clearance
# --no-paper --closed-up-to 0 --pinocchio --chain-rule-from 1 --versus-straight-line`, commit
# a3449a6, load average 2.9-3.8 on a loaded 2-core machine): state Jacobian per call 17.0
# against 13.3 us, 35.5 against 34.3, 37.2 against 60.6 and 111 against 234 (1.28x, 1.04x,
# 0.61x and 0.47x; Pinocchio's computeABADerivatives 30.2, 83.3, 138 and 379 us in the same
# rounds); build (derive + emit + gcc) 5.7 against 20.0 s, 7.9 against 18.7, 14.2 against
# 34.3 and 17.6 against 79.8; C 415 against 767 kB at 8 joints and 1349 against 4168 at 24;
# the two Jacobians differ by 7e-14 to 6e-13 of their largest entry. So the chain rule costs
# as much per call at 12 joints and less from 16 on, and builds 2-4x faster; it starts at 12
# joints, where the build budget (10 s) rules out the straight-line code.
CHAIN_RULE_FROM = 36
# Columns a looped Jacobian differentiates per pass: the nominal recursion is evaluated once per
# pass, its tangents once per column, so wider passes spend less on the nominal values and
# more on C (the code of a pass grows with its width). The state Jacobian is called at every
# Newton matrix update; the others (mass matrix, torques, parameters, impact speeds) are not
# called while integrating, so they take the smallest code.
STATE_COLUMNS_PER_PASS = 4
# Columns of the straight-line state Jacobian's M^-1 solves per call (when 2n is a multiple
# of it; else 2 or 1): each call reads the articulated factors once.
SOLVE_COLUMNS_PER_CALL = 4
OTHER_COLUMNS_PER_PASS = 1
# Whether chains of ideal (and locked) joints take dID/dx in closed form (see
# jointplay.derive.ideal_derivatives) rather than by AD of the RNEA (False: for comparison).
IDEAL_DERIVATIVES_IN_CLOSED_FORM = True


def differentiates_the_aba(structure: Any) -> bool:
    """Whether the recursion's straight-line state Jacobian is AD of the ABA's accelerations
    (da/dx directly) rather than -M^-1 dID/dx (AD of the RNEA, then 2n solves through the
    articulated factors).

    Where every joint with coordinates has three (a clearance joint), no joint passes an
    articulated inertia on (it is exactly zero), so a column's tangent through the ABA stays
    near the joint it is seeded at, while -M^-1 dID/dx multiplies a dense dID/dx column by
    M^-1 for each of the 2n columns. Where a joint has one or two coordinates, the articulated
    inertias it passes on depend on every coordinate below it and their derivatives fill the
    tangents. (From CHAIN_RULE_FROM coordinates on, a chain of clearance joints takes the
    chain rule instead, see uses_the_chain_rule.) Measured with `python
    benchmarks/formulations.py --links 12 --structures
    clearance,ideal --no-paper --closed-up-to 0 --pinocchio --state-jacobian aba` and then
    `solves` (loaded 2-core machine, load average 4.5 and 3.9): 12 clearance joints, state
    Jacobian 0.58x and 1.62x Pinocchio's computeABADerivatives (timed beside it in each run),
    C 1737 and 1378 kB, build 44.5 and 27.2 s; 12 ideal joints, 1.43x and 0.63x. The price of
    AD of the ABA is C about a quarter larger for chains of clearance joints. Chains that mix
    the kinds keep the solves (not measured)."""
    kinds = [kind for kind in structure.joints if kind in MOVING_KINDS or kind in
             CLEARANCE_KINDS]
    return bool(kinds) and all(kind in MOVING_KINDS and kind in CLEARANCE_KINDS
                               for kind in kinds)


def uses_the_chain_rule(structure: Any, coordinates: int) -> bool:
    """Whether the state Jacobian is the chain rule through each link's pose and twist
    (:mod:`jointplay.derive.recursive_chain_rule`): where every joint is a clearance joint
    (a chain with a locked joint keeps AD of the ABA), from CHAIN_RULE_FROM coordinates on."""
    return coordinates >= CHAIN_RULE_FROM and recursive_chain_rule.applies(structure)


def _unit_columns(start: Any, size: int, width: int) -> Any:
    """Columns ``start`` .. ``start + width - 1`` of the size x size identity, built from the
    symbol ``start``: the C then holds no identity matrix as a constant (size^2 numbers)."""
    return ca.horzcat(*[ca.vertcat(*[start == row - column for row in range(size)])
                        for column in range(width)])


def _looped_columns(name: str, inputs: list[Any], start: Any, columns: Any, size: int,
                    width: int, args: list[Any]) -> Any:
    """The ``size`` columns of a Jacobian, ``width`` at a time: ``columns`` (an SX expression
    of ``inputs`` and ``start``) holds the ``width`` columns from column ``start``; ``args``
    are the MX values of ``inputs``, the same for every pass.

    What does not depend on the column (the nominal recursion's values, which the tangents
    multiply) is computed once, by ``name_nominal``; the loop over passes, in the C, holds
    only the tangents' arithmetic (``name_tangents``)."""
    body, symbols, values = ca.extract_parametric(columns, ca.veccat(*inputs))
    nominal = ca.veccat(*values) if values else ca.SX(0, 1)
    nominal_sym = ca.SX.sym("nominal", nominal.numel())
    if symbols:
        body = ca.substitute(body, ca.veccat(*symbols), nominal_sym)
    fn_nominal = emitted_function(f"{name}_nominal", inputs, [nominal])
    fn_tangents = emitted_function(f"{name}_tangents", [*inputs, nominal_sym, start], [body])
    passes = -(-size // width)
    looped = fn_tangents.map(f"{name}_loop", "serial", passes, list(range(len(inputs) + 1)),
                             [])
    starts = ca.DM([list(range(0, passes * width, width))])
    return looped(*args, fn_nominal(*args), starts)[:, :size]


class RecursiveJacobians:
    """The recursion's mass matrix and the Jacobians of its accelerations.

    da/dy = -M^-1 dID/dy at the computed accelerations a (Carpentier and Mansard, RSS 2018):
    dID/dy is differentiated with the contact forces held as symbols, then chained with each
    law's own Jacobian (a law is local to its joint, so it is differentiated once, not once per
    output). M^-1 is applied column by column through the articulated factors, computed once.
    The columns are loops in the C over passes of COLUMNS_PER_PASS columns, so the code grows
    with the chain, not with the chain squared; only the state Jacobian of short chains is
    straight-line code (below LOOPED_STATE_JACOBIAN_FROM coordinates), and for a chain of
    clearance joints only it is AD of the ABA's accelerations (see differentiates_the_aba),
    or from CHAIN_RULE_FROM coordinates on the chain rule through each link's pose and twist
    (see uses_the_chain_rule).
    """

    def __init__(self, model: SymbolicModel, inputs: _Inputs, chain: Any,
                 contact: dict[int, tuple[Any, Any, Any]], acc_sym: Any,
                 slots: dict[tuple[int, str], int], torque_slots: dict[int, int],
                 parameter: Any, thetas: list[Any], omegas: list[Any], fn_fd: ca.Function,
                 acceleration: Any) -> None:
        from jointplay.derive import recursive

        self.n = n = model.n_coordinates
        self.symbols = inputs
        self.acc_sym = acc_sym
        self.fn_fd = fn_fd
        self.acceleration = acceleration
        self.direct = differentiates_the_aba(model.structure)
        self.model = model
        # A chain of ideal (and locked) joints has dID/dx in closed form
        # (jointplay.derive.ideal_derivatives): a few operations an entry instead of AD.
        self.ideal_in_closed_form = (IDEAL_DERIVATIVES_IN_CLOSED_FORM
                                     and ideal_derivatives.applies(model.structure))
        self.ideal_arguments = (parameter, thetas, omegas)
        self.slots = slots
        self.chain_rule = uses_the_chain_rule(model.structure, model.n_coordinates)
        q, u, tau = inputs.q, inputs.u, inputs.tau
        held: dict[int, tuple[Any, Any, Any]] = {
            i: (ca.SX.sym(f"Fx{i}"), ca.SX.sym(f"Fy{i}"), ca.SX.sym(f"Ft{i}")) for i in contact}
        self.forces = (ca.vertcat(*[f for i in contact for f in contact[i]]) if contact
                       else ca.SX(0, 1))
        self.held = (ca.vertcat(*[f for i in held for f in held[i]]) if held
                     else ca.SX(0, 1))
        rigid = recursive.chain(model.structure, q, u, tau, slots, torque_slots, parameter,
                                held, thetas, omegas)
        self.residual = recursive.inverse_dynamics(rigid, acc_sym)
        factors = recursive.factor_vector(chain)
        self.factor_sym = ca.SX.sym("factors", factors.numel())
        self.column_sym = ca.SX.sym("column", n)
        self.solved = recursive.forward_dynamics(
            recursive.with_factors(chain, self.factor_sym), self.column_sym)
        self.fn_factors = emitted_function("articulated_factors", [q, inputs.p], [factors])
        names = ["x", "tau", "p", "v_imp"]
        self.mx_inputs = tuple(ca.MX.sym(name, arg.numel()) for name, arg in
                               zip(names, (inputs.x, tau, inputs.p, inputs.v_imp), strict=True))

    def _solve_each(self, columns: Any) -> Any:
        """M^-1 applied to each column of ``columns`` (n x width) through the factors."""
        return ca.horzcat(*[ca.substitute(self.solved, self.column_sym, columns[:, c])
                            for c in range(columns.size2())])

    def mass_matrix(self) -> ca.Function:
        """``mass_matrix``: M e_j = dID/da e_j (ID is linear in a), a pass of columns at a
        time."""
        n, q, p = self.n, self.symbols.q, self.symbols.p
        start = ca.SX.sym("start")
        width = OTHER_COLUMNS_PER_PASS
        columns = ca.jtimes(self.residual, self.acc_sym, _unit_columns(start, n, width))
        qm, pm = ca.MX.sym("q", n), ca.MX.sym("p", p.numel())
        return emitted_function("mass_matrix", [qm, pm],
                           [_looped_columns("mass_matrix_columns", [q, p], start, columns, n,
                                            width, [qm, pm])],
                           ["q", "p"], ["M"])

    def state(self) -> ca.Function:
        """``jac_state``: d xdot / dx = [0 I; -M^-1 dID/dx] at the computed accelerations."""
        n = self.n
        x, tau, p, v_imp = (self.symbols.x, self.symbols.tau, self.symbols.p,
                            self.symbols.v_imp)
        xm, taum, pm, vm = self.mx_inputs
        acc_m = self.fn_fd(xm, taum, pm, vm)[n:]
        factors_m = self.fn_factors(xm[:n], pm)
        if self.chain_rule:
            return emitted_function("jac_state", [xm, taum, pm, vm],
                                    [recursive_chain_rule.state_jacobian(
                                        self.model, self.slots, self.mx_inputs)],
                                    ["x", "tau", "p", "v_imp"], ["jac_xdot_x"])
        d_forces = ca.jacobian(self.forces, x)
        if n < LOOPED_STATE_JACOBIAN_FROM and self.direct:
            # da/dx by AD of the ABA itself, straight-line: no dID/dx, no M^-1 solves.
            jac_sx = ca.vertcat(ca.horzcat(ca.SX(n, n), ca.SX.eye(n)),
                                ca.jacobian(self.acceleration, x))
            return emitted_function("jac_state", [x, tau, p, v_imp], [jac_sx],
                             ["x", "tau", "p", "v_imp"], ["jac_xdot_x"])
        if n < LOOPED_STATE_JACOBIAN_FROM:
            # dID/dx as straight-line code: in closed form for ideal chains, else AD, which
            # skips what a column's seed does not reach.
            d_residual = (ideal_derivatives.residual_state_jacobian(
                self.model.structure, self.acc_sym, self.slots, *self.ideal_arguments, n)
                if self.ideal_in_closed_form else ca.jacobian(self.residual, x))
            if self.held.numel():
                d_residual = d_residual + ca.mtimes(ca.jacobian(self.residual, self.held),
                                                    d_forces)
            d_residual = ca.substitute(d_residual, self.held, self.forces)
            # Dense, so that each column the solves read is contiguous (zeros written here cost
            # less than densifying the sparse output afterwards).
            fn_parts = emitted_function("jac_state_parts", [x, tau, p, v_imp, self.acc_sym],
                                 [ca.densify(d_residual)])
            return emitted_function("jac_state", [xm, taum, pm, vm],
                             [self._state_from_parts(fn_parts(xm, taum, pm, vm, acc_m),
                                                     factors_m)],
                             ["x", "tau", "p", "v_imp"], ["jac_xdot_x"])
        fn_forces = emitted_function("contact_forces_x", [x, p, v_imp], [self.forces, d_forces])
        forces_m, d_forces_m = fn_forces(xm, pm, vm)
        start = ca.SX.sym("start")
        seed = _unit_columns(start, 2 * n, STATE_COLUMNS_PER_PASS)
        d_forces_sym = ca.SX.sym("d_forces", d_forces.sparsity())
        directional = ca.jtimes(self.residual, ca.vertcat(x, self.held),
                                ca.vertcat(seed, ca.mtimes(d_forces_sym, seed)))
        columns = _looped_columns(
            "jac_state_columns",
            [x, tau, p, self.acc_sym, self.held, self.factor_sym, d_forces_sym], start,
            self._solve_each(directional), 2 * n, STATE_COLUMNS_PER_PASS,
            [xm, taum, pm, acc_m, forces_m, factors_m, d_forces_m])
        jac_x = ca.vertcat(ca.horzcat(ca.MX(n, n), ca.MX.eye(n)), -columns)
        # Not densified: the driver reads the output's pattern as CSC, which a dense one is not.
        return emitted_function("jac_state", [xm, taum, pm, vm], [jac_x],
                           ["x", "tau", "p", "v_imp"], ["jac_xdot_x"])

    def _state_from_parts(self, d_residual: Any, factors: Any) -> Any:
        """[0 I; -M^-1 dID/dx] from dID/dx (dense, n x 2n) with no copying or transposing
        after the solves: the output's pattern holds every column's entry in the row of its
        own coordinate (a stored 0 in the first n columns, the 1 of I in the others) above
        the n rows of the speeds, so column c of the output's nonzeros is
        (c >= n, -M^-1 dID/dx_c), which is what each solve writes, in order. The solves
        take SOLVE_COLUMNS_PER_CALL columns a call: the factors are read once per call (and
        copied once per call by CasADi's map), not once per column."""
        n = self.n
        width = next(w for w in (SOLVE_COLUMNS_PER_CALL, 2, 1) if (2 * n) % w == 0)
        columns = ca.SX.sym("columns", n, width)
        identity = ca.SX.sym("identity", 1, width)
        solved = ca.vertcat(identity, -self._solve_each(columns))
        fn_solve = emitted_function("mass_matrix_solve", [self.factor_sym, columns, identity],
                             [solved])
        calls = 2 * n // width
        solve = fn_solve.map("mass_matrix_solve_loop", "serial", calls, [0], [])
        identity_row = ca.DM([[0.0] * n + [1.0] * n])
        values = solve(factors, d_residual, identity_row)
        rows = [[c % n, *range(n, 2 * n)] for c in range(2 * n)]
        pattern = ca.Sparsity.triplet(2 * n, 2 * n, [r for rs in rows for r in rs],
                                      [c for c, rs in enumerate(rows) for _ in rs])
        return ca.sparsity_cast(values, pattern)

    def inputs(self, xm: Any, taum: Any, pm: Any, vm: Any) -> list[Any]:
        """d xdot / d tau, d p and d v_imp (not needed while integrating): one loop over the
        stacked inputs [tau; p; v_imp], a pass of columns at a time."""
        n = self.n
        x, tau, p, v_imp = (self.symbols.x, self.symbols.tau, self.symbols.p,
                            self.symbols.v_imp)
        sizes = [tau.numel(), p.numel(), v_imp.numel()]
        loads = ca.vertcat(p, v_imp)
        d_forces = ca.jacobian(self.forces, loads)
        fn_forces = emitted_function("contact_forces_inputs", [x, p, v_imp],
                                [self.forces, d_forces])
        forces_m, d_forces_m = fn_forces(xm, pm, vm)
        start = ca.SX.sym("start")
        seed = _unit_columns(start, sum(sizes), OTHER_COLUMNS_PER_PASS)
        d_forces_sym = ca.SX.sym("d_forces", d_forces.sparsity())
        directional = ca.jtimes(
            self.residual, ca.vertcat(tau, p, self.held),
            ca.vertcat(seed[:sizes[0] + sizes[1], :],
                       ca.mtimes(d_forces_sym, seed[sizes[0]:, :])))
        acc_m = self.fn_fd(xm, taum, pm, vm)[n:]
        columns = _looped_columns(
            "jac_input_columns",
            [x, tau, p, self.acc_sym, self.held, self.factor_sym, d_forces_sym], start,
            self._solve_each(directional), sum(sizes), OTHER_COLUMNS_PER_PASS,
            [xm, taum, pm, acc_m, forces_m, self.fn_factors(xm[:n], pm), d_forces_m])
        blocks, offset = [], 0
        for size in sizes:
            blocks.append(ca.vertcat(ca.MX(n, size), -columns[:, offset:offset + size]))
            offset += size
        return blocks
