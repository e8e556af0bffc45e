"""How wide the true valley of a case's cost is: chi² along a line through the truth.

    python benchmarks/calibration_cases/valley_width.py paper-fast-tip --window 0.02 \\
        --reach 3e-7 --points 31

The case's measured file is made as the benchmark makes it (its noiseless motion plus the
seeded noise of ``--seed``); chi² of jointplay's runs over the samples up to ``--window``
seconds, at the calibration's own tolerances (the scene's divided by 1000) or ``--looser``
times them, at points ``truth + s (e_a - e_b) / sqrt(2)`` for ``s`` in ±``--reach`` (m),
``e_a`` and ``e_b`` the case's first two free clearances, the other free parameters at their
truths. Where chi² leaves the truth's value by more than a few units within one step, the
valley is narrower than the step: no grid or line coarser than that can land in it.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import runner  # noqa: E402

import jointplay as jp  # noqa: E402
from jointplay.calibration.api import prepare  # noqa: E402
from jointplay.calibration.continuation import _window_problem  # noqa: E402
from jointplay.calibration.predict import Predictor, chi2_at  # noqa: E402


def line_chi2(case: str, window: float, reach: float, points: int, seed: int,
              looser: float) -> tuple[np.ndarray, list[float]]:
    """The steps (m) and chi² along the line through the case's truth."""
    record, table, header = runner.load_case(case)
    clearances = [k for k, name in enumerate(record["free"]) if name.endswith(".clearance")]
    if len(clearances) < 2:
        raise SystemExit(f"{case} has fewer than two free clearances")
    with tempfile.TemporaryDirectory() as folder:
        measured = Path(folder) / "measured.csv"
        runner.noisy_csv(record, table, header, seed, measured)
        scene = jp.load_scene(runner.DATA / case / "scene.toml")
        problem = prepare(scene, measured, record["free"], noise=record["noise"])
    predictor = Predictor(problem.scene, problem.model, problem.free, problem.measured)
    part, window_scene = _window_problem(predictor, window, looser)
    probe = Predictor(window_scene, predictor.model, predictor.free, part,
                      compiled=predictor.compiled)
    truth = np.array([record["truth"][name] for name in record["free"]])
    direction = np.zeros(truth.size)
    direction[clearances[0]], direction[clearances[1]] = 1 / np.sqrt(2), -1 / np.sqrt(2)
    steps = np.linspace(-reach, reach, points)
    chi2, _ = chi2_at(probe, problem.sigma, [truth + s * direction for s in steps])
    return steps, chi2


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("case")
    parser.add_argument("--window", type=float, default=0.02, help="window end, s")
    parser.add_argument("--reach", type=float, default=3e-7, help="half-length of the line, m")
    parser.add_argument("--points", type=int, default=31)
    parser.add_argument("--seed", type=int, default=0, help="noise seed")
    parser.add_argument("--looser", type=float, default=1.0,
                        help="the runs' tolerances times this (1: the calibration's own)")
    args = parser.parse_args()
    steps, chi2 = line_chi2(args.case, args.window, args.reach, args.points, args.seed,
                            args.looser)
    print(f"{args.case}: chi² over the first {args.window:g} s along c_a - c_b through the "
          "truth")
    print("| step (nm) | chi² |\n|---|---|")
    for s, value in zip(steps, chi2, strict=True):
        print(f"| {s * 1e9:+.1f} | {value:.2f} |")


if __name__ == "__main__":
    main()
