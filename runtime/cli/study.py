"""``jointplay control-study``: the controllers over training seeds, trajectories and
clearances, the median and the worst seed (the study itself:
:mod:`jointplay.neural.study.control_study`).

Exit status 3 when an internal-model run diverged."""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import time
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.cli.neural_args import (
    add_controller_arguments,
    add_identify_arguments,
    check_identify_for,
    check_tracked_for,
    neural_scene_argument,
)
from jointplay.cli.neural_settings import (
    SETTINGS_HELP,
    add_settings_file_arguments,
    controller_settings,
    scene_and_settings,
    settings_flags,
)
from jointplay.common.errors import DescriptionError
from jointplay.common.files import OutputPlan, all_or_nothing, atomic_write_text
from jointplay.neural.control.imc import ControllerSettings
from jointplay.neural.control.loop_accuracy import ACCURACY_COLUMNS, accuracy_lines, check_tolerance
from jointplay.neural.control.metrics import WORSE_MARGIN
from jointplay.neural.model.narx import load_narx
from jointplay.neural.study.control_run import MODEL_BASED, load_lpv, load_twin
from jointplay.neural.study.control_study import (
    CASES,
    REPORTED,
    Case,
    case_list,
    case_scene,
    declared,
    ensure_models,
    goal_checks,
    nominal_clearance,
    plot_study,
    summarise,
    summary_table,
)
from jointplay.neural.study.report import ratio_goals, worse_lines
from jointplay.neural.study.runs import JUDGED, STUDY_JOBS, pool_map
from jointplay.neural.study.settings import (
    SETTINGS_FILE,
    Settings,
    settings_toml,
)

if TYPE_CHECKING:
    from jointplay.scene.definition import Scene


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``control-study`` to a ``jointplay`` argument parser's subcommands."""
    p = subparsers.add_parser(
        "control-study", help="the controllers over training seeds, trajectories and "
                              "clearances: median and worst case",
        description="Identify a model per seed (and per clearance), run every controller on "
                    "several trajectories and loop conditions, report the median and the worst "
                    "seed per controller, check the goals and plot. Exit status 3 when an "
                    "internal-model run diverged.")
    neural_scene_argument(p)
    p.add_argument("--out", required=True, metavar="DIR",
                   help="folder for models/, study.md, study.csv, study.json and the plots")
    study_flags = {"first_seed": "study.first_seed", "seeds": "study.seeds",
                   "cases": "study.cases", "clearances": "study.clearances",
                   "clearance_seeds": "study.clearance_seeds", "workers": "study.workers",
                   "undeclared_noise": "study.undeclared_noise", "verify": "study.verify"}
    for dest, kind, text in (
            ("first_seed", int, "the seeds are FIRST_SEED, FIRST_SEED + 1, ... (a study of "
                                "seeds not used for tuning starts past them)"),
            ("seeds", int, "training seeds at the scene's clearance"),
            ("cases", str, f"cases to run, of {','.join(CASES)}"),
            ("clearances", str, "other radial clearances, m, e.g. 10e-6,60e-6 (each "
                                "identified again)"),
            ("clearance_seeds", int, "seeds per other clearance"),
            ("workers", int, "processes for the closed-loop runs")):
        p.add_argument("--" + dest.replace("_", "-"), dest=dest, type=kind, help=text)
    p.add_argument("--undeclared-noise", action="store_true",
                   help="run the noise case without telling the controllers the sensors' "
                        "noise (by default they are told, and choose their horizon for it)")
    p.add_argument("--verify", action="store_true",
                   help="check every run against the same loop with the plant at tolerances "
                        "10x tighter: per case and controller, the estimated tip error, the "
                        "agreement horizon of the impact sequence and the energy residual "
                        "(study.csv, study.md); costs a second run of every loop")
    flags = {**add_identify_arguments(p, study=True), **add_controller_arguments(p),
             **study_flags}
    p.add_argument("--quiet", action="store_true", help="no progress, no report")
    add_settings_file_arguments(p)
    settings_flags(p, flags, shown=SHOWN_FLAGS)
    p.epilog = ("A study is a file: jointplay control-study STUDY.toml --out DIR (the scene's "
                "[identify], [control] and [study] tables, or a settings file naming its "
                "scene; scenes/study_best.toml); DIR/settings.toml reruns it. The flags not "
                "listed (--identify-hidden, --scheduling, --lambda, ...) are still accepted "
                "as overrides; " + SETTINGS_HELP + ".")
    p.set_defaults(func=cmd_study, settings_keys=flags)
    return p


