"""Where in the run an internal-model controller loses: RMS acceleration error by time window.

    python benchmarks/control_windows.py --model MODEL_DIR [--clearance 100e-6]
        [--windows 0.144,0.5,1,1.5,2] [--out DIR]

Runs every controller of ``jointplay control`` on the paper scene (at ``--clearance``, m,
radial, on every clearance joint; default the scene's) with the model folder's network, ARX
twin and LPV-ARX model, and prints each controller's RMS end-effector acceleration error
(sampled once per output step) in each window between the given times, beside the whole
"after settling" figure the commands report. It also prints the range of the ideal robot's
joint angles and speeds in each window against the range the model's training runs of the
scene's own torques covered (its datasets.h5): a window that leaves that range is motion the
network was not trained on. Writes control_windows.md when ``--out`` is given.
"""

from __future__ import annotations

import argparse
import os
from itertools import pairwise
from pathlib import Path

import numpy as np

from jointplay.common.files import atomic_write_text
from jointplay.neural.control.imc_settings import ControllerSettings
from jointplay.neural.control.metrics import tip_errors
from jointplay.neural.identify.datasets import read_datasets
from jointplay.neural.model.narx import load_narx
from jointplay.neural.model.plant import control_plant
from jointplay.neural.study.cases import case_list, case_scene, nominal_clearance
from jointplay.neural.study.comparison import compare
from jointplay.neural.study.control_run import load_lpv, load_twin
from jointplay.scene.definition import default_scene


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", required=True, help="a model folder (jointplay identify)")
    parser.add_argument("--clearance", type=float, help="radial clearance, m (default: the "
                                                        "scene's)")
    parser.add_argument("--windows", default="0.144,0.5,1,1.5,2",
                        help="window edges, s (default %(default)s)")
    parser.add_argument("--out", help="folder for control_windows.md")
    args = parser.parse_args()
    edges = [float(x) for x in args.windows.split(",")]
    model_dir = Path(args.model)
    scene = control_plant(default_scene())
    if args.clearance is not None:
        case = next(c for c in case_list(scene, ["scene"], [args.clearance],
                                          nominal_clearance(scene))
                    if c.clearance == args.clearance)
        scene = control_plant(case_scene(scene, case))
    narx = load_narx(model_dir)
    result = compare(scene, narx, ControllerSettings(), arx=load_twin(model_dir, narx),
                     lpv=load_lpv(model_dir), analyse=False)
    dt, nj = scene.run.output_step, len(scene.robot.moving_joints)
    spans = list(pairwise(edges))
    header = ["controller", "RMS |Δa| after settling"] + [f"{a:g}-{b:g} s" for a, b in spans]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for name, run in result.runs.items():
        acc = np.asarray(tip_errors(run, result.reference, nj)["acceleration"])
        cells = [f"{np.sqrt(np.mean(acc[round(a / dt): round(b / dt)] ** 2)):.3g}"
                 for a, b in spans]
        lines.append(f"| {name} | {result.metrics[name]['rms_acceleration_after']:.3g} | "
                     + " | ".join(cells) + " |")
    runs, meta = read_datasets(model_dir / "datasets.h5")
    names = list(meta["output_names"])
    cols = [names.index(n) for n in names if n.startswith(("q", "dq"))]
    seen = np.vstack([t.r[:, cols] for t in runs if t.split == "train" and t.family == "scene"])
    lines += ["", "Ideal robot, min / max per window (" + ", ".join(names[c] for c in cols)
              + "); the training runs of the scene's torques: "
              + ", ".join(f"{lo:.3g} / {hi:.3g}" for lo, hi in zip(seen.min(0), seen.max(0),
                                                                       strict=True)), ""]
    for a, b in spans:
        part = result.reference[round(a / dt): round(b / dt)][:, cols]
        lines.append(f"- {a:g}-{b:g} s: " + ", ".join(
            f"{lo:.3g} / {hi:.3g}" for lo, hi in zip(part.min(0), part.max(0), strict=True)))
    text = "\n".join(lines)
    print(text)
    if args.out:
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        atomic_write_text(out / "control_windows.md",
                          f"{text}\n\nload average {os.getloadavg()}\n")


if __name__ == "__main__":
    main()
