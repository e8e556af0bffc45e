"""Mechanism calibration on data from an outside simulator: the slider-crank over a revolution.

    python benchmarks/mechanism_calibration.py --out DIR [--seeds 5] [--quick]
        [--truths C:MU,...] [--first-seed N]

The measured motion is Exudyn's (``tests/exudyn_slider_crank.py``: its own equations and
contact law, none of jointplay's model code; it agrees with ``jointplay simulate`` at the
same values to 7e-9 m over the revolution): the 0.1 mm slider-crank with friction
(``scenes/slider_crank_friction.toml`` with a 10.1 mm bearing), 12 ms at 10 µs, the slider's
position and the journal's eccentricity, plus Gaussian noise of 1 µm per seed. Each truth
(clearance and mu within ±50 % of the scene's 0.1 mm and 0.01) is calibrated from the scene's
values by ``jointplay.calibrate`` with its defaults, the noise stated and estimated from the
data's scatter. Writes DIR/mechanism_calibration.md and .csv: per truth and noise mode, the
intervals holding the truth, the parameters reported determined (and how many of those miss
the truth), the worst determined error, chi²/dof, the runs' model error (chi² between runs at
the fit's tolerances and 10 times looser, at the estimate), wall and CPU seconds.
"""

from __future__ import annotations

import argparse
import csv
import io
import math
import os
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

import jointplay as jp

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from exudyn_slider_crank import SliderCrank, simulate
from slider_crank_ladder import write_outputs

SCENE = Path(__file__).resolve().parents[1] / "scenes" / "slider_crank_friction.toml"
BEARING = 10.1e-3
NOISE = 1e-6
NAMES = ("slider_pin.clearance", "friction.mu")
COLUMNS = ("guide.position", "slider_pin.ex", "slider_pin.ey")
# (clearance m, mu): the example of docs/reference/mechanism-file.md first, then four more
# within ±50 % of the scene's values, one of them (0.14 mm, 0.018) a motion the runs cannot
# resolve to the noise over a revolution.
TRUTHS = ((1.02e-4, 0.013), (0.6e-4, 0.006), (1.4e-4, 0.018), (0.55e-4, 0.0145),
          (1.45e-4, 0.0055))


def exudyn_record(clearance: float, mu: float, times: np.ndarray) -> np.ndarray:
    """Exudyn's slider position and orbit (journal - bearing) at ``times``: (n, 3)."""
    run = simulate(SliderCrank(bearing_radius=BEARING, journal_radius=BEARING - clearance,
                               mu=mu), float(times[-1]))
    out = run.at(times)
    return np.column_stack([out["slider_position"], out["orbit"]])


def calibrate_once(scene_path: Path, times: np.ndarray, exact: np.ndarray, seed: int,
                   stated: bool, folder: Path) -> Any:
    noisy = exact + NOISE * np.random.default_rng(seed).standard_normal(exact.shape)
    table = folder / f"measured_{seed}.csv"
    np.savetxt(table, np.column_stack([times, noisy]), delimiter=",", comments="",
               header="time," + ",".join(COLUMNS), fmt="%.17g")
    scene = jp.load_mechanism_scene(scene_path)
    return jp.calibrate(scene, table, list(NAMES), noise=NOISE if stated else None)


def summary_row(truth: tuple[float, float], stated: bool, rows: list[dict[str, Any]]
                ) -> dict[str, Any]:
    holds = sum(r[f"{n} holds"] for r in rows for n in NAMES)
    determined = [(r[f"{n} error %"], r[f"{n} holds"]) for r in rows for n in NAMES
                  if r[f"{n} determined"]]
    errors = [abs(e) for e, _ in determined]
    return {
        "clearance mm": f"{truth[0] * 1e3:g}", "mu": f"{truth[1]:g}",
        "noise": "stated" if stated else "estimated",
        "intervals holding the truth": f"{holds} of {len(rows) * len(NAMES)}",
        "determined (truth outside)": f"{len(determined)} ({sum(not h for _, h in determined)})",
        "worst determined error %": f"{max(errors):.3f}" if errors else "-",
        "chi²/dof (median)": f"{statistics.median(r['chi2/dof'] for r in rows):.3g}",
        "model error chi² (median)":
            f"{statistics.median(r['model error chi2'] for r in rows):.2g}",
        "wall s (median)": f"{statistics.median(r['wall s'] for r in rows):.1f}",
        "wall s (worst)": f"{max(r['wall s'] for r in rows):.1f}",
        "CPU s (median)": f"{statistics.median(r['CPU s'] for r in rows):.1f}",
    }


