"""The accuracy statement checked against a converged reference, at several tolerances.

For each rtol / atol: the default scene simulated with ``verify=True`` (the statement), and
against a converged reference (``bdf`` at rtol = atol = 1e-12, whose own error is bounded by
its distance to the run at 1e-11): the true largest tip position error beside the estimate,
and the true agreement horizon of the impact sequence beside the stated one. Writes
``accuracy_check.csv`` and ``.md`` into ``--out`` (atomically) and prints the Markdown.

    python benchmarks/accuracy_check.py --out out/bench/accuracy_check
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from jointplay import RunSettings, default_scene, load_scene_model, simulate
from jointplay.bench import machine_facts, markdown_table, to_csv
from jointplay.common.files import atomic_write_text
from jointplay.results.accuracy import agreement_horizon

SETTINGS = ((RunSettings().rtol, RunSettings().atol), (1e-6, 1e-5), (1e-6, 1e-7), (1e-8, 1e-8),
            (1e-9, 1e-9), (1e-10, 1e-10))
COLUMNS = [("rtol", "rtol", "{:.0e}"), ("atol", "atol", "{:.0e}"),
           ("true_error", "true max tip error m", "{:.2e}"),
           ("estimate", "estimate m", "{:.2e}"), ("ratio", "estimate / true", "{:.2f}"),
           ("true_horizon", "true horizon s", "{:.5g}"),
           ("horizon", "stated horizon s", "{:.5g}"),
           ("impacts", "impacts", "{}"), ("reference_impacts", "reference impacts", "{}"),
           ("energy_fraction", "energy residual / dissipated", "{:.3%}")]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="folder for the CSV and Markdown")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scene = default_scene()
    model = load_scene_model(scene)
    reference = simulate(scene.with_run(rtol=1e-12, atol=1e-12), model=model)
    near = simulate(scene.with_run(rtol=1e-11, atol=1e-11), model=model)
    bound = float(np.max(np.linalg.norm(near.tip_position - reference.tip_position, axis=1)))
    rows = []
    for rtol, atol in SETTINGS:
        run = simulate(scene.with_run(rtol=rtol, atol=atol), model=model, verify=True)
        acc = run.accuracy
        assert acc is not None
        true = float(np.max(np.linalg.norm(run.tip_position - reference.tip_position, axis=1)))
        horizon, _ = agreement_horizon(run.impacts, reference.impacts, scene.run.t_end)
        rows.append({"rtol": rtol, "atol": atol, "true_error": true,
                     "estimate": acc.tip_error_estimate, "ratio": acc.tip_error_estimate / true,
                     "true_horizon": horizon, "horizon": acc.agreement_horizon,
                     "impacts": len(run.impacts), "reference_impacts": len(reference.impacts),
                     "energy_fraction": acc.energy_residual_fraction})
    md = ["# The accuracy statement against a converged reference", "",
          "Command: `python benchmarks/accuracy_check.py --out " + args.out + "`", "",
          f"- scene: {scene.name}, {scene.run.t_end:g} s; reference: bdf rtol = atol = 1e-12, "
          f"within {bound:.2g} m of the run at 1e-11 (its error bound)",
          *(f"- {k}: {v}" for k, v in machine_facts().items()), "",
          markdown_table(rows, COLUMNS), ""]
    atomic_write_text(out / "accuracy_check.csv", to_csv(rows, [c[0] for c in COLUMNS]))
    atomic_write_text(out / "accuracy_check.md", "\n".join(md))
    print("\n".join(md))


if __name__ == "__main__":
    main()
