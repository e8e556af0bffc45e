"""The state Jacobian of a chain of clearance joints by the chain rule through each link's
absolute pose and twist: code that grows linearly with the chain, cost quadratically.

Where every joint has three coordinates (a clearance joint: the angle and the eccentricity),
its subspace S_i is invertible, no joint passes an articulated inertia on, and the
articulated-body algorithm decouples (see :mod:`jointplay.derive.recursive`): link i's
absolute acceleration is A_i = I_i^-1 (S_i^-T g_i - X_{i+1}^T S_{i+1}^-T g_{i+1} + loads), with
g_i the generalised forces of joint i (drive, contact), whatever the acceleration of link i-1,
and joint i's accelerations are a_i = S_i^-1 (A_i - X_i A_{i-1} - bias_i). So a_i depends on
the states of joints i-1, i and i+1 (its *window*) and, through the pose and twist of the
link the window hangs from (link i-2), on every state below it:

* Z_m = (theta_m, omega_m, E_m, dE_m/dt), link m's absolute angle and rate and the position
  and velocity of its end, follows Z_m = psi(Z_{m-1}, x_m), x_m joint m's six states;
* a_i = phi_i(Z_{i-2}, the window's states, torques, contact forces and parameters): the
  recursion's own chain over the window alone, hung from Z_{i-2}, then the decoupled ABA
  above (the window's first link's acceleration does not need the one it hangs from);
* each joint's contact law is evaluated once, with its Jacobian with respect to its
  arguments (the eccentricity, the two links' angles and rates), and held in the windows
  that read it (three), which chain it.

psi, phi (one function per kind of window: the middle windows share one) and the law are
small SX functions differentiated by CasADi's AD: fixed-size local Jacobians, O(1) code per
kind. The chain rule then sweeps outward: dZ_m/dx_j = dpsi_m/dZ_{m-1} dZ_{m-1}/dx_j for every
joint j below link m, and joint i's rows in joint j's columns are dphi_i/dZ_{i-2}
dZ_{i-2}/dx_j, 6 x 6 and 3 x 6 products of fixed pattern, done for all j by one loop in the
C (a CasADi map) per link: code linear in the chain, cost one small product per pair of
joints, none for the pairs that are structurally zero (a link's pose depends on no joint
beyond it). One gather writes the pieces into the output's pattern (the index tables of the
gather and of the pattern grow with the square of the chain, as the Jacobian does).
"""

from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace
from typing import TYPE_CHECKING, Any

import casadi as ca

from jointplay.derive.to_casadi import SympyToCasadi, emitted_function
from jointplay.robot.structure import CLEARANCE_KINDS, MOVING_KINDS

if TYPE_CHECKING:
    from jointplay.derive.symbolic import SymbolicModel

# A link's absolute state that the windows hang from: theta, omega, E_x, E_y, dE_x, dE_y.
LINK_STATE = 6
# A joint's states in a window: angle, e_x, e_y, then their rates.
JOINT_STATES = 6
# Parameter names that belong to one link or joint (the rest are shared by all joints).
_OWNED_PREFIXES = ("link", "joint")


def applies(structure: Any) -> bool:
    """Whether the chain rule holds: every joint has three coordinates (no locked joint,
    whose link would take the next one's inertia, no ideal one)."""
    return bool(structure.joints) and all(kind in MOVING_KINDS and kind in CLEARANCE_KINDS
                                          for kind in structure.joints)


class _LocalParameters:
    """The parameters a window's function reads, as its own input vector: names as the
    window numbers its links and joints (from 1), recorded in the order first asked for."""

    def __init__(self) -> None:
        self.names: list[str] = []
        self._symbols: dict[str, Any] = {}

    def __call__(self, name: str) -> Any:
        if name not in self._symbols:
            self._symbols[name] = ca.SX.sym(name.replace(".", "_"))
            self.names.append(name)
        return self._symbols[name]

    def vector(self) -> Any:
        return (ca.vertcat(*[self._symbols[name] for name in self.names]) if self.names
                else ca.SX(0, 1))


def _global_name(name: str, offset: int) -> str:
    """A window's parameter name in the whole chain's numbering (window joint w is joint
    w + offset)."""
    owner, _, attribute = name.partition(".")
    for prefix in _OWNED_PREFIXES:
        if owner.startswith(prefix) and owner[len(prefix):].isdigit():
            return f"{prefix}{int(owner[len(prefix):]) + offset}.{attribute}"
    return name


