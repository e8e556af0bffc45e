"""Probes at the edges: the cache removes only what jointplay made, a build holds what it
links against, the penetration stop reads the located extremes, the plausibility stop is a
setting, and odd inputs end in jointplay's own errors (the outputs checked before the work:
tests/test_output_names.py; every limit: tests/test_limits.py).

Each probe satisfies the contract of :mod:`test_probes` (exit 0, 1, 2 or 130, one error line,
no traceback)."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from test_probes import check_contract

from jointplay.cli import main
from jointplay.store import cache
from jointplay.store.build import OWNER_NAME, build_key, compile_source

# Compiles in a fraction of a second, where any library will do.
TINY = ("/* GENERATED FILE: DO NOT EDIT.\n * model: tiny\n */\n"
        "double tiny(double x) { return 2.0 * x; }\n")
USES_TINY = ("/* GENERATED FILE: DO NOT EDIT.\n * model: uses_tiny\n */\n"
             "double tiny(double x);\ndouble twice_tiny(double x) { return tiny(tiny(x)); }\n")


def _tree(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


# ---- the cache owns only what it made --------------------------------------------------------

def test_clear_leaves_folders_jointplay_did_not_make(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    root = tmp_path / "P"
    package = root / "build" / "lib" / "pkg"
    package.mkdir(parents=True)
    (package / "mod.py").write_text("x\n")
    (root / "models" / "notes").mkdir(parents=True)
    (root / "models" / "notes" / "a.txt").write_text("mine\n")
    ours, _ = compile_source(TINY, cache=root)
    assert (ours.parent / OWNER_NAME).is_file()
    before = _tree(root / "build" / "lib") + _tree(root / "models")
    monkeypatch.setenv("JOINTPLAY_CACHE", str(root))
    code = main(["cache", "clear"])
    out, err = capsys.readouterr()
    check_contract(code, err)
    assert code == 0
    assert "removed 1 entries" in out, out
    assert not ours.parent.exists()
    assert f"not jointplay's, left: {root / 'build' / 'lib'}" in out
    assert f"not jointplay's, left: {root / 'models' / 'notes'}" in out
    assert _tree(root / "build" / "lib") + _tree(root / "models") == before
    assert not (root / "build" / "lib" / ".lock").exists()


@pytest.mark.parametrize("action", [["clear"], ["prune", "--older-than", "0s"],
                                    ["prune", "--max-size", "0"]])
def test_clear_and_prune_never_follow_links(tmp_path: Path, action: list[str],
                                            capsys: pytest.CaptureFixture[str],
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """A link where an entry lives (even to a folder that looks like an entry, owner file and
    all), and ``build`` itself a link: nothing behind them is removed or written into."""
    root = tmp_path / "c"
    ours, _ = compile_source(TINY, cache=root)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "precious.txt").write_text("keep\n")
    (elsewhere / OWNER_NAME).write_text("forged\n")
    (root / "build" / "linked").symlink_to(elsewhere)
    (root / "models").symlink_to(elsewhere)
    monkeypatch.setenv("JOINTPLAY_CACHE", str(root))
    code = main(["cache", *action])
    out, err = capsys.readouterr()
    check_contract(code, err)
    assert code == 0, err
    assert "removed 1 entries" in out and not ours.parent.exists()
    assert sorted(p.name for p in elsewhere.iterdir()) == [OWNER_NAME, "precious.txt"]
    assert (root / "build" / "linked").is_symlink() and (root / "models").is_symlink()
    assert f"not jointplay's, left: {root / 'build' / 'linked'}" in out
    assert f"not jointplay's, left: {root / 'models'}" in out


def test_prune_with_a_size_of_400_digits_keeps_everything(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    root = tmp_path / "c"
    ours, _ = compile_source(TINY, cache=root)
    monkeypatch.setenv("JOINTPLAY_CACHE", str(root))
    code = main(["cache", "prune", "--max-size", "9" * 400])
    out, err = capsys.readouterr()
    check_contract(code, err)
    assert code == 0 and "removed 0 entries" in out and ours.exists()
    assert cache.parse_size("1" + "0" * 399 + "K") == 10 ** 399 * 1024
    code = main(["cache", "prune", "--max-size", "9" * 5000])
    check_contract(code, capsys.readouterr().err)
    assert code == 2


_SLOW_LINKER = """#!{python}
import os, sys, time
# Any call that links against a cached library signals, then waits before linking.
if any(arg.endswith("/model.so") for arg in sys.argv[1:]):
    open({signal!r}, "w").close()
    time.sleep(4.0)
