"""What a run option costs: runs of the compiled BDF with it one way and the other, side by side.

``--option peaks``: each run samples the normal force at every step in contact and locates
each contact phase's peak by Brent's method on the dense output (with sensitivities, the
peak's derivatives too); ``simulate(..., peaks=False)`` skips that and leaves the trajectory
the same to the bit (checked here on every pair). ``--option newton``: the full 2n x 2n Newton
matrix against the n x n one it reduces to (``simulate(..., newton="reduced")``, a
calibration's choice); the two differ by round-off, which an impact burst turns into another
step sequence: the largest difference of the tip's position is printed beside the steps.

Per scene, run length and sensitivity count: the median and least CPU seconds of
``--repeats`` runs of each kind, alternated so that the machine's drift is shared, and the
ratio of the second to the first. The scenes: the paper's and the calibration benchmark's
second arm (three moving links), at their own tolerances and at the calibration's (divided by
1000).

    python benchmarks/run_options_cost.py --option peaks --repeats 7
    python benchmarks/run_options_cost.py --option newton --repeats 7
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

import jointplay
from jointplay.scene import load_scene
from jointplay.sim import load_scene_model, simulate

HERE = Path(__file__).resolve().parent
THREE_LINK = HERE / "calibration_cases" / "data" / "three-link-both" / "scene.toml"
SENSITIVITIES = {"paper": ("joint2.clearance", "joint3.clearance", "friction.mu"),
                 "three-link": ("joint2.clearance", "joint4.clearance", "friction.mu")}
OPTIONS: dict[str, tuple[Any, Any]] = {"peaks": (True, False), "newton": ("full", "reduced")}
"""Each option's two values, the usual first."""


def _same(a: jointplay.SimulationResult, b: jointplay.SimulationResult) -> bool:
    """Whether two runs' motion, impacts and sensitivities agree to the bit."""
    same = (np.array_equal(a.q, b.q) and np.array_equal(a.u, b.u)
            and np.array_equal(a.tip_position, b.tip_position)
            and np.array_equal(a.impacts.time, b.impacts.time)
            and np.array_equal(a.impacts.max_penetration, b.impacts.max_penetration)
            and a.stats["steps"] == b.stats["steps"])
    if a.sensitivities is not None and b.sensitivities is not None:
        same = same and np.array_equal(a.sensitivities.state, b.sensitivities.state)
    return same


def _compared(option: str, a: jointplay.SimulationResult, b: jointplay.SimulationResult
              ) -> str:
    """The last column: for peaks, whether the pair is the same to the bit; for newton, the
    steps of each and the largest difference of the tip's position."""
    if option == "peaks":
        return "yes" if _same(a, b) else "NO"
    tip = float(np.max(np.abs(a.tip_position - b.tip_position)))
    return f"{a.stats['steps']}, {b.stats['steps']}; {tip:.1e} m"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--option", choices=sorted(OPTIONS), default="peaks",
                        help="the option compared (default peaks)")
    parser.add_argument("--repeats", type=int, default=7, help="runs of each kind (default 7)")
    parser.add_argument("--t-end", type=float, default=1.5, help="run length, s (default 1.5)")
    args = parser.parse_args(argv)
    if args.repeats < 1 or not args.t_end > 0:
        parser.error("--repeats must be >= 1 and --t-end > 0")
    first, second = OPTIONS[args.option]
    last = "same to the bit" if args.option == "peaks" else "steps; largest tip difference"
    scenes = {"paper": jointplay.default_scene(), "three-link": load_scene(THREE_LINK)}
    print(f"| scene | tolerances | sensitivities | CPU s, {args.option} = {first!r} (median, "
          f"least) | {second!r} | ratio (median, least) | {last} |")
    print("|---|---|---|---|---|---|---|")
    for name, base in scenes.items():
        model = load_scene_model(base)
        for tighten in (1.0, 1000.0):
            run = base.run
            scene = base.with_run(t_end=args.t_end, rtol=run.rtol / tighten,
                                  atol=run.atol / tighten)
            for names in ((), SENSITIVITIES[name]):
                kwargs = {"sensitivities": names} if names else {}
                simulate(scene.with_run(t_end=0.01), model=model, **kwargs)  # loaded once
                times: dict[Any, list[float]] = {first: [], second: []}
                compared = []
                for _ in range(args.repeats):
                    results = {}
                    for value in (first, second):
                        start = time.process_time()
                        results[value] = simulate(scene, model=model,
                                                  **{args.option: value}, **kwargs)
                        times[value].append(time.process_time() - start)
                    compared.append(_compared(args.option, results[first], results[second]))
                a, b = times[first], times[second]
                print(f"| {name} | rtol {scene.run.rtol:g} | {len(names)} | "
                      f"{statistics.median(a):.3f}, {min(a):.3f} | "
                      f"{statistics.median(b):.3f}, {min(b):.3f} | "
                      f"{statistics.median(b) / statistics.median(a):.2f}, "
                      f"{min(b) / min(a):.2f} | "
                      f"{'NO' if 'NO' in compared else compared[-1]} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
