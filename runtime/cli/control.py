"""``jointplay control``: validate, compile, run every controller against the ideal robot's
motion, report and plot (the loops themselves: :mod:`jointplay.neural.study.control_run`).

Exit status 3 when any controller (PD and computed torque included) diverged."""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.cli.args import check_writable_dir
from jointplay.cli.neural_args import (
    add_controller_arguments,
    float_list,
    neural_scene_argument,
)
from jointplay.cli.neural_settings import (
    add_settings_file_arguments,
    controller_settings,
    scene_and_settings,
    settings_flags,
)
from jointplay.common.errors import DescriptionError
from jointplay.common.files import OutputPlan, all_or_nothing, atomic_write_text, make_folder
from jointplay.neural.control.imc import ControllerSettings
from jointplay.neural.control.loop import NO_CONDITIONS, LoopConditions
from jointplay.neural.control.metrics import WORSE_MARGIN, worse_lines
from jointplay.neural.control.noise_tuning import noise_vector
from jointplay.neural.model.narx import MODEL_FILE, Narx, check_robot, load_narx
from jointplay.neural.study.control_run import (
    DIVERGENCE_FACTOR,
    EXIT_DIVERGED,
    LINEAR,
    MODEL_BASED,
    NEURAL,
    Comparison,
    compare,
    load_lpv,
    load_twin,
    metrics_table,
    test_case_scenes,
    verdict,
    write_runs,
)
from jointplay.neural.study.recommend import Recommendation, recommend_from_runs
from jointplay.neural.study.settings import SETTINGS_FILE, settings_toml

if TYPE_CHECKING:
    from jointplay.scene.definition import Scene


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``control`` to a ``jointplay`` argument parser's subcommands."""
    p = subparsers.add_parser(
        "control", help="closed-loop runs of the internal-model controllers and baselines "
                        "against the ideal robot's motion",
        description="Track the ideal-joint robot's motion with the clearance robot: open loop, "
                    "PD, computed torque (ideal model), internal-model control with the linear "
                    "ARX twin, and with the guarded NARX network (compiled), side by side. "
                    "Exit status 3 when any controller (PD and computed torque included) "
                    "diverged.")
    neural_scene_argument(p)
    p.add_argument("--model", required=True, metavar="MODEL_DIR",
                   help="folder written by `jointplay identify`")
    p.add_argument("--plot", metavar="DIR", help="write figures and the table (control.md) here")
    p.add_argument("--out", metavar="RUN.h5", help="write every run and the metrics (HDF5)")
    flags = add_controller_arguments(p)
    p.add_argument("--pd-kp", help="PD baseline stiffness per driven joint, N m/rad (default: "
                                   "the inner loop's)")
    p.add_argument("--pd-kd", help="PD baseline damping per driven joint, N m s/rad (default: "
                                   "the inner loop's)")
    p.add_argument("--ct-omega", type=float, default=15.0,
                   help="computed-torque baseline bandwidth, rad/s (default %(default)s)")
    p.add_argument("--ct-zeta", type=float, default=0.2,
                   help="computed-torque baseline damping ratio (default %(default)s)")
    p.add_argument("--transient", type=float, default=None,
                   help="seconds at the start left out of the 'after' metrics (default: from "
                        "the run: the later of the outer loop's engagement plus its setpoint "
                        "filter's decay and the end of the open loop's release impacts)")
    p.add_argument("--divergence-factor", type=float, default=DIVERGENCE_FACTOR,
                   help="a run whose tip error exceeds this x the open loop's largest is "
                        "stopped as diverged (default %(default)s)")
    p.add_argument("--test-cases", action="store_true",
                   help="also run PD and both internal-model controllers on the model's stored "
                        "test excitations")
    p.add_argument("--quiet", action="store_true", help="no progress, no report")
    add_settings_file_arguments(p)
    settings_flags(p, flags)
    p.set_defaults(func=cmd_control, settings_keys=flags)
    return p


@dataclass(frozen=True)
class ControlJob:
    """What the flags resolve to, every one checked before any loop runs."""

    scene: Scene
    model_dir: Path
    narx: Narx
    arx: Narx
    lpv: Narx | None  # the LPV-ARX model (model folders written before it: none)
    settings: ControllerSettings
    pd_kp: tuple[float, ...]
    pd_kd: tuple[float, ...]
    cases: list[tuple[str, Any]]
    record: str  # the resolved settings, as settings.toml (written under --plot)


