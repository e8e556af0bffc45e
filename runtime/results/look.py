"""Looking at results files again: every figure of one run (``jointplay plot``), and runs
side by side with a table of their differences (``jointplay compare``).

Everything here works on :class:`SimulationResult` objects; files are read in one place,
:func:`read_result`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Any, TypeVar

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.figures import ORBIT_GID, FigureJob, draw_all, figure, save
from jointplay.results.records import SimulationResult


def read_result(path: str | Path, argument: str = "RUN") -> SimulationResult:
    """A results file as the :class:`SimulationResult` that was written; a file that is
    missing, not a results file or fails its checks is refused naming ``argument`` and the
    path."""
    return read_result_checked(path, argument)[0]


def read_result_checked(path: str | Path, argument: str = "RUN"
                        ) -> tuple[SimulationResult, bool]:
    """:func:`read_result` and whether the file's checksums were verified (False: a file
    written before results files carried them)."""
    from jointplay.results.write import read_checked

    try:
        return read_checked(path)
    except DescriptionError as err:
        if err.field == "path":  # not a file at all: missing, a folder, a FIFO, a device
            raise DescriptionError(argument, f"{path}: {err.message}") from None
        raise DescriptionError(argument, f"{path} is not a jointplay results file "
                               f"({err.field}: {err.message})") from None


AnyResult = TypeVar("AnyResult")  # a results record of any kind: an arm's or a mechanism's
UNCHECKED_NOTE = ("written before results files carried checksums: its numbers are read "
                  "unchecked (write it again with `jointplay simulate --out` to have them "
                  "checked)")


# ------------------------------------------------------------------------------- differences


@dataclass(frozen=True)
class RunDifference:
    """One run against the first of a comparison (SI units; NaN where not known)."""

    label: str
    integrator: str
    t_end: float  # s
    impacts: int  # contact phases
    peak_force: float  # N, largest located peak over all joints (NaN: not located)
    max_approach_speed: float  # m/s, largest onset speed (NaN without impacts)
    max_film_force: float  # N, largest film force over the output samples (NaN: no lubricant)
    max_tip_difference: float  # m, largest |tip - tip of the first run| at shared times
    max_tip_difference_time: float  # s
    compared_samples: int  # output times shared with the first run (where tips are compared)
    final_energy: float  # J, total mechanical energy at the end
    max_balance_error: float  # J, largest |energy balance residual|


def common_samples(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Indices ``(ia, ib)`` of the output times ``a`` and ``b`` share (equal to a millionth of
    the finer spacing: the same instant written by two output grids), in time order."""
    if a.size == 0 or b.size == 0:
        return np.zeros(0, dtype=int), np.zeros(0, dtype=int)
    spacing = min((float(np.min(np.diff(t))) for t in (a, b) if t.size > 1), default=1.0)
    tolerance = 1e-6 * spacing
    nearest = np.clip(np.searchsorted(b, a), 1, max(b.size - 1, 1))
    left = np.clip(nearest - 1, 0, b.size - 1)
    right = np.clip(nearest, 0, b.size - 1)
    ib = np.where(np.abs(b[left] - a) <= np.abs(b[right] - a), left, right)
    keep = np.abs(b[ib] - a) <= tolerance
    return np.flatnonzero(keep), ib[keep]


def tip_difference(run: SimulationResult, reference: SimulationResult
                   ) -> tuple[np.ndarray, np.ndarray]:
    """Times and |tip(run) - tip(reference)| (m) at the output times both runs share.

    Nothing is interpolated: a difference between samples of one run and an interpolant of
    the other would be the interpolant's error, not the runs'. Symmetric: swapping the runs
    gives the same times and the same numbers. Runs at output steps that are multiples of
    one another share every sample of the coarser.
    """
    i_run, i_ref = common_samples(run.t, reference.t)
    t = 0.5 * (run.t[i_run] + reference.t[i_ref])
    gap = np.hypot(*(run.tip_position[i_run] - reference.tip_position[i_ref]).T)
    return t, gap


