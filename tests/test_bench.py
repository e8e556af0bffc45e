"""The bench commands on a tiny case: they run, and what they write is well formed.

No timing is asserted: the numbers depend on the machine. The commands are dispatched through
:func:`jointplay.cli.bench.register` on a fresh parser, as the ``jointplay`` CLI does.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path
from types import SimpleNamespace
from typing import Any, cast

import numpy as np
import pytest

from jointplay import bench
from jointplay.cli import bench as bench_command
from jointplay.cli.args import parse_links
from jointplay.common.errors import DescriptionError
from jointplay.scene.definition import default_scene

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def run_bench(*argv: str) -> int:
    parser = argparse.ArgumentParser(prog="jointplay")
    sub = parser.add_subparsers(dest="command", required=True)
    bench_command.register(sub)
    args = parser.parse_args(["bench", *argv])
    return int(args.func(args))


def read_csv(path: Path) -> tuple[list[str], list[dict[str, str]]]:
    with open(path, newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        rows = list(reader)
        return list(reader.fieldnames or []), rows


def assert_png(path: Path) -> None:
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE, f"{path} is not a PNG"
    assert len(data) > 1000


def assert_markdown_table(path: Path, header: str, rows: int) -> None:
    lines = path.read_text(encoding="utf-8").splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(f"| {header} |"))
    assert set(lines[start + 1]) <= set("|-:")
    body = [line for line in lines[start + 2:start + 2 + rows]]
    assert len(body) == rows and all(line.startswith("| ") for line in body)


def test_work_precision_quick(tmp_path: Path) -> None:
    out = tmp_path / "wp"  # created by the command
    assert run_bench("work-precision", "--quick", "--out", str(out), "--quiet",
                     "--steps", "1e-5") == 0
    header, rows = read_csv(out / "work_precision.csv")
    assert header == bench.WP_CSV_KEYS
    # bdf, cvodes and idas at two tolerances, rk4 and radau at one step, then the scene's
    # settings
    assert [(r["config"], r["method"], r["rtol"] or r["step"]) for r in rows[:-1]] == [
        ("sweep", "bdf", "0.0001"), ("sweep", "bdf", "1e-06"),
        ("sweep", "cvodes", "0.0001"), ("sweep", "cvodes", "1e-06"),
        ("sweep", "idas", "0.0001"), ("sweep", "idas", "1e-06"),
        ("sweep", "rk4", "1e-05"), ("sweep", "radau", "1e-05")]
    assert rows[-1]["config"] == "scene settings"
    assert rows[-1]["method"] == default_scene().run.integrator
    for r in rows:
        assert r["repeats"] == ("1" if r["status"] == "ok" else "0")
        if r["status"] == "ok":
            for key in (*bench.ERROR_KEYS, "cpu_median_s", "cpu_min_s", "cpu_max_s"):
                assert np.isfinite(float(r[key])), (r["method"], key)
            assert float(r["cpu_min_s"]) <= float(r["cpu_median_s"]) <= float(r["cpu_max_s"])
            assert int(r["steps"]) > 0 and int(r["rhs_evaluations"]) > 0
        else:
            assert r["failure"]
    assert any(r["status"] == "ok" for r in rows)
    assert_png(out / "work_precision.png")
    assert_markdown_table(out / "work_precision.md", "method", len(rows))
    text = (out / "work_precision.md").read_text(encoding="utf-8")
    assert "reference agreement" in text and "idas rtol=1e-10" in text
    assert "compile" in text and "the scene's own settings" in text


@pytest.mark.slow
def test_fidelity_quick_with_missing_surrogate_module(tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str],
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, bench.SURROGATE_MODULE, None)  # import fails
    surrogate = tmp_path / "trained"
    surrogate.mkdir()
    out = tmp_path / "fid"
    assert run_bench("fidelity", "--quick", "--out", str(out), "--quiet",
                     "--surrogate", str(surrogate)) == 0
    header, rows = read_csv(out / "fidelity.csv")
    assert header == bench.FID_CSV_KEYS
    assert [(r["rung"], r["tolerance"]) for r in rows] == [
        ("ideal joints", "scene"), ("ideal joints", "reference"),
        ("clearance, no friction", "scene"), ("clearance, no friction", "reference"),
        ("clearance + friction (full)", "scene"), ("clearance + friction (full)", "reference"),
        ("neural surrogate", "")]
    full_ref = rows[5]
    assert full_ref["status"] == "ok" and float(full_ref["err_position"]) == 0.0
    assert all(r["status"] == "ok" for r in rows[:6])
    # Ideal joints leave out the play: the tip differs from the full model's.
    assert float(rows[1]["err_position"]) > 0
    surrogate_row = rows[6]
    assert surrogate_row["status"] == "skipped"
    assert "jointplay.neural.model.narx" in surrogate_row["note"]
    assert "not importable" in surrogate_row["note"]
    assert "not importable" in capsys.readouterr().err
    assert_png(out / "fidelity.png")
    assert_markdown_table(out / "fidelity.md", "model", len(rows))


def test_fidelity_surrogate_hook(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Skipped without a model; with one, the module's loader is called and its rollout of
    the scene is scored like every other row."""
    from jointplay.scene.definition import ideal_counterpart
    from jointplay.sim import load_scene_model, simulate

    row = bench.surrogate_row(cast(Any, None), None, cast(Any, None))
    assert row["status"] == "skipped" and "--surrogate" in row["note"]

    scene = default_scene().with_run(t_end=0.005)
    reference = simulate(scene, model=load_scene_model(scene))
    ideal_scene = scene.with_robot(ideal_counterpart(scene.robot))
    loaded: list[Path] = []

    class Surrogate:  # stands in for a trained model: the ideal-joint robot
        def rollout(self, s: Any) -> Any:
            assert s is scene
            return simulate(ideal_scene, model=load_scene_model(scene, ideal=True))

    def load_surrogate(path: Path) -> Surrogate:
        loaded.append(path)
        return Surrogate()

    monkeypatch.setitem(sys.modules, bench.SURROGATE_MODULE,
                        SimpleNamespace(load_surrogate=load_surrogate))
    row = bench.surrogate_row(scene, tmp_path, reference, repeats=1)
    assert loaded == [tmp_path]
    assert row["status"] == "ok" and row["repeats"] == 1
    assert row["err_position"] > 0 and np.isfinite(row["cpu_median_s"])

    monkeypatch.setitem(sys.modules, bench.SURROGATE_MODULE, SimpleNamespace())
    row = bench.surrogate_row(scene, tmp_path, reference)
    assert row["status"] == "skipped" and bench.SURROGATE_ENTRY in row["note"]


