"""One validation behind every front door (TOML files, --set, the Python API and its
``parameters=`` overrides), physical plausibility, run-time stops for impossible states, and
the messages that name the real cause. The property-based half is tests/test_doors_property.py.
"""

from __future__ import annotations

import argparse
import math
import re
import shutil
from dataclasses import replace
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from sim_fixtures import make_scene, pin_in_bearing

from jointplay import DescriptionError, SimulationError, default_scene, load_scene, simulate
from jointplay.cli import main, make_parser
from jointplay.cli.args import add_debug_flag
from jointplay.common.errors import DescriptionErrors
from jointplay.common.limits import MAX_PENETRATION_FRACTION, PHYSICAL_RANGES
from jointplay.robot import with_parameters
from jointplay.scene.definition import scene_from_dict
from jointplay.sim.problem import _parameter_vector
from jointplay.store.lookup import model_for

SCENES = Path(__file__).resolve().parent.parent / "scenes"


def fields(err: DescriptionError) -> set[str]:
    return {p.field for p in err.problems}


def scene_text(**replacements: str) -> str:
    text = (SCENES / "paper_4dof.toml").read_text(encoding="utf-8")
    for old, new in replacements.items():
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


# ---- one validation, two front doors -----------------------------------------------------------

def test_replace_initial_is_validated_as_toml_is(tmp_path: Path) -> None:
    scene = default_scene()
    with pytest.raises(DescriptionError, match=r"initial\.q9: unknown key"):
        replace(scene, initial={"q9": 1.0})
    with pytest.raises(DescriptionError, match=r"initial\.qq3: unknown key.*did you mean 'q3'"):
        replace(scene, initial={"qq3": 1.0})
    # ex2 beyond twice the 30 um clearance: refused by the API exactly as by the file
    with pytest.raises(DescriptionError, match=r"initial\.ex2: the journal must start inside"):
        replace(scene, initial={"ex2": 1e-3})
    path = tmp_path / "s.toml"
    path.write_text(scene_text(**{"ex2 = 0.0": "ex2 = 1e-3"}), encoding="utf-8")
    with pytest.raises(DescriptionError, match=r"initial\.ex2: the journal must start inside"):
        load_scene(path)


def test_with_run_unknown_settings_are_named_with_a_hint() -> None:
    with pytest.raises(DescriptionErrors) as err:
        default_scene().with_run(foo=1, t_edn=2.0)
    assert fields(err.value) == {"run.foo", "run.t_edn"}
    assert "did you mean 't_end'" in str(err.value)


def test_with_initial_and_with_torques() -> None:
    scene = default_scene()
    moved = scene.with_initial(q2="-pi/2", dq3=0.5)
    assert moved.initial["q2"] == pytest.approx(-math.pi / 2, rel=1e-15)
    assert moved.initial["dq3"] == 0.5 and moved.initial["q3"] == scene.initial["q3"]
    with pytest.raises(DescriptionErrors) as err:
        scene.with_initial(qq2=1.0, dq2=math.nan)
    assert fields(err.value) == {"initial.qq2", "initial.dq2"}
    driven = scene.with_torques(joint2="3*sin(2*pi*t)")
    assert driven.torque_text == {"joint2": "3*sin(2*pi*t)", "joint3": "2*sin(2*pi*t)"}
    assert float(driven.torques[0].numpy(0.25)) == pytest.approx(3.0, rel=1e-15)
    with pytest.raises(DescriptionError, match=r"torques\.joint9: unknown key"):
        scene.with_torques(joint9="1")
    with pytest.raises(DescriptionError, match=r"torques\.joint2: the torque '1/t' is inf"):
        scene.with_torques(joint2="1/t")


def test_every_problem_of_a_scene_file_is_reported_at_once(tmp_path: Path) -> None:
    path = tmp_path / "s.toml"
    # a robot with three bad numbers, and a bad run setting
    path.write_text(scene_text(**{"mass = 2.0": "mass = -2.0", "exponent = 1.5": "exponent = nan",
                                  "mass = 3.0": "mass = 1e300",
                                  "[run]": "[run]\nrtoll = 1e-6"}), encoding="utf-8")
    with pytest.raises(DescriptionErrors) as err:
        load_scene(path)
    assert fields(err.value) == {"payload.mass", "links[1].mass", "contact.exponent",
                                 "run.rtoll"}
    assert str(err.value).startswith("4 problems:")
    # a valid robot: initial values, torques and constants are checked against it, together
    path.write_text(scene_text(**{'joint2 = "4*sin(2*pi*t)"': 'joint2 = "4*sin(2*pi*t"',
                                  "q3 = 0.0": "q7 = 0.0", "ex2 = 0.0": "ex2 = 1.0",
                                  "[run]": "[constants]\nt = 1\n[run]"}), encoding="utf-8")
    with pytest.raises(DescriptionErrors) as err:
        load_scene(path)
    assert fields(err.value) == {"torques.joint2", "initial.q7", "initial.ex2", "constants.t"}


