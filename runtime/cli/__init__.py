"""The ``jointplay`` command.

  jointplay build   [ROBOT.toml | flags]                 derive, compile, load and check a model
  jointplay derive  [ROBOT.toml | flags] --out DIR       write the generated model to DIR
  jointplay inspect [ROBOT.toml | flags] [--format text|latex|markdown] [--out FILE.md]
  jointplay simulate [SCENE.toml] [--out RUN.h5] [--csv RUN.csv] [--plot DIR] [--compare-ideal]
                     [--output-step H] [--animate FILE.gif|mp4]

With neither a file nor flags, the robot is the built-in default (the paper's 4-link arm).
Bad input exits with status 2 and a message naming the field and what is allowed; nothing is
written. Deriving imports sympy; loading and evaluating a generated model does not.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
import traceback
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common import interrupts
from jointplay.common.errors import DescriptionError, JointplayError
from jointplay.common.timing import per_call_seconds
from jointplay.robot.description import Robot, load_robot, robot_from_flags

EXIT_BAD_INPUT = 2


def _robot_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("robot", nargs="?", help="robot description (TOML); default: the "
                                                  "built-in paper robot")
    group = parser.add_argument_group("robot from flags (instead of a file)")
    group.add_argument("--links", help="number of links, 1 to 32")
    group.add_argument("--clearance", default="", help="joints with clearance, e.g. 2,5")
    group.add_argument("--locked", default="", help="locked joints, e.g. 1")
    group.add_argument("--locked-clearance", default="",
                       help="locked joints whose journal still has play")
    group.add_argument("--friction", choices=("none", "coulomb"), default="coulomb")
    group.add_argument("--contact-law", default="lankarani-nikravesh",
                       choices=("lankarani-nikravesh", "hunt-crossley", "gonthier", "flores"))
    group.add_argument("--no-gravity", action="store_true")


def _robot_from_args(args: argparse.Namespace) -> Robot:
    flags_used = args.links is not None or any(
        (args.clearance, args.locked, args.locked_clearance))
    if args.robot and flags_used:
        raise DescriptionError("--links", "give either a description file or flags, not both")
    if args.robot:
        return load_robot(args.robot)
    if flags_used:
        if args.links is None:
            raise DescriptionError("--links", "is required when joints are given by flags")
        return robot_from_flags(args.links, clearance=args.clearance, locked=args.locked,
                                locked_clearance=args.locked_clearance, friction=args.friction,
                                contact_law=args.contact_law, gravity=not args.no_gravity)
    from jointplay import default_robot

    return default_robot()


def _check_writable_dir(path: Path, flag: str) -> None:
    target = path if path.exists() else path.parent
    if path.exists() and not path.is_dir():
        raise DescriptionError(flag, f"{path} exists and is not a folder")
    while not target.exists():
        target = target.parent
    if not os.access(target, os.W_OK):
        raise DescriptionError(flag, f"cannot write to {target}: permission denied")


def _check_writable_file(path: Path, flag: str) -> None:
    if path.is_dir():
        raise DescriptionError(flag, f"{path} is a folder; give a file name")
    if not path.parent.exists():
        raise DescriptionError(flag, f"folder {path.parent} does not exist")
    if not os.access(path.parent, os.W_OK):
        raise DescriptionError(flag, f"cannot write to {path.parent}: permission denied")


def cmd_derive(args: argparse.Namespace) -> int:
    robot = _robot_from_args(args)
    out = Path(args.out)
    _check_writable_dir(out, "--out")
    from jointplay.derive import write_generated

    emitted = write_generated(robot, out)
    t = emitted.timings
    print(f"wrote {out}/model.c ({len(emitted.source) / 1024:.0f} KiB), layout.json, robot.toml "
          f"in {t['derive']:.2f} s derive + {t['emit']:.2f} s emit")
    return 0


def cmd_inspect(args: argparse.Namespace) -> int:
    robot = _robot_from_args(args)
    out = Path(args.out) if args.out else None
    if out is not None:
        _check_writable_file(out, "--out")
    from jointplay.derive import derive
    from jointplay.derive.inspect import render

    fmt = args.format or ("markdown" if out is not None and out.suffix == ".md" else "text")
    text = render(derive(robot.structure()), fmt, simplify=args.simplify, title=robot.name)
    if out is None:
        sys.stdout.write(text)
    else:
        from jointplay.common.files import atomic_write_text

        atomic_write_text(out, text)
        print(f"wrote {out} ({fmt})")
    return 0


def cmd_build(args: argparse.Namespace) -> int:
    robot = _robot_from_args(args)
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
    fd = model.function("forward_dynamics")
    jac = model.function("jac_forward_dynamics")
    for fast, args_ in ((fd, (x, tau, p, np.zeros(len(model.clearance_joints)))),
                        (jac, (x, tau, p, np.zeros(len(model.clearance_joints)), []))):
        fast(*args_)
    fd_us, jac_us = (1e6 * per_call_seconds(f.trigger) for f in (fd, jac))
    print(f"  per call (compiled, buffer path): forward_dynamics {fd_us:.2f} us, "
          f"jac_forward_dynamics {jac_us:.2f} us")
    return 0


def _overrides(items: list[str]) -> dict[str, float]:
    out: dict[str, float] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise DescriptionError("--set", f"expects NAME=VALUE (e.g. friction.mu=0.1), got "
                                   f"{item!r}")
        try:
            number = float(value)
        except ValueError:
            raise DescriptionError(f"--set {name}", f"must be a number, got {value!r}") \
                from None
        if not np.isfinite(number):
            raise DescriptionError(f"--set {name}", f"must be finite, got {value!r}")
        out[name.strip()] = number
    return out


# Run settings --set may change (numbers only; the integrator has its own flag).
_RUN_NUMBERS = ("t_end", "output_step", "rtol", "atol", "step", "max_steps")


def _run_overrides(overrides: dict[str, float]) -> dict[str, Any]:
    """Take the ``run.NAME`` entries out of ``overrides`` (in place) as run-setting changes."""
    changes: dict[str, Any] = {}
    for name in [n for n in overrides if n.startswith("run.")]:
        value = overrides.pop(name)
        key = name.removeprefix("run.")
        if key not in _RUN_NUMBERS:
            raise DescriptionError(f"--set {name}", "is not a run setting --set can change; "
                                   f"these are run.{', run.'.join(_RUN_NUMBERS)} (the "
                                   "integrator: --integrator)")
        if key == "max_steps":
            if not value.is_integer():
                raise DescriptionError(f"--set {name}", f"must be a whole number, got {value}")
            changes[key] = int(value)
        else:
            changes[key] = value
    return changes


def cmd_simulate(args: argparse.Namespace) -> int:
    from jointplay.results.write import check_distinct_outputs, check_output_path
    from jointplay.scene.definition import default_scene, load_scene, scene_inputs

    # Everything is validated before anything is derived, compiled or written.
    scene = load_scene(args.scene) if args.scene else default_scene()
    changes = {k: v for k, v in (("integrator", args.integrator), ("rtol", args.rtol),
                                 ("atol", args.atol), ("t_end", args.t_end),
                                 ("step", args.step), ("output_step", args.output_step))
               if v is not None}
    if changes:
        try:
            scene = scene.with_run(**changes)
        except DescriptionError as err:
            name = err.field.removeprefix("run.")
            if name not in changes:  # a consequence elsewhere in the scene
                raise
            raise DescriptionError("--" + name.replace("_", "-"), err.message) from None
    overrides = _overrides(args.set or [])
    run_changes = _run_overrides(overrides)
    if run_changes:
        try:
            scene = scene.with_run(**run_changes)
        except DescriptionError as err:
            raise DescriptionError(f"--set {err.field}", err.message) from None
    check_distinct_outputs({"--out": args.out, "--csv": args.csv})
    for flag, path in (("--out", args.out), ("--csv", args.csv)):
        if path:
            check_output_path(path, flag, inputs=scene_inputs(scene))
    if args.csv:
        from jointplay.results.write import impacts_csv_path

        check_output_path(impacts_csv_path(args.csv), "--csv", inputs=scene_inputs(scene))
    if args.plot:
        _check_writable_dir(Path(args.plot), "--plot")
    if args.animate:
        from jointplay.results.animate import check_animation_path

        check_animation_path(args.animate)
    if overrides:
        from jointplay.robot.description import with_parameters

        try:
            scene = scene.with_robot(with_parameters(scene.robot, overrides))
        except DescriptionError as err:
            raise DescriptionError(f"--set {err.field}", err.message) from None

    from jointplay.simulation import load_scene_model, simulate

    quiet = args.quiet
    t0 = time.perf_counter()
    model = load_scene_model(scene)
    if not quiet:
        print(f"scene {scene.name}: model {model.name} ready in "
              f"{time.perf_counter() - t0:.2f} s ({', '.join(model.coordinates)})")
    result = simulate(scene, model=model, compare_ideal=args.compare_ideal, quiet=quiet)
    written = []
    if args.out:
        from jointplay.results.write import write_hdf5

        write_hdf5(result, args.out)
        written.append(args.out)
    if args.csv:
        from jointplay.results.write import write_csv

        written += [str(p) for p in write_csv(result, args.csv)]
    if args.plot:
        from jointplay.results.plots import plot_result

        written += [str(p) for p in plot_result(result, args.plot)]
    if args.animate:
        from jointplay.results.animate import animate_result

        written.append(str(animate_result(result, args.animate, quiet=quiet)))
    if not quiet:
        print(summary(result))
        for path in written:
            print(f"wrote {path}")
    return 0


def _output_step_text(result: Any) -> str:
    if result.n_samples < 2:
        return "at the output samples"
    step = float(np.median(np.diff(result.t)))
    return f"every {step * 1e3:.4g} ms" if step >= 1e-4 else f"every {step * 1e6:.4g} us"


def contact_lines(result: Any) -> list[str]:
    """Per clearance joint: impacts, largest approach speed, and the located peak force and
    penetration with their times (from the impact table); a sampled value says it is one."""
    from jointplay.results.contacts import joint_contacts

    lines = []
    for c in joint_contacts(result):
        if c.impacts == 0 and c.located:
            lines.append(f"  joint {c.joint}: no impacts, no contact")
            continue
        head = f"  joint {c.joint}: {c.impacts} impacts"
        if c.impacts:
            head += (f", largest approach speed {c.max_approach_speed:.4g} m/s (onset at "
                     f"{c.max_approach_speed_time:.7g} s)")
        lines.append(head)
        if c.located:
            lines.append(f"    peak normal force {c.peak_force:.4g} N at {c.peak_force_time:.7g} "
                         f"s, max penetration {c.max_penetration * 1e6:.4g} um at "
                         f"{c.max_penetration_time:.7g} s (located)")
        else:
            lines.append(f"    peak normal force and max penetration {c.note}")
            lines.append(f"    sampled {_output_step_text(result)} (not the peak): normal "
                         f"force up to {c.sampled_peak_force:.4g} N, penetration up to "
                         f"{c.sampled_max_penetration * 1e6:.4g} um")
    return lines


def summary(result: Any) -> str:
    """A few lines a person reads after a run."""
    st = result.stats
    lines = [
        f"simulated {result.t[-1]:g} s with {result.integrator} in {st['wall_time_s']:.2f} s "
        f"wall ({st['realtime_factor']:.3f} x real time)",
        f"  steps {st['steps']}, right-hand sides {st['rhs_evaluations']}, Jacobians "
        f"{st['jacobian_evaluations']}, contact events {st['events']}, impacts "
        f"{st['impacts']}",
        f"  energy balance: max |E - E0 - W_drive + D| = "
        f"{np.max(np.abs(result.energy['balance'])):.3g} J "
        f"(drive work {result.energy['drive_work'][-1]:.4g} J, dissipated "
        f"{result.energy['dissipated'][-1]:.4g} J)",
    ]
    lines += contact_lines(result)
    for k, j in enumerate(result.wear.joints if result.wear is not None else ()):
        wear = result.wear
        lines.append(f"  joint {j} wear: volume {wear.volume[k]:.4g} m^3, deepest "
                     f"{wear.bearing_depth[k].max():.4g} m on the bearing, "
                     f"{wear.journal_depth[k].max():.4g} m on the journal")
    if result.ideal is not None:
        ideal = result.ideal
        for name, a, b, unit in (("position", result.tip_position, ideal.tip_position, "m"),
                                 ("velocity", result.tip_velocity, ideal.tip_velocity, "m/s"),
                                 ("acceleration", result.tip_acceleration,
                                  ideal.tip_acceleration, "m/s^2")):
            err = np.max(np.linalg.norm(a - b, axis=1))
            lines.append(f"  end-effector {name} error vs ideal joints: max {err:.4g} {unit} "
                         f"(sampled {_output_step_text(result)})")
    return "\n".join(lines)


def make_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="jointplay",
        description="Dynamics of planar serial robots with revolute-joint clearance.")
    sub = parser.add_subparsers(dest="command", required=True)
    p_build = sub.add_parser("build", help="derive (if needed), compile and load a model, "
                                           "and evaluate it once")
    _robot_arguments(p_build)
    p_build.set_defaults(func=cmd_build)
    p_derive = sub.add_parser("derive", help="write a robot's generated model to a folder")
    _robot_arguments(p_derive)
    p_derive.add_argument("--out", required=True, help="folder to write model.c, layout.json "
                                                        "and robot.toml into")
    p_derive.set_defaults(func=cmd_derive)
    p_inspect = sub.add_parser("inspect", help="show a model's equations")
    _robot_arguments(p_inspect)
    p_inspect.add_argument("--format", choices=("text", "latex", "markdown"))
    p_inspect.add_argument("--out", help="write to this file (.md: Markdown) instead of stdout")
    p_inspect.add_argument("--simplify", action="store_true",
                           help="trigonometric simplification (readable, slow beyond 3 links)")
    p_inspect.set_defaults(func=cmd_inspect)
    p_sim = sub.add_parser("simulate", help="simulate a scene (default: the paper's example)")
    p_sim.add_argument("scene", nargs="?", help="scene file (TOML); default: the built-in "
                                                 "paper scene")
    p_sim.add_argument("--out", help="write the results to this HDF5 file (atomically)")
    p_sim.add_argument("--csv", help="also write a flat CSV table")
    p_sim.add_argument("--plot", help="write PNG figures into this folder")
    p_sim.add_argument("--compare-ideal", action="store_true",
                       help="also simulate the scene with ideal joints and report the errors")
    p_sim.add_argument("--integrator", help="override run.integrator (cvodes, idas, rk4, radau)")
    p_sim.add_argument("--rtol", type=float, help="override run.rtol")
    p_sim.add_argument("--atol", type=float, help="override run.atol")
    p_sim.add_argument("--step", type=float, help="override run.step (fixed-step methods)")
    p_sim.add_argument("--output-step", type=float, metavar="H",
                       help="override run.output_step (s): the spacing of the output samples; "
                            "it must divide run.t_end")
    p_sim.add_argument("--animate", metavar="FILE.gif|mp4",
                       help="write an animation of the arm, each journal's orbit magnified in "
                            "an inset (mp4 needs ffmpeg)")
    p_sim.add_argument("--t-end", type=float, help="override run.t_end (s)")
    p_sim.add_argument("--set", action="append", metavar="NAME=VALUE",
                       help="override a robot parameter, e.g. --set friction.mu=0.1 "
                            "(repeatable; never recompiles), or a run setting, e.g. --set "
                            "run.output_step=1e-6")
    p_sim.add_argument("--quiet", action="store_true", help="no progress bar, no summary")
    p_sim.set_defaults(func=cmd_simulate)
    from jointplay import bench, sweep
    from jointplay.neural import control, identify, study

    identify.register(sub)
    control.register(sub)
    study.register(sub)
    sweep.register(sub)
    bench.register(sub)
    return parser


def _add_debug_flag(parser: argparse.ArgumentParser) -> None:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                # SUPPRESS: a subcommand's absent flag must not reset the top-level one.
                sub.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                                 help="show the full traceback of an error")


def main(argv: list[str] | None = None) -> int:
    parser = make_parser()
    parser.add_argument("--debug", action="store_true",
                        help="show the full traceback of an error")
    _add_debug_flag(parser)
    args = parser.parse_args(argv)
    with interrupts.installed():
        try:
            code = int(args.func(args))
            interrupts.raise_if_interrupted()  # one that a library swallowed still counts
            return code
        except KeyboardInterrupt:
            return _interrupted(args)
        except Exception as err:
            # Compiled code may turn an interrupt into an error of its own: still Ctrl-C.
            if interrupts.interrupted():
                return _interrupted(args)
            return _report(err, args)


def _interrupted(args: argparse.Namespace) -> int:
    if args.debug:
        traceback.print_exc()
    status = interrupts.exit_status()
    print("jointplay: interrupted" if status == interrupts.EXIT_INTERRUPTED
          else "jointplay: terminated", file=sys.stderr)
    return status


def _report(err: Exception, args: argparse.Namespace) -> int:
    """One line naming the cause (the traceback only with --debug); the exit status."""
    if args.debug:
        traceback.print_exc()
    if isinstance(err, DescriptionError):
        print(f"jointplay: error: {err}", file=sys.stderr)
        return EXIT_BAD_INPUT
    if isinstance(err, JointplayError):
        text = str(err)
    elif isinstance(err, OSError):
        from jointplay.common.files import describe_os_error

        where = f"{err.filename}: " if err.filename else ""
        text = f"{where}{describe_os_error(err)}"
    elif isinstance(err, MemoryError):
        text = "out of memory; give a shorter run, fewer outputs or fewer cases"
    else:
        text = f"internal error ({type(err).__name__}: {err})"
    lines = text.splitlines() or [type(err).__name__]
    hint = "" if args.debug or isinstance(err, JointplayError) else \
        " (--debug shows the traceback)"
    print(f"jointplay: error: {lines[0]}{hint}", file=sys.stderr)
    if len(lines) > 1:  # a compiler's output, say: the detail, after the one line
        print("\n".join(lines[1:]), file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
