"""Figures of a closed-loop comparison, as a controls engineer reads them.

- ``control_tracking.png``: the end effector's reference and actual position per axis, and
  below each the error zoomed in (every controller);
- ``control_error.png``: the error norms of position, velocity and acceleration over time (log);
- ``control_joints.png``: joint angles against the reference, and their deviations;
- ``control_torque.png``: the total actuator torque with its limits, the torque each controller
  adds, the outer loop's part v, and where the guard acted.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_path

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from jointplay.neural.control import Comparison

COLORS = {"open loop": "C3", "PD": "C2", "computed torque": "C4", "ARX-IMC": "C1",
          "neural IMC": "C0"}
LABELS = (("position", "m"), ("velocity", "m/s"), ("acceleration", "m/s²"))


def figure(rows: int, cols: int, width: float, height: float,
           sharex: bool = True) -> tuple[Figure, np.ndarray]:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    return fig, fig.subplots(rows, cols, squeeze=False, sharex=sharex)


def save(fig: Figure, path: Path) -> Path:
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=130)
    return path


def _width(name: str) -> float:
    return 1.3 if name == "neural IMC" else 0.8


def plot_comparison(comparison: Comparison, scene: Any, folder: Path) -> list[Path]:
    from jointplay.neural.control import dense_acceleration_error, tip_errors

    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise DescriptionError("--plot", f"cannot create folder {folder}: {err}") from None
    runs, ref = comparison.runs, comparison.reference
    joints: Sequence[int] = scene.robot.moving_joints
    nj = len(joints)
    base = 2 * nj
    t_ref = np.arange(ref.shape[0]) * scene.run.output_step
    skip = comparison.transient
    paths = []

    fig, axes = figure(4, 1, 10, 11)
    for row, comp in enumerate("xy"):
        col = base + row
        ax, err_ax = axes[2 * row, 0], axes[2 * row + 1, 0]
        ax.plot(t_ref, ref[:, col], "k--", lw=1.0, label="reference (ideal joints)")
        for name, run in runs.items():
            ax.plot(run.t, run.y[:, col], color=COLORS.get(name, "C5"), lw=_width(name),
                    label=name)
            err_ax.plot(run.t, run.y[:, col] - ref[: run.y.shape[0], col],
                        color=COLORS.get(name, "C5"), lw=_width(name))
        ax.set_ylabel(f"tip {comp} [m]")
        err_ax.set_ylabel(f"{comp} error [m]")
        closed = [r for n, r in runs.items() if n != "open loop"]
        if closed:  # zoom on the controlled errors after the settling, not the open loop's
            span = max(float(np.max(np.abs(r.y[skip:, col] - ref[skip: r.y.shape[0], col])))
                       for r in closed if r.y.shape[0] > skip) if any(
                r.y.shape[0] > skip for r in closed) else 0.0
            if span > 0 and math.isfinite(span):
                err_ax.set_ylim(-1.2 * span, 1.2 * span)
        for a in (ax, err_ax):
            a.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle(f"{scene.name}: end-effector tracking; error axes zoomed to the controlled "
                 f"runs after {skip * scene.run.output_step * 1e3:g} ms")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=3)
    paths.append(save(fig, folder / "control_tracking.png"))

    fig, axes = figure(3, 1, 10, 9)
    for row, (label, unit) in enumerate(LABELS):
        ax = axes[row, 0]
        floor = math.inf
        for name, run in runs.items():
            e, t = tip_errors(run, ref, nj)[label], run.t
            if label == "acceleration" and run.dense_t.size and comparison.dense_reference.size:
                # between samples too, as the metrics take it
                e = np.concatenate([e[:1], dense_acceleration_error(
                    run, comparison.dense_reference)])
                t = np.concatenate([run.t[:1], run.dense_t])
            if e.size > 1:
                floor = min(floor, 0.01 * float(np.median(e[1:])))
                ax.semilogy(t[1:], np.maximum(e[1:], 1e-15), color=COLORS.get(name, "C5"),
                            lw=_width(name), label=name)
        if math.isfinite(floor) and floor > 0:
            ax.set_ylim(bottom=floor)  # every run starts on the reference: e(0) = 0
        ax.axvline(skip * scene.run.output_step, color="0.5", lw=0.7, ls=":")
        ax.set_ylabel(f"|{label} error| [{unit}]")
        ax.grid(True, which="both", alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle(f"{scene.name}: end-effector error vs the ideal-joint robot (dotted: end of "
                 "the settling transient)")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=5)
    paths.append(save(fig, folder / "control_error.png"))

    fig, axes = figure(2, nj, 6 * nj, 7)
    for j in range(nj):
        ax, dev_ax = axes[0, j], axes[1, j]
        ax.plot(t_ref, ref[:, j], "k--", lw=1.0, label="reference")
        for name, run in runs.items():
            ax.plot(run.t, run.y[:, j], color=COLORS.get(name, "C5"), lw=_width(name),
                    label=name)
            dev_ax.plot(run.t, 1e3 * (run.y[:, j] - ref[: run.y.shape[0], j]),
                        color=COLORS.get(name, "C5"), lw=_width(name))
        ax.set_ylabel(f"q{joints[j]} [rad]")
        dev_ax.set_ylabel(f"q{joints[j]} deviation [mrad]")
        dev_ax.set_xlabel("time [s]")
        for a in (ax, dev_ax):
            a.grid(True, alpha=0.3)
    fig.suptitle(f"{scene.name}: joint angles")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=6)
    paths.append(save(fig, folder / "control_joints.png"))

    limits = None
    ctrl = comparison.controllers.get("neural IMC") or next(
        iter(comparison.controllers.values()), None)
    if ctrl is not None:
        limits = ctrl.settings.torque_limit
    ff = comparison.tau_ff
    fig, axes = figure(2, nj, 6 * nj, 7)
    for j in range(nj):
        ax, add_ax = axes[0, j], axes[1, j]
        for name, run in runs.items():
            total = run.tau[:, j] + (ff[: run.tau.shape[0], j] if ff.size else 0.0)
            ax.plot(run.t, total, color=COLORS.get(name, "C5"), lw=_width(name), label=name)
            if name != "open loop":
                add_ax.plot(run.t, run.tau[:, j], color=COLORS.get(name, "C5"),
                            lw=_width(name), label=f"{name}: added")
            if np.any(run.v):
                add_ax.plot(run.t, run.v[:, j], color=COLORS.get(name, "C5"), lw=0.6, ls=":",
                            label=f"{name}: outer loop v")
            if run.flags.size and np.any(run.flags[:, 0] > 0.5):
                hit = run.t[: run.flags.shape[0]][run.flags[:, 0] > 0.5]
                add_ax.plot(hit, np.zeros_like(hit), "|", color=COLORS.get(name, "C5"),
                            ms=10, label=f"{name}: network distrusted")
        if limits is not None and math.isfinite(limits[j]):
            for sign in (-1, 1):
                ax.axhline(sign * limits[j], color="k", lw=0.8, ls="--")
        ax.set_ylabel(f"joint {joints[j]} total torque [N m] (dashed: limits)")
        add_ax.set_ylabel(f"joint {joints[j]} added torque [N m]")
        add_ax.set_xlabel("time [s]")
        for a in (ax, add_ax):
            a.grid(True, alpha=0.3)
    handles, labels = [], []
    for a in (axes[0, 0], axes[1, 0]):
        h, lab = a.get_legend_handles_labels()
        handles += h
        labels += lab
    fig.legend(handles, labels, loc="outside lower center", ncols=4)
    fig.suptitle(f"{scene.name}: actuator torque")
    paths.append(save(fig, folder / "control_torque.png"))
    return paths


__all__ = ["COLORS", "figure", "plot_comparison", "save"]
