"""What ``result.sol`` costs against the run that made it, side by side.

For each adaptive integrator on the paper scene (``jointplay.default_scene()``, shortened with
``--t-end``), runs the scene, then evaluates ``result.sol`` on the grid the orbit figures use
(:func:`jointplay.results.derived.dense_times`), ``--repeats`` times, and prints the median
wall times and their ratio. Timings depend on the machine's load; the ratio is what to read.

    python benchmarks/dense_output.py --t-end 2.0 --repeats 3
"""

from __future__ import annotations

import argparse
import statistics
import time

import jointplay
from jointplay.results.derived import dense_times


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=2.0, help="simulated time (s)")
    parser.add_argument("--repeats", type=int, default=3, help="runs per integrator")
    parser.add_argument("--integrators", default="bdf,cvodes", help="comma-separated")
    args = parser.parse_args()
    scene = jointplay.default_scene().with_run(t_end=args.t_end)
    print("| integrator | run [s] | sol on the orbit grid [s] | points | sol / run |")
    print("|---|---|---|---|---|")
    for integrator in args.integrators.split(","):
        case = scene.with_run(integrator=integrator)
        jointplay.simulate(case.with_run(t_end=min(args.t_end, 0.01)))  # model loaded once
        runs, sols, points = [], [], 0
        for _ in range(args.repeats):
            start = time.perf_counter()
            result = jointplay.simulate(case)
            runs.append(time.perf_counter() - start)
            grid = dense_times(result)
            points = grid.size
            start = time.perf_counter()
            result.sol(grid)
            sols.append(time.perf_counter() - start)
        run, sol = statistics.median(runs), statistics.median(sols)
        print(f"| {integrator} | {run:.3f} | {sol:.3f} | {points} | {sol / run:.2f} |")


if __name__ == "__main__":
    main()
