"""The deferred library's names and the C of its wrappers over the eager library (used by
:mod:`jointplay.derive.codegen`; loaded by :mod:`jointplay.store.model`)."""

from __future__ import annotations

# The deferred library: what integration and a default run never call, compiled on the first
# call that needs it (see jointplay.store.model). Its C holds the input blocks of the full
# Jacobian (torques, parameters, impact speeds: over a third of the 12-link chain's gcc time)
# and two wrappers over the eager library's own functions, which it is linked against:
# ``jac_forward_dynamics`` (the state block is the eager ``jac_state``, not compiled twice) and
# ``differentiable_forward_dynamics``, ``forward_dynamics`` beside that Jacobian, for CasADi's
# integrators (a compiled function's Jacobian is looked up in its own library).
INPUT_JACOBIANS = "jac_forward_dynamics_inputs"
# Forward sensitivities need d xdot / d (p, v_imp) only along the named parameters'
# directions: this function gives it by forward-mode AD for INPUT_DIRECTIONS directions at a
# time (seeds, (np + nc) x INPUT_DIRECTIONS, a zero column for none), at under half the cost
# of the full input blocks of INPUT_JACOBIANS (docs/explanation/sensitivities.md, "Cost").
INPUT_DIRECTIONAL = "forward_dynamics_input_directions"
INPUT_DIRECTIONS = 4
DEFERRED_FUNCTIONS = (INPUT_JACOBIANS, INPUT_DIRECTIONAL)
DEFERRED_EXPORTS = (INPUT_JACOBIANS, INPUT_DIRECTIONAL, "jac_forward_dynamics",
                    "differentiable_forward_dynamics", "jac_differentiable_forward_dynamics")


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
