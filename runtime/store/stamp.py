"""The provenance stamp of generated code, computable without sympy.

The runtime needs a model's input hash to find it (checked in, or in the cache) before it
knows whether anything must be derived; computing it must not import the derivation.
"""

from __future__ import annotations

import hashlib
from importlib.metadata import version
from importlib.util import find_spec
from pathlib import Path
from typing import Any

from jointplay.robot import canonical_json

_EMITTING_MODULES = ("codegen.py", "cylindrical.py", "deferred.py", "fixed_step.py",
                     "ideal_derivatives.py", "laws.py", "lubrication.py", "recursive.py",
                     "recursive_chain_rule.py", "recursive_jacobians.py", "slots.py",
                     "symbolic.py", "to_casadi.py", "wear.py")


def _generator_version() -> str:
    """The package version plus a hash of the modules that decide the emitted text: any
    change to the derivation or emission code changes the stamp, so stale cached models are
    never reused (inspection and package glue are left out: they do not change the C)."""
    h = hashlib.sha256()
    for path in sorted(_derive_folder() / name for name in _EMITTING_MODULES):
        h.update(path.name.encode())
        h.update(path.read_bytes())
    return f"{version('jointplay')}+{h.hexdigest()[:12]}"


def _derive_folder() -> Path:
    """Where :mod:`jointplay.derive`'s sources are, found without importing it (or sympy)."""
    spec = find_spec("jointplay.derive")
    if spec is None or not spec.submodule_search_locations:
        raise ImportError("jointplay.derive is not installed beside the runtime")
    return Path(next(iter(spec.submodule_search_locations)))


GENERATOR_VERSION = _generator_version()


def provenance(structure: dict[str, Any], formulation: str = "closed") -> dict[str, str]:
    """What the emitted text depends on, and the hash that stamps it (``formulation``: see
    :mod:`jointplay.store.formulation`)."""
    versions = {"generator": GENERATOR_VERSION, "casadi": version("casadi"),
                "sympy": version("sympy")}
    inputs = {"structure": structure, "formulation": formulation, **versions}
    return {**versions, "formulation": formulation,
            "input_hash": hashlib.sha256(canonical_json(inputs).encode()).hexdigest()}
