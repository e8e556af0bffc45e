"""MkDocs hook: the command reference, written at build time from the parsers themselves.

``jointplay.cli.make_parser()`` is walked command by command (and sub-command by sub-command:
``bench work-precision``, ``cache prune``); every argument is listed with its flags, value,
default and help, so the page can never disagree with what ``--help`` prints.
"""

from __future__ import annotations

import argparse
from typing import Any

from mkdocs.structure.files import File, Files

PAGE = "reference/cli.md"

INTRO = """# Commands

Every command of the `jointplay` program, read from its own parser when this site was built
(`jointplay COMMAND --help` prints the same). With neither a file nor robot flags, a command
uses the built-in default: the paper's 4-DOF arm and its scene. Exit statuses and limits are
in [Limits, exit statuses and errors](limits-and-errors.md).
"""


def _escape(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _subparsers(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    return {}


def _help_of(parser: argparse.ArgumentParser, name: str) -> str:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for choice in action._choices_actions:
                if choice.dest == name:
                    return choice.help or ""
    return ""


def _argument_rows(parser: argparse.ArgumentParser) -> list[str]:
    rows = []
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction | argparse._HelpAction):
            continue
        if action.help == argparse.SUPPRESS:
            continue
        if action.option_strings:
            metavar = ""
            if action.nargs != 0:
                metavar = " " + (action.metavar if isinstance(action.metavar, str)
                                 else action.dest.upper())
            name = ", ".join(f"`{flag}{metavar}`" for flag in action.option_strings)
        else:
            name = f"`{action.metavar if isinstance(action.metavar, str) else action.dest}`"
        default = ""
        if action.default not in (None, False, "", [], argparse.SUPPRESS) and action.nargs != 0:
            default = f"`{action.default}`"
        help_text = (action.help or "") % {"default": action.default, "prog": parser.prog} \
            if action.help and "%(" in action.help else (action.help or "")
        if action.choices and not isinstance(action.choices, dict):
            help_text += " (one of: " + ", ".join(f"`{c}`" for c in action.choices) + ")"
        rows.append(f"| {name} | {default} | {_escape(help_text.strip())} |")
    return rows


def _section(parser: argparse.ArgumentParser, title: str, summary: str, level: int) -> list[str]:
    out = [f"{'#' * level} `{title}`", ""]
    if summary:
        out += [_escape(summary[0].upper() + summary[1:]) + ".", ""]
    usage = parser.format_usage().removeprefix("usage: ").strip()
    out += ["```text", usage, "```", ""]
    if parser.description:
        out += [parser.description.strip(), ""]
    rows = _argument_rows(parser)
    if rows:
        out += ["| argument | default | meaning |", "|---|---|---|", *rows, ""]
    if parser.epilog:
        out += [parser.epilog.strip(), ""]
    for name, child in _subparsers(parser).items():
        out += _section(child, f"{title} {name}", _help_of(parser, name), level + 1)
    return out


def command_reference() -> str:
    """The page's Markdown: one section per command, from ``jointplay.cli.make_parser()``."""
    from jointplay.cli import make_parser
    from jointplay.cli.args import add_debug_flag

    parser = make_parser()
    add_debug_flag(parser)  # as jointplay.cli.main does, on every command
    lines = [INTRO, "## `jointplay`", "",
             "The program's own options; `--debug` is taken by every command too.", ""]
    lines += ["| argument | default | meaning |", "|---|---|---|", *_argument_rows(parser), ""]
    for name, child in _subparsers(parser).items():
        lines += _section(child, f"jointplay {name}", _help_of(parser, name), 2)
    return "\n".join(lines)


def on_files(files: Files, config: Any, **kwargs: Any) -> Files:
    files.append(File.generated(config, PAGE, content=command_reference()))
    return files
