"""Measured motion to calibrate against: a CSV table or a jointplay results file.

A CSV has a header, a ``time`` column (s, strictly increasing) and any of ``tip_x``,
``tip_y`` (m) and the joint angles of the model (``q2``, ... in rad). A results file (.h5,
from ``jointplay simulate --out``) gives its tip position and every joint angle. Every cell
is checked before any simulation: a bad one is named by file, row and column.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.limits import MAX_MEASURED, MAX_TABLE_BYTES, MIN_NOISE
from jointplay.scene.definition import Scene
from jointplay.store.model import Model

TIP_COLUMNS = ("tip_x", "tip_y")
MIN_SAMPLES = 3
"""The fewest measured times: fewer leave nothing to fit beyond the start."""
# Times this close to a sample of the run (relative to its output step) are on its grid.
_ON_GRID = 1e-9


@dataclass(frozen=True)
class Measured:
    """Measured samples: ``values[i, k]`` is column ``columns[k]`` at ``t[i]``."""

    source: str
    t: np.ndarray
    columns: tuple[str, ...]
    values: np.ndarray

    @property
    def size(self) -> int:
        return int(self.values.size)


def angle_columns(model: Model) -> list[str]:
    """The joint angles a measurement may hold: the model's coordinates that are angles."""
    return [c for c in model.coordinates if c.startswith("q")]


def read_measured(path: str | Path, model: Model) -> Measured:
    """The measured samples in ``path`` (CSV or results file), checked against ``model``."""
    path = Path(path)
    if not path.is_file():
        raise DescriptionError("measured", f"{path} does not exist or is not a file; give a "
                               "CSV table or a results file (.h5)")
    if path.suffix.lower() in (".h5", ".hdf5"):
        return _from_results(path, model)
    return _from_csv(path, model)


def checked_for_scene(measured: Measured, scene: Scene, n_free: int) -> Measured:
    """``measured`` if its times lie inside the scene's run and it holds more numbers than
    free parameters; else the error naming the file."""
    t_end, source = scene.run.t_end, measured.source
    if measured.t[0] < 0.0:
        raise DescriptionError("time", f"{measured.t[0]:g} s is before the run starts (0 s); "
                               "measured times must lie in the scene's run", source)
    if measured.t[-1] > t_end * (1 + 1e-12):
        raise DescriptionError("time", f"{measured.t[-1]:g} s is after the scene's run ends "
                               f"({t_end:g} s); drop the later rows or lengthen run.t_end", source)
    if measured.size <= n_free:
        raise DescriptionError("time", f"{measured.size} measured numbers cannot determine "
                               f"{n_free} free parameters; measure longer or free fewer", source)
    return measured


def noise_levels(noise: float | Mapping[str, float] | None,
                 measured: Measured) -> np.ndarray | None:
    """The sensors' standard deviations, one per measured column (None: not given)."""
    if noise is None:
        return None
    if isinstance(noise, Mapping):
        unknown = [k for k in noise if k not in measured.columns]
        if unknown:
            raise DescriptionError(f"noise {unknown[0]}", "is not a measured column ("
                                   f"{', '.join(measured.columns)})"
                                   + did_you_mean(unknown[0], measured.columns))
        missing = [c for c in measured.columns if c not in noise]
        if missing:
            raise DescriptionError(f"noise {missing[0]}", "has no standard deviation; give "
                                   "one for every measured column, or one number for all")
        pairs = [(c, noise[c]) for c in measured.columns]
    else:
        pairs = [("noise", noise)] * len(measured.columns)
    for name, level in pairs:
        flag = name if name == "noise" else f"noise {name}"
        if isinstance(level, bool) or not isinstance(level, (int, float, np.floating)) \
                or not math.isfinite(level) or level <= 0:
            raise DescriptionError(flag, f"must be a finite standard deviation > 0, got {level!r}")
        if level < MIN_NOISE:
            raise DescriptionError(flag, f"must be at least {MIN_NOISE:g} (a standard deviation "
                                   f"in m or rad; no sensor resolves less), got {level!r}")
    return np.asarray([level for _, level in pairs], dtype=float)


def grid_indices(t: np.ndarray, output_step: float) -> np.ndarray | None:
    """Indices of ``t`` in the run's output grid, or None when a time falls between samples."""
    k = np.rint(t / output_step)
    if np.all(np.abs(t - k * output_step) <= _ON_GRID * output_step):
        return k.astype(int)
    return None


def _from_csv(path: Path, model: Model) -> Measured:
    return read_csv_table(path, "time, tip_x, ...", lambda header, source: checked_header(
        header, [*TIP_COLUMNS, *angle_columns(model)], source,
        "is not a column this model can be compared on"), _checked_value)