@dataclass(frozen=True)
class _WindowKind:
    """A window's shape: its joints' count, which of them is the joint whose accelerations it
    gives (0-based) and whether it hangs from a link's state Z (else from the ground: only
    joint 1's window; joint 2's hangs from Z_0 = 0, the ground as a link). Its last link
    carries the payload: only the centre joint's accelerations are read, and they read the
    last link's inertia only where the centre is the window's last joint, the chain's last
    joint (a link's own inertia does not reach the accelerations of the joint below it)."""

    size: int
    centre: int
    hung: bool


@dataclass
class _WindowFunction:
    # (base if hung, states, tau, parameters, then per joint: forces, law Jacobian, law
    #  arguments)
    #   -> (dphi/dbase if hung, dphi/dstates)
    function: ca.Function
    parameter_names: list[str]  # in the window's numbering


# A contact law's arguments: the journal's eccentricity and its rate, the bearing's and the
# journal's links' absolute angles and rates.
LAW_ARGUMENTS = 8


def _law_arguments(ex: Any, ey: Any, vx: Any, vy: Any, theta_b: Any, theta_j: Any,
                   omega_b: Any, omega_j: Any) -> Any:
    return ca.vertcat(ex, ey, vx, vy, theta_b, theta_j, omega_b, omega_j)


@dataclass
class _LawFunction:
    # (theta, omega of the bearing's link, the joint's states, impact speed, parameters)
    #   -> (F_x, F_y, F_t), d(F)/d(arguments), the arguments
    function: ca.Function
    parameter_names: list[str]  # the joint is joint 1


def _law_function(model: SymbolicModel) -> _LawFunction:
    """A clearance joint's contact law (the template's) and its Jacobian with respect to its
    arguments: evaluated once per joint, then chained inside the windows, which hold the
    forces (three windows read each joint's forces)."""
    template = model.template
    assert template is not None  # every joint has clearance
    parameters = _LocalParameters()
    before = ca.SX.sym("before", 2)
    states = ca.SX.sym("x", JOINT_STATES)
    v_imp = ca.SX.sym("v_imp")
    angle, ex, ey, rate, vx, vy = ca.vertsplit(states)
    arguments = _law_arguments(ex, ey, vx, vy, before[0], before[0] + angle, before[1],
                               before[1] + rate)
    symbols = ca.SX.sym("arguments", LAW_ARGUMENTS)
    leaves: dict[Any, Any] = {
        symbol: parameters(prm.name)
        for prm, symbol in zip(model.parameters, model.parameter_symbols, strict=True)
        if not prm.name.startswith((*_OWNED_PREFIXES, "payload"))}
    leaves.update(dict(zip([*template.eccentricity, *template.angles, *template.speeds],
                           ca.vertsplit(symbols), strict=True)))
    leaves[template.impact_speed] = v_imp
    leaves.update({symbol: parameters(f"joint1.{attribute}")
                   for attribute, symbol in template.joint_parameters.items()})
    convert = SympyToCasadi(leaves, formulation=model.formulation)
    law = template.law
    forces = ca.vertcat(convert(law.force_x), convert(law.force_y),
                        convert(law.friction_force))
    jacobian = ca.jacobian(forces, symbols)
    forces, jacobian = ca.substitute([forces, jacobian], [symbols], [arguments])
    return _LawFunction(emitted_function(
        "chain_rule_law", [before, states, v_imp, parameters.vector()],
        [forces, jacobian, arguments]), parameters.names)


