"""jointplay against Exudyn on the slider-crank's first revolution, at matched accuracy.

Each code runs scenes/slider_crank.toml's mechanism (the Exudyn model: tests/exudyn_slider_crank.py)
over the first revolution (0.012 s) on a ladder of tolerances. A rung's error is the largest
difference of the slider's position, on the 1e-5 s output grid, from the same code's run 100x
tighter. Each code's matched setting is the loosest rung from which it and every tighter rung
stay within the target (1e-6 m by default: issue 53's goal); chance enters through the
sensitivity of the motion, so a lucky loose rung does not count. The report gives both codes'
CPU seconds there (jointplay: median of ``--repeats`` runs, Exudyn: one run; time.process_time),
their ratio, the errors reached, and how far the two codes' tightest runs agree.

Exudyn's clearance force and its event bookkeeping are Python callbacks (a user function of
the kinematic tree, called at every stage), so its time is mostly Python's; the ratio compares
the two ways of getting this answer, not the two integrators' cores.

    python benchmarks/slider_crank_peers.py --out DIR [--target 1e-6] [--repeats 5]
"""

from __future__ import annotations

import datetime
import math
import os
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from exudyn_slider_crank import SliderCrank, simulate
from slider_crank_ladder import ladder_arguments, write_outputs

from jointplay.bench import machine_facts, markdown_table, to_csv
from jointplay.mechanism.model import model_for
from jointplay.mechanism.reading import load_mechanism_scene
from jointplay.mechanism.simulate import simulate_mechanism

SCENE = Path(__file__).resolve().parents[1] / "scenes" / "slider_crank.toml"
REVOLUTION = 0.012
GRID = np.arange(1201) * 1e-5
JOINTPLAY_RTOLS = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13)
EXUDYN_RTOLS = (1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12)
COLUMNS = [("code", "code", "{}"), ("rtol", "rtol", "{:.0e}"),
           ("cpu_s", "CPU s", "{:.3g}"), ("cpu_min_s", "min", "{:.3g}"),
           ("cpu_max_s", "max", "{:.3g}"), ("error_m", "slider error (m)", "{:.2e}"),
           ("impacts", "impacts", "{}"), ("steps", "steps", "{}")]


def jointplay_rung(scene: Any, model: Any, rtol: float, repeats: int) -> dict[str, Any]:
    run = scene.with_run(t_end=REVOLUTION, output_step=1e-5, rtol=rtol, atol=rtol)
    cpu = []
    for _ in range(repeats):
        start = time.process_time()
        result = simulate_mechanism(run, model=model)
        cpu.append(time.process_time() - start)
    return {"code": "jointplay", "rtol": rtol, "cpu_s": statistics.median(cpu),
            "cpu_min_s": min(cpu), "cpu_max_s": max(cpu),
            "x": result.coordinate("guide.position"), "impacts": len(result.impacts.time),
            "steps": int(result.stats.get("steps", 0))}


def exudyn_rung(rtol: float) -> dict[str, Any]:
    start = time.process_time()
    run = simulate(SliderCrank(), REVOLUTION, rtol=rtol, atol=1e-2 * rtol)
    cpu = time.process_time() - start
    return {"code": "Exudyn", "rtol": rtol, "cpu_s": cpu, "cpu_min_s": cpu, "cpu_max_s": cpu,
            "x": run.at(GRID)["slider_position"], "impacts": len(run.impacts),
            "steps": int(run.t.size - 1)}


def score(rungs: list[dict[str, Any]], target: float) -> dict[str, Any] | None:
    """Errors against the run 100x tighter; the matched rung (see the module docstring)."""
    for r in rungs:
        tight = next((s for s in rungs if math.isclose(s["rtol"], r["rtol"] / 100.0)), None)
        if tight is not None:
            r["error_m"] = float(np.max(np.abs(r["x"] - tight["x"])))
    scored = sorted((r for r in rungs if "error_m" in r), key=lambda r: -r["rtol"])
    for k, r in enumerate(scored):
        if all(s["error_m"] <= target for s in scored[k:]):
            return r
    return None


def main(argv: list[str] | None = None) -> int:
    args = ladder_arguments(__doc__, argv, repeats=5)
    load_start = " ".join(f"{v:.2f}" for v in os.getloadavg())
    scene = load_mechanism_scene(str(SCENE))
    model = model_for(scene.mechanism)
    ours = [jointplay_rung(scene, model, r, args.repeats) for r in JOINTPLAY_RTOLS]
    theirs = [exudyn_rung(r) for r in EXUDYN_RTOLS]
    our_pick, their_pick = score(ours, args.target), score(theirs, args.target)
    agreement = float(np.max(np.abs(ours[-1]["x"] - theirs[-1]["x"])))
    rows = [{k: v for k, v in r.items() if k != "x"} for r in ours + theirs]

    lines = ["# jointplay and Exudyn on the slider-crank's first revolution", "",
             f"Measured {datetime.date.today().isoformat()}. Scene: scenes/slider_crank.toml, "
             f"0 to {REVOLUTION} s; error: the slider's largest difference from the same "
             f"code's run at rtol / 100 on the 1e-5 s grid; target {args.target:g} m. "
             f"jointplay: rtol = atol (scaled), median of {args.repeats} runs; Exudyn "
             "(DOPRI5, Python force and events): atol = rtol / 100, one run.", "",
             "## At matched accuracy", ""]
    if our_pick and their_pick:
        ratio = their_pick["cpu_s"] / our_pick["cpu_s"]
        lines += [f"- jointplay: rtol {our_pick['rtol']:.0e}, {our_pick['cpu_s']:.3g} s CPU, "
                  f"slider error {our_pick['error_m']:.2e} m",
                  f"- Exudyn: rtol {their_pick['rtol']:.0e}, {their_pick['cpu_s']:.3g} s CPU, "
                  f"slider error {their_pick['error_m']:.2e} m",
                  f"- Exudyn / jointplay CPU time: {ratio:.0f}x (goal: >= 10x)"]
    else:
        lines.append(f"- not reached by {'jointplay' if not our_pick else 'Exudyn'} on this "
                     "ladder: no ratio")
    lines += [f"- the two codes' tightest runs (jointplay {ours[-1]['rtol']:.0e}, Exudyn "
              f"{theirs[-1]['rtol']:.0e}) differ by {agreement:.2e} m in the slider's position",
              "", "## Every run", "", markdown_table(rows, COLUMNS), "", "## Machine", "",
              f"- load average (1/5/15 min) at the start: {load_start}",
              *(f"- {k}: {v}" for k, v in machine_facts().items()), ""]
    report = "\n".join(lines)
    write_outputs(args.out, {"slider_crank_peers.md": report,
                              "slider_crank_peers.csv": to_csv(rows, [k for k, _, _ in COLUMNS])})
    print(report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
