"""Every limit of :mod:`jointplay.common.limits` is enforced by code: one probe per constant,
just past it, through the door a user meets it by. A constant added there without a probe
here fails :func:`test_every_limit_has_a_probe`.

Input limits refuse before any work (exit 2, naming the field); the two run-time stops end the
run (exit 1) and write nothing."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

import pytest
from test_probes import check_contract, paper_scene

from jointplay.cli import main
from jointplay.common import limits

Probe = Callable[[Path], tuple[list[str], int, str]]  # folder -> (argv, exit status, field)


def _scene(tmp: Path, **replace: str) -> str:
    return str(paper_scene(tmp, **replace))


def _sweep(tmp: Path, body: str) -> str:
    path = tmp / "sweep.toml"
    path.write_text('scene = "default"\n' + body, encoding="utf-8")
    return str(path)


def _big_scene(tmp: Path) -> list[str]:
    path = tmp / "big.toml"
    text = paper_scene(tmp).read_text(encoding="utf-8")
    path.write_text(text + "#" * (limits.MAX_TOML_BYTES - len(text.encode()) + 1) + "\n",
                    encoding="utf-8")
    return ["simulate", str(path)]


def _nested_scene(tmp: Path) -> list[str]:
    depth = limits.MAX_TOML_NESTING + 1
    path = paper_scene(tmp, **{"[run]": f"[run]\nnested = {'[' * depth}1{']' * depth}"})
    return ["simulate", str(path)]


def _big_table(tmp: Path) -> list[str]:
    """A torque table one byte over the limit: a sparse file (no disk used), which must be
    refused from its size, before a byte of it is read."""
    table = tmp / "torques.csv"
    with open(table, "wb") as fh:
        fh.write(b"t,joint2,joint3\n0,0,0\n")
        fh.truncate(limits.MAX_TABLE_BYTES + 1)
    scene = paper_scene(tmp, **{'joint2 = "4*sin(2*pi*t)"\njoint3 = "2*sin(2*pi*t)"':
                                'table = "torques.csv"'})
    return ["simulate", str(scene)]


def _identify(*flags: str) -> Probe:
    return lambda tmp: (["identify", "--out", str(tmp / "m"), *flags], 2, flags[0])


def _calibrate(tmp: Path, row: str, *flags: str) -> list[str]:
    """calibrate on the short paper scene, the measured file's second row ``row``."""
    scene = _scene(tmp, **{"t_end = 2.0 ": "t_end = 0.02 "})
    measured = tmp / "m.csv"
    measured.write_text(f"time,tip_x\n0.0,0.1\n{row}\n0.002,0.1\n", encoding="utf-8")
    return ["calibrate", scene, "--measured", str(measured), "--free", "friction.mu", "--out",
            str(tmp / "cal"), *flags]