def _window_function(model: SymbolicModel, kind: _WindowKind, law_pattern: ca.Sparsity
                     ) -> _WindowFunction:
    """phi for a kind of window: the recursion's chain over the window alone with its joints'
    contact forces held (their values, and their Jacobians chained by the law's own), the
    decoupled ABA, and the Jacobians (transposed) of the centre joint's accelerations."""
    from jointplay.derive import recursive

    size = kind.size
    q = ca.SX.sym("q", 3 * size)
    u = ca.SX.sym("u", 3 * size)
    drive = bool(model.torque_joints)
    tau = ca.SX.sym("tau", size if drive else 0)
    base_sym = ca.SX.sym("base", LINK_STATE)
    # Each window joint's law: its forces, their Jacobian and the arguments it was evaluated
    # at, each an input of its own (the law's outputs are passed as they are, not copied).
    forces = [ca.SX.sym(f"forces{w}", 3) for w in range(size)]
    law_jacobians = [ca.SX.sym(f"law_jacobian{w}", law_pattern) for w in range(size)]
    law_values = [ca.SX.sym(f"law_arguments{w}", LAW_ARGUMENTS) for w in range(size)]
    parameters = _LocalParameters()
    base = (recursive.Base(*ca.vertsplit(base_sym)) if kind.hung
            else recursive.Base(*[ca.SX(0)] * LINK_STATE))
    slots = {(w, axis): 3 * (w - 1) + offset for w in range(1, size + 1)
             for offset, axis in enumerate(("angle", "ex", "ey"))}
    thetas, omegas = [], []
    theta, omega = base.theta, base.omega
    for w in range(1, size + 1):
        theta = theta + q[slots[(w, "angle")]]
        omega = omega + u[slots[(w, "angle")]]
        thetas.append(theta)
        omegas.append(omega)
    contact = {}
    for w in range(1, size + 1):
        a, b = slots[(w, "ex")], slots[(w, "ey")]
        arguments = _law_arguments(q[a], q[b], u[a], u[b],
                                   thetas[w - 2] if w > 1 else base.theta, thetas[w - 1],
                                   omegas[w - 2] if w > 1 else base.omega, omegas[w - 1])
        # The held forces, moving with the arguments as the law's Jacobian says: the value
        # is the law's (the arguments equal those it was evaluated at), the derivative too.
        held = forces[w - 1] + ca.mtimes(law_jacobians[w - 1],
                                         arguments - law_values[w - 1])
        fx, fy, ft = ca.vertsplit(held)
        contact[w] = (fx, fy, ft)
    # The window as a structure of its own (its last link carries the payload).
    structure = SimpleNamespace(joints=("clearance",) * size, links=size,
                                gravity=model.structure.gravity)
    window = recursive.chain(structure, q, u, tau, slots,  # type: ignore[arg-type]
                             {w: w - 1 for w in range(1, size + 1)} if drive else {},
                             parameters, contact, thetas, omegas, base)
    centre = _centre_accelerations(window.joints, kind.centre)
    states = ca.vertcat(q, u)
    outputs = [ca.jacobian(centre, states)]
    inputs = [states, tau, parameters.vector(),
              *[symbol for w in range(size)
                for symbol in (forces[w], law_jacobians[w], law_values[w])]]
    if kind.hung:
        outputs.insert(0, ca.jacobian(centre, base_sym))
        inputs.insert(0, base_sym)
    name = f"chain_rule_window_{size}_{kind.centre}_{'hung' if kind.hung else 'ground'}"
    return _WindowFunction(emitted_function(name, inputs, outputs), parameters.names)


def _centre_accelerations(joints: list[Any], centre: int) -> Any:
    """The accelerations of window joint ``centre`` (0-based) by the decoupled ABA: each
    link's absolute acceleration from the forces its two joints transmit, S^-T g (S is
    invertible), then a = S^-1 (A - X A_before - bias); a window hung from the ground has its
    centre at joint 0 or 1, so A_before is the ground's (zero) or the first link's."""
    from jointplay.derive import recursive

    def absolute(m: int) -> Any:
        joint = joints[m]
        force = (recursive._inverse_transpose_times(joint.S, joint.generalised)
                 + joint.external - joint.inertia_rate_times_velocity)
        if m + 1 < len(joints):
            after = joints[m + 1]
            force = force - ca.mtimes(after.X.T, recursive._inverse_transpose_times(
                after.S, after.generalised))
        return recursive.rigid_solve(joint.rigid, force)

    joint = joints[centre]
    before = (ca.mtimes(joint.X, absolute(centre - 1)) if centre > 0
              else ca.SX.zeros(3, 1))
    return recursive._inverse_times(joint.S, absolute(centre) - before - joint.bias)


