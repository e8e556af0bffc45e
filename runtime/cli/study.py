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
import os
import time
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.cli.neural_args import (
    CONTROL_FLAGS,
    IDENTIFY_DATA,
    SETTINGS_HELP,
    FlagKeys,
    add_base_fraction_argument,
    add_base_motions_argument,
    add_contact_argument,
    add_identify_data_arguments,
    add_iterations_argument,
    add_linear_gain_argument,
    add_operating_range_arguments,
    add_residual_argument,
    add_scene_motions_argument,
    add_scheduling_argument,
    add_settings_arguments,
    add_settings_file_arguments,
    base_fraction_setting,
    contact_setting,
    fill_from_settings,
    float_list,
    int_list,
    iteration_counts,
    lpv_base_setting,
    neural_scene_argument,
    operating_range,
    residual_setting,
    scene_and_settings,
    scene_motions_setting,
    settings_defaults,
    settings_from_args,
    trajectory_counts,
)
from jointplay.common.errors import DescriptionError
from jointplay.common.files import OutputPlan, all_or_nothing, atomic_write_text
from jointplay.neural.control.imc import ControllerSettings
from jointplay.neural.control.loop_accuracy import ACCURACY_COLUMNS, accuracy_lines, check_tolerance
from jointplay.neural.control.metrics import WORSE_MARGIN
from jointplay.neural.identify.config import IdentifyConfig
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
    with_overrides,
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
    p.add_argument("--first-seed", type=int, default=0,
                   help="the seeds are FIRST_SEED, FIRST_SEED + 1, ... (default 0; a study of "
                        "seeds not used for tuning starts past them)")
    p.add_argument("--seeds", type=int, default=3,
                   help="training seeds at the scene's clearance (default %(default)s)")
    p.add_argument("--cases", default=",".join(CASES),
                   help=f"cases to run (default: all: {','.join(CASES)})")
    p.add_argument("--clearances", help="other radial clearances, m, e.g. 10e-6,60e-6 "
                                        "(each identified again)")
    p.add_argument("--clearance-seeds", type=int, default=2,
                   help="seeds per other clearance (default %(default)s)")
    p.add_argument("--workers", type=int, default=min(2, os.cpu_count() or 1),
                   help="processes for the closed-loop runs (default %(default)s)")
    add_identify_data_arguments(p, study=True)
    add_scheduling_argument(p)
    add_contact_argument(p, "--identify-contact-outputs")
    add_linear_gain_argument(p, "--identify-linear-input-gain")
    add_residual_argument(p, "--identify-residual-by")
    add_base_fraction_argument(p, "--identify-base-fraction")
    add_base_motions_argument(p, "--identify-base-motions")
    add_scene_motions_argument(p, "--identify-scene-motions")
    add_operating_range_arguments(p, prefix="identify-")
    p.add_argument("--identify-lags", default="2,2",
                   help="identify: output lags,input lags (default %(default)s)")
    p.add_argument("--identify-hidden", default="13,14",
                   help="identify: hidden layer widths (default %(default)s)")
    p.add_argument("--identify-window", type=int, default=IdentifyConfig.window,
                   help="identify: samples per free-run window, for training and for "
                        "weighing the residual (default %(default)s)")
    add_iterations_argument(p, "--identify-iterations",
                            "identify: L-BFGS iterations (default %(default)s)")
    add_settings_arguments(p, ControllerSettings())
    p.add_argument("--undeclared-noise", action="store_true",
                   help="run the noise case without telling the controllers the sensors' "
                        "noise (by default they are told, and choose their horizon for it)")
    p.add_argument("--verify", action="store_true",
                   help="check every run against the same loop with the plant at tolerances "
                        "10x tighter: per case and controller, the estimated tip error, the "
                        "agreement horizon of the impact sequence and the energy residual "
                        "(study.csv, study.md); costs a second run of every loop")
    p.add_argument("--quiet", action="store_true", help="no progress, no report")
    add_settings_file_arguments(p)
    settings_defaults(p, STUDY_FLAGS, shown=SHOWN_FLAGS)
    p.epilog = ("A study is a file: jointplay control-study STUDY.toml --out DIR (the scene's "
                "[identify], [control] and [study] tables, or a settings file naming its "
                "scene; scenes/study_best.toml); DIR/settings.toml reruns it. The flags not "
                "listed (--identify-hidden, --scheduling, --lambda, ...) are still accepted "
                "as overrides; " + SETTINGS_HELP
                + ".")
    p.set_defaults(func=cmd_study)
    return p


