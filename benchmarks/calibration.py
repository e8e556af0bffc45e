"""Calibration benchmarks: the cases made by an independent simulator, and the paper scene's draws.

    python benchmarks/calibration.py --cases [NAME ...] --seeds 5 --out out/calibration-cases
    python benchmarks/calibration.py --out out/calibration [--draws 3] [--seeds 20]

With ``--cases`` (no names: every case), each case of benchmarks/calibration_cases/ (made by
its own simulator, reference.py, which shares no code with jointplay's model) is calibrated
with ``--seeds`` noise seeds by running ``jointplay calibrate`` as a user would, and one table
is written: OUT/cases.md, OUT/cases.csv, OUT/cases.json (see
benchmarks/calibration_cases/runner.py and README.md there).

Without ``--cases``, the paper scene's draws, as follows.

Measurements: 2 s of tip position at 1 ms made by the paper scene with joint 2's and joint
3's radial clearances and the journal friction drawn up to 50 % away from the scene's
values (uniform, seeded), at tolerances 1e4 tighter than the scene's (the fit runs at 1e3
tighter), with 1 µm of Gaussian noise on each coordinate. Two parts:

- recovery: for each draw, ``jointplay.calibrate`` from the scene's values with its default
  options (the global stage: friction first over the whole record, a 16 x 16 grid of the
  clearances on 20 ms, its minima carried as tracks through windows of 20 ms to 1.28 s with
  lines across c2 - c3 from 0.32 s on, each window at the loosest tolerances that keep its
  runs within the noise; the valley and basin checks; two worker processes): the relative
  error of each estimate,
  whether its 95 % interval holds the truth, chi²/dof, runs, wall and CPU seconds;
- coverage: the first draw's truth measured with ``--seeds`` noise seeds, each fit started at
  the truth (one local fit on the whole record, no continuation: the global search is the
  recovery part's), counting the seeds
  whose 95 % interval holds the truth, and the reported std against the estimates' spread.

Writes OUT/recovery.csv, OUT/coverage.csv and OUT/calibration.md (with the machine, its load
average and the package versions). Times: wall (``time.perf_counter``) and CPU
(``time.process_time``) of each calibration. Wall times depend on the machine as much as on
the code (two 2-core machines here differed 1.9x per run), so the summary also gives the
machine's *reference run*, the fastest of 7 plain runs of the paper scene over the whole
record at the fit's tolerances (the fastest: the one least disturbed by whatever else the
machine does), measured before the calibrations and again after them, and each
calibration's wall time in such runs (the one before).
"""

from __future__ import annotations

import argparse
import csv
import os
import platform
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

import jointplay as jp
from jointplay.calibration import CalibrationOptions, Measured, calibrate
from jointplay.calibration.parameters import scene_value

NAMES = ("joint2.clearance", "joint3.clearance", "friction.mu")
REFERENCE_RUNS = 7
NOISE = 1e-6
TRUTH_TIGHTEN = 1e4


def synthetic(scene: jp.Scene, model: Any, truth: dict[str, float], seed: int) -> Measured:
    exact = jp.simulate(scene.with_run(rtol=scene.run.rtol / TRUTH_TIGHTEN,
                                       atol=scene.run.atol / TRUTH_TIGHTEN),
                        model=model, parameters=truth)
    rng = np.random.default_rng(seed)
    tip = exact.tip_position + NOISE * rng.standard_normal(exact.tip_position.shape)
    return Measured(f"synthetic seed {seed}", exact.t.copy(), ("tip_x", "tip_y"), tip)


def reference_run_s(scene: jp.Scene, model: Any) -> float:
    """The machine's reference run (s): the fastest of REFERENCE_RUNS plain runs of
    ``scene`` over the whole record at the fit's tolerances (the default ``tighten``)."""
    tighten = CalibrationOptions().tighten
    fit_scene = scene.with_run(rtol=scene.run.rtol / tighten, atol=scene.run.atol / tighten)
    times = []
    for _ in range(REFERENCE_RUNS):
        start = time.perf_counter()
        jp.simulate(fit_scene, model=model)
        times.append(time.perf_counter() - start)
    return min(times)


def draw_truth(scene: jp.Scene, rng: np.random.Generator) -> dict[str, float]:
    return {n: scene_value(n, scene) * (1 + rng.uniform(-0.5, 0.5)) for n in NAMES}


