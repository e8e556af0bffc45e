"""The compile cache: keyed by what produced the build, robust to corruption and races."""

from __future__ import annotations

import hashlib
import json
import multiprocessing
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from jointplay import default_scene, generated, load_model, simulate
from jointplay.store.build import (
    DEFAULT_CFLAGS,
    LIBRARY_NAME,
    MARKER_NAME,
    build_key,
    compile_source,
)

SOURCE = (generated.folders()["paper_4dof"] / "model.c").read_text()


def _entry(cache: Path) -> Path:
    return cache / "build" / build_key(SOURCE)


def test_build_is_reused_only_when_the_key_matches(tmp_path: Path) -> None:
    lib, seconds = compile_source(SOURCE, cache=tmp_path)
    assert seconds > 0 and lib.is_file()
    again, seconds_again = compile_source(SOURCE, cache=tmp_path)
    assert again == lib and seconds_again == 0.0
    other_flags = (*DEFAULT_CFLAGS, "-DJOINTPLAY_TEST_FLAG")
    assert build_key(SOURCE, other_flags) != build_key(SOURCE)
    assert build_key(SOURCE + "\n") != build_key(SOURCE)


# Two damages in the quick tier, two in the slow one (each rebuilds the library).
@pytest.mark.parametrize("damage", ["truncate_library",
                                    pytest.param("delete_marker", marks=pytest.mark.slow),
                                    pytest.param("garbage_marker", marks=pytest.mark.slow),
                                    "library_missing"])
def test_corrupt_entry_is_rebuilt(tmp_path: Path, damage: str) -> None:
    lib, _ = compile_source(SOURCE, cache=tmp_path)
    entry = _entry(tmp_path)
    if damage == "truncate_library":
        lib.write_bytes(lib.read_bytes()[:1000])
    elif damage == "delete_marker":
        (entry / MARKER_NAME).unlink()
    elif damage == "garbage_marker":
        (entry / MARKER_NAME).write_text("{not json")
    else:
        lib.unlink()
    rebuilt, seconds = compile_source(SOURCE, cache=tmp_path)
    assert seconds > 0
    marker = json.loads((entry / MARKER_NAME).read_text())
    assert marker["cflags"] == list(DEFAULT_CFLAGS)
    assert rebuilt.stat().st_size > 1000


def _build_in_child(cache: str) -> str:
    lib, _ = compile_source(SOURCE, cache=Path(cache))
    return str(lib)


def test_concurrent_builds_do_not_corrupt_each_other(tmp_path: Path) -> None:
    ctx = multiprocessing.get_context("spawn")
    with ctx.Pool(3) as pool:
        libs = pool.map(_build_in_child, [str(tmp_path)] * 3)
    assert len(set(libs)) == 1
    entry = _entry(tmp_path)
    assert sorted(p.name for p in entry.iterdir() if not p.name.startswith(".")) == sorted(
        [MARKER_NAME, LIBRARY_NAME, "model.c"])
    assert not list(entry.glob("*.part"))


