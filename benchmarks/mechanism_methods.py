"""What accuracy costs a mechanism, method by method: the slider-crank's first revolution.

scenes/slider_crank.toml (0.5 mm, 5000 rpm) over 0 to 0.012 s by the compiled BDF on a ladder
of tolerances (rtol = atol) and by RK4 and Radau IIA on a ladder of fixed steps, side by side
in one run. A rung's error is the slider's largest distance, on the 1e-5 s output grid, from
the BDF at rtol = atol = 1e-13 (whose own error, against 1e-12, is reported). Each method's
matched rung is the cheapest from which every finer rung stays within the target (1e-6 m by
default); the report gives its CPU time (median of ``--repeats`` runs; time.process_time)
and the ratio to the BDF's.

    python benchmarks/mechanism_methods.py --out DIR [--target 1e-6] [--repeats 3]
"""

from __future__ import annotations

import datetime
import os
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np
from slider_crank_ladder import ladder_arguments, write_outputs

from jointplay.bench import machine_facts, markdown_table, to_csv
from jointplay.mechanism.model import model_for
from jointplay.mechanism.reading import load_mechanism_scene
from jointplay.mechanism.simulate import simulate_mechanism

SCENE = Path(__file__).resolve().parents[1] / "scenes" / "slider_crank.toml"
REVOLUTION = 0.012
TOLERANCES = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11)
STEPS = (1e-6, 5e-7, 2e-7, 1e-7, 5e-8, 2e-8, 1e-8)
COLUMNS = [("method", "method", "{}"), ("setting", "rtol or step", "{:.0e}"),
           ("cpu_s", "CPU s", "{:.3g}"), ("error_m", "slider error (m)", "{:.2e}"),
           ("impacts", "impacts", "{}"), ("steps", "steps", "{}")]


def rung(scene: Any, model: Any, method: str, setting: float, repeats: int
         ) -> dict[str, Any]:
    changes: dict[str, Any] = ({"rtol": setting, "atol": setting} if method == "bdf"
                               else {"integrator": method, "step": setting})
    run = scene.with_run(t_end=REVOLUTION, output_step=1e-5, **changes)
    cpu = []
    for _ in range(repeats):
        start = time.process_time()
        result = simulate_mechanism(run, model=model)
        cpu.append(time.process_time() - start)
    return {"method": method, "setting": setting, "cpu_s": statistics.median(cpu),
            "x": result.coordinate("guide.position"), "impacts": len(result.impacts.time),
            "steps": int(result.stats.get("steps", 0))}


def matched(rungs: list[dict[str, Any]], target: float) -> dict[str, Any] | None:
    """The coarsest rung (the ladders run coarse to fine) from which every finer rung is
    within the target: a lucky coarse rung does not count."""
    for k, r in enumerate(rungs):
        if all(s["error_m"] <= target for s in rungs[k:]):
            return r
    return None


def main(argv: list[str] | None = None) -> int:
    args = ladder_arguments(__doc__, argv, repeats=3)
    load_start = " ".join(f"{v:.2f}" for v in os.getloadavg())
    scene = load_mechanism_scene(str(SCENE))
    model = model_for(scene.mechanism)
    reference = rung(scene, model, "bdf", 1e-13, 1)["x"]
    check = rung(scene, model, "bdf", 1e-12, 1)["x"]
    ladders = {"bdf": [rung(scene, model, "bdf", s, args.repeats) for s in TOLERANCES]}
    for method in ("rk4", "radau"):
        ladders[method] = [rung(scene, model, method, s, args.repeats) for s in STEPS]
    for rungs in ladders.values():
        for r in rungs:
            r["error_m"] = float(np.max(np.abs(r["x"] - reference)))
    picks = {m: matched(rungs, args.target) for m, rungs in ladders.items()}
    rows = [{k: v for k, v in r.items() if k != "x"} for rungs in ladders.values()
            for r in rungs]
    lines = ["# The slider-crank's first revolution, method by method", "",
             f"Measured {datetime.date.today().isoformat()}. Scene: scenes/slider_crank.toml, "
             f"0 to {REVOLUTION} s; error: the slider's largest distance from the BDF at "
             "rtol = atol = 1e-13 on the 1e-5 s grid (that run's own distance from 1e-12: "
             f"{float(np.max(np.abs(reference - check))):.1e} m); target {args.target:g} m; "
             f"CPU: median of {args.repeats} runs.", "", "## At matched accuracy", ""]
    bdf = picks["bdf"]
    for method, pick in picks.items():
        if pick is None:
            lines.append(f"- {method}: not reached on this ladder")
            continue
        ratio = (f", {pick['cpu_s'] / bdf['cpu_s']:.0f}x the BDF's"
                 if bdf is not None and method != "bdf" else "")
        lines.append(f"- {method}: {'rtol' if method == 'bdf' else 'step'} "
                     f"{pick['setting']:.0e}, {pick['cpu_s']:.3g} s CPU{ratio}, slider error "
                     f"{pick['error_m']:.2e} m")
    lines += ["", "## Every run", "", markdown_table(rows, COLUMNS), "", "## Machine", "",
              f"- load average (1/5/15 min) at the start: {load_start}",
              *(f"- {k}: {v}" for k, v in machine_facts().items()), ""]
    report = "\n".join(lines)
    write_outputs(args.out, {"mechanism_methods.md": report,
                              "mechanism_methods.csv": to_csv(rows, [k for k, _, _ in COLUMNS])})
    print(report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
