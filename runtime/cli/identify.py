"""``jointplay identify``: read the settings and validate every flag, then simulate the
excitation runs, train the network and write the model folder (the work itself:
:mod:`jointplay.neural.identify.pipeline`)."""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.cli.args import check_writable_dir
from jointplay.cli.neural_args import (
    add_identify_arguments,
    check_identify_for,
    check_tracked_for,
    neural_scene_argument,
)
from jointplay.cli.neural_settings import (
    add_settings_file_arguments,
    scene_and_settings,
    settings_flags,
)
from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_write_text
from jointplay.neural.identify.pipeline import (
    REPORT_FILE,
    IdentifyConfig,
    ModelRejected,
    default_limits,
)
from jointplay.neural.study.closed_loop_choice import identify_model
from jointplay.neural.study.settings import SETTINGS_FILE, settings_toml

if TYPE_CHECKING:
    from jointplay.common.files import OutputPlan
    from jointplay.scene.definition import Scene


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``identify`` to a ``jointplay`` argument parser's subcommands."""
    p = subparsers.add_parser(
        "identify", help="simulate excitation runs and train the NARX network for the "
                         "neural controller",
        description="Simulate the clearance robot (under the inner PD loop) with excitation "
                    "torques, train a NARX network on the deviations from the ideal robot, "
                    "report one-step and free-run errors on unseen test runs against "
                    "persistence and a linear ARX model, and write MODEL_DIR.")
    neural_scene_argument(p)
    p.add_argument("--out", required=True, metavar="MODEL_DIR",
                   help="folder for narx.json, datasets.h5, metrics.json and report.md")
    flags = add_identify_arguments(p)
    p.add_argument("--quiet", action="store_true", help="no progress bars, no report")
    add_settings_file_arguments(p)
    settings_flags(p, flags)
    p.set_defaults(func=cmd_identify, settings_keys=flags)
    return p


def cmd_identify(args: argparse.Namespace) -> int:
    """``jointplay identify``: validate everything, then simulate, train and write."""
    from jointplay.common.extras import require

    require("control", "jointplay identify")  # before any work
    scene, settings, scene_file, given = scene_and_settings(args, args.settings_keys)
    out = Path(args.out)
    output_plan(args, scene)
    check_writable_dir(out, "--out")
    config = check_identify_for(settings.identify, scene, given)
    check_tracked_for(settings.control.tracked, scene, config.contact_outputs, given)
    check_scene_for(config, scene, given.get("identify.duration", "identify.duration"))
    # What this model folder was identified with: `jointplay identify settings.toml` again.
    record = settings_toml(replace(settings, identify=config), scene_file,
                           "jointplay identify settings.toml --out MODEL_DIR")
    started = time.perf_counter()
    try:
        metrics = identify_model(scene, out, config, quiet=args.quiet)
    except ModelRejected:
        atomic_write_text(out / SETTINGS_FILE, record)
        if not args.quiet:
            print((out / REPORT_FILE).read_text(encoding="utf-8"))
        raise
    atomic_write_text(out / SETTINGS_FILE, record)
    if not args.quiet:
        print((out / REPORT_FILE).read_text(encoding="utf-8"))
        print(f"wrote {out}/narx.json, datasets.h5, metrics.json, report.md in "
              f"{time.perf_counter() - started:.1f} s")
    for warning in metrics.get("warnings", []):
        print(f"jointplay: warning: {warning}", file=sys.stderr)
    return 0


def output_plan(args: argparse.Namespace, scene: Scene) -> OutputPlan:
    """The model folder's files and the scene's: refused when one is the other (exit 2)."""
    from jointplay.cli.args import plan_scene_inputs
    from jointplay.common.files import OutputPlan
    from jointplay.neural.identify.pipeline import (
        ARX_FILE,
        DATASETS_FILE,
        METRICS_FILE,
        REJECTED_FILE,
    )
    from jointplay.neural.model.narx import MODEL_FILE

    plan = OutputPlan()
    plan_scene_inputs(plan, scene)
    for name in (MODEL_FILE, REJECTED_FILE, ARX_FILE, DATASETS_FILE, METRICS_FILE,
                 REPORT_FILE, SETTINGS_FILE):
        plan.file("--out", Path(args.out) / name, f"the model folder's {name}")
    plan.check()
    return plan


def check_scene_for(config: IdentifyConfig, scene: Scene, duration: str) -> None:
    """What depends on the scene fails now, before any work: the default torque limits and
    the run at the trajectories' duration."""
    if not config.torque_limit:
        default_limits(scene)
    try:
        scene.with_run(t_end=config.duration)
    except DescriptionError as err:
        raise DescriptionError(duration, err.message) from None
