"""``jointplay calibrate`` on a mechanism file: the same command, the mechanism's outputs
measured and a multi-start fit (:mod:`jointplay.mechanism.calibration`)."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from jointplay.common.errors import DescriptionError

# The options of the arms' global stage and checks, by flag: a mechanism's search does not
# run them (jointplay.mechanism.calibration.ARMS_ONLY).
_FLAGS = {"horizon_first": "--horizon-first", "horizon_growth": "--horizon-growth",
          "grid_window": "--grid-window", "grid_points": "--grid-points",
          "grid_line_points": "--grid-line-points",
          "valley_check_points": "--valley-check-points", "basins": "--no-basin-check"}


def cmd_calibrate_mechanism(args: argparse.Namespace) -> int:
    from jointplay.calibration.api import CalibrationOptions
    from jointplay.calibration.report import output_plan, write_report
    from jointplay.cli.args import check_writable_dir, command_line
    from jointplay.cli.calibrate import _flagged, _noise, _options, _start
    from jointplay.mechanism.calibration import prepare_mechanism, run_mechanism
    from jointplay.mechanism.reading import load_mechanism_scene

    scene = load_mechanism_scene(args.scene)
    out = Path(args.out)
    check_writable_dir(out, "--out")
    plan = output_plan(out, {"scene": scene.source, "--measured": args.measured})
    free = [n.strip() for n in args.free.split(",") if n.strip()]
    options = _options(args, CalibrationOptions)
    try:
        problem = prepare_mechanism(scene, args.measured, free, noise=_noise(args.noise),
                                    start=_start(args.start), options=options)
    except DescriptionError as err:
        name = err.field.removeprefix("options.")
        if name in _FLAGS:
            raise DescriptionError(_FLAGS[name], "belongs to the serial arms' global stage "
                                   "and checks; a mechanism is fitted by a multi-start "
                                   "(--starts, --spread): drop the flag") from None
        raise _flagged(err) from None
    if not args.quiet:
        print(f"calibrating {', '.join(problem.free.names)} of mechanism {scene.name} on "
              f"{problem.measured.t.size} samples of {', '.join(problem.measured.columns)} "
              f"(a local fit from each of {options.starts} starts)")
    result = run_mechanism(problem)
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
