"""The calibration benchmark's cases (benchmarks/calibration_cases/): stored data, generator,
independence of the reference simulator, and its agreement with ``jointplay simulate``.

1. Every stored case is whole and current: truth.csv matches the hash in case.json, the hash
   of the inputs (reference, robot file, case definition) is the current one, the truth and
   scene file are what the definition gives.
2. The generator imports nothing of jointplay.
3. The stored motion (made by the reference at the truth) agrees with ``jointplay simulate``
   at the truth, its tolerances tightened 1e4, over each case's whole record: tip within
   1e-7 m and joint angles within 1e-6 rad. Measured: at most 1.5e-8 m and 3.1e-8 rad on
   every case but the fast excitation's, and 4.1e-8 m and 5.1e-7 rad on that one (reference
   at rtol 1e-9 there), where jointplay's own motion changes by 1.6e-8 m and 1.9e-7 rad when
   its tolerances are tightened 10x further (benchmarks/calibration_cases/README.md). The
   benchmark's noise is 1 µm and 5 µrad.
4. A regeneration reproduces a stored case to 1e-9 (slow).
5. The runner adds seeded noise of the stated size and reads a calibration's files.
"""

from __future__ import annotations

import hashlib
import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp

CASES_DIR = Path(__file__).resolve().parents[1] / "benchmarks" / "calibration_cases"
sys.path.insert(0, str(CASES_DIR))

import cases as case_definitions  # noqa: E402
import generate  # noqa: E402
import runner  # noqa: E402

TIP_TOLERANCE = 1e-7  # m
ANGLE_TOLERANCE = 1e-6  # rad
# The cases on the paper arm run in the quick tier; the other robots need a build of their own.
PAPER_CASES = [c.name for c in case_definitions.CASES
               if c.robot_file == case_definitions.PAPER_ROBOT]
OTHER_CASES = [c.name for c in case_definitions.CASES
               if c.robot_file != case_definitions.PAPER_ROBOT]


def test_at_least_eight_cases_of_every_kind() -> None:
    all_cases = case_definitions.CASES
    assert len(all_cases) >= 8
    excitations = {repr(sorted(c.torques.items())) for c in all_cases
                   if c.robot_file == case_definitions.PAPER_ROBOT}
    assert len(excitations) >= 4  # the default and at least three others
    columns = {c.columns for c in all_cases}
    assert ("tip_x", "tip_y") in columns and ("q2", "q3") in columns
    assert any("tip_x" in c and "q2" in c for c in columns)
    assert {c.noise_stated for c in all_cases} == {True, False}
    assert len({c.robot_file for c in all_cases}) >= 3
    for case in all_cases:
        nominal = case_definitions.catalogue_values(case.robot_table(), case.free)
        for name, value in case.true_values().items():
            assert 0.5 * nominal[name] <= value <= 1.5 * nominal[name], (case.name, name)


@pytest.mark.parametrize("case", case_definitions.CASES, ids=lambda c: c.name)
def test_stored_case_is_whole_and_current(case: case_definitions.Case) -> None:
    folder = case_definitions.DATA / case.name
    record = json.loads((folder / "case.json").read_text())
    text = (folder / "truth.csv").read_text()
    assert hashlib.sha256(text.encode()).hexdigest() == record["truth_csv_sha256"]
    assert record["input_sha256"] == generate.input_hash(case), \
        "the case's inputs changed: rerun python benchmarks/calibration_cases/generate.py"
    assert record["truth"] == case.true_values()
    assert record["free"] == list(case.free) and record["columns"] == list(case.columns)
    assert (folder / "scene.toml").read_text() == case.scene_text(folder)
    table = np.loadtxt(folder / "truth.csv", delimiter=",", skiprows=1, ndmin=2)
    samples = round(case.t_end / case.output_step) + 1
    assert table.shape == (samples, 1 + len(case.columns))
    assert np.all(np.isfinite(table))


def test_generator_imports_no_jointplay() -> None:
    code = ("import sys; sys.path.insert(0, sys.argv[1]); import generate, reference, cases; "
            "bad = sorted(m for m in sys.modules if m.split('.')[0] == 'jointplay'); "
            "print(bad); sys.exit(1 if bad else 0)")
    done = subprocess.run([sys.executable, "-c", code, str(CASES_DIR)], capture_output=True,
                          text=True, check=False)
    assert done.returncode == 0, done.stdout + done.stderr