def differences(runs: Sequence[tuple[str, SimulationResult]]) -> list[RunDifference]:
    """Each run against the first (the first against itself: zero tip difference)."""
    from jointplay.results.contacts import joint_contacts, overall
    from jointplay.results.derived import film_force, is_lubricated

    reference = runs[0][1]
    rows = []
    for label, run in runs:
        contacts = joint_contacts(run)
        t, gap = tip_difference(run, reference)
        k = int(np.argmax(gap)) if gap.size else 0
        speeds = [c.max_approach_speed for c in contacts if c.impacts]
        balance = run.energy.get("balance", np.zeros(1))
        film = (float(np.max(np.hypot(*np.moveaxis(film_force(run), -1, 0)), initial=0.0))
                if is_lubricated(run) else math.nan)
        rows.append(RunDifference(
            label=label, integrator=run.integrator, t_end=float(run.t[-1]),
            impacts=len(run.impacts),
            peak_force=overall([c.peak_force for c in contacts]) if contacts else 0.0,
            max_approach_speed=max(speeds) if speeds else math.nan, max_film_force=film,
            max_tip_difference=float(gap[k]) if gap.size else math.nan,
            max_tip_difference_time=float(t[k]) if gap.size else math.nan,
            compared_samples=int(gap.size),
            final_energy=float(run.energy["total"][-1]),
            max_balance_error=float(np.max(np.abs(balance)))))
    return rows


def _number(value: float, unit: str, digits: int = 4) -> str:
    return "n/a" if not math.isfinite(value) else f"{value:.{digits}g} {unit}"


def difference_table(rows: Sequence[RunDifference]) -> str:
    """The comparison as an aligned text table, with a line on what it compares."""
    header = ("run", "integrator", "impacts", "dry peak force", "max approach",
              "film max (sampled)", "max tip diff", "at", "samples compared", "final energy",
              "max |balance|")
    lines = [header]
    for i, r in enumerate(rows):
        first = i == 0
        lines.append((r.label, r.integrator, str(r.impacts), _number(r.peak_force, "N"),
                      _number(r.max_approach_speed, "m/s", 3) if r.impacts else "none",
                      _number(r.max_film_force, "N") if math.isfinite(r.max_film_force)
                      else "no film",
                      "reference" if first else _number(r.max_tip_difference, "m", 3),
                      "" if first else _number(r.max_tip_difference_time, "s"),
                      "" if first else str(r.compared_samples),
                      _number(r.final_energy, "J", 6), _number(r.max_balance_error, "J", 3)))
    widths = [max(len(line[i]) for line in lines) for i in range(len(header))]
    text = ["  ".join(cell.ljust(w) for cell, w in zip(line, widths, strict=True)).rstrip()
            for line in lines]
    text.insert(1, "  ".join("-" * w for w in widths))
    text.append(f"tip differences against {rows[0].label} at the output times both runs "
                "share (never interpolated); dry peak forces located on the dense output "
                "(n/a: not located, see the impact table); film forces the largest output "
                "sample")
    return "\n".join(text)


# ----------------------------------------------------------------------------------- figures


def _labels(paths: Sequence[str | Path]) -> list[str]:
    """Short names for the runs: file stems, whole paths where stems repeat."""
    stems = [Path(p).stem for p in paths]
    return [s if stems.count(s) == 1 else str(p) for s, p in zip(stems, paths, strict=True)]