def test_a_sweep_file_given_to_simulate_names_the_sweep_command(
        capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["simulate", str(SCENES / "sweep_clearance.toml"), "--quiet"]) == 2
    assert "is a sweep file" in capsys.readouterr().err


def test_a_nul_in_the_scene_name_is_refused_when_read(tmp_path: Path) -> None:
    path = tmp_path / "s.toml"
    path.write_text(scene_text(**{'name = "paper_4dof"': 'name = "pa\\u0000per"'}),
                    encoding="utf-8")
    with pytest.raises(DescriptionError, match=r"name: must be printable text.*\\x00"):
        load_scene(path)


# ---- parameters= overrides: checked like the file ------------------------------------------------

def test_simulate_parameter_overrides_are_refused_naming_the_field() -> None:
    scene = default_scene().with_run(t_end=0.01)
    for overrides, field, message in (
            ({"link1.length": math.nan}, "link1.length", "finite"),
            ({"contact.exponent": math.inf}, "contact.exponent", "finite"),
            ({"link2.mass": -1.0}, "link2.mass", "> 0"),
            ({"contact.exponent": 1e300}, "contact.exponent", "outside the range"),
            ({"payload.mas": 1.0}, "payload.mas", "did you mean 'payload.mass'"),
            ({"q2": 1.0}, "q2", "[initial]")):
        with pytest.raises(DescriptionError) as err:
            simulate(scene, parameters=overrides)
        assert err.value.field == field and message in err.value.message, err.value
        assert err.value.source == "parameters"


def test_every_parameter_kind_refuses_nan_inf_and_out_of_range() -> None:
    """NaN, inf and a value far outside its range, for every parameter of two models (the
    paper's arm and the same arm worn and lubricated), through the override path."""
    for scene in (default_scene(), load_scene(SCENES / "paper_4dof_wear.toml")):
        model = model_for(scene.robot)
        for name in model.parameters:
            for bad in (math.nan, math.inf, -math.inf, 1e300):
                with pytest.raises(DescriptionError) as err:
                    _parameter_vector(model, scene, {name: bad})
                assert name in fields(err.value), (name, bad, err.value)
        # the whole vector, given as a sequence, is checked too
        vector = np.asarray(scene.robot.parameter_values())
        vector[0] = math.nan
        with pytest.raises(DescriptionError, match=model.parameters[0]):
            _parameter_vector(model, scene, vector)


