"""How well a run tracked the ideal robot: end-effector errors, their maxima and RMS (whole
run and after the settling transient), the guard's counts, and the table that sets the
controllers side by side."""

from __future__ import annotations

import numpy as np

from jointplay.neural.control.loop import Run

METRICS = ("position", "velocity", "acceleration")
_SLICES = {"position": slice(0, 2), "velocity": slice(2, 4), "acceleration": slice(4, 6)}


def tip_errors(run: Run, reference: np.ndarray, nj: int) -> dict[str, np.ndarray]:
    """|end-effector error| per sample (Euclidean norm over x, y) for each quantity."""
    base = 2 * nj
    ref = reference[: run.y.shape[0]]
    return {k: np.linalg.norm(run.y[:, base + s.start: base + s.stop]
                              - ref[:, base + s.start: base + s.stop], axis=1)
            for k, s in _SLICES.items()}


GUARD_METRICS = {"guard_episodes": "episodes", "distrusted_samples": "model_distrusted",
                 "fallback_samples": "on_fallback_model", "inner_only_samples": "inner_loop_only",
                 "input_bound_samples": "input_at_trust_bound"}


def dense_acceleration_error(run: Run, dense_reference: np.ndarray) -> np.ndarray:
    """|end-effector acceleration error| at the run's dense points; ``dense_reference`` is the
    reference's acceleration on the same grid from t = 0 (row i at i T / SUBSTEPS)."""
    return np.linalg.norm(_dense_error(run, dense_reference), axis=1)


def _dense_error(run: Run, dense_reference: np.ndarray) -> np.ndarray:
    """The (x, y) end-effector acceleration error at the run's dense points."""
    return run.dense_acceleration - dense_reference[1: run.dense_t.size + 1]


# RMS |Δa| after the transient split in two (from the dense acceleration; NaN without it): the
# error's mean over each sample period, and what is left of it within the periods. The two
# add in squares to the RMS. The sample-mean part is what the sampled outputs carry (about
# the tip velocity error's change over each period / T); the within-sample part is the
# acceleration's profile inside the periods, which no model of the sampled outputs predicts
# and a torque held over the period changes only through its steps.
SPLIT_METRICS = ("rms_acceleration_after_sample_mean", "rms_acceleration_after_within_sample")


