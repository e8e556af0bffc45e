"""The settings file of identification, the controller and studies: every key checked as a
scene's are (all problems at once, an unknown key with the nearest known one), the presets,
the order of overrides (flags > --set > file > preset), settings.toml read back the same, and
control-study's short --help."""

from __future__ import annotations

import argparse
import re
import tomllib
from dataclasses import fields
from pathlib import Path

import pytest

from jointplay.common.errors import DescriptionError
from jointplay.neural.control.imc_settings import ControllerSettings
from jointplay.neural.identify.config import IdentifyConfig
from jointplay.neural.study.settings import (
    DEFAULT_PRESET,
    PRESETS,
    Settings,
    StudySettings,
    is_settings_document,
    preset_settings,
    read_settings_file,
    resolve_settings,
    settings_tables,
    settings_toml,
)
from jointplay.neural.study.settings_schema import SCHEMA

ROOT = Path(__file__).resolve().parents[1]
STUDY_BEST = ROOT / "scenes" / "study_best.toml"
HOW_TO = ROOT / "docs" / "how-to" / "settings-file.md"


def test_every_field_is_a_key_and_every_key_a_field() -> None:
    for section, cls in (("identify", IdentifyConfig), ("control", ControllerSettings),
                         ("study", StudySettings)):
        assert list(SCHEMA[section]) == [f.name for f in fields(cls)], section


def test_the_how_to_documents_every_key() -> None:
    text = HOW_TO.read_text(encoding="utf-8")
    missing = [f"{s}.{k}" for s in SCHEMA for k in SCHEMA[s] if f"`{k}`" not in text]
    assert missing == []


def test_the_how_tos_defaults_are_the_presets() -> None:
    """Each table row ``| `key` | paper | best | meaning |`` of the how-to, against the code."""
    from jointplay.neural.study.settings_schema import toml_value

    rows = re.findall(r"^\| `(\w+)` \| (.+?) \| (.+?) \| .+ \|$",
                      HOW_TO.read_text(encoding="utf-8"), flags=re.M)
    sections = [s for s in SCHEMA for _ in SCHEMA[s]]
    assert [key for key, _, _ in rows] == [k for s in SCHEMA for k in SCHEMA[s]]
    for section, (key, paper, best) in zip(sections, rows, strict=True):
        for preset, shown in (("paper", paper), ("best", best)):
            value = getattr(getattr(preset_settings(preset), section), key)
            expected = "(absent)" if value is None else toml_value(SCHEMA[section][key], value)
            assert shown == expected, (section, key, preset)


def problems_of(tables: dict, **kw: object) -> list[tuple[str, str]]:
    with pytest.raises(DescriptionError) as caught:
        resolve_settings(tables, **kw)  # type: ignore[arg-type]
    return [(p.field, p.message) for p in caught.value.problems]


def test_all_problems_are_reported_at_once_with_the_nearest_key() -> None:
    found = problems_of({"preset": "bset", "identify": {"hiden": [24], "duration": -1.0,
                                                       "seed": "7"},
                         "control": {"horizon": 0, "guard": 1},
                         "study": {"cases": ["scene", "sceen"], "workers": 2.5},
                         "stduy": {}})
    fields_found = [f for f, _ in found]
    assert fields_found == ["preset", "identify.hiden", "identify.duration", "identify.seed",
                            "control.horizon", "control.guard", "study.cases[1]",
                            "study.workers"]
    messages = dict(found)
    assert "did you mean 'best'" in messages["preset"]
    assert "did you mean 'hidden'" in messages["identify.hiden"]
    assert messages["identify.duration"] == "must be above 0 and at most 100000, got -1.0"
    assert messages["identify.seed"] == "must be a whole number, got '7'"
    assert messages["control.guard"] == "must be true or false, got 1"
    assert "got 'sceen'" in messages["study.cases[1]"]


def test_a_file_reports_the_same_problems_naming_itself(tmp_path: Path) -> None:
    path = tmp_path / "study.toml"
    path.write_text('preset = "best"\nscnee = "x.toml"\n[identify]\nhidden = [0]\n'
                    "[control]\nsetpoint_filter = 1.0\n", encoding="utf-8")
    with pytest.raises(DescriptionError) as caught:
        read_settings_file(path)
    assert [(p.field, p.source) for p in caught.value.problems] == [("scnee", str(path))]
    assert "did you mean 'scene'" in caught.value.problems[0].message
    path.write_text('[identify]\nhidden = [0]\n[control]\nsetpoint_filter = 1.0\n',
                    encoding="utf-8")
    with pytest.raises(DescriptionError) as caught:
        read_settings_file(path)
    assert [(p.field, p.source) for p in caught.value.problems] == [
        ("identify.hidden[0]", str(path)), ("control.setpoint_filter", str(path))]