def test_documented_ranges_refuse_values_no_robot_has(tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    scene = default_scene()
    for name, value in (("contact.exponent", 1e300), ("link1.mass", 1e300),
                        ("link1.length", 1e-300), ("joint2.bearing_E", 1.0)):
        with pytest.raises(DescriptionError, match="outside the range"):
            with_parameters(scene.robot, {name: value})
        assert main(["simulate", "--set", f"{name}={value!r}", "--quiet"]) == 2
        assert f"--set {name}: " in capsys.readouterr().err
    worn = (SCENES / "paper_4dof_wear.toml").read_text(encoding="utf-8")
    path = tmp_path / "w.toml"
    path.write_text(re.sub(r"hardness = \S+", "hardness = 5e-324", worn), encoding="utf-8")
    assert main(["simulate", str(path), "--quiet"]) == 2
    assert "wear.hardness: 4.94066e-324 Pa is outside the range" in capsys.readouterr().err
    assert all(low <= high for low, high, _, _ in PHYSICAL_RANGES.values())


def test_readme_lists_every_physical_range() -> None:
    readme = (Path(__file__).resolve().parent.parent / "README.md").read_text(encoding="utf-8")
    section = readme.split("## Limits, interrupts and errors", 1)[1].split("\n## ", 1)[0]
    for kind, (low, high, unit, _) in PHYSICAL_RANGES.items():
        row = f"| `{kind}` | {low:g} | {high:g} | {unit} |"
        assert row in section, row
    assert f"{MAX_PENETRATION_FRACTION:g}" in section


# ---- run-time stops -----------------------------------------------------------------------------

def test_a_journal_driven_through_its_bearing_stops_the_run(tmp_path: Path,
                                                             capsys: pytest.CaptureFixture[str]
                                                             ) -> None:
    scene = default_scene().with_run(t_end=0.05).with_initial(dq2=1e3)
    with pytest.raises(SimulationError, match=r"penetrated its bearing.*dq2 = 1000") as err:
        simulate(scene)
    assert err.value.joint == 2 and err.value.time <= 0.002
    path = tmp_path / "fast.toml"
    path.write_text(scene_text(**{"[initial]": "[initial]\ndq2 = 1e3",
                                  "t_end = 2.0": "t_end = 0.05"}), encoding="utf-8")
    out = tmp_path / "run.h5"
    assert main(["simulate", str(path), "--out", str(out), "--quiet"]) == 1
    assert "at joint 2: the journal has penetrated" in capsys.readouterr().err
    assert not out.exists()


def test_an_energy_balance_that_no_longer_closes_stops_the_run() -> None:
    scene = default_scene().with_run(t_end=0.5, rtol=0.05, atol=1.0)
    with pytest.raises(SimulationError, match=r"energy balance no longer closes.*run\.rtol"):
        simulate(scene)


def test_non_finite_derived_quantities_and_wear_are_never_returned() -> None:
    from jointplay.sim.plausibility import check_result
    from jointplay.sim.problem import _Problem

    scene = load_scene(SCENES / "paper_4dof_wear.toml").with_run(t_end=0.01)
    result = simulate(scene)
    model = model_for(scene.robot)
    problem = _Problem(model, scene, result.parameters)
    check_result(result, problem)  # the run itself passes
    force = result.normal_force.copy()
    force[3, 0] = math.nan
    with pytest.raises(SimulationError, match=r"normal_force is not finite") as err:
        check_result(replace(result, normal_force=force), problem)
    assert err.value.time == result.t[3]
    assert result.wear is not None
    worn = replace(result.wear, volume=np.full_like(result.wear.volume, math.inf))
    with pytest.raises(SimulationError, match=r"wear volume is not finite.*wear\.hardness"):
        check_result(replace(result, wear=worn), problem)


def test_a_torque_singular_between_output_times_is_named() -> None:
    scene = default_scene().with_run(t_end=0.35).with_torques(joint2="1/(t-0.3005)")
    with pytest.raises(SimulationError, match=r"torques\.joint2 \('1/\(t-0\.3005\)'\)"):
        simulate(scene)


def test_a_torque_table_must_cover_the_run(tmp_path: Path) -> None:
    table = tmp_path / "torques.csv"
    table.write_text("t,joint2,joint3\n0,0,0\n0.5,1,1\n", encoding="utf-8")
    text = scene_text(**{'joint2 = "4*sin(2*pi*t)"': 'table = "torques.csv"',
                         'joint3 = "2*sin(2*pi*t)"': ""})
    path = tmp_path / "s.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(DescriptionError, match=r"torques\.table: covers t = 0 to 0\.5 s.*2 s"):
        load_scene(path)
    path.write_text(text.replace('table = "torques.csv"',
                                 'table = "torques.csv"\nhold_ends = true'), encoding="utf-8")
    held = load_scene(path)
    assert float(held.torques[0].numpy(1.5)) == 1.0
    assert load_scene(path).with_run(t_end=0.5).torque_text["hold_ends"] == "true"
    with pytest.raises(DescriptionError, match=r"covers t = 0 to 0\.5 s"):
        replace(held, torque_text={"table": "torques.csv"})


# ---- messages ------------------------------------------------------------------------------------

def test_every_help_names_only_options_that_exist() -> None:
    parser = make_parser()
    add_debug_flag(parser)

    def walk(p: argparse.ArgumentParser, path: list[str]):  # type: ignore[no-untyped-def]
        yield path, p
        for action in p._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    yield from walk(sub, [*path, name])

    seen = 0
    for path, p in walk(parser, []):
        text = p.format_help()
        options = {o for a in p._actions for o in a.option_strings}
        named = set(re.findall(r"(?<![\w-])--[a-z][a-z0-9-]*", text))
        assert named <= options, (path, named - options)
        seen += 1
    assert seen >= 12  # the command, its subcommands and bench's three
    simulate_help = next(p for path, p in walk(parser, []) if path == ["simulate"])
    assert "bdf" in simulate_help.format_help().split("--integrator", 2)[2][:200]


def test_version(capsys: pytest.CaptureFixture[str]) -> None:
    from jointplay import __version__

    with pytest.raises(SystemExit) as exit_:
        main(["--version"])
    assert exit_.value.code == 0
    assert capsys.readouterr().out.strip() == f"jointplay {__version__}"


def test_set_messages(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["simulate", "--set", "run.integrator=rk4", "--set", "run.t_end=abc",
                 "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "--set run.t_end: must be a number" in err
    assert main(["simulate", "--set", "run.integrator=rk5", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "must be one of bdf" in err and "did you mean 'rk4'" in err
    assert main(["simulate", "--set", "dq2=1", "--quiet"]) == 2
    assert "--set dq2: is an initial value" in capsys.readouterr().err


def test_identify_seed_out_of_range(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from jointplay.neural.identify.config import IdentifyConfig

    for seed in ("-1", str(2**32)):
        assert main(["identify", "--seed", seed, "--out", str(tmp_path / "m"), "--quiet"]) == 2
        assert "--seed: must be a whole number from 0 to 4294967295" in capsys.readouterr().err
    with pytest.raises(DescriptionError, match="seed"):
        IdentifyConfig(seed=-1)
    assert not (tmp_path / "m").exists()


def test_toml_nesting_and_byte_order_mark(tmp_path: Path) -> None:
    deep = tmp_path / "deep.toml"
    deep.write_text("a = " + "[" * 5000 + "]" * 5000 + "\n", encoding="utf-8")
    with pytest.raises(DescriptionError, match=r"\(toml\): nests arrays or inline tables 5000"):
        load_scene(deep)
    bom = tmp_path / "bom.toml"
    bom.write_bytes(b"\xef\xbb\xbf" + (SCENES / "paper_4dof.toml").read_bytes())
    shutil.copy(SCENES / "paper_4dof.toml", tmp_path / "plain.toml")
    assert load_scene(bom).initial == load_scene(tmp_path / "plain.toml").initial


def test_plot_clashing_with_csv_is_named_before_the_run(tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]
                                                        ) -> None:
    csv = tmp_path / "run.csv"
    for plot in (csv, tmp_path / "run.impacts.csv"):
        assert main(["simulate", "--csv", str(csv), "--plot", str(plot), "--quiet"]) == 2
        assert "--plot: names the same path as --csv" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_control_exits_3_when_any_reported_controller_diverged() -> None:
    from jointplay.cli.control import any_diverged

    def runs(**diverged: str) -> SimpleNamespace:
        names = ("PD", "computed torque", "ARX-IMC", "neural IMC")
        return SimpleNamespace(runs={n: SimpleNamespace(diverged=diverged.get(n.split()[0], ""))
                                     for n in names})

    assert not any_diverged(runs())  # type: ignore[arg-type]
    assert any_diverged(runs(PD="|p| > 10 m"))  # type: ignore[arg-type]
    assert any_diverged(runs(computed="|v| grew"))  # type: ignore[arg-type]


def test_fixed_step_run_through_the_bearing_still_says_reduce_the_step() -> None:
    scene = make_scene(pin_in_bearing(restitution=0.9), initial={"dex1": 1.0}, t_end=1e-3,
                       output_step=1e-4, integrator="rk4", step=1e-4)
    with pytest.raises(SimulationError, match=r"reduce run\.step"):
        simulate(scene)


def test_scene_from_dict_api_reports_like_the_file() -> None:
    data = {"robot": "missing.toml", "initial": {"zz": 1}, "run": {"t_end": -1}}
    with pytest.raises(DescriptionErrors) as err:
        scene_from_dict(data, source="api")
    assert fields(err.value) == {"robot", "run.t_end"}  # initial needs the robot: not guessed


def test_every_problem_of_a_sweep_is_reported_at_once() -> None:
    from jointplay.sweep.spec import sweep_from_dict

    data = {"scene": "default", "mode": "prodct", "seed": -1,
            "parameters": {"friction.mu": {"values": [0.1]}, "link1.mas": {"values": [1.0]}}}
    with pytest.raises(DescriptionErrors) as err:
        sweep_from_dict(data, source="api")
    assert fields(err.value) == {"mode", "seed", "parameters.link1.mas"}
    assert "did you mean 'link1.mass'" in str(err.value)
