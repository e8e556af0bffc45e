"""``jointplay calibrate`` on a mechanism file: the same command, the mechanism's outputs
measured, a multi-start over its first impacts and a continuation to the whole record
(:mod:`jointplay.mechanism.calibration`)."""

from __future__ import annotations

import argparse

from jointplay.common.errors import DescriptionError

# The options of the arms' global stage and checks, by flag: a mechanism's search does not
# run them (jointplay.mechanism.calibration.ARMS_ONLY).
_FLAGS = {"horizon_first": "--horizon-first", "grid_window": "--grid-window",
          "grid_points": "--grid-points", "grid_line_points": "--grid-line-points",
          "valley_check_points": "--valley-check-points", "basins": "--no-basin-check"}


def cmd_calibrate_mechanism(args: argparse.Namespace) -> int:
    from jointplay.cli.calibrate import _flagged, calibrate_and_report
    from jointplay.mechanism.calibration import prepare_mechanism, run_mechanism
    from jointplay.mechanism.calibration_search import FIRST_WINDOW_IMPACTS
    from jointplay.mechanism.reading import load_mechanism_scene

    scene = load_mechanism_scene(args.scene)

    def flagged(err: DescriptionError) -> DescriptionError:
        name = err.field.removeprefix("options.")
        if name in _FLAGS:
            return DescriptionError(_FLAGS[name], "belongs to the serial arms' global stage "
                                    "and checks; a mechanism is fitted by a multi-start "
                                    "and a continuation (--starts, --spread, "
                                    "--horizon-growth): drop the flag")
        return _flagged(err)

    return calibrate_and_report(
        args, scene.source,
        lambda measured, free, **kw: prepare_mechanism(scene, measured, free, **kw),
        run_mechanism,
        lambda problem, options: (
            f"calibrating {', '.join(problem.free.names)} of mechanism {scene.name} on "
            f"{problem.measured.t.size} samples of {', '.join(problem.measured.columns)} "
            f"(a local fit from each of {options.starts} starts; where a run holds more than "
            f"{FIRST_WINDOW_IMPACTS} impacts, over its first ones, then continued over "
            "growing windows)"),
        flagged)
