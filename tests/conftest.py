"""Shared fixtures and options for the jointplay test suite.

The suite builds into a temporary model cache, never the user's: ``JOINTPLAY_CACHE`` is set
before any test module is imported (subprocesses inherit it) and the folder is removed at the
end. ``JOINTPLAY_TEST_CACHE=DIR`` keeps the builds in DIR instead, to reuse them between runs.
"""

from __future__ import annotations

import os
import shutil
import signal
import tempfile
from pathlib import Path
from typing import Any

import pytest

_CACHE: dict[str, Any] = {}


def pytest_configure(config: pytest.Config) -> None:
    # The suite presses Ctrl-C at the commands it runs, in this process and in children. Run
    # as a shell's background job, it would start with SIGINT ignored, which the commands
    # (and every child, across exec) keep: give it Python's usual handler instead.
    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)
    kept = os.environ.get("JOINTPLAY_TEST_CACHE")
    root = Path(kept) if kept else Path(tempfile.mkdtemp(prefix="jointplay-test-cache-"))
    _CACHE.update(root=root, temporary=not kept, previous=os.environ.get("JOINTPLAY_CACHE"))
    os.environ["JOINTPLAY_CACHE"] = str(root)


def pytest_unconfigure(config: pytest.Config) -> None:
    if not _CACHE:
        return
    if _CACHE["previous"] is None:
        os.environ.pop("JOINTPLAY_CACHE", None)
    else:
        os.environ["JOINTPLAY_CACHE"] = _CACHE["previous"]
    if _CACHE["temporary"]:
        shutil.rmtree(_CACHE["root"], ignore_errors=True)


@pytest.fixture(scope="session")
def model_cache() -> Path:
    """The model cache of this test session (``$JOINTPLAY_CACHE`` for it and its
    subprocesses)."""
    return Path(_CACHE["root"])


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-generated", action="store_true", default=False,
                     help="rewrite the checked-in generated models instead of diffing them")


@pytest.fixture
def update_generated(request: pytest.FixtureRequest) -> bool:
    return bool(request.config.getoption("--update-generated"))


@pytest.fixture(scope="session")
def identified(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Any, Any]:
    """A small model of the default scene identified once per session: (folder, network,
    its ARX twin)."""
    pytest.importorskip("torch")
    from jointplay.neural.identify.pipeline import IdentifyConfig, identify
    from jointplay.neural.model.narx import load_narx
    from jointplay.neural.study.control_run import load_twin
    from jointplay.scene.definition import default_scene

    out = tmp_path_factory.mktemp("model")
    identify(default_scene(), out, IdentifyConfig(
        duration=1.0, n_train=6, n_validation=2, n_test=1, one_step_iterations=30,
        multi_step_iterations=10, workers=2), quiet=True)
    narx = load_narx(out)
    return out, narx, load_twin(out, narx)
