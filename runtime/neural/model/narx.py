"""NARX model folders: a model written and read (``narx.json``, and its linear twin
``arx.json``), and the robot it must be used with.

The model itself (its equations, evaluation and checksum) is in jointplay.neural.model.narx_model;
its names are importable from here as well. The file format is described in
``docs/control.md``; every number is written with ``repr`` precision, so a load gives back the
trained float64 weights exactly, and a checksum over the content catches edits and corruption.
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_write_text
from jointplay.neural.model.narx_model import (
    ACTIVATIONS,
    FORMAT,
    FORMAT_VERSION,
    Narx,
    fit_percent,
    nrmse,
)
from jointplay.neural.model.narx_model import _checksum as _checksum  # as before: tests import it

MODEL_FILE = "narx.json"
ARX_FILE = "arx.json"  # the linear twin: same regressor, least squares, same format
LPV_FILE = "lpv.json"  # the LPV-ARX baseline (scheduled input gain and offset), same format
REJECTED_FILE = "narx.rejected.json"  # a model identify judged unusable (kept to inspect)


# ---- saving and loading ---------------------------------------------------------------------

def save_narx(model: Narx, folder: str | Path, filename: str = MODEL_FILE) -> Path:
    """Write ``narx.json`` (or ``filename``) into ``folder`` (atomically); return its path."""
    path = Path(folder) / filename
    text = json.dumps(model.to_dict(), indent=1, allow_nan=False)
    atomic_write_text(path, text + "\n")
    return path


def _fail(path: Path, what: str, flag: str = "--model") -> DescriptionError:
    return DescriptionError(flag, f"{path}: {what}")


RETRAIN = "run `jointplay identify SCENE.toml --out MODEL_DIR` to make a new one"


def narx_from_dict(data: Any, path: Path, flag: str = "--model") -> Narx:
    """Validate a parsed ``narx.json``; errors name the file, the entry and what to do."""
    def bad(what: str) -> DescriptionError:
        return _fail(path, f"{what}; the file is corrupt or was edited: {RETRAIN}", flag)

    if not isinstance(data, Mapping):
        raise bad("is not a JSON object")
    if data.get("format") != FORMAT:
        raise bad(f"'format' is {data.get('format')!r}, expected {FORMAT!r}")
    version = data.get("format_version")
    if version != FORMAT_VERSION:
        raise _fail(path, f"format_version {version!r} is not supported (this jointplay reads "
                          f"version {FORMAT_VERSION}): {RETRAIN}", flag)
    required = ("outputs", "inputs", "output_lags", "input_lags", "sample_time", "activation",
                "layers", "linear", "normalisation", "context", "checksum")
    missing = [k for k in required if k not in data]
    if missing:
        raise bad(f"missing entries {', '.join(missing)}")
    try:
        outputs = [(str(o["name"]), str(o["unit"])) for o in data["outputs"]]
        increment = tuple(bool(o["increment"]) for o in data["outputs"])
        linear = None if data["linear"] is None else np.array(data["linear"], dtype=float)
        inputs = [(str(i["name"]), str(i["unit"])) for i in data["inputs"]]
        layers = data["layers"]
        weights = tuple(np.array(layer["weight"], dtype=float) for layer in layers)
        biases = tuple(np.array(layer["bias"], dtype=float) for layer in layers)
        norm = data["normalisation"]
        vectors = {k: np.array(norm[k], dtype=float).reshape(-1)
                   for k in ("regressor_mean", "regressor_scale", "increment_mean",
                             "increment_scale", "output_scale")}
        scheduling = tuple(str(n) for n in data.get("scheduling", ()))
        bilinear = None if data.get("bilinear") is None else np.array(data["bilinear"],
                                                                       dtype=float)
        sample_time = data["sample_time"]
        sample_time = float(sample_time) if isinstance(sample_time, (int, float)) \
            and not isinstance(sample_time, bool) else sample_time
    except (KeyError, TypeError, ValueError) as err:
        raise bad(f"malformed entry ({type(err).__name__}: {err})") from None
    context = data["context"]
    if not isinstance(context, dict):
        raise bad("'context' must be an object")
    try:
        model = Narx(
            output_names=tuple(n for n, _ in outputs), output_units=tuple(u for _, u in outputs),
            input_names=tuple(n for n, _ in inputs), input_units=tuple(u for _, u in inputs),
            output_lags=data["output_lags"], input_lags=data["input_lags"],
            weights=weights, biases=biases, sample_time=sample_time,
            activation=data["activation"], context=context, increment=increment,
            linear=linear, scheduling=scheduling, bilinear=bilinear, **vectors)
    except ValueError as err:
        raise bad(str(err)) from None
    if model.checksum() != data["checksum"]:
        raise bad("checksum mismatch (the weights, normalisation or context differ from what "
                  "was saved)")
    return model


def load_narx(folder: str | Path, flag: str = "--model", filename: str = MODEL_FILE) -> Narx:
    """Read and validate ``folder/narx.json`` (or ``folder/filename``)."""
    folder = Path(folder)
    if not folder.is_dir():
        what = "is not a folder" if folder.exists() else "does not exist"
        raise _fail(folder, f"{what}; give the folder written by `jointplay identify ... --out "
                            "MODEL_DIR`", flag)
    path = folder / filename
    if filename == MODEL_FILE and not path.is_file() and (folder / REJECTED_FILE).is_file():
        raise _fail(folder, f"identification rejected its model ({REJECTED_FILE}: worse than "
                            "persistence or the linear ARX model on validation; report.md says "
                            f"by how much and what to change): {RETRAIN} with more data or "
                            "iterations", flag)
    if not path.is_file():
        raise _fail(folder, f"has no {MODEL_FILE} (the trained network); it is not a model "
                            f"folder, or training did not finish: {RETRAIN}", flag)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError) as err:
        raise _fail(path, f"cannot be read as JSON ({err}); the file is corrupt: {RETRAIN}",
                    flag) from None
    return narx_from_dict(data, path, flag)


# ---- robot identity -------------------------------------------------------------------------

def robot_identity(robot: Any) -> dict[str, str]:
    """What a model must be used with: the robot's structure and every parameter value.

    ``structure_hash`` changes with the generated code; ``robot_hash`` also with any number
    (a heavier payload is a different plant for a network, though not for the compiler).
    """
    from jointplay.robot import canonical_json

    values = dict(zip([p.name for p in robot.parameters()], robot.parameter_values(),
                      strict=True))
    text = canonical_json({"structure": robot.structure().as_dict(), "parameters": values})
    return {"name": robot.name, "structure_hash": robot.structure_hash(),
            "robot_hash": hashlib.sha256(text.encode()).hexdigest()}


def check_robot(model: Narx, robot: Any, sample_time: float, path: str | Path,
                flag: str = "--model") -> None:
    """Refuse a model trained on another robot (one outside the clearances and payloads its
    runs spanned) or at another sampling period."""
    trained = model.context.get("robot", {})
    here = robot_identity(robot)
    where = Path(path)
    if trained.get("structure_hash") != here["structure_hash"]:
        raise _fail(where, f"was trained on robot {trained.get('name')!r} with a different "
                           f"structure (hash {str(trained.get('structure_hash'))[:12]}, this "
                           f"scene's robot {here['name']!r} has {here['structure_hash'][:12]}); "
                           f"identify this robot: {RETRAIN}", flag)
    spanned = trained.get("operating_range", {}).get("robot_hashes", [])
    if trained.get("robot_hash") != here["robot_hash"] and here["robot_hash"] not in spanned:
        raise _fail(where, f"was trained on robot {trained.get('name')!r} with different "
                           f"parameter values (robot hash {str(trained.get('robot_hash'))[:12]}"
                           f", this scene's {here['robot_hash'][:12]}); identify this robot: "
                           f"{RETRAIN}", flag)
    if not math.isclose(model.sample_time, sample_time, rel_tol=1e-9):
        raise _fail(where, f"was trained at a sampling period of {model.sample_time:g} s, the "
                           f"scene samples every {sample_time:g} s (run.output_step); use the "
                           f"same period, or identify again at this one", flag)


__all__ = [
    "ACTIVATIONS",
    "ARX_FILE",
    "FORMAT",
    "FORMAT_VERSION",
    "LPV_FILE",
    "MODEL_FILE",
    "REJECTED_FILE",
    "Narx",
    "check_robot",
    "fit_percent",
    "load_narx",
    "narx_from_dict",
    "nrmse",
    "robot_identity",
    "save_narx",
]
