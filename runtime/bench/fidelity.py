"""The fidelity ladder: each modelling level (ideal joints, clearance without friction, the
full model, a trained surrogate) scored against the full model, with what it costs."""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.bench.measure import (
    COUNT_KEYS,
    CPU_COLUMNS,
    ERROR_KEYS,
    REFERENCE_RTOL,
    TIMING_KEYS,
    TIP_ERROR_COLUMNS,
    TIP_ERRORS,
    cold_compile_seconds,
    run_label,
    timed_runs,
    timing_columns,
    tip_errors,
)
from jointplay.bench.report import heading, machine_facts, markdown_table, write_report
from jointplay.common.errors import SimulationError
from jointplay.common.figures import figure, save

if TYPE_CHECKING:
    from jointplay.results.records import SimulationResult
    from jointplay.scene.definition import Scene

SURROGATE_MODULE = "jointplay.neural.model.narx"
SURROGATE_ENTRY = "load_surrogate"

FID_COLUMNS: list[tuple[str, str, str]] = [
    ("rung", "model", "{}"),
    ("run", "integration", "{}"),
    ("status", "status", "{}"),
    *CPU_COLUMNS,
    *TIP_ERROR_COLUMNS,
    ("compile_s", "gcc s", "{:.2f}"),
    ("impacts", "impacts", "{}"),
    ("note", "note", "{}"),
]
FID_CSV_KEYS: list[str] = [
    "rung", "model", "run", "tolerance", "status", "note", "repeats", *TIMING_KEYS,
    *ERROR_KEYS[:3], "compile_s", *COUNT_KEYS]


@dataclass
class Fidelity:
    scene: Scene
    reference_label: str
    rows: list[dict[str, Any]]
    facts: dict[str, str]


def without_friction(scene: Scene) -> Scene:
    """The scene's robot with clearance but no friction (a separately compiled model)."""
    robot = scene.robot
    return scene.with_robot(replace(robot, friction=replace(robot.friction, law="none"),
                                    name=f"{robot.name}_nofriction"))


def fidelity(scene: Scene, *, run_scene: Scene | None = None,
             reference_rtol: float = REFERENCE_RTOL, repeats: int = 3,
             surrogate: Path | None = None, quiet: bool = False,
             effects: bool = False, stiffness: Sequence[str] = ()) -> Fidelity:
    """Each modelling level's end-effector error against the full model at ``reference_rtol``
    and its cost, at the scene's own run settings (``run_scene``) and at the reference
    tolerance (which leaves the modelling error alone). Each law in ``stiffness`` other than
    the scene's adds a rung: the full model under that contact stiffness law."""
    from tqdm import tqdm

    from jointplay.store.lookup import model_for

    run_scene = run_scene or scene
    rungs = _rungs(scene, stiffness)
    tight = {"integrator": "cvodes", "rtol": reference_rtol, "atol": reference_rtol}
    models = {name: model_for(rscene.robot) for name, rscene, _ in rungs}
    full_name = rungs[-1][0]
    ref_timed = timed_runs(scene.with_run(**tight), models[full_name], 1)
    if ref_timed.result is None:
        raise SimulationError(0.0, "the full model failed at the reference tolerance "
                                   f"(rtol {reference_rtol:g}): {ref_timed.failure}")
    reference = ref_timed.result
    rows: list[dict[str, Any]] = []
    with tqdm(total=2 * len(rungs), unit="run", disable=quiet, leave=False) as bar:
        for name, rscene, note in rungs:
            bar.set_description(name)
            model = models[name]
            compile_s = cold_compile_seconds(model)
            for label, settings in (("scene", _run_settings(run_scene)), ("reference", tight)):
                cfg = rscene.with_run(**settings)
                if name == full_name and label == "reference":
                    timed, row_note = ref_timed, "the reference (errors 0 by definition)"
                else:
                    timed = timed_runs(cfg, model, repeats if label == "scene" else 1)
                    row_note = note or (timed.failure or "")
                row = {"rung": name, "model": model.name, "run": run_label(cfg),
                       "tolerance": label, "status": "ok" if timed.result else "failed",
                       "note": row_note, "compile_s": compile_s,
                       **timing_columns(timed, cfg.run.t_end)}
                row.update(tip_errors(timed.result, reference) if timed.result is not None
                           else {k: math.nan for k in ERROR_KEYS[:3]})
                rows.append(row)
                bar.update(1)
    if effects:  # lubrication and wear (see jointplay.bench.effects)
        from jointplay.bench.effects import fidelity_rows

        rows += fidelity_rows(scene, run_scene, reference, repeats)
    rows.append(surrogate_row(run_scene, surrogate, reference, repeats))
    return Fidelity(scene=run_scene, reference_label=run_label(scene.with_run(**tight)),
                    rows=rows, facts=machine_facts())


