"""The README's tables of exit statuses and limits say what the code does: each documented
number is checked against the constant the table names beside it."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest

from jointplay.common import limits

README = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
_SECTION = README[README.index("## Limits, interrupts and errors"):]
_SECTION = _SECTION[:_SECTION.index("\n## ", 10)]


def table(header: str) -> list[list[str]]:
    """The rows (cells stripped) of the Markdown table whose header row starts ``header``."""
    start = _SECTION.index(header)
    rows = []
    for line in _SECTION[start:].splitlines()[2:]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip().strip("|").split("|")])
    assert rows, header
    return rows


def constants(cell: str) -> list[str]:
    return re.findall(r"`([\w.]+)`", cell)


_NUMBER = re.compile(r"(\d[\d ]*(?:\.\d+)?(?:e-?\d+)?)(\s*MiB)?")


def numbers(text: str) -> list[float]:
    """Every number in a limit's wording: ``1e5``, ``2 000 000``, ``256 MiB`` (in bytes)."""
    out = []
    for digits, mib in _NUMBER.findall(text):
        value = float(digits.replace(" ", ""))
        out.append(value * (1 << 20) if mib else value)
    return out


LIMIT_ROWS = table("| what | limit | constant")
EXIT_ROWS = table("| status | when | constant |")


@pytest.mark.parametrize("row", LIMIT_ROWS, ids=[r[0] for r in LIMIT_ROWS])
def test_limits_table_matches_the_code(row: list[str]) -> None:
    what, limit, names = row
    documented = numbers(limit.split("(")[0])  # a parenthesis explains, it limits nothing
    if "from 1 to" in limit:  # run.max_steps: the lower bound is the integer 1, not a limit
        documented = documented[1:]
    values = [getattr(limits, name) for name in constants(names)]
    if all(isinstance(v, dict) for v in values):  # a table of its own, checked row by row
        assert not documented, (what, limit)  # in tests/test_front_doors.py
        return
    assert documented == values, (what, limit, names)


def test_every_limit_is_documented() -> None:
    named = {name for row in LIMIT_ROWS for name in constants(row[2])}
    assert named == set(limits.__all__)


@pytest.mark.parametrize("row", EXIT_ROWS, ids=[r[0] for r in EXIT_ROWS])
def test_exit_table_matches_the_code(row: list[str]) -> None:
    status, _, name = row
    [path] = constants(name)
    module, attribute = path.rsplit(".", 1)
    assert getattr(importlib.import_module(module), attribute) == int(status), row


def test_exit_table_is_complete() -> None:
    """Every EXIT_* constant of the command line appears, and no status twice."""
    from jointplay.cli import args
    from jointplay.common import interrupts
    from jointplay.neural.study import control_run as control

    documented = [int(row[0]) for row in EXIT_ROWS]
    assert len(set(documented)) == len(documented)
    for module in (args, interrupts, control):
        for name in dir(module):
            if name.startswith("EXIT_"):
                assert getattr(module, name) in documented, name
