"""``jointplay simulate`` (and ``inspect``) on a mechanism file (a scene with a
``[mechanism]`` table): the same command, the mechanism's model and outputs."""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.cli.summary import divided_steps_lines
from jointplay.common.errors import DescriptionError

# Flags of ``simulate`` that mechanism runs do not take, and why.
_UNSUPPORTED = {
    "plausibility": "mechanism runs stop on a failed step; they have no plausibility setting",
}
_RUN_SETTINGS = ("rtol", "atol", "t_end", "output_step", "max_steps", "step")


def refuse_unsupported(args: argparse.Namespace) -> None:
    for flag, why in _UNSUPPORTED.items():
        if getattr(args, flag, None) not in (None, False):
            raise DescriptionError(f"--{flag.replace('_', '-')}", f"{why}; drop the flag")


def scene_with_overrides(args: argparse.Namespace) -> Any:
    from jointplay.mechanism.description import INTEGRATORS
    from jointplay.mechanism.reading import load_mechanism_scene

    scene = load_mechanism_scene(args.scene)
    changes: dict[str, Any] = {
        k: v for k, v in (("rtol", args.rtol), ("atol", args.atol), ("t_end", args.t_end),
                          ("output_step", args.output_step),
                          ("step", getattr(args, "step", None))) if v is not None}
    integrator = getattr(args, "integrator", None)
    values: dict[str, float] = {}
    for item in getattr(args, "set", None) or []:
        name, sep, value = item.partition("=")
        name = name.strip()
        if name == "run.integrator":
            integrator = value.strip()
            continue
        try:
            number = float(value)
        except ValueError:
            raise DescriptionError(f"--set {name}", f"must be a number, got {value!r}") from None
        if not sep or not name or not np.isfinite(number):
            raise DescriptionError("--set", f"expects NAME=VALUE with a finite number, got "
                                   f"{item!r}")
        if name.startswith("run."):
            changes[name.removeprefix("run.")] = number
        else:
            values[name] = number
    for key, value in changes.items():
        if key not in _RUN_SETTINGS:
            raise DescriptionError(f"--set run.{key}", "is not a run setting of a mechanism "
                                   "(run.t_end, run.output_step, run.rtol, run.atol, "
                                   "run.max_steps, run.integrator, run.step)")
        if not value > 0:
            raise DescriptionError(f"run.{key}", f"must be > 0, got {value!r}")
    if integrator is not None:
        if integrator not in INTEGRATORS:
            raise DescriptionError("--integrator", f"a mechanism runs with "
                                   f"{', '.join(INTEGRATORS)}, got {integrator!r}")
        changes["integrator"] = integrator
    if changes:
        scene = scene.with_run(**{k: int(v) if k == "max_steps" else v
                                  for k, v in changes.items()})
    if values:
        try:
            scene = scene.with_mechanism(scene.mechanism.with_values(values))
        except DescriptionError as err:
            raise DescriptionError(f"--set {err.field}", err.message) from None
    return scene


def cmd_simulate_mechanism(args: argparse.Namespace) -> int:
    from jointplay.common.files import OutputPlan, all_or_nothing, make_folder
    from jointplay.mechanism.accuracy import with_accuracy
    from jointplay.mechanism.model import model_for
    from jointplay.mechanism.simulate import simulate_mechanism

    refuse_unsupported(args)
    scene = scene_with_overrides(args)
    plan = OutputPlan()
    plan.input("scene", args.scene)
    if args.csv:
        plan.file("--csv", args.csv)
    if args.out:
        plan.file("--out", args.out)
    if args.plot:
        plan.folder("--plot", args.plot, "its figures", pattern="*.png")
    if args.animate:
        from jointplay.results.animate import check_animation_path

        plan.file("--animate", args.animate)
        check_animation_path(args.animate)
    plan.check()
    quiet = args.quiet
    t0 = time.perf_counter()
    model = model_for(scene.mechanism)
    if not quiet:
        print(f"scene {scene.name}: mechanism model ready in {time.perf_counter() - t0:.2f} s "
              f"({', '.join(model.coordinates)})")
    result = simulate_mechanism(scene, model=model, compare_ideal=args.compare_ideal)
    if args.verify is not False:
        from jointplay.cli.simulate import CHECK_COST_RATIO, VERIFY_BUDGET_S
        from jointplay.results.accuracy import TIGHTER

        # At a fixed step the check takes ten times the steps: it costs ten times the run.
        ratio = CHECK_COST_RATIO if scene.run.integrator == "bdf" else TIGHTER
        estimate = ratio * float(result.stats["wall_time_s"])
        if args.verify is None and estimate > VERIFY_BUDGET_S:
            if not quiet:
                tighter = ("tolerances 10x tighter" if scene.run.integrator == "bdf"
                           else "a step 10x shorter")
                print(f"accuracy not checked: the check (the same run at {tighter}) would "
                      f"take about {estimate:.0f} s; ask for it with --verify, or skip this "
                      "note with --no-verify")
        else:
            result = with_accuracy(result, scene, model)
    written: list[str] = []
    with all_or_nothing(plan):
        if args.out:
            from jointplay.mechanism.results import write_mechanism_result

            write_mechanism_result(result, args.out)
            written.append(args.out)
        if args.csv:
            write_csv(result, args.csv)
            written.append(args.csv)
        if args.plot:
            from jointplay.mechanism.plots import write_figures

            make_folder(args.plot, "--plot")
            written += [str(p) for p in write_figures(result, args.plot)]
        if args.animate:
            from jointplay.mechanism.animate import animate_mechanism

            written.append(str(animate_mechanism(scene, result, args.animate, quiet=quiet,
                                                 model=model)))
    if not quiet:
        for line in summary_lines(result):
            print(line)
        for path in written:
            print(f"wrote {path}")
    return 0


