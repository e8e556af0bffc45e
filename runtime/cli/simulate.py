"""``jointplay simulate``: run a scene, write what was asked for, print a summary."""

from __future__ import annotations

import argparse
import contextlib
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.cli.args import (
    check_writable_dir,
    plausibility_argument,
    run_flag,
    scene_argument,
    scene_from_args,
)
from jointplay.cli.summary import summary
from jointplay.common.errors import DescriptionError, SimulationError
from jointplay.common.hints import did_you_mean

if TYPE_CHECKING:
    from jointplay.common.figure_process import FigureProcess
    from jointplay.common.files import OutputPlan
    from jointplay.results.records import SimulationResult
    from jointplay.scene.definition import Scene

# The accuracy check runs by default when it should take at most this long (wall s); it is
# estimated as CHECK_COST_RATIO times the run's own integration (10x tighter tolerances cost
# 1.3-2x on the default scene: 23 -> 40 ms at 1e-6 / 1e-5, 95 -> 123 ms at 1e-9).
VERIFY_BUDGET_S = 5.0
CHECK_COST_RATIO = 3.0

# Run settings --set may change (also --integrator, --t-end, ... for the common ones).
_RUN_NUMBERS = ("t_end", "output_step", "rtol", "atol", "step", "max_steps", "integrator",
                "plausibility")


def register(subparsers: Any) -> argparse.ArgumentParser:
    p_sim = subparsers.add_parser("simulate",
                                  help="simulate a scene (default: the paper's example)")
    scene_argument(p_sim)
    p_sim.add_argument("--out", help="write the results to this HDF5 file (atomically; a file "
                                     "name: not '-', not ending in '/')")
    p_sim.add_argument("--csv", help="also write a flat CSV table")
    p_sim.add_argument("--plot", help="write PNG figures into this folder")
    p_sim.add_argument("--compare-ideal", action="store_true",
                       help="also simulate the scene with ideal joints and report the errors")
    p_sim.add_argument("--integrator", help="override run.integrator (bdf, cvodes, idas, rk4, "
                                            "radau)")
    p_sim.add_argument("--rtol", type=float, help="override run.rtol")
    p_sim.add_argument("--atol", type=float, help="override run.atol")
    p_sim.add_argument("--step", type=float, help="override run.step (fixed-step methods)")
    p_sim.add_argument("--output-step", type=float, metavar="H",
                       help="override run.output_step (s): the spacing of the output samples; "
                            "it must divide run.t_end")
    p_sim.add_argument("--animate", metavar="FILE.gif|mp4",
                       help="write an animation of the arm or the mechanism, each journal's "
                            "orbit magnified in an inset (mp4 needs ffmpeg)")
    p_sim.add_argument("--t-end", type=float, help="override run.t_end (s)")
    plausibility_argument(p_sim)
    p_sim.add_argument("--set", action="append", metavar="NAME=VALUE",
                       help="override a robot parameter, e.g. --set friction.mu=0.1 "
                            "(repeatable; never recompiles), or a run setting, e.g. --set "
                            "run.output_step=1e-6")
    verify = p_sim.add_mutually_exclusive_group()
    verify.add_argument("--verify", dest="verify", action="store_true", default=None,
                        help="check the run against the same run at tolerances 10x tighter "
                             "and state its accuracy, however long the check takes (default: "
                             f"checked when it should take under {VERIFY_BUDGET_S:g} s)")
    verify.add_argument("--no-verify", dest="verify", action="store_false",
                        help="skip the accuracy check")
    p_sim.add_argument("--quiet", action="store_true", help="no progress bar, no summary")
    p_sim.set_defaults(func=cmd_simulate)
    return p_sim


def cmd_simulate(args: argparse.Namespace) -> int:
    from jointplay.cli.args import warn_plausibility
    from jointplay.sim import can_check_accuracy, load_scene_model, simulate

    if args.scene and _is_mechanism(args.scene):
        from jointplay.cli.mechanism import cmd_simulate_mechanism

        return cmd_simulate_mechanism(args)
    # Everything is validated before anything is derived, compiled or written.
    scene, plan = _scene(args)
    if args.verify and not can_check_accuracy(scene):
        raise DescriptionError("--verify", "the run's settings are at their limits "
                               "(run.rtol, run.atol or run.step): no tighter run can check "
                               "its accuracy; drop --verify")
    quiet = args.quiet
    with _figure_process(args) as figures:
        t0 = time.perf_counter()
        model = load_scene_model(scene)
        if not quiet:
            print(f"scene {scene.name}: model {model.name} ready in "
                  f"{time.perf_counter() - t0:.2f} s ({', '.join(model.coordinates)})")
        with warn_plausibility():
            result = simulate(scene, model=model, compare_ideal=args.compare_ideal,
                              quiet=quiet)
        result = _checked(result, scene, model, args.verify, quiet)
        written = _write(result, args, plan, quiet, figures)
    if not quiet:
        print(summary(result))
        for path in written:
            print(f"wrote {path}")
    return 0


