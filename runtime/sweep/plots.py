"""The sweep's figures: one PNG per swept name, the main metrics of every case against it."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.figures import figure, save
from jointplay.sweep.axes import Axis
from jointplay.sweep.spec import Sweep

MAX_PLOT_LINES = 10
PLOT_METRICS: tuple[tuple[str, str, str], ...] = (
    ("max_position_error", "max tip position error", "m"),
    ("max_velocity_error", "max tip velocity error", "m/s"),
    ("max_acceleration_error", "max tip acceleration error", "m/s²"),
    ("energy_dissipated", "energy dissipated", "J"),
    ("peak_normal_force", "peak normal force (located)", "N"),
    ("max_penetration", "max penetration (located)", "m"),
    ("impacts", "impacts", "count"),
    ("max_approach_speed", "largest approach speed", "m/s"),
)

DPI = 110


def plot_sweep(sweep: Sweep, table: Any, folder: str | Path) -> list[Path]:
    """One PNG per swept name: the main metrics of every successful case against it.

    In a product sweep, cases sharing the values of the other swept names are joined by a
    line (one line per combination, up to ``MAX_PLOT_LINES``), so each line is a 1-D cut.
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    data = table.to_pydict()
    ok = np.array([s == "ok" for s in data["status"]], dtype=bool)
    return [_plot_against(sweep, axis, data, ok, folder / f"{axis.name}.png")
            for axis in sweep.axes]


def _plot_against(sweep: Sweep, axis: Axis, data: dict[str, list[Any]], ok: np.ndarray,
                  path: Path) -> Path:
    """The figure of every metric against one swept name."""
    from matplotlib.ticker import NullFormatter

    from jointplay.results.plots import _scale

    raw_x = np.asarray(data[axis.name], dtype=np.float64)
    x_factor, x_prefix = _scale(raw_x) if swept_unit(sweep, axis.name) else (1.0, "")
    x = x_factor * raw_x
    others = [a.name for a in sweep.axes if a.name != axis.name]
    groups: dict[tuple[float, ...], list[int]] = {}
    for i in range(len(x)):
        groups.setdefault(tuple(data[o][i] for o in others), []).append(i)
    lines = sweep.mode == "product" and len(groups) <= MAX_PLOT_LINES
    fig, axs = figure(2, 4, 14.0, 6.4, sharex=True)
    for ax, (col, label, unit) in zip(axs.ravel(), PLOT_METRICS, strict=True):
        y = np.array([np.nan if v is None else v for v in data[col]], dtype=np.float64)
        keep = ok & np.isfinite(y)
        # An SI prefix instead of matplotlib's offset text, which sits where the title is.
        factor, prefix = _scale(y[keep]) if unit != "count" else (1.0, "")
        y = factor * y
        if lines:
            _plot_lines(ax, x, y, keep, groups, others)
        else:
            ax.plot(x[keep], y[keep], "o", ms=3, color="C0", alpha=0.7)
        ax.set_title(label, fontsize=10)
        ax.set_ylabel(unit if unit == "count" else f"[{prefix}{unit}]")
        ax.ticklabel_format(axis="y", style="plain", useOffset=False)
        if not keep.any() and ok.any():  # e.g. peaks of fixed-step runs: never located
            ax.text(0.5, 0.5, "not located\n(see the peak_note column)", ha="center",
                    va="center", transform=ax.transAxes, color="C3")
        if axis.log:
            ax.set_xscale("log")
            ticks = sorted({x_factor * v for v in axis.values})
            if len(ticks) <= 8:  # label the swept values themselves
                ax.set_xticks(ticks, [f"{v:.3g}" for v in ticks])
                ax.tick_params(axis="x", labelrotation=35)
            ax.xaxis.set_minor_formatter(NullFormatter())
        ax.grid(True, alpha=0.3)
    unit = swept_unit(sweep, axis.name)
    for ax in axs[-1]:
        ax.set_xlabel(f"{axis.name} [{x_prefix}{unit}]" if unit else axis.name)
    if lines and others:
        axs[0, 0].legend(fontsize=8)
    failed = int(np.sum(~ok))
    note = f", {failed} failed case(s) not shown" if failed else ""
    fig.suptitle(f"{sweep.name}: {len(x)} cases against {axis.name}{note}")
    return save(fig, path, dpi=DPI)


def swept_unit(sweep: Sweep, name: str) -> str:
    """The SI unit of a swept name: its robot parameter's, metres for a clearance alias
    (``jointN.clearance``), "" for a pure number."""
    from jointplay.sweep.axes import CLEARANCE_ALIAS

    if CLEARANCE_ALIAS.fullmatch(name):
        return "m"
    units = {p.name: p.unit for p in sweep.scene.robot.parameters()}
    unit = units.get(name, "")
    return "" if unit in ("1", "-") else unit


def _plot_lines(ax: Any, x: np.ndarray, y: np.ndarray, keep: np.ndarray,
                groups: dict[tuple[float, ...], list[int]], others: list[str]) -> None:
    """One line per combination of the other swept names: each a 1-D cut of the sweep."""
    for n, (values, members) in enumerate(groups.items()):
        idx = np.array([i for i in members if keep[i]], dtype=int)
        idx = idx[np.argsort(x[idx], kind="stable")]
        name = ", ".join(f"{o} = {v:.3g}" for o, v in zip(others, values, strict=True))
        ax.plot(x[idx], y[idx], "o-", ms=4, lw=1.0, color=f"C{n % 10}", label=name or None)
