"""``jointplay identify``: validate every flag, then simulate the excitation runs, train the
network and write the model folder (the work itself: :mod:`jointplay.neural.identify.pipeline`)."""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.cli.args import check_writable_dir
from jointplay.cli.neural_args import (
    IDENTIFY_DATA,
    FlagKeys,
    add_base_fraction_argument,
    add_base_motions_argument,
    add_contact_argument,
    add_identify_data_arguments,
    add_iterations_argument,
    add_linear_gain_argument,
    add_operating_range_arguments,
    add_residual_argument,
    add_scene_motions_argument,
    add_scheduling_argument,
    add_settings_file_arguments,
    base_fraction_setting,
    check_duration,
    contact_setting,
    fill_from_settings,
    float_list,
    int_list,
    iteration_counts,
    lpv_base_setting,
    neural_scene_argument,
    operating_range,
    residual_setting,
    scene_and_settings,
    scene_motions_setting,
    settings_defaults,
    trajectory_counts,
)
from jointplay.common import limits as size_limits
from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_write_text
from jointplay.neural.identify.config import MAX_SEED
from jointplay.neural.identify.pipeline import (
    DEFAULT_KD,
    DEFAULT_KP,
    LIMIT_FACTOR,
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
    add_identify_data_arguments(p)
    p.add_argument("--lags", default="2,2", help="output lags,input lags (default 2,2)")
    p.add_argument("--hidden", default="13,14", help="hidden layer widths (default 13,14)")
    add_iterations_argument(p, "--iterations",
                            "L-BFGS iterations: one-step phase, free-run phase (default "
                            "%(default)s; early stopping may end either sooner)")
    p.add_argument("--window", type=int, default=IdentifyConfig.window,
                   help="samples per free-run training window (default %(default)s)")
    add_scheduling_argument(p)
    add_contact_argument(p, "--contact-outputs")
    add_linear_gain_argument(p, "--linear-input-gain")
    add_residual_argument(p)
    add_base_fraction_argument(p, "--base-fraction")
    add_base_motions_argument(p, "--base-motions")
    add_scene_motions_argument(p, "--scene-motions")
    add_operating_range_arguments(p)
    p.add_argument("--no-linear-path", action="store_true",
                   help="no linear direct path beside the hidden layers (the bare network)")
    p.add_argument("--kp", help=f"inner-loop PD stiffness per driven joint, N m/rad (default "
                                f"{DEFAULT_KP:g})")
    p.add_argument("--kd", help=f"inner-loop PD damping per driven joint, N m s/rad (default "
                                f"{DEFAULT_KD:g})")
    p.add_argument("--torque-limit", help=f"actuator limits per driven joint, N m (default "
                                          f"{LIMIT_FACTOR:g} x the scene's peak torque)")
    p.add_argument("--seed", type=int, default=0, help="seed of everything random (default 0)")
    p.add_argument("--workers", type=int, default=0,
                   help="processes simulating trajectories (default: one per core, at most 4)")
    p.add_argument("--quiet", action="store_true", help="no progress bars, no report")
    add_settings_file_arguments(p)
    settings_defaults(p, IDENTIFY_FLAGS)
    p.set_defaults(func=cmd_identify)
    return p


# identify's flags and the keys of the settings' [identify] table they override
IDENTIFY_FLAGS: FlagKeys = {
    **IDENTIFY_DATA, "lags": ("identify.output_lags", "identify.input_lags"),
    "hidden": "identify.hidden",
    "iterations": ("identify.one_step_iterations", "identify.multi_step_iterations"),
    "window": "identify.window", "no_linear_path": "!identify.linear_path",
    "kp": "identify.kp", "kd": "identify.kd", "torque_limit": "identify.torque_limit",
    "seed": "identify.seed", "workers": "identify.workers"}


def cmd_identify(args: argparse.Namespace) -> int:
    """``jointplay identify``: validate everything, then simulate, train and write."""
    from jointplay.common.extras import require

    require("control", "jointplay identify")  # before any work
    scene, settings, scene_file = scene_and_settings(args)
    fill_from_settings(args, settings, IDENTIFY_FLAGS)
    out = Path(args.out)
    output_plan(args, scene)
    check_writable_dir(out, "--out")
    config = identify_config(args, scene, settings.identify)
    check_scene_for(config, scene)
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


def identify_config(args: argparse.Namespace, scene: Scene,
                    base: IdentifyConfig | None = None) -> IdentifyConfig:
    """The configuration the flags give over ``base`` (the settings' keys without a flag),
    every flag checked and named when refused."""
    n = len(scene.robot.moving_joints)
    if not 0 <= args.seed <= MAX_SEED:
        raise DescriptionError("--seed", f"must be a whole number from 0 to {MAX_SEED} "
                               f"(2**32 - 1), got {args.seed}")
    lags = int_list(args.lags, "--lags", 2, high=size_limits.MAX_LAGS)
    hidden = int_list(args.hidden, "--hidden", high=size_limits.MAX_HIDDEN_WIDTH)
    if len(hidden) > size_limits.MAX_HIDDEN_LAYERS:
        raise DescriptionError("--hidden", f"gives {len(hidden)} layers; at most "
                               f"{size_limits.MAX_HIDDEN_LAYERS} are allowed")
    iters = iteration_counts(args.iterations, "--iterations", high=size_limits.MAX_ITERATIONS)
    counts = trajectory_counts(args)
    if sum(counts) > size_limits.MAX_TRAJECTORIES:
        raise DescriptionError("--train/--validation/--test", f"{sum(counts)} trajectories in "
                               f"all; at most {size_limits.MAX_TRAJECTORIES} are allowed")
    for flag, value, low, high in (("--window", args.window, size_limits.MIN_WINDOW,
                                       size_limits.MAX_WINDOW),
                                   ("--workers", args.workers, 0, size_limits.MAX_WORKERS)):
        if not low <= value <= high:
            raise DescriptionError(flag, f"must be an integer from {low} to {high}, got {value}")
    check_duration(args.duration, counts, lags, scene.run.output_step)
    return replace(
        base or IdentifyConfig(), duration=args.duration, n_train=counts[0],
        n_validation=counts[1], n_test=counts[2],
        output_lags=lags[0], input_lags=lags[1], hidden=hidden, seed=args.seed,
        kp=float_list(args.kp, "--kp", n), kd=float_list(args.kd, "--kd", n, positive=False),
        torque_limit=float_list(args.torque_limit, "--torque-limit", n),
        one_step_iterations=iters[0], multi_step_iterations=iters[1],
        window=args.window, workers=args.workers, linear_path=not args.no_linear_path,
        scheduling=args.scheduling, lpv_base=lpv_base_setting(args),
        contact_outputs=contact_setting(args, scene, "--contact-outputs"),
        linear_input_gain=args.linear_input_gain,
        residual_by=residual_setting(args, "--residual-by", counts[1]),
        base_fraction=base_fraction_setting(args, "--base-fraction"),
        base_motions=args.base_motions,
        scene_motions=scene_motions_setting(args, "--scene-motions"), **operating_range(args))


def check_scene_for(config: IdentifyConfig, scene: Scene) -> None:
    """What depends on the scene fails now, before any work: the default torque limits and
    the run at the trajectories' duration."""
    if not config.torque_limit:
        default_limits(scene)
    try:
        scene.with_run(t_end=config.duration)
    except DescriptionError as err:
        raise DescriptionError("--duration", err.message) from None
