"""A calibration's files: ``calibration.json``, ``report.md`` and three figures.

``write_report`` writes them all or none (:func:`jointplay.common.files.all_or_nothing`);
the folder and its files are planned, and refused, before any run (:func:`output_plan`).
"""

from __future__ import annotations

import json
import math
from functools import partial
from pathlib import Path

import numpy as np

from jointplay.calibration.result import CalibrationResult
from jointplay.common.figures import Margins, draw_all, figure, save
from jointplay.common.files import OutputPlan, all_or_nothing, atomic_write_text, make_folder

FILES = ("calibration.json", "report.md", "fit.png", "residuals.png", "profiles.png")


def output_plan(out: str | Path, inputs: dict[str, str | None]) -> OutputPlan:
    """The files ``write_report`` will write into ``out``, checked against the inputs."""
    plan = OutputPlan()
    for flag, path in inputs.items():
        plan.input(flag, path)
    for name in FILES:
        plan.file("--out", Path(out) / name)
    plan.check()
    return plan


def write_report(result: CalibrationResult, out: str | Path, plan: OutputPlan,
                 command: str = "") -> list[Path]:
    """Write every file of the calibration into ``out`` (all or none); their paths."""
    folder = Path(out)
    with all_or_nothing(plan):
        make_folder(folder, "--out")
        data = {**result.to_dict(), "command": command}
        atomic_write_text(folder / "calibration.json", json.dumps(data, indent=2) + "\n")
        atomic_write_text(folder / "report.md", report_text(result, command))
        draw_all([partial(_column_figure, result, folder / "fit.png", residuals=False),
                  partial(_column_figure, result, folder / "residuals.png", residuals=True),
                  partial(_profile_figure, result, folder / "profiles.png")])
    return [folder / name for name in FILES]


def report_text(result: CalibrationResult, command: str = "") -> str:
    """``report.md``: estimates with their intervals, warnings, fit quality and cost."""
    stats = result.residuals
    lines = [f"# Calibration of {result.scene_name}", ""]
    if command:
        lines += ["```sh", command, "```", ""]
    lines += [f"Measured: `{result.measured.source}`, {stats['samples']} samples of "
              f"{', '.join(result.measured.columns)} from {result.measured.t[0]:g} s to "
              f"{result.measured.t[-1]:g} s.", ""]
    if result.fit_explains_data is False:
        lines += ["**The residuals are not the noise: nothing is determined (see the "
                  "warning); the estimates below are the best fit found, not established "
                  "values.**", ""]
    lines += ["| parameter | start | estimate | std | 95 % interval | determined |",
              "|---|---|---|---|---|---|"]
    for e in result.estimates.values():
        std = f"{e.std:.3g}" if math.isfinite(e.std) else "inf"
        lines.append(f"| `{e.name}` | {e.start:.6g} | {e.value:.8g} | {std} | "
                     f"[{e.low95:.8g}, {e.high95:.8g}] | {'yes' if e.determined else 'NO'} |")
    lines += [""]
    if result.warnings:
        lines += ["## Warnings", ""] + [f"- {w}" for w in result.warnings] + [""]
    noise = ("stated" if result.noise_stated
             else "estimated from the data's own sample-to-sample scatter")
    lines += ["## Fit", "",
              f"- chi² = {stats['chi2']:.6g} on {stats['dof']} degrees of freedom "
              f"(chi²/dof = {stats['normalised_chi2']:.4g}); noise {noise}: "
              + ", ".join(f"{c} {v:.3g}" for c, v in result.noise.items()),
              "- residual RMS: " + ", ".join(f"{c} {v:.3g}" for c, v in stats["rms"].items()),
              f"- condition number of the correlation form of JᵀJ: "
              f"{result.condition_number:.4g}",
              "- correlations: " + _correlations(result),
              f"- cost: {result.simulations} runs ("
              + ", ".join(f"{k} {v}" for k, v in result.simulations_by_kind.items())
              + f"), {result.wall_time_s:.1f} s wall, {result.cpu_time_s:.1f} s CPU; "
              f"{len(result.starts)} local fits",
              "- Jacobian: " + ", ".join(f"{k}: {v}" for k, v in result.jacobian_source.items()),
              f"- runs at rtol {result.settings['rtol']:g}, atol {result.settings['atol']:g}",
              f"- search: {result.settings['search']}" if "search" in result.settings
              else f"- search: {len(result.stages)} fits over growing windows"
              + (f" from a grid of {result.grid.simulations} runs" if result.grid else "")
              + " (`continuation` and `grid` in `calibration.json`)", "",
              "The 95 % intervals are ±1.96 standard deviations of the linearised "
              "covariance (JᵀJ)⁻¹ of the whitened residuals, clipped to the physical range; "
              "they hold where the fit explains the data (chi²/dof near 1). The cost "
              "profiles (`profiles.png`) hold the other parameters at their estimates.", ""]
    return "\n".join(lines)


