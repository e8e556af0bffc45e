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
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import os
import platform
import shlex
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.errors import DescriptionError, SimulationError
from jointplay.files import atomic_path, atomic_write_text
from jointplay.scene import ADAPTIVE

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from jointplay.model import Model
    from jointplay.results import SimulationResult
    from jointplay.scene import Scene

DEFAULT_RTOLS: tuple[float, ...] = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9)
DEFAULT_STEPS: tuple[float, ...] = (4e-5, 2e-5, 1e-5, 5e-6, 2.5e-6)
DEFAULT_METHODS: tuple[str, ...] = ("bdf", "cvodes", "idas", "rk4", "radau")
QUICK_T_END = 0.01
QUICK_RTOLS: tuple[float, ...] = (1e-4, 1e-6)
QUICK_STEPS: tuple[float, ...] = (2e-5, 1e-5)
REFERENCE_RTOL = 1e-10
CHECK_METHODS: tuple[str, ...] = ("idas", "radau")
DEFAULT_CHECK_STEP = 1e-6
SCALING_SIM_TIME = 0.2
SCALING_TORQUE = "1.0*sin(2*pi*t)"  # N m on every moving joint of the scaling chains
STRUCTURES: tuple[str, ...] = ("clearance", "ideal")
SURROGATE_MODULE = "jointplay.narx"
SURROGATE_ENTRY = "load_surrogate"

# (key, Markdown header, format) of the tip error measures.
TIP_ERRORS: tuple[tuple[str, str, str], ...] = (
    ("position", "tip_position", "m"),
    ("velocity", "tip_velocity", "m/s"),
    ("acceleration", "tip_acceleration", "m/s^2"),
)
ERROR_KEYS: tuple[str, ...] = ("err_position", "err_velocity", "err_acceleration",
                               "err_final_state")
ERROR_LABELS: dict[str, str] = {
    "err_position": "end-effector position error [m]",
    "err_velocity": "end-effector velocity error [m/s]",
    "err_acceleration": "end-effector acceleration error [m/s²]",
    "err_final_state": "final-state error [scaled: rad, clearances]",
}


# ---- measuring ----------------------------------------------------------------------------


def tip_errors(result: SimulationResult, reference: SimulationResult) -> dict[str, float]:
    """Max over the output samples of the end-effector error norms, against ``reference``."""
    _check_same_grid(result, reference)
    return {f"err_{key}": float(np.max(np.linalg.norm(
        getattr(result, attr) - getattr(reference, attr), axis=1)))
        for key, attr, _ in TIP_ERRORS}


def state_scale(result: SimulationResult) -> np.ndarray:
    """Scale of each state entry: 1 for angles, c for eccentricities, c / 1 ms for their rates."""
    from jointplay.simulation import RATE_SCALE_TIME

    n = len(result.coordinate_names)
    scale = np.ones(2 * n)
    for i, name in enumerate(result.coordinate_names):
        if name.startswith(("ex", "ey")):
            c = float(result.radial_clearance[result.clearance_joints.index(int(name[2:]))])
            scale[i], scale[n + i] = c, c / RATE_SCALE_TIME
    return scale


def final_state_error(result: SimulationResult, reference: SimulationResult) -> float:
    """max |x(T) - x_ref(T)| in scaled units (see the module docstring)."""
    if result.coordinate_names != reference.coordinate_names:
        return math.nan  # a different model (e.g. ideal joints): states do not compare
    x = np.r_[result.q[-1], result.u[-1]]
    x_ref = np.r_[reference.q[-1], reference.u[-1]]
    return float(np.max(np.abs(x - x_ref) / state_scale(reference)))


def all_errors(result: SimulationResult, reference: SimulationResult) -> dict[str, float]:
    return {**tip_errors(result, reference),
            "err_final_state": final_state_error(result, reference)}


def _check_same_grid(result: SimulationResult, reference: SimulationResult) -> None:
    if result.t.shape != reference.t.shape or not np.allclose(result.t, reference.t,
                                                              rtol=0, atol=1e-12):
        raise ValueError("the result and the reference have different output times "
                         f"({result.t.size} vs {reference.t.size} samples)")


@dataclass
class Timed:
    """Repeated runs of one configuration: the first result, and every run's times."""

    result: SimulationResult | None
    cpu_s: list[float] = field(default_factory=list)
    wall_s: list[float] = field(default_factory=list)
    failure: str | None = None

    def spread(self, key: str = "cpu") -> dict[str, float]:
        values = self.cpu_s if key == "cpu" else self.wall_s
        if not values:
            return {f"{key}_median_s": math.nan, f"{key}_min_s": math.nan,
                    f"{key}_max_s": math.nan}
        return {f"{key}_median_s": statistics.median(values), f"{key}_min_s": min(values),
                f"{key}_max_s": max(values)}


def timed_runs(scene: Scene, model: Model, repeats: int,
               parameters: dict[str, float] | None = None) -> Timed:
    """Simulate ``repeats`` times; a :class:`SimulationError` ends it and is recorded."""
    from jointplay.simulation import simulate

    timed = Timed(result=None)
    for _ in range(max(1, repeats)):
        c0 = time.process_time()
        try:
            result = simulate(scene, model=model, parameters=parameters, quiet=True)
        except SimulationError as err:
            return Timed(result=None, failure=str(err))
        timed.cpu_s.append(time.process_time() - c0)
        timed.wall_s.append(float(result.stats["wall_time_s"]))
        if timed.result is None:
            timed.result = result
    return timed


def run_counts(result: SimulationResult | None) -> dict[str, Any]:
    keys = ("steps", "rhs_evaluations", "jacobian_evaluations", "events", "impacts")
    if result is None:
        return dict.fromkeys(keys)
    return {k: int(result.stats.get(k, 0)) for k in keys}


def run_label(scene: Scene) -> str:
    run = scene.run
    if run.integrator in ADAPTIVE:
        return f"{run.integrator} rtol={run.rtol:g} atol={run.atol:g}"
    return f"{run.integrator} step={run.step:g}"


