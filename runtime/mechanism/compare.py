"""Mechanism runs side by side (``jointplay compare`` on mechanism results files): their
output's acceleration (the slider, the rocker's angle), journal orbits, contact forces and
driving torques overlaid, and a table of what differs, each run against the first."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.figures import figure, save
from jointplay.mechanism.plots import _output
from jointplay.mechanism.simulate import MechanismResult

Runs = list[tuple[str, MechanismResult]]


def check_comparable(runs: Runs) -> None:
    first = runs[0][1]
    for label, result in runs[1:]:
        if result.coordinates != first.coordinates or result.cut_joints != first.cut_joints:
            raise DescriptionError("RUN.h5", f"{label} is another mechanism (coordinates "
                                   f"{result.coordinates}, not {first.coordinates}); compare "
                                   "runs of one mechanism")


def _common(a: MechanismResult, b: MechanismResult) -> tuple[np.ndarray, np.ndarray]:
    """Indices of the samples the two runs share (same times)."""
    _, ia, ib = np.intersect1d(np.round(a.t, 12), np.round(b.t, 12), return_indices=True)
    return ia, ib


def difference_rows(runs: Runs) -> list[dict[str, float | str]]:
    first = runs[0][1]
    name = _output(first)[0]
    k = first.coordinates.index(name)
    rows: list[dict[str, float | str]] = []
    for label, result in runs:
        ia, ib = _common(first, result)
        rows.append({
            "run": label, "impacts": float(len(result.impacts)),
            "largest_force": max((result.largest_contact_force(j + 1)[0]
                                  for j in range(len(result.cut_joints))), default=0.0),
            "distance": float(np.max(np.abs(first.x[ia, k] - result.x[ib, k]), initial=0.0)),
            "shared": float(ia.size),
            "energy_residual": float(np.max(np.abs(result.energy_residual)))})
    return rows


def difference_table(runs: Runs) -> str:
    first = runs[0][1]
    name = _output(first)[0]
    unit = first.units[first.coordinates.index(name)]
    how = ("located" if all(r.step is None for _, r in runs)
           else "located; on the samples at a fixed step")
    lines = [f"| run | impacts | largest contact force (N, {how}) | {name} from "
             f"{runs[0][0]}'s ({unit}, shared samples) | energy balance (J) |",
             "|---|---|---|---|---|"]
    for row in difference_rows(runs):
        lines.append(f"| {row['run']} | {row['impacts']:.0f} | {row['largest_force']:.4g} | "
                     f"{row['distance']:.3g} ({row['shared']:.0f}) | "
                     f"{row['energy_residual']:.2g} |")
    return "\n".join(lines)


def compare_figures(runs: Runs, folder: str | Path) -> list[Path]:
    folder = Path(folder)
    first = runs[0][1]
    name, stem, what, _, acc_unit = _output(first)
    k = first.coordinates.index(name)
    paths = []
    series = (
        (f"{stem}_acceleration.png", f"{what} acceleration ({acc_unit})",
         lambda r: r.acceleration[:, k]),
        ("driving_torque.png", "driving torque (N m)", lambda r: r.driving_torque))
    for file, label, values in series:
        fig, axes = figure(1, 1, 7.0, 3.6)
        ax = axes[0, 0]
        for run_label, result in runs:
            ax.plot(result.t, values(result), lw=0.8, label=run_label)
        ax.set_xlabel("time (s)")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
        paths.append(save(fig, folder / file))
    if first.cut_joints:
        fig, axes = figure(1, 1, 4.6, 4.6)
        ax = axes[0, 0]
        c = first.clearance[0]
        ring = np.linspace(0, 2 * np.pi, 361)
        ax.plot(c * 1e3 * np.cos(ring), c * 1e3 * np.sin(ring), color="0.5", lw=0.8)
        for run_label, result in runs:
            ax.plot(result.eccentricity[:, 0, 0] * 1e3, result.eccentricity[:, 0, 1] * 1e3,
                    lw=0.7, label=run_label, gid=f"orbit:{run_label}")
        ax.set_aspect("equal")
        ax.set_xlabel("eccentricity x (mm)")
        ax.set_ylabel("eccentricity y (mm)")
        ax.set_title(f"{first.cut_joints[0]}: journal centre in its clearance circle",
                     fontsize=9)
        ax.legend(loc="best", fontsize=7)
        paths.append(save(fig, folder / "journal_orbit.png"))
        fig, axes = figure(1, 1, 7.0, 3.6)
        ax = axes[0, 0]
        for run_label, result in runs:
            line, = ax.plot(result.t, result.normal_force[:, 0], lw=0.8, label=run_label)
            rows = (result.impacts.joint == 1) & np.isfinite(result.impacts.peak_force)
            if rows.any():  # a fixed-step run locates no peaks
                ax.plot(result.impacts.peak_force_time[rows], result.impacts.peak_force[rows],
                        "v", ms=4, color=line.get_color())
        ax.set_xlabel("time (s)")
        ax.set_ylabel(f"{first.cut_joints[0]} contact force (N; located peaks ▼)")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
        paths.append(save(fig, folder / "contact_force.png"))
    return paths
