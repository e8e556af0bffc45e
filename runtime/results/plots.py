"""Standard figures of a :class:`SimulationResult`, written as PNG files.

matplotlib is imported inside the functions, and figures are drawn on an Agg canvas without
pyplot, so ``import jointplay`` stays fast and no global backend state is touched.
"""

from __future__ import annotations

import math
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.figures import ORBIT_GID, FigureJob, Margins, figure, save
from jointplay.results.records import Impacts, SimulationResult

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from jointplay.common.figure_process import FigureProcess

_XY = (("x", "C0"), ("y", "C3"))
# Titles are set at y=1.0: placed there directly, not moved above whatever the axes draw
# there (a measurement of every tick label that costs more than the rest of the axes).
_PREFIXES = ((1.0, ""), (1e-3, "m"), (1e-6, "µ"), (1e-9, "n"))


def plot_result(result: SimulationResult, folder: str | Path, *,
                process: FigureProcess | None = None) -> list[Path]:
    """Write every figure the run's effects call for into ``folder`` (created if missing);
    return the paths.

    Always the end effector and the energy; with clearance joints, each journal's orbit (from
    the dense output), the contact forces, each joint's contact timeline and the eccentricity
    ratio; with a lubricant, the film force; with wear, the worn depth around each surface.
    ``process``: a started :class:`~jointplay.common.figure_process.FigureProcess` to draw
    them in (else they are drawn here).
    """
    from jointplay.common.figure_process import draw

    return draw(figure_jobs(result, folder), process)


def figure_jobs(result: SimulationResult, folder: str | Path) -> list[FigureJob]:
    """The jobs of :func:`plot_result`, each drawing and saving one figure into ``folder``
    (created here if missing), the costliest first."""
    from jointplay.results.derived import dense_eccentricity, is_lubricated

    folder = Path(folder)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise DescriptionError("--plots", f"cannot create folder {folder}: {exc}", None) from exc
    # The costliest first (a figure process's two drawers, like draw_all's workers, take
    # the next job as they come free): on the paper scene the end effector 0.43 CPU s, the
    # energy 0.28, each contact timeline 0.24, the contact forces 0.17, the eccentricity
    # ratio 0.12, each orbit 0.10 (benchmarks/figures.py).
    jobs: list[FigureJob] = [partial(plot_end_effector, result, folder / "end_effector.png"),
                             partial(plot_energy, result, folder / "energy.png")]
    if result.clearance_joints:
        for k, joint in enumerate(result.clearance_joints):
            jobs.append(partial(plot_contact_timeline, result, k,
                                folder / f"contact_timeline_joint{joint}.png"))
        jobs.append(partial(plot_contact_force, result, folder / "contact_force.png"))
        jobs.append(partial(plot_eccentricity_ratio, result, folder / "eccentricity_ratio.png"))
        if is_lubricated(result):
            jobs.append(partial(plot_film, result, folder / "film_force.png"))
        dense = dense_eccentricity(result)  # here, once: the dense output lives in this process
        for k, joint in enumerate(result.clearance_joints):
            jobs.append(partial(plot_orbit, result, k, folder / f"orbit_joint{joint}.png",
                                dense))
    if result.wear is not None:
        from jointplay.results.wear import plot as plot_wear

        jobs.append(partial(plot_wear, result.wear, folder / "wear.png",
                            f"{result.scene_name}: Archard wear over {result.t[-1]:g} s"))
    return jobs


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


# The scale after the release transient leaves out the most extreme samples on either side
# (ringing of the last impacts), as a share of the samples shown.
TRANSIENT_CLIP_PERCENT = 0.5


