"""Run ``jointplay calibrate`` on every benchmark case and seed, as a user would; one table.

Per case (data/NAME, written by generate.py) and noise seed: Gaussian noise of the case's
standard deviations is added to the stored noiseless motion (seeded by the case's name and
the seed), written to a CSV, and

    jointplay calibrate data/NAME/scene.toml --measured FILE --free A,B,C --out DIR
                        [--noise COLUMN=SIGMA,...]     (only where the case states the noise)

runs in a process of its own. From its calibration.json: each parameter's estimate, its
error (% of the truth), whether its 95 % interval holds the truth, its verdict; chi²/dof;
the noise estimate against the truth where not stated. Wall time is the process's, CPU
time the process's and its workers' (``resource.getrusage(RUSAGE_CHILDREN)``).

Summary: coverage (the fraction of intervals holding the truth), parameters reported
determined with the truth outside their interval, the accuracy goals (clearances within
2 %, friction within 5 %, where determined), median and worst wall per case and overall, and
the same in units of the machine's speed, measured before each run (:func:`machine_reference`):
on a shared machine the same calibration, on the same path, took 0.56 to 1.69 times its wall
at another hour (2026-11-30 and 12-01).
"""

from __future__ import annotations

import csv
import hashlib
import json
import os
import platform
import resource
import signal
import subprocess
import sys
import time
import zlib
from pathlib import Path
from typing import Any

import numpy as np

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
ACCURACY = {"clearance": 0.02, "mu": 0.05}  # relative error goals where determined


def load_case(name: str) -> tuple[dict[str, Any], np.ndarray, list[str]]:
    """The case's record, its noiseless table (time first) and the table's header; the
    table's hash checked against the record's."""
    folder = DATA / name
    record = json.loads((folder / "case.json").read_text())
    text = (folder / "truth.csv").read_text()
    if hashlib.sha256(text.encode()).hexdigest() != record["truth_csv_sha256"]:
        raise SystemExit(f"{folder / 'truth.csv'} does not match its case.json hash; rerun "
                         "python benchmarks/calibration_cases/generate.py")
    header = text.splitlines()[0].split(",")
    table = np.loadtxt(folder / "truth.csv", delimiter=",", skiprows=1, ndmin=2)
    return record, table, header


def case_names() -> list[str]:
    return sorted(p.name for p in DATA.iterdir() if (p / "case.json").is_file())


def noisy_csv(record: dict[str, Any], table: np.ndarray, header: list[str], seed: int,
              path: Path) -> None:
    rng = np.random.default_rng([seed, zlib.crc32(record["name"].encode())])
    noisy = table.copy()
    for k, column in enumerate(header[1:], start=1):
        noisy[:, k] += record["noise"][column] * rng.standard_normal(len(table))
    lines = [",".join(header)] + [",".join(f"{v:.17g}" for v in row) for row in noisy]
    path.write_text("\n".join(lines) + "\n")


def _calibrate_command() -> list[str]:
    return [sys.executable, "-m", "jointplay.cli", "calibrate"]


