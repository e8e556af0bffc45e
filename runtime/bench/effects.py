"""Bench rows for the effects a scene can ask for: lubricated joints and Archard wear.

``jointplay bench work-precision --effects`` and ``jointplay bench fidelity --effects`` add
them to their tables. The scene's robot gets each effect in turn (joints without an axial
length get ``DEFAULT_LENGTH``); each is a separately compiled model.

* Lubrication changes the motion: its work-precision rows are measured against its own
  reference (CVODES at the reference tolerance, checked like the scene's where the check
  gets through), and its fidelity
  row gives how far the lubricant moves the tip from the dry full model.
* Wear leaves the motion alone (it is integrated beside it): its rows are measured against the
  dry reference, so their errors repeat the dry rows' and their times show what integrating
  the wear costs.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from jointplay.robot import Lubrication, Wear
from jointplay.scene.definition import Scene

DEFAULT_LENGTH = 10.0e-3  # m, axial length given to joints that have none
EFFECTS = ("lubrication", "wear")


def effect_scene(scene: Scene, effect: str) -> Scene:
    """The scene with one effect switched on (the description's defaults otherwise)."""
    robot = scene.robot
    joints = tuple(replace(j, length=j.length or DEFAULT_LENGTH) if j.has_clearance else j
                   for j in robot.joints)
    changes: dict[str, Any] = {"joints": joints, "name": f"{robot.name}_{effect}"}
    if effect == "lubrication":
        if robot.lubrication.model == "none":
            changes["lubrication"] = Lubrication(model="short-bearing")
    elif robot.wear.model == "none":
        changes["wear"] = Wear(model="archard")
    return scene.with_robot(replace(robot, **changes))


def effect_label(scene: Scene, effect: str) -> str:
    robot = effect_scene(scene, effect).robot
    if effect == "lubrication":
        lub = robot.lubrication
        return f"+ lubrication ({lub.model}, {lub.viscosity:g} Pa s)"
    return f"+ Archard wear (k {robot.wear.coefficient:g}, H {robot.wear.hardness:g} Pa)"


def work_precision_rows(scene: Scene, dry_reference: Any, *, rtols: Any, repeats: int,
                        reference_rtol: float, check: str, check_step: float,
                        quiet: bool) -> list[dict[str, Any]]:
    """BDF rows at ``rtols`` and at the scene's settings, for each effect."""
    from jointplay.bench import work_precision
    from jointplay.store.lookup import model_for

    rows: list[dict[str, Any]] = []
    if not scene.robot.clearance_joints:
        return rows
    for effect in EFFECTS:
        worn = effect_scene(scene, effect)
        model = model_for(worn.robot)
        reference = dry_reference if effect == "wear" else _reference(
            worn, model, reference_rtol, check, check_step)
        _, effect_rows = work_precision(worn, model, methods=["bdf"], rtols=rtols, steps=[],
                                        repeats=repeats, reference=reference, quiet=quiet)
        for row in effect_rows:
            row["method"] = f"bdf {effect_label(scene, effect)}"
            row["config"] = f"{effect}: {row['config']}"
        rows += effect_rows
    return rows


def _reference(scene: Scene, model: Any, rtol: float, check: str, check_step: float) -> Any:
    """The effect's own reference, as the scene's; where only the check fails (IDAS at the
    reference tolerance does not always get through a closing film), CVODES alone, with the
    check's failure as its label."""
    from jointplay.bench import Reference, reference_solution, run_label, timed_runs
    from jointplay.common.errors import SimulationError

    try:
        return reference_solution(scene, model, rtol=rtol, check=check, check_step=check_step)
    except SimulationError as err:
        ref_scene = scene.with_run(integrator="cvodes", rtol=rtol, atol=rtol)
        timed = timed_runs(ref_scene, model, 1)
        if timed.result is None:
            raise
        return Reference(result=timed.result, label=run_label(ref_scene), cpu_s=timed.cpu_s[0],
                         check_label=f"none: {err}", check_cpu_s=float("nan"), agreement={})


def fidelity_rows(scene: Scene, run_scene: Scene, reference: Any,
                  repeats: int) -> list[dict[str, Any]]:
    """One row per effect at the scene's run settings, against the dry full model."""
    from jointplay.bench import (
        cold_compile_seconds,
        run_counts,
        run_label,
        timed_runs,
        tip_errors,
    )
    from jointplay.bench.fidelity import _run_settings
    from jointplay.store.lookup import model_for

    rows: list[dict[str, Any]] = []
    if not scene.robot.clearance_joints:
        return rows
    notes = {"lubrication": "against the dry full model: what the lubricant changes",
             "wear": "wear leaves the motion unchanged: the cost of integrating it"}
    for effect in EFFECTS:
        worn = effect_scene(scene, effect)
        model = model_for(worn.robot)
        cfg = worn.with_run(**_run_settings(run_scene))
        timed = timed_runs(cfg, model, repeats)
        row = {"rung": effect_label(scene, effect), "model": model.name, "run": run_label(cfg),
               "tolerance": "scene", "status": "ok" if timed.result else "failed",
               "note": notes[effect] if timed.result else (timed.failure or ""),
               "repeats": len(timed.cpu_s), "compile_s": cold_compile_seconds(model),
               **timed.spread("cpu"), **timed.spread("wall"), **run_counts(timed.result)}
        row["realtime_factor"] = row["cpu_median_s"] / cfg.run.t_end
        row.update(tip_errors(timed.result, reference) if timed.result is not None
                   else {k: float("nan") for k in ("err_position", "err_velocity",
                                                   "err_acceleration")})
        rows.append(row)
    return rows
