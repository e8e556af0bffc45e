"""``jointplay calibrate``: a scene's physical parameters estimated from measured motion."""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

from jointplay.cli.args import check_writable_dir, command_line, scene_argument, scene_from_args
from jointplay.common.errors import DescriptionError
from jointplay.common.names import check_output_name


def register(subparsers: Any) -> argparse.ArgumentParser:
    p = subparsers.add_parser(
        "calibrate", help="estimate robot parameters (clearance, friction, ...) from measured "
                          "motion, with confidence intervals")
    scene_argument(p)
    p.add_argument("--measured", required=True, metavar="FILE",
                   help="CSV with a header: time (s) and any of tip_x, tip_y (m), q2, ... "
                        "(rad); or a results file (.h5). For a mechanism file: time and any "
                        "columns of the CSV that simulate writes (guide.position, ...)")
    p.add_argument("--free", required=True, metavar="NAME[,NAME...]",
                   help="parameters to estimate: any robot parameter by name (friction.mu, "
                        "link2.mass, ...) or jointN.clearance (bearing radius held); for a "
                        "mechanism, JOINT.clearance (slider_pin.clearance)")
    p.add_argument("--out", required=True, metavar="DIR",
                   help="folder for calibration.json, report.md, fit.png, residuals.png, "
                        "profiles.png (written all or none)")
    p.add_argument("--noise", metavar="SIGMA|COLUMN=SIGMA,...",
                   help="the sensors' standard deviations: one number for every column, or "
                        "one per column (tip_x=1e-6,tip_y=1e-6); default: estimated from the "
                        "data's own sample-to-sample scatter")
    p.add_argument("--start", metavar="NAME=VALUE,...",
                   help="start values of free parameters (default: the scene's)")
    p.add_argument("--starts", type=int, default=6,
                   help="without the continuation (--horizon-first 0): local fits at "
                        "most, the start, then a Latin hypercube within --spread of it, "
                        "tried while the fit does not explain the data (default 6)")
    p.add_argument("--spread", type=float, default=0.5,
                   help="relative half-width of the box of further starts and of the scan "
                        "(default 0.5)")
    p.add_argument("--scan-points", type=int, default=201,
                   help="without the continuation: runs along the weakest direction of the "
                        "first fit, where impacts make the cost rugged (default 201; 0: no "
                        "scan)")
    p.add_argument("--horizon-first", type=float, default=0.005,
                   help="first window (s) of the horizon continuation: the fit runs on the "
                        "data up to it, then on windows longer by the growth factor below, each "
                        "from the last estimate, up to the whole record (default 0.005; 0: "
                        "fit the whole record at once)")
    p.add_argument("--horizon-growth", type=float, default=2.0,
                   help="factor each window of the continuation grows by, a mechanism's "
                        "too (default 2)")
    p.add_argument("--grid-window", type=float, default=0.02,
                   help="window (s) of the global stage: a grid of the free clearances on the "
                        "data up to it, its lowest minima carried as tracks through the "
                        "continuation (default 0.02; 0: no grid)")
    p.add_argument("--grid-points", type=int, default=16,
                   help="values of each free clearance in the grid, across --spread of the "
                        "start (default 16)")
    p.add_argument("--grid-line-points", type=int, default=151,
                   help="runs on the grid's window along the clearances' rugged directions "
                        "through the best grid point, 1.5 grid spacings either side; their "
                        "lowest minima take its place as tracks (default 151; 0: no line)")
    p.add_argument("--valley-check-points", type=int, default=161,
                   help="runs over 0.32 s along the clearances' rugged directions (all "
                        "but the weakest) through the best fit, 0.2 grid spacings either "
                        "side; a clearance whose interval misses another valley within "
                        "chi² + 3.84 of the fit's there, or whose own valley the line is too "
                        "coarse to resolve, is reported not determined, its interval "
                        "spanning the lines; run only where the noise explains the "
                        "residuals (default 161 per direction; 0: no check)")
    p.add_argument("--no-basin-check", dest="basins", action="store_false",
                   help="skip the search for the other minima of the whole record's cost "
                        "near the best fit (lines along the axes of its confidence "
                        "ellipsoid, local fits from their lowest minima), which the "
                        "intervals are otherwise widened to hold")
    p.add_argument("--profile-points", type=int, default=13,
                   help="points of each cost profile (default 13; 0: none)")
    p.add_argument("--tighten", type=float, default=1000.0,
                   help="the fit's runs use the scene's tolerances divided by this "
                        "(default 1000)")
    p.add_argument("--seed", type=int, default=0, help="seed of the further starts")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="run the calibration's parallel pieces on the Dask cluster whose "
                        "scheduler is at ADDRESS (tcp://host:8786) instead of this machine's "
                        "cores")
    p.add_argument("--quiet", action="store_true", help="print nothing but errors")
    p.set_defaults(func=cmd_calibrate)
    return p


def cmd_calibrate(args: argparse.Namespace) -> int:
    from jointplay.calibration.api import prepare, run
    from jointplay.mechanism.reading import is_mechanism_file

    check_output_name("--out", args.out, "folder")
    if args.scene and is_mechanism_file(args.scene):
        from jointplay.cli.calibrate_mechanism import cmd_calibrate_mechanism

        return cmd_calibrate_mechanism(args)
    scene = scene_from_args(args)
    return calibrate_and_report(
        args, scene.source,
        lambda measured, free, **kw: prepare(scene, measured, free, **kw), run,
        lambda problem, _: (f"calibrating {', '.join(problem.free.names)} of {scene.name} on "
                            f"{problem.measured.t.size} samples of "
                            f"{', '.join(problem.measured.columns)}"),
        _flagged)


