"""Drive torques as CSV tables: ``t`` and one column per driven joint, interpolated linearly
and held at their end values outside the time range, identically in numpy and CasADi."""

from __future__ import annotations

import csv
import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from jointplay.common import limits
from jointplay.common.errors import DescriptionError
from jointplay.scene.expressions import TIME, Symbolic, _as_casadi

# --- Tables ------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class TableColumn:
    """One column of a :class:`TorqueTable`, as a piecewise-linear function of time.

    Values are held at the first/last row outside the table's time range.
    """

    name: str
    times: np.ndarray
    values: np.ndarray

    def numpy(self, t: float | np.ndarray) -> np.ndarray:
        """Interpolate with :func:`numpy.interp` (which holds the end values)."""
        times = np.asarray(t, dtype=np.float64)
        return np.asarray(np.interp(times, self.times, self.values), dtype=np.float64)

    @cached_property
    def _interpolant(self) -> Any:
        return ca.interpolant("torque_table", "linear", [self.times.tolist()],
                              self.values.tolist())

    def casadi(self, t: Symbolic) -> Symbolic:
        """Interpolate with a CasADi linear interpolant.

        CasADi's interpolant extrapolates the end segments, so ``t`` is clamped into the table
        range first to hold the end values like numpy.
        """
        t, _ = _as_casadi(t)
        clamped = ca.fmin(ca.fmax(t, float(self.times[0])), float(self.times[-1]))
        return self._interpolant(clamped)


@dataclass(frozen=True, eq=False)
class TorqueTable:
    """Torques sampled in time: ``times`` (n,), ``values`` (n, columns), ``header`` names.

    The arrays are read-only so the table stays immutable.
    """

    times: np.ndarray
    values: np.ndarray
    header: tuple[str, ...]

    @property
    def columns(self) -> int:
        """Number of torque columns (the ``t`` column not counted)."""
        return int(self.values.shape[1])

    def column(self, i: int) -> TableColumn:
        """The ``i``-th torque column, counted from 0 after ``t``."""
        if not 0 <= i < self.columns:
            raise IndexError(f"torque column {i} out of range 0..{self.columns - 1}")
        return TableColumn(self.header[i + 1], self.times, self.values[:, i])


def load_torque_table(path: str | Path, *, columns: int, field: str,
                      source: str | None = None) -> TorqueTable:
    """Read a CSV of torques: a header ``t,<name>,...``, then rows of finite floats.

    ``t`` (s) must be strictly increasing with at least 2 rows, and there must be exactly
    ``columns`` torque columns. Raises :class:`DescriptionError` naming ``field``.
    """
    if isinstance(columns, bool) or not isinstance(columns, int) or columns < 1:
        raise ValueError(f"columns must be a positive integer, got {columns!r}")
    path = Path(path)
    expected = f"expected a CSV file with header 't' then {columns} torque column(s)"

    def fail(message: str) -> DescriptionError:
        return DescriptionError(field, f"{path}: {message}", source)

    rows = _read_rows(path, expected, fail)
    header = _header(rows, columns, fail)
    table = _data_rows(rows[1:], header, fail)
    times = table[:, 0].copy()
    values = table[:, 1:].copy()
    times.flags.writeable = False
    values.flags.writeable = False
    return TorqueTable(times, values, header)


# Builds the error for a message about the file being read (it names the field and the file).
_Fail = Callable[[str], DescriptionError]


def _read_rows(path: Path, expected: str, fail: _Fail) -> list[tuple[int, list[str]]]:
    """(line number, cells) of every non-blank line; the file must exist and hold some."""
    if not path.is_file():
        what = "is not a file" if path.exists() else "file not found"
        raise fail(f"{what}; {expected}")
    try:  # the limit is checked before a byte is read
        size = path.stat().st_size
    except OSError as error:
        raise fail(f"cannot be read ({error}); {expected}") from None
    if size > limits.MAX_TABLE_BYTES:
        raise fail(f"is {size} bytes; a torque table may have at most "
                   f"{limits.MAX_TABLE_BYTES} ({limits.MAX_TABLE_BYTES >> 20} MiB)")
    rows: list[tuple[int, list[str]]] = []
    try:
        with path.open(newline="", encoding="utf-8-sig") as handle:
            reader = csv.reader(handle)
            for row in reader:
                if any(cell.strip() for cell in row):
                    rows.append((reader.line_num, row))
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        raise fail(f"cannot be read ({error}); {expected}") from None
    if not rows:
        raise fail(f"is empty; {expected}")
    return rows


def _header(rows: list[tuple[int, list[str]]], columns: int, fail: _Fail) -> tuple[str, ...]:
    """The first row: 't', then one named column per driven joint."""
    _, header_row = rows[0]
    header = tuple(cell.strip() for cell in header_row)
    if len(header) != columns + 1:
        raise fail(f"header has {len(header)} column(s), expected {columns + 1} "
                   f"('t' then one per driven joint)")
    if header[0] != TIME:
        raise fail(f"first header cell is {header[0]!r}; it must be 't' (time in seconds)")
    for i, name in enumerate(header[1:], start=2):
        if not name:
            raise fail(f"header column {i} is empty; every column needs a name")
    return header


def _data_rows(data: list[tuple[int, list[str]]], header: tuple[str, ...], fail: _Fail
               ) -> np.ndarray:
    """The rows after the header as floats, (rows, 1 + torque columns): at least two, every
    cell a finite number, times strictly increasing."""
    width = len(header)
    if len(data) < 2:
        raise fail(f"has {len(data)} data row(s); at least 2 are needed to interpolate")
    table = np.empty((len(data), width), dtype=np.float64)
    for r, (line, row) in enumerate(data):
        if len(row) != width:
            raise fail(f"line {line} has {len(row)} cell(s), expected {width}")
        for c, cell in enumerate(row):
            table[r, c] = _cell(cell, line, c, header, fail)
        if r > 0 and not table[r, 0] > table[r - 1, 0]:
            raise fail(f"line {line}: t = {float(table[r, 0])!r} is not greater than the "
                       f"previous t = {float(table[r - 1, 0])!r}; times must be strictly "
                       "increasing")
    return table


def _cell(cell: str, line: int, c: int, header: tuple[str, ...], fail: _Fail) -> float:
    try:
        value = float(cell.strip())
    except ValueError:
        raise fail(f"line {line}, column {header[c]!r} ({c + 1}): {cell!r} is not a "
                   "number; every cell must be a finite number") from None
    if not math.isfinite(value):
        raise fail(f"line {line}, column {header[c]!r} ({c + 1}): {cell.strip()!r} is "
                   "not finite; every cell must be a finite number")
    return value