def recovery(scene: jp.Scene, model: Any, draws: int, first: int = 0
             ) -> list[dict[str, Any]]:
    rows = []
    rng = np.random.default_rng(2026)
    for draw in range(draws):
        truth = draw_truth(scene, rng)
        if draw < first:
            continue
        measured = synthetic(scene, model, truth, seed=draw)
        result = calibrate(scene, measured, list(NAMES), noise=NOISE, model=model,
                           options=CalibrationOptions())
        row: dict[str, Any] = {"draw": draw}
        for name in NAMES:
            e = result.estimates[name]
            row[f"{name} truth"] = truth[name]
            row[f"{name} estimate"] = e.value
            row[f"{name} rel error"] = (e.value - truth[name]) / truth[name]
            row[f"{name} covered"] = bool(e.low95 <= truth[name] <= e.high95)
            row[f"{name} determined"] = e.determined
        row.update(chi2_dof=result.residuals["normalised_chi2"], runs=result.simulations,
                   window_runs=result.simulations_by_kind.get("continuation windows", 0),
                   stages=len(result.stages), local_fits=len(result.starts),
                   wall_s=result.wall_time_s, cpu_s=result.cpu_time_s,
                   warnings=len(result.warnings))
        print(row, flush=True)
        rows.append(row)
    return rows


def coverage(scene: jp.Scene, model: Any, seeds: int) -> list[dict[str, Any]]:
    truth = draw_truth(scene, np.random.default_rng(2026))
    options = CalibrationOptions(starts=1, scan_points=0, profile_points=0, horizon_first=0)
    rows = []
    for seed in range(seeds):
        measured = synthetic(scene, model, truth, seed=1000 + seed)
        result = calibrate(scene, measured, list(NAMES), noise=NOISE, start=truth,
                           model=model, options=options)
        row: dict[str, Any] = {"seed": 1000 + seed}
        for name in NAMES:
            e = result.estimates[name]
            row[f"{name} estimate"] = e.value
            row[f"{name} std"] = e.std
            row[f"{name} covered"] = bool(e.low95 <= truth[name] <= e.high95)
        row.update(truth=truth, chi2_dof=result.residuals["normalised_chi2"],
                   runs=result.simulations, wall_s=result.wall_time_s, cpu_s=result.cpu_time_s)
        print(row, flush=True)
        rows.append(row)
    return rows