def acceleration_split(error: np.ndarray, substeps: int, transient: int) -> dict[str, float]:
    """:data:`SPLIT_METRICS` of the (x, y) acceleration error at a run's dense points
    (``substeps`` per sample period): over the periods after ``transient`` samples, the
    error's mean over each period, and the rest."""
    n = error.shape[0]
    periods = error[: (n // substeps) * substeps].reshape(-1, substeps, 2)
    if periods.shape[0] > transient:  # as the RMS after the transient: all of a short run
        periods = periods[transient:]
    mean = periods.mean(axis=1, keepdims=True)
    return {SPLIT_METRICS[0]: float(np.sqrt(np.mean(np.sum(mean[:, 0] ** 2, axis=-1)))),
            SPLIT_METRICS[1]: float(np.sqrt(np.mean(np.sum((periods - mean) ** 2, axis=-1))))}


def run_metrics(run: Run, reference: np.ndarray, nj: int, transient: int,
                dense_reference: np.ndarray | None = None,
                engaged: int = 0) -> dict[str, float]:
    """Maxima and RMS of the end-effector errors (whole run, from ``engaged`` samples on and
    after ``transient`` samples), the largest added torque, impacts, whether the run diverged
    and the guard's counts.

    ``engaged``: the sample at which the outer loop engages; before it every controller is
    the inner loop alone, so the "_engaged" metrics are the whole run as far as any
    controller can act on it. With ``dense_reference`` and a run that recorded its
    acceleration between samples, the acceleration metrics are taken over those points (the
    RMS a time average), the others at the samples."""
    err = tip_errors(run, reference, nj)
    out: dict[str, float] = {}
    dense = dense_reference is not None and run.dense_t.size > 0
    out.update(dict.fromkeys(SPLIT_METRICS, float("nan")))
    for k, e in err.items():
        if k == "acceleration" and dense:
            assert dense_reference is not None
            substeps = round(run.dense_t.size / max(1, run.y.shape[0] - 1))
            after_k = transient * substeps  # the first point after the transient's end
            vectors = _dense_error(run, dense_reference)
            e = np.linalg.norm(vectors, axis=1)
            after = e[after_k:] if e.size > after_k else e
            acting = e[engaged * substeps:] if e.size > engaged * substeps else e
            out.update(acceleration_split(vectors, substeps, transient))
        else:
            after = e[transient:] if e.size > transient else e
            acting = e[engaged:] if e.size > engaged else e
        out[f"max_{k}_engaged"] = float(np.max(acting))
        out[f"rms_{k}_engaged"] = float(np.sqrt(np.mean(acting ** 2)))
        out[f"max_{k}"] = float(np.max(e))
        out[f"max_{k}_after"] = float(np.max(after))
        out[f"rms_{k}"] = float(np.sqrt(np.mean(e ** 2)))
        out[f"rms_{k}_after"] = float(np.sqrt(np.mean(after ** 2)))
    out["max_torque_added"] = float(np.max(np.abs(run.tau)))
    out["impacts"] = float(run.impacts)
    out["diverged"] = 1.0 if run.diverged else 0.0
    counts = run.guard_counts
    for key, name in GUARD_METRICS.items():
        out[key] = float(counts.get(name, 0))
    return out


# The metrics the table reports, each judged against the open loop and PD where a controller
# can act: the whole run from the outer loop's engagement on (before it every row is the inner
# loop alone, and the journals' release from the bearing centres, which no joint torque
# prevents, sets the open loop's whole-run figures), and the window after settling.
REPORTED = {"max_position_engaged": "max |Δp| from engagement",
            "max_velocity_engaged": "max |Δv| from engagement",
            "max_acceleration_engaged": "max |Δa| from engagement",
            "rms_acceleration_engaged": "RMS |Δa| from engagement",
            "max_velocity_after": "max |Δv| after the transient",
            "max_acceleration_after": "max |Δa| after the transient",
            "rms_acceleration_after": "RMS |Δa| after the transient"}
# A ratio within this of 1 is a tie, not "worse": 1 %, above what the plant's integration
# changes in these metrics (control-study --verify states each run's accuracy) and below any
# difference a controller is chosen for.
WORSE_MARGIN = 0.01


# Against PD only the internal-model controllers are judged, and only after settling: PD is
# the inner loop they run around, acting from t = 0, while between their engagement and the
# end of settling they are still letting go of the deviation measured at engagement (the
# setpoint filter); against the open loop every controller is judged in both windows.
MODEL_BASED_NAMES = ("ARX-IMC", "LPV-ARX-IMC", "neural IMC")
AFTER_SETTLING = ("max_velocity_after", "max_acceleration_after", "rms_acceleration_after")


def judged(name: str, base: str) -> tuple[str, ...]:
    """The reported metrics on which controller ``name`` is judged against ``base``."""
    if base == "open loop":
        return tuple(REPORTED) if name != "open loop" else ()
    return AFTER_SETTLING if name.startswith(MODEL_BASED_NAMES) else ()


def worse_than_baselines(metrics: dict[str, dict[str, float]]
                         ) -> list[tuple[str, str, str, float]]:
    """Every (controller, metric, baseline, ratio) where a controller ends worse than the open
    loop on a reported metric, or an internal-model controller worse than PD after settling
    (:func:`judged`; ties within WORSE_MARGIN)."""
    out: list[tuple[str, str, str, float]] = []
    for name, mt in metrics.items():
        for base in ("open loop", "PD"):
            if name == base or base not in metrics:
                continue
            for key in judged(name, base):
                ref = metrics[base].get(key, 0.0)
                if ref > 0 and mt.get(key, 0.0) > ref * (1 + WORSE_MARGIN):
                    out.append((name, key, base, mt[key] / ref))
    return out


def worse_lines(metrics: dict[str, dict[str, float]]) -> list[str]:
    """One sentence per controller and baseline it ends worse than."""
    grouped: dict[tuple[str, str], list[str]] = {}
    for name, key, base, ratio in worse_than_baselines(metrics):
        grouped.setdefault((name, base), []).append(f"{REPORTED[key]} {ratio:.4g}x")
    return [f"{name} is worse than {'no control (open loop)' if base == 'open loop' else base}"
            f" on " + ", ".join(items) for (name, base), items in grouped.items()]


def metrics_table(metrics: dict[str, dict[str, float]], transient_s: float,
                  recommended: str | None = None) -> str:
    """Markdown table: every controller side by side (``recommended`` marked), and the
    open-loop / controller ratio."""
    cols = [("max_position", "max \\|Δp\\| [m]"), ("max_velocity", "max \\|Δv\\| [m/s]"),
            ("max_acceleration", "max \\|Δa\\| [m/s²]"),
            ("rms_acceleration", "RMS \\|Δa\\| [m/s²]")]
    ms = f"{transient_s * 1e3:g} ms"
    head = ("| controller | " + " | ".join(f"{label}" for _, label in cols)
            + f" | after {ms}: max \\|Δv\\| | max \\|Δa\\| | RMS \\|Δa\\| | impacts |")
    lines = [head, "|---" * (len(cols) + 5) + "|"]
    base = metrics.get("open loop")
    for name, mt in metrics.items():
        cells = [f"{mt[k]:.3g}" for k, _ in cols]
        cells += [f"{mt['max_velocity_after']:.3g}", f"{mt['max_acceleration_after']:.3g}",
                  f"{mt['rms_acceleration_after']:.3g}", f"{mt['impacts']:.0f}"]
        label = f"{name} (DIVERGED)" if mt.get("diverged") else name
        label = f"**{label} (recommended)**" if name == recommended else label
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    if base is not None:
        for name, mt in metrics.items():
            if name == "open loop":
                continue
            keys = [k for k, _ in cols] + ["max_velocity_after", "max_acceleration_after",
                                            "rms_acceleration_after"]
            cells = [f"{base[k] / mt[k]:.3g}x" if mt[k] > 0 else "-" for k in keys]
            lines.append(f"| reduction, {name} | " + " | ".join(cells) + " | |")
    return "\n".join(lines)


__all__ = ["AFTER_SETTLING", "GUARD_METRICS", "METRICS", "REPORTED", "SPLIT_METRICS",
           "WORSE_MARGIN", "acceleration_split", "dense_acceleration_error", "judged",
           "metrics_table", "run_metrics", "tip_errors", "worse_lines", "worse_than_baselines"]
