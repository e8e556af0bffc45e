"""What the figures of the first command cost, side by side with the job around them.

On the paper scene (``jointplay.default_scene()``, its ideal twin beside it): each of the
eight default figures drawn alone in this process; the whole set by ``plot_result`` drawn in
this process, and in a figure process (:mod:`jointplay.common.figure_process`, started and
given time to load matplotlib first, as the command starts it early: the wall time runs from
handing it the jobs to the files written, the CPU time is both processes', its start-up
included); ``--animate`` of a 0.5 s run (frames per second); and the warm main job
``jointplay simulate --compare-ideal --out run.h5 --plot plots`` against the same without
``--plot`` and with its figures drawn in its own process (``JOINTPLAY_FIGURE_PROCESS=0``),
each in a fresh interpreter with its byte code cached (as installed). Optionally
(``--sweep``) the 12-case example sweep (``scenes/sweep_clearance.toml``) with the default
engine against ``--workers 0``.

Every row gives the median wall time and the median CPU time (this process and its children:
the figure process, the command's interpreter and its figure process) over ``--repeats``
runs, with the worst wall time; on a machine other jobs share, wall time rises with the load
while CPU time stays nearer the unloaded cost. Rows of two versions (``--against``) give the
ratio of this one's medians to the other's. Writes ``figures.csv`` and ``figures.md`` into
``--out`` (atomically) and prints the Markdown.

    python benchmarks/figures.py --out out/bench/figures --repeats 3 --sweep

``--against DIR`` also times the main job and an animation by another version of the
package (a folder holding it as ``DIR/jointplay``), alternating with this one.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from jointplay import default_scene, simulate
from jointplay.bench import machine_facts, markdown_table, to_csv
from jointplay.common import figure_process, figures
from jointplay.common.files import atomic_write_text
from jointplay.results import plots
from jointplay.results.animate import animate_result
from jointplay.results.derived import dense_eccentricity

COLUMNS = [("what", "what", "{}"), ("wall_s", "wall s (median)", "{:.3f}"),
           ("worst_wall_s", "wall s (worst)", "{:.3f}"),
           ("cpu_s", "CPU s (median)", "{:.3f}"), ("rate", "frames per s (wall / CPU)", "{}"),
           ("ratio", "this / other (wall, CPU)", "{}")]
# Seconds a figure process is given to load matplotlib before it is handed the jobs (it
# takes about 1 s on an idle machine; the command starts it that long before it needs it).
WARM_S = 4.0
SWEEP = Path(__file__).resolve().parents[1] / "scenes" / "sweep_clearance.toml"


def cpu_seconds() -> float:
    """CPU time of this process and of its children that have ended."""
    own, children = (resource.getrusage(who) for who in (resource.RUSAGE_SELF,
                                                          resource.RUSAGE_CHILDREN))
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def timed(what: str, work: Callable[[], Any], repeats: int) -> dict[str, Any]:
    """The row of ``what``: median wall and CPU seconds of ``work`` over ``repeats`` runs."""
    walls, cpus = [], []
    for _ in range(repeats):
        cpu, start = cpu_seconds(), time.perf_counter()
        work()
        walls.append(time.perf_counter() - start)
        cpus.append(cpu_seconds() - cpu)
    return {"what": what, "wall_s": statistics.median(walls), "worst_wall_s": max(walls),
            "cpu_s": statistics.median(cpus)}


def command(argv: list[str], folder: Path, package: Path | None = None,
            extra_env: dict[str, str] | None = None) -> Callable[[], None]:
    """A run of ``jointplay ARGV`` in ``folder``, in a fresh interpreter that may write byte
    code (as an installed package has it); ``package``: a folder holding another version's
    ``jointplay`` package, imported instead of this one."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if package is not None:
        env["PYTHONPATH"] = str(package)
    env.update(extra_env or {})

    def run() -> None:
        subprocess.run([sys.executable, "-m", "jointplay.cli", *argv], cwd=folder, env=env,
                       check=True, capture_output=True, timeout=900)

    return run


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="folder for the CSV and Markdown")
    parser.add_argument("--repeats", type=int, default=3, help="runs of each row")
    parser.add_argument("--against", metavar="DIR", type=Path,
                        help="a folder holding another version's jointplay package (e.g. "
                             "git main's runtime/ as DIR/jointplay, with derive/ and "
                             "generated/ inside it): its main job and animation command are "
                             "timed in the same rounds, alternating")
    parser.add_argument("--sweep", action="store_true",
                        help="also the 12-case example sweep, default engine against "
                             "--workers 0 (about a minute each on a loaded machine)")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scene = default_scene()
    result = simulate(scene, compare_ideal=True)
    dense = dense_eccentricity(result)
    rows: list[dict[str, Any]] = []
    with tempfile.TemporaryDirectory(prefix="jointplay-figures-") as scratch:
        folder = Path(scratch)
        figures.WORKERS = 1
        plots.plot_result(result, folder / "warm")  # matplotlib imported, fonts loaded
        each = [("end_effector.png", lambda p: plots.plot_end_effector(result, p))]
        for k, joint in enumerate(result.clearance_joints):
            each.append((f"orbit_joint{joint}.png",
                         lambda p, k=k: plots.plot_orbit(result, k, p, dense)))
        each.append(("contact_force.png", lambda p: plots.plot_contact_force(result, p)))
        for k, joint in enumerate(result.clearance_joints):
            each.append((f"contact_timeline_joint{joint}.png",
                         lambda p, k=k: plots.plot_contact_timeline(result, k, p)))
        each += [("eccentricity_ratio.png", lambda p: plots.plot_eccentricity_ratio(result, p)),
                 ("energy.png", lambda p: plots.plot_energy(result, p))]
        for name, draw in each:
            rows.append(timed(name, lambda draw=draw, name=name: draw(folder / name),
                              args.repeats))
        rows.append(timed(f"the {len(each)} figures, plot_result, in this process (the default)",
                          lambda: plots.plot_result(result, folder / "serial"), args.repeats))
        rows.append(_in_figure_process(result, folder / "process", len(each), args.repeats))
        short = simulate(scene.with_run(t_end=0.5))
        row = timed("--animate, 0.5 s run (250 frames, GIF)",
                    lambda: animate_result(short, folder / "arm.gif"), args.repeats)
        frames = 250
        row["rate"] = f"{frames / row['wall_s']:.0f} / {frames / row['cpu_s']:.0f}"
        rows.append(row)
        job = ["simulate", "--compare-ideal", "--out", "run.h5"]
        with_plots = [*job, "--plot", "plots"]
        command(with_plots, folder)()  # byte code and models cached
        rows.append(timed("warm main job: simulate --compare-ideal --out run.h5",
                          command(job, folder), args.repeats))
        rows.append(timed("warm main job with --plot plots (figures in the figure process, "
                          "the default)", command(with_plots, folder), args.repeats))
        rows.append(timed("warm main job with --plot plots, figures in the command's process "
                          "(JOINTPLAY_FIGURE_PROCESS=0)",
                          command(with_plots, folder, extra_env={"JOINTPLAY_FIGURE_PROCESS": "0"}),
                          args.repeats))
        if args.against is not None:
            _against(rows, folder, args.against, job, args.repeats)
        if args.sweep:
            sweep = ["sweep", str(SWEEP), "--quiet"]
            for label, extra in (("default engine", []), ("--workers 0", ["--workers", "0"])):
                rows.append(timed(f"example sweep (12 cases), {label}",
                                  lambda extra=extra: _fresh_sweep(folder, sweep, extra), 1))
    md = ["# What the figures of the first command cost", "",
          f"Command: `python benchmarks/figures.py --out {args.out} --repeats {args.repeats}"
          + (f" --against {args.against}" if args.against else "")
          + (" --sweep`" if args.sweep else "`"), "",
          f"- scene: {scene.name}, {scene.run.t_end:g} s, with its ideal twin; "
          f"{args.repeats} runs per row (the sweeps: one each)",
          *(f"- {k}: {v}" for k, v in machine_facts().items()), "",
          markdown_table(rows, COLUMNS), ""]
    atomic_write_text(out / "figures.csv", to_csv(rows, [c[0] for c in COLUMNS]))
    atomic_write_text(out / "figures.md", "\n".join(md))
    print("\n".join(md))