def run_one(name: str, seed: int, out: Path, timeout_s: float) -> dict[str, Any]:
    """One calibration of case ``name`` with noise seed ``seed``; its row."""
    record, table, header = load_case(name)
    folder = out / "runs" / name / f"seed{seed}"
    folder.mkdir(parents=True, exist_ok=True)
    measured = folder / "measured.csv"
    noisy_csv(record, table, header, seed, measured)
    result_dir = folder / "calibration"
    command = [*_calibrate_command(), str(DATA / name / "scene.toml"), "--measured",
               str(measured), "--free", ",".join(record["free"]), "--out", str(result_dir)]
    if record["noise_stated"]:
        command += ["--noise", ",".join(f"{c}={s!r}" for c, s in record["noise"].items())]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    status = "ok"
    (folder / "row.json").unlink(missing_ok=True)
    with open(folder / "log.txt", "w") as log:
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT,
                                   start_new_session=True)
        try:
            rc = process.wait(timeout=timeout_s)
            if rc != 0:
                status = f"exit {rc}"
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            status = f"timeout {timeout_s:g} s"
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    row: dict[str, Any] = {"case": name, "seed": seed, "noise_stated": record["noise_stated"],
                           "columns": "+".join(record["columns"]), "status": status,
                           "wall_s": wall, "cpu_s": cpu, "command": " ".join(command)}
    result_file = result_dir / "calibration.json"
    if status != "ok" or not result_file.is_file():
        row["status"] = status if status != "ok" else "no calibration.json"
        row["parameters"] = {}
        return row
    result = json.loads(result_file.read_text())
    row["parameters"] = {}
    for pname in record["free"]:
        truth = record["truth"][pname]
        e = result["estimates"][pname]
        row["parameters"][pname] = {
            "truth": truth, "estimate": e["value"], "std": e.get("std"),
            "low95": e["low95"], "high95": e["high95"],
            "error_pct": 100.0 * (e["value"] - truth) / truth,
            "covered": bool(e["low95"] <= truth <= e["high95"]),
            "determined": bool(e["determined"]),
            "inseparable": pname in record.get("inseparable", []),
        }
    residuals = result.get("residuals", {})
    row["chi2_dof"] = residuals.get("normalised_chi2")
    noise = result.get("noise", {}).get("std", {})
    if isinstance(noise, dict) and not record["noise_stated"]:
        row["noise_ratio"] = {c: noise[c] / s for c, s in record["noise"].items() if c in noise}
    row["warnings"] = len(result.get("warnings", []))
    row["reported_wall_s"] = result.get("wall_time_s")
    row["stages"] = stage_effects(result)
    return row


def stage_effects(result: dict[str, Any]) -> dict[str, Any]:
    """What each stage of the search did in one calibration (from its calibration.json):
    its runs, and whether the checks after the whole-record fit changed the outcome: the
    basin check moved the estimate to a lower minimum or widened an interval, the valley
    check widened one, the residual check withdrew every verdict."""
    warnings = result.get("warnings", [])
    stages = result.get("continuation") or []
    record_end = stages[-1]["end"] if stages else None
    estimate = [e["value"] for e in result["estimates"].values()]
    moved = record_end is not None and not np.allclose(estimate, record_end, rtol=1e-12,
                                                       atol=0.0)
    whole = stages[-1]["chi2"] if stages else None
    final = result.get("residuals", {}).get("chi2")
    return {
        "runs": result.get("simulations_by_kind", {}),
        "basin check moved the estimate": bool(moved),
        "chi2 lowered by": (whole - final) if moved and whole is not None
        and final is not None else 0.0,
        "basin check widened": any("other minimum" in w or "not the quadratic" in w
                                   for w in warnings),
        "valley check widened": any("not determined by the search" in w for w in warnings),
        "residual check withdrew the verdicts": any(w.startswith("nothing is determined")
                                                    for w in warnings),
    }


def _goal(pname: str) -> float | None:
    if pname.endswith(".clearance"):
        return ACCURACY["clearance"]
    if pname == "friction.mu":
        return ACCURACY["mu"]
    return None


REFERENCE_CODE = """
import statistics, time, jointplay
scene = jointplay.default_scene()
rtol, atol = jointplay.CalibrationOptions().tightened(scene.run.rtol, scene.run.atol)
scene = scene.with_run(rtol=rtol, atol=atol)
jointplay.simulate(scene, peaks=False)
seconds = []
for _ in range(5):
    start = time.process_time()
    jointplay.simulate(scene, peaks=False)
    seconds.append(time.process_time() - start)
print(statistics.median(seconds))
"""


def machine_reference() -> float:
    """CPU seconds of one plain run of the paper scene over its 2 s at the fit's tolerances
    (median of five, in a process of its own, after one untimed): the machine's speed now, by
    which the times of runs on different machines or days compare. A RuntimeError with the
    child's last line of error where it fails (a broken install: the benchmark stops at once)."""
    done = subprocess.run([sys.executable, "-c", REFERENCE_CODE], capture_output=True, text=True)
    if done.returncode != 0 or not done.stdout.split():
        last = (done.stderr.strip().splitlines() or ["no message"])[-1]
        raise RuntimeError(f"the machine reference (a plain run of the paper scene in a child "
                           f"process) failed with exit status {done.returncode}: {last}")
    return float(done.stdout.split()[-1])