def _limits(values: np.ndarray, pad: float = 0.08, clip: float = 0.0) -> tuple[float, float]:
    """y limits that show ``values`` with a margin (never a zero-height range); ``clip`` > 0
    leaves out that percentage of the samples at either end."""
    finite = values[np.isfinite(values)]
    lo, hi = ((float(np.percentile(finite, clip)), float(np.percentile(finite, 100 - clip)))
              if finite.size else (0.0, 0.0))
    width = hi - lo if hi > lo else max(abs(hi), 1e-12)
    return lo - pad * width, hi + pad * width


def plot_end_effector(result: SimulationResult, path: Path) -> Path:
    """End-effector position (absolute, in the base frame), velocity and acceleration; with an
    ideal run, the error of each beside it. The panels share the time axis.

    When the run begins with a release transient (journals released inside their clearance:
    an impact burst, or a film taking up the load,
    :func:`jointplay.results.derived.release_transient_end`), its accelerations dwarf the
    rest: the acceleration panels are then scaled to the samples after it, the transient is
    shaded, and the title gives the run's largest sample (x-y norm, as the summary does).
    """
    from jointplay.results.derived import release_transient_end

    ideal = result.ideal
    transient = release_transient_end(result)
    rows = (("position", "tip_position", "m"), ("velocity", "tip_velocity", "m/s"),
            ("acceleration", "tip_acceleration", "m/s²"))
    fig, axes = figure(len(rows), 2 if ideal else 1, 12 if ideal else 7, 10.2, sharex=True,
                       margins=Margins(left=0.95, right=0.3, top=0.75, bottom=1.35,
                                       between_rows=0.7 if transient else 0.45,
                                       between_cols=1.0))
    t0, t1 = float(result.t[0]), float(result.t[-1])
    for row, (label, name, unit) in enumerate(rows):
        values = getattr(result, name)
        panels = [(axes[row, 0], values, "", f"end-effector {label}")]
        if ideal is not None:
            error = values - getattr(ideal, name)
            factor, prefix = _scale(error)
            panels.append((axes[row, 1], factor * error, prefix,
                           f"{label} error (clearance − ideal)"))
        for column, (ax, shown, prefix, title) in enumerate(panels):
            for c, (comp, color) in enumerate(_XY):
                ax.plot(result.t, shown[:, c], color=color, lw=1.4 if column == 0 else 1.0,
                        label=(f"{comp} (clearance)" if ideal else comp) if column == 0
                        else None)
            if column == 0 and ideal is not None:
                for c in range(2):
                    ax.plot(ideal.t, getattr(ideal, name)[:, c], color="k", lw=0.8, ls="--",
                            alpha=0.8, label="ideal joints" if c == 0 else None)
            if column == 1:
                ax.axhline(0.0, color="0.5", lw=0.6)
            if label == "acceleration" and transient is not None:
                title = _off_scale(ax, result.t, shown, transient, f"{prefix}{unit}", title)
            ax.set_ylabel(f"{label} [{prefix}{unit}]" if column == 0
                          else f"error [{prefix}{unit}]")
            ax.set_title(title, fontsize="medium", y=1.0)
            ax.set_xlim(t0, t1)
            _time_axis(ax)
    fig.suptitle(f"{result.scene_name}: end-effector response")
    fig.legend(*_legend_entries(axes), loc="outside lower center", ncols=2)
    return save(fig, path)


def _off_scale(ax: Axes, t: np.ndarray, values: np.ndarray, transient: tuple[float, str],
               unit: str, title: str) -> str:
    """Scale ``ax`` to the samples after the release transient, shade the transient, and
    return ``title`` with the run's largest sample (its x-y norm, wherever it lies) added."""
    end, rule = transient
    after = t >= end
    ax.set_ylim(*_limits(values[after], 0.3, TRANSIENT_CLIP_PERCENT))
    ax.axvspan(float(t[0]), end, color="0.87", lw=0, zorder=0,
               label=f"release transient, to {end:.4g} s ({rule});\nacceleration scaled to "
                     f"{100 - 2 * TRANSIENT_CLIP_PERCENT:g} % of the samples after it")
    # The x-y norm over the whole run: the number the run's summary gives as the largest
    # error against the ideal joints (and the same samples), so that the two never disagree.
    norm = np.hypot(values[:, 0], values[:, 1])
    if not norm.size:
        return title
    top = int(np.argmax(norm))
    where = "in the transient" if t[top] < end else "after it"
    return (f"{title}\ntransient shaded; largest |sample| {norm[top]:.4g} {unit} at "
            f"{t[top]:.4g} s ({where})")


