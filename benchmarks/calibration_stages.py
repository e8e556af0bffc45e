"""What each stage of the calibration search earns: the benchmark cases with one stage removed.

    python benchmarks/calibration_stages.py --out DIR [--stages NAME ...] [--cases NAME ...]
                                            [--seeds 1] [--first-seed 0]

For every case of benchmarks/calibration_cases/ (made by an independent simulator) and noise
seed, ``jointplay.calibrate`` runs in this process with its default options, once as it is
(``full``) and once with each stage in ``--stages`` removed (default: all of them):

- ``later-lines``: no valley lines at the windows after the first one that has them (0.64 s
  and 1.28 s on a 2 s record; the lines at 0.32 s stay);
- ``basin-lines``: the basin check runs no lines (it still compares the other tracks'
  whole-record fits with the best);
- ``valley-check``: no valley check (``valley_check_points = 0``);
- ``grid-line``: no line through the best grid point (``grid_line_points = 0``);
- ``others-first``: the friction is not fitted over the whole record before the grid (the
  windows hold it at its start instead).

The stages with no option of their own are removed by replacing one function of the search
for the run (the worker processes are forked, so they see the same). Writes DIR/stages.csv
(a row per stage, case, seed and parameter) and DIR/stages.md (per stage: intervals holding
the truth, estimates reported determined and those missing the truth, runs, and every
estimate whose verdict, interval or error moved against the full search), each atomically
at the end; the noisy CSVs go to DIR/measured/.
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import io
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "calibration_cases"))

import runner  # noqa: E402

import jointplay as jp  # noqa: E402
from jointplay.calibration import (  # noqa: E402
    CalibrationOptions,
    api,
    basins,
    calibrate,
    continuation,
)
from jointplay.calibration.fit import timed  # noqa: E402
from jointplay.common.files import atomic_write_text  # noqa: E402

MOVED_PCT = 0.05
"""An estimate whose error moves by more than this (percentage points of the truth) against
the full search is listed, as is any change of verdict or of whether its interval holds the
truth."""


@contextlib.contextmanager
def _replaced(module: Any, name: str, new: Callable[..., Any]) -> Iterator[None]:
    old = getattr(module, name)
    setattr(module, name, new)
    try:
        yield
    finally:
        setattr(module, name, old)


def _without_later_lines() -> contextlib.AbstractContextManager[None]:
    lines = continuation._line_minima
    first = CalibrationOptions().valley_window

    def first_only(predictor: Any, stage_scene: Any, part: Any, *rest: Any) -> Any:
        if float(part.t[-1]) > 1.5 * first:  # a window after the first with lines
            return [], 0
        return lines(predictor, stage_scene, part, *rest)

    return _replaced(continuation, "_line_minima", first_only)


@contextlib.contextmanager
def _without_basin_lines() -> Iterator[None]:
    with _replaced(basins, "_line_points", lambda *args: []), \
            _replaced(basins, "_other_centres", lambda *args: []):
        yield


def _without_others_first() -> contextlib.AbstractContextManager[None]:
    return _replaced(api, "others_first", lambda predictor, weights, start, *rest: (start, 0))


STAGES: dict[str, tuple[Callable[[], contextlib.AbstractContextManager[None]], dict[str, Any]]]
STAGES = {
    "later-lines": (_without_later_lines, {}),
    "basin-lines": (_without_basin_lines, {}),
    "valley-check": (contextlib.nullcontext, {"valley_check_points": 0}),
    "grid-line": (contextlib.nullcontext, {"grid_line_points": 0}),
    "others-first": (_without_others_first, {}),
}


def calibrate_case(name: str, seed: int, stage: str, measured_dir: Path) -> dict[str, Any]:
    """One calibration of a case with ``stage`` removed (``full``: none)."""
    record, table, header = runner.load_case(name)
    measured = measured_dir / f"{name}_seed{seed}.csv"
    if not measured.is_file():
        runner.noisy_csv(record, table, header, seed, measured)
    scene = jp.load_scene(runner.DATA / name / "scene.toml")
    noise = ({c: record["noise"][c] for c in record["columns"]} if record["noise_stated"]
             else None)
    remove, options = STAGES[stage] if stage != "full" else (contextlib.nullcontext, {})
    wall0, cpu0 = timed()
    with remove():
        result = calibrate(scene, measured, record["free"], noise=noise,
                           options=CalibrationOptions(**options))
    wall1, cpu1 = timed()
    row: dict[str, Any] = {"stage": stage, "case": name, "seed": seed,
                           "runs": result.simulations, "wall_s": wall1 - wall0,
                           "cpu_s": cpu1 - cpu0, "explains": result.fit_explains_data,
                           "parameters": {}}
    for pname in record["free"]:
        estimate, truth = result.estimates[pname], record["truth"][pname]
        row["parameters"][pname] = {
            "error_pct": 100 * (estimate.value - truth) / truth,
            "covered": bool(estimate.low95 <= truth <= estimate.high95),
            "determined": bool(estimate.determined)}
    return row


def _cell(p: dict[str, Any]) -> str:
    return (f"{p['error_pct']:+.2f} % ({'in' if p['covered'] else 'out'}, "
            f"{'det.' if p['determined'] else 'not det.'})")


def _moved(full: dict[str, Any], other: dict[str, Any]) -> list[str]:
    out = []
    for pname, p in other["parameters"].items():
        q = full["parameters"][pname]
        if (p["determined"], p["covered"]) != (q["determined"], q["covered"]) \
                or abs(p["error_pct"] - q["error_pct"]) > MOVED_PCT:
            out.append(f"{other['case']} seed {other['seed']} {pname}: {_cell(q)} → {_cell(p)}")
    return out


def markdown(rows: list[dict[str, Any]], command: str) -> str:
    full = {(r["case"], r["seed"]): r for r in rows if r["stage"] == "full"}
    lines = ["# What each stage of the calibration search earns", "", "```sh", command, "```",
             "", "| removed | intervals holding the truth | determined | determined, truth "
             "outside | runs (median per case) | wall s (median) |", "|---|---|---|---|---|---|"]
    moved: list[str] = []
    for stage in dict.fromkeys(r["stage"] for r in rows):
        mine = [r for r in rows if r["stage"] == stage]
        params = [p for r in mine for p in r["parameters"].values()]
        det = [p for p in params if p["determined"]]
        runs = sorted(r["runs"] for r in mine)
        walls = sorted(r["wall_s"] for r in mine)
        lines.append(f"| {stage} | {sum(p['covered'] for p in params)} of {len(params)} | "
                     f"{len(det)} | {sum(not p['covered'] for p in det)} | "
                     f"{runs[len(runs) // 2]} | {walls[len(walls) // 2]:.1f} |")
        if stage != "full":
            changes = [m for r in mine if (r["case"], r["seed"]) in full
                       for m in _moved(full[(r["case"], r["seed"])], r)]
            moved += [f"- **{stage}**: {m}" for m in changes] or [f"- **{stage}**: no change"]
    return "\n".join([*lines, "", "Changes against the full search (verdict, interval, or "
                       f"error by more than {MOVED_PCT} points):", "", *moved, ""])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--stages", nargs="*", default=list(STAGES), choices=list(STAGES))
    parser.add_argument("--cases", nargs="*", default=None)
    parser.add_argument("--seeds", type=int, default=1)
    parser.add_argument("--first-seed", type=int, default=0)
    args = parser.parse_args()
    cases = args.cases or runner.case_names()
    unknown = sorted(set(cases) - set(runner.case_names()))
    if unknown:
        raise SystemExit(f"unknown case {unknown[0]!r}; cases: {', '.join(runner.case_names())}")
    measured_dir = args.out / "measured"
    measured_dir.mkdir(parents=True, exist_ok=True)
    rows = []
    for seed in range(args.first_seed, args.first_seed + args.seeds):
        for name in cases:
            for stage in ["full", *args.stages]:
                row = calibrate_case(name, seed, stage, measured_dir)
                print(f"{stage} {name} seed {seed}: {row['wall_s']:.1f} s, {row['runs']} runs, "
                      + "; ".join(f"{n} {_cell(p)}" for n, p in row["parameters"].items()),
                      flush=True)
                rows.append(row)
    flat = [{k: v for k, v in r.items() if k != "parameters"} | {"parameter": n, **p}
            for r in rows for n, p in r["parameters"].items()]
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(flat[0]))
    writer.writeheader()
    writer.writerows(flat)
    atomic_write_text(args.out / "stages.csv", buffer.getvalue())
    command = "python benchmarks/calibration_stages.py " + " ".join(sys.argv[1:])
    text = markdown(rows, command)
    atomic_write_text(args.out / "stages.md", text)
    print(text)


if __name__ == "__main__":
    main()