def compare_runs(runs: Sequence[tuple[str, SimulationResult]], folder: str | Path
                 ) -> list[Path]:
    """Write the comparison figures into ``folder``; return their paths."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    jobs: list[FigureJob] = [partial(plot_tip, runs, folder / "compare_tip.png")]
    joints = sorted({j for _, run in runs for j in run.clearance_joints})
    if joints:
        from jointplay.results.derived import dense_eccentricity

        # Here, once: the dense output lives in this process, not in draw_all's workers.
        dense = {label: dense_eccentricity(run) for label, run in runs if run.clearance_joints}
        for joint in joints:
            jobs.append(partial(plot_orbits, runs, joint, dense,
                                folder / f"compare_orbit_joint{joint}.png"))
        jobs.append(partial(plot_forces, runs, joints, folder / "compare_contact_force.png"))
        jobs.append(partial(plot_impacts, runs, joints, folder / "compare_impacts.png"))
    jobs.append(partial(plot_energies, runs, folder / "compare_energy.png"))
    return draw_all(jobs)


def plot_tip(runs: Sequence[tuple[str, SimulationResult]], path: Path) -> Path:
    """Tip paths overlaid, tip x and y against time, and each run's distance from the first."""
    from jointplay.results.plots import _scale

    fig, axes = figure(2, 2, 13, 8.5)
    path_ax, gap_ax = axes[0, 0], axes[0, 1]
    x_ax, y_ax = axes[1, 0], axes[1, 1]
    reference_label, reference = runs[0]
    gaps = [tip_difference(run, reference) for _, run in runs[1:]]
    factor, prefix = _scale(np.concatenate([g for _, g in gaps] + [np.zeros(1)]))
    for i, (label, run) in enumerate(runs):
        style = {"color": f"C{i}", "lw": 1.4 if i == 0 else 1.0, "ls": "-" if i == 0 else "--",
                 "label": label}
        path_ax.plot(run.tip_position[:, 0], run.tip_position[:, 1], **style)
        x_ax.plot(run.t, run.tip_position[:, 0], **style)
        y_ax.plot(run.t, run.tip_position[:, 1], **style)
        if i:
            t, gap = gaps[i - 1]
            gap_ax.plot(t, factor * gap, color=f"C{i}", lw=1.0, label=label)
    path_ax.set_aspect("equal", adjustable="datalim")
    path_ax.set_xlabel("tip x [m]")
    path_ax.set_ylabel("tip y [m]")
    path_ax.set_title("tip path")
    gap_ax.set_ylabel(f"|tip − tip of {reference_label}| [{prefix}m]")
    gap_ax.set_title(f"distance from {reference_label}")
    x_ax.set_ylabel("tip x [m]")
    y_ax.set_ylabel("tip y [m]")
    for ax in (gap_ax, x_ax, y_ax):
        ax.set_xlabel("time [s]")
    for ax in axes.ravel():
        ax.grid(True, alpha=0.3)
    fig.suptitle("end effector, runs compared")
    fig.legend(*path_ax.get_legend_handles_labels(), loc="outside lower center",
               ncols=min(len(runs), 4))
    return save(fig, path)


