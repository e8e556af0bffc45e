"""Where a calibration's time goes: wall and CPU seconds of each stage of the search, per window.

    python benchmarks/calibration_time.py --case paper-multisine-b-tip --seed 4 [--out FILE.md]

Calibrates one case of benchmarks/calibration_cases/ (its noise drawn as
benchmarks/calibration.py draws it) in this process, from the scene's values with the default
options, timing each stage by wrapping the function that runs it: the friction fitted first
over the whole record, the grid, each window of the continuation (the choice of its
tolerances, its valley lines, its tracks' fits), the ranking on the whole record, the
whole-record fit, the basin and valley checks and the cost profiles. Then, per window, its
tracks, their least-squares evaluations and runs, and the share of the runs spent on tracks
whose chi² ended more than the continuation's margin above the window's best (fitted, then
dropped). Prints a Markdown table (and writes it to ``--out``). The wrapped functions run
unchanged, so the estimates are those of ``jointplay calibrate``; the worker processes are
forked and counted in the stages that start them.
"""

from __future__ import annotations

import argparse
import collections
import functools
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "calibration_cases"))

import runner  # noqa: E402

from jointplay.calibration import api, continuation, profiles  # noqa: E402
from jointplay.calibration.continuation import track_margin  # noqa: E402
from jointplay.calibration.fit import timed  # noqa: E402
from jointplay.common.files import atomic_write_text  # noqa: E402
from jointplay.scene import load_scene  # noqa: E402

SECONDS: dict[str, float] = collections.defaultdict(float)
CPU_SECONDS: dict[str, float] = collections.defaultdict(float)


def _timed(module: Any, name: str, label: Any) -> None:
    """Replace ``module.name`` by itself, adding its wall and CPU seconds (the workers'
    included) to ``label(*args)``."""
    original = getattr(module, name)

    @functools.wraps(original)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        wall0, cpu0 = timed()
        try:
            return original(*args, **kwargs)
        finally:
            wall1, cpu1 = timed()
            SECONDS[label(*args)] += wall1 - wall0
            CPU_SECONDS[label(*args)] += cpu1 - cpu0

    setattr(module, name, wrapper)


def _instrument() -> None:
    for name, label in (("others_first", "friction first (whole record)"),
                        ("grid_candidates", "grid"), ("_ranked", "tracks ranked on the record"),
                        ("least_squares_fit", "whole-record fit"),
                        ("neighbouring_basins", "basin check"), ("valley_check", "valley check")):
        _timed(api, name, lambda *_, label=label: label)
    _timed(continuation, "window_looseness",
           lambda predictor, weights, x, end, *_: f"window {end:.3g} s: tolerances")
    _timed(continuation, "_line_minima",
           lambda predictor, scene, part, *_: f"window {part.t[-1]:.3g} s: lines")
    _timed(continuation, "_window_fits",
           lambda predictor, scene, part, *_: f"window {part.t[-1]:.3g} s: fits")
    _timed(profiles, "cost_profiles", lambda *_: "cost profiles")


def _windows(stages: Any) -> list[str]:
    """Per window: tracks, evaluations, runs, and the runs of tracks it then dropped."""
    by_end: dict[float, list[Any]] = collections.defaultdict(list)
    for stage in stages:
        by_end[stage.window_end].append(stage)
    rows = []
    for end, mine in sorted(by_end.items())[:-1]:  # the last is the whole record's
        best = min(s.chi2 for s in mine)
        margin = track_margin(best, mine[0].dof)
        runs = sum(s.simulations for s in mine)
        dropped = sum(s.simulations for s in mine if s.chi2 > best + margin)
        rows.append(f"| {end:.3g} | {len(mine)} | {sum(s.evaluations for s in mine)} | {runs} "
                    f"| {dropped} ({dropped / runs:.0%}) |" if runs else
                    f"| {end:.3g} | {len(mine)} | 0 | 0 | 0 |")
    return rows


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--case", default="paper-multisine-b-tip", choices=runner.case_names())
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, help="also write the table here (Markdown)")
    args = parser.parse_args()
    _instrument()
    record, table, header = runner.load_case(args.case)
    scene = load_scene(runner.DATA / args.case / "scene.toml")
    with tempfile.TemporaryDirectory() as folder:
        measured = Path(folder) / "measured.csv"
        runner.noisy_csv(record, table, header, args.seed, measured)
        start = time.perf_counter()
        result = api.calibrate(scene, measured, record["free"],
                               noise=record["noise"] if record["noise_stated"] else None)
        wall = time.perf_counter() - start
    lines = [f"# Where the time goes: {args.case}, seed {args.seed}", "", "```sh",
             "python benchmarks/calibration_time.py " + " ".join(sys.argv[1:]), "```", "",
             f"{wall:.1f} s wall, {result.cpu_time_s:.1f} s CPU (the workers' included), "
             f"{result.simulations} runs.", "",
             "| stage | wall s | share | CPU s | CPU / wall |", "|---|---|---|---|---|"]
    lines += [f"| {name} | {seconds:.1f} | {seconds / wall:.0%} | {CPU_SECONDS[name]:.1f} "
              f"| {CPU_SECONDS[name] / seconds if seconds else 0:.2f} |"
              for name, seconds in SECONDS.items()]
    lines += ["", "| window s | tracks | evaluations | runs | runs of tracks then dropped |",
              "|---|---|---|---|---|", *_windows(result.stages), "",
              "Estimates: " + ", ".join(
                  f"{name} {100 * (e.value - record['truth'][name]) / record['truth'][name]:+.2f} "
                  f"%{' (determined)' if e.determined else ''}"
                  for name, e in result.estimates.items())]
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out is not None:
        atomic_write_text(args.out, text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