@pytest.mark.slow
def test_scaling_tiny(tmp_path: Path) -> None:
    out = tmp_path / "scaling"
    assert run_bench("scaling", "--links", "1", "--sim-time", "0.005", "--repeats", "1",
                     "--out", str(out), "--quiet") == 0
    header, rows = read_csv(out / "scaling.csv")
    assert header == bench.SCALING_CSV_KEYS
    assert [(r["structure"], r["k"]) for r in rows] == [("clearance", "1"), ("ideal", "1")]
    for r in rows:
        assert not r["error"], r["error"]
        assert r["n_coords"] == ("3" if r["structure"] == "clearance" else "1")
        for key in ("derive_s", "emit_s", "compile_s", "build_s", "cost_per_sim_s"):
            assert float(r[key]) > 0, key
    assert_png(out / "scaling.png")
    assert_markdown_table(out / "scaling.md", "structure", len(rows))


@pytest.mark.parametrize(("argv", "flag"), [
    (["work-precision", "--t-end", "-1"], "--t-end"),
    (["work-precision", "--steps", "3e-5"], "--steps"),
    (["work-precision", "--rtols", "1e-3,abc"], "--rtols"),
    (["work-precision", "--methods", "euler"], "--methods"),
    (["work-precision", "--repeats", "0"], "--repeats"),
    (["fidelity", "--rtol", "2"], "--rtol"),
    (["fidelity", "--stiffness", "hertzian"], "--stiffness"),
    (["work-precision", "--stiffness", "liu,liu"], "--stiffness"),
    (["work-precision", "--stiffness", ","], "--stiffness"),
    (["scaling", "--links", "0-3"], "--links"),
    (["scaling", "--links", "40"], "--links"),
    (["scaling", "--structures", "rigid"], "--structures"),
    (["scaling", "--sim-time", "0.0005"], "--sim-time"),
])
def test_bad_arguments_name_the_flag(tmp_path: Path, argv: list[str], flag: str) -> None:
    out = tmp_path / "never"
    with pytest.raises(DescriptionError) as info:
        run_bench(*argv, "--out", str(out))
    assert info.value.field == flag
    assert not out.exists()  # validated before anything is written


