"""Closed form against recursion, and both against Pinocchio, per call, side by side.

For each case (the paper robot; a chain of k links with clearance at every joint; a chain of k
ideal joints) this derives, emits and compiles the model in both formulations (``closed``:
Kane's equations and an LDL^T solve; ``recursive``: the articulated-body algorithm and the
Jacobian -M^-1 dID/dx, see jointplay.derive.recursive) into a temporary cache, and times, in
one process and in alternating rounds (so a change in the machine's load hits every
function alike):

* ``forward_dynamics`` and ``jac_state`` (the state block of the Jacobian, what the BDF
  calls) of each formulation, inputs written in place (``FastFunction.trigger``);
* with ``--pinocchio``, Pinocchio's ``aba`` and ``computeABADerivatives`` on the same chain
  (a planar joint, 3 coordinates, for each clearance joint; a revolute joint for each ideal
  one), called from Python, so its figure includes Python's call overhead (about 1 us);
* with ``--versus-straight-line``, the recursion's ``jac_state`` once more with the
  straight-line state Jacobian (AD of the ABA) where the chain rule would be used (chains of
  clearance joints, see jointplay.derive.recursive_chain_rule), its build, and the largest
  difference between the two Jacobians relative to the largest entry.

The state has every clearance joint in contact (|e| = 1.1 c) and moving. Build figures are
the derive + emit wall time and gcc's, with gcc's peak memory. The closed form is skipped
above ``--closed-up-to`` coordinates (its build grows too fast to be worth waiting for).

Writes ``formulations.csv`` and ``formulations.md`` into ``--out`` atomically and prints the
Markdown.

    python benchmarks/formulations.py --links 1-4,8,12 --pinocchio --out out/formulations
    python benchmarks/formulations.py --links 8,12,16 --structures clearance --no-paper \
        --closed-up-to 0 --pinocchio --chain-rule-from 1 --versus-straight-line --out DIR
    python benchmarks/formulations.py --links 12,32 --structures ideal --no-paper \
        --closed-up-to 0 --pinocchio --ideal-derivatives ad --out DIR
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from build_scaling import machine_facts, markdown, parse_links, to_csv
from build_scaling_case import PAPER, _robot, pinocchio_chain

from jointplay.bench.child import ChildFailed, json_from_child
from jointplay.common.files import atomic_write_text
from jointplay.common.timing import per_call_seconds

FORMULATIONS = ("recursive", "closed")  # recursive first: gcc's peak memory is its own
COLUMNS: list[tuple[str, str, str]] = [
    ("structure", "structure", "{}"),
    ("k", "k", "{}"),
    ("n", "n", "{}"),
    ("closed_build_s", "closed build s", "{:.1f}"),
    ("recursive_build_s", "recursive build s", "{:.1f}"),
    ("recursive_gcc_mib", "recursive gcc MiB", "{:.0f}"),
    ("recursive_c_kb", "recursive C kB", "{:.0f}"),
    ("closed_fd_us", "closed fd us", "{:.2f}"),
    ("recursive_fd_us", "recursive fd us", "{:.2f}"),
    ("pinocchio_aba_us", "Pinocchio aba us", "{:.2f}"),
    ("closed_jac_us", "closed jac_state us", "{:.1f}"),
    ("recursive_jac_us", "recursive jac_state us", "{:.1f}"),
    ("pinocchio_derivatives_us", "Pinocchio ABA derivatives us", "{:.1f}"),
    ("max_rel_diff", "max rel diff", "{:.1e}"),
    ("straight_build_s", "straight-line build s", "{:.1f}"),
    ("straight_c_kb", "straight-line C kB", "{:.0f}"),
    ("straight_jac_us", "straight-line jac_state us", "{:.1f}"),
    ("straight_max_rel_diff", "jac_state vs straight-line", "{:.1e}"),
    ("load", "load", "{:.1f}"),
]


def _state(layout: dict[str, Any], params: Any, rng: Any) -> Any:
    import numpy as np

    names = [c["name"] for c in layout["coordinates"]]
    pnames = [p["name"] for p in layout["parameters"]]
    n = len(names)
    x = np.zeros(2 * n)
    for i, name in enumerate(names):
        if name.startswith("q"):
            x[i], x[n + i] = rng.uniform(-1.0, 1.0, size=2)
        elif name.startswith("ex"):
            j = name[2:]
            c = (params[pnames.index(f"joint{j}.bearing_radius")]
                 - params[pnames.index(f"joint{j}.journal_radius")])
            phi = rng.uniform(0.0, 2.0 * math.pi)
            x[i], x[i + 1] = 1.1 * c * math.cos(phi), 1.1 * c * math.sin(phi)
            x[n + i], x[n + i + 1] = rng.uniform(-1e-3, 1e-3, size=2)
    return x


def run_case(spec: dict[str, Any]) -> dict[str, Any]:
    """Build both formulations of one case and time them (and Pinocchio) interleaved."""
    import resource

    import casadi as ca
    import numpy as np

    from jointplay.derive import recursive_jacobians
    from jointplay.derive.codegen import emit
    from jointplay.store.build import DEFAULT_CFLAGS, compile_source

    if spec.get("looped_from") is not None:
        recursive_jacobians.LOOPED_STATE_JACOBIAN_FROM = spec["looped_from"]
    if spec.get("chain_rule_from") is not None:
        recursive_jacobians.CHAIN_RULE_FROM = spec["chain_rule_from"]
    if spec.get("ideal_derivatives") is not None:
        recursive_jacobians.IDEAL_DERIVATIVES_IN_CLOSED_FORM = \
            spec["ideal_derivatives"] == "closed-form"
    if spec.get("state_jacobian", "auto") != "auto":
        forced = spec["state_jacobian"] == "aba"
        recursive_jacobians.differentiates_the_aba = lambda structure: forced
    from jointplay.store.model import FastFunction

    robot = _robot(spec["structure"], spec["k"])
    params = np.asarray(robot.parameter_values(), dtype=float)
    row: dict[str, Any] = {"structure": spec["structure"], "k": spec["k"]}
    calls: dict[str, Any] = {}
    outputs: dict[str, list[Any]] = {}
    with tempfile.TemporaryDirectory(prefix="jointplay-formulations-") as tmp:

        def build(formulation: str, key: str) -> list[Any]:
            """Emit and compile ``formulation``, record its build as ``key`` and register
            its functions' calls; returns their outputs."""
            t0 = time.perf_counter()
            emitted = emit(robot, formulation)
            emit_s = time.perf_counter() - t0
            before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
            library, compile_s = compile_source(emitted.source, DEFAULT_CFLAGS,
                                                cache=Path(tmp) / key)
            peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
            row[f"{key}_build_s"] = emit_s + compile_s
            row[f"{key}_gcc_mib"] = max(peak, before) / 1024
            row[f"{key}_c_kb"] = len(emitted.source) / 1000
            x = _state(emitted.layout, params, np.random.default_rng(1))
            rng = np.random.default_rng(2)
            args = [x, rng.uniform(-1.0, 1.0, len(emitted.layout["torque_joints"])), params,
                    np.full(len(emitted.layout["clearance_joints"]), 0.05)]
            outs = []
            for name, short in (("forward_dynamics", "fd"), ("jac_state", "jac")):
                fn = FastFunction(ca.external(name, str(library)))
                for arr, value in zip(fn.inputs, args, strict=False):
                    arr[:] = value
                calls[f"{key}_{short}_us"] = fn.trigger
                outs.append(np.concatenate([np.ravel(o) for o in fn(*args)]))
            return outs

        n = len(robot.structure().moving_joints) + 2 * len(robot.structure().clearance_joints)
        row["n"] = n
        for formulation in FORMULATIONS:
            if formulation == "closed" and n > spec["closed_up_to"]:
                continue
            outputs[formulation] = build(formulation, formulation)
        if spec.get("versus_straight_line"):
            # The recursion again with the straight-line state Jacobian (AD of the ABA), for
            # chains that take the chain rule: timed in the same rounds.
            chain_rule_from = recursive_jacobians.CHAIN_RULE_FROM
            recursive_jacobians.CHAIN_RULE_FROM = 10**9
            straight = build("recursive", "straight")
            recursive_jacobians.CHAIN_RULE_FROM = chain_rule_from
            del calls["straight_fd_us"]
            chain_rule, reference = outputs["recursive"][1], straight[1]
            row["straight_max_rel_diff"] = float(np.max(np.abs(chain_rule - reference))
                                                 / max(np.max(np.abs(reference)), 1e-300))
        if spec["pinocchio"] and spec["structure"] != PAPER:
            peer = pinocchio_chain(robot)
            if peer is not None:
                calls["pinocchio_aba_us"] = peer.aba
                calls["pinocchio_derivatives_us"] = peer.derivatives
        samples: dict[str, list[float]] = {name: [] for name in calls}
        for _ in range(spec["rounds"]):
            for name, fn in calls.items():
                samples[name].append(per_call_seconds(fn, 3, spec["batch_s"]))
        row.update({name: statistics.median(v) * 1e6 for name, v in samples.items()})
    if len(outputs) == 2:
        row["max_rel_diff"] = max(
            float(np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300))
            for a, b in zip(outputs["recursive"], outputs["closed"], strict=True))
    row["load"] = os.getloadavg()[0]
    return row


