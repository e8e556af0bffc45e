"""What sensitivities cost and how accurate they are, on the paper scene.

Cost: the scene (``jointplay.default_scene()``, 2 s at its own tolerances unless
``--t-end``) run with 0, 1, 3 and 6 sensitivities side by side, outside the error test and in
it (``sensitivity_error_control``), each ``--repeats`` times: median CPU seconds of the whole
``simulate`` call (``time.process_time``: integration, the derived outputs and, with
sensitivities, the tip's and peaks'), min and max, and the ratio to the run without. Outside
the error test the steps are those of the run without; the last column counts the Jacobians
the sensitivities take. Each row with sensitivities outside the error test is run twice, the
step's forcing along the named directions by forward-mode AD (``directions``, what the
integrator uses) and from the full input blocks over every parameter (``blocks``, what a
model generated before the directional function uses). ``--tighten F`` divides the scene's
tolerances by F (the calibration's runs: 1000).

Accuracy (``--accuracy``): the sensitivities of runs at several tolerances, outside the error
test and in it, against central differences of runs at rtol = atol = 1e-13
(jointplay.sim.sensitivity_check; h = 1e-3 of each parameter; the differences' own
uncertainty, h against h / 2, in brackets), normwise, the state and the tip between impacts,
the largest over the parameters (``--detail``: each), on the scene's first 5 ms (five
impacts of the two joints) and on a journal falling in its bearing (three impacts).

    python benchmarks/sensitivities.py --repeats 5
    python benchmarks/sensitivities.py --repeats 5 --tighten 1000
    python benchmarks/sensitivities.py --accuracy
"""

from __future__ import annotations

import argparse
import contextlib
import os
import platform
import statistics
import time
from collections.abc import Iterator
from importlib.metadata import version
from typing import Any

import jointplay
from jointplay.derive import deferred
from jointplay.scene.definition import Scene, scene_from_dict

NAMES = ("joint2.clearance", "joint3.clearance", "friction.mu", "payload.mass",
         "link3.length", "joint2.bearing_E")
COUNTS = (0, 1, 3, 6)
PAPER_NAMES = ("joint2.clearance", "friction.mu", "payload.mass", "link3.length",
               "joint3.bearing_E")
PIN_NAMES = ("gravity.y", "joint1.clearance", "link1.mass", "contact.restitution",
             "joint1.bearing_E")
REFERENCE_TOLERANCE = 1e-13


def machine() -> str:
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    return (f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, load "
            f"{load:.1f}; Python {platform.python_version()}, numpy {version('numpy')}, "
            f"casadi {version('casadi')}, jointplay {version('jointplay')}")