def _compare_with_jointplay(name: str) -> None:
    case = next(c for c in case_definitions.CASES if c.name == name)
    folder = case_definitions.DATA / name
    record, table, header = runner.load_case(name)
    scene = jp.load_scene(folder / "scene.toml")
    scene = scene.with_run(rtol=scene.run.rtol / 1e4, atol=scene.run.atol / 1e4)
    result = jp.simulate(scene, parameters=record["truth"])
    assert np.allclose(result.t, table[:, 0], rtol=0, atol=1e-12)
    for k, column in enumerate(header[1:], start=1):
        if column in ("tip_x", "tip_y"):
            theirs = result.tip_position[:, ("tip_x", "tip_y").index(column)]
            tolerance = TIP_TOLERANCE
        else:
            theirs = result.q[:, result.coordinate_names.index(column)]
            tolerance = ANGLE_TOLERANCE
        error = float(np.max(np.abs(table[:, k] - theirs)))
        assert error <= tolerance, f"{case.name} {column}: {error:.3g} > {tolerance:g}"


@pytest.mark.parametrize("name", PAPER_CASES)
def test_reference_agrees_with_jointplay_on_the_paper_arm(name: str) -> None:
    _compare_with_jointplay(name)


@pytest.mark.slow
@pytest.mark.parametrize("name", OTHER_CASES)
def test_reference_agrees_with_jointplay_on_other_robots(name: str) -> None:
    _compare_with_jointplay(name)


@pytest.mark.slow
def test_regeneration_reproduces_a_stored_case(tmp_path: Path) -> None:
    case = next(c for c in case_definitions.CASES if c.name == "paper-default-tip")
    generate.generate(case, root=tmp_path)
    fresh = np.loadtxt(tmp_path / case.name / "truth.csv", delimiter=",", skiprows=1)
    stored = np.loadtxt(case_definitions.DATA / case.name / "truth.csv", delimiter=",",
                        skiprows=1)
    # Same code and inputs: equal up to the C compiler's rounding, far below the noise.
    assert np.max(np.abs(fresh - stored)) <= 1e-9


def test_runner_noise_is_seeded_and_of_the_stated_size(tmp_path: Path) -> None:
    record, table, header = runner.load_case("paper-exchange-trap")
    paths = [tmp_path / f"{k}.csv" for k in range(3)]
    for path, seed in zip(paths, (0, 0, 1), strict=True):
        runner.noisy_csv(record, table, header, seed, path)
    a, b, c = (np.loadtxt(p, delimiter=",", skiprows=1) for p in paths)
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    for k, column in enumerate(header[1:], start=1):
        noise = a[:, k] - table[:, k]
        # 2001 samples: the sample std is within 10 % of the truth (5 sigma).
        assert abs(np.std(noise) / record["noise"][column] - 1) < 0.1
    assert np.array_equal(a[:, 0], table[:, 0])


def test_summary_counts_coverage_verdicts_and_goals() -> None:
    def param(error_pct: float, covered: bool, determined: bool) -> dict[str, object]:
        return {"error_pct": error_pct, "covered": covered, "determined": determined}

    rows = [
        {"case": "a", "status": "ok", "wall_s": 10.0, "cpu_s": 5.0, "parameters": {
            "joint2.clearance": param(1.5, True, True),     # goal met
            "joint3.clearance": param(-2.5, False, True),   # determined, outside, goal missed
            "friction.mu": param(4.0, True, False)}},       # not determined: no goal
        {"case": "b", "status": "exit 2", "wall_s": 30.0, "cpu_s": 1.0, "parameters": {}},
        {"case": "a", "status": "ok", "wall_s": 20.0, "cpu_s": 7.0, "parameters": {
            "friction.mu": param(-4.9, True, True)}},       # goal met
    ]
    s = runner.summarise(rows)
    assert (s["runs"], s["failed"], s["intervals"], s["covered"]) == (3, 1, 4, 3)
    assert (s["determined"], s["determined_outside"]) == (3, 1)
    assert (s["goals_checked"], s["goals_met"]) == (3, 2)
    assert (s["wall_median_s"], s["wall_worst_s"]) == (20.0, 30.0)
    assert s["wall_by_case"] == {"a": (15.0, 20.0), "b": (30.0, 30.0)}