# control-study's flags and the settings key each overrides; --help lists SHOWN_FLAGS (the
# rest are overrides the settings file documents, also accepted as --set SECTION.KEY=VALUE).
STUDY_FLAGS: FlagKeys = {
    **IDENTIFY_DATA, "identify_lags": ("identify.output_lags", "identify.input_lags"),
    "identify_hidden": "identify.hidden", "identify_window": "identify.window",
    "identify_iterations": ("identify.one_step_iterations", "identify.multi_step_iterations"),
    **CONTROL_FLAGS, "first_seed": "study.first_seed", "seeds": "study.seeds",
    "cases": "study.cases", "clearances": "study.clearances",
    "clearance_seeds": "study.clearance_seeds", "workers": "study.workers",
    "undeclared_noise": "study.undeclared_noise", "verify": "study.verify"}
SHOWN_FLAGS = ("seeds", "first_seed", "cases", "clearances", "workers", "train", "validation",
               "test", "duration", "horizon", "verify")


def hidden_widths(args: argparse.Namespace) -> tuple[int, ...]:
    """--identify-hidden, checked as identify checks --hidden."""
    from jointplay.common import limits as size_limits

    hidden = tuple(int_list(args.identify_hidden, "--identify-hidden",
                            high=size_limits.MAX_HIDDEN_WIDTH))
    if len(hidden) > size_limits.MAX_HIDDEN_LAYERS:
        raise DescriptionError("--identify-hidden", f"gives {len(hidden)} layers; at most "
                               f"{size_limits.MAX_HIDDEN_LAYERS} are allowed")
    return hidden


def lag_settings(args: argparse.Namespace) -> dict[str, int]:
    """--identify-lags, checked as identify checks --lags."""
    from jointplay.common import limits as size_limits

    lags = int_list(args.identify_lags, "--identify-lags", 2, high=size_limits.MAX_LAGS)
    return {"output_lags": lags[0], "input_lags": lags[1]}