def _rungs(scene: Scene, stiffness: Sequence[str] = ()) -> list[tuple[str, Scene, str]]:
    """(name, scene, note) of each modelling level, the full model last."""
    from jointplay.robot.contact_laws import with_stiffness
    from jointplay.scene.definition import ideal_counterpart

    laws = [(f"clearance + friction, {law} stiffness",
             scene.with_robot(with_stiffness(scene.robot, law)), "")
            for law in stiffness if law != scene.robot.contact.stiffness]
    return [
        ("ideal joints", scene.with_robot(ideal_counterpart(scene.robot)), ""),
        ("clearance, no friction", without_friction(scene),
         "same as the full model: the scene has no friction"
         if scene.robot.friction.law == "none" else ""),
        *laws,
        ("clearance + friction (full)", scene, ""),
    ]


def _run_settings(scene: Scene) -> dict[str, Any]:
    run = scene.run
    return {"integrator": run.integrator, "rtol": run.rtol, "atol": run.atol, "step": run.step}


def surrogate_row(scene: Scene, model_dir: Path | None, reference: SimulationResult,
                  repeats: int = 3) -> dict[str, Any]:
    """The neural-surrogate rung: a hook, skipped with a note unless a trained model is given.

    The surrogate module (``jointplay.neural.model.narx``) is expected to provide
    ``load_surrogate(model_dir)`` returning an object whose ``rollout(scene)`` gives the
    end effector over the scene's output times (attributes ``t``, ``tip_position``,
    ``tip_velocity``, ``tip_acceleration``, as in a SimulationResult).
    """
    import importlib

    row: dict[str, Any] = {"rung": "neural surrogate", "model": "", "run": "",
                           "tolerance": "", "status": "skipped", "repeats": 0,
                           **{k: math.nan for k in ERROR_KEYS[:3]}}
    if model_dir is None:
        row["note"] = "no trained model given (--surrogate MODEL_DIR)"
        return row
    try:
        module = importlib.import_module(SURROGATE_MODULE)
    except ImportError as err:
        row["note"] = (f"--surrogate was given, but the surrogate module {SURROGATE_MODULE} "
                       f"is not importable ({err})")
        return row
    loader = getattr(module, SURROGATE_ENTRY, None)
    if loader is None:
        row["note"] = (f"--surrogate was given, but {SURROGATE_MODULE} provides no "
                       f"{SURROGATE_ENTRY}(MODEL_DIR), the hook this row calls")
        return row
    surrogate = loader(model_dir)
    cpu = []
    prediction: Any = None
    for _ in range(max(1, repeats)):
        c0 = time.process_time()
        prediction = surrogate.rollout(scene)
        cpu.append(time.process_time() - c0)
    row.update(model=str(model_dir), run="rollout", status="ok", note="", repeats=len(cpu),
               cpu_median_s=statistics.median(cpu), cpu_min_s=min(cpu), cpu_max_s=max(cpu),
               realtime_factor=statistics.median(cpu) / scene.run.t_end,
               **tip_errors(prediction, reference))
    return row


def _plot_fidelity(fid: Fidelity, path: Path) -> Path:
    fig, axes = figure(1, 3, 13.0, 4.2)
    for ax, (key, _, unit) in zip(axes[0], TIP_ERRORS, strict=True):
        for i, row in enumerate(r for r in fid.rows if r["status"] == "ok"):
            err = row[f"err_{key}"]
            if not (np.isfinite(err) and err > 0):
                continue
            marker = "o" if row["tolerance"] == "scene" else "s"
            ax.scatter(row["cpu_median_s"], err, marker=marker, color=f"C{i // 2}",
                       label=f"{row['rung']} ({row['run']})", s=28)
            ax.errorbar(row["cpu_median_s"], err,
                        xerr=[[row["cpu_median_s"] - row["cpu_min_s"]],
                              [row["cpu_max_s"] - row["cpu_median_s"]]],
                        color=f"C{i // 2}", capsize=2, lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU time per run [s]")
        ax.set_ylabel(f"end-effector {key} error [{unit}]")
        ax.grid(True, which="both", alpha=0.25)
    handles, labels = axes[0, 0].get_legend_handles_labels()
    if handles:
        fig.legend(handles, labels, loc="outside lower center", ncol=2, fontsize=7)
    fig.suptitle(f"Fidelity ladder: {fid.scene.name}, {fid.scene.run.t_end:g} s; errors "
                 f"against the full model at {fid.reference_label}", fontsize=10)
    return save(fig, path)


def write_fidelity(fid: Fidelity, out: Path, command: str = "") -> list[Path]:
    md = heading(f"Fidelity ladder: {fid.scene.name}", command)
    md += [f"- scene: {fid.scene.source or fid.scene.name}, t_end = {fid.scene.run.t_end:g} s",
           f"- errors: max over the output samples of the end-effector error norm against "
           f"the full model at {fid.reference_label}",
           "- each model runs at the scene's own settings (what it costs) and at the "
           "reference tolerance (its modelling error alone)",
           *(f"- {k}: {v}" for k, v in fid.facts.items()), "",
           markdown_table(fid.rows, FID_COLUMNS), ""]
    return write_report(out, "fidelity", fid.rows, FID_CSV_KEYS, md,
                        lambda path: _plot_fidelity(fid, path))
