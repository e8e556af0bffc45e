"""The contact stiffness laws side by side: force against penetration, and the paper scene.

1. Force against penetration of every elastic law (Hertz's pin-in-hole K d^1.5 and the
   cylindrical laws of ``jointplay.derive.cylindrical``) on the default joint: 10 mm steel
   bearing, 0.03 mm radial clearance, a 20 mm long journal; evaluated from the same sympy
   expressions that are compiled into the models (``contact_laws.png``).
2. The paper scene (2 s) under each law, with the scene's damping (Lankarani-Nikravesh,
   ce = 0.9) and friction: the end effector's error against the same scene on ideal joints,
   the located peak normal force and penetration, the impact count, and the CPU time at the
   scene's own settings. The outputs compared are from runs at rtol = atol = 1e-9 (bdf), so
   the differences are the laws', not the integrator's (``contact_laws.csv``, ``.md``).

    python benchmarks/contact_laws.py --out out/bench/contact_laws
"""

from __future__ import annotations

import argparse
import csv
import io
import math
import statistics
import time
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np
import sympy as sp

from jointplay.bench import machine_facts, markdown_table
from jointplay.common.figures import figure, save
from jointplay.common.files import atomic_write_text
from jointplay.derive import cylindrical
from jointplay.derive.to_casadi import SympyToCasadi
from jointplay.robot import CONTACT_STIFFNESSES
from jointplay.robot.contact_laws import DEFAULT_LENGTH, with_stiffness
from jointplay.scene.definition import default_scene, ideal_counterpart
from jointplay.sim import load_scene_model, simulate

TIGHT = 1e-9
REPEATS = 3
COLUMNS = [
    ("stiffness", "stiffness law", "{}"),
    ("max_tip_error_m", "max tip error vs ideal m", "{:.3e}"),
    ("rms_tip_error_m", "RMS tip error m", "{:.3e}"),
    ("max_tip_difference_vs_hertz_m", "max tip difference vs hertz m", "{:.2e}"),
    ("peak_force_n", "peak normal force N", "{:.4g}"),
    ("max_penetration_m", "max penetration m", "{:.3e}"),
    ("impacts", "impacts", "{}"),
    ("cpu_median_s", "CPU s, scene settings", "{:.3f}"),
    ("tip_error_scene_vs_tight_m", "integration error at scene settings m", "{:.1e}"),
]


def _force_functions() -> dict[str, ca.Function]:
    """F_e(d; c, L, E*, Rb) for each law, from the compiled expressions."""
    d, c, length, e_star, rb = sp.symbols("d c L E R", real=True)
    leaves = [ca.SX.sym(n) for n in ("d", "c", "L", "E", "R")]
    convert = SympyToCasadi(dict(zip((d, c, length, e_star, rb), leaves, strict=True)))
    # Hertz's pin-in-hole law as compiled: K = 4/3 E* sqrt(Rb Rj / c), n = 1.5
    hertz = sp.Rational(4, 3) * e_star * sp.sqrt(rb * (rb - c) / c) \
        * sp.Piecewise((sp.Max(d, 1e-300) ** sp.Rational(3, 2), d > 0), (0, True))
    exprs = {"hertz": hertz} | {k: law(d, c, length, e_star).force
                               for k, law in cylindrical.LAWS.items()}
    return {k: ca.Function(k, leaves, [convert(e)]) for k, e in exprs.items()}