def impact_positions(result: SimulationResult, k: int) -> np.ndarray:
    """Eccentricity (m) at each impact of clearance joint number ``k`` (0-based column)."""
    joint = result.clearance_joints[k]
    return result.impacts.eccentricity[result.impacts.joint == joint].reshape(-1, 2)


def plot_orbit(result: SimulationResult, k: int, path: Path,
               dense: tuple[np.ndarray, np.ndarray, str] | None = None) -> Path:
    """Path of the journal centre inside the clearance circle, in micrometres, drawn from the
    dense output (``result.sol``: the output samples alias the fast motion in contact);
    ``dense`` is :func:`jointplay.results.derived.dense_eccentricity` when already at hand."""
    from jointplay.results.derived import dense_eccentricity

    joint, um = result.clearance_joints[k], 1e6
    c = um * float(result.radial_clearance[k])
    times, ecc, source = dense if dense is not None else dense_eccentricity(result)
    ex, ey = um * ecc[:, k, 0], um * ecc[:, k, 1]
    hits = um * impact_positions(result, k)
    fig, axes = figure(1, 1, 8.6, 6.0, margins=Margins(left=0.9, right=3.2, top=0.5,
                                                    bottom=0.65))
    ax = axes[0, 0]
    angle = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(c * np.cos(angle), c * np.sin(angle), color="0.3", lw=1.5,
            label=f"clearance c = {c:.4g} µm")
    ax.plot(ex, ey, color="C0", lw=0.6, alpha=0.9, gid=ORBIT_GID,
            label=f"journal centre, {times.size} points:\n{source}")
    ax.plot(hits[:, 0], hits[:, 1], "o", color="C3", ms=4, label=f"impacts ({len(hits)})")
    ax.plot(ex[0], ey[0], "^", color="C2", ms=9, mec="k", label=f"start, t = {times[0]:.3g} s")
    ax.plot(ex[-1], ey[-1], "s", color="C1", ms=8, mec="k",
            label=f"end, t = {times[-1]:.3g} s")
    reach = 1.15 * max(c, float(np.nanmax(np.hypot(ex, ey))) if ex.size else 0.0)
    ax.set_xlim(-reach, reach)
    ax.set_ylim(-reach, reach)
    ax.set_aspect("equal")
    ax.axhline(0.0, color="0.8", lw=0.6, zorder=0)
    ax.axvline(0.0, color="0.8", lw=0.6, zorder=0)
    ax.set_xlabel("eccentricity, x [µm]")
    ax.set_ylabel("eccentricity, y [µm]")
    ax.set_title(f"{result.scene_name}: journal orbit, joint {joint}", y=1.0)
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
    return save(fig, path)


