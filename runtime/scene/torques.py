"""A scene's drive torques and the named constants their expressions may use: read from
``[constants]`` and ``[torques]`` (expressions of t through the restricted parser, or a CSV
table), then checked against the run (a table covers it; every torque is finite at every
output time)."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.common.errors import DescriptionError
from jointplay.common.validation import Problems, check_keys
from jointplay.robot import Robot
from jointplay.scene.expressions import FUNCTIONS, TimeFunction, parse_expression
from jointplay.scene.initial import finite_number as _finite_number
from jointplay.scene.tables import TableColumn, load_torque_table

if TYPE_CHECKING:
    from jointplay.scene.definition import RunSettings


def _error(field_name: str, message: str, source: str | None) -> DescriptionError:
    return DescriptionError(field_name, message, source)


def read_constants(raw: Any, source: str | None) -> dict[str, float]:
    check_keys(raw, tuple(raw) if isinstance(raw, Mapping) else (), "constants", source)
    out: dict[str, float] = {}
    for key, value in raw.items():
        if not key.isidentifier() or key.startswith("_") or key in ("t", "pi", "e"):
            raise _error(f"constants.{key}", "a constant's name must be a plain identifier "
                         "(letters, digits, underscores; not starting with _), and not t, pi "
                         "or e", source)
        if key in FUNCTIONS:
            raise _error(f"constants.{key}", f"{key!r} is the name of a function "
                         f"({key}(x)); choose another name for the constant", source)
        out[key] = _finite_number(value, f"constants.{key}", source)
    return out


def read_torques(raw: Any, robot: Robot, constants: Mapping[str, float], base: Path | None,
             source: str | None) -> tuple[tuple[TimeFunction, ...], dict[str, str]]:
    driven = robot.moving_joints if robot.drive else ()
    keys = tuple(f"joint{j}" for j in driven)
    check_keys(raw, (*keys, "table", "hold_ends"), "torques", source)
    if raw and not robot.drive:
        raise _error("torques", "the robot's drive is disabled (drive.enabled = false); "
                     "remove [torques] or enable the drive", source)
    hold = raw.get("hold_ends", False)
    if "hold_ends" in raw and ("table" not in raw or not isinstance(hold, bool)):
        raise _error("torques.hold_ends", "is true or false, and only beside table = ...: it "
                     "holds a table's first and last rows outside its time range", source)
    if "table" in raw:
        if len(raw) > 1 + ("hold_ends" in raw):
            raise _error("torques.table", "give either a table or expressions, not both",
                         source)
        if not isinstance(raw["table"], str):
            raise _error("torques.table", "must be the path of a CSV file", source)
        path = (base / raw["table"]) if base is not None else Path(raw["table"])
        table = load_torque_table(path, columns=len(driven), field="torques.table",
                                  source=source)
        table_texts = {"table": str(raw["table"])}
        if hold:
            table_texts["hold_ends"] = "true"
        return tuple(table.column(i) for i in range(len(driven))), table_texts
    functions: list[TimeFunction] = []
    texts: dict[str, str] = {}
    problems = Problems()
    for key in keys:
        with problems.check():
            text = raw.get(key, "0")
            if isinstance(text, (int, float)) and not isinstance(text, bool):
                text = repr(float(text))
            if not isinstance(text, str):
                raise _error(f"torques.{key}", "must be an expression of t (a string) or a "
                             "number", source)
            functions.append(parse_expression(text, field=f"torques.{key}",
                                              constants=constants, source=source))
            texts[key] = text
    problems.raise_any(source)
    return tuple(functions), texts


def check_table_covers_run(torques: tuple[TimeFunction, ...],
                           torque_text: Mapping[str, str], t_end: float) -> None:
    """A torque table must cover [0, run.t_end], unless ``hold_ends = true`` asks for its first
    and last rows to be held outside its range: a table that ends at 0.5 s for a 2 s run is
    otherwise a mistake that would pass unseen."""
    if torque_text.get("hold_ends") == "true":
        return
    for torque in torques:
        if isinstance(torque, TableColumn):
            first, last = float(torque.times[0]), float(torque.times[-1])
            if first > 0.0 or last < t_end * (1 - 1e-12):
                raise _error("torques.table", f"covers t = {first:g} to {last:g} s, but the run "
                             f"lasts from 0 to run.t_end = {t_end:g} s; extend the table, "
                             "shorten the run, or add hold_ends = true to [torques] to hold "
                             "its first and last rows", None)


def check_finite(torques: tuple[TimeFunction, ...], torque_text: Mapping[str, str],
                          robot: Robot, run: RunSettings, source: str | None) -> None:
    """Refuse a torque that is not finite at an output time (see
    :func:`jointplay.scene.definition.check_torques_finite`)."""
    import numpy as np

    t = np.arange(run.n_outputs + 1) * run.output_step
    keys = [f"joint{j}" for j in robot.moving_joints] if robot.drive else []
    for k, torque in enumerate(torques):
        values = np.asarray(torque.numpy(t), dtype=np.float64)
        bad = ~np.isfinite(values)
        if bad.any():
            i = int(np.argmax(bad))
            key = keys[k] if k < len(keys) else f"[{k}]"
            field_name = "torques.table" if "table" in torque_text else f"torques.{key}"
            text = torque_text.get(key)
            shown = f" {text!r}" if text else ""
            raise _error(field_name, f"the torque{shown} is {values[i]} at t = {t[i]:.9g} s "
                         "(an output time); every torque must be finite over [0, run.t_end]",
                         source)