def _is_mechanism(path: str) -> bool:
    from jointplay.mechanism.reading import is_mechanism_file

    return is_mechanism_file(path)


def _checked(result: SimulationResult, scene: Scene, model: Any, verify: bool | None,
             quiet: bool) -> SimulationResult:
    """The result with its accuracy statement, unless skipped (``--no-verify``) or, without
    ``--verify``, too expensive: then the reason is printed."""
    from jointplay.sim import can_check_accuracy, tighter_note, with_accuracy

    if verify is False:
        return result
    if not can_check_accuracy(scene):
        if not quiet:
            print("accuracy not checked: the run's settings are at their limits, so no "
                  "tighter run can check it")
        return result
    estimate = CHECK_COST_RATIO * float(result.stats["wall_time_s"])
    if verify is None and estimate > VERIFY_BUDGET_S:
        if not quiet:
            print(f"accuracy not checked: the check (the same run at tolerances 10x tighter) "
                  f"would take about {estimate:.0f} s; ask for it with --verify, or skip this "
                  "note with --no-verify")
        return result
    if not quiet:
        print(f"checking accuracy: the same run at tolerances 10x tighter (about "
              f"{estimate:.1f} s; --no-verify skips it)")
    note = tighter_note(scene)
    if note and not quiet:
        print(f"  note: {note}")
    try:
        return with_accuracy(result, scene, model=model, quiet=quiet)
    except SimulationError as err:  # the run itself is fine: keep it, say what is not known
        print(f"accuracy not checked: the check (the same run at tolerances 10x tighter) "
              f"stopped: {err}", file=sys.stderr)
        return result


def _scene(args: argparse.Namespace) -> tuple[Scene, OutputPlan]:
    """The scene with the command's overrides, and the output plan, every path checked."""
    scene = scene_from_args(args)
    changes = {k: v for k, v in (("integrator", args.integrator), ("rtol", args.rtol),
                                 ("atol", args.atol), ("t_end", args.t_end),
                                 ("step", args.step), ("output_step", args.output_step),
                                 ("plausibility", args.plausibility))
               if v is not None}
    if changes:
        try:
            scene = scene.with_run(**changes)
        except DescriptionError as err:
            if err.field.removeprefix("run.") not in changes:  # a consequence elsewhere
                raise
            raise DescriptionError(run_flag(err.field), err.message) from None
    overrides = _overrides(args.set or [])
    run_changes = _run_overrides(overrides)
    if run_changes:
        try:
            scene = scene.with_run(**run_changes)
        except DescriptionError as err:
            raise DescriptionError(f"--set {err.field}", err.message) from None
    plan = _check_outputs(args, scene)
    if overrides:
        from jointplay.robot import with_parameters
        from jointplay.robot.description import parameter_name

        try:
            scene = scene.with_robot(with_parameters(scene.robot, overrides))
        except DescriptionError as err:
            raise err.renamed(lambda f: f"--set {parameter_name(f)}").with_source(None) \
                from None
    return scene, plan


def output_plan(args: argparse.Namespace, scene: Scene) -> OutputPlan:
    """Every file the command will write (given and derived) and every file it reads,
    refused before any work when two coincide or an output is an input (exit 2)."""
    from jointplay.cli.args import plan_scene_inputs
    from jointplay.common.files import OutputPlan
    from jointplay.results import wear
    from jointplay.results.write import impacts_csv_path

    plan = OutputPlan()
    plan_scene_inputs(plan, scene)
    if args.out:
        plan.file("--out", args.out)
    if args.csv:
        plan.file("--csv", args.csv)
        plan.file("--csv", impacts_csv_path(args.csv), "its contact-phase table")
        if scene.robot.structure().wear is not None:
            plan.file("--csv", wear.csv_path(args.csv), "its wear table")
    if args.plot:
        plan.folder("--plot", args.plot, "its figures", pattern="*.png")
    if args.animate:
        plan.file("--animate", args.animate)
    plan.check()
    return plan