def cost(scene: Scene, repeats: int) -> None:
    jointplay.simulate(scene.with_run(t_end=min(scene.run.t_end, 0.01)),
                       sensitivities=NAMES)  # the model and its parameter Jacobian, once
    print(f"Paper scene, {scene.run.t_end:g} s at rtol {scene.run.rtol:g}, atol "
          f"{scene.run.atol:g}; {machine()}\n")
    print("| sensitivities | in the error test | forcing | CPU s (median) | min | max | ratio "
          "| steps | impacts | sensitivity Jacobians |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    base = None
    paired = []
    for control in (False, True):
        for count in COUNTS if not control else COUNTS[1:]:
            names = NAMES[:count] or None
            forcings = ("directions", "blocks") if count and not control else ("directions",)
            times: dict[str, list[float]] = {f: [] for f in forcings}
            results: dict[str, Any] = {}
            for _ in range(repeats):  # the two forcings in turn: the machine's drift shared
                for forcing in forcings:
                    with _forcing(forcing):
                        start = time.process_time()
                        results[forcing] = jointplay.simulate(
                            scene, sensitivities=names, sensitivity_error_control=control)
                        times[forcing].append(time.process_time() - start)
            for forcing in forcings:
                median = statistics.median(times[forcing])
                base = base or median
                result = results[forcing]
                label = ", ".join(NAMES[:count]) if count else "none"
                print(f"| {count} ({label}) | {'yes' if control else 'no'} | "
                      f"{forcing if count else ''} | {median:.3f} | "
                      f"{min(times[forcing]):.3f} | {max(times[forcing]):.3f} | "
                      f"{median / base:.2f} | {result.stats['steps']} | "
                      f"{len(result.impacts)} | "
                      f"{result.stats.get('sensitivity_jacobians', 0)} |")
            if len(forcings) == 2:
                ratios = [a / b for a, b in zip(times["directions"], times["blocks"],
                                                strict=True)]
                paired.append((count, statistics.median(ratios), max(ratios)))
    print("\nDirections against blocks, run for run (median and worst of the ratios):")
    for count, median, worst in paired:
        print(f"- {count} sensitivities: {median:.2f} (worst {worst:.2f})")


@contextlib.contextmanager
def _forcing(forcing: str) -> Iterator[None]:
    """The step's forcing from the directional function, or from the full blocks (as for a
    model generated without it)."""
    generated = deferred.INPUT_DIRECTIONAL
    deferred.INPUT_DIRECTIONAL = generated if forcing == "directions" else "not generated"
    try:
        yield
    finally:
        deferred.INPUT_DIRECTIONAL = generated


def falling_journal(tolerance: float) -> Scene:
    """A journal (2 kg, 30 um radial clearance, steel) falling from the centre of its bearing
    and bouncing (restitution 0.8): one clearance joint, no friction, 12 ms."""
    robot: dict[str, Any] = {
        "name": "falling_journal",
        "links": [{"length": 0.1, "mass": 2.0, "inertia": 1e-3, "com": 0.05}],
        "joints": [{"kind": "locked_clearance", "angle": 0.0, "bearing_radius": 10e-3,
                    "journal_radius": 10e-3 - 30e-6}],
        "payload": {"mass": 0.0},
        "gravity": {"enabled": True, "vector": [0.0, -9.81]},
        "contact": {"law": "lankarani-nikravesh", "exponent": 1.5, "restitution": 0.8,
                    "impact_speed_floor": 1e-3},
        "friction": {"law": "none"},
        "drive": {"enabled": False},
    }
    return scene_from_dict({"name": "falling_journal", "robot": robot, "torques": {},
                            "initial": {}, "run": {"t_end": 0.012, "output_step": 1e-4,
                                                   "rtol": tolerance, "atol": tolerance}},
                           source="benchmark")


def accuracy(tolerances: list[float], detail: bool) -> None:
    from jointplay.sim.sensitivity_check import OUTPUTS, compare_with_differences

    paper = jointplay.default_scene().with_run(t_end=0.005, output_step=2.5e-4)
    cases = [("paper scene, first 5 ms", PAPER_NAMES,
              lambda tol: paper.with_run(rtol=tol, atol=tol)),
             ("falling journal, 12 ms", PIN_NAMES, falling_journal)]
    print(f"Central differences at rtol = atol = {REFERENCE_TOLERANCE:g}; {machine()}")
    for title, names, make in cases:
        reference = make(REFERENCE_TOLERANCE)
        summary = []
        for tol in tolerances:
            for control in (False, True):
                report = compare_with_differences(make(tol), names, reference=reference,
                                                  error_control=control)
                worst = {k: max(row[k] for row in report.values()) for k in OUTPUTS}
                noise = {k: max(row[k + "_stability"] for row in report.values())
                         for k in OUTPUTS}
                summary.append((tol, control, worst, noise))
                if detail:
                    print(f"\n{title}, rtol = atol = {tol:g}, in the error test: {control}\n")
                    print("| parameter | " + " | ".join(OUTPUTS) + " |")
                    print("|---|" + "---|" * len(OUTPUTS))
                    for name, row in report.items():
                        cells = [f"{row[k]:.1e} ({row[k + '_stability']:.0e})"
                                 for k in OUTPUTS]
                        print(f"| {name} | " + " | ".join(cells) + " |")
        print(f"\n{title} ({', '.join(names)}): the largest over the parameters\n")
        print("| rtol = atol | in the error test | " + " | ".join(OUTPUTS) + " |")
        print("|---|---|" + "---|" * len(OUTPUTS))
        for tol, control, worst, noise in summary:
            cells = [f"{worst[k]:.1e} ({noise[k]:.0e})" for k in OUTPUTS]
            print(f"| {tol:g} | {'yes' if control else 'no'} | " + " | ".join(cells) + " |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=None, help="simulated time (s)")
    parser.add_argument("--repeats", type=int, default=5, help="runs per row")
    parser.add_argument("--tighten", type=float, default=1.0,
                        help="the scene's tolerances divided by this (the calibration's: 1000)")
    parser.add_argument("--accuracy", action="store_true",
                        help="the accuracy tables instead of the cost table")
    parser.add_argument("--detail", action="store_true",
                        help="with --accuracy: a table per parameter too")
    parser.add_argument("--tolerances", default="1e-12,1e-10,1e-8,2e-6",
                        help="tolerances of the runs checked by --accuracy (comma-separated)")
    args = parser.parse_args()
    if args.accuracy:
        accuracy([float(t) for t in args.tolerances.split(",")], args.detail)
        return
    scene = jointplay.default_scene()
    if args.t_end is not None:
        scene = scene.with_run(t_end=args.t_end)
    scene = scene.with_run(rtol=scene.run.rtol / args.tighten,
                           atol=scene.run.atol / args.tighten)
    cost(scene, args.repeats)


if __name__ == "__main__":
    main()
