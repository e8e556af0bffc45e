"""Closed loops on the clearance robot: the ``jointplay control`` command over the comparison.

Controllers, each against the ideal-joint robot's motion under the scene's torques:

- open loop: the scene's torques only;
- PD: the inner loop alone;
- computed torque with the ideal-joint model;
- ARX-IMC: the internal-model law with the linear ARX twin inside;
- neural IMC: the same law with the NARX network inside, guarded (see jointplay.neural.imc), the ARX
  twin as its fallback.

The loop and its laws are in jointplay.neural.loop, the metrics in jointplay.neural.metrics, the
whole comparison and the stability verdict in jointplay.neural.comparison; their names are
importable from here as well.
"""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_write_text
from jointplay.neural.comparison import (
    CONTROLLERS,
    DEFAULT_TRANSIENT,
    DIVERGENCE_FACTOR,
    LINEAR,
    MARGINAL,
    MODEL_BASED,
    NEURAL,
    Comparison,
    compare,
    stability_radii,
    verdict,
    write_runs,
)
from jointplay.neural.imc import (
    FLAGS,
    Controller,
    ControllerSettings,
    build_step,
    compile_controller,
    default_tracked,
    generate_c,
    horizon_gain,
    local_spectral_radii,
    nominal_spectral_radius,
    per_call_us,
    resolve_settings,
)
from jointplay.neural.loop import (
    Law,
    LoopConditions,
    Run,
    computed_torque_law,
    imc_law,
    pd_law,
    run_loop,
)
from jointplay.neural.metrics import (
    GUARD_METRICS,
    METRICS,
    dense_acceleration_error,
    metrics_table,
    run_metrics,
    tip_errors,
)
from jointplay.neural.narx import ARX_FILE, MODEL_FILE, Narx, check_robot, load_narx

EXIT_DIVERGED = 3


# ---- the command ------------------------------------------------------------------------------

def _floats(text: str | None, flag: str, count: int | None = None,
            positive: bool = True) -> tuple[float, ...]:
    from jointplay.neural.identify import _floats as parse

    return parse(text, flag, count, positive)


def test_case_scenes(model_dir: Path, scene: Any) -> list[tuple[str, Any]]:
    """Scenes driven by the base torques of the stored test trajectories."""
    from jointplay.neural.identify import Chirp, Multisine, read_datasets, with_torques
    from jointplay.scene.expressions import parse_expression
    from jointplay.scene.tables import TableColumn

    path = model_dir / "datasets.h5"
    if not path.is_file():
        raise DescriptionError("--test-cases", f"{path} is missing; the model folder has no "
                               "stored test trajectories (run `jointplay identify` again)")
    trajectories, meta = read_datasets(path)
    out = []
    for tr in (t for t in trajectories if t.split == "test"):
        torques: list[Any] = []
        for i, desc in enumerate(tr.description.get("base", [])):
            kind = desc.get("kind")
            if kind == "multisine":
                torques.append(Multisine(np.array(desc["amplitude"]), np.array(desc["frequency"]),
                                         np.array(desc["phase"])))
            elif kind == "chirp":
                torques.append(Chirp(desc["amplitude"], desc["f0"], desc["f1"],
                                     desc["duration"], desc["phase"]))
            elif kind == "steps":
                torques.append(TableColumn(f"joint{i}", np.array(desc["times"]),
                                           np.array(desc["values"])))
            else:
                torques.append(parse_expression(desc["text"], field="torques",
                                                constants=scene.constants))
        duration = float(tr.t[-1])
        out.append((f"test {tr.family}", with_torques(scene.with_run(t_end=duration), torques)))
    del meta
    return out


def load_twin(model_dir: Path, narx: Narx) -> Narx:
    """The ARX twin of a model folder: arx.json, or (folders written before it existed) a
    least-squares fit on the stored training runs, as identify makes it."""
    from dataclasses import replace

    if (model_dir / ARX_FILE).is_file():
        return load_narx(model_dir, filename=ARX_FILE)
    from jointplay.neural.identify import _segments, fit_arx, read_datasets

    path = model_dir / "datasets.h5"
    if not path.is_file():
        raise DescriptionError("--model", f"{model_dir} has neither {ARX_FILE} nor datasets.h5 "
                               "for the ARX baseline: run `jointplay identify` again")
    trajectories, _ = read_datasets(path)
    skip = max(0, round(narx.context.get("plant", {}).get("transient", DEFAULT_TRANSIENT)
                        / narx.sample_time))
    names = {"output_names": narx.output_names, "output_units": narx.output_units,
             "input_names": narx.input_names, "input_units": narx.input_units}
    arx = fit_arx(_segments([t for t in trajectories if t.split == "train"], skip), names,
                  narx.output_lags, narx.input_lags, narx.sample_time)
    return replace(arx, context=narx.context)


