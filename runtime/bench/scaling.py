"""Scaling with the number of links: derive, emit and compile time from a cold start, and the
cost of a simulated second, each case in a fresh process (see :mod:`jointplay.bench.child`)."""

from __future__ import annotations

import json
import os
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.bench.child import ChildFailed, json_from_child
from jointplay.bench.measure import run_counts, timed_runs
from jointplay.bench.report import heading, markdown_table, write_report
from jointplay.common.figures import figure, save

if TYPE_CHECKING:
    from jointplay.scene.definition import Scene

SCALING_SIM_TIME = 0.2
SCALING_TORQUE = "1.0*sin(2*pi*t)"  # N m on every moving joint of the scaling chains
STRUCTURES: tuple[str, ...] = ("clearance", "ideal")

SCALING_COLUMNS: list[tuple[str, str, str]] = [
    ("structure", "structure", "{}"),
    ("k", "k", "{}"),
    ("n_coords", "n", "{}"),
    ("derive_s", "derive s", "{:.2f}"),
    ("emit_s", "emit s", "{:.2f}"),
    ("compile_s", "gcc s", "{:.2f}"),
    ("build_s", "build s", "{:.2f}"),
    ("sim_cpu_s", "sim CPU s", "{:.3f}"),
    ("cost_per_sim_s", "CPU s per sim s", "{:.3f}"),
    ("sim_wall_per_sim_s", "wall s per sim s", "{:.3f}"),
    ("steps", "steps", "{}"),
    ("rhs_evaluations", "rhs evals", "{}"),
    ("jacobian_evaluations", "Jac evals", "{}"),
    ("impacts", "impacts", "{}"),
]
SCALING_CSV_KEYS: list[str] = [
    "structure", "k", "n_coords", "derive_s", "kane_s", "emit_s", "compile_s", "build_s",
    "sim_time", "repeats", "sim_cpu_s", "sim_cpu_min_s", "sim_cpu_max_s", "cost_per_sim_s",
    "sim_wall_s", "sim_wall_per_sim_s", "steps", "rhs_evaluations", "jacobian_evaluations",
    "events", "impacts", "load_start", "load_end", "error"]


def scaling_scene(robot: Any, sim_time: float) -> Scene:
    """A short driven motion: hanging straight down at rest, sinusoidal torque on every joint."""
    from jointplay.scene.definition import scene_from_dict

    torques = {f"joint{j}": SCALING_TORQUE for j in robot.moving_joints} if robot.drive else {}
    initial = {"q1": "-pi/2"} if 1 in robot.moving_joints else {}
    return scene_from_dict({
        "name": robot.name, "robot": robot.to_dict(), "torques": torques, "initial": initial,
        "run": {"t_end": sim_time, "output_step": 1e-3, "integrator": "bdf",
                "rtol": 1e-6, "atol": 1e-6}})


def scaling_case(spec: dict[str, Any]) -> dict[str, Any]:
    """Measure one (structure, k) from a cold start: derive, emit, gcc into an empty cache,
    then simulate ``sim_time`` seconds ``repeats`` times. Runs in a fresh process."""
    with tempfile.TemporaryDirectory(prefix="jointplay-bench-") as tmp_name:
        tmp = Path(tmp_name)
        os.environ["JOINTPLAY_CACHE"] = str(tmp / "cache")

        import jointplay
        from jointplay.derive import write_generated
        from jointplay.store.build import DEFAULT_CFLAGS, compile_source
        from jointplay.store.model import load_model

        structure, k = str(spec["structure"]), int(spec["k"])
        robot = jointplay.uniform_chain(k, kinds=[structure] * k, name=f"{structure}{k}")
        load_start = os.getloadavg()[0]
        emitted = write_generated(robot, tmp / "model")
        _, compile_s = compile_source(emitted.source, DEFAULT_CFLAGS, cache=tmp / "cache")
        model = load_model(tmp / "model")
        sim_time = float(spec["sim_time"])
        timed = timed_runs(scaling_scene(robot, sim_time), model, int(spec["repeats"]))
        row: dict[str, Any] = {
            "structure": structure, "k": k, "n_coords": model.n_coordinates,
            "derive_s": emitted.timings["derive"], "kane_s": emitted.timings.get("kane"),
            "emit_s": emitted.timings["emit"], "compile_s": compile_s,
            "build_s": emitted.timings["derive"] + emitted.timings["emit"] + compile_s,
            "sim_time": sim_time, "repeats": len(timed.cpu_s),
            **run_counts(timed.result), "load_start": load_start,
            "load_end": os.getloadavg()[0], "error": timed.failure or "",
        }
        if timed.result is not None:
            cpu = timed.spread("cpu")
            wall = timed.spread("wall")
            row.update(sim_cpu_s=cpu["cpu_median_s"], sim_cpu_min_s=cpu["cpu_min_s"],
                       sim_cpu_max_s=cpu["cpu_max_s"],
                       cost_per_sim_s=cpu["cpu_median_s"] / sim_time,
                       sim_wall_s=wall["wall_median_s"],
                       sim_wall_per_sim_s=wall["wall_median_s"] / sim_time)
        return row


