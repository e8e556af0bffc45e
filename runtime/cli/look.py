"""``jointplay plot`` and ``jointplay compare``: results files looked at again, no Python."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from jointplay.cli.args import check_writable_dir
from jointplay.common.errors import DescriptionError


def register(subparsers: Any) -> None:
    p_plot = subparsers.add_parser(
        "plot", help="draw every figure a results file's effects call for",
        description="Draw every figure the run's effects call for (end effector, energy; with "
                    "clearance: orbits, contact forces and timelines, eccentricity ratio; with "
                    "a lubricant: the film force; with wear: the worn depth) from a results "
                    "file written by `jointplay simulate --out`.")
    p_plot.add_argument("run", metavar="RUN.h5", help="results file")
    p_plot.add_argument("--out", required=True, metavar="DIR",
                        help="folder for the PNG figures (created if missing)")
    p_plot.set_defaults(func=cmd_plot)

    p_cmp = subparsers.add_parser(
        "compare", help="overlay runs and print a table of their differences",
        description="Overlay two or more runs (tip path and the distance between runs, journal "
                    "orbits, contact forces, impacts side by side, energy) and print a table "
                    "of their differences against the first: largest tip difference, impacts, "
                    "peak force, approach speed, energy.")
    p_cmp.add_argument("runs", nargs="+", metavar="RUN.h5",
                       help="results files; the first is the reference")
    p_cmp.add_argument("--out", required=True, metavar="DIR",
                       help="folder for the PNG figures (created if missing)")
    p_cmp.set_defaults(func=cmd_compare)


def _check_out(folder: str) -> Path:
    path = Path(folder)
    check_writable_dir(path, "--out")
    return path


def cmd_plot(args: argparse.Namespace) -> int:
    from jointplay.results.look import read_result
    from jointplay.results.plots import plot_result

    folder = _check_out(args.out)
    result = read_result(args.run, "RUN.h5")
    for path in plot_result(result, folder):
        print(f"wrote {path}")
    return 0


def cmd_compare(args: argparse.Namespace) -> int:
    from jointplay.results.look import (
        compare_runs,
        difference_table,
        differences,
        labelled,
        read_result,
    )

    if len(args.runs) < 2:
        raise DescriptionError("RUN.h5", "compare needs two or more results files; for one "
                               "run use `jointplay plot RUN.h5 --out DIR`")
    folder = _check_out(args.out)
    runs = labelled(args.runs, [read_result(p, f"RUN.h5 #{i + 1}")
                                for i, p in enumerate(args.runs)])
    paths = compare_runs(runs, folder)
    print(difference_table(differences(runs)))
    for path in paths:
        print(f"wrote {path}")
    return 0
