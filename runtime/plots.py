"""Standard figures of a :class:`SimulationResult`, written as PNG files.

matplotlib is imported inside the functions, and figures are drawn on an Agg canvas without
pyplot, so ``import jointplay`` stays fast and no global backend state is touched.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.errors import DescriptionError
from jointplay.files import atomic_path
from jointplay.results import SimulationResult

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

DPI = 130
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
    paths.append(plot_energy(result, folder / "energy.png"))
    return paths


def _figure(rows: int, cols: int, width: float, height: float,
            sharex: bool = True) -> tuple[Figure, np.ndarray]:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(rows, cols, squeeze=False, sharex=sharex)
    return fig, axes


def _save(fig: Figure, path: Path) -> Path:
    """Save through a temporary name so a reader never sees a half-written PNG."""
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=DPI)
    return path


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
    fig, axes = _figure(3, 2 if ideal else 1, 12 if ideal else 7, 9.5)
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
    return _save(fig, path)


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
    fig, axes = _figure(1, 1, 8.5, 6.0, sharex=False)
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
    return _save(fig, path)


def plot_contact_force(result: SimulationResult, path: Path) -> Path:
    """Normal and friction force of each clearance joint, impacts ticked along the time axis."""
    from matplotlib.transforms import blended_transform_factory

    nc = len(result.clearance_joints)
    fig, axes = _figure(nc, 1, 10, 1.0 + 2.6 * nc)
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
    return _save(fig, path)


def plot_energy(result: SimulationResult, path: Path) -> Path:
    """Energy components, and the balance residual that is zero for an exact solution."""
    fig, axes = _figure(2, 1, 11, 7)
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
    return _save(fig, path)
