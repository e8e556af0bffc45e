"""Work-precision: error against the reference and CPU time, for every integrator across
tolerances (adaptive) or steps (fixed), and for the scene's own settings."""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.bench.measure import (
    COUNT_KEYS,
    CPU_COLUMNS,
    ERROR_KEYS,
    ERROR_LABELS,
    TIMING_KEYS,
    TIP_ERROR_COLUMNS,
    Reference,
    Timed,
    all_errors,
    reference_solution,
    run_label,
    timed_runs,
    timing_columns,
)
from jointplay.bench.report import heading, markdown_table, write_report
from jointplay.common.figures import figure, save
from jointplay.scene.definition import ADAPTIVE
from jointplay.sim.plausibility import PlausibilityWarning

if TYPE_CHECKING:
    from jointplay.scene.definition import Scene
    from jointplay.store.model import Model

DEFAULT_RTOLS: tuple[float, ...] = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9)
DEFAULT_STEPS: tuple[float, ...] = (4e-5, 2e-5, 1e-5, 5e-6, 2.5e-6)
DEFAULT_METHODS: tuple[str, ...] = ("bdf", "cvodes", "idas", "rk4", "radau")
QUICK_RTOLS: tuple[float, ...] = (1e-4, 1e-6)
QUICK_STEPS: tuple[float, ...] = (2e-5, 1e-5)
# The project's working accuracy: a run meets it with a tip position error of at most
# WORKING_TIP_ERROR (m) against the reference and an energy balance residual of at most
# WORKING_ENERGY_FRACTION of the energy that contact dissipated. The scene defaults are the
# cheapest setting found that meets it (``--atols`` shows the choice; see docs/results/accuracy.md).
WORKING_TIP_ERROR = 1e-5
WORKING_ENERGY_FRACTION = 1e-3

WP_COLUMNS: list[tuple[str, str, str]] = [
    ("method", "method", "{}"),
    ("config", "runs", "{}"),
    ("rtol", "rtol", "{:.0e}"),
    ("atol", "atol", "{:.0e}"),
    ("step", "step s", "{:.2e}"),
    ("status", "status", "{}"),
    ("implausible", "implausible (kept: warn)", "{}"),
    *CPU_COLUMNS,
    *TIP_ERROR_COLUMNS,
    ("energy_fraction", "energy res / dissipated", "{:.2%}"),
    ("working_accuracy", "working accuracy", "{}"),
    ("err_final_state", "final-state err", "{:.2e}"),
    ("steps", "steps", "{}"),
    ("rhs_evaluations", "rhs evals", "{}"),
    ("jacobian_evaluations", "Jac evals", "{}"),
    ("impacts", "impacts", "{}"),
]
WP_CSV_KEYS: list[str] = [
    "stiffness", "config", "method", "rtol", "atol", "step", "status", "implausible", "failure",
    "repeats",
    *TIMING_KEYS, *ERROR_KEYS, "energy_residual", "energy_dissipated", "energy_fraction",
    "working_accuracy", *COUNT_KEYS]


@dataclass
class WorkPrecision:
    scene: Scene
    reference: Reference
    rows: list[dict[str, Any]]
    compile_s: float
    load_s: float
    repeats: int
    facts: dict[str, str]


def sweep_configurations(scene: Scene, methods: Sequence[str], rtols: Sequence[float],
                         steps: Sequence[float], atols: Sequence[float] = ()) -> list[Scene]:
    """One scene per (method, tolerance or step), in table order: adaptive methods with
    atol = rtol, or with every rtol paired with every one of ``atols``. A loose setting may
    leave the physical domain: each is run with ``plausibility = "warn"``, so its row is
    kept and marked (``implausible``) instead of lost."""
    out = []
    for method in methods:
        if method in ADAPTIVE:
            pairs = [(r, a) for r in rtols for a in atols] if atols else [(r, r) for r in rtols]
            out += [scene.with_run(integrator=method, rtol=r, atol=a, plausibility="warn")
                    for r, a in pairs]
        else:
            out += [scene.with_run(integrator=method, step=h, plausibility="warn")
                    for h in steps]
    return out