def read_csv_table(path: Path, example: str,
                   header_columns: Callable[[list[str], str], list[str]],
                   check_value: Callable[[float, str, str, str], None] | None = None,
                   ) -> Measured:
    """The measured samples of the CSV table ``path``, every cell checked.

    ``example`` begins the header the error for an empty file suggests; ``header_columns``
    checks the header (stripped cells) and gives the measured columns; ``check_value``, if
    given, checks each finite value beyond being a number (value, ``row N column NAME``,
    column, file). The scene's and the mechanism's calibrations both read their tables here.
    """
    source = str(path)
    if path.stat().st_size > MAX_TABLE_BYTES:
        raise DescriptionError("measured", f"is larger than {MAX_TABLE_BYTES >> 20} MiB; "
                               "give fewer samples", source)
    try:
        # utf-8-sig: spreadsheet programs start a CSV with a byte-order mark
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise DescriptionError("measured", "is not a UTF-8 text table; give a CSV with a "
                               "header row, or a results file (.h5)", source) from None
    rows = [row for row in csv.reader(io.StringIO(text)) if any(c.strip() for c in row)]
    if not rows:
        raise DescriptionError("measured", f"is empty; give a header row ({example}) "
                               "and the samples", source)
    header = [c.strip() for c in rows[0]]
    columns = header_columns(header, source)
    data = np.empty((len(rows) - 1, len(header)))
    for i, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            raise DescriptionError(f"row {i}", f"has {len(row)} cells, the header "
                                   f"{len(header)}; give every column in every row", source)
        for k, cell in enumerate(row):
            value = _cell(cell, i, header[k], source)
            if check_value is not None and header[k] != "time":
                check_value(value, f"row {i} column {header[k]}", header[k], source)
            data[i - 2, k] = value
    t = data[:, header.index("time")]
    values = data[:, [header.index(c) for c in columns]]
    return checked_times(Measured(source, t, tuple(columns), values))


def checked_header(header: Sequence[str], allowed: Sequence[str], source: str,
                   not_allowed: str, refused: Mapping[str, str] | None = None) -> list[str]:
    """The measured columns of ``header``: ``time`` and names from ``allowed``, each once.

    A name outside ``allowed`` gets ``not_allowed`` (what it is not) with the allowed names;
    a name in ``refused`` gets its message there instead.
    """
    listed = ", ".join(allowed)
    if "time" not in header:
        raise DescriptionError("time", "column is missing; the header needs time (s) and "
                               f"any of {listed}", source)
    seen: set[str] = set()
    for name in header:
        if name in seen:
            raise DescriptionError(name or "header", "column appears twice; name each once", source)
        seen.add(name)
        if refused and name in refused:
            raise DescriptionError(name, refused[name], source)
        if name != "time" and name not in allowed:
            raise DescriptionError(name or "header", f"{not_allowed}; allowed: time, {listed}"
                                   + did_you_mean(name, ["time", *allowed]), source)
    columns = [c for c in header if c != "time"]
    if not columns:
        raise DescriptionError("header", "has a time column only; add measured columns ("
                               f"{listed})", source)
    return columns


def _cell(text: str, row: int, column: str, source: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise DescriptionError(f"row {row} column {column}", f"is not a number ({text!r})",
                               source) from None
    if not math.isfinite(value):
        raise DescriptionError(f"row {row} column {column}", f"is {text.strip()}; every cell "
                               "must be a finite number (drop or fill missing samples)", source)
    return value


def _checked_value(value: float, where: str, column: str, source: str) -> None:
    if abs(value) > MAX_MEASURED:
        unit = "m" if column in TIP_COLUMNS else "rad"
        raise DescriptionError(where, f"is {value:g} {unit}; a measured "
                               f"value must lie within ±{MAX_MEASURED:g} {unit} (check the "
                               "units: metres and radians)", source)


def checked_times(measured: Measured) -> Measured:
    """``measured`` if it has enough samples at strictly increasing times."""
    t = measured.t
    if t.size < MIN_SAMPLES:
        raise DescriptionError("time", f"has {t.size} samples; a calibration needs at least "
                               f"{MIN_SAMPLES}", measured.source)
    steps = np.diff(t)
    if np.any(steps <= 0):
        k = int(np.argmax(steps <= 0))
        raise DescriptionError("time", f"must increase strictly: {t[k + 1]:g} s follows "
                               f"{t[k]:g} s (sample {k + 2})", measured.source)
    return measured


def _from_results(path: Path, model: Model) -> Measured:
    from jointplay.results.write import read

    source = str(path)
    try:
        result = read(path)
    except DescriptionError:
        raise
    except (OSError, ValueError, KeyError) as err:
        raise DescriptionError("measured", f"cannot be read as a results file ({err}); give one "
                               "written by jointplay simulate --out, or a CSV", source) from None
    angles = angle_columns(model)
    missing = [c for c in angles if c not in result.coordinate_names]
    if missing:
        raise DescriptionError("measured", f"holds no {missing[0]}: it is a run of another "
                               "robot; measure this scene's robot", source)
    values = np.column_stack([result.tip_position[:, 0], result.tip_position[:, 1],
                              *(result.q[:, result.coordinate_names.index(c)] for c in angles)])
    if not np.all(np.isfinite(values)):
        raise DescriptionError("measured", "holds values that are not finite", source)
    if np.any(np.abs(values) > MAX_MEASURED):
        raise DescriptionError("measured", f"holds values beyond ±{MAX_MEASURED:g} (m or rad); "
                               "give a run of a real robot", source)
    t = np.asarray(result.t, float)
    return checked_times(Measured(source, t, (*TIP_COLUMNS, *angles), values))