def test_a_file_naming_itself_as_its_scene_is_refused_as_such(tmp_path: Path) -> None:
    """``scene`` naming the settings file itself (by any path) is a mistake said as one, not
    the file read again as a scene (which then looked like a sweep file)."""
    path = tmp_path / "study.toml"
    for name in ("study.toml", "./study.toml", f"../{tmp_path.name}/study.toml"):
        path.write_text(f'scene = "{name}"\n', encoding="utf-8")
        with pytest.raises(DescriptionError, match="names this settings file itself") as caught:
            read_settings_file(path)
        assert caught.value.field == "scene"


def test_checks_across_keys_name_the_table() -> None:
    assert problems_of({"preset": "paper", "identify": {"lpv_base": True}})[0][0] == \
        "identify.lpv_base"
    assert problems_of({"identify": {"residual_by": "closed-loop", "n_validation": 1}})[0][0] \
        == "identify.residual_by"


def test_set_overrides_are_checked_by_the_same_schema() -> None:
    found = problems_of({}, overrides=["identify.hidden=24,0", "identify.hiden=3",
                                       "control.horizon=x", "nonsense"])
    assert [f for f, _ in found] == ["--set identify.hidden[1]", "--set", "--set control.horizon"]
    assert "did you mean 'identify.hidden'" in found[1][1]
    settings = resolve_settings({}, overrides=[
        "identify.hidden=30,30", "identify.residual_by=free-run", "control.guard=false",
        "control.measurement_noise=q2=3e-6,dq2=4e-3", "study.cases=scene,noise",
        "study.clearances=[]", "control.engage=0.2"])
    assert settings.identify.hidden == (30, 30) and settings.identify.residual_by == "free-run"
    assert not settings.control.guard and settings.control.engage == 0.2
    assert settings.control.measurement_noise == (("q2", 3e-6), ("dq2", 4e-3))
    assert settings.study.cases == ("scene", "noise") and settings.study.clearances == ()