_WORKER = ("import json, sys; from jointplay.bench.scaling import scaling_case; "
           "print(json.dumps(scaling_case(json.loads(sys.argv[1]))))")


def run_scaling_case(spec: dict[str, Any], timeout: float) -> dict[str, Any]:
    """:func:`scaling_case` in a fresh interpreter (sympy's caches cold); killed on timeout."""
    try:
        return json_from_child([sys.executable, "-c", _WORKER, json.dumps(spec)], timeout)
    except ChildFailed as err:
        return {"structure": spec["structure"], "k": spec["k"], "error": str(err)}


def scaling(links: Sequence[int], structures: Sequence[str] = STRUCTURES, *,
            sim_time: float = SCALING_SIM_TIME, repeats: int = 3, timeout: float = 1200.0,
            quiet: bool = False) -> list[dict[str, Any]]:
    from tqdm import tqdm

    cases = [(s, k) for s in structures for k in links]
    rows = []
    with tqdm(cases, unit="case", disable=quiet, dynamic_ncols=True) as bar:
        for structure, k in bar:
            bar.set_description(f"{structure} k={k}")
            row = run_scaling_case({"structure": structure, "k": k, "sim_time": sim_time,
                                    "repeats": repeats}, timeout)
            rows.append(row)
            if row.get("error") and "cost_per_sim_s" not in row:
                tqdm.write(f"{structure} k={k}: FAILED {row['error']}")
            elif not quiet:
                tqdm.write(f"{structure} k={k}: build {row['build_s']:.2f} s, "
                           f"{row['cost_per_sim_s']:.3f} CPU s per simulated s")
    return rows


def _plot_scaling(rows: list[dict[str, Any]], path: Path, sim_time: float) -> Path:
    fig, axes = figure(1, 2, 11.0, 4.2)
    styles = {"clearance": "-", "ideal": "--"}
    for structure in dict.fromkeys(r["structure"] for r in rows):
        ok = [r for r in rows if r["structure"] == structure and "build_s" in r]
        if not ok:
            continue
        k = [r["k"] for r in ok]
        for i, (key, label) in enumerate((("derive_s", "derive"), ("emit_s", "emit"),
                                          ("compile_s", "gcc"), ("build_s", "total"))):
            axes[0, 0].plot(k, [r[key] for r in ok], styles.get(structure, "-"), marker="o",
                            ms=3, color=f"C{i}", label=f"{label} ({structure})")
        sim = [r for r in ok if r.get("cost_per_sim_s") is not None]
        axes[0, 1].plot([r["k"] for r in sim], [r["cost_per_sim_s"] for r in sim],
                        styles.get(structure, "-"), marker="o", ms=3, label=structure)
    axes[0, 0].set_ylabel("seconds (cold process, empty cache)")
    axes[0, 0].set_title("derive, emit and compile", fontsize=10)
    axes[0, 1].set_ylabel("CPU s per simulated second")
    axes[0, 1].set_title(f"simulation ({sim_time:g} s driven motion, bdf rtol 1e-6)",
                         fontsize=10)
    for ax in axes[0]:
        ax.set_yscale("log")
        ax.set_xlabel("links k")
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=7)
    return save(fig, path)


def write_scaling(rows: list[dict[str, Any]], out: Path, *, sim_time: float,
                  facts: dict[str, str], command: str = "") -> list[Path]:
    md = heading("Scaling with the number of links", command)
    md += ["- each case in a fresh process with an empty compile cache: sympy derivation "
           "(Kane's method), CasADi emission, gcc with the default flags",
           f"- simulation: uniform chain of 0.3 m, 1 kg rods hanging at rest, torque "
           f"{SCALING_TORQUE} N m on every joint, {sim_time:g} s with bdf rtol = atol = "
           "1e-6; CPU time median over the repeats, divided by the simulated time",
           "- clearance: every joint has 0.03 mm radial clearance (Lankarani-Nikravesh "
           "contact, Coulomb friction); ideal: every joint ideal",
           *(f"- {k}: {v}" for k, v in facts.items()), "",
           markdown_table(rows, SCALING_COLUMNS), ""]
    failed = [r for r in rows if r.get("error")]
    if failed:
        md += ["## Failed or incomplete cases", ""]
        md += [f"- {r['structure']} k={r['k']}: {r['error']}" for r in failed]
        md.append("")
    return write_report(out, "scaling", rows, SCALING_CSV_KEYS, md,
                        lambda path: _plot_scaling(rows, path, sim_time))