def markdown(rows: list[dict[str, Any]]) -> str:
    keys = list(rows[0])
    lines = ["| " + " | ".join(keys) + " |", "|" + "---|" * len(keys)]
    lines += ["| " + " | ".join(str(r[k]) for k in keys) + " |" for r in rows]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--seeds", type=int, default=5, help="noise seeds per truth")
    parser.add_argument("--quick", action="store_true",
                        help="the first truth only, noise stated (a check of the script)")
    parser.add_argument("--truths", metavar="C:MU,...",
                        help="other truths (clearance m, mu), e.g. 8e-5:0.009 (held-out cases)")
    parser.add_argument("--first-seed", type=int, default=0, help="the first noise seed")
    args = parser.parse_args(argv)
    if args.seeds < 1:
        parser.error("--seeds must be >= 1")
    truths = TRUTHS[:1] if args.quick else TRUTHS
    if args.truths:
        truths = tuple((float(c), float(mu)) for c, mu in
                       (pair.split(":") for pair in args.truths.split(",")))
    modes = (True,) if args.quick else (True, False)
    text = SCENE.read_text(encoding="utf-8").replace("bearing_radius = 10.5e-3",
                                                     f"bearing_radius = {BEARING!r}")
    detail: list[dict[str, Any]] = []
    summary: list[dict[str, Any]] = []
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        scene_path = folder / "slider_crank_0_1mm_friction.toml"
        scene_path.write_text(text, encoding="utf-8")
        run = jp.load_mechanism_scene(scene_path).run
        times = np.arange(round(run.t_end / run.output_step) + 1) * run.output_step
        for truth in truths:
            exact = exudyn_record(*truth, times)
            for stated in modes:
                rows = []
                for seed in range(args.first_seed, args.first_seed + args.seeds):
                    wall = time.perf_counter()
                    result = calibrate_once(scene_path, times, exact, seed, stated, folder)
                    row: dict[str, Any] = {"clearance": truth[0], "mu": truth[1],
                                           "noise": "stated" if stated else "estimated",
                                           "seed": seed}
                    for name, value in zip(NAMES, truth, strict=True):
                        e = result.estimates[name]
                        row[f"{name} error %"] = 100.0 * (e.value - value) / value
                        row[f"{name} holds"] = bool(e.low95 <= value <= e.high95)
                        row[f"{name} determined"] = bool(e.determined)
                    error = result.residuals.get("model_error_chi2")
                    row.update({"chi2/dof": result.residuals["normalised_chi2"],
                                "model error chi2": math.inf if error is None else error,
                                "runs": result.simulations,
                                "wall s": time.perf_counter() - wall,
                                "CPU s": result.cpu_time_s})
                    rows.append(row)
                    print(f"{truth} {row['noise']} seed {seed}: " + ", ".join(
                        f"{n} {row[f'{n} error %']:+.3f} % "
                        f"{'held' if row[f'{n} holds'] else 'MISSED'} "
                        f"{'determined' if row[f'{n} determined'] else 'not determined'}"
                        for n in NAMES) + f", {row['wall s']:.1f} s", flush=True)
                detail += rows
                summary.append(summary_row(truth, stated, rows))
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(detail[0]))
    writer.writeheader()
    writer.writerows(detail)
    report = "\n".join([
        "# Mechanism calibration on Exudyn's slider-crank",
        "",
        f"Command: `python benchmarks/mechanism_calibration.py {' '.join(sys.argv[1:])}`",
        "",
        f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"load average {', '.join(f'{v:.2f}' for v in os.getloadavg())}; jointplay "
        f"{jp.__version__}.",
        "",
        markdown(summary), ""])
    write_outputs(args.out, {"mechanism_calibration.md": report,
                             "mechanism_calibration.csv": buffer.getvalue()})
    print(report)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
