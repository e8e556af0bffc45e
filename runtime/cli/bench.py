"""``jointplay bench work-precision | fidelity | scaling``: what accuracy costs, measured
(the studies themselves: :mod:`jointplay.bench`)."""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import jointplay.bench as bench
from jointplay.bench import (
    CHECK_METHODS,
    DEFAULT_CHECK_STEP,
    DEFAULT_METHODS,
    DEFAULT_RTOLS,
    DEFAULT_STEPS,
    QUICK_RTOLS,
    QUICK_STEPS,
    QUICK_T_END,
    REFERENCE_RTOL,
    SCALING_SIM_TIME,
    STRUCTURES,
    SURROGATE_MODULE,
    WorkPrecision,
    cold_compile_seconds,
    fidelity,
    machine_facts,
    reference_solution,
    scaling,
    work_precision,
    write_fidelity,
    write_scaling,
    write_work_precision,
)
from jointplay.cli.args import (
    choices_list,
    command_line,
    parse_links,
    positive_floats,
    positive_int,
    prepare_out_dir,
    run_flag,
    scene_argument,
    scene_from_args,
)
from jointplay.common.errors import DescriptionError
from jointplay.common.files import OutputPlan, all_or_nothing

if TYPE_CHECKING:
    from jointplay.scene.definition import Scene


def _with_run(scene: Scene, **changes: Any) -> Scene:
    """``scene.with_run`` with errors naming the command-line flag instead of the field."""
    changes = {k: v for k, v in changes.items() if v is not None}
    if not changes:
        return scene
    try:
        return scene.with_run(**changes)
    except DescriptionError as err:
        raise DescriptionError(run_flag(err.field), err.message) from None


def _report(paths: Sequence[Path], markdown_path: Path, quiet: bool) -> None:
    if not quiet:
        print(markdown_path.read_text(encoding="utf-8"))
    for path in paths:
        print(f"wrote {path}")


def _repeats(args: argparse.Namespace) -> int:
    return positive_int(args.repeats if args.repeats is not None
                        else (1 if getattr(args, "quick", False) else 3), "--repeats")


def _quick_scene(args: argparse.Namespace) -> Scene:
    """The scene, its run cut to --t-end (or to the quick case's)."""
    t_end = args.t_end if args.t_end is not None else (QUICK_T_END if args.quick else None)
    return _with_run(scene_from_args(args), t_end=t_end)


def cmd_work_precision(args: argparse.Namespace) -> int:
    from jointplay.scene.definition import INTEGRATORS

    scene = _quick_scene(args)
    methods = choices_list(args.methods, INTEGRATORS, "--methods", "method")
    rtols = positive_floats(args.rtols, "--rtols") if args.rtols else \
        list(QUICK_RTOLS if args.quick else DEFAULT_RTOLS)
    steps = positive_floats(args.steps, "--steps") if args.steps else \
        list(QUICK_STEPS if args.quick else DEFAULT_STEPS)
    for r in rtols:
        if r >= 1:
            raise DescriptionError("--rtols", f"every tolerance must be < 1, got {r:g}")
    for h in steps:
        try:
            scene.with_run(integrator="rk4", step=h)
        except DescriptionError as err:
            raise DescriptionError("--steps", err.message) from None
    repeats = _repeats(args)
    _with_run(scene, rtol=args.reference_rtol)
    if args.check == "radau":
        _with_run(scene, integrator="radau", step=args.check_step)
    laws = _stiffness_option(args, scene)
    plan = bench_plan(args, scene)
    out = prepare_out_dir(args.out)
    reports: list[list[Path]] = []
    if len(laws) == 1:
        with all_or_nothing(plan):
            _work_precision_one(_law_scene(scene, laws[0]), args, out, methods, rtols, steps,
                                repeats, reports)
        _report(reports[0], reports[0][1], args.quiet)
        return 0
    # One full work-precision (own model, own reference) per law, and a table of all rows.
    rows: list[dict[str, Any]] = []
    with all_or_nothing(plan):
        for law in laws:
            rows += _work_precision_one(_law_scene(scene, law), args, prepare_out_dir(out / law),
                                        methods, rtols, steps, repeats, reports)
        _laws_table(scene, rows, out)
    for paths in reports:
        _report(paths, paths[1], args.quiet)
    _report([out / "work_precision_laws.csv"], out / "work_precision_laws.md", args.quiet)
    return 0