def _write_csv(path: Path, rows: list[dict[str, Any]]) -> None:
    with open(path, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def _median_worst(values: list[float]) -> str:
    return f"{np.median(values):.3g} / {np.max(values):.3g}"


def summary(rec: list[dict[str, Any]], cov: list[dict[str, Any]], command: str,
            reference_s: tuple[float, float]) -> str:
    import casadi
    import scipy

    lines = ["# Calibration benchmark", "", "```sh", command, "```", "",
             f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
             f"load average {', '.join(f'{v:.2f}' for v in os.getloadavg())}; jointplay "
             f"{jp.__version__}, SciPy {scipy.__version__}, CasADi {casadi.__version__}, "
             f"NumPy {np.__version__}. Reference run (one plain run of the whole record at "
             f"the fit's tolerances, the fastest of {REFERENCE_RUNS}): "
             f"{1e3 * reference_s[0]:.1f} ms before the calibrations, "
             f"{1e3 * reference_s[1]:.1f} ms after.", ""]
    if rec:
        lines += ["## Recovery from the scene's values", "",
                  "| draw | " + " | ".join(f"{n} truth → rel. error (covered, verdict)"
                                           for n in NAMES)
                  + " | chi²/dof | runs | wall s | wall in reference runs | CPU s |",
                  "|---" * (len(NAMES) + 6) + "|"]
        for r in rec:
            cells = [f"{r[f'{n} truth']:.4g} → {r[f'{n} rel error']:+.2e} "
                     f"({'yes' if r[f'{n} covered'] else 'no'}, "
                     f"{'determined' if r[f'{n} determined'] else 'not determined'})"
                     for n in NAMES]
            lines.append(f"| {r['draw']} | " + " | ".join(cells)
                         + f" | {r['chi2_dof']:.3g} | {r['runs']} | {r['wall_s']:.1f} | "
                         f"{r['wall_s'] / reference_s[0]:.0f} | {r['cpu_s']:.1f} |")
        lines += ["", "Median / worst: wall " + _median_worst([r["wall_s"] for r in rec])
                  + " s, CPU " + _median_worst([r["cpu_s"] for r in rec]) + " s, runs "
                  + _median_worst([r["runs"] for r in rec]) + "; |rel. error| "
                  + ", ".join(f"{n} " + _median_worst([abs(r[f'{n} rel error']) for r in rec])
                              for n in NAMES) + ".", "",
                  f"Intervals holding the truth: {_count(rec, 'covered')} of "
                  f"{len(rec) * len(NAMES)}; reported determined but missing it: "
                  f"{_count(rec, 'determined', 'covered')}.", ""]
    if cov:
        lines += ["## Coverage of the 95 % intervals (fits started at the truth)", "",
                  "| parameter | covered | median reported std | spread of estimates |",
                  "|---|---|---|---|"]
        for n in NAMES:
            est = [r[f"{n} estimate"] for r in cov]
            lines.append(f"| {n} | {sum(r[f'{n} covered'] for r in cov)} / {len(cov)} | "
                         f"{np.median([r[f'{n} std'] for r in cov]):.3g} | "
                         f"{np.std(est, ddof=1):.3g} |")
        lines += ["", "chi²/dof median / worst " + _median_worst([r["chi2_dof"] for r in cov])
                  + "; CPU s " + _median_worst([r["cpu_s"] for r in cov]) + ".", ""]
    return "\n".join(lines)


def _count(rows: list[dict[str, Any]], key: str, unless: str | None = None) -> int:
    """How many (row, parameter) have ``key`` true (and ``unless`` false, when given)."""
    return sum(bool(r[f"{n} {key}"]) and not (unless and r[f"{n} {unless}"])
               for r in rows for n in NAMES)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="folder for the CSV and Markdown")
    parser.add_argument("--cases", nargs="*", metavar="NAME",
                        help="run the benchmark cases (no names: all of them) instead of the "
                             "paper scene's draws")
    parser.add_argument("--draws", type=int, default=3, help="truths drawn for recovery")
    parser.add_argument("--seeds", type=int, default=None,
                        help="noise seeds: per case with --cases (default 5), else for the "
                             "coverage part (default 20)")
    parser.add_argument("--first-seed", type=int, default=0,
                        help="with --cases: the first noise seed")
    parser.add_argument("--timeout", type=float, default=1800.0,
                        help="with --cases: seconds one calibration may take before it is "
                             "stopped and reported as timed out")
    parser.add_argument("--resume", action="store_true",
                        help="with --cases: keep the runs an earlier call into the same --out "
                             "finished (their rows, times included) and run the rest")
    parser.add_argument("--first-draw", type=int, default=0,
                        help="skip the draws before this one (their truths are still drawn, "
                             "so draw N is the same truth in every run)")
    args = parser.parse_args()
    out = Path(args.out)
    if args.cases is not None:
        run_cases(args, out)
        return
    if args.seeds is None:
        args.seeds = 20
    out.mkdir(parents=True, exist_ok=True)
    scene = jp.default_scene()
    model = jp.load_scene_model(scene)
    before = reference_run_s(scene, model)
    start = time.perf_counter()
    cov = coverage(scene, model, args.seeds) if args.seeds else []
    if cov:
        _write_csv(out / "coverage.csv", cov)
    rec = recovery(scene, model, args.draws, args.first_draw) if args.draws else []
    if rec:
        _write_csv(out / "recovery.csv", rec)
    command = (f"python benchmarks/calibration.py --out {args.out} --draws {args.draws} "
               f"--seeds {args.seeds}"
               + (f" --first-draw {args.first_draw}" if args.first_draw else ""))
    total = time.perf_counter() - start
    reference_s = (before, reference_run_s(scene, model))
    (out / "calibration.md").write_text(summary(rec, cov, command, reference_s))
    print(summary(rec, cov, command, reference_s))
    print(f"total {total:.0f} s wall")


def run_cases(args: argparse.Namespace, out: Path) -> None:
    sys.path.insert(0, str(Path(__file__).resolve().parent / "calibration_cases"))
    from runner import run  # the cases' runner, beside their data

    seeds = 5 if args.seeds is None else args.seeds
    command = ("python benchmarks/calibration.py --cases " + " ".join(args.cases)
               + f" --seeds {seeds}" + (f" --first-seed {args.first_seed}" if args.first_seed
                                        else "") + (" --resume" if args.resume else "")
               + f" --out {args.out}")
    run(list(args.cases), seeds, args.first_seed, out, args.timeout, command.replace("  ", " "),
        resume=args.resume)


if __name__ == "__main__":
    main()