def plot_orbits(runs: Sequence[tuple[str, SimulationResult]], joint: int,
                dense: dict[str, tuple[np.ndarray, np.ndarray, str]], path: Path) -> Path:
    """The journal orbits of one joint overlaid, each from its run's ``sol``."""
    um = 1e6
    fig, axes = figure(1, 1, 10.0, 6.5)
    ax = axes[0, 0]
    reach = 0.0
    angle = np.linspace(0.0, 2.0 * np.pi, 361)
    for i, (label, run) in enumerate(runs):
        if joint not in run.clearance_joints:
            continue
        k = run.clearance_joints.index(joint)
        c = um * float(run.radial_clearance[k])
        _, ecc, source = dense[label]
        ax.plot(c * np.cos(angle), c * np.sin(angle), color=f"C{i}", lw=0.8, ls=":")
        ax.plot(um * ecc[:, k, 0], um * ecc[:, k, 1], color=f"C{i}", lw=0.6,
                gid=f"{ORBIT_GID}:{label}", label=f"{label} ({source}; c = {c:.4g} µm)")
        hits = um * run.impacts.eccentricity[run.impacts.joint == joint].reshape(-1, 2)
        ax.plot(hits[:, 0], hits[:, 1], "o", color=f"C{i}", ms=3.5, mec="k", mew=0.4)
        reach = max(reach, c, float(np.nanmax(np.hypot(ecc[:, k, 0], ecc[:, k, 1])) * um))
    reach *= 1.15
    ax.set_xlim(-reach, reach)
    ax.set_ylim(-reach, reach)
    ax.set_aspect("equal")
    ax.set_xlabel("eccentricity $e_x$ [µm]")
    ax.set_ylabel("eccentricity $e_y$ [µm]")
    ax.set_title(f"journal orbits, joint {joint} (dots: impact onsets; dotted: clearance)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
    return save(fig, path)


def plot_forces(runs: Sequence[tuple[str, SimulationResult]], joints: list[int],
                path: Path) -> Path:
    """Each joint's dry normal force (and film force, with a lubricant), runs overlaid."""
    from jointplay.results.derived import film_force, is_lubricated
    from jointplay.results.plots import _legend_entries

    fig, axes = figure(len(joints), 1, 11, 1.2 + 2.6 * len(joints), sharex=True)
    for row, joint in enumerate(joints):
        ax = axes[row, 0]
        for i, (label, run) in enumerate(runs):
            if joint not in run.clearance_joints:
                continue
            k = run.clearance_joints.index(joint)
            ax.plot(run.t, run.normal_force[:, k], color=f"C{i}", lw=0.9,
                    label=f"{label}: dry normal $F_n$")
            if is_lubricated(run):
                film = np.hypot(*film_force(run)[:, k].T)
                ax.plot(run.t, film, color=f"C{i}", lw=0.9, ls="--",
                        label=f"{label}: film |$F_{{film}}$|")
        ax.set_ylabel("force [N]")
        ax.set_title(f"joint {joint} (output samples; located peaks: compare_impacts.png)",
                     fontsize="medium")
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle("contact forces, runs compared")
    fig.legend(*_legend_entries(axes), loc="outside lower center", ncols=2)
    return save(fig, path)


def plot_impacts(runs: Sequence[tuple[str, SimulationResult]], joints: list[int],
                 path: Path) -> Path:
    """Impacts side by side: per joint, each run's contact onsets along time (one row per
    run), marked by their located peak force; beside it, the located peaks against time."""
    fig, axes = figure(len(joints), 2, 13, 1.4 + 2.4 * len(joints))
    for row, joint in enumerate(joints):
        onsets, peaks = axes[row, 0], axes[row, 1]
        for i, (label, run) in enumerate(runs):
            rows = run.impacts.for_joint(joint) if joint in run.clearance_joints else None
            count = 0 if rows is None else len(rows)
            if rows is not None and count:
                onsets.plot(rows.time, np.full(count, i), "|", color=f"C{i}", ms=14, mew=1.3)
                located = np.isfinite(rows.peak_force)
                peaks.plot(rows.peak_force_time[located], rows.peak_force[located],
                           label=f"{label}: {int(located.sum())} located",
                           **_peak_marker(i))
            onsets.text(1.0, i, f" {count}", transform=onsets.get_yaxis_transform(),
                        va="center", fontsize="small")
        onsets.set_yticks(range(len(runs)), [label for label, _ in runs])
        onsets.set_ylim(-0.6, len(runs) - 0.4)
        onsets.set_title(f"joint {joint}: contact onsets (count at the right)",
                         fontsize="medium")
        peaks.set_title(f"joint {joint}: located peak force of each phase (first run "
                        "hollow)", fontsize="medium")
        peaks.set_ylabel("peak force [N]")
        if peaks.get_legend_handles_labels()[0]:
            peaks.legend(fontsize="small")
        for ax in (onsets, peaks):
            ax.set_xlabel("time [s]")
            ax.grid(True, alpha=0.3)
    fig.suptitle("impacts, runs side by side")
    return save(fig, path)


# Each run's located peaks get their own marker; the first run's are large and hollow, the
# others' smaller and filled, so a peak two runs share shows both (one inside the other).
_PEAK_MARKERS = ("o", "v", "^", "s", "D", "P", "X")


def _peak_marker(i: int) -> dict[str, Any]:
    """Line2D keywords of run ``i``'s located-peak markers in compare_impacts.png."""
    marker = _PEAK_MARKERS[i % len(_PEAK_MARKERS)]
    if i == 0:
        return {"ls": "none", "marker": marker, "ms": 9, "mfc": "none", "mec": "C0",
                "mew": 1.4, "zorder": 3}
    return {"ls": "none", "marker": marker, "ms": 5, "color": f"C{i}", "mec": "k",
            "mew": 0.4, "zorder": 3 + i}


def plot_energies(runs: Sequence[tuple[str, SimulationResult]], path: Path) -> Path:
    """Total mechanical energy and the energy-balance residual of every run."""
    fig, axes = figure(2, 1, 11, 7, sharex=True)
    top, bottom = axes[0, 0], axes[1, 0]
    for i, (label, run) in enumerate(runs):
        top.plot(run.t, run.energy["total"], color=f"C{i}", lw=1.2, label=label)
        bottom.plot(run.t, run.energy.get("balance", np.zeros_like(run.t)), color=f"C{i}",
                    lw=1.0, label=label)
    top.set_ylabel("total energy [J]")
    bottom.set_ylabel("balance residual [J]")
    bottom.set_title("energy balance: total − total(t₀) − drive work + dissipated (0 if exact)")
    bottom.set_xlabel("time [s]")
    for ax in (top, bottom):
        ax.grid(True, alpha=0.3)
    top.legend(fontsize="small")
    fig.suptitle("energy, runs compared")
    return save(fig, path)


def labelled(paths: Sequence[str | Path], results: Sequence[AnyResult]
             ) -> list[tuple[str, AnyResult]]:
    """Each result with the label of its file (an arm's or a mechanism's results alike)."""
    return list(zip(_labels(paths), results, strict=True))


__all__: list[Any] = ["UNCHECKED_NOTE", "RunDifference", "compare_runs", "difference_table",
                      "differences", "labelled", "read_result", "read_result_checked",
                      "tip_difference"]