def work_precision(scene: Scene, model: Model, *, methods: Sequence[str] = DEFAULT_METHODS,
                   rtols: Sequence[float] = DEFAULT_RTOLS,
                   steps: Sequence[float] = DEFAULT_STEPS, repeats: int = 3,
                   reference: Reference | None = None, quiet: bool = False,
                   atols: Sequence[float] = ()) -> tuple[Reference, list[dict[str, Any]]]:
    """Error against the reference and CPU time for every configuration; failures recorded.
    ``atols``: pair every adaptive rtol with each of these (default atol = rtol)."""
    from tqdm import tqdm

    reference = reference or reference_solution(scene, model)
    configs = [(c, "sweep") for c in sweep_configurations(scene, methods, rtols, steps, atols)]
    configs.append((scene, "scene settings"))
    rows: list[dict[str, Any]] = []
    with tqdm(configs, unit="run", disable=quiet, leave=False, dynamic_ncols=True) as bar, \
            warnings.catch_warnings():
        warnings.simplefilter("ignore", PlausibilityWarning)  # the rows are marked instead
        for config, kind in bar:
            bar.set_description(run_label(config))
            timed = timed_runs(config, model, repeats)
            rows.append(_row(config, kind, timed, reference))
            if timed.result is None:
                tqdm.write(f"{run_label(config)}: failed: {timed.failure}")
    return reference, rows


def _row(config: Scene, kind: str, timed: Timed, reference: Reference) -> dict[str, Any]:
    run = config.run
    adaptive = run.integrator in ADAPTIVE
    row: dict[str, Any] = {
        "stiffness": config.robot.contact.stiffness,
        "config": kind,
        "method": run.integrator,
        "rtol": run.rtol if adaptive else None,
        "atol": run.atol if adaptive else None,
        "step": None if adaptive else run.step,
        "status": "ok" if timed.result is not None else "failed",
        "failure": timed.failure or "",
        **timing_columns(timed, run.t_end),
    }
    row["implausible"] = "yes" if timed.result is not None and timed.result.implausible \
        else ""
    if timed.result is not None:
        row.update(all_errors(timed.result, reference.result))
        row.update(_energy_columns(timed.result))
        row["working_accuracy"] = "yes" if (
            row["err_position"] <= WORKING_TIP_ERROR and not row["implausible"]
            and row["energy_fraction"] <= WORKING_ENERGY_FRACTION) else "no"
    else:
        row.update(dict.fromkeys(ERROR_KEYS, math.nan))
        row.update(energy_residual=math.nan, energy_dissipated=math.nan,
                   energy_fraction=math.nan, working_accuracy="")
    return row


def _energy_columns(result: Any) -> dict[str, float]:
    """The run's own energy balance residual (J), the energy contact dissipated (J), and
    their ratio (NaN where nothing was dissipated)."""
    residual = float(np.max(np.abs(result.energy["balance"])))
    dissipated = float(result.energy["dissipated"][-1])
    return {"energy_residual": residual, "energy_dissipated": dissipated,
            "energy_fraction": residual / dissipated if dissipated > 0 else math.nan}


def cheapest_meeting_working_accuracy(rows: Sequence[dict[str, Any]],
                                      cost: str = "cpu_median_s") -> dict[str, Any] | None:
    """The row of least ``cost`` (median CPU time, or a count such as
    ``rhs_evaluations``, which other work on the machine does not change) that meets the
    working accuracy (None if none)."""
    meeting = [r for r in rows if r.get("working_accuracy") == "yes"
               and r.get("config") in ("sweep", "scene settings")]  # the scene's own model
    return min(meeting, key=lambda r: r[cost]) if meeting else None


def _plot_work_precision(wp: WorkPrecision, path: Path) -> Path:
    fig, axes = figure(2, 2, 10.0, 7.5)
    markers = {"bdf": "*", "cvodes": "o", "idas": "s", "rk4": "^", "radau": "D"}
    for ax, key in zip(axes.ravel(), ERROR_KEYS, strict=True):
        for r in wp.rows:
            if r["config"] == "scene settings" and r["status"] == "ok" and r[key] > 0:
                ax.plot(r["cpu_median_s"], r[key], "*", ms=11, color="k", zorder=5,
                        label=f"scene settings ({run_label(wp.scene)})")
        for method in dict.fromkeys(r["method"] for r in wp.rows):
            ok = [r for r in wp.rows if r["method"] == method and r["status"] == "ok"
                  and r["config"] == "sweep" and np.isfinite(r[key]) and r[key] > 0]
            if not ok:
                continue
            t = np.array([r["cpu_median_s"] for r in ok])
            e = np.array([r[key] for r in ok])
            spread = np.array([[r["cpu_median_s"] - r["cpu_min_s"] for r in ok],
                               [r["cpu_max_s"] - r["cpu_median_s"] for r in ok]])
            ax.errorbar(t, e, xerr=spread, marker=markers.get(method, "o"), ms=4,
                        capsize=2, lw=1.2, label=method)
            for r, ti, ei in zip(ok, t, e, strict=True):
                tag = f"{r['rtol']:.0e}" if r["rtol"] is not None else f"{r['step']:.1e}"
                ax.annotate(tag, (ti, ei), fontsize=6, alpha=0.6, xytext=(3, 2),
                            textcoords="offset points")
        floor = wp.reference.agreement.get(key, math.nan)
        if np.isfinite(floor) and floor > 0:
            ax.axhline(floor, color="0.4", ls="--", lw=0.9,
                       label="reference agreement")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU time per run [s] (median; bars: min-max)")
        ax.set_ylabel(ERROR_LABELS[key])
        ax.grid(True, which="both", alpha=0.25)
    axes[0, 0].legend(fontsize=8)
    fig.suptitle(f"Work-precision: {wp.scene.name}, {wp.scene.run.t_end:g} s; reference "
                 f"{wp.reference.label}", fontsize=10)
    return save(fig, path)


