"""The output a mechanism run follows (its summary line against the ideal mechanism, its
first two figures): the file's ``[output] coordinate``, validated with the nearest valid
name, or the rule of :mod:`jointplay.mechanism.output` (the slider, else the rocker's angle
from the ground, else the last angle)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from jointplay.cli.mechanism import summary_lines
from jointplay.common.errors import DescriptionError
from jointplay.mechanism.inspect import render
from jointplay.mechanism.output import default_output, followed
from jointplay.mechanism.plots import write_figures
from jointplay.mechanism.reading import load_mechanism_scene
from jointplay.mechanism.simulate import simulate_mechanism
from jointplay.mechanism.structure import coordinates

FOUR_BAR = Path("scenes/four_bar.toml")
FOUR_BAR_TEXT = FOUR_BAR.read_text(encoding="utf-8")
SLIDER_CRANK_TEXT = Path("scenes/slider_crank.toml").read_text(encoding="utf-8")
OUTPUT_TABLE = re.compile(r"^\[output\].*\ncoordinate = .*\n", re.MULTILINE)


def _written(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "variant.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _without_output(text: str) -> str:
    assert OUTPUT_TABLE.search(text), "the four-bar names its output"
    return OUTPUT_TABLE.sub("", text)


def _joint_block(text: str, name: str) -> tuple[int, int]:
    start = text.rindex("[[mechanism.joints]]", 0, text.index(f'name = "{name}"'))
    end = text.find("[[", start + 1)
    following = [i for i in (end, text.find("\n[", start + 1)) if i > 0]
    return start, min(following)


def test_the_files_follow_the_slider_and_the_rocker() -> None:
    four_bar = load_mechanism_scene(FOUR_BAR)
    assert four_bar.output_coordinate == "rocker.angle"
    assert ("  output (what the summary and the figures follow, the file's [output]): "
            "rocker.angle") in render(four_bar).splitlines()
    for name in ("slider_crank", "slider_crank_0_1mm", "slider_crank_friction"):
        scene = load_mechanism_scene(f"scenes/{name}.toml")
        assert scene.output is None and scene.output_coordinate == "guide.position"
        assert ("  output (what the summary and the figures follow, the default rule): "
                "guide.position") in render(scene).splitlines()


def test_the_rule_without_an_output_table(tmp_path: Path) -> None:
    # The four-bar's rocker floats (its pivot on the ground has clearance): its own angle.
    scene = load_mechanism_scene(_written(tmp_path, _without_output(FOUR_BAR_TEXT)))
    assert scene.output is None
    assert default_output(scene.mechanism) == "rocker.angle"
    # With ideal crank and rocker pins (play in the coupler-rocker pin only) the rocker is
    # placed by its ideal pivot on the ground: that joint's angle, not the crank pin's.
    text = _without_output(FOUR_BAR_TEXT)
    for pin in ("crank_pin", "rocker_pivot"):
        start, end = _joint_block(text, pin)
        block = re.sub(r'kind = "clearance"', 'kind = "ideal"', text[start:end])
        block = re.sub(r"^(bearing|journal)_radius = .*\n", "", block, flags=re.MULTILINE)
        text = text[:start] + block + text[end:]
    text = re.sub(r"^\[initial\].*?\n\n", "", text, flags=re.MULTILINE | re.DOTALL)
    text = text.replace("[run]", "[initial]\nrocker_pivot.angle = 0.96\n\n[run]")
    scene = load_mechanism_scene(_written(tmp_path, text))
    names = {c.name for c in coordinates(scene.mechanism.structure())}
    assert names == {"crank_pin.angle", "rocker_pivot.angle", "t"}
    assert scene.output_coordinate == "rocker_pivot.angle"
    # No slider and no other ground pivot (the slider-crank's guide removed: the slider
    # hangs on its clearance pin): the last angle, the link placed last.
    start, end = _joint_block(SLIDER_CRANK_TEXT, "guide")
    scene = load_mechanism_scene(_written(tmp_path, SLIDER_CRANK_TEXT[:start]
                                          + SLIDER_CRANK_TEXT[end:]))
    assert scene.output_coordinate == "slider.angle"


@pytest.mark.parametrize(("table", "field", "words"), [
    ('coordinate = "rocker.angel"', "output.coordinate", "did you mean 'rocker.angle'"),
    ('coordinate = "t"', "output.coordinate", "rocker.angle"),
    ("coordinate = 3", "output.coordinate", "got 3"),
    ('coordnate = "rocker.angle"', "output.coordnate", "did you mean 'coordinate'"),
])
def test_a_bad_output_is_named_with_what_is_allowed(tmp_path: Path, table: str, field: str,
                                                    words: str) -> None:
    text = OUTPUT_TABLE.sub(f"[output]\n{table}\n", FOUR_BAR_TEXT)
    with pytest.raises(DescriptionError) as caught:
        load_mechanism_scene(_written(tmp_path, text))
    assert field in str(caught.value) and words in str(caught.value), str(caught.value)


def test_a_result_without_a_recorded_output_falls_back_on_its_names() -> None:
    assert followed("", ["guide.position", "crank_pin.angle", "t"]) == "guide.position"
    assert followed("", ["coupler.x", "coupler.angle", "rocker.angle", "t"]) == "rocker.angle"
    assert followed("coupler.x", ["coupler.x", "rocker.angle", "t"]) == "coupler.x"


@pytest.fixture(scope="module")
def four_bar_run() -> Any:
    scene = load_mechanism_scene(FOUR_BAR)
    return simulate_mechanism(scene.with_run(t_end=0.05, output_step=1e-3),
                              compare_ideal=True)


def test_the_four_bars_summary_and_figures_follow_the_rocker(four_bar_run: Any,
                                                             tmp_path: Path) -> None:
    result = four_bar_run
    assert result.output == "rocker.angle"
    k = result.coordinates.index("rocker.angle")
    deviation = np.max(np.abs(result.x[:, k] - result.ideal["x"][:, k]))
    lines = summary_lines(result)
    assert f"  rocker.angle: at most {deviation:.4g} rad from the ideal mechanism's" in lines
    assert not any(line.startswith("  coupler.x") for line in lines)
    names = sorted(p.name for p in write_figures(result, tmp_path))
    assert "rocker_angle_acceleration.png" in names and "rocker_angle_velocity.png" in names
    assert not any(name.startswith("coupler_x") for name in names)


def test_a_four_bar_sweep_reports_the_rockers_distance_from_the_ideal(
        four_bar_run: Any, tmp_path: Path) -> None:
    from jointplay.cli import main

    (tmp_path / "four_bar.toml").write_text(FOUR_BAR_TEXT, encoding="utf-8")
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('scene = "four_bar.toml"\n[run]\nt_end = 0.05\n'
                     '[parameters."rocker.mass"]\nvalues = [1.0, 2.0]\n', encoding="utf-8")
    assert main(["sweep", str(sweep), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    lines = (tmp_path / "out" / "mechanism_sweep.csv").read_text(encoding="utf-8").splitlines()
    rows = [dict(zip(lines[0].split(","), map(float, line.split(",")), strict=True))
            for line in lines[1:]]
    k = four_bar_run.coordinates.index("rocker.angle")  # the first case is the scene's run
    expected = np.max(np.abs(four_bar_run.x[:, k] - four_bar_run.ideal["x"][:, k]))
    assert rows[0]["output_from_ideal"] == pytest.approx(expected, rel=1e-9)
    # rad: about 2.9 mrad per mm of play in the three pins, as the scene test measures
    assert 2.0 * 5e-3 < rows[1]["output_from_ideal"] < 4.0 * 5e-3
    assert all(np.isnan(row["slider_from_ideal_m"]) for row in rows)  # a four-bar: no slider