def _check_outputs(args: argparse.Namespace, scene: Scene) -> OutputPlan:
    from jointplay.results.write import check_output_path

    plan = output_plan(args, scene)
    for output in plan.outputs:
        if output.kind == "file" and output.flag != "--animate":
            check_output_path(output.path, output.flag)
    if args.plot:
        from jointplay.results.write import impacts_csv_path

        derived = impacts_csv_path(args.csv) if args.csv else None
        for flag, path in (("--out", args.out), ("--csv", args.csv), ("--csv", derived)):
            if path and Path(path).resolve() == Path(args.plot).resolve():
                raise DescriptionError("--plot", f"names the same path as {flag} ({path}); "
                                       "--plot takes a folder for the figures")
        check_writable_dir(Path(args.plot), "--plot")
    if args.animate:
        from jointplay.results.animate import check_animation_path

        check_animation_path(args.animate)
    return plan


def _figure_process(args: argparse.Namespace) -> contextlib.AbstractContextManager[Any]:
    """With ``--plot``, a process that imports matplotlib while this one simulates and then
    draws the figures while this one writes the other files (killed on leaving the block);
    otherwise, or where it cannot help (one CPU), nothing."""
    if args.plot:
        from jointplay.common import figure_process

        if figure_process.wanted():
            return figure_process.claim()
    return contextlib.nullcontext()


def _write(result: SimulationResult, args: argparse.Namespace, plan: OutputPlan,
           quiet: bool, figures: FigureProcess | None = None) -> list[str]:
    """Write the files asked for, all or none (see
    :func:`~jointplay.common.files.all_or_nothing`); their paths. ``figures``: the process
    that draws the figures."""
    from jointplay.common.files import all_or_nothing, make_folder

    with all_or_nothing(plan):
        if args.plot:
            make_folder(args.plot, "--plot")
        return _write_each(result, args, quiet, figures)


def _write_each(result: SimulationResult, args: argparse.Namespace, quiet: bool,
                figures: FigureProcess | None) -> list[str]:
    written = []
    pending = None
    if args.plot:  # handed out first: the figures are drawn while the files are written
        from jointplay.common.figure_process import draw
        from jointplay.results.plots import figure_jobs

        jobs = figure_jobs(result, args.plot)
        if figures is not None:
            pending = figures.submit(jobs)
    if args.out:
        from jointplay.results.write import write_hdf5

        write_hdf5(result, args.out)
        written.append(args.out)
    if args.csv:
        from jointplay.results.write import write_csv

        written += [str(p) for p in write_csv(result, args.csv)]
    if args.plot:
        drawn = pending.collect() if pending is not None else draw(jobs, None)
        written += [str(p) for p in drawn]
    if args.animate:
        from jointplay.results.animate import animate_result

        written.append(str(animate_result(result, args.animate, quiet=quiet)))
    return written


def _overrides(items: list[str]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise DescriptionError("--set", f"expects NAME=VALUE (e.g. friction.mu=0.1), got "
                                   f"{item!r}")
        if name.strip().startswith("run."):  # checked and converted by _run_overrides
            out[name.strip()] = value.strip()
            continue
        number = _number(name, value)
        if not np.isfinite(number):
            raise DescriptionError(f"--set {name}", f"must be finite, got {value!r}")
        out[name.strip()] = number
    return out


def _number(name: str, value: str) -> float:
    try:
        return float(value)
    except ValueError:
        raise DescriptionError(f"--set {name}", f"must be a number, got {value!r}") from None


def _run_overrides(overrides: dict[str, Any]) -> dict[str, Any]:
    """Take the ``run.NAME`` entries out of ``overrides`` (in place) as run-setting changes."""
    changes: dict[str, Any] = {}
    for name in [n for n in overrides if n.startswith("run.")]:
        value = overrides.pop(name)
        key = name.removeprefix("run.")
        if key not in _RUN_NUMBERS:
            raise DescriptionError(f"--set {name}", "is not a run setting; these are "
                                   f"run.{', run.'.join(_RUN_NUMBERS)}"
                                   + did_you_mean(name, [f"run.{k}" for k in _RUN_NUMBERS]))
        if key in ("integrator", "plausibility"):  # the settings that are names
            changes[key] = value
            continue
        number = _number(name, value)
        if key == "max_steps":
            if not number.is_integer():
                raise DescriptionError(f"--set {name}", f"must be a whole number, got {value}")
            changes[key] = int(number)
        else:
            changes[key] = number
    return changes
