"""What every ``jointplay`` command shares: the robot flags, checks of the paths it will write,
parsing of number lists, the ``--debug`` flag, and turning an error into one line and an exit
status. Every check runs before any work and names the flag it refuses."""

from __future__ import annotations

import argparse
import contextlib
import math
import os
import shlex
import sys
import traceback
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from jointplay.common import interrupts
from jointplay.common.errors import DescriptionError, JointplayError
from jointplay.robot import Robot, load_robot, robot_from_flags

if TYPE_CHECKING:
    from jointplay.common.files import OutputPlan
    from jointplay.scene.definition import Scene

# Exit statuses (docs/reference/limits-and-errors.md; tests/test_docs_tables.py checks the
# table there against these, jointplay.common.interrupts's and
# jointplay.neural.study.control_run's).
EXIT_OK = 0
EXIT_FAILURE = 1
EXIT_BAD_INPUT = 2


# ---- the robot, the scene --------------------------------------------------------------------

def robot_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("robot", nargs="?", help="robot description (TOML); default: the "
                                                  "built-in paper robot")
    group = parser.add_argument_group("robot from flags (instead of a file)")
    group.add_argument("--links", help="number of links, 1 to 32")
    group.add_argument("--clearance", default="", help="joints with clearance, e.g. 2,5")
    group.add_argument("--locked", default="", help="locked joints, e.g. 1")
    group.add_argument("--locked-clearance", default="",
                       help="locked joints whose journal still has play")
    group.add_argument("--friction", choices=("none", "coulomb"), default="coulomb",
                       help="friction in the clearance joints (default: %(default)s; none "
                            "compiles it out)")
    group.add_argument("--contact-law", default="lankarani-nikravesh",
                       choices=("lankarani-nikravesh", "hunt-crossley", "gonthier", "flores"),
                       help="damping factor of the contact law (default: %(default)s)")
    group.add_argument("--no-gravity", action="store_true",
                       help="a model without gravity (the arm moves in a horizontal plane)")


def robot_from_args(args: argparse.Namespace) -> Robot:
    flags_used = args.links is not None or any(
        (args.clearance, args.locked, args.locked_clearance))
    if args.robot and flags_used:
        raise DescriptionError("--links", "give either a description file or flags, not both")
    if args.robot:
        return load_robot(args.robot)
    if flags_used:
        if args.links is None:
            raise DescriptionError("--links", "is required when joints are given by flags")
        return robot_from_flags(args.links, clearance=args.clearance, locked=args.locked,
                                locked_clearance=args.locked_clearance, friction=args.friction,
                                contact_law=args.contact_law, gravity=not args.no_gravity)
    from jointplay import default_robot

    return default_robot()


def scene_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", nargs="?", help="scene file (TOML); default: the built-in "
                                                  "paper scene")


def scene_from_args(args: argparse.Namespace) -> Scene:
    from jointplay.scene.definition import default_scene, load_scene

    return load_scene(args.scene) if args.scene else default_scene()


def plausibility_argument(parser: argparse.ArgumentParser) -> None:
    from jointplay.scene.definition import PLAUSIBILITY

    parser.add_argument("--plausibility", choices=PLAUSIBILITY,
                        help="override run.plausibility: what a run that leaves the physical "
                             "domain (a journal through its bearing, an energy balance that "
                             "does not close) does: stop with exit 1 (default), warn and keep "
                             "the result marked, or check nothing")


@contextlib.contextmanager
def warn_plausibility() -> Iterator[None]:
    """Within: a run kept with ``run.plausibility = "warn"`` prints its one warning line as
    ``jointplay: warning: ...`` (not Python's warning format)."""
    import warnings

    from jointplay.sim.plausibility import PlausibilityWarning

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PlausibilityWarning)
        try:
            yield
        finally:
            for warning in caught:
                if issubclass(warning.category, PlausibilityWarning):
                    print(f"jointplay: warning: {warning.message}", file=sys.stderr)
                else:
                    warnings.showwarning(warning.message, warning.category,
                                         warning.filename, warning.lineno)


def run_flag(field: str) -> str:
    """The command-line flag of a run setting: ``run.t_end`` -> ``--t-end``."""
    return "--" + field.removeprefix("run.").replace("_", "-")


# ---- paths the command will write ------------------------------------------------------------

def check_writable_dir(path: Path, flag: str) -> None:
    target = path if path.exists() else path.parent
    if path.exists() and not path.is_dir():
        raise DescriptionError(flag, f"{path} exists and is not a folder")
    while not target.exists():
        target = target.parent
    if not os.access(target, os.W_OK):
        raise DescriptionError(flag, f"cannot write to {target}: permission denied")


def check_writable_file(path: Path, flag: str) -> None:
    if path.is_dir():
        raise DescriptionError(flag, f"{path} is a folder; give a file name")
    if not path.parent.exists():
        raise DescriptionError(flag, f"folder {path.parent} does not exist")
    if not os.access(path.parent, os.W_OK):
        raise DescriptionError(flag, f"cannot write to {path.parent}: permission denied")