# The flags --help lists (by dest); the others are overrides the settings file documents,
# each also a --set SECTION.KEY=VALUE.
SHOWN_FLAGS = ("seeds", "first_seed", "cases", "clearances", "workers", "identify_train",
               "identify_validation", "identify_test", "identify_duration", "horizon",
               "verify")


@dataclass(frozen=True)
class StudyPlan:
    """What the flags resolve to, checked before any model is identified."""

    scene: Scene
    out: Path
    cases: list[Case]
    scenes: dict[str, Scene]
    nominal: float
    identify_args: dict[str, Any]
    settings: Settings  # as resolved, flags included: recorded as settings.toml
    scene_file: Path | None
    source: Path | None  # the file given: a scene, or a settings file


def cmd_study(args: argparse.Namespace) -> int:
    """``jointplay control-study``: identify, run every case, summarise, check and plot."""
    from jointplay.common.extras import require

    require("control", "jointplay control-study")  # before any work
    plan = study_plan(args)
    plan.out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    models = identify_models(args, plan)
    # Checked against the first model; each model then fills the defaults (tracked outputs,
    # their scales) from its own training data.
    resolved = controller_settings(plan.settings, load_narx(models[plan.nominal][0]))
    settings = plan.settings.control
    compile_all(models, settings)
    rows = run_cases(args, plan, models, settings)
    summary = summarise(rows)
    text = "\n".join([
        f"# Controller study: {plan.scene.name}",
        "",
        f"{plan.settings.study.seeds} training seeds at {plan.nominal * 1e6:g} µm ("
        f"{', '.join(f'{size * 1e6:g} µm: {len(p)}' for size, p in models.items())} usable "
        "models); "
        f"cases: {', '.join(c.name for c in plan.cases)}; controller settings: horizon "
        f"{resolved.horizon}, guard {'on' if resolved.guard else 'OFF'}. Baselines run once per "
        "case (they do not depend on the seed). Worst = the largest value over the seeds.",
        "",
        summary_table(summary, plan.cases),
        "",
        *noise_note(rows, plan.settings.study.undeclared_noise),
        "Goals:",
        "",
        *goal_checks(summary, plan.cases),
        *ratio_goals(rows, plan.cases),
        "",
        "Against the baselines (" + ", ".join(JUDGED) + "; ties within "
        f"{WORSE_MARGIN:g} not counted):",
        "",
        *worse_lines(rows, plan.cases),
        "",
        *identification_lines(models),
        *(accuracy_lines(rows, plan.cases, check_tolerance(plan.scene))
          if plan.settings.study.verify else []),
        "The \"after settling\" window of each case starts at "
        + ", ".join(sorted({f"{r['settle_s'] * 1e3:.0f} ms" for r in rows}))
        + " (the later of the internal-model controllers' engagement plus their setpoint "
        "filter's decay and the end of the open loop's release impacts).",
        "",
        f"Wall time {time.perf_counter() - started:.0f} s.",
    ])
    written = write_study(plan, rows, summary, text, verify=plan.settings.study.verify)
    if not args.quiet:
        print(text)
        for path in written:
            print(f"wrote {path}")
    diverged = any(r["diverged"] > 0 for r in rows if r["controller"] in MODEL_BASED)
    return 3 if diverged else 0


def identification_lines(models: dict[float, list[Path]]) -> list[str]:
    """Free-run loss on each model's test runs: the saved network, its ARX twin and the
    LPV-ARX baseline (median and worst over seeds), from each model's metrics.json."""
    lines = ["Identification, free-run loss on the test runs (from each model's metrics.json; "
             "median / worst seed):", "",
             "| clearance | models | saved network | ARX | LPV-ARX | network residual weight "
             "> 0 |", "|---|---|---|---|---|---|"]
    for size, paths in models.items():
        losses: dict[str, list[float]] = {"model": [], "arx": [], "lpv_arx": []}
        alphas = []
        for path in paths:
            metrics = json.loads((path / "metrics.json").read_text(encoding="utf-8"))
            test = metrics.get("free_run_loss", {}).get("test")
            if test:
                for k in losses:
                    losses[k].append(float(test[k]))
            alphas.append(float(metrics.get("residual", {}).get("alpha", 0.0)))
        if not losses["model"]:
            continue
        import numpy as np

        cells = " | ".join(f"{np.median(v):.3g} / {np.max(v):.3g}" for v in losses.values())
        lines.append(f"| {size * 1e6:g} µm | {len(losses['model'])} | {cells} | "
                     f"{sum(a > 0 for a in alphas)} of {len(alphas)} |")
    return [*lines, ""]


