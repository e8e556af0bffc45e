"""What locating the peak forces costs: runs with and without it, side by side.

Each run of the compiled BDF samples the normal force at every step in contact and locates
each contact phase's peak by Brent's method on the dense output (with sensitivities, the
peak's derivatives too). ``simulate(..., peaks=False)`` skips that and leaves the trajectory
the same to the bit (checked here on every pair). Per scene, run length and sensitivity count:
the median and least CPU seconds of ``--repeats`` runs of each kind, alternated so that the
machine's drift is shared, and the ratio without / with. The scenes: the paper's and the
calibration benchmark's second arm (three moving links), at their own tolerances and at the
calibration's (divided by 1000).

    python benchmarks/peaks_cost.py --repeats 7
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import jointplay
from jointplay.scene import load_scene
from jointplay.sim import load_scene_model, simulate

HERE = Path(__file__).resolve().parent
THREE_LINK = HERE / "calibration_cases" / "data" / "three-link-both" / "scene.toml"
SENSITIVITIES = {"paper": ("joint2.clearance", "joint3.clearance", "friction.mu"),
                 "three-link": ("joint2.clearance", "joint4.clearance", "friction.mu")}


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


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=7, help="runs of each kind (default 7)")
    parser.add_argument("--t-end", type=float, default=1.5, help="run length, s (default 1.5)")
    args = parser.parse_args(argv)
    if args.repeats < 1 or not args.t_end > 0:
        parser.error("--repeats must be >= 1 and --t-end > 0")
    scenes = {"paper": jointplay.default_scene(), "three-link": load_scene(THREE_LINK)}
    print("| scene | tolerances | sensitivities | CPU s with peaks (median, least) | without "
          "| ratio (median, least) | same to the bit |")
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
                times: dict[bool, list[float]] = {True: [], False: []}
                same = True
                for _ in range(args.repeats):
                    results = {}
                    for peaks in (True, False):
                        start = time.process_time()
                        results[peaks] = simulate(scene, model=model, peaks=peaks, **kwargs)
                        times[peaks].append(time.process_time() - start)
                    same = same and _same(results[True], results[False])
                on, off = times[True], times[False]
                print(f"| {name} | rtol {scene.run.rtol:g} | {len(names)} | "
                      f"{statistics.median(on):.3f}, {min(on):.3f} | "
                      f"{statistics.median(off):.3f}, {min(off):.3f} | "
                      f"{statistics.median(off) / statistics.median(on):.2f}, "
                      f"{min(off) / min(on):.2f} | {'yes' if same else 'NO'} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
