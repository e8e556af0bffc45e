"""``jointplay inspect``: show a model's equations (text, LaTeX or Markdown)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from jointplay.cli.args import check_writable_file, robot_arguments, robot_from_args
from jointplay.common.files import OutputPlan


def register(subparsers: Any) -> argparse.ArgumentParser:
    p_inspect = subparsers.add_parser("inspect", help="show a model's equations")
    robot_arguments(p_inspect)
    p_inspect.add_argument("--format", choices=("text", "latex", "markdown"),
                           help="how the equations are written (default: markdown when --out "
                                "ends in .md, else text)")
    p_inspect.add_argument("--out", help="write to this file (.md: Markdown) instead of stdout")
    p_inspect.add_argument("--simplify", action="store_true",
                           help="trigonometric simplification (readable, slow beyond 3 links)")
    p_inspect.set_defaults(func=cmd_inspect)
    return p_inspect


def cmd_inspect(args: argparse.Namespace) -> int:
    from jointplay.mechanism.reading import is_mechanism_file

    if args.robot and is_mechanism_file(args.robot):
        return _inspect_mechanism(args)
    robot = robot_from_args(args)
    out = Path(args.out) if args.out else None
    plan = OutputPlan()
    plan.input("robot", args.robot)
    if out is not None:
        plan.file("--out", out)
        plan.check()
        check_writable_file(out, "--out")
    from jointplay.derive import derive
    from jointplay.derive.inspect import render

    fmt = args.format or ("markdown" if out is not None and out.suffix == ".md" else "text")
    text = render(derive(robot.structure()), fmt, simplify=args.simplify, title=robot.name)
    if out is None:
        sys.stdout.write(text)
    else:
        from jointplay.common.files import all_or_nothing, atomic_write_text

        with all_or_nothing(plan):
            atomic_write_text(out, text)
        print(f"wrote {out} ({fmt})")
    return 0


def _inspect_mechanism(args: argparse.Namespace) -> int:
    """A mechanism file: its tree, cut joints, coordinates, parameters, equations' form."""
    from jointplay.common.errors import DescriptionError
    from jointplay.common.files import all_or_nothing, atomic_write_text
    from jointplay.mechanism.inspect import render
    from jointplay.mechanism.reading import load_mechanism_scene

    if args.format == "latex":
        raise DescriptionError("--format", "a mechanism is shown as text or markdown")
    scene = load_mechanism_scene(args.robot)
    out = Path(args.out) if args.out else None
    fmt = args.format or ("markdown" if out is not None and out.suffix == ".md" else "text")
    text = render(scene, fmt)
    if out is None:
        sys.stdout.write(text)
        return 0
    plan = OutputPlan()
    plan.input("robot", args.robot)
    plan.file("--out", out)
    plan.check()
    check_writable_file(out, "--out")
    with all_or_nothing(plan):
        atomic_write_text(out, text)
    print(f"wrote {out} ({fmt})")
    return 0