def plot_contact_force(result: SimulationResult, path: Path) -> Path:
    """Normal and friction force of each clearance joint at the output samples, and the
    lubricant film's force where there is one; each contact phase's located peak (from the
    dense output, :class:`~jointplay.results.records.Impacts`) marked at its located time,
    since an impact of microseconds falls between samples (the sampled curve shows a
    fraction of the peak); impacts ticked along the time axis."""
    from matplotlib.transforms import blended_transform_factory

    from jointplay.results.derived import film_force, is_lubricated

    nc = len(result.clearance_joints)
    film = np.hypot(*np.moveaxis(film_force(result), -1, 0)) if is_lubricated(result) else None
    step = float(np.median(np.diff(result.t))) if result.n_samples > 1 else 0.0
    sampled = f"output samples, every {step * 1e3:.3g} ms" if step else "output samples"
    fig, axes = figure(nc, 1, 10, 1.2 + 2.6 * nc, sharex=True,
                       margins=Margins(left=0.85, right=0.3, top=0.75, bottom=1.35,
                                       between_rows=0.45))
    for k, joint in enumerate(result.clearance_joints):
        ax: Any = axes[k, 0]
        drawn = [result.normal_force[:, k], result.friction_force[:, k]]
        ax.plot(result.t, result.normal_force[:, k], color="C0", lw=1.2,
                label=f"dry normal force ({sampled})")
        ax.plot(result.t, result.friction_force[:, k], color="C1", lw=0.7,
                label="dry friction force (output samples)")
        if film is not None:
            ax.plot(result.t, film[:, k], color="C2", lw=1.0, label="film |$F_{film}$|")
            drawn.append(film[:, k])
        rows = result.impacts.for_joint(joint)
        located = np.isfinite(rows.peak_force) & np.isfinite(rows.peak_force_time)
        title = f"joint {joint}: {len(rows)} impacts"
        if located.any():
            ax.plot(rows.peak_force_time[located], rows.peak_force[located], "v", color="C3",
                    ms=5, mec="k", mew=0.4, zorder=4,
                    label="located peak normal force of each phase (dense output)")
            drawn.append(rows.peak_force[located])
            top = int(np.argmax(np.where(located, rows.peak_force, -np.inf)))
            title += (f"; largest located peak {rows.peak_force[top]:.4g} N at "
                      f"{rows.peak_force_time[top]:.6g} s, largest sample "
                      f"{float(np.max(result.normal_force[:, k])):.4g} N")
        times = rows.time
        if times.size:  # an empty unclipped line has no extent: constrained layout fails
            ticks = blended_transform_factory(ax.transData, ax.transAxes)
            ax.plot(times, np.full(times.shape, 0.0), "|", color="C3", ms=12, mew=1.2,
                    transform=ticks, clip_on=False, label="impact onset")
        ax.set_ylim(*_limits(np.concatenate([*drawn, [0.0]])))
        ax.set_ylabel("force [N]")
        ax.set_title(title, fontsize="medium", y=1.0)
        _time_axis(ax)
    fig.suptitle(f"{result.scene_name}: contact forces")
    fig.legend(*_legend_entries(axes), loc="outside lower center", ncols=2)
    return save(fig, path)


def _legend_entries(axes: Any) -> tuple[list[Any], list[str]]:
    """Handles and labels of every panel, each label once, in order of appearance."""
    handles: dict[str, Any] = {}
    for ax in np.ravel(axes):
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            handles.setdefault(label, handle)
    return list(handles.values()), list(handles)


def plot_eccentricity_ratio(result: SimulationResult, path: Path) -> Path:
    """epsilon(t) = |e| / c of every clearance joint: 1 where dry contact begins; with a
    lubricant, the ratio where the film's coefficients freeze (``lubrication.transition``)."""
    from jointplay.results.derived import eccentricity_ratio, is_lubricated, parameter

    ratio = eccentricity_ratio(result)
    fig, axes = figure(1, 1, 10, 4.2, margins=Margins(left=0.8, right=0.3, top=0.45,
                                                   bottom=0.6))
    ax = axes[0, 0]
    for k, joint in enumerate(result.clearance_joints):
        ax.plot(result.t, ratio[:, k], lw=1.0, color=f"C{k}", label=f"joint {joint}")
    ax.axhline(1.0, color="k", lw=0.8, ls="--", label="ε = 1: dry contact")
    transition = parameter(result, "lubrication.transition")
    if is_lubricated(result) and transition is not None:
        ax.axhline(transition, color="C3", lw=0.8, ls=":",
                   label=f"ε = {transition:g}: film closing (lubrication.transition)")
    ax.set_ylim(0.0, max(1.1, 1.05 * float(np.nanmax(ratio, initial=0.0))))
    ax.set_ylabel("eccentricity ratio ε = |e| / c")
    ax.set_title(f"{result.scene_name}: eccentricity ratio (output samples)", y=1.0)
    ax.legend(fontsize="small", loc="lower right")
    _time_axis(ax)
    return save(fig, path)


