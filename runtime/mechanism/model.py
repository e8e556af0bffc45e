"""Find, derive, build and load a mechanism's compiled model (sympy-free unless deriving).

The generated C is keyed by the hash of the structure and the generator (the derivation's
own source files, CasADi's and sympy's versions): it is written once into the per-user cache
(``<cache>/mechanisms/<hash>/model.c``, stamped) and compiled through the same hash-keyed
build cache as the arms' models. Parameters are runtime inputs: a new mass, radius or
friction coefficient never recompiles.
"""

from __future__ import annotations

import hashlib
import json
import time
from importlib.metadata import version
from pathlib import Path
from types import SimpleNamespace

import casadi as ca
import numpy as np

from jointplay.common.files import atomic_write_text
from jointplay.mechanism.description import Mechanism
from jointplay.mechanism.structure import (
    MechanismStructure,
    coordinates,
    parameter_names,
)
from jointplay.robot import canonical_json
from jointplay.store.build import DEFAULT_CFLAGS, cache_root, compile_source
from jointplay.store.model import FastFunction
from jointplay.store.stamp import _derive_folder

FUNCTIONS = ("forward_dynamics", "jac_forward_dynamics", "contact", "gaps", "drive_power",
             "outputs", "closure", "ideal_residual", "rk4_step", "radau_step")
_GENERATOR_FILES = ("mechanism.py", "laws.py", "to_casadi.py", "fixed_step.py")


def input_hash(structure: MechanismStructure) -> str:
    h = hashlib.sha256()
    folder = _derive_folder()
    for name in _GENERATOR_FILES:
        h.update((folder / name).read_bytes())
    inputs = {"structure": structure.as_dict(), "generator": h.hexdigest(),
              "casadi": version("casadi"), "sympy": version("sympy")}
    return hashlib.sha256(canonical_json(inputs).encode()).hexdigest()


class MechanismModel:
    """A loaded mechanism model: its functions bound to buffers, and what the compiled
    integrator asks of a model (the same attributes as :class:`jointplay.store.Model`)."""

    def __init__(self, name: str, structure: MechanismStructure, library: Path,
                 seconds: dict[str, float]) -> None:
        self.name = name
        self.structure = structure
        self.library = library
        self.seconds = seconds
        self.coordinates = [c.name for c in coordinates(structure)]
        self.units = [c.unit for c in coordinates(structure)]
        self.parameters = parameter_names(structure)
        self.n_coordinates = len(self.coordinates)
        self.n_state = 2 * self.n_coordinates
        self.clearance_joints = list(range(1, len(structure.cut_joints) + 1))
        self.cut_joint_names = [j.name for j in structure.cut_joints]
        self.n_loads = len(structure.load_inputs)
        # The compiled integrator's time-function inputs (the arms' drive torques): here the
        # applied loads, by position in the input tau.
        self.torque_joints: list[int] = list(range(1, self.n_loads + 1))
        self._casadi: dict[str, ca.Function] = {}
        # What the integrators ask of a model's layout: its functions by name (the arms'
        # layout.json entries; here only Radau's Newton iteration count is read).
        iterations = int(self.casadi_function("radau_newton_iterations")()["iterations"])
        self.layout = SimpleNamespace(functions={
            name: SimpleNamespace(newton_iterations=iterations if name == "radau_step" else None)
            for name in FUNCTIONS})
        self._functions: dict[str, FastFunction] = {}

    def casadi_function(self, name: str) -> ca.Function:
        """The compiled function as a CasADi Function (for graphs built on it: the fixed-step
        methods' blocks of steps)."""
        if name not in self._casadi:
            self._casadi[name] = ca.external(name, str(self.library))
        return self._casadi[name]

    def function(self, name: str) -> FastFunction:
        if name not in self._functions:
            self._functions[name] = FastFunction(self.casadi_function(name),
                                                 frozenset({"e_q", "jac_x"}))
        return self._functions[name]

    def parameter_vector(self, mechanism: Mechanism) -> np.ndarray:
        values = mechanism.parameter_values()
        return np.array([values[name] for name in self.parameters], dtype=float)


def model_for(mechanism: Mechanism, *, quiet: bool = True) -> MechanismModel:
    """The compiled model of a mechanism's structure (derived and compiled on first use)."""
    structure = mechanism.structure()
    key = input_hash(structure)
    folder = cache_root() / "mechanisms" / key[:24]
    source_path = folder / "model.c"
    seconds = {"derive": 0.0, "compile": 0.0}
    if not source_path.is_file() or f"input hash: {key}" not in _head(source_path):
        from jointplay.derive.mechanism import emit

        t0 = time.perf_counter()
        source = emit(structure, mechanism.name, key)
        seconds["derive"] = time.perf_counter() - t0
        folder.mkdir(parents=True, exist_ok=True)
        atomic_write_text(source_path, source)
        atomic_write_text(folder / "structure.json",
                          json.dumps(structure.as_dict(), indent=1) + "\n")
    source = source_path.read_text(encoding="utf-8")
    library, compile_seconds = compile_source(source, DEFAULT_CFLAGS,
                                              what=f"mechanism '{mechanism.name}'")
    seconds["compile"] = compile_seconds
    return MechanismModel(mechanism.name, structure, library, seconds)


def _head(path: Path) -> str:
    with path.open(encoding="utf-8") as handle:
        return handle.read(2000)