def noise_note(rows: list[dict[str, Any]], undeclared: bool) -> list[str]:
    """A line saying what the noise case's controllers were told and which horizons they took."""
    noisy = [r for r in rows if r["case"] == "noise" and "horizon" in r]
    if not noisy:
        return []
    if undeclared:
        return ["Noise case: the controllers were not told the sensors' noise "
                "(--undeclared-noise).", ""]
    horizons = sorted({int(r["horizon"]) for r in noisy})
    lines = ["Noise case: the internal-model controllers were told the sensors' noise and "
             f"chose horizon {', '.join(map(str, horizons))} "
             "(jointplay.neural.control.noise_tuning)."]
    pd = [r for r in rows if r["case"] == "noise" and r["controller"] == "PD"]
    if pd:
        base = pd[0]["rms_acceleration_after"]
        for name in sorted({r["controller"] for r in noisy}):
            mine = [r for r in noisy if r["controller"] == name]
            predicted = [r["predicted_noise_ratio"] for r in mine]
            measured = [r["rms_acceleration_after"] / base for r in mine]
            lines.append(f"{name}: RMS |Δa| after settling predicted {_span(predicted)}x the "
                         f"inner loop's alone, measured {_span(measured)}x PD's (over the "
                         "seeds; the prediction is the linear twin's, the measurement the "
                         "clearance robot's).")
    return [*lines, ""]


def _span(values: list[float]) -> str:
    return f"{min(values):.3f}-{max(values):.3f}" if len(values) > 1 else f"{values[0]:.3f}"


def study_plan(args: argparse.Namespace) -> StudyPlan:
    """The scene, the cases and the identification settings, every flag checked."""
    scene, settings, scene_file, given = scene_and_settings(args, args.settings_keys)
    source = Path(args.scene) if args.scene else None  # never written over
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise DescriptionError("--out", f"{out} exists and is not a folder")
    study_outputs(out, scene, source)
    if settings.control.measurement_noise:
        raise DescriptionError(
            given.get("control.measurement_noise", "control.measurement_noise"),
            "control-study's noise case puts its own noise on the measurements and tells the "
            "controllers (see --help); run it with --cases noise, or --undeclared-noise to "
            "leave them untold; `jointplay control --measurement-noise` runs one model under "
            "noise of your choice")
    config = check_identify_for(settings.identify, scene, given)
    check_tracked_for(settings.control.tracked, scene, config.contact_outputs, given)
    study = settings.study
    nominal = nominal_clearance(scene)
    # Every model's identification: the settings' [identify] table but its seed (one per
    # model) and its workers (a process pool of the study's).
    identify_args = {k: v for k, v in asdict(config).items() if k not in ("seed", "workers")}
    cases = case_list(scene, study.cases, study.clearances, nominal,
                      scene.robot.clearance_joints if config.contact_outputs else ())
    scenes = {c.name: case_scene(scene, c) for c in cases}
    return StudyPlan(scene, out, cases, scenes, nominal, identify_args,
                     replace(settings, identify=config), scene_file, source)


def study_outputs(out: Path, scene: Scene, source: Path | None = None) -> OutputPlan:
    """study.csv, .md, .json and the figures, the model folders under models/, and the
    files read (the scene, its torque table): refused when they meet (exit 2)."""
    from jointplay.cli.args import plan_scene_inputs

    plan = OutputPlan()
    plan_scene_inputs(plan, scene)
    plan.input("scene", source)
    for name in ("study.csv", "study.md", "study.json", SETTINGS_FILE):
        plan.file("--out", out / name, f"the study's {name}")
    plan.folder("--out", out / "models", "the identified models")
    plan.folder("--out", out, "the figures", pattern="*.png")
    plan.check()
    return plan