def plot_film(result: SimulationResult, path: Path) -> Path:
    """The lubricant film's force on each journal: its load-carrying part along the line of
    centres, its part across it, and the dry contact's normal force where the film closed."""
    from jointplay.results.derived import film_components

    radial, across = film_components(result)
    nc = len(result.clearance_joints)
    fig, axes = figure(nc, 1, 10, 1.2 + 2.8 * nc, sharex=True)
    for k, joint in enumerate(result.clearance_joints):
        ax: Any = axes[k, 0]
        ax.plot(result.t, np.hypot(radial[:, k], across[:, k]), color="k", lw=1.4,
                label="film |$F_{film}$|")
        ax.plot(result.t, radial[:, k], color="C2", lw=0.9,
                label="film, along the line of centres (towards the centre)")
        ax.plot(result.t, across[:, k], color="C4", lw=0.9, label="film, across it")
        ax.plot(result.t, result.normal_force[:, k], color="C0", lw=0.9, ls="--",
                label="dry normal $F_n$ (film closed)")
        peak = int(np.argmax(np.hypot(radial[:, k], across[:, k])))
        ax.set_title(f"joint {joint}: largest film force sample "
                     f"{np.hypot(radial[peak, k], across[peak, k]):.4g} N at "
                     f"{result.t[peak]:.4g} s", fontsize="medium", y=1.0)
        ax.set_ylabel("force [N]")
        _time_axis(ax)
    fig.suptitle(f"{result.scene_name}: lubricant film force")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=2)
    return save(fig, path)


# The contact's energy terms, drawn in energy.png below the motion's on their own scale (on
# the paper scene a thousandth of the motion's).
_CONTACT_ENERGY = ("contact", "dissipated")


def plot_energy(result: SimulationResult, path: Path) -> Path:
    """Energy of the motion (kinetic, gravity, total, drive work) at the top; the contact's
    elastic energy and the energy dissipated in the middle, on their own scale (on the paper
    scene they are a few mJ beside the gravity term's −7 J); the balance residual, zero for
    an exact solution, at the bottom."""
    energy = result.energy
    fig, axes = figure(3, 1, 11, 9, sharex=True,
                       margins=Margins(left=0.9, right=2.0, top=0.75, bottom=0.6,
                                       between_rows=0.45))
    top, middle, bottom = axes[0, 0], axes[1, 0], axes[2, 0]
    for name, values in energy.items():
        if name not in (*_CONTACT_ENERGY, "balance"):
            style = {"color": "k", "lw": 2.0} if name == "total" else {"lw": 1.2}
            top.plot(result.t, values, label=name.replace("_", " "), **style)
    top.set_ylabel("energy [J]")
    top.set_title("energy of the motion", y=1.0)
    top.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    small = [energy[name] for name in _CONTACT_ENERGY if name in energy]
    factor, prefix = _scale(np.concatenate([*small, np.zeros(1)]))
    for name, color in zip(_CONTACT_ENERGY, ("C2", "C4"), strict=True):
        if name in energy:
            label = "contact (elastic)" if name == "contact" else "dissipated (since t₀)"
            middle.plot(result.t, factor * energy[name], color=color, lw=1.2, label=label)
    middle.set_ylabel(f"energy [{prefix}J]")
    middle.set_title("contact: elastic energy and energy dissipated (own scale)", y=1.0)
    middle.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    balance = energy.get("balance", np.zeros_like(result.t))
    factor, prefix = _scale(balance)
    bottom.plot(result.t, factor * balance, color="C3", lw=1.0)
    bottom.axhline(0.0, color="0.5", lw=0.6)
    bottom.set_ylabel(f"residual [{prefix}J]")
    bottom.set_title("energy balance: total − total(t₀) − drive work + dissipated", y=1.0)
    for ax in (top, middle, bottom):
        _time_axis(ax)
    fig.suptitle(f"{result.scene_name}: energy")
    return save(fig, path)