def write_work_precision(wp: WorkPrecision, out: Path, command: str = "") -> list[Path]:
    """work_precision.csv, .md and .png in ``out``."""
    ref = wp.reference
    default_rows = [r for r in wp.rows if r["config"] == "scene settings"]
    md = heading(f"Work-precision: {wp.scene.name}", command)
    md += [
        f"- scene: {wp.scene.source or wp.scene.name}, t_end = {wp.scene.run.t_end:g} s, "
        f"output every {wp.scene.run.output_step:g} s",
        f"- model: compile {wp.compile_s:.2f} s (gcc into an empty cache; not in the run "
        f"times), load {wp.load_s:.2f} s",
        f"- reference: {ref.label} ({ref.cpu_s:.2f} s CPU); check: {ref.check_label} "
        f"({ref.check_cpu_s:.2f} s CPU)",
        "- reference agreement (check vs reference; errors below this are not resolved): "
        + ", ".join(f"{k.removeprefix('err_').replace('_', ' ')} {v:.2e}"
                    for k, v in ref.agreement.items()),
        f"- reference signal size: max |tip velocity| "
        f"{np.max(np.linalg.norm(ref.result.tip_velocity, axis=1)):.3g} m/s, max |tip "
        f"acceleration| {np.max(np.linalg.norm(ref.result.tip_acceleration, axis=1)):.3g} "
        f"m/s², impacts {len(ref.result.impacts)}",
        f"- repeats per configuration: {wp.repeats} (CPU time: median, min, max)",
    ]
    for r in default_rows:
        if r["status"] != "ok":
            md.append(f"- the scene's own settings ({run_label(wp.scene)}): failed: "
                      f"{r['failure']}")
            continue
        md.append(f"- the scene's own settings ({run_label(wp.scene)}): "
                  f"{r['cpu_median_s']:.3f} s CPU for {wp.scene.run.t_end:g} s simulated "
                  f"({r['realtime_factor']:.3f} CPU s per simulated s; integration wall "
                  f"{r['wall_median_s']:.3f} s), position error {r['err_position']:.2e} m")
    best = cheapest_meeting_working_accuracy(wp.rows)
    md.append(f"- working accuracy (tip position error <= {WORKING_TIP_ERROR:g} m and energy "
              f"balance residual <= {WORKING_ENERGY_FRACTION:.1%} of the energy dissipated): "
              + ("met by no run" if best is None else
                 f"cheapest run meeting it: {best['method']} rtol {best['rtol']:g}, atol "
                 f"{best['atol']:g} ({best['cpu_median_s']:.3f} s CPU, tip error "
                 f"{best['err_position']:.2e} m, energy residual {best['energy_fraction']:.3%} "
                 "of the dissipated)" if best["rtol"] is not None else
                 f"cheapest run meeting it: {best['method']} step {best['step']:g} s "
                 f"({best['cpu_median_s']:.3f} s CPU)"))
    fewest = cheapest_meeting_working_accuracy(wp.rows, "rhs_evaluations")
    if fewest is not None and fewest["rtol"] is not None:
        md.append(f"- fewest right-hand sides among the runs meeting it (a cost that other work "
                  f"on the machine does not change): {fewest['method']} rtol "
                  f"{fewest['rtol']:g}, atol {fewest['atol']:g} ({fewest['rhs_evaluations']} "
                  "right-hand sides)")
    md += [*(f"- {k}: {v}" for k, v in wp.facts.items()), "",
           "Errors are maxima over the output samples against the reference; the final-state "
           "error is in scaled units (rad, rad/s; radial clearances, clearances per ms). "
           "Adaptive methods use atol = rtol unless --atols pairs them.", "",
           markdown_table(wp.rows, WP_COLUMNS), ""]
    failed = [r for r in wp.rows if r["status"] != "ok"]
    if failed:
        md += ["## Failed runs", ""]
        md += [f"- {r['method']} step {r['step']:g}: {r['failure']}" if r["step"] is not None
               else f"- {r['method']} rtol {r['rtol']:g}: {r['failure']}" for r in failed]
        md.append("")
    return write_report(out, "work_precision", wp.rows, WP_CSV_KEYS, md,
                        lambda path: _plot_work_precision(wp, path))
