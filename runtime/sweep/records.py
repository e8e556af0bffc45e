"""A sweep's files in its output folder: one durable row per finished case, written atomically
(the row file marks the case done), read back only when whole and well formed, and the
manifest of the sweep that wrote them."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

from jointplay.common.files import atomic_write_text
from jointplay.sweep.case import STAGE_SIMULATION, CaseOutcome
from jointplay.sweep.metrics import metric_columns
from jointplay.sweep.spec import Sweep

TABLE_NAME = "sweep.parquet"
MANIFEST_NAME = "sweep.json"
CASES_DIR = "cases"
SERIES_DIR = "series"
PLOTS_DIR = "plots"


def _case_path(out: Path, key: str) -> Path:
    return out / CASES_DIR / f"{key}.json"


def read_row(out: Path, key: str) -> dict[str, Any] | None:
    """The case's row, or None when it has none or one that is damaged or of another shape
    (that case then runs again instead of breaking the table)."""
    try:
        row = json.loads(_case_path(out, key).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return row if _valid_row(row, key) else None


_INT_METRICS = frozenset(name for name, kind in metric_columns(()) if kind == "int")
_TEXT_FIELDS = ("error", "error_type", "error_stage", "worker", "series", "peak_note",
                "implausible")


def _is_number(value: Any, integer: bool = False) -> bool:
    if isinstance(value, bool):
        return False
    return isinstance(value, int) if integer else isinstance(value, (int, float))


def _valid_row(row: Any, key: str) -> bool:
    """A row as :func:`run_case` writes it: the types :func:`build_table` needs, and finite
    metrics when its status is ok."""
    if not isinstance(row, dict) or row.get("key") != key or \
            row.get("status") not in ("ok", "failed"):
        return False
    params = row.get("parameters")
    if not isinstance(params, dict) or not all(_is_number(v) for v in params.values()):
        return False
    if any(row.get(name) is not None and not isinstance(row[name], str)
           for name in _TEXT_FIELDS):
        return False
    if row.get("ideal_reused") is not None and not isinstance(row["ideal_reused"], bool):
        return False
    if row.get("error_time") is not None and not _is_number(row["error_time"]):
        return False
    if row.get("error_joint") is not None and not _is_number(row["error_joint"], True):
        return False
    fixed = {"key", "status", "parameters", "ideal_reused", "error_time", "error_joint",
             *_TEXT_FIELDS}
    for name, value in row.items():
        if name in fixed or value is None:
            continue
        if not _is_number(value, name in _INT_METRICS):
            return False
        if row["status"] == "ok" and not math.isfinite(value):
            return False
    return True


def is_finished(row: dict[str, Any] | None, out: Path, *, series: bool,
                 retry_failed: bool, verify: bool = False) -> bool:
    if row is None:
        return False
    if row.get("status") == "ok":
        if verify and row.get("tip_error_estimate") is None:  # finished without the check
            return False
        return not series or (row.get("series") is not None
                              and (out / row["series"]).is_file())
    return row.get("error_stage") == STAGE_SIMULATION and not retry_failed


def record(out: Path, outcome: CaseOutcome) -> dict[str, Any]:
    """Write the case's series (if any), then its row: the row file marks the case done."""
    row = dict(outcome.row)
    if outcome.result is not None:
        from jointplay.results.write import write_hdf5

        rel = f"{SERIES_DIR}/{outcome.key}.h5"
        write_hdf5(outcome.result, out / rel)
        row["series"] = rel
    atomic_write_text(_case_path(out, outcome.key), json.dumps(row, sort_keys=True))
    return row


def write_manifest(sweep: Sweep, out: Path) -> None:
    doc = {"name": sweep.name, "source": sweep.source, "scene": sweep.scene.name,
           "mode": sweep.mode, "swept": sweep.swept_names, "sweep_file": sweep.text,
           "cases": [{"case": c.index, "key": c.key, "parameters": {**c.swept, **c.parameters}}
                     for c in sweep.cases]}
    atomic_write_text(out / MANIFEST_NAME, json.dumps(doc, indent=1))
