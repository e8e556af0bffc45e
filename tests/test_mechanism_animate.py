"""The mechanism animation: its bodies placed where the closed-form kinematics put them, and
the file written by ``simulate --animate`` whole or not at all."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from jointplay.cli import main
from jointplay.mechanism import load_mechanism_scene, simulate_mechanism
from jointplay.mechanism.animate import BodyPaths, animate_mechanism, body_paths

SCENE = Path("scenes/slider_crank.toml")
FOUR_BAR = Path("scenes/four_bar.toml")


def _point(paths: BodyPaths, body: str, joint: str) -> np.ndarray:
    if body == "ground":
        return paths.ground[paths.ground_labels.index(joint)]
    return paths.points[body][:, paths.labels[body].index(joint)]


def test_slider_crank_bodies_follow_the_closed_form() -> None:
    """The crank's tip at r (cos th, sin th) with th = 5000 rpm x t, the rod 0.12 m long, the
    slider's pin on the guide at the slider's travel, the rod's pin off it by the
    eccentricity: to rounding (1e-15 m)."""
    scene = load_mechanism_scene(SCENE).with_run(t_end=0.004)
    result = simulate_mechanism(scene)
    paths = body_paths(scene, result)
    theta = 2 * np.pi * 5000 / 60 * result.t
    tip = _point(paths, "crank", "crank_pin")
    assert np.max(np.abs(tip - 0.05 * np.stack([np.cos(theta), np.sin(theta)], 1))) < 1e-15
    assert np.max(np.abs(_point(paths, "crank", "crank_pivot"))) < 1e-15
    rod = np.linalg.norm(_point(paths, "rod", "slider_pin") - _point(paths, "rod", "crank_pin"),
                         axis=1)
    assert np.max(np.abs(rod - 0.12)) < 1e-15
    pin = _point(paths, "slider", "slider_pin")
    assert np.max(np.abs(pin[:, 0] - result.coordinate("guide.position"))) < 1e-15
    assert np.max(np.abs(pin[:, 1])) < 1e-15
    gap = _point(paths, "rod", "slider_pin") - pin
    assert np.max(np.abs(gap - result.eccentricity[:, 0])) < 1e-15
    assert np.max(np.linalg.norm(gap, axis=1)) > 1e-4  # the journal did move in its play
    assert paths.sliders == ["slider"] and len(paths.guides) == 1


def test_four_bar_loop_closes_to_the_eccentricity() -> None:
    """In the four-bar every body's points come from the model's frames; across the clearance
    joint they differ by the eccentricity, and the ground pivots stay put."""
    scene = load_mechanism_scene(FOUR_BAR)
    scene = scene.with_run(t_end=min(scene.run.t_end, 20 * scene.run.output_step))
    result = simulate_mechanism(scene)
    paths = body_paths(scene, result)
    structure = scene.mechanism.structure()
    for k, joint in enumerate(j for j in structure.joints if j.cut):
        gap = _point(paths, joint.child, joint.name) - _point(paths, joint.parent, joint.name)
        assert np.max(np.abs(gap - result.eccentricity[:, k])) < 1e-14
    crank = _point(paths, "crank", "crank_pivot")  # the ideal ground pivot stays put
    assert np.max(np.abs(crank - _point(paths, "ground", "crank_pivot"))) < 1e-14
    assert len(paths.ground) == 2 and not paths.guides


def test_simulate_animate_writes_a_gif(tmp_path: Path, capsys: pytest.CaptureFixture[str]
                                       ) -> None:
    from PIL import Image

    gif = tmp_path / "crank.gif"
    assert main(["simulate", str(SCENE), "--t-end", "0.002", "--no-verify", "--animate",
                 str(gif)]) == 0
    assert f"wrote {gif}" in capsys.readouterr().out
    assert os.listdir(tmp_path) == ["crank.gif"]  # no temporary left beside it
    with Image.open(gif) as image:
        assert image.format == "GIF" and image.n_frames == 201


def test_animation_frames_are_limited(tmp_path: Path) -> None:
    from PIL import Image

    scene = load_mechanism_scene(SCENE).with_run(t_end=0.001)
    result = simulate_mechanism(scene)
    path = animate_mechanism(scene, result, tmp_path / "a.gif", max_frames=6)
    with Image.open(path) as image:
        assert image.n_frames == 6


def test_the_docstring_example_runs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import doctest

    from jointplay.mechanism import animate

    monkeypatch.chdir(tmp_path)  # the example writes crank.gif
    (test,) = doctest.DocTestFinder(recurse=False).find(animate.animate_mechanism,
                                                        "animate_mechanism", globs={})
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    runner.run(test)
    assert runner.summarize(verbose=False).failed == 0
    assert (tmp_path / "crank.gif").is_file()