def prepare_out_dir(path: str | Path, flag: str = "--out") -> Path:
    """Create the output folder (and parents) or fail naming the flag, before any work."""
    path = Path(path)
    if path.exists() and not path.is_dir():
        raise DescriptionError(flag, f"{path} exists and is not a folder")
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise DescriptionError(flag, f"cannot create folder {path}: {err.strerror}") from None
    if not os.access(path, os.W_OK | os.X_OK):
        raise DescriptionError(flag, f"cannot write to {path}: permission denied")
    return path


# ---- numbers and lists -----------------------------------------------------------------------

def positive_floats(text: str, flag: str) -> list[float]:
    """``"1e-3, 1e-4"`` to finite numbers > 0; an empty list is refused."""
    values = []
    for item in text.split(","):
        item = item.strip()
        if not item:
            continue
        try:
            value = float(item)
        except ValueError:
            raise DescriptionError(flag, f"expects comma-separated numbers, got {item!r}") \
                from None
        if not (math.isfinite(value) and value > 0):
            raise DescriptionError(flag, f"every value must be a finite number > 0, got "
                                         f"{item!r}")
        values.append(value)
    if not values:
        raise DescriptionError(flag, "no values given")
    return values


def choices_list(text: str, allowed: Sequence[str], flag: str, what: str) -> list[str]:
    """A comma list of names, each one of ``allowed``; an empty list is refused."""
    names = [s.strip() for s in text.split(",") if s.strip()]
    for name in names:
        if name not in allowed:
            raise DescriptionError(flag, f"unknown {what} {name!r}; choose from "
                                         f"{', '.join(allowed)}")
    if not names:
        raise DescriptionError(flag, f"no {what}s given")
    return names


def parse_links(text: str, flag: str = "--links") -> list[int]:
    """``"1-12"``, ``"4,9,12"`` or ``"1-4,12"`` to a sorted list of link counts."""
    from jointplay.robot import MAX_LINKS

    out: set[int] = set()
    for part in text.split(","):
        part = part.strip()
        if not part:
            continue
        lo, sep, hi = part.partition("-")
        try:
            first, last = int(lo), int(hi) if sep else int(lo)
        except ValueError:
            raise DescriptionError(flag, f"expects link counts like 1-12 or 2,4,8, got "
                                         f"{part!r}") from None
        if first < 1 or last < first or last > MAX_LINKS:
            raise DescriptionError(flag, f"link counts must be 1 to {MAX_LINKS}, low to high, "
                                         f"got {part!r}")
        out.update(range(first, last + 1))
    if not out:
        raise DescriptionError(flag, "no link counts given")
    return sorted(out)


def positive_int(value: int, flag: str) -> int:
    if value < 1:
        raise DescriptionError(flag, f"must be >= 1, got {value}")
    return value


def command_line() -> str:
    """The command line, when run as the ``jointplay`` program (else a report's settings
    stand alone)."""
    if Path(sys.argv[0]).name == "jointplay":
        return shlex.join(["jointplay", *sys.argv[1:]])
    return ""


# ---- --debug, errors and exit statuses -------------------------------------------------------

def add_debug_flag(parser: argparse.ArgumentParser) -> None:
    """``--debug`` on the command and on every subcommand."""
    parser.add_argument("--debug", action="store_true",
                        help="show the full traceback of an error")
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                # SUPPRESS: a subcommand's absent flag must not reset the top-level one.
                sub.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                                 help="show the full traceback of an error")


def interrupted(args: argparse.Namespace) -> int:
    if args.debug:
        traceback.print_exc()
    status = interrupts.exit_status()
    print("jointplay: interrupted" if status == interrupts.EXIT_INTERRUPTED
          else "jointplay: terminated", file=sys.stderr)
    return status


def report_error(err: Exception, args: argparse.Namespace) -> int:
    """One line naming the cause (the traceback only with --debug); the exit status."""
    if args.debug:
        traceback.print_exc()
    if isinstance(err, DescriptionError):
        print(f"jointplay: error: {err}", file=sys.stderr)
        return EXIT_BAD_INPUT
    if isinstance(err, JointplayError):
        text = str(err)
    elif isinstance(err, OSError):
        from jointplay.common.files import describe_os_error

        where = f"{err.filename}: " if err.filename else ""
        text = f"{where}{describe_os_error(err)}"
    elif isinstance(err, MemoryError):
        text = "out of memory; give a shorter run, fewer outputs or fewer cases"
    else:
        text = f"internal error ({type(err).__name__}: {err})"
    lines = text.splitlines() or [type(err).__name__]
    hint = "" if args.debug or isinstance(err, JointplayError) else \
        " (--debug shows the traceback)"
    print(f"jointplay: error: {lines[0]}{hint}", file=sys.stderr)
    if len(lines) > 1:  # a compiler's output, say: the detail, after the one line
        print("\n".join(lines[1:]), file=sys.stderr)
    return EXIT_FAILURE


def plan_scene_inputs(plan: OutputPlan, scene: Scene) -> None:
    """The files a scene was read from, as inputs of ``plan``: the scene, its torque table."""
    from jointplay.scene.definition import scene_inputs

    for k, path in enumerate(scene_inputs(scene)):
        plan.input("scene" if k == 0 else "torque table", path)
