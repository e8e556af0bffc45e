"""The study's report: median and worst seed per case and controller, the goals checked, the
table and the figure."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from jointplay.neural.control.metrics import SPLIT_METRICS, WORSE_MARGIN, judged
from jointplay.neural.study.cases import Case
from jointplay.neural.study.comparison import LINEAR, LPV, MODEL_BASED, NEURAL
from jointplay.neural.study.runs import BASELINES, GOAL_METRICS, JUDGED, REPORTED

PAPER = {"max_position": 2.4e-4, "max_velocity": 7.7e-3}


def summarise(rows: list[dict[str, Any]]) -> dict[tuple[str, str], dict[str, Any]]:
    """(case, controller) -> count, and median and worst of every metric over seeds."""
    groups: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for row in rows:
        groups.setdefault((row["case"], row["controller"]), []).append(row)
    out = {}
    for key, items in groups.items():
        stats: dict[str, Any] = {"runs": len(items)}
        for metric in REPORTED:
            values = np.array([r[metric] for r in items], dtype=float)
            stats[f"median_{metric}"] = float(np.median(values))
            stats[f"worst_{metric}"] = float(np.max(values))
        out[key] = stats
    return out


def goal_checks(summary: dict[tuple[str, str], dict[str, Any]], cases: list[Case]
                ) -> list[str]:
    lines = []
    first = cases[0].name
    neural, pd, linear, ol = ((first, n) for n in (NEURAL, "PD", LINEAR, "open loop"))
    if neural in summary and pd in summary:
        s, p = summary[neural], summary[pd]
        diverged = sum(summary[(c.name, n)]["worst_diverged"] > 0 for c in cases
                       for n in MODEL_BASED if (c.name, n) in summary)
        lines.append(f"- runs diverged over all cases: {diverged or 'none'}"
                     f" ({s['runs']} seeds)")
        for key, label in GOAL_METRICS:
            met = s[f"worst_{key}"] < p[f"median_{key}"]
            lines.append(f"- {first}: neural IMC worst seed {s[f'worst_{key}']:.3g} vs PD "
                         f"{p[f'median_{key}']:.3g} on {label}: "
                         f"{'beats PD' if met else 'does NOT beat PD'}")
        for key, label in GOAL_METRICS:
            if linear in summary:
                a = summary[linear][f"median_{key}"]
                n = s[f"median_{key}"]
                verdict = ("beats" if n < 0.98 * a else "matches (within 2 %)"
                           if n <= 1.02 * a else "is WORSE than")
                lines.append(f"- {first}: neural IMC median {n:.3g} {verdict} ARX-IMC median "
                             f"{a:.3g} on {label}")
        if ol in summary:
            ratio = summary[ol]["median_rms_acceleration_after"] / \
                s["median_rms_acceleration_after"]
            lines.append(f"- {first}: paper figures: median max |Δp| "
                         f"{s['median_max_position']:.3g} m (paper 2.4e-4), median max |Δv| "
                         f"after settling {s['median_max_velocity_after']:.3g} m/s (paper 7.7e-3;"
                         f" over the whole run {s['median_max_velocity']:.3g}, the journals' "
                         f"fall), RMS |Δa| after settling reduced {ratio:.3g}x from the open loop "
                         "(paper: tenfold)")
    for c in cases[1:]:
        worse = []
        for key, label in GOAL_METRICS:
            ns, ps = summary.get((c.name, NEURAL)), summary.get((c.name, "PD"))
            if ns and ps and ns[f"worst_{key}"] > 1.1 * ps[f"median_{key}"]:
                worse.append(f"{label} {ns[f'worst_{key}']:.3g} vs PD "
                             f"{ps[f'median_{key}']:.3g} "
                             f"({ns[f'worst_{key}'] / ps[f'median_{key}']:.3g}x)")
        lines.append(f"- {c.name}: neural IMC worst seed "
                     + ("within 10 % of PD or better on every metric" if not worse
                        else "worse than PD by more than 10 %: " + "; ".join(worse)))
    return lines


def worse_counts(rows: list[dict[str, Any]]) -> dict[tuple[str, str, str], int]:
    """(case, controller, baseline) -> runs (seeds) that end worse than that baseline on some
    judged metric (:func:`jointplay.neural.control.metrics.judged`; ties within WORSE_MARGIN not
    counted)."""
    base = {(r["case"], r["controller"]): r for r in rows if r["seed"] == -1}
    out: dict[tuple[str, str, str], int] = {}
    for r in rows:
        for baseline in ("open loop", "PD"):
            ref = base.get((r["case"], baseline))
            if ref is None or r["controller"] in (baseline, "open loop"):
                continue
            keys = [k for k in judged(r["controller"], baseline) if k in JUDGED]
            worse = any(ref[k] > 0 and r[k] > ref[k] * (1 + WORSE_MARGIN) for k in keys)
            key = (r["case"], r["controller"], baseline)
            out[key] = out.get(key, 0) + int(worse)
    return out


def worse_lines(rows: list[dict[str, Any]], cases: list[Case]) -> list[str]:
    counts = worse_counts(rows)
    runs: dict[tuple[str, str], int] = {}
    for r in rows:
        runs[(r["case"], r["controller"])] = runs.get((r["case"], r["controller"]), 0) + 1
    lines = []
    for c in cases:
        for name in ("PD", "computed torque", LINEAR, LPV, NEURAL):
            for baseline in ("open loop", "PD"):
                n = counts.get((c.name, name, baseline), 0)
                if n:
                    lines.append(f"- {c.name}: {name} ends worse than "
                                 f"{'no control (open loop)' if baseline == 'open loop' else 'PD'}"
                                 f" on some judged metric in {n} of "
                                 f"{runs[(c.name, name)]} run(s)")
    return lines or ["- no controller ends worse than the open loop or PD on any judged metric"]


def ratio_goals(rows: list[dict[str, Any]], cases: list[Case]) -> list[str]:
    """Neural IMC / ARX-IMC and neural IMC / LPV-ARX-IMC RMS |Δa| after settling, per seed:
    median and worst (goal 0.75 against ARX-IMC, and better than LPV-ARX-IMC)."""
    key = "rms_acceleration_after"
    lines = []
    for c in cases:
        mine = {r["seed"]: r[key] for r in rows if r["case"] == c.name
                and r["controller"] == NEURAL}
        # ARX-IMC: at most 0.75x; LPV-ARX-IMC: better (below 1x); on the worst seed.
        for other, goal, strict in ((LINEAR, 0.75, False), (LPV, 1.0, True)):
            twin = {r["seed"]: r[key] for r in rows if r["case"] == c.name
                    and r["controller"] == other}
            ratios = [mine[s] / twin[s] for s in mine if s in twin and twin[s] > 0]
            if ratios:
                med, worst = float(np.median(ratios)), float(np.max(ratios))
                met = worst < goal if strict else worst <= goal
                lines.append(f"- {c.name}: neural IMC / {other} RMS |Δa| after settling: "
                             f"median {med:.3f}, worst seed {worst:.3f} (goal "
                             f"{'<' if strict else '<='} {goal:g} on the worst seed: "
                             f"{'met' if met else 'NOT met'})")
        lines += split_lines(rows, c)
    return lines


def split_lines(rows: list[dict[str, Any]], case: Case) -> list[str]:
    """RMS |Δa| after settling split into its sample-mean and within-sample parts
    (jointplay.neural.control.metrics.SPLIT_METRICS) for the internal-model controllers: medians,
    and how far the neural IMC's within-sample part alone sits against ARX-IMC's whole error."""
    mean_key, within_key = SPLIT_METRICS
    by = {name: {r["seed"]: r for r in rows if r["case"] == case.name
                 and r["controller"] == name and np.isfinite(r.get(within_key, np.nan))}
          for name in MODEL_BASED}
    if not all(by.values()):
        return []
    parts = ", ".join(f"{name} {np.median([r[within_key] for r in by[name].values()]):.3g}"
                      for name in MODEL_BASED)
    lines = [f"- {case.name}: RMS |Δa| after settling within the sample periods (the "
             f"acceleration's profile inside each period, which no model of the sampled "
             f"outputs predicts), median m/s²: {parts}"]
    seeds = [s for s in by[NEURAL] if s in by[LINEAR] and by[LINEAR][s][
        "rms_acceleration_after"] > 0]
    if seeds:
        floor = [by[NEURAL][s][within_key] / by[LINEAR][s]["rms_acceleration_after"]
                 for s in seeds]
        means = [by[NEURAL][s][mean_key] / by[LINEAR][s][mean_key] for s in seeds
                 if by[LINEAR][s][mean_key] > 0]
        lines.append(f"- {case.name}: the neural IMC's within-sample part alone is "
                     f"{np.median(floor):.3f} (median), {max(floor):.3f} (worst seed) of "
                     "ARX-IMC's RMS |Δa| after settling: the lowest ratio the neural IMC could "
                     "reach with that part as it is"
                     + (f"; on the sample-mean part, neural IMC / ARX-IMC is median "
                        f"{np.median(means):.3f}, worst seed {max(means):.3f}" if means
                        else ""))
    return lines


def summary_table(summary: dict[tuple[str, str], dict[str, Any]], cases: list[Case]) -> str:
    head = ("| case | controller | runs | " + " | ".join(
        f"{label} median | worst" for _, label in GOAL_METRICS)
        + " | diverged | guard episodes (median, worst) |")
    lines = [head, "|---|---|---|" + "---|---|" * len(GOAL_METRICS) + "---|---|"]
    for c in cases:
        for name in (*BASELINES, LINEAR, LPV, NEURAL):
            s = summary.get((c.name, name))
            if not s:
                continue
            cells = [f"{s[f'median_{k}']:.3g} | {s[f'worst_{k}']:.3g}" for k, _ in GOAL_METRICS]
            lines.append(f"| {c.name} | {name} | {s['runs']} | " + " | ".join(cells)
                         + f" | {'YES' if s['worst_diverged'] > 0 else 'no'} | "
                         f"{s['median_guard_episodes']:g}, "
                         f"{s['worst_guard_episodes']:g} |")
    return "\n".join(lines)


def plot_winners(summary: dict[tuple[str, str], dict[str, Any]], cases: list[Case],
                 folder: Path) -> Path:
    """Which controller has the lowest median of each goal metric in each case (the regimes
    where each wins), with its ratio to the runner-up."""
    from matplotlib.colors import ListedColormap

    from jointplay.common.figures import figure, save
    from jointplay.neural.study.control_plots import COLORS

    names = (*BASELINES, LINEAR, LPV, NEURAL)
    grid = np.full((len(GOAL_METRICS), len(cases)), np.nan)
    fig, axes = figure(1, 1, max(8, 1.4 * len(cases)), 4)
    ax = axes[0, 0]
    for i, (key, _) in enumerate(GOAL_METRICS):
        for j, c in enumerate(cases):
            values = {n: summary[(c.name, n)][f"median_{key}"] for n in names
                      if (c.name, n) in summary}
            if not values:
                continue
            order = sorted(values, key=lambda n: values[n])
            grid[i, j] = names.index(order[0])
            ratio = values[order[1]] / values[order[0]] if len(order) > 1 and values[
                order[0]] > 0 else float("nan")
            tie = " (tie)" if ratio < 1 + WORSE_MARGIN else ""
            ax.text(j, i, f"{order[0]}\nrunner-up {order[1]}: {ratio:.4g}x{tie}", ha="center",
                    va="center", fontsize=7)
    cmap = ListedColormap([COLORS.get(n, "C5") for n in names])
    ax.imshow(grid, cmap=cmap, vmin=-0.5, vmax=len(names) - 0.5, aspect="auto", alpha=0.45)
    ax.set_xticks(range(len(cases)), [c.name for c in cases], rotation=20)
    ax.set_yticks(range(len(GOAL_METRICS)), [label for _, label in GOAL_METRICS])
    ax.set_title("Lowest median over seeds, per case and metric", fontsize=10)
    return save(fig, folder / "study_winners.png")


def plot_study(rows: list[dict[str, Any]], cases: list[Case], folder: Path) -> list[Path]:
    from jointplay.common.figures import figure, save
    from jointplay.neural.study.control_plots import COLORS

    names = (*BASELINES, LINEAR, LPV, NEURAL)
    fig, axes = figure(len(GOAL_METRICS), 1, max(10, 1.6 * len(cases)), 10, sharex=True)
    width = 0.8 / len(names)
    rng = np.random.default_rng(0)
    for row_i, (key, label) in enumerate(GOAL_METRICS):
        ax = axes[row_i, 0]
        for ci, case in enumerate(cases):
            for ni, name in enumerate(names):
                values = np.array([r[key] for r in rows if r["case"] == case.name
                                   and r["controller"] == name], dtype=float)
                if values.size == 0:
                    continue
                x = ci + (ni - (len(names) - 1) / 2) * width
                jitter = rng.uniform(-0.25, 0.25, values.size) * width
                ax.scatter(x + jitter, values, s=9, color=COLORS.get(name, "C5"), alpha=0.7,
                           label=name if ci == 0 else None)
                ax.hlines(np.median(values), x - 0.45 * width, x + 0.45 * width,
                          color=COLORS.get(name, "C5"), lw=2)
        ax.set_yscale("log")
        ax.set_ylabel(label)
        ax.grid(True, which="both", axis="y", alpha=0.3)
    axes[-1, 0].set_xticks(range(len(cases)), [c.name for c in cases], rotation=20)
    fig.suptitle("Controllers over training seeds, trajectories and clearances (dots: seeds; "
                 "bars: medians; baselines do not depend on the seed)")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=5)
    return [save(fig, folder / "study_errors.png"),
            plot_winners(summarise(rows), cases, folder)]


__all__ = ["PAPER", "goal_checks", "plot_study", "plot_winners", "ratio_goals", "summarise",
           "summary_table", "worse_counts", "worse_lines"]