PROBES: dict[str, Probe] = {
    "MAX_T_END": lambda tmp: (["simulate", "--t-end", f"{limits.MAX_T_END * 10:g}"], 2,
                              "--t-end"),
    "MIN_OUTPUT_STEP": lambda tmp: (["simulate", "--output-step",
                                     f"{limits.MIN_OUTPUT_STEP / 10:g}"], 2, "--output-step"),
    "MAX_OUTPUTS": lambda tmp: (["simulate", "--t-end", "1", "--output-step",
                                 f"{1 / (limits.MAX_OUTPUTS * 2):g}"], 2, "--output-step"),
    "MIN_STEP": lambda tmp: (["simulate", "--integrator", "rk4", "--step",
                              f"{limits.MIN_STEP / 10:g}"], 2, "--step"),
    "MAX_FIXED_STEPS": lambda tmp: (["simulate", "--integrator", "rk4", "--t-end", "10",
                                     "--step", f"{limits.MIN_STEP:g}"], 2, "--step"),
    "MAX_MAX_STEPS": lambda tmp: (["simulate", "--set",
                                   f"run.max_steps={limits.MAX_MAX_STEPS + 1}"], 2,
                                  "--set run.max_steps"),
    "MIN_RTOL": lambda tmp: (["simulate", "--rtol", f"{limits.MIN_RTOL / 10:g}"], 2, "--rtol"),
    "MIN_ATOL": lambda tmp: (["simulate", "--atol", f"{limits.MIN_ATOL / 10:g}"], 2, "--atol"),
    "MAX_TOML_BYTES": lambda tmp: (_big_scene(tmp), 2, "scene"),
    "MAX_TOML_NESTING": lambda tmp: (_nested_scene(tmp), 2, "(toml)"),
    "MAX_TABLE_BYTES": lambda tmp: (_big_table(tmp), 2, "torques.table"),
    "MAX_CASES": lambda tmp: (["sweep", _sweep(tmp, '[parameters."friction.mu"]\nstart = 0.0\n'
                                               f'stop = 0.2\nnum = {limits.MAX_CASES + 1}\n'),
                               "--out", str(tmp / "o")], 2, "parameters.friction.mu.num"),
    "MAX_WORKERS": lambda tmp: (["sweep", _sweep(tmp, '[parameters."friction.mu"]\n'
                                                 'values = [0.0, 0.1]\n'), "--out",
                                 str(tmp / "o"), "--workers", str(limits.MAX_WORKERS + 1)],
                                2, "--workers"),
    "MAX_TRAJECTORIES": _identify("--train", str(limits.MAX_TRAJECTORIES + 1)),
    "MAX_IDENTIFY_SAMPLES": _identify("--duration", "1e4"),
    "MAX_LAGS": _identify("--lags", f"{limits.MAX_LAGS + 1},2"),
    "MAX_HIDDEN_WIDTH": _identify("--hidden", str(limits.MAX_HIDDEN_WIDTH + 1)),
    "MAX_HIDDEN_LAYERS": _identify("--hidden", ",".join(["4"] * (limits.MAX_HIDDEN_LAYERS + 1))),
    "MAX_ITERATIONS": _identify("--iterations", str(limits.MAX_ITERATIONS + 1)),
    "MIN_WINDOW": _identify("--window", str(limits.MIN_WINDOW - 1)),
    "MAX_WINDOW": _identify("--window", str(limits.MAX_WINDOW + 1)),
    "MAX_MEASURED": lambda tmp: (_calibrate(tmp, f"0.001,{limits.MAX_MEASURED * 2:g}"), 2,
                                 "row 3 column tip_x"),
    "MIN_NOISE": lambda tmp: (_calibrate(tmp, "0.001,0.1", "--noise",
                                         f"{limits.MIN_NOISE / 2:g}"), 2, "--noise"),
    "MAX_CALIBRATION_RUNS": lambda tmp: (_calibrate(
        tmp, "0.001,0.1", "--scan-points", str(limits.MAX_CALIBRATION_RUNS + 1)), 2,
        "--scan-points"),
    "MIN_RADIAL_CLEARANCE": lambda tmp: (["simulate", "--set", "joint2.clearance="
                                          f"{limits.MIN_RADIAL_CLEARANCE / 2:g}"], 2,
                                         "--set joint2"),
    "MIN_RESTITUTION": lambda tmp: (["simulate", "--set", "contact.restitution=1e-300"], 2,
                                    "--set contact.restitution"),
    # the run-time stops (exit 1, nothing written)
    "MAX_PENETRATION_FRACTION": lambda tmp: (["simulate", _scene(tmp, **{
        "q3 = 0.0": "q3 = 0.0\ndq3 = 800.0", "t_end = 2.0 ": "t_end = 0.05 "}), "--out",
        str(tmp / "run.h5")], 1, "penetrated its bearing"),
    "MAX_ENERGY_RESIDUAL": lambda tmp: (["simulate", "--rtol", "1e-3", "--no-verify", "--out",
                                         str(tmp / "run.h5")], 1, "energy balance"),
}


def test_every_limit_has_a_probe() -> None:
    scalar = {name for name in limits.__all__ if name != "PHYSICAL_RANGES"}
    assert scalar == set(PROBES), (scalar ^ set(PROBES))


@pytest.mark.parametrize("name", sorted(PROBES))
def test_limit_is_enforced(name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str],
                           monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    argv, status, field = PROBES[name](tmp_path)
    before = sorted(os.listdir(tmp_path))
    code = main([*argv, "--quiet"] if argv[0] == "simulate" else argv)
    err = capsys.readouterr().err
    check_contract(code, err)
    assert code == status, err
    line = next(line for line in err.splitlines() if line.startswith("jointplay: error:"))
    assert field in line, line
    assert sorted(os.listdir(tmp_path)) == before  # nothing written


@pytest.mark.parametrize("kind", sorted(limits.PHYSICAL_RANGES))
def test_every_physical_range_is_enforced(kind: str) -> None:
    """Each kind's range refuses a number just outside it, naming the field."""
    from jointplay.common.errors import DescriptionError
    from jointplay.common.validation import plausible

    low, high, _, _ = limits.PHYSICAL_RANGES[kind]
    above = high * 1.5 if high > 0 else high / 2 + 1.0
    below = low * 1.5 if low < 0 else low / 2 if low > 0 else -1.0
    for outside in (above, below):
        with pytest.raises(DescriptionError, match=kind.replace(".", r"\.")):
            plausible(kind, outside, kind)
    plausible(kind, low, kind)
    plausible(kind, high, kind)