def test_loaded_model_matches_casadi_reference(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """The buffer path returns what CasADi's own evaluation of the compiled function does."""
    monkeypatch.setenv("JOINTPLAY_CACHE", str(tmp_path))
    model = load_model(generated.folders()["paper_4dof"])
    assert str(model.library).startswith(str(tmp_path))
    rng = np.random.default_rng(7)
    x = rng.normal(size=model.n_state) * 1e-5
    x[:2] = rng.normal(size=2)
    p = model.parameter_vector()
    tau = rng.normal(size=2)
    vimp = np.array([0.1, 0.2])
    fast = model.forward_dynamics(x, tau, p, vimp)
    reference = np.asarray(model.casadi_function("forward_dynamics")(x, tau, p, vimp)).ravel()
    np.testing.assert_array_equal(fast, reference)
    jac = model.jacobian(x, tau, p, vimp)["x"]
    ref_jac = np.asarray(model.casadi_function("forward_dynamics").jacobian()(
        x, tau, p, vimp, 0)[0])
    np.testing.assert_allclose(jac, ref_jac, rtol=0, atol=1e-12 * np.abs(ref_jac).max())
    with pytest.raises(ValueError, match="'x' needs 12 values"):
        model.forward_dynamics(x[:5], tau, p, vimp)


@pytest.mark.slow
def test_deferred_library_is_built_on_first_use(tmp_path: Path, monkeypatch, capsys) -> None:  # type: ignore[no-untyped-def]
    """What integration never calls is compiled on its first call, once, into its own cache
    entry (keyed by its own C, stamped with the model's provenance); the full Jacobian it
    serves has the eager library's state block bit for bit and input blocks that match
    central differences of the forward dynamics."""
    monkeypatch.setenv("JOINTPLAY_CACHE", str(tmp_path))
    folder = generated.folders()["paper_4dof"]
    model = load_model(folder)
    rng = np.random.default_rng(3)
    x = rng.normal(size=model.n_state) * 1e-5
    x[:2] = rng.normal(size=2)
    p, tau, vimp = model.parameter_vector(), rng.normal(size=2), np.array([0.1, 0.2])
    state_block = model.function("jac_state")(x, tau, p, vimp)[0]
    assert model.deferred_library is None
    assert len(list((tmp_path / "build").iterdir())) == 1
    # A simulation, integration and the assembly of its outputs, never needs it either (the
    # cache gains the simulation driver's library, not the deferred one).
    simulate(default_scene().with_run(t_end=0.02), model=model)
    assert model.deferred_library is None
    capsys.readouterr()
    blocks = model.jacobian(x, tau, p, vimp)
    assert "compiling the rest of model" in capsys.readouterr().err
    deferred = model.deferred_library
    assert deferred is not None and model.deferred_compile_seconds > 0
    assert deferred.parent != model.library.parent and str(deferred).startswith(str(tmp_path))
    header = (deferred.parent / "model.c").read_text()[:1500]
    assert header.startswith("/* GENERATED FILE: DO NOT EDIT.")
    assert f"input hash: {model.layout.input_hash}" in header
    np.testing.assert_array_equal(blocks["x"], state_block)
    for _ in range(3):  # a call leaves the caller's (reused) argument arrays as it found them
        for name, block in model.jacobian(x, tau, p, vimp).items():
            np.testing.assert_array_equal(block, blocks[name], err_msg=name)
    for name, value, column_of in (("tau", tau, 0), ("p", p, 1), ("v_imp", vimp, 2)):
        args = [x, tau, p, vimp]
        for j in range(value.size):
            step = 1e-6 * max(1.0, abs(value[j]))
            up, down = value.copy(), value.copy()
            up[j] += step
            down[j] -= step
            args[column_of + 1] = up
            plus = model.forward_dynamics(*args)
            args[column_of + 1] = down
            minus = model.forward_dynamics(*args)
            central = (plus - minus) / (2 * step)
            scale = max(1.0, float(np.abs(central).max()))
            np.testing.assert_allclose(blocks[name][:, j], central, rtol=0,
                                       atol=1e-5 * scale, err_msg=f"d xdot / d {name}[{j}]")
    again = load_model(folder)  # a new process would find both libraries in the cache
    capsys.readouterr()
    np.testing.assert_array_equal(again.jacobian(x, tau, p, vimp)["p"], blocks["p"])
    assert again.deferred_library == deferred and again.deferred_compile_seconds == 0.0
    assert "compiling" not in capsys.readouterr().err
    # A deferred library in the cache that is whole and verified but does not load (here a
    # valid library without the model's functions) is compiled again, once, and then serves.
    # (Replaced by a rename, and loaded in a new process: this one has the old one mapped.)
    tiny, _ = compile_source("double tiny(double x) { return 2.0 * x; }\n",
                             cache=tmp_path / "other")
    (deferred.parent / "stand-in").write_bytes(tiny.read_bytes())
    os.replace(deferred.parent / "stand-in", deferred)
    marker_path = deferred.parent / MARKER_NAME
    marker = json.loads(marker_path.read_text())
    marker.update(sha256=hashlib.sha256(tiny.read_bytes()).hexdigest(),
                  size=tiny.stat().st_size)
    marker_path.write_text(json.dumps(marker))
    np.savez(tmp_path / "arguments.npz", x=x, tau=tau, p=p, vimp=vimp)
    code = ("import numpy as np, jointplay, sys\n"
            "from jointplay import generated\n"
            f"a = np.load({str(tmp_path / 'arguments.npz')!r})\n"
            "m = jointplay.load_model(generated.folders()['paper_4dof'])\n"
            "block = m.jacobian(a['x'], a['tau'], a['p'], a['vimp'])['p']\n"
            f"np.save({str(tmp_path / 'healed.npy')!r}, block)\n"
            "assert m.deferred_compile_seconds > 0\n")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=300, env={**os.environ, "JOINTPLAY_CACHE": str(tmp_path)})
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr.count("does not load; compiling it again") == 1, proc.stderr
    np.testing.assert_array_equal(np.load(tmp_path / "healed.npy"), blocks["p"])
