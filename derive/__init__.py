"""Symbolic derivation (sympy.physics.mechanics) and C emission (CasADi) of robot models.

This is the only part of jointplay that imports sympy. The runtime imports it only to derive
a model that is found nowhere (see :mod:`jointplay.store.lookup`); finding, building and
loading models that exist never import it.
"""

from __future__ import annotations

import importlib
import warnings
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from jointplay.derive.codegen import Emitted, emit, write_generated
    from jointplay.derive.symbolic import SymbolicModel, derive

__all__ = ["Emitted", "SymbolicModel", "derive", "emit", "write_generated"]

_LAZY = {"Emitted": "codegen", "emit": "codegen", "write_generated": "codegen",
         "SymbolicModel": "symbolic", "derive": "symbolic"}
# Names that moved to the sympy-free model store; kept as deprecated aliases.
_MOVED = {"model_for": "jointplay.store.lookup", "generated_folder": "jointplay.store.lookup",
          "provenance": "jointplay.store.stamp", "GENERATOR_VERSION": "jointplay.store.stamp"}


def __getattr__(name: str) -> Any:
    """Import the sympy-based modules on first use only."""
    if name in _LAZY:
        return getattr(importlib.import_module(f"jointplay.derive.{_LAZY[name]}"), name)
    if name in _MOVED:
        warnings.warn(f"jointplay.derive.{name} moved to {_MOVED[name]}.{name}",
                      DeprecationWarning, stacklevel=2)
        return getattr(importlib.import_module(_MOVED[name]), name)
    raise AttributeError(f"module 'jointplay.derive' has no attribute {name!r}")