def cmd_control(args: argparse.Namespace) -> int:
    """``jointplay control``: validate, compile, run every controller, report and plot.

    Exit status 3 when any controller (PD and computed torque included) diverged."""
    from jointplay.common.extras import require

    require("control", "jointplay control")  # before any work
    job = control_job(args)
    if not args.quiet:
        print(f"scene {job.scene.name}: reference = ideal-joint robot under the scene's "
              f"torques; plant = compiled clearance model; controller every "
              f"{job.scene.run.output_step:g} s")
    comparison = compare(job.scene, job.narx, job.settings, arx=job.arx, lpv=job.lpv,
                         transient=args.transient, ct_omega=args.ct_omega,
                         ct_zeta=args.ct_zeta, pd_kp=job.pd_kp, pd_kd=job.pd_kd,
                         quiet=args.quiet, divergence_factor=args.divergence_factor,
                         conditions=sensor_noise(job))
    verdicts: list[str] = []
    warnings, diverged = stability_lines(comparison, verdicts)
    warnings = [*identification_warnings(job.model_dir), *warnings]
    advice = recommendation(job, comparison, warnings, worse_lines(comparison.metrics))
    lines = report_lines(args, job, comparison, advice) + verdicts
    lines += retune_lines(args, job, comparison)
    worse = worse_lines(comparison.metrics)
    lines += ["", "Against the baselines (the open loop: every reported metric, the whole run "
                  "from the outer loop's engagement on and after settling; PD: the "
                  "internal-model controllers after settling; ties within "
                  f"{WORSE_MARGIN:.0%} not counted):", *([f"- {w}" for w in worse] or [
                      "- no controller is worse than the open loop, and no model-based one "
                      "worse than PD, on any judged metric"])]
    warnings += worse
    if comparison.noise_tuning is not None and not comparison.noise_tuning.met:
        warnings.append(comparison.noise_tuning.describe())
    if job.scene.name == "paper_4dof":
        lines += ["", "paper (its robot, with control): max |Δp| 2.4e-4 m, max |Δv| 7.7e-3 m/s, "
                      "acceleration error reduced tenfold"]
    # Exit 3 for any controller the report calls DIVERGED (PD and computed torque included).
    diverged = any_diverged(comparison)
    case_rows, cases_diverged = test_case_rows(args, job, comparison)
    lines += case_rows
    text = "\n".join(lines)
    written = write_outputs(args, job, comparison, text)
    if not args.quiet:
        print(text)
        for path in written:
            print(f"wrote {path}")
    for warning in warnings:
        print(f"jointplay: warning: {warning}", file=sys.stderr)
    return EXIT_DIVERGED if diverged or cases_diverged else 0


def control_job(args: argparse.Namespace) -> ControlJob:
    """Load the scene, the model and its twin; check every flag; prepare the outputs."""
    scene, resolved, scene_file, _ = scene_and_settings(args, args.settings_keys)
    output_plan(args, scene)  # outputs meeting each other or an input: refused first
    model_dir = Path(args.model)
    narx = load_narx(model_dir)
    check_robot(narx, scene.robot, scene.run.output_step, model_dir / MODEL_FILE)
    arx = load_twin(model_dir, narx)
    lpv = load_lpv(model_dir)
    settings = controller_settings(resolved, narx)
    nj = len(scene.robot.moving_joints)
    pd_kp = float_list(args.pd_kp, "--pd-kp", nj)
    pd_kd = float_list(args.pd_kd, "--pd-kd", nj, positive=False)
    check_loop_flags(args, scene)
    if args.plot:
        check_plot_dir(Path(args.plot))
    if args.out:
        from jointplay.results.write import check_output_path

        check_output_path(args.out, "--out")
    cases = test_case_scenes(model_dir, scene) if args.test_cases else []
    record = settings_toml(resolved, scene_file,
                           "jointplay control settings.toml --model MODEL_DIR")
    return ControlJob(scene, model_dir, narx, arx, lpv, settings, pd_kp, pd_kd, cases, record)


