"""Write the calibration benchmark's cases: scene files and noiseless measured motion.

    python benchmarks/calibration_cases/generate.py [--cases NAME ...]

For each case of cases.py, into data/NAME/: ``scene.toml`` (the robot at its catalogue
values, the case's torques and run: what the calibration is given), ``truth.csv`` (the
motion the independent reference (reference.py) makes at the case's true values, sampled on
the run's output grid: time, then the measured columns, noiseless) and ``case.json`` (the
truth, the free parameters, the noise to add and whether it is stated, the reference's
settings, a hash of every input and of truth.csv). The benchmark runner adds the noise.
Nothing here imports jointplay.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import reference
from cases import DATA, HERE, INSEPARABLE, REPOSITORY, Case, by_name, true_robot

GENERATOR_VERSION = 1


def input_hash(case: Case) -> str:
    """sha256 of what the case's motion follows from: the reference's source, the robot
    file and the case's definition (its truth and scene file are checked on their own)."""
    digest = hashlib.sha256()
    for path in (HERE / "reference.py", case.robot_file):
        digest.update(path.read_bytes())
    # The definition with the robot file named relative to the repository, so the hash is
    # the same in every checkout.
    definition = replace(case, robot_file=case.robot_file.relative_to(REPOSITORY))
    digest.update(repr(definition).encode())
    return digest.hexdigest()


def measured_table(case: Case) -> tuple[np.ndarray, dict[str, Any]]:
    """The noiseless measured columns at the case's truth: (rows of time + columns, stats)."""
    arm = reference.Arm(true_robot(case))
    start = time.perf_counter()
    motion = arm.simulate(case.torques, case.initial, case.t_end, case.output_step)
    wall = time.perf_counter() - start
    columns = [motion["t"]]
    for name in case.columns:
        if name in ("tip_x", "tip_y"):
            columns.append(motion["tip"][:, ("tip_x", "tip_y").index(name)])
        else:
            columns.append(motion["x"][:, arm.coordinates.index(name)])
    return np.column_stack(columns), {"onsets": int(motion["onsets"]), "wall_s": wall}


def csv_text(case: Case, table: np.ndarray) -> str:
    lines = [",".join(("time", *case.columns))]
    lines += [",".join(f"{v:.17g}" for v in row) for row in table]
    return "\n".join(lines) + "\n"


def _write(path: Path, text: str) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def generate(case: Case, root: Path = DATA) -> dict[str, Any]:
    folder = root / case.name
    folder.mkdir(parents=True, exist_ok=True)
    table, stats = measured_table(case)
    truth_csv = csv_text(case, table)
    record = {
        "name": case.name, "why": case.why, "free": list(case.free),
        "truth": case.true_values(), "columns": list(case.columns), "noise": case.noise(),
        "noise_stated": case.noise_stated, "t_end": case.t_end,
        "output_step": case.output_step, "inseparable": list(INSEPARABLE.get(case.name, ())),
        "reference": {"rtol": reference.RTOL, "atol": reference.ATOL,
                      "onsets": stats["onsets"]},
        "generator_version": GENERATOR_VERSION, "input_sha256": input_hash(case),
        "truth_csv_sha256": hashlib.sha256(truth_csv.encode()).hexdigest(),
    }
    # The scene and the record last: a folder whose case.json matches its truth.csv is whole.
    _write(folder / "truth.csv", truth_csv)
    _write(folder / "scene.toml", case.scene_text(folder))
    _write(folder / "case.json", json.dumps(record, indent=1) + "\n")
    print(f"{case.name}: {len(table)} samples, {stats['onsets']} contact onsets, "
          f"{stats['wall_s']:.1f} s", flush=True)
    return record


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", nargs="*", help="case names (default: all)")
    args = parser.parse_args()
    for case in by_name(args.cases):
        generate(case)


if __name__ == "__main__":
    main()