def _laws_table(scene: Scene, rows: list[dict[str, Any]], out: Path) -> None:
    md = [f"# Work-precision per contact stiffness law: {scene.name}", "",
          f"Command: `{command_line()}`", "",
          "Each law's errors are against its own reference (see the law's folder).", "",
          bench.markdown_table(rows, [("stiffness", "stiffness", "{}"), *bench.WP_COLUMNS]),
          ""]
    from jointplay.common.files import atomic_write_text

    atomic_write_text(out / "work_precision_laws.csv", bench.to_csv(rows, bench.WP_CSV_KEYS))
    atomic_write_text(out / "work_precision_laws.md", "\n".join(md))


def _stiffness_option(args: argparse.Namespace, scene: Scene) -> list[str]:
    """The contact stiffness laws of --stiffness, each checked on the scene's robot."""
    from jointplay.robot.contact_laws import parse_stiffnesses, with_stiffness

    if not args.stiffness:
        return [scene.robot.contact.stiffness]
    laws = parse_stiffnesses(args.stiffness, "--stiffness")
    if not scene.robot.clearance_joints:
        raise DescriptionError("--stiffness", "the scene's robot has no clearance joint, so "
                                              "no contact law")
    for law in laws:
        try:
            with_stiffness(scene.robot, law)
        except DescriptionError as err:
            raise DescriptionError("--stiffness", f"{law}: {err.field}: {err.message}"
                                   ) from None
    return laws


def _law_scene(scene: Scene, law: str) -> Scene:
    from jointplay.robot.contact_laws import with_stiffness

    if law == scene.robot.contact.stiffness:
        return scene
    return scene.with_robot(with_stiffness(scene.robot, law))


def _work_precision_one(scene: Scene, args: argparse.Namespace, out: Path,
                        methods: list[str], rtols: list[float], steps: list[float],
                        repeats: int, reports: list[list[Path]]) -> list[dict[str, Any]]:
    """One work-precision of ``scene``: its model, its reference, its rows and report (the
    paths written go to ``reports``, to be shown once every output is in place)."""
    from jointplay.sim import load_scene_model

    t0 = time.perf_counter()
    model = load_scene_model(scene)
    load_s = time.perf_counter() - t0
    compile_s = cold_compile_seconds(model)
    if not args.quiet:
        print(f"reference: cvodes rtol {args.reference_rtol:g}, checked by {args.check}",
              file=sys.stderr)
    reference = reference_solution(scene, model, rtol=args.reference_rtol, check=args.check,
                                   check_step=args.check_step)
    atols = positive_floats(args.atols, "--atols") if getattr(args, "atols", None) else []
    reference, rows = work_precision(scene, model, methods=methods, rtols=rtols, steps=steps,
                                     repeats=repeats, reference=reference, quiet=args.quiet,
                                     atols=atols)
    if args.effects:
        from jointplay.bench.effects import work_precision_rows

        rows += work_precision_rows(scene, reference, rtols=rtols, repeats=repeats,
                                    reference_rtol=args.reference_rtol, check=args.check,
                                    check_step=args.check_step, quiet=args.quiet)
    wp = WorkPrecision(scene=scene, reference=reference, rows=rows, compile_s=compile_s,
                       load_s=load_s, repeats=repeats, facts=machine_facts())
    reports.append(write_work_precision(wp, out, command_line()))
    return rows


def bench_plan(args: argparse.Namespace, scene: Scene | None) -> OutputPlan:
    """The report folder's tables, Markdown and figures (law folders included) and the
    files read (the scene, its torque table, a surrogate's folder): refused when an output
    would be one of them (exit 2), before any measurement."""
    from jointplay.cli.args import plan_scene_inputs

    plan = OutputPlan()
    if scene is not None:
        plan_scene_inputs(plan, scene)
    plan.input("--surrogate", getattr(args, "surrogate", None))
    plan.folder("--out", args.out, "the report", pattern="*.csv|*.md|*.png")
    plan.check()
    return plan