def cold_compile_seconds(model: Model) -> float:
    """gcc time of the model's C into an empty cache (the cached library costs nothing)."""
    from jointplay.build import DEFAULT_CFLAGS, compile_source

    source = (model.folder / "model.c").read_text(encoding="utf-8")
    with tempfile.TemporaryDirectory(prefix="jointplay-bench-") as tmp:
        _, seconds = compile_source(source, DEFAULT_CFLAGS, cache=Path(tmp))
    return seconds


@dataclass
class Reference:
    """The reference solution and how far a second method agrees with it."""

    result: SimulationResult
    label: str
    cpu_s: float
    check_label: str
    check_cpu_s: float
    agreement: dict[str, float]


def reference_solution(scene: Scene, model: Model, *, rtol: float = REFERENCE_RTOL,
                       check: str = "idas", check_step: float = DEFAULT_CHECK_STEP
                       ) -> Reference:
    """CVODES at ``rtol`` (atol tied to it), checked against IDAS at the same tolerance or
    Radau IIA at ``check_step``. Raises :class:`SimulationError` if either run fails."""
    ref_scene = scene.with_run(integrator="cvodes", rtol=rtol, atol=rtol)
    if check == "idas":
        check_scene = scene.with_run(integrator="idas", rtol=rtol, atol=rtol)
    else:
        check_scene = scene.with_run(integrator="radau", step=check_step)
    ref = timed_runs(ref_scene, model, 1)
    if ref.result is None:
        raise SimulationError(0.0, f"the reference run ({run_label(ref_scene)}) failed: "
                                   f"{ref.failure}")
    second = timed_runs(check_scene, model, 1)
    if second.result is None:
        raise SimulationError(0.0, f"the reference check ({run_label(check_scene)}) failed: "
                                   f"{second.failure}")
    return Reference(result=ref.result, label=run_label(ref_scene), cpu_s=ref.cpu_s[0],
                     check_label=run_label(check_scene), check_cpu_s=second.cpu_s[0],
                     agreement=all_errors(second.result, ref.result))


def per_call_seconds(fn: Callable[[], Any], repeats: int = 7, batch_s: float = 0.05) -> float:
    """Median seconds per call over ``repeats`` batches sized to take about ``batch_s``
    (batch size calibrated first; the garbage collector off while timing)."""
    import gc

    fn()
    number = 1
    while True:
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        elapsed = time.perf_counter() - t0
        if elapsed >= batch_s / 4 or number >= 1 << 22:
            break
        number *= 4
    number = max(1, int(number * batch_s / max(elapsed, 1e-9)))
    samples = []
    enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(repeats):
            t0 = time.perf_counter()
            for _ in range(number):
                fn()
            samples.append((time.perf_counter() - t0) / number)
    finally:
        if enabled:
            gc.enable()
    return statistics.median(samples)


# ---- work-precision -----------------------------------------------------------------------

WP_COLUMNS: list[tuple[str, str, str]] = [
    ("method", "method", "{}"),
    ("config", "runs", "{}"),
    ("rtol", "rtol", "{:.0e}"),
    ("atol", "atol", "{:.0e}"),
    ("step", "step s", "{:.2e}"),
    ("status", "status", "{}"),
    ("cpu_median_s", "CPU s (median)", "{:.3f}"),
    ("cpu_min_s", "min", "{:.3f}"),
    ("cpu_max_s", "max", "{:.3f}"),
    ("realtime_factor", "CPU s / sim s", "{:.3f}"),
    ("err_position", "pos err m", "{:.2e}"),
    ("err_velocity", "vel err m/s", "{:.2e}"),
    ("err_acceleration", "acc err m/s²", "{:.2e}"),
    ("err_final_state", "final-state err", "{:.2e}"),
    ("steps", "steps", "{}"),
    ("rhs_evaluations", "rhs evals", "{}"),
    ("jacobian_evaluations", "Jac evals", "{}"),
    ("impacts", "impacts", "{}"),
]
WP_CSV_KEYS: list[str] = [
    "stiffness", "config", "method", "rtol", "atol", "step", "status", "failure", "repeats",
    "cpu_median_s", "cpu_min_s", "cpu_max_s", "wall_median_s", "wall_min_s", "wall_max_s",
    "realtime_factor", *ERROR_KEYS, "steps", "rhs_evaluations", "jacobian_evaluations",
    "events", "impacts"]


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
                         steps: Sequence[float]) -> list[Scene]:
    """One scene per (method, tolerance or step), in table order."""
    out = []
    for method in methods:
        if method in ADAPTIVE:
            out += [scene.with_run(integrator=method, rtol=r, atol=r) for r in rtols]
        else:
            out += [scene.with_run(integrator=method, step=h) for h in steps]
    return out


def work_precision(scene: Scene, model: Model, *, methods: Sequence[str] = DEFAULT_METHODS,
                   rtols: Sequence[float] = DEFAULT_RTOLS,
                   steps: Sequence[float] = DEFAULT_STEPS, repeats: int = 3,
                   reference: Reference | None = None, quiet: bool = False
                   ) -> tuple[Reference, list[dict[str, Any]]]:
    """Error against the reference and CPU time for every configuration; failures recorded."""
    from tqdm import tqdm

    reference = reference or reference_solution(scene, model)
    configs = [(c, "sweep") for c in sweep_configurations(scene, methods, rtols, steps)]
    configs.append((scene, "scene settings"))
    rows: list[dict[str, Any]] = []
    with tqdm(configs, unit="run", disable=quiet, leave=False, dynamic_ncols=True) as bar:
        for config, kind in bar:
            bar.set_description(run_label(config))
            timed = timed_runs(config, model, repeats)
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
                "repeats": len(timed.cpu_s),
                **timed.spread("cpu"), **timed.spread("wall"),
                **run_counts(timed.result),
            }
            row["realtime_factor"] = row["cpu_median_s"] / run.t_end
            if timed.result is not None:
                row.update(all_errors(timed.result, reference.result))
            else:
                row.update(dict.fromkeys(ERROR_KEYS, math.nan))
                tqdm.write(f"{run_label(config)}: failed: {timed.failure}")
            rows.append(row)
    return reference, rows


