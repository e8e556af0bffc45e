"""Module paths of the flat layout, kept importable for a while with a DeprecationWarning.

``import jointplay.control`` still works and hands out the module's names, but warns that
the module is now :mod:`jointplay.neural.study.control_run`; so does
``import jointplay.neural.narx`` (the neural modules of the flat ``neural/`` folder, now in
its packages ``model``, ``identify``, ``control`` and ``study``; the three whose names became
those packages cannot be forwarded). The public API (``jointplay.*``) did not move; only the
private module paths did.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import importlib.util
import sys
import types
import warnings
from typing import Any

MOVED = {
    "jointplay.errors": "jointplay.common.errors",
    "jointplay.files": "jointplay.common.files",
    "jointplay.interrupts": "jointplay.common.interrupts",
    "jointplay.limits": "jointplay.common.limits",
    "jointplay.description": "jointplay.robot.description",
    "jointplay.robotio": "jointplay.robot.robotio",
    "jointplay.model": "jointplay.store.model",
    "jointplay.build": "jointplay.store.build",
    "jointplay.expressions": "jointplay.scene.expressions",
    "jointplay.output": "jointplay.results.write",
    "jointplay.export": "jointplay.results.export",
    "jointplay.contacts": "jointplay.results.contacts",
    "jointplay.plots": "jointplay.results.plots",
    "jointplay.animate": "jointplay.results.animate",
    "jointplay.narx": "jointplay.neural.model.narx",
    "jointplay.identify": "jointplay.neural.identify.pipeline",
    "jointplay.twin": "jointplay.neural.model.twin",
    "jointplay.imc": "jointplay.neural.control.imc",
    "jointplay.imc_kernel": "jointplay.neural.control.imc_kernel",
    "jointplay.control": "jointplay.neural.study.control_run",
    "jointplay.control_plots": "jointplay.neural.study.control_plots",
    "jointplay.study": "jointplay.neural.study.control_study",
    "jointplay.wear": "jointplay.results.wear",
    "jointplay.bench_effects": "jointplay.bench.effects",
    "jointplay.simulation": "jointplay.sim",
    "jointplay.plant": "jointplay.neural.model.plant",
    "jointplay.neural.narx_model": "jointplay.neural.model.narx_model",
    "jointplay.neural.narx": "jointplay.neural.model.narx",
    "jointplay.neural.scheduling": "jointplay.neural.model.scheduling",
    "jointplay.neural.inner_loop": "jointplay.neural.model.inner_loop",
    "jointplay.neural.plant": "jointplay.neural.model.plant",
    "jointplay.neural.twin": "jointplay.neural.model.twin",
    "jointplay.neural.identify_config": "jointplay.neural.identify.config",
    "jointplay.neural.excitation": "jointplay.neural.identify.excitation",
    "jointplay.neural.datasets": "jointplay.neural.identify.datasets",
    "jointplay.neural.trajectories": "jointplay.neural.identify.trajectories",
    "jointplay.neural.linear_fit": "jointplay.neural.identify.linear_fit",
    "jointplay.neural.lpv": "jointplay.neural.identify.lpv",
    "jointplay.neural.training": "jointplay.neural.identify.training",
    "jointplay.neural.evaluation": "jointplay.neural.identify.evaluation",
    "jointplay.neural.imc": "jointplay.neural.control.imc",
    "jointplay.neural.imc_kernel": "jointplay.neural.control.imc_kernel",
    "jointplay.neural.imc_settings": "jointplay.neural.control.imc_settings",
    "jointplay.neural.imc_step": "jointplay.neural.control.imc_step",
    "jointplay.neural.internal_model": "jointplay.neural.control.internal_model",
    "jointplay.neural.kernel_network": "jointplay.neural.control.kernel_network",
    "jointplay.neural.mismatch_filter": "jointplay.neural.control.mismatch_filter",
    "jointplay.neural.loop": "jointplay.neural.control.loop",
    "jointplay.neural.loop_accuracy": "jointplay.neural.control.loop_accuracy",
    "jointplay.neural.metrics": "jointplay.neural.control.metrics",
    "jointplay.neural.noise_tuning": "jointplay.neural.control.noise_tuning",
    "jointplay.neural.comparison": "jointplay.neural.study.comparison",
    "jointplay.neural.control_plots": "jointplay.neural.study.control_plots",
    "jointplay.neural.closed_loop_choice": "jointplay.neural.study.closed_loop_choice",
    "jointplay.neural.study_cases": "jointplay.neural.study.cases",
    "jointplay.neural.study_runs": "jointplay.neural.study.runs",
    "jointplay.neural.study_report": "jointplay.neural.study.report",
}


class _Forwarder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old path and loads a small module that forwards every name to the new one
    (the real module is not registered under two names: its ``__spec__`` stays its own)."""

    def find_spec(self, fullname: str, path: Any = None,
                  target: Any = None) -> importlib.machinery.ModuleSpec | None:
        if fullname not in MOVED:
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> types.ModuleType:
        new = MOVED[spec.name]
        warnings.warn(f"{spec.name} moved to {new}; import it from there",
                      DeprecationWarning, stacklevel=2)
        target = importlib.import_module(new)
        module = types.ModuleType(spec.name, target.__doc__)
        module.__getattr__ = lambda name: getattr(target, name)  # type: ignore[method-assign]
        module.__dir__ = lambda: dir(target)  # type: ignore[method-assign]
        return module

    def exec_module(self, module: types.ModuleType) -> None:
        pass


def install() -> None:
    if not any(isinstance(f, _Forwarder) for f in sys.meta_path):
        sys.meta_path.append(_Forwarder())