def calibrate_and_report(args: argparse.Namespace, source: str | None,
                         prepare: Callable[..., Any], run: Callable[[Any], Any],
                         announce: Callable[[Any, Any], str],
                         flagged: Callable[[DescriptionError], DescriptionError]) -> int:
    """The steps a scene's and a mechanism's calibration share: plan the outputs, parse the
    flags, ``prepare(measured, free, noise=, start=, options=)`` (a DescriptionError passed
    through ``flagged``), print ``announce(problem, options)``, ``run(problem)``, write the
    report and print its findings."""
    from jointplay.calibration.api import CalibrationOptions
    from jointplay.calibration.report import output_plan, write_report

    out = Path(args.out)
    check_writable_dir(out, "--out")
    plan = output_plan(out, {"scene": source, "--measured": args.measured})
    free = [n.strip() for n in args.free.split(",") if n.strip()]
    options = _options(args, CalibrationOptions)
    try:
        problem = prepare(args.measured, free, noise=_noise(args.noise),
                          start=_start(args.start), options=options)
    except DescriptionError as err:
        raise flagged(err) from None
    if not args.quiet:
        print(announce(problem, options))
    result = run(problem)
    written = write_report(result, out, plan, command_line())
    if not args.quiet:
        if not result.noise_stated:
            print("noise estimated from the data's scatter: " + ", ".join(
                f"{c} {v:.3g}" for c, v in result.noise.items()))
        for e in result.estimates.values():
            std = f"{e.std:.3g}" if math.isfinite(e.std) else "inf"
            note = "" if e.determined else "  (NOT determined by the data)"
            print(f"  {e.name} = {e.value:.8g} ± {std}  95 % [{e.low95:.8g}, "
                  f"{e.high95:.8g}]{note}")
        for warning in result.warnings:
            print(f"warning: {warning}")
        print(f"chi²/dof = {result.residuals['normalised_chi2']:.4g}; {result.simulations} "
              f"runs, {result.wall_time_s:.1f} s")
        for path in written:
            print(f"wrote {path}")
    return 0


def _options(args: argparse.Namespace, options_type: Any) -> Any:
    flags = {"--starts": args.starts, "--spread": args.spread,
             "--scan-points": args.scan_points, "--profile-points": args.profile_points,
             "--tighten": args.tighten, "--horizon-first": args.horizon_first,
             "--horizon-growth": args.horizon_growth, "--grid-window": args.grid_window,
             "--grid-points": args.grid_points, "--grid-line-points": args.grid_line_points,
             "--valley-check-points": args.valley_check_points, "--seed": args.seed}
    try:
        return options_type(tighten=args.tighten, starts=args.starts, spread=args.spread,
                            seed=args.seed, profile_points=args.profile_points,
                            scan_points=args.scan_points, horizon_first=args.horizon_first,
                            horizon_growth=args.horizon_growth,
                            grid_window=args.grid_window, grid_points=args.grid_points,
                            grid_line_points=args.grid_line_points,
                            valley_check_points=args.valley_check_points,
                            basins=args.basins, scheduler=args.scheduler)
    except DescriptionError as err:
        flag = "--" + err.field.removeprefix("options.").replace("_", "-")
        if flag not in flags:
            raise
        raise DescriptionError(flag, err.message) from None


def _noise(text: str | None) -> float | dict[str, float] | None:
    if text is None:
        return None
    if "=" not in text:
        return _number("--noise", text)
    return {name: _number(f"--noise {name}", value) for name, value in _pairs(text, "--noise")}


def _start(text: str | None) -> dict[str, float] | None:
    if text is None:
        return None
    return {name: _number(f"--start {name}", value) for name, value in _pairs(text, "--start")}


def _pairs(text: str, flag: str) -> list[tuple[str, str]]:
    out: list[tuple[str, str]] = []
    for item in text.split(","):
        if not item.strip():
            continue
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise DescriptionError(flag, f"expects NAME=VALUE pairs separated by commas, got "
                                   f"{item!r}")
        if any(name.strip() == seen for seen, _ in out):
            raise DescriptionError(flag, f"gives {name.strip()} twice; give each name once")
        out.append((name.strip(), value.strip()))
    if not out:
        raise DescriptionError(flag, "no values given")
    return out


def _number(flag: str, text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise DescriptionError(flag, f"must be a number, got {text!r}") from None


def _flagged(err: DescriptionError) -> DescriptionError:
    """A Python-API field name as the flag that gave it (``free x`` -> ``--free x``,
    ``options.tighten`` -> ``--tighten``)."""
    for name in ("free", "start", "noise", "measured"):
        if err.field == name or err.field.startswith(name + " "):
            return DescriptionError("--" + err.field, err.message, err.source)
    if err.field.startswith("options."):
        flag = "--" + err.field.removeprefix("options.").replace("_", "-")
        return DescriptionError(flag, err.message, err.source)
    return err