def _plot_work_precision(wp: WorkPrecision, path: Path) -> Path:
    fig, axes = _figure(2, 2, 10.0, 7.5)
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
    return _save(fig, path)


def write_work_precision(wp: WorkPrecision, out: Path, command: str = "") -> list[Path]:
    """work_precision.csv, .md and .png in ``out``."""
    ref = wp.reference
    default_rows = [r for r in wp.rows if r["config"] == "scene settings"]
    md = [f"# Work-precision: {wp.scene.name}", ""]
    if command:
        md += [f"Command: `{command}`", ""]
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
    md += [*(f"- {k}: {v}" for k, v in wp.facts.items()), "",
           "Errors are maxima over the output samples against the reference; the final-state "
           "error is in scaled units (rad, rad/s; radial clearances, clearances per ms). "
           "Adaptive methods use atol = rtol.", "",
           markdown_table(wp.rows, WP_COLUMNS), ""]
    failed = [r for r in wp.rows if r["status"] != "ok"]
    if failed:
        md += ["## Failed runs", ""]
        md += [f"- {r['method']} step {r['step']:g}: {r['failure']}" if r["step"] is not None
               else f"- {r['method']} rtol {r['rtol']:g}: {r['failure']}" for r in failed]
        md.append("")
    paths = [out / "work_precision.csv", out / "work_precision.md",
             out / "work_precision.png"]
    atomic_write_text(paths[0], to_csv(wp.rows, WP_CSV_KEYS))
    atomic_write_text(paths[1], "\n".join(md))
    _plot_work_precision(wp, paths[2])
    return paths


# ---- fidelity ladder ----------------------------------------------------------------------

FID_COLUMNS: list[tuple[str, str, str]] = [
    ("rung", "model", "{}"),
    ("run", "integration", "{}"),
    ("status", "status", "{}"),
    ("cpu_median_s", "CPU s (median)", "{:.3f}"),
    ("cpu_min_s", "min", "{:.3f}"),
    ("cpu_max_s", "max", "{:.3f}"),
    ("realtime_factor", "CPU s / sim s", "{:.3f}"),
    ("err_position", "pos err m", "{:.2e}"),
    ("err_velocity", "vel err m/s", "{:.2e}"),
    ("err_acceleration", "acc err m/s²", "{:.2e}"),
    ("compile_s", "gcc s", "{:.2f}"),
    ("impacts", "impacts", "{}"),
    ("note", "note", "{}"),
]
FID_CSV_KEYS: list[str] = [
    "rung", "model", "run", "tolerance", "status", "note", "repeats", "cpu_median_s",
    "cpu_min_s", "cpu_max_s", "wall_median_s", "wall_min_s", "wall_max_s", "realtime_factor",
    "err_position", "err_velocity", "err_acceleration", "compile_s", "steps",
    "rhs_evaluations", "jacobian_evaluations", "events", "impacts"]


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
             stiffness: Sequence[str] = ()) -> Fidelity:
    """Each modelling level's end-effector error against the full model at ``reference_rtol``
    and its cost, at the scene's own run settings (``run_scene``) and at the reference
    tolerance (which leaves the modelling error alone). Each law in ``stiffness`` other than
    the scene's adds a rung: the full model under that contact stiffness law."""
    from tqdm import tqdm

    from jointplay.derive import model_for
    from jointplay.scene import ideal_counterpart

    run_scene = run_scene or scene
    rungs: list[tuple[str, Scene, str]] = [
        ("ideal joints", scene.with_robot(ideal_counterpart(scene.robot)), ""),
        ("clearance, no friction", without_friction(scene),
         "same as the full model: the scene has no friction"
         if scene.robot.friction.law == "none" else ""),
        ("clearance + friction (full)", scene, ""),
    ]
    from jointplay.contact_laws import with_stiffness

    rungs[-1:-1] = [(f"clearance + friction, {law} stiffness",
                     scene.with_robot(with_stiffness(scene.robot, law)), "")
                    for law in stiffness if law != scene.robot.contact.stiffness]
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
                       "note": row_note, "repeats": len(timed.cpu_s), "compile_s": compile_s,
                       **timed.spread("cpu"), **timed.spread("wall"),
                       **run_counts(timed.result)}
                row["realtime_factor"] = row["cpu_median_s"] / cfg.run.t_end
                row.update(tip_errors(timed.result, reference) if timed.result is not None
                           else {k: math.nan for k in ERROR_KEYS[:3]})
                rows.append(row)
                bar.update(1)
    rows.append(surrogate_row(run_scene, surrogate, reference, repeats))
    return Fidelity(scene=run_scene, reference_label=run_label(scene.with_run(**tight)),
                    rows=rows, facts=machine_facts())


def _run_settings(scene: Scene) -> dict[str, Any]:
    run = scene.run
    return {"integrator": run.integrator, "rtol": run.rtol, "atol": run.atol, "step": run.step}


