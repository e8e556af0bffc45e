"""The compile cache: keyed by what produced the build, robust to corruption and races."""

from __future__ import annotations

import json
import multiprocessing
from pathlib import Path

import numpy as np
import pytest

from jointplay import generated, load_model
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


@pytest.mark.parametrize("damage", ["truncate_library", "delete_marker", "garbage_marker",
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
