"""From the symbolic model to CasADi functions, C source with provenance, and layout.json.

Functions emitted (all take the parameter vector ``p`` as a runtime input):

* ``mass_matrix(q, p) -> M``                      M(q) du/dt = f
* ``forcing(x, tau, p, v_imp) -> f``              f including contact, friction, gravity, drive
* ``forward_dynamics(x, tau, p, v_imp) -> xdot``  xdot = [u; M^-1 f], plus ``jac_state``, its
  exact Jacobian with respect to x, and ``jac_forward_dynamics``, with respect to every input,
  in the calling convention CasADi looks up in a compiled library (so CVODES/IDAS get it for
  free); the latter's input blocks live in a second, deferred library (DEFERRED_EXPORTS),
  compiled on first use
* ``contact(x, p, v_imp) -> delta, delta_dot, v_t, f_n, f_t, f_x, f_y`` per clearance joint
* ``energy(x, p) -> kinetic, gravity, contact, total``
* ``end_effector(x, udot, p) -> position, velocity, acceleration`` of the tip of the last link

Choices that keep build time low as the link count grows: the accelerations come from a sparse
LDL^T factorisation node (``ca.solve(M, f, "ldl")``), generated as a loop rather than an
unrolled symbolic solve; the Jacobian is assembled as -M^-1 dR/dx with R(x, a) = M(q) a - f
differentiated by CasADi's AD, rather than differentiating through the solve.
"""

from __future__ import annotations

import hashlib
import json
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import casadi as ca
import sympy as sp

from jointplay.common.files import atomic_write_text
from jointplay.derive.slots import (
    PER_JOINT_DOC,
    add_step_slots,
    function_slots,
    shared_slots,
    slot,
)
from jointplay.derive.symbolic import SymbolicModel, derive
from jointplay.derive.to_casadi import SympyToCasadi
from jointplay.robot import Robot
from jointplay.robot.robotio import robot_to_toml
from jointplay.robot.structure import CLEARANCE_KINDS, MOVING_KINDS
from jointplay.store.formulation import formulation_for
from jointplay.store.layout import Layout
from jointplay.store.model import DEFERRED_SOURCE_NAME, LAYOUT_NAME, ROBOT_NAME, SOURCE_NAME
from jointplay.store.stamp import provenance

# CasADi's common-subexpression elimination on every emitted function: the symbolic laws and
# AD repeat subexpressions that are not shared nodes (at 12 clearance joints it takes the
# straight-line state Jacobian from 33779 to 21697 instructions). It merges identical
# operations only, so every output is bit for bit what it was.
FUNCTION_OPTIONS: dict[str, Any] = {"cse": True}


def _function(name: str, inputs: list[Any], outputs: list[Any],
              input_names: list[str] | None = None, output_names: list[str] | None = None
              ) -> ca.Function:
    """``ca.Function`` with FUNCTION_OPTIONS (and the slots' names, when given)."""
    if input_names is None or output_names is None:
        return ca.Function(name, inputs, outputs, FUNCTION_OPTIONS)
    return ca.Function(name, inputs, outputs, input_names, output_names, FUNCTION_OPTIONS)


@dataclass
class Emitted:
    source: str  # the C text, header included
    layout: dict[str, Any]
    timings: dict[str, float]
    deferred_source: str = ""  # the deferred library's C text, header included


@dataclass(frozen=True)
class _Inputs:
    """The SX inputs every function shares: coordinates, speeds, state, parameters, torques
    and the impact speeds captured at each clearance joint's contact onset."""

    q: Any
    u: Any
    x: Any
    p: Any
    tau: Any
    v_imp: Any


# The deferred library: what integration and a default run never call, compiled on the first
# call that needs it (see jointplay.store.model). Its C holds the input blocks of the full
# Jacobian (torques, parameters, impact speeds: over a third of the 12-link chain's gcc time)
# and two wrappers over the eager library's own functions, which it is linked against:
# ``jac_forward_dynamics`` (the state block is the eager ``jac_state``, not compiled twice) and
# ``differentiable_forward_dynamics``, ``forward_dynamics`` beside that Jacobian, for CasADi's
# integrators (a compiled function's Jacobian is looked up in its own library).
INPUT_JACOBIANS = "jac_forward_dynamics_inputs"
DEFERRED_FUNCTIONS = (INPUT_JACOBIANS,)
DEFERRED_EXPORTS = (INPUT_JACOBIANS, "jac_forward_dynamics", "differentiable_forward_dynamics",
                    "jac_differentiable_forward_dynamics")


# Where the dynamics come from: "closed", Kane's mass matrix and forcing, solved by LDL^T;
# "recursive", the recursion over the chain (see jointplay.derive.recursive).
FORMULATIONS = ("closed", "recursive")


