"""Per-call cost of two generated models of the same chain, side by side in one process.

Compiles (or takes from the cache) the ``model.c`` of each generated folder, binds
``forward_dynamics`` and ``jac_state`` of both to the same state (every clearance joint in
contact, as in ``build_scaling.py``) and times them through ``FastFunction.trigger`` in
interleaved rounds, so a change in the machine's load hits both alike. Prints the median and
the fastest round of each, their ratio, and the largest difference between their outputs.
Made to check that a change to how a model is emitted or split into libraries leaves what
integration calls as cheap as it was (the folders: ``jointplay derive`` of the same robot
before and after the change).

    python benchmarks/compare_libraries.py OLD_FOLDER NEW_FOLDER --rounds 30
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
from build_scaling_case import _state


def _children_cpu() -> float:
    import resource

    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def main() -> int:
    import casadi as ca

    from jointplay.robot import load_robot
    from jointplay.store.build import DEFAULT_CFLAGS, compile_source
    from jointplay.store.model import FastFunction, read_generated

    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("folders", nargs=2, type=Path, help="two generated model folders")
    parser.add_argument("--rounds", type=int, default=30, help="interleaved timing rounds")
    parser.add_argument("--round-ms", type=float, default=50.0, help="length of one round")
    parser.add_argument("--second-cflags", default=None,
                        help="compile the second folder with these flags instead of the "
                             "default (e.g. \"-Og -fPIC -shared -fno-math-errno\")")
    args = parser.parse_args()
    functions = ("forward_dynamics", "jac_state")
    bound: dict[tuple[int, str], FastFunction] = {}
    for i, folder in enumerate(args.folders):
        source, layout = read_generated(folder)
        params = np.asarray(load_robot(folder / "robot.toml").parameter_values())
        cflags = tuple(args.second_cflags.split()) if i == 1 and args.second_cflags else \
            DEFAULT_CFLAGS
        cpu = _children_cpu()
        library, seconds = compile_source(source, cflags)
        if seconds:
            print(f"{folder}: gcc {' '.join(cflags)}: {seconds:.2f} s, "
                  f"{_children_cpu() - cpu:.2f} CPU s", flush=True)
        model = argparse.Namespace(layout=layout)
        rng = np.random.default_rng(1)
        values = [_state(model, params, rng), rng.uniform(-1.0, 1.0, len(layout.torque_joints)),
                  params, np.full(len(layout.clearance_joints), 0.05)]
        for name in functions:
            fast = FastFunction(ca.external(name, str(library)))
            for buffer, value in zip(fast.inputs, values, strict=True):
                buffer[:] = value
            fast.trigger()
            bound[(i, name)] = fast
    times: dict[tuple[int, str], list[float]] = {key: [] for key in bound}
    for _ in range(args.rounds):
        for key, fast in bound.items():
            start, calls = time.perf_counter(), 0
            while time.perf_counter() - start < args.round_ms / 1e3:
                fast.trigger()
                calls += 1
            times[key].append((time.perf_counter() - start) / calls * 1e6)
    print(f"{'function':<18}{'first us':>10}{'second us':>11}{'ratio':>7}"
          f"{'fastest first / second us':>27}{'max |diff|':>12}")
    for name in functions:
        first, second = times[(0, name)], times[(1, name)]
        diff = float(np.max(np.abs(bound[(0, name)].outputs[0] - bound[(1, name)].outputs[0])))
        print(f"{name:<18}{np.median(first):>10.2f}{np.median(second):>11.2f}"
              f"{np.median(second) / np.median(first):>7.2f}"
              f"{min(first):>14.2f} / {min(second):<10.2f}{diff:>12.1e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