def main() -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--links", type=parse_links, default=parse_links("1-4,8,12"))
    parser.add_argument("--structures", default="clearance,ideal")
    parser.add_argument("--no-paper", action="store_true")
    parser.add_argument("--pinocchio", action="store_true",
                        help="time Pinocchio's aba and computeABADerivatives beside")
    parser.add_argument("--closed-up-to", type=int, default=36,
                        help="skip the closed form above this many coordinates")
    parser.add_argument("--looped-from", type=int, default=None,
                        help="coordinates from which the recursion's state Jacobian is looped "
                             "(default: the generator's LOOPED_STATE_JACOBIAN_FROM)")
    parser.add_argument("--chain-rule-from", type=int, default=None,
                        help="coordinates from which a chain of clearance joints takes the "
                             "state Jacobian by the chain rule (default: the generator's "
                             "CHAIN_RULE_FROM)")
    parser.add_argument("--ideal-derivatives", choices=("closed-form", "ad"), default=None,
                        help="dID/dx of chains of ideal (and locked) joints: in closed form "
                             "(jointplay.derive.ideal_derivatives) or by AD of the RNEA, for "
                             "comparison (default: the generator's "
                             "IDEAL_DERIVATIVES_IN_CLOSED_FORM)")
    parser.add_argument("--versus-straight-line", action="store_true",
                        help="also build the recursion with the straight-line state Jacobian "
                             "(AD of the ABA, no chain rule) and time it in the same rounds")
    parser.add_argument("--state-jacobian", choices=("auto", "aba", "solves"), default="auto",
                        help="the recursion's straight-line state Jacobian: AD of the ABA, "
                             "-M^-1 dID/dx by solves, or the generator's choice (default)")
    parser.add_argument("--rounds", type=int, default=9, help="alternating timing rounds")
    parser.add_argument("--batch-ms", type=float, default=20.0)
    parser.add_argument("--timeout", type=float, default=3600.0, help="seconds per case")
    parser.add_argument("--out", type=Path, required=False)
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        print(json.dumps(run_case(json.loads(args.worker))))
        return 0
    if args.out is None:
        parser.error("--out is required")
    cases = [] if args.no_paper else [(PAPER, 4)]
    cases += [(s.strip(), k) for s in args.structures.split(",") if s.strip()
              for k in args.links]
    plan = [args.out / "formulations.csv", args.out / "formulations.md"]
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    for structure, k in cases:
        spec = {"structure": structure, "k": k, "pinocchio": args.pinocchio,
                "closed_up_to": args.closed_up_to, "rounds": args.rounds,
                "looped_from": args.looped_from, "state_jacobian": args.state_jacobian,
                "chain_rule_from": args.chain_rule_from,
                "ideal_derivatives": args.ideal_derivatives,
                "versus_straight_line": args.versus_straight_line,
                "batch_s": args.batch_ms / 1000}
        try:
            row = json_from_child([sys.executable, __file__, "--worker", json.dumps(spec)],
                                  args.timeout)
        except ChildFailed as err:
            row = {**spec, "error": str(err)}
        rows.append(row)
        print(json.dumps(row), file=sys.stderr, flush=True)
    facts = machine_facts()
    command = " ".join(["python", "benchmarks/formulations.py", *sys.argv[1:]])
    text = "\n".join([f"`{command}`", "",
                      *[f"- {key}: {value}" for key, value in facts.items()], "",
                      markdown(rows, COLUMNS), ""])
    atomic_write_text(plan[0], to_csv(rows, [k for k, _, _ in COLUMNS] + ["error"]))
    atomic_write_text(plan[1], text)
    print(text)
    return 1 if any(r.get("error") for r in rows) else 0


if __name__ == "__main__":
    raise SystemExit(main())
