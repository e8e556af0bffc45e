"""``jointplay sweep``: validate a sweep file, run what is not done yet, write the table and
plots (the sweep itself: :mod:`jointplay.sweep`)."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from jointplay.common.files import OutputPlan
from jointplay.sweep import CASES_DIR, default_workers, load_sweep, run_sweep
from jointplay.sweep.records import MANIFEST_NAME, PLOTS_DIR, SERIES_DIR, TABLE_NAME
from jointplay.sweep.run import check_options


def output_plan(args: argparse.Namespace, scene: Any) -> OutputPlan:
    """The folder's table, manifest, case records, series files and figures, and the files
    read (the sweep file, the scene, its torque table): refused when they meet (exit 2).

    The case records and series files are written one by one as cases finish (each
    atomically): they are what a later run resumes from.
    """
    from jointplay.cli.args import plan_scene_inputs

    out = Path(args.out)
    plan = OutputPlan()
    plan.input("sweep", args.sweep)
    plan_scene_inputs(plan, scene)
    plan.file("--out", out / TABLE_NAME, "the table")
    plan.file("--out", out / MANIFEST_NAME, "the manifest")
    plan.folder("--out", out / CASES_DIR, "the case records")
    if args.series:
        plan.folder("--out", out / SERIES_DIR, "the series files")
    plan.folder("--out", out / PLOTS_DIR, "the figures", pattern="*.png")
    plan.check()
    return plan


def cmd_sweep(args: argparse.Namespace) -> int:
    """``jointplay sweep``: validate, run what is not done yet, write the table and plots."""
    from jointplay.mechanism.sweep import sweep_scene_path

    if sweep_scene_path(args.sweep) is not None:
        return _mechanism_sweep(args)
    from jointplay.common.extras import require

    require("sweep", "jointplay sweep")  # before any work
    sweep = load_sweep(args.sweep)
    check_options(None, args.workers, args.scheduler)
    output_plan(args, sweep.scene)
    quiet = bool(args.quiet)
    if not quiet:
        where = (f"the cluster at {args.scheduler}" if args.scheduler
                 else "this process" if args.workers == 0
                 else f"{args.workers} local worker process(es)" if args.workers
                 else "this process, or a local cluster when the first case shows that it "
                      "saves time")
        print(f"sweep {sweep.name}: {len(sweep.cases)} case(s) of scene {sweep.scene.name} "
              f"({sweep.mode} of {', '.join(sweep.swept_names)}) on {where}")
    result = run_sweep(sweep, args.out, workers=args.workers, scheduler=args.scheduler,
                       series=args.series, retry_failed=args.retry_failed, quiet=quiet,
                       verify=args.verify)
    if not quiet:
        print(f"{result.cases} case(s): {result.ran} run, {result.reused} reused from "
              f"{Path(args.out) / CASES_DIR}, {result.failed} failed; "
              f"{result.wall_time_s:.1f} s")
        print(f"wrote {result.path}")
        for path in result.plots:
            print(f"wrote {path}")
    return 0


def _mechanism_sweep(args: argparse.Namespace) -> int:
    """A sweep over a mechanism scene: every case in this process, one table out."""
    from jointplay.common.errors import DescriptionError
    from jointplay.mechanism.sweep import load_mechanism_sweep, run_mechanism_sweep

    for flag, value in (("--scheduler", args.scheduler), ("--series", args.series),
                        ("--verify", args.verify), ("--retry-failed", args.retry_failed)):
        if value:
            raise DescriptionError(flag, "a sweep of a mechanism runs its cases in this "
                                   "process, without records to resume or series; drop it")
    if args.workers not in (None, 0):
        raise DescriptionError("--workers", "a sweep of a mechanism runs its cases in this "
                               "process; drop it")
    sweep = load_mechanism_sweep(args.sweep)
    quiet = bool(args.quiet)
    if not quiet:
        print(f"sweep {sweep.name}: {len(sweep.cases)} case(s) of mechanism "
              f"{sweep.scene.name} ({', '.join(sweep.names)}) in this process")
    table, figures, seconds = run_mechanism_sweep(sweep, args.out, quiet=quiet)
    if not quiet:
        print(f"{len(sweep.cases)} case(s) in {seconds:.1f} s")
        for path in (table, *figures):
            print(f"wrote {path}")
    return 0


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``sweep`` command to the ``jointplay`` command's subparsers."""
    parser = subparsers.add_parser(
        "sweep", help="simulate a scene for many parameter vectors (Dask), one table out",
        description="Run every case of a sweep file in this process or on a Dask cluster "
                    "(a local one by default, when that saves time). Finished cases are kept "
                    "in OUT/cases/ and skipped when the same sweep runs again; the table is "
                    "OUT/sweep.parquet.")
    parser.add_argument("sweep", help="sweep file (TOML); see docs/how-to/sweep.md")
    parser.add_argument("--out", required=True, help="folder for the table, case files, "
                                                     "plots and series")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="use the Dask cluster at this address (tcp://host:8786) instead "
                             "of starting a local one")
    parser.add_argument("--workers", type=int, metavar="N",
                        help="local worker processes; 0 runs the cases in this process "
                             "(default: this process runs the first case, and the rest go to "
                             f"a local cluster of min(cores, 4) = {default_workers()} workers "
                             "only when that saves more than its start-up; one line says "
                             "which and why)")
    parser.add_argument("--series", action="store_true",
                        help="also write every case's full time series (OUT/series/KEY.h5)")
    parser.add_argument("--retry-failed", action="store_true",
                        help="run cases that failed before again (they are kept otherwise)")
    parser.add_argument("--verify", action="store_true",
                        help="check every case against the same case at tolerances 10x "
                             "tighter (about twice the cost): adds the columns "
                             "tip_error_estimate, agreement_horizon, accuracy_energy_residual")
    parser.add_argument("--quiet", action="store_true", help="no progress bar, no summary")
    parser.set_defaults(func=cmd_sweep)
    return parser