def window_setting(args: argparse.Namespace) -> int:
    """--identify-window, within identify's limits for --window."""
    from jointplay.common import limits as size_limits

    low, high = size_limits.MIN_WINDOW, size_limits.MAX_WINDOW
    if not low <= args.identify_window <= high:
        raise DescriptionError("--identify-window", f"must be an integer from {low} to {high}, "
                               f"got {args.identify_window}")
    return int(args.identify_window)


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
    resolved = settings_from_args(args, load_narx(models[plan.nominal][0]))
    settings = settings_from_args(args, None)
    compile_all(models, settings)
    rows = run_cases(args, plan, models, settings)
    summary = summarise(rows)
    text = "\n".join([
        f"# Controller study: {plan.scene.name}",
        "",
        f"{args.seeds} training seeds at {plan.nominal * 1e6:g} µm ("
        f"{', '.join(f'{size * 1e6:g} µm: {len(p)}' for size, p in models.items())} usable "
        "models); "
        f"cases: {', '.join(c.name for c in plan.cases)}; controller settings: horizon "
        f"{resolved.horizon}, guard {'on' if resolved.guard else 'OFF'}. Baselines run once per "
        "case (they do not depend on the seed). Worst = the largest value over the seeds.",
        "",
        summary_table(summary, plan.cases),
        "",
        *noise_note(rows, args.undeclared_noise),
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
        *(accuracy_lines(rows, plan.cases, check_tolerance(plan.scene)) if args.verify
          else []),
        "The \"after settling\" window of each case starts at "
        + ", ".join(sorted({f"{r['settle_s'] * 1e3:.0f} ms" for r in rows}))
        + " (the later of the internal-model controllers' engagement plus their setpoint "
        "filter's decay and the end of the open loop's release impacts).",
        "",
        f"Wall time {time.perf_counter() - started:.0f} s.",
    ])
    written = write_study(plan, rows, summary, text, verify=args.verify)
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
    scene, settings, scene_file = scene_and_settings(args)
    source = Path(args.scene) if args.scene else None  # never written over
    fill_from_settings(args, settings, STUDY_FLAGS)
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise DescriptionError("--out", f"{out} exists and is not a folder")
    study_outputs(out, scene, source)
    if args.measurement_noise:
        raise DescriptionError("--measurement-noise", "control-study's noise case puts its own "
                               "noise on the measurements and tells the controllers (see "
                               "--help); run it with --cases noise, or --undeclared-noise to "
                               "leave them untold; `jointplay control --measurement-noise` "
                               "runs one model under noise of your choice")
    contact = contact_setting(args, scene, "--identify-contact-outputs")
    if args.seeds < 1:
        raise DescriptionError("--seeds", f"must be at least 1, got {args.seeds}")
    if args.first_seed < 0:
        raise DescriptionError("--first-seed", f"must be 0 or more, got {args.first_seed}")
    names = tuple(c.strip() for c in args.cases.split(",") if c.strip())
    unknown = [c for c in names if c not in CASES]
    if unknown or not names:
        raise DescriptionError("--cases", f"unknown case(s) {unknown}; choose from "
                               f"{', '.join(CASES)}")
    nominal = nominal_clearance(scene)
    clearances = float_list(args.clearances, "--clearances") if args.clearances else ()
    counts = trajectory_counts(args)
    iters = iteration_counts(args.identify_iterations, "--identify-iterations")
    identify_args = {**{k: v for k, v in asdict(settings.identify).items()
                        if k not in ("seed", "workers")},
                     "n_train": counts[0], "n_validation": counts[1], "n_test": counts[2],
                     "duration": args.duration, "one_step_iterations": iters[0],
                     "multi_step_iterations": iters[1], "scheduling": args.scheduling,
                     "contact_outputs": contact,
                     "linear_input_gain": args.linear_input_gain,
                     "lpv_base": lpv_base_setting(args), "hidden": hidden_widths(args),
                     "window": window_setting(args),
                     "residual_by": residual_setting(args, "--identify-residual-by", counts[1]),
                     "base_fraction": base_fraction_setting(args, "--identify-base-fraction"),
                     "base_motions": args.base_motions,
                     "scene_motions": scene_motions_setting(args,
                                                            "--identify-scene-motions"),
                     **lag_settings(args),
                     **operating_range(args, prefix="identify-")}
    cases = case_list(scene, names, clearances, nominal,
                      scene.robot.clearance_joints if contact else ())
    scenes = {c.name: case_scene(scene, c) for c in cases}
    resolved = with_overrides(
        settings, study={"seeds": args.seeds, "first_seed": args.first_seed, "cases": names,
                         "clearances": clearances, "clearance_seeds": args.clearance_seeds,
                         "workers": args.workers, "undeclared_noise": bool(args.undeclared_noise),
                         "verify": bool(args.verify)})
    resolved = replace(resolved, control=settings_from_args(args, None), identify=replace(
        settings.identify, **identify_args))
    return StudyPlan(scene, out, cases, scenes, nominal, identify_args, resolved, scene_file,
                     source)


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
        n = args.seeds if math.isclose(size, plan.nominal, rel_tol=1e-9) else min(
            args.seeds, args.clearance_seeds)
        robot_scene = plan.scenes[next(k.name for k in plan.cases if k.clearance == size)]
        models[size] = ensure_models(robot_scene, plan.out / "models" / f"{size * 1e6:g}um", n,
                                     plan.identify_args, args.quiet, first=args.first_seed)
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
    STUDY_JOBS.clear()
    for c in plan.cases:
        STUDY_JOBS.append((c, plan.scenes[c.name], None, settings, None, args.verify))
    base_rows = pool_map(list(range(len(STUDY_JOBS))), args.workers, args.quiet, "baselines")
    rows = [r for rs in base_rows for r in rs]
    limits = {r["case"]: (r["limit"], r["settle_s"]) for r in rows if "limit" in r}
    start = len(STUDY_JOBS)
    for c in plan.cases:
        told = settings if args.undeclared_noise else declared(settings, plan.scene, c)
        for path in models[c.clearance]:
            STUDY_JOBS.append((c, plan.scenes[c.name], path, told, limits[c.name],
                               args.verify))
    model_rows = pool_map(list(range(start, len(STUDY_JOBS))), args.workers, args.quiet,
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
