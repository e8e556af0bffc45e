"""``jointplay build``: derive (if needed), compile and load a model, and evaluate it once."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

import numpy as np

from jointplay.cli.args import robot_arguments, robot_from_args
from jointplay.common.timing import per_call_seconds


def register(subparsers: Any) -> argparse.ArgumentParser:
    p_build = subparsers.add_parser("build", help="derive (if needed), compile and load a "
                                                  "model, and evaluate it once")
    robot_arguments(p_build)
    p_build.set_defaults(func=cmd_build)
    return p_build


def cmd_build(args: argparse.Namespace) -> int:
    from jointplay.mechanism.reading import is_mechanism_file

    if args.robot and is_mechanism_file(args.robot):
        return _build_mechanism(args.robot)
    robot = robot_from_args(args)
    from jointplay.store.lookup import generated_folder
    from jointplay.store.model import load_model

    t0 = time.perf_counter()
    folder = generated_folder(robot)
    t1 = time.perf_counter()
    model = load_model(folder)
    model.default_parameters = np.asarray(robot.parameter_values())
    t2 = time.perf_counter()
    print(f"model {robot.name}: {robot.n_links} links, joints "
          f"{', '.join(f'{i + 1}:{j.kind}' for i, j in enumerate(robot.joints))}")
    print(f"  generated code   {folder}")
    print(f"  compiled library {model.library}")
    print(f"  derive+emit {t1 - t0:.2f} s (0 if reused), compile {model.compile_seconds:.2f} s "
          f"(0 if cached), load {t2 - t1 - model.compile_seconds:.2f} s")
    print(f"  coordinates      {', '.join(model.coordinates)}")
    print(f"  parameters       {len(model.parameters)} (see layout.json)")
    return _check_at_rest(model)


def _build_mechanism(path: str) -> int:
    from jointplay.mechanism.model import model_for
    from jointplay.mechanism.reading import load_mechanism_scene

    scene = load_mechanism_scene(path)
    t0 = time.perf_counter()
    model = model_for(scene.mechanism)
    joints = [f"{j.name}:{j.kind}" + (" (cut)" if j.cut else "")
              for j in model.structure.joints]
    print(f"mechanism {scene.name}: joints {', '.join(joints)}")
    print(f"  compiled library {model.library}")
    print(f"  derive+emit {model.seconds['derive']:.2f} s (0 if reused), compile "
          f"{model.seconds['compile']:.2f} s (0 if cached), in all "
          f"{time.perf_counter() - t0:.2f} s")
    print(f"  coordinates      {', '.join(model.coordinates)}")
    print(f"  parameters       {len(model.parameters)} (jointplay inspect {path})")
    return 0


def _check_at_rest(model: Any) -> int:
    """Evaluate the model once at rest; 1 when anything is not finite. Then time a call."""
    p = model.parameter_vector()
    x = np.zeros(model.n_state)
    tau = np.zeros(len(model.torque_joints))
    xdot = model.forward_dynamics(x, tau, p)
    energy = model.energy(x, p)
    tip = model.end_effector(x, xdot[model.n_coordinates:], p)
    print("  at q = 0, at rest, no torque:")
    print(f"    accelerations  {np.array2string(xdot[model.n_coordinates:], precision=4)}")
    print(f"    tip position   {np.array2string(tip['position'], precision=4)} m")
    print(f"    energy         {energy['total']:.6g} J")
    bad = [name for name, value in (("accelerations", xdot), ("energy", energy["total"]))
           if not np.all(np.isfinite(value))]
    if bad:
        print(f"error: non-finite {', '.join(bad)} at the rest state", file=sys.stderr)
        return 1
    # The state Jacobian, what integration calls (the full one is in the deferred library,
    # compiled on its first use: `jointplay build` does not wait for it).
    fd = model.function("forward_dynamics")
    jac = model.function("jac_state")
    for fast in (fd, jac):
        fast(x, tau, p, np.zeros(len(model.clearance_joints)))
    fd_us, jac_us = (1e6 * per_call_seconds(f.trigger) for f in (fd, jac))
    print(f"  per call (compiled, buffer path): forward_dynamics {fd_us:.2f} us, "
          f"jac_state {jac_us:.2f} us")
    return 0