def _link_function() -> ca.Function:
    """psi: a link's state from the one before and its joint's states, with its Jacobians
    with respect to both."""
    before = ca.SX.sym("before", LINK_STATE)
    states = ca.SX.sym("x", JOINT_STATES)
    length = ca.SX.sym("length")
    theta_b, omega_b, end_x, end_y, end_vx, end_vy = ca.vertsplit(before)
    angle, ex, ey, rate, vx, vy = ca.vertsplit(states)
    theta, omega = theta_b + angle, omega_b + rate
    cos, sin = ca.cos(theta), ca.sin(theta)
    after = ca.vertcat(theta, omega, end_x + ex + length * cos, end_y + ey + length * sin,
                       end_vx + vx - length * omega * sin, end_vy + vy + length * omega * cos)
    return emitted_function("chain_rule_link", [before, states, length],
                            [after, ca.jacobian(after, before), ca.jacobian(after, states)])


def _far_function(link_jacobian: ca.Sparsity, block: ca.Sparsity) -> ca.Function:
    """One step of the outward sweep for one joint j below link m: dZ_m/dx_j =
    dpsi_m/dZ_{m-1} dZ_{m-1}/dx_j, and the block of the Jacobian it gives the joint whose
    window hangs from link m, da_{m+2}/dx_j = dphi_{m+2}/dZ_m dZ_m/dx_j (3 x 6). The blocks
    dZ/dx_j keep one pattern (a link's angle moves with joint angles only, its end's
    position with no speed, and so on), which the step's product keeps."""
    step = ca.SX.sym("link_jacobian", link_jacobian)
    hung = ca.SX.sym("window_jacobian", 3, LINK_STATE)
    before = ca.SX.sym("tangent", block)
    after = ca.mtimes(step, before)
    if after.sparsity() != block:
        after = ca.project(after, block)
    return emitted_function("chain_rule_far", [step, hung, before],
                            [after, ca.densify(ca.mtimes(hung, after))])


def state_jacobian(model: SymbolicModel, slots: dict[tuple[int, str], int],
                   mx_inputs: tuple[Any, ...]) -> Any:
    """d xdot / dx = [0 I; da/dx] of a chain of clearance joints (see :func:`applies`), as an
    MX expression of the MX inputs (x, tau, p, v_imp).

    Its pattern: the 1 of I in the first n rows, and below them, in the columns of joint j,
    the rows of every joint from j - 1 on (the joints whose window holds j, and those whose
    window hangs from a link beyond j)."""
    xm, taum, pm, vm = mx_inputs
    k = model.structure.links
    n = model.n_coordinates
    by_name = {prm.name: i for i, prm in enumerate(model.parameters)}
    torque_index = {joint: i for i, joint in enumerate(model.torque_joints)}
    impact_index = {terms.index: j for j, terms in enumerate(model.clearance)}
    axes = ("angle", "ex", "ey")

    def joint_rows(joint: int) -> list[int]:
        """The rows of x that hold a joint's states, in the order of JOINT_STATES."""
        q_rows = [slots[(joint, axis)] for axis in axes]
        return q_rows + [n + r for r in q_rows]

    link = _link_function()
    law = _law_function(model)
    far = _far_function(link.sparsity_out(1), link.sparsity_out(2))
    links: list[Any] = [ca.MX.zeros(LINK_STATE)]  # Z_0: the ground
    steps: list[Any] = [None]  # dZ_m/dZ_{m-1}
    owns: list[Any] = [None]  # dZ_m/dx_m
    for m in range(1, k):
        after, d_before, d_states = link(links[m - 1], xm[joint_rows(m)],
                                         pm[by_name[f"link{m}.length"]])
        links.append(after)
        steps.append(d_before)
        owns.append(d_states)
    laws = [law.function(links[j - 1][:2], xm[joint_rows(j)], vm[impact_index[j]],
                         pm[[by_name[_global_name(name, j - 1)] for name in law.parameter_names]])
            for j in range(1, k + 1)]
    law_pattern = law.function.sparsity_out(1)
    functions: dict[_WindowKind, _WindowFunction] = {}
    # Joint i's rows come in pieces: the window's columns, and the columns of each joint
    # below the window (those of all but the last side by side, from one loop).
    pieces: list[Any] = []
    sources: dict[tuple[int, int], tuple[int, int, int]] = {}

    tangents: Any = None  # dZ_m/dx_j, j = 1 .. m, side by side
    for i in range(1, k + 1):
        first, last = max(1, i - 1), min(k, i + 1)
        # Joint 2's window hangs from the ground as a link at rest at the origin (Z_0 = 0):
        # it is then of the middle windows' kind, which saves a function.
        kind = _WindowKind(last - first + 1, i - first, i > 1)
        if kind not in functions:
            functions[kind] = _window_function(model, kind, law_pattern)
        window = functions[kind]
        joints = list(range(first, last + 1))
        rows = ([r for j in joints for r in joint_rows(j)[:3]]
                + [r for j in joints for r in joint_rows(j)[3:]])
        args = [xm[rows],
                taum[[torque_index[j] for j in joints]] if model.torque_joints else ca.MX(0, 1),
                pm[[by_name[_global_name(name, first - 1)] for name in window.parameter_names]],
                *[value for j in joints for value in laws[j - 1]]]
        if not kind.hung:
            local = window.function(*args)
        else:
            m = first - 1  # the link the window hangs from
            d_base, local = window.function(links[m], *args)
            if m == 1:  # (m = 0: the ground, which no state moves)
                tangents = owns[1]
            elif m > 1:
                # Every joint below link m at once: a loop in the C over the joints (the
                # shared factors repeated here: CasADi's map with shared inputs does the
                # same, in a wrapper whose outputs are copied once more).
                moved, blocks = far.map(m - 1, "serial")(
                    ca.repmat(steps[m], 1, m - 1), ca.repmat(d_base, 1, m - 1), tangents)
                pieces.append(blocks)
                for j in range(1, m):
                    sources[(i, j)] = (len(pieces) - 1, JOINT_STATES * (j - 1),
                                       JOINT_STATES * (j - 1) + 3)
                tangents = ca.horzcat(moved, owns[m])
            if m > 0:
                pieces.append(ca.densify(ca.mtimes(d_base, owns[m])))
                sources[(i, m)] = (len(pieces) - 1, 0, 3)
        # The window's columns are its joints' q (angle, e_x, e_y) side by side, then their u.
        pieces.append(local)
        for w, j in enumerate(joints):
            sources[(i, j)] = (len(pieces) - 1, 3 * w, 3 * len(joints) + 3 * w)
    return _assemble(pieces, sources, k, n, slots)


