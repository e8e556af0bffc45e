"""Find, build and load the model of a robot, without sympy unless something must be derived.

A model is found by the hash of its structure and generator (:mod:`.stamp`): first among the
checked-in models (:mod:`jointplay.generated`), then in the per-user cache. Only a model found
nowhere (or a damaged cached one) is derived, and that is the one place the runtime imports
:mod:`jointplay.derive`.
"""

from __future__ import annotations

import fcntl
from pathlib import Path

import numpy as np

from jointplay import generated
from jointplay.common.errors import FileError, GeneratedCodeError
from jointplay.common.files import sweep_stale
from jointplay.robot import Robot
from jointplay.store.build import cache_error, cache_root
from jointplay.store.formulation import formulation_for
from jointplay.store.model import Model, check_generated, load_model, note
from jointplay.store.stamp import provenance


def generated_folder(robot: Robot) -> Path:
    """A folder holding generated code for ``robot``'s structure, generating it if needed.

    Checked-in models are used when their input hash matches; otherwise the model is derived
    once into the per-user cache, keyed by that hash. A cached folder that does not load (a
    damaged file, a half-written one) is generated again, with a one-line note, under a lock
    so that concurrent runs repair it once.
    """
    structure = robot.structure()
    prov = provenance(structure.as_dict(), formulation_for(structure))
    folder = generated.find(prov["input_hash"])
    if folder is not None:
        return folder
    folder = cache_root() / "models" / prov["input_hash"]
    if _damage(folder) is None:
        return folder
    _regenerate(robot, folder)
    return folder


def model_for(robot: Robot) -> Model:
    """Find (or derive), compile (or reuse) and load the model of ``robot``.

    The returned model's default parameter vector is ``robot``'s numbers.
    """
    model = load_model(generated_folder(robot))
    model.default_parameters = np.asarray(robot.parameter_values())
    return model


def _damage(folder: Path) -> str | None:
    """Why the generated folder does not load ("absent" if it does not exist), or None."""
    if not folder.exists():
        return "absent"
    try:
        check_generated(folder)
    except GeneratedCodeError as err:
        return str(err)
    return None


def _regenerate(robot: Robot, folder: Path) -> None:
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
            # The one import of the derivation (and of sympy) on the runtime's side.
            from jointplay.derive.codegen import write_generated

            write_generated(robot, folder)
    except (OSError, FileError) as err:
        raise cache_error(folder, err) from None
