"""The ``jointplay`` command.

  jointplay build   [ROBOT.toml | flags]                 derive, compile, load and check a model
  jointplay derive  [ROBOT.toml | flags] --out DIR       write the generated model to DIR
  jointplay inspect [ROBOT.toml | flags] [--format text|latex|markdown] [--out FILE.md]
  jointplay simulate [SCENE.toml] [--out RUN.h5] [--csv RUN.csv] [--plot DIR] [--compare-ideal]
                     [--output-step H] [--animate FILE.gif|mp4]
  jointplay plot RUN.h5 --out DIR                        every figure of a results file
  jointplay compare A.h5 B.h5 [...] --out DIR            runs overlaid, table of differences
  jointplay identify | control | control-study ...       identification, the neural controller
  jointplay sweep SWEEP.toml --out DIR                   parameter sweeps on Dask
  jointplay calibrate [SCENE.toml] --measured FILE --free NAME[,...] --out DIR
                                                         parameters from measured motion
  jointplay bench work-precision | fidelity | scaling    what accuracy costs, measured
  jointplay cache list | clear | prune [--older-than AGE] [--max-size SIZE]

With neither a file nor flags, the robot is the built-in default (the paper's 4-link arm).
Bad input exits with status 2 and a message naming the field and what is allowed; nothing is
written. Deriving imports sympy; loading and evaluating a generated model does not.

One module per command (``jointplay.cli.simulate`` and so on, each with its ``register``),
over the argument helpers they share (:mod:`jointplay.cli.args`).
"""

from __future__ import annotations

import argparse
import importlib
import sys

from jointplay.cli.args import EXIT_BAD_INPUT, add_debug_flag, interrupted, report_error
from jointplay.cli.summary import contact_lines, summary
from jointplay.common import interrupts

# Each command's module (``jointplay.cli.NAME``, with its ``register``), in the order of the
# listing. A command imports its own module only: the others are named, not imported (the
# control commands' modules alone took 0.12 s to import before a simulation could start).
COMMANDS = {"build": "build", "derive": "derive", "inspect": "inspect",
            "simulate": "simulate", "plot": "look", "compare": "look", "identify": "identify",
            "calibrate": "calibrate", "control": "control", "control-study": "study",
            "sweep": "sweep", "bench": "bench", "cache": "cache"}


def make_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The parser of every command; with ``command`` (one of :data:`COMMANDS`), that
    command's in full and the others by name only, so that only its module is imported."""
    parser = argparse.ArgumentParser(
        prog="jointplay",
        description="Dynamics of planar serial robots with revolute-joint clearance.")
    parser.add_argument("--version", action="version", version=f"jointplay {_version()}")
    sub = parser.add_subparsers(dest="command", required=True)
    chosen = COMMANDS.get(command or "")
    for module in dict.fromkeys(COMMANDS.values()):
        if chosen is None or module == chosen:
            importlib.import_module(f"jointplay.cli.{module}").register(sub)
        else:
            for name in (n for n, m in COMMANDS.items() if m == module):
                sub.add_parser(name)
    return parser


def _command_word(argv: list[str]) -> str | None:
    """The command a command line names: its first word that is not an option (the
    program's own options take no value)."""
    return next((word for word in argv if not word.startswith("-")), None)


def _version() -> str:
    from jointplay import __version__

    return __version__


def main(argv: list[str] | None = None) -> int:
    parser = make_parser(_command_word(sys.argv[1:] if argv is None else argv))
    add_debug_flag(parser)
    args, extras = parser.parse_known_args(argv)
    if extras:
        refuse_unknown(parser, args, extras)
    with interrupts.installed():
        try:
            refuse_empty_values(parser, args)
            code = int(args.func(args))
            interrupts.raise_if_interrupted()  # one that a library swallowed still counts
            return code
        except KeyboardInterrupt:
            return interrupted(args)
        except Exception as err:
            # Compiled code may turn an interrupt into an error of its own: still Ctrl-C.
            if interrupts.interrupted():
                return interrupted(args)
            return report_error(err, args)


def refuse_unknown(parser: argparse.ArgumentParser, args: argparse.Namespace,
                   extras: list[str]) -> None:
    """Words no argument took: argparse's error (exit 2) with the usage of the command
    given, not the program's, and for a misspelt option the nearest of that command's
    (``simulate --t-edn``: did you mean '--t-end'?)."""
    from jointplay.common.hints import did_you_mean

    command = parser
    while True:  # the deepest subcommand chosen (``cache clear``, ``bench scaling``)
        chosen = next((action.choices.get(getattr(args, action.dest, None) or "")
                       for action in command._actions
                       if isinstance(action, argparse._SubParsersAction)), None)
        if chosen is None:
            break
        command = chosen
    options = [o for action in command._actions for o in action.option_strings
               if o.startswith("--")]
    hint = ""
    for word in extras:
        if word.startswith("-"):
            hint = did_you_mean(word.split("=", 1)[0], options)
            if hint:
                break
    command.error(f"unrecognized arguments: {' '.join(extras)}{hint}")


def refuse_empty_values(parser: argparse.ArgumentParser, args: argparse.Namespace) -> None:
    """An empty value given to an argument whose default is not empty (``--out ''``, a scene
    ``''``) is a mistake, not a request for the default or for nothing: refused (exit 2)."""
    from jointplay.common.errors import DescriptionError

    for action in _actions(parser, args):
        if getattr(args, action.dest, None) == "" and action.default != "":
            name = action.option_strings[-1] if action.option_strings else action.dest
            what = f" ({action.metavar})" if isinstance(action.metavar, str) else ""
            raise DescriptionError(name, f"is empty; give a value{what}")


def _actions(parser: argparse.ArgumentParser, args: argparse.Namespace
             ) -> list[argparse.Action]:
    """Every argument of ``parser`` and of the subcommand ``args`` chose, at any depth."""
    found = []
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            chosen = action.choices.get(getattr(args, action.dest, None) or "")
            if chosen is not None:
                found += _actions(chosen, args)
        else:
            found.append(action)
    return found


__all__ = ["EXIT_BAD_INPUT", "contact_lines", "main", "make_parser", "summary"]

if __name__ == "__main__":
    sys.exit(main())
