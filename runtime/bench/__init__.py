"""What accuracy costs: work-precision sweeps, a fidelity ladder, and scaling with link count.

    jointplay bench work-precision [SCENE.toml] --out DIR [--quick] [--t-end T] [--repeats N]
    jointplay bench fidelity [SCENE.toml] --out DIR [--surrogate MODEL_DIR]
    jointplay bench scaling --out DIR [--links 1-12] [--structures clearance,ideal]

Errors are measured against a reference solution of the same scene (CVODES at a tight
tolerance), whose own accuracy is checked by agreement with a second method (IDAS at the same
tolerance, or Radau IIA at a tiny step): errors below that agreement mean nothing, and every
report states it. Error measures, each the maximum over the output samples:

* end-effector position, velocity and acceleration: max_t |tip(t) - tip_ref(t)| (Euclidean
  norm in the plane; m, m/s, m/s^2);
* final state: max over the state's entries of |x(T) - x_ref(T)| in the integrators' scaled
  units (rad and rad/s for angles; the joint's radial clearance c for eccentricities, and
  c per millisecond for their rates), so angles and eccentricities count alike.

Times are CPU seconds of the whole ``simulate`` call (``time.process_time``: other processes
on a shared machine do not inflate it), the median of repeated runs with min and max; the
integration's wall time is kept beside it. Compiling the model is timed separately (gcc into
an empty cache), since a cached model costs nothing to load.

Every table is written as CSV and Markdown, every figure as PNG, all atomically.

The rooms of this package: ``measure`` (errors, timed runs, the reference), ``work_precision``,
``fidelity`` and ``scaling`` (one study each), ``child`` (a measurement in a fresh process),
``report`` (tables and machine facts). The ``jointplay bench`` command is
``jointplay.cli.bench``.
"""

from __future__ import annotations

import warnings
from typing import Any

from jointplay.bench.child import (
    ChildFailed,
    ChildLimits,
    ChildOutcome,
    ChildProgress,
    json_from_child,
    report_stage,
    watch_child,
)
from jointplay.bench.fidelity import (
    FID_COLUMNS,
    FID_CSV_KEYS,
    SURROGATE_ENTRY,
    SURROGATE_MODULE,
    Fidelity,
    fidelity,
    surrogate_row,
    without_friction,
    write_fidelity,
)
from jointplay.bench.measure import (
    CHECK_METHODS,
    COUNT_KEYS,
    CPU_COLUMNS,
    DEFAULT_CHECK_STEP,
    ERROR_KEYS,
    ERROR_LABELS,
    QUICK_T_END,
    REFERENCE_RTOL,
    TIMING_KEYS,
    TIP_ERROR_COLUMNS,
    TIP_ERRORS,
    Reference,
    Timed,
    all_errors,
    cold_compile_seconds,
    final_state_error,
    reference_solution,
    run_counts,
    run_label,
    state_scale,
    timed_runs,
    timing_columns,
    tip_errors,
)
from jointplay.bench.report import (
    cpu_name,
    heading,
    machine_facts,
    markdown_table,
    to_csv,
    write_report,
)
from jointplay.bench.scaling import (
    SCALING_COLUMNS,
    SCALING_CSV_KEYS,
    SCALING_SIM_TIME,
    SCALING_TORQUE,
    STRUCTURES,
    run_scaling_case,
    scaling,
    scaling_case,
    scaling_scene,
    write_scaling,
)
from jointplay.bench.work_precision import (
    DEFAULT_METHODS,
    DEFAULT_RTOLS,
    DEFAULT_STEPS,
    QUICK_RTOLS,
    QUICK_STEPS,
    WP_COLUMNS,
    WP_CSV_KEYS,
    WorkPrecision,
    sweep_configurations,
    work_precision,
    write_work_precision,
)

# The command and its argument helpers moved to jointplay.cli; these names still resolve
# there, with a warning.
_MOVED_TO_CLI = {"cmd_fidelity": "bench", "cmd_scaling": "bench", "cmd_work_precision": "bench",
                 "register": "bench", "parse_links": "args", "prepare_out_dir": "args"}


def __getattr__(name: str) -> Any:
    if name in _MOVED_TO_CLI:
        import importlib

        where = f"jointplay.cli.{_MOVED_TO_CLI[name]}"
        warnings.warn(f"jointplay.bench.{name} is now {where}.{name}", DeprecationWarning,
                      stacklevel=2)
        return getattr(importlib.import_module(where), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "CHECK_METHODS", "COUNT_KEYS", "CPU_COLUMNS", "DEFAULT_CHECK_STEP", "DEFAULT_METHODS",
    "DEFAULT_RTOLS", "DEFAULT_STEPS", "ERROR_KEYS", "ERROR_LABELS", "FID_COLUMNS",
    "FID_CSV_KEYS", "QUICK_RTOLS", "QUICK_STEPS", "QUICK_T_END", "REFERENCE_RTOL",
    "SCALING_COLUMNS", "SCALING_CSV_KEYS", "SCALING_SIM_TIME", "SCALING_TORQUE", "STRUCTURES",
    "SURROGATE_ENTRY", "SURROGATE_MODULE", "TIMING_KEYS", "TIP_ERRORS", "TIP_ERROR_COLUMNS",
    "WP_COLUMNS", "WP_CSV_KEYS", "ChildFailed", "ChildLimits", "ChildOutcome", "ChildProgress",
    "Fidelity", "Reference", "Timed", "WorkPrecision", "all_errors", "cold_compile_seconds",
    "cpu_name", "fidelity", "final_state_error", "heading", "json_from_child", "machine_facts",
    "markdown_table", "reference_solution", "report_stage", "run_counts", "run_label",
    "run_scaling_case", "scaling", "scaling_case", "scaling_scene", "state_scale",
    "surrogate_row", "sweep_configurations", "timed_runs", "timing_columns", "tip_errors",
    "to_csv", "watch_child", "without_friction", "work_precision", "write_fidelity",
    "write_report", "write_scaling", "write_work_precision",
]