def _in_figure_process(result: Any, folder: Path, count: int, repeats: int) -> dict[str, Any]:
    """The row of the figure set drawn by a figure process, started WARM_S earlier."""
    walls, cpus = [], []
    for _ in range(repeats):
        cpu = cpu_seconds()
        with figure_process.FigureProcess() as process:
            time.sleep(WARM_S)
            start = time.perf_counter()
            plots.plot_result(result, folder, process=process)
            walls.append(time.perf_counter() - start)
        cpus.append(cpu_seconds() - cpu)  # the process has ended: its CPU time is counted
    return {"what": f"the {count} figures, plot_result, in a warm figure process (wall: "
                    "jobs handed over to files written; CPU: both processes, its start-up "
                    "included)",
            "wall_s": statistics.median(walls), "worst_wall_s": max(walls),
            "cpu_s": statistics.median(cpus)}


def _against(rows: list[dict[str, Any]], folder: Path, package: Path, job: list[str],
             repeats: int) -> None:
    """The main job with and without --plot, and a 0.1 s run animated (101 frames), by this
    version and by the one in ``package``, alternating run by run."""
    animate = ["simulate", "--t-end", "0.1", "--no-verify", "--quiet", "--animate", "arm.gif"]
    cases = [("warm main job", job), ("warm main job with --plot plots",
                                      [*job, "--plot", "plots"]),
             ("simulate --t-end 0.1 --animate arm.gif (101 frames)", animate)]
    for what, argv in cases:
        here, there = command(argv, folder), command(argv, folder, package)
        there()  # byte code of the other version written
        pair: dict[str, list[dict[str, Any]]] = {"this": [], "other": []}
        for _ in range(repeats):
            pair["this"].append(timed(what, here, 1))
            pair["other"].append(timed(what, there, 1))
        medians = {}
        for side, label in (("other", f"{what} [{package}]"), ("this", f"{what} [this]")):
            walls = [r["wall_s"] for r in pair[side]]
            medians[side] = {"what": label, "wall_s": statistics.median(walls),
                             "worst_wall_s": max(walls),
                             "cpu_s": statistics.median(r["cpu_s"] for r in pair[side])}
            rows.append(medians[side])
        medians["this"]["ratio"] = (
            f"{medians['this']['wall_s'] / medians['other']['wall_s']:.2f}, "
            f"{medians['this']['cpu_s'] / medians['other']['cpu_s']:.2f}")


def _fresh_sweep(folder: Path, sweep: list[str], extra: list[str]) -> None:
    """The sweep into a new output folder (nothing reused from an earlier run)."""
    target = Path(tempfile.mkdtemp(prefix="sweep-", dir=folder))
    command([*sweep, "--out", str(target), *extra], folder)()


if __name__ == "__main__":
    main()
