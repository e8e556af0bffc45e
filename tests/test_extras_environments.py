"""Each command in an environment holding only the extras it documents (README, "extras"):
the modules of every other extra are made unimportable in a fresh interpreter (a finder first
on ``sys.meta_path`` refuses them, as an environment without them would), and the command,
asked for every output it can write, either succeeds or stops before any work with one line
naming the ``pip install`` that adds what is missing (exit 1, the documented status of a
missing extra), leaving nothing behind.

The suite itself has every extra installed, so without this a command that imports an
undocumented module while writing (``control --out`` needed h5netcdf after 20 s of runs)
would pass every other test."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from jointplay.common.extras import EXTRAS

ROOT = Path(__file__).resolve().parents[1]

# The extras each command documents (README.md, the extras table).
DOCUMENTED: dict[str, tuple[str, ...]] = {
    "simulate": (), "plot": (), "compare": (), "inspect": (), "build": (), "derive": (),
    "calibrate": (), "cache": (), "bench": (),
    "identify": ("control",), "control": ("control",), "control-study": ("control",),
    "sweep": ("sweep",),
}

_RUN = """
import importlib.abc, sys
BLOCKED = {blocked!r}
class Absent(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in BLOCKED:
            raise ModuleNotFoundError(f"No module named {{name!r}}", name=name)
        return None
sys.meta_path.insert(0, Absent())
from jointplay.cli import main
code = main({argv!r})
leaked = sorted(m for m in BLOCKED if m in sys.modules)
assert not leaked, leaked
sys.exit(code)
"""


def blocked_for(extras: tuple[str, ...]) -> list[str]:
    """The modules of every extra but ``extras`` (those the kept extras install stay)."""
    kept = {m for extra in extras for m in EXTRAS[extra]}
    return sorted({m for modules in EXTRAS.values() for m in modules} - kept)


def run_with(extras: tuple[str, ...], argv: list[str], cwd: Path,
             timeout: float = 300) -> subprocess.CompletedProcess[str]:
    code = _RUN.format(blocked=blocked_for(extras), argv=argv)
    return subprocess.run([sys.executable, "-c", code], cwd=cwd, capture_output=True,
                          text=True, timeout=timeout)


def test_the_table_of_documented_extras_is_the_readme_s() -> None:
    """Every command is listed; each command named in an extra's row documents that extra."""
    from jointplay.cli import COMMANDS

    assert set(DOCUMENTED) == set(COMMANDS)
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for extra in EXTRAS:
        row = next(line for line in readme.splitlines() if line.startswith(f"| `[{extra}]`"))
        for command, extras in DOCUMENTED.items():
            assert (f"`{command}`" in row.split("|")[3]) == (extra in extras), (extra, command)


@pytest.mark.parametrize(("argv", "extra"), [
    (["identify", "--out", "m", "--quiet"], "control"),
    (["control", "--model", "m", "--out", "c.h5", "--plot", "p", "--quiet"], "control"),
    (["control-study", "--out", "s", "--quiet"], "control"),
    (["sweep", str(ROOT / "scenes" / "sweep_clearance.toml"), "--out", "s"], "sweep"),
])
def test_without_its_extra_a_command_stops_before_any_work(tmp_path: Path, argv: list[str],
                                                           extra: str) -> None:
    out = run_with((), argv, tmp_path)
    assert out.returncode == 1, out.stderr
    assert out.stderr.strip().splitlines() == [
        line for line in out.stderr.strip().splitlines() if line.startswith("jointplay: error:")]
    assert f"pip install 'jointplay[{extra}]'" in out.stderr, out.stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("missing", ["torch", "h5netcdf"])
def test_control_with_part_of_its_extra_stops_before_any_work(tmp_path: Path,
                                                              missing: str) -> None:
    """The [control] extra but one of its modules: control --out (a netCDF-4 file, written
    with h5netcdf) stops before loading the model, naming the module and the extra."""
    blocked = [missing, *blocked_for(("control",))]
    argv = ["control", "--model", "m", "--plot", "p", "--out", "c.h5", "--quiet"]
    out = subprocess.run([sys.executable, "-c", _RUN.format(blocked=blocked, argv=argv)],
                         cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert out.returncode == 1, out.stderr
    assert f"needs {missing}, not installed" in out.stderr, out.stderr
    assert "pip install 'jointplay[control]'" in out.stderr
    assert list(tmp_path.iterdir()) == []


def test_simulate_writes_every_output_with_the_core_alone(tmp_path: Path) -> None:
    out = run_with((), ["simulate", "--t-end", "0.02", "--compare-ideal", "--quiet", "--out",
                        "r.h5", "--csv", "r.csv", "--plot", "figures"], tmp_path)
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "r.h5").is_file() and (tmp_path / "r.csv").is_file()
    assert any((tmp_path / "figures").glob("*.png"))


@pytest.mark.slow
def test_core_commands_write_every_output_with_the_core_alone(tmp_path: Path) -> None:
    """simulate (results file, CSV, figures), plot, compare, inspect and calibrate, each with
    no extra at all: exit 0 and their files written."""
    import numpy as np

    import jointplay

    steps = [
        ["simulate", "--t-end", "0.02", "--compare-ideal", "--quiet", "--out", "r.h5", "--csv",
         "r.csv", "--plot", "figures"],
        ["simulate", "--t-end", "0.02", "--set", "friction.mu=0.2", "--quiet", "--out",
         "mu.h5"],
        ["plot", "r.h5", "--out", "plots"],
        ["compare", "r.h5", "mu.h5", "--out", "compared"],
        ["inspect", "--out", "model.md"],
    ]
    for argv in steps:
        out = run_with((), argv, tmp_path)
        assert out.returncode == 0, (argv, out.stderr)
    run = jointplay.read(tmp_path / "mu.h5")
    rows = np.column_stack([run.t, run.tip_position])[::2]
    (tmp_path / "m.csv").write_text("time,tip_x,tip_y\n" + "\n".join(
        ",".join(f"{v:.17g}" for v in row) for row in rows) + "\n", encoding="utf-8")
    scene = (ROOT / "scenes" / "paper_4dof.toml").read_text(encoding="utf-8")
    (tmp_path / "short.toml").write_text(scene.replace("t_end = 2.0 ", "t_end = 0.02 "),
                                         encoding="utf-8")
    out = run_with((), ["calibrate", "short.toml", "--measured", "m.csv", "--free",
                        "friction.mu", "--noise", "1e-6", "--out", "fit", "--quiet",
                        "--starts", "1", "--scan-points", "0", "--profile-points", "0",
                        "--grid-window", "0", "--horizon-first", "0",
                        "--valley-check-points", "0", "--no-basin-check"], tmp_path)
    assert out.returncode == 0, out.stderr
    for name in ("r.h5", "r.csv", "figures", "plots", "compared", "model.md",
                 "fit/calibration.json", "fit/report.md", "fit/fit.png"):
        assert (tmp_path / name).exists(), name


@pytest.mark.slow
def test_control_writes_every_output_with_its_extra_alone(
        tmp_path: Path, identified: tuple[Path, object, object]) -> None:
    """control with the [control] extra alone (no xarray, pandas, Dask): every output of the
    tutorial's command line, the netCDF-4 file among them."""
    model = identified[0]
    argv = ["control", "--model", str(model), "--plot", "plots", "--out", "control.h5",
            "--quiet"]
    out = run_with(("control",), argv, tmp_path, timeout=600)
    assert out.returncode in (0, 3), out.stderr  # 3: a controller diverged, reported
    assert (tmp_path / "control.h5").is_file() and any((tmp_path / "plots").iterdir())


@pytest.mark.slow
def test_sweep_writes_its_table_with_its_extra_alone(tmp_path: Path) -> None:
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('scene = "default"\n[run]\nt_end = 0.02\n'
                     '[parameters."friction.mu"]\nvalues = [0.1, 0.2]\n', encoding="utf-8")
    out = run_with(("sweep",), ["sweep", str(sweep), "--out", "s", "--workers", "0"],
                   tmp_path, timeout=600)
    assert out.returncode == 0, out.stderr
    assert any(p.suffix == ".parquet" for p in (tmp_path / "s").rglob("*"))
