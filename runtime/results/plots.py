"""Standard figures of a :class:`SimulationResult`, written as PNG files.

matplotlib is imported inside the functions, and figures are drawn on an Agg canvas without
pyplot, so ``import jointplay`` stays fast and no global backend state is touched.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.figures import figure, save
from jointplay.results.records import Impacts, SimulationResult

if TYPE_CHECKING:
    from matplotlib.axes import Axes

_XY = (("x", "C0"), ("y", "C3"))
_PREFIXES = ((1.0, ""), (1e-3, "m"), (1e-6, "µ"), (1e-9, "n"))


def plot_result(result: SimulationResult, folder: str | Path) -> list[Path]:
    """Write every standard figure into ``folder`` (created if missing); return the paths."""
    folder = Path(folder)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise DescriptionError("--plots", f"cannot create folder {folder}: {exc}", None) from exc
    paths = [plot_end_effector(result, folder / "end_effector.png")]
    for k, joint in enumerate(result.clearance_joints):
        paths.append(plot_orbit(result, k, folder / f"orbit_joint{joint}.png"))
    if result.clearance_joints:
        paths.append(plot_contact_force(result, folder / "contact_force.png"))
    for k, joint in enumerate(result.clearance_joints):
        paths.append(plot_contact_timeline(result, k,
                                           folder / f"contact_timeline_joint{joint}.png"))
    paths.append(plot_energy(result, folder / "energy.png"))
    if result.wear is not None:
        from jointplay.results.wear import plot as plot_wear

        paths.append(plot_wear(result.wear, folder / "wear.png",
                               f"{result.scene_name}: Archard wear over {result.t[-1]:g} s"))
    return paths


def _scale(values: np.ndarray) -> tuple[float, str]:
    """Factor and SI prefix that bring the largest magnitude of ``values`` to 0.1 .. 1000."""
    peak = float(np.nanmax(np.abs(values))) if values.size else 0.0
    for factor, prefix in _PREFIXES:
        if peak >= 0.1 * factor:
            return 1.0 / factor, prefix
    return 1.0, ""


def _time_axis(ax: Axes) -> None:
    """Grid on every panel; the time label only under the bottom row of a shared axis."""
    spec = ax.get_subplotspec()
    if spec is None or spec.is_last_row():
        ax.set_xlabel("time [s]")
    ax.grid(True, alpha=0.3)


def plot_end_effector(result: SimulationResult, path: Path) -> Path:
    """End-effector displacement, velocity and acceleration; with an ideal run, the error too."""
    ideal = result.ideal
    rows = (("displacement", "tip_position", "m"), ("velocity", "tip_velocity", "m/s"),
            ("acceleration", "tip_acceleration", "m/s²"))
    fig, axes = figure(3, 2 if ideal else 1, 12 if ideal else 7, 9.5, sharex=True)
    for row, (label, name, unit) in enumerate(rows):
        ax = axes[row, 0]
        for c, (comp, color) in enumerate(_XY):
            ax.plot(result.t, getattr(result, name)[:, c], color=color, lw=1.4,
                    label=f"{comp} (clearance)" if ideal else comp)
        if ideal is not None:
            for c in range(2):
                ax.plot(ideal.t, getattr(ideal, name)[:, c], color="k", lw=0.8, ls="--", alpha=0.8,
                        label="ideal joints" if c == 0 else None)
        ax.set_ylabel(f"{label} [{unit}]")
        ax.set_title(f"end-effector {label}")
        if ideal is not None:
            error = getattr(result, name) - getattr(ideal, name)
            factor, prefix = _scale(error)
            ax = axes[row, 1]
            for c, (_, color) in enumerate(_XY):
                ax.plot(result.t, factor * error[:, c], color=color, lw=1.0)
            ax.axhline(0.0, color="0.5", lw=0.6)
            ax.set_ylabel(f"error [{prefix}{unit}]")
            ax.set_title(f"{label} error (clearance − ideal)")
    for ax in axes.ravel():
        _time_axis(ax)
    fig.suptitle(f"{result.scene_name}: end-effector response")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=3)
    return save(fig, path)


def impact_positions(result: SimulationResult, k: int) -> np.ndarray:
    """Eccentricity (m) at each impact of clearance joint number ``k`` (0-based column)."""
    joint = result.clearance_joints[k]
    return result.impacts.eccentricity[result.impacts.joint == joint].reshape(-1, 2)


def plot_orbit(result: SimulationResult, k: int, path: Path) -> Path:
    """Path of the journal centre inside the clearance circle, in micrometres."""
    joint, um = result.clearance_joints[k], 1e6
    c = um * float(result.radial_clearance[k])
    ex, ey = um * result.eccentricity[:, k, 0], um * result.eccentricity[:, k, 1]
    hits = um * impact_positions(result, k)
    fig, axes = figure(1, 1, 8.5, 6.0)
    ax = axes[0, 0]
    angle = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(c * np.cos(angle), c * np.sin(angle), color="0.3", lw=1.5,
            label=f"clearance c = {c:.4g} µm")
    ax.plot(ex, ey, color="C0", lw=0.8, alpha=0.9, label="journal centre")
    ax.plot(hits[:, 0], hits[:, 1], "o", color="C3", ms=4, label=f"impacts ({len(hits)})")
    ax.plot(ex[0], ey[0], "^", color="C2", ms=9, mec="k", label=f"start, t = {result.t[0]:.3g} s")
    ax.plot(ex[-1], ey[-1], "s", color="C1", ms=8, mec="k",
            label=f"end, t = {result.t[-1]:.3g} s")
    reach = 1.15 * max(c, float(np.nanmax(np.hypot(ex, ey))) if ex.size else 0.0)
    ax.set_xlim(-reach, reach)
    ax.set_ylim(-reach, reach)
    ax.set_aspect("equal")
    ax.axhline(0.0, color="0.8", lw=0.6, zorder=0)
    ax.axvline(0.0, color="0.8", lw=0.6, zorder=0)
    ax.set_xlabel("eccentricity $e_x$ [µm]")
    ax.set_ylabel("eccentricity $e_y$ [µm]")
    ax.set_title(f"{result.scene_name}: journal orbit, joint {joint}")
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
    return save(fig, path)


def plot_contact_force(result: SimulationResult, path: Path) -> Path:
    """Normal and friction force of each clearance joint, impacts ticked along the time axis."""
    from matplotlib.transforms import blended_transform_factory

    nc = len(result.clearance_joints)
    fig, axes = figure(nc, 1, 10, 1.0 + 2.6 * nc, sharex=True)
    for k, joint in enumerate(result.clearance_joints):
        ax: Any = axes[k, 0]
        ax.plot(result.t, result.normal_force[:, k], color="C0", lw=1.2, label="normal $F_n$")
        ax.plot(result.t, result.friction_force[:, k], color="C1", lw=0.7,
                label="friction $F_t$")
        times = result.impacts.time[result.impacts.joint == joint]
        ticks = blended_transform_factory(ax.transData, ax.transAxes)
        ax.plot(times, np.full(times.shape, 0.0), "|", color="C3", ms=12, mew=1.2,
                transform=ticks, clip_on=False, label="impact onset")
        ax.set_ylabel("force [N]")
        ax.set_title(f"joint {joint}: {times.size} impacts")
        _time_axis(ax)
    fig.suptitle(f"{result.scene_name}: contact forces")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=3)
    return save(fig, path)


def plot_energy(result: SimulationResult, path: Path) -> Path:
    """Energy components, and the balance residual that is zero for an exact solution."""
    fig, axes = figure(2, 1, 11, 7, sharex=True)
    top, bottom = axes[0, 0], axes[1, 0]
    for name, values in result.energy.items():
        if name == "total":
            top.plot(result.t, values, color="k", lw=2.0, label=name)
        elif name != "balance":
            top.plot(result.t, values, lw=1.2, label=name.replace("_", " "))
    top.set_ylabel("energy [J]")
    top.set_title("energy components")
    top.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    balance = result.energy.get("balance", np.zeros_like(result.t))
    factor, prefix = _scale(balance)
    bottom.plot(result.t, factor * balance, color="C3", lw=1.0)
    bottom.axhline(0.0, color="0.5", lw=0.6)
    bottom.set_ylabel(f"residual [{prefix}J]")
    bottom.set_title("energy balance: total − total(t₀) − drive work + dissipated")
    for ax in (top, bottom):
        _time_axis(ax)
    fig.suptitle(f"{result.scene_name}: energy")
    return save(fig, path)


# The first impact burst ends at the first gap between phases longer than this fraction of
# the run (or after BURST_MAX phases): a rule on the run, not on the output step.
BURST_GAP = 0.02
BURST_MAX = 40


def first_burst(impacts: Impacts, span: float) -> tuple[float, float]:
    """(start, end) s of the first burst of phases in ``impacts`` (one joint's rows)."""
    if len(impacts) == 0:
        return math.nan, math.nan
    ends = np.where(np.isfinite(impacts.separation_time), impacts.separation_time,
                    impacts.time)
    end = float(ends[0])
    for k in range(1, min(len(impacts), BURST_MAX)):
        if impacts.time[k] - end > BURST_GAP * span:
            break
        end = max(end, float(ends[k]))
    return float(impacts.time[0]), end


def _mark_phases(ax: Any, rows: Impacts, scale: float, located: bool) -> None:
    """Onsets, located peaks (stems) and separations of one joint's phases."""
    ax.plot(rows.time, np.zeros(len(rows)), "^", color="C2", ms=6, mec="k", mew=0.5,
            label="onset", zorder=4)
    if located:
        ax.vlines(rows.peak_force_time, 0.0, scale * rows.peak_force, color="C3", lw=1.0,
                  zorder=3)
        ax.plot(rows.peak_force_time, scale * rows.peak_force, "v", color="C3", ms=6,
                mec="k", mew=0.5, label="located peak", zorder=5)
    sep = np.isfinite(rows.separation_time)
    ax.plot(rows.separation_time[sep], np.zeros(int(sep.sum())), "o", color="C4", mfc="w",
            ms=5, mew=1.2, label="separation", zorder=4)


def plot_contact_timeline(result: SimulationResult, k: int, path: Path) -> Path:
    """Normal force of clearance joint ``k`` against time with every onset, located peak and
    separation marked; below, a zoom on the first impact burst."""
    from jointplay.results.contacts import joint_contact

    summary = joint_contact(result, k)
    joint = summary.joint
    rows = result.impacts.for_joint(joint)
    force = result.normal_force[:, k]
    step = float(np.median(np.diff(result.t))) if result.n_samples > 1 else 0.0
    peaks = rows.peak_force[np.isfinite(rows.peak_force)]
    factor, prefix = _scale(np.r_[force, peaks, 0.0])
    fig, axes = figure(2, 1, 11, 7.5, sharex=False)
    full, zoom = axes[0, 0], axes[1, 0]
    sampled = f"sampled every {step * 1e3:.3g} ms" if step else "sampled"
    for ax in (full, zoom):
        ax.plot(result.t, factor * force, color="C0", lw=0.9, label=f"normal force, {sampled}")
        _mark_phases(ax, rows, factor, summary.located and len(rows) > 0)
        ax.set_ylabel(f"normal force [{prefix}N]")
        _time_axis(ax)
    if summary.located and summary.impacts:
        full.set_title(f"joint {joint}: {summary.impacts} contact phases; largest located peak "
                       f"{summary.peak_force:.4g} N at {summary.peak_force_time:.6g} s")
    else:
        full.set_title(f"joint {joint}: {summary.impacts} contact phases")
    if not summary.located:
        full.text(0.99, 0.95, f"peak forces {summary.note}", transform=full.transAxes,
                  ha="right", va="top", fontsize=8,
                  bbox={"boxstyle": "round", "fc": "w", "ec": "C3"})
    span = float(result.t[-1] - result.t[0]) if result.n_samples > 1 else 1.0
    start, end = first_burst(rows, span)
    if np.isfinite(start):
        width = max(end - start, 1e-3 * span)
        lo, hi = start - 0.1 * width, end + 0.1 * width
        inside = (result.t >= lo) & (result.t <= hi)
        zoom.plot(result.t[inside], factor * force[inside], ".", color="C0", ms=4)
        zoom.set_xlim(lo, hi)
        shown = (rows.time >= lo) & (rows.time <= hi)
        tops = [factor * force[inside].max() if inside.any() else 0.0]
        if summary.located:
            tops.append(factor * float(np.max(rows.peak_force[shown], initial=0.0)))
        zoom.set_ylim(-0.05 * max(max(tops), 1e-12), 1.1 * max(max(tops), 1e-12))
        count = int(shown.sum())
        zoom.set_title(f"first impact burst: {count} phase{'s' if count != 1 else ''} from "
                       f"{start:.6g} s to {end:.6g} s")
    else:
        zoom.set_title("no impacts")
    fig.legend(*full.get_legend_handles_labels(), loc="outside lower center", ncols=4)
    fig.suptitle(f"{result.scene_name}: contact timeline, joint {joint}")
    return save(fig, path)
