"""The layout's description of every emitted function: each input and output slot with its
name, shape, unit, meaning and entry names (written to layout.json and summarised in the C
header)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from jointplay.derive.symbolic import SymbolicModel


def slot(name: str, size: int | tuple[int, int], unit: str, doc: str,
         entries: list[str] | None = None) -> dict[str, Any]:
    """One input or output slot: its name, shape, unit, meaning and entry names."""
    shape = [size, 1] if isinstance(size, int) else list(size)
    out: dict[str, Any] = {"name": name, "shape": shape, "unit": unit, "doc": doc}
    if not isinstance(size, int):
        out["matrix"] = True
    if entries is not None:
        out["entries"] = entries
    return out


@dataclass(frozen=True)
class SharedSlots:
    """The layout slots several functions share (state, parameters, torques, impact speeds),
    and the entry names the per-function slots are built from."""

    x: dict[str, Any]
    p: dict[str, Any]
    tau: dict[str, Any]
    v_imp: dict[str, Any]
    coord_names: list[str]
    x_entries: list[str]
    joints: list[str]


# One output per clearance joint of ``contact``, in order: (unit, doc).
PER_JOINT_DOC = {
    "delta": ("m", "penetration |e| - c (negative: no contact)"),
    "delta_dot": ("m/s", "normal rate d(delta)/dt"),
    "v_t": ("m/s", "sliding speed of the contact points along the tangent"),
    "f_n": ("N", "normal contact force (>= 0)"),
    "f_t": ("N", "friction force on the journal along the tangent"),
    "f_x": ("N", "total contact force on the journal, x"),
    "f_y": ("N", "total contact force on the journal, y"),
    "dissipation": ("W", "power taken out by contact damping and friction (>= 0)"),
}


def shared_slots(model: SymbolicModel) -> SharedSlots:
    """The state, parameter, torque and impact-speed slots, named from the model."""
    n = model.n_coordinates
    coord_names = [c.name for c in model.coordinates]
    speed_names = [f"d{c}" for c in coord_names]
    x_entries = coord_names + speed_names
    joints = [str(c.index) for c in model.clearance]
    param_names = [prm.name for prm in model.parameters]
    tau_names = [f"tau{j}" for j in model.torque_joints]
    vimp_names = [f"v_imp{j}" for j in joints]
    return SharedSlots(
        x=slot("x", 2 * n, "rad, m, rad/s, m/s",
                "state: coordinates then their time derivatives", x_entries),
        p=slot("p", len(param_names), "SI", "parameter vector (see 'parameters')",
                param_names),
        tau=slot("tau", len(tau_names), "N m",
                  "drive torque of each moving joint (on link i, reaction on link i-1)",
                  tau_names),
        v_imp=slot("v_imp", len(model.clearance), "m/s",
                    "normal approach speed captured at the onset of each joint's current impact",
                    vimp_names),
        coord_names=coord_names, x_entries=x_entries, joints=joints)


def function_slots(model: SymbolicModel, slots: SharedSlots) -> dict[str, Any]:
    """The layout's inputs and outputs of every function but the fixed steps and wear."""
    n, nc = model.n_coordinates, len(model.clearance)
    x_slot, p_slot, tau_slot, v_slot = slots.x, slots.p, slots.tau, slots.v_imp
    coord_names, x_entries, joints = slots.coord_names, slots.x_entries, slots.joints
    return {
        "mass_matrix": {"inputs": [slot("q", n, "rad, m", "coordinates", coord_names), p_slot],
                        "outputs": [slot("M", (n, n), "kg, kg m, kg m^2", "mass matrix")]},
        "forcing": {"inputs": [x_slot, tau_slot, p_slot, v_slot],
                    "outputs": [slot("f", n, "N m, N", "M du/dt = f", coord_names)]},
        "forward_dynamics": {"inputs": [x_slot, tau_slot, p_slot, v_slot],
                             "outputs": [slot("xdot", 2 * n, "rad/s, m/s, rad/s^2, m/s^2",
                                               "state derivative", x_entries)],
                             "jacobian": "jac_forward_dynamics"},
        "jac_state": {"inputs": [x_slot, tau_slot, p_slot, v_slot],
                      "outputs": [slot("jac_xdot_x", (2 * n, 2 * n), "1/s and mixed",
                                       "d xdot / d x, the state block of "
                                       "jac_forward_dynamics alone (what the BDF needs)")]},
        "contact": {"inputs": [x_slot, p_slot, v_slot],
                    "outputs": [slot(k, nc, unit, doc, [f"{k}{j}" for j in joints])
                                for k, (unit, doc) in PER_JOINT_DOC.items()]},
        "normal_force": {"inputs": [x_slot, p_slot, v_slot],
                         "outputs": [slot("f_n", nc, *PER_JOINT_DOC["f_n"],
                                          [f"f_n{j}" for j in joints])]},
        "energy": {"inputs": [x_slot, p_slot],
                   "outputs": [slot("kinetic", 1, "J", "kinetic energy"),
                               slot("gravity", 1, "J", "gravitational potential energy"),
                               slot("contact", 1, "J",
                                     "elastic contact energy, sum of K d+^(n+1)/(n+1)"),
                               slot("total", 1, "J", "kinetic + gravity + contact")]},
        "end_effector": {"inputs": [x_slot, slot("udot", n, "rad/s^2, m/s^2",
                                                  "accelerations", coord_names), p_slot],
                         "outputs": [slot("position", 2, "m", "tip of the last link"),
                                     slot("velocity", 2, "m/s", "tip velocity"),
                                     slot("acceleration", 2, "m/s^2", "tip acceleration")]},
    }


def add_step_slots(functions: dict[str, Any], rk4: str, radau: str, newton_iterations: int,
                   model: SymbolicModel, slots: SharedSlots) -> None:
    """The layout entries of the fixed-step functions named ``rk4`` and ``radau`` (the Radau
    step runs ``newton_iterations`` simplified Newton iterations)."""
    n = model.n_coordinates
    n_tau = len(model.torque_joints)
    step_inputs = [slots.x, None, slot("h", 1, "s", "step size"), slots.p, slots.v_imp]
    for name, stages, doc in (
            (rk4, "t, t + h/2, t + h", "explicit fourth-order Runge-Kutta step"),
            (radau, "t + c_i h, c = ((4 - 6^0.5)/10, (4 + 6^0.5)/10, 1)",
             f"implicit Radau IIA step (3 stages, order 5), {newton_iterations} "
             "simplified Newton iterations")):
        ins = list(step_inputs)
        ins[1] = slot("tau_stages", (n_tau, 3), "N m",
                       f"drive torques at the stage times {stages}, one column per stage")
        outs = [slot("x_next", 2 * n, "rad, m, rad/s, m/s", f"state after one {doc}",
                      slots.x_entries)]
        functions[name] = {"inputs": ins, "outputs": outs}
        if name == radau:
            outs.append(slot("newton_increment", 1, "rad, m, rad/s, m/s",
                              "max norm of the last Newton update (convergence check)"))
            functions[name]["newton_iterations"] = newton_iterations
