"""Which outputs and regressors a linear model of the clearance plant should see, measured.

    python benchmarks/identify_outputs.py --model MODEL_DIR [--out DIR]

On the trajectories stored in a model folder (``datasets.h5`` of ``jointplay identify``) fits,
by least squares on the training runs, and compares in free run over 200-sample windows on the
validation and test runs (the loss ``identify`` selects by: mean squared deviation error, each
output divided by its scale):

- ``ARX, deviations``: the twin ``identify`` fits (deviations from the ideal robot; inputs the
  added torque);
- ``ARX, absolute``: the same structure on the absolute outputs, with the drive torques of the
  motion as further inputs (judged on the deviation it predicts, prediction minus the ideal
  robot's);
- ``LPV-ARX``: deviations, input gain and offset scheduled on the ideal robot's configuration,
  speeds and drive torques (jointplay.neural.identify.lpv).

Writes identify_outputs.md under --out (default: the model folder's parent).
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

import numpy as np

from jointplay.common.files import atomic_write_text
from jointplay.neural.identify.lpv import fit_lpv_arx, scheduled_segments
from jointplay.neural.identify.lpv import window_loss as lpv_loss
from jointplay.neural.identify.pipeline import _segments, fit_arx, output_increments, read_datasets
from jointplay.neural.model.twin import window_loss, windows

WINDOW = 200


def absolute_loss(train: list, part: list, skip: int, names: dict, scale: np.ndarray,
                  nj: int) -> float:
    """ARX on absolute outputs (inputs: added torque and drive torque), judged on deviations."""
    seg = [(t.y[skip:], np.hstack([t.v, t.tau_base])[skip:]) for t in train]
    wide = {**names, "input_names": (*names["input_names"], *(f"tau{j}" for j in range(nj))),
            "input_units": (*names["input_units"], *("N m",) * nj)}
    model = fit_arx(seg, wide, 2, 2, 1e-3)
    ys = [(t.y[skip:], np.hstack([t.v, t.tau_base])[skip:]) for t in part]
    d, u, _ = windows(ys, WINDOW, model.history)
    rs = [(t.r[skip:], np.hstack([t.v, t.tau_base])[skip:]) for t in part]
    r, _, _ = windows(rs, WINDOW, model.history)
    m = model.history
    hist = [d[:, m - i] for i in range(2)]
    out = []
    with np.errstate(all="ignore"):
        for j in range(d.shape[1] - m - 1):
            k = m + j
            phi = np.concatenate(hist + [u[:, k - i] for i in range(2)], axis=1)
            nxt = model.predict(phi)
            out.append(nxt)
            hist = [nxt, *hist[:-1]]
        pred = np.stack(out, axis=1) - r[:, m + 1:]
        loss = float(np.mean(((pred - (d[:, m + 1:] - r[:, m + 1:])) / scale) ** 2))
    return loss if np.isfinite(loss) else float("inf")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--model", required=True, help="a folder written by jointplay identify")
    parser.add_argument("--out", help="folder for identify_outputs.md")
    args = parser.parse_args()
    folder = Path(args.model)
    trajectories, meta = read_datasets(folder / "datasets.h5")
    names = {k: tuple(meta[k]) for k in ("output_names", "output_units", "input_names",
                                          "input_units")}
    skip = round(meta["config"]["transient"] / meta["sample_time"])
    nj = len(names["input_names"])
    split = {s: [t for t in trajectories if t.split == s] for s in ("train", "validation",
                                                                     "test")}
    arx = fit_arx(_segments(split["train"], skip), names, 2, 2, meta["sample_time"])
    lpv = fit_lpv_arx(scheduled_segments(split["train"], skip, nj), 2, 2,
                      output_increments(names["output_names"]))
    rows = []
    for part in ("validation", "test"):
        d, u, _ = windows(_segments(split[part], skip), WINDOW, arx.history)
        rows.append((part, window_loss(arx, d, u, arx.output_scale),
                     absolute_loss(split["train"], split[part], skip, names, arx.output_scale,
                                   nj),
                     lpv_loss(lpv, scheduled_segments(split[part], skip, nj), WINDOW,
                              arx.output_scale)))
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    text = "\n".join([
        f"# Outputs and regressors of a linear model ({folder})", "",
        f"Free-run loss over {WINDOW}-sample windows (lower is better):", "",
        "| runs | ARX, deviations | ARX, absolute (+ drive torques) | LPV-ARX |",
        "|---|---|---|---|",
        *(f"| {p} | {a:.4g} | {b:.4g} | {c:.4g} |" for p, a, b, c in rows), "",
        f"`python benchmarks/identify_outputs.py --model {folder}`; load average {load}.", ""])
    out = Path(args.out) if args.out else folder.parent
    out.mkdir(parents=True, exist_ok=True)
    atomic_write_text(out / "identify_outputs.md", text)
    print(text)


if __name__ == "__main__":
    main()