def build_functions(model: SymbolicModel, formulation: str | None = None
                    ) -> tuple[list[ca.Function], dict[str, Any]]:
    """CasADi functions for a symbolic model, and the description of their slots.

    ``formulation`` defaults to the one the model was derived for; a model derived for the
    recursion has no closed form to emit."""
    formulation = formulation or model.formulation
    if formulation not in FORMULATIONS:
        raise ValueError(f"formulation must be one of {', '.join(FORMULATIONS)}, "
                         f"got {formulation!r}")
    if formulation == "closed" and model.mass_matrix is None:
        raise ValueError("this model was derived for the recursive formulation; derive it "
                         "with formulation='closed' to emit the closed form")
    inputs = _symbolic_inputs(model)
    convert = _converter(model, inputs)
    if formulation == "recursive":
        per_joint, potential, kinetic, gravity_pot, tip, dynamics, converters = _recursive(
            model, inputs, convert)
        fn_mass, fn_forcing, fn_fd, fn_jac, fn_jac_state = dynamics
    else:
        per_joint, potential = _contact_outputs(model, convert, inputs.v_imp)
        # Converted after the contact laws, which bind the placeholder forces the equations
        # use.
        mass = convert(model.mass_matrix)
        forcing = convert(model.forcing)
        kinetic = convert(model.kinetic_energy)
        gravity_pot = convert(model.gravity_potential)
        tip = convert(model.tip_position)
        fn_mass, fn_forcing, fn_fd, fn_jac, fn_jac_state = _dynamics_functions(
            model, inputs, mass, forcing)
    fn_contact, fn_energy = _contact_and_energy_functions(inputs, per_joint, kinetic,
                                                          gravity_pot, potential)
    fn_tip = _end_effector_function(model, inputs, tip)

    slots = shared_slots(model)
    functions = function_slots(model, slots)
    layout = {
        "structure": model.structure.as_dict(),
        "coordinates": [c.as_dict() for c in model.coordinates],
        "parameters": [prm.as_dict() for prm in model.parameters],
        "torque_joints": model.torque_joints,
        "clearance_joints": [c.index for c in model.clearance],
        "functions": functions,
    }
    extra = wear_function(model, convert, inputs.x, inputs.p, inputs.v_imp, slots.x, slots.p,
                          slots.v_imp, slots.joints, functions,
                          converters if formulation == "recursive" else None)
    fn_rk4, fn_radau = fixed_step_functions(fn_fd, fn_jac_state)
    add_step_slots(functions, fn_rk4.name(), fn_radau.name(), RADAU_NEWTON_ITERATIONS, model,
                   slots)
    return [fn_mass, fn_forcing, fn_fd, fn_jac, fn_jac_state, fn_contact, fn_energy, fn_tip,
            fn_rk4, fn_radau, *extra], layout


def _symbolic_inputs(model: SymbolicModel) -> _Inputs:
    n = model.n_coordinates
    q = ca.SX.sym("q", n)
    u = ca.SX.sym("u", n)
    return _Inputs(q=q, u=u, x=ca.vertcat(q, u), p=ca.SX.sym("p", len(model.parameters)),
                   tau=ca.SX.sym("tau", len(model.torques)),
                   v_imp=ca.SX.sym("v_imp", len(model.clearance)))


def _converter(model: SymbolicModel, inputs: _Inputs) -> SympyToCasadi:
    """A sympy-to-SX converter whose leaves are the model's symbols bound to the inputs."""
    leaves: dict[sp.Basic, Any] = {}
    leaves.update({s: inputs.q[i] for i, s in enumerate(model.q)})
    leaves.update({s: inputs.u[i] for i, s in enumerate(model.u)})
    leaves.update({s: inputs.p[i] for i, s in enumerate(model.parameter_symbols)})
    leaves.update({s: inputs.tau[i] for i, s in enumerate(model.torques)})
    return SympyToCasadi(leaves)


def _contact_outputs(model: SymbolicModel, convert: SympyToCasadi, v_imp: Any
                     ) -> tuple[dict[str, list[Any]], Any]:
    """Each clearance joint's law as SX, one list per ``contact`` output, and the summed
    elastic potential; binds the equations' placeholder forces to the law's forces."""
    per_joint: dict[str, list[Any]] = {k: [] for k in PER_JOINT_DOC}
    potential = ca.SX(0)
    for j, terms in enumerate(model.clearance):
        convert._cache[terms.impact_speed] = v_imp[j]
        law = terms.law
        values = {
            "delta": convert(law.penetration),
            "delta_dot": convert(law.penetration_rate),
            "v_t": convert(law.sliding_speed),
            "f_n": convert(law.normal_force),
            "f_t": convert(law.friction_force),
            "f_x": convert(law.force_x),
            "f_y": convert(law.force_y),
            "dissipation": convert(law.dissipation),
        }
        for key, value in values.items():
            per_joint[key].append(value)
        # The equations use the placeholders; bind them to the law's forces.
        convert._cache[terms.force_x] = values["f_x"]
        convert._cache[terms.force_y] = values["f_y"]
        convert._cache[terms.force_t] = values["f_t"]
        potential = potential + convert(law.potential)
    return per_joint, potential


