"""Closed loops on the clearance robot: the ``jointplay control`` command over the comparison.

Controllers, each against the ideal-joint robot's motion under the scene's torques:

- open loop: the scene's torques only;
- PD: the inner loop alone;
- computed torque with the ideal-joint model;
- ARX-IMC: the internal-model law with the linear ARX twin inside;
- LPV-ARX-IMC: the same law with the LPV-ARX model inside (its input gain and offset affine
  in the scheduling signals, jointplay.neural.identify.lpv), guarded, the ARX twin as its fallback;
- neural IMC: the same law with the NARX network inside, guarded (see
  jointplay.neural.control.imc), the ARX twin as its fallback.

The loop and its laws are in jointplay.neural.control.loop, the metrics in
jointplay.neural.control.metrics, the whole comparison and the stability verdict in
jointplay.neural.study.comparison; their names are importable from here as well.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.neural.control import EXIT_DIVERGED as EXIT_DIVERGED
from jointplay.neural.control.imc import (
    FLAGS,
    Controller,
    ControllerSettings,
    build_step,
    compile_controller,
    default_tracked,
    generate_c,
    horizon_gain,
    local_spectral_radii,
    nominal_spectral_radius,
    per_call_us,
    resolve_settings,
)
from jointplay.neural.control.loop import (
    Law,
    LoopConditions,
    Run,
    computed_torque_law,
    imc_law,
    pd_law,
    run_loop,
)
from jointplay.neural.control.metrics import (
    GUARD_METRICS,
    METRICS,
    dense_acceleration_error,
    metrics_table,
    run_metrics,
    tip_errors,
)
from jointplay.neural.model.narx import ARX_FILE, LPV_FILE, Narx, load_narx
from jointplay.neural.study.comparison import (
    CONTROLLERS,
    DEFAULT_TRANSIENT,
    DIVERGENCE_FACTOR,
    LINEAR,
    MARGINAL,
    MODEL_BASED,
    NEURAL,
    Comparison,
    compare,
    stability_radii,
    verdict,
    write_runs,
)

# ---- the command ------------------------------------------------------------------------------



def test_case_scenes(model_dir: Path, scene: Any) -> list[tuple[str, Any]]:
    """Scenes driven by the base torques of the stored test trajectories."""
    from jointplay.neural.identify.pipeline import Chirp, Multisine, read_datasets, with_torques
    from jointplay.scene.expressions import parse_expression
    from jointplay.scene.tables import TableColumn

    path = model_dir / "datasets.h5"
    if not path.is_file():
        raise DescriptionError("--test-cases", f"{path} is missing; the model folder has no "
                               "stored test trajectories (run `jointplay identify` again)")
    trajectories, meta = read_datasets(path)
    out = []
    for tr in (t for t in trajectories if t.split == "test"):
        torques: list[Any] = []
        for i, desc in enumerate(tr.description.get("base", [])):
            kind = desc.get("kind")
            if kind == "multisine":
                torques.append(Multisine(np.array(desc["amplitude"]), np.array(desc["frequency"]),
                                         np.array(desc["phase"])))
            elif kind == "chirp":
                torques.append(Chirp(desc["amplitude"], desc["f0"], desc["f1"],
                                     desc["duration"], desc["phase"]))
            elif kind == "steps":
                torques.append(TableColumn(f"joint{i}", np.array(desc["times"]),
                                           np.array(desc["values"])))
            else:
                torques.append(parse_expression(desc["text"], field="torques",
                                                constants=scene.constants))
        duration = float(tr.t[-1])
        out.append((f"test {tr.family}", with_torques(scene.with_run(t_end=duration), torques)))
    del meta
    return out


def load_lpv(model_dir: Path) -> Narx | None:
    """The LPV-ARX model of a model folder (lpv.json), or None for folders written before
    identify made it."""
    if not (model_dir / LPV_FILE).is_file():
        return None
    return load_narx(model_dir, filename=LPV_FILE)


def load_twin(model_dir: Path, narx: Narx) -> Narx:
    """The ARX twin of a model folder: arx.json, or (folders written before it existed) a
    least-squares fit on the stored training runs, as identify makes it."""
    from dataclasses import replace

    if (model_dir / ARX_FILE).is_file():
        return load_narx(model_dir, filename=ARX_FILE)
    from jointplay.neural.identify.linear_fit import fit_arx, segments
    from jointplay.neural.identify.pipeline import read_datasets

    path = model_dir / "datasets.h5"
    if not path.is_file():
        raise DescriptionError("--model", f"{model_dir} has neither {ARX_FILE} nor datasets.h5 "
                               "for the ARX baseline: run `jointplay identify` again")
    trajectories, _ = read_datasets(path)
    skip = max(0, round(narx.context.get("plant", {}).get("transient", DEFAULT_TRANSIENT)
                        / narx.sample_time))
    names = {"output_names": narx.output_names, "output_units": narx.output_units,
             "input_names": narx.input_names, "input_units": narx.input_units}
    arx = fit_arx(segments([t for t in trajectories if t.split == "train"], skip), names,
                  narx.output_lags, narx.input_lags, narx.sample_time)
    return replace(arx, context=narx.context)










__all__ = ["CONTROLLERS", "DEFAULT_TRANSIENT", "DIVERGENCE_FACTOR", "FLAGS", "GUARD_METRICS",
           "LINEAR", "MARGINAL", "METRICS", "MODEL_BASED", "NEURAL", "Comparison", "Controller",
           "ControllerSettings", "Law", "LoopConditions", "Run", "build_step", "compare",
           "compile_controller", "computed_torque_law",
           "default_tracked", "dense_acceleration_error", "generate_c", "horizon_gain",
           "imc_law", "load_lpv", "load_twin", "local_spectral_radii", "metrics_table",
           "nominal_spectral_radius", "pd_law", "per_call_us", "resolve_settings",
           "run_loop", "run_metrics", "stability_radii",
           "test_case_scenes", "tip_errors", "verdict", "write_runs"]