@pytest.mark.slow
def test_work_precision_and_fidelity_rows_per_stiffness_law(tmp_path: Path) -> None:
    """--stiffness: a work-precision per law (own folder) with every row in one table, and
    a fidelity rung per law other than the scene's, each with a finite, non-zero error
    against the scene's full model."""
    out = tmp_path / "wp"
    assert run_bench("work-precision", "--quick", "--methods", "bdf", "--out", str(out),
                     "--quiet", "--stiffness", "hertz,liu") == 0
    header, rows = read_csv(out / "work_precision_laws.csv")
    assert header == bench.WP_CSV_KEYS
    assert [r["stiffness"] for r in rows] == ["hertz"] * 3 + ["liu"] * 3
    assert all(r["status"] == "ok" for r in rows)
    for law in ("hertz", "liu"):
        assert read_csv(out / law / "work_precision.csv")[1][0]["stiffness"] == law
        assert_png(out / law / "work_precision.png")
    assert_markdown_table(out / "work_precision_laws.md", "stiffness", len(rows))
    out = tmp_path / "fid"
    assert run_bench("fidelity", "--quick", "--out", str(out), "--quiet",
                     "--stiffness", "hertz,pereira") == 0
    rows = read_csv(out / "fidelity.csv")[1]
    law_rows = [r for r in rows if r["rung"] == "clearance + friction, pereira stiffness"]
    assert [r["tolerance"] for r in law_rows] == ["scene", "reference"]
    assert rows[-3]["rung"] == "clearance + friction (full)"  # still the reference rung
    for r in law_rows:
        assert r["status"] == "ok" and 0 < float(r["err_position"]) < 1e-3


def test_effect_scenes_switch_one_effect_on() -> None:
    """The quick tier's part of --effects (the rows themselves run in the slow tier): each
    effect's scene is the scene's robot with that effect alone, an axial length given to the
    clearance joints that have none, and a model name of its own."""
    from jointplay.bench.effects import DEFAULT_LENGTH, effect_label, effect_scene

    scene = default_scene()
    wet, worn = effect_scene(scene, "lubrication"), effect_scene(scene, "wear")
    assert (wet.robot.lubrication.model, wet.robot.wear.model) == ("short-bearing", "none")
    assert (worn.robot.lubrication.model, worn.robot.wear.model) == ("none", "archard")
    for robot in (wet.robot, worn.robot):
        assert [j.length for j in robot.joints] == [
            DEFAULT_LENGTH if j.has_clearance else None for j in scene.robot.joints]
    assert (wet.robot.name, worn.robot.name) == ("paper_4dof_lubrication", "paper_4dof_wear")
    assert effect_label(scene, "lubrication") == "+ lubrication (short-bearing, 0.04 Pa s)"
    assert effect_label(scene, "wear") == "+ Archard wear (k 0.0001, H 2e+09 Pa)"


@pytest.mark.slow
def test_effect_rows_in_both_benches(tmp_path: Path) -> None:
    """--effects: the lubricated and the worn arm get rows of their own in work-precision and
    fidelity, each run to the end with a finite error."""
    out = tmp_path / "wp"
    assert run_bench("work-precision", "--quick", "--methods", "bdf", "--out", str(out),
                     "--quiet", "--effects") == 0
    rows = read_csv(out / "work_precision.csv")[1]
    assert len(rows) > 3 and all(r["status"] == "ok" for r in rows)
    out = tmp_path / "fid"
    assert run_bench("fidelity", "--quick", "--out", str(out), "--quiet", "--effects") == 0
    rows = read_csv(out / "fidelity.csv")[1]
    effect_rows = [r for r in rows if "lubricat" in r["rung"] or "wear" in r["rung"]]
    assert len(effect_rows) >= 2, [r["rung"] for r in rows]
    for r in effect_rows:
        assert r["status"] == "ok" and math.isfinite(float(r["err_position"]))


