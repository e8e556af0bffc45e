"""``jointplay derive``: write a robot's generated model (C, layout, robot) to a folder."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from jointplay.cli.args import check_writable_dir, robot_arguments, robot_from_args
from jointplay.common.files import OutputPlan, all_or_nothing, make_folder
from jointplay.store.formulation import CHOICES, ENVIRONMENT, RECURSIVE_FROM_COORDINATES
from jointplay.store.model import DEFERRED_SOURCE_NAME, LAYOUT_NAME, ROBOT_NAME, SOURCE_NAME


def register(subparsers: Any) -> argparse.ArgumentParser:
    p_derive = subparsers.add_parser("derive",
                                     help="write a robot's generated model to a folder")
    robot_arguments(p_derive)
    p_derive.add_argument("--out", required=True, help="folder to write model.c, layout.json "
                                                        "and robot.toml into")
    p_derive.add_argument("--formulation", choices=CHOICES, default=None,
                          help="closed form (Kane) or recursion over the chain; default: "
                               f"${ENVIRONMENT}, else auto (the recursion from "
                               f"{RECURSIVE_FROM_COORDINATES} coordinates on)")
    p_derive.set_defaults(func=cmd_derive)
    return p_derive


def cmd_derive(args: argparse.Namespace) -> int:
    from jointplay.mechanism.reading import is_mechanism_file

    if args.robot and is_mechanism_file(args.robot):
        return _derive_mechanism(args)
    robot = robot_from_args(args)
    out = Path(args.out)
    plan = OutputPlan()
    plan.input("robot", args.robot)
    for name in (SOURCE_NAME, DEFERRED_SOURCE_NAME, LAYOUT_NAME, ROBOT_NAME):
        plan.file("--out", out / name, f"the generated {name}")
    plan.check()
    check_writable_dir(out, "--out")
    from jointplay.derive import write_generated

    with all_or_nothing(plan):
        make_folder(out, "--out")
        emitted = write_generated(robot, out, args.formulation)
    t = emitted.timings
    formulation = emitted.layout["provenance"]["formulation"]
    print(f"wrote {out}/model.c ({len(emitted.source) / 1024:.0f} KiB, {formulation} "
          f"formulation), {DEFERRED_SOURCE_NAME} "
          f"({len(emitted.deferred_source) / 1024:.0f} KiB, compiled on first use), "
          f"layout.json, robot.toml in {t['derive']:.2f} s derive + "
          f"{t['emit']:.2f} s emit")
    return 0


def _derive_mechanism(args: argparse.Namespace) -> int:
    """A mechanism file: its stamped model.c and structure.json into ``--out``."""
    import json
    import time

    from jointplay.common.errors import DescriptionError
    from jointplay.common.files import atomic_write_text
    from jointplay.mechanism.model import input_hash
    from jointplay.mechanism.reading import load_mechanism_scene

    if args.formulation not in (None, "auto"):
        raise DescriptionError("--formulation", "a mechanism has one formulation; drop it")
    scene = load_mechanism_scene(args.robot)
    out = Path(args.out)
    plan = OutputPlan()
    plan.input("robot", args.robot)
    for name in (SOURCE_NAME, "structure.json"):
        plan.file("--out", out / name, f"the generated {name}")
    plan.check()
    check_writable_dir(out, "--out")
    from jointplay.derive.mechanism import emit

    structure = scene.mechanism.structure()
    t0 = time.perf_counter()
    source = emit(structure, scene.name, input_hash(structure))
    seconds = time.perf_counter() - t0
    with all_or_nothing(plan):
        make_folder(out, "--out")
        atomic_write_text(out / SOURCE_NAME, source)
        atomic_write_text(out / "structure.json",
                          json.dumps(structure.as_dict(), indent=1) + "\n")
    print(f"wrote {out}/{SOURCE_NAME} ({len(source) / 1024:.0f} KiB), structure.json in "
          f"{seconds:.2f} s derive + emit")
    return 0
