"""The sweep's table: one row per case from the case files, as Parquet, written atomically."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from jointplay.sweep.metrics import ACCURACY_METRICS, metric_columns
from jointplay.sweep.records import CASES_DIR, TABLE_NAME, read_row
from jointplay.sweep.spec import Sweep, SweepError


def build_table(sweep: Sweep, out: str | Path) -> Any:
    """The sweep's table (``pyarrow.Table``) from the case files, written atomically."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    from jointplay.common.files import atomic_path

    out = Path(out)
    rows = []
    missing = []
    for case in sweep.cases:
        row = read_row(out, case.key)
        if row is None:
            missing.append(case.index)
        else:
            rows.append((case, row))
    if missing:
        raise SweepError(f"{len(missing)} case(s) of the sweep have no result in "
                         f"{out / CASES_DIR} (first: case {missing[0]}); run the sweep again "
                         "to finish them")
    clearance = list(sweep.scene.robot.clearance_joints)
    columns: dict[str, Any] = {
        "case": pa.array([c.index for c, _ in rows], pa.int64()),
        "key": pa.array([c.key for c, _ in rows], pa.string()),
        "status": pa.array([r["status"] for _, r in rows], pa.string()),
    }
    for name in sweep.parameter_names:
        columns[name] = pa.array([r["parameters"].get(name) for _, r in rows], pa.float64())
    types = {"float": pa.float64(), "int": pa.int64(), "str": pa.string()}
    for name, kind in metric_columns(clearance, sweep.scene.robot.structure().wear is not None):
        columns[name] = pa.array([r.get(name) for _, r in rows], types[kind])
    if any(r.get("tip_error_estimate") is not None for _, r in rows):  # run with verify
        for name, kind in ACCURACY_METRICS:
            columns[name] = pa.array([r.get(name) for _, r in rows], types[kind])
    for name, kind in (("ideal_reused", pa.bool_()), ("error", pa.string()),
                       ("error_type", pa.string()), ("error_stage", pa.string()),
                       ("error_time", pa.float64()), ("error_joint", pa.int64()),
                       ("worker", pa.string()), ("series", pa.string())):
        columns[name] = pa.array([r.get(name) for _, r in rows], kind)
    meta = {"jointplay.sweep": sweep.text, "jointplay.sweep_name": sweep.name,
            "jointplay.scene.definition": sweep.scene.name,
            "jointplay.swept": json.dumps(sweep.swept_names),
            "jointplay.mode": sweep.mode}
    table = pa.table(columns).replace_schema_metadata(meta)
    with atomic_path(out / TABLE_NAME) as tmp:
        pq.write_table(table, tmp)
    return table