def summary_lines(result: Any) -> list[str]:
    """What a mechanism run found, in a few lines."""
    out = [f"{result.name}: {result.t[-1]:g} s simulated in {result.stats['wall_time_s']:.3f} s "
           f"({result.stats['steps']} steps, {len(result.impacts)} impacts)"]
    for j, joint in enumerate(result.cut_joints):
        rows = result.impacts.joint == j + 1
        if rows.any():
            force, at, located = result.largest_contact_force(j + 1)
            how = "located" if located else "on the samples: a fixed step locates no peaks"
            count = int(rows.sum())
            out.append(f"  {joint}: {count} impact{'' if count == 1 else 's'}, largest contact "
                       f"force {force:.4g} N at {at:.6g} s ({how}), largest eccentricity "
                       f"{np.max(np.hypot(*result.eccentricity[:, j].T)) * 1e3:.4g} mm "
                       f"(clearance {result.clearance[j] * 1e3:.4g} mm)")
    out += divided_steps_lines(result.stats)
    torque = result.driving_torque
    out.append(f"  driving torque from {torque.min():.4g} to {torque.max():.4g} N m (on the "
               "samples)")
    if result.ideal is not None:
        from jointplay.mechanism.output import followed

        # The output the file names (the slider, the rocker's angle...).
        name = followed(result.output, result.coordinates)
        k = result.coordinates.index(name)
        dev = np.max(np.abs(result.x[:, k] - result.ideal["x"][:, k]))
        shown = f"{dev * 1e3:.4g} mm" if result.units[k] == "m" else f"{dev:.4g} rad"
        out.append(f"  {name}: at most {shown} from the ideal mechanism's")
        out.append(f"  ideal driving torque from {result.ideal['driving_torque'].min():.4g} to "
                   f"{result.ideal['driving_torque'].max():.4g} N m (on the samples)")
    if result.accuracy is not None:
        out += result.accuracy.lines()
    return out


def write_csv(result: Any, path: str | Path) -> None:
    from jointplay.common.files import atomic_write_text

    n = len(result.coordinates)
    names = ["time"] + result.coordinates + [f"d/dt {c}" for c in result.coordinates] + \
        [f"d2/dt2 {c}" for c in result.coordinates] + ["driving_torque", "kinetic",
                                                        "potential", "contact_potential",
                                                        "drive_work", "dissipated"]
    columns = [result.t, *result.x[:, :2 * n].T, *result.acceleration.T, result.driving_torque,
               result.kinetic, result.potential, result.contact_potential, result.drive_work,
               result.dissipated]
    for j, joint in enumerate(result.cut_joints):
        names += [f"{joint}.ex", f"{joint}.ey", f"{joint}.normal_force"]
        columns += [result.eccentricity[:, j, 0], result.eccentricity[:, j, 1],
                    result.normal_force[:, j]]
    table = np.stack(columns, axis=1)
    lines = [",".join(names)] + [",".join(f"{v:.17g}" for v in row) for row in table]
    atomic_write_text(path, "\n".join(lines) + "\n")