def cmd_fidelity(args: argparse.Namespace) -> int:
    scene = _quick_scene(args)
    run_scene = _with_run(scene, integrator=args.integrator, rtol=args.rtol, atol=args.atol,
                          step=args.step)
    _with_run(scene, rtol=args.reference_rtol)
    repeats = _repeats(args)
    surrogate = Path(args.surrogate) if args.surrogate else None
    if surrogate is not None and not surrogate.is_dir():
        raise DescriptionError("--surrogate", f"{surrogate} is not a folder holding a trained "
                                              "model")
    laws = _stiffness_option(args, scene) if args.stiffness else []
    plan = bench_plan(args, scene)
    out = prepare_out_dir(args.out)
    fid = fidelity(scene, run_scene=run_scene, reference_rtol=args.reference_rtol,
                   repeats=repeats, surrogate=surrogate, quiet=args.quiet,
                   effects=args.effects, stiffness=laws)
    skipped = [r for r in fid.rows if r["status"] == "skipped" and surrogate is not None]
    for r in skipped:
        print(f"jointplay: note: surrogate row skipped: {r['note']}", file=sys.stderr)
    with all_or_nothing(plan):
        paths = write_fidelity(fid, out, command_line())
    _report(paths, paths[1], args.quiet)
    return 0


def cmd_scaling(args: argparse.Namespace) -> int:
    links = parse_links(args.links)
    structures = choices_list(args.structures, STRUCTURES, "--structures", "structure")
    if not (math.isfinite(args.sim_time) and args.sim_time > 0):
        raise DescriptionError("--sim-time", f"must be > 0 s, got {args.sim_time}")
    if abs(round(args.sim_time / 1e-3) * 1e-3 - args.sim_time) > 1e-9:
        raise DescriptionError("--sim-time", f"must be a whole number of milliseconds, got "
                                             f"{args.sim_time}")
    repeats = positive_int(args.repeats, "--repeats")
    if args.timeout <= 0:
        raise DescriptionError("--timeout", f"must be > 0 s, got {args.timeout}")
    plan = bench_plan(args, None)
    out = prepare_out_dir(args.out)
    load_before = " ".join(f"{v:.2f}" for v in os.getloadavg())
    rows = scaling(links, structures, sim_time=args.sim_time, repeats=repeats,
                   timeout=args.timeout, quiet=args.quiet)
    facts = {"load average (1/5/15 min) at the start": load_before, **machine_facts()}
    with all_or_nothing(plan):
        paths = write_scaling(rows, out, sim_time=args.sim_time, facts=facts,
                              command=command_line())
    _report(paths, paths[1], args.quiet)
    return 0 if all("build_s" in r for r in rows) else 1


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``bench`` with its sub-commands to a CLI's ``add_subparsers()`` object."""
    parser = subparsers.add_parser(
        "bench", help="benchmarks: work-precision, fidelity ladder, scaling with links",
        description=(bench.__doc__ or "").split("\n\n")[0])
    sub = parser.add_subparsers(dest="bench_command", required=True)
    _register_work_precision(sub)
    _register_fidelity(sub)
    _register_scaling(sub)
    return parser


def _common(p: argparse.ArgumentParser, scene: bool = True, quick: bool = False) -> None:
    if scene:
        scene_argument(p)
    p.add_argument("--out", required=True, help="folder for the CSV, Markdown and PNG "
                                                "(created if missing)")
    p.add_argument("--repeats", type=int, help="timed runs per configuration (default 3"
                                               + ("; 1 with --quick)" if quick else ")"))
    p.add_argument("--quiet", action="store_true", help="no progress bars, no table")


