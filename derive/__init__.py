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
    otherwise the model is derived once into the per-user cache, keyed by that hash. A cached
    folder that does not load (a damaged file, a half-written one) is generated again, with a
    one-line note, under a lock so that concurrent runs repair it once.
    """
    from jointplay import generated
    from jointplay.build import cache_root

    prov = provenance(robot.structure())
    folder = generated.find(prov["input_hash"])
    if folder is not None:
        return folder
    folder = cache_root() / "models" / prov["input_hash"]
    if _damage(folder) is None:
        return folder
    _regenerate(robot, folder)
    return folder


def _damage(folder: Path) -> str | None:
    """Why the generated folder does not load ("absent" if it does not exist), or None."""
    from jointplay.errors import GeneratedCodeError
    from jointplay.model import check_generated

    if not folder.exists():
        return "absent"
    try:
        check_generated(folder)
    except GeneratedCodeError as err:
        return str(err)
    return None


def _regenerate(robot: Robot, folder: Path) -> None:
    import fcntl

    from jointplay.build import cache_error
    from jointplay.errors import FileError
    from jointplay.files import sweep_stale
    from jointplay.model import note

    try:
        folder.mkdir(parents=True, exist_ok=True)
        with open(folder / ".lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            damage = _damage(folder)  # another process may have repaired it meanwhile
            if damage is None:
                return
            sweep_stale(folder)
            if not (folder / "layout.json").exists() and not (folder / "model.c").exists():
                damage = "absent"
            if damage != "absent":
                reason = damage.splitlines()[0].split("; regenerate")[0]
                reason = reason.replace(f"{folder}/", "").replace(f"{folder}: ", "")
                note(f"the cached model {folder} does not load ({reason}); generating it again")
            from jointplay.derive.codegen import write_generated

            write_generated(robot, folder)
    except (OSError, FileError) as err:
        raise cache_error(folder, err) from None


def model_for(robot: Robot) -> Model:
    """Derive (or reuse), compile (or reuse) and load the model of ``robot``.

    The returned model's default parameter vector is ``robot``'s numbers.
    """
    import numpy as np

    from jointplay.model import load_model

    model = load_model(generated_folder(robot))
    model.default_parameters = np.asarray(robot.parameter_values())
    return model