def identify_models(args: argparse.Namespace, plan: StudyPlan) -> dict[float, list[Path]]:
    """Usable model folders per clearance (all seeds at the scene's, fewer at the others)."""
    models: dict[float, list[Path]] = {}
    for size in sorted({c.clearance for c in plan.cases}):
        n = plan.settings.study.seeds if math.isclose(size, plan.nominal, rel_tol=1e-9) else min(
            plan.settings.study.seeds, plan.settings.study.clearance_seeds)
        robot_scene = plan.scenes[next(k.name for k in plan.cases if k.clearance == size)]
        models[size] = ensure_models(robot_scene, plan.out / "models" / f"{size * 1e6:g}um", n,
                                     plan.identify_args, args.quiet,
                                     first=plan.settings.study.first_seed)
    if not models[plan.nominal]:
        raise DescriptionError("--seeds", "no seed gave a usable model; see the reports in "
                               f"{plan.out / 'models'}")
    return models


def compile_all(models: dict[float, list[Path]], settings: ControllerSettings) -> None:
    """Compile every controller once, before the workers fork (they then load it from the
    cache instead of compiling it twice at the same time)."""
    from jointplay.neural.control.imc import compile_controller

    for paths in models.values():
        for path in paths:
            narx = load_narx(path)
            arx = load_twin(path, narx)
            compile_controller(narx, settings, fallback=arx)
            compile_controller(arx, settings)
            lpv = load_lpv(path)
            if lpv is not None:
                compile_controller(lpv, settings, fallback=arx)


def run_cases(args: argparse.Namespace, plan: StudyPlan, models: dict[float, list[Path]],
              settings: ControllerSettings) -> list[dict[str, Any]]:
    """The baselines once per case, then the internal-model controllers per case and seed
    (bounded by the baselines' divergence limit, measured after the baselines' settling
    window); one row per run."""
    study = plan.settings.study
    STUDY_JOBS.clear()
    for c in plan.cases:
        STUDY_JOBS.append((c, plan.scenes[c.name], None, settings, None, study.verify))
    workers = study.workers
    base_rows = pool_map(list(range(len(STUDY_JOBS))), workers, args.quiet, "baselines")
    rows = [r for rs in base_rows for r in rs]
    limits = {r["case"]: (r["limit"], r["settle_s"]) for r in rows if "limit" in r}
    start = len(STUDY_JOBS)
    for c in plan.cases:
        told = settings if study.undeclared_noise else declared(settings, plan.scene, c)
        for path in models[c.clearance]:
            STUDY_JOBS.append((c, plan.scenes[c.name], path, told, limits[c.name],
                               study.verify))
    model_rows = pool_map(list(range(start, len(STUDY_JOBS))), workers, args.quiet,
                           "internal-model runs")
    return rows + [r for rs in model_rows for r in rs]


def write_study(plan: StudyPlan, rows: list[dict[str, Any]],
                summary: dict[tuple[str, str], dict[str, Any]], text: str, *,
                verify: bool = False) -> list[Path]:
    """study.csv, study.md, study.json and the plots; the paths written. ``verify`` adds
    the accuracy columns to study.csv."""
    with all_or_nothing(study_outputs(plan.out, plan.scene, plan.source)):
        return _write_study(plan, rows, summary, text, verify)


def _write_study(plan: StudyPlan, rows: list[dict[str, Any]],
                 summary: dict[tuple[str, str], dict[str, Any]], text: str,
                 verify: bool) -> list[Path]:
    out = plan.out
    buf = io.StringIO()
    fields = ["case", "clearance_um", "controller", "seed", "horizon", "predicted_noise_ratio",
              *REPORTED, *(ACCURACY_COLUMNS if verify else ())]
    writer = csv.DictWriter(buf, fieldnames=fields, extrasaction="ignore")
    writer.writeheader()
    writer.writerows(rows)
    atomic_write_text(out / "study.csv", buf.getvalue())
    atomic_write_text(out / "study.md", text + "\n")
    atomic_write_text(out / SETTINGS_FILE, settings_toml(plan.settings, plan.scene_file))
    atomic_write_text(out / "study.json", json.dumps(
        {"rows": rows, "summary": {f"{k[0]} / {k[1]}": v for k, v in summary.items()}},
        indent=1, default=float) + "\n")
    return [out / "study.md", out / "study.csv", out / "study.json", out / SETTINGS_FILE,
            *plot_study(rows, cases=plan.cases, folder=out)]