def _recursive(model: SymbolicModel, inputs: _Inputs, convert: SympyToCasadi
               ) -> tuple[dict[str, list[Any]], Any, Any, Any, Any,
                          tuple[ca.Function, ...], list[SympyToCasadi]]:
    """The contact outputs, energies, tip and the four dynamics functions from the recursion
    over the chain (see :mod:`jointplay.derive.recursive`)."""
    from jointplay.derive import recursive

    n = model.n_coordinates
    q, u, x, p, tau, v_imp = inputs.q, inputs.u, inputs.x, inputs.p, inputs.tau, inputs.v_imp
    slots: dict[tuple[int, str], int] = {(c.joint, c.kind): i
                                         for i, c in enumerate(model.coordinates)}
    by_name = {prm.name: i for i, prm in enumerate(model.parameters)}

    def parameter(name: str) -> Any:
        return p[by_name[name]]

    structure = model.structure
    thetas, omegas = recursive.kinematics(structure, q, u, slots, parameter)
    converters = _joint_converters(model, inputs, slots, parameter, thetas, omegas)
    per_joint: dict[str, list[Any]] = {key: [] for key in PER_JOINT_DOC}
    potential = ca.SX(0)
    for joint_convert in converters:
        law = model.clearance[0].law  # every joint's law is the template's, rebound
        for key, value in zip(PER_JOINT_DOC, _law_values(law), strict=True):
            per_joint[key].append(joint_convert(value))
        potential = potential + joint_convert(law.potential)
    contact = {terms.index: (per_joint["f_x"][j], per_joint["f_y"][j], per_joint["f_t"][j])
               for j, terms in enumerate(model.clearance)}
    torque_slots = {joint: i for i, joint in enumerate(model.torque_joints)}
    chain = recursive.chain(structure, q, u, tau, slots, torque_slots, parameter, contact,
                            thetas, omegas)
    forcing = -recursive.inverse_dynamics(chain, ca.SX.zeros(n, 1))
    acc = recursive.forward_dynamics(chain)
    names = ["x", "tau", "p", "v_imp"]
    fn_forcing = _function("forcing", [x, tau, p, v_imp], [forcing], names, ["f"])
    fn_fd = _function("forward_dynamics", [x, tau, p, v_imp], [ca.vertcat(u, acc)], names,
                        ["xdot"])
    # da/dy = -M^-1 dID/dy at the computed a (Carpentier and Mansard), M^-1 by the ABA.
    acc_sym = ca.SX.sym("a", n)
    jacobians = _RecursiveJacobians(model, inputs, chain, contact, acc_sym, slots, torque_slots,
                                    parameter, thetas, omegas, fn_fd, acc)
    fn_mass = jacobians.mass_matrix()
    fn_jac_state = jacobians.state()
    xm, taum, pm, vm = jacobians.mx_inputs
    blocks = jacobians.inputs(xm, taum, pm, vm)
    fn_jac = _input_jacobians(xm, taum, pm, vm, blocks)
    return (per_joint, potential, chain.kinetic, chain.gravity_potential, chain.tip,
            (fn_mass, fn_forcing, fn_fd, fn_jac, fn_jac_state), converters)


def _input_jacobians(xm: Any, taum: Any, pm: Any, vm: Any, blocks: list[Any]) -> ca.Function:
    """``jac_forward_dynamics_inputs``: d xdot / d tau, d p and d v_imp, the blocks of the full
    Jacobian that integration never calls; they go into the deferred library."""
    return _function(INPUT_JACOBIANS, [xm, taum, pm, vm], blocks, ["x", "tau", "p", "v_imp"],
                     ["jac_xdot_tau", "jac_xdot_p", "jac_xdot_v_imp"])


# From this many coordinates on, the recursion's state Jacobian differentiates the inverse
# dynamics a pass of columns at a time in a loop (C the size of a few recursions' tangents,
# growing linearly with the chain) instead of as straight-line code (C quadratic in the chain,
# but AD there skips what a column's seed does not reach). Measured on 20 and 32 clearance
# joints (60 and 96 coordinates; `python benchmarks/formulations.py --links 20,32 --structures
# clearance --no-paper --closed-up-to 0 --pinocchio` with `--looped-from 1`, then `1000`):
# straight-line code was 2.3x and 8.2x cheaper per call, for 1.08x and 1.31x the build time
# and 1.4x and 2.3x gcc's peak memory (1.3 GB at 96 coordinates). Beyond the measured range
# the loop keeps the build bounded. (Runs one after the other on a loaded 2-core machine.)
LOOPED_STATE_JACOBIAN_FROM = 100
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