os.execv({gcc!r}, [{gcc!r}, *sys.argv[1:]])
"""


def test_clear_during_a_build_keeps_the_library_it_links_against(tmp_path: Path) -> None:
    """Two processes: one builds a library linked against a cached one (as a model's first
    deferred compile does), the other clears the cache meanwhile. The build succeeds, the
    library it links against is kept (in use), and the clear removes it once the build ends."""
    import shutil

    root = tmp_path / "c"
    eager, _ = compile_source(TINY, cache=root)
    tools = tmp_path / "bin"
    tools.mkdir()
    signal = tmp_path / "linking"
    gcc = shutil.which("gcc")
    gcc = gcc and os.path.realpath(gcc)
    assert gcc is not None
    wrapper = tools / "gcc"
    wrapper.write_text(_SLOW_LINKER.format(python=sys.executable, signal=str(signal), gcc=gcc))
    wrapper.chmod(0o755)
    code = textwrap.dedent(f"""
        from pathlib import Path
        from jointplay.store.build import compile_source
        lib, _ = compile_source({USES_TINY!r}, cache=Path({str(root)!r}),
                                libraries=({str(eager)!r},))
        print(lib)
    """)
    env = {**os.environ, "PATH": f"{tools}:{os.environ['PATH']}"}
    builder = subprocess.Popen([sys.executable, "-c", code], env=env, text=True,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        for _ in range(600):
            if signal.exists() or builder.poll() is not None:
                break
            import time
            time.sleep(0.05)
        assert signal.exists(), builder.communicate()
        removed, busy = cache.clear(root)
        assert eager.parent in [e.path for e in busy]
        assert eager.exists()
        out, err = builder.communicate(timeout=120)
    finally:
        if builder.poll() is None:
            builder.kill()
            builder.wait()
    assert builder.returncode == 0, err
    assert Path(out.strip()).exists()
    removed, busy = cache.clear(root)
    assert busy == [] and not eager.exists()
    assert build_key(TINY) in {e.key for e in removed}


# ---- the penetration stop reads the located deepest points -----------------------------------

def _paper(tmp: Path, **replace: str) -> Path:
    from test_probes import paper_scene

    return paper_scene(tmp, **replace)


SPIN3 = {"q3 = 0.0": "q3 = 0.0\ndq3 = 800.0", "t_end = 2.0 ": "t_end = 0.05 "}


@pytest.mark.parametrize("output_step", ["0.01", "0.001"])
def test_penetration_stop_does_not_depend_on_the_output_step(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], output_step: str) -> None:
    """dq3 = 800 rad/s drives joint 3's journal 0.33 mm (3.3 % of its radius) into its
    bearing between two 10 ms samples: the stop reads the located deepest point, so the
    verdict and the time it names are the same at either output step; nothing is written."""
    scene = _paper(tmp_path, **SPIN3)
    out = tmp_path / "run.h5"
    code = main(["simulate", str(scene), "--output-step", output_step, "--out", str(out),
                 "--no-verify", "--quiet"])
    err = capsys.readouterr().err
    check_contract(code, err)
    assert code == 1, err
    assert "at t = 0.000127" in err and "at joint 3" in err, err
    assert "located: the deepest point of a contact phase" in err, err
    assert not out.exists() and list(tmp_path.iterdir()) == [scene]


def test_penetration_stop_at_the_default_output_step(tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    scene = _paper(tmp_path, **{"q3 = 0.0": "q3 = 0.0\ndq2 = 500.0"})
    code = main(["simulate", str(scene), "--out", str(tmp_path / "run.h5"), "--no-verify",
                 "--quiet"])
    err = capsys.readouterr().err
    check_contract(code, err)
    assert code == 1 and "penetrated its bearing" in err and "located" in err, err
    assert not (tmp_path / "run.h5").exists()


# ---- the plausibility stop as a setting ------------------------------------------------------

def test_plausibility_warn_keeps_the_run_marked(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    """--plausibility warn: exit 0, one warning line naming what the stop would have said,
    the summary and the results file say the run is implausible."""
    import jointplay

    scene = _paper(tmp_path, **SPIN3)
    out = tmp_path / "run.h5"
    code = main(["simulate", str(scene), "--output-step", "0.01", "--out", str(out),
                 "--no-verify", "--plausibility", "warn"])
    captured = capsys.readouterr()
    check_contract(code, captured.err)
    assert code == 0, captured.err
    warned = [line for line in captured.err.splitlines() if "warning" in line]
    assert len(warned) == 1 and warned[0].startswith("jointplay: warning: implausible run "
                                                     "kept"), captured.err
    assert "penetrated its bearing" in warned[0] and "at joint 3" in warned[0]
    assert "IMPLAUSIBLE" in captured.out
    back = jointplay.read(out)
    assert back.implausible is not None and "penetrated its bearing" in back.implausible
    # off: no check, no warning, no mark
    out.unlink()
    code = main(["simulate", str(scene), "--output-step", "0.01", "--out", str(out),
                 "--no-verify", "--quiet", "--set", "run.plausibility=off"])
    err = capsys.readouterr().err
    check_contract(code, err)
    assert code == 0 and err == "", err
    assert jointplay.read(out).implausible is None


def test_plausibility_in_the_scene_is_validated(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    from test_probes import bad_input

    scene = _paper(tmp_path, **{"integrator = \"bdf\"":
                                "integrator = \"bdf\"\nplausibility = \"warnn\""})
    bad_input(capsys, ["simulate", str(scene)], "run.plausibility", "stop, warn, off",
              "'warn'")
    bad_input(capsys, ["simulate", "--set", "run.plausibility=maybe"],
              "--set run.plausibility", "stop, warn, off")
    with pytest.raises(SystemExit) as refused:  # argparse's own refusal of a choice
        main(["simulate", "--plausibility", "sometimes"])
    assert refused.value.code == 2
    assert "--plausibility: invalid choice" in capsys.readouterr().err


def test_energy_balance_check_follows_the_setting() -> None:
    """At rtol 1e-3 the paper scene's energy balance stops closing (1 % of its largest
    energy): the default raises, warn returns the result with one warning, off is silent.
    A warned result is otherwise the very run the stop would have refused."""
    import warnings

    import numpy as np

    import jointplay
    from jointplay.sim.plausibility import PlausibilityWarning

    scene = jointplay.default_scene().with_run(rtol=1e-3)
    with pytest.raises(jointplay.SimulationError, match="energy balance no longer closes"):
        jointplay.simulate(scene)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warned = jointplay.simulate(scene, plausibility="warn")
    assert [w.category for w in caught] == [PlausibilityWarning]
    assert warned.implausible is not None
    assert "energy balance no longer closes" in warned.implausible
    assert warned.metadata["run"]["plausibility"] == "warn"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        off = jointplay.simulate(scene.with_run(plausibility="off"))
    assert off.implausible is None
    np.testing.assert_array_equal(off.q, warned.q)


def test_tolerance_hint_quotes_the_defaults() -> None:
    import jointplay
    from jointplay.scene.definition import RunSettings

    scene = jointplay.default_scene().with_run(rtol=1e-2, atol=1.0)
    with pytest.raises(jointplay.SimulationError) as caught:
        jointplay.simulate(scene)
    text = str(caught.value)
    assert f"the defaults are {RunSettings.rtol:g} and {RunSettings.atol:g}" in text, text


# ---- a missing extra names exactly what is missing ---------------------------------------------

@pytest.mark.parametrize(("absent", "call", "named"), [
    (("pandas",), "to_pandas", "pandas"),
    (("xarray",), "to_xarray", "xarray"),
    (("xarray", "pandas"), "to_xarray", "xarray, pandas"),
])
def test_missing_extra_names_exactly_the_missing(monkeypatch: pytest.MonkeyPatch,
                                                 absent: tuple[str, ...], call: str,
                                                 named: str) -> None:
    import pandas

    import jointplay
    from jointplay.common.extras import MissingExtra

    result = jointplay.simulate(jointplay.default_scene().with_run(t_end=0.01))
    for module in absent:
        monkeypatch.setitem(sys.modules, module, None)
    target = result.impacts if call == "to_pandas" else result
    with pytest.raises(MissingExtra) as caught:
        getattr(target, call)()
    assert f"{call}() needs {named}, not installed" in str(caught.value)
    if call == "to_pandas":  # without xarray, pandas alone is enough
        monkeypatch.setitem(sys.modules, "pandas", pandas)
        monkeypatch.setitem(sys.modules, "xarray", None)
        assert len(result.impacts.to_pandas()) == len(result.impacts)


# ---- tracebacks and statuses ------------------------------------------------------------------

def test_huge_numbers_and_short_vectors_are_named() -> None:
    import jointplay
    from jointplay.common.errors import DescriptionError

    scene = jointplay.default_scene().with_run(t_end=0.01)
    with pytest.raises(DescriptionError, match=r"initial\.q2: must be a finite number"):
        scene.with_initial(q2=10**400)
    with pytest.raises(DescriptionError, match=r"parameters: has 2 numbers; the model has"):
        jointplay.simulate(scene, parameters=[1.0, 2.0])
    with pytest.raises(DescriptionError, match=r"friction\.mu: must be a finite number"):
        jointplay.simulate(scene, parameters={"friction.mu": 10**400})


def test_restitution_range_and_eccentricity_within_the_clearance(
        capsys: pytest.CaptureFixture[str]) -> None:
    from test_probes import bad_input

    import jointplay
    from jointplay.common.errors import DescriptionError
    from jointplay.common.limits import MIN_RESTITUTION

    bad_input(capsys, ["simulate", "--set", "contact.restitution=1e-300"],
              "--set contact.restitution", f"from {MIN_RESTITUTION:g} to 1")
    scene = jointplay.default_scene()
    joint = scene.robot.joints[1]
    c = joint.bearing_radius - joint.journal_radius
    assert scene.with_initial(ex2=c).initial["ex2"] == c  # on the wall: inside
    assert scene.with_initial(ex2=1.05 * c).initial["ex2"] == 1.05 * c  # pressed in, elastic
    with pytest.raises(DescriptionError, match="must start inside its bearing"):
        scene.with_initial(ex2=1.5 * c)  # 15 um into the wall


def test_clearance_is_a_parameter_alias(capsys: pytest.CaptureFixture[str]) -> None:
    """jointN.clearance sets the radial clearance with the bearing radius held, through
    --set and the API alike; a joint without play and a typo are named."""
    from test_probes import bad_input

    import jointplay

    scene = jointplay.default_scene().with_run(t_end=0.01)
    result = jointplay.simulate(scene, parameters={"joint2.clearance": 2e-5})
    bearing = scene.robot.joints[1].bearing_radius
    assert result.radial_clearance[0] == pytest.approx(2e-5, rel=1e-9)
    index = result.parameter_names.index("joint2.journal_radius")
    assert result.parameters[index] == bearing - 2e-5
    assert main(["simulate", "--t-end", "0.01", "--no-verify", "--quiet", "--set",
                 "joint2.clearance=2e-5"]) == 0
    bad_input(capsys, ["simulate", "--set", "joint2.clearanc=2e-5"], "--set joint2.clearanc",
              "did you mean 'joint2.clearance'")
    bad_input(capsys, ["simulate", "--set", "joint1.clearance=2e-5"], "--set joint1.clearance",
              "has no clearance")
    bad_input(capsys, ["simulate", "--set", "joint2.clearance=0.02"], "--set joint2.clearance",
              "between 0 and the bearing radius")


@pytest.mark.parametrize(("q2", "q3", "payload"), [(-1.5707963267948966, 0.0, 2.0),
                                                   (-1.5707963267948966, 1.0, 2.0),
                                                   (0.3, 0.0, 2.0), (-2.0, 0.5, 2.0)])
def test_resting_journals_are_solved_in_any_pose(q2: float, q3: float, payload: float) -> None:
    """Each journal rests where its contact force carries the weight beyond it: every
    acceleration of the state found is below the solver's tolerance, and the journal sits
    against its bearing in the direction of gravity (a few micrometres of the 30 um play
    plus a sub-micrometre elastic penetration)."""
    import numpy as np

    import jointplay
    from jointplay.sim.equilibrium import TOLERANCE, static_equilibrium
    from jointplay.sim.problem import _parameter_vector

    scene = jointplay.default_scene().with_initial(q2=q2, q3=q3)
    model = jointplay.load_scene_model(scene)
    p = _parameter_vector(model, scene, {"payload.mass": payload})
    x0 = np.zeros(model.n_state)
    x0[:2] = q2, q3
    clearances = {j: 3e-5 for j in model.clearance_joints}
    x, tau = static_equilibrium(model, p, x0, clearances)
    accelerations = np.asarray(model.forward_dynamics(x, tau, p)).ravel()[model.n_coordinates:]
    assert np.max(np.abs(accelerations)) < TOLERANCE * 9.81
    for k in range(len(model.clearance_joints)):
        ex, ey = x[2 + 2 * k], x[3 + 2 * k]
        assert abs(ex) < 1e-12 and 0.0 < -ey - 3e-5 < 1e-6


def test_resting_without_a_drive_is_refused_before_compiling() -> None:
    from dataclasses import replace

    import jointplay
    from jointplay.common.errors import DescriptionError

    scene = jointplay.default_scene()
    robot = replace(scene.robot, drive=False)
    undriven = replace(scene, robot=robot, torques=(), torque_text={})
    with pytest.raises(DescriptionError, match=r"initial\.journals: \"resting\" holds the arm"):
        undriven.with_journals("resting")


@pytest.mark.slow
def test_ctrl_c_as_a_command_finishes_is_never_a_traceback(tmp_path: Path) -> None:
    """SIGINT at moments spread over the end of a short command (its last 30 % and the
    interpreter's shutdown): exit 0 (it had finished) or 130 with its one line; never a
    traceback, never death by the signal."""
    import signal
    import time

    argv = [sys.executable, "-m", "jointplay.cli", "cache", "list"]
    env = {**os.environ, "JOINTPLAY_CACHE": str(tmp_path / "c")}
    start = time.perf_counter()
    subprocess.run(argv, env=env, capture_output=True, check=True)
    duration = time.perf_counter() - start
    for fraction in (0.7, 0.8, 0.9, 0.95, 1.0, 1.05):
        proc = subprocess.Popen(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True)
        time.sleep(duration * fraction)
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=120)
        assert "Traceback" not in err, err
        assert proc.returncode in (0, 130), (fraction, proc.returncode, err)
        if proc.returncode == 130:
            assert err.strip().endswith("jointplay: interrupted"), err


def test_resting_too_deep_is_refused_before_compiling_and_the_estimate_is_the_solution(
        ) -> None:
    """A payload of 1e5 kg would rest joint 2's journal 233 um into its bearing (2.3 % of its
    radius): refused when the scene is made, before any model exists. The closed-form Hertz
    estimate behind the refusal agrees with the Newton solution of the static equilibrium
    to 0.1 % at 1e4 kg, where the run is allowed."""
    import numpy as np

    import jointplay
    from jointplay.common.errors import DescriptionError
    from jointplay.robot import with_parameters
    from jointplay.sim.equilibrium import static_equilibrium
    from jointplay.sim.problem import _parameter_vector

    scene = jointplay.default_scene()
    heavy = with_parameters(scene.robot, {"payload.mass": 1e5})
    with pytest.raises(DescriptionError, match=r"joint 2's journal would rest 232\.\d um"):
        scene.with_robot(heavy).with_journals("resting")
    kept = scene.with_run(plausibility="warn").with_robot(heavy).with_journals("resting")
    assert kept.journals == "resting"
    model = jointplay.load_scene_model(scene)
    p = _parameter_vector(model, scene, {"payload.mass": 1e4})
    x0 = np.zeros(model.n_state)
    x0[0] = -np.pi
    joint = scene.robot.joints[1]
    c = joint.bearing_radius - joint.journal_radius
    x, _ = static_equilibrium(model, p, x0, {2: c, 3: c})
    solved = -x[3] - c  # joint 2 rests straight down
    links = scene.robot.links[1:]
    weight = 9.81 * (sum(link.mass for link in links) + 1e4)
    soft = 2 * (1 - joint.bearing_nu ** 2) / joint.bearing_E
    stiffness = 4 / (3 * soft) * np.sqrt(joint.bearing_radius * joint.journal_radius / c)
    assert solved == pytest.approx((weight / stiffness) ** (1 / 1.5), rel=1e-3)


def test_a_sweep_keeps_and_marks_implausible_cases(tmp_path: Path) -> None:
    """A sweep with [run] plausibility = "warn": a case driven through its bearing is an ok
    row marked in the implausible column, the plausible one is unmarked."""
    from jointplay.sweep import load_sweep, run_sweep

    scene = _paper(tmp_path, **{"t_end = 2.0 ": "t_end = 0.01 "})
    sweep_file = tmp_path / "sweep.toml"
    sweep_file.write_text(f'scene = "{scene.name}"\n[run]\nplausibility = "warn"\n'
                          '[parameters."payload.mass"]\nvalues = [2.0, 1e5]\n',
                          encoding="utf-8")
    sweep = load_sweep(sweep_file)
    result = run_sweep(sweep, tmp_path / "out", workers=0, plots=False)
    import pyarrow.parquet as pq

    table = pq.read_table(result.path).to_pylist()
    marks = {row["payload.mass"]: (row["status"], row["implausible"]) for row in table}
    assert marks[2.0] == ("ok", None)
    assert marks[1e5][0] == "ok" and "penetrated its bearing" in marks[1e5][1]
