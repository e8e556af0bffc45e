"""What a person reads after ``jointplay simulate``: the run's cost, energy balance, contacts
per clearance joint, and the tip's error against ideal joints."""

from __future__ import annotations

from typing import Any

import numpy as np


def _output_step_text(result: Any) -> str:
    if result.n_samples < 2:
        return "at the output samples"
    step = float(np.median(np.diff(result.t)))
    return f"every {step * 1e3:.4g} ms" if step >= 1e-4 else f"every {step * 1e6:.4g} us"


def _sensitive_note(result: Any, joint: int) -> str:
    """' (N tolerance-sensitive)' for a joint's impacts after the agreement horizon of the
    run's accuracy check, '' without a check or without such impacts."""
    accuracy = getattr(result, "accuracy", None)
    if accuracy is None:
        return ""
    sensitive = int(np.count_nonzero(accuracy.tolerance_sensitive
                                     & (np.asarray(result.impacts.joint) == joint)))
    return f" ({sensitive} tolerance-sensitive)" if sensitive else ""


def contact_lines(result: Any) -> list[str]:
    """Per clearance joint: impacts, largest approach speed, and the located peak force and
    penetration with their times (from the impact table); a sampled value says it is one."""
    from jointplay.results.contacts import joint_contacts

    lines = []
    for c in joint_contacts(result):
        if c.impacts == 0 and c.located:
            lines.append(f"  joint {c.joint}: no impacts, no contact")
            continue
        head = f"  joint {c.joint}: {c.impacts} impacts"
        head += _sensitive_note(result, c.joint)
        if c.impacts:
            head += (f", largest approach speed {c.max_approach_speed:.4g} m/s (onset at "
                     f"{c.max_approach_speed_time:.7g} s)")
        lines.append(head)
        if c.located:
            lines.append(f"    peak normal force {c.peak_force:.4g} N at {c.peak_force_time:.7g} "
                         f"s, max penetration {c.max_penetration * 1e6:.4g} um at "
                         f"{c.max_penetration_time:.7g} s (located)")
        else:
            lines.append(f"    peak normal force and max penetration {c.note}")
            lines.append(f"    sampled {_output_step_text(result)} (not the peak): normal "
                         f"force up to {c.sampled_peak_force:.4g} N, penetration up to "
                         f"{c.sampled_max_penetration * 1e6:.4g} um")
    return lines


def film_lines(result: Any) -> list[str]:
    """Per lubricated joint: the largest eccentricity ratio, and whether the film went above
    its transition (where it is regularised, so that value depends on the transition)."""
    names = list(result.parameter_names)
    if "lubrication.transition" not in names or not len(result.clearance_joints):
        return []
    transition = float(result.parameters[names.index("lubrication.transition")])
    ratio = np.linalg.norm(result.eccentricity, axis=2) / result.radial_clearance
    lines = []
    for k, joint in enumerate(result.clearance_joints):
        largest = float(ratio[:, k].max())
        if largest <= transition:
            lines.append(f"  joint {joint} film: largest eccentricity ratio {largest:.4g} "
                         f"(sampled {_output_step_text(result)}), below the film's transition "
                         f"{transition:g}")
            continue
        first = float(result.t[np.argmax(ratio[:, k] > transition)])
        lines.append(f"  joint {joint} film: eccentricity ratio above the film's transition "
                     f"{transition:g} from t = {first:.4g} s (largest {largest:.4g}): the film "
                     "is regularised there, so how far it closes depends on "
                     "lubrication.transition, not on the film")
    return lines


def divided_steps_lines(stats: Any) -> list[str]:
    """A line on the Radau steps that failed at ``run.step`` and were taken in parts."""
    count = int(stats.get("subdivided_steps", 0))
    if not count:
        return []
    return [f"  {count} radau steps failed at run.step and were taken in 10x shorter parts "
            "(100x, 1000x where a part failed too)"]


def summary(result: Any) -> str:
    """A few lines a person reads after a run."""
    st = result.stats
    lines = [
        f"simulated {result.t[-1]:g} s with {result.integrator} in {st['wall_time_s']:.2f} s "
        f"wall ({st['realtime_factor']:.3f} x real time)",
        f"  steps {st['steps']}, right-hand sides {st['rhs_evaluations']}, Jacobians "
        f"{st['jacobian_evaluations']}, contact events {st['events']}, impacts "
        f"{st['impacts']}",
        f"  energy balance: max |E - E0 - W_drive + D| = "
        f"{np.max(np.abs(result.energy['balance'])):.3g} J "
        f"(drive work {result.energy['drive_work'][-1]:.4g} J, dissipated "
        f"{result.energy['dissipated'][-1]:.4g} J)",
    ]
    lines += divided_steps_lines(st)
    if getattr(result, "implausible", None):
        lines.append("  IMPLAUSIBLE (kept with plausibility = warn): the contact laws do not "
                     "describe this run; see the warning above")
    if result.accuracy is not None:
        lines += result.accuracy.lines()
    lines += contact_lines(result)
    lines += film_lines(result)
    for k, j in enumerate(result.wear.joints if result.wear is not None else ()):
        wear = result.wear
        lines.append(f"  joint {j} wear: volume {wear.volume[k]:.4g} m^3, deepest "
                     f"{wear.bearing_depth[k].max():.4g} m on the bearing, "
                     f"{wear.journal_depth[k].max():.4g} m on the journal")
    if result.ideal is not None:
        ideal = result.ideal
        for name, a, b, unit in (("position", result.tip_position, ideal.tip_position, "m"),
                                 ("velocity", result.tip_velocity, ideal.tip_velocity, "m/s"),
                                 ("acceleration", result.tip_acceleration,
                                  ideal.tip_acceleration, "m/s^2")):
            err = np.max(np.linalg.norm(a - b, axis=1))
            lines.append(f"  end-effector {name} error vs ideal joints: max {err:.4g} {unit} "
                         f"(sampled {_output_step_text(result)})")
    return "\n".join(lines)