def _register_work_precision(sub: Any) -> None:
    wp = sub.add_parser("work-precision", help="error against a reference vs CPU time, per "
                                               "integrator and tolerance or step")
    _common(wp, quick=True)
    wp.add_argument("--quick", action="store_true",
                    help=f"a tiny case: t_end {QUICK_T_END:g} s, two tolerances and two "
                         "steps, one repeat")
    wp.add_argument("--t-end", type=float, help="override run.t_end (s)")
    wp.add_argument("--methods", default=",".join(DEFAULT_METHODS),
                    help="comma list of bdf, cvodes, idas, rk4, radau (default all)")
    wp.add_argument("--rtols", help="adaptive tolerances, atol = rtol (default "
                                    f"{','.join(f'{r:g}' for r in DEFAULT_RTOLS)})")
    wp.add_argument("--atols", help="pair every adaptive rtol with each of these atols "
                                    "(default atol = rtol): the search for the cheapest "
                                    "setting that meets the working accuracy")
    wp.add_argument("--steps", help="fixed steps in s, each dividing the output step (default "
                                    f"{','.join(f'{h:g}' for h in DEFAULT_STEPS)})")
    wp.add_argument("--reference-rtol", type=float, default=REFERENCE_RTOL,
                    help=f"tolerance of the CVODES reference (default {REFERENCE_RTOL:g})")
    wp.add_argument("--check", choices=CHECK_METHODS, default="idas",
                    help="second method that checks the reference: idas at the same "
                         "tolerance (default) or radau at --check-step")
    wp.add_argument("--check-step", type=float, default=DEFAULT_CHECK_STEP,
                    help=f"Radau step of the check (default {DEFAULT_CHECK_STEP:g} s)")
    _effects_flag(wp)
    wp.add_argument("--stiffness", metavar="LAWS",
                    help="comma list of contact stiffness laws (hertz, johnson, liu, pereira): "
                         "one work-precision per law, in DIR/<law>/, and all rows in "
                         "DIR/work_precision_laws.md (default: the scene's own law; clearance "
                         "joints without a length get 0.02 m)")
    wp.set_defaults(func=cmd_work_precision)


def _register_fidelity(sub: Any) -> None:
    fid = sub.add_parser("fidelity", help="ideal joints, clearance without and with "
                                          "friction: error against the full model vs time")
    _common(fid)
    fid.add_argument("--quick", action="store_true",
                     help=f"a tiny case: t_end {QUICK_T_END:g} s, one repeat")
    fid.add_argument("--t-end", type=float, help="override run.t_end (s)")
    fid.add_argument("--integrator", help="override run.integrator for the timed runs")
    fid.add_argument("--rtol", type=float, help="override run.rtol for the timed runs")
    fid.add_argument("--atol", type=float, help="override run.atol for the timed runs")
    fid.add_argument("--step", type=float, help="override run.step for the timed runs")
    fid.add_argument("--reference-rtol", type=float, default=REFERENCE_RTOL,
                     help=f"tolerance of the full-model reference (default "
                          f"{REFERENCE_RTOL:g})")
    fid.add_argument("--surrogate", metavar="MODEL_DIR",
                     help=f"a trained neural surrogate ({SURROGATE_MODULE}); without it the "
                          "surrogate row is skipped with a note")
    _effects_flag(fid)
    fid.add_argument("--stiffness", metavar="LAWS",
                     help="comma list of contact stiffness laws (hertz, johnson, liu, "
                          "pereira): each one other than the scene's adds a rung, the full "
                          "model under that law (clearance joints without a length get "
                          "0.02 m)")
    fid.set_defaults(func=cmd_fidelity)


def _effects_flag(parser: Any) -> None:
    parser.add_argument("--effects", action="store_true",
                        help="add rows for lubricated joints and Archard wear")


def _register_scaling(sub: Any) -> None:
    sc = sub.add_parser("scaling", help="derive, emit and compile time, and the cost of a "
                                        "simulated second, against the number of links")
    _common(sc, scene=False)
    sc.set_defaults(repeats=3)
    sc.add_argument("--links", default="1-12", help="link counts, e.g. 1-12 or 2,4,8 "
                                                    "(default 1-12)")
    sc.add_argument("--structures", default=",".join(STRUCTURES),
                    help="comma list of clearance (every joint), ideal (default both)")
    sc.add_argument("--sim-time", type=float, default=SCALING_SIM_TIME,
                    help=f"simulated seconds per case (default {SCALING_SIM_TIME:g})")
    sc.add_argument("--timeout", type=float, default=1200.0, help="seconds per case")
    sc.set_defaults(func=cmd_scaling)
