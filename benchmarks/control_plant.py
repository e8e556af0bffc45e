"""What the plant's integration accuracy does to the control metrics.

    python benchmarks/control_plant.py --out out/bench/control_plant [--model MODEL_DIR]

Runs the default scene's open loop and PD (and, with ``--model``, both internal-model
controllers) on the clearance robot integrated by ``bdf`` at the scenes' default tolerances
(rtol 1e-6, atol 1e-5) and at rtol = atol = 1e-7 ... 1e-10, and reports the goal metrics and
the wall time of each. With the last setting it also reports the acceleration metrics taken
once per sample (just before each control update) beside the dense ones
(jointplay.neural.model.plant .SUBSTEPS points per sample, what the commands report). Writes
control_plant.md with the machine's load average.
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

from jointplay.common.files import atomic_write_text
from jointplay.neural.model.plant import PLANT_TOLERANCE, SUBSTEPS
from jointplay.neural.study.control_run import (
    NEURAL,
    ControllerSettings,
    compare,
    load_twin,
    run_metrics,
)
from jointplay.neural.study.runs import _dummy_model
from jointplay.scene.definition import default_scene

KEYS = ("max_position", "max_velocity_after", "rms_acceleration_after")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("--model", help="a model folder: also run ARX-IMC and neural IMC")
    args = parser.parse_args()
    scene = default_scene()
    narx, arx, names = _dummy_model(scene), None, ("open loop", "PD")
    if args.model:
        from jointplay.neural.model.narx import load_narx

        narx = load_narx(args.model)
        arx = load_twin(Path(args.model), narx)
        names = ("open loop", "PD", "ARX-IMC", NEURAL)
    lines = [f"Default scene, 2 s, bdf; load average {os.getloadavg()[0]:.2f} at the start", "",
             "| rtol / atol | controller | max \\|Δp\\| [m] | max \\|Δv\\| after 50 ms [m/s] | "
             "RMS \\|Δa\\| after 50 ms [m/s²] | wall s (all controllers) |",
             "|---|---|---|---|---|---|"]
    last = None
    for rtol, atol in ((1e-6, 1e-5), (1e-7, 1e-7), (1e-8, 1e-8), (PLANT_TOLERANCE,) * 2,
                       (1e-10, 1e-10)):
        t0 = time.perf_counter()
        result = compare(scene.with_run(rtol=rtol, atol=atol), narx, ControllerSettings(),
                         arx=arx, controllers=names, analyse=False,
                         plant_tolerance=max(rtol, atol))
        wall = time.perf_counter() - t0
        for name in names:
            m = result.metrics[name]
            lines.append(f"| {rtol:g} / {atol:g} | {name} | " + " | ".join(
                f"{m[k]:.4g}" for k in KEYS) + f" | {wall:.1f} |")
        print(lines[-1], flush=True)
        if rtol == PLANT_TOLERANCE:
            last = result
    assert last is not None
    lines += ["", f"At rtol = atol = {PLANT_TOLERANCE:g}: RMS |Δa| after 50 ms once per sample "
                  f"against {SUBSTEPS} points per sample:", "",
              "| controller | once per sample | dense | dense / sampled |", "|---|---|---|---|"]
    nj = len(scene.robot.moving_joints)
    for name in names:
        sampled = run_metrics(last.runs[name], last.reference, nj, last.transient)
        dense = last.metrics[name]
        a, b = sampled["rms_acceleration_after"], dense["rms_acceleration_after"]
        lines.append(f"| {name} | {a:.4g} | {b:.4g} | {b / a:.3f} |")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    text = "\n".join(lines) + "\n"
    atomic_write_text(out / "control_plant.md", text)
    print(text)


if __name__ == "__main__":
    main()