def test_out_must_be_a_writable_folder(tmp_path: Path) -> None:
    a_file = tmp_path / "file.txt"
    a_file.write_text("x")
    with pytest.raises(DescriptionError) as info:
        run_bench("work-precision", "--quick", "--out", str(a_file))
    assert info.value.field == "--out"
    with pytest.raises(DescriptionError) as info:
        run_bench("fidelity", "--quick", "--out", str(tmp_path), "--surrogate",
                  str(tmp_path / "missing"))
    assert info.value.field == "--surrogate"


def test_links_parsing() -> None:
    assert parse_links("1-3,6") == [1, 2, 3, 6]
    assert parse_links(" 4, 2 ") == [2, 4]


def test_moved_names_still_resolve_with_a_warning() -> None:
    import jointplay.sweep
    from jointplay.cli import sweep as sweep_command

    with pytest.warns(DeprecationWarning, match="jointplay.cli.args.parse_links"):
        assert bench.parse_links is parse_links
    with pytest.warns(DeprecationWarning, match="jointplay.cli.bench.register"):
        assert bench.register is bench_command.register
    with pytest.warns(DeprecationWarning, match="jointplay.cli.sweep.cmd_sweep"):
        assert jointplay.sweep.cmd_sweep is sweep_command.cmd_sweep
    with pytest.raises(AttributeError):
        _ = bench.no_such_name


def test_error_measures() -> None:
    """Tip errors are maxima of the Euclidean norm; the final state is scaled per entry."""
    t = np.linspace(0.0, 1.0, 5)
    ref = SimpleNamespace(
        t=t, tip_position=np.zeros((5, 2)), tip_velocity=np.zeros((5, 2)),
        tip_acceleration=np.zeros((5, 2)), coordinate_names=["q2", "ex2", "ey2"],
        q=np.zeros((5, 3)), u=np.zeros((5, 3)), clearance_joints=[2],
        radial_clearance=np.array([3e-5]))
    moved = SimpleNamespace(**vars(ref))
    moved.tip_position = ref.tip_position.copy()
    moved.tip_position[2] = [3e-3, 4e-3]
    moved.q = ref.q.copy()
    moved.q[-1] = [1e-3, 1.5e-5, 0.0]  # half a clearance off in ex
    moved.u = ref.u.copy()
    moved.u[-1] = [0.0, 0.0, 3e-3]  # 0.1 clearance per ms in dey
    errors = bench.all_errors(cast(Any, moved), cast(Any, ref))
    assert errors["err_position"] == pytest.approx(5e-3)
    assert errors["err_velocity"] == 0.0
    assert errors["err_final_state"] == pytest.approx(0.5)
    with pytest.raises(ValueError, match="output times"):
        bench.tip_errors(cast(Any, SimpleNamespace(**{**vars(ref), "t": t[:3]})), cast(Any, ref))


def test_atols_pair_with_every_rtol_and_the_cheapest_working_setting_is_named() -> None:
    from jointplay.bench.work_precision import cheapest_meeting_working_accuracy

    scene = default_scene()
    configs = bench.sweep_configurations(scene, ["bdf", "rk4"], [1e-5, 1e-6], [1e-5],
                                   atols=[1e-6, 1e-7])
    assert [(c.run.integrator, c.run.rtol, c.run.atol) for c in configs[:4]] == [
        ("bdf", 1e-5, 1e-6), ("bdf", 1e-5, 1e-7), ("bdf", 1e-6, 1e-6), ("bdf", 1e-6, 1e-7)]
    assert configs[4].run.integrator == "rk4" and len(configs) == 5
    rows = [{"working_accuracy": "yes", "cpu_median_s": 0.05, "name": "slow", "config": "sweep"},
            {"working_accuracy": "no", "cpu_median_s": 0.01, "name": "inaccurate",
             "config": "sweep"},
            {"working_accuracy": "yes", "cpu_median_s": 0.03, "name": "cheapest",
             "config": "scene settings"},
            {"working_accuracy": "yes", "cpu_median_s": 0.001, "name": "another model",
             "config": "lubrication: sweep"}]
    best = cheapest_meeting_working_accuracy(rows)
    assert best is not None and best["name"] == "cheapest"
    assert cheapest_meeting_working_accuracy(rows[1:2]) is None
    assert cheapest_meeting_working_accuracy(rows[3:]) is None  # an effect's rows: not the scene