def settings_from_args(args: argparse.Namespace, narx: Narx | None) -> ControllerSettings:
    """The settings the flags give; resolved against ``narx`` when given (defaults filled
    from it, every value checked), else as given (each model resolves them for itself)."""
    tracked = tuple(n.strip() for n in args.track.split(",") if n.strip()) if args.track else ()
    settings = ControllerSettings(
        horizon=args.horizon, regularisation=args.lambda_, setpoint_filter=args.setpoint_filter,
        mismatch_filter=args.mismatch_filter, tracked=tracked,
        scales=_floats(args.scales, "--scales"),
        torque_limit=_floats(args.torque_limit, "--torque-limit"),
        rate_limit=_floats(args.rate_limit, "--rate-limit"), iterations=args.iterations,
        guard=not args.no_guard, trust_input=args.trust_input, trust_range=args.trust_range,
        trust_mismatch=args.trust_mismatch, fallback_hold=args.fallback_hold,
        engage=args.engage)
    return resolve_settings(narx, settings) if narx is not None else settings


def cmd_control(args: argparse.Namespace) -> int:
    """``jointplay control``: validate, compile, run every controller, report and plot.

    Exit status 3 when an internal-model controller diverged."""
    from jointplay.neural.identify import _load_scene_arg

    scene = _load_scene_arg(args.scene, args.quiet)
    model_dir = Path(args.model)
    narx = load_narx(model_dir)
    check_robot(narx, scene.robot, scene.run.output_step, model_dir / MODEL_FILE)
    arx = load_twin(model_dir, narx)
    settings = settings_from_args(args, narx)
    nj = len(scene.robot.moving_joints)
    pd_kp = _floats(args.pd_kp, "--pd-kp", nj)
    pd_kd = _floats(args.pd_kd, "--pd-kd", nj, positive=False)
    for flag, value in (("--ct-omega", args.ct_omega), ("--ct-zeta", args.ct_zeta),
                        ("--divergence-factor", args.divergence_factor)):
        if not (math.isfinite(value) and value > 0):
            raise DescriptionError(flag, f"must be a positive number, got {value}")
    if not (math.isfinite(args.transient) and 0 <= args.transient < scene.run.t_end):
        raise DescriptionError("--transient", f"must be in [0, run.t_end), got {args.transient}")
    if args.plot:
        plot = Path(args.plot)
        if plot.exists() and not plot.is_dir():
            raise DescriptionError("--plot", f"{plot} exists and is not a folder")
        try:
            plot.mkdir(parents=True, exist_ok=True)
        except OSError as err:
            raise DescriptionError("--plot", f"cannot create folder {plot}: {err}") from None
    if args.out:
        from jointplay.results.write import check_output_path
        from jointplay.scene.definition import scene_inputs

        check_output_path(args.out, "--out",
                          inputs=[*scene_inputs(scene), model_dir / MODEL_FILE,
                                  model_dir / "datasets.h5"])
    cases = test_case_scenes(model_dir, scene) if args.test_cases else []

    quiet = args.quiet
    if not quiet:
        print(f"scene {scene.name}: reference = ideal-joint robot under the scene's torques; "
              f"plant = compiled clearance model; controller every {scene.run.output_step:g} s")
    comparison = compare(scene, narx, settings, arx=arx, transient=args.transient,
                         ct_omega=args.ct_omega, ct_zeta=args.ct_zeta, pd_kp=pd_kp,
                         pd_kd=pd_kd, quiet=quiet, divergence_factor=args.divergence_factor)
    inner = narx.context["plant"]["inner_loop"]
    alpha = narx.context.get("training", {}).get("metrics", {}).get("residual_weight")
    lines = [
        "",
        f"End-effector errors vs the ideal-joint robot ({scene.name}, {scene.run.t_end:g} s; "
        "norms over x, y):",
        "",
        metrics_table(comparison.metrics, args.transient),
        "",
        f"internal-model controllers: horizon {settings.horizon}, lambda "
        f"{settings.regularisation:g}, setpoint filter {settings.setpoint_filter:g}, mismatch "
        f"filter {settings.mismatch_filter:g}, tracked {', '.join(settings.tracked)}; guard "
        + (f"on (|v| <= {settings.trust_input:g} x training, range margin "
           f"{settings.trust_range:g}, mismatch <= {settings.trust_mismatch:g}, hold "
           f"{settings.fallback_hold})" if settings.guard else "OFF")
        + f"; inner PD kp {inner['kp']}, kd {inner['kd']}; PD baseline kp "
        f"{list(pd_kp) or inner['kp']}, kd {list(pd_kd) or inner['kd']}; computed torque "
        f"omega {args.ct_omega:g} rad/s, zeta {args.ct_zeta:g}; network residual weight "
        f"{alpha if alpha is not None else 'not recorded'}",
        "compiled step: " + ", ".join(
            f"{name} {us:.2f} us per call" for name, us in comparison.per_call_us.items())
        + f" (buffer path); divergence bound {comparison.limit:.3g} m (x"
        f"{args.divergence_factor:g} the open loop's largest tip error)",
        "",
        "Stability:",
    ]
    warnings = []
    diverged = False
    for name in MODEL_BASED:
        if name in comparison.runs:
            text, warn = verdict(name, comparison.runs[name], comparison)
            lines.append(f"- {text}")
            diverged |= bool(comparison.runs[name].diverged)
            if warn:
                warnings.append(text)
    if scene.name == "paper_4dof":
        lines += ["", "paper (its robot, with control): max |Δp| 2.4e-4 m, max |Δv| 7.7e-3 m/s, "
                      "acceleration error reduced tenfold"]
    case_rows = []
    for label, case_scene in cases:
        sub = compare(case_scene, narx, settings, arx=arx, transient=args.transient,
                      controllers=("PD", LINEAR, NEURAL), quiet=True, analyse=False,
                      compiled=comparison.controllers)
        cells = []
        for name in ("PD", LINEAR, NEURAL):
            mt = sub.metrics.get(name)
            cells += [f"{mt['max_position']:.3g}" if mt else "-",
                      f"{mt['max_velocity_after']:.3g}" if mt else "-"]
        states = [("DIVERGED" if sub.runs[n].diverged else "bounded") for n in MODEL_BASED
                  if n in sub.runs]
        diverged |= any(sub.runs[n].diverged for n in MODEL_BASED if n in sub.runs)
        case_rows.append(f"| {label} | " + " | ".join(cells) + f" | {', '.join(states)} |")
    if case_rows:
        lines += ["", "Closed loop on the stored test excitations (never used in training; "
                      "max |Δp| [m], max |Δv| after the transient [m/s]):", "",
                  "| case | PD Δp | PD Δv | ARX-IMC Δp | ARX-IMC Δv | neural Δp | neural Δv | "
                  "ARX-IMC, neural |", "|---|---|---|---|---|---|---|---|", *case_rows]
    text = "\n".join(lines)
    written = []
    if args.plot:
        from jointplay.neural.control_plots import plot_comparison

        written += [str(p) for p in plot_comparison(comparison, scene, Path(args.plot))]
        atomic_write_text(Path(args.plot) / "control.md", text.strip() + "\n")
        written.append(str(Path(args.plot) / "control.md"))
    if args.out:
        write_runs(Path(args.out), comparison,
                   {"settings": asdict(settings), "scene": scene.name,
                    "per_call_us": comparison.per_call_us,
                    "nominal_radius": comparison.nominal_radius,
                    "network_checksum": narx.checksum(), "arx_checksum": arx.checksum()})
        written.append(args.out)
    if not quiet:
        print(text)
        for path in written:
            print(f"wrote {path}")
    for text in warnings:
        print(f"jointplay: warning: {text}", file=sys.stderr)
    return EXIT_DIVERGED if diverged else 0


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``control`` to a ``jointplay`` argument parser's subcommands."""
    d = ControllerSettings()
    p = subparsers.add_parser(
        "control", help="closed-loop runs of the internal-model controllers and baselines "
                        "against the ideal robot's motion",
        description="Track the ideal-joint robot's motion with the clearance robot: open loop, "
                    "PD, computed torque (ideal model), internal-model control with the linear "
                    "ARX twin, and with the guarded NARX network (compiled), side by side. "
                    "Exit status 3 when an internal-model controller diverged.")
    p.add_argument("scene", nargs="?", help="scene file (TOML); default: the paper scene")
    p.add_argument("--model", required=True, metavar="MODEL_DIR",
                   help="folder written by `jointplay identify`")
    p.add_argument("--plot", metavar="DIR", help="write figures and the table (control.md) here")
    p.add_argument("--out", metavar="RUN.h5", help="write every run and the metrics (HDF5)")
    add_settings_arguments(p, d)
    p.add_argument("--pd-kp", help="PD baseline stiffness per driven joint, N m/rad (default: "
                                   "the inner loop's)")
    p.add_argument("--pd-kd", help="PD baseline damping per driven joint, N m s/rad (default: "
                                   "the inner loop's)")
    p.add_argument("--ct-omega", type=float, default=15.0,
                   help="computed-torque baseline bandwidth, rad/s (default %(default)s)")
    p.add_argument("--ct-zeta", type=float, default=0.2,
                   help="computed-torque baseline damping ratio (default %(default)s)")
    p.add_argument("--transient", type=float, default=DEFAULT_TRANSIENT,
                   help="seconds at the start reported separately (journals settling; "
                        "default %(default)s)")
    p.add_argument("--divergence-factor", type=float, default=DIVERGENCE_FACTOR,
                   help="a run whose tip error exceeds this x the open loop's largest is "
                        "stopped as diverged (default %(default)s)")
    p.add_argument("--test-cases", action="store_true",
                   help="also run PD and both internal-model controllers on the model's stored "
                        "test excitations")
    p.add_argument("--quiet", action="store_true", help="no progress, no report")
    p.set_defaults(func=cmd_control)
    return p


