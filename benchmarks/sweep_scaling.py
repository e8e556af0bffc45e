"""Throughput of parameter sweeps: cases per second against the number of Dask workers.

The sweep is the paper scene (``scenes/paper_4dof.toml``) over a short ``--t-end``: a log grid
of joint 2's radial clearance times two friction coefficients (``--cases`` in all). Measured,
each on a fresh output folder so that nothing is reused:

* ``loop``: a plain serial loop of ``simulate(..., compare_ideal=True)`` in this process, no
  Dask, no files: the baseline;
* ``in-process``: ``run_sweep(workers=0)``: the same cases with the shared ideal run and the
  durable per-case files, the table and no plots;
* ``dask``, for each worker count: a local cluster of that many single-threaded worker
  processes. ``cluster_start_s`` is the time to start it; ``cold`` is the first sweep on it
  (each worker imports jointplay and loads the model from the compile cache on its first
  case); ``warm`` is a second sweep of the same cases on the same, now warm, workers.

``mean_case_s`` and ``mean_case_cpu_s`` are the mean wall and CPU time of one case where it
ran: wall well above CPU means the case waited for a core (workers contending with each other
or with other work on the machine). ``load_avg`` is the machine's 1-minute load average before
the measurement: other work on the machine skews every figure.

Writes ``sweep_scaling.csv`` and ``sweep_scaling.md`` into ``--out`` (atomically) and prints
the Markdown.

    python benchmarks/sweep_scaling.py --out out/sweep_scaling
    python benchmarks/sweep_scaling.py --workers 1,2,4 --cases 32 --t-end 0.2 --out out/s
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import io
import logging
import math
import os
import platform
import tempfile
import time
from pathlib import Path
from typing import Any

COLUMNS = ("mode", "workers", "cases", "cluster_start_s", "cold_s", "cold_cases_per_s",
           "warm_s", "warm_cases_per_s", "speedup_vs_loop", "mean_case_s", "mean_case_cpu_s",
           "load_avg")


def _sweep(cases: int, t_end: float) -> Any:
    from jointplay.sweep import sweep_from_dict

    num = max(1, cases // 2)
    return sweep_from_dict({
        "name": "sweep_scaling",
        "scene": "default",
        "run": {"t_end": t_end},
        "parameters": {
            "joint2.clearance": {"start": 1e-5, "stop": 1e-4, "num": num, "spacing": "log"},
            "friction.mu": {"values": [0.0, 0.1]},
        },
    }, source="sweep_scaling")


def _loop(sweep: Any) -> tuple[float, float]:
    """Elapsed wall and CPU seconds of a plain loop over the cases."""
    from jointplay.common.errors import SimulationError
    from jointplay.sim import load_scene_model, simulate

    model = load_scene_model(sweep.scene)
    load_scene_model(sweep.scene, ideal=True)
    start, cpu = time.perf_counter(), time.process_time()
    for case in sweep.cases:
        # A failed case still costs its time, as in a sweep.
        with contextlib.suppress(SimulationError):
            simulate(case.scene, model=model, compare_ideal=True, quiet=True)
    return time.perf_counter() - start, time.process_time() - cpu


def _timed_sweep(sweep: Any, root: Path, **kwargs: Any) -> tuple[float, float, float]:
    """Elapsed seconds, and the mean wall and CPU time of one case where it ran."""
    from jointplay.sweep import run_sweep

    out = Path(tempfile.mkdtemp(dir=root))
    start = time.perf_counter()
    result = run_sweep(sweep, out, plots=False, quiet=True, **kwargs)
    elapsed = time.perf_counter() - start
    assert result.ran == len(sweep.cases), "a benchmark sweep must not reuse cases"
    wall = result.table.column("wall_time_s").to_pylist()
    cpu = result.table.column("cpu_time_s").to_pylist()
    return elapsed, sum(wall) / len(wall), sum(cpu) / len(cpu)


def _row(mode: str, workers: int, cases: int, loop_s: float, start_s: float | None,
         cold_s: float | None, warm_s: float, mean_case_s: float, mean_cpu_s: float,
         load: float) -> dict[str, Any]:
    return {"mode": mode, "workers": workers, "cases": cases,
            "cluster_start_s": start_s, "cold_s": cold_s,
            "cold_cases_per_s": cases / cold_s if cold_s else None,
            "warm_s": warm_s, "warm_cases_per_s": cases / warm_s,
            "speedup_vs_loop": loop_s / warm_s, "mean_case_s": mean_case_s,
            "mean_case_cpu_s": mean_cpu_s, "load_avg": load}


def _load() -> float:
    """1-minute load average: other work on the machine skews every figure."""
    return os.getloadavg()[0] if hasattr(os, "getloadavg") else math.nan


def measure(worker_counts: list[int], cases: int, t_end: float) -> list[dict[str, Any]]:
    from distributed import Client, LocalCluster

    sweep = _sweep(cases, t_end)
    n = len(sweep.cases)
    rows = []
    with tempfile.TemporaryDirectory(prefix="sweep_scaling_") as tmp:
        root = Path(tmp)
        _loop(sweep)  # warm this process: model loads, integrator set-up
        load = _load()
        loop_s, loop_cpu = _loop(sweep)
        rows.append(_row("loop", 0, n, loop_s, None, None, loop_s, loop_s / n, loop_cpu / n,
                         load))
        load = _load()
        elapsed, mean_case, mean_cpu = _timed_sweep(sweep, root, workers=0)
        rows.append(_row("in-process", 0, n, loop_s, None, None, elapsed, mean_case, mean_cpu,
                         load))
        for w in worker_counts:
            load = _load()
            t0 = time.perf_counter()
            cluster = LocalCluster(n_workers=w, threads_per_worker=1, processes=True,
                                   dashboard_address=None, silence_logs=logging.ERROR)
            client = Client(cluster)
            client.wait_for_workers(w)
            start_s = time.perf_counter() - t0
            try:
                cold, _, _ = _timed_sweep(sweep, root, client=client)
                warm, mean_case, mean_cpu = _timed_sweep(sweep, root, client=client)
            finally:
                client.close()
                cluster.close()
            rows.append(_row("dask", w, n, loop_s, start_s, cold, warm, mean_case, mean_cpu,
                             load))
    return rows


def _fmt(value: Any) -> str:
    if value is None:
        return ""
    return f"{value:.3g}" if isinstance(value, float) else str(value)


def to_markdown(rows: list[dict[str, Any]], meta: str) -> str:
    lines = [meta, "", "| " + " | ".join(COLUMNS) + " |",
             "|" + "|".join("---" for _ in COLUMNS) + "|"]
    lines += ["| " + " | ".join(_fmt(r[c]) for c in COLUMNS) + " |" for r in rows]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else \
        (os.cpu_count() or 1)
    parser.add_argument("--workers", default=",".join(str(w) for w in range(1, cores + 1)),
                        help="worker counts, comma-separated (default 1..cores)")
    parser.add_argument("--cases", type=int, default=16, help="cases in the sweep (even)")
    parser.add_argument("--t-end", type=float, default=0.1, help="simulated time per case (s)")
    parser.add_argument("--out", required=True, help="folder for the CSV and Markdown")
    args = parser.parse_args(argv)
    counts = [int(w) for w in args.workers.split(",") if w.strip()]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = measure(counts, args.cases, args.t_end)
    from jointplay.common.files import atomic_write_text

    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    atomic_write_text(out / "sweep_scaling.csv", buf.getvalue())
    meta = (f"Sweep throughput: paper scene, t_end = {args.t_end:g} s, {rows[0]['cases']} "
            f"cases; {platform.processor() or platform.machine()}, {cores} usable core(s), "
            f"Python {platform.python_version()}. Times in s; warm = second sweep on the "
            "same workers.")
    md = to_markdown(rows, meta)
    atomic_write_text(out / "sweep_scaling.md", md)
    print(md, end="")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
