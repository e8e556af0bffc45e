"""The figures a reader of the clearance-joint literature expects of a mechanism run.

The output's acceleration and velocity against the ideal mechanism's (the slider of a
slider-crank, the rocker's angle of a four-bar: :mod:`jointplay.mechanism.output`), the
journal's orbit inside its clearance circle, the contact force, the driving torque (against
the ideal's): each an atomic PNG (:func:`jointplay.common.figures.save`), drawn on the
samples, with the located contact phases' peak forces marked where they were located (not
read off the samples).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from jointplay.common.figures import figure, save
from jointplay.mechanism.output import figure_stem, followed
from jointplay.mechanism.simulate import MechanismResult


def _output(result: MechanismResult) -> tuple[str, str, str, str, str]:
    """The coordinate whose motion is drawn against the ideal's (the run's output: the
    file's ``[output]``, or :mod:`jointplay.mechanism.output`'s rule), its figures' name
    stem, the axis's word for it, and its units of rate and acceleration."""
    name = followed(result.output, result.coordinates)
    unit = result.units[result.coordinates.index(name)]
    stem, what = figure_stem(name, unit)
    return name, stem, what, f"{unit}/s", f"{unit}/s²"


def _revolutions_axis(ax: object, result: MechanismResult) -> None:
    ax.set_xlabel("time (s)")  # type: ignore[attr-defined]
    ax.grid(True, alpha=0.3)  # type: ignore[attr-defined]


def write_figures(result: MechanismResult, folder: str | Path) -> list[Path]:
    """Draw every figure into ``folder`` (created by the caller); returns the paths."""
    folder = Path(folder)
    output, stem, what, rate_unit, acc_unit = _output(result)
    k = result.coordinates.index(output)
    n = len(result.coordinates)
    ideal = result.ideal
    paths = []
    t = result.t
    for name, values, ideal_values, label in (
            (f"{stem}_acceleration.png", result.acceleration[:, k],
             ideal["acceleration"][:, k] if ideal else None,
             f"{what} acceleration ({acc_unit})"),
            (f"{stem}_velocity.png", result.x[:, n + k],
             ideal["x"][:, n + k] if ideal else None, f"{what} velocity ({rate_unit})")):
        fig, axes = figure(1, 1, 7.0, 3.6)
        ax = axes[0, 0]
        ax.plot(t, values, lw=0.8, label=f"clearance joint ({result.name})")
        if ideal_values is not None:
            ax.plot(t, ideal_values, lw=1.0, ls="--", color="k", label="ideal mechanism")
        ax.set_ylabel(label)
        ax.legend(loc="best", fontsize=8)
        _revolutions_axis(ax, result)
        paths.append(save(fig, folder / name))
    if result.cut_joints:
        fig, axes = figure(1, 1, 4.6, 4.6)
        ax = axes[0, 0]
        for j, joint in enumerate(result.cut_joints):
            c = result.clearance[j]
            ring = np.linspace(0, 2 * np.pi, 361)
            ax.plot(c * 1e3 * np.cos(ring), c * 1e3 * np.sin(ring), color="0.5", lw=0.8)
            ax.plot(result.eccentricity[:, j, 0] * 1e3, result.eccentricity[:, j, 1] * 1e3,
                    lw=0.7, label=f"{joint}", gid="orbit")
        ax.set_aspect("equal")
        ax.set_xlabel("eccentricity x (mm)")
        ax.set_ylabel("eccentricity y (mm)")
        ax.set_title("journal centre in its clearance circle", fontsize=9)
        paths.append(save(fig, folder / "journal_orbit.png"))
        fig, axes = figure(1, 1, 7.0, 3.6)
        ax = axes[0, 0]
        for j, joint in enumerate(result.cut_joints):
            ax.plot(t, result.normal_force[:, j], lw=0.8, label=f"{joint} (samples)")
            rows = (result.impacts.joint == j + 1) & np.isfinite(result.impacts.peak_force)
            if rows.any():  # a fixed-step run locates no peaks
                ax.plot(result.impacts.peak_force_time[rows], result.impacts.peak_force[rows],
                        "v", ms=4, label=f"{joint}: located peaks")
        ax.set_ylabel("contact force (N)")
        ax.legend(loc="best", fontsize=8)
        _revolutions_axis(ax, result)
        paths.append(save(fig, folder / "contact_force.png"))
    fig, axes = figure(1, 1, 7.0, 3.6)
    ax = axes[0, 0]
    ax.plot(t, result.driving_torque, lw=0.8, label="clearance joint")
    if ideal is not None:
        ax.plot(t, ideal["driving_torque"], lw=1.0, ls="--", color="k", label="ideal mechanism")
    ax.set_ylabel("driving torque (N m)")
    ax.legend(loc="best", fontsize=8)
    _revolutions_axis(ax, result)
    paths.append(save(fig, folder / "driving_torque.png"))
    return paths