def add_settings_arguments(p: argparse.ArgumentParser, d: ControllerSettings) -> None:
    """The controller's tuning flags (shared with the study command)."""
    p.add_argument("--horizon", type=int, default=d.horizon,
                   help="samples ahead the prediction is matched (default %(default)s)")
    p.add_argument("--lambda", dest="lambda_", type=float, default=d.regularisation,
                   help="regularisation of the inverse (default %(default)s)")
    p.add_argument("--setpoint-filter", type=float, default=d.setpoint_filter,
                   help="a in y_d(k+1) = a y_d(k) + (1 - a) r(k+1) (default %(default)s)")
    p.add_argument("--mismatch-filter", type=float, default=d.mismatch_filter,
                   help="b of the first-order mismatch filter (default %(default)s)")
    p.add_argument("--iterations", type=int, default=d.iterations,
                   help="linearisations per step (default %(default)s: the AIMNC law)")
    p.add_argument("--track", help="outputs the controller matches, e.g. q2,q3 (default: the "
                                   "end effector's position and velocity along the axis the "
                                   "torques move it most, and the last joint's angle and "
                                   "speed)")
    p.add_argument("--scales", help="error of each tracked output that counts as 1 (default: "
                                    "its spread in the training data)")
    p.add_argument("--torque-limit", help="actuator limits per driven joint, N m (default: "
                                          "the model's)")
    p.add_argument("--rate-limit", help="limit on the outer loop's torque rate per driven "
                                        "joint, N m/s (default: 10 x the torque limit)")
    p.add_argument("--no-guard", action="store_true",
                   help="run the network without its trust region and fallback (to see what "
                        "the guard prevents; a diverging loop is still stopped and reported)")
    p.add_argument("--trust-input", type=float, default=d.trust_input,
                   help="|v| kept within this x the largest |v| in training (default "
                        "%(default)s)")
    p.add_argument("--trust-range", type=float, default=d.trust_range,
                   help="the internal model's regressor and prediction must stay in the "
                        "training range widened by this x its width (default %(default)s)")
    p.add_argument("--trust-mismatch", type=float, default=d.trust_mismatch,
                   help="largest scaled mismatch on a tracked output before the network is "
                        "distrusted (default %(default)s)")
    p.add_argument("--engage", type=float, default=None,
                   help="seconds the outer loop waits at the start, the inner PD alone, before "
                        "it starts its models from the measured history (default: twice the "
                        "start-up the model's training runs left out, 0.1 s)")
    p.add_argument("--fallback-hold", type=int, default=d.fallback_hold,
                   help="samples on the fallback after a first intervention, doubling with "
                        "each further one (default %(default)s)")


__all__ = ["CONTROLLERS", "DEFAULT_TRANSIENT", "DIVERGENCE_FACTOR", "FLAGS", "GUARD_METRICS",
           "LINEAR", "MARGINAL", "METRICS", "MODEL_BASED", "NEURAL", "Comparison", "Controller",
           "ControllerSettings", "Law", "LoopConditions", "Run", "add_settings_arguments",
           "build_step", "compare", "compile_controller", "computed_torque_law",
           "default_tracked", "dense_acceleration_error", "generate_c", "horizon_gain",
           "imc_law", "load_twin", "local_spectral_radii", "metrics_table",
           "nominal_spectral_radius", "pd_law", "per_call_us", "register", "resolve_settings",
           "run_loop", "run_metrics", "settings_from_args", "stability_radii",
           "test_case_scenes", "tip_errors", "verdict", "write_runs"]
