"""Find, build and load the model of a robot, without sympy unless something must be derived.

A model is found by the hash of its structure and generator (:mod:`.stamp`): first among the
checked-in models (:mod:`jointplay.generated`), then in the per-user cache. Only a model found
nowhere (or a damaged cached one) is derived, and that is the one place the runtime imports
:mod:`jointplay.derive`.
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path

import numpy as np

from jointplay import generated
from jointplay.common.errors import FileError, GeneratedCodeError
from jointplay.robot import Robot
from jointplay.store.build import (
    cache_error,
    cache_root,
    claim_entry,
    entry_lock,
    remove_temporaries,
)
from jointplay.store.formulation import formulation_for
from jointplay.store.model import Model, check_generated, load_model, note
from jointplay.store.stamp import provenance


def generated_folder(robot: Robot) -> Path:
    """A folder holding generated code for ``robot``'s structure, generating it if needed.

    Checked-in models are used when their input hash matches; otherwise the model is derived
    once into the per-user cache, keyed by that hash. A cached folder that does not load (a
    damaged file, a half-written one) is generated again, with a one-line note, under a lock so
    that concurrent runs repair it once.

    Parameters
    ----------
    robot : Robot
        The robot; only its structure matters.

    Returns
    -------
    pathlib.Path
        The generated folder.
    """
    structure = robot.structure()
    prov = provenance(structure.as_dict(), formulation_for(structure))
    folder = generated.find(prov["input_hash"])
    if folder is not None:
        return folder
    folder = cache_root() / "models" / prov["input_hash"]
    if _damage(folder) is None:
        with contextlib.suppress(OSError):  # last used now (`jointplay cache prune`)
            os.utime(folder)
        return folder
    _regenerate(robot, folder)
    return folder


def model_for(robot: Robot) -> Model:
    """Find (or derive), compile (or reuse) and load the model of ``robot``.

    Parameters
    ----------
    robot : Robot
        The robot.

    Returns
    -------
    Model
        The loaded model; its default parameter vector is ``robot``'s numbers.
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
    fresh = not folder.exists()
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with entry_lock(folder):
            damage = _damage(folder)  # another process may have repaired it meanwhile
            if damage is None:
                return
            remove_temporaries(folder)  # under the lock: left by killed runs
            claim_entry(folder)  # jointplay writes it: `jointplay cache clear` may remove it
            if not (folder / "layout.json").exists() and not (folder / "model.c").exists():
                damage = "absent"
            if damage != "absent":
                reason = damage.splitlines()[0].split("; regenerate")[0]
                reason = reason.replace(f"{folder}/", "").replace(f"{folder}: ", "")
                note(f"the cached model {folder} does not load ({reason}); generating it again")
            say_deriving(robot)
            # The one import of the derivation (and of sympy) on the runtime's side.
            from jointplay.derive.codegen import write_generated

            write_generated(robot, folder)
    except BaseException as err:
        _discard_failed(folder, fresh)
        if isinstance(err, OSError | FileError):
            raise cache_error(folder, err) from None
        raise


# Seconds to derive and emit a model with sympy, for the estimate said before a derivation:
# about DERIVE_BASE_S (importing sympy and CasADi) and DERIVE_S_PER_COORDINATE more per
# generalised coordinate (the paper robot's ideal twin, 4 coordinates: 1.4 s; README "Build
# times": 12 clearance joints, 36 coordinates, 7.6 s with gcc).
DERIVE_BASE_S = 1.0
DERIVE_S_PER_COORDINATE = 0.2


def say_deriving(robot: Robot) -> None:
    """Say on stderr which model is derived now, and about how long it takes."""
    import sys

    from jointplay.robot.structure import coordinate_layout

    structure = robot.structure()
    coordinates = len(coordinate_layout(structure))
    seconds = DERIVE_BASE_S + DERIVE_S_PER_COORDINATE * coordinates
    kinds = ", ".join(structure.joints)
    print(f"jointplay: deriving the model of {structure.links} links (joints: {kinds}; "
          f"{coordinates} coordinates) with sympy: about {max(1, round(seconds))} s, once "
          "(then cached)", file=sys.stderr, flush=True)


def _discard_failed(folder: Path, fresh: bool) -> None:
    """A derivation that failed (a full disk, Ctrl-C) leaves no half-written model: the
    folder is removed if this run made it and no other run has completed it meanwhile."""
    import contextlib
    import shutil

    with contextlib.suppress(OSError), entry_lock(folder, blocking=False) as held:
        if held and fresh and _damage(folder) is not None:
            shutil.rmtree(folder)