def surrogate_row(scene: Scene, model_dir: Path | None, reference: SimulationResult,
                  repeats: int = 3) -> dict[str, Any]:
    """The neural-surrogate rung: a hook, skipped with a note unless a trained model is given.

    The surrogate module (``jointplay.narx``) is expected to provide
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
    fig, axes = _figure(1, 3, 13.0, 4.2)
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
    return _save(fig, path)


def write_fidelity(fid: Fidelity, out: Path, command: str = "") -> list[Path]:
    md = [f"# Fidelity ladder: {fid.scene.name}", ""]
    if command:
        md += [f"Command: `{command}`", ""]
    md += [f"- scene: {fid.scene.source or fid.scene.name}, t_end = {fid.scene.run.t_end:g} s",
           f"- errors: max over the output samples of the end-effector error norm against "
           f"the full model at {fid.reference_label}",
           "- each model runs at the scene's own settings (what it costs) and at the "
           "reference tolerance (its modelling error alone)",
           *(f"- {k}: {v}" for k, v in fid.facts.items()), "",
           markdown_table(fid.rows, FID_COLUMNS), ""]
    paths = [out / "fidelity.csv", out / "fidelity.md", out / "fidelity.png"]
    atomic_write_text(paths[0], to_csv(fid.rows, FID_CSV_KEYS))
    atomic_write_text(paths[1], "\n".join(md))
    _plot_fidelity(fid, paths[2])
    return paths


# ---- scaling with the number of links -----------------------------------------------------

SCALING_COLUMNS: list[tuple[str, str, str]] = [
    ("structure", "structure", "{}"),
    ("k", "k", "{}"),
    ("n_coords", "n", "{}"),
    ("derive_s", "derive s", "{:.2f}"),
    ("emit_s", "emit s", "{:.2f}"),
    ("compile_s", "gcc s", "{:.2f}"),
    ("build_s", "build s", "{:.2f}"),
    ("sim_cpu_s", "sim CPU s", "{:.3f}"),
    ("cost_per_sim_s", "CPU s per sim s", "{:.3f}"),
    ("sim_wall_per_sim_s", "wall s per sim s", "{:.3f}"),
    ("steps", "steps", "{}"),
    ("rhs_evaluations", "rhs evals", "{}"),
    ("jacobian_evaluations", "Jac evals", "{}"),
    ("impacts", "impacts", "{}"),
]
SCALING_CSV_KEYS: list[str] = [
    "structure", "k", "n_coords", "derive_s", "kane_s", "emit_s", "compile_s", "build_s",
    "sim_time", "repeats", "sim_cpu_s", "sim_cpu_min_s", "sim_cpu_max_s", "cost_per_sim_s",
    "sim_wall_s", "sim_wall_per_sim_s", "steps", "rhs_evaluations", "jacobian_evaluations",
    "events", "impacts", "load_start", "load_end", "error"]


def scaling_scene(robot: Any, sim_time: float) -> Scene:
    """A short driven motion: hanging straight down at rest, sinusoidal torque on every joint."""
    from jointplay.scene import scene_from_dict

    torques = {f"joint{j}": SCALING_TORQUE for j in robot.moving_joints} if robot.drive else {}
    initial = {"q1": "-pi/2"} if 1 in robot.moving_joints else {}
    return scene_from_dict({
        "name": robot.name, "robot": robot.to_dict(), "torques": torques, "initial": initial,
        "run": {"t_end": sim_time, "output_step": 1e-3, "integrator": "bdf",
                "rtol": 1e-6, "atol": 1e-6}})


def scaling_case(spec: dict[str, Any]) -> dict[str, Any]:
    """Measure one (structure, k) from a cold start: derive, emit, gcc into an empty cache,
    then simulate ``sim_time`` seconds ``repeats`` times. Runs in a fresh process."""
    with tempfile.TemporaryDirectory(prefix="jointplay-bench-") as tmp_name:
        tmp = Path(tmp_name)
        os.environ["JOINTPLAY_CACHE"] = str(tmp / "cache")

        import jointplay
        from jointplay.build import DEFAULT_CFLAGS, compile_source
        from jointplay.derive import emit
        from jointplay.model import LAYOUT_NAME, ROBOT_NAME, SOURCE_NAME, load_model
        from jointplay.robotio import robot_to_toml

        structure, k = str(spec["structure"]), int(spec["k"])
        robot = jointplay.uniform_chain(k, kinds=[structure] * k, name=f"{structure}{k}")
        load_start = os.getloadavg()[0]
        emitted = emit(robot)
        folder = tmp / "model"
        folder.mkdir()
        atomic_write_text(folder / SOURCE_NAME, emitted.source)
        atomic_write_text(folder / LAYOUT_NAME, json.dumps(emitted.layout, indent=1) + "\n")
        atomic_write_text(folder / ROBOT_NAME, robot_to_toml(robot))
        _, compile_s = compile_source(emitted.source, DEFAULT_CFLAGS, cache=tmp / "cache")
        model = load_model(folder)
        sim_time = float(spec["sim_time"])
        scene = scaling_scene(robot, sim_time)
        timed = timed_runs(scene, model, int(spec["repeats"]))
        row: dict[str, Any] = {
            "structure": structure, "k": k, "n_coords": model.n_coordinates,
            "derive_s": emitted.timings["derive"], "kane_s": emitted.timings.get("kane"),
            "emit_s": emitted.timings["emit"], "compile_s": compile_s,
            "build_s": emitted.timings["derive"] + emitted.timings["emit"] + compile_s,
            "sim_time": sim_time, "repeats": len(timed.cpu_s),
            **run_counts(timed.result), "load_start": load_start,
            "load_end": os.getloadavg()[0], "error": timed.failure or "",
        }
        if timed.result is not None:
            cpu = timed.spread("cpu")
            wall = timed.spread("wall")
            row.update(sim_cpu_s=cpu["cpu_median_s"], sim_cpu_min_s=cpu["cpu_min_s"],
                       sim_cpu_max_s=cpu["cpu_max_s"],
                       cost_per_sim_s=cpu["cpu_median_s"] / sim_time,
                       sim_wall_s=wall["wall_median_s"],
                       sim_wall_per_sim_s=wall["wall_median_s"] / sim_time)
        return row


_WORKER = ("import json, sys; from jointplay.bench import scaling_case; "
           "print(json.dumps(scaling_case(json.loads(sys.argv[1]))))")


def run_scaling_case(spec: dict[str, Any], timeout: float) -> dict[str, Any]:
    """:func:`scaling_case` in a fresh interpreter (sympy's caches cold); killed on timeout."""
    proc = subprocess.Popen([sys.executable, "-c", _WORKER, json.dumps(spec)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return {"structure": spec["structure"], "k": spec["k"],
                "error": f"timed out after {timeout:.0f} s"}
    if proc.returncode != 0:
        tail = (err.strip().splitlines() or ["?"])[-1]
        return {"structure": spec["structure"], "k": spec["k"],
                "error": f"exit {proc.returncode}: {tail}"}
    return dict(json.loads(out.strip().splitlines()[-1]))


def scaling(links: Sequence[int], structures: Sequence[str] = STRUCTURES, *,
            sim_time: float = SCALING_SIM_TIME, repeats: int = 3, timeout: float = 1200.0,
            quiet: bool = False) -> list[dict[str, Any]]:
    from tqdm import tqdm

    cases = [(s, k) for s in structures for k in links]
    rows = []
    with tqdm(cases, unit="case", disable=quiet, dynamic_ncols=True) as bar:
        for structure, k in bar:
            bar.set_description(f"{structure} k={k}")
            row = run_scaling_case({"structure": structure, "k": k, "sim_time": sim_time,
                                    "repeats": repeats}, timeout)
            rows.append(row)
            if row.get("error") and "cost_per_sim_s" not in row:
                tqdm.write(f"{structure} k={k}: FAILED {row['error']}")
            elif not quiet:
                tqdm.write(f"{structure} k={k}: build {row['build_s']:.2f} s, "
                           f"{row['cost_per_sim_s']:.3f} CPU s per simulated s")
    return rows


def _plot_scaling(rows: list[dict[str, Any]], path: Path, sim_time: float) -> Path:
    fig, axes = _figure(1, 2, 11.0, 4.2)
    styles = {"clearance": "-", "ideal": "--"}
    for structure in dict.fromkeys(r["structure"] for r in rows):
        ok = [r for r in rows if r["structure"] == structure and "build_s" in r]
        if not ok:
            continue
        k = [r["k"] for r in ok]
        for i, (key, label) in enumerate((("derive_s", "derive"), ("emit_s", "emit"),
                                          ("compile_s", "gcc"), ("build_s", "total"))):
            axes[0, 0].plot(k, [r[key] for r in ok], styles.get(structure, "-"), marker="o",
                            ms=3, color=f"C{i}", label=f"{label} ({structure})")
        sim = [r for r in ok if r.get("cost_per_sim_s") is not None]
        axes[0, 1].plot([r["k"] for r in sim], [r["cost_per_sim_s"] for r in sim],
                        styles.get(structure, "-"), marker="o", ms=3, label=structure)
    axes[0, 0].set_ylabel("seconds (cold process, empty cache)")
    axes[0, 0].set_title("derive, emit and compile", fontsize=10)
    axes[0, 1].set_ylabel("CPU s per simulated second")
    axes[0, 1].set_title(f"simulation ({sim_time:g} s driven motion, bdf rtol 1e-6)",
                         fontsize=10)
    for ax in axes[0]:
        ax.set_yscale("log")
        ax.set_xlabel("links k")
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=7)
    return _save(fig, path)


def write_scaling(rows: list[dict[str, Any]], out: Path, *, sim_time: float,
                  facts: dict[str, str], command: str = "") -> list[Path]:
    md = ["# Scaling with the number of links", ""]
    if command:
        md += [f"Command: `{command}`", ""]
    md += ["- each case in a fresh process with an empty compile cache: sympy derivation "
           "(Kane's method), CasADi emission, gcc with the default flags",
           f"- simulation: uniform chain of 0.3 m, 1 kg rods hanging at rest, torque "
           f"{SCALING_TORQUE} N m on every joint, {sim_time:g} s with bdf rtol = atol = "
           "1e-6; CPU time median over the repeats, divided by the simulated time",
           "- clearance: every joint has 0.03 mm radial clearance (Lankarani-Nikravesh "
           "contact, Coulomb friction); ideal: every joint ideal",
           *(f"- {k}: {v}" for k, v in facts.items()), "",
           markdown_table(rows, SCALING_COLUMNS), ""]
    failed = [r for r in rows if r.get("error")]
    if failed:
        md += ["## Failed or incomplete cases", ""]
        md += [f"- {r['structure']} k={r['k']}: {r['error']}" for r in failed]
        md.append("")
    paths = [out / "scaling.csv", out / "scaling.md", out / "scaling.png"]
    atomic_write_text(paths[0], to_csv(rows, SCALING_CSV_KEYS))
    atomic_write_text(paths[1], "\n".join(md))
    _plot_scaling(rows, paths[2], sim_time)
    return paths


# ---- tables, figures, facts ---------------------------------------------------------------


def _cell(value: Any, fmt: str) -> str:
    if value is None or value == "" or (isinstance(value, float) and math.isnan(value)):
        return ""
    try:
        return fmt.format(value)
    except (ValueError, TypeError):
        return str(value)


def markdown_table(rows: Sequence[dict[str, Any]], columns: Sequence[tuple[str, str, str]]
                   ) -> str:
    lines = ["| " + " | ".join(h for _, h, _ in columns) + " |",
             "|" + "|".join("---" if f == "{}" else "---:" for _, _, f in columns) + "|"]
    for row in rows:
        cells = [_cell(row.get(k), f).replace("|", "\\|") for k, _, f in columns]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def to_csv(rows: Sequence[dict[str, Any]], keys: Sequence[str]) -> str:
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=list(keys), extrasaction="ignore",
                            lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: ("" if v is None else repr(v) if isinstance(v, float) else v)
                         for k, v in row.items() if k in keys})
    return buf.getvalue()