def _correlations(result: CalibrationResult) -> str:
    names = result.names
    pairs = [f"{names[i]}/{names[j]} {result.correlation[i, j]:+.3f}"
             for i, j in zip(*np.triu_indices(len(names), 1), strict=True)]
    return ", ".join(pairs) if pairs else "(one parameter)"


def _column_figure(result: CalibrationResult, path: Path, residuals: bool) -> Path:
    """Each measured column against time: measured and fitted, or the residuals beside the
    noise's ±2σ band."""
    measured, n = result.measured, len(result.measured.columns)
    fig, axes = figure(n, 1, 7.0, (2.0 if residuals else 2.2) * n + 0.6, sharex=True,
                       margins=Margins(left=1.0))
    for k, column in enumerate(measured.columns):
        ax = axes[k, 0]
        if residuals:
            ax.plot(measured.t, result.fitted[:, k] - measured.values[:, k], lw=0.6,
                    color="C3", rasterized=True)
            sigma = result.noise[column]
            ax.axhspan(-2 * sigma, 2 * sigma, color="0.85", zorder=0,
                       label=f"±2σ noise ({'stated' if result.noise_stated else 'estimated'})")
            ax.set_ylabel(f"{column} residual")
            continue
        ax.plot(measured.t, measured.values[:, k], ".", ms=2, color="0.5", label="measured",
                rasterized=True)
        ax.plot(measured.t, result.fitted[:, k], "-", lw=1.0, color="C0", label="fitted")
        unit = result.settings.get("units", {}).get(column)  # a mechanism's outputs
        ax.set_ylabel(f"{column} ({unit or ('m' if column.startswith('tip') else 'rad')})")
    axes[0, 0].legend(loc="upper right" if residuals else "best", fontsize=8)
    axes[-1, 0].set_xlabel("time (s)")
    fig.suptitle("residuals (fitted - measured)" if residuals
                 else f"{result.scene_name}: measured and fitted")
    return save(fig, path)


def _profile_figure(result: CalibrationResult, path: Path) -> Path:
    names = result.names
    fig, axes = figure(1, len(names), 3.6 * len(names), 3.4, margins=Margins(left=0.8))
    for k, name in enumerate(names):
        ax, profile, estimate = axes[0, k], result.profiles.get(name), result.estimates[name]
        if profile:
            ax.plot(profile["value"], profile["chi2"], "o-", ms=3, label="chi² (others held)")
            ax.plot(profile["value"], profile["quadratic"], "--", lw=1.0,
                    label="quadratic from JᵀJ")
        else:
            ax.text(0.5, 0.5, "no profile computed", ha="center", transform=ax.transAxes)
        ax.axvline(estimate.value, color="k", lw=0.8)
        if math.isfinite(estimate.std):
            ax.axvspan(estimate.low95, estimate.high95, color="C2", alpha=0.2,
                       label="95 % interval")
        ax.set_xlabel(name)
        ax.set_ylabel("chi²")
        ax.ticklabel_format(axis="x", style="sci", scilimits=(-3, 3))
    axes[0, 0].legend(fontsize=7)
    fig.suptitle("cost profiles: chi² along each parameter, the others held at their estimates")
    return save(fig, path)
