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
from jointplay.derive.deferred import (
    DEFERRED_EXPORTS,
    DEFERRED_FUNCTIONS,
    INPUT_DIRECTIONAL,
    INPUT_DIRECTIONS,
    INPUT_JACOBIANS,
    deferred_wrappers,
)
from jointplay.derive.fixed_step import RADAU_NEWTON_ITERATIONS, fixed_step_functions
from jointplay.derive.recursive_jacobians import RecursiveJacobians
from jointplay.derive.slots import (
    PER_JOINT_DOC,
    add_step_slots,
    function_slots,
    shared_slots,
    slot,
)
from jointplay.derive.symbolic import SymbolicModel, derive
from jointplay.derive.to_casadi import SympyToCasadi, emitted_function
from jointplay.robot import Robot
from jointplay.robot.robotio import robot_to_toml
from jointplay.store.formulation import formulation_for
from jointplay.store.layout import Layout
from jointplay.store.model import DEFERRED_SOURCE_NAME, LAYOUT_NAME, ROBOT_NAME, SOURCE_NAME
from jointplay.store.stamp import provenance


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
    fn_contact, fn_normal, fn_energy = _contact_and_energy_functions(
        inputs, per_joint, kinetic, gravity_pot, potential)
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
    return [fn_mass, fn_forcing, fn_fd, fn_jac, _input_directions(fn_fd), fn_jac_state,
            fn_contact, fn_normal, fn_energy, fn_tip, fn_rk4, fn_radau, *extra], layout


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
    return SympyToCasadi(leaves, formulation=model.formulation)


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
    fn_forcing = emitted_function("forcing", [x, tau, p, v_imp], [forcing], names, ["f"])
    fn_fd = emitted_function("forward_dynamics", [x, tau, p, v_imp], [ca.vertcat(u, acc)], names,
                        ["xdot"])
    # da/dy = -M^-1 dID/dy at the computed a (Carpentier and Mansard), M^-1 by the ABA.
    acc_sym = ca.SX.sym("a", n)
    jacobians = RecursiveJacobians(model, inputs, chain, contact, acc_sym, slots, torque_slots,
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
    return emitted_function(INPUT_JACOBIANS, [xm, taum, pm, vm], blocks, ["x", "tau", "p", "v_imp"],
                     ["jac_xdot_tau", "jac_xdot_p", "jac_xdot_v_imp"])


def _input_directions(fn_fd: ca.Function) -> ca.Function:
    """``forward_dynamics_input_directions(x, tau, p, v_imp, seeds) -> d_xdot``: the
    derivative of ``forward_dynamics`` along each column of ``seeds`` in (p, v_imp), by
    forward-mode AD (what a forward sensitivity step needs: d xdot / d p times the named
    parameters' directions, plus d xdot / d v_imp times the impact speeds' derivatives),
    dense, INPUT_DIRECTIONS columns; it goes into the deferred library."""
    shapes = [fn_fd.size_in(i) for i in range(4)]
    xm, taum, pm, vm = (ca.MX.sym(name, *shape)
                        for name, shape in zip(("x", "tau", "p", "v_imp"), shapes, strict=True))
    inputs = ca.vertcat(pm, vm)
    seeds = ca.MX.sym("seeds", inputs.shape[0], INPUT_DIRECTIONS)
    derivative = ca.jtimes(fn_fd(xm, taum, pm, vm), inputs, seeds)
    return emitted_function(INPUT_DIRECTIONAL, [xm, taum, pm, vm, seeds],
                            [ca.densify(derivative)], ["x", "tau", "p", "v_imp", "seeds"],
                            ["d_xdot"])


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
        converters.append(SympyToCasadi(leaves, formulation=model.formulation))
    return converters


def _dynamics_functions(model: SymbolicModel, inputs: _Inputs, mass: Any, forcing: Any
                        ) -> tuple[ca.Function, ...]:
    """``mass_matrix``, ``forcing``, ``forward_dynamics``, ``jac_forward_dynamics`` and
    ``jac_state`` from the closed form."""
    n = model.n_coordinates
    q, x, p, tau, v_imp = inputs.q, inputs.x, inputs.p, inputs.tau, inputs.v_imp
    fn_mass = emitted_function("mass_matrix", [q, p], [mass], ["q", "p"], ["M"])
    fn_forcing = emitted_function("forcing", [x, tau, p, v_imp], [forcing],
                             ["x", "tau", "p", "v_imp"], ["f"])
    acc_sym = ca.SX.sym("a", n)
    residual = ca.mtimes(mass, acc_sym) - forcing
    fn_residual_jac_x = emitted_function("residual_jacobian", [x, acc_sym, tau, p, v_imp],
                                    [ca.jacobian(residual, x)])
    fn_residual_jac_rest = emitted_function(
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
    fn_fd = emitted_function("forward_dynamics", [xm, taum, pm, vm], [xdot], names, ["xdot"])
    dres = [fn_residual_jac_x(xm, acc, taum, pm, vm),
            *fn_residual_jac_rest(xm, acc, taum, pm, vm)]
    blocks = []
    for arg, dr in zip([xm, taum, pm, vm], dres, strict=True):
        d_acc = -ca.solve(mass_m, dr, "ldl")
        d_vel = ca.jacobian(um, arg)  # [0 I] for x, zero for the rest
        blocks.append(ca.vertcat(d_vel, d_acc))
    # Not densified: the driver reads the output's pattern as CSC, which a dense one is not
    # (CasADi writes a dense pattern in a short form).
    fn_jac_state = emitted_function("jac_state", [xm, taum, pm, vm], [blocks[0]], names,
                               ["jac_xdot_x"])
    return fn_fd, _input_jacobians(xm, taum, pm, vm, blocks[1:]), fn_jac_state


def _contact_and_energy_functions(inputs: _Inputs, per_joint: dict[str, list[Any]],
                                  kinetic: Any, gravity_pot: Any, potential: Any
                                  ) -> tuple[ca.Function, ca.Function, ca.Function]:
    """``contact`` (one column per output, one row per clearance joint), ``normal_force``
    (its f_n alone: what the BDF driver's event scan samples, without the rest's cost) and
    ``energy``."""
    x, p, v_imp = inputs.x, inputs.p, inputs.v_imp

    def stack(values: list[Any]) -> Any:
        return ca.vertcat(*values) if values else ca.SX(0, 1)

    contact_outs = [stack(per_joint[k]) for k in per_joint]
    fn_contact = emitted_function("contact", [x, p, v_imp], contact_outs,
                             ["x", "p", "v_imp"], list(per_joint))
    fn_normal = emitted_function("normal_force", [x, p, v_imp], [stack(per_joint["f_n"])],
                                 ["x", "p", "v_imp"], ["f_n"])
    total = kinetic + gravity_pot + potential
    fn_energy = emitted_function("energy", [x, p], [kinetic, gravity_pot, potential, total],
                            ["x", "p"], ["kinetic", "gravity", "contact", "total"])
    return fn_contact, fn_normal, fn_energy


def _end_effector_function(model: SymbolicModel, inputs: _Inputs, tip: Any) -> ca.Function:
    """``end_effector``: the tip's position and, by forward-mode AD, velocity and
    acceleration."""
    q, u, x, p = inputs.q, inputs.u, inputs.x, inputs.p
    udot = ca.SX.sym("udot", model.n_coordinates)
    tip_vel = ca.jtimes(tip, q, u)
    tip_acc = ca.jtimes(tip_vel, x, ca.vertcat(u, udot))
    return emitted_function("end_effector", [x, udot, p], [tip, tip_vel, tip_acc],
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
    return [emitted_function("wear", [x, p, v_imp], outs, ["x", "p", "v_imp"], out_names)]


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
