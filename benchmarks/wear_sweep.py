"""Wear against clearance and friction: runs scenes/sweep_wear.toml and plots its wear columns.

    python benchmarks/wear_sweep.py --out out/sweep_wear

The sweep's table (OUT/sweep.parquet) holds every number; this draws the worn volume and the
deepest bearing wear of joint 2 against its clearance, one line per friction coefficient, into
OUT/wear_sweep.png, and prints them.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from jointplay.sweep import load_sweep, run_sweep

SWEEP = Path(__file__).resolve().parent.parent / "scenes" / "sweep_wear.toml"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="the sweep's output folder")
    parser.add_argument("--workers", type=int, default=0,
                        help="Dask worker processes (default 0: one by one, no Dask)")
    args = parser.parse_args()
    out = Path(args.out)
    result = run_sweep(load_sweep(SWEEP), out, workers=args.workers, quiet=False)
    data = result.table.to_pydict()

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    clearance = np.asarray(data["joint2.clearance"])
    mu = np.asarray(data["friction.mu"])
    for n, value in enumerate(sorted(set(mu))):
        rows = np.flatnonzero((mu == value) & (np.asarray(data["status"]) == "ok"))
        rows = rows[np.argsort(clearance[rows])]
        for ax, column, scale, unit in (
                (axes[0], "wear_volume_joint2", 1e9, "mm^3"),
                (axes[1], "max_bearing_wear_depth_joint2", 1e9, "nm"),
                (axes[2], "max_position_error", 1e3, "mm")):
            y = np.asarray([data[column][i] for i in rows], dtype=float) * scale
            ax.plot(clearance[rows] * 1e6, y, "o-", color=f"C{n}", label=f"mu = {value:g}")
            ax.set_ylabel(unit)
            ax.set_title(column.replace("_", " "), fontsize=10)
        for i in rows:
            print(f"clearance {clearance[i] * 1e6:6.1f} um, mu {value:g}: wear volume "
                  f"{data['wear_volume_joint2'][i]:.3e} m^3, deepest bearing wear "
                  f"{data['max_bearing_wear_depth_joint2'][i]:.3e} m, impacts "
                  f"{data['impacts_joint2'][i]}, tip error {data['max_position_error'][i]:.3e} m")
    for ax in axes:
        ax.set_xscale("log")
        ax.set_xlabel("joint 2 radial clearance [um]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("paper arm, 2 s, joint 2: Archard wear (k = 1e-4, H = 2 GPa) against "
                 "clearance and friction")
    fig.tight_layout()
    fig.savefig(out / "wear_sweep.png", dpi=100)
    print(f"wrote {out / 'wear_sweep.png'}")


if __name__ == "__main__":
    main()