def _figure(rows: int, cols: int, width: float, height: float) -> tuple[Figure, Any]:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(rows, cols, squeeze=False)
    return fig, axes


def _save(fig: Figure, path: Path) -> Path:
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=130)
    return path


def cpu_name() -> str:
    """The processor's model name (from /proc/cpuinfo where there is one)."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def machine_facts() -> dict[str, str]:
    """Where the numbers were measured: they mean little without it."""
    from importlib.metadata import version

    from jointplay.build import compiler_version

    cpu = cpu_name()
    load = os.getloadavg()
    return {
        "code": _commit(),
        "cpu": f"{cpu}, {os.cpu_count()} cores",
        "load average (1/5/15 min) at the end": " ".join(f"{v:.2f}" for v in load),
        "versions": ", ".join(f"{p} {version(p)}" for p in ("jointplay", "casadi", "numpy"))
        + f", python {platform.python_version()}, {compiler_version()}",
    }


def _commit() -> str:
    """The git commit measured, and whether the package's sources differ from it."""
    root = Path(__file__).resolve().parents[1]
    try:
        head = subprocess.run(["git", "-C", str(root), "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True, check=True, timeout=10)
        dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--",
                                "runtime", "derive", "generated", "scenes"],
                               capture_output=True, text=True, check=True, timeout=10)
    except (OSError, subprocess.SubprocessError):
        return "unknown (not a git checkout)"
    changed = [line[3:] for line in dirty.stdout.splitlines() if line.strip()]
    return f"commit {head.stdout.strip()}" + (
        f" with local changes in {', '.join(changed)}" if changed else "")


