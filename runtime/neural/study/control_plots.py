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
from jointplay.common.figures import figure, save
from jointplay.neural.control.metrics import dense_acceleration_error, tip_errors

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from jointplay.neural.control.loop import Run
    from jointplay.neural.study.comparison import Comparison

COLORS = {"open loop": "C3", "PD": "C2", "computed torque": "C4", "ARX-IMC": "C1",
          "neural IMC": "C0"}
LABELS = (("position", "m"), ("velocity", "m/s"), ("acceleration", "m/s²"))


def _width(name: str) -> float:
    return 1.3 if name == "neural IMC" else 0.8


def plot_comparison(comparison: Comparison, scene: Any, folder: Path) -> list[Path]:
    """The four figures of the module docstring, written into ``folder``."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise DescriptionError("--plot", f"cannot create folder {folder}: {err}") from None
    return [save(_tracking(comparison, scene), folder / "control_tracking.png"),
            save(_errors(comparison, scene), folder / "control_error.png"),
            save(_joints(comparison, scene), folder / "control_joints.png"),
            save(_torque(comparison, scene), folder / "control_torque.png")]


def _color(name: str) -> str:
    return COLORS.get(name, "C5")


def _reference_time(comparison: Comparison, scene: Any) -> np.ndarray:
    return np.arange(comparison.reference.shape[0]) * scene.run.output_step


def _controlled_span(runs: dict[str, Run], ref: np.ndarray, col: int, skip: int) -> float:
    """The largest |error| of the controlled runs after the settling (0 when none is longer):
    the error axes zoom on it, not on the open loop's."""
    closed = [r for n, r in runs.items() if n != "open loop" and r.y.shape[0] > skip]
    if not closed:
        return 0.0
    return max(float(np.max(np.abs(r.y[skip:, col] - ref[skip: r.y.shape[0], col])))
               for r in closed)


def _tracking(comparison: Comparison, scene: Any) -> Figure:
    """The end effector's reference and actual position per axis, each with its error."""
    runs, ref, skip = comparison.runs, comparison.reference, comparison.transient
    base = 2 * len(scene.robot.moving_joints)
    t_ref = _reference_time(comparison, scene)
    fig, axes = figure(4, 1, 10, 11, sharex=True)
    for row, comp in enumerate("xy"):
        col = base + row
        ax, err_ax = axes[2 * row, 0], axes[2 * row + 1, 0]
        ax.plot(t_ref, ref[:, col], "k--", lw=1.0, label="reference (ideal joints)")
        for name, run in runs.items():
            ax.plot(run.t, run.y[:, col], color=_color(name), lw=_width(name), label=name)
            err_ax.plot(run.t, run.y[:, col] - ref[: run.y.shape[0], col],
                        color=_color(name), lw=_width(name))
        ax.set_ylabel(f"tip {comp} [m]")
        err_ax.set_ylabel(f"{comp} error [m]")
        span = _controlled_span(runs, ref, col, skip)
        if span > 0 and math.isfinite(span):
            err_ax.set_ylim(-1.2 * span, 1.2 * span)
        for a in (ax, err_ax):
            a.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle(f"{scene.name}: end-effector tracking; error axes zoomed to the controlled "
                 f"runs after {skip * scene.run.output_step * 1e3:g} ms")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=3)
    return fig


def _errors(comparison: Comparison, scene: Any) -> Figure:
    """The error norms of position, velocity and acceleration over time (log)."""
    runs, ref, skip = comparison.runs, comparison.reference, comparison.transient
    nj = len(scene.robot.moving_joints)
    fig, axes = figure(3, 1, 10, 9, sharex=True)
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
                ax.semilogy(t[1:], np.maximum(e[1:], 1e-15), color=_color(name),
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
    return fig


def _joints(comparison: Comparison, scene: Any) -> Figure:
    """Joint angles against the reference, and their deviations."""
    runs, ref = comparison.runs, comparison.reference
    joints: Sequence[int] = scene.robot.moving_joints
    nj = len(joints)
    t_ref = _reference_time(comparison, scene)
    fig, axes = figure(2, nj, 6 * nj, 7, sharex=True)
    for j in range(nj):
        ax, dev_ax = axes[0, j], axes[1, j]
        ax.plot(t_ref, ref[:, j], "k--", lw=1.0, label="reference")
        for name, run in runs.items():
            ax.plot(run.t, run.y[:, j], color=_color(name), lw=_width(name), label=name)
            dev_ax.plot(run.t, 1e3 * (run.y[:, j] - ref[: run.y.shape[0], j]),
                        color=_color(name), lw=_width(name))
        ax.set_ylabel(f"q{joints[j]} [rad]")
        dev_ax.set_ylabel(f"q{joints[j]} deviation [mrad]")
        dev_ax.set_xlabel("time [s]")
        for a in (ax, dev_ax):
            a.grid(True, alpha=0.3)
    fig.suptitle(f"{scene.name}: joint angles")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=6)
    return fig


def _torque(comparison: Comparison, scene: Any) -> Figure:
    """The total actuator torque with its limits, the torque each controller adds, the outer
    loop's part v, and where the guard acted."""
    runs = comparison.runs
    joints: Sequence[int] = scene.robot.moving_joints
    nj = len(joints)
    limits = None
    ctrl = comparison.controllers.get("neural IMC") or next(
        iter(comparison.controllers.values()), None)
    if ctrl is not None:
        limits = ctrl.settings.torque_limit
    ff = comparison.tau_ff
    fig, axes = figure(2, nj, 6 * nj, 7, sharex=True)
    for j in range(nj):
        ax, add_ax = axes[0, j], axes[1, j]
        for name, run in runs.items():
            total = run.tau[:, j] + (ff[: run.tau.shape[0], j] if ff.size else 0.0)
            ax.plot(run.t, total, color=_color(name), lw=_width(name), label=name)
            _added(add_ax, name, run, j)
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
    return fig


def _added(ax: Any, name: str, run: Run, j: int) -> None:
    """The torque a controller adds at joint index ``j``, its outer loop's v, and the samples
    on which the guard distrusted the controller's model."""
    if name != "open loop":
        ax.plot(run.t, run.tau[:, j], color=_color(name), lw=_width(name),
                label=f"{name}: added")
    if np.any(run.v):
        ax.plot(run.t, run.v[:, j], color=_color(name), lw=0.6, ls=":",
                label=f"{name}: outer loop v")
    if run.flags.size and np.any(run.flags[:, 0] > 0.5):
        hit = run.t[: run.flags.shape[0]][run.flags[:, 0] > 0.5]
        ax.plot(hit, np.zeros_like(hit), "|", color=_color(name), ms=10,
                label=f"{name}: model distrusted")


__all__ = ["COLORS", "figure", "plot_comparison", "save"]