def _assemble(pieces: list[Any], sources: dict[tuple[int, int], tuple[int, int, int]], k: int,
              n: int, slots: dict[tuple[int, str], int]) -> Any:
    """[0 I; da/dx] from the pieces of its rows, by one gather into the output's pattern
    (see :func:`state_jacobian`). ``sources[(i, j)]``: the piece that holds joint i's rows
    in joint j's columns, and the column of j's angle there, and of its rate."""
    entries, total = [], 0
    for piece in pieces:
        rows, columns = piece.sparsity().get_triplet()
        entries.append({(r, c): total + e for e, (r, c) in
                        enumerate(zip(rows, columns, strict=True))})
        total += piece.nnz()
    one, zero = total, total + 1
    owner = {slots[(j, axis)]: (j, a) for j in range(1, k + 1)
             for a, axis in enumerate(("angle", "ex", "ey"))}
    pattern_rows: list[int] = []
    pattern_columns: list[int] = []
    gather: list[int] = []
    for column in range(2 * n):
        j, axis = owner[column % n]
        rate = column >= n
        if rate:
            pattern_rows.append(column - n)
            pattern_columns.append(column)
            gather.append(one)
        for row in range(n):
            i, component = owner[row]
            if i < j - 1:
                continue
            piece, angle_column, rate_column = sources[(i, j)]
            at = (component, (rate_column if rate else angle_column) + axis)
            pattern_rows.append(n + row)
            pattern_columns.append(column)
            gather.append(entries[piece].get(at, zero))
    pattern = ca.Sparsity.triplet(2 * n, 2 * n, pattern_rows, pattern_columns)
    # Each piece's nonzeros as a column (a cast, no copy), then the constants.
    values = ca.vertcat(*[ca.sparsity_cast(piece, ca.Sparsity.dense(piece.nnz(), 1))
                          for piece in pieces], ca.MX(ca.DM([1.0, 0.0])))
    return ca.sparsity_cast(values[gather], pattern)