# ---- command line -------------------------------------------------------------------------


def _floats(text: str, flag: str) -> list[float]:
    values = []
    for item in text.split(","):
        item = item.strip()
        if not item:
            continue
        try:
            value = float(item)
        except ValueError:
            raise DescriptionError(flag, f"expects comma-separated numbers, got {item!r}") \
                from None
        if not (math.isfinite(value) and value > 0):
            raise DescriptionError(flag, f"every value must be a finite number > 0, got "
                                         f"{item!r}")
        values.append(value)
    if not values:
        raise DescriptionError(flag, "no values given")
    return values


def parse_links(text: str, flag: str = "--links") -> list[int]:
    """``"1-12"``, ``"4,9,12"`` or ``"1-4,12"`` to a sorted list of link counts."""
    from jointplay.description import MAX_LINKS

    out: set[int] = set()
    for part in text.split(","):
        part = part.strip()
        if not part:
            continue
        lo, sep, hi = part.partition("-")
        try:
            first, last = int(lo), int(hi) if sep else int(lo)
        except ValueError:
            raise DescriptionError(flag, f"expects link counts like 1-12 or 2,4,8, got "
                                         f"{part!r}") from None
        if first < 1 or last < first or last > MAX_LINKS:
            raise DescriptionError(flag, f"link counts must be 1 to {MAX_LINKS}, low to high, "
                                         f"got {part!r}")
        out.update(range(first, last + 1))
    if not out:
        raise DescriptionError(flag, "no link counts given")
    return sorted(out)


def prepare_out_dir(path: str | Path, flag: str = "--out") -> Path:
    """Create the output folder (and parents) or fail naming the flag, before any work."""
    path = Path(path)
    if path.exists() and not path.is_dir():
        raise DescriptionError(flag, f"{path} exists and is not a folder")
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise DescriptionError(flag, f"cannot create folder {path}: {err.strerror}") from None
    if not os.access(path, os.W_OK | os.X_OK):
        raise DescriptionError(flag, f"cannot write to {path}: permission denied")
    return path


def _positive_int(value: int, flag: str) -> int:
    if value < 1:
        raise DescriptionError(flag, f"must be >= 1, got {value}")
    return value


def _load_scene(args: argparse.Namespace) -> Scene:
    from jointplay.scene import default_scene, load_scene

    return load_scene(args.scene) if args.scene else default_scene()


def _with_run(scene: Scene, **changes: Any) -> Scene:
    """``scene.with_run`` with errors naming the command-line flag instead of the field."""
    changes = {k: v for k, v in changes.items() if v is not None}
    if not changes:
        return scene
    try:
        return scene.with_run(**changes)
    except DescriptionError as err:
        flag = "--" + err.field.removeprefix("run.").replace("_", "-")
        raise DescriptionError(flag, err.message) from None


def _command() -> str:
    """The command line, when run as the ``jointplay`` program (else the report's settings
    stand alone)."""
    if Path(sys.argv[0]).name == "jointplay":
        return shlex.join(["jointplay", *sys.argv[1:]])
    return ""


def _report(paths: Sequence[Path], markdown_path: Path, quiet: bool) -> None:
    if not quiet:
        print(markdown_path.read_text(encoding="utf-8"))
    for path in paths:
        print(f"wrote {path}")