# The first impact burst ends at the first pause between phases longer than BURST_GAP times
# the time since the run began (the release), or after BURST_MAX phases: a rule on the
# motion alone, so that a run of 0.2 s and one of 2 s find the same burst.
BURST_GAP = 1.0
BURST_MAX = 40


def first_burst(impacts: Impacts, t0: float) -> tuple[float, float]:
    """(start, end) s of the first burst of phases in ``impacts`` (one joint's rows) of a run
    that began at ``t0``; (NaN, NaN) without phases."""
    if len(impacts) == 0:
        return math.nan, math.nan
    ends = np.where(np.isfinite(impacts.separation_time), impacts.separation_time,
                    impacts.time)
    end = float(ends[0])
    for k in range(1, min(len(impacts), BURST_MAX)):
        if impacts.time[k] - end > BURST_GAP * (end - t0):
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
    from jointplay.results.derived import film_force, is_lubricated

    summary = joint_contact(result, k)
    joint = summary.joint
    rows = result.impacts.for_joint(joint)
    force = result.normal_force[:, k]
    step = float(np.median(np.diff(result.t))) if result.n_samples > 1 else 0.0
    peaks = rows.peak_force[np.isfinite(rows.peak_force)]
    factor, prefix = _scale(np.r_[force, peaks, 0.0])
    fig, axes = figure(2, 1, 11, 7.5, sharex=False,
                       margins=Margins(left=0.85, right=0.3, top=0.75, bottom=0.95,
                                       between_rows=0.75))
    full, zoom = axes[0, 0], axes[1, 0]
    sampled = f"sampled every {step * 1e3:.3g} ms" if step else "sampled"
    film = None
    if is_lubricated(result):
        film = np.hypot(*np.moveaxis(film_force(result)[:, k], -1, 0))
        factor, prefix = _scale(np.r_[force, peaks, film, 0.0])
    for ax in (full, zoom):
        ax.plot(result.t, factor * force, color="C0", lw=0.9,
                label=f"dry normal force, {sampled}")
        if film is not None:
            ax.plot(result.t, factor * film, color="C2", lw=0.9,
                    label=f"film |$F_{{film}}$|, {sampled}")
        _mark_phases(ax, rows, factor, summary.located and len(rows) > 0)
        ax.set_ylabel(f"force [{prefix}N]")
        _time_axis(ax)
    if summary.located and summary.impacts:
        full.set_title(f"joint {joint}: {summary.impacts} contact phases; largest located peak "
                       f"{summary.peak_force:.4g} N at {summary.peak_force_time:.6g} s", y=1.0)
    else:
        full.set_title(f"joint {joint}: {summary.impacts} contact phases", y=1.0)
    if not summary.located:
        full.text(0.99, 0.95, f"peak forces {summary.note}", transform=full.transAxes,
                  ha="right", va="top", fontsize=8,
                  bbox={"boxstyle": "round", "fc": "w", "ec": "C3"})
    span = float(result.t[-1] - result.t[0]) if result.n_samples > 1 else 1.0
    start, end = first_burst(rows, float(result.t[0]))
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
                       f"{start:.6g} s to {end:.6g} s", y=1.0)
    else:
        zoom.set_title("no impacts", y=1.0)
    fig.legend(*full.get_legend_handles_labels(), loc="outside lower center", ncols=4)
    fig.suptitle(f"{result.scene_name}: contact timeline, joint {joint}")
    return save(fig, path)