def check_loop_flags(args: argparse.Namespace, scene: Scene) -> None:
    for flag, value in (("--ct-omega", args.ct_omega), ("--ct-zeta", args.ct_zeta),
                        ("--divergence-factor", args.divergence_factor)):
        if not (math.isfinite(value) and value > 0):
            raise DescriptionError(flag, f"must be a positive number, got {value}")
    if args.transient is not None and not (math.isfinite(args.transient)
                                           and 0 <= args.transient < scene.run.t_end):
        raise DescriptionError("--transient", f"must be in [0, run.t_end), got {args.transient}")


def output_plan(args: argparse.Namespace, scene: Scene) -> OutputPlan:
    """The files the command writes (--out, the figures and control.md in --plot) and reads
    (the scene, its torque table, the model folder); refused when they meet (exit 2)."""
    from jointplay.cli.args import plan_scene_inputs

    plan = OutputPlan()
    plan_scene_inputs(plan, scene)
    plan.input("--model", args.model)
    if args.out:
        plan.file("--out", args.out)
    if args.plot:
        plan.folder("--plot", args.plot, "its figures and control.md")
    plan.check()
    return plan


def check_plot_dir(plot: Path) -> None:
    if plot.exists() and not plot.is_dir():
        raise DescriptionError("--plot", f"{plot} exists and is not a folder")
    check_writable_dir(plot, "--plot")


def report_lines(args: argparse.Namespace, job: ControlJob, comparison: Comparison,
                 advice: Recommendation | None = None) -> list[str]:
    """The controller to use, the metrics table and every setting the runs used."""
    settings, scene = ran_settings(job.settings, comparison), job.scene
    inner = job.narx.context["plant"]["inner_loop"]
    alpha = job.narx.context.get("training", {}).get("metrics", {}).get("residual_weight")
    criterion = {"closed-loop": "closed-loop error on the validation runs",
                 "closed-loop-scene": "closed-loop error on motions of the scene's family"}.get(
        job.narx.context.get("training", {}).get("residual_by", ""),
        "free-run error on the validation runs")
    guard = (f"on (|v| <= {settings.trust_input:g} x training, range margin "
             f"{settings.trust_range:g}, mismatch <= {settings.trust_mismatch:g}, hold "
             f"{settings.fallback_hold})" if settings.guard else "OFF")
    return [
        *([f"Recommended: {advice.line}."] if advice else []),
        "",
        f"End-effector errors vs the ideal-joint robot ({scene.name}, {scene.run.t_end:g} s; "
        "norms over x, y):",
        "",
        metrics_table(comparison.metrics, settled_time(comparison),
                      advice.controller if advice else None),
        "",
        (comparison.settling.describe() if comparison.settling else "") + ".",
        "",
        f"internal-model controllers: horizon {settings.horizon}, lambda "
        f"{settings.regularisation:g}, setpoint filter {settings.setpoint_filter:g}, mismatch "
        f"filter {settings.mismatch_filter:g}, tracked {', '.join(settings.tracked)}; guard "
        + guard
        + f"; inner PD kp {inner['kp']}, kd {inner['kd']}; PD baseline kp "
        f"{list(job.pd_kp) or inner['kp']}, kd {list(job.pd_kd) or inner['kd']}; computed "
        f"torque omega {args.ct_omega:g} rad/s, zeta {args.ct_zeta:g}; network residual "
        f"weight {alpha if alpha is not None else 'not recorded'}"
        + (f" (chosen by its {criterion})" if alpha is not None
           else "")
        + ("; the network's residual weight is 0: the neural IMC's model IS its ARX twin, "
           "its row is the ARX-IMC's with the guard, and the network does no work"
           if alpha == 0 and not job.narx.n_scheduling else "")
        + ("; the network's residual weight is 0: the neural IMC's model is the linear ARX "
           "model with the scheduling signals as further regressors, and the network does "
           "no work" if alpha == 0 and job.narx.n_scheduling and job.narx.bilinear is None
           else "")
        + ("; the network's residual weight is 0: the neural IMC's model is the LPV-ARX fit "
           "it was trained on (--lpv-base), and the network does no work"
           if alpha == 0 and job.narx.bilinear is not None else ""),
        *([comparison.noise_tuning.describe() + "; every controller measured through that "
           "noise (seed 1)"] if comparison.noise_tuning else []),
        "compiled step: " + ", ".join(
            f"{name} {us:.2f} us per call" for name, us in comparison.per_call_us.items())
        + f" (buffer path); divergence bound {comparison.limit:.3g} m (x"
        f"{args.divergence_factor:g} the open loop's largest tip error)",
        "",
        "Stability:",
    ]