def differentiates_the_aba(structure: Any) -> bool:
    """Whether the recursion's straight-line state Jacobian is AD of the ABA's accelerations
    (da/dx directly) rather than -M^-1 dID/dx (AD of the RNEA, then 2n solves through the
    articulated factors).

    Where every joint with coordinates has three (a clearance joint), no joint passes an
    articulated inertia on (it is exactly zero), so a column's tangent through the ABA stays
    near the joint it is seeded at, while -M^-1 dID/dx multiplies a dense dID/dx column by
    M^-1 for each of the 2n columns. Where a joint has one or two coordinates, the articulated
    inertias it passes on depend on every coordinate below it and their derivatives fill the
    tangents. Measured with `python benchmarks/formulations.py --links 12 --structures
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
    fn_nominal = _function(f"{name}_nominal", inputs, [nominal])
    fn_tangents = _function(f"{name}_tangents", [*inputs, nominal_sym, start], [body])
    passes = -(-size // width)
    looped = fn_tangents.map(f"{name}_loop", "serial", passes, list(range(len(inputs) + 1)),
                             [])
    starts = ca.DM([list(range(0, passes * width, width))])
    return looped(*args, fn_nominal(*args), starts)[:, :size]


class _RecursiveJacobians:
    """The recursion's mass matrix and the Jacobians of its accelerations.

    da/dy = -M^-1 dID/dy at the computed accelerations a (Carpentier and Mansard, RSS 2018):
    dID/dy is differentiated with the contact forces held as symbols, then chained with each
    law's own Jacobian (a law is local to its joint, so it is differentiated once, not once per
    output). M^-1 is applied column by column through the articulated factors, computed once.
    The columns are loops in the C over passes of COLUMNS_PER_PASS columns, so the code grows
    with the chain, not with the chain squared; only the state Jacobian of short chains is
    straight-line code (below LOOPED_STATE_JACOBIAN_FROM coordinates), and for a chain of
    clearance joints only it is AD of the ABA's accelerations (see differentiates_the_aba).
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
        self.fn_factors = _function("articulated_factors", [q, inputs.p], [factors])
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
        return _function("mass_matrix", [qm, pm],
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
        d_forces = ca.jacobian(self.forces, x)
        if n < LOOPED_STATE_JACOBIAN_FROM and self.direct:
            # da/dx by AD of the ABA itself, straight-line: no dID/dx, no M^-1 solves.
            jac_sx = ca.vertcat(ca.horzcat(ca.SX(n, n), ca.SX.eye(n)),
                                ca.jacobian(self.acceleration, x))
            return _function("jac_state", [x, tau, p, v_imp], [jac_sx],
                             ["x", "tau", "p", "v_imp"], ["jac_xdot_x"])
        if n < LOOPED_STATE_JACOBIAN_FROM:
            # dID/dx as straight-line code: AD skips what a column's seed does not reach.
            d_residual = ca.jacobian(self.residual, x)
            if self.held.numel():
                d_residual = d_residual + ca.mtimes(ca.jacobian(self.residual, self.held),
                                                    d_forces)
            d_residual = ca.substitute(d_residual, self.held, self.forces)
            # Dense, so that each column the solves read is contiguous (zeros written here cost
            # less than densifying the sparse output afterwards).
            fn_parts = _function("jac_state_parts", [x, tau, p, v_imp, self.acc_sym],
                                 [ca.densify(d_residual)])
            return _function("jac_state", [xm, taum, pm, vm],
                             [self._state_from_parts(fn_parts(xm, taum, pm, vm, acc_m),
                                                     factors_m)],
                             ["x", "tau", "p", "v_imp"], ["jac_xdot_x"])
        fn_forces = _function("contact_forces_x", [x, p, v_imp], [self.forces, d_forces])
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
        return _function("jac_state", [xm, taum, pm, vm], [jac_x],
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
        fn_solve = _function("mass_matrix_solve", [self.factor_sym, columns, identity],
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
        fn_forces = _function("contact_forces_inputs", [x, p, v_imp],
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


def _law_values(law: Any) -> list[Any]:
    """A law's expressions in the order of the ``contact`` outputs (PER_JOINT_DOC)."""
    return [law.penetration, law.penetration_rate, law.sliding_speed, law.normal_force,
            law.friction_force, law.force_x, law.force_y, law.dissipation]


def _joint_converters(model: SymbolicModel, inputs: _Inputs, slots: dict[tuple[int, str], int],
                      parameter: Any, thetas: list[Any], omegas: list[Any]
                      ) -> list[SympyToCasadi]:
    """For each clearance joint, a converter that binds the template law's generic symbols to
    that joint's coordinates, links' angles and rates, impact speed and parameters."""
    template = model.template
    if template is None:
        return []
    shared = {symbol: inputs.p[i] for i, symbol in enumerate(model.parameter_symbols)}
    converters = []
    for j, terms in enumerate(model.clearance):
        i = terms.index
        ex, ey, vx, vy = template.eccentricity
        a, b = slots[(i, "ex")], slots[(i, "ey")]
        leaves: dict[sp.Basic, Any] = {
            **shared, ex: inputs.q[a], ey: inputs.q[b], vx: inputs.u[a], vy: inputs.u[b],
            template.angles[0]: thetas[i - 2] if i > 1 else ca.SX(0),
            template.angles[1]: thetas[i - 1],
            template.speeds[0]: omegas[i - 2] if i > 1 else ca.SX(0),
            template.speeds[1]: omegas[i - 1],
            template.impact_speed: inputs.v_imp[j]}
        leaves.update({symbol: parameter(f"joint{i}.{attribute}")
                       for attribute, symbol in template.joint_parameters.items()})
        converters.append(SympyToCasadi(leaves))
    return converters


def _dynamics_functions(model: SymbolicModel, inputs: _Inputs, mass: Any, forcing: Any
                        ) -> tuple[ca.Function, ...]:
    """``mass_matrix``, ``forcing``, ``forward_dynamics``, ``jac_forward_dynamics`` and
    ``jac_state`` from the closed form."""
    n = model.n_coordinates
    q, x, p, tau, v_imp = inputs.q, inputs.x, inputs.p, inputs.tau, inputs.v_imp
    fn_mass = _function("mass_matrix", [q, p], [mass], ["q", "p"], ["M"])
    fn_forcing = _function("forcing", [x, tau, p, v_imp], [forcing],
                             ["x", "tau", "p", "v_imp"], ["f"])
    acc_sym = ca.SX.sym("a", n)
    residual = ca.mtimes(mass, acc_sym) - forcing
    fn_residual_jac_x = _function("residual_jacobian", [x, acc_sym, tau, p, v_imp],
                                    [ca.jacobian(residual, x)])
    fn_residual_jac_rest = _function(
        "residual_jacobian_inputs", [x, acc_sym, tau, p, v_imp],
        [ca.jacobian(residual, arg) for arg in [tau, p, v_imp]])
    return (fn_mass, fn_forcing,
            *_forward_dynamics(model, fn_mass, fn_forcing, fn_residual_jac_x,
                               fn_residual_jac_rest))


def _forward_dynamics(model: SymbolicModel, fn_mass: ca.Function, fn_forcing: ca.Function,
                      fn_residual_jac_x: ca.Function, fn_residual_jac_rest: ca.Function
                      ) -> tuple[ca.Function, ca.Function, ca.Function]:
    """Forward dynamics, its Jacobian and the Jacobian's state block alone, as MX graphs
    around a sparse LDL^T solve."""
    n = model.n_coordinates
    xm = ca.MX.sym("x", 2 * n)
    taum = ca.MX.sym("tau", len(model.torques))
    pm = ca.MX.sym("p", len(model.parameters))
    vm = ca.MX.sym("v_imp", len(model.clearance))
    um = xm[n:]
    mass_m = fn_mass(xm[:n], pm)
    acc = ca.solve(mass_m, fn_forcing(xm, taum, pm, vm), "ldl")
    xdot = ca.vertcat(um, acc)
    names = ["x", "tau", "p", "v_imp"]
    fn_fd = _function("forward_dynamics", [xm, taum, pm, vm], [xdot], names, ["xdot"])
    dres = [fn_residual_jac_x(xm, acc, taum, pm, vm),
            *fn_residual_jac_rest(xm, acc, taum, pm, vm)]
    blocks = []
    for arg, dr in zip([xm, taum, pm, vm], dres, strict=True):
        d_acc = -ca.solve(mass_m, dr, "ldl")
        d_vel = ca.jacobian(um, arg)  # [0 I] for x, zero for the rest
        blocks.append(ca.vertcat(d_vel, d_acc))
    # Not densified: the driver reads the output's pattern as CSC, which a dense one is not
    # (CasADi writes a dense pattern in a short form).
    fn_jac_state = _function("jac_state", [xm, taum, pm, vm], [blocks[0]], names,
                               ["jac_xdot_x"])
    return fn_fd, _input_jacobians(xm, taum, pm, vm, blocks[1:]), fn_jac_state


def _contact_and_energy_functions(inputs: _Inputs, per_joint: dict[str, list[Any]],
                                  kinetic: Any, gravity_pot: Any, potential: Any
                                  ) -> tuple[ca.Function, ca.Function]:
    """``contact`` (one column per output, one row per clearance joint) and ``energy``."""
    x, p, v_imp = inputs.x, inputs.p, inputs.v_imp

    def stack(values: list[Any]) -> Any:
        return ca.vertcat(*values) if values else ca.SX(0, 1)

    contact_outs = [stack(per_joint[k]) for k in per_joint]
    fn_contact = _function("contact", [x, p, v_imp], contact_outs,
                             ["x", "p", "v_imp"], list(per_joint))
    total = kinetic + gravity_pot + potential
    fn_energy = _function("energy", [x, p], [kinetic, gravity_pot, potential, total],
                            ["x", "p"], ["kinetic", "gravity", "contact", "total"])
    return fn_contact, fn_energy


def _end_effector_function(model: SymbolicModel, inputs: _Inputs, tip: Any) -> ca.Function:
    """``end_effector``: the tip's position and, by forward-mode AD, velocity and
    acceleration."""
    q, u, x, p = inputs.q, inputs.u, inputs.x, inputs.p
    udot = ca.SX.sym("udot", model.n_coordinates)
    tip_vel = ca.jtimes(tip, q, u)
    tip_acc = ca.jtimes(tip_vel, x, ca.vertcat(u, udot))
    return _function("end_effector", [x, udot, p], [tip, tip_vel, tip_acc],
                       ["x", "udot", "p"], ["position", "velocity", "acceleration"])


def wear_function(model: SymbolicModel, convert: SympyToCasadi, x: Any, p: Any, v_imp: Any,
                  x_slot: dict[str, Any], p_slot: dict[str, Any], v_slot: dict[str, Any],
                  joints: list[str], functions: dict[str, Any],
                  joint_converters: list[SympyToCasadi] | None = None) -> list[ca.Function]:
    """``wear(x, p, v_imp)``, the Archard integrands per joint (see :mod:`.wear`), emitted only
    for a structure that asks for wear. With ``joint_converters`` (the recursive
    formulation), the integrands are the template joint's, bound joint by joint."""
    if not model.structure.wear:
        return []
    from jointplay.derive.wear import OUTPUTS, wear_terms

    columns: list[list[Any]] = [[] for _ in OUTPUTS]
    if joint_converters is not None and model.template is not None:
        t = model.template
        generic = wear_terms(t.law, 0, *t.eccentricity, t.angles, t.speeds,
                             t.parameter).values()
        for joint_convert in joint_converters:
            for column, value in zip(columns, generic, strict=True):
                column.append(joint_convert(value))
    psym = dict(zip([prm.name for prm in model.parameters], model.parameter_symbols,
                    strict=True))
    names = [c.name for c in model.coordinates]
    for terms in model.clearance if joint_converters is None else []:
        j = terms.index
        ex, ey = (model.q[names.index(f"{axis}{j}")] for axis in ("ex", "ey"))
        vx, vy = (model.u[names.index(f"{axis}{j}")] for axis in ("ex", "ey"))
        values = wear_terms(terms.law, j, ex, ey, vx, vy, terms.angles, terms.speeds,
                            psym.__getitem__).values()
        for column, value in zip(columns, values, strict=True):
            column.append(convert(value))
    outs = [ca.vertcat(*column) for column in columns]
    out_names = [name for name, _, _ in OUTPUTS]
    functions["wear"] = {"inputs": [x_slot, p_slot, v_slot],
                         "outputs": [slot(name, len(joints), unit, doc,
                                           [f"{name}{j}" for j in joints])
                                     for name, unit, doc in OUTPUTS]}
    return [_function("wear", [x, p, v_imp], outs, ["x", "p", "v_imp"], out_names)]


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
    rk4 = _function("rk4_step", [x, tau, h, p, v], [x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)],
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
    radau = _function("radau_step", [x, tau, h, p, v], [x + z[:, 2], increment],
                        names, ["x_next", "newton_increment"])
    return rk4, radau


_FULL_JACOBIAN_IN = ("x", "tau", "p", "v_imp", "out_xdot")
_FULL_JACOBIAN_OUT = ("jac_xdot_x", "jac_xdot_tau", "jac_xdot_p", "jac_xdot_v_imp")


def _switch(names: tuple[str, ...]) -> str:
    cases = "".join(f'    case {i}: return "{name}";\n' for i, name in enumerate(names))
    return f"  switch (i) {{\n{cases}    default: return 0;\n  }}\n"


def _exported(name: str, call: str, n_in: int, n_out: int, names_in: tuple[str, ...],
              names_out: tuple[str, ...], sparsity_in: str, sparsity_out: str, work: str
              ) -> str:
    """The entry points CasADi's ``external`` reads, for a function implemented by ``call``
    (C statements ending in a return) and ``work`` (statements setting the four sizes)."""
    sizes = "casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w"
    real = "const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem"
    export = "CASADI_SYMBOL_EXPORT"
    return (
        f"{export} int {name}({real}) {{\n  (void) mem;\n{call}}}\n\n"
        f"{export} int {name}_checkout(void) {{\n  return 0;\n}}\n\n"
        f"{export} void {name}_release(int mem) {{\n  (void) mem;\n}}\n\n"
        f"{export} void {name}_incref(void) {{\n}}\n\n"
        f"{export} void {name}_decref(void) {{\n}}\n\n"
        f"{export} casadi_int {name}_n_in(void) {{ return {n_in};}}\n\n"
        f"{export} casadi_int {name}_n_out(void) {{ return {n_out};}}\n\n"
        f"{export} casadi_real {name}_default_in(casadi_int i) {{\n  (void) i;\n"
        "  return 0;\n}\n\n"
        f"{export} const char* {name}_name_in(casadi_int i) {{\n{_switch(names_in)}}}\n\n"
        f"{export} const char* {name}_name_out(casadi_int i) {{\n{_switch(names_out)}}}\n\n"
        f"{export} const casadi_int* {name}_sparsity_in(casadi_int i) {{\n{sparsity_in}}}\n\n"
        f"{export} const casadi_int* {name}_sparsity_out(casadi_int i) {{\n{sparsity_out}}}"
        "\n\n"
        f"{export} int {name}_work({sizes}) {{\n{work}  return 0;\n}}\n\n"
        f"{export} int {name}_work_bytes({sizes}) {{\n{work}"
        "  if (sz_arg) *sz_arg *= sizeof(const casadi_real*);\n"
        "  if (sz_res) *sz_res *= sizeof(casadi_real*);\n"
        "  if (sz_iw) *sz_iw *= sizeof(casadi_int);\n"
        "  if (sz_w) *sz_w *= sizeof(casadi_real);\n"
        "  return 0;\n}\n\n")


def deferred_wrappers(n_state: int) -> str:
    """The C of the deferred library's wrappers over the eager library (see DEFERRED_EXPORTS),
    appended to the CasADi code of the input blocks."""
    real = "const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem"
    sizes = "casadi_int* sz_arg, casadi_int* sz_res, casadi_int* sz_iw, casadi_int* sz_w"
    inputs = INPUT_JACOBIANS
    head = (
        "/* Wrappers over the eager library, which this one is linked against. */\n"
        + "".join(f"int {fn}({real});\nint {fn}_work({sizes});\n"
                  f"const casadi_int* {fn}_sparsity_in(casadi_int i);\n"
                  f"const casadi_int* {fn}_sparsity_out(casadi_int i);\n"
                  for fn in ("jac_state", "forward_dynamics"))
        + f"\nstatic const casadi_int jp_nominal_sparsity[4] = {{{n_state}, 1, 0, 0}};\n\n"
        "static casadi_int jp_max(casadi_int a, casadi_int b) { return a > b ? a : b; }\n\n"
        "/* The state block from jac_state, the others from " + inputs + ". A callee uses\n"
        " * the pointer arrays beyond its own inputs and outputs as scratch, and the caller's\n"
        " * arrays are its own (kept between calls), so this function's fifth input and its\n"
        " * outputs are put back before it returns; a block not asked for (a null pointer) is\n"
        " * not computed. */\n"
        "static int jp_full_jacobian(const casadi_real** arg, casadi_real** res, "
        "casadi_int* iw, casadi_real* w) {\n"
        "  const casadi_real* nominal = arg[4];\n"
        "  casadi_real* out[4];\n  casadi_int i;\n  int status = 0;\n"
        "  for (i = 0; i < 4; ++i) out[i] = res[i];\n"
        "  if (out[0]) {\n    res[0] = out[0];\n"
        "    status = jac_state(arg, res, iw, w, 0);\n  }\n"
        "  if (!status && (out[1] || out[2] || out[3])) {\n"
        "    res[0] = out[1];\n    res[1] = out[2];\n    res[2] = out[3];\n"
        f"    status = {inputs}(arg, res, iw, w, 0);\n  }}\n"
        "  arg[4] = nominal;\n"
        "  for (i = 0; i < 4; ++i) res[i] = out[i];\n"
        "  return status;\n}\n\n"
        f"static void jp_full_jacobian_work({sizes}) {{\n"
        "  casadi_int a0, r0, i0, w0, a1, r1, i1, w1;\n"
        "  jac_state_work(&a0, &r0, &i0, &w0);\n"
        f"  {inputs}_work(&a1, &r1, &i1, &w1);\n"
        "  if (sz_arg) *sz_arg = jp_max(jp_max(a0, a1), 5);\n"
        "  if (sz_res) *sz_res = jp_max(jp_max(r0, r1), 4);\n"
        "  if (sz_iw) *sz_iw = jp_max(i0, i1);\n"
        "  if (sz_w) *sz_w = jp_max(w0, w1);\n}\n\n")
    full_in = (f"  if (i >= 0 && i < 4) return {inputs}_sparsity_in(i);\n"
               "  return i == 4 ? jp_nominal_sparsity : 0;\n")
    full_out = ("  if (i == 0) return jac_state_sparsity_out(0);\n"
                f"  if (i > 0 && i < 4) return {inputs}_sparsity_out(i - 1);\n  return 0;\n")
    full_call = "  return jp_full_jacobian(arg, res, iw, w);\n"
    full_work = "  jp_full_jacobian_work(sz_arg, sz_res, sz_iw, sz_w);\n"
    text = head
    for name in ("jac_forward_dynamics", "jac_differentiable_forward_dynamics"):
        text += _exported(name, full_call, 5, 4, _FULL_JACOBIAN_IN, _FULL_JACOBIAN_OUT,
                          full_in, full_out, full_work)
    text += _exported(
        "differentiable_forward_dynamics", "  return forward_dynamics(arg, res, iw, w, 0);\n",
        4, 1, _FULL_JACOBIAN_IN[:4], ("xdot",),
        "  return forward_dynamics_sparsity_in(i);\n",
        "  return forward_dynamics_sparsity_out(i);\n",
        "  forward_dynamics_work(sz_arg, sz_res, sz_iw, sz_w);\n")
    return text


def _slot_summary(layout: dict[str, Any]) -> str:
    lines = [" * Functions (inputs -> outputs; column vectors, dense, float64):"]
    for name, fn in layout["functions"].items():
        ins = ", ".join(f"{s['name']}[{s['shape'][0]}]" for s in fn["inputs"])
        outs = ", ".join(f"{s['name']}[{'x'.join(map(str, s['shape']))}]" for s in fn["outputs"])
        lines.append(f" *   {name}({ins}) -> {outs}")
        if "jacobian" in fn:
            lines.append(f" *   {fn['jacobian']}: d {name} / d each input, CasADi's calling "
                         "convention")
    for described in layout["functions"]["forward_dynamics"]["inputs"]:
        entries = described.get("entries", [])
        lines.append(f" * {described['name']} [{described['unit']}]: {described['doc']}")
        for start in range(0, len(entries), 6):
            lines.append(f" *     {start}: {', '.join(entries[start:start + 6])}")
    return "\n".join(lines) + "\n"


def header(prov: dict[str, str], robot_name: str, layout: dict[str, Any],
           deferred: bool = False) -> str:
    """The provenance header of model.c, or with ``deferred`` of the deferred library's C."""
    if deferred:
        about = (" * The deferred part of this model: compiled on the first call that needs it,\n"
                 f" * linked against the library of {SOURCE_NAME}. Functions, in CasADi's calling\n"
                 " * convention (their slots are forward_dynamics' and its Jacobian's):\n"
                 + "".join(f" *   {name}\n" for name in DEFERRED_EXPORTS))
    else:
        about = (" * Every input and output slot is described, with names and units, in "
                 "layout.json.\n" + _slot_summary(layout))
    return (
        "/* GENERATED FILE: DO NOT EDIT.\n"
        " * Regenerate: `jointplay derive robot.toml --out <this folder>`, or for the models\n"
        " * checked in under generated/: `pytest tests/test_generated.py --update-generated`.\n"
        f" * model: {robot_name}\n"
        f" * generator: jointplay.derive {prov['generator']}, casadi {prov['casadi']}, "
        f"sympy {prov['sympy']}\n"
        f" * formulation: {prov.get('formulation', 'closed')}\n"
        f" * input hash: {prov['input_hash']}\n"
        + about
        + " */\n"
    )


def emit(robot: Robot, formulation: str | None = None) -> Emitted:
    """Derive and emit the C source and layout for a robot's structure.

    ``formulation``: "closed", "recursive" or "auto"; None takes ``$JOINTPLAY_FORMULATION``,
    else "auto" (see :mod:`jointplay.store.formulation`)."""
    structure = robot.structure()
    formulation = formulation_for(structure, formulation)
    t0 = time.perf_counter()
    model = derive(structure, formulation)
    t1 = time.perf_counter()
    functions, layout = build_functions(model, formulation)
    gen = ca.CodeGenerator(SOURCE_NAME, {"with_header": False, "verbose": False})
    deferred_gen = ca.CodeGenerator(DEFERRED_SOURCE_NAME, {"with_header": False,
                                                           "verbose": False})
    for fn in functions:
        (deferred_gen if fn.name() in DEFERRED_FUNCTIONS else gen).add(fn)
    body = gen.dump()
    deferred_body = deferred_gen.dump() + deferred_wrappers(2 * model.n_coordinates)
    prov = {**provenance(structure.as_dict(), formulation),
            "code_sha256": hashlib.sha256(body.encode()).hexdigest(),
            "deferred_code_sha256": hashlib.sha256(deferred_body.encode()).hexdigest()}
    # Through the runtime's own type: what is written is what the loader reads back.
    layout = Layout.from_dict({"name": robot.name, "provenance": prov, **layout,
                               "deferred": list(DEFERRED_EXPORTS)}).as_dict()
    source = header(prov, robot.name, layout) + body
    deferred_source = header(prov, robot.name, layout, deferred=True) + deferred_body
    t2 = time.perf_counter()
    return Emitted(source=source, layout=layout,
                   timings={"derive": t1 - t0, "emit": t2 - t1, **model.timings},
                   deferred_source=deferred_source)


def write_generated(robot: Robot, folder: str | Path, formulation: str | None = None
                    ) -> Emitted:
    """Write model.c, layout.json and the robot description into ``folder`` atomically."""
    emitted = emit(robot, formulation)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    atomic_write_text(folder / SOURCE_NAME, emitted.source)
    atomic_write_text(folder / DEFERRED_SOURCE_NAME, emitted.deferred_source)
    atomic_write_text(folder / LAYOUT_NAME, json.dumps(emitted.layout, indent=1) + "\n")
    atomic_write_text(folder / ROBOT_NAME, robot_to_toml(robot))
    return emitted
