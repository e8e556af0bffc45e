"""Sweeps of a mechanism scene: many parameter vectors on one compiled model, one table out.

The sweep file is the arms' format (docs/how-to/sweep.md): ``name``, ``description``,
``scene`` (here a mechanism file), ``mode`` (product or zip), ``[run]`` overrides and
``[parameters."NAME"]`` axes (a grid, a list, or random samples), where NAME is a parameter
of the mechanism (``jointplay inspect SCENE`` lists them) or the alias ``JOINT.clearance``
(the journal radius set to the bearing radius minus the value). Each case is one run in this
process (a run takes a fraction of a second), with the ideal mechanism beside it where the
driver moves it completely. The table (``OUT/mechanism_sweep.csv``) has a row per case: the
swept values and the run's contact statistics, the slider's and the output's (the file's
``[output]``: a four-bar's rocker angle) largest distance from the ideal mechanism's, the
largest driving torques and the energy balance.
"""

from __future__ import annotations

import itertools
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.validation import Problems, check_keys, read_toml
from jointplay.mechanism.description import MechanismScene

TABLE_NAME = "mechanism_sweep.csv"
FIGURE_NAME = "mechanism_sweep.png"
_TOP = ("name", "description", "scene", "mode", "run", "parameters")
_RUN = ("t_end", "output_step", "rtol", "atol", "max_steps")
MAX_MECHANISM_CASES = 10000
CLEARANCE_SUFFIX = ".clearance"


@dataclass(frozen=True)
class MechanismSweep:
    name: str
    scene: MechanismScene
    names: tuple[str, ...]
    cases: tuple[dict[str, float], ...]


def sweep_scene_path(path: str | Path) -> Path | None:
    """The scene a sweep file names, when that scene is a mechanism file; else None."""
    from jointplay.mechanism.reading import is_mechanism_file

    try:
        data, _ = read_toml(path, "sweep")
    except DescriptionError:
        return None
    scene = data.get("scene")
    if not isinstance(scene, str) or scene == "default":
        return None
    candidate = Path(path).parent / scene
    return candidate if candidate.is_file() and is_mechanism_file(candidate) else None


def _resolved(scene: MechanismScene, swept: dict[str, float]) -> dict[str, float]:
    """The mechanism's parameters a case sets (the clearance alias resolved)."""
    out: dict[str, float] = {}
    for name, value in swept.items():
        if name.endswith(CLEARANCE_SUFFIX):
            joint = name.removesuffix(CLEARANCE_SUFFIX)
            found = next((j for j in scene.mechanism.joints
                          if j.name == joint and j.kind == "clearance"), None)
            if found is None:
                raise DescriptionError(f"parameters.{name}", f"{joint!r} is no clearance joint "
                                       "of the mechanism")
            out[f"{joint}.journal_radius"] = found.clearance["bearing_radius"] - value
        else:
            out[name] = value
    return out


def load_mechanism_sweep(path: str | Path) -> MechanismSweep:
    """Read and validate a sweep file over a mechanism scene (every case checked)."""
    from jointplay.mechanism.reading import load_mechanism_scene
    from jointplay.sweep.axes import read_axis

    source = str(path)
    data, _ = read_toml(path, "sweep")
    problems = Problems()
    with problems.check():
        check_keys(data, _TOP, "", source)
    scene_path = sweep_scene_path(path)
    if scene_path is None:
        raise DescriptionError("scene", "must name a mechanism file beside the sweep file",
                               source)
    scene = load_mechanism_scene(scene_path)
    run = data.get("run", {})
    with problems.check():
        check_keys(run, _RUN, "run", source)
        if run:
            scene = scene.with_run(**{k: (int(v) if k == "max_steps" else float(v))
                                      for k, v in run.items()})
    mode = data.get("mode", "product")
    if mode not in ("product", "zip"):
        problems.found.append(DescriptionError("mode", f"must be product or zip, got {mode!r}",
                                               source))
    raw = data.get("parameters")
    if not isinstance(raw, dict) or not raw:
        problems.found.append(DescriptionError("parameters", "must hold one or more "
                                               "[parameters.\"NAME\"] tables", source))
        raw = {}  # reported with the problems below; no axes to read
    defaults = scene.mechanism.parameter_values()
    axes = []
    for name, spec in raw.items():
        with problems.check():
            axes.append(read_axis(name, spec, defaults, source))
    problems.raise_any(source)
    names = tuple(a.name for a in axes)
    if mode == "zip":
        lengths = {len(a.values) for a in axes}
        if len(lengths) != 1:
            raise DescriptionError("mode", "zip needs axes of one length, got "
                                   f"{sorted(lengths)}", source)
        combos = list(zip(*(a.values for a in axes), strict=True))
    else:
        count = int(np.prod([len(a.values) for a in axes]))
        if count > MAX_MECHANISM_CASES:
            raise DescriptionError("parameters", f"make {count} cases; at most "
                                   f"{MAX_MECHANISM_CASES} are allowed", source)
        combos = list(itertools.product(*(a.values for a in axes)))
    cases = tuple(dict(zip(names, combo, strict=True)) for combo in combos)
    for i, case in enumerate(cases):  # every case valid before any runs
        try:
            scene.mechanism.with_values(_resolved(scene, case))
        except DescriptionError as err:
            raise DescriptionError(f"parameters (case {i + 1}: {case})",
                                   f"{err.field}: {err.message}", source) from None
    return MechanismSweep(name=str(data.get("name", f"{scene.name}_sweep")), scene=scene,
                          names=names, cases=cases)


