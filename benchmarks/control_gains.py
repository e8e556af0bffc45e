"""How torque reaches the tracked outputs within a few samples: the rigid arm against the
identified models.

    python benchmarks/control_gains.py --out out/bench/control_gains --model MODEL_DIR

Reports (1) the ideal-joint arm's mass matrix M at the scene's start and its one-step gain
from torque to angle, T^2/2 M^-1 (a double integrator under a held torque); (2) for the
model folder's network and its ARX twin, d y(k+d) / d v with v held over d = 1, 2, 3, 5
samples, from rest: the angles' gains, and the singular values of the scaled Jacobian of
the default tracked outputs (C J, what the controller inverts); (3) the same over 400
regressors drawn (seed 0) from the training runs: the spread of the network's one-step angle
gains and of its singular values, and how many entries of C J have the ARX twin's sign.
Writes control_gains.md.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

import casadi as ca
import h5py
import numpy as np

from jointplay.common.files import atomic_write_text
from jointplay.neural.control.imc_settings import ControllerSettings, resolve_settings
from jointplay.neural.control.imc_step import _tracking_matrix
from jointplay.neural.control.internal_model import _rollout, horizon_gain
from jointplay.neural.model.narx import Narx, load_narx
from jointplay.neural.study.control_run import load_twin
from jointplay.scene.definition import default_scene, ideal_counterpart
from jointplay.sim import load_scene_model

HORIZONS = (1, 2, 3, 5)
SAMPLES = 400


def rigid_gain(sample_time: float) -> tuple[np.ndarray, np.ndarray]:
    scene = default_scene()
    model = load_scene_model(scene, ideal=True)
    p = np.asarray(ideal_counterpart(scene.robot).parameter_values(), dtype=float)
    q0 = np.array([float(scene.initial.get(f"q{j}", 0.0)) for j in scene.robot.moving_joints])
    mass = np.asarray(model.mass_matrix(q0, p), dtype=float)
    return mass, sample_time ** 2 / 2 * np.linalg.inv(mass)


def training_regressors(folder: Path, narx: Narx) -> np.ndarray:
    skip = round(0.05 / narx.sample_time)  # the start-up training leaves out
    with h5py.File(folder / "datasets.h5", "r") as f:
        rows = [narx.regressors(f["train"][k]["y"][skip:] - f["train"][k]["r"][skip:],
                                f["train"][k]["v"][skip:]) for k in sorted(f["train"])]
    all_rows = np.concatenate(rows)
    return all_rows[np.random.default_rng(0).choice(len(all_rows), SAMPLES, replace=False)]


def gain_function(model: Narx, d: int) -> ca.Function:
    ny, nu = model.n_outputs, model.n_inputs
    hist = ca.MX.sym("h", model.output_lags * ny)
    upast = ca.MX.sym("u", (model.input_lags - 1) * nu)
    v = ca.MX.sym("v", nu)
    return ca.Function("J", [hist, upast, v], [ca.jacobian(_rollout(model, hist, upast, v, d),
                                                           v)])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("--model", required=True, help="a folder written by jointplay identify")
    args = parser.parse_args()
    folder = Path(args.model)
    narx = load_narx(folder)
    arx = load_twin(folder, narx)
    settings = resolve_settings(narx, ControllerSettings())
    cm = _tracking_matrix(narx, settings)
    iq = [narx.output_index("q2"), narx.output_index("q3")]
    mass, rigid = rigid_gain(narx.sample_time)

    def fmt(a: np.ndarray, precision: int = 3) -> str:  # one line, for a table cell
        return np.array2string(a, precision=precision, separator=", ",
                               max_line_width=10 ** 6).replace("\n", "")
    lines = [f"Model {folder}; load average {os.getloadavg()[0]:.2f}", "",
             f"Ideal-joint arm at the start: M = {fmt(mass, precision=4)} kg m^2; "
             f"T^2/2 M^-1 = {fmt(rigid, precision=3)} rad per N m "
             f"(T^2/2M_22 = {narx.sample_time ** 2 / 2 / mass[0, 0]:.3g})", "",
             f"Tracked (default): {', '.join(settings.tracked)}, each over its scale", "",
             "| model | d | dq/dv at rest (q2,q3 x v2,v3) | singular values of C J at rest | "
             "along training: dq2/dv2 min..max | dq3/dv3 min..max | sigma_min median (min) "
             "| cond median (max) | entries of C J with ARX's sign, median (min) |",
             "|---|---|---|---|---|---|---|---|---|"]
    phis = training_regressors(folder, narx)
    ny, nu, na = narx.n_outputs, narx.n_inputs, narx.output_lags
    for label, model in (("network", narx), ("ARX", arx)):
        for d in HORIZONS:
            g0 = horizon_gain(model, d)
            sv0 = np.linalg.svd(cm @ g0, compute_uv=False)
            ref_sign = np.sign(cm @ horizon_gain(arx, d))
            jac = gain_function(model, d)
            gq, svs, agree = [], [], []
            for phi in phis:
                jk = np.asarray(jac(phi[:na * ny], phi[na * ny + nu:], phi[na * ny:na * ny + nu]))
                sv = np.linalg.svd(cm @ jk, compute_uv=False)
                gq.append([jk[iq[0], 0], jk[iq[1], 1]])
                svs.append(sv)
                agree.append(int((np.sign(cm @ jk) == ref_sign).sum()))
            gqa, sva = np.array(gq), np.array(svs)
            cond = sva[:, 0] / sva[:, -1]
            lines.append(
                f"| {label} | {d} | {fmt(g0[iq], precision=3)} | {fmt(sv0, precision=3)} | "
                f"{gqa[:, 0].min():.3g}..{gqa[:, 0].max():.3g} | "
                f"{gqa[:, 1].min():.3g}..{gqa[:, 1].max():.3g} | "
                f"{np.median(sva[:, -1]):.3g} ({sva[:, -1].min():.3g}) | "
                f"{np.median(cond):.3g} ({cond.max():.3g}) | "
                f"{int(np.median(agree))} of {cm.shape[0] * nu} ({min(agree)}) |")
            print(lines[-1], flush=True)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    atomic_write_text(out / "control_gains.md", "\n".join(lines) + "\n")
    print(f"wrote {out / 'control_gains.md'}")


if __name__ == "__main__":
    main()
