"""A cold cache says what it compiles and about how long it takes, before it starts, and no
progress bar runs while it does."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from jointplay.store.build import (
    COMPILE_S_PER_BYTE,
    DEFAULT_CFLAGS,
    MARKER_NAME,
    compile_estimate,
    compile_source,
)

TINY = "double jp_tiny(double x) { return 2.0 * x; }\n"


def test_compile_estimate_from_the_cache_or_the_measured_rate(tmp_path: Path) -> None:
    size = 100_000
    assert compile_estimate(size, DEFAULT_CFLAGS, tmp_path) == pytest.approx(
        COMPILE_S_PER_BYTE["-O1"] * size, rel=1e-12)
    library, _ = compile_source(TINY, cache=tmp_path)
    marker = library.parent / MARKER_NAME
    record = json.loads(marker.read_text())
    record["seconds"] = 0.5
    marker.write_text(json.dumps(record))
    rate = 0.5 / (library.parent / "model.c").stat().st_size
    assert compile_estimate(size, DEFAULT_CFLAGS, tmp_path) == pytest.approx(rate * size,
                                                                              rel=1e-12)
    other = ("-O2", *DEFAULT_CFLAGS[1:])  # other flags: the cache has nothing to say
    assert compile_estimate(size, other, tmp_path) == pytest.approx(2e-5 * size, rel=1e-12)


def test_compile_is_announced_only_when_it_happens(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    compile_source(TINY, cache=tmp_path, what="the tiny function")
    said = capsys.readouterr().err.splitlines()
    assert len(said) == 1
    assert re.fullmatch(r"jointplay: compiling the tiny function \(0 kB of C\): about \d+ s, "
                        r"once \(then cached\)", said[0]), said
    compile_source(TINY, cache=tmp_path, what="the tiny function")  # cached: nothing said
    assert capsys.readouterr().err == ""


@pytest.mark.slow
def test_cold_cache_names_each_build_before_the_run(tmp_path: Path) -> None:
    """The main job on an empty cache: the model, the ideal twin (derived, then compiled) and
    the integrator are each named with an estimate before they are built, in that order, and
    the progress bar appears only with the integration (never beside a compile)."""
    env = {**os.environ, "JOINTPLAY_CACHE": str(tmp_path / "cache")}
    done = subprocess.run([sys.executable, "-m", "jointplay.cli", "simulate", "--t-end", "0.01",
                           "--compare-ideal", "--no-verify"], capture_output=True, text=True,
                          env=env, timeout=600)
    assert done.returncode == 0, done.stderr
    lines = done.stderr.splitlines()
    expected = [r"jointplay: compiling model 'paper_4dof' \(\d+ kB of C\): about \d+ s, once "
                r"\(then cached\)",
                r"jointplay: deriving the model of 4 links \(joints: locked, ideal, ideal, "
                r"locked; 2 coordinates\) with sympy: about \d+ s, once \(then cached\)",
                r"jointplay: compiling model 'paper_4dof_ideal' \(\d+ kB of C\): about \d+ s, "
                r"once \(then cached\)",
                r"jointplay: compiling the BDF integrator, jointplay/sim/driver.c, \(\d+ kB of "
                r"C\): about \d+ s, once \(then cached\)"]
    assert len(lines) == len(expected), lines  # nothing else: no progress bar among them
    for line, pattern in zip(lines, expected, strict=True):
        assert re.fullmatch(pattern, line), line
    assert done.stdout.startswith("scene paper_4dof: model paper_4dof ready in ")
