"""Shared fixtures and options for the jointplay test suite."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest


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
    from jointplay.neural.control import load_twin
    from jointplay.neural.identify import IdentifyConfig, identify
    from jointplay.neural.narx import load_narx
    from jointplay.scene.definition import default_scene

    out = tmp_path_factory.mktemp("model")
    identify(default_scene(), out, IdentifyConfig(
        duration=1.0, n_train=6, n_validation=2, n_test=1, one_step_iterations=30,
        multi_step_iterations=10, workers=2), quiet=True)
    narx = load_narx(out)
    return out, narx, load_twin(out, narx)