def test_the_case_table_states_the_walls_in_machine_references() -> None:
    """Each run's wall over the machine reference measured before it (by which runs on other
    machines or hours compare), median and worst; a dash where a run has none."""
    rows = [{"case": "a", "seed": k, "status": "ok", "wall_s": wall, "cpu_s": 50.0,
             "noise_stated": True, "parameters": {}, "reference_s": ref}
            for k, (wall, ref) in enumerate([(30.0, 0.15), (45.0, 0.1), (20.0, 0.2)])]
    summary = runner.summarise(rows)
    assert summary["references"] == (200.0, 450.0, 0.15)
    assert "median 0.150 s), median / worst: 200 / 450" in runner.markdown(rows, summary, "")
    del rows[1]["reference_s"]
    assert runner.summarise(rows)["references"] is None
    assert "in machine references: - (not measured)" in runner.markdown(
        rows, runner.summarise(rows), "")


def test_a_failing_machine_reference_stops_with_the_childs_error(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """A reference run that fails (here: its code raises) stops the benchmark with one line
    naming the child's error, not a number read from nothing."""
    monkeypatch.setattr(runner, "REFERENCE_CODE", "raise ImportError('no jointplay here')")
    with pytest.raises(RuntimeError, match=r"exit status 1: ImportError: no jointplay here"):
        runner.machine_reference()
    monkeypatch.setattr(runner, "REFERENCE_CODE", "print('0.125')")
    assert runner.machine_reference() == 0.125


def test_the_stage_benchmark_removes_each_stage_and_puts_it_back() -> None:
    """benchmarks/calibration_stages.py: inside each removal the search's function is
    replaced (or an option turns the stage off), outside it the original is back; the
    later-lines removal keeps the first window's lines and drops the later ones; the summary
    counts and lists what moved against the full search."""
    sys.path.insert(0, str(CASES_DIR.parent))
    import calibration_stages as stages

    from jointplay.calibration import api, basins, continuation

    places = [(continuation, "_line_minima"), (basins, "_line_points"),
              (basins, "_other_centres"), (api, "others_first")]
    originals = [getattr(m, n) for m, n in places]
    for name, (remove, options) in stages.STAGES.items():
        with remove():
            replaced = [getattr(m, n) is not f for (m, n), f in zip(places, originals,
                                                                    strict=True)]
        assert any(replaced) != bool(options), name  # a replacement or an option, not both
        assert all(getattr(m, n) is f for (m, n), f in zip(places, originals, strict=True))

    class Part:
        def __init__(self, end: float) -> None:
            self.t = np.array([0.0, end])

    calls = []
    first = stages.CalibrationOptions().valley_window
    with stages._replaced(continuation, "_line_minima",
                          lambda *args: calls.append(args[2].t[-1]) or ([1], 7)), \
            stages._without_later_lines():
        assert continuation._line_minima(None, None, Part(first)) == ([1], 7)
        assert continuation._line_minima(None, None, Part(2 * first)) == ([], 0)
    assert calls == [first]

    def row(stage: str, error: float, determined: bool) -> dict[str, object]:
        return {"stage": stage, "case": "a", "seed": 0, "runs": 10, "wall_s": 1.0,
                "parameters": {"friction.mu": {"error_pct": error, "covered": True,
                                               "determined": determined}}}

    text = stages.markdown([row("full", 0.01, True), row("basin-lines", 0.30, False),
                            row("later-lines", 0.02, True)], "cmd")
    assert "| basin-lines | 1 of 1 | 0 | 0 | 10 | 1.0 |" in text
    assert "- **basin-lines**: a seed 0 friction.mu: +0.01 % (in, det.) → +0.30 % (in, " \
        "not det.)" in text
    assert "- **later-lines**: no change" in text


def test_the_time_benchmark_counts_the_runs_of_tracks_it_then_dropped() -> None:
    """benchmarks/calibration_time.py: per window (not the whole record's stage), its tracks,
    evaluations and runs, and the runs of the tracks whose chi² ended more than the
    continuation's margin (TRACK_MARGIN at this many degrees of freedom) above the best."""
    sys.path.insert(0, str(CASES_DIR.parent))
    import calibration_time

    from jointplay.calibration.continuation import Stage

    def stage(end: float, chi2: float, runs: int) -> Stage:
        return Stage(end, 100, (0.0,), (0.0,), chi2, 1000, runs - 1, runs, "")

    rows = calibration_time._windows([stage(0.32, 1000.0, 10), stage(0.32, 1049.0, 20),
                                      stage(0.32, 1051.0, 30), stage(0.64, 900.0, 5),
                                      stage(1.5, 2000.0, 3)])
    assert rows == ["| 0.32 | 3 | 57 | 60 | 30 (50%) |", "| 0.64 | 1 | 4 | 5 | 0 (0%) |"]


def test_code_size_counts_code_not_comments_docstrings_or_blanks() -> None:
    """benchmarks/code_size.py: a wrapped statement counts each line; a docstring, a string
    standing as a statement, a comment and a blank line count none."""
    sys.path.insert(0, str(CASES_DIR.parent))
    import code_size

    source = ('"""Module.\n\nMore."""\n\n# a comment\nX = 1  # counted\n"""X\'s doc."""\n\n'
              'def f(a: int,\n      b: int) -> int:\n    """Doc."""\n    return a + b\n')
    assert code_size.code_lines(source) == 4
    files = code_size.sources("runtime/calibration", None)
    assert "runtime/calibration/api.py" in files and all(f.endswith(".py") for f in files)


@pytest.mark.slow
def test_the_time_benchmark_runs_a_case(tmp_path: Path) -> None:
    """The whole script on the quickest case: a table of stages whose wall seconds add up to
    no more than the wall time it states, each with its CPU seconds (the workers' included)."""
    out = tmp_path / "time.md"
    proc = subprocess.run([sys.executable, str(CASES_DIR.parent / "calibration_time.py"),
                           "--case", "paper-one-clearance", "--out", str(out)],
                          capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr
    text = out.read_text()
    wall = float(text.split(" s wall")[0].rsplit("\n", 1)[-1])
    table = text.split("| stage | wall s | share | CPU s | CPU / wall |")[1].split("\n\n")[0]
    rows = [line.split("|") for line in table.splitlines()[2:]]
    stages = [float(row[2]) for row in rows]
    assert stages and sum(stages) <= wall * 1.001
    assert all(float(row[4]) >= 0 for row in rows)
    assert "| grid |" in text and "whole-record fit" in text


def test_the_run_options_benchmark_checks_each_pair(
        capsys: pytest.CaptureFixture[str]) -> None:
    """benchmarks/run_options_cost.py on short runs: a row per scene, tolerance and sensitivity
    count, each pair with and without peaks the same to the bit; its check tells a run whose
    motion differs in one number. With ``--option newton`` each row gives both runs' steps and
    their largest tip difference."""
    import dataclasses

    sys.path.insert(0, str(CASES_DIR.parent))
    import run_options_cost

    def rows(option: str) -> list[str]:
        assert run_options_cost.main(["--option", option, "--repeats", "1",
                                      "--t-end", "0.02"]) == 0
        return [line for line in capsys.readouterr().out.splitlines()
                if line.startswith("| paper |") or line.startswith("| three-link |")]

    peaks = rows("peaks")
    assert len(peaks) == 8 and all(row.endswith("| yes |") for row in peaks), peaks
    newton = rows("newton")
    assert len(newton) == 8 and all(re.search(r"\| \d+, \d+; \d\.\de[-+]\d+ m \|$", row)
                                    for row in newton), newton
    run = jp.simulate(jp.default_scene().with_run(t_end=0.005), peaks=False)
    moved = run.q.copy()
    moved[-1, 0] = np.nextafter(moved[-1, 0], np.inf)
    assert run_options_cost._same(run, run)
    assert not run_options_cost._same(run, dataclasses.replace(run, q=moved))
