"""Statistics, not one run: the controllers over training seeds, trajectories and clearances.

``jointplay control-study`` identifies a model per seed (and per clearance size), then runs the
baselines once per case and both internal-model controllers once per case and seed. A case is
a trajectory and what the loop is exposed to:

- ``scene``: the scene's torques;
- ``slow``, ``fast``: other frequencies and amplitudes (0.5 Hz at 1.25x, 2 Hz at 0.5x);
- ``offset``: two harmonics and a constant offset;
- ``disturbance``: the scene, and a torque step on the plant at 1 s that no model knows;
- ``noise``: the scene, with white noise on every signal the controllers measure;
- ``delay``: the scene, with one sample of actuator delay;
- ``clearance <c>``: the scene's trajectory on a robot whose clearance joints have radial
  clearance c, with models identified on that robot.

It reports the median and the worst seed of every metric per controller and case
(``study.md``, ``study.csv``), checks the goals, and plots the statistics (``study_*.png``).
Model folders are kept under ``OUT/models`` and reused when the command is run again; runs go
through a process pool (``--workers``).
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import os
import time
from pathlib import Path
from typing import Any

from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_write_text
from jointplay.neural.control import (
    MODEL_BASED,
    ControllerSettings,
    add_settings_arguments,
    load_twin,
    settings_from_args,
)
from jointplay.neural.narx import load_narx
from jointplay.neural.study_cases import (
    CASES,
    NOISE,
    Case,
    case_list,
    case_scene,
    noise_levels,
    nominal_clearance,
)
from jointplay.neural.study_report import PAPER, goal_checks, plot_study, summarise, summary_table
from jointplay.neural.study_runs import (
    _JOBS,
    BASELINES,
    GOAL_METRICS,
    REPORTED,
    _pool_map,
    ensure_models,
)


def cmd_study(args: argparse.Namespace) -> int:
    from jointplay.neural.identify import _floats, _ints, _load_scene_arg

    scene = _load_scene_arg(args.scene, args.quiet)
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise DescriptionError("--out", f"{out} exists and is not a folder")
    if args.seeds < 1:
        raise DescriptionError("--seeds", f"must be at least 1, got {args.seeds}")
    names = tuple(c.strip() for c in args.cases.split(",") if c.strip())
    unknown = [c for c in names if c not in CASES]
    if unknown or not names:
        raise DescriptionError("--cases", f"unknown case(s) {unknown}; choose from "
                               f"{', '.join(CASES)}")
    nominal = nominal_clearance(scene)
    clearances = _floats(args.clearances, "--clearances") if args.clearances else ()
    counts = _ints(f"{args.train},{args.validation},{args.test}", "--train/--validation/--test")
    iters = _ints(args.identify_iterations, "--identify-iterations", 2, low=0)
    identify_args = {"n_train": counts[0], "n_validation": counts[1], "n_test": counts[2],
                     "duration": args.duration, "one_step_iterations": iters[0],
                     "multi_step_iterations": iters[1]}
    cases = case_list(scene, names, clearances, nominal)
    scenes = {c.name: case_scene(scene, c) for c in cases}
    out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    models: dict[float, list[Path]] = {}
    for size in sorted({c.clearance for c in cases}):
        n = args.seeds if math.isclose(size, nominal, rel_tol=1e-9) else min(
            args.seeds, args.clearance_seeds)
        robot_scene = scenes[next(k.name for k in cases if k.clearance == size)]
        models[size] = ensure_models(robot_scene, out / "models" / f"{size * 1e6:g}um", n,
                                     identify_args, args.quiet)
    if not models[nominal]:
        raise DescriptionError("--seeds", "no seed gave a usable model; see the reports in "
                               f"{out / 'models'}")
    # Checked against the first model; each model then fills the defaults (tracked outputs,
    # their scales) from its own training data.
    resolved = settings_from_args(args, load_narx(models[nominal][0]))
    settings = settings_from_args(args, None)
    # Compile every controller once, before the workers fork (they then load it from the
    # cache instead of compiling it twice at the same time).
    from jointplay.neural.imc import compile_controller

    for paths in models.values():
        for path in paths:
            narx = load_narx(path)
            arx = load_twin(path, narx)
            compile_controller(narx, settings, fallback=arx)
            compile_controller(arx, settings)
    _JOBS.clear()
    for c in cases:
        _JOBS.append((c, scenes[c.name], None, settings, None))
    base_rows = _pool_map(list(range(len(_JOBS))), args.workers, args.quiet, "baselines")
    rows = [r for rs in base_rows for r in rs]
    limits = {r["case"]: r["limit"] for r in rows if "limit" in r}
    start = len(_JOBS)
    for c in cases:
        for path in models[c.clearance]:
            _JOBS.append((c, scenes[c.name], path, settings, limits[c.name]))
    model_rows = _pool_map(list(range(start, len(_JOBS))), args.workers, args.quiet,
                           "internal-model runs")
    rows += [r for rs in model_rows for r in rs]
    summary = summarise(rows)
    checks = goal_checks(summary, cases)
    buf = io.StringIO()
    fields = ["case", "clearance_um", "controller", "seed", *REPORTED]
    writer = csv.DictWriter(buf, fieldnames=fields, extrasaction="ignore")
    writer.writeheader()
    writer.writerows(rows)
    atomic_write_text(out / "study.csv", buf.getvalue())
    text = "\n".join([
        f"# Controller study: {scene.name}",
        "",
        f"{args.seeds} training seeds at {nominal * 1e6:g} µm ("
        f"{', '.join(f'{size * 1e6:g} µm: {len(p)}' for size, p in models.items())} usable "
        "models); "
        f"cases: {', '.join(c.name for c in cases)}; controller settings: horizon "
        f"{resolved.horizon}, guard {'on' if resolved.guard else 'OFF'}. Baselines run once per "
        "case (they do not depend on the seed). Worst = the largest value over the seeds.",
        "",
        summary_table(summary, cases),
        "",
        "Goals:",
        "",
        *checks,
        "",
        f"Wall time {time.perf_counter() - started:.0f} s.",
    ])
    atomic_write_text(out / "study.md", text + "\n")
    atomic_write_text(out / "study.json", json.dumps(
        {"rows": rows, "summary": {f"{k[0]} / {k[1]}": v for k, v in summary.items()}},
        indent=1, default=float) + "\n")
    written = [out / "study.md", out / "study.csv", out / "study.json",
               *plot_study(rows, cases, out)]
    if not args.quiet:
        print(text)
        for path in written:
            print(f"wrote {path}")
    diverged = any(r["diverged"] > 0 for r in rows if r["controller"] in MODEL_BASED)
    return 3 if diverged else 0


def register(subparsers: Any) -> argparse.ArgumentParser:
    p = subparsers.add_parser(
        "control-study", help="the controllers over training seeds, trajectories and "
                              "clearances: median and worst case",
        description="Identify a model per seed (and per clearance), run every controller on "
                    "several trajectories and loop conditions, report the median and the worst "
                    "seed per controller, check the goals and plot. Exit status 3 when an "
                    "internal-model run diverged.")
    p.add_argument("scene", nargs="?", help="scene file (TOML); default: the paper scene")
    p.add_argument("--out", required=True, metavar="DIR",
                   help="folder for models/, study.md, study.csv, study.json and the plots")
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
    p.add_argument("--train", type=int, default=12, help="identify: training runs (default 12)")
    p.add_argument("--validation", type=int, default=3, help="identify: validation runs "
                                                               "(default 3)")
    p.add_argument("--test", type=int, default=3, help="identify: test runs (default 3)")
    p.add_argument("--duration", type=float, default=2.0,
                   help="identify: seconds per run (default 2)")
    p.add_argument("--identify-iterations", default="60,30",
                   help="identify: L-BFGS iterations (default 60,30)")
    add_settings_arguments(p, ControllerSettings())
    p.add_argument("--quiet", action="store_true", help="no progress, no report")
    p.set_defaults(func=cmd_study)
    return p


__all__ = ["BASELINES", "CASES", "GOAL_METRICS", "NOISE", "PAPER", "REPORTED", "Case",
           "case_list", "case_scene", "cmd_study", "ensure_models", "goal_checks",
           "noise_levels", "nominal_clearance", "plot_study", "register", "summarise",
           "summary_table"]