def summarise(rows: list[dict[str, Any]]) -> dict[str, Any]:
    params = [(r, n, p) for r in rows for n, p in r["parameters"].items()]
    determined = [(r, n, p) for r, n, p in params if p["determined"]]
    goals = [(n, p, goal) for _, n, p in determined if (goal := _goal(n)) is not None]
    walls = [r["wall_s"] for r in rows]
    per_case: dict[str, list[float]] = {}
    for r in rows:
        per_case.setdefault(r["case"], []).append(r["wall_s"])
    return {
        "runs": len(rows), "failed": sum(r["status"] != "ok" for r in rows),
        "intervals": len(params), "covered": sum(p["covered"] for _, _, p in params),
        "determined": len(determined),
        "determined_outside": sum(not p["covered"] for _, _, p in determined),
        "goals_checked": len(goals),
        "goals_met": sum(abs(p["error_pct"]) <= 100 * g for _, p, g in goals),
        "wall_median_s": float(np.median(walls)) if walls else None,
        "wall_worst_s": float(np.max(walls)) if walls else None,
        "cpu_median_s": float(np.median([r["cpu_s"] for r in rows])) if rows else None,
        "wall_by_case": {c: (float(np.median(w)), float(np.max(w))) for c, w in per_case.items()},
        "references": _in_references(rows),
    }


def _in_references(rows: list[dict[str, Any]]) -> tuple[float, float, float] | None:
    """The walls in units of the reference measured before each run, median and worst, and
    the references' median (s); None where a run has none."""
    if not rows or any(not r.get("reference_s") for r in rows):
        return None
    ratios = [r["wall_s"] / r["reference_s"] for r in rows]
    return (float(np.median(ratios)), float(np.max(ratios)),
            float(np.median([r["reference_s"] for r in rows])))


def _cell(p: dict[str, Any]) -> str:
    verdict = "det." if p["determined"] else "not det."
    holds = "in" if p["covered"] else "**out**"
    return f"{p['error_pct']:+.2f} % ({holds}, {verdict})"


