"""Symbolic derivation (sympy.physics.mechanics) and C emission (CasADi) of robot models.

This is the only part of jointplay that imports sympy, and only when something is derived:
finding and loading a model that was generated before does not import it.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.derive.stamp import GENERATOR_VERSION, provenance
from jointplay.description import Robot
from jointplay.model import Model

if TYPE_CHECKING:
    from jointplay.derive.codegen import Emitted, emit, write_generated
    from jointplay.derive.symbolic import SymbolicModel, derive

__all__ = [
    "GENERATOR_VERSION",
    "Emitted",
    "SymbolicModel",
    "derive",
    "emit",
    "generated_folder",
    "model_for",
    "provenance",
    "write_generated",
]

_LAZY = {"Emitted": "codegen", "emit": "codegen", "write_generated": "codegen",
         "SymbolicModel": "symbolic", "derive": "symbolic"}


def __getattr__(name: str) -> Any:
    """Import the sympy-based modules on first use only."""
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(f"jointplay.derive.{_LAZY[name]}"), name)
    raise AttributeError(f"module 'jointplay.derive' has no attribute {name!r}")


def generated_folder(robot: Robot) -> Path:
    """A folder holding generated code for ``robot``'s structure, generating it if needed.

    Checked-in models (``jointplay.generated``) are used when their input hash matches;
    otherwise the model is derived once into the per-user cache, keyed by that hash.
    """
    from jointplay import generated
    from jointplay.build import cache_root
    from jointplay.errors import GeneratedCodeError
    from jointplay.model import read_generated

    prov = provenance(robot.structure())
    folder = generated.find(prov["input_hash"])
    if folder is not None:
        return folder
    folder = cache_root() / "models" / prov["input_hash"]
    try:
        read_generated(folder)
    except GeneratedCodeError:  # absent, half-written or damaged: (re)generate it
        from jointplay.derive.codegen import write_generated

        write_generated(robot, folder)
    return folder


def model_for(robot: Robot) -> Model:
    """Derive (or reuse), compile (or reuse) and load the model of ``robot``.

    The returned model's default parameter vector is ``robot``'s numbers.
    """
    import numpy as np

    from jointplay.model import load_model

    model = load_model(generated_folder(robot))
    model.default_parameters = np.asarray(robot.parameter_values())
    return model
