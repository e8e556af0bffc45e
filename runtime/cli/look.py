"""``jointplay plot`` and ``jointplay compare``: results files looked at again, no Python."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.cli.args import check_writable_dir
from jointplay.common.errors import DescriptionError
from jointplay.common.files import all_or_nothing, make_folder

if TYPE_CHECKING:
    from jointplay.common.files import OutputPlan
    from jointplay.results.records import SimulationResult


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
    _replay_flag(p_plot)
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
    _replay_flag(p_cmp)
    p_cmp.set_defaults(func=cmd_compare)


def _replay_flag(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--no-replay", action="store_true",
                        help="draw orbits by cubic Hermite between the file's samples; by "
                             "default the run's scene is run again for its dense output "
                             "(used only if it reproduces the file's samples)")


def _dense_output(result: SimulationResult, label: str, skip: bool) -> None:
    """Give a result read from a file its dense output back (see jointplay.sim.dense.replay)
    and say where its orbits come from."""
    if not result.clearance_joints:
        return
    if skip:
        print(f"{label}: orbits by cubic Hermite between the samples (--no-replay)")
        return
    from jointplay.sim.dense import replay

    solution, how = replay(result)
    if solution is not None:
        result.with_dense_output(solution)
        print(f"{label}: orbits from the {how}")
    else:
        print(f"{label}: orbits by cubic Hermite between the samples: {how}")


def _check_out(folder: str, runs: list[str]) -> tuple[Path, OutputPlan]:
    """The figure folder and the command's output plan: the figures (``*.png`` in ``--out``)
    against the results files read, refused before any work when they coincide (exit 2)."""
    from jointplay.common.files import OutputPlan

    plan = OutputPlan()
    plan.add_inputs("RUN.h5", runs)
    plan.folder("--out", folder, "its figures", pattern="*.png")
    plan.check()
    path = Path(folder)
    check_writable_dir(path, "--out")
    return path, plan


def _read(path: str, argument: str, label: str) -> SimulationResult:
    """The results file, checked; a file written before checksums existed says so once."""
    from jointplay.results.look import UNCHECKED_NOTE, read_result_checked

    result, checked = read_result_checked(path, argument)
    if not checked:
        print(f"{label}: {UNCHECKED_NOTE}")
    return result


def cmd_plot(args: argparse.Namespace) -> int:
    from jointplay.mechanism.results import is_mechanism_result
    from jointplay.results.plots import plot_result

    folder, plan = _check_out(args.out, [args.run])
    if is_mechanism_result(args.run):
        from jointplay.mechanism.plots import write_figures
        from jointplay.mechanism.results import read_mechanism_result

        mechanism = read_mechanism_result(args.run)
        with all_or_nothing(plan):
            make_folder(folder, "--out")
            paths = write_figures(mechanism, folder)
        for path in paths:
            print(f"wrote {path}")
        return 0
    result = _read(args.run, "RUN.h5", Path(args.run).name)
    _dense_output(result, Path(args.run).name, args.no_replay)
    with all_or_nothing(plan):  # every figure or none
        make_folder(folder, "--out")
        paths = plot_result(result, folder)
    for path in paths:
        print(f"wrote {path}")
    return 0


def _compare_mechanisms(args: argparse.Namespace, folder: Path, plan: OutputPlan) -> int:
    from jointplay.mechanism.compare import check_comparable, compare_figures, difference_table
    from jointplay.mechanism.results import read_mechanism_result
    from jointplay.results.look import labelled

    runs = labelled(args.runs, [read_mechanism_result(p, f"RUN.h5 #{i + 1}")
                                for i, p in enumerate(args.runs)])
    check_comparable(runs)
    with all_or_nothing(plan):
        make_folder(folder, "--out")
        paths = compare_figures(runs, folder)
    print(difference_table(runs))
    for path in paths:
        print(f"wrote {path}")
    return 0


def cmd_compare(args: argparse.Namespace) -> int:
    from jointplay.results.look import compare_runs, difference_table, differences, labelled

    if len(args.runs) < 2:
        raise DescriptionError("RUN.h5", "compare needs two or more results files; for one "
                               "run use `jointplay plot RUN.h5 --out DIR`")
    folder, plan = _check_out(args.out, args.runs)
    from jointplay.mechanism.results import is_mechanism_result

    kinds = {is_mechanism_result(p) for p in args.runs}
    if kinds == {True}:
        return _compare_mechanisms(args, folder, plan)
    if len(kinds) > 1:
        raise DescriptionError("RUN.h5", "compare takes runs of one kind: mechanism results "
                               "files or arms' results files, not both")
    runs = labelled(args.runs, [_read(p, f"RUN.h5 #{i + 1}", p)
                                for i, p in enumerate(args.runs)])
    for label, result in runs:
        _dense_output(result, label, args.no_replay)
    with all_or_nothing(plan):  # every figure or none
        make_folder(folder, "--out")
        paths = compare_runs(runs, folder)
    print(difference_table(differences(runs)))
    for path in paths:
        print(f"wrote {path}")
    return 0