def cmd_work_precision(args: argparse.Namespace) -> int:
    from jointplay.scene import INTEGRATORS

    scene = _load_scene(args)
    t_end = args.t_end if args.t_end is not None else (QUICK_T_END if args.quick else None)
    scene = _with_run(scene, t_end=t_end)
    methods = [m.strip() for m in args.methods.split(",") if m.strip()]
    for m in methods:
        if m not in INTEGRATORS:
            raise DescriptionError("--methods", f"unknown method {m!r}; choose from "
                                                f"{', '.join(INTEGRATORS)}")
    if not methods:
        raise DescriptionError("--methods", "no methods given")
    rtols = _floats(args.rtols, "--rtols") if args.rtols else \
        list(QUICK_RTOLS if args.quick else DEFAULT_RTOLS)
    steps = _floats(args.steps, "--steps") if args.steps else \
        list(QUICK_STEPS if args.quick else DEFAULT_STEPS)
    for r in rtols:
        if r >= 1:
            raise DescriptionError("--rtols", f"every tolerance must be < 1, got {r:g}")
    for h in steps:
        try:
            scene.with_run(integrator="rk4", step=h)
        except DescriptionError as err:
            raise DescriptionError("--steps", err.message) from None
    repeats = _positive_int(args.repeats if args.repeats is not None
                            else (1 if args.quick else 3), "--repeats")
    _with_run(scene, rtol=args.reference_rtol)
    if args.check == "radau":
        _with_run(scene, integrator="radau", step=args.check_step)
    laws = _stiffness_option(args, scene)
    out = prepare_out_dir(args.out)
    if len(laws) == 1:
        _work_precision_one(_law_scene(scene, laws[0]), args, out, methods, rtols, steps,
                            repeats)
        return 0
    # One full work-precision (own model, own reference) per law, and a table of all rows.
    rows: list[dict[str, Any]] = []
    for law in laws:
        rows += _work_precision_one(_law_scene(scene, law), args,
                                    prepare_out_dir(out / law), methods, rtols, steps, repeats)
    md = [f"# Work-precision per contact stiffness law: {scene.name}", "",
          f"Command: `{_command()}`", "",
          "Each law's errors are against its own reference (see the law's folder).", "",
          markdown_table(rows, [("stiffness", "stiffness", "{}"), *WP_COLUMNS]), ""]
    atomic_write_text(out / "work_precision_laws.csv", to_csv(rows, WP_CSV_KEYS))
    atomic_write_text(out / "work_precision_laws.md", "\n".join(md))
    _report([out / "work_precision_laws.csv"], out / "work_precision_laws.md", args.quiet)
    return 0


def _stiffness_option(args: argparse.Namespace, scene: Scene) -> list[str]:
    from jointplay.contact_laws import parse_stiffnesses, with_stiffness

    if not args.stiffness:
        return [scene.robot.contact.stiffness]
    laws = parse_stiffnesses(args.stiffness, "--stiffness")
    if not scene.robot.clearance_joints:
        raise DescriptionError("--stiffness", "the scene's robot has no clearance joint, so "
                                              "no contact law")
    for law in laws:
        try:
            with_stiffness(scene.robot, law)
        except DescriptionError as err:
            raise DescriptionError("--stiffness", f"{law}: {err.field}: {err.message}"
                                   ) from None
    return laws


def _law_scene(scene: Scene, law: str) -> Scene:
    from jointplay.contact_laws import with_stiffness

    if law == scene.robot.contact.stiffness:
        return scene
    return scene.with_robot(with_stiffness(scene.robot, law))


def _work_precision_one(scene: Scene, args: argparse.Namespace, out: Path,
                        methods: list[str], rtols: list[float], steps: list[float],
                        repeats: int) -> list[dict[str, Any]]:
    from jointplay.simulation import load_scene_model

    t0 = time.perf_counter()
    model = load_scene_model(scene)
    load_s = time.perf_counter() - t0
    compile_s = cold_compile_seconds(model)
    if not args.quiet:
        print(f"reference: cvodes rtol {args.reference_rtol:g}, checked by {args.check}",
              file=sys.stderr)
    reference = reference_solution(scene, model, rtol=args.reference_rtol, check=args.check,
                                   check_step=args.check_step)
    reference, rows = work_precision(scene, model, methods=methods, rtols=rtols, steps=steps,
                                     repeats=repeats, reference=reference, quiet=args.quiet)
    wp = WorkPrecision(scene=scene, reference=reference, rows=rows, compile_s=compile_s,
                       load_s=load_s, repeats=repeats, facts=machine_facts())
    paths = write_work_precision(wp, out, _command())
    _report(paths, paths[1], args.quiet)
    return rows


def cmd_fidelity(args: argparse.Namespace) -> int:
    scene = _load_scene(args)
    t_end = args.t_end if args.t_end is not None else (QUICK_T_END if args.quick else None)
    scene = _with_run(scene, t_end=t_end)
    run_scene = _with_run(scene, integrator=args.integrator, rtol=args.rtol, atol=args.atol,
                          step=args.step)
    _with_run(scene, rtol=args.reference_rtol)
    repeats = _positive_int(args.repeats if args.repeats is not None
                            else (1 if args.quick else 3), "--repeats")
    surrogate = Path(args.surrogate) if args.surrogate else None
    if surrogate is not None and not surrogate.is_dir():
        raise DescriptionError("--surrogate", f"{surrogate} is not a folder holding a trained "
                                              "model")
    laws = _stiffness_option(args, scene) if args.stiffness else []
    out = prepare_out_dir(args.out)
    fid = fidelity(scene, run_scene=run_scene, reference_rtol=args.reference_rtol,
                   repeats=repeats, surrogate=surrogate, quiet=args.quiet, stiffness=laws)
    skipped = [r for r in fid.rows if r["status"] == "skipped" and surrogate is not None]
    for r in skipped:
        print(f"jointplay: note: surrogate row skipped: {r['note']}", file=sys.stderr)
    paths = write_fidelity(fid, out, _command())
    _report(paths, paths[1], args.quiet)
    return 0


