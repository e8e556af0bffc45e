"""Parameter sweeps: one compiled model, many parameter vectors, run on a Dask cluster.

A sweep file (TOML, data only, never executed) names a base scene and the numbers to vary;
see ``docs/how-to/sweep.md`` for the format. Everything is validated before any work starts, and a
sweep never changes the model's structure, so the model is compiled once (here, in the parent
process) and every worker loads it from the compile cache.

Faults lose nothing. Each finished case is written at once, atomically, as
``OUT/cases/<key>.json``, where the key hashes the case's full parameter vector, the base
scene (structure, torques, initial state) and the run settings. A restarted sweep skips every
case whose file exists, so rows are never computed twice nor lost; the Parquet table
``OUT/sweep.parquet`` is rebuilt from those files, atomically, at the end of every run. Cases
that fail in the simulation are recorded (status ``failed`` with the message) and the sweep
goes on; tasks on a worker that dies are rerun by Dask (and ``retries`` covers exceptions
outside the simulation).

The rooms of this package: ``spec`` (the sweep file and its cases), ``axes`` (swept names and
their values), ``case`` (one case on a worker), ``metrics`` (a case's summary numbers),
``records`` (durable per-case files), ``table`` and ``plots`` (what a person reads), ``run``
(the cluster and the loop). The ``jointplay sweep`` command is ``jointplay.cli.sweep``.
"""

from __future__ import annotations

import warnings
from typing import Any

from jointplay.sweep.axes import MAX_CASES, Axis
from jointplay.sweep.case import CaseOutcome, run_case
from jointplay.sweep.metrics import CONTACT_METRICS, contact_metrics, metric_columns
from jointplay.sweep.plots import plot_sweep
from jointplay.sweep.records import (
    CASES_DIR,
    MANIFEST_NAME,
    PLOTS_DIR,
    SERIES_DIR,
    TABLE_NAME,
)
from jointplay.sweep.run import SweepResult, default_workers, run_sweep
from jointplay.sweep.spec import (
    KEY_VERSION,
    MODES,
    Case,
    Sweep,
    SweepError,
    case_key,
    load_sweep,
    sweep_from_dict,
)
from jointplay.sweep.table import build_table

# The command moved to jointplay.cli.sweep; these names still resolve, with a warning.
_MOVED_TO_CLI = ("cmd_sweep", "register")


def __getattr__(name: str) -> Any:
    if name in _MOVED_TO_CLI:
        from jointplay.cli import sweep as command

        warnings.warn(f"jointplay.sweep.{name} is now jointplay.cli.sweep.{name}",
                      DeprecationWarning, stacklevel=2)
        return getattr(command, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["CASES_DIR", "CONTACT_METRICS", "KEY_VERSION", "MANIFEST_NAME", "MAX_CASES", "MODES",
           "PLOTS_DIR", "SERIES_DIR", "TABLE_NAME", "Axis", "Case", "CaseOutcome", "Sweep",
           "SweepError", "SweepResult", "build_table", "case_key", "contact_metrics",
           "default_workers", "load_sweep", "metric_columns", "plot_sweep", "run_case",
           "run_sweep", "sweep_from_dict"]