AFTER_METRICS = ("max_velocity_after", "max_acceleration_after", "rms_acceleration_after")
RETUNE_HORIZONS = (2, 4)  # x the asked horizon: a longer horizon asks less of each step


def worse_after(mine: dict[str, float], base: dict[str, float]) -> list[str]:
    """The after-settling metrics on which ``mine`` is worse than ``base``."""
    return [k for k in AFTER_METRICS
            if base.get(k, 0.0) > 0 and mine.get(k, 0.0) > base[k] * (1 + WORSE_MARGIN)]


def retune_lines(args: argparse.Namespace, job: ControlJob,
                 comparison: Comparison) -> list[str]:
    """An internal-model controller that ends worse than no control after settling is run
    again with a longer horizon (2x, then 4x); the first retune that is not worse is added to
    the table as its own row. Without one, the line says it falls back to PD (v = 0)."""
    base = comparison.metrics.get("open loop")
    if base is None or comparison.settling is None:
        return []
    lines = []
    for name in MODEL_BASED:
        mine = comparison.metrics.get(name)
        if mine is None or not worse_after(mine, base):
            continue
        settings = ran_settings(job.settings, comparison)
        found = None
        for factor in RETUNE_HORIZONS:
            tuned = replace(settings, horizon=settings.horizon * factor)
            sub = compare(job.scene, job.narx, tuned, arx=job.arx, lpv=job.lpv,
                          controllers=(name,),
                          limit=comparison.limit, transient=comparison.settling.time,
                          quiet=True, analyse=False, conditions=sensor_noise(job),
                          ct_omega=args.ct_omega, ct_zeta=args.ct_zeta)
            if not sub.runs[name].diverged and not worse_after(sub.metrics[name], base):
                found = (tuned.horizon, sub)
                break
        if found is not None:
            horizon, sub = found
            label = f"{name} retuned (horizon {horizon})"
            comparison.metrics[label] = sub.metrics[name]
            comparison.runs[label] = sub.runs[name]
            lines.append(f"- {name} ends worse than no control after settling; retuned to "
                         f"horizon {horizon} it does not (row \"{label}\"): run it with "
                         f"--horizon {horizon}")
        else:
            tried = ", ".join(str(settings.horizon * f) for f in RETUNE_HORIZONS)
            pd = comparison.metrics.get("PD")
            fallback = ("use PD (its inner loop alone) instead on this scene"
                        if pd is not None and not worse_after(pd, base) else
                        "PD is worse than no control here too: on this scene no feedback "
                        "tried beats leaving the robot alone on these metrics")
            lines.append(f"- {name} ends worse than no control after settling, and so does it "
                         f"at horizons {tried}: {fallback}")
    return ["", "Retuning:", *lines] if lines else []


def recommendation(job: ControlJob, comparison: Comparison, warnings: list[str],
                   worse: list[str]) -> Recommendation | None:
    """The controller to use from this run (:mod:`jointplay.neural.study.recommend`); a controller
    named in a warning is not recommended while another is there."""
    warned = {name for name in comparison.metrics
              if any(w.startswith(f"{name}:") or w.startswith(f"{name} is worse")
                     for w in [*warnings, *worse])}
    alpha = job.narx.context.get("training", {}).get("metrics", {}).get("residual_weight")
    return recommend_from_runs(comparison.metrics, warned, alpha)


