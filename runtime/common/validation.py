"""Checks every data file shares (robots, scenes, sweeps): reading TOML safely, refusing unknown
keys with the nearest allowed one, and numbers that must be finite, positive or in SI units.

Each error is a :class:`~jointplay.common.errors.DescriptionError` that names the field and
what is allowed, so every file format reports mistakes the same way.
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from jointplay.common.errors import DescriptionError, combined
from jointplay.common.hints import did_you_mean
from jointplay.common.limits import PHYSICAL_RANGES


class Problems:
    """Collects the invalid fields of one description, so that all are reported at once.

        problems = Problems()
        with problems.check():
            positive("links[1].mass", mass)
        ...
        problems.raise_any()   # one DescriptionError, or DescriptionErrors for several
    """

    def __init__(self) -> None:
        self.found: list[DescriptionError] = []

    def check(self) -> Problems:
        """Run a check (``with problems.check(): ...``); a :class:`DescriptionError` it raises
        is kept, not raised."""
        return self

    def __enter__(self) -> None:
        return None

    def __exit__(self, kind: type[BaseException] | None, err: BaseException | None,
                 traceback: object) -> bool:
        if isinstance(err, DescriptionError):
            self.found.extend(err.problems)
            return True
        return False

    def __bool__(self) -> bool:
        return bool(self.found)

    def attributed(self, source: str | None) -> list[DescriptionError]:
        """Everything found, each problem without a source attributed to ``source``."""
        return [p if p.source or source is None else p.with_source(source) for p in self.found]

    def raise_any(self, source: str | None = None) -> None:
        """Raise everything found (attributed to ``source`` when it is given); else nothing."""
        if self.found:
            raise combined(self.attributed(source))


def positive(field_name: str, value: float, *, allow_zero: bool = False) -> None:
    """A finite number > 0 (>= 0 with ``allow_zero``)."""
    if not isinstance(value, (int, float)) or isinstance(value, bool) or math.isnan(value) \
            or math.isinf(value):
        raise DescriptionError(field_name, f"must be a finite number, got {value!r}")
    if value < 0 or (value == 0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise DescriptionError(field_name, f"must be {bound}, got {value!r}")


def plausible(field_name: str, value: float, kind: str) -> None:
    """A finite number inside the documented range of its kind of quantity
    (:data:`jointplay.common.limits.PHYSICAL_RANGES`): no real robot has a link of 1e-300 m
    or a contact exponent of 1e300, and such numbers only overflow later, mid-run."""
    finite(field_name, value)
    low, high, unit, what = PHYSICAL_RANGES[kind]
    if not low <= value <= high:
        units = f" {unit}" if unit else ""
        raise DescriptionError(field_name, f"{value:g}{units} is outside the range a real "
                               f"robot's {what} has ({low:g} to {high:g}{units}); see "
                               "docs/reference/limits-and-errors.md")


def finite(field_name: str, value: float) -> None:
    try:  # an integer beyond float64 (10**400) is no finite float either
        number = float(value) if isinstance(value, (int, float)) else math.nan
    except OverflowError:
        number = math.inf
    if not isinstance(value, (int, float)) or isinstance(value, bool) \
            or not math.isfinite(number):
        shown = repr(value)
        shown = shown if len(shown) <= 40 else f"{shown[:20]}... ({len(shown)} characters)"
        raise DescriptionError(field_name, f"must be a finite number, got {shown}")


def number(value: Any, where: str) -> float:
    """A TOML number (int or float, not a boolean) as a float."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise DescriptionError(where, f"must be a number in SI units, got {value!r}")
    return float(value)


def boolean(value: Any, where: str) -> bool:
    if not isinstance(value, bool):
        raise DescriptionError(where, f"must be true or false, got {value!r}")
    return value


def check_keys(table: Any, allowed: Sequence[str], where: str,
               source: str | None = None) -> None:
    """Refuse a non-table or an unknown key, naming the nearest allowed key."""
    if not isinstance(table, Mapping):
        raise DescriptionError(where or "(top level)",
                               f"must be a table, got {type(table).__name__}", source)
    prefix = f"{where}." if where else ""
    unknown = [DescriptionError(f"{prefix}{key}", f"unknown key (allowed: {', '.join(allowed)})"
                                f"{did_you_mean(str(key), allowed)}", source)
               for key in table if key not in allowed]
    if unknown:  # all of them, so that one round of corrections fixes them all
        raise combined(unknown)


def read_toml(path: str | Path, what: str) -> tuple[dict[str, Any], str]:
    """The parsed document and its text; errors name the file (``what``: "robot", "scene"...).

    Only a regular file of at most ``MAX_TOML_BYTES`` is read: a device or FIFO is refused at
    once instead of blocking or filling memory.
    """
    from jointplay.common.files import read_input
    from jointplay.common.limits import MAX_TOML_BYTES, MAX_TOML_NESTING

    path = Path(path)
    data = read_input(path, "(file)", f"{what} TOML file", MAX_TOML_BYTES)
    try:
        # Newlines translated as by a text-mode read; a UTF-8 byte-order mark (which some
        # Windows editors write) is accepted and dropped, as TOML's text is UTF-8 anyway.
        text = data.decode("utf-8-sig").replace("\r\n", "\n").replace("\r", "\n")
    except UnicodeDecodeError as err:
        raise DescriptionError("(file)", f"is not UTF-8 text ({err})", str(path)) from None
    depth = _nesting_depth(text)
    if depth > MAX_TOML_NESTING:
        raise DescriptionError("(toml)", f"nests arrays or inline tables {depth} deep; at most "
                               f"{MAX_TOML_NESTING} levels are allowed (a description needs "
                               "three)", str(path))
    try:
        return tomllib.loads(text), text
    except tomllib.TOMLDecodeError as err:
        raise DescriptionError("(toml)", f"malformed TOML: {err}", str(path)) from None
    except RecursionError:  # nesting that the count above did not see (inside strings, say)
        raise DescriptionError("(toml)", "nests too deeply to be read", str(path)) from None


def _nesting_depth(text: str) -> int:
    """An upper bound of the nesting depth of ``[``/``{`` in the text (brackets inside strings
    and comments counted too: a bound is all the check needs, and descriptions nest little)."""
    depth = deepest = 0
    for char in text:
        if char in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif char in "]}":
            depth = max(0, depth - 1)
    return deepest