def markdown(rows: list[dict[str, Any]], summary: dict[str, Any], command: str) -> str:
    import scipy

    load = ", ".join(f"{v:.2f}" for v in os.getloadavg())
    lines = ["# Calibration benchmark: cases", "", "```sh", command, "```", "",
             f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
             f"load average at the end {load} (times on a shared machine are inflated); "
             f"Python {platform.python_version()}, NumPy {np.__version__}, "
             f"SciPy {scipy.__version__}.", "",
             "Each cell: error of the estimate (% of the truth), whether the 95 % interval "
             "holds the truth, the verdict (determined or not).", "",
             "| case | seed | noise | parameters | chi²/dof | noise est. / truth | warnings "
             "| wall s | CPU s | status |", "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        params = "; ".join(f"{n}: {_cell(p)}" for n, p in r["parameters"].items())
        ratio = r.get("noise_ratio") or {}
        noise = "stated" if r["noise_stated"] else "estimated"
        ratios = ", ".join(f"{c} {v:.2f}" for c, v in ratio.items()) \
            if not r["noise_stated"] else "-"
        chi2 = f"{r['chi2_dof']:.3g}" if r.get("chi2_dof") is not None else "-"
        lines.append(f"| {r['case']} | {r['seed']} | {noise} | {params or '-'} | {chi2} | "
                     f"{ratios} | {r.get('warnings', '-')} | {r['wall_s']:.1f} | "
                     f"{r['cpu_s']:.1f} | {r['status']} |")
    s = summary
    cov = f"{s['covered']} of {s['intervals']}" + \
        (f" ({s['covered'] / s['intervals']:.0%})" if s["intervals"] else "")
    lines += ["", "## Summary", "",
              f"- runs: {s['runs']}, failed or timed out: {s['failed']}",
              f"- 95 % intervals holding the truth: {cov} (goal: at least 95 %)",
              f"- reported determined with the truth outside the interval: "
              f"{s['determined_outside']} of {s['determined']} determined (goal: 0)",
              f"- accuracy where determined (clearances within 2 %, friction within 5 %): "
              f"{s['goals_met']} of {s['goals_checked']}",
              f"- wall per run, median / worst: {_s(s['wall_median_s'])} / "
              f"{_s(s['wall_worst_s'])} s (goal: 60 / 120 s on 2 cores); CPU median "
              f"{_s(s['cpu_median_s'])} s", _references_line(s["references"]), "",
              "| case | wall median / worst s |", "|---|---|"]
    lines += [f"| {c} | {m:.1f} / {w:.1f} |" for c, (m, w) in s["wall_by_case"].items()]
    lines += ["", "## What each stage did", "",
              "Runs of each stage, and whether a check after the whole-record fit changed "
              "the outcome (yes: it did in that run).", "",
              "| case | seed | grid and windows | valley check | basin lines | basin check "
              "moved (chi² lower by) / widened | valley check widened | residual check "
              "withdrew |",
              "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        st = r.get("stages")
        if not st:
            continue
        runs = st["runs"]

        def yes(key: str, stages: dict[str, Any] = st) -> str:
            return "yes" if stages[key] else "no"

        lines.append(f"| {r['case']} | {r['seed']} | {runs.get('continuation windows', 0)} | "
                     f"{runs.get('valley check', 0)} | {runs.get('basin lines', 0)} | "
                     f"{_moved(st)} / {yes('basin check widened')}"
                     f" | {yes('valley check widened')} | "
                     f"{yes('residual check withdrew the verdicts')} |")
    return "\n".join(lines) + "\n"


def _references_line(references: tuple[float, float, float] | None) -> str:
    if references is None:
        return "- wall in machine references: - (not measured)"
    median, worst, reference = references
    return (f"- wall per run in machine references (its wall over the CPU seconds of one plain "
            f"run of the paper scene at the fit's tolerances, measured just before it; median "
            f"{reference:.3f} s), median / worst: {median:.0f} / {worst:.0f}")


def _moved(stages: dict[str, Any]) -> str:
    if not stages["basin check moved the estimate"]:
        return "no"
    return f"yes ({stages.get('chi2 lowered by', 0.0):.3g})"


def _s(v: float | None) -> str:
    return "-" if v is None else f"{v:.1f}"


def flat_rows(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """One CSV row per case, seed and parameter."""
    out = []
    for r in rows:
        base = {k: r.get(k) for k in ("case", "seed", "noise_stated", "columns", "status",
                                      "chi2_dof", "warnings", "wall_s", "cpu_s")}
        base["noise_ratio"] = ";".join(f"{c}={v:.4g}" for c, v in
                                       (r.get("noise_ratio") or {}).items())
        for n, p in (r["parameters"] or {"-": {}}).items():
            out.append({**base, "parameter": n, **p})
    return out


def run(cases: list[str], seeds: int, first_seed: int, out: Path, timeout_s: float,
        command: str, resume: bool = False) -> dict[str, Any]:
    known = case_names()
    unknown = [c for c in cases if c not in known]
    if unknown:
        raise SystemExit(f"unknown case {unknown[0]!r}; cases: {', '.join(known)}")
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for name in cases or known:
        for seed in range(first_seed, first_seed + seeds):
            done = out / "runs" / name / f"seed{seed}" / "row.json"
            if resume and done.is_file():  # a finished run of an earlier, interrupted call
                row = json.loads(done.read_text())
                result_file = done.parent / "calibration" / "calibration.json"
                if row["status"] == "ok" and result_file.is_file():
                    row["stages"] = stage_effects(json.loads(result_file.read_text()))
            else:
                reference = machine_reference()
                row = {**run_one(name, seed, out, timeout_s), "reference_s": reference}
                done.write_text(json.dumps(row, indent=1) + "\n")
            print(f"{name} seed {seed}: {row['status']}, {row['wall_s']:.1f} s wall, "
                  + "; ".join(f"{n} {_cell(p)}" for n, p in row["parameters"].items()),
                  flush=True)
            rows.append(row)
    summary = summarise(rows)
    (out / "cases.json").write_text(json.dumps({"command": command, "rows": rows,
                                                "summary": summary}, indent=1) + "\n")
    flat = flat_rows(rows)
    fields = list(dict.fromkeys(k for row in flat for k in row))
    with open(out / "cases.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=fields)
        writer.writeheader()
        writer.writerows(flat)
    text = markdown(rows, summary, command)
    (out / "cases.md").write_text(text)
    print(text)
    return summary
