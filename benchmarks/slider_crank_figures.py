"""Figures and feature table of docs/results/slider-crank.md: the slider-crank's first revolution.

jointplay (scenes/slider_crank.toml and its 0.1 mm variant, rtol = atol = 1e-10, with the
ideal mechanism from ``--compare-ideal``) beside the outside Exudyn model
(tests/exudyn_slider_crank.py, DOPRI5 at rtol 1e-10, atol 1e-12):

- exudyn_slider_crank_acceleration.png: the slider's acceleration against the crank angle,
  ideal and with 0.5 mm clearance (jointplay; Exudyn dashed over it);
- exudyn_slider_crank_orbits.png: the journal centre's path in its clearance circle, 0.5 and
  0.1 mm;
- exudyn_slider_crank_torque.png: the driving torque, ideal and with clearance.

The table (Markdown, printed and written to --out) lists located features only (impact count,
largest contact force, fastest approach, time in contact from onsets and separations), for
jointplay and Exudyn.

    python benchmarks/slider_crank_figures.py --img docs/img --out DIR
"""

from __future__ import annotations

import argparse
import datetime
import math
import sys
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from exudyn_slider_crank import SliderCrank, simulate

from jointplay.bench import machine_facts, markdown_table
from jointplay.mechanism.model import model_for
from jointplay.mechanism.reading import load_mechanism_scene
from jointplay.mechanism.simulate import simulate_mechanism

ROOT = Path(__file__).resolve().parents[1]
REVOLUTION = 0.012
CASES = (("0.5 mm", "scenes/slider_crank.toml", 10.5e-3),
         ("0.1 mm", "scenes/slider_crank_0_1mm.toml", 10.1e-3))
FEATURES = [("case", "case", "{}"), ("code", "code", "{}"), ("impacts", "impacts", "{}"),
            ("force", "largest contact force (N)", "{:.5g}"),
            ("speed", "fastest approach (m/s)", "{:.4g}"),
            ("contact", "time in contact (% of the revolution)", "{:.2f}")]


def run_case(scene_file: str, bearing_radius: float) -> dict[str, Any]:
    scene = load_mechanism_scene(str(ROOT / scene_file))
    run = scene.with_run(t_end=REVOLUTION, output_step=1e-5, rtol=1e-10, atol=1e-10)
    ours = simulate_mechanism(run, model=model_for(scene.mechanism), compare_ideal=True)
    theirs = simulate(SliderCrank(bearing_radius=bearing_radius), REVOLUTION, rtol=1e-10,
                      atol=1e-12)
    return {"ours": ours, "theirs": theirs, "at": theirs.at(ours.t),
            "clearance": bearing_radius - 10.0e-3}


def features(label: str, case: dict[str, Any]) -> list[dict[str, Any]]:
    """Located quantities only: impact onsets, separations and peak forces."""
    ours, theirs = case["ours"], case["theirs"]
    imp = ours.impacts
    return [
        {"case": label, "code": "jointplay", "impacts": len(imp.time),
         "force": float(np.max(imp.peak_force)), "speed": float(np.max(imp.speed)),
         "contact": 100.0 * float(np.sum(imp.duration)) / REVOLUTION},
        {"case": label, "code": "Exudyn", "impacts": len(theirs.impacts),
         "force": max(i.peak_force for i in theirs.impacts),
         "speed": max(i.approach_speed for i in theirs.impacts),
         "contact": 100.0 * sum((REVOLUTION if math.isnan(i.separation) else i.separation)
                                - i.onset for i in theirs.impacts) / REVOLUTION},
    ]


def _pyplot() -> Any:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def plot_series(cases: dict[str, dict[str, Any]], key: str, ylabel: str, path: Path) -> None:
    plt = _pyplot()
    case = cases["0.5 mm"]
    ours, at = case["ours"], case["at"]
    angle = np.degrees(2.0 * np.pi * ours.t / REVOLUTION)
    if key == "acceleration":
        ideal = ours.ideal["acceleration"][:, 0]
        mine, theirs = ours.coordinate_acceleration("guide.position"), at["slider_acceleration"]
    else:
        ideal, mine, theirs = (ours.ideal["driving_torque"], ours.driving_torque,
                               at["driving_torque"])
    fig, ax = plt.subplots(figsize=(7.0, 3.0), dpi=90)
    ax.plot(angle, mine, lw=0.8, color="tab:blue", label="jointplay, 0.5 mm clearance")
    ax.plot(angle, theirs, lw=0.8, ls="--", color="tab:orange", label="Exudyn, 0.5 mm")
    ax.plot(angle, ideal, lw=1.2, color="black", label="ideal joints")
    ax.set_xlabel("crank angle (deg)")
    ax.set_ylabel(ylabel)
    ax.set_xlim(0.0, 360.0)
    ax.set_xticks(range(0, 361, 45))
    ax.legend(fontsize=7, loc="upper right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def plot_orbits(cases: dict[str, dict[str, Any]], path: Path) -> None:
    plt = _pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.4), dpi=90)
    for ax, (label, case) in zip(axes, cases.items(), strict=True):
        c = case["clearance"]
        circle = np.linspace(0.0, 2.0 * np.pi, 200)
        ax.plot(np.cos(circle), np.sin(circle), color="black", lw=1.0)
        e = case["ours"].eccentricity[:, 0, :] / c
        ax.plot(e[:, 0], e[:, 1], lw=0.7, color="tab:blue", label="jointplay")
        ex = case["at"]["orbit"] / c
        ax.plot(ex[:, 0], ex[:, 1], lw=0.7, ls="--", color="tab:orange", label="Exudyn")
        ax.set_aspect("equal")
        ax.set_title(f"{label} clearance", fontsize=9)
        ax.set_xlabel("e_x / c")
        ax.set_ylabel("e_y / c")
        ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--img", type=Path, default=ROOT / "docs" / "img")
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args(argv)
    cases = {label: run_case(scene, rb) for label, scene, rb in CASES}
    args.img.mkdir(parents=True, exist_ok=True)
    outputs = {
        "exudyn_slider_crank_acceleration.png": lambda p: plot_series(
            cases, "acceleration", "slider acceleration (m/s²)", p),
        "exudyn_slider_crank_torque.png": lambda p: plot_series(cases, "torque",
                                                         "driving torque (N m)", p),
        "exudyn_slider_crank_orbits.png": lambda p: plot_orbits(cases, p),
    }
    for name, draw in outputs.items():
        part = args.img / (name + ".part.png")
        draw(part)
        part.replace(args.img / name)
    rows = [row for label, case in cases.items() for row in features(label, case)]
    report = "\n".join([
        "# The slider-crank's first revolution: features", "",
        f"Measured {datetime.date.today().isoformat()}; jointplay rtol = atol = 1e-10, "
        "Exudyn rtol 1e-10, atol 1e-12.", "", markdown_table(rows, FEATURES), "",
        "## Machine", "", *(f"- {k}: {v}" for k, v in machine_facts().items()), ""])
    args.out.mkdir(parents=True, exist_ok=True)
    part = args.out / "slider_crank_features.md.part"
    part.write_text(report, encoding="utf-8")
    part.replace(args.out / "slider_crank_features.md")
    print(report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