def identification_warnings(model_dir: Path) -> list[str]:
    """What identify warned about when it made this model (too little excitation, runs too
    short): repeated, since the controller inherits it."""
    import json

    try:
        metrics = json.loads((model_dir / "metrics.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return []
    return [f"the model was identified with a warning: {w}"
            for w in metrics.get("warnings", []) if isinstance(w, str)]


def settled_time(comparison: Comparison) -> float:
    """Seconds left out of the "after" metrics."""
    return comparison.settling.time if comparison.settling else 0.0


def sensor_noise(job: ControlJob) -> LoopConditions:
    """Declared sensor noise is also put on what every controller measures (seeded), so that
    the baselines are judged under the same sensors."""
    if not job.settings.measurement_noise:
        return NO_CONDITIONS
    return LoopConditions(noise=tuple(noise_vector(job.narx, job.settings)), seed=1)


def ran_settings(settings: ControllerSettings, comparison: Comparison) -> ControllerSettings:
    """The settings the internal-model controllers ran with: the horizon chosen for declared
    sensor noise in place of the asked one (and the noise, having been used, not again)."""
    tuning = comparison.noise_tuning
    if tuning is None:
        return settings
    return replace(settings, horizon=tuning.horizon, measurement_noise=())


def any_diverged(comparison: Comparison) -> bool:
    """Whether any controller of the comparison was stopped as diverged (the report marks each
    one DIVERGED): the exit status is 3 then, whichever controller it was."""
    return any(bool(run.diverged) for run in comparison.runs.values())


def stability_lines(comparison: Comparison, lines: list[str]) -> tuple[list[str], bool]:
    """Append each internal-model controller's verdict; return the warnings and whether one
    diverged."""
    warnings = []
    diverged = False
    for name in MODEL_BASED:
        if name in comparison.runs:
            text, warn = verdict(name, comparison.runs[name], comparison)
            lines.append(f"- {text}")
            diverged |= bool(comparison.runs[name].diverged)
            if warn:
                warnings.append(text)
    return warnings, diverged


def test_case_rows(args: argparse.Namespace, job: ControlJob,
                   comparison: Comparison) -> tuple[list[str], bool]:
    """The table of the closed loops on the stored test excitations (none without
    --test-cases), and whether any controller diverged on one."""
    rows, diverged = [], False
    for label, case_scene in job.cases:
        sub = compare(case_scene, job.narx, ran_settings(job.settings, comparison), arx=job.arx,
                      transient=args.transient, conditions=sensor_noise(job),
                      controllers=("PD", LINEAR, NEURAL), quiet=True, analyse=False,
                      compiled=comparison.controllers)
        cells = []
        for name in ("PD", LINEAR, NEURAL):
            mt = sub.metrics.get(name)
            cells += [f"{mt['max_position']:.3g}" if mt else "-",
                      f"{mt['max_velocity_after']:.3g}" if mt else "-"]
        model_runs = [sub.runs[n] for n in MODEL_BASED if n in sub.runs]
        states = ["DIVERGED" if run.diverged else "bounded" for run in model_runs]
        diverged |= any_diverged(sub)
        rows.append(f"| {label} | " + " | ".join(cells) + f" | {', '.join(states)} |")
    if not rows:
        return [], diverged
    return ["", "Closed loop on the stored test excitations (never used in training; "
                "max |Δp| [m], max |Δv| after the transient [m/s]):", "",
            "| case | PD Δp | PD Δv | ARX-IMC Δp | ARX-IMC Δv | neural Δp | neural Δv | "
            "ARX-IMC, neural |", "|---|---|---|---|---|---|---|---|", *rows], diverged


def write_outputs(args: argparse.Namespace, job: ControlJob, comparison: Comparison,
                  text: str) -> list[str]:
    """Figures and control.md under --plot, the runs in --out; the paths written."""
    with all_or_nothing(output_plan(args, job.scene)):
        if args.plot:
            make_folder(args.plot, "--plot")
        return _write_each(args, job, comparison, text)


def _write_each(args: argparse.Namespace, job: ControlJob, comparison: Comparison,
                text: str) -> list[str]:
    written = []
    if args.plot:
        from jointplay.neural.study.control_plots import plot_comparison

        plot = Path(args.plot)
        written += [str(p) for p in plot_comparison(comparison, job.scene, plot)]
        atomic_write_text(plot / "control.md", text.strip() + "\n")
        atomic_write_text(plot / SETTINGS_FILE, job.record)
        written += [str(plot / "control.md"), str(plot / SETTINGS_FILE)]
    if args.out:
        write_runs(Path(args.out), comparison,
                   {"settings": asdict(job.settings), "scene": job.scene.name,
                    "noise_tuning": (asdict(comparison.noise_tuning)
                                     if comparison.noise_tuning else None),
                    "per_call_us": comparison.per_call_us,
                    "nominal_radius": comparison.nominal_radius,
                    "network_checksum": job.narx.checksum(),
                    "arx_checksum": job.arx.checksum()},
                   tuple(zip(job.narx.output_names, job.narx.output_units, strict=True)))
        written.append(args.out)
    return written