def test_the_command_line_reports_file_set_and_flag_problems_at_once(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("torch")
    from jointplay.cli import main

    study = tmp_path / "study.toml"
    study.write_text('[identify]\nwindow = 1\n', encoding="utf-8")
    out = tmp_path / "model"
    assert main(["identify", str(study), "--out", str(out), "--set", "identify.hiden=3",
                 "--hidden", "0", "--lags", "2"]) == 2
    err = capsys.readouterr().err
    for named in ("identify.window:", "--set: 'identify.hiden=3'", "--hidden:", "--lags:"):
        assert named in err, err
    assert "4 problems" in err and not out.exists()
    # the file's problem carries its name; the --set value came from the command line
    assert f"{study}: identify.window:" in err and f"{study}: --set" not in err, err


def test_paper_is_the_dataclasses_defaults_and_best_the_measured_setting() -> None:
    paper = preset_settings("paper")
    assert paper == Settings("paper", IdentifyConfig(), ControllerSettings(), StudySettings())
    assert paper.identify.hidden == (13, 14) and paper.identify.residual_by == "free-run"
    best = preset_settings()
    assert DEFAULT_PRESET == "best" and best.preset == "best"
    config = best.identify
    assert (config.scheduling, config.lpv_base, config.linear_input_gain) == (True, True, True)
    assert (config.residual_by, config.base_motions, config.hidden) == (
        "closed-loop-scene", "scene-family", (24, 24))
    assert (config.n_train, config.n_validation, config.n_test, config.duration) == (
        24, 2, 2, 2.0)
    assert (config.one_step_iterations, config.multi_step_iterations) == (20, 5)
    assert best.control == ControllerSettings() and best.study == StudySettings()
    assert set(PRESETS) == {"paper", "best"}


def test_the_preset_flag_beats_the_files_preset_and_the_file_beats_the_preset() -> None:
    tables = {"preset": "paper", "identify": {"n_train": 7}}
    assert resolve_settings(tables).identify.hidden == (13, 14)
    flagged = resolve_settings(tables, preset="best")
    assert flagged.preset == "best" and flagged.identify.hidden == (24, 24)
    assert flagged.identify.n_train == 7  # the file over the preset
    assert resolve_settings(tables, overrides=["identify.n_train=9"]).identify.n_train == 9


def study_plan_of(argv: list[str]) -> object:
    from jointplay.cli import make_parser
    from jointplay.cli.study import study_plan

    return study_plan(make_parser().parse_args(["control-study", *argv]))


def test_flags_beat_set_which_beats_the_file_which_beats_the_preset(tmp_path: Path) -> None:
    pytest.importorskip("torch")
    study = tmp_path / "study.toml"
    study.write_text('[identify]\nhidden = [30, 30]\n[study]\nseeds = 4\n', encoding="utf-8")
    out = str(tmp_path / "out")

    def hidden(*argv: str) -> tuple[int, ...]:
        return study_plan_of([*argv, "--out", out]).settings.identify.hidden  # type: ignore

    assert hidden() == (24, 24)  # the preset
    assert hidden(str(study)) == (30, 30)  # the file
    assert hidden(str(study), "--set", "identify.hidden=20,20") == (20, 20)
    assert hidden(str(study), "--set", "identify.hidden=20,20", "--identify-hidden",
                  "10") == (10,)
    assert hidden(str(study), "--preset", "paper") == (30, 30)
    plan = study_plan_of([str(study), "--out", out, "--seeds", "2", "--preset", "paper"])
    assert plan.settings.study.seeds == 2 and plan.settings.preset == "paper"  # type: ignore
    assert plan.identify_args["n_train"] == IdentifyConfig.n_train  # type: ignore


@pytest.mark.parametrize("preset", ["paper", "best"])
def test_settings_toml_reads_back_as_the_same_settings(tmp_path: Path, preset: str) -> None:
    settings = resolve_settings({"preset": preset, "identify": {"kp": [50.0, 40.0, 30.0]},
                                 "control": {"engage": 0.25, "tracked": ["q2", "dq2"],
                                             "measurement_noise": {"q2": 3e-6}},
                                 "study": {"clearances": [1e-5, 6e-5]}})
    for scene in (None, tmp_path / "my scene.toml"):
        path = tmp_path / "settings.toml"
        path.write_text(settings_toml(settings, scene), encoding="utf-8")
        again, named = read_settings_file(path)
        assert again == settings and named == scene
    assert "engage" not in settings_toml(preset_settings(preset), None)  # decided per run
    assert resolve_settings(tomllib.loads(settings_toml(preset_settings(preset), None))) == \
        preset_settings(preset)


def test_a_study_records_settings_that_rerun_it(tmp_path: Path) -> None:
    """The plan's resolved settings (file, --set and flags) as settings.toml, read back as a
    study: the same settings and the same scene."""
    pytest.importorskip("torch")
    scene = tmp_path / "short.toml"
    scene.write_text((ROOT / "scenes" / "paper_4dof.toml").read_text(encoding="utf-8"),
                     encoding="utf-8")
    plan = study_plan_of([str(scene), "--out", str(tmp_path / "a"), "--set",
                          "identify.window=50", "--identify-scene-motions", "3",
                          "--horizon", "3", "--cases", "scene,noise"])
    recorded = tmp_path / "settings.toml"
    recorded.write_text(settings_toml(plan.settings, plan.scene_file),  # type: ignore
                        encoding="utf-8")
    again = study_plan_of([str(recorded), "--out", str(tmp_path / "b")])
    assert again.settings == plan.settings  # type: ignore[attr-defined]
    assert again.scene_file == scene.resolve()  # type: ignore[attr-defined]
    assert again.identify_args == plan.identify_args  # type: ignore[attr-defined]
    assert plan.settings.control.horizon == 3  # type: ignore[attr-defined]
    assert plan.settings.identify.scene_motions == 3  # type: ignore[attr-defined]


def test_identify_records_the_settings_it_ran_with(tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """identify's model folder gets settings.toml (preset, file, --set and flags resolved);
    read back, it gives the same identification (the work itself replaced by a stand-in)."""
    pytest.importorskip("torch")
    import jointplay.cli.identify as command
    from jointplay.cli import main

    ran: list[IdentifyConfig] = []

    def stand_in(scene: object, out: Path, config: IdentifyConfig,
                 quiet: bool = False) -> dict[str, object]:
        out.mkdir(parents=True, exist_ok=True)
        ran.append(config)
        return {}

    monkeypatch.setattr(command, "identify_model", stand_in)
    out = tmp_path / "model"
    assert main(["identify", "--out", str(out), "--quiet", "--set", "identify.window=50",
                 "--hidden", "8,8", "--kp", "40", "--seed", "3"]) == 0
    settings, scene = read_settings_file(out / "settings.toml")
    assert scene is None and settings.preset == "best"
    assert settings.identify == ran[0]
    assert (ran[0].window, ran[0].hidden, ran[0].kp, ran[0].seed) == (50, (8, 8), (40.0, 40.0),
                                                                      3)
    assert ran[0].lpv_base  # the best preset's, no flag needed
    again = tmp_path / "again"
    assert main(["identify", str(out / "settings.toml"), "--out", str(again), "--quiet"]) == 0
    assert ran[1] == ran[0]


def test_control_study_help_lists_at_most_20_options() -> None:
    from jointplay.cli import make_parser

    parser = make_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    text = sub.choices["control-study"].format_help()
    options = re.findall(r"^  (-[-\w]+)", text.split("options:", 1)[1], flags=re.M)
    assert "--set" in options and "--preset" in options
    assert len(options) <= 20, options
    assert "docs/how-to/settings-file.md" in text.replace("settings-\nfile", "settings-file")


def test_the_best_study_is_a_short_file_of_the_best_preset() -> None:
    lines = STUDY_BEST.read_text(encoding="utf-8").splitlines()
    assert len(lines) <= 30
    settings, scene = read_settings_file(STUDY_BEST)
    assert settings.identify == preset_settings("best").identify
    assert scene == ROOT / "scenes" / "paper_4dof.toml" and scene.is_file()
    assert settings.study.cases == ("scene",) and settings.study.clearances == (1e-4,)


def test_a_scene_may_hold_the_settings_and_a_settings_file_is_no_scene(
        tmp_path: Path) -> None:
    from jointplay.scene.definition import load_scene

    text = (ROOT / "scenes" / "paper_4dof.toml").read_text(encoding="utf-8")
    scene = tmp_path / "scene.toml"
    scene.write_text('preset = "paper"\n' + text + "\n[identify]\nn_train = 5\n",
                     encoding="utf-8")
    assert load_scene(scene).name == "paper_4dof"
    data = tomllib.loads(scene.read_text(encoding="utf-8"))
    assert not is_settings_document(data)
    settings = resolve_settings(settings_tables(data))
    assert (settings.preset, settings.identify.n_train) == ("paper", 5)
    with pytest.raises(DescriptionError, match="is a settings file"):
        load_scene(STUDY_BEST)


@pytest.mark.slow
def test_a_tiny_best_study_runs_end_to_end_and_reruns_from_its_output(tmp_path: Path) -> None:
    """scenes/study_best.toml beside a 0.15 s copy of its scene, every size made small with
    --set: identification (with the closed-loop choice), the study's runs, its files, and
    settings.toml naming the scene and the sizes given."""
    pytest.importorskip("torch")
    from jointplay.cli import main

    short = (ROOT / "scenes" / "paper_4dof.toml").read_text(encoding="utf-8").replace(
        "t_end = 2.0 ", "t_end = 0.15 ")
    (tmp_path / "paper_4dof.toml").write_text(short, encoding="utf-8")
    (tmp_path / "study_best.toml").write_text(STUDY_BEST.read_text(encoding="utf-8"),
                                              encoding="utf-8")
    out = tmp_path / "out"
    # (with fewer runs or iterations the network is worse than persistence and refused)
    tiny = ["--set", "identify.n_train=2", "--set", "identify.n_validation=1", "--set",
            "identify.n_test=1", "--set", "identify.duration=0.5", "--set",
            "identify.hidden=4", "--set", "identify.one_step_iterations=20", "--set",
            "identify.multi_step_iterations=0", "--set", "identify.window=20", "--set",
            "identify.scene_motions=1", "--set", "study.clearances=[]", "--seeds", "1"]
    code = main(["control-study", str(tmp_path / "study_best.toml"), "--out", str(out),
                 "--quiet", *tiny])
    assert code in (0, 3)  # 3: an internal-model run diverged, which a tiny model may
    for name in ("study.md", "study.csv", "study.json", "settings.toml"):
        assert (out / name).is_file(), name
    recorded, scene = read_settings_file(out / "settings.toml")
    assert scene == (tmp_path / "paper_4dof.toml").resolve()
    assert recorded.identify.hidden == (4,) and recorded.study.seeds == 1
    assert recorded.identify.residual_by == "closed-loop-scene"
    # control on the study's model records its settings beside its figures
    plot = tmp_path / "plot"
    model = next((out / "models").glob("*/seed11"))
    assert main(["control", str(tmp_path / "paper_4dof.toml"), "--model", str(model),
                 "--plot", str(plot), "--quiet", "--horizon", "3"]) in (0, 3)
    controlled, _ = read_settings_file(plot / "settings.toml")
    assert controlled.control.horizon == 3 and controlled.preset == "best"


@pytest.mark.parametrize("command", ["identify", "control-study"])
@pytest.mark.parametrize("text", ["", "# nothing set yet\n"])
def test_an_empty_file_is_refused_as_neither_scene_nor_settings(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], command: str, text: str) -> None:
    """An empty file (or one of comments only) is named as such, with both kinds it could
    be, not read as a scene that lacks its [robot] table; nothing is written."""
    pytest.importorskip("torch")
    from jointplay.cli import main

    empty = tmp_path / "empty.toml"
    empty.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main([command, str(empty), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert f"{empty}: (file): is empty: give a scene" in err and "settings file" in err, err
    assert "[robot] table or the path" not in err and not out.exists()