def cmd_scaling(args: argparse.Namespace) -> int:
    links = parse_links(args.links)
    structures = [s.strip() for s in args.structures.split(",") if s.strip()]
    for s in structures:
        if s not in STRUCTURES:
            raise DescriptionError("--structures", f"unknown structure {s!r}; choose from "
                                                   f"{', '.join(STRUCTURES)}")
    if not structures:
        raise DescriptionError("--structures", "no structures given")
    if not (math.isfinite(args.sim_time) and args.sim_time > 0):
        raise DescriptionError("--sim-time", f"must be > 0 s, got {args.sim_time}")
    if abs(round(args.sim_time / 1e-3) * 1e-3 - args.sim_time) > 1e-9:
        raise DescriptionError("--sim-time", f"must be a whole number of milliseconds, got "
                                             f"{args.sim_time}")
    repeats = _positive_int(args.repeats, "--repeats")
    if args.timeout <= 0:
        raise DescriptionError("--timeout", f"must be > 0 s, got {args.timeout}")
    out = prepare_out_dir(args.out)
    load_before = " ".join(f"{v:.2f}" for v in os.getloadavg())
    rows = scaling(links, structures, sim_time=args.sim_time, repeats=repeats,
                   timeout=args.timeout, quiet=args.quiet)
    facts = {"load average (1/5/15 min) at the start": load_before, **machine_facts()}
    paths = write_scaling(rows, out, sim_time=args.sim_time, facts=facts,
                          command=_command())
    _report(paths, paths[1], args.quiet)
    return 0 if all("build_s" in r for r in rows) else 1


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``bench`` with its sub-commands to a CLI's ``add_subparsers()`` object."""
    bench = subparsers.add_parser(
        "bench", help="benchmarks: work-precision, fidelity ladder, scaling with links",
        description=__doc__.split("\n\n")[0])
    sub = bench.add_subparsers(dest="bench_command", required=True)

    def common(p: argparse.ArgumentParser, scene: bool = True) -> None:
        if scene:
            p.add_argument("scene", nargs="?", help="scene file (TOML); default: the built-in "
                                                     "paper scene")
        p.add_argument("--out", required=True, help="folder for the CSV, Markdown and PNG "
                                                    "(created if missing)")
        p.add_argument("--repeats", type=int, help="timed runs per configuration "
                                                   "(default 3; 1 with --quick)")
        p.add_argument("--quiet", action="store_true", help="no progress bars, no table")

    wp = sub.add_parser("work-precision", help="error against a reference vs CPU time, per "
                                               "integrator and tolerance or step")
    common(wp)
    wp.add_argument("--quick", action="store_true",
                    help=f"a tiny case: t_end {QUICK_T_END:g} s, two tolerances and two "
                         "steps, one repeat")
    wp.add_argument("--t-end", type=float, help="override run.t_end (s)")
    wp.add_argument("--methods", default=",".join(DEFAULT_METHODS),
                    help="comma list of bdf, cvodes, idas, rk4, radau (default all)")
    wp.add_argument("--rtols", help="adaptive tolerances, atol = rtol (default "
                                    f"{','.join(f'{r:g}' for r in DEFAULT_RTOLS)})")
    wp.add_argument("--steps", help="fixed steps in s, each dividing the output step (default "
                                    f"{','.join(f'{h:g}' for h in DEFAULT_STEPS)})")
    wp.add_argument("--reference-rtol", type=float, default=REFERENCE_RTOL,
                    help=f"tolerance of the CVODES reference (default {REFERENCE_RTOL:g})")
    wp.add_argument("--check", choices=CHECK_METHODS, default="idas",
                    help="second method that checks the reference: idas at the same "
                         "tolerance (default) or radau at --check-step")
    wp.add_argument("--check-step", type=float, default=DEFAULT_CHECK_STEP,
                    help=f"Radau step of the check (default {DEFAULT_CHECK_STEP:g} s)")
    wp.add_argument("--stiffness", metavar="LAWS",
                    help="comma list of contact stiffness laws (hertz, johnson, liu, pereira): "
                         "one work-precision per law, in DIR/<law>/, and all rows in "
                         "DIR/work_precision_laws.md (default: the scene's own law; clearance "
                         "joints without a length get 0.02 m)")
    wp.set_defaults(func=cmd_work_precision)

    fid = sub.add_parser("fidelity", help="ideal joints, clearance without and with "
                                          "friction: error against the full model vs time")
    common(fid)
    fid.add_argument("--quick", action="store_true",
                     help=f"a tiny case: t_end {QUICK_T_END:g} s, one repeat")
    fid.add_argument("--t-end", type=float, help="override run.t_end (s)")
    fid.add_argument("--integrator", help="override run.integrator for the timed runs")
    fid.add_argument("--rtol", type=float, help="override run.rtol for the timed runs")
    fid.add_argument("--atol", type=float, help="override run.atol for the timed runs")
    fid.add_argument("--step", type=float, help="override run.step for the timed runs")
    fid.add_argument("--reference-rtol", type=float, default=REFERENCE_RTOL,
                     help=f"tolerance of the full-model reference (default "
                          f"{REFERENCE_RTOL:g})")
    fid.add_argument("--surrogate", metavar="MODEL_DIR",
                     help=f"a trained neural surrogate ({SURROGATE_MODULE}); without it the "
                          "surrogate row is skipped with a note")
    fid.add_argument("--stiffness", metavar="LAWS",
                     help="comma list of contact stiffness laws (hertz, johnson, liu, "
                          "pereira): each one other than the scene's adds a rung, the full "
                          "model under that law (clearance joints without a length get "
                          "0.02 m)")
    fid.set_defaults(func=cmd_fidelity)

    sc = sub.add_parser("scaling", help="derive, emit and compile time, and the cost of a "
                                        "simulated second, against the number of links")
    common(sc, scene=False)
    sc.set_defaults(repeats=3)
    sc.add_argument("--links", default="1-12", help="link counts, e.g. 1-12 or 2,4,8 "
                                                    "(default 1-12)")
    sc.add_argument("--structures", default=",".join(STRUCTURES),
                    help="comma list of clearance (every joint), ideal (default both)")
    sc.add_argument("--sim-time", type=float, default=SCALING_SIM_TIME,
                    help=f"simulated seconds per case (default {SCALING_SIM_TIME:g})")
    sc.add_argument("--timeout", type=float, default=1200.0, help="seconds per case")
    sc.set_defaults(func=cmd_scaling)
    return bench


__all__ = [
    "Fidelity",
    "Reference",
    "Timed",
    "WorkPrecision",
    "all_errors",
    "cmd_fidelity",
    "cmd_scaling",
    "cmd_work_precision",
    "fidelity",
    "final_state_error",
    "markdown_table",
    "parse_links",
    "prepare_out_dir",
    "reference_solution",
    "register",
    "scaling",
    "scaling_case",
    "tip_errors",
    "to_csv",
    "work_precision",
    "write_fidelity",
    "write_scaling",
    "write_work_precision",
]