def forcefigure(path: Path) -> Path:
    robot = default_scene().robot
    joint = robot.joints[robot.clearance_joints[0] - 1]
    c = joint.bearing_radius - joint.journal_radius
    e_star = 1 / ((1 - joint.bearing_nu**2) / joint.bearing_E
                  + (1 - joint.journal_nu**2) / joint.journal_E)
    functions = _force_functions()
    depth = np.geomspace(1e-9, 0.5 * c, 400)
    fig, axes = figure(1, 2, 11.0, 4.2)
    for i, kind in enumerate(CONTACT_STIFFNESSES):
        force = [float(functions[kind](x, c, DEFAULT_LENGTH, e_star, joint.bearing_radius))
                 for x in depth]
        for ax in axes[0]:
            ax.plot(depth * 1e6, force, color=f"C{i}", label=kind)
    d_lim = 8 * c * math.exp(-3)
    for ax in axes[0]:
        ax.axvline(d_lim * 1e6, color="C1", lw=0.7, ls=":")
        ax.set_xlabel("penetration δ [µm]")
        ax.set_ylabel("elastic normal force F_e [N]")
        ax.grid(True, which="both", alpha=0.25)
    axes[0, 0].set_xscale("log")
    axes[0, 0].set_yscale("log")
    axes[0, 1].set_xlim(0, 0.5 * c * 1e6)
    axes[0, 1].set_ylim(0, None)
    axes[0, 1].text(d_lim * 1e6, 0, " johnson: tangent beyond 8c/e³", color="C1", fontsize=7,
                    rotation=90, va="bottom")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle(f"Elastic laws on the default joint: Rb = {joint.bearing_radius * 1e3:g} mm, "
                 f"c = {c * 1e6:g} µm, steel, L = {DEFAULT_LENGTH * 1e3:g} mm "
                 "(hertz has no length)", fontsize=10)
    return save(fig, path)


def _tip_errors(result: Any, ideal: Any) -> tuple[float, float]:
    err = np.linalg.norm(result.tip_position - ideal.tip_position, axis=1)
    return float(np.max(err)), float(np.sqrt(np.mean(err**2)))


def scene_rows() -> list[dict[str, Any]]:
    scene = default_scene()
    tight = {"rtol": TIGHT, "atol": TIGHT}
    ideal_scene = scene.with_robot(ideal_counterpart(scene.robot)).with_run(**tight)
    ideal = simulate(ideal_scene, model=load_scene_model(ideal_scene))
    rows = []
    runs: dict[str, Any] = {}
    for kind in CONTACT_STIFFNESSES:
        law_scene = scene.with_robot(with_stiffness(scene.robot, kind))
        model = load_scene_model(law_scene)
        accurate = runs[kind] = simulate(law_scene.with_run(**tight), model=model)
        cpu = []
        for _ in range(REPEATS):
            c0 = time.process_time()
            quick = simulate(law_scene, model=model)
            cpu.append(time.process_time() - c0)
        worst, rms = _tip_errors(accurate, ideal)
        imp = accurate.impacts
        rows.append({
            "stiffness": kind, "max_tip_error_m": worst, "rms_tip_error_m": rms,
            "max_tip_difference_vs_hertz_m": _tip_errors(accurate, runs["hertz"])[0],
            "peak_force_n": float(np.max(imp.peak_force)) if len(imp) else 0.0,
            "max_penetration_m": float(np.max(imp.max_penetration)) if len(imp) else 0.0,
            "impacts": len(imp), "cpu_median_s": statistics.median(cpu),
            "cpu_min_s": min(cpu), "cpu_max_s": max(cpu),
            "tip_error_scene_vs_tight_m": _tip_errors(quick, accurate)[0],
        })
        print(f"{kind}: {rows[-1]}", flush=True)
    return rows


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="folder for the PNG, CSV and Markdown")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    figure = forcefigure(out / "contact_laws.png")
    rows = scene_rows()
    keys = [*(k for k, _, _ in COLUMNS), "cpu_min_s", "cpu_max_s"]
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=keys, extrasaction="ignore")
    writer.writeheader()
    writer.writerows(rows)
    atomic_write_text(out / "contact_laws.csv", text.getvalue())
    md = ["# Contact stiffness laws on the paper scene", "",
          "Command: `python benchmarks/contact_laws.py --out " + str(args.out) + "`", "",
          f"- paper scene, 2 s; cylindrical laws with L = {DEFAULT_LENGTH * 1e3:g} mm journals; "
          f"errors and forces from bdf at rtol = atol = {TIGHT:g}; CPU median of {REPEATS} "
          f"runs at the scene's settings (bdf, rtol {default_scene().run.rtol:g}, atol "
          f"{default_scene().run.atol:g})",
          *(f"- {k}: {v}" for k, v in machine_facts().items()), "",
          markdown_table(rows, COLUMNS), ""]
    atomic_write_text(out / "contact_laws.md", "\n".join(md))
    print("\n".join(md))
    print(f"wrote {figure}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