COLUMNS = ("impacts", "impact_rate", "contact_fraction", "median_peak_force",
           "largest_peak_force", "median_approach_speed", "slider_from_ideal_m",
           "output_from_ideal", "largest_driving_torque", "largest_ideal_driving_torque",
           "energy_residual", "wall_time_s")


def run_mechanism_sweep(sweep: MechanismSweep, out: str | Path, *, quiet: bool = True
                        ) -> tuple[Path, list[Path], float]:
    """Run every case; write the table and its figure into ``out`` (all or nothing)."""
    from jointplay.common.files import OutputPlan, all_or_nothing, atomic_write_text, make_folder
    from jointplay.mechanism.model import model_for
    from jointplay.mechanism.simulate import (
        ideal_motion,
        load_functions,
        load_values,
        simulate_mechanism,
    )

    out = Path(out)
    plan = OutputPlan()
    plan.file("--out", out / TABLE_NAME, "the table")
    plan.file("--out", out / FIGURE_NAME, "the figure")
    plan.check()
    model = model_for(sweep.scene.mechanism)
    started = time.perf_counter()
    rows = []
    for i, case in enumerate(sweep.cases):
        scene = sweep.scene.with_mechanism(
            sweep.scene.mechanism.with_values(_resolved(sweep.scene, case)))
        result = simulate_mechanism(scene, model=model)
        p = model.parameter_vector(scene.mechanism)
        try:
            ideal: dict[str, np.ndarray] | None = ideal_motion(
                model, p, result.t, scene.initial,
                load_values(load_functions(scene), result.t), guess=result.x)
        except DescriptionError:
            ideal = None
        stats = result.contact_statistics()
        sliders = [k for k, name in enumerate(result.coordinates) if name.endswith(".position")]
        output = result.coordinates.index(result.output)
        row = {**case, **stats,
               "slider_from_ideal_m": (float(np.max(np.abs(result.x[:, sliders]
                                                           - ideal["x"][:, sliders])))
                                       if ideal is not None and sliders else np.nan),
               # the output the file names (its unit: m for a slider, rad for a rocker)
               "output_from_ideal": (float(np.max(np.abs(result.x[:, output]
                                                         - ideal["x"][:, output])))
                                     if ideal is not None else np.nan),
               "largest_driving_torque": float(np.max(np.abs(result.driving_torque))),
               "largest_ideal_driving_torque": (float(np.max(np.abs(ideal["driving_torque"])))
                                                if ideal is not None else np.nan),
               "energy_residual": float(np.max(np.abs(result.energy_residual))),
               "wall_time_s": float(result.stats["wall_time_s"])}
        rows.append(row)
        if not quiet:
            print(f"  case {i + 1}/{len(sweep.cases)}: "
                  + ", ".join(f"{k} = {v:g}" for k, v in case.items())
                  + f": {stats['impacts']:.0f} impacts")
    header = [*sweep.names, *COLUMNS]
    lines = [",".join(header)] + [",".join(f"{row[k]:.17g}" for k in header) for row in rows]
    with all_or_nothing(plan):
        make_folder(out)
        atomic_write_text(out / TABLE_NAME, "\n".join(lines) + "\n")
        figure = _figure(sweep, rows, out / FIGURE_NAME)
    return out / TABLE_NAME, [figure], time.perf_counter() - started


def _figure(sweep: MechanismSweep, rows: list[dict[str, Any]], path: Path) -> Path:
    from jointplay.common.figures import figure, save

    first = sweep.names[0]
    x = np.array([row[first] for row in rows])
    order = np.argsort(x, kind="stable")
    fig, axes = figure(1, 2, 9.0, 3.6)
    for ax, key, label in ((axes[0, 0], "largest_peak_force", "largest contact force (N)"),
                           (axes[0, 1], "contact_fraction", "time in contact (fraction)")):
        ax.plot(x[order], np.array([row[key] for row in rows])[order], "o", ms=4)
        ax.set_xlabel(first)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    return save(fig, path)
